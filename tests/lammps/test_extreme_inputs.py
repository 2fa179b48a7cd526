"""Stiff and extreme inputs: no crash, no NaN, no energy gain (issue: stiff and extreme cases).

Energy bounds used: a rebound is never faster than e_d times the impact (the film only
removes momentum and never reverses the relative motion; the contact is exact), and a
sphere released from an overlap leaves no faster than its stored spring energy allows.
"""
import math
import random

import pytest

import scenes

R, U, RHO = scenes.R, scenes.U, scenes.RHO
MU = scenes.viscosity_for_stokes(10)    # St = 10 for the random scenes


@pytest.mark.parametrize("dt_ru", [0.02, 0.002])
def test_rebound_vanishes_smoothly_as_stokes_goes_to_zero(lmp, dt_ru):
    stokes = [1e5, 1000, 100, 50, 30, 20, 5, 1, 0.1, 0.01]
    ratios = [lmp(scenes.wall_bounce(0.9, dt_ru=dt_ru, mu=scenes.viscosity_for_stokes(st),
                                     tcontact_ru=0.04))["e"] / 0.9 for st in stokes]
    assert all(math.isfinite(r) for r in ratios)
    assert all(-1e-9 <= r <= 1.0 + 1e-9 for r in ratios)      # a sphere held in the film may
    assert all(a >= b - 1e-9 for a, b in zip(ratios, ratios[1:]))    # creep on at ~1e-17
    assert ratios[0] > 0.999 and max(abs(r) for r in ratios[-4:]) < 1e-9


@pytest.mark.parametrize("ncontact", [1, 2, 3, 8, 64])
def test_any_contact_step_count(lmp, ncontact):
    result = lmp(scenes.wall_bounce(0.5, dt_ru=0.005, ncontact=ncontact))
    assert result["e"] == pytest.approx(0.5, rel=1e-6)
    if ncontact < 8:
        assert "WARNING" in lmp.log


@pytest.mark.parametrize("e_dry", [0.01, 0.1, 0.999, 1.0])
def test_any_dry_restitution(lmp, e_dry):
    assert lmp(scenes.pair_bounce(e_dry, dt_ru=0.005))["e"] == pytest.approx(e_dry, rel=1e-6)


@pytest.mark.parametrize("scene", ["wall", "pair"])
def test_half_radius_overlap_in_one_step(lmp, scene):
    """u dt = R/2: the first step into contact would overlap by half a radius."""
    if scene == "wall":
        result = lmp(scenes.wall_bounce(0.8, dt_ru=0.5, ncontact=2, gap0=1.37))
    else:
        result = lmp(scenes.pair_bounce(0.8, dt_ru=0.5, ncontact=2, gap0=1.37, skin=2 * R))
    assert result["e"] == pytest.approx(0.8, rel=1e-6)


def test_radius_ratio_one_to_ten(lmp):
    dry = lmp(scenes.pair_bounce(0.7, radius_ratio=10.0, mass_ratio=1000.0, dt_ru=0.005, skin=R))
    assert dry["e"] == pytest.approx(0.7, rel=1e-6)
    wet = lmp(scenes.pair_bounce(0.7, radius_ratio=10.0, mass_ratio=1000.0, dt_ru=0.005, skin=R,
                                 mu=scenes.viscosity_for_stokes(20)))
    assert 0.0 <= wet["e"] < dry["e"]


CLUSTER = scenes.HEADER.replace("${newton}", "on") + """
boundary p p p
lattice fcc {a}
region box block -3 3 -3 3 -3 3
create_box 1 box
region ball sphere 0 0 0 0.75
create_atoms 1 region ball
set group all diameter {d} density 8000
velocity all create 1e-14 4928459 dist gaussian
pair_style lubricated/springdashpot
pair_coeff * * 0.5 ncontact 8 {wet}
fix nve all nve/sphere
timestep 5e-5
compute e all reduce sum c_ke
compute ke all ke/atom
thermo_style custom step atoms ke pe etotal
thermo 50
run 0
print "RESULT start $(etotal:%.15g) $(atoms)"
run 1000
print "RESULT end $(etotal:%.15g)"
print "RESULT finite $(is_os(nan)) $(x[7]:%.10g)"
""".replace("compute e all reduce sum c_ke\n", "")


@pytest.mark.parametrize("wet", ["", "viscosity 1e-2 activation 0.09375"])
def test_dense_pile_with_twelve_contacts(lmp, wet):
    """13 spheres: one touching 12 in fcc, all overlapping by 1 % of R, at rest: the pile
    may relax but its total energy (kinetic + spring) never grows."""
    a = 2 * R * 0.99 * math.sqrt(2)          # nearest-neighbour distance 0.99 * 2R
    script = CLUSTER.replace("{a}", repr(a)).replace("{d}", repr(2 * R)).replace("{wet}", wet)
    script = script.replace('print "RESULT finite $(is_os(nan)) $(x[7]:%.10g)"\n', "")
    result = lmp(script.replace("lattice fcc", "lattice fcc").replace(
        "lattice fcc " + repr(a), f"lattice custom {a} a1 1 0 0 a2 0 1 0 a3 0 0 1 "
        "basis 0 0 0 basis 0.5 0.5 0 basis 0.5 0 0.5 basis 0 0.5 0.5"))
    start, natoms = result["start"]
    assert natoms == 13
    assert start > 0.0
    assert result["end"] <= start * (1 + 1e-9)


def test_coincident_centres(lmp):
    script = scenes.HEADER.replace("${newton}", "on") + f"""
boundary p p p
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 0 0 0
create_atoms 1 single {1.9 * R} 0 0
set group all diameter {2 * R} density 8000
pair_style lubricated/springdashpot
pair_coeff * * 0.5 viscosity 1e-3 activation 0.09375
fix nve all nve/sphere
timestep 5e-6
run 200
print "RESULT state $(x[1]:%.10g) $(x[3]:%.10g) $(vx[3]:%.10g) $(ke:%.10g)"
"""
    result = lmp(script)
    assert all(math.isfinite(v) for v in result["state"])


@pytest.mark.parametrize("integrator", ["nve/sphere", "nve/sphere/midpoint"])
def test_sphere_starting_inside_a_wall(lmp, integrator):
    """Released from an overlap of R/2 at rest: pushed out, no faster than the spring's energy."""
    t_c = 8 * 0.005 * R / U
    script = scenes.wall_bounce(0.9, dt_ru=0.005, gap0=-0.5, steps=40, integrator=integrator).replace(
        f"velocity all set 0 0 {-U}", "velocity all set 0 0 0")
    vz = lmp(script)["e"] * U
    v_max = 0.5 * R * math.sqrt(math.pi ** 2 + math.log(0.9) ** 2) / t_c
    assert 0.0 < vz <= v_max * (1 + 1e-9)


@pytest.mark.parametrize("scene", ["wall", "pair"])
@pytest.mark.parametrize("integrator", ["nve/sphere", "nve/sphere/midpoint"])
@pytest.mark.parametrize("gap0", [0.005, 0.03])
def test_contact_starting_within_the_first_step(lmp, scene, integrator, gap0):
    """The run starts u dt = 0.1 R from contact: the contact begins within the first step,
    within the midpoint scheme's first half-step drift X~ = X + dt/2 V. Exact dry rebound
    (the start places X~ on the collision's trajectory; contact_step.h)."""
    build = scenes.wall_bounce if scene == "wall" else scenes.pair_bounce
    result = lmp(build(0.9, dt_ru=0.1, gap0=gap0, integrator=integrator))
    assert result["e"] == pytest.approx(0.9, rel=1e-9)


@pytest.mark.parametrize("integrator", ["nve/sphere", "nve/sphere/midpoint"])
def test_start_in_the_saturated_film_gains_no_energy(lmp, integrator):
    """The stability map's hardest start: inside the saturated film (gap 5e-4 R), St = 1e4,
    dt = 0.1 R/U: the film removes O(1/St) of the speed (about 35/St in and out, the Legendre
    law), so the rebound stays below e_d and above e_d (1 - 100/St)."""
    result = lmp(scenes.wall_bounce(0.9, dt_ru=0.1, gap0=5e-4, integrator=integrator,
                                    mu=scenes.viscosity_for_stokes(1e4)))
    assert 0.9 * (1 - 100 / 1e4) < result["e"] < 0.9


@pytest.mark.parametrize("scene", ["wall", "pair"])
def test_grid_activation_below_saturation_gives_no_film(lmp, scene):
    """0.75 dx / R = 0.01 < eps_1 = 0.05: no film, so the dry rebound (an attracting film
    before the fix: lambda(eps_1) - lambda(eps_al) < 0 gave e above e_d)."""
    film = f"viscosity {scenes.viscosity_for_stokes(20)} grid {0.01 * R / 0.75} saturation 0.05"
    if scene == "wall":
        result = lmp(scenes.wall_bounce(0.9, dt_ru=0.005, extra=film))
    else:    # pair film radius 2 R R / (R + R) = R
        result = lmp(scenes.pair_bounce(0.9, dt_ru=0.005, extra=film))
    assert result["e"] == pytest.approx(0.9, rel=1e-6)


def random_scene(seed, coefficients, integrator="nve/sphere", n=40):
    """n polydisperse spheres (radii R/2 to 3R/2) in a box periodic in x and y between two walls, placed at
    random with overlaps up to 3 % of the smaller radius and many pairs inside the film, at
    random velocities up to U and spins up to U/R, two atom types."""
    rng = random.Random(seed)
    half = 6 * R
    placed = []
    while len(placed) < n:
        r = R * rng.uniform(0.5, 1.5)
        x = [rng.uniform(-half, half), rng.uniform(-half, half), rng.uniform(r * 1.05, 2 * half + 2 * R - r * 1.05)]
        def gap(p):
            d = [x[k] - p[k] for k in range(3)]
            for k in range(2):    # periodic in x and y
                d[k] -= 2 * half * round(d[k] / (2 * half))
            return math.sqrt(sum(c * c for c in d)) - r - p[3]
        if all(gap(p) > -0.03 * min(r, p[3]) for p in placed):
            placed.append(x + [r])
    atoms = "\n".join(
        f"create_atoms {1 + k % 2} single {p[0]} {p[1]} {p[2]}\n"
        f"set atom {k + 1} diameter {2 * p[3]} density {RHO}\n"
        f"set atom {k + 1} vx {rng.uniform(-U, U)} vy {rng.uniform(-U, U)} vz {rng.uniform(-U, U)}\n"
        f"set atom {k + 1} omega {rng.uniform(-U, U) / R} {rng.uniform(-U, U) / R} 0"
        for k, p in enumerate(placed))
    return scenes.HEADER.replace("${newton}", "on") + f"""
region box block -{half} {half} -{half} {half} 0 {2 * half + 2 * R}
create_box 2 box
{atoms}
pair_style lubricated/springdashpot
pair_coeff 1 1 {coefficients[0]}
pair_coeff 2 2 {coefficients[1]}
pair_coeff 1 2 {coefficients[2]}
fix walls all wall/lubrication {coefficients[0]} zplane 0.0 {2 * half + 2 * R}
fix nve all {integrator}
neighbor {R} bin
timestep {0.01 * R / U}
compute rot all erotate/sphere
thermo_style custom step ke c_rot pe
thermo 0
run 0
print "RESULT start $(ke + c_rot + pe:%.15g)"
run 2000
print "RESULT end $(ke + c_rot + pe:%.15g)"
"""



@pytest.mark.parametrize("seed,coefficients", [
    (1, ["0.9", "0.5 ncontact 3", "0.7 ncontact 20"]),
    (2, [f"0.9 viscosity {MU} activation 0.1", f"0.3 viscosity {MU} grid {0.2 * R}",
         f"0.6 viscosity {10 * MU} activation 0.5 saturation 0.01"]),
    (3, [f"0.9 viscosity {MU} activation 0.1 legendre 35", "0.8",
         f"0.5 viscosity {MU} grid {0.01 * R} saturation 0.02 release 0.0"]),    # no film: eps_al < eps_1
    (4, [f"0.9 viscosity {MU} activation 0.1 friction 0.4 rolling 0.05", "0.7 friction 1.0",
         f"0.5 viscosity {MU} grid {0.2 * R} friction 0.2 tangential 0.0"]),
])
@pytest.mark.parametrize("integrator", ["nve/sphere", "nve/sphere/midpoint"])
def test_random_polydisperse_scene_never_gains_energy(lmp, seed, coefficients, integrator):
    """Mixed types, dry and wet, film and contact, friction: the total energy (translation,
    rotation, springs) never grows. Only the wall spring's and the tangential springs'
    energy are left out, which can only make the end look lower."""
    result = lmp(random_scene(seed, coefficients, integrator))
    assert result["start"] > 0.0
    assert result["end"] <= result["start"] * (1 + 1e-9)
    assert result["end"] < 0.9 * result["start"]    # it dissipated: collisions happened


@pytest.mark.parametrize("friction", ["", "friction 0.3"])
def test_wall_placed_above_the_atoms_leaves_them_alone(lmp, friction):
    """A lower wall put above every sphere (issue 18: it launched them at ~80 m/s and lost them):
    spheres whose centres lie behind a wall are not in contact with it (a warning says how many);
    they keep their velocity, no atom is lost. A sphere in front of it still bounces."""
    script = scenes.wall_bounce(0.9, dt_ru=0.005, steps=200).replace(
        "zplane 0.0 NULL", f"{friction} zplane {3 * R} NULL").replace(
        f"create_atoms 1 single 0 0 {R * (1 + 0.2137)}",
        f"create_atoms 1 single 0 0 {R * (1 + 0.2137)}\ncreate_atoms 1 single 0.005 0 {R * (4 + 0.2137)}").replace(
        f"set atom 1 diameter {2 * R} density {RHO}", f"set group all diameter {2 * R} density {RHO}")
    script += 'print "RESULT lost $(atoms) $(vz[2]:%.17g)"\n'
    result = lmp(script)
    atoms, vz2 = result["lost"]
    assert atoms == 2
    assert result["e"] == pytest.approx(-1.0, rel=1e-12)    # sphere 1 behind the wall: untouched
    assert 0.0 < vz2 <= 0.9 * U * (1 + 1e-9)    # sphere 2 fell onto the wall's face and bounced
    assert "1 atom(s) have their centre behind a wall (lo = 0.003, hi = NULL)" in lmp.log

"""Walls in the coupled film solve (`limit implicit`, doc/film_solve.rst, "Walls in the solve").

A column of three spheres (R = 1 mm, rho 2500) squeezed in a viscous liquid (mu_f 10 Pa s, shear
film on) between a still floor and a lid that comes down at 0.06 m/s and slides at 0.05 m/s;
the spheres are offset sideways, so every film is oblique. Only films act (no contact in 1 ms).
A film's a = c dt / m reaches 3.6 at dt = 1e-5 s and 7 at 2e-5 s: the budget binds and scales
the films (the lid's force comes out at a seventh of the true one), while the solve takes the
two pair films and the two wall films together. The reference resolves every film step-exact at
dt = 1e-7 s, where no budget binds. The lid's force (its fix's vector, averaged over the second
half of the run, past the start's transient) converges to it in dt; the plane wall (translate)
and a moving region (move) alike; 1 and 2 ranks (the lid's sphere on the other rank) agree to
the solver's tolerance. A turning wall: a wet bed tumbling in a rotating drum (a cylinder
region) gives the drum's torque converged in dt.
"""
import pytest

import dense_scenes

R = 1e-3
GAP = 5e-5
SPHERES = 3
TOP = SPHERES * (2 * R + GAP) + GAP
SQUEEZE, SLIDE = 0.06, 0.05
DURATION = 1e-3
FILM = "ncontact 8 viscosity 10.0 activation 0.2 shearfilm yes"

LIDS = {
    "plane": f"fix lid all wall/lubrication 0.9 {FILM} zplane NULL {TOP:.10g} translate {SLIDE} 0 {-SQUEEZE}",
    "region": (f"variable dx equal {SLIDE}*step*dt\n"
               f"variable dz equal {-SQUEEZE}*step*dt\n"
               f"region lid plane 0 0 {TOP:.10g} 0 0 -1 move v_dx NULL v_dz\n"
               f"fix lid all wall/lubrication/region 0.9 lid {FILM}"),
}


def squeeze(limit, dt, lid="plane"):
    steps = int(round(DURATION / dt))
    atoms = "\n".join(f"create_atoms 1 single {k * 2e-4:.6g} 0 {R + GAP + k * (2 * R + GAP):.10g}"
                      for k in range(SPHERES))
    return dense_scenes.HEADER.replace("boundary p p p", "boundary f f f") + f"""processors 1 1 *
region box block -0.01 0.01 -0.01 0.01 -0.001 0.0075
create_box 1 box
{atoms}
set group all diameter {2 * R} density 2500
velocity all set 0 0 0
pair_style lubricated/springdashpot limit {limit}
pair_coeff * * 0.9 {FILM}
fix floor all wall/lubrication 0.9 {FILM} zplane 0.0 NULL
{LIDS[lid]}
neighbor 0.0002 bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep {dt}
compute solve all pair lubricated/springdashpot
variable fz equal f_lid[3]
variable fx equal f_lid[1]
variable solved equal c_solve[4]
fix avg all ave/time 1 {steps // 2} {steps} v_fz v_fx v_solved
thermo_style custom step ke c_solve[3] c_solve[4]
thermo {steps // 10}
run {steps}
print "RESULT lid $(f_avg[1]:%.17g) $(f_avg[2]:%.17g) $(f_avg[3]:%.17g) $(count(all))"
"""


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The resolved lid force (normal, sliding) of each lid, step-exact at dt = 1e-7 s."""
    import lammps_run
    out = {}
    for lid in LIDS:
        results, log = lammps_run.run(squeeze("atom", 1e-7, lid), tmp_path_factory.mktemp(lid), {})
        assert "(limit atom)" in log
        out[lid] = results["lid"][:2]
    return out


@pytest.mark.parametrize("lid", list(LIDS))
def test_lid_force_converges_to_the_resolved_films(lmp, reference, lid):
    """Relative error of the lid's normal and sliding force: under 5 % at dt 2e-5 s, under 2 % at
    1e-5 s and shrinking with dt (backward Euler: first order; measured 1.3 and 0.3 % for the
    plane, 2.8 and 1.0 % for the region); all four films solved; the budget alone at 2e-5 s is
    far off (the scaled films). Without the walls' links both lids fail."""
    normal, sliding = reference[lid]
    assert normal < 0.0 and sliding < 0.0    # the lid pushes down, drags the spheres along
    errors = []
    for dt in (2e-5, 1e-5):
        fz, fx, solved, atoms = lmp(squeeze("implicit", dt, lid))["lid"]
        assert atoms == SPHERES
        assert solved > 3.5 and "WARNING" not in lmp.log    # 2 pair films and 2 wall films, most steps
        errors.append(max(abs(fz / normal - 1.0), abs(fx / sliding - 1.0)))
    assert errors[0] < 0.05 and errors[1] < 0.02 and errors[1] < 0.6 * errors[0], errors
    fz, fx, solved, _ = lmp(squeeze("atom", 2e-5, lid))["lid"]
    assert solved == 0.0 and fz / normal < 0.3


def test_one_and_two_ranks_agree(lmp):
    """tolerance 1e-12, the column split over two ranks in z (floor's and lid's spheres apart),
    newton pair on and off (a wall film belongs to its owned sphere: solved once either way)."""
    script = squeeze("implicit tolerance 1e-12", 1e-5)
    assert "newton on" in script
    one = lmp(script)["lid"]
    for newton in ("on", "off"):
        two = lmp(script.replace("newton on", f"newton {newton}"), nprocs=2)["lid"]
        assert "1 by 1 by 2" in lmp.log
        assert two[0] == pytest.approx(one[0], rel=1e-9) and two[1] == pytest.approx(one[1], rel=1e-9), newton
        assert two[2] == pytest.approx(one[2], rel=1e-9)    # the films solved


DRUM = """region box block -0.022 0.022 -0.022 0.022 -0.022 0.022
create_box 1 box
region fill cylinder z 0 -0.012 0.006 -0.003 0.003 units box
lattice sc 0.00105
create_atoms 1 region fill
set group all diameter 0.001 density 2500
variable theta equal 20.0*step*dt
region drum cylinder z 0 0 0.02 -0.02 0.02 side in units box rotate v_theta 0 0 0 0 0 1
pair_style lubricated/springdashpot limit implicit
pair_coeff * * 0.9 ncontact 8 viscosity 1.0 activation 0.2 friction 0.3 shearfilm yes
fix drum all wall/lubrication/region 0.9 drum ncontact 8 viscosity 1.0 activation 0.2 friction 0.3 shearfilm yes
fix g all gravity 9.81 vector 0 -1 0
neighbor 0.0002 bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep {dt}
compute solve all pair lubricated/springdashpot
variable torque equal f_drum[6]
variable solved equal c_solve[4]
fix avg all ave/time 1 {half} {steps} v_torque v_solved
thermo_style custom step atoms ke c_solve[3] c_solve[4]
thermo {half}
run {steps}
print "RESULT drum $(f_avg[1]:%.17g) $(f_avg[2]:%.17g) $(ke:%.17g) $(count(all))"
"""


def test_rotating_drum_torque_converges_in_the_step(lmp):
    """520 spheres (1 mm, 2500 kg/m^3) tumbling in a drum (a cylinder region turning at 20 rad/s)
    in a liquid of 1 Pa s, friction and shear films on pairs and the drum: the drum's torque on
    the spheres, averaged over the second half of 0.1 s, at dt 2e-5 and 1e-5 s within 3 %
    (measured 8.29e-5 and 8.26e-5 N m; the film budget alone, limit atom, 7 % lower at both).
    The turning wall's films of spheres over budget are solved with the pairs'."""
    torques = []
    for dt in (2e-5, 1e-5):
        steps = int(round(0.1 / dt))
        script = dense_scenes.HEADER.replace("boundary p p p", "boundary f f f") + DRUM.format(
            dt=dt, steps=steps, half=steps // 2)
        torque, solved, energy, atoms = lmp(script, name="in.drum")["drum"]
        assert atoms == 520 and "WARNING" not in lmp.log
        assert solved > 100 and energy > 0.0
        torques.append(torque)
    assert torques[0] > 0.0 and torques[1] == pytest.approx(torques[0], rel=0.03), torques

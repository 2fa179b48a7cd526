"""Partners a contact cannot move, and rigid bodies (issue 17, "Frozen partners").

doc/model.rst, "Solid contact: the spring-dashpot" takes k and c from m_e, the mass the contact
accelerates: the reduced mass
m_i m_j / (m_i + m_j) of two free spheres, m_i against a partner that does not move (a wall,
a sphere left out of the time integration, held by fix freeze, by fix setforce 0 0 0 or
moved by fix move), m_i M / (m_i + M) against a rigid body of mass M. With that m_e the
step-exact contact gives an isolated impact e_d to round-off (test_dry_restitution.py), so
the relative tolerance here is 1e-9.

Every test fails without the contact masses (m_e of the two spheres' own masses), measured:
held sphere e = 1.0002, 0.928, 0.62 at e_d = 1, 0.9, 0.5 (fix move at -U/2: 0.779 at 0.7);
rough base head-on 0.9285; rigid body 0.913 at 0.9, 0.553 at 0.5, on a wall 0.779 at 0.7;
a frozen atom in a wall is pushed (twice the wall's energy and force); two held atoms keep 5.7e-6 J of spring energy;
wet held 0.410 against 0.445 for the free pair (St 50); friction e 0.868 against 0.843;
six spheres on a held one 0.711 against 0.245 alone (the held atom's load scaled them).
"""
import math

import pytest

import scenes

R, U, RHO = scenes.R, scenes.U, scenes.RHO
DT = 0.005 * R / U
TIGHT = 1e-9

# How the partner (atom 2, group base) is held; the mover is atom 1 (group mover).
HOLDS = {
    "unintegrated": "fix nve mover nve/sphere",
    "freeze": "fix nve all nve/sphere\nfix hold base freeze",
    "setforce": "fix nve all nve/sphere\nfix hold base setforce 0.0 0.0 0.0",
    "move": "fix nve mover nve/sphere\nfix hold base move linear 0 0 0",
}


def header(half=0.01):
    return scenes.HEADER.replace("${newton}", "on") + f"""boundary p p p
region box block -{half} {half} -{half} {half} -{half} {half}
"""


def frozen_pair(e_dry, hold, wet="", density=RHO, gap0=0.2137, steps=300):
    """Atom 1 moving at U along x towards atom 2 (held as `hold`, or `free`), the contact at
    x = 0 (the boundary between 2 ranks). RESULT e: separation / approach speed."""
    lines = HOLDS.get(hold, "fix nve all nve/sphere")
    return header() + f"""create_box 1 box
create_atoms 1 single {-R - 0.5 * gap0 * R} 0 0
create_atoms 1 single {R + 0.5 * gap0 * R} 0 0
set group all diameter {2 * R} density {density}
group mover id 1
group base id 2
velocity mover set {U} 0 0
pair_style lubricated/springdashpot
pair_coeff * * {e_dry} ncontact 8 {wet}
{lines}
timestep {DT}
neighbor {0.5 * R} bin
thermo 0
run {steps}
print "RESULT e $((vx[2]-vx[1])/{U}:%.15g)"
print "RESULT v2 $(vx[2]:%.15g) $(x[2]:%.15g)"
"""


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("hold", list(HOLDS))
@pytest.mark.parametrize("e_dry", [1.0, 0.9, 0.5])
def test_held_partner_rebounds_with_e_dry(lmp, e_dry, hold, nprocs):
    result = lmp(frozen_pair(e_dry, hold), nprocs=nprocs)
    assert result["e"] == pytest.approx(e_dry, rel=TIGHT)
    assert result["v2"] == [0.0, pytest.approx(R + 0.5 * 0.2137 * R, rel=1e-15)]    # never moved
    assert "1 immovable" in lmp.log


def test_moving_prescribed_partner(lmp):
    """fix move with a velocity: the contact sees the relative motion and infinite mass."""
    script = frozen_pair(0.7, "move").replace("move linear 0 0 0", f"move linear {-0.5 * U} 0 0").replace(
        f"velocity mover set {U} 0 0", f"velocity mover set {0.5 * U} 0 0")
    assert lmp(script)["e"] == pytest.approx(0.7, rel=TIGHT)


@pytest.mark.parametrize("force", ["NULL 0.0 0.0", "v_keep 0.0 0.0", "0.0 0.0 0.0 region far"])
def test_only_setforce_all_zero_holds(lmp, force):
    """`setforce 0 0 0` (no region, no variable) holds its atoms: e_d against them. With a NULL
    component, a variable or a region the fix may let the atom move, and here it does (x is
    free, the variable keeps the force, the region is elsewhere): the free pair's e_d."""
    script = frozen_pair(0.9, "setforce").replace("group base id 2", "group base id 2\n"
        f"variable keep atom fx\nregion far block 0 {R} {4 * R} {5 * R} 0 {R} units box")
    held = lmp(script)
    assert held["e"] == pytest.approx(0.9, rel=TIGHT) and held["v2"][0] == 0.0
    loose = lmp(script.replace("setforce 0.0 0.0 0.0", f"setforce {force}"))
    assert loose["e"] == pytest.approx(0.9, rel=TIGHT) and loose["v2"][0] > 0.0
    assert "immovable" not in lmp.log


def test_setforce_arguments_are_known_after_clear(lmp):
    """The plugin records each fix setforce as it is created: after a clear that works again
    once a style of the plugin exists; a setforce defined before that is not taken as holding,
    with a warning (its atom keeps its mass: the free pair's m_e, e = 0.928 at e_d 0.9)."""
    held = frozen_pair(0.9, "setforce")
    first = held.replace(f'print "RESULT e', f'print "RESULT first', 1)
    body = held[held.index("atom_style"):]
    early = body.replace("fix hold base setforce 0.0 0.0 0.0\n", "").replace(
        "pair_style lubricated/springdashpot", "fix hold base setforce 0.0 0.0 0.0\npair_style lubricated/springdashpot")
    result = lmp(first + "clear\nunits si\n" + body + "clear\nunits si\n" + early.replace(
        'print "RESULT e', 'print "RESULT early'))
    assert result["first"] == pytest.approx(0.9, rel=TIGHT)
    assert result["e"] == pytest.approx(0.9, rel=TIGHT)
    assert result["early"] == pytest.approx(0.928431933052934, rel=1e-6)
    assert "fix hold setforce was defined before the plugin was loaded" in lmp.log


def test_two_held_atoms_exert_nothing(lmp):
    """Two overlapping atoms that neither moves: no force, no energy (nothing moves)."""
    script = frozen_pair(0.9, "freeze", gap0=-0.1, steps=1).replace("group base id 2", "group base id 1 2")
    script += 'print "RESULT pe $(pe:%.15g)"\n'
    result = lmp(script)
    assert result["pe"] == 0.0
    assert "2 immovable" in lmp.log


def oblique(hold, friction, density=RHO):
    """frozen_pair with a slip 0.5 U along y: RESULT slip, the relative slip at the contact
    (v1 - v2 + (R w1 + R w2) x n) along y over its start value."""
    return frozen_pair(0.9, hold, density=density).replace(
        f"velocity mover set {U} 0 0", f"velocity mover set {U} {0.5 * U} 0").replace(
        "ncontact 8", f"ncontact 8 friction {friction}").replace(
        "thermo 0", "compute om all property/atom omegaz\ncompute wz all reduce sum c_om\n"
        "thermo_style custom step c_wz\nthermo 0") + \
        f'print "RESULT slip $((vy[1] - vy[2] + {R} * c_wz) / {0.5 * U}:%.15g)"\n'


@pytest.mark.parametrize("friction", ["1e6 tangential 0.5", "0.05"])
def test_friction_against_a_held_sphere(lmp, friction):
    """The tangential contact (m_t = 2/7 m_e) against a held sphere moves the sphere as the free
    pair of twice the density (m_e = m) moves relative to each other: sticking (e_t 0.5) and
    sliding (mu_c 0.05). (Rolling resistance acts on w_1 - w_2, which the symmetric free pair keeps 0.)"""
    held = lmp(oblique("freeze", friction))
    free = lmp(oblique("free", friction, density=2 * RHO))
    assert held["e"] == pytest.approx(free["e"], rel=TIGHT)
    assert held["slip"] == pytest.approx(free["slip"], rel=TIGHT)
    assert held["slip"] < 0.9    # friction acted


def rough_base(hold, e_dry=0.9, spacing=1.98):
    """A square layer of 8 x 8 spheres (overlapping by 1 % of a diameter) held as `hold`, and
    three spheres moving down at U onto it: above a base sphere (one contact), above the
    middle of an edge (two) and above a hollow (four). RESULT vz: their rebound speeds / U."""
    s = spacing * R
    n = 8
    drops = [(s, s, 2 * R), (4.5 * s, s, math.sqrt(4 * R * R - (0.5 * s) ** 2)),
             (1.5 * s, 4.5 * s, math.sqrt(4 * R * R - 0.5 * s * s))]
    atoms = "\n".join(f"create_atoms 1 single {x} {y} {z + 0.2 * R} units box" for x, y, z in drops)
    fix = {"unintegrated": "fix nve mover nve/sphere",
           "freeze": "fix nve all nve/sphere\nfix hold base freeze"}[hold]
    return scenes.HEADER.replace("${newton}", "on") + f"""boundary p p f
lattice sc {s} origin 0 0 0
region box block 0 {n * s} 0 {n * s} {-R} {4 * R} units box
create_box 1 box
region layer block 0 {n * s} 0 {n * s} {-0.1 * R} {0.1 * R} units box
create_atoms 1 region layer
group base type 1
{atoms}
group mover subtract all base
set group all diameter {2 * R} density {RHO}
velocity mover set 0 0 {-U} units box
pair_style lubricated/springdashpot
pair_coeff * * {e_dry} ncontact 8
{fix}
timestep {DT}
neighbor {0.5 * R} bin
thermo 0
run 200
print "RESULT n $(count(base)) $(count(mover))"
print "RESULT vz $(vz[65]/{U}:%.15g) $(vz[66]/{U}:%.15g) $(vz[67]/{U}:%.15g)"
"""


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("hold", ["unintegrated", "freeze"])
def test_rough_base_rebound_never_above_e_dry(lmp, hold, nprocs):
    """Straight onto a base sphere: e_d (an isolated contact). Onto two or four at once (30 and
    45 degrees from the vertical): N contacts at angle theta damp the vertical motion with the
    ratio sqrt(N) cos(theta) times the contact's (>= 1.2 here), so the rebound is below e_d."""
    result = lmp(rough_base(hold), nprocs=nprocs)
    assert result["n"] == [64, 3]
    single, edge, hollow = result["vz"]
    assert single == pytest.approx(0.9, rel=TIGHT)
    assert 0.0 < edge < 0.9 and 0.0 < hollow < 0.9


def rigid_scene(e_dry, rigid, wall=False):
    """A body of two spheres 2.2 R apart on the x axis (z axis with `wall`), struck head-on by
    a sphere at U along the axis (with `wall`: the body falls at U onto a wall at z = 0), so it
    does not rotate. RESULT e: separation / approach speed."""
    if wall:
        place = f"create_atoms 1 single 0 0 {1.2 * R}\ncreate_atoms 1 single 0 0 {3.4 * R}"
        extra = f"fix wall all wall/lubrication {e_dry} ncontact 8 zplane 0.0 NULL"
        box = f"region box block -0.01 0.01 -0.01 0.01 0 0.02\nboundary p p f"
        bodies = "group body id 1 2"
        start = f"velocity all set 0 0 {-U}"
        e = f"$(vz[1]/{U}:%.15g)"
    else:
        place = (f"create_atoms 1 single {-R - 0.1 * R} 0 0\ncreate_atoms 1 single {R + 0.1 * R} 0 0\n"
                 f"create_atoms 1 single {3.2 * R + 0.1 * R} 0 0")
        extra = ""
        box = "boundary p p p\nregion box block -0.01 0.01 -0.01 0.01 -0.01 0.01"
        bodies = "group body id 2 3\ngroup mover id 1\nfix nve mover nve/sphere"
        start = f"velocity mover set {U} 0 0"
        e = f"$((vx[2]-vx[1])/{U}:%.15g)"
    body_fix = {"rigid": "fix body body rigid single",
                "rigid/small": "variable b atom 1\nfix body body rigid/small custom v_b"}[rigid]
    return scenes.HEADER.replace("${newton}", "on") + f"""{box}
create_box 1 box
{place}
set group all diameter {2 * R} density {RHO}
{bodies}
{start}
pair_style lubricated/springdashpot
pair_coeff * * {e_dry} ncontact 8
{extra}
{body_fix}
timestep {DT}
neighbor {0.5 * R} bin
thermo_style custom step
thermo 0
run 250
print "RESULT e {e}"
"""


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("rigid", ["rigid", "rigid/small"])
@pytest.mark.parametrize("e_dry", [0.9, 0.5])
def test_rigid_body_takes_its_mass(lmp, e_dry, rigid, nprocs):
    """m_e = m 2m / 3m (sphere against the body of two): the two-body result, e = e_d."""
    result = lmp(rigid_scene(e_dry, rigid), nprocs=nprocs)
    assert result["e"] == pytest.approx(e_dry, rel=TIGHT)
    assert "2 in rigid bodies" in lmp.log


@pytest.mark.parametrize("rigid", ["rigid", "rigid/small"])
def test_rigid_body_on_a_wall_takes_its_mass(lmp, rigid):
    """A body of two spheres falling on fix wall/lubrication: m_e = the body's mass, e = e_d."""
    assert lmp(rigid_scene(0.7, rigid, wall=True))["e"] == pytest.approx(0.7, rel=TIGHT)


def test_wall_leaves_a_held_atom_alone(lmp):
    """Two spheres resting 1 % of R into a wall, one frozen: the wall acts on the free one
    only (spring energy k d^2 / 2 with k = m (pi^2 + ln^2 e_d) / t_c^2, its force)."""
    script = scenes.HEADER.replace("${newton}", "on") + f"""boundary p p f
region box block -0.01 0.01 -0.01 0.01 0 0.02
create_box 1 box
create_atoms 1 single 0 0 {0.99 * R}
create_atoms 1 single {5 * R} 0 {0.99 * R}
set group all diameter {2 * R} density {RHO}
group base id 1
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact 8
fix wall all wall/lubrication 0.9 ncontact 8 zplane 0.0 NULL
fix nve all nve/sphere
fix hold base freeze
timestep {DT}
thermo_style custom step f_wall f_wall[3]
run 0
print "RESULT wall $(f_wall:%.15g) $(f_wall[3]:%.15g) $(fz[2]:%.15g)"
"""
    energy, force, on_free = lmp(script)["wall"]
    mass = RHO * 4.0 / 3.0 * math.pi * R**3
    k = mass * (math.pi**2 + math.log(0.9) ** 2) / (8 * DT) ** 2
    assert energy == pytest.approx(0.5 * k * (0.01 * R) ** 2, rel=TIGHT)
    assert force == pytest.approx(on_free, rel=TIGHT) and on_free > 0.0


# Wet: St = (2/9) rho R U / mu_f for the free pair of spheres twice as dense (m_e = m).
@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("stokes", [50, 100, 1000])
def test_wet_held_partner_is_the_free_pair_of_equal_reduced_mass(lmp, stokes, nprocs):
    """The relative motion sees only m_e: a sphere of mass m against a held one moves exactly as
    two free spheres of mass 2 m (m_e = m) with the same radii, film and impact speed. Its
    rebound stays below the dry e_d and follows Legendre's law as the free pair does."""
    wet = f"viscosity {scenes.viscosity_for_stokes(stokes, rho=2 * RHO)} activation {scenes.EPS_AL}"
    held = lmp(frozen_pair(0.9, "unintegrated", wet), nprocs=nprocs)["e"]
    free = lmp(frozen_pair(0.9, "free", wet, density=2 * RHO), nprocs=nprocs)["e"]
    assert held == pytest.approx(free, rel=1e-9, abs=1e-12)
    assert held < 0.9
    assert held / 0.9 == pytest.approx(scenes.legendre(stokes), abs=0.05)


def star(movers, stokes):
    """`movers` spheres approaching a held sphere at the origin along +-x, +-y, +-z at U, in a
    strong film (dt = 0.05 R / U: one step takes a large share of each approach)."""
    axes = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)][:movers]
    d = 2.2 * R
    atoms = "\n".join(f"create_atoms 1 single {a * d} {b * d} {c * d}" for a, b, c in axes)
    velocities = "\n".join(f"set atom {k + 2} vx {-a * U} vy {-b * U} vz {-c * U}"
                           for k, (a, b, c) in enumerate(axes))
    mu = scenes.viscosity_for_stokes(stokes)
    return header() + f"""create_box 1 box
create_atoms 1 single 0 0 0
{atoms}
set group all diameter {2 * R} density {RHO}
group base id 1
group mover subtract all base
{velocities}
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact 8 viscosity {mu} activation {scenes.EPS_AL}
fix nve mover nve/sphere
timestep {10 * DT}
neighbor {0.5 * R} bin
thermo 0
run 60
print "RESULT vx2 $(vx[2]/{U}:%.15g)"
"""


def test_held_atom_does_not_limit_its_partners_films(lmp):
    """The many-body film budget (lubricated/film_budget.h) bounds each moving sphere's films;
    a held sphere is not part of the state it protects, so six spheres striking it at once
    rebound as one alone does (each is its own isolated contact)."""
    alone = lmp(star(1, 20))["vx2"]
    six = lmp(star(6, 20))["vx2"]
    assert 0.0 < alone < 0.9
    assert six == pytest.approx(alone, rel=1e-12)

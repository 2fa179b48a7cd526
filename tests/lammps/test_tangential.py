"""Tangential contact: friction, tangential restitution, rolling resistance, shear film.

Wall impacts compare with the analytic linear spring-dashpot with Coulomb friction
(tangential_reference.py); the sphere on an incline with rigid-body mechanics; the history
with 1/2 ranks, list rebuilds, migration and restarts.
"""
import math

import pytest

import scenes
from scene_chain import dump_state
from tangential_reference import normal_impulse_magnitude, slip_ratio

R, U, RHO = scenes.R, scenes.U, scenes.RHO
MASS = RHO * 4.0 / 3.0 * math.pi * R**3


def wall_impact(e_t, mu, psi, ncontact=8, gap0=0.2137, e_d=0.9, extra=""):
    """A sphere hits the zplane wall at normal speed U and slip psi*U (along x), no spin.
    Prints RESULT en (normal restitution), slip (s'/s0), spin (R omega_y' / s0), vx (vx'/s0)."""
    dt = 0.01 * R / U * 8 / ncontact
    steps = int((gap0 + 0.2) * R / U / dt) + 3 * ncontact
    ut = psi * U
    return scenes.HEADER.replace("${newton}", "on") + f"""
region box block -0.01 0.01 -0.01 0.01 0 0.02
create_box 1 box
create_atoms 1 single 0 0 {R * (1 + gap0)}
set atom 1 diameter {2 * R} density {RHO}
velocity all set {ut} 0 {-U}
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix wall all wall/lubrication {e_d} ncontact {ncontact} friction {mu} tangential {e_t} {extra} zplane 0.0 NULL
fix nve all nve/sphere
timestep {dt}
compute om all property/atom omegay
compute wy all reduce sum c_om
thermo_style custom step c_wy
thermo 0
run {steps}
print "RESULT en $(vz[1]/{U}:%.15g)"
print "RESULT slip $((vx[1]-{R}*c_wy)/{ut}:%.15g)"
print "RESULT spin $({R}*c_wy/{ut}:%.15g)"
print "RESULT vx $(vx[1]/{ut}:%.15g)"
"""


@pytest.mark.parametrize("e_t", [0.9, 0.5, 0.1, 0.0])
@pytest.mark.parametrize("gap0", [0.2137, 0.5])
def test_sticking_wall_impact_reverses_slip_with_e_t(lmp, e_t, gap0):
    """mu_c huge: a sticking contact is a damped oscillator lasting t_c: s' = -e_t s0, for any
    N_c and impact phase (the per-step force lands on the analytic oscillator)."""
    res = lmp(wall_impact(e_t, 1e6, 0.5, gap0=gap0))
    assert res["en"] == pytest.approx(0.9, abs=1e-9)    # friction leaves the normal part alone
    assert res["slip"] == pytest.approx(-e_t, abs=1e-9)
    # Angular momentum about the contact point is conserved: v' + (2/5) R w' = v0 (psi * U).
    assert res["vx"] + 0.4 * res["spin"] == pytest.approx(1.0, abs=1e-9)


PSIS = [0.05, 0.2, 0.5, 1.0, 2.0, 4.0]


@pytest.fixture(scope="module")
def reference_slip():
    return dict(zip(PSIS, slip_ratio(0.9, 0.5, 0.2, PSIS)))


@pytest.mark.parametrize("ncontact", [8, 32])
@pytest.mark.parametrize("psi", PSIS)
def test_oblique_wall_impact_follows_coulomb_spring_dashpot(lmp, reference_slip, psi, ncontact):
    """e_d 0.9, e_t 0.5, mu_c 0.2 over impact angles atan(psi): rebound slip and spin of the
    continuous model. The stick-slip switch is resolved to a step, hence 0.03 of s0."""
    res = lmp(wall_impact(0.5, 0.2, psi, ncontact=ncontact))
    assert res["slip"] == pytest.approx(reference_slip[psi], abs=0.03)
    # The impulse acts at the contact point: R w' = -(5/2) (v' - v0).
    assert res["spin"] == pytest.approx(-2.5 * (res["vx"] - 1.0), abs=1e-9)


def test_sliding_regime_matches_closed_form(lmp):
    """At large angles the contact slides throughout: the tangential impulse is mu_c times
    the integral of |F_n|, so s'/s0 = 1 - (7/2) mu_c J_n / psi."""
    psi, mu = 4.0, 0.2
    expected = 1.0 - 3.5 * mu * normal_impulse_magnitude(0.9) / psi
    res = lmp(wall_impact(0.5, mu, psi, ncontact=32))
    assert res["slip"] > 0.0    # still sliding forward
    assert res["slip"] == pytest.approx(expected, abs=0.005)


def test_small_angles_stick(reference_slip):
    """The reference itself: sticking (s' close to -e_t) at small angles, sliding at large."""
    assert reference_slip[0.2] == pytest.approx(-0.5, abs=0.02)
    assert reference_slip[4.0] > 0.5


def test_pair_oblique_impact_sticks_with_e_t(lmp):
    """Two equal spheres, mu_c huge: the slip of the contact points reverses with e_t, up to
    the turn of the line of centres during the contact, which feeds the normal speed into the
    slip: of order U t_c / (2 R) = 0.004 here (it is 0.04 at dt = 0.01 R/U)."""
    ut, gap0, ncontact = 0.1 * U, 0.2137, 8
    dt = 0.001 * R / U
    t_hit = gap0 * R / U
    steps = int((gap0 + 0.2) * R / U / dt) + 3 * ncontact
    res = lmp(scenes.HEADER.replace("${newton}", "on") + f"""
boundary p p p
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 1 box
create_atoms 1 single {-R - 0.5 * gap0 * R} {-0.5 * ut * t_hit} 0
create_atoms 1 single {R + 0.5 * gap0 * R} {0.5 * ut * t_hit} 0
set atom * diameter {2 * R} density {RHO}
velocity all set 0 0 0
set atom 1 vx {U / 2} vy {ut / 2}
set atom 2 vx {-U / 2} vy {-ut / 2}
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact {ncontact} friction 1e6 tangential 0.5
fix nve all nve/sphere
timestep {dt}
compute om all property/atom omegaz
group g1 id 1
group g2 id 2
compute w1 g1 reduce sum c_om
compute w2 g2 reduce sum c_om
thermo_style custom step c_w1 c_w2
thermo 0
neighbor {0.5 * R} bin
run {steps}
print "RESULT slip $((vy[1]-vy[2]+{R}*(c_w1+c_w2))/{ut}:%.15g)"
print "RESULT spin $((c_w1-c_w2):%.15g)"
""")
    assert res["slip"] == pytest.approx(-0.5, abs=0.004)
    assert res["spin"] == pytest.approx(0.0, abs=1e-9)    # equal spheres spin alike


def incline(theta_deg, mu, rolling=0.0, steps=3000):
    """A sphere resting on the zplane wall under gravity tilted by theta (an incline along x).
    Prints the x velocity and the slip speed after `steps` steps from rest."""
    dt = 1e-5
    g = 9.81
    return scenes.HEADER.replace("${newton}", "on") + f"""
region box block -0.5 0.5 -0.01 0.01 0 0.02
create_box 1 box
create_atoms 1 single 0 0 {R}
set atom 1 diameter {2 * R} density {RHO}
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix wall all wall/lubrication 0.5 tcontact 2e-4 friction {mu} rolling {rolling} zplane 0.0 NULL
fix grav all gravity {g} vector {math.sin(math.radians(theta_deg))} 0 {-math.cos(math.radians(theta_deg))}
fix nve all nve/sphere
timestep {dt}
compute om all property/atom omegay
compute wy all reduce sum c_om
thermo_style custom step c_wy
thermo 0
run {steps}
print "RESULT vx $(vx[1]:%.15g)"
print "RESULT slip $((vx[1]-{R}*c_wy):%.15g)"
print "RESULT t $({steps * dt}:%.15g)"
"""


def test_sphere_rolls_without_slipping_below_friction_angle(lmp):
    """tan(theta) < (7/2) mu_c: rolling without slip, a = (5/7) g sin(theta)."""
    res = lmp(incline(10.0, 0.5))
    a = 5.0 / 7.0 * 9.81 * math.sin(math.radians(10.0))
    assert res["vx"] == pytest.approx(a * res["t"], rel=0.01)
    assert abs(res["slip"]) < 1e-3 * res["vx"]


def test_sphere_slides_above_friction_angle(lmp):
    """tan(theta) > (7/2) mu_c: sliding, a = g (sin - mu_c cos), and the slip grows."""
    theta, mu = 40.0, 0.1
    res = lmp(incline(theta, mu))
    a = 9.81 * (math.sin(math.radians(theta)) - mu * math.cos(math.radians(theta)))
    assert res["vx"] == pytest.approx(a * res["t"], rel=0.01)
    assert res["slip"] > 0.3 * res["vx"]


def test_rolling_resistance_decelerates_a_rolling_sphere(lmp):
    """Constant rolling torque mu_r R m g on a sphere rolling without slip on a flat wall:
    deceleration (5/7) mu_r g (torque / (m R) through I + m R^2 = 7/5 m R^2)."""
    mu_r, v0, steps, dt = 0.05, 0.05, 3000, 1e-5
    script = incline(0.0, 0.5, rolling=mu_r, steps=steps).replace(
        "fix nve all nve/sphere",
        f"velocity all set {v0} 0 0\nset atom 1 omega 0 {v0 / R} 0\nfix nve all nve/sphere")
    res = lmp(script)
    decel = 5.0 / 7.0 * mu_r * 9.81
    assert res["vx"] == pytest.approx(v0 - decel * steps * dt, rel=0.01)


def test_friction_off_is_the_normal_model(lmp):
    """friction 0 (the default) leaves a slipping sphere's tangential motion untouched."""
    res = lmp(wall_impact(0.5, 0.0, 1.0).replace("friction 0.0 tangential 0.5", ""))
    assert res["slip"] == pytest.approx(1.0, abs=1e-12) and res["spin"] == 0.0


def shear_film(mu_f, steps):
    """A sphere sliding along the wall at a fixed gap eps = 0.01 inside the film, no spin."""
    dt = 0.005 * R / U
    return scenes.HEADER.replace("${newton}", "on") + f"""
region box block -0.5 0.5 -0.01 0.01 0 0.02
create_box 1 box
create_atoms 1 single 0 0 {R * 1.01}
set atom 1 diameter {2 * R} density {RHO}
velocity all set {U} 0 0
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix wall all wall/lubrication 0.9 viscosity {mu_f} activation 0.09375 shearfilm yes zplane 0.0 NULL
fix nve all nve/sphere
timestep {dt}
compute om all property/atom omegay
compute wy all reduce sum c_om
thermo_style custom step c_wy
thermo 0
run {steps}
print "RESULT slip $((vx[1]-{R}*c_wy)/{U}:%.15g)"
print "RESULT t $({steps * dt}:%.15g)"
"""


@pytest.mark.parametrize("stokes", [1000.0, 10.0, 0.01])
def test_shear_film_decays_slip_exactly_and_never_reverses_it(lmp, stokes):
    """At fixed gap the slip obeys m_t s' = -2 pi mu R ln(eps_al/eps) s: each full step
    multiplies it by exp(-x), x = rate dt, exactly (the per-step exponential), however stiff
    (St = 0.01: x ~ 40). Velocity Verlet's half kicks at the run's ends apply half a step of
    the same force: s_end = s0 (1 - f/2)^2 exp(-(N-1) x) with f = 1 - exp(-x)."""
    mu_f = scenes.viscosity_for_stokes(stokes)
    steps = 200
    res = lmp(shear_film(mu_f, steps))
    rate = 2 * math.pi * mu_f * R * math.log(0.09375 / 0.01) / (2.0 / 7.0 * MASS)
    x = rate * res["t"] / steps
    half = 1.0 - 0.5 * (-math.expm1(-x))
    assert res["slip"] == pytest.approx(half * half * math.exp(-(steps - 1) * x), rel=1e-9, abs=1e-15)
    assert res["slip"] >= 0.0
    if x < 0.01:    # and the continuous solution, to O(x^2) from the ends
        assert res["slip"] == pytest.approx(math.exp(-rate * res["t"]), rel=x * x)


def frictional_scene(newton="on", neighbor_every=1, steps=1200, extra_run="", shift=0.0):
    """Four spheres in a box periodic in x, split at x = 0 by a 2 x 1 x 1 grid: an oblique,
    long (N_c = 128) frictional collision of a pair drifting at 5 U, so that the contact
    straddles x = 0 and one sphere migrates while in contact; a sphere rolling and slipping on
    the floor across both boundaries; all of them landing on the floor under gravity.
    shift = 4.5 R moves the collision onto the periodic boundary x = +-6 R instead: the
    pair then flips its order in the half list, so the partner's copy of the history (sent
    to ghost owners by reverse communication under newton on) is the one that is used."""
    dt = 0.005 * R / U
    return scenes.HEADER.replace("${newton}", newton) + f"""
boundary p p f
region box block -0.006 0.006 -0.003 0.003 0 0.006
create_box 1 box
create_atoms 1 single {(-2.65 + shift) * R} {-0.06 * R} {3 * R}
create_atoms 1 single {(-0.55 + shift) * R} {0.06 * R} {3 * R}
create_atoms 1 single {-2.0 * R} 0 {R * 0.999}
create_atoms 1 single {-4.0 * R} {1.5 * R} {R * 0.999}
set atom * diameter {2 * R} density {RHO}
velocity all set 0 0 0
set atom 1 vx {5.4 * U} vy {0.1 * U}
set atom 2 vx {4.6 * U} vy {-0.1 * U}
set atom 3 vx {2.0 * U} omega 0 {0.5 * U / R} 0
set atom 4 vx {0.4 * U}
pair_style lubricated/springdashpot
pair_coeff * * 0.8 ncontact 128 friction 0.3 tangential 0.6 rolling 0.02
fix wall all wall/lubrication 0.7 ncontact 128 friction 0.4 tangential 0.5 zplane 0.0 NULL
fix grav all gravity 9.81 vector 0 0 -1
fix nve all nve/sphere
timestep {dt}
neighbor {0.5 * R} bin
neigh_modify every {neighbor_every} delay 0 check no
thermo 200
run {steps}
{extra_run}
"""


def assert_same(a, b, rel=1e-10):
    assert a.keys() == b.keys() and len(a) >= 8
    for key in a:
        assert b[key] == pytest.approx(a[key], rel=rel, abs=1e-13), key


@pytest.mark.parametrize("shift", [0.0, 4.5])
def test_history_survives_list_rebuilds(lmp, shift):
    """Rebuilding the list (and migrating atoms) every step or every 8th gives the same
    motion: the elongations are carried through every rebuild by partner tag. (8 steps move
    no sphere more than 0.2 R < skin / 2; 1200 is a multiple of 8, so both end wrapped alike.)"""
    every_step = lmp(frictional_scene(neighbor_every=1, shift=shift) + dump_state(4))
    rarely = lmp(frictional_scene(neighbor_every=8, shift=shift) + dump_state(4))
    assert_same(every_step, rarely)
    # The scene is a test only if friction acted: the floor slowed the slipping sphere 3.
    if shift == 0.0:
        assert every_step["v3"][0] < 1.9 * U


@pytest.mark.parametrize("shift", [0.0, 4.5])
@pytest.mark.parametrize("newton", ["on", "off"])
def test_one_and_two_ranks_agree_with_friction(lmp, newton, shift):
    serial = lmp(frictional_scene(newton, shift=shift) + dump_state(4))
    parallel = lmp(frictional_scene(newton, shift=shift) + dump_state(4), nprocs=2)
    assert "2 by 1 by 1 MPI processor grid" in lmp.log
    assert_same(serial, parallel)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_restart_continues_with_contact_history(lmp, nprocs):
    """run 600; write_restart (contacts open); run 600 == read_restart; same fixes; run 600 ==
    run 1200 (the restart file keeps the last step's velocities too)."""
    reference = lmp(frictional_scene(steps=600, extra_run="write_restart mid.restart\nrun 600")
                    + dump_state(4), nprocs=nprocs)
    restarted = lmp(f"""plugin load ${{plugin}}
read_restart mid.restart
comm_modify vel yes
fix wall all wall/lubrication 0.7 ncontact 128 friction 0.4 tangential 0.5 zplane 0.0 NULL
fix grav all gravity 9.81 vector 0 0 -1
fix nve all nve/sphere
timestep {0.005 * R / U}
neighbor {0.5 * R} bin
neigh_modify every 1 delay 0 check no
run 600
""" + dump_state(4), nprocs=nprocs, name="in.restart")
    assert_same(reference, restarted, rel=1e-12)
    assert_same(lmp(frictional_scene(steps=1200) + dump_state(4), nprocs=nprocs), reference, rel=1e-12)


def order_flip_scene(newton="on"):
    """Two spheres meeting across x = 0 (the boundary of a 2 x 1 x 1 grid) while sliding past
    each other in y: their y order flips during the contact. A half list under newton on
    keeps a cross-rank pair on the rank of the atom whose bin sorts lower (z, then y, then x);
    bins of size R put a bin boundary at y = 0, so the flip moves the pair to the other rank,
    which computes it with the history it received for its atom by reverse communication at
    the last rebuild (every step here). Losing that copy would restart the tangential spring
    from zero and change the motion."""
    dt = 0.005 * R / U
    return scenes.HEADER.replace("${newton}", newton) + f"""
boundary p p p
region box block -0.006 0.006 -0.002 0.002 -0.002 0.002
create_box 1 box
create_atoms 1 single {-1.005 * R} {-0.03 * R} {0.5 * R}
create_atoms 1 single {1.005 * R} {0.03 * R} {0.5 * R}
set atom * diameter {2 * R} density {RHO}
velocity all set 0 0 0
set atom 1 vx {0.1 * U} vy {0.1 * U}
set atom 2 vx {-0.1 * U} vy {-0.1 * U}
pair_style lubricated/springdashpot
pair_coeff * * 0.8 ncontact 128 friction 0.3 tangential 0.6
fix nve all nve/sphere
timestep {dt}
neighbor {0.5 * R} bin
neigh_modify every 1 delay 0 check no binsize {R}
run 200
"""


def test_history_follows_a_pair_that_changes_rank(lmp):
    serial = lmp(order_flip_scene() + dump_state(2))
    parallel = lmp(order_flip_scene() + dump_state(2), nprocs=2)
    assert "2 by 1 by 1 MPI processor grid" in lmp.log
    assert serial.keys() == parallel.keys() and len(serial) == 4
    for key in serial:
        assert parallel[key] == pytest.approx(serial[key], rel=1e-10, abs=1e-13), key
    # Friction acted on the sliding (the relative y speed was 0.2 U) and the order flipped.
    assert abs(serial["v1"][1] - serial["v2"][1]) < 0.15 * U
    assert serial["x1"][1] > serial["x2"][1]


def split_wall_impact(first, zero_runs, e_t=0.5, mu=0.3, psi=1.0):
    """wall_impact() with its run split after `first` steps and `zero_runs` times `run 0` between."""
    script = wall_impact(e_t, mu, psi)
    run = next(line for line in script.splitlines() if line.startswith("run "))
    steps = int(run.split()[1])
    return script.replace(run, f"run {first}\n" + "run 0\n" * zero_runs + f"run {steps - first}")


@pytest.mark.parametrize("first", [22, 25])    # the sphere touches the wall in steps 22-29
def test_run_0_inside_a_frictional_wall_contact_changes_nothing(lmp, first):
    """Issue 18: each `run 0` re-applied the tangential history (slip ratio -0.643 split, -0.686
    with one `run 0`, -0.774 with three). A set-up evaluation lets no time pass: it lengthens
    and stores no elongation, so any number of them leaves the run as it was."""
    split = lmp(split_wall_impact(first, 0))
    for zero_runs in (1, 3):
        assert lmp(split_wall_impact(first, zero_runs)) == split, zero_runs
    # The second run's set-up continues the first run's last step (src/fix_step_velocity): the
    # split run ends as the single one (before: e 0.879 for 0.9, slip ratio -0.503 for -0.5).
    single = lmp(wall_impact(0.5, 0.3, 1.0))
    for key in single:
        assert split[key] == pytest.approx(single[key], rel=1e-12, abs=1e-14), key


@pytest.mark.parametrize("nprocs", [1, 2])
def test_run_0_between_runs_of_a_frictional_bed_changes_nothing(lmp, nprocs):
    """Pairs and walls in contact (across ranks and the periodic boundary on 2 ranks): run 600;
    run 600 against run 600; run 0 (three times); run 600, bit for bit; and both as run 1200
    (to rounding: the set-up restores the last step's velocities from v and f)."""
    plain = lmp(frictional_scene(steps=600, extra_run="run 600") + dump_state(4), nprocs=nprocs)
    zeros = lmp(frictional_scene(steps=600, extra_run="run 0\nrun 0\nrun 0\nrun 600") + dump_state(4), nprocs=nprocs)
    assert zeros == plain
    single = lmp(frictional_scene(steps=1200) + dump_state(4), nprocs=nprocs)
    assert_same(single, plain, rel=1e-12)


def test_wall_elongation_is_forgotten_away_from_the_wall(lmp):
    """A sphere stopped mid-contact (elongation stored, touched) is moved far from the wall for a
    few steps, then put back into a small overlap at rest, without spin. Out of reach the wall
    forgets the elongation (the plane walls' pre-test keeps the atoms that hold one), so the
    sphere is pushed off along the normal alone: no tangential velocity or spin (with the stale
    elongation, a tangential spring force of the first contact's order acts)."""
    script = wall_impact(0.5, 1e6, 1.0)
    run = next(line for line in script.splitlines() if line.startswith("run "))
    again = f"""run 25
set atom 1 z {5 * R}
velocity all set 0 0 0
set atom 1 omega 0 0 0
run 5
set atom 1 z {R * (1 - 1e-3)}
run 10
print "RESULT vx_again $(vx[1]/{U}:%.15g)"
print "RESULT spin_again $({R}*c_wy/{U}:%.15g)"
print "RESULT vz_again $(vz[1]/{U}:%.15g)"
"""
    res = lmp(script.replace(run, again))
    assert res["vz_again"] > 1e-3    # the overlap did push the sphere off
    assert abs(res["vx_again"]) < 1e-12
    assert abs(res["spin_again"]) < 1e-12

"""Curved and moving walls of fix wall/lubrication (doc/fix_wall_lubrication.rst, "Curved and
moving walls"; lubricated/wall_geometry.h; the film radius R_f: doc/model.rst "Curved walls").

- A translating wall is a Galilean change of frame: a sphere hitting it at U while it moves at W
  rebounds, in the wall's frame, exactly as from a wall at rest hit at U + W, dry (e_d) and wet
  (the same St), to round-off.
- A wiggling wall accelerates: in its frame the sphere feels the pseudo-force -m a_w, so the
  rebound keeps e_d up to that force's impulse over the contact, at most max|a_w| t_c.
- A head-on impact on a cylinder (along a radius, where the gap is linear in the motion) is the
  plane impact of a sphere with the same mass and the film radius R_f = sqrt(R a),
  a = R R_w / (R_w -+ R): dry e_d to round-off, wet the plane's e for a sphere of radius R_f and
  mass m, to round-off; for R_w = 1000 R the plane's own e.
- A sphere in a rotating drum with friction, rolling resistance and a viscous damping of its
  centre settles where friction holds gravity and the rolling torque balances the friction
  torque: tan(theta) = mu_r R_f / R, rolling without slip on the moving wall (|omega| R = V).
- 1 and 2 ranks agree; a restart in the middle continues the wiggle and the drum as one run.
"""
import math

import pytest

import scenes
from scene_chain import dump_state
from test_tangential import assert_same

R, U, RHO = scenes.R, scenes.U, scenes.RHO
MASS = RHO * 4.0 / 3.0 * math.pi * R**3
DT = 0.01 * R / U    # N_c = 8: t_c = 0.08 R/U
MU_WET = scenes.viscosity_for_stokes(100)


def impact(wall, e_d=0.5, speed=U, start=(0.0, 0.0, R * 1.2137), velocity_dir=(0, 0, -1), radius=R, rho=RHO,
           wet=False, steps=None, box="-0.01 0.01 -0.01 0.01 -0.01 0.02"):
    """One sphere hits `wall` (the wall style and motion words of the fix); prints its final
    velocity and the time elapsed."""
    steps = steps or int(1.0 * R / U / DT) + 80
    film = f"viscosity {MU_WET} activation {scenes.EPS_AL}" if wet else ""
    vx, vy, vz = (speed * c for c in velocity_dir)
    return scenes.HEADER.replace("${newton}", "on").replace("boundary p p f", "boundary f f f") + f"""
region box block {box}
create_box 1 box
create_atoms 1 single {start[0]} {start[1]} {start[2]}
set atom 1 diameter {2 * radius} density {rho}
velocity all set {vx} {vy} {vz}
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix wall all wall/lubrication {e_d} ncontact 8 {film} {wall}
fix nve all nve/sphere
timestep {DT}
thermo 0
run {steps}
print "RESULT v $(vx[1]:%.17g) $(vy[1]:%.17g) $(vz[1]:%.17g)"
print "RESULT t $(time:%.17g)"
"""


@pytest.mark.parametrize("wet", [False, True], ids=["dry", "wet"])
def test_translating_wall_rebounds_as_a_wall_at_rest_in_its_frame(lmp, wet):
    """Wall moving up at W = 0.6 U (and sideways, which leaves a frictionless impact alone),
    sphere down at U: (v' - W) / (U + W) equals the rebound from a wall at rest hit at U + W."""
    w = 0.6 * U
    rest = lmp(impact("zplane 0.0 NULL", speed=U + w, wet=wet))["v"][2] / (U + w)
    moving = lmp(impact(f"zplane 0.0 NULL translate {0.3 * U} 0 {w}", wet=wet))
    relative = (moving["v"][2] - w) / (U + w)
    assert relative == pytest.approx(rest, rel=1e-9)
    if not wet:
        assert rest == pytest.approx(0.5, rel=1e-10)    # the step-exact contact: e_d to round-off
    else:
        assert 0.2 < rest < 0.45    # the film took its share
    # In the lab the rebound is far from e_d: the test sees the wall's motion.
    assert abs(moving["v"][2] / U - rest) > 0.5


def test_wiggling_wall_keeps_e_d_up_to_its_acceleration(lmp):
    """The sphere meets the wall (z = A (1 - cos wt)) so that the contact is centred on t = T/4,
    where the wall is fastest (A w) and its acceleration changes sign. The rebound in the wall's
    frame, (v' - v_w(t_exit)) / (U + v_w(t_entry)), misses e_d by at most the pseudo-force's
    impulse over the contact, max|a_w| t_c / u_rel with max|a_w| = A w^2 sin(w t_c / 2)."""
    e_d, t_c = 0.5, 8 * DT
    period = 40 * t_c
    omega = 2 * math.pi / period
    amplitude = 0.5 * U / omega
    t_in = period / 4 - t_c / 2
    z0 = R + U * t_in + amplitude * (1 - math.cos(omega * t_in))
    res = lmp(impact(f"zplane 0.0 NULL wiggle z {amplitude} {period}", e_d=e_d, start=(0, 0, z0),
                     steps=int(round((t_in + 3 * t_c) / DT))))
    v_wall = lambda t: amplitude * omega * math.sin(omega * t)    # noqa: E731
    u_rel = U + v_wall(t_in)
    e = (res["v"][2] - v_wall(t_in + t_c)) / u_rel
    bound = amplitude * omega**2 * math.sin(omega * t_c / 2) * t_c / u_rel
    assert e == pytest.approx(e_d, abs=bound)
    # The bound is tight enough to see the wall's speed: the lab-frame rebound is far off.
    assert abs(res["v"][2] / U - e_d) > 10 * bound


def cylinder_film_radius(radius, wall_radius, inside):
    a = radius * wall_radius / (wall_radius - radius if inside else wall_radius + radius)
    return math.sqrt(radius * a)


@pytest.mark.parametrize("inside", [True, False], ids=["inside", "outside"])
@pytest.mark.parametrize("wall_radius", [3 * R, 1000 * R])
def test_head_on_cylinder_impact_is_the_plane_impact_with_the_film_radius(lmp, wall_radius, inside):
    gap0 = 0.2137 * R
    if inside:    # from near the axis outwards along +x
        x0, direction, side = wall_radius - R - gap0, (1, 0, 0), ""
    else:         # from outside inwards along -x
        x0, direction, side = wall_radius + R + gap0, (-1, 0, 0), "side out"
    box = f"{wall_radius - 6 * R} {wall_radius + 6 * R} -0.01 0.01 -0.01 0.01"    # around the impact
    cylinder = f"zcylinder {wall_radius} {side}"
    dry = lmp(impact(cylinder, start=(x0, 0, 0), velocity_dir=direction, box=box))["v"][0]
    assert abs(dry) / U == pytest.approx(0.5, rel=1e-9)
    wet = abs(lmp(impact(cylinder, start=(x0, 0, 0), velocity_dir=direction, box=box, wet=True))["v"][0]) / U
    # The plane with a sphere of radius R_f and the same mass (density scaled), at the same gap.
    r_f = cylinder_film_radius(R, wall_radius, inside)
    plane_rf = lmp(impact("zplane 0.0 NULL", start=(0, 0, r_f + gap0), radius=r_f, rho=RHO * (R / r_f)**3,
                          wet=True))["v"][2] / U
    plane_r = lmp(impact("zplane 0.0 NULL", wet=True))["v"][2] / U
    assert wet == pytest.approx(plane_rf, rel=1e-9)
    if wall_radius > 100 * R:
        assert wet == pytest.approx(plane_r, abs=2e-3)
    else:    # and R_f matters: the sphere's own radius would be far off
        assert abs(plane_rf - plane_r) > 0.02


V_DRUM, R_DRUM, MU_R = 0.05, 10 * R, 0.1


def drum(steps, extra_fix="", extra_run="", wiggle=""):
    """A sphere at rest at the bottom of a drum (zcylinder 10 R, gravity along -y) that turns with
    surface speed V (shear x V: clockwise seen from +z, the bottom moves along -x); friction 0.5,
    rolling resistance mu_r; fix viscous damps the centre's swinging (not its spin)."""
    t_c = 1e-3
    return scenes.HEADER.replace("${newton}", "on").replace("boundary p p f", "boundary f f p") + f"""
region box block -0.012 0.012 -0.012 0.012 -0.002 0.002
create_box 1 box
create_atoms 1 single 0 {-(R_DRUM - R)} 0
set atom 1 diameter {2 * R} density {RHO}
velocity all set 0 0 0
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix wall all wall/lubrication 0.5 tcontact {t_c} friction 0.5 rolling {MU_R} zcylinder {R_DRUM} shear x {V_DRUM} {wiggle}
fix grav all gravity 9.81 vector 0 -1 0
fix damp all viscous 2e-3
fix nve all nve/sphere
{extra_fix}
timestep {t_c / 8}
compute om all property/atom omegaz
compute wz all reduce sum c_om
thermo_style custom step c_wz
thermo 1000
run {steps}
{extra_run}
print "RESULT theta $(atan2(-x[1],-y[1]):%.17g)"
print "RESULT spin $(c_wz*{R}/{V_DRUM}:%.17g)"
print "RESULT speed $(sqrt(vx[1]^2+vy[1]^2)/{V_DRUM}:%.17g)"
"""


def test_sphere_in_a_rotating_drum_rolls_at_the_rolling_resistance_angle(lmp):
    """Steady state: the centre at rest, so friction F_t = m g sin(theta) and N = m g cos(theta);
    the spin steady, so R F_t = mu_r R_f N: tan(theta) = mu_r R_f / R, on the side the bottom
    moves to (x < 0); the sphere rolls on the wall without slip: |omega| R = V."""
    res = lmp(drum(16000))
    r_f = cylinder_film_radius(R, R_DRUM, True)
    assert res["speed"] < 1e-6
    assert math.tan(res["theta"]) == pytest.approx(MU_R * r_f / R, rel=1e-3)
    assert abs(res["spin"]) == pytest.approx(1.0, rel=1e-3)
    # With the spin instead of the spin relative to the wall... a turning wall that did not move its
    # surface would leave the sphere at the bottom.
    assert res["theta"] > 0.05


def drum_scene(steps=1200, extra_run=""):
    """Four wet frictional spheres in a drum that turns and wiggles along x, on both sides of x = 0
    (the ranks' boundary), with rolling and shear film."""
    dt = 1e-3 / 16
    mu = scenes.viscosity_for_stokes(200)
    return scenes.HEADER.replace("${newton}", "on").replace("boundary p p f", "boundary f f p") + f"""
processors * 1 1
region box block -0.012 0.012 -0.012 0.012 -0.002 0.002
create_box 1 box
create_atoms 1 single {-2.5 * R} {-(R_DRUM - 1.02 * R)} 0
create_atoms 1 single {2.3 * R} {-(R_DRUM - 2.0 * R)} {0.3 * R}
create_atoms 1 single {0.2 * R} {-(R_DRUM - 4.5 * R)} 0
create_atoms 1 single {-6.0 * R} {-5.0 * R} {-0.2 * R}
set atom * diameter {2 * R} density {RHO}
velocity all set 0 0 0
set atom 3 vx 0.02
set atom 4 vx -0.04 vy -0.03
reset_timestep 1000 time 0.0123
pair_style lubricated/springdashpot
pair_coeff * * 0.8 tcontact 1e-3 friction 0.3 rolling 0.02 viscosity {mu} activation 0.1
fix wall all wall/lubrication 0.7 tcontact 1e-3 friction 0.4 rolling 0.05 viscosity {mu} activation 0.1 """ \
        f"""zcylinder {R_DRUM} shear x {V_DRUM} wiggle x {0.3 * R} 0.02
fix grav all gravity 9.81 vector 0 -1 0
fix nve all nve/sphere
timestep {dt}
neighbor {0.5 * R} bin
neigh_modify every 1 delay 0 check no
thermo 200
run {steps}
{extra_run}
"""


def test_drum_one_and_two_ranks_agree(lmp):
    serial = lmp(drum_scene() + dump_state(4))
    parallel = lmp(drum_scene() + dump_state(4), nprocs=2)
    assert "2 by 1 by 1 MPI processor grid" in lmp.log
    assert_same(serial, parallel)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_restart_continues_the_moving_drum(lmp, nprocs):
    """write_restart at step 600 (spheres on the turning, wiggling wall, friction history open);
    a new process reads it, defines the fixes again and runs 600 steps: as the uninterrupted run.
    The wiggle's phase comes from the restart file: the fix was defined at t = 0.0123, and a fix
    defined anew would start its wiggle again."""
    single = lmp(drum_scene() + dump_state(4), nprocs=nprocs)
    lmp(drum_scene(steps=600, extra_run="write_restart mid.restart"), nprocs=nprocs)
    fixes = [line for line in drum_scene().splitlines()
             if line.startswith(("fix ", "timestep", "neighbor", "neigh_modify"))]
    restarted = lmp("plugin load ${plugin}\nread_restart mid.restart\ncomm_modify vel yes\n" + "\n".join(fixes)
                    + "\nrun 600\n" + dump_state(4), nprocs=nprocs, name="in.restart")
    assert_same(single, restarted, rel=1e-12)
    # The wall redefined without friction and rolling keeps no history and drops the file's (it
    # wrote through a null history: a segfault); the spheres then slide on the turning wall.
    frictionless = [line.replace(" friction 0.4 rolling 0.05", "") for line in fixes]
    assert frictionless != fixes
    slid = lmp("plugin load ${plugin}\nread_restart mid.restart\ncomm_modify vel yes\n" + "\n".join(frictionless)
               + "\nrun 600\n" + dump_state(4), nprocs=nprocs, name="in.frictionless")
    assert slid.keys() == single.keys()
    assert slid["v1"] != pytest.approx(single["v1"], rel=1e-3)

"""fix wall/lubrication/region (doc/fix_wall_lubrication_region.rst): the wall of fix
wall/lubrication on a region's surface, static, moving or rotating.

- A flat face of a block region is the plane wall: the trajectory of fix wall/lubrication
  zplane, dry and wet, with friction and rolling, to round-off (the same kernel, the same gap
  and normal; only the order of additions differs).
- Curved surfaces (doc/model.rst, "Curved walls"): the normal motion of a sphere of radius R
  and mass m against a wall of film radius R_f = sqrt(a b) obeys the same equation as a
  sphere of radius R_f and mass m against a plane (the spring-dashpot depends on m and t_c
  only, the film on h, u_n and R_f), so a bounce inside a sphere region, outside it and
  inside a cylinder region equals that plane bounce to round-off; for R_w = 1000 R it is the
  plane bounce of the sphere itself within 1e-3.
- Moving walls: a floor moving up at W returns the sphere with e_d in the floor's frame; a
  floor sliding under a resting sphere pulls it with mu F_n (Coulomb); a rotating inner
  cylinder (Couette cell) transmits the torque mu F_n (r - R) about its axis, with the sign of
  its rotation.
- Two faces at once: a sphere pressed into a block's corner with friction follows the two
  plane walls xplane and zplane to round-off (one friction history per face).
- Many bodies: three wet films of one floor on one sphere share the pair style's film budget
  (without it the sphere is thrown back at twice its speed each step: energy x4); a wet
  cluster in a sphere region never gains energy.
- 1 = 2 ranks, a restart in the middle of frictional contacts continues the run, bad input.
"""
import math

import pytest

from scene_chain import dump_state

R = 1.0e-3
U = 0.1
RHO = 8000.0
DT = 0.005 * R / U
EPS_AL = 0.09375

HEADER = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary p p f
comm_modify vel yes
"""


def bounce(wall, radius=R, density=RHO, x0=(0.0, 0.0, 1.2137 * R), v0=(0.0, 0.0, -U), steps=600,
           extra_regions="", box="-0.01 0.01 -0.01 0.01 -0.01 0.02", integrator="nve/sphere", spin=None):
    """One sphere and a wall; prints its final state and its state mid-way."""
    spin_line = f"set atom 1 omega {spin[0]} {spin[1]} {spin[2]}" if spin else ""
    return HEADER + f"""
region box block {box}
create_box 1 box
create_atoms 1 single {x0[0]} {x0[1]} {x0[2]}
set atom 1 diameter {2 * radius} density {density}
velocity all set {v0[0]} {v0[1]} {v0[2]}
{spin_line}
{extra_regions}
{wall}
fix nve all {integrator}
compute om all property/atom omegax omegay omegaz
compute spin all reduce sum c_om[1] c_om[2] c_om[3]
timestep {DT}
thermo_style custom step c_spin[1]
thermo 0
run {steps // 3}
print "RESULT mid $(x[1]:%.17g) $(y[1]:%.17g) $(z[1]:%.17g) $(vx[1]:%.17g) $(vy[1]:%.17g) $(vz[1]:%.17g)"
run {steps - steps // 3}
print "RESULT x $(x[1]:%.17g) $(y[1]:%.17g) $(z[1]:%.17g)"
print "RESULT v $(vx[1]:%.17g) $(vy[1]:%.17g) $(vz[1]:%.17g)"
print "RESULT w $(c_spin[1]:%.17g) $(c_spin[2]:%.17g) $(c_spin[3]:%.17g)"
"""


def region_wall(keywords, region_id, fix_id="wall"):
    """fix ... wall/lubrication/region e_d regionID keywords, from 'e_d keywords'."""
    e_d, _, rest = keywords.partition(" ")
    return f"fix {fix_id} all wall/lubrication/region {e_d} {region_id} {rest}"


def close(a, b, rel, abs_=1e-15):
    assert a.keys() == b.keys()
    for key in a:
        assert b[key] == pytest.approx(a[key], rel=rel, abs=abs_), key


KEYWORDS = {
    "dry": "0.5",
    "wet": f"0.9 viscosity 2e-3 activation {EPS_AL}",
    "friction": f"0.7 friction 0.3 tangential 0.5 rolling 0.02 viscosity 1e-3 activation {EPS_AL}",
}


@pytest.mark.parametrize("case", sorted(KEYWORDS))
def test_flat_face_is_the_plane_wall(lmp, case):
    """A block's lower face at z = 0 against fix wall/lubrication zplane 0.0: an oblique,
    spinning impact (friction, rolling, shear film in the third case)."""
    kw = KEYWORDS[case]
    kwargs = dict(v0=(0.03, -0.01, -U), spin=(20.0, -5.0, 3.0))
    plane = lmp(bounce(f"fix wall all wall/lubrication {kw} zplane 0.0 NULL", **kwargs))
    region = lmp(bounce(region_wall(kw, "floor"),
                        extra_regions="region floor block INF INF INF INF 0.0 INF", **kwargs))
    close(plane, region, rel=1e-12)
    if case == "dry":    # e_d itself (the sphere left the wall)
        assert region["v"][2] / U == pytest.approx(0.5, rel=1e-9)
    assert region["v"][2] > 0.0


def corner_scene(walls, steps=1500):
    """A spinning sphere thrown into the corner x = 0, z = 0 under a slanted gravity, where it
    stays pressed on both faces, rolling and sliding (two frictional contacts at once)."""
    return HEADER + f"""
region box block -0.01 0.01 -0.01 0.01 -0.01 0.02
create_box 1 box
create_atoms 1 single {1.3 * R} 0 {1.2 * R}
set atom 1 diameter {2 * R} density {RHO}
velocity all set -0.05 0.02 -0.08
set atom 1 omega 30 -40 10
{walls}
fix g all gravity 9.81 vector -0.6 0.3 -1
fix nve all nve/sphere
compute om all property/atom omegax omegay omegaz
compute spin all reduce sum c_om[1] c_om[2] c_om[3]
timestep {DT}
thermo_style custom step c_spin[1]
thermo 0
run {steps // 2}
print "RESULT mid $(x[1]:%.17g) $(y[1]:%.17g) $(z[1]:%.17g) $(vx[1]:%.17g) $(vy[1]:%.17g) $(vz[1]:%.17g)"
run {steps - steps // 2}
print "RESULT x $(x[1]:%.17g) $(y[1]:%.17g) $(z[1]:%.17g)"
print "RESULT v $(vx[1]:%.17g) $(vy[1]:%.17g) $(vz[1]:%.17g)"
print "RESULT w $(c_spin[1]:%.17g) $(c_spin[2]:%.17g) $(c_spin[3]:%.17g)"
"""


@pytest.mark.parametrize("kw", [KEYWORDS["friction"], "0.5 friction 0.4 tangential 0.3"], ids=["wet", "dry"])
def test_corner_of_a_block_is_two_plane_walls(lmp, kw):
    """Two faces of one block region at once (one friction history per face) follow the two
    plane walls xplane 0 and zplane 0 of fix wall/lubrication to round-off."""
    e_d, _, rest = kw.partition(" ")
    planes = lmp(corner_scene(f"fix wx all wall/lubrication {kw} xplane 0.0 NULL\n"
                              f"fix wz all wall/lubrication {kw} zplane 0.0 NULL"))
    region = lmp(corner_scene("region corner block 0.0 INF INF INF 0.0 INF units box\n" +
                              region_wall(kw, "corner")))
    close(planes, region, rel=1e-11, abs_=1e-14)
    # In the corner at the end, pressed on both faces.
    assert region["x"][0] < 1.001 * R and region["x"][2] < 1.001 * R


def plane_of_radius(film_radius, kw, steps=900):
    """The sphere of mass m and radius R_f bouncing on a plane from the same gap at U."""
    density = RHO * (R / film_radius) ** 3
    gap0 = 0.2137 * R
    return bounce(f"fix wall all wall/lubrication {kw} zplane 0.0 NULL", radius=film_radius, density=density,
                  x0=(0.0, 0.0, film_radius + gap0), steps=steps)


def normal_speed_ratio(result, direction):
    v = result["v"]
    return (v[0] * direction[0] + v[1] * direction[1] + v[2] * direction[2]) / U


# region line, start position, velocity, unit normal from the wall to the sphere, film radius
def curved_cases(rw):
    gap0 = 0.2137 * R
    inside = rw - R - gap0          # centre distance from the region's centre, inside
    outside = rw + R + gap0         # outside
    return {
        # concave sphere: R_w = -rw, a = b = R rw / (rw - R)
        "sphere_inside": (f"region wall sphere 0 0 0 {rw} side in", (inside, 0.0, 0.0), (U, 0.0, 0.0),
                          (-1.0, 0.0, 0.0), R * rw / (rw - R)),
        # convex sphere: R_w = +rw, a = b = R rw / (rw + R)
        "sphere_outside": (f"region wall sphere 0 0 0 {rw} side out", (outside, 0.0, 0.0), (-U, 0.0, 0.0),
                           (1.0, 0.0, 0.0), R * rw / (rw + R)),
        # concave cylinder along z: a = R rw / (rw - R), b = R
        "cylinder_inside": (f"region wall cylinder z 0 0 {rw} INF INF side in", (0.0, inside, 0.0), (0.0, U, 0.0),
                            (0.0, -1.0, 0.0), math.sqrt(R * R * rw / (rw - R))),
    }


WET = f"0.9 viscosity 4e-3 activation {EPS_AL}"    # St = (2/9) rho R U / mu = 44


@pytest.mark.parametrize("case", ["sphere_inside", "sphere_outside", "cylinder_inside"])
def test_curved_wall_is_the_plane_of_the_film_radius(lmp, case):
    rw = 3.0 * R
    region, x0, v0, normal, film_radius = curved_cases(rw)[case]
    box = f"{-2 * rw - 0.01} {2 * rw + 0.01} {-2 * rw - 0.01} {2 * rw + 0.01} -0.01 0.01"
    curved = lmp(bounce(region_wall(WET, "wall"), x0=x0, v0=v0, extra_regions=region,
                        box=box, steps=900))
    flat = lmp(plane_of_radius(film_radius, WET))
    e_curved = normal_speed_ratio(curved, normal)
    e_flat = flat["v"][2] / U
    assert 0.05 < e_flat < 0.85    # wet: the film took a good part of e_d = 0.9
    assert e_curved == pytest.approx(e_flat, rel=1e-9)
    # ... and the film radius matters: the sphere's own radius gives another restitution.
    e_own = lmp(plane_of_radius(R, WET))["v"][2] / U
    assert abs(e_own - e_curved) > 0.01


@pytest.mark.parametrize("case", ["sphere_inside", "cylinder_inside"])
def test_large_curved_wall_is_the_plane(lmp, case):
    """R_w = 1e4 R: R_f = R (1 + 1e-4) (sphere) or R (1 + 5e-5) (cylinder); the film's loss,
    proportional to R_f^2, changes e by about 2e-4 of ln(e_d / e) ~ 1e-4."""
    rw = 1.0e4 * R
    region, x0, v0, normal, _ = curved_cases(rw)[case]
    box = f"{-rw - 0.01} {rw + 0.01} {-rw - 0.01} {rw + 0.01} -0.01 0.01"
    curved = lmp(bounce(region_wall(WET, "wall"), x0=x0, v0=v0, extra_regions=region,
                        box=box, steps=900))
    flat = lmp(plane_of_radius(R, WET))
    assert normal_speed_ratio(curved, normal) == pytest.approx(flat["v"][2] / U, rel=1e-3)


W = 0.05    # the wall's speed


@pytest.mark.parametrize("kw", ["0.5", f"0.9 viscosity 4e-3 activation {EPS_AL}"], ids=["dry", "wet"])
def test_moving_floor_bounces_in_its_frame(lmp, kw):
    """A floor moving up at W (region move, displacement W t): in the floor's frame the sphere
    comes in at U + W and leaves as from a fixed plane hit at U + W (Galilean invariance of the
    contact and the film: only the relative motion enters); dry, that is e_d."""
    moving = lmp(bounce(region_wall(kw, "floor"), extra_regions=f"variable zw equal {W}*step*{DT}\n"
                        "region floor block INF INF INF INF -0.01 0.0 side out move NULL NULL v_zw"))
    fixed = lmp(bounce(f"fix wall all wall/lubrication {kw} zplane 0.0 NULL", v0=(0.0, 0.0, -(U + W))))
    e_moving = (moving["v"][2] - W) / (U + W)
    assert e_moving == pytest.approx(fixed["v"][2] / (U + W), rel=1e-9)
    if kw == "0.5":
        assert e_moving == pytest.approx(0.5, rel=1e-9)
    else:
        assert 0.05 < e_moving < 0.8


def sliding_scene(mu, wall_speed, steps=100):
    """A sphere set down on a floor sliding along x at wall_speed, under gravity 9.81 along -z."""
    return HEADER + f"""
region box block -0.01 0.01 -0.01 0.01 -0.01 0.02
create_box 1 box
create_atoms 1 single 0 0 {R}
set atom 1 diameter {2 * R} density {RHO}
velocity all set 0 0 0
variable xw equal {wall_speed}*step*{DT}
region floor block INF INF INF INF -0.01 0.0 side out move v_xw NULL NULL
fix wall all wall/lubrication/region 0.1 floor friction {mu} tangential 0.5
fix g all gravity 9.81 vector 0 0 -1
fix nve all nve/sphere
timestep {DT}
thermo_style custom step f_wall[1] f_wall[3]
thermo 0
run {steps}
print "RESULT force $(f_wall[1]:%.17g) $(f_wall[2]:%.17g) $(f_wall[3]:%.17g)"
print "RESULT vx $(vx[1]:%.17g)"
"""


def test_sliding_floor_pulls_with_coulomb_friction(lmp):
    """The floor slides under the sphere at 0.1 m/s: the slip lasts 2/7 W / (mu g) ~ 10 ms
    (200 steps); at step 100 the contact slides and pulls along +x with mu F_n exactly, and the
    sphere has gained mu g t of speed (within the settling of the first contact)."""
    mu = 0.3
    out = lmp(sliding_scene(mu, 0.1))
    fx, fy, fz = out["force"]
    mass = RHO * 4.0 / 3.0 * math.pi * R**3
    assert fz == pytest.approx(mass * 9.81, rel=0.05)
    assert fx == pytest.approx(mu * fz, rel=1e-9)
    assert abs(fy) < 1e-12 * fz
    assert out["vx"] == pytest.approx(mu * 9.81 * 100 * DT, rel=0.05)
    # A floor at rest leaves the resting sphere alone along x (the pull above is the motion's).
    assert lmp(sliding_scene(mu, 0.0))["force"][0] == pytest.approx(0.0, abs=1e-15)


def couette_scene(mu, omega, steps=40, r_in=5 * R, push=2.0):
    """A sphere pressed by a radial force (push x its weight) against an inner cylinder
    region that rotates about z at omega."""
    mass = RHO * 4.0 / 3.0 * math.pi * R**3
    force = push * mass * 9.81
    return HEADER.replace("boundary p p f", "boundary p p p") + f"""
region box block -0.02 0.02 -0.02 0.02 -0.005 0.005
create_box 1 box
create_atoms 1 single {r_in + R} 0 0
set atom 1 diameter {2 * R} density {RHO}
velocity all set 0 0 0
variable theta equal {omega}*step*{DT}
region inner cylinder z 0 0 {r_in} INF INF side out rotate v_theta 0 0 0 0 0 1
fix wall all wall/lubrication/region 0.1 inner friction {mu}
variable fx atom -{force}*x/sqrt(x*x+y*y)
variable fy atom -{force}*y/sqrt(x*x+y*y)
fix push all addforce v_fx v_fy 0.0
fix nve all nve/sphere
timestep {DT}
thermo_style custom step f_wall[1] f_wall[6]
thermo 0
run {steps}
print "RESULT wall $(f_wall[1]:%.17g) $(f_wall[2]:%.17g) $(f_wall[3]:%.17g) $(f_wall[4]:%.17g) $(f_wall[5]:%.17g) $(f_wall[6]:%.17g)"
print "RESULT x $(x[1]:%.17g) $(y[1]:%.17g) $(z[1]:%.17g)"
"""


@pytest.mark.parametrize("omega", [20.0, -20.0])
def test_rotating_cylinder_transmits_the_friction_torque(lmp, omega):
    """Couette cell, dilute limit: one sphere pressed with F against the inner cylinder (radius
    R_in = 5 R) rotating at omega (surface speed 0.1 m/s; F = 2 m g: the slip lasts
    0.1 / (3.5 mu F / m) ~ 5 ms, 100 steps; checked at step 40). While it slides,
    the wall's tangential force is mu F_n along the surface's motion and its torque about the
    axis (r - R) mu F_n (r: the sphere centre's distance from the axis, r - R the contact's), on
    the cylinder the opposite: mu F R_in in the dilute limit (F_n = F - m v^2 / r, within 2 %)."""
    mu = 0.3
    out = lmp(couette_scene(mu, omega))
    fx, fy, fz, tx, ty, tz = out["wall"]
    x, y, _ = out["x"]
    r = math.hypot(x, y)
    f_n = (fx * x + fy * y) / r
    f_t = (-fx * y + fy * x) / r
    mass = RHO * 4.0 / 3.0 * math.pi * R**3
    assert f_t == pytest.approx(math.copysign(mu * f_n, omega), rel=1e-9)
    assert tz == pytest.approx((r - R) * f_t, rel=1e-9)
    assert abs(tz) == pytest.approx(mu * 2.0 * mass * 9.81 * 5 * R, rel=0.02)
    assert abs(fz) + abs(tx) + abs(ty) < 1e-12 * abs(tz) / R


PUSH = 2.0 * 9.81 * RHO * 4.0 / 3.0 * math.pi * R**3    # twice a sphere's weight


def annulus_scene(steps=400, extra_run="", omega=20.0):
    """A wet frictional annular cell: 64 spheres on two rings in two layers between an inner
    cylinder (R_in = 4.2 mm) rotating at omega and a fixed outer one (9.8 mm), periodic along z
    (4 mm), every sphere touching a wall at the start, oblique velocities set from the ids
    (the same on any number of ranks), all pushed towards the axis with twice their weight (the
    inner ring slides on the rotating cylinder throughout)."""
    atoms = []
    for z in (1.0e-3, 3.0e-3):
        for ring, count in ((5.2e-3, 12), (8.8e-3, 20)):
            for k in range(count):
                a = 2.0 * math.pi * (k + 0.25 * (z > 2e-3)) / count
                atoms.append(f"create_atoms 1 single {ring * math.cos(a):.9f} {ring * math.sin(a):.9f} {z}")
    return HEADER.replace("boundary p p f", "boundary f f p") + f"""
region box block -0.011 0.011 -0.011 0.011 0.0 0.004
create_box 1 box
{chr(10).join(atoms)}
set group all diameter {2 * R} density {RHO}
variable vx atom 0.05*sin(1.7*id)
variable vy atom 0.05*cos(2.3*id)
variable vz atom 0.02*sin(0.9*id)
velocity all set v_vx v_vy v_vz
variable theta equal {omega}*step*{DT}
region inner cylinder z 0 0 4.2e-3 INF INF side out rotate v_theta 0 0 0 0 0 1
region outer cylinder z 0 0 9.8e-3 INF INF side in
pair_style lubricated/springdashpot
pair_coeff * * 0.8 friction 0.3 rolling 0.02 viscosity 1e-3 activation 0.1
fix inner all wall/lubrication/region 0.7 inner friction 0.4 rolling 0.02 viscosity 1e-3 activation 0.1
fix outer all wall/lubrication/region 0.7 outer friction 0.4 viscosity 1e-3 activation 0.1
variable fx atom -{PUSH}*x/sqrt(x*x+y*y)
variable fy atom -{PUSH}*y/sqrt(x*x+y*y)
fix push all addforce v_fx v_fy 0.0
fix nve all nve/sphere
timestep {DT}
neighbor 0.5e-3 bin
thermo_style custom step f_inner[1] f_inner[6]
thermo 0
fix torque all ave/time 1 200 400 f_inner[6] f_outer[6]
run {steps}
{extra_run}
print "RESULT torque $(f_torque[1]:%.17g) $(f_torque[2]:%.17g)"
""" + dump_state(6)


def assert_same(a, b, rel):
    assert a.keys() == b.keys() and len(a) >= 13
    for key in a:
        assert b[key] == pytest.approx(a[key], rel=rel, abs=1e-13), key


def test_annulus_one_and_two_ranks_and_restart(lmp):
    """The annulus on 1 and 2 ranks (walls and contacts on both sides of the ranks' boundary,
    atoms migrating with their per-face friction history) agrees to 1e-10; a restart written at
    step 200 (spheres sliding on both walls) and read by a new process continues the
    uninterrupted run to 1e-12 (per-face elongations, the region's motion of the last step)."""
    single = lmp(annulus_scene())
    assert single["torque"][0] > 0.0    # the rotating cylinder drags the spheres along
    two = lmp(annulus_scene(), nprocs=2)
    assert_same(single, two, rel=1e-10)
    lmp(annulus_scene(steps=200, extra_run="write_restart mid.restart"))
    fixes = [line for line in annulus_scene().splitlines()
             if line.startswith(("variable theta", "variable f", "region inner", "region outer", "fix ", "timestep", "neighbor",
                                 "thermo"))]
    restarted = lmp("plugin load ${plugin}\nread_restart mid.restart\ncomm_modify vel yes\n" + "\n".join(fixes) +
                    "\nrun 200\n" + 'print "RESULT torque $(f_torque[1]:%.17g) $(f_torque[2]:%.17g)"\n' +
                    dump_state(6), name="in.restart")
    assert_same(single, restarted, rel=1e-12)
    # Both walls redefined without friction and rolling drop the file's history (a segfault
    # before: it was written through a null history) and no longer drag the spheres along.
    frictionless = [line.replace(" friction 0.4 rolling 0.02", "").replace(" friction 0.4", "") for line in fixes]
    assert frictionless != fixes
    slid = lmp("plugin load ${plugin}\nread_restart mid.restart\ncomm_modify vel yes\n" + "\n".join(frictionless) +
               "\nrun 200\n" + 'print "RESULT torque $(f_torque[1]:%.17g) $(f_torque[2]:%.17g)"\n' + dump_state(6),
               name="in.frictionless")
    assert abs(slid["torque"][0]) < 0.5 * abs(single["torque"][0])


def bad_scene(fix, region="region floor block INF INF INF INF 0.0 INF", radius=R):
    return bounce(fix, radius=radius, extra_regions=region, steps=30)


BAD = {
    "unknown_region": (bad_scene("fix w all wall/lubrication/region 0.9 nosuch"),
                       ["Fix wall/lubrication/region: region nosuch does not exist"]),
    "missing_e_d": (bad_scene("fix w all wall/lubrication/region floor"),
                    ["Fix wall/lubrication/region: expected e_d and a region ID"]),
    "region_before_e_d": (bad_scene("fix w all wall/lubrication/region floor 0.9"),
                          ["expected a number for e_d, got 'floor'"]),
    "e_d_out_of_range": (bad_scene("fix w all wall/lubrication/region 1.5 floor"),
                         ["e_d = 1.5 is out of range (allowed: 0 < e_d <= 1)"]),
    "unknown_keyword": (bad_scene("fix w all wall/lubrication/region 0.9 floor stiffness 3"),
                        ["unknown keyword 'stiffness'"]),
    "sphere_larger_than_concave_region": (
        bad_scene("fix w all wall/lubrication/region 0.9 cavity", region=f"region cavity sphere 0 0 {1.2137 * R} "
                  f"{0.9 * R} side in"),
        ["a sphere of radius 0.001 does not fit inside the concave surface of radius 0.0009 of region cavity"]),
    "sphere_nearly_filling_a_cylinder": (
        bad_scene(f"fix w all wall/lubrication/region 0.9 pipe viscosity 1e-3 activation {EPS_AL}", region=f"region pipe cylinder z {0.1 * R} 0 {1.05 * R} "
                  "INF INF side in"),
        ["nearly fills the concave surface of radius 0.00105 of region pipe", "allowed: R_f <= 4 R"]),
    "shape_variable_region": (
        bad_scene("fix w all wall/lubrication/region 0.9 ball",
                  region=f"variable r equal {5 * R}\nregion ball sphere 0 0 0 v_r side out"),
        ["region ball changes its shape with variables"]),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_input_names_the_problem(lmp, case):
    text, expected = BAD[case]
    lmp(text, check=False)
    lines = lmp.log.splitlines()
    first = next((k for k, line in enumerate(lines) if "ERROR" in line), None)
    assert first is not None, f"no ERROR for {case}:\n{lmp.log[-1500:]}"
    message = "\n".join(lines[first:first + 3])
    for fragment in expected:
        assert fragment in message, message
    assert "Segmentation" not in lmp.log


@pytest.mark.parametrize("mu,dt", [(10.0, 1e-5), (1.0, 1e-6), (0.1, 1e-6)])
def test_wet_cup_films_never_raise_the_energy(lmp, mu, dt):
    """The 13-sphere cluster of the dense-bed tests (every gap in the film, St = 5.6e-3 / mu_f
    down to 5.6e-4) inside a sphere region whose concave surface has every outer sphere in its
    film too (gap 0.002 R, R_f = 1.5 R): the wall films join each sphere's many-body budget in
    the pair style, and the energy (kinetic, rotational, spring of pairs and wall) never rises
    beyond round-off between samples."""
    import dense_scenes
    from test_dense_beds import assert_never_gains
    outer = 2.0 * dense_scenes.R * 1.001 + dense_scenes.R    # the outer spheres' far side
    cup = (f"region cup sphere 0 0 0 {outer + 0.002 * dense_scenes.R!r} side in units box\n"
           f"fix cup all wall/lubrication/region 0.9 cup ncontact 8 viscosity {mu} activation 0.1\n"
           "fix_modify cup energy yes\nfix nve all nve/sphere\n")
    script = dense_scenes.cluster(mu, dt).replace("fix nve all nve/sphere\n", cup)
    energy = assert_never_gains(lmp, script)
    assert energy[-1] < 0.9 * energy[0]    # the films acted


def stacked_floors_scene(mu=10.0, dt=1e-5, steps=300):
    """One sphere (rho 2500) approaching, at 0.01 m/s from 0.05 R, three identical wet region
    floors (three fixes on one block face: three films on the same mode, each at its own cap
    at this St = 5.6e-4), pair_style lubricated/springdashpot keeping the film budget."""
    import dense_scenes
    walls = "".join(f"fix floor{k} all wall/lubrication/region 0.9 floor viscosity {mu} activation 0.1\n"
                     f"fix_modify floor{k} energy yes\n" for k in range(3))
    return dense_scenes.HEADER.replace("boundary p p p", "boundary p p f") + f"""
region box block -0.005 0.005 -0.005 0.005 0 0.01
create_box 1 box
create_atoms 1 single 0 0 {1.05 * R}
set group all diameter {2 * R} density 2500
velocity all set 0 0 -0.01
region floor block INF INF INF INF 0 INF units box
pair_style lubricated/springdashpot
pair_coeff * * 0.9 viscosity {mu} activation 0.1
{walls}
fix nve all nve/sphere
timestep {dt}
compute rot all erotate/sphere
compute kin all ke
variable e equal c_kin+c_rot+pe
thermo_style custom step atoms c_kin c_rot pe v_e
thermo_modify lost error norm no format float %.17g
thermo 1
run {steps}
"""


def test_region_wall_films_share_the_pair_styles_budget(lmp):
    """Three films on one mode would take 3 m |u_n| a step and throw the sphere back at twice its
    speed; within the budget (the pair style sums the region walls' shares) they stop it, and the
    energy never rises."""
    from test_dense_beds import assert_never_gains
    energy = assert_never_gains(lmp, stacked_floors_scene())
    assert energy[-1] < energy[0]

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

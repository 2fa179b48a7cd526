"""A sphere resting on two or three faces of a region wall under gravity (issue 46; doc/model.rst,
"Contacts under a steady load"). The loaded event steps take gravity's steady load b_k along each
face's normal; the faces a sphere overlaps share the weight: sum_k b_k n_k = -g, b_k >= 0
(lubricated/load_sharing.h). Before, each face took its own projection -g . n_k as if it held
the sphere alone, and a sphere resting in a 60 degree V-groove rose without bound (1.5e-10 m in
1 s at e_d = 1); measured over the 100000 steps (1 s) here with the plugin before the change: 5.6e-11 m
above the start in the groove, 3.5e-11 m in the corner (e_d = 1), and at e_d = 0.9 too.
"""
import math

import pytest

R = 1e-3    # m
DT = 1e-5    # s
STEPS = 100000


def faces(kind):
    """Plane regions through the origin (unit normals into the region) and the resting height of
    a sphere touching them all at gap 0."""
    if kind == "groove":    # 60 degrees between the faces: normals 60 degrees from the vertical
        tilt, azimuths = math.pi / 3, (0.0, math.pi)
    else:                   # a corner of three faces tilted 60 degrees, 120 degrees apart
        tilt, azimuths = math.pi / 3, (0.0, 2 * math.pi / 3, 4 * math.pi / 3)
    normals = [(math.sin(tilt) * math.cos(a), math.sin(tilt) * math.sin(a), math.cos(tilt)) for a in azimuths]
    return normals, R / math.cos(tilt)


def resting(kind, e_dry, n_c=8):
    normals, height = faces(kind)
    planes = "\n".join(f"region f{k} plane 0 0 0 {n[0]!r} {n[1]!r} {n[2]!r} side in"
                       for k, n in enumerate(normals))
    names = " ".join(f"f{k}" for k in range(len(normals)))
    return f"""plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block -0.01 0.01 -0.01 0.01 -0.01 0.03
create_box 1 box
create_atoms 1 single 0 0 {height!r} units box
set atom 1 diameter {2 * R} density 2500
{planes}
region faces intersect {len(normals)} {names}
pair_style lubricated/springdashpot
pair_coeff * * {e_dry} ncontact {n_c}
fix wall all wall/lubrication/region {e_dry} faces ncontact {n_c}
fix g all gravity 9.81 vector 0 0 -1
fix nve all nve/sphere
timestep {DT}
neighbor 1e-3 bin
variable rise equal z[1]-{height!r}
variable speed equal sqrt(vx[1]^2+vy[1]^2+vz[1]^2)
fix out all print 1 "$(step) ${{rise}} ${{speed}}" file rise.txt screen no
thermo 0
run {STEPS}
print "RESULT speed $(v_speed:%.17g)"
"""


def rises(lmp):
    rows = [line.split() for line in (lmp.dir / "rise.txt").read_text().splitlines() if line and line[0] != "#"]
    return [float(r[1]) for r in rows]


@pytest.mark.parametrize("kind", ["groove", "corner"])
@pytest.mark.parametrize("e_dry", [1.0, 0.9])
def test_a_resting_sphere_never_rises(lmp, kind, e_dry):
    result = lmp(resting(kind, e_dry))
    rise = rises(lmp)
    assert len(rise) >= STEPS
    assert max(rise) <= 1e-15, f"highest point {max(rise):.3e} m above the start"
    if e_dry < 1.0:
        assert result["speed"] < 1e-9, f"speed {result['speed']:.3e} m/s: not at rest"

"""A sphere resting on a plane wall under gravity (doc/model.rst, "Contacts under a steady load").

The step-exact contact lands each step on the trajectory of the isolated pair. In the steps where
a contact starts or ends that trajectory must include the load that the integrator adds on top
(fix gravity); without it each such step returns the sphere faster by about 0.03 g dt (at N_c = 8)
and a sphere put down at rest keeps hopping: at e_d = 1 it gains height without bound, at
e_d = 0.99, N_c = 4 or e_d = 0.9, N_c = 2 it never settles. fix wall/lubrication takes gravity's
acceleration along the wall normal as that load: at e_d = 1 the sphere never rises above its
start, below it settles to rest in the spring's equilibrium.

Without the load (the plugin before it), measured over the 20000 steps here: highest point
1.7e-7 m above the start at e_d = 1, N_c = 8 (on the floor and on the ceiling wall alike),
4.1e-8 m at e_d = 0.99, N_c = 4 and 1.0e-8 m at e_d = 0.9, N_c = 2; with it 0 (and a speed below
1e-14 m/s where damped).
"""
import pytest

R = 1e-3    # m
DT = 1e-5    # s
STEPS = 20000


def resting_sphere(e_dry, n_c, axis="z", side="lo"):
    """A sphere touching the wall at rest (gap 0), gravity 9.81 m/s^2 onto the wall; heights
    (distance of the centre from the wall) every step in heights.txt."""
    lo = side == "lo"
    position = {"x": 0.0, "y": 0.0, "z": 0.0}
    position[axis] = R if lo else 0.03 - R
    direction = {"x": 0, "y": 0, "z": 0}
    direction[axis] = -1 if lo else 1
    walls = f"0.0 NULL" if lo else f"NULL 0.03"
    height = f"{axis}[1]" if lo else f"0.03-{axis}[1]"
    return f"""plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block -0.01 0.03 -0.01 0.03 -0.01 0.03
create_box 1 box
create_atoms 1 single {position['x']} {position['y']} {position['z']} units box
set atom 1 diameter {2 * R} density 2500
pair_style lubricated/springdashpot
pair_coeff * * {e_dry} ncontact {n_c}
fix floor all wall/lubrication {e_dry} ncontact {n_c} {axis}plane {walls}
fix g all gravity 9.81 vector {direction['x']} {direction['y']} {direction['z']}
fix nve all nve/sphere
timestep {DT}
neighbor 1e-3 bin
variable h equal {height}
variable speed equal sqrt(vx[1]^2+vy[1]^2+vz[1]^2)
fix out all print 1 "$(step) ${{h}} ${{speed}}" file heights.txt screen no
thermo 0
run {STEPS}
print "RESULT speed $(v_speed:%.17g)"
"""


def heights(lmp):
    rows = [line.split() for line in (lmp.dir / "heights.txt").read_text().splitlines()
            if line and line[0] != "#"]
    return [float(r[1]) for r in rows]


@pytest.mark.parametrize("axis,side", [("z", "lo"), ("y", "hi")])
def test_undamped_sphere_never_rises(lmp, axis, side):
    res = lmp(resting_sphere(1.0, 8, axis, side))
    h = heights(lmp)
    assert len(h) >= STEPS
    assert max(h) - R <= 1e-12, f"highest point {max(h) - R:.3e} m above the start"
    assert res["speed"] < 1e-4    # oscillating in the overlap, about g dt at most


@pytest.mark.parametrize("e_dry,n_c", [(0.99, 4), (0.9, 2)])
def test_damped_sphere_comes_to_rest(lmp, e_dry, n_c):
    res = lmp(resting_sphere(e_dry, n_c))
    h = heights(lmp)
    assert max(h) - R <= 1e-12
    assert res["speed"] < 1e-9, f"speed {res['speed']:.3e} m/s after {STEPS} steps"

"""fix fluid/drag in a sheared triclinic box (issue 45): the affine flow of fix deform as the
fluid velocity (flow affine), the drag in the virial on request (fix_modify virial yes).

References: a sphere released from rest at height y in simple shear, u_x = gdot (y - ylo),
relaxes as Stokes drag alone says, v_x(t) = u_x (1 - exp(-t / tau)), tau = m / (3 pi mu d);
for spheres held still the drag is F_x = 3 pi mu d gdot (y - ylo), so the virial's xy term is
W_xy = sum_i y_i F_x,i, and compute pressure's (virial only) P_xy = W_xy / V, compute
stress/atom's sum -W_xy.
"""
import math

import pytest

SCENE = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
region box prism 0 {L} 0 {L} 0 {L} 0 0 0
create_box 1 box
create_atoms 1 single 0.001 {y1} 0.002
create_atoms 1 single 0.006 {y2} 0.007
set group all diameter {d} density {rho_p}
pair_style lubricated/springdashpot
pair_coeff * * 0.9
{integrate}
fix shear all deform 1 xy erate {gdot} remap v
fix fluid all fluid/drag viscosity {mu} density 1000 law stokes flow affine
{modify}
compute pv all pressure NULL virial
compute sa all stress/atom NULL virial
compute ssum all reduce sum c_sa[4]
thermo_style custom step c_pv[4] c_ssum
thermo {steps}
timestep {dt}
run {steps}
print "RESULT v $(vx[1]:%.15g) $(vx[2]:%.15g) $(vy[1]:%.15g) $(vy[2]:%.15g)"
print "RESULT y $(y[1]:%.15g) $(y[2]:%.15g)"
print "RESULT p $(c_pv[4]:%.15g) $(c_ssum:%.15g)"
"""

L, D, RHO_P, MU, GDOT = 0.01, 1e-3, 2500.0, 0.1, 1.0
Y1, Y2 = 0.002, 0.007
MASS = RHO_P * math.pi / 6 * D ** 3
BETA = 3 * math.pi * MU * D
TAU = MASS / BETA
DT = TAU / 100


def scene(steps, integrate=True, modify="", extra_fix=""):
    values = {"{L}": repr(L), "{y1}": repr(Y1), "{y2}": repr(Y2), "{d}": repr(D), "{rho_p}": repr(RHO_P),
              "{gdot}": repr(GDOT), "{mu}": repr(MU), "{dt}": repr(DT), "{steps}": str(steps),
              "{integrate}": "fix nve all nve/sphere" if integrate else "", "{modify}": modify}
    text = SCENE
    for key, value in values.items():
        text = text.replace(key, value)
    return text.replace("flow affine", "flow affine " + extra_fix)


@pytest.mark.parametrize("relaxation_times", [2, 20])
def test_a_sphere_relaxes_to_the_affine_velocity_at_its_height(lmp, relaxation_times):
    """Stokes relaxation towards u_x = gdot y (ylo = 0); the step's error is O(dt / tau) = 1e-2
    of u at 2 tau, none in the steady state."""
    steps = 100 * relaxation_times
    v = lmp(scene(steps))["v"]
    for k, y in ((0, Y1), (1, Y2)):
        u = GDOT * y
        expected = u * (1 - math.exp(-relaxation_times))
        assert v[k] == pytest.approx(expected, abs=(1e-2 if relaxation_times == 2 else 1e-7) * u)
        assert abs(v[2 + k]) < 1e-15


def test_one_and_two_ranks_agree(lmp):
    serial = lmp(scene(400))
    parallel = lmp(scene(400).replace("create_box", "processors 2 1 1\ncreate_box"), nprocs=2)
    assert "2 by 1 by 1 MPI processor grid" in lmp.log
    for key in ("v", "y", "p"):
        assert parallel[key] == pytest.approx(serial[key], rel=1e-12, abs=1e-18), key


def test_the_drag_enters_the_virial_on_request(lmp):
    """Spheres held still: F_x = beta gdot y; compute pressure (virial) and compute stress/atom see
    W_xy = sum y F_x with fix_modify virial yes and nothing without."""
    without = lmp(scene(1, integrate=False))["p"]
    with_virial = lmp(scene(1, integrate=False, modify="fix_modify fluid virial yes"))["p"]
    w_xy = sum(y * BETA * GDOT * y for y in (Y1, Y2))
    assert without[0] == 0.0 and without[1] == 0.0
    assert with_virial[0] == pytest.approx(w_xy / L ** 3, rel=1e-9)
    assert with_virial[1] == pytest.approx(-w_xy, rel=1e-9)


@pytest.mark.parametrize("edit,fragment", [
    (lambda s: s.replace("fix shear all deform 1 xy erate 1.0 remap v", ""),
     "flow affine needs a deforming box (fix deform"),
    (lambda s: s.replace("flow affine", "flow affine velocity 0 0 0"),
     "flow affine and the velocity keyword both give the fluid velocity"),
    (lambda s: s.replace("flow affine", "flow sideways"), "flow must be affine or velocity, got 'sideways'"),
    (lambda s: s.replace("law stokes flow affine", "flow"), "missing value(s) for keyword flow"),
])
def test_bad_flow_input(lmp, edit, fragment):
    lmp(edit(scene(1)), check=False)
    error = next((line for line in lmp.log.splitlines() if "ERROR" in line), None)
    assert error is not None, lmp.log[-1500:]
    assert fragment in error, error


TILTED = """plugin load ${plugin}
units si
atom_style sphere
boundary p p p
comm_modify vel yes
region box prism 0 0.01 0 0.01 0 0.01 0.004 0 0
create_box 1 box
create_atoms 1 single 0.0035 0.0025 0.0025
set group all diameter 0.001 density 2500
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix fluid all fluid/drag viscosity 1e-3 density 1000 hindrance richardson-zaki 4.65 bins 2 2 2
thermo_style custom step f_fluid[4]
run 0
print "RESULT phi $(f_fluid[4]:%.15g)"
"""


def test_bins_of_a_tilted_box_follow_its_edges(lmp):
    """A sphere at box coordinates (1/4, 1/4, 1/4) of a box tilted by xy = 0.4 L sits on the
    centre of one bin of 2 x 2 x 2: all its volume in that bin, phi = 8 V_s / V there (the
    orthogonal mapping would split it between two bins, 4 V_s / V)."""
    phi = lmp(TILTED)["phi"]
    assert phi == pytest.approx(8 * math.pi / 6 * 1e-9 / 1e-6, rel=1e-12)

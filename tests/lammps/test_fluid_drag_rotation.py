"""fix fluid/drag rotation yes: the Stokes torque T = 8 pi mu_f a^3 (curl u_f / 2 - omega) on a
sphere's spin (doc/fix_fluid_drag.rst, "Rotation"; src/lubricated/drag.h).

References: a lone sphere spinning in a fluid at rest slows as I domega/dt = -8 pi mu a^3 omega,
omega(t) = omega_0 exp(-t / tau_r), tau_r = I / (8 pi mu a^3) = m / (20 pi mu a); the backward-
Euler step gives about omega_0 / (1 + k)^n, k = dt / tau_r, within about n k^2 / 2 of it
(relative; the test allows n k^2). In
simple shear u_x = gdot y (fix deform xy erate, flow affine) a free sphere spins up to the
fluid's rotation, -gdot / 2 about z.
"""
import math

import pytest

SCENE = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
region box prism 0 0.01 0 0.01 0 0.01 0 0 0
create_box 1 box
create_atoms 1 single 0.005 0.004 0.005
set group all diameter {d} density {rho_p}
set atom 1 omega {w0} {w0} {w0}
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix nve all nve/sphere
{deform}
fix fluid all fluid/drag viscosity {mu} density 1000 law stokes {fluid}
{after}
timestep {dt}
compute spin all property/atom omegax omegay omegaz
compute w all reduce sum c_spin[1] c_spin[2] c_spin[3]
thermo_style custom step c_w[1] c_w[2] c_w[3]
thermo {steps}
run {steps}
print "RESULT w $(c_w[1]:%.17g) $(c_w[2]:%.17g) $(c_w[3]:%.17g)"
"""

D, RHO_P, MU, GDOT = 1e-3, 2500.0, 0.1, 2.0
A = D / 2
MASS = RHO_P * math.pi / 6 * D ** 3
TAU_R = 0.4 * MASS * A ** 2 / (8 * math.pi * MU * A ** 3)


def scene(steps, dt, w0=0.0, fluid="rotation yes", deform="", after=""):
    values = {"{d}": repr(D), "{rho_p}": repr(RHO_P), "{mu}": repr(MU), "{w0}": repr(w0), "{dt}": repr(dt),
              "{steps}": str(steps), "{fluid}": fluid, "{deform}": deform, "{after}": after}
    text = SCENE
    for key, value in values.items():
        text = text.replace(key, value)
    return text


@pytest.mark.parametrize("k", [0.01, 0.1])
def test_a_spinning_sphere_slows_as_stokes_says(lmp, k):
    steps = round(2.0 / k)    # two relaxation times
    w = lmp(scene(steps, k * TAU_R, w0=10.0))["w"]
    exact = 10.0 * math.exp(-2.0)
    for component in w:
        assert component == pytest.approx(exact, rel=steps * k * k)


def test_a_step_longer_than_the_spin_relaxation_never_reverses_it(lmp):
    w = lmp(scene(5, 10.0 * TAU_R, w0=10.0))["w"]
    for component in w:
        assert 0.0 < component < 10.0 / 11.0 ** 4


def test_without_rotation_the_spin_is_kept(lmp):
    w = lmp(scene(50, 0.1 * TAU_R, w0=10.0, fluid=""))["w"]
    assert w == [10.0, 10.0, 10.0]


@pytest.mark.parametrize("k", [0.1, 5.0])
def test_a_sphere_in_simple_shear_spins_with_the_fluid(lmp, k):
    """From rest to -gdot / 2 about z, at any step (stiff ones included)."""
    deform = f"fix shear all deform 1 xy erate {GDOT!r} remap v"
    w = lmp(scene(round(40 / min(k, 1.0)), k * TAU_R, fluid="flow affine rotation yes", deform=deform))["w"]
    assert abs(w[0]) < 1e-12 and abs(w[1]) < 1e-12
    assert w[2] == pytest.approx(-GDOT / 2, rel=1e-9)


def test_the_vorticity_keyword_sets_the_fluid_rotation(lmp):
    w = lmp(scene(400, 0.1 * TAU_R, fluid="rotation yes vorticity 0 4.0 0"))["w"]
    assert w[1] == pytest.approx(2.0, rel=1e-9)
    assert abs(w[0]) < 1e-12 and abs(w[2]) < 1e-12


@pytest.mark.parametrize("edit,fragment", [
    ({"fluid": "rotation maybe"}, "rotation must be yes or no, got 'maybe'"),
    ({"after": "fix push all addforce 0 0 0"},
     "with added_mass, history or rotation must be the last fix that adds forces: define fix push"),
])
def test_bad_rotation_input(lmp, edit, fragment):
    lmp(scene(1, 1e-6, **edit), check=False)
    error = next((line for line in lmp.log.splitlines() if "ERROR" in line), None)
    assert error is not None, lmp.log[-1500:]
    assert fragment in error, error


def test_one_and_two_ranks_agree(lmp):
    deform = f"fix shear all deform 1 xy erate {GDOT!r} remap v"
    text = scene(30, 0.5 * TAU_R, w0=3.0, fluid="flow affine rotation yes", deform=deform)
    two = text.replace("create_box", "processors 2 1 1\ncreate_box").replace(
        "create_atoms 1 single 0.005 0.004 0.005", "create_atoms 1 single 0.0075 0.004 0.005")
    one = text.replace("create_atoms 1 single 0.005 0.004 0.005", "create_atoms 1 single 0.0075 0.004 0.005")
    serial = lmp(one)["w"]
    parallel = lmp(two, nprocs=2)["w"]
    assert "2 by 1 by 1 MPI processor grid" in lmp.log
    assert parallel == pytest.approx(serial, rel=1e-14, abs=1e-300)


def dense_bed(fluid):
    """The 256-sphere wet fcc bed of tools/dense_scenes.py (every gap in the film, St 5.6e-3,
    coupled film solve, friction and shear film) spinning at the start, with the drag fix."""
    import dense_scenes
    script = dense_scenes.fcc(1.0, 1e-6, steps=200, limit="implicit", extra="friction 0.3 shearfilm yes")
    script = script.replace("fix nve all nve/sphere\n", "fix nve all nve/sphere\nset group all omega 40 -30 20\n"
                            f"fix drag all fluid/drag viscosity 1.0 law stokes {fluid}\n")
    return script


def energies(log):
    """Thermo rows' rotational and total energy (ke + c_rot + pe)."""
    out = []
    for line in log.splitlines():
        r = line.split()
        if len(r) == 6 and r[0].isdigit() and r[1].isdigit():
            out.append((float(r[3]), float(r[5])))
    return out


def test_a_dense_wet_bed_with_the_torque_never_gains_energy(lmp):
    """Drag, torque, films in the coupled solve and friction: the energy sampled every 10 steps
    never rises, and the torque takes the spin's energy faster than the films and contacts
    alone."""
    lmp(dense_bed("rotation yes"))
    with_torque = energies(lmp.log)
    lmp(dense_bed(""))
    without = energies(lmp.log)
    assert len(with_torque) >= 20 and with_torque[0][1] > 0.0
    rises = [(b[1] - a[1]) / with_torque[0][1] for a, b in zip(with_torque, with_torque[1:])]
    assert max(rises) <= 1e-12, max(rises)
    assert with_torque[-1][0] < 0.5 * without[-1][0]

"""In the viscous regime a sheared suspension's rheology does not depend on eta_f at fixed St
(issue 45): the dense suspension of examples/suspension_shear (tests/lammps/suspension_scene.py:
80 bidisperse spheres at solid fraction 0.54, friction 0.5, St = rho gdot a^2 / eta_f = 1e-3,
gdot t_c = 1e-3, N_c = 16, `limit implicit tolerance 1e-10`, the affine drag in the virial),
sheared from rest for 300 steps (strain 0.019, the CG solve taken on every step).

Keeping St, the solid fraction, gdot t_c, N_c, e_d, the friction and the film's gaps (eps_al,
eps_1, in units of a) keeps every dimensionless group of the run, so a change of eta_f at fixed
St is a change of units (Buckingham): of time (gdot and eta_f times s, t_c and dt over s), of
length (a times s and eta_f times s^2, rho and gdot kept: the variant with a changed with eta_f)
or of mass (rho_p = rho_f and eta_f times s). eta_s = 1 + sigma_xy / (eta_f gdot),
P / (eta_f gdot) and mu = sigma_xy / P, the positions in units of a, the velocities in units of
gdot a and the forces in units of eta_f gdot a^2 must not change.

*Powers of two: bit-identical.* Multiplying by 2^k is exact in floating point and commutes with
every rounding (no overflow or underflow here), so every quantity of the scaled run is the
original one times a power of two, bit for bit, unless the code compares a dimensional
quantity with a constant of its own (an absolute threshold, a tolerance in SI units) or adds
quantities of different dimensions. The check is exact equality. The mass factor must be a
power of 4 (mass x 16, length x 4: mass x 64, moment of inertia x 1024): the solve works in
mass-weighted variables M^(1/2) w (doc/film_solve.rst), and the square root of 8 is not a power
of two (mass x 8 and length x 2 agree to 1e-12, as round-off).

*A factor of 10: round-off.* Then the two runs round differently from the first operation
(0.1 s has no exact binary form), by about 1e-16 relative per operation; a step's forces carry
errors of about 1e-15 (sums over a dozen contacts and films, the solve's conditioning, at most
1 + max D, about 100 here, on the velocities: 1e-14), which the dense packing carries forward
and grows over the 300 steps. Measured: 2e-11 on the averaged P and mu, 1.5e-12 a on the
positions. The tolerance, 1e-8 relative on the averages and 1e-9 a on the positions, is that
with a margin of 500 for other compilers and orderings, and far below what any dimensional
slip would give (a constant of the code that does not scale changes the result at first order,
as the power-of-two cases show exactly). What round-off can flip is a branch: a sphere's film
load D within round-off of 1 decides whether its films take the step-exact per-pair form or go
into the solve (doc/film_solve.rst); with rho_p = rho_f times 10 one film of this packing does
so at the first step and the averages then differ by 1e-4 (a different discretisation of that
film for one step, not a dependence on eta_f). The runs compared here flip none (same solved
films and CG iterations, checked).
"""
import pytest

import lammps_run
import suspension_scene as scene

ROUND_OFF_GROWTH = 1e-8    # relative, averages and final values (see above)
POSITION_GROWTH = 1e-9     # in units of a


@pytest.fixture(scope="module")
def packing(tmp_path_factory):
    out = tmp_path_factory.mktemp("suspension_packing")
    lammps_run.run(scene.packing_script(), out, scene.PACKING, name="in.packing")
    return out / "packing.data"


def shear(out, data, **units):
    results, log = lammps_run.run(scene.shear(str(data), **units), out, {}, name="in.shear")
    assert "(limit implicit)" in log and "WARNING" not in log
    assert results["iterations"] > 1.0    # the budget binds: the films were solved
    return results, scene.final_state(out)


@pytest.fixture(scope="module")
def reference(packing, tmp_path_factory):
    return shear(tmp_path_factory.mktemp("shear_reference"), packing)


UNIT_CHANGES = {
    "time / 8 (gdot, eta_f x 8)": dict(gdot=8.0),
    "length x 4 (a x 4, eta_f x 16)": dict(a=4e-4, length=4.0),
    "mass x 16 (rho_p = rho_f, eta_f x 16)": dict(rho=16000.0),
}


@pytest.mark.parametrize("change", list(UNIT_CHANGES))
def test_power_of_two_unit_change_is_bit_identical(packing, reference, tmp_path, change):
    units = dict(UNIT_CHANGES[change])
    data = packing
    length = units.pop("length", None)
    if length:
        data = scene.scaled_data(packing, length, tmp_path / "scaled.data")
    results, state = shear(tmp_path, data, **units)
    expected, expected_state = reference
    for key in ("mean", "final", "iterations"):
        assert results[key] == expected[key], key
    assert (state == expected_state).all()


def test_eta_f_times_ten_at_fixed_st(reference, packing, tmp_path):
    """gdot and eta_f times 10 (t_c and dt over 10): the averaged and final eta_s, P / (eta_f
    gdot) and mu, the scaled positions, velocities and forces agree to round-off growth."""
    results, state = shear(tmp_path, packing, gdot=10.0)
    expected, expected_state = reference
    assert results["iterations"] == expected["iterations"]    # no branch flipped
    for key in ("mean", "final"):
        assert results[key] == pytest.approx(expected[key], rel=ROUND_OFF_GROWTH), key
    assert abs(state[:, 1:4] - expected_state[:, 1:4]).max() <= POSITION_GROWTH
    for columns in (slice(4, 7), slice(7, 10)):
        scale = abs(expected_state[:, columns]).max()
        assert abs(state[:, columns] - expected_state[:, columns]).max() <= ROUND_OFF_GROWTH * scale
    eta_s, pressure, mu = expected["mean"]
    assert eta_s > 2.0 and pressure > 0.0    # the films carry stress (start-up from rest)

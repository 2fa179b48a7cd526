"""Dry impacts (doc/model.rst, "Solid contact: the spring-dashpot"): the rebound speed is e_d and
the contact lasts N_c steps.

Tolerance: 1 % of e_d, the issue's requirement. The step integration is exact for an
isolated pair, so a failure here means a broken contact law, not noise.
"""
import pytest

import scenes

E_DRY = [0.97, 0.5, 0.1]


def check(result, e_dry, ncontact=8):
    assert result["e"] == pytest.approx(e_dry, rel=0.01)
    assert abs(result["contact_steps"] - ncontact) <= 1.0


@pytest.mark.parametrize("e_dry", E_DRY)
def test_particle_wall(lmp, e_dry):
    check(lmp(scenes.wall_bounce(e_dry, dt_ru=0.005)), e_dry)


@pytest.mark.parametrize("e_dry", E_DRY)
@pytest.mark.parametrize("mass_ratio", [1.0, 3.0])
def test_particle_particle(lmp, e_dry, mass_ratio):
    check(lmp(scenes.pair_bounce(e_dry, mass_ratio=mass_ratio, dt_ru=0.005)), e_dry)


@pytest.mark.parametrize("newton", ["on", "off"])
def test_unequal_radii(lmp, newton):
    """Polydisperse pair, radius ratio 2 (mass ratio 8)."""
    check(lmp(scenes.pair_bounce(0.5, radius_ratio=2.0, mass_ratio=8.0, newton=newton)), 0.5)


def test_contact_duration_follows_ncontact(lmp):
    check(lmp(scenes.wall_bounce(0.5, ncontact=16)), 0.5, ncontact=16)


def test_tcontact_sets_duration_in_time_units(lmp):
    """tcontact = 12 dt must behave as ncontact 12."""
    dt = 0.005 * scenes.R / scenes.U
    result = lmp(scenes.wall_bounce(0.5, dt_ru=0.005, ncontact=12).replace(
        "ncontact 12", f"tcontact {12 * dt}"))
    check(result, 0.5, ncontact=12)


@pytest.mark.parametrize("e_dry", E_DRY)
@pytest.mark.parametrize("scene", ["wall", "pair"])
def test_papers_integrator_also_gives_e_dry(lmp, e_dry, scene):
    """fix nve/sphere/midpoint (the paper's scheme) with the step-exact contact, N_c = 8."""
    build = scenes.wall_bounce if scene == "wall" else scenes.pair_bounce
    check(lmp(build(e_dry, dt_ru=0.005, integrator="nve/sphere/midpoint")), e_dry)


def test_sampled_integration_is_the_papers_force(lmp):
    """The printed force sampled once per step misses e_d at e_d = 0.1 (why 'exact' is the default)."""
    result = lmp(scenes.wall_bounce(0.1, dt_ru=0.005, extra="integration sampled"))
    assert abs(result["e"] - 0.1) > 0.01 * 0.1


def test_coefficients_per_type_pair(lmp):
    """Types 1 and 2 with their own e_d; a 1-2 collision uses the 1 2 coefficients, and a wet
    1 1 pair next to dry pairs leaves the dry ones dry."""
    script = scenes.pair_bounce(0.9, dt_ru=0.005).replace("create_box 1 box", "create_box 2 box").replace(
        "set atom 2 diameter", "set atom 2 type 2\nset atom 2 diameter").replace(
        "pair_coeff * * 0.9 ncontact 8", "pair_coeff 1 1 0.9 viscosity 1e-3 activation 0.09375\n"
        "pair_coeff 2 2 0.5\npair_coeff 1 2 0.3 ncontact 8")
    result = lmp(script)
    assert result["e"] == pytest.approx(0.3, rel=1e-6)
    assert "types 1 2: e_d = 0.3" in lmp.log and "film" in lmp.log

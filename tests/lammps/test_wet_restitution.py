"""Wet particle-wall impacts (doc/model.rst, "Lubrication film" and "Wet restitution"), set-up (a)
of the paper: no fluid,
lubrication imposed for a given viscosity, St varied through mu_f, at the documented time
step dt = 0.005 R/U with e_d = 0.9, N_c = 8 and eps_al = 0.09375 (R/dx = 8).

Tolerance 0.05 on e/e_d against Legendre's exp(-35/St), the issue's requirement.
"""
import pytest

import scenes

E_DRY = 0.9


@pytest.mark.parametrize("stokes", [50, 100, 200, 500, 1000])
def test_follows_legendre_law(lmp, stokes):
    result = lmp(scenes.wall_bounce(E_DRY, mu=scenes.viscosity_for_stokes(stokes)))
    assert result["e"] / E_DRY == pytest.approx(scenes.legendre(stokes), abs=0.05)


def test_no_rebound_at_low_stokes(lmp):
    result = lmp(scenes.wall_bounce(E_DRY, mu=scenes.viscosity_for_stokes(5)))
    assert result["e"] <= 0.01 * E_DRY


def test_viscosity_reduces_rebound_monotonically(lmp):
    """The film must act at the wall at all (a peer's bug): more viscous, less rebound."""
    rebound = [lmp(scenes.wall_bounce(E_DRY, mu=scenes.viscosity_for_stokes(st)))["e"]
               for st in (1000, 200, 50)]
    assert rebound[0] > rebound[1] > rebound[2]
    assert rebound[0] < E_DRY

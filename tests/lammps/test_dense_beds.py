"""Dense wet beds (issue 17): the films of many neighbours never add energy.

Scenes (tools/dense_scenes.py): 256 spheres on an fcc lattice and a 13-sphere cluster (one
sphere, 12 neighbours), every gap inside the film, no gravity, no drive. The energy sampled
every 10 steps is kinetic + rotational + spring energy; the films and dashpots only remove
it, so it may not rise between samples beyond round-off: 1e-12 of E0 (the 17-digit sums of
256 terms round at ~1e-16 E0; the bound also covers the 1e-29 E0 floor the fastest decays
reach). With the per-pair caps alone (`limit pair`) the same scenes gain 1e5-1e12 x E0, so
the check detects the defect it guards against.
"""
import pytest

import dense_scenes

ROUND_OFF = 1e-12

# (mu_f [Pa s], dt [s]): St = 5.6e-3 / mu_f from 5.6e-4 to 560; dt from 1e-7 to 1e-5 s (the
# films of the fcc gaps close in ~2e-4 s at 0.01 m/s).
CASES = [(10.0, 1e-5), (3.0, 1e-6), (1.0, 1e-6), (1.0, 1e-5), (0.3, 1e-7), (0.1, 1e-6),
         (1e-3, 1e-6), (1e-5, 1e-6)]


def assert_never_gains(lmp, script):
    lmp(script)
    energy, atoms = dense_scenes.energies(lmp.log)
    assert len(energy) >= 50 and energy[0] > 0.0
    assert set(atoms) == {atoms[0]}
    rises = [(b - a) / energy[0] for a, b in zip(energy, energy[1:])]
    assert max(rises) <= ROUND_OFF, f"energy rose by {max(rises):.3g} E0"
    return energy


@pytest.mark.parametrize("scene", ["fcc", "cluster"])
@pytest.mark.parametrize("mu,dt", CASES)
def test_dense_films_never_raise_the_energy(lmp, scene, mu, dt):
    energy = assert_never_gains(lmp, getattr(dense_scenes, scene)(mu, dt))
    assert energy[-1] < energy[0]    # and they do dissipate


@pytest.mark.parametrize("scene", ["fcc", "cluster"])
@pytest.mark.parametrize("mu,dt", [(1.0, 1e-6), (3.0, 1e-5)])
def test_with_friction_and_shear_film(lmp, scene, mu, dt):
    assert_never_gains(lmp, getattr(dense_scenes, scene)(mu, dt, extra="friction 0.3 shearfilm yes"))


@pytest.mark.parametrize("scene", ["fcc", "cluster"])
def test_per_pair_caps_alone_gain_energy(lmp, scene):
    """`limit pair`: each film capped on its own, as before the budget."""
    lmp(getattr(dense_scenes, scene)(1.0, 1e-6, limit="pair"))
    energy, _ = dense_scenes.energies(lmp.log)
    assert "(limit pair)" in lmp.log
    assert max(energy) > 1e3 * energy[0]


def test_one_and_two_ranks_agree(lmp):
    script = dense_scenes.fcc(0.3, 1e-7, steps=300)
    one = lmp(script)["final"]
    two = lmp(script, nprocs=2)["final"]
    assert one[1] == two[1] == 256
    assert two[0] == pytest.approx(one[0], rel=1e-10)
    assert "(limit atom)" in lmp.log

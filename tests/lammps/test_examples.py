"""The example inputs run as documented (smoke tests with physics checks where cheap)."""
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def example(name):
    return (ROOT / "examples" / name).read_text()


@pytest.mark.parametrize("radius", ["1.5e-3", "3e-3"])
def test_settling_sphere_bounces_as_legendre(lmp, radius):
    """Validation case (b): a sphere settling onto a wall; St from the impact speed."""
    result = lmp(example("settling_sphere/in.settling_sphere"), R=radius)
    assert result["St"] > 50
    assert result["e_over_ed"] == pytest.approx(result["legendre"], abs=0.05)


def test_settling_sphere_stops_at_low_stokes(lmp):
    result = lmp(example("settling_sphere/in.settling_sphere"), R="0.5e-3")
    assert result["St"] < 20 and result["e_over_ed"] < 1e-6


@pytest.mark.parametrize("wet", [0, 1])
def test_settling_bed_dry_and_wet(lmp, wet):
    result = lmp(example("settling_bed/in.settling_bed"), wet=wet, steps=3000)
    assert "Lost atoms" not in lmp.log
    assert result["top"] < 35.0            # the bed is falling / settled inside the box


def test_fluidized_bed_input_runs_on_two_ranks(lmp):
    """A few hundred steps of the 2133-sphere bed on 2 ranks (the full run: make fluidized-bed)."""
    result = lmp(example("fluidized_bed/in.fluidized_bed"), nprocs=2, steps=200)
    assert result["atoms"] == 2133
    assert list(lmp.dir.glob("dump.fluidized_bed.*"))


@pytest.mark.parametrize("wet,nprocs", [(0, 1), (1, 2)])
def test_rotating_drum_lifts_its_bed(lmp, wet, nprocs):
    """3000 steps (0.375 s, 0.13 turn) of the drum (the full run: make rotating-drum): no atom
    lost, and the turning wall has lifted the bed to a tilted free surface (the bed starts flat,
    theta ~ 1 degree; the dry and wet runs average 25 and 28 degrees over 5 s)."""
    result = lmp(example("rotating_drum/in.rotating_drum"), nprocs=nprocs, wet=wet, steps=3000)
    assert result["atoms"] == 232
    assert 12.0 < result["theta"] < 45.0

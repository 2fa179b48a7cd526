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


def test_shear_cell_runs_on_two_ranks_and_drags_the_beads(lmp):
    """The wet annular shear cell (make shear-cell), 1000 steps on 2 ranks: no bead lost, and the
    beads brake the rotating inner cylinder (a torque against its rotation)."""
    result = lmp(example("shear_cell/in.shear_cell"), nprocs=2, steps=1000)
    assert result["atoms"] == 752
    assert result["torque_mean_last_1000"] < 0.0

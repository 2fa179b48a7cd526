"""The LIGGGHTS examples run as documented: the wall bounce gives the LAMMPS example's
restitution, and the settling bed runs dry and wet under mpirun -np 2."""
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


@pytest.mark.parametrize("stokes", [0, 50])
def test_wall_bounce_matches_the_lammps_example(run, stokes):
    lig = run.lig((EXAMPLES / "liggghts" / "in.wall_bounce").read_text(), variables={"St": stokes},
                  nprocs=2)
    lmp_script = (EXAMPLES / "wall_bounce" / "in.wall_bounce").read_text()
    lmp = run.lmp("plugin load ${plugin}\n" + lmp_script.replace("${St}", str(stokes), 1)
                  .replace("variable St      index 100", f"variable St      index {stokes}"))
    assert lig["e"] == pytest.approx(lmp["e"], abs=1e-3)


def test_settling_bed_runs_wet_on_two_ranks(run):
    bed = run.lig((EXAMPLES / "liggghts" / "in.settling_bed").read_text(),
                  variables={"wet": 1, "steps": 8000}, nprocs=2)
    assert "WARNING" not in run.log
    assert bed["atoms"] == 2254 and 0 < bed["top"] < 34.0 and bed["ke"] > 0


def test_settled_bed_matches_hooke_stiffness(run):
    """Same k and gamma: the settled bed has the height of LIGGGHTS's own linear model."""
    script = (EXAMPLES / "liggghts" / "in.settling_bed").read_text()
    ours = run.lig(script, variables={"steps": 25000})
    hooke = run.lig(script, variables={"steps": 25000, "model": "hooke/stiffness"})
    assert ours["top"] == pytest.approx(hooke["top"], rel=0.02)
    assert ours["top"] < 23.0    # 2254 spheres at a packing fraction near 0.6 fill ~19.7 d

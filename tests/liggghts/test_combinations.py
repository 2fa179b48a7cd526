"""Every model combination the library registers runs: LIGGGHTS would otherwise fall back to
its generic style and stop with "Unknown normal model" for the one a user typed."""
import pytest

import liggghts_scenes

EXTRA = """fix c1 all property/global cohesionEnergyDensity peratomtypepair 2 1e3 1e3 1e3 1e3
fix c2 all property/global coefficientRollingFriction peratomtypepair 2 0.05 0.05 0.05 0.05
fix c3 all property/global coefficientRollingViscousDamping peratomtypepair 2 0.1 0.1 0.1 0.1
fix c4 all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3
fix c5 all property/global rollingStiffness scalar 2.25
"""


@pytest.mark.parametrize("tangential", ["no_history", "history"])
@pytest.mark.parametrize("cohesion", ["", "sjkr", "sjkr2"])
@pytest.mark.parametrize("rolling", ["", "cdt", "epsd", "epsd2", "epsd3"])
def test_combination_runs(run, tangential, cohesion, rolling):
    model = f"model lubricated tangential {tangential}"
    model += f" cohesion {cohesion}" if cohesion else ""
    model += f" rolling_friction {rolling}" if rolling else ""
    script = liggghts_scenes.wall_bounce(0.9, model=model).replace("pair_style gran", EXTRA + "pair_style gran")
    e = run.lig(script)["e"]
    assert "unoptimized" not in run.log          # not LIGGGHTS's generic fallback
    assert 0.8 < e < 0.95                        # head-on: friction and rolling do not act

"""`run 0` before `timestep` (issue 46). ncontact's t_c = N_c dt is settled by the first run that
takes steps (lubricated/coefficients.h settle_contact_time); a run without steps evaluates with
N_c times the current step and settles nothing. The common idiom `run 0` (to initialise computes)
at LAMMPS's default step (1e-8 s in SI), then the real `timestep` and run, gives the contact
t_c = N_c times the real step. Before, the `run 0` settled t_c = 8e-8 s and the real run stopped
with "give ncontact again for the new time step".
"""
import pytest

import scenes

E_D = 0.5
DT = 0.005 * scenes.R / scenes.U


def run_zero_first(script):
    """The scene with `run 0` at LAMMPS's default step before its `timestep`."""
    line = f"timestep {DT}"
    assert line in script
    return script.replace(line, "run 0\n" + line)


@pytest.mark.parametrize("scene", ["wall", "pair"])
def test_run_0_at_the_default_step_settles_nothing(lmp, scene):
    """e = e_d to 1e-9 and the contact lasts N_c = 8 steps of the real step, as without the
    `run 0`; the log reports t_c = 8 dt."""
    build = scenes.wall_bounce if scene == "wall" else scenes.pair_bounce
    plain = lmp(build(E_D, dt_ru=0.005))
    result = lmp(run_zero_first(build(E_D, dt_ru=0.005)))
    assert result["e"] == pytest.approx(E_D, rel=1e-9)
    assert result["contact_steps"] == plain["contact_steps"]
    assert 7 <= result["contact_steps"] <= 9
    assert f"t_c = {8 * DT:.6g} (8 steps)" in lmp.log, lmp.log


@pytest.mark.parametrize("scene", ["wall", "pair"])
def test_run_0_then_a_run_equals_the_run_alone(lmp, scene):
    """`run 0` then `run N` at one step gives the run's result to the last bit."""
    build = scenes.wall_bounce if scene == "wall" else scenes.pair_bounce
    script = build(E_D, dt_ru=0.005)
    run = next(line for line in script.splitlines() if line.startswith("run "))
    alone = lmp(script)
    split = lmp(script.replace(run, "run 0\n" + run))
    assert split["e"] == alone["e"]
    assert split["contact_steps"] == alone["contact_steps"]

"""A run continues as the uninterrupted run in LIGGGHTS too (issue 18), whatever interrupts it:
several `run N`, `run 0` any number of times, `run N pre no`, write_restart and a new process
reading it, on 1 and 2 ranks. The set-up of each run evaluates the model's contacts with the
last step's velocities, v - dt/2 f/m (src/liggghts/fix_lubricated_step_velocity.h).

The scene (liggghts_chain): the wet polydisperse chain between two walls, collisions and films
straddling the ranks' boundary, interrupted inside them. LIGGGHTS's own tangential models see
the full-step velocities at a set-up (and its history model lengthens its spring there), so the
bit-for-bit check runs with `tangential off`; with friction a split run never adds energy
(test_dense_beds.py).

Tolerance 1e-12 relative: the restored velocities differ from the step's own by round-off."""
import pytest

from liggghts_chain import chain, dump_state, setup
from test_parallel_restart import assert_same_state

STEPS = 600
CUTS = (37, 211, 452)


def runs_with(between, pre_no=False):
    commands, last = [], 0
    for end in list(CUTS) + [STEPS]:
        commands.append(f"run {end - last}" + (" pre no" if pre_no and last else ""))
        if end != STEPS:
            commands += between
        last = end
    return "\n".join(commands)


def scene(commands, processors=""):
    """The chain with its run replaced by `commands`."""
    text = chain(steps=STEPS, tangential="off", processors=processors)
    assert f"run {STEPS}\n" in text
    return text.replace(f"run {STEPS}\n", commands + "\n") + dump_state()


@pytest.mark.parametrize("nprocs", [1, 2])
def test_interrupted_runs_continue_as_one_run(run, nprocs):
    processors = "processors 2 1 1" if nprocs == 2 else ""
    single = run.lig(scene(f"run {STEPS}", processors), nprocs=nprocs)
    for case, commands in {"runs": runs_with([]), "run 0": runs_with(["run 0", "run 0"]),
                           "pre no": runs_with([], pre_no=True)}.items():
        state = run.lig(scene(commands, processors), nprocs=nprocs)
        assert_same_state(single, state, rel=1e-12), case


@pytest.mark.parametrize("nprocs", [1, 2])
def test_restart_in_the_middle_of_the_collisions_continues_as_one_run(run, nprocs):
    processors = "processors 2 1 1" if nprocs == 2 else ""
    single = run.lig(scene(f"run {STEPS}", processors), nprocs=nprocs)
    run.lig(scene(f"run {CUTS[1]}\nwrite_restart mid.restart", processors), nprocs=nprocs)
    restarted = run.lig(f"""atom_modify map array
communicate single vel yes
newton off
{processors}
read_restart mid.restart
{setup("off")}
run {STEPS - CUTS[1]}
""" + dump_state(), nprocs=nprocs, name="in.restart")
    assert_same_state(single, restarted, rel=1e-12)

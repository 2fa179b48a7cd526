"""A run continues as the uninterrupted run (issue 18), whatever interrupts it: several `run N`,
any number of `run 0`, `run N pre no`, `reset_timestep`, write_restart and a new process reading it, on 1, 2
and 4 ranks. The set-up of each run evaluates the contacts as the last step did, with that
step's velocities restored from v and f (src/fix_step_velocity), and lengthens no tangential
spring.

The scene (test_tangential.frictional_scene): a long oblique frictional collision straddling
the ranks' boundary, a sphere rolling and slipping on the floor across the periodic boundary
(atoms not re-wrapped between runs: `neigh_modify check no` rebuilds every step), rolling
resistance, walls; dry, or wet (films on the pair and the floor, the drag of fix fluid/drag
with buoyancy). Interruptions at steps 37, 300 and 901 fall inside the collision and the
rolling contacts.

Tolerance 1e-12 relative: the restored velocities differ from the step's own by round-off
(v - dt/2 f/m undoes v + dt/2 f/m to an ulp).
"""
import re

import pytest

import dense_scenes
from scene_chain import dump_state
from test_tangential import assert_same, frictional_scene

STEPS = 1200
CUTS = (37, 300, 901)
WET = ("pair_coeff * * 0.8 ncontact 128 friction 0.3 tangential 0.6 rolling 0.02",
       "pair_coeff * * 0.8 ncontact 128 friction 0.3 tangential 0.6 rolling 0.02 viscosity 2e-3 activation 0.1")
WET_WALL = ("fix wall all wall/lubrication 0.7 ncontact 128 friction 0.4 tangential 0.5 zplane 0.0 NULL",
            "fix wall all wall/lubrication 0.7 ncontact 128 friction 0.4 tangential 0.5 viscosity 2e-3 "
            "activation 0.1 zplane 0.0 NULL\nfix drag all fluid/drag viscosity 2e-3 density 1000 buoyancy 0 0 -9.81")


def scene(wet, steps=STEPS, extra_run=""):
    text = frictional_scene(steps=steps, extra_run=extra_run)
    if wet:
        text = text.replace(*WET).replace(*WET_WALL)
    return text


def interrupted(commands, wet):
    """The scene with its run replaced by `commands` (each a line)."""
    return dense_scenes.split(scene(wet), *commands)


def runs_with(between):
    """run 37, `between`, run 263, `between`, run 601, `between`, run 299 (ends at 1200)."""
    ends = list(CUTS) + [STEPS]
    commands, last = [], 0
    for end in ends:
        commands.append(f"run {end - last}")
        if end != STEPS:
            commands += between
        last = end
    return commands


def run(lmp, script, nprocs, name="in.run"):
    env = dense_scenes.OVERSUBSCRIBED if nprocs > 2 else None
    return lmp(script + dump_state(4), nprocs=nprocs, name=name, env=env)


@pytest.mark.parametrize("wet", [False, True], ids=["dry", "wet"])
@pytest.mark.parametrize("nprocs", [1, 2, 4])
def test_interrupted_runs_continue_as_one_run(lmp, nprocs, wet):
    single = run(lmp, scene(wet), nprocs)
    # The scene tests something: friction slowed the slipping sphere, the films and drag acted.
    assert single["v3"][0] < 1.9 * 0.1
    cases = {
        "runs": runs_with([]),
        "run 0": runs_with(["run 0", "run 0", "run 0"]),
        "reset_timestep": runs_with(["reset_timestep 0"]),
        # No set-up at all: the next run starts from the last step's forces and history.
        "pre no": [f"{command} pre no" if k else command for k, command in enumerate(runs_with([]))],
        # A set-up (run 0) and then a run without one.
        "run 0, pre no": [line.replace("run 263", "run 263 pre no") for line in runs_with(["run 0"])],
    }
    for case, commands in cases.items():
        state = run(lmp, interrupted(commands, wet), nprocs)
        assert_same(single, state, rel=1e-12), case
        assert dense_scenes.ranks(lmp.log) == {nprocs}, case


@pytest.mark.parametrize("wet", [False, True], ids=["dry", "wet"])
@pytest.mark.parametrize("nprocs", [1, 2])
def test_restart_in_the_middle_of_the_collisions_continues_as_one_run(lmp, nprocs, wet):
    """write_restart at step 300 (the pair in contact, the rolling sphere on the floor), a new
    process reads it, redefines the fixes and runs 900 steps: as the uninterrupted run."""
    single = run(lmp, scene(wet), nprocs)
    run(lmp, scene(wet, steps=300, extra_run="write_restart mid.restart"), nprocs)
    fixes = [line for line in scene(wet).splitlines()
             if line.startswith(("fix ", "timestep", "neighbor", "neigh_modify"))]
    restarted = run(lmp, "plugin load ${plugin}\nread_restart mid.restart\ncomm_modify vel yes\n" +
                    "\n".join(fixes) + "\nrun 900\n", nprocs, name="in.restart")
    assert_same(single, restarted, rel=1e-12)


@pytest.mark.parametrize("nprocs", [1, 2, 4])
def test_dense_frictional_bed_restarts_as_one_run(lmp, nprocs):
    """The 256-sphere fcc bed (every neighbour in overlap, periodic in all directions: contacts
    across every rank and periodic boundary), wet, with friction and rolling: write_restart at
    step 150 within the run sequence, or write_data there (both migrate and reorder atoms between
    the runs: the last half kicks and the contact records travel with them, the forces and the
    neighbor list do not; before, the friction history was stored again from the stale list),
    and a new process reading the restart file: all as the uninterrupted run to 1e-12."""
    env = dense_scenes.OVERSUBSCRIBED if nprocs > 2 else None
    scene = dense_scenes.fcc(1e-3, 1e-6, steps=400, gap_ratio=-0.002, extra="friction 0.3 rolling 0.02",
                             loop="geom")
    single = lmp(scene, nprocs=nprocs, env=env)["final"]
    data = lmp(dense_scenes.split(scene, "run 150", "write_data mid.data", "run 250"), nprocs=nprocs,
               env=env)["final"]
    split = lmp(dense_scenes.split(scene, "run 150", "write_restart mid.restart", "run 250"), nprocs=nprocs,
                env=env)["final"]
    restarted = lmp(dense_scenes.restarted(1e-6, 250), nprocs=nprocs, env=env, name="in.restart")["final"]
    assert dense_scenes.ranks(lmp.log) == {nprocs}
    for final in (data, split, restarted):
        assert final[1] == 256
        assert final[0] == pytest.approx(single[0], rel=1e-12)


def builds_after_first_run(log):
    """LAMMPS's "Neighbor list builds" of the log's runs after the first, summed."""
    return sum(int(n) for n in re.findall(r"Neighbor list builds = (\d+)", log)[1:])


@pytest.mark.parametrize("nprocs", [1, 2])
def test_runs_without_set_up_keep_the_history_of_their_first_steps(lmp, nprocs):
    """`run N pre no` has no set-up: the list and the contact history's flat arrays go on from
    the last run's, and the pair writes the new history there. The first
    rebuild within such a run must store that history, not the records stored when the last run
    ended (it did: the runs equalled the uninterrupted one only with `check no`, whose rebuild
    falls on the run's first step). The fcc bed of test_dense_frictional_bed_restarts_as_one_run
    with a skin of 10 nm (its spheres vibrate by about 25 nm in their contacts) and `every 25 check
    yes`: a rebuild every 25 steps, the first of a run up to 25 steps after its start."""
    scene = dense_scenes.fcc(1e-3, 1e-6, steps=400, gap_ratio=-0.002, extra="friction 0.3 rolling 0.02",
                             loop="geom").replace("neighbor 0.0002 bin", "neighbor 1e-08 bin")
    scene = scene.replace("every 1 check yes", "every 25 check yes")
    assert "neighbor 1e-08 bin" in scene and "every 25 check yes" in scene
    # The spins, which the tangential springs drive (the energy is the normal springs').
    scene += 'print "RESULT spin $(c_rot:%.17g)"\n'
    single = lmp(scene, nprocs=nprocs)
    assert single["spin"] > 0.0
    for commands in (("run 150", "run 250 pre no"), ("run 90", "run 110 pre no", "run 200 pre no")):
        state = lmp(dense_scenes.split(scene, *commands), nprocs=nprocs)
        assert builds_after_first_run(lmp.log) > 0, commands    # a rebuild inside the run without set-up
        assert dense_scenes.ranks(lmp.log) == {nprocs}
        assert state["final"][1] == 256
        assert state["final"][0] == pytest.approx(single["final"][0], rel=1e-12), commands
        assert state["spin"] == pytest.approx(single["spin"], rel=1e-12, abs=0.0), commands

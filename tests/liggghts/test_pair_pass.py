"""`pair_style gran model lubricated` replaces LIGGGHTS's pass over the neighbour list with a
lean one (src/liggghts/pair_pass.h): the same calls to the contact model in the same order, the
pairs beyond LIGGGHTS's contact distance skipped after their distance alone, so the same forces.
LUBRICATED_LIGGGHTS_PASS=liggghts runs LIGGGHTS's own pass instead: both must give the same
trajectory to round-off (1e-13 relative; measured: equal to the bit).

Scenes: the wet polydisperse chain between walls with friction (1 and 2 ranks, the film's
activation fixed and from a grid spacing), and the preloaded random 1:10 packing (592 sustained
contacts, films around them), wet, with tangential history, on 1 and 2 ranks. A lean pass that
drops j's share, a contact or a close pair, or the tangential history's reset of the pairs that
separate, moves these far beyond the tolerance."""
import pytest

import dense_packings
from liggghts_chain import chain, dump_state
from test_dense_beds import packing_rows, packing_run, packings  # noqa: F401 (fixture)
from test_parallel_restart import assert_same_state

ROUND_OFF = 1e-13
LEAN = "pair gran model lubricated: lean pair pass"
LIGGGHTS = "pair gran model lubricated: LIGGGHTS's own pair pass"


def both_passes(run, script, nprocs):
    lean = run.lig(script, nprocs=nprocs)
    assert LEAN in run.log and LIGGGHTS not in run.log
    lean_log = run.log
    own = run.lig(script, nprocs=nprocs, environment={"LUBRICATED_LIGGGHTS_PASS": "liggghts"})
    assert LIGGGHTS in run.log and LEAN not in run.log
    return lean, lean_log, own, run.log


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("activation", ["fixed", "grid"])
def test_lean_pass_follows_liggghts_pass_on_the_chain(run, activation, nprocs):
    text = chain(processors="processors 2 1 1" if nprocs == 2 else "")
    if activation == "grid":
        fixed = "fix m5 all property/global lubricatedActivation scalar 0.09375\n"
        assert fixed in text
        text = text.replace(fixed, "fix m5 all property/global lubricatedGridSpacing scalar 1e-4\n")
    lean, _, own, _ = both_passes(run, text + dump_state(), nprocs)
    assert_same_state(own, lean, rel=ROUND_OFF)


def frictional_wet_packing(data):
    script = packing_run(data, "lubricatedContactSteps scalar 8", dt=5e-6, steps=400,
                         mu=dense_packings.viscosity_for_stokes(1.0), every=20)
    script = script.replace("pair_style gran model lubricated\n",
                            "fix mu all property/global coefficientFriction peratomtypepair 1 0.5\n"
                            "pair_style gran model lubricated tangential history\n")
    assert "tangential history" in script
    return script + dump_state()


@pytest.mark.parametrize("nprocs", [1, 2])
def test_lean_pass_follows_liggghts_pass_in_a_dense_frictional_bed(run, packings, nprocs):  # noqa: F811
    lean, lean_log, own, own_log = both_passes(run, frictional_wet_packing(packings["preloaded"]), nprocs)
    rows, reference = packing_rows(lean_log), packing_rows(own_log)
    assert len(rows) == len(reference) == 21 and {r[1] for r in rows} == {300}
    assert reference[-1][2] < 0.5 * reference[0][2]    # the bed dissipates: contacts and films act
    for row, ref in zip(rows, reference):
        assert row == pytest.approx(ref, rel=ROUND_OFF, abs=0.0)
    assert own.pop("atoms") == lean.pop("atoms") == 300
    assert_same_state(own, lean, rel=ROUND_OFF)


def test_unknown_pass_is_refused(run):
    with pytest.raises(Exception, match="LUBRICATED_LIGGGHTS_PASS = 'fast' \\(expected lean or liggghts\\)"):
        run.lig(chain(steps=10), environment={"LUBRICATED_LIGGGHTS_PASS": "fast"})

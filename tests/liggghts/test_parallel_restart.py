"""mpirun -np 2 and -np 4 agree with 1 rank, a restart continues the run, and the launcher and the
LD_PRELOAD route give the same run. Relative tolerance 1e-10: ranks only reorder sums."""
import pytest

from liggghts_chain import chain, dump_state, setup


def assert_same_state(a, b, rel=1e-10):
    assert a.keys() == b.keys() and len(a) == 24
    for key in a:
        assert b[key] == pytest.approx(a[key], rel=rel, abs=1e-13), key


def collisions_happened(log):
    rows = [line.split() for line in log.splitlines()]
    ke = [float(r[1]) for r in rows if len(r) == 2 and r[0].isdigit()]
    return len(ke) > 2 and ke[-1] < 0.9 * ke[0]


@pytest.mark.parametrize("nprocs", [2, 4])
@pytest.mark.parametrize("tangential", ["history", "no_history"])
def test_one_and_more_ranks_agree(run, tangential, nprocs):
    serial = run.lig(chain(tangential=tangential) + dump_state())
    assert collisions_happened(run.log)
    parallel = run.lig(chain(tangential=tangential, processors=f"processors {nprocs} 1 1") + dump_state(),
                       nprocs=nprocs)
    assert f"{nprocs} by 1 by 1 MPI processor grid" in run.log
    assert_same_state(serial, parallel)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_restart_continues_the_run(run, nprocs):
    """run 300; write_restart; run 300  ==  read_restart (pair style from the file); run 300."""
    processors = "processors 2 1 1" if nprocs == 2 else ""
    reference = run.lig(chain(steps=300, extra_run="write_restart mid.restart\nrun 300",
                              processors=processors) + dump_state(), nprocs=nprocs)
    restarted = run.lig(f"""atom_modify map array
communicate single vel yes
newton off
{processors}
read_restart mid.restart
{setup()}
run 300
""" + dump_state(), nprocs=nprocs, name="in.restart")
    assert "pair_style" not in (run.dir / "in.restart").read_text()
    assert_same_state(reference, restarted)


def test_launcher_runs_the_same(run):
    preloaded = run.lig(chain() + dump_state())
    launched = run.lig(chain() + dump_state(), launcher=True)
    assert_same_state(preloaded, launched, rel=0.0)

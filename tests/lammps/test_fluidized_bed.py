"""Fluidised beds with fix fluid/drag (Richardson-Zaki hindrance, superficial velocity).

examples/fluidized_bed/in.rz_column: 400 spheres in a 5d x 5d column settle from a loose
suspension into a bed fluidised by U = r u_t; its mean solid fraction must follow
Richardson & Zaki, U = u_t (1 - phi)^n with n = 4.65, within 10 % (the issue's tolerance).
"""
import math
import pathlib

import pytest

from scene_chain import dump_state

ROOT = pathlib.Path(__file__).resolve().parents[2]
COLUMN = (ROOT / "examples" / "fluidized_bed" / "in.rz_column").read_text()


def richardson_zaki_phi(ratio, n=4.65):
    return 1.0 - ratio ** (1.0 / n)


@pytest.mark.parametrize("ratio", [0.1, 0.2, 0.4])
def test_bed_expansion_follows_richardson_zaki(lmp, ratio):
    phi = lmp(COLUMN, ratio=ratio)["phi"]
    assert phi == pytest.approx(richardson_zaki_phi(ratio), rel=0.10)


def test_without_hindrance_the_bed_collapses(lmp):
    """The contrast that makes the test above meaningful: single-sphere drag cannot hold a
    bed up at U = 0.4 u_t, it settles into a packing."""
    script = COLUMN.replace("hindrance richardson-zaki 4.65 ", "")
    phi = lmp(script, ratio=0.4)["phi"]
    assert phi > 2.0 * richardson_zaki_phi(0.4)


def test_two_ranks_agree_statistically(lmp):
    phi = lmp(COLUMN, nprocs=2, ratio=0.2)["phi"]
    assert "1 by 1 by 2 MPI processor grid" in lmp.log
    assert phi == pytest.approx(richardson_zaki_phi(0.2), rel=0.10)


# 12 spheres on a helix through the column (explicit IDs, identical on any rank count)
HELIX = "\n".join(f"create_atoms    1 single {1e-3 * (2.5 + 1.6 * math.cos(k))} "
                  f"{1e-3 * (2.5 + 1.6 * math.sin(k))} {1e-3 * (3 + 5.5 * k)} units box"
                  for k in range(12))
SMALL = COLUMN[:COLUMN.index("create_atoms    1 random")] + HELIX + "\n" + \
    COLUMN[COLUMN.index("set             group all"):]
SMALL = SMALL[:SMALL.index('print           "RESULT phi')]


def continuation(script):
    """The same run restarted: the set-up becomes read_restart, the first run is skipped."""
    start = script.index("units           si")
    end = script.index("pair_style")
    setup_free = script[:start] + "atom_modify     map array\nread_restart    bed.restart\n" + \
        "comm_modify     vel yes\n" + script[end:]
    return setup_free.replace("run             ${settle}\n", "")


def assert_same(a, b):
    assert a.keys() == b.keys() and len(a) == 24
    for key in a:
        assert b[key] == pytest.approx(a[key], rel=1e-10, abs=1e-13), key


def test_small_bed_is_identical_on_one_and_two_ranks_and_after_restart(lmp):
    """12 spheres crossing the rank boundary, with hindrance bins summed over ranks."""
    steps = dict(ratio=0.2, settle=3000, sample=3000)
    serial = lmp(SMALL + dump_state(12), **steps)
    parallel = lmp(SMALL + dump_state(12), nprocs=2, **steps)
    assert_same(serial, parallel)
    first = SMALL.replace("reset_timestep  0\n", "write_restart   bed.restart\nreset_timestep  0\n")
    reference = lmp(first + dump_state(12), nprocs=2, **steps)
    restarted = lmp(continuation(SMALL) + dump_state(12), nprocs=2, name="in.restart", **steps)
    assert_same(reference, restarted)

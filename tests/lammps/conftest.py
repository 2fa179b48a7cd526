"""Shared fixtures for the tests that run LAMMPS with the plugin."""
import os
import pathlib
import shutil
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "tests"))

import lammps_run  # noqa: E402
from scratch_support import pytest_runtest_makereport, scratch_directory  # noqa: E402,F401

SCRATCH = pathlib.Path(os.environ.get("LUBRICATED_SCRATCH", ROOT / "build" / "test-scratch"))


@pytest.fixture(scope="session", autouse=True)
def plugin_built():
    shutil.rmtree(SCRATCH, ignore_errors=True)    # what failed last time is gone now
    if not lammps_run.PLUGIN.exists():
        pytest.exit(f"{lammps_run.PLUGIN} is missing: run 'make build' first", returncode=2)


@pytest.fixture
def scratch(request):
    """A scratch directory under build/, removed again when the test passes."""
    yield from scratch_directory(request, SCRATCH)


@pytest.fixture
def lmp(scratch):
    """lmp(script, **variables) -> results dict; lmp.log is the last log text."""
    def run(script, nprocs=1, name="in.run", check=True, env=None, **variables):
        results, log = lammps_run.run(script, scratch, variables, nprocs=nprocs, name=name,
                                      check=check, env=env)
        run.log = log
        return results
    run.dir = scratch
    return run

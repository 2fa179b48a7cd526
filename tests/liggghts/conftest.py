"""Fixtures for the LIGGGHTS runs of model lubricated (skipped, with the reason, when Debian's
LIGGGHTS or the model library is absent: scripts/setup_liggghts.sh says what to install)."""
import pathlib
import shutil
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "tests" / "lammps"))
sys.path.insert(0, str(ROOT / "tests"))

import lammps_run  # noqa: E402
import liggghts_run  # noqa: E402
from scratch_support import pytest_runtest_makereport, scratch_directory  # noqa: E402,F401

SCRATCH = ROOT / "build" / "test-scratch-liggghts"


def pytest_collection_modifyitems(config, items):
    missing = liggghts_run.available()
    if missing:
        skip = pytest.mark.skip(reason=f"LIGGGHTS tests skipped: {missing}")
        for item in items:
            item.add_marker(skip)


@pytest.fixture(scope="session", autouse=True)
def clean_scratch():
    shutil.rmtree(SCRATCH, ignore_errors=True)


@pytest.fixture
def scratch(request):
    yield from scratch_directory(request, SCRATCH)


class Runner:
    """lig(script) runs LIGGGHTS, lmp(script) the LAMMPS plugin, both in the test's scratch."""

    def __init__(self, directory):
        self.dir = directory
        self.log = ""

    def lig(self, script, nprocs=1, name="in.liggghts", **kwargs):
        results, self.log = liggghts_run.run(script, self.dir, nprocs=nprocs, name=name, **kwargs)
        return results

    def lmp(self, script, nprocs=1, name="in.lammps"):
        if not lammps_run.PLUGIN.exists():
            pytest.skip(f"{lammps_run.PLUGIN} is missing: run 'make build'")
        results, self.log = lammps_run.run(script, self.dir, nprocs=nprocs, name=name)
        return results


@pytest.fixture
def run(scratch):
    return Runner(scratch)

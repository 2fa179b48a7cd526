"""Fixtures for the LIGGGHTS runs of model lubricated (skipped, with the reason, when Debian's
LIGGGHTS or the model library is absent: scripts/setup_liggghts.sh says what to install)."""
import pathlib
import shutil
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "tests" / "lammps"))

import lammps_run  # noqa: E402
import liggghts_run  # noqa: E402

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
    path = SCRATCH / request.node.name.replace("[", "_").replace("]", "").replace("/", "_")
    shutil.rmtree(path, ignore_errors=True)
    path.mkdir(parents=True)
    yield path
    if not getattr(request.node, "failed", False):
        shutil.rmtree(path, ignore_errors=True)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    if report.when == "call" and report.failed:
        item.failed = True


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

"""Scratch directories for tests that run LAMMPS or LIGGGHTS: one per test under build/,
removed when the test passes, kept (with inputs and logs) when it fails. Both conftests
import scratch_directory() and the report hook below (pytest registers hooks by name)."""
import shutil

import pytest


def scratch_directory(request, root):
    """Generator for a scratch fixture: root/<test name>, emptied first."""
    path = root / request.node.name.replace("[", "_").replace("]", "").replace("/", "_")
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

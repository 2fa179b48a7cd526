"""Run Debian's LIGGGHTS 3.8.0 with `model lubricated`, for tests, examples and bench.

The stock `liggghts` binary gets liblubricated_liggghts.so through LD_PRELOAD (Open MPI's
mpirun passes it on with -x); launcher=True runs build/liggghts-lubricated instead, which is
linked to the library. Like lammps_run.py, everything goes to a scratch directory and only the
"RESULT name value ..." lines an input prints come back, parsed into a dict.
"""
import os
import pathlib
import shutil
import subprocess

from lammps_run import LammpsError, parse_results

ROOT = pathlib.Path(__file__).resolve().parents[1]
BUILD = ROOT / "build"
LIBRARY = BUILD / "liblubricated_liggghts.so"
LAUNCHER = BUILD / "liggghts-lubricated"
LIGGGHTS = shutil.which("liggghts") or "/usr/bin/liggghts"
MPIRUN = shutil.which("mpirun.openmpi") or "/usr/bin/mpirun.openmpi"


def available():
    """'' when LIGGGHTS runs can be made, else what is missing."""
    if not os.path.exists(LIGGGHTS):
        return "liggghts is not installed (apt-get install liggghts libliggghts-dev)"
    if not LIBRARY.exists():
        return f"{LIBRARY} was not built (libliggghts-dev or libopenmpi-dev missing at cmake time)"
    return ""


def command(nprocs=1, launcher=False, preload=True, exported=()):
    """The command line; exported: environment variables mpirun passes on to the ranks."""
    program = str(LAUNCHER) if launcher else LIGGGHTS
    if nprocs == 1:
        return [program]
    args = [MPIRUN, "-np", str(nprocs), "--oversubscribe", "--mca", "btl", "self,vader"]
    if os.geteuid() == 0:
        args.append("--allow-run-as-root")
    if preload and not launcher:
        args += ["-x", "LD_PRELOAD"]
    for name in exported:
        args += ["-x", name]
    return args + [program]


def run(script, workdir, nprocs=1, name="in.liggghts", timeout=600, check=True, launcher=False,
        preload=True, variables=None, environment=None):
    """Write script to workdir/name, run LIGGGHTS on it, return (results dict, log text).
    environment: extra environment variables for every rank."""
    workdir = pathlib.Path(workdir)
    workdir.mkdir(parents=True, exist_ok=True)
    (workdir / name).write_text(script)
    log = workdir / (name + ".log")
    # A screen file, not "-screen none": LIGGGHTS's mesh reader prints to screen unchecked.
    environment = environment or {}
    args = command(nprocs, launcher, preload, environment.keys()) + ["-in", name, "-log", log.name,
                                                 "-screen", name + ".screen", "-echo", "none"]
    for key, value in (variables or {}).items():
        args += ["-var", key, str(value)]
    env = dict(os.environ)
    env.pop("LD_PRELOAD", None)
    if preload and not launcher:
        env["LD_PRELOAD"] = str(LIBRARY)
    env["OMP_NUM_THREADS"] = "1"
    env["OMPI_MCA_btl_vader_single_copy_mechanism"] = "none"
    env.update({key: str(value) for key, value in environment.items()})
    # errors="replace": LIGGGHTS prints some ERROR texts a second time from freed memory.
    proc = subprocess.run(args, cwd=workdir, env=env, capture_output=True, text=True,
                          encoding="utf-8", errors="replace", timeout=timeout)
    text = log.read_text(errors="replace") if log.exists() else ""
    text += proc.stdout + proc.stderr
    if check and (proc.returncode != 0 or "ERROR" in text):
        error = next((line for line in text.splitlines() if "ERROR" in line), text[-2000:])
        raise LammpsError(error, text)
    return parse_results(text), text

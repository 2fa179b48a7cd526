"""Instructions on the hot path of one contact: callgrind counts of the pair style's compute()
and fix wall/lubrication's pre_force() and post_force(), per atom and step, for builds of the plugin compared in
the same run (issue 22: a shared contact kernel must cost nothing).

    .venv/bin/python bench/contact_instructions.py                       # this build
    .venv/bin/python bench/contact_instructions.py --plugin before=/tmp/b/lubricatedplugin.so \\
        --plugin after=build/lubricatedplugin.so

Instruction counts (valgrind's Ir) do not depend on the machine's load, so one run per scene
and build is exact; they count instructions, not cycles (cache misses and branch
mispredictions are not in them: bench/settling_bed.py times the real runs).

Scenes (SI, R = 1 mm, rho 2500 kg/m^3, 256 spheres on an fcc lattice compressed so that every
sphere overlaps its 12 neighbours by `--overlap` of 2R, random velocities and spins, so that
each contact is sustained and slips): the pair style dry with friction; wet with friction,
rolling and the shear film; and the same wet frictional contact as walls on both z faces of
the lattice (its bottom and top layers in overlap with them).
"""
import argparse
import math
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import lammps_run  # noqa: E402

R = 1.0e-3
RHO = 2500.0
SPEED = 0.02
SPIN = 20.0    # rad/s

SCENES = {
    "pair dry friction": ("0.9 ncontact 8 friction 0.4", None),
    "pair wet friction rolling shearfilm": (
        "0.9 ncontact 8 friction 0.4 rolling 0.05 viscosity 1e-3 activation 0.1 shearfilm yes", None),
    "wall wet friction rolling shearfilm": (
        "0.9 ncontact 8", "0.8 ncontact 8 friction 0.4 rolling 0.05 viscosity 2e-3 activation 0.1 shearfilm yes"),
}


def script(pair_coeff, wall, overlap, steps, cells=4):
    a = 2.0 * R * (1.0 - overlap) * math.sqrt(2.0)
    top = (cells - 0.5) * a    # the last layer of the lattice is at (cells - 1/2) a
    wall_fix = ""
    if wall:
        lo, hi = -R * (1.0 - overlap), top + R * (1.0 - overlap)
        wall_fix = f"fix walls all wall/lubrication {wall} zplane {lo!r} {hi!r}\n"
    return f"""plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary p p {'f' if wall else 'p'}
comm_modify vel yes
newton on
lattice fcc {a!r}
region box block 0 {cells} 0 {cells} {-0.5 if wall else 0} {cells}
create_box 1 box
region atoms block 0 {cells} 0 {cells} 0 {cells - 0.25 if wall else cells}
create_atoms 1 region atoms
set group all diameter {2 * R!r} density {RHO}
variable vx atom {SPEED}*(2*random(0,1,11)-1)
variable vy atom {SPEED}*(2*random(0,1,12)-1)
variable vz atom {SPEED}*(2*random(0,1,13)-1)
velocity all set v_vx v_vy v_vz units box
variable wx atom {SPIN}*(2*random(0,1,14)-1)
variable wy atom {SPIN}*(2*random(0,1,15)-1)
set group all omega v_wx v_wx v_wy
pair_style lubricated/springdashpot
pair_coeff * * {pair_coeff}
{wall_fix}neighbor {0.2 * R!r} bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep 1e-6
thermo {steps}
thermo_modify lost error
run 20
run {steps}
print "RESULT atoms $(atoms)"
"""


def instructions(plugin, scene, args, workdir):
    """Inclusive Ir of the pair style's compute() and the wall fix's force hooks, per atom and step."""
    pair_coeff, wall = SCENES[scene]
    workdir.mkdir(parents=True, exist_ok=True)
    (workdir / "in.run").write_text(script(pair_coeff, wall, args.overlap, args.steps))
    out = (workdir / "callgrind.out").resolve()
    # Collected only inside the two functions, and only in the second run (the first warms up:
    # neighbor lists and history grown, the set-up evaluation done).
    cmd = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", "--collect-atstart=no",
           "--toggle-collect=*PairLubricatedSpringDashpot::compute*",
           "--toggle-collect=*FixWallLubrication::pre_force*",
           "--toggle-collect=*FixWallLubrication::post_force*"] + lammps_run.lmp_command(1) + [
        "-in", "in.run", "-log", "log.lammps", "-screen", "none", "-nocite", "-var", "plugin", str(plugin)]
    proc = subprocess.run(cmd, cwd=workdir, env=lammps_run.lmp_env(), capture_output=True, text=True,
                          timeout=1800)
    log = (workdir / "log.lammps").read_text() if (workdir / "log.lammps").exists() else ""
    if proc.returncode != 0 or "ERROR" in log or "RESULT atoms" not in log:
        raise RuntimeError(f"{scene}: run failed\n{log[-2000:]}{proc.stderr[-2000:]}")
    atoms = int(float(lammps_run.parse_results(log)["atoms"]))
    annotated = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", str(out)], capture_output=True,
                               text=True, check=True).stdout
    # The engine's entry points (virtual: never inlined): the pair's compute(), the wall fix's
    # pre_force() (the walls) and post_force() (their deferred films), summed per style.
    costs = {}
    for line in annotated.splitlines():
        # One line per function and object ("[...so]"; with debug information the parts inlined
        # from other files are listed besides, without it).
        m = re.match(r"\s*([\d,]+)\s.*?(PairLubricatedSpringDashpot::compute|FixWallLubrication::p\w+_force)"
                     r"\(int.*\[.*\]\s*$", line)
        if m:
            style = m.group(2).split("::")[0]
            costs[style] = costs.get(style, 0) + int(m.group(1).replace(",", ""))
    # compute() also runs in the set-up of both runs; pre_force() and post_force() in steps only.
    calls = {"PairLubricatedSpringDashpot": args.steps + 22, "FixWallLubrication": args.steps + 20}
    per_atom_step = {k: v / atoms / calls[k] for k, v in costs.items()}
    return per_atom_step


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--plugin", action="append", default=[],
                        help="NAME=PATH of a plugin build to measure (default: this=build/lubricatedplugin.so)")
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--overlap", type=float, default=0.003, help="overlap of neighbours, in 2R")
    parser.add_argument("--keep", action="store_true", help="keep the callgrind output files (for callgrind_annotate)")
    parser.add_argument("--out", default=str(ROOT / "build" / "bench-instructions"))
    args = parser.parse_args()
    plugins = [p.split("=", 1) for p in args.plugin] or [["this", str(lammps_run.PLUGIN)]]
    out = pathlib.Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    results = {}
    for scene in SCENES:
        for name, path in plugins:
            work = out / re.sub(r"\W+", "_", scene) / name
            results[(scene, name)] = instructions(pathlib.Path(path).resolve(), scene, args, work)
            if not args.keep:
                (work / "callgrind.out").unlink(missing_ok=True)
    base = plugins[0][0]
    print(f"Ir per atom and step ({args.steps} steps after 20, 256 atoms; ratio against '{base}')")
    print(f"{'scene':40s} {'style':30s} " + " ".join(f"{n:>16s}" for n, _ in plugins))
    for scene in SCENES:
        functions = sorted({f for (s, _), r in results.items() if s == scene for f in r})
        for function in functions:
            row = []
            for name, _ in plugins:
                value = results[(scene, name)].get(function, float("nan"))
                ratio = value / results[(scene, base)].get(function, float("nan"))
                row.append(f"{value:9.0f} ({ratio:4.2f})")
            print(f"{scene:40s} {function:30s} " + " ".join(f"{c:>16s}" for c in row))


if __name__ == "__main__":
    main()

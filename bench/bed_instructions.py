"""Instructions per particle-step of the pair styles on an independent bed (issue 19): callgrind
counts (valgrind's Ir) of the pair's compute() on the bed of bench/independent_beds.py, settled
and active, for the plugin's frictional styles and gran/hooke/history, with a split of the
plugin's instructions by source file (a build with -g: the general loop's inlined kernel files,
the vectorised loops, pass 1, libm).

    .venv/bin/python bench/bed_instructions.py                               # this build
    .venv/bin/python bench/bed_instructions.py --plugin before=/tmp/b/lubricatedplugin.so \\
        --plugin after=build/prof/lubricatedplugin.so --split after

Instruction counts do not depend on the machine's load (one run per scene and build is exact);
they count instructions, not cycles (no cache misses, no mispredicted branches). Under valgrind
the loops' x86-64-v3 (AVX2) clones run, not the AVX-512 ones. The bed: OUT/bed<size>/settled.data
of bench/independent_beds.py (built here the same way when missing; 2000 spheres: about 10 s
natively). Each run: `--steps` steps from the snapshot (no contact history: every style starts
the same), all compute() calls counted, set-up included (1 + steps calls settled; active:
steps + steps/100, the set-up of each 100-step chunk).
"""
import argparse
import pathlib
import re
import shutil
import subprocess
import sys
from types import SimpleNamespace

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import independent_beds as beds  # noqa: E402
import lammps_run  # noqa: E402
from bench_common import SETTINGS  # noqa: E402

STYLES = ["gran/hooke/history", "plugin dry+friction", "plugin wet+friction", "plugin wet+friction shearfilm no"]

SCRIPT = beds.HEADER + """{pair}
{wall}
""" + SETTINGS + """thermo_style custom step atoms ke
thermo {steps}
{drive}
run {steps}{chunks}
print "RESULT atoms $(atoms)"
"""

# Parts of the plugin's compute(): by the function the instructions run in (the vectorised loops,
# pass 1), else by their source file (inlined code keeps its file in the debug information):
# name -> pattern on "file:function".
PARTS = [
    ("vectorised loops (vector_pairs.cpp, kernels inlined)", r":.*vector_pairs::"),
    ("pass 1 (select_pairs, update_step_reach)", r":.*(select_pairs|update_step_reach)"),
    ("gathers and scatters of the vectorised loops (vector_forces.h)", r"^\S*vector_forces\.h:"),
    ("general loop: normal (normal_model, contact_step, lubrication)",
     r"^\S*(normal_model\.h|contact_step\.h|lubrication\.h|spring_dashpot\.h):"),
    ("general loop: tangential (contact.h, tangential.h)", r"^\S*(contact\.h|tangential\.h):"),
    ("general loop: libm (log, expm1, sqrt)", r"libm|e_log|s_expm1|expm1|w_log|e_exp"),
    ("film budget (film_budget.h, records, correction)", r"^\S*(film_budget\.h|pair_lubricated_springdashpot\.h|_bed\.cpp):"),
    ("contact history lookups", r"^\S*fix_contact_history"),
    ("general loop: the rest (evaluate_pair, scatter)", r"^\S*pair_lubricated_springdashpot_eval\.cpp:"),
]

def run_one(plugin, style, state, args, work):
    pair, wall = beds.styles()[style]
    work.mkdir(parents=True, exist_ok=True)
    active = state == "active"
    fmt = dict(data=str((args.bed / "settled.data").resolve()), pair=pair, wall=wall, g=beds.G, skin=beds.SKIN,
               dt=beds.DT, steps=args.steps, drive=beds.ACTIVE_DRIVE if active else "",
               chunks=beds.ACTIVE_CHUNKS if active else "")
    (work / "in.run").write_text(SCRIPT.format(**fmt))
    out = (work / "callgrind.out").resolve()
    target = "PairGranHookeHistory::compute" if style.startswith("gran") else "PairLubricatedSpringDashpot::compute"
    cmd = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", "--collect-atstart=no",
           f"--toggle-collect=*{target}*"] + lammps_run.lmp_command(1) + [
        "-in", "in.run", "-log", "log.lammps", "-screen", "none", "-nocite", "-var", "plugin", str(plugin)]
    proc = subprocess.run(cmd, cwd=work, env=lammps_run.lmp_env(), capture_output=True, text=True, timeout=3600)
    log = (work / "log.lammps").read_text() if (work / "log.lammps").exists() else ""
    if proc.returncode != 0 or "ERROR" in log or "RESULT atoms" not in log:
        raise RuntimeError(f"{style} {state}: run failed\n{log[-2000:]}{proc.stderr[-2000:]}")
    atoms = int(float(lammps_run.parse_results(log)["atoms"]))
    calls = args.steps + (args.steps // beds.KICK_EVERY if active else 1)
    annotated = subprocess.run(["callgrind_annotate", "--auto=no", "--inclusive=no", "--show-percs=no",
                                "--threshold=100", str(out)], capture_output=True, text=True, check=True).stdout
    total = int(re.search(r"^\s*([\d,]+)\s+PROGRAM TOTALS", annotated, re.M).group(1).replace(",", ""))
    parts = {}
    for line in annotated.splitlines():
        m = re.match(r"\s*([\d,]+)\s+(\S.*:.*)$", line)    # Ir  file:function (exclusive)
        if not m or "PROGRAM TOTALS" in line:
            continue
        part = next((name for name, pattern in PARTS if re.search(pattern, m.group(2))), "other")
        parts[part] = parts.get(part, 0) + int(m.group(1).replace(",", ""))
    if not args.keep:
        out.unlink(missing_ok=True)
    scale = 1.0 / (atoms * calls)
    return total * scale, {k: v * scale for k, v in parts.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--plugin", action="append", default=[],
                        help="NAME=PATH of a plugin build (default: this=build/lubricatedplugin.so)")
    parser.add_argument("--size", type=int, default=2000)
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--states", nargs="+", choices=["settled", "active"], default=["settled", "active"])
    parser.add_argument("--styles", nargs="+", default=STYLES)
    parser.add_argument("--split", action="append", default=[], help="NAME of a build (with -g) to split by file")
    parser.add_argument("--keep", action="store_true", help="keep the callgrind output files")
    parser.add_argument("--out", default=str(ROOT / "build" / "bench-bed-instructions"))
    parser.add_argument("--beds", default=str(ROOT / "build" / "bench-beds"),
                        help="independent_beds.py's OUT, where the bed is cached (default build/bench-beds)")
    args = parser.parse_args()
    plugins = [p.split("=", 1) for p in args.plugin] or [["this", str(lammps_run.PLUGIN)]]
    bed_args = SimpleNamespace(out=args.beds, seed=beds.SEED, settle_min=beds.SETTLE_MIN,
                               settle_max=beds.SETTLE_MAX, settle_ke=beds.SETTLE_KE, rebuild=False)
    args.bed, _ = beds.build_bed(args.size, bed_args, print)
    out = pathlib.Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    rows = []
    for state in args.states:
        for style in args.styles:
            for name, path in plugins[:1] if style.startswith("gran") else plugins:
                work = out / state / re.sub(r"\W+", "_", f"{style}_{name}")
                total, parts = run_one(pathlib.Path(path).resolve(), style, state, args, work)
                rows.append((state, style, name, total, parts))
                print(f"{state:8s} {style:34s} {name:10s} {total:8.0f} Ir per particle-step", flush=True)
    print(f"\nIr per particle-step, pair compute() only, {args.size} spheres, {args.steps} steps")
    print("| state | style | build | Ir |")
    print("|---|---|---|---:|")
    for state, style, name, total, _ in rows:
        print(f"| {state} | {style} | {'' if style.startswith('gran') else name} | {total:.0f} |")
    for state, style, name, total, parts in rows:
        if name not in args.split or style.startswith("gran"):
            continue
        print(f"\n{state}, {style}, {name}: {total:.0f} Ir per particle-step")
        for part, ir in sorted(parts.items(), key=lambda kv: -kv[1]):
            print(f"  {part:66s} {ir:8.0f}  {ir / total:5.1%}")


if __name__ == "__main__":
    main()

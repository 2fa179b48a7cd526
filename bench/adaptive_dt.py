"""Adaptive time stepping: fix dt/reset changing the time step at every step of a falling and
landing bed, the plugin against LAMMPS's built-in gran/hooke in the same run (issue 18: each
change cost the plugin ~3 ms, 2000 steps of 704 spheres 5.0 s against 0.15 s).

    .venv/bin/python bench/adaptive_dt.py                      # 700 and 2000 spheres, ~2 min
    .venv/bin/python bench/adaptive_dt.py --sizes 700 --repeats 2 --results none

The bed is bench/settling_bed.py's initial loose packing (same R, density, e_d, N_c, gravity,
floor, neighbor settings; sizes and seed varied here), timed from its start: the spheres fall
and land, so the fastest speed, and with it the time step that `fix dt/reset 1 NULL dt_max
{xmax} units box` chooses, changes at every step. Each style also runs at a fixed time step,
so that the cost of the changes alone shows. Runs are interleaved (style after style, then the
next repetition); reported: ns per particle-step, median and spread of the repetitions, and the
plugin's ratio to gran/hooke measured alike.
"""
import argparse
import pathlib
import shutil
import statistics
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import bench_common  # noqa: E402
import lammps_run  # noqa: E402
import settling_bed as bed  # noqa: E402

XMAX = 0.002 * bed.R    # largest move per step: at 0.1 m/s dt = 2e-5 s, the bed's own step

TIMED = bed.HEADER + """read_data init.data
{pair}
{wall}
""" + bed.SETTINGS + """{adapt}
thermo_style custom step atoms ke dt
thermo {steps}
run {steps}
print "RESULT dt_final $(dt:%.6g)"
print "RESULT atoms $(atoms)"
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", type=int, nargs="+", default=[700, 2000])
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument("--out", default=str(ROOT / "build" / "bench-adaptive"))
    parser.add_argument("--results", default=str(bench_common.RESULTS),
                        help="markdown file whose section 'adaptive' gets the results ('none' to skip)")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    styles = {k: v for k, v in bed.styles().items() if k in ("gran/hooke", "plugin dry", "plugin wet")}
    modes = {"fixed dt": "", "dt/reset every step": f"fix adapt all dt/reset 1 NULL {bed.DT} {XMAX!r} units box"}
    rows = []
    for size in args.sizes:
        work = out / f"bed{size}"
        work.mkdir(parents=True)
        bed.write_initial(work / "init.data", size, 20 * bed.R * (size / 2000) ** 0.5, args.seed + size)
        times = {}
        for rep in range(args.repeats):
            for mode, adapt in modes.items():
                for name, (pair, wall) in styles.items():
                    script = TIMED.format(pair=pair, wall=wall, adapt=adapt, steps=args.steps, g=bed.G,
                                          skin=bed.SKIN, dt=bed.DT)
                    result, log = lammps_run.run(script, work, name=f"in.{rep}", timeout=1800)
                    timing = bed.parse_log(log)
                    assert int(result["atoms"]) == size, f"{name}: atoms lost"
                    times.setdefault((mode, name), []).append(timing["ns"])
                    if adapt and rep == 0:
                        print(f"{size} {name}: dt at the end {result['dt_final']:.3g} s", flush=True)
        for mode in modes:
            base = statistics.median(times[(mode, "gran/hooke")])
            for name in styles:
                t = times[(mode, name)]
                rows.append((size, mode, name, statistics.median(t), min(t), max(t), statistics.median(t) / base))
    lines = ["# Adaptive time stepping (bench/adaptive_dt.py)", "",
             f"One rank, {args.steps} steps from the loose packing (falling and landing), {args.repeats} "
             f"repetitions interleaved; `fix dt/reset 1 NULL {bed.DT} {XMAX:.3g} units box` changes dt at every "
             "step. ns per particle-step: median [min, max]; ratio of medians to gran/hooke in the same mode.", "",
             "| spheres | mode | style | ns/particle-step | ratio to gran/hooke |", "|---|---|---|---|---|"]
    for size, mode, name, med, lo, hi, ratio in rows:
        lines.append(f"| {size} | {mode} | {name} | {med:.1f} [{lo:.1f}, {hi:.1f}] | {ratio:.2f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    (out / "RESULTS_ADAPTIVE.md").write_text(text)
    if args.results != "none":
        bench_common.write_section(args.results, "adaptive", text)


if __name__ == "__main__":
    main()

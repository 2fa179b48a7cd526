"""The time step of the sheared suspension by paired runs: how much eta_s, P and mu change when
dt is halved once and twice from N_c 8, resolved below the statistical noise of one run.

    .venv/bin/python bench/suspension_step_paired.py [--cases 0.56:0.5] [--segments 20]
        [--spacing 0.1] [--window 0.2] [--skip 0.05] [--out build/suspension_step_paired]

bench/suspension_step.py compares independent runs: at phi 0.56 with friction their stress
fluctuates by 10 % over strain 2, so a change of 5 % is not resolved. Here every N_c starts from
the same states: one run at N_c 8 shears the packing (examples/suspension_shear, -var packing 2)
and writes a restart file every --spacing of strain after --settle; from each restart file each
N_c shears on for --window (-var packing 3). The stresses of runs that start from one state stay
correlated over a window much shorter than the strain over which trajectories part, so the
difference of their means over the window after --skip is the step's effect on that state with
little of the flow's noise; its mean over the segments and that mean's standard error are the
change. Whether --skip and --window cover the step's effect on the microstructure shows in the
difference against the strain since the restart (the transient lines: a change still growing at
the end of the window would not be caught). The N_c 8 segments re-run the base run's own steps
from its restart files: they must repeat it (a check of the restart, printed).
Writes bench/data/suspension_step_paired.csv and the section suspension-step-paired of
bench/RESULTS.md (--results none to skip).
"""
import argparse
import concurrent.futures
import csv
import os
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import bench_common  # noqa: E402
import lammps_run  # noqa: E402
import suspension_step  # noqa: E402

SCRIPT = suspension_step.SCRIPT
CSV = ROOT / "bench" / "data" / "suspension_step_paired.csv"
NCS = [8, 16, 32]
ETA_F_GDOT = suspension_step.ETA_F_GDOT
START_STEP = 3000                               # the example's squeeze + relax steps
SAMPLES_PER_STRAIN = 1000


def common_variables(phi, mu_c, nc, args):
    return {"n": args.n, "phi": phi, "mu_c": mu_c, "nc": nc, "gtc": args.gtc, "thermo": 1000000,
            "series": max(1, round(nc / args.gtc / SAMPLES_PER_STRAIN))}


def base_run(out, phi, mu_c, args):
    """N_c 8 from the packing, restart files every --spacing; returns {strain: restart file}."""
    work = out / f"phi{phi:.2f}_mu{mu_c:.1f}" / "base"
    steps_per_strain = NCS[0] / args.gtc
    every = round(args.spacing * steps_per_strain)
    strain = args.settle + (args.segments + 1) * args.spacing
    if not (args.reuse and (work / "in.suspension_shear.log").exists()):
        variables = {**common_variables(phi, mu_c, NCS[0], args), "strain": strain, "average": args.spacing,
                     "packing": 2, "packing_file": suspension_step.packing(out, phi, args),
                     "restart_every": every}
        lammps_run.run(SCRIPT.read_text(), work, variables, name="in.suspension_shear", timeout=6 * 3600)
    # restart N writes at the steps that are multiples of N: take the first --segments from --settle on
    steps = sorted(int(f.name.split(".")[1]) for f in work.glob("suspension.*.restart"))
    chosen = [s for s in steps if s >= START_STEP + args.settle * steps_per_strain - 0.5][:args.segments]
    if len(chosen) < args.segments:
        raise SystemExit(f"{work}: {len(chosen)} restart files after strain {args.settle}, {args.segments} wanted")
    files = {round((s - START_STEP) / steps_per_strain, 6): work / f"suspension.{s}.restart" for s in chosen}
    return files, np.loadtxt(work / "suspension_series.txt", comments="#")[:, 1:4]


def segment(out, phi, mu_c, nc, gamma, restart, args):
    """N_c nc for --window from one restart file; returns the series (strain since the restart, sxy, P)."""
    work = out / f"phi{phi:.2f}_mu{mu_c:.1f}" / f"nc{nc}_at{gamma:.3f}"
    series = work / "suspension_series.txt"
    if not (args.reuse and series.exists()):
        variables = {**common_variables(phi, mu_c, nc, args), "strain": args.window,
                     "average": args.window - args.skip, "packing": 3, "packing_file": restart.resolve()}
        lammps_run.run(SCRIPT.read_text(), work, variables, name="in.suspension_shear", timeout=3600)
    seconds = bench_common.parse_log((work / "in.suspension_shear.log").read_text())["seconds"]
    return np.loadtxt(series, comments="#")[:, 1:4], seconds


def window_means(series, lo, hi):
    strain, sxy, pressure = series.T
    mask = (strain > lo + 1e-12) & (strain <= hi + 1e-12)
    return np.array([sxy[mask].mean(), pressure[mask].mean()])


def restart_check(base, segments, args):
    """Largest difference between the N_c 8 segments and the base run over the same strains, relative
    to the base's mean |sigma_xy|: at the first sample after the set-up (the restart) and over the
    window (the flow's own divergence from round-off). A sample at the set-up itself is left out:
    the set-up sees the box fix deform moved after the last step's forces."""
    first = worst = 0.0
    scale = np.abs(base[:, 1]).mean()
    for gamma, series in segments.items():
        strain = series[:, 0] + gamma
        mask = (strain <= base[-1, 0]) & (series[:, 0] > 1e-12)
        gap = np.abs(series[mask, 1] - np.interp(strain[mask], base[:, 0], base[:, 1])) / scale
        first, worst = max(first, float(gap[0])), max(worst, float(gap.max()))
    return first, worst


def changes(segments_by_nc, args):
    """Per N_c: the mean over segments of (N_c run - N_c 8 run) relative to N_c 8, with errors."""
    base = np.array([window_means(s, args.skip, args.window) for s in segments_by_nc[NCS[0]].values()])
    s0, p0 = base[:, 0].mean(), base[:, 1].mean()
    sem = lambda x: float(np.std(x, ddof=1) / np.sqrt(len(x)))   # noqa: E731
    rows = {}
    for nc, segments in segments_by_nc.items():
        means = np.array([window_means(s, args.skip, args.window) for s in segments.values()])
        ds, dp = means[:, 0] - base[:, 0], means[:, 1] - base[:, 1]
        mu0 = s0 / p0
        dmu = (ds - mu0 * dp) / p0                 # the linearised change of mu = sigma_xy / P
        rows[nc] = {"eta_s": 1.0 + means[:, 0].mean() / ETA_F_GDOT, "P": float(means[:, 1].mean()),
                    "mu": float(means[:, 0].mean() / means[:, 1].mean()),
                    "d_eta": ds.mean() / s0, "d_eta_err": sem(ds) / s0, "d_P": dp.mean() / p0,
                    "d_P_err": sem(dp) / p0, "d_mu": dmu.mean() / mu0, "d_mu_err": sem(dmu) / mu0}
    return rows


def transient(segments_by_nc, args, bins=4):
    """The change of sigma_xy against the strain since the restart, in bins over the window."""
    edges = np.linspace(0.0, args.window, bins + 1)
    base = segments_by_nc[NCS[0]]
    lines = []
    for nc in NCS[1:]:
        cells = []
        for lo, hi in zip(edges[:-1], edges[1:]):
            d = [window_means(segments_by_nc[nc][g], lo, hi)[0] - window_means(base[g], lo, hi)[0] for g in base]
            s0 = np.mean([window_means(base[g], lo, hi)[0] for g in base])
            cells.append(f"{100 * np.mean(d) / s0:+.2f} ± {100 * np.std(d, ddof=1) / np.sqrt(len(d)) / s0:.2f} %"
                         f" ({lo:.2f}-{hi:.2f})")
        lines.append(f"- N_c {nc}, eta_s change against the strain since the restart: " + ", ".join(cells))
    return lines


def run_case(out, phi, mu_c, args):
    files, base = base_run(out, phi, mu_c, args)
    jobs = [(nc, g) for nc in reversed(NCS) for g in files]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        done = dict(zip(jobs, pool.map(lambda j: segment(out, phi, mu_c, j[0], j[1], files[j[1]], args), jobs)))
    segments_by_nc = {nc: {g: done[(nc, g)][0] for g in files} for nc in NCS}
    seconds = {nc: sum(done[(nc, g)][1] for g in files) for nc in NCS}
    rows = changes(segments_by_nc, args)
    for nc in NCS:
        rows[nc]["seconds"] = seconds[nc]
    notes = transient(segments_by_nc, args)
    first, worst = restart_check(base, segments_by_nc[NCS[0]], args)
    notes.append(f"- restart check: the N_c 8 runs repeat the base run to {first:.1e} of its mean |sigma_xy| at "
                 f"their first sample after the set-up and part from it by up to {worst:.1e} over the window (round-off, amplified by the flow and the solve's tolerance)")
    return rows, notes


def table(results, args):
    lines = ["# The sheared suspension over the time step, paired runs (bench/suspension_step_paired.py)", "",
             f"examples/suspension_shear as a user runs it (limit implicit, rotation yes, saturation 1e-3), {args.n} "
             f"spheres, St 1e-3, gdot t_c {args.gtc:g}. One run at N_c 8 shears one packing to strain {args.settle:g} "
             f"and on; from its state every {args.spacing:g} of strain ({args.segments} states) each N_c shears on "
             f"for {args.window:g}, averaged after the first {args.skip:g}. Changes from N_c 8: mean over the states "
             "of the paired differences, with their standard error; one rank.", "",
             "| phi | mu_c | N_c | eta_s | P [Pa] | mu | eta_s change | P change | mu change | loop s (all states) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    notes = []
    for (phi, mu_c), (rows, case_notes) in results.items():
        for nc in NCS:
            r = rows[nc]
            moves = ["" if nc == NCS[0] else f"{100 * r['d_' + k]:+.2f} ± {100 * r['d_' + k + '_err']:.2f} %"
                     for k in ("eta", "P", "mu")]
            lines.append(f"| {phi:.2f} | {mu_c:.1f} | {nc} | {r['eta_s']:.4g} | {r['P']:.4g} | {r['mu']:.4g} | "
                         + " | ".join(moves) + f" | {r['seconds']:.0f} |")
        notes += [f"phi {phi:.2f}, mu_c {mu_c:.1f}:"] + case_notes
    return "\n".join(lines + [""] + notes)


def write_csv(results, path):
    path.parent.mkdir(parents=True, exist_ok=True)
    keys = ["eta_s", "P", "mu", "d_eta", "d_eta_err", "d_P", "d_P_err", "d_mu", "d_mu_err", "seconds"]
    with open(path, "w", newline="") as f:
        f.write("# bench/suspension_step_paired.py: paired runs over N_c (see its docstring); d_*: relative change\n")
        writer = csv.DictWriter(f, fieldnames=["phi", "mu_c", "nc"] + keys, lineterminator="\n")
        writer.writeheader()
        for (phi, mu_c), (rows, _) in results.items():
            for nc, r in rows.items():
                writer.writerow({"phi": phi, "mu_c": mu_c, "nc": nc, **{k: f"{r[k]:.6g}" for k in keys}})


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=str(ROOT / "build" / "suspension_step_paired"))
    parser.add_argument("--cases", nargs="+", default=["0.56:0.5"], help="phi:mu_c pairs")
    parser.add_argument("--n", type=int, default=300)
    parser.add_argument("--gtc", type=float, default=2.5e-4, help="gdot t_c of the contacts (the example's)")
    parser.add_argument("--settle", type=float, default=1.0, help="strain of the base run before the first state")
    parser.add_argument("--segments", type=int, default=20)
    parser.add_argument("--spacing", type=float, default=0.1, help="strain between the states")
    parser.add_argument("--window", type=float, default=0.2, help="strain of each paired run")
    parser.add_argument("--skip", type=float, default=0.05, help="strain left out of each run's mean")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--reuse", action="store_true")
    parser.add_argument("--results", default=str(bench_common.RESULTS))
    parser.add_argument("--section", default="suspension-step-paired")
    parser.add_argument("--csv", default=str(CSV), help="the table as CSV ('none' to skip)")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    os.nice(5)
    results = {}
    for case in args.cases:
        phi, mu_c = (float(v) for v in case.split(":"))
        results[(phi, mu_c)] = run_case(out, phi, mu_c, args)
    if args.csv != "none":
        write_csv(results, pathlib.Path(args.csv))
    text = table(results, args)
    print(text)
    if args.results != "none":
        bench_common.write_section(pathlib.Path(args.results), args.section, text)


if __name__ == "__main__":
    main()

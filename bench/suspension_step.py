"""The sheared suspension of examples/suspension_shear as a user runs it (limit implicit, the
fluid's torque on the spins, default saturation), over the time step: eta_s, the particle
pressure P and mu at N_c 8, 16 and 32 from one packing per solid fraction, and how much each
changes when dt is halved once and twice from N_c 8 (issue 45 asks for less than 5 %).

    .venv/bin/python bench/suspension_step.py [--out build/suspension_step] [--n 300] [--rollfilm]
        [--strain 2] [--average 1.5] [--jobs 2] [--reuse]

Cases: solid fractions 0.50, 0.54, 0.56 with friction 0.5 and 0. Each packing is compressed
and relaxed once (-var packing 1) and every N_c shears that data file (-var packing 2) to
--strain; the stress is averaged over the last --average in blocks of 0.25 of strain, whose
spread gives the statistical error of each run (standard error of the block means; mu's by the
linearised ratio). A change is quoted with its error, the two runs' errors combined: the runs
shear the same packing but their trajectories part within a fraction of a strain unit, so they
are statistically independent over the averaged strain. Writes bench/data/suspension_step.csv
and the section suspension-step of bench/RESULTS.md (--results none to skip).
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

SCRIPT = ROOT / "examples" / "suspension_shear" / "in.suspension_shear"
CSV = ROOT / "bench" / "data" / "suspension_step.csv"
CASES = [(0.50, 0.5), (0.54, 0.5), (0.56, 0.5), (0.50, 0.0), (0.54, 0.0), (0.56, 0.0)]
NCS = [8, 16, 32]
BLOCK = 0.25                                    # strain per block of the averages
ETA_F_GDOT = 1000 * 1.0 * 1e-4 ** 2 / 1e-3      # eta_f gdot [Pa] of the input at St 1e-3
SAMPLES_PER_STRAIN = 2000


def packing(out, phi, args):
    path = (out / "packings" / f"phi{phi:.2f}.data").resolve()
    if not path.exists():
        variables = {"n": args.n, "phi": phi, "nc": 8, "gtc": args.gtc, "strain": 0.002, "average": 0.001, "packing": 1,
                     "packing_file": path.name, "thermo": 100000}
        lammps_run.run(SCRIPT.read_text(), path.parent, variables, name=f"phi{phi:.2f}.in")
    return path


def shear(out, phi, mu_c, nc, args):
    """One run from the packing of phi; returns (series of strain, sigma_xy, P; loop seconds)."""
    work = out / "runs" / f"phi{phi:.2f}_mu{mu_c:.1f}_nc{nc}"
    log_path = work / "in.suspension_shear.log"
    if not (args.reuse and log_path.exists() and "RESULT mu" in log_path.read_text()):
        steps_per_strain = nc / args.gtc
        variables = {"n": args.n, "phi": phi, "mu_c": mu_c, "nc": nc, "gtc": args.gtc, "strain": args.strain,
                     "average": args.average, "packing": 2, "packing_file": packing(out, phi, args),
                     "series": max(1, round(steps_per_strain / SAMPLES_PER_STRAIN)), "thermo": 1000000,
                     "rollfilm": "yes" if args.rollfilm else "no"}
        lammps_run.run(SCRIPT.read_text(), work, variables, name="in.suspension_shear", timeout=6 * 3600)
    seconds = bench_common.parse_log(log_path.read_text())["seconds"]
    return np.loadtxt(work / "suspension_series.txt", comments="#")[:, 1:4], seconds


def summarise(series, args):
    """Means and standard errors of eta_s, P and mu over the blocks of the averaged strain."""
    strain, sxy, pressure = series.T
    edges = np.arange(args.strain - args.average, args.strain + 1e-9, BLOCK)
    means = np.array([(sxy[m].mean(), pressure[m].mean())
                      for m in ((strain > lo + 1e-12) & (strain <= hi + 1e-12) for lo, hi in zip(edges[:-1], edges[1:]))])
    count = len(means)
    error = lambda x: float(np.std(x, ddof=1) / np.sqrt(count))    # noqa: E731
    s, p = means[:, 0], means[:, 1]
    mu = s.mean() / p.mean()
    return {"eta_s": 1.0 + s.mean() / ETA_F_GDOT, "eta_s_err": error(s) / ETA_F_GDOT, "P": float(p.mean()),
            "P_err": error(p), "mu": float(mu), "mu_err": error((s - mu * p) / p.mean())}


def change(a, b, key):
    """Relative change from a to b and its error."""
    ratio = b[key] / a[key]
    err = ratio * np.hypot(a[key + "_err"] / a[key], b[key + "_err"] / b[key])
    return ratio - 1.0, err


def table(rows, args):
    lines = ["# The sheared suspension over the time step (bench/suspension_step.py)", "",
             f"examples/suspension_shear as a user runs it (limit implicit, rotation yes, saturation 1e-3"
             f"{', rollfilm yes' if args.rollfilm else ''}), "
             f"{args.n} spheres, St 1e-3, gdot t_c {args.gtc:g}, one packing per phi, strain {args.strain:g} averaged over "
             f"its last {args.average:g} in blocks of {BLOCK:g}; one rank. Changes from N_c 8, with the combined "
             "statistical error.", "",
             "| phi | mu_c | N_c | eta_s | P [Pa] | mu | eta_s change | P change | mu change | loop s |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for (phi, mu_c), by_nc in rows.items():
        base = by_nc[NCS[0]]
        for nc in NCS:
            r = by_nc[nc]
            cells = [f"{r[k]:.4g} ± {r[k + '_err']:.2g}" for k in ("eta_s", "P", "mu")]
            moves = ["" if nc == NCS[0] else "{:+.1f} ± {:.1f} %".format(*(100 * x for x in change(base, r, k)))
                     for k in ("eta_s", "P", "mu")]
            lines.append(f"| {phi:.2f} | {mu_c:.1f} | {nc} | " + " | ".join(cells + moves) + f" | {r['seconds']:.0f} |")
    return "\n".join(lines)


def write_csv(rows, path=CSV):
    path.parent.mkdir(parents=True, exist_ok=True)
    keys = ["phi", "mu_c", "nc", "eta_s", "eta_s_err", "P", "P_err", "mu", "mu_err", "seconds"]
    with open(path, "w", newline="") as f:
        f.write("# bench/suspension_step.py: examples/suspension_shear over N_c (see its docstring)\n")
        writer = csv.DictWriter(f, fieldnames=keys, lineterminator="\n")
        writer.writeheader()
        for (phi, mu_c), by_nc in rows.items():
            for nc, r in by_nc.items():
                writer.writerow({"phi": phi, "mu_c": mu_c, "nc": nc,
                                 **{k: f"{r[k]:.6g}" for k in keys[3:]}})


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=str(ROOT / "build" / "suspension_step"))
    parser.add_argument("--n", type=int, default=300)
    parser.add_argument("--strain", type=float, default=2.0)
    parser.add_argument("--average", type=float, default=1.5)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--reuse", action="store_true")
    parser.add_argument("--results", default=str(bench_common.RESULTS))
    parser.add_argument("--gtc", type=float, default=1e-3, help="gdot t_c of the contacts (the example's: 2.5e-4)")
    parser.add_argument("--cases", nargs="+", default=None, help="phi:mu_c pairs (default: the six)")
    parser.add_argument("--section", default="suspension-step", help="section of --results")
    parser.add_argument("--csv", default=str(CSV), help="the table as CSV ('none' to skip)")
    parser.add_argument("--rollfilm", action="store_true", help="the films' rolling term on (pair_coeff rollfilm yes)")
    args = parser.parse_args()
    cases = [tuple(float(v) for v in c.split(":")) for c in args.cases] if args.cases else CASES
    out = pathlib.Path(args.out)
    os.nice(5)
    for phi in sorted({phi for phi, _ in cases}):
        packing(out, phi, args)
    jobs = [(phi, mu_c, nc) for nc in reversed(NCS) for phi, mu_c in cases]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        done = dict(zip(jobs, pool.map(lambda job: shear(out, *job, args), jobs)))
    rows = {}
    for phi, mu_c in cases:
        rows[(phi, mu_c)] = {}
        for nc in NCS:
            series, seconds = done[(phi, mu_c, nc)]
            rows[(phi, mu_c)][nc] = {**summarise(series, args), "seconds": seconds}
    if args.csv != "none":
        write_csv(rows, pathlib.Path(args.csv))
    text = table(rows, args)
    print(text)
    if args.results != "none":
        bench_common.write_section(pathlib.Path(args.results), args.section, text)


if __name__ == "__main__":
    main()

"""The sheared dense suspension of issue 45 against a reference that resolves every film, and
its convergence in the time step, for the film budget (limit atom) and the coupled solve
(limit implicit).

    .venv/bin/python bench/suspension_convergence.py [--out build/suspension_convergence]
        [--jobs 4] [--reuse] [--no-reference]

The system: examples/suspension_shear/in.suspension_shear with 64 bidisperse spheres (radii a
and 1.4 a, equal volumes), St = 1e-3, gdot t_c = 1e-3, activation 0.1, no torque on the spins
(rotation no: the reference was made before the example turned it on) and saturation 1e-2 (a
film ten times weaker near contact than the default 1e-3, so that a step that resolves every
film is affordable: with 1e-3 the budget binds until N_c is about ten times larger still).
Solid fractions 0.50, 0.54, 0.56, friction 0 and 0.5, two packings (seeds) each. Every run of
one packing starts from the same compressed, relaxed data file and shears to a strain of 1; the
stress is averaged over the last 0.7 in blocks of 0.1 of strain (7 per run, 14 per case), whose
spread gives the statistical error (standard error of the block means).

- The reference: N_c = 4096 (dt = t_c / 4096) with `limit implicit`, which takes the
  step-exact per-pair film of `limit atom`, bit for bit, wherever no sphere's budget load
  exceeds 1, and reports the films it had to solve (compute pair, c_solve[4]): the runs
  record the fraction of samples with any film solved, which must be about 0.
- The convergence runs: `limit implicit` at N_c 1, 2, 4, 8, 16, 32 and `limit atom` at N_c 4,
  8, 16, 32.

Writes tests/data/suspension_reference.csv (the reference, per case: eta_s, P, mu with their
errors, the wall time), bench/data/suspension_convergence.csv (every scheme and N_c, per case,
with the deviation from the reference) and the section `suspension-convergence` of
bench/RESULTS.md. bench/suspension_report.py draws the figure of `make report` from the CSVs.
Runs go to --out; the logs are kept there (in.suspension_shear.log per run). --reuse takes a
run whose log is complete instead of running it again; --no-reference reads the reference from
tests/data instead of running it (hours of CPU on one core).
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
REFERENCE_CSV = ROOT / "tests" / "data" / "suspension_reference.csv"
CONVERGENCE_CSV = ROOT / "bench" / "data" / "suspension_convergence.csv"
CASES = [(0.50, 0.5), (0.54, 0.5), (0.56, 0.5), (0.50, 0.0), (0.54, 0.0), (0.56, 0.0)]
SEEDS = [4928, 7331]
COMMON = {"n": 64, "St": 1e-3, "gtc": 1e-3, "saturation": 1e-2, "strain": 1.0, "average": 0.7,
          "thermo": 400000, "rotation": "no"}
BLOCK = 0.1                  # strain per block of the averages
REFERENCE_NC = 4096
SAMPLES_PER_STRAIN = 8000    # the series' samples (every max(1, steps per strain / this) steps)
# N_c of each scheme: the coupled solve from 1 (its films stabilise the contact network,
# doc/film_solve.rst), the budget from 4 (below, the network check stops it).
NCS = {"implicit": [1, 2, 4, 8, 16, 32], "atom": [4, 8, 16, 32]}
ETA_F_GDOT = 1000 * 1.0 * 1e-4 ** 2 / 1e-3    # eta_f gdot [Pa] of the input at St 1e-3
COLUMNS = ["phi", "mu_c", "limit", "nc", "eta_s", "eta_s_err", "P", "P_err", "mu", "mu_err",
           "solved_fraction", "seconds", "runs"]


def run_dir(out, phi, mu_c, seed, limit, nc):
    return out / "runs" / f"phi{phi:.2f}_mu{mu_c:.1f}_seed{seed}_{limit}_nc{nc}"


def packing(out, phi, seed):
    """The compressed, relaxed packing of (phi, seed): made once at N_c 16, dry."""
    path = (out / "packings" / f"phi{phi:.2f}_seed{seed}.data").resolve()
    if not path.exists():
        variables = {**COMMON, "phi": phi, "seed": seed, "nc": 16, "strain": 0.002, "average": 0.001,
                     "packing": 1, "packing_file": path.name}
        lammps_run.run(SCRIPT.read_text(), path.parent, variables, name=f"phi{phi:.2f}_seed{seed}.in")
    return path


def shear(out, phi, mu_c, seed, limit, nc, reuse):
    """One run; returns its series (strain, sigma_xy, P, films solved) and loop seconds."""
    work = run_dir(out, phi, mu_c, seed, limit, nc)
    log_path = work / "in.suspension_shear.log"
    if not (reuse and log_path.exists() and "RESULT mu" in log_path.read_text()):
        steps_per_strain = nc / COMMON["gtc"]
        variables = {**COMMON, "phi": phi, "mu_c": mu_c, "seed": seed, "limit": limit, "nc": nc,
                     "packing": 2, "packing_file": packing(out, phi, seed),
                     "series": max(1, round(steps_per_strain / SAMPLES_PER_STRAIN))}
        lammps_run.run(SCRIPT.read_text(), work, variables, name="in.suspension_shear", timeout=6 * 3600)
    seconds = bench_common.parse_log(log_path.read_text())["seconds"]
    series = np.loadtxt(work / "suspension_series.txt", comments="#")[:, 1:]
    return series, seconds


def blocks(series):
    """Block means of sigma_xy and P over the averaged strain, and the films-solved fraction."""
    strain, sxy, pressure, solved = series.T
    start = COMMON["strain"] - COMMON["average"]
    edges = start + BLOCK * np.arange(round(COMMON["average"] / BLOCK) + 1)
    rows = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        inside = (strain > lo + 1e-12) & (strain <= hi + 1e-12)
        rows.append((sxy[inside].mean(), pressure[inside].mean()))
    return np.array(rows), float(np.mean(solved > 0))


def summarise(phi, mu_c, limit, nc, results):
    """Pooled blocks of every seed: means and standard errors of eta_s, P and mu."""
    pooled = np.concatenate([blocks(series)[0] for series, _ in results])
    solved = np.mean([blocks(series)[1] for series, _ in results])
    count = len(pooled)
    sxy, pressure = pooled[:, 0], pooled[:, 1]
    mu = sxy.mean() / pressure.mean()
    # mu's error by the linearised ratio of the block means
    mu_blocks = (sxy - mu * pressure) / pressure.mean()
    error = lambda x: float(np.std(x, ddof=1) / np.sqrt(count))    # noqa: E731
    return {"phi": phi, "mu_c": mu_c, "limit": limit, "nc": nc,
            "eta_s": 1.0 + sxy.mean() / ETA_F_GDOT, "eta_s_err": error(sxy) / ETA_F_GDOT,
            "P": float(pressure.mean()), "P_err": error(pressure), "mu": float(mu),
            "mu_err": error(mu_blocks), "solved_fraction": float(solved),
            "seconds": float(sum(s for _, s in results)), "runs": len(results)}


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    for row in rows:
        for key in COLUMNS:
            if key != "limit":
                row[key] = float(row[key])
    return rows


def write_csv(path, rows, header):
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        f.write("".join(f"# {line}\n" for line in header.strip().splitlines()))
        extra = ["eta_s_dev", "P_dev", "mu_dev"] if "eta_s_dev" in rows[0] else []
        writer = csv.DictWriter(f, fieldnames=COLUMNS + extra, lineterminator="\n")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in row.items()})


REFERENCE_HEADER = f"""The reference of the sheared suspension (bench/suspension_convergence.py): every film resolved.
examples/suspension_shear/in.suspension_shear, n 64, St 1e-3, gdot t_c 1e-3, activation 0.1,
rotation no, saturation 1e-2, N_c {REFERENCE_NC} (dt = t_c / {REFERENCE_NC}) with limit implicit, which is limit atom
bit for bit where no sphere's budget load exceeds 1 (solved_fraction: the fraction of samples
with any film solved). Seeds {' '.join(map(str, SEEDS))} (one packing each, made at N_c 16), strain 1,
the stress averaged over the last 0.7 in blocks of 0.1 of strain, pooled over the seeds; *_err
are standard errors of the block means (mu's by the linearised ratio). seconds: LAMMPS loop time
of all seeds, summed (one core of a shared machine, runs four at a time)."""


def table(reference, rows):
    """Markdown of the reference and of every scheme's deviation from it."""
    lines = ["# The sheared suspension: reference and convergence in the time step", "",
             f"64 bidisperse spheres, St 1e-3, gdot t_c 1e-3, saturation 1e-2, seeds {SEEDS}, strain 1",
             "averaged over its last 0.7 (bench/suspension_convergence.py). Reference: every film",
             f"resolved, N_c {REFERENCE_NC}. Deviations in units of the combined statistical error in brackets.",
             "", "| phi | mu_c | scheme | N_c | eta_s | P [Pa] | mu | films solved (share of samples) | loop s |",
             "|---|---|---|---|---|---|---|---|---|"]
    ref = {(r["phi"], r["mu_c"]): r for r in reference}
    for r in reference + rows:
        base = ref[(r["phi"], r["mu_c"])]
        cells = []
        for key in ("eta_s", "P", "mu"):
            text = f"{r[key]:.4g} ± {r[key + '_err']:.2g}"
            if r is not base:
                sigma = np.hypot(r[key + "_err"], base[key + "_err"])
                text += f" ({100 * (r[key] / base[key] - 1):+.0f} %, {(r[key] - base[key]) / sigma:+.1f})"
            cells.append(text)
        name = "reference" if r is base else r["limit"]
        lines.append(f"| {r['phi']:.2f} | {r['mu_c']:.1f} | {name} | {int(r['nc'])} | " + " | ".join(cells) +
                     f" | {r['solved_fraction']:.2f} | {r['seconds']:.0f} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=str(ROOT / "build" / "suspension_convergence"))
    parser.add_argument("--jobs", type=int, default=4)
    parser.add_argument("--reuse", action="store_true")
    parser.add_argument("--no-reference", action="store_true")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    os.nice(5)
    for phi in sorted({phi for phi, _ in CASES}):
        for seed in SEEDS:
            packing(out, phi, seed)
    schemes = [(limit, nc) for limit in ("implicit", "atom") for nc in NCS[limit]]
    if not args.no_reference:
        schemes = [("implicit", REFERENCE_NC)] + schemes
    jobs = [(phi, mu_c, seed, limit, nc) for limit, nc in schemes for phi, mu_c in CASES for seed in SEEDS]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        done = dict(zip(jobs, pool.map(lambda job: shear(out, *job, args.reuse), jobs)))
    summary = {(limit, nc, phi, mu_c): summarise(phi, mu_c, limit, nc,
                                                 [done[(phi, mu_c, s, limit, nc)] for s in SEEDS])
               for limit, nc in schemes for phi, mu_c in CASES}
    if args.no_reference:
        reference = read_csv(REFERENCE_CSV)
    else:
        reference = [summary[("implicit", REFERENCE_NC, phi, mu_c)] for phi, mu_c in CASES]
        write_csv(REFERENCE_CSV, reference, REFERENCE_HEADER)
    ref = {(r["phi"], r["mu_c"]): r for r in reference}
    rows = []
    for limit, nc in schemes:
        for phi, mu_c in CASES:
            if nc == REFERENCE_NC:
                continue
            row = summary[(limit, nc, phi, mu_c)]
            for key in ("eta_s", "P", "mu"):
                row[key + "_dev"] = row[key] / ref[(phi, mu_c)][key] - 1.0
            rows.append(row)
    write_csv(CONVERGENCE_CSV, rows, "The sheared suspension at N_c 1-32 (bench/suspension_convergence.py;\n"
              "the system and columns as in tests/data/suspension_reference.csv); *_dev: relative\n"
              "deviation from that reference.")
    report = table(reference, rows)
    print(report)
    bench_common.write_section(bench_common.RESULTS, "suspension-convergence", report)


if __name__ == "__main__":
    main()

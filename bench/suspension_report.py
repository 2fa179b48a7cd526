"""The many-body counterpart of the restitution figure of `make report`: the sheared
suspension's error against the resolved reference, against run time, per scheme.

    .venv/bin/python bench/suspension_report.py [--out build/report]

Reads the stored data of bench/suspension_convergence.py (tests/data/suspension_reference.csv,
bench/data/suspension_convergence.csv; no runs) and writes suspension_convergence.png and the
table suspension_convergence.md to --out:
for the film budget (limit atom) and the coupled solve (limit implicit), one line each over
N_c = 1 (the solve) or 4 (the budget) to 32, the root-mean-square over the solid fractions and frictions of the relative
deviation of eta_s (left) and of the particle pressure P (right) from the reference, against
the LAMMPS loop time per run (one strain unit of 64 spheres). The grey band is the reference's
own statistical error (its standard error, root-mean-square over the cases): deviations inside
it are not resolved by the data.
"""
import argparse
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "bench"))
import suspension_convergence as convergence  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCHEMES = {"atom": ("film budget (limit atom)", "C3", "s"),
           "implicit": ("coupled solve (limit implicit)", "C0", "o")}


def rms(values):
    return float(np.sqrt(np.mean(np.square(values))))


def curves(rows, key):
    """Per scheme: (N_c, seconds per run, rms relative deviation of key) sorted by N_c."""
    out = {}
    for limit in SCHEMES:
        points = []
        for nc in sorted({r["nc"] for r in rows if r["limit"] == limit}):
            sel = [r for r in rows if r["limit"] == limit and r["nc"] == nc]
            seconds = np.mean([r["seconds"] / r["runs"] for r in sel])
            points.append((int(nc), seconds, rms([r[key + "_dev"] for r in sel])))
        out[limit] = points
    return out


def plot(reference, rows, path):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
    ref_seconds = np.mean([r["seconds"] / r["runs"] for r in reference])
    for ax, key, label in ((axes[0], "eta_s", "eta_s"), (axes[1], "P", "particle pressure P")):
        band = rms([r[key + "_err"] / r[key] for r in reference])
        ax.axhspan(1e-3, band, color="0.85", label=f"reference's statistical error ({100 * band:.0f} %)")
        for limit, points in curves(rows, key).items():
            name, colour, marker = SCHEMES[limit]
            nc, seconds, error = zip(*points)
            ax.loglog(seconds, np.maximum(error, 1e-3), marker + "-", color=colour, label=name)
            for n, x, y in points:
                ax.annotate(f"N_c {n}", (x, max(y, 1e-3)), textcoords="offset points", xytext=(4, 4),
                            fontsize=8, color=colour)
        ax.axvline(ref_seconds, color="k", ls=":", lw=0.8)
        ax.annotate(f"reference\nN_c {convergence.REFERENCE_NC}", (ref_seconds, 0.5), xytext=(-60, 0),
                    textcoords="offset points", fontsize=8)
        ax.set_ylim(1e-3, 2.0)
        ax.set_xlabel("LAMMPS loop time per run [s] (1 strain unit, 64 spheres, one core)")
        ax.set_ylabel(f"rms relative deviation of {label} from the reference")
        ax.set_title(f"{label}: error against run time")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="center right")
    fig.suptitle("Sheared suspension, St 1e-3, phi 0.50-0.56, mu_c 0 and 0.5, saturation 1e-2 "
                 "(bench/suspension_convergence.py)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default=str(ROOT / "build" / "report"))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    reference = convergence.read_csv(convergence.REFERENCE_CSV)
    rows = convergence.read_csv(convergence.CONVERGENCE_CSV)
    for row in rows:
        for key in ("eta_s", "P", "mu"):
            row[key + "_dev"] = float(row[key + "_dev"])
    plot(reference, rows, out / "suspension_convergence.png")
    (out / "suspension_convergence.md").write_text(convergence.table(reference, rows) + "\n")
    for key in ("eta_s", "P"):
        for limit, points in curves(rows, key).items():
            print(f"{key} {limit}: " + ", ".join(f"N_c {n}: {s:.1f} s, {100 * e:.1f} %" for n, s, e in points))
    print(f"wrote {out / 'suspension_convergence.png'}")


if __name__ == "__main__":
    main()

"""Runs examples/rotating_drum/in.rotating_drum dry and wet (in water) and plots the beds at the
end of the run and the dynamic angle of repose against time (rotating_drum.png).

    .venv/bin/python examples/rotating_drum/run_rotating_drum.py [--steps 40000] [--out DIR]

The angle: the bed is a circular segment whose free surface is perpendicular to the line from
the drum's axis to its centre of mass, theta = atan(|x_cm| / |y_cm|); the printed value is its
time average over the second half of the run.
"""
import argparse
import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import lammps_run  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

D = 2.0e-3
R_DRUM = 10 * D


def last_snapshot(path):
    """(x, y, radius) of every atom in the last snapshot of a custom dump (id x y z radius)."""
    lines = path.read_text().splitlines()
    start = max(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    return [tuple(float(w) for w in (line.split()[1], line.split()[2], line.split()[4])) for line in lines[start + 1:]]


def series(path, dt):
    """Time and angle from the fix ave/time file."""
    rows = [line.split() for line in path.read_text().splitlines() if line and not line.startswith("#")]
    return [int(r[0]) * dt for r in rows], [float(r[1]) for r in rows]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--steps", type=int, default=40000)
    parser.add_argument("--out", default=str(ROOT / "build" / "rotating_drum"))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    script = (ROOT / "examples" / "rotating_drum" / "in.rotating_drum").read_text()
    dt = 1.0e-3 / 8
    fig, axes = plt.subplots(1, 3, figsize=(12, 4))
    results = {}
    for column, (wet, label) in enumerate(((0, "dry"), (1, "wet (water)"))):
        run_dir = out / ("wet" if wet else "dry")
        result, _ = lammps_run.run(script, run_dir, {"wet": wet, "steps": args.steps}, name="in.rotating_drum",
                                   timeout=3600)
        results[label] = result
        ax = axes[column]
        atoms = last_snapshot(run_dir / "dump.rotating_drum")
        ax.add_collection(PatchCollection([Circle((x / D, y / D), r / D) for x, y, r in atoms],
                                          facecolor="tab:blue" if not wet else "tab:cyan", edgecolor="k", lw=0.3))
        ax.add_patch(Circle((0, 0), R_DRUM / D, fill=False, lw=1.5))
        # The mean surface: slope -tan(theta), at the height of the top spheres along its normal.
        theta = math.radians(result["theta"])
        normal = (math.sin(theta), math.cos(theta))
        heights = sorted((x * normal[0] + y * normal[1] + r) / D for x, y, r in atoms)
        level = heights[int(0.97 * (len(heights) - 1))]
        half = math.sqrt(max((R_DRUM / D) ** 2 - level**2, 0.0))
        ends = [(level * normal[0] + t * normal[1], level * normal[1] - t * normal[0]) for t in (-half, half)]
        ax.plot([e[0] for e in ends], [e[1] for e in ends], "r--", lw=1,
                label=f"mean theta = {result['theta']:.1f} deg")
        ax.set_aspect("equal")
        ax.set_xlim(-10.5, 10.5)
        ax.set_ylim(-10.5, 10.5)
        ax.set_title(f"{label}: {int(result['atoms'])} spheres, Fr = 0.01", fontsize=9)
        ax.set_xlabel("x / d")
        ax.legend(fontsize=7, loc="upper right")
        t, angle = series(run_dir / "theta.dat", dt)
        axes[2].plot(t, angle, lw=0.8, label=f"{label}: {result['theta']:.1f} deg")
    axes[0].set_ylabel("y / d")
    axes[2].axvspan(args.steps * dt / 2, args.steps * dt, color="0.9", label="averaged")
    axes[2].set_xlabel("time (s)")
    axes[2].set_ylabel("dynamic angle of repose (deg)")
    axes[2].legend(fontsize=7)
    axes[2].grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "rotating_drum.png", dpi=110)
    for label, result in results.items():
        print(f"{label}: dynamic angle of repose {result['theta']:.1f} deg, Omega = {result['omega']:.3g} rad/s")
    print(f"plot: {out / 'rotating_drum.png'}")


if __name__ == "__main__":
    main()

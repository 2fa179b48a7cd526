"""Runs examples/fluidized_bed/in.fluidized_bed on 2 MPI ranks and plots the time-averaged
solid-fraction profile against height (profile.png), with Richardson-Zaki's value.

    .venv/bin/python examples/fluidized_bed/run_fluidized_bed.py [--nprocs 2] [--scale 1]
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


def read_profile(path, d, area):
    """Last block of fix ave/chunk: z (bin centre) and solid fraction n V_p / V_bin."""
    blocks, current = [], None
    for line in path.read_text().splitlines():
        if line.startswith("#"):
            continue
        words = line.split()
        if len(words) == 3:
            current = []
            blocks.append(current)
        elif len(words) == 4 and current is not None:
            z, density = float(words[1]), float(words[3])
            current.append((z, density * math.pi / 6 * d ** 3))
    return blocks[-1]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--nprocs", type=int, default=2)
    parser.add_argument("--scale", type=float, default=1.0)
    parser.add_argument("--steps", type=int, default=100000)
    parser.add_argument("--out", default=str(ROOT / "build" / "fluidized_bed"))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    script = (ROOT / "examples" / "fluidized_bed" / "in.fluidized_bed").read_text()
    result, log = lammps_run.run(script, out, {"scale": args.scale, "steps": args.steps},
                                 nprocs=args.nprocs, name="in.fluidized_bed", timeout=3600)
    d = 1.0e-3
    profile = read_profile(out / "profile.dat", d, None)
    rz = 1 - 0.354 ** (1 / 4.65)
    fig, ax = plt.subplots(figsize=(4.5, 5))
    ax.plot([phi for _, phi in profile], [z / d for z, _ in profile], "o-", ms=3, label="LAMMPS + plugin")
    ax.axvline(rz, color="k", ls="--", lw=1, label=f"Richardson-Zaki, phi = {rz:.2f}")
    ax.set_xlabel("solid fraction")
    ax.set_ylabel("height z / d")
    ax.set_title(f"Fluidised bed, {int(result['atoms'])} spheres, U = 0.354 u_t", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out / "profile.png", dpi=120)
    base = [phi for z, phi in profile if 4 * d <= z <= 12 * d]
    print(f"{int(result['atoms'])} spheres on {args.nprocs} ranks; mean solid fraction near the base "
          f"(4-12 d): {sum(base) / len(base):.3f} (Richardson-Zaki {rz:.3f})")
    print(f"wrote {out / 'profile.png'}, {out / 'profile.dat'} and dumps {out}/dump.fluidized_bed.*")


if __name__ == "__main__":
    main()

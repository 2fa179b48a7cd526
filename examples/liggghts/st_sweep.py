"""The wet-restitution study in LIGGGHTS: e/e_d against St for a sphere bouncing on a wall,
computed by LIGGGHTS 3.8.0 runs of examples/liggghts/in.wall_bounce (model lubricated), with
Legendre's law exp(-35/St) drawn over it. Writes st_sweep.csv and st_sweep.png to --out."""
import argparse
import csv
import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import liggghts_run  # noqa: E402

STOKES = [5, 10, 20, 30, 50, 100, 200, 500, 1000, 2000]
E_DRY = 0.9


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default=str(ROOT / "build" / "liggghts-demo"))
    parser.add_argument("--np", type=int, default=1, help="MPI ranks (Open MPI)")
    args = parser.parse_args()
    missing = liggghts_run.available()
    if missing:
        sys.exit(f"st_sweep: {missing}")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    script = (ROOT / "examples" / "liggghts" / "in.wall_bounce").read_text()
    rows = []
    for st in STOKES:
        result, _ = liggghts_run.run(script, out / "runs", nprocs=args.np, name="in.wall_bounce",
                                     variables={"St": st, "e_d": E_DRY})
        ratio = max(result["e"], 0.0) / E_DRY
        legendre = math.exp(-35.0 / st)
        rows.append({"St": st, "e": result["e"], "e_over_ed": ratio, "legendre": legendre,
                     "difference": ratio - legendre})
        print(f"St = {st:6g}   e/e_d = {ratio:.4f}   exp(-35/St) = {legendre:.4f}")
    with open(out / "st_sweep.csv", "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    st_line = [10 ** (k / 50) for k in range(25, 176)]
    ax.semilogx(st_line, [math.exp(-35 / s) for s in st_line], "k-", label="exp(-35/St)")
    ax.semilogx([r["St"] for r in rows], [r["e_over_ed"] for r in rows], "s", color="tab:blue",
                label=f"LIGGGHTS model lubricated (e_d = {E_DRY}, N_c = 8)")
    ax.set_xlabel("Stokes number St = (2/9) rho_p R U / mu_f")
    ax.set_ylabel("e / e_d")
    ax.set_ylim(-0.05, 1.05)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "st_sweep.png", dpi=120)
    print(f"wrote {out / 'st_sweep.csv'} and {out / 'st_sweep.png'}")


if __name__ == "__main__":
    main()

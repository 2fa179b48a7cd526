"""The wet-restitution study in LIGGGHTS: e/e_d against St for a sphere bouncing on a wall,
computed by LIGGGHTS 3.8.0 runs of examples/liggghts/in.wall_bounce (model lubricated), with
Legendre's law exp(-35/St) drawn over it. Writes st_sweep.csv and st_sweep.png to --out."""
import argparse
import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import liggghts_run  # noqa: E402
import st_sweep_output  # noqa: E402

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
    st_sweep_output.write_csv(out / "st_sweep.csv", rows)
    st_sweep_output.plot(out / "st_sweep.png", rows,
                         f"LIGGGHTS model lubricated (e_d = {E_DRY}, N_c = 8)", "s", "tab:blue")
    print(f"wrote {out / 'st_sweep.csv'} and {out / 'st_sweep.png'}")


if __name__ == "__main__":
    main()

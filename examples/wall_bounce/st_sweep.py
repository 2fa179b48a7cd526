"""The wet-restitution study: e/e_d against St for a sphere bouncing on a wall, computed by
LAMMPS runs of examples/wall_bounce/in.wall_bounce, with Legendre's law exp(-35/St) drawn
over it. Writes st_sweep.csv and st_sweep.png to --out."""
import argparse
import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import lammps_run  # noqa: E402
import st_sweep_output  # noqa: E402

STOKES = [5, 10, 15, 20, 30, 50, 75, 100, 150, 200, 300, 500, 750, 1000, 2000]
E_DRY = 0.9


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default=str(ROOT / "build" / "demo"))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    script = (ROOT / "examples" / "wall_bounce" / "in.wall_bounce").read_text()

    rows = []
    for st in STOKES:
        result, _ = lammps_run.run(script, out / "runs", {"St": st, "e_d": E_DRY},
                                   name="in.wall_bounce",
                                   env={"LAMMPS_PLUGIN_PATH": str(lammps_run.PLUGIN.parent)})
        ratio = max(result["e"], 0.0) / E_DRY
        legendre = math.exp(-35.0 / st)
        mu_f = 2.0 / 9.0 * 8000 * 1.0e-3 * 0.1 / st    # as in in.wall_bounce
        rows.append({"St": st, "mu_f": mu_f, "e": result["e"], "e_over_ed": ratio,
                     "legendre": legendre, "difference": ratio - legendre})
        print(f"St = {st:6g}   e/e_d = {ratio:.4f}   exp(-35/St) = {legendre:.4f}   "
              f"difference = {ratio - legendre:+.4f}")

    st_sweep_output.write_csv(out / "st_sweep.csv", rows)
    st_sweep_output.plot(out / "st_sweep.png", rows,
                         f"LAMMPS + lubricated plugin (e_d = {E_DRY}, N_c = 8)")
    worst = max(abs(r["difference"]) for r in rows if 50 <= r["St"] <= 1000)
    print(f"wrote {out / 'st_sweep.csv'} and {out / 'st_sweep.png'}")
    print(f"largest |e/e_d - exp(-35/St)| for 50 <= St <= 1000: {worst:.3f}")


if __name__ == "__main__":
    main()

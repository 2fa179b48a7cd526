"""The wet-restitution study: e/e_d against St for a sphere bouncing on a wall, computed by
LAMMPS runs of examples/wall_bounce/in.wall_bounce, with Legendre's law exp(-35/St) drawn
over it: the paper's film as printed, and the same film with the contact calibrated to the
law (keyword legendre 35). Writes st_sweep.csv and st_sweep.png to --out."""
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

    def bounce(st, legendre_constant):
        result, _ = lammps_run.run(script, out / "runs",
                                   {"St": st, "e_d": E_DRY, "legendre": legendre_constant},
                                   name="in.wall_bounce",
                                   env={"LAMMPS_PLUGIN_PATH": str(lammps_run.PLUGIN.parent)})
        return result["e"], max(result["e"], 0.0) / E_DRY

    rows = []
    for st in STOKES:
        e, ratio = bounce(st, 0)
        _, calibrated = bounce(st, 35)
        legendre = math.exp(-35.0 / st)
        mu_f = 2.0 / 9.0 * 8000 * 1.0e-3 * 0.1 / st    # as in in.wall_bounce
        rows.append({"St": st, "mu_f": mu_f, "e": e, "e_over_ed": ratio,
                     "legendre": legendre, "difference": ratio - legendre,
                     "e_over_ed_calibrated": calibrated,
                     "difference_calibrated": calibrated - legendre})
        print(f"St = {st:6g}   e/e_d = {ratio:.4f}   calibrated {calibrated:.4f}   "
              f"exp(-35/St) = {legendre:.4f}   difference = {ratio - legendre:+.4f}, "
              f"calibrated {calibrated - legendre:+.4f}")

    st_sweep_output.write_csv(out / "st_sweep.csv", rows)
    st_sweep_output.plot(out / "st_sweep.png", rows,
                         f"LAMMPS + lubricated plugin (e_d = {E_DRY}, N_c = 8)",
                         extra=("e_over_ed_calibrated", "the same with legendre 35", "s",
                                "tab:blue"))
    worst = max(abs(r["difference"]) for r in rows if 50 <= r["St"] <= 1000)
    worst_calibrated = max(abs(r["difference_calibrated"]) for r in rows if 10 <= r["St"] <= 1000)
    print(f"wrote {out / 'st_sweep.csv'} and {out / 'st_sweep.png'}")
    print(f"largest |e/e_d - exp(-35/St)| for 50 <= St <= 1000: {worst:.3f}")
    print(f"with legendre 35, for 10 <= St <= 1000: {worst_calibrated:.3f}")


if __name__ == "__main__":
    main()

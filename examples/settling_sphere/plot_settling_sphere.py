"""A steel sphere settling in silicone oil onto a wall (examples/settling_sphere/in.settling_sphere),
DEM without a resolved fluid: the trajectory (approach, rebounds, rest) to CSV and PNG, and the
first rebound coefficient against Legendre's law e_d exp(-35/St).

The rebound coefficient is defined as in the experiments (Joseph et al. 2001, Gondret et al.
2002), from the trajectory: e = u_out / u_in, u_in the approach speed before the wall slows the
sphere (its largest downward speed before the first contact) and u_out the largest upward speed
after it. St = rho_p u_in D / (9 mu_f). The same run with the activation given directly (the
recipe the documentation gave before `activation dem`: 0.09375 from the paper's grid, and 1)
shows how much the answer depended on it. Writes settling_sphere_<film>.csv and
settling_sphere.png to --out; runs in a few seconds."""
import argparse
import math
import pathlib
import shutil
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import lammps_run  # noqa: E402

FILMS = ["dem", "0.09375", "1"]    # the DEM setting, then the old "give activation directly"


def first_rebound(t, gap, vz):
    """u_in, u_out, rebound height [R] of the first rebound of a trajectory (gap in R). A sphere
    that never touches the wall (the film stops it) rebounds from its closest approach, if at all."""
    touch = int(np.argmax(gap <= 0.0)) if (gap <= 0.0).any() else int(np.argmin(gap))
    u_in = -vz[:touch].min()
    leave = touch
    while leave < len(vz) and gap[leave] <= 0.0:
        leave += 1
    top = leave
    while top < len(vz) and vz[top] > 0.0:
        top += 1
    u_out = max(vz[touch:top].max(), 0.0) if top > touch else 0.0
    height = gap[touch:top].max() if top > touch else 0.0
    return u_in, u_out, max(height, 0.0)


def run(film, out, settle=0.4, ncontact=8):
    script = (ROOT / "examples" / "settling_sphere" / "in.settling_sphere").read_text()
    csv = f"settling_sphere_{film}.csv"
    result, _ = lammps_run.run(script, out / "runs", {"film": film, "csv": csv, "settle": settle,
                                                        "ncontact": ncontact}, name="in.settling_sphere")
    shutil.copy(out / "runs" / csv, out / csv)
    data = np.genfromtxt(out / csv, delimiter=",", names=True)
    u_in, u_out, height = first_rebound(data["t"], data["gap_over_R"], data["vz"])
    return result, data, u_in, u_out, height


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default=str(ROOT / "build" / "settling_sphere"))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    runs = {film: run(film, out) for film in FILMS}
    print(f"{'activation':>10} {'St':>6} {'u_in':>7} {'u_out':>7} {'e':>6} {'e_d exp(-35/St)':>16} "
          f"{'rebound [R]':>11}")
    for film, (result, _, u_in, u_out, height) in runs.items():
        st = result["St"]
        law = result["e_d"] * math.exp(-35.0 / st)
        print(f"{film:>10} {st:6.1f} {u_in:7.4f} {u_out:7.4f} {u_out / u_in:6.3f} {law:16.3f} {height:11.3f}")
        print(f"RESULT {film} St {st:.4f} e {u_out / u_in:.5f} law {law:.5f} rebound_R {height:.5f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for film, (result, data, u_in, u_out, height) in runs.items():
        label = "activation dem (DEM setting)" if film == "dem" else f"activation {film} (given directly)"
        t = data["t"] - data["t"][np.argmax(data["gap_over_R"] <= 0.0)]
        top.plot(t * 1e3, data["gap_over_R"], label=f"{label}: e = {u_out / u_in:.3f}")
        bottom.plot(t * 1e3, data["vz"], label=label)
    result = runs["dem"][0]
    law = result["e_d"] * math.exp(-35.0 / result["St"])
    top.set_ylabel("gap / R")
    top.set_ylim(-0.05, 4.5)
    top.set_title(f"steel sphere in silicone oil, St = {result['St']:.1f}: e_d exp(-35/St) = {law:.3f}")
    top.legend(fontsize=8)
    bottom.axhline(law * runs["dem"][2], color="k", lw=0.8, ls="--", label="e_d exp(-35/St) u_in")
    bottom.set_ylabel("v_z [m/s]")
    bottom.set_xlabel("time from the first contact [ms]")
    bottom.set_xlim(-40, 120)
    bottom.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "settling_sphere.png", dpi=120)
    print(f"wrote {out}/settling_sphere_*.csv and {out}/settling_sphere.png")


if __name__ == "__main__":
    main()

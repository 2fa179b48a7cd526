"""The settling sphere (in.settling_sphere, DEM without a resolved fluid) against the measured
trajectories of Gondret, Lance & Petit (2002) (data/README.md): steel spheres settling in silicone
oils onto a glass wall, St = 27 and 152, and a third St between them without a measured
trajectory (Legendre's law only). Each case runs the example's documented DEM settings
(activation dem, t_c = 0.04 R/U in 8 steps, added_mass 0.5 history yes kernel mei-adrian wall
zplane 0.0 NULL) and reports the first and second rebound heights and the times of the
rebound peaks and of the second impact against the data. Writes compare_experiments.csv and
compare_experiments.png to --out; --diagnose adds the St 27 runs with one term at a time
switched off (the separation-phase budget of doc/model.rst). A few seconds per run."""
import argparse
import csv
import math
import pathlib
import shutil
import sys

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import lammps_run  # noqa: E402

INERTIA = "added_mass 0.5 history yes kernel mei-adrian wall zplane 0.0 NULL"
OIL_DENSITY = 965.0    # both oils of the data (data/README.md)
STEEL = 7800.0
# name, radius [m], viscosity [Pa s], release height of the centre [R], data file (None: no
# measured trajectory). St 152: released where the PARTIES set-up of that experiment releases it.
CASES = [
    ("St27", 3.0e-3, 0.1, 60, "gondret2002_st27.csv"),
    ("St90", 3.0e-3, 0.04, 60, None),
    ("St152", 1.5e-3, 0.0103, 131, "gondret2002_st152.csv"),
]
# The wall film's tension on separation (fix wall/lubrication cavitation): the default (none),
# a film that ruptures (0) and one that holds the ambient pressure's tension (1e5 Pa).
SETTINGS = [("none", "film as printed (default)"), ("0", "cavitation 0"), ("1e5", "cavitation 1e5 Pa")]
# St 27 with one term at a time off (--diagnose): the fix fluid/drag inertia string.
DIAGNOSIS = [
    ("all terms", INERTIA),
    ("no history force", "added_mass 0.5 wall zplane 0.0 NULL"),
    ("no near-wall added mass", "added_mass 0.5 history yes kernel mei-adrian"),
    ("no added mass, no history", "added_mass 0"),
]


def events(t, gap, touch):
    """Impacts and rebound peaks of a trajectory (gap >= 0 out of contact): the first impact is
    the first sample with gap <= touch; each peak the largest gap before the gap comes back to
    touch, and the next impact that return. Returns ([t_impact], [(t_peak, gap_peak)])."""
    impacts, peaks = [], []
    i = int(np.argmax(gap <= touch)) if (gap <= touch).any() else None
    while i is not None and len(impacts) < 3:
        impacts.append(t[i])
        after = np.nonzero(gap[i:] > touch)[0]
        if not len(after):
            break
        up = i + after[0]
        back = np.nonzero(gap[up:] <= touch)[0]
        end = up + back[0] if len(back) else len(gap)
        top = up + int(np.argmax(gap[up:end]))
        peaks.append((t[top], gap[top]))
        i = end if len(back) else None
    return impacts, peaks


def measured_events(name, t, gap):
    """The data's impacts and peaks: its local minima and maxima (its samples are 2 ms apart, so
    an impact time is known to 1 ms). The St 27 record starts at the impact (t = 0) and ends
    0.1 mm above the wall: its second impact is the linear extrapolation of the last two samples."""
    minima = [k for k in range(1, len(gap) - 1) if gap[k] <= gap[k - 1] and gap[k] < gap[k + 1]]
    maxima = [k for k in range(1, len(gap) - 1) if gap[k] >= gap[k - 1] and gap[k] > gap[k + 1]]
    maxima = [k for k in maxima if gap[k] > 2.0e-4]    # digitisation noise while resting
    if name == "St27":
        second = t[-1] + gap[-1] * (t[-1] - t[-2]) / (gap[-2] - gap[-1])
        return [0.0, second], [(t[k], gap[k]) for k in maxima]
    return [t[k] for k in minima if gap[k] < 3.5e-4], [(t[k], gap[k]) for k in maxima]


def run_case(name, radius, mu, height, out, cavitation, inertia=INERTIA, tag="", plugin=None):
    script = (HERE / "in.settling_sphere").read_text()
    csv_name = f"cmp_{name}_cavitation_{cavitation}{tag}.csv"
    variables = {"R": radius, "mu": mu, "rho_f": OIL_DENSITY, "rho_p": STEEL, "e_d": 0.97, "film": "dem",
                 "csv": csv_name, "settle": 0.25, "height": height, "every": 4, "inertia": inertia,
                 "cavitation": cavitation}
    kwargs = {"plugin": plugin} if plugin else {}
    result, _ = lammps_run.run(script, out / "runs", variables, name="in.settling_sphere", **kwargs)
    shutil.copy(out / "runs" / csv_name, out / csv_name)
    data = np.genfromtxt(out / csv_name, delimiter=",", names=True)
    t, gap = data["t"], data["gap_over_R"] * radius
    impacts, peaks = events(t, gap, 0.0)
    # e as the experiments take it: the largest upward speed out of contact before the first peak
    rising = (t > impacts[0]) & (gap > 0.0) & (t < peaks[0][0]) if peaks else np.zeros_like(t, bool)
    result["e_out"] = data["vz"][rising].max() / result["U"] if rising.any() else 0.0
    return result, t - impacts[0], gap, [s - impacts[0] for s in impacts], [(a - impacts[0], h) for a, h in peaks]


def row(name, setting, radius, result, impacts, peaks, measured=None):
    """One line of the table: model (and data) first and second peak [R], their times and the
    second impact time [ms], from the first impact."""
    def get(seq, k, f):
        return f(seq[k]) if len(seq) > k else float("nan")
    values = {"case": name, "cavitation": setting, "St": result["St"], "U": result["U"], "e_out": result["e_out"],
              "h1_R": get(peaks, 0, lambda p: p[1] / radius), "t_h1_ms": get(peaks, 0, lambda p: 1e3 * p[0]),
              "t_impact2_ms": get(impacts, 1, lambda s: 1e3 * s),
              "h2_R": get(peaks, 1, lambda p: p[1] / radius), "t_h2_ms": get(peaks, 1, lambda p: 1e3 * p[0])}
    if measured:
        m_impacts, m_peaks = measured
        values.update({"exp_h1_R": get(m_peaks, 0, lambda p: p[1] / radius),
                       "exp_t_h1_ms": get(m_peaks, 0, lambda p: 1e3 * (p[0] - m_impacts[0])),
                       "exp_t_impact2_ms": get(m_impacts, 1, lambda s: 1e3 * (s - m_impacts[0])),
                       "exp_h2_R": get(m_peaks, 1, lambda p: p[1] / radius),
                       "exp_t_h2_ms": get(m_peaks, 1, lambda p: 1e3 * (p[0] - m_impacts[0]))})
    return values


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default=str(ROOT / "build" / "settling_sphere"))
    parser.add_argument("--diagnose", action="store_true", help="St 27 with one term at a time off")
    parser.add_argument("--plugin", default=None, help="lubricatedplugin.so (default: the tree's build)")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows, curves = [], []
    for name, radius, mu, height, data_file in CASES:
        measured, measured_curve = None, None
        if data_file:
            d = np.genfromtxt(HERE / "data" / data_file, delimiter=",", names=True)
            measured = measured_events(name, d["t_s"], d["gap_m"])
            measured_curve = (d["t_s"] - measured[0][0], d["gap_m"] / radius)
        runs = []
        for setting, label in SETTINGS:
            result, t, gap, impacts, peaks = run_case(name, radius, mu, height, out, setting, plugin=args.plugin)
            rows.append(row(name, setting, radius, result, impacts, peaks, measured))
            runs.append((label, result, t, gap / radius))
        curves.append((name, runs, measured_curve))
    if args.diagnose:
        name, radius, mu, height, _ = CASES[0]
        for setting in ("none", "0"):
            for k, (label, inertia) in enumerate(DIAGNOSIS):
                result, _, _, impacts, peaks = run_case(name, radius, mu, height, out, setting, inertia, f"_diag{k}",
                                                        args.plugin)
                rows.append(row(f"St27 {label}", setting, radius, result, impacts, peaks))
    keys = list(dict.fromkeys(k for r in rows for k in r))
    with open(out / "compare_experiments.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=keys)
        writer.writeheader()
        writer.writerows(rows)
    for r in rows:
        text = " ".join(f"{k} {v:.4g}" if isinstance(v, float) else f"{k} {v}" for k, v in r.items())
        print("RESULT", text.replace("case ", "case=", 1))
    plot(curves, out)


def plot(curves, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(curves), figsize=(5 * len(curves), 4))
    for ax, (name, runs, measured) in zip(axes, curves):
        for (label, result, t, gap), style in zip(runs, ("b-", "r-", "g--")):
            ax.plot(t * 1e3, gap, style, lw=1, label=f"DEM, {label}")
        if measured is not None:
            ax.plot(measured[0] * 1e3, measured[1], "ko", ms=3, mfc="none", label="Gondret et al. (2002)")
        result = runs[0][1]
        law = 0.97 * math.exp(-35.0 / result["St"])
        ax.set_title(f"{name}: St = {result['St']:.0f}, U = {result['U']:.3f} m/s, e_d exp(-35/St) = {law:.2f}",
                     fontsize=9)
        ax.set_xlim(-10, 60) if name == "St27" else ax.set_xlim(-20, 200)
        top = max(gap[t > 0].max() for _, _, t, gap in runs)
        ax.set_ylim(-0.1, 1.1 * max(top, measured[1].max() if measured is not None else 0.0, 0.5))
        ax.set_xlabel("time from the first impact [ms]")
        ax.set_ylabel("gap / R")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "compare_experiments.png", dpi=110)


if __name__ == "__main__":
    main()

"""A dense suspension in simple shear (examples/suspension_shear/in.suspension_shear) at a few
solid fractions, against the experimental laws of dense non-Brownian suspensions.

Each run shears 300 bidisperse spheres (radii a and 1.4 a, equal volumes, rho_p = rho_f) at
St = rho gdot a^2 / eta_f = 1e-3 (gdot t_c = 2.5e-4, N_c 8) to a strain of 1 with the films solved
together where the film budget binds (limit implicit), friction mu_c 0.5 (and 0 with
--frictionless), and averages the stress over the second half of the strain:
the friction coefficient mu = sigma_xy / P, the viscous number J = eta_f gdot / P and the
relative viscosity eta_s = 1 + sigma_xy / (eta_f gdot). One solid fraction is run again with the
film budget alone (limit atom) to show what the solve changes. --rollfilm adds the films' rolling
term (pair_coeff rollfilm yes).

The laws (Boyer, Guazzelli & Pouliquen 2011, PRL 107:188301, fitted to their pressure-imposed
rheometry of PMMA and polystyrene spheres in viscous oils):
    mu(J)  = mu_1 + (mu_2 - mu_1) / (1 + J_0 / J) + J + (5/2) phi_m J^(1/2)
    phi(J) = phi_m / (1 + J^(1/2))
with mu_1 = 0.32, mu_2 = 0.7, J_0 = 0.005, phi_m = 0.585; and for eta_s(phi) the
Maron-Pierce form (1 - phi / phi_m)^-2 with the same phi_m, and the law's own
eta_s = mu(J) / J at phi(J). Writes suspension.csv and suspension.png to --out."""
import argparse
import csv
import pathlib
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import lammps_run  # noqa: E402

MU_1, MU_2, J_0, PHI_M = 0.32, 0.7, 0.005, 0.585     # Boyer, Guazzelli & Pouliquen (2011)
PHIS = [0.45, 0.50, 0.54, 0.56, 0.58, 0.60]
STRAIN = 1.0          # shear strain of each run; the stress is averaged over its second half
COLUMNS = ["phi", "mu_c", "limit", "strain", "St", "J", "mu", "eta_s", "P", "sigma_xy",
           "iterations", "seconds"]


def mu_of_j(j):
    return MU_1 + (MU_2 - MU_1) / (1.0 + J_0 / j) + j + 2.5 * PHI_M * np.sqrt(j)


def phi_of_j(j):
    return PHI_M / (1.0 + np.sqrt(j))


def maron_pierce(phi):
    """(1 - phi / phi_m)^-2 below phi_m; not defined (nan) at and above it."""
    return (1.0 - phi / PHI_M) ** -2 if phi < PHI_M else float("nan")


def shear(phi, out, mu_c=0.5, limit="implicit", strain=STRAIN, rollfilm="no"):
    script = (ROOT / "examples" / "suspension_shear" / "in.suspension_shear").read_text()
    variables = {"phi": phi, "mu_c": mu_c, "limit": limit, "strain": strain,
                 "average": strain / 2, "rollfilm": rollfilm}
    start = time.perf_counter()
    result, _ = lammps_run.run(script, out / "runs" / f"phi{phi}_mu{mu_c}_{limit}", variables,
                               name="in.suspension_shear")
    row = {"phi": phi, "mu_c": mu_c, "limit": limit, "seconds": time.perf_counter() - start}
    for key in ["strain", "St", "J", "mu", "eta_s", "P", "sigma_xy", "iterations"]:
        row[key] = result[key]
    return row


def plot(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax_mu, ax_phi, ax_eta) = plt.subplots(1, 3, figsize=(15, 4.8))
    j = np.geomspace(1e-4, 1.0, 200)
    ax_mu.plot(j, mu_of_j(j), "k-", label="Boyer et al. (2011)")
    ax_phi.plot(j, phi_of_j(j), "k-", label="Boyer et al. (2011)")
    phi = np.linspace(0.3, 0.575, 200)
    ax_eta.plot(phi, (1.0 - phi / PHI_M) ** -2, "k-", label=f"Maron-Pierce, phi_m = {PHI_M}")
    ax_eta.plot(phi_of_j(j), mu_of_j(j) / j, "k--", label="Boyer et al.: mu(J) / J at phi(J)")
    styles = {("implicit", 0.5): ("o", "C0", "limit implicit, mu_c 0.5"),
              ("implicit", 0.0): ("s", "C1", "limit implicit, mu_c 0"),
              ("atom", 0.5): ("x", "C3", "limit atom (budget only), mu_c 0.5")}
    for (limit, mu_c), (marker, color, label) in styles.items():
        sel = [r for r in rows if r["limit"] == limit and r["mu_c"] == mu_c and r["P"] > 0]
        if not sel:
            continue
        js = [r["J"] for r in sel]
        ax_mu.plot(js, [r["mu"] for r in sel], marker, color=color, label=label)
        ax_phi.plot(js, [r["phi"] for r in sel], marker, color=color, label=label)
        ax_eta.plot([r["phi"] for r in sel], [r["eta_s"] for r in sel], marker, color=color,
                    label=label)
    for ax in (ax_mu, ax_phi):
        ax.set_xscale("log")
        ax.set_xlim(1e-4, 3.0)           # a nearly pressureless run (J >> 1) falls outside
        ax.set_xlabel("J = eta_f gdot / P")
    ax_mu.set_ylim(0.0, 3.5)
    ax_mu.set_ylabel("mu = sigma_xy / P")
    ax_phi.set_ylabel("solid fraction phi")
    ax_eta.set_yscale("log")
    ax_eta.set_xlabel("solid fraction phi")
    ax_eta.set_ylabel("eta_s = 1 + sigma_xy / (eta_f gdot)")
    st = rows[0]["St"]
    ax_mu.set_title(f"friction coefficient (St = {st:g})")
    ax_phi.set_title("solid fraction against J")
    ax_eta.set_title("relative viscosity")
    for ax in (ax_mu, ax_phi, ax_eta):
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "suspension.png", dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default=str(ROOT / "build" / "suspension"))
    parser.add_argument("--frictionless", action="store_true",
                        help="also run every solid fraction with mu_c 0")
    parser.add_argument("--rollfilm", action="store_true",
                        help="the films' rolling term on (pair_coeff rollfilm yes)")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    roll = "yes" if args.rollfilm else "no"
    rows = [shear(phi, out, rollfilm=roll) for phi in PHIS]
    rows.append(shear(0.54, out, limit="atom", rollfilm=roll))
    if args.frictionless:
        rows += [shear(phi, out, mu_c=0.0, rollfilm=roll) for phi in PHIS]
    with open(out / "suspension.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    print(f"{'phi':>5} {'mu_c':>4} {'limit':>8} {'strain':>6} {'J':>9} {'mu':>7} {'mu(J) law':>9} "
          f"{'phi(J) law':>10} {'eta_s':>8} {'Maron-P.':>8} {'iter/step':>9} {'s':>5}")
    for r in rows:
        law_mu = mu_of_j(r["J"]) if r["J"] > 0 else float("nan")
        law_phi = phi_of_j(r["J"]) if r["J"] > 0 else float("nan")
        print(f"{r['phi']:5.2f} {r['mu_c']:4.1f} {r['limit']:>8} {r['strain']:6.2f} {r['J']:9.3g} "
              f"{r['mu']:7.3f} {law_mu:9.3f} {law_phi:10.3f} {r['eta_s']:8.1f} "
              f"{maron_pierce(r['phi']):8.1f} {r['iterations']:9.1f} {r['seconds']:5.0f}")
        print(f"RESULT phi {r['phi']} mu_c {r['mu_c']} limit {r['limit']} J {r['J']:.5g} "
              f"mu {r['mu']:.5g} eta_s {r['eta_s']:.5g}")
    plot(rows, out)
    print(f"wrote {out}/suspension.csv and {out}/suspension.png")


if __name__ == "__main__":
    main()

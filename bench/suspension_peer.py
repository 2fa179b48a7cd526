"""The plugin's coupled film solve against LAMMPS's own implicit lubrication on the same packings.

    .venv/bin/python bench/suspension_peer.py            # phi 0.40 0.45 0.50, about 30 min
    .venv/bin/python bench/suspension_peer.py --quick    # phi 0.45, a few minutes

A dense suspension in periodic simple shear, as examples/suspension_shear: bidisperse spheres
(radii a = 100 um and 1.4 a, equal volumes), rho_p = rho_f, St = rho gdot a^2 / eta_f = 1e-3,
Coulomb friction mu_c 0.5, contacts of duration gdot t_c = 1e-3 (e_d 0.5). Each packing is
made once with the plugin (compressed dry to phi, relaxed in fluid at rest; write_data) and
sheared from rest by both engines:

  plugin  pair_style lubricated/springdashpot limit implicit (films within activation 0.1,
          saturation 1e-3, shear film, friction), fix nve/sphere, fix fluid/drag stokes flow
          affine rotation yes (the Stokes torque on the spins, as the peer's), at N_c 8 and 16
          (and 32 unless --quick);
  peer    pair_style hybrid/overlay granular lubricateU/poly: the same linear spring-dashpot
          contacts with history and friction (granular hooke, damping mass_velocity, per type
          pair k so that every pair has the plugin's t_c and e_d), and lubricateU/poly (mu =
          eta_f, log terms on, cutinner at the plugin's saturation gap, cutoff at its activation
          gap, flagHI 1, flagVF 0: its isotropic drag is then the plugin's Stokes drag 6 pi eta_f
          a relative to the affine flow), fix nve/noforce, over a sweep of dt.

Both are sheared with fix deform xy erate gdot remap v to the same strain; the stress is
averaged over its second half. eta_s = 1 + sigma_xy / (eta_f gdot) with sigma_xy the virial of
the pair forces (contacts and films; the peer's lubrication stress at its converged
velocities) and P the trace of that virial / 3; the plugin's drag virial and the peer's
isotropic stresslet (its Einstein term, 5/2 phi with flagVF 0) are reported apart, since the
other model has no counterpart. Runs are interleaved and repeated (--repeats); the peer's
conjugate-gradient loop has no iteration limit, so each run has a time-out (--timeout) and a
run that passes it is reported as such. Logs: OUT/phiX/ (wiped at the start). Output: the
table on stdout, OUT/suspension_peer.md and section suspension-peer of --results (default
bench/RESULTS.md, 'none' to skip).
"""
import argparse
import json
import re
import math
import pathlib
import shutil
import statistics
import subprocess
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import bench_common  # noqa: E402
import lammps_run  # noqa: E402

A = 1.0e-4                  # small radius [m]; the large ones are 1.4 a
RATIO = 1.4
RHO = 1000.0                # spheres and fluid [kg/m^3]
GDOT = 1.0                  # shear rate [1/s]
ST = 1.0e-3
ETA_F = RHO * GDOT * A ** 2 / ST
E_D = 0.5
GTC = 1.0e-3                # gdot t_c
ACTIVATION = 0.1            # eps_al of the plugin's films
SATURATION = 1.0e-3         # eps_1 (the plugin's default)
TOL = 1.0e-4                # the plugin's solve tolerance (the example's)

HEADER = """units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
"""

PACK = "plugin load ${{plugin}}\n" + HEADER + """newton on
region box prism 0 {l0} 0 {l0} 0 {l0} 0 0 0 units box
create_box 2 box
create_atoms 2 random {nlarge} {seed} NULL overlap {olarge} maxtry 20000
create_atoms 1 random {nsmall} {seed1} NULL overlap {osmall} maxtry 20000
set type 1 diameter {d1} density {rho}
set type 2 diameter {d2} density {rho}
neighbor {skin} bin
neigh_modify delay 0 every 1 check yes
timestep {dt}
pair_style lubricated/springdashpot
pair_coeff * * {e_d} tcontact {tc}
fix nve all nve/sphere
fix drag all fluid/drag viscosity {eta} density {rho} law stokes
fix squeeze all deform 1 x final 0 {l} y final 0 {l} z final 0 {l} remap v
run 2000
unfix squeeze
run 1000
velocity all set 0 0 0
write_data pack.data nocoeff
print "RESULT atoms $(atoms)"
print "RESULT phi $(({vsolid})/vol:%.6f)"
"""

# The shear and the stress average, common to both engines (after the engine's own lines).
SHEAR = """newton {newton}
read_data pack.data
neighbor {skin} bin
neigh_modify delay 0 every 1 check yes
timestep {dt}
{engine}
fix shear all deform 1 xy erate {gdot} remap v
{computes}
variable steps equal round({strain}/({gdot}*dt))
variable start equal round({transient}/({gdot}*dt))
fix mean all ave/time {every} 1 {every} {averaged} ave running start ${{start}}
dump snap all custom $(round(v_steps/20)) {dump} id radius x y z
thermo_style custom step atoms ke {thermo_extra}
thermo_modify norm no
thermo $(round(v_steps/5))
run ${{steps}}
{results}
print "RESULT atoms $(atoms)"
"""

PLUGIN_ENGINE = """pair_style lubricated/springdashpot limit implicit tolerance {tol}
pair_coeff * * {e_d} tcontact {tc} viscosity {eta} activation {act} saturation {sat} friction {mu_c} shearfilm yes
fix nve all nve/sphere
fix drag all fluid/drag viscosity {eta} density {rho} law stokes flow affine rotation yes
fix_modify drag virial yes"""
PLUGIN_COMPUTES = """compute pairs all pressure NULL pair
compute drag all pressure NULL fix
compute solve all pair lubricated/springdashpot"""
PLUGIN_AVERAGED = "c_pairs[4] c_pairs c_drag[4] c_drag c_solve[3]"
PLUGIN_RESULTS = """print "RESULT sxy $(-f_mean[1]:%.8g)"
print "RESULT P $(f_mean[2]:%.8g)"
print "RESULT sxy_extra $(-f_mean[3]:%.8g)"
print "RESULT P_extra $(f_mean[4]:%.8g)"
print "RESULT iterations $(f_mean[5]:%.6g)\""""

PEER_ENGINE = """pair_style hybrid/overlay granular lubricateU/poly {eta} 1 {cin_global} {cout_global} {gdot} 1 0
{coeffs}
fix nve all nve/noforce"""
PEER_COMPUTES = """compute contacts all pressure NULL pair/hybrid granular
compute films all pressure NULL pair/hybrid lubricateU/poly"""
PEER_AVERAGED = "c_contacts[4] c_contacts c_films[4] c_films"
# The films' virial holds the isotropic stresslet (5/2 phi eta_f gdot in sigma_xy, no part in P):
# it is taken out of sigma_xy below and reported as sxy_extra.
PEER_RESULTS = """print "RESULT sxy_contacts $(-f_mean[1]:%.8g)"
print "RESULT P_contacts $(f_mean[2]:%.8g)"
print "RESULT sxy_films $(-f_mean[3]:%.8g)"
print "RESULT P_films $(f_mean[4]:%.8g)\""""


def radii():
    return {1: A, 2: RATIO * A}


def masses():
    return {t: RHO * 4.0 / 3.0 * math.pi * r ** 3 for t, r in radii().items()}


def counts(n):
    nlarge = round(n / (1 + RATIO ** 3))
    return n - nlarge, nlarge


def solid_volume(n):
    nsmall, nlarge = counts(n)
    return 4.0 / 3.0 * math.pi * A ** 3 * (nsmall + nlarge * RATIO ** 3)


def make_packing(work, n, phi, seed):
    """Compress n spheres to phi with the plugin (dry, drag damping), relax, write pack.data."""
    nsmall, nlarge = counts(n)
    vsolid = solid_volume(n)
    tc = GTC / GDOT
    script = PACK.format(l0=(vsolid / 0.2) ** (1 / 3), l=(vsolid / phi) ** (1 / 3), nlarge=nlarge,
                         nsmall=nsmall, seed=seed, seed1=seed + 1, olarge=2.8 * A, osmall=2.4 * A,
                         d1=2 * A, d2=2 * RATIO * A, rho=RHO, skin=0.3 * A, dt=tc / 16, e_d=E_D, tc=tc,
                         eta=ETA_F, vsolid=vsolid)
    result, _ = lammps_run.run(script, work, name="in.pack")
    assert int(result["atoms"]) == n, "spheres lost in the compression"
    return result["phi"]


def peer_coeffs(mu_c):
    """pair_coeff lines of the peer: per type pair the plugin's contact (k = m_e (pi^2 +
    ln^2 e_d) / t_c^2, damping -2 ln(e_d) / t_c per unit reduced mass, tangential 2/7 of both,
    friction mu_c) and lubricateU/poly's cutinner / cutoff at the plugin's saturation and
    activation gaps (normalised by R = 2 r_i r_j / (r_i + r_j), a centre distance)."""
    r, m = radii(), masses()
    tc = GTC / GDOT
    kappa = (math.pi ** 2 + math.log(E_D) ** 2) / tc ** 2
    gamma_n = -2.0 * math.log(E_D) / tc
    lines = []
    for i, j in ((1, 1), (1, 2), (2, 2)):
        m_e = m[i] * m[j] / (m[i] + m[j])
        kn = m_e * kappa
        lines.append(f"pair_coeff {i} {j} granular hooke {kn!r} {gamma_n!r} tangential linear_history "
                     f"{2.0 / 7.0 * kn!r} {2.0 / 7.0!r} {mu_c} damping mass_velocity")
        gap_r = 2.0 * r[i] * r[j] / (r[i] + r[j])
        lines.append(f"pair_coeff {i} {j} lubricateU/poly {r[i] + r[j] + SATURATION * gap_r!r} "
                     f"{r[i] + r[j] + ACTIVATION * gap_r!r}")
    return "\n".join(lines)


def shear_script(engine, dt, strain, mu_c, dump="snap.dump"):
    """The input of one arm: engine 'plugin' or 'peer', time step dt; snapshots to dump."""
    tc = GTC / GDOT
    if engine == "plugin":
        lines = PLUGIN_ENGINE.format(tol=TOL, e_d=E_D, tc=tc, eta=ETA_F, act=ACTIVATION, sat=SATURATION,
                                     mu_c=mu_c, rho=RHO)
        computes, averaged, results, extra = PLUGIN_COMPUTES, PLUGIN_AVERAGED, PLUGIN_RESULTS, "c_solve[3]"
        prefix = "plugin load ${plugin}\n"
    else:
        # the global cutoffs only size the neighbour list: the largest pair's activation gap
        big = radii()[2]
        lines = PEER_ENGINE.format(eta=ETA_F, cin_global=2 * big * (1 + SATURATION / 2),
                                   cout_global=2 * big * (1 + ACTIVATION / 2), gdot=GDOT,
                                   coeffs=peer_coeffs(mu_c))
        computes, averaged, results, extra = PEER_COMPUTES, PEER_AVERAGED, PEER_RESULTS, "c_contacts[4]"
        prefix = ""
    newton = "on" if engine == "plugin" else "off"      # lubricateU/poly needs newton pair off
    return prefix + HEADER + SHEAR.format(newton=newton, skin=0.3 * A, dt=dt, engine=lines, gdot=GDOT,
                                          computes=computes, strain=strain, transient=strain / 2, every=20,
                                          dump=dump, averaged=averaged, thermo_extra=extra, results=results)


def shear(work, engine, dt, strain, mu_c, phi, timeout):
    """Run one arm; returns a row (eta_s, P, mu, extras, seconds) or one saying it timed out."""
    name = f"{engine}_dt{dt:.3g}"
    row = {"engine": engine, "dt": dt, "strain": strain}
    try:
        result, log = lammps_run.run(shear_script(engine, dt, strain, mu_c, f"{name}.dump"), work,
                                     name=f"in.{name}", timeout=timeout)
    except subprocess.TimeoutExpired:
        row["timeout"] = timeout
        return row
    # the cost: CPU seconds of the loop (its wall time times LAMMPS's 'CPU use'), which a shared
    # machine's other loads change less than the wall time
    timing = bench_common.parse_log(log)
    cpu = re.search(r"([0-9.]+)% CPU use", log)
    row["wall"] = timing["seconds"]
    row["seconds"] = timing["seconds"] * (float(cpu.group(1)) / 100.0 if cpu else 1.0)
    if engine == "plugin":
        sxy, p = result["sxy"], result["P"]
        row["sxy_extra"], row["iterations"] = result["sxy_extra"], result["iterations"]
    else:
        einstein = 2.5 * phi * ETA_F * GDOT
        sxy = result["sxy_contacts"] + result["sxy_films"] - einstein
        p = result["P_contacts"] + result["P_films"]
        row["sxy_extra"], row["iterations"] = einstein, float("nan")
        row["film_share"] = result["sxy_films"] - einstein
    row.update(eta_s=1.0 + sxy / (ETA_F * GDOT), P=p, mu=sxy / p if p else float("nan"))
    row["springs_sxy"], row["springs_P"] = spring_stress(work / f"{name}.dump", strain / 2 / (GDOT * dt))
    return row


def snapshots(path):
    """(step, box (lo, hi, xy), radius, x) of each snapshot of a dump 'id radius x y z'."""
    lines = path.read_text().split("\n")
    k = 0
    while k < len(lines) and lines[k].startswith("ITEM: TIMESTEP"):
        step, count = int(lines[k + 1]), int(lines[k + 3])
        bounds = [[float(v) for v in lines[k + 5 + d].split()] for d in range(3)]
        xy = bounds[0][2] if len(bounds[0]) > 2 else 0.0
        lo = np.array([bounds[0][0] - min(0.0, xy), bounds[1][0], bounds[2][0]])
        hi = np.array([bounds[0][1] - max(0.0, xy), bounds[1][1], bounds[2][1]])
        atoms = np.array([[float(v) for v in line.split()] for line in lines[k + 9:k + 9 + count]])
        yield step, (lo, hi, xy), atoms[:, 1], atoms[:, 2:5]
        k += 9 + count


def spring_stress(path, start):
    """sigma_xy and P of the normal contact springs alone (k delta along the line of centres, the
    plugin's k for every pair: both engines have it), averaged over the snapshots from step start:
    how the stress splits into contacts and films the same way for both engines."""
    kappa = (math.pi ** 2 + math.log(E_D) ** 2) / (GTC / GDOT) ** 2
    sums = []
    for step, (lo, hi, xy), radius, x in snapshots(path):
        if step < start:
            continue
        length = hi - lo
        d = x[:, None, :] - x[None, :, :]
        images = np.round(d[..., 1] / length[1])            # the tilted periodic images along y
        d[..., 0] -= images * xy
        d[..., 1] -= images * length[1]
        for axis in (0, 2):
            d[..., axis] -= np.round(d[..., axis] / length[axis]) * length[axis]
        dist = np.sqrt((d ** 2).sum(-1))
        mass = RHO * 4.0 / 3.0 * math.pi * radius ** 3
        m_e = mass[:, None] * mass[None, :] / (mass[:, None] + mass[None, :])
        overlap = np.clip(radius[:, None] + radius[None, :] - dist, 0.0, None)
        np.fill_diagonal(overlap, 0.0)
        f_over_r = kappa * m_e * overlap / np.where(dist > 0, dist, 1.0)
        virial = 0.5 * np.einsum("ij,ija,ijb->ab", f_over_r, d, d) / length.prod()
        sums.append((-virial[0, 1], np.trace(virial) / 3.0))
    if not sums:
        return float("nan"), float("nan")
    return tuple(float(v) for v in np.mean(sums, axis=0))


def arms(quick):
    """(engine, dt) of every timed arm: the plugin at N_c 8, 16 (32), the peer at gdot dt 5e-4 and
    2.5e-4. The peer at gdot dt 1e-3 is PROBE: run once per packing, with its own time-out."""
    tc = GTC / GDOT
    plugin = [("plugin", tc / nc) for nc in ((8, 16) if quick else (8, 16, 32))]
    return plugin + [("peer", g / GDOT) for g in (5e-4, 2.5e-4)]


PROBE = ("peer", 1e-3 / GDOT)


def summarise(rows):
    """Per arm: medians of eta_s, P, mu over the repetitions, the spread of the seconds."""
    out = []
    keys = sorted(set((r["engine"], r["dt"]) for r in rows), key=lambda k: (k[0] != "plugin", -k[1]))
    for key in keys:
        sel = [r for r in rows if (r["engine"], r["dt"]) == key]
        done = [r for r in sel if "timeout" not in r]
        row = {"engine": key[0], "dt": key[1], "runs": len(sel), "done": len(done),
               "strain": sel[0]["strain"]}
        if done:
            for k in ("eta_s", "P", "mu", "sxy_extra", "iterations", "film_share", "springs_sxy", "springs_P"):
                row[k] = statistics.median(r.get(k, float("nan")) for r in done)
            secs = [r["seconds"] for r in done]
            row.update(seconds=statistics.median(secs), smin=min(secs), smax=max(secs),
                       wall=statistics.median(r["wall"] for r in done))
        else:
            row["timeout"] = sel[0]["timeout"]
        out.append(row)
    return out


def label(row):
    if row["engine"] == "plugin":
        return f"plugin, N_c {GTC / GDOT / row['dt']:.0f}"
    return f"peer, gdot dt {GDOT * row['dt']:.3g}"


def table(phi_rows):
    lines = ["| phi | arm | eta_s | P [Pa] | mu | springs: eta, P [Pa] | not in eta_s | CG it./step "
             "| CPU s per strain [min, max] (wall) | runs |", "|---|---|---|---|---|---|---|---|---|---|"]
    for phi, rows in phi_rows:
        for r in rows:
            if "timeout" in r:
                lines.append(f"| {phi:.3f} | {label(r)} | - | - | - | - | - | - | over {r['timeout']:.0f} s "
                             f"(time-out) | 0/{r['runs']} |")
                continue
            per = 1.0 / r["strain"]
            extra = (r["sxy_extra"] / (ETA_F * GDOT))
            what = "drag" if r["engine"] == "plugin" else "Einstein"
            it = f"{r['iterations']:.0f}" if r["engine"] == "plugin" else "-"
            springs = f"{r['springs_sxy'] / (ETA_F * GDOT):.2f}, {r['springs_P']:.3g}"
            lines.append(f"| {phi:.3f} | {label(r)} | {r['eta_s']:.2f} | {r['P']:.4g} | {r['mu']:.3f} | "
                         f"{springs} | {what} {extra:+.2f} | {it} | {r['seconds'] * per:.0f} [{r['smin'] * per:.0f}, "
                         f"{r['smax'] * per:.0f}] ({r['wall'] * per:.0f}) | {r['done']}/{r['runs']} |")
    return lines


def verdict(phi_rows, tolerance=0.05):
    """Per phi: each engine's coarsest arm within tolerance of its next finer one (converged),
    the eta_s ratio of the two finest arms, and the cost ratio of the converged arms."""
    lines = []
    for phi, rows in phi_rows:
        best = {}
        for engine in ("plugin", "peer"):
            sel = sorted((r for r in rows if r["engine"] == engine and "timeout" not in r),
                         key=lambda r: -r["dt"])
            converged = next((a for a, b in zip(sel, sel[1:])
                              if abs(a["eta_s"] - b["eta_s"]) <= tolerance * abs(b["eta_s"])), None)
            best[engine] = (sel[-1] if sel else None, converged)
        (fine_p, conv_p), (fine_q, conv_q) = best["plugin"], best["peer"]
        if not (fine_p and fine_q):
            lines.append(f"- phi {phi:.3f}: an engine has no finished arm")
            continue
        ratio = fine_p["eta_s"] / fine_q["eta_s"]
        text = (f"- phi {phi:.3f}: eta_s plugin / peer (finest arms) = {ratio:.2f} "
                f"({'within' if abs(ratio - 1) <= 0.2 else 'outside'} 20 %); ")
        if conv_p and conv_q:
            cost = (conv_q["seconds"] / conv_q["strain"]) / (conv_p["seconds"] / conv_p["strain"])
            text += (f"converged to {tolerance:.0%}: {label(conv_p)} and {label(conv_q)}, the peer costs "
                     f"{cost:.1f} x the plugin per unit strain")
        else:
            missing = [e for e, c in (("plugin", conv_p), ("peer", conv_q)) if not c]
            text += f"not converged to {tolerance:.0%} within the sweep: {', '.join(missing)}"
        lines.append(text)
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="phi 0.45, strain 0.3, fewer arms, one repetition")
    parser.add_argument("--phis", type=float, nargs="+", default=None)
    parser.add_argument("--n", type=int, default=None, help="spheres (default 100)")
    parser.add_argument("--strain", type=float, default=None, help="default 0.5 (0.3 with --quick)")
    parser.add_argument("--friction", type=float, default=0.5)
    parser.add_argument("--repeats", type=int, default=None, help="default 2 (1 with --quick)")
    parser.add_argument("--timeout", type=float, default=900.0, help="seconds per run")
    parser.add_argument("--probe-timeout", type=float, default=120.0,
                        help="seconds for the peer at gdot dt 1e-3 (run once per packing)")
    parser.add_argument("--seed", type=int, default=4928)
    parser.add_argument("--engines", nargs="+", default=["plugin", "peer"], choices=["plugin", "peer"],
                        help="run only these; with --keep the others' rows come from OUT")
    parser.add_argument("--report", action="store_true",
                        help="run nothing: report the rows kept in OUT (runs of separate processes, one per phi)")
    parser.add_argument("--keep", action="store_true",
                        help="keep OUT: reuse its packings and the rows of the engines not run now")
    parser.add_argument("--out", default=str(ROOT / "build" / "bench-suspension-peer"))
    parser.add_argument("--results", default=str(bench_common.RESULTS),
                        help="markdown file whose section 'suspension-peer' gets the results ('none' to skip)")
    args = parser.parse_args()
    phis = args.phis or ([0.45] if args.quick else [0.40, 0.45, 0.50])
    n = args.n or 100
    strain = args.strain or (0.3 if args.quick else 0.5)
    repeats = args.repeats or (1 if args.quick else 2)
    out = pathlib.Path(args.out)
    if args.report:
        args.engines = []
        args.keep = True
    if not args.keep:
        shutil.rmtree(out, ignore_errors=True)
    phi_rows = []
    for phi in phis:
        work = out / f"phi{phi}"
        saved = work / "rows.json"
        if args.keep and (work / "pack.data").exists():
            measured = json.loads((work / "phi.json").read_text())
        else:
            measured = make_packing(work, n, phi, args.seed)
            (work / "phi.json").write_text(json.dumps(measured))
        # rows of the engines not run now come from an earlier run on the same packing (--keep)
        rows = [r for r in (json.loads(saved.read_text()) if args.keep and saved.exists() else [])
                if r["engine"] not in args.engines]
        for rep in range(repeats):
            todo = arms(args.quick) + ([PROBE] if rep == 0 and not args.quick else [])
            for engine, dt in (a for a in todo if a[0] in args.engines):
                timeout = args.probe_timeout if (engine, dt) == PROBE else args.timeout
                row = shear(work, engine, dt, strain, args.friction, measured, timeout)
                rows.append(row)
                print(f"phi {measured:.3f} rep {rep} {label(row)}: "
                      + (f"time-out {row['timeout']:.0f} s" if "timeout" in row else
                         f"eta_s {row['eta_s']:.3f} P {row['P']:.4g} mu {row['mu']:.3f} {row['seconds']:.1f} s"),
                      flush=True)
                saved.write_text(json.dumps(rows))
        phi_rows.append((measured, summarise(rows)))
    text = report(phi_rows, n, strain, repeats, args)
    print(text)
    (out / "suspension_peer.md").write_text(text)
    if args.results != "none":
        bench_common.write_section(args.results, "suspension-peer", text)


DIFFERENCES = """What differs between the two models, with the parameters chosen to match (R = 2 r_i r_j /
(r_i + r_j), eps = gap / R; for two equal spheres of radius a, R = a):

- Pairwise films: the peer's are not, for unequal radii. It evaluates each film from both
  spheres' sides, the response to the imposed strain with 2 r_i in place of r_i + r_j, so an
  unequal pair gets a net force 2 a_sq (n.E.n)(r_j - r_i) (bench/peer_pair_check.py: 117 times
  the Stokes drag at the shear velocity for radii a and 1.4 a at the saturation gap; LAMMPS
  issue 1933). Here its contacts keep compressing (at strain 0.5, 24 to 75 pairs past 1 % of R
  and up to 3-6 %, still growing; the plugin's below 1 %) and its CG slows down.
  bench/suspension_peer_mono.py compares the two with equal radii, where they are pairwise.
- Squeeze film: the plugin 6 pi eta_f R u_n [lambda(max(eps, eps_1)) - lambda(eps_al)], lambda =
  1/(2 eps) - 9/20 ln eps + ...; lubricateU/poly 6 pi eta_f a [1/(4 h) + 9/40 ln(1/h) + O(h ln h)]
  (h = gap / a, Jeffrey-Onishi coefficients for unequal spheres). The plugin's singular terms are
  twice the peer's (the paper's lambda applied to the relative velocity,
  doc/pair_lubricated_springdashpot.rst, "Unequal radii"); the plugin's film vanishes
  continuously at eps_al, the peer's is cut off with a jump at its cutoff, so between eps of
  about 0.04 and 0.1 the peer's film is the stronger one, below it the plugin's (up to 2 x).
- Shear film: the plugin 2 pi eta_f R_e ln(eps_al / max(eps, eps_1)) on the surface slip (R_e
  = a/2 for equal spheres, the peer's pi eta_f a ln(1/h) shifted by ln eps_al); the peer also has
  the pump term (relative spin); both apply the rotational drag 8 pi eta_f a^3 against the
  fluid's vorticity (the plugin's fix fluid/drag rotation yes).
- Near contact: both hold the film at the saturation gap eps_1 = 1e-3 R (the peer's cutinner);
  the plugin removes it beyond an overlap of 1e-2 R (release), the peer keeps it at any overlap.
- Far field: the same Stokes drag 6 pi eta_f a relative to the affine flow (flagVF 0); the
  plugin tallies its virial (fix_modify virial yes; shown apart), the peer none, but adds the
  isotropic stresslet 5/2 phi eta_f gdot (shown apart).
- Dynamics: the plugin keeps the spheres' inertia (St 1e-3) and integrates contacts and films in
  one backward-Euler step (contacts as forces of the step); the peer is inertia-free: each step
  solves R U = F for the velocities twice (midpoint), the contact forces explicit, with its own
  conjugate-gradient loop (relative tolerance 1e-3, no iteration limit).
- Contacts: the same linear spring-dashpot with history and friction per type pair; the plugin
  integrates it over the step (integration exact), granular evaluates it once per step.
"""


def report(phi_rows, n, strain, repeats, args):
    lines = ["# Dense suspension: the coupled film solve against lubricateU/poly (bench/suspension_peer.py)", "",
             f"{n} bidisperse spheres (a and {RATIO} a, equal volumes), St {ST:g}, mu_c {args.friction}, "
             f"gdot t_c {GTC:g}, e_d {E_D}; one packing per phi (the plugin's compression), sheared from rest "
             f"by both engines to strain {strain:g}, stress averaged over the second half; {repeats} "
             f"repetition(s) interleaved, medians; one rank; LAMMPS {bench_common.lammps_version()}; time-out "
             f"{args.timeout:.0f} s per run ({args.probe_timeout:.0f} s for the peer at gdot dt 1e-3). The cost is "
             "the loop's CPU seconds (wall time x LAMMPS's CPU use), the wall time beside it. eta_s = 1 + sigma_xy / (eta_f gdot) and P from the pair "
             "virial (contacts and films); 'not in eta_s' is the plugin's drag virial or the peer's "
             "isotropic (Einstein) stresslet, in units of eta_f gdot. 'springs': sigma_xy / (eta_f gdot) "
             "and P of the normal contact springs alone (k delta, from 20 snapshots of the averaging window): "
             "the rest of eta_s - 1 and of P is the films' (and the tangential contacts').", ""]
    lines += table(phi_rows) + [""] + verdict(phi_rows) + ["", DIFFERENCES]
    return "\n".join(lines)


if __name__ == "__main__":
    main()

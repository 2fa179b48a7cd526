"""Settling-bed benchmark: the plugin dry and wet against LAMMPS's built-in gran/hooke.

    .venv/bin/python bench/settling_bed.py [--sizes 2000 20000] [--steps N] [--out DIR]

For each size a bed is built once: spheres (R = 1 mm, 2500 kg/m^3) on a jittered loose
lattice fall under gravity onto a floor (z = 0, periodic in x and y) with the plugin, dry.
Two snapshots are written with write_data (positions and velocities): the bed while it
settles (t = 0.1 s: the upper layers are still landing) and the settled bed (t = 0.4 s: near
rest, about 6 contacts per sphere). From each snapshot every style runs the same number of
steps, on one rank, in this one invocation; the styles are interleaved (a, b, c, a, b, c, ...)
and the smallest loop time of the repeats counts, since the machine is noisy (runs of fewer
than 1e7 particle-steps are repeated three times as often):

  gran/hooke          built-in pair gran/hooke + fix wall/gran hooke, same normal stiffness
                      and damping as the plugin (k = m_e (pi^2 + ln^2 e)/t_c^2 with m_e = m/2
                      between spheres, m_e = m at the wall; gamma_n = -2 ln(e)/t_c per unit
                      reduced mass), tangential off (Kt = gamma_t = xmu = 0, dampflag 0)
  plugin dry          pair lubricated/springdashpot, pair_coeff * * 0.9 ncontact 8,
                      fix wall/lubrication 0.9 ncontact 8
  plugin wet          the same with viscosity 1e-3 activation 0.09375 (pair and wall)
  plugin dry sampled  for information: the force sampled once per step (integration sampled)
  plugin wet limit pair  for information: wet without the many-body film budget (the cost of
                      the budget is plugin wet / plugin wet limit pair)

All styles: e = 0.9, t_c = 8 dt, dt = 2e-5 s, fix nve/sphere, neighbor 0.0005 bin (skin R/2),
neigh_modify delay 0 every 1 check yes, comm_modify vel yes.

Reported: ns per particle-step = loop time / (atoms * steps) * 1e9, the ratio to gran/hooke
(same size, same snapshot), the Pair / Neigh / Modify shares of the loop (LAMMPS timing
breakdown), dangerous neighbor builds, and physics checks on the final state of every run
(deepest wall overlap, spheres sunk into the floor, deepest sphere-sphere overlap, bed top,
contacts per sphere, fastest sphere). Logs, data files and runs.csv (every timed run) stay in
--out (wiped at the start);
the table goes to stdout, to OUT/RESULTS.md and to section settling (friction with --friction)
of --results (bench/RESULTS.md by default; 'none' to skip). Targets (from the issue): plugin
dry <= 1.0 x gran/hooke, wet <= 1.3 x.
"""
import argparse
import datetime
import math
import pathlib
import platform
import random
import shutil
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import lammps_run  # noqa: E402
from bench_common import (RESULTS, SETTINGS, hooke_coefficients, lammps_version, parse_log,  # noqa: E402,F401
                          physics_flags, write_section)

R = 1.0e-3           # sphere radius [m]
RHO = 2500.0         # sphere density [kg/m^3]
G = 9.81             # gravity [m/s^2]
E_DRY = 0.9          # dry restitution coefficient
NC = 8               # contact duration in steps
DT = 2.0e-5          # time step [s]
SKIN = 0.5 * R       # neighbor skin
WET = "viscosity 1e-3 activation 0.09375"
SPACING = 2.5 * R    # lattice spacing of the initial loose packing (gap 0.5 R)
JITTER = 0.2 * R     # uniform jitter per coordinate: neighbours close in by at most 0.4 R < 0.5 R
TARGETS = {"plugin dry": 1.0, "plugin wet": 1.3, "plugin friction": 1.2}
MU_C = 0.5          # friction coefficient of the --friction benchmark (issue: within 1.2x)
FRICTION = False    # set by --friction: gran/hooke/history against the plugin with friction
SETTLING_AT = 5000   # 0.1 s: the bulk of the spheres is landing (kinetic energy falls 30-fold by 0.12 s)
SETTLED_AT = 20000   # 0.4 s: near rest, about 6 contacts per sphere
SETTLING_STEPS = 2000            # timed window on the settling bed: 0.1 s to 0.14 s for every size
SETTLED_PARTICLE_STEPS = 4e7     # timed steps on the settled bed: 4e7 / size
SHORT_RUN = 1e7                  # runs of fewer particle-steps are repeated 3 times as often

HEADER = """plugin load ${{plugin}}
units si
atom_style sphere
boundary p p f
comm_modify vel yes
newton on
"""

# Evaluated after the timed run, in a 'run 0' of its own, so that nothing of it is timed.
CHECKS = """variable gap atom (z-radius)/{R}
variable sunk atom z<0.5*{R}
variable speed atom sqrt(vx*vx+vy*vy+vz*vz)
compute gapmin all reduce min v_gap
compute sunk all reduce sum v_sunk
compute top all reduce max z
compute vmax all reduce max v_speed
compute cn all contact/atom
compute cnave all reduce ave c_cn
compute pl all pair/local dist
compute dmin all reduce min c_pl inputs local
thermo_style custom step atoms ke c_gapmin c_sunk c_top c_vmax c_cnave c_dmin
run 0 post no
print "RESULT atoms $(atoms)"
print "RESULT ke_per_atom $(ke/atoms:%.6g)"
print "RESULT wall_overlap $(-c_gapmin:%.6g)"
print "RESULT sunk $(c_sunk)"
print "RESULT top $(c_top/{R}:%.6g)"
print "RESULT vmax $(c_vmax:%.6g)"
print "RESULT contacts $(c_cnave:%.6g)"
print "RESULT pair_overlap $((2*{R}-c_dmin)/{R}:%.6g)"
"""

SETTLE = HEADER + """read_data init.data
pair_style lubricated/springdashpot
pair_coeff * * {e} ncontact {nc}
fix floor all wall/lubrication {e} ncontact {nc} zplane 0.0 NULL
""" + SETTINGS + """thermo_style custom step atoms ke
thermo 1000
run {settling_at}
write_data settling.data nocoeff
run {more}
write_data settled.data nocoeff
""" + CHECKS

TIMED = HEADER + """read_data {data}
{pair}
{wall}
""" + SETTINGS + """thermo_style custom step atoms ke
thermo {steps}
run {steps}
""" + CHECKS


def reference_style():
    return "gran/hooke/history" if FRICTION else "gran/hooke"


def styles():
    """name -> (pair lines, wall line); same e, t_c and neighbor settings for all.
    With --friction: tangential stiffness and damping of the plugin (e_t = e_d, m_t = 2/7 m_e:
    Kt = 2/7 Kn, gamma_t = 2/7 gamma_n per unit m_e), Coulomb mu_c on both."""
    c = hooke_coefficients(R, RHO, E_DRY, NC, DT)
    kn_pair, kn_wall, gamma_n = c["kn_pair"], c["kn_wall"], c["gamma_n"]
    plugin = f"{E_DRY} ncontact {NC}"
    if FRICTION:
        kt_pair, kt_wall, gamma_t = c["kt_pair"], c["kt_wall"], c["gamma_t"]
        return {
            "gran/hooke/history": (
                f"pair_style gran/hooke/history {kn_pair:.10g} {kt_pair:.10g} {gamma_n:.10g} {gamma_t:.10g} {MU_C} 1\n"
                "pair_coeff * *",
                f"fix floor all wall/gran hooke/history {kn_wall:.10g} {kt_wall:.10g} {gamma_n:.10g} {gamma_t:.10g} "
                f"{MU_C} 1 zplane 0.0 NULL"),
            "plugin friction": (f"pair_style lubricated/springdashpot\npair_coeff * * {plugin} friction {MU_C}",
                                f"fix floor all wall/lubrication {plugin} friction {MU_C} zplane 0.0 NULL"),
        }
    return {
        "gran/hooke": (f"pair_style gran/hooke {kn_pair:.10g} 0.0 {gamma_n:.10g} 0.0 0.0 0\npair_coeff * *",
                       f"fix floor all wall/gran hooke {kn_wall:.10g} 0.0 {gamma_n:.10g} 0.0 0.0 0 zplane 0.0 NULL"),
        "plugin dry": (f"pair_style lubricated/springdashpot\npair_coeff * * {plugin}",
                       f"fix floor all wall/lubrication {plugin} zplane 0.0 NULL"),
        "plugin wet": (f"pair_style lubricated/springdashpot\npair_coeff * * {plugin} {WET}",
                       f"fix floor all wall/lubrication {plugin} {WET} zplane 0.0 NULL"),
        "plugin wet limit pair": (f"pair_style lubricated/springdashpot limit pair\npair_coeff * * {plugin} {WET}",
                                  f"fix floor all wall/lubrication {plugin} {WET} zplane 0.0 NULL"),
        "plugin dry sampled": (f"pair_style lubricated/springdashpot\npair_coeff * * {plugin} integration sampled",
                               f"fix floor all wall/lubrication {plugin} integration sampled zplane 0.0 NULL"),
    }


def write_initial(path, natoms, width, seed):
    """natoms spheres on a jittered simple-cubic lattice, random velocities; returns geometry."""
    per_row = max(2, round(width / SPACING))
    side = per_row * SPACING
    layers = math.ceil(natoms / per_row ** 2)
    rng = random.Random(seed)
    sites = [(i, j, k) for k in range(layers) for j in range(per_row) for i in range(per_row)]
    full = sites[:(layers - 1) * per_row ** 2]
    last = rng.sample(sites[len(full):], natoms - len(full))        # partial top layer
    top = layers * SPACING + 10 * R
    lines = ["LAMMPS data file: settling bed, initial loose packing", "",
             f"{natoms} atoms", "1 atom types", "",
             f"0 {side:.10g} xlo xhi", f"0 {side:.10g} ylo yhi", f"{-2 * R:.10g} {top:.10g} zlo zhi", "",
             "Atoms # sphere", ""]
    velocities = ["", "Velocities", ""]
    for n, (i, j, k) in enumerate(full + last, start=1):
        x, y, z = ((c + 0.5) * SPACING + rng.uniform(-JITTER, JITTER) for c in (i, j, k))
        lines.append(f"{n} 1 {2 * R:.10g} {RHO:.10g} {x:.10g} {y:.10g} {z:.10g}")
        vx, vy, vz = (rng.uniform(-0.05, 0.05) for _ in range(3))
        velocities.append(f"{n} {vx:.6g} {vy:.6g} {vz:.6g} 0 0 0")
    path.write_text("\n".join(lines + velocities) + "\n")
    return dict(side=side / R, layers=layers)


def bench_size(size, phases, repeats, width, args, log):
    """Build the bed of one size, then time every style on every phase; returns settle, runs."""
    work = pathlib.Path(args.out) / f"bed{size}"
    work.mkdir(parents=True)
    geometry = write_initial(work / "init.data", size, width, args.seed)
    fmt = dict(R=R, g=G, skin=SKIN, dt=DT, e=E_DRY, nc=NC, settling_at=args.settling_at,
               more=args.settled_at - args.settling_at)
    t0 = time.time()
    check, text = lammps_run.run(SETTLE.format(**fmt), work, name="in.settle", timeout=1800)
    settle = parse_log(text)
    settle.update(check=check, wall=time.time() - t0, geometry=geometry)
    log(f"{size} spheres: box {geometry['side']:.1f} R wide, {geometry['layers']} loose layers; "
        f"settled {args.settled_at} steps ({args.settled_at * DT:.2f} s) with the plugin dry in "
        f"{settle['wall']:.0f} s: top {check['top']:.1f} R, {check['contacts']:.2f} contacts/sphere, "
        f"fastest {check['vmax']:.3g} m/s, dangerous builds {settle['dangerous']}")
    runs = {}
    for phase, (data, steps) in phases.items():
        # short runs (the 0.04 s settling window of a small bed) are the noisiest: repeat them more
        for rep in range(repeats * (3 if size * steps < SHORT_RUN else 1)):
            for name, (pair, wall) in styles().items():
                tag = f"{phase}.{name.replace(' ', '_').replace('/', '_')}.{rep + 1}"
                script = TIMED.format(data=data, pair=pair, wall=wall, **dict(fmt, steps=steps))
                check, text = lammps_run.run(script, work, name=f"in.{tag}", timeout=1800)
                timing = parse_log(text)
                timing["check"] = check
                runs.setdefault((phase, name), []).append(timing)
                log(f"  {size} {phase:8s} {name:19s} run {rep + 1}: {timing['ns']:7.1f} ns/particle-step, "
                    f"{timing['seconds']:.2f} s, dangerous builds {timing['dangerous']}")
    return settle, runs


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", type=int, nargs="+", default=[2000, 20000])
    parser.add_argument("--steps", type=int, default=0,
                        help=f"steps per timed run, both beds (default: {SETTLING_STEPS} on the settling bed, "
                             f"{SETTLED_PARTICLE_STEPS:.0e}/size on the settled bed)")
    parser.add_argument("--phases", nargs="+", choices=["settling", "settled"], default=["settling", "settled"])
    parser.add_argument("--repeats", type=int, default=3,
                        help="interleaved repeats, the minimum counts (default 3; runs of fewer than "
                             f"{SHORT_RUN:.0e} particle-steps get 3 times as many)")
    parser.add_argument("--settling-at", type=int, default=SETTLING_AT,
                        help=f"step of the settling snapshot (default {SETTLING_AT}, t = {SETTLING_AT * DT:g} s)")
    parser.add_argument("--settled-at", type=int, default=SETTLED_AT,
                        help=f"step of the settled snapshot (default {SETTLED_AT}, t = {SETTLED_AT * DT:g} s)")
    parser.add_argument("--width", type=float, default=0.0,
                        help="box width in x and y in units of R (default: 20 R at 2000 spheres, "
                             "growing as sqrt(size/2000) so that every bed has the same depth)")
    parser.add_argument("--seed", type=int, default=20251)
    parser.add_argument("--friction", action="store_true",
                        help="time the plugin with friction against gran/hooke/history (issue 4)")
    parser.add_argument("--out", default=str(ROOT / "build" / "bench"))
    parser.add_argument("--results", default=str(RESULTS),
                        help="markdown file whose section 'settling' ('friction' with --friction) gets "
                             "the results besides OUT/RESULTS.md ('none' to skip)")
    args = parser.parse_args()
    global FRICTION
    FRICTION = args.friction
    if not 0 < args.settling_at < args.settled_at:
        parser.error("need 0 < --settling-at < --settled-at")

    out = pathlib.Path(args.out)
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    started = time.time()

    def log(line):
        print(line, flush=True)

    rows, settles, problems = [], {}, []
    raw = ["size,bed,style,repeat,steps,loop_s,ns_per_particle_step,pair_share,dangerous_builds"]
    for size in args.sizes:
        phases = {}
        if "settling" in args.phases:
            phases["settling"] = ("settling.data", args.steps or SETTLING_STEPS)
        if "settled" in args.phases:
            phases["settled"] = ("settled.data", args.steps or max(100, round(SETTLED_PARTICLE_STEPS / size)))
        width = args.width * R if args.width else 20 * R * math.sqrt(size / 2000)
        settle, runs = bench_size(size, phases, args.repeats, width, args, log)
        settles[size] = settle
        if settle["dangerous"] != 0:
            problems.append(f"{size} settle run: {settle['dangerous']} dangerous builds")
        problems += [f"{size} settle run: {f}" for f in physics_flags(settle["check"])]
        for phase in phases:
            ref = min(t["ns"] for t in runs[(phase, reference_style())])
            for name in styles():
                timings = runs[(phase, name)]
                raw += [f"{t['atoms']},{phase},{name},{i + 1},{t['steps']},{t['seconds']:.6g},{t['ns']:.2f},"
                        f"{t['shares']['Pair']:.4f},{t['dangerous']}" for i, t in enumerate(timings)]
                best = min(timings, key=lambda t: t["ns"])
                dangerous = max(t["dangerous"] for t in timings)
                if dangerous != 0:
                    problems.append(f"{size} {phase} {name}: {dangerous} dangerous builds")
                for t in timings:
                    problems += [f"{size} {phase} {name}: {f}" for f in physics_flags(t["check"])]
                rows.append(dict(size=best["atoms"], phase=phase, name=name, steps=best["steps"], ns=best["ns"],
                                 ratio=best["ns"] / ref, spread=max(t["ns"] for t in timings) / best["ns"] - 1.0,
                                 shares=best["shares"], dangerous=dangerous, check=best["check"]))
    wall = time.time() - started
    problems = list(dict.fromkeys(problems))

    print()
    print(f"{'spheres':>8} {'bed':8s} {'style':19s} {'ns/particle-step':>17} {'ratio':>6} {'target':>9} "
          f"{'spread':>7} {'Pair':>5} {'Neigh':>6} {'Modify':>6} {'danger':>6}")
    for r in rows:
        target = TARGETS.get(r["name"])
        verdict = f"{'PASS' if r['ratio'] <= target else 'MISS'} {target:.1f}" if target else ""
        print(f"{r['size']:>8} {r['phase']:8s} {r['name']:19s} {r['ns']:17.1f} {r['ratio']:6.2f} {verdict:>9} "
              f"{r['spread']:7.1%} {r['shares']['Pair']:5.0%} {r['shares']['Neigh']:6.0%} "
              f"{r['shares']['Modify']:6.0%} {r['dangerous']:>6}")
    print(f"\ntotal wall time {wall:.0f} s")
    for p in problems:
        print("PROBLEM:", p)

    text = report(rows, settles, problems, args, wall)
    (out / "RESULTS.md").write_text(text)
    (out / "runs.csv").write_text("\n".join(raw) + "\n")
    if args.results.lower() != "none":
        write_section(args.results, "friction" if args.friction else "settling", text)
        print(f"wrote {args.results}")


def report(rows, settles, problems, args, wall):
    today = datetime.date.today().isoformat()
    lines = [f"# Settling-bed benchmark: plugin against {reference_style()} ({today})", "",
             f"Machine: 2 vCPU cloud VM (about one core of throughput), 1 rank, OMP_NUM_THREADS=1; "
             f"LAMMPS {lammps_version()} (PyPI wheel), {platform.machine()}. "
             f"Written by `bench/settling_bed.py{' --friction' if FRICTION else ''} --sizes {' '.join(map(str, args.sizes))}` "
             f"(set-up in [README.md](README.md)); whole benchmark {wall / 60:.1f} min.", "",
             f"Every style runs the same steps from the same snapshot of the bed (dt = {DT:g} s, "
             f"t_c = {NC} dt, e = {E_DRY}): *settling* = the bed at t = {args.settling_at * DT:g} s while "
             f"its upper layers land, *settled* = the bed at t = {args.settled_at * DT:g} s, near rest. "
             f"The figure is the minimum over {args.repeats} interleaved repeats ({3 * args.repeats} for runs "
             f"of fewer than {SHORT_RUN:.0e} particle-steps); *spread* is "
             "(slowest - fastest) / fastest of those repeats. Shares are of the loop time (LAMMPS "
             "timing breakdown, fastest repeat); Modify holds the wall fix (wall/gran or "
             "wall/lubrication), nve/sphere and gravity. On this VM the ratios of separate "
             "invocations differed by up to about 0.2 (most on the short 2000-sphere settling "
             "window): a ratio within 0.1 of its target is not decided by one run.", "",
             "| spheres | bed | style | steps | ns / particle-step | ratio to " + reference_style() + " | target | verdict "
             "| spread | Pair | Neigh | Modify | dangerous builds |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        target = TARGETS.get(r["name"])
        verdict = ("PASS" if r["ratio"] <= target else "**MISS**") if target else "(info)"
        lines.append(f"| {r['size']} | {r['phase']} | {r['name']} | {r['steps']} | {r['ns']:.1f} | {r['ratio']:.2f} | "
                     f"{f'<= {target:.1f}' if target else '-'} | {verdict} | {r['spread']:.0%} | "
                     f"{r['shares']['Pair']:.0%} | {r['shares']['Neigh']:.0%} | {r['shares']['Modify']:.0%} | "
                     f"{r['dangerous']} |")
    misses = [r for r in rows if r["name"] in TARGETS and r["ratio"] > TARGETS[r["name"]]]
    lines.append("")
    if misses:
        lines.append("**Targets missed:** " + "; ".join(
            f"{r['name']}, {r['size']} spheres, {r['phase']} bed: {r['ratio']:.2f}x gran/hooke "
            f"(target {TARGETS[r['name']]:.1f}x; Pair {r['shares']['Pair']:.0%} of its loop)" for r in misses) + ".")
    else:
        lines.append("All targets met.")
    lines += ["", "## Beds and physics checks", "",
              "State at the end of the dry settling run (plugin, the settled snapshot) and at the end "
              "of the fastest timed run of each style: top = highest sphere centre, contacts = mean "
              "touching neighbours per sphere, overlaps in R (deepest), sunk = sphere centres below "
              "z = R/2.", "",
              "| spheres | run | top [R] | contacts | wall overlap [R] | pair overlap [R] "
              "| sunk | fastest [m/s] | KE / sphere [J] |",
              "|---|---|---|---|---|---|---|---|---|"]

    def state(c):
        return (f"{c['top']:.1f} | {c['contacts']:.2f} | {c['wall_overlap']:.4f} | {c['pair_overlap']:.4f} | "
                f"{int(c['sunk'])} | {c['vmax']:.3g} | {c['ke_per_atom']:.3g} |")

    for size, s in settles.items():
        lines.append(f"| {size} | settle to step {args.settled_at} (box {s['geometry']['side']:.1f} R wide) | "
                     + state(s["check"]))
        for r in rows:
            if r["size"] == size:
                lines.append(f"| {size} | {r['phase']}, {r['name']}, +{r['steps']} steps | " + state(r["check"]))
    lines += ["", "Problems: " + ("; ".join(problems) if problems else
                                  "none (no dangerous builds, no sphere through the floor, overlaps below 0.2 R)."),
              ""]
    return "\n".join(lines)


if __name__ == "__main__":
    main()

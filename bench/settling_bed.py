"""Settling-bed benchmark: the plugin dry and wet against LAMMPS's built-in gran/hooke.

    .venv/bin/python bench/settling_bed.py [--sizes 2000 20000] [--steps N] [--out DIR]

For each size a bed is first settled once with the plugin (dry) and written with write_data;
then each style runs the same number of steps from that same configuration, interleaved and
repeated (the minimum loop time counts, the machine is noisy), on one rank:
  gran/hooke       built-in, same normal stiffness and damping (k = m_e (pi^2 + ln^2 e)/t_c^2,
                   gamma_n = -2 ln e / t_c, m_e = m/2), tangential off (Kt = gammat = xmu = 0)
  plugin dry       pair_style lubricated/springdashpot, pair_coeff * * 0.9 ncontact 8
  plugin dry sampled  the printed force sampled once per step (integration sampled)
  plugin wet       the same with viscosity 1e-3 activation 0.09375 (film on every close pair)
Walls: fix wall/gran hooke for the built-in, fix wall/lubrication for the plugin.
Prints ns per particle-step and the ratios to gran/hooke; writes results.md to --out.
"""
import argparse
import datetime
import math
import pathlib
import re
import shutil
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import lammps_run  # noqa: E402

R, RHO, E_DRY, DT, NC = 1.0e-3, 2500.0, 0.9, 2.0e-5, 8

HEADER = """plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary p p f
comm_modify vel yes
newton on
"""

BUILD = HEADER + """
region box block 0 {L} 0 {L} 0 {H}
create_box 1 box
lattice sc {a} origin 0.5 0.5 0.5
region fill block 0 {L} 0 {L} 0 {Hfill} units box
create_atoms 1 region fill
set group all diameter {d} density {rho}
velocity all create 1e-9 87287 dist gaussian
velocity all set NULL NULL -0.05 sum yes
pair_style lubricated/springdashpot
pair_coeff * * {e} ncontact {nc}
fix floor all wall/lubrication {e} ncontact {nc} zplane 0.0 NULL
fix nve all nve/sphere
fix weight all gravity 9.81 vector 0 0 -1
neighbor {skin} bin
neigh_modify delay 0
timestep {dt}
thermo 1000
run {settle}
write_data bed.data
print "RESULT atoms $(atoms)"
"""

RUN = HEADER + """
read_data bed.data
{pair}
{wall}
fix nve all nve/sphere
fix weight all gravity 9.81 vector 0 0 -1
neighbor {skin} bin
neigh_modify delay 0
timestep {dt}
thermo {steps}
run {steps}
print "RESULT dangerous $(v_dangerous)"
""".replace('print "RESULT dangerous $(v_dangerous)"', "")


def styles():
    mass = RHO * 4.0 / 3.0 * math.pi * R ** 3
    t_c = NC * DT
    kappa = (math.pi ** 2 + math.log(E_DRY) ** 2) / t_c ** 2
    gamma = -2.0 * math.log(E_DRY) / t_c
    wet = "viscosity 1e-3 activation 0.09375"
    return {
        "gran/hooke": (f"pair_style gran/hooke {0.5 * mass * kappa:.10g} 0.0 {gamma:.10g} 0.0 0.0 0\npair_coeff * *",
                       f"fix floor all wall/gran hooke {mass * kappa:.10g} 0.0 {gamma:.10g} 0.0 0.0 0 "
                       "zplane 0.0 NULL"),
        "plugin dry": ("pair_style lubricated/springdashpot\npair_coeff * * 0.9 ncontact 8",
                       "fix floor all wall/lubrication 0.9 ncontact 8 zplane 0.0 NULL"),
        "plugin dry sampled": ("pair_style lubricated/springdashpot\npair_coeff * * 0.9 ncontact 8 integration sampled",
                               "fix floor all wall/lubrication 0.9 ncontact 8 integration sampled zplane 0.0 NULL"),
        "plugin wet": (f"pair_style lubricated/springdashpot\npair_coeff * * 0.9 ncontact 8 {wet}",
                       f"fix floor all wall/lubrication 0.9 ncontact 8 {wet} zplane 0.0 NULL"),
    }


def parse(log):
    loop = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", log)
    seconds, steps, atoms = float(loop[-1][0]), int(loop[-1][1]), int(loop[-1][2])
    pair = re.findall(r"^Pair\s+\|[^|]+\|\s*([0-9.eE+-]+)", log, re.M)
    dangerous = re.findall(r"Dangerous builds = (\d+)", log)
    return dict(ns=seconds / (steps * atoms) * 1e9, pair_s=float(pair[-1]) if pair else float("nan"),
                seconds=seconds, dangerous=int(dangerous[-1]) if dangerous else -1)


def bench(size, steps, repeats, out):
    work = out / f"bed{size}"
    shutil.rmtree(work, ignore_errors=True)
    side = max(10, round(math.sqrt(size / 20)))          # spheres per row: about 20 layers
    layers = math.ceil(size / side ** 2)
    a = 2.1 * R
    fmt = dict(L=side * a, H=(layers + 10) * a * 2, a=a, Hfill=layers * a, d=2 * R, rho=RHO, e=E_DRY,
               nc=NC, skin=R / 2, dt=DT, settle=3000)
    result, _ = lammps_run.run(BUILD.format(**fmt), work, name="in.build", timeout=1800)
    natoms = int(result["atoms"])
    best = {}
    for _ in range(repeats):
        for name, (pair, wall) in styles().items():
            script = RUN.format(pair=pair, wall=wall, skin=R / 2, dt=DT, steps=steps)
            _, log = lammps_run.run(script, work, name="in." + name.replace(" ", "_").replace("/", "_"),
                                    timeout=1800)
            timing = parse(log)
            if name not in best or timing["ns"] < best[name]["ns"]:
                best[name] = timing
    shutil.rmtree(work, ignore_errors=True)
    return natoms, best


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--sizes", type=int, nargs="+", default=[2000, 20000])
    parser.add_argument("--steps", type=int, default=0, help="steps per timing (default: 4e6 particle-steps)")
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--out", default=str(ROOT / "build" / "bench"))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for size in args.sizes:
        steps = args.steps or max(500, int(2e7 / size))
        natoms, best = bench(size, steps, args.repeats, out)
        ref = best["gran/hooke"]["ns"]
        for name, t in best.items():
            rows.append((natoms, name, t["ns"], t["ns"] / ref, t["pair_s"] / t["seconds"], t["dangerous"]))
    lines = [f"# Settling-bed benchmark ({datetime.date.today()}, one rank)", "",
             "Same settled bed, same steps, minimum of interleaved repeats. Targets: plugin dry "
             "<= 1.0 x gran/hooke, plugin wet <= 1.3 x.", "",
             "| spheres | style | ns / particle-step | ratio to gran/hooke | Pair share | dangerous builds |",
             "|---|---|---|---|---|---|"]
    for natoms, name, ns, ratio, share, dangerous in rows:
        lines.append(f"| {natoms} | {name} | {ns:.1f} | {ratio:.2f} | {share:.0%} | {dangerous} |")
    text = "\n".join(lines) + "\n"
    (out / "results.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()

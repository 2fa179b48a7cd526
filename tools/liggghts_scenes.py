"""LIGGGHTS input scripts for the impact scenes of scenes.py (same sphere, speed and film).

The LAMMPS plugin's fix wall/lubrication and pair_coeff keywords map onto LIGGGHTS
properties (src/liggghts/lubricated_properties.h): e_d -> coefficientRestitution (type 2 is
the wall), ncontact -> lubricatedContactSteps, viscosity -> lubricatedViscosity,
activation -> lubricatedActivation, grid -> lubricatedGridSpacing, saturation ->
lubricatedSaturation, legendre -> lubricatedLegendre.
"""
from scenes import EPS_AL, R, RHO, U, WET_DT, pair_bounce_layout, wall_bounce_steps

HEADER = """atom_style granular
atom_modify map array
communicate single vel yes
newton off
units si
"""


def properties(e_dry, mu, ncontact, e_wall=None, friction=None, legendre=0.0, grid=None,
               saturation=None):
    e_wall = e_dry if e_wall is None else e_wall
    text = (f"fix m1 all property/global coefficientRestitution peratomtypepair 2 "
            f"{e_dry} {e_wall} {e_wall} {e_wall}\n"
            f"fix m2 all property/global lubricatedContactSteps scalar {ncontact}\n")
    if mu > 0:
        text += f"fix m3 all property/global lubricatedViscosity scalar {mu}\n"
        if grid:
            text += f"fix m4 all property/global lubricatedGridSpacing scalar {grid}\n"
        else:
            text += f"fix m4 all property/global lubricatedActivation scalar {EPS_AL}\n"
        if saturation:
            text += f"fix m7 all property/global lubricatedSaturation scalar {saturation}\n"
    if legendre:
        text += f"fix m6 all property/global lubricatedLegendre scalar {legendre}\n"
    if friction is not None:
        text += f"fix m5 all property/global coefficientFriction peratomtypepair 2 {' '.join([str(friction)] * 4)}\n"
    return text


def wall_bounce(e_dry, dt_ru=WET_DT, mu=0.0, ncontact=8, gap0=0.2137, model="model lubricated",
                legendre=0.0, grid=None, saturation=None):
    """scenes.wall_bounce in LIGGGHTS: prints RESULT e and RESULT contact_steps."""
    dt = dt_ru * R / U
    steps = wall_bounce_steps(dt_ru, gap0, ncontact)
    return HEADER + f"""boundary p p f
region box block -0.01 0.01 -0.01 0.01 0 0.02 units box
create_box 2 box
neighbor {0.5 * R} bin
neigh_modify delay 0
{properties(e_dry, mu, ncontact, legendre=legendre, grid=grid, saturation=saturation)}
pair_style gran {model}
pair_coeff * *
fix wall all wall/gran {model} primitive type 2 zplane 0.0
create_atoms 1 single 0 0 {R * (1 + gap0)} units box
set atom 1 diameter {2 * R} density {RHO}
velocity all set 0 0 {-U} units box
fix nve all nve/sphere
timestep {dt}
variable overlap equal "z[1] < {R}"
fix count all ave/time 1 1 1 v_overlap mode scalar ave running
thermo_style custom step atoms
thermo {steps}
run {steps}
variable e equal vz[1]/{U}
variable n equal f_count*{steps + 1}
print "RESULT e ${{e}}"
print "RESULT contact_steps ${{n}}"
"""


def pair_bounce(e_dry, mass_ratio=1.0, dt_ru=WET_DT, mu=0.0, ncontact=8, gap0=0.2137,
                radius_ratio=1.0, x_offset=0.0, skin=0.5 * R, model="model lubricated", legendre=0.0,
                grid=None, saturation=None):
    """scenes.pair_bounce in LIGGGHTS: two spheres head-on along x, centre-of-mass frame."""
    dt = dt_ru * R / U
    r2, rho2, x1, x2, v1, v2, half, steps = pair_bounce_layout(
        mass_ratio, dt_ru, ncontact, gap0, radius_ratio, x_offset)
    return HEADER + f"""boundary p p p
region box block -{half} {half} -{half} {half} -{half} {half} units box
create_box 2 box
neighbor {skin} bin
neigh_modify delay 0
{properties(e_dry, mu, ncontact, legendre=legendre, grid=grid, saturation=saturation)}
pair_style gran {model}
pair_coeff * *
create_atoms 1 single {x1} 0 0 units box
create_atoms 1 single {x2} 0 0 units box
set atom 1 diameter {2 * R} density {RHO}
set atom 2 diameter {2 * r2} density {rho2}
velocity all set 0 0 0 units box
set atom 1 vx {v1}
set atom 2 vx {v2}
fix nve all nve/sphere
timestep {dt}
variable overlap equal "(x[2]-x[1]) < {R + r2}"
fix count all ave/time 1 1 1 v_overlap mode scalar ave running
thermo_style custom step atoms
thermo {steps}
run {steps}
variable e equal (vx[2]-vx[1])/{U}
variable n equal f_count*{steps + 1}
print "RESULT e ${{e}}"
print "RESULT contact_steps ${{n}}"
"""


HOLDS = {
    "freeze": "fix nve all nve/sphere\nfix hold base freeze",
    "unintegrated": "fix nve mover nve/sphere",
    "move": "fix nve mover nve/sphere\nfix hold base move linear 0 0 0",
    "setforce": "fix nve all nve/sphere\nfix hold base setforce 0.0 0.0 0.0",
    "free": "fix nve all nve/sphere",
}


def frozen_pair(e_dry, mu=0.0, dt_ru=0.005, gap0=0.2137, steps=300, frozen=True, hold=None):
    """Atom 1 moving at U along x towards atom 2, held as `hold` (HOLDS; frozen=True: fix
    freeze, False: free); the contact at x = 0 (the boundary between 2 ranks). RESULT e:
    separation / approach speed (test_frozen_partners.frozen_pair of the LAMMPS tests, in
    LIGGGHTS syntax)."""
    half = 0.01
    hold = HOLDS[hold or ("freeze" if frozen else "free")]
    return HEADER + f"""boundary p p p
region box block -{half} {half} -{half} {half} -{half} {half} units box
create_box 1 box
neighbor {0.5 * R} bin
neigh_modify delay 0
{properties(e_dry, mu, 8, e_wall=e_dry).replace("peratomtypepair 2", "peratomtypepair 1").replace(
        f" {e_dry} {e_dry} {e_dry}", "")}
pair_style gran model lubricated
pair_coeff * *
create_atoms 1 single {-R - 0.5 * gap0 * R} 0 0 units box
create_atoms 1 single {R + 0.5 * gap0 * R} 0 0 units box
set group all diameter {2 * R} density {RHO}
group mover id 1
group base id 2
velocity all set 0 0 0 units box
velocity mover set {U} 0 0 units box
{hold}
timestep {dt_ru * R / U}
thermo {steps}
run {steps}
variable e equal (vx[2]-vx[1])/{U}
variable v2 equal vx[2]
print "RESULT e ${{e}}"
print "RESULT v2 ${{v2}}"
"""


def rigid_body_hit(e_dry, mu=0.0):
    """A body of two spheres 2.2 R apart on the x axis (fix rigid single), struck head-on by a
    third sphere at U (test_frozen_partners.rigid_scene of the LAMMPS tests). RESULT e:
    separation / approach speed."""
    half = 0.01
    return HEADER + f"""boundary p p p
region box block -{half} {half} -{half} {half} -{half} {half} units box
create_box 1 box
neighbor {0.5 * R} bin
neigh_modify delay 0
{properties(e_dry, mu, 8).replace("peratomtypepair 2", "peratomtypepair 1").replace(
        f" {e_dry} {e_dry} {e_dry}", "")}
pair_style gran model lubricated
pair_coeff * *
create_atoms 1 single {-1.1 * R} 0 0 units box
create_atoms 1 single {1.1 * R} 0 0 units box
create_atoms 1 single {3.3 * R} 0 0 units box
set group all diameter {2 * R} density {RHO}
group mover id 1
group body id 2 3
velocity all set 0 0 0 units box
velocity mover set {U} 0 0 units box
fix nve mover nve/sphere
fix body body rigid single
timestep {0.005 * R / U}
thermo 300
run 300
variable e equal (vx[2]-vx[1])/{U}
print "RESULT e ${{e}}"
"""

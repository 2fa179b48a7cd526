"""The wet polydisperse chain of tests/lammps/scene_chain.py in LIGGGHTS syntax: a row of
spheres of two sizes along x between two walls, alternately moving towards each other, so
that collisions and films straddle x = 0, the boundary between the ranks of a 2 x 1 x 1 grid."""
import scenes
from liggghts_scenes import HEADER
from scene_chain import chain_layout

R = scenes.R


def chain_atoms():
    return "\n".join(
        f"create_atoms 1 single {x} {y} 0 units box\n"
        f"set atom {k + 1} diameter {2 * radius} density {scenes.RHO}\n"
        f"set atom {k + 1} vx {vx} vy {0.01 * (k - 3)}"
        for k, (x, y, radius, vx) in enumerate(chain_layout()))


def setup(tangential="history"):
    mu = scenes.viscosity_for_stokes(100)
    return f"""fix m1 all property/global coefficientRestitution peratomtypepair 2 0.8 0.7 0.7 0.7
fix m2 all property/global coefficientFriction peratomtypepair 2 0.4 0.4 0.4 0.4
fix m3 all property/global lubricatedContactSteps scalar 8
fix m4 all property/global lubricatedViscosity scalar {mu}
fix m5 all property/global lubricatedActivation scalar 0.09375
fix lo all wall/gran model lubricated tangential {tangential} primitive type 2 xplane -0.008
fix hi all wall/gran model lubricated tangential {tangential} primitive type 2 xplane 0.008
fix nve all nve/sphere
timestep {0.005 * R / scenes.U}
thermo_style custom step ke
thermo 100
neighbor {0.3 * R} bin
neigh_modify delay 0
"""


def chain(steps=600, extra_run="", tangential="history", processors=""):
    return HEADER + f"""boundary f p p
{processors}
region box block -0.008 0.008 -0.003 0.003 -0.003 0.003 units box
create_box 2 box
pair_style gran model lubricated tangential {tangential}
pair_coeff * *
{chain_atoms()}
{setup(tangential)}
run {steps}
{extra_run}
"""


def dump_state(n_atoms=8):
    """Every atom's position, velocity and spin as RESULT lines (20 digits)."""
    lines = []
    for k in range(1, n_atoms + 1):
        for name, a in (("x", "x y z"), ("v", "vx vy vz"), ("w", "omegax omegay omegaz")):
            values = " ".join(f"$({q}[{k}])" for q in a.split())
            lines.append(f'print "RESULT {name}{k} {values}"')
    return "\n".join(lines) + "\n"

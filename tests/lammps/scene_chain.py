"""A small wet, polydisperse many-body scene for MPI and restart checks: a row of spheres
of two sizes along x, alternately moving towards each other, so that several collisions
(and films) straddle x = 0, the boundary between the two ranks of a 2 x 1 x 1 grid."""

import scenes

R = scenes.R


def chain_layout():
    """(x, y, radius, vx) of the 8 spheres (shared with the LIGGGHTS chain); vy = 0.01 (k - 3)."""
    pos = []
    x = -6.68 * R
    for k in range(8):
        radius = R if k % 2 == 0 else 0.6 * R
        x += radius
        pos.append((x, 0.05 * R * (k % 3), radius, 0.1 if k % 2 == 0 else -0.1))
        x += radius + 0.07 * R
    return pos


def chain(newton="on", steps=600, extra_run=""):
    pos = chain_layout()
    atoms = "\n".join(
        f"create_atoms 1 single {px} {py} 0\nset atom {k + 1} diameter {2 * rad} density {scenes.RHO}\n"
        f"set atom {k + 1} vx {vx} vy {0.01 * (k - 3)}"
        for k, (px, py, rad, vx) in enumerate(pos))
    mu = scenes.viscosity_for_stokes(100)
    dt = 0.005 * R / scenes.U
    return scenes.HEADER.replace("${newton}", newton) + f"""
boundary f p p
region box block -0.008 0.008 -0.003 0.003 -0.003 0.003
create_box 1 box
{atoms}
pair_style lubricated/springdashpot
pair_coeff * * 0.8 ncontact 8 viscosity {mu} activation 0.09375
fix walls all wall/lubrication 0.7 viscosity {mu} grid 1.25e-4 xplane -0.008 0.008
fix nve all nve/sphere
timestep {dt}
thermo 100
thermo_style custom step ke pe f_walls
neighbor {0.3 * R} bin
run {steps}
{extra_run}
"""


def dump_state(n_atoms=8):
    """Input lines that print every atom's position and velocity as RESULT lines."""
    lines = []
    for k in range(1, n_atoms + 1):
        lines.append(f'print "RESULT x{k} $(x[{k}]:%.17g) $(y[{k}]:%.17g) $(z[{k}]:%.17g)"')
        lines.append(f'print "RESULT v{k} $(vx[{k}]:%.17g) $(vy[{k}]:%.17g) $(vz[{k}]:%.17g)"')
    return "\n".join(lines) + "\n"

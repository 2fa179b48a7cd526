"""Unit styles (issue 18). The styles compute forces as masses times accelerations and energies as
masses times velocities squared, with no conversion factor: right in the unit styles where
LAMMPS's ftm2v and mvv2e are 1 (lj, si, cgs, micro, nano), so the same dimensionless scene must
give the same numbers in each of them; refused with an ERROR in the others (real, metal,
electron), where the forces would be off by those factors (src/unit_style/unit_style.h).

The scene, in R = 1, rho = 1, U = 1 of whatever unit style: a sphere hitting a wet frictional
wall obliquely with spin, two spheres colliding off-centre in the film with friction, rolling
and the wet-restitution law, everything in a Stokes drag with buoyancy; 300 steps of dt = 0.005
(contact and film both act). The results are the same floating-point operations on the same
numbers, so they agree to rounding; 1e-10 leaves room for nothing but that.
"""
import pytest

SUPPORTED = ["lj", "si", "cgs", "micro", "nano"]
REFUSED = ["real", "metal", "electron"]

HEADER = """plugin load ${{plugin}}
units {units}
atom_style sphere
atom_modify map array
boundary p p f
comm_modify vel yes
region box block -8 8 -8 8 0 16
create_box 2 box
create_atoms 1 single 0 0 1.3
create_atoms 2 single 4 0 5
create_atoms 2 single 6.4 0.3 5
set group all diameter 2 density 1
velocity all set 0 0 0 units box
set atom 1 vx 0.3 vz -1 omega 0 0.4 0.1
set atom 2 vx 1 omega 0 0 0.5
set atom 3 vx -1 vy 0.1
neighbor 0.2 bin
neigh_modify delay 0 every 1 check yes
timestep 0.005
"""

STYLES = """pair_style lubricated/springdashpot
pair_coeff * * 0.8 ncontact 8 viscosity 0.01 activation 0.1 friction 0.3 rolling 0.02 legendre 35
fix wall all wall/lubrication 0.7 ncontact 8 viscosity 0.01 activation 0.1 friction 0.3 rolling 0.02 zplane 0 NULL
fix drag all fluid/drag viscosity 0.001 density 0.5 buoyancy 0 0 -0.1
fix nve all nve/sphere
"""

QUANTITIES = ["x[1]", "z[1]", "vx[1]", "vz[1]", "c_wy1", "vx[2]", "vy[2]", "c_wz2", "vx[3]", "vy[3]", "c_wz3",
              "f_wall", "f_wall[3]"]


def scene(units):
    values = " ".join(f"$({q}:%.17g)" for q in QUANTITIES)
    # Spins of single atoms: per-atom values reduced over a group of one (thermo keeps them current).
    return HEADER.format(units=units) + STYLES + f"""compute w all property/atom omegay omegaz
group a1 id 1
group a2 id 2
group a3 id 3
compute wy1 a1 reduce sum c_w[1]
compute wz2 a2 reduce sum c_w[2]
compute wz3 a3 reduce sum c_w[2]
thermo_style custom step c_wy1 c_wz2 c_wz3
thermo 100
run 300
print "RESULT state {values}"
"""


def test_the_same_scene_gives_the_same_numbers_in_every_supported_unit_style(lmp):
    states = {units: lmp(scene(units))["state"] for units in SUPPORTED}
    reference = states["si"]
    # The scene does what it is for: the wall sphere bounced (moving up), the pair collided.
    assert reference[QUANTITIES.index("vz[1]")] > 0.0
    assert reference[QUANTITIES.index("vx[2]")] < 0.0 < reference[QUANTITIES.index("vx[3]")]
    for units, state in states.items():
        for name, value, ref in zip(QUANTITIES, state, reference):
            assert value == pytest.approx(ref, rel=1e-10, abs=1e-12), (units, name)


COMMANDS = {
    "pair": STYLES.splitlines()[0],
    "wall": "fix wall all wall/lubrication 0.7 zplane 0 NULL",
    "drag": "fix drag all fluid/drag viscosity 0.001",
    "midpoint": "fix nve all nve/sphere/midpoint",
}
STYLE_NAMES = {"pair": "lubricated/springdashpot", "wall": "Fix wall/lubrication", "drag": "Fix fluid/drag",
               "midpoint": "nve/sphere/midpoint"}


@pytest.mark.parametrize("units", REFUSED)
@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_unit_styles_with_conversion_factors_are_refused(lmp, units, command):
    lmp(HEADER.format(units=units) + COMMANDS[command] + "\nrun 1\n", check=False)
    error = next((line for line in lmp.log.splitlines() if "ERROR" in line), None)
    assert error is not None, lmp.log[-1500:]
    assert f"does not support units {units}" in error and STYLE_NAMES[command] in error, error
    assert "supported: lj, si, cgs, micro, nano" in error

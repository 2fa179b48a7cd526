"""The contact-network check counts the walls of fix wall/lubrication and
fix wall/lubrication/region (lubricated/contact_network.h: a wall is a partner of infinite
mass; its sustained contacts join the sums of their sphere).

Without them a sphere pressed between two walls at N_c = 2 (load s = 3 - e_d^(2/N_c) = 2.1 per
contact, two collinear contacts: a mode with 2 s = 4.2 >= 4 that grows every step) was lost
within 2000 steps without a word, and a 6 mm sphere resting on a 2 mm one on a floor (the pair
contact's quotient s (1 + m_e/m_1) = 4.12 once the floor counts, as it does on a held sphere)
gained energy silently.
"""
import pytest

import lammps_run

SQUEEZE = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary p p f
comm_modify vel yes
region box block -0.01 0.01 -0.01 0.01 0 0.02
create_box 1 box
create_atoms 1 single 0 0 0.001
set atom 1 diameter 0.002 density 2500
velocity all set 0 0 0
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact {nc}
{walls}
fix nve all nve/sphere
timestep 1e-5
thermo 100
run 1000
print "RESULT z $(z[1]:%.12g) $(ke:%.6g)"
"""
PLANES = "fix floor all wall/lubrication 0.9 ncontact {nc} zplane 5e-6 0.001995"
REGION = ("region cell block INF INF INF INF 5e-6 0.001995 units box\n"
          "fix floor all wall/lubrication/region 0.9 cell ncontact {nc}")

STACK = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block -0.01 0.01 -0.01 0.01 0 0.03
create_box 1 box
create_atoms 1 single 0 0 0.001 units box
create_atoms 1 single 0 0 0.005 units box
set atom 1 diameter 2e-3 density 2500
set atom 2 diameter 6e-3 density 2500
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact {nc}
fix floor all wall/lubrication 0.9 ncontact {nc} zplane 0.0 NULL
fix g all gravity 9.81 vector 0 0 -1
fix nve all nve/sphere
timestep 1e-5
thermo 1000
run 4000
print "RESULT z $(z[1]:%.12g) $(z[2]:%.12g)"
"""


def scene(template, nc, walls=""):
    return template.replace("{walls}", walls.replace("{nc}", str(nc))).replace("{nc}", str(nc))


@pytest.mark.parametrize("walls,named", [(PLANES, "the walls of fix floor (wall/lubrication)"),
                                         (REGION, "the walls of fix floor (wall/lubrication/region)")])
def test_a_sphere_pressed_between_two_walls(lmp, walls, named):
    with pytest.raises(lammps_run.LammpsError) as err:
        lmp(scene(SQUEEZE, 2, walls))
    message = str(err.value)
    assert "type 1 and " + named in message and "ncontact = 2 is too short" in message
    assert "atom 1 (2 contacts)" in message and "load 4.2 >= 4" in message
    assert "Lost atoms" not in err.value.log
    # N_c = 3: 2 s = 2 (3 - 0.9^(2/3) - 2 0.9^(1/3) cos(pi/3)) = 2.39 < 4, stable: no message, at rest.
    z, ke = lmp(scene(SQUEEZE, 3, walls))["z"]
    assert "contact network" not in lmp.log and "too short" not in lmp.log
    assert z == pytest.approx(0.001, abs=1e-12) and ke < 1e-20


@pytest.mark.parametrize("nprocs", [1, 2])
def test_a_heavy_sphere_on_a_light_one_on_a_floor(lmp, nprocs):
    with pytest.raises(lammps_run.LammpsError) as err:
        lmp(scene(STACK, 2), nprocs=nprocs)
    assert "ncontact = 2 is too short a contact for this packing" in str(err.value)
    assert "load 4.12 >= 4" in str(err.value)
    # N_c = 8: the floor counted, the stack is checked and stable: no message.
    z1, z2 = lmp(scene(STACK, 8), nprocs=nprocs)["z"]
    assert "contact network" not in lmp.log and "too short" not in lmp.log
    assert 0.0009 < z1 < 0.001 and 0.0049 < z2 < 0.005


WET = "viscosity 10.0 activation 0.2"


def wet_and_solved(text):
    """The scene wet (pairs and walls, mu_f 10 Pa s) under limit implicit."""
    text = text.replace("pair_style lubricated/springdashpot\n", "pair_style lubricated/springdashpot limit implicit\n")
    text = text.replace("pair_coeff * * 0.9 ncontact 2", f"pair_coeff * * 0.9 ncontact 2 {WET}")
    text = text.replace("0.9 ncontact 2 zplane", f"0.9 ncontact 2 {WET} zplane").replace("cell ncontact 2", f"cell ncontact 2 {WET}")
    assert text.count(WET) == 2 and "limit implicit" in text
    return text


@pytest.mark.parametrize("walls", [PLANES, REGION, ""])
def test_wet_walls_in_the_solve_relieve_their_contacts(lmp, walls):
    """The two scenes above at N_c = 2, wet, under limit implicit: the walls' films of the sphere
    over budget are solved with the pairs' and act on the step's end velocity, so each wall
    contact counts with its relieved load (doc/film_solve.rst, "The contacts' network with the
    films in the solve"): no ERROR (dry, and before the walls' films were counted: the ERRORs
    above). The squeezed sphere, started at 0.01 m/s, comes to rest at the middle; the stack
    settles on the floor."""
    template = STACK if not walls else SQUEEZE.replace("velocity all set 0 0 0", "velocity all set 0 0 0.01")
    result = lmp(wet_and_solved(scene(template, 2, walls)))["z"]
    assert "contact network" not in lmp.log and "too short" not in lmp.log and "(limit implicit)" in lmp.log
    if walls:
        z, ke = result
        assert z == pytest.approx(0.001, abs=1e-9) and ke < 1e-20
    else:
        z1, z2 = result
        assert 0.0009 < z1 < 0.001 and 0.0049 < z2 < 0.005

"""Fixes that add or remove atoms during a run (fix evaporate, fix deposit) leave the contact
history of the other spheres alone, wherever they stand in the input script.

The pair style keeps the tangential history in a fix of its own. It held no place in the fix
list until the first run, so fixes defined before that run (the usual order: pair style, fix
deposit, run) came first in each step's pre_exchange: they removed or inserted atoms, and the
history was then stored from the list with indices that named other atoms (the bed's spins off
by 0.2-10 %). Now the pair style holds the history's place from its definition (a placeholder
fix, as LAMMPS's granular styles do).

The scene: 256 wet frictional spheres (radius 1 mm) on an fcc lattice in overlap, random
velocities, no gravity, and two spheres 9 mm above the bed that never touch anything; fix
evaporate removes them, or fix deposit inserts spheres far above the bed. Neither touches the
bed, whose spin must be the run's without the fix (different atom counts reorder sums: 1e-9).
"""
import pytest

SCENE = """plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary p p f
comm_modify vel yes
lattice fcc 0.002822770270496698
region box block 0 4 0 4 -0.5 12
create_box 1 box
region bed block 0 4 0 4 0 3.9
create_atoms 1 region bed
create_atoms 1 single 0.002 0.002 0.02 units box
create_atoms 1 single 0.008 0.008 0.02 units box
set group all diameter 0.002 density 2500
group bed region bed
velocity bed create 1.0 4821 dist gaussian mom yes rot no loop geom
velocity bed scale 2.5e13
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact 8 viscosity 0.001 activation 0.1 friction 0.3 rolling 0.02
neighbor 0.0002 bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep 1e-6
compute spin bed erotate/sphere
thermo_modify lost error
thermo 100
{fix}
run 400
print "RESULT bed $(c_spin:%.17g) $(atoms)"
"""

EVAPORATE = "region above block 0 0.011 0 0.011 0.018 0.024 units box\nfix gone all evaporate 100 1 above 4321"
MOLECULE = "# one sphere\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.0008\n\nMasses\n\n1 6.702e-07\n"
DEPOSIT = ("molecule ball {dir}/ball.mol\nregion top block 0.0005 0.0105 0.0005 0.0105 0.03 0.033 units box\n"
           "fix add all deposit 20 0 50 99 region top near 0.0015 mol ball")


@pytest.mark.parametrize("nprocs", [1, 2])
def test_atoms_removed_or_added_away_from_the_bed_leave_its_contacts_alone(lmp, nprocs):
    (lmp.dir / "ball.mol").write_text(MOLECULE)
    alone = lmp(SCENE.format(fix=""), nprocs=nprocs)["bed"]
    assert alone[0] > 0.0 and alone[1] == 258
    for fix, atoms in ((EVAPORATE, 256), (DEPOSIT.format(dir=lmp.dir), 258 + 8)):
        for where in ("before the first run", "after a run 0"):
            text = SCENE.format(fix=fix if where.startswith("before") else "run 0\n" + fix)
            bed = lmp(text, nprocs=nprocs)["bed"]
            assert bed[1] == atoms, (fix, where)
            assert bed[0] == pytest.approx(alone[0], rel=1e-9, abs=0.0), (fix, where)

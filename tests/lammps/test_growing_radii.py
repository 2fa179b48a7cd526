"""Spheres whose radii grow during a run (fix adapt diameter): the pair style's cutoffs come from
the largest radius of each type at the run's setup (pair_lubricated_springdashpot.cpp init_one),
or from `pair_coeff ... cutoff`; at each neighbor build it takes the radii as they are
(pair_lubricated_springdashpot_list.cpp follow_radii): the films' reach follows them, and a type
pair whose contact and film distance outgrows its cutoff stops the run with an error, where its
pairs would otherwise be missed without a word (a wet list with the setup's cutoff never listed
the pair below, which ended the run 0.1 mm in overlap without a force).

The scene: two spheres of diameter 2 mm, centres 2.5 mm apart (across the boundary of two ranks
on 2), growing by 0.2 um a step and approaching at 2 mm/s: their film acts from a gap of 0.094
mm (grid) or 0.1 R (eps_al = 0.1, a reach that grows with R: 0.119 mm when they get there,
0.1 mm at the setup's radii), then their contact, which pushes them apart; a third sphere of
the same type 4.5 mm away takes no part. 3000 steps (to 2.6 mm), the list rebuilt every step. The reference: the same run with the third
sphere of diameter 3 mm, so that the setup's radii already cover the growth. Both runs list the
pair at every step and compute it the same way: they agree to the bit, on 1 and 2 ranks. Caught:
a film reach left at the setup's radii (eps_al: the film between gaps of 0.119 and 0.1 mm
missed), no error (the error tests), a restart file without the cutoff.
"""
import pathlib
import re

import pytest

import dense_scenes

SCENE = """plugin load ${{plugin}}
units si
atom_style sphere 1
atom_modify map array
boundary p p p
comm_modify vel yes
processors {nprocs} 1 1
region box block 0 0.02 0 0.02 0 0.02
create_box 1 box
create_atoms 1 single 0.0085 0.01 0.01
create_atoms 1 single 0.011 0.01 0.01
create_atoms 1 single 0.0155 0.01 0.01
set atom * density 2500
set atom 1*2 diameter 0.002
set atom 3 diameter {third}
group growing id 1 2
velocity growing set NULL NULL NULL
set atom 1 vx 0.001
set atom 2 vx -0.001
variable d equal 0.002+2e-7*step
fix grow growing adapt 1 atom diameter v_d
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact 8 {coefficients}
neighbor 0.0002 bin
neigh_modify delay 0 every 1 check no
fix nve all nve/sphere
timestep 1.25e-05
thermo 1000
run {steps}
print "RESULT pair $(x[1]:%.17g) $(x[2]:%.17g) $(vx[1]:%.17g) $(vx[2]:%.17g) $(vy[1]:%.17g)"
print "RESULT third $(x[3]:%.17g) $(vx[3]:%.17g)"
"""

CASES = {
    "dry": "",
    "wet grid": "viscosity 1e-3 grid 1.25e-4",
    # a fixed eps_al: the film's reach 0.1 R grows with the radii
    "wet activation": "viscosity 1e-3 activation 0.1",
    "wet friction": "viscosity 1e-3 grid 1.25e-4 friction 0.3",
}


def scene(coefficients, third=0.002, nprocs=1, steps=3000):
    return SCENE.format(coefficients=coefficients, third=third, nprocs=nprocs, steps=steps)


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("case", CASES)
def test_growing_spheres_meet_as_if_their_radii_were_known(lmp, case, nprocs):
    grown = lmp(scene(CASES[case] + " cutoff 0.003", nprocs=nprocs), nprocs=nprocs)
    known = lmp(scene(CASES[case], third=0.003, nprocs=nprocs), nprocs=nprocs)
    x1, x2, vx1, vx2, _ = grown["pair"]
    assert vx1 < -1e-3 and vx2 > 1e-3    # they met and were pushed apart
    assert x2 - x1 > 2.5e-3
    assert grown["third"] == [0.0155, 0.0]
    assert grown == known


@pytest.mark.parametrize("case", ["dry", "wet grid"])
def test_growing_past_the_cutoff_is_an_error(lmp, case):
    lmp(scene(CASES[case]), check=False)
    errors = [line for line in lmp.log.splitlines() if line.startswith("ERROR")]
    assert errors, lmp.log[-1500:]
    assert "types 1 1: spheres of radius 0.0010001 and 0.0010001 need a cutoff of" in errors[0]
    assert "from the radii at its setup" in errors[0]
    assert "pair_coeff 1 1 ... cutoff" in errors[0] and "check no" in errors[0]
    # stopped at the first build after the spheres outgrew the setup's, long before step 1000
    assert not re.search(r"^\s+1000\s", lmp.log, re.M)


def test_a_cutoff_too_short_for_the_growth_is_an_error(lmp):
    lmp(scene(CASES["wet grid"] + " cutoff 0.0024"), check=False)
    errors = [line for line in lmp.log.splitlines() if line.startswith("ERROR")]
    assert errors and "beyond this run's 0.0024 (pair_coeff cutoff)" in errors[0], lmp.log[-1500:]


# The rest of the run of scene() after a file written at step 0 was read back (`load`: the
# commands that read it).
GROW_ON = """group growing id 1 2
variable d equal 0.002+2e-7*step
fix grow growing adapt 1 atom diameter v_d
neighbor 0.0002 bin
neigh_modify delay 0 every 1 check no
fix nve all nve/sphere
timestep 1.25e-05
run 3000
print "RESULT pair $(x[1]:%.17g) $(x[2]:%.17g) $(vx[1]:%.17g) $(vx[2]:%.17g) $(vy[1]:%.17g)"
print "RESULT third $(x[3]:%.17g) $(vx[3]:%.17g)"
"""


def written_at_start(lmp, command):
    """The grid case with its cutoff, written by `command` at step 0 (the whole run returned)."""
    whole = lmp(scene(CASES["wet grid"] + " cutoff 0.003"))
    first = scene(CASES["wet grid"] + " cutoff 0.003", steps=0)
    lmp(first.replace('print "RESULT pair', f'{command}\nprint "RESULT pair'))
    return whole


def test_cutoff_survives_a_restart_file(lmp):
    """The cutoff is written with each type pair's coefficients (restart flag bit 3): a run read
    from the file lets the spheres grow, as the run that wrote it would."""
    whole = written_at_start(lmp, f"write_restart {lmp.dir}/grow.restart")
    restarted = lmp(f"plugin load ${{plugin}}\nread_restart {lmp.dir}/grow.restart\ncomm_modify vel yes\n" + GROW_ON)
    assert restarted == whole


def test_cutoff_survives_write_data(lmp):
    """write_data writes each type pair's pair_coeff words with its cutoff (PairIJ Coeffs), which
    read_data gives back: the spheres then grow as in the run that wrote the file."""
    whole = written_at_start(lmp, f"write_data {lmp.dir}/grow.data pair ij")
    assert "cutoff 0.0030000000000000001" in (lmp.dir / "grow.data").read_text()
    read = lmp(f"""plugin load ${{plugin}}
units si
atom_style sphere 1
atom_modify map array
boundary p p p
comm_modify vel yes
pair_style lubricated/springdashpot
read_data {lmp.dir}/grow.data
""" + GROW_ON)
    assert read == whole


# A dense bed that grows: the random 1:10 packing of solid fraction 0.61
# (tests/lammps/dense_packings/p61.data, 300 spheres of radii 0.1-1 mm, periodic), wet (eps_al =
# 0.1) with friction, random velocities (each component uniform in +-0.1 m/s), every diameter scaled by 1 + 5e-5 step
# (2 % in 400 steps of 1e-6 s, overlaps growing by up to 20 um: about 900 pairs listed),
# the list rebuilt every step, cutoff 2.3 mm (2 x 1.02 mm and the film's reach, 0.1 R).
BED = """plugin load ${{plugin}}
units si
atom_style sphere 1
atom_modify map array
boundary p p p
comm_modify vel yes
read_data {data}
{velocities}
variable s equal 1+5e-5*step
fix grow all adapt 1 atom diameter v_s scale yes
pair_style lubricated/springdashpot trim {trim}
pair_coeff * * 0.9 ncontact 8 viscosity 1e-3 activation 0.1 friction 0.3{cutoff}
neighbor 2e-5 bin
neigh_modify delay 0 every 1 check no
fix nve all nve/sphere
timestep 1e-6
compute rot all erotate/sphere
thermo_style custom step atoms ke c_rot pe
thermo_modify lost error norm no
thermo 100
{run}
print "RESULT final $(ke:%.17g) $(c_rot:%.17g) $(pe:%.17g) $(atoms)"
print "RESULT some $(x[1]:%.17g) $(vx[77]:%.17g) $(radius[77]:%.17g) $(z[250]:%.17g)"
"""
DATA = pathlib.Path(__file__).resolve().parent / "dense_packings" / "p61.data"


def bed(trim="yes", cutoff=" cutoff 0.0023", run="run 400"):
    return BED.format(data=DATA, trim=trim, cutoff=cutoff, run=run, velocities=dense_scenes.hashed_velocities(0.1))


def test_a_growing_dense_bed(lmp):
    """The bed's pairs as the two spheres' above: the trimmed list keeps every pair the grown
    radii bring within reach (trim yes = no, to the bit), 2 ranks give the run of 1 (relative
    1e-8), a run continued with `run N pre no` is the same run to the bit, no atom is lost, and
    without the cutoff the first build after the largest spheres grew stops it. (A new run's set-up
    makes fix adapt's `scale yes` start again from the radii then, LAMMPS's rule: runs split
    otherwise grow differently, whatever the pair style.)"""
    trimmed = lmp(bed())
    assert trimmed["final"][3] == 300
    assert trimmed["some"][2] == pytest.approx(1.02 * 0.5 * 0.001132557351274878, rel=1e-12)    # grown 2 %
    assert lmp(bed(trim="no")) == trimmed
    assert lmp(bed(run="run 200\nrun 200 pre no")) == trimmed
    two = lmp(bed(), nprocs=2)
    for key in trimmed:
        assert two[key] == pytest.approx(trimmed[key], rel=1e-8), key
    lmp(bed(cutoff=""), check=False)
    errors = [line for line in lmp.log.splitlines() if line.startswith("ERROR")]
    assert errors and "need a cutoff of" in errors[0], lmp.log[-1500:]

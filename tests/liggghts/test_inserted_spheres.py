"""lubricatedGridSpacing with spheres inserted during a run (fix insert/pack): the film reaches
0.75 dx whatever the radius, which the model turns into a contact distance factor of the
smallest radius. That radius was taken at the run's start only: a smaller sphere inserted later
got a film cut at factor * r (a rebound of 0.529 instead of 0.503 on a wet floor) and skipped
the check eps_al = 0.75 dx / R <= 1. Now the factor follows the smallest radius at every
neighbor list build, before the build."""
import pytest


def scene(parked_diameter, inserted_radius=2e-4, skin=3e-4):
    """One sphere (radius inserted_radius) inserted at the first step 0.4 mm or less above a wet
    floor, falling at 0.5 m/s; a sphere of parked_diameter rests far from it from the start (not
    integrated). RESULT e: the rebound's speed / 0.5 after 6000 steps."""
    return f"""atom_style granular
atom_modify map array
communicate single vel yes
newton off
units si
boundary p p f
region box block 0 0.01 0 0.01 0 0.01 units box
create_box 3 box
neighbor {skin} bin
neigh_modify delay 0
fix m1 all property/global coefficientRestitution peratomtypepair 3 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9
fix m3 all property/global lubricatedContactSteps scalar 8
fix m4 all property/global lubricatedViscosity scalar 1.1e-3
fix m5 all property/global lubricatedGridSpacing scalar 2e-4
pair_style gran model lubricated
pair_coeff * *
fix floor all wall/gran model lubricated primitive type 3 zplane 0.0
create_atoms 1 single 0.001 0.001 0.008 units box
set atom 1 diameter {parked_diameter} density 2500
group parked id 1
group mobile subtract all parked
fix pts all particletemplate/sphere 15485863 atom_type 2 density constant 2500 radius constant {inserted_radius}
fix pdd all particledistribution/discrete 32452843 1 pts 1.0
region insreg block 0.003 0.007 0.003 0.007 0.0010 0.0016 units box
fix ins mobile insert/pack seed 32452867 distributiontemplate pdd maxattempt 100 insert_every once &
    overlapcheck yes all_in no vel constant 0 0 -0.5 region insreg particles_in_region 1
fix nve mobile nve/sphere
timestep 1e-6
compute vmax mobile reduce max vz
variable v equal c_vmax
thermo_style custom step atoms c_vmax
thermo 1000
run 6000
print "RESULT e $(v_v/0.5)"
"""


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("skin", [3e-4, 1e-3])
def test_inserted_sphere_has_the_film_of_one_present_from_the_start(run, nprocs, skin):
    """The inserted sphere rebounds from the wet floor as when a sphere of its size rests
    elsewhere from the start (the run-start factor then covers it): the same e to round-off;
    a 2 mm sphere at the start instead left it a film cut at 0.17 r (e 0.529 against 0.503)."""
    small = run.lig(scene(4e-4, skin=skin), nprocs=nprocs)["e"]
    assert "appeared" not in run.log
    big = run.lig(scene(2e-3, skin=skin), nprocs=nprocs, name="in.big")["e"]
    assert "a sphere of radius 0.0002 appeared (the smallest at the run's start: 0.001)" in run.log
    assert 0.4 < small < 0.6
    assert big == pytest.approx(small, rel=1e-12, abs=0.0)


def test_inserted_sphere_too_small_for_the_grid_stops(run):
    """eps_al = 0.75 dx / R <= 1 holds for the spheres inserted during a run too: an ERROR naming
    the radius, the run-start smallest radius and the property."""
    run.lig(scene(2e-3, inserted_radius=1e-4), check=False)
    error = next((line for line in run.log.splitlines() if line.startswith("ERROR")), "")
    assert "a sphere of radius 0.0001 appeared during the run (the smallest at its start: 0.001)" in error, error
    assert "lubricatedGridSpacing = 0.0002 gives eps_al = 0.75 dx / R = 1.5" in error, error
    assert "Use a smaller lubricatedGridSpacing, or lubricatedActivation" in error, error

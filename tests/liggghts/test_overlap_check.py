"""The overlap check of model lubricated in LIGGGHTS (src/lubricated/overlap_check.h; doc/model.rst,
"Overlap check"), as in the LAMMPS plugin (tests/lammps/test_overlap_check.py): a contact whose
overlap exceeds 0.1 of the smaller radius (a wall: the sphere's) warns once per run, one beyond
0.5 once more; the WARNING names the contact, t_c and N_c, and the lubricatedContactTime (or the
time step with lubricatedContactSteps) that would keep it below. A documented contact is silent.
"""
import pytest

from liggghts_scenes import HEADER

R, U, RHO, DT = 1.0e-3, 0.1, 2500.0, 1.0e-4


def impact(kind, contact, steps=600, runs=1):
    """A 1 mm sphere onto a plane wall (type 2) or two head-on at U, e_d 0.9; contact: the
    property line that sets t_c (lubricatedContactTime or lubricatedContactSteps). Each run
    launches the impact again."""
    if kind == "wall":
        atoms = f"create_atoms 1 single 0 0 {1.2 * R!r} units box"
        launch = f"set atom 1 z {1.2 * R!r}\nvelocity all set 0 0 {-U!r} units box"
        wall = "fix floor all wall/gran model lubricated primitive type 2 zplane 0.0"
    else:
        atoms = (f"create_atoms 1 single 0 0 {1.1 * R!r} units box\n"
                 f"create_atoms 1 single 0 0 {-1.1 * R!r} units box")
        launch = (f"set atom 1 z {1.1 * R!r}\nset atom 2 z {-1.1 * R!r}\nvelocity all set 0 0 0 units box\n"
                  f"set atom 1 vz {-U / 2!r}\nset atom 2 vz {U / 2!r}")
        wall = ""
    runs_text = "\n".join([f"{launch}\nrun {steps}"] * runs)
    return HEADER + f"""boundary f f f
region box block -0.01 0.01 -0.01 0.01 -0.01 0.03 units box
create_box 2 box
neighbor {0.5 * R!r} bin
neigh_modify delay 0
fix m1 all property/global coefficientRestitution peratomtypepair 2 0.9 0.9 0.9 0.9
fix m2 all property/global {contact}
pair_style gran model lubricated
pair_coeff * *
{wall}
{atoms}
set group all diameter {2 * R!r} density {RHO}
fix nve all nve/sphere
timestep {DT!r}
thermo_style custom step atoms
thermo {steps}
{runs_text}
print "RESULT done 1"
"""


def overlap_warnings(log):
    return [line for line in log.splitlines() if "WARNING" in line and "overlap by" in line]


@pytest.mark.parametrize("kind", ["wall", "pair"])
def test_a_moderately_soft_contact_warns_once(run, kind):
    """d_max about U t_c / pi = 0.19 R at t_c = 6e-3 s: one WARNING naming the contact, the run goes on."""
    assert run.lig(impact(kind, "lubricatedContactTime scalar 6e-3"))["done"] == 1
    warnings = overlap_warnings(run.log)
    assert len(warnings) == 1, warnings
    text = warnings[0]
    who = ("model lubricated: atom 1 (type 1) and the wall of fix floor (wall/gran)" if kind == "wall"
           else "pair gran model lubricated: atoms ")
    assert who in text, text
    assert ("of the sphere's radius" if kind == "wall" else "of the smaller radius") in text, text
    assert "warned above is 0.1, reported once per run" in text, text
    assert "t_c = 0.006 (N_c = 60 steps of 0.0001)" in text, text
    assert "lubricatedContactTime 0.00" in text and "ncontact" not in text and "tcontact" not in text, text
    assert "per-type-pair" not in text, text


@pytest.mark.parametrize("kind", ["wall", "pair"])
def test_beyond_half_the_radius_warns_a_second_time(run, kind):
    """t_c = 3e-2 s: the overlap passes 0.1 then 0.5 of the radius: two WARNINGs, one per limit, in
    each of two runs (the check is reset at each run); given in steps, the advice is a time step."""
    run.lig(impact(kind, "lubricatedContactSteps scalar 300", steps=800, runs=2))
    warnings = overlap_warnings(run.log)
    assert len(warnings) == 4, warnings
    assert "warned above is 0.1" in warnings[0] and "the limit is 0.5" in warnings[1], warnings
    assert "the limit is 0.5" in warnings[3], warnings
    assert "or a time step of " in warnings[1] and " or less with lubricatedContactSteps 300" in warnings[1]


@pytest.mark.parametrize("kind", ["wall", "pair"])
def test_the_documented_contact_is_silent(run, kind):
    run.lig(impact(kind, "lubricatedContactSteps scalar 8"))
    assert not overlap_warnings(run.log)

"""The overlap check (issue 46; doc/model.rst, "Overlap check"). k = m_e (pi^2 + ln^2 e_d) / t_c^2
is tuned to each contact's m_e: a small sphere under a heavy one, or a fast impact, at a t_c far
beyond the documented one overlaps by more than its radius and goes through the wall or its
partner (LAMMPS's "Lost atoms" later, nothing from the plugin before). Now: an overlap beyond 0.5
of the smaller radius stops the run with an ERROR naming the contact, its t_c and the t_c that
keeps it below; beyond 0.1 a WARNING once per run; a centre gone behind a wall after a contact
stops the run. Normal runs print neither.
"""
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]

R_SMALL, R_BIG = 1e-4, 1e-3


def stacked(dt, steps=2000, region=False):
    """A 1 mm sphere resting on a 0.1 mm sphere on a floor, gravity, N_c 8 at dt."""
    wall = ("region floor block INF INF INF INF 0.0 INF\n"
            "fix floor all wall/lubrication/region 0.9 floor ncontact 8" if region
            else "fix floor all wall/lubrication 0.9 ncontact 8 zplane 0.0 NULL")
    return f"""plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block -0.01 0.01 -0.01 0.01 -0.01 0.03
create_box 2 box
create_atoms 1 single 0 0 {R_SMALL!r} units box
create_atoms 2 single 0 0 {2 * R_SMALL + R_BIG!r} units box
set atom 1 diameter {2 * R_SMALL!r} density 2500
set atom 2 diameter {2 * R_BIG!r} density 2500
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact 8
{wall}
fix g all gravity 9.81 vector 0 0 -1
fix nve all nve/sphere
timestep {dt!r}
neighbor 1e-4 bin
thermo 0
run {steps}
print "RESULT z1 $(z[1]:%.17g)"
"""


def impact(kind, tcontact, dt=1e-4, speed=0.1, start_gap=0.2, steps=400, region=False):
    """A 1 mm sphere onto a floor (wall) or onto a second one (pair) at `speed`, e_d 0.9."""
    r = R_BIG
    if kind == "wall":
        wall = ("region floor block INF INF INF INF 0.0 INF\n"
                f"fix floor all wall/lubrication/region 0.9 floor tcontact {tcontact!r}" if region
                else f"fix floor all wall/lubrication 0.9 tcontact {tcontact!r} zplane 0.0 NULL")
        atoms = f"create_atoms 1 single 0 0 {r * (1 + start_gap)!r} units box"
        velocities = f"velocity all set 0 0 {-speed!r}"
    else:
        wall = ""
        atoms = (f"create_atoms 1 single 0 0 {r * (1 + start_gap / 2)!r} units box\n"
                 f"create_atoms 1 single 0 0 {-r * (1 + start_gap / 2)!r} units box")
        velocities = f"velocity all set 0 0 0\nset atom 1 vz {-speed / 2!r}\nset atom 2 vz {speed / 2!r}"
    return f"""plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block -0.01 0.01 -0.01 0.01 -0.01 0.03
create_box 1 box
{atoms}
set group all diameter {2 * r!r} density 2500
{velocities}
pair_style lubricated/springdashpot
pair_coeff * * 0.9 tcontact {tcontact!r}
{wall}
fix nve all nve/sphere
timestep {dt!r}
neighbor 1e-3 bin
thermo 0
run {steps}
print "RESULT done 1"
"""


def error_line(log):
    return next((line for line in log.splitlines() if "ERROR" in line), "")


def overlap_warnings(log):
    return [line for line in log.splitlines() if "WARNING" in line and "overlap by" in line]


@pytest.mark.parametrize("region", [False, True], ids=["plane", "region"])
def test_a_small_sphere_under_a_heavy_one_stops_the_run(lmp, region):
    """50x the documented step: the overlaps beyond half the small sphere's radius warn, then the
    sphere is pressed through the floor: the ERROR names the contact and a t_c below 8e-4 s
    instead of LAMMPS's lost atom later."""
    lmp(stacked(1e-4, region=region), check=False)
    error = error_line(lmp.log)
    assert "went behind the wall" in error and "atom 1 (type 1) and the wall of fix floor" in error, error
    assert any("the limit is 0.5" in line for line in overlap_warnings(lmp.log)), lmp.log[-3000:]
    assert "t_c = 0.0008 (N_c = 8 steps of 0.0001)" in error, error
    assert "brings this overlap to 0.5 of the radius" in error and "tcontact 0.000" in error, error


@pytest.mark.parametrize("region", [False, True], ids=["plane", "region"])
def test_the_documented_step_is_silent(lmp, region):
    result = lmp(stacked(1e-6, region=region))
    assert not overlap_warnings(lmp.log)
    assert result["z1"] > 0.99 * R_SMALL


@pytest.mark.parametrize("kind", ["wall", "pair"])
def test_a_moderately_soft_contact_warns_once(lmp, kind):
    """d_max about U t_c / pi = 0.19 R at t_c = 6e-3 s: one WARNING, the run goes on."""
    result = lmp(impact(kind, 6e-3, steps=600))
    assert result["done"] == 1
    warnings = overlap_warnings(lmp.log)
    assert len(warnings) == 1, warnings
    assert "reported once per run" in warnings[0] and "tcontact 0.00" in warnings[0]


@pytest.mark.parametrize("region", [False, True], ids=["plane", "region"])
def test_a_sphere_through_the_wall_stops_the_run(lmp, region):
    """0.6 R per step at a contact of 1 s: from 0.45 R of overlap the centre goes behind the wall
    in one step: the ERROR says so instead of LAMMPS's lost atom later."""
    speed = 0.6 * R_BIG / 1e-4
    lmp(impact("wall", 1.0, speed=speed, start_gap=0.15, steps=20, region=region), check=False)
    error = error_line(lmp.log)
    assert "went behind the wall after a contact" in error, error
    assert "atom 1 (type 1) and the wall of fix floor" in error, error


@pytest.mark.parametrize("name,variables,nprocs", [
    ("settling_bed/in.settling_bed", {"wet": 0, "steps": 3000}, 1),
    ("settling_bed/in.settling_bed", {"wet": 1, "steps": 3000}, 1),
    ("shear_cell/in.shear_cell", {"steps": 1000}, 2),
])
def test_the_examples_print_neither(lmp, name, variables, nprocs):
    """The examples' beds (as test_examples.py runs them): no overlap warning, no error."""
    lmp((ROOT / "examples" / name).read_text(), nprocs=nprocs, **variables)
    assert not overlap_warnings(lmp.log)


def test_the_rotating_drum_warns_once(lmp):
    """The drum example's contact is soft on purpose (t_c = 1 ms for 2 mm glass beads, a long step):
    the beads' first fall onto the drum overlaps a pair by just over 0.1 R: one WARNING, no more."""
    lmp((ROOT / "examples" / "rotating_drum/in.rotating_drum").read_text(), wet=0, steps=3000)
    assert len(overlap_warnings(lmp.log)) == 1

"""`pair_style gran model lubricated` replaces LIGGGHTS's pass over the neighbour list with a
lean one (src/liggghts/pair_pass.h): the same calls to the contact model in the same order, the
pairs beyond LIGGGHTS's contact distance skipped after their distance alone, so the same forces.
LUBRICATED_LIGGGHTS_PASS=liggghts runs LIGGGHTS's own pass instead: both must give the same
trajectory to round-off (1e-13 relative; measured: equal to the bit).

Scenes: the wet polydisperse chain between walls with friction (1 and 2 ranks, the film's
activation fixed and from a grid spacing), and the preloaded random 1:10 packing (592 sustained
contacts, films around them), wet, with tangential history, on 1 and 2 ranks. A lean pass that
drops j's share, a contact or a close pair, or the tangential history's reset of the pairs that
separate, moves these far beyond the tolerance.

The lean pass also skips the pairs without a contact flag that lie beyond what the normal model
can reach in the step (its film's reach and both atoms' moves; pair_pass.h, idle_close_pairs):
fast head-on pairs, dry and wet, whose gap closes by more than the film's reach in a step,
check that bound (without the atoms' moves in it, contacts that start within a step are missed);
a sliding contact jerked into that band and back within a run (fix deform, which moves the atoms
without their velocities) keeps LIGGGHTS's reset of its tangential history (a pair with a contact
flag is never skipped: without that, the stale history returns with the contact). Both passes list
the same close pairs (the model lists no idle pair in either), so that the pieces of 1024 close
pairs are applied at the same points of a pass: on a jittered lattice of 500 spheres with
contacts, films and idle pairs, the two trajectories are equal to the bit.

The model sets no contact flag for a film and clears its own for a pair apart (a film has no
history), so LIGGGHTS keeps no contact history for a film, and the lean pass lists those pairs as
pairs without a flag: a pair in the film writes the restart file of a pair far apart (a flag set
by the film adds its partner record: caught), a pressed contact a larger one."""
import itertools
import random

import pytest

import liggghts_dense_scenes as dense
from liggghts_scenes import HEADER, properties

import dense_packings
from liggghts_chain import chain, dump_state
from test_dense_beds import packing_rows, packing_run, packings  # noqa: F401 (fixture)
from test_parallel_restart import assert_same_state

ROUND_OFF = 1e-13
LEAN = "pair gran model lubricated: lean pair pass"
LIGGGHTS = "pair gran model lubricated: LIGGGHTS's own pair pass"


def both_passes(run, script, nprocs):
    lean = run.lig(script, nprocs=nprocs)
    assert LEAN in run.log and LIGGGHTS not in run.log
    lean_log = run.log
    own = run.lig(script, nprocs=nprocs, environment={"LUBRICATED_LIGGGHTS_PASS": "liggghts"})
    assert LIGGGHTS in run.log and LEAN not in run.log
    return lean, lean_log, own, run.log


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("activation", ["fixed", "grid"])
def test_lean_pass_follows_liggghts_pass_on_the_chain(run, activation, nprocs):
    text = chain(processors="processors 2 1 1" if nprocs == 2 else "")
    if activation == "grid":
        fixed = "fix m5 all property/global lubricatedActivation scalar 0.09375\n"
        assert fixed in text
        text = text.replace(fixed, "fix m5 all property/global lubricatedGridSpacing scalar 1e-4\n")
    lean, _, own, _ = both_passes(run, text + dump_state(), nprocs)
    assert_same_state(own, lean, rel=ROUND_OFF)


def frictional_wet_packing(data):
    script = packing_run(data, "lubricatedContactSteps scalar 8", dt=5e-6, steps=400,
                         mu=dense_packings.viscosity_for_stokes(1.0), every=20)
    script = script.replace("pair_style gran model lubricated\n",
                            "fix mu all property/global coefficientFriction peratomtypepair 1 0.5\n"
                            "pair_style gran model lubricated tangential history\n")
    assert "tangential history" in script
    return script + dump_state()


@pytest.mark.parametrize("nprocs", [1, 2])
def test_lean_pass_follows_liggghts_pass_in_a_dense_frictional_bed(run, packings, nprocs):  # noqa: F811
    lean, lean_log, own, own_log = both_passes(run, frictional_wet_packing(packings["preloaded"]), nprocs)
    rows, reference = packing_rows(lean_log), packing_rows(own_log)
    assert len(rows) == len(reference) == 21 and {r[1] for r in rows} == {300}
    assert reference[-1][2] < 0.5 * reference[0][2]    # the bed dissipates: contacts and films act
    for row, ref in zip(rows, reference):
        assert row == pytest.approx(ref, rel=ROUND_OFF, abs=0.0)
    assert own.pop("atoms") == lean.pop("atoms") == 300
    assert_same_state(own, lean, rel=ROUND_OFF)


# The small scenes' integration and output (dt = 1e-5 s, thermo every 10 steps).
STEPPING = """fix nve all nve/sphere
timestep 1e-5
thermo_style custom step ke
thermo 10
neighbor 3e-4 bin
neigh_modify delay 0
"""


def fast_pairs(wet, processors=""):
    """Four head-on pairs (R = 1 mm) closing at 2 m/s, 2e-5 m a step: more than the film's reach
    (0.75 dx = 7.5e-6 m) and less than LIGGGHTS's approach margin (0.02 (r_i + r_j)); gaps so
    that contacts start at different points of a step; the pairs rebound through the film."""
    radius, speed = 1e-3, 1.0
    atoms = []
    for k, gap in enumerate((1.1e-4, 1.17e-4, 1.243e-4, 1.31e-4)):
        centre = -0.0075 + 0.005 * k    # the second pair straddles x = 0 (two ranks)
        for side in (-1, 1):
            atoms.append((centre + side * (radius + gap / 2), 1e-4 * k, -side * speed))
    lines = "\n".join(f"create_atoms 1 single {x} {y} 0 units box\n"
                      f"set atom {n + 1} diameter {2 * radius} density 8000\n"
                      f"set atom {n + 1} vx {vx} vy {0.02 * (n % 3 - 1)}"
                      for n, (x, y, vx) in enumerate(atoms))
    film = properties(0.9, 1.7e-3 if wet else 0.0, 8, friction=0.3, grid=1e-5)
    return HEADER + f"""boundary f p p
{processors}
region box block -0.012 0.012 -0.003 0.003 -0.003 0.003 units box
create_box 2 box
pair_style gran model lubricated tangential history
pair_coeff * *
{lines}
{film}{STEPPING}run 40
""" + dump_state()


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("wet", [False, True])
def test_lean_pass_follows_liggghts_pass_for_fast_pairs(run, wet, nprocs):
    lean, _, own, own_log = both_passes(run, fast_pairs(wet, "processors 2 1 1" if nprocs == 2 else ""), nprocs)
    ke = [float(r.split()[1]) for r in own_log.splitlines() if len(r.split()) == 2 and r.split()[0].isdigit()]
    assert len(ke) == 5 and ke[-1] < 0.95 * ke[0]    # the pairs collided and lost energy
    assert_same_state(own, lean, rel=ROUND_OFF)


def jerked_contact():
    """Two spheres pressed together (fix addforce) and sliding (friction 0.3), in a periodic box
    that fix deform (remap x) widens and narrows within 8 steps: the pair jumps to gaps of about
    1e-5 m (within LIGGGHTS's contact distance, beyond the normal model's reach over the step,
    with its contact flag still set) and back into contact, without the velocities that would
    bound such a move."""
    radius, overlap, push = 1e-3, 8e-7, 0.02
    return HEADER + f"""boundary p p p
region box block -0.004 0.004 -0.003 0.003 -0.003 0.003 units box
create_box 2 box
pair_style gran model lubricated tangential history
pair_coeff * *
create_atoms 1 single {-(radius - overlap / 2)} 0 0 units box
create_atoms 1 single {radius - overlap / 2} 0 0 units box
set atom * diameter {2 * radius} density 8000
set atom 1 vy 0.01
set atom 2 vy -0.01
group one id 1
group two id 2
{properties(0.9, 0.0, 8, friction=0.3)}fix push1 one addforce {push} 0 0
fix push2 two addforce {-push} 0 0
{STEPPING}run 40
fix jerk all deform 1 x wiggle 4.4e-5 8e-5 remap x
run 8
unfix jerk
run 40
""" + dump_state(n_atoms=2)


def test_lean_pass_resets_a_jerked_contact_as_liggghts(run):
    lean, _, own, _ = both_passes(run, jerked_contact(), 1)
    for key in own:
        assert lean[key] == pytest.approx(own[key], rel=ROUND_OFF, abs=1e-13), key


def jittered_lattice(processors=""):
    """The fcc lattice of 500 spheres of liggghts_dense_scenes (periodic, mean gap 0.05 R, friction
    0.3), each centre moved by up to 3e-5 m (seeded): about 1500 pairs within LIGGGHTS's contact
    distance a pass, in overlap, in the film (reach 0.1 R) and beyond it."""
    radius, cells = dense.R, 5
    a = 2.0 * radius * 1.025 * 2 ** 0.5
    size = cells * a
    rng = random.Random(4242)
    lines = []
    for cell in itertools.product(range(cells), repeat=3):
        for basis in ((0, 0, 0), (0.5, 0.5, 0), (0.5, 0, 0.5), (0, 0.5, 0.5)):
            x = [((c + b) * a + rng.uniform(-3e-5, 3e-5)) % size for c, b in zip(cell, basis)]
            lines.append(f"create_atoms 1 single {x[0]!r} {x[1]!r} {x[2]!r} units box")
    atoms = f"""{processors}
region box block 0 {size!r} 0 {size!r} 0 {size!r} units box
create_box 1 box
""" + "\n".join(lines) + f"""
set group all diameter {2 * radius!r} density {dense.RHO}
variable vx atom {dense.SPEED}*sin(7919*x+3571*y+1231*z)
variable vy atom {dense.SPEED}*sin(2203*x+7919*y+4409*z)
variable vz atom {dense.SPEED}*sin(1543*x+6007*y+7919*z)
velocity all set v_vx v_vy v_vz units box
velocity all zero linear
"""
    return dense._script("liggghts", "off", "p p p", atoms, dense.viscosity_for_stokes(1.0), 1e-6, 200, 20,
                         "atom", 0.3) + dump_state(500)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_lean_pass_equals_liggghts_pass_to_the_bit_in_pieces(run, nprocs):
    lean, lean_log, own, own_log = both_passes(run, jittered_lattice("processors 2 1 1" if nprocs == 2 else ""), nprocs)
    rows, reference = dense.rows(lean_log), dense.rows(own_log)
    assert len(rows) == len(reference) == 11 and {r[1] for r in rows} == {500}
    assert reference[0][4] > 0 and reference[-1][5] != reference[0][5]    # contacts act
    assert rows == reference
    assert lean == own


def test_unknown_pass_is_refused(run):
    with pytest.raises(Exception, match="LUBRICATED_LIGGGHTS_PASS = 'fast' \\(expected lean or liggghts\\)"):
        run.lig(chain(steps=10), environment={"LUBRICATED_LIGGGHTS_PASS": "fast"})


def one_pair(gap, push):
    """Two spheres (R = 1 mm) gap apart, closing at 2e-3 m/s and sliding (friction 0.3), wet
    (film reach 0.75 dx = 7.5e-6 m), pressed together by push [N] each, 40 steps, then a restart
    file: its size counts the pairs whose contact history LIGGGHTS keeps (a contact flag set)."""
    radius = 1e-3
    return HEADER + f"""boundary p p p
region box block -0.004 0.004 -0.003 0.003 -0.003 0.003 units box
create_box 2 box
pair_style gran model lubricated tangential history
pair_coeff * *
create_atoms 1 single {-(radius + gap / 2)!r} 0 0 units box
create_atoms 1 single {radius + gap / 2!r} 0 0 units box
set atom * diameter {2 * radius} density 8000
set atom 1 vx 0.001 vy 0.01
set atom 2 vx -0.001 vy -0.01
group one id 1
group two id 2
{properties(0.9, 1.7e-3, 8, friction=0.3, grid=1e-5)}fix push1 one addforce {push} 0 0
fix push2 two addforce {-push} 0 0
{STEPPING}run 40
write_restart pair.restart
""" + dump_state(n_atoms=2)


def test_a_film_leaves_no_contact_flag(run):
    """The film acts on a pair apart without a contact flag: LIGGGHTS keeps no contact history for
    it (a partner record per pair and neighbour build), and the lean pass takes it as a pair
    without one (pair_pass.h). A pair in the film writes the restart file of a pair far apart; a
    pressed contact (flags set: its tangential history and the film's lambda) a larger one."""
    sizes = {}
    for case, gap, push in (("far", 1e-3, 0.0), ("film", 4e-6, 0.0), ("contact", -8e-7, 0.02)):
        state = run.lig(one_pair(gap, push), name=f"in.{case}")
        sizes[case] = (run.dir / "pair.restart").stat().st_size
        if case == "film":    # still in the film, which slowed the approach (2e-3 m/s without it)
            assert 0.0 < state["x2"][0] - state["x1"][0] - 2e-3 < 7.5e-6
            assert state["v1"][0] < 0.999e-3
    assert sizes["film"] == sizes["far"]
    assert sizes["contact"] > sizes["far"]

"""The pair style as a sub-style of pair_style hybrid, and under comm_style tiled.

hybrid/overlay with pair zero: the same run to the bit (the pair style's list is then LAMMPS's
copy of the master list, which it does not trim). hybrid with gran/hooke/history for a second
type (half the spheres): the style acts on the pairs of type 1 only, through a skip list (trimmed
or not: the same run to the bit), beside LAMMPS's own contact history; 2 ranks give the 1-rank
run (relative 1e-8; measured 1e-13).

comm_style tiled with recursive-bisection balancing (fix balance rcb), as clusters use for beds
of uneven density: the same run as the one-rank brick run, within the rounding that the other
order of the sums makes in a dense bed (relative 1e-8 after 400 steps; measured 1e-10).

The bed: the random 1:10 packing of solid fraction 0.61 (tests/lammps/dense_packings/p61.data,
300 spheres, periodic) with random velocities of rms 0.3 m/s (a hash of the atom ID), wet
(mu_f = 1e-3 Pa s, eps_al = 0.1), e_d = 0.9, N_c = 8, dt = 1e-6 s, 400 steps, rebalanced every 50.
With friction the contact history moves its records with a variable-size reverse communication
under newton on, which LAMMPS's CommTiled does not provide (nor for gran/hooke/history, whose
history fix needs the same): LAMMPS's own error then, and with newton off the run goes on.
"""
import pathlib

import pytest

import dense_scenes

DATA = pathlib.Path(__file__).resolve().parent / "dense_packings" / "p61.data"

SCRIPT = """plugin load ${{plugin}}
units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
{comm}
read_data {data}{types}
{velocities}
pair_style {pair}
{pair_coeff}
neighbor 2e-5 bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
{balance}
timestep 1e-6
compute rot all erotate/sphere
thermo_style custom step atoms ke c_rot
thermo_modify lost error norm no
thermo 100
run 400
print "RESULT final $(ke:%.17g) $(c_rot:%.17g) $(atoms)"
print "RESULT a1 $(x[1]:%.17g) $(vx[1]:%.17g) $(vy[77]:%.17g)"
"""

WET = "0.9 ncontact 8 viscosity 1e-3 activation 0.1"
TILED = "comm_style tiled"
RCB = "fix balance all balance 50 1.05 rcb"


def script(coefficients, comm="", balance="", pair="lubricated/springdashpot", pair_coeff=None, types=""):
    pair_coeff = pair_coeff or f"pair_coeff * * {coefficients}"
    return SCRIPT.format(comm=comm, data=DATA, types=types, pair=pair, pair_coeff=pair_coeff, balance=balance,
                         velocities=dense_scenes.hashed_velocities(0.3))


def test_overlay_with_pair_zero_is_the_plain_run(lmp):
    plain = lmp(script(WET + " friction 0.3"))
    overlay = lmp(script(None, pair="hybrid/overlay lubricated/springdashpot zero 0.0001",
                         pair_coeff=f"pair_coeff * * lubricated/springdashpot {WET} friction 0.3\n"
                                    "pair_coeff * * zero"))
    assert overlay == plain


HALF_TYPE_2 = " extra/atom/types 1\ngroup odd id 1:300:2\nset group odd type 2"
HOOKE = "gran/hooke/history 5000 NULL 2000 NULL 0.3 1"


def test_hybrid_with_a_builtin_style(lmp):
    pair = f"hybrid lubricated/springdashpot {HOOKE}"
    pair_coeff = (f"pair_coeff 1 1 lubricated/springdashpot {WET} friction 0.3\n"
                  "pair_coeff 1 2 gran/hooke/history\npair_coeff 2 2 gran/hooke/history")
    one = lmp(script(None, pair=pair, pair_coeff=pair_coeff, types=HALF_TYPE_2))
    two = lmp(script(None, pair=pair, pair_coeff=pair_coeff, types=HALF_TYPE_2), nprocs=2)
    assert "on 2 procs" in lmp.log
    assert_close(two, one)
    # its skip list trimmed or kept whole: the same run to the bit
    kept = lmp(script(None, pair=pair.replace("springdashpot", "springdashpot trim no"), pair_coeff=pair_coeff,
                      types=HALF_TYPE_2))
    assert kept == one
    # the plugin acts on the pairs of type 1: not the run of gran/hooke/history everywhere
    builtin = lmp(script("", pair=HOOKE, types=HALF_TYPE_2))
    assert one["final"][0] != pytest.approx(builtin["final"][0], rel=1e-3)


SEVERAL = "several instances under pair_style hybrid"


def test_several_wet_instances_warn_of_their_separate_budgets(lmp):
    """Each instance keeps the film budget of its own pairs (and a wall fix joins none): a sphere
    with films of two instances is not held within one budget. One instance, beside a built-in
    style, does not warn (test above); two wet instances do."""
    pair = "hybrid lubricated/springdashpot lubricated/springdashpot"
    pair_coeff = "\n".join(f"pair_coeff {i} {j} lubricated/springdashpot {k} {WET}"
                           for i, j, k in ((1, 1, 1), (1, 2, 1), (2, 2, 2)))
    lmp(script(None, pair=pair, pair_coeff=pair_coeff, types=HALF_TYPE_2))
    assert SEVERAL in lmp.log
    lmp(script(None, pair=f"hybrid lubricated/springdashpot {HOOKE}",
               pair_coeff=f"pair_coeff 1 1 lubricated/springdashpot {WET}\npair_coeff 1 2 gran/hooke/history\n"
                          "pair_coeff 2 2 gran/hooke/history", types=HALF_TYPE_2))
    assert SEVERAL not in lmp.log


def assert_close(got, want):
    assert got.keys() == want.keys()
    for key in want:
        assert got[key] == pytest.approx(want[key], rel=1e-8, abs=1e-12), key


@pytest.mark.parametrize("coefficients, newton", [(WET, "on"), (WET + " friction 0.3", "off")],
                         ids=["wet newton on", "wet friction newton off"])
def test_tiled_rcb_run_is_the_brick_run(lmp, coefficients, newton):
    brick = lmp(script(coefficients, comm=f"newton {newton}"))
    tiled = lmp(script(coefficients, comm=f"newton {newton}\n{TILED}", balance=RCB), nprocs=2)
    assert "on 2 procs" in lmp.log and tiled["final"][2] == 300
    assert tiled["final"][0] > 0.1 * brick["final"][0]    # the bed still moves
    assert_close(tiled, brick)


@pytest.mark.parametrize("pair, coefficients", [("lubricated/springdashpot", WET + " friction 0.3"),
                                                ("gran/hooke/history 5000 NULL 2000 NULL 0.3 1", "")],
                         ids=["plugin", "gran/hooke/history"])
def test_friction_with_newton_on_needs_what_comm_tiled_lacks(lmp, pair, coefficients):
    lmp(script(coefficients, comm=TILED, balance=RCB, pair=pair), nprocs=2, check=False)
    assert "Reverse comm fix variable not yet supported by CommTiled" in lmp.log

"""Pass 1 of the pair loop selects the neighbor list in pieces of at most pairs_per_piece pairs
(pair_lubricated_springdashpot.h; each piece goes to the force loops before the next is
selected, pair_lubricated_springdashpot_eval.cpp): no pair may be lost or taken twice at a
piece's edge.

The scene: 10648 identical dimers (R = 1 mm) on a simple cubic lattice of 8 mm (no pair between
dimers: the list's cutoff is under 2.3 mm), each approaching head-on at 0.1 m/s with a sideways
slip of 0.04 m/s, in overlap of 0.005 R (contact: the candidates' list; clear of the film's
release at eps_2 = -0.01, where rounding would decide whether the film acts) or apart inside the
film (the film-only list), dry and wet, with and without friction; 1 rank (3 pieces of 4096) and
2 ranks (2 pieces each; the test requires more than one per rank of the header's piece size). Every
dimer feels the same force at the set-up and after 5 steps: a pair dropped at a piece's edge
would leave its dimer without force (or with the previous step's), a pair taken twice would
double it (and `compute pair`'s count of the selected pairs, one per dimer, would miss or double
it too: it is checked exactly, with the film-only pairs). Tolerance: 1e-9 of the force. The
dimers differ only in where they sit: coordinates up to 0.18 m round the 1e-5 m overlap to about
2e-12 of itself, and 5 steps make that 1e-10. A lost or doubled pair changes its dimer's force by
100 %.
"""
import pathlib
import re

import pytest

import dense_scenes

R = 1.0e-3
SPACING = 8.0e-3
CELLS = (22, 22, 22)    # 10648 dimers
HEADER = pathlib.Path(__file__).resolve().parents[2] / "src" / "pair_lubricated_springdashpot" / \
    "pair_lubricated_springdashpot.h"
PAIRS_PER_PIECE = int(re.search(r"pairs_per_piece = (\d+);", HEADER.read_text()).group(1))
SKIN = 0.2e-3

CASES = {
    "dry, contact": ("", -0.005),
    "wet, contact": ("viscosity 1e-3 grid 1.25e-4", -0.005),
    "wet, film": ("viscosity 1e-3 grid 1.25e-4", 0.05),
    "dry friction, contact": ("friction 0.3", -0.005),
    "wet friction, contact": ("viscosity 1e-3 grid 1.25e-4 friction 0.3", -0.005),
    "wet friction, film": ("viscosity 1e-3 grid 1.25e-4 friction 0.3", 0.05),
}


def scene(coefficients, gap):
    """Dimers with centres 2R + gap R apart along x."""
    offset = (2.0 + gap) * R / SPACING
    nx, ny, nz = CELLS
    summary = "\n".join(
        f"compute {name} one reduce {kind} fx fy fz" for name, kind in (("low", "min"), ("high", "max")))
    report = ('print "RESULT force{s} $(c_low[1]:%.17g) $(c_high[1]:%.17g) $(c_low[2]:%.17g) $(c_high[2]:%.17g) '
              '$(c_low[3]:%.17g) $(c_high[3]:%.17g) $(count(one))"\n'
              'print "RESULT pairs{s} $(c_pairs[1]:%.17g) $(c_pairs[2]:%.17g)"')
    return dense_scenes.HEADER + f"""lattice sc {SPACING!r}
region box block 0 {nx} 0 {ny} 0 {nz}
create_box 2 box
create_atoms 1 box
lattice sc {SPACING!r} origin {offset!r} 0 0
create_atoms 2 box
set group all diameter {2 * R!r} density 2500
group one type 1
group two type 2
velocity one set 0.05 0.02 0 units box
velocity two set -0.05 -0.02 0 units box
pair_style lubricated/springdashpot
pair_coeff * * 0.9 ncontact 8 {coefficients}
neighbor {SKIN!r} bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep 1e-5
{summary}
compute pairs all pair lubricated/springdashpot
thermo_style custom step atoms c_low[1] c_high[1] c_pairs[1] c_pairs[2]
thermo_modify lost error
run 0
{report.format(s=0)}
run 5
{report.format(s=5)}
"""


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("case", CASES)
def test_every_dimer_feels_the_same_force(lmp, case, nprocs):
    # more than one piece on each rank (the ranks split the lattice in halves), or no edge to test
    assert CELLS[0] * CELLS[1] * CELLS[2] // nprocs > PAIRS_PER_PIECE
    coefficients, gap = CASES[case]
    result = lmp(scene(coefficients, gap), nprocs=nprocs)
    assert dense_scenes.ranks(lmp.log) == {nprocs}
    for state in ("force0", "force5"):
        low_x, high_x, low_y, high_y, low_z, high_z, count = result[state]
        assert count == CELLS[0] * CELLS[1] * CELLS[2]
        # head-on along x (the contact repels, the film resists the approach: both push i back)
        assert low_x < 0.0, f"{state}: no force along x"
        scale = abs(low_x)
        for low, high in ((low_x, high_x), (low_y, high_y), (low_z, high_z)):
            assert high - low <= 1e-9 * scale, f"{state}: dimers differ by {(high - low) / scale:.3g}"
        if "friction" in case and gap < 0.0 and state == "force0":
            assert low_y < 0.0, "no friction against the slip"
    # compute pair: every dimer's pair selected once over the pieces and ranks, and counted as
    # film-only where the film alone acts (apart by 50 um, the step moves them 1.4 um at most);
    # the set-up (force0) takes the general loop, the steps (force5) the vectorised lists.
    dimers = CELLS[0] * CELLS[1] * CELLS[2]
    film_only = dimers if gap > 0.0 else 0
    for state in ("pairs0", "pairs5"):
        assert result[state] == [dimers, film_only], f"{state}: selected, film-only"


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("wet", [False, True], ids=["dry", "wet"])
def test_friction_added_between_runs(lmp, wet, nprocs):
    """A run without friction, then pair_coeff adds it: the second run's set-up creates the
    contact history, which must follow the list the first run built (LAMMPS does not call
    init_list again for an unchanged request), and pass 1's history index array must grow
    although its pair arrays are already long enough. Both used to crash (segmentation fault).
    The dimers, still in contact (overlap 0.005 R, 5 steps at 0.1 m/s close 0.5 um more), then
    feel friction against their slip, every dimer the same (tolerance as above)."""
    film = "viscosity 1e-3 grid 1.25e-4 " if wet else ""
    script = scene(film, -0.005)
    first, second = script.split("run 0\n", 1)
    script = (first + "run 0\n" + second.replace(
        "run 5\n", f"run 5\npair_coeff * * 0.9 ncontact 8 {film}friction 0.3\nrun 0\n", 1))
    result = lmp(script, nprocs=nprocs)
    assert dense_scenes.ranks(lmp.log) == {nprocs}
    low_x, high_x, low_y, high_y, low_z, high_z, count = result["force5"]
    assert count == CELLS[0] * CELLS[1] * CELLS[2]
    assert low_x < 0.0, "no normal force"
    assert low_y < 0.0, "no friction against the slip"
    scale = abs(low_x)
    for low, high in ((low_x, high_x), (low_y, high_y), (low_z, high_z)):
        assert high - low <= 1e-9 * scale, f"dimers differ by {(high - low) / scale:.3g}"

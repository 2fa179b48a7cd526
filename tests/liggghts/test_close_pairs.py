"""The close pairs of a LIGGGHTS step (within the contact distance, not in overlap) are listed by
`model lubricated` and evaluated in one vectorised loop at the end of the pass
(src/liggghts/close_pairs.h); the same pairs one by one (surfacesClose) where a per-pair force
is read. Both must give the same trajectory: the loop's film is the kernel's
film_force_apart(), the closed form of normal_force() for a pair apart over the step.

The scene (liggghts_chain): the wet polydisperse chain between two walls, friction on,
collisions and films on 1 and 2 ranks, with the film's activation fixed and from a grid
spacing (the loop's two forms). `compute pair/gran/local` makes every step take the per-pair
path. Tolerance 1e-10 relative: the two paths differ by the rounding of a logarithm and by the
order in which forces are summed, which the collisions amplify (measured: at most 4.2e-12).
A loop that drops or doubles the films, or applies them to the wrong atom, moves the spheres by
far more: films 1 % too strong in the loop fail every case."""
import pytest

import liggghts_dense_scenes as dense
import scenes
from liggghts_chain import chain, dump_state
from test_parallel_restart import assert_same_state

STEPS = 600
PER_PAIR = "compute pairs all pair/gran/local pos vel force\n"


def scene(activation, per_pair, processors):
    text = chain(steps=STEPS, processors=processors)
    if activation == "grid":    # 0.75 dx = 0.075 R: films of about the same reach
        fixed = "fix m5 all property/global lubricatedActivation scalar 0.09375\n"
        assert fixed in text
        text = text.replace(fixed, f"fix m5 all property/global lubricatedGridSpacing scalar {0.1 * scenes.R}\n")
    if per_pair:
        text = text.replace(f"run {STEPS}\n", PER_PAIR + f"run {STEPS}\n")
    return text + dump_state()


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("activation", ["fixed", "grid"])
def test_close_pairs_loop_equals_the_per_pair_path(run, activation, nprocs):
    processors = "processors 2 1 1" if nprocs == 2 else ""
    looped = run.lig(scene(activation, False, processors), nprocs=nprocs)
    per_pair = run.lig(scene(activation, True, processors), nprocs=nprocs)
    assert_same_state(looped, per_pair, rel=1e-10)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_close_pairs_in_pieces_equal_the_per_pair_path(run, nprocs):
    """A pass evaluates its close pairs in pieces of 1024 while their atoms are in the cache
    (src/liggghts/normal_model_lubricated.h). The periodic fcc lattice of 500 spheres (gaps of
    0.002 R, each sphere's 12 neighbours in the film, St = 1) has at least 3000 close pairs a
    pass (newton off: more, where a pair's atom is a ghost): every pass spans several pieces. A
    piece applied twice or dropped moves the spheres far beyond the tolerance (above)."""
    script = dense.fcc(dense.viscosity_for_stokes(1.0), 1e-6, steps=300, every=30, cells=5)
    if nprocs == 2:
        script = script.replace("units si\n", "units si\nprocessors 2 1 1\n")
    script += dump_state()
    looped = run.lig(script, nprocs=nprocs)
    rows = dense.rows(run.log)
    per_pair = run.lig(script.replace("\nrun 300\n", "\n" + PER_PAIR + "run 300\n"), nprocs=nprocs)
    reference = dense.rows(run.log)
    assert "compute pairs" not in script and len(rows) == len(reference) == 11
    assert {r[1] for r in rows} == {500}
    assert rows[-1][2] < 0.9 * rows[0][2]    # the films dissipate
    for row, ref in zip(rows, reference):
        assert row == pytest.approx(ref, rel=1e-10, abs=0.0)
    assert looped.pop("final") == pytest.approx(per_pair.pop("final"), rel=1e-10)
    assert_same_state(looped, per_pair, rel=1e-10)

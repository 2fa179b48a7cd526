"""Time-step changes (issue 18). *ncontact* N_c sets t_c = N_c dt with the time step of the first
run that uses the coefficients; from then on t_c, k and c are the contact's own, as with
*tcontact* (lubricated/coefficients.h, settle_contact_time), so a later time step (the
timestep command between runs, fix dt/reset within one) changes only the steps per contact.
Before: k followed dt, and a contact under way when dt shrank fivefold left with e = 3.03 for
e_d = 0.5; fix dt/reset gave e = 0.196; a settled bed given dt/4 gained energy.

Tolerances: a collision integrated entirely at one time step is exact (e_d to 1e-9); one whose
time step changes while it is under way is exact before and after the change but not across the
step where the change falls (the leapfrog's last velocity is an average over a step of the old
length): measured e/e_d within 4 % of 1 for changes by a factor 5 either way, asserted within 6 %
and never beyond 1.01 e_d; under fix dt/reset (a change at every step) within 1 %.
"""
import pytest

import dense_scenes
import scenes

R, U = scenes.R, scenes.U
DT = 0.005 * R / U
E_D = 0.5


def bounce_with_a_new_time_step(first, factor):
    """A wall bounce (N_c 8 at dt) whose time step becomes factor * dt after `first` steps."""
    rest = int(300 / factor)
    return scenes.wall_bounce(E_D, dt_ru=0.005, steps=1).replace(
        "run 1\n", f"run {first}\ntimestep {DT * factor!r}\nrun {rest}\n").replace(
        "variable n equal f_count*2", f"variable n equal f_count*{rest + 1}")


@pytest.mark.parametrize("factor", [0.2, 5.0])
def test_a_new_time_step_during_a_contact_keeps_it_dissipative(lmp, factor):
    # The sphere touches the wall in steps 43-50 of dt: changes before, during and after contact.
    for first in (40, 43, 45, 47, 49, 55):
        e = lmp(bounce_with_a_new_time_step(first, factor))["e"]
        assert e == pytest.approx(E_D, rel=0.06), (first, e)
        assert e <= 1.01 * E_D, (first, e)
        if first in (40, 55):    # the contact at one time step only: exact
            assert e == pytest.approx(E_D, rel=1e-9), first
    # The log reports the contact at the new step: t_c kept, N_c = 8 / factor steps.
    assert f"t_c = 0.0004 ({8 / factor:.3g} steps)" in lmp.log


@pytest.mark.parametrize("scene", ["wall", "pair"])
def test_fix_dt_reset_keeps_the_restitution(lmp, scene):
    """fix dt/reset at every step, the step bounded by a move of 0.0005 R: e_d within 1 %."""
    script = (scenes.wall_bounce if scene == "wall" else scenes.pair_bounce)(E_D, dt_ru=0.005)
    run = next(line for line in script.splitlines() if line.startswith("run "))
    script = script.replace(run, "run 1200").replace(
        "fix nve all nve/sphere", f"fix nve all nve/sphere\nfix adapt all dt/reset 1 NULL {DT!r} {0.0005 * R!r} units box")
    script += 'print "RESULT dt_end $(dt:%.6g)"\n'
    result = lmp(script)
    assert result["e"] == pytest.approx(E_D, rel=0.01)
    assert result["dt_end"] < 0.5 * DT    # the time step did change


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("wet", [False, True], ids=["dry", "wet"])
def test_a_compressed_bed_given_a_quarter_time_step_gains_no_energy(lmp, wet, nprocs):
    """256 spheres on an fcc lattice, every neighbour in overlap (0.2 % of 2R) and moving; after
    100 steps the time step becomes dt/4 for 800 more: the energy (kinetic, rotational, springs)
    never rises by more than round-off (before: the springs stiffened 16-fold)."""
    scene = dense_scenes.fcc(1.0 if wet else 0.0, 1e-6, steps=900, every=10, gap_ratio=-0.002)
    lmp(dense_scenes.split(scene, "run 100", "timestep 2.5e-7", "run 800"), nprocs=nprocs)
    energy, atoms = dense_scenes.energies(lmp.log)
    assert dense_scenes.ranks(lmp.log) == {nprocs}
    assert len(energy) >= 90 and set(atoms) == {256}
    rises = [(b - a) / energy[0] for a, b in zip(energy, energy[1:])]
    assert max(rises) <= 1e-12, f"energy rose by {max(rises):.3g} E0"
    assert energy[-1] < energy[0]


def test_a_time_step_beyond_the_settled_contact_stops_with_an_error(lmp):
    """ncontact 8 settles t_c = 8 dt at the first run; a later step of 100 dt would give
    N_c = 0.08: an ERROR that names ncontact, the settled t_c and the allowed range."""
    script = bounce_with_a_new_time_step(10, 100.0)
    lmp(script, check=False)
    error = next((line for line in lmp.log.splitlines() if "ERROR" in line), "")
    assert "ncontact = 8 settled t_c = 0.0004 at the first run" in error, error
    assert "N_c = t_c / dt = 0.08" in error and "1 <= N_c <= 1e6" in error and "give ncontact again" in error

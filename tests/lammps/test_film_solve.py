"""The coupled film solve (`pair_style lubricated/springdashpot limit implicit`, issue 45,
doc/film_solve.rst): an isolated collision keeps its step-exact films (no load exceeds 1, the
solve is never taken), dense wet beds at low St never gain energy with the films of the
spheres over budget solved together, 1 and 2 ranks agree to the solver's tolerance (1, 2 and 4
on a sheared suspension), bad
keywords end in an ERROR naming them, and a restart keeps the mode.

Scenes: tools/dense_scenes.py (256 spheres on an fcc lattice, every gap in the film, St =
5.6e-3 at mu_f = 1 Pa s; the thermo rows gain the solve's iterations and solved films, compute
pair's 3rd and 4th values), and the polydisperse packings of test_dense_packings.py (radii
1:10, its fixture and energy criteria), on wet walls too (whose films of spheres over budget
join the solve: test_film_solve_walls.py). Newton pair off and 2 ranks solve each film once;
compute pressure and the sum of compute stress/atom see the solved films alike.
"""
import numpy as np
import pytest

import dense_scenes
import lammps_run
import suspension_scene

ROUND_OFF = 1e-12

SOLVE_THERMO = ("thermo_style custom step atoms ke c_rot pe v_e",
                "compute solve all pair lubricated/springdashpot\n"
                "thermo_style custom step atoms ke c_rot pe v_e c_solve[3] c_solve[4]")


def with_solve_columns(script):
    assert SOLVE_THERMO[0] in script
    return script.replace(*SOLVE_THERMO)


def rows(log):
    """Thermo rows: (step, atoms, energy, iterations, solved films)."""
    out = []
    for line in log.splitlines():
        r = line.split()
        if len(r) == 8 and r[0].isdigit() and r[1].isdigit():
            out.append((int(r[0]), int(r[1]), float(r[5]), float(r[6]), float(r[7])))
    return out


def assert_never_gains(log):
    table = rows(log)
    energy = [r[2] for r in table]
    assert len(energy) >= 20 and energy[0] > 0.0
    assert {r[1] for r in table} == {table[0][1]}    # no atom lost
    rises = [(b - a) / energy[0] for a, b in zip(energy, energy[1:])]
    assert max(rises) <= ROUND_OFF, f"energy rose by {max(rises):.3g} E0"
    assert energy[-1] < energy[0]
    return table


ISOLATED = dense_scenes.HEADER + """region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 1 box
create_atoms 1 single -0.00106 0 0
create_atoms 1 single 0.00106 0.0003 0
set group all diameter 0.002 density 2500
velocity all set 0 0 0
set atom 1 vx 0.1 omega 0 0 20
set atom 2 vx -0.1
pair_style lubricated/springdashpot limit {limit}
pair_coeff * * 0.9 ncontact 8 viscosity 1e-3 activation 0.1 friction 0.3 shearfilm yes
neighbor 0.0002 bin
neigh_modify delay 0 every 1 check yes
fix nve all nve/sphere
timestep 2e-6
compute solve all pair lubricated/springdashpot
thermo_style custom step c_solve[3] c_solve[4]
thermo 100
run 1500
print "RESULT a $(vx[1]:%.17g) $(vy[1]:%.17g) $(y[1]:%.17g) $(x[1]:%.17g)"
print "RESULT b $(vx[2]:%.17g) $(vy[2]:%.17g) $(y[2]:%.17g) $(x[2]:%.17g)"
"""


def test_isolated_collision_is_unchanged(lmp):
    """A wet oblique collision with friction and the shear film (St ~ 100): bit-identical with
    limit implicit and limit atom; the spheres did collide and rebound."""
    atom = lmp(ISOLATED.replace("{limit}", "atom"))
    implicit = lmp(ISOLATED.replace("{limit}", "implicit"))
    assert "(limit implicit)" in lmp.log
    assert implicit["a"] == atom["a"] and implicit["b"] == atom["b"]
    assert atom["a"][0] < 0.0 < atom["b"][0]    # rebound


@pytest.mark.parametrize("extra", ["", "friction 0.3 shearfilm yes"])
def test_dense_bed_never_gains_energy(lmp, extra):
    """mu_f = 1 Pa s (St 5.6e-3), dt = 1e-6 s: the budget binds on every sphere (limit atom
    scales the films there); with limit implicit the films are solved, and the energy sampled
    every 10 steps never rises."""
    lmp(with_solve_columns(dense_scenes.fcc(1.0, 1e-6, steps=200, limit="implicit", extra=extra)))
    table = assert_never_gains(lmp.log)
    # The solve is taken at every sample while the bed moves (its first 100 steps; then the
    # kinetic energy is at round-off and the films over budget come and go).
    assert all(r[3] > 0 and r[4] > 0 for r in table[1:11])
    assert "WARNING" not in lmp.log


def test_one_and_two_ranks_agree(lmp):
    """tolerance 1e-12: the final energies of 1 and 2 ranks agree (the solve's relative residual
    bounds the velocity error by the tolerance times the kick)."""
    finals = []
    for nprocs in (1, 2):
        script = dense_scenes.fcc(1.0, 1e-6, steps=100, loop="geom", limit="implicit tolerance 1e-12")
        final = lmp(with_solve_columns(script), nprocs=nprocs)["final"]
        assert dense_scenes.ranks(lmp.log) == {nprocs}
        assert final[1] == 256
        assert rows(lmp.log)[-1][4] > 0
        finals.append(final[0])
    assert finals[1] == pytest.approx(finals[0], rel=1e-9)


# Without yielding, MPICH's ranks spin while they wait; with 4 ranks on 2 loaded cores each of the
# solve's hundreds of exchanges per step then waits for time slices (5 steps: 26 s, 4 s with it).
FOUR_RANKS = {**dense_scenes.OVERSUBSCRIBED, "MPIR_CVAR_ENABLE_HEAVY_YIELD": "1"}


def test_one_two_and_four_ranks_agree_on_a_sheared_suspension(lmp):
    """The dense sheared suspension of tests/lammps/suspension_scene.py (80 spheres at solid
    fraction 0.54, friction 0.5, St 1e-3, the affine drag in the virial), 8 steps from rest at
    tolerance tau = 1e-8 (about 130 iterations a step) on 1, 2 and 4 ranks (processor grids
    1 1 1, 1 1 2, 1 2 2). Each step's velocities lie within tau of the kick of the exact solve,
    so two rank counts differ by at most 2 tau per step, 2 N tau over N steps while the packing
    does not amplify (8 steps, strain 5e-4): the averaged and final eta_s, P / (eta_f gdot) and
    mu, the velocities and forces (relative to their largest) and the positions (in units of a)
    within 2 N tau = 1.6e-7. (Measured over 20 steps at tau = 1e-8, 1e-10 and 1e-12: 1e-11 or
    less; the ranks run the same iterations, so their difference is the round-off of the other
    summation order, not tau.)"""
    lmp(suspension_scene.packing_script(), name="in.packing", **suspension_scene.PACKING)
    steps, tolerance = 8, 1e-8
    script = suspension_scene.shear(str(lmp.dir / "packing.data"), steps=steps, tol=tolerance)
    runs = {}
    for nprocs in (1, 2, 4):
        results = lmp(script, nprocs=nprocs, name="in.shear", env=FOUR_RANKS if nprocs > 2 else None)
        assert dense_scenes.ranks(lmp.log) == {nprocs}
        assert results["iterations"] > 1.0 and "WARNING" not in lmp.log
        runs[nprocs] = results, suspension_scene.final_state(lmp.dir)
    bound = 2 * steps * tolerance
    (reference, state) = runs[1]
    for nprocs in (2, 4):
        results, other = runs[nprocs]
        for key in ("mean", "final"):
            assert results[key] == pytest.approx(reference[key], rel=bound), (nprocs, key)
        assert (other[:, 0] == state[:, 0]).all()
        assert abs(other[:, 1:4] - state[:, 1:4]).max() <= bound
        for columns in (slice(4, 7), slice(7, 10)):
            assert abs(other[:, columns] - state[:, columns]).max() <= bound * abs(state[:, columns]).max()


def test_warm_start_follows_the_atoms_across_list_builds(lmp):
    """The sheared suspension of suspension_scene.py at the example's tolerance 1e-4 (thermo every
    step) with a list build at every step (`neigh_modify ... check no`, which may reorder the
    atoms): 100 steps, 30 runs of one step (each after a set-up, so each solve starts from 0),
    100 steps. Along the shear each solve starts from the last steps' increments extrapolated,
    each atom's found by its tag (doc/film_solve.rst, "Starting guess"): the steps of the last
    100 need under half the iterations of the cold ones (measured: 25 against 68; before
    the increments followed the atoms, every step after a list build started from 0)."""
    lmp(suspension_scene.packing_script(), name="in.packing", **suspension_scene.PACKING)
    script = suspension_scene.shear(str(lmp.dir / "packing.data"), steps=100, tol=1e-4, thermo=1)
    script = script.replace("fix nve all nve/sphere", "neigh_modify delay 0 every 1 check no\nfix nve all nve/sphere")
    script = script.replace("run 100\n", "run 100\nvariable k loop 30\nlabel cold\nrun 1\nnext k\njump SELF cold\nrun 100\n", 1)
    assert "check no" in script and "jump SELF cold" in script
    lmp(script, name="in.shear")
    iterations = {}
    for row in lmp.log.splitlines():
        words = row.split()
        if len(words) == 6 and words[0].isdigit():
            iterations.setdefault(int(words[0]), float(words[5]))    # a step's row, not the set-up's after it
    assert len(iterations) == 231 and "WARNING" not in lmp.log and "Neighbor list builds = 100" in lmp.log
    cold = [iterations[s] for s in range(101, 131)]
    warm = [iterations[s] for s in range(131, 231)]
    assert np.mean(warm) < 0.5 * np.mean(cold), (np.mean(warm), np.mean(cold))


def test_hindered_drag_with_bins_joins_the_solve(lmp):
    """The sheared suspension of suspension_scene.py with a hindered drag, Richardson-Zaki's
    n = 4.65 on the solid fraction of one bin (beta about 17 times Stokes' at phi 0.54), strain
    0.2 at tolerance 1e-6: with the drag solved with the films, N_c 8 and 32 give eta_s within 3 %
    and P within 8 % (measured 0.3 % and 4 %). With that drag explicit (before the solid fraction
    was made ahead of the solve) they parted by 41 % and 95 %."""
    lmp(suspension_scene.packing_script(), name="in.packing", **suspension_scene.PACKING)
    means = {}
    for nc in (8, 32):
        script = suspension_scene.shear(str(lmp.dir / "packing.data"), steps=int(0.2 * nc / 1e-3), tol=1e-6,
                                        thermo=100000)
        script = script.replace("timestep $(v_tc/16)", f"timestep $(v_tc/{nc})")
        script = script.replace("flow affine", "flow affine hindrance richardson-zaki 4.65 bins 1 1 1")
        assert "bins 1 1 1" in script and f"v_tc/{nc}" in script
        means[nc] = lmp(script, name="in.shear")["mean"]
        assert "WARNING" not in lmp.log
    (eta_8, p_8, _), (eta_32, p_32, _) = means[8], means[32]
    assert eta_8 == pytest.approx(eta_32, rel=0.03) and p_8 == pytest.approx(p_32, rel=0.08), means


def test_fluid_velocity_from_variables_joins_the_solve(lmp):
    """The sheared suspension of suspension_scene.py (N_c 16, strain 0.1, tolerance 1e-8) with
    its fluid velocity given as an atom-style variable, u_x = gdot (y - ylo), instead of `flow
    affine`: the same field, now made when the solve asks for the drag, so the same run (eta_s
    and P to 1e-6; measured equal to every printed digit). With that drag explicit (before) eta_s
    was 25 % lower at N_c 8 and changed by 12 % from N_c 8 to 32."""
    lmp(suspension_scene.packing_script(), name="in.packing", **suspension_scene.PACKING)
    script = suspension_scene.shear(str(lmp.dir / "packing.data"), steps=1600, tol=1e-8, thermo=100000)
    affine = lmp(script, name="in.shear")["mean"]
    variable = script.replace("flow affine", "velocity v_ux 0 0")
    variable = variable.replace("fix nve all nve/sphere", "variable ux atom v_gdot*(y-ylo)\nfix nve all nve/sphere")
    assert "velocity v_ux 0 0" in variable and "variable ux atom" in variable
    by_variable = lmp(variable, name="in.shear")["mean"]
    assert "WARNING" not in lmp.log
    assert by_variable[0] == pytest.approx(affine[0], rel=1e-6) and by_variable[1] == pytest.approx(affine[1], rel=1e-6)


def test_added_mass_joins_the_solve(lmp):
    """The sheared suspension of suspension_scene.py (strain 0.2, tolerance 1e-6) with the
    fluid's added mass, `added_mass 0.5`: the fix solves each sphere's acceleration with m + m_a,
    the mass its contacts move; the solve now moves that mass and takes the drag. N_c 8 and 32
    give eta_s within 3 % (measured 0.01 %) and P within 0.05 eta_s; at St 1e-3 the fluid's
    inertia is a small correction, so eta_s lies within 5 % of the run without added mass
    (measured 2.3 %). With that drag explicit (before) eta_s was 12.8 and 14.3, 18 % and 9 %
    below, and the solve at N_c 8 did not converge within its 200 iterations."""
    lmp(suspension_scene.packing_script(), name="in.packing", **suspension_scene.PACKING)
    means = {}
    for words in ("", "added_mass 0.5"):
        for nc in (8, 32):
            script = suspension_scene.shear(str(lmp.dir / "packing.data"), steps=int(0.2 * nc / 1e-3), tol=1e-6,
                                            thermo=100000)
            script = script.replace("timestep $(v_tc/16)", f"timestep $(v_tc/{nc})")
            script = script.replace("flow affine", f"flow affine {words}")
            assert f"v_tc/{nc}" in script
            means[words, nc] = lmp(script, name="in.shear")["mean"]
            assert "WARNING" not in lmp.log
    (eta_8, p_8, _), (eta_32, p_32, _) = means["added_mass 0.5", 8], means["added_mass 0.5", 32]
    assert eta_8 == pytest.approx(eta_32, rel=0.03) and abs(p_8 - p_32) <= 0.05 * eta_32, means
    for nc in (8, 32):
        assert means["added_mass 0.5", nc][0] == pytest.approx(means["", nc][0], rel=0.05), means


def test_fluid_inertia_in_the_solve_on_one_and_two_ranks(lmp):
    """The sheared suspension with `added_mass 0.5 history yes` in the solve (the history's
    current-step weight moves with the sphere), 16 steps at tolerance tau = 1e-10 on 1 and 2
    ranks: velocities and forces within 2 N tau of their largest (as
    test_one_two_and_four_ranks_agree_on_a_sheared_suspension argues)."""
    lmp(suspension_scene.packing_script(), name="in.packing", **suspension_scene.PACKING)
    steps, tolerance = 16, 1e-10
    script = suspension_scene.shear(str(lmp.dir / "packing.data"), steps=steps, tol=tolerance)
    script = script.replace("flow affine", "flow affine added_mass 0.5 history yes")
    states = []
    for nprocs in (1, 2):
        assert lmp(script, nprocs=nprocs, name="in.shear")["iterations"] > 1.0
        assert dense_scenes.ranks(lmp.log) == {nprocs} and "WARNING" not in lmp.log
        states.append(suspension_scene.final_state(lmp.dir))
    one, two = states
    bound = 2 * steps * tolerance
    assert (one[:, 0] == two[:, 0]).all()
    for columns in (slice(4, 7), slice(7, 10)):
        assert abs(two[:, columns] - one[:, columns]).max() <= bound * abs(one[:, columns]).max()


def test_films_in_the_solve_relieve_the_contact_network(lmp):
    """The sheared suspension of suspension_scene.py with the example's stiffer contacts (gdot t_c
    2.5e-4), strain 0.4 from rest: at N_c 2 its contact network is unstable for the check without
    films (lower bound 4.9: `limit atom` stops with the check's ERROR), but every contact's own
    film is in the solve, which acts on the step's end velocity, so the step is stable where S < 4
    I + 2 D (contact_network.h) and the check lets it run. eta_s within 4 % and P within 10 % of
    N_c 16 (measured 2.0 % and 7.4 %, the start-up transient), no WARNING; on 2 ranks with newton
    off (a film with a ghost partner on both ranks) the same run to 1e-6 (measured 1e-8)."""
    lmp(suspension_scene.packing_script(), name="in.packing", **suspension_scene.PACKING)

    def script(nc, limit):
        text = suspension_scene.shear(str(lmp.dir / "packing.data"), steps=int(0.4 * nc / 2.5e-4), tol=1e-6,
                                      thermo=100000)
        text = text.replace("timestep $(v_tc/16)", f"timestep $(v_tc/{nc})")
        text = text.replace("variable tc equal 0.001/v_gdot", "variable tc equal 2.5e-4/v_gdot")
        text = text.replace("limit implicit tolerance 1e-06", f"{limit} iterations 1000")
        assert "2.5e-4/v_gdot" in text and f"{limit} iterations" in text
        return text

    lmp(script(2, "limit atom").replace(" iterations 1000", ""), check=False)
    assert "is too short a contact for this packing" in lmp.log
    means = {}
    for nc in (2, 16):
        means[nc] = lmp(script(nc, "limit implicit tolerance 1e-6"), name="in.shear")["mean"]
        assert not [line for line in lmp.log.splitlines() if line.startswith("WARNING") and "drifts" not in line]
    (eta_2, p_2, _), (eta_16, p_16, _) = means[2], means[16]
    assert eta_2 == pytest.approx(eta_16, rel=0.04) and p_2 == pytest.approx(p_16, rel=0.10), means
    two = lmp(script(2, "limit implicit tolerance 1e-6").replace("newton on", "newton off"), nprocs=2,
              name="in.shear")["mean"]
    assert dense_scenes.ranks(lmp.log) == {2} and "newton off" in lmp.log
    assert two == pytest.approx(means[2], rel=1e-6)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_split_run_in_a_sheared_box_goes_on_as_one(lmp, nprocs):
    """The sheared suspension of suspension_scene.py (fix deform xy erate ... remap v), 16 steps
    at tolerance 1e-10 in one run and as run 8 + run 8. The second run's set-up evaluates as the
    last step did (fix_step_velocity.h), ghosts included: a ghost that is an image across the
    sheared boundary moves with its owner's velocity plus gdot L_y, as LAMMPS communicates it.
    Without that shift the set-up's films across the boundary saw a relative velocity of
    gdot L_y and the split run's velocities parted from the single run's by 2.6e-3 of the
    largest (forces 0.14). What remains is the box's last move, which fix deform makes after the
    forces of a step and the set-up sees (images across the boundary displaced by gdot dt L_y):
    1.3e-5 of the velocities, 3e-4 of the forces. Bounds: 1e-4 and 3e-3. On 2 ranks the images
    across the boundary are sent by the periodic swaps alone, as on 1."""
    lmp(suspension_scene.packing_script(), name="in.packing", **suspension_scene.PACKING)
    script = suspension_scene.shear(str(lmp.dir / "packing.data"), steps=16, tol=1e-10)
    states = []
    for name, text in (("one", script), ("split", script.replace("run 16\n", "run 8\nrun 8\n"))):
        lmp(text, name=f"in.{name}", nprocs=nprocs)
        assert "WARNING" not in lmp.log and dense_scenes.ranks(lmp.log) == {nprocs}
        states.append(suspension_scene.final_state(lmp.dir))
    one, split = states
    assert (one[:, 0] == split[:, 0]).all()
    assert abs(split[:, 4:7] - one[:, 4:7]).max() <= 1e-4 * abs(one[:, 4:7]).max()
    assert abs(split[:, 7:10] - one[:, 7:10]).max() <= 3e-3 * abs(one[:, 7:10]).max()


def test_iteration_limit_warns_once(lmp):
    """iterations 1 cannot reach the tolerance: one WARNING naming tolerance and iterations."""
    lmp(with_solve_columns(dense_scenes.fcc(1.0, 1e-6, steps=20, limit="implicit iterations 1")))
    warnings = [line for line in lmp.log.splitlines() if line.startswith("WARNING") and "film solve" in line]
    assert len(warnings) == 1
    assert "tolerance 1e-08" in warnings[0] and "iterations 1" in warnings[0]


BAD = {
    "tolerance 0": "tolerance = 0 is not allowed (a number in (0, 1))",
    "tolerance -1": "tolerance = -1 is not allowed (a number in (0, 1))",
    "tolerance 2": "tolerance = 2 is not allowed (a number in (0, 1))",
    "iterations 0": "iterations = 0 is not allowed (an integer from 1 to 1e9)",
    "iterations 2.5": "iterations = 2.5 is not allowed",
    "tolerance": "keyword tolerance needs a value",
    "tolerances 1e-6": "unknown keyword 'tolerances'",
}


@pytest.mark.parametrize("words", list(BAD))
def test_bad_keywords(lmp, words):
    script = dense_scenes.fcc(1.0, 1e-6, steps=1, limit="implicit " + words)
    lmp(script, check=False)
    assert "ERROR" in lmp.log and BAD[words] in lmp.log


def test_solve_keywords_need_limit_implicit(lmp):
    lmp(dense_scenes.fcc(1.0, 1e-6, steps=1, limit="atom tolerance 1e-6"), check=False)
    assert "tolerance and iterations belong to limit implicit" in lmp.log


def test_restart_keeps_the_mode(lmp):
    """write_restart after 10 steps with limit implicit tolerance 1e-10 iterations 1; a new
    process that reads it (no pair_style command) solves the films with both settings: its
    warning names them."""
    first = dense_scenes.split(dense_scenes.fcc(1.0, 1e-6, steps=20, limit="implicit tolerance 1e-10 iterations 1"),
                               "run 10", "write_restart mid.restart")
    lmp(with_solve_columns(first))
    lmp(with_solve_columns(dense_scenes.restarted(1e-6, 10)))
    assert "(limit implicit)" in lmp.log
    assert rows(lmp.log)[-1][4] > 0
    warning = next(line for line in lmp.log.splitlines() if line.startswith("WARNING") and "film solve" in line)
    assert "tolerance 1e-10" in warning and "iterations 1 " in warning


def test_newton_off_matches_newton_on(lmp):
    """With newton pair off each film with a ghost partner is recorded on both ranks and solved
    by one: 1 and 2 ranks with newton off give newton on's final energy (tolerance 1e-12; 30
    steps, the energy 1e-6 of E0: the films are summed in another order)."""
    script = dense_scenes.fcc(1.0, 1e-6, steps=30, loop="geom", limit="implicit tolerance 1e-12")
    reference = lmp(script)["final"][0]
    off = script.replace("newton on", "newton off")
    for nprocs in (1, 2):
        final = lmp(with_solve_columns(off), nprocs=nprocs)["final"]
        assert dense_scenes.ranks(lmp.log) == {nprocs}
        assert rows(lmp.log)[-1][4] > 0
        assert final[0] == pytest.approx(reference, rel=1e-10)


STRESS = """compute sa all stress/atom NULL pair
compute ssum all reduce sum c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6]
compute p all pressure NULL pair
variable pxy_atoms equal -c_ssum[4]/vol
variable pxx_atoms equal -c_ssum[1]/vol
run 0
print "RESULT stress $(c_p[1]:%.17g) $(v_pxx_atoms:%.17g) $(c_p[4]:%.17g) $(v_pxy_atoms:%.17g)"
"""


@pytest.mark.parametrize("nprocs", [1, 2])
def test_solved_films_are_in_the_virial(lmp, nprocs):
    """compute pressure (the global virial, f.r over owned and ghost atoms) and the sum of
    compute stress/atom (each pair's tally) agree with the solved films, which dominate the
    stress of the bed: both see every solved film force."""
    script = dense_scenes.fcc(1.0, 1e-6, steps=20, loop="geom", limit="implicit",
                              extra="friction 0.3 shearfilm yes")
    stress = lmp(script.replace("run 20\n", "run 20\n" + STRESS), nprocs=nprocs)["stress"]
    assert stress[1] == pytest.approx(stress[0], rel=1e-9)
    assert stress[3] == pytest.approx(stress[2], rel=1e-9, abs=1e-9 * abs(stress[0]))


# ------------------------------------------------------------------------------------------
# The polydisperse dense packings of test_dense_packings.py (radii 1:10) with limit implicit:
# their energy criteria, and the solve taken.
# ------------------------------------------------------------------------------------------

from test_dense_packings import (ROUND_OFF as STRICT, assert_bounded, dt_for, mu_for,  # noqa: E402,F401
                                 packings, run_energy, walled_scene, with_velocities)
import dense_packings as dp  # noqa: E402


def implicit_was_solved(log):
    """The mode logged. (The 1:10 beds with contacts may warn: at St 1e-3 a few steps' solves
    stop at 200 iterations with a relative residual of 1e-8 to 3e-7; the energy criteria hold.)"""
    assert "(limit implicit)" in log


def test_gapped_polydisperse_bed_without_contact_never_gains(lmp, packings):
    """Strict (films alone, St 1e-3, dt 5e-4 R_min/U, 500 steps): ke + erot never rises beyond
    1e-12 E0, and the films dissipate."""
    script = dp.energy_scene(with_velocities(lmp, packings["gapped"]), mu_for(1e-3), dt_for(5e-4), 500, every=1,
                             limit="implicit")
    rows, log = run_energy(lmp, script)
    implicit_was_solved(log)
    assert len(rows) == 501 and set(rows[:, 1]) == {dp.N_ATOMS}
    assert not rows[:, 4].any()
    energy = rows[:, 2] + rows[:, 3]
    assert np.diff(energy).max() <= STRICT * energy[0]
    assert energy[-1] < 0.5 * energy[0]


@pytest.mark.parametrize("bed", ["gapped", "preloaded"])
def test_polydisperse_bed_with_contacts_never_gains(lmp, packings, bed):
    """Bounded (test_dense_packings.py): St 1e-3, dt 5e-3 R_min/U, 500 steps."""
    script = dp.energy_scene(with_velocities(lmp, packings[bed]), mu_for(1e-3), dt_for(5e-3), 500, every=10,
                             limit="implicit")
    rows, log = run_energy(lmp, script)
    implicit_was_solved(log)
    energy = assert_bounded(rows, rows[0, 2] + rows[0, 3] + rows[0, 4])
    assert energy[-1] <= energy[0]


def test_bed_settling_on_wet_walls_never_gains(lmp, packings):
    """The walled bed with the shear film on pairs and walls (mu_f 10 Pa s, 5e-5 s, 1000 steps):
    the pairs' and the walls' films of spheres over budget solved together."""
    rows, log = run_energy(lmp, walled_scene(lmp, packings, 10.0, 5e-5, 1000, limit="implicit",
                                             extra="shearfilm yes"))
    implicit_was_solved(log)
    energy = assert_bounded(rows, rows[0, 2] + rows[0, 3] + rows[0, 4] + rows[0, 5])
    assert rows[-1, 5] < rows[0, 5]
    assert energy[-1] < energy[0]


def test_midpoint_integrator_is_refused(lmp):
    script = dense_scenes.fcc(1.0, 1e-6, steps=1, limit="implicit")
    lmp(script.replace("fix nve all nve/sphere", "fix nve all nve/sphere/midpoint"), check=False)
    assert "limit implicit is not available with fix nve/sphere/midpoint" in lmp.log


@pytest.mark.parametrize("scene", ["preloaded", "compression"])
def test_contacts_without_their_own_film_still_stop_the_run(lmp, packings, scene):
    """N_c = 2 under limit implicit where the contacts' own films do not carry the network: the
    preloaded 1:10 bed at St 1e-3 (overlaps up to a quarter of the smaller radius, beyond the
    films' release) and the wet compression from 0.46 to 0.70 (mu_f 10 Pa s, friction and shear
    film). The check stops both with its ERROR before any atom is lost (with the check disabled:
    `Lost atoms` within 500 and 200 steps; with every film of the two spheres counted in the
    lower bound, the compression lost atoms after a WARNING)."""
    if scene == "preloaded":
        script = dp.energy_scene(with_velocities(lmp, packings["preloaded"]), mu_for(1e-3), dt_for(5e-3), 500,
                                 every=10, e_d=0.9, contact="ncontact 2", limit="implicit")
    else:
        script = dp.compression_scene(str(packings["loose46"]), 10.0, 5e-5, 200, 0.70, contact="ncontact 2")
        script = script.replace("pair_style lubricated/springdashpot\n", "pair_style lubricated/springdashpot limit implicit\n")
    assert "limit implicit" in script
    with pytest.raises(lammps_run.LammpsError) as err:
        lmp(script)
    assert "ncontact = 2 is too short a contact for this packing" in str(err.value)
    assert "Lost atoms" not in err.value.log

"""1, 2 and 4 MPI ranks, newton on and off, restarts, and the vectorised and general pair loops
give the same trajectories.

Relative tolerance 1e-10 (the issue's): the ranks only reorder floating-point sums (and the
vectorised loops evaluate the logarithm inline, within a few units in the last place).
"""
import re
import pytest

import dense_scenes
import scenes
from scene_chain import chain, dump_state


def assert_same_state(a, b, rel=1e-10):
    assert a.keys() == b.keys() and len(a) >= 16
    for key in a:
        assert b[key] == pytest.approx(a[key], rel=rel, abs=1e-13), key


def collisions_happened(log):
    """The scene is only a test if pairs collided: kinetic energy must have been lost."""
    rows = [line.split() for line in log.splitlines()]
    ke = [float(r[1]) for r in rows if len(r) == 4 and r[0].isdigit()]
    return ke[-1] < 0.9 * ke[0]


@pytest.mark.parametrize("nprocs", [2, 4])
@pytest.mark.parametrize("newton", ["on", "off"])
def test_one_and_more_ranks_agree(lmp, newton, nprocs):
    """The isolated collisions of the chain (several across rank boundaries), with the film
    budget and the network check in their default state: the same on 1, 2 and 4 ranks."""
    serial = lmp(chain(newton) + dump_state())
    assert collisions_happened(lmp.log)
    parallel = lmp(chain(newton) + dump_state(), nprocs=nprocs, env=dense_scenes.OVERSUBSCRIBED)
    assert dense_scenes.ranks(lmp.log) == {nprocs}
    assert_same_state(serial, parallel)


def test_newton_on_and_off_agree(lmp):
    assert_same_state(lmp(chain("on") + dump_state()), lmp(chain("off") + dump_state()))


@pytest.mark.parametrize("nprocs", [1, 2])
def test_restart_continues_the_run(lmp, nprocs):
    """run 600  ==  run 300; write_restart; run 300  ==  read_restart; run 300 (pair_coeff from
    the file): the set-up of a run that continues the last one evaluates as its last step did
    (the last step's velocities restored, src/fix_step_velocity), so neither the split nor the
    restart changes the wet collisions under way (before: e off by up to 2.4 %)."""
    single = lmp(chain(steps=600) + dump_state(), nprocs=nprocs)
    reference = lmp(chain(steps=300, extra_run="write_restart mid.restart\nrun 300") + dump_state(),
                    nprocs=nprocs)
    restarted = lmp(continue_from_restart("fix nve all nve/sphere"), nprocs=nprocs, name="in.restart")
    assert "pair_coeff" not in (lmp.dir / "in.restart").read_text()
    assert_same_state(single, reference, rel=1e-12)
    assert_same_state(reference, restarted, rel=1e-12)


def continue_from_restart(integrator_fix, wall_extra=""):
    """read_restart mid.restart, the fixes again (integrator_fix is the whole fix line), run 300."""
    mu = 2.0 / 9.0 * 8000 * 1e-3 * 0.1 / 100
    return f"""plugin load ${{plugin}}
read_restart mid.restart
comm_modify vel yes
fix walls all wall/lubrication 0.7 viscosity {mu} grid 1.25e-4 {wall_extra} xplane -0.008 0.008
{integrator_fix}
timestep {0.005 * 1e-3 / 0.1}
neighbor {0.3e-3} bin
run 300
""" + dump_state()


@pytest.mark.parametrize("nprocs", [1, 2])
def test_midpoint_integrator_restarts_and_runs_in_parallel(lmp, nprocs):
    """fix nve/sphere/midpoint keeps V^(n-1) through restarts and migration."""
    # The printed forces use V~, so the stored V^(n-1) matters (the step-exact ones use V^n).
    script = chain(steps=300, extra_run="write_restart mid.restart\nrun 300").replace(
        "fix nve all nve/sphere", "fix nve all nve/sphere/midpoint").replace(
        "activation 0.09375", "activation 0.09375 integration sampled").replace(
        "grid 1.25e-4", "grid 1.25e-4 integration sampled")
    reference = lmp(script + dump_state(), nprocs=nprocs)
    serial = lmp(script + dump_state(), nprocs=1)
    assert_same_state(reference, serial)
    restarted = lmp(continue_from_restart("fix nve all nve/sphere/midpoint", "integration sampled"),
                    nprocs=nprocs, name="in.restart")
    assert_same_state(reference, restarted)
    # Without the stored V^(n-1) (a fix of another ID) the continuation differs: the test can fail.
    fresh = lmp(continue_from_restart("fix other all nve/sphere/midpoint", "integration sampled"),
                nprocs=nprocs, name="in.fresh")
    assert any(fresh[k] != pytest.approx(reference[k], rel=1e-10, abs=1e-13) for k in reference)


def test_midpoint_integrator_ignores_a_later_runs_setup(lmp):
    """Under fix nve/sphere/midpoint only an atom's first step uses the set-up forces (its
    second-order first drift): run 300; run 300 == run 600, with the step-exact contact and
    film (a set-up of the second run that leaked into its first step would differ)."""
    script = chain(steps=600).replace("fix nve all nve/sphere", "fix nve all nve/sphere/midpoint")
    whole = lmp(script + dump_state())
    assert collisions_happened(lmp.log)
    split = lmp(chain(steps=300, extra_run="run 300").replace(
        "fix nve all nve/sphere", "fix nve all nve/sphere/midpoint") + dump_state())
    assert_same_state(whole, split, rel=1e-13)




VECTOR_CASES = {
    # one model for all type pairs
    "wet": "pair_coeff * * 0.8 ncontact 8 {film}",
    "dry": "pair_coeff * * 0.8 ncontact 8",
    # the entry loss: contacts that start or end take the general loop
    "wet legendre": "pair_coeff * * 0.8 ncontact 8 {film} legendre 35",
    # a model per type pair, dry and wet mixed: grouped by type pair
    "mixed": "pair_coeff 1 1 0.8 ncontact 8 {film}\npair_coeff 1 2 0.6 ncontact 6\n"
             "pair_coeff 2 2 0.9 ncontact 10 viscosity {mu2} grid 1e-4",
    # friction and rolling (the shear film on by default): the pairs apart over a step take the
    # film loop with the shear film
    "wet friction": "pair_coeff * * 0.8 ncontact 8 {film} friction 0.4 rolling 0.02",
    "mixed friction": "pair_coeff 1 1 0.8 ncontact 8 {film} friction 0.3 shearfilm no\n"
                      "pair_coeff 1 2 0.6 ncontact 6 friction 0.5\n"
                      "pair_coeff 2 2 0.9 ncontact 10 viscosity {mu2} grid 1e-4 rolling 0.02 shearfilm no",
}


@pytest.mark.parametrize("case", VECTOR_CASES)
def test_vectorised_loops_agree_with_the_general_loop(lmp, case):
    """Pairs in sustained contact, contacts that start or end within a step (without legendre)
    and pairs apart over a step (the film alone) take vectorised loops, by default; `pair_style
    lubricated/springdashpot vector no` takes every pair through the general loop. Same
    trajectories, spring energy and virial."""
    mu = scenes.viscosity_for_stokes(100)
    small_spheres_type_2 = "\n".join(f"set atom {k} type 2" for k in range(2, 9, 2))
    coefficients = VECTOR_CASES[case].format(film=f"viscosity {mu} activation 0.09375", mu2=2 * mu)
    two_types = chain().replace("create_box 1 box", "create_box 2 box").replace(
        "pair_style", small_spheres_type_2 + "\npair_style").replace(
        f"pair_coeff * * 0.8 ncontact 8 viscosity {mu} activation 0.09375", coefficients)
    assert coefficients in two_types
    # Every 10 steps: the spring energy and the pressure (virial) tallied by the loops too.
    two_types = two_types.replace("thermo 100\nthermo_style custom step ke pe f_walls",
                                  "thermo 10\nthermo_style custom step ke pe press")
    spins = 'compute spin all erotate/sphere\nrun 0\nprint "RESULT w $(c_spin:%.17g) $(ke:%.17g)"\n'
    two_types += spins if "friction" in case else ""
    vectorised = lmp(two_types + dump_state())
    assert ("take the vectorised film loop" if "friction" in case else "take vectorised loops") in lmp.log
    assert collisions_happened(lmp.log)
    vectorised_thermo = thermo_rows(lmp.log)
    general = two_types.replace("pair_style lubricated/springdashpot",
                                "pair_style lubricated/springdashpot vector no")
    reference = lmp(general + dump_state())
    assert "vectorised" not in lmp.log
    assert_same_state(vectorised, reference)
    if "friction" in case:    # friction acts: the spheres spin (rotational against translational energy)
        assert vectorised["w"][0] > 1e-3 * vectorised["w"][1]
    reference_thermo = thermo_rows(lmp.log)
    assert len(vectorised_thermo) == (62 if "friction" in case else 61) and sum(row[2] > 0.0 for row in vectorised_thermo) >= 3
    for mine, theirs in zip(vectorised_thermo, reference_thermo):
        assert mine == pytest.approx(theirs, rel=1e-10, abs=1e-20)


def test_vector_setting_survives_a_restart(lmp):
    """`vector no` is stored in the restart file with the coefficients."""
    script = chain(steps=10, extra_run="write_restart mid.restart").replace(
        "pair_style lubricated/springdashpot", "pair_style lubricated/springdashpot vector no")
    lmp(script)
    assert "take vectorised loops" not in lmp.log
    lmp(continue_from_restart("fix nve all nve/sphere"), name="in.restart")
    assert "pair_style" not in (lmp.dir / "in.restart").read_text()
    assert "take vectorised loops" not in lmp.log
    lmp(chain(steps=10, extra_run="write_restart mid.restart"))
    lmp(continue_from_restart("fix nve all nve/sphere"), name="in.restart")
    assert "take vectorised loops" in lmp.log


def test_limit_setting_survives_a_restart(lmp):
    """`limit pair` is stored in the restart file with `vector` (one flag word)."""
    wet = "pair_coeff * * 0.9 ncontact 8 viscosity 1e-3 activation 0.1"
    script = chain(steps=10, extra_run="write_restart mid.restart").replace(
        "pair_style lubricated/springdashpot", "pair_style lubricated/springdashpot vector no limit pair")
    script = re.sub(r"pair_coeff \* \* .*", wet, script)
    lmp(script)
    assert "(limit pair)" in lmp.log
    lmp(continue_from_restart("fix nve all nve/sphere"), name="in.restart")
    assert "(limit pair)" in lmp.log and "take vectorised loops" not in lmp.log
    lmp(re.sub(r"pair_coeff \* \* .*", wet, chain(steps=10, extra_run="write_restart mid.restart")))
    lmp(continue_from_restart("fix nve all nve/sphere"), name="in.restart")
    assert "(limit atom)" in lmp.log and "take vectorised loops" in lmp.log


def thermo_rows(log):
    """The numeric rows of the thermo output (step ke pe press)."""
    rows = [line.split() for line in log.splitlines()]
    return [[float(v) for v in r] for r in rows if len(r) == 4 and r[0].isdigit()]


@pytest.mark.parametrize("nprocs", [1, 2])
def test_data_file_keeps_the_pair_coefficients(lmp, nprocs):
    """`write_data ... pair ij` writes every type pair's pair_coeff words, read_data gives them
    back to the pair style (no pair_coeff after it), and the run continues (before: no
    coefficients were written, and read_data left the style unset). A data file holds the
    full-step velocities and no forces, so its run starts its contacts anew from (x, v) as any
    first run does (contact_step.h: exact for an isolated pair, O(dt^2) of a many-body
    contact's impulse): the same run as the split one to 1e-4 R in position and 1e-3 U in
    velocity after 300 steps, not to rounding (a restart file continues exactly, test above)."""
    reference = lmp(chain(steps=300, extra_run="write_data mid.data pair ij\nrun 300") + dump_state(),
                    nprocs=nprocs)
    data = (lmp.dir / "mid.data").read_text()
    assert "PairIJ Coeffs" in data and "1 1 0.80000000000000004 ncontact 8 viscosity" in data
    mu = 2.0 / 9.0 * 8000 * 1e-3 * 0.1 / 100
    continued = lmp(scenes.HEADER.replace("${newton}", "on").replace("boundary p p f", "boundary f p p") + f"""
pair_style lubricated/springdashpot
read_data mid.data
fix walls all wall/lubrication 0.7 viscosity {mu} grid 1.25e-4 xplane -0.008 0.008
fix nve all nve/sphere
timestep {0.005 * 1e-3 / 0.1}
neighbor {0.3e-3} bin
run 300
""" + dump_state(), nprocs=nprocs, name="in.data")
    assert "pair_coeff" not in (lmp.dir / "in.data").read_text()
    assert reference.keys() == continued.keys()
    for key in reference:
        scale = 1e-4 * 1e-3 if key.startswith("x") else 1e-3 * 0.1    # 1e-4 R, 1e-3 U
        assert continued[key] == pytest.approx(reference[key], rel=0, abs=scale), key

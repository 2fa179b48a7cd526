"""Dense wet beds in LIGGGHTS (issue 17): the films of many neighbours never add energy.

`model lubricated` shares the LAMMPS plugin's many-body film budget (film_budget.h; in LIGGGHTS
fix_lubricated_film_budget.h): each film is scaled by 1 / max(1, D_i, D_j), D the sum of the
shares of its atoms' films, pair and wall. Before it (as `lubricatedLimitPair 1` still does)
the scenes below gained up to 2e6 E0 and the wet settling bed at 1 Pa s gained 46 E0 (issue:
x37 and 2254 atoms down to 1238 over 20000 steps).

Scenes (tools/liggghts_dense_scenes.py): 256 spheres on an fcc lattice and a 13-sphere cluster,
every gap inside the film, no gravity, St 1e-3 to 1e3, dt from 2e-4 to 10 times the documented
step 0.005 R / U = 5e-4 s. LIGGGHTS tallies no spring energy, so three checks:
- the energy of motion ke + erot never exceeds E0 (every gap is open at the start, so E0 is the
  whole energy; the spring energy is never negative), no atom is lost and the bed dissipates;
- where no pair touches at any sample, the films alone act: ke + erot may not rise between
  samples beyond round-off (1e-12 E0, 256-term sums);
- where the films dominate (St <= 10, dt <= 1e-4 s) the LAMMPS plugin runs the same scene
  (same kernel, same budget) and LIGGGHTS's energy of motion equals its ke + erot at every
  sample to 1e-9 E0 (measured at most 1.2e-11 E0; the round-off of different summation orders
  grows through the contacts), while the LAMMPS total with the spring energy never rises.
"""
import pathlib

import pytest

import lammps_run
import liggghts_dense_scenes as dense
import liggghts_scenes
import scenes

ROOT = pathlib.Path(__file__).resolve().parents[2]
ROUND_OFF = 1e-12
SAME_TRAJECTORY = 1e-9
STEP, ATOMS, KE, EROT, CONTACTS, MOTION, PE, TOTAL = range(8)

STOKES = [1e-3, 0.1, 10.0, 1e3]
STEPS = [1e-7, 1e-5, 1e-4, 5e-3]


def scene_run(run, scene, st, dt, engine="liggghts", nprocs=1, **kwargs):
    # At most 0.1 s of flight (the films close the gaps in ~2e-4 s): the open cluster may not
    # leave its box at 10 times the documented step.
    steps = min(1000, round(0.1 / dt))
    script = getattr(dense, scene)(dense.viscosity_for_stokes(st), dt, steps=steps,
                                   every=max(1, steps // 100), engine=engine, **kwargs)
    if engine == "lammps":
        results, log = lammps_run.run(script, run.dir / "lammps", nprocs=nprocs)
    else:
        run.lig(script, nprocs=nprocs)
        log = run.log
    return dense.rows(log)


@pytest.mark.parametrize("scene", ["fcc", "cluster"])
@pytest.mark.parametrize("dt", STEPS)
@pytest.mark.parametrize("st", STOKES)
def test_dense_films_never_raise_the_energy(run, scene, st, dt):
    rows = scene_run(run, scene, st, dt)
    e0 = rows[0][MOTION]
    assert len(rows) >= 20 and e0 > 0.0
    assert {r[ATOMS] for r in rows} == {rows[0][ATOMS]}
    assert max(r[MOTION] for r in rows) <= e0 * (1.0 + ROUND_OFF)
    assert rows[-1][MOTION] < e0
    if all(r[CONTACTS] == 0 for r in rows):
        rises = [(b[MOTION] - a[MOTION]) / e0 for a, b in zip(rows, rows[1:])]
        assert max(rises) <= ROUND_OFF, f"films alone raised the energy by {max(rises):.3g} E0"
    if st <= 10.0 and dt <= 1e-4:
        reference = scene_run(run, scene, st, dt, engine="lammps")
        assert len(reference) == len(rows)
        assert max(abs(a[MOTION] - b[MOTION]) for a, b in zip(rows, reference)) <= SAME_TRAJECTORY * e0
        rises = [b[TOTAL] - a[TOTAL] for a, b in zip(reference, reference[1:])]
        assert max(rises) <= ROUND_OFF * reference[0][TOTAL]


@pytest.mark.parametrize("scene", ["fcc", "cluster"])
def test_per_pair_caps_alone_gain_energy(run, scene):
    """`lubricatedLimitPair 1`: each film capped on its own, as before the budget (measured:
    fcc 2.7e5 E0, cluster 5e5 E0)."""
    rows = scene_run(run, scene, dense.stokes(1.0), 1e-6, limit="pair")
    assert max(r[MOTION] for r in rows) > 1e3 * rows[0][MOTION]


@pytest.mark.parametrize("scene", ["fcc", "cluster"])
@pytest.mark.parametrize("newton", ["off", "on"])
def test_one_two_and_four_ranks_agree(run, scene, newton):
    """Loads summed on their owners (newton on: reverse communication), scales sent to the
    ghosts, corrections of ghost forces summed after LIGGGHTS's own: the same run on 1, 2 and 4
    ranks (measured: 6e-14 E0 apart)."""
    rows = {}
    for nprocs in (1, 2, 4):
        rows[nprocs] = scene_run(run, scene, dense.stokes(1.0), 1e-6, nprocs=nprocs, newton=newton)
        assert len([line for line in run.log.splitlines() if "MPI processor grid" in line]) == 1
        grid = next(line for line in run.log.splitlines() if "MPI processor grid" in line).split()
        assert int(grid[0]) * int(grid[2]) * int(grid[4]) == nprocs
    e0 = rows[1][0][MOTION]
    for nprocs in (2, 4):
        assert len(rows[nprocs]) == len(rows[1])
        assert max(abs(a[MOTION] - b[MOTION]) for a, b in zip(rows[nprocs], rows[1])) <= 1e-12 * e0


def settling_bed(steps, limit="atom"):
    """examples/liggghts/in.settling_bed, wet at mu_f = 1 Pa s (St ~ 0.02 at the impact speeds
    of the settling), with the energy ke + erot + m g' z (g' the reduced gravity) every 100 steps."""
    script = (ROOT / "examples" / "liggghts" / "in.settling_bed").read_text()
    script = script.replace("variable mu      equal 1.0e-3", "variable mu      equal 1.0")
    script = script.replace("thermo_style    custom step atoms ke c_zmax",
                            "compute rot all erotate/sphere\nvariable pz atom mass*v_g*z\n"
                            "compute pg all reduce sum v_pz\nvariable E equal ke+c_rot+c_pg\n"
                            "thermo_style    custom step atoms ke c_rot c_zmax v_E")
    script = script.replace("thermo          5000", "thermo          100\nthermo_modify   format float %.17g")
    return script, {"wet": 1, "steps": steps, "limit": 1 if limit == "pair" else 0}


def bed_energies(log):
    rows = [line.split() for line in log.splitlines()]
    rows = [r for r in rows if len(r) == 6 and r[0].isdigit() and "by" not in r]
    return [float(r[5]) for r in rows], [int(r[1]) for r in rows]


def test_wet_settling_bed_at_one_pascal_second(run):
    """Gravity, a wet floor and 2254 spheres with friction, 2 ranks, the example's own step:
    ke + erot + m g' z never exceeds E0 (the spheres start at rest: E0 is all potential, and
    the spring energy is never negative), no atom is lost, and the bed settles."""
    script, variables = settling_bed(20000)
    result = run.lig(script, nprocs=2, variables=variables)
    energy, atoms = bed_energies(run.log)
    assert len(energy) == 201 and set(atoms) == {2254} and result["atoms"] == 2254
    assert max(energy) <= energy[0] * (1.0 + ROUND_OFF)
    assert energy[-1] < 0.8 * energy[0] and result["top"] < 34.0


def test_settling_bed_with_per_pair_caps_alone_gains_energy(run):
    """The check above fails as the issue found it: 46 E0 within 8000 steps (measured)."""
    script, variables = settling_bed(8000, limit="pair")
    run.lig(script, variables=variables)
    energy, _ = bed_energies(run.log)
    assert max(energy) > 10.0 * energy[0]


@pytest.mark.parametrize("mu,dt", [(10.0, 1e-5), (1.0, 1e-6)])
def test_floor_added_after_a_run_joins_the_budget(run, mu, dt):
    """The budget fix is kept after every fix wall/gran, since a wall records the films of a
    run's set-up in its own setup: a floor defined after a `run 0` gives, to the last digit,
    the run with the floor from the start. The lowest spheres of the cluster start inside the
    floor's film and the films of the spheres above (measured with the fix left before the
    floor: ke 2.3e-14 J and 1.46e-13 J instead of 1.96e-13 J and 1.94e-13 J)."""
    first = run.lig(dense.cluster_on_floor(mu, dt))
    late = run.lig(dense.cluster_on_floor(mu, dt, floor_late=True), name="in.late")
    assert late["ke"] == first["ke"]


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("e_dry", [1.0, 0.9, 0.5])
def test_frozen_partner_rebounds_with_e_dry(run, e_dry, nprocs):
    """A sphere in fix freeze's group moves with no contact: m_e is the mover's mass, as
    LIGGGHTS's own overlap branch has it; the film and the step-exact contact's entry now use
    it too (before: e = 0.8992 at e_d 0.9, 0.511 at 0.5). Step-exact: e_d to round-off."""
    result = run.lig(liggghts_scenes.frozen_pair(e_dry), nprocs=nprocs)
    assert result["e"] == pytest.approx(e_dry, rel=1e-9)
    assert result["v2"] == 0.0


@pytest.mark.parametrize("e_dry", [0.9, 0.5])
def test_wet_frozen_partner_matches_lammps(run, e_dry):
    """Wet (St 50 of the free pair): the held partner's film with m_e = m_i, as the LAMMPS
    plugin's contact masses give it (measured: the same to 1e-15; the free pair 0.445)."""
    from test_frozen_partners import frozen_pair
    mu = scenes.viscosity_for_stokes(50)
    ours = run.lig(liggghts_scenes.frozen_pair(e_dry, mu=mu))
    lammps = run.lmp(frozen_pair(e_dry, "freeze", wet=f"viscosity {mu} activation {scenes.EPS_AL}")
                     .replace("${newton}", "on"))
    assert ours["e"] == pytest.approx(lammps["e"], rel=1e-9)
    free = run.lig(liggghts_scenes.frozen_pair(e_dry, mu=mu, frozen=False))
    assert ours["e"] > free["e"]


@pytest.mark.parametrize("value", ["2", "0.5", "-1"])
def test_limit_pair_takes_zero_or_one(run, value):
    script = dense.cluster(1.0, 1e-6, steps=10).replace(
        "pair_style gran", f"fix m5 all property/global lubricatedLimitPair scalar {value}\npair_style gran")
    with pytest.raises(lammps_run.LammpsError, match=f"lubricatedLimitPair = {value}"):
        run.lig(script)


# ------------------------------------------------------------------------------------------
# The contact network (lubricated/contact_network.h): contacts too short for the packing
# ------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def preloaded():
    """The LAMMPS tests' random 1:10 packing at solid fraction 0.70 (300 spheres, 592 sustained
    contacts), built by the LAMMPS plugin, with random velocities: LIGGGHTS reads the data file."""
    import dense_packings
    if not lammps_run.PLUGIN.exists():
        pytest.skip(f"{lammps_run.PLUGIN} is missing: run 'make build'")
    root = ROOT / "build" / "test-scratch-liggghts" / "packings"
    data, _ = dense_packings.build(root / "p70", 0.70)
    return dense_packings.with_velocities(data, root / "start.data")


def packing_run(data, duration, dt=5e-6, steps=500):
    import dense_packings
    return f"""atom_style granular
atom_modify map array
communicate single vel yes
newton off
units si
boundary p p p
read_data {data}
fix m1 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m2 all property/global {duration}
pair_style gran model lubricated
pair_coeff * *
neighbor {0.2 * dense_packings.R_MIN} bin
neigh_modify delay 0
fix nve all nve/sphere
timestep {dt}
thermo_style custom step atoms ke
thermo_modify lost error
thermo 50
run {steps}
variable n equal atoms
print "RESULT atoms ${{n}}"
"""


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("duration,named", [
    ("lubricatedContactSteps scalar 2", "lubricatedContactSteps = 2 "),
    ("lubricatedContactSteps scalar 1", "lubricatedContactSteps = 1 "),
    ("lubricatedContactTime scalar 1e-5", "lubricatedContactTime = 1e-05 (N_c = t_c / dt = 2)")])
def test_too_short_a_contact_stops_with_an_error(run, preloaded, duration, named, nprocs):
    """The preloaded bed, dry, N_c <= 2: a mode of the contact network grows every step (lower
    bound 4.92 at N_c = 2, 7.18 at 1, as in the LAMMPS plugin). Before the check LIGGGHTS lost
    atoms without a word: 300 spheres down to 12 (N_c = 2) and 5 (N_c = 1) in 500 steps."""
    with pytest.raises(lammps_run.LammpsError) as err:
        run.lig(packing_run(preloaded, duration), nprocs=nprocs)
    message = str(err.value)
    assert named in message and "too short a contact for this packing" in message
    assert "contacts) and" in message and "grows every step" in message
    if "Steps" in duration:
        assert "Use lubricatedContactSteps >=" in message
    else:
        assert "a timestep <=" in message
    assert "Lost atoms" not in err.value.log


def test_a_long_enough_contact_runs(run, preloaded):
    """N_c = 8 (load 0.20, below the check's 0.25): no check, no atom lost."""
    assert run.lig(packing_run(preloaded, "lubricatedContactSteps scalar 8"))["atoms"] == 300
    assert "WARNING" not in run.log


def test_likely_unstable_network_is_warned_once_a_run(run):
    """The settling bed at N_c = 2: columns of two contacts per sphere (lower bound 3.15, upper
    5.36): a growing mode is likely, not proven; one WARNING per run, and the bed does not
    settle (its top stays near 31 d instead of 22.5 d)."""
    script = (ROOT / "examples" / "liggghts" / "in.settling_bed").read_text()
    result = run.lig(script.replace("variable N_c     equal 8", "variable N_c     equal 2"),
                     variables={"steps": 20000, "settled": 2000})
    warnings = [line for line in run.log.splitlines() if "likely unstable" in line]
    assert len(warnings) == 2
    assert "lubricatedContactSteps = 2" in warnings[0] and "use lubricatedContactSteps >=" in warnings[0]
    assert result["top"] > 25.0

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
import math
import pathlib
import re

import pytest

import dense_packings
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


def test_wet_settling_bed_at_one_pascal_second(run):
    """Gravity, a wet floor and 2254 spheres with friction, 2 ranks, the example's own step:
    ke + erot + m g' z never exceeds E0 (the spheres start at rest: E0 is all potential, and
    the spring energy is never negative), no atom is lost, and the bed settles."""
    script, variables = dense.settling_bed(20000)
    result = run.lig(script, nprocs=2, variables=variables)
    energy, atoms = dense.bed_energies(run.log)
    assert len(energy) == 201 and set(atoms) == {2254} and result["atoms"] == 2254
    assert max(energy) <= energy[0] * (1.0 + ROUND_OFF)
    assert energy[-1] < 0.8 * energy[0] and result["top"] < 34.0


def test_settling_bed_with_per_pair_caps_alone_gains_energy(run):
    """The check above fails as the issue found it: 46 E0 within 8000 steps (measured)."""
    script, variables = dense.settling_bed(8000, limit="pair")
    run.lig(script, variables=variables)
    energy, _ = dense.bed_energies(run.log)
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


@pytest.mark.parametrize("value", ["2", "0.5", "-1"])
def test_limit_pair_takes_zero_or_one(run, value):
    script = dense.cluster(1.0, 1e-6, steps=10).replace(
        "pair_style gran", f"fix m5 all property/global lubricatedLimitPair scalar {value}\npair_style gran")
    with pytest.raises(lammps_run.LammpsError, match=f"lubricatedLimitPair = {value}"):
        run.lig(script)


@pytest.mark.parametrize("dt,steps", [(5e-6, 2000), (5e-5, 200)])
def test_compression_to_solid_fraction_070(run, packings, dt, steps):
    """The loose 0.46 packing compressed by fix deform to 0.70 in 0.01 s, wet at mu_f = 10 Pa s
    with friction 0.5: all 300 spheres kept, the bed ends compressed (virial pressure > 0;
    measured 3.0e5 Pa at 5e-6 s and 2.9e3 Pa at 5e-5 s, as the LAMMPS plugin's 3e5 and 2.8e3).
    (A sheared triclinic bed, the LAMMPS tests' other scene, could not be run in LIGGGHTS 3.8.0:
    `change_box all triclinic` with fix deform xy lost atoms at the first step with the per-film
    caps as well; not pursued.)"""
    import math
    _, _, radii = dense_packings.read_data(packings["loose46"])
    edge = float((sum(4.0 / 3.0 * math.pi * radii ** 3) / 0.70) ** (1.0 / 3.0))
    script = packing_run(packings["loose46"], "lubricatedContactSteps scalar 8", dt=dt, steps=steps,
                         mu=10.0, every=100)
    script = script.replace("pair_style gran model lubricated\n",
                            "fix m5 all property/global coefficientFriction peratomtypepair 1 0.5\n"
                            "pair_style gran model lubricated tangential history\n")
    # The pressure in the thermo rows: evaluated on the last step (thermo every 100 steps).
    script = script.replace("thermo_style custom step atoms ke c_rot c_contacts",
                            "compute pv all pressure thermo_temp virial\nvariable p equal c_pv\n"
                            "thermo_style custom step atoms ke c_rot c_contacts c_pv")
    script = script.replace(f"run {steps}\n",
                            f"fix compress all deform 1 x final 0 {edge!r} y final 0 {edge!r} "
                            f"z final 0 {edge!r} remap x\nrun {steps}\nprint \"RESULT pressure ${{p}}\"\n")
    result = run.lig(script)
    assert result["atoms"] == 300
    assert result["pressure"] > 0.0


# ------------------------------------------------------------------------------------------
# The contact network (lubricated/contact_network.h): contacts too short for the packing
# ------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def packings():
    """The LAMMPS tests' random 1:10 packings (300 spheres, radii 0.1-1 mm; kept, see
    tools/dense_packings.py, PINNED), with random velocities (rms 0.01 m/s, in the data files): LIGGGHTS reads them.
    preloaded: solid fraction 0.70, 592 sustained contacts; gapped: 0.642, every pair apart,
    4.6 film neighbours per sphere (tests/lammps/test_dense_packings.py)."""
    if not lammps_run.PLUGIN.exists():
        pytest.skip(f"{lammps_run.PLUGIN} is missing: run 'make build'")
    root = ROOT / "build" / "test-scratch-liggghts" / "packings"
    root.mkdir(parents=True, exist_ok=True)
    preloaded = dense_packings.pinned("p70")
    dense_packings.gapped(dense_packings.pinned("p65"), root / "gapped.data")
    loose = dense_packings.pinned("p46")
    return {"preloaded": dense_packings.with_velocities(preloaded, root / "preloaded_v.data"),
            "gapped": dense_packings.with_velocities(root / "gapped.data", root / "gapped_v.data"),
            "loose46": loose}


def packing_run(data, duration, dt=5e-6, steps=500, mu=0.0, every=50):
    film = (f"fix m3 all property/global lubricatedViscosity scalar {mu}\n"
            f"fix m4 all property/global lubricatedActivation scalar {dense_packings.ACTIVATION}\n"
            if mu > 0 else "")
    return f"""atom_style granular
atom_modify map array
communicate single vel yes
newton off
units si
boundary p p p
read_data {data}
fix m1 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m2 all property/global {duration}
{film}pair_style gran model lubricated
pair_coeff * *
neighbor {0.2 * dense_packings.R_MIN} bin
neigh_modify delay 0
fix nve all nve/sphere
timestep {dt}
compute rot all erotate/sphere
compute touching all contact/atom
compute contacts all reduce sum c_touching
thermo_style custom step atoms ke c_rot c_contacts
thermo_modify lost error norm no format float %.17g
thermo {every}
run {steps}
variable n equal atoms
print "RESULT atoms ${{n}}"
"""


def packing_rows(log):
    rows = [line.split() for line in log.splitlines()]
    return [[float(v) for v in r] for r in rows if len(r) == 5 and r[0].isdigit() and "by" not in r]


@pytest.mark.parametrize("st,dt", [(1e-3, 5e-7), (1e-3, 2e-5), (0.1, 5e-6), (10.0, 5e-6), (1e3, 5e-7)])
def test_polydisperse_packing_never_gains(run, packings, st, dt):
    """The gapped 1:10 packing, wet (St of the largest spheres; the smallest have St / 10), dt
    from 5e-5 to 2e-3 R_min / U: the energy of motion never exceeds E0 (every gap is open at the
    start), no atom is lost; LIGGGHTS follows the LAMMPS plugin's run of the same packing
    (dense_packings.energy_scene: its energy with the springs never rises beyond round-off) to
    1e-9 E0 where the films dominate (St <= 10; measured at most 8e-13 E0)."""
    mu = dense_packings.viscosity_for_stokes(st)
    steps = 400
    result = run.lig(packing_run(packings["gapped"], "lubricatedContactSteps scalar 8", dt=dt,
                                 steps=steps, mu=mu, every=10))
    rows = packing_rows(run.log)
    motion = [r[2] + r[3] for r in rows]
    assert result["atoms"] == 300 and {r[1] for r in rows} == {300}
    assert max(motion) <= motion[0] * (1.0 + ROUND_OFF) and motion[-1] < motion[0]
    if st > 10.0:
        return
    reference = dense_packings.thermo_rows(lammps_run.run(
        dense_packings.energy_scene(packings["gapped"], mu, dt, steps), run.dir / "lammps")[1])
    assert len(reference) == len(rows)
    total = reference[:, 2] + reference[:, 3] + reference[:, 4]
    assert max(total[1:] - total[:-1]) <= ROUND_OFF * total[0]
    assert max(abs(m - (r[2] + r[3])) for m, r in zip(motion, reference)) <= SAME_TRAJECTORY * motion[0]


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("duration,named", [
    ("lubricatedContactSteps scalar 2", "lubricatedContactSteps = 2 "),
    ("lubricatedContactSteps scalar 1", "lubricatedContactSteps = 1 "),
    ("lubricatedContactTime scalar 1e-5", "lubricatedContactTime = 1e-05 (N_c = t_c / dt = 2)")])
def test_too_short_a_contact_stops_with_an_error(run, packings, duration, named, nprocs):
    """The preloaded bed, dry, N_c <= 2: a mode of the contact network grows every step (lower
    bound 4.92 at N_c = 2, 7.18 at 1, as in the LAMMPS plugin). Before the check LIGGGHTS lost
    atoms without a word: 300 spheres down to 12 (N_c = 2) and 5 (N_c = 1) in 500 steps."""
    with pytest.raises(lammps_run.LammpsError) as err:
        run.lig(packing_run(packings["preloaded"], duration), nprocs=nprocs)
    message = str(err.value)
    assert named in message and "too short a contact for this packing" in message
    assert "contacts) and" in message and "grows every step" in message
    if "Steps" in duration:
        assert "Use lubricatedContactSteps >=" in message
    else:
        assert "a timestep <=" in message
    assert "Lost atoms" not in err.value.log


SETTLING_N_C_1 = """atom_style granular
atom_modify map array
communicate single vel yes
newton off
units si
boundary p p f
region box block 0 0.012 0 0.012 0 0.06 units box
create_box 2 box
neighbor 5e-4 bin
neigh_modify delay 0
fix m1 all property/global coefficientRestitution peratomtypepair 2 0.9 0.9 0.9 0.9
fix m3 all property/global lubricatedContactSteps scalar 1
pair_style gran model lubricated
pair_coeff * *
fix floor all wall/gran model lubricated primitive type 2 zplane 0.0
lattice bcc 0.0030 origin 0.25 0.25 0.25
region fill block 0 0.012 0 0.012 0.004 0.05 units box
create_atoms 1 region fill
set group all diameter 2e-3 density 2500
displace_atoms all random 2e-4 2e-4 2e-4 15485863 units box
fix nve all nve/sphere
fix weight all gravity 9.81 vector 0 0 -1
timestep 1e-5
run 3500
"""


def network_bound_load(n, e=0.9):
    """The load that bounds a LIGGGHTS contact lasting n steps (contact_network.h): the larger of
    the exact normal contact's and the sampled tangential spring's (kt = 2/7 k on 2/7 m_e)."""
    m = max(n, 1.5)
    big_e, cos = e ** (1.0 / m), math.cos(math.pi / m)
    log_e = math.log(e)
    return max(3.0 - big_e ** 2 - 2.0 * big_e * cos, (math.pi ** 2 + log_e ** 2) / n ** 2 - 4.0 * log_e / n)


def test_advised_duration_is_longer_and_passes(run):
    """A settling bcc bed at N_c = 1 (the probe's): pairs of spheres touch with the upper bound
    10.3 of the sampled tangential spring's load. The WARNING advised "lubricatedContactSteps >= 1",
    the duration in use (its advice left out that load and rounded down); now a longer one, under
    which that bound (per unit load, from the printed upper bound, rounded down) is below 4."""
    run.lig(SETTLING_N_C_1)
    warning = next(line for line in run.log.splitlines() if "likely unstable" in line)
    upper = float(re.search(r"reach the upper bound ([0-9.e+]+) >= 4", warning).group(1))
    advised = float(re.search(r"use lubricatedContactSteps >= ([0-9.e+]+) ", warning).group(1))
    assert "lubricatedContactSteps = 1 " in warning and advised > 1.0, warning
    unit_upper = upper * (1.0 - 5e-3) / network_bound_load(1.0)
    assert network_bound_load(advised) * unit_upper < 4.0, warning


def test_a_long_enough_contact_runs(run, packings):
    """N_c = 8 (load 0.20, below the check's 0.25): no check, no atom lost. The packing is
    preloaded (overlaps up to 0.19 of the smaller radius): the overlap check's WARNING, and only it."""
    assert run.lig(packing_run(packings["preloaded"], "lubricatedContactSteps scalar 8"))["atoms"] == 300
    assert not [line for line in run.log.splitlines() if "WARNING" in line and "overlap by" not in line]


def test_likely_unstable_network_is_warned_once_a_run(run):
    """The settling bed at N_c = 2: columns of two contacts per sphere (lower bound 3.15, upper
    5.36): a growing mode is likely, not proven; one WARNING per run, and the bed does not
    settle: its top stays at least 1 d above the same bed's at N_c = 8 (measured 24.6 d and
    31 d in two builds that differ by round-off, the growing mode being chaotic; 22.5 d settled)."""
    script = (ROOT / "examples" / "liggghts" / "in.settling_bed").read_text()
    variables = {"steps": 20000, "settled": 2000}
    settled = run.lig(script, variables=variables)["top"]
    result = run.lig(script.replace("variable N_c     equal 8", "variable N_c     equal 2"), variables=variables)
    warnings = [line for line in run.log.splitlines() if "likely unstable" in line]
    assert len(warnings) == 2
    assert "lubricatedContactSteps = 2" in warnings[0] and "use lubricatedContactSteps >=" in warnings[0]
    assert result["top"] > settled + 1.0


@pytest.mark.parametrize("nprocs", [1, 2])
def test_interrupted_dense_bed_never_gains(run, nprocs):
    """The fcc bed at 1 Pa s, 1e-6 s (a film-dominated case) run as six runs with `run 0` between
    them, then written to a restart file and continued by a new LIGGGHTS process (the budget
    fix holds nothing between steps; the pair style comes back from the file, the properties
    are given again): ke + erot never rises between any two samples, boundaries included, and
    no atom is lost; `lubricatedLimitPair 1` gains more than 1e3 E0 on the same runs."""
    def split(limit):
        script = dense.fcc(1.0, 1e-6, steps=50, limit=limit, newton="on")
        body, tail = script.split("run 50\n")
        runs = "".join("run 50\nrun 0\n" for _ in range(6))
        return body + runs + "write_restart mid.restart\n", tail
    first, _ = split("atom")
    model = first[first.index("fix m1"):first.index("pair_style")]
    after = first[first.index("neighbor"):first.index("run 50")]
    second = (dense.HEADERS["liggghts"] + "newton on\nread_restart mid.restart\n" + model + after +
              "run 150\n")
    run.lig(first, nprocs=nprocs)
    rows = dense.rows(run.log)
    run.lig(second, nprocs=nprocs, name="in.restart")
    rows += dense.rows(run.log)
    e0 = rows[0][MOTION]
    assert {r[ATOMS] for r in rows} == {256}
    assert all(r[CONTACTS] == 0 for r in rows)
    rises = [(b[MOTION] - a[MOTION]) / e0 for a, b in zip(rows, rows[1:])]
    assert max(rises) <= ROUND_OFF and rows[-1][MOTION] < 1e-6 * e0
    pair, _ = split("pair")
    run.lig(pair, nprocs=nprocs, name="in.pair")
    assert max(r[MOTION] for r in dense.rows(run.log)) > 1e3 * e0

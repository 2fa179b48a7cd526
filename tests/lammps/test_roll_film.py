"""The rolling film (`pair_coeff ... rollfilm yes`, doc/model.rst "The rolling mode"): Jeffrey &
Onishi's rolling term, a torque -gamma P_t(omega_i - omega_j) on i and the opposite on j with
gamma = (24/5) pi mu_f R_e^3 ln(eps_al / eps).

A pair of spheres a and 1.4 a at rest at a gap of 1e-2 of the film radius, spinning: the relative
spin across the line of centres decays by exactly exp(-gamma dt / I_e) per step (velocity Verlet
reads the half-step spins, so the run's end value carries two half kicks), the spin along it is
untouched and the pair's angular momentum is kept, on 1 and 2 ranks; without the keyword
nothing changes. Dense wet beds keep their energy bound with it (limit atom and limit implicit),
and walls refuse it."""
import math
import pathlib

import pytest

import dense_scenes

A = 1.0e-4
RATIO = 1.4
RHO = 1000.0
ETA = 1.0e-2
EPS = 1.0e-2          # gap / film radius
X = 0.05              # gamma dt / I_e
STEPS = 40
SPIN_1 = (3.0, 2.0, 0.5)
SPIN_2 = (-1.0, 0.0, 1.0)

SCRIPT = """region box block 0 {box} 0 {box} 0 {box} units box
create_box 2 box
create_atoms 1 single {x1} {c} {c} units box
create_atoms 2 single {x2} {c} {c} units box
set type 1 diameter {d1} density {rho}
set type 2 diameter {d2} density {rho}
set atom 1 omega {w1}
set atom 2 omega {w2}
neighbor {skin} bin
timestep {dt}
pair_style lubricated/springdashpot
pair_coeff * * 0.5 tcontact {tc} viscosity {eta} activation 0.1 shearfilm no {roll}
fix nve all nve/sphere
compute om all property/atom omegax omegay omegaz
group one id 1
group two id 2
compute w1 one reduce sum c_om[1] c_om[2] c_om[3]
compute w2 two reduce sum c_om[1] c_om[2] c_om[3]
thermo_style custom step c_w1[1] c_w1[2] c_w1[3] c_w2[1] c_w2[2] c_w2[3]
thermo {steps}
run {steps}
print "RESULT w1 $(c_w1[1]:%.17g) $(c_w1[2]:%.17g) $(c_w1[3]:%.17g)"
print "RESULT w2 $(c_w2[1]:%.17g) $(c_w2[2]:%.17g) $(c_w2[3]:%.17g)"
print "RESULT v $(vx[1]:%.17g) $(vy[1]:%.17g) $(vx[2]:%.17g)"
"""


def pair_scene(roll="rollfilm yes"):
    r1, r2 = A, RATIO * A
    film_radius, reduced = 2 * r1 * r2 / (r1 + r2), r1 * r2 / (r1 + r2)
    gamma = 24.0 / 5.0 * math.pi * ETA * reduced ** 3 * math.log(0.1 / EPS)
    inertia = [0.4 * RHO * 4.0 / 3.0 * math.pi * r ** 3 * r ** 2 for r in (r1, r2)]
    dt = X / (gamma * (1.0 / inertia[0] + 1.0 / inertia[1]))
    dist, box = r1 + r2 + EPS * film_radius, 20 * A
    c = 0.5 * box
    header = dense_scenes.HEADER.replace("boundary p p p", "boundary f f f")
    script = header + SCRIPT.format(box=box, c=c, x1=c + 0.5 * dist, x2=c - 0.5 * dist, d1=2 * r1, d2=2 * r2,
                                    rho=RHO, w1=" ".join(map(str, SPIN_1)), w2=" ".join(map(str, SPIN_2)),
                                    skin=0.5 * A, dt=dt, tc=20 * dt, eta=ETA, roll=roll, steps=STEPS)
    return script, inertia


@pytest.mark.parametrize("nprocs", [1, 2])
def test_relative_spin_decays_at_the_rolling_films_rate(lmp, nprocs):
    script, (i1, i2) = pair_scene()
    r = lmp(script, nprocs=nprocs)
    w1, w2 = r["w1"], r["w2"]
    # n is along x: the spin about the line of centres is not resisted
    assert w1[0] == SPIN_1[0] and w2[0] == SPIN_2[0]
    # across it: a half kick at the set-up, STEPS - 1 whole steps, a half kick at the end
    kick = 1.0 - math.exp(-X)
    factor = (1.0 - 0.5 * kick) ** 2 * math.exp(-X * (STEPS - 1))
    for d in (1, 2):
        expected = (SPIN_1[d] - SPIN_2[d]) * factor
        assert abs((w1[d] - w2[d]) - expected) < 1e-12 * abs(SPIN_1[d] - SPIN_2[d])
        # a pure couple: the pair's angular momentum is kept
        before = i1 * SPIN_1[d] + i2 * SPIN_2[d]
        assert abs(i1 * w1[d] + i2 * w2[d] - before) < 1e-12 * (i1 + i2) * 3.0
    assert r["v"] == [0.0, 0.0, 0.0]    # no force: the spheres stay at rest


@pytest.mark.parametrize("split", ["run 20\nrun 20", "run 20\nrun 0\nrun 0\nrun 20"])
def test_split_runs_and_run_0_continue_as_one_run(lmp, split):
    """The run cut in two, with or without `run 0` between: each set-up continues the last step
    (the spins it kept), so the relative spin decays as in one run, to round-off."""
    script, _ = pair_scene()
    whole = lmp(script)
    parts = lmp(script.replace(f"run {STEPS}\n", split + "\n"))
    for key in ("w1", "w2"):
        assert parts[key] == pytest.approx(whole[key], rel=1e-12, abs=1e-14)


def test_without_the_keyword_the_spins_are_untouched(lmp):
    script, _ = pair_scene(roll="")
    r = lmp(script)
    assert r["w1"] == list(SPIN_1) and r["w2"] == list(SPIN_2)


def energies(log):
    """(atoms, total energy) of the thermo rows of a dense scene."""
    out = []
    for line in log.splitlines():
        w = line.split()
        if len(w) == 6 and w[0].isdigit() and w[1].isdigit():
            out.append((int(w[1]), float(w[5])))
    return out


@pytest.mark.parametrize("limit", ["atom", "implicit"])
def test_dense_bed_with_rolling_films_never_gains_energy(lmp, limit):
    """The fcc bed at St 5.6e-3 (mu_f = 1 Pa s, dt 1e-6 s), friction and both tangential films:
    the spins the friction and the shear film give are braked by the rolling films too, every
    sphere's budget binds, and the energy sampled every 10 steps never rises."""
    extra = "friction 0.3 shearfilm yes rollfilm yes"
    lmp(dense_scenes.fcc(1.0, 1e-6, steps=200, limit=limit, extra=extra))
    rows = energies(lmp.log)
    assert len(rows) >= 20 and {a for a, _ in rows} == {rows[0][0]}
    energy = [e for _, e in rows]
    assert max(b - a for a, b in zip(energy, energy[1:])) <= 1e-12 * energy[0]
    assert energy[-1] < 0.5 * energy[0]
    assert "rolling film on" in lmp.log


def test_walls_refuse_the_rolling_film(lmp):
    script, _ = pair_scene()
    script = script.replace("fix nve all nve/sphere",
                            "fix nve all nve/sphere\nfix wall all wall/lubrication 0.5 tcontact 1e-3 "
                            "viscosity 0.01 activation 0.1 rollfilm yes zplane 0.0 NULL")
    lmp(script, check=False)
    assert "ERROR" in lmp.log and "rollfilm is for pairs of spheres" in lmp.log


def spinning_cluster(limit, newton="on"):
    """The cluster scene of dense_scenes with its centre spinning, rolling films only."""
    script = dense_scenes.cluster(1000.0, 1e-6, steps=100, limit=limit, extra="shearfilm no rollfilm yes")
    line = next(w for w in script.splitlines() if w.startswith("velocity centre set"))
    script = script.replace(line, "set group centre omega 30 20 10").replace("newton on", f"newton {newton}")
    return script.replace("print \"RESULT final", "compute om all property/atom omegax omegay omegaz\n"
                          "compute spin all reduce sum c_om[1] c_om[2] c_om[3]\n"
                          "compute mine centre reduce sum c_om[1] c_om[2] c_om[3]\n"
                          "run 0\nprint \"RESULT spin $(c_spin[1]:%.17g) $(c_spin[2]:%.17g) $(c_spin[3]:%.17g)\"\n"
                          "print \"RESULT centre $(c_mine[1]:%.17g) $(c_mine[2]:%.17g) $(c_mine[3]:%.17g)\"\n"
                          "print \"RESULT final")


@pytest.mark.parametrize("limit", ["atom", "implicit"])
def test_a_spinning_sphere_among_twelve_keeps_the_energy_bound(lmp, limit):
    """One sphere spinning among its 12 fcc neighbours at rest (gaps 2e-3 R, mu_f = 1000 Pa s, dt
    1e-6 s), no other film acting (no translation): each rolling film alone nearly stops its
    relative spin in a step (gamma dt / I_e about 3.5), so the films applied whole would reverse
    the centre's spin several times over. Within the budget (its loads count the rolling films)
    or solved together, the energy never rises, the angular momentum is kept and the spin is
    shared out."""
    r = lmp(spinning_cluster(limit))
    rows = energies(lmp.log)
    energy = [e for _, e in rows]
    assert len(energy) >= 10 and energy[0] > 0.0
    assert max(b - a for a, b in zip(energy, energy[1:])) <= 1e-12 * energy[0]
    # equal spheres: the sum of the spins is the angular momentum over I
    assert r["spin"] == pytest.approx([30.0, 20.0, 10.0], rel=1e-10)
    # the spun sphere's spin has gone most of the way to the pair-free common spin L / (13 I)
    common = [w / 13.0 for w in (30.0, 20.0, 10.0)]
    start = math.dist((30.0, 20.0, 10.0), common)
    assert math.dist(r["centre"], common) < 0.1 * start


@pytest.mark.parametrize("limit", ["atom", "implicit"])
def test_one_and_two_ranks_and_newton_off_agree(lmp, limit):
    """The spinning cluster on 2 ranks with newton off (each film once, its couple on a ghost's
    owner by the reverse communication of the budget and the solve) as on 1 rank with newton on,
    to the solver's tolerance."""
    one = lmp(spinning_cluster(limit))["centre"]
    two = lmp(spinning_cluster(limit, newton="off"), nprocs=2, env=dense_scenes.OVERSUBSCRIBED)["centre"]
    assert two == pytest.approx(one, rel=1e-10, abs=1e-10 * 30.0)


RESTART_PAIRS = [
    "1 1 0.90000000000000002 ncontact 8 viscosity 0.01 activation 0.10000000000000001 saturation 0.001 "
    "release -0.01 friction 0.29999999999999999 shearfilm yes",
    "1 2 0.69999999999999996 tcontact 0.0001 viscosity 0.02 activation 0.20000000000000001 saturation 0.002 "
    "release -0.01 rolling 0.050000000000000003",
    "2 2 0.5 ncontact 16 integration sampled",
]


def pair_ij_lines(path):
    lines = path.read_text().splitlines()
    start = lines.index("PairIJ Coeffs # lubricated/springdashpot") + 2
    return lines[start:lines.index("", start)]


def test_restart_files_written_before_rollfilm_read_the_same(lmp):
    """tests/data/before_rollfilm.restart: two types, written by the style before rollfilm (one
    coefficient value less per type pair). Read now, every type pair's coefficients come back as
    they were given (write_data pair ij) and none has a rolling film."""
    data = pathlib.Path(__file__).resolve().parents[1] / "data" / "before_rollfilm.restart"
    lmp(f"plugin load ${{plugin}}\nread_restart {data}\nwrite_data after.data pair ij\n")
    assert pair_ij_lines(lmp.dir / "after.data") == RESTART_PAIRS


def test_rollfilm_survives_a_restart(lmp):
    script, _ = pair_scene()
    lmp(script + "write_restart roll.restart\n")
    lmp("plugin load ${plugin}\nread_restart roll.restart\nwrite_data after.data pair ij\n")
    assert all(line.endswith("rollfilm yes") for line in pair_ij_lines(lmp.dir / "after.data"))

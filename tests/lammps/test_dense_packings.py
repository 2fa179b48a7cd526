"""Random polydisperse dense packings (issue 17): energy, lost atoms, compression, shear and the
stability of the contact network.

Packings (tools/dense_packings.py; built with the plugin at b70aa61 and kept in
tests/lammps/dense_packings/, since a rebuild with other rounding is another realisation): 300
spheres, radii log-uniform 0.1-1 mm (1:10), rho_p = 2500 kg/m^3, periodic cube of about 7.5 mm,
compressed dry with fix deform and relaxed by quenches (test_packings_build_with_this_plugin
builds one with the plugin under test):
- *gapped*: relaxed at solid fraction 0.65, every radius then shrunk by one factor: phi = 0.642,
  every pair apart (eps = h / R >= 0.008), 4.6 neighbours per sphere inside the film (eps_al = 0.1).
  Gapped packings do not go higher: this distribution jams at about 0.65 (zero pressure after
  relaxation up to 0.64, preloaded from 0.66).
- *preloaded*: relaxed at 0.70, 592 sustained contacts (up to 15 per sphere), overlaps up to
  about a quarter of the smaller radius (the stiffness k = m_e (pi^2 + ln^2 e_d) / t_c^2 scales with the
  reduced mass: the light spheres take the compression).
- *loose* 0.46 and 0.61 (relaxed, zero pressure) for the compression and the shear.

Scenes: random translational velocities of rms U = 0.01 m/s (zero momentum), no gravity unless
stated, e_d = 0.9, N_c = 8, eps_al = 0.1. St = (2/9) rho_p R U / mu_f with R = 1 mm (the smallest
spheres: St / 10); time steps in R_min / U = 0.01 s, the documented step being 0.005 R / U
(t_c = 0.04 R / U, doc "Wet restitution and the time step"): 5e-5 to 0.02 R_min / U, i.e.
5e-7 s to 2e-4 s.

Energy criteria (E = ke + erot + pe [+ sum m g z], pe the spring energy k d^2 / 2, thermo rows):
- *strict*, 1e-12 E0 (round-off of 300-term sums): where no contact acts, i.e. pe = 0 at every
  step, the films alone act and the many-body budget (film_budget.h) guarantees that they never
  raise the kinetic energy.
- *bounded*, where contacts act: the sampled energy is not the integrator's invariant. The
  positions of an isolated collision are exact at the samples, but the sampled velocity is the
  mean of the two half-step velocities; over all impact phases its sampled energy rises by at
  most 0.017 (N_c = 8, e_d = 0.9; 0.09 at N_c = 4) of the impact energy between any two samples,
  below theta0^2 / 3 = 0.051, theta0 = omega_0 dt = sqrt(pi^2 + ln^2 e_d) / N_c (the central
  difference's error, omega^2 dt^2 / 6 on the velocity). A rise between samples may therefore
  reach theta0^2 / 3 of the energy of motion ke + erot + pe at the earlier sample (gravity's
  potential excluded), plus round-off.
Measured (limit atom, samples every 10 steps, St 1e-3..1e3, dt 5e-5..0.02 R_min/U): the preloaded
runs never rise (at round-off); the gapped ones rise only at St = 1000 and 5e-5 R_min/U (4e-6 E0; up
to 2.4e-4 E0 when sampled every step), the collision sampling, far below the bound (which is loose:
5 % of the preload's energy in the preloaded bed); the walled beds under gravity never rise. With `limit pair` (each film capped on
its own) the scenes at St <= 0.1 and dt >= 5e-3 R_min/U gain 60 to 8.6e3 E0 and lose atoms in
both beds, at smaller steps up to 4.7e7 E0 (gapped, St 1e-3; preloaded 0.07-190 E0); walls:
0.4-1.9e4 E0 and lost atoms. The criteria detect the defect the film budget removes.

Compression (0.46 to 0.70 by fix deform) and steady shear at 0.61 (fix deform xy erate 20/s,
remap v) with mu_f up to 10 Pa s, friction 0.5 and the shear film: no atom lost, pressure and
shear stress -pxy (virial; see test_steady_shear_at_solid_fraction_061) positive. With `limit pair` they lose atoms.

A light sphere under a heavy one at a wall carries the heavy one's weight on springs of its own
reduced mass (k = m_e (pi^2 + ln^2 e_d) / t_c^2): the static overlap (m_heavy / m_light) g /
omega0^2 exceeds R_light in these beds at the walled scenes' steps (1:10 radii, t_c = 8 dt: 2.5 mm
against 0.1 mm at dt = 2e-4 s), and only the bed's other contacts hold such a sphere. The
realisation the builder gave with the vectorised contact events (after b70aa61) put a 0.106 mm
sphere under a 0.57 mm one at the floor: at mu_f 1 Pa s and 2e-4 s it was pushed through the
wall at step 99 (ERROR: Lost atoms), with b70aa61's plugin as with the new one. The kept packings
have no such sphere; the model gives this scene no guarantee (a shorter t_c, i.e. a smaller dt at
the same N_c, or a narrower size range does).

The contact network (issue 17 item 4; lubricated/contact_network.h): the preloaded bed at
N_c <= 2 lost atoms (before: `ERROR: Lost atoms: original 300 current 297` within 50 steps at
N_c = 2, `current 39` at N_c = 1, after only the warning about N_c < 8); it now stops at the first
step with an ERROR that names ncontact, the contacts and the remedy.

The shear film (`shearfilm yes`; test_shear_film_in_a_dense_polydisperse_bed) kept its per-pair
cap only and gained 3.5e4 E0 in the gapped bed at mu_f dt = 5e-5 Pa s^2 (none at 5e-6 Pa s^2); it
now shares each sphere's film budget with the normal films (film_budget.h) and never rises there,
on wet walls either.
"""
import math
import pathlib
import re

import numpy as np

import pytest

import dense_packings as dp
import dense_scenes
import lammps_run

ROUND_OFF = 1e-12
E_DRY, N_C = 0.9, 8
THETA0_SQ = (math.pi ** 2 + math.log(E_DRY) ** 2) / N_C ** 2
SAMPLING = THETA0_SQ / 3.0    # 0.051: sampled-energy rise per unit energy of motion


def mu_for(st):
    return dp.viscosity_for_stokes(st)


def dt_for(dt_ru):
    return dt_ru * dp.R_MIN / dp.SPEED


@pytest.fixture(scope="module")
def packings():
    root = lammps_run.ROOT / "build" / "test-scratch" / "dense-packings"
    root.mkdir(parents=True, exist_ok=True)
    beds = {}
    beds["preloaded"] = dp.pinned("p70")
    beds["gapped"] = root / "gapped.data"
    beds["gapped_phi"] = dp.gapped(dp.pinned("p65"), beds["gapped"])
    beds["loose46"] = dp.pinned("p46")
    beds["loose61"] = dp.pinned("p61")
    beds["walled"] = root / "walled.data"
    beds["walled_zhi"] = dp.walled(beds["gapped"], beds["walled"])
    return beds


def with_velocities(lmp, data, speed=dp.SPEED):
    """The packing with its velocities in the test's scratch directory (the run's working
    directory: the name alone, as test ids may hold spaces)."""
    dp.with_velocities(data, pathlib.Path(lmp.dir) / "start.data", speed=speed)
    return "start.data"


def run_energy(lmp, script, check=True):
    """Runs the scene; returns thermo rows (step atoms ke erot pe grav) and the log."""
    lmp(script, check=check)
    return dp.thermo_rows(lmp.log), lmp.log


def rises(rows):
    """Energy E = ke + erot + pe + grav, its rises between samples, and the bound of each rise
    (theta0^2 / 3 of the earlier sample's energy of motion ke + erot + pe)."""
    energy = rows[:, 2] + rows[:, 3] + rows[:, 4] + rows[:, 5]
    motion = rows[:, 2] + rows[:, 3] + rows[:, 4]
    return energy, np.diff(energy), SAMPLING * motion[:-1]


def assert_bounded(rows, scale):
    energy, rise, bound = rises(rows)
    assert len(rows) >= 20
    assert set(rows[:, 1]) == {dp.N_ATOMS}
    excess = rise - bound - ROUND_OFF * scale
    k = int(np.argmax(excess))
    assert excess[k] <= 0.0, (f"energy rose by {rise[k] / scale:.3g} E0 at step {rows[k + 1, 0]:.0f}, "
                              f"allowed {bound[k] / scale:.3g}")
    return energy


def test_packings_build_with_this_plugin(lmp):
    """The builder's dry compression and quenches (tools/dense_packings.py) with the plugin under
    test, to the gapped beds' 0.65: no atom lost (the build's thermo stops at a lost atom), the
    solid fraction reached and relaxed: the largest net force below 1e-5 N, 1e-3 of the contact
    forces of the preload (k d at a quarter of R_min, about 1e-2 N). Measured 8.5e-7 N."""
    path, largest = dp.build(pathlib.Path(lmp.dir) / "p65", dp.PACKINGS["p65"])
    box, _, radii = dp.read_data(path)
    assert len(radii) == dp.N_ATOMS
    assert dp.solid_fraction(box, radii) == pytest.approx(dp.PACKINGS["p65"], rel=1e-9)
    assert largest < 1e-5


# ------------------------------------------------------------------------------------------
# Item 1: no gravity
# ------------------------------------------------------------------------------------------

# (St, dt in R_min / U) where the films keep every pair apart over 500 steps.
CONTACT_FREE = [(1e-3, 5e-5), (1e-3, 5e-4), (0.1, 5e-5)]


@pytest.mark.parametrize("st,dt_ru", CONTACT_FREE)
def test_gapped_bed_without_contact_never_gains(lmp, packings, st, dt_ru):
    """Strict: the films alone act (pe = 0 at every step); ke + erot never rises beyond 1e-12 E0.
    Measured: largest change -5.6e-5, -6.1e-5, -2.0e-4 E0 (never a rise)."""
    rows, _ = run_energy(lmp, dp.energy_scene(with_velocities(lmp, packings["gapped"]), mu_for(st),
                                              dt_for(dt_ru), 500, every=1))
    assert len(rows) == 501 and set(rows[:, 1]) == {dp.N_ATOMS}
    assert not rows[:, 4].any(), "a contact formed: the scene is not contact-free"
    energy = rows[:, 2] + rows[:, 3]
    assert np.diff(energy).max() <= ROUND_OFF * energy[0]
    assert energy[-1] < 0.5 * energy[0]    # and the films do dissipate


# St 1e-3..1e3 (mu_f 5.6 Pa s .. 5.6e-6 Pa s) and dt 5e-4..0.02 R_min/U, contacts forming (gapped)
# or sustained (preloaded).
GRID = [(st, dt_ru) for st in (1e-3, 0.1, 10.0, 1e3) for dt_ru in (5e-4, 5e-3, 2e-2)]


@pytest.mark.parametrize("st,dt_ru", GRID)
@pytest.mark.parametrize("bed", ["gapped", "preloaded"])
def test_dense_bed_with_contacts_never_gains(lmp, packings, bed, st, dt_ru):
    """Bounded (module docstring): no rise beyond theta0^2/3 of the energy of motion, no atom
    lost, and the energy falls over the run."""
    rows, _ = run_energy(lmp, dp.energy_scene(with_velocities(lmp, packings[bed]), mu_for(st),
                                              dt_for(dt_ru), 1000, every=10))
    energy = assert_bounded(rows, rows[0, 2] + rows[0, 3] + rows[0, 4])
    assert energy[-1] <= energy[0]
    # Contacts did form in the gapped bed, except where its 1000 steps last only 0.5 R_min / U
    # and the films (St <= 0.1) nearly stop every approach: there whether one contact forms
    # depends on the packing, which the plugin builds anew each session (a change of rounding
    # anywhere in the dry contact gives another packing: contacts in 17 and 68 of the 100
    # samples with one, none with another; at St >= 10 or 10 times that time, 96-100 with both).
    if bed == "gapped" and (st >= 10.0 or dt_ru >= 5e-3):
        assert rows[:, 4].any()


@pytest.mark.parametrize("bed,st,dt_ru", [("gapped", 1e-3, 5e-3), ("gapped", 0.1, 5e-3),
                                          ("preloaded", 1e-3, 5e-4), ("preloaded", 0.1, 5e-3)])
def test_per_pair_caps_alone_break_the_criterion(lmp, packings, bed, st, dt_ru):
    """`limit pair` on scenes of the test above: atoms lost or the bound exceeded. Measured:
    gains of 1.7e3, 8.6e3, 0.47 and 90 E0, atoms lost in all four (at St = 10 and 1000 the films
    hardly matter: limit pair exceeds the bound only at St = 10, 0.02 R_min/U, by 1e-4 E0)."""
    script = dp.energy_scene(with_velocities(lmp, packings[bed]), mu_for(st), dt_for(dt_ru), 1000,
                             every=10, limit="pair")
    rows, log = run_energy(lmp, script, check=False)
    assert "(limit pair)" in log
    energy, rise, bound = rises(rows)
    lost = "Lost atoms" in log or set(rows[:, 1]) != {dp.N_ATOMS}
    assert lost or (rise - bound).max() > ROUND_OFF * energy[0]


@pytest.mark.parametrize("st,dt_ru", [(1e-3, 5e-3), (10.0, 5e-4)])
def test_friction_in_dense_beds(lmp, packings, st, dt_ru):
    """Coulomb friction 0.5 (tangential spring-dashpot, no shear film) in the preloaded bed:
    bounded criterion, no atom lost."""
    rows, _ = run_energy(lmp, dp.energy_scene(with_velocities(lmp, packings["preloaded"]), mu_for(st),
                                              dt_for(dt_ru), 1000, every=10,
                                              extra="friction 0.5 shearfilm no"))
    assert_bounded(rows, rows[0, 2] + rows[0, 3] + rows[0, 4])


@pytest.mark.parametrize("mu,dt", [(10.0, 5e-6), (10.0, 5e-5), (1.0, 5e-6)])
def test_shear_film_in_a_dense_polydisperse_bed(lmp, packings, mu, dt):
    """`shearfilm yes` in the gapped bed, U = 1e-3 m/s, 500 steps: no contact forms, so the strict
    criterion holds (the films, normal and shear, share each sphere's budget: film_budget.h).
    Before the shear film joined the budget the first case (mu_f dt = 5e-5 Pa s^2) gained 3.5e4 E0
    (1.2e4 E0 at the end); now measured: never rises (largest change -1.6e-5, -7.3e-6 and
    -3.2e-4 E0), 1.4 %, 1.1 % and 2.2 % of E0 left."""
    data = with_velocities(lmp, packings["gapped"], speed=1e-3)
    rows, _ = run_energy(lmp, dp.energy_scene(data, mu, dt, 500, every=10, extra="shearfilm yes"))
    assert len(rows) == 51 and set(rows[:, 1]) == {dp.N_ATOMS}
    assert not rows[:, 4].any(), "a contact formed: the scene is not contact-free"
    energy = rows[:, 2] + rows[:, 3]
    assert np.diff(energy).max() <= ROUND_OFF * energy[0]
    assert energy[-1] < 0.1 * energy[0]


def test_shear_film_one_and_two_ranks_agree(lmp, packings):
    """The gapped bed with the shear film at mu_f = 10 Pa s, 5e-6 s, where the shear films are
    scaled by the budget: 300 steps on 1 and 2 ranks (measured: the energies 1.6e-10 apart, the
    ranks' sums in another order; 1e-8 as the other rank comparisons)."""
    data = with_velocities(lmp, packings["gapped"], speed=1e-3)
    script = dp.energy_scene(data, 10.0, 5e-6, 300, every=10, extra="shearfilm yes")
    one = lmp(script)["final"]
    two = lmp(script, nprocs=2)["final"]
    assert one[1] == two[1] == dp.N_ATOMS
    assert two[0] == pytest.approx(one[0], rel=1e-8)


# ------------------------------------------------------------------------------------------
# Item 2: gravity and wet walls
# ------------------------------------------------------------------------------------------

def walled_scene(lmp, packings, mu, dt, steps, limit="atom", extra=""):
    film = f"viscosity {mu} activation {dp.ACTIVATION}" if mu > 0 else ""
    walls = (f"fix walls all wall/lubrication {E_DRY} ncontact {N_C} {film} {extra} zplane 0.0 "
             f"{packings['walled_zhi']!r}\nfix_modify walls energy yes")
    return dp.energy_scene(with_velocities(lmp, packings["walled"]), mu, dt, steps, every=10,
                           boundary="p p f", walls=walls, gravity=9.81, limit=limit, extra=extra)


@pytest.mark.parametrize("mu,dt", [(1e-3, 5e-6), (1e-3, 5e-5), (0.1, 5e-5), (10.0, 5e-5), (1.0, 2e-4)])
def test_bed_settling_on_a_wet_wall_never_gains(lmp, packings, mu, dt):
    """The gapped bed between two wet walls (fix wall/lubrication, the same e_d, N_c, film),
    settling under gravity 9.81 m/s^2 for 2000 steps (0.01-0.4 s): ke + erot + pe (springs of
    pairs and walls) + sum m g z never rises beyond the bounded criterion, no atom lost, and the
    bed goes down. Measured: never rises (largest change -5e-7 E0 .. -7e-6 E0)."""
    rows, _ = run_energy(lmp, walled_scene(lmp, packings, mu, dt, 2000 if dt < 2e-4 else 1000))
    energy = assert_bounded(rows, rows[0, 2] + rows[0, 3] + rows[0, 4] + rows[0, 5])
    assert rows[-1, 5] < rows[0, 5]
    assert energy[-1] < energy[0]


@pytest.mark.parametrize("mu", [1.0, 10.0])
def test_bed_settling_on_wet_walls_with_the_shear_film_never_gains(lmp, packings, mu):
    """As above with `shearfilm yes` on the pairs and the walls, 5e-5 s: the walls' shear films are
    deferred and scaled with their normal films. Measured: never rises (largest change -3.9e-6 and
    -2.0e-6 E0); with `limit pair` 2.2 and 47 E0 gained and atoms lost."""
    rows, _ = run_energy(lmp, walled_scene(lmp, packings, mu, 5e-5, 2000, extra="shearfilm yes"))
    energy = assert_bounded(rows, rows[0, 2] + rows[0, 3] + rows[0, 4] + rows[0, 5])
    assert rows[-1, 5] < rows[0, 5]
    assert energy[-1] < energy[0]


def test_walled_bed_with_per_pair_caps_alone_gains(lmp, packings):
    """Measured with `limit pair`: 0.38 E0 gained and 132 atoms lost (mu_f 10 Pa s, 5e-5 s)."""
    rows, log = run_energy(lmp, walled_scene(lmp, packings, 10.0, 5e-5, 2000, limit="pair"), check=False)
    energy, rise, bound = rises(rows)
    assert "Lost atoms" in log or (rise - bound).max() > ROUND_OFF * energy[0]


# ------------------------------------------------------------------------------------------
# Item 3: compression and steady shear, wet, with friction and the shear film
# ------------------------------------------------------------------------------------------

WET_FRICTION = "friction 0.5 shearfilm yes"


@pytest.mark.parametrize("mu,dt,steps", [(1e-3, 5e-6, 2000), (10.0, 5e-6, 2000), (10.0, 5e-5, 200)])
def test_compression_to_solid_fraction_070(lmp, packings, mu, dt, steps):
    """fix deform from 0.46 to 0.70 in 0.01 s (13 % linear strain, edges moving at ~0.1 m/s):
    all 300 spheres kept, the bed ends compressed (virial pressure > 0; measured 3e5 Pa at 5e-6 s,
    2.8e3 Pa at 5e-5 s, where the contacts are 100 times softer)."""
    result = lmp(dp.compression_scene(str(packings["loose46"]), mu, dt, steps, 0.70, extra=WET_FRICTION))
    phi, pressure, atoms = result["final"]
    assert atoms == dp.N_ATOMS
    assert phi == pytest.approx(0.70, rel=1e-6)
    assert pressure > 0.0


@pytest.mark.parametrize("mu,extra", [(0.01, WET_FRICTION), (10.0, WET_FRICTION), (10.0, "friction 0.5 shearfilm no"),
                                      (0.0, "friction 0.5")])
def test_steady_shear_at_solid_fraction_061(lmp, packings, mu, extra):
    """Simple shear of the 0.61 packing: triclinic periodic box, fix deform xy erate 20/s remap v
    (the image above moves in +x), velocities started on vx = 20/s y, 2000 steps of 5e-5 s
    (strain 2), averages over strain 1-2. The shear stress the bed opposes to that motion is
    sigma_xy = -pxy (LAMMPS's pressure tensor is minus the stress; contacts along the compressive
    diagonal x = -y give a negative virial pxy), from the virial alone (compute pressure NULL
    virial: the kinetic part holds the streaming profile). All atoms kept; -pxy > 0, and below
    the pressure (an effective friction between 0 and 1). Measured -pxy / p: 151/379 Pa
    (mu_f 0.01), 140/469 (10), 72/151 (10, no shear film), 82/180 (dry); with `limit pair` atoms
    are lost (next test)."""
    result = lmp(dp.shear_scene(str(packings["loose61"]), mu, 5e-5, 2000, 20.0, extra=extra))
    tau, pressure, atoms, _ = result["final"]
    assert atoms == dp.N_ATOMS
    assert 0.0 < tau < pressure


def test_shear_stress_follows_the_shear(lmp, packings):
    """The sign convention checked: shearing the other way (erate -20/s) gives -pxy < 0 (measured
    -116 Pa against a pressure of 263 Pa, dry with friction)."""
    tau, pressure, atoms, _ = lmp(dp.shear_scene(str(packings["loose61"]), 0.0, 5e-5, 2000, -20.0,
                                                 extra="friction 0.5"))["final"]
    assert atoms == dp.N_ATOMS
    assert -pressure < tau < 0.0


def with_per_pair_caps(script):
    return script.replace("pair_style lubricated/springdashpot", "pair_style lubricated/springdashpot limit pair")


def largest_kinetic_energy(log):
    """The largest ke of the thermo rows (step atoms ke ...) of a log."""
    rows = [line.split() for line in log.splitlines() if re.match(r"^\s+\d+\s+\d+\s+[-+0-9.e]+\s", line)]
    return max(float(row[2]) for row in rows)


@pytest.mark.parametrize("scene", ["shear", "compression"])
def test_compression_and_shear_with_per_pair_caps_alone_blow_up(lmp, packings, scene):
    """mu_f = 10 Pa s, friction and the shear film: with `limit pair` the films feed the motion
    until atoms are lost (measured with LAMMPS's whole neighbor list, `trim no`: 233 atoms lost in
    the shear, 5e-5 s, 181 in the compression, 5e-6 s) or, with the trimmed list (the default),
    until the kinetic energy is 70 (shear) and 7000 (compression) times the largest of the same
    scene with `limit atom` (which both lists run alike, to all printed digits). Which of the two
    a blow-up ends in follows its round-off: either counts, with the energy 30 times at least."""
    if scene == "shear":
        script = dp.shear_scene(str(packings["loose61"]), 10.0, 5e-5, 2000, 20.0, extra=WET_FRICTION)
    else:
        script = dp.compression_scene(str(packings["loose46"]), 10.0, 5e-6, 2000, 0.70, extra=WET_FRICTION)
    lmp(script)
    stable = largest_kinetic_energy(lmp.log)
    lmp(with_per_pair_caps(script).replace("thermo_modify lost error", "thermo_modify lost warn"), check=False)
    assert "(limit pair)" in lmp.log
    assert "Lost atoms" in lmp.log or largest_kinetic_energy(lmp.log) >= 30.0 * stable


@pytest.mark.parametrize("scene", ["shear", "shear with the shear film", "compression"])
def test_one_two_and_four_ranks_agree(lmp, packings, scene):
    """300 steps, wet with friction. Before the shear film joined the film budget its chatter
    amplified round-off (2e-8 after 100 steps and 20 % after 300 at mu_f 10 Pa s); now the shear
    with the shear film agrees to all printed digits on 1 and 2 ranks. 4 ranks (LAMMPS's grid
    2 by 1 by 2, checked in the log: MPICH oversubscribes a 2-vCPU machine rather than fail): the
    same, to all printed digits, in the three scenes (the velocities come from the data file, the
    same on any grid)."""
    if scene.startswith("shear"):
        extra = WET_FRICTION if scene.endswith("film") else "friction 0.5 shearfilm no"
        script = dp.shear_scene(str(packings["loose61"]), 10.0, 5e-5, 300, 20.0, average_from=100,
                                extra=extra)
    else:
        script = dp.compression_scene(str(packings["loose46"]), 1.0, 5e-5, 300, 0.70,
                                      extra="friction 0.5 shearfilm no")
    one = lmp(script)["final"]
    two = lmp(script, nprocs=2)["final"]
    assert dense_scenes.ranks(lmp.log) == {2}
    four = lmp(script, nprocs=4, env=dense_scenes.OVERSUBSCRIBED)["final"]
    assert dense_scenes.ranks(lmp.log) == {4}
    assert one[-1 if scene == "compression" else 2] == dp.N_ATOMS
    assert two == pytest.approx(one, rel=1e-8)
    assert four == pytest.approx(one, rel=1e-8)


# ------------------------------------------------------------------------------------------
# Item 4: contacts too short for the packing
# ------------------------------------------------------------------------------------------

def dry_preloaded(lmp, packings, e_d, duration, steps=500):
    return dp.energy_scene(with_velocities(lmp, packings["preloaded"]), 0.0, 5e-6, steps, every=50,
                           e_d=e_d, contact=duration)


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("duration,named", [("ncontact 2", "ncontact = 2 "), ("ncontact 1", "ncontact = 1 "),
                                            ("tcontact 1e-5", "tcontact = 1e-05 (N_c = t_c / dt = 2)")])
def test_too_short_a_contact_stops_with_an_error(lmp, packings, duration, named, nprocs):
    """The preloaded bed, dry, N_c <= 2: a mode of the contact network grows every step (lower
    bound 4.92 at N_c = 2, 7.2 at 1). Before the check: `Lost atoms: original 300 current 297`
    (N_c = 2, t_c = 2 dt) and `current 39` (N_c = 1) within 50 steps."""
    with pytest.raises(lammps_run.LammpsError) as err:
        lmp(dry_preloaded(lmp, packings, 0.9, duration), nprocs=nprocs)
    message = str(err.value)
    assert named in message
    assert "too short a contact for this packing" in message
    assert "contacts) and" in message and "grows every step" in message
    assert ("Use ncontact >=" in message) if duration.startswith("ncontact") else ("a timestep <=" in message)
    assert "Lost atoms" not in err.value.log


def test_the_advised_contact_duration_runs_silently(lmp, packings):
    """The ERROR's advice (N_c = 2 on the preloaded bed) is a duration whose upper bound is below 4:
    run with it, the check says nothing (the advice is the shortest of 3 digits, rounded up, whose
    bound passes: tests/kernel/test_contact_network.cpp; in LIGGGHTS it once named the N_c in use)."""
    with pytest.raises(lammps_run.LammpsError) as err:
        lmp(dry_preloaded(lmp, packings, 0.9, "ncontact 2"))
    advised = float(re.search(r"Use ncontact >= (\S+?)[ .,;]", str(err.value)).group(1))
    assert 2.0 < advised < 8.0
    rows, log = run_energy(lmp, dry_preloaded(lmp, packings, 0.9, f"ncontact {advised}", steps=1000))
    assert "contact network" not in log and "too short" not in log
    assert_bounded(rows, rows[0, 2] + rows[0, 3] + rows[0, 4])


@pytest.mark.parametrize("extra", ["", "friction 0.5"])
def test_compression_with_too_short_a_contact_stops_with_an_error(lmp, packings, extra):
    """Dry compression from 0.46 to 0.70 at N_c = 2: the network becomes unstable on the way
    (checked every 10 steps). Before the check: `Lost atoms: original 300 current 298` at phi 0.66
    (`current 206` with friction); now the ERROR, before any atom is lost."""
    script = dp.compression_scene(str(packings["loose46"]), 0.0, 5e-6, 2000, 0.70, extra=extra,
                                  contact="ncontact 2")
    with pytest.raises(lammps_run.LammpsError) as err:
        lmp(script)
    assert "ncontact = 2 is too short a contact for this packing" in str(err.value)
    assert "Lost atoms" not in err.value.log


def test_likely_unstable_network_is_warned(lmp, packings):
    """e_d = 0.02 at N_c = 8: the dashpots alone (load 1.49, largest eigenvalue 3.07 of the unit
    network: 4.6 > 4) make a mode grow; the lower bound (3.5) cannot prove it, the upper (15)
    cannot exclude it: a WARNING, once, and the run goes on."""
    lmp(dry_preloaded(lmp, packings, 0.02, "ncontact 8"))
    warnings = [line for line in lmp.log.splitlines() if "likely unstable" in line]
    assert len(warnings) == 1 and "ncontact = 8" in warnings[0] and "ncontact >=" in warnings[0]


@pytest.mark.parametrize("e_d,duration", [(0.9, "ncontact 8"), (0.9, "ncontact 3"), (0.5, "ncontact 8")])
def test_stable_networks_run_silently(lmp, packings, e_d, duration):
    """N_c = 8 (e_d = 0.9: below the check; 0.5: checked, bounds 1.09 and 4.7) and N_c = 3 (checked;
    stable, lambda_max s = 3.4): no message, no atom lost, the energy bounded as above."""
    rows, log = run_energy(lmp, dry_preloaded(lmp, packings, e_d, duration, steps=1000))
    assert "contact network" not in log and "too short" not in log
    assert_bounded(rows, rows[0, 2] + rows[0, 3] + rows[0, 4])

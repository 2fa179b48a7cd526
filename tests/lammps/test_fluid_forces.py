"""fix fluid/drag's fluid inertia and memory (doc/fix_fluid_drag.rst, src/lubricated/fluid_inertia.h):
added mass (solved for, stable at any density ratio), the undisturbed-flow force, the Basset
history force (window + exponential tail, per atom), Magnus lift.

References: Basset's problem (a sphere released from rest in Stokes flow) in closed form
(basset_closed_form.py); the steady response to an oscillating fluid in closed form (Fourier
transform of the same equation); terminal velocities of the drag law; an uninterrupted run for
restarts and for 2 ranks.
"""
import cmath
import math

import pytest

from basset_closed_form import released_from_rest, without_history
from scene_chain import dump_state

SCENE = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
processors * 1 1
neigh_modify every 1 delay 0 check no
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 1 box
create_atoms 1 single {x0} 0 0
create_atoms 1 single 0.004 0.004 0.004
set group all diameter {d} density {rho_p}
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix nve all nve/sphere
{gravity}
fix fluid all fluid/drag viscosity {mu} density {rho_f} law {law} {buoyancy} {extra}
timestep {dt}
variable s equal step
variable vx equal vx[1]
fix out all print {every} "RESULT v${s} ${vx}"
thermo {steps}
run {steps}
"""

D, MU, RHO_F, G = 1e-3, 1.0, 1000.0, 9.81    # Stokes: Re < 1e-3 below


def volume(d=D):
    return math.pi / 6 * d ** 3


def scene(rho_p, extra, dt, steps, every, d=D, mu=MU, law="stokes", x0=-1e-6, gravity=True):
    text = SCENE
    grav = "fix weight all gravity 9.81 vector 1 0 0" if gravity else ""
    values = {"{x0}": repr(x0), "{d}": repr(d), "{rho_p}": repr(rho_p), "{mu}": repr(mu),
              "{rho_f}": repr(RHO_F), "{law}": law, "{extra}": extra, "{dt}": repr(dt),
              "{steps}": str(steps), "{every}": str(every), "{gravity}": grav,
              "{buoyancy}": "buoyancy 9.81 0 0" if gravity else ""}
    for key, value in values.items():
        text = text.replace(key, value)
    return text


def basset_problem(rho_p, c_m=0.5):
    """Force F, effective mass M, beta, K of a sphere released from rest (gravity along +x)."""
    m = rho_p * volume()
    return ((rho_p - RHO_F) * volume() * G, m + c_m * RHO_F * volume(), 3 * math.pi * MU * D,
            1.5 * D * D * math.sqrt(math.pi * RHO_F * MU))


@pytest.mark.parametrize("rho_p", [2500.0, 250.0, 10.0], ids=["heavy", "light", "bubble"])
def test_released_from_rest_follows_bassets_solution(lmp, rho_p):
    """Added mass + history against the erfc-exp closed form over 20 relaxation times
    tau = M / beta, 100 steps per tau. Tolerance 3e-3 of the terminal speed: the time
    discretisation's O(dt / tau) error on the slip acceleration of the first step, about 1e-3
    (measured at 50 and 200 steps per tau), and the tail's kernel error (< 1e-3, kernel test).
    The solution without history differs by up to 0.3 of the terminal speed, so the test sees
    the history; with no tail modes (window only) the run is off by 0.15-0.3."""
    force, mass, beta, basset = basset_problem(rho_p)
    tau, n = mass / beta, 100
    result = lmp(scene(rho_p, "added_mass 0.5 history yes", tau / n, 20 * n, n))
    terminal = force / beta
    worst, history_effect = 0.0, 0.0
    for k in range(1, 21):
        t = k * tau
        exact = released_from_rest(t, force, mass, beta, basset)
        worst = max(worst, abs(result[f"v{k * n}"] - exact) / abs(terminal))
        history_effect = max(history_effect, abs(without_history(t, force, mass, beta) - exact) / abs(terminal))
    assert worst < 3e-3
    assert history_effect > 0.1


def test_added_mass_alone_relaxes_exponentially(lmp):
    """Without history: v = v_t (1 - exp(-t / tau)), tau = (m + m_a) / beta, for a sphere
    five times lighter than the fluid (the explicit added mass diverges there). The drag of
    a step sees the half-step velocity, a lag of dt / 2: the error is below (dt / 2 tau) v_t."""
    rho_p = 200.0
    force, mass, beta, _ = basset_problem(rho_p)
    tau, n = mass / beta, 50
    result = lmp(scene(rho_p, "added_mass 0.5", tau / n, 8 * n, n))
    for k in range(1, 9):
        exact = without_history(k * tau, force, mass, beta)
        assert result[f"v{k * n}"] == pytest.approx(exact, abs=0.5 / n * abs(force / beta))


def schiller_naumann_terminal(d, rho_p, mu):
    weight = abs(rho_p - RHO_F) * volume(d) * G
    lo, hi = 0.0, weight / (3 * math.pi * mu * d)
    for _ in range(200):
        w = 0.5 * (lo + hi)
        re = RHO_F * w * d / mu
        (lo, hi) = (w, hi) if 3 * math.pi * mu * d * w * (1 + 0.15 * re ** 0.687) < weight else (lo, w)
    return 0.5 * (lo + hi)


@pytest.mark.parametrize("extra", ["added_mass 0.5", "added_mass 0.5 history yes"])
def test_light_sphere_rises_to_the_terminal_velocity(lmp, extra):
    """rho_p / rho_f = 0.01 at finite Re (Schiller-Naumann, Re ~ 60), half a Stokes relaxation
    time (m + m_a) / beta per step, where an explicit added mass diverges at once: stable,
    monotone, and at the drag law's terminal speed (the rise is -x: gravity is +x). Without
    history exactly (steady state); with history from below by the Basset tail's deficit,
    K / (beta_lin sqrt(t)) for large t (Laplace transform at small s), beta_lin >= 3 pi mu d."""
    d, mu, rho_p = 1e-3, 5e-3, 10.0
    beta = 3 * math.pi * mu * d
    tau = (rho_p + 0.5 * RHO_F) * volume(d) / beta
    steps = 3000
    result = lmp(scene(rho_p, extra, tau / 2, steps, 10, d=d, mu=mu, law="schiller-naumann"))
    terminal = schiller_naumann_terminal(d, rho_p, mu)
    assert RHO_F * terminal * d / mu > 5.0
    speeds = [-result[f"v{k}"] for k in range(10, steps + 1, 10)]
    assert all(b >= a - 1e-6 * terminal for a, b in zip(speeds, speeds[1:]))    # no oscillation
    if "history" not in extra:
        assert speeds[-1] == pytest.approx(terminal, rel=1e-9)
    else:
        basset = 1.5 * d * d * math.sqrt(math.pi * RHO_F * mu)
        deficit = 1 - speeds[-1] / terminal
        assert 0 < deficit < basset / (beta * math.sqrt(steps * tau / 2))


def test_finite_re_transient_with_added_mass(lmp):
    """A glass bead (rho_p / rho_f = 2.5) released from rest in water at Re_t ~ 20: the
    transient of (m + m_a) dv/dt = F - beta_SN(v) v against a fine RK4 integration of the
    same equation (no history: not a comparison with experiment). The drag sees the
    half-step velocity: error below (dt / 2 tau_lin) v_t, tau_lin = (m + m_a) / beta_lin the
    relaxation time of the linearised drag at the terminal velocity."""
    d, mu, rho_p = 5e-4, 1e-3, 2500.0
    m, m_a = rho_p * volume(d), 0.5 * RHO_F * volume(d)
    force = (rho_p - RHO_F) * volume(d) * G
    tau = (m + m_a) / (3 * math.pi * mu * d)
    n = 200
    result = lmp(scene(rho_p, "added_mass 0.5", tau / n, 6 * n, n // 5, d=d, mu=mu, law="schiller-naumann"))

    def transient(mass, h=tau / 2000):
        def accel(v):
            re = RHO_F * abs(v) * d / mu
            return (force - 3 * math.pi * mu * d * (1 + 0.15 * re ** 0.687) * v) / mass
        v, velocities = 0.0, {}
        for k in range(1, 6 * 2000 + 1):
            k1 = accel(v)
            k2 = accel(v + h / 2 * k1)
            k3 = accel(v + h / 2 * k2)
            k4 = accel(v + h * k3)
            v += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            if k % 400 == 0:
                velocities[k // 400] = v    # every tau / 5
        return velocities
    reference = transient(m + m_a)
    terminal = schiller_naumann_terminal(d, rho_p, mu)
    assert RHO_F * terminal * d / mu > 10
    assert reference[30] == pytest.approx(terminal, rel=1e-2)
    re_t = RHO_F * terminal * d / mu
    tau_lin = tau / (1 + 0.15 * 1.687 * re_t ** 0.687)
    tolerance = 0.5 * (tau / n) / tau_lin * terminal
    for k in range(1, 31):
        assert result[f"v{k * n // 5}"] == pytest.approx(reference[k], abs=tolerance)
    # Without the added mass the bead would be faster early on: the test sees it.
    light = transient(m)
    assert max(light[k] - reference[k] for k in light) > 4 * tolerance


def test_keywords_off_change_nothing(lmp):
    """Every new keyword given as off: the same bits as none given."""
    plain = lmp(scene(2500.0, "", 1e-6, 200, 100) + dump_state(2))
    off = lmp(scene(2500.0, "added_mass 0 pressure no history no magnus no saffman no", 1e-6, 200, 100)
              + dump_state(2))
    assert off == plain


def oscillation_response(rho_p, omega, c_m=0.5, history=True):
    """Complex v / u of a sphere in u = U sin(omega t): Fourier transform of
    m dv/dt = beta (u - v) + rho_f V du/dt + m_a (du/dt - dv/dt) + K int (u' - v')/sqrt(t - tau)."""
    m, m_a = rho_p * volume(), c_m * RHO_F * volume()
    beta = 3 * math.pi * MU * D
    memory = 1.5 * D * D * math.sqrt(math.pi * RHO_F * MU) * cmath.sqrt(math.pi * 1j * omega) if history else 0
    return ((beta + 1j * omega * (RHO_F * volume() + m_a) + memory) /
            (beta + 1j * omega * (m + m_a) + memory))


@pytest.mark.parametrize("history", [False, True], ids=["added-mass", "history"])
def test_oscillating_fluid(lmp, history):
    """A light sphere (rho_p / rho_f = 0.2) in u = U sin(omega t), omega tau = 3: amplitude and
    phase of its steady oscillation against the closed form (amplified above U by the fluid's
    inertia). Fitted over the last two of eight periods; 1 % of the amplitude and 0.01 rad:
    the start-up transient (algebraic with history) and O(dt) of 100 steps per period."""
    rho_p = 200.0
    _, mass, beta, _ = basset_problem(rho_p)
    omega = 3.0 * beta / mass
    period, n = 2 * math.pi / omega, 200
    amplitude = 1e-3
    variables = (f"variable ux equal {amplitude}*sin({omega}*time)\n"
                 f"variable ax equal {amplitude * omega}*cos({omega}*time)\n")
    extra = "velocity v_ux 0 0 acceleration v_ax 0 0 added_mass 0.5 pressure yes" + (
        " history yes" if history else "")
    script = scene(rho_p, extra, period / n, 8 * n, 1, gravity=False).replace(
        "fix nve all", variables + "fix nve all")
    result = lmp(script)
    # Project the last two periods on sin and cos.
    s = c = 0.0
    for k in range(6 * n, 8 * n):
        phase = omega * k * period / n
        s += result[f"v{k}"] * math.sin(phase)
        c += result[f"v{k}"] * math.cos(phase)
    measured = complex(s, c) / n / amplitude    # v = U Re(R) sin + U Im(R) cos
    expected = oscillation_response(rho_p, omega, history=history)
    assert abs(expected) > 1.3
    assert abs(measured) == pytest.approx(abs(expected), rel=1e-2)
    assert cmath.phase(measured) == pytest.approx(cmath.phase(expected), abs=1e-2)


HISTORY = "added_mass 0.5 history yes window 5 tail 10"


def history_scene(steps, extra_run=""):
    """The heavy sphere of Basset's problem, crossing x = 0 (the ranks' boundary on 2 ranks)
    while its history builds up, and a second sphere at rest."""
    force, mass, beta, _ = basset_problem(2500.0)
    text = scene(2500.0, HISTORY, mass / beta / 50, steps, 10 ** 6, x0=-3e-7)
    return text.replace(f"run {steps}\n", f"run {steps}\n{extra_run}") + dump_state(2)


def test_two_ranks_agree_and_the_history_migrates(lmp):
    serial = lmp(history_scene(600))
    assert serial["x1"][0] > 1e-8    # crossed the boundary
    parallel = lmp(history_scene(600), nprocs=2)
    assert "2 by 1 by 1 MPI processor grid" in lmp.log
    for key in serial:
        assert parallel[key] == pytest.approx(serial[key], rel=1e-10, abs=1e-18), key


RESTARTED = """plugin load ${plugin}
read_restart mid.restart
neigh_modify every 1 delay 0 check no
comm_modify vel yes
fix nve all nve/sphere
fix weight all gravity 9.81 vector 1 0 0
fix {id} all fluid/drag viscosity {mu} density {rho_f} law stokes buoyancy 9.81 0 0 {extra}
run 300
"""


@pytest.mark.parametrize("integrator", ["nve/sphere", "nve/sphere/midpoint"])
@pytest.mark.parametrize("nprocs", [1, 2])
def test_restart_continues_the_history_exactly(lmp, nprocs, integrator):
    """run 600 == run 300; write_restart; (new process) read_restart; run 300 == run 300; run 300,
    to 1e-12: the window, the tail modes and the step under way travel in the restart file. A
    fix of another ID (its history lost) differs: the test can fail. With nve/sphere/midpoint
    the set-up's forces (at X^n, V^n) are not those of the step (at the mid-step point): the
    set-up must keep the step's uncommitted slip acceleration (before, it stored its own, and
    the split run differed by 7e-6)."""
    def integrated(script):
        return script.replace("fix nve all nve/sphere", f"fix nve all {integrator}")
    whole = lmp(integrated(history_scene(600)), nprocs=nprocs)
    split = lmp(integrated(history_scene(300, "write_restart mid.restart\nrun 300\n")), nprocs=nprocs)
    restarted_script = integrated(RESTARTED.replace("{mu}", repr(MU)).replace("{rho_f}", repr(RHO_F)).replace(
        "{extra}", HISTORY))
    restarted = lmp(restarted_script.replace("{id}", "fluid") + dump_state(2), nprocs=nprocs, name="in.restart")
    fresh = lmp(restarted_script.replace("{id}", "other") + dump_state(2), nprocs=nprocs, name="in.fresh")
    for key in ("x1", "v1", "x2", "v2"):
        assert split[key] == pytest.approx(whole[key], rel=1e-12, abs=1e-18), key
        assert restarted[key] == pytest.approx(whole[key], rel=1e-12, abs=1e-18), key
    assert fresh["v1"][0] != pytest.approx(whole["v1"][0], rel=1e-6)


def dt_reset_scene(steps, dt_reset, runs=1):
    """history_scene with fix dt/reset before the drag fix (its set-up then changes the step
    first), `runs` runs of `steps`."""
    text = history_scene(steps).replace("fix fluid all", f"fix dtr all dt/reset 1 {dt_reset} units box\nfix fluid all")
    return text.replace(f"run {steps}\n", f"run {steps}\n" * runs)


def test_a_step_set_at_the_first_set_up_lays_the_tail_out_for_it(lmp):
    """fix dt/reset with a large Xmax and Tmax sets the step at the set-up of the first run (not the
    timestep command's) and keeps it: the history is empty until the first step, so the tail is
    laid out for that step and the run equals one with that timestep, to 1e-12, without a
    warning. Before, the tail kept the rates of the timestep command's step (here 4 times
    smaller) for the whole run."""
    force, mass, beta, _ = basset_problem(2500.0)
    dt = mass / beta / 50
    reset = lmp(dt_reset_scene(300, f"NULL {dt / 4!r} 1.0").replace(f"timestep {dt!r}", f"timestep {dt / 16!r}"))
    assert f"timestep {dt / 16!r}" in lmp.log
    reference = lmp(history_scene(300).replace(f"timestep {dt!r}", f"timestep {dt / 4!r}"))
    assert "WARNING" not in lmp.log
    for key in reference:
        assert reset[key] == pytest.approx(reference[key], rel=1e-12, abs=1e-18), key


@pytest.mark.parametrize("dt", [1e-3, 1e-4])
def test_a_step_beyond_the_drag_cap_warns_with_history(lmp, dt):
    """beta dt / (m + m_a + m_h) > 1, m_h = 2 K sqrt(dt): the drag is capped at (m + m_a +
    m_h) / dt but the history force is not, which overshoots (a sphere stopped by the drag
    moves on): a warning with the ratio (1.36 at dt = 1 ms, 0.29 at 0.1 ms: none)."""
    _, mass, beta, basset = basset_problem(2500.0)
    ratio = beta * dt / (mass + 2 * basset * math.sqrt(dt))
    lmp(scene(2500.0, "added_mass 0.5 history yes", dt, 1, 1))
    warnings = [line for line in lmp.log.splitlines() if line.startswith("WARNING") and "beta dt" in line]
    if ratio > 1:
        assert len(warnings) == 1 and f"= {ratio:.3g} (allowed for an accurate history: <= 1" in warnings[0], warnings
    else:
        assert not warnings, warnings


def test_magnus_lift_of_a_spinning_sphere(lmp):
    """Rubinow & Keller: a sphere spinning at omega z in a fluid moving at U x feels
    pi R^3 rho_f (w x Omega) = -pi R^3 rho_f U omega y at rest (the fix's global vector)."""
    u, omega = 0.01, 50.0
    script = scene(1000.0, f"velocity {u} 0 0 magnus yes", 1e-5, 0, 1, gravity=False).replace(
        "run 0", f"set atom 1 omega 0 0 {omega}\nset atom 2 omega 0 0 0\nrun 0\n"
        'print "RESULT lift $(f_fluid[1]:%.15g) $(f_fluid[2]:%.15g) $(f_fluid[3]:%.15g)"')
    lift = lmp(script)["lift"]
    beta = 3 * math.pi * MU * D
    assert lift[0] == pytest.approx(2 * beta * u, rel=1e-12)    # drag on both spheres
    assert lift[1] == pytest.approx(-math.pi * (D / 2) ** 3 * RHO_F * u * omega, rel=1e-12)
    assert lift[2] == 0.0


def test_saffman_lift_and_the_fluids_rotation(lmp):
    """Spheres at rest in a fluid moving at U x with the vorticity of the shear u = gamma y x,
    curl u = -gamma z: Saffman's lift with Mei's correction, 1.615 d^2 sqrt(rho mu / gamma) C U
    gamma, along +y (towards the faster fluid for the lagging spheres). Sphere 1 spins with
    the fluid (omega = curl u / 2): no Magnus lift; sphere 2 does not spin, so relative to the
    fluid it spins at Omega = -curl u / 2 = gamma / 2 z: Magnus pi R^3 rho (w x Omega), -y."""
    u, gamma = 0.01, 40.0
    script = scene(1000.0, f"velocity {u} 0 0 vorticity 0 0 {-gamma} saffman yes magnus yes", 1e-5, 0, 1,
                   gravity=False).replace(
        "run 0", f"set atom 1 omega 0 0 {-gamma / 2}\nset atom 2 omega 0 0 0\nrun 0\n"
        'print "RESULT lift $(f_fluid[1]:%.15g) $(f_fluid[2]:%.15g) $(f_fluid[3]:%.15g)"')
    lift = lmp(script)["lift"]
    re_p, re_s = RHO_F * u * D / MU, RHO_F * gamma * D * D / MU
    b = re_s / (2 * re_p)
    mei = (1 - 0.3314 * math.sqrt(b)) * math.exp(-re_p / 10) + 0.3314 * math.sqrt(b)
    saffman = 1.615 * D * D * math.sqrt(RHO_F * MU / gamma) * mei * u * gamma
    magnus = -math.pi * (D / 2) ** 3 * RHO_F * u * gamma / 2
    assert lift[1] == pytest.approx(2 * saffman + magnus, rel=1e-12)
    assert 2 * saffman > 10 * abs(magnus)


@pytest.mark.parametrize("extra,fragment", [
    ("added_mass -0.5", "added_mass C_m = -0.5 is out of range (allowed: 0 <= C_m <= 10"),
    ("history maybe", "history must be yes or no, got 'maybe'"),
    ("history yes window 0", "window N_w = 0 is out of range (allowed: 1 <= N_w <= 1000)"),
    ("history yes tail 65", "tail M = 65 is out of range (allowed: 0 or 8 <= M <= 64)"),
    ("history yes tail 4", "tail M = 4 is out of range"),
    ("pressure yes velocity v_ux 0 0", "needs the acceleration keyword"),
    ("added_mass 0.5 acceleration v_nothing 0 0", "variable nothing for the fluid acceleration does not exist"),
    ("magnus", "missing value(s) for keyword magnus"),
    ("saffman yes vorticity v_nothing 0 0", "variable nothing for the fluid vorticity does not exist"),
    ("saffman yes", "saffman yes needs the vorticity keyword"),
    ("wall zplane 0 NULL", "wall (the added mass's near-wall increase) needs added_mass C_m > 0"),
    ("added_mass 0.5 wall wplane 0 NULL", "wall must be xplane, yplane or zplane, got 'wplane'"),
    ("added_mass 0.5 wall zplane NULL NULL", "wall zplane NULL NULL gives no wall"),
    ("added_mass 0.5 wall zplane -0.01 NULL wall zplane NULL 0.01", "wall zplane is given twice"),
    ("added_mass 0.5 wall zplane -0.01 NULL", "wall zplane in a periodic dimension"),
])
def test_bad_input(lmp, extra, fragment):
    script = scene(2500.0, extra, 1e-6, 1, 1).replace("fix nve all", "variable ux equal 0.0\nfix nve all")
    lmp(script, check=False)
    error = next(line for line in lmp.log.splitlines() if "ERROR" in line)
    assert fragment in error, error


def test_fluid_inertia_needs_the_density(lmp):
    script = scene(2500.0, "history yes", 1e-6, 1, 1, gravity=False).replace(
        f"density {RHO_F!r}", "density 0")
    lmp(script, check=False)
    assert "need the fluid density" in next(line for line in lmp.log.splitlines() if "ERROR" in line)


def test_a_force_fix_after_the_added_mass_is_an_error(lmp):
    """The added mass divides the total force: a force added after it would be wrong."""
    script = scene(2500.0, "added_mass 0.5", 1e-6, 1, 1).replace(
        "timestep", "fix late all addforce 0 0 1e-9\ntimestep")
    lmp(script, check=False)
    error = next(line for line in lmp.log.splitlines() if "ERROR" in line)
    assert "must be the last fix that adds forces: define fix late (style addforce) before it" in error


NEAR_WALL = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary p p f
comm_modify vel yes
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 1 box
create_atoms 1 single 0 0 {z0}
set atom 1 diameter {d} density {rho}
velocity all set {vx} 0 {vz}
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix nve all nve/sphere
fix fluid all fluid/drag viscosity 1e-9 density {rho} law stokes added_mass 0.5 {wall}
timestep {dt}
thermo 1000
run {steps}
print "RESULT z $(z[1]:%.17g)"
print "RESULT vx $(vx[1]:%.17g)"
print "RESULT vz $(vz[1]:%.17g)"
"""


@pytest.mark.parametrize("wall", ["wall zplane 0 NULL", "wall zplane NULL 0.0"])
def test_near_wall_added_mass_conserves_energy_and_momentum(lmp, wall):
    """A neutrally buoyant sphere (rho_p = rho_f, a fluid without viscosity: 1e-9 Pa s) moving at
    (0.4, 0, -1) m/s from 4 R to 1.05 R above a floor (or, mirrored, below a ceiling): with the
    near-wall added mass M_d(h) = C_m rho_f V (1 + c_d (R/h)^3) (c = 3/8 normal, 3/16 parallel;
    wall_added_mass.h) and its forces, Lagrange's equations conserve the kinetic energy
    (1/2) sum (m + M_d) v_d^2 and the momentum along the wall (m + M_x) v_x, so the sphere slows
    from 1 to 0.951 m/s normal to the wall and 0.4 to 0.385 along it. Tolerance 2e-5: the forces
    take the half-step velocity, as every velocity-dependent force under velocity Verlet, so the
    error is first order in dt: 9.2e-6, 4.6e-6, 2.3e-6 in energy at 1500, 3000, 6000 steps (the
    drag, 1e-9 of the inertia, is far below). Without the forces the energy is 10 % off."""
    radius, rho = 0.5e-3, 1000.0
    ceiling = "NULL" in wall.split()[2]
    z0 = 4 * radius if not ceiling else -4 * radius
    vz0, vx0 = (-1.0 if not ceiling else 1.0), 0.4
    steps = 3000
    dt = 2.95 * radius / 1.0 / steps
    script = NEAR_WALL
    for key, value in {"{z0}": repr(z0), "{d}": repr(2 * radius), "{rho}": repr(rho), "{vx}": repr(vx0),
                       "{vz}": repr(vz0), "{wall}": wall, "{dt}": repr(dt), "{steps}": str(steps)}.items():
        script = script.replace(key, value)
    result = lmp(script)
    mass, base = rho * volume(2 * radius), 0.5 * rho * volume(2 * radius)

    def added(h, c):
        return base * (1 + c * (radius / h) ** 3)

    h = abs(result["z"])
    assert 1.0 * radius < h < 1.2 * radius
    energy0 = 0.5 * (mass + added(4 * radius, 3 / 8)) * vz0 ** 2 + 0.5 * (mass + added(4 * radius, 3 / 16)) * vx0 ** 2
    energy = (0.5 * (mass + added(h, 3 / 8)) * result["vz"] ** 2
              + 0.5 * (mass + added(h, 3 / 16)) * result["vx"] ** 2)
    assert energy == pytest.approx(energy0, rel=2e-5)
    assert (mass + added(h, 3 / 16)) * result["vx"] == pytest.approx((mass + added(4 * radius, 3 / 16)) * vx0,
                                                                     rel=2e-5)
    assert abs(result["vz"]) < 0.96    # slowed by 5 % (0.951 at h = 1.05 R)

"""fix fluid/drag's finite-Re history kernel (kernel mei-adrian, src/lubricated/history_kernel.h,
doc/fix_fluid_drag.rst): a sphere settling from rest in water against the measured transients of
Mordant & Pinton, and the kernel's Stokes limit (Basset's closed form).

Data: N. Mordant, J.-F. Pinton, Velocity measurement of a settling sphere, Eur. Phys. J. B 18,
343 (2000), as quoted (their table: diameter, terminal speed v_inf, time tau_95 to 95 % of it, and
the exponential fit v = v_inf (1 - exp(-3 t / tau_95)) of the measured curves) by the Basilisk
test case "Settling sphere in a large container" (sphere-settling-large-domain, A. Ghigo), whose
cases 1-3 are glass (rho_p / rho_f = 2.56) of 0.5 and 1.5 mm and steel (7.71) of 0.8 mm in water
with nu = 0.89e-6 m^2/s (the nu of its Galileo numbers 49.14, 255.35, 206.27; the Re = 41, 360,
280 it quotes give nu = 0.90e-6). The original paper was not read: the numbers are those of the
quote.
"""
import math

import pytest

from basset_closed_form import released_from_rest
from scene_chain import dump_state
from test_fluid_forces import basset_problem, scene, schiller_naumann_terminal

RHO_F, MU = 1000.0, 0.89e-3
MORDANT = {    # d [m], rho_p [kg/m^3], v_inf [m/s], tau_95 [s]
    "glass-0.5mm": (0.5e-3, 2560.0, 0.0741, 0.055),
    "glass-1.5mm": (1.5e-3, 2560.0, 0.218, 0.142),
    "steel-0.8mm": (0.8e-3, 7710.0, 0.316, 0.108),
}


def settle(lmp, case, extra, n=150, periods=3):
    """Velocities every step of a sphere released from rest, n steps per tau_95, and the time
    to 95 % of the drag law's terminal speed (linear interpolation between steps)."""
    d, rho_p, _, tau95 = MORDANT[case]
    dt, steps = tau95 / n, periods * n
    result = lmp(scene(rho_p, "added_mass 0.5 " + extra, dt, steps, 1, d=d, mu=MU, law="schiller-naumann"))
    speeds = [0.0] + [result[f"v{k}"] for k in range(1, steps + 1)]
    terminal = schiller_naumann_terminal(d, rho_p, MU)
    t95 = math.inf
    for k in range(1, steps + 1):
        if speeds[k] >= 0.95 * terminal:
            f = (0.95 * terminal - speeds[k - 1]) / (speeds[k] - speeds[k - 1])
            t95 = (k - 1 + f) * dt
            break
    return speeds, dt, terminal, t95


@pytest.mark.parametrize("case", list(MORDANT))
def test_settling_sphere_follows_the_measured_transient(lmp, case):
    """Added mass, Schiller-Naumann drag and the Mei-Adrian history force against the measured
    transient (Re_t = 40-370). Tolerances:
    - terminal speed, 7 %: Schiller-Naumann's C_D is good to about 5 % below Re 800 (the
      accuracy usually quoted for it; from memory, not re-read), 3-4 % of the speed at these
      Re; and nu, rho_p are the quote's, not the paper's (water at 20-25 C spans nu =
      0.89-1.0e-6, another 3-4 % of the speed). The 0.5 mm bead is 6.4 % fast.
    - tau_95, 15 %: the drag law's 5 % in C_D is 5 % of the relaxation time; 10 % for the
      exponential fit's representation of the measured curves and the kernel's own accuracy,
      neither of which the quote states: a budget, not a derived bound. The model is 10-14 %
      early on all three (it is not tuned to them).
    - the whole curve v / v_t against the fit, 0.05 of v_t (0.026-0.047 here).
    The same transient with Basset's kernel (too much memory, the t^-1/2 tail) takes 1.8 to
    about 9 times tau_95, and without history 0.65-0.8 times: both outside the tolerance."""
    d, rho_p, v_inf, tau95 = MORDANT[case]
    speeds, dt, terminal, t95 = settle(lmp, case, "history yes kernel mei-adrian")
    assert terminal == pytest.approx(v_inf, rel=0.07)
    assert speeds[-1] == pytest.approx(terminal, rel=2e-3)    # at rest after 3 tau_95, within the kernel's tail
    assert t95 == pytest.approx(tau95, rel=0.15)
    fit = [1 - math.exp(-3 * k * dt / tau95) for k in range(len(speeds))]
    assert max(abs(v / terminal - f) for v, f in zip(speeds, fit)) < 0.05
    # The kernel decides it: Basset's is far too slow, none too fast.
    _, _, _, t95_basset = settle(lmp, case, "history yes kernel basset")
    _, _, _, t95_none = settle(lmp, case, "")
    assert t95_basset > 1.5 * tau95
    assert t95_none < 0.85 * tau95


def test_stokes_limit_is_bassets_solution(lmp):
    """At Re -> 0 (Re_t ~ 1e-3 here, crossover time s_c ~ 1e6 relaxation times) the Mei-Adrian
    kernel is Basset's: the sphere released from rest follows the erfc-exp closed form within
    the 3e-3 of the terminal speed of the Basset kernel's test (test_fluid_forces.py)."""
    rho_p = 2500.0
    force, mass, beta, basset = basset_problem(rho_p)
    tau, n = mass / beta, 100
    result = lmp(scene(rho_p, "added_mass 0.5 history yes kernel mei-adrian", tau / n, 20 * n, n))
    for k in range(1, 21):
        exact = released_from_rest(k * tau, force, mass, beta, basset)
        assert result[f"v{k * n}"] == pytest.approx(exact, abs=3e-3 * force / beta)


def test_basset_kernel_keyword_changes_nothing(lmp):
    """kernel basset is the default: the same bits."""
    plain = lmp(scene(2500.0, "added_mass 0.5 history yes", 1e-5, 200, 100))
    named = lmp(scene(2500.0, "added_mass 0.5 history yes kernel basset", 1e-5, 200, 100))
    assert named == plain


FINITE_RE = "added_mass 0.5 history yes kernel mei-adrian window 5 tail 10"


def moving_scene(steps, extra_run=""):
    """The 0.5 mm glass sphere at Re ~ 40, from just left of x = 0 (the ranks' boundary on 2
    ranks): it crosses that boundary and the periodic one while its history builds up."""
    d, rho_p, _, tau95 = MORDANT["glass-0.5mm"]
    text = scene(rho_p, FINITE_RE, tau95 / 100, steps, 10 ** 6, d=d, mu=MU, law="schiller-naumann", x0=-3e-5)
    return text.replace(f"run {steps}\n", f"run {steps}\n{extra_run}") + dump_state(2)


RESTARTED = f"""plugin load ${{plugin}}
read_restart mid.restart
neigh_modify every 1 delay 0 check no
comm_modify vel yes
fix nve all nve/sphere
fix weight all gravity 9.81 vector 1 0 0
fix {{id}} all fluid/drag viscosity {MU!r} density {RHO_F!r} law schiller-naumann buoyancy 9.81 0 0 {FINITE_RE}
run 300
""" + dump_state(2)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_ranks_and_restart_continue_the_finite_re_history(lmp, nprocs):
    """1 and 2 ranks agree to 1e-10 (the history migrates with the atom); run 600 == run 300,
    write_restart, read_restart (new process), run 300, to 1e-12. A fix of another ID starts
    without the history: it differs, so the test can fail."""
    whole = lmp(moving_scene(600), nprocs=nprocs)
    assert RHO_F * whole["v1"][0] * MORDANT["glass-0.5mm"][0] / MU > 30    # at finite Re
    if nprocs == 2:
        assert "2 by 1 by 1 MPI processor grid" in lmp.log
        serial = lmp(moving_scene(600))
        for key in serial:
            assert whole[key] == pytest.approx(serial[key], rel=1e-10, abs=1e-18), key
    lmp(moving_scene(300, "write_restart mid.restart\n"), nprocs=nprocs)
    restarted = lmp(RESTARTED.replace("{id}", "fluid"), nprocs=nprocs, name="in.restart")
    fresh = lmp(RESTARTED.replace("{id}", "other"), nprocs=nprocs, name="in.fresh")
    for key in ("x1", "v1", "x2", "v2"):
        assert restarted[key] == pytest.approx(whole[key], rel=1e-12, abs=1e-18), key
    assert fresh["v1"][0] != pytest.approx(whole["v1"][0], rel=1e-6)


@pytest.mark.parametrize("extra,fragment", [
    ("history yes kernel stokes", "kernel must be basset or mei-adrian, got 'stokes'"),
    ("kernel mei-adrian", "kernel mei-adrian needs history yes"),
    ("history yes kernel", "missing value(s) for keyword kernel"),
])
def test_bad_kernel(lmp, extra, fragment):
    lmp(scene(2500.0, extra, 1e-6, 1, 1), check=False)
    error = next(line for line in lmp.log.splitlines() if "ERROR" in line)
    assert fragment in error, error

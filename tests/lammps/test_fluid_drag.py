"""fix fluid/drag: terminal velocities, buoyancy, fluid velocity from variables, bad input."""
import math

import pytest

SPHERE = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
region box block -0.01 0.01 -0.01 0.01 -0.05 0.05
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 0.005 0.005 0.02
set group all diameter {d} density {rho_p}
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix nve all nve/sphere
fix weight all gravity 9.81 vector 0 0 -1
fix fluid all fluid/drag viscosity {mu} density {rho_f} buoyancy 0 0 -9.81 {extra}
timestep {dt}
thermo 1000
run {steps}
print "RESULT v $(vx[1]:%.15g) $(vy[1]:%.15g) $(vz[1]:%.15g) $(vz[2]:%.15g)"
print "RESULT z $(z[1]:%.15g)"
"""


def sphere(d=5e-4, rho_p=2500.0, rho_f=1000.0, mu=1e-3, extra="", dt=1e-4, steps=4000):
    return (SPHERE.replace("{d}", repr(d)).replace("{rho_p}", repr(rho_p)).replace("{rho_f}", repr(rho_f))
            .replace("{mu}", repr(mu)).replace("{extra}", extra).replace("{dt}", repr(dt))
            .replace("{steps}", str(steps)))


def stokes_terminal(d, rho_p, rho_f, mu, g=9.81):
    return (rho_p - rho_f) * g * d * d / (18 * mu)


def schiller_naumann_terminal(d, rho_p, rho_f, mu, g=9.81):
    """Solve 3 pi mu d w (1 + 0.15 Re^0.687) = (rho_p - rho_f) V g for w by bisection."""
    weight = (rho_p - rho_f) * math.pi / 6 * d ** 3 * g
    lo, hi = 0.0, stokes_terminal(d, rho_p, rho_f, mu, g)
    for _ in range(200):
        w = 0.5 * (lo + hi)
        re = rho_f * w * d / mu
        (lo, hi) = (w, hi) if 3 * math.pi * mu * d * w * (1 + 0.15 * re ** 0.687) < weight else (lo, w)
    return 0.5 * (lo + hi)


def test_stokes_terminal_velocity(lmp):
    d, mu = 1e-4, 5e-2                     # Re ~ 1e-4
    vz = lmp(sphere(d=d, mu=mu, extra="law stokes", dt=1e-6, steps=3000))["v"][2]
    assert -vz == pytest.approx(stokes_terminal(d, 2500, 1000, mu), rel=0.01)


def test_schiller_naumann_terminal_velocity(lmp):
    d = 5e-4                                # glass in water, Re ~ 20
    vz = lmp(sphere(d=d, extra="law schiller-naumann", dt=1e-4, steps=6000))["v"][2]
    expected = schiller_naumann_terminal(d, 2500, 1000, 1e-3)
    assert 1000 * expected * d / 1e-3 > 5.0          # really outside the Stokes regime
    assert -vz == pytest.approx(expected, rel=0.01)
    assert -vz < 0.8 * stokes_terminal(d, 2500, 1000, 1e-3)


def test_neutrally_buoyant_sphere_stays_put(lmp):
    result = lmp(sphere(rho_p=1000.0, steps=2000))
    assert abs(result["z"]) < 1e-12
    assert max(abs(v) for v in result["v"]) < 1e-12


def test_fluid_velocity_from_variables(lmp):
    """Equal-style u_x(t) and atom-style u_y(z): a neutrally buoyant sphere drifts with the fluid."""
    script = sphere(rho_p=1000.0, dt=1e-4, steps=3000,
                    extra="velocity v_ux v_uy 0.0").replace(
        "fix nve all nve/sphere", "variable ux equal 0.01*step/3000\nvariable uy atom 0.5*z\nfix nve all nve/sphere")
    v = lmp(script)["v"]
    # sphere 1 sits at z = 0 (u_y = 0); u_x ramps to 0.01 and lags by tau = m / beta
    tau = 1000 * math.pi / 6 * 5e-4 ** 3 / (3 * math.pi * 1e-3 * 5e-4 * 1.0)
    assert v[0] == pytest.approx(0.01 - 0.01 / 0.3 * tau, rel=0.05)
    assert abs(v[1]) < 1e-9


@pytest.mark.parametrize("extra,fragment", [
    ("density -1", "density = -1 is out of range (allowed: rho_f = 0 or 1e-100 <= rho_f <= 1e100)"),
    ("density 1e300", "density = 1e300 is out of range"),
    ("viscosity -1e-3", "viscosity = -1e-3 is out of range (allowed: 1e-100 <= mu_f <= 1e100)"),
    # beyond these the history kernel gave NaN forces (1e-300 with mei-adrian, 1e308 with added mass)
    ("viscosity 1e-300", "viscosity = 1e-300 is out of range"),
    ("viscosity 1e308", "viscosity = 1e308 is out of range"),
    ("velocity v_nothing 0 0", "variable nothing for the fluid velocity does not exist"),
    ("hindrance richardson-zaki 4.65", "need the bins keyword"),
    ("hindrance richardson-zaki 0.5 bins 1 1 4", "richardson-zaki n = 0.5 is out of range"),
    ("drag 3", "unknown keyword 'drag'"),
])
def test_bad_input(lmp, extra, fragment):
    lmp(sphere(extra=extra, steps=1), check=False)
    error = next(line for line in lmp.log.splitlines() if "ERROR" in line)
    assert fragment in error, error


TWO_D = """plugin load ${plugin}
units si
dimension 2
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
region box block 0 0.01 0 0.01 -0.0005 0.0005
create_box 1 box
create_atoms 1 single 0.005 0.005 0
set group all diameter 1e-4 density 2500
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix nve all nve/sphere
fix e2d all enforce2d
fix weight all gravity 9.81 vector 0 -1 0
fix fluid all fluid/drag viscosity 0.05 density 1000 law stokes buoyancy 0 -9.81 0 {extra}
timestep 1e-6
run 3000
print "RESULT vy $(vy[1]:%.15g)"
"""


@pytest.mark.parametrize("extra,keyword", [
    ("hindrance richardson-zaki 4.65 bins 4 4 1", "hindrance richardson-zaki"),
    ("hindrance di-felice bins 4 4 1", "hindrance di-felice"),
    ("superficial yes bins 4 4 1", "superficial yes"),
])
def test_solid_fraction_needs_a_3d_simulation(lmp, extra, keyword):
    """phi is a volume fraction: in 2-d (before: sphere volume over bin area, a length, so the
    hindrance did nothing) what needs it stops with an error naming the keyword; the drag
    alone still runs in 2-d, a lone sphere settling at Stokes' u_t (Re ~ 1e-4)."""
    lmp(TWO_D.replace("{extra}", extra), check=False)
    error = next(line for line in lmp.log.splitlines() if "ERROR" in line)
    assert f"{keyword} needs the solid volume fraction phi, which needs a 3-d simulation (dimension = 2" in error, error
    vy = lmp(TWO_D.replace("{extra}", "bins 4 4 1"))["vy"]
    assert -vy == pytest.approx(stokes_terminal(1e-4, 2500, 1000, 0.05), rel=0.01)


SUSPENSION = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
neigh_modify every 1 delay 0 check no
region box block 0 0.006 0 0.006 0 0.012
create_box 1 box
lattice sc 0.002 origin 0.25 0.25 0.25
create_atoms 1 box
displace_atoms all random 3e-4 3e-4 3e-4 4711 units box
set group all diameter 1e-3 density 2500
pair_style lubricated/springdashpot
pair_coeff * * 0.9
"""
SUSPENSION_FIXES = """fix nve all nve/sphere
fix weight all gravity 9.81 vector 0 0 -1
fix fluid all fluid/drag viscosity 0.05 density 1200 law stokes hindrance richardson-zaki 4.65 &
    velocity 0.02 0 0 buoyancy 0 0 -9.81 bins 3 3 6 every 7
timestep 2e-4
"""
N_SUSPENSION = 54    # 3 x 3 x 6


@pytest.mark.parametrize("runs", [("run 150", "run 150"), ("run 147", "run 0", "run 153")], ids=["150", "147"])
def test_solid_fraction_every_n_continues_across_runs_and_restarts(lmp, runs):
    """every 7: phi at the multiples of 7 (and the first set-up), the last one kept between
    runs and carried by the restart file. A split at step 150 (between multiples; before, each
    run recomputed phi at its set-up and counted 7 from there) or at 147 (a multiple, then
    recomputed from the same positions), and a new process reading the restart file written
    there, all continue as the uninterrupted run: 1e-12 relative (the set-up of a continued
    run restores the last step's velocities to round-off, fix_step_velocity.h)."""
    from scene_chain import dump_state
    whole = lmp(SUSPENSION + SUSPENSION_FIXES + "run 300\n" + dump_state(N_SUSPENSION))
    split = lmp(SUSPENSION + SUSPENSION_FIXES + "\n".join(runs) + "\n" + dump_state(N_SUSPENSION))
    first = runs[0]
    lmp(SUSPENSION + SUSPENSION_FIXES + f"{first}\nwrite_restart mid.restart\n", name="in.first")
    rest = 300 - int(first.split()[1])
    restarted = lmp("plugin load ${plugin}\nread_restart mid.restart\ncomm_modify vel yes\n"
                    "neigh_modify every 1 delay 0 check no\n" + SUSPENSION_FIXES + f"run {rest}\n" +
                    dump_state(N_SUSPENSION), name="in.restart")
    assert "Resetting global fix info from restart file" in lmp.log
    for key in whole:
        assert split[key] == pytest.approx(whole[key], rel=1e-12, abs=1e-18), key
        assert restarted[key] == pytest.approx(whole[key], rel=1e-12, abs=1e-18), key

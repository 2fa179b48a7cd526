"""Input-script builders for the impact scenes the tests and the demo share.

Units: SI. A steel-like sphere (rho_p = 8000 kg/m^3) of radius R = 1 mm hits a wall or
another sphere head-on at U = 0.1 m/s; no gravity, so the rebound speed measured once the
sphere has left the film is the restitution velocity. The time step is given in units of
R/U (the documented wet setting is dt = 0.005 R/U with e_d = 0.9, N_c = 8 and eps_al = 0.75 dx/R at
R/dx = 8, i.e. eps_al = 0.09375).
"""
import math

RHO = 8000.0
R = 1.0e-3
U = 0.1
EPS_AL = 0.75 / 8.0
WET_DT = 0.005    # in R/U


def viscosity_for_stokes(st, radius=R, speed=U, rho=RHO):
    """St = (2/9) rho_p R u / mu_f  (doc/model.rst, "Wet restitution and the Stokes number")."""
    return 2.0 / 9.0 * rho * radius * speed / st


def legendre(st):
    return math.exp(-35.0 / st)


HEADER = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
boundary p p f
comm_modify vel yes
newton ${newton}
"""


def duration(ncontact, tcontact_ru):
    """Contact-duration keyword: N_c steps, or a fixed t_c given in R/U."""
    return f"tcontact {tcontact_ru * R / U}" if tcontact_ru else f"ncontact {ncontact}"


def wall_bounce_steps(dt_ru, gap0, ncontact, tcontact_ru=None):
    """Steps for the wall bounce: in, contact and out of the film, with margin."""
    dt = dt_ru * R / U
    travel = (2.0 * gap0 + 2.0 * EPS_AL + 0.2) * R / U
    return int(math.ceil(travel / dt)) + 8 * ncontact + (
        int(4 * tcontact_ru * R / U / dt) if tcontact_ru else 0)


def pair_bounce_layout(mass_ratio, dt_ru, ncontact, gap0, radius_ratio, x_offset, tcontact_ru=None):
    """The pair bounce's geometry (shared with the LIGGGHTS scene): radius and density of
    sphere 2, start positions and velocities along x (centre-of-mass frame), box half-width,
    steps."""
    dt = dt_ru * R / U
    r2 = radius_ratio * R
    rho2 = RHO * mass_ratio / radius_ratio**3
    v1, v2 = U * mass_ratio / (1 + mass_ratio), -U / (1 + mass_ratio)
    x1 = x_offset - R - 0.5 * gap0 * R
    x2 = x_offset + r2 + 0.5 * gap0 * R
    travel = (2.0 * gap0 + 4.0 * EPS_AL + 0.2) * R / U
    half = max(0.01, 3.0 * (R + r2))
    steps = int(math.ceil(travel / dt)) + 8 * ncontact + (
        int(4 * tcontact_ru * R / U / dt) if tcontact_ru else 0)
    return r2, rho2, x1, x2, v1, v2, half, steps


def wall_bounce(e_dry, dt_ru=WET_DT, mu=0.0, ncontact=8, extra="", gap0=0.2137, steps=None,
                tcontact_ru=None, integrator="nve/sphere"):
    """A sphere starting gap0*R above a zplane wall, moving down at U.

    Prints RESULT e (rebound/impact speed), RESULT contact_steps (steps with overlap).
    """
    dt = dt_ru * R / U
    steps = steps or wall_bounce_steps(dt_ru, gap0, ncontact, tcontact_ru)
    wet = f"viscosity {mu} activation {EPS_AL}" if mu > 0 else ""
    return HEADER.replace("${newton}", "on") + f"""
region box block -0.01 0.01 -0.01 0.01 0 0.02
create_box 1 box
create_atoms 1 single 0 0 {R * (1 + gap0)}
set atom 1 diameter {2 * R} density {RHO}
velocity all set 0 0 {-U}
pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix wall all wall/lubrication {e_dry} {duration(ncontact, tcontact_ru)} {wet} {extra} zplane 0.0 NULL
fix nve all {integrator}
timestep {dt}
variable overlap equal "z[1] < {R}"
variable contact_steps equal 0
fix count all ave/time 1 1 1 v_overlap mode scalar ave running
thermo 0
run {steps}
variable n equal f_count*{steps + 1}
print "RESULT e $(vz[1]/{U}:%.15g)"
print "RESULT contact_steps $(v_n:%.6f)"
"""


def pair_bounce(e_dry, mass_ratio=1.0, dt_ru=WET_DT, mu=0.0, ncontact=8, gap0=0.2137, newton="on",
                radius_ratio=1.0, x_offset=0.0, skin=0.5 * R, tcontact_ru=None, extra="",
                integrator="nve/sphere"):
    """Two spheres approaching head-on along x at relative speed U (centre-of-mass frame).

    Sphere 2 has radius radius_ratio*R and density such that m2/m1 = mass_ratio.
    Prints RESULT e (relative separation / approach speed) and RESULT contact_steps.
    """
    dt = dt_ru * R / U
    r2, rho2, x1, x2, v1, v2, half, steps = pair_bounce_layout(
        mass_ratio, dt_ru, ncontact, gap0, radius_ratio, x_offset, tcontact_ru)
    wet = f"viscosity {mu} activation {EPS_AL}" if mu > 0 else ""
    return HEADER.replace("${newton}", newton) + f"""
boundary p p p
region box block -{half} {half} -{half} {half} -{half} {half}
create_box 1 box
create_atoms 1 single {x1} 0 0
create_atoms 1 single {x2} 0 0
set atom 1 diameter {2 * R} density {RHO}
set atom 2 diameter {2 * r2} density {rho2}
velocity all set 0 0 0
set atom 1 vx {v1}
set atom 2 vx {v2}
pair_style lubricated/springdashpot
pair_coeff * * {e_dry} {duration(ncontact, tcontact_ru)} {wet} {extra}
fix nve all {integrator}
timestep {dt}
variable overlap equal "(x[2]-x[1]) < {R + r2}"
fix count all ave/time 1 1 1 v_overlap mode scalar ave running
thermo 0
neighbor {skin} bin
run {steps}
variable n equal f_count*{steps + 1}
print "RESULT e $((vx[2]-vx[1])/{U}:%.15g)"
print "RESULT contact_steps $(v_n:%.6f)"
"""

"""Added mass at contact (doc/fix_fluid_drag.rst, "Added mass at contact"): a sphere of the group
of fix fluid/drag with added_mass carries m_a = C_m rho_f V into its contacts, which move
m + m_a (a wall) or ((m_i + m_a,i)^-1 + (m_j + m_a,j)^-1)^-1 (a pair), the masses fix fluid/drag
divides the total force by.

The fluid's drag is made negligible (Stokes law, mu_f = 1e-100) and there is no gravity (but in
the resting test), so the only fluid force is the added mass. Then the motion is that of spheres of mass m + m_a:

- dry: the rebound is e_d and the contact lasts N_c steps, at every density ratio, as without
  added mass (the event steps are exact for an isolated contact: e_d to rounding);
- wet: the same isolated collision of spheres of density rho_p + C_m rho_f without the fix (the
  same radius, so the same film and m_e = m + m_a): the film's cap, entry loss and budget all
  take m_e, so the two runs give the same e to rounding, and St is the one of m + m_a.

Also: the wet law with St of m + m_a, fix fluid/drag's near-wall added mass along a wall's
normal, the tangential mass of a sticking impact, and a resting sphere's load (with gravity).
Tolerances: 1e-9 on e (the exact event steps leave rounding only), contact steps N_c exactly;
the tests that differ say why.
"""
import math

import pytest

R = 1.0e-3
U = 0.1
DT = 0.005 * R / U
C_M = 0.5
EPS_AL = 0.75 / 8.0
E_DRY = 0.5
RHO_P = 1000.0
RATIOS = [0.001, 1.0, 1000.0]    # rho_p / rho_f

HEADER = """plugin load ${plugin}
units si
atom_style sphere
atom_modify map array
comm_modify vel yes
newton on
"""


def fluid(rho_f, near_wall=""):
    """Added mass alone: Stokes drag of a vanishing viscosity, no gravity."""
    if rho_f is None:
        return ""
    return f"fix fluid all fluid/drag viscosity 1e-100 density {rho_f} law stokes added_mass {C_M} {near_wall}\n"


def film(mu):
    return f"viscosity {mu} activation {EPS_AL}" if mu > 0 else ""


def counted(run_steps, overlap):
    return f"""variable overlap equal "{overlap}"
fix count all ave/time 1 1 1 v_overlap mode scalar ave running
thermo 0
run {run_steps}
variable n equal f_count*{run_steps + 1}
"""


def wall_fix(e_dry, ncontact, mu, region):
    """The floor z = 0: fix wall/lubrication, or the face of a block region."""
    if region:
        return (f"region floor block INF INF INF INF 0.0 INF\n"
                f"fix wall all wall/lubrication/region {e_dry} floor ncontact {ncontact} {film(mu)}")
    return f"fix wall all wall/lubrication {e_dry} ncontact {ncontact} {film(mu)} zplane 0.0 NULL"


def wall_scene(rho_p, rho_f, mu=0.0, ncontact=8, nprocs=1, gap0=0.2137, e_dry=E_DRY, integrator="nve/sphere",
               near_wall="", region=False):
    """Two spheres side by side (one per rank on 2 ranks) fall onto a zplane wall at U."""
    steps = int(math.ceil((2 * gap0 + 2 * EPS_AL + 0.2) * R / U / DT)) + 8 * ncontact
    return HEADER + f"""boundary p p f
processors {nprocs} 1 1
region box block -0.01 0.01 -0.01 0.01 0 0.02
create_box 1 box
create_atoms 1 single -0.005 0 {R * (1 + gap0)}
create_atoms 1 single 0.005 0 {R * (1 + gap0)}
set group all diameter {2 * R} density {rho_p}
velocity all set 0 0 {-U}
pair_style lubricated/springdashpot
pair_coeff * * 0.9
{wall_fix(e_dry, ncontact, mu, region)}
{fluid(rho_f, near_wall)}fix nve all {integrator}
timestep {DT}
{counted(steps, f"z[1] < {R}")}
print "RESULT e1 $(vz[1]/{U}:%.15g)"
print "RESULT e2 $(vz[2]/{U}:%.15g)"
print "RESULT z $(z[1]:%.15g)"
print "RESULT contact_steps $(v_n:%.6f)"
"""


def pair_scene(rho_1, rho_2, rho_f, mu=0.0, ncontact=8, nprocs=1, radius_ratio=1.0, gap0=0.2137):
    """Two spheres approach head-on along x at relative speed U in their centre-of-mass frame
    (with the masses m + m_a), touching at x = 0: one per rank on 2 ranks."""
    r2 = radius_ratio * R
    carried = 0.0 if rho_f is None else C_M * rho_f
    m1 = (rho_1 + carried) * R**3
    m2 = (rho_2 + carried) * r2**3
    v1, v2 = U * m2 / (m1 + m2), -U * m1 / (m1 + m2)
    half = 3.0 * (R + r2)
    steps = int(math.ceil((2 * gap0 + 4 * EPS_AL + 0.2) * R / U / DT)) + 8 * ncontact
    return HEADER + f"""boundary p p p
processors {nprocs} 1 1
region box block -{half} {half} -{half} {half} -{half} {half}
create_box 1 box
create_atoms 1 single {-R * (1 + 0.5 * gap0)} 0 0
create_atoms 1 single {r2 + 0.5 * gap0 * R} 0 0
set atom 1 diameter {2 * R} density {rho_1}
set atom 2 diameter {2 * r2} density {rho_2}
velocity all set 0 0 0
set atom 1 vx {v1}
set atom 2 vx {v2}
pair_style lubricated/springdashpot
pair_coeff * * {E_DRY} ncontact {ncontact} {film(mu)}
neighbor {0.5 * R} bin
{fluid(rho_f)}fix nve all nve/sphere
timestep {DT}
{counted(steps, f"(x[2]-x[1]) < {R + r2}")}
print "RESULT e $((vx[2]-vx[1])/{U}:%.15g)"
print "RESULT contact_steps $(v_n:%.6f)"
"""


@pytest.mark.parametrize("ratio", RATIOS)
@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("region", [False, True])
def test_wall_dry_rebound_is_e_dry(lmp, ratio, nprocs, region):
    result = lmp(wall_scene(RHO_P, RHO_P / ratio, nprocs=nprocs, region=region), nprocs=nprocs)
    assert result["e1"] == pytest.approx(E_DRY, abs=1e-9)
    assert result["e2"] == pytest.approx(E_DRY, abs=1e-9)
    assert result["contact_steps"] == 8


@pytest.mark.parametrize("ratio", RATIOS)
@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("unequal", [False, True])
def test_pair_dry_rebound_is_e_dry(lmp, ratio, nprocs, unequal):
    """Each sphere with its own added mass; unequal: density 3x and radius 1.5x for sphere 2."""
    rho_2, radius_ratio = (3.0 * RHO_P, 1.5) if unequal else (RHO_P, 1.0)
    result = lmp(pair_scene(RHO_P, rho_2, RHO_P / ratio, nprocs=nprocs, radius_ratio=radius_ratio), nprocs=nprocs)
    assert result["e"] == pytest.approx(E_DRY, abs=1e-9)
    assert result["contact_steps"] == 8


@pytest.mark.parametrize("ratio", [0.001, 1000.0])
def test_papers_integrator_also_gives_e_dry(lmp, ratio):
    result = lmp(wall_scene(RHO_P, RHO_P / ratio, integrator="nve/sphere/midpoint"))
    assert result["e1"] == pytest.approx(E_DRY, abs=1e-9)
    assert result["contact_steps"] == 8


def test_contact_lasts_ncontact_steps(lmp):
    """t_c as set: 16 steps for N_c 16, for a bubble (m_a = 500 m)."""
    result = lmp(wall_scene(RHO_P, 1000.0 * RHO_P, ncontact=16))
    assert result["e1"] == pytest.approx(E_DRY, abs=1e-9)
    assert result["contact_steps"] == 16


@pytest.mark.parametrize("ratio", RATIOS)
@pytest.mark.parametrize("region", [False, True])
def test_near_wall_added_mass_in_contact(lmp, ratio, region):
    """fix fluid/drag's wall keyword: the added mass along the wall's normal grows to 1.375 m_a in
    contact, and the contact takes it. Away from the wall the speed follows the position-dependent
    mass, (m + M(h)) v^2 conserved (no viscosity), so the rebound is compared at the start height:
    e = v_end sqrt((m + M(h_end)) / (m + M(h_0))) / U. Within 2e-3 of e_d: the near-wall forces are
    explicit, first order in the step (with the unbounded m_a in the contact: 0.56 for the bubble)."""
    gap0 = 0.2137
    result = lmp(wall_scene(RHO_P, RHO_P / ratio, gap0=gap0, near_wall="wall zplane 0.0 NULL", region=region))

    def mass(h):    # m + M(h) in units of rho_p V
        return 1.0 + C_M / ratio * (1.0 + 3.0 / 8.0 * (R / h)**3)

    e = result["e1"] * math.sqrt(mass(result["z"]) / mass(R * (1.0 + gap0)))
    assert e == pytest.approx(E_DRY, abs=2e-3)
    assert result["contact_steps"] == 8


# Wet: St of the mass m + m_a about 60 for the film of mu below (e / e_d about exp(-35 / St)).
MU = 2.0 / 9.0 * RHO_P * R * U / 30.0


@pytest.mark.parametrize("ratio", RATIOS)
@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("region", [False, True])
def test_wall_wet_is_the_collision_of_the_carried_mass(lmp, ratio, nprocs, region):
    rho_f = RHO_P / ratio
    carried = lmp(wall_scene(RHO_P, rho_f, mu=MU, nprocs=nprocs, region=region), nprocs=nprocs)
    heavy = lmp(wall_scene(RHO_P + C_M * rho_f, None, mu=MU, nprocs=nprocs, region=region), nprocs=nprocs)
    assert 0.0 < heavy["e1"] < E_DRY
    assert carried["e1"] == pytest.approx(heavy["e1"], abs=1e-9)
    assert carried["e2"] == pytest.approx(heavy["e2"], abs=1e-9)
    assert carried["contact_steps"] == heavy["contact_steps"]


@pytest.mark.parametrize("ratio", RATIOS)
@pytest.mark.parametrize("nprocs", [1, 2])
def test_pair_wet_is_the_collision_of_the_carried_masses(lmp, ratio, nprocs):
    rho_f = RHO_P / ratio
    carried = lmp(pair_scene(RHO_P, 3.0 * RHO_P, rho_f, mu=MU, nprocs=nprocs, radius_ratio=1.5), nprocs=nprocs)
    heavy = lmp(pair_scene(RHO_P + C_M * rho_f, 3.0 * RHO_P + C_M * rho_f, None, mu=MU, nprocs=nprocs,
                           radius_ratio=1.5), nprocs=nprocs)
    assert 0.0 < heavy["e"] < E_DRY
    assert carried["e"] == pytest.approx(heavy["e"], abs=1e-9)
    assert carried["contact_steps"] == heavy["contact_steps"]


@pytest.mark.parametrize("ratio", RATIOS)
def test_wall_wet_follows_legendre_with_the_carried_mass(lmp, ratio):
    """The wet law with St of m + m_a, (2/9) (rho_p + C_m rho_f) R U / mu = 100, at the documented
    wet setting (e_d 0.9, N_c 8): e / e_d = exp(-35 / St) within 0.05, as test_wet_restitution
    without added mass (with St of m alone a bubble would be at St 0.2 and not rebound)."""
    stokes, e_dry = 100.0, 0.9
    rho_f = RHO_P / ratio
    mu = 2.0 / 9.0 * (RHO_P + C_M * rho_f) * R * U / stokes
    result = lmp(wall_scene(RHO_P, rho_f, mu=mu, e_dry=e_dry))
    assert result["e1"] / e_dry == pytest.approx(math.exp(-35.0 / stokes), abs=0.05)


def sticking_scene(rho_f):
    """The wall bounce with a small slip (0.05 U along x, sticking: friction 0.5, e_t 0.5); prints
    the slip at the contact point after the rebound over the one before, v_x - R omega_y."""
    scene = wall_scene(RHO_P, rho_f).replace(f"ncontact 8  zplane", "ncontact 8 friction 0.5 tangential 0.5 zplane")
    scene = scene.replace(f"velocity all set 0 0 {-U}", f"velocity all set {0.05 * U} 0 {-U}")
    return scene + f"""compute spin all property/atom omegay
variable slip atom (vx-{R}*c_spin)/{0.05 * U}
compute slips all reduce sum v_slip
thermo_style custom step c_slips
run 0
print "RESULT slip $(c_slips/2:%.15g)"
"""


@pytest.mark.parametrize("ratio", RATIOS)
def test_sticking_slip_as_without_added_mass(lmp, ratio):
    """The tangential contact takes 1/m_t = 1/(m + m_a) + R^2/I (a turning sphere carries no added
    mass): the slip then evolves as without added mass, and the rebound's slip is the same."""
    without = lmp(sticking_scene(None))
    carried = lmp(sticking_scene(RHO_P / ratio))
    assert without["slip"] < 0.0
    assert carried["slip"] == pytest.approx(without["slip"], abs=1e-9)
    assert carried["e1"] == pytest.approx(E_DRY, abs=1e-9)


def resting_scene(rho_f, g, region=False):
    """A sphere put down on the floor under gravity g (fix gravity), 2000 steps (0.1 s): its
    resting height."""
    scene = wall_scene(RHO_P, rho_f, gap0=0.001, region=region)
    scene = scene.replace(f"velocity all set 0 0 {-U}", "velocity all set 0 0 0")
    scene = scene.replace("fix wall all", f"fix gravity all gravity {g} vector 0 0 -1\nfix wall all", 1)
    scene = scene.replace(f"\nrun ", "\nrun 2000 # ", 1)
    return scene + """print "RESULT z_rest $(z[1]:%.15g)"
print "RESULT v_rest $(vz[1]:%.15g)"
"""


@pytest.mark.parametrize("ratio", [1.0, 0.001])
@pytest.mark.parametrize("region", [False, True])
def test_resting_load_is_the_carried_weight(lmp, ratio, region):
    """The wall's steady load (gravity pressing the sphere on, the loaded event steps) is the
    acceleration fix fluid/drag leaves, g m / (m + m_a): the sphere rests where a sphere without
    added mass rests under that gravity (with g itself a bubble hovered 2e-5 R above the floor)."""
    g = 9.81
    carried = lmp(resting_scene(RHO_P / ratio, g, region))
    plain = lmp(resting_scene(None, g / (1.0 + C_M / ratio), region))
    assert carried["z_rest"] < R
    assert carried["z_rest"] == pytest.approx(plain["z_rest"], abs=1e-9 * R)
    assert abs(carried["v_rest"]) < 1e-9 * U

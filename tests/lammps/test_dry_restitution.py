"""Dry impacts (doc/model.rst, "Solid contact: the spring-dashpot"): the rebound speed is e_d and
the contact lasts N_c steps.

Tolerance: 1 % of e_d, the issue's requirement. The step integration is exact for an
isolated pair, so a failure here means a broken contact law, not noise.
"""
import pytest

import scenes

E_DRY = [0.97, 0.5, 0.1]


def check(result, e_dry, ncontact=8):
    assert result["e"] == pytest.approx(e_dry, rel=0.01)
    assert abs(result["contact_steps"] - ncontact) <= 1.0


@pytest.mark.parametrize("e_dry", E_DRY)
def test_particle_wall(lmp, e_dry):
    check(lmp(scenes.wall_bounce(e_dry, dt_ru=0.005)), e_dry)


@pytest.mark.parametrize("e_dry", E_DRY)
@pytest.mark.parametrize("mass_ratio", [1.0, 3.0])
def test_particle_particle(lmp, e_dry, mass_ratio):
    check(lmp(scenes.pair_bounce(e_dry, mass_ratio=mass_ratio, dt_ru=0.005)), e_dry)


@pytest.mark.parametrize("newton", ["on", "off"])
def test_unequal_radii(lmp, newton):
    """Polydisperse pair, radius ratio 2 (mass ratio 8)."""
    check(lmp(scenes.pair_bounce(0.5, radius_ratio=2.0, mass_ratio=8.0, newton=newton)), 0.5)


def test_contact_duration_follows_ncontact(lmp):
    check(lmp(scenes.wall_bounce(0.5, ncontact=16)), 0.5, ncontact=16)


def test_tcontact_sets_duration_in_time_units(lmp):
    """tcontact = 12 dt must behave as ncontact 12."""
    dt = 0.005 * scenes.R / scenes.U
    result = lmp(scenes.wall_bounce(0.5, dt_ru=0.005, ncontact=12).replace(
        "ncontact 12", f"tcontact {12 * dt}"))
    check(result, 0.5, ncontact=12)


@pytest.mark.parametrize("e_dry", E_DRY)
@pytest.mark.parametrize("scene", ["wall", "pair"])
def test_papers_integrator_also_gives_e_dry(lmp, e_dry, scene):
    """fix nve/sphere/midpoint (the paper's scheme) with the step-exact contact, N_c = 8."""
    build = scenes.wall_bounce if scene == "wall" else scenes.pair_bounce
    check(lmp(build(e_dry, dt_ru=0.005, integrator="nve/sphere/midpoint")), e_dry)


def test_sampled_integration_is_the_papers_force(lmp):
    """The printed force sampled once per step misses e_d at e_d = 0.1 (why 'exact' is the default)."""
    result = lmp(scenes.wall_bounce(0.1, dt_ru=0.005, extra="integration sampled"))
    assert abs(result["e"] - 0.1) > 0.01 * 0.1


def test_coefficients_per_type_pair(lmp):
    """Types 1 and 2 with their own e_d; a 1-2 collision uses the 1 2 coefficients, and a wet
    1 1 pair next to dry pairs leaves the dry ones dry."""
    script = scenes.pair_bounce(0.9, dt_ru=0.005).replace("create_box 1 box", "create_box 2 box").replace(
        "set atom 2 diameter", "set atom 2 type 2\nset atom 2 diameter").replace(
        "pair_coeff * * 0.9 ncontact 8", "pair_coeff 1 1 0.9 viscosity 1e-3 activation 0.09375\n"
        "pair_coeff 2 2 0.5\npair_coeff 1 2 0.3 ncontact 8")
    result = lmp(script)
    assert result["e"] == pytest.approx(0.3, rel=1e-6)
    assert "types 1 2: e_d = 0.3" in lmp.log and "film" in lmp.log


def test_papers_integrator_many_spheres_on_a_wall(lmp):
    """Nine spheres side by side (no two in reach), each falling on the wall at its own speed
    from its own height, under fix nve/sphere/midpoint: each rebounds with e_d. The plane wall's
    pre-test reads each atom's step velocity from the integrator's rows (not from v): read from
    the wrong row, it misses the step in which a contact starts and the rebound is wrong."""
    e_dry, dt = 0.5, 0.005 * scenes.R / scenes.U
    R, U = scenes.R, scenes.U
    atoms = "".join(f"create_atoms 1 single {4 * R * (k - 4)} 0 {R * (1.2137 + 0.37 * k)}\n" for k in range(9))
    speeds = "".join(f"velocity s{k} set 0 0 {-U * (0.5 + 0.2 * k)}\n" for k in range(9))
    groups = "".join(f"group s{k} id {k + 1}\n" for k in range(9))
    steps = int(8.0 * R / (0.5 * U) / dt) + 80
    result = lmp(scenes.HEADER.replace("${newton}", "on") + f"""
region box block -0.02 0.02 -0.01 0.01 0 0.02
create_box 1 box
{atoms}set group all diameter {2 * R} density {scenes.RHO}
{groups}{speeds}pair_style lubricated/springdashpot
pair_coeff * * 0.9
fix wall all wall/lubrication {e_dry} ncontact 8 zplane 0.0 NULL
fix nve all nve/sphere/midpoint
timestep {dt}
thermo 0
run {steps}
""" + "".join(f'print "RESULT e{k} $(vz[{k + 1}]/{U * (0.5 + 0.2 * k)}:%.15g)"\n' for k in range(9)))
    for k in range(9):
        assert result[f"e{k}"] == pytest.approx(e_dry, rel=0.01), k

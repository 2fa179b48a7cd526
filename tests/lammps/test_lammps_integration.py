"""How the styles sit in LAMMPS: plugin autoload, energy and single() for compute pair/local,
and neighbor lists that keep every pair inside the film whatever the skin."""
import math

import pytest

import scenes
import lammps_run


def test_autoload_through_lammps_plugin_path(lmp):
    script = scenes.wall_bounce(0.5, dt_ru=0.005).replace("plugin load ${plugin}\n", "")
    result = lmp(script, env={"LAMMPS_PLUGIN_PATH": str(lammps_run.PLUGIN.parent)})
    assert "Loaded 1 plugins from" in lmp.log
    assert result["e"] == pytest.approx(0.5, rel=1e-6)


PAIR_AT_REST = scenes.HEADER.replace("${newton}", "on") + """
boundary p p p
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single {x2} 0 0
set atom 1 diameter 0.002 density 8000
set atom 2 diameter {d2} density 8000
pair_style lubricated/springdashpot
pair_coeff * * 0.5 ncontact 8 viscosity 1e-3 activation 0.09375
timestep 1e-5
compute pl all pair/local dist p1 p2 p3 cutoff type
compute sum all reduce sum c_pl[2] c_pl[3] c_pl[4] inputs local
fix nve all nve/sphere
run 0
print "RESULT pe $(pe:%.15g)"
print "RESULT press $(press:%.15g)"
print "RESULT fx1 $(fx[1]:%.15g)"
print "RESULT single $(c_sum[1]:%.15g) $(c_sum[2]:%.15g) $(c_sum[3]:%.15g)"
"""


def pair_at_rest(x2, d2):
    return PAIR_AT_REST.replace("{x2}", repr(x2)).replace("{d2}", repr(d2))


def test_energy_and_single_in_overlap(lmp):
    """Two spheres at rest overlapping by d: pe = k d^2 / 2 with the paper's k, single()
    gives the force applied and no lubrication (at rest u_n = 0), and eps = -d / R."""
    d = 1e-5
    result = lmp(pair_at_rest(0.002 - d, 0.002))
    mass = 8000 * 4.0 / 3.0 * math.pi * 1e-9
    m_e = mass / 2.0
    t_c = 8e-5
    k = m_e * (math.pi ** 2 + math.log(0.5) ** 2) / t_c ** 2
    assert result["pe"] == pytest.approx(0.5 * k * d * d, rel=1e-9)
    contact, lubrication, eps = result["single"]
    # In sustained contact the step-exact force is k' d - c' u_n (contact_step.h).
    dt = 1e-5
    decay, omega = -math.log(0.5) / t_c, math.pi / t_c
    big_e, big_c = math.exp(-decay * dt), math.cos(omega * dt)
    k_step = m_e * (1 + big_e ** 2 - 2 * big_e * big_c) / dt ** 2
    assert contact == pytest.approx(k_step * d, rel=1e-9)
    assert k_step == pytest.approx(k, rel=0.1)
    # The force applied at the run start (full-step velocities, half a kick) lands the first
    # half step on the analytic oscillation from rest at -d.
    g1 = math.exp(-decay * dt) * (-d * math.cos(omega * dt) - decay * d / omega * math.sin(omega * dt))
    assert -result["fx1"] == pytest.approx(2 * m_e * (g1 + d) / dt ** 2, rel=1e-9)
    assert lubrication == 0.0
    assert eps == pytest.approx(-d / 1e-3, rel=1e-9)
    # Virial of the pair at rest: P = r F / (3 V), box of 0.02^3.
    assert result["press"] == pytest.approx((0.002 - d) * -result["fx1"] / (3 * 0.02 ** 3), rel=1e-9)


@pytest.mark.parametrize("integration", ["sampled", "exact"])
def test_single_reports_the_film_of_unequal_spheres(lmp, integration):
    """Apart by a gap inside the film, approaching: p2 is the film force with R = 2 R1 R2/(R1+R2).
    Sampled: the printed law c_l u_n. Exact: the film's path integral over the last step,
    which differs from it at O(u dt / gap) = 0.5 % here."""
    script = pair_at_rest(0.001 + 0.0005 + 2e-5, 0.001).replace(
        "fix nve all nve/sphere", "velocity all set 0 0 0\nset atom 2 vx -0.01\nfix nve all nve/sphere").replace(
        "activation 0.09375", f"activation 0.09375 integration {integration}")
    result = lmp(script)
    contact, lubrication, eps = result["single"]
    radius = 2 * 1e-3 * 0.5e-3 / 1.5e-3
    lam = lambda e: 0.5 / e - 0.45 * math.log(e) - 3 / 56 * e * math.log(e) + 1.346
    expected = 6 * math.pi * 1e-3 * radius * 0.01 * (lam(2e-5 / radius) - lam(0.09375))
    assert eps == pytest.approx(2e-5 / radius, rel=1e-9)
    assert contact == 0.0
    if integration == "sampled":
        assert lubrication == pytest.approx(expected, rel=1e-9)
    else:
        assert lubrication == pytest.approx(expected, rel=0.01)
        assert lubrication != pytest.approx(expected, rel=1e-6)


COLLISION = scenes.HEADER.replace("${newton}", "{newton}") + """
boundary p p p
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 1 box
create_atoms 1 single {x1} 0 0
create_atoms 1 single {x2} 0.0003 0
set atom * diameter 0.002 density 8000
velocity all set 0 0 0
set atom 1 vx 0.05
set atom 2 vx -0.05
pair_style lubricated/springdashpot
pair_coeff * * 0.5 ncontact 16 {film}
fix nve all nve/sphere
timestep 5e-6
neighbor 0.0005 bin
compute pl all pair/local dist p1 p2
compute sum all reduce sum c_pl[2] c_pl[3] inputs local
variable applied equal sqrt(fx[1]^2+fy[1]^2+fz[1]^2)
variable reported equal abs(c_sum[1]+c_sum[2])
thermo_style custom step v_applied v_reported
thermo_modify format float %.15g
thermo 10
run 425
thermo 1
run 40
"""


def collision_rows(log):
    """(applied, reported) of each step of the second run (thermo 1)."""
    rows = log.split("Step")[-1].split("Loop time")[0].splitlines()[1:]
    return [(float(r.split()[1]), float(r.split()[2])) for r in rows if r.split() and r.split()[0].isdigit()]


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("newton", ["on", "off"])
@pytest.mark.parametrize("where", ["inside", "across the periodic boundary"])
@pytest.mark.parametrize("film", ["", "viscosity 1e-3 activation 0.05"], ids=["dry", "wet"])
def test_pair_local_reports_the_force_the_step_applied(lmp, nprocs, newton, where, film):
    """compute pair/local at the end of each step of a collision (e_d = 0.5, N_c = 16; wet: the
    film's approach and rebound too) gives the normal force the step applied: single() takes the
    step's velocity, v - dt/2 f/m for an owned atom after fix nve/sphere's second half kick (it
    took v^(n+1): p1 4 % off, 2 % across the periodic boundary, whose ghost held v^(n+1/2)).
    An oblique impact (the spheres offset by 0.3 R), so the applied force has no tangential part
    only because the pair is frictionless: |f| = |p1 + p2|. Not reported: the step at which a
    dry contact ends within the step, the pair then beyond compute pair/local's cutoff."""
    x1, x2 = (-0.0011, 0.0011) if where == "inside" else (0.0089, -0.0089)
    script = COLLISION
    for key, value in (("{newton}", newton), ("{x1}", repr(x1)), ("{x2}", repr(x2)), ("{film}", film)):
        script = script.replace(key, value)
    lmp(script, nprocs=nprocs)
    rows = collision_rows(lmp.log)
    assert len(rows) == 41
    acting = [(a, r) for a, r in rows if a > 0.0 and r > 0.0]
    assert len(acting) >= 16    # the contact (N_c = 16 steps) and, wet, the film
    for applied, reported in acting:
        assert reported == pytest.approx(applied, rel=1e-9)
    assert all(r == 0.0 or a > 0.0 for a, r in rows)


def neighbor_info(log):
    return log[log.index("Neighbor list info"):log.index("Per MPI rank memory")]


def test_dry_pays_only_for_contact(lmp):
    """Dry: a radius-based list whose cutoff is the sum of the largest radii (+ skin)."""
    lmp(scenes.pair_bounce(0.9))
    info = neighbor_info(lmp.log)
    assert "half/size/bin" in info
    assert "master list distance cutoff = 0.0025" in info      # 2 R + skin R/2


def test_wet_list_covers_the_film(lmp):
    lmp(scenes.pair_bounce(0.9, mu=1e-3))
    info = neighbor_info(lmp.log)
    assert "half/size" not in info and "half/bin" in info
    cutoff = 2e-3 + 0.09375e-3 + 0.5e-3                          # 2 R + eps_al R + skin
    assert f"master list distance cutoff = {cutoff:.6g}" in info


def test_time_step_change_keeps_the_contact(lmp):
    """ncontact sets t_c = N_c dt at the first run; halving dt afterwards keeps t_c (and k, c):
    the contact then lasts 2 N_c steps of the new dt and still gives e_d (issue 18: k following
    dt released the spring's energy into contacts under way)."""
    script = scenes.wall_bounce(0.5, dt_ru=0.005, steps=10)
    dt2 = 0.0025 * scenes.R / scenes.U
    script = script.replace('variable n equal', f"""timestep {dt2}
fix count2 all ave/time 1 1 1 v_overlap mode scalar ave running
run 600
variable n2 equal f_count2*601
print "RESULT steps2 $(v_n2:%.6f)"
variable n equal""")
    result = lmp(script)
    assert result["e"] == pytest.approx(0.5, rel=1e-9)
    assert abs(result["steps2"] - 16) <= 1
    assert "e_d = 0.5, t_c = 0.0004 (16 steps), k/m_e = 6.46879e+07" in lmp.log    # second run


@pytest.mark.parametrize("newton", ["on", "off"])
def test_film_pairs_survive_any_skin(lmp, newton):
    """A tiny skin must not lose the pair inside the film (radius lists do: LAMMPS PR #4685)."""
    mu = scenes.viscosity_for_stokes(100)
    wide = lmp(scenes.pair_bounce(0.9, mu=mu, skin=0.5e-3, newton=newton, radius_ratio=0.5,
                                  mass_ratio=0.125))
    tiny = lmp(scenes.pair_bounce(0.9, mu=mu, skin=1e-9, newton=newton, radius_ratio=0.5,
                                  mass_ratio=0.125))
    assert wide["e"] < 0.9 * 0.95            # the film acted
    assert tiny["e"] == pytest.approx(wide["e"], rel=1e-10)


@pytest.mark.parametrize("wet", ["", "viscosity 1e-3 activation 0.09375"])
def test_fix_pour_into_an_empty_box(lmp, wet):
    """No atoms at the start: the cutoff comes from the radius fix pour will insert."""
    script = f"""plugin load ${{plugin}}
units si
atom_style sphere
boundary p p f
comm_modify vel yes
region box block 0 0.02 0 0.02 0 0.05
create_box 1 box
pair_style lubricated/springdashpot
pair_coeff * * 0.9 {wet}
fix floor all wall/lubrication 0.9 zplane 0.0 NULL
fix nve all nve/sphere
fix g all gravity 9.81 vector 0 0 -1
region ins block 0 0.02 0 0.02 0.03 0.045
fix p all pour 100 1 4767 region ins diam one 0.002 dens 2500 2500
timestep 2e-5
run 6000
print "RESULT n $(atoms)"
print "RESULT zmin $(bound(all,zmin))"
"""
    result = lmp(script)
    assert result["n"] == 100
    # 2 R + (film: eps_al R) + the default SI skin of 1 mm
    cutoff = 0.002 + (0.09375e-3 if wet else 0.0) + 0.001
    assert f"master list distance cutoff = {cutoff:.6g}" in lmp.log
    assert result["zmin"] < 0.0015           # the first spheres have reached the floor

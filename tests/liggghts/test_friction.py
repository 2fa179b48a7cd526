"""model lubricated with LIGGGHTS's own tangential models: the normal model hands them the
solid contact force (Coulomb limit) and kt = 2/7 k, gammat = 2/7 c. A steep oblique impact
slides throughout, so the closed form of Coulomb sliding holds whatever kt:
  tangential impulse  J_t = mu_c (1 + e_d) m U_n,   spin  omega R = (5/2) J_t / m (a / R),
where a = R - delta/2 is LIGGGHTS's lever arm (delta the overlap, about 1 % of R here)."""
import pytest

import scenes
from liggghts_scenes import HEADER

R, U, RHO = scenes.R, scenes.U, scenes.RHO


def oblique(tangential, mu_c=0.3, e_dry=0.9, ratio=5.0):
    dt = 0.005 * R / U
    steps = int(0.6 * R / U / dt) + 64
    return HEADER + f"""boundary p p f
region box block -0.05 0.05 -0.01 0.01 0 0.02 units box
create_box 2 box
neighbor {0.5 * R} bin
neigh_modify delay 0
fix m1 all property/global coefficientRestitution peratomtypepair 2 {e_dry} {e_dry} {e_dry} {e_dry}
fix m2 all property/global coefficientFriction peratomtypepair 2 {mu_c} {mu_c} {mu_c} {mu_c}
pair_style gran model lubricated tangential {tangential}
pair_coeff * *
fix wall all wall/gran model lubricated tangential {tangential} primitive type 2 zplane 0.0
create_atoms 1 single 0 0 {1.2 * R} units box
set atom 1 diameter {2 * R} density {RHO}
velocity all set {ratio * U} 0 {-U} units box
fix nve all nve/sphere
timestep {dt}
thermo {steps}
run {steps}
variable vx equal vx[1]
variable vz equal vz[1]
variable wy equal omegay[1]
print "RESULT v ${{vx}} ${{vz}} ${{wy}}"
"""


def test_sliding_impact_follows_coulomb(run):
    mu_c, e_dry = 0.3, 0.9
    vx, vz, wy = run.lig(oblique("history", mu_c, e_dry))["v"]
    assert vz == pytest.approx(e_dry * U, rel=1e-6)             # normal model untouched
    impulse = mu_c * (1 + e_dry) * U                              # J_t / m
    assert 5 * U - vx == pytest.approx(impulse, rel=0.01)
    lever = wy * R / (2.5 * (5 * U - vx))                         # a / R, I = 2/5 m R^2
    assert 0.98 < lever < 1.0


def test_no_friction_without_tangential_model(run):
    vx, vz, wy = run.lig(oblique("no_history", mu_c=0.0))["v"]
    assert vx == pytest.approx(5 * U, rel=1e-12) and wy == pytest.approx(0.0, abs=1e-12)

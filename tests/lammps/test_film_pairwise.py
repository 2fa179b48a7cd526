"""The films are internal forces of a pair, also for unequal radii in a sheared box.

Two spheres of radii a and 1.4 a (rho_p 1000 kg/m^3) at a gap of 1e-3 R (R = 2 r_i r_j / (r_i +
r_j)) on the compressive axis of simple shear (fix deform xy erate remap v), moving with the
affine flow u = gdot y (and spinning at -gdot/2), no drag, no contact: the squeeze and shear
films brake the approach, and being internal they leave the pair's momentum as it was, to
round-off, with the per-pair film (limit atom) and the coupled solve (limit implicit), on 1 and
2 ranks. LAMMPS's lubricateU/poly fails this: it gives such a pair a net force of about 100
times its Stokes drag (bench/peer_pair_check.py)."""
import math

import pytest

import dense_scenes

A = 1.0e-4
RATIO = 1.4
GDOT = 1.0
ETA = 1.0e-2
RHO = 1000.0

SCRIPT = """region box prism 0 {box} 0 {box} 0 {box} 0 0 0 units box
create_box 2 box
create_atoms 1 single {x1} {y1} {z} units box
create_atoms 2 single {x2} {y2} {z} units box
set type 1 diameter {d1} density {rho}
set type 2 diameter {d2} density {rho}
velocity all ramp vx 0 {vtop} y 0 {box} units box
set group all omega 0 0 {spin}
neighbor {skin} bin
timestep {dt}
pair_style lubricated/springdashpot limit {limit}
pair_coeff * * 0.5 tcontact {tc} viscosity {eta} activation 0.1 shearfilm yes
fix nve all nve/sphere
fix shear all deform 1 xy erate {gdot} remap v
variable m1 equal mass[1]
variable m2 equal mass[2]
variable px0 equal v_m1*vx[1]+v_m2*vx[2]
variable py0 equal v_m1*vy[1]+v_m2*vy[2]
variable un0 equal ((vx[1]-vx[2])*{nx}+(vy[1]-vy[2])*{ny})
print "RESULT px0 $(v_px0:%.17g)"
print "RESULT py0 $(v_py0:%.17g)"
print "RESULT un0 $(v_un0:%.17g)"
run {steps}
print "RESULT px $(v_px0:%.17g)"
print "RESULT py $(v_py0:%.17g)"
print "RESULT un $(v_un0:%.17g)"
print "RESULT mass $((v_m1+v_m2):%.17g)"
"""


def pair_script(limit):
    r1, r2 = A, RATIO * A
    reduced = 2.0 * r1 * r2 / (r1 + r2)
    dist = r1 + r2 + 1e-3 * reduced
    n = (1.0 / math.sqrt(2.0), -1.0 / math.sqrt(2.0))       # from sphere 2 to sphere 1
    box = 20.0 * A
    c = 0.5 * box
    tc = 1.0e-3 / GDOT
    return dense_scenes.HEADER + SCRIPT.format(
        box=box, x1=c + 0.5 * dist * n[0], y1=c + 0.5 * dist * n[1], x2=c - 0.5 * dist * n[0],
        y2=c - 0.5 * dist * n[1], z=c, d1=2 * r1, d2=2 * r2, rho=RHO, vtop=GDOT * box, spin=-0.5 * GDOT,
        skin=0.5 * A, dt=tc / 8, limit=limit, tc=tc, eta=ETA, gdot=GDOT, nx=n[0], ny=n[1], steps=40)


@pytest.mark.parametrize("limit,nprocs", [("atom", 1), ("implicit", 1), ("implicit", 2)])
def test_films_of_unequal_spheres_keep_the_pairs_momentum(lmp, limit, nprocs):
    r = lmp(pair_script(limit), nprocs=nprocs)
    # the films act: the approach (u_n < 0 on the compressive axis) is braked by far more than
    # round-off, so a force on one sphere alone would show in the momentum
    assert r["un0"] < 0.0
    assert abs(r["un"]) < 0.5 * abs(r["un0"])
    scale = r["mass"] * abs(r["un0"])          # the momentum the films remove from the pair's motion
    assert abs(r["px"] - r["px0"]) < 1e-12 * scale + 1e-12 * abs(r["px0"])
    assert abs(r["py"] - r["py0"]) < 1e-12 * scale

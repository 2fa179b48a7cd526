"""Memory accounting (issue 19): the pair style's memory_usage() counts its per-pair records of the
many-body film budget, and a bed where no film can bind (film_budget.h: the normal and the shear
films' share bounds) keeps none. Through build/memory_parts (bench/memory_parts.cpp), which prints
each part's memory_usage() after a `run 0`.
"""
import pathlib
import random
import re
import subprocess

import pytest

import lammps_run

ROOT = pathlib.Path(__file__).resolve().parents[2]
TOOL = ROOT / "build" / "memory_parts"
R = 1.0e-3               # sphere radius [m]
SPACING = 2.05e-3        # lattice spacing [m]: gaps of 0.05 R, inside the film (eps_al = 0.094)
N_SIDE = 6               # 216 spheres, periodic
RECORD_BYTES = 2 * 4 + 4 * 8    # i, j; normal film, shear film x y z

SCENE = """plugin load ${{plugin}}
units si
atom_style sphere
boundary p p p
comm_modify vel yes
newton on
read_data lattice.data
pair_style lubricated/springdashpot limit {limit}
pair_coeff * * 0.9 ncontact 8 viscosity {mu} grid 1.25e-4 friction 0.3
fix nve all nve/sphere
neighbor 2e-4 bin
timestep 1.25e-5
run 0
"""


def lattice(path, seed=19):
    """A simple cubic lattice, every sphere moving at random (|v| ~ 0.1 m/s)."""
    rng = random.Random(seed)
    side = N_SIDE * SPACING
    lines = ["lattice for test_memory_usage", "", f"{N_SIDE ** 3} atoms", "1 atom types", "",
             f"0 {side} xlo xhi", f"0 {side} ylo yhi", f"0 {side} zlo zhi", "", "Atoms # sphere", ""]
    k = 0
    for a in range(N_SIDE):
        for b in range(N_SIDE):
            for c in range(N_SIDE):
                k += 1
                lines.append(f"{k} 1 {2 * R} 2500 {(a + 0.5) * SPACING} {(b + 0.5) * SPACING} {(c + 0.5) * SPACING}")
    lines += ["", "Velocities", ""]
    for i in range(1, k + 1):
        lines.append(f"{i} " + " ".join(f"{rng.uniform(-0.1, 0.1):.6g}" for _ in range(3)) + " 0 0 0")
    path.write_text("\n".join(lines) + "\n")


def parts(scratch, limit, mu):
    """Bytes per part of the lattice scene (pair style, fixes) and atom->nmax."""
    name = f"in.memory_{limit}_{mu}"
    (scratch / name).write_text(SCENE.format(limit=limit, mu=mu))
    out = subprocess.run([str(TOOL), name, "-var", "plugin", str(lammps_run.PLUGIN)], cwd=scratch,
                         env=lammps_run.lmp_env(), capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stdout + out.stderr
    found = {m.group(1).split()[0]: float(m.group(2))
             for m in re.finditer(r"PART (.+?)\s+[0-9.eE+-]+ MB/1000 atoms\s+([0-9]+) bytes", out.stdout)}
    found["nmax"] = int(re.search(r"NMAX (\d+)", out.stdout).group(1))
    return found


@pytest.mark.skipif(not TOOL.exists(), reason="build/memory_parts is not built (no liblammps.so found)")
def test_pair_memory_counts_the_film_budget_records(scratch):
    lattice(scratch / "lattice.data")
    # Every lattice neighbour pair (3 per sphere) is in the film: with mu_f = 1 Pa s each film's
    # share bound is far above 1/6, so the budget runs and records each film (normal and shear).
    film_pairs = 3 * N_SIDE ** 3
    # Beyond limit pair's lists, limit atom holds each owned and ghost atom's load and scale
    # (2 doubles, atom->nmax of each) and its records.
    def records(limit_atom, limit_pair):
        return limit_atom["pair"] - limit_pair["pair"] - 2 * 8 * limit_atom["nmax"]

    assert records(parts(scratch, "atom", 1.0), parts(scratch, "pair", 1.0)) >= RECORD_BYTES * film_pairs
    # Water (mu_f 1e-3 Pa s): each sphere's six films' bounds, normal and shear, sum below 1, so
    # no film can bind and the budget keeps no records.
    assert records(parts(scratch, "atom", 1e-3), parts(scratch, "pair", 1e-3)) == 0

"""examples/suspension_shear (make suspension), tiny: 60 bidisperse spheres at solid fraction
0.5 sheared to a strain of 0.6 at St 1e-3 (contacts of gdot t_c 1e-3, four times softer than the
example's, to keep it short), averaged over its last 0.3 (in the start-up, below a
strain of about 0.3, the particle pressure of so small a box may still be negative). The films
solved together (limit implicit) keep every sphere and give a finite positive shear stress and
particle pressure; the films add to the viscosity, and solved they resist more than scaled down
by the budget (limit atom)."""
import math
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
TINY = {"n": 60, "phi": 0.5, "strain": 0.6, "average": 0.3, "gtc": 1e-3}


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """The three variants once for the module: limit implicit, limit atom, films off."""
    import lammps_run
    out = tmp_path_factory.mktemp("suspension")
    script = (ROOT / "examples" / "suspension_shear" / "in.suspension_shear").read_text()
    variants = {"implicit": {"limit": "implicit"}, "atom": {"limit": "atom"}, "dry films": {"films": 0}}
    results = {}
    for name, extra in variants.items():
        results[name], results[name + " log"] = lammps_run.run(
            script, out / name.replace(" ", "_"), {**TINY, **extra}, name="in.suspension_shear")
    return results


def test_implicit_keeps_every_sphere_and_gives_a_positive_stress(runs):
    result, log = runs["implicit"], runs["implicit log"]
    assert "(limit implicit)" in log
    assert result["atoms"] == TINY["n"]
    assert result["strain"] == pytest.approx(TINY["strain"])
    assert result["St"] == pytest.approx(1e-3)
    for key in ["sigma_xy", "P", "eta_s", "J", "mu"]:
        assert math.isfinite(result[key]) and result[key] > 0.0, key
    assert result["iterations"] >= 1.0    # the budget binds: the solve ran on the averaged steps
    assert "did not converge" not in log


def test_films_raise_the_viscosity(runs):
    """The films' viscosity adds to that of the drag and contacts alone, and the solved films
    resist more than the same films scaled down to the budget."""
    dry, atom, implicit = (runs[k]["eta_s"] for k in ("dry films", "atom", "implicit"))
    assert runs["dry films"]["iterations"] == 0.0 and runs["atom"]["iterations"] == 0.0
    assert dry < atom < implicit


def test_a_restart_file_continues_the_shear(tmp_path):
    """-var restart_every writes the shear's state; -var packing 3 goes on from it (strain counted
    from the file), as bench/suspension_step_paired.py does: at the same N_c the continuation
    repeats the run's own stresses, contact springs and films included. The solve's tolerance
    and the box's last move (fix deform moves it after a step's forces; the set-up sees it)
    bound what the restart may change: 1e-4 of the mean stresses over 0.05 of strain (measured
    2e-6 and 1e-5). A file written within a run (LAMMPS's restart command: no last kicks, a
    fresh set-up) parted by 7e-4 in sigma_xy and 3e-3 in P."""
    import lammps_run
    import numpy as np
    script = (ROOT / "examples" / "suspension_shear" / "in.suspension_shear").read_text()
    steps_per_strain = 8 / TINY["gtc"]    # N_c 8, gdot 1
    tiny = {**TINY, "strain": 0.1, "average": 0.05, "series": 20}
    lammps_run.run(script, tmp_path / "base", {**tiny, "restart_every": 200},
                   name="in.suspension_shear")
    # restart N writes at the multiples of N: step 3400 is strain 0.05 of the shear
    restart = tmp_path / "base" / f"suspension.{3000 + round(0.05 * steps_per_strain)}.restart"
    lammps_run.run(script, tmp_path / "continued", {**tiny, "strain": 0.05, "average": 0.02, "packing": 3,
                                                    "packing_file": restart}, name="in.suspension_shear")
    base = np.loadtxt(tmp_path / "base" / "suspension_series.txt", comments="#")
    continued = np.loadtxt(tmp_path / "continued" / "suspension_series.txt", comments="#")[1:]    # after the set-up
    later = base[base[:, 1] > 0.05 + 1e-9]
    assert continued[:, 1] == pytest.approx(later[:, 1] - 0.05, abs=1e-9)    # the strain from the file
    for column in (2, 3):    # sigma_xy, P
        scale = np.abs(base[:, column]).mean()
        assert np.max(np.abs(continued[:, column] - later[:, column])) < 1e-4 * scale

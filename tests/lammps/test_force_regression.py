"""Force regression (issue 22), in the manner of LAMMPS's force-style YAML tests: for a few
pair and wall configurations (tools/force_scenes.py: dry, sampled, wet, wet on a grid with
Legendre's calibration, friction, friction with rolling and the shear film) the per-atom forces
and torques, the energy and the virial after `run 0` (the set-up evaluation) and after 3 steps
(the step evaluation, vectorised loops included) are recorded once in force_regression/*.json
and must be reproduced on every run, newton on and off, so that a refactor cannot change the
physics unseen.

Tolerance 1e-13 of the largest force (torque) of the scene: the recorded digits (17) and the
order of the sums (newton off sums a pair on both ranks' sides) differ by round-off, ~1e-16
relative; anything the model computes differently moves forces by far more.

Regenerate after an intended change of the physics, and say why in the commit:
    REGENERATE_FORCES=1 .venv/bin/python -m pytest tests/lammps/test_force_regression.py
"""
import json
import os
import pathlib

import pytest

import force_scenes  # noqa: E402

REFERENCE = pathlib.Path(__file__).parent / "force_regression"
TOLERANCE = 1e-13
STEPS = 3
MODELS = list(force_scenes.PAIR_MODELS) + list(force_scenes.WALL_MODELS)


def run_scene(lmp, model, newton):
    (lmp.dir / "scene.data").write_text(force_scenes.data_file())
    results = lmp(force_scenes.script(model, newton, STEPS))
    return {
        "model": (force_scenes.WALL_MODELS if model in force_scenes.WALL_MODELS else force_scenes.PAIR_MODELS)[model],
        "atoms": int(results["atoms"]),
        "state0": results["state0"], "state1": results["state1"],
        "forces0": force_scenes.read_dump(lmp.dir / "forces0.dump"),
        "forces1": force_scenes.read_dump(lmp.dir / "forces1.dump"),
    }


def assert_rows_match(rows, reference, what):
    assert len(rows) == len(reference)
    for columns, name in ((slice(0, 3), "force"), (slice(3, 6), "torque")):
        scale = max(abs(v) for row in reference for v in row[columns])
        if name == "torque" and scale == 0.0:    # normal-only models: none, exactly
            assert all(v == 0.0 for row in rows for v in row[columns]), f"{what}: torques appeared"
            continue
        assert scale > 0.0, f"{what}: no {name} at all: the scene tests nothing"
        worst = max(abs(a - b) for row, ref in zip(rows, reference) for a, b in zip(row[columns], ref[columns]))
        assert worst <= TOLERANCE * scale, f"{what}: {name} differs by {worst / scale:.3g} of the largest"


@pytest.mark.parametrize("newton", ["on", "off"])
@pytest.mark.parametrize("model", MODELS)
def test_forces_torques_energy_virial(lmp, model, newton):
    got = run_scene(lmp, model, newton)
    path = REFERENCE / f"{model}.json"
    if os.environ.get("REGENERATE_FORCES") and newton == "on":
        path.write_text(json.dumps(got, indent=1) + "\n")
    reference = json.loads(path.read_text())
    assert got["model"] == reference["model"], "the scene's model changed: regenerate"
    assert got["atoms"] == reference["atoms"]
    for state in ("0", "1"):
        assert_rows_match(got["forces" + state], reference["forces" + state], f"{model} newton {newton} step {state}")
        # the energy, then the six virial components (pair) or the wall's force, against the
        # largest of them
        energy, virial = got["state" + state][0], got["state" + state][1:]
        ref_energy, ref_virial = reference["state" + state][0], reference["state" + state][1:]
        assert energy == pytest.approx(ref_energy, rel=TOLERANCE, abs=1e-300)
        scale = max(abs(v) for v in ref_virial)
        assert max(abs(a - b) for a, b in zip(virial, ref_virial)) <= TOLERANCE * scale


def test_the_scene_takes_every_branch(lmp):
    """The wet friction scene has contacts, films and pairs beyond the film: forces on most
    spheres, none on the pair outside the film (its 0.15 R_e gap exceeds the 0.1 activation)."""
    reference = json.loads((REFERENCE / "wet_friction_rolling.json").read_text())
    forces = reference["forces0"]
    nonzero = [any(v != 0.0 for v in row[:3]) for row in forces]
    npairs = 2 * len(force_scenes.PAIR_GAPS)
    assert nonzero[:npairs - 2] == [True] * (npairs - 2)      # every gap up to 0.08 R_e acts
    assert nonzero[npairs - 2:npairs] == [False, False]       # 0.15 R_e: outside the film
    assert all(nonzero[npairs:npairs + 3])                    # the triple

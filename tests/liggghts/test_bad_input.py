"""Bad input ends with a LIGGGHTS ERROR that names the property, its value and the allowed
range (the kernel's validation, with the LAMMPS keywords replaced by property names); a
missing model library is reported clearly."""
import os

import pytest

import liggghts_run
import liggghts_scenes
import scenes

GOOD = liggghts_scenes.wall_bounce(0.9, mu=scenes.viscosity_for_stokes(100))

CASES = {
    "e_d above 1": (("peratomtypepair 2 0.9 0.9 0.9 0.9", "peratomtypepair 2 1.5 0.9 0.9 0.9"),
                    ["coefficientRestitution = 1.5", "types 1 1", "0 < coefficientRestitution <= 1"]),
    "e_d zero": (("peratomtypepair 2 0.9 0.9 0.9 0.9", "peratomtypepair 2 0.9 0 0 0.9"),
                 ["coefficientRestitution = 0", "types 1 2"]),
    "N_c below 1": (("lubricatedContactSteps scalar 8", "lubricatedContactSteps scalar 0.5"),
                    ["lubricatedContactSteps = 0.5", "1 <= N_c <= 1e6"]),
    "negative viscosity": (("lubricatedViscosity scalar 0", "lubricatedViscosity scalar -0"),
                           ["lubricatedViscosity = -", "mu_f = 0 (dry) or 1e-100 <= mu_f <= 1e100"]),
    "activation above 1": (("lubricatedActivation scalar 0.09375", "lubricatedActivation scalar 2"),
                           ["lubricatedActivation = 2", "eps_al <= 1"]),
    "release above saturation": (
        ("lubricatedActivation scalar 0.09375",
         "lubricatedActivation scalar 0.09375\nfix m9 all property/global lubricatedRelease scalar 0.01"),
        ["lubricatedRelease = 0.01", "lubricatedSaturation", "eps_2 < eps_1"]),
    "film without activation": (("fix m4 all property/global lubricatedActivation scalar 0.09375", ""),
                                ["lubricatedViscosity > 0 requires", "lubricatedActivation",
                                 "lubricatedGridSpacing"]),
    "steps and time": (("lubricatedContactSteps scalar 8",
                        "lubricatedContactSteps scalar 8\nfix m9 all property/global lubricatedContactTime scalar 4e-4"),
                       ["lubricatedContactSteps and lubricatedContactTime are mutually exclusive"]),
    "contact shorter than a step": (("lubricatedContactSteps scalar 8", "lubricatedContactTime scalar 1e-6"),
                                    ["lubricatedContactTime = 1e-06", "shorter than the time step 5e-05"]),
    "grid not positive": (("lubricatedActivation scalar 0.09375", "lubricatedGridSpacing scalar -1e-4"),
                          ["lubricatedGridSpacing = -0.0001", "1e-100 <= dx <= 1e100"]),
    "negative legendre": (("lubricatedActivation scalar 0.09375",
                           "lubricatedActivation scalar 0.09375\nfix m9 all property/global lubricatedLegendre scalar -35"),
                          ["lubricatedLegendre = -35", "A >= 0"]),
    "legendre with a film in overlap": (
        ("lubricatedActivation scalar 0.09375",
         "lubricatedActivation scalar 0.09375\nfix m9 all property/global lubricatedLegendre scalar 35\n"
         "fix m10 all property/global lubricatedRelease scalar -0.01"),
        ["lubricatedRelease = -0.01 is out of range with lubricatedLegendre"]),
    # Finite but absurd values (issue 17): an ERROR with the value and the range, not a NaN.
    "N_c absurd": (("lubricatedContactSteps scalar 8", "lubricatedContactSteps scalar 1e160"),
                   ["lubricatedContactSteps = 1e+160 is out of range", "1 <= N_c <= 1e6"]),
    "contact time absurd": (("lubricatedContactSteps scalar 8", "lubricatedContactTime scalar 1e300"),
                            ["lubricatedContactTime = 1e+300 is out of range", "1e-100 <= t_c <= 1e100"]),
    "contact time of too many steps": (("lubricatedContactSteps scalar 8", "lubricatedContactTime scalar 100"),
                                       ["lubricatedContactTime = 100 is out of range with the time step 5e-05",
                                        "N_c = t_c / dt = 2e+06", "1 <= N_c <= 1e6"]),
    "saturation absurd": (("lubricatedActivation scalar 0.09375",
                           "lubricatedActivation scalar 0.09375\nfix m9 all property/global lubricatedSaturation scalar 1e-310"),
                          ["lubricatedSaturation = 1e-310 is out of range", "1e-12 <= eps_1 < 1"]),
    "viscosity absurd": (("lubricatedViscosity scalar 0.", "lubricatedViscosity scalar 1e300  # replaces 0."),
                         ["lubricatedViscosity = 1e+300 is out of range", "1e-100 <= mu_f <= 1e100"]),
    "grid beyond a radius": (("lubricatedActivation scalar 0.09375", "lubricatedGridSpacing scalar 8e-3"),
                             ["lubricatedGridSpacing = 0.008 gives eps_al = 0.75 dx / R = 6",
                              "(R = 0.001)", "as lubricatedActivation <= 1"]),
    "grid absurd": (("lubricatedActivation scalar 0.09375", "lubricatedGridSpacing scalar 1e300"),
                    ["lubricatedGridSpacing = 1e+300 is out of range", "1e-100 <= dx <= 1e100"]),
    # Forces are masses times accelerations with no conversion factor (src/unit_style/unit_style.h):
    # LIGGGHTS's granular styles refuse such units themselves, before the model is set up.
    "units metal": (("units si", "units metal"), ["non-consistent unit system", "si,cgs or lj"]),
    "units real": (("units si", "units real"), ["non-consistent unit system", "si,cgs or lj"]),
    # The text of every property the model reads is checked as LAMMPS checks a number (issue 18:
    # LIGGGHTS itself reads "1e" as 1).
    "viscosity text": (("lubricatedViscosity scalar 0.00177", "lubricatedViscosity scalar 1e-3e"),
                       ["property/global lubricatedViscosity: '1e-3e77777777777779' is not a number"]),
    "steps text": (("lubricatedContactSteps scalar 8", "lubricatedContactSteps scalar 8steps"),
                   ["property/global lubricatedContactSteps: '8steps' is not a number"]),
    "restitution text": (("peratomtypepair 2 0.9 0.9 0.9 0.9", "peratomtypepair 2 0.9 0.9 0.9 .9.9"),
                         ["property/global coefficientRestitution: '.9.9' is not a number"]),
    "restitution hex": (("peratomtypepair 2 0.9 0.9 0.9 0.9", "peratomtypepair 2 0.9 0.9 0.9 0x1p-1"),
                        ["coefficientRestitution: '0x1p-1' is not a number"]),
    "missing restitution": (("fix m1 all property/global coefficientRestitution peratomtypepair 2 0.9 0.9 0.9 0.9", ""),
                            ["coefficientRestitution", "model lubricated"]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_error_names_the_property(run, case):
    (old, new), expected = CASES[case]
    assert old in GOOD
    run.lig(GOOD.replace(old, new), check=False)
    error = next((line for line in run.log.splitlines() if line.startswith("ERROR")), "")
    for text in expected:
        assert text in error, (text, error)


# The model's global properties with a valid value each: in another style than scalar LIGGGHTS's
# lookup by style skipped them without a word (the run went on dry, or with N_c = 8).
SCALAR_PROPERTIES = {"lubricatedContactSteps": "8", "lubricatedContactTime": "4e-4", "lubricatedViscosity": "1e-3",
                     "lubricatedActivation": "0.09375", "lubricatedGridSpacing": "1e-4",
                     "lubricatedSaturation": "1e-3", "lubricatedRelease": "-1e-2", "lubricatedLegendre": "35",
                     "lubricatedLimitPair": "1"}
OTHER_STYLES = {"vector": "{v} {v}", "peratomtype": "{v} {v}", "peratomtypepair": "2 {v} {v} {v} {v}"}


@pytest.mark.parametrize("style", sorted(OTHER_STYLES))
@pytest.mark.parametrize("name", sorted(SCALAR_PROPERTIES))
def test_property_in_another_style_is_refused(run, name, style):
    """A property of the model given as vector, peratomtype or peratomtypepair stops at its fix
    property/global command with an ERROR naming the fix, the property and the style."""
    kept = [line for line in GOOD.splitlines() if f" {name} " not in line]
    script = "\n".join(kept).replace(
        "pair_style gran", f"fix m9 all property/global {name} {style} "
        + OTHER_STYLES[style].format(v=SCALAR_PROPERTIES[name]) + "\npair_style gran")
    run.lig(script, check=False)
    error = next((line for line in run.log.splitlines() if line.startswith("ERROR")), "")
    assert f"fix m9 property/global {name}: style {style} is not allowed; {name} must be scalar" in error, error


def test_good_input_runs(run):
    assert run.lig(GOOD)["e"] > 0.0


@pytest.mark.parametrize("launcher", [False, True], ids=["preload", "launcher"])
def test_property_text_is_checked_with_either_program(run, launcher):
    """Numbers in every form LAMMPS accepts pass and give the same run; a malformed one stops
    with the property and its text, whether the library is preloaded or linked."""
    plain = run.lig(GOOD, launcher=launcher)
    forms = GOOD.replace("lubricatedContactSteps scalar 8", "lubricatedContactSteps scalar +8.0E+00").replace(
        "peratomtypepair 2 0.9 0.9 0.9 0.9", "peratomtypepair 2 9e-1 .9 0.90 9.E-1")
    assert forms != GOOD and run.lig(forms, launcher=launcher)["e"] == plain["e"]
    run.lig(GOOD.replace("lubricatedActivation scalar 0.09375", "lubricatedActivation scalar 1e"),
            launcher=launcher, check=False)
    assert "lubricatedActivation: '1e' is not a number" in run.log


def test_stock_liggghts_without_the_library_fails(run):
    """Without the library LIGGGHTS rejects the model name (its own message); with LD_PRELOAD
    naming a missing file, the loader names that file too."""
    run.lig(GOOD, preload=False, check=False)
    assert "ERROR: Invalid model specified" in run.log
    missing = run.dir / "nowhere" / "liblubricated_liggghts.so"
    library = liggghts_run.LIBRARY
    try:
        liggghts_run.LIBRARY = missing
        run.lig(GOOD, check=False)
    finally:
        liggghts_run.LIBRARY = library
    assert str(missing) in run.log and "cannot be preloaded" in run.log
    assert "ERROR: Invalid model specified" in run.log


def test_runner_names_a_missing_library(monkeypatch, tmp_path):
    monkeypatch.setattr(liggghts_run, "LIBRARY", tmp_path / "liblubricated_liggghts.so")
    assert "liblubricated_liggghts.so" in liggghts_run.available()
    assert os.path.exists(liggghts_run.LIGGGHTS)


def test_setup_is_described_and_warned_as_in_lammps(run):
    """The kernel's check_setup, as the LAMMPS styles report it: one line per type pair with the
    derived k/m_e and c/m_e, and the WARNING for N_c below 8 (LIGGGHTS printed neither before)."""
    run.lig(liggghts_scenes.wall_bounce(0.9, ncontact=4))
    log = run.log
    assert "pair gran model lubricated types 1 1: e_d = 0.9, t_c = " in log and "(4 steps), k/m_e = " in log
    assert "fix wall/gran model lubricated types 1 2: e_d = 0.9" in log
    warnings = [line for line in log.splitlines() if line.startswith("WARNING") and "N_c = 4 steps" in line]
    assert any("pair gran model lubricated" in w for w in warnings)
    assert any("fix wall/gran model lubricated" in w for w in warnings)
    run.lig(liggghts_scenes.wall_bounce(0.9, ncontact=8))
    assert "N_c = " not in run.log

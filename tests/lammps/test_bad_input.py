"""Every bad input ends in a LAMMPS ERROR that names the parameter (and its allowed range)."""
import pytest

import scenes

BASE = """plugin load ${plugin}
units si
atom_style ATOMSTYLE
boundary p p f
comm_modify vel yes
region box block -0.01 0.01 -0.01 0.01 0 0.02
create_box 2 box
create_atoms 1 single 0 0 0.005
ATOMSET
pair_style lubricated/springdashpot
PAIRCOEFF
FIX
timestep 1e-5
run 1
"""


def script(pair_coeff="pair_coeff * * 0.9", fix="", atom_style="sphere", extra_before_run=""):
    atom_set = "set atom 1 diameter 0.002 density 8000" if atom_style == "sphere" else "mass * 1.0"
    text = (BASE.replace("ATOMSTYLE", atom_style).replace("ATOMSET", atom_set)
            .replace("PAIRCOEFF", pair_coeff).replace("FIX", fix))
    return text.replace("timestep 1e-5", "timestep 1e-5\n" + extra_before_run)


CASES = {
    "e_d_zero": (script("pair_coeff * * 0"), ["e_d = 0", "0 < e_d <= 1"]),
    "e_d_above_one": (script("pair_coeff * * 1.5"), ["e_d = 1.5", "0 < e_d <= 1"]),
    "ncontact_below_one": (script("pair_coeff * * 0.9 ncontact 0.5"), ["ncontact = 0.5", "1 <= N_c <= 1e6"]),
    "negative_viscosity": (script("pair_coeff * * 0.9 viscosity -1e-3 activation 0.1"),
                           ["viscosity = -0.001", "mu_f = 0 (dry) or 1e-100 <= mu_f <= 1e100"]),
    "eps1_not_above_eps2": (script("pair_coeff * * 0.9 saturation 1e-3 release 2e-3"),
                            ["release = 0.002", "eps_2 < eps_1"]),
    "wet_without_activation": (script("pair_coeff * * 0.9 viscosity 1e-3"), ["activation", "grid"]),
    "activation_dem_between_spheres": (script("pair_coeff * * 0.9 viscosity 1e-3 activation dem"),
                                       ["activation dem is for walls", "activation eps_al or grid dx"]),
    "activation_not_dem": (script(fix="fix w all wall/lubrication 0.9 viscosity 1e-3 activation DEM "
                                      "zplane 0.0 NULL"),
                           ["expected a number for keyword activation (or dem)", "'DEM'"]),
    "unknown_pair_keyword": (script("pair_coeff * * 0.9 viscosty 1e-3"),
                             ["unknown keyword 'viscosty'", "pair_coeff also takes cutoff"]),
    "cutoff_zero": (script("pair_coeff * * 0.9 cutoff 0"), ["cutoff = 0 is not allowed", "a distance > 0"]),
    "cutoff_negative": (script("pair_coeff * * 0.9 cutoff -0.003"), ["cutoff = -0.003 is not allowed"]),
    "cutoff_not_a_number": (script("pair_coeff * * 0.9 cutoff big"), ["cutoff = big is not allowed"]),
    "cutoff_missing": (script("pair_coeff * * 0.9 ncontact 8 cutoff"), ["missing value for keyword cutoff"]),
    # below the contact distance of the spheres present (diameter 2 mm): every pair could be lost
    "cutoff_below_the_radii": (script("pair_coeff * * 0.9 cutoff 0.0015"),
                               ["types 1 1: spheres of radius 0.001 and 0.001 need a cutoff of 0.002",
                                "beyond this run's 0.0015 (pair_coeff cutoff)"]),
    "missing_coefficients": (script("pair_coeff 1 1 0.9"), ["All pair coeffs are not set", "1      2: is not set"]),
    "pair_style_arguments": (script().replace("pair_style lubricated/springdashpot",
                                              "pair_style lubricated/springdashpot 0.9"),
                             ["unknown keyword '0.9'", "vector yes|no", "limit atom|pair", "trim yes|no"]),
    "pair_style_vector_value": (script().replace("pair_style lubricated/springdashpot",
                                                 "pair_style lubricated/springdashpot vector maybe"),
                                ["vector = maybe", "yes or no"]),
    "pair_style_vector_missing": (script().replace("pair_style lubricated/springdashpot",
                                                   "pair_style lubricated/springdashpot vector"),
                                  ["keyword vector needs a value"]),
    "pair_style_limit_value": (script().replace("pair_style lubricated/springdashpot",
                                                "pair_style lubricated/springdashpot limit none"),
                               ["limit = none", "atom, pair or implicit"]),
    "pair_style_limit_missing": (script().replace("pair_style lubricated/springdashpot",
                                                  "pair_style lubricated/springdashpot vector yes limit"),
                                 ["keyword limit needs a value"]),
    "pair_style_trim_value": (script().replace("pair_style lubricated/springdashpot",
                                               "pair_style lubricated/springdashpot trim always"),
                              ["trim = always", "yes or no"]),
    "pair_style_trim_missing": (script().replace("pair_style lubricated/springdashpot",
                                                 "pair_style lubricated/springdashpot limit atom trim"),
                                ["keyword trim needs a value"]),
    "point_particle": (script(extra_before_run="set atom 1 diameter 0.0"),
                       ["atom 1 has diameter 0", "allowed: > 0"]),
    "wall_point_particle": (script(pair_coeff="pair_coeff * *", fix="fix w all wall/lubrication 0.9 zplane 0.0 NULL",
                                   extra_before_run="set atom 1 diameter 0.0").replace(
                                "pair_style lubricated/springdashpot", "pair_style zero 0.001"),
                            ["Fix wall/lubrication: atom 1 has diameter 0"]),
    "wrong_atom_style": (script(atom_style="atomic"), ["requires atom_style sphere"]),
    "no_ghost_velocity": (script().replace("comm_modify vel yes", ""), ["comm_modify vel yes"]),
    "tcontact_below_dt": (script("pair_coeff * * 0.9 tcontact 1e-6"), ["tcontact", "N_c = t_c / dt >= 1"]),
    "wall_unknown_keyword": (script(fix="fix w all wall/lubrication 0.9 zplane 0.0 NULL units box"),
                             ["unknown keyword 'units'"]),
    "wall_cylinder_radius_zero": (script(fix="fix w all wall/lubrication 0.9 zcylinder 0"),
                                  ["zcylinder radius = 0 is out of range", "0 < R"]),
    "wall_cylinder_radius_negative": (script(fix="fix w all wall/lubrication 0.9 zcylinder -0.008"),
                                      ["zcylinder radius = -0.008 is out of range"]),
    "wall_cylinder_smaller_than_sphere": (script(fix="fix w all wall/lubrication 0.9 zcylinder 0.0008"),
                                          ["sphere of radius 0.001 does not fit inside the zcylinder of radius "
                                           "0.0008", "allowed: R < 0.0008"]),
    "wall_cylinder_missing_radius": (script(fix="fix w all wall/lubrication 0.9 zcylinder"),
                                     ["zcylinder needs its radius"]),
    "wall_wiggle_unknown_dim": (script(fix="fix w all wall/lubrication 0.9 zplane 0.0 NULL wiggle w 1e-4 0.01"),
                                ["wiggle dim = w is unknown", "allowed: x, y, z"]),
    "wall_wiggle_period": (script(fix="fix w all wall/lubrication 0.9 zplane 0.0 NULL wiggle z 1e-4 0"),
                           ["wiggle period = 0 is out of range", "0 < period"]),
    "wall_wiggle_missing": (script(fix="fix w all wall/lubrication 0.9 zplane 0.0 NULL wiggle z 1e-4"),
                            ["wiggle needs 3 values"]),
    "wall_shear_normal": (script(fix="fix w all wall/lubrication 0.9 zplane 0.0 NULL shear z 0.1"),
                          ["shear dim = z is normal to the wall"]),
    "wall_shear_unknown_dim": (script(fix="fix w all wall/lubrication 0.9 zcylinder 0.008 shear q 0.1"),
                               ["shear dim = q is unknown"]),
    "wall_side_on_plane": (script(fix="fix w all wall/lubrication 0.9 zplane 0.0 NULL side out"),
                           ["side applies to zcylinder only"]),
    "wall_side_value": (script(fix="fix w all wall/lubrication 0.9 zcylinder 0.008 side up"),
                        ["side = up is unknown", "allowed: in, out"]),
    "wall_moving_reset_timestep": (script(fix="fix w all wall/lubrication 0.9 zplane 0.0 NULL translate 0 0 0.1",
                                          extra_before_run="reset_timestep 0"),
                                   ["Cannot reset timestep with time-dependent fix wall/lubrication"]),
    "wall_bad_keyword_before_plane": (script(fix="fix w all wall/lubrication 0.9 damping 3 zplane 0.0 NULL"),
                                      ["Fix wall/lubrication", "unknown keyword 'damping'"]),
    "wall_e_d": (script(fix="fix w all wall/lubrication 0 zplane 0.0 NULL"), ["e_d = 0", "0 < e_d <= 1"]),
    "wall_viscosity": (script(fix="fix w all wall/lubrication 0.9 viscosity -2 grid 1e-4 zplane 0.0 NULL"),
                       ["viscosity = -2", "mu_f = 0 (dry) or 1e-100 <= mu_f <= 1e100"]),
    "wall_missing_plane": (script(fix="fix w all wall/lubrication 0.9 ncontact 8"), ["missing wall style"]),
    "wall_both_null": (script(fix="fix w all wall/lubrication 0.9 zplane NULL NULL"), ["both walls are NULL"]),
    "legendre_negative": (script("pair_coeff * * 0.9 viscosity 1e-3 activation 0.1 legendre -35"),
                          ["legendre = -35", "A >= 0"]),
    "legendre_dry": (script("pair_coeff * * 0.9 legendre 35"), ["legendre needs a wet contact"]),
    "legendre_sampled": (script("pair_coeff * * 0.9 viscosity 1e-3 activation 0.1 legendre 35 "
                                "integration sampled"), ["legendre needs integration exact"]),
    "wall_legendre_release": (script(fix="fix w all wall/lubrication 0.9 viscosity 1e-3 activation 0.1 "
                                         "legendre 35 release -0.01 zplane 0.0 NULL"),
                              ["release = -0.01 is out of range with legendre"]),
    "negative_friction": (script("pair_coeff * * 0.9 friction -0.3"), ["friction = -0.3", "mu_c >= 0"]),
    "tangential_above_one": (script("pair_coeff * * 0.9 friction 0.3 tangential 1.2"),
                             ["tangential = 1.2", "0 <= e_t <= 1"]),
    "tangential_negative": (script("pair_coeff * * 0.9 friction 0.3 tangential -0.5"),
                            ["tangential = -0.5", "0 <= e_t <= 1"]),
    "negative_rolling": (script("pair_coeff * * 0.9 friction 0.3 rolling -0.1"), ["rolling = -0.1", "mu_r >= 0"]),
    "shearfilm_value": (script("pair_coeff * * 0.9 shearfilm maybe"), ["shearfilm must be yes or no"]),
    "wall_negative_friction": (script(fix="fix w all wall/lubrication 0.9 friction -1 zplane 0.0 NULL"),
                               ["Fix wall/lubrication", "friction = -1", "mu_c >= 0"]),
    "wall_tangential": (script(fix="fix w all wall/lubrication 0.9 friction 0.5 tangential 2 zplane 0.0 NULL"),
                        ["Fix wall/lubrication", "tangential = 2", "0 <= e_t <= 1"]),
    "wall_lo_above_hi": (script(fix="fix w all wall/lubrication 0.9 zplane 0.02 0.01"), ["must be below hi"]),
    # Finite but absurd values (issue 17): an ERROR with the value and the range, not a NaN.
    "ncontact_absurd": (script("pair_coeff * * 0.9 ncontact 1e160"),
                        ["ncontact = 1e+160 is out of range", "1 <= N_c <= 1e6"]),
    "tcontact_absurd": (script("pair_coeff * * 0.9 tcontact 1e300"),
                        ["tcontact = 1e+300 is out of range", "1e-100 <= t_c <= 1e100"]),
    "saturation_absurd": (script("pair_coeff * * 0.9 viscosity 1e-3 activation 0.1 saturation 1e-310"),
                          ["saturation = 1e-310 is out of range", "1e-12 <= eps_1 < 1"]),
    "viscosity_absurd": (script("pair_coeff * * 0.9 viscosity 1e300 activation 0.1"),
                         ["viscosity = 1e+300 is out of range", "1e-100 <= mu_f <= 1e100"]),
    "grid_absurd": (script("pair_coeff * * 0.9 viscosity 1e-3 grid 1e300"),
                    ["grid = 1e+300 is out of range", "1e-100 <= dx <= 1e100"]),
    "tcontact_too_many_steps": (script("pair_coeff * * 0.9 tcontact 100"),
                                ["tcontact = 100 is out of range with the time step 1e-05",
                                 "N_c = t_c / dt = 1e+07", "1 <= N_c <= 1e6"]),
    "ncontact_absurd_time_step": (script("pair_coeff * * 0.9", extra_before_run="timestep 1e-101"),
                                  ["ncontact = 8 is out of range with the time step 1e-101",
                                   "1e-100 <= t_c <= 1e100"]),
    "wall_ncontact_absurd": (script(fix="fix w all wall/lubrication 0.9 ncontact 1e160 zplane 0.0 NULL"),
                             ["Fix wall/lubrication", "ncontact = 1e+160 is out of range", "1 <= N_c <= 1e6"]),
    "wall_tcontact_absurd": (script(fix="fix w all wall/lubrication 0.9 tcontact 1e300 zplane 0.0 NULL"),
                             ["Fix wall/lubrication", "tcontact = 1e+300 is out of range"]),
    "wall_saturation_absurd": (script(fix="fix w all wall/lubrication 0.9 viscosity 1e-3 grid 1e-4 "
                                          "saturation 1e-310 zplane 0.0 NULL"),
                               ["Fix wall/lubrication", "saturation = 1e-310 is out of range",
                                "1e-12 <= eps_1 < 1"]),
    "wall_viscosity_absurd": (script(fix="fix w all wall/lubrication 0.9 viscosity 1e300 grid 1e-4 "
                                         "zplane 0.0 NULL"),
                              ["Fix wall/lubrication", "viscosity = 1e+300 is out of range"]),
    "grid_beyond_a_radius": (script("pair_coeff * * 0.9 viscosity 1e-3 grid 8e-3"),
                             ["types 1 1: grid = 0.008 gives eps_al = 0.75 dx / R = 6", "(R = 0.001)",
                              "allowed: 0.75 dx / R <= 1"]),
    "wall_grid_beyond_a_radius": (script(fix="fix w all wall/lubrication 0.9 viscosity 1e-3 grid 8e-3 zplane 0.0 NULL"),
                                  ["Fix wall/lubrication", "grid = 0.008 gives eps_al = 0.75 dx / R = 6"]),
    "wall_tcontact_too_many_steps": (script(fix="fix w all wall/lubrication 0.9 tcontact 100 zplane 0.0 NULL"),
                                     ["Fix wall/lubrication", "tcontact = 100 is out of range with the time "
                                      "step 1e-05", "1 <= N_c <= 1e6"]),
    # The contacts take every atom's step velocity from the midpoint fix; atoms another fix moves
    # kept their set-up velocity there (a pair rebounded with 0.94 for e_d = 0.9; a sphere under
    # fix nve/sphere left a wall with 1.00002 for 0.8).
    "midpoint_beside_nve_sphere": (script(fix="group one id 1\nfix a one nve/sphere/midpoint\n"
                                              "fix b all nve/sphere"),
                                   ["Pair style lubricated/springdashpot", "fix a (nve/sphere/midpoint) must be the "
                                    "only time integration", "fix b (nve/sphere) moves atoms too"]),
    "two_midpoint_fixes": (script(fix="group one id 1\nfix a one nve/sphere/midpoint\nfix b all nve/sphere/midpoint"),
                           ["fix a (nve/sphere/midpoint) must be the only time integration",
                            "fix b (nve/sphere/midpoint) moves atoms too"]),
    "wall_midpoint_beside_nve_sphere": (script("pair_coeff * * 0.9", fix="fix w all wall/lubrication 0.9 zplane 0.0 "
                                               "NULL\nfix b all nve/sphere\nfix a all nve/sphere/midpoint")
                                        .replace("pair_style lubricated/springdashpot\npair_coeff * * 0.9\n",
                                                 "pair_style gran/hooke 2e3 NULL 50 NULL 0 0\npair_coeff * *\n"),
                                        ["Fix wall/lubrication: fix a (nve/sphere/midpoint) must be the only time "
                                         "integration", "fix b (nve/sphere) moves atoms too"]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_error_names_the_parameter(lmp, case):
    text, expected = CASES[case]
    lmp(text, check=False)
    lines = lmp.log.splitlines()
    first = next((k for k, line in enumerate(lines) if "ERROR" in line), None)
    assert first is not None, f"no ERROR for {case}:\n{lmp.log[-1500:]}"
    message = "\n".join(lines[first:first + 5])    # LAMMPS may list details below the line
    for fragment in expected:
        assert fragment in message, message
    assert "Segmentation" not in lmp.log


def test_good_input_runs(lmp):
    """The base script itself is valid, so the errors above come from the one bad value."""
    lmp(script("pair_coeff * * 0.9 ncontact 8 viscosity 1e-3 activation 0.1",
               fix="fix w all wall/lubrication 0.9 zplane 0.0 NULL"))


def test_few_contact_steps_warn(lmp):
    lmp(script("pair_coeff * * 0.9 ncontact 4"))
    assert "WARNING" in lmp.log and "N_c = 4" in lmp.log

"""LIGGGHTS's model lubricated and the LAMMPS plugin run the same kernel: the same impact must
give the same restitution (the issue asks 1e-3; both integrate with velocity Verlet, so they
agree to round-off), and that restitution must be the model's (anchors from doc/model.rst)."""
import pytest

import liggghts_scenes
import scenes


@pytest.mark.parametrize("kind", ["wall", "pair"])
@pytest.mark.parametrize("e_dry", [0.97, 0.5, 0.1])
def test_dry_restitution_matches_lammps(run, kind, e_dry):
    build = {"wall": (liggghts_scenes.wall_bounce, scenes.wall_bounce),
             "pair": (liggghts_scenes.pair_bounce, scenes.pair_bounce)}[kind]
    lig = run.lig(build[0](e_dry))
    lmp = run.lmp(build[1](e_dry))
    assert lig["e"] == pytest.approx(lmp["e"], abs=1e-3)
    assert lig["e"] == pytest.approx(e_dry, rel=0.01)           # doc/model.rst: e = e_d
    assert abs(lig["contact_steps"] - 8) <= 1                     # contact lasts N_c steps


@pytest.mark.parametrize("kind", ["wall", "pair"])
@pytest.mark.parametrize("stokes", [20, 50, 100, 1000])
def test_wet_restitution_matches_lammps(run, kind, stokes):
    mu = scenes.viscosity_for_stokes(stokes)
    build = {"wall": (liggghts_scenes.wall_bounce, scenes.wall_bounce),
             "pair": (liggghts_scenes.pair_bounce, scenes.pair_bounce)}[kind]
    lig = run.lig(build[0](0.9, mu=mu))
    lmp = run.lmp(build[1](0.9, mu=mu))
    assert lig["e"] == pytest.approx(lmp["e"], abs=1e-3)
    # The film took energy: below e_d, above zero for St >= 50 (Legendre: e/e_d = exp(-35/St)).
    assert lig["e"] < 0.9 * (1 - 0.5 * (1 - scenes.legendre(stokes)))
    if stokes >= 50:
        assert lig["e"] / 0.9 == pytest.approx(scenes.legendre(stokes), abs=0.1)


@pytest.mark.parametrize("kind", ["wall", "pair"])
def test_calibrated_contact_matches_lammps_and_the_law(run, kind):
    """lubricatedLegendre 35 is pair_coeff's legendre 35: Legendre's law at St = 20, where
    the paper's film alone falls under it (test above: only bounded from above)."""
    mu = scenes.viscosity_for_stokes(20)
    build = {"wall": (liggghts_scenes.wall_bounce, scenes.wall_bounce),
             "pair": (liggghts_scenes.pair_bounce, scenes.pair_bounce)}[kind]
    lig = run.lig(build[0](0.9, mu=mu, legendre=35))
    lmp = run.lmp(build[1](0.9, mu=mu, extra="legendre 35"))
    assert lig["e"] == pytest.approx(lmp["e"], abs=1e-3)
    assert lig["e"] / 0.9 == pytest.approx(scenes.legendre(20), abs=0.05)


@pytest.mark.parametrize("kind", ["wall", "pair"])
def test_grid_activation_below_saturation_gives_no_film(run, kind):
    """0.75 dx / R = 0.01 < eps_1 = 0.05: no film (the kernel's rule), so the dry rebound."""
    mu, dx = scenes.viscosity_for_stokes(20), 0.01 * scenes.R / 0.75
    build = {"wall": (liggghts_scenes.wall_bounce, scenes.wall_bounce),
             "pair": (liggghts_scenes.pair_bounce, scenes.pair_bounce)}[kind]
    lig = run.lig(build[0](0.9, dt_ru=0.005, mu=mu, grid=dx, saturation=0.05))
    lmp = run.lmp(build[1](0.9, dt_ru=0.005, extra=f"viscosity {mu} grid {dx} saturation 0.05"))
    assert lig["e"] == pytest.approx(lmp["e"], abs=1e-3)
    assert lig["e"] == pytest.approx(0.9, rel=1e-3)


def test_unequal_masses_match_lammps(run):
    mu = scenes.viscosity_for_stokes(100)
    lig = run.lig(liggghts_scenes.pair_bounce(0.7, mass_ratio=3.0, radius_ratio=0.5, mu=mu))
    lmp = run.lmp(scenes.pair_bounce(0.7, mass_ratio=3.0, radius_ratio=0.5, mu=mu))
    assert lig["e"] == pytest.approx(lmp["e"], abs=1e-3)


def test_no_rebound_at_stokes_5(run):
    lig = run.lig(liggghts_scenes.wall_bounce(0.9, mu=scenes.viscosity_for_stokes(5)))
    assert lig["e"] < 0.01


def test_mesh_wall_bounces_like_the_primitive_wall(run, scratch):
    """fix wall/gran ... mesh: a plane of two triangles, hit on their shared edge, wet and dry."""
    (scratch / "plane.stl").write_text(PLANE_STL)
    for mu in (0.0, scenes.viscosity_for_stokes(50)):
        script = liggghts_scenes.wall_bounce(0.9, mu=mu)
        primitive = run.lig(script)
        mesh = run.lig(script.replace(
            "fix wall all wall/gran model lubricated primitive type 2 zplane 0.0",
            "fix cad all mesh/surface file plane.stl type 2\n"
            "fix wall all wall/gran model lubricated mesh n_meshes 1 meshes cad"))
        assert mesh["e"] == pytest.approx(primitive["e"], rel=1e-9, abs=1e-12)


PLANE_STL = """solid plane
facet normal 0 0 1
 outer loop
  vertex -0.01 -0.01 0
  vertex 0.01 -0.01 0
  vertex 0.01 0.01 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex -0.01 -0.01 0
  vertex 0.01 0.01 0
  vertex -0.01 0.01 0
 endloop
endfacet
endsolid plane
"""


@pytest.mark.parametrize("grid_change", [False, True])
def test_contact_history_keeps_the_film_lambda(run, grid_change):
    """With LIGGGHTS's tangential history a contact keeps lambda(eps_al) of its film in its history
    (keyed by eps_al; normal_model_lubricated.h, history_lambda), without one it is computed at
    every step. A head-on impact (no tangential force) must move the same both ways, to the bit,
    also where the grid spacing (so eps_al) changes in the middle of the contact."""
    grid = 1e-4
    base = liggghts_scenes.pair_bounce(0.9, mu=scenes.viscosity_for_stokes(50), grid=grid)
    steps = int(base.split("\nrun ")[1].split("\n")[0])
    friction = "fix mf all property/global coefficientFriction peratomtypepair 2 0.3 0.3 0.3 0.3\n"
    if grid_change:    # the contact starts at step 43 and lasts 8 steps
        base = base.replace(f"\nrun {steps}\n", f"\nrun 46\nfix m4 all property/global lubricatedGridSpacing "
                                                 f"scalar {2 * grid}\nrun {steps - 46}\n")
    results = {}
    for tangential in ("history", "no_history"):
        script = base.replace("pair_style gran model lubricated\n",
                              friction + f"pair_style gran model lubricated tangential {tangential}\n")
        assert f"tangential {tangential}" in script
        results[tangential] = run.lig(script + "\n".join(
            f'print "RESULT {q}{k} $({q}[{k}])"' for k in (1, 2) for q in ("x", "vx")) + "\n")
    assert 0.0 < results["history"]["e"] < 0.9
    assert results["history"] == results["no_history"]

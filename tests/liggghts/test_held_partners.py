"""Partners a contact cannot move, and rigid bodies, in LIGGGHTS (issue 17, "Frozen partners").

The model takes the mass LIGGGHTS's own overlap branch gives a contact (sidata.meff: the
partner's mass alone against an atom of fix freeze's group, a body's mass for an atom of
fix rigid) and now computes the same mass itself where LIGGGHTS gives none, before and after
overlap (the film and the step-exact contact's first and last steps, surfacesClose()). With
one mass throughout, the step-exact contact gives e_d to round-off (relative tolerance 1e-9,
as the LAMMPS plugin's tests)."""
import pytest

import liggghts_scenes
import scenes


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("hold", ["unintegrated", "move", "setforce"])
@pytest.mark.parametrize("e_dry", [1.0, 0.9, 0.5])
def test_partner_no_integrator_moves_rebounds_with_e_dry(run, e_dry, hold, nprocs):
    """A partner left out of fix nve/sphere, moved by fix move (at rest) or held by fix setforce
    0 0 0 is immovable too, as in the LAMMPS plugin (LIGGGHTS's own models keep the reduced mass there; with it, measured
    before: e = 1.0002, 0.928 and 0.621 at e_d = 1, 0.9 and 0.5, above e_d)."""
    result = run.lig(liggghts_scenes.frozen_pair(e_dry, hold=hold), nprocs=nprocs)
    assert result["e"] == pytest.approx(e_dry, rel=1e-9)
    assert result["v2"] == 0.0


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("e_dry", [1.0, 0.9, 0.5])
def test_frozen_partner_rebounds_with_e_dry(run, e_dry, nprocs):
    """A sphere in fix freeze's group moves with no contact: m_e is the mover's mass, as
    LIGGGHTS's own overlap branch has it; the film and the step-exact contact's entry now use
    it too (before: e = 0.8992 at e_d 0.9, 0.511 at 0.5). Step-exact: e_d to round-off."""
    result = run.lig(liggghts_scenes.frozen_pair(e_dry), nprocs=nprocs)
    assert result["e"] == pytest.approx(e_dry, rel=1e-9)
    assert result["v2"] == 0.0


@pytest.mark.parametrize("e_dry", [0.9, 0.5])
def test_wet_frozen_partner_matches_lammps(run, e_dry):
    """Wet (St 50 of the free pair): the held partner's film with m_e = m_i, as the LAMMPS
    plugin's contact masses give it (measured: the same to 1e-15; the free pair 0.445)."""
    from test_frozen_partners import frozen_pair
    mu = scenes.viscosity_for_stokes(50)
    ours = run.lig(liggghts_scenes.frozen_pair(e_dry, mu=mu))
    lammps = run.lmp(frozen_pair(e_dry, "freeze", wet=f"viscosity {mu} activation {scenes.EPS_AL}")
                     .replace("${newton}", "on"))
    assert ours["e"] == pytest.approx(lammps["e"], rel=1e-9)
    free = run.lig(liggghts_scenes.frozen_pair(e_dry, mu=mu, frozen=False))
    assert ours["e"] > free["e"]


@pytest.mark.parametrize("nprocs", [1, 2])
@pytest.mark.parametrize("e_dry", [0.9, 0.5])
def test_rigid_body_takes_its_mass(run, e_dry, nprocs):
    """A sphere against a body of two spheres (fix rigid single): m_e = m 2m / 3m, e = e_d
    (measured 1e-13)."""
    assert run.lig(liggghts_scenes.rigid_body_hit(e_dry), nprocs=nprocs)["e"] == pytest.approx(e_dry, rel=1e-9)


@pytest.mark.parametrize("force", ["NULL 0.0 0.0", "0.0 0.0 0.0 region far"])
def test_only_setforce_all_zero_holds(run, force):
    """With a NULL component or a region the fix may let the atom move, and here it does (x is
    free, the region is elsewhere): the free pair's e_d, the partner pushed."""
    script = liggghts_scenes.frozen_pair(0.9, hold="setforce").replace(
        "setforce 0.0 0.0 0.0", f"setforce {force}").replace(
        "group base id 2", f"group base id 2\nregion far block 0 {scenes.R} {4 * scenes.R} {5 * scenes.R} 0 "
                           f"{scenes.R} units box")
    result = run.lig(script)
    assert result["e"] == pytest.approx(0.9, rel=1e-9) and result["v2"] > 0.0

// A pair's films as a link of the coupled film solve (lubricated/film_link.h): the normal film's
// coefficient is the film law's (Lubrication::damping), the shear film's raw coefficient is the
// one shear_film_force integrates exactly over a step (equal as the step tends to 0), and both
// vanish outside the film. A wall's films as a link: the same laws at the wall's film radius, and
// the link's force at the sphere's velocities is the contact's film force for a wall that
// translates and turns.
#include "lubricated/film_link.h"
#include "lubricated/wall_motion.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

namespace {

Coefficients wet_frictional()
{
  Coefficients c;
  c.e_dry = 0.9;
  c.viscosity = 1e-3;
  c.eps_activation = 0.1;
  c.friction = 0.3;
  return c;
}

}    // namespace

TEST(FilmLink, CoefficientsAreTheFilmLaws)
{
  const double dt = 1e-9, ri = 1e-3, rj = 1.4e-3;
  const ContactModel m = make_contact_model(wet_frictional(), Partner::particle, dt);
  const FilmRadius radius = film_radius_pair(ri, rj);
  const double reduced_radius = ri * rj / (ri + rj), m_t = tangential_mass_ratio * 1e-5;
  const Vec3 n{0.0, 0.6, 0.8}, slip{1.0, 0.0, 0.0};
  for (double eps : {5e-2, 1e-2, 1e-3, 1e-4, -5e-3}) {
    const double r = ri + rj + eps * radius.value;
    const FilmLink link = pair_film_link(m, 3, 7, n, r, ri, rj);
    EXPECT_EQ(link.i, 3);
    EXPECT_EQ(link.j, 7);
    // eps recomputed from r: equal to its rounding.
    EXPECT_NEAR(link.normal_damping, m.normal.lubrication.damping(eps, radius.value), 1e-9 * link.normal_damping);
    EXPECT_GT(link.normal_damping, 0.0);
    // shear_film_force's exact integration: -c_t (1 - a/2 + ...) s, a = c_t dt / m_t ~ 1e-7.
    const Lubrication &film = m.normal.lubrication;
    const Vec3 f = shear_film_force(m.tangential, slip, eps, film.activation_for(radius.value), film.eps_saturation,
                                    film.eps_release, reduced_radius, m_t);
    EXPECT_NEAR(link.shear_damping, -f.x, 1e-6 * link.shear_damping) << eps;
  }
  // Out of the film (beyond eps_al, below eps_2): no coefficients.
  for (double eps : {0.2, -0.02}) {
    const FilmLink link = pair_film_link(m, 0, 1, n, ri + rj + eps * radius.value, ri, rj);
    EXPECT_EQ(link.normal_damping, 0.0);
    EXPECT_EQ(link.shear_damping, 0.0);
  }
  // Without a shear film the shear coefficient is 0; dry: both.
  Coefficients no_shear = wet_frictional();
  no_shear.shearfilm = 0;
  const ContactModel ns = make_contact_model(no_shear, Partner::particle, dt);
  EXPECT_EQ(pair_film_link(ns, 0, 1, n, ri + rj + 1e-3 * radius.value, ri, rj).shear_damping, 0.0);
  Coefficients dry = wet_frictional();
  dry.viscosity = 0.0;
  const FilmLink dry_link = pair_film_link(make_contact_model(dry, Partner::particle, dt), 0, 1, n, ri + rj, ri, rj);
  EXPECT_EQ(dry_link.normal_damping, 0.0);
  EXPECT_EQ(dry_link.shear_damping, 0.0);
}

namespace {

double norm(const Vec3 &a)
{
  return std::sqrt(dot(a, a));
}

Vec3 near(const Vec3 &a, const Vec3 &b, double tolerance)
{
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
  return a;
}

}    // namespace

TEST(FilmLink, WallLinkIsTheContactsFilmsOfAMovingTurningWall)
{
  const double dt = 1e-9, r = 1e-3;
  Coefficients c = wet_frictional();
  c.shearfilm = 1;
  const ContactModel m = make_contact_model(c, Partner::wall, dt);
  const Lubrication &film = m.normal.lubrication;
  RigidWallMotion wall;
  wall.velocity = {0.02, -0.01, 0.005}, wall.spin = {3.0, -1.0, 7.0}, wall.point = {0.01, 0.0, -0.02};
  const Vec3 tilted{0.2, -0.3, 0.9};
  const Vec3 n = scaled(tilted, 1.0 / norm(tilted));
  const Vec3 v{0.1, 0.05, -0.2}, omega{10.0, -20.0, 5.0};
  for (double eps : {5e-2, 1e-2, 1e-3}) {
    const double gap = eps * r;
    const Vec3 x{0.003, 0.001, 0.002};
    const Vec3 contact_point = minus(x, scaled(n, r + gap));
    const RelativeMotion rel = relative_to_wall(wall, v, omega, r, n, contact_point);
    const Vec3 wall_velocity = wall_velocity_at_contact(v, omega, r, n, rel.u_n, &rel.dv, &rel.omega);
    const FilmLink link = wall_film_link(m, 4, n, gap, FilmRadius(r), r, wall_velocity);
    EXPECT_EQ(link.i, 4);
    EXPECT_EQ(link.j, -1);
    EXPECT_NEAR(link.normal_damping, film.damping(eps, r), 1e-12 * link.normal_damping);
    // The contact's shear film at a step short enough to be the linear damper -c_t s.
    const Vec3 slip = film_surface_slip(n, rel.dv, r, rel.omega, 0.0, {});
    const Vec3 shear = shear_film_force(m.tangential, slip, eps, film.activation_for(r), film.eps_saturation,
                                        film.eps_release, r, tangential_mass_ratio * 1e-5);
    EXPECT_GT(link.shear_damping, 0.0);
    // At the sphere's velocities (the wall's counted): the normal film -c_n u_n n and the shear
    // film, with its torque -R n x F_t.
    const double w[film_dofs] = {v.x, v.y, v.z, omega.x, omega.y, omega.z};
    const double radius[1] = {r};
    FilmAtoms atoms;
    atoms.owned = atoms.total = 1, atoms.radius = radius;
    FilmLink at_zero = link;
    at_zero.i = 0;
    const FilmLinkForce f = film_link_force(at_zero, atoms, w, true);
    const Vec3 expected = plus(scaled(n, -link.normal_damping * rel.u_n), shear);
    near(f.force_i, expected, 1e-6 * norm(expected));
    near(f.torque_i, scaled(cross(n, shear), -r), 1e-6 * r * norm(shear));
  }
  // Without tangential parts only the normal velocity is kept.
  const Vec3 normal_only = wall_velocity_at_contact(v, omega, r, n, 0.03, nullptr, nullptr);
  near(normal_only, scaled(n, dot(v, n) - 0.03), 1e-15);
}

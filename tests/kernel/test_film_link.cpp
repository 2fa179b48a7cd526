// A pair's films as a link of the coupled film solve (lubricated/film_link.h): the normal film's
// coefficient is the film law's (Lubrication::damping), the shear film's raw coefficient is the
// one shear_film_force integrates exactly over a step (equal as the step tends to 0), and both
// vanish outside the film.
#include "lubricated/film_link.h"

#include <gtest/gtest.h>

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

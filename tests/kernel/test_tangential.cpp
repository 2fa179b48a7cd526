// Tangential kernel (tangential.h): coefficients, stick recurrence, Coulomb cap, film, rolling.
#include "lubricated/contact.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

namespace {

Coefficients frictional(double e_t, double mu)
{
  Coefficients c;
  c.e_dry = 0.9;
  c.n_contact = 8;
  c.friction = mu;
  c.e_tangential = e_t;
  return c;
}

}    // namespace

TEST(Tangential, OffByDefault)
{
  Coefficients c;
  c.e_dry = 0.9;
  EXPECT_FALSE(c.tangential());
  EXPECT_FALSE(make_contact_model(c, Partner::particle, 1e-5).tangential.active());
  EXPECT_DOUBLE_EQ(c.tangential_restitution(), 0.9);    // e_t defaults to e_d
}

TEST(Tangential, StickingOscillatorReversesSlipWithEt)
{
  // Integrate an isolated sticking contact with the per-step force for exactly N_c steps
  // (entry on a step): the slip comes back as -e_t s0, the spring relaxed.
  for (double e_t : {0.9, 0.5, 0.1}) {
    const double dt = 1.0, m_t = 2.0;
    const TangentialModel m = make_contact_model(frictional(e_t, 1e9), Partner::particle, dt).tangential;
    Vec3 delta, n{0, 0, 1};
    double s = 1.0;
    for (int k = 0; k < 8; ++k) {
      const Vec3 f = tangential_contact_force(m, delta, n, Vec3{s, 0, 0}, m_t, 1.0);
      s += f.x * dt / m_t;
    }
    EXPECT_NEAR(s, -e_t, 1e-12) << e_t;
  }
}

TEST(Tangential, CoulombCapsTheForceAndTruncatesTheSpring)
{
  const TangentialModel m = make_contact_model(frictional(0.5, 0.3), Partner::particle, 1e-5).tangential;
  Vec3 delta{1e-3, 0, 0}, n{0, 0, 1};
  const Vec3 f = tangential_contact_force(m, delta, n, Vec3{0.1, 0, 0}, 1e-3, 2.0);
  EXPECT_NEAR(std::sqrt(dot(f, f)), 0.3 * 2.0, 1e-12);
  EXPECT_LT(f.x, 0.0);    // against the slip
  // The truncated spring reproduces the capped force: -m_t (k' delta + c' s) = f.
  EXPECT_NEAR(-1e-3 * (m.stiffness_step * delta.x + m.damping_step * 0.1), f.x, 1e-12);
}

TEST(Tangential, ElongationIsRotatedIntoTheTangentPlaneKeepingItsLength)
{
  const TangentialModel m = make_contact_model(frictional(0.5, 1e30), Partner::particle, 1e-5).tangential;
  Vec3 delta{1.0, 0.0, 0.5}, n{0, 0, 1};
  tangential_contact_force(m, delta, n, Vec3{}, 1.0, 1.0);
  EXPECT_NEAR(delta.z, 0.0, 1e-15);
  EXPECT_NEAR(delta.x, std::sqrt(1.25), 1e-14);
  // A small rotation (one step's, where the series replaces the square roots): the same.
  Vec3 small{1.0, 0.0, 3e-3};
  tangential_contact_force(m, small, n, Vec3{}, 1.0, 1.0);
  EXPECT_NEAR(small.z, 0.0, 1e-15);
  EXPECT_NEAR(small.x, std::sqrt(1.0 + 9e-6), 1e-15);
}

TEST(Tangential, ShearFilmNeverReversesTheSlipAndVanishesOutsideTheFilm)
{
  Coefficients c = frictional(0.5, 0.3);
  c.viscosity = 1e3;    // absurdly viscous
  c.eps_activation = 0.1;
  const TangentialModel m = make_contact_model(c, Partner::particle, 1.0).tangential;
  ASSERT_TRUE(m.film_active());
  const Vec3 s{2.0, 0, 0};
  const Vec3 f = shear_film_force(m, s, 0.01, 0.1, 1e-3, -1e-2, 1.0, 1.0);
  EXPECT_LT(f.x, 0.0);
  EXPECT_GE(s.x + f.x * 1.0 / 1.0, 0.0);    // at most stops it within the step
  EXPECT_EQ(shear_film_force(m, s, 0.2, 0.1, 1e-3, -1e-2, 1.0, 1.0).x, 0.0);
  EXPECT_EQ(shear_film_force(m, s, -0.02, 0.1, 1e-3, -1e-2, 1.0, 1.0).x, 0.0);
  // Continuous at activation: ln(eps_al / eps) -> 0.
  EXPECT_NEAR(shear_film_force(m, s, 0.1 * (1 - 1e-9), 0.1, 1e-3, -1e-2, 1.0, 1.0).x, 0.0, 1e-4);
}

TEST(Tangential, RollingTorqueOpposesRollingAndCannotReverseIt)
{
  Coefficients c = frictional(0.5, 0.3);
  c.rolling_friction = 0.1;
  const TangentialModel m = make_contact_model(c, Partner::particle, 1e-5).tangential;
  const Vec3 n{0, 0, 1}, w{0, 3.0, 0.7};    // the twist (along n) is not resisted
  const Vec3 t = rolling_torque(m, n, w, 1e-3, 1.0, 10.0);
  EXPECT_NEAR(t.y, -0.1 * 1e-3 * 10.0, 1e-15);
  EXPECT_EQ(t.z, 0.0);
  const Vec3 capped = rolling_torque(m, n, w, 1e-3, 1e-9, 10.0);
  EXPECT_NEAR(capped.y, -1e-9 * 3.0 / 1e-5, 1e-18);
}

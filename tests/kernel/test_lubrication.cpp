// Lubrication law of doc/model.rst, "Lubrication film": the lambda expansions, the activation at
// eps_al, the saturation below eps_1 and the release below eps_2.
#include "lubricated/normal_model.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

TEST(Lambda, PrintedExpansions)
{
  const double eps = 0.01, l = std::log(eps);
  EXPECT_DOUBLE_EQ(particle_particle_expansion.lambda(eps), 0.5 / eps - 0.45 * l - 3.0 / 56.0 * eps * l + 1.346);
  EXPECT_DOUBLE_EQ(particle_wall_expansion.lambda(eps), 1.0 / eps - 0.2 * l - 1.0 / 21.0 * eps * l + 0.9713);
  // Leading terms: Brenner's 1/eps at a wall, half of it between equal spheres.
  EXPECT_NEAR(particle_wall_expansion.lambda(1e-8) * 1e-8, 1.0, 1e-6);
  EXPECT_NEAR(particle_particle_expansion.lambda(1e-8) * 1e-8, 0.5, 1e-6);
}

TEST(Lambda, DecreasingOverTheAllowedActivationRange)
{
  for (double eps = 1e-4; eps < 1.0; eps *= 1.1) {
    EXPECT_GT(particle_wall_expansion.lambda(eps), particle_wall_expansion.lambda(eps * 1.1));
    EXPECT_GT(particle_particle_expansion.lambda(eps), particle_particle_expansion.lambda(eps * 1.1));
  }
}

class Film : public ::testing::TestWithParam<Partner> {};

TEST_P(Film, ZonesOfTheActivationTable)
{
  const Partner partner = GetParam();
  const double mu = 1e-3, R = 2e-3, eps_al = 0.1, eps1 = 1e-3, eps2 = -1e-2;
  const Lubrication lub = make_lubrication(partner, mu, eps_al, 0.0, eps1, eps2);
  const double six_pi_mu_R = 6.0 * pi * mu * R;

  // Far: nothing. Just inside eps_al: continuous, tends to zero.
  EXPECT_EQ(lub.damping(eps_al, R), 0.0);
  EXPECT_EQ(lub.damping(0.5, R), 0.0);
  EXPECT_NEAR(lub.damping(eps_al * (1 - 1e-9), R), 0.0, 1e-6 * six_pi_mu_R);
  // Lubrication zone: the formula.
  const double eps = 0.02;
  EXPECT_DOUBLE_EQ(lub.damping(eps, R), six_pi_mu_R * (lambda_of(partner, eps) - lambda_of(partner, eps_al)));
  // Saturated between eps_2 and eps_1, also in overlap, equal to its eps_1 value.
  const double sat = six_pi_mu_R * (lambda_of(partner, eps1) - lambda_of(partner, eps_al));
  for (double e : {eps1, 5e-4, 1e-6, 0.0, -1e-3, -0.0099})
    EXPECT_DOUBLE_EQ(lub.damping(e, R), sat);
  // Continuous at eps_1 from above.
  EXPECT_NEAR(lub.damping(eps1 * (1 + 1e-9), R), sat, 1e-6 * sat);
  // Deep overlap: released.
  EXPECT_EQ(lub.damping(eps2, R), 0.0);
  EXPECT_EQ(lub.damping(-0.5, R), 0.0);
}

TEST_P(Film, ForceOpposesRelativeNormalMotion)
{
  Coefficients c;
  c.e_dry = 0.9;
  c.viscosity = 1e-3;
  c.eps_activation = 0.1;
  const NormalModel m = make_normal_model(c, GetParam(), 1e-4);
  EXPECT_GT(normal_force(m, 1e-5, 1e-3, 1.0, -0.1).lubrication, 0.0);    // approach: pushed apart
  EXPECT_LT(normal_force(m, 1e-5, 1e-3, 1.0, +0.1).lubrication, 0.0);    // separation: held back
  EXPECT_EQ(normal_force(m, 1e-5, 1e-3, 1.0, 0.0).lubrication, 0.0);
  EXPECT_DOUBLE_EQ(m.reach(1e-3), 1e-4);
}

TEST_P(Film, GridSpacingSetsActivationPerRadius)
{
  // Breugem: eps_al = 0.75 dx / R.
  const Lubrication lub = make_lubrication(GetParam(), 1e-3, 0.0, 1e-3, 1e-3, -1e-2);
  for (double R : {2e-3, 8e-3}) {
    const double eps_al = 0.75 * 1e-3 / R;
    EXPECT_DOUBLE_EQ(lub.activation_for(R), eps_al);
    EXPECT_EQ(lub.damping(eps_al, R), 0.0);
    EXPECT_GT(lub.damping(0.9 * eps_al, R), 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(BothPartners, Film, ::testing::Values(Partner::particle, Partner::wall));

TEST(LubricationRadius, EqualSpheresGiveThePapersRadius)
{
  EXPECT_DOUBLE_EQ(film_radius_pair(1.5, 1.5).value, 1.5);
  // Leading term 6 pi mu R^2 u / (2 h) scales with the reduced radius squared; the radius and
  // its inverse from one division.
  const double R1 = 1.0, R2 = 3.0, reduced = R1 * R2 / (R1 + R2);
  const FilmRadius film = film_radius_pair(R1, R2);
  EXPECT_DOUBLE_EQ(film.value, 2.0 * reduced);
  EXPECT_DOUBLE_EQ(film.inverse, 1.0 / (2.0 * reduced));
}

TEST(Dry, ZeroViscosityRunsNoLubrication)
{
  Coefficients c;
  c.e_dry = 0.9;
  const NormalModel m = make_normal_model(c, Partner::particle, 1e-4);
  EXPECT_FALSE(m.lubrication.active());
  EXPECT_EQ(m.reach(1.0), 0.0);
  EXPECT_EQ(normal_force(m, -1e-4, 1.0, 1.0, -1.0).lubrication, 0.0);
}

TEST_P(Film, IntegralIsTheAntiderivativeOfTheDamping)
{
  const Partner partner = GetParam();
  const double R = 1e-3;
  const Lubrication lub = make_lubrication(partner, 1e-3, 0.1, 0.0, 1e-3, -1e-2);
  const double scale = lub.six_pi_mu * R;
  // -dP/deps = c_l / (6 pi mu R) in every zone (central differences away from the kinks).
  for (double eps : {0.09, 0.05, 0.01, 0.002, 5e-4, 0.0, -5e-3, -0.02, 0.2}) {
    const double h = 1e-7;
    const double slope = (lub.film_integral(eps - h, R) - lub.film_integral(eps + h, R)) / (2 * h);
    EXPECT_NEAR(slope, lub.damping(eps, R) / scale, 1e-5 * (1 + slope)) << "eps=" << eps;
  }
  // Continuous at every zone boundary.
  for (double edge : {0.1, 1e-3, -1e-2})
    EXPECT_NEAR(lub.film_integral(edge * (1 + 1e-12), R), lub.film_integral(edge * (1 - 1e-12), R), 1e-7);
  EXPECT_EQ(lub.film_integral(0.1, R), 0.0);
}

TEST_P(Film, ImpulseOfAPassTelescopesWhateverTheSteps)
{
  const Lubrication lub = make_lubrication(GetParam(), 1e-3, 0.1, 0.0, 1e-3, -1e-2);
  const double R = 1e-3, start = 0.15 * R, end = -0.005 * R;
  for (int steps : {1, 7, 1000}) {
    double total = 0.0;
    for (int k = 0; k < steps; ++k) {
      const double a = start + (end - start) * k / steps, b = start + (end - start) * (k + 1) / steps;
      total += lub.impulse(a, b, R);
    }
    EXPECT_NEAR(total, lub.impulse(start, end, R), 1e-12 * lub.impulse(start, end, R));
  }
  EXPECT_GT(lub.impulse(start, end, R), 0.0);    // approaching: pushed apart
  EXPECT_LT(lub.impulse(end, start, R), 0.0);    // separating: held back
}

TEST_P(Film, GridSpacingBelowSaturationGivesNoFilm)
{
  // 0.75 dx / R = 5e-4 < eps_1 = 1e-3: lambda(eps_1) - lambda(eps_al) would be negative, a film
  // pulling the surfaces together on approach; the contact gets no film instead.
  const double R = 1.5e-3, dx = 1e-6;
  const Lubrication lub = make_lubrication(GetParam(), 1e-3, 0.0, dx, 1e-3, -1e-2);
  EXPECT_EQ(lub.activation_for(R), 1e-3);
  for (double eps : {2e-3, 1e-3, 7e-4, 1e-4, 0.0, -5e-3}) {
    EXPECT_EQ(lub.damping(eps, R), 0.0) << "eps " << eps;
    EXPECT_EQ(lub.impulse((eps + 1e-4) * R, eps * R, R), 0.0) << "eps " << eps;
  }
  // A smaller contact of the same scene still has its film.
  EXPECT_GT(lub.damping(0.5 * 0.75 * dx / 1e-4, 1e-4), 0.0);
}

TEST_P(Film, GridSpacingGivesTheSameImpulseAsItsActivationGap)
{
  // dx with 0.75 dx / R = 0.1: the per-contact path (and its saturated shortcut) must agree
  // with the per-type-pair constants of activation 0.1, in every zone.
  const double R = 1e-3;
  const Lubrication fixed = make_lubrication(GetParam(), 1e-3, 0.1, 0.0, 1e-3, -1e-2);
  const Lubrication grid = make_lubrication(GetParam(), 1e-3, 0.0, 0.1 * R / 0.75, 1e-3, -1e-2);
  const double gaps[][2] = {{0.15, 0.05},   {0.05, 0.004}, {0.004, 5e-4}, {5e-4, -3e-3},
                            {-3e-3, -2e-2}, {-2e-2, 5e-4}, {8e-4, 2e-4}};
  for (const auto &g : gaps) {
    const double expected = fixed.impulse(g[0] * R, g[1] * R, R);
    EXPECT_NEAR(grid.impulse(g[0] * R, g[1] * R, R), expected, 1e-12 * std::fabs(expected) + 1e-30)
        << g[0] << " -> " << g[1];
  }
}

TEST(FilmImpulse, NeverReversesTheRelativeMotion)
{
  Coefficients c;
  c.e_dry = 0.9;
  c.viscosity = 1e6;    // St ~ 1e-7
  c.eps_activation = 0.1;
  const double dt = 1e-4, m_e = 1e-6, u = -0.1;
  const NormalModel m = make_normal_model(c, Partner::wall, dt);
  const NormalForce f = normal_force(m, 1e-5, 1e-3, m_e, u);
  EXPECT_DOUBLE_EQ(f.lubrication * dt, m_e * -u);    // stops it, exactly, no more
}

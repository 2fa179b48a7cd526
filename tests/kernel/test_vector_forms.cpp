// The branch-free forms the pair style's vectorised loops use (film_force_apart for pairs that
// stay apart over a step, sustained_contact_force, log_inline): the same forces as
// normal_force() where they apply, to rounding.
#include "lubricated/inline_log.h"
#include "lubricated/normal_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace lubricated;

namespace {

// Distance of a from b in units in the last place of b.
double ulps(double a, double b)
{
  if (a == b) return 0.0;
  return std::fabs(a - b) / (std::nextafter(std::fabs(b), INFINITY) - std::fabs(b));
}

}    // namespace

TEST(InlineLog, WithinFourUlpsOfTheLibraryOverTheNormalRange)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-708.0, 709.0), near_one(-1e-3, 1e-3);
  double worst = 0.0;
  for (int n = 0; n < 200000; ++n) {
    const double x = n % 4 == 0 ? 1.0 + near_one(rng) : std::exp(exponent(rng));
    // Close to 1 the logarithm is small: count its error against the size of x - 1 instead.
    const double reference = std::log(x);
    const double error = std::fabs(x - 1.0) < 0.5
        ? std::fabs(log_inline(x) - reference) / std::fabs(x - 1.0) / 2.220446049250313e-16
        : ulps(log_inline(x), reference);
    worst = std::max(worst, error);
  }
  EXPECT_LE(worst, 4.0);
  EXPECT_EQ(log_inline(1.0), 0.0);
  for (int k = -1022; k <= 1023; k += 89)
    EXPECT_LE(ulps(log_inline(std::ldexp(1.0, k)), k * std::log(2.0)), 1.0) << "2^" << k;
}

// Random wet, exactly integrated pairs, apart over the step (gap >= 0 and gap - u_n dt >= 0,
// from inside the saturated film to past eps_al): the film-only force equals normal_force's
// film (and normal_force has no contact part there). The two differ only by the rounding of
// their logarithms, amplified by the difference P(after) - P(before) of film integrals: the
// tolerance is 1e-13 of the size of the terms of that difference.
TEST(FilmApart, EqualsTheFilmOfNormalForce)
{
  std::mt19937_64 rng(2026);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, uniform(0.0, 1.0)); };
  int compared = 0, in_film = 0, clamped = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Coefficients c;
    c.e_dry = log_uniform(1e-3, 1.0);
    c.viscosity = log_uniform(1e-6, 10.0);
    c.eps_saturation = log_uniform(1e-6, 0.05);
    const bool grid = trial % 3 == 0;
    if (grid) c.grid_spacing = log_uniform(1e-6, 1e-1);
    else c.eps_activation = uniform(1.5 * c.eps_saturation, 1.0);
    c.eps_release = uniform(-0.1, 0.0);
    if (trial % 4 == 0) c.eps_release = 0.0, c.legendre = 35.0;
    ASSERT_EQ(validate(c), "");
    const double dt = log_uniform(1e-8, 1e-2);
    const NormalModel m = make_normal_model(c, Partner::particle, dt);
    for (int state = 0; state < 100; ++state) {
      const double ri = log_uniform(1e-6, 1e-1), rj = ri * log_uniform(0.2, 5.0);
      const FilmRadius radius = film_radius_pair(ri, rj);
      const double mass = log_uniform(1e-12, 1.0);
      const double eps_al = m.lubrication.activation_for(radius);
      const double gap = radius.value * log_uniform(1e-3 * c.eps_saturation, 2.0 * eps_al);
      // |u_n| dt from a creeping fraction of the gap up to the whole gap (closing) or beyond.
      const double u_n = gap / dt * log_uniform(1e-9, 1.0) * (state % 2 ? 1.0 : -1.0);
      const NormalForce expected = normal_force(m, gap, radius, mass, u_n);
      ASSERT_EQ(expected.contact, 0.0);
      const double film = grid ? film_force_apart<true>(m.lubrication, gap, radius, mass, u_n, dt, 1.0 / dt)
                               : film_force_apart<false>(m.lubrication, gap, radius, mass, u_n, dt, 1.0 / dt);
      const Lubrication::Activation al = m.lubrication.activation(radius);
      const double terms = std::fabs(al.integral) + std::fabs(m.lubrication.integral_saturated) +
          (std::fabs(al.lambda) + std::fabs(m.lubrication.lambda_saturated)) * (al.eps + 0.1);
      const double tolerance = 1e-13 * m.lubrication.six_pi_mu * radius.value * radius.value * terms / dt;
      ASSERT_NEAR(film, expected.lubrication, tolerance)
          << "eps " << gap / radius.value << " eps_al " << al.eps << " u_n dt / gap " << u_n * dt / gap;
      if (gap < eps_al * radius.value) ++in_film;
      if (std::fabs(expected.lubrication) * dt >= mass * std::fabs(u_n) * (1.0 - 1e-12)) ++clamped;
      // Beyond eps_al before and after the step the film is exactly zero.
      if (gap - u_n * dt >= eps_al * radius.value && gap >= eps_al * radius.value) {
        ASSERT_EQ(film, 0.0);
      }
      ++compared;
    }
  }
  // The draws reach the film, its saturated part and the cap on the impulse.
  EXPECT_EQ(compared, 40000);
  EXPECT_GT(in_film, 10000);
  EXPECT_GT(clamped, 100);
}

// Random exactly integrated pairs, dry and wet, in overlap now and a step ago: where
// sustained_contact_force says the contact is sustained, contact and energy equal
// normal_force's and the film does to rounding (both ends saturated: no logarithm of the gap).
TEST(SustainedContact, EqualsNormalForceWhereItApplies)
{
  std::mt19937_64 rng(11);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, uniform(0.0, 1.0)); };
  int sustained_count = 0, other_count = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Coefficients c;
    c.e_dry = log_uniform(1e-3, 1.0);
    c.n_contact = log_uniform(1.0, 64.0);
    const bool grid = trial % 3 == 0;
    if (trial % 4 != 0) {
      c.viscosity = log_uniform(1e-6, 10.0);
      c.eps_saturation = log_uniform(1e-6, 0.05);
      if (grid) c.grid_spacing = log_uniform(1e-6, 1e-1);
      else c.eps_activation = uniform(1.5 * c.eps_saturation, 1.0);
      c.eps_release = uniform(-0.1, 0.0);
    }
    ASSERT_EQ(validate(c), "");
    const double dt = log_uniform(1e-8, 1e-2);
    const NormalModel m = make_normal_model(c, Partner::particle, dt);
    for (int state = 0; state < 100; ++state) {
      const double ri = log_uniform(1e-6, 1e-1), rj = ri * log_uniform(0.2, 5.0);
      const FilmRadius radius = film_radius_pair(ri, rj);
      const double mass = log_uniform(1e-12, 1.0);
      const double gap = -radius.value * log_uniform(1e-9, 0.2);
      // Overlap rates from creeping to leaving the overlap within the step, both signs.
      const double u_n = -gap / dt * log_uniform(1e-6, 3.0) * (state % 2 ? 1.0 : -1.0);
      bool sustained = false;
      const NormalForce vector_form =
          grid ? sustained_contact_force<true>(m, gap, radius, mass, u_n, sustained)
               : sustained_contact_force<false>(m, gap, radius, mass, u_n, sustained);
      if (!sustained) {
        ++other_count;
        continue;
      }
      ++sustained_count;
      const NormalForce expected = normal_force(m, gap, radius, mass, u_n);
      ASSERT_DOUBLE_EQ(vector_form.contact, expected.contact);
      ASSERT_DOUBLE_EQ(vector_form.energy, expected.energy);
      // normal_force takes the film as a difference of film integrals P (sums of terms of
      // order 1): its rounding is 1e-16 of those terms, however close the two ends.
      const Lubrication::Activation al = m.lubrication.activation(radius);
      const double terms = std::fabs(al.integral) + std::fabs(m.lubrication.integral_saturated) +
          (std::fabs(al.lambda) + std::fabs(m.lubrication.lambda_saturated)) * (al.eps + 0.1);
      const double tolerance = 1e-13 * m.lubrication.six_pi_mu * radius.value * radius.value * terms / dt;
      ASSERT_NEAR(vector_form.lubrication, expected.lubrication, tolerance)
          << "gap " << gap << " u_n dt " << u_n * dt;
    }
  }
  // Both kinds are drawn: sustained contacts and contacts that start or end within the step.
  EXPECT_GT(sustained_count, 10000);
  EXPECT_GT(other_count, 5000);
}

// DEM without a resolved fluid (doc/model.rst, "DEM without a resolved fluid"): with
// `activation dem` a wall film plus the unbounded Stokes drag of fix fluid/drag (lambda = 1)
// follows Brenner's exact resistance of a sphere approaching a plane wall, computed here from his
// series (Brenner 1961, eq. 2.19).
#include "lubricated/check_setup.h"
#include "lubricated/normal_model.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

namespace {

// Brenner's lambda(eps) for a sphere moving normal to a rigid plane, eps = gap / R:
//   lambda = 4/3 sinh(a) sum_n n(n+1)/((2n-1)(2n+3)) [(2 sinh((2n+1)a) + (2n+1) sinh(2a)) /
//            (4 sinh^2((n+1/2)a) - (2n+1)^2 sinh^2(a)) - 1],   cosh(a) = 1 + eps,
// each fraction divided through by exp((2n+1)a) so that no sinh overflows (x = exp(-(2n+1)a)).
double brenner(double eps)
{
  const double a = std::acosh(1.0 + eps), s = std::sinh(a), s2 = std::sinh(2.0 * a);
  double sum = 0.0;
  for (int n = 1; n < 1000000; ++n) {
    const double k = 2.0 * n + 1.0, x = std::exp(-k * a);
    const double ratio = ((1.0 - x * x) + k * s2 * x) / ((1.0 - x) * (1.0 - x) - k * k * s * s * x);
    const double term = n * (n + 1.0) / ((2.0 * n - 1.0) * (2.0 * n + 3.0)) * (ratio - 1.0);
    sum += term;
    if (n > 10 && std::fabs(term) < 1e-17 * std::fabs(sum)) break;
  }
  return 4.0 / 3.0 * s * sum;
}

NormalModel dem_wall_model()
{
  Coefficients c;
  c.e_dry = 0.9;
  c.viscosity = 1e-3;
  c.eps_activation = activation_dem;
  EXPECT_EQ(validate(c), "");
  return make_normal_model(c, Partner::wall, 1e-5);
}

// film + drag in units of 6 pi mu R u: the film's damping coefficient over 6 pi mu R, plus 1.
double film_and_drag(const NormalModel &m, double eps)
{
  const double R = 1e-3;
  return m.lubrication.damping(eps, R) / (m.lubrication.six_pi_mu * R) + 1.0;
}

}    // namespace

TEST(Brenner, SeriesMatchesItsKnownLimits)
{
  // Far: the method of reflections, 1 + 9/8 (R/l) + (9/8 R/l)^2 + O((R/l)^3), l = R (1 + eps).
  const double r = 1.0 / 51.0;
  EXPECT_NEAR(brenner(50.0), 1.0 + 9.0 / 8.0 * r + 81.0 / 64.0 * r * r, 2.0 * r * r * r);
  // Near: Cox and Brenner (1967), 1/eps - (1/5) ln eps + 0.9713 + O(eps ln eps).
  for (double eps : {1e-3, 1e-2})
    EXPECT_NEAR(brenner(eps), 1.0 / eps - 0.2 * std::log(eps) + 0.9713, 0.1 * eps * std::fabs(std::log(eps)));
  // Brenner's own table: lambda = 3.0361 at h/a = cosh(1) (eps = 0.5431).
  EXPECT_NEAR(brenner(std::cosh(1.0) - 1.0), 3.0361, 1e-3);
}

TEST(DemFilm, HandsOverToTheDragWhereLambdaIsOne)
{
  const double eps_star = drag_handover_activation();
  EXPECT_NEAR(particle_wall_expansion.lambda(eps_star), 1.0, 1e-13);
  EXPECT_NEAR(eps_star, 2.7505, 1e-4);
  const NormalModel m = dem_wall_model();
  EXPECT_EQ(m.lubrication.eps_activation, eps_star);
  EXPECT_NEAR(m.reach(1e-3), eps_star * 1e-3, 1e-15);
  // Continuous: the film vanishes at eps*, film + drag = 1 on both sides.
  EXPECT_NEAR(film_and_drag(m, eps_star * (1.0 - 1e-9)), 1.0, 1e-8);
  EXPECT_EQ(film_and_drag(m, eps_star), 1.0);
}

// Near the wall film + drag = lambda_pw, Brenner's resistance to the expansion's remainder, O(eps)
// (the first term Cox and Brenner leave out): |error| <= 0.2 eps up to eps = 1 (0.16 eps measured).
// Up to eps* it never exceeds Brenner (the wall is not counted twice), and what it misses there
// is at most the drag's own miss at eps*, lambda_B(eps*) - 1 = 0.41.
TEST(DemFilm, FilmPlusDragFollowsBrenner)
{
  const NormalModel m = dem_wall_model();
  const double eps_star = drag_handover_activation(), eps_1 = m.lubrication.eps_saturation;
  for (double eps = eps_1; eps <= 1.0; eps *= 1.05) {
    const double exact = brenner(eps);
    EXPECT_NEAR(film_and_drag(m, eps), exact, 0.2 * eps) << "eps = " << eps;
  }
  const double miss_at_handover = brenner(eps_star) - 1.0;
  EXPECT_NEAR(miss_at_handover, 0.4146, 1e-3);
  for (double eps = eps_1; eps < 20.0; eps *= 1.05) {
    const double exact = brenner(eps), model = film_and_drag(m, eps);
    EXPECT_LE(model, exact) << "eps = " << eps;
    EXPECT_LE(exact - model, miss_at_handover + 1e-12) << "eps = " << eps;
  }
}

// The activations a DEM input gave before (0.09375 from a grid the run does not have, or 1) miss
// a constant lambda_pw(eps_al) - 1 right down to the wall: 11.1 and 0.97 where Brenner's
// remainder allows 0.2 eps.
TEST(DemFilm, GivenActivationsMissTheWall)
{
  for (double eps_al : {0.09375, 1.0}) {
    Coefficients c;
    c.e_dry = 0.9;
    c.viscosity = 1e-3;
    c.eps_activation = eps_al;
    const NormalModel m = make_normal_model(c, Partner::wall, 1e-5);
    const double eps = 0.01;
    EXPECT_NEAR(brenner(eps) - film_and_drag(m, eps), particle_wall_expansion.lambda(eps_al) - 1.0, 0.2 * eps);
    EXPECT_GT(brenner(eps) - film_and_drag(m, eps), 0.9);
  }
}

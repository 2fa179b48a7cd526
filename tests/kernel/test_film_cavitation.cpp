// Cavitation of a separating film (src/lubricated/film_cavitation.h, fix wall/lubrication keyword
// cavitation).
#include "lubricated/film_cavitation.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

namespace {
constexpr double pi = 3.141592653589793;
// The settling sphere at St 27: mu 0.1 Pa s, R 3 mm, leaving the wall at 0.2 m/s.
constexpr double six_pi_mu = 6.0 * pi * 0.1, radius = 3e-3, u = 0.2;
double reynolds(double gap)
{
  return six_pi_mu * radius * radius * u / gap;
}
}    // namespace

TEST(FilmCavitation, OffLeavesTheFilm)
{
  // dp_c < 0 (none), an approaching film, a pushing film: nothing removed.
  EXPECT_EQ(cavitation_relief(six_pi_mu, radius, 1e-5, u, -1.0, -reynolds(1e-5)), 0.0);
  EXPECT_EQ(cavitation_relief(six_pi_mu, radius, 1e-5, -u, 1e5, reynolds(1e-5)), 0.0);
  EXPECT_EQ(cavitation_relief(six_pi_mu, radius, 1e-5, u, 1e5, 0.0), 0.0);
  EXPECT_EQ(cavitation_relief(six_pi_mu, radius, 1e-5, 0.0, 1e5, -1.0), 0.0);
}

TEST(FilmCavitation, HalfSommerfeldForce)
{
  const double dp = 1e5;
  const double h_c = std::sqrt(3.0 * 0.1 * radius * u / dp);    // 4.24e-5 m
  // Beyond h_c the Reynolds pressure stays above p_0 - dp_c: nothing removed.
  EXPECT_EQ(cavitation_relief(six_pi_mu, radius, 1.01 * h_c, u, dp, -reynolds(1.01 * h_c)), 0.0);
  // Below it the film holds -dp_c over r < r_c and the Reynolds tension outside:
  // F = -2 pi R dp_c (2 h_c - h), the direct integral of the capped pressure.
  for (double h : {1e-7, 1e-6, 1e-5, 0.5 * h_c, 0.999 * h_c}) {
    const double film = -reynolds(h);
    const double capped = film + cavitation_relief(six_pi_mu, radius, h, u, dp, film);
    const double r_c2 = 2.0 * radius * (h_c - h);    // h(r_c) = h_c
    const double outside = -six_pi_mu * radius * radius * u / h_c;
    EXPECT_NEAR(capped, -dp * pi * r_c2 + outside, 1e-12 * std::fabs(film)) << h;
    EXPECT_NEAR(capped, -2.0 * pi * radius * dp * (2.0 * h_c - h), 1e-9 * std::fabs(capped)) << h;
    EXPECT_LE(capped, 0.0);
    EXPECT_GE(capped, film);
  }
  // Continuous at h_c.
  const double at = -reynolds(h_c) + cavitation_relief(six_pi_mu, radius, h_c * (1 - 1e-12), u, dp, -reynolds(h_c));
  EXPECT_NEAR(at, -reynolds(h_c), 1e-9 * reynolds(h_c));
}

TEST(FilmCavitation, TensionFallsWithTheLimit)
{
  // A smaller tension limit removes more; 0 removes the Reynolds tension at every gap, never more
  // than the film (which then holds none).
  const double h = 1e-5, film = -reynolds(h);
  double last = 0.0;
  for (double dp : {1e7, 1e5, 1e3, 10.0, 0.0}) {
    const double relief = cavitation_relief(six_pi_mu, radius, h, u, dp, film);
    EXPECT_GE(relief, last) << dp;
    last = relief;
  }
  EXPECT_EQ(cavitation_relief(six_pi_mu, radius, h, u, 0.0, film), -film);
  EXPECT_EQ(cavitation_relief(six_pi_mu, radius, 1e-3, u, 0.0, -0.5 * reynolds(1e-3)), 0.5 * reynolds(1e-3));
  // Never more than the film force itself, whatever dp_c.
  EXPECT_EQ(cavitation_relief(six_pi_mu, radius, h, u, 1.0, -1e-9), 1e-9);
}

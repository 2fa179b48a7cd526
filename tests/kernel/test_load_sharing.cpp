// Steady loads shared among the faces a sphere rests on (src/lubricated/load_sharing.h).
#include "lubricated/load_sharing.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

TEST(LoadSharing, OneFaceTakesTheProjection)
{
  const Vec3 n[1] = {{0.0, 0.6, 0.8}}, g{0.0, 0.0, -9.81};
  double b[1];
  shared_loads(n, 1, g, b);
  EXPECT_DOUBLE_EQ(b[0], 0.8 * 9.81);
}

TEST(LoadSharing, TwoFacesOfAGrooveBalanceTheWeight)
{
  // 60 degrees between the faces: normals 60 degrees from the vertical, each carries g.
  const double s = std::sin(M_PI / 3), c = std::cos(M_PI / 3);
  const Vec3 n[2] = {{s, 0.0, c}, {-s, 0.0, c}}, g{0.0, 0.0, -9.81};
  double b[2];
  shared_loads(n, 2, g, b);
  EXPECT_NEAR(b[0], 9.81, 1e-12);
  EXPECT_NEAR(b[1], 9.81, 1e-12);
  // The sum of the loads along the normals is the weight.
  EXPECT_NEAR(b[0] * n[0].z + b[1] * n[1].z, 9.81, 1e-12);
  EXPECT_NEAR(b[0] * n[0].x + b[1] * n[1].x, 0.0, 1e-12);
}

TEST(LoadSharing, AFloorAndASideWallLeaveTheSideUnloaded)
{
  const Vec3 n[2] = {{0.0, 0.0, 1.0}, {1.0, 0.0, 0.0}}, g{0.0, 0.0, -9.81};
  double b[2];
  shared_loads(n, 2, g, b);
  EXPECT_DOUBLE_EQ(b[0], 9.81);
  EXPECT_DOUBLE_EQ(b[1], 0.0);
}

TEST(LoadSharing, ANonNegativeSolutionWhereLeastSquaresWouldPull)
{
  // An asymmetric groove with gravity tilted beyond one face: the plain least-squares solution
  // would pull on the other face; the non-negative one puts the whole projection on one face.
  const double s = std::sin(M_PI / 6), c = std::cos(M_PI / 6);
  const Vec3 n[2] = {{s, 0.0, c}, {-s, 0.0, c}}, g{-9.81, 0.0, -1.0};
  double b[2];
  shared_loads(n, 2, g, b);
  EXPECT_GE(b[0], 0.0);
  EXPECT_EQ(b[1], 0.0);
  EXPECT_NEAR(b[0], -dot(n[0], g), 1e-12);
}

TEST(LoadSharing, ThreeFacesOfACorner)
{
  // Three faces tilted 45 degrees from the vertical, 120 degrees apart: each carries g / (3 cos 45).
  Vec3 n[3];
  for (int k = 0; k < 3; k++) {
    const double phi = 2.0 * M_PI * k / 3.0;
    n[k] = {std::sqrt(0.5) * std::cos(phi), std::sqrt(0.5) * std::sin(phi), std::sqrt(0.5)};
  }
  const Vec3 g{0.0, 0.0, -9.81};
  double b[3];
  shared_loads(n, 3, g, b);
  for (int k = 0; k < 3; k++)
    EXPECT_NEAR(b[k], 9.81 / (3.0 * std::sqrt(0.5)), 1e-12);
  // Parallel faces (degenerate): still a non-negative balance.
  const Vec3 twice[2] = {{0.0, 0.0, 1.0}, {0.0, 0.0, 1.0}};
  shared_loads(twice, 2, g, b);
  EXPECT_NEAR(b[0] + b[1], 9.81, 1e-12);
}

// Film radius against curved walls (src/lubricated/wall_curvature.h, doc/model.rst "Curved walls").
#include "lubricated/wall_curvature.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

TEST(WallCurvature, FlatWallKeepsTheSphereRadius)
{
  EXPECT_EQ(wall_film_radius(1e-3, 0.0, 0.0), 1e-3);
  // A very large cylinder or sphere tends to the plane.
  EXPECT_NEAR(wall_film_radius(1e-3, -1e6, 0.0), 1e-3, 1e-12);
  EXPECT_NEAR(wall_film_radius(1e-3, 1e6, 1e6), 1e-3, 1e-12);
}

TEST(WallCurvature, SphereRegionGivesTheRelativeRadius)
{
  const double R = 1e-3, Rw = 5e-3;
  // Outside a sphere: R Rw / (R + Rw); inside: R Rw / (Rw - R).
  EXPECT_NEAR(wall_film_radius(R, Rw, Rw), R * Rw / (R + Rw), 1e-18);
  EXPECT_NEAR(wall_film_radius(R, -Rw, -Rw), R * Rw / (Rw - R), 1e-18);
}

TEST(WallCurvature, CylinderIsTheGeometricMean)
{
  const double R = 1e-3, Rw = 4e-3;
  EXPECT_NEAR(wall_film_radius(R, -Rw, 0.0), std::sqrt(R * R * Rw / (Rw - R)), 1e-18);
  EXPECT_NEAR(wall_film_radius(R, Rw, 0.0), std::sqrt(R * R * Rw / (Rw + R)), 1e-18);
  // Concave walls hold the film closer (larger radius), convex ones less.
  EXPECT_GT(wall_film_radius(R, -Rw, 0.0), R);
  EXPECT_LT(wall_film_radius(R, Rw, 0.0), R);
}

TEST(WallCurvature, ConcaveWallSmallerThanTheSphereDoesNotFit)
{
  EXPECT_TRUE(sphere_fits_wall(1e-3, 0.0));
  EXPECT_TRUE(sphere_fits_wall(1e-3, 1e-4));
  EXPECT_TRUE(sphere_fits_wall(1e-3, -1.01e-3));
  EXPECT_FALSE(sphere_fits_wall(1e-3, -1e-3));
  EXPECT_FALSE(sphere_fits_wall(1e-3, -0.5e-3));
}

// A wall moving as a rigid body (src/lubricated/wall_motion.h): the relative motion the
// contact kernel's wall partner takes gives the slip of the two surfaces at the contact point
// and the spin relative to the wall.
#include "lubricated/wall_motion.h"

#include <gtest/gtest.h>

using namespace lubricated;

static void expect_near(const Vec3 &a, const Vec3 &b, double tol)
{
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(WallMotion, VelocityOfTheMaterialPoint)
{
  RigidWallMotion wall;
  wall.velocity = {0.1, 0.0, 0.0};
  wall.spin = {0.0, 0.0, 2.0};
  wall.point = {1.0, 0.0, 0.0};
  EXPECT_TRUE(wall.moving());
  // V + Omega x (x - P) at x = P + (0, 3, 0): (0.1 - 6, 0, 0).
  expect_near(wall.velocity_at({1.0, 3.0, 0.0}), {0.1 - 6.0, 0.0, 0.0}, 1e-15);
  EXPECT_FALSE(RigidWallMotion().moving());
}

TEST(WallMotion, KernelSlipIsTheSurfacesSlip)
{
  RigidWallMotion wall;
  wall.velocity = {0.02, -0.01, 0.03};
  wall.spin = {1.0, -2.0, 3.0};
  wall.point = {0.1, 0.2, -0.3};
  const Vec3 v{0.3, 0.1, -0.2}, omega{-5.0, 4.0, 7.0}, n{0.0, 0.6, 0.8};
  const double radius = 1e-3;
  const Vec3 x_contact{0.5, 0.4, 0.2};
  const RelativeMotion rel = relative_to_wall(wall, v, omega, radius, n, x_contact);
  // The sphere's surface point at the contact: v - R omega x n; the wall's: velocity_at(x_c).
  const Vec3 surfaces = minus(minus(v, scaled(cross(omega, n), radius)), wall.velocity_at(x_contact));
  // The kernel's wall slip (contact.h): tangential part of dv' - R omega' x n.
  const Vec3 kernel = tangential_part(minus(rel.dv, cross(scaled(rel.omega, radius), n)), n);
  expect_near(kernel, tangential_part(surfaces, n), 1e-15);
  expect_near(rel.omega, minus(omega, wall.spin), 0.0);
  EXPECT_NEAR(rel.u_n, dot(minus(v, wall.velocity_at(x_contact)), n), 1e-15);
}

TEST(WallMotion, ASphereRollingWithTheWallHasNoSlipNorSpin)
{
  // A sphere glued to a rotating wall (centre moving with the wall, spinning at Omega): no
  // slip at the contact, no relative spin, no normal motion.
  RigidWallMotion wall;
  wall.spin = {0.0, 0.0, 4.0};
  const double radius = 0.1;
  const Vec3 centre{1.0 + radius, 0.0, 0.0}, n{1.0, 0.0, 0.0};
  const Vec3 v = wall.velocity_at(centre);
  const RelativeMotion rel = relative_to_wall(wall, v, wall.spin, radius, n, {1.0, 0.0, 0.0});
  expect_near(tangential_part(minus(rel.dv, cross(scaled(rel.omega, radius), n)), n), {}, 1e-15);
  expect_near(rel.omega, {}, 0.0);
  EXPECT_NEAR(rel.u_n, 0.0, 1e-15);
}

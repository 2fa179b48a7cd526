// Wall shapes and motion of fix wall/lubrication (src/lubricated/wall_geometry.h).
#include "lubricated/wall_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

TEST(WallMotion, WiggleFollowsFixWallGransLawAndItsDerivative)
{
  WallMotion m;
  m.translation = {0.1, 0.0, 0.0};
  m.wiggle_dim = 2, m.amplitude = 1e-3, m.period = 0.02;
  const double t = 0.0037, h = 1e-7, w = two_pi / m.period;
  EXPECT_DOUBLE_EQ(m.displacement(t).z, 1e-3 * (1.0 - std::cos(w * t)));
  EXPECT_DOUBLE_EQ(m.displacement(t).x, 0.1 * t);
  EXPECT_EQ(m.displacement(0.0).z, 0.0);    // the wall starts where it was given, at rest
  EXPECT_NEAR(m.velocity(t).z, (m.displacement(t + h).z - m.displacement(t - h).z) / (2 * h), 1e-8);
  // The step velocity is the displacement over the step, not the velocity at its end.
  const double dt = 1e-3;
  EXPECT_DOUBLE_EQ(m.step_velocity(t, dt).z, (m.displacement(t).z - m.displacement(t - dt).z) / dt);
  EXPECT_GT(std::fabs(m.step_velocity(t, dt).z - m.velocity(t).z), 1e-3 * std::fabs(m.velocity(t).z));
  EXPECT_FALSE(WallMotion{}.moves());
  EXPECT_TRUE(m.moves());
}

TEST(WallMotion, PlaneAndCylinderGapsAndNormals)
{
  const double R = 1e-3, x[3] = {3e-3, -4e-3, 2e-3};
  WallSurface lo;    // zplane lo at 1e-3, moved up by 5e-4
  lo.axis = 2, lo.side = 1, lo.position = 1e-3;
  const WallPoint p = wall_point(lo, x, R, {7.0, 7.0, 5e-4});
  EXPECT_NEAR(p.gap, 2e-3 - 1e-3 - 5e-4 - R, 1e-18);
  EXPECT_EQ(p.n.z, 1.0);
  WallSurface in;    // zcylinder of radius 1e-2, sphere inside at r = 5e-3
  in.cylinder = true, in.radius = 1e-2, in.side = -1;
  const WallPoint c = wall_point(in, x, R, {});
  EXPECT_NEAR(c.gap, 1e-2 - 5e-3 - R, 1e-18);
  EXPECT_NEAR(c.n.x, -0.6, 1e-15);    // towards the axis
  EXPECT_NEAR(c.n.y, 0.8, 1e-15);
  WallSurface out = in;
  out.side = 1, out.radius = 2e-3;
  EXPECT_NEAR(wall_point(out, x, R, {}).gap, 5e-3 - 2e-3 - R, 1e-18);
  EXPECT_NEAR(wall_point(out, x, R, {}).n.x, 0.6, 1e-15);
  // Film radius: concave larger than R, convex smaller; a plane keeps R.
  EXPECT_GT(in.film_radius(R), R);
  EXPECT_LT(out.film_radius(R), R);
  EXPECT_EQ(lo.film_radius(R), R);
  EXPECT_FALSE(in.holds(1e-2));
  EXPECT_TRUE(out.holds(1.0));
}

TEST(WallMotion, NormalStepVelocityGivesTheGapAStepAgo)
{
  const double R = 1e-3, dt = 1e-4;
  WallSurface in;
  in.cylinder = true, in.radius = 1e-2, in.side = -1;
  const double x[3] = {5e-3, 3e-3, 0.0}, v[3] = {0.3, -0.2, 0.1};
  const Vec3 shift{1e-4, 0.0, 0.0}, before{0.9e-4, -0.1e-4, 0.0};
  const Vec3 wall_v = scaled(minus(shift, before), 1.0 / dt);
  const WallPoint now = wall_point(in, x, R, shift);
  const double u_n = normal_step_velocity(in, now, x, v, R, before, wall_v, dt);
  const double x0[3] = {x[0] - v[0] * dt, x[1] - v[1] * dt, x[2] - v[2] * dt};
  EXPECT_NEAR(now.gap - u_n * dt, wall_point(in, x0, R, before).gap, 1e-18);
  // To first order it is the relative velocity along n; the curvature adds the chord's
  // sagitta, at most |v_t|^2 dt / r with r the distance from the axis.
  const Vec3 rel{v[0] - wall_v.x, v[1] - wall_v.y, 0.0};
  const double linear = dot(rel, now.n), v_t2 = dot(rel, rel) - linear * linear;
  const double r = std::hypot(x[0] - shift.x, x[1] - shift.y);
  EXPECT_NEAR(u_n, linear, v_t2 * dt / r);
  EXPECT_GT(std::fabs(u_n - linear), 0.1 * v_t2 * dt / r);    // and it is there
}

TEST(WallMotion, TurningCylinderSlipIsTheSurfacesRelativeVelocity)
{
  // The sphere's motion relative to the wall frame gives v - v_wall(contact) - R omega x n.
  WallSurface in;
  in.cylinder = true, in.radius = 1e-2, in.side = -1;
  WallMotion m;
  m.shear_dim = 0, m.shear_speed = 0.05;
  const double R = 1e-3, x[3] = {2e-3, -8.5e-3, 0.0};
  const Vec3 v{0.01, 0.02, -0.003}, omega{1.0, -2.0, 30.0};
  const Vec3 n = wall_point(in, x, R, {}).n;
  const double spin = wall_spin(in, m);
  EXPECT_DOUBLE_EQ(spin, -0.05 / 1e-2);    // clockwise seen from +z for vshear > 0
  const Vec3 v_frame = frame_velocity(in, m, {}, {}, x);
  const Vec3 rel_omega{omega.x, omega.y, omega.z - spin};
  const Vec3 s_frame = minus(minus(v, v_frame), cross(scaled(rel_omega, R), n));
  const Vec3 contact{x[0] - R * n.x, x[1] - R * n.y, 0.0};
  const Vec3 v_wall = cross(Vec3{0.0, 0.0, spin}, contact);
  const Vec3 s_direct = minus(minus(v, v_wall), cross(scaled(omega, R), n));
  EXPECT_NEAR(s_frame.x, s_direct.x, 1e-15);
  EXPECT_NEAR(s_frame.y, s_direct.y, 1e-15);
  EXPECT_NEAR(s_frame.z, s_direct.z, 1e-15);
  // The wall's surface speed is vshear.
  const double speed = std::sqrt(dot(v_wall, v_wall)) * in.radius / std::sqrt(dot(contact, contact));
  EXPECT_NEAR(speed, 0.05, 1e-15);
  // A plane's shear is a tangential velocity.
  WallSurface plane;
  WallMotion ms;
  ms.shear_dim = 0, ms.shear_speed = 0.2;
  EXPECT_EQ(frame_velocity(plane, ms, {}, {}, x).x, 0.2);
  EXPECT_EQ(wall_spin(plane, ms), 0.0);
}

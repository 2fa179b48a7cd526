// Wall shapes and wall motion of fix wall/lubrication (doc/fix_wall_lubrication.rst, "Curved
// and moving walls"): a plane perpendicular to an axis or a cylinder along z, at rest,
// translating, wiggling or sheared (a cylinder sheared about its axis turns).
//
// Conventions (doc/model.rst): n is the unit normal from the wall to the sphere's centre, the
// gap h the centre's distance to the wall surface minus the sphere's radius R (negative in
// overlap). A wall is described in its own rigid frame, which moves with the translation and
// the wiggle and, for a sheared cylinder, turns about the cylinder's axis; a sphere sees the
// wall through its motion relative to that frame (velocity v - v_frame(x), spin omega - Omega),
// which gives the slip of the surfaces at the contact point exactly:
//   v - (V + Omega x (x - R n)) - R omega x n = (v - V - Omega x x) - R (omega - Omega) x n.
// Lengths, times and velocities in the input's units.
#pragma once

#include "tangential.h"    // Vec3
#include "wall_curvature.h"
#include "wall_motion.h"    // RigidWallMotion, relative_to_wall

#include <cmath>

namespace lubricated {

constexpr double two_pi = 6.283185307179586476925286766559;

// How the wall frame moves with the time t since the fix was defined:
//   translate: displacement V t;
//   wiggle:    displacement A (1 - cos(2 pi t / T)) along one axis (fix wall/gran's wiggle);
//   shear:     a surface velocity that leaves the wall where it is: along a plane's tangent,
//              along a cylinder's axis, or a cylinder turning about its axis.
struct WallMotion {
  Vec3 translation;    // V
  int wiggle_dim = -1;
  double amplitude = 0.0, period = 0.0;
  int shear_dim = -1;
  double shear_speed = 0.0;

  bool moves() const
  {
    return translation.x != 0.0 || translation.y != 0.0 || translation.z != 0.0 || wiggle_dim >= 0 || shear_dim >= 0;
  }
  // Displacement of the wall frame at time t.
  Vec3 displacement(double t) const
  {
    Vec3 d = scaled(translation, t);
    if (wiggle_dim >= 0) component(d, wiggle_dim) += amplitude * (1.0 - std::cos(two_pi * t / period));
    return d;
  }
  // Velocity of the frame's translation at time t (the derivative of displacement()).
  Vec3 velocity(double t) const
  {
    Vec3 v = translation;
    if (wiggle_dim >= 0) component(v, wiggle_dim) += amplitude * two_pi / period * std::sin(two_pi * t / period);
    return v;
  }
  // Its mean over the step that ends at t, (d(t) - d(t - dt)) / dt: the wall's counterpart of a
  // sphere's velocity over the step, which the step-exact contact takes (the gap a step ago is
  // h - u_n dt exactly, doc/model.rst "Integrating the contact over a step").
  Vec3 step_velocity(double t, double dt) const
  {
    return scaled(minus(displacement(t), displacement(t - dt)), 1.0 / dt);
  }

  static double &component(Vec3 &v, int dim) { return dim == 0 ? v.x : dim == 1 ? v.y : v.z; }
};

// One wall surface. A plane: the wall at coordinate `position` along `axis`, side +1 for a lower
// wall (the spheres above it, n = +axis), -1 for an upper one. A cylinder along z of radius
// `radius` about (0, 0): side -1 holds the spheres inside it, +1 outside.
struct WallSurface {
  bool cylinder = false;
  int axis = 2;
  int side = 1;
  double position = 0.0, radius = 0.0;

  // The wall's principal radius of curvature across its axis (wall_curvature.h: positive where
  // convex towards the sphere): +R_w outside a cylinder, -R_w inside, 0 for a plane.
  double curvature_radius() const { return cylinder ? side * radius : 0.0; }
  // Film radius R_f = sqrt(a b) of a sphere of radius R (doc/model.rst, "Curved walls").
  double film_radius(double sphere_radius) const
  {
    return cylinder ? wall_film_radius(sphere_radius, curvature_radius(), 0.0) : sphere_radius;
  }
  // Whether a sphere of radius R fits against the wall (a concave cylinder of radius <= R does not).
  bool holds(double sphere_radius) const { return sphere_fits_wall(sphere_radius, curvature_radius()); }
};

struct WallPoint {
  double gap = 0.0;
  Vec3 n;
};

// Gap and normal of a sphere of radius R centred at x, the wall frame displaced by `shift`.
// On a cylinder's axis the normal is undefined; +x is taken there (the gap holds either way).
inline WallPoint wall_point(const WallSurface &w, const double *x, double sphere_radius, const Vec3 &shift)
{
  WallPoint p;
  if (!w.cylinder) {
    const double s[3] = {shift.x, shift.y, shift.z};
    p.gap = w.side * (x[w.axis] - w.position - s[w.axis]) - sphere_radius;
    WallMotion::component(p.n, w.axis) = w.side;
    return p;
  }
  const double dx = x[0] - shift.x, dy = x[1] - shift.y;
  const double r = std::sqrt(dx * dx + dy * dy);
  p.gap = w.side * (r - w.radius) - sphere_radius;
  if (r > 0.0)
    p.n = {w.side * dx / r, w.side * dy / r, 0.0};
  else
    p.n = {1.0, 0.0, 0.0};
  return p;
}

// The normal velocity over the last step, u_n = (h - h_before) / dt, with h_before the gap of
// the centre a step ago (x - v dt, v its velocity over the step) against the wall a step ago
// (shift_before): the step-exact contact's g_0 = h - u_n dt, exact on a curved wall too. A plane
// gives (v - V_wall) . n, V_wall the frame's velocity over the step.
inline double normal_step_velocity(const WallSurface &w, const WallPoint &now, const double *x, const double *v,
                                   double sphere_radius, const Vec3 &shift_before, const Vec3 &wall_velocity, double dt)
{
  if (!w.cylinder) {
    const double v_wall = w.axis == 0 ? wall_velocity.x : w.axis == 1 ? wall_velocity.y : wall_velocity.z;
    return w.side * (v[w.axis] - v_wall);
  }
  const double before[3] = {x[0] - v[0] * dt, x[1] - v[1] * dt, x[2] - v[2] * dt};
  return (now.gap - wall_point(w, before, sphere_radius, shift_before).gap) / dt;
}

// Angular velocity (about +z) of a cylinder sheared across its axis: surface speed vshear at its
// radius, clockwise seen from +z for vshear > 0 (fix wall/gran's convention); 0 otherwise.
inline double wall_spin(const WallSurface &w, const WallMotion &m)
{
  return w.cylinder && (m.shear_dim == 0 || m.shear_dim == 1) ? -m.shear_speed / w.radius : 0.0;
}

// The wall frame as a rigid motion (wall_motion.h, shared with the region wall): the
// translation's (and wiggle's) velocity V plus the shear of a plane or along a cylinder's axis,
// and a turning cylinder's spin Omega about its displaced axis.
inline RigidWallMotion rigid_motion(const WallSurface &w, const WallMotion &m, const Vec3 &translation_velocity,
                                    const Vec3 &shift)
{
  RigidWallMotion frame;
  frame.velocity = translation_velocity;
  frame.point = shift;
  if (m.shear_dim < 0) return frame;
  const double spin = wall_spin(w, m);
  if (spin != 0.0)
    frame.spin = {0.0, 0.0, spin};
  else
    WallMotion::component(frame.velocity, m.shear_dim) += m.shear_speed;
  return frame;
}

// Velocity of the wall frame at the point x.
inline Vec3 frame_velocity(const WallSurface &w, const WallMotion &m, const Vec3 &translation_velocity,
                           const Vec3 &shift, const double *x)
{
  return rigid_motion(w, m, translation_velocity, shift).velocity_at({x[0], x[1], x[2]});
}

}    // namespace lubricated

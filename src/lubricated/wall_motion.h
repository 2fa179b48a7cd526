// A wall that moves as a rigid body (a moving or rotating region): translation velocity V and
// angular velocity Omega about a point P, both over the last step (the velocity convention of
// normal_model.h). The contact kernel (contact.h) treats a wall as a partner that neither moves
// nor turns; a moving wall enters it through the relative motion at the contact point
// (doc/fix_wall_lubrication_region.rst, "Moving regions").
#pragma once

#include "lubricated/contact.h"

namespace lubricated {

struct RigidWallMotion {
  Vec3 velocity, spin, point;    // V, Omega, P (length/time, 1/time, length)

  bool moving() const
  {
    return velocity.x != 0.0 || velocity.y != 0.0 || velocity.z != 0.0 || spin.x != 0.0 || spin.y != 0.0 ||
           spin.z != 0.0;
  }
  // Velocity of the wall's material point at x: V + Omega x (x - P).
  Vec3 velocity_at(const Vec3 &x) const { return plus(velocity, cross(spin, minus(x, point))); }
};

// The sphere's motion relative to the wall at the contact point x_c, as the kernel's wall
// partner needs it: u_n = (v - v_w(x_c)) . n, and, for the tangential parts,
//   dv' = v - v_w(x_c) - R Omega x n,   omega' = omega - Omega,
// so that the kernel's slip dv' - R omega' x n = v - R omega x n - v_w(x_c) is the slip of the
// two surfaces at the contact, and its rolling resistance acts on the spin relative to the
// wall, omega - Omega (a wall that does not turn: dv' = v - v_w, omega' = omega).
struct RelativeMotion {
  Vec3 dv, omega;
  double u_n = 0.0;
};

inline RelativeMotion relative_to_wall(const RigidWallMotion &wall, const Vec3 &v, const Vec3 &omega, double radius,
                                       const Vec3 &n, const Vec3 &contact_point)
{
  RelativeMotion out;
  const Vec3 dv = minus(v, wall.velocity_at(contact_point));
  out.u_n = dot(dv, n);
  out.dv = minus(dv, scaled(cross(wall.spin, n), radius));
  out.omega = minus(omega, wall.spin);
  return out;
}

}    // namespace lubricated

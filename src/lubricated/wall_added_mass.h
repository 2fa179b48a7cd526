// Added mass of a sphere near plane walls at rest (doc/fix_fluid_drag.rst, keyword wall):
// potential flow, the first reflection of the method of images. A sphere of radius R whose
// centre is at distance h from a wall carries, along the wall's normal and parallel to it,
//   C_perp(h) = C_m (1 + (3/8) (R/h)^3),   C_par(h) = C_m (1 + (3/16) (R/h)^3),
// C_m the unbounded value (1/2 for a sphere). Derivation: the sphere's dipole, strength
// R^3 U / 2, has a mirror image at 2h; its flow at the sphere is -(R/2h)^3 U (normal motion) or
// -(R/2h)^3 U / 2 (parallel); the sphere's own reflection of that uniform flow makes the
// surface potential 3R/2 of it, and the kinetic energy -(rho_f/2) int phi dphi/dn dS grows by
// C_m m_f (3/8 or 3/16) (R/h)^3 U^2 / 2, m_f = rho_f V (Lamb, Hydrodynamics, 6th ed., sec. 98;
// Milne-Thomson, Theoretical Hydrodynamics, sec. 16.60, for the image system). Higher reflections
// add O((R/h)^6) and raise the value in contact further; the first reflection is kept.
// Several walls add their increments (their images' images are O((R/h)^6) too).
//
// A mass that depends on position brings forces of its own. From Lagrange's equations with the
// fluid's kinetic energy T = (1/2) sum_d M_d(x) w_d^2 (w the velocity relative to the fluid at
// rest, M_d = m_a,d):
//   F_k = -M_k dw_k/dt - (sum_j dM_k/dx_j w_j) w_k + (1/2) sum_d dM_d/dx_k w_d^2:
// a sphere approaching a wall is pushed back, one moving along it is drawn to it, and
// (m + M(h)) w^2 / 2 plus the work of the other forces is conserved. The first term is solved
// for with the rest of the added mass (fluid_inertia.h); the others, here, are explicit.
// Centres closer than R (in overlap) take the value in contact, without the gradient.
#pragma once

#include <algorithm>

namespace lubricated {

constexpr double wall_added_mass_normal = 3.0 / 8.0;       // C_perp / C_m - 1 at h = R
constexpr double wall_added_mass_parallel = 3.0 / 16.0;    // C_par / C_m - 1 at h = R

// One plane wall at rest, normal along axis `axis` (0, 1, 2) at coordinate `position`.
struct AddedMassWall {
  int axis = 2;
  double position = 0.0;
};

// The added mass per axis of a sphere (radius, centre x) near the walls, in units of C_m rho_f V:
// mass[d] = 1 + the walls' increments, slope[d][k] = d mass[d] / d x_k [1/length].
struct WallAddedMass {
  double mass[3] = {1.0, 1.0, 1.0};
  double slope[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
};

inline WallAddedMass wall_added_mass(const AddedMassWall *walls, int nwalls, double radius, const double *x)
{
  WallAddedMass m;
  for (int w = 0; w < nwalls; w++) {
    const int k = walls[w].axis;
    const double offset = x[k] - walls[w].position;    // signed: which side of the wall
    const double h = std::max(offset < 0.0 ? -offset : offset, radius);
    const double ratio = radius / h, cube = ratio * ratio * ratio;
    // d (R/h)^3 / dx_k = -3 (R/h)^3 / h * sign(offset), 0 in overlap (h held at R)
    const double dcube = h > radius ? -3.0 * cube / h * (offset < 0.0 ? -1.0 : 1.0) : 0.0;
    for (int d = 0; d < 3; d++) {
      const double c = d == k ? wall_added_mass_normal : wall_added_mass_parallel;
      m.mass[d] += c * cube;
      m.slope[d][k] += c * dcube;
    }
  }
  return m;
}

// The explicit forces of the position-dependent mass (F_k above without -M_k dw_k/dt), for a
// sphere of slip-free added mass `base` = C_m rho_f V [mass] moving at w relative to the fluid.
inline void wall_added_mass_force(const WallAddedMass &m, double base, const double *w, double *force)
{
  for (int k = 0; k < 3; k++) {
    double rate = 0.0, pull = 0.0;
    for (int j = 0; j < 3; j++)
      rate += m.slope[k][j] * w[j];    // dM_k/dt / base
    for (int d = 0; d < 3; d++)
      pull += m.slope[d][k] * w[d] * w[d];
    force[k] = base * (-rate * w[k] + 0.5 * pull);
  }
}

}    // namespace lubricated

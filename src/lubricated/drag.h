// Force of an unresolved fluid on one sphere, for the drag fix (doc/model.rst, "What the paper
// leaves out").
//
//   F = beta (u_f - u_p) - rho_f V_p g
//
// beta [mass/time] from the slip speed w = |u_f - u_p| and the local voidage eps = 1 - phi:
//   stokes:            beta = 3 pi mu d
//   schiller-naumann:  beta = 3 pi mu d (1 + 0.15 Re^0.687), Re = rho_f w d / mu < 1000;
//                      Newton's regime C_D = 0.44 above (Schiller & Naumann 1933)
// times a hindered-settling factor for dense suspensions:
//   richardson-zaki n: eps^(1 - n), so that a uniform bed fluidised by a superficial
//                      velocity U = eps u_f settles into U = u_t eps^n (Richardson & Zaki
//                      1954); exact in the Stokes regime
//   di-felice:         eps^(1 - chi) with the slip taken as superficial, eps (u_f - u_p),
//                      chi = 3.7 - 0.65 exp(-(1.5 - log10 Re_eps)^2 / 2) (Di Felice 1994)
// The second term is buoyancy (hydrostatic pressure of the fluid), g the gravity vector.
#pragma once

#include "spring_dashpot.h"    // pi

#include <algorithm>
#include <cmath>

namespace lubricated {

enum class DragLaw { stokes, schiller_naumann };
enum class Hindrance { none, richardson_zaki, di_felice };

struct DragModel {
  double viscosity = 0.0;    // mu_f  [mass/(length time)]
  double density = 0.0;      // rho_f [mass/length^3]
  DragLaw law = DragLaw::schiller_naumann;
  Hindrance hindrance = Hindrance::none;
  double rz_exponent = 4.65;    // Richardson-Zaki n (Stokes regime value)
  double min_voidage = 0.36;    // eps never taken below random close packing
};

// Single-sphere drag coefficient beta = |F| / w for slip speed w.
inline double single_sphere_beta(const DragModel &m, double diameter, double slip_speed)
{
  const double stokes = 3.0 * pi * m.viscosity * diameter;
  if (m.law == DragLaw::stokes) return stokes;
  const double re = m.density * slip_speed * diameter / m.viscosity;
  if (re < 1000.0) return stokes * (1.0 + 0.15 * std::pow(re, 0.687));
  return stokes * 0.44 * re / 24.0;
}

// beta including the hindrance of neighbours at local voidage eps (1 for a lone sphere).
inline double drag_beta(const DragModel &m, double diameter, double slip_speed, double voidage)
{
  const double eps = std::min(1.0, std::max(voidage, m.min_voidage));
  switch (m.hindrance) {
  case Hindrance::none:
    return single_sphere_beta(m, diameter, slip_speed);
  case Hindrance::richardson_zaki:
    return single_sphere_beta(m, diameter, slip_speed) * std::pow(eps, 1.0 - m.rz_exponent);
  case Hindrance::di_felice: {
    const double w = eps * slip_speed;    // superficial slip
    const double re = std::max(m.density * w * diameter / m.viscosity, 1e-12);
    const double chi = 3.7 - 0.65 * std::exp(-0.5 * std::pow(1.5 - std::log10(re), 2));
    // F = beta_single(w) w eps^-chi, expressed per unit interstitial slip.
    return single_sphere_beta(m, diameter, w) * eps * std::pow(eps, -chi);
  }
  }
  return 0.0;
}

// The affine velocity of a deforming box (fix deform's remap v, SLLOD): a point at fixed box
// coordinates lamda (0..1 across the box) moves with the box, u = hdot lamda + lo_dot, with h
// the upper-triangular box matrix in Voigt order (xx yy zz yz xz xy) and lo its origin.
// Simple shear xy erate gdot: u_x = gdot (y - ylo).
inline void affine_velocity(const double *h_rate, const double *lo_rate, const double *lamda, double *u)
{
  u[0] = h_rate[0] * lamda[0] + h_rate[5] * lamda[1] + h_rate[4] * lamda[2] + lo_rate[0];
  u[1] = h_rate[1] * lamda[1] + h_rate[3] * lamda[2] + lo_rate[1];
  u[2] = h_rate[2] * lamda[2] + lo_rate[2];
}

// The curl of that affine velocity, curl u = eps_ijk d_j u_k with grad u = hdot h^-1 (both
// upper triangular, Voigt order; h_inv is h^-1 in the same order). Simple shear xy erate
// gdot: curl u = (0, 0, -gdot).
inline void affine_vorticity(const double *h_rate, const double *h_inv, double *curl)
{
  const double l01 = h_rate[0] * h_inv[5] + h_rate[5] * h_inv[1];                           // du_x/dy
  const double l02 = h_rate[0] * h_inv[4] + h_rate[5] * h_inv[3] + h_rate[4] * h_inv[2];    // du_x/dz
  const double l12 = h_rate[1] * h_inv[3] + h_rate[3] * h_inv[2];                           // du_y/dz
  curl[0] = -l12;
  curl[1] = l02;
  curl[2] = -l01;
}

// The fluid's resistance to a sphere's spin relative to its own rotation curl u_f / 2:
// T = 8 pi mu_f a^3 (curl u_f / 2 - omega) in creeping flow (Happel & Brenner 1965; Kim &
// Karrila 1991), for a spin Reynolds number |curl u_f / 2 - omega| a^2 / nu_f well below 1.
inline double rotational_drag_coefficient(double radius, double viscosity)
{
  return 8.0 * pi * viscosity * radius * radius * radius;
}

// The torque of that resistance over a step dt on a sphere of moment of inertia I, backward
// Euler in the spin with the step's other torques T_o held: the spin ends at
// (omega + k Omega_f + dt T_o / I) / (1 + k), k = beta_r dt / I, so the torque is
// (beta_r s - k T_o) / (1 + k) with s = Omega_f - omega. Stable for any k, exact in steady
// state (omega = Omega_f + T_o / beta_r), and beta_r s where k is small.
inline void implicit_drag_torque(double beta_r, double inertia, double dt, const double *spin_slip, const double *other,
                                 double *torque)
{
  const double k = beta_r * dt / inertia;
  for (int d = 0; d < 3; d++)
    torque[d] = (beta_r * spin_slip[d] - k * other[d]) / (1.0 + k);
}

inline double sphere_volume(double radius)
{
  return 4.0 / 3.0 * pi * radius * radius * radius;
}

// Terminal settling speed of a lone sphere (drag = buoyant weight), by bisection; for tests
// and for the log report. g > 0 is the magnitude of gravity.
inline double terminal_speed(const DragModel &m, double diameter, double particle_density, double g)
{
  const double volume = sphere_volume(0.5 * diameter);
  const double weight = (particle_density - m.density) * volume * g;
  if (weight <= 0.0) return 0.0;
  double lo = 0.0, hi = weight / single_sphere_beta(m, diameter, 0.0);    // Stokes bound
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (single_sphere_beta(m, diameter, mid) * mid < weight ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}    // namespace lubricated

// Solid contact of Brandle de Motta et al. (CFM 2011), eq. (4); doc/model.rst, "Solid contact: the
// spring-dashpot".
//
//   F_s = k d + c d_dot,   k = m_e (pi^2 + ln(e_d)^2) / t_c^2,   c = -2 m_e ln(e_d) / t_c
//
// d is the overlap (> 0 in contact), d_dot its growth rate, m_e the reduced mass and
// t_c = N_c dt the contact duration. Both k and c scale with m_e, so the per-type-pair
// constants below are k/m_e and c/m_e (units 1/time^2 and 1/time); a pair multiplies them
// by its own m_e. For this linear oscillator the half period of the damped motion is
// exactly t_c and the ratio of exit to entry speed is exactly e_d (the force is allowed to
// turn slightly attractive at the end of the contact, as in the paper's derivation).
#pragma once

#include <cmath>

namespace lubricated {

constexpr double pi = 3.14159265358979323846;

struct SpringDashpot {
  double stiffness_per_mass = 0.0;    // k / m_e   [1/time^2]
  double damping_per_mass = 0.0;      // c / m_e   [1/time]
};

// e_dry in (0, 1], t_contact > 0 (validated by the caller, see coefficients.h).
inline SpringDashpot spring_dashpot_from_restitution(double e_dry, double t_contact)
{
  const double log_e = std::log(e_dry);
  SpringDashpot sd;
  sd.stiffness_per_mass = (pi * pi + log_e * log_e) / (t_contact * t_contact);
  sd.damping_per_mass = -2.0 * log_e / t_contact;
  return sd;
}

// Restitution coefficient of a continuous linear spring-dashpot with these constants,
// the inverse of spring_dashpot_from_restitution (used by tests and by the log report).
inline double restitution_of(const SpringDashpot &sd)
{
  const double half_rate = 0.5 * sd.damping_per_mass;
  const double omega_d = std::sqrt(sd.stiffness_per_mass - half_rate * half_rate);
  return std::exp(-half_rate * pi / omega_d);
}

// Contact duration (half period of the damped oscillation) of the same oscillator.
inline double contact_duration_of(const SpringDashpot &sd)
{
  const double half_rate = 0.5 * sd.damping_per_mass;
  return pi / std::sqrt(sd.stiffness_per_mass - half_rate * half_rate);
}

}    // namespace lubricated

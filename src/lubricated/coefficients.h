// Coefficients of one contact model (a pair style type pair, or a wall) and their limits.
// Shared by every adapter so that the syntax, the defaults and the error messages are the same
// in pair_coeff, fix wall/lubrication and LIGGGHTS; their keywords, parsing, restart order and
// checks are the table in coefficient_keywords.h (included at the end).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace lubricated {

// eps_activation of `activation dem` (DEM without a resolved fluid): the film hands over to the
// unbounded drag where its coefficient equals the drag's share (lubrication.h,
// drag_handover_activation; doc/model.rst, "DEM without a resolved fluid"). A value no input
// gives (parse_coefficients refuses it typed as a number); kept through pack() and restarts.
constexpr double activation_dem = -std::numeric_limits<double>::max();

struct Coefficients {
  double e_dry = -1.0;             // dry restitution e_d, 0 < e_d <= 1
  double n_contact = 8.0;          // contact duration in steps, 1...1e6 (used when t_contact == 0)
  double t_contact = 0.0;          // contact duration in time units (> 0 overrides N_c)
  double viscosity = 0.0;          // mu_f, 1e-100...1e100; 0 means dry: no lubrication code runs
  double eps_activation = 0.0;     // eps_al (normalised activation gap); activation_dem: `activation dem`
  double grid_spacing = 0.0;       // dx: eps_al = 0.75 dx / R instead of a fixed eps_al
  double eps_saturation = 1e-3;    // eps_1, 1e-12 <= eps_1 < 1
  double eps_release = -1e-2;      // eps_2
  bool exact_contact = true;       // integration exact (contact_step.h) or sampled
  // Tangential model (tangential.h); all off by default: a normal-only contact.
  double friction = 0.0;            // Coulomb coefficient mu_c >= 0; > 0 turns it on
  double e_tangential = -1.0;       // tangential restitution e_t in [0, 1]; < 0: e_d
  double rolling_friction = 0.0;    // rolling resistance mu_r >= 0 (a length ratio)
  int shearfilm = -1;               // shear film: 1 yes, 0 no, -1 yes when friction > 0
  double legendre = 0.0;            // A > 0: contact calibrated to e / e_d = exp(-A / St)
  int rollfilm = 0;                 // rolling film (Jeffrey & Onishi's rolling term): 1 yes, 0 no
  // Not a keyword: t_c = N_c dt settled at the first run that uses these coefficients
  // (settle_contact_time); 0 before. Not packed: a restart settles it again at its first run.
  double settled_contact_time = 0.0;

  static constexpr int packed_size = 15;

  bool wet() const { return viscosity > 0.0; }
  bool dem_activation() const { return eps_activation == activation_dem; }
  double tangential_restitution() const { return e_tangential >= 0.0 ? e_tangential : e_dry; }
  bool shear_film() const { return shearfilm < 0 ? friction > 0.0 : shearfilm == 1; }
  bool roll_film() const { return rollfilm == 1; }
  // Whether the contact needs the tangential kernel (and, for friction, contact history).
  bool tangential() const
  {
    return friction > 0.0 || rolling_friction > 0.0 || (wet() && (shear_film() || roll_film()));
  }
  double contact_time(double dt) const
  {
    return t_contact > 0.0 ? t_contact : settled_contact_time > 0.0 ? settled_contact_time : n_contact * dt;
  }
  double steps_per_contact(double dt) const { return contact_time(dt) / dt; }

  // One value per keyword, in the table's order (coefficient_keywords.h): restart files.
  void pack(double *buf) const;
  void unpack(const double *buf);
};

namespace detail {

inline bool to_number(const std::string &word, double &value)
{
  if (word.empty()) return false;
  char *end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return end && *end == '\0' && std::isfinite(value);
}

// A value as users typed it (%g), not std::to_string's fixed six decimals (1e-06, not 0.000001).
inline std::string number(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

inline std::string range_error(const char *name, double value, const char *allowed)
{
  return std::string(name) + " = " + number(value) + " is out of range (allowed: " + allowed + ")";
}

}    // namespace detail

// Limits on finite values that would make the model's constants non-finite or meaningless.
//
// Dimensional values (t_c, mu_f, dx) lie within 1e-100...1e100 in any unit system (si, cgs,
// real, metal, micro, nano, lj put them within a few decades of 1). Inside these bounds the
// constants built from them, k/m_e ~ 1/t_c^2 and c/m_e ~ 1/t_c, the per-step constants
// ~ 1/dt^2, 6 pi mu_f, 0.75 dx, stay within 1e+-212 and leave their products with masses,
// radii and velocities some 100 decades before the double range (1e+-308) over- or
// underflows (beyond it k/m_e = 0 and the contact is NaN).
constexpr double smallest_dimensional = 1e-100;
constexpr double largest_dimensional = 1e100;
// The per-step constants of the exact contact (contact_step.h), 1 + E^2 - 2 E C ~ (pi/N_c)^2,
// are differences of numbers near 1 and keep ~ 16 - 2 log10(N_c) digits: at N_c = 1e6 the
// rebound is e_d to ~1e-5, at 1e7 to ~1e-3, and from N_c ~ 1e8 on the spring is lost in
// round-off (k' = 0, NaN). A contact longer than a million steps is resolved no better
// with more steps.
constexpr double largest_steps_per_contact = 1e6;
// The film's lambda(eps_1) ~ 1/eps_1 and its integral: eps_1 must be a normal double well
// above underflow (eps_1 = 1e-310 makes 1/eps_1 = inf and the film NaN). A gap of 1e-12 R is
// below an atomic radius for any sphere up to 100 m, so no roughness or molecular film is
// smaller; lambda stays <= 1e12. eps_1 < 1: the expansions hold for gaps below R, and a
// fixed eps_al must exceed eps_1 anyway.
constexpr double smallest_saturation = 1e-12;

namespace detail {

inline bool within(double value, double lo, double hi)
{
  return value >= lo && value <= hi;
}

}    // namespace detail

// Checks that depend on the time step; returns "" when fine. The contact must last
// 1 <= N_c <= 1e6 steps (largest_steps_per_contact) and t_c = N_c dt, from which k/m_e and
// c/m_e follow, 1e-100...1e100 time units (smallest_dimensional, largest_dimensional).
inline std::string validate_time_step(const Coefficients &c, double dt)
{
  if (c.t_contact > 0.0) {
    const double steps = c.steps_per_contact(dt);
    if (!(steps >= 1.0))
      return "tcontact = " + detail::number(c.t_contact) + " is shorter than the time step " + detail::number(dt) +
             " (N_c = t_c / dt >= 1 required)";
    if (!(steps <= largest_steps_per_contact))
      return "tcontact = " + detail::number(c.t_contact) + " is out of range with the time step " + detail::number(dt) +
             ": N_c = t_c / dt = " + detail::number(steps) + " (allowed: 1 <= N_c <= 1e6)";
  } else if (!detail::within(c.contact_time(dt), smallest_dimensional, largest_dimensional)) {
    return "ncontact = " + detail::number(c.n_contact) + " is out of range with the time step " + detail::number(dt) +
           ": t_c = N_c dt = " + detail::number(c.contact_time(dt)) + " (allowed: 1e-100 <= t_c <= 1e100)";
  } else if (c.settled_contact_time > 0.0 &&
             !(c.steps_per_contact(dt) >= 1.0 && c.steps_per_contact(dt) <= largest_steps_per_contact)) {
    return "ncontact = " + detail::number(c.n_contact) + " settled t_c = " + detail::number(c.settled_contact_time) +
           " at the first run; the time step " + detail::number(dt) +
           " gives N_c = t_c / dt = " + detail::number(c.steps_per_contact(dt)) +
           " (allowed: 1 <= N_c <= 1e6; give ncontact again for the new time step)";
  }
  return "";
}

// ncontact N_c means t_c = N_c dt with the time step of the first run that uses the
// coefficients; from then on t_c is the contact's own, as with tcontact: a later time step
// (timestep, fix dt/reset) keeps k and c (a spring that stiffened with a smaller step would
// release energy into a contact under way) and changes only the steps per contact.
// A run without steps (`run 0`, often given before the real time step) settles nothing: it
// evaluates with N_c times the current step.
inline void settle_contact_time(Coefficients &c, double dt, bool run_has_steps = true)
{
  if (run_has_steps && !(c.t_contact > 0.0) && !(c.settled_contact_time > 0.0))
    c.settled_contact_time = c.n_contact * dt;
}

// Advice that is not an error: the paper finds N_c = 8 the smallest count that keeps e_d. A t_c
// of exactly 8 steps computed in floating point (7.999999999999999) is 8.
inline std::string time_step_warning(const Coefficients &c, double dt)
{
  const double n = c.steps_per_contact(dt);
  if (n < 8.0 * (1.0 - 1e-12))
    return "contact resolved with N_c = " + detail::number(n) + " steps; the restitution drifts from e_d below N_c = 8";
  return "";
}

}    // namespace lubricated

#include "lubricated/coefficient_keywords.h"

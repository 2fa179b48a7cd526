// The overlap check (doc/model.rst, "Overlap check"): a contact whose overlap exceeds a fraction
// of the smaller radius (a wall: of the sphere's radius) is too soft for its load or impact
// speed. Above overlap_warning_fraction and above overlap_error_fraction it warns once per run
// each; a centre gone behind a wall after a contact stops the run. The message names the
// contact, its t_c and the t_c that keeps it below. The same in every adapter (LAMMPS pair style
// and walls, LIGGGHTS model lubricated).
#pragma once

#include "lubricated/coefficients.h"

#include <string>

namespace lubricated {

// Beyond half the radius one more step at the same closing speed can put the centre behind a
// wall or deep in a partner; the linear spring-dashpot is a small-overlap model.
constexpr double overlap_error_fraction = 0.5;
// Beyond a tenth the contact is soft for its load or speed (the model is calibrated for small
// overlaps), but the run stays meaningful.
constexpr double overlap_warning_fraction = 0.1;

// The overlap as a fraction of the smaller radius (> 0 in overlap).
inline double overlap_fraction(double gap, double smaller_radius)
{
  return -gap / smaller_radius;
}

// The centre distance below which a pair of radii r_i, r_j overlaps by more than `fraction` of
// the smaller radius (a branch-free test on squared distances in the pair loops).
inline double overlap_distance(double r_i, double r_j, double fraction)
{
  return r_i + r_j - fraction * (r_i < r_j ? r_i : r_j);
}

enum class OverlapLevel { none, warning, error };

inline OverlapLevel overlap_level(double fraction)
{
  return fraction > overlap_error_fraction     ? OverlapLevel::error
         : fraction > overlap_warning_fraction ? OverlapLevel::warning
                                               : OverlapLevel::none;
}

// The overlap grows with t_c at most linearly (an impact: d <= u t_c / pi) or quadratically (a
// steady load: d = F t_c^2 / (m_e (pi^2 + ln^2 e_d))): scaling t_c by limit / fraction (< 1)
// keeps the same contact below `limit` of the radius.
inline double contact_time_below(double contact_time, double fraction, double limit)
{
  return contact_time * limit / fraction;
}

// How the message's advice names the settings of t_c: the LAMMPS plugin's keywords, where
// ncontact settles t_c at the first run's time step (coefficients.h) and each type pair has its
// own, or LIGGGHTS's properties, where t_c = N_c dt follows every time step (steps_follow_dt)
// and one value holds for all type pairs.
struct ContactTimeNames {
  const char *time = "tcontact", *steps = "ncontact";
  bool steps_follow_dt = false, per_type_pair = true;
};

namespace detail {
// The advice's second way to reach t_below, where the contact time is given in steps.
inline std::string steps_advice(const Coefficients &c, double t_below, const ContactTimeNames &names)
{
  if (c.t_contact > 0.0) return "";
  const std::string step = number(t_below / c.n_contact);
  if (names.steps_follow_dt)
    return ", or a time step of " + step + " or less with " + names.steps + " " + number(c.n_contact);
  return ", or " + std::string(names.steps) + " " + number(c.n_contact) + " from a first run at a time step of " +
         step + " or less";
}
}    // namespace detail

// The message for a contact (`who`: "atoms 12 and 5 (types 1 2)", "atom 17 (type 1) and the
// wall of fix floor") overlapping by `fraction` of radius `radius` (gap < 0) under coefficients c
// at step dt. through: the centre went behind the wall it touched (the certain failure); wall:
// the radius is the sphere's; names: how the advice names t_c's settings.
inline std::string overlap_message(const std::string &who, double gap, double radius, double fraction,
                                   const Coefficients &c, double dt, bool through, bool wall = false,
                                   const ContactTimeNames &names = {})
{
  using detail::number;
  const OverlapLevel level = through ? OverlapLevel::error : overlap_level(fraction);
  const double limit = level == OverlapLevel::error ? overlap_error_fraction : overlap_warning_fraction;
  const double t_c = c.contact_time(dt);
  const double t_below = contact_time_below(t_c, fraction, limit);
  std::string text = who;
  if (through)
    text += ": the centre went behind the wall after a contact (overlap d = " + number(-gap) +
            ", radius R = " + number(radius) + ")";
  else
    text += " overlap by " + number(fraction) + (wall ? " of the sphere's radius" : " of the smaller radius") +
            " (d = " + number(-gap) + ", R = " + number(radius) + "; " +
            (level == OverlapLevel::error ? "the limit" : "warned above") + " is " + number(limit) +
            (level == OverlapLevel::warning ? ", reported once per run)" : ")");
  text += ": the contact is too soft for its load or impact speed (k = m_e (pi^2 + ln^2 e_d) / t_c^2). t_c = " +
          number(t_c) + " (N_c = " + number(t_c / dt) + " steps of " + number(dt) + "); t_c <= " + number(t_below) +
          " brings this overlap to " + number(limit) +
          " of the radius (an overlap still growing under a load needs "
          "less): " +
          names.time + " " + number(t_below) + detail::steps_advice(c, t_below, names) +
          (names.per_type_pair ? "; per-type-pair coefficients can give small spheres a shorter t_c" : "") +
          " (doc/model.rst, \"Overlap check\")";
  return text;
}

}    // namespace lubricated

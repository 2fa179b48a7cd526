// The ERROR and WARNING of the contact-network check (contact_network.h), one text for the LAMMPS
// pair style and the LIGGGHTS model (which puts its property names in).
#pragma once

#include "lubricated/coefficients.h"
#include "lubricated/contact_network.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace lubricated {

// What the check found, as every rank knows it after the reductions.
struct NetworkFinding {
  bool unstable = false;                        // a growing mode is proven (lower bound >= 4)
  double load = 0.0;                            // the worst contact's lower bound (unstable) or upper bound
  int type_i = 0, type_j = 0;                   // its types
  long long tag_i = 0, tag_j = 0;               // its atoms
  double contacts_i = 0.0, contacts_j = 0.0;    // their sustained contacts
  double largest_unit_upper = 0.0;              // the largest upper bound per unit load (for the advice)
  double largest_lower = 0.0;                   // the largest lower bound
};

namespace detail {
inline std::string number3(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// A positive value moved to a neighbouring number of 3 significant digits (as number3 prints it
// and a user types it back): the next one up (up) or down, or value itself where it has 3 digits
// and `strict` is false.
inline double step3(double value, bool up, bool strict)
{
  const double unit = std::pow(10.0, std::floor(std::log10(value)) - 2);
  const double k = up ? std::ceil(value / unit) : std::floor(value / unit);
  const double r = std::strtod(number3(k * unit).c_str(), nullptr);
  if (!strict || r != value) return r;
  return std::strtod(number3((up ? k + 1 : k - (k > 100 ? 1 : 0.1)) * unit).c_str(), nullptr);
}
}    // namespace detail

// The contact duration to advise, as printed (3 digits, rounded up): the shortest at which the
// packing's largest upper bound per unit load gives a load below 4 with this type pair's load
// model, and longer than the current one where that fails (the loads fall with the duration).
inline double advised_contact_steps(const ContactLoadModel &load, double unit_upper, double current)
{
  if (!(unit_upper > 0.0)) return current;
  const auto passes = [&](double n) { return load(n) * unit_upper < stable_network_load; };
  const bool fails = !passes(current);
  const double from = std::max(1.0, current);
  double n = detail::step3(contact_steps_for_load(load, stable_network_load / unit_upper, from), true, false);
  const auto good = [&](double m) { return passes(m) && (!fails || m > current); };
  while (n < largest_steps_per_contact && !good(n))
    n = detail::step3(n, true, true);
  for (int k = 0; k < 10 && good(detail::step3(n, false, true)); k++)    // the search's tolerance
    n = detail::step3(n, false, true);
  return std::min(n, largest_steps_per_contact);
}

// The load model of the message's type pair: the pair style's exact or sampled contact and its
// friction's exact tangential spring; with sampled_tangential (LIGGGHTS) a tangential spring
// sampled with the normal constants.
inline ContactLoadModel contact_load_model(const Coefficients &c, bool sampled_tangential)
{
  ContactLoadModel model;
  model.e_n = c.e_dry;
  model.sampled_normal = !c.exact_contact;
  model.e_t = c.friction > 0.0 ? c.tangential_restitution() : -1.0;
  model.sampled_tangential = sampled_tangential;
  return model;
}

// The message for the contacts of type pair (type_i, type_j) with coefficients c at time step dt;
// sampled_tangential: the bound counts a tangential spring sampled with the normal constants
// (the LIGGGHTS model's, contact_load_model).
inline std::string network_message(const std::string &style, const Coefficients &c, double dt, const NetworkFinding &f,
                                   bool sampled_tangential = false, const std::string &wall = "")
{
  using detail::number;
  using detail::number3;
  const double steps = c.steps_per_contact(dt);
  // N_c at which the upper bound of this packing would be below 4 (the same load model).
  const ContactLoadModel load = contact_load_model(c, sampled_tangential);
  const double needed = advised_contact_steps(load, f.largest_unit_upper, steps);
  // The time step for it, rounded down as printed.
  double dt_needed = c.t_contact > 0.0 ? detail::step3(c.t_contact / needed, false, false) : 0.0;
  for (int k = 0; k < 100 && dt_needed > 0.0 && c.t_contact / dt_needed < needed; k++)
    dt_needed = detail::step3(dt_needed, false, true);
  const std::string duration = c.t_contact > 0.0
                                   ? "tcontact = " + number(c.t_contact) + " (N_c = t_c / dt = " + number3(steps) + ")"
                                   : "ncontact = " + number(steps);
  const std::string remedy = c.t_contact > 0.0 ? "a longer tcontact or a timestep <= " + number3(dt_needed) +
                                                     " (N_c >= " + number3(needed) + ")"
                                               : "ncontact >= " + number3(needed);
  // wall: the worst contact is a sphere's with a wall (the finding's tag_i, type_j), so named.
  const std::string atoms =
      wall.empty() ? "atoms " + std::to_string(f.tag_i) + " (" + number(f.contacts_i) + " contacts) and " +
                         std::to_string(f.tag_j) + " (" + number(f.contacts_j) + ")"
                   : "atom " + std::to_string(f.tag_i) + " (" + number(f.contacts_i) + " contacts) and " + wall;
  const std::string types = wall.empty()
                                ? style + " types " + std::to_string(f.type_i) + " " + std::to_string(f.type_j) + ": "
                                : style + " type " + std::to_string(f.type_j) + " and " + wall + ": ";
  if (f.unstable)
    return types + duration + " is too short a contact for this packing: the contacts of " + atoms +
           " have a mode that grows every step (load " + number3(f.load) +
           " >= 4; the springs and dashpots "
           "of a bed are stable under velocity Verlet only below 4: doc page, Dense beds: the contact "
           "network). Use " +
           remedy +
           " (which keeps every mode of this packing stable) or fewer contacts "
           "per sphere";
  return types + "with " + duration +
         " the contact network of this packing is likely unstable: its "
         "load is at least " +
         number3(f.largest_lower) +
         " (a growing mode is proven from 4; the largest "
         "load was at most 1.5 times this bound on random packings) and stability is not guaranteed (" +
         atoms + " reach the upper bound " + number3(f.load) +
         " >= 4). If the energy grows or atoms are "
         "lost, use " +
         remedy;
}

}    // namespace lubricated

// The ERROR and WARNING of the contact-network check (contact_network.h), one text for the LAMMPS
// pair style and the LIGGGHTS model (which puts its property names in).
#pragma once

#include "lubricated/coefficients.h"
#include "lubricated/contact_network.h"

#include <cstdio>
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
}    // namespace detail

// The message for the contacts of type pair (type_i, type_j) with coefficients c at time step dt.
inline std::string network_message(const std::string &style, const Coefficients &c, double dt, const NetworkFinding &f)
{
  using detail::number;
  using detail::number3;
  const double steps = c.steps_per_contact(dt);
  // N_c at which the upper bound of this packing would be below 4 (same e_d and e_t).
  const double needed = contact_steps_for_load(c.e_dry, c.friction > 0.0 ? c.tangential_restitution() : -1.0,
                                               stable_network_load / f.largest_unit_upper);
  const std::string duration = c.t_contact > 0.0
                                   ? "tcontact = " + number(c.t_contact) + " (N_c = t_c / dt = " + number3(steps) + ")"
                                   : "ncontact = " + number(steps);
  const std::string remedy = c.t_contact > 0.0 ? "a longer tcontact or a timestep <= " + number3(c.t_contact / needed) +
                                                     " (N_c >= " + number3(needed) + ")"
                                               : "ncontact >= " + number3(needed);
  const std::string atoms = "atoms " + std::to_string(f.tag_i) + " (" + number(f.contacts_i) + " contacts) and " +
                            std::to_string(f.tag_j) + " (" + number(f.contacts_j) + ")";
  const std::string types = style + " types " + std::to_string(f.type_i) + " " + std::to_string(f.type_j) + ": ";
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

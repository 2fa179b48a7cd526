// What every adapter checks and reports for one set of coefficients (a pair of atom types, or a
// wall) when a run is set up, the same in LAMMPS and LIGGGHTS: the ERROR (empty when the
// coefficients fit the time step), the WARNINGs, and the one-line description of the derived
// contact (k and c per unit reduced mass, the contact's resolution) and film.
#pragma once

#include "lubricated/coefficients.h"
#include "lubricated/normal_model.h"

#include <cstdio>
#include <string>
#include <vector>

namespace lubricated {

struct SetupCheck {
  std::string error;                    // validate_time_step(): stop with it when not empty
  std::vector<std::string> warnings;    // N_c below 8, a calibration that cannot act
  std::string description;              // e_d, t_c, k/m_e, c/m_e, film, integration
  std::string tangential;               // friction, e_t, rolling, shear film ("" without)
};

inline SetupCheck check_setup(const Coefficients &c, Partner partner, double dt)
{
  SetupCheck check;
  check.error = validate_time_step(c, dt);
  if (check.error.empty() && c.wet() && c.dem_activation() && partner != Partner::wall)
    check.error = "activation dem is for walls (fix wall/lubrication); between spheres give activation eps_al or grid "
                  "dx (doc/model.rst, \"DEM without a resolved fluid\")";
  if (check.error.empty() && c.wet() && c.roll_film() && partner == Partner::wall)
    check.error = "rollfilm is for pairs of spheres (pair_style lubricated/springdashpot): at a wall the shear film "
                  "is not the slip term of Jeffrey and Onishi's split (doc/model.rst, \"The rolling mode\")";
  if (!check.error.empty()) return check;
  for (const std::string &w : {time_step_warning(c, dt), calibration_warning(c, partner)})
    if (!w.empty()) check.warnings.push_back(w);
  const NormalModel m = make_normal_model(c, partner, dt);
  char text[256];
  std::snprintf(text, sizeof text, "e_d = %s, t_c = %.6g (%.3g steps), k/m_e = %.6g, c/m_e = %.6g, ",
                detail::number(c.e_dry).c_str(), c.contact_time(dt), c.steps_per_contact(dt),
                m.contact.stiffness_per_mass, m.contact.damping_per_mass);
  const std::string dem = c.dem_activation() ? " (activation dem: eps_al = " + detail::number(activation_of(c)) +
                                                   ", film lambda_pw - 1 over the drag)"
                                             : "";
  check.description = std::string(text) +
                      (c.wet() ? "film mu_f = " + detail::number(c.viscosity) + dem + ", " : "dry, ") +
                      (c.exact_contact ? "integration exact" : "integration sampled");
  if (c.tangential())
    check.tangential =
        "friction mu_c = " + detail::number(c.friction) + ", e_t = " + detail::number(c.tangential_restitution()) +
        ", rolling mu_r = " + detail::number(c.rolling_friction) + ", shear film " +
        (c.wet() && c.shear_film() ? "on" : "off") + ", rolling film " + (c.wet() && c.roll_film() ? "on" : "off");
  return check;
}

}    // namespace lubricated

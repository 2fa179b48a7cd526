// Material properties of LIGGGHTS's `model lubricated`, read from `fix property/global`:
//
//   coefficientRestitution   peratomtypepair  e_d (required, the usual LIGGGHTS property)
//   lubricatedContactSteps   scalar           N_c, contact duration in steps (default 8)
//   lubricatedContactTime    scalar           t_c in time units (instead of N_c)
//   lubricatedViscosity      scalar           mu_f of the fluid (default 0: dry)
//   lubricatedActivation     scalar           eps_al, film activation gap / R
//   lubricatedGridSpacing    scalar           dx: eps_al = 0.75 dx / R (instead of eps_al)
//   lubricatedSaturation     scalar           eps_1 (default 1e-3)
//   lubricatedRelease        scalar           eps_2 (default -1e-2; 0 with lubricatedLegendre)
//   lubricatedLegendre       scalar           A: contact calibrated to e / e_d = exp(-A / St)
//   lubricatedLimitPair      scalar           1: each film capped on its own (default 0)
//
// The coefficient properties are the property column of the kernel's keyword table
// (lubricated/coefficient_keywords.h); the values go through its validate(), the same ranges
// and messages as pair_coeff in the LAMMPS plugin, with each keyword named by its property.
#pragma once

#include "fix_property_global.h"
#include "modify.h"

#include "lubricated/coefficients.h"
#include "lubricated/normal_model.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace lubricated {
namespace liggghts {

// Relative gap beyond contact, in units of r_i + r_j, kept for the step before an impact
// (the step-exact contact acts one step early); neigh_modify contact_distance_factor raises it.
constexpr double approach_margin = 0.02;

// Model options read as properties that are no coefficients (normal_model_lubricated.h).
constexpr const char *limit_pair_property = "lubricatedLimitPair";

// A kernel message with its keywords replaced by the property names users typed.
inline std::string with_property_names(std::string message)
{
  std::string out;
  size_t pos = 0;
  while (pos < message.size()) {
    bool replaced = false;
    for (const CoefficientKeyword &row : coefficient_keywords) {
      if (!row.property) continue;
      const std::string key = row.name;
      const bool start = pos == 0 || !std::isalnum(static_cast<unsigned char>(message[pos - 1]));
      const size_t end = pos + key.size();
      if (start && message.compare(pos, key.size(), key) == 0 &&
          (end == message.size() || !(std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '_'))) {
        out += row.property;
        pos = end;
        replaced = true;
        break;
      }
    }
    if (!replaced) out += message[pos++];
  }
  return out;
}

// The properties the model reads as one global value: every coefficient property but
// coefficientRestitution (per type pair), and lubricatedLimitPair.
inline bool is_scalar_property(const char *name)
{
  for (const CoefficientKeyword &row : coefficient_keywords)
    if (row.id != keyword::e_d && row.property && std::strcmp(name, row.property) == 0) return true;
  return std::strcmp(name, limit_pair_property) == 0;
}

// A scalar property given in another style: LIGGGHTS's lookup by style would skip it silently
// (the model then ran with the default, e.g. dry).
inline std::string scalar_style_error(const std::string &fix_id, const std::string &name, const std::string &style)
{
  return "model lubricated: fix " + fix_id + " property/global " + name + ": style " + style + " is not allowed; " +
         name + " must be scalar (one value for every type pair: fix ID all property/global " + name + " scalar value)";
}

// An optional scalar property: sets value and returns true when it exists. A property/global
// of that name in another style sets message (property_text.cpp refuses it when it is defined;
// this catches one that was not seen there).
inline bool read_scalar(LAMMPS_NS::Modify *modify, const char *name, const char *caller, double &value,
                        std::string &message)
{
  for (int f = 0; f < modify->nfix; f++) {
    if (!modify->fix[f] || std::strcmp(modify->fix[f]->style, "property/global") != 0) continue;
    auto *fix = static_cast<LAMMPS_NS::FixPropertyGlobal *>(modify->fix[f]);
    if (fix->check_fix(name, "scalar", 0, 0, caller, false)) {
      value = fix->compute_scalar();
      return true;
    }
    const bool vector = fix->check_fix(name, "vector", 0, 0, caller, false) != nullptr;
    if (vector || fix->check_fix(name, "matrix", 0, 0, caller, false)) {
      if (message.empty())
        message = scalar_style_error(fix->id, name, vector ? "vector or peratomtype" : "matrix or peratomtypepair");
      return false;
    }
  }
  return false;
}

// Coefficients per type pair, index i * (ntypes + 1) + j; message is set on bad input.
inline std::vector<Coefficients> read_coefficients(LAMMPS_NS::Modify *modify, int ntypes, const char *caller,
                                                   std::string &message)
{
  message.clear();
  std::vector<Coefficients> table((ntypes + 1) * (ntypes + 1));
  auto *restitution = static_cast<LAMMPS_NS::FixPropertyGlobal *>(modify->find_fix_property(
      coefficient_keywords[keyword::e_d].property, "property/global", "peratomtypepair", ntypes, ntypes, caller));
  Coefficients common;    // defaults unless the property exists
  Given given;
  for (const CoefficientKeyword &row : coefficient_keywords) {
    double value = 0.0;
    if (row.id == keyword::e_d || !row.property || !read_scalar(modify, row.property, caller, value, message)) continue;
    row.set(common, value);
    given.keyword[row.id] = true;
  }
  double limit_pair = 0.0;    // read by the model; here for its style check
  read_scalar(modify, limit_pair_property, caller, limit_pair, message);
  if (!message.empty()) return table;
  complete_defaults(common, given);

  for (int i = 1; i <= ntypes; i++)
    for (int j = 1; j <= ntypes; j++) {
      Coefficients c = common;
      c.e_dry = restitution->compute_array(i - 1, j - 1);
      const std::string error = validate_given(c, given);    // the pair_coeff checks
      if (!error.empty()) {
        message = std::string(caller) + ": types " + std::to_string(i) + " " + std::to_string(j) + ": " +
                  with_property_names(error);
        return table;
      }
      table[i * (ntypes + 1) + j] = c;
    }
  return table;
}

inline std::vector<NormalModel> build_models(const std::vector<Coefficients> &table, int ntypes, bool wall, double dt,
                                             std::string &message)
{
  message.clear();
  std::vector<NormalModel> models(table.size());
  for (int i = 1; i <= ntypes; i++)
    for (int j = 1; j <= ntypes; j++) {
      const Coefficients &c = table[i * (ntypes + 1) + j];
      const std::string error = validate_time_step(c, dt);
      if (!error.empty()) {
        message = "model lubricated: " + with_property_names(error);
        return models;
      }
      models[i * (ntypes + 1) + j] = make_normal_model(c, wall ? Partner::wall : Partner::particle, dt);
    }
  return models;
}

// Largest film reach beyond contact in units of the distance LIGGGHTS scales by its contact
// distance factor: r_i + r_j for pairs (reach eps_al R with R = 2 r_i r_j / (r_i + r_j),
// at most eps_al / 2 of r_i + r_j), r_i for walls. A grid spacing needs the smallest radius;
// returns -1 when it is unknown (no particles yet).
inline double reach_fraction(const std::vector<Coefficients> &table, int ntypes, bool wall, double r_min)
{
  double reach = 0.0;
  for (int i = 1; i <= ntypes; i++)
    for (int j = 1; j <= ntypes; j++) {
      const Coefficients &c = table[i * (ntypes + 1) + j];
      if (!c.wet()) continue;
      double fraction = wall ? c.eps_activation : 0.5 * c.eps_activation;
      if (c.grid_spacing > 0.0) {    // reach 0.75 dx whatever the radii
        if (!(r_min > 0.0)) return -1.0;
        fraction = lubricated::Lubrication::grid_activation * c.grid_spacing / (wall ? r_min : 2.0 * r_min);
      }
      reach = std::max(reach, fraction);
    }
  return reach;
}

inline std::string missed_approach_warning(double u_n, double dt, double factor)
{
  return "model lubricated: an impact at normal speed " + detail::number(std::fabs(u_n)) +
         " started farther away than the contact distance (contact_distance_factor " + detail::number(factor) +
         ") one step before; its first contact step is integrated "
         "approximately. Raise neigh_modify contact_distance_factor so that (factor - 1) (r_i + r_j) "
         "exceeds the largest approach per step (" +
         detail::number(std::fabs(u_n) * dt) + ")";
}

}    // namespace liggghts
}    // namespace lubricated

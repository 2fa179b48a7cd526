// Coefficients of one contact model (a pair style type pair, or a wall), their keyword
// syntax and their validation. Shared by every adapter so that the syntax, the defaults and
// the error messages are the same in pair_coeff, fix wall/lubrication and LIGGGHTS.
//
//   e_d [ncontact N | tcontact t_c] [viscosity mu_f] [activation eps_al | activation dem | grid dx]
//       [saturation eps_1] [release eps_2] [integration exact | sampled]
//       [friction mu_c] [tangential e_t] [rolling mu_r] [shearfilm yes | no] [legendre A]
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
  // Not a keyword: t_c = N_c dt settled at the first run that uses these coefficients
  // (settle_contact_time); 0 before. Not packed: a restart settles it again at its first run.
  double settled_contact_time = 0.0;

  static constexpr int packed_size = 14;

  bool wet() const { return viscosity > 0.0; }
  bool dem_activation() const { return eps_activation == activation_dem; }
  double tangential_restitution() const { return e_tangential >= 0.0 ? e_tangential : e_dry; }
  bool shear_film() const { return shearfilm < 0 ? friction > 0.0 : shearfilm == 1; }
  // Whether the contact needs the tangential kernel (and, for friction, contact history).
  bool tangential() const { return friction > 0.0 || rolling_friction > 0.0 || (wet() && shear_film()); }
  double contact_time(double dt) const
  {
    return t_contact > 0.0 ? t_contact : settled_contact_time > 0.0 ? settled_contact_time : n_contact * dt;
  }
  double steps_per_contact(double dt) const { return contact_time(dt) / dt; }

  void pack(double *buf) const
  {
    const double v[packed_size] = {e_dry,
                                   n_contact,
                                   t_contact,
                                   viscosity,
                                   eps_activation,
                                   grid_spacing,
                                   eps_saturation,
                                   eps_release,
                                   exact_contact ? 1.0 : 0.0,
                                   friction,
                                   e_tangential,
                                   rolling_friction,
                                   static_cast<double>(shearfilm),
                                   legendre};
    for (int i = 0; i < packed_size; ++i)
      buf[i] = v[i];
  }
  void unpack(const double *buf)
  {
    e_dry = buf[0];
    n_contact = buf[1];
    t_contact = buf[2];
    viscosity = buf[3];
    eps_activation = buf[4];
    grid_spacing = buf[5];
    eps_saturation = buf[6];
    eps_release = buf[7];
    exact_contact = buf[8] != 0.0;
    friction = buf[9];
    e_tangential = buf[10];
    rolling_friction = buf[11];
    shearfilm = static_cast<int>(buf[12]);
    legendre = buf[13];
  }
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

// Checks every value against its allowed range; returns "" when all are valid. Conditions
// are written so that NaN fails them.
inline std::string validate(const Coefficients &c)
{
  using detail::range_error;
  using detail::within;
  if (!(c.e_dry > 0.0 && c.e_dry <= 1.0)) return range_error("e_d", c.e_dry, "0 < e_d <= 1");
  if (c.t_contact > 0.0) {
    if (!within(c.t_contact, smallest_dimensional, largest_dimensional))
      return range_error("tcontact", c.t_contact, "1e-100 <= t_c <= 1e100");
  } else if (!within(c.n_contact, 1.0, largest_steps_per_contact)) {
    return range_error("ncontact", c.n_contact, "1 <= N_c <= 1e6");
  }
  if (!(c.viscosity == 0.0 || within(c.viscosity, smallest_dimensional, largest_dimensional)))
    return range_error("viscosity", c.viscosity, "mu_f = 0 (dry) or 1e-100 <= mu_f <= 1e100");
  if (!(c.eps_saturation >= smallest_saturation && c.eps_saturation < 1.0))
    return range_error("saturation", c.eps_saturation, "1e-12 <= eps_1 < 1");
  if (!(c.eps_release < c.eps_saturation))
    return "release = " + detail::number(c.eps_release) +
           " must be below saturation = " + detail::number(c.eps_saturation) + " (eps_2 < eps_1 required)";
  if (!(c.friction >= 0.0)) return range_error("friction", c.friction, "mu_c >= 0");
  if (c.e_tangential != -1.0 && !(c.e_tangential >= 0.0 && c.e_tangential <= 1.0))
    return range_error("tangential", c.e_tangential, "0 <= e_t <= 1");
  if (!(c.rolling_friction >= 0.0)) return range_error("rolling", c.rolling_friction, "mu_r >= 0");
  if (!(c.legendre >= 0.0)) return range_error("legendre", c.legendre, "A >= 0");
  if (c.legendre > 0.0) {
    if (!c.wet()) return "legendre needs a wet contact (viscosity > 0)";
    if (!c.exact_contact) return "legendre needs integration exact";
    if (c.eps_release < 0.0)
      return "release = " + detail::number(c.eps_release) +
             " is out of range with legendre (allowed: 0 <= eps_2 < eps_1; the calibrated contact "
             "replaces the film in overlap)";
  }
  if (c.wet()) {
    if (c.grid_spacing != 0.0 && !within(c.grid_spacing, smallest_dimensional, largest_dimensional))
      return range_error("grid", c.grid_spacing, "1e-100 <= dx <= 1e100");
    if (c.grid_spacing == 0.0) {
      if (c.eps_activation == 0.0) return "viscosity > 0 requires the activation (eps_al) or grid (dx) keyword";
      if (!c.dem_activation() && !(c.eps_activation > c.eps_saturation && c.eps_activation <= 1.0))
        return "activation = " + detail::number(c.eps_activation) +
               " is out of range (allowed: saturation eps_1 < eps_al <= 1)";
    }
  }
  return "";
}

// Which of the keywords with alternatives or sentinel defaults were given (pair_coeff words,
// or LIGGGHTS properties that exist).
struct Given {
  bool ncontact = false, tcontact = false, activation = false, grid = false, tangential = false, release = false;
};

// Defaults that depend on other keywords: with legendre the film ends at contact (eps_2 = 0),
// because the calibrated contact stands for the film in overlap.
inline void complete_defaults(Coefficients &c, const Given &given)
{
  if (c.legendre > 0.0 && !given.release) c.eps_release = 0.0;
}

// The checks that depend on which keywords were given, then validate().
inline std::string validate_given(const Coefficients &c, const Given &given)
{
  if (given.ncontact && given.tcontact) return "ncontact and tcontact are mutually exclusive";
  if (given.activation && given.grid) return "activation and grid are mutually exclusive";
  if (given.tangential && !(c.e_tangential >= 0.0 && c.e_tangential <= 1.0))
    return detail::range_error("tangential", c.e_tangential, "0 <= e_t <= 1");
  if (given.tcontact && !detail::within(c.t_contact, smallest_dimensional, largest_dimensional))
    return detail::range_error("tcontact", c.t_contact, "1e-100 <= t_c <= 1e100");
  if (given.grid && !detail::within(c.grid_spacing, smallest_dimensional, largest_dimensional))
    return detail::range_error("grid", c.grid_spacing, "1e-100 <= dx <= 1e100");
  return validate(c);
}

// Parses "e_d keyword value ..." from words[first..]; returns "" on success, else a message
// naming the offending word. The result is validated.
inline std::string parse_coefficients(const std::vector<std::string> &words, size_t first, Coefficients &c)
{
  c = Coefficients();
  if (words.size() <= first) return "missing e_d (dry restitution coefficient)";
  if (!detail::to_number(words[first], c.e_dry)) return "expected a number for e_d, got '" + words[first] + "'";
  Given given;
  for (size_t i = first + 1; i < words.size(); i += 2) {
    const std::string &key = words[i];
    if (key == "integration") {
      if (i + 1 >= words.size()) return "missing value for keyword integration";
      if (words[i + 1] != "exact" && words[i + 1] != "sampled")
        return "integration must be exact or sampled, got '" + words[i + 1] + "'";
      c.exact_contact = words[i + 1] == "exact";
      continue;
    }
    if (key == "shearfilm") {
      if (i + 1 >= words.size()) return "missing value for keyword shearfilm";
      if (words[i + 1] != "yes" && words[i + 1] != "no")
        return "shearfilm must be yes or no, got '" + words[i + 1] + "'";
      c.shearfilm = words[i + 1] == "yes" ? 1 : 0;
      continue;
    }
    if (key == "activation" && i + 1 < words.size() && words[i + 1] == "dem") {
      c.eps_activation = activation_dem, given.activation = true;
      continue;
    }
    double *target = nullptr;
    if (key == "ncontact")
      target = &c.n_contact, given.ncontact = true;
    else if (key == "tcontact")
      target = &c.t_contact, given.tcontact = true;
    else if (key == "viscosity")
      target = &c.viscosity;
    else if (key == "activation")
      target = &c.eps_activation, given.activation = true;
    else if (key == "grid")
      target = &c.grid_spacing, given.grid = true;
    else if (key == "saturation")
      target = &c.eps_saturation;
    else if (key == "release")
      target = &c.eps_release, given.release = true;
    else if (key == "friction")
      target = &c.friction;
    else if (key == "tangential")
      target = &c.e_tangential, given.tangential = true;
    else if (key == "rolling")
      target = &c.rolling_friction;
    else if (key == "legendre")
      target = &c.legendre;
    else
      return "unknown keyword '" + key +
             "' (expected ncontact, tcontact, viscosity, activation, grid, saturation, release, "
             "integration, friction, tangential, rolling, shearfilm or legendre)";
    if (i + 1 >= words.size()) return "missing value for keyword " + key;
    if (!detail::to_number(words[i + 1], *target))
      return "expected a number for keyword " + key + (key == "activation" ? " (or dem)" : "") + ", got '" +
             words[i + 1] + "'";
    if (target == &c.eps_activation && c.dem_activation())
      return detail::range_error("activation", c.eps_activation, "saturation eps_1 < eps_al <= 1, or dem");
  }
  complete_defaults(c, given);
  return validate_given(c, given);
}

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

// The coefficients as pair_coeff words (write_data's Pair Coeffs): parse_coefficients() of this
// text gives them back exactly (%.17g). Keywords at their defaults are left out.
inline std::string coefficients_words(const Coefficients &c)
{
  auto number = [](double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return std::string(text);
  };
  std::string words = number(c.e_dry);
  words += c.t_contact > 0.0 ? " tcontact " + number(c.t_contact) : " ncontact " + number(c.n_contact);
  if (c.wet()) {
    words += " viscosity " + number(c.viscosity);
    words += c.grid_spacing > 0.0 ? " grid " + number(c.grid_spacing)
             : c.dem_activation() ? std::string(" activation dem")
                                  : " activation " + number(c.eps_activation);
    words += " saturation " + number(c.eps_saturation) + " release " + number(c.eps_release);
  }
  if (!c.exact_contact) words += " integration sampled";
  if (c.friction > 0.0) words += " friction " + number(c.friction);
  if (c.e_tangential >= 0.0) words += " tangential " + number(c.e_tangential);
  if (c.rolling_friction > 0.0) words += " rolling " + number(c.rolling_friction);
  if (c.shearfilm >= 0) words += c.shearfilm == 1 ? " shearfilm yes" : " shearfilm no";
  if (c.legendre > 0.0) words += " legendre " + number(c.legendre);
  return words;
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

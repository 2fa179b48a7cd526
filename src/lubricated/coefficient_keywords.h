// The coefficient keywords as one table: pair_coeff and fix wall/lubrication(/region) parse
// their words with it, restart files pack its values in its order, write_data writes its words,
// the messages name its keywords and ranges, and LIGGGHTS reads its properties from it.
//
//   e_d [ncontact N | tcontact t_c] [viscosity mu_f] [activation eps_al | activation dem | grid dx]
//       [saturation eps_1] [release eps_2] [integration exact | sampled]
//       [friction mu_c] [tangential e_t] [rolling mu_r] [shearfilm yes | no] [legendre A]
//       [rollfilm yes | no]
//
// A new coefficient is a member of Coefficients, an entry of keyword::Id and a row of
// coefficient_keywords (appended: the row's index is its place in restart files), plus its
// checks in validate() when they are more than a range.
#pragma once

#include "lubricated/coefficients.h"

#include <string>
#include <vector>

namespace lubricated {

namespace keyword {
// Rows of coefficient_keywords, in restart-file order.
enum Id : int {
  e_d,    // the leading value, not a keyword
  ncontact,
  tcontact,
  viscosity,
  activation,
  grid,
  saturation,
  release,
  integration,
  friction,
  tangential,
  rolling,
  shearfilm,
  legendre,
  rollfilm,
  count
};
}    // namespace keyword

// A word that stands for a value (integration exact, shearfilm no, activation dem).
struct NamedValue {
  const char *word;
  double value;
};

struct CoefficientKeyword {
  keyword::Id id;
  const char *name;        // the pair_coeff keyword (e_d: the name in messages)
  const char *property;    // LIGGGHTS fix property/global name; nullptr: none
  const char *allowed;     // the allowed values in messages; nullptr: only the named values
  NamedValue named[2];     // words that stand for values ({nullptr, 0}: none)
  double (*get)(const Coefficients &);
  void (*set)(Coefficients &, double);
  // Written by coefficients_words also at its default; nullptr: only when it differs.
  bool (*shown)(const Coefficients &);

  bool takes_number() const { return allowed != nullptr; }
};

// clang-format off
inline constexpr CoefficientKeyword coefficient_keywords[keyword::count] = {
    {keyword::e_d, "e_d", "coefficientRestitution", "0 < e_d <= 1", {},
     [](const Coefficients &c) { return c.e_dry; }, [](Coefficients &c, double v) { c.e_dry = v; },
     [](const Coefficients &) { return true; }},
    {keyword::ncontact, "ncontact", "lubricatedContactSteps", "1 <= N_c <= 1e6", {},
     [](const Coefficients &c) { return c.n_contact; }, [](Coefficients &c, double v) { c.n_contact = v; },
     [](const Coefficients &c) { return !(c.t_contact > 0.0); }},
    {keyword::tcontact, "tcontact", "lubricatedContactTime", "1e-100 <= t_c <= 1e100", {},
     [](const Coefficients &c) { return c.t_contact; }, [](Coefficients &c, double v) { c.t_contact = v; }, nullptr},
    {keyword::viscosity, "viscosity", "lubricatedViscosity", "mu_f = 0 (dry) or 1e-100 <= mu_f <= 1e100", {},
     [](const Coefficients &c) { return c.viscosity; }, [](Coefficients &c, double v) { c.viscosity = v; }, nullptr},
    {keyword::activation, "activation", "lubricatedActivation", "saturation eps_1 < eps_al <= 1",
     {{"dem", activation_dem}},
     [](const Coefficients &c) { return c.eps_activation; }, [](Coefficients &c, double v) { c.eps_activation = v; },
     [](const Coefficients &c) { return c.wet() && !(c.grid_spacing > 0.0); }},
    {keyword::grid, "grid", "lubricatedGridSpacing", "1e-100 <= dx <= 1e100", {},
     [](const Coefficients &c) { return c.grid_spacing; }, [](Coefficients &c, double v) { c.grid_spacing = v; },
     nullptr},
    {keyword::saturation, "saturation", "lubricatedSaturation", "1e-12 <= eps_1 < 1", {},
     [](const Coefficients &c) { return c.eps_saturation; }, [](Coefficients &c, double v) { c.eps_saturation = v; },
     [](const Coefficients &c) { return c.wet(); }},
    {keyword::release, "release", "lubricatedRelease", "eps_2 < eps_1", {},
     [](const Coefficients &c) { return c.eps_release; }, [](Coefficients &c, double v) { c.eps_release = v; },
     [](const Coefficients &c) { return c.wet(); }},
    {keyword::integration, "integration", nullptr, nullptr, {{"exact", 1.0}, {"sampled", 0.0}},
     [](const Coefficients &c) { return c.exact_contact ? 1.0 : 0.0; },
     [](Coefficients &c, double v) { c.exact_contact = v != 0.0; }, nullptr},
    {keyword::friction, "friction", nullptr, "mu_c >= 0", {},
     [](const Coefficients &c) { return c.friction; }, [](Coefficients &c, double v) { c.friction = v; }, nullptr},
    {keyword::tangential, "tangential", nullptr, "0 <= e_t <= 1", {},
     [](const Coefficients &c) { return c.e_tangential; }, [](Coefficients &c, double v) { c.e_tangential = v; },
     nullptr},
    {keyword::rolling, "rolling", nullptr, "mu_r >= 0", {},
     [](const Coefficients &c) { return c.rolling_friction; },
     [](Coefficients &c, double v) { c.rolling_friction = v; }, nullptr},
    {keyword::shearfilm, "shearfilm", nullptr, nullptr, {{"yes", 1.0}, {"no", 0.0}},
     [](const Coefficients &c) { return static_cast<double>(c.shearfilm); },
     [](Coefficients &c, double v) { c.shearfilm = static_cast<int>(v); }, nullptr},
    {keyword::legendre, "legendre", "lubricatedLegendre", "A >= 0", {},
     [](const Coefficients &c) { return c.legendre; }, [](Coefficients &c, double v) { c.legendre = v; }, nullptr},
    {keyword::rollfilm, "rollfilm", nullptr, nullptr, {{"yes", 1.0}, {"no", 0.0}},
     [](const Coefficients &c) { return static_cast<double>(c.rollfilm); },
     [](Coefficients &c, double v) { c.rollfilm = static_cast<int>(v); }, nullptr},
};
// clang-format on

namespace detail {

constexpr bool rows_in_order(int k = 0)
{
  return k == keyword::count || (coefficient_keywords[k].id == k && rows_in_order(k + 1));
}

}    // namespace detail

static_assert(detail::rows_in_order(), "coefficient_keywords: row k must be keyword::Id k");
static_assert(Coefficients::packed_size == keyword::count, "a restart file holds one value per keyword");

inline void Coefficients::pack(double *buf) const
{
  for (const CoefficientKeyword &row : coefficient_keywords)
    buf[row.id] = row.get(*this);
}

inline void Coefficients::unpack(const double *buf)
{
  for (const CoefficientKeyword &row : coefficient_keywords)
    row.set(*this, buf[row.id]);
}

// The row of a pair_coeff keyword; nullptr when there is none (e_d is no keyword).
inline const CoefficientKeyword *find_keyword(const std::string &word)
{
  for (const CoefficientKeyword &row : coefficient_keywords)
    if (row.id != keyword::e_d && word == row.name) return &row;
  return nullptr;
}

// "ncontact, tcontact, ... legendre or rollfilm"
inline std::string keyword_list()
{
  std::string list = coefficient_keywords[keyword::e_d + 1].name;
  for (int k = keyword::e_d + 2; k < keyword::count; k++)
    list += std::string(k + 1 == keyword::count ? " or " : ", ") + coefficient_keywords[k].name;
  return list;
}

// "<name> = <value> is out of range (allowed: <the row's range>)"
inline std::string out_of_range(keyword::Id k, double value)
{
  return detail::range_error(coefficient_keywords[k].name, value, coefficient_keywords[k].allowed);
}

// Which keywords were given (pair_coeff words, or LIGGGHTS properties that exist): the checks
// of keywords with alternatives or sentinel defaults depend on it.
struct Given {
  bool keyword[keyword::count] = {};
  bool operator[](keyword::Id k) const { return keyword[k]; }
};

// Defaults that depend on other keywords: with legendre the film ends at contact (eps_2 = 0),
// because the calibrated contact stands for the film in overlap.
inline void complete_defaults(Coefficients &c, const Given &given)
{
  if (c.legendre > 0.0 && !given[keyword::release]) c.eps_release = 0.0;
}

// Checks every value against its allowed range; returns "" when all are valid. Conditions
// are written so that NaN fails them.
inline std::string validate(const Coefficients &c)
{
  using detail::within;
  using namespace keyword;
  if (!(c.e_dry > 0.0 && c.e_dry <= 1.0)) return out_of_range(e_d, c.e_dry);
  if (c.t_contact > 0.0) {
    if (!within(c.t_contact, smallest_dimensional, largest_dimensional)) return out_of_range(tcontact, c.t_contact);
  } else if (!within(c.n_contact, 1.0, largest_steps_per_contact)) {
    return out_of_range(ncontact, c.n_contact);
  }
  if (!(c.viscosity == 0.0 || within(c.viscosity, smallest_dimensional, largest_dimensional)))
    return out_of_range(viscosity, c.viscosity);
  if (!(c.eps_saturation >= smallest_saturation && c.eps_saturation < 1.0))
    return out_of_range(saturation, c.eps_saturation);
  if (!(c.eps_release < c.eps_saturation))
    return "release = " + detail::number(c.eps_release) +
           " must be below saturation = " + detail::number(c.eps_saturation) + " (eps_2 < eps_1 required)";
  if (!(c.friction >= 0.0)) return out_of_range(friction, c.friction);
  if (c.e_tangential != -1.0 && !(c.e_tangential >= 0.0 && c.e_tangential <= 1.0))
    return out_of_range(tangential, c.e_tangential);
  if (!(c.rolling_friction >= 0.0)) return out_of_range(rolling, c.rolling_friction);
  if (!(c.legendre >= 0.0)) return out_of_range(legendre, c.legendre);
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
      return out_of_range(grid, c.grid_spacing);
    if (c.grid_spacing == 0.0) {
      if (c.eps_activation == 0.0) return "viscosity > 0 requires the activation (eps_al) or grid (dx) keyword";
      if (!c.dem_activation() && !(c.eps_activation > c.eps_saturation && c.eps_activation <= 1.0))
        return out_of_range(activation, c.eps_activation);
    }
  }
  return "";
}

// The checks that depend on which keywords were given, then validate().
inline std::string validate_given(const Coefficients &c, const Given &given)
{
  using namespace keyword;
  if (given[ncontact] && given[tcontact]) return "ncontact and tcontact are mutually exclusive";
  if (given[activation] && given[grid]) return "activation and grid are mutually exclusive";
  if (given[tangential] && !(c.e_tangential >= 0.0 && c.e_tangential <= 1.0))
    return out_of_range(tangential, c.e_tangential);
  if (given[tcontact] && !detail::within(c.t_contact, smallest_dimensional, largest_dimensional))
    return out_of_range(tcontact, c.t_contact);
  if (given[grid] && !detail::within(c.grid_spacing, smallest_dimensional, largest_dimensional))
    return out_of_range(grid, c.grid_spacing);
  return validate(c);
}

namespace detail {

// Sets row's value from word (a named value, or a number where the row takes one).
inline std::string parse_value(const CoefficientKeyword &row, const std::string &word, Coefficients &c)
{
  const NamedValue &first = row.named[0], &second = row.named[1];
  for (const NamedValue &named : row.named)
    if (named.word && word == named.word) {
      row.set(c, named.value);
      return "";
    }
  if (!row.takes_number())
    return std::string(row.name) + " must be " + first.word + " or " + second.word + ", got '" + word + "'";
  double value = 0.0;
  if (!to_number(word, value))
    return std::string("expected a number for keyword ") + row.name +
           (first.word ? std::string(" (or ") + first.word + ")" : "") + ", got '" + word + "'";
  if (first.word && value == first.value)    // a value only its word gives
    return range_error(row.name, value, (std::string(row.allowed) + ", or " + first.word).c_str());
  row.set(c, value);
  return "";
}

}    // namespace detail

// Parses "e_d keyword value ..." from words[first..]; returns "" on success, else a message
// naming the offending word. The result is validated.
inline std::string parse_coefficients(const std::vector<std::string> &words, size_t first, Coefficients &c)
{
  c = Coefficients();
  if (words.size() <= first) return "missing e_d (dry restitution coefficient)";
  if (!detail::to_number(words[first], c.e_dry)) return "expected a number for e_d, got '" + words[first] + "'";
  Given given;
  for (size_t i = first + 1; i < words.size(); i += 2) {
    const CoefficientKeyword *row = find_keyword(words[i]);
    if (!row) return "unknown keyword '" + words[i] + "' (expected " + keyword_list() + ")";
    if (i + 1 >= words.size()) return "missing value for keyword " + words[i];
    const std::string problem = detail::parse_value(*row, words[i + 1], c);
    if (!problem.empty()) return problem;
    given.keyword[row->id] = true;
  }
  complete_defaults(c, given);
  return validate_given(c, given);
}

// The coefficients as pair_coeff words (write_data's Pair Coeffs): parse_coefficients() of this
// text gives them back exactly (%.17g). A keyword is written where it differs from its default
// or its row shows it (ncontact without tcontact, the film's values when wet).
inline std::string coefficients_words(const Coefficients &c)
{
  const Coefficients defaults;
  std::string words;
  for (const CoefficientKeyword &row : coefficient_keywords) {
    const double value = row.get(c);
    if (!(value != row.get(defaults) || (row.shown && row.shown(c)))) continue;
    if (row.id != keyword::e_d) words += std::string(" ") + row.name + " ";
    const char *named = nullptr;
    for (const NamedValue &n : row.named)
      if (n.word && value == n.value) named = n.word;
    char number[32];
    std::snprintf(number, sizeof number, "%.17g", value);
    words += named ? named : number;
  }
  return words;
}

}    // namespace lubricated

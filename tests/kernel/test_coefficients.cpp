// Keyword parsing and range checks shared by pair_coeff and fix wall/lubrication: every
// bad value is rejected with a message that names the parameter and the allowed range.
#include "lubricated/check_setup.h"
#include "lubricated/coefficients.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace lubricated;

// The coefficients as a restart file carries them (pack, then unpack).
static Coefficients restart_copy(const Coefficients &c)
{
  double buf[Coefficients::packed_size];
  c.pack(buf);
  Coefficients back;
  back.unpack(buf);
  return back;
}

static std::string parse(const std::string &line, Coefficients &c)
{
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;)
    words.push_back(w);
  return parse_coefficients(words, 0, c);
}

TEST(Coefficients, DefaultsOfThePaper)
{
  Coefficients c;
  ASSERT_EQ(parse("0.9", c), "");
  EXPECT_EQ(c.e_dry, 0.9);
  EXPECT_EQ(c.n_contact, 8.0);
  EXPECT_EQ(c.eps_saturation, 1e-3);
  EXPECT_EQ(c.eps_release, -1e-2);
  EXPECT_FALSE(c.wet());
  EXPECT_DOUBLE_EQ(c.contact_time(0.5), 4.0);
}

TEST(Coefficients, AllKeywords)
{
  Coefficients c;
  ASSERT_EQ(parse("0.5 tcontact 2e-4 viscosity 1e-3 activation 0.1 saturation 2e-3 release -0.02", c), "");
  EXPECT_EQ(c.t_contact, 2e-4);
  EXPECT_DOUBLE_EQ(c.contact_time(1e-5), 2e-4);
  EXPECT_EQ(c.viscosity, 1e-3);
  EXPECT_EQ(c.eps_activation, 0.1);
  EXPECT_EQ(c.eps_saturation, 2e-3);
  EXPECT_EQ(c.eps_release, -0.02);
  ASSERT_EQ(parse("0.5 ncontact 16 viscosity 1e-3 grid 1e-4", c), "");
  EXPECT_EQ(c.grid_spacing, 1e-4);
  const Coefficients d = restart_copy(c);
  EXPECT_EQ(d.n_contact, 16.0);
  EXPECT_EQ(d.grid_spacing, 1e-4);
}

struct BadInput {
  const char *line;
  const char *must_mention;
};

class Rejects : public ::testing::TestWithParam<BadInput> {};

TEST_P(Rejects, WithAMessageNamingTheParameter)
{
  Coefficients c;
  const std::string msg = parse(GetParam().line, c);
  EXPECT_NE(msg.find(GetParam().must_mention), std::string::npos)
      << "input '" << GetParam().line << "' gave '" << msg << "'";
}

INSTANTIATE_TEST_SUITE_P(
    BadValues, Rejects,
    ::testing::Values(BadInput{"0", "e_d = 0"}, BadInput{"-0.5", "0 < e_d <= 1"}, BadInput{"1.01", "e_d = 1.01"},
                      BadInput{"nan", "e_d"}, BadInput{"abc", "e_d, got 'abc'"}, BadInput{"", "missing e_d"},
                      BadInput{"0.9 ncontact 0.5", "1 <= N_c <= 1e6"},
                      BadInput{"0.9 tcontact 0", "tcontact = 0 is out of range (allowed: 1e-100 <= t_c <= 1e100)"},
                      BadInput{"0.9 ncontact 8 tcontact 1", "mutually exclusive"},
                      BadInput{"0.9 viscosity -1",
                               "viscosity = -1 is out of range (allowed: mu_f = 0 (dry) or 1e-100 <= mu_f <= 1e100)"},
                      BadInput{"0.9 viscosity 1e-3", "activation"},
                      BadInput{"0.9 viscosity 1e-3 activation 1e-4", "eps_al"},
                      BadInput{"0.9 viscosity 1e-3 activation 2", "eps_al <= 1"},
                      BadInput{"0.9 viscosity 1e-3 grid -1",
                               "grid = -1 is out of range (allowed: 1e-100 <= dx <= 1e100)"},
                      BadInput{"0.9 viscosity 1e-3 grid 1 activation 0.1", "mutually exclusive"},
                      BadInput{"0.9 saturation 0", "saturation = 0 is out of range (allowed: 1e-12 <= eps_1 < 1)"},
                      BadInput{"0.9 saturation 1e-3 release 1e-3", "eps_2 < eps_1"},
                      BadInput{"0.9 frobnicate 3", "unknown keyword 'frobnicate'"},
                      BadInput{"0.9 viscosity", "missing value for keyword viscosity"},
                      BadInput{"0.9 viscosity x", "keyword viscosity, got 'x'"},
                      BadInput{"0.9 viscosity 1e-3 activation 0.1 legendre -35", "A >= 0"},
                      BadInput{"0.9 legendre 35", "legendre needs a wet contact (viscosity > 0)"},
                      BadInput{"0.9 viscosity 1e-3 activation 0.1 legendre 35 integration sampled",
                               "legendre needs integration exact"},
                      BadInput{"0.9 viscosity 1e-3 activation 0.1 legendre 35 release -0.01",
                               "release = -0.01 is out of range with legendre"},
                      BadInput{"0.9 rollfilm maybe", "rollfilm must be yes or no, got 'maybe'"},
                      BadInput{"0.9 rollfilm 1", "rollfilm must be yes or no, got '1'"},
                      BadInput{"0.9 rollfilm", "missing value for keyword rollfilm"}));

// Finite but absurd values (issue 17): each stops with its name, its value and the range,
// instead of a NaN or an infinity in the model's constants (k = 0 at N_c = 1e160, 1/eps_1 = inf
// at eps_1 = 1e-310, ...). The limits and why: coefficients.h.
INSTANTIATE_TEST_SUITE_P(
    AbsurdValues, Rejects,
    ::testing::Values(
        BadInput{"0.9 ncontact 1e160", "ncontact = 1e+160 is out of range (allowed: 1 <= N_c <= 1e6)"},
        BadInput{"0.9 ncontact 2e6", "ncontact = 2e+06 is out of range (allowed: 1 <= N_c <= 1e6)"},
        BadInput{"0.9 tcontact 1e300", "tcontact = 1e+300 is out of range (allowed: 1e-100 <= t_c <= 1e100)"},
        BadInput{"0.9 tcontact 1e-300", "tcontact = 1e-300 is out of range (allowed: 1e-100 <= t_c <= 1e100)"},
        BadInput{"0.9 saturation 1e-310", "saturation = 1e-310 is out of range (allowed: 1e-12 <= eps_1 < 1)"},
        BadInput{"0.9 saturation 1e-13", "saturation = 1e-13 is out of range (allowed: 1e-12 <= eps_1 < 1)"},
        BadInput{"0.9 saturation 1 release 0.5", "saturation = 1 is out of range (allowed: 1e-12 <= eps_1 < 1)"},
        BadInput{"0.9 viscosity 1e-3 activation 0.1 saturation 1e-310", "saturation = 1e-310 is out of range"},
        BadInput{"0.9 viscosity 1e300 activation 0.1",
                 "viscosity = 1e+300 is out of range (allowed: mu_f = 0 (dry) or 1e-100 <= mu_f <= 1e100)"},
        BadInput{"0.9 viscosity 1e-310 activation 0.1", "viscosity = 1e-310 is out of range"},
        BadInput{"0.9 viscosity 1e-3 grid 1e300", "grid = 1e+300 is out of range (allowed: 1e-100 <= dx <= 1e100)"},
        BadInput{"0.9 viscosity 1e-3 grid 1e-310", "grid = 1e-310 is out of range (allowed: 1e-100 <= dx <= 1e100)"},
        BadInput{"0.9 grid 1e300", "grid = 1e+300 is out of range"}));

// The allowed ranges end exactly where the messages say.
TEST(Coefficients, LimitsOfTheRangesAreAccepted)
{
  Coefficients c;
  EXPECT_EQ(parse("0.9 ncontact 1e6", c), "");
  EXPECT_EQ(parse("0.9 ncontact 1", c), "");
  EXPECT_EQ(parse("0.9 tcontact 1e100", c), "");
  EXPECT_EQ(parse("0.9 tcontact 1e-100", c), "");
  EXPECT_EQ(parse("0.9 viscosity 1e100 activation 0.1 saturation 1e-12 release -1e300", c), "");
  EXPECT_EQ(parse("0.9 viscosity 1e-100 grid 1e100", c), "");
  EXPECT_EQ(parse("0.9 viscosity 1e-3 grid 1e-100 saturation 0.999", c), "");
  EXPECT_EQ(parse("1e-300 friction 1e300 rolling 1e300 tangential 1e-300", c), "");
  // Not-a-number never passes validate() (LIGGGHTS hands it values without parsing them).
  c = Coefficients();
  c.e_dry = 0.9;
  for (double *field : {&c.n_contact, &c.viscosity, &c.eps_saturation, &c.eps_release, &c.legendre}) {
    const double keep = *field;
    *field = std::nan("");
    EXPECT_NE(validate(c), "");
    *field = keep;
  }
  c.viscosity = 1e-3;
  c.grid_spacing = std::nan("");
  EXPECT_NE(validate(c).find("grid = nan is out of range"), std::string::npos) << validate(c);
}

TEST(Coefficients, LegendreEndsTheFilmAtContactUnlessReleaseIsGiven)
{
  Coefficients c;
  ASSERT_EQ(parse("0.9 viscosity 1e-3 activation 0.1", c), "");
  EXPECT_EQ(c.eps_release, -1e-2);
  ASSERT_EQ(parse("0.9 viscosity 1e-3 activation 0.1 legendre 35", c), "");
  EXPECT_EQ(c.legendre, 35.0);
  EXPECT_EQ(c.eps_release, 0.0);
  ASSERT_EQ(parse("0.9 viscosity 1e-3 activation 0.1 legendre 35 release 5e-4", c), "");
  EXPECT_EQ(c.eps_release, 5e-4);
  EXPECT_EQ(restart_copy(c).legendre, 35.0);
}

// activation dem (DEM without a resolved fluid): parsed for every adapter, written back as typed,
// a wall film from eps* where lambda_pw(eps*) = 1; refused between spheres and as a number.
TEST(Coefficients, ActivationDem)
{
  Coefficients c;
  ASSERT_EQ(parse("0.9 viscosity 1e-3 activation dem", c), "");
  EXPECT_TRUE(c.dem_activation());
  EXPECT_EQ(restart_copy(c).eps_activation, activation_dem);
  EXPECT_NE(coefficients_words(c).find(" activation dem "), std::string::npos);
  Coefficients back;
  ASSERT_EQ(parse(coefficients_words(c), back), "");
  EXPECT_TRUE(back.dem_activation());
  EXPECT_NE(parse("0.9 viscosity 1e-3 activation dem grid 1e-4", c).find("mutually exclusive"), std::string::npos);
  EXPECT_NE(parse("0.9 viscosity 1e-3 activation demo", c).find("expected a number for keyword activation (or dem)"),
            std::string::npos);
  EXPECT_NE(parse("0.9 viscosity 1e-3 activation -1.7976931348623157e308", c).find("out of range"), std::string::npos);
  ASSERT_EQ(parse("0.9 viscosity 1e-3 activation dem", c), "");
  EXPECT_EQ(check_setup(c, Partner::wall, 1e-5).error, "");
  EXPECT_NE(check_setup(c, Partner::wall, 1e-5).description.find("activation dem: eps_al = 2.75"), std::string::npos)
      << check_setup(c, Partner::wall, 1e-5).description;
  EXPECT_NE(check_setup(c, Partner::particle, 1e-5).error.find("activation dem is for walls"), std::string::npos);
  // Dry: the keyword is accepted and does nothing, as activation is.
  ASSERT_EQ(parse("0.9 activation dem", c), "");
  EXPECT_EQ(check_setup(c, Partner::particle, 1e-5).error, "");
}

TEST(Coefficients, TimeStepChecks)
{
  Coefficients c;
  ASSERT_EQ(parse("0.9 tcontact 1e-4", c), "");
  EXPECT_EQ(validate_time_step(c, 1e-5), "");
  EXPECT_NE(validate_time_step(c, 2e-4).find("N_c = t_c / dt >= 1"), std::string::npos);
  EXPECT_NE(time_step_warning(c, 2e-5).find("N_c = 5"), std::string::npos);
  EXPECT_EQ(time_step_warning(c, 1e-5), "");
  // A contact of more than 1e6 steps is lost in round-off (coefficients.h).
  EXPECT_EQ(validate_time_step(c, 1e-10), "");
  EXPECT_EQ(validate_time_step(c, 1e-4 / 1e6), "");
  EXPECT_EQ(validate_time_step(c, 1e-11),
            "tcontact = 0.0001 is out of range with the time step 1e-11: N_c = t_c / dt = 1e+07 "
            "(allowed: 1 <= N_c <= 1e6)");
  ASSERT_EQ(parse("0.9 tcontact 1e100", c), "");
  EXPECT_NE(validate_time_step(c, 1e-5).find("tcontact = 1e+100 is out of range with the time step 1e-05"),
            std::string::npos);
  // ncontact: t_c = N_c dt must stay within 1e-100...1e100 time units.
  ASSERT_EQ(parse("0.9 ncontact 8", c), "");
  EXPECT_EQ(validate_time_step(c, 1e-5), "");
  EXPECT_EQ(validate_time_step(c, 1e-101),
            "ncontact = 8 is out of range with the time step 1e-101: t_c = N_c dt = 8e-101 "
            "(allowed: 1e-100 <= t_c <= 1e100)");
  EXPECT_NE(validate_time_step(c, 1e100).find("ncontact = 8 is out of range"), std::string::npos);
}

// A contact of exactly 8 steps whose time step comes through an input script (variable dt equal
// v_tc/8, timestep ${dt}: LAMMPS writes an equal-style variable with 15 digits) gives
// t_c / dt = 7.999999999999994...: that is N_c = 8, no warning (issue 21). The sample must contain
// such cases, or the test could not fail.
static double as_input_variable(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", value);
  return std::strtod(text, nullptr);
}

TEST(Coefficients, EightStepsUpToRoundingDoNotWarn)
{
  int rounded_below = 0;
  for (double r_over_u = 1e-4; r_over_u < 1e-2; r_over_u *= 1.013) {
    Coefficients c;
    c.e_dry = 0.9;
    c.t_contact = as_input_variable(0.04 * r_over_u);
    const double dt = as_input_variable(c.t_contact / 8.0);
    rounded_below += c.steps_per_contact(dt) < 8.0;
    EXPECT_EQ(time_step_warning(c, dt), "") << "t_c / dt = " << c.steps_per_contact(dt);
    EXPECT_NE(time_step_warning(c, dt * (1.0 + 1e-9)), "");    // a contact truly shorter than 8 steps
    EXPECT_TRUE(check_setup(c, Partner::wall, dt).warnings.empty());
  }
  EXPECT_GT(rounded_below, 0);
}

// Messages quote values as users type them (%g), so 1e-06 reads as 1e-06, not 0.000001.
TEST(Coefficients, MessagesQuoteValuesAsTyped)
{
  Coefficients c;
  EXPECT_NE(parse("1.5", c).find("e_d = 1.5 is out of range"), std::string::npos);
  ASSERT_EQ(parse("0.9 tcontact 1e-6", c), "");
  const std::string message = validate_time_step(c, 5e-5);
  EXPECT_NE(message.find("tcontact = 1e-06 is shorter than the time step 5e-05"), std::string::npos) << message;
}

// check_setup: the checks and description every adapter (pair style, wall, LIGGGHTS) reports.
TEST(Coefficients, CheckSetupReportsWhatEveryAdapterPrints)
{
  Coefficients c;
  ASSERT_EQ(parse("0.9 ncontact 4 viscosity 0.001 activation 0.1", c), "");
  const SetupCheck wet = check_setup(c, Partner::particle, 1e-5);
  EXPECT_EQ(wet.error, "");
  ASSERT_EQ(wet.warnings.size(), 1u);
  EXPECT_NE(wet.warnings[0].find("N_c = 4 steps"), std::string::npos) << wet.warnings[0];
  EXPECT_EQ(wet.description.rfind("e_d = 0.9, t_c = 4e-05 (4 steps), k/m_e = ", 0), 0u) << wet.description;
  EXPECT_NE(wet.description.find("film mu_f = 0.001, integration exact"), std::string::npos) << wet.description;
  EXPECT_EQ(wet.tangential, "");
  // k/m_e = (pi^2 + ln^2 e_d) / t_c^2 in the text.
  const double k = (M_PI * M_PI + std::log(0.9) * std::log(0.9)) / (4e-5 * 4e-5);
  char expected[64];
  std::snprintf(expected, sizeof expected, "k/m_e = %.6g,", k);
  EXPECT_NE(wet.description.find(expected), std::string::npos) << wet.description;

  // A contact of 8 steps up to rounding is 8 steps: no warning.
  ASSERT_EQ(parse("0.9 tcontact 8e-05 friction 0.3", c), "");
  const SetupCheck eight = check_setup(c, Partner::wall, 1e-5 * (1.0 + 1e-15));
  EXPECT_TRUE(eight.warnings.empty());
  EXPECT_NE(eight.description.find("dry, integration exact"), std::string::npos);
  EXPECT_EQ(eight.tangential.rfind("friction mu_c = 0.3, e_t = 0.9, rolling mu_r = 0", 0), 0u) << eight.tangential;
  EXPECT_EQ(check_setup(c, Partner::wall, 1.01e-5).warnings.size(), 1u);

  // A time step the contact cannot hold is the error, and nothing else is derived.
  const SetupCheck bad = check_setup(c, Partner::wall, 2e-4);
  EXPECT_NE(bad.error.find("N_c = t_c / dt >= 1"), std::string::npos);
  EXPECT_EQ(bad.description, "");

  // A calibration that cannot act is warned about (test_wet_calibration.cpp).
  ASSERT_EQ(parse("0.1 ncontact 8 viscosity 0.001 activation 0.1 legendre 35", c), "");
  const SetupCheck calibrated = check_setup(c, Partner::wall, 1e-5);
  ASSERT_EQ(calibrated.warnings.size(), 1u);
  EXPECT_NE(calibrated.warnings[0].find("legendre 35 cannot act"), std::string::npos);
}

// coefficients_words (write_data's Pair Coeffs): parsed back, every coefficient is the same.
TEST(Coefficients, WordsParseBackExactly)
{
  const char *lines[] = {"0.9",
                         "0.5 ncontact 12",
                         "0.123456789 tcontact 3.3e-5 viscosity 0.0035555555555555557 activation 0.1",
                         "0.9 ncontact 8 viscosity 1e-3 grid 1.25e-4 saturation 2e-3 release -0.005",
                         "0.7 integration sampled friction 0.3 tangential 0.4 rolling 0.01 shearfilm no",
                         "0.9 viscosity 1e-3 activation 0.1 friction 0.2 shearfilm yes",
                         "0.9 viscosity 1e-3 activation 0.1 legendre 35"};
  for (const char *line : lines) {
    Coefficients c, back;
    ASSERT_EQ(parse(line, c), "") << line;
    const std::string words = coefficients_words(c);
    ASSERT_EQ(parse(words, back), "") << words;
    double a[Coefficients::packed_size], b[Coefficients::packed_size];
    c.pack(a);
    back.pack(b);
    for (int k = 0; k < Coefficients::packed_size; k++)
      EXPECT_EQ(a[k], b[k]) << line << " -> " << words << " (value " << k << ")";
  }
}

// Random valid pair_coeff lines in random keyword order: the keyword table carries every value
// through parse, a restart file (pack, unpack), write_data's words and parse again unchanged.
static std::string random_line(std::mt19937 &rng)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto chance = [&](double p) { return unit(rng) < p; };
  auto text = [](double value) {
    char t[32];
    std::snprintf(t, sizeof t, "%.17g", value);
    return std::string(t);
  };
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
  std::vector<std::string> pairs;
  if (chance(0.3))
    pairs.push_back("ncontact " + text(std::floor(log_uniform(1.0, 1e6))));
  else if (chance(0.4))
    pairs.push_back("tcontact " + text(log_uniform(1e-9, 1e-2)));
  const bool wet = chance(0.6), exact = chance(0.8);
  const double saturation = chance(0.5) ? log_uniform(1e-6, 1e-2) : 1e-3;
  if (saturation != 1e-3 || chance(0.2)) pairs.push_back("saturation " + text(saturation));
  const bool legendre = wet && exact && chance(0.3);
  if (legendre) pairs.push_back("legendre " + text(log_uniform(1.0, 100.0)));
  if (chance(0.5)) pairs.push_back("release " + text(legendre ? saturation * unit(rng) : -log_uniform(1e-4, 1e-1)));
  if (wet) {
    pairs.push_back("viscosity " + text(log_uniform(1e-5, 1.0)));
    const double pick = unit(rng);
    pairs.push_back(pick < 0.3   ? "grid " + text(log_uniform(1e-6, 1e-3))
                    : pick < 0.5 ? std::string("activation dem")
                                 : "activation " + text(saturation + (1.0 - saturation) * (0.01 + 0.99 * unit(rng))));
  } else if (chance(0.3)) {
    pairs.push_back("activation " + text(0.5 * unit(rng)));
  }
  if (!exact || chance(0.2)) pairs.push_back(exact ? "integration exact" : "integration sampled");
  if (chance(0.5)) pairs.push_back("friction " + text(unit(rng)));
  if (chance(0.4)) pairs.push_back("tangential " + text(unit(rng)));
  if (chance(0.4)) pairs.push_back("rolling " + text(0.1 * unit(rng)));
  if (chance(0.4)) pairs.push_back(chance(0.5) ? "shearfilm yes" : "shearfilm no");
  if (chance(0.3)) pairs.push_back(chance(0.5) ? "rollfilm yes" : "rollfilm no");
  std::shuffle(pairs.begin(), pairs.end(), rng);
  std::string line = text(0.01 + 0.99 * unit(rng));
  for (const std::string &pair : pairs)
    line += " " + pair;
  return line;
}

TEST(Coefficients, KeywordTableRoundTripsRandomInput)
{
  std::mt19937 rng(44);
  for (int trial = 0; trial < 3000; trial++) {
    const std::string line = random_line(rng);
    Coefficients c, back;
    ASSERT_EQ(parse(line, c), "") << line;
    const std::string words = coefficients_words(restart_copy(c));
    ASSERT_EQ(parse(words, back), "") << line << " -> " << words;
    double a[Coefficients::packed_size], b[Coefficients::packed_size];
    c.pack(a);
    back.pack(b);
    for (int k = 0; k < Coefficients::packed_size; k++)
      ASSERT_EQ(a[k], b[k]) << line << " -> " << words << " (" << coefficient_keywords[k].name << ")";
  }
}

// The restart file's order of values is the table's: files written before the table read the same.
TEST(Coefficients, RestartOrderIsTheTableOrder)
{
  Coefficients c;
  ASSERT_EQ(parse("0.7 tcontact 2e-4 viscosity 3e-3 activation 0.2 saturation 2e-3 release -0.02 integration "
                  "sampled friction 0.3 tangential 0.4 rolling 0.05 shearfilm no rollfilm yes",
                  c),
            "");
  const double expected[] = {0.7, 8.0, 2e-4, 3e-3, 0.2, 0.0, 2e-3, -0.02, 0.0, 0.3, 0.4, 0.05, 0.0, 0.0, 1.0};
  ASSERT_EQ(sizeof expected / sizeof expected[0], static_cast<size_t>(Coefficients::packed_size));
  double buf[Coefficients::packed_size];
  c.pack(buf);
  for (int k = 0; k < Coefficients::packed_size; k++)
    EXPECT_EQ(buf[k], expected[k]) << coefficient_keywords[k].name;
  EXPECT_EQ(parse("0.9 viscosity 1e-3 activation 0.1 size 3", c),
            "unknown keyword 'size' (expected ncontact, tcontact, viscosity, activation, grid, saturation, release, "
            "integration, friction, tangential, rolling, shearfilm, legendre or rollfilm)");
}

// Keyword parsing and range checks shared by pair_coeff and fix wall/lubrication: every
// bad value is rejected with a message that names the parameter and the allowed range.
#include "lubricated/coefficients.h"

#include <gtest/gtest.h>

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
  for (std::string w; in >> w;) words.push_back(w);
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
    ::testing::Values(BadInput{"0", "e_d = 0"}, BadInput{"-0.5", "0 < e_d <= 1"},
                      BadInput{"1.01", "e_d = 1.01"}, BadInput{"nan", "e_d"},
                      BadInput{"abc", "e_d, got 'abc'"}, BadInput{"", "missing e_d"},
                      BadInput{"0.9 ncontact 0.5", "N_c >= 1"},
                      BadInput{"0.9 tcontact 0", "t_c > 0"},
                      BadInput{"0.9 ncontact 8 tcontact 1", "mutually exclusive"},
                      BadInput{"0.9 viscosity -1", "mu_f >= 0"},
                      BadInput{"0.9 viscosity 1e-3", "activation"},
                      BadInput{"0.9 viscosity 1e-3 activation 1e-4", "eps_al"},
                      BadInput{"0.9 viscosity 1e-3 activation 2", "eps_al <= 1"},
                      BadInput{"0.9 viscosity 1e-3 grid -1", "dx > 0"},
                      BadInput{"0.9 viscosity 1e-3 grid 1 activation 0.1", "mutually exclusive"},
                      BadInput{"0.9 saturation 0", "eps_1 > 0"},
                      BadInput{"0.9 saturation 1e-3 release 1e-3", "eps_2 < eps_1"},
                      BadInput{"0.9 frobnicate 3", "unknown keyword 'frobnicate'"},
                      BadInput{"0.9 viscosity", "missing value for keyword viscosity"},
                      BadInput{"0.9 viscosity x", "keyword viscosity, got 'x'"},
                      BadInput{"0.9 viscosity 1e-3 activation 0.1 legendre -35", "A >= 0"},
                      BadInput{"0.9 legendre 35", "legendre needs a wet contact (viscosity > 0)"},
                      BadInput{"0.9 viscosity 1e-3 activation 0.1 legendre 35 integration sampled",
                               "legendre needs integration exact"},
                      BadInput{"0.9 viscosity 1e-3 activation 0.1 legendre 35 release -0.01",
                               "release = -0.01 is out of range with legendre"}));

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

TEST(Coefficients, TimeStepChecks)
{
  Coefficients c;
  ASSERT_EQ(parse("0.9 tcontact 1e-4", c), "");
  EXPECT_EQ(validate_time_step(c, 1e-5), "");
  EXPECT_NE(validate_time_step(c, 2e-4).find("N_c = t_c / dt >= 1"), std::string::npos);
  EXPECT_NE(time_step_warning(c, 2e-5).find("N_c = 5"), std::string::npos);
  EXPECT_EQ(time_step_warning(c, 1e-5), "");
}

// Messages quote values as users type them (%g), so 1e-06 reads as 1e-06, not 0.000001.
TEST(Coefficients, MessagesQuoteValuesAsTyped)
{
  Coefficients c;
  EXPECT_NE(parse("1.5", c).find("e_d = 1.5 is out of range"), std::string::npos);
  ASSERT_EQ(parse("0.9 tcontact 1e-6", c), "");
  const std::string message = validate_time_step(c, 5e-5);
  EXPECT_NE(message.find("tcontact = 1e-06 is shorter than the time step 5e-05"), std::string::npos)
      << message;
}

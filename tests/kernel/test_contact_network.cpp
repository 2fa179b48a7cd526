// Stability of the network of sustained contacts (lubricated/contact_network.h). The step of the
// linearised network, y' - 2 y + y'' = -(K y + C (y - y'')) in mass-weighted coordinates, is stable
// when lambda_max(S) < 4, S = sum_k s_k b_k b_k^T; the per-atom bounds must bracket lambda_max,
// be exact for an isolated pair, and predict the growth of the actual recurrence.
#include "lubricated/contact_network.h"
#include "lubricated/contact_network_message.h"
#include "lubricated/contact_step.h"
#include "lubricated/contact.h"

#include "contact_network_systems.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace lubricated;

using namespace contact_network_test;

TEST(ContactNetwork, LoadIsThatOfTheStepConstants)
{
  const double dt = 1e-5;
  for (double e : {1.0, 0.9, 0.5, 0.1, 0.01})
    for (double n : {1.0, 1.5, 2.0, 3.0, 8.0, 100.0}) {
      const ContactStep cs = make_contact_step(spring_dashpot_from_restitution(e, n * dt), dt);
      EXPECT_NEAR(contact_load(cs.stiffness_step, cs.damping_step, dt), contact_load_of_steps(e, n), 1e-12)
          << "e = " << e << ", N_c = " << n;
      Coefficients c;
      c.e_dry = 0.9, c.n_contact = n, c.friction = 0.3, c.e_tangential = e;
      const TangentialModel tm = make_contact_model(c, Partner::particle, dt).tangential;
      EXPECT_NEAR(contact_load(tm.stiffness_step, tm.damping_step, dt), contact_load_of_steps(e, n), 1e-12);
    }
}

TEST(ContactNetwork, IsolatedPairIsNeverLimited)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 1000; trial++) {
    const double e = trial == 0 ? 0.5 : u(rng), steps = 1.0 + 20.0 * u(rng) * u(rng);
    const double s = contact_load_of_steps(e, steps);
    EXPECT_LE(s, 3.25 + 1e-12);
    Network net;
    net.mass.push_back(std::exp(6.0 * u(rng)));
    net.mass.push_back(std::exp(6.0 * u(rng)));
    net.contacts.push_back({0, 1, {0.6, 0.0, 0.8}, net.mass[0] * net.mass[1] / (net.mass[0] + net.mass[1]), s});
    double upper, lower;
    bounds(net, upper, lower);
    EXPECT_NEAR(upper, s, 1e-12 * s);
    EXPECT_NEAR(lower, s, 1e-12 * s);
    EXPECT_LT(upper, stable_network_load);
  }
}

TEST(ContactNetwork, ThreeInARowIsExact)
{
  const Network net{std::vector<double>(3, 1.0),
                    {Contact{0, 1, {1, 0, 0}, 0.5, 2.0}, Contact{1, 2, {1, 0, 0}, 0.5, 2.0}}};
  double upper, lower;
  bounds(net, upper, lower);
  std::mt19937_64 rng(3);
  EXPECT_NEAR(largest_eigenvalue(net, rng), 3.0, 1e-9);    // 2 x 1.5
  EXPECT_NEAR(upper, 3.0, 1e-12);
  EXPECT_NEAR(lower, 2.5, 1e-12);    // 2 x 1.25
}

TEST(ContactNetwork, BoundsBracketTheLargestEigenvalue)
{
  std::mt19937_64 rng(11);
  int dense = 0;
  for (int trial = 0; trial < 20; trial++) {
    const Network net = random_network(rng, 60, 1.0 + 0.05 * trial, 0.1, 3.0);
    if (net.contacts.empty()) continue;
    double upper, lower;
    bounds(net, upper, lower);
    const double lambda = largest_eigenvalue(net, rng);
    EXPECT_LE(lower, lambda * (1.0 + 1e-6)) << "trial " << trial;
    EXPECT_GE(upper, lambda) << "trial " << trial;
    dense += net.contacts.size() > 60;
  }
  EXPECT_GE(dense, 5);    // several networks with more contacts than spheres
}

// The recurrence itself: stable where the upper bound is below 4, growing where the lower bound
// is 4 or more (contacts of one model: N_c steps, e_d).
TEST(ContactNetwork, BoundsPredictTheStep)
{
  std::mt19937_64 rng(5);
  const Network unit = random_network(rng, 60, 1.0, 1.0, 1.0);
  ASSERT_GT(unit.contacts.size(), 60u);
  double upper, lower;
  bounds(unit, upper, lower);
  const double lambda = largest_eigenvalue(unit, rng);
  int stable = 0, unstable = 0;
  for (double e : {0.9, 0.5, 0.02})
    for (double n = 1.0; n <= 40.0; n *= 1.5) {
      const double s = contact_load_of_steps(e, n);
      const double E = std::pow(e, 1.0 / std::max(n, 1.5)), C = std::cos(3.14159265358979323846 / std::max(n, 1.5));
      const double amplitude = largest_amplitude(unit, 1.0 + E * E - 2.0 * E * C, 1.0 - E * E, 2000, rng);
      if (upper * s < stable_network_load) {
        EXPECT_LT(amplitude, 1e3) << "e_d = " << e << ", N_c = " << n;
        stable++;
      }
      if (lower * s >= stable_network_load) {
        EXPECT_GT(amplitude, 1e6) << "e_d = " << e << ", N_c = " << n;
        unstable++;
      }
      // lambda_max itself decides, whichever bound applies.
      if (lambda * s < 0.95 * stable_network_load) {
        EXPECT_LT(amplitude, 1e3);
      } else if (lambda * s > 1.05 * stable_network_load) {
        EXPECT_GT(amplitude, 1e6);
      }
    }
  EXPECT_GE(stable, 4) << "unstable: " << unstable;
  EXPECT_GE(unstable, 4) << "stable: " << stable;
}

TEST(ContactNetwork, StepsForLoadInvertsTheLoad)
{
  for (double e : {0.9, 0.5, 0.1})
    for (double target : {0.1, 0.4, 1.0, 2.5}) {
      const double n = contact_steps_for_load(e, -1.0, target);
      EXPECT_LE(contact_load_of_steps(e, n), target * (1.0 + 1e-9));
      EXPECT_GT(contact_load_of_steps(e, 0.99 * n), target);
      const double both = contact_steps_for_load(e, 0.3, target);
      EXPECT_GE(both, n * (1.0 - 1e-3));
      EXPECT_LE(contact_load_of_steps(0.3, both), target * (1.0 + 1e-9));
    }
}

// The message both engines print: the duration as given, the atoms, the load and a remedy whose
// N_c brings the worst upper bound below 4 (contact_steps_for_load).
TEST(ContactNetwork, MessageNamesTheDurationAndARemedyThatHolds)
{
  Coefficients c;
  c.e_dry = 0.9;
  c.n_contact = 2.0;
  NetworkFinding f;
  f.unstable = true;
  f.load = 4.92;
  f.type_i = 1;
  f.type_j = 2;
  f.tag_i = 70;
  f.tag_j = 82;
  f.contacts_i = 8;
  f.contacts_j = 9;
  f.largest_unit_upper = 10.1;
  f.largest_lower = 4.92;
  const double dt = 1e-5;
  const std::string error = network_message("pair_style x", c, dt, f);
  EXPECT_EQ(error.rfind("pair_style x types 1 2: ncontact = 2 is too short a contact for this packing", 0), 0u);
  EXPECT_NE(error.find("atoms 70 (8 contacts) and 82 (9)"), std::string::npos);
  EXPECT_NE(error.find("(load 4.92 >= 4;"), std::string::npos);
  const double needed = advised_contact_steps(contact_load_model(c, false), f.largest_unit_upper, 2.0);
  EXPECT_LT(contact_load_of_steps(0.9, needed) * f.largest_unit_upper, stable_network_load);
  char remedy[64];
  std::snprintf(remedy, sizeof remedy, "Use ncontact >= %.3g ", needed);
  EXPECT_NE(error.find(remedy), std::string::npos);

  c.n_contact = 8.0;
  c.t_contact = 2e-5;
  f.unstable = false;
  f.load = 5.36;
  f.largest_lower = 3.15;
  const std::string warning = network_message("model lubricated", c, dt, f);
  EXPECT_NE(warning.find("with tcontact = 2e-05 (N_c = t_c / dt = 2) the contact network of this packing "
                         "is likely unstable: its load is at least 3.15"),
            std::string::npos);
  EXPECT_NE(warning.find("reach the upper bound 5.36 >= 4"), std::string::npos);
  EXPECT_NE(warning.find("a longer tcontact or a timestep <="), std::string::npos);
}

// The sampled spring-dashpot's load (LIGGGHTS's tangential models, integration sampled): that of
// the constants of spring_dashpot_from_restitution.
TEST(ContactNetwork, SampledLoadIsThatOfTheSpringDashpot)
{
  const double dt = 1e-5;
  for (double e : {1.0, 0.9, 0.5, 0.1, 0.01})
    for (double n : {1.0, 1.5, 2.0, 3.0, 8.0, 100.0}) {
      const SpringDashpot sd = spring_dashpot_from_restitution(e, n * dt);
      const double load = contact_load(sd.stiffness_per_mass, sd.damping_per_mass, dt);
      EXPECT_NEAR(sampled_load_of_steps(e, n), load, 1e-12 * load) << "e = " << e << ", N_c = " << n;
    }
}

namespace {
// The number that follows `key` in a message.
double number_after(const std::string &text, const std::string &key)
{
  const size_t at = text.find(key);
  return at == std::string::npos ? -1.0 : std::strtod(text.c_str() + at + key.size(), nullptr);
}
}    // namespace

// The advised duration, as printed and typed back, passes the upper bound (load below 4) and, where
// the current one fails, is longer; one step of 3 digits less fails or is not longer. For every
// load model of the engines, whatever the margin by which the current duration fails.
TEST(ContactNetwork, AdvisedDurationPassesAndExceedsTheCurrent)
{
  for (int kind = 0; kind < 4; kind++)
    for (double e : {1.0, 0.9, 0.5, 0.1})
      for (double current : {1.0, 1.3, 1.5, 2.0, 2.5, 3.0, 5.0, 8.0, 30.0})
        for (double margin : {1.0001, 1.001, 1.3, 3.0, 10.0, 100.0}) {
          ContactLoadModel load;
          load.e_n = e;
          load.sampled_normal = kind == 1;
          load.e_t = kind == 2 ? 0.3 : -1.0;
          load.sampled_tangential = kind == 3;    // LIGGGHTS
          const double unit_upper = margin * stable_network_load / load(current);
          const double advised = advised_contact_steps(load, unit_upper, current);
          const double typed = std::strtod(detail::number3(advised).c_str(), nullptr);
          const std::string where = "kind " + std::to_string(kind) + ", e = " + std::to_string(e) +
                                    ", N_c = " + std::to_string(current) + ", margin " + std::to_string(margin);
          EXPECT_EQ(typed, advised) << where;
          EXPECT_LT(load(typed) * unit_upper, stable_network_load) << where;
          EXPECT_GT(typed, current) << where;
          const double less = detail::step3(typed, false, true);
          EXPECT_TRUE(!(load(less) * unit_upper < stable_network_load) || !(less > current)) << where;
        }
}

// The LIGGGHTS probe's WARNING at N_c = 1 on an isolated contact (upper bound 10.3, the sampled
// tangential spring's load): it advised "lubricatedContactSteps >= 1", the duration in use. The
// printed duration and time step now pass.
TEST(ContactNetwork, MessageAdvisesADurationThatPasses)
{
  const double dt = 1e-5;
  Coefficients c;
  c.e_dry = 0.9;
  ContactLoadModel liggghts;
  liggghts.e_n = 0.9;
  liggghts.sampled_tangential = true;
  for (double steps : {1.0, 2.0, 3.0})
    for (double unit_upper : {1.0, 2.5, 4.0}) {
      c.n_contact = steps;
      c.t_contact = 0.0;
      NetworkFinding f;
      f.load = liggghts(steps) * unit_upper;
      if (f.load < stable_network_load) continue;
      f.largest_unit_upper = unit_upper;
      f.largest_lower = 3.0;
      const std::string warning = network_message("model lubricated", c, dt, f, true);
      const double advised = number_after(warning, "use ncontact >= ");
      EXPECT_GT(advised, steps) << warning;
      EXPECT_LT(liggghts(advised) * unit_upper, stable_network_load) << warning;

      c.t_contact = steps * dt;
      const std::string timed = network_message("model lubricated", c, dt, f, true);
      const double dt_advised = number_after(timed, "a timestep <= ");
      EXPECT_GT(dt_advised, 0.0) << timed;
      EXPECT_LT(liggghts(c.t_contact / dt_advised) * unit_upper, stable_network_load) << timed;
      EXPECT_GE(c.t_contact / dt_advised, number_after(timed, "(N_c >= ")) << timed;
    }
}

// The per-step integration of the spring-dashpot (contact_step.h): a leapfrog collision of
// an isolated pair reproduces the analytic solution, hence e_d and t_c, for every impact
// phase, and it falls back to the sampled law's constants as dt -> 0.
#include "lubricated/normal_model.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace lubricated;

struct Bounce {
  double restitution;
  int steps_in_contact;
};

// Leapfrog (the position/mid-step-velocity form of velocity Verlet) of the relative gap.
static Bounce leapfrog_bounce(double e, double n_c, double phase)
{
  const double dt = 1.0;
  const ContactStep cs = make_contact_step(spring_dashpot_from_restitution(e, n_c * dt), dt);
  double g = (3.0 + phase) * dt, u = -1.0;
  int in_contact = 0;
  for (int n = 0; n < 10000; ++n) {
    u += dt * contact_acceleration(cs, g, u);
    g += dt * u;
    if (g < 0.0) ++in_contact;
    if (g > 2.0 * dt && u > 0.0) break;
  }
  return {u, in_contact};
}

TEST(ContactStep, IsolatedCollisionIsExactForEveryPhase)
{
  for (double n_c : {1.0, 2.0, 4.0, 8.0, 64.0})
    for (double e : {1.0, 0.97, 0.5, 0.1, 0.01})
      for (int k = 0; k < 40; ++k) {
        const double phase = k / 40.0;
        const Bounce b = leapfrog_bounce(e, n_c, phase);
        EXPECT_NEAR(b.restitution, e, 1e-9 + 1e-7 * e) << "N_c=" << n_c << " e=" << e << " phase=" << phase;
        // The overlap is sampled N_c times, or once less when a sample lands on contact.
        EXPECT_LE(std::abs(b.steps_in_contact - n_c), 1.0) << "N_c=" << n_c << " phase=" << phase;
      }
}

TEST(ContactStep, SustainedContactIsASpringDashpotThatTendsToTheSampledOne)
{
  const SpringDashpot sd = spring_dashpot_from_restitution(0.5, 1.0);
  for (double dt : {1e-2, 1e-3}) {
    const ContactStep cs = make_contact_step(sd, dt);
    EXPECT_NEAR(cs.stiffness_step / sd.stiffness_per_mass, 1.0, 2.0 * dt);
    EXPECT_NEAR(cs.damping_step / sd.damping_per_mass, 1.0, 2.0 * dt);
    // Deep in overlap and slow, the force is k' d - c' u.
    const double g = -0.05, u = -1e-3;
    EXPECT_NEAR(contact_acceleration(cs, g, u), -cs.stiffness_step * g - cs.damping_step * u,
                1e-9 * cs.stiffness_step * 0.05);
  }
}

TEST(ContactStep, ActsOnlyInOrWithinOneStepOfContact)
{
  const ContactStep cs = make_contact_step(spring_dashpot_from_restitution(0.9, 8.0), 1.0);
  EXPECT_EQ(contact_acceleration(cs, 1.01, -1.0), 0.0);    // reaches contact after the step
  EXPECT_GT(contact_acceleration(cs, 0.5, -1.0), 0.0);     // contact half-way through the step
  EXPECT_EQ(contact_acceleration(cs, 1.5, +1.0), 0.0);     // separating, apart a step ago too
  EXPECT_TRUE(contact_possible(0.5, -1.0, 1.0));
  EXPECT_FALSE(contact_possible(1.5, -1.0, 1.0));
}

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

// Velocity Verlet from full-step velocities: the first force is evaluated at the start with
// v^n and half a kick; a collision already under way at the start stays exact.
TEST(ContactStep, RunStartingDuringTheContactIsExact)
{
  const double e = 0.6, dt = 1.0;
  const ContactStep cs = make_contact_step(spring_dashpot_from_restitution(e, 8.0), dt);
  for (double start_gap : {0.3, -0.5, -2.0}) {
    // Exact state at the start: free flight at -1 into the oscillator.
    double g = start_gap, v = -1.0;
    if (g < 0.0) {
      const double t_in = 1.37;    // time since the contact began, g from the oscillator
      const double a = cs.decay_rate, w = cs.omega;
      g = -std::exp(-a * t_in) * std::sin(w * t_in) / w;
      v = -std::exp(-a * t_in) * (std::cos(w * t_in) - a / w * std::sin(w * t_in));
    }
    double acc = contact_acceleration_at_start(cs, g, v);
    for (int n = 0; n < 100 && !(g > 1.0 && v > 0.0); ++n) {
      const double v_half = v + 0.5 * dt * acc;
      g += dt * v_half;
      acc = contact_acceleration(cs, g, v_half);
      v = v_half + 0.5 * dt * acc;
    }
    EXPECT_NEAR(v, e, 1e-9) << "start gap " << start_gap;
  }
}

// fix nve/sphere/midpoint: forces at X~ = X + dt/2 V (+ dt^2/8 A on an atom's first step, A
// from the set-up forces), then V += dt F/m and X~ += dt V: a leapfrog of the X~ points. A
// contact that begins within the first half-step drift must not be read as a faster impact.
static double midpoint_rebound(const ContactStep &cs, double g, double v)
{
  const double dt = cs.dt;
  double x = g + 0.5 * v * dt;
  x += 0.125 * dt * dt * contact_acceleration_at_midpoint_start(cs, g, v, x);
  for (int n = 0; n < 1000 && !(x > 2.0 * dt && v > 0.0); ++n) {
    v += dt * contact_acceleration(cs, x, v);
    x += dt * v;
  }
  return v;
}

TEST(ContactStep, MidpointStartWithinTheFirstHalfStepIsExact)
{
  for (double n_c : {1.0, 2.0, 8.0, 64.0})
    for (double e : {1.0, 0.9, 0.1})
      for (int k = 0; k <= 20; ++k) {
        const ContactStep cs = make_contact_step(spring_dashpot_from_restitution(e, n_c), 1.0);
        const double start_gap = 0.5 * k / 20.0;    // contact within the first half step
        EXPECT_NEAR(midpoint_rebound(cs, start_gap, -1.0), e, 1e-9)
            << "N_c=" << n_c << " e=" << e << " gap=" << start_gap;
      }
}

// A run starting in overlap: X~ is placed where the oscillator has moved v dt over the step
// before, exact while that step stays in overlap; within half a step of the contact's start
// or near its end the placement is second order: e_d to O((omega dt)^2).
TEST(ContactStep, MidpointStartDuringTheContact)
{
  const double e = 0.6;
  for (double n_c : {8.0, 64.0}) {
    const ContactStep cs = make_contact_step(spring_dashpot_from_restitution(e, n_c), 1.0);
    const double a = cs.decay_rate, w = cs.omega;
    for (double t_in : {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}) {    // of t_c
      const double t = t_in * n_c;
      const double g = -std::exp(-a * t) * std::sin(w * t) / w;
      const double v = -std::exp(-a * t) * (std::cos(w * t) - a / w * std::sin(w * t));
      const double tolerance = t_in >= 0.1 && t_in <= 0.8 ? 1e-9 : 0.5 * e * std::pow(pi / n_c, 2);
      EXPECT_NEAR(midpoint_rebound(cs, g, v), e, tolerance) << "N_c=" << n_c << " t=" << t_in;
    }
  }
}

// Adaptive time stepping: a new time step within table_tolerance keeps the guess tables of the
// last one (no rebuild, ~1 ms per type pair otherwise). The guesses only seed Newton, so every
// collision stays exact; beyond the tolerance, or for another e_d, the tables are rebuilt.
TEST(ContactStep, GuessTablesKeptForANearbyTimeStepLeaveCollisionsExact)
{
  for (double e : {0.97, 0.5, 0.1})
    for (double n_c : {2.0, 8.0, 40.0}) {
      const SpringDashpot sd = spring_dashpot_from_restitution(e, n_c);    // t_c = n_c, dt = 1 first
      const ContactStep first = make_contact_step(sd, 1.0);
      for (double dt : {0.96, 1.04}) {
        const ContactStep kept = make_contact_step(sd, dt, &first);
        EXPECT_EQ(kept.table_steps, first.table_steps);                              // the tables were copied
        EXPECT_EQ(kept.stiffness_step, make_contact_step(sd, dt).stiffness_step);    // constants are dt's
        for (int k = 0; k < 20; ++k) {
          double g = (3.0 + k / 20.0) * dt, u = -1.0;
          for (int n = 0; n < 100000 && !(g > 2.0 * dt && u > 0.0); ++n) {
            u += dt * contact_acceleration(kept, g, u);
            g += dt * u;
          }
          EXPECT_NEAR(u, e, 1e-9 + 1e-7 * e) << "e " << e << " N_c " << n_c << " dt " << dt;
        }
      }
      EXPECT_NE(make_contact_step(sd, 1.2, &first).table_steps, first.table_steps);    // rebuilt
      const ContactStep other = make_contact_step(spring_dashpot_from_restitution(0.3, n_c), 1.0, &first);
      EXPECT_NE(other.table_restitution, first.table_restitution);
    }
}

// The step-exact contact under a steady load b pressing the pair together (loaded_contact.h):
// without a load normal_force() is what it was; an isolated collision under b rebounds as the
// forced system (a parabola apart, the oscillator about g_b = -b / k' in overlap) for every impact
// phase; a contact resting under b stays down (e_d = 1: never above its start) or settles.
#include "lubricated/normal_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace lubricated;

static ContactStep contact_step_for(double e, double n_c, double dt)
{
  return make_contact_step(spring_dashpot_from_restitution(e, n_c * dt), dt);
}

// The contact acceleration of a step under the load b, as normal_force() takes it.
static double step_acceleration(const ContactStep &cs, double g, double u, double b)
{
  return contact_possible(g, u, cs.dt, b) ? loaded_contact_acceleration(cs, g, u, b) : 0.0;
}

TEST(LoadedContact, WithoutALoadNormalForceIsUnchanged)
{
  Coefficients c;
  c.e_dry = 0.7;
  c.n_contact = 6.0;
  c.viscosity = 1e-3;
  c.eps_activation = 0.05;
  const NormalModel m = make_normal_model(c, Partner::wall, 1e-5);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 20000; ++k) {
    const double u = 1e-2 * unit(rng), gap = 3e-7 * unit(rng);
    for (Evaluation when : {Evaluation::step, Evaluation::verlet_start, Evaluation::midpoint_start}) {
      const NormalForce a = normal_force(m, gap, 1e-3, 2e-6, u, when),
                        b = normal_force(m, gap, 1e-3, 2e-6, u, when, 0.0);
      EXPECT_EQ(a.contact, b.contact);
      EXPECT_EQ(a.lubrication, b.lubrication);
      EXPECT_EQ(a.energy, b.energy);
    }
  }
}

// The loaded forms with b -> 0 are contact_step.h's (same trajectories, other arithmetic).
TEST(LoadedContact, VanishingLoadGivesTheUnloadedForms)
{
  for (double n_c : {1.0, 2.0, 8.0, 64.0})
    for (double e : {1.0, 0.6, 0.05}) {
      const ContactStep cs = contact_step_for(e, n_c, 1.0);
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> unit(-1.0, 1.0);
      for (int k = 0; k < 2000; ++k) {
        const double u = unit(rng), g = 2.0 * n_c * unit(rng) / pi;
        if (!contact_possible(g, u, 1.0)) continue;
        const double expected = contact_acceleration(cs, g, u), scale = std::fabs(u) + std::fabs(g);
        EXPECT_NEAR(loaded_contact_acceleration(cs, g, u, 1e-300), expected, 1e-10 * scale)
            << "N_c=" << n_c << " e=" << e << " g=" << g << " u=" << u;
        EXPECT_NEAR(loaded_contact_acceleration_at_start(cs, g, u, 1e-300), contact_acceleration_at_start(cs, g, u),
                    1e-10 * scale);
      }
    }
}

// The forced system's rebound, independently: the oscillator h = g - g_b, h(0) = -g_b, h'(0) = -v,
// leaves the overlap at its first upward crossing of -g_b (found on a fine grid, then bisected).
// Returns -1 where it never leaves.
static double forced_rebound(const ContactStep &cs, double b, double v)
{
  const double a = cs.decay_rate, w = cs.omega, rest = -b / cs.stiffness_step, A = -rest, B = (-v + a * A) / w;
  auto h = [&](double t) { return std::exp(-a * t) * (A * std::cos(w * t) + B * std::sin(w * t)); };
  const double step = 1e-4 * pi / w;
  double t = step;
  while (h(t) < A) {
    t += step;
    if (t > 4.0 * pi / w) return -1.0;
  }
  double lo = t - step, hi = t;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (h(mid) < A ? lo : hi) = mid;
  }
  const double s = 0.5 * (lo + hi);
  return std::exp(-a * s) * ((B * w - a * A) * std::cos(w * s) - (A * w + a * B) * std::sin(w * s));
}

// Leapfrog of the gap under the load b and the contact, from the parabola that reaches contact at
// speed v at time 0, sampled from (2 + phase) steps before; returns the speed at which the parabola
// after the rebound leaves contact (from two samples in flight, exact on a parabola).
static double leapfrog_rebound(const ContactStep &cs, double b, double v, double phase)
{
  const double dt = cs.dt;
  auto parabola = [&](double t) { return -v * t - 0.5 * b * t * t; };
  const double t1 = -(2.0 + phase) * dt;
  double g = parabola(t1), u = (g - parabola(t1 - dt)) / dt;
  for (int n = 0; n < 100000; ++n) {
    const double g_before = g;
    u += dt * (step_acceleration(cs, g, u, b) - b);
    g += dt * u;
    if (g_before > 0.0 && g > 0.0 && u > 0.0 && g > 2.0 * u * dt) {
      const double middle = 0.5 * (g_before + g) + 0.125 * b * dt * dt;
      return std::sqrt(u * u + 2.0 * b * middle);
    }
  }
  return -1.0;
}

TEST(LoadedContact, IsolatedCollisionUnderALoadIsExactForEveryPhase)
{
  const double dt = 1.0, v = 1.0;
  int compared = 0;
  for (double n_c : {1.0, 2.0, 4.0, 8.0, 64.0})
    for (double e : {1.0, 0.9, 0.5})
      for (double beta : {0.01, 0.05, -0.05}) {
        const ContactStep cs = contact_step_for(e, n_c, dt);
        const double b = beta * v / cs.contact_time;
        const double expected = forced_rebound(cs, b, v);
        if (expected < 0.0) continue;
        ++compared;
        for (int k = 0; k < 20; ++k) {
          const double phase = (k + 0.5) / 20.0;
          EXPECT_NEAR(leapfrog_rebound(cs, b, v, phase) / expected, 1.0, 1e-9)
              << "N_c=" << n_c << " e=" << e << " b t_c / v=" << beta << " phase=" << phase;
        }
        if (e == 1.0) EXPECT_NEAR(expected, v, 1e-12);
      }
  EXPECT_GT(compared, 30);
}

// A run starting during a loaded collision (velocity Verlet's first half kick) stays on it.
TEST(LoadedContact, RunStartingDuringALoadedCollisionIsExact)
{
  const double dt = 1.0, v = 1.0;
  for (double e : {1.0, 0.6}) {
    const ContactStep cs = contact_step_for(e, 8.0, dt);
    const double b = 0.05 * v / cs.contact_time, expected = forced_rebound(cs, b, v);
    for (double since : {-1.3, 0.4, 2.7, 5.1}) {    // time since contact began (< 0: before)
      // The exact state then: the parabola, or the oscillator about g_b from contact.
      double g, w_v;
      if (since < 0.0) {
        g = v * -since - 0.5 * b * since * since, w_v = -v + b * -since;
      } else {
        const double a = cs.decay_rate, w = cs.omega, rest = -b / cs.stiffness_step;
        const double A = -rest, B = (-v + a * A) / w, t = since;
        g = rest + std::exp(-a * t) * (A * std::cos(w * t) + B * std::sin(w * t));
        w_v = std::exp(-a * t) * ((B * w - a * A) * std::cos(w * t) - (A * w + a * B) * std::sin(w * t));
      }
      double acc = loaded_contact_acceleration_at_start(cs, g, w_v, b);
      double u = w_v + 0.5 * dt * (acc - b);
      g += dt * u;
      double rebound = -1.0;
      for (int n = 0; n < 1000; ++n) {
        const double g_before = g;
        u += dt * (step_acceleration(cs, g, u, b) - b);
        g += dt * u;
        if (g_before > 0.0 && g > 0.0 && u > 0.0 && g > 2.0 * u * dt) {
          rebound = std::sqrt(u * u + 2.0 * b * (0.5 * (g_before + g) + 0.125 * b * dt * dt));
          break;
        }
      }
      EXPECT_NEAR(rebound / expected, 1.0, 1e-9) << "e=" << e << " since " << since;
    }
  }
}

struct Rest {
  double highest, last_gap, last_speed, rest;
};

// A sphere put at contact at rest under gravity (dt = 1e-5 s, 9.81 m/s^2), for `steps` steps.
static Rest resting_contact(double e, double n_c, int steps)
{
  const double dt = 1e-5, b = 9.81;
  const ContactStep cs = contact_step_for(e, n_c, dt);
  double g = 0.0, v = 0.0;
  const double acc = loaded_contact_acceleration_at_start(cs, g, v, b);
  double u = v + 0.5 * dt * (acc - b);
  g += dt * u;
  double highest = g;
  for (int n = 0; n < steps; ++n) {
    u += dt * (step_acceleration(cs, g, u, b) - b);
    g += dt * u;
    highest = std::max(highest, g);
  }
  return {highest, g, std::fabs(u), -b / cs.stiffness_step};
}

TEST(LoadedContact, RestingContactNeverRisesWithoutDamping)
{
  for (double n_c : {2.0, 4.0, 8.0, 32.0}) {
    const Rest r = resting_contact(1.0, n_c, 20000);
    EXPECT_LE(r.highest, 1e-9 * 9.81 * 1e-10) << "N_c=" << n_c;    // round-off of b dt^2
  }
}

TEST(LoadedContact, RestingContactSettles)
{
  for (double n_c : {2.0, 4.0, 8.0})
    for (double e : {0.99, 0.9, 0.5}) {
      const Rest r = resting_contact(e, n_c, 20000);
      EXPECT_LE(r.highest, 1e-9 * 9.81 * 1e-10) << "N_c=" << n_c << " e=" << e;
      EXPECT_LT(r.last_speed, 1e-9) << "N_c=" << n_c << " e=" << e;
      EXPECT_NEAR(r.last_gap, r.rest, 1e-6 * std::fabs(r.rest)) << "N_c=" << n_c << " e=" << e;
    }
}

// The spring-dashpot constants reproduce e_d and t_c exactly for the continuous oscillator,
// and a fine integration of m_e x'' = -F_s recovers them (doc/model.rst, "Solid contact: the
// spring-dashpot").
#include "lubricated/normal_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace lubricated;

TEST(SpringDashpot, ClosedFormReproducesRestitutionAndDuration)
{
  for (double e : {1.0, 0.97, 0.5, 0.1, 0.01}) {
    for (double tc : {1e-6, 1.0, 40.0}) {
      const SpringDashpot sd = spring_dashpot_from_restitution(e, tc);
      EXPECT_NEAR(restitution_of(sd), e, 1e-12 * e) << "e=" << e << " tc=" << tc;
      EXPECT_NEAR(contact_duration_of(sd), tc, 1e-12 * tc);
    }
  }
}

TEST(SpringDashpot, PaperFormulaForStiffnessAndDamping)
{
  // k = m_e (pi^2 + ln^2 e) / (N_c dt)^2, c = -2 m_e ln e / (N_c dt), here per unit m_e.
  const double e = 0.5, n_c = 8.0, dt = 1e-4;
  const SpringDashpot sd = spring_dashpot_from_restitution(e, n_c * dt);
  const double tc = n_c * dt;
  EXPECT_DOUBLE_EQ(sd.stiffness_per_mass, (pi * pi + std::log(e) * std::log(e)) / (tc * tc));
  EXPECT_DOUBLE_EQ(sd.damping_per_mass, -2.0 * std::log(e) / tc);
  EXPECT_EQ(spring_dashpot_from_restitution(1.0, tc).damping_per_mass, 0.0);
}

// Integrates a head-on impact through normal_force() with a tiny RK4 step: the exit speed
// over the entry speed must be e_d and the contact must last t_c.
TEST(SpringDashpot, IntegratedImpactThroughNormalForce)
{
  for (double e : {0.97, 0.5, 0.1}) {
    Coefficients c;
    c.e_dry = e;
    c.t_contact = 1.0;
    c.exact_contact = false;    // the continuous law, sampled by the fine RK4 steps here
    const NormalModel m = make_normal_model(c, Partner::wall, 1.0);
    const double mass = 2.5, u0 = -1.0, h = 1e-5;
    double gap = 0.0, u = u0, t = 0.0;
    auto accel = [&](double g, double v) { return normal_force(m, g, 1.0, mass, v).total() / mass; };
    do {
      const double k1x = u, k1v = accel(gap, u);
      const double k2x = u + 0.5 * h * k1v, k2v = accel(gap + 0.5 * h * k1x, u + 0.5 * h * k1v);
      const double k3x = u + 0.5 * h * k2v, k3v = accel(gap + 0.5 * h * k2x, u + 0.5 * h * k2v);
      const double k4x = u + h * k3v, k4v = accel(gap + h * k3x, u + h * k3v);
      gap += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
      u += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      t += h;
    } while (gap < 0.0 || t < h * 1.5);
    EXPECT_NEAR(u / -u0, e, 1e-4) << "e=" << e;
    EXPECT_NEAR(t, 1.0, 2 * h) << "e=" << e;
  }
}

TEST(NormalForce, SignsAndEnergy)
{
  Coefficients c;
  c.e_dry = 0.8;
  const NormalModel m = make_normal_model(c, Partner::particle, 0.1);
  const double m_e = 3.0;
  // Overlap at rest: repulsive along n, energy k d^2 / 2.
  const NormalForce rest = normal_force(m, -0.01, 1.0, m_e, 0.0);
  EXPECT_GT(rest.contact, 0.0);
  EXPECT_DOUBLE_EQ(rest.energy, 0.5 * m_e * m.contact.stiffness_per_mass * 1e-4);
  // Approaching (u_n < 0) adds to the repulsion, separating takes from it.
  EXPECT_GT(normal_force(m, -0.01, 1.0, m_e, -1.0).contact, rest.contact);
  EXPECT_LT(normal_force(m, -0.01, 1.0, m_e, +1.0).contact, rest.contact);
  // Dry and more than a step apart: nothing at all.
  const NormalForce apart = normal_force(m, 0.2, 1.0, m_e, -1.0);
  EXPECT_EQ(apart.total(), 0.0);
  EXPECT_EQ(apart.energy, 0.0);
}

TEST(NormalForce, ReducedMassOfInverses)
{
  // Free pair: the reduced mass; a partner no contact moves (inverse 0): the other's mass, as
  // on a wall; neither moves: 0, and then no force at all (issue 17).
  EXPECT_DOUBLE_EQ(reduced_mass_of_inverses(1.0 / 2.0, 1.0 / 6.0), reduced_mass(2.0, 6.0));
  EXPECT_EQ(reduced_mass_of_inverses(1.0 / 3.0, 0.0), 1.0 / (1.0 / 3.0));
  EXPECT_EQ(reduced_mass_of_inverses(0.0, 0.25), 4.0);
  EXPECT_EQ(reduced_mass_of_inverses(0.0, 0.0), 0.0);
  // The vectorised loops take such pairs through the branch-free forms, which give no force
  // with m_e = 0 (normal_force() needs m_e > 0: the engines skip these pairs before it).
  Coefficients c;
  c.e_dry = 0.9;
  c.viscosity = 1e-3;
  c.eps_activation = 0.1;
  const NormalModel m = make_normal_model(c, Partner::particle, 1e-5);
  const FilmRadius radius(1e-3);
  bool sustained = false;
  const NormalForce f = sustained_contact_force<false>(m, -1e-6, radius, 0.0, -0.01, sustained);
  EXPECT_TRUE(sustained);
  EXPECT_EQ(f.total(), 0.0);
  EXPECT_EQ(f.energy, 0.0);
  for (double gap : {1e-6, 5e-5})
    EXPECT_EQ(film_force_apart<false>(m.lubrication, gap, radius, 0.0, -0.01, m.step.dt, m.step.inv_dt), 0.0);
}

// NormalModel::may_act, the test before the square root (LIGGGHTS's surfacesClose), is false
// only where acts() is: over dry, fixed-activation and grid films, the step-exact model and the
// sampled one, pairs of unequal spheres and walls (radsum = the sphere's radius, film radius
// the same), gaps from overlap to beyond the reach and speeds from creeping to a gap per step.
// It leaves most far pairs out (the test that makes it worth having).
TEST(NormalModel, MayActWhereverItActs)
{
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int acting = 0, left_out = 0, far = 0;
  for (int trial = 0; trial < 60000; trial++) {
    Coefficients c;
    c.e_dry = 0.9;
    c.n_contact = 8;
    const int film = trial % 3;    // dry, fixed eps_al, grid
    if (film > 0) c.viscosity = 1e-3;
    if (film == 1) c.eps_activation = 0.05 + 0.5 * unit(rng);
    if (film == 2) c.grid_spacing = 1e-5 + 2e-4 * unit(rng);
    const bool wall = trial % 5 == 0;
    const double dt = 1e-5;
    NormalModel m = make_normal_model(c, wall ? Partner::wall : Partner::particle, dt);
    m.exact = trial % 7 != 0;
    const double ri = 1e-3 * (0.5 + unit(rng)), rj = 1e-3 * (0.5 + unit(rng));
    const double radsum = wall ? ri : ri + rj;
    const double radius = wall ? ri : film_radius_pair(ri, rj).value;
    const double gap = radsum * (-0.01 + 0.6 * unit(rng) * unit(rng));
    const double r = radsum + gap;
    // A random direction of x_i - x_j and of the relative velocity.
    double n[3] = {unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5};
    const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double speed = std::pow(10.0, -4.0 + 6.0 * unit(rng)) * (unit(rng) < 0.5 ? -1.0 : 1.0);
    const double dv[3] = {speed * (unit(rng) - 0.5), speed * (unit(rng) - 0.5), speed * (unit(rng) - 0.5)};
    double del[3], dv_dot_del = 0.0;
    for (int d = 0; d < 3; d++) {
      del[d] = r * n[d] / norm;
      dv_dot_del += dv[d] * del[d];
    }
    const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
    const double u_n = dv_dot_del / std::sqrt(rsq);
    const bool acts = m.acts(std::sqrt(rsq) - radsum, radius, u_n);
    const bool may = m.may_act(rsq, dv_dot_del, radsum);
    if (acts) {
      ASSERT_TRUE(may) << "trial " << trial << " gap " << gap << " u_n " << u_n << " wall " << wall;
      ++acting;
    }
    if (gap > 0.35 * radsum) {
      ++far;
      left_out += !may;
    }
  }
  EXPECT_GT(acting, 10000);
  EXPECT_GT(left_out, far / 2);
}

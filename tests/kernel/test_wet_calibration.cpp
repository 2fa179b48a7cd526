// The wet-restitution calibration (keyword legendre, normal_model.h): an isolated collision
// through the film rebounds with e / e_d = exp(-A / St) for every time step, where the
// paper's film alone falls under that law below St of about 50; it only ever removes speed.
#include "lubricated/normal_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <cmath>

using namespace lubricated;

namespace {

constexpr double e_dry = 0.9, eps_al = 0.09375, legendre_constant = 35.0;

// Units R = 1, impact speed U = 1, mass 1 per sphere: St = m U / (6 pi mu R^2) for the wall
// and for two equal spheres at relative speed U (m_e = 1/2, c_inv = 1/2). Keyword defaults:
// the film ends at contact with legendre, at the paper's -1e-2 R of overlap without.
Coefficients wet(double e, double stokes, double legendre)
{
  Coefficients c;
  c.e_dry = e;
  c.viscosity = 1.0 / (6.0 * pi * stokes);
  c.eps_activation = eps_al;
  c.legendre = legendre;
  complete_defaults(c, Given());
  EXPECT_EQ(validate(c), "");
  return c;
}

NormalModel model(double stokes, double dt, double t_c, bool wall, double legendre)
{
  Coefficients c = wet(e_dry, stokes, legendre);
  c.t_contact = t_c;
  return make_normal_model(c, wall ? Partner::wall : Partner::particle, dt);
}

// Leapfrog of the gap from outside the film until the pair has left it (or stopped).
double rebound(const NormalModel &m, double dt, bool wall, double phase)
{
  const double m_e = wall ? 1.0 : 0.5;
  double g = eps_al + 0.05 + phase * dt, u = -1.0;
  for (long n = 0; n * dt < 100.0; ++n) {
    u += dt * normal_force(m, g, 1.0, m_e, u).total() / m_e;
    g += dt * u;
    if (g > eps_al + 0.01 && u > 0.0) return u;
  }
  return 0.0;
}

}    // namespace

TEST(WetCalibration, StartSpeedOnlyRemovesSpeedAndHasTheRightSlope)
{
  EntryLoss loss;
  loss.film_loss = 0.2, loss.pending = 0.05, loss.stokes_speed = 0.02;
  loss.decay_constant = 35.0, loss.restitution = 0.9;
  for (double v : {0.01, 0.06, 0.3, 1.0, 3.0, 100.0}) {
    double dS;
    const double S = loss.start_speed(v, dS);
    EXPECT_LE(S, v) << v;
    EXPECT_GT(S, 0.0) << v;
    const double h = 1e-6 * v;
    EXPECT_NEAR(dS, (loss.start_speed(v + h) - loss.start_speed(v - h)) / (2 * h), 1e-5) << v;
  }
  // Stopped by the film before contact: nothing to calibrate.
  EXPECT_EQ(loss.start_speed(0.04), 0.04);
}

TEST(WetCalibration, FollowsLegendresLawForEveryTimeStep)
{
  for (bool wall : {true, false})
    for (double stokes : {20.0, 30.0, 50.0, 100.0, 1000.0})
      for (double dt : {0.01, 0.003, 0.001})
        for (double t_c : {0.04, 8.0 * dt})    // fixed t_c, and N_c = 8
          for (double phase : {0.0, 0.37, 0.71}) {
            const double e = rebound(model(stokes, dt, t_c, wall, legendre_constant), dt, wall, phase);
            // 0.05: the tolerance; the film's one-step lag makes up the rest.
            EXPECT_NEAR(e / e_dry, std::exp(-legendre_constant / stokes), 0.05)
                << (wall ? "wall" : "pair") << " St=" << stokes << " dt=" << dt << " t_c=" << t_c;
          }
}

TEST(WetCalibration, ThePapersFilmAloneFallsUnderTheLawAtLowStokes)
{
  // The contrast that makes the calibration necessary (doc: wet restitution).
  const double dt = 0.003;
  const double e = rebound(model(20.0, dt, 0.04, true, 0.0), dt, true, 0.0);
  EXPECT_LT(e / e_dry, std::exp(-legendre_constant / 20.0) - 0.1);
}

TEST(WetCalibration, NoReboundAtVeryLowStokesAndDryLimitAtHighStokes)
{
  const double dt = 0.003;
  EXPECT_EQ(rebound(model(5.0, dt, 0.04, true, legendre_constant), dt, true, 0.0), 0.0);
  EXPECT_NEAR(rebound(model(1e6, dt, 0.04, true, legendre_constant), dt, true, 0.0), e_dry, 1e-3);
}

TEST(WetCalibration, SustainedContactIsUnchanged)
{
  const double dt = 0.003;
  const NormalModel plain = model(20.0, dt, 0.04, true, 0.0);
  const NormalModel calibrated = model(20.0, dt, 0.04, true, legendre_constant);
  // In overlap for the last step and the next: the same spring-dashpot.
  for (double u : {-0.5, -0.01, 0.01})
    EXPECT_EQ(normal_force(plain, -0.01, 1.0, 1.0, u).contact, normal_force(calibrated, -0.01, 1.0, 1.0, u).contact);
}

TEST(WetCalibration, ExtremeInputsStayFiniteAndGainNoEnergy)
{
  // St 0.01 ... 1e5, N_c 1 ... 64, e_d 0.01 ... 1, and a step that reaches half a radius of
  // overlap (dt = 0.5 R/U): every step's velocity stays within the impact speed (a leapfrog
  // velocity is the mean over its step, so it may exceed the exit speed while leaving the
  // contact), and the pair leaves the film at no more than e_d times the impact speed.
  for (double legendre : {0.0, legendre_constant})
    for (double stokes : {0.01, 1.0, 20.0, 1e5})
      for (double n_c : {1.0, 2.0, 8.0, 64.0})
        for (double e : {0.01, 0.5, 1.0})
          for (double dt : {0.001, 0.05, 0.5}) {
            Coefficients c = wet(e, stokes, legendre);
            c.n_contact = n_c;
            const NormalModel m = make_normal_model(c, Partner::wall, dt);
            double g = eps_al + 0.05, u = -1.0, fastest = 0.0;
            // Until a step past the film: the step after an exit still corrects the velocity.
            for (long n = 0; n * dt < 50.0 && !(g > eps_al + 0.01 + 2.0 * dt && u > 0.0); ++n) {
              u += dt * normal_force(m, g, 1.0, 1.0, u).total();
              g += dt * u;
              ASSERT_TRUE(std::isfinite(u) && std::isfinite(g));
              fastest = std::max(fastest, std::fabs(u));
            }
            const std::string where = "A=" + std::to_string(legendre) + " St=" + std::to_string(stokes) +
                                      " N_c=" + std::to_string(n_c) + " e=" + std::to_string(e) +
                                      " dt=" + std::to_string(dt);
            EXPECT_LE(fastest, 1.0 + 1e-9) << where;
            EXPECT_LE(std::max(u, 0.0), e * (1.0 + 1e-9)) << where;
          }
}

TEST(WetCalibration, WarnsWhereItCannotAct)
{
  Coefficients c = wet(0.9, 100.0, legendre_constant);
  EXPECT_EQ(calibration_warning(c, Partner::wall), "");
  // e_d = 0.1: the film's speed loss P(0) = 4.56 per St on the way out alone exceeds
  // e_d exp(-35/St) u0 at every St; the threshold is P / (A - P) = 0.15.
  c.e_dry = 0.1;
  const std::string message = calibration_warning(c, Partner::wall);
  EXPECT_NE(message.find("legendre 35 cannot act with e_d = 0.1"), std::string::npos) << message;
  EXPECT_NE(message.find("e_d > 0.15"), std::string::npos) << message;
  // Beyond the threshold the contact stays dry: the film takes L = P(0)/St of the impact speed
  // in and out, e = e_d (1 - L) - L = 0.0749 at St = 200, under the law's 0.1 exp(-35/200) = 0.084.
  const double dt = 0.003, stokes = 200.0;
  NormalModel m = model(stokes, dt, 0.04, true, legendre_constant);
  m.restitution = 0.1;
  m.contact = spring_dashpot_from_restitution(0.1, 0.04);
  m.step = make_contact_step(m.contact, dt);
  const double film = m.lubrication.film_integral(0.0, 1.0) / stokes;
  EXPECT_NEAR(rebound(m, dt, true, 0.0), 0.1 * (1.0 - film) - film, 2e-3);
}

// Fluid inertia and memory of the drag fix (src/lubricated/fluid_inertia.h, doc/model.rst
// "Fluid inertia and memory").
#include "lubricated/fluid_inertia.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace lubricated;

namespace {

// Largest relative error of the tail's exponential sum against 1/sqrt(tau), tau in [t_win, tau_max].
double tail_error(int modes, double t_win, double tau_max)
{
  const BassetTail tail(modes, t_win);
  double worst = 0.0;
  for (double tau = t_win; tau <= tau_max; tau *= 1.02)
    worst = std::max(worst, std::abs(tail.kernel(tau) * std::sqrt(tau) - 1.0));
  return worst;
}

}    // namespace

TEST(BassetTail, ExponentialSumFollowsTheKernel)
{
  // The accuracy stated in fluid_inertia.h and doc/fix_fluid_drag.rst.
  const double t_win = 2.2e-5;
  EXPECT_LT(tail_error(16, t_win, 1e3 * t_win), 1.05e-3);
  EXPECT_LT(tail_error(16, t_win, 1e5 * t_win), 3.6e-3);
  EXPECT_LT(tail_error(20, t_win, 1e5 * t_win), 1.05e-3);
  EXPECT_LT(tail_error(20, t_win, 1e7 * t_win), 3.0e-3);
  // Beyond its range the sum forgets the far past (decays faster than 1/sqrt(tau)).
  const BassetTail tail(10, t_win);
  EXPECT_LT(tail.kernel(1e5 * t_win) * std::sqrt(1e5 * t_win), 0.1);
}

TEST(BassetHistory, ConstantSlipAccelerationGivesTheExactIntegral)
{
  // wdot constant from t = 0: F_H = K wdot int_0^t dtau / sqrt(t - tau) = 2 K wdot sqrt(t).
  const double dt = 1e-4, coefficient = 3.0, wdot[3] = {1.0, -2.0, 0.5};
  const BassetHistory history(10, 20, dt);
  std::vector<double> state(history.size(), 0.0);
  for (int n = 0; n <= 20000; n++) {
    if (n > 0) history.commit(state.data());
    double known[3];
    const double m_h = history.known_force(state.data(), coefficient, dt, known);
    BassetHistory::store(state.data(), wdot);
    if (n == 0) {
      EXPECT_EQ(m_h, 0.0);    // the start of the history: no step behind it
      continue;
    }
    EXPECT_DOUBLE_EQ(m_h, 2.0 * coefficient * std::sqrt(dt));
    const double exact = 2.0 * coefficient * std::sqrt(n * dt);
    // Within the window (n <= 11) the sum telescopes: exact to round-off; later the tail's
    // kernel error (< 1e-3 over the times here).
    const double tolerance = n <= 11 ? 1e-12 : 1e-3;
    for (int d = 0; d < 3; d++)
      ASSERT_NEAR(known[d] + m_h * wdot[d], exact * wdot[d], tolerance * std::abs(exact * wdot[d])) << n;
  }
}

TEST(HistorySteps, StepsOfUnequalLengthGiveTheExactIntegral)
{
  // As above with a step that changes every step (between dt0 / 4 and 2 dt0): the window
  // weighted by the kernel over its true ages telescopes to 2 K wdot sqrt(t) while the history
  // lies in the window; later the tail, laid out for dt0, adds its kernel error.
  const double dt0 = 1e-4, coefficient = 3.0, wdot[3] = {1.0, -2.0, 0.5};
  const int window = 10;
  const BassetHistory history(window, 20, dt0);
  HistorySteps steps(window, dt0);
  std::vector<double> state(history.size(), 0.0), bound(window + 2), weight(window + 1), decay(20), feed(20);
  double time = 0.0, last = 0.0;
  for (int n = 0; n <= 4000; n++) {
    const double dt = dt0 * (0.25 + 1.75 * (0.5 + 0.5 * std::sin(0.37 * n)));
    if (n > 0) {
      steps.advance(last, dt, history.tail(), decay.data(), feed.data());
      history.commit(state.data(), decay.data(), feed.data());
      time += dt;
    }
    steps.bounds(dt, bound.data());
    window_weights(window, bound.data(), weight.data());
    double known[3];
    const double m_h = history.known_force(state.data(), coefficient, dt, known, weight.data());
    BassetHistory::store(state.data(), wdot);
    last = dt;
    if (n == 0) continue;
    const double exact = 2.0 * coefficient * std::sqrt(time);
    const double tolerance = n <= window + 1 ? 1e-12 : 2e-3;
    for (int d = 0; d < 3; d++)
      ASSERT_NEAR(known[d] + m_h * wdot[d], exact * wdot[d], tolerance * std::abs(exact * wdot[d])) << n;
  }
}

TEST(HistorySteps, EqualStepsGiveTheLayoutsWeights)
{
  const double dt = 1e-3;
  const BassetHistory history(5, 12, dt);
  HistorySteps steps(5, dt);
  std::vector<double> bound(7), weight(6), decay(12), feed(12);
  steps.bounds(dt, bound.data());
  window_weights(5, bound.data(), weight.data());
  for (int lag = 0; lag <= 5; lag++)
    EXPECT_NEAR(weight[lag], window_weight(lag), 1e-15) << lag;
  // decay and feed of equal steps: one commit with them equals the layout's commit
  steps.advance(dt, dt, history.tail(), decay.data(), feed.data());
  std::vector<double> a(history.size()), b(history.size());
  for (std::size_t k = 0; k < a.size(); k++)
    a[k] = b[k] = k == 0 ? 2.0 : std::sin(1.0 + k);
  history.commit(a.data());
  history.commit(b.data(), decay.data(), feed.data());
  for (std::size_t k = 0; k < a.size(); k++)
    EXPECT_NEAR(a[k], b[k], 1e-14 * std::abs(a[k]) + 1e-300) << k;
}

TEST(BassetHistory, EvaluatingAStepAgainChangesNothing)
{
  // A set-up re-evaluates the step under way (no commit in between): same force, same state.
  const double dt = 1e-3;
  const BassetHistory history(3, 8, dt);
  std::vector<double> state(history.size(), 0.0);
  double known[3], again[3];
  for (int n = 0; n < 30; n++) {
    if (n > 0) history.commit(state.data());
    const double wdot[3] = {std::sin(0.3 * n), std::cos(0.2 * n), 1.0 / (1.0 + n)};
    const double m_h = history.known_force(state.data(), 1.0, dt, known);
    BassetHistory::store(state.data(), wdot);
    const std::vector<double> before = state;
    EXPECT_EQ(history.known_force(state.data(), 1.0, dt, again), m_h);
    BassetHistory::store(state.data(), wdot);
    for (int d = 0; d < 3; d++)
      EXPECT_EQ(known[d], again[d]);
    EXPECT_EQ(state, before);
  }
}

TEST(FluidInertia, BassetCoefficientIsSixRSquaredRootPiRhoMu)
{
  const double R = 2e-4, rho = 1000.0, mu = 1e-3;
  EXPECT_NEAR(basset_coefficient(2 * R, rho, mu), 6 * R * R * std::sqrt(pi * rho * mu), 1e-18);
}

TEST(FluidInertia, MagnusLiftOfABackspinningSphereIsUpward)
{
  // A sphere moving at +x through still fluid (slip w = -v) with backspin (omega along -y,
  // its top moving back) is lifted, +z: pi R^3 rho_f Omega x v.
  const double R = 1e-3, rho = 1.2, v = 3.0, omega = 40.0;
  const double slip[3] = {-v, 0.0, 0.0}, spin[3] = {0.0, -omega, 0.0};
  double f[3];
  magnus_force(R, rho, spin, slip, f);
  EXPECT_NEAR(f[2], pi * R * R * R * rho * omega * v, 1e-15);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_EQ(f[1], 0.0);
}

TEST(FluidInertia, SaffmanLiftPushesALaggingSphereTowardsTheFasterFluid)
{
  // Shear u = gamma y x: curl u = -gamma z. A sphere lagging the fluid (w along +x) is
  // lifted to +y; at vanishing Re_p Mei's factor is 1 and the force Saffman's.
  const double d = 1e-4, rho = 1000.0, mu = 1e-3, gamma = 100.0, w = 1e-6;
  const double slip[3] = {w, 0.0, 0.0}, curl[3] = {0.0, 0.0, -gamma};
  double f[3];
  saffman_force(d, rho, mu, slip, curl, f);
  const double re_p = rho * w * d / mu, re_s = rho * gamma * d * d / mu;
  EXPECT_NEAR(saffman_mei_correction(re_p, re_s), 1.0, 1e-2);
  EXPECT_NEAR(f[1], 1.615 * d * d * std::sqrt(rho * mu / gamma) * saffman_mei_correction(re_p, re_s) * w * gamma,
              1e-12 * std::abs(f[1]));
  EXPECT_GT(f[1], 0.0);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_EQ(f[2], 0.0);
  // No vorticity, no lift; Mei's factor falls with Re_p (0.0524 (b Re_p)^1/2 above 40).
  const double still[3] = {0.0, 0.0, 0.0};
  saffman_force(d, rho, mu, slip, still, f);
  EXPECT_EQ(f[1], 0.0);
  EXPECT_EQ(saffman_mei_correction(0.0, 1.0), 1.0);
  EXPECT_LT(saffman_mei_correction(20.0, 1.0), 0.3);
  EXPECT_NEAR(saffman_mei_correction(100.0, 2.0), 0.0524 * std::sqrt(1.0), 1e-15);
}

// The finite-Re history kernel of Mei & Adrian (src/lubricated/history_kernel.h,
// doc/fix_fluid_drag.rst "kernel"): its formula, the window's closed-form weights, the tail's
// exponential sum, the Basset limit, and the history of a constant slip acceleration.
#include "lubricated/history_kernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace lubricated;

namespace {

// int_a^b psi(s) s^-1/2 ds by the midpoint rule in u = s^(1/4) (s^-1/2 ds = 4 u du): smooth.
double integral(double a, double b, double rate, int n = 20000)
{
  const double ua = std::sqrt(std::sqrt(a)), ub = std::sqrt(std::sqrt(b)), h = (ub - ua) / n;
  double sum = 0.0;
  for (int i = 0; i < n; i++) {
    const double u = ua + (i + 0.5) * h;
    const double root = 1.0 + std::sqrt(rate) * u * u * u;
    sum += 4.0 * u / (root * root) * h;
  }
  return sum;
}

}    // namespace

TEST(MeiAdrianKernel, IsMeiAndAdriansFormula)
{
  // 3 pi mu d {(4 pi nu s / d^2)^(1/4) + (pi w^3 s^2 / (d nu f_H^3))^(1/2)}^-2 with
  // f_H = 0.75 + 0.105 Re (Mei & Adrian 1992), against K psi(s) s^-1/2 of the code.
  const double d = 5e-4, rho = 1000.0, mu = 8.9e-4, nu = mu / rho;
  for (double w : {1e-4, 1e-2, 0.07, 0.3})
    for (double s : {1e-5, 1e-3, 1e-2, 0.3}) {
      const double f_h = 0.75 + 0.105 * w * d / nu;
      const double bracket =
          std::pow(4 * pi * nu * s / (d * d), 0.25) + std::sqrt(pi * w * w * w * s * s / (d * nu * f_h * f_h * f_h));
      const double formula = 3 * pi * mu * d / (bracket * bracket);
      const double code = basset_coefficient(d, rho, mu) * mei_adrian_kernel(s, mei_adrian_rate(w, d, nu));
      EXPECT_NEAR(code, formula, 1e-12 * formula) << w << " " << s;
    }
  // At rest the kernel is Basset's, 1/sqrt(s).
  EXPECT_EQ(mei_adrian_rate(0.0, d, nu), 0.0);
  EXPECT_DOUBLE_EQ(mei_adrian_kernel(0.01, 0.0), 1.0 / std::sqrt(0.01));
}

TEST(MeiAdrianKernel, PrimitiveIsContinuousAndDifferentiates)
{
  // The series (T < 1/2) and the closed form meet; I'(T) = 3T / (1 + T^3)^2.
  EXPECT_NEAR(mei_adrian_primitive(0.5 - 1e-15), mei_adrian_primitive(0.5), 1e-14);
  for (double T : {0.01, 0.3, 0.49, 0.51, 1.0, 3.0, 50.0}) {
    const double h = 1e-5 * T;
    const double slope = (mei_adrian_primitive(T + h) - mei_adrian_primitive(T - h)) / (2 * h);
    EXPECT_NEAR(slope, 3 * T / std::pow(1 + T * T * T, 2), 1e-7 * (1 + slope)) << T;
  }
  // I(inf) = 2 pi / (3 sqrt 3): the whole kernel integrates to (4/3) C^(-1/3) I(inf).
  EXPECT_NEAR(mei_adrian_primitive(1e6), 2 * pi / (3 * std::sqrt(3.0)), 1e-11);
}

TEST(MeiAdrianKernel, WindowWeightsAreTheKernelsIntegralOverEachStep)
{
  const int window = 12;
  std::vector<double> weights(window + 1);
  for (double c : {1e-12, 1e-6, 1e-3, 0.1, 1.0, 30.0, 1e4}) {
    mei_adrian_window_weights(window, c, weights.data());
    for (int lag = 0; lag <= window; lag++) {
      // dt = 1: int_L^(L+1) psi s^-1/2 ds = 2 weight
      const double exact = integral(lag, lag + 1.0, c);
      EXPECT_NEAR(2 * weights[lag], exact, 1e-8 * exact + 1e-15) << c << " " << lag;
      EXPECT_LE(weights[lag], window_weight(lag) * (1 + 1e-12));    // psi <= 1
    }
  }
  // The Basset limit, exactly at c = 0 and continuously as c -> 0.
  mei_adrian_window_weights(window, 0.0, weights.data());
  for (int lag = 0; lag <= window; lag++)
    EXPECT_EQ(weights[lag], window_weight(lag));
  mei_adrian_window_weights(window, 1e-18, weights.data());
  for (int lag = 0; lag <= window; lag++)
    EXPECT_NEAR(weights[lag], window_weight(lag), 1e-5 * window_weight(lag));
}

TEST(MeiAdrianKernel, TailFollowsTheKernel)
{
  // The tail's exponential sum against psi(s) s^-1/2 over [t_win, 1e5 t_win] (M = 20, the
  // range where Basset's tail is accurate to 1e-3): 2e-3 of Basset's kernel and 2e-2 of the
  // finite-Re kernel, on the table's rows, between them, and beyond it.
  const double t_win = 3e-4;
  const BassetTail basset(20, t_win);
  const MeiAdrianTail tail(20);
  std::vector<double> w(20);
  double worst_basset = 0.0, worst_own = 0.0;
  for (double log_gamma = -17.0; log_gamma <= 7.0; log_gamma += 0.37) {
    const double gamma = std::pow(10.0, log_gamma), rate = gamma / (t_win * std::sqrt(t_win));
    tail.weights(gamma, w.data());
    for (int k = 0; k < 20; k++)
      EXPECT_GE(w[k], 0.0);
    for (double s = t_win; s <= 1e5 * t_win; s *= 1.05) {
      double sum = 0.0;
      for (int k = 0; k < 20; k++)
        sum += w[k] / std::sqrt(t_win) * std::exp(-basset.rate[k] * s);
      const double exact = mei_adrian_kernel(s, rate);
      worst_basset = std::max(worst_basset, std::abs(sum - exact) * std::sqrt(s));
      worst_own = std::max(worst_own, std::abs(sum / exact - 1));
    }
  }
  EXPECT_LT(worst_basset, 2e-3);
  EXPECT_LT(worst_own, 2e-2);
  // gamma = 0: Basset's tail exactly.
  tail.weights(0.0, w.data());
  for (int k = 0; k < 20; k++)
    EXPECT_NEAR(w[k] / std::sqrt(t_win), basset.weight[k], 1e-14 * basset.weight[k]);
}

TEST(MeiAdrianKernel, ConstantSlipAccelerationGivesTheKernelsIntegral)
{
  // wdot constant from t = 0 at a fixed rate C: F_H = K wdot int_0^t psi s^-1/2 ds =
  // K wdot sqrt(dt) (4/3) c^(-1/3) I(c^(1/6) (t/dt)^(1/4)), c = C dt^(3/2); through the window,
  // then the tail. Tolerance: the tail's 2e-3 of Basset's kernel, relative to this integral.
  const double dt = 1e-4, coefficient = 3.0, wdot[3] = {1.0, -2.0, 0.5};
  const BassetHistory history(10, 20, dt);
  MeiAdrianKernel kernel(history);
  std::vector<double> state(history.size(), 0.0);
  for (double rate : {1.0, 300.0, 3e4}) {
    std::fill(state.begin(), state.end(), 0.0);
    const double c = rate * dt * std::sqrt(dt);
    for (int n = 0; n <= 20000; n++) {
      if (n > 0) history.commit(state.data());
      kernel.weigh(rate, dt);
      double known[3];
      const double m_h = history.known_force(state.data(), coefficient, dt, known, kernel.window(), kernel.tail());
      BassetHistory::store(state.data(), wdot);
      if (n == 0) continue;
      const double exact = coefficient * std::sqrt(dt) * 4.0 / 3.0 / std::cbrt(c) *
                           mei_adrian_primitive(std::pow(c, 1.0 / 6.0) * std::pow(n, 0.25));
      const double tolerance = n <= 11 ? 1e-12 : 2e-3;
      for (int d = 0; d < 3; d++)
        ASSERT_NEAR(known[d] + m_h * wdot[d], exact * wdot[d], tolerance * std::abs(exact * wdot[d]))
            << rate << " " << n;
    }
  }
}

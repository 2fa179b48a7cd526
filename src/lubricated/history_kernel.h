// The finite-Reynolds-number history kernel of Mei & Adrian (J. Fluid Mech. 237, 323 (1992)),
// for the drag fix's history force (fluid_inertia.h, doc/fix_fluid_drag.rst "kernel"):
//
//   F_H = K int_0^t psi(t - tau) (dw/dtau) / sqrt(t - tau) dtau,  K = (3/2) d^2 sqrt(pi rho_f mu_f),
//   psi(s) = [1 + (C s^(3/2))^(1/2)]^(-2),  C = sqrt(pi) |w|^3 / (2 nu^(3/2) f_H^3)  [time^(-3/2)],
//   f_H = 0.75 + 0.105 Re,  Re = |w| d / nu,  nu = mu_f / rho_f,
//
// which is Mei & Adrian's 3 pi mu d {(4 pi nu s / d^2)^(1/4) + (pi |w|^3 s^2 / (d nu f_H^3))^(1/2)}^(-2)
// (written with the radius a = d/2 in their paper; the same form with c1 = 2 in Dorgan & Loth,
// Int. J. Multiphase Flow 33, 833 (2007)). psi = 1 (Basset's kernel) for lags s << s_c =
// (4/pi)^(1/3) nu f_H^2 / w^2; beyond, the kernel decays as s^-2 instead of s^-1/2, so that a
// sphere approaches its terminal velocity at Re of tens to hundreds without Basset's t^-1/2
// tail. C is taken from the slip speed at the current time t (the kernel of every past step
// is that of the current Re): C = 0 at rest, where the kernel is Basset's exactly.
//
// Window (fluid_inertia.h): the slip acceleration is constant over each past step, so a step
// of lag L weighs int_(L dt)^((L+1) dt) psi(s) s^(-1/2) ds, in closed form: with T = c^(1/6)
// sigma^(1/4), sigma = s / dt, c = C dt^(3/2), the integrand becomes (4/3) c^(-1/3) 3T / (1 + T^3)^2
// dT, whose primitive is I(T) = T^2/(1 + T^3) + (1/6) ln((T^2 - T + 1)/(1 + T)^2)
// + (atan((2T - 1)/sqrt(3)) + pi/6)/sqrt(3) (series below T = 1/2, where the logarithms cancel).
//
// Tail: psi(s) s^(-1/2) is completely monotone (a sum of Bernstein functions to the power -2),
// i.e. int_0^inf rho(lambda) exp(-lambda s) d lambda with rho >= 0. Its exponential sum on the
// tail's rates (BassetTail: the trapezoidal rule in ln lambda) weighs mode k by h lambda_k
// rho(lambda_k), the slowest one plus the mass of the slower rates left out, int_0^lambda_cut
// rho; rho is the inverse Laplace transform of the kernel, computed once by the fixed Talbot
// contour (Abate & Valko, Int. J. Numer. Meth. Eng. 60, 979 (2004)) on a table in
// gamma = C t_win^(3/2), 16 rows a decade, interpolated linearly in log10 gamma. The weights are
// positive; error of the sum (M = 20, tests/kernel/test_history_kernel.cpp): 1.5e-3 of Basset's
// kernel up to 1e5 t_win (3e-3 up to 1e7 t_win) and 2e-2 of the finite-Re kernel itself. Beyond the
// table (gamma > 1e6) the tail is below 1e-6 of the window's force and scales as 1/gamma.
#pragma once

#include "fluid_inertia.h"    // BassetTail, pi

#include <cmath>
#include <complex>
#include <vector>

namespace lubricated {

// C of the Mei-Adrian kernel [time^(-3/2)] for slip speed w, diameter d, kinematic viscosity nu.
inline double mei_adrian_rate(double slip_speed, double diameter, double kinematic_viscosity)
{
  const double re = slip_speed * diameter / kinematic_viscosity;
  const double f_h = 0.75 + 0.105 * re;
  return std::sqrt(pi) * slip_speed * slip_speed * slip_speed /
         (2.0 * kinematic_viscosity * std::sqrt(kinematic_viscosity) * f_h * f_h * f_h);
}

// The kernel psi(s) s^(-1/2) at lag s for rate C.
inline double mei_adrian_kernel(double lag, double rate)
{
  const double root = 1.0 + std::sqrt(rate * lag * std::sqrt(lag));
  return 1.0 / (std::sqrt(lag) * root * root);
}

// int_0^T 3t / (1 + t^3)^2 dt.
inline double mei_adrian_primitive(double T)
{
  if (T < 0.5) {    // 3 sum (-1)^n (n + 1) T^(3n+2) / (3n + 2): 24 terms reach 1e-21 at T = 1/2
    const double cube = T * T * T;
    double term = 3.0 * T * T, sum = 0.0;
    for (int n = 0; n < 24; n++) {
      sum += (n + 1) * term / (3 * n + 2);
      term *= -cube;
    }
    return sum;
  }
  const double sqrt3 = std::sqrt(3.0);
  return T * T / (1.0 + T * T * T) + std::log((T * T - T + 1.0) / ((1.0 + T) * (1.0 + T))) / 6.0 +
         (std::atan((2.0 * T - 1.0) / sqrt3) + pi / 6.0) / sqrt3;
}

// Weights of the window's steps, lag 0..window, over 2 sqrt(dt) (as window_weight in
// fluid_inertia.h), for c = C dt^(3/2); c = 0 gives Basset's sqrt(L + 1) - sqrt(L). Steps of
// unequal length: bound[L + 1] the age of the far end of lag L over dt (HistorySteps::bounds);
// none: L + 1.
inline void mei_adrian_window_weights(int window, double c, double *weights, const double *bound = nullptr)
{
  if (c <= 0.0) {
    if (bound) return window_weights(window, bound, weights);
    for (int lag = 0; lag <= window; lag++)
      weights[lag] = window_weight(lag);
    return;
  }
  const double scale = std::pow(c, 1.0 / 6.0), factor = 2.0 / (3.0 * scale * scale);
  double below = 0.0;    // I(T) at the lag's start, T = c^(1/6) (age / dt)^(1/4)
  for (int lag = 0; lag <= window; lag++) {
    const double above = mei_adrian_primitive(scale * std::sqrt(std::sqrt(bound ? bound[lag + 1] : lag + 1.0)));
    weights[lag] = factor * (above - below);
    below = above;
  }
}

// The tail's weights for the Mei-Adrian kernel, on BassetTail's rates.
class MeiAdrianTail {
 public:
  static constexpr double log_min = -16.0, log_max = 6.0;    // log10 gamma of the table
  static constexpr int per_decade = 16;

  MeiAdrianTail() = default;
  explicit MeiAdrianTail(int modes) : modes_(modes)
  {
    const BassetTail basset(modes, 1.0);    // t_win = 1: weights in units of 1/sqrt(t_win)
    const int rows = static_cast<int>((log_max - log_min) * per_decade) + 1;
    table_.reserve(static_cast<std::size_t>(rows + 1) * modes);
    table_.insert(table_.end(), basset.weight.begin(), basset.weight.end());    // gamma = 0
    const double cut = std::exp(BassetTail::x_max - (modes - 0.5) * BassetTail::spacing);
    for (int row = 0; row < rows; row++) {
      const double gamma = std::pow(10.0, log_min + static_cast<double>(row) / per_decade);
      for (int k = 0; k < modes; k++) {
        const double rate = basset.rate[k];
        double w = BassetTail::spacing * rate * inverse_laplace(gamma, rate, false);
        if (k == modes - 1) w += inverse_laplace(gamma, cut, true);
        table_.push_back(w);
      }
    }
  }
  int modes() const { return modes_; }

  // weight[k] for gamma = C t_win^(3/2), in units of 1/sqrt(t_win) (divide by it).
  void weights(double gamma, double *weight) const
  {
    if (modes_ == 0) return;
    const double *first = table_.data() + modes_;
    const double gamma_min = std::pow(10.0, log_min);
    if (gamma < gamma_min) {    // linear in gamma from Basset's weights (gamma = 0)
      const double f = gamma / gamma_min;
      for (int k = 0; k < modes_; k++)
        weight[k] = (1.0 - f) * table_[k] + f * first[k];
      return;
    }
    const int rows = static_cast<int>(table_.size()) / modes_ - 1;
    const double position = (std::log10(gamma) - log_min) * per_decade;
    if (position >= rows - 1) {    // K -> 1/(gamma s^2): the weights scale as 1/gamma
      const double scale = std::pow(10.0, log_max) / gamma;
      for (int k = 0; k < modes_; k++)
        weight[k] = scale * first[(rows - 1) * modes_ + k];
      return;
    }
    const int row = static_cast<int>(position);
    const double f = position - row;
    for (int k = 0; k < modes_; k++)
      weight[k] = (1.0 - f) * first[row * modes_ + k] + f * first[(row + 1) * modes_ + k];
  }

  // rho(lambda) (or int_0^lambda rho, cumulative) of the kernel (s^(1/4) + sqrt(gamma) s)^(-2),
  // t_win = 1, by the fixed Talbot contour with 24 nodes (relative accuracy ~1e-8 in double).
  static double inverse_laplace(double gamma, double lambda, bool cumulative)
  {
    using complex = std::complex<double>;
    const int nodes = 24;
    const double r = 2.0 * nodes / (5.0 * lambda), root = std::sqrt(gamma);
    auto transform = [&](complex s) {
      const complex denominator = std::pow(s, 0.25) + root * s;
      complex value = 1.0 / (denominator * denominator);
      return cumulative ? value / s : value;
    };
    double sum = 0.5 * std::exp(lambda * r) * transform(complex(r, 0.0)).real();
    for (int k = 1; k < nodes; k++) {
      const double theta = k * pi / nodes, cot = 1.0 / std::tan(theta);
      const complex s = r * theta * complex(cot, 1.0);
      const double sigma = theta + (theta * cot - 1.0) * cot;
      sum += (std::exp(lambda * s) * transform(s) * complex(1.0, sigma)).real();
    }
    return r / nodes * sum;
  }

 private:
  int modes_ = 0;
  std::vector<double> table_;    // (rows + 1) x modes: gamma = 0, then the rows
};

// The weights of one evaluation of BassetHistory::known_force with the Mei-Adrian kernel.
class MeiAdrianKernel {
 public:
  MeiAdrianKernel() = default;
  explicit MeiAdrianKernel(const BassetHistory &history) :
      window_(history.window()), t_win_((history.window() + 1) * history.tail_dt()), tail_(history.modes()),
      window_weight_(history.window() + 1), tail_weight_(history.modes())
  {
  }
  // For rate C (mei_adrian_rate) and step dt; bound: steps of unequal length (HistorySteps::bounds).
  void weigh(double rate, double dt, const double *bound = nullptr)
  {
    mei_adrian_window_weights(window_, rate * dt * std::sqrt(dt), window_weight_.data(), bound);
    tail_.weights(rate * t_win_ * std::sqrt(t_win_), tail_weight_.data());
    for (double &w : tail_weight_)
      w /= std::sqrt(t_win_);
  }
  // Laid out for this history (window, modes, tail step): no need to build it again.
  bool fits(const BassetHistory &history) const
  {
    return window_ == history.window() && tail_.modes() == history.modes() &&
           t_win_ == (history.window() + 1) * history.tail_dt();
  }
  const double *window() const { return window_weight_.data(); }
  const double *tail() const { return tail_weight_.data(); }

 private:
  int window_ = 0;
  double t_win_ = 0.0;
  MeiAdrianTail tail_;
  std::vector<double> window_weight_, tail_weight_;
};

}    // namespace lubricated

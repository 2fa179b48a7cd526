// Fluid inertia and memory on one sphere, for the drag fix (doc/model.rst "Fluid inertia and
// memory", doc/fix_fluid_drag.rst): the added mass, the undisturbed-flow (pressure-gradient)
// force, the Basset-Boussinesq history force and the Magnus and Saffman lifts of the Maxey-Riley-Gatignol
// equation (Maxey & Riley 1983, Gatignol 1983) for a sphere of mass m, volume V, diameter d:
//
//   m dv/dt = F + rho_f V Du/Dt + C_m rho_f V (Du/Dt - dv/dt)
//               + K int_0^t (dw/dtau) / sqrt(t - tau) dtau + F_lift,
//   w = u - v (slip), K = (3/2) d^2 sqrt(pi rho_f mu_f)   [mass / time^(1/2)],
//
// F: every other force (contacts, gravity, drag, buoyancy). Units: any consistent set.
//
// Time discretisation (one step dt, velocity Verlet: v_n - v_(n-1) = dt (a_(n-1) + a_n) / 2):
// dw/dt is taken constant over each past step at the mean of its end values, (wdot_(k-1) +
// wdot_k) / 2, wdot_k = Du/Dt(t_k) - a_k, exactly the mean slip acceleration of the step.
// The kernel integrated exactly over a step of lag L (ending L steps before t) weighs it by
// 2 sqrt(dt) (sqrt(L + 1) - sqrt(L)). The current step (L = 0) is taken at its end value,
// the unknown wdot_n, with the weight m_h = 2 K sqrt(dt): like the added mass it is solved
// for, not extrapolated, so that
//   (m + m_a + m_h) a_n = F + (rho_f V + m_a + m_h) Du/Dt + H,  m_a = C_m rho_f V,
// H the known part of the history force; stable for any density ratio (an explicit added
// mass, a_n from a_(n-1), diverges once m_a > m, rho_p / rho_f < C_m). The end value makes
// the force's error O(dt^(3/2)) at the current step only. The mean there too (trapezoidal)
// puts the weight -K sqrt(dt) on a_(n-1), which with a stiff drag (beta dt ~ m + m_a + m_h)
// diverges once that weight exceeds half the effective mass; the step's end value alone in
// every step (backward) is stable but first order, 0.24 dt / tau of the terminal velocity
// in Basset's problem (tau the relaxation time), ten times the present error.
//
// Bounded memory (after van Hinsberg, ten Thije Boonkkamp & Clercx, J. Comput. Phys. 230,
// 1465 (2011)): the last W steps are kept as they are (the window); older ones feed M
// exponential modes, 1/sqrt(tau) ~ sum_k c_k exp(-s_k tau) for tau >= t_win = (W + 1) dt,
// each mode advanced by one exact decay per step. The exponential sum is the trapezoidal
// quadrature, with step h = 1.2 in x = ln s, of the Laplace representation
//   1/sqrt(tau) = (1/sqrt(pi)) int_R e^(x/2) exp(-e^x tau) dx
// (as in Beylkin & Monzon, Appl. Comput. Harmon. Anal. 28, 131 (2010)), exponentially
// accurate in h; the rates go down from s t_win = 30 by e^-h per mode. Relative error of the
// kernel (tests/kernel/test_fluid_inertia.cpp): M = 16: 1.0e-3 up to tau = 1e3 t_win, 3.5e-3
// up to 1e5 t_win; M = 20: 1e-3 up to 1e5 t_win, 3e-3 up to 1e7 t_win. Beyond, the kernel
// decays exponentially: the far past is forgotten. A finite-Re kernel (history_kernel.h) keeps
// this layout and state and only gives other weights to the window's steps and the modes.
#pragma once

#include "spring_dashpot.h"    // pi

#include <cmath>
#include <vector>

namespace lubricated {

// K of the Basset force, F_H = K int (dw/dtau) / sqrt(t - tau) dtau.
inline double basset_coefficient(double diameter, double fluid_density, double viscosity)
{
  return 1.5 * diameter * diameter * std::sqrt(pi * fluid_density * viscosity);
}

// Kernel weight of the step of lag L, over 2 sqrt(dt): int of 1/sqrt over it, /(2 sqrt(dt)).
inline double window_weight(int lag)
{
  return std::sqrt(lag + 1.0) - std::sqrt(static_cast<double>(lag));
}

// The same for steps of unequal length: the step of lag L spans the ages bound[L]..bound[L + 1]
// (in units of the current step dt; bound[0] = 0, bound[1] = 1).
inline void window_weights(int window, const double *bound, double *weight)
{
  for (int lag = 0; lag <= window; lag++)
    weight[lag] = std::sqrt(bound[lag + 1]) - std::sqrt(bound[lag]);
}

// The exponential tail: 1/sqrt(tau) ~ sum_k weight[k] exp(-rate[k] tau) for tau >= t_win.
struct BassetTail {
  std::vector<double> rate, weight;

  BassetTail() = default;
  BassetTail(int modes, double t_win)
  {
    for (int k = 0; k < modes; k++) {
      const double x = x_max - k * spacing;    // s t_win = e^x
      rate.push_back(std::exp(x) / t_win);
      weight.push_back(spacing / std::sqrt(pi) * std::exp(0.5 * x) / std::sqrt(t_win));
    }
    // The slower modes left out, x < x_last - h/2, add (2/sqrt(pi)) e^((x_last - h/2)/2) while
    // tau << 1/s_last: lumped on the slowest mode, they extend its range tenfold.
    if (modes > 0)
      weight.back() += 2.0 / std::sqrt(pi) * std::exp(0.5 * (x_max - (modes - 0.5) * spacing)) / std::sqrt(t_win);
  }
  static constexpr double spacing = 1.2;                 // h, in ln s
  static constexpr double x_max = 3.4011973816621555;    // ln 30: e^(-30) is nothing
  double kernel(double tau) const
  {
    double sum = 0.0;
    for (std::size_t k = 0; k < rate.size(); k++)
      sum += weight[k] * std::exp(-rate[k] * tau);
    return sum;
  }
};

// The per-atom history state, a flat array of size() doubles (so that the adapter can grow,
// migrate and restart it as one block):
//   [0]            ends: how many end values are known (0, 1 or 2)
//   [1..3]         wdot at the last committed step t_(n-1)
//   [4..6]         wdot at the step being evaluated, t_n (not yet committed)
//   [7 + 3(L-1)]   the mean wdot of the step of lag L = 1..W (at the next evaluation)
//   [7 + 3W + 3k]  tail mode k: int over the steps older than the window of wdot e^(-s_k lag)
class BassetHistory {
 public:
  BassetHistory() = default;
  // window W >= 1 steps, M >= 0 tail modes, tail_dt: the step the tail is laid out for.
  BassetHistory(int window, int modes, double tail_dt) :
      window_(window), modes_(modes), tail_dt_(tail_dt), tail_(modes, (window + 1) * tail_dt)
  {
    for (int k = 0; k < modes; k++) {
      const double s = tail_.rate[k];
      decay_.push_back(std::exp(-s * tail_dt));
      // a step of lag W + 1, its wdot constant: int over it of exp(-s (t - tau)) dtau
      feed_.push_back(std::exp(-s * (window + 1) * tail_dt) * -std::expm1(-s * tail_dt) / s);
    }
  }
  int size() const { return 7 + 3 * window_ + 3 * modes_; }
  int window() const { return window_; }
  int modes() const { return modes_; }
  double tail_dt() const { return tail_dt_; }
  const BassetTail &tail() const { return tail_; }

  // A new step begins: the last evaluation's wdot becomes history. The modes decay by one step
  // and take in the step leaving the window: decay[k], feed[k] (HistorySteps where the steps
  // differ in length; those of the layout otherwise).
  void commit(double *s) const { commit(s, decay_.data(), feed_.data()); }
  void commit(double *s, const double *decay, const double *feed) const
  {
    if (s[0] < 0.5) return;    // not evaluated yet
    if (s[0] < 1.5) {          // the first end value: no step behind it yet
      for (int d = 0; d < 3; d++)
        s[1 + d] = s[4 + d];
      s[0] = 2.0;
      return;
    }
    double *win = s + 7, *modes = s + 7 + 3 * window_;
    for (int d = 0; d < 3; d++) {
      const double oldest = win[3 * (window_ - 1) + d];
      for (int k = 0; k < modes_; k++)
        modes[3 * k + d] = decay[k] * modes[3 * k + d] + feed[k] * oldest;
      for (int lag = window_ - 1; lag > 0; lag--)
        win[3 * lag + d] = win[3 * (lag - 1) + d];
      win[d] = 0.5 * (s[1 + d] + s[4 + d]);
      s[1 + d] = s[4 + d];
    }
  }

  // The history force at this step: returns m_h (the weight of this step's unknown
  // acceleration) and the known part H [force]; both zero at an atom's first evaluation.
  // Another kernel (history_kernel.h) gives its own weights: window[0..W] for the steps of
  // lag 0..W over 2 sqrt(dt) (window_weight), tail[k] for the modes (BassetTail::weight).
  double known_force(double *s, double coefficient, double dt, double *known, const double *window = nullptr,
                     const double *tail = nullptr) const
  {
    known[0] = known[1] = known[2] = 0.0;
    if (s[0] < 1.5) {
      s[0] = 1.0;
      return 0.0;
    }
    const double root = std::sqrt(dt);
    const double *win = s + 7, *modes = s + 7 + 3 * window_;
    for (int d = 0; d < 3; d++) {
      double sum = 0.0;
      for (int lag = 1; lag <= window_; lag++)
        sum += 2.0 * root * (window ? window[lag] : window_weight(lag)) * win[3 * (lag - 1) + d];
      for (int k = 0; k < modes_; k++)
        sum += (tail ? tail[k] : tail_.weight[k]) * modes[3 * k + d];
      known[d] = coefficient * sum;
    }
    return current_weight(s, coefficient, dt, window);
  }

  // m_h alone (known_force's return), for a solve that moves it with the sphere's mass.
  double current_weight(const double *s, double coefficient, double dt, const double *window = nullptr) const
  {
    return s[0] < 1.5 ? 0.0 : 2.0 * coefficient * std::sqrt(dt) * (window ? window[0] : 1.0);
  }

  // This step's wdot = Du/Dt - a, once the acceleration is known.
  static void store(double *s, const double *wdot)
  {
    for (int d = 0; d < 3; d++)
      s[4 + d] = wdot[d];
  }

 private:
  int window_ = 0, modes_ = 0;
  double tail_dt_ = 0.0;
  BassetTail tail_;
  std::vector<double> decay_, feed_;
};

// The lengths of the window's steps, for steps that change (fix dt/reset, a timestep changed
// between runs). They are the same for every atom: an atom's window shifts at every step once
// its history has begun, and its slots before that hold zeros. Each step of the window is then
// weighted by the kernel's integral over its true ages, and the tail's modes decay by the true
// step and take in the leaving step over its true ages, so that the history stays that of the
// real times. The tail's exponential sum keeps the rates it was laid out for (t_win = (W + 1) dt0):
// where the steps became shorter, it also serves ages below t_win, down to (W + 1) dt.
class HistorySteps {
 public:
  HistorySteps() = default;
  HistorySteps(int window, double dt) : length_(window, dt) {}
  const std::vector<double> &lengths() const { return length_; }
  void set_lengths(const double *lengths)
  {
    for (std::size_t l = 0; l < length_.size(); l++)
      length_[l] = lengths[l];
  }
  bool uniform(double dt) const
  {
    for (double h : length_)
      if (h != dt) return false;
    return true;
  }
  // bound[0..W + 1]: the ages of the steps' ends at an evaluation after a step dt, over dt.
  void bounds(double dt, double *bound) const
  {
    bound[0] = 0.0;
    double age = dt;
    for (std::size_t l = 0; l <= length_.size(); l++) {
      bound[l + 1] = age / dt;
      if (l < length_.size()) age += length_[l];
    }
  }
  // The commit between the step just evaluated (length last) and the next (length next): the
  // decay of the modes over next, and the feed of the oldest step, whose ages at the next
  // evaluation are a..a + h, int exp(-s age) = exp(-s a) (1 - exp(-s h)) / s; then the window
  // shifts.
  void advance(double last, double next, const BassetTail &tail, double *decay, double *feed)
  {
    const int window = static_cast<int>(length_.size());
    double age = next + last;
    for (int l = 0; l < window - 1; l++)
      age += length_[l];
    const double oldest = length_[window - 1];
    for (std::size_t k = 0; k < tail.rate.size(); k++) {
      const double s = tail.rate[k];
      decay[k] = std::exp(-s * next);
      feed[k] = std::exp(-s * age) * -std::expm1(-s * oldest) / s;
    }
    for (int l = window - 1; l > 0; l--)
      length_[l] = length_[l - 1];
    length_[0] = last;
  }

 private:
  std::vector<double> length_;    // of the steps of lag 1..W
};

// Magnus lift of a spinning sphere, Rubinow & Keller, J. Fluid Mech. 11, 447 (1961), at low
// Reynolds number: F = pi R^3 rho_f Omega x (v - u) = pi R^3 rho_f (w x Omega), Omega the
// spin relative to the fluid, omega_p - (curl u) / 2.
inline void magnus_force(double radius, double fluid_density, const double *spin, const double *slip, double *force)
{
  const double c = pi * radius * radius * radius * fluid_density;
  force[0] = c * (slip[1] * spin[2] - slip[2] * spin[1]);
  force[1] = c * (slip[2] * spin[0] - slip[0] * spin[2]);
  force[2] = c * (slip[0] * spin[1] - slip[1] * spin[0]);
}

// Saffman's shear lift, Saffman, J. Fluid Mech. 22, 385 (1965) (corrigendum 31, 624 (1968)),
// in the vector form F = 1.615 d^2 sqrt(rho_f mu_f / |omega_f|) C (w x omega_f) for a sphere
// with slip w in a fluid of vorticity omega_f = curl u (Crowe, Sommerfeld & Tsuji, Multiphase
// Flows with Droplets and Particles (1998), ch. 4), towards the faster fluid for a sphere that
// lags it. C is Mei's finite-Re correction (Mei, Int. J. Multiphase Flow 18, 145 (1992)):
// with Re_p = rho_f |w| d / mu_f, Re_s = rho_f |omega_f| d^2 / mu_f, b = Re_s / (2 Re_p),
//   C = (1 - 0.3314 b^1/2) exp(-Re_p / 10) + 0.3314 b^1/2   (Re_p <= 40),
//   C = 0.0524 (b Re_p)^1/2                                  (Re_p > 40); C -> 1 as Re_p -> 0.
inline double saffman_mei_correction(double re_p, double re_s)
{
  if (re_p <= 0.0) return 1.0;
  const double b = re_s / (2.0 * re_p);
  if (re_p <= 40.0) return (1.0 - 0.3314 * std::sqrt(b)) * std::exp(-0.1 * re_p) + 0.3314 * std::sqrt(b);
  return 0.0524 * std::sqrt(b * re_p);
}

inline void saffman_force(double diameter, double fluid_density, double viscosity, const double *slip,
                          const double *vorticity, double *force)
{
  force[0] = force[1] = force[2] = 0.0;
  const double vort =
      std::sqrt(vorticity[0] * vorticity[0] + vorticity[1] * vorticity[1] + vorticity[2] * vorticity[2]);
  if (vort == 0.0) return;
  const double speed = std::sqrt(slip[0] * slip[0] + slip[1] * slip[1] + slip[2] * slip[2]);
  const double re_p = fluid_density * speed * diameter / viscosity;
  const double re_s = fluid_density * vort * diameter * diameter / viscosity;
  const double c =
      1.615 * diameter * diameter * std::sqrt(fluid_density * viscosity / vort) * saffman_mei_correction(re_p, re_s);
  force[0] = c * (slip[1] * vorticity[2] - slip[2] * vorticity[1]);
  force[1] = c * (slip[2] * vorticity[0] - slip[0] * vorticity[2]);
  force[2] = c * (slip[0] * vorticity[1] - slip[1] * vorticity[0]);
}

}    // namespace lubricated

// The step-exact contact (contact_step.h) under a steady load: an acceleration b along the
// normal that presses the pair together (b > 0: gravity on a sphere resting on a floor; doc/model.rst,
// "Contacts under a steady load").
//
// contact_acceleration() lands a leapfrog step on the isolated pair's trajectory: free flight apart
// and a force-free oscillator in overlap. The integrator adds the other forces on top, which is exact
// in sustained contact (the recurrence then oscillates about the shifted equilibrium) but not in the
// steps where a contact starts or ends: under a load each such step returns the pair faster by about
// 0.03 |b| dt, and a sphere resting on a wall keeps hopping (at e_d = 1 without bound). Here the
// exact trajectory is that of the forced system
//
//   apart (g >= 0):  g'' = -b                               (a parabola),
//   in overlap:      g'' = -omega0^2 (g - g_b) - 2 a g',  g_b = -b / k'
//
// (k' = stiffness_step: the equilibrium about which the sustained recurrence with the integrator's
// -b oscillates exactly, so that a contact passing from event steps to sustained steps is one
// trajectory; omega0^2 / k' = 1 + O((omega dt)^2)). In h = g - g_b the overlap is the free
// oscillator of contact_step.h, which leaves the overlap at h = -g_b. The acceleration returned is
// the contact's alone: the integrator's own -b completes the step, (g2 - 2 g1 + g0) / dt^2 = A - b.
// With b = 0 normal_force() takes contact_step.h's forms (bit for bit what they were).
#pragma once

#include "contact_step.h"

#include <algorithm>
#include <cmath>

namespace lubricated {

struct SteadyLoad {
  double b = 0.0;       // acceleration pressing the pair together  [length/time^2]
  double rest = 0.0;    // g_b = -b / k', the overlap's equilibrium  [length]
};

inline SteadyLoad steady_load(const ContactStep &cs, double b)
{
  SteadyLoad l;
  l.b = b;
  l.rest = -b / cs.stiffness_step;
  return l;
}

// Whether the contact can act under the load: in overlap, or within a step of it (the flight over a
// step moves the gap by u dt - b dt^2 at most, as seen from now).
inline bool contact_possible(double g1, double u, double dt, double b)
{
  return g1 < std::fabs(u) * dt + std::fabs(b) * dt * dt;
}

namespace detail {

struct LoadedMotion {
  double gap = 0.0, velocity = 0.0;
  bool touched = false;    // in overlap at some time of it
};

// The forced system from gap g and velocity v over time t, through any number of entries and exits
// (16 at most: the last regime then runs on). loss: the entry loss of the first entry from flight.
inline LoadedMotion loaded_motion(const ContactStep &cs, const SteadyLoad &load, double g, double v, double t,
                                  const EntryLoss *loss = nullptr)
{
  const double a = cs.decay_rate, w = cs.omega, b = load.b, threshold = -load.rest;
  bool touched = false, entered = false;
  for (int segment = 0;; ++segment) {
    const bool last = segment == 15;
    const bool contact = g < 0.0 || (g == 0.0 && (v < 0.0 || (v == 0.0 && b > 0.0)));
    if (!contact) {
      // Downward crossing of g + v s - b s^2 / 2 = 0 (where the velocity is -sqrt(D)).
      const double D = v * v + 2.0 * b * g;
      double lands_after = t, speed = 0.0;
      bool lands = false;
      if (D >= 0.0 && !last) {
        speed = std::sqrt(D);
        if (v <= 0.0 && speed - v > 0.0)
          lands_after = 2.0 * g / (speed - v), lands = true;
        else if (v > 0.0 && b > 0.0)
          lands_after = (v + speed) / b, lands = true;
      }
      if (!lands || lands_after >= t) return {g + v * t - 0.5 * b * t * t, v - b * t, touched};
      v = loss && !entered ? -loss->start_speed(speed) : -speed;
      entered = touched = true;
      g = 0.0;
      t -= lands_after;
      continue;
    }
    // In overlap: h(s) = exp(-a s) (A cos ws + B sin ws), h' = exp(-a s) (P cos ws - Q sin ws).
    touched = true;
    const double A = g - load.rest, B = (v + a * A) / w, P = v, Q = A * w + a * B;
    auto h = [&](double s) { return std::exp(-a * s) * (A * std::cos(w * s) + B * std::sin(w * s)); };
    auto rate = [&](double s) { return std::exp(-a * s) * (P * std::cos(w * s) - Q * std::sin(w * s)); };
    auto stay = [&]() { return LoadedMotion{load.rest + h(t), rate(t), true}; };
    if (last || (P == 0.0 && Q == 0.0)) return stay();
    // h' ~ cos(ws + psi): h rises from its next minimum (lo) to the maximum after it (hi), and can
    // leave the overlap (h = threshold) only there; a later maximum is lower unless threshold <= 0,
    // where this one already leaves.
    const double psi = std::atan2(Q, P);
    double lo = 0.0, hi;
    if (psi >= -0.5 * pi && psi < 0.5 * pi) {
      hi = (0.5 * pi - psi) / w;
    } else {
      lo = (psi >= 0.5 * pi ? 1.5 * pi - psi : -0.5 * pi - psi) / w;
      hi = lo + pi / w;
    }
    if (lo >= t || !(h(hi) > threshold)) return stay();
    const double end = std::min(hi, t), h_end = h(end), h_lo = h(lo);
    if (h_end < threshold) return stay();
    double s = lo;
    if (h_lo < threshold) {
      auto below = [&](double x, double &df) {
        df = -rate(x);
        return threshold - h(x);
      };
      double evaluated_at;
      const double guess = lo + (end - lo) * (threshold - h_lo) / (h_end - h_lo);
      s = falling_root(below, lo, end, guess, evaluated_at);
    }
    v = std::max(rate(s), 0.0);
    g = 0.0;
    t -= s;
    if (!(t > 0.0)) return {g, v, true};
  }
}

}    // namespace detail

// contact_acceleration() (contact_step.h) under the load b: the contact's relative acceleration
// over the coming step (force / m_e, along n) that, with the integrator's own -b, lands a leapfrog
// step on the forced system's trajectory through the gaps a step ago (g1 - u dt) and now (g1). In
// every case, sustained contact included (there sustained_acceleration(), exact under the load).
// loss and kick as contact_acceleration's.
__attribute__((noinline)) inline double loaded_contact_acceleration(const ContactStep &cs, double g1, double u,
                                                                    double b, const EntryLoss *loss = nullptr,
                                                                    double kick = 0.0)
{
  const SteadyLoad load = steady_load(cs, b);
  const double dt = cs.dt, a = cs.decay_rate, w = cs.omega, threshold = -load.rest;
  const double g0 = g1 - u * dt;
  // The step from the state now (g1, v1 after the kick): what the contact adds to -b and the kick.
  // flying: in flight over the last step, where a step without contact is the integrator's own.
  auto landing = [&](double v1, const EntryLoss *entry, bool flying = false) {
    const detail::LoadedMotion m = detail::loaded_motion(cs, load, g1, v1 + kick, dt, entry);
    if (flying && !m.touched) return 0.0;
    return ((m.gap - g1) * cs.inv_dt - u) * cs.inv_dt + b - kick * cs.inv_dt;
  };
  if (g1 >= 0.0 && g0 >= 0.0) return landing(u - 0.5 * b * dt, loss, true);    // the velocity now
  if (g1 >= 0.0) {
    // Contact ended s after the previous sample, at h = threshold with speed v_e, then a parabola
    // over r = dt - s to g1: v_e = (g1 + b r^2 / 2) / r. The oscillator from there back over s meets
    // h0: times w r exp(-a s), falling in s from -w dt g0 > 0 to -g1 sin(w dt) <= 0:
    //   threshold w r cos ws - (g1 + b r^2 / 2 + a threshold r) sin ws - w r h0 exp(-a s) = 0.
    const double h0 = g0 - load.rest;
    auto excess = [&](double s, double &df) {
      const double r = dt - s, decay = std::exp(-a * s), sn = std::sin(w * s), cn = std::cos(w * s);
      const double lift = g1 + 0.5 * b * r * r + a * threshold * r;
      df = -threshold * w * cn - threshold * w * w * r * sn + (b * r + a * threshold) * sn - w * lift * cn +
           w * h0 * decay * (1.0 + a * r);
      return threshold * w * r * cn - lift * sn - w * r * h0 * decay;
    };
    double evaluated_at;
    const double s = detail::falling_root(
        excess, 0.0, dt, dt * detail::table_lookup(cs.exit_guess, ContactStep::table_size, g1 / -g0), evaluated_at);
    const double r = dt - s;
    const double v_exit =
        s < 0.5 * dt ? (g1 + 0.5 * b * r * r) / r
                     : w * (threshold * std::cos(w * s) - h0 * std::exp(-a * s)) / std::sin(w * s) - a * threshold;
    return landing(v_exit - b * r, nullptr);
  }
  if (g0 >= 0.0) {
    // Contact started s before now, after a parabola from g0 over r = dt - s at the approach speed
    // v = g0 / r + b r / 2 (the oscillator from S(v), EntryLoss), and reached h1 = g1 - g_b. With
    // p = -r S(v): exp(-a s) (r threshold (cos ws + a/w sin ws) + p sin ws / w) - r h1 = 0, falling.
    const double h1 = g1 - load.rest;
    auto start = [&](double r, double &dp) {    // p and dp/ds
      if (!loss) {
        dp = b * r;
        return -g0 - 0.5 * b * r * r;
      }
      if (!(r > 0.0)) {
        dp = 0.0;
        return -g0;
      }
      const double v = g0 / r + 0.5 * b * r;
      double dS;
      const double S = loss->start_speed(v, dS);
      dp = S - dS * (g0 / r - 0.5 * b * r);
      return -r * S;
    };
    auto mismatch = [&](double s, double &df) {
      const double r = dt - s, decay = std::exp(-a * s), sn = std::sin(w * s), cn = std::cos(w * s);
      double dp;
      const double p = start(r, dp);
      const double X = r * threshold * (cn + a / w * sn) + p * sn / w;
      const double dX = -threshold * (cn + a / w * sn) + r * threshold * (a * cn - w * sn) + dp * sn / w + p * cn;
      df = decay * (dX - a * X) + h1;
      return decay * X - r * h1;
    };
    const double guess_ratio = loss ? -g1 * -u / (loss->start_speed(-u) * g0) : -g1 / g0;
    double evaluated_at;
    const double s = detail::falling_root(
        mismatch, 0.0, dt,
        g0 > 0.0 ? dt * detail::table_lookup(cs.entry_guess, ContactStep::table_size, guess_ratio) : dt, evaluated_at);
    const double r = dt - s, decay = std::exp(-a * s), sn = std::sin(w * s), cn = std::cos(w * s);
    const double v_in = s < 0.5 * dt ? (loss ? -loss->start_speed(g0 / r + 0.5 * b * r) : -g0 / r - 0.5 * b * r)
                                     : w * (h1 / decay - threshold * cn) / sn - a * threshold;
    const double B = (v_in + a * threshold) / w;
    const double v1 = decay * (v_in * cn - (threshold * w + a * B) * sn);
    // The kick may stop the oscillator's own velocity, not reverse or speed it up (as
    // contact_acceleration).
    const double stop = v1 < 0.0 ? std::min(std::max(kick, 0.0), -v1) : std::max(std::min(kick, 0.0), -v1);
    return landing(v1 + stop - kick, nullptr);
  }
  // In overlap a step ago and now: the recurrence about g_b, exact as the sustained spring-dashpot
  // where it stays in overlap; otherwise the oscillator now leaves within the step.
  const double h1 = g1 - load.rest, h0 = g0 - load.rest;
  if (load.rest + recurrence_gap(cs, h1, h0) < 0.0 || !(cs.S > 1e-12)) return sustained_acceleration(cs, g1, u);
  return landing(oscillator_sine_part(cs, h1, h0) * w - a * h1 - kick, nullptr);
}

// contact_acceleration_at_start() under the load b: velocity Verlet's first half kick, with the
// integrator's -b, lands on the forced trajectory from (g, v) (full-step velocity).
__attribute__((noinline)) inline double loaded_contact_acceleration_at_start(const ContactStep &cs, double g, double v,
                                                                             double b, const EntryLoss *loss = nullptr)
{
  const SteadyLoad load = steady_load(cs, b);
  const double dt = cs.dt;
  const detail::LoadedMotion m = detail::loaded_motion(cs, load, g, v, dt, g >= 0.0 ? loss : nullptr);
  if (!m.touched && g >= 0.0) return 0.0;
  return 2.0 * ((m.gap - g) / dt - v) / dt + b;
}

}    // namespace lubricated

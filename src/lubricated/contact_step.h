// Time integration of the spring-dashpot over one step (numerics for doc/model.rst, "Solid
// contact: the spring-dashpot").
//
// Sampling F_s = k d + c d_dot once per step misses e_d badly at N_c = 8: the dashpot
// switches on and off part-way through a step, and the impulse lost or gained there is
// of order c u dt (60 % of the rebound speed at e_d = 0.1). Instead the force applied over
// a step is the constant force that makes a leapfrog step (LAMMPS's velocity Verlet, whose
// positions and mid-step velocities form a leapfrog) land exactly on the analytic solution
// of the isolated pair:
//
//   g'' = -omega0^2 g - 2 a g'  in overlap (g < 0),  g'' = 0 apart,
//   a = c / (2 m_e) = -ln(e_d) / t_c,  omega = pi / t_c (damped frequency, by construction).
//
// With g1 the gap now and u the normal velocity of the last step (so g0 = g1 - u dt was
// the gap a step ago), the exact trajectory through g0 and g1 gives g2 one step ahead and
//   F = m_e (g2 - 2 g1 + g0) / dt^2.
// In sustained contact this is a spring-dashpot with per-step constants
//   k' = m_e (1 + E^2 - 2 E C) / dt^2,  c' = m_e (1 - E^2) / dt,  E = exp(-a dt), C = cos(omega dt),
// as cheap as the sampled force; only the steps where the contact starts or ends solve
// for the entry or exit time. An isolated collision then rebounds with exactly e_d after
// exactly t_c, for any impact phase; other forces acting during the contact (gravity, other
// contacts) make it approximate at O(their impulse over t_c). The entry and exit equations
// degenerate when the contact lasts a single step (omega dt = pi), so contacts shorter than
// min_steps_per_contact = 1.5 steps are integrated as if they lasted 1.5 steps: e_d is kept,
// the duration is what the time step can resolve.
#pragma once

#include "guess_tables.h"
#include "inline_atan.h"
#include "inline_exp.h"
#include "inline_sincos.h"
#include "spring_dashpot.h"

#include <algorithm>
#include <cmath>

namespace lubricated {

struct ContactStep {
  // Entry and exit times within a step depend on the gap ratio and the steps per contact only;
  // tabulated guesses (see make_contact_step) let Newton finish in one or two iterations.
  static constexpr int table_size = guess_table_size;
  // Shared, kept for the process (detail::guess_tables): a contact's constants copy cheaply.
  const double *exit_guess = nullptr;     // exit time s / dt against x = r / (1 + r), r = g1 / -g0
  const double *entry_guess = nullptr;    // entry time s / dt against x = r / (1 + r), r = -g1 / g0
                                          // (stored right after the exit guesses)
  double table_steps = 0.0;               // t_c / dt (and table_restitution e_d) they were built for
  double table_restitution = 0.0;
  double dt = 0.0;
  double inv_dt = 0.0;          // 1 / dt (engines multiply: no division per pair)
  double contact_time = 0.0;    // t_c as integrated (at least min_steps_per_contact steps)
  double decay_rate = 0.0;      // a      [1/time]
  double omega = 0.0;           // omega  [1/time]
  double E = 1.0, C = 1.0, S = 0.0;
  double stiffness_step = 0.0;    // k' / m_e  [1/time^2]
  double damping_step = 0.0;      // c' / m_e  [1/time]
};

constexpr double min_steps_per_contact = 1.5;

// The contact duration a step of dt can integrate (see above).
inline double resolved_contact_time(double t_c, double dt)
{
  return std::max(t_c, min_steps_per_contact * dt);
}

// Per-step constants of a damped oscillator that completes half a period in t_c and keeps the
// factor e of its speed over it (e = 0: fully damped, E = 0): E = exp(-a dt), C = cos(omega dt),
// S = sin(omega dt), a = -ln(e) / t_c, omega = pi / t_c, and the spring-dashpot per unit mass
// that lands a leapfrog step on it, k' = (1 + E^2 - 2 E C) / dt^2, c' = (1 - E^2) / dt. The
// normal contact (e_d) and the tangential spring (e_t, tangential.h) share them.
struct OscillatorStep {
  double decay_rate = 0.0, omega = 0.0, E = 0.0, C = 1.0, S = 0.0;
  double stiffness_step = 0.0, damping_step = 0.0;
};

inline OscillatorStep oscillator_step(double restitution, double t_c, double dt)
{
  OscillatorStep o;
  o.omega = pi / t_c;
  if (restitution > 0.0) {
    o.decay_rate = -std::log(restitution) / t_c;
    o.E = std::exp(-o.decay_rate * dt);
  }
  o.C = std::cos(o.omega * dt);
  o.S = std::sin(o.omega * dt);
  o.stiffness_step = (1.0 + o.E * o.E - 2.0 * o.E * o.C) / (dt * dt);
  o.damping_step = (1.0 - o.E * o.E) / dt;
  return o;
}

// Gap a step ahead of g1 (g0 a step before it) by the exact two-step recurrence of the damped
// oscillator, valid while the pair stays in overlap.
inline double recurrence_gap(const ContactStep &cs, double g1, double g0)
{
  return 2.0 * cs.E * cs.C * g1 - cs.E * cs.E * g0;
}

// Sustained contact: in overlap a step ago and now and, by the recurrence, a step ahead. There
// (g2 - 2 g1 + g0) / dt^2 is a spring-dashpot with the per-step constants k', c' above (per
// unit reduced mass: an acceleration, u the normal velocity of the last step).
inline bool in_sustained_contact(const ContactStep &cs, double g1, double g0)
{
  return (g1 < 0.0) & (g0 < 0.0) & (recurrence_gap(cs, g1, g0) < 0.0);
}
inline double sustained_acceleration(const ContactStep &cs, double g1, double u)
{
  return -(cs.stiffness_step * g1 + cs.damping_step * u);
}

// A loss at the start of a contact (the wet-restitution calibration of normal_model.h): the
// oscillator starts at S(v) <= v, v the approach speed. S depends on v alone, so every step
// reconstructs it from the gaps it sees: no contact history.
struct EntryLoss {
  double film_loss = 0.0;         // speed the film takes from eps_al to contact, one way  [velocity]
  double pending = 0.0;           // part of it not yet in v (applied in the steps to come)
  double stokes_speed = 0.0;      // impact speed / St  [velocity]
  double decay_constant = 0.0;    // A of e / e_d = exp(-A / St)
  double restitution = 1.0;       // e_d of the contact

  // After the pending film the contact starts at v_c = v - pending; u0 = v_c + film_loss is
  // the impact speed of an isolated collision. The contact must return
  //   e_d exp(-A / St(u0)) u0 + film_loss
  // for the film's pull on the way out to leave e_d exp(-A / St) u0; the pending film acts
  // at the start of the contact, so it is added back. dS = S'(v).
  double start_speed(double v, double &dS) const
  {
    const double contact = v - pending;
    dS = 1.0;
    if (!(contact > 0.0)) return v;    // the film stops the pair before contact
    const double u0 = contact + film_loss, x = decay_constant * stokes_speed / u0;
    const double decay = std::exp(-x);
    const double calibrated = u0 * decay + film_loss / restitution;
    if (!(calibrated < contact)) return v;    // never less loss than the dry contact
    dS = decay * (1.0 + x);
    return pending + calibrated;
  }
  double start_speed(double v) const
  {
    double dS;
    return start_speed(v, dS);
  }
};

// reuse: the contact's constants before a change of the time step within a run (reset_dt).
// Its guess tables are kept where the steps per contact changed by less than table_tolerance,
// or those of the band taken otherwise: a guess a few per cent off costs Newton an iteration or
// two in the steps where a contact starts or ends, far less than building tables at each change. Without reuse (a run's set-up) the tables are exact for these steps.
inline ContactStep make_contact_step(const SpringDashpot &sd, double dt, const ContactStep *reuse = nullptr)
{
  ContactStep cs;
  cs.dt = dt;
  cs.inv_dt = 1.0 / dt;
  // Same e_d = exp(-a t_c) with t_c = pi / omega, at no less than 1.5 steps per contact.
  cs.contact_time = resolved_contact_time(contact_duration_of(sd), dt);
  const double restitution = restitution_of(sd);
  const OscillatorStep o = oscillator_step(restitution, cs.contact_time, dt);
  cs.omega = o.omega;
  cs.decay_rate = o.decay_rate;
  cs.E = o.E, cs.C = o.C, cs.S = o.S;
  cs.stiffness_step = o.stiffness_step;
  cs.damping_step = o.damping_step;
  const double steps = cs.contact_time / dt;
  cs.table_restitution = restitution;
  if (reuse && reuse->table_restitution == restitution &&
      std::fabs(steps / reuse->table_steps - 1.0) <= table_tolerance) {
    cs.exit_guess = reuse->exit_guess, cs.entry_guess = reuse->entry_guess, cs.table_steps = reuse->table_steps;
    return cs;
  }
  const detail::GuessTables &t = detail::guess_tables(restitution, steps, reuse != nullptr);
  cs.exit_guess = t.guess, cs.entry_guess = t.guess + detail::GuessTables::size, cs.table_steps = t.steps;
  return cs;
}

// Gap after time t for a contact (g < 0) known to reopen within t: w s = atan2(-A, B) at the
// exit, where cos = B / rho and sin = -A / rho, so the exit speed is exp(-a s) w rho; free
// flight after that.
// INLINE: atan2 and exp without calls, for loops the compiler vectorises (normal_model.h,
// overlap_exit_force); libm's in scalar code, where they are faster.
template <bool INLINE = false>
__attribute__((always_inline)) inline double exit_and_fly(const ContactStep &cs, double A, double B, double t)
{
  const double s = (INLINE ? atan2_nonnegative_inline(-A, B) : std::atan2(-A, B)) / cs.omega;
  const double decay = INLINE ? exp_inline(-cs.decay_rate * s) : std::exp(-cs.decay_rate * s);
  return decay * cs.omega * std::sqrt(A * A + B * B) * (t - s);
}

// Gap a step ahead of a contact in overlap now (g1) and a step ago (g0) whose recurrence leaves
// the overlap within the step (S > 0): the oscillator through g0 and g1 exits and flies on.
// B of the oscillator g(s) = exp(-a s) (A cos ws + B sin ws), A = g1, through g0 a step before.
inline double oscillator_sine_part(const ContactStep &cs, double g1, double g0)
{
  return (g1 * cs.C - g0 * cs.E) / cs.S;
}
template <bool INLINE = false>
__attribute__((always_inline)) inline double exit_gap(const ContactStep &cs, double g1, double g0)
{
  return exit_and_fly<INLINE>(cs, g1, oscillator_sine_part(cs, g1, g0), cs.dt);
}

// Gap after time t, starting in overlap or at contact (g <= 0) with rate v; once the gap
// reopens the motion continues in free flight with the exit speed.
inline double propagate_contact(const ContactStep &cs, double g, double v, double t)
{
  const double a = cs.decay_rate, w = cs.omega;
  const double A = g, B = (v + a * g) / w;    // g(s) = exp(-a s) (A cos ws + B sin ws)
  const double g_t = std::exp(-a * t) * (A * std::cos(w * t) + B * std::sin(w * t));
  if (g_t < 0.0 || A >= 0.0) return g_t;    // still in contact (an exit would stay apart)
  return exit_and_fly(cs, A, B, t);
}

// Relative normal acceleration (force / m_e, along n) applied over the coming step.
// g1: gap now; u: normal relative velocity over the last step (> 0 separating).
// kick: velocity change other forces (the film) give the pair over the coming step; in the
// steps where a contact starts the contact follows the motion after it (a film that stops
// the pair before contact leaves no contact to predict).
__attribute__((noinline)) inline double contact_acceleration(const ContactStep &cs, double g1, double u,
                                                             const EntryLoss *loss = nullptr, double kick = 0.0)
{
  const double dt = cs.dt, a = cs.decay_rate, w = cs.omega;
  const double g0 = g1 - u * dt;
  double g2;
  if (g1 >= 0.0) {
    if (g0 >= 0.0) {
      const double v = u + kick;
      if (g1 + v * dt >= 0.0) return 0.0;    // apart now and a step from now
      // Contact starts within the coming step, after free flight over g1.
      const double t_entry = g1 / -v;
      g2 = propagate_contact(cs, 0.0, loss ? -loss->start_speed(-v) : v, dt - t_entry);
      return (g2 - 2.0 * g1 + g0) / (dt * dt) - kick / dt;
    } else {
      // Contact ended within the last step: find the exit time s after the previous sample
      // such that the oscillator from g0 exits at s and flies on to g1:
      //   exp(-a s) w g0 (dt - s) + g1 sin(w s) = 0  (times -1 below, falling in s).
      auto excess = [&](double t, double &df) {
        const double decay = std::exp(-a * t), sn = std::sin(w * t), cs_ = std::cos(w * t);
        df = decay * w * g0 * (a * (dt - t) + 1.0) - g1 * w * cs_;
        return -decay * w * g0 * (dt - t) - g1 * sn;
      };
      double evaluated_at;
      const double s = detail::falling_root(
          excess, 0.0, dt, dt * detail::table_lookup(cs.exit_guess, ContactStep::table_size, g1 / -g0), evaluated_at);
      const double v_exit = s < 0.5 * dt ? g1 / (dt - s) : -std::exp(-a * s) * w * g0 / std::sin(w * s);
      return (v_exit - u) / dt;
    }
  } else if (g0 >= 0.0) {
    // Contact started within the last step, s before now, at the speed v_in of free flight:
    //   g0 h(s) + g1 (dt - s) = 0,  h(s) = exp(-a s) sin(w s) / w  (times -1, falling in s).
    // With an entry loss the oscillator starts at S(v), v = g0 / (dt - s) (EntryLoss), and
    // the mismatch is S(v) (dt - s) h(s) + g1 (dt - s), which is the above when S(v) = v.
    double decay_s = 1.0, sin_s = 0.0, cos_s = 1.0;
    auto mismatch = [&](double t, double &df) {
      decay_s = std::exp(-a * t), sin_s = std::sin(w * t), cos_s = std::cos(w * t);
      const double rest = dt - t;
      if (!loss) {
        df = -g0 * decay_s * (cos_s - a / w * sin_s) + g1;
        return -g0 * decay_s * sin_s / w - g1 * rest;
      }
      const double v = g0 / rest;
      double dS;
      const double S = loss->start_speed(v, dS);
      df = -(dS * v - S) * decay_s * sin_s / w - S * rest * decay_s * (cos_s - a / w * sin_s) + g1;
      return -S * rest * decay_s * sin_s / w - g1 * rest;
    };
    const double guess_ratio = loss ? -g1 * -u / (loss->start_speed(-u) * g0) : -g1 / g0;
    double evaluated_at;
    const double s = detail::falling_root(
        mismatch, 0.0, dt,
        g0 > 0.0 ? dt * detail::table_lookup(cs.entry_guess, ContactStep::table_size, guess_ratio) : dt, evaluated_at);
    {    // move decay_s, sin_s, cos_s from the last evaluated point to s (first order)
      const double shift = s - evaluated_at;
      decay_s *= 1.0 - a * shift;
      const double sin_old = sin_s;
      sin_s += w * shift * cos_s;
      cos_s -= w * shift * sin_old;
    }
    const double v_in =
        s < 0.5 * dt ? (loss ? -loss->start_speed(g0 / (dt - s)) : -g0 / (dt - s)) : g1 * w / (decay_s * sin_s);
    // The kick may stop the oscillator's own velocity, not reverse or speed it up (the film
    // was capped against the mean velocity of the last step, not this one).
    const double v1 = v_in * decay_s * (cos_s - a / w * sin_s);
    const double stop = v1 < 0.0 ? std::min(std::max(kick, 0.0), -v1) : std::max(std::min(kick, 0.0), -v1);
    g2 = propagate_contact(cs, g1, v1 + stop, dt);
    return (g2 - 2.0 * g1 + g0) / (dt * dt) - kick / dt;
  } else {
    // Sustained contact: the exact two-step recurrence of the damped oscillator.
    g2 = recurrence_gap(cs, g1, g0);
    if (g2 >= 0.0 && cs.S > 1e-12) g2 = exit_gap(cs, g1, g0);
  }
  return (g2 - 2.0 * g1 + g0) / (dt * dt);
}

// The same at the start of a run, where engines hold full-step velocities (velocity Verlet's
// v^n, not v^(n-1/2)) and apply only half a kick before the first position update: the
// acceleration that makes that first half-step land on the exact trajectory from (g, v).
__attribute__((noinline)) inline double contact_acceleration_at_start(const ContactStep &cs, double g, double v,
                                                                      const EntryLoss *loss = nullptr)
{
  const double dt = cs.dt;
  double g1;
  if (g >= 0.0) {
    if (g + v * dt >= 0.0) return 0.0;
    g1 = propagate_contact(cs, 0.0, loss ? -loss->start_speed(-v) : v, dt - g / -v);
  } else {
    g1 = propagate_contact(cs, g, v, dt);
  }
  return 2.0 * ((g1 - g) / dt - v) / dt;
}

namespace detail {

// For a contact under way at a midpoint start (below): the time tau near dt/2 at which the
// oscillator through (g, v) at time 0 has moved v dt over the step before, so that its points
// at tau - dt and tau are a leapfrog pair with velocity v. Newton from dt/2; returns dt/2
// (a second-order placement) where the pair would leave the overlap or Newton stalls.
inline double midpoint_start_time(const ContactStep &cs, double g, double v)
{
  const double dt = cs.dt, a = cs.decay_rate, w = cs.omega;
  const double A = g, B = (v + a * g) / w;    // g(t) = exp(-a t) (A cos wt + B sin wt)
  auto gap = [&](double t) { return std::exp(-a * t) * (A * std::cos(w * t) + B * std::sin(w * t)); };
  auto rate = [&](double t) {
    return std::exp(-a * t) * ((B * w - a * A) * std::cos(w * t) - (A * w + a * B) * std::sin(w * t));
  };
  double tau = 0.5 * dt;
  for (int it = 0; it < 8; ++it) {
    const double mismatch = gap(tau) - gap(tau - dt) - v * dt, slope = rate(tau) - rate(tau - dt);
    if (!(std::fabs(slope) > 0.0)) return 0.5 * dt;
    tau -= mismatch / slope;
    if (!(tau > 0.0 && tau < dt)) return 0.5 * dt;
    if (std::fabs(mismatch) <= 1e-13 * std::fabs(v * dt) + 1e-300) break;
  }
  return gap(tau) < 0.0 && gap(tau - dt) < 0.0 ? tau : 0.5 * dt;
}

}    // namespace detail

// The same at the start of a run under fix nve/sphere/midpoint. Its first step evaluates
// forces at X~ = X + dt/2 V + dt^2/8 A, A the set-up acceleration (a second-order start), and
// from then on takes X~ - dt V^n as the point a step before it (the leapfrog above). Both
// points must lie on one exact trajectory of the collision, which may run up to half a step
// early or late. A contact that would begin within the half step is therefore met where it
// begins: X~ stops at contact, and free flight before it is exact (a drift into the overlap
// would be read as a faster impact). A contact already under way is met where the oscillator
// has moved v dt over the step before (detail::midpoint_start_time). g: gap at X; v: normal
// velocity; drifted: where the rest of the set-up forces (the film) put X~. Returns A.
__attribute__((noinline)) inline double contact_acceleration_at_midpoint_start(const ContactStep &cs, double g,
                                                                               double v, double drifted)
{
  const double dt = cs.dt;
  const double target =
      g >= 0.0 ? std::max(drifted, 0.0)
               : drifted + propagate_contact(cs, g, v, detail::midpoint_start_time(cs, g, v)) - (g + 0.5 * v * dt);
  return 8.0 * (target - drifted) / (dt * dt);
}

// Whether contact_acceleration can be non-zero: in overlap, or within a step of it.
inline bool contact_possible(double g1, double u, double dt)
{
  return g1 < std::fabs(u) * dt;
}

// contact_acceleration() without an entry loss, for loops the compiler vectorises over the steps
// where a contact starts or ends (apart now or a step ago: g1 >= 0 or g0 >= 0; every lane pays
// for the three cases), without branches or calls (inline exp, sin, cos and atan2). Contacts in
// overlap now and a step ago (sustained, or leaving the overlap within the step) are resolved
// too, at little more cost (for loops over every kind of pair). The entry or exit time within
// the last step is falling_root's first Newton step from the tabulated guess, which meets its
// tolerance in nearly every such step (tests/kernel/test_vector_forms.cpp counts it on random
// draws); resolved = false where it does not: take
// contact_acceleration() there. Otherwise equal to it within rounding.
__attribute__((always_inline)) inline double event_acceleration_inline(const ContactStep &cs, double g1, double u,
                                                                       double kick, bool &resolved)
{
  const double dt = cs.dt, a = cs.decay_rate, w = cs.omega;
  const double g0 = g1 - u * dt;
  const bool exited = (g1 >= 0.0) & (g0 < 0.0), entered = (g1 < 0.0) & (g0 >= 0.0);
  // Newton's step: exit time from exp(-a s) w g0 (dt - s) + g1 sin(w s) = 0 (r = g1 / -g0), entry
  // time from g0 h(s) + g1 (dt - s) = 0 (r = -g1 / g0), both times -1 (falling in s). The share
  // r / (1 + r) of the tables as g1 / (g1 - g0) (no division by a zero g0), 0 in other lanes.
  const double numerator = exited ? g1 : -g1, denominator = exited ? g1 - g0 : g0 - g1;
  const double share = std::min(std::max(0.0, denominator > 0.0 ? numerator / denominator : 0.0), 1.0);
  const double tabulated = dt * detail::table_lookup_share(cs.exit_guess, ContactStep::table_size, share,
                                                           exited ? 0.0 : ContactStep::table_size + 1.0);
  const double x = std::min(std::max(entered & !(g0 > 0.0) ? dt : tabulated, 0.0), dt);
  double sin_x, cos_x;
  sincos_inline(w * x, sin_x, cos_x);
  const double decay_x = exp_inline(-a * x), rest_x = dt - x;
  const double f = exited ? -decay_x * w * g0 * rest_x - g1 * sin_x : -g0 * decay_x * sin_x / w - g1 * rest_x;
  const double df =
      exited ? decay_x * w * g0 * (a * rest_x + 1.0) - g1 * w * cos_x : -g0 * decay_x * (cos_x - a / w * sin_x) + g1;
  const double step = f == 0.0 ? 0.0 : f / df;
  const double s = x - step;
  // falling_root's bracket after its first evaluation: [x, dt] where f > 0, else [0, x].
  const double lo = f > 0.0 ? x : 0.0, hi = f > 0.0 ? dt : x;
  const bool converged = (f == 0.0) | ((std::fabs(step) <= 1e-7 * dt) & (s >= lo) & (s <= hi));
  resolved = converged | !(exited | entered);    // only entries and exits have a root to find

  // Free flight towards contact: the contact starts after g1 / -v and runs for the rest of the
  // step (propagate_contact from g = 0); a contact that ended s into the last step left at the
  // speed of the oscillator there (unless s < dt / 2, where the flight over dt - s gives it).
  const double v = u + kick;
  const double t = exited ? s : dt - g1 / -v;
  double sin_t, cos_t;
  sincos_inline(w * t, sin_t, cos_t);
  const double decay_t = exp_inline(-a * t);
  const double landing = decay_t * (v / w) * sin_t;
  const double approach = g1 + v * dt >= 0.0 ? 0.0 : (landing - 2.0 * g1 + g0) / (dt * dt) - kick / dt;
  const double v_exit = s < 0.5 * dt ? g1 / (dt - s) : -decay_t * w * g0 / sin_t;
  const double exit = (v_exit - u) / dt;

  // A contact that started s into the last step: the oscillator there, moved from x to s to first
  // order (as contact_acceleration), its velocity now stopped by the kick at most, then a whole
  // step (E, C, S), leaving the overlap on the way (exit_and_fly) if it does. In overlap a step
  // ago too: the recurrence, or the exit (exit_gap's B) where it leaves the overlap.
  const double shift = s - x;
  const double decay_s = decay_x * (1.0 - a * shift);
  const double sin_s = sin_x + w * shift * cos_x, cos_s = cos_x - w * shift * sin_x;
  const double v_in = s < 0.5 * dt ? -g0 / (dt - s) : g1 * w / (decay_s * sin_s);
  const double v1 = v_in * decay_s * (cos_s - a / w * sin_s);
  const double stop = v1 < 0.0 ? std::min(std::max(kick, 0.0), -v1) : std::max(std::min(kick, 0.0), -v1);
  const double B = entered ? (v1 + stop + a * g1) / w : oscillator_sine_part(cs, g1, g0);
  const double in_overlap = entered ? cs.E * (g1 * cs.C + B * cs.S) : recurrence_gap(cs, g1, g0);
  const bool flies = (in_overlap >= 0.0) & (entered | (cs.S > 1e-12));
  const double g2 = flies ? exit_and_fly<true>(cs, g1, B, dt) : in_overlap;
  const double entry = (g2 - 2.0 * g1 + g0) / (dt * dt) - kick / dt;
  const bool overlapping = (g1 < 0.0) & (g0 < 0.0);
  const double overlap = in_overlap < 0.0 ? sustained_acceleration(cs, g1, u) : (g2 - 2.0 * g1 + g0) / (dt * dt);

  const double acceleration = exited ? exit : entered ? entry : overlapping ? overlap : approach;
  return contact_possible(g1, u, dt) ? acceleration : 0.0;
}

}    // namespace lubricated

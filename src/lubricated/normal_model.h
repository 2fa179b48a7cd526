// The full normal interaction of one contact: spring-dashpot in overlap plus the lubrication
// film (doc/model.rst, "Zones" to "The per-pair cap"). Engines call normal_force() once per
// neighbour pair or per particle-wall pair; everything else here is set up once per type pair.
//
// Conventions (the only place they are written down):
//   n     unit normal pointing from the partner (particle j or the wall) to particle i;
//   gap   surface separation h = |x_i - x_j| - R_i - R_j (wall: distance - R_i), < 0 in overlap;
//   u_n   (v_i - v_j) . n, > 0 when the surfaces separate; overlap rate d_dot = -u_n;
//         the velocity over the last step of the force-evaluation points: velocity
//         Verlet's mid-step velocity, V^n under fix nve/sphere/midpoint;
//   m_e   reduced mass m_i m_j / (m_i + m_j); m_i for a wall or a partner that cannot move
//         (src/contact_mass for LAMMPS);
//   force on i = (contact + lubrication) n, on j the opposite; energy = k d^2 / 2.
#pragma once

#include "coefficients.h"
#include "contact_step.h"
#include "loaded_contact.h"
#include "lubrication.h"
#include "spring_dashpot.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lubricated {

struct NormalModel {
  SpringDashpot contact;
  ContactStep step;     // exact integration over one step (contact_step.h)
  bool exact = true;    // false: sample F_s once per step (for comparison only)
  Lubrication lubrication;
  double legendre = 0.0;       // A > 0: calibrate the contact to e / e_d = exp(-A / St)
  double restitution = 1.0;    // e_d of the contact

  bool calibrated() const { return legendre > 0.0 && lubrication.active(); }

  // Whether the pair needs evaluating at gap g with normal velocity u (cheap pre-test):
  // in the film or in contact now, or within the last or next step of it.
  bool acts(double gap, double radius, double u) const
  {
    return gap < reach(radius) + (exact ? std::fabs(u) * step.dt : 0.0);
  }
  // The same under a steady load b (loaded_contact.h): a pair that gravity may press into contact
  // within the step.
  bool acts(double gap, double radius, double u, double load) const
  {
    return gap < reach(radius) + (exact ? std::fabs(u) * step.dt + std::fabs(load) * step.dt * step.dt : 0.0);
  }

  // Largest gap (length) at which the model acts, for a contact of lubrication radius R.
  double reach(double radius) const { return lubrication.reach(radius); }

  // acts() before the square root, for a pair at squared distance rsq whose radii sum to radsum
  // (a wall: the sphere's radius), dv_dot_del = (v_i - v_j) . (x_i - x_j): false only where
  // acts() is false. The film's reach is bounded by its largest for a lubrication radius up to
  // radsum (a pair's 2 r_i r_j / (r_i + r_j) <= radsum / 2, a wall's r_i = radsum); then
  // gap < reach + |u_n| dt is rsq - |dv_dot_del| dt < (radsum + reach) r, squared where positive.
  bool may_act(double rsq, double dv_dot_del, double radsum) const
  {
    const double outer = radsum + lubrication.reach(radsum);
    if (!exact) return rsq < outer * outer;
    const double s = rsq - std::fabs(dv_dot_del) * step.dt;
    return s <= 0.0 || s * s < outer * outer * rsq;
  }
};

// The fixed eps_al of the coefficients: the given one, or with `activation dem` the gap where the
// wall film hands over to the unbounded drag (drag_handover_activation, lubrication.h; walls only,
// check_setup refuses it between spheres).
inline double activation_of(const Coefficients &c)
{
  return c.dem_activation() ? drag_handover_activation() : c.eps_activation;
}

// reuse: the model for the last time step (its guess tables may serve, contact_step.h).
inline NormalModel make_normal_model(const Coefficients &c, Partner partner, double dt,
                                     const NormalModel *reuse = nullptr)
{
  NormalModel m;
  m.contact = spring_dashpot_from_restitution(c.e_dry, c.contact_time(dt));
  m.step = make_contact_step(m.contact, dt, reuse ? &reuse->step : nullptr);
  m.exact = c.exact_contact;
  m.lubrication =
      make_lubrication(partner, c.viscosity, activation_of(c), c.grid_spacing, c.eps_saturation, c.eps_release);
  m.legendre = c.legendre;
  m.restitution = c.e_dry;
  return m;
}

// Wet-restitution calibration (keyword legendre A; doc/pair_lubricated_springdashpot.rst).
// For an isolated collision the film takes the same speed L = 6 pi mu R^2 P(0) / m_e on the
// way in and on the way out (P: the film integral of lubrication.h, nothing in overlap), and
// the contact returns e_d times its entry speed. Starting the contact at a speed chosen from
// the approach speed alone (EntryLoss, contact_step.h) makes the rebound e_d exp(-A / St) u0,
// u0 the impact speed, St = m_e u0 / (c_inv 6 pi mu R^2) (c_inv: the 1/eps coefficient of
// lambda, 1 wall, 1/2 pair; for a sphere on a wall and for two equal spheres
// St = (2/9) rho_p R u0 / mu_f). gap_before: the gap from which on the film has not yet
// acted on the velocity the contact sees (a step ago; now at a run start).
inline EntryLoss entry_loss(const NormalModel &m, const FilmRadius &radius, double reduced_mass, double gap_before)
{
  const Lubrication &lub = m.lubrication;
  const double speed_per_integral = lub.six_pi_mu * radius.value * radius.value / reduced_mass;
  const Lubrication::Activation al = lub.activation(radius);
  const double at_contact = lub.film_integral(0.0, al);
  EntryLoss loss;
  loss.film_loss = speed_per_integral * at_contact;
  loss.pending = speed_per_integral * (at_contact - lub.film_integral(std::max(gap_before, 0.0) * radius.inverse, al));
  loss.stokes_speed = speed_per_integral * lub.expansion.c_inv;
  loss.decay_constant = m.legendre;
  loss.restitution = m.restitution;
  return loss;
}

// With a grid spacing eps_al = 0.75 dx / R per contact; like a given activation it may not exceed
// 1 (the film would start more than a radius away). R is smallest between the smallest spheres
// (R = r for two of radius r, and at a wall), so the check takes the smallest radius present.
inline std::string validate_grid_for_radius(const Coefficients &c, double smallest_radius)
{
  if (!(c.wet() && c.grid_spacing > 0.0 && smallest_radius > 0.0)) return "";
  const double eps = Lubrication::grid_activation * c.grid_spacing / smallest_radius;
  if (eps <= 1.0) return "";
  return "grid = " + detail::number(c.grid_spacing) + " gives eps_al = 0.75 dx / R = " + detail::number(eps) +
         " for the smallest spheres (R = " + detail::number(smallest_radius) +
         ") (allowed: 0.75 dx / R <= 1, as activation <= 1)";
}

// The calibration can only remove speed: it acts at no St when the film alone, in and out,
// takes more than the law allows, P(0)/c_inv (1 + 1/e_d) >= A (St -> infinity in
// EntryLoss::start_speed). Advice for a fixed eps_al ("" when fine; with a grid spacing
// P(0) depends on each contact's R).
inline std::string calibration_warning(const Coefficients &c, Partner partner)
{
  if (!(c.legendre > 0.0 && c.wet() && c.grid_spacing <= 0.0)) return "";
  const Lubrication lub =
      make_lubrication(partner, c.viscosity, activation_of(c), 0.0, c.eps_saturation, c.eps_release);
  const double loss = lub.film_integral(0.0, 1.0) / lub.expansion.c_inv;
  if (loss * (1.0 + 1.0 / c.e_dry) < c.legendre) return "";
  return "legendre " + detail::number(c.legendre) + " cannot act with e_d = " + detail::number(c.e_dry) +
         " and activation " + (c.dem_activation() ? std::string("dem") : detail::number(c.eps_activation)) +
         ": the film alone takes more than the law allows (e_d > " +
         detail::number(std::ceil(100.0 * loss / (c.legendre - loss)) / 100.0) + " needed, or a smaller activation)";
}

struct NormalForce {
  double contact = 0.0;        // spring-dashpot part, along n
  double lubrication = 0.0;    // film part, along n
  double energy = 0.0;         // elastic energy k d^2 / 2 of the spring
  double total() const { return contact + lubrication; }
};

// The film's force over a step from its impulse there: it may stop the relative motion but
// never reverse it, |impulse| <= m_e |u_n| = limit (lubrication.h, doc/model.rst, "Lubrication
// film").
inline double film_force_of_impulse(double impulse, double limit, double inv_dt)
{
  return std::max(-limit, std::min(limit, impulse)) * inv_dt;
}

// Which force evaluation: a step, or the set-up of a run, where velocities are full-step and
// the integrator applies them in its own way: velocity Verlet half a kick before the first
// drift, fix nve/sphere/midpoint a shift dt^2/8 F/m of its first half-step drift.
enum class Evaluation { step, verlet_start, midpoint_start };

inline Evaluation evaluation_of(bool setup, bool midpoint_integrator)
{
  return !setup ? Evaluation::step : midpoint_integrator ? Evaluation::midpoint_start : Evaluation::verlet_start;
}

// radius: the film's R (lubrication.h) with its inverse. load: a steady acceleration b along n that
// presses the pair together (gravity onto a wall; b > 0 pressing), which the integrator adds on
// top: the steps where a contact starts or ends then follow the forced trajectory (loaded_contact.h;
// not at a midpoint start). 0: none, contact_step.h's forms.
__attribute__((always_inline)) inline NormalForce normal_force(const NormalModel &m, double gap,
                                                               const FilmRadius &radius, double reduced_mass,
                                                               double u_n, Evaluation when = Evaluation::step,
                                                               double load = 0.0)
{
  const bool at_start = when != Evaluation::step;
  NormalForce f;
  if (gap < 0.0) {
    const double overlap = -gap;
    const double k = reduced_mass * m.contact.stiffness_per_mass;
    if (!m.exact) f.contact = k * overlap - reduced_mass * m.contact.damping_per_mass * u_n;
    f.energy = 0.5 * k * overlap * overlap;
  }
  if (m.lubrication.active()) {
    const double dt = m.step.dt;
    const double limit = reduced_mass * std::fabs(u_n);
    if (m.exact && !at_start) {
      // The film's path integral over the last step (gap - u_n dt -> gap): summed over
      // steps it telescopes to the exact impulse of the continuous model, whatever dt.
      // It may stop the relative motion but never reverse it: |impulse| <= m_e |u_n|.
      const double impulse = m.lubrication.impulse(gap - u_n * dt, gap, radius);
      f.lubrication = film_force_of_impulse(impulse, limit, m.step.inv_dt);
    } else {
      f.lubrication = -m.lubrication.damping(gap * radius.inverse, radius.value) * u_n;
      // At a run start it may stop the motion over the half kick (dt/2 F/m) or the half drift
      // (dt^2/8 F/m against dt/2 u_n), not reverse it.
      const double cap = when == Evaluation::midpoint_start ? 4.0 * limit / dt : 2.0 * limit / dt;
      if (m.exact || when == Evaluation::midpoint_start) f.lubrication = std::max(-cap, std::min(cap, f.lubrication));
    }
  }
  if (m.exact && (load == 0.0 ? contact_possible(gap, u_n, m.step.dt) : contact_possible(gap, u_n, m.step.dt, load))) {
    const ContactStep &cs = m.step;
    const double g0 = gap - u_n * cs.dt;
    const bool loaded = load != 0.0 && when != Evaluation::midpoint_start;
    if (!at_start && !loaded && in_sustained_contact(cs, gap, g0))    // inline: a spring-dashpot
      f.contact = reduced_mass * sustained_acceleration(cs, gap, u_n);
    else if (when == Evaluation::midpoint_start) {
      // Only places the first drift (the contact and its entry loss act from the next step).
      const double drifted = gap + 0.5 * u_n * cs.dt + 0.125 * cs.dt * cs.dt * f.lubrication / reduced_mass;
      f.contact = reduced_mass * contact_acceleration_at_midpoint_start(cs, gap, u_n, drifted);
    } else {
      // Where a contact may start, it follows the motion after the film's kick of this step
      // (a film that stops the pair leaves no contact), with the calibrated entry loss.
      const double before = at_start ? gap : g0;
      EntryLoss loss;
      const EntryLoss *entry = nullptr;
      if (m.calibrated() && before >= 0.0)
        loss = entry_loss(m, radius, reduced_mass, gap >= 0.0 ? gap : g0), entry = &loss;
      if (at_start) {
        f.contact = reduced_mass * (loaded ? loaded_contact_acceleration_at_start(cs, gap, u_n, load, entry)
                                           : contact_acceleration_at_start(cs, gap, u_n, entry));
      } else {
        const double kick = g0 >= 0.0 ? f.lubrication * cs.dt / reduced_mass : 0.0;
        f.contact = reduced_mass * (loaded ? loaded_contact_acceleration(cs, gap, u_n, load, entry, kick)
                                           : contact_acceleration(cs, gap, u_n, entry, kick));
      }
    }
  }
  return f;
}

// The film force of normal_force() (exact integration, a step) for a pair that stays apart over
// the step, gap >= 0 and gap - u_n dt >= 0, where no contact can act: the film's path integral
// over the step (doc/model.rst, "Lubrication film", lubrication.h) as a force [force], without
// branches or calls, for loops over such pairs that the compiler vectorises. Requires an
// active film; GRID: whether it has a grid spacing (Lubrication::activation_inline). shear_log:
// the shear film's logarithm at the gap (Lubrication::film_integral_change_inline).
// lambda_al: lambda(eps_al) of the pair's film radius (for sustained_contact_force: one
// logarithm fewer where a loop needs both).
template <bool GRID> __attribute__((always_inline)) inline double
film_force_apart(const Lubrication &lub, double gap, const FilmRadius &radius, double reduced_mass, double u_n,
                 double dt, double inv_dt, double &shear_log, double &lambda_al)
{
  const double after = gap * radius.inverse, before = (gap - u_n * dt) * radius.inverse;
  const double impulse = lub.six_pi_mu * radius.value * radius.value *
                         lub.film_integral_change_inline<GRID>(after, before, radius, shear_log, lambda_al);
  return film_force_of_impulse(impulse, reduced_mass * std::fabs(u_n), inv_dt);
}
template <bool GRID>
__attribute__((always_inline)) inline double film_force_apart(const Lubrication &lub, double gap,
                                                              const FilmRadius &radius, double reduced_mass, double u_n,
                                                              double dt, double inv_dt, double &shear_log)
{
  double lambda_al;
  return film_force_apart<GRID>(lub, gap, radius, reduced_mass, u_n, dt, inv_dt, shear_log, lambda_al);
}
template <bool GRID> __attribute__((always_inline)) inline double film_force_apart(const Lubrication &lub, double gap,
                                                                                   const FilmRadius &radius,
                                                                                   double reduced_mass, double u_n,
                                                                                   double dt, double inv_dt)
{
  double unused;
  return film_force_apart<GRID>(lub, gap, radius, reduced_mass, u_n, dt, inv_dt, unused);
}

// normal_force() (exact integration, a step) for a pair in sustained contact: in overlap now
// and a step ago and, by the oscillator's recurrence, still a step ahead (contact_step.h).
// Its film is saturated there (doc/model.rst, "Lubrication film": held at its eps_1 value, removed
// below eps_2), so P is linear in eps and the impulse needs no logarithm of the gap. Forces
// [force], energy k d^2 / 2 [energy]. Without branches or calls, for loops the compiler
// vectorises; `sustained` says whether the pair is in that state (if not, the result means
// nothing: take normal_force()). lambda_al: lambda(eps_al) of the pair's film radius
// (Lubrication::activation, activation_inline or lambda_activation_for).
__attribute__((always_inline)) inline NormalForce sustained_contact_force(const NormalModel &m, double gap,
                                                                          const FilmRadius &radius, double reduced_mass,
                                                                          double u_n, double lambda_al, bool &sustained)
{
  const ContactStep &cs = m.step;
  const double g0 = gap - u_n * cs.dt;
  sustained = in_sustained_contact(cs, gap, g0);
  NormalForce f;
  f.energy = 0.5 * reduced_mass * m.contact.stiffness_per_mass * gap * gap;
  f.contact = reduced_mass * sustained_acceleration(cs, gap, u_n);
  const Lubrication &lub = m.lubrication;
  const double release = lub.eps_release * radius.value;
  const double impulse = lub.six_pi_mu * radius.value * (lub.lambda_saturated - lambda_al) *
                         (std::max(g0, release) - std::max(gap, release));
  f.lubrication = film_force_of_impulse(impulse, reduced_mass * std::fabs(u_n), cs.inv_dt);
  return f;
}

// The same for loops the compiler vectorises (lambda_al by log_inline); GRID: whether the film
// has a grid spacing.
template <bool GRID>
__attribute__((always_inline)) inline NormalForce sustained_contact_force(const NormalModel &m, double gap,
                                                                          const FilmRadius &radius, double reduced_mass,
                                                                          double u_n, bool &sustained)
{
  return sustained_contact_force(m, gap, radius, reduced_mass, u_n,
                                 m.lubrication.activation_inline<GRID>(radius).lambda, sustained);
}

// Whether a contact in overlap now (g1) and a step ago (g0) leaves the overlap within the coming
// step: contact_acceleration's exit from the oscillator (contact_step.h, exit_gap).
inline bool leaves_overlap(const ContactStep &cs, double g1, double g0)
{
  return (g1 < 0.0) & (g0 < 0.0) & (recurrence_gap(cs, g1, g0) >= 0.0) & (cs.S > 1e-12);
}

// normal_force() (exact integration, a step) for a contact that leaves_overlap(): the exit and
// free flight after it, and the saturated film of the step in overlap (as sustained_contact_force).
// Without branches or calls (exit_gap<true>), for loops the compiler vectorises over such
// contacts alone (every lane pays the exit's arithmetic); equal to normal_force() within
// rounding. GRID: whether the film has a grid spacing.
template <bool GRID> __attribute__((always_inline)) inline NormalForce
overlap_exit_force(const NormalModel &m, double gap, const FilmRadius &radius, double reduced_mass, double u_n)
{
  const ContactStep &cs = m.step;
  bool sustained;
  NormalForce f = sustained_contact_force<GRID>(m, gap, radius, reduced_mass, u_n, sustained);
  const double g0 = gap - u_n * cs.dt;
  f.contact = reduced_mass * ((exit_gap<true>(cs, gap, g0) - 2.0 * gap + g0) / (cs.dt * cs.dt));
  return f;
}

// normal_force() (exact integration, a step) of a model without an entry loss (!m.calibrated())
// for a pair apart now or a step ago and within a step of contact: a contact that starts within
// the coming step or started or ended within the last one (event_acceleration_inline), with the
// film's path integral over the step (film_force_apart's, valid along any path) and its kick.
// Without branches or calls, for loops the compiler vectorises over such pairs; resolved as
// event_acceleration_inline (where false, take normal_force()). reduced_mass > 0; WET: whether
// the film is active, GRID: whether it has a grid spacing.
// shear_log: as film_force_apart's (WET only).
template <bool WET, bool GRID>
__attribute__((always_inline)) inline NormalForce contact_event_force(const NormalModel &m, double gap,
                                                                      const FilmRadius &radius, double reduced_mass,
                                                                      double u_n, bool &resolved, double &shear_log)
{
  const ContactStep &cs = m.step;
  NormalForce f;
  const double k = reduced_mass * m.contact.stiffness_per_mass;
  f.energy = gap < 0.0 ? 0.5 * k * gap * gap : 0.0;
  shear_log = 0.0;
  f.lubrication =
      WET ? film_force_apart<GRID>(m.lubrication, gap, radius, reduced_mass, u_n, cs.dt, cs.inv_dt, shear_log) : 0.0;
  const double kick = gap - u_n * cs.dt >= 0.0 ? f.lubrication * cs.dt / reduced_mass : 0.0;
  f.contact = reduced_mass * event_acceleration_inline(cs, gap, u_n, kick, resolved);
  return f;
}
template <bool WET, bool GRID>
__attribute__((always_inline)) inline NormalForce contact_event_force(const NormalModel &m, double gap,
                                                                      const FilmRadius &radius, double reduced_mass,
                                                                      double u_n, bool &resolved)
{
  double unused;
  return contact_event_force<WET, GRID>(m, gap, radius, reduced_mass, u_n, resolved, unused);
}

inline NormalForce normal_force(const NormalModel &m, double gap, double radius, double reduced_mass, double u_n,
                                Evaluation when = Evaluation::step, double load = 0.0)
{
  return normal_force(m, gap, FilmRadius(radius), reduced_mass, u_n, when, load);
}

inline double reduced_mass(double m_i, double m_j)
{
  return m_i * m_j / (m_i + m_j);
}

// The same from inverse masses, where 0 stands for a partner no contact moves (m_e = m_i
// against it); 0 where neither moves: such a pair exerts no force (the branch-free forms
// above give 0; normal_force() needs m_e > 0, engines skip these pairs).
__attribute__((always_inline)) inline double reduced_mass_of_inverses(double inverse_i, double inverse_j)
{
  const double sum = inverse_i + inverse_j;
  return sum > 0.0 ? 1.0 / sum : 0.0;
}

}    // namespace lubricated

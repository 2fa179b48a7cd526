// One contact, whole: the normal interaction (spring-dashpot and film, normal_model.h) and the
// tangential ones (friction over a history slot, the shear film, rolling resistance;
// tangential.h) of a particle i and its partner, a particle j or a wall, as forces on i and
// torques on both (doc/model.rst). The pair style and fix wall/lubrication evaluate every
// contact with contact_forces(); LIGGGHTS keeps its own tangential and rolling models (its
// users' syntax) and calls the normal part, normal_force().
//
// A wall is a partner that neither moves with the contact nor turns: radius_j = 0, omega_j = 0,
// inertia_j = 0, reduced radius R_i. Conventions of n, gap, u_n and m_e: normal_model.h.
#pragma once

#include "contact_network.h"
#include "film_budget.h"
#include "normal_model.h"
#include "tangential.h"

namespace lubricated {

// Everything a type pair (or a wall) derives from its coefficients and the time step.
struct ContactModel {
  NormalModel normal;
  TangentialModel tangential;
};

// reuse: the model for the last time step, where there is one (contact_step.h: its tables).
inline ContactModel make_contact_model(const Coefficients &c, Partner partner, double dt,
                                       const ContactModel *reuse = nullptr)
{
  ContactModel m;
  m.normal = make_normal_model(c, partner, dt, reuse ? &reuse->normal : nullptr);
  m.tangential = make_tangential_model(c, m.normal.step.contact_time, dt);
  return m;
}

// The kind of this evaluation and the time its films act on the velocities (film_kick_time), as
// every engine works them out: setup, a run's set-up evaluation (the engine's set-up flag);
// continued, a set-up that continues the last run's step, evaluated as that step was (the step
// velocities the engine kept); midpoint_integrator, fix nve/sphere/midpoint integrates.
struct EvaluationKind {
  Evaluation when;
  double kick_time;
};
inline EvaluationKind evaluation_kind(double dt, bool setup, bool continued, bool midpoint_integrator)
{
  const Evaluation when = continued ? Evaluation::step : evaluation_of(setup, midpoint_integrator);
  return {when, film_kick_time(dt, when != Evaluation::step, when == Evaluation::midpoint_start)};
}

// The contact as the engine sees it this step.
struct ContactPoint {
  // Normal (normal_model.h): gap, the normal velocity over the last step, m_e, the film's R.
  double gap = 0.0, u_n = 0.0, reduced_mass = 0.0;
  FilmRadius film;
  // A steady acceleration along n pressing the pair together, that the integrator adds (gravity
  // onto a wall; normal_force's load): 0 for none.
  double load = 0.0;
  // Tangential (tangential.h), read only where the model has tangential parts: the unit normal,
  // v_i - v_j and the spins as the engine holds them, the lever arms, R_e = R_i R_j / (R_i + R_j)
  // and the masses of the spheres that turn with the contact (solid spheres, for the rolling
  // inertia; 0: this side does not turn with it: a wall, an immovable atom; read only in overlap
  // with rolling resistance and, between spheres, by the rolling film, so an engine may leave
  // them unset elsewhere).
  Vec3 n, dv, omega_i, omega_j;
  double radius_i = 0.0, radius_j = 0.0, reduced_radius = 0.0;
  double mass_i = 0.0, mass_j = 0.0;
  // m_t where it is not tangential_mass_ratio m_e (spheres carrying an added mass:
  // tangential_mass_of_sides); 0: tangential_mass_ratio m_e.
  double tangential_mass = 0.0;
};

// The contact's friction history (tangential.h), where the engine keeps it: the elongation
// delta (3 values; nullptr where none is kept: no friction force) and whether the contact
// touched at the last step. The elongation is updated in place, the flag here (the engine
// stores it back: a store through a pointer into its char flags may alias anything and costs
// reloads in the pair loop); a contact out of overlap forgets its elongation.
struct HistorySlot {
  double *elongation = nullptr;
  bool touched = false;
  // false in a run's set-up evaluation (and `run 0`): no time passes there, so the stored
  // elongation acts as it is and nothing is written (as LAMMPS's granular styles, which do not
  // update history in set-up); any number of set-ups then leaves the contact as it was.
  bool advance = true;
  // Whether the spring has slid (Coulomb) at any step of the contact: only one that stuck
  // throughout is released after its half oscillation (tangential_release_force).
  bool slid = false;
};

// The touched flag as engines store it (one number per contact: 0 apart, 1 stuck throughout, 2
// slid at some step), and back.
inline double history_flag(const HistorySlot &slot)
{
  return slot.touched ? (slot.slid ? 2.0 : 1.0) : 0.0;
}
inline HistorySlot history_slot(double *elongation, double flag, bool advance)
{
  return HistorySlot{elongation, flag != 0.0, advance, flag == 2.0};
}

struct ContactForces {
  NormalForce normal;    // along n, and the spring's energy
  // Force on i at the contact point (on j the opposite) and the torques on i and j: friction,
  // shear film and rolling; with shear_apart, the shear film is left out of them and given in
  // shear and shear_torque_i alone (on j: radius_j / radius_i of it).
  Vec3 tangential, torque_i, torque_j;
  Vec3 shear, shear_torque_i;
  Vec3 slip;                       // s (tangential.h)
  double tangential_mass = 0.0;    // m_t = 2/7 m_e
  // The rolling film's torque on i (on j the opposite; in torque_i and torque_j too) and its
  // share of the film budget per unit kick time (roll_film_torque).
  Vec3 roll_film;
  double roll_share_rate = 0.0;

  // The tangential films' share of the film budget for this kick time (film_budget.h): the shear
  // film's and the rolling film's, summed (both act on the spins).
  double shear_share(double kick_time) const
  {
    return shear_film_share(dot(shear, shear), dot(slip, slip), tangential_mass, kick_time) +
           roll_share_rate * kick_time;
  }
};

namespace detail {

// Moment of inertia of the relative rolling of the contact's spheres (tangential.h).
inline double rolling_inertia(const ContactPoint &p)
{
  return lubricated::rolling_inertia(p.mass_i, p.radius_i, p.mass_j, p.radius_j);
}

// The rolling film of a pair of spheres (tangential.h, roll_film_torque) and its share rate, out
// of line: the contact of a scene without the film carries none of its arithmetic.
__attribute__((noinline)) inline Vec3 pair_roll_film(const ContactModel &m, const ContactPoint &p, double &share_rate)
{
  const Lubrication &film = m.normal.lubrication;
  const TangentialModel &tm = m.tangential;
  const double gamma = roll_film_coefficient(tm.roll_mu, p.gap / p.film.value, film.activation_for(p.film.value),
                                             film.eps_saturation, film.eps_release, p.reduced_radius);
  return roll_film_torque(tm, minus(p.omega_i, p.omega_j), p.n, gamma, rolling_inertia(p), share_rate);
}
// The normal force that bounds a release (tangential_release_force) by Coulomb: what is left of
// the contact's now and the spring-dashpot's over the leapfrog kick the release completes (the
// last one in overlap stands for the step from half a step before it: the overlap there, half a
// step's motion more than at the last evaluation, and the normal velocity of the last step).
inline double release_load(const ContactModel &m, const ContactPoint &p, const NormalForce &normal)
{
  const SpringDashpot &law = m.normal.contact;
  const double overlap = std::max(0.0, 1.5 * p.u_n * m.tangential.dt - p.gap);
  return std::fabs(normal.contact) +
         p.reduced_mass * (law.stiffness_per_mass * overlap + law.damping_per_mass * std::fabs(p.u_n));
}
}    // namespace detail

// The whole contact. TANGENTIAL false: the normal interaction alone (no tangential field of p
// read, no history touched), what a scene without friction, rolling or shear film pays.
// PARTNER: a wall's side j terms are left out at compile time (not added as zeros).
template <bool TANGENTIAL, Partner PARTNER = Partner::particle> __attribute__((always_inline)) inline ContactForces
contact_forces(const ContactModel &m, const ContactPoint &p, HistorySlot &history, Evaluation when = Evaluation::step,
               bool shear_apart = false)
{
  const NormalForce normal = normal_force(m.normal, p.gap, p.film, p.reduced_mass, p.u_n, when, p.load);
  if (!TANGENTIAL) {
    ContactForces out;
    out.normal = normal;
    return out;
  }
  // The tangential parts in locals, the result assembled once (a default-built result that the
  // branches overwrite stays in memory and costs a zero fill per contact).
  const TangentialModel &tm = m.tangential;
  constexpr bool wall = PARTNER == Partner::wall;
  // Slip of the surfaces (tangential.h): (v_i - v_j) - (R_i omega_i + R_j omega_j) x n.
  const Vec3 lever = wall ? scaled(p.omega_i, p.radius_i) : contact_lever(p.omega_i, p.radius_i, p.omega_j, p.radius_j);
  const Vec3 s = surface_slip(p.dv, lever, p.n);
  const double m_t = p.tangential_mass > 0.0 ? p.tangential_mass : tangential_mass_ratio * p.reduced_mass;

  Vec3 f;
  if (history.elongation) {
    double *h = history.elongation;
    if (tm.contact_active() && tangential_in_contact(p.gap)) {
      // In a set-up the stored elongation acts, not lengthened, and nothing is written.
      const double fraction = !history.advance  ? 0.0
                              : history.touched ? 1.0
                                                : first_contact_fraction(p.gap, p.u_n, tm.dt);
      Vec3 delta{h[0], h[1], h[2]};
      bool slid;
      f = tangential_contact_force(tm, delta, p.n, s, m_t, normal.contact, fraction, &slid);
      if (history.advance) {
        h[0] = delta.x, h[1] = delta.y, h[2] = delta.z;
        history.slid = history.slid || slid;
        history.touched = true;
      }
    } else if (history.touched && history.advance) {
      // The overlap ended within the last step: the spring is released, then forgotten.
      if (tm.contact_active() && !history.slid && overlap_just_ended(p.gap, p.u_n, tm.dt))
        f = tangential_release_force(tm, Vec3{h[0], h[1], h[2]}, p.n, s, m_t, detail::release_load(m, p, normal));
      history.touched = history.slid = false;
      h[0] = h[1] = h[2] = 0.0;
    }
  }
  Vec3 shear, shear_torque_i;
  if (tm.film_active()) {
    const Lubrication &film = m.normal.lubrication;
    shear = shear_film_force(tm, s, p.gap / p.film.value, film.activation_for(p.film.value), film.eps_saturation,
                             film.eps_release, p.reduced_radius, m_t);
    if (shear_apart)
      shear_torque_i = scaled(cross(p.n, shear), -p.radius_i);
    else
      f = plus(f, shear);
  }
  Vec3 roll;
  if (tm.rolling_active() && p.gap < 0.0)
    roll = rolling_torque(tm, p.n, wall ? p.omega_i : minus(p.omega_i, p.omega_j), p.reduced_radius,
                          wall ? sphere_inertia(p.mass_i, p.radius_i) : detail::rolling_inertia(p), normal.contact);
  // The film's torque added to the rolling resistance only where it acts (the other way round,
  // every frictional contact of a scene without the film cost more: bench/contact_instructions.py).
  Vec3 roll_film;
  double roll_share_rate = 0.0;
  if (!wall && tm.roll_film_active()) {
    roll_film = detail::pair_roll_film(m, p, roll_share_rate);
    roll = plus(roll, roll_film);
  }
  const Vec3 nxf = cross(p.n, f);
  const Vec3 torque_i = plus(scaled(nxf, -p.radius_i), roll);
  const Vec3 torque_j = wall ? Vec3{} : minus(scaled(nxf, -p.radius_j), roll);
  return ContactForces{normal, f, torque_i, torque_j, shear, shear_torque_i, s, m_t, roll_film, roll_share_rate};
}

// Loads of a sustained contact of this model for the contact-network check (contact_network.h):
// kappa + 2 gamma of the normal per-step constants (exact or sampled), and for the upper bound
// the larger of it and the tangential spring's (friction). The pair style's type pairs and the
// walls of the wall fixes alike.
inline void network_loads(const ContactModel &model, double dt, double &load, double &bound)
{
  const NormalModel &m = model.normal;
  load = m.exact ? contact_load(m.step.stiffness_step, m.step.damping_step, dt)
                 : contact_load(m.contact.stiffness_per_mass, m.contact.damping_per_mass, dt);
  const TangentialModel &tm = model.tangential;
  bound = tm.contact_active() ? std::max(load, contact_load(tm.stiffness_step, tm.damping_step, dt)) : load;
}

}    // namespace lubricated

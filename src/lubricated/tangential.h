// Tangential interaction of one contact: spring-dashpot with a Coulomb limit and history
// (Costa et al., Phys. Rev. E 92, 053012, 2015), optional rolling resistance, and the shear
// film of the lubrication layer. Conventions as in normal_model.h (n from the partner to
// particle i); in addition:
//
//   s     slip velocity of the surfaces along the line of centres, tangential part:
//         s = (v_i - v_j) - (R_i omega_i + R_j omega_j) x n,  s . n removed
//         (wall: v_i - R_i omega_i x n); velocities of the last step, like u_n;
//   delta tangential spring elongation (history), kept in the tangent plane;
//   m_t   tangential mass 2/7 m_e: with solid spheres (I = 2/5 m R^2) a force F applied at
//         the contact points changes s by F dt / m_t, both translation and rotation counted
//         (1/m_t = 1/m_i + 1/m_j + R_i^2/I_i + R_j^2/I_j = 7 / (2 m_e));
//   force on i = F_t at the contact point, on j = -F_t; torque on i = -R_i n x F_t,
//   on j = -R_j n x F_t.
//
// Stiffness and damping follow from the tangential restitution e_t and the normal contact
// duration t_c, as the normal ones from e_d (Costa et al. eq. 9):
//   k_t = m_t (pi^2 + ln^2 e_t) / t_c^2,  eta_t = -2 m_t ln(e_t) / t_c,
// so a sticking contact completes half a damped oscillation in t_c and reverses s with
// factor e_t. As in the normal direction (contact_step.h), the force over a step is the one
// that makes the leapfrog step land on the analytic oscillator,
//   F = m_t (delta_next - 2 delta + delta_prev) / dt^2,  delta_next = 2 E C delta - E^2 delta_prev,
// i.e. a spring-dashpot with per-step constants k' = m_t (1 + E^2 - 2 E C) / dt^2 and
// c' = m_t (1 - E^2) / dt, exact for any N_c in sticking and finite for e_t = 0 (E = 0).
// Coulomb: |F_t| <= mu_c |F_n| with F_n the normal contact force of the step; beyond it the
// contact slides with |F_t| = mu_c |F_n| and delta is reset to the elongation that force
// implies, delta = -(F_t + c' s) / k' (the usual history truncation).
#pragma once

#include "coefficients.h"
#include "contact_step.h"
#include "inline_exp.h"
#include "inline_log.h"

#include <algorithm>
#include <cmath>

namespace lubricated {

constexpr double tangential_mass_ratio = 2.0 / 7.0;    // m_t / m_e for solid spheres
constexpr double solid_sphere_inertia_ratio = 0.4;     // I / (m R^2)

inline double sphere_inertia(double mass, double radius)
{
  return solid_sphere_inertia_ratio * mass * radius * radius;
}

// Moment of inertia of the relative rolling of two solid spheres of masses m_i, m_j (0: that
// side does not turn: a wall, an immovable atom), 1/I_e = 1/I_i + 1/I_j over the sides that turn.
inline double rolling_inertia(double mass_i, double radius_i, double mass_j, double radius_j)
{
  const double inertia_i = sphere_inertia(mass_i, radius_i), inertia_j = sphere_inertia(mass_j, radius_j);
  if (inertia_j == 0.0) return inertia_i;
  if (inertia_i == 0.0) return inertia_j;
  return inertia_i * inertia_j / (inertia_i + inertia_j);
}

// m_t where a sphere's translation carries more than its own mass (the fluid's added mass,
// which a turning sphere does not carry): 1/m_t = sum over the sides that move of
// 1/m_c + R^2/I = 1/m_c + 1/(0.4 m), m_c its contact mass (1/m_c: inverse_c, 0 for a side that
// does not move: a wall, an immovable atom) and m its own mass. Without added mass (m_c = m)
// this is tangential_mass_ratio m_e.
inline double tangential_mass_of_sides(double inverse_i, double mass_i, double inverse_j, double mass_j)
{
  double inverse = 0.0;
  if (inverse_i > 0.0) inverse += inverse_i + 1.0 / (solid_sphere_inertia_ratio * mass_i);
  if (inverse_j > 0.0) inverse += inverse_j + 1.0 / (solid_sphere_inertia_ratio * mass_j);
  return 1.0 / inverse;
}

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};
__attribute__((always_inline)) inline double dot(const Vec3 &a, const Vec3 &b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
__attribute__((always_inline)) inline Vec3 cross(const Vec3 &a, const Vec3 &b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
__attribute__((always_inline)) inline Vec3 scaled(const Vec3 &a, double s)
{
  return {a.x * s, a.y * s, a.z * s};
}
__attribute__((always_inline)) inline Vec3 minus(const Vec3 &a, const Vec3 &b)
{
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
__attribute__((always_inline)) inline Vec3 plus(const Vec3 &a, const Vec3 &b)
{
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
__attribute__((always_inline)) inline Vec3 tangential_part(const Vec3 &a, const Vec3 &n)
{
  return minus(a, scaled(n, dot(a, n)));
}

struct TangentialModel {
  double friction = 0.0;          // mu_c; 0: no tangential contact force, no history
  double rolling = 0.0;           // mu_r; 0: no rolling resistance
  double stiffness_step = 0.0;    // k' / m_t  [1/time^2]
  double damping_step = 0.0;      // c' / m_t  [1/time]
  // The oscillator itself (contact_step.h, OscillatorStep), for the release of a spring
  // (tangential_release_force): a, omega, E = exp(-a dt), C = cos(omega dt), S = sin(omega dt).
  double decay_rate = 0.0, omega = 0.0, E = 0.0, C = 1.0, S = 0.0;
  double dt = 0.0;
  // Shear film: F = -2 pi mu_f R_e ln(eps_al / max(eps, eps_1)) s for eps_2 < eps < eps_al.
  double two_pi_mu = 0.0;    // 2 pi mu_f = 6 pi mu_f / 3; 0: no shear film
  double roll_mu = 0.0;      // mu_f of the rolling film (roll_film_coefficient); 0: none
  bool contact_active() const { return friction > 0.0; }
  bool rolling_active() const { return rolling > 0.0; }
  bool film_active() const { return two_pi_mu > 0.0; }
  bool roll_film_active() const { return roll_mu > 0.0; }
  bool active() const { return contact_active() || rolling_active() || film_active() || roll_film_active(); }
};

// t_c: the normal contact's duration as integrated (ContactStep::contact_time), so that both
// directions share the floor of min_steps_per_contact steps.
inline TangentialModel make_tangential_model(const Coefficients &c, double t_c, double dt)
{
  TangentialModel m;
  m.friction = c.friction;
  m.rolling = c.rolling_friction;
  m.dt = dt;
  const OscillatorStep o = oscillator_step(c.tangential_restitution(), t_c, dt);
  m.stiffness_step = o.stiffness_step;
  m.damping_step = o.damping_step;
  m.decay_rate = o.decay_rate, m.omega = o.omega, m.E = o.E, m.C = o.C, m.S = o.S;
  if (c.wet() && c.shear_film()) m.two_pi_mu = 2.0 * pi * c.viscosity;
  if (c.wet() && c.roll_film()) m.roll_mu = c.viscosity;
  return m;
}

// Whether the tangential contact acts: in overlap (a contact that sticks throughout is released
// after its half oscillation, tangential_release_force, however many evaluations fall in the
// overlap).
inline bool tangential_in_contact(double gap)
{
  return gap < 0.0;
}

// Part of the last step spent in overlap by a contact that is new now (free flight before).
inline double first_contact_fraction(double gap, double u_n, double dt)
{
  if (u_n >= 0.0) return 1.0;
  return std::min(1.0, std::max(0.0, gap / (u_n * dt)));
}

// Whether a contact's overlap ended within the last step (apart now, in overlap a step ago): the
// evaluation that releases its spring (tangential_release_force).
__attribute__((always_inline)) inline bool overlap_just_ended(double gap, double u_n, double dt)
{
  return (gap >= 0.0) & (gap - u_n * dt < 0.0);
}

// The slip of the surfaces, s = (v_i - v_j) - lever x n with its normal part removed; lever =
// R_i omega_i + R_j omega_j (contact_lever; a wall: R_i omega_i).
__attribute__((always_inline)) inline Vec3 surface_slip(const Vec3 &dv, const Vec3 &lever, const Vec3 &n)
{
  return tangential_part(minus(dv, cross(lever, n)), n);
}
// (Each radius multiplies first: in the vectorised loops GCC then fuses the same products into
// multiply-adds as the loops' own code always did, which keeps their results.)
__attribute__((always_inline)) inline Vec3 contact_lever(const Vec3 &omega_i, double radius_i, const Vec3 &omega_j,
                                                         double radius_j)
{
  return {radius_i * omega_i.x + radius_j * omega_j.x, radius_i * omega_i.y + radius_j * omega_j.y,
          radius_i * omega_i.z + radius_j * omega_j.z};
}

// The elongation kept in the tangent plane with its length (the pair may have rotated): its
// normal part r removed and the rest rescaled by sqrt(1 / (1 - x)), x = r^2 / |delta|^2; for the
// small x of one step's rotation the series 1 + x/2 + 3x^2/8 (error 5x^3/16 < 1e-13) saves two
// square roots per contact and step. Unscaled where nothing tangential is left (x >= 1).
// Selects, not branches: the vectorised friction loop inlines it too.
__attribute__((always_inline)) inline Vec3 elongation_in_tangent_plane(const Vec3 &delta, const Vec3 &n)
{
  const double normal_part = dot(delta, n);
  const double length_sq = dot(delta, delta);
  const double x = normal_part != 0.0 ? normal_part * normal_part / length_sq : 0.0;
  const double stretch = x < 1e-4 ? 1.0 + x * (0.5 + 0.375 * x) : x < 1.0 ? std::sqrt(1.0 / (1.0 - x)) : 1.0;
  return scaled(minus(delta, scaled(n, normal_part)), stretch);
}

// Tangential contact force on i for a contact in overlap. delta (history, in: elongation at
// the end of the last step; out: now) is rotated into the current tangent plane before use.
// first_fraction: for a contact that opened during the last step, the part of that step spent
// in overlap (the elongation starts from zero there); 1 for a sustained contact. Coulomb: beyond
// mu |F_n| the contact slides and the spring holds what the capped force implies. The scalar
// contact (contact_forces) and the vectorised friction loop both take this one form.
__attribute__((always_inline)) inline Vec3 tangential_contact_force(const TangentialModel &m, Vec3 &delta,
                                                                    const Vec3 &n, const Vec3 &s,
                                                                    double tangential_mass, double normal_force,
                                                                    double first_fraction = 1.0, bool *slid = nullptr)
{
  delta = plus(elongation_in_tangent_plane(delta, n), scaled(s, first_fraction * m.dt));
  const Vec3 f = scaled(plus(scaled(delta, m.stiffness_step), scaled(s, m.damping_step)), -tangential_mass);
  const double limit = m.friction * std::fabs(normal_force);
  const double f2 = dot(f, f);
  const bool slides = f2 > limit * limit;
  const Vec3 capped = scaled(f, slides ? limit / std::sqrt(f2) : 1.0);
  const double inverse_mass = 1.0 / tangential_mass, inverse_stiffness = -1.0 / m.stiffness_step;
  const Vec3 held = scaled(plus(scaled(capped, inverse_mass), scaled(s, m.damping_step)), inverse_stiffness);
  delta = {slides ? held.x : delta.x, slides ? held.y : delta.y, slides ? held.z : delta.z};
  if (slid) *slid = slides;
  return capped;
}

// The first evaluation after the overlap of a contact that stuck throughout has ended: the force
// on i that completes the spring's half oscillation. With the elongation started at the entry as
// above, the leapfrog's elongations are the samples, one per step, of an oscillator x(t) of the
// spring's a and omega through delta = (f - 1) s0 dt a step before the entry's step and f s0 dt
// after it; half a period later, x(t + t_c) = -e_t x(t), so the slip over the step that starts
// N_c steps after the one before the entry, where x comes back through zero, is -e_t s0. The
// leapfrog reaches it after exactly N_c evaluations in overlap; a contact that lasts a little
// more or less than N_c steps (a film in the overlap, the round-off of an entry on a step
// boundary, N_c not a whole number) has one evaluation more or fewer. This force sets the slip to
// x's over the whole step in which x comes back through zero, x from the last elongation
// delta_m (history, rotated into the current tangent plane) and the slip s of the step since,
// x(t) = exp(-a t) (A cos omega t + B sin omega t), A = delta_m, x(dt) = delta_m + s dt: nothing
// where that is the last step, one more step of the oscillator or one less where it is the next
// or the one before. A sticking impact thus reverses the slip with exactly e_t whatever its phase
// (N_c a whole number; otherwise to the step's part of the oscillation). Coulomb: at most mu F_n,
// F_n the normal load of the step it completes (contact.h, detail::release_load). Energy: the
// slip is the oscillator's, which never holds more than the contact did.
inline Vec3 tangential_release_force(const TangentialModel &m, const Vec3 &elongation, const Vec3 &n, const Vec3 &s,
                                     double tangential_mass, double normal_force)
{
  const double length_sq = dot(elongation, elongation);
  if (!(m.E > 0.0 && m.S > 0.0 && length_sq > 0.0)) return {};    // e_t = 0: the slip is already 0
  const double dt = m.dt, w = m.omega;
  const Vec3 A = elongation_in_tangent_plane(elongation, n);
  const Vec3 B = scaled(minus(scaled(plus(A, scaled(s, dt)), 1.0 / m.E), scaled(A, m.C)), 1.0 / m.S);
  // x along A back through zero: omega t = atan2(B.A, |A|^2) + pi / 2 (mod pi), in (0, pi) or a
  // half period before; the step it falls in, counted from the last evaluation in overlap.
  const double rest = (std::atan2(dot(B, A), dot(A, A)) + 0.5 * pi) / w;
  const double nearest = (rest - pi / w > -dt ? rest - pi / w : rest) / dt;
  // On a step boundary (to rounding, or to what moves a pair's line of centres: an entry on one,
  // f = 1 or f -> 0), the step nearer the last.
  const double boundary = std::round(nearest);
  const double step = std::fabs(nearest - boundary) > 2e-3 ? std::floor(nearest)
                      : boundary > 0.0                     ? boundary - 1.0
                                                           : boundary;
  if (step == 0.0 || std::fabs(step) > 1.0) return {};
  auto x = [&](double t) {
    return scaled(plus(scaled(A, std::cos(w * t)), scaled(B, std::sin(w * t))), std::exp(-m.decay_rate * t));
  };
  const Vec3 slip = scaled(minus(x((step + 1.0) * dt), x(step * dt)), 1.0 / dt);
  const Vec3 f = scaled(minus(slip, s), tangential_mass / dt);
  const double limit = m.friction * std::fabs(normal_force), f2 = dot(f, f);
  return f2 > limit * limit ? scaled(f, limit / std::sqrt(f2)) : f;
}

// Rolling resistance (constant-torque model, Ai et al., Powder Technol. 206, 269, 2011,
// model A): torque on i of size mu_r R_e |F_n| against the relative rolling rate
// w = tangential part of omega_i - omega_j, capped so that one step cannot reverse w
// (moment of inertia of the relative rolling: 1/I_e = 1/I_i + 1/I_j). On j: the opposite.
inline Vec3 rolling_torque(const TangentialModel &m, const Vec3 &n, const Vec3 &omega_rel, double reduced_radius,
                           double reduced_inertia, double normal_force)
{
  const Vec3 w = tangential_part(omega_rel, n);
  const double speed = std::sqrt(dot(w, w));
  if (speed == 0.0) return {};
  const double torque = std::min(m.rolling * reduced_radius * std::fabs(normal_force), reduced_inertia * speed / m.dt);
  return scaled(w, -torque / speed);
}

// Shear film (the gap's Couette flow to leading order): force on i for the slip velocity s at
// normalised gap eps. The coefficient 2 pi mu R_e ln(1/eps) is the leading term of the
// tangential resistance of a sphere translating along a wall, the slip mode of Goldman, Cox &
// Brenner (Chem. Eng. Sci. 22, 637, 1967) and O'Neill & Stewartson (J. Fluid Mech. 27, 705,
// 1967): 6 pi mu a (8/15 U - 2/15 a Omega) ln(1/eps) has slip-mode coefficient 6 pi mu a / 3;
// for two spheres R_e = R_1 R_2 / (R_1 + R_2) gives Jeffrey & Onishi's (1/6) 6 pi mu a for
// equal spheres. Activated at eps_al (continuous there), saturated below eps_1, cut below eps_2,
// like the normal film. The damper is integrated exactly over the step (factor 1 - exp(-x)),
// so it never reverses s, however viscous the fluid or long the step.
//
// shear_film_damping: the damping d [mass/time] (force -d s) over a step from its logarithm log_ratio =
// ln(eps_al / max(eps, eps_saturation)): rate x = in_film 2 pi mu R_e log_ratio dt / m_t and d =
// m_t (1 - exp(-x)) / dt. in_film: 1 inside the film, 0 outside. BRANCH_FREE: 1 - exp(-x) by
// one_minus_exp_neg_inline (for loops the compiler vectorises; the same to a few units in the
// last place), else to rounding.
template <bool BRANCH_FREE>
__attribute__((always_inline)) inline double shear_film_damping(const TangentialModel &m, double in_film,
                                                                double reduced_radius, double log_ratio,
                                                                double tangential_mass)
{
  const double rate = in_film * m.two_pi_mu * reduced_radius * log_ratio * m.dt / tangential_mass;
  const double factor = BRANCH_FREE   ? one_minus_exp_neg_inline(rate)
                        : rate < 1e-6 ? rate * (1.0 - 0.5 * rate)
                                      : -std::expm1(-rate);
  return factor * tangential_mass / m.dt;
}

// Whether a normalised gap eps lies in the shear film: between eps_release and eps_al.
__attribute__((always_inline)) inline bool in_shear_film(double eps, double eps_al, double eps_release)
{
  return (eps < eps_al) & (eps > eps_release);
}

// Rolling film (doc/model.rst, Shear film: the rolling mode): Jeffrey & Onishi's (J. Fluid Mech.
// 139, 261, 1984) leading logarithms of Y^A, Y^B and Y^C of two spheres of any size ratio are a
// dissipation alpha |s|^2 + 2 beta s.(w x n) + gamma |w|^2 in the slip s and the relative spin
// w = P_t (omega_i - omega_j); the shear film above is the alpha term (exact for equal spheres)
// and the rolling term a torque -gamma w on i, +gamma w on j with gamma = (24/5) pi mu_f R_e^3
// ln(1/eps). Coefficient [torque / angular velocity] at normalised gap eps, activated, saturated
// and released like the shear film (`rollfilm yes`; pairs of spheres only: at a wall the shear
// film is not the alpha of this split).
//
// roll_film_gamma: gamma for the logarithm log_ratio = ln(eps_al / max(eps, eps_1)) (also for bounds).
inline double roll_film_gamma(double viscosity, double reduced_radius, double log_ratio)
{
  return 24.0 / 5.0 * pi * viscosity * reduced_radius * reduced_radius * reduced_radius * log_ratio;
}
inline double roll_film_coefficient(double viscosity, double eps, double eps_al, double eps_saturation,
                                    double eps_release, double reduced_radius)
{
  if (!in_shear_film(eps, eps_al, eps_release)) return 0.0;
  return roll_film_gamma(viscosity, reduced_radius, std::log(eps_al / std::max(eps, eps_saturation)));
}

// The rolling film's torque on i over a step (on j the opposite) for the relative spin
// omega_rel = omega_i - omega_j: the damper -gamma P_t omega_rel integrated exactly over the step
// with the rolling inertia I_e (1/I_e = 1/I_i + 1/I_j over the sides that turn), -(1 -
// exp(-x)) I_e P_t omega_rel / dt with x = gamma dt / I_e: it never reverses the relative spin.
// share_rate: (1 - exp(-x)) / dt, the film budget's share per unit kick time.
inline Vec3 roll_film_torque(const TangentialModel &m, const Vec3 &omega_rel, const Vec3 &n, double gamma,
                             double inertia, double &share_rate)
{
  share_rate = 0.0;
  if (!(gamma > 0.0 && inertia > 0.0)) return {};
  const double factor = -std::expm1(-gamma * m.dt / inertia);
  share_rate = factor / m.dt;
  return scaled(tangential_part(omega_rel, n), -factor * inertia / m.dt);
}

inline Vec3 shear_film_force(const TangentialModel &m, const Vec3 &s, double eps, double eps_al, double eps_saturation,
                             double eps_release, double reduced_radius, double tangential_mass)
{
  if (!in_shear_film(eps, eps_al, eps_release)) return {};
  const double log_ratio = std::log(eps_al / std::max(eps, eps_saturation));
  return scaled(s, -shear_film_damping<false>(m, 1.0, reduced_radius, log_ratio, tangential_mass));
}

// shear_film_force() for a pair apart by more than eps_release R, without branches or calls, for
// loops the compiler vectorises: the damping d of the force -d s [mass/time] (shear_film_damping's
// branch-free form); 0 where the tangential mass is 0 (two immovable atoms). log_ratio:
// ln(eps_al / max(eps, eps_saturation)) where the caller has it (the normal film's logarithms give
// it, Lubrication::film_integral_change_inline).
__attribute__((always_inline)) inline double shear_film_damping_of_log(const TangentialModel &m, double eps,
                                                                       double eps_al, double eps_release,
                                                                       double log_ratio, double reduced_radius,
                                                                       double tangential_mass)
{
  // Every operation done for every pair, the result selected (no branch for the compiler to
  // keep): outside the film the rate is 0; a zero mass is replaced by 1 and its damping
  // multiplied by 0.
  const double in_film = in_shear_film(eps, eps_al, eps_release) ? 1.0 : 0.0;
  const double movable = tangential_mass > 0.0 ? 1.0 : 0.0;
  const double mass = tangential_mass + (1.0 - movable);
  return movable * shear_film_damping<true>(m, in_film, reduced_radius, log_ratio, mass);
}
__attribute__((always_inline)) inline double shear_film_damping_apart(const TangentialModel &m, double eps,
                                                                      double eps_al, double eps_saturation,
                                                                      double eps_release, double reduced_radius,
                                                                      double tangential_mass)
{
  return shear_film_damping_of_log(m, eps, eps_al, eps_release, log_inline(eps_al / std::max(eps, eps_saturation)),
                                   reduced_radius, tangential_mass);
}

}    // namespace lubricated

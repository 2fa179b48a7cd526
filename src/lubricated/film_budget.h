// Many-body limit of the lubrication film (doc/model.rst, "Many-body film budget": stability
// when the lubrication damper is stiffer than the time step can resolve;
// doc/pair_lubricated_springdashpot.rst, "Dense beds").
//
// Over one step the film of contact k acts as a linear damper F_k = -c_k u_k n_k (c_k >= 0: its
// path integral over the step divided by u_k dt, lubrication.h). The velocities the next step
// sees are then v' = v - dt M^-1 sum_k c_k b_k b_k^T v, b_k = n_k (e_i - e_j) for a pair, n_k e_i
// for a wall. Each contact's own cap (|impulse| <= m_e |u_n|, normal_model.h) keeps
// c_k dt <= m_e,k, so an isolated pair never reverses; but a sphere with a dozen film
// neighbours takes the sum of their kicks, and in a dense wet bed at low St the explicit
// update amplifies.
//
// The budget. In mass-weighted velocities y = M^1/2 v the update is y' = (I - A) y with
// A = sum_k c_k dt w_k w_k^T, w_k . y = n_k . (y_i / sqrt(m_i) - y_j / sqrt(m_j)) and
// |w_k|^2 = 1/m_i + 1/m_j = 1/m_e,k. By Cauchy-Schwarz (w_k . y)^2 <= (|y_i|^2 + |y_j|^2) / m_e,k,
// so y^T A y <= sum_i |y_i|^2 D_i with the atom's load
//   D_i = sum over its contacts k of a_k,   a_k = c_k dt / m_e,k   (a wall: m_e = m_i),
// the share of its own cap each contact uses. Scaling every contact by s_k = 1 / max(1, D_i, D_j)
// gives y^T A y <= sum_i |y_i|^2 D_i / max(1, D_i) <= |y|^2: 0 <= A <= I. Every mode of the film
// update is multiplied by a factor in [0, 1]: the film never raises the kinetic energy
// (|y'|^2 <= |y|^2 - y^T A y) and never reverses a mode, whatever the packing, St or time step.
// An isolated pair or wall contact has D = a_k <= 1 and is never scaled, for any masses (other
// weightings of the inequality favour a heavy sphere among light ones but scale isolated
// unequal pairs at their cap; isolated collisions keep their exact results here). Where every
// D <= 1 (dilute beds, films the step resolves) nothing changes; where D > 1 the film does what
// one explicit step can: at most stop the stiffest mode.
//
// The shear film (tangential lubrication, tangential.h) shares the budget. It is a damper on
// the slip s_k = P_t (v_i - v_j) - (R_i w_i + R_j w_j) x n_k (P_t: projection on the tangent
// plane), F = -c_t s on i, -F on j, torques -R_i n x F and -R_j n x F. Take the state with
// rotation, y = (M^1/2 v, I^1/2 w) per atom, whose |y|^2 / 2 is the kinetic energy including the
// rotational one. For a tangent direction t_d (d = 1, 2) of contact k, t_d . s_k = u_kd . y with
//   u_kd = (t_d / sqrt(m_i), -t_d / sqrt(m_j); -R_i (n x t_d) / sqrt(I_i), -R_j (n x t_d) / sqrt(I_j))
// (translation of i, j; rotation of i, j), and the film's update of one step is y' = (I - A) y
// with A_k^t = c_t t_kick (u_k1 u_k1^T + u_k2 u_k2^T), the generalised force of F being exactly
// -c_t sum_d u_kd (u_kd . y) (the torques above are the rotational rows). Its coefficients
// square-sum to |u_kd|^2 = 1/m_i + 1/m_j + R_i^2/I_i + R_j^2/I_j = 7 / (2 m_e) = 1 / m_t for
// solid spheres (I = 2/5 m R^2): m_t = 2/7 m_e is the tangential mass of tangential.h (an
// immovable atom has inverse mass and inverse inertia 0 and m_t follows from the other's; a
// wall: 1/m_t = 1/m_i + R_i^2/I_i, m_e = m_i). So A_k^t = a_t (û_k1 û_k1^T + û_k2 û_k2^T) with
// unit û and the shear share a_t = c_t t_kick / m_t = |F| t_kick / (m_t |s|), the fraction of
// the shear film's own cap (tangential.h integrates it exactly: a_t < 1 over a step).
// One contact's films act on orthogonal directions of y: the normal film's ŵ_k has only
// translational rows along n, û_kd translational rows along t_d (n . t_d = 0) and rotational
// rows along n x t_d ((n x t_1) . (n x t_2) = t_1 . t_2 = 0). So for one contact
//   y^T (A_k^n + A_k^t) y = a_n (ŵ . y)^2 + a_t sum_d (û_kd . y)^2 <= max(a_n, a_t) |P_k y|^2
//                          <= max(a_n, a_t) (|y_i|^2 + |y_j|^2)
// (P_k: the orthogonal projection on span(ŵ, û_k1, û_k2), which lies in the rows of i and j;
// the bound is attained on ŵ or û, so max, not the sum, is the contact's norm). Across contacts
// the bounds add: y^T A y <= sum_i |y_i|^2 D_i with
//   D_i = sum over its contacts k of max(a_n,k, a_t,k)
// and scaling both films of contact k by s_k = 1 / max(1, D_i, D_j) gives 0 <= A <= I again,
// now for the kinetic energy including rotation (|y_i|^2 counts both). The sum over contacts is
// needed (several contacts of one atom can align on one mode); within a contact the max is
// enough, so an isolated pair or wall contact still has D = max(a_n, a_t) <= 1 and keeps its
// exact result, however much of both caps it uses. (Where a rigid body's inertia exceeds its
// spheres' 2/5 m R^2, |u_kd|^2 < 1 / m_t and the share computed with m_t is conservative.)
#pragma once

#include "lubricated/lubrication.h"
#include "lubricated/tangential.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace lubricated {

// The time over which a film force evaluated now acts on the velocity the next evaluation
// sees: a step; half a step at a velocity Verlet start (half kick); a quarter at a
// fix nve/sphere/midpoint start (dt^2/8 F/m of drift against dt/2 u_n), matching the caps of
// normal_force() [time].
inline double film_kick_time(double dt, bool at_start, bool midpoint_start)
{
  return !at_start ? dt : midpoint_start ? 0.25 * dt : 0.5 * dt;
}

// The contact's capacity m_e |u_n|: the largest impulse its own cap allows [mass velocity].
__attribute__((always_inline)) inline double film_capacity(double reduced_mass, double u_n)
{
  return reduced_mass * std::fabs(u_n);
}

// The contact's share a_k = c_k t_kick / m_e = |F_l| t_kick / (m_e |u_n|) (dimensionless, <= 1
// after the contact's own cap; m_e = m for a wall) from its film force and capacity.
// F_l = 0 wherever u_n = 0, so the guard only avoids 0/0.
__attribute__((always_inline)) inline double film_share_of_capacity(double film_force, double capacity,
                                                                    double kick_time)
{
  return std::fabs(film_force) * kick_time / std::max(capacity, DBL_MIN);
}

__attribute__((always_inline)) inline double film_share(double film_force, double reduced_mass, double u_n,
                                                        double kick_time)
{
  return film_share_of_capacity(film_force, film_capacity(reduced_mass, u_n), kick_time);
}

// A bound on the share of any film contact of film radius R and reduced mass m_e (a wall:
// m_e = m), for any gap and velocity: with the contact's eps_al (fixed, or 0.75 dx / R with a grid
// spacing: the same for the contact at every step) the film's impulse over a gap change dg is at
// most 6 pi mu_f R (lambda(eps_1) - lambda(eps_al)) |dg| (lambda decreases with the gap and is
// held at lambda(eps_1) below eps_1, lubrication.h), and |dg| = |u_n| t_kick with t_kick <= dt,
// so a_k <= 6 pi mu_f R (lambda(eps_1) - lambda(eps_al)) dt / m_e; never above 1 (the contact's
// own cap); 0 where a grid leaves no film (0.75 dx / R <= eps_1). Where the bounds of an atom's
// possible film contacts sum to 1 or less, its load cannot exceed 1 and the budget has nothing
// to do.
inline double film_share_bound(const Lubrication &film, double film_radius, double reduced_mass, double dt)
{
  if (!film.active()) return 0.0;
  const double lambda_al =
      film.grid_spacing > 0.0 ? film.activation(FilmRadius(film_radius)).lambda : film.lambda_activation;
  const double slope = std::max(0.0, film.lambda_saturated - lambda_al);
  return std::min(1.0, film.six_pi_mu * film_radius * slope * dt / reduced_mass);
}

// Whether any atom's bound on its load (the sum of its contacts' film_share_bound) can exceed 1,
// with a margin for the rounding of the film's integral (~1e-12 relative): where none can, the
// budget has nothing to do until the bounds change.
inline bool any_load_can_exceed_budget(const double *bound, int n)
{
  constexpr double below_one = 1.0 - 1e-6;
  bool over = false;
  for (int i = 0; i < n; i++)
    over |= bound[i] > below_one;
  return over;
}

// A bound on the shear film's share of any contact (tangential.h, shear_film_force) of film
// radius R_f (eps = gap / R_f, eps_al from R_f with a grid spacing), reduced radius R_e and
// tangential mass m_t, for any gap and slip: the film is the damper integrated exactly over the
// step, F = -(1 - exp(-x)) (m_t / dt) s with x = 2 pi mu_f R_e ln(eps_al / max(eps, eps_1)) dt / m_t,
// so a_t = |F| t_kick / (m_t |s|) = (1 - exp(-x)) t_kick / dt <= 1 - exp(-x_1), x_1 the rate at
// eps <= eps_1 (attained there with t_kick = dt); 0 without a shear film or where a grid leaves
// no film. With the normal film's film_share_bound, a contact's share is at most the larger
// of the two (contact_film_share).
inline double shear_film_share_bound(const TangentialModel &shear, const Lubrication &film, double film_radius,
                                     double reduced_radius, double tangential_mass, double dt)
{
  if (!shear.film_active() || !film.active()) return 0.0;
  const double log_range = std::log(film.activation_for(film_radius) / film.eps_saturation);
  const double rate = shear.two_pi_mu * reduced_radius * std::max(0.0, log_range) * dt / tangential_mass;
  return -std::expm1(-rate);
}

// A bound on the rolling film's share (tangential.h, roll_film_torque) of any pair of film radius
// R_f, reduced radius R_e and rolling inertia I_e (1/I_e = 1/I_i + 1/I_j): a_r = (1 - exp(-x))
// t_kick / dt <= 1 - exp(-x_1), x = gamma dt / I_e largest at eps <= eps_1. It acts on the spins,
// as the shear film does: a contact's tangential share is the sum of the two (the norm of a sum
// of dampers is at most the sum of their norms), and its share the larger of that and the normal
// film's (orthogonal: translation along n).
inline double roll_film_share_bound(const TangentialModel &m, const Lubrication &film, double film_radius,
                                    double reduced_radius, double rolling_inertia, double dt)
{
  if (!m.roll_film_active() || !film.active()) return 0.0;
  const double log_range = std::max(0.0, std::log(film.activation_for(film_radius) / film.eps_saturation));
  return -std::expm1(-roll_film_gamma(m.roll_mu, reduced_radius, log_range) * dt / rolling_inertia);
}

// The shear film's share a_t = |F| t_kick / (m_t |s|) from the squared lengths of its force and
// the slip (F = -c_t s: parallel), m_t the tangential mass (tangential_mass_ratio m_e).
inline double shear_film_share(double force_sq, double slip_sq, double tangential_mass, double kick_time)
{
  return std::sqrt(force_sq / std::max(slip_sq, DBL_MIN)) * kick_time / tangential_mass;
}

// A bound on film_share_bound and shear_film_share_bound of every pair of spheres with radii in
// [r_min, r_max] and masses of at least m_min, for one film (no logarithm per pair: one check of
// a whole bed costs a comparison per pair). The film radius 2 r_i r_j / (r_i + r_j) and the
// reduced radius times 2 lie in [r_min, r_max], and 1 / m_e = 1 / m_i + 1 / m_j <= 2 / m_min. eps_al
// does not grow with R, and lambda(eps) = c_inv / eps + c_log ln eps + c_elog eps ln eps + c_0
// decreases for every eps > 0 (c_inv > 0 and c_log, c_elog <= 0: -eps^2 (ln eps + 1) <= 0.025 where
// c_elog's term grows, and c_inv > 0.025 |c_elog|), so lambda(eps_1) - lambda(eps_al) and
// ln(eps_al / eps_1) are largest at R = r_min.
inline double pair_film_share_ceiling(const TangentialModel &shear, const Lubrication &film, double r_min, double r_max,
                                      double m_min, double dt)
{
  if (!film.active()) return 0.0;
  const FilmRadius smallest(r_min);
  const double lambda_al = film.grid_spacing > 0.0 ? film.activation(smallest).lambda : film.lambda_activation;
  const double slope = std::max(0.0, film.lambda_saturated - lambda_al);
  const double normal = std::min(1.0, film.six_pi_mu * r_max * slope * dt * 2.0 / m_min);
  if (!shear.film_active() && !shear.roll_film_active()) return normal;
  const double log_range = std::max(0.0, std::log(film.activation_for(smallest) / film.eps_saturation));
  const double rate = shear.two_pi_mu * (0.5 * r_max) * log_range * dt / (tangential_mass_ratio * 0.5 * m_min);
  // Rolling film: R_e <= r_max / 2 and 1/I_e <= 2 / (0.4 m_min r_min^2).
  const double roll_rate = roll_film_gamma(shear.roll_mu, 0.5 * r_max, log_range) * dt * 2.0 /
                           (solid_sphere_inertia_ratio * m_min * r_min * r_min);
  return std::max(normal, -std::expm1(-rate) - std::expm1(-roll_rate));
}

// One contact's share of its atoms' loads: the larger of its normal and shear films' shares
// (orthogonal directions of the contact's relative motion; see above).
inline double contact_film_share(double normal_share, double shear_share)
{
  return std::max(normal_share, shear_share);
}

// Scale of one atom's films from its load D_i; a pair takes the smaller of its two atoms'
// scales (a wall: its atom's).
inline double film_scale_of_load(double load)
{
  return 1.0 / std::max(1.0, load);
}

}    // namespace lubricated

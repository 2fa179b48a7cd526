// Many-body limit of the lubrication film (MODEL.md section 3 and section 6, "stability when the
// lubrication damper is stiffer than the time step can resolve";
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
#pragma once

#include "lubricated/lubrication.h"

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
// m_e = m), for any gap and velocity: with a fixed eps_al the film's impulse over a gap change
// dg is at most 6 pi mu_f R (lambda(eps_1) - lambda(eps_al)) |dg| (lambda decreases with the gap
// and is held at lambda(eps_1) below eps_1, lubrication.h), and |dg| = |u_n| t_kick with
// t_kick <= dt, so a_k <= 6 pi mu_f R (lambda(eps_1) - lambda(eps_al)) dt / m_e; never above 1
// (the contact's own cap). With a grid spacing eps_al differs per contact: 1, no bound.
// Where the bounds of an atom's possible film contacts sum to 1 or less, its load cannot
// exceed 1 and the budget has nothing to do.
inline double film_share_bound(const Lubrication &film, double film_radius, double reduced_mass, double dt)
{
  if (!film.active()) return 0.0;
  if (film.grid_spacing > 0.0) return 1.0;
  const double slope = film.lambda_saturated - film.lambda_activation;
  return std::min(1.0, film.six_pi_mu * film_radius * slope * dt / reduced_mass);
}

// Scale of one atom's films from its load D_i; a pair takes the smaller of its two atoms'
// scales (a wall: its atom's).
inline double film_scale_of_load(double load)
{
  return 1.0 / std::max(1.0, load);
}

}    // namespace lubricated

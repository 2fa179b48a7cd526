// Stability of a bed's network of sustained contacts under the explicit step (doc/model.rst,
// "Dense beds: the contact network"; doc/pair_lubricated_springdashpot.rst, the same section).
//
// In a contact that lasts (in overlap a step ago, now and a step ahead: "sustained") the exact
// integration is a spring-dashpot with per-step constants
// (contact_step.h): per unit reduced mass kappa = k' dt^2 = 1 + E^2 - 2 E C and gamma = c' dt = 1 - E^2,
// the dashpot acting on the velocity of the last step ("integration sampled": kappa = (k/m_e) dt^2,
// gamma = (c/m_e) dt, the same form). An isolated pair then lands on the analytic oscillator for any
// N_c; a sphere pressed by many others is another matter.
//
// In mass-weighted coordinates y = M^1/2 x each contact k acts along a unit vector b_k,
// b_k . y = sqrt(m_e) n_k . (y_i / sqrt(m_i) - y_j / sqrt(m_j)) (|b_k| = 1 since m_e (1/m_i + 1/m_j)
// = 1), and the step is y' - 2 y + y'' = -(K y + C (y - y'')) with K = sum kappa_k b_k b_k^T,
// C = sum gamma_k b_k b_k^T (y' next, y'' last; the gaps are affine in y). With u = y - y'' and
// ybar the midpoint, G = u^T (I - K/4 - C/2) u + ybar^T K ybar obeys G_next = G - (u_next + u)^T
// C (u_next + u) / 2: the step is stable (G positive definite and non-increasing) when
//   lambda_max(S) < 4,   S = sum_k s_k b_k b_k^T,   s_k = kappa_k + 2 gamma_k  (the contact's load).
// For contacts of one model (K and C proportional) this is also necessary: a mode of
// sum b_k b_k^T with eigenvalue mu has the characteristic equation z^2 - (2 - mu (kappa + gamma)) z
// + 1 - mu gamma = 0, with a root z < -1 (a motion that changes sign and grows every step) exactly
// when mu s >= 4. An isolated pair (mu = 1) has s = 3 - E^2 - 2 E C <= 3.25 < 4 for every N_c >= 1
// (C >= -1/2 by the floor of 1.5 steps per contact) and e_d: it is never limited.
//
// lambda_max(S) is a property of the whole packing; two bounds cost a per-atom sum each:
//
// - upper (Gershgorin on the Gram matrix of the sqrt(s_k) b_k; b_k . b_l = +-sqrt(m_e,k m_e,l)
//   (n_k . n_l) / m_i for contacts sharing sphere i):
//     lambda_max(S) <= max_k sqrt(s_k m_e,k) (T_i / m_i + T_j / m_j),  T_i = sum over i's contacts
//     of sqrt(s_l m_e,l);
//   exact for an isolated pair (s) and for three spheres in a row; below 4 the network is stable.
// - lower (Rayleigh quotient of b_k):
//     lambda_max(S) >= b_k^T S b_k = s_k + m_e,k [(n_k^T F_i n_k - s_k m_e,k) / m_i^2 + (same for j)],
//     F_i = sum over i's contacts of s_l m_e,l n_l n_l^T;
//   at 4 or above a mode of the (linearised) network grows: the run cannot be right.
//
// On a random packing of 300 spheres with radii 0.1-1 mm at solid fraction 0.70 (592 contacts,
// tests/lammps/test_dense_packings.py) the unit network (s = 1) has lambda_max = 3.07, between the
// bounds 2.34 and 10.1 (a dry run there is stable at N_c = 2.8 and unstable at N_c = 2.5 and 2,
// stable at N_c = 8 with e_d = 0.05 and unstable with 0.02, as lambda_max s < 4 predicts).
//
// With friction the tangential spring adds two unit vectors per contact (the slip directions, with
// the rotations; m_t = 2/7 m_e is the slip mode's mass), orthogonal to b_k, whose parts on each
// sphere have the same norm sqrt(m_e / m_i): block Gershgorin gives the upper bound with
// s_k = max(s_normal, s_tangential); the lower bound stays valid with the normal load alone
// (the tangential springs only add to S). A contact in overlap a step ago and now whose
// oscillator would leave within the step is pushed out harder than the recurrence (to the exit);
// the checks count it as sustained, which at N_c <= 2 (every contact predicted to leave within a
// step) is every contact of a pressed bed. Contacts that slide (Coulomb) are softer; the films
// of the per-pair step, dampers on the velocity of the last step too, add to C (up to a load of
// 2 with the film budget) and are not counted. A film solved implicitly (the coupled film solve,
// film_solve.h) acts on the velocity the step ends with instead:
//   y' - 2 y + y'' = -(K y + C (y - y'')) - D (y' - y),   D = dt M^-1/2 R M^-1/2 (R: its films),
// and G = u^T (I - K/4 - C/2 + D/2) u + ybar^T K ybar obeys G_next = G - (u_next + u)^T (C + D)
// (u_next + u) / 2: stable when S < 4 I + 2 D. A sustained contact whose own normal film is in
// the solve, a_k = c_k dt / m_e,k (D >= sum a_k b_k b_k^T, R being positive semi-definite), so
// counts with the relieved load (s_k - 2 a_k)^+ (film_relieved_load) in the upper bound: S - 2 D
// <= the sum of the relieved loads' terms (the tangential loads not relieved), so below 4 the
// step is stable. The lower bound counts the contact's own film alone, b_k^T S b_k - 2 a_k: the
// other films of its spheres resist its mode too (b_k^T D b_k >= a_k), but a mode that moves
// those spheres together escapes them, and a bed compressed at N_c = 2 with its films solved lost
// atoms while the lower bound with every film counted stayed below 4; so the check errs toward
// stopping a run (exact without films, as before). A wall contact with its wall's film of the
// sphere in the solve counts alike, m_i in place of m_e. A wall is a partner of infinite mass
// (its contact's b_k lies on the sphere alone: the terms of the second sphere drop out); the
// LAMMPS pair style counts the contacts of the plugin's wall fixes so, the LIGGGHTS model not.
#pragma once

#include <algorithm>
#include <cmath>

namespace lubricated {

// The step is stable while lambda_max(S) < stable_network_load.
constexpr double stable_network_load = 4.0;
// Where the upper bound reaches 4, a run is warned only if the lower bound reaches this: on random
// packings (radii equal or 1:10, 160-1900 contacts) lambda_max was 1.15-1.41 times the lower bound,
// so there a growing mode is likely (at 2/3 of the limit and a ratio up to 1.5).
constexpr double likely_unstable_network_load = 8.0 / 3.0;
// Pairs of types whose load is at most this need no check: with it, an ERROR needs a lower bound
// (unit loads) of 16 and a WARNING one of 10.7, where equal spheres reach at most
// 1 + (z_i + z_j - 2) / 4 = 6.5 (12 contacts each; the packing above: 2.34).
constexpr double network_check_load = 0.25;

// Steps between two checks (and the first step of each run). A growing mode depends on the
// packing, not on its amplitude: the first check of an unstable bed finds it. One that a run makes
// unstable (a compression) grows for at most this many steps before the check (by 4 per step at
// N_c = 2 on the packing above, from round-off), while the check costs 1/interval of its pass.
constexpr int network_check_interval = 10;

// Load s = kappa + 2 gamma of a sustained contact from its per-step constants per unit mass:
// stiffness [1/time^2], damping [1/time], time step [time].
inline double contact_load(double stiffness_per_mass, double damping_per_mass, double dt)
{
  return stiffness_per_mass * dt * dt + 2.0 * damping_per_mass * dt;
}

// Load of the exact integration of a contact with restitution e (0 <= e <= 1) lasting n steps:
// 3 - E^2 - 2 E C, E = e^(1/n), C = cos(pi / n), n at least 1.5 (contact_step.h, tangential.h).
inline double contact_load_of_steps(double e, double n)
{
  n = std::max(n, 1.5);
  const double E = e > 0.0 ? std::pow(e, 1.0 / n) : 0.0, C = std::cos(3.14159265358979323846 / n);
  return 3.0 - E * E - 2.0 * E * C;
}

// Load of a spring-dashpot with restitution e (0 < e <= 1) lasting n steps whose force is sampled
// once per step (integration sampled; LIGGGHTS's tangential models, kt = 2/7 k on 2/7 m_e):
// (k/m) dt^2 + 2 (c/m) dt with k/m = (pi^2 + ln^2 e) / t_c^2, c/m = -2 ln e / t_c (spring_dashpot.h).
inline double sampled_load_of_steps(double e, double n)
{
  const double l = std::log(e), pi = 3.14159265358979323846;
  return (pi * pi + l * l) / (n * n) - 4.0 * l / n;
}

// How the load that bounds a type pair's contacts depends on their duration n (steps), as the
// engines set it: the normal contact's (exact or sampled integration) and, where one acts, a
// tangential spring's: exact with restitution e_t (the LAMMPS pair style's friction) or sampled
// with the normal's k/m_e and c/m_e (LIGGGHTS's tangential models).
struct ContactLoadModel {
  double e_n = 1.0;
  bool sampled_normal = false;
  double e_t = -1.0;                  // >= 0: an exact tangential spring of this restitution
  bool sampled_tangential = false;    // a sampled tangential spring of the normal's constants

  double operator()(double n) const
  {
    double load = sampled_normal ? sampled_load_of_steps(e_n, n) : contact_load_of_steps(e_n, n);
    if (e_t >= 0.0) load = std::max(load, contact_load_of_steps(e_t, n));
    if (sampled_tangential) load = std::max(load, sampled_load_of_steps(e_n, n));
    return load;
  }
};

// Smallest contact duration in steps, from `from` up to 1e6, at which the model's load is at most
// `load` (to 1e-3 relative; the loads fall with n).
inline double contact_steps_for_load(const ContactLoadModel &model, double load, double from = 1.0)
{
  double lo = from, hi = 1e6;
  if (model(lo) <= load) return lo;
  for (int it = 0; it < 200 && hi - lo > 1e-3 * lo; ++it) {
    const double mid = std::sqrt(lo * hi);
    (model(mid) <= load ? hi : lo) = mid;
  }
  return hi;
}

// The same for the exact integration with restitutions e_n (normal) and e_t (tangential; < 0: none).
inline double contact_steps_for_load(double e_n, double e_t, double load)
{
  ContactLoadModel model;
  model.e_n = e_n;
  model.e_t = e_t;
  return contact_steps_for_load(model, load);
}

// What a contact's own normal film of coefficient c [force/velocity], taken implicitly by the
// coupled solve, takes off its load: 2 a, a = c dt / m_e (above; m_i for a wall).
inline double film_relief(double film_damping, double dt, double reduced_mass)
{
  return 2.0 * film_damping * dt / reduced_mass;
}

// The relieved load of such a contact, (s - 2 a)^+, for the upper bound.
inline double film_relieved_load(double load, double film_damping, double dt, double reduced_mass)
{
  return std::max(0.0, load - film_relief(film_damping, dt, reduced_mass));
}

// Per-sphere sums over its sustained contacts: T, the six components of F (xx yy zz xy xz yz)
// and the number of contacts.
constexpr int network_values = 8;

// Adds contact k (normal load s_normal, bounding load s_bound = max(normal, tangential), reduced
// mass m_e, unit normal n) to one of its spheres.
inline void add_network_contact(double *sums, double s_normal, double s_bound, double reduced_mass, const double *n)
{
  const double w = s_normal * reduced_mass;
  sums[0] += std::sqrt(s_bound * reduced_mass);
  sums[1] += w * n[0] * n[0];
  sums[2] += w * n[1] * n[1];
  sums[3] += w * n[2] * n[2];
  sums[4] += w * n[0] * n[1];
  sums[5] += w * n[0] * n[2];
  sums[6] += w * n[1] * n[2];
  sums[7] += 1.0;
}

// Upper bound of contact k (Gershgorin row): the network is stable if every row is below 4.
inline double network_upper_row(double s_bound, double reduced_mass, const double *sums_i, double m_i,
                                const double *sums_j, double m_j)
{
  return std::sqrt(s_bound * reduced_mass) * (sums_i[0] / m_i + sums_j[0] / m_j);
}

// Lower bound of contact k (Rayleigh quotient of b_k): a mode grows if one is 4 or more.
inline double network_lower_quotient(double s_normal, double reduced_mass, const double *n, const double *sums_i,
                                     double m_i, const double *sums_j, double m_j)
{
  auto nFn = [n](const double *s) {
    return s[1] * n[0] * n[0] + s[2] * n[1] * n[1] + s[3] * n[2] * n[2] +
           2.0 * (s[4] * n[0] * n[1] + s[5] * n[0] * n[2] + s[6] * n[1] * n[2]);
  };
  const double own = s_normal * reduced_mass;
  return s_normal + reduced_mass * ((nFn(sums_i) - own) / (m_i * m_i) + (nFn(sums_j) - own) / (m_j * m_j));
}

}    // namespace lubricated

// Lubrication film force of Brandle de Motta et al. (CFM 2011), eqs. (5)-(7); doc/model.rst,
// "Lubrication film".
//
//   F_l = -6 pi mu_f R u_n [lambda(eps) - lambda(eps_al)]
//
// eps = gap / R, u_n = normal relative velocity (> 0 when the surfaces separate), so F_l
// opposes both approach and separation. The force is active for eps_2 < eps < eps_al and
// held at its eps_1 value for eps < eps_1 (saturation: roughness, non-continuum film).
//
// Radius convention (documented in doc/pair_lubricated_springdashpot.rst):
//   particle-wall:     R = particle radius, lambda = lambda_pw;
//   particle-particle: R = 2 R_1 R_2 / (R_1 + R_2), lambda = lambda_pp.
// For equal spheres this is the paper's R; for unequal spheres the leading singular term
// 6 pi mu R^2 u_n / (2 gap) then scales with the square of the reduced radius
// R_1 R_2 / (R_1 + R_2), the dependence of the asymptotic two-sphere theory.
#pragma once

#include "inline_log.h"
#include "spring_dashpot.h"

#include <algorithm>
#include <cmath>

namespace lubricated {

enum class Partner { particle, wall };

// Brenner / Cox-Brenner expansions as printed in the paper (eqs. 6 and 7), both of the form
//   lambda(eps) = c_inv / eps + c_log ln eps + c_elog eps ln eps + c_0,
// with the antiderivative
//   L(eps) = c_inv ln eps + c_log (eps ln eps - eps) + c_elog (eps^2 ln eps / 2 - eps^2 / 4) + c_0 eps.
struct Expansion {
  double c_inv, c_log, c_elog, c_0;

  // l = ln(eps), when the caller has it already.
  double lambda(double eps, double l) const { return c_inv / eps + c_log * l + c_elog * eps * l + c_0; }
  // The same with 1 / eps given (no division where the caller has it from another quotient).
  double lambda_of_inverse(double eps, double inverse, double l) const
  {
    return c_inv * inverse + c_log * l + c_elog * eps * l + c_0;
  }
  double integral(double eps, double l) const
  {
    return c_inv * l + c_log * (eps * l - eps) + c_elog * eps * eps * (0.5 * l - 0.25) + c_0 * eps;
  }
  double lambda(double eps) const { return lambda(eps, std::log(eps)); }
  double integral(double eps) const { return integral(eps, std::log(eps)); }
};

constexpr Expansion particle_particle_expansion{0.5, -0.45, -3.0 / 56.0, 1.346};
constexpr Expansion particle_wall_expansion{1.0, -0.2, -1.0 / 21.0, 0.9713};

inline const Expansion &expansion_of(Partner partner)
{
  return partner == Partner::wall ? particle_wall_expansion : particle_particle_expansion;
}

inline double lambda_of(Partner partner, double eps)
{
  return expansion_of(partner).lambda(eps);
}

// Antiderivative of lambda (d/deps of it is lambda).
inline double lambda_integral_of(Partner partner, double eps)
{
  return expansion_of(partner).integral(eps);
}

// DEM without a resolved fluid (doc/model.rst, "DEM without a resolved fluid"): fix fluid/drag
// already applies the unbounded fluid's resistance, 6 pi mu_f R u_n at a wall (lambda = 1 far
// from it, Brenner 1961). The film must add only the wall's excess, lambda_pw(eps) - 1: it starts
// at the gap eps* where lambda_pw(eps*) = 1, so that film + drag = lambda_pw(eps) below eps*
// (Brenner's resistance to the expansion's accuracy) and hands over continuously to the drag
// above it. eps* = 2.7505 (lambda_pw decreases on [1, 10]; bisection to round-off).
constexpr double wall_drag_share = 1.0;

inline double drag_handover_activation()
{
  double lo = 1.0, hi = 10.0;    // lambda_pw(1) = 1.97 > 1 > lambda_pw(10) = -0.43
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (particle_wall_expansion.lambda(mid) > wall_drag_share ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The radius R of the film force and its inverse (one division per pair, not two).
struct FilmRadius {
  double value = 0.0, inverse = 0.0;
  FilmRadius() = default;
  explicit FilmRadius(double radius) : value(radius), inverse(1.0 / radius) {}
  FilmRadius(double radius, double inverse_radius) : value(radius), inverse(inverse_radius) {}
};

// Per-type-pair lubrication constants. eps_activation <= 0 marks a dry pair.
struct Lubrication {
  Partner partner = Partner::particle;
  Expansion expansion = particle_particle_expansion;
  double six_pi_mu = 0.0;              // 6 pi mu_f            [mass/(length time)]
  double eps_activation = 0.0;         // eps_al (used when grid_spacing == 0)
  double grid_spacing = 0.0;           // dx > 0: eps_al = 0.75 dx / R per contact (Breugem)
  double eps_saturation = 1e-3;        // eps_1
  double eps_release = -1e-2;          // eps_2
  double lambda_activation = 0.0;      // lambda(eps_al) when eps_al is fixed
  double integral_activation = 0.0;    // antiderivative of lambda at eps_al (fixed eps_al)
  double lambda_saturated = 0.0;       // lambda(eps_1)
  double integral_saturated = 0.0;     // antiderivative of lambda at eps_1

  bool active() const { return six_pi_mu > 0.0; }

  // Breugem's rule with a grid: the film starts at a gap of 0.75 dx (doc/model.rst, "Zones of the
  // normal interaction").
  static constexpr double grid_activation = 0.75;

  // Activation distance in units of R for a contact of lubrication radius R. With a grid, a
  // contact so large that 0.75 dx / R falls below eps_1 gets eps_al = eps_1, that is no film:
  // lambda(eps_1) - lambda(eps_al) < 0 would make a film that pulls the surfaces together
  // (doc/model.rst, "Zones of the normal interaction" orders the zones eps_2 < eps_1 < eps_al; a
  // fixed eps_al must exceed eps_1, coefficients.h).
  double activation_for(const FilmRadius &radius) const
  {
    return grid_spacing > 0.0 ? activation_inline_eps<true>(radius) : activation_inline_eps<false>(radius);
  }
  double activation_for(double radius) const { return activation_for(FilmRadius(radius)); }

  // Film integral P(eps) = int_eps^inf [c_l(s) / (6 pi mu R)] ds over the zones above:
  // 0 beyond eps_al, growing towards contact, constant below eps_2. The impulse of the film
  // along any path from eps_a to eps_b is exactly 6 pi mu R^2 [P(eps_b) - P(eps_a)].
  // eps_al, lambda(eps_al) and L(eps_al) are passed in (fixed per type pair, or per contact).
  double film_integral(double eps, double eps_al, double lambda_al, double integral_al) const
  {
    if (eps >= eps_al) return 0.0;
    if (eps >= eps_saturation) return integral_al - expansion.integral(eps) - lambda_al * (eps_al - eps);
    // Saturated (no logarithm: L(eps_1) is kept per type pair).
    return integral_al - integral_saturated - lambda_al * (eps_al - eps_saturation) +
           (lambda_saturated - lambda_al) * (eps_saturation - std::max(eps, eps_release));
  }

  // eps_al with lambda and L there, for a contact of film radius R: kept per type pair for a
  // fixed eps_al, from one logarithm with a grid spacing.
  struct Activation {
    double eps, lambda, integral;
  };
  Activation activation(const FilmRadius &radius) const
  {
    const double eps_al = activation_for(radius);
    if (grid_spacing <= 0.0) return {eps_al, lambda_activation, integral_activation};
    const double l = std::log(eps_al);
    return {eps_al, expansion.lambda(eps_al, l), expansion.integral(eps_al, l)};
  }

  double film_integral(double eps, const Activation &al) const
  {
    return film_integral(eps, al.eps, al.lambda, al.integral);
  }

  // lambda(eps_al) alone, as activation(): for one pair at a time, where std::log's call costs
  // less than log_inline's series (a chain of dependent operations there, not a vector's lanes).
  double lambda_activation_for(const FilmRadius &radius) const
  {
    if (grid_spacing <= 0.0) return lambda_activation;
    const double eps_al = activation_for(radius);
    // 1 / eps_al as R / (0.75 dx) (clamped at 1 / eps_1): no division after the logarithm.
    const double inverse_al = std::min(radius.value * (1.0 / (grid_activation * grid_spacing)), 1.0 / eps_saturation);
    const double l = std::log(eps_al);
    return expansion.lambda_of_inverse(eps_al, inverse_al, l);
  }

  // activation() without branches or calls (log_inline), for loops the compiler vectorises;
  // equal to it within rounding. Only for an active film; GRID: whether it has a grid spacing.
  template <bool GRID> __attribute__((always_inline)) Activation activation_inline(const FilmRadius &radius) const
  {
    if (!GRID) return {eps_activation, lambda_activation, integral_activation};
    const double eps_al = activation_inline_eps<GRID>(radius);
    const double l = log_inline(eps_al);
    return {eps_al, expansion.lambda(eps_al, l), expansion.integral(eps_al, l)};
  }
  // eps_al alone, as activation_inline's (no logarithm).
  template <bool GRID> __attribute__((always_inline)) double activation_inline_eps(const FilmRadius &radius) const
  {
    return GRID ? std::max(grid_activation * grid_spacing * radius.inverse, eps_saturation) : eps_activation;
  }
  double film_integral(double eps, double radius) const { return film_integral(eps, activation(FilmRadius(radius))); }

  // P(after) - P(before) for a contact of film radius R (film_integral) without branches or calls,
  // equal to it within rounding and cheaper than two of them: L(eps_al), which cancels, left out,
  // 1 / eps_al as R / (0.75 dx) (the clamp at eps_1 as a clamp of the inverse) and the
  // logarithms' divisions shared (log_inline of two or three). For loops the compiler vectorises
  // (film_force_apart); GRID: whether the film has a grid spacing.
  //   P(a) - P(b) = L(f_b) - L(f_a) + lambda(eps_al) (f_a - f_b) + (lambda(eps_1) - lambda(eps_al)) (s_b - s_a)
  // with f = eps clamped to [eps_1, eps_al] and s = eps clamped to [eps_2, eps_1].
  // shear_log: ln(eps_al / f_a), what the shear film's coefficient needs at eps = after inside
  // the film (ln(eps_al / max(eps, eps_1)) there; tangential.h), from the same logarithms.
  // lambda_al: lambda(eps_al) of the pair (as activation_inline's, within rounding).
  template <bool GRID> __attribute__((always_inline)) double film_integral_change_inline(double after, double before,
                                                                                         const FilmRadius &radius,
                                                                                         double &shear_log,
                                                                                         double &lambda_al) const
  {
    const double reach = grid_activation * grid_spacing;
    const double eps_al = activation_inline_eps<GRID>(radius);
    const double f_a = std::min(std::max(after, eps_saturation), eps_al);
    const double f_b = std::min(std::max(before, eps_saturation), eps_al);
    double l_a, l_b;
    if (GRID) {
      double l_al;
      log_inline(f_a, f_b, eps_al, l_a, l_b, l_al);
      const double inverse_al = std::min(radius.value * (1.0 / reach), 1.0 / eps_saturation);
      lambda_al = expansion.lambda_of_inverse(eps_al, inverse_al, l_al);
      shear_log = l_al - l_a;
    } else {
      log_inline(f_a, f_b, l_a, l_b);
      lambda_al = lambda_activation;
      shear_log = log_inline(eps_activation) - l_a;    // the same for every pair: out of a loop
    }
    const double s_a = std::min(std::max(after, eps_release), eps_saturation);
    const double s_b = std::min(std::max(before, eps_release), eps_saturation);
    return expansion.integral(f_b, l_b) - expansion.integral(f_a, l_a) + lambda_al * (f_a - f_b) +
           (lambda_saturated - lambda_al) * (s_b - s_a);
  }

  // Momentum the film transfers to the pair (along n) while the gap goes from gap_before to
  // gap_after: the path integral of c_l, independent of how the path is split into steps.
  double impulse(double gap_before, double gap_after, const FilmRadius &radius) const
  {
    const double before = gap_before * radius.inverse, after = gap_after * radius.inverse;
    const double eps_al = activation_for(radius);
    if (before >= eps_al && after >= eps_al) return 0.0;    // no logarithm far from the film
    const Activation al = activation(radius);
    return six_pi_mu * radius.value * radius.value * (film_integral(after, al) - film_integral(before, al));
  }

  double impulse(double gap_before, double gap_after, double radius) const
  {
    return impulse(gap_before, gap_after, FilmRadius(radius));
  }

  // Largest gap (length) at which the film acts for a contact of lubrication radius R.
  double reach(double radius) const
  {
    if (!active()) return 0.0;
    return grid_spacing > 0.0 ? grid_activation * grid_spacing : eps_activation * radius;
  }

  // Damping coefficient c_l >= 0 such that F_l = -c_l u_n, for normalised gap eps.
  double damping(double eps, double radius) const
  {
    if (eps <= eps_release) return 0.0;
    const double eps_al = activation_for(radius);
    if (eps >= eps_al) return 0.0;
    const double lambda_al = grid_spacing > 0.0 ? expansion.lambda(eps_al) : lambda_activation;
    const double lambda_eps = expansion.lambda(std::max(eps, eps_saturation));
    return six_pi_mu * radius * (lambda_eps - lambda_al);
  }
};

inline Lubrication make_lubrication(Partner partner, double mu_f, double eps_activation, double grid_spacing,
                                    double eps_saturation, double eps_release)
{
  Lubrication lub;
  lub.partner = partner;
  lub.expansion = expansion_of(partner);
  lub.six_pi_mu = 6.0 * pi * mu_f;
  lub.eps_activation = eps_activation;
  lub.grid_spacing = grid_spacing;
  lub.eps_saturation = eps_saturation;
  lub.eps_release = eps_release;
  if (lub.active() && grid_spacing <= 0.0) {
    lub.lambda_activation = lambda_of(partner, eps_activation);
    lub.integral_activation = lambda_integral_of(partner, eps_activation);
  }
  lub.lambda_saturated = lambda_of(partner, eps_saturation);
  lub.integral_saturated = lambda_integral_of(partner, eps_saturation);
  return lub;
}

// Radius that enters the film force between two particles (see the convention above),
// R = 2 R_i R_j / (R_i + R_j), with its inverse (R_i + R_j) / (2 R_i R_j), from a single division.
// Every engine takes it from here (the same rounding everywhere).
inline FilmRadius film_radius_pair(double radius_i, double radius_j)
{
  const double sum = radius_i + radius_j, twice_product = 2.0 * radius_i * radius_j;
  const double q = 1.0 / (sum * twice_product);
  return FilmRadius(twice_product * twice_product * q, sum * sum * q);
}

}    // namespace lubricated

// atan2 without branches or calls, so that loops over pairs that need it can be vectorised by
// the compiler (std::atan2 is a call): the exit time of contacts that leave the overlap within a
// step (normal_model.h, overlap_exit_force). In scalar code libm's is faster.
#pragma once

#include <algorithm>
#include <cmath>

#include "lubricated/polynomial.h"

namespace lubricated {

namespace detail {

// atan(u) / u in z = u^2 for |u| <= tan(pi/8): its minimax polynomial of degree 11 (relative error
// 1.2e-18, tools/series_minimax.py atan; the series needs degree 19), one multiply-add per degree.
__attribute__((always_inline)) inline double atan_ratio_of_square(double z)
{
  static constexpr double coefficients[] = {1.0,
                                            -0.3333333333333313,
                                            0.19999999999942733,
                                            -0.1428571427941696,
                                            0.11111110752666387,
                                            -0.09090897019142409,
                                            0.0769204888361344,
                                            -0.06662990408013629,
                                            0.0584714768303636,
                                            -0.05036270211262671,
                                            0.0379938683666244,
                                            -0.01783567200022157};
  return horner(z, coefficients);
}

}    // namespace detail

// atan2(y, x) in [0, pi] for y >= 0 (not both 0), within a few units in the last place of
// std::atan2: t = min(|x|, y) / max(|x|, y) in [0, 1]; above tan(pi/8), atan t = pi/4 +
// atan((t - 1) / (t + 1)); then mirrored about pi/4 where y > |x| and about pi/2 where x < 0.
__attribute__((always_inline)) inline double atan2_nonnegative_inline(double y, double x)
{
  constexpr double pi = 3.14159265358979323846, quarter_pi = 0.78539816339744830962;
  constexpr double tan_eighth_pi = 0.41421356237309504880;
  const double ax = std::fabs(x), big = std::max(ax, y), small = std::min(ax, y);
  const double t = small / big;
  const bool reduced = t > tan_eighth_pi;
  const double u = reduced ? (t - 1.0) / (t + 1.0) : t;
  const double a = (reduced ? quarter_pi : 0.0) + u * detail::atan_ratio_of_square(u * u);
  const double in_first = y > ax ? 0.5 * pi - a : a;
  return x < 0.0 ? pi - in_first : in_first;
}

}    // namespace lubricated

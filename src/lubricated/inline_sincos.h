// sin and cos without branches or calls, so that loops over pairs that need them can be
// vectorised by the compiler (std::sin and std::cos are calls): the steps where a contact starts
// or ends (contact_step.h, event_acceleration_inline). In scalar code libm's are faster.
#pragma once

#include <cstdint>
#include <cstring>

#include "lubricated/polynomial.h"

namespace lubricated {

namespace detail {

// sin(r) / r and cos(r) in z = r^2 for |r| <= pi/4: their minimax polynomials of degree 6 and 7
// (relative error 3.3e-18 and 3.6e-20, tools/series_minimax.py sin, cos), one multiply-add per degree.
__attribute__((always_inline)) inline double sin_ratio_of_square(double z)
{
  static constexpr double coefficients[] = {1.0,
                                            -0.16666666666666616,
                                            0.008333333333320002,
                                            -0.00019841269828402131,
                                            2.755731329901569e-06,
                                            -2.5050705846484807e-08,
                                            1.589413637832744e-10};
  return horner(z, coefficients);
}

__attribute__((always_inline)) inline double cos_of_square(double z)
{
  static constexpr double coefficients[] = {1.0,
                                            -0.5,
                                            0.04166666666666643,
                                            -0.0013888888888858961,
                                            2.4801587282899458e-05,
                                            -2.755731286569497e-07,
                                            2.0875555145571405e-09,
                                            -1.1352123201883281e-11};
  return horner(z, coefficients);
}

}    // namespace detail

// sin(x) and cos(x) within a few units in the last place of libm's for |x| < 1e5 (the angles of
// an oscillator over a step are below pi): x = k pi/2 + r, |r| <= pi/4, with pi/2 in three parts
// (the first two with 33 significant bits, so k times them is exact), sin(r) and cos(r) by their
// minimax polynomials, then the quadrant k mod 4 picks and signs them.
__attribute__((always_inline)) inline void sincos_inline(double x, double &sin_x, double &cos_x)
{
  constexpr double two_over_pi = 6.36619772367581382433e-01;
  constexpr double half_pi_1 = 1.57079632673412561417e+00, half_pi_2 = 6.07710050630396597660e-11,
                   half_pi_3 = 2.02226624879595063154e-21;
  constexpr double round_magic = 6755399441055744.0;    // 1.5 2^52: adding it rounds to an integer
  const double shifted = x * two_over_pi + round_magic;
  const double k = shifted - round_magic;
  const double r = ((x - k * half_pi_1) - k * half_pi_2) - k * half_pi_3;
  const double z = r * r;
  const double sin_r = r * detail::sin_ratio_of_square(z);
  const double cos_r = detail::cos_of_square(z);
  // The low bits of shifted's mantissa are k's (two's complement; no int64 conversion, which
  // AVX2 lacks): odd k swaps sin and cos; sin is negative in quadrants 2 and 3, cos in 1 and 2.
  std::uint64_t bits;
  std::memcpy(&bits, &shifted, sizeof bits);
  const bool swap = (bits & 1u) != 0, sin_negative = (bits & 2u) != 0, cos_negative = ((bits + 1u) & 2u) != 0;
  const double s = swap ? cos_r : sin_r, c = swap ? sin_r : cos_r;
  sin_x = sin_negative ? -s : s;
  cos_x = cos_negative ? -c : c;
}

}    // namespace lubricated

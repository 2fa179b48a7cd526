// sin and cos without branches or calls, so that loops over pairs that need them can be
// vectorised by the compiler (std::sin and std::cos are calls): the steps where a contact starts
// or ends (contact_step.h, event_acceleration_inline). In scalar code libm's are faster.
#pragma once

#include <cstdint>
#include <cstring>

namespace lubricated {

namespace detail {

// sin(r) / r = 1 - z/(2 3) (1 - z/(4 5) (...)) and cos(r) = 1 - z/(1 2) (1 - z/(3 4) (...)),
// z = r^2, N the first factor's index, unrolled at compile time.
template <int N, int LAST> __attribute__((always_inline)) inline double alternating_series(double z)
{
  if constexpr (N > LAST)
    return 1.0;
  else
    return 1.0 - z * (1.0 / (N * (N + 1))) * alternating_series<N + 2, LAST>(z);
}

}    // namespace detail

// sin(x) and cos(x) within a few units in the last place of libm's for |x| < 1e5 (the angles of
// an oscillator over a step are below pi): x = k pi/2 + r, |r| <= pi/4, with pi/2 in three parts
// (the first two with 33 significant bits, so k times them is exact), sin(r) to r^17 and cos(r) to
// r^18 by their series (the next terms are below 1e-19), then the quadrant k mod 4 picks and signs them.
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
  const double sin_r = r * detail::alternating_series<2, 16>(z);
  const double cos_r = detail::alternating_series<1, 17>(z);
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

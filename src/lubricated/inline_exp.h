// exp(x) and 1 - exp(-x) without branches or calls, so that loops over pairs that need them can
// be vectorised by the compiler (std::exp and std::expm1 are calls): the shear film of pairs
// that stay apart over a step (tangential.h) and contacts that leave the overlap within a step
// (normal_model.h, overlap_exit_force). In scalar code libm's are faster (a series is a chain
// of dependent operations there).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "lubricated/polynomial.h"

namespace lubricated {

namespace detail {

// exp(r) for |r| <= ln 2 / 2: its minimax polynomial of degree 11 (relative error 3.1e-18,
// tools/series_minimax.py exp), one multiply-add per degree.
__attribute__((always_inline)) inline double exp_of_reduced(double r)
{
  static constexpr double coefficients[] = {1.0,
                                            1.0,
                                            0.5000000000000018,
                                            0.1666666666666617,
                                            0.04166666666649277,
                                            0.00833333333355927,
                                            0.0013888888951223987,
                                            0.00019841269432679237,
                                            2.4801486521427463e-05,
                                            2.7557622530872255e-06,
                                            2.7632293279459877e-07,
                                            2.4994304884817207e-08};
  return horner(r, coefficients);
}

// (exp(r) - 1) / r for |r| <= ln 2 / 2: its minimax polynomial of degree 11 (relative error
// 2.4e-19, tools/series_minimax.py expm1).
__attribute__((always_inline)) inline double expm1_ratio_of_reduced(double r)
{
  static constexpr double coefficients[] = {1.0,
                                            0.5,
                                            0.1666666666666668,
                                            0.04166666666666649,
                                            0.0083333333333197,
                                            0.0013888888888965133,
                                            0.00019841269889815148,
                                            2.4801587172494723e-05,
                                            2.7557241139410014e-06,
                                            2.755739989100927e-07,
                                            2.510996403418814e-08,
                                            2.087675039218933e-09};
  return horner(r, coefficients);
}

// 2^k for an integral k with k + 1023 in [1, 2046], from the bits of k + 1023 moved into the
// exponent field: the mantissa of 2^52 + n holds n (no int64 conversion, which AVX2 lacks).
__attribute__((always_inline)) inline double power_of_two(double k)
{
  const double biased = k + (4503599627370496.0 + 1023.0);
  std::uint64_t bits;
  std::memcpy(&bits, &biased, sizeof bits);
  const std::uint64_t scale_bits = (bits & 0x7FFull) << 52;
  double scale;
  std::memcpy(&scale, &scale_bits, sizeof scale);
  return scale;
}

// y = k ln 2 + r with k integral and |r| <= ln 2 / 2 (ln 2 in two parts: r exact to rounding).
__attribute__((always_inline)) inline void reduce_by_ln2(double y, double &k, double &r)
{
  constexpr double inv_ln2 = 1.44269504088896338700e+00;
  constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  constexpr double round_magic = 6755399441055744.0;    // 1.5 2^52: adding it rounds to an integer
  k = (y * inv_ln2 + round_magic) - round_magic;
  r = (y - k * ln2_hi) - k * ln2_lo;
}

}    // namespace detail

// exp(x) within a few units in the last place of std::exp, x clamped to [-708, 709] (beyond,
// std::exp is below 3e-308 or overflows): x = k ln 2 + r, |r| <= ln 2 / 2, and exp(r) by its
// minimax polynomial (exp_of_reduced).
__attribute__((always_inline)) inline double exp_inline(double x)
{
  double k, r;
  detail::reduce_by_ln2(std::min(std::max(x, -708.0), 709.0), k, r);
  return detail::power_of_two(k) * detail::exp_of_reduced(r);
}

// 1 - exp(-x) for x >= 0, within a few units in the last place of -std::expm1(-x), by one
// polynomial for every x (no second form selected): -x = k ln 2 + r, |r| <= ln 2 / 2, exp(r) - 1 =
// r expm1_ratio_of_reduced(r), and
// 1 - exp(-x) = (1 - 2^k) - 2^k (exp(r) - 1): for x below ln 2 / 2 (k = 0, r = -x exactly) the
// series alone, no cancellation; above, a sum in [0.29, 1). x clamped at 708 (1 there).
__attribute__((always_inline)) inline double one_minus_exp_neg_inline(double x)
{
  double k, r;
  detail::reduce_by_ln2(-std::min(x, 708.0), k, r);
  const double exp_r_minus_1 = r * detail::expm1_ratio_of_reduced(r);
  const double scale = detail::power_of_two(k);    // k in [-1022, 0] here
  return (1.0 - scale) - scale * exp_r_minus_1;
}

}    // namespace lubricated

// Natural logarithm without branches or calls, so that loops over pairs that need it can be
// vectorised by the compiler (std::log is a call; glibc's vector variants need -ffast-math).
// Used by the film of pairs that stay apart over a step (lubrication.h, film_integral_change_inline).
#pragma once

#include <cstdint>
#include <cstring>

#include "lubricated/polynomial.h"

namespace lubricated {

namespace detail {

// x = 2^k m with m in [sqrt(1/2), sqrt(2)), for a positive normal double x (not 0, denormal, inf
// or NaN); k as a double.
__attribute__((always_inline)) inline void split_for_log(double x, double &k, double &m)
{
  constexpr std::uint64_t sqrt_half_bits = 0x3FE6A09E667F3BCDull;    // sqrt(1/2)
  constexpr std::uint64_t exponent_bias = 0x3FFull << 52;
  constexpr std::uint64_t exponent_mask = 0xFFFull << 52;
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  // Biased k in the exponent field of t (k + 1023 in [1, 2046] for normal x), read back as a
  // double without an int64 conversion (which AVX2 lacks): 2^52 + n has n as its mantissa.
  const std::uint64_t t = bits - sqrt_half_bits + exponent_bias;
  const std::uint64_t biased_k = t >> 52;
  const std::uint64_t k_as_mantissa = 0x4330000000000000ull | biased_k;
  std::memcpy(&k, &k_as_mantissa, sizeof k);
  k -= 4503599627370496.0 + 1023.0;
  const std::uint64_t m_bits = bits - (t & exponent_mask) + exponent_bias;
  std::memcpy(&m, &m_bits, sizeof m);
}

// k ln 2 + 2 atanh(s), s = (m - 1) / (m + 1), |s| < 0.1716: atanh(s) / s = 1 + z / 3 + z^2 / 5 + ...
// (z = s^2 < 0.02944) by its minimax polynomial of degree 7 in z on that range (Remez, relative
// error 1.1e-18, tools/series_minimax.py atanh; the Taylor series needs degree 10 for as much:
// three multiply-adds more).
__attribute__((always_inline)) inline double log_of_split(double k, double s)
{
  const double z = s * s;
  static constexpr double coefficients[] = {1.0,
                                            0.33333333333333826,
                                            0.1999999999964944,
                                            0.1428571438067352,
                                            0.11111098494107967,
                                            0.09091817547819114,
                                            0.07656221863236867,
                                            0.07405265044557953};
  const double series = horner(z, coefficients);
  constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  return k * ln2_hi + (k * ln2_lo + 2.0 * s * series);
}

}    // namespace detail

// ln x for a positive normal double x (not 0, denormal, inf or NaN). x = 2^k m with m in
// [sqrt(1/2), sqrt(2)): ln x = k ln 2 + 2 atanh(s), s = (m - 1) / (m + 1): within a few units in
// the last place of std::log.
__attribute__((always_inline)) inline double log_inline(double x)
{
  double k, m;
  detail::split_for_log(x, k, m);
  return detail::log_of_split(k, (m - 1.0) / (m + 1.0));
}

// ln a and ln b (as log_inline) with one division: the two s over a common denominator (its
// factors in [1.7, 2.5]: a few more roundings, not a loss of precision).
__attribute__((always_inline)) inline void log_inline(double a, double b, double &ln_a, double &ln_b)
{
  double ka, ma, kb, mb;
  detail::split_for_log(a, ka, ma);
  detail::split_for_log(b, kb, mb);
  const double pa = ma + 1.0, pb = mb + 1.0, q = 1.0 / (pa * pb);
  ln_a = detail::log_of_split(ka, (ma - 1.0) * pb * q);
  ln_b = detail::log_of_split(kb, (mb - 1.0) * pa * q);
}

// ln a, ln b and ln c, as above, with one division.
__attribute__((always_inline)) inline void log_inline(double a, double b, double c, double &ln_a, double &ln_b,
                                                      double &ln_c)
{
  double ka, ma, kb, mb, kc, mc;
  detail::split_for_log(a, ka, ma);
  detail::split_for_log(b, kb, mb);
  detail::split_for_log(c, kc, mc);
  const double pa = ma + 1.0, pb = mb + 1.0, pc = mc + 1.0, q = 1.0 / (pa * pb * pc);
  ln_a = detail::log_of_split(ka, (ma - 1.0) * (pb * pc) * q);
  ln_b = detail::log_of_split(kb, (mb - 1.0) * (pa * pc) * q);
  ln_c = detail::log_of_split(kc, (mc - 1.0) * (pa * pb) * q);
}

}    // namespace lubricated

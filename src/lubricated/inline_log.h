// Natural logarithm without branches or calls, so that loops over pairs that need it can be
// vectorised by the compiler (std::log is a call; glibc's vector variants need -ffast-math).
// Used by the film of pairs that stay apart over a step (lubrication.h, film_integral_inline).
#pragma once

#include <cstdint>
#include <cstring>

namespace lubricated {

// ln x for a positive normal double x (not 0, denormal, inf or NaN). x = 2^k m with m in
// [sqrt(1/2), sqrt(2)): ln x = k ln 2 + 2 atanh(s), s = (m - 1) / (m + 1), |s| < 0.1716,
// atanh by its odd series to s^21 (the next term is below 1e-18 of the sum): within a few
// units in the last place of std::log.
__attribute__((always_inline)) inline double log_inline(double x)
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
  double k;
  std::memcpy(&k, &k_as_mantissa, sizeof k);
  k -= 4503599627370496.0 + 1023.0;
  const std::uint64_t m_bits = bits - (t & exponent_mask) + exponent_bias;
  double m;
  std::memcpy(&m, &m_bits, sizeof m);
  const double s = (m - 1.0) / (m + 1.0), z = s * s;
  const double series =
      1.0 +
      z * (1.0 / 3 +
           z * (1.0 / 5 +
                z * (1.0 / 7 +
                     z * (1.0 / 9 +
                          z * (1.0 / 11 +
                               z * (1.0 / 13 + z * (1.0 / 15 + z * (1.0 / 17 + z * (1.0 / 19 + z * (1.0 / 21))))))))));
  constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  return k * ln2_hi + (k * ln2_lo + 2.0 * s * series);
}

}    // namespace lubricated

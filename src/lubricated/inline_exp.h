// 1 - exp(-x) without branches or calls, so that loops over pairs that need it can be
// vectorised by the compiler (std::expm1 is a call). Used by the shear film of pairs that stay
// apart over a step (tangential.h, shear_film_factor).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace lubricated {

namespace detail {

// 1 + s x/N (1 + s x/(N+1) (... (1 + s x/LAST))), unrolled at compile time (s = +1 or -1).
template <int N, int LAST> __attribute__((always_inline)) inline double nested_series(double x)
{
  if constexpr (N > LAST)
    return 1.0;
  else
    return 1.0 + x * (1.0 / N) * nested_series<N + 1, LAST>(x);
}

}    // namespace detail

// 1 - exp(-x) for x >= 0, within a few units in the last place of -std::expm1(-x): up to 1/2
// by its alternating series x (1 - x/2 (1 - x/3 (...))) to x^17 (0.5^18/18! < 1e-21, no
// cancellation), above by 1 - 2^k P(r) with -x = k ln 2 + r, |r| <= ln 2 / 2 and P the
// exponential's series to r^13 (the next term is below 1e-17). Beyond x = 700 the exponential
// is below 1e-304: x is clamped there.
__attribute__((always_inline)) inline double one_minus_exp_neg_inline(double x)
{
  const double small = x * detail::nested_series<2, 17>(-x);
  const double y = -std::min(x, 700.0);
  constexpr double inv_ln2 = 1.44269504088896338700e+00;
  constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  constexpr double round_magic = 6755399441055744.0;    // 1.5 2^52: adding it rounds to an integer
  const double k = (y * inv_ln2 + round_magic) - round_magic;
  const double r = (y - k * ln2_hi) - k * ln2_lo;
  const double p = detail::nested_series<1, 13>(r);
  // 2^k from the bits of k + 1023 (k >= -1010 here) moved into the exponent field; the
  // mantissa of 2^52 + n holds n (no int64 conversion, which AVX2 lacks).
  const double biased = k + (4503599627370496.0 + 1023.0);
  std::uint64_t bits;
  std::memcpy(&bits, &biased, sizeof bits);
  const std::uint64_t scale_bits = (bits & 0x7FFull) << 52;
  double scale;
  std::memcpy(&scale, &scale_bits, sizeof scale);
  const double large = 1.0 - scale * p;
  return x <= 0.5 ? small : large;
}

}    // namespace lubricated

// Polynomials by Horner's rule for the inline elementary functions (inline_log.h, inline_exp.h,
// inline_sincos.h, inline_atan.h), whose coefficients tools/series_minimax.py computes.
#pragma once

#include <cstddef>

namespace lubricated {
namespace detail {

// c[0] + x (c[1] + x (c[2] + ... + x c[N - 1])): one multiply-add per degree, the nesting
// written out at compile time (no loop), so that loops calling it stay vectorised.
template <std::size_t K = 0, std::size_t N>
__attribute__((always_inline)) inline double horner(double x, const double (&c)[N])
{
  if constexpr (K + 1 == N)
    return c[K];
  else
    return c[K] + x * horner<K + 1>(x, c);
}

}    // namespace detail
}    // namespace lubricated

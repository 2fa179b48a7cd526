// The guess tables of the step-exact contact (contact_step.h): where within a step a contact
// starts or ends depends on the gap ratio and the steps per contact only, so tabulated guesses
// let Newton (falling_root) finish in one or two iterations. Their lookup, build and the cache
// that keeps them for the process.
#pragma once

#include "spring_dashpot.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <utility>

namespace lubricated {

// Intervals of each table (table_size + 1 values, over x = r / (1 + r) in [0, 1]).
constexpr int guess_table_size = 256;

namespace detail {

// Quadratic interpolation in a table of n + 1 values over share = ratio / (1 + ratio) in [0, 1],
// the table starting `skip` values (a whole number) after `table`. The index k = min(floor(x),
// n - 2) from the bits of k + 2^52 (as exp_inline's 2^k): a 64-bit index, with which GCC 12
// vectorises loops over doubles, and one base pointer with an offset where a loop picks one of
// two tables per lane (two gathers from two pointers stop it).
__attribute__((always_inline)) inline double table_lookup_share(const double *table, int n, double share,
                                                                double skip = 0.0)
{
  constexpr double round_magic = 4503599627370496.0;    // 2^52: adding it rounds x >= 0 to an integer
  const double x = share * n;
  const double nearest = (x + round_magic) - round_magic;
  const double k = std::min(nearest > x ? nearest - 1.0 : nearest, n - 2.0);
  const double biased = k + skip + round_magic;
  std::uint64_t bits;
  std::memcpy(&bits, &biased, sizeof bits);
  const std::uint64_t at = bits & 0xFFFFFFFFull;
  const double t = x - k, f0 = table[at], f1 = table[at + 1], f2 = table[at + 2];
  return f0 + t * (f1 - f0) + 0.5 * t * (t - 1.0) * (f2 - 2.0 * f1 + f0);
}
inline double table_lookup(const double *table, int n, double ratio)
{
  return table_lookup_share(table, n, ratio / (1.0 + ratio));    // ratio in [0, inf) -> [0, 1)
}

// Root of f on [lo, hi], where the caller guarantees f(lo) > 0 >= f(hi), by Newton's method
// from guess, kept inside the shrinking bracket (bisection when a step leaves it).
// fdf(x, df) returns f and sets f'. Newton converges quadratically, so once a step is below
// 1e-7 of the bracket the stepped point is the root to ~1e-14; evaluated_at is the last point
// fdf saw (callers that reuse fdf's side values correct them to first order).
template <class F> double falling_root(F fdf, double lo, double hi, double guess, double &evaluated_at)
{
  double df = 0.0;
  double x = std::min(std::max(guess, lo), hi);
  const double tolerance = 1e-7 * (hi - lo);
  for (int it = 0; it < 60; ++it) {
    const double fx = fdf(x, df);
    evaluated_at = x;
    if (fx == 0.0) return x;
    (fx > 0.0 ? lo : hi) = x;
    const double step = fx / df;
    double next = x - step;
    if (std::fabs(step) <= tolerance && next >= lo && next <= hi) return next;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    x = next;
  }
  return x;
}

}    // namespace detail

// Steps per contact by which guess tables may be off before others are taken (make_contact_step).
constexpr double table_tolerance = 0.05;

namespace detail {

// The guess tables (in units of dt) of an oscillator with e = restitution that lasts `steps`
// steps (a dt = -ln(e) / steps, omega dt = pi / steps), by bisection: 2 x 257 x `iterations`
// evaluations of exp and sin (40 leave a guess within 1e-12 of its root).
inline void build_guess_tables(double restitution, double steps, double *exit_guess, double *entry_guess,
                               int iterations = 100)
{
  const double a = restitution > 0.0 ? -std::log(restitution) / steps : 0.0, w = pi / steps;
  for (int k = 0; k <= guess_table_size; ++k) {
    const double x = static_cast<double>(k) / guess_table_size;
    const double r = x < 1.0 ? x / (1.0 - x) : 1e300;
    double lo = 0.0, hi = 1.0, lo2 = 0.0, hi2 = 1.0;
    for (int it = 0; it < iterations; ++it) {
      const double m = 0.5 * (lo + hi), m2 = 0.5 * (lo2 + hi2);
      // exit: exp(-a s) w (1 - s) - r sin(w s), falling from > 0 at s = 0
      (std::exp(-a * m) * w * (1.0 - m) - r * std::sin(w * m) > 0.0 ? lo : hi) = m;
      // entry: exp(-a s) sin(w s) / w - r (1 - s), rising from < 0 at s = 0
      (std::exp(-a * m2) * std::sin(w * m2) / w - r * (1.0 - m2) < 0.0 ? lo2 : hi2) = m2;
    }
    exit_guess[k] = 0.5 * (lo + hi);
    entry_guess[k] = 0.5 * (lo2 + hi2);
  }
}

// The tables of an oscillator (e, steps), built once and kept for the process (a few kB each):
// exactly for the steps per contact of a run's set-up; for a time step changed within a run
// (adaptive time stepping, which may change it at every step) for the band of steps per contact
// (table_tolerance wide, on a logarithmic scale) it falls in.
struct GuessTables {
  static constexpr int size = guess_table_size + 1;
  double steps;
  double guess[2 * size];    // exit guesses, then entry guesses
};

inline const GuessTables &guess_tables(double restitution, double steps, bool banded)
{
  static std::map<std::pair<double, double>, GuessTables> cache;
  if (banded) {
    const double band = std::log1p(table_tolerance);
    steps = std::exp(std::lround(std::log(steps) / band) * band);
  }
  auto found = cache.find({restitution, steps});
  if (found != cache.end()) return found->second;
  GuessTables &t = cache[{restitution, steps}];
  t.steps = steps;
  build_guess_tables(restitution, steps, t.guess, t.guess + GuessTables::size, banded ? 40 : 100);
  return t;
}

}    // namespace detail

}    // namespace lubricated

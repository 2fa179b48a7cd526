"""The polynomial coefficients of the inline elementary functions (src/lubricated/inline_log.h,
inline_exp.h, inline_sincos.h, inline_atan.h): minimax polynomials, relative error, by the Remez exchange algorithm in 60-digit
arithmetic; prints them rounded to doubles and the largest relative error. Needs mpmath
(Debian: python3-mpmath).

    python3 tools/series_minimax.py FUNCTION [--degree N]

  atanh  atanh(s) / s in z = s^2 on 0 <= z <= ((sqrt 2 - 1) / (sqrt 2 + 1))^2 = 0.02944 (|s| <
         0.1716, the range log_inline's split leaves); degree 7 (log_of_split)
  exp    exp(r) on |r| <= ln 2 / 2 (the range reduce_by_ln2 leaves); degree 11 (exp_inline)
  expm1  (exp(r) - 1) / r on |r| <= ln 2 / 2; degree 11 (one_minus_exp_neg_inline)
  sin    sin(r) / r in z = r^2 on 0 <= z <= (pi / 4)^2 (sincos_inline's range); degree 6
  cos    cos(r) in z = r^2 on the same range; degree 7
  atan   atan(u) / u in z = u^2 on 0 <= z <= tan(pi / 8)^2 (atan2_nonnegative_inline's range);
         degree 11
"""
import argparse

import mpmath as mp

mp.mp.dps = 60
GRID = 4000


def atanh_ratio(z):
    """atanh(s) / s with s = sqrt(z) (1 at z = 0)."""
    if z == 0:
        return mp.mpf(1)
    s = mp.sqrt(z)
    return mp.atanh(s) / s


def expm1_ratio(r):
    return mp.mpf(1) if r == 0 else mp.expm1(r) / r


def in_square(f):
    """g(z) = f(sqrt(z)) (f even in its argument, f(0) = its limit)."""
    return lambda z: f(mp.sqrt(z))


def sin_ratio(r):
    return mp.mpf(1) if r == 0 else mp.sin(r) / r


def atan_ratio(u):
    return mp.mpf(1) if u == 0 else mp.atan(u) / u


HALF_LN2 = mp.log(2) / 2
# name -> (function, interval, default degree)
FUNCTIONS = {"atanh": (atanh_ratio, (mp.mpf(0), ((mp.sqrt(2) - 1) / (mp.sqrt(2) + 1)) ** 2), 7),
             "exp": (mp.exp, (-HALF_LN2, HALF_LN2), 11),
             "expm1": (expm1_ratio, (-HALF_LN2, HALF_LN2), 11),
             "sin": (in_square(sin_ratio), (mp.mpf(0), (mp.pi / 4) ** 2), 6),
             "cos": (in_square(mp.cos), (mp.mpf(0), (mp.pi / 4) ** 2), 7),
             "atan": (in_square(atan_ratio), (mp.mpf(0), mp.tan(mp.pi / 8) ** 2), 11)}


def remez(f, interval, degree, rounds=30):
    """Coefficients c_0 ... c_degree and the largest relative error |p(x) / f(x) - 1| on a grid."""
    low, high = interval
    n = degree + 2
    nodes = [low + (high - low) / 2 * (1 - mp.cos(mp.pi * k / (n - 1))) for k in range(n)]
    grid = [low + (high - low) * mp.mpf(i) / GRID for i in range(GRID + 1)]
    for _ in range(rounds):
        # p(x_k) + (-1)^k E f(x_k) = f(x_k) at the reference nodes (E: the relative error)
        a, b = mp.matrix(n, n), mp.matrix(n, 1)
        for k, x in enumerate(nodes):
            for j in range(degree + 1):
                a[k, j] = x ** j
            a[k, degree + 1] = (-1) ** k * f(x)
            b[k] = f(x)
        solution = mp.lu_solve(a, b)
        coefficients = [solution[j] for j in range(degree + 1)]
        errors = [mp.polyval(coefficients[::-1], x) / f(x) - 1 for x in grid]
        # the new reference: the extrema of the error, alternating in sign, the largest kept
        extrema = [0] + [i for i in range(1, GRID) if (errors[i] - errors[i - 1]) * (errors[i + 1] - errors[i]) <= 0]
        extrema.append(GRID)
        alternating = []
        for i in extrema:
            if alternating and mp.sign(errors[i]) == mp.sign(errors[alternating[-1]]):
                if abs(errors[i]) > abs(errors[alternating[-1]]):
                    alternating[-1] = i
            else:
                alternating.append(i)
        if len(alternating) < n:
            break
        while len(alternating) > n:
            alternating.pop(0 if abs(errors[alternating[0]]) < abs(errors[alternating[-1]]) else -1)
        nodes = [grid[i] for i in alternating]
    return coefficients, max(abs(e) for e in errors)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("function", choices=sorted(FUNCTIONS))
    parser.add_argument("--degree", type=int, default=None)
    args = parser.parse_args()
    f, interval, degree = FUNCTIONS[args.function]
    degree = args.degree or degree
    coefficients, error = remez(f, interval, degree)
    print(f"{args.function}, degree {degree} on [{mp.nstr(interval[0], 6)}, {mp.nstr(interval[1], 6)}]: "
          f"largest relative error {mp.nstr(error, 3)}")
    for j, c in enumerate(coefficients):
        print(f"c{j} = {float(c)!r}")


if __name__ == "__main__":
    main()

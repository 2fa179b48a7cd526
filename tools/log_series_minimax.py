"""The coefficients of src/lubricated/inline_log.h (log_of_split): the minimax polynomial of
degree 7 in z = s^2 for atanh(s) / s on 0 <= z <= ((sqrt 2 - 1) / (sqrt 2 + 1))^2 = 0.02944
(|s| < 0.1716, the range log_inline's split leaves), by the Remez exchange algorithm in 60-digit
arithmetic; prints them rounded to doubles and the largest error. Needs mpmath (Debian:
python3-mpmath).

    python3 tools/log_series_minimax.py [--degree 7]
"""
import argparse

import mpmath as mp

mp.mp.dps = 60
Z_MAX = ((mp.sqrt(2) - 1) / (mp.sqrt(2) + 1)) ** 2
GRID = 4000


def atanh_ratio(z):
    """atanh(s) / s with s = sqrt(z) (1 at z = 0)."""
    if z == 0:
        return mp.mpf(1)
    s = mp.sqrt(z)
    return mp.atanh(s) / s


def remez(degree, rounds=30):
    """Coefficients c_0 ... c_degree and the largest error |p(z) - atanh_ratio(z)| on the grid
    (the function is about 1 there: absolute and relative error agree)."""
    n = degree + 2
    nodes = [Z_MAX / 2 * (1 - mp.cos(mp.pi * k / (n - 1))) for k in range(n)]
    grid = [Z_MAX * mp.mpf(i) / GRID for i in range(GRID + 1)]
    for _ in range(rounds):
        # p(z_k) + (-1)^k E = f(z_k) at the reference nodes
        a, b = mp.matrix(n, n), mp.matrix(n, 1)
        for k, z in enumerate(nodes):
            for j in range(degree + 1):
                a[k, j] = z ** j
            a[k, degree + 1] = (-1) ** k
            b[k] = atanh_ratio(z)
        solution = mp.lu_solve(a, b)
        coefficients = [solution[j] for j in range(degree + 1)]
        errors = [mp.polyval(coefficients[::-1], z) - atanh_ratio(z) for z in grid]
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
    parser.add_argument("--degree", type=int, default=7)
    args = parser.parse_args()
    coefficients, error = remez(args.degree)
    print(f"degree {args.degree} on [0, {mp.nstr(Z_MAX, 6)}]: largest error {mp.nstr(error, 3)}")
    for j, c in enumerate(coefficients):
        print(f"c{j} = {float(c)!r}")


if __name__ == "__main__":
    main()

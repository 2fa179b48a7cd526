"""Closed forms of the Maxey-Riley-Gatignol equation for one sphere in Stokes flow, for the
tests of fix fluid/drag's fluid inertia and memory (doc/fix_fluid_drag.rst).

Sphere released from rest in a fluid at rest under a constant force F (its buoyant weight):

    M dv/dt = F - beta v - K int_0^t v'(tau) / sqrt(t - tau) dtau,
    M = m + C_m rho_f V,  beta = 3 pi mu d,  K = (3/2) d^2 sqrt(pi rho_f mu).

Laplace transform (v(0) = 0): V(s) = F / (s (M s + K sqrt(pi) sqrt(s) + beta)). With p =
sqrt(s) the bracket is M (p - p1)(p - p2), and 1 / (s (p - a)) inverts to
(exp(a^2 t) erfc(-a sqrt t) - 1) / a, so

    v(t) = F / (M (p1 - p2)) [ (E(p1) - 1) / p1 - (E(p2) - 1) / p2 ],  E(a) = exp(a^2 t) erfc(-a sqrt t),

the classic erfc-exp solution of Basset's problem (Basset 1888; e.g. Clift, Grace & Weber,
Bubbles, Drops and Particles (1978), ch. 11; Michaelides, J. Fluids Eng. 119, 233 (1997)).
p1, p2 are complex conjugates for rho_p / rho_f > 5/8 (C_m = 1/2): the helper below evaluates
exp(z^2) erfc(z) for complex z (Taylor series of erf near 0, Laplace's continued fraction
further out, both to ~1e-12).
"""
import cmath
import math


def exp_erfc(z):
    """exp(z^2) erfc(z) for complex z with Re z >= 0."""
    z = complex(z)
    if abs(z) < 3.0:
        term, total, n = z, z, 0
        while abs(term) > 1e-17 * max(1.0, abs(total)) or n < 5:
            n += 1
            term *= -z * z / n
            total += term / (2 * n + 1)
        return cmath.exp(z * z) * (1.0 - 2.0 / math.sqrt(math.pi) * total)
    fraction = z
    for k in range(120, 0, -1):
        fraction = z + (k / 2.0) / fraction
    return 1.0 / (math.sqrt(math.pi) * fraction)


def released_from_rest(t, force, mass, beta, basset):
    """v(t) of M v' = F - beta v - K int v'/sqrt(t - tau) dtau (mass = M, basset = K), v(0) = 0."""
    b = basset * math.sqrt(math.pi)
    disc = cmath.sqrt(b * b - 4 * mass * beta)
    p1, p2 = (-b + disc) / (2 * mass), (-b - disc) / (2 * mass)
    if t <= 0.0:
        return 0.0
    root = math.sqrt(t)
    e1, e2 = exp_erfc(-p1 * root), exp_erfc(-p2 * root)
    return (force / (mass * (p1 - p2)) * ((e1 - 1) / p1 - (e2 - 1) / p2)).real


def without_history(t, force, mass, beta):
    return force / beta * (1.0 - math.exp(-beta * t / mass))

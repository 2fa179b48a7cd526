"""Reference solutions for the tangential contact (src/lubricated/tangential.h).

A sphere (m, I = 2/5 m R^2) hits a plane wall with normal speed U and slip speed s0 = psi U.
Normal: the linear spring-dashpot's closed form, overlap x(t) = (U/w) exp(-a t) sin(w t),
w = pi / t_c, a = -ln(e_d) / t_c, force F_n = m x''... = k x + c x'.
Tangential: m_t s' = F_t, F_t = -k_t d - eta_t s capped at mu |F_n| (sliding resets the
spring to the capped force), k_t = m_t (w^2 + a_t^2), eta_t = 2 m_t a_t, m_t = 2/7 m.
Units U = 1, t_c = 1, m = 1. The ODE is integrated with a fine symmetric splitting (error
about 1e-4 of s0 at 40000 sub-steps, checked by halving), independent of the plugin.
"""
import math

import numpy as np


def slip_ratio(e_n, e_t, mu, psi, n_sub=40000):
    """Rebound slip over impact slip, s'/s0, for each psi (an array)."""
    w = math.pi
    a_n = -math.log(e_n)
    m_t = 2.0 / 7.0
    a_t = -math.log(e_t)
    k_t, eta_t = m_t * (w * w + a_t * a_t), 2.0 * m_t * a_t
    k_n, c_n = w * w + a_n * a_n, 2.0 * a_n
    s0 = np.atleast_1d(np.asarray(psi, float))
    s, d = s0.copy(), np.zeros_like(s0)
    h = 1.0 / n_sub
    for k in range(n_sub):
        t = (k + 0.5) * h
        decay = math.exp(-a_n * t)
        x = decay * math.sin(w * t) / w
        xdot = decay * (math.cos(w * t) - a_n / w * math.sin(w * t))
        limit = mu * abs(k_n * x + c_n * xdot)
        d = d + 0.5 * h * s
        f = -k_t * d - eta_t * s
        sliding = np.abs(f) > limit
        f = np.where(sliding, np.sign(f) * limit, f)
        s = s + h * f / m_t
        d = d + 0.5 * h * s
        d = np.where(sliding, -(f + eta_t * s) / k_t, d)
    return s / s0


def normal_impulse_magnitude(e_n, n=200000):
    """Integral of |F_n| dt over the contact, in units of m U (> 1 + e_n: the dashpot pulls
    at the end of the contact)."""
    w, a = math.pi, -math.log(e_n)
    t = (np.arange(n) + 0.5) / n
    decay = np.exp(-a * t)
    x = decay * np.sin(w * t) / w
    xdot = decay * (np.cos(w * t) - a / w * np.sin(w * t))
    return float(np.sum(np.abs((w * w + a * a) * x + 2.0 * a * xdot)) / n)

"""The pole of an undamped harmonic response near a natural frequency, shared by the
frequency-domain tests (tests/test_harmonic_closed_forms.py, tests/test_frequency_3d.py).

:func:`secant_pole`: the zero of g(omega^2) = 1 / Q(omega^2) by the secant method from
omega_n^2 (1 -+ 1e-3), Q a real response amplitude (undamped, real drive) that blows up
at the pole; converged when a step moves omega^2 by less than 1e-13 of omega_n^2.
"""

from __future__ import annotations

import math


def secant_pole(g, omega_n: float, what: str) -> float:
    """The pole [rad/s] of the response whose reciprocal is ``g(omega^2)``, near the
    natural frequency ``omega_n`` [rad/s]; AssertionError naming ``what`` when 20 secant
    steps do not converge."""
    lam0 = omega_n ** 2
    a, b = lam0 * (1.0 - 1e-3), lam0 * (1.0 + 1e-3)
    ga, gb = g(a), g(b)
    for _ in range(20):
        c = b - gb * (b - a) / (gb - ga)
        if abs(c - b) < 1e-13 * lam0:
            return math.sqrt(c)
        a, ga = b, gb
        b, gb = c, g(c)
    raise AssertionError(f"no pole found near {what}")

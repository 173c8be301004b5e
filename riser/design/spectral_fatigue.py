"""Fatigue damage of a stationary Gaussian stress process from its spectrum (frequency
domain): the narrow-band (Rayleigh) damage and Dirlik's (1985) broad-band estimate,
against a DNV-RP-C203 S-N curve (:mod:`riser.design.sn_curves`).

Conventions:

- the spectrum ``S`` is one-sided, in circular frequency: S(omega) [Pa^2 s/rad] on
  ``omega`` [rad/s], the variance m0 = integral of S d omega [Pa^2];
- spectral moments m_n = integral omega^n S d omega [Pa^2 (rad/s)^n] by the trapezoidal
  rule on ``omega``; or, when ``d_omega`` is given (a list of equally spaced wave
  components, each standing for a band d_omega wide), the sum m_n = sum omega^n S d_omega;
- rates in Hz (1/s): the mean zero up-crossing rate nu0 = sqrt(m2/m0) / (2 pi), the rate
  of peaks (maxima) nu_p = sqrt(m4/m2) / (2 pi), the irregularity factor
  gamma = nu0 / nu_p = m2 / sqrt(m0 m4) (1 for a narrow band);
- stress ranges R are peak-to-valley (twice the amplitude), in Pa;
- damage rates are Miner sums per second [1/s]: rate x integral of p(R) / N(R) dR, with
  p the density of the ranges and N the curve's cycles (its thickness correction and
  stress concentration included), integrated by the trapezoidal rule on a fine grid in R
  (the slope change of a two-slope curve is a node of the grid).
"""

from __future__ import annotations

import math

import numpy as np

from .sn_curves import MPA, SNCurve

#: intervals of the grid in the stress range
GRID_INTERVALS = 8000
#: the grid's end for the Gaussian (Rayleigh) parts of the range densities, in units of
#: their scale: exp(-z^2/2) z^6 < 1e-14 beyond it, negligible against any m <= 5 moment
GAUSSIAN_REACH = 10.0
#: the grid's end for Dirlik's exponential part, in units of its scale Q: the tail of
#: z^5 exp(-z/Q) beyond 60 Q is < 1e-17 of its integral
EXPONENTIAL_REACH = 60.0


def spectral_moments(omega, S, d_omega: float | None = None) -> dict[str, float]:
    """m0, m1, m2, m4 of the one-sided spectrum ``S`` [Pa^2 s/rad] on ``omega`` [rad/s].

    Trapezoidal rule on ``omega``, or, when ``d_omega`` [rad/s] is given, the sum
    omega^n S d_omega over the components. Units: m_n in Pa^2 (rad/s)^n.
    """
    w = np.asarray(omega, dtype=float)
    s = np.asarray(S, dtype=float)
    if w.shape != s.shape or w.ndim != 1:
        raise ValueError(f"omega {w.shape} and S {s.shape} must be equal 1-D arrays")
    if np.any(s < 0.0) or np.any(w < 0.0):
        raise ValueError("a one-sided spectrum has omega >= 0 and S >= 0")
    out = {}
    for n in (0, 1, 2, 4):
        f = w ** n * s
        out[f"m{n}"] = float(np.sum(f) * d_omega if d_omega is not None
                             else np.trapezoid(f, w))
    return out


def rates(moments: dict[str, float]) -> dict[str, float]:
    """nu0 (mean zero up-crossing rate [1/s]), nu_p (rate of peaks [1/s]) and the
    irregularity factor gamma = nu0 / nu_p of the moments of :func:`spectral_moments`."""
    m0, m2, m4 = moments["m0"], moments["m2"], moments["m4"]
    nu0 = math.sqrt(m2 / m0) / (2.0 * math.pi)
    nu_p = math.sqrt(m4 / m2) / (2.0 * math.pi)
    return {"nu0": nu0, "nu_p": nu_p, "gamma": nu0 / nu_p}


def rayleigh_range_density(R, m0: float) -> np.ndarray:
    """Density of the stress ranges of a narrow-band Gaussian process of variance ``m0``
    [Pa^2]: the ranges are twice the Rayleigh amplitudes,
    p(R) = R / (4 m0) exp(-R^2 / (8 m0)) [1/Pa], R [Pa]."""
    R = np.asarray(R, dtype=float)
    return R / (4.0 * m0) * np.exp(-R ** 2 / (8.0 * m0))


#: |1 - gamma - D1 + D1^2| at or below this is a line spectrum (Dirlik's 0/0: Rayleigh)
NARROW_BAND_LIMIT = 1e-12


def dirlik_coefficients(moments: dict[str, float]) -> dict[str, float]:
    """Dirlik's (1985) constants of his range density from the moments:

    x_m = m1/m0 sqrt(m2/m4), gamma = m2 / sqrt(m0 m4),
    D1 = 2 (x_m - gamma^2) / (1 + gamma^2),
    R = (gamma - x_m - D1^2) / (1 - gamma - D1 + D1^2),
    D2 = (1 - gamma - D1 + D1^2) / (1 - R), D3 = 1 - D1 - D2,
    Q = 1.25 (gamma - D3 - D2 R) / D1.

    D1 + D2 + D3 = 1. In the narrow-band limit (gamma -> 1) D1, D2 -> 0 and D3 -> 1 (the
    Rayleigh density); Q is then 0/0 and is returned as 0 with D1 = 0 (no exponential
    part); at a line spectrum (a single frequency, |1 - gamma - D1 + D1^2| <=
    :data:`NARROW_BAND_LIMIT`) R and D2 are 0/0 too and the Rayleigh constants are
    returned. R enters the density squared: it may come out negative for a broad spectrum
    with a long high-frequency tail (a Pierson-Moskowitz stress spectrum, say), and the
    density is the same as for |R|.
    """
    m0, m1, m2, m4 = (moments[k] for k in ("m0", "m1", "m2", "m4"))
    x_m = m1 / m0 * math.sqrt(m2 / m4)
    g = m2 / math.sqrt(m0 * m4)
    d1 = 2.0 * (x_m - g * g) / (1.0 + g * g)
    denominator = 1.0 - g - d1 + d1 * d1
    if abs(denominator) <= NARROW_BAND_LIMIT:
        # a line spectrum (one frequency: x_m = gamma = 1, D1 = 0) or within round-off of
        # it: Dirlik's density is the Rayleigh one (the constants are 0/0 there)
        return {"x_m": x_m, "gamma": g, "D1": 0.0, "D2": 0.0, "D3": 1.0, "R": 0.0, "Q": 0.0}
    r = (g - x_m - d1 * d1) / denominator
    d2 = (1.0 - g - d1 + d1 * d1) / (1.0 - r)
    d3 = 1.0 - d1 - d2
    q = 1.25 * (g - d3 - d2 * r) / d1 if d1 > 0.0 else 0.0
    return {"x_m": x_m, "gamma": g, "D1": d1, "D2": d2, "D3": d3, "R": r, "Q": q}


def dirlik_range_density(R, moments: dict[str, float]) -> np.ndarray:
    """Dirlik's density of the rainflow ranges R [Pa] [1/Pa]: with Z = R / (2 sqrt(m0)),

    p(R) = [D1/Q e^(-Z/Q) + D2 Z/R^2 e^(-Z^2/(2 R^2)) + D3 Z e^(-Z^2/2)] / (2 sqrt(m0)).

    A term whose weight or scale is zero (Q = 0 in the narrow-band limit) is left out;
    R enters squared (see :func:`dirlik_coefficients`).
    """
    c = dirlik_coefficients(moments)
    sig = math.sqrt(moments["m0"])
    z = np.asarray(R, dtype=float) / (2.0 * sig)
    p = c["D3"] * z * np.exp(-0.5 * z * z)
    if c["D1"] > 0.0 and c["Q"] > 0.0:
        p = p + c["D1"] / c["Q"] * np.exp(-z / c["Q"])
    if c["D2"] != 0.0 and c["R"] != 0.0:
        p = p + c["D2"] * z / c["R"] ** 2 * np.exp(-0.5 * (z / c["R"]) ** 2)
    return p / (2.0 * sig)


def _range_grid(reach: float, curve: SNCurve, thickness, scf: float) -> np.ndarray:
    """0 .. ``reach`` [Pa] in GRID_INTERVALS steps, with the nominal range at the curve's
    slope change (after the thickness factor and scf) added as a node."""
    grid = np.linspace(0.0, reach, GRID_INTERVALS + 1)
    if curve.two_slopes:
        kink = curve.switch_stress / (scf * curve.thickness_factor(thickness))
        if 0.0 < kink < reach:
            k = int(np.searchsorted(grid, kink))    # grid is sorted: insert, not re-sort
            if grid[k] != kink:                     # (np.unique's result, 10x faster)
                grid = np.insert(grid, k, kink)
    return grid


def _damage_integral(grid, density, curve, thickness, scf) -> float:
    """integral of density / N over the grid (trapezoid) [1/cycle]."""
    return float(np.trapezoid(density / curve.cycles(grid, thickness, scf), grid))


def narrow_band_damage_rate(omega, S, curve: SNCurve, thickness: float | None = None,
                            scf: float = 1.0, d_omega: float | None = None) -> float:
    """Narrow-band damage rate [1/s]: nu0 x integral of p(R) / N(R) dR with the Rayleigh
    range density (:func:`rayleigh_range_density`); ``omega`` [rad/s], ``S``
    [Pa^2 s/rad], ``d_omega`` as in :func:`spectral_moments`, ``thickness`` [m]."""
    mom = spectral_moments(omega, S, d_omega)
    reach = 2.0 * GAUSSIAN_REACH * math.sqrt(mom["m0"])
    grid = _range_grid(reach, curve, thickness, scf)
    p = rayleigh_range_density(grid, mom["m0"])
    return rates(mom)["nu0"] * _damage_integral(grid, p, curve, thickness, scf)


def dirlik_damage_rate(omega, S, curve: SNCurve, thickness: float | None = None,
                       scf: float = 1.0, d_omega: float | None = None) -> float:
    """Dirlik's damage rate [1/s]: nu_p x integral of p(R) / N(R) dR with Dirlik's range
    density (:func:`dirlik_range_density`), his cycles counted at the rate of peaks.
    Arguments as in :func:`narrow_band_damage_rate`."""
    mom = spectral_moments(omega, S, d_omega)
    c = dirlik_coefficients(mom)
    z_max = max(GAUSSIAN_REACH, GAUSSIAN_REACH * abs(c["R"]),
                EXPONENTIAL_REACH * max(c["Q"], 0.0))
    grid = _range_grid(2.0 * math.sqrt(mom["m0"]) * z_max, curve, thickness, scf)
    p = dirlik_range_density(grid, mom)
    return rates(mom)["nu_p"] * _damage_integral(grid, p, curve, thickness, scf)


def closed_form_narrow_band(m0: float, nu0: float, m: float, log_a: float) -> float:
    """The narrow-band damage rate [1/s] against a single-slope curve N = a S^-m:

    nu0 (2 sqrt(2 m0))^m Gamma(1 + m/2) / a,

    the mean of R^m over the Rayleigh ranges, times the cycle rate, over a. ``m0`` is the
    variance in Pa^2 (converted here to MPa^2, the unit of a's table), ``nu0`` in 1/s,
    ``log_a`` = log10 a with S in MPa. No thickness correction, scf = 1.
    """
    m0_mpa = m0 / MPA ** 2
    return nu0 * (2.0 * math.sqrt(2.0 * m0_mpa)) ** m * math.gamma(1.0 + m / 2.0) \
        / 10.0 ** log_a

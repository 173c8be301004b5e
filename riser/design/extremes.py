"""Extremes over a storm: the most probable maximum (MPM) of an irregular response, from a
time-domain record (:func:`storm_extreme`) and, for a Gaussian response given by its
standard deviation and zero-up-crossing period, by the Rayleigh distribution
(:func:`rayleigh_mpm`; the frequency domain's). Pure functions of arrays, SI units of the
record's quantity; no scene (``storm_duration`` of a scene: :func:`storm_duration`).

The method (docs/design.md, "Extremes over a storm"):

1. **Peaks.** The record x_i at times t_i; its mean m; an up-crossing of the mean is a
   sample pair x_i < m <= x_{i+1}. A peak is the largest sample between two successive
   up-crossings (samples i+1 ... j of the up-crossings i and j): one peak a cycle, so that
   the peaks count the cycles. The mean zero-up-crossing period is counted on the same
   crossings, Tz = (t of the last - t of the first) / (their number - 1) (the definition
   of :func:`riser.results.recorder.most_probable_maximum`). A minimum's peaks are those of
   -x about -m (the troughs, one between successive down-crossings).
2. **Fit.** The peaks' excesses over the mean, y = peak - m (> 0), n of them; their
   upper part, the n_u = :data:`TAIL` n largest, above the threshold u (the largest
   excess left out), is fitted by a two-parameter Weibull F(y) = 1 - exp(-(y /
   lambda)^k) (location 0) by maximum likelihood conditioned on y > u: the truncated
   Weibull's log-likelihood n_u [ln k - ln theta + (k - 1) mean(ln y)] - sum(y^k - u^k)
   / theta, theta = lambda^k, whose theta is mean(y^k - u^k) in closed form and whose k
   maximises the profile likelihood ln k - ln mean(y^k - u^k) + (k - 1) mean(ln y)
   (bounded Brent on ln k). With every peak (u = 0) it is the estimator of
   ``scipy.stats.weibull_min.fit(y, floc=0)``. Why the upper half: the extreme is the
   tail's, and a broad-banded response has many small peaks (a riding wave's cycle
   between two crossings of the mean) that a fit of every peak follows, bending its
   tail: on Gaussian JONSWAP records (Tp 14 s, 30 min) the MPM of every peak's fit is
   14 % above the exact sigma sqrt(2 ln N), the upper half's 2 % below it (1 standard
   error; tests/test_storm_extremes.py).
3. **MPM over the storm.** The storm of duration D has N = D / Tz peaks, N_u = N n_u / n
   of them above u; the largest of N independent peaks has the distribution F^N, whose
   mode tends, as N grows, to the characteristic largest value u_N, N (1 - F(u_N)) = 1
   (the location of the Gumbel distribution the largest of N approaches for a tail like
   the Weibull's). Above u, N_u (1 - F(y | y > u)) = 1 gives
   x_mpm = m + (u^k + lambda^k ln N_u)^(1/k), with u = 0 and N_u = N the familiar
   m + lambda (ln N)^(1/k); a minimum's x_mpm = m - the same of the troughs' fit.
4. **Rayleigh beside.** The peaks of a narrow-banded Gaussian response are Rayleigh, the
   Weibull of k = 2 and lambda = sigma sqrt(2): x_mpm = m + sigma sqrt(2 ln N) with the
   record's standard deviation sigma (the form the frequency domain uses with its
   spectral moments, bvp/frequency/sea_response.py; by Rice's rate of up-crossings of a
   level it is also the characteristic largest value of a broad-banded Gaussian
   response). A non-Gaussian response (a slack line, a touchdown that opens and closes)
   is outside it; the Weibull fit adapts its shape to the record's peaks.
5. **Uncertainty.** A percentile bootstrap of the peaks: :data:`RESAMPLES` resamples of
   the n peaks with replacement (``numpy.random.default_rng(SEED)``: deterministic, a
   report regenerates byte for byte), each refitted (its own upper part) and taken to
   the MPM with the record's mean and Tz held; the 5th and 95th percentiles are the 90 %
   interval. It measures the fit's sampling error from n peaks taken as independent;
   the peaks of a narrow-banded response are correlated from cycle to cycle through its
   slowly varying envelope, and the record's mean and Tz scatter too, which the
   resampling of the peaks does not see: measured on synthesised narrow-banded records
   (tests/test_storm_extremes.py: 2 h, a Gaussian spectrum 10 % of its peak frequency
   wide), the interval's half-width is 0.74-0.77 of 1.645 standard deviations of the MPM
   over 200 and 40 independent records, and it covers the closed form in 74-78 % of
   them, not 90 %.

References (docs/references.md, "Extremes over a storm"): Ochi (1973, 1990) on the
extreme values of Gaussian processes and the most probable extreme; Gumbel (1958);
DNV-RP-C205 and DNV-OS-E301 on the practice of fitting the peaks of a time-domain record
and extrapolating to the storm; Cohen (1965) on the Weibull's likelihood; Efron and
Tibshirani (1993) on the bootstrap.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize_scalar

#: the design storm's duration [s] without a [design] table (3 h)
STORM_DURATION = 10800.0
#: bootstrap resamples of the peaks and the generator's seed (module docstring, 5.)
RESAMPLES = 200
SEED = 0
#: the interval's coverage (the 5th and 95th percentiles)
LEVEL = 0.90
#: fewer peaks than this are not fitted (no figures)
MIN_PEAKS = 10
#: the fraction of the peaks, the largest, that the Weibull is fitted to (module
#: docstring, 2.); at least MIN_PEAKS of them (all, in a record of fewer)
TAIL = 0.5
#: the bounds of the Weibull's shape k searched
SHAPE_BOUNDS = (0.02, 100.0)
#: the extremes of a dynamic run's summary in an irregular sea (riser.results.recorder,
#: riser.design.dynamic; ``dynamic_NAME_mpm`` and the keys of :meth:`StormExtreme.summary`):
#: NAME -> (the summary's key of the record's own extreme, SI unit, what it is)
SUMMARY_EXTREMES = {
    "hang_off_tension": ("dynamic_max_hang_off_tension", "N", "hang-off tension, max"),
    "min_tension": ("dynamic_min_tension", "N", "least tension along the line"),
    "max_moment": ("dynamic_max_moment", "N m", "largest moment along the line"),
    "max_utilisation": ("dynamic_max_utilisation", "-", "largest utilisation along the line")}


def storm_duration(scene) -> float:
    """The storm of the most probable maxima [s]: ``[design] storm_duration`` of a scene
    with [design], else :data:`STORM_DURATION`."""
    design = getattr(scene, "design", None)
    value = getattr(design, "storm_duration", None) if design is not None else None
    return float(value) if value is not None else STORM_DURATION


def up_crossings(x: np.ndarray, mean: float) -> np.ndarray:
    """Indices i of the up-crossings of ``mean``: x[i] < mean <= x[i + 1]."""
    x = np.asarray(x, float)
    return np.flatnonzero((x[:-1] < mean) & (x[1:] >= mean))


def peaks(x: np.ndarray, mean: float | None = None, minimum: bool = False) -> np.ndarray:
    """The peaks of the record ``x`` (module docstring, 1.): the largest sample between
    each two successive up-crossings of ``mean`` (default the record's); ``minimum``: the
    least sample between successive down-crossings (the troughs). Values of x, in the
    record's order; empty with fewer than two crossings."""
    x = np.asarray(x, float)
    m = float(np.mean(x)) if mean is None else float(mean)
    z = -x if minimum else x
    up = up_crossings(z, -m if minimum else m)
    if len(up) < 2:
        return np.zeros(0)
    top = np.maximum.reduceat(z[:up[-1] + 1], up[:-1] + 1)
    return -top if minimum else top


def weibull_fit(y: np.ndarray, threshold: float = 0.0) -> tuple[float, float]:
    """(k, lambda): the maximum-likelihood two-parameter Weibull (location 0) of the
    samples ``y``, all above ``threshold`` u >= 0 (module docstring, 2.: the likelihood
    conditioned on y > u; u = 0: every sample, scipy's ``weibull_min.fit(y, floc=0)``).
    Samples without spread: (inf, their value), the limit of a distribution without
    spread."""
    y = np.asarray(y, float)
    if y.size == 0 or np.any(y <= 0.0) or threshold < 0.0 or np.any(y < threshold):
        raise ValueError("weibull_fit needs positive samples at or above the threshold")
    top = float(np.max(y))
    z = np.log(y / top)                       # <= 0: y^k / top^k without overflow
    zbar = float(np.mean(z))
    if zbar > -1e-14:                         # no spread
        return math.inf, top
    u = threshold / top                       # the problem is scale-free: in units of top
    w = np.exp(z)

    def minus_profile(log_k):
        k = math.exp(log_k)
        theta = float(np.mean(w ** k - u ** k))
        if not theta > 0.0:
            return math.inf
        return -(log_k - math.log(theta) + (k - 1.0) * zbar)

    lo, hi = (math.log(b) for b in SHAPE_BOUNDS)
    log_k = minimize_scalar(minus_profile, bounds=(lo, hi), method="bounded",
                            options={"xatol": 1e-11}).x
    k = math.exp(log_k)
    theta = float(np.mean(w ** k - u ** k))
    return float(k), float(top * theta ** (1.0 / k))


def weibull_quantile(k: float, lam: float, n: float, threshold: float = 0.0) -> float:
    """The characteristic largest of ``n`` Weibull (k, lambda) samples above
    ``threshold`` u: the y with n (1 - F(y | y > u)) = 1, (u^k + lambda^k ln n)^(1/k)
    (module docstring, 3.; u = 0: F^{-1}(1 - 1/n) = lambda (ln n)^(1/k)); u at n <= 1."""
    ln = math.log(max(n, 1.0))
    if not math.isfinite(k):
        return max(lam, threshold)
    return (threshold ** k + lam ** k * ln) ** (1.0 / k)


def upper_part(y: np.ndarray, fraction: float = TAIL) -> tuple[np.ndarray, float]:
    """(the largest ``fraction`` of the samples ``y``, at least :data:`MIN_PEAKS` of
    them, all when there are no more; the threshold u: the largest sample left out, 0
    when none is)."""
    y = np.sort(np.asarray(y, float))[::-1]
    n_u = min(len(y), max(int(round(fraction * len(y))), MIN_PEAKS))
    return y[:n_u], (float(y[n_u]) if n_u < len(y) else 0.0)


def tail_mpm(y: np.ndarray, n_storm: float, fraction: float = TAIL):
    """(MPM excess, k, lambda, u, n_u) of the excesses ``y`` over ``n_storm`` peaks:
    the Weibull of their upper part (:func:`upper_part`, :func:`weibull_fit`) taken to
    N_u = n_storm n_u / n peaks above u (:func:`weibull_quantile`)."""
    tail, u = upper_part(y, fraction)
    k, lam = weibull_fit(tail, u)
    return (weibull_quantile(k, lam, n_storm * len(tail) / len(y), u), k, lam, u,
            len(tail))


def rayleigh_mpm(sigma, tz, duration: float):
    """sigma sqrt(2 ln N), N = ``duration`` / ``tz`` (taken as 1 below 1): the most
    probable maximum above the mean of a narrow-banded Gaussian response of standard
    deviation ``sigma`` and zero-up-crossing period ``tz`` [s] over ``duration`` [s];
    arrays elementwise (0 where tz is not a positive number)."""
    sigma, tz = np.asarray(sigma, float), np.asarray(tz, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        n = np.where(np.isfinite(tz) & (tz > 0.0), duration / tz, 1.0)
    out = sigma * np.sqrt(2.0 * np.log(np.maximum(n, 1.0)))
    return float(out) if out.ndim == 0 else out


@dataclass(frozen=True)
class StormExtreme:
    """The extreme of one record over a storm (module docstring; the record's unit).

    mean, std : the record's; tz [s] : counted on its up-crossings of the mean;
    peaks : the record's number of peaks n; fitted : the number of the largest fitted,
    n_u, above threshold u (an excess over the mean, the record's unit); shape, scale :
    the Weibull's k and lambda of the excesses; storm_duration [s], storm_peaks N =
    storm_duration / tz; mpm : the Weibull's MPM, low and high its bootstrap interval
    (:data:`LEVEL`; low < high, for a minimum too); rayleigh : mean +- std sqrt(2 ln N);
    record : the record's own extreme; minimum : the extreme is a minimum."""

    mean: float
    std: float
    tz: float
    peaks: int
    fitted: int
    threshold: float
    shape: float
    scale: float
    storm_duration: float
    storm_peaks: float
    mpm: float
    low: float
    high: float
    rayleigh: float
    record: float
    minimum: bool = False

    def summary(self, name: str) -> dict:
        """summary.json's keys of the quantity ``name`` (without the ``dynamic_``
        prefix): ``NAME_mpm``, ``_mpm_low``, ``_mpm_high``, ``_mpm_rayleigh``,
        ``_weibull_shape``, ``_weibull_scale``, ``_weibull_threshold`` (u),
        ``_weibull_peaks`` (n_u), ``_peaks`` (n), ``_tz``."""
        return {f"{name}_mpm": self.mpm, f"{name}_mpm_low": self.low,
                f"{name}_mpm_high": self.high, f"{name}_mpm_rayleigh": self.rayleigh,
                f"{name}_weibull_shape": self.shape, f"{name}_weibull_scale": self.scale,
                f"{name}_weibull_threshold": self.threshold,
                f"{name}_weibull_peaks": self.fitted, f"{name}_peaks": self.peaks,
                f"{name}_tz": self.tz}


def storm_extreme(t: np.ndarray, x: np.ndarray, storm_duration: float = STORM_DURATION,
                  minimum: bool = False, resamples: int = RESAMPLES, seed: int = SEED,
                  fraction: float = TAIL) -> StormExtreme | None:
    """The most probable maximum (``minimum``: minimum) over ``storm_duration`` [s] of
    the record ``x`` at times ``t`` [s], its bootstrap interval, the Rayleigh MPM and the
    record's own extreme (module docstring; :class:`StormExtreme`); ``resamples`` 0: no
    interval (NaN); ``fraction``: of the peaks fitted (1: every peak). None when the
    record has fewer than :data:`MIN_PEAKS` peaks or no spread."""
    t, x = np.asarray(t, float), np.asarray(x, float)
    if len(x) < 3 or len(t) != len(x):
        return None
    mean, std = float(np.mean(x)), float(np.std(x))
    sign = -1.0 if minimum else 1.0
    z = sign * x
    up = up_crossings(z, sign * mean)
    if len(up) < MIN_PEAKS + 1 or std == 0.0:
        return None
    tz = float(t[up[-1]] - t[up[0]]) / (len(up) - 1)
    if not tz > 0.0:
        return None
    y = np.maximum.reduceat(z[:up[-1] + 1], up[:-1] + 1) - sign * mean
    y = y[y > 0.0]
    if len(y) < MIN_PEAKS:
        return None
    n_storm = storm_duration / tz
    mpm, k, lam, u, n_u = tail_mpm(y, n_storm, fraction)
    lo = hi = math.nan                        # resamples = 0: no interval
    if resamples > 0:
        rng = np.random.default_rng(seed)
        boot = np.empty(resamples)
        for b in range(resamples):
            boot[b] = tail_mpm(y[rng.integers(0, len(y), len(y))], n_storm, fraction)[0]
        tail = 50.0 * (1.0 - LEVEL)
        lo, hi = (float(v) for v in np.percentile(boot, (tail, 100.0 - tail)))
    if minimum:
        lo, hi = hi, lo
    record = float(np.min(x) if minimum else np.max(x))
    return StormExtreme(mean, std, tz, int(len(y)), int(n_u), u, k, lam,
                        float(storm_duration), n_storm,
                        mean + sign * mpm, mean + sign * lo, mean + sign * hi,
                        mean + sign * rayleigh_mpm(std, tz, storm_duration), record,
                        minimum)


def storm_statistics(t, records: dict, storm_duration: float = STORM_DURATION) -> dict:
    """summary.json's figures of the extremes over ``storm_duration`` [s] of records
    sampled at the times ``t`` [s]: ``records`` maps a name to (x, minimum); each record
    with enough peaks gives the keys of :meth:`StormExtreme.summary`, and
    ``storm_duration`` [s] is given beside (without the ``dynamic_`` prefix)."""
    out = {"storm_duration": float(storm_duration)}
    for name, (x, minimum) in records.items():
        e = storm_extreme(np.asarray(t, float), np.asarray(x, float), storm_duration,
                          minimum=minimum)
        if e is not None:
            out.update(e.summary(name))
    return out


def summary_extreme(info: dict, name: str) -> dict | None:
    """A quantity of :data:`SUMMARY_EXTREMES` read back from a run's summary ``info``:
    ``mpm``, ``low``, ``high``, ``rayleigh``, ``record`` (the record's own extreme),
    ``peaks``, ``shape`` (None where missing); None when the summary has no MPM of it."""
    if f"dynamic_{name}_mpm" not in info:
        return None

    def get(key):
        v = info.get(key)
        return None if v is None else float(v)
    out = {k: get(f"dynamic_{name}{suffix}") for k, suffix in (
        ("mpm", "_mpm"), ("low", "_mpm_low"), ("high", "_mpm_high"),
        ("rayleigh", "_mpm_rayleigh"), ("peaks", "_peaks"), ("shape", "_weibull_shape"))}
    out["record"] = get(SUMMARY_EXTREMES[name][0])
    return out

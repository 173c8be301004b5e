"""Harmonic content of a periodic time series: the mean, the first harmonic's complex
amplitude and phase, the higher harmonics and the envelope, by least squares on whole
periods of a window.

Convention (the frequency domain's, :mod:`bvp.frequency.harmonic`): a signal
    q(t) = q_0 + Re(Q_1 e^{i omega t}) + Re(Q_2 e^{2 i omega t}) + ...
so a motion d(t) = A sin(omega t) has Q_1 = -i A (amplitude A, phase -90 deg). The
amplitude of a harmonic is |Q_k|, its phase arg(Q_k) [rad]. The fit is least squares on
cos/sin of the motion's frequency and its multiples up to ``harmonics`` (exact for a
periodic signal sampled evenly over whole periods; the window's leftover transient shows
as a residual, reported).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: harmonics fitted besides the mean (the 2nd and 3rd measure the nonlinearity)
HARMONICS = 3


@dataclass(frozen=True)
class Harmonics:
    """Fit of one or many signals (trailing axis: time).

    mean : q_0; first : Q_1 (complex); higher : (k - 1, ...) complex Q_2 ... Q_k;
    half_range : (max - min) / 2 over the window; residual : rms of the fit's residual;
    periods : whole periods in the window."""

    mean: np.ndarray
    first: np.ndarray
    higher: np.ndarray
    half_range: np.ndarray
    residual: np.ndarray
    periods: int

    @property
    def amplitude(self) -> np.ndarray:
        return np.abs(self.first)

    @property
    def phase(self) -> np.ndarray:
        """Phase of the first harmonic [rad] (arg Q_1)."""
        return np.angle(self.first)

    @property
    def higher_ratio(self) -> np.ndarray:
        """sqrt(sum |Q_k|^2, k >= 2) / |Q_1|: the nonlinearity of the response."""
        top = np.sqrt(np.sum(np.abs(self.higher) ** 2, axis=0))
        return top / np.maximum(np.abs(self.first), np.finfo(float).tiny)


def window(t: np.ndarray, start: float, period: float) -> np.ndarray:
    """Indices of the samples over the last whole number of periods from ``start`` [s]:
    the window ends at the last sample and starts k periods earlier (k as large as fits)."""
    t = np.asarray(t, float)
    span = t[-1] - max(start, t[0])
    k = int(np.floor(span / period + 1e-9))
    if k < 1:
        raise ValueError(f"the window from {start:g} s to {t[-1]:g} s holds no whole "
                         f"period of {period:g} s")
    t0 = t[-1] - k * period
    return np.flatnonzero(t >= t0 - 1e-9 * period)


def fit(t: np.ndarray, q: np.ndarray, period: float, start: float = 0.0,
        harmonics: int = HARMONICS, trend: int = 0) -> Harmonics:
    """Least-squares harmonics of ``q`` (time on the last axis, sampled at ``t`` [s]) at
    the frequency 2 pi / ``period``, over the whole periods after ``start`` (see
    :func:`window`). The last sample of a whole-period window repeats the first: it is
    dropped so that every phase weighs the same."""
    t = np.asarray(t, float)
    q = np.asarray(q, float)
    idx = window(t, start, period)
    if idx.size > 2 and abs((t[idx[-1]] - t[idx[0]]) / period
                            - round((t[idx[-1]] - t[idx[0]]) / period)) < 1e-6:
        idx = idx[:-1]
    tw = t[idx]
    qw = np.take(q, idx, axis=-1)
    w = 2.0 * np.pi / period
    cols = [np.ones_like(tw)]
    for k in range(1, harmonics + 1):
        cols += [np.cos(k * w * tw), np.sin(k * w * tw)]
    tau = (tw - tw.mean()) / max(tw[-1] - tw[0], 1e-300)
    for k in range(1, trend + 1):
        cols.append(tau ** k)
    X = np.stack(cols, axis=1)
    flat = qw.reshape(-1, tw.size).T
    coef, *_ = np.linalg.lstsq(X, flat, rcond=None)
    resid = flat - X @ coef
    shape = qw.shape[:-1]
    # Re(Q e^{i w t}) = Re(Q) cos - Im(Q) sin: Q = a - i b for a cos + b sin
    k = 2 * harmonics + 1
    Q = (coef[1:k:2] - 1j * coef[2:k:2]).reshape((harmonics,) + shape)
    periods = int(round((t[idx[-1]] - t[idx[0]]) / period)) if idx.size > 1 else 0
    return Harmonics(mean=coef[0].reshape(shape), first=Q[0], higher=Q[1:],
                     half_range=0.5 * (np.max(qw, axis=-1) - np.min(qw, axis=-1)),
                     residual=np.sqrt(np.mean(resid ** 2, axis=0)).reshape(shape),
                     periods=max(periods, 1))

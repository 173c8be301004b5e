"""Fatigue damage of stress time series: rainflow counting (ASTM E1049-85) and the
Palmgren-Miner sum against a DNV-RP-C203 S-N curve (:mod:`riser.design.sn_curves`).

Counting convention (ASTM E1049-85, sec. 5.4.4, as the ``rainflow`` package implements
it): the series is reduced to its reversals (the first and last samples count as
reversals); a range Y is closed as a full cycle (count 1) when the next range X is at
least as large and Y does not contain the starting point; a range Y that contains the
starting point is counted as a half cycle (count 0.5) and the start moves on; the
residual ranges left at the end of the record are each counted as a half cycle (count
0.5). The ranges are peak-to-valley stress ranges in the unit of the series (Pa here).
"""

from __future__ import annotations

import numpy as np
import rainflow

from .sn_curves import SNCurve


def reversals(x: np.ndarray) -> np.ndarray:
    """The series reduced to its first sample, its turning points and its last sample
    (repeated values dropped): the points the rainflow count uses (ASTM E1049 counts
    the reversals only), so counting them gives the same cycles, faster (numpy instead
    of the package's per-sample loop)."""
    x = np.asarray(x, float)
    if x.size < 3:
        return x
    x = x[np.concatenate([[True], np.diff(x) != 0.0])]
    if x.size < 3:
        return x
    d = np.diff(x)
    turn = np.flatnonzero(d[:-1] * d[1:] < 0.0) + 1
    return x[np.concatenate([[0], turn, [x.size - 1]])]


def cycles_of(series) -> tuple[np.ndarray, np.ndarray]:
    """The rainflow cycles of a 1-D series: ``(ranges, counts)``.

    ``ranges`` are in the unit of ``series`` (Pa for a stress); ``counts`` are 1.0 for a
    closed cycle and 0.5 for a half cycle (one containing the record's start, or a
    residual range at its end, ASTM E1049-85 sec. 5.4.4). A series of fewer than two
    samples, or a constant one, has no cycles (empty arrays).
    """
    x = np.asarray(series, dtype=float)
    if x.ndim != 1:
        raise ValueError(f"a series is one-dimensional, got shape {x.shape}")
    out = [(rng, count) for rng, _mean, count, _i0, _i1 in
           rainflow.extract_cycles(reversals(x))]
    if not out:
        return np.zeros(0), np.zeros(0)
    ranges, counts = np.array(out, dtype=float).T
    return ranges, counts


def miner_sum(ranges, counts, curve: SNCurve, thickness: float | None = None,
              scf: float = 1.0) -> float:
    """Palmgren-Miner damage sum(counts / N(ranges)) of cycles of nominal stress
    ``ranges`` [Pa] against ``curve`` (its thickness correction for ``thickness`` [m], the
    stress concentration ``scf`` on the ranges). Dimensionless; a zero range adds 0."""
    ranges = np.asarray(ranges, dtype=float)
    counts = np.asarray(counts, dtype=float)
    if ranges.shape != counts.shape:
        raise ValueError(f"ranges {ranges.shape} and counts {counts.shape} differ in shape")
    if ranges.size == 0:
        return 0.0
    return float(np.sum(counts / curve.cycles(ranges, thickness, scf)))


def series_damage(stress, curve: SNCurve, thickness: float | None = None,
                  scf: float = 1.0) -> np.ndarray:
    """Miner damage of the rainflow cycles of each column of ``stress`` [Pa].

    ``stress`` is (k,) or (k, p): time along axis 0, p points (e.g. around the
    circumference or along the line). Returns an array of shape () or (p,): the damage of
    the record, dimensionless (divide by the record's duration for a rate).
    """
    x = np.asarray(stress, dtype=float)
    if x.ndim not in (1, 2):
        raise ValueError(f"stress is (k,) or (k, p), got shape {x.shape}")
    columns = x.reshape(x.shape[0], -1)
    out = np.array([miner_sum(*cycles_of(columns[:, j]), curve, thickness, scf)
                    for j in range(columns.shape[1])])
    return out.reshape(x.shape[1:])

"""Tolerances MEASURED from each method's convergence (``compare --time-domain``).

Every compared quantity is measured at three levels of one discretisation parameter of one
method, the element length or the time step, each level twice the next (the suite's
refinement ratio 2): q1 (4x), q2 (2x), q3 (1x) for a coarsening down to the default, or
q1 (1x, the default), q2 (1/2), q3 (1/4) for a refinement from it (the VFIFE's explicit
step cannot be made coarser than its critical step: see :mod:`.protocol`). A quantity is a
number or an array (a time series over the window, an envelope along s): the changes
between levels are d1 = ||q1 - q2|| and d2 = ||q2 - q3|| (the root mean square of an
array's difference; the absolute value of a number's), r = d1 / d2 = 2^p (p the observed
order).

The estimated error of the default level (:func:`estimate`):
- both changes below :data:`FLOOR` x the quantity's scale: converged to the noise of the
  runs' own tolerances; the error is the larger change (at least the floor);
- otherwise the levels converge when the changes shrink by at least 2^:data:`MIN_ORDER`
  (r >= sqrt 2) and, for a number, keep their sign (monotone); then the error at the
  finest level is max(d2, d2 / (r - 1)) (the last change, or the Richardson estimate when
  order is below 1 and the last change underestimates what is left), and at the coarsest
  level (the default of a refinement) d1 r / (r - 1) (Richardson from the default: what
  the two refinements still changed and what would follow). The levels a run can take
  are not always exactly 2 apart (a time step is made an exact divisor of the sampling
  interval): the order and the Richardson estimates then use the levels' own values
  (:func:`observed_order`; with ratio 2 they are the formulas above);
- else (non-monotone, order < 0.5): not converged, no error: the row is reported "not
  judged: not converged" with the numbers.

A row's tolerance is the sum of the two methods' estimated errors in element length and in
time step (:func:`combine`): a bound on what the discretisations alone can make the two
methods differ by; the reason names the dominating part.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: the order below which three levels are not taken as converging (r < 2^0.5)
MIN_ORDER = 0.5
#: changes below this fraction of the quantity's scale are the runs' own noise: the
#: VFIFE's statics stop at 1e-3 of an element's weight and the ANCF's at 1e-6 of the load
#: scale (relative changes of the tension of 1e-6 to 1e-5), the ANCF's steps at 1e-3 of
#: it (ancf/dynamics/run.py: the hang-off tension range within 0.01 % of the runs at
#: 1e-6); 1e-4 sits above both, so that a trend below it is never read as an order
FLOOR = 1.0e-4


@dataclass(frozen=True)
class Estimate:
    """The convergence of one quantity in one parameter of one method.

    method, parameter : e.g. "vfife", "element length"; levels : the parameter's values at
    the three levels (coarse to fine, [m] or [s]); values : the quantity's scalar summary
    at each level (the number, or the rms of the array); d1, d2 : the changes between
    levels; order : the observed order p (None: not defined); error : the estimated error
    of the default level (None: not converged); note : how it was estimated."""

    method: str
    parameter: str
    levels: tuple
    values: tuple
    d1: float
    d2: float
    order: float | None
    error: float | None
    note: str

    @property
    def converged(self) -> bool:
        return self.error is not None


def _norm(a) -> float:
    a = np.asarray(a, float)
    return float(np.sqrt(np.mean(a * a))) if a.size > 1 else float(abs(a.reshape(-1)[0]))


def estimate(method: str, parameter: str, levels, values, default: str = "finest",
             scale: float | None = None) -> Estimate:
    """The error at the default level of three ``values`` (coarse to fine, ratio 2; numbers
    or arrays of one shape) measured at ``levels`` of ``parameter``; ``default``: "finest"
    (a coarsening to the default) or "coarsest" (a refinement from it); ``scale``: the
    quantity's scale for :data:`FLOOR` (default the largest level's norm)."""
    q = [np.asarray(v, float) for v in values]
    summary = tuple(_norm(v) for v in q)
    if any(not np.all(np.isfinite(v)) for v in q):
        return Estimate(method, parameter, tuple(levels), summary, np.nan, np.nan, None,
                        None, "a level is not finite")
    d1, d2 = _norm(q[0] - q[1]), _norm(q[1] - q[2])
    scale = max(summary) if scale is None else scale
    floor = FLOOR * scale
    if d1 <= floor and d2 <= floor:
        return Estimate(method, parameter, tuple(levels), summary, d1, d2, None,
                        max(d1, d2, floor), "changes below the noise floor")
    h = np.asarray(levels, float)
    order = observed_order(h, d1, d2) if d2 > 0 else np.inf
    monotone = True
    if q[0].size == 1:
        a, b = float(q[0] - q[1]), float(q[1] - q[2])
        monotone = a * b > 0 or abs(b) <= floor
    if not monotone or order < MIN_ORDER:
        why = "non-monotone" if not monotone else f"order {order:.2f} < {MIN_ORDER:g}"
        return Estimate(method, parameter, tuple(levels), summary, d1, d2,
                        order if np.isfinite(order) else None, None, f"not converged ({why})")
    if not np.isfinite(order):
        err, note = (d2, "last change") if default == "finest" else (d1, "first change")
    elif default == "finest":
        rich = d2 * h[2] ** order / (h[1] ** order - h[2] ** order)
        err, note = (d2, "last change") if d2 >= rich else (rich, "Richardson")
    else:
        err = d1 * h[0] ** order / (h[0] ** order - h[1] ** order)
        note = "Richardson from the default"
    return Estimate(method, parameter, tuple(levels), summary, d1, d2,
                    order if np.isfinite(order) else None, max(err, floor), note)


def observed_order(h, d1: float, d2: float) -> float:
    """The order p of q(h) = q* + C h^p through three levels h[0] > h[1] > h[2] whose
    changes are d1 = |q(h0) - q(h1)| and d2 = |q(h1) - q(h2)| (any ratios; 2 each: log2
    (d1 / d2)), by bisection on (h0^p - h1^p) / (h1^p - h2^p) = d1 / d2 between -4 and 12
    (the ends when outside)."""
    target = d1 / d2

    def ratio(p):
        if abs(p) < 1e-9:
            return np.log(h[0] / h[1]) / np.log(h[1] / h[2])
        return (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p)

    lo, hi = -4.0, 12.0
    if target <= ratio(lo):
        return lo
    if target >= ratio(hi):
        return hi
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ratio(mid) < target else (lo, mid)
    return 0.5 * (lo + hi)


@dataclass(frozen=True)
class Tolerance:
    """A row's tolerance: ``value`` (None: not judged), ``reason`` (the dominating part,
    or why not judged) and the estimates behind it."""

    value: float | None
    reason: str
    parts: tuple


def combine(parts) -> Tolerance:
    """The sum of the estimated errors of ``parts`` (:class:`Estimate` of both methods in
    both parameters); not judged when any part did not converge (named, with its changes
    and order)."""
    parts = tuple(parts)
    if not parts:
        return Tolerance(None, "not judged: no convergence measured", parts)
    bad = [p for p in parts if not p.converged]
    if bad:
        why = "; ".join(f"{p.method} {p.parameter}: " + (
            f"changes {p.d1:.4g}, {p.d2:.4g}" + (f", order {p.order:.2f}"
                                                  if p.order is not None else "")
            + (", non-monotone" if "non-monotone" in p.note else "")
            if np.isfinite(p.d1) else p.note) for p in bad)
        return Tolerance(None, f"not judged: not converged ({why})", parts)
    total = sum(p.error for p in parts)
    top = max(parts, key=lambda p: p.error)
    share = top.error / total if total > 0 else 1.0
    order = f", order {top.order:.2f}" if top.order is not None else ""
    return Tolerance(total, f"{top.method} {top.parameter} dominates ({100 * share:.0f} %: "
                     f"{top.note}{order})", parts)

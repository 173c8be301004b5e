"""Convergence fits of the cost study: the Richardson limit of an element-length sequence,
the fitted order of the errors in element length (with the local orders of successive
lengths), and the Pareto front of error against time. Arithmetic on numbers only."""

from __future__ import annotations

import math

import numpy as np

#: a point enters the order fit only if its error is this many times the noise floor: its
#: log error is then uncertain by at most log(1.1) ~ 0.1, i.e. <= 0.1 in the order over a
#: factor-2.5 step of the element length
NOISE_MARGIN = 10.0
#: errors above this are pre-asymptotic (unresolved boundary layers) and left out of the fit
PRE_ASYMPTOTIC = 1e-2


def richardson(hs, qs) -> tuple[float, float | None]:
    """Limit and observed order from the three finest of ``hs`` (a constant refinement
    ratio is not required: the order solves (q1-q2)/(q2-q3) = (h1^p-h2^p)/(h2^p-h3^p)).
    Returns (limit, order); order None (limit = finest value) when the differences change
    sign or are zero, i.e. the sequence is not in its asymptotic range."""
    pts = sorted(zip(hs, qs))[:3]
    if len(pts) < 3:
        return (pts[0][1] if pts else float("nan")), None
    (h3, q3), (h2, q2), (h1, q1) = pts
    d12, d23 = q1 - q2, q2 - q3
    if d12 == 0.0 or d23 == 0.0 or (d12 > 0) != (d23 > 0):
        return q3, None
    target = d12 / d23

    def f(p):
        return (h1 ** p - h2 ** p) / (h2 ** p - h3 ** p) - target
    lo, hi = 0.2, 8.0
    if f(lo) * f(hi) > 0:
        return q3, None
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0:
            hi = mid
        else:
            lo = mid
    p = 0.5 * (lo + hi)
    C = d23 / (h2 ** p - h3 ** p)
    return q3 - C * h3 ** p, p


def richardson_limits(hs, values: list[dict]) -> tuple[dict, dict]:
    """Per raw key of ``values`` (aligned with ``hs``): (Richardson limit, order)."""
    keys = sorted({k for v in values for k in v if v.get(k) is not None})
    limits, orders = {}, {}
    for k in keys:
        ok = [(h, v[k]) for h, v in zip(hs, values) if v.get(k) is not None]
        if len(ok) >= 3:
            limits[k], orders[k] = richardson([h for h, _ in ok], [q for _, q in ok])
        elif ok:
            limits[k], orders[k] = min(ok)[1], None
    return limits, orders


def fit_order(hs, errs, floor: float = 0.0, ceiling: float = PRE_ASYMPTOTIC) -> dict:
    """Least-squares slope of log(err) vs log(h) over the points with
    floor < err <= ceiling (above the noise, in the asymptotic range).
    Returns {'order', 'points' (h used), 'r2'} (order None with fewer than 2 points)."""
    pts = [(h, e) for h, e in zip(hs, errs)
           if e is not None and np.isfinite(e) and max(floor, 0.0) < e <= ceiling]
    if len(pts) < 2:
        return {"order": None, "points": [h for h, _ in pts], "r2": None}
    x = np.log([h for h, _ in pts])
    y = np.log([e for _, e in pts])
    p, c = np.polyfit(x, y, 1)
    yhat = p * x + c
    ss = float(np.sum((y - y.mean()) ** 2))
    r2 = 1.0 - float(np.sum((y - yhat) ** 2)) / ss if ss > 0 else 1.0
    return {"order": float(p), "const": float(c), "points": [h for h, _ in pts], "r2": r2}


def element_length_fits(hs, errors: dict, floor: dict | None = None,
                        h_max: float = math.inf) -> dict:
    """Fitted order per quantity of an element-length sweep. ``errors[q]``: errors aligned
    with ``hs`` (against the reference); a point enters the fit if its element length is
    at most ``h_max`` (the asymptotic range) and its error above ``floor[q]``. Each fit
    also carries the local orders of successive lengths (see :func:`_fit_context`)."""
    fits = {}
    for q, errs in errors.items():
        use = [(h, e) for h, e in zip(hs, errs) if h <= h_max]
        fl = (floor or {}).get(q, 0.0)
        fits[q] = fit_order([h for h, _ in use], [e for _, e in use], fl)
        fits[q].update(_fit_context(hs, errs, h_max, fl))
        fits[q]["errors"] = [e for h, e in use if h in fits[q]["points"]]
    return fits


def _fit_context(hs, errs, h_max: float, floor: float) -> dict:
    """Local orders log(e1/e2)/log(h1/h2) of successive element lengths (all of them, for
    the report) and the largest error of the lengths in the asymptotic range (h <= h_max)
    when none of them is above the noise floor."""
    pts = list(zip(hs, errs))
    local = [(h1, h2, math.log(e1 / e2) / math.log(h1 / h2))
             for (h1, e1), (h2, e2) in zip(pts, pts[1:]) if e1 and e2 and e1 > 0 and e2 > 0]
    inside = [e for h, e in zip(hs, errs) if h <= h_max and e is not None]
    below = bool(inside) and max(inside) <= floor
    return {"local": local, "below_noise": max(inside) if below else None,
            "noise_margin": floor, "n_inside": len(inside)}


def worst_mesh(fit: dict) -> float | None:
    """Element length of the fit whose error relative to h^2 stands out (at least twice the
    median of the others), else None."""
    r = sorted((e / (h * h), h) for h, e in zip(fit.get("points", []), fit.get("errors", [])))
    if len(r) < 3:
        return None
    rest = [x for x, _ in r[:-1]]
    return r[-1][1] if r[-1][0] >= 2.0 * rest[len(rest) // 2] else None


def pareto(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Non-dominated (time, error) points, sorted by time."""
    front, best = [], float("inf")
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front

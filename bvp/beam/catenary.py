"""Multi-segment catenary (EI = 0, no drag), inextensible or elastic, closed form per
segment.

Used as the starting guess of the beam solver. With s the unstretched arc length, a
constant horizontal tension H [N] and the vertical force V(s) = V0 + sum of w ds [N]
growing along the line, each segment of weight w [N/m of unstretched length] is

    x(s) = x0 + H/w [asinh(V/H) - asinh(V0/H)] + H (s - s0) / EA
    y(s) = y0 + H/w [sqrt(1 + (V/H)^2) - sqrt(1 + (V0/H)^2)] + (V0 + V) (s - s0) / (2 EA)

(a straight line where w = 0; the EA terms are the stretch eps = T/EA, Irvine's elastic
catenary, absent for EA = inf), with the tension T = sqrt(H^2 + V^2), the angle
theta = atan2(V, H) and the curvature w H / T^2 (per unit stretched length).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq


def catenary_state(s: np.ndarray, weights: np.ndarray, lengths: np.ndarray, H: float,
                   V0: float, x0: float = 0.0, y0: float = 0.0,
                   EA=None) -> dict[str, np.ndarray]:
    """Catenary through (x0, y0) at s = 0 with forces (H, V0) there.

    Parameters
    ----------
    s : arc lengths [m], shape (m,), in [0, sum(lengths)].
    weights : submerged weight per segment [N/m], shape (n,).
    lengths : segment lengths [m], shape (n,).
    H : horizontal tension [N], > 0.  V0 : vertical force at s = 0 [N].
    EA : axial stiffness per segment [N], shape (n,) (None: inextensible).

    Returns a dict of arrays x, y, theta, tension, curvature (shape (m,)).
    """
    s = np.asarray(s, dtype=float)
    iEA = np.zeros(len(lengths)) if EA is None else 1.0 / np.asarray(EA, float)
    edges = np.concatenate([[0.0], np.cumsum(lengths)])
    # start values of each segment
    V_start = V0 + np.concatenate([[0.0], np.cumsum(np.asarray(weights) * lengths)])
    dx, dy = _segment_offsets(np.asarray(lengths, float), np.asarray(weights, float), H,
                              V_start[:-1], iEA)
    xs = x0 + np.concatenate([[0.0], np.cumsum(dx)])
    ys = y0 + np.concatenate([[0.0], np.cumsum(dy)])
    k = np.clip(np.searchsorted(edges, s, side="right") - 1, 0, len(lengths) - 1)
    ds = s - edges[k]
    w = np.asarray(weights)[k]
    Va = V_start[k]
    dx, dy = _segment_offsets(ds, w, H, Va, iEA[k])
    V = Va + w * ds
    T = np.hypot(H, V)
    return {"x": xs[k] + dx, "y": ys[k] + dy, "theta": np.arctan2(V, H), "tension": T,
            "curvature": w * H / T ** 2, "V": V}


def _segment_offsets(ds: np.ndarray, w, H: float, Va, iEA=0.0) -> tuple[np.ndarray, np.ndarray]:
    """Horizontal and vertical offsets after unstretched arc length ds along one segment
    (iEA = 1/EA [1/N], 0 when inextensible), in forms free of cancellation for a taut line
    (w ds << H) and of a division by w (exact for w = 0, a straight line):

        H/w (asinh b - asinh a) = ds asinh(z)/z D,  z = (w ds / H) D,
            D = (a + b) / (b sqrt(1 + a^2) + a sqrt(1 + b^2))     (a, b of one sign)
        H/w (sqrt(1 + b^2) - sqrt(1 + a^2)) = ds (a + b) / (sqrt(1 + a^2) + sqrt(1 + b^2))

    with a = Va/H, b = Vb/H (the first from asinh b - asinh a = asinh(b sqrt(1 + a^2) -
    a sqrt(1 + b^2)); where a and b differ in sign the plain difference has no
    cancellation)."""
    ds = np.asarray(ds, dtype=float)
    w = np.broadcast_to(np.asarray(w, dtype=float), ds.shape)
    Va = np.broadcast_to(np.asarray(Va, dtype=float), ds.shape)
    Vb = Va + w * ds
    a, b = Va / H, Vb / H
    ra, rb = np.hypot(1.0, a), np.hypot(1.0, b)
    dy = ds * (a + b) / (ra + rb)
    same = a * b >= 0.0
    flip = np.where(a + b < 0.0, -1.0, 1.0)            # both negative: mirror
    aa, bb = np.where(flip < 0, -b, a), np.where(flip < 0, -a, b)
    den = bb * np.hypot(1.0, aa) + aa * np.hypot(1.0, bb)
    D = np.where(den > 0.0, (aa + bb) / np.where(den > 0.0, den, 1.0), 1.0)
    z = np.abs(w) * ds / H * D
    zs = np.where(z > 1e-8, z, 1.0)
    ratio = np.where(z > 1e-8, np.arcsinh(zs) / zs, 1.0 - z * z / 6.0)
    wsafe = np.where(w != 0.0, w, 1.0)
    # evaluated everywhere, used only where the shear changes sign: on a near-weightless
    # segment elsewhere H / w overflows harmlessly (a RuntimeWarning the fuzzer met)
    with np.errstate(over="ignore", invalid="ignore"):
        plain = H / wsafe * (np.arcsinh(b) - np.arcsinh(a))
    dx = np.where(same, ds * ratio * D, plain)
    return dx + H * ds * iEA, dy + (2.0 * Va + w * ds) * ds * 0.5 * iEA


def end_offsets(w, L, H: float, V0: float, EA=None) -> tuple[float, float]:
    """(x, y) [m] of the end of a multi-segment catenary (weights ``w`` [N/m], lengths
    ``L`` [m], ``EA`` [N] per segment or None: inextensible) relative to its start, where
    the forces are (H, V0) [N]."""
    w, L = np.asarray(w, float), np.asarray(L, float)
    iEA = np.zeros(len(L)) if EA is None else 1.0 / np.asarray(EA, float)
    Va = V0 + np.concatenate([[0.0], np.cumsum(w * L)])[:-1]
    dx, dy = _segment_offsets(L, w, H, Va, iEA)
    return float(np.sum(dx)), float(np.sum(dy))


def end_offsets_rows(w, L, H) -> tuple[np.ndarray, np.ndarray]:
    """:func:`end_offsets` of many inextensible lines at once, each starting horizontal
    (V0 = 0): row i has the segment lengths ``L[i]`` [m] ((k, segments)) and the
    horizontal tension ``H[i]`` [N] ((k,)); the same weights ``w`` [N/m]. Returns the
    end's x and y [m], (k,) each."""
    L = np.asarray(L, float)
    w = np.asarray(w, float)
    H = np.asarray(H, float)[:, None]
    Va = np.zeros_like(L)
    np.cumsum((w * L)[:, :-1], axis=1, out=Va[:, 1:])
    dx, dy = _segment_offsets(L, w, H, Va)
    return dx.sum(axis=1), dy.sum(axis=1)


def horizontal_tensions(w, L, dy: float, lo: float, hi: float,
                        xtol: float = 1e-12) -> np.ndarray:
    """For each row of segment lengths ``L`` ((k, segments)) of a line starting
    horizontal: the horizontal tension H [N] whose end rises ``dy`` [m], found by
    bisection on log H in [``lo``, ``hi``] to ``xtol``, all rows at once; NaN where the
    end's height minus dy has one sign at both ends of the bracket."""
    L = np.asarray(L, float)
    k = L.shape[0]

    def f(lh):
        return end_offsets_rows(w, L, np.exp(lh))[1] - dy

    a, b = np.full(k, lo), np.full(k, hi)
    fa = f(a)
    ok = fa * f(b) <= 0.0
    while float(np.max(b - a)) > xtol:
        m = 0.5 * (a + b)
        fm = f(m)
        left = fa * fm <= 0.0
        b = np.where(left, m, b)
        a, fa = np.where(left, a, m), np.where(left, fa, fm)
    return np.where(ok, np.exp(0.5 * (a + b)), np.nan)


def pinned(w, L, dx: float, dy: float, EA=None) -> tuple[float, float] | None:
    """(H, V0) [N] of the catenary from a pinned end to another at (dx, dy) [m] from it
    (``w``, ``L``, ``EA`` as :func:`end_offsets`), or None when the search finds none.

    Two nested one-dimensional root finds on bracketed, monotone functions, valid from a
    slack line to a taut one that must stretch (where a least-squares fit in log H, the
    former search, stalls: the end moves by L/EA per newton of tension, 1e-6 m/N on a
    stiff line, far below its tolerance):

    - for a given H the end height rises monotonically with V0 (dy/dV0 = sum L/EA +
      (sin theta_b - sin theta_a)/w > 0 on every segment, buoyant ones included), from
      -inf to +inf on an extensible line (-L to L inextensible): V0(H) by bracketing;
    - along V0(H) the end's x rises with H, from the line hanging straight down (x -> 0 as
      H -> 0) to the line stretched out (x -> inf extensible; sqrt(L^2 - dy^2)
      inextensible): H by Brent's method on log H.

    Needs dx > 0 (the hang-off ahead of the anchor).
    """
    L = np.asarray(L, float)
    W = float(np.sum(np.abs(np.asarray(w, float)) * L)) or 1.0
    total = float(np.sum(np.asarray(w, float) * L))
    if not dx > 0.0:
        return None

    def height(H, V0):
        return end_offsets(w, L, H, V0, EA)[1] - dy

    def v0_of(H):
        # bracket the monotone height around the straight chord's V0, widening by 2x
        v = H * dy / dx - 0.5 * total
        step = max(W, H * abs(dy) / dx, 1e-12 * H, 1e-300)
        lo, hi = v - step, v + step
        for _ in range(200):
            if height(H, lo) <= 0.0:
                break
            lo, step = lo - step, 2.0 * step
        else:
            return None
        step = hi - v
        for _ in range(200):
            if height(H, hi) >= 0.0:
                break
            hi, step = hi + step, 2.0 * step
        else:
            return None
        return brentq(lambda v0: height(H, v0), lo, hi, xtol=1e-15 * (abs(lo) + abs(hi)),
                      rtol=4.0 * np.finfo(float).eps, maxiter=500)

    def reach(lh):
        H = math.exp(lh)
        v0 = v0_of(H)
        return math.nan if v0 is None else end_offsets(w, L, H, v0, EA)[0] - dx

    lo = math.log(1e-9 * W)
    hi = math.log(W)
    if not reach(lo) < 0.0:
        return None
    for _ in range(100):
        r = reach(hi)
        if r >= 0.0:
            break
        if math.isnan(r):
            return None
        lo, hi = hi, hi + math.log(10.0)
    else:
        return None
    lh = brentq(reach, lo, hi, xtol=1e-15, rtol=4.0 * np.finfo(float).eps, maxiter=500)
    H = math.exp(lh)
    V0 = v0_of(H)
    x, y = end_offsets(w, L, H, V0, EA)
    if abs(x - dx) + abs(y - dy) > 1e-9 * float(np.sum(L)):
        return None
    return H, V0

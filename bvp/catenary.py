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

import numpy as np


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
    xs = np.empty(len(lengths) + 1)
    ys = np.empty(len(lengths) + 1)
    xs[0], ys[0] = x0, y0
    for k, (w, L) in enumerate(zip(weights, lengths)):
        dx, dy = _segment_offsets(np.array([L]), w, H, V_start[k], iEA[k])
        xs[k + 1] = xs[k] + dx[0]
        ys[k + 1] = ys[k] + dy[0]
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
    (iEA = 1/EA [1/N], 0 when inextensible)."""
    ds = np.asarray(ds, dtype=float)
    w = np.broadcast_to(np.asarray(w, dtype=float), ds.shape)
    Va = np.broadcast_to(np.asarray(Va, dtype=float), ds.shape)
    Vb = Va + w * ds
    small = np.abs(w * ds) < 1e-9 * H
    wsafe = np.where(small, 1.0, w)
    dx = np.where(small, ds * H / np.hypot(H, Va),
                  H / wsafe * (np.arcsinh(Vb / H) - np.arcsinh(Va / H)))
    dy = np.where(small, ds * Va / np.hypot(H, Va),
                  H / wsafe * (np.hypot(1.0, Vb / H) - np.hypot(1.0, Va / H)))
    return dx + H * ds * iEA, dy + (2.0 * Va + w * ds) * ds * 0.5 * iEA


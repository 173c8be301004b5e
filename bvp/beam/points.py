"""Point attachments in the BVP (riser/model/attachments.py): jump conditions in the force.

The line's pieces (bvp/beam/problem.py) are split at every attachment, and the attachment
becomes a piece of its own of zero length: on it ds/dtau = a = 0, so x, y, theta and M
keep their values, while the coefficient products it carries over its tau width b,
a w = W / b (W = (m - rho V) g [N], its net weight) and a c_p = c_p / b (c_p = 0.5 rho
C_D A [kg/m]), make F and T change across it by exactly

    dF = -W cos(theta) - c_p |V| V sin(theta),   dT = W sin(theta) - c_p |V| V cos(theta)

(V the current along +x at the point's height): the internal force P = T t - F n jumps
by -f, f = (c_p |V| V, -W) the point force. The collocation integrates the piece exactly
(F and T are linear in tau there), so the jump is the jump conditions, not a smoothed
load. Such a piece has zero weight, drag and stretch of its own and the bending stiffness
of the line below it (a = 0: unused).
"""

from __future__ import annotations

import numpy as np

#: the length [m] a point's piece is given in the starting catenary (a zero-length
#: segment there would carry no weight; this one carries the point's)
GUESS_LENGTH = 1.0e-6


def split_at_points(scene, arrays: dict) -> dict:
    """The per-segment arrays (EI, EA, w, L, c_n, c_t: the scene's segments) with every
    attachment inserted as a piece of zero length, and the arrays point_w [N] and point_c
    [kg/m] (zero on the line's pieces); unchanged without attachments."""
    n = len(arrays["L"])
    out = {k: [] for k in (*arrays, "point_w", "point_c")}
    atts = sorted(scene.attachments, key=lambda a: a.s)
    g, rho = scene.gravity, scene.water_density
    edges = np.concatenate([[0.0], np.cumsum(arrays["L"])])

    def piece(k, length, pw=0.0, pc=0.0):
        for key, a in arrays.items():
            out[key].append(a[k])
        out["L"][-1] = length
        out["point_w"].append(pw)
        out["point_c"].append(pc)
        if pw or pc or length == 0.0:      # the point itself: no line load of its own
            out["w"][-1], out["c_n"][-1], out["c_t"][-1] = 0.0, 0.0, 0.0

    i = 0
    for k in range(n):
        at = edges[k]
        while i < len(atts) and atts[i].s < edges[k + 1]:
            a = atts[i]
            if a.s > at:
                piece(k, a.s - at)
            piece(k, 0.0, a.net_weight(g, rho), a.drag_coefficient(rho))
            at = a.s
            i += 1
        piece(k, edges[k + 1] - at)
    return {k: np.asarray(v, float) for k, v in out.items()}


def guess_arrays(w: np.ndarray, L: np.ndarray, point_w: np.ndarray):
    """(w, L) of the starting catenary: a point's piece of :data:`GUESS_LENGTH` carrying
    its weight (the catenary's vertical force jumps by it), the line's pieces as they are."""
    point = L == 0.0
    Lg = np.where(point, GUESS_LENGTH, L)
    wg = np.where(point, point_w / GUESS_LENGTH, w)
    return wg, Lg


def bending_weights(w: np.ndarray, L: np.ndarray) -> np.ndarray:
    """The weights [N/m] of the starting guess's bending terms: a point's piece takes the
    line's weight below it (the catenary's curvature w H / T^2 stays the line's there,
    where the point's short heavy guess segment would make it huge)."""
    out = np.asarray(w, float).copy()
    for k in np.flatnonzero(np.asarray(L) == 0.0):
        out[k] = out[k - 1] if k > 0 else (out[k + 1] if k + 1 < len(out) else 0.0)
    return out

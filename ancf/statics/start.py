"""The ANCF statics' starting shapes: the elastic catenary through the fixed ends (the
line without bending stiffness), or a straight line for the ends a catenary does not fit
(a vertical chord, a tensioned top, a free anchor). This package's own: the other
methods' starts are theirs.

Catenary (in the vertical plane of the ends, xi the horizontal distance from the anchor,
y up): with H the horizontal force and V(s) the vertical force at unstretched arc length
s, the effective tension is T = sqrt(H^2 + V^2), the stretch 1 + T/EA and
x' = (1 + T/EA) H / T, y' = (1 + T/EA) V / T, V' = w (the submerged weight per length).
An anchor on the seabed lets the line lie flat on it up to a touchdown s_t (V = 0 there,
V(s) = int_{s_t}^s w); otherwise V(s) = V_0 + int_0^s w. The two unknowns (H and s_t,
or H and V_0) put the end on the hang-off (least squares from a few starts). The nodes'
slopes are r' = (1 + T/EA) t, the tangent stretched by the strain.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import least_squares

from riser.model.frame import LinePlane
from riser.model.scene import Scene

from ..mesh import Mesh


def _integral(f: np.ndarray, s: np.ndarray) -> np.ndarray:
    out = np.zeros_like(f)
    out[1:] = np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(s))
    return out


def _fine(mesh: Mesh, step: float = 0.5):
    """A fine grid along the line with the weight and EA on it (by element)."""
    L = float(mesh.s[-1])
    m = max(400, int(math.ceil(L / step)))
    sg = np.linspace(0.0, L, m + 1)
    e = np.clip(np.searchsorted(mesh.s, sg, side="right") - 1, 0, mesh.ne - 1)
    w = mesh.weight[e].copy()
    return sg, w, mesh.EA[e], e


def catenary_start(scene: Scene, mesh: Mesh, d: int):
    """(q (n, 2 d) the positions and slopes at the nodes, T (n,) the catenary's tension
    [N], misfit [m]) of the elastic catenary through the scene's fixed ends. Point
    weights are spread over their element (a start only)."""
    e = scene.ends
    a3 = np.asarray(e.anchor_point, float)
    h3 = np.asarray(e.hang_off_point, float)
    plane = LinePlane.of(scene)
    span = math.hypot(h3[0] - a3[0], h3[2] - a3[2])
    a = np.array([0.0, a3[1]])
    h = np.array([span, h3[1]])
    sg, w, ea, el = _fine(mesh)
    # the point attachments' weights smeared over their elements, a start only
    for i in np.nonzero(mesh.point_weight)[0]:
        k = min(i, mesh.ne - 1)
        w = np.where(el == k, w + mesh.point_weight[i] / mesh.l0[k], w)
    L = float(sg[-1])
    W = _integral(w, sg)
    chord = float(np.hypot(*(h - a)))
    wref = float(np.mean(np.abs(w)))
    wref = wref if wref > 1e-9 else 1.0
    on_seabed = scene.seabed is not None and a[1] <= 1e-9

    def shape(p):
        H = abs(p[0]) * wref * chord + 1e-12
        if on_seabed and p[1] >= 0.0:
            st = min(p[1], 1.0) * L
            V = np.where(sg < st, 0.0, W - np.interp(st, sg, W))
        elif on_seabed:
            V = W - p[1] * L * wref
        else:
            V = W + p[1] * wref * chord
        T = np.sqrt(H * H + V * V)
        f = 1.0 + T / ea
        return a[0] + _integral(f * H / T, sg), a[1] + _integral(f * V / T, sg), H, V, T

    def resid(p):
        x, y, *_ = shape(p)
        return np.array([x[-1] - h[0], y[-1] - h[1]]) / chord

    best = None
    for g1 in (0.05, 0.2, 0.5, 1.0, 3.0):
        for g2 in ((0.0, 0.1, 0.25, 0.5, -0.1) if on_seabed else (-1.0, -0.3, 0.0, 0.3)):
            sol = least_squares(resid, [g1, g2], method="lm", xtol=1e-13, ftol=1e-13)
            err = float(np.max(np.abs(sol.fun)))
            if best is None or err < best[0]:
                best = (err, sol.x)
        if best[0] < 1e-10:
            break
    err, p = best
    x, y, H, V, T = shape(p)
    if scene.seabed is not None:            # a buoyant line's catenary below the seabed
        y = np.maximum(y, 0.0)
    xs, ys = np.interp(mesh.s, sg, x), np.interp(mesh.s, sg, y)
    Tn = np.interp(mesh.s, sg, T)
    str_ = 1.0 + Tn / np.interp(mesh.s, sg, ea)
    cx, cy = np.interp(mesh.s, sg, H / T), np.interp(mesh.s, sg, V / T)
    if scene.seabed is not None:
        flat = ys <= 0.0
        cy = np.where(flat, 0.0, cy)
        cx = np.where(flat, 1.0, cx)
    nrm = np.hypot(cx, cy)
    cx, cy = cx / nrm, cy / nrm
    q = np.zeros((mesh.n, 2 * d))
    X, Z = plane.from_plane(xs, 0.0)
    tX, tZ = plane.vector_from_plane(cx, 0.0)
    q[:, 0], q[:, 1] = X, ys
    q[:, d], q[:, d + 1] = str_ * tX, str_ * cy
    if d == 3:
        q[:, 2], q[:, 5] = Z, str_ * tZ
    q[0, :d] = a3[:d]
    q[-1, :d] = h3[:d]
    return q, Tn, err * chord


def needs_straight_start(scene: Scene) -> bool:
    """A vertical chord, a tensioner or a free anchor: no catenary through the ends."""
    e = scene.ends
    return (e.tensioner is not None or e.free_anchor
            or e.anchor_point[0] == e.hang_off_point[0]
            and e.anchor_point[2] == e.hang_off_point[2])


def straight_start(scene: Scene, mesh: Mesh, d: int):
    """(q (n, 2 d), T (n,) [N]) of a straight line stretched by a vertical line's tension
    T(s) = T_0 + int_0^s w: a free anchor hangs straight down from the hang-off (T_0 = 0),
    a tensioned line rises from the anchor with the tensioner's pull at the top, and a
    line between fixed ends lies on the chord with the T_0 whose stretch fits it."""
    e = scene.ends
    w_nodes = np.concatenate([[0.0], np.cumsum(mesh.weight * mesh.l0)])
    w_nodes += np.cumsum(mesh.point_weight) - mesh.point_weight
    ea = np.concatenate([mesh.EA, mesh.EA[-1:]])
    a, h = np.asarray(e.anchor_point, float), np.asarray(e.hang_off_point, float)
    if e.free_anchor:
        T = w_nodes
    elif e.tensioner is not None:
        T = w_nodes + e.tensioner.top_tension - w_nodes[-1]
    else:
        chord = float(np.linalg.norm(h - a))
        # the stretched length sum l0 (1 + (T0 + W) / EA) = chord, solved for T0
        mid = 0.5 * (w_nodes[1:] + w_nodes[:-1])
        T0 = (chord - float(np.sum(mesh.l0)) - float(np.sum(mesh.l0 * mid / mesh.EA))) / float(
            np.sum(mesh.l0 / mesh.EA))
        T = w_nodes + T0
    Tm = 0.5 * (T[1:] + T[:-1])
    stretched = np.concatenate([[0.0], np.cumsum(mesh.l0 * (1.0 + Tm / mesh.EA))])
    if e.free_anchor:
        u = np.array([0.0, 1.0, 0.0])
        start = h - stretched[-1] * u
    else:
        u = (h - a) / np.linalg.norm(h - a)
        if e.tensioner is not None:
            horiz = math.hypot(h[0] - a[0], h[2] - a[2])
            up = math.sqrt(max(stretched[-1] ** 2 - horiz ** 2, 0.0))
            u = np.array([h[0] - a[0], up, h[2] - a[2]])
            u /= np.linalg.norm(u)
        start = a
    X = start[None, :] + stretched[:, None] * u[None, :]
    q = np.zeros((mesh.n, 2 * d))
    q[:, :d] = X[:, :d]
    q[:, d:] = (1.0 + T / ea)[:, None] * u[None, :d]
    if not e.free_anchor:
        q[0, :d] = a[:d]
    if e.tensioner is None:
        q[-1, :d] = h[:d]
    return q, T

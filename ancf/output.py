"""The ANCF's results along the line: the static :class:`riser.results.profile.Profile`
read off the element fields.

The profile is sampled at the nodes and at ``sub`` - 1 equally spaced points inside each
element (spacing at most :data:`OUTPUT_SPACING`), positions and tangents the elements'
own. The internal forces are not read off the elements' strain and curvature: a cubic
element's EA (|r'| - 1) oscillates along it where the line bends (up to 0.6 % of the
tension inside the end element of a flex-jointed lazy wave at 2 m) and its EI kappa at the nodes
carries the interpolation's error (0.6 % of the joint's moment). They are the section
forces (:func:`section_forces`): at each node the force and moment the rest of the line
exerts, from the elements' own nodal forces, which satisfy the discrete equilibrium
exactly (within 0.01 % there), and between nodes a cubic spline through them. The
tension is the force along the tangent, the shear its part across it, the curvature
|M| / EI (the larger side's at a change of EI).

Moment vector: m = EI t x t' = EI (r' x r'') / |r'|^2 (per unstretched length, the
moment of the BVP's rod; a planar line's signed moment is its z component).
"""

from __future__ import annotations

import numpy as np
from scipy.interpolate import CubicSpline

from riser.model.frame import LinePlane, elevation, plane_columns
from riser.physics.internal_flow import wall_tension
from riser.results.profile import Profile

from .element import element_fields

#: the largest spacing [m] of the profile's samples
OUTPUT_SPACING = 0.5


def _moment_vector(a: np.ndarray, b: np.ndarray, EI: float) -> np.ndarray:
    a3 = np.zeros(3)
    b3 = np.zeros(3)
    a3[:len(a)] = a
    b3[:len(b)] = b
    return EI * np.cross(a3, b3) / float(a3 @ a3)


def _pad(v: np.ndarray) -> np.ndarray:
    out = np.zeros((v.shape[0], 3))
    out[:, :v.shape[1]] = v
    return out


def section_forces(model, q: np.ndarray, v: np.ndarray | None = None,
                   inertia: np.ndarray | None = None, sides: bool = False):
    """(F (n, 3) [N], m (n, 3) [N m]) at the nodes: the force and the bending moment the
    line beyond a node exerts on the line before it, from the elements' own nodal forces
    (:meth:`ancf.model.Model.element_forces`; the mean of the two sides at an interior
    node, which differ by a point load). The moment from the slope's generalised force G:
    with r' = (1 + eps) t, G . dr' = (1 + eps) (t x G) . dtheta, so m = (1 + eps) t x G.
    With ``sides`` also the two sides' own values, (F, m) from the element before each
    node and (F, m) from the element after it (an end: its one element's)."""
    d, n = model.d, model.mesh.n
    g = model.element_forces(q, v, inertia)
    left_r, left_s = -g[:, :d], -g[:, d:2 * d]            # at each element's first node
    right_r, right_s = g[:, 2 * d:3 * d], g[:, 3 * d:]    # at its second node
    a = q.reshape(n, 2 * d)[:, d:]
    stretch = np.linalg.norm(a, axis=1)
    t = _pad(a / stretch[:, None])

    def moment(G):
        return stretch[:, None] * np.cross(t, _pad(G))

    # each node's two sides: from the element before it (its second node) and after it
    before_F, before_G = np.full((n, d), np.nan), np.full((n, d), np.nan)
    after_F, after_G = np.full((n, d), np.nan), np.full((n, d), np.nan)
    before_F[1:], before_G[1:] = right_r, right_s
    after_F[:-1], after_G[:-1] = left_r, left_s
    before_F[0], before_G[0] = after_F[0], after_G[0]
    after_F[-1], after_G[-1] = before_F[-1], before_G[-1]
    F = 0.5 * (before_F + after_F)
    G = 0.5 * (before_G + after_G)
    if not sides:
        return _pad(F), moment(G)
    return (_pad(F), moment(G), (_pad(before_F), moment(before_G)),
            (_pad(after_F), moment(after_G)))


def samples(model, q: np.ndarray) -> dict:
    """Arrays along the line at the sample points: s, r (k, 3), t (k, 3) unit tangents,
    tension, moment vectors (k, 3), curvature, and ``node`` (k,) bool. Positions and
    tangents are the elements'; the tension and the moment at the nodes are the section
    forces' (:func:`section_forces`: the elements' own fields at the nodes carry the
    interpolation's error, 0.6 % of a flex joint's moment at 2 m where the section force
    is within 0.01 %), between them a cubic spline through the nodal values of each run
    of nodes without a joint (a point load or a change of section: a kink)."""
    mesh, d = model.mesh, model.d
    z0 = float(model.scene.ends.anchor_point[2])
    F, m_nodes, before, after = section_forces(model, q, sides=True)
    sub = np.maximum(1, np.ceil(mesh.l0 / OUTPUT_SPACING - 1e-9).astype(int))
    s_list, r_list, a_list, e_list = [], [], [], []
    for e in range(mesh.ne):
        for j in range(sub[e]):
            xi = j / sub[e]
            r, a, _, _, _ = element_fields(q, d, mesh.l0, mesh.EA, mesh.EI, e, xi)
            s_list.append(mesh.s[e] + xi * mesh.l0[e])
            r_list.append(r)
            a_list.append(a)
            e_list.append(e)
    r, a, _, _, _ = element_fields(q, d, mesh.l0, mesh.EA, mesh.EI, mesh.ne - 1, 1.0)
    s_list.append(mesh.s[-1])
    r_list.append(r)
    a_list.append(a)
    e_list.append(mesh.ne - 1)
    s = np.array(s_list)
    X = np.zeros((len(s), 3))
    X[:, :d] = r_list
    if d == 2:
        X[:, 2] = z0
    t = _pad(np.array(a_list))
    t /= np.linalg.norm(t, axis=1)[:, None]
    node = np.isin(s, mesh.s)
    # the tension, the shear vector and the moment vector at the nodes (the nodes' own
    # tangents), between them splines over runs without a joint; the tension not from the
    # force's spline and the element's tangent inside the element: next to a kink that
    # tangent turns by a few degrees more than the line (400 N of 277 kN beside a chain's
    # clump weight)
    tn = np.zeros((mesh.n, 3))
    tn[:, :d] = q.reshape(mesh.n, 2 * d)[:, d:]
    tn /= np.linalg.norm(tn, axis=1)[:, None]
    def split(F_, m_):
        T_ = np.einsum("ij,ij->i", F_, tn)
        return T_[:, None], F_ - T_[:, None] * tn, m_

    T_nodes, Q_nodes, _ = split(F, m_nodes)
    T_nodes = T_nodes[:, 0]
    T_b, Q_b, m_b = split(*before)
    T_a, Q_a, m_a = split(*after)
    Ts = np.zeros((len(s), 1))
    Qs = np.zeros((len(s), 3))
    ms = np.zeros((len(s), 3))
    breaks = [0, *np.nonzero(mesh.joints)[0].tolist(), mesh.n - 1]
    for i0, i1 in zip(breaks[:-1], breaks[1:]):
        sel = (s >= mesh.s[i0]) & (s <= mesh.s[i1])
        knots = mesh.s[i0:i1 + 1]
        # the run's end knots take their own side's value (a joint's jump is not smeared
        # into the spline); its inner knots the mean of the two sides (equal there)
        runs = []
        for mean, b_, a_ in ((T_nodes[:, None], T_b, T_a), (Q_nodes, Q_b, Q_a),
                             (m_nodes, m_b, m_a)):
            vals = mean[i0:i1 + 1].copy()
            vals[0] = a_[i0]
            vals[-1] = b_[i1]
            runs.append(vals)
        for arr, vals in zip((Ts, Qs, ms), runs):
            if len(knots) >= 4:
                arr[sel] = CubicSpline(knots, vals, axis=0)(s[sel])
            else:
                for c in range(arr.shape[1]):
                    arr[sel, c] = np.interp(s[sel], knots, vals[:, c])
    # the nodes' own values (a joint: the mean of the two sides)
    idx = np.searchsorted(s, mesh.s)
    Ts[idx, 0] = T_nodes
    Qs[idx] = Q_nodes
    ms[idx] = m_nodes
    tension = Ts[:, 0]
    EI = mesh.EI[np.array(e_list)]
    curvature = np.linalg.norm(ms, axis=1) / EI
    # at a node where EI changes: the larger of the two sides' |M| / EI
    for i in np.nonzero(mesh.joints)[0]:
        curvature[idx[i]] = np.linalg.norm(m_nodes[i]) / min(mesh.EI[i - 1], mesh.EI[i])
    return {"s": s, "r": X, "t": t, "tension": tension, "m": ms, "shear": Qs,
            "curvature": curvature, "node": node}


def touchdown_s(s: np.ndarray, y: np.ndarray, has_seabed: bool) -> float | None:
    """Arc length [m] of the touchdown: the end towards the hang-off of the first contact
    zone from the bottom (y <= 0), at the linear crossing of y = 0 after it; None without
    a seabed or contact."""
    if not has_seabed:
        return None
    on = np.flatnonzero(y <= 0.0)
    if on.size == 0:
        return None
    i = on[0]
    while i + 1 < len(y) and y[i + 1] <= 0.0:
        i += 1
    if i + 1 < len(y):
        return float(s[i] + (0.0 - y[i]) / (y[i + 1] - y[i]) * (s[i + 1] - s[i]))
    return float(s[i])


def make_profile(model, q: np.ndarray) -> Profile:
    """The static profile of the state ``q`` (module docstring). A static state out of the
    line's plane (3D) carries ``lateral``, ``moment_in_plane`` and
    ``moment_out_of_plane``."""
    scene = model.scene
    sm = samples(model, q)
    s, X, t, m = sm["s"], sm["r"], sm["t"], sm["m"]
    plane = LinePlane.of(scene)
    shear_vec = sm["shear"]
    lateral = inplane = oop = None
    if model.d == 3 and not scene.statics_planar:
        lateral, inplane, oop = plane_columns(plane, X[:, 0], X[:, 2], t, m)
    wall = (wall_tension(scene, s, X[:, 1], sm["tension"])
            if scene.internal_flow is not None else None)
    return Profile(s=s, x=X[:, 0], y=X[:, 1], z=X[:, 2], theta=elevation(plane, t),
                   tension=sm["tension"], moment=np.linalg.norm(m, axis=1),
                   shear=np.linalg.norm(shear_vec, axis=1), curvature=sm["curvature"],
                   tdp_s=touchdown_s(s, X[:, 1], scene.seabed is not None),
                   wall_tension=wall, lateral=lateral, moment_in_plane=inplane,
                   moment_out_of_plane=oop)

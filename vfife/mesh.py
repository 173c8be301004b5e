"""Discretisation of a fixed-ends scene into VFIFE nodes and elements, and starting shapes.

Elements never straddle a segment joint: each segment of length L gets ceil(L / h)
equal elements. Element properties come from :func:`riser.model.sections.segment_properties`
(computed once for both solvers); nodal masses, weights, drag coefficients and inertias
are lumped half-and-half from the two adjacent elements.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import least_squares

from riser.model.frame import LinePlane
from riser.model.scene import Scene
from riser.model.sections import segment_properties

from .end_conditions import end_array

#: [N/m] a submerged weight below which the starting catenary is that of a weightless line
WEIGHTLESS = 1e-6


@dataclass
class Mesh:
    """Nodes i = 0..n-1 (anchor first) and elements e = 0..n-2.

    s : (n,) unstretched arc length of the nodes [m].
    l0, EA, EI, mass_pl, weight_pl, rot_pl, added_pl, cdn_pl, cdt_pl, fluid_pl : (ne,)
        element length [m] and per-length section values (EA [N], EI [N m2], mass [kg/m],
        submerged weight [N/m, + down], diametral rotary inertia [kg m], added mass [kg/m],
        drag coefficients 0.5 rho D C_D [kg/m2], the water of the hydrodynamic section rho
        pi D^2 / 4 [kg/m], riser.model.sections).
    BA : (ne,) internal axial damping [N s] (the line type's ``axial_damping``: the axial
        force gains BA d(eps)/dt in the dynamics); None is read as zeros.
    trib : (n,) tributary length of the nodes [m]; :meth:`lump` gives the other nodal
        values.
    end_springs : the rotational stiffness [N m/rad] of the flex joints at the anchor
        (node 0) and the hang-off (node n - 1), 0 without one (their nodes' stable step).
    point_weight, point_mass, point_added, point_drag : (n,) the point attachments on the
        nodes (riser/model/attachments.py; a node at each): net weight [N, + down], mass [kg],
        added mass C_a rho V [kg], drag 0.5 rho C_D A [kg/m]; zeros without (None is
        read as zeros).
    """

    s: np.ndarray
    l0: np.ndarray
    EA: np.ndarray
    EI: np.ndarray
    mass_pl: np.ndarray
    weight_pl: np.ndarray
    rot_pl: np.ndarray
    added_pl: np.ndarray
    cdn_pl: np.ndarray
    cdt_pl: np.ndarray
    fluid_pl: np.ndarray
    end_springs: tuple = (0.0, 0.0)
    point_weight: np.ndarray | None = None
    point_mass: np.ndarray | None = None
    point_added: np.ndarray | None = None
    point_drag: np.ndarray | None = None
    BA: np.ndarray | None = None

    def __post_init__(self) -> None:
        if self.BA is None:
            self.BA = np.zeros(len(self.l0))
        for name in ("point_weight", "point_mass", "point_added", "point_drag"):
            if getattr(self, name) is None:
                setattr(self, name, np.zeros(len(self.s)))

    @property
    def point_nodes(self) -> np.ndarray:
        """(n,) bool: the nodes that carry a point attachment."""
        return ((self.point_weight != 0.0) | (self.point_mass != 0.0)
                | (self.point_added != 0.0) | (self.point_drag != 0.0))

    @property
    def n(self) -> int:
        return len(self.s)

    @property
    def ne(self) -> int:
        return len(self.l0)

    def lump(self, per_length: np.ndarray) -> np.ndarray:
        """Nodal lumping of an element per-length quantity: half of q*l0 to each end."""
        q = per_length * self.l0
        out = np.zeros(self.n)
        out[:-1] += 0.5 * q
        out[1:] += 0.5 * q
        return out

    @property
    def trib(self) -> np.ndarray:
        return self.lump(np.ones(self.ne))


def build_mesh(scene: Scene, element_length: float) -> Mesh:
    """Mesh ``scene`` with elements of at most ``element_length`` [m]."""
    props = segment_properties(scene)
    cols: dict[str, list] = {k: [] for k in ("l0", "EA", "EI", "mass_pl", "weight_pl", "rot_pl",
                                             "added_pl", "cdn_pl", "cdt_pl", "fluid_pl",
                                             "BA")}
    s = [0.0]
    # attachments at one point (or within 1e-6 of an element of each other) share a node:
    # a zero-length element between them has no direction (NaN) and no stable step
    cuts: list[float] = []
    for c in sorted(a.s for a in scene.attachments):
        if not cuts or c - cuts[-1] > 1e-6 * element_length:
            cuts.append(c)
    for p in props:
        # a node at every attachment inside the segment: the spans between them meshed
        # alike
        edges = [p.s_start, *(c for c in cuts if p.s_start < c < p.s_end), p.s_end]
        les = []
        for a, b in zip(edges[:-1], edges[1:]):
            k = max(1, int(math.ceil((b - a) / element_length - 1e-9)))
            les += [(b - a) / k] * k
        ne = len(les)
        for le in les:
            s.append(s[-1] + le)
        cols["l0"] += les
        cols["EA"] += [p.EA] * ne
        cols["EI"] += [p.EI] * ne
        cols["mass_pl"] += [p.mass] * ne
        cols["weight_pl"] += [p.weight] * ne
        cols["rot_pl"] += [0.5 * p.rotary_inertia] * ne      # diametral = polar / 2
        cols["added_pl"] += [p.added_mass] * ne
        cols["cdn_pl"] += [p.drag_normal_coef] * ne
        cols["cdt_pl"] += [p.drag_tangential_coef] * ne
        cols["fluid_pl"] += [p.fluid_mass] * ne
        cols["BA"] += [p.BA] * ne
    arrays = {k: np.asarray(v, dtype=float) for k, v in cols.items()}
    s_arr = np.asarray(s)
    s_arr[-1] = props[-1].s_end
    ends = end_array(scene)                # the flex joints' stiffnesses: slots 0 and 2
    return Mesh(s=s_arr, **arrays, end_springs=(float(ends[0]), float(ends[2])),
                **_points(scene, s_arr))


def _points(scene: Scene, s: np.ndarray) -> dict:
    """The point attachments' nodal arrays (see :class:`Mesh`) on the nodes ``s`` [m]."""
    out = {k: np.zeros(len(s)) for k in ("point_weight", "point_mass", "point_added",
                                         "point_drag")}
    g, rho = scene.gravity, scene.water_density
    for a in scene.attachments:
        i = int(np.argmin(np.abs(s - a.s)))
        out["point_weight"][i] += a.net_weight(g, rho)
        out["point_mass"][i] += a.mass
        out["point_added"][i] += a.added_mass(rho)
        out["point_drag"][i] += a.drag_coefficient(rho)
    return out


# ----------------------------------------------------------------- starting shape
def _cumtrapz(y: np.ndarray, x: np.ndarray) -> np.ndarray:
    out = np.zeros_like(y)
    out[1:] = np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(x))
    return out


def catenary_shape(scene: Scene, s_nodes: np.ndarray, grid_step: float = 1.0,
                   uniform_weight: float | None = None):
    """Multi-segment extensible catenary through the scene's fixed ends (no bending).

    With a seabed and the anchor on it (y = 0), the line lies straight on the seabed from
    the anchor to a touchdown arc length s_t, then hangs as a catenary with horizontal
    force H: V(s) = integral of w from s_t, x' = (1 + T/EA) H/T, y' = (1 + T/EA) V/T;
    a line buoyant enough to lift off at the anchor (s_t "negative") has an upward force
    V(0) > 0 there instead (hard-large-buoyancy: without that branch the fit stopped at
    s_t = 0 with the end 120 m off the hang-off, and the relaxation diverged at step 1).
    Otherwise the line hangs from the anchor with the unknown vertical force V0 there.
    The two unknowns are found by least squares so the end lands on the hang-off.
    The catenary lies in the vertical plane through the two ends (x, y for ends in one
    plane z = const, which keeps their z; else :class:`riser.model.frame.LinePlane`: it is
    computed in (xi, y), xi the horizontal distance from the anchor along the plane, and
    positions and tangents are mapped back to (x, z)); node 0 is put on the anchor and the
    last node on the hang-off.
    ``uniform_weight`` [N/m]: the shape of a line of that uniform submerged weight instead
    of the scene's (the start of a continuation in the weight, see
    :func:`vfife.statics.equilibrium.solve_static`).
    Returns (X (n, 3), D (n, 3) unit tangents, info dict; info 'catenary_below_seabed_m':
    how far the EI = 0 shape passed below the seabed before it was clamped onto it).
    """
    props = segment_properties(scene)
    ends = scene.ends
    a3 = np.asarray(ends.anchor_point, float)
    h3 = np.asarray(ends.hang_off_point, float)
    plane = None if ends.in_plane else LinePlane.of(scene)
    if plane is None:              # (x, y) as given: the planar arithmetic unchanged
        a, h = a3[:2].copy(), h3[:2].copy()
    else:                          # (xi, y) in the plane, xi from the anchor
        a = np.array([0.0, a3[1]])
        h = np.array([math.hypot(h3[0] - a3[0], h3[2] - a3[2]), h3[1]])
    L = scene.total_length
    m = max(200, int(math.ceil(L / grid_step)))
    sg = np.linspace(0.0, L, m + 1)
    w = np.empty_like(sg)
    ea = np.empty_like(sg)
    for p in props:
        sel = (sg >= p.s_start - 1e-9)
        w[sel] = p.weight if uniform_weight is None else uniform_weight
        ea[sel] = p.EA
    on_seabed = scene.seabed is not None and a[1] <= 1e-9
    W = _cumtrapz(w, sg)          # integral of w from the anchor
    span = h - a
    chord = float(np.hypot(*span))
    # the weights' scale of the unknowns; a line of negligible weight (below 1 uN/m, e.g.
    # -4e-226 N/m given) is shaped as weightless: its scale squared underflowed to a zero
    # tension (NaN shapes at every start, and no start at all: a TypeError, fuzzing)
    wref = float(np.mean(np.abs(w)))
    wref = wref if wref > WEIGHTLESS else 1.0

    def shape(params):
        H = abs(params[0]) * wref * chord
        if on_seabed and params[1] >= 0.0:
            st = min(params[1], 1.0) * L
            V = W - np.interp(st, sg, W)
            V = np.where(sg < st, 0.0, V)
        elif on_seabed:
            # lift-off at the anchor (a strongly buoyant line): an upward force there,
            # continuous with the touchdown branch at params[1] = 0
            V = W - params[1] * L * wref
        else:
            V = W + params[1] * wref * chord
        T = np.sqrt(H * H + V * V)
        f = 1.0 + T / ea
        x = a[0] + _cumtrapz(f * H / T, sg)
        y = a[1] + _cumtrapz(f * V / T, sg)
        return x, y, H, V, T

    def resid(params):
        x, y, *_ = shape(params)
        return np.array([x[-1] - h[0], y[-1] - h[1]]) / chord

    best = None
    guesses_2 = ((0.0, 0.1, 0.2, 0.35, 0.5, -0.05, -0.2) if on_seabed
                 else (-1.0, -0.3, 0.0, 0.3))
    for g1 in (0.05, 0.2, 0.5, 1.0, 3.0):
        for g2 in guesses_2:
            try:
                sol = least_squares(resid, [g1, g2], method="lm", xtol=1e-12, ftol=1e-12)
            except Exception:   # pragma: no cover - a bad start
                continue
            err = float(np.max(np.abs(sol.fun)))
            if best is None or err < best[0]:
                best = (err, sol.x)
        if best is not None and best[0] < 1e-9:
            break
    err, params = best
    x, y, H, V, T = shape(params)
    X = np.zeros((len(s_nodes), 3))
    X[:, 0] = np.interp(s_nodes, sg, x)
    X[:, 1] = np.interp(s_nodes, sg, y)
    X[-1, :2] = h
    X[0, :2] = a
    D = np.zeros_like(X)
    D[:, 0] = np.interp(s_nodes, sg, H / T)
    D[:, 1] = np.interp(s_nodes, sg, V / T)
    below_m = float(max(0.0, -np.min(y))) if scene.seabed is not None else 0.0
    if scene.seabed is not None:
        # the EI = 0 catenary of a buoyant line can dip below the seabed (a second
        # touchdown): start those nodes on the seabed, lying flat, instead of metres deep
        # in a stiff penalty spring (which launched them at step 1)
        below = X[:, 1] < 0.0
        X[below, 1] = 0.0
        D[below, 1] = 0.0
        D[below, 0] = np.where(D[below, 0] == 0.0, 1.0, D[below, 0])
    if plane is None:
        X[:, 2] = a3[2]
    else:                          # (xi, y) -> (x, y, z); tangents rotated alike
        X[:, 0], X[:, 2] = plane.from_plane(X[:, 0], 0.0)
        D[:, 0], D[:, 2] = plane.vector_from_plane(D[:, 0], 0.0)
    X[0] = a3
    X[-1] = h3
    D /= np.linalg.norm(D, axis=1)[:, None]
    smid = 0.5 * (s_nodes[1:] + s_nodes[:-1])
    info = {"catenary_misfit_m": err * chord, "catenary_H": H,
            "catenary_below_seabed_m": below_m,
            "element_tension": np.interp(smid, sg, T),
            "catenary_tdp_s": (min(max(params[1], 0.0), 1.0) * L)
            if on_seabed and params[1] >= 0.0 else None}
    return X, D, info


def interpolate_state(s_from: np.ndarray, X: np.ndarray, s_to: np.ndarray):
    """Positions on a new mesh by a cubic spline of the old positions in unstretched arc
    length (so the stretch carries over), directors from the spline's tangent."""
    cs = CubicSpline(s_from, X, axis=0, bc_type="not-a-knot")
    Xn = cs(s_to)
    Dn = cs(s_to, 1)
    Dn /= np.linalg.norm(Dn, axis=1)[:, None]
    Xn[0] = X[0]
    Xn[-1] = X[-1]
    return Xn, Dn


def length_consistent(X: np.ndarray, lengths: np.ndarray, free: np.ndarray | None = None,
                      iterations: int = 8) -> np.ndarray:
    """Positions with the element chords of ``X`` (n, 3) re-scaled to exactly ``lengths``
    (ne,) [m], chained from the anchor X[0], the end kept on X[-1] by small rotations of
    the chords of the ``free`` elements (minimum-norm, Gauss-Newton).

    Why: a starting shape sampled from a catenary or interpolated from a coarse mesh has
    chord-length errors ~ (l kappa)^2 / 24 (up to 7 % next to a kink of the coarse
    touchdown) that cost EA x error of out-of-balance force: nothing for the soft
    bending, but with a stiff line (EA x100) it starts the relaxation with forces of
    1e2-1e6 element weights, launches the nodes and excites every mode, so the relaxation
    takes many more than sqrt(EA) x the steps, or diverges. Elements lying on the seabed
    are left straight (``free`` False) so that the rotations do not push nodes into it.
    """
    X = np.asarray(X, float)
    L = np.asarray(lengths, float)
    target = X[-1].copy()
    t = np.diff(X, axis=0)
    t /= np.linalg.norm(t, axis=1)[:, None]
    w = np.ones(len(L)) if free is None else np.asarray(free, float)
    if not np.any(w > 0.0):
        w = np.ones(len(L))
    tol = 1e-13 * float(np.sum(L))
    for _ in range(iterations):
        P = X[0] + np.concatenate([np.zeros((1, 3)), np.cumsum(L[:, None] * t, axis=0)])
        gap = P[-1] - target
        if float(np.linalg.norm(gap)) <= tol:
            break
        wl2 = w * L * L
        A = np.einsum("e,ij->ij", wl2, np.eye(3)) - np.einsum("e,ei,ej->ij", wl2, t, t)
        lam = -np.linalg.lstsq(A, gap, rcond=1e-12)[0]
        phi = (w * L)[:, None] * np.cross(t, lam)
        t = t + np.cross(phi, t)
        t /= np.linalg.norm(t, axis=1)[:, None]
    P = X[0] + np.concatenate([np.zeros((1, 3)), np.cumsum(L[:, None] * t, axis=0)])
    P[-1] = target
    return P

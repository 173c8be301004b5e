"""The ANCF model of a fixed-ends scene: its mesh, ends and loads as arrays, and the
assembly of the residual and its tangent (the kernels of :mod:`ancf.element` and
:mod:`ancf.loads`, the ends of :mod:`ancf.ends`).

Residual of the equilibrium R(q) = F_int(q) - F_ext(q) [N, and N m at the slopes], F_int
the elastic forces (the strain energy's gradient), F_ext the loads: the submerged weight
(constant, consistent: int N^T (0, -w) ds), the point attachments' net weights at their
nodes, an optional dead load, the seabed and drag (state-dependent). Only the effects the
scene calls for run: no drag kernel without a current (statics) or drag coefficients
(dynamics), no seabed kernel without a seabed.
"""

from __future__ import annotations

import numpy as np

from riser.model.scene import Scene

from . import banded
from .element import damping_pass, elastic_pass, shape
from .ends import EndConditions, end_conditions, end_energy, rotate, unrotate
from .flow import Flow, frozen_slug_weight
from .loads import Drag, Seabed, Surface, Waves, load_pass
from .mesh import Mesh


def gauss(count: int):
    """Gauss-Legendre points and weights on [0, 1]."""
    x, w = np.polynomial.legendre.leggauss(count)
    return 0.5 * (x + 1.0), 0.5 * w


def consistent_load(mesh: Mesh, d: int, f: np.ndarray, xg, wg) -> np.ndarray:
    """int N^T f ds of a load f (ne, d) [N/m] uniform on each element, per element
    (ne, 4 d)."""
    out = np.zeros((mesh.ne, 4 * d))
    for gp in range(len(xg)):
        for e in range(mesh.ne):
            N, _, _ = shape(xg[gp], mesh.l0[e])
            w = wg[gp] * mesh.l0[e]
            for k in range(4):
                out[e, k * d:k * d + d] += w * N[k] * f[e]
    return out


def scatter(per_element: np.ndarray, n: int, d: int) -> np.ndarray:
    """The global vector (N,) of element vectors (ne, 4 d) (nodes shared by neighbours)."""
    out = np.zeros(n * 2 * d)
    nd = 2 * d
    for e in range(per_element.shape[0]):
        out[e * nd:e * nd + 2 * nd] += per_element[e]
    return out


class Model:
    """The arrays of one mesh in dimension ``d`` (2: the x-y plane, z the anchor's; 3).

    scene, mesh : the fixed-ends scene and its mesh; d : 2 or 3.
    current : load the line with the scene's current (statics: a current of non-zero
        speed; the drag kernel runs only then).
    dynamic : a time domain: the drag kernel runs whenever the line (or a point
        attachment) has drag coefficients, with or without a current (a line moving
        through water feels drag on its own velocity).
    dead_load : optional (qx, qy, qz) [N/m] of fixed direction, added to the weight.
    """

    def __init__(self, scene: Scene, mesh: Mesh, d: int, *, current: bool,
                 dead_load=None, gauss_points: int | None = None, dynamic: bool = False):
        self.scene = scene
        self.mesh = mesh
        self.d = d
        self.kl = banded.half_bandwidth(d)
        self.N = mesh.n * 2 * d
        self.xg, self.wg = gauss(gauss_points or scene.ancf.gauss_points)
        self.ends: EndConditions = end_conditions(scene, mesh.n, d)
        load = np.zeros((mesh.ne, d))
        load[:, 1] = -mesh.weight
        if dead_load is not None:
            load += np.asarray(dead_load, float)[:d]
        self.weight_elements = consistent_load(mesh, d, load, self.xg, self.wg)
        # the internal flow (ancf/flow.py): the time domain's flow pass; statics: a slug's
        # weight frozen at t = 0
        fl = scene.internal_flow
        self.flow = Flow(scene, mesh, d, self.xg, self.wg) if (dynamic and fl is not None) \
            else None
        if not dynamic:
            self.weight_elements += frozen_slug_weight(scene, mesh, d, self.xg, self.wg)
        self.weight = scatter(self.weight_elements, mesh.n, d)
        # the point attachments' mass and added mass on their nodes' position unknowns (N,)
        # [kg] (isotropic: the time domain's inertia, the modes' mass matrix)
        self.point_mass = np.zeros(self.N)
        for i in np.flatnonzero(mesh.point_mass + mesh.point_added):
            self.point_mass[i * 2 * d:i * 2 * d + d] = mesh.point_mass[i] + mesh.point_added[i]
        for i in np.nonzero(mesh.point_weight)[0]:
            self.weight[i * 2 * d + 1] -= mesh.point_weight[i]
        self.load_scale = float(max(np.max(np.abs(load).sum(axis=1) * mesh.l0, initial=0.0),
                                    np.max(np.abs(mesh.point_weight), initial=0.0)))
        if self.load_scale <= 0.0:
            self.load_scale = 1e-6 * float(np.max(mesh.EA))
        sb = scene.seabed
        self.use_seabed = sb is not None
        self.kseabed = sb.stiffness if sb is not None else 0.0
        self.mu = sb.friction if sb is not None else 0.0
        self.zeta = sb.damping if sb is not None else 0.0
        self.cseabed = 2.0 * self.zeta * np.sqrt(self.kseabed * (mesh.mass + mesh.added))
        self.vfric = 0.01
        cur = scene.current
        self.has_current = bool(cur is not None and cur.max_abs_speed > 0.0)
        coefs = bool(np.any(mesh.cdn > 0) or np.any(mesh.cdt > 0))
        self.use_drag = coefs and (dynamic or (current and self.has_current))
        self.points = np.nonzero(mesh.point_drag > 0.0)[0]
        self.use_point_drag = self.points.size > 0 and (
            dynamic or (current and self.has_current))
        self.dead_load = dead_load
        # the sea surface (a time domain with a water depth): the dry part of the line
        # loses its buoyancy, drag and added mass (ancf/loads.py)
        self.use_surface = bool(dynamic and scene.water_depth is not None)
        self.ysurf = float(scene.water_depth) if self.use_surface else np.inf
        self.band = mesh.diameter.copy()
        self.buoy = scene.gravity * mesh.mass - mesh.weight
        # the waves (a time domain; ancf/waves.py fills the arrays at each step)
        self.waves = None
        npts = mesh.ne * len(self.xg)
        self.WU = np.zeros((npts, d))
        self.WA = np.zeros((npts, d))
        self.WS = np.full(npts, self.ysurf)
        self.cinn = mesh.fluid + mesh.added
        self.cint = mesh.fluid.copy()
        self.heights, self.comps, self.slopes = _current_arrays(scene, d)
        self.ei_scale = 1.0
        self.drag_scale = 1.0
        self._none = np.zeros((0, 4 * d))      # the kernels' 'no per-element output'
        self.tensioner_shift = 0.0      # [m] the tensioner's reference moved by the heave
        # the internal axial damping BA d(eps)/dt (a time domain; ancf.element.damping_pass)
        self.use_axial_damping = bool(dynamic and np.any(mesh.BA > 0.0))

    def load_groups(self, unscaled: bool = False) -> tuple:
        """The argument groups of :func:`ancf.loads.load_pass` (Seabed, Drag, Surface,
        Waves); the drag scaled by the statics' load stepping unless ``unscaled``."""
        m = self.mesh
        f = 1.0 if unscaled else self.drag_scale
        return (Seabed(self.use_seabed, float(self.kseabed), self.cseabed, float(self.mu),
                       float(self.vfric)),
                Drag(self.use_drag, m.cdn * f, m.cdt * f, self.heights, self.comps,
                     self.slopes),
                Surface(self.use_surface, float(self.ysurf), self.band, self.buoy),
                Waves(self.waves is not None, self.WU, self.WA, self.WS, self.cinn,
                      self.cint))

    def set_waves(self, field) -> None:
        """Load the line with the waves of ``field`` (:class:`ancf.waves.WaveField`, its
        arrays shared: each evaluation is seen by the next residual)."""
        self.waves = field
        self.WU, self.WA, self.WS = field.U, field.A, field.surface

    @property
    def effects(self) -> list[str]:
        out = ["weight", "axial", "bending"]
        if self.use_seabed:
            out.append("seabed")
            if self.mu > 0.0:
                out.append("seabed_friction")
        if self.use_drag or self.use_point_drag:
            out.append("current_drag" if self.has_current else "drag")
        if self.use_surface:
            out.append("sea_surface")
        if self.waves is not None:
            out.append("waves")
        if self.dead_load is not None:
            out.append("dead_load")
        fl = self.scene.internal_flow
        if fl is not None:              # a steady flow in statics: no force (Fylling)
            out.append("slug_flow" if fl.has_slug else "internal_flow")
        return out

    def residual(self, q: np.ndarray, tangent: bool = True, v: np.ndarray | None = None,
                 cK: float = 1.0, cC: float = 0.0):
        """(R (N,), K band or None, the potential energy of the conservative forces [J]:
        strain, ends, seabed and weight) at ``q``;
        the loads' linearisation enters K as cK (-dF/dq) + cC (-dF/dv), the internal axial
        damping's (a time domain's, at the rates ``v``) as cK dF/dq + cC dF/dv."""
        m = self.mesh
        F = np.zeros(self.N)
        K = banded.zeros(self.N, self.kl) if tangent else np.zeros((1, 1))
        EI = m.EI * self.ei_scale if self.ei_scale != 1.0 else m.EI
        energy = elastic_pass(q, self.d, m.l0, m.EA, EI, self.xg, self.wg, tangent, F, K,
                              self.kl, self._none)
        energy += end_energy(self.ends, q, F, K if tangent else None, self.kl,
                             self.tensioner_shift)
        if self.use_axial_damping and v is not None:     # internal: no potential energy
            damping_pass(q, v, self.d, m.l0, m.BA, self.xg, self.wg, cK if tangent else 0.0,
                         cC if tangent else 0.0, F, K, self.kl, self._none)
        vv = np.zeros(self.N) if v is None else v
        if self.use_seabed or self.use_drag or self.use_surface or self.waves is not None:
            Fe = np.zeros(self.N)
            energy += load_pass(q, vv, self.d, m.l0, self.xg, self.wg, *self.load_groups(),
                                cK if tangent else 0.0, cC if tangent else 0.0, Fe, K,
                                self.kl, self._none)
            F -= Fe
        if self.use_point_drag:
            self._point_drag(q, vv, F, K if tangent else None, cK, cC)
        if self.flow is not None:
            Ff = np.zeros(self.N)
            self.flow.forces(q, vv, Ff, K, self.kl, cK if tangent else 0.0,
                             cC if tangent else 0.0, self._none)
            F -= Ff
        F -= self.weight
        # the potential energy of the conservative part: strain, ends, seabed, weight
        energy -= float(self.weight @ q)
        return F, (K if tangent else None), energy

    def _point_drag(self, q, v, F, K, cK, cC) -> None:
        """The point attachments' drag, isotropic, f = c |u| u on the velocity u = U(y) - v
        relative to the current (c = 0.5 rho C_D A [kg/m]), at their nodes."""
        d, nd = self.d, 2 * self.d
        for i in self.points:
            y = q[i * nd + 1]
            U = np.array([np.interp(y, self.heights, self.comps[k]) for k in range(d)])
            u = U * self.drag_scale - v[i * nd:i * nd + d]
            nu = float(np.linalg.norm(u))
            c = self.mesh.point_drag[i]
            F[i * nd:i * nd + d] -= c * nu * u
            if K is not None:
                Fu = c * (nu * np.eye(d) + (np.outer(u, u) / nu if nu > 0 else 0.0))
                dU = np.zeros(d)
                if len(self.heights) > 1 and self.heights[0] < y < self.heights[-1]:
                    j = int(np.searchsorted(self.heights, y) - 1)
                    dU = self.slopes[:, j] * self.drag_scale
                block = np.zeros((nd, nd))
                block[:d, 1] -= cK * Fu @ dU
                block[:d, :d] += cC * Fu
                banded.add_diagonal_block(K, self.kl, i * nd, block)


    def element_forces(self, q: np.ndarray, v: np.ndarray | None = None,
                       inertia: np.ndarray | None = None) -> np.ndarray:
        """Each element's internal forces less its own loads (at the rates ``v``, zero by
        default) plus its own ``inertia`` forces (ne, 4 d) when given, (ne, 4 d): at
        equilibrium the forces its nodes receive from the rest of the line (ancf/output.py's
        section forces)."""
        m = self.mesh
        Fe = np.zeros((m.ne, 4 * self.d))
        F = np.zeros(self.N)
        K = np.zeros((1, 1))
        elastic_pass(q, self.d, m.l0, m.EA, m.EI, self.xg, self.wg, False, F, K, self.kl, Fe)
        if self.use_axial_damping and v is not None:
            Fd = np.zeros((m.ne, 4 * self.d))
            damping_pass(q, v, self.d, m.l0, m.BA, self.xg, self.wg, 0.0, 0.0, F, K,
                         self.kl, Fd)
            Fe += Fd
        Fe -= self.weight_elements
        if self.use_seabed or self.use_drag or self.use_surface or self.waves is not None:
            Le = np.zeros((m.ne, 4 * self.d))
            load_pass(q, np.zeros(self.N) if v is None else v, self.d, m.l0, self.xg, self.wg,
                      *self.load_groups(unscaled=True), 0.0, 0.0, np.zeros(self.N), K, self.kl,
                      Le)
            Fe -= Le
        if self.flow is not None:
            Lf = np.zeros((m.ne, 4 * self.d))
            self.flow.forces(q, np.zeros(self.N) if v is None else v, np.zeros(self.N),
                             K, self.kl, 0.0, 0.0, Lf)
            Fe -= Lf
        if inertia is not None:
            Fe += inertia
        return Fe


def _current_arrays(scene: Scene, d: int):
    """(heights (m,), components (d, m) [m/s], slopes (d, max(m - 1, 1)) [1/s]) of the
    scene's current (zeros without one)."""
    cur = scene.current
    if cur is None:
        return np.zeros(1), np.zeros((d, 1)), np.zeros((d, 1))
    h = np.asarray(cur.heights, float)
    if cur.turns:
        ux, uz = cur.components
        comps3 = np.vstack([np.asarray(ux, float), np.zeros(len(h)), np.asarray(uz, float)])
    else:
        direction = np.asarray(cur.direction, float)
        comps3 = np.outer(direction, np.asarray(cur.speeds, float))
    comps = comps3[:d].copy()
    if len(h) > 1:
        slopes = np.diff(comps, axis=1) / np.diff(h)[None, :]
    else:
        slopes = np.zeros((d, 1))
    return h, comps, np.ascontiguousarray(slopes)


# ------------------------------------------------------------------ residual measures
def free_part(model: "Model", R: np.ndarray) -> np.ndarray:
    """``R`` on the free unknowns: in the clamped nodes' rotated slope basis, the
    prescribed unknowns' entries (the supports' reactions) zeroed."""
    r = R.copy()
    rotate(model.ends, None, r, model.kl)
    r[model.ends.fixed] = 0.0
    return r


def residual_ratio(model: "Model", R: np.ndarray) -> float:
    """The stopping rule's measure of ``R`` (free unknowns only)."""
    d = model.d
    r = free_part(model, R).reshape(-1, 2 * d)
    fr = float(np.max(np.linalg.norm(r[:, :d], axis=1)))
    fm = float(np.max(np.linalg.norm(r[:, d:], axis=1)))
    h = float(np.max(model.mesh.l0))
    return max(fr, fm / h) / model.load_scale


def round_off_floor(model: "Model", q: np.ndarray) -> float:
    """The residual ratio round-off allows (module docstring)."""
    extent = float(np.max(np.abs(q.reshape(-1, 2 * model.d)[:, :model.d])))
    m = model.mesh
    return float(np.max(m.EA / m.l0)) * max(extent, 1.0) * 2.2e-16 / model.load_scale


def newton_correction(model: "Model", K: np.ndarray, R: np.ndarray) -> np.ndarray | None:
    """The Newton correction dq of K dq = -R on the free unknowns (statics and a time
    step alike): the clamped nodes' slopes in their rotated basis, the prescribed
    unknowns fixed (dq = 0 there), the banded LU; None when the factorisation fails or
    the correction is not finite. ``K`` (band storage) is overwritten."""
    kl = model.kl
    rhs = -R
    rotate(model.ends, K, rhs, kl)
    banded.fix(K, kl, model.ends.fixed)
    rhs[model.ends.fixed] = 0.0
    dq = banded.solve(K, kl, rhs)
    if dq is None or not np.all(np.isfinite(dq)):
        return None
    unrotate(model.ends, dq)
    return dq

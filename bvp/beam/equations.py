"""Large-deformation extensible beam equations on an elastic seabed (after Wang, Duan &
Tian 2014, eqs (1)-(4), extended with axial strain and a Winkler foundation).

Material (unstretched) arc length s [m] from the bottom end; the state (SI units) is

    u = [x, y, theta, M, F, T]
        x, y   position [m] (x towards the hang-off, y up from the seabed)
        theta  tangent angle from the horizontal [rad]
        M      bending moment [N m], M = EI dtheta/ds (curvature per unstretched length)
        F      shear force [N]: the internal force is P = T t - F n with
               t = (cos theta, sin theta), n = (-sin theta, cos theta)
        T      effective tension [N] (the tangential component of P)

Conventions (the same as the VFIFE elements, written independently in
``vfife/kernels.py``; see docs/theory.md, "One model, two methods"):

- axial strain eps = T / EA (EA [N]); a material element ds occupies (1 + eps) ds;
  ``EA = inf`` is the inextensible limit (Wang's model);
- moment M = EI dtheta/ds on the unstretched length;
- weight w [N/m, + down], drag and seabed reaction are forces per unit *unstretched*
  length;
- seabed: a unilateral, frictionless Winkler foundation at y = 0, upward reaction
  p = k max(-y, 0) [N/m] with k [N/m2] (force per unit length per metre of
  penetration); ``k = 0`` means no foundation.

Equilibrium of a material element, dP/ds + q = 0 with the external load
q = (0, -w) + drag + (0, p), and of moments, dM/ds + (dr/ds x P)_z = 0, give

    x' = (1 + eps) cos theta,   y' = (1 + eps) sin theta,   theta' = M / EI,
    M' = (1 + eps) F,
    F' = T M / EI - w cos theta + f_n + p cos theta              (eq. 1, + seabed)
    T' = -F M / EI + w sin theta - f_t - p sin theta             (eq. 2, + seabed)

with the Morison drag of a current of signed speed V(y) along +x (eqs 3, 4)

    f_n = c_n |V_n| V_n,  V_n = -V sin theta,  c_n = 0.5 rho D C_Dn      (along n)
    f_t = c_t |V_t| V_t,  V_t =  V cos theta,  c_t = 0.5 rho pi D C_Dt   (along t)

Drag is written as s|s| with its analytic Jacobian, which is smooth enough at sign
changes; the foundation's kink at y = 0 has the one-sided Jacobian of its active branch.

One domain (bvp/beam/layout.py). The solver integrates over the unit coordinate tau with
ds/dtau = a, so dY/dtau = a u'. Every term of a u' is a function of the state times one
of the six coefficient products C = (a, a w, a/EI, a/EA, a c_n, a c_t): the pieces of the
line have constant C, blended linearly across a tiny gap at each joint. The state is one
block of 6 (the line), or two in the contact-zone form (``split_first``): block 0 is the
contact zone [0, s_L] (its pieces the segments up to the lift-off point s_L, in any
segment), where the foundation acts as the linear spring p = -k y (the active branch of
the same law: y <= 0 there is checked after solving), and block 1 the rest of the line
from s_L, an unknown parameter with y(s_L) = 0. The unilateral law holds everywhere in
the line block.
The solver works with the scaled state Y = u / scale so that every unknown is O(1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .layout import Layout

NSTATE = 6
IX, IY, ITH, IM, IF, IT = range(NSTATE)
NCOEF = 6                      # the products a, a w, a/EI, a/EA, a c_n, a c_t (+ the
#                                point drag's, a 7th row, on a line with attachments)


class LiftOffOutside(ValueError):
    """The contact-zone form's lift-off point left the piece it is solved in."""


@dataclass
class BeamModel:
    """Per-segment properties of the line and its layout on the unit domain.

    EI [N m2], EA [N] (``inf``: inextensible), w [N/m], c_n and c_t [kg/m2] and
    ``lengths`` [m] are per segment. The line block's pieces are the segments, except that
    ``free_first_length`` makes the first piece's length the parameter p[0] *
    ``length_scale`` (the suspended length of the first segment), and in the contact-zone
    form (``split_first``) p[0] * ``length_scale`` is the lift-off point s_L in segment
    ``cut``: the zone block's pieces are segments 0 .. cut - 1 and the part of segment
    ``cut`` up to s_L, the line block's the rest of segment ``cut`` and the segments after
    it. ``layout`` (``zone_layout``) places the line (zone) block's pieces on tau
    (default: proportional to their lengths); ``scale`` (shape (6,)) converts the scaled
    state to SI; ``speed``/``speed_gradient`` give the signed in-plane current along +x
    [m/s] at height y; ``k_seabed`` [N/m2] is the Winkler stiffness of the seabed (0:
    none); ``drag_factor`` scales the current (the continuation's load factor).
    """

    EI: np.ndarray
    w: np.ndarray
    c_n: np.ndarray
    c_t: np.ndarray
    lengths: np.ndarray
    scale: np.ndarray
    EA: np.ndarray | None = None
    k_seabed: float = 0.0
    speed: object = None
    speed_gradient: object = None
    free_first_length: bool = False
    split_first: bool = False
    length_scale: float = 1.0
    drag_factor: float = 1.0
    layout: Layout | None = None
    zone_layout: Layout | None = None
    cut: int = 0
    point_w: np.ndarray | None = None
    point_c: np.ndarray | None = None

    #: states per block (the 3D rod, bvp/rod/equations.py, has 10)
    block = NSTATE

    def __post_init__(self) -> None:
        self.EI = np.asarray(self.EI, float)
        self.lengths = np.asarray(self.lengths, float)
        if self.EA is None:
            self.EA = np.full_like(self.EI, np.inf)
        self.inv_EA = 1.0 / np.asarray(self.EA, float)       # 0 where inextensible
        self.starts = np.concatenate([[0.0], np.cumsum(self.lengths)])
        zero = np.zeros_like(self.EI)
        self.point_w = zero if self.point_w is None else np.asarray(self.point_w, float)
        self.point_c = zero if self.point_c is None else np.asarray(self.point_c, float)
        self.has_points = bool(np.any(self.point_w != 0.0) or np.any(self.point_c != 0.0))
        if self.layout is None:
            self.layout = Layout.proportional(self.lengths[self.line_segs])

    @property
    def n_seg(self) -> int:
        return len(self.EI)

    @property
    def n_block(self) -> int:
        """Blocks of six states: 2 in the contact-zone form, else 1."""
        return 2 if self.split_first else 1

    @property
    def n_state(self) -> int:
        return self.block * self.n_block

    @property
    def extensible(self) -> bool:
        return bool(np.any(self.inv_EA > 0.0))

    @property
    def line_segs(self) -> np.ndarray:
        """Segment of each piece of the line block."""
        return np.arange(self.cut if self.split_first else 0, self.n_seg)

    @property
    def zone_segs(self) -> np.ndarray:
        """Segment of each piece of the contact zone's block (split form)."""
        return np.arange(0, self.cut + 1)

    # ------------------------------------------------------------------ lengths and s
    def piece_lengths(self, p: np.ndarray) -> np.ndarray:
        """Lengths [m] of the line block's pieces at the parameters p."""
        L = self.lengths[self.line_segs].copy()
        if self.split_first:
            L[0] = self.starts[self.cut + 1] - p[0] * self.length_scale
        elif self.free_first_length:
            L[0] = p[0] * self.length_scale
        return L

    def zone_lengths(self, p: np.ndarray) -> np.ndarray:
        """Lengths [m] of the contact zone's pieces (split form)."""
        L = self.lengths[:self.cut + 1].copy()
        L[-1] = p[0] * self.length_scale - self.starts[self.cut]
        return L

    def zone_length(self, p: np.ndarray) -> float:
        """Length s_L [m] of the contact zone (0 without one)."""
        return float(p[0]) * self.length_scale if self.split_first else 0.0

    def s_of(self, tau: np.ndarray, p: np.ndarray) -> np.ndarray:
        """Unstretched arc length s [m] from the bottom end at tau, shape (blocks, m)."""
        line = self.layout.s_of(tau, self.piece_lengths(p), self.zone_length(p))
        if not self.split_first:
            return line[None, :]
        return np.stack([self.zone_layout.s_of(tau, self.zone_lengths(p)), line])

    def tau_of(self, s: np.ndarray, p: np.ndarray) -> np.ndarray:
        """tau of the line block at arc length s [m] (s >= the contact zone)."""
        return self.layout.tau_of(s, self.piece_lengths(p), self.zone_length(p))

    def segment_at(self, tau: np.ndarray, block: int) -> np.ndarray:
        """Segment index at each tau of ``block``."""
        if self.split_first and block == 0:
            return self.zone_segs[self.zone_layout.piece(tau)]
        return self.line_segs[self.layout.piece(tau)]

    # ------------------------------------------------------------------ coefficients
    def _unit(self, k) -> np.ndarray:
        """Coefficient products per unit stretch of segments k: (6, len(k))."""
        one = np.ones(len(k))
        return np.stack([one, self.w[k], 1.0 / self.EI[k], self.inv_EA[k], self.c_n[k],
                         self.c_t[k]])

    def _block(self, tau, layout, segs, L, var, dL):
        """(C, dC/dp) of one block: pieces ``segs`` of lengths ``L`` [m] on ``layout``;
        piece ``var``'s length moves with p by ``dL`` [m] (None: no parameter)."""
        base = self._unit(segs) * (L / layout.widths)[None, :]
        if self.has_points:
            # a point attachment is a piece of zero length (a = 0) carrying its net weight
            # and drag coefficient over the piece's tau width: integrated across it they
            # are the jump conditions of the force (bvp/beam/points.py)
            base[1] += self.point_w[segs] / layout.widths
            base = np.vstack([base, self.point_c[segs] / layout.widths])
        kl, kr, lam = layout.blend(tau)
        C = (1.0 - lam) * base[:, kl] + lam * base[:, kr]
        if dL is None:
            return C, None
        share = (1.0 - lam) * (kl == var) + lam * (kr == var)
        return C, share * (base[:, var:var + 1] * dL / L[var])

    def coefficients(self, tau: np.ndarray, p: np.ndarray):
        """[(C, dC/dp or None, linear)] per block: C (6, m) the products at tau, linear
        True where the foundation is the contact zone's linear spring. Raises
        :class:`LiftOffOutside` when the lift-off point leaves the segment the pieces were
        cut in (a piece of negative length: no solution of this problem lies there)."""
        tau = np.asarray(tau, float)
        if self.split_first and not (self.starts[self.cut] < p[0] * self.length_scale
                                     < self.starts[self.cut + 1]):
            raise LiftOffOutside(
                f"the lift-off point s = {p[0] * self.length_scale:.1f} m left the piece "
                f"[{self.starts[self.cut]:.1f}, {self.starts[self.cut + 1]:.1f}] m it was "
                "cut in")
        dL = None
        if self.free_first_length:
            dL = (-1.0 if self.split_first else 1.0) * self.length_scale
        C, dC = self._block(tau, self.layout, self.line_segs, self.piece_lengths(p), 0, dL)
        if not self.split_first:
            return [(C, dC, False)]
        zone = self._block(tau, self.zone_layout, self.zone_segs, self.zone_lengths(p),
                           self.cut, self.length_scale)
        return [(*zone, True), (C, dC, False)]

    # ------------------------------------------------------------------ SI right-hand side
    def _current(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if self.speed is None or self.drag_factor == 0.0:
            z = np.zeros_like(y)
            return z, z
        return self.drag_factor * self.speed(y), self.drag_factor * self.speed_gradient(y)

    @property
    def has_current(self) -> bool:
        return self.speed is not None

    @property
    def has_drag(self) -> bool:
        return self.speed is not None and self.drag_factor != 0.0

    def seabed_reaction(self, y: np.ndarray, linear=False) -> np.ndarray:
        """Upward seabed reaction per unstretched length p = k max(-y, 0) [N/m]; where
        ``linear`` (contact zone) its active branch -k y."""
        return self.k_seabed * np.where(linear, -y, np.maximum(-y, 0.0))

    def terms(self, u: np.ndarray, C: np.ndarray, linear: bool) -> np.ndarray:
        """a du/ds for the SI state u (6, m) with the coefficient products C (6, m); linear
        in C (the blend and d/dp rely on it)."""
        y, th, M, F, T = u[IY], u[ITH], u[IM], u[IF], u[IT]
        a, aw, aiEI, aiEA, acn, act = C[:NCOEF]
        c, s = np.cos(th), np.sin(th)
        e1 = a + T * aiEA
        d = np.empty_like(u)
        d[IX] = e1 * c
        d[IY] = e1 * s
        d[ITH] = aiEI * M
        d[IM] = e1 * F
        d[IF] = aiEI * T * M - aw * c
        d[IT] = -aiEI * F * M + aw * s
        if self.has_drag:
            V, _ = self._current(y)
            Vn = -V * s
            Vt = V * c
            d[IF] += acn * np.abs(Vn) * Vn
            d[IT] -= act * np.abs(Vt) * Vt
            if self.has_points:          # a point's drag c_p |V| V along x, in n and t
                q = C[NCOEF] * np.abs(V) * V
                d[IF] -= q * s
                d[IT] -= q * c
        if self.k_seabed > 0.0:
            p = a * self.seabed_reaction(y, linear)
            d[IF] += p * c
            d[IT] -= p * s
        return d

    def terms_jac(self, u: np.ndarray, C: np.ndarray, linear: bool) -> np.ndarray:
        """d terms / du, shape (6, 6, m)."""
        y, th, M, F, T = u[IY], u[ITH], u[IM], u[IF], u[IT]
        a, aw, aiEI, aiEA, acn, act = C[:NCOEF]
        c, s = np.cos(th), np.sin(th)
        e1 = a + T * aiEA
        J = np.zeros((NSTATE, NSTATE, u.shape[1]))
        J[IX, ITH] = -e1 * s
        J[IX, IT] = c * aiEA
        J[IY, ITH] = e1 * c
        J[IY, IT] = s * aiEA
        J[ITH, IM] = aiEI
        J[IM, IF] = e1
        J[IM, IT] = F * aiEA
        J[IF, IT] = aiEI * M
        J[IF, IM] = aiEI * T
        J[IF, ITH] = aw * s
        J[IT, IF] = -aiEI * M
        J[IT, IM] = -aiEI * F
        J[IT, ITH] = aw * c
        if self.has_drag:
            V, dV = self._current(y)
            Vn = -V * s
            Vt = V * c
            J[IF, ITH] += 2.0 * acn * np.abs(Vn) * (-V * c)
            J[IF, IY] += 2.0 * acn * np.abs(Vn) * (-dV * s)
            J[IT, ITH] -= 2.0 * act * np.abs(Vt) * (-V * s)
            J[IT, IY] -= 2.0 * act * np.abs(Vt) * (dV * c)
            if self.has_points:
                q = C[NCOEF] * np.abs(V) * V
                dq = 2.0 * C[NCOEF] * np.abs(V) * dV
                J[IF, ITH] -= q * c
                J[IF, IY] -= dq * s
                J[IT, ITH] += q * s
                J[IT, IY] -= dq * c
        if self.k_seabed > 0.0:
            pr = a * self.seabed_reaction(y, linear)
            dp = a * np.where(linear | (y < 0.0), -self.k_seabed, 0.0)       # d(a p)/dy
            J[IF, IY] += dp * c
            J[IF, ITH] -= pr * s
            J[IT, IY] -= dp * s
            J[IT, ITH] -= pr * c
        return J

    # ------------------------------------------------------------------ scaled, for solve_bvp
    def rhs(self, tau: np.ndarray, Y: np.ndarray, p: np.ndarray) -> np.ndarray:
        """dY/dtau of the scaled state; Y has shape (``block`` x blocks, m)."""
        sc = self.scale[:, None]
        out = np.empty_like(Y)
        n = self.block
        for b, (C, _, linear) in enumerate(self.coefficients(tau, p)):
            rows = slice(b * n, (b + 1) * n)
            out[rows] = self.terms(Y[rows] * sc, C, linear) / sc
        return out

    def jac(self, tau: np.ndarray, Y: np.ndarray, p: np.ndarray):
        """(d rhs/dY, d rhs/dp) with shapes (nb, nb, m) and (nb, k, m) (n = ``block``
        states a block; None without parameters); the blocks do not interact, so d rhs/dY
        is block diagonal."""
        sc = self.scale
        n, nb, m = self.block, self.n_block, Y.shape[1]
        full = np.zeros((nb * n, nb * n, m))
        dp = np.zeros((nb * n, 1, m)) if self.free_first_length else None
        ratio = (sc[None, :] / sc[:, None])[:, :, None]      # J_ij sc_j / sc_i
        for b, (C, dC, linear) in enumerate(self.coefficients(tau, p)):
            rows = slice(b * n, (b + 1) * n)
            u = Y[rows] * sc[:, None]
            full[rows, rows] = self.terms_jac(u, C, linear) * ratio
            if dp is not None:
                dp[rows, 0] = self.terms(u, dC, linear) / sc[:, None]
        return full, dp

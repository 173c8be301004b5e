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

Contact zone (``split_first``): the solver may split the first segment at the lift-off
point s_L, an unknown parameter with y(s_L) = 0. Stacked segment 0 is then the contact
zone [0, s_L], where the foundation acts as the linear spring p = -k y (the active branch
of the same law: y <= 0 there is checked after solving), and stacked segment 1 the rest of
the first segment. Both pieces are smooth, so the collocation needs no refinement at the
kink; the unilateral law stays on every other segment.

Segments are stacked: segment k runs over tau in [0, 1] with s = s_k + L_k tau, and the
solver works with the scaled state Y = u / scale so that every unknown is O(1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

NSTATE = 6
IX, IY, ITH, IM, IF, IT = range(NSTATE)


@dataclass
class BeamModel:
    """Per-segment coefficients of the stacked problem (arrays of shape (n_seg,)).

    EI [N m2], EA [N] (``inf``: inextensible), w [N/m], c_n and c_t [kg/m2]; ``lengths``
    [m] are the segment lengths solved (for a parameterised first segment, ``lengths[0]``
    is replaced by the parameter); ``scale`` (shape (6,)) converts the scaled state to SI;
    ``speed``/``speed_gradient`` give the signed in-plane current along +x [m/s] at height
    y; ``k_seabed`` [N/m2] is the Winkler stiffness of the seabed (0: none).
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

    def __post_init__(self) -> None:
        if self.EA is None:
            self.EA = np.full_like(np.asarray(self.EI, float), np.inf)
        self.inv_EA = 1.0 / np.asarray(self.EA, float)       # 0 where inextensible
        # per stacked segment: 1 where the foundation is the linear spring of the contact
        # zone (split_first), 0 where it is unilateral
        self.linear_zone = np.zeros(len(self.EI))
        if self.split_first:
            self.linear_zone[0] = 1.0

    @property
    def n_seg(self) -> int:
        return len(self.EI)

    @property
    def extensible(self) -> bool:
        return bool(np.any(self.inv_EA > 0.0))

    def segment_lengths(self, p: np.ndarray) -> np.ndarray:
        L = self.lengths.astype(float).copy()
        if self.free_first_length:
            L[0] = p[0] * self.length_scale
            if self.split_first:          # the rest of the first segment
                L[1] = self.lengths[0] + self.lengths[1] - L[0]
        return L

    # ------------------------------------------------------------------ SI right-hand side
    def _si(self, Y: np.ndarray) -> np.ndarray:
        n = self.n_seg
        return Y.reshape(n, NSTATE, -1) * self.scale[None, :, None]

    def _current(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if self.speed is None or self.drag_factor == 0.0:
            z = np.zeros_like(y)
            return z, z
        return self.drag_factor * self.speed(y), self.drag_factor * self.speed_gradient(y)

    def seabed_reaction(self, y: np.ndarray, linear=0.0) -> np.ndarray:
        """Upward seabed reaction per unstretched length p = k max(-y, 0) [N/m]; where
        ``linear`` is 1 (contact zone) its active branch -k y."""
        return self.k_seabed * np.where(linear > 0.0, -y, np.maximum(-y, 0.0))

    def _reaction_and_slope(self, y: np.ndarray):
        lin = self.linear_zone[:, None]
        p = self.seabed_reaction(y, lin)
        dp = np.where((lin > 0.0) | (y < 0.0), -self.k_seabed, 0.0)      # dp/dy
        return p, dp

    def si_rhs(self, u: np.ndarray) -> np.ndarray:
        """du/ds [SI per m of unstretched length] for the SI state u of shape (n, 6, m)."""
        x, y, th, M, F, T = (u[:, i, :] for i in range(NSTATE))
        EI = self.EI[:, None]
        w = self.w[:, None]
        c, s = np.cos(th), np.sin(th)
        kappa = M / EI
        e1 = 1.0 + T * self.inv_EA[:, None]
        d = np.empty_like(u)
        d[:, IX] = e1 * c
        d[:, IY] = e1 * s
        d[:, ITH] = kappa
        d[:, IM] = e1 * F
        d[:, IF] = T * kappa - w * c
        d[:, IT] = -F * kappa + w * s
        if self.speed is not None and self.drag_factor != 0.0:
            V, _ = self._current(y)
            Vn = -V * s
            Vt = V * c
            d[:, IF] += self.c_n[:, None] * np.abs(Vn) * Vn
            d[:, IT] -= self.c_t[:, None] * np.abs(Vt) * Vt
        if self.k_seabed > 0.0:
            p, _ = self._reaction_and_slope(y)
            d[:, IF] += p * c
            d[:, IT] -= p * s
        return d

    def rhs(self, tau: np.ndarray, Y: np.ndarray, p: np.ndarray) -> np.ndarray:
        """dY/dtau of the stacked, scaled state; Y has shape (6 n_seg, m)."""
        d = self.si_rhs(self._si(Y))
        L = self.segment_lengths(p)
        d *= (L[:, None, None] / self.scale[None, :, None])
        return d.reshape(Y.shape)

    def jac(self, tau: np.ndarray, Y: np.ndarray, p: np.ndarray):
        """(d rhs/dY, d rhs/dp) with shapes (6n, 6n, m) and (6n, k, m)."""
        n = self.n_seg
        m = Y.shape[1]
        u = self._si(Y)
        y, th, M, F, T = u[:, IY], u[:, ITH], u[:, IM], u[:, IF], u[:, IT]
        EI = self.EI[:, None]
        iEA = self.inv_EA[:, None]
        w = self.w[:, None]
        c, s = np.cos(th), np.sin(th)
        kappa = M / EI
        e1 = 1.0 + T * iEA
        J = np.zeros((n, NSTATE, NSTATE, m))      # SI Jacobian per segment
        J[:, IX, ITH] = -e1 * s
        J[:, IX, IT] = c * iEA
        J[:, IY, ITH] = e1 * c
        J[:, IY, IT] = s * iEA
        J[:, ITH, IM] = 1.0 / EI
        J[:, IM, IF] = e1
        J[:, IM, IT] = F * iEA
        J[:, IF, IT] = kappa
        J[:, IF, IM] = T / EI
        J[:, IF, ITH] = w * s
        J[:, IT, IF] = -kappa
        J[:, IT, IM] = -F / EI
        J[:, IT, ITH] = w * c
        if self.speed is not None and self.drag_factor != 0.0:
            V, dV = self._current(y)
            cn = self.c_n[:, None]
            ct = self.c_t[:, None]
            Vn = -V * s
            Vt = V * c
            J[:, IF, ITH] += 2.0 * cn * np.abs(Vn) * (-V * c)
            J[:, IF, IY] += 2.0 * cn * np.abs(Vn) * (-dV * s)
            J[:, IT, ITH] -= 2.0 * ct * np.abs(Vt) * (-V * s)
            J[:, IT, IY] -= 2.0 * ct * np.abs(Vt) * (dV * c)
        if self.k_seabed > 0.0:
            pr, dp = self._reaction_and_slope(y)
            J[:, IF, IY] += dp * c
            J[:, IF, ITH] -= pr * s
            J[:, IT, IY] -= dp * s
            J[:, IT, ITH] -= pr * c
        L = self.segment_lengths(p)
        sc = self.scale
        # scaled: dY_i/dtau = L/sc_i f_i(sc * Y)  ->  J_ij * L * sc_j / sc_i
        J *= L[:, None, None, None] * (sc[None, None, :, None] / sc[None, :, None, None])
        full = np.zeros((n * NSTATE, n * NSTATE, m))
        for k in range(n):
            sl = slice(k * NSTATE, (k + 1) * NSTATE)
            full[sl, sl] = J[k]
        if not self.free_first_length:
            return full, None
        dp = np.zeros((n * NSTATE, 1, m))
        f = self.rhs(tau, Y, p)                   # segment k rows = L_k / sc * f
        dp[:NSTATE, 0] = f[:NSTATE] / L[0] * self.length_scale
        if self.split_first:                      # L_1 = first length - L_0
            dp[NSTATE:2 * NSTATE, 0] = -f[NSTATE:2 * NSTATE] / L[1] * self.length_scale
        return full, dp

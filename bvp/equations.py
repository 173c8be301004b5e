"""Large-deformation inextensible beam equations (Wang, Duan & Tian 2014, eqs (1)-(4)).

For each segment, with s the arc length [m] and the state (SI units)

    u = [x, y, theta, M, F, T]
        x, y   position [m] (x towards the hang-off, y up from the seabed)
        theta  tangent angle from the horizontal [rad]
        M      bending moment EI theta' [N m]
        F      shear EI theta'' [N]  (the paper's F; the transverse shear is -F)
        T      effective tension [N]

the planar equilibrium of a beam under submerged weight w [N/m, + down] and current
drag is

    x' = cos theta,   y' = sin theta,   theta' = M / EI,   M' = F,
    F' = T M / EI - w cos theta + f_n                        (eq. 1)
    T' = -F M / EI + w sin theta - f_t                       (eq. 2)

with the Morison drag of a current of signed speed V(y) along +x (eqs 3, 4)

    f_n = c_n |V_n| V_n,  V_n = -V sin theta,  c_n = 0.5 rho D C_Dn      (along the normal n)
    f_t = c_t |V_t| V_t,  V_t =  V cos theta,  c_t = 0.5 rho pi D C_Dt   (along the tangent t)

where t = (cos theta, sin theta) and n = (-sin theta, cos theta). Drag is written as
s|s| with its analytic Jacobian, which is smooth enough at sign changes.

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

    EI [N m2], w [N/m], c_n and c_t [kg/m2]; ``lengths`` [m] are the suspended segment
    lengths (for a parameterised first segment, ``lengths[0]`` is replaced by the
    parameter); ``scale`` (shape (6,)) converts the scaled state to SI;
    ``speed``/``speed_gradient`` give the signed in-plane current along +x [m/s] at height y.
    """

    EI: np.ndarray
    w: np.ndarray
    c_n: np.ndarray
    c_t: np.ndarray
    lengths: np.ndarray
    scale: np.ndarray
    speed: object = None
    speed_gradient: object = None
    free_first_length: bool = False
    length_scale: float = 1.0
    drag_factor: float = 1.0

    @property
    def n_seg(self) -> int:
        return len(self.EI)

    def segment_lengths(self, p: np.ndarray) -> np.ndarray:
        L = self.lengths.astype(float).copy()
        if self.free_first_length:
            L[0] = p[0] * self.length_scale
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

    def rhs(self, tau: np.ndarray, Y: np.ndarray, p: np.ndarray) -> np.ndarray:
        """dY/dtau of the stacked, scaled state; Y has shape (6 n_seg, m)."""
        u = self._si(Y)
        x, y, th, M, F, T = (u[:, i, :] for i in range(NSTATE))
        EI = self.EI[:, None]
        w = self.w[:, None]
        c, s = np.cos(th), np.sin(th)
        kappa = M / EI
        d = np.empty_like(u)
        d[:, IX] = c
        d[:, IY] = s
        d[:, ITH] = kappa
        d[:, IM] = F
        d[:, IF] = T * kappa - w * c
        d[:, IT] = -F * kappa + w * s
        if self.speed is not None and self.drag_factor != 0.0:
            V, _ = self._current(y)
            Vn = -V * s
            Vt = V * c
            d[:, IF] += self.c_n[:, None] * np.abs(Vn) * Vn
            d[:, IT] -= self.c_t[:, None] * np.abs(Vt) * Vt
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
        w = self.w[:, None]
        c, s = np.cos(th), np.sin(th)
        kappa = M / EI
        J = np.zeros((n, NSTATE, NSTATE, m))      # SI Jacobian per segment
        J[:, IX, ITH] = -s
        J[:, IY, ITH] = c
        J[:, ITH, IM] = 1.0 / EI
        J[:, IM, IF] = 1.0
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
        f0 = self.rhs(tau, Y, p)[:NSTATE]          # = L0 / sc * f
        dp[:NSTATE, 0] = f0 / L[0] * self.length_scale
        return full, dp

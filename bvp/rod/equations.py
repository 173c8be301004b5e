"""The 3D large-deformation rod: the planar beam of bvp/beam/equations.py out of its plane.

A torsion-free, extensible rod of isotropic bending stiffness EI [N m2] and axial stiffness
EA [N], in the frame of the line's plane (riser.model.frame.LinePlane: x along the plane from the
anchor towards the hang-off, y up from the seabed, z across the plane; the solver rotates
the scene into it and its results back). Material (unstretched) arc length s [m] from the
bottom end. The unit tangent is given by two angles,

    t  = (cos phi cos theta, cos phi sin theta, sin phi)

theta the angle in the x-y plane from the horizontal and phi the tilt out of it. This is
regular wherever the line does not point along +-z (|phi| < 90 deg), which a riser hung in
its plane never does; at phi = 0 it is the planar tangent. With
n1 = dt/dtheta / cos phi = (-sin theta, cos theta, 0) and n2 = dt/dphi =
(-sin phi cos theta, -sin phi sin theta, cos phi) the frame (t, n1, n2) is orthonormal and
right-handed (t x n1 = n2), and along s

    t' = theta' cos phi n1 + phi' n2,   n1' = -theta' cos phi t + theta' sin phi n2,
    n2' = -phi' t - theta' sin phi n1.

The state (SI) is, block by block (the first six are the planar state, in its order),

    u = [x, y, theta, M1, F1, T, z, phi, M2, F2]

with the bending moment m = EI t x t' = M1 n2 - M2 n1 (M1 = EI cos(phi) theta': bending in
the plane of t and n1, the planar M at phi = 0; M2 = EI phi': bending out of it), the
internal force P = T t - F1 n1 - F2 n2 (T the effective tension, F1 the planar shear F),
and the axial strain eps = T / EA. Equilibrium of an element, P' + q = 0 and
m' + r' x P = 0 with r' = (1 + eps) t (a torsion-free rod: the twisting moment m.t is zero,
which the equations keep: its derivative vanishes identically), projected on the frame:

    x' = (1 + eps) cos phi cos theta,  y' = (1 + eps) cos phi sin theta,  z' = (1 + eps) sin phi
    theta' = M1 / (EI cos phi),        phi' = M2 / EI
    M1' = (1 + eps) F1 + M1 M2 tan(phi) / EI
    M2' = (1 + eps) F2 - M1^2 tan(phi) / EI
    F1' = T M1 / EI + F2 M1 tan(phi) / EI + q.n1
    F2' = T M2 / EI - F1 M1 tan(phi) / EI + q.n2
    T'  = -F1 M1 / EI - F2 M2 / EI - q.t

At phi = M2 = F2 = 0 (and no load across the plane) the last four rows vanish and the rest
is bvp/beam/equations.py term for term. The load q per unstretched length [N/m]: the weight
(0, -w, 0), the seabed's upward reaction (0, k max(-y, 0), 0) (frictionless, the planar
BVP's Winkler law, its linear branch in the contact zone), Morison drag of the current
U(y) = (u_x, 0, u_z) [m/s] (the plane's components, interpolated by riser.physics.environment.
Current.velocity): tangential c_t |U.t| (U.t) t and normal c_n |U_n| U_n with the normal
relative velocity U_n = (U.n1) n1 + (U.n2) n2 (the cross-flow principle, as the VFIFE
applies it), and an optional uniform dead load D (a load of fixed direction for closed-form
checks). Every term is a coefficient product of bvp/beam/layout.py (a, a w, a/EI, a/EA, a c_n,
a c_t) times a function of the state, as in the planar model, so the pieces, joints,
blends and the free-length parameter of the planar problem carry over unchanged, and so
do the scaled right-hand side and Jacobian (:meth:`BeamModel.rhs`, :meth:`BeamModel.jac`
on ``block`` = 10 states).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..beam.equations import IF, IM, IT, ITH, IX, IY, BeamModel

#: the rod's states per block: the planar six, then z, phi, M2, F2
NROD = 10
IZ, IPH, IM2, IF2 = 6, 7, 8, 9


def rod_scale(planar: np.ndarray) -> np.ndarray:
    """The rod's state scale (10,) from the planar problem's (6,): z as x, phi as theta
    (1), M2 as M1, F2 as F1."""
    planar = np.asarray(planar, float)
    return np.concatenate([planar, [planar[IX], 1.0, planar[IM], planar[IF]]])


@dataclass
class RodModel(BeamModel):
    """The 3D rod on the planar model's pieces and layout (:class:`BeamModel`'s fields;
    ``scale`` has the rod's 10 entries, :func:`rod_scale`).

    ``velocity(y) -> (u_x, u_z)`` and ``velocity_gradient(y)`` [m/s, 1/s] give the current
    in the plane's frame (None: no current); ``drag_factor`` scales the whole current (the
    planar continuation's load factor) and ``cross_factor`` the z components of the
    current and the dead load (the continuation from the loads in the plane to the full
    ones; ``cross_loads``: there is something across the plane to scale). ``dead_load``
    (3,) [N/m] is a uniform load of fixed direction per unstretched length in the plane's
    frame (None: none).
    """

    velocity: object = None
    velocity_gradient: object = None
    cross_factor: float = 1.0
    dead_load: np.ndarray | None = None
    cross_loads: bool = False

    block = NROD

    @property
    def has_current(self) -> bool:
        return self.velocity is not None

    @property
    def has_drag(self) -> bool:
        return self.velocity is not None and self.drag_factor != 0.0

    def current(self, y: np.ndarray):
        """(u_x, u_z, du_x/dy, du_z/dy) at heights y [m], the factors applied."""
        ux, uz = (np.asarray(v, float) * np.ones_like(y) for v in self.velocity(y))
        dx, dz = (np.asarray(v, float) * np.ones_like(y) for v in self.velocity_gradient(y))
        f, fz = self.drag_factor, self.drag_factor * self.cross_factor
        return f * ux, fz * uz, f * dx, fz * dz

    def grounded_velocity(self) -> np.ndarray:
        """The current (u_x, 0, u_z) [m/s] at the seabed y = 0, factors applied."""
        if not self.has_drag:
            return np.zeros(3)
        ux, uz, _, _ = self.current(np.zeros(1))
        return np.array([float(ux[0]), 0.0, float(uz[0])])

    def _dead(self) -> np.ndarray:
        """The dead load (3, 1) [N/m] with ``cross_factor`` on its z component."""
        D = np.array(self.dead_load, float)
        D[2] *= self.cross_factor
        return D[:, None]

    # ------------------------------------------------------------------ the frame
    @staticmethod
    def frame(th: np.ndarray, ph: np.ndarray):
        """(t, n1, n2), each (3, m), at the angles theta, phi [rad]."""
        c, s, cp, sp = np.cos(th), np.sin(th), np.cos(ph), np.sin(ph)
        z = np.zeros_like(th)
        return (np.stack([cp * c, cp * s, sp]), np.stack([-s, c, z]),
                np.stack([-sp * c, -sp * s, cp]))

    def loads(self, u: np.ndarray, C: np.ndarray, linear: bool):
        """(Qt, Q1, Q2): a q . (t, n1, n2) [N per unit tau] of the SI state u (10, m)."""
        y, th, ph = u[IY], u[ITH], u[IPH]
        a, aw, _, _, acn, act = C
        t, n1, n2 = self.frame(th, ph)
        g = -aw + (a * self.seabed_reaction(y, linear) if self.k_seabed > 0.0 else 0.0)
        Qt, Q1, Q2 = g * t[1], g * n1[1], g * n2[1]
        if self.dead_load is not None:
            D = self._dead()
            Qt = Qt + a * np.sum(D * t, axis=0)
            Q1 = Q1 + a * np.sum(D * n1, axis=0)
            Q2 = Q2 + a * np.sum(D * n2, axis=0)
        if self.has_drag:
            ux, uz, _, _ = self.current(y)
            Ut = ux * t[0] + uz * t[2]
            U1 = ux * n1[0]
            U2 = ux * n2[0] + uz * n2[2]
            r = np.hypot(U1, U2)
            Qt = Qt + act * np.abs(Ut) * Ut
            Q1 = Q1 + acn * r * U1
            Q2 = Q2 + acn * r * U2
        return Qt, Q1, Q2

    # ------------------------------------------------------------------ SI right-hand side
    def terms(self, u: np.ndarray, C: np.ndarray, linear: bool) -> np.ndarray:
        """a du/ds for the SI state u (10, m) with the coefficient products C (6, m)."""
        th, M1, F1, T = u[ITH], u[IM], u[IF], u[IT]
        ph, M2, F2 = u[IPH], u[IM2], u[IF2]
        a, _, k, aiEA, _, _ = C
        c, s, cp, sp = np.cos(th), np.sin(th), np.cos(ph), np.sin(ph)
        tp = sp / cp
        e1 = a + T * aiEA
        Qt, Q1, Q2 = self.loads(u, C, linear)
        d = np.empty_like(u)
        d[IX] = e1 * cp * c
        d[IY] = e1 * cp * s
        d[IZ] = e1 * sp
        d[ITH] = k * M1 / cp
        d[IPH] = k * M2
        d[IM] = e1 * F1 + k * M1 * M2 * tp
        d[IM2] = e1 * F2 - k * M1 * M1 * tp
        d[IF] = k * T * M1 + k * F2 * M1 * tp + Q1
        d[IF2] = k * T * M2 - k * F1 * M1 * tp + Q2
        d[IT] = -k * F1 * M1 - k * F2 * M2 - Qt
        return d

    def terms_jac(self, u: np.ndarray, C: np.ndarray, linear: bool) -> np.ndarray:
        """d terms / du, shape (10, 10, m) (checked against finite differences in
        tests/test_bvp_rod.py)."""
        y, th, M1, F1, T = u[IY], u[ITH], u[IM], u[IF], u[IT]
        ph, M2, F2 = u[IPH], u[IM2], u[IF2]
        a, aw, k, aiEA, acn, act = C
        c, s, cp, sp = np.cos(th), np.sin(th), np.cos(ph), np.sin(ph)
        tp, sec2 = sp / cp, 1.0 / (cp * cp)
        e1 = a + T * aiEA
        J = np.zeros((NROD, NROD, u.shape[1]))
        J[IX, ITH], J[IX, IPH], J[IX, IT] = -e1 * cp * s, -e1 * sp * c, aiEA * cp * c
        J[IY, ITH], J[IY, IPH], J[IY, IT] = e1 * cp * c, -e1 * sp * s, aiEA * cp * s
        J[IZ, IPH], J[IZ, IT] = e1 * cp, aiEA * sp
        J[ITH, IM], J[ITH, IPH] = k / cp, k * M1 * sp * sec2
        J[IPH, IM2] = k
        J[IM, IF], J[IM, IT] = e1, aiEA * F1
        J[IM, IM], J[IM, IM2], J[IM, IPH] = k * M2 * tp, k * M1 * tp, k * M1 * M2 * sec2
        J[IM2, IF2], J[IM2, IT] = e1, aiEA * F2
        J[IM2, IM], J[IM2, IPH] = -2.0 * k * M1 * tp, -k * M1 * M1 * sec2
        J[IF, IT], J[IF, IM], J[IF, IF2] = k * M1, k * T + k * F2 * tp, k * M1 * tp
        J[IF, IPH] = k * F2 * M1 * sec2
        J[IF2, IT], J[IF2, IM2], J[IF2, IF] = k * M2, k * T, -k * M1 * tp
        J[IF2, IM], J[IF2, IPH] = -k * F1 * tp, -k * F1 * M1 * sec2
        J[IT, IF], J[IT, IM], J[IT, IF2], J[IT, IM2] = -k * M1, -k * F1, -k * M2, -k * F2
        # the loads: d(Qt, Q1, Q2) / d(y, theta, phi)
        t, n1, n2 = self.frame(th, ph)
        t_th, n1_th = cp * n1, np.stack([-c, -s, np.zeros_like(th)])
        n2_th = -sp * n1
        t_ph, n2_ph = n2, -t
        g = -aw + (a * self.seabed_reaction(y, linear) if self.k_seabed > 0.0 else 0.0)
        dg = (a * np.where(linear | (y < 0.0), -self.k_seabed, 0.0) if self.k_seabed > 0.0
              else np.zeros_like(y))
        dQ = {"t": [dg * t[1], g * t_th[1], g * t_ph[1]],
              "1": [dg * n1[1], g * n1_th[1], np.zeros_like(y)],
              "2": [dg * n2[1], g * n2_th[1], g * n2_ph[1]]}
        if self.dead_load is not None:
            D = self._dead()
            dQ["t"][1] = dQ["t"][1] + a * np.sum(D * t_th, axis=0)
            dQ["t"][2] = dQ["t"][2] + a * np.sum(D * t_ph, axis=0)
            dQ["1"][1] = dQ["1"][1] + a * np.sum(D * n1_th, axis=0)
            dQ["2"][1] = dQ["2"][1] + a * np.sum(D * n2_th, axis=0)
            dQ["2"][2] = dQ["2"][2] + a * np.sum(D * n2_ph, axis=0)
        if self.has_drag:
            ux, uz, dux, duz = self.current(y)
            Ut = ux * t[0] + uz * t[2]
            U1 = ux * n1[0]
            U2 = ux * n2[0] + uz * n2[2]
            # d(Ut, U1, U2) / d(y, theta, phi)
            dUt = [dux * t[0] + duz * t[2], ux * t_th[0] + uz * t_th[2], ux * t_ph[0] + uz * t_ph[2]]
            dU1 = [dux * n1[0], ux * n1_th[0], np.zeros_like(y)]
            dU2 = [dux * n2[0] + duz * n2[2], ux * n2_th[0] + uz * n2_th[2],
                   ux * n2_ph[0] + uz * n2_ph[2]]
            r = np.hypot(U1, U2)
            ir = np.where(r > 0.0, 1.0 / np.where(r > 0.0, r, 1.0), 0.0)
            g11, g12 = acn * (r + U1 * U1 * ir), acn * U1 * U2 * ir
            g22 = acn * (r + U2 * U2 * ir)
            ft = 2.0 * act * np.abs(Ut)
            for j in range(3):
                dQ["t"][j] = dQ["t"][j] + ft * dUt[j]
                dQ["1"][j] = dQ["1"][j] + g11 * dU1[j] + g12 * dU2[j]
                dQ["2"][j] = dQ["2"][j] + g12 * dU1[j] + g22 * dU2[j]
        for j, col in enumerate((IY, ITH, IPH)):
            J[IF, col] += dQ["1"][j]
            J[IF2, col] += dQ["2"][j]
            J[IT, col] -= dQ["t"][j]
        return J

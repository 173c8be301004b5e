"""The ANCF's wave kinematics and their loads' inputs: Airy components at the Gauss points.

The scene's waves (:mod:`riser.physics.waves`: the components, their phase convention, the
stretching and the ramp) are this package's own evaluation: per component j with the
phase theta = omega t - k ((x - x0) cos b + (z - z0) sin b) - eps, the elevation a cos
theta, the horizontal particle velocity a omega cosh(k y') / sinh(k h) cos theta along the
heading b and the vertical -a omega sinh(k y') / sinh(k h) sin theta, the accelerations
their time derivatives; y' the stretched height: Wheeler's y' = h y / (h + eta) below the
surface, or (vertical stretching) min(y, h); above the surface y' = h. The hyperbolic
ratios are written with decaying exponentials (no overflow in deep water). The ramp r(t)
(a half cosine over ``ramp_time``) multiplies the velocity, and the acceleration becomes
r a + r' u.

In the time domain (:mod:`ancf.dynamics.run`) the kinematics are evaluated once a step, at
the Gauss points of the state at the step's start and at the step's force time t_{n+1-af}
(the line moves a fraction of a wave length in a step: the kinematics' change with the
position within a step is left out of the Newton iterations, and of their Jacobian). The
loads (:func:`ancf.loads.load_pass`): Morison drag on the velocity relative to the water
(current + waves - line) and the fluid inertia rho A ((1 + C_a) a_n + a_t) per length,
each times the wet fraction under the instantaneous surface.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from riser.physics.hang_off_motion import scene_components

from .element import shape_into

_JIT = dict(cache=True, error_model="numpy", nogil=True)


@njit(**_JIT)
def gauss_positions(q, d, l0, xg, out):
    """The positions (ne * ng, d) of the Gauss points of every element (row e * ng + gp)."""
    ne = l0.shape[0]
    ng = xg.shape[0]
    nd = 2 * d
    N = np.empty(4)
    dN = np.empty(4)
    ddN = np.empty(4)
    for e in range(ne):
        for gp in range(ng):
            shape_into(xg[gp], l0[e], N, dN, ddN)
            for i in range(d):
                s = 0.0
                for k in range(4):
                    s += N[k] * q[e * nd + k * d + i]
                out[e * ng + gp, i] = s


@njit(**_JIT)
def airy(px, py, pz, t, amp, omega, k, phase, cosb, sinb, x0, z0, depth, wheeler, ramp,
         dramp, U, A, eta):
    """Velocity U (p, 3), acceleration A (p, 3) [m/s, m/s2] and elevation eta (p,) [m] of
    the components at the points (px, py, pz) at time t (the module docstring; ``ramp``
    and ``dramp`` its factor and rate at t)."""
    p = px.shape[0]
    m = amp.shape[0]
    for i in range(p):
        e = 0.0
        for j in range(m):
            th = omega[j] * t - k[j] * ((px[i] - x0) * cosb[j] + (pz[i] - z0) * sinb[j]) \
                - phase[j]
            e += amp[j] * math.cos(th)
        eta[i] = ramp * e
        if wheeler:
            top = depth + eta[i]
            yp = depth * min(py[i], top) / top if top > 0.0 else 0.0
        else:
            yp = min(py[i], depth)
        yp = max(yp, 0.0)
        ux = uy = uz = ax = ay = az = 0.0
        for j in range(m):
            w = omega[j]
            kk = k[j]
            ep = math.exp(kk * (yp - depth))
            if ep < 1e-13:
                continue
            em = math.exp(-kk * (yp + depth))
            den = 1.0 - math.exp(-2.0 * kk * depth)
            th = w * t - kk * ((px[i] - x0) * cosb[j] + (pz[i] - z0) * sinb[j]) - phase[j]
            c = math.cos(th)
            s = math.sin(th)
            uh = amp[j] * w * (ep + em) / den
            uv = -amp[j] * w * (ep - em) / den
            ux += uh * c * cosb[j]
            uz += uh * c * sinb[j]
            uy += uv * s
            ax += -uh * w * s * cosb[j]
            az += -uh * w * s * sinb[j]
            ay += uv * w * c
        U[i, 0] = ramp * ux
        U[i, 1] = ramp * uy
        U[i, 2] = ramp * uz
        A[i, 0] = ramp * ax + dramp * ux
        A[i, 1] = ramp * ay + dramp * uy
        A[i, 2] = ramp * az + dramp * uz


class WaveField:
    """The scene's wave components and the arrays of the loads at the Gauss points of one
    model: ``U``, ``A`` (ne * ng, d) and the surface height ``surface`` (ne * ng,) [m]."""

    def __init__(self, scene, model):
        comp = scene_components(scene)
        self.comp = comp
        self.depth = float(scene.water_depth)
        self.cosb, self.sinb = np.cos(comp.heading), np.sin(comp.heading)
        self.wheeler = comp.stretching == "wheeler"
        self.d = model.d
        self.z0 = float(scene.ends.anchor_point[2])
        npts = model.mesh.ne * len(model.xg)
        self.U = np.zeros((npts, model.d))
        self.A = np.zeros((npts, model.d))
        self.surface = np.full(npts, self.depth)
        self._pos = np.zeros((npts, model.d))
        self._U3 = np.zeros((npts, 3))
        self._A3 = np.zeros((npts, 3))
        self._eta = np.zeros(npts)

    def ramp(self, t: float) -> tuple[float, float]:
        T = self.comp.ramp_time
        if T <= 0.0 or t >= T:
            return 1.0, 0.0
        return 0.5 * (1.0 - math.cos(math.pi * t / T)), 0.5 * math.pi / T * math.sin(
            math.pi * t / T)

    def evaluate(self, model, q: np.ndarray, t: float) -> None:
        """The kinematics at the Gauss points of the state ``q`` at time ``t`` [s]."""
        gauss_positions(q, self.d, model.mesh.l0, model.xg, self._pos)
        px, py = self._pos[:, 0], self._pos[:, 1]
        pz = self._pos[:, 2] if self.d == 3 else np.full(px.shape, self.z0)
        r, dr = self.ramp(t)
        c = self.comp
        airy(np.ascontiguousarray(px), np.ascontiguousarray(py), np.ascontiguousarray(pz),
             float(t), c.amplitude, c.omega, c.k, c.phase, self.cosb, self.sinb,
             float(c.origin[0]), float(c.origin[1]), self.depth, self.wheeler, r, dr,
             self._U3, self._A3, self._eta)
        self.U[:] = self._U3[:, :self.d]
        self.A[:] = self._A3[:, :self.d]
        self.surface[:] = self.depth + self._eta

    def elevations(self, x, z, t: float) -> np.ndarray:
        """The elevation [m] at the points (x, z) at t."""
        x = np.atleast_1d(np.asarray(x, float))
        z = np.broadcast_to(np.asarray(z, float), x.shape).copy()
        U = np.zeros((x.size, 3))
        A = np.zeros((x.size, 3))
        eta = np.zeros(x.size)
        r, dr = self.ramp(t)
        c = self.comp
        airy(x.copy(), np.full(x.size, self.depth), z, float(t), c.amplitude, c.omega, c.k,
             c.phase, self.cosb, self.sinb, float(c.origin[0]), float(c.origin[1]),
             self.depth, self.wheeler, r, dr, U, A, eta)
        return eta

    def elevation(self, x: float, z: float, t: float) -> float:
        """The elevation [m] at (x, z) at t (the time series' wave_elevation)."""
        return float(self.elevations(x, z, t)[0])

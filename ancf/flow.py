"""The internal flow on the ANCF's elements: the contents' mass per length moving along the
line in an arbitrary Lagrangian-Eulerian description (Liu et al. 2021, Eqs. 1-9), the
mathematical model of the suite's other time domain (docs/theory.md, "Internal flow").

The contents of mass per length mu(s, t) move along the pipe at the constant relative
speed U [m/s] (positive from the anchor to the hang-off); s is the unstretched arc length
from the anchor [m]. The slug is the travelling density wave of the scene's
``[internal_flow.slug]`` (riser/physics/internal_flow.py):

    mu(s, t) = mu_0 (1 + eta cos(k s - omega t + psi)),  omega = k U,

mu_0 the mean contents mass per length (already in the mesh's mass and weight). A contents
particle at r(s, t) accelerates by r_tt + 2 U r_st + U^2 r_ss (Liu's Eq. 5 at constant U);
with the tangent tau = r_s / |r_s|, U^2 mu r_ss is written d/ds (mu U^2 tau) - U^2 mu_s
tau and the first part is taken into the effective tension (Fylling: the flow's momentum
flux rho U^2 counts as an internal pressure; the element's EA (|r_s| - 1) is that
effective tension, the wall tension is reported beside it). What is left on the line per
unstretched length, beyond the mesh's mean mass and weight:

    f = U^2 mu_s tau - 2 mu U P r_st - (mu - mu_0) (r_tt + g e_y),   P = I - tau tau^T,

the gradient (centrifugal) force along the tangent, the Coriolis force across it (the
continuum's tau . tau_t = 0: only the part of r_st across the axis turns the tangent) and
the slug's own inertia and weight. Its generalised forces are Q = int N^T f ds by Gauss
quadrature on each element (the elastic forces' points). A steady uniform flow (eta = 0)
leaves only the Coriolis force: no static force (Fylling), as the VFIFE's
(vfife/flow.py, the same model, its own code).

Linearisation (the implicit step's Jacobian), with dtau/dr_s = P / |r_s|:

    d f / d r_s  = U^2 mu_s P / |r_s| + 2 mu U (P (tau . r_st) + tau r_st^T P) / |r_s|,
    d f / d r_st = -2 mu U P,    d f / d r_tt = -(mu - mu_0) I,

carried to the element's unknowns by dN (r_s, r_st) and N (r_tt): the Coriolis part is
skew in v (gyroscopic) and the tangent is not symmetric (the banded LU takes it).
tests/test_ancf_flow.py checks the three blocks against central differences.

Statics: a steady flow has no static force; a slug is frozen at t = 0 by its weight only
(:func:`frozen_slug_weight`: the line's equilibrium with that density pattern, as the
VFIFE's statics). The time domain runs :func:`flow_pass` at every residual from t = 0 of
the run (the clock the run sets, ``Flow.time``).
"""

from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numba import njit

from riser.physics.internal_flow import contents_mass_per_length

from .element import shape_into

_JIT = dict(cache=True, error_model="numpy", nogil=True)

#: the kernel's flow constants: U [m/s], mu_0 [kg/m], eta [-], k [1/m], omega [rad/s],
#: psi [rad], g [m/s2]
FlowPar = namedtuple("FlowPar", "U mu0 eta k omega psi g")


@njit(**_JIT)
def flow_pass(q, v, acc, d, s0, l0, xg, wg, U, mu0, eta, k, omega, psi, g, t,
              forces, cK, cC, cM, F, K, kl, Fe):
    """The flow's generalised forces (module docstring) at time ``t`` [s], added to ``F``
    (N,) [N, N m] and each element's share to ``Fe`` (ne, 4 d) when it has ne rows.

    q, v (N,) the state and its rates; acc (N,) the accelerations the slug's inertia acts
    on (length 0: no inertia); s0 (n,) [m] the nodes' unstretched arc length, l0 (ne,)
    [m]; ``forces``: the gradient, Coriolis and slug-weight forces (else the inertia
    only). With ``K`` of the band's shape, adds cK (-dQ/dq) + cC (-dQ/dv) + cM (-dQ/da)
    to it (LAPACK band storage, ``kl`` sub-diagonals, as :func:`ancf.mass.mass_pass`)."""
    ne = l0.shape[0]
    nd = 2 * d
    ng = xg.shape[0]
    row0 = 2 * kl
    N = np.empty(4)
    dN = np.empty(4)
    ddN = np.empty(4)
    a = np.empty(d)
    b = np.empty(d)
    tau = np.empty(d)
    ag = np.empty(d)
    f = np.empty(d)
    Jq = np.empty((d, d))
    Jv = np.empty((d, d))
    kloc = np.empty((4 * d, 4 * d))      # an element's block, scattered once (the band's
    acc_on = acc.shape[0] > 0
    tangent = K.shape[0] > 1
    keep = Fe.shape[0] == ne
    for e in range(ne):              # strided writes cost more than the arithmetic)
        L = l0[e]
        base = e * nd
        if tangent:
            kloc[:, :] = 0.0
        for gp in range(ng):
            shape_into(xg[gp], L, N, dN, ddN)
            s = s0[e] + xg[gp] * L
            ph = k * s - omega * t + psi
            dmu = mu0 * eta * math.cos(ph)          # mu - mu_0
            mu = mu0 + dmu
            mus = -mu0 * eta * k * math.sin(ph)     # d mu / ds
            w = wg[gp] * L
            for i in range(d):
                f[i] = 0.0
            if forces:
                na = 0.0
                for i in range(d):
                    ai = 0.0
                    bi = 0.0
                    for kk in range(4):
                        ai += dN[kk] * q[base + kk * d + i]
                        bi += dN[kk] * v[base + kk * d + i]
                    a[i] = ai
                    b[i] = bi
                    na += ai * ai
                na = math.sqrt(na)
                tb = 0.0
                for i in range(d):
                    tau[i] = a[i] / na
                    tb += tau[i] * b[i]
                c = 2.0 * mu * U
                gr = U * U * mus
                for i in range(d):
                    f[i] = gr * tau[i] - c * (b[i] - tau[i] * tb)
                f[1] -= dmu * g
                if tangent:
                    # Pb = P b (the part of r_st across the axis)
                    for i in range(d):
                        for j in range(d):
                            pij = (1.0 if i == j else 0.0) - tau[i] * tau[j]
                            pbj = b[j] - tau[j] * tb
                            Jq[i, j] = (gr * pij + c * (pij * tb + tau[i] * pbj)) / na
                            Jv[i, j] = -c * pij
            if acc_on:
                for i in range(d):
                    s_ = 0.0
                    for kk in range(4):
                        s_ += N[kk] * acc[base + kk * d + i]
                    ag[i] = s_
                for i in range(d):
                    f[i] -= dmu * ag[i]
            for kk in range(4):
                for i in range(d):
                    fi = w * N[kk] * f[i]
                    F[base + kk * d + i] += fi
                    if keep:
                        Fe[e, kk * d + i] += fi
            if not tangent:
                continue
            for kk in range(4):
                for ll in range(4):
                    if forces:
                        c1 = w * N[kk] * dN[ll]
                        for i in range(d):
                            for j in range(d):
                                kloc[kk * d + i, ll * d + j] -= c1 * (cK * Jq[i, j]
                                                                      + cC * Jv[i, j])
                    if acc_on:
                        c2 = cM * w * N[kk] * N[ll] * dmu
                        for i in range(d):
                            kloc[kk * d + i, ll * d + i] += c2
        if tangent:
            for r in range(4 * d):
                for c_ in range(4 * d):
                    K[row0 + r - c_, base + c_] += kloc[r, c_]


class Flow:
    """The scene's internal flow on one mesh (``mesh``, dimension ``d``, Gauss points
    ``xg``, ``wg``) for the time domain; ``time`` [s] the flow's clock (t = 0 at the
    static state, set by the run)."""

    def __init__(self, scene, mesh, d: int, xg, wg):
        fl = scene.internal_flow
        self.d = d
        self.s0 = np.ascontiguousarray(mesh.s, dtype=float)
        self.l0 = mesh.l0
        self.xg, self.wg = xg, wg
        eta = fl.density_amplitude if fl.has_slug else 0.0
        self.par = FlowPar(float(fl.speed), contents_mass_per_length(scene), float(eta),
                           float(fl.wavenumber), float(fl.omega),
                           math.radians(fl.phase_deg), float(scene.gravity))
        self.has_slug = fl.has_slug
        self.time = 0.0

    def _call(self, q, v, acc, forces, cK, cC, cM, F, K, kl, Fe):
        p = self.par
        flow_pass(q, v, acc, self.d, self.s0, self.l0, self.xg, self.wg, p.U, p.mu0, p.eta,
                  p.k, p.omega, p.psi, p.g, self.time, forces, cK, cC, cM, F, K, kl, Fe)

    def forces(self, q, v, F, K, kl, cK: float, cC: float, Fe) -> None:
        """The gradient, Coriolis and slug-weight forces into ``F`` (N,) (``Fe`` per
        element), their linearisation cK (-dQ/dq) + cC (-dQ/dv) into the band ``K``
        (shape (1, 1): none)."""
        self._call(q, v, np.zeros(0), True, cK, cC, 0.0, F, K, kl, Fe)

    def inertia(self, acc, F, K, kl, cM: float, Fe) -> None:
        """The slug's inertial force int (mu - mu_0) N^T N ds ``acc`` (the mass matrix's
        share beyond the mesh's mean contents, times ``acc``) added to ``F`` (N,) (``Fe``
        per element), as :func:`ancf.mass.mass_pass` adds M acc; cM x that mass matrix
        into the band ``K`` (shape (1, 1): none)."""
        if not self.has_slug:
            return
        z = np.zeros(0)
        # the kernel adds the force -(mu - mu_0) r_tt: given -acc, it adds the inertia
        self._call(z, z, -acc, False, 0.0, 0.0, cM, F, K, kl, Fe)


def frozen_slug_weight(scene, mesh, d: int, xg, wg) -> np.ndarray:
    """The slug's extra weight frozen at t = 0, int N^T (0, -(mu(s, 0) - mu_0) g) ds per
    element (ne, 4 d) [N] (zeros without a slug): the statics' density pattern."""
    out = np.zeros((mesh.ne, 4 * d))
    fl = scene.internal_flow
    if fl is None or not fl.has_slug:
        return out
    flow = Flow(scene, mesh, d, xg, wg)
    n = mesh.n * 2 * d
    q = np.zeros((mesh.n, 2 * d))   # at rest with U = 0: the weight alone (a unit slope
    q[:, d] = 1.0                   # for the tangent the zero forces are read along)
    q = q.ravel()
    p = flow.par
    flow_pass(q, np.zeros(n), np.zeros(0), d, flow.s0, flow.l0, xg, wg, 0.0, p.mu0, p.eta,
              p.k, p.omega, p.psi, p.g, 0.0, True, 0.0, 0.0, 0.0, np.zeros(n),
              np.zeros((1, 1)), 0, out)
    return out

"""The ANCF's inertia: the consistent mass matrix with the added mass normal to the axis
(Numba).

Per unit unstretched length the line carries its mass m (pipe and contents) [kg/m],
isotropic, and the added mass m_a = C_a rho pi D^2 / 4 [kg/m] across its axis only: the
inertial force per length is m r_tt + m_a P r_tt with P = I - t t^T the projector across
the tangent t = r'/|r'|. Consistently integrated, M(q) = int N^T (m I + m_a P) N ds
(Gauss quadrature, the same points as the elastic forces): constant for the structure,
dependent on the tangent through the added mass. A point attachment adds its mass and
(isotropic) added mass to its node's position unknowns.

The time integration (:mod:`ancf.dynamics.run`) uses M(q) at the current iterate in both the
inertial force and the Jacobian, leaving out dP/dq r_tt (of order m_a |r_tt| / |r'|,
small against the stiffness; the Newton iterations converge to the same step).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .element import shape_into
from .loads import wet_fraction

_JIT = dict(cache=True, error_model="numpy", nogil=True)


@njit(**_JIT)
def mass_pass(q, acc, d, l0, m, ma, xg, wg, coef, M, kl, f, Fe, use_surface, ysurf, band):
    """Add ``coef`` x M(q) to the band matrix ``M`` (``coef`` 0: not) and M(q) ``acc`` to
    ``f`` (N,) (``acc`` of length 0: not), each element's share also to ``Fe`` (ne, 4 d)
    when it has ne rows. q (N,) the state, l0, m, ma (ne,) the elements' length [m], mass
    and added mass per length [kg/m]; with ``use_surface`` the added mass is that of the
    wet fraction (:func:`ancf.loads.wet_fraction`, band (ne,) [m])."""
    ne = l0.shape[0]
    nd = 2 * d
    ng = xg.shape[0]
    row0 = 2 * kl
    t = np.empty(d)
    N = np.empty(4)
    dN = np.empty(4)
    ddN = np.empty(4)
    acc_on = acc.shape[0] > 0
    ag = np.empty(d)
    for e in range(ne):
        L = l0[e]
        base = e * nd
        for gp in range(ng):
            shape_into(xg[gp], L, N, dN, ddN)
            na = 0.0
            y = 0.0
            for k in range(4):
                y += N[k] * q[base + k * d + 1]
            mae = ma[e]
            if use_surface:
                wet, _ = wet_fraction(y, ysurf, band[e])
                mae = wet * ma[e]
            for i in range(d):
                ai = 0.0
                for k in range(4):
                    ai += dN[k] * q[base + k * d + i]
                t[i] = ai
                na += ai * ai
            na = np.sqrt(na)
            for i in range(d):
                t[i] /= na
            w = wg[gp] * L
            if acc_on:
                for i in range(d):
                    s = 0.0
                    for k in range(4):
                        s += N[k] * acc[base + k * d + i]
                    ag[i] = s
                at = 0.0
                for i in range(d):
                    at += ag[i] * t[i]
                keep = Fe.shape[0] == ne
                for k in range(4):
                    for i in range(d):
                        fi = w * N[k] * ((m[e] + mae) * ag[i] - mae * at * t[i])
                        f[base + k * d + i] += fi
                        if keep:
                            Fe[e, k * d + i] += fi
            if coef != 0.0:
                for k in range(4):
                    for l in range(4):
                        c = coef * w * N[k] * N[l]
                        for i in range(d):
                            for j in range(d):
                                dij = 1.0 if i == j else 0.0
                                M[row0 + k * d + i - (l * d + j), base + l * d + j] += c * (
                                    (m[e] + mae) * dij - mae * t[i] * t[j])

"""The ANCF element: gradient-deficient beam (cable) elements with cubic Hermite
interpolation, their elastic forces and consistent tangent (Numba).

Each node i carries the position r_i [m] and the slope r'_i = dr/ds [-] (d = 2 components in
a planar scene, 3 in a 3D one), s the unstretched arc length [m]; the generalised
coordinates are stored node by node, q = [r_0, r'_0, r_1, r'_1, ...] (2d per node). On an
element of length L between nodes e and e + 1, with xi = (s - s_e) / L in [0, 1],

    r(xi) = N1 r_e + N2 r'_e + N3 r_{e+1} + N4 r'_{e+1},
    N1 = 1 - 3 xi^2 + 2 xi^3, N2 = L (xi - 2 xi^2 + xi^3),
    N3 = 3 xi^2 - 2 xi^3,     N4 = L (xi^3 - xi^2)

(C1 across nodes: the slope is shared). With a = r' and b = r'' the strain energy per
unstretched length of the extensible elastica (the model of the other methods: axial
strain eps = |r'| - 1, the effective tension T = EA eps, the bending moment M = EI kappa
with kappa = d theta / ds the rotation of the tangent per unstretched length) is

    e(a, b) = EA/2 (|a| - 1)^2 + EI/2 kappa^2,
    kappa^2 = |a x b|^2 / |a|^4 = ((a.a)(b.b) - (a.b)^2) / (a.a)^2

(the cross product's square written with dot products: the same formula in 2D and 3D;
Liu et al.'s Eq. 14 divides by |a|^3, the curvature per stretched length: their moment
differs from this one by the strain T/EA: 0.03-0.06 % on the built-in steel risers, up to
0.1-0.3 % in steel stressed to 200-600 MPa, which the comparisons' 0.2 % would see). The elastic forces are the energy's gradient Q = int (dN^T e_a + ddN^T e_b)
ds and the tangent its Hessian, both by Gauss quadrature with the analytic derivatives
of e (:func:`_energy_derivatives`; tests/unit/ancf/test_ancf_element.py checks them against
central differences). The tangent is symmetric and indefinite where the line is in
compression (the term (|a| - 1)/|a| of the axial part), so the assembly is solved by LU.
"""

from __future__ import annotations

import numpy as np
from numba import njit

_JIT = dict(cache=True, error_model="numpy", nogil=True)


@njit(inline="always", **_JIT)
def shape(xi, L):
    """(N (4,), dN/ds (4,), d2N/ds2 (4,)) of the cubic Hermite element of length ``L`` [m]
    at ``xi`` in [0, 1]."""
    N = np.empty(4)
    dN = np.empty(4)
    ddN = np.empty(4)
    shape_into(xi, L, N, dN, ddN)
    return N, dN, ddN


@njit(inline="always", **_JIT)
def shape_into(xi, L, N, dN, ddN):
    """:func:`shape` written into the given arrays (the kernels' loops allocate nothing)."""
    x2 = xi * xi
    x3 = x2 * xi
    N[0] = 1.0 - 3.0 * x2 + 2.0 * x3
    N[1] = L * (xi - 2.0 * x2 + x3)
    N[2] = 3.0 * x2 - 2.0 * x3
    N[3] = L * (x3 - x2)
    dN[0] = (-6.0 * xi + 6.0 * x2) / L
    dN[1] = 1.0 - 4.0 * xi + 3.0 * x2
    dN[2] = (6.0 * xi - 6.0 * x2) / L
    dN[3] = 3.0 * x2 - 2.0 * xi
    ddN[0] = (12.0 * xi - 6.0) / (L * L)
    ddN[1] = (6.0 * xi - 4.0) / L
    ddN[2] = (6.0 - 12.0 * xi) / (L * L)
    ddN[3] = (6.0 * xi - 2.0) / L


@njit(inline="always", **_JIT)
def _energy_derivatives(a, b, EA, EI, ga, gb, Haa, Hab, Hbb, hessian):
    """The strain energy per length e(a, b) of the module docstring, its gradient (ga, gb)
    and (with ``hessian``) its Hessian blocks Haa, Hab (d2e/da db, [i, j] = d/db_j of
    de/da_i), Hbb, written into the given arrays. Returns (e, |a|, kappa)."""
    d = a.shape[0]
    g = 0.0
    bb = 0.0
    ab = 0.0
    for i in range(d):
        g += a[i] * a[i]
        bb += b[i] * b[i]
        ab += a[i] * b[i]
    na = np.sqrt(g)
    eps = na - 1.0
    h = g * bb - ab * ab
    if h < 0.0:
        h = 0.0
    g2 = g * g
    f = h / g2
    kappa = np.sqrt(f)
    # axial: EA/2 (|a| - 1)^2
    for i in range(d):
        ga[i] = EA * eps * a[i] / na
    # bending: EI/2 h g^-2, h_a = 2 a bb - 2 b ab, h_b = 2 b g - 2 a ab, g_a = 2 a
    c = 0.5 * EI
    g3 = g2 * g
    for i in range(d):
        ha = 2.0 * a[i] * bb - 2.0 * b[i] * ab
        hb = 2.0 * b[i] * g - 2.0 * a[i] * ab
        ga[i] += c * (ha / g2 - 4.0 * h * a[i] / g3)
        gb[i] = c * hb / g2
    if hessian:
        g4 = g3 * g
        t1 = EA / g
        t2 = EA * eps / na
        for i in range(d):
            hai = 2.0 * a[i] * bb - 2.0 * b[i] * ab
            hbi = 2.0 * b[i] * g - 2.0 * a[i] * ab
            for j in range(d):
                dij = 1.0 if i == j else 0.0
                haj = 2.0 * a[j] * bb - 2.0 * b[j] * ab
                hbj = 2.0 * b[j] * g - 2.0 * a[j] * ab
                # axial: EA [a a^T / g + eps/|a| (I - a a^T / g)]
                axial = t1 * a[i] * a[j] + t2 * (dij - a[i] * a[j] / g)
                h_aa = 2.0 * bb * dij - 2.0 * b[i] * b[j]
                h_bb = 2.0 * g * dij - 2.0 * a[i] * a[j]
                h_ab = 4.0 * a[i] * b[j] - 2.0 * b[i] * a[j] - 2.0 * ab * dij
                f_aa = (h_aa / g2 - 4.0 * (hai * a[j] + a[i] * haj) / g3
                        + 24.0 * h * a[i] * a[j] / g4 - 4.0 * h * dij / g3)
                f_ab = h_ab / g2 - 4.0 * a[i] * hbj / g3
                Haa[i, j] = axial + c * f_aa
                Hab[i, j] = c * f_ab
                Hbb[i, j] = c * h_bb / g2
            _ = hbi
    return 0.5 * EA * eps * eps + c * f, na, kappa


@njit(**_JIT)
def elastic_pass(q, d, l0, EA, EI, xg, wg, hessian, F, K, kl, Fe):
    """Elastic forces (added to ``F`` (N,)) and, with ``hessian``, the tangent (added to the
    band matrix ``K`` in LAPACK's general band layout: K[i, j] at row kl + kl + i - j...
    see :mod:`ancf.banded`, ``kl`` the half-bandwidth, 4 d - 1) of every element.

    q (N,) the generalised coordinates (2 d per node), d the dimension (2 or 3), l0, EA,
    EI (ne,) the elements' length [m], axial [N] and bending stiffness [N m2], xg, wg the
    Gauss points on [0, 1] and their weights; ``Fe`` (ne, 4 d) receives each element's
    own force vector (the section forces' recovery, :mod:`ancf.output`; an empty (0, 4 d)
    array keeps none).
    Returns the strain energy [J]."""
    ne = l0.shape[0]
    nd = 2 * d
    ng = xg.shape[0]
    a = np.empty(d)
    b = np.empty(d)
    ga = np.empty(d)
    gb = np.empty(d)
    Haa = np.empty((d, d))
    Hab = np.empty((d, d))
    Hbb = np.empty((d, d))
    fl = np.empty(2 * nd)
    kloc = np.empty((2 * nd, 2 * nd))
    N = np.empty(4)
    dN = np.empty(4)
    ddN = np.empty(4)
    energy = 0.0
    row0 = 2 * kl
    for e in range(ne):
        L = l0[e]
        base = e * nd
        for p in range(2 * nd):
            fl[p] = 0.0
            if hessian:
                for r in range(2 * nd):
                    kloc[p, r] = 0.0
        for gp in range(ng):
            shape_into(xg[gp], L, N, dN, ddN)
            for i in range(d):
                ai = 0.0
                bi = 0.0
                for k in range(4):
                    v = q[base + k * d + i]
                    ai += dN[k] * v
                    bi += ddN[k] * v
                a[i] = ai
                b[i] = bi
            en, _, _ = _energy_derivatives(a, b, EA[e], EI[e], ga, gb, Haa, Hab, Hbb,
                                           hessian)
            w = wg[gp] * L
            energy += w * en
            for k in range(4):
                for i in range(d):
                    fl[k * d + i] += w * (dN[k] * ga[i] + ddN[k] * gb[i])
            if hessian:
                for k in range(4):
                    for m in range(4):
                        c_aa = w * dN[k] * dN[m]
                        c_ab = w * dN[k] * ddN[m]
                        c_ba = w * ddN[k] * dN[m]
                        c_bb = w * ddN[k] * ddN[m]
                        for i in range(d):
                            for j in range(d):
                                kloc[k * d + i, m * d + j] += (
                                    c_aa * Haa[i, j] + c_ab * Hab[i, j]
                                    + c_ba * Hab[j, i] + c_bb * Hbb[i, j])
        add_element(F, K, Fe, fl, kloc, e, base, row0, hessian)
    return energy


@njit(inline="always", **_JIT)
def add_element(F, K, Fe, fl, kloc, e, base, row0, with_matrix):
    """Add element ``e``'s vector ``fl`` (4 d) to ``F`` at ``base`` (and keep it in row e
    of ``Fe`` when Fe has a row per element) and, ``with_matrix``, its matrix ``kloc``
    to the band ``K`` (its rows from ``row0`` = 2 kl, :mod:`ancf.banded`)."""
    n = fl.shape[0]
    keep = Fe.shape[0] > e
    for p in range(n):
        F[base + p] += fl[p]
        if keep:
            Fe[e, p] = fl[p]
        if with_matrix:
            for r in range(n):
                K[row0 + p - r, base + r] += kloc[p, r]


@njit(**_JIT)
def element_fields(q, d, l0, EA, EI, e, xi):
    """(r (d,), a = r' (d,), b = r'' (d,), tension EA (|a| - 1) [N], kappa [1/m]) of element
    ``e`` at ``xi`` in [0, 1]."""
    nd = 2 * d
    L = l0[e]
    N, dN, ddN = shape(xi, L)
    r = np.zeros(d)
    a = np.zeros(d)
    b = np.zeros(d)
    base = e * nd
    for i in range(d):
        for k in range(4):
            v = q[base + k * d + i]
            r[i] += N[k] * v
            a[i] += dN[k] * v
            b[i] += ddN[k] * v
    g = 0.0
    bb = 0.0
    ab = 0.0
    for i in range(d):
        g += a[i] * a[i]
        bb += b[i] * b[i]
        ab += a[i] * b[i]
    h = max(g * bb - ab * ab, 0.0)
    return r, a, b, EA[e] * (np.sqrt(g) - 1.0), np.sqrt(h) / g


@njit(**_JIT)
def damping_pass(q, v, d, l0, BA, xg, wg, cK, cC, F, K, kl, Fe):
    """The internal axial damping (Kelvin-Voigt, MoorDyn's BA): the axial force N_d = BA
    d(eps)/dt [N] with eps = |r'| - 1, so d(eps)/dt = r'.v'/|r'| (v' = dr'/dt, the rates'
    slope), whose virtual work N_d d(eps) = N_d (r'/|r'|).d(r') gives the generalised force
    int dN^T N_d r'/|r'| ds, added to ``F`` (N,) (and per element to ``Fe`` as
    :func:`elastic_pass`). Per unstretched length its vector g = BA (a.c) a / (a.a) (a = r',
    c = v') has the Jacobians dg/da = BA (a c^T + (a.c) I - 2 (a.c) a a^T / (a.a)) / (a.a)
    and dg/dc = BA a a^T / (a.a); with ``cK`` or ``cC`` non-zero ``cK`` dF/dq + ``cC`` dF/dv
    is added to the band ``K`` (an implicit step's consistent Jacobian;
    tests/test_axial_damping.py checks it against central differences).

    q, v (N,) the generalised coordinates and their rates, d the dimension, l0 (ne,) [m],
    BA (ne,) [N s] (elements with BA = 0 skipped), xg, wg the Gauss points and weights on
    [0, 1]. Returns the dissipated power int N_d d(eps)/dt ds [W]."""
    ne = l0.shape[0]
    nd = 2 * d
    ng = xg.shape[0]
    a = np.empty(d)
    c = np.empty(d)
    fl = np.empty(2 * nd)
    kloc = np.empty((2 * nd, 2 * nd))
    N = np.empty(4)
    dN = np.empty(4)
    ddN = np.empty(4)
    G = np.empty((d, d))
    matrix = cK != 0.0 or cC != 0.0
    row0 = 2 * kl
    power = 0.0
    for e in range(ne):
        ba = BA[e]
        if ba == 0.0:
            continue
        L = l0[e]
        base = e * nd
        for p in range(2 * nd):
            fl[p] = 0.0
            if matrix:
                for r in range(2 * nd):
                    kloc[p, r] = 0.0
        for gp in range(ng):
            shape_into(xg[gp], L, N, dN, ddN)
            for i in range(d):
                ai = 0.0
                ci = 0.0
                for k in range(4):
                    ai += dN[k] * q[base + k * d + i]
                    ci += dN[k] * v[base + k * d + i]
                a[i] = ai
                c[i] = ci
            g = 0.0
            ac = 0.0
            for i in range(d):
                g += a[i] * a[i]
                ac += a[i] * c[i]
            w = wg[gp] * L
            power += w * ba * ac * ac / g
            s = ba * ac / g                     # N_d / |a|
            for k in range(4):
                for i in range(d):
                    fl[k * d + i] += w * dN[k] * s * a[i]
            if matrix:
                for i in range(d):
                    for j in range(d):
                        dij = 1.0 if i == j else 0.0
                        G[i, j] = (cK * ba * (a[i] * c[j] + ac * dij
                                              - 2.0 * ac * a[i] * a[j] / g)
                                   + cC * ba * a[i] * a[j]) / g
                for k in range(4):
                    for m in range(4):
                        cw = w * dN[k] * dN[m]
                        for i in range(d):
                            for j in range(d):
                                kloc[k * d + i, m * d + j] += cw * G[i, j]
        add_element(F, K, Fe, fl, kloc, e, base, row0, matrix)
    return power

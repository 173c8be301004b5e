"""The ANCF's distributed loads that depend on the state: the seabed's Winkler contact and
Morison drag on the velocity relative to the current (Numba), each with its linearisation.

Both are integrated over each element by Gauss quadrature on the unstretched length (loads
per unit unstretched length, like the other methods'), F_ext = int N^T f ds; the kernels
add F_ext to ``F`` and its derivatives to the band matrix as the residual R = F_int -
F_ext needs them: ``cK`` (-dF_ext/dq) + ``cC`` (-dF_ext/dq_dot) (statics: cK = 1, cC =
0; an implicit step: its own coefficients, :mod:`ancf.dynamics.run`).

Seabed (y = 0, y up): the unilateral Winkler foundation p = k max(-y, 0) [N/m per m]
upwards with the dashpot -c y_dot while in contact, c = 2 zeta sqrt(k m) [N s/m2] per
unit length (zeta the scene's damping ratio, m the mass per length with the added mass),
and Coulomb friction mu p on the horizontal velocity, regularised as mu p v_h /
sqrt(|v_h|^2 + v_f^2) (v_f a small speed). A planar scene's friction acts along x.

Drag: u = U(y) - v the water's velocity relative to the line (U the current at the
height y, its components interpolated linearly between the profile's heights and constant
beyond them), t = r'/|r'| the tangent, u_t = u.t and u_n = u - u_t t;
f = c_n |u_n| u_n + c_t |u_t| u_t t with c_n = rho D C_dn / 2 and c_t = rho pi D C_dt / 2
[kg/m2] (the tangential coefficient on the perimeter, as the scenes define it).
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np
from numba import njit

from .element import add_element, shape_into

_JIT = dict(cache=True, error_model="numpy", nogil=True)


@njit(inline="always", **_JIT)
def _current(y, heights, comps, slopes, d, U, dU):
    """The current's velocity U (d,) [m/s] at height ``y`` and its derivative dU/dy."""
    m = heights.shape[0]
    for i in range(d):
        U[i] = comps[i, 0]
        dU[i] = 0.0
    for j in range(m - 1):
        h0 = heights[j]
        h1 = heights[j + 1]
        if y > h0:
            yy = y if y < h1 else h1
            for i in range(d):
                U[i] += slopes[i, j] * (yy - h0)
                if y < h1:
                    dU[i] = slopes[i, j]


@njit(inline="always", **_JIT)
def wet_fraction(y, ysurf, band):
    """(wet, d wet / dy): the immersed fraction of a section of height ``band`` [m]
    centred at ``y`` under the surface ``ysurf`` [m] (linear across the band)."""
    x = (ysurf - y) / band + 0.5
    if x >= 1.0:
        return 1.0, 0.0
    if x <= 0.0:
        return 0.0, 0.0
    return x, -1.0 / band


@njit(inline="always", **_JIT)
def drag_force(u, t, cn, ct, d, f, Fu, Ft, un):
    """Morison drag f (d,) per length of the relative velocity u (d,) on an element of
    unit tangent t (d,), and its Jacobians Fu = df/du, Ft = df/dt (d, d) (the module
    docstring's law); ``un`` (d,) scratch."""
    ut = 0.0
    for i in range(d):
        ut += u[i] * t[i]
    un2 = 0.0
    for i in range(d):
        un[i] = u[i] - ut * t[i]
        un2 += un[i] * un[i]
    nun = np.sqrt(un2)
    aut = abs(ut)
    inv = 1.0 / nun if nun > 0.0 else 0.0
    for i in range(d):
        f[i] = cn * nun * un[i] + ct * aut * ut * t[i]
        for j in range(d):
            dij = 1.0 if i == j else 0.0
            P = dij - t[i] * t[j]
            Fu[i, j] = cn * (nun * P + un[i] * un[j] * inv) + 2.0 * ct * aut * t[i] * t[j]
            Ft[i, j] = (cn * (-ut * un[i] * un[j] * inv - nun * (t[i] * u[j] + ut * dij))
                        + ct * aut * (2.0 * t[i] * u[j] + ut * dij))


#: the kernels' argument groups (named tuples: one argument each to Numba)
#: the seabed: on, stiffness k [N/m2], damping c (ne,) [N s/m2], friction mu, vfric [m/s]
Seabed = namedtuple("Seabed", "on k c mu vfric")
#: the drag: on, cdn, cdt (ne,) [kg/m2], the current's heights (m,) [m], components (d, m)
#: [m/s] and slopes (d, m - 1) [1/s]
Drag = namedtuple("Drag", "on cdn cdt heights comps slopes")
#: the sea surface: on, its still level [m], the band (ne,) [m], the lost buoyancy (ne,) [N/m]
Surface = namedtuple("Surface", "on level band buoy")
#: the waves: on, velocity U and acceleration A at the Gauss points (ne ng, d), the
#: surface's height S (ne ng,) [m], the inertia coefficients cinn, cint (ne,) [kg/m]
Waves = namedtuple("Waves", "on U A S cinn cint")


@njit(**_JIT)
def load_pass(q, v, d, l0, xg, wg, seabed, drag, surface, waves, cK, cC, F, K, kl, Fe):
    """Add the seabed's and the drag's nodal loads F_ext to ``F`` (N,) and cK (-dF/dq) +
    cC (-dF/dv) to the band matrix ``K`` (skipped when both are 0).

    q, v (N,): generalised coordinates and their rates (zeros in statics); l0 (ne,) [m];
    the groups :data:`Seabed` (kseabed [N/m2] and cseabed (ne,) [N s/m2] the contact's
    stiffness and damping per length, mu and vfric [m/s] the friction), :data:`Drag` (cdn,
    cdt (ne,) [kg/m2]; heights (m,) [m], comps (d, m) [m/s] the current's components at
    those heights, slopes (d, m - 1) their gradients [1/s]), :data:`Surface` and
    :data:`Waves`; ``Fe`` (ne, 4 d) receives each element's own loads (an empty (0, 4 d) array:
    not kept). The sea surface (``use_surface``, a time domain): at a height y the line
    is wet by the fraction wet = clip((ysurf - y) / band + 1/2, 0, 1) (band (ne,) [m] the
    outer diameter: the section crossing the surface), and its dry part loses its
    buoyancy, buoy (ne,) [N/m] (the weight in air less the submerged weight), and its
    drag (:func:`wet_fraction`; the added mass likewise, :mod:`ancf.mass`). Waves
    (``use_waves``, :mod:`ancf.waves`): at Gauss point p = e ng + gp the water's velocity
    WU[p] and acceleration WA[p] (ne ng, d) [m/s, m/s2] and the surface's height WS[p] [m]:
    drag on the velocity relative to current + waves, and the fluid inertia
    cinn a_n + cint a_t per length (cinn = (1 + C_a) rho A, cint = rho A [kg/m], (ne,)),
    both times the wet fraction under that surface.
    Returns the seabed's potential energy int k/2 min(y, 0)^2 ds [J]."""
    kseabed, cseabed, mu, vfric, use_seabed = seabed.k, seabed.c, seabed.mu, seabed.vfric, \
        seabed.on
    cdn, cdt, heights, comps, slopes, use_drag = (drag.cdn, drag.cdt, drag.heights,
                                                  drag.comps, drag.slopes, drag.on)
    use_surface, ysurf, band, buoy = surface.on, surface.level, surface.band, surface.buoy
    use_waves, WU, WA, WS, cinn, cint = (waves.on, waves.U, waves.A, waves.S, waves.cinn,
                                         waves.cint)
    ne = l0.shape[0]
    nd = 2 * d
    ng = xg.shape[0]
    lin = cK != 0.0 or cC != 0.0
    r = np.empty(d)
    a = np.empty(d)
    rv = np.empty(d)
    t = np.empty(d)
    u = np.empty(d)
    U = np.empty(d)
    dU = np.empty(d)
    f = np.empty(d)
    Fu = np.empty((d, d))
    Ft = np.empty((d, d))
    Fq = np.empty((d, d, 2))       # df/dr (via U(y)), df/da (via t): [:, :, 0], [:, :, 1]
    Fv = np.empty((d, d))
    fl = np.empty(2 * nd)
    kloc = np.empty((2 * nd, 2 * nd))
    N = np.empty(4)
    dN = np.empty(4)
    ddN = np.empty(4)
    un = np.empty(d)
    fd = np.empty(d)
    row0 = 2 * kl
    seabed_energy = 0.0
    for e in range(ne):
        L = l0[e]
        base = e * nd
        if use_seabed and not use_drag:
            # an element whose nodes and slopes keep it clear of the seabed (the cubic's
            # lowest point is above min(y) - L/4 max|y'|) has no contact: skipped
            y0 = q[base + 1]
            y1 = q[base + nd + 1]
            sl = max(abs(q[base + d + 1]), abs(q[base + nd + d + 1]))
            if min(y0, y1) - 0.25 * L * sl > 0.0:
                continue
        for p in range(2 * nd):
            fl[p] = 0.0
            for s in range(2 * nd):
                kloc[p, s] = 0.0
        touched = False
        for gp in range(ng):
            shape_into(xg[gp], L, N, dN, ddN)
            for i in range(d):
                ri = 0.0
                ai = 0.0
                vi = 0.0
                for k in range(4):
                    ri += N[k] * q[base + k * d + i]
                    ai += dN[k] * q[base + k * d + i]
                    vi += N[k] * v[base + k * d + i]
                r[i] = ri
                a[i] = ai
                rv[i] = vi
            w = wg[gp] * L
            for i in range(d):
                f[i] = 0.0
                for j in range(d):
                    Fq[i, j, 0] = 0.0
                    Fq[i, j, 1] = 0.0
                    Fv[i, j] = 0.0
            y = r[1]
            wet = 1.0
            pidx = e * ng + gp
            if use_surface:
                wet, dwet = wet_fraction(y, WS[pidx] if use_waves else ysurf, band[e])
                if wet < 1.0:
                    touched = True
                    f[1] -= (1.0 - wet) * buoy[e]
                    Fq[1, 1, 0] += dwet * buoy[e]
            if use_seabed and y < 0.0:
                touched = True
                seabed_energy += w * 0.5 * kseabed * y * y
                p_n = -kseabed * y
                f[1] += p_n
                Fq[1, 1, 0] += -kseabed
                f[1] -= cseabed[e] * rv[1]
                Fv[1, 1] -= cseabed[e]
                if mu > 0.0:
                    vh2 = vfric * vfric
                    for i in range(d):
                        if i != 1:
                            vh2 += rv[i] * rv[i]
                    den = np.sqrt(vh2)
                    for i in range(d):
                        if i == 1:
                            continue
                        fr = mu * p_n * rv[i] / den
                        f[i] -= fr
                        Fq[i, 1, 0] += mu * kseabed * rv[i] / den
                        for j in range(d):
                            if j == 1:
                                continue
                            dij = 1.0 if i == j else 0.0
                            Fv[i, j] -= mu * p_n * (dij / den - rv[i] * rv[j] / (den ** 3))
            if use_drag and wet > 0.0 and (cdn[e] > 0.0 or cdt[e] > 0.0):
                _current(y, heights, comps, slopes, d, U, dU)
                na = 0.0
                for i in range(d):
                    na += a[i] * a[i]
                na = np.sqrt(na)
                for i in range(d):
                    t[i] = a[i] / na
                    u[i] = U[i] - rv[i]
                    if use_waves:
                        u[i] += WU[pidx, i]
                drag_force(u, t, wet * cdn[e], wet * cdt[e], d, fd, Fu, Ft, un)
                if wet < 1.0:               # d(wet)/dy on the drag of the dry part
                    for i in range(d):
                        Fq[i, 1, 0] += fd[i] / wet * dwet
                for i in range(d):
                    f[i] += fd[i]
                    for j in range(d):
                        Fv[i, j] -= Fu[i, j]
                        # df/dy through U(y)
                        Fq[i, 1, 0] += Fu[i, j] * dU[j]
                        # df/da = Ft (I - t t^T) / |a|
                        s_ = 0.0
                        for m in range(d):
                            dmj = 1.0 if m == j else 0.0
                            s_ += Ft[i, m] * (dmj - t[m] * t[j])
                        Fq[i, j, 1] += s_ / na
                touched = True
            if use_waves and wet > 0.0:
                # the fluid's inertia: (1 + C_a) rho A a_n + rho A a_t
                na = 0.0
                at = 0.0
                for i in range(d):
                    na += a[i] * a[i]
                na = np.sqrt(na)
                for i in range(d):
                    at += WA[pidx, i] * a[i] / na
                dc = cint[e] - cinn[e]
                for i in range(d):
                    ti = a[i] / na
                    fi = cinn[e] * WA[pidx, i] + dc * at * ti
                    f[i] += wet * fi
                    if use_surface:
                        Fq[i, 1, 0] += dwet * fi
                    # d/da of dc (A.t) t: dc (t A^T + (A.t) I) (I - t t^T) / |a|
                    for j in range(d):
                        tj = a[j] / na
                        s_ = 0.0
                        for m in range(d):
                            tm = a[m] / na
                            dmj = 1.0 if m == j else 0.0
                            dim = 1.0 if i == m else 0.0
                            s_ += (ti * WA[pidx, m] + at * dim) * (dmj - tm * tj)
                        Fq[i, j, 1] += wet * dc * s_ / na
                touched = True
            for k in range(4):
                for i in range(d):
                    fl[k * d + i] += w * N[k] * f[i]
            if lin:
                for k in range(4):
                    for m in range(4):
                        cr = w * N[k] * N[m]
                        ca = w * N[k] * dN[m]
                        for i in range(d):
                            for j in range(d):
                                kloc[k * d + i, m * d + j] -= (
                                    cK * (cr * Fq[i, j, 0] + ca * Fq[i, j, 1])
                                    + cC * cr * Fv[i, j])
        if touched:
            add_element(F, K, Fe, fl, kloc, e, base, row0, lin)
    return seabed_energy

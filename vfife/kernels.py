"""Numba kernels of the VFIFE riser model, on plain arrays.

Model (see ``vfife/__init__.py`` for the full statement)
--------------------------------------------------------
Nodes i = 0..n-1 carry a position ``X[i]`` [m], a velocity ``V[i]`` [m/s], a unit
*director* ``D[i]`` (the pipe axis at the node, rotated by the node's rotational DOF) and
an angular velocity ``W[i]`` [rad/s] perpendicular to ``D[i]``. Elements e = 0..n-2 join
nodes e (end a) and e+1 (end b) and are massless space beams.

Per element and step the rigid-body motion is removed by measuring everything against
the current chord ``e = (X[b]-X[a])/l`` (fictitious reverse translation and rotation):
the pure deformations are the elongation ``l - l0`` and the bending rotations of the end
directors relative to the chord, ``phi_a = e x D[a]`` and ``phi_b = e x D[b]`` (vectors
perpendicular to the chord carrying both bending planes). The element energy is

    U = EA/(2 l0) (l - l0)^2 + EI/l0 (2|phi_a|^2 + 2 phi_a.phi_b + 2|phi_b|^2),

i.e. the cubic beam's end moments M_a = EI/l0 (4 phi_a + 2 phi_b), M_b = EI/l0 (2 phi_a
+ 4 phi_b), and the nodal forces and moments are its exact gradient, so the internal
forces are conservative and vanish under any rigid-body motion. The shear follows from
element equilibrium (the transverse part of the force pair). Torsion: for an isotropic
round pipe without distributed torque and with ends free to twist the torsional moment
is zero everywhere (Kirchhoff), so the twist DOF is not integrated (GJ unused). Ends are
pinned (moment-free) unless ``[vfife] clamped_ends`` fixes their rotation: jinv = 0 at
that node, so its director keeps its starting direction and the end element's bending is
measured against it.

Integration: explicit central differences with mass-proportional damping ``c`` [1/s]:
``v+ = ((1 - c dt/2) v + dt a) / (1 + c dt/2)``, ``x+ = x + dt v+``; directors are
rotated by ``dt W`` and renormalised. The added mass acts normal to the director:
``a = F/(m + ma) + (d.F) d (1/m - 1/(m + ma))``.

Array layout is component-major (vectorises: 8x faster than (n, 3)): X, V, D, W are
(3, n) [(2, n) positions and (n,) rotation rate in the planar kernels], element force
arrays (3, ne), element and node scalars (ne,) and (n,). The planar
kernels (``*_2d``) run on the first two rows of the same arrays.
"""

from __future__ import annotations

import math
from collections import namedtuple

import llvmlite.binding as _llvm
import numpy as np
from numba import njit

# No 'nnan'/'ninf' fast-math flags: the blow-up checks rely on NaN comparisons.
# _NOWRAP: loops that read and write the same array index it with an unsigned integer
# (np.uint64): Numba wraps signed indices (a[-1]) with a select that LLVM cannot remove
# (no nsw on the range counter), which makes the addresses non-affine and stops the
# vectoriser ("unsafe indirect dependence"); unsigned indices are not wrapped. Mixed
# uint64/int64 arithmetic gives float64 in Numba, so offsets are uint64 too (``one``).
_FM = {"contract", "arcp", "reassoc", "nsz"}
# forceinline (LLVM 'alwaysinline'; inherited by the Numba functions compiled for them,
# np.cross, np.zeros): reproducible bits. Numba links a copy of every jitted callee into
# its caller's module (weak, 'linkonce_odr') and optimises that copy again with the
# caller; with the fast-math flags the re-optimised copy rounds differently from the
# callee's own library. A caller loaded from the on-disk cache calls its own copy, but
# one compiled in this process calls the callee's own library (compiled first, during
# the caller's typing, and the process-wide symbol wins over a weak one): the same
# relaxation gave other bits on a cold cache than on a warm one (node_pass; 3e-9 in the
# reports). Inlined, a caller has no call to resolve, so the code is the same whether
# compiled or loaded. Costs a third more compile time on a cold cache (16 -> 21 s), nothing
# per step (the bench kernels within +-5 %, the noise; docs/theory.md, Reproducibility;
# tests/test_reproducible.py checks that no call is left).
_JIT = dict(cache=True, error_model="numpy", fastmath=_FM, nogil=True, forceinline=True)

# ------------------------------------------------------------------ the arrays of run()
#: The arrays and flags :func:`run` takes, grouped by what they describe (named tuples:
#: Numba passes them as one argument each and reads a field at no cost; the bench's
#: kernel rows measured the same speed as 68 positional arguments, issue 45).
#: the state: positions X [m], velocities V [m/s], directors D, rotation rates W [1/s] (3, n)
State = namedtuple("State", "X V D W")
#: the line's properties: per element (ne,) l0 [m], kax [N/m], kb [N m], eta [N s/m];
#: per node (n,) mass [kg], im, imd (inverse masses), jinv, jrot, wload [N], kst [N/m],
#: wair [N], iair [1/kg], madd [kg], trib [m] (tributary length), dnode [m] (outer
#: diameter), cin (2, n) [kg], cdn, cdt (drag), cdp [kg/m] (point attachments' drag)
Line = namedtuple("Line", "l0 kax kb mass im imd jinv jrot wload kst eta wair iair madd "
                          "trib dnode cin cdn cdt cdp")
#: the sea: the current's profile (heights [m], speeds [m/s], slopes [1/s], cdir its
#: heading as the kernels take it, speeds_z, slopes_z of a turning current, cdir3 the 3D
#: heading), the seabed (cseabed, mu, vfric), the surface heights ysurf [m], the waves'
#: Taylor coefficients WT and the dead load P (3, n) [N]
Sea = namedtuple("Sea", "heights speeds slopes cdir speeds_z slopes_z cdir3 cseabed mu "
                        "vfric ysurf WT P")
#: which effects run (booleans): drag, a turning current, the axial dashpots, the sea
#: surface, internal flow, a dead load, waves, point attachments' drag
Effects = namedtuple("Effects", "drag turning dashpot surface flow dead waves points")
#: scratch arrays: element forces F, moments MA, MB, the current at the nodes U, Uz, the
#: residuals R, the dashpot forces Q, the flow forces FL, the waves' values WV and loads PW
Scratch = namedtuple("Scratch", "F MA MB U Uz R Q FL WV PW")
#: internal flow: the time t0 [s] at the start of the call, its parameters and nodes
Flow = namedtuple("Flow", "t0 fpar fnodes")
#: the ends: the planar kernels' end conditions (:data:`END_SLOTS`,), the hang-off's
#: position top0 (3,) [m] and its displacement top_disp (3, nsteps + 1) [m]
Ends = namedtuple("Ends", "conditions top0 top_disp")
# Vectorising the node passes: they read ~25 and write ~7 separate arrays, and since
# Numba cannot tell LLVM that the arrays do not overlap, the vectoriser guards the SIMD
# loop with a runtime overlap check per pair of pointers; above its default limit of 8
# checks it gives up ("too many memory checks needed") and the node passes stayed scalar
# (5.9 ns of the 16.9 ns per element-step 3D + drag). Raising the limits lets it emit the
# checks (a few hundred compares per call, against ~3,000 nodes per loop): the results
# are the same (the checks fall back to the scalar loop if arrays ever overlapped). The
# options are process-wide LLVM settings that only allow more runtime checks; they must
# be set before the kernels are compiled (cache=True stores the vectorised code).
_llvm.set_option("", "-runtime-memory-check-threshold=1000")
_llvm.set_option("", "-vectorize-memory-check-threshold=1000")


# ============================================================================ 3D
@njit(**_JIT)
def element_pass(x, y, z, dx_, dy_, dz_, l0, kax, kb, f0, f1, f2, a0, a1, a2, b0, b1, b2):
    """Internal forces of every element (pass 1, 3D).

    x, y, z, dx_, dy_, dz_ : (n,) node positions [m] and unit directors, one 1D array per
        component (separate 1D rows let LLVM vectorise the loop: 2.9 vs 18.7 ns).
    l0 : (ne,) unstretched lengths [m]; kax = EA/l0 [N/m]; kb = EI/l0 [N m].
    f0, f1, f2 : (ne,) out: force of element e on its node a [N] (node b receives -f).
    a0..a2, b0..b2 : (ne,) out: moments of element e on nodes a and b [N m].
    """
    ne = l0.shape[0]
    for e in range(ne):
        dx = x[e + 1] - x[e]
        dy = y[e + 1] - y[e]
        dz = z[e + 1] - z[e]
        l = math.sqrt(dx * dx + dy * dy + dz * dz)
        il = 1.0 / l
        ex = dx * il
        ey = dy * il
        ez = dz * il
        N = kax[e] * (l - l0[e])
        ax = dx_[e]
        ay = dy_[e]
        az = dz_[e]
        bx = dx_[e + 1]
        by = dy_[e + 1]
        bz = dz_[e + 1]
        # bending rotations of the end directors relative to the chord: phi = e x d
        pax = ey * az - ez * ay
        pay = ez * ax - ex * az
        paz = ex * ay - ey * ax
        pbx = ey * bz - ez * by
        pby = ez * bx - ex * bz
        pbz = ex * by - ey * bx
        k = kb[e]
        max_ = k * (4.0 * pax + 2.0 * pbx)
        may = k * (4.0 * pay + 2.0 * pby)
        maz = k * (4.0 * paz + 2.0 * pbz)
        mbx = k * (2.0 * pax + 4.0 * pbx)
        mby = k * (2.0 * pay + 4.0 * pby)
        mbz = k * (2.0 * paz + 4.0 * pbz)
        # G = d_a x M_a + d_b x M_b; its part normal to the chord / l is the shear pair
        gx = ay * maz - az * may + by * mbz - bz * mby
        gy = az * max_ - ax * maz + bz * mbx - bx * mbz
        gz = ax * may - ay * max_ + bx * mby - by * mbx
        eg = ex * gx + ey * gy + ez * gz
        f0[e] = (gx - eg * ex) * il + N * ex
        f1[e] = (gy - eg * ey) * il + N * ey
        f2[e] = (gz - eg * ez) * il + N * ez
        # nodal moments m = -((e.d) M - (M.d) e)
        eda = ex * ax + ey * ay + ez * az
        mda = max_ * ax + may * ay + maz * az
        a0[e] = mda * ex - eda * max_
        a1[e] = mda * ey - eda * may
        a2[e] = mda * ez - eda * maz
        edb = ex * bx + ey * by + ez * bz
        mdb = mbx * bx + mby * by + mbz * bz
        b0[e] = mdb * ex - edb * mbx
        b1[e] = mdb * ey - edb * mby
        b2[e] = mdb * ez - edb * mbz


@njit(**_JIT)
def current_pass(y, heights, speeds, slopes, U):
    """Current speed U[i] [m/s] at every node height y[i] [m]: the signed speed piecewise
    linear in height, constant outside the given heights, written branch-free as a sum of
    clamped ramps, U = speeds[0] + sum_j slopes[j] (clip(y, h_j, h_j+1) - h_j), slopes[j] =
    (speeds[j+1] - speeds[j]) / (h_j+1 - h_j), so that the loop over the nodes vectorises
    (a search for the interval of each node does not; equal to it to round-off). A single
    height (uniform current) is a fill. A turning profile runs it twice, on the x and on
    the z components of the velocity at the heights (see :func:`run`)."""
    n = y.shape[0]
    s0 = speeds[0]
    for i in range(n):
        U[i] = s0
    for j in range(heights.shape[0] - 1):
        h0 = heights[j]
        h1 = heights[j + 1]
        g = slopes[j]
        for i in range(np.uint64(n)):           # unsigned: see _NOWRAP
            U[i] += g * (min(max(y[i], h0), h1) - h0)


@njit(**_JIT)
def element_pass_2d(x, y, dx_, dy_, l0, kax, kb, f0, f1, a0, b0):
    """Planar version of :func:`element_pass`: rows x, y, dx_, dy_ (n,); forces f0, f1
    (ne,); a0, b0 (ne,) moments about +z on nodes a and b [N m]."""
    ne = l0.shape[0]
    for e in range(ne):
        dx = x[e + 1] - x[e]
        dy = y[e + 1] - y[e]
        l = math.sqrt(dx * dx + dy * dy)
        il = 1.0 / l
        ex = dx * il
        ey = dy * il
        N = kax[e] * (l - l0[e])
        ax = dx_[e]
        ay = dy_[e]
        bx = dx_[e + 1]
        by = dy_[e + 1]
        pa = ex * ay - ey * ax           # phi_a (z component)
        pb = ex * by - ey * bx
        k = kb[e]
        ma = k * (4.0 * pa + 2.0 * pb)
        mb = k * (2.0 * pa + 4.0 * pb)
        gx = ay * ma + by * mb           # G = d x (M z)
        gy = -ax * ma - bx * mb
        eg = ex * gx + ey * gy
        f0[e] = (gx - eg * ex) * il + N * ex
        f1[e] = (gy - eg * ey) * il + N * ey
        a0[e] = -(ex * ax + ey * ay) * ma
        b0[e] = -(ex * bx + ey * by) * mb


# ============================================================================ axial dashpot
# A dashpot per element on the elongation rate, N_d = eta (e . (v_b - v_a)): in the statics
# stiffness-proportional damping of the axial modes (eta = beta EA/l0, see
# :mod:`vfife.statics.equilibrium`), in the dynamics the line types' internal axial
# damping (Kelvin-Voigt, N_d = BA d(eps)/dt: eta = BA / l0, :mod:`vfife.dynamics.run`).
# A separate pass (as the drag) so that the elastic element pass and the dynamics
# without it are untouched; the node pass adds its forces after measuring the
# out-of-balance force, so the residual is the elastic + external force only and the
# dashpot, which vanishes at rest, cannot change the equilibrium.
@njit(**_JIT)
def dashpot_pass(x, y, z, vx, vy, vz, eta, q0, q1, q2):
    """Axial dashpot forces (3D): q (ne,) rows = force of element e on its node a [N]
    (node b receives -q); eta (ne,) [N s/m]; velocities lagged half a step (explicit)."""
    ne = eta.shape[0]
    for e in range(ne):
        dx = x[e + 1] - x[e]
        dy = y[e + 1] - y[e]
        dz = z[e + 1] - z[e]
        il = 1.0 / math.sqrt(dx * dx + dy * dy + dz * dz)
        ex = dx * il
        ey = dy * il
        ez = dz * il
        nd = eta[e] * (ex * (vx[e + 1] - vx[e]) + ey * (vy[e + 1] - vy[e])
                       + ez * (vz[e + 1] - vz[e]))
        q0[e] = nd * ex
        q1[e] = nd * ey
        q2[e] = nd * ez


@njit(**_JIT)
def dashpot_pass_2d(x, y, vx, vy, eta, q0, q1):
    """Planar version of :func:`dashpot_pass`."""
    ne = eta.shape[0]
    for e in range(ne):
        dx = x[e + 1] - x[e]
        dy = y[e + 1] - y[e]
        il = 1.0 / math.sqrt(dx * dx + dy * dy)
        ex = dx * il
        ey = dy * il
        nd = eta[e] * (ex * (vx[e + 1] - vx[e]) + ey * (vy[e + 1] - vy[e]))
        q0[e] = nd * ex
        q1[e] = nd * ey


# ============================================================================ internal flow
# Contents flowing at speed U along the pipe (see riser/physics/internal_flow.py and
# vfife/flow.py for the formulation): the contents mass per length mu_i at the nodes (a
# travelling slug: mu_0 (1 + eta cos(k s - omega t + psi)) = mu_0 (1 + eta (C cos(omega t)
# + S sin(omega t))) with C, S = cos, sin(k s + psi) precomputed, so no trigonometry per
# node), and the nodal forces it adds to the fixed-ends model whose element force is the
# effective tension T_e (Fylling: it already holds the uniform part of the centrifugal
# force mu U^2 kappa): the axial force of the density gradient U^2 (d mu / ds) tau and
# the Coriolis force -2 mu U d tau / dt, discretised as
#     f_i = 0.5 U^2 (mu_i+1 - mu_i-1) t_i - P_i mu_i U (v_i+1 - v_i-1)
# (central differences over the tributary length; t_i the unit chord from node i-1 to
# i+1, P_i the projection normal to the director; for a uniform mu the Coriolis form is
# skew-symmetric in the velocities, so it does no work, as the continuum's does not). A
# separate pass (as the drag) reads the velocities before the node pass updates them.
@njit(inline="always", **_JIT)
def _slug_update(t, fpar, fnodes, trib, madd, mass, im, imd, iair, wair, wload):
    """The slug's contents mu_i [kg/m] at time t [s] into fnodes[4], and the nodal masses
    (mass, im = 1/(m + ma), imd = 1/m - im, iair = 1/m) and weights in water (wload) and
    in air (wair) that follow from it; nothing for a steady flow (eta = 0: mu = mu_0)."""
    eta = fpar[2]
    if eta == 0.0:
        return
    n = trib.shape[0]
    mu0 = fpar[1]
    ct = math.cos(fpar[3] * t)
    st = math.sin(fpar[3] * t)
    g = fpar[4]
    C = fnodes[0]
    S = fnodes[1]
    mp = fnodes[2]
    w0 = fnodes[3]
    mu = fnodes[4]
    for i in range(n):
        mu[i] = mu0 * (1.0 + eta * (C[i] * ct + S[i] * st))
    for i in range(n):
        m = mp[i] + mu[i] * trib[i]
        mass[i] = m
        im[i] = 1.0 / (m + madd[i])
        imd[i] = 1.0 / m - im[i]
        iair[i] = 1.0 / m
        wair[i] = g * m
        wload[i] = w0[i] + (mu[i] - mu0) * trib[i] * g


@njit(**_JIT)
def flow_pass(t, fpar, fnodes, trib, madd, mass, im, imd, iair, wair, wload,
              x, y, z, vx, vy, vz, dx, dy, dz, q0, q1, q2, p0, p1, p2):
    """Internal-flow pass (3D) at time t [s] (dynamics).

    fpar : (U [m/s], mu_0 [kg/m], eta [-], omega [rad/s], g [m/s2]).
    fnodes : (5, n) rows C, S (cos and sin of k s + psi), the nodes' pipe mass [kg] (no
        contents), their weight with the mean contents [N] and mu_i [kg/m] (mu_0 for a
        steady flow); the masses and weights follow the slug (:func:`_slug_update`).
    q0..q2 (n,) out: the flow force on each node [N] (ends: 0): the density gradient's
    along the chord tangent of the neighbours, and the Coriolis force normal to the
    director (the continuum's tau . tau_t = 0; its axial part coupled the axial modes,
    which run at the stability limit, and blew up).
    p0..p2 (n,) in/out: the Coriolis force of the previous step [N]. The Coriolis force
    from the lagged velocities v^(n-1/2) alone is a forward-Euler rotation, which grows
    a mode by (1 + theta^2)^(1/2) per step (theta = 2 mu U dt / ((m + mu + m_a) l): a taut
    pipe at 20 m/s blew up within 130 s); it is extrapolated to the step's time t_n as
    1.5 f(v^(n-1/2)) - 0.5 f(v^(n-3/2)) (Adams-Bashforth 2, second order, growth ~
    theta^4 / 4 per step).
    """
    _slug_update(t, fpar, fnodes, trib, madd, mass, im, imd, iair, wair, wload)
    n = trib.shape[0]
    U = fpar[0]
    mu = fnodes[4]
    h = 0.5 * U * U
    q0[0] = q1[0] = q2[0] = 0.0
    q0[n - 1] = q1[n - 1] = q2[n - 1] = 0.0
    one = np.uint64(1)
    for i in range(one, np.uint64(n - 1)):      # unsigned: see _NOWRAP
        gr = h * (mu[i + one] - mu[i - one])
        c = U * mu[i]
        cx = -c * (vx[i + one] - vx[i - one])
        cy = -c * (vy[i + one] - vy[i - one])
        cz = -c * (vz[i + one] - vz[i - one])
        ca = cx * dx[i] + cy * dy[i] + cz * dz[i]
        cx -= ca * dx[i]
        cy -= ca * dy[i]
        cz -= ca * dz[i]
        tx = x[i + one] - x[i - one]
        ty = y[i + one] - y[i - one]
        tz = z[i + one] - z[i - one]
        gr /= math.sqrt(tx * tx + ty * ty + tz * tz)
        q0[i] = gr * tx + 1.5 * cx - 0.5 * p0[i]
        q1[i] = gr * ty + 1.5 * cy - 0.5 * p1[i]
        q2[i] = gr * tz + 1.5 * cz - 0.5 * p2[i]
        p0[i] = cx
        p1[i] = cy
        p2[i] = cz


@njit(**_JIT)
def flow_pass_2d(t, fpar, fnodes, trib, madd, mass, im, imd, iair, wair, wload,
                 x, y, vx, vy, dx, dy, q0, q1, p0, p1):
    """Planar version of :func:`flow_pass`."""
    _slug_update(t, fpar, fnodes, trib, madd, mass, im, imd, iair, wair, wload)
    n = trib.shape[0]
    U = fpar[0]
    mu = fnodes[4]
    h = 0.5 * U * U
    q0[0] = q1[0] = 0.0
    q0[n - 1] = q1[n - 1] = 0.0
    one = np.uint64(1)
    for i in range(one, np.uint64(n - 1)):      # unsigned: see _NOWRAP
        gr = h * (mu[i + one] - mu[i - one])
        c = U * mu[i]
        cx = -c * (vx[i + one] - vx[i - one])
        cy = -c * (vy[i + one] - vy[i - one])
        ca = cx * dx[i] + cy * dy[i]
        cx -= ca * dx[i]
        cy -= ca * dy[i]
        tx = x[i + one] - x[i - one]
        ty = y[i + one] - y[i - one]
        gr /= math.sqrt(tx * tx + ty * ty)
        q0[i] = gr * tx + 1.5 * cx - 0.5 * p0[i]
        q1[i] = gr * ty + 1.5 * cy - 0.5 * p1[i]
        p0[i] = cx
        p1[i] = cy


# ============================================================================ node pass
# Pass 2 in one loop over the nodes: gather the element forces and moments, add weight,
# seabed contact and the current drag, and update translation and rotation (the nodal
# resultants are never stored). Each node reads only its own old velocity and director,
# so the order of the updates within the loop does not matter and the scheme is identical
# to separate passes. The loop vectorises (AVX-512 on the bench machine) because it holds
# no max-reduction (LLVM does not vectorise a floating-point max without 'nnan', which
# the NaN checks forbid): the squared nodal force and moment go to scratch rows R, RM and
# are reduced by :func:`_max_reduce` only when ``stats`` is set (every step in statics,
# every 256th and the last step of a call in dynamics). The kinetic energy (a sum,
# vectorised) is summed every step and carries the NaN check of every step. Together with
# the unsigned indices (_NOWRAP) and the runtime-check limits above: 3D + drag
# 16.9 -> 6.6 ns, planar 5.7 -> 3.2 ns per element-step (bench, this machine).
@njit(**_JIT)
def _max_reduce(a, i0, i1):
    """max(a[i0:i1]) of non-negative values (0 for an empty range; a NaN is returned
    as NaN), in 8 independent lanes (the single running max is latency-bound)."""
    acc = np.zeros(8)
    nan = False
    nb = (i1 - i0) // 8
    for b in range(nb):
        for j in range(8):
            v = a[i0 + 8 * b + j]
            nan = nan or v != v
            acc[j] = v if v > acc[j] else acc[j]
    m = 0.0
    for j in range(8):
        m = acc[j] if acc[j] > m else m
    for i in range(i0 + 8 * nb, i1):
        v = a[i]
        nan = nan or v != v
        m = v if v > m else m
    return math.nan if nan else m


@njit(inline="always", **_JIT)
def _rotate_3d(i, dx, dy, dz, wx, wy, wz, px, py, pz, jinv, jrot, dt, c1, c2):
    """Rotation update of node i under the moment (px, py, pz); returns (|m_perp|^2,
    2 x rotational KE). The moment along the director is dropped (no torsion). A clamped
    node has jinv = 0: its rotation rate stays zero and its director fixed (its moment,
    the clamp's reaction, is returned as zero: not an out-of-balance moment)."""
    ax = dx[i]
    ay = dy[i]
    az = dz[i]
    md = px * ax + py * ay + pz * az
    px -= md * ax
    py -= md * ay
    pz -= md * az
    ji = jinv[i]
    qx = (c1 * wx[i] + dt * ji * px) * c2
    qy = (c1 * wy[i] + dt * ji * py) * c2
    qz = (c1 * wz[i] + dt * ji * pz) * c2
    nx = ax + dt * (qy * az - qz * ay)
    ny = ay + dt * (qz * ax - qx * az)
    nz = az + dt * (qx * ay - qy * ax)
    inv = 1.5 - 0.5 * (nx * nx + ny * ny + nz * nz)   # Newton step to |d| = 1
    nx *= inv
    ny *= inv
    nz *= inv
    wd = qx * nx + qy * ny + qz * nz
    wx[i] = qx - wd * nx
    wy[i] = qy - wd * ny
    wz[i] = qz - wd * nz
    dx[i] = nx
    dy[i] = ny
    dz[i] = nz
    m2 = px * px + py * py + pz * pz
    return (m2 if ji > 0.0 else 0.0), (qx * qx + qy * qy + qz * qz) * jrot[i]


@njit(**_JIT)
def node_pass(x, y, z, vx, vy, vz, dx, dy, dz, wx, wy, wz, f0, f1, f2, a0, a1, a2,
              b0, b1, b2, wload, mass, im, imd, jinv, jrot, kst, cseabed, mu, vfric,
              U, Uz, cdn, cdt, cdir, use_drag, qd0, qd1, qd2, use_dashpot, wair, iair, madd,
              trib, dnode, ysurf, use_surface, ql0, ql1, ql2, use_flow, pl0, pl1, pl2,
              use_dead, dt, c, stats, R, RM):
    """Fused node pass (3D): nodal force = f[i] - f[i-1] - weight (+ seabed, + drag,
    + dead load), moment = a[i] + b[i-1]; central-difference update of the translations
    of nodes 1..n-2 (added mass normal to the director: im = 1/(m + ma), imd = 1/m - im)
    and of the rotations of every node. All arrays are (n,) or (ne,) rows.
    kst (n,): seabed stiffness x tributary length [N/m] (zeros without a seabed);
    cseabed (n,): contact damping [N s/m]; mu, vfric: friction coefficient and
    regularisation speed [m/s].
    Drag (when use_drag): Morison on the velocity relative to the current, U (n,) the
    current speed at the nodes [m/s] (:func:`current_pass`) along the unit heading cdir
    (3,), plus Uz (n,) [m/s] along +z: u = U cdir + Uz e_z - v. One heading: U the signed
    speed along it, Uz = 0 (adding 0.0 changes no bit); a turning profile: U the x
    components (cdir = e_x) and Uz the z components of the current at the nodes, each
    interpolated linearly in height. Normal part u_n = u - (u.d) d, tangential u_t = u.d;
    f = cdn |u_n| u_n + cdt |u_t| u_t d with cdn, cdt (n,) = 0.5 rho D C_D x tributary
    length [kg/m] (cdt uses the perimeter, pi D).
    qd0..qd2 (ne,): axial dashpot forces of :func:`dashpot_pass` (read only when
    use_dashpot; added after the residual is measured).
    Sea surface (when use_surface): a node's line segment (its tributary length trib
    (n,) [m]) is immersed by the fraction q = clip((ysurf - y) / b + 1/2, 0, 1), with b =
    max(dnode, trib |d_y|) the vertical extent of that segment (dnode (n,) the outer
    diameter [m]): the exact fraction for a straight segment, continuous as a node
    crosses the surface (a node-wise on/off switch made the results depend on mesh and
    step). Weight wair + q (wload - wair) (wair (n,) the weight in air [N]), mass m + q
    m_a normal to the axis (madd (n,) [kg]; iair = 1/m), drag x q.
    ql0..ql2 (n,): internal-flow forces of :func:`flow_pass` (read only when use_flow).
    pl0..pl2 (n,): a dead load of fixed direction [N] per node, added to the weight
    (read only when use_dead; see :class:`vfife.model.Model`).
    Returns (max squared free-node force [N2], max squared moment [N2 m2], 2 x KE [J]);
    the two maxima are 0 unless ``stats``."""
    n = x.shape[0]
    c1 = 1.0 - 0.5 * c * dt
    c2 = 1.0 / (1.0 + 0.5 * c * dt)
    rmax = 0.0
    mmax = 0.0
    ke = 0.0
    m2, kr = _rotate_3d(0, dx, dy, dz, wx, wy, wz, a0[0], a1[0], a2[0], jinv, jrot, dt, c1, c2)
    mmax = m2 if m2 > mmax else mmax
    ke += kr
    m2, kr = _rotate_3d(n - 1, dx, dy, dz, wx, wy, wz, b0[n - 2], b1[n - 2], b2[n - 2],
                        jinv, jrot, dt, c1, c2)
    mmax = m2 if m2 > mmax else mmax
    ke += kr
    cx = cdir[0]
    cy = cdir[1]
    cz = cdir[2]
    one = np.uint64(1)
    for i in range(one, np.uint64(n - 1)):      # unsigned: see _NOWRAP
        wi = wload[i]
        imi = im[i]
        imdi = imd[i]
        wet = 1.0
        if use_surface:                   # immersed fraction of the node's segment
            band = max(dnode[i], trib[i] * abs(dy[i]))
            wet = min(max((ysurf[i] - y[i]) / band + 0.5, 0.0), 1.0)
            wi = wair[i] + wet * (wi - wair[i])
            imi = 1.0 / (mass[i] + wet * madd[i])
            imdi = iair[i] - imi
        gx = f0[i] - f0[i - one]
        gy = f1[i] - f1[i - one] - wi
        gz = f2[i] - f2[i - one]
        ux = vx[i]
        uy = vy[i]
        uz = vz[i]
        ex = dx[i]
        ey = dy[i]
        ez = dz[i]
        # seabed (branch-free: kst = 0 without one; keeps the loop vectorisable)
        pen = min(y[i], 0.0)
        fn = -kst[i] * pen
        gy += fn - (cseabed[i] * uy if pen < 0.0 else 0.0)
        if mu > 0.0:
            fr = mu * fn / math.sqrt(ux * ux + uz * uz + vfric * vfric)
            gx -= fr * ux
            gz -= fr * uz
        if use_drag:
            cu = U[i]
            rx = cu * cx - ux
            ry = cu * cy - uy
            rz = cu * cz + Uz[i] - uz
            rt = rx * ex + ry * ey + rz * ez
            rnx = rx - rt * ex
            rny = ry - rt * ey
            rnz = rz - rt * ez
            cn = wet * cdn[i] * math.sqrt(rnx * rnx + rny * rny + rnz * rnz)
            ft = wet * cdt[i] * abs(rt) * rt
            gx += cn * rnx + ft * ex
            gy += cn * rny + ft * ey
            gz += cn * rnz + ft * ez
        if use_flow:
            gx += ql0[i]
            gy += ql1[i]
            gz += ql2[i]
        if use_dead:
            gx += pl0[i]
            gy += pl1[i]
            gz += pl2[i]
        R[i] = gx * gx + gy * gy + gz * gz
        if use_dashpot:                   # after the residual: not an out-of-balance force
            gx += qd0[i] - qd0[i - one]
            gy += qd1[i] - qd1[i - one]
            gz += qd2[i] - qd2[i - one]
        fd = (gx * ex + gy * ey + gz * ez) * imdi
        ux = (c1 * ux + dt * (gx * imi + fd * ex)) * c2
        uy = (c1 * uy + dt * (gy * imi + fd * ey)) * c2
        uz = (c1 * uz + dt * (gz * imi + fd * ez)) * c2
        vx[i] = ux
        vy[i] = uy
        vz[i] = uz
        x[i] += dt * ux
        y[i] += dt * uy
        z[i] += dt * uz
        ke += mass[i] * (ux * ux + uy * uy + uz * uz)
        m2, kr = _rotate_3d(i, dx, dy, dz, wx, wy, wz, a0[i] + b0[i - one], a1[i] + b1[i - one],
                            a2[i] + b2[i - one], jinv, jrot, dt, c1, c2)
        RM[i] = m2
        ke += kr
    if stats:
        rmax = _max_reduce(R, 1, n - 1)
        mm = _max_reduce(RM, 1, n - 1)
        mmax = mm if not mm <= mmax else mmax      # keeps a NaN
    return rmax, mmax, ke


@njit(**_JIT)
def node_pass_2d(x, y, vx, vy, dx, dy, w, f0, f1, a0, b0, wload, mass, im, imd, jinv, jrot,
                 kst, cseabed, mu, vfric, U, cdn, cdt, cdir, use_drag, qd0, qd1,
                 use_dashpot, wair, iair, madd, trib, dnode, ysurf, use_surface, ql0, ql1,
                 use_flow, pl0, pl1, use_dead, dt, c, stats, R, RM, ends, cdp, use_points):
    """Planar version of :func:`node_pass` (w (n,) rotation rate about z, a0, b0 (ne,)
    moments about z, cdir (2,) in plane, qd0, qd1 (ne,) dashpot forces, ql0, ql1 (n,)
    flow forces, pl0, pl1 (n,) dead load [N]). ``ends`` (:data:`END_SLOTS`,) the end
    conditions: see :func:`_end_translation`; a rotational spring of stiffness
    ends[2 j] [N m/rad] about the neutral direction ends[2 j + 1] [rad] at end j (0 the
    anchor, 1 the hang-off) adds the moment -k (phi - phi_0) to the end node. cdp (n,):
    the point attachments' drag 0.5 rho C_D A [kg/m], isotropic on the relative velocity
    (f = cdp |u| u, MoorDyn's point), with the line's drag when use_drag and use_points
    (a separate, loop-invariant branch: a line without attachments runs the same
    arithmetic, bit for bit, as before they existed)."""
    n = x.shape[0]
    c1 = 1.0 - 0.5 * c * dt
    c2 = 1.0 / (1.0 + 0.5 * c * dt)
    rmax = 0.0
    mmax = 0.0
    ke = 0.0
    for j in range(2):                      # end nodes: rotation (translation below)
        i = 0 if j == 0 else n - 1
        mi = a0[0] if j == 0 else b0[n - 2]
        kj = ends[2 * j]
        if kj > 0.0:                        # a flex joint: -k times the end's rotation
            c0 = math.cos(ends[2 * j + 1])
            s0 = math.sin(ends[2 * j + 1])
            mi -= kj * math.atan2(c0 * dy[i] - s0 * dx[i], c0 * dx[i] + s0 * dy[i])
        q = (c1 * w[i] + dt * jinv[i] * mi) * c2
        w[i] = q
        ax = dx[i]
        ay = dy[i]
        nx = ax - dt * q * ay
        ny = ay + dt * q * ax
        inv = 1.5 - 0.5 * (nx * nx + ny * ny)
        dx[i] = nx * inv
        dy[i] = ny * inv
        if jinv[i] > 0.0:                   # a clamp's reaction is not out of balance
            mmax = mi * mi if mi * mi > mmax else mmax
        ke += q * q * jrot[i]
    cx = cdir[0]
    cy = cdir[1]
    one = np.uint64(1)
    for i in range(one, np.uint64(n - 1)):      # unsigned: see _NOWRAP
        wi = wload[i]
        imi = im[i]
        imdi = imd[i]
        wet = 1.0
        if use_surface:                       # see node_pass
            band = max(dnode[i], trib[i] * abs(dy[i]))
            wet = min(max((ysurf[i] - y[i]) / band + 0.5, 0.0), 1.0)
            wi = wair[i] + wet * (wi - wair[i])
            imi = 1.0 / (mass[i] + wet * madd[i])
            imdi = iair[i] - imi
        gx = f0[i] - f0[i - one]
        gy = f1[i] - f1[i - one] - wi
        ux = vx[i]
        uy = vy[i]
        ex = dx[i]
        ey = dy[i]
        pen = min(y[i], 0.0)                  # seabed, branch-free (see node_pass)
        fn = -kst[i] * pen
        gy += fn - (cseabed[i] * uy if pen < 0.0 else 0.0)
        if mu > 0.0:
            gx -= mu * fn * ux / math.sqrt(ux * ux + vfric * vfric)
        if use_drag:                          # see node_pass
            cu = U[i]
            rx = cu * cx - ux
            ry = cu * cy - uy
            rt = rx * ex + ry * ey
            rnx = rx - rt * ex
            rny = ry - rt * ey
            cn = wet * cdn[i] * math.sqrt(rnx * rnx + rny * rny)
            ft = wet * cdt[i] * abs(rt) * rt
            gx += cn * rnx + ft * ex
            gy += cn * rny + ft * ey
            if use_points:
                cq = wet * cdp[i] * math.sqrt(rx * rx + ry * ry)
                gx += cq * rx
                gy += cq * ry
        if use_flow:
            gx += ql0[i]
            gy += ql1[i]
        if use_dead:
            gx += pl0[i]
            gy += pl1[i]
        R[i] = gx * gx + gy * gy
        if use_dashpot:                   # after the residual: not an out-of-balance force
            gx += qd0[i] - qd0[i - one]
            gy += qd1[i] - qd1[i - one]
        fd = (gx * ex + gy * ey) * imdi
        ux = (c1 * ux + dt * (gx * imi + fd * ex)) * c2
        uy = (c1 * uy + dt * (gy * imi + fd * ey)) * c2
        vx[i] = ux
        vy[i] = uy
        x[i] += dt * ux
        y[i] += dt * uy
        ke += mass[i] * (ux * ux + uy * uy)
        mi = a0[i] + b0[i - one]
        q = (c1 * w[i] + dt * jinv[i] * mi) * c2
        w[i] = q
        nx = ex - dt * q * ey
        ny = ey + dt * q * ex
        inv = 1.5 - 0.5 * (nx * nx + ny * ny)   # Newton step to |d| = 1 (|dt w| << 1)
        dx[i] = nx * inv
        dy[i] = ny * inv
        RM[i] = mi * mi
        ke += q * q * jrot[i]
    if ends[4] > 0.0:                       # a free anchor end
        ke += _end_translation(0, 1.0, f0[0], f1[0], x, y, vx, vy, wload, mass, im, pl0, pl1,
                               use_dead, 0.0, dt, c1, c2, R)
    if ends[5] > 0.0:                       # a tensioner: the top's height is free
        pull = ends[6] - ends[7] * (y[n - 1] - ends[9])
        ke += _end_translation(n - 1, 0.0, -f0[n - 2], -f1[n - 2], x, y, vx, vy, wload, mass,
                               im, pl0, pl1, use_dead, pull, dt, c1, c2, R)
    if stats:
        rmax = _max_reduce(R, 1, n - 1)
        if ends[4] > 0.0:
            rmax = R[0] if not R[0] <= rmax else rmax
        if ends[5] > 0.0:
            rmax = R[n - 1] if not R[n - 1] <= rmax else rmax
        mm = _max_reduce(RM, 1, n - 1)
        mmax = mm if not mm <= mmax else mmax      # keeps a NaN
    return rmax, mmax, ke


#: the slots of the planar kernels' ``ends`` array: the anchor's and the hang-off's
#: rotational spring (k [N m/rad], neutral direction [rad]), a free anchor (1/0), a
#: tensioner (1/0, top_tension [N], stiffness [N/m], the hang-off height [m], and the
#: reference height [m] that :func:`run` sets every step: the hang-off height moved by the
#: prescribed vertical displacement)
END_SLOTS = 10


@njit(inline="always", **_JIT)
def _end_translation(i, fx_on, gx, gy, x, y, vx, vy, wload, mass, im, pl0, pl1, use_dead,
                     pull, dt, c1, c2, R):
    """Central-difference step of end node ``i``'s translation: its element's force (gx,
    gy) [N], its weight, its dead load (point attachments) and ``pull`` [N] upwards (a
    tensioner); x moves only where ``fx_on`` (a free end; a tensioned top keeps the x its
    motion prescribes). The end node's half element carries no drag, seabed or flow load
    (an O(h) defect of the free end, shrinking with the element length). Returns its
    2 x kinetic energy; R[i] gets its squared out-of-balance force."""
    gy += pull - wload[i]
    if use_dead:
        gx += pl0[i]
        gy += pl1[i]
    gx *= fx_on
    R[i] = gx * gx + gy * gy
    ux = (c1 * vx[i] + dt * gx * im[i]) * c2
    uy = (c1 * vy[i] + dt * gy * im[i]) * c2
    vx[i] = ux
    vy[i] = uy
    x[i] += dt * ux
    y[i] += dt * uy
    return mass[i] * (ux * ux + uy * uy)


# ============================================================================ waves
@njit(**_JIT)
def wave_pass(x, y, z, t, amp, omega, k, phase, cosb, sinb, x0, z0, depth, wheeler, out):
    """Airy wave kinematics at the nodes (x, y, z) [m] at time t [s], summed over the
    components (amp [m], omega [rad/s], k [1/m], phase [rad], heading cosb, sinb; origin
    x0, z0 [m]; mean surface at y = depth [m]; see :mod:`riser.physics.waves` for the
    convention eta = a cos(omega t - k (dx cos b + dz sin b) - eps)), without the ramp.

    out (21, n): rows 0-6 the values of (u_x, u_y, u_z [m/s], a_x, a_y, a_z [m/s2], eta
    [m]), rows 7-13 their first and rows 14-20 their second time derivatives at the fixed
    point (the Taylor coefficients :func:`wave_taylor` steps with). Per component, with
    theta the phase above: eta = a cos theta, horizontal velocity a omega C cos theta
    along the heading, vertical -a omega S sin theta (= d eta / dt at the surface),
    acceleration their time derivative;
    C = cosh(k y')/sinh(k h), S = sinh(k y')/sinh(k h), written as exponentials that do
    not overflow in deep water. y' is the stretched height: Wheeler (``wheeler``) y' = h
    y / (h + eta) below the surface (eta the sum's elevation, computed first), else
    min(y, h) (vertical stretching); above the surface y' = h (the node is dry there). A
    component decayed to e^{k (y' - h)} < 1e-13 at a node is skipped there (its share is
    below round-off of its value at the surface; deep nodes skip the short waves)."""
    n = x.shape[0]
    m = amp.shape[0]
    for r in range(21):
        for i in range(n):
            out[r, i] = 0.0
    for i in range(n):                  # the elevation first (Wheeler needs it)
        e = 0.0
        for j in range(m):
            th = omega[j] * t - k[j] * ((x[i] - x0) * cosb[j] + (z[i] - z0) * sinb[j]) - phase[j]
            e += amp[j] * math.cos(th)
        out[6, i] = e
    for i in range(n):
        eta = out[6, i]
        if wheeler:
            top = depth + eta
            yp = depth * min(y[i], top) / top if top > 0.0 else 0.0
        else:
            yp = min(y[i], depth)
        yp = max(yp, 0.0)
        for j in range(m):
            w = omega[j]
            kk = k[j]
            ep = math.exp(kk * (yp - depth))
            if ep < 1e-13:             # decayed below round-off of the surface's value
                continue
            em = math.exp(-kk * (yp + depth))
            d = 1.0 - math.exp(-2.0 * kk * depth)
            th = w * t - kk * ((x[i] - x0) * cosb[j] + (z[i] - z0) * sinb[j]) - phase[j]
            ct = math.cos(th)
            st = math.sin(th)
            cc = (ep + em) / d
            ss = (ep - em) / d
            a = amp[j]
            uh = a * w * cc            # horizontal velocity amplitude
            uv = -a * w * ss           # vertical: u_y = d eta / dt at the surface
            w2 = w * w
            # values, then d/dt (cos -> -w sin, sin -> w cos), then d2/dt2 = -w^2 value
            vals = (uh * ct, uv * st, -uh * w * st, uv * w * ct, a * ct)
            rates = (-uh * w * st, uv * w * ct, -uh * w2 * ct, -uv * w2 * st, -a * w * st)
            for q in range(5):
                v0 = vals[q]
                v1 = rates[q]
                row = (0, 1, 3, 4, 6)[q]
                if q == 4:
                    out[7 + row, i] += v1
                    out[14 + row, i] -= w2 * v0
                    continue
                if q == 0 or q == 2:      # horizontal: along the heading
                    out[row, i] += v0 * cosb[j]
                    out[row + 2, i] += v0 * sinb[j]
                    out[7 + row, i] += v1 * cosb[j]
                    out[7 + row + 2, i] += v1 * sinb[j]
                    out[14 + row, i] -= w2 * v0 * cosb[j]
                    out[14 + row + 2, i] -= w2 * v0 * sinb[j]
                else:
                    out[row, i] += v0
                    out[7 + row, i] += v1
                    out[14 + row, i] -= w2 * v0


@njit(**_JIT)
def wave_taylor(WT, tau, WV):
    """The wave kinematics WV (7, n) at tau [s] after the Taylor point: value + tau rate +
    tau^2 / 2 second derivative (WT (21, n), see :func:`wave_pass`; rows 0-5 of WV the
    velocity and acceleration, row 6 the surface height: WT's row 6 holds depth + eta)."""
    h2 = 0.5 * tau * tau
    n = WV.shape[1]
    for r in range(7):
        for i in range(np.uint64(n)):       # unsigned: see _NOWRAP
            WV[r, i] = WT[r, i] + tau * WT[7 + r, i] + h2 * WT[14 + r, i]


@njit(**_JIT)
def wave_load_pass(x, y, z, vx, vy, vz, dx, dy, dz, U, Uz, cdir, cdn, cdt, cin, trib,
                   dnode, WV, P, PW):
    """The Morison loads of a line in waves, per node, into PW (3, n) [N] = P (the dead
    load, zeros without one) + drag + fluid inertia; :func:`node_pass` adds PW as its dead
    load (its own drag off), so that a run without waves runs the node passes it ran
    before. Drag on the velocity relative to the water, u = U cdir + Uz e_z (the current,
    :func:`current_pass`; cdir (3,)) + the waves' particle velocity WV[0:3] - v, normal
    and tangential as :func:`node_pass` has it; fluid inertia cin[0] a_n + cin[1] a_t, a =
    WV[3:6] the fluid acceleration split along the director, cin (2, n) = ((1 + C_a), 1)
    rho pi D^2 / 4 x tributary length [kg] (the Froude-Krylov force of the whole
    acceleration and the added mass normal to the axis, :mod:`vfife.dynamics.waves`). Each times
    the node's immersed fraction under the instantaneous surface WV[6] (:func:`node_pass`'s
    rule)."""
    n = x.shape[0]
    cx = cdir[0]
    cy = cdir[1]
    cz = cdir[2]
    for i in range(np.uint64(n)):           # unsigned: see _NOWRAP
        ex = dx[i]
        ey = dy[i]
        ez = dz[i]
        band = max(dnode[i], trib[i] * abs(ey))
        wet = min(max((WV[6, i] - y[i]) / band + 0.5, 0.0), 1.0)
        cu = U[i]
        rx = cu * cx + WV[0, i] - vx[i]
        ry = cu * cy + WV[1, i] - vy[i]
        rz = cu * cz + Uz[i] + WV[2, i] - vz[i]
        rt = rx * ex + ry * ey + rz * ez
        rnx = rx - rt * ex
        rny = ry - rt * ey
        rnz = rz - rt * ez
        cn = wet * cdn[i] * math.sqrt(rnx * rnx + rny * rny + rnz * rnz)
        ft = wet * cdt[i] * abs(rt) * rt
        ax_ = WV[3, i]
        ay_ = WV[4, i]
        az_ = WV[5, i]
        at = ax_ * ex + ay_ * ey + az_ * ez
        ci = wet * cin[0, i]
        ct = wet * cin[1, i] * at - ci * at + ft
        PW[0, i] = P[0, i] + cn * rnx + ci * ax_ + ct * ex
        PW[1, i] = P[1, i] + cn * rny + ci * ay_ + ct * ey
        PW[2, i] = P[2, i] + cn * rnz + ci * az_ + ct * ez


# ============================================================================ driver
@njit(**_JIT)
def run(nsteps, planar, state, line, sea, effects, scratch, flow, ends, dt, c, tol_f, tol_m,
        vmax):
    """Advance up to ``nsteps`` explicit steps.

    The arrays come grouped (:data:`State`, :data:`Line`, :data:`Sea`, :data:`Effects`,
    :data:`Scratch`, :data:`Flow`, :data:`Ends`; named tuples, unpacked below at no cost):
    their fields by the names used here.

    ends.conditions : (:data:`END_SLOTS`,) the end conditions of the planar kernels (flex joints, a
        free anchor, a tensioner; see :func:`node_pass_2d`); a tensioned top follows the
        hang-off's motion in x and z, its reference height (slot 9) in y.
    cdp, use_points : (n,) the point attachments' isotropic drag [kg/m] (planar kernels),
        read only when use_points.
    jinv, jrot : (n,) inverse rotational inertia [1/(kg m2)] (0 at a clamped end) and the
        inertia [kg m2].
    kst : (n,) seabed stiffness x tributary length [N/m] (zeros without a seabed).
    R : (2, n) scratch for the squared nodal out-of-balance forces and moments.
    U : (n,) scratch for the current speed at the nodes [m/s]; heights [m], speeds
        [m/s], slopes [1/s] the current profile (see :func:`current_pass`); cdir its unit
        heading.
    Uz, speeds_z, slopes_z, turning : a current that turns with height (``turning``,
        3D kernels only): speeds, slopes the profile's x components and cdir = e_x,
        speeds_z, slopes_z its z components [m/s], [1/s] at the same heights, Uz (n,)
        scratch for the z component at the nodes (:func:`current_pass` on them, only when
        turning; otherwise Uz stays zero, see :func:`node_pass`).
    eta : (ne,) axial dashpot coefficients [N s/m] and Q (k, ne) scratch for their forces,
        used only when use_dashpot (the statics' dashpot, the dynamics' BA / l0; see
        :func:`dashpot_pass`).
    wair, iair, madd, trib, dnode : (n,) weight in air [N], inverse mass [1/kg], added
        mass [kg], tributary length and outer diameter [m] of the nodes, for the sea surface
        at the heights ysurf (n,) [m] of the nodes, used only when use_surface (dynamics;
        see :func:`node_pass`).
    use_flow, t0, fpar, fnodes, FL : internal flow (see :func:`flow_pass`), run only when
        use_flow (dynamics): t0 [s] the time at the start of this call, FL (6, n)
        the flow forces (rows 0-2) and the previous step's Coriolis forces (rows 3-5).
    P, use_dead : (3, n) a dead load of fixed direction per node [N] (global x, y, z),
        added to the weight when use_dead (rows x, y on the planar path).
    planar : use the planar kernels on rows 0-1 of X, V, D (z untouched) and W[2] as the
        rotation rate; F (2, ne), MA, MB (1, ne), cdir (2,) then.
    WT, WV, cin, PW, cdir3, use_waves : waves (:func:`wave_taylor`,
        :func:`wave_load_pass`): WT (21, n) the kinematics' quadratic Taylor coefficients
        about the time t0 of this call, WV (7, n) scratch for their values at each step
        (row 6 the surface, the node passes' ysurf then), cin (2, n) the inertia
        coefficients [kg], PW (3, n) scratch for the loads (the node passes' dead load
        then, their drag off), cdir3 (3,) the current's heading; run only when use_waves
        (dynamics).
    top0 (3,) hang-off position at zero displacement; top_disp (3, nsteps + 1) hang-off
    displacement [m] (x, y, z) at the end of each step (column 0: at the start). The
    anchor (node 0) keeps its position.
    Stops early when the force residual < tol_f and the moment residual < tol_m (negative
    tolerances: never), or on a blow-up (NaN, or a speed above vmax [m/s]).
    The residuals are measured every step when a tolerance is given (statics), else on
    every 256th and on the last step (the NaN check of the other steps is on the kinetic
    energy, which every step sums over all nodes).
    Returns (steps done, force residual [N], moment residual [N m], kinetic energy [J],
    status: 0 all steps done, 1 converged, 2 blow-up).
    """
    X, V, D, W = state.X, state.V, state.D, state.W
    l0, kax, kb, mass, im, imd = line.l0, line.kax, line.kb, line.mass, line.im, line.imd
    jinv, jrot, wload, kst, eta = line.jinv, line.jrot, line.wload, line.kst, line.eta
    wair, iair, madd, trib, dnode = line.wair, line.iair, line.madd, line.trib, line.dnode
    cin, cdn, cdt, cdp = line.cin, line.cdn, line.cdt, line.cdp
    heights, speeds, slopes, cdir = sea.heights, sea.speeds, sea.slopes, sea.cdir
    speeds_z, slopes_z, cdir3 = sea.speeds_z, sea.slopes_z, sea.cdir3
    cseabed, mu, vfric, ysurf, WT, P = sea.cseabed, sea.mu, sea.vfric, sea.ysurf, sea.WT, sea.P
    use_drag, turning, use_dashpot = effects.drag, effects.turning, effects.dashpot
    use_surface, use_flow, use_dead = effects.surface, effects.flow, effects.dead
    use_waves, use_points = effects.waves, effects.points
    F, MA, MB, U, Uz, R = scratch.F, scratch.MA, scratch.MB, scratch.U, scratch.Uz, scratch.R
    Q, FL, WV, PW = scratch.Q, scratch.FL, scratch.WV, scratch.PW
    t0, fpar, fnodes = flow.t0, flow.fpar, flow.fnodes
    conds, top0, top_disp = ends.conditions, ends.top0, ends.top_disp
    n = X.shape[1]
    res = 0.0
    mres = 0.0
    ke = 0.0
    Wz = W[2]
    check = tol_f >= 0.0 or tol_m >= 0.0
    # with waves the node passes take the wave pass's loads as their dead load (their own
    # drag off: the wave pass has it, on the current and the waves) and its surface
    node_drag = use_drag and not use_waves
    load = PW if use_waves else P
    use_load = use_dead or use_waves
    ys = WV[6] if use_waves else ysurf
    drag_profile = use_drag and heights.shape[0] > 1
    drag_z = use_drag and turning and not planar
    if use_drag and not drag_profile:       # uniform current: U never changes
        current_pass(X[1], heights, speeds, slopes, U)
        if drag_z:
            current_pass(X[1], heights, speeds_z, slopes_z, Uz)
    for k in range(nsteps):
        stats = check or (k & 255) == 0 or k == nsteps - 1
        if drag_profile:
            current_pass(X[1], heights, speeds, slopes, U)
            if drag_z:
                current_pass(X[1], heights, speeds_z, slopes_z, Uz)
        if use_waves:
            wave_taylor(WT, k * dt, WV)
            wave_load_pass(X[0], X[1], X[2], V[0], V[1], V[2], D[0], D[1], D[2], U, Uz,
                           cdir3, cdn, cdt, cin, trib, dnode, WV, P, PW)
        if use_flow:
            tk = t0 + k * dt
            if planar:
                flow_pass_2d(tk, fpar, fnodes, trib, madd, mass, im, imd, iair,
                             wair, wload, X[0], X[1], V[0], V[1], D[0], D[1], FL[0], FL[1],
                             FL[3], FL[4])
            else:
                flow_pass(tk, fpar, fnodes, trib, madd, mass, im, imd, iair,
                          wair, wload, X[0], X[1], X[2], V[0], V[1], V[2], D[0], D[1],
                          D[2], FL[0], FL[1], FL[2], FL[3], FL[4], FL[5])
        tensioned = conds[5] > 0.0
        if tensioned:
            conds[9] = conds[8] + top_disp[1, k]
        if planar:
            element_pass_2d(X[0], X[1], D[0], D[1], l0, kax, kb, F[0], F[1], MA[0], MB[0])
            if use_dashpot:
                dashpot_pass_2d(X[0], X[1], V[0], V[1], eta, Q[0], Q[1])
            r2, m2, k1 = node_pass_2d(X[0], X[1], V[0], V[1], D[0], D[1], Wz, F[0], F[1],
                                      MA[0], MB[0], wload, mass, im, imd, jinv, jrot, kst,
                                      cseabed, mu, vfric, U, cdn, cdt, cdir, node_drag,
                                      Q[0], Q[1], use_dashpot, wair, iair, madd, trib,
                                      dnode, ys, use_surface, FL[0], FL[1], use_flow,
                                      load[0], load[1], use_load, dt, c, stats, R[0], R[1],
                                      conds, cdp, use_points)
        else:
            element_pass(X[0], X[1], X[2], D[0], D[1], D[2], l0, kax, kb, F[0], F[1], F[2],
                         MA[0], MA[1], MA[2], MB[0], MB[1], MB[2])
            if use_dashpot:
                dashpot_pass(X[0], X[1], X[2], V[0], V[1], V[2], eta, Q[0], Q[1], Q[2])
            r2, m2, k1 = node_pass(X[0], X[1], X[2], V[0], V[1], V[2], D[0], D[1], D[2],
                                   W[0], W[1], W[2], F[0], F[1], F[2], MA[0], MA[1], MA[2],
                                   MB[0], MB[1], MB[2], wload, mass, im, imd, jinv, jrot,
                                   kst, cseabed, mu, vfric, U, Uz, cdn, cdt, cdir,
                                   node_drag, Q[0], Q[1], Q[2], use_dashpot, wair, iair,
                                   madd, trib, dnode, ys, use_surface, FL[0], FL[1],
                                   FL[2], use_flow, load[0], load[1], load[2], use_load, dt,
                                   c, stats, R[0], R[1])
        ke = 0.5 * k1
        for j in range(3):
            if j == 1 and tensioned:
                continue
            d1 = top_disp[j, k + 1]
            X[j, n - 1] = top0[j] + d1
            V[j, n - 1] = (d1 - top_disp[j, k]) / dt
        if not ke < 1e300:
            if stats:
                res = math.sqrt(r2)
                mres = math.sqrt(m2)
            return k + 1, res, mres, ke, 2
        if stats:
            res = math.sqrt(r2)
            mres = math.sqrt(m2)
            if not (res < 1e300 and mres < 1e300):
                return k + 1, res, mres, ke, 2
            if res < tol_f and mres < tol_m:
                return k + 1, res, mres, ke, 1
        if (k & 255) == 0:
            for i in range(n):
                vv = V[0, i] * V[0, i] + V[1, i] * V[1, i] + V[2, i] * V[2, i]
                if not (vv <= vmax * vmax):
                    return k + 1, res, mres, ke, 2
    return nsteps, res, mres, ke, 0


@njit(**_JIT)
def element_state(X, D, l0, kax, kb):
    """Element results for output (3D formulas, valid for planar states with z = 0):
    axial force N [N] (effective tension), end bending-moment vectors Ma, Mb (3, ne)
    [N m], shear magnitude Q [N], chord length l [m] (ne,) and the shear force vector S
    (3, ne) [N] (the transverse part of the end moments' force pair, |S| = Q; one sign
    convention along the line, so that nodes can interpolate it, see vfife/recovery.py).
    Written on scalars (no small arrays per element): 150x faster than with np.cross on
    3-vectors, the same values to rounding (issue 36)."""
    ne = l0.shape[0]
    N = np.empty(ne)
    Q = np.empty(ne)
    L = np.empty(ne)
    Ma = np.empty((3, ne))
    Mb = np.empty((3, ne))
    S = np.empty((3, ne))
    for e in range(ne):
        dx = X[0, e + 1] - X[0, e]
        dy = X[1, e + 1] - X[1, e]
        dz = X[2, e + 1] - X[2, e]
        l = math.sqrt(dx * dx + dy * dy + dz * dz)
        ex = dx / l
        ey = dy / l
        ez = dz / l
        ax = D[0, e]
        ay = D[1, e]
        az = D[2, e]
        bx = D[0, e + 1]
        by = D[1, e + 1]
        bz = D[2, e + 1]
        pax = ey * az - ez * ay                 # e x a
        pay = ez * ax - ex * az
        paz = ex * ay - ey * ax
        pbx = ey * bz - ez * by                 # e x b
        pby = ez * bx - ex * bz
        pbz = ex * by - ey * bx
        k = kb[e]
        max_ = k * (4.0 * pax + 2.0 * pbx)
        may = k * (4.0 * pay + 2.0 * pby)
        maz = k * (4.0 * paz + 2.0 * pbz)
        mbx = k * (2.0 * pax + 4.0 * pbx)
        mby = k * (2.0 * pay + 4.0 * pby)
        mbz = k * (2.0 * paz + 4.0 * pbz)
        gx = (ay * maz - az * may) + (by * mbz - bz * mby)     # a x ma + b x mb
        gy = (az * max_ - ax * maz) + (bz * mbx - bx * mbz)
        gz = (ax * may - ay * max_) + (bx * mby - by * mbx)
        ge = ex * gx + ey * gy + ez * gz
        tx = gx - ge * ex
        ty = gy - ge * ey
        tz = gz - ge * ez
        N[e] = kax[e] * (l - l0[e])
        Q[e] = math.sqrt(tx * tx + ty * ty + tz * tz) / l
        L[e] = l
        Ma[0, e] = max_
        Ma[1, e] = may
        Ma[2, e] = maz
        Mb[0, e] = mbx
        Mb[1, e] = mby
        Mb[2, e] = mbz
        S[0, e] = tx / l
        S[1, e] = ty / l
        S[2, e] = tz / l
    return N, Ma, Mb, Q, L, S

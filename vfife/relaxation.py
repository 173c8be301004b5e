"""Kinetic-damping relaxation driver and fictitious static inertia (statics only).

Kept apart from :mod:`vfife.kernels` (whose inner loops are tuned separately): the driver
below calls the same element, drag, dashpot and node passes as :func:`vfife.kernels.run`,
so the forces, the out-of-balance measure and the integration are identical; only the
damping differs.

Kinetic damping (Cundall 1976, Barnes 1977; Topping & Ivanyi): the relaxation runs
(almost) undamped and the total kinetic energy of the fictitious motion is watched every
step; when it falls, the motion has just passed a kinetic-energy peak, i.e. the
configuration is near a minimum of the potential energy along the path, and every
velocity (translational and rotational) is set to zero. No damping coefficient, and so no
estimate of the fundamental frequency, is needed; the velocities vanish at rest and the
equilibrium is unchanged. The reset removes the energy of the dominant (slowest, largest)
motion at each peak, which is what the viscous scheme damps only at ~omega_1^2 / c when
over-damped.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from . import kernels
from .mesh import Mesh

_JIT = dict(cache=True, error_model="numpy", nogil=True)


@njit(**_JIT)
def run_kinetic(nsteps, planar, X, V, D, W, F, MA, MB, Fn, l0, kax, kb, mass, im, imd, jinv,
                jrot, wload, trib, cdn, cdt, heights, speeds, cdir, use_drag, kseabed, cseabed,
                mu, vfric, use_seabed, eta, Q, use_dashpot, dt, c, tol_f, tol_m, vmax,
                ke_prev, peak_gap):
    """Up to ``nsteps`` explicit steps with kinetic damping (the hang-off stays put).

    Arguments as :func:`vfife.kernels.run` (``c`` [1/s]: optional light viscous damping on
    top, normally 0); ``ke_prev``: the kinetic energy [J] of the step before (carries the
    peak detection across calls; 0 after a reset); ``peak_gap``: steps since the last
    reset (carried across calls).
    Returns (steps done, force residual [N], moment residual [N m], kinetic energy [J],
    status 0 all steps done / 1 converged / 2 blow-up, resets, ke_prev, peak_gap,
    mean steps between resets over this call).
    """
    n = X.shape[1]
    res = 0.0
    mres = 0.0
    ke = 0.0
    Wz = W[2]
    resets = 0
    gap_sum = 0
    for k in range(nsteps):
        if planar:
            kernels.element_pass_2d(X[0], X[1], D[0], D[1], l0, kax, kb, F[0], F[1], MA[0],
                                    MB[0])
            if use_drag:
                kernels.drag_forces_2d(X, V, D, cdn, cdt, heights, speeds, cdir, Fn)
            if use_dashpot:
                kernels.dashpot_pass_2d(X[0], X[1], V[0], V[1], eta, Q[0], Q[1])
            r2, m2, k1 = kernels.node_pass_2d(X[0], X[1], V[0], V[1], D[0], D[1], Wz, F[0],
                                              F[1], MA[0], MB[0], wload, mass, im, imd, jinv,
                                              jrot, trib, kseabed, cseabed, mu, vfric,
                                              use_seabed, Fn[0], Fn[1], use_drag, Q[0], Q[1],
                                              use_dashpot, dt, c)
        else:
            kernels.element_pass(X[0], X[1], X[2], D[0], D[1], D[2], l0, kax, kb, F[0], F[1],
                                 F[2], MA[0], MA[1], MA[2], MB[0], MB[1], MB[2])
            if use_drag:
                kernels.drag_forces(X, V, D, cdn, cdt, heights, speeds, cdir, Fn)
            if use_dashpot:
                kernels.dashpot_pass(X[0], X[1], X[2], V[0], V[1], V[2], eta, Q[0], Q[1],
                                     Q[2])
            r2, m2, k1 = kernels.node_pass(X[0], X[1], X[2], V[0], V[1], V[2], D[0], D[1],
                                           D[2], W[0], W[1], W[2], F[0], F[1], F[2], MA[0],
                                           MA[1], MA[2], MB[0], MB[1], MB[2], wload, mass, im,
                                           imd, jinv, jrot, trib, kseabed, cseabed, mu, vfric,
                                           use_seabed, Fn[0], Fn[1], Fn[2], use_drag, Q[0],
                                           Q[1], Q[2], use_dashpot, dt, c)
        res = math.sqrt(r2)
        mres = math.sqrt(m2)
        ke = 0.5 * k1
        peak_gap += 1
        if not (res < 1e300 and mres < 1e300 and ke < 1e300):
            return k + 1, res, mres, ke, 2, resets, ke_prev, peak_gap, 0.0
        if res < tol_f and mres < tol_m:
            return (k + 1, res, mres, ke, 1, resets, ke_prev, peak_gap,
                    gap_sum / resets if resets > 0 else 0.0)
        if ke < ke_prev:
            # past a kinetic-energy peak: stop every motion there
            for j in range(3):
                for i in range(n):
                    V[j, i] = 0.0
                    W[j, i] = 0.0
            resets += 1
            gap_sum += peak_gap
            peak_gap = 0
            ke_prev = 0.0
        else:
            ke_prev = ke
        if (k & 255) == 0:
            for i in range(n):
                vv = V[0, i] * V[0, i] + V[1, i] * V[1, i] + V[2, i] * V[2, i]
                if not (vv <= vmax * vmax):
                    return k + 1, res, mres, ke, 2, resets, ke_prev, peak_gap, 0.0
    return (nsteps, res, mres, ke, 0, resets, ke_prev, peak_gap,
            gap_sum / resets if resets > 0 else 0.0)


def static_inertia(mesh: Mesh, *, rot_scale: float, tension, safety: float,
                   seabed_stiffness: float = 0.0, seabed_zeta: float = 0.0,
                   contact=None, axial_damping=0.0):
    """Fictitious nodal masses and rotational inertias for statics, and the time step.

    The step is ``safety`` x the axial critical step of the physical masses (with the axial
    dashpot, see :func:`vfife.timestep.critical_steps`). Every node then gets the larger
    of its physical inertia and the inertia that makes *its own* transverse (bending
    zig-zag 24 EI/l^3 + string 2 T/l per element, plus the seabed spring k_s x tributary
    length on the ``contact`` nodes, with its damping ratio) and rotational (6 EI/l per
    element) frequencies stable at that step with the same safety (Gershgorin row bound,
    as in :mod:`vfife.timestep`: m >= K (dt / safety)^2 / (4 f^2), f the damped factor).
    So the step no longer falls with a stiff pipe (hard-stiff: rotation- then
    bending-limited at 1/8 and 1/2 of the axial step), long elements on a stiff seabed
    or a stiff contact: only the nodes concerned get slower. Inertia does not enter the
    equilibrium.

    tension : (ne,) or scalar element tension estimate [N] (string stiffness).
    contact : (n,) bool, nodes that may touch the seabed (None: all, if a seabed).
    Returns (dt [s], mass (n,) [kg], rotational inertia (n,) [kg m2], info dict).
    """
    from .timestep import damped_factor
    m = mesh.lump(mesh.mass_pl)
    J = rot_scale * mesh.lump(mesh.rot_pl)
    ka = mesh.EA / mesh.l0
    sa = np.zeros(mesh.n)
    sa[:-1] += ka
    sa[1:] += ka
    eta = np.broadcast_to(np.asarray(axial_damping, float), mesh.l0.shape)
    se = np.zeros(mesh.n)
    se[:-1] += eta
    se[1:] += eta
    om_a = np.sqrt(2.0 * sa / m)
    dt_axial = float(np.min(2.0 * damped_factor(se / (m * om_a)) / om_a))
    dt = safety * dt_axial
    dc = dt / safety                         # the critical step every node must reach
    T = np.broadcast_to(np.abs(np.asarray(tension, float)), mesh.l0.shape)
    kt_e = 24.0 * mesh.EI / mesh.l0 ** 3 + 2.0 * T / mesh.l0
    st = np.zeros(mesh.n)
    st[:-1] += kt_e
    st[1:] += kt_e
    m_t = st * dc * dc / 4.0
    if seabed_stiffness > 0.0:
        on = np.ones(mesh.n, bool) if contact is None else np.asarray(contact, bool)
        f = float(damped_factor(seabed_zeta))
        m_s = (st + seabed_stiffness * mesh.trib) * dc * dc / (4.0 * f * f)
        m_t = np.where(on, np.maximum(m_t, m_s), m_t)
    kr = 6.0 * mesh.EI / mesh.l0
    sr = np.zeros(mesh.n)
    sr[:-1] += kr
    sr[1:] += kr
    J_t = sr * dc * dc / 4.0
    mass = np.maximum(m, m_t)
    Jf = np.maximum(J, J_t)
    info = {"dt_axial": dt_axial, "mass_factor_max": float(np.max(mass / m)),
            "mass_scaled_nodes": int(np.sum(mass > m)),
            "rot_factor_max": float(np.max(Jf / np.maximum(J, 1e-300)))}
    return dt, mass, Jf, info

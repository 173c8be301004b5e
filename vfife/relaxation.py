"""Fictitious static inertia for the dynamic relaxation (statics only).

The equilibrium does not depend on the masses, so statics may use any positive nodal
masses and rotational inertias: :func:`static_inertia` keeps the physical ones where the
axial wave sets the time step and raises them where the bending, the rotation or the
seabed spring would force a smaller one (Underwood-style mass scaling). (A kinetic-damping
driver was tried and dropped: with the global kinetic energy, the high-frequency content
of the start triggered a reset every ~3 steps and the relaxation stalled.)
"""

from __future__ import annotations

import math

import numpy as np

from .mesh import Mesh


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
    from .timestep import critical_steps, damped_factor, nodal_stiffness
    m = mesh.lump(mesh.mass_pl)
    J = rot_scale * mesh.lump(mesh.rot_pl)
    dt_axial = critical_steps(mesh, rot_scale=rot_scale, axial_damping=axial_damping)["axial"]
    dt = safety * dt_axial
    dc = dt / safety                         # the critical step every node must reach
    k = nodal_stiffness(mesh, tension)
    st = k["transverse"]
    m_t = st * dc * dc / 4.0
    if seabed_stiffness > 0.0:
        on = np.ones(mesh.n, bool) if contact is None else np.asarray(contact, bool)
        f = float(damped_factor(seabed_zeta))
        m_s = (st + seabed_stiffness * mesh.trib) * dc * dc / (4.0 * f * f)
        m_t = np.where(on, np.maximum(m_t, m_s), m_t)
    J_t = k["rotation"] * dc * dc / 4.0
    mass = np.maximum(m, m_t)
    Jf = np.maximum(J, J_t)
    info = {"dt_axial": dt_axial, "mass_factor_max": float(np.max(mass / m)),
            "mass_scaled_nodes": int(np.sum(mass > m)),
            "rot_factor_max": float(np.max(Jf / np.maximum(J, 1e-300)))}
    return dt, mass, Jf, info

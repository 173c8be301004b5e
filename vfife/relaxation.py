"""The dynamic relaxation loop and its fictitious static inertia (statics only).

The equilibrium does not depend on the masses, so statics may use any positive nodal
masses and rotational inertias: :func:`static_inertia` keeps the physical ones where the
axial wave sets the time step and raises them where the bending, the rotation or the
seabed spring would force a smaller one (Underwood-style mass scaling). (A kinetic-damping
driver was tried and dropped: with the global kinetic energy, the high-frequency content
of the start triggered a reset every ~3 steps and the relaxation stalled.)
"""

from __future__ import annotations

import math
import time
from enum import StrEnum

import numpy as np

from .mesh import Mesh
from .model import Model
from .timestep import critical_steps, damped_factor, nodal_stiffness


class RelaxOutcome(StrEnum):
    """How a relaxation ended (its value is written in summary.json's stages)."""

    #: force (and moment) residual below the tolerance, and the creep test met
    CONVERGED = "converged"
    #: the step budget ran out before the residual met the tolerance
    MAX_STEPS = "max_steps"
    #: the residual is met but the displacement still to come is not (creep test)
    CREEPING = "creeping"
    #: NaN/inf in the state or a runaway speed
    BLOW_UP = "blow-up"


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


def weight_scale(mesh: Mesh) -> float:
    """One element's weight [N] for the residual scale: max |w| l0 (EA-strain-free
    fallback for weightless lines: 1e-6 EA l0/l0 = 1e-6 EA)."""
    w = float(np.max(np.abs(mesh.weight_pl * mesh.l0)))
    return w if w > 0.0 else 1e-6 * float(np.max(mesh.EA))


def relax(model: Model, dt: float, c: float, tol: float, max_steps: int,
          chunk: int = 20000, progress=None, label: str = "",
          creep_tol: float | None = None, creep_windows: int | None = None) -> dict:
    """Relax ``model`` to equilibrium; returns a dict (steps, residual (relative),
    moment_residual (relative), creep_m (estimated remaining displacement [m], NaN when not
    checked), status (a :class:`RelaxOutcome`), wall_s).

    Converged when the largest nodal out-of-balance force is below ``tol`` x one element's
    weight (moments: x the element length) and, with ``creep_tol`` [m], when the
    displacement still to come is below ``creep_tol``. Why the second test: a soft mode
    (the touchdown sliding along the seabed, the lateral sway of a lazy wave) carries a
    large displacement error for a small force (error ~ r / (m omega_1^2): 1e-3 element
    weights is ~1 m on the 2,600 m Wang riser), and the over-damped relaxation creeps
    towards it at omega_1^2 / c. The remaining displacement is estimated by Aitken
    extrapolation of the largest nodal displacement over successive windows of steps:
    d_k -> remaining = d_k q / (1 - q), q = d_k / d_(k-1) (exact for one decaying mode),
    accepted only once q is steady (changes by <= 0.05 between windows), i.e. the slowest
    mode dominates the motion. ``creep_windows``: give up after that many windows with
    status ``CREEPING`` (the caller then changes the damping), None: until ``max_steps``.
    ``progress``: optional callable(message), told after every ``chunk`` of steps and
    every creep window (no fraction: when the relaxation converges is not known).
    """
    wl = weight_scale(model.mesh)
    h = float(np.max(model.mesh.l0))
    tol_f = tol * wl
    tol_m = tol * wl * h
    t0 = time.perf_counter()
    done = 0
    status = RelaxOutcome.MAX_STEPS
    res = mres = float("nan")
    creep = float("nan")
    while done < max_steps:
        nstep = min(chunk, max_steps - done)
        k, res, mres, ke, st = model.run(nstep, dt, c, tol_f=tol_f, tol_m=tol_m)
        done += k
        if progress is not None:
            progress(f"statics {label}: {done} steps, residual {res / wl:.3g} x element "
                     f"weight")
        if st == 2 or not (np.all(np.isfinite(model.X)) and np.all(np.isfinite(model.D))):
            status = RelaxOutcome.BLOW_UP
            break
        if st == 1:
            if creep_tol is None:
                status = RelaxOutcome.CONVERGED
                break
            window = int(min(max(done // 4, 1000), 50000))
            d_prev = math.inf
            q_prev = math.nan
            status = RelaxOutcome.CREEPING
            nwin = 0
            while done < max_steps and (creep_windows is None or nwin < creep_windows):
                nwin += 1
                X0 = model.X.copy()
                k, res, mres, ke, st = model.run(min(window, max_steps - done), dt, c)
                done += k
                if st == 2 or not np.all(np.isfinite(model.X)):
                    status = RelaxOutcome.BLOW_UP
                    break
                d = float(np.max(np.sqrt(np.sum((model.X - X0) ** 2, axis=0))))
                q = d / d_prev if d_prev > 0.0 else 0.0
                # one decaying mode has a steady ratio q; while faster modes still decay the
                # ratio grows from window to window and the extrapolation is not yet valid
                steady = abs(q - q_prev) <= 0.05
                creep = d * q / (1.0 - q) if (q < 1.0 and steady) else math.inf
                d_prev, q_prev = d, q
                if progress is not None:
                    progress(f"statics {label}: creep check, {done} steps, moved {d:.3g} m "
                             f"in {window} steps, estimated remaining {creep:.3g} m")
                # a motion below 1e-3 creep tolerances per window is round-off jitter (its
                # ratio q is noise): a mode that slow would need > 1000 windows to cover
                # one creep tolerance
                if d < 1e-3 * creep_tol:
                    creep = d
                if (creep < creep_tol and d < creep_tol and res <= tol_f
                        and (mres <= tol_m or tol_m <= 0.0)):
                    status = RelaxOutcome.CONVERGED
                    break
            break
    return {"steps": done, "residual": res / wl, "moment_residual": mres / (wl * h),
            "creep_m": creep, "status": status, "wall_s": time.perf_counter() - t0,
            "dt": dt, "damping": c}

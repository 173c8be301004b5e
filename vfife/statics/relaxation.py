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
from dataclasses import dataclass
from enum import StrEnum

import numpy as np

from ..mesh import WEIGHTLESS, Mesh
from ..model import Model
from ..timestep import critical_steps, damped_factor, nodal_stiffness


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


def divergence_message(scene, h: float, dt: float, limit: str, steps: dict,
                       nstep: int) -> str:
    """Message for a relaxation that diverged (NaN/inf or runaway speeds), naming the
    likely cause from the step and the critical steps of the mesh being relaxed."""
    crit = min(steps.values())
    name = min(steps, key=steps.get)
    head = (f"static relaxation diverged (NaN/inf or runaway speed) after {nstep} steps on "
            f"the {h:g} m mesh with time step {dt:.3g} s (critical: {name} {crit:.3g} s)")
    if dt > crit:
        if limit.startswith("user"):
            cause = (f"the fixed [vfife] static_time_step {dt:.3g} s is {dt / crit:.3g} x the "
                     f"critical step; remove it or use <= {0.8 * crit:.3g} s")
        else:
            cause = ("[vfife] time_step_safety too high for the critical-step estimate; "
                     "lower it")
    elif "seabed" in steps and steps["seabed"] <= 1.05 * crit:
        cause = (f"the seabed contact (stiffness {scene.seabed.stiffness:.3g} N/m2, damping "
                 f"{scene.seabed.damping:g} of critical) limits the step; lower "
                 "[vfife] time_step_safety or the seabed stiffness")
    else:
        cause = ("an impossible or badly started geometry (line much longer or shorter than "
                 "the span, a slack line buckling); check the ends and segment lengths, or "
                 "lower [vfife] time_step_safety")
    return f"{head}; likely cause: {cause}"


def weight_scale(model: Model) -> float:
    """One element's load [N] for the residual scale: max |q| l0 over the elements, q the
    largest distributed load per length [N/m] of the element: its submerged weight |w|,
    the dead load |q_d| (tests) and the normal drag of the current at its largest speed,
    0.5 rho D C_Dn U_max^2 (a weightless or light line is held by the drag or the dead
    load: measured against the weight alone, whose fallback for a weightless line was
    1e-6 EA, a taut weightless line under 0.1 N/m sideways stopped 'converged' 22 % short
    of its deflection, the out-of-balance force a quarter of the load on a node). The
    weight governs on every built-in riser (drag / weight <= 0.3); the residuals are
    reported as fractions of this load ('element weight')."""
    mesh = model.mesh
    q = np.abs(mesh.weight_pl)
    if model.dead_load is not None:
        q = np.maximum(q, float(np.linalg.norm(model.dead_load)))
    cur = model.scene.current
    if model.use_drag and cur is not None:
        q = np.maximum(q, mesh.cdn_pl * cur.max_abs_speed ** 2)
    w = float(np.max(q * mesh.l0))
    # below WEIGHTLESS [N/m] a line is weightless here too (a weight of -4e-226 N/m gave a
    # scale of 1e-225 N and a converged run reported 'residual 1.2e+222 x element weight')
    weightless = w <= WEIGHTLESS * float(np.max(mesh.l0))
    return 1e-6 * float(np.max(mesh.EA)) if weightless else w


def roundoff_floor(model: Model) -> tuple[float, float]:
    """The force [N] and moment [N m] residuals that the round-off of the positions alone
    leaves, 16 x the element stiffness times one ulp of the largest coordinate:
    (max of EA/l0 and 24 EI/l0^3, max EI/l0^2) x spacing(max |X|).

    Why: a node's out-of-balance force is the difference of two element forces EA (l -
    l0)/l0, whose chords l are differences of coordinates known to ulp(|X|) (1.1e-13 m
    at 1 km): a noise ~EA/l0 ulp(|X|) that no relaxation removes. On a stiff, light line it
    exceeds 1e-3 element weights (w 0.5 N/m, EA 1e9 N at 0.5 m elements: the residual
    stalled at 3.4e-3 element weights, ~4 x EA/l0 ulp(|X|), and never converged; at 0.25
    m at 1.6e-2). The force test asks for no less than this floor (a residual relative to
    the element forces' resolution as well as to the element weight); the accuracy of
    what is reported is then bounded by the tests on what is still to come
    (:func:`relax`). 16: the largest nodal noise measured is ~4 x the estimate (x4
    margin). On the built-in scenes it is 4e-2 to 4e-5 of the force tolerance."""
    xmax = float(np.max(np.abs(model.X)))
    ulp = float(np.spacing(max(xmax, 1.0)))
    l0 = model.mesh.l0
    # the transverse stiffness of the bending zig-zag, 24 EI/l0^3, where it exceeds EA/l0
    # (a stiff pipe on short elements: hard-stiff at 0.25 m, where one ulp of the
    # positions moves a node's force by 1.6 N against EA/l0 ulp = 2e-3 N, and Newton's
    # method stalled at 0.34 N against a floor of 0.03 N)
    stiff = np.maximum(model.kax, 24.0 * model.kb / (l0 * l0))
    return (16.0 * float(np.max(stiff)) * ulp,
            16.0 * float(np.max(model.kb / l0)) * ulp)


class StillToCome:
    """Aitken estimate of what is still to come of a quantity that settles
    geometrically, from its largest change ``d`` over successive equal windows of steps:
    remaining = d q / (1 - q), q = d_k / d_(k-1) (exact for one decaying mode), accepted
    only once q is steady (changes by <= 0.05 between windows: the slowest mode
    dominates). A change below ``noise`` (the round-off of the quantity) or 1e-3 of the
    tolerance is jitter, whose ratio q is noise: it counts as what remains (a mode that
    slow would need > 1000 windows to cover one tolerance). ``tol``: the tolerance in the
    unit of ``d`` (a relative one is updated per window, :meth:`update`)."""

    def __init__(self, tol: float, noise: float = 0.0):
        self.tol = tol
        self.noise = noise
        self.d_prev = math.inf
        self.q_prev = math.nan
        self.d = math.inf
        self.remaining = math.inf

    def update(self, d: float, tol: float | None = None) -> float:
        """Take the change ``d`` of the latest window (and the tolerance ``tol`` when
        given); returns the estimate of what remains."""
        if tol is not None:
            self.tol = tol
        q = d / self.d_prev if self.d_prev > 0.0 else 0.0
        steady = abs(q - self.q_prev) <= 0.05
        self.remaining = d * q / (1.0 - q) if (q < 1.0 and steady) else math.inf
        if d < max(1e-3 * self.tol, self.noise):
            self.remaining = d
        self.d_prev, self.q_prev, self.d = d, q, d
        return self.remaining

    @property
    def met(self) -> bool:
        """What remains and the latest change are both below the tolerance."""
        return self.remaining < self.tol and self.d < self.tol


@dataclass(frozen=True)
class Tolerances:
    """The tests of :func:`relax` (None: that test off).

    force : largest nodal out-of-balance force, fraction of one element's weight (the
        moment: x the element length).
    creep_m : [m] displacement still to come.
    tension : change still to come of every element tension, fraction of the largest.
    moment : change still to come of every element end moment, fraction of the largest.
    """

    force: float
    creep_m: float | None = None
    tension: float | None = None
    moment: float | None = None

    @property
    def windowed(self) -> bool:
        """Any test that needs windows of steps after the force test is met."""
        return not (self.creep_m is None and self.tension is None and self.moment is None)


def resultants(model: Model) -> tuple[np.ndarray, np.ndarray]:
    """The element tensions N (ne,) [N] and the element end moments (2, 3, ne) [N m]: what
    the reported tension and moment are made of (:mod:`vfife.recovery`)."""
    N, Ma, Mb, *_ = model.element_state()
    return N, np.stack([Ma, Mb])


def _to_come(estimate: StillToCome, new: np.ndarray, old: np.ndarray, rel_tol: float,
             floor: float) -> float:
    """Update ``estimate`` with the largest change of a resultant over the latest window
    (``old`` -> ``new``) against ``rel_tol`` of its largest value (at least ``floor``, the
    residual test's own tolerance in that unit); returns what is still to come, as a
    fraction of the largest value."""
    top = max(float(np.max(np.abs(new))), floor)
    return estimate.update(float(np.max(np.abs(new - old))), max(rel_tol * top, floor)) / top


def relax(model: Model, dt: float, c: float, tol: Tolerances, max_steps: int,
          chunk: int = 20000, progress=None, label: str = "",
          creep_windows: int | None = None) -> dict:
    """Relax ``model`` to equilibrium at damping ``c`` [1/s]; returns a dict (steps,
    residual (relative), moment_residual (relative), creep_m (estimated remaining
    displacement [m]), tension_to_come, moment_to_come (estimated remaining change of
    the element tensions / the largest, of the end moments / the largest; each NaN when
    not checked), status (a :class:`RelaxOutcome`), wall_s).

    Converged when (``tol``, :class:`Tolerances`) the largest nodal out-of-balance force
    is below ``tol.force`` x one element's weight (moments: x the element length; never
    below the round-off floor of the element forces, :func:`roundoff_floor`) and what is
    still to come is below its tolerance: the displacement (``tol.creep_m``), every
    element tension (``tol.tension`` x the largest, at least the force tolerance) and
    every element end moment (``tol.moment`` x the largest, at least the moment
    tolerance).

    Why the creep test: a soft mode (the touchdown sliding along the seabed, the lateral
    sway of a lazy wave) carries a large displacement error for a small force (error ~ r
    / (m omega_1^2): 1e-3 element weights is ~1 m on the 2,600 m Wang riser), and the
    over-damped relaxation creeps towards it at omega_1^2 / c.
    Why the resultant tests: neither of the others bounds what is reported. A taut line's
    transverse equilibrium T kappa = w cos(theta) holds its tension: a residual r per
    node (r / (w h) of the load) is balanced by a sag change df and a tension change
    dT = EA (8/3) f df / L^2 together, so dT / T ~ r / (w h) x lambda / (1 + lambda),
    lambda = (8/3) EA f^2 / (T L^2): up to the whole 1e-3 on a stiff line (0.5 N/m, 0.01
    m from taut: stopped 1.4e-4 off) for micrometres of displacement, far below any
    creep test. On risers the creep estimate undershoots a slow touchdown mode (Yu A1:
    7 cm to come against an estimated 1 cm): 1.8e-4 of T_max still to come in the
    tension, 3.2e-3 of M_max in the moment next to the touchdown (Wang, current -1.5
    m/s). The resultants settle like the displacement, so the same Aitken estimate
    (:class:`StillToCome`) bounds them, window by window.
    ``creep_windows``: give up after that many windows with status ``CREEPING`` (the
    caller then changes the damping), None: until ``max_steps``. ``progress``: optional
    callable(message), told after every ``chunk`` of steps and every window (no
    fraction: when the relaxation converges is not known).
    """
    wl = weight_scale(model)
    h = float(np.max(model.mesh.l0))
    floor_f, floor_m = roundoff_floor(model)
    tol_f = max(tol.force * wl, floor_f)
    tol_m = max(tol.force * wl * h, floor_m)
    t0 = time.perf_counter()
    done = 0
    status = RelaxOutcome.MAX_STEPS
    res = mres = float("nan")
    creep = t_come = m_come = float("nan")
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
            if not tol.windowed:
                status = RelaxOutcome.CONVERGED
                break
            window = int(min(max(done // 4, 1000), 50000))
            disp = StillToCome(tol.creep_m if tol.creep_m is not None else math.inf)
            # the resultants' round-off: the noise of the force floor, a quarter of it
            ten = StillToCome(math.inf, 0.25 * floor_f)
            mom = StillToCome(math.inf, 0.25 * floor_m)
            status = RelaxOutcome.CREEPING
            nwin = 0
            while done < max_steps and (creep_windows is None or nwin < creep_windows):
                nwin += 1
                X0 = model.X.copy()
                watch = tol.tension is not None or tol.moment is not None
                N0, M0 = resultants(model) if watch else (None, None)
                k, res, mres, ke, st = model.run(min(window, max_steps - done), dt, c)
                done += k
                if st == 2 or not np.all(np.isfinite(model.X)):
                    status = RelaxOutcome.BLOW_UP
                    break
                ok = res <= tol_f and (mres <= tol_m or tol_m <= 0.0)
                msg = ""
                if tol.creep_m is not None:
                    d = float(np.max(np.sqrt(np.sum((model.X - X0) ** 2, axis=0))))
                    creep = disp.update(d)
                    ok = ok and disp.met
                    msg += (f", moved {d:.3g} m in {window} steps, estimated remaining "
                            f"{creep:.3g} m")
                N, M = resultants(model) if watch else (None, None)
                if tol.tension is not None:
                    t_come = _to_come(ten, N, N0, tol.tension, tol_f)
                    ok = ok and ten.met
                    msg += f", tension to come {t_come:.2g} x T_max"
                if tol.moment is not None:
                    m_come = _to_come(mom, M, M0, tol.moment, tol_m)
                    ok = ok and mom.met
                    msg += f", moment to come {m_come:.2g} x M_max"
                if progress is not None:
                    progress(f"statics {label}: creep check, {done} steps{msg}")
                if ok:
                    status = RelaxOutcome.CONVERGED
                    break
            break
    return {"steps": done, "residual": res / wl, "moment_residual": mres / (wl * h),
            "creep_m": creep, "tension_to_come": t_come, "moment_to_come": m_come,
            "status": status, "wall_s": time.perf_counter() - t0, "dt": dt, "damping": c}

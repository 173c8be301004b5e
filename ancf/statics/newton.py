"""The ANCF statics: Newton-Raphson on R(q) = F_int(q) - F_ext(q) = 0 from the starting
shape (:mod:`ancf.statics.start`), with a backtracking line search and, when the full problem does
not converge from the start, continuation (load stepping) in the bending stiffness and the
current's drag.

Stopping rule (stated like the VFIFE's, in forces): converged when the largest
out-of-balance force at a node, |R_r| [N], is below ``tolerance`` x the load scale (the
largest load an element carries, |w| l0 [N], or a point attachment's weight), and the
largest out-of-balance at a node's slope |R_r'| [N m] below ``tolerance`` x the load scale
x the element length. Newton converges quadratically near the solution, so the default
1e-6 costs one or two iterations more than 1e-3 (the VFIFE's default). The residual
cannot go below its round-off: a position known to eps |r| (eps = 2.2e-16, |r| the line's
extent) gives a strain known to eps |r| / h and a force to EA eps |r| / h, so the
tolerance taken is at least 16 x that floor / the load scale (:func:`round_off_floor`;
5e-7 on scr-steel at 2 m elements, where the measured floor was 4-7e-7).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..model import Model, free_part, newton_correction, residual_ratio, round_off_floor


@dataclass
class NewtonOutcome:
    """converged, iterations (total), residual (the largest of the two ratios of the
    stopping rule), steps (the continuation's load steps), message."""

    converged: bool
    iterations: int
    residual: float
    steps: int
    message: str = ""


#: the trust region of a Newton step: the largest change of a node's position, as a
#: fraction of the shortest element at the start (it then doubles after each step the
#: line search took whole and halves after each it cut, between MIN_RADIUS x that and
#: MAX_RADIUS x the line's length), and of its slope. Why: from a start far from
#: equilibrium, a line with next to no bending stiffness and no tension (a chain lying
#: on the seabed) has a nearly singular tangent whose full step threw the line into a
#: spurious folded equilibrium (mooring-clump-weight: a hang-off tension of 926 kN
#: against the BVP's 262 kN), and full steps across the seabed's contact switches kept
#: scr-steel's residual from falling; a fixed small region took 100s of iterations where
#: the line must move tens of metres (ttr-steel in its current).
START_RADIUS = 0.25
MIN_RADIUS = 1e-3
MAX_RADIUS = 0.05
START_SLOPE = 0.1
MAX_SLOPE = 1.0


def step_cap(dq: np.ndarray, d: int, radius: float, slope: float) -> float:
    """The fraction of the Newton step ``dq`` inside the trust region (at most 1)."""
    r = dq.reshape(-1, 2 * d)
    dr = float(np.max(np.linalg.norm(r[:, :d], axis=1)))
    ds = float(np.max(np.linalg.norm(r[:, d:], axis=1)))
    return min(1.0, radius / max(dr, 1e-300), slope / max(ds, 1e-300))


def _free_norm(model: Model, R: np.ndarray) -> float:
    return float(np.linalg.norm(free_part(model, R)))


def newton(model: Model, q: np.ndarray, tolerance: float, max_iterations: int):
    """(q, converged, iterations, residual ratio) of Newton's method from ``q`` (the fixed
    unknowns keep their values)."""
    q = q.copy()
    tolerance = max(tolerance, 16.0 * round_off_floor(model, q))
    h = float(np.min(model.mesh.l0))
    length = float(model.mesh.s[-1])
    radius, slope = START_RADIUS * h, START_SLOPE
    R, K, energy = model.residual(q)
    conservative = not (model.use_drag or model.use_point_drag)
    ratio = residual_ratio(model, R)
    it = 0
    while it < max_iterations:
        if not math.isfinite(ratio):
            return q, False, it, ratio
        if ratio < tolerance:
            return q, True, it, ratio
        it += 1
        dq = newton_correction(model, K, R)
        if dq is None:
            return q, False, it, ratio
        norm0 = _free_norm(model, R)
        slope_e = float(R @ dq)          # the energy's derivative along the step
        cap = step_cap(dq, model.d, radius, slope)
        alpha = cap
        accepted = whole = False
        for k in range(12):
            qt = q + alpha * dq
            Rt, Kt, et = model.residual(qt)
            nt = _free_norm(model, Rt)
            # accepted when the residual falls, or (conservative loads, a descent
            # direction) the potential energy falls by Armijo's rule: on a stiff line a
            # good step first raises the residual 1e4-fold through the axial strain
            # (a cantilever at EA = 1e6 P stalled on the residual alone)
            if math.isfinite(nt) and (
                    nt < (1.0 - 1e-4 * alpha) * norm0
                    or (conservative and slope_e < 0.0 and math.isfinite(et)
                        and et <= energy + 1e-4 * alpha * slope_e)):
                accepted, whole = True, k == 0
                break
            alpha *= 0.5
        if not accepted:
            # no decrease along the Newton direction: the capped step (past a contact
            # switch the residual may first grow), counted like the others
            qt = q + cap * dq
            Rt, Kt, et = model.residual(qt)
            if not np.all(np.isfinite(Rt)):
                return q, False, it, ratio
        if whole and cap < 1.0:
            radius, slope = min(2.0 * radius, MAX_RADIUS * length), min(2.0 * slope, MAX_SLOPE)
        elif not whole:
            radius, slope = max(0.5 * radius, MIN_RADIUS * h), max(0.5 * slope, 1e-3)
        q, R, K, energy = qt, Rt, Kt, et
        ratio = residual_ratio(model, R)
    return q, ratio < tolerance, it, ratio


def solve_statics(model: Model, q0: np.ndarray, tolerance: float, max_iterations: int,
                  progress=None) -> tuple[np.ndarray, NewtonOutcome]:
    """The static equilibrium from ``q0``: Newton on the full problem; if that fails,
    continuation from the start in load steps, each halved when its Newton fails (at most
    12 halvings): in the current's drag (0 -> 1) when the line has drag, else in the
    bending stiffness (EI x 1e-3 -> 1; the start is the line without it)."""
    q, ok, it, ratio = newton(model, q0, tolerance, max_iterations)
    if ok:
        return q, NewtonOutcome(True, it, ratio, 1)
    total = it
    if progress is not None:
        progress(f"ancf: Newton from the start stopped at {ratio:.2g} after {it} "
                 "iterations: load stepping")
    q = q0.copy()
    lam, step, steps, halvings = 0.0, 0.25, 0, 0
    by_drag = model.use_drag
    while lam < 1.0:
        target = min(1.0, lam + step)
        if by_drag:
            model.drag_scale = target
        else:
            model.ei_scale = 10.0 ** (-3.0 * (1.0 - target))
        qt, ok, it, ratio = newton(model, q, tolerance, max_iterations)
        total += it
        if ok:
            q, lam, steps = qt, target, steps + 1
            step = min(2.0 * step, 0.5)
        else:
            step *= 0.5
            halvings += 1
            if halvings > 12:
                model.ei_scale = model.drag_scale = 1.0
                what = "the current's drag" if by_drag else "the bending stiffness"
                return q, NewtonOutcome(False, total, ratio, steps,
                                        f"load stepping in {what} stalled at {lam:.3g} of "
                                        f"it (residual {ratio:.3g} x the load scale)")
    model.ei_scale = model.drag_scale = 1.0
    return q, NewtonOutcome(True, total, ratio, steps)

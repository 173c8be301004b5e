"""Boundary-value solver of the multi-segment large-deformation beam (scipy ``solve_bvp``).

Public entry: :func:`solve` (scene -> :class:`riser.result.SolveResult`).

The model (``bvp/equations.py``) is chosen by the scene: ``scene.axial_model``
('extensible', strain T/EA, or the 'inextensible' limit) and ``scene.seabed_model``
('elastic' Winkler foundation of [seabed] stiffness, or the 'rigid' limit). Ends
(``scene.ends.kind``):

- ``tdp_tension`` (Wang form, rigid seabed): touchdown at the origin with theta = 0,
  M = 0, T = T_TDP; M = 0 at the free top. The hang-off point is an output.
- ``hang_off_angle`` (rigid seabed): touchdown at the origin (theta = 0, M = 0); hang-off
  height and angle given, M = 0 there; the suspended length of the first segment is an
  unknown parameter, the TDP tension an output.
- ``top_tension`` (J-lay, rigid seabed): as ``hang_off_angle`` with the hang-off height
  and effective tension given (M = 0 there); the hang-off x and angle and the TDP tension
  are outputs. The first segment's length in the file is the pipe available: a solved
  suspended length beyond it is no equilibrium; the rest lies on the seabed.
- ``fixed`` on an elastic seabed (the default with a [seabed]): the whole line from the
  anchor to the hang-off, positions given and M = 0 at both; wherever it is below y = 0
  the seabed pushes it up with k max(-y, 0), so the lift-off point (any contact) is found
  by the solver, with no touchdown condition.
- ``fixed`` on a rigid seabed with the anchor on it (y = 0): the grounded part from the
  anchor is straight and frictionless, its tension the TDP tension plus the tangential
  drag of the current at the seabed; the touchdown position (the suspended length of the
  first segment) is an unknown parameter; M = 0 at the touchdown and the hang-off.
- ``fixed`` otherwise: pinned-pinned free-hanging line, positions given and M = 0 at both.

Unknown T(0) is simply a free state value. Continuity of x, y, theta, M, F, T at every
joint closes the stacked system. Current drag is planar only.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from riser import validity
from riser.internal_flow import wall_tension
from riser.result import SolveResult, Status
from riser.scene import FixedEnds, HangOffAngleEnds, Scene, TdpTensionEnds, TopTensionEnds
from riser.sections import segment_properties

from . import guess as guesses
from .catenary import catenary_state
from .equations import IM, IT, ITH, IX, IY, NSTATE, BeamModel
from .guess import BVPFailure, NoEquilibrium
from .mesh import clustered_mesh
from .output import build_profile, grounded_drag
from .strategy import (good, hopeless_span, hopeless_start, second_contact,
                       solve_with_continuation)


@dataclass
class _Problem:
    """Everything solve_bvp needs for one scene, plus what is needed to build the profile."""

    model: BeamModel
    bc: object
    guess_p: np.ndarray
    form: str
    anchor_xy: tuple = (0.0, 0.0)
    first_total: float = 0.0           # full length of the first segment [m]
    guess: object = None               # callable(tau) -> scaled state (6n, m)


def effects_of(scene: Scene) -> list[str]:
    """Physical effects the BVP includes for this scene."""
    eff = ["weight", "bending"]
    if scene.axial_model == "extensible":
        eff.append("axial")
    if scene.current is not None:
        eff.append("current_drag")
    if scene.seabed_model is not None and (not isinstance(scene.ends, FixedEnds)
                                           or scene.seabed_model == "elastic"
                                           or scene.ends.anchor[1] == 0.0):
        eff.append("seabed")
    if scene.internal_flow is not None:
        eff.append("internal_flow")
    return eff


def solve(scene: Scene, *, tolerance: float | None = None, max_nodes: int | None = None,
          initial_nodes: int | None = None, continuation: bool = True) -> SolveResult:
    """Solve the static configuration of ``scene`` (see module docstring for the ends).

    Never raises on non-convergence: the result has a :class:`~riser.result.Status` other
    than converged and a message saying why; a scene the method cannot represent
    (out-of-plane current, a slug in the internal flow, a second touchdown) is ``refused``.
    """
    t0 = time.perf_counter()
    settings = scene.bvp.override(tolerance=tolerance, max_nodes=max_nodes,
                                  initial_nodes=initial_nodes)
    if scene.current is not None and not scene.current.is_planar:
        return SolveResult.refused("bvp", scene, (
            f"{scene.source}: environment.current.heading_deg: {scene.current.heading_deg:g} "
            "deg is out of plane; the bvp method is planar only (use --method vfife)"))
    if scene.internal_flow is not None and scene.internal_flow.has_slug:
        return SolveResult.refused("bvp", scene, (
            f"{scene.source}: internal_flow.slug: the bvp method models a steady uniform "
            "flow only (a slug is a travelling load: use --method vfife)"))

    effects = effects_of(scene)
    info = {"tolerance": settings.tolerance}
    warnings = []
    if scene.dynamics is not None:
        warnings.append("ignored_input: bvp solves statics only: [dynamics] ignored")
    if scene.seabed is not None and scene.seabed.friction > 0.0:
        warnings.append(f"ignored_input: bvp seabed is frictionless: seabed.friction = "
                        f"{scene.seabed.friction:g} ignored")

    def result(status: Status, msg: str, profile=None) -> SolveResult:
        return SolveResult("bvp", scene.name, status, msg, profile, time.perf_counter() - t0,
                           effects, model=scene.continuum_model(), warnings=warnings,
                           info=info)

    tau0 = clustered_mesh(settings.initial_nodes)
    hopeless = hopeless_span(scene)        # give up early: no equilibrium of these forms
    if hopeless:
        return result(Status.NO_EQUILIBRIUM, hopeless)
    split_tried = ""
    for split in (True, False):
        try:
            prob = _build_problem(scene, split)
        except BVPFailure as exc:
            return result(Status.NO_EQUILIBRIUM if isinstance(exc, NoEquilibrium)
                          else Status.NOT_CONVERGED, str(exc))
        early = hopeless_start(scene, prob, tau0)
        if early is not None and early[0] is Status.REFUSED:
            return SolveResult.refused("bvp", scene, f"{scene.source}: bvp refused: {early[1]}")
        if early is not None:
            return result(*early)
        sol, how, failure = solve_with_continuation(prob, tau0, settings, continuation)
        if prob.form == "fixed_liftoff" and sol is not None and good(sol, prob):
            # the contact zone must be in contact (y <= 0 up to 1 % of the sink depth w/k),
            # else solve the unilateral law everywhere (a failure to converge is final: the
            # unilateral form starts from the same guess and only adds the kink)
            why = _contact_zone_violation(prob, sol)
            if why:
                split_tried = f"contact zone + lift-off point: {why}; then "
                continue
        break
    info["strategy"] = split_tried + how
    if sol is None or not good(sol, prob):
        msg = sol.message if sol is not None else "no solution"
        return result(failure, f"solve_bvp did not converge ({msg}); tried: {split_tried}"
                      f"{how}" + _second_contact(prob, tau0))

    info["nodes"] = int(sol.x.size)
    info["iterations"] = int(sol.niter)
    # solve_bvp's measure: the largest rms collocation residual, relative to 1 + |f|
    info["collocation_residual"] = float(np.max(sol.rms_residuals))
    try:
        profile, checks = build_profile(prob, sol, scene.water_depth)
        if scene.internal_flow is not None:
            # steady flow: no term in the shape equations (T is Fylling's effective
            # tension), one in the wall tension (riser/internal_flow.py)
            profile.wall_tension = wall_tension(scene, profile.s, profile.y, profile.tension)
    except BVPFailure as exc:
        return result(Status.NOT_CONVERGED, str(exc))
    info.update(checks)
    bad = validity.nonfinite(profile)
    if bad:
        return result(Status.DIVERGED, bad)
    message = f"converged ({how})"
    lengths = [g.length for g in scene.segments]
    if isinstance(scene.ends, (HangOffAngleEnds, TopTensionEnds)):
        lengths[0] = checks["first_segment_suspended_length"]
        note, warn = validity.first_segment_warnings(scene, lengths[0])
        info["first_segment_length_in_file"] = scene.segments[0].length
        if isinstance(scene.ends, TopTensionEnds) and lengths[0] > scene.segments[0].length:
            return result(Status.NO_EQUILIBRIUM, "no equilibrium: " + note)
        message += "; " + note
        warnings.extend(warn)
    warnings.extend(validity.profile_warnings(scene, profile, lengths))
    return result(Status.CONVERGED, message, profile)


def _second_contact(prob: _Problem, tau: np.ndarray) -> str:
    """A reason to add to a failure when the starting catenary dips below the seabed away
    from the contact zone at the anchor: the solver starts from one contact zone only."""
    m = prob.model
    if m.k_seabed <= 0.0 and prob.form not in ("fixed_seabed", "fixed_lifted"):
        return ""
    depth, s = second_contact(prob, tau)
    if depth <= 1.0:
        return ""
    return (f"; the starting catenary passes {depth:.3g} m below the seabed "
            f"at s = {s:.1f} m: a second touchdown, which the BVP's start (one contact zone "
            "from the anchor) does not represent")


def _contact_zone_violation(prob: _Problem, sol) -> str:
    """Why the converged contact-zone solution is not valid ('' when it is)."""
    m = prob.model
    zone_y = sol.y[IY] * m.scale[IY]
    sink = max(float(m.w[0]), 0.0) / m.k_seabed
    if float(np.max(zone_y)) > 0.01 * sink + 1e-9:
        return f"the zone rises {float(np.max(zone_y)):.3g} m above the seabed"
    return ""


# ---------------------------------------------------------------------------- set-up
def _build_problem(scene: Scene, split: bool = True) -> _Problem:
    """The stacked problem of ``scene``. ``split``: on an elastic seabed with the anchor on
    it, solve the contact zone (linear spring) and the rest of the line as two pieces
    joined at an unknown lift-off point with y = 0 (see bvp/equations.py)."""
    props = segment_properties(scene)
    n = len(props)
    EI = np.array([p.EI for p in props])
    EA = (np.array([p.EA for p in props], float) if scene.axial_model == "extensible"
          else np.full(n, np.inf))
    w = np.array([p.weight for p in props])
    L = np.array([p.length for p in props])
    c_n = np.array([p.drag_normal_coef for p in props])
    c_t = np.array([p.drag_tangential_coef for p in props])
    ends = scene.ends
    speed = grad = None
    if scene.current is not None:
        sign = math.cos(math.radians(scene.current.heading_deg))   # +1 or -1 (planar)
        cur = scene.current
        speed = lambda y: sign * cur.speed(y)                     # noqa: E731
        grad = lambda y: sign * cur.speed_gradient(y)             # noqa: E731

    length_scale = float(np.sum(L))
    k_seabed = scene.seabed.stiffness if scene.seabed_model == "elastic" else 0.0

    # ---- catenary starting guess for each form: (H, V0, suspended lengths, origin); the
    # problem's form is the end form's kind, a fixed-ends one refined below (its boundary
    # conditions: fixed_seabed, fixed_liftoff, fixed_elastic, fixed)
    form = ends.kind
    anchor = (0.0, 0.0)
    free_first = False
    extensible = scene.axial_model == "extensible"
    cat_EA = None             # the elastic catenary between pinned ends (else inextensible)
    if isinstance(ends, TdpTensionEnds):
        H, V0, Ls = ends.tdp_tension, 0.0, L.copy()
    elif isinstance(ends, HangOffAngleEnds):
        free_first = True
        H, V0, Ls = guesses.hang_off_angle(w, L, ends.hang_off_height,
                                           math.radians(ends.hang_off_angle_deg))
    elif isinstance(ends, TopTensionEnds):
        free_first = True
        H, V0, Ls = guesses.top_tension(w, L, ends.hang_off_height, ends.top_tension)
    else:
        anchor = ends.anchor
        dx = ends.hang_off[0] - anchor[0]
        dy = ends.hang_off[1] - anchor[1]
        on_seabed = scene.seabed is not None and anchor[1] == 0.0
        found = False
        if on_seabed:
            try:
                H, V0, Ls = guesses.grounded(w, L, dx, dy)
                found = True
            except BVPFailure:
                pass
        if k_seabed > 0.0:
            # a contact zone of at least a metre ahead of the anchor, else unilateral throughout
            form = ("fixed_liftoff" if found and split and L[0] - Ls[0] > 1.0
                    else "fixed_elastic")
        elif found:
            form, free_first = "fixed_seabed", True
        else:
            # no touchdown ahead of the anchor: the line may lift off at the anchor,
            # i.e. hang pinned there and rise from the seabed (checked after solving)
            form = "fixed_lifted" if on_seabed else "fixed_free"
        if not found:
            cat_EA = EA if extensible else None
            H, V0, Ls = guesses.free_hanging(w, L, dx, dy, cat_EA)

    grounded = (float(L[0] - Ls[0]) if form in ("fixed_seabed", "fixed_elastic", "fixed_liftoff")
                else 0.0)
    ox = anchor[0] + grounded
    oy = anchor[1]
    cat_top_T = float(catenary_state(np.array([Ls.sum()]), w, Ls, H, V0)["tension"][0])
    Ts = max(cat_top_T, H, 1.0)
    wref = max(float(np.max(np.abs(w))), Ts / length_scale * 1e-3)
    EImax = float(np.max(EI))
    scale = np.array([length_scale, length_scale, 1.0, EImax * wref / Ts,
                      wref * math.sqrt(EImax / Ts), Ts])

    sink = max(float(w[0]), 0.0) / k_seabed if k_seabed > 0.0 else 0.0
    split_first = form == "fixed_liftoff"
    if split_first:
        # stacked segment 0: the contact zone [0, s_L]; 1: the rest of the first segment
        EI, EA, w, c_n, c_t = (np.concatenate([a[:1], a]) for a in (EI, EA, w, c_n, c_t))
        lengths = np.concatenate([[grounded], [L[0] - grounded], L[1:]])
        Ls = np.concatenate([[0.0], Ls])        # the guess's catenary starts after the zone
        p0 = np.array([grounded / length_scale])
    else:
        lengths = L.copy() if free_first or form == "fixed_elastic" else Ls
        p0 = np.array([Ls[0] / length_scale]) if free_first else np.zeros(0)
    model = BeamModel(EI=EI, EA=EA, w=w, c_n=c_n, c_t=c_t, lengths=lengths, scale=scale,
                      k_seabed=k_seabed, speed=speed, speed_gradient=grad,
                      free_first_length=free_first or split_first, split_first=split_first,
                      length_scale=length_scale)
    # the line lying on the seabed ahead of the touchdown (elastic forms), sunk by w/k
    zone = (grounded, sink) if form in ("fixed_elastic", "fixed_liftoff") else (0.0, 0.0)

    def guess(tau: np.ndarray) -> np.ndarray:
        return guesses.state_guess(tau, w, Ls, EI, H, V0, ox, oy, scale, *zone, EA=cat_EA)

    return _Problem(model=model, bc=_boundary_conditions(form, scene, model, L), guess_p=p0,
                    form=form, anchor_xy=anchor, first_total=float(L[0]), guess=guess)


def _boundary_conditions(form: str, scene: Scene, model: BeamModel, L: np.ndarray):
    """bc(ya, yb[, p]) -> scaled residuals; ya/yb have shape (6n,)."""
    ends = scene.ends
    n = model.n_seg
    sc = model.scale
    top = (n - 1) * NSTATE

    def continuity(ya, yb):
        return [yb[k * NSTATE + i] - ya[(k + 1) * NSTATE + i]
                for k in range(n - 1) for i in range(NSTATE)]

    if form == "tdp_tension":
        Tt = ends.tdp_tension / sc[IT]

        def bc(ya, yb, p=None):
            return np.array([ya[IX], ya[IY], ya[ITH], ya[IM], ya[IT] - Tt, *continuity(ya, yb),
                             yb[top + IM]])
    elif form in ("hang_off_angle", "top_tension"):
        Hh = ends.hang_off_height / sc[IY]
        # the third condition at the top: the angle (form b) or the tension (J-lay)
        i3, v3 = ((ITH, math.radians(ends.hang_off_angle_deg)) if form == "hang_off_angle"
                  else (IT, ends.top_tension / sc[IT]))

        def bc(ya, yb, p):
            return np.array([ya[IX], ya[IY], ya[ITH], ya[IM], *continuity(ya, yb),
                             yb[top + IM], yb[top + IY] - Hh, yb[top + i3] - v3])
    elif form == "fixed_seabed":
        xa = ends.anchor[0]
        xh, yh = ends.hang_off[0] / sc[IX], ends.hang_off[1] / sc[IY]
        L0 = float(L[0])

        def bc(ya, yb, p):
            # touchdown at x = anchor + the stretched grounded length (L0 - suspended):
            # integral of 1 + T/EA with T = T_tdp + f_t (g - s) along the grounded part
            g = L0 - p[0] * model.length_scale
            T0 = ya[IT] * sc[IT]
            reach = g + (T0 * g + 0.5 * grounded_drag(model) * g * g) * model.inv_EA[0]
            return np.array([ya[IX] - (xa + reach) / sc[IX], ya[IY], ya[ITH], ya[IM],
                             *continuity(ya, yb), yb[top + IM], yb[top + IX] - xh,
                             yb[top + IY] - yh])
    elif form == "fixed_liftoff":
        xa = ends.anchor[0] / sc[IX]
        xh, yh = ends.hang_off[0] / sc[IX], ends.hang_off[1] / sc[IY]

        def bc(ya, yb, p):
            # anchor pinned on y = 0; y = 0 at the lift-off point (end of the contact zone)
            return np.array([ya[IX] - xa, ya[IY], ya[IM], *continuity(ya, yb),
                             yb[top + IM], yb[top + IX] - xh, yb[top + IY] - yh, yb[IY]])
    else:
        xa, ya0 = ends.anchor[0] / sc[IX], ends.anchor[1] / sc[IY]
        xh, yh = ends.hang_off[0] / sc[IX], ends.hang_off[1] / sc[IY]

        def bc(ya, yb, p=None):
            return np.array([ya[IX] - xa, ya[IY] - ya0, ya[IM], *continuity(ya, yb),
                             yb[top + IM], yb[top + IX] - xh, yb[top + IY] - yh])
    return bc

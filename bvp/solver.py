"""Boundary-value solver of the multi-segment large-deformation beam (scipy ``solve_bvp``).

Public entry: :func:`solve` (scene -> :class:`riser.results.result.SolveResult`).

The model (``bvp/beam/equations.py``) is chosen by the scene: ``scene.axial_model``
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

Unknown T(0) is simply a free state value. The line is one block of six states over one
domain with its joints as mesh points (bvp/beam/layout.py, bvp/beam/problem.py), so the cost does
not grow with the number of segments beyond the mesh the physics needs.

A 3D scene (a hang-off out of the anchor's plane, a current at any heading or turning with
depth) is solved as the 3D rod of bvp/rod/equations.py in the plane of its ends
(bvp/rod/problem.py): ten states a block, the same forms with z, the tilt phi and the
out-of-plane moment M2 added to their conditions, the same continuations plus one from the
loads in the plane to the full ones (bvp/strategy.py).
"""

from __future__ import annotations

import dataclasses
import time

import numpy as np

from riser.results import validity
from riser.physics.internal_flow import wall_tension
from riser.results.result import SolveResult, Status
from riser.model.scene import FixedEnds, HangOffAngleEnds, Scene, TopTensionEnds

from .budget import over_budget, peak_bytes
from .beam.equations import IY
from .beam.guess import BVPFailure, NoEquilibrium
from .beam.output import build_profile
from .beam.problem import _Problem, build_problem
from .rod.output import build_rod_profile
from .rod.problem import build_rod_problem, in_plane_scene, rigid_grounded_across
from .strategy import (
    good,
    hopeless_span,
    hopeless_start,
    second_contact,
    solve_with_continuation,
)


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
          initial_nodes: int | None = None, continuation: bool = True,
          three_d: bool | None = None, dead_load=None) -> SolveResult:
    """Solve the static configuration of ``scene`` (see module docstring for the ends).

    A 3D scene (``scene.statics_planar`` False: a hang-off out of the anchor's plane, a
    current out of the x-y plane) is solved as the 3D rod (bvp/rod/equations.py); ``three_d``
    True solves a planar scene that way too (the rod reduces to the planar equations),
    False refuses a 3D scene. ``dead_load``: a uniform load (qx, qy, qz) [N/m] per
    unstretched length in the scene's axes, added to the weight (closed-form checks; the
    rod).

    Never raises on non-convergence: the result has a :class:`~riser.results.result.Status` other
    than converged and a message saying why; a scene the method cannot represent (a slug
    in the internal flow, a second touchdown, a problem whose solve could take more than
    [bvp] memory_budget: bvp/budget.py, a rigid seabed's grounded line under a current
    out of plane) is ``refused``.
    """
    t0 = time.perf_counter()
    settings = scene.bvp.override(tolerance=tolerance, max_nodes=max_nodes,
                                  initial_nodes=initial_nodes)
    why_3d = scene.out_of_plane(statics=True)
    rod = bool(three_d) or dead_load is not None or (three_d is None and why_3d is not None)
    if why_3d is not None and not rod:
        return SolveResult.refused("bvp", scene, (
            f"{scene.source}: {why_3d[0]}: {why_3d[1]}; solved in plane only "
            "(three_d=False)"))
    validity.check_end_loads(scene)
    if rod and ((isinstance(scene.ends, FixedEnds) and not scene.ends.plain)
                or scene.attachments):
        return SolveResult.refused("bvp", scene, (
            f"{scene.source}: ends: the 3D rod holds its ends pinned in place and carries "
            "no point loads (a joint, a tensioner, a free end or an attachment is solved "
            "in plane only)"))
    if scene.attachments and scene.seabed_model == "rigid":
        return SolveResult.refused("bvp", scene, (
            f"{scene.source}: attachments: on a rigid seabed the grounded line's form has "
            "no point loads; give the seabed a stiffness ([seabed], the elastic model)"))
    if rod:
        refusal = rigid_grounded_across(scene)
        if refusal:
            return SolveResult.refused("bvp", scene, f"{scene.source}: {refusal}")
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

    # the in-plane geometry (the rod's plane's frame) for the checks before solving
    flat = in_plane_scene(scene)[0] if rod else xy_ends(scene)
    info["formulation"] = ("3d rod (10 states a block, in the plane of the ends)" if rod
                           else "planar (6 states a block)")
    hopeless = hopeless_span(flat)         # give up early: no equilibrium of these forms
    if hopeless:
        return result(Status.NO_EQUILIBRIUM, hopeless)
    split_tried = ""
    for split in (True, False):
        try:
            prob = (build_rod_problem(scene, split, dead_load) if rod
                    else build_problem(flat, split))
        except BVPFailure as exc:
            return result(Status.NO_EQUILIBRIUM if isinstance(exc, NoEquilibrium)
                          else Status.NOT_CONVERGED, str(exc))
        tau0 = prob.mesh(settings.initial_nodes)
        if rod:
            settings = _rod_node_cap(prob, settings, info)
        too_big = over_budget(prob.model.n_state, prob.guess_p.size, prob.mesh(0).size,
                              prob.model.n_seg, settings.max_nodes, settings.memory_budget)
        if too_big:
            return SolveResult.refused("bvp", scene, f"{scene.source}: bvp refused: {too_big}")
        early = hopeless_start(flat, prob, tau0)
        if early is not None and early[0] is Status.REFUSED:
            return SolveResult.refused("bvp", scene, f"{scene.source}: bvp refused: {early[1]}")
        if early is not None:
            return result(*early)
        sol, how, failure = solve_with_continuation(prob, tau0, settings, continuation)
        if prob.form == "fixed_liftoff" and sol is not None and good(sol, prob):
            # the contact zone must be in contact (y <= 0 up to 1 % of the sink depth w/k),
            # else solve the unilateral law everywhere
            why = _contact_zone_violation(prob, sol)
            if why:
                split_tried = f"contact zone + lift-off point: {why}; then "
                continue
        elif prob.form == "fixed_liftoff" and failure is Status.NOT_CONVERGED:
            # e.g. the lift-off point leaving the segment it was cut in: the unilateral
            # form, with its continuation in the seabed stiffness, does not assume where
            split_tried = f"contact zone + lift-off point: {how} (did not converge); then "
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
        state = None
        if rod:
            profile, checks, state = build_rod_profile(prob, sol, scene.water_depth)
        else:
            profile, checks = build_profile(prob, sol, scene.water_depth)
        if not rod and isinstance(scene.ends, FixedEnds):
            profile = profile.replace(z=np.full_like(profile.s, scene.ends.anchor_point[2]))
        if scene.internal_flow is not None:
            # steady flow: no term in the shape equations (T is Fylling's effective
            # tension), one in the wall tension (riser/physics/internal_flow.py)
            profile = profile.replace(wall_tension=wall_tension(scene, profile.s, profile.y,
                                                                profile.tension))
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
    out = result(Status.CONVERGED, message, profile)
    if state is not None:                # the rod's states, for a linearisation about them
        out = out.replace(solver_state=state)
    return out


def xy_ends(scene: Scene) -> Scene:
    """A planar scene with its fixed ends as (x, y): ends given as (x, y, z) in one plane
    z = const lose their z (the planar problem's; the profile gets it back)."""
    e = scene.ends
    if isinstance(e, FixedEnds) and (len(e.anchor) > 2 or len(e.hang_off) > 2):
        return scene.replace(ends=dataclasses.replace(e, anchor=e.anchor[:2],
                                                      hang_off=e.hang_off[:2]))
    return scene


def _rod_node_cap(prob: _Problem, settings, info: dict):
    """The rod's settings with [bvp] max_nodes lowered to what fits in [bvp]
    memory_budget (bvp/budget.py; the rod's 10 or 20 states cost (10/6)^2 to (20/6)^2 x
    a planar node), noted in ``info``; unchanged when it fits or when even the starting
    mesh would not (over_budget then refuses, naming the settings)."""
    per_node = peak_bytes(prob.model.n_state, prob.guess_p.size, 1)
    fits = int(settings.memory_budget * 1e9 / per_node)
    if fits >= settings.max_nodes or fits < 4 * prob.mesh(0).size:
        return settings
    info["max_nodes_capped"] = (f"[bvp] max_nodes {settings.max_nodes:,} lowered to {fits:,} "
                                f"for the 3D rod ({prob.model.n_state} states, "
                                f"{per_node / 1e3:.3g} kB a node) to stay within [bvp] "
                                f"memory_budget = {settings.memory_budget:g} GB")
    return settings.replace(max_nodes=fits)


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
    sink = max(float(np.max(m.w[m.zone_segs])), 0.0) / m.k_seabed
    if float(np.max(zone_y)) > 0.01 * sink + 1e-9:
        return f"the zone rises {float(np.max(zone_y)):.3g} m above the seabed"
    return ""

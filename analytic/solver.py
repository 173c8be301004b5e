"""The analytic method: catenary and boundary layers in closed form (microseconds to
milliseconds per solve), a third reference beside the BVP and the VFIFE.

Public entry: :func:`solve` (scene -> :class:`riser.results.result.SolveResult`).

Scope: one section along the whole line (every segment of the same weight, EI and EA),
no current (a catenary with drag has no closed form; refused), steady internal flow
(Fylling's effective tension: no term in the statics, the wall tension reported) but no
slug. End forms: ``tdp_tension``, ``hang_off_angle`` and ``top_tension`` (J-lay) on the
rigid seabed of the Wang forms; ``fixed`` with the anchor on the seabed (rigid or
elastic, the touchdown found), or free-hanging between pinned ends. The continuum model
is the scene's (``axial``: extensible or inextensible; ``seabed``: rigid or elastic).

Accuracy (analytic/layers.py): with eps = sqrt(EI / (H L^2)) (L the suspended length) and
delta = w lambda / H (the catenary's angle one layer length lambda = sqrt(EI/H) above the
touchdown), the composite solution is the catenary to O(eps^2) away from the ends and the
linearised layer to O(delta^2) relative in it; delta = eps w L / H. The catenary model alone
is O(1) wrong in the moment at the touchdown (its jump) and O(eps) in the shape.

Refused beyond the expansion (analytic/forms.py): a composite or piecewise line whose eps
exceeds ``forms.EPS_LIMIT`` or delta ``forms.DELTA_LIMIT`` (bending, not tension, shapes
it: e.g. a line of 1e-3 N/m with EI 1e7 N m2), and a weight below :data:`MIN_WEIGHT`. A
root search that fails for another reason ends ``not_converged`` with the place.
"""

from __future__ import annotations

import math
import sys
import time

import numpy as np

from riser.results import validity
from riser.errors import UnsupportedSceneError
from riser.model.frame import LinePlane
from riser.physics.internal_flow import wall_tension
from riser.results.result import SolveResult, Status
from riser.model.scene import FixedEnds, HangOffAngleEnds, Scene, TdpTensionEnds, TopTensionEnds
from riser.model.sections import segment_properties
from riser.model.settings import AnalyticSettings

from . import forms
from .composite import build
from .forms import Line, NoEquilibrium, RootNotFound, Unsupported
from .layers import layer_length

#: eps or delta above this gets a validity warning (the neglected terms are their squares)
VALIDITY_LIMIT = 0.1

#: the smallest submerged weight [N/m] the closed forms compute with: the smallest normal
#: float over the machine epsilon (~1e-292), so that w times a relative round-off is still
#: a normal number (below it a 350 m hang-off catenary came out half its length)
MIN_WEIGHT = sys.float_info.min / sys.float_info.epsilon


def effects_of(scene: Scene) -> list[str]:
    eff = ["weight", "bending"]
    if scene.axial_model == "extensible":
        eff.append("axial")
    if scene.seabed_model is not None:
        eff.append("seabed")
    if scene.internal_flow is not None:
        eff.append("internal_flow")
    return eff


def settings_of(scene: Scene) -> AnalyticSettings:
    return getattr(scene, "analytic", None) or AnalyticSettings()


def line_of(scene: Scene) -> Line:
    """The single section of ``scene``; raises UnsupportedSceneError for anything else."""
    src = scene.source
    plain = getattr(scene.ends, "plain", True)
    if not plain:
        raise UnsupportedSceneError(
            f"{src}: ends: the analytic method's catenary is pinned at both ends' positions "
            "(a joint, a tensioner or a free end has no closed form here): use --method bvp "
            "or --method vfife")
    if scene.attachments:
        raise UnsupportedSceneError(
            f"{src}: attachments: the analytic method's catenary has no point loads (a "
            "two-catenary closed form is a test, not a method here): use --method bvp or "
            "--method vfife")
    if scene.current is not None:
        raise UnsupportedSceneError(
            f"{src}: environment.current: the analytic method has no drag (a catenary under "
            "current drag has no closed form): use --method bvp or --method vfife")
    if scene.internal_flow is not None and scene.internal_flow.has_slug:
        raise UnsupportedSceneError(
            f"{src}: internal_flow.slug: the analytic method is static and has no travelling "
            "load: use --method vfife")
    props = segment_properties(scene)
    p0 = props[0]
    for i, p in enumerate(props[1:], start=1):
        if (p.weight, p.EI, p.EA) != (p0.weight, p0.EI, p0.EA):
            raise UnsupportedSceneError(
                f"{src}: segments[{i}]: the analytic method solves a single section, and "
                f"segment {i} differs from segment 0 in weight, EI or EA ({len(props)} "
                "segments, e.g. a lazy wave): use --method bvp or --method vfife")
    if not p0.weight > 0.0:
        raise UnsupportedSceneError(
            f"{src}: segments[0]: submerged weight {p0.weight:g} N/m; the analytic method "
            "needs a line that sinks (w > 0)")
    if p0.weight < MIN_WEIGHT:
        raise UnsupportedSceneError(
            f"{src}: segments[0]: submerged weight {p0.weight:g} N/m is below the "
            f"{MIN_WEIGHT:.3g} N/m the analytic method computes with: the closed forms' "
            "ratios of force and weight (H/w, w s/H) reach the floating-point underflow "
            "there and lose their digits")
    if not p0.EI > 0.0:
        raise UnsupportedSceneError(
            f"{src}: line_types.{scene.segments[0].line_type}.bending_stiffness: must be > 0 "
            "for the analytic method's boundary layers (a line without EI is the catenary)")
    EA = p0.EA if scene.axial_model == "extensible" else math.inf
    k = scene.seabed.stiffness if scene.seabed_model == "elastic" else None
    return Line(w=p0.weight, EI=p0.EI, EA=EA, length=scene.total_length, k=k)


def _outer(scene: Scene, line: Line, model: str):
    with_layer = model != "catenary"
    e = scene.ends
    if isinstance(e, TdpTensionEnds):
        return forms.tdp_tension(line, e.tdp_tension, with_layer)
    if isinstance(e, HangOffAngleEnds):
        return forms.hang_off_angle(line, e.hang_off_height, math.radians(e.hang_off_angle_deg),
                                    with_layer, top_layer=model == "composite")
    if isinstance(e, TopTensionEnds):
        # only the first segment's length is solved in the Wang forms: the whole line here
        return forms.top_tension(line, e.hang_off_height, e.top_tension, with_layer)
    # in the plane of the ends (a hang-off out of the anchor's plane: the same planar
    # problem over the horizontal distance, mapped back by :func:`_to_scene`)
    (xa, ya, za), (xh, yh, zh) = e.anchor_point, e.hang_off_point
    return forms.fixed(line, (xa, ya), (xa + math.hypot(xh - xa, zh - za), yh),
                       scene.seabed is not None, with_layer)


def _to_scene(scene: Scene, profile):
    """A profile solved in the plane of fixed ends (x along it from the anchor's x) put
    into the scene's axes: x, z rotated by the plane's heading; a 3D scene's profile gets
    its 3D columns (on its plane: no lateral offset, no out-of-plane moment, the in-plane
    moment the signed planar one)."""
    e = scene.ends
    if not isinstance(e, FixedEnds):
        return profile
    plane = LinePlane.of(scene)
    if plane.heading_deg == 0.0:                  # the x-y plane (shifted by z): x as solved
        profile = profile.replace(z=np.full_like(profile.s, e.anchor_point[2]))
    else:
        xi = profile.x - e.anchor_point[0]
        x, z = plane.from_plane(xi, np.zeros_like(xi))
        profile = profile.replace(x=x, z=z)
    if not scene.statics_planar:
        kappa = np.gradient(np.unwrap(profile.theta), profile.s)
        profile = profile.replace(
            lateral=np.zeros_like(profile.s),
            moment_in_plane=np.where(kappa < 0.0, -profile.moment, profile.moment),
            moment_out_of_plane=np.zeros_like(profile.s))
    return profile


def solve(scene: Scene) -> SolveResult:
    """Solve the static configuration of ``scene`` in closed form (module docstring).

    What the method cannot represent is ``refused`` before solving (the reason in the
    message); a form without equilibrium ends in ``no_equilibrium``."""
    try:
        return _solve(scene)
    except UnsupportedSceneError as exc:
        return SolveResult.refused("analytic", scene, exc)


def _solve(scene: Scene) -> SolveResult:
    """:func:`solve`, raising :class:`UnsupportedSceneError` for what it refuses."""
    t0 = time.perf_counter()
    settings = settings_of(scene)
    line = line_of(scene)
    model = settings.model
    effects = effects_of(scene)
    warnings: list[str] = []
    info: dict = {"analytic_model": model}
    if scene.dynamics is not None:
        warnings.append("ignored_input: the analytic method solves statics only: [dynamics] "
                        "ignored")
    if scene.seabed is not None and scene.seabed.friction > 0.0:
        warnings.append(f"ignored_input: the analytic seabed is frictionless: seabed.friction "
                        f"= {scene.seabed.friction:g} ignored")

    def result(status: Status, msg: str, profile=None) -> SolveResult:
        return SolveResult("analytic", scene.name, status, msg, profile,
                           time.perf_counter() - t0, effects, model=scene.continuum_model(),
                           warnings=warnings, info=info)

    try:
        outer = _outer(scene, line, model)
    except NoEquilibrium as exc:
        text = str(exc)
        return result(Status.NO_EQUILIBRIUM, text if text.startswith("no equilibrium")
                      else f"no equilibrium: {text}")
    except Unsupported as exc:
        raise UnsupportedSceneError(f"{scene.source}: {exc.key}: analytic refused: {exc}"
                                    ) from None
    except RootNotFound as exc:
        # not evidence that no equilibrium exists: the search failed, and says where
        return result(Status.NOT_CONVERGED, f"not converged: the analytic outer problem: "
                      f"{exc}; cross-check with --method bvp")
    threshold = None
    if model == "piecewise":
        if outer.kind != "touchdown":
            raise UnsupportedSceneError(
                f"{scene.source}: analytic.model: 'piecewise' joins a beam at the touchdown "
                "to the catenary above it, and this line has no touchdown: use 'composite'")
        kappa0 = line.w / outer.H
        threshold = settings.curvature_threshold or 0.5 * kappa0
        if threshold >= kappa0:
            raise UnsupportedSceneError(
                f"{scene.source}: analytic.curvature_threshold: must be < the catenary's "
                f"touchdown curvature w/H = {kappa0:.6g} 1/m, got {threshold:g}")
        info["curvature_threshold"] = threshold
    solved_first = isinstance(scene.ends, (HangOffAngleEnds, TopTensionEnds))
    total = outer.suspended if solved_first else line.length
    profile, extra = build(outer, line, model, total, threshold=threshold)
    profile = _to_scene(scene, profile)
    info.update(extra)
    if model == "piecewise" and extra["piecewise_s_E"] >= total:
        warnings.append(f"piecewise_threshold: curvature_threshold {threshold:g} 1/m is below "
                        "the catenary's curvature everywhere: the switch point E lies beyond "
                        "the hang-off, so no part of the line is the catenary")
    H = outer.H
    lam = layer_length(line.EI, H, line.EA)
    info.update({"horizontal_tension": H, "boundary_layer_length": lam,
                 "suspended_length": outer.suspended,
                 "epsilon": lam / outer.suspended, "delta": line.w * lam / H})
    if scene.internal_flow is not None:
        profile = profile.replace(wall_tension=wall_tension(scene, profile.s, profile.y,
                                                            profile.tension))
    bad = validity.nonfinite(profile)
    if bad:
        return result(Status.DIVERGED, bad)
    message = f"converged ({model}; closed form, H = {H:.6g} N)"
    lengths = [g.length for g in scene.segments]
    if solved_first:
        info["first_segment_suspended_length"] = outer.suspended
        message += f"; suspended length {outer.suspended:.3f} m"
        lengths = [outer.suspended]
    for name in ("epsilon", "delta"):
        if model != "catenary" and info[name] > VALIDITY_LIMIT:
            warnings.append(f"asymptotic_validity: {name} = {info[name]:.3g} > "
                            f"{VALIDITY_LIMIT:g}: the neglected terms are O({name}^2) of the "
                            "boundary-layer correction; cross-check with --method bvp")
    warnings.extend(validity.profile_warnings(scene, profile, lengths))
    return result(Status.CONVERGED, message, profile)

"""One way to run a method on a scene, used by every command and study.

:func:`solve_scene` solves a scene with one method. The VFIFE needs both ends fixed in
space; a scene in a Wang form (touchdown tension; hang-off height and angle; or, J-lay,
hang-off height and top tension) leaves the hang-off point as an output.
:func:`vfife_equivalent` is the one conversion every caller uses: the BVP solves the scene as given (its own model, inextensible on a rigid seabed by
default), the hang-off is fixed at that solution's top point, and ``[vfife]
seabed_length`` (300 m) of line is added to the first segment on an elastic seabed ahead
of that touchdown, so that the touchdown is free to move (``riser.model.transform``). That
fixed-ends scene is the model both methods solve (extensible, elastic seabed). Its arc
lengths are reported in the scene's own coordinate, from the BVP touchdown: the converted
scene's s minus the added length (negative s lies on the added line).

A VFIFE result of a converted scene says so: its message ends with the conversion note
(``info['ends_conversion']``), it carries the BVP's warnings of the solve the conversion
started from, and it warns (``ends_conversion: ...``) when its hang-off angle or a tension
the form gives departs from the scene's own model by more than :data:`ANGLE_DEPARTURE_DEG`
or :data:`TENSION_DEPARTURE` (it then solved a different problem). A result also ends with
the scene's own notes (``Scene.notes``: an anchor put on the seabed).
"""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass

from riser.results import validity
from riser.errors import SolveFailed, UnsupportedSceneError
from riser.results.profile import Profile
from riser.results.result import DynamicsResult, SolveResult, Status
from riser.model.scene import (
    FixedEnds,
    HangOffAngleEnds,
    Scene,
    TdpTensionEnds,
    TopTensionEnds,
)
from riser.model.transform import fixed_ends_scene
from riser.results.recorder import ARC_LENGTH_COLUMNS, ARC_LENGTH_KEYS
from verification.methods import method as method_of
from vfife.ends import require_vfife_model

#: [deg] a VFIFE hang-off angle this far from the BVP's of the scene's own model (the
#: given angle of form (b)) is warned: the conversion solved a different problem. The
#: conversion's model difference (stretch T/EA, the elastic seabed) moves the angle by at
#: most 0.006 deg on the built-in Wang scenes and 0.018 deg on Kang's J-lay (measured at
#: 2 m elements); the Wang riser's 11.12 deg from the vertical typed as 12 deg from the
#: horizontal moved it by 7.4 deg (and the hang-off tension by -64 %).
ANGLE_DEPARTURE_DEG = 0.5
#: a VFIFE hang-off tension (the given top tension of the J-lay form) or touchdown tension
#: (the given one of form (a)) this far (fraction) from the BVP's of the scene's own model
#: is warned; the model difference moves them by at most 0.1 % on the built-in scenes
#: (Wang: -0.097 % at the touchdown, -0.015 % at the top; Kang: -0.074 % at the top)
TENSION_DEPARTURE = 0.01


@dataclass(frozen=True)
class VfifeEquivalent:
    """The scene the VFIFE solves for a scene, and how to read its results back.

    scene : fixed-ends scene (the given scene when it already has fixed ends).
    s_shift : [m] to subtract from its arc lengths to get the given scene's s (the line
        added on the seabed; 0 for a fixed-ends scene).
    note : one sentence saying how the scene was converted ('' when it was not).
    paper : the BVP result of the given scene the conversion started from (None for
        fixed ends).
    seconds : wall time of the conversion [s] (the BVP solve).
    """

    scene: Scene
    s_shift: float = 0.0
    note: str = ""
    paper: SolveResult | None = None
    seconds: float = 0.0


def vfife_equivalent(scene: Scene, paper: SolveResult | None = None) -> VfifeEquivalent:
    """The fixed-ends equivalent of ``scene`` (see the module docstring). ``paper``: a
    converged BVP result of ``scene`` to start from (solved here when None). Raises
    :class:`UnsupportedSceneError` when the BVP refuses the scene (the VFIFE's conversion
    needs it) and :class:`SolveFailed` when it does not converge."""
    if isinstance(scene.ends, FixedEnds):
        return VfifeEquivalent(scene)
    t0 = time.perf_counter()
    if paper is None:
        paper = method_of("bvp").solve(scene)
    if paper.status is Status.REFUSED:        # the VFIFE refuses what the BVP refuses
        raise UnsupportedSceneError(paper.message)
    if not paper.converged:
        raise SolveFailed("bvp", paper.status, f"cannot convert {scene.name} to fixed ends: "
                          f"the BVP of its own model did not converge ({paper.message})")
    length = scene.vfife.seabed_length
    sm = paper.summary()
    top = (sm["hang_off_x"], sm["hang_off_height"])
    if sm["hang_off_z"] != 0.0:          # a current out of plane moved the top sideways
        top += (sm["hang_off_z"],)
    fixed = fixed_ends_scene(scene, top, length,
                             first_segment_length=sm["first_segment_suspended_length"])
    model = ", ".join(f"{k} {v}" for k, v in paper.model.items() if k != "seabed_stiffness")
    note = (f"{scene.ends.kind} ends converted to fixed ends from the BVP solution of the "
            f"scene's own model ({model}): hang-off fixed at that top point "
            f"({', '.join(f'{v:.3f}' for v in top)}) m, anchor at x = "
            f"{-length:g} m on a seabed of stiffness {fixed.seabed.stiffness:.3g} N/m2, i.e. "
            f"{length:g} m of line added to the first segment; arc lengths s are measured "
            f"from that BVP touchdown (the added line has s < 0)")
    return VfifeEquivalent(fixed, float(length), note, paper, time.perf_counter() - t0)


def shifted(profile: Profile | None, s_shift: float) -> Profile | None:
    """``profile`` with ``s_shift`` [m] subtracted from its arc lengths."""
    if profile is None or not s_shift:
        return profile
    return dataclasses.replace(profile, s=profile.s - s_shift,
                               tdp_s=None if profile.tdp_s is None else profile.tdp_s - s_shift)


def shifted_dynamics(dyn: DynamicsResult | None, s_shift: float) -> DynamicsResult | None:
    """``dyn`` with ``s_shift`` [m] subtracted from its arc lengths (envelope and states
    ``s``, the time series' ``touchdown_s``, ``min_tension_s`` and ``max_moment_s``)."""
    if dyn is None or not s_shift:
        return dyn
    ts = {k: v - s_shift if k in ARC_LENGTH_COLUMNS else v for k, v in dyn.timeseries.items()}
    env = {**dyn.envelope, "s": dyn.envelope["s"] - s_shift}
    states = None if dyn.states is None else {**dyn.states, "s": dyn.states["s"] - s_shift}
    return DynamicsResult(ts, env, states)


def solve_scene(scene: Scene, method: str, *, tolerance: float | None = None,
                element_length: float | None = None, progress=None) -> SolveResult:
    """Solve ``scene`` with ``method`` (a name of :data:`verification.methods.METHODS`: 'bvp',
    'vfife' or 'analytic', the closed form of a single-section line without current).
    ``tolerance`` applies to the BVP (solve_bvp tolerance), ``element_length`` [m] to the
    VFIFE; each overrides the scene's setting and is validated like it. A VFIFE run of a
    Wang-form scene solves its :func:`vfife_equivalent`, says so in
    ``info['ends_conversion']`` and reports arc lengths in the scene's own coordinate.

    A scene the method cannot represent gives a ``refused`` result; raises SceneError (bad
    input) and SolveFailed (the BVP a conversion needs did not converge); every other
    outcome is in the result's status. ``progress``: optional callable,
    ``progress(message)`` or ``progress(message, fraction=None)`` (see
    :mod:`verification.runtime.progress`); a method without a callback (the BVP's
    ``solve_bvp``) is said only when it starts."""
    m = method_of(method)
    given = {"tolerance": tolerance, "element_length": element_length}
    kwargs = {k: given[k] for k in m.overrides}
    if m.progress:
        kwargs["progress"] = progress
    elif progress is not None:
        progress(f"{method}: solving")
    solve = m.solve
    if not m.fixed_ends_only or isinstance(scene.ends, FixedEnds):
        return with_notes(solve(scene, **kwargs), scene)
    return with_notes(_solve_converted(scene, solve, kwargs, progress), scene)


def with_notes(res: SolveResult, scene: Scene) -> SolveResult:
    """``res`` with the scene's notes (``Scene.notes``: what the scene changed of its
    input) at the end of its message and in ``info['scene_notes']``."""
    if not scene.notes:
        return res
    return res.replace(message="; ".join((res.message, *scene.notes)),
                       info={**res.info, "scene_notes": list(scene.notes)})


def conversion_warnings(scene: Scene, eq: VfifeEquivalent, res: SolveResult) -> list[str]:
    """The warnings a VFIFE result of the converted ``scene`` adds to its own: those of the
    BVP solve the conversion started from (``eq.paper``; not ``ignored_input``, which names
    what the VFIFE models), and ``ends_conversion`` when the result's hang-off angle or the
    tension the form gives departs from that BVP solution (the scene's own model) by more
    than :data:`ANGLE_DEPARTURE_DEG` / :data:`TENSION_DEPARTURE`."""
    if eq.paper is None:
        return []
    # the BVP's ignored_input ([dynamics], seabed friction) is what the VFIFE does model
    out = [f"{w} (in the BVP solution of the scene's own model that the conversion to fixed "
           "ends started from)" for w in eq.paper.warnings if not w.startswith("ignored_input")]
    if not res.converged or res.profile is None:
        return out
    bvp_sm, sm = eq.paper.summary(), res.summary()
    e = scene.ends
    given = {HangOffAngleEnds: "the given hang-off angle", TopTensionEnds:
             "the given top tension", TdpTensionEnds: "the given touchdown tension"}[type(e)]
    departs = []
    d_angle = sm["hang_off_angle_deg"] - bvp_sm["hang_off_angle_deg"]
    if abs(d_angle) > ANGLE_DEPARTURE_DEG:
        departs.append(f"hang-off angle {sm['hang_off_angle_deg']:.3f} deg against "
                       f"{bvp_sm['hang_off_angle_deg']:.3f} deg ({d_angle:+.3f} deg, beyond "
                       f"{ANGLE_DEPARTURE_DEG:g} deg)")
    tensions = [("hang-off tension", "hang_off_tension")]
    if isinstance(e, TdpTensionEnds):
        tensions.append(("touchdown tension", "tdp_tension"))
    for label, key in tensions:
        ref, got = bvp_sm.get(key), sm.get(key)
        if ref is None:
            continue
        if got is None:
            departs.append(f"no {label} (no touchdown found) against {ref / 1e3:.2f} kN")
            continue
        rel = (got - ref) / abs(ref)
        if abs(rel) > TENSION_DEPARTURE:
            departs.append(f"{label} {got / 1e3:.2f} kN against {ref / 1e3:.2f} kN "
                           f"({100 * rel:+.2f} %, beyond {100 * TENSION_DEPARTURE:g} %)")
    if departs:
        model = ", ".join(f"{k} {v}" for k, v in eq.paper.model.items()
                          if k != "seabed_stiffness")
        out.append(f"ends_conversion: the VFIFE solved the fixed-ends equivalent (extensible, "
                   f"on an elastic seabed), which departs from the BVP solution of the "
                   f"scene's own {scene.ends.kind} form ({model}; {given} is "
                   f"{_given_value(e)}): {'; '.join(departs)}: it solved a different "
                   "problem; check the ends (a first_segment_length warning points at the "
                   "hang-off angle) and read the BVP result")
    return out


def _given_value(ends) -> str:
    """The value a touchdown form gives, as a warning says it."""
    if isinstance(ends, HangOffAngleEnds):
        return f"{ends.hang_off_angle_deg:g} deg from the horizontal"
    if isinstance(ends, TopTensionEnds):
        return f"{ends.top_tension / 1e3:g} kN"
    return f"{ends.tdp_tension / 1e3:g} kN"


def _solve_converted(scene: Scene, solve, kwargs: dict, progress) -> SolveResult:
    """The VFIFE (the fixed-ends-only method) on a touchdown-form ``scene``: refused before
    the conversion's BVP solve where it would be refused after, then solved on
    :func:`vfife_equivalent` and reported in the scene's own arc length."""
    validity.check_resolution(scene, scene.vfife.override(
        element_length=kwargs.get("element_length")).element_length)
    try:
        require_vfife_model(scene)
        if progress is not None:
            progress("bvp: solving the scene's own model for the conversion to fixed ends")
        eq = vfife_equivalent(scene)
    except UnsupportedSceneError as exc:
        return SolveResult.refused("vfife", scene, exc)
    res = solve(eq.scene, **kwargs)
    info = {**res.info, "ends_conversion": eq.note}
    for key in ARC_LENGTH_KEYS:
        if isinstance(info.get(key), list):          # the stations' arc lengths
            info[key] = [v - eq.s_shift for v in info[key]]
        elif info.get(key) is not None:
            info[key] -= eq.s_shift
    warnings = [*res.warnings, *conversion_warnings(scene, eq, res)]
    return res.replace(scene=scene.name, profile=shifted(res.profile, eq.s_shift),
                       dynamics=shifted_dynamics(res.dynamics, eq.s_shift), info=info,
                       warnings=warnings, message=f"{res.message}; {eq.note}")

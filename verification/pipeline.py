"""One way to run a method on a scene, used by every command and study.

:func:`solve_scene` solves a scene with one method. The VFIFE needs both ends fixed in
space; a scene in a Wang form (touchdown tension; hang-off height and angle; or, J-lay,
hang-off height and top tension) leaves the hang-off point as an output.
:func:`vfife_equivalent` is the one conversion every caller uses: the BVP solves the scene as given (its own model, inextensible on a rigid seabed by
default), the hang-off is fixed at that solution's top point, and ``[vfife]
seabed_length`` (300 m) of line is added to the first segment on an elastic seabed ahead
of that touchdown, so that the touchdown is free to move (``riser.transform``). That
fixed-ends scene is the model both methods solve (extensible, elastic seabed). Its arc
lengths are reported in the scene's own coordinate, from the BVP touchdown: the converted
scene's s minus the added length (negative s lies on the added line).
"""

from __future__ import annotations

import dataclasses
import importlib
import time
from dataclasses import dataclass

import bvp
from riser import validity
from riser.errors import SolveFailed, UnsupportedSceneError
from riser.profile import Profile
from riser.result import METHODS, DynamicsResult, SolveResult, Status
from riser.scene import FixedEnds, Scene
from riser.transform import fixed_ends_scene
from vfife.dynamic_outputs import ARC_LENGTH_COLUMNS, ARC_LENGTH_KEYS
from vfife.ends import require_vfife_model


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
        paper = bvp.solve(scene)
    if paper.status is Status.REFUSED:        # the VFIFE refuses what the BVP refuses
        raise UnsupportedSceneError(paper.message)
    if not paper.converged:
        raise SolveFailed("bvp", paper.status, f"cannot convert {scene.name} to fixed ends: "
                          f"the BVP of its own model did not converge ({paper.message})")
    length = scene.vfife.seabed_length
    sm = paper.summary()
    fixed = fixed_ends_scene(scene, (sm["hang_off_x"], sm["hang_off_height"]), length,
                             first_segment_length=sm["first_segment_suspended_length"])
    model = ", ".join(f"{k} {v}" for k, v in paper.model.items() if k != "seabed_stiffness")
    note = (f"{scene.ends.kind} ends converted to fixed ends from the BVP solution of the "
            f"scene's own model ({model}): hang-off fixed at that top point "
            f"({sm['hang_off_x']:.3f}, {sm['hang_off_height']:.3f}) m, anchor at x = "
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
    """Solve ``scene`` with ``method`` (a name of :data:`riser.result.METHODS`: 'bvp',
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
    m = METHODS.get(method)
    if m is None:
        raise ValueError(f"method must be one of {tuple(METHODS)}, got {method!r}")
    given = {"tolerance": tolerance, "element_length": element_length}
    kwargs = {k: given[k] for k in m.overrides}
    if m.progress:
        kwargs["progress"] = progress
    elif progress is not None:
        progress(f"{method}: solving")
    solve = importlib.import_module(m.package).solve
    if not m.fixed_ends_only or isinstance(scene.ends, FixedEnds):
        return solve(scene, **kwargs)
    return _solve_converted(scene, solve, kwargs, progress)


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
        if info.get(key) is not None:
            info[key] -= eq.s_shift
    return res.replace(scene=scene.name, profile=shifted(res.profile, eq.s_shift),
                       dynamics=shifted_dynamics(res.dynamics, eq.s_shift), info=info)

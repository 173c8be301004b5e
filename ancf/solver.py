"""Public entry point: :func:`solve` a fixed-ends scene with the ANCF method."""

from __future__ import annotations

import time

import numpy as np

from riser.errors import UnsupportedSceneError
from riser.model.scene import Scene
from riser.results import validity
from riser.results.result import DynamicsResult, SolveResult, Status

from .ends import require_ancf_ends
from .mesh import build_mesh
from .dynamics.run import run_dynamics
from .model import Model
from .output import make_profile
from .statics.newton import solve_statics
from .statics.start import catenary_start, needs_straight_start, straight_start


def dimension(scene: Scene, dead_load=None) -> int:
    """2 for a scene that stays in the x-y plane (statics and dynamics, no dead load along
    z), else 3: a planar scene stays planar."""
    out = not scene.is_planar or (dead_load is not None and dead_load[2] != 0.0)
    return 3 if out else 2


def require_ancf(scene: Scene) -> None:
    """Raise :class:`UnsupportedSceneError` for what the ANCF does not represent: the ends
    (:func:`ancf.ends.require_ancf_ends`) and, for now, the point attachments' wave loads
    (not modelled, as in the VFIFE). Internal flow is modelled (ancf/flow.py: a steady flow
    changes no static effective tension, Fylling; a slug is frozen at t = 0 in statics,
    moving along the line in the time domain)."""
    require_ancf_ends(scene)
    if scene.attachments and scene.waves is not None and scene.waves.line_loads:
        raise UnsupportedSceneError(
            f"{scene.name}: attachments: the wave loads on a point attachment are not "
            "modelled; remove the waves or the attachments")


def static_state(scene: Scene, *, element_length: float | None = None,
                 tolerance: float | None = None, progress=None, dead_load=None):
    """(model, q, outcome, info) of the static equilibrium (no refusal checks)."""
    st = scene.ancf.override(element_length=element_length, static_tolerance=tolerance)
    d = dimension(scene, dead_load)
    mesh = build_mesh(scene, st.element_length)

    def start(mesh):
        if needs_straight_start(scene):
            return (*straight_start(scene, mesh, d), 0.0)
        return catenary_start(scene, mesh, d)

    q0, T0, misfit = start(mesh)
    ends = held_end_lengths(scene, mesh, T0, st.element_length)
    if ends != (None, None):            # graded to a held end's bending layer
        mesh = build_mesh(scene, st.element_length, ends)
        q0, T0, misfit = start(mesh)
    model = Model(scene, mesh, d, current=True, dead_load=dead_load)
    q0 = q0.copy()
    for node, R in model.ends.rotations.items():   # a clamp's slope along its direction
        a = q0[node, d:]
        q0[node, d:] = float(np.linalg.norm(a)) * R[:, 0]
    if progress is not None:
        progress(f"ancf: Newton statics on {mesh.ne} elements of {float(np.max(mesh.l0)):.3g} m")
    q, outcome = solve_statics(model, q0.ravel(), st.static_tolerance, st.max_iterations,
                               progress)
    info = {"elements": mesh.ne, "nodes": mesh.n, "element_length": float(np.max(mesh.l0)),
            "unknowns": model.N, "dimension": d, "gauss_points": st.gauss_points,
            "newton_iterations": outcome.iterations, "load_steps": outcome.steps,
            # the largest nodal out-of-balance force / the load scale (ancf/statics/newton.py)
            "force_residual": outcome.residual, "tolerance": st.static_tolerance,
            "start_misfit_m": misfit}
    return model, q, outcome, info


#: the first element at an end that holds its rotation (a clamp or a flex joint), as a
#: fraction of the bending length sqrt(EI/T) there (the start's tension), when shorter
#: than the element length: the moment's boundary layer lies within a few of them.
#: MEASURED on a flexible riser on a flex joint (EI 1e5 N m2, lambda 0.84 m): at uniform
#: 2 m elements the joint's moment was 3.5 % off the BVP's (the moment along s 12 %)
HELD_END_FRACTION = 0.25


def held_end_lengths(scene: Scene, mesh, T0, h: float) -> tuple:
    """(anchor, hang-off) first element lengths [m] for the ends that hold their rotation
    and whose bending length is short against ``h`` (None: no grading)."""
    e = scene.ends
    out = []
    for end, i, el in (("anchor", 0, 0), ("hang_off", -1, -1)):
        joint = e.joint(end)
        if joint is None or not joint.holds_rotation:
            out.append(None)
            continue
        lam = float(np.sqrt(mesh.EI[el] / max(abs(float(T0[i])), 1e-9)))
        out.append(HELD_END_FRACTION * lam if HELD_END_FRACTION * lam < h else None)
    return tuple(out)


def solve(scene: Scene, *, element_length: float | None = None, tolerance: float | None = None,
          progress=None, dead_load=None, observers=()) -> SolveResult:
    """Solve a fixed-ends scene (statics; the time domain of [dynamics] follows in
    :mod:`ancf.dynamics.run`).

    element_length [m]: default ``[ancf] element_length``; tolerance: the Newton statics'
    stopping rule (``[ancf] static_tolerance``, ancf/statics/newton.py); progress: optional
    ``progress(message)``; dead_load: optional (qx, qy, qz) [N/m] of fixed direction added
    to the weight (closed-form checks). A scene the method does not represent is refused
    before solving; a failed solve has a status other than converged with the reason."""
    try:
        require_ancf(scene)
        if scene.dynamics is not None:
            require_ancf_dynamics(scene)
    except UnsupportedSceneError as exc:
        return SolveResult.refused("ancf", scene, exc)
    h = scene.ancf.override(element_length=element_length).element_length
    validity.check_resolution(scene, h, key="ancf.element_length")
    validity.check_end_loads(scene)
    t0 = time.perf_counter()
    model, q, outcome, info = static_state(scene, element_length=element_length,
                                           tolerance=tolerance, progress=progress,
                                           dead_load=dead_load)
    warnings: list[str] = []

    def result(status: Status, message: str, profile=None, **fields) -> SolveResult:
        return SolveResult("ancf", scene.name, status, message, profile,
                           time.perf_counter() - t0, model.effects,
                           model=scene.continuum_model(), warnings=warnings, info=info,
                           **fields)

    if not outcome.converged or not np.all(np.isfinite(q)):
        why = outcome.message or (f"Newton statics did not converge: residual "
                                  f"{outcome.residual:.3g} x the load scale (tolerance "
                                  f"{info['tolerance']:g}) after {outcome.iterations} "
                                  "iterations; raise [ancf] max_iterations or check the "
                                  "geometry")
        finite = np.all(np.isfinite(q)) and np.isfinite(outcome.residual)
        return result(Status.NOT_CONVERGED if finite else Status.DIVERGED, why)
    profile = make_profile(model, q)
    bad = validity.nonfinite(profile)
    if bad:
        return result(Status.DIVERGED, bad)
    warnings.extend(resolution_warnings(model, profile))
    warnings.extend(validity.profile_warnings(scene, profile))
    message = (f"static equilibrium: residual {outcome.residual:.2g} x the load scale after "
               f"{outcome.iterations} Newton iterations")
    if scene.dynamics is None:
        return result(Status.CONVERGED, message, profile, solver_state=(model, q))
    dinfo = run_dynamics(scene, model, q, progress, observers=observers)
    simulated = dinfo["steps"] * dinfo["time_step"]
    info.update({"dynamic_time_step": dinfo["time_step"], "dynamic_steps": dinfo["steps"],
                 "dynamic_wall_s": dinfo["wall_s"], "integrator": dinfo["integrator"],
                 "realtime_factor": simulated / dinfo["wall_s"] if dinfo["wall_s"] > 0
                 else float("inf"),
                 "newton_iterations_per_step": dinfo["newton_iterations"],
                 "step_halvings": dinfo["halvings"], "ramp_time": dinfo["ramp_time"]})
    effects = dinfo["effects"]
    if not dinfo["ok"]:
        return result(Status.DIVERGED, dinfo["message"]).replace(effects=effects)
    message += (f"; {dinfo['message']} ({dinfo['steps']} steps of {dinfo['time_step']:.3g} s, "
                f"{dinfo['newton_iterations']:.2f} Newton iterations a step)")
    env = dinfo["envelope"]
    warnings.extend(validity.dynamic_warnings(scene, env))
    info.update(dinfo["statistics"])
    if dinfo["states"] is not None:
        info["states_file"] = ("states.npz (t (k,), s (n,), x (k, n, 3), v (k, n, 3), "
                               "tension (k, n), moment (k, n))")
    return result(Status.CONVERGED, message, profile, solver_state=(model, q),
                  dynamics=DynamicsResult(dinfo["timeseries"], env, dinfo["states"], None)
                  ).replace(effects=effects)


def require_ancf_dynamics(scene: Scene) -> None:
    """Refuse the dynamics the ANCF's time domain does not model: nothing at present (the
    internal flow, steady or slug, is ancf/flow.py's; the refusals of :func:`require_ancf`
    hold for the dynamics too)."""
    return None


def resolution_warnings(model: Model, profile) -> list[str]:
    """A warning when the elements are long against the shortest bending length
    sqrt(EI/T) of the solved line (a cubic element resolves a boundary layer of about its
    own length; the convergence study of tests/test_ancf_closed_forms.py)."""
    mesh = model.mesh
    h = float(np.max(mesh.l0))
    T = np.abs(profile.tension)
    EI = mesh.EI[np.clip(np.searchsorted(mesh.s, profile.s, side="right") - 1, 0,
                         mesh.ne - 1)]
    lam = float(np.min(np.sqrt(EI / np.maximum(T, 1e-9))))
    if h > lam:
        return [f"resolution: element length {h:g} m is long compared with the bending "
                f"length sqrt(EI/T) = {lam:.3g} m (use <= {lam:.2g} m for the moment peaks)"]
    return []

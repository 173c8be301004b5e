"""Running the cost study: each setting solved and timed (:func:`run_setting`), the
progress line, the whole study (:func:`study`) and one unit of ``reproduce cost``
(:func:`run_unit`)."""

from __future__ import annotations

import time
from pathlib import Path

from riser.results.profile import summarize
from riser.model.scene import Dynamics, Scene, TopMotion
from verification.catalog import resolve
from verification.methods import method
from verification.pipeline import vfife_equivalent
from verification.quantities import raw_values, reference_depth
from verification.runtime.progress import RunCounter
from vfife.dynamics.run import DynamicsOutcome, run_dynamics
from vfife.solver import compile_seconds

from . import dynamics as dyn
from . import dynamics_ancf as dyn_ancf
from .analysis import analyse, cost_scaling
from .dynamics_analysis import analyse as analyse_dynamics
from .dynamics_ancf_analysis import analyse as analyse_ancf
from .errors import densified, distance, rel_errors
from .records import CostStudy, Run
from .report import write
from .settings import Setting, default_settings, predicted_cost
from .touchdown import asymptotic_length

#: runs longer than this [s] are timed once: the median of several guards against the
#: jitter of short runs, which is a small fraction of a long one
REPEAT_BELOW_S = 2.0
#: simulated time of each dynamics run [s]
DYNAMICS_DURATION = 1.0
#: BVP first (its finest tolerance is the reference, whose touchdown sets the order sweep),
#: then the VFIFE statics, then the dynamics (from the statics' states)
METHOD_ORDER = {"bvp": 0, "vfife": 1, "vfife-dyn": 2}


def _solve(s: Setting, scene: Scene):
    if s.method == "bvp":
        return method("bvp").solve(scene, **s.solve_kwargs)
    sc = scene.replace(vfife=scene.vfife.replace(**s.vfife_changes)) if s.vfife_changes \
        else scene
    return method("vfife").solve(sc, **s.solve_kwargs)


def _dynamics_time(s: Setting, scene: Scene, repeats: int, static_cache: dict):
    """Wall time [s] of ``DYNAMICS_DURATION`` s of heave (1 m, 10 s, ramped in over the run:
    the default ramp, one period, would be longer than the run) from the static state of
    the same mesh (the static solve is not timed here). Returns (times, steps, msg,
    whether every timed run completed)."""
    h = s.solve_kwargs["element_length"]
    res = static_cache.get(h)
    if res is None or not res.converged:
        return [], None, "no converged static state", False
    dyn = Dynamics(duration=DYNAMICS_DURATION, output_interval=DYNAMICS_DURATION / 2,
                   top_motion=TopMotion(axis="y", amplitude=1.0, period=10.0,
                                        ramp_time=DYNAMICS_DURATION))
    sc = scene.replace(dynamics=dyn)
    times, steps, msg, ok = [], None, "", True
    for _ in range(repeats):
        t0 = time.perf_counter()
        _, info = run_dynamics(sc, res.solver_state, bool(sc.is_planar))
        times.append(time.perf_counter() - t0)
        steps, msg = info["steps"], info["message"]
        ok = ok and info["status"] is DynamicsOutcome.OK
        if not ok or times[-1] > REPEAT_BELOW_S:
            break
    return times, steps, msg, ok


def run_setting(s: Setting, scene: Scene, repeats: int, compile_s: float,
                static_cache: dict) -> Run:
    """Solve ``s`` on ``scene`` and time it (see :data:`REPEAT_BELOW_S`); a converged VFIFE
    ``element_length`` result goes into ``static_cache`` for the dynamics runs."""
    run = Run(s)
    if s.method == "vfife-dyn":
        run.times, run.steps, run.message, ok = _dynamics_time(s, scene, repeats,
                                                                 static_cache)
        run.converged = bool(run.times) and ok
        run.compile_time_s = compile_s
        run.size = static_cache[s.value].info["elements"] if s.value in static_cache \
            else None
        return run
    for i in range(repeats):
        try:
            res = _solve(s, scene)
        except (RuntimeError, ValueError, FloatingPointError) as exc:
            run.converged, run.message = False, f"{type(exc).__name__}: {exc}"
            break
        run.times.append(res.wall_time_s)
        if i == 0:
            run.converged, run.message = res.converged, res.message
            run.size = res.info.get("nodes" if s.method == "bvp" else "elements")
            run.steps = res.info.get("steps")
            run.profile = res.profile if res.converged else None
            if s.method == "vfife" and s.setting == "element_length":
                static_cache[s.value] = res
        if not res.converged or res.wall_time_s > REPEAT_BELOW_S:
            break
    if s.method == "vfife":
        run.compile_time_s = compile_s
    return run


def study(scene: Scene, *, repeats: int = 3, quick: bool = False, element_lengths=None,
          settings: list[Setting] | None = None, progress=None,
          full: bool = False, dynamics=None, ancf=None) -> CostStudy:
    """Run the study on ``scene`` (see :mod:`verification.studies.cost`): ``settings`` (default
    :func:`~verification.studies.cost.settings.default_settings` of ``quick``, ``element_lengths``
    and ``full``, the order sweep planned from the reference's asymptotic length),
    each timed as the median of up to ``repeats`` runs; ``progress``: a callable
    ``progress(message, fraction=None)`` told of each finished run, ``k/N runs`` with the
    share of the predicted cost done (:class:`verification.runtime.progress.RunCounter`;
    a :class:`~verification.runtime.progress.Progress` draws it), None or False: quiet.
    ``dynamics``: the dynamic sweep (:mod:`verification.studies.cost.dynamics`); None: the
    default of the sweep (fast, full or quick; none with given ``settings``), False: none,
    or (element length, step factor) pairs. ``ancf``: the ANCF's dynamic sweep beside it
    (:mod:`verification.studies.cost.dynamics_ancf`), judged with it against a common
    reference; None: the sweep's default when the VFIFE's runs by default, else none;
    False: none; or (element length, steps per period) pairs."""
    t_start = time.perf_counter()
    repeats = max(1, int(repeats))
    notes = []
    compile_s = compile_seconds()     # warms up on the first call
    eq = vfife_equivalent(scene)
    fixed = eq.scene
    if eq.paper is not None:
        notes.append(f"Both methods solve the fixed-ends equivalent of the scene ({eq.note}; "
                     f"the seabed is a property of the soil, the same for every run of both "
                     f"methods; conversion {eq.seconds:.2f} s, in no run's time).")
    sweep = "given" if settings is not None else "quick" if quick else "full" if full \
        else "fast"
    dyn_settings = _dynamic_plan(fixed, sweep, dynamics, element_lengths)
    ancf_settings = _ancf_plan(fixed, sweep, dynamics, ancf)
    runs, ref, dyn_runs, static_s, sweep_s, ancf_runs, ancf_s = _solve_all(
        scene, fixed, settings, (quick, element_lengths, full), repeats, compile_s,
        progress or None, dyn_settings, ancf_settings)
    ref_sm = summarize(ref.profile)
    depth = reference_depth(fixed, ref_sm)
    ref_values = raw_values(ref.profile)
    dense = densified(ref.profile)
    for r in runs:
        if r.profile is None:
            continue
        r.values = raw_values(r.profile, ref_sm)
        r.errors = rel_errors(r.values, ref_values, depth)
        r.errors["curve_distance"] = distance(dense, r.profile, depth)
    st = CostStudy(scene, fixed, depth, repeats, runs, ref, ref_values, notes=notes,
                   sweep=sweep)
    if dyn_settings:
        st.dynamics = dyn.DynStudy(dyn_runs, fixed.vfife.time_step_safety,
                                   sweep if dynamics is None else "given",
                                   dyn.surface_piercing(fixed), static_s, elapsed_s=sweep_s)
        analyse_dynamics(st.dynamics)
    if ancf_settings:
        st.ancf_dynamics = dyn_ancf.AncfStudy(
            ancf_runs, sweep if ancf is None else "given", elapsed_s=ancf_s[0],
            warm_up_s=ancf_s[1])
        analyse_ancf(st.ancf_dynamics, st.dynamics)
    if eq.paper is not None:
        psm = eq.paper.summary()
        st.paper_difference = {q: (psm[q] - ref_sm[q]) / abs(ref_sm[q])
                               for q in ("hang_off_tension", "max_moment")}
    analyse(st)
    cost_scaling(st)
    st.elapsed_s = time.perf_counter() - t_start
    return st


def _dynamic_plan(fixed: Scene, sweep: str, dynamics, element_lengths=None) -> list:
    """The dynamic runs of the study (see :func:`study`'s ``dynamics``; given
    ``element_lengths`` replace the sweep's lengths)."""
    if dynamics is None:
        return [] if sweep == "given" else dyn.dynamic_settings(fixed, sweep,
                                                                  element_lengths)
    if dynamics is False:
        return []
    return [s if isinstance(s, dyn.DynSetting) else dyn.DynSetting(*map(float, s))
            for s in dynamics]


def _ancf_plan(fixed: Scene, sweep: str, dynamics, ancf) -> list:
    """The ANCF's dynamic runs (see :func:`study`'s ``ancf``)."""
    if ancf is None:
        default = dynamics is None and sweep != "given"
        return dyn_ancf.ancf_settings(fixed, sweep) if default else []
    if ancf is False:
        return []
    return [s if isinstance(s, dyn_ancf.AncfSetting) else dyn_ancf.AncfSetting(
        float(s[0]), int(s[1])) for s in ancf]


def _solve_all(scene: Scene, fixed: Scene, settings, plan: tuple, repeats: int,
               compile_s: float, progress, dyn_settings=(), ancf_settings=()) -> tuple:
    """Every setting solved on ``fixed`` (BVP first); without given ``settings`` the VFIFE
    ones are planned once the reference is known, from ``plan`` = (quick,
    element_lengths, full) of :func:`default_settings`; then the dynamic runs
    ``dyn_settings`` from the static states, and the ANCF's ``ancf_settings``. Returns
    (runs, reference, dynamic runs, the seconds of statics solved for the dynamics only
    (element length -> s), the wall time of the dynamic sweep [s], the ANCF's runs, (the
    wall time of its sweep [s], of its warm-up within it [s]))."""
    given = settings is not None
    quick, element_lengths, full = plan
    if settings is None:
        settings = default_settings(fixed, quick, element_lengths, full=full)
    settings = sorted(settings, key=lambda s: METHOD_ORDER[s.method])
    dyn_weights = [dyn.predicted_cost(fixed, s) for s in dyn_settings] + [
        dyn_ancf.predicted_cost(fixed, s) for s in ancf_settings]
    prog = RunCounter([predicted_cost(s) for s in settings] + dyn_weights, progress) \
        if progress is not None else None
    runs: list[Run] = []
    static_cache: dict = {}
    ref = None
    i = 0
    while i < len(settings):
        s = settings[i]
        if s.method != "bvp" and ref is None:
            ref = _reference(runs, scene)
            if not given:
                asym = asymptotic_length(fixed, ref.profile)
                settings = settings[:i] + [t for t in default_settings(
                    fixed, quick, element_lengths, asym, full) if t.method != "bvp"]
                if prog:
                    prog.plan([predicted_cost(t) for t in settings[i:]] + dyn_weights)
                s = settings[i]
        run = run_setting(s, fixed, repeats, compile_s, static_cache)
        runs.append(run)
        if prog:
            prog.step(f"{run.method} {s.setting}={s.value:g}: "
                      f"{run.wall_time_s:.3g} s" + ("" if run.converged else ", not converged"))
        i += 1
    ref = ref or _reference(runs, scene)
    dyn_runs, static_s, t_dyn = [], {}, time.perf_counter()
    for s in dyn_settings:
        r = dyn.run_dynamic(s, fixed, repeats, static_cache, static_s, REPEAT_BELOW_S)
        dyn_runs.append(r)
        if prog:
            prog.step(f"vfife dynamics {s.element_length:g} m, factor {s.factor:g}: "
                      f"{r.wall_s:.3g} s" + ("" if r.converged else ", failed"))
    t_ancf = time.perf_counter()
    sweep_s = t_ancf - t_dyn
    ancf_runs = []
    warm_s = dyn_ancf.warm_up(fixed, ancf_settings[0]) if ancf_settings else 0.0
    for s in ancf_settings:
        if ancf_runs and ancf_runs[-1].refused:       # the scene, not the run: said once
            break
        r = dyn_ancf.run_ancf(s, fixed, repeats, REPEAT_BELOW_S)
        ancf_runs.append(r)
        if prog:
            prog.step(f"ancf dynamics {s.element_length:g} m, {s.steps_per_period} a "
                      f"period: {r.wall_s:.3g} s" + ("" if r.converged else ", failed"))
    return (runs, ref, dyn_runs, static_s, sweep_s, ancf_runs,
            (time.perf_counter() - t_ancf, warm_s))


def _reference(runs: list, scene: Scene) -> Run:
    """The finest converged BVP tolerance."""
    bvp_tol = [r for r in runs if r.setting.method == "bvp" and r.setting.setting == "tolerance"
               and r.converged]
    if not bvp_tol:
        raise RuntimeError(f"no BVP run converged on {scene.name}: no reference")
    return min(bvp_tol, key=lambda r: r.setting.value)


def run_unit(scene_name: str, out: Path, note: str = "", full: bool = False) -> str:
    """The study of one built-in scene into ``out/scene_name`` (``note``: a sentence on
    the timings, added to the report's notes; ``full``: the full sweep, ``--full``);
    returns the log line."""
    st = study(resolve(scene_name), full=full)     # reproduce shows its own progress
    if note:
        st.notes.append(note)
    write(st, out / scene_name)
    return f"cost {scene_name}: wrote {out / scene_name}/ in {st.elapsed_s:.0f} s"

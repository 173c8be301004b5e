"""The VFIFE against the ANCF on a scene's own ``[dynamics]`` (``riser-verify compare SCENE
--time-domain``): both methods get the identical Scene (the same ramp, record, waves,
irregular sea realisation and vessel) with ``save_states`` on, and are compared over the
statistics window.

Compared quantities (:func:`measures`; SI units, s from the bottom end; a time series is
compared by the rms of its difference over the window, an envelope along s by the rms of
its difference on a common grid of the VFIFE's element length):
- the hang-off tension [N]: its time series, maximum and minimum;
- at each station (:mod:`.stations`): the time series of the effective tension [N], the
  bending moment [N m] and the curvature (moment / EI) [1/m], the tension's extremes and
  the moment's and curvature's maxima;
- the envelopes along s: minimum and maximum tension, maximum moment and curvature, and
  their extremes over the line; the touchdown's travel (its least and largest s [m]);
- a periodic drive (a harmonic top motion, or one regular wave train): the first-harmonic
  amplitudes of the hang-off tension and of the tension and moment at the stations;
- with ``[design.fatigue]``: the rainflow fatigue damage along s (the envelopes'
  ``fatigue_damage``), its largest value and its value at the stations.

Tolerances (:mod:`.tolerances`): each quantity at three levels of each method's element
length (4x, 2x, 1x its default: coarsened to reach the default) and time step. The ANCF's
implicit step is coarsened the same way (4x, 2x, 1x its default, the excitation's period /
steps_per_period) where it can be: its step is an exact divisor of the sampling interval
and never longer, so when the coarsened levels cannot differ (the default step is already
the sampling interval) it is refined instead, at 1x, 1/2 and 1/4 of its default step
(the default the coarsest level: Richardson from it). The VFIFE's explicit step cannot be coarsened (it runs at
``time_step_safety`` 0.8 of its critical step, which is proportional to the element length):
its levels are taken on its coarsest mesh (4x), at safety 0.8, 0.4 and 0.2 of that mesh's
critical step, i.e. 4x, 2x and 1x its default step (:func:`levels_plan`).

Negative controls (:data:`PERTURBATIONS`): the ANCF's scene alone with a drag coefficient,
the added mass coefficient or the seabed stiffness 5 % higher; compared with the same
tolerances, a control must fail.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from riser.errors import SceneError, SolveFailed
from riser.model.sections import segment_properties
from verification.methods import method

from .. import harmonics
from . import stations as stations_mod
from .tolerances import Estimate, Tolerance, combine, estimate

#: the three levels of each discretisation parameter, times the default (coarse to fine)
LEVELS = (4.0, 2.0, 1.0)
#: the negative controls: name -> (what, the scene keys of the ANCF's scene to scale)
PERTURBATIONS = {"drag": "drag coefficients (normal and tangential) +5 %",
                 "added_mass": "added mass coefficient +5 %",
                 "seabed": "seabed stiffness +5 %"}
PERTURBATION = 1.05
#: a relative difference is not formed below this fraction of the quantity's scale
TINY = 1e-12


@dataclass
class Run:
    """One solve of one method: ``label`` (e.g. "h x2"), its element length [m] and time
    step [s] as run, its wall time [s] and its measures (:func:`measures`)."""

    method: str
    label: str
    element_length: float
    time_step: float | None
    wall_s: float
    measures: dict
    result: object = None


@dataclass
class Comparison:
    """The outcome of :func:`compare_time_domain`."""

    scene: object
    stations: list
    period: float | None
    start: float
    vfife: Run
    ancf: Run
    rows: list
    tolerances: list                 # rows of tolerances.csv
    levels: dict = field(default_factory=dict)      # (method, parameter) -> [Run]
    controls: dict = field(default_factory=dict)    # name -> (Run, rows)
    borrowed: str = ""

    @property
    def judged(self) -> list:
        return [r for r in self.rows if r["judged"]]

    @property
    def passed(self) -> bool:
        return bool(self.judged) and all(r["pass"] for r in self.judged)

    def control_failed(self, name: str) -> bool:
        rows = self.controls[name][1]
        return any(r["judged"] and not r["pass"] for r in rows)


# ------------------------------------------------------------------------------ the input
def check_scene(scene) -> None:
    """Exit-2 refusals before any solving: a scene without [dynamics]."""
    if scene.dynamics is None:
        raise SceneError(scene.name, "dynamics", "compare --time-domain needs the scene's "
                         "[dynamics] (duration, and a top motion, waves or a vessel)")


def with_states(scene):
    """The scene with ``[dynamics] save_states`` on (the stations' time series)."""
    return scene if scene.dynamics.save_states else scene.replace(
        **{"dynamics.save_states": True})


def drive_period(scene) -> float | None:
    """The period [s] of a periodic drive: a harmonic top motion without waves, or one
    regular wave train without a spectrum (and a top motion, if any, at its period); else
    None (an irregular sea, a time series of motion)."""
    tm, w = scene.dynamics.top_motion, scene.waves
    periods = set()
    if tm is not None:
        if tm.times is not None:
            return None
        periods.add(float(tm.period))
    if w is not None:
        if w.spectrum is not None or len(w.trains) != 1:
            return None
        periods.add(float(w.trains[0].period))
    return periods.pop() if len(periods) == 1 else None


def perturbed(scene, name: str):
    """The scene of a negative control (:data:`PERTURBATIONS`): every line type's drag
    coefficients, added mass coefficient or the seabed stiffness x :data:`PERTURBATION`."""
    if name == "seabed":
        if scene.seabed is None:
            raise SceneError(scene.name, "seabed", "the seabed-stiffness control needs a seabed")
        return scene.replace(**{"seabed.stiffness": scene.seabed.stiffness * PERTURBATION})
    keys = {"drag": ("drag_normal", "drag_tangential"), "added_mass": ("added_mass",)}[name]
    changes = {}
    for lt_name, lt in scene.line_types.items():
        for k in keys:
            changes[f"line_types.{lt_name}.{k}"] = getattr(lt, k) * PERTURBATION
    return scene.replace(**changes)


# ----------------------------------------------------------------------------- the solves
def solve(scene, name: str, label: str, element_length: float, period, stations, grid,
          progress=None, keep: bool = False) -> Run:
    """One solve of ``name`` ("vfife" or "ancf") at ``element_length`` [m] and its
    measures; SolveFailed when it fails."""
    t0 = time.perf_counter()
    res = method(name).solve(scene, element_length=element_length, progress=progress)
    wall = time.perf_counter() - t0
    if not res.converged or res.dynamics is None:
        raise SolveFailed(name, res.status, f"{name} ({label}): {res.message}")
    info = res.summary()
    dt = info.get("dynamic_time_step")
    m = measures(res, scene, stations, grid, period)
    return Run(name, label, element_length, dt, wall, m, res if keep else None)


def levels_plan(scene, ancf_dt_refine: bool = False) -> dict:
    """(method, parameter) -> [(label, scene, element length [m])] coarse to fine (the
    module docstring); the default runs are "default" of each method. ``ancf_dt_refine``:
    the ANCF's step refined from its default (1x, 1/2, 1/4: a case whose default step is
    already coarse, e.g. the storm's T/25) instead of coarsened to it."""
    hv, ha = scene.vfife.element_length, scene.ancf.element_length
    safety = scene.vfife.time_step_safety
    an = scene.ancf
    plan = {("vfife", "element length"): [(f"h x{f:g}", scene, f * hv) for f in LEVELS],
            ("ancf", "element length"): [(f"h x{f:g}", scene, f * ha) for f in LEVELS]}
    plan[("vfife", "time step")] = [
        (f"h x{LEVELS[0]:g}, dt x{f:g}" if f != LEVELS[0] else f"h x{LEVELS[0]:g}",
         scene if f == LEVELS[0] else scene.replace(
             **{"vfife.time_step_safety": safety * f / LEVELS[0]}), LEVELS[0] * hv)
        for f in LEVELS]
    steps = []
    factors = tuple(f / LEVELS[0] for f in LEVELS) if ancf_dt_refine else LEVELS
    for f in factors:
        if f == 1.0:
            steps.append(("default", scene, ha))
        elif an.time_step is not None:
            steps.append((f"dt x{f:g}", scene.replace(**{"ancf.time_step": an.time_step * f}), ha))
        else:
            n = max(8, int(round(an.steps_per_period / f)))
            steps.append((f"dt x{f:g}", scene.replace(**{"ancf.steps_per_period": n}), ha))
    plan[("ancf", "time step")] = steps
    return plan


def distinct(runs, ratio: float = 1.3) -> bool:
    """The runs' time steps fall by at least ``ratio`` from one level to the next (a level
    that failed counts as distinct: its failure is the row's reason)."""
    dts = [r.time_step for r in runs]
    if any(d is None for d in dts):
        return True
    return all(a >= ratio * b for a, b in zip(dts, dts[1:]))


def compare_time_domain(scene, *, convergence: bool = True, controls=(), tolerances=None,
                        progress=None, keep: bool = True, ancf_dt_refine: bool = False,
                        borrowed: str = "") -> Comparison:
    """Run both methods on ``scene`` (its [dynamics], states saved), compare them over the
    window with tolerances measured from the levels (``convergence``) or taken from
    ``tolerances`` (a {(quantity, station): Tolerance} of another case, ``borrowed``);
    ``controls``: names of :data:`PERTURBATIONS` to run on the ANCF's side alone;
    ``ancf_dt_refine``: :func:`levels_plan`; ``borrowed``: where ``tolerances`` come from."""
    check_scene(scene)
    scene = with_states(scene)
    period = drive_period(scene)
    # the static state of the ANCF (its default mesh) picks the stations
    say = progress or (lambda *a, **k: None)
    say("time domain: the VFIFE at its default element length")
    L = scene.total_length
    grid = np.linspace(0.0, L, int(round(L / scene.vfife.element_length)) + 1)
    hv, ha = scene.vfife.element_length, scene.ancf.element_length
    # the stations from the VFIFE's static profile, at the default mesh
    t0 = time.perf_counter()
    vres = method("vfife").solve(scene, element_length=hv, progress=progress)
    wall = time.perf_counter() - t0
    if not vres.converged or vres.dynamics is None:
        raise SolveFailed("vfife", vres.status, f"vfife (default): {vres.message}")
    st = stations_mod.pick(vres.profile, scene.attachments, hv)
    vf = Run("vfife", "default", hv, vres.summary().get("dynamic_time_step"), wall,
             measures(vres, scene, st, grid, period), vres if keep else None)
    say("time domain: the ANCF at its default element length")
    an = solve(scene, "ancf", "default", ha, period, st, grid, progress, keep)
    start = float(vres.summary().get("statistics_start", scene.dynamics.statistics_from))
    runs: dict = {}
    tol: dict = {}
    tol_rows: list = []
    if convergence:
        plan = levels_plan(scene, ancf_dt_refine)
        done = {("vfife", "default"): vf, ("ancf", "default"): an}
        failed_coarse: list = []          # the ANCF's coarsened steps that failed
        for (mname, param), lv in plan.items():
            rs = []
            for label, sc, h in lv:
                key = (mname, "default" if label in ("h x1", "default") else label)
                if key not in done:
                    say(f"time domain: {mname} {label}")
                    try:
                        done[key] = solve(sc, mname, label, h, period, st, grid, progress)
                    except (SolveFailed, SceneError) as exc:
                        done[key] = Run(mname, label, h, None, 0.0, {}, None)
                        done[key].failure = str(exc)
                rs.append(done[key])
            if (mname, param) == ("ancf", "time step") and not ancf_dt_refine \
                    and (not distinct(rs) or any(not r.measures for r in rs)):
                # the step cannot be coarsened past the sampling interval (it is an exact
                # divisor of it), or a coarsened step failed (Newton on a slack line):
                # refine it from the default instead, at exact halves
                ancf_dt_refine = True
                failed_coarse = [r for r in rs if not r.measures]
                rs = [an]
                for f in (2, 4):
                    label = f"dt x1/{f}"
                    say(f"time domain: ancf {label}")
                    sc = scene.replace(**{"ancf.time_step": an.time_step / f})
                    try:
                        rs.append(solve(sc, "ancf", label, ha, period, st, grid, progress))
                    except (SolveFailed, SceneError) as exc:
                        rs.append(Run("ancf", label, ha, None, 0.0, {}, None))
                        rs[-1].failure = str(exc)
            runs[(mname, param)] = rs
        tol, tol_rows = measured_tolerances(vf, an, runs, ancf_dt_refine)
        if failed_coarse:             # in runs.csv with their failure, not in the levels
            runs[("ancf", "failed coarsened time step")] = failed_coarse
    elif tolerances is not None:
        tol = borrow(tolerances, vf, an, borrowed)
    rows = agreement_rows(vf, an, tol)
    comp = Comparison(scene, st, period, start, vf, an, rows, tol_rows, runs,
                      borrowed=borrowed if not convergence else "")
    comp.tolerance_map = tol
    for name in controls:
        say(f"time domain: negative control {name} (the ANCF's scene alone)")
        try:
            run = solve(perturbed(scene, name), "ancf", f"control {name}", ha, period, st,
                        grid, progress)
        except SceneError as exc:
            comp.controls[name] = (None, [], str(exc))
            continue
        comp.controls[name] = (run, agreement_rows(vf, run, tol), "")
    return comp


# ---------------------------------------------------------------------------- the measures
def _window_index(t, start):
    return np.flatnonzero(np.asarray(t) >= start - 1e-9)


def _at(s_nodes, values, s):
    """Values (k, n) at the nodes s_nodes, linearly interpolated to s [m] (k,)."""
    j = int(np.clip(np.searchsorted(s_nodes, s) - 1, 0, len(s_nodes) - 2))
    a = (s - s_nodes[j]) / (s_nodes[j + 1] - s_nodes[j])
    return (1.0 - a) * values[:, j] + a * values[:, j + 1]


def _ei_at(scene, s: np.ndarray) -> np.ndarray:
    """The bending stiffness EI [N m2] along s [m] (the segments')."""
    out = np.empty_like(np.asarray(s, float))
    for p in segment_properties(scene):
        out[(s >= p.s_start - 1e-9) & (s <= p.s_end + 1e-9)] = p.EI
    return out


def measures(res, scene, stations, grid, period) -> dict:
    """(quantity, station or "along s") -> value (a number, or an array: a time series over
    the window, an envelope on ``grid``), with the kind "series", "profile" or "value"
    under the same key in ``out['_kind']`` (module docstring)."""
    dyn = res.dynamics
    ts, env, st = dyn.timeseries, dyn.envelope, dyn.states
    start = float(res.summary().get("statistics_start", scene.dynamics.statistics_from))
    out: dict = {}
    kind: dict = {}

    def put(q, where, k, v):
        out[(q, where)] = np.asarray(v, float) if k != "value" else float(v)
        kind[(q, where)] = k

    w = _window_index(ts["time"], start)
    top = np.asarray(ts["hang_off_tension"], float)[w]
    put("hang-off tension", "time series", "series", top)
    put("hang-off tension max", "hang-off", "value", np.max(top))
    put("hang-off tension min", "hang-off", "value", np.min(top))
    tds = np.asarray(ts["touchdown_s"], float)[w]
    if np.any(np.isfinite(tds)):
        put("touchdown s min", "travel", "value", np.nanmin(tds))
        put("touchdown s max", "travel", "value", np.nanmax(tds))
    tw = _window_index(st["t"], start)
    s_nodes = np.asarray(st["s"], float)
    T, M = np.asarray(st["tension"])[tw], np.asarray(st["moment"])[tw]
    t_w = np.asarray(st["t"])[tw]
    for name, s in stations:
        ei = float(_ei_at(scene, np.array([s]))[0])
        Ts, Ms = _at(s_nodes, T, s), _at(s_nodes, M, s)
        where = f"{name} (s {s:.1f} m)"
        put("tension", where, "series", Ts)
        put("moment", where, "series", Ms)
        put("curvature", where, "series", Ms / ei)
        put("tension max", where, "value", np.max(Ts))
        put("tension min", where, "value", np.min(Ts))
        put("moment max", where, "value", np.max(Ms))
        put("curvature max", where, "value", np.max(Ms) / ei)
        if period is not None:
            put("tension 1st harmonic", where, "value",
                harmonics.fit(t_w, Ts, period, start).amplitude)
            put("moment 1st harmonic", where, "value",
                harmonics.fit(t_w, Ms, period, start).amplitude)
    if period is not None:
        put("hang-off tension 1st harmonic", "hang-off", "value",
            harmonics.fit(np.asarray(ts["time"])[w], top, period, start).amplitude)
    s_env = np.asarray(env["s"], float)
    for col, q, pick in (("tension_min", "tension min", np.min),
                         ("tension_max", "tension max", np.max),
                         ("moment_max", "moment max", np.max),
                         ("curvature_max", "curvature max", np.max),
                         ("fatigue_damage", "fatigue damage", np.max)):
        if col not in env:
            continue
        e = np.asarray(env[col], float)
        if not np.all(np.isfinite(e)):
            continue
        put(q, "along s", "profile", np.interp(grid, s_env, e))
        put(q, "extreme along s", "value", pick(e))
        if col == "fatigue_damage":
            for name, s in stations:
                put(q, f"{name} (s {s:.1f} m)", "value", np.interp(s, s_env, e))
    out["_kind"] = kind
    return out


# ------------------------------------------------------------------------------ the rows
def _scale(*values) -> float:
    return max(float(np.sqrt(np.mean(np.square(v)))) if np.ndim(v) else abs(float(v))
               for v in values)


#: the quantity families whose noise floor is set by the line's largest value (a pinned
#: end's moment is zero but for round-off: its changes are not an order)
FAMILIES = ("tension", "moment", "curvature")


def family_scale(key, run: Run) -> float:
    """The largest value along the line of the family of ``key``'s quantity (tension,
    moment or curvature; 0 for the others): the scale of its noise floor."""
    for fam in FAMILIES:
        if fam in key[0]:
            v = run.measures.get((f"{fam} max", "extreme along s"))
            return abs(float(v)) if v is not None else 0.0
    return 0.0


def measured_tolerances(vf: Run, an: Run, runs: dict, ancf_dt_refine: bool = False):
    """{key: Tolerance} of every quantity both default runs measured, and the rows of
    tolerances.csv (each level's value, the changes, order, estimated error)."""
    tol, rows = {}, []
    for key, kind in vf.measures["_kind"].items():
        if key not in an.measures:
            continue
        scale = max(_scale(vf.measures[key], an.measures[key]), family_scale(key, vf))
        parts = []
        for (mname, param), rs in runs.items():
            fails = [getattr(r, "failure", "") for r in rs if not r.measures]
            levels = tuple(r.time_step if param == "time step" else r.element_length
                           for r in rs)
            default = "coarsest" if (ancf_dt_refine and mname == "ancf"
                                     and param == "time step") else "finest"
            if fails or any(key not in r.measures for r in rs) or \
                    len({np.shape(r.measures[key]) for r in rs}) != 1:
                why = fails[0] if fails else "not measured at every level (shape or presence)"
                e = Estimate(mname, param, levels, (), np.nan, np.nan, None, None,
                             f"not converged ({why})")
            else:
                e = estimate(mname, param, levels, [r.measures[key] for r in rs], default,
                             scale)
            parts.append(e)
            rows.append({"quantity": key[0], "station": key[1], "kind": kind,
                         "method": mname, "parameter": param,
                         "level_1": levels[0], "level_2": levels[1], "level_3": levels[2],
                         "value_1": e.values[0] if e.values else None,
                         "value_2": e.values[1] if e.values else None,
                         "value_3": e.values[2] if e.values else None,
                         "change_1": e.d1, "change_2": e.d2, "order": e.order,
                         "error": e.error, "note": e.note})
        tol[key] = combine(parts)
    return tol, rows


def agreement_rows(vf: Run, an: Run, tol: dict) -> list[dict]:
    """One row per quantity both runs measured (agreement.csv's columns)."""
    rows = []
    for key, kind in vf.measures["_kind"].items():
        if key not in an.measures:
            continue
        a, b = vf.measures[key], an.measures[key]
        if kind == "value":
            va, vb, diff = float(a), float(b), abs(float(a) - float(b))
        else:
            if np.shape(a) != np.shape(b):
                continue
            va, vb = _scale(a), _scale(b)
            diff = float(np.sqrt(np.mean((np.asarray(a) - np.asarray(b)) ** 2)))
        scale = max(abs(va), abs(vb))
        rel = diff / scale if scale > TINY else None
        t: Tolerance | None = tol.get(key)
        judged = t is not None and t.value is not None
        reason = t.reason if t is not None else "not judged: no tolerance measured"
        where = key[1] if kind != "series" else f"{key[1]} (rms over the window)"
        if kind == "profile":
            where = "along s (rms over s)"
        rows.append({"quantity": key[0], "station": where, "kind": kind, "vfife": va,
                     "ancf": vb, "abs_diff": diff, "rel_diff": rel,
                     "tolerance": t.value if judged else None, "tolerance_reason": reason,
                     "judged": judged, "pass": (diff <= t.value) if judged else None,
                     "_key": key})
    return rows


def relative_tolerances(comp) -> dict:
    """{key: (tolerance / the row's scale, reason)} of a comparison's judged rows (the
    scale: the larger of the two methods' values, an array's rms): what another case of
    the same line borrows (:func:`borrow`); a row not judged lends nothing."""
    out = {}
    for r in comp.rows:
        scale = max(abs(r["vfife"]), abs(r["ancf"]))
        if r["judged"] and scale > TINY:
            out[r["_key"]] = (r["tolerance"] / scale, r["tolerance_reason"])
    return out


def borrow(relative: dict, vf: Run, an: Run, source: str) -> dict:
    """{key: Tolerance}: the relative tolerances of another case (:func:`relative_tolerances`)
    times this case's scale of the same row; a row the source did not judge is not judged
    here either."""
    out = {}
    for key in vf.measures["_kind"]:
        if key not in an.measures:
            continue
        if key not in relative:
            out[key] = Tolerance(None, f"not judged: {source} judged no such row", ())
            continue
        rel, why = relative[key]
        scale = max(_scale(vf.measures[key]), _scale(an.measures[key]))
        out[key] = Tolerance(rel * scale, f"borrowed from {source} "
                             f"({100 * rel:.3g} % of the row): {why}", ())
    return out

"""What accuracy costs in time: convergence and cost study of both methods on one scene.

``riser-verify cost SCENE [--out DIR]`` (default ``reports/cost/SCENE/``) writes
``runs.csv``, ``values.csv``, ``report.md`` and three plots.

Protocol
--------
- Settings swept. VFIFE: element length (20 ... 0.5 m), time-step safety factor, static
  tolerance, relaxation scheme (coarse-mesh sequencing, rotational-inertia scale), and the
  cost of one second of dynamics per element length. BVP: ``solve_bvp`` tolerance
  (1e-2 ... 1e-9), initial mesh size, node cap. Every setting not swept keeps its default.
- Timing: one global warm-up (Numba compilation, or its on-disk cache load, reported as
  ``compile_time_s``), then the median of ``repeats`` runs (the solvers' own
  ``wall_time_s``). A run that does not converge is not repeated (its one time is kept).
- Errors (runs.csv ``err_*``): against the reference, the finest-tolerance BVP solution,
  as fractions: tensions and moment relative to the reference value; touchdown position,
  crest and sag heights and the curve distance relative to the water depth (else the
  hang-off height). Same material arc length: the VFIFE arc length of a Wang-form scene is
  shifted by the line added on the seabed (see :mod:`verification.compare`).
- Self-convergence (``self_*``): VFIFE runs against VFIFE's own limit, Richardson-
  extrapolated from the three finest element lengths of the order sweep; BVP runs
  against the finest BVP. The difference between the VFIFE limit and the BVP reference is
  the *model difference* (extensible line and penalty seabed vs inextensible and rigid),
  which no mesh refinement removes.
- Observed VFIFE order: slope of log(self error) vs log(element length) over the order
  sweep (``element_length_tight``: static tolerance 1e-4, creep tolerance 1e-7, so that
  the relaxation error is far below the discretisation error), against its Richardson
  limit. A length enters the fit if it is coarser than the finest (whose self error is
  set by the extrapolation), not longer than the bending boundary layer sqrt(EI/T) at the
  touchdown (else pre-asymptotic), its error is at most 1e-2 and at least 10x the
  relaxation error of the sweep, measured at the middle length against a run with both
  tolerances 10x tighter (``element_length_tight_check``). The report gives the local
  orders of successive lengths too, and says per quantity why an order differs from 2.
"""

from __future__ import annotations

import dataclasses
import math
import statistics
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from riser.profile import Profile, summarize
from riser.scene import Dynamics, Scene, TopMotion

from .report import GENERATED_NOTE, fmt, md_table, new_figure, save

# scenes of the study (reproduce all)
COST_SCENES = ("wang2014-baseline", "yu2021-a3", "yu2021-a2-sheared")

QUANTITIES = ("hang_off_tension", "tdp_tension", "tdp_x", "max_moment", "crest_height",
              "sag_height", "curve_distance")
QUANTITY_LABEL = {
    "hang_off_tension": "hang-off tension", "tdp_tension": "touchdown tension",
    "tdp_x": "touchdown position", "max_moment": "peak moment",
    "crest_height": "crest height(s)", "sag_height": "sag height(s)",
    "curve_distance": "curve distance (max)"}
RUN_COLUMNS = ("method", "setting", "value", "wall_time_s", "compile_time_s",
               *(f"err_{q}" for q in QUANTITIES))
EXTRA_COLUMNS = ("converged", "repeats", "size", "steps", *(f"self_{q}" for q in QUANTITIES),
                 "message")

ELEMENT_LENGTHS = (20.0, 10.0, 5.0, 2.0, 1.0, 0.5)
BVP_TOLERANCES = (1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9)
TARGETS = (1e-2, 1e-3, 1e-4)
#: expected order of the VFIFE static solution in element length (see report text)
EXPECTED_ORDER = 2.0
DYNAMICS_DURATION = 1.0
#: tolerances of the order sweep (element_length_tight rows): static force tolerance [element
#: weights] and creep tolerance [fraction of the line length]. The default creep test (1e-5)
#: leaves relaxation errors of ~1e-4 in the peak moment, above the discretisation error
#: below 5 m (Wang baseline 5 m: moment 31992.42 N m at 1e-5, 31990.05 at 1e-7, 31990.02
#: at 1e-8); the force tolerance is not the limiter once the creep test is this tight
#: (1e-4 and 1e-5 give the same result to 1e-9 there).
TIGHT_TOLERANCE = 1e-4
TIGHT_CREEP = 1e-7
#: the relaxation noise of the order sweep is measured at the middle element length by a
#: run with both tolerances 10x tighter (``element_length_tight_check``)
CHECK_FACTOR = 10.0
#: a point enters the order fit only if its error is this many times the noise floor: its
#: log error is then uncertain by at most log(1.1) ~ 0.1, i.e. <= 0.1 in the order over a
#: factor-2.5 step of the element length
NOISE_MARGIN = 10.0
#: |fitted order - expected| beyond which the report explains the departure
ORDER_BAND = 0.3
#: errors above this are pre-asymptotic (unresolved boundary layers) and left out of the fit
PRE_ASYMPTOTIC = 1e-2


# ----------------------------------------------------------------------------- settings
@dataclass
class Setting:
    method: str                      # 'bvp' | 'vfife' | 'vfife-dyn'
    setting: str
    value: float
    solve_kwargs: dict = field(default_factory=dict)
    vfife_changes: dict = field(default_factory=dict)


def default_settings(scene: Scene, quick: bool = False, element_lengths=None,
                     boundary_layer: float = math.inf) -> list[Setting]:
    """The runs of the study (``quick``: a coarse subset for tests and development).
    ``boundary_layer`` [m] (see :func:`boundary_layer_length`): the order sweep
    (``element_length_tight``) runs the element lengths of at least 1 m, and finer ones
    only when fewer than three lengths between its finest and the boundary layer would
    enter the fit (the Wang baseline, 7.8 m: 5, 2, 1 m and the finest 0.5 m; the Yu
    scenes, 27 m: 20 ... 2 m and the finest 1 m; a 0.5 m run with the tight tolerances
    costs ~50 s on yu2021-a2-sheared)."""
    out: list[Setting] = []
    hs = tuple(element_lengths) if element_lengths else (
        (20.0, 10.0, 5.0) if quick else ELEMENT_LENGTHS)
    tols = (1e-3, 1e-6, 1e-8) if quick else BVP_TOLERANCES
    for t in tols:
        out.append(Setting("bvp", "tolerance", t, {"tolerance": t}))
    if not quick:
        for n in (50, 100, 400, 1600):
            out.append(Setting("bvp", "initial_nodes", n, {"tolerance": 1e-6, "initial_nodes": n}))
        for n in (300, 600, 1200, 30000):
            out.append(Setting("bvp", "max_nodes", n, {"tolerance": 1e-6, "max_nodes": n}))
    for h in hs:
        out.append(Setting("vfife", "element_length", h, {"element_length": h}))
    hmid = 2.0 if not quick else hs[-1]
    if not quick:
        vf = scene.vfife
        for f in (0.2, 0.4, 0.8, 0.95):
            if f != vf.get("time_step_safety", 0.8):
                out.append(Setting("vfife", "time_step_safety", f, {"element_length": hmid},
                                   {"time_step_safety": f}))
        for tol in (1e-2, 1e-3, 1e-4, 1e-5):
            if tol != vf.get("static_tolerance", 1e-3):
                out.append(Setting("vfife", "static_tolerance", tol,
                                   {"element_length": hmid, "tolerance": tol},
                                   {"max_steps": 2_000_000}))
        for hc in (hmid, 5.0, 20.0):
            if hc != vf.get("coarse_element_length", 10.0):
                out.append(Setting("vfife", "coarse_element_length", hc,
                                   {"element_length": hmid}, {"coarse_element_length": hc}))
        for r in (1.0, 16.0):
            if r != vf.get("rotational_inertia_scale", 4.0):
                out.append(Setting("vfife", "rotational_inertia_scale", r,
                                   {"element_length": hmid}, {"rotational_inertia_scale": r}))
        tight = {"max_steps": 20_000_000, "creep_tolerance": TIGHT_CREEP}
        tight_hs = [h for h in hs if h >= 1.0]
        for h in sorted((h for h in hs if h < 1.0), reverse=True):
            if sum(1 for g in tight_hs if min(tight_hs) < g <= boundary_layer) >= 3:
                break
            tight_hs.append(h)
        for h in tight_hs:
            out.append(Setting("vfife", "element_length_tight", h,
                               {"element_length": h, "tolerance": TIGHT_TOLERANCE}, tight))
        out.append(Setting("vfife", "element_length_tight_check", hmid,
                           {"element_length": hmid,
                            "tolerance": TIGHT_TOLERANCE / CHECK_FACTOR},
                           {**tight, "creep_tolerance": TIGHT_CREEP / CHECK_FACTOR}))
        for h in hs:
            out.append(Setting("vfife-dyn", "dynamics_1s_element_length", h,
                               {"element_length": h}))
    return out


# ----------------------------------------------------------------------------- records
@dataclass
class Run:
    setting: Setting
    times: list = field(default_factory=list)
    converged: bool = False
    message: str = ""
    compile_time_s: float = 0.0
    size: int | None = None          # BVP nodes / VFIFE elements
    steps: int | None = None
    values: dict = field(default_factory=dict)     # raw scalar quantities
    profile: Profile | None = None
    errors: dict = field(default_factory=dict)     # vs the BVP reference
    self_errors: dict = field(default_factory=dict)

    @property
    def wall_time_s(self) -> float:
        return float(statistics.median(self.times)) if self.times else float("nan")

    @property
    def method(self) -> str:
        return "vfife" if self.setting.method.startswith("vfife") else "bvp"


@dataclass
class CostStudy:
    scene: Scene
    vfife_scene: Scene
    s_shift: float
    depth: float
    repeats: int
    runs: list
    reference: Run
    ref_values: dict
    bvp_self: dict = field(default_factory=dict)       # quantity -> rel. uncertainty of ref
    vfife_limit: dict = field(default_factory=dict)    # raw key -> Richardson limit
    vfife_richardson_order: dict = field(default_factory=dict)
    orders: dict = field(default_factory=dict)         # quantity -> fit dict
    noise_floor: dict = field(default_factory=dict)    # quantity -> rel. relaxation error
    sweep_noise: dict = field(default_factory=dict)    # ... of the order sweep
    boundary_layer: float = math.inf                    # [m], asymptotic range h <= this
    foundation_length: float | None = None              # [m], penalty seabed at touchdown
    model_difference: dict = field(default_factory=dict)
    order_sweep: str = ""
    order_setting: str = ""
    scaling: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)
    elapsed_s: float = 0.0

    def frame(self) -> pd.DataFrame:
        rows = []
        for r in self.runs:
            s = r.setting
            row = {"method": r.method if s.method != "vfife-dyn" else "vfife",
                   "setting": s.setting, "value": s.value, "wall_time_s": r.wall_time_s,
                   "compile_time_s": r.compile_time_s}
            for q in QUANTITIES:
                row[f"err_{q}"] = r.errors.get(q)
            row.update({"converged": r.converged, "repeats": len(r.times), "size": r.size,
                        "steps": r.steps})
            for q in QUANTITIES:
                row[f"self_{q}"] = r.self_errors.get(q)
            row["message"] = r.message
            rows.append(row)
        return pd.DataFrame(rows, columns=RUN_COLUMNS + EXTRA_COLUMNS)

    def values_frame(self) -> pd.DataFrame:
        keys = sorted({k for r in self.runs for k in r.values})
        rows = [{"method": r.method, "setting": r.setting.setting, "value": r.setting.value,
                 **{k: r.values.get(k) for k in keys}} for r in self.runs if r.values]
        rows.insert(0, {"method": "reference", "setting": "bvp tolerance",
                        "value": self.reference.setting.value,
                        **{k: self.ref_values.get(k) for k in keys}})
        return pd.DataFrame(rows)


# ----------------------------------------------------------------------------- quantities
def _shifted(p: Profile, shift: float) -> Profile:
    if not shift:
        return p
    q = dataclasses.replace(p, s=p.s - shift)
    if p.tdp_s is not None:
        q.tdp_s = p.tdp_s - shift
    return q


def raw_values(profile: Profile, ref_summary: dict | None = None) -> dict:
    """Scalar quantities of a profile (already in the reference arc length). Crests and sags
    are matched to the reference ones by arc length: keys crest1_height, sag1_height, ..."""
    sm = summarize(profile)
    out = {"hang_off_tension": sm["hang_off_tension"], "tdp_tension": sm["tdp_tension"],
           "tdp_x": sm["tdp_x"], "max_moment": sm["max_moment"]}
    ref = ref_summary or sm
    for kind in ("crests", "sags"):
        for i, cb in enumerate(ref[kind]):
            cand = sm[kind]
            c = min(cand, key=lambda c: abs(c["s"] - cb["s"])) if cand else None
            out[f"{kind[:-1]}{i + 1}_height"] = c["height"] if c else None
    return out


def _family(q: str, values: dict) -> list[str]:
    if q in ("crest_height", "sag_height"):
        tag = q.split("_")[0]
        return sorted(k for k in values if k.startswith(tag) and k.endswith("_height"))
    return [q]


def _norm(q: str, ref_values: dict, depth: float) -> float:
    if q in ("hang_off_tension", "tdp_tension", "max_moment"):
        v = ref_values.get(q)
        return abs(v) if v else float("nan")
    return depth


def rel_errors(values: dict, ref_values: dict, depth: float, norm_values=None) -> dict:
    """Relative errors per quantity family (max over crests/sags); None when undefined.
    Tensions and moment are normalised by ``norm_values`` (default ``ref_values``)."""
    out = {}
    nv = norm_values or ref_values
    for q in QUANTITIES:
        if q == "curve_distance":
            continue
        keys = _family(q, ref_values)
        errs = []
        for k in keys:
            a, b = values.get(k), ref_values.get(k)
            if a is None or b is None:
                errs = None
                break
            errs.append(abs(a - b) / _norm(q, nv, depth))
        out[q] = max(errs) if errs else None
    return out


# ----------------------------------------------------------------------------- Richardson
def richardson(hs, qs) -> tuple[float, float | None]:
    """Limit and observed order from the three finest of ``hs`` (a constant refinement
    ratio is not required: the order solves (q1-q2)/(q2-q3) = (h1^p-h2^p)/(h2^p-h3^p)).
    Returns (limit, order); order None (limit = finest value) when the differences change
    sign or are zero, i.e. the sequence is not in its asymptotic range."""
    pts = sorted(zip(hs, qs))[:3]
    if len(pts) < 3:
        return (pts[0][1] if pts else float("nan")), None
    (h3, q3), (h2, q2), (h1, q1) = pts
    d12, d23 = q1 - q2, q2 - q3
    if d12 == 0.0 or d23 == 0.0 or (d12 > 0) != (d23 > 0):
        return q3, None
    target = d12 / d23

    def f(p):
        return (h1 ** p - h2 ** p) / (h2 ** p - h3 ** p) - target
    lo, hi = 0.2, 8.0
    if f(lo) * f(hi) > 0:
        return q3, None
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0:
            hi = mid
        else:
            lo = mid
    p = 0.5 * (lo + hi)
    C = d23 / (h2 ** p - h3 ** p)
    return q3 - C * h3 ** p, p


def fit_order(hs, errs, floor: float = 0.0, ceiling: float = PRE_ASYMPTOTIC) -> dict:
    """Least-squares slope of log(err) vs log(h) over the points with
    floor < err <= ceiling (above the noise, in the asymptotic range).
    Returns {'order', 'points' (h used), 'r2'} (order None with fewer than 2 points)."""
    pts = [(h, e) for h, e in zip(hs, errs)
           if e is not None and np.isfinite(e) and max(floor, 0.0) < e <= ceiling]
    if len(pts) < 2:
        return {"order": None, "points": [h for h, _ in pts], "r2": None}
    x = np.log([h for h, _ in pts])
    y = np.log([e for _, e in pts])
    p, c = np.polyfit(x, y, 1)
    yhat = p * x + c
    ss = float(np.sum((y - y.mean()) ** 2))
    r2 = 1.0 - float(np.sum((y - yhat) ** 2)) / ss if ss > 0 else 1.0
    return {"order": float(p), "const": float(c), "points": [h for h, _ in pts], "r2": r2}


def element_length_order(hs, values: list[dict], norms: dict, floor: dict | None = None,
                         h_max: float = math.inf):
    """Self-convergence of an element-length sweep: per raw key the Richardson limit and
    order; per quantity family the relative self errors and the fitted order (points
    coarser than the finest, not longer than ``h_max`` (the asymptotic range), above
    ``floor[q]``). Returns (limits, rich_orders, self_err, fits) with self_err[q] a list
    aligned with ``hs``."""
    keys = sorted({k for v in values for k in v if v.get(k) is not None})
    limits, rorders = {}, {}
    for k in keys:
        ok = [(h, v[k]) for h, v in zip(hs, values) if v.get(k) is not None]
        if len(ok) >= 3:
            limits[k], rorders[k] = richardson([h for h, _ in ok], [q for _, q in ok])
        elif ok:
            limits[k], rorders[k] = min(ok)[1], None
    self_err, fits = {}, {}
    hfin = min(hs)
    for q in QUANTITIES:
        if q == "curve_distance":
            continue
        fam = [k for k in _family(q, limits)]
        if not fam:
            continue
        errs = []
        for v in values:
            e = [abs(v[k] - limits[k]) / norms[q] for k in fam if v.get(k) is not None]
            errs.append(max(e) if len(e) == len(fam) else None)
        self_err[q] = errs
        use = [(h, e) for h, e in zip(hs, errs) if hfin < h <= h_max]
        fits[q] = fit_order([h for h, _ in use], [e for _, e in use],
                            (floor or {}).get(q, 0.0))
        fits[q].update(_fit_context([h for h in hs if h > hfin],
                                    [e for h, e in zip(hs, errs) if h > hfin],
                                    h_max, (floor or {}).get(q, 0.0)))
    return limits, rorders, self_err, fits


def _fit_context(hs, errs, h_max: float, floor: float) -> dict:
    """Local orders log(e1/e2)/log(h1/h2) of successive element lengths (all of them, for
    the report) and the largest error of the lengths in the asymptotic range (h <= h_max)
    when none of them is above the noise floor."""
    pts = list(zip(hs, errs))
    local = [(h1, h2, math.log(e1 / e2) / math.log(h1 / h2))
             for (h1, e1), (h2, e2) in zip(pts, pts[1:]) if e1 and e2 and e1 > 0 and e2 > 0]
    inside = [e for h, e in zip(hs, errs) if h <= h_max and e is not None]
    below = bool(inside) and max(inside) <= floor
    return {"local": local, "below_noise": max(inside) if below else None,
            "noise_margin": floor, "n_inside": len(inside)}


# ----------------------------------------------------------------------------- running
class Progress:
    """Runs done / total, elapsed and estimated remaining time on stderr."""

    def __init__(self, total: int, label: str, stream=None, weights=None):
        self.total, self.label = total, label
        self.stream = stream if stream is not None else sys.stderr
        self.t0 = time.perf_counter()
        self.done = 0
        self.weights = weights or [1.0] * total   # predicted relative cost of each run
        self.tty = getattr(self.stream, "isatty", lambda: False)()

    def step(self, what: str) -> None:
        self.done += 1
        el = time.perf_counter() - self.t0
        wd = sum(self.weights[:self.done])
        wr = sum(self.weights[self.done:])
        rem = el / wd * wr if wd > 0 else float("nan")
        msg = (f"[cost {self.label}] {self.done}/{self.total} runs, elapsed {el:.0f} s, "
               f"remaining ~{rem:.0f} s ({what})")
        if self.tty:
            self.stream.write("\r" + msg[:150].ljust(150))
            if self.done == self.total:
                self.stream.write("\n")
        else:
            self.stream.write(msg + "\n")
        self.stream.flush()


def _weight(s: Setting) -> float:
    """Rough predicted cost of a setting (for the remaining-time estimate)."""
    if s.method == "bvp":
        t = s.solve_kwargs.get("tolerance", 1e-6)
        return 0.2 * 2.0 ** max(0.0, -math.log10(t) - 5.0)
    h = s.solve_kwargs.get("element_length", 2.0)
    # the tight creep test costs ~4-20x the default at 2 m, the 10x tighter check ~10-60x
    factor = {"element_length_tight": 5.0, "element_length_tight_check": 15.0}.get(
        s.setting, 0.05 if s.method == "vfife-dyn" else 1.0)
    return factor * max(0.3, (2.0 / h) ** 2)


def _solve(s: Setting, scene: Scene, vf_scene: Scene):
    if s.method == "bvp":
        import bvp
        return bvp.solve(scene, **s.solve_kwargs)
    import vfife
    sc = vf_scene.replace(vfife={**vf_scene.vfife, **s.vfife_changes}) if s.vfife_changes \
        else vf_scene
    return vfife.solve(sc, **s.solve_kwargs)


def _dynamics_time(s: Setting, vf_scene: Scene, repeats: int, static_cache: dict):
    """Wall time [s] of ``DYNAMICS_DURATION`` s of heave (1 m, 10 s) from the static state
    of the same mesh (the static solve is not timed here). Returns (times, steps, msg)."""
    from vfife.dynamics import run_dynamics
    h = s.solve_kwargs["element_length"]
    res = static_cache.get(h)
    if res is None or not res.converged:
        return [], None, "no converged static state"
    dyn = Dynamics(duration=DYNAMICS_DURATION, output_interval=DYNAMICS_DURATION / 2,
                   top_motion=TopMotion(axis="y", amplitude=1.0, period=10.0))
    sc = vf_scene.replace(dynamics=dyn)
    times, steps, msg = [], None, ""
    for _ in range(repeats):
        t0 = time.perf_counter()
        _, info = run_dynamics(sc, res.model, bool(sc.is_planar))
        times.append(time.perf_counter() - t0)
        steps, msg = info["steps"], info["message"]
        if info["status"] != "ok":
            break
    return times, steps, msg


def study(scene: Scene, *, repeats: int = 3, quick: bool = False, element_lengths=None,
          settings: list[Setting] | None = None, progress: bool = True,
          stream=None) -> CostStudy:
    """Run the study on ``scene`` (see the module docstring)."""
    import bvp
    import vfife.solver
    from .compare import reference_depth
    from .equivalence import DEFAULT_SEABED_LENGTH, fixed_ends_from_bvp, fixed_ends_note
    t_start = time.perf_counter()
    repeats = max(1, int(repeats))
    notes = []
    compile_s = vfife.solver.warm_up() or vfife.solver._COMPILED.get("compile_s", 0.0)
    # one BVP solve at the default tolerance: the fixed-ends equivalent of a Wang-form
    # scene and the boundary layer that sets the order sweep
    t0 = time.perf_counter()
    pre = bvp.solve(scene) if (scene.ends.kind != "fixed" or settings is None) else None
    if scene.ends.kind != "fixed":
        if not pre.converged:
            raise RuntimeError(f"cannot build the fixed-ends scene: the BVP did not converge "
                               f"({pre.message})")
        vf_scene = fixed_ends_from_bvp(scene, pre, DEFAULT_SEABED_LENGTH)
        note = fixed_ends_note(scene, vf_scene, DEFAULT_SEABED_LENGTH)
        s_shift = DEFAULT_SEABED_LENGTH
        notes.append(f"VFIFE solves the fixed-ends equivalent ({note}; seabed stiffness from "
                     f"the scene's default element length, the same for every VFIFE run so "
                     f"that the element-length sweep refines one model; conversion "
                     f"{time.perf_counter() - t0:.2f} s, not in the VFIFE times).")
    else:
        vf_scene, s_shift = scene, 0.0
    if settings is None:
        bl = boundary_layer_length(vf_scene, s_shift, pre.profile) if pre.converged \
            else math.inf
        settings = default_settings(scene, quick, element_lengths, bl)
    # BVP first (the finest tolerance is the reference), VFIFE statics, then dynamics
    order = {"bvp": 0, "vfife": 1, "vfife-dyn": 2}
    settings = sorted(settings, key=lambda s: order[s.method])
    prog = Progress(len(settings), scene.name, stream,
                    [_weight(s) for s in settings]) if progress else None
    runs: list[Run] = []
    static_cache: dict = {}
    for s in settings:
        run = Run(s)
        if s.method == "vfife-dyn":
            run.times, run.steps, run.message = _dynamics_time(s, vf_scene, repeats,
                                                               static_cache)
            run.converged = bool(run.times) and "blow" not in run.message
            run.compile_time_s = compile_s
            run.size = static_cache[s.value].info["elements"] if s.value in static_cache \
                else None
        else:
            for i in range(repeats):
                try:
                    res = _solve(s, scene, vf_scene)
                except (RuntimeError, ValueError, FloatingPointError) as exc:
                    run.converged, run.message = False, f"{type(exc).__name__}: {exc}"
                    break
                run.times.append(res.wall_time_s)
                if i == 0:
                    run.converged, run.message = res.converged, res.message
                    run.size = res.info.get("nodes" if s.method == "bvp" else "elements")
                    run.steps = res.info.get("steps")
                    run.profile = _shifted(res.profile, s_shift if s.method == "vfife"
                                           else 0.0) if res.converged else None
                    if s.method == "vfife" and s.setting == "element_length":
                        static_cache[s.value] = res
                if not res.converged:
                    break
            if s.method == "vfife":
                run.compile_time_s = compile_s
        runs.append(run)
        if prog:
            prog.step(f"{run.method} {s.setting}={s.value:g}: "
                      f"{run.wall_time_s:.3g} s" + ("" if run.converged else ", not converged"))
    # reference: the finest converged BVP tolerance
    bvp_tol = [r for r in runs if r.setting.method == "bvp" and r.setting.setting == "tolerance"
               and r.converged]
    if not bvp_tol:
        raise RuntimeError(f"no BVP run converged on {scene.name}: no reference")
    bvp_tol.sort(key=lambda r: r.setting.value)
    ref = bvp_tol[0]
    ref_sm = summarize(ref.profile)
    depth = reference_depth(scene, ref_sm)
    ref_values = raw_values(ref.profile)
    from .compare import curve_distance
    for r in runs:
        if r.profile is None:
            continue
        r.values = raw_values(r.profile, ref_sm)
        r.errors = rel_errors(r.values, ref_values, depth)
        lo = max(ref.profile.s[0], r.profile.s[0])
        hi = min(ref.profile.s[-1], r.profile.s[-1])
        r.errors["curve_distance"] = curve_distance(ref.profile, r.profile, (lo, hi))[0] / depth
    st = CostStudy(scene, vf_scene, s_shift, depth, repeats, runs, ref, ref_values,
                   notes=notes)
    _self_convergence(st, bvp_tol)
    _scaling(st)
    st.elapsed_s = time.perf_counter() - t_start
    return st


def _self_convergence(st: CostStudy, bvp_tol: list) -> None:
    depth = st.depth
    norms = {q: _norm(q, st.ref_values, depth) for q in QUANTITIES}
    # BVP: every run against the reference; the reference's own uncertainty is its change
    # from the next-finest tolerance
    for r in st.runs:
        if r.method == "bvp" and r.values:
            r.self_errors = dict(r.errors)
    if len(bvp_tol) >= 2:
        st.bvp_self = dict(bvp_tol[1].errors)

    def sweep(name):
        return sorted([r for r in st.runs if r.setting.method == "vfife"
                       and r.setting.setting == name and r.values],
                      key=lambda r: -r.setting.value)
    from .compare import curve_distance
    default, tight = sweep("element_length"), sweep("element_length_tight")
    # relaxation error, measured against a run with both tolerances 10x tighter than the
    # order sweep's at the middle element length: of the default settings (noise_floor)
    # and of the order sweep (sweep_noise, the floor of the fit)
    check = next((r for r in st.runs if r.setting.setting == "element_length_tight_check"
                  and r.converged and r.values), None)
    if check is not None:
        hmid = check.setting.value
        for attr, rs in (("noise_floor", default), ("sweep_noise", tight)):
            base = next((r for r in rs if math.isclose(r.setting.value, hmid)), None)
            if base is not None:
                err = rel_errors(base.values, check.values, depth)
                lo = max(base.profile.s[0], check.profile.s[0])
                hi = min(base.profile.s[-1], check.profile.s[-1])
                err["curve_distance"] = curve_distance(base.profile, check.profile,
                                                       (lo, hi))[0] / depth
                setattr(st, attr, {q: (v if v is not None else 0.0) for q, v in err.items()})
    if len(tight) >= 3:
        order_sweep = tight
        label = (f"static tolerance {TIGHT_TOLERANCE:g} x element weight and creep tolerance "
                 f"{TIGHT_CREEP:g} x line length, mesh sequencing as by default")
        floor = st.sweep_noise
    else:
        order_sweep, label, floor = default, "default static and creep tolerances", \
            st.noise_floor
    st.order_sweep = label
    st.order_setting = order_sweep[0].setting.setting if order_sweep else ""
    if len(order_sweep) < 2:
        return
    floor = {q: NOISE_MARGIN * v for q, v in floor.items()}
    st.boundary_layer = boundary_layer_length(st.vfife_scene, st.s_shift, st.reference.profile)
    st.foundation_length = foundation_length(st.vfife_scene, st.s_shift, st.reference.profile)
    hs = [r.setting.value for r in order_sweep]
    limits, rorders, self_err, fits = element_length_order(hs, [r.values for r in order_sweep],
                                                           norms, floor, st.boundary_layer)
    st.vfife_limit, st.vfife_richardson_order, st.orders = limits, rorders, fits
    # every VFIFE static run against the VFIFE limit (discretisation + relaxation error)
    for r in st.runs:
        if r.setting.method == "vfife" and r.values:
            r.self_errors.update(rel_errors(r.values, limits, depth, norm_values=st.ref_values))
    # curve distance to the finest run of the order sweep (no extrapolation of a curve)
    fin = order_sweep[-1].profile
    for r in st.runs:
        if r.setting.method == "vfife" and r.profile is not None:
            lo, hi = max(fin.s[0], r.profile.s[0]), min(fin.s[-1], r.profile.s[-1])
            r.self_errors["curve_distance"] = curve_distance(fin, r.profile, (lo, hi))[0] / depth
    cd_all = [(r.setting.value, r.self_errors["curve_distance"]) for r in order_sweep[:-1]]
    cd = [(h, e) for h, e in cd_all if h <= st.boundary_layer]
    st.orders["curve_distance"] = fit_order([h for h, _ in cd], [e for _, e in cd],
                                            floor.get("curve_distance", 0.0))
    st.orders["curve_distance"].update(_fit_context(
        [h for h, _ in cd_all], [e for _, e in cd_all], st.boundary_layer,
        floor.get("curve_distance", 0.0)))
    st.orders["curve_distance"]["note"] = "vs the finest VFIFE curve"
    st.model_difference = rel_errors(limits, st.ref_values, depth)


def boundary_layer_length(vf_scene: Scene, s_shift: float, ref: Profile) -> float:
    """Length of the bending boundary layer at the touchdown [m]: sqrt(EI/T) with the
    touchdown tension of the BVP profile ``ref`` and the EI of the VFIFE scene's section
    there (a line without touchdown: the lowest tension along the line). The quantities
    of the order fit are decided around the touchdown and the sag bend, where the tension
    is lowest and this length the longest; elements longer than it do not resolve the
    curvature there, so their errors are pre-asymptotic (Wang baseline: 7.8 m; Yu A3:
    27 m). ``s_shift``: the VFIFE arc length minus the BVP one."""
    EI, T = _touchdown_section(vf_scene, s_shift, ref)
    return math.sqrt(EI / max(T, 1e-9))


def foundation_length(vf_scene: Scene, s_shift: float, ref: Profile) -> float | None:
    """Foundation length (4 EI/k)^(1/4) [m] of the penalty seabed at the touchdown (None
    without a seabed): the length over which the line settles into the seabed spring."""
    if vf_scene.seabed is None or vf_scene.seabed.stiffness <= 0.0:
        return None
    EI, _ = _touchdown_section(vf_scene, s_shift, ref)
    return (4.0 * EI / vf_scene.seabed.stiffness) ** 0.25


def _touchdown_section(vf_scene: Scene, s_shift: float, ref: Profile) -> tuple[float, float]:
    """(EI [N m2], |T| [N]) at the touchdown of the BVP profile ``ref`` (else at its lowest
    tension)."""
    from vfife.mesh import build_mesh
    mesh = build_mesh(vf_scene, 10.0)
    mid = 0.5 * (mesh.s[1:] + mesh.s[:-1]) - s_shift
    if ref.tdp_s is not None:
        s0 = ref.tdp_s
    else:
        s0 = float(ref.s[int(np.argmin(np.abs(ref.tension)))])
    T = abs(float(np.interp(s0, ref.s, ref.tension)))
    return float(mesh.EI[int(np.argmin(np.abs(mid - s0)))]), T


#: why a quantity's observed order may differ from 2 (quoted in the report only where it does)
DEPARTURE = {
    "tdp_x": "the line meets the seabed tangentially with almost zero curvature (the moment "
             "is continuous and vanishes on the flat seabed), so near the touchdown "
             "y ~ c (s - s_tdp)^3 and a height error e moves the crossing of y = 0 by "
             "~(e/c)^(1/3): with O(h^2) heights the position converges like h^(2/3), and it "
             "is read off the piecewise-linear nodal line (O(h) on a tangent curve); and "
             "elements longer than the foundation length of the penalty seabed (see above) "
             "do not resolve the contact zone, so the touchdown keeps moving until they are "
             "shorter. An ill-conditioned output, not a low-order solver: the tension, "
             "moment and heights around it converge at order 2",
    "tdp_tension": "taken at the touchdown position, which converges slowly (see touchdown "
                   "position); the tension gradient there (w sin(theta) plus the tangential "
                   "drag) is small, so the error mixes the O(h^2) tension with the slow "
                   "touchdown position, in proportions that change with the mesh",
    "hang_off_tension": "the weight is lumped exactly (the total weight is right on every "
                        "mesh), so the hang-off tension errs only through the shape. In a "
                        "current the drag on the suspended length ties it to the touchdown "
                        "position, which converges slowly while the elements are longer "
                        "than the foundation length of the penalty seabed (see touchdown "
                        "position); without one its errors are small and few lengths lie "
                        "above the noise margin",
    "max_moment": "the peak moment is a maximum over the line: where two peaks (crest and "
                  "sag bend, or the touchdown region) are nearly equal, the peak taken can "
                  "change between meshes and the error jumps between their error curves",
    "crest_height": "the worst of several crests: each converges at order 2 with its own "
                    "constant, and the worst one can switch between meshes",
    "sag_height": "the worst of several sag bends: each converges at order 2 with its own "
                  "constant, and the worst one can switch between meshes; in a current the "
                  "line's position also follows the slowly converging touchdown (see "
                  "touchdown position)",
    "curve_distance": "measured against the finest VFIFE curve, not an extrapolated limit: "
                      "the finest run's own error, (h_finest/h)^2 of the error at h, cancels "
                      "part of the error of the nearest lengths and lowers the slope",
}


def order_assessment(q: str, fit: dict) -> str:
    """One phrase on a fitted order: expected, or why not (see :data:`DEPARTURE`)."""
    p, n = fit.get("order"), len(fit.get("points", []))
    if p is None and fit.get("below_noise") is not None:
        return (f"converged beyond measurement: every element length within the boundary "
                f"layer errs by at most {fit['below_noise']:.1e}, below {NOISE_MARGIN:g}x "
                f"the relaxation error ({fit['noise_margin']:.1e}); nothing to fit")
    m = fit.get("n_inside", 0)
    if p is None and m < 2:
        return (f"not fitted: only {m} element length(s) coarser than the finest lie within "
                "the boundary layer (see the local orders)")
    if p is None:
        return (f"not fitted: {n} of the {m} element lengths within the boundary layer err by "
                f"more than {NOISE_MARGIN:g}x the relaxation error; the others have converged "
                "to it (see the local orders)")
    good = abs(p - EXPECTED_ORDER) <= ORDER_BAND and (fit.get("r2") or 0.0) >= 0.9
    pts = set(fit.get("points", []))
    inner = [lp for a, b, lp in fit.get("local", []) if a in pts and b in pts]
    scatter = [lp for lp in inner if abs(lp - EXPECTED_ORDER) > 2.0 * ORDER_BAND]
    if good and n >= 3 and scatter:
        why = DEPARTURE.get(q, "")
        return (f"order {EXPECTED_ORDER:g} on average, but the local orders in the fit "
                f"scatter ({min(inner):.2f} to {max(inner):.2f})" + (f": {why}" if why else ""))
    if good and n >= 3:
        return f"order {EXPECTED_ORDER:g}, as expected"
    if good:
        return (f"order {EXPECTED_ORDER:g}, as expected, but from two points only (no third "
                "to check the slope)")
    why = DEPARTURE.get(q, "")
    few = " (two points only)" if n < 3 else ""
    return f"differs{few}: {why}" if why else f"differs{few}"


def _scaling(st: CostStudy) -> None:
    """Cost exponents: wall time ~ elements^a (statics, 1 s of dynamics), steps ~ n^b."""
    for kind, setting in (("statics", "element_length"),
                          ("statics_tight", "element_length_tight"),
                          ("dynamics_1s", "dynamics_1s_element_length")):
        rs = [r for r in st.runs if r.setting.setting == setting and r.converged and r.size
              and r.times]
        if len(rs) < 2:
            continue
        n = np.array([r.size for r in rs], float)
        t = np.array([r.wall_time_s for r in rs])
        out = {"elements": n.tolist(), "time": t.tolist()}
        out["exponent_all"] = float(np.polyfit(np.log(n), np.log(t), 1)[0])
        fine = n >= np.sort(n)[-min(3, len(n))]
        out["exponent_fine"] = float(np.polyfit(np.log(n[fine]), np.log(t[fine]), 1)[0])
        steps = np.array([r.steps or np.nan for r in rs], float)
        if np.all(np.isfinite(steps)):
            out["steps"] = steps.tolist()
            out["steps_exponent_fine"] = float(np.polyfit(np.log(n[fine]), np.log(steps[fine]),
                                                          1)[0])
            out["us_per_element_step"] = (1e6 * t / (n * steps)).tolist()
        st.scaling[kind] = out


# ----------------------------------------------------------------------------- analysis
def recommendations(st: CostStudy) -> list[dict]:
    """Cheapest converged run of each method reaching each target in peak moment and
    hang-off tension: against the BVP reference (both methods) and, for VFIFE, against
    its own limit (discretisation error only)."""
    out = []
    stat = [r for r in st.runs if r.converged and r.values and r.setting.method != "vfife-dyn"]
    for q in ("max_moment", "hang_off_tension"):
        for tgt in TARGETS:
            row = {"quantity": q, "target": tgt}
            for key, method, errs in (("bvp", "bvp", "errors"), ("vfife", "vfife", "errors"),
                                      ("vfife_self", "vfife", "self_errors")):
                ok = [r for r in stat if r.method == method and getattr(r, errs).get(q)
                      is not None and getattr(r, errs)[q] <= tgt]
                if method == "bvp":   # the reference itself is not a recommendation
                    ok = [r for r in ok if r is not st.reference] or (
                        [st.reference] if st.reference in ok else [])
                best = min(ok, key=lambda r: r.wall_time_s) if ok else None
                row[key] = best
            out.append(row)
    return out


def pareto(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Non-dominated (time, error) points, sorted by time."""
    front, best = [], float("inf")
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front


# ----------------------------------------------------------------------------- output
def _label(r: Run | None) -> str:
    if r is None:
        return "not reached"
    s = r.setting
    v = f"{s.value:g}"
    ctx = ""
    h = s.solve_kwargs.get("element_length")
    if s.setting != "element_length" and h is not None:
        ctx = f", element length {h:g} m"
    if s.setting.startswith("element_length_tight"):
        ctx = (f", static tolerance {s.solve_kwargs.get('tolerance'):g}, creep tolerance "
               f"{s.vfife_changes.get('creep_tolerance'):g}")
    elif s.method == "bvp" and s.setting != "tolerance":
        ctx = f", tolerance {s.solve_kwargs.get('tolerance'):g}"
    return f"{s.setting} = {v}{ctx} ({r.wall_time_s:.3g} s)"


def report_markdown(st: CostStudy) -> str:
    sc = st.scene
    ref = st.reference
    compile_s = next((r.compile_time_s for r in st.runs if r.method == "vfife"), 0)
    L = [f"# Accuracy versus cost: `{sc.name}`", "", GENERATED_NOTE, "",
         f"- Scene: {sc.title or sc.name}.",
         f"- Reference: BVP at tolerance {ref.setting.value:g} ({ref.size} nodes, "
         f"{ref.wall_time_s:.2f} s). Lengths are normalised by {st.depth:.1f} m "
         f"({'water depth' if sc.water_depth else 'hang-off height'}); tensions and moment "
         "by the reference value.",
         f"- Timing: median of {st.repeats} runs after a warm-up; the Numba compilation (or "
         f"cache load) of VFIFE, {compile_s:.2f} s "
         "in this process, is reported separately (`compile_time_s`). Runs that did not "
         "converge are timed once. Study wall time "
         f"{st.elapsed_s:.0f} s.",
         "- Errors are fractions (1e-3 = 0.1 %). `err_*`: against the BVP reference; "
         "`self_*`: against the method's own converged limit (VFIFE: Richardson "
         "extrapolation of the three finest element lengths).", ""]
    L += [f"- {n}" for n in st.notes]
    failed = [r for r in st.runs if not r.converged]
    if failed:
        L += ["", "Runs that did not converge (kept in `runs.csv`, excluded from fits and "
              "recommendations):", ""]
        L += [f"- {r.method} {r.setting.setting} = {r.setting.value:g}: {r.message} "
              f"({r.wall_time_s:.2f} s)" for r in failed]
    # recommendation
    L += ["", "## Recommendation", "",
          "Cheapest setting reaching each accuracy (among the runs below). 'VFIFE vs BVP' "
          "includes the model difference (a VFIFE entry reaching a target below the model "
          "difference is a cancellation of discretisation or relaxation error against it, "
          "not accuracy); 'VFIFE discretisation' is the error against VFIFE's own limit. "
          "BVP entries: its error against the finest tolerance.", ""]
    rows = []
    for rec in recommendations(st):
        rows.append((QUANTITY_LABEL[rec["quantity"]], f"{100 * rec['target']:g} %",
                     _label(rec["bvp"]), _label(rec["vfife"]), _label(rec["vfife_self"])))
    L.append(md_table(["quantity", "accuracy", "BVP", "VFIFE vs BVP reference",
                       "VFIFE discretisation"], rows))
    # self convergence / model difference
    hmid = next((r.setting.value for r in st.runs
                 if r.setting.setting == "element_length_tight_check"), None)
    hm = f"{hmid:g} m" if hmid is not None else "the middle element length"
    L += ["", "## Self-convergence and model difference", "",
          "Per quantity: the reference's own uncertainty (change from the next-finer BVP "
          "tolerance), the VFIFE Richardson order (three finest element lengths of the order "
          "sweep below), the relative difference between the VFIFE limit and the BVP "
          "reference (the model difference: extensible line and penalty seabed vs "
          "inextensible, rigid seabed), and the VFIFE relaxation error at "
          f"{hm}: the change of the result from the default tolerances, and from the order "
          "sweep's, to a run with both tolerances of the order sweep 10x tighter "
          "(`element_length_tight_check`). The `self_*` columns of every VFIFE run are "
          "against the VFIFE limit, so they contain the discretisation and the relaxation "
          "error.", ""]
    rows = []
    for q in QUANTITIES:
        fam = _family(q, st.ref_values) if q != "curve_distance" else []
        rorder = [st.vfife_richardson_order.get(k) for k in fam]
        rtxt = ", ".join("n/a" if p is None else f"{p:.2f}" for p in rorder)
        rows.append((QUANTITY_LABEL[q], st.bvp_self.get(q), rtxt,
                     st.model_difference.get(q), st.noise_floor.get(q),
                     st.sweep_noise.get(q)))
    L.append(md_table(["quantity", "BVP reference uncertainty", "VFIFE Richardson order",
                       "model difference (VFIFE limit vs BVP)",
                       "VFIFE relaxation error, default tolerances",
                       "... order-sweep tolerances"], rows))
    if st.bvp_self.get("tdp_tension") == 0.0:
        L += ["", "The BVP touchdown tension and position are inputs of this scene (ends "
              "given as the touchdown tension), hence exact on every tolerance."]
    # orders
    bl = st.boundary_layer
    L += ["", "## Observed VFIFE order in element length", "",
          f"Expected order: {EXPECTED_ORDER:g}. The VFIFE line is a chain of straight "
          "elements with lumped nodal mass and weight, element forces constant along an "
          "element (belonging to its midpoint) and the bending moment from the element-end "
          "rotations relative to the chord: each is a midpoint/central-difference "
          "approximation of the continuous beam, with errors O(h^2) (nodal averages and the "
          "end extrapolation of the forces are second order too; the peak moment and the "
          "crest and sag heights are located by a parabola through three nodal values).", "",
          f"Sweep used: `{st.order_setting}` rows ({st.order_sweep}; one run per element "
          "length, timed like every run). The error of each element length is against the "
          "Richardson limit of the three finest ones, so the finest is not fitted. A point "
          "enters the fit only if (i) its element length is at most the bending boundary "
          f"layer sqrt(EI/T) = {bl:.3g} m at the touchdown (longer elements do not resolve "
          "the touchdown and sag-bend curvature, so their errors are pre-asymptotic), "
          f"(ii) its error is at most {PRE_ASYMPTOTIC:g}, and (iii) its error is at least "
          f"{NOISE_MARGIN:g}x the order sweep's relaxation error above (then the noise moves "
          f"the log error by <= 0.1). Orders within +/-{ORDER_BAND:g} of "
          f"{EXPECTED_ORDER:g} with R^2 >= 0.9 over three or more points count as expected; "
          "every other row says why. Local orders in parentheses involve a length left out "
          "of the fit (pre-asymptotic, or with an error at the relaxation error)."
          + (f" The foundation length of the penalty seabed, (4 EI/k)^(1/4), is "
             f"{st.foundation_length:.3g} m." if st.foundation_length else ""), ""]
    rows = []
    for q, f in st.orders.items():
        pts = set(f.get("points", []))
        local = ", ".join((f"{a:g}-{b:g}: {p:.2f}" if a in pts and b in pts
                           else f"({a:g}-{b:g}: {p:.2f})") for a, b, p in f.get("local", []))
        rows.append((QUANTITY_LABEL[q], f["order"], ", ".join(f"{h:g}" for h in f["points"]),
                     f.get("r2"), local, f.get("note", "vs the Richardson limit"),
                     order_assessment(q, f)))
    L.append(md_table(["quantity", "fitted order", "element lengths in the fit [m]", "R^2",
                       "local orders (successive lengths [m])", "error measured",
                       "assessment"], rows))
    # scaling
    L += ["", "## Cost scaling", ""]
    rows = []
    for kind, s in st.scaling.items():
        rows.append((kind.replace("_", " "), s["exponent_all"], s["exponent_fine"],
                     s.get("steps_exponent_fine"),
                     ", ".join(f"{t:.3g}" for t in s["time"])))
    L.append(md_table(["run", "time ~ n^a, all meshes", "a, three finest meshes",
                       "steps ~ n^b (three finest)", "times [s] (coarse to fine)"], rows))
    L += ["", "Statics by explicit dynamic relaxation: cost = steps x cost per step; the cost "
          "per step is proportional to the number of elements n, and the stable step to "
          "the element length (axial wave), so the number of steps grows like n at best "
          "(time ~ n^2); one second of dynamics has the same step limit (time ~ n^2). The "
          "BVP cost grows with the number of collocation nodes that the tolerance needs.",
          ""]
    # tables of runs
    L += ["## Runs", ""]
    for method in ("bvp", "vfife"):
        rows = []
        for r in st.runs:
            if r.method != method:
                continue
            rows.append((r.setting.setting, r.setting.value, r.size, r.steps, r.wall_time_s,
                         *(r.errors.get(q) for q in QUANTITIES),
                         r.self_errors.get("max_moment"), "yes" if r.converged else "**no**"))
        L += [f"### {method.upper()}", "",
              md_table(["setting", "value", "nodes/elements", "steps", "time [s]",
                        *(QUANTITY_LABEL[q] for q in QUANTITIES), "self: peak moment",
                        "converged"], rows), ""]
    L += ["## Figures", "", "![error vs wall time](error_vs_time.png)", "",
          "![error vs element length](error_vs_element_length.png)", "",
          "![time vs elements](time_vs_elements.png)", "",
          "Files: `runs.csv` (one row per run: " + ", ".join(f"`{c}`" for c in RUN_COLUMNS)
          + ", then " + ", ".join(f"`{c}`" for c in EXTRA_COLUMNS) + "), `values.csv` (the "
          "raw quantities of every run and of the reference).", ""]
    return "\n".join(L)


def _plots(st: CostStudy, out: Path) -> None:
    colors = {"bvp": "C0", "vfife": "C1"}
    fig, axes = new_figure(1, 2, (12, 5))
    for ax, q in zip(axes[0], ("max_moment", "hang_off_tension")):
        pts = []
        for method in ("bvp", "vfife"):
            rs = [r for r in st.runs if r.method == method and r.converged and r.values
                  and r.errors.get(q) and r is not st.reference]
            t = [r.wall_time_s for r in rs]
            e = [r.errors[q] for r in rs]
            ax.loglog(t, e, "o", color=colors[method], alpha=0.7, label=method.upper())
            pts += list(zip(t, e))
        fr = pareto(pts)
        if fr:
            ax.step([p[0] for p in fr], [p[1] for p in fr], where="post", color="k", lw=1,
                    label="Pareto front")
            ax.plot([p[0] for p in fr], [p[1] for p in fr], "s", mfc="none", mec="k", ms=9)
        md = st.model_difference.get(q)
        if md:
            ax.axhline(md, color=colors["vfife"], ls=":", label="model difference")
        ax.set_xlabel("wall time [s] (median)")
        ax.set_ylabel(f"relative error in {QUANTITY_LABEL[q]} vs BVP reference")
        ax.set_title(f"{st.scene.name}: {QUANTITY_LABEL[q]}")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    save(fig, out / "error_vs_time.png")

    el = sorted([r for r in st.runs if r.setting.method == "vfife"
                 and r.setting.setting == st.order_setting and r.values],
                key=lambda r: r.setting.value)
    fig, axes = new_figure(1, 1, (8, 5.5))
    ax = axes[0, 0]
    for i, (q, f) in enumerate(st.orders.items()):
        hs = [r.setting.value for r in el if r.self_errors.get(q)]
        es = [r.self_errors[q] for r in el if r.self_errors.get(q)]
        if not hs:
            continue
        c = f"C{i}"
        lab = QUANTITY_LABEL[q] + (f" (order {f['order']:.2f})" if f["order"] is not None
                                   else "")
        ax.loglog(hs, es, "o-", color=c, lw=0.8, label=lab)
        if f["order"] is not None:
            hh = np.array(f["points"])
            ax.loglog(hh, np.exp(f["const"]) * hh ** f["order"], "--", color=c, lw=1.5)
    if el:
        h = np.array([r.setting.value for r in el])
        ax.loglog(h, 1e-4 * (h / h.max()) ** 2, "k:", label="slope 2")
        if h.min() < st.boundary_layer < h.max():
            ax.axvline(st.boundary_layer, color="0.5", ls="-.", lw=1,
                       label=f"boundary layer sqrt(EI/T) = {st.boundary_layer:.3g} m "
                       "(fit: shorter elements only)")
    ax.set_xlabel("element length [m]")
    ax.set_ylabel("relative self-convergence error (vs VFIFE limit)")
    ax.set_title(f"{st.scene.name}: VFIFE convergence in element length\n(`{st.order_setting}` "
                 "rows; dashed: fitted order)", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    save(fig, out / "error_vs_element_length.png")

    fig, axes = new_figure(1, 1, (8, 5))
    ax = axes[0, 0]
    for kind, s in st.scaling.items():
        n, t = np.array(s["elements"]), np.array(s["time"])
        ax.loglog(n, t, "o-", label=f"{kind.replace('_', ' ')} (exponent "
                  f"{s['exponent_fine']:.2f} fine, {s['exponent_all']:.2f} all)")
    bv = [r for r in st.runs if r.method == "bvp" and r.setting.setting == "tolerance"
          and r.converged]
    if bv:
        ax.loglog([r.size for r in bv], [r.wall_time_s for r in bv], "s--", color="C0",
                  alpha=0.6, label="BVP (nodes, tolerance sweep)")
    ax.set_xlabel("number of elements (VFIFE) / nodes (BVP)")
    ax.set_ylabel("wall time [s]")
    ax.set_title(f"{st.scene.name}: cost scaling")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    save(fig, out / "time_vs_elements.png")


def write(st: CostStudy, out_dir: str | Path) -> None:
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    st.frame().to_csv(out / "runs.csv", index=False, float_format="%.6g")
    st.values_frame().to_csv(out / "values.csv", index=False, float_format="%.10g")
    _plots(st, out)
    (out / "report.md").write_text(report_markdown(st))


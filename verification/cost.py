"""What accuracy costs in time: convergence and cost study of both methods on one scene.

``riser-verify cost SCENE [--out DIR]`` (default ``reports/cost/SCENE/``) writes
``runs.csv``, ``values.csv``, ``report.md`` and three plots. This module runs the study;
:mod:`verification.cost_fit` holds the quantities, errors and fits, and
:mod:`verification.cost_report` the report, plots and CSV files.

Protocol
--------
- One model for both methods. A fixed-ends scene is solved as it is; a Wang-form scene
  (touchdown tension, or hang-off angle) is first solved by the BVP in its own form
  (inextensible on a rigid seabed, the paper's model) only to place the hang-off, then
  converted to fixed ends with 300 m of line on an elastic seabed ahead of the touchdown
  (:func:`verification.equivalence.fixed_ends_from_bvp`). Both methods then solve that
  same continuum model: extensible line on the scene's elastic (Winkler) seabed.
- Settings swept. VFIFE: element length (20 ... 0.5 m), time-step safety factor, static
  tolerance, relaxation scheme (coarse-mesh sequencing, rotational-inertia scale), and the
  cost of one second of dynamics per element length. BVP: ``solve_bvp`` tolerance
  (1e-2 ... 1e-8), initial mesh size, node cap. Every setting not swept keeps its default.
- Timing: one global warm-up (Numba compilation, or its on-disk cache load, reported as
  ``compile_time_s``), then the median of ``repeats`` runs (the solvers' own
  ``wall_time_s``). A run that does not converge, or takes longer than
  :data:`REPEAT_BELOW_S`, is timed once.
- Errors (runs.csv ``err_*``): against the reference, the BVP of the same scene at the
  finest tolerance, as fractions: tensions and moment relative to the reference value;
  touchdown position, crest and sag heights and the curve distance relative to the water
  depth (else the hang-off height). Same model and same arc length, so a VFIFE error is
  its discretisation and relaxation error only.
- Self-convergence (``self_*``): VFIFE runs against VFIFE's own limit, Richardson-
  extrapolated from the three finest element lengths of the order sweep (the curve
  distance against the finest curve); BVP runs against the reference. The VFIFE limit
  against the BVP reference is a consistency check of the two methods.
- Observed VFIFE order: slope of log(error vs the reference) against log(element length)
  over the order sweep (``element_length_tight``: static and creep tolerances tight enough
  that the relaxation error is far below the discretisation error). A length enters the
  fit if it is not longer than the asymptotic length (the shorter of the bending boundary
  layer sqrt(EI/T) at the touchdown and the seabed's foundation length (4 EI/k)^(1/4)),
  its error is at most 1e-2, and at least 10x both the relaxation error of the sweep
  (measured at the middle length against a run with both tolerances 10x tighter,
  ``element_length_tight_check``) and the reference's own uncertainty. The report gives
  the local orders of successive lengths too, and says per quantity why an order differs
  from 2.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from riser.profile import summarize
from riser.scene import Scene

# re-exported (callers and tests use them as cost.NAME)
from .cost_fit import (NOISE_MARGIN, QUANTITIES, asymptotic_length,  # noqa: F401
                       boundary_layer_length, densified, distance, element_length_fits,
                       fit_order, foundation_length, liftoff_interpolation, order_assessment,
                       pareto, raw_values, rel_errors, richardson, richardson_limits,
                       signed_errors, worst_mesh)
from .cost_runs import (BVP_TOLERANCES, CHECK_FACTOR, ELEMENT_LENGTHS,  # noqa: F401
                        ORDER_LENGTHS, REPEAT_BELOW_S, TIGHT_CREEP, TIGHT_TOLERANCE, Progress,
                        Run, Setting, default_settings, predicted_cost, run_setting)

# scenes of the study (reproduce all)
COST_SCENES = ("wang2014-baseline", "yu2021-a3", "yu2021-a2-sheared")

RUN_COLUMNS = ("method", "setting", "value", "wall_time_s", "compile_time_s",
               *(f"err_{q}" for q in QUANTITIES))
EXTRA_COLUMNS = ("converged", "repeats", "size", "steps", *(f"self_{q}" for q in QUANTITIES),
                 "message")

TARGETS = (1e-2, 1e-3, 1e-4)


@dataclass
class CostStudy:
    scene: Scene                     # as given
    fixed_scene: Scene               # the fixed-ends scene both methods solve
    depth: float
    repeats: int
    runs: list
    reference: Run
    ref_values: dict
    paper_difference: dict = field(default_factory=dict)  # Wang form vs the reference
    bvp_self: dict = field(default_factory=dict)       # quantity -> rel. uncertainty of ref
    vfife_limit: dict = field(default_factory=dict)    # raw key -> Richardson limit
    vfife_richardson_order: dict = field(default_factory=dict)
    limit_vs_reference: dict = field(default_factory=dict)   # quantity -> rel. difference
    orders: dict = field(default_factory=dict)         # quantity -> fit dict
    noise_floor: dict = field(default_factory=dict)    # quantity -> rel. relaxation error
    sweep_noise: dict = field(default_factory=dict)    # ... of the order sweep
    boundary_layer: float = math.inf                    # [m], sqrt(EI/T) at the touchdown
    foundation_length: float | None = None              # [m], (4 EI/k)^(1/4)
    asymptotic: float = math.inf                        # [m], fit range h <= this
    liftoff: dict | None = None                         # see cost_fit.liftoff_interpolation
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
    paper = None
    if scene.ends.kind != "fixed":
        t0 = time.perf_counter()
        paper = bvp.solve(scene)
        if not paper.converged:
            raise RuntimeError(f"cannot build the fixed-ends scene: the BVP did not converge "
                               f"({paper.message})")
        fixed = fixed_ends_from_bvp(scene, paper, DEFAULT_SEABED_LENGTH)
        notes.append(f"Both methods solve the fixed-ends equivalent of the scene "
                     f"({fixed_ends_note(scene, fixed, DEFAULT_SEABED_LENGTH)}; the seabed "
                     f"is a property of the soil, the same for every run of both methods; "
                     f"conversion {time.perf_counter() - t0:.2f} s, in no run's time).")
    else:
        fixed = scene
    # BVP first: its finest tolerance is the reference, whose touchdown sets the order sweep
    given = settings is not None
    if settings is None:
        settings = default_settings(fixed, quick, element_lengths)
    order = {"bvp": 0, "vfife": 1, "vfife-dyn": 2}
    settings = sorted(settings, key=lambda s: order[s.method])
    prog = Progress(len(settings), scene.name, stream,
                    [predicted_cost(s) for s in settings]) if progress else None
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
                    fixed, quick, element_lengths, asym) if t.method != "bvp"]
                if prog:
                    prog.plan([predicted_cost(t) for t in settings[i:]])
                s = settings[i]
        run = run_setting(s, fixed, repeats, compile_s, static_cache)
        runs.append(run)
        if prog:
            prog.step(f"{run.method} {s.setting}={s.value:g}: "
                      f"{run.wall_time_s:.3g} s" + ("" if run.converged else ", not converged"))
        i += 1
    ref = ref or _reference(runs, scene)
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
    st = CostStudy(scene, fixed, depth, repeats, runs, ref, ref_values, notes=notes)
    if paper is not None:
        psm = paper.summary()
        st.paper_difference = {q: (psm[q] - ref_sm[q]) / abs(ref_sm[q])
                               for q in ("hang_off_tension", "max_moment")}
    _analyse(st)
    _scaling(st)
    st.elapsed_s = time.perf_counter() - t_start
    return st


def _reference(runs: list, scene: Scene) -> Run:
    """The finest converged BVP tolerance."""
    bvp_tol = [r for r in runs if r.setting.method == "bvp" and r.setting.setting == "tolerance"
               and r.converged]
    if not bvp_tol:
        raise RuntimeError(f"no BVP run converged on {scene.name}: no reference")
    return min(bvp_tol, key=lambda r: r.setting.value)


def _sweep(st: CostStudy, name: str) -> list:
    return sorted([r for r in st.runs if r.setting.method == "vfife"
                   and r.setting.setting == name and r.values],
                  key=lambda r: -r.setting.value)


def _analyse(st: CostStudy) -> None:
    """Reference uncertainty, relaxation errors, orders, VFIFE limit and self errors."""
    depth = st.depth
    bvp_tol = sorted([r for r in st.runs if r.setting.method == "bvp" and r.values
                      and r.setting.setting == "tolerance"], key=lambda r: r.setting.value)
    # BVP: every run against the reference; the reference's own uncertainty is its change
    # from the next-finest tolerance
    for r in st.runs:
        if r.method == "bvp" and r.values:
            r.self_errors = dict(r.errors)
    if len(bvp_tol) >= 2:
        st.bvp_self = dict(bvp_tol[1].errors)
    default, tight = _sweep(st, "element_length"), _sweep(st, "element_length_tight")
    # relaxation error, measured against a run with both tolerances 10x tighter than the
    # order sweep's at the middle element length: of the default settings (noise_floor)
    # and of the order sweep (sweep_noise, part of the floor of the fit)
    check = next((r for r in st.runs if r.setting.setting == "element_length_tight_check"
                  and r.converged and r.values), None)
    if check is not None:
        hmid = check.setting.value
        for attr, rs in (("noise_floor", default), ("sweep_noise", tight)):
            base = next((r for r in rs if math.isclose(r.setting.value, hmid)), None)
            if base is not None:
                err = rel_errors(base.values, check.values, depth)
                err["curve_distance"] = distance(check.profile, base.profile, depth)
                setattr(st, attr, {q: (v if v is not None else 0.0) for q, v in err.items()})
    if len(tight) >= 3:
        order_sweep = tight
        label = (f"static tolerance {TIGHT_TOLERANCE:g} x element weight and creep tolerance "
                 f"{TIGHT_CREEP:g} x line length, mesh sequencing as by default")
        noise = st.sweep_noise
    else:
        order_sweep, label, noise = default, "default static and creep tolerances", \
            st.noise_floor
    st.order_sweep = label
    st.order_setting = order_sweep[0].setting.setting if order_sweep else ""
    prof = st.reference.profile
    st.boundary_layer = boundary_layer_length(st.fixed_scene, prof)
    st.foundation_length = foundation_length(st.fixed_scene, prof)
    st.asymptotic = asymptotic_length(st.fixed_scene, prof)
    st.liftoff = liftoff_interpolation(prof)
    if len(order_sweep) < 2:
        return
    floor = {q: NOISE_MARGIN * max(noise.get(q, 0.0), st.bvp_self.get(q) or 0.0)
             for q in QUANTITIES}
    hs = [r.setting.value for r in order_sweep]
    errors = {q: [r.errors.get(q) for r in order_sweep] for q in QUANTITIES
              if any(r.errors.get(q) is not None for r in order_sweep)}
    st.orders = element_length_fits(hs, errors, floor, st.asymptotic)
    signed = [signed_errors(r.values, st.ref_values, depth) for r in order_sweep]
    for q, fit in st.orders.items():
        fit["signed"] = [sg.get(q) for h, sg in zip(hs, signed) if h in fit["points"]]
    # VFIFE's own limit (Richardson, three finest lengths): self errors, consistency check
    limits, rorders = richardson_limits(hs, [r.values for r in order_sweep])
    st.vfife_limit, st.vfife_richardson_order = limits, rorders
    st.limit_vs_reference = rel_errors(limits, st.ref_values, depth)
    for r in st.runs:
        if r.setting.method == "vfife" and r.values:
            r.self_errors.update(rel_errors(r.values, limits, depth, norm_values=st.ref_values))
    fin = order_sweep[-1].profile
    for r in st.runs:
        if r.setting.method == "vfife" and r.profile is not None:
            r.self_errors["curve_distance"] = distance(fin, r.profile, depth)


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


def recommendations(st: CostStudy) -> list[dict]:
    """Cheapest converged run of each method reaching each target in each quantity, against
    the BVP reference (for the BVP: its error against its finest tolerance)."""
    out = []
    stat = [r for r in st.runs if r.converged and r.values and r.setting.method != "vfife-dyn"]
    for q in QUANTITIES:
        if all(r.errors.get(q) is None for r in stat):
            continue
        for tgt in TARGETS:
            row = {"quantity": q, "target": tgt}
            for method in ("bvp", "vfife"):
                ok = [r for r in stat if r.method == method and r.errors.get(q) is not None
                      and r.errors[q] <= tgt]
                if method == "bvp":   # the reference itself is not a recommendation
                    ok = [r for r in ok if r is not st.reference] or (
                        [st.reference] if st.reference in ok else [])
                row[method] = min(ok, key=lambda r: r.wall_time_s) if ok else None
            out.append(row)
    return out


def write(st: CostStudy, out_dir) -> None:
    """``runs.csv``, ``values.csv``, ``report.md`` and the plots into ``out_dir``."""
    from .cost_report import write as _write
    _write(st, out_dir)


"""The dynamics section of the cost report (:func:`section`), its figure
(:func:`plot`, ``dynamics_error.png``) and ``dynamics.csv`` (:func:`write`)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from verification.report.figures import new_figure, save
from verification.report.markdown import md_table

from .assessment import EXPECTED_ORDER, ORDER_BAND
from .dynamics import (
    CSV_COLUMNS,
    CSV_EXTRA,
    DURATION,
    FULL_DYNAMICS,
    HEAVE_AMPLITUDE,
    HEAVE_PERIOD,
    ORDER_FACTORS,
    ORDER_LENGTH,
    QUANTITIES,
    QUANTITY_LABEL,
    STATISTICS_START,
    DynRun,
    DynStudy,
)
from .dynamics_analysis import (
    MATTERS,
    MATTERS_ABOVE,
    RICHARDSON_ORDERS,
    STEP_SHARE,
    recommendations,
)
from .fits import NOISE_MARGIN, PRE_ASYMPTOTIC

CSV = "dynamics.csv"
FIGURE = "dynamics_error.png"


def _run_label(r: DynRun) -> str:
    return f"{r.h:g} m, factor {r.factor:g} ({r.wall_s:.3g} s)"


def _cell(cell, q: str | None = None) -> str:
    kind, x = cell
    if kind == "uncertain":
        return (f"below the reference's uncertainty ({x:.1e})" if x is not None else
                "not judged: the reference's uncertainty is unknown")
    if kind == "not reached":
        return "not reached"
    errs = [x.errors[k] for k in ((q,) if q else QUANTITIES)]
    return f"{_run_label(x)}, error {max(errs):.1e}"


def section(st, ds: DynStudy | None) -> list[str]:
    """Markdown lines of the dynamics section of the cost report."""
    L = ["## Dynamics: accuracy and cost against element length and time-step factor", ""]
    if ds is None or not ds.runs:
        return L + ["No dynamic sweep in this study (given settings)."]
    f0 = ds.default_factor
    L += [f"Every run: {DURATION:g} s of a {HEAVE_AMPLITUDE:g} m heave of the hang-off at "
          f"{HEAVE_PERIOD:g} s (half-cosine ramp over the first period), from the VFIFE "
          "static state of its own element length (the statics are not in its time); "
          f"statistics from {STATISTICS_START:g} s to the end (two periods), sampled every "
          f"{HEAVE_PERIOD / 40:g} s on every mesh. The same motion and window for every "
          "run, so only the discretisation changes. Quantities: the hang-off tension "
          "amplitude (half the range of the hang-off tension over the window) and the peak "
          "moment (the largest nodal moment over the window). The step factor is `[vfife] "
          f"time_step_safety`, the time step over the critical step ({f0:g} by default); "
          "errors are fractions of the reference value. Timings are wall times of this "
          "run (see Timing above), so speed claims are ratios of runs measured side by "
          "side here."]
    if ds.sweep in ("fast", "quick"):
        L += ["", f"Fast sweep: `--full` adds {FULL_DYNAMICS}."]
    bad = [r for r in ds.runs if not r.converged]
    if bad:
        L += ["", "Runs that failed (kept in `dynamics.csv`, excluded from the analysis):", ""]
        L += [f"- {r.h:g} m, factor {r.factor:g}: {r.message}" for r in bad]
    if ds.ref_run is None:
        return L + ["", "No dynamic run completed: nothing to analyse."]
    L += ["", "### Recommendation (dynamics)", "",
          "Cheapest run within each accuracy of the reference (below), per quantity and on "
          "both; an accuracy finer than the reference's own uncertainty is not judged.", ""]
    rows = [(f"{100 * rec['target']:g} %", *(_cell(rec[q], q) for q in QUANTITIES),
             _cell(rec["both"])) for rec in recommendations(ds)]
    L.append(md_table(["accuracy", *(QUANTITY_LABEL[q] for q in QUANTITIES),
                       "both"], rows))
    L += _reference_lines(ds) + _order_lines(st, ds) + _step_lines(ds) + _cost_lines(ds)
    return L


def _reference_lines(ds: DynStudy) -> list[str]:
    r = ds.ref_run
    L = ["", "### Reference", "",
         f"Per quantity: the run at the finest element length and the smallest step factor "
         f"({r.h:g} m, factor {r.factor:g}), unless the three finest lengths at factor "
         f"{ds.default_factor:g} give a clean Richardson limit (order "
         f"{RICHARDSON_ORDERS[0]:g} to {RICHARDSON_ORDERS[1]:g}, and the step factor's "
         f"change at the finest length below {STEP_SHARE:g} of the last mesh change). Its "
         "uncertainty is an estimate: the larger of its change from the next-coarser "
         f"length and from factor {ds.default_factor:g} (for a Richardson limit: the size of "
         "the extrapolation).", ""]
    rows = []
    for q in QUANTITIES:
        ref = ds.reference[q]
        what = (f"finest run ({r.h:g} m, factor {r.factor:g})" if ref["kind"] == "finest"
                else "Richardson limit of " + ", ".join(
                    f"{h:g}" for h in ref["richardson_lengths"]) + " m")
        p = ref.get("richardson_order")
        step = ref.get("step_change")
        if step is not None and ref.get("step_at") not in (None, r.h):
            step = (f"{step:.3g} (at {ref['step_at']:g} m: factor {ds.default_factor:g} "
                    f"failed at {r.h:g} m)")
        elif step is not None and ref.get("step_factor") != ds.default_factor:
            step = (f"{step:.3g} (from factor {ref['step_factor']:g}: factor "
                    f"{ds.default_factor:g} failed)")
        rows.append((QUANTITY_LABEL[q], what, ref["value"], ref.get("uncertainty"),
                     ref.get("mesh_change"), step,
                     "n/a" if p is None else f"{p:.2f}"))
    L.append(md_table(["quantity", "reference", "value [N, N m]", "uncertainty (estimate)",
                       "change from the next-coarser length",
                       f"change from factor {ds.default_factor:g}",
                       "Richardson order (three finest)"], rows))
    return L


def _order_note(q: str, fit: dict, ds: DynStudy) -> str:
    p, n, r2 = fit.get("order"), len(fit.get("points", [])), fit.get("r2") or 0.0
    if p is None:
        below = [e for e in fit["errors"] if e is not None and e <= fit["floor"]]
        head = (f"not fitted: {n} length(s) err by more than {NOISE_MARGIN:g}x the step "
                f"change of the reference ({fit['floor']:.1e}) and at most "
                f"{PRE_ASYMPTOTIC:g}" + (f"; {len(below)} err by at most {max(below):.1e}, "
                                         f"within {NOISE_MARGIN:g}x the step change"
                                         if below else ""))
    elif abs(p - EXPECTED_ORDER) <= ORDER_BAND and n >= 3:
        pts = set(fit["points"])
        inner = [lp for a, b, lp in fit["local"] if a in pts and b in pts]
        scatter = [lp for lp in inner if abs(lp - EXPECTED_ORDER) > 2.0 * ORDER_BAND]
        if r2 >= 0.9 and not scatter:
            head = f"order {EXPECTED_ORDER:g}, as expected"
        else:
            head = (f"order {EXPECTED_ORDER:g} on average (R^2 {r2:.2f}), but the local "
                    "orders of successive lengths in the fit scatter ("
                    + ", ".join(f"{lp:.2f}" for lp in inner) + ")" if scatter else
                    f"order {EXPECTED_ORDER:g} on average, but the errors scatter about the "
                    f"fitted line (R^2 {r2:.2f})")
    else:
        head = f"differs (order {p:.2f}, R^2 {r2:.2f}, {n} points)"
    why = ""
    if q == "amplitude" and ds.surface is not None:
        counts = ", ".join(f"{r.nodes_above_surface} at {r.h:g} m" for r in sorted(
            (r for r in ds.runs if r.converged and r.factor == ds.default_factor
             and r.nodes_above_surface is not None), key=lambda r: -r.h))
        why = (f"the hang-off is {ds.surface['below']:g} m below the sea surface, so the "
               f"{HEAVE_AMPLITUDE:g} m heave lifts the top of the line out of the water. "
               "Each free node takes the immersed fraction of its own stretch of line, but "
               "the top half element belongs to the prescribed hang-off node, whose load "
               "goes straight into the support: while half an element is longer than the "
               "emerged length, the free nodes stay under water and the emergence is "
               "missed (an error that stays put from mesh to mesh); once it is shorter, "
               "the fraction resolves it and the error falls at once (free nodes above the "
               f"surface in the window: {counts})")
    elif q == "peak_moment":
        why = ("a maximum over the nodes (the largest nodal value, not refined between "
               "nodes as the static peak is) and over the sample times: its error depends on "
               "where the peak falls between nodes and samples, differently on every mesh, "
               "so it need not fall steadily with h")
    return head + (f"; {why}" if why and head != f"order {EXPECTED_ORDER:g}, as expected"
                   else "")


def _order_lines(st, ds: DynStudy) -> list[str]:
    L = ["", "### Observed order in element length", "",
         f"Errors of the runs at factor {ds.default_factor:g} against the reference (the "
         "reference's own length left out when the reference is its run: its error there "
         "is the step factor's alone). Expected order 2 in h, as in the statics (midpoint "
         "and lumped-mass approximations; the central differences in time are second order "
         "too, and the step shrinks with h). Against the finest run the errors of the "
         "next-coarser lengths are understated by (h_min/h)^p of themselves. A length "
         f"enters the fit if its error is at most {PRE_ASYMPTOTIC:g} and at least "
         f"{NOISE_MARGIN:g}x the step change of the reference.", ""]
    rows = []
    for q in QUANTITIES:
        f = ds.orders.get(q)
        if f is None:
            continue
        local = ", ".join(f"{a:g}-{b:g}: {p:.2f}" for a, b, p in f["local"])
        errs = ", ".join("-" if e is None else f"{e:.1e}" for e in f["errors"])
        rows.append((QUANTITY_LABEL[q], f.get("order"),
                     ", ".join(f"{h:g}" for h in f["points"]), f.get("r2"), errs, local,
                     _order_note(q, f, ds)))
    L.append(md_table(["quantity", "fitted order in h", "lengths in the fit [m]", "R^2",
                       "errors (" + ", ".join(f"{h:g}" for h in ds.orders[QUANTITIES[0]][
                           "lengths"]) + " m)", "local orders", "assessment"], rows))
    return L


def _step_lines(ds: DynStudy) -> list[str]:
    L = ["", "### Step factor", "",
         "At each length run at several factors: the change of each quantity from the "
         "smallest factor run there (a fraction of the reference value), and that change "
         "as a share of the mesh error of the length (its error against the reference; at "
         "the reference's length, its change from the next-coarser length). Wall-time "
         "ratios are against the smallest factor, measured side by side.", ""]
    rows = [(row["h"], row["factor"], row["base_factor"], row["run"].time_step,
             row["time_ratio"], row["amplitude"], row["amplitude_share"],
             row["peak_moment"], row["peak_moment_share"]) for row in ds.step]
    L.append(md_table(["element length [m]", "factor", "vs factor", "time step [s]",
                       "wall-time ratio", "change: amplitude", "share of mesh error",
                       "change: peak moment", "share of mesh error"], rows))
    L.append("")
    for q in QUANTITIES:
        v = ds.step_verdict.get(q, {})
        big, worst = v.get("largest"), v.get("worst_share")
        if big is None:
            continue
        row = big[1]
        txt = (f"- {QUANTITY_LABEL[q].capitalize()}: the step factor "
               + ("**matters**" if v["matters"] else "does not matter")
               + f": its largest change is {big[0]:.1e} ({row['factor']:g} vs "
               f"{row['base_factor']:g} at {row['h']:g} m)")
        if worst is not None:
            txt += (f"; at most {worst[0]:.2g}x the mesh error ({worst[1]['h']:g} m) among "
                    f"the changes above {MATTERS_ABOVE:.0e}; it matters beyond {MATTERS:g}x")
        else:
            txt += (f", below {MATTERS_ABOVE:.0e} (the finest accuracy judged) at every "
                    "length")
        L.append(txt + ".")
    for q, items in ds.dt_order.items():
        for it in items:
            p = it["order"]
            L.append(f"- Order in the time step, {QUANTITY_LABEL[q]} ({it['h']:g} m, factors "
                     f"{', '.join(f'{f:g}' for f in it['factors'])}; Richardson over the "
                     "three smallest): " + ("not clean (the changes are not monotone)"
                                            if p is None else
                                            f"{p:.2f}, the step error at factor "
                                            f"{ds.default_factor:g} {it['default_error']:.1e}"
                                            ) + ".")
    if not any(math.isclose(it["h"], ORDER_LENGTH) for its in ds.dt_order.values()
               for it in its):
        L.append(f"- The step-factor sweep at {ORDER_LENGTH:g} m (factors "
                 f"{', '.join(f'{f:g}' for f in ORDER_FACTORS)}), which measures the order "
                 "in the time step, needs `--full`.")
    L.append("- Expected order in the time step: 2 for the central differences; 1 where "
             "an explicit force acts on the lagged velocity (the Morison drag, the seabed "
             "contact damping).")
    return L


def _cost_lines(ds: DynStudy) -> list[str]:
    sc = ds.scaling
    L = ["", "### Cost and runs", "",
         f"The dynamic sweep took {ds.elapsed_s:.1f} s of this study ({len(ds.runs)} runs, "
         "short runs repeated; statics solved for it included)."]
    if "exponent_all" in sc:
        L.append(f"Wall time ~ h^a at factor {ds.default_factor:g}: a = "
                 f"{sc['exponent_all']:.2f} over all lengths, {sc['exponent_fine']:.2f} over "
                 "the three finest (the elements grow as 1/h and the steps as 1/(factor h) "
                 "while the axial wave sets the step, so a = -2; where bending or the seabed "
                 "contact sets it, dt ~ h^2 and a = -3); median "
                 f"{sc.get('ns_per_element_step', math.nan):.3g} ns per element-step.")
    if ds.static_s:
        L.append("Statics solved for the dynamics only (not in any run's time): " + ", ".join(
            f"{h:g} m {s:.1f} s" for h, s in sorted(ds.static_s.items())) + ".")
    L.append("")
    rows = [(r.h, r.factor, r.elements, r.time_step, r.steps, r.wall_s, r.amplitude,
             r.peak_moment, r.errors.get("amplitude"), r.errors.get("peak_moment"),
             r.nodes_above_surface, "yes" if r.converged else "**no**") for r in ds.runs]
    L.append(md_table(["element length [m]", "factor", "elements", "time step [s]", "steps",
                       "wall [s]", "amplitude [N]", "peak moment [N m]", "error: amplitude",
                       "error: peak moment", "free nodes above surface", "completed"], rows))
    return L


def plot(st, ds: DynStudy | None, out: Path) -> None:
    """``dynamics_error.png``: errors against wall time and against element length."""
    if ds is None or ds.ref_run is None:
        return
    fig, axes = new_figure(1, 2, (12, 5))
    ok = [r for r in ds.runs if r.converged and r.errors]
    marks = {"amplitude": "o", "peak_moment": "s"}
    factors = sorted({r.factor for r in ok}, reverse=True)
    for i, q in enumerate(QUANTITIES):
        for j, f in enumerate(factors):
            rs = sorted((r for r in ok if r.factor == f and r.errors.get(q)),
                        key=lambda r: -r.h)
            if not rs:
                continue
            lab = f"{QUANTITY_LABEL[q]}, factor {f:g}"
            axes[0, 0].loglog([r.wall_s for r in rs], [r.errors[q] for r in rs], marks[q],
                              color=f"C{j}", mfc="none" if i else None, label=lab)
            axes[0, 1].loglog([r.h for r in rs], [r.errors[q] for r in rs],
                              marks[q] + ("-" if f == ds.default_factor else ""),
                              color=f"C{j}", mfc="none" if i else None, lw=0.8, label=lab)
    hs = np.array(sorted({r.h for r in ok}))
    if len(hs) > 1:
        axes[0, 1].loglog(hs, 1e-3 * (hs / hs.max()) ** 2, "k:", label="slope 2")
    for ax, xl in ((axes[0, 0], "wall time of the dynamic run [s]"),
                   (axes[0, 1], "element length [m]")):
        ax.set_xlabel(xl)
        ax.set_ylabel("relative error vs the dynamic reference")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    r = ds.ref_run
    axes[0, 0].set_title(f"{st.scene.name}: dynamics, error vs cost\n(reference: "
                         f"{r.h:g} m, factor {r.factor:g}; {DURATION:g} s of "
                         f"{HEAVE_AMPLITUDE:g} m heave)", fontsize=10)
    axes[0, 1].set_title(f"{st.scene.name}: dynamics, error vs element length\n(line: "
                         f"factor {ds.default_factor:g})", fontsize=10)
    save(fig, out / FIGURE)


def write(st, ds: DynStudy | None, out: Path) -> None:
    """``dynamics.csv`` and the figure (nothing without a dynamic sweep)."""
    if ds is None or not ds.runs:
        return
    ds.frame().to_csv(out / CSV, index=False, float_format="%.10g")
    plot(st, ds, out)


def files_line(ds: DynStudy | None) -> str:
    """The sentence of the Files paragraph on ``dynamics.csv``."""
    if ds is None or not ds.runs:
        return ""
    return (f" `{CSV}` (one row per dynamic run: " + ", ".join(
        f"`{c}`" for c in CSV_COLUMNS) + ", then " + ", ".join(f"`{c}`" for c in CSV_EXTRA)
        + ").")

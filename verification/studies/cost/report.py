"""Report of the cost study: ``report.md``, the three plots, ``runs.csv`` and
``values.csv``; and the row of the reports index read back from them."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, md_table

from . import dynamics_ancf_report, dynamics_report
from .analysis import recommendations
from .assessment import EXPECTED_ORDER, ORDER_BAND, order_assessment
from .errors import QUANTITIES, QUANTITY_LABEL, family
from .fits import NOISE_MARGIN, PRE_ASYMPTOTIC, pareto, worst_mesh
from .records import EXTRA_COLUMNS, RUN_COLUMNS, CostStudy, Run
from .settings import FAST_SWEEP, FULL_ADDS

#: how to get what the fast sweep leaves out
FULL_COMMAND = ("`riser-verify cost SCENE --full` (or `riser-verify reproduce cost --full`, "
                "`riser-verify reproduce all --full`)")


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


def _model_lines(st: CostStudy) -> list[str]:
    fx = st.fixed_scene
    k = fx.seabed.stiffness if fx.seabed is not None else None
    model = (f"extensible line on an elastic (Winkler) seabed of stiffness {k:.3g} N/m2"
             if fx.seabed_model == "elastic" else
             f"{fx.axial_model} line, {fx.seabed_model or 'no'} seabed")
    out = [f"- Model: both methods solve the same continuum model, {model} "
           f"(frictionless), on the same fixed-ends scene; an error against the reference is "
           "the method's discretisation (and, for VFIFE, relaxation) error, not a model "
           "difference."]
    if st.paper_difference:
        pd_ = st.paper_difference
        out.append(f"- The scene's own form (inextensible line on a rigid seabed, the "
                   f"paper's model, BVP) differs from this reference by "
                   f"{pd_['hang_off_tension']:+.2e} in hang-off tension and "
                   f"{pd_['max_moment']:+.2e} in peak moment: a model difference, outside "
                   "this study.")
    return out


def report_markdown(st: CostStudy) -> str:
    sc = st.scene
    ref = st.reference
    compile_s = next((r.compile_time_s for r in st.runs if r.method == "vfife"), 0)
    L = [f"# Accuracy versus cost: `{sc.name}`", "", GENERATED_NOTE, "",
         f"- Scene: {sc.title or sc.name}.", *_model_lines(st),
         f"- Reference: BVP of the same scene at tolerance {ref.setting.value:g} "
         f"({ref.size} nodes, {ref.wall_time_s:.2f} s). Lengths are normalised by "
         f"{st.depth:.1f} m ({'water depth' if st.fixed_scene.water_depth else 'hang-off height'}"
         "); tensions and moment by the reference value.",
         f"- Timing: median of up to {st.repeats} runs after a warm-up (runs longer than "
         "2 s, and runs that did not converge, are timed once); the Numba compilation (or "
         f"cache load) of VFIFE, {compile_s:.2f} s in this process, is reported separately "
         f"(`compile_time_s`). Study wall time {st.elapsed_s:.0f} s.",
         "- Errors are fractions (1e-3 = 0.1 %). `err_*`: against the BVP reference; "
         "`self_*`: against the method's own converged limit (VFIFE: Richardson "
         "extrapolation of the three finest element lengths of the order sweep).", ""]
    L += [f"- {n}" for n in st.notes]
    L += _sweep_lines(st)
    failed = [r for r in st.runs if not r.converged]
    if failed:
        L += ["", "Runs that did not converge (kept in `runs.csv`, excluded from fits and "
              "recommendations):", ""]
        L += [f"- {r.method} {r.setting.setting} = {r.setting.value:g}: {r.message} "
              f"({r.wall_time_s:.2f} s)" for r in failed]
    L += ["", "## Recommendation", "",
          "Cheapest setting reaching each accuracy against the BVP reference (among the "
          "runs below; for the BVP, its error against its finest tolerance).", ""]
    rows = [(QUANTITY_LABEL[rec["quantity"]], f"{100 * rec['target']:g} %",
             _label(rec["bvp"]), _label(rec["vfife"])) for rec in recommendations(st)]
    L.append(md_table(["quantity", "accuracy", "BVP", "VFIFE"], rows))
    L += _limit_section(st)
    L += _order_section(st)
    L += _scaling_section(st)
    L += dynamics_report.section(st, st.dynamics)
    L += dynamics_ancf_report.section(st, st.ancf_dynamics)
    L += ["", "## Runs", ""]
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
          "![time vs elements](time_vs_elements.png)", ""]
    if st.dynamics is not None and st.dynamics.ref_run is not None:
        L += [f"![dynamics: error vs cost and element length]({dynamics_report.FIGURE})", ""]
    L += ["Files: `runs.csv` (one row per run: " + ", ".join(f"`{c}`" for c in RUN_COLUMNS)
          + ", then " + ", ".join(f"`{c}`" for c in EXTRA_COLUMNS) + "), `values.csv` (the "
          "raw quantities of every run and of the reference)."
          + dynamics_report.files_line(st.dynamics)
          + dynamics_ancf_report.files_line(st.ancf_dynamics), ""]
    return "\n".join(L)


def _sweep_lines(st: CostStudy) -> list[str]:
    """What a fast (or quick) sweep ran and which sections need ``--full``."""
    if st.sweep not in ("fast", "quick"):
        return []
    ran = FAST_SWEEP if st.sweep == "fast" else "a coarse subset (`--quick`, development)"
    return [f"- **Fast sweep, not the full study.** This report ran {ran}. The full sweep, "
            f"{FULL_COMMAND}, adds {FULL_ADDS}. So these need `--full` and show no numbers "
            "here: the `self_*` errors of the VFIFE runs (against VFIFE's own Richardson "
            "limit), the VFIFE columns of \"Reference, relaxation and the VFIFE limit\", the "
            "\"Observed VFIFE order in element length\" and the `statics tight` row of \"Cost "
            "scaling\"."]


def _limit_section(st: CostStudy) -> list[str]:
    if not st.has_order_sweep:
        rows = [(QUANTITY_LABEL[q], st.bvp_self.get(q)) for q in QUANTITIES
                if q == "curve_distance" or family(q, st.ref_values)]
        return ["", "## Reference, relaxation and the VFIFE limit", "",
                "Per quantity: the reference's own uncertainty (its change from the "
                "next-coarser BVP tolerance, an upper bound).", "",
                md_table(["quantity", "BVP reference uncertainty"], rows), "",
                "**Needs `--full`:** the VFIFE Richardson order and limit (from the order "
                "sweep at tight tolerances), the limit's difference from the BVP reference, "
                "and the VFIFE relaxation errors (`element_length_tight_check`); this sweep "
                f"ran none of them: {FULL_COMMAND}."]
    hmid = next((r.setting.value for r in st.runs
                 if r.setting.setting == "element_length_tight_check"), None)
    hm = f"{hmid:g} m" if hmid is not None else "the middle element length"
    L = ["", "## Reference, relaxation and the VFIFE limit", "",
         "Per quantity: the reference's own uncertainty (its change from the next-coarser "
         "BVP tolerance, an upper bound), the VFIFE Richardson order (three finest element "
         "lengths of the order sweep below), the relative difference between that VFIFE "
         "limit and the BVP reference (both solve the same model, so it is what the "
         "extrapolation leaves of the discretisation and relaxation errors), and the VFIFE "
         f"relaxation error at {hm}: the change of the result from the default tolerances, "
         "and from the order sweep's, to a run with both tolerances of the order sweep 10x "
         "tighter (`element_length_tight_check`).", ""]
    rows = []
    for q in QUANTITIES:
        fam = family(q, st.ref_values) if q != "curve_distance" else []
        if q != "curve_distance" and not fam:
            continue                  # the scene has none (e.g. no crest)
        rorder = [st.vfife_richardson_order.get(k) for k in fam]
        rtxt = ", ".join("n/a" if p is None else f"{p:.2f}" for p in rorder)
        rows.append((QUANTITY_LABEL[q], st.bvp_self.get(q), rtxt,
                     st.limit_vs_reference.get(q), st.noise_floor.get(q),
                     st.sweep_noise.get(q)))
    L.append(md_table(["quantity", "BVP reference uncertainty", "VFIFE Richardson order",
                       "VFIFE limit vs BVP reference",
                       "VFIFE relaxation error, default tolerances",
                       "... order-sweep tolerances"], rows))
    return L


def _order_section(st: CostStudy) -> list[str]:
    if not st.has_order_sweep:
        return ["", "## Observed VFIFE order in element length", "",
                f"**Needs `--full`:** the order is fitted on the order sweep at tight static "
                "and creep tolerances (`element_length_tight`), which this sweep did not run "
                f"(at the default tolerances the relaxation error hides the order): "
                f"{FULL_COMMAND}."]
    lf = st.foundation_length
    lengths = (f"the bending boundary layer sqrt(EI/T) = {st.boundary_layer:.3g} m at the "
               "touchdown" + (f" and the foundation length (4 EI/k)^(1/4) = {lf:.3g} m of the "
                              "seabed" if lf else ""))
    L = ["", "## Observed VFIFE order in element length", "",
         f"Expected order: {EXPECTED_ORDER:g}. The VFIFE line is a chain of straight "
         "elements with lumped nodal mass, weight and seabed reaction, element forces "
         "constant along an element (belonging to its midpoint) and the bending moment from "
         "the element-end rotations relative to the chord: each is a midpoint/central-"
         "difference approximation of the continuous beam, with errors O(h^2) (nodal "
         "averages and the end extrapolation of the forces are second order too; the peak "
         "moment and the crest and sag heights are located by a parabola through three "
         "nodal values). The elastic seabed's reaction k max(-y, 0) is continuous, so the "
         "touchdown is smooth and converges too; its kink at the lift-off falls at a "
         "different place inside an element on every mesh, which makes the O(h^2) "
         "constant of the quantities set there vary from mesh to mesh.", "",
         f"Sweep used: `{st.order_setting}` rows ({st.order_sweep}; one run per element "
         "length). The error of each element length is against the BVP reference. A point "
         f"enters the fit only if (i) its element length is at most {st.asymptotic:.3g} m, "
         f"the shorter of {lengths} (longer elements do not resolve the touchdown, the "
         "sag bend or the contact zone, so their errors are pre-asymptotic), "
         f"(ii) its error is at most {PRE_ASYMPTOTIC:g}, and (iii) its error is at least "
         f"{NOISE_MARGIN:g}x both the order sweep's relaxation error and the reference "
         "uncertainty above (then the noise moves the log error by <= 0.1). Orders within "
         f"+/-{ORDER_BAND:g} of {EXPECTED_ORDER:g} with R^2 >= 0.9 over three or more "
         "points count as expected; every other row says why. Local orders in parentheses "
         "involve a length left out of the fit.", ""]
    if st.order_setting != "element_length_tight":
        L[-2] += (" The order sweep fell back to the default tolerances: fewer than three "
                  "tight runs converged.")
    rows = []
    for q, f in st.orders.items():
        pts = set(f.get("points", []))
        local = ", ".join((f"{a:g}-{b:g}: {p:.2f}" if a in pts and b in pts
                           else f"({a:g}-{b:g}: {p:.2f})") for a, b, p in f.get("local", []))
        rows.append((QUANTITY_LABEL[q], f["order"], ", ".join(f"{h:g}" for h in f["points"]),
                     f.get("r2"), local, order_assessment(q, f, _context(st))))
    L.append(md_table(["quantity", "fitted order", "element lengths in the fit [m]", "R^2",
                       "local orders (successive lengths [m])", "assessment"], rows))
    return L


def _context(st: CostStudy) -> dict:
    """Numbers the order assessment quotes."""
    ctx = {"depth": st.depth,
           "touchdown_worst_mesh": worst_mesh(st.orders.get("tdp_tension", {})),
           **{f"n_{q}": len(family(q, st.ref_values)) for q in ("crest_height", "sag_height")}}
    if st.fixed_scene.seabed is not None:
        ctx["stiffness"] = st.fixed_scene.seabed.stiffness
    if st.liftoff:
        ctx.update(st.liftoff)
    return ctx


def _scaling_section(st: CostStudy) -> list[str]:
    L = ["", "## Cost scaling", ""]
    rows = []
    for kind, s in st.scaling.items():
        rows.append((kind.replace("_", " "), s["exponent_all"], s["exponent_fine"],
                     s.get("steps_exponent_fine"),
                     ", ".join(f"{t:.3g}" for t in s["time"])))
    L.append(md_table(["run", "time ~ n^a, all meshes", "a, three finest meshes",
                       "steps ~ n^b (three finest)", "times [s] (coarse to fine)"], rows))
    if not st.has_order_sweep:
        L += ["", "The `statics tight` row (the cost of the order sweep) needs `--full`."]
    L += ["", "Statics by explicit dynamic relaxation: cost = steps x cost per step; the cost "
          "per step is proportional to the number of elements n, and the stable step to "
          "the element length (axial wave), so the number of steps grows like n at best "
          "(time ~ n^2); one second of dynamics has the same step limit (time ~ n^2). The "
          "BVP cost grows with the number of collocation nodes that the tolerance needs.",
          ""]
    return L


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
        ax.set_xlabel("wall time [s] (median)")
        ax.set_ylabel(f"relative error in {QUANTITY_LABEL[q]} vs BVP reference")
        ax.set_title(f"{st.scene.name}: {QUANTITY_LABEL[q]}")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    save(fig, out / "error_vs_time.png")

    sweep = st.order_setting or "element_length"        # no order sweep: no fits
    el = sorted([r for r in st.runs if r.setting.method == "vfife"
                 and r.setting.setting == sweep and r.values],
                key=lambda r: r.setting.value)
    fig, axes = new_figure(1, 1, (8, 5.5))
    ax = axes[0, 0]
    curves = st.orders or {q: {"order": None} for q in QUANTITIES}
    for i, (q, f) in enumerate(curves.items()):
        hs = [r.setting.value for r in el if r.errors.get(q)]
        es = [r.errors[q] for r in el if r.errors.get(q)]
        if not hs:
            continue
        c = f"C{i}"
        lab = QUANTITY_LABEL[q] + (f" (order {f['order']:.2f})" if f["order"] is not None
                                   else "")
        ax.loglog(hs, es, "o-", color=c, lw=0.8, label=lab)
        if f["order"] is not None:
            hh = np.array(f["points"])
            ax.loglog(hh, np.exp(f["const"]) * hh ** f["order"], "--", color=c, lw=1.5)
        if q == "tdp_x" and st.liftoff:
            hh = np.array(hs)
            ax.loglog(hh, st.liftoff["coef"] * hh ** 2 / st.depth, ":", color=c, lw=1.2,
                      label="lift-off interpolation bound h^2 kappa0/(8 theta0)")
    if el:
        h = np.array([r.setting.value for r in el])
        ax.loglog(h, 1e-4 * (h / h.max()) ** 2, "k:", label="slope 2")
        for length, name, ls in ((st.boundary_layer, "boundary layer sqrt(EI/T)", "-."),
                                 (st.foundation_length, "foundation length (4EI/k)^(1/4)",
                                  "--")):
            if length and h.min() < length < h.max():
                ax.axvline(length, color="0.5", ls=ls, lw=1, label=f"{name} = {length:.3g} m")
    ax.set_xlabel("element length [m]")
    ax.set_ylabel("relative error vs the BVP reference (same model)")
    fitted = (f"dashed: fitted order over h <= {st.asymptotic:.3g} m" if st.orders else
              "default tolerances; the order fit needs --full")
    ax.set_title(f"{st.scene.name}: VFIFE convergence in element length\n(`{sweep}` "
                 f"rows; {fitted})", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    if ax.get_legend_handles_labels()[0]:        # no VFIFE run (given settings): none
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
    """``runs.csv``, ``values.csv``, ``report.md``, the plots and (with a dynamic sweep)
    ``dynamics.csv`` and its figure, (with the ANCF's beside it) ``dynamics_ancf.csv``
    and its figure into ``out_dir``."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    st.frame().to_csv(out / "runs.csv", index=False, float_format="%.6g")
    st.values_frame().to_csv(out / "values.csv", index=False, float_format="%.10g")
    _plots(st, out)
    dynamics_report.write(st, st.dynamics, out)
    dynamics_ancf_report.write(st, st.ancf_dynamics, out)
    (out / "report.md").write_text(report_markdown(st))


def index_row(d: Path):
    """(cases, worst agreement, verdict) of one scene's cost-study directory."""
    if not ((d / "runs.csv").exists() and (d / "report.md").exists()):
        return None
    df = pd.read_csv(d / "runs.csv")
    conv = df["converged"].astype(bool).sum() if "converged" in df else len(df)
    fast = "element_length_tight" not in set(df["setting"])
    return (f"{len(df)} runs ({conv} converged)" + (", fast sweep" if fast else ""),
            "accuracy vs cost: see the recommendation table",
            "reported" + (" (orders: `--full`)" if fast else ""))

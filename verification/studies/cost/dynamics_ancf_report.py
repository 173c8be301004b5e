"""The section "The ANCF beside the VFIFE" of the cost report (:func:`section`), its
figure (:func:`plot`, ``dynamics_ancf.png``) and ``dynamics_ancf.csv`` (:func:`write`)."""

from __future__ import annotations

import math
from pathlib import Path

from verification.report.figures import new_figure, save
from verification.report.markdown import md_table

from .dynamics import DURATION, HEAVE_AMPLITUDE, HEAVE_PERIOD, QUANTITIES, QUANTITY_LABEL
from .dynamics_ancf import (
    CSV_COLUMNS,
    CSV_EXTRA,
    FULL_ANCF,
    AncfStudy,
    frame,
    per_simulated_second,
)
from .dynamics_ancf_analysis import GOAL_RATIO, TARGET

CSV = "dynamics_ancf.csv"
FIGURE = "dynamics_ancf.png"
TITLE = "## The ANCF beside the VFIFE"


def _pct(x) -> str:
    return "" if x is None or not math.isfinite(x) else f"{100.0 * x:.3g} %"


def _step(r) -> str:
    """The step setting of a run, in its method's terms."""
    if r.method == "ancf":
        return f"{r.steps_per_period} a period"
    return f"factor {r.factor:g}"


def _cell(cell) -> str:
    kind, x = cell
    if kind == "uncertain":
        return (f"not judged: the common reference is uncertain by {_pct(x)}" if x is not None
                else "not judged: the common reference's uncertainty is unknown")
    if kind == "not reached":
        return f"no run within {_pct(TARGET)}"
    return ""


def _wall(r) -> float:
    return r.wall_s if r.method == "ancf" else r.loop_wall_s


def _g(x, digits: int = 3) -> str:
    """A measured or derived number at ``digits`` significant digits (blank for none)."""
    return "" if x is None or not math.isfinite(x) else f"{x:.{digits}g}"


def _per_s(seconds) -> str:
    """Seconds of a run per simulated second, 3 digits."""
    return _g(per_simulated_second(seconds))


def section(st, ancf: AncfStudy | None) -> list[str]:
    """Markdown lines of the section (none without an ANCF sweep)."""
    if ancf is None:
        return []
    L = ["", TITLE, "",
         f"The ANCF's time domain on the same scene, motion and window as the VFIFE's sweep "
         f"above ({DURATION:g} s of a {HEAVE_AMPLITUDE:g} m heave at {HEAVE_PERIOD:g} s, "
         f"statistics from the same start, sampled every {HEAVE_PERIOD / 40:g} s), the same "
         "quantities, against its element length and steps per period (`[ancf] "
         "element_length`, `steps_per_period`; multiples of 40, because the ANCF makes its "
         "step an exact divisor of the sampling interval: 25, 50, 100 and 200 a period "
         "would run as 40, 80, 120 and 200). Each ANCF run is one solve (its Newton statics "
         "on its own mesh, then the implicit dynamics; the statics are not in its time). "
         "Cost: the CPU time of the process over the dynamic run, from its first sample "
         "(the static state) to its last, clocked alike for both methods by an observer "
         "of the run's recorder, per simulated second; the wall time of the same loop "
         "(the ANCF's `dynamic_wall_s`, the VFIFE's `wall_s` of its run) beside it. "
         "Measured in this one run, side by side: the ratio is what carries to another "
         "machine."]
    if ancf.sweep in ("fast", "quick"):
        L += ["", f"Fast sweep: `--full` adds {FULL_ANCF}."]
    bad = [r for r in ancf.runs if not r.converged]
    if bad and all(r.refused for r in ancf.runs):
        return L + ["", f"The ANCF refuses this scene's runs: {bad[0].message}"]
    if bad:
        L += ["", "ANCF runs that failed (kept in `dynamics_ancf.csv`, excluded):", ""]
        L += [f"- {r.label()}: {r.message}" for r in bad]
    if not ancf.reference:
        return L + ["", "No ANCF run completed: nothing to compare."]
    L += _matched_lines(ancf) + _reference_lines(ancf) + _run_lines(st, ancf)
    return L


def _matched_lines(ancf: AncfStudy) -> list[str]:
    L = ["", f"### Cost at matched accuracy ({_pct(TARGET)})", "",
         f"Per method, the run with the least CPU time per simulated second that is within "
         f"{_pct(TARGET)} in the peak moment (the issue's accuracy in the moment: the sweep's "
         "moment quantity, the largest nodal moment over the window), and, a second row, "
         "in both quantities: its error against the common reference (below) plus that "
         f"reference's uncertainty at most {_pct(TARGET)}, so that it is within it wherever "
         "in its uncertainty the limit lies. Each pick's "
         "other error is shown beside it: a pick on the moment alone may miss the tension "
         "amplitude by more (the ANCF's coarsest steps). The ratio is the "
         f"ANCF's over the VFIFE's (the goal: at most {GOAL_RATIO:g}). The VFIFE takes no "
         "Newton iterations (explicit central differences: one force evaluation a step).",
         ""]
    rows = []
    for p in ancf.picks:
        what = (f"{QUANTITY_LABEL[p['key']]} within {_pct(TARGET)}" if p["key"] != "both"
                else f"both within {_pct(TARGET)}")
        for name in ("vfife", "ancf"):
            kind, r = p[name]
            if kind != "run":
                rows.append((what, name.upper(), _cell(p[name]), *[""] * 10))
                continue
            errs = ancf.vfife_errors.get(id(r), {}) if name == "vfife" else r.errors
            rows.append((what, name.upper(), r.h, _step(r), _g(r.time_step, 4), r.elements,
                         _pct(errs.get("peak_moment")), _pct(errs.get("amplitude")),
                         _per_s(r.cpu_s), _per_s(_wall(r)),
                         _g(r.newton_iterations_per_step) if name == "ancf" else "explicit",
                         r.step_halvings if name == "ancf" else "",
                         "" if name == "vfife" else _ratio(p)))
    L.append(md_table(["accuracy", "method", "element length [m]", "step setting",
                       "time step [s]", "elements", "error: peak moment",
                       "error: hang-off tension amplitude", "CPU s per simulated s",
                       "wall s per simulated s", "Newton iterations a step",
                       "step halvings", "ANCF / VFIFE: CPU (wall)"], rows))
    head = next((p for p in ancf.picks if p["key"] == "peak_moment"), None)
    if head is not None and head["ratio_cpu"] is not None:
        met = head["ratio_cpu"] <= GOAL_RATIO
        L += ["", f"**ANCF / VFIFE CPU time at {_pct(TARGET)} in the peak moment: "
              f"{head['ratio_cpu']:.2f}** (wall {head['ratio_wall']:.2f}): the goal "
              f"(at most {GOAL_RATIO:g}) is " + ("met." if met else "**not met**.")]
    own = ancf.own_picks
    if own:
        L += ["", "Each method's own convergence study (its runs against its own reference, "
              f"at {_pct(TARGET)} in the peak moment): " + "; ".join(
                  f"{name.upper()} " + _own(own[name]) for name in ("vfife", "ancf")) + "."]
    return L


def _ratio(p: dict) -> str:
    if p["ratio_cpu"] is None:
        return ""
    return f"{p['ratio_cpu']:.2f} ({p['ratio_wall']:.2f})"


def _own(cell) -> str:
    kind, x = cell
    if kind == "run":
        return f"picks {x.label()}"
    if kind == "uncertain":
        return ("cannot judge it: its reference is uncertain by " + _pct(x) if x is not None
                else "cannot judge it: its reference's uncertainty is unknown")
    return "reaches it with no run"


def _reference_lines(ancf: AncfStudy) -> list[str]:
    L = ["", "### The common reference", "",
         "Per quantity, the own reference of the method whose uncertainty estimate is the "
         "smaller (the VFIFE's: its sweep's reference above; the ANCF's: its run at the "
         "finest length and the most steps a period, uncertain by the larger of its change "
         "from the next-fewer steps a period and of the next-coarser length's change from "
         "it), so that an accuracy of " + _pct(TARGET) + " can be judged at all. Both "
         "methods solve the same continuum model, so both converge to one limit: the "
         "difference between their own references is the check that they do (it includes "
         "the larger of their discretisation errors).", ""]
    rows = []
    for q in QUANTITIES:
        c = ancf.common.get(q)
        if not c:
            continue
        o = c.get("other") or {}
        rows.append((QUANTITY_LABEL[q], c["label"], c["value"], _pct(c.get("uncertainty")),
                     o.get("label", ""), o.get("value"), _pct(o.get("uncertainty")),
                     _pct(c.get("difference"))))
    L.append(md_table(["quantity", "common reference", "value [N, N m]",
                       "its uncertainty (estimate)", "the other method's own reference",
                       "value", "its uncertainty", "difference"], rows))
    notes = []
    for q in QUANTITIES:
        r = ancf.reference.get(q)
        if r is None:
            continue
        parts = []
        if r.get("step_change") is not None:
            parts.append(f"{_pct(r['step_change'])} from {r['step_from']} steps a period")
        if r.get("mesh_change") is not None:
            h2, n = r["mesh_at"]
            parts.append(f"{_pct(r['mesh_change'])} between {h2:g} m and "
                         f"{r['run'].h:g} m at {n} a period")
        if parts:
            notes.append(f"{QUANTITY_LABEL[q]} " + ", ".join(parts))
    if notes:
        L += ["", "The ANCF reference's changes: " + "; ".join(notes) + "."]
    return L


def _run_lines(st, ancf: AncfStudy) -> list[str]:
    L = ["", "### The ANCF's runs", "",
         "Errors against the common reference (`err`) and against the ANCF's own "
         "reference (`self`); the time step is the one the ANCF took.", ""]
    rows = [(r.h, r.steps_per_period, _g(r.time_step, 4), r.elements, r.steps,
             _g(r.newton_iterations_per_step), r.step_halvings,
             _per_s(r.cpu_s), _per_s(r.wall_s), r.amplitude,
             r.peak_moment, _pct(r.errors.get("amplitude")),
             _pct(r.errors.get("peak_moment")), _pct(r.self_errors.get("peak_moment")),
             "yes" if r.converged else "**no**") for r in ancf.runs]
    L.append(md_table(["element length [m]", "steps a period", "time step [s]", "elements",
                       "steps", "Newton iterations a step", "step halvings",
                       "CPU s per simulated s", "wall s per simulated s", "amplitude [N]",
                       "peak moment [N m]", "err: amplitude", "err: peak moment",
                       "self: peak moment", "completed"], rows))
    ds = st.dynamics
    if ds is not None and ds.runs:
        L += ["", "The VFIFE's runs against the same common reference:", ""]
        rows = []
        for r in ds.runs:
            errs = ancf.vfife_errors.get(id(r), {})
            rows.append((r.h, r.factor, _g(r.time_step, 4), r.elements, r.steps,
                         _per_s(r.cpu_s), _per_s(r.loop_wall_s),
                         _pct(errs.get("amplitude")), _pct(errs.get("peak_moment")),
                         "yes" if r.converged else "**no**"))
        L.append(md_table(["element length [m]", "factor", "time step [s]", "elements",
                           "steps", "CPU s per simulated s", "wall s per simulated s",
                           "err: amplitude", "err: peak moment", "completed"], rows))
    L += ["", f"The ANCF's sweep took {ancf.elapsed_s:.1f} s of this study ({len(ancf.runs)} "
          "runs, short runs repeated, statics included; a warm-up solve before them, "
          f"{ancf.warm_up_s:.2f} s, compiled the ANCF's kernels or loaded them from Numba's "
          "cache, in no run's time).",
          "", f"![the ANCF beside the VFIFE: error vs CPU per simulated second]({FIGURE})"]
    return L


def plot(st, ancf: AncfStudy | None, out: Path) -> None:
    """``dynamics_ancf.png``: each quantity's error against the common reference vs the
    CPU time per simulated second, both methods, the target and the picks marked."""
    if ancf is None or not ancf.reference:
        return
    fig, axes = new_figure(1, 2, (12, 5))
    ds = st.dynamics
    vruns = [r for r in (ds.runs if ds is not None else []) if id(r) in ancf.vfife_errors]
    arun = [r for r in ancf.runs if r.errors]
    picked = {id(p[m][1]) for p in ancf.picks[:1] for m in ("vfife", "ancf")
              if p[m][0] == "run"}
    for ax, q in zip(axes[0], ("peak_moment", "amplitude")):
        for name, runs, errs, mark, color in (
                ("VFIFE", vruns, lambda r: ancf.vfife_errors[id(r)], "o", "C1"),
                ("ANCF", arun, lambda r: r.errors, "s", "C0")):
            pts = [(per_simulated_second(r.cpu_s), errs(r)[q], r)
                   for r in runs if errs(r).get(q)]          # the reference (0): not shown
            if not pts:
                continue
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], mark, color=color,
                      mfc="none", label=name)
            for x, y, r in pts:
                ax.annotate(f"{r.h:g}/{r.steps_per_period if name == 'ANCF' else r.factor:g}",
                            (x, y), fontsize=6, xytext=(3, 2), textcoords="offset points")
                if id(r) in picked:
                    ax.loglog([x], [y], mark, color=color, ms=11, mfc="none", mew=2)
        ax.axhline(TARGET, color="k", ls=":", lw=1, label=f"{_pct(TARGET)}")
        ax.set_xlabel("CPU time per simulated second [s/s]")
        ax.set_ylabel("relative error vs the common reference")
        ax.set_title(f"{st.scene.name}: {QUANTITY_LABEL[q]}\nlabels: element length [m] / "
                     "factor (VFIFE) or steps a period (ANCF)\nringed: the picks at "
                     f"{_pct(TARGET)} in the peak moment", fontsize=8)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    save(fig, out / FIGURE)


def write(st, ancf: AncfStudy | None, out: Path) -> None:
    """``dynamics_ancf.csv`` and the figure (nothing without an ANCF sweep)."""
    if ancf is None or not ancf.runs:
        return
    ds = st.dynamics
    frame(ancf, ds.runs if ds is not None else []).to_csv(out / CSV, index=False,
                                                          float_format="%.10g")
    plot(st, ancf, out)


def files_line(ancf: AncfStudy | None) -> str:
    """The sentence of the Files paragraph on ``dynamics_ancf.csv``."""
    if ancf is None or not ancf.runs:
        return ""
    return (f" `{CSV}` (one row per ANCF run, then per VFIFE dynamic run, against the "
            "common reference: " + ", ".join(f"`{c}`" for c in CSV_COLUMNS) + ", then "
            + ", ".join(f"`{c}`" for c in CSV_EXTRA) + ").")

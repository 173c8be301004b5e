"""Writing a :class:`verification.comparison.static.protocol.Comparison`: agreement.csv, report.md (verdict,
headline, the rows with signed differences, units and tolerance bases, the paper-model
section) and the plots."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from riser.results.result import Status
from verification.pipeline import shifted
from verification.quantities import signed_moment
from verification.report.figures import add_panel_below, new_figure, plan_view, save
from verification.report.markdown import GENERATED_NOTE, fmt, md_table, timed

from ..formatting import ROUND_OFF, num, rel, scale, signed, where
from .protocol import Comparison, model_text


#: the report's word for a row's ``pass``: within, outside, or not judged (shown only)
PASS_WORD = {True: "yes", False: "**no**", None: "n/a"}


def write(comp: Comparison, out_dir: str | Path) -> None:
    """agreement.csv, report.md, the plots, each method's solve folder and each further
    column's files."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    comp.frame().to_csv(out / "agreement.csv", index=False, float_format="%.8g")
    comp.bvp.write(out / "bvp")
    comp.vfife.write(out / "vfife")
    if comp.paper is not None and comp.paper.converged:
        comp.paper.write(out / "bvp_paper_model")
    for res in comp.columns.values():
        res.column.write(comp, res, out)
    _plots(comp, out)
    (out / "report.md").write_text(report_markdown(comp))


def _rows_table(rows: list[dict]) -> str:
    """The agreement rows: values, the signed difference VFIFE - BVP in the quantity's
    unit and relative to the basis of its tolerance, the tolerance and its basis."""
    out = []
    for r in rows:
        sc = scale(r)
        note = f" ({r['note']})" if r.get("note") else ""
        out.append((f"`{r['quantity']}`", r.get("unit", ""), num(r["bvp"], sc),
                    num(r["vfife"], sc), signed(r.get("diff"), sc) + where(r) + note, rel(r),
                    num(r["tolerance"]), r.get("tol_label", ""),
                    PASS_WORD[r["pass"]]))
    return md_table(["quantity", "unit", "BVP", "VFIFE", "VFIFE - BVP", "relative",
                     "tolerance", "tolerance basis", "pass"], out)


def _headline(comp: Comparison) -> list[str]:
    names = {"configuration": "configuration (largest distance between the lines)",
             "tension": "effective tension", "moment": "bending moment",
             "tdp_x": "touchdown x"}
    rows = []
    for q, r in comp.worst().items():
        rows.append((names[q], signed(r.get("diff"), scale(r)) + f" {r['unit']}" + where(r),
                     rel(r), r.get("tol_label", ""), PASS_WORD[r["pass"]]))
    return [md_table(["worst difference (VFIFE - BVP)", "value", "relative", "tolerance",
                      "pass"], rows)]


def report_markdown(comp: Comparison, heading: str = "#") -> str:
    sc = comp.scene
    ms = comp.matched_scene or comp.vfife_scene
    b, v = comp.bvp, comp.vfife
    verdict = "PASS" if comp.passed else "FAIL"
    failed = [r["quantity"] for r in comp.rows if r["pass"] is False]
    not_judged = [r for r in comp.rows if r["pass"] is None]
    lines = [
        f"{heading} VFIFE vs BVP: `{sc.name}`",
        "",
        GENERATED_NOTE,
        "",
        f"**Verdict: {verdict}**" + (f" (outside tolerance: {', '.join(failed)})" if failed else
                                     " (every judged metric within its tolerance)"
                                     if not_judged else " (every metric within its tolerance)"),
        "",
    ]
    if not_judged:
        lines += [f"Not judged ({', '.join(r['quantity'] for r in not_judged)}): "
                  f"{not_judged[0]['note']}.", ""]
    lines += _headline(comp)
    lines += [
        "",
        f"- Scene: {sc.title or sc.name}.",
        f"- Model solved by both methods: {model_text(ms)}.",
    ]
    lines += [f"- {n}" for n in comp.notes]
    lines += [
        f"- BVP: {b.message}, {b.info.get('nodes')} nodes, {timed(b.wall_time_s)}"
        + (f", {b.info['formulation']}" if b.profile is not None and b.profile.is_3d
           else "") + ".",
        f"- VFIFE: {v.message}; {v.info.get('elements')} elements of "
        f"{fmt(v.info.get('element_length'), 4)} m, time step "
        f"{fmt(v.info.get('time_step'), 4)} s, {timed(v.wall_time_s)}.",
        f"- Lengths are normalised by {comp.depth:.1f} m "
        f"({'water depth' if sc.water_depth else 'hang-off height; the scene gives no depth'}).",
        "",
        "Both methods report effective tension and bending moment, compared at the same "
        "arc length: at the VFIFE nodes, the BVP interpolated there (both as point values: "
        "the VFIFE recovers its nodal tension to second order, each side of a joint "
        "extrapolating its own elements)." + (
            " The scene is 3D: its line's plane is the vertical plane through the anchor "
            "and the hang-off, the lateral rows are offsets from it, and the moment is "
            "compared as a vector (the row `moment` is the largest magnitude of the "
            "difference of its components in and out of that plane)."
            if b.profile is not None and b.profile.is_3d else "") +
        " Differences are signed VFIFE - BVP; `relative` divides "
        "them by the basis of the row's tolerance (depth, T_max or M_max of the BVP, or the BVP value itself); the "
        "configuration is a distance (unsigned); values below "
        f"{ROUND_OFF:g} of their basis are round-off and printed as 0. The tolerances and "
        "their reasons: `verification/comparison/tolerances.py`.",
        "", f"{heading}# Agreement (the verdict)", "",
    ]
    lines.append(_rows_table(comp.rows))
    for res in comp.columns.values():
        lines += res.column.markdown(comp, res, heading)
    if comp.paper is not None:
        lines += ["", f"{heading}# Paper model (limit), not part of the verdict", "",
                  "The same VFIFE run against the BVP in the paper model of Wang et al. (2014): "
                  "an inextensible line on a rigid seabed (touchdown with zero angle and "
                  "moment), the limit EA -> inf, k -> inf of the model above"
                  + (" (the scene's own paper-model solution, from which it was converted)"
                     if comp.s_shift else "") + ". The differences show what the axial "
                  "stretch and the soft seabed change; a tolerance is not applied to them.", ""]
        if comp.paper_rows:
            base = {r["quantity"]: r for r in comp.rows}
            rows = []
            for r in comp.paper_rows:
                r0 = base.get(r["quantity"])
                sc0 = scale(r)
                rows.append((f"`{r['quantity']}`", r.get("unit", ""), num(r["bvp"], sc0),
                             signed(r.get("diff"), sc0) + where(r), rel(r),
                             rel(r0) if r0 else "",
                             {True: "yes", False: "no", None: "n/a"}[r["pass"]]))
            lines.append(md_table(["quantity", "unit", "BVP paper model", "VFIFE - paper",
                                   "relative", "relative, matched model", "within tolerance"],
                                  rows))
        else:
            how = ("does not apply (refused)" if comp.paper.status is Status.REFUSED
                   else f"did not converge ({comp.paper.status.value})")
            lines.append(f"The paper-model BVP {how}: {comp.paper.message}")
    lines += ["", f"{heading}# Figures", "", "![configurations](configurations.png)", "",
              "![tension, moment, shear](forces.png)", "", "![differences](differences.png)", "",
              "Files: `agreement.csv` (columns " + ", ".join(f"`{c}`" for c in comp.frame().columns)
              + "; `rel_diff` is the signed relative difference above"
              + "".join(f", {res.column.files_note()}" for res in comp.columns.values())
              + "), `bvp/` and `vfife/` "
              "(each `profile.csv`, `summary.json`, in the solved scene's arc length)"
              + (", `bvp_paper_model/`" if comp.paper is not None and comp.paper.converged
                 else "") + ".", ""]
    return "\n".join(lines)


def _plots(comp: Comparison, out: Path) -> None:
    bp = shifted(comp.bvp.profile, comp.s_shift)
    vp = shifted(comp.vfife.profile, comp.s_shift)
    pp = comp.paper.profile if comp.paper is not None and comp.paper.converged else None
    further = [res for res in comp.columns.values() if res.profile is not None]
    fig, axes = new_figure(1, 1, (9, 5))
    ax = axes[0, 0]
    ax.plot(bp.x, bp.y, "-", lw=2.0, label="BVP")
    ax.plot(vp.x, vp.y, "--", lw=1.2, label="VFIFE")
    for res in further:
        ax.plot(res.profile.x, res.profile.y, label=res.column.label, **res.column.style)
    if pp is not None:
        ax.plot(pp.x, pp.y, ":", lw=1.0, color="0.4", label="BVP paper model")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m] above the seabed")
    ax.set_title(f"{comp.scene.name}: configurations")
    ax.legend()
    ax.grid(alpha=0.3)
    if bp.is_3d or vp.is_3d:             # a 3D line: its plan view below (planar: none)
        plan_view(add_panel_below(fig, 4.0), [
            (bp.x, bp.z, {"ls": "-", "lw": 2.0}), (vp.x, vp.z, {"ls": "--", "lw": 1.2}),
            *[(r.profile.x, r.profile.z, r.column.style) for r in further],
            *([(pp.x, pp.z, {"ls": ":", "lw": 1.0, "color": "0.4"})] if pp is not None
              else [])])
    save(fig, out / "configurations.png")
    fig, axes = new_figure(3, 1, (9, 10))
    for ax, key, label in zip(axes[:, 0], ("tension", "moment", "shear"),
                              ("effective tension [kN]", "bending moment [kN m]", "shear [kN]")):
        ax.plot(bp.s, getattr(bp, key) / 1e3, "-", lw=2.0, label="BVP")
        ax.plot(vp.s, getattr(vp, key) / 1e3, "--", lw=1.2, label="VFIFE")
        for res in further:
            if key in res.column.forces:
                ax.plot(res.profile.s, getattr(res.profile, key) / 1e3, label=res.column.label,
                        **res.column.style)
        if pp is not None:
            ax.plot(pp.s, getattr(pp, key) / 1e3, ":", lw=1.0, color="0.4",
                    label="BVP paper model")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0, 0].legend()
    axes[2, 0].set_xlabel("arc length s [m] (the scene's coordinate)")
    save(fig, out / "forces.png")
    # the differences as the metrics take them: at the VFIFE nodes (see agreement)
    lo, hi = max(bp.s[0], vp.s[0]), min(bp.s[-1], vp.s[-1])
    sel = (vp.s >= lo - 1e-9) & (vp.s <= hi + 1e-9)
    g = vp.s[sel]
    fig, axes = new_figure(3, 1, (9, 9))
    dT = vp.tension[sel] - np.interp(g, bp.s, bp.tension)
    dM = signed_moment(vp)[sel] - np.interp(g, bp.s, signed_moment(bp))
    # vertical offset at the same arc length (a simple view of the configuration difference)
    dy = vp.y[sel] - np.interp(g, bp.s, bp.y)
    for ax, d, label in zip(axes[:, 0], (dT / 1e3, dM / 1e3, dy),
                            ("VFIFE - BVP tension [kN]", "VFIFE - BVP moment [kN m]",
                             "VFIFE - BVP height at same s [m]")):
        ax.plot(g, d)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[2, 0].set_xlabel("arc length s [m] (the scene's coordinate)")
    save(fig, out / "differences.png")

"""Writing a :class:`verification.compare.Comparison`: agreement.csv, report.md (verdict,
headline, the rows with signed differences, units and tolerance bases, the paper-model
section) and the plots."""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np
import pandas as pd

from riser.errors import SolveFailed

from .catalog import resolve
from .compare import AGREEMENT_COLUMNS, ROUND_OFF, Comparison, compare, model_text
from .compare_moordyn import moordyn_markdown
from .compare_moordyn import write as moordyn_files
from .pipeline import shifted
from .quantities import nodal_average, signed_moment
from .report import GENERATED_NOTE, fmt, md_table, new_figure, pct, save
from .study import Study


def write(comp: Comparison, out_dir: str | Path) -> None:
    """agreement.csv, report.md and the plots."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    comp.frame().to_csv(out / "agreement.csv", index=False, float_format="%.8g")
    comp.bvp.write(out / "bvp")
    comp.vfife.write(out / "vfife")
    if comp.analytic is not None:
        comp.analytic.write(out / "analytic")
    if comp.paper is not None and comp.paper.converged:
        comp.paper.write(out / "bvp_paper_model")
    moordyn_files(comp, out)
    _plots(comp, out)
    (out / "report.md").write_text(report_markdown(comp))


def _is_zero(value, scale) -> bool:
    return scale is not None and scale > 0 and abs(value) <= ROUND_OFF * scale


def _num(value, scale=None, digits: int = 6) -> str:
    """A number for the tables; 0 when below round-off of ``scale``."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return ""
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
        return str(int(value))
    if _is_zero(value, scale):
        return "0"
    return fmt(float(value), digits)


def _signed(value, scale=None, digits: int = 4) -> str:
    if value is None:
        return ""
    if value == 0 or _is_zero(value, scale):
        return "0"
    return f"{value:+.{digits}g}"


def _rel(r: dict) -> str:
    """Signed relative difference in % of the row's basis ('' when it has none)."""
    rel = r.get("rel_diff")
    if rel is None:
        return ""
    if abs(rel) <= ROUND_OFF:
        return "0"
    label = r.get("basis_label") or ""
    return f"{100.0 * rel:+.3g} %" + (f" of {label}" if label else "")


def _scale(r: dict):
    """Scale below which a value of row ``r`` is round-off: its basis, else its size."""
    if r.get("basis"):
        return r["basis"]
    vals = [abs(x) for x in (r.get("bvp"), r.get("vfife")) if x is not None]
    return max(vals) if vals else None


def _where(r: dict) -> str:
    return f" at s = {r['at_s']:.1f} m" if r.get("at_s") is not None else ""


def _rows_table(rows: list[dict]) -> str:
    """The agreement rows: values, the signed difference VFIFE - BVP in the quantity's
    unit and relative to the basis of its tolerance, the tolerance and its basis."""
    out = []
    for r in rows:
        sc = _scale(r)
        note = f" ({r['note']})" if r.get("note") else ""
        out.append((f"`{r['quantity']}`", r.get("unit", ""), _num(r["bvp"], sc),
                    _num(r["vfife"], sc), _signed(r.get("diff"), sc) + _where(r) + note, _rel(r),
                    _num(r["tolerance"]), r.get("tol_label", ""),
                    "yes" if r["pass"] else "**no**"))
    return md_table(["quantity", "unit", "BVP", "VFIFE", "VFIFE - BVP", "relative",
                     "tolerance", "tolerance basis", "pass"], out)


def _headline(comp: Comparison) -> list[str]:
    names = {"configuration": "configuration (largest distance between the lines)",
             "tension": "effective tension", "moment": "bending moment",
             "tdp_x": "touchdown x"}
    rows = []
    for q, r in comp.worst().items():
        rows.append((names[q], _signed(r.get("diff"), _scale(r)) + f" {r['unit']}" + _where(r),
                     _rel(r), r.get("tol_label", ""), "yes" if r["pass"] else "**no**"))
    return [md_table(["worst difference (VFIFE - BVP)", "value", "relative", "tolerance",
                      "pass"], rows)]


def report_markdown(comp: Comparison, heading: str = "#") -> str:
    sc = comp.scene
    ms = comp.matched_scene or comp.vfife_scene
    b, v = comp.bvp, comp.vfife
    verdict = "PASS" if comp.passed else "FAIL"
    failed = [r["quantity"] for r in comp.rows if not r["pass"]]
    lines = [
        f"{heading} VFIFE vs BVP: `{sc.name}`",
        "",
        GENERATED_NOTE,
        "",
        f"**Verdict: {verdict}**" + (f" (outside tolerance: {', '.join(failed)})" if failed else
                                     " (every metric within its tolerance)"),
        "",
    ]
    lines += _headline(comp)
    lines += [
        "",
        f"- Scene: {sc.title or sc.name}.",
        f"- Model solved by both methods: {model_text(ms)}.",
    ]
    lines += [f"- {n}" for n in comp.notes]
    lines += [
        f"- BVP: {b.message}, {b.info.get('nodes')} nodes, {b.wall_time_s:.2f} s.",
        f"- VFIFE: {v.message}; {v.info.get('elements')} elements of "
        f"{fmt(v.info.get('element_length'), 4)} m, time step "
        f"{fmt(v.info.get('time_step'), 4)} s, {v.wall_time_s:.2f} s.",
        f"- Lengths are normalised by {comp.depth:.1f} m "
        f"({'water depth' if sc.water_depth else 'hang-off height; the scene gives no depth'}).",
        "",
        "Both methods report effective tension and bending moment, compared at the same "
        "arc length: at the VFIFE nodes, the BVP interpolated there (the BVP tension "
        "sampled at the VFIFE element midpoints and averaged to the nodes, as VFIFE reports "
        "its element forces). Differences are signed VFIFE - BVP; `relative` divides "
        "them by the basis of the row's tolerance (depth, T_max or M_max of the BVP, or the BVP value itself); the "
        "configuration is a distance (unsigned); values below "
        f"{ROUND_OFF:g} of their basis are round-off and printed as 0. The tolerances and "
        "their reasons: `verification/tolerances.py`.",
        "", f"{heading}# Agreement (the verdict)", "",
    ]
    lines.append(_rows_table(comp.rows))
    lines += analytic_markdown(comp, heading)
    lines += moordyn_markdown(comp, heading)
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
                sc0 = _scale(r)
                rows.append((f"`{r['quantity']}`", r.get("unit", ""), _num(r["bvp"], sc0),
                             _signed(r.get("diff"), sc0) + _where(r), _rel(r),
                             _rel(r0) if r0 else "",
                             "yes" if r["pass"] else "no"))
            lines.append(md_table(["quantity", "unit", "BVP paper model", "VFIFE - paper",
                                   "relative", "relative, matched model", "within tolerance"],
                                  rows))
        else:
            lines.append(f"The paper-model BVP did not converge: {comp.paper.message}")
    lines += ["", f"{heading}# Figures", "", "![configurations](configurations.png)", "",
              "![tension, moment, shear](forces.png)", "", "![differences](differences.png)", "",
              "Files: `agreement.csv` (columns " + ", ".join(f"`{c}`" for c in AGREEMENT_COLUMNS)
              + "; `rel_diff` is the signed relative difference above, `analytic_rel_diff` "
              "the analytic method's, empty where it does not apply, `moordyn_rel_diff` MoorDyn's, "
              "empty without `--peer moordyn`), `bvp/` and `vfife/` "
              "(each `profile.csv`, `summary.json`, in the solved scene's arc length)"
              + (", `bvp_paper_model/`" if comp.paper is not None and comp.paper.converged
                 else "") + ".", ""]
    return "\n".join(lines)


def analytic_markdown(comp, heading: str = "#") -> list[str]:
    """The report's section on the third column ([] when it does not apply)."""
    if comp.analytic_note == "":
        return []
    lines = ["", f"{heading}# Analytic method (third column), not part of the verdict", "",
             comp.analytic_note]
    if comp.analytic is None or not comp.analytic.converged:
        return lines
    lines += ["", "Its error against the BVP is asymptotic: it depends on eps = sqrt(EI / "
              "(H L^2)) and delta = w lambda / H, not on a mesh. The composite solution "
              "(catenary with its O(eps^2) bending correction, matched touchdown layer, "
              "moment-free layer at the hang-off) was measured to converge as eps^2 in "
              "angle and position and about eps^3 in the peak moment "
              "(`reports/kang2015/`, epsilon scaling).", ""]
    rows = []
    for r in comp.rows:
        if r.get("analytic_diff") is None:
            continue
        rel = r.get("analytic_rel_diff")
        label = r.get("basis_label") or ""
        rows.append((f"`{r['quantity']}`", r.get("unit", ""), _num(r["bvp"]),
                     _num(r.get("analytic")), _signed(r["analytic_diff"]),
                     "" if rel is None else f"{100.0 * rel:+.3g} %" + (f" of {label}" if label
                                                                          else ""),
                     _signed(r.get("diff"))))
    lines.append(md_table(["quantity", "unit", "BVP", "analytic", "analytic - BVP", "relative",
                           "VFIFE - BVP"], rows))
    return lines


def _plots(comp: Comparison, out: Path) -> None:
    bp = shifted(comp.bvp.profile, comp.s_shift)
    vp = shifted(comp.vfife.profile, comp.s_shift)
    pp = comp.paper.profile if comp.paper is not None and comp.paper.converged else None
    ap = (shifted(comp.analytic.profile, comp.s_shift)
          if comp.analytic is not None and comp.analytic.converged else None)
    mp = comp.moordyn.profile if comp.moordyn is not None else None
    fig, axes = new_figure(1, 1, (9, 5))
    ax = axes[0, 0]
    ax.plot(bp.x, bp.y, "-", lw=2.0, label="BVP")
    ax.plot(vp.x, vp.y, "--", lw=1.2, label="VFIFE")
    if ap is not None:
        ax.plot(ap.x, ap.y, "-.", lw=1.0, label="analytic")
    if mp is not None:
        ax.plot(mp.x, mp.y, ".", ms=2.5, label="MoorDyn (nodes)")
    if pp is not None:
        ax.plot(pp.x, pp.y, ":", lw=1.0, color="0.4", label="BVP paper model")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m] above the seabed")
    ax.set_title(f"{comp.scene.name}: configurations")
    ax.legend()
    ax.grid(alpha=0.3)
    save(fig, out / "configurations.png")
    fig, axes = new_figure(3, 1, (9, 10))
    for ax, key, label in zip(axes[:, 0], ("tension", "moment", "shear"),
                              ("effective tension [kN]", "bending moment [kN m]", "shear [kN]")):
        ax.plot(bp.s, getattr(bp, key) / 1e3, "-", lw=2.0, label="BVP")
        ax.plot(vp.s, getattr(vp, key) / 1e3, "--", lw=1.2, label="VFIFE")
        if ap is not None:
            ax.plot(ap.s, getattr(ap, key) / 1e3, "-.", lw=1.0, label="analytic")
        if mp is not None and key != "shear":
            ax.plot(mp.s, getattr(mp, key) / 1e3, ".", ms=2.5, label="MoorDyn (nodes)")
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
    dT = vp.tension[sel] - nodal_average(vp.s, bp.s, bp.tension)[sel]
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


# ----------------------------------------------------------------------------- the study
#: scenes with a comparison report in reports/compare/ (every built-in scene but the hard
#: cases, which are the stress suite's)
COMPARE_SCENES = ("wang2014-baseline", "wang2014-current-neg1p5", "wang2014-current-neg0p75",
                  "wang2014-current-0p75", "wang2014-current-1p5", "scr-steel",
                  "yu2021-a1", "yu2021-a2", "yu2021-a2-sheared", "yu2021-a3", "yu2021-a4",
                  "kang2015-jlay")


def run_unit(scene_name: str, out: Path, note: str = "", full: bool = False) -> str:
    """Compare one built-in scene into ``out/scene_name`` (``note``, ``full``: unused, the
    comparison has no timings to qualify and no dear part); returns the log line."""
    t0 = time.perf_counter()
    try:
        comp = compare(resolve(scene_name))
    except SolveFailed as exc:
        return f"compare {scene_name}: {exc}"
    write(comp, out / scene_name)
    return (f"compare {scene_name}: {'PASS' if comp.passed else 'FAIL'} "
            f"({time.perf_counter() - t0:.1f} s)")


def index_row(d: Path):
    """(cases, worst agreement, verdict) of one scene's comparison directory."""
    if not (d / "agreement.csv").exists():
        return None
    df = pd.read_csv(d / "agreement.csv")
    failed = df[~df["pass"].astype(bool)].quantity.tolist()
    rows = df.set_index("quantity")
    bases = {"configuration": "of depth", "tension": "of T_max", "moment": "of M_max"}
    text = ", ".join(f"{q} {pct(rows.loc[q, 'rel_diff'], 2)} {bases[q]}" for q in bases
                     if q in rows.index)
    if "tdp_x" in rows.index:
        tdp = rows.loc["tdp_x"]
        text += f", touchdown {tdp['vfife'] - tdp['bvp']:+.3f} m"
    if failed:
        text += f"; outside tolerance: {', '.join(failed)}"
    return "1 scene", text, "pass" if not failed else "fail"


#: measured wall times [s] of the units in ``reproduce all`` (2 processes, 2 cores)
STUDY = Study("compare", COMPARE_SCENES, run_unit, index_row,
              seconds={"yu2021-a4": 12, "wang2014-current-neg1p5": 7, "wang2014-current-neg0p75": 7,
                       "wang2014-current-0p75": 7, "wang2014-current-1p5": 7, "yu2021-a2": 6,
                       "yu2021-a2-sheared": 6, "yu2021-a3": 5, "wang2014-baseline": 4,
                       "yu2021-a1": 2, "scr-steel": 2, "kang2015-jlay": 6})


"""Reproduction of the multi-buoy lazy-wave studies of Yu, Zhao, Zhang et al. (2021).

Frames. The paper puts the origin at the hang-off with x horizontal towards the anchor side
and depth measured down; ours has the anchor at the origin on the seabed, x towards the
hang-off and y up. With the hang-off at (X_h, 500 m): x_paper = X_h - x, depth = 500 - y.
The paper's current "along +x" therefore flows along our -x (heading 180 deg); with it the
hang-off angle grows with speed as the paper reports (heading 0 would tilt the top the
other way).

Unstated inputs (docs/references.md, Yu et al. 2021): the hang-off's horizontal offset X_h is
calibrated once, with the BVP, so that A3 without current has the published hang-off angle
4.372 deg from vertical, and kept for every case; the internal contents are taken as empty;
the seabed stiffness is 1e5 N/m2 (a soft clay), the same elastic seabed for both methods.

Definitions used for the paper's quantities:

- hang-off tension: effective tension at the top;
- "max tension in the lower middle part": the largest effective tension below the upper
  end of the uppermost buoyancy section;
- crest of a buoyancy section: the highest point of the line within that section's arc
  length (the paper's third A3 crest is a shoulder, not a local maximum);
- peak moment: the largest bending moment along the line.
"""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path

import numpy as np
import pandas as pd
from scipy.optimize import brentq

from riser.errors import SolveFailed
from riser.results.profile import _parabolic_peak
from riser.results.result import Status
from riser.model.scene import Current, FixedEnds, Scene
from verification.catalog import resolve
from verification.pipeline import solve_scene
from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, md_table, pct, timed

from ..study import Study
from .agreement import conditioning, within_lines
from .agreement import tolerance as method_tolerance
from .dynamics import TOP_SPEED
from .dynamics import run as run_dynamics

DEPTH = 500.0
BUOYANCY = 1130.0          # N/m
TARGET_ANGLE_FROM_VERTICAL = 4.372

PAPER = {
    ("layout", "A1"): {"hang_off_tension": 160.5e3, "lower_max_tension": 99.3e3, "max_moment": 145.1e3},
    ("layout", "A2"): {"hang_off_tension": 149.8e3, "lower_max_tension": 67.6e3, "max_moment": 189.7e3},
    ("layout", "A3"): {"hang_off_tension": 142.5e3, "lower_max_tension": 42.2e3, "max_moment": 228.6e3,
                       "crest1_x": 186.0, "crest1_depth": 285.0, "crest2_x": 333.0,
                       "crest2_depth": 296.0, "crest3_x": 468.0, "crest3_depth": 389.0},
    ("layout", "A4"): {"hang_off_tension": 138.7e3, "lower_max_tension": 23.2e3, "max_moment": 246.3e3},
    ("gap", "100"): {"max_moment": 228.6e3},
    ("gap", "75"): {"max_moment": 178.7e3, "lower_max_tension_ratio": 1.35},
    ("gap", "50"): {"max_moment": 143.2e3, "lower_max_tension_ratio": 1.70},
    ("buoyancy_loss", "first"): {"crest1_x": 170.0, "crest1_depth": 345.0,
                                 "hang_off_tension": 152.4e3, "crest1_moment": 169.9e3},
    ("buoyancy_loss", "middle"): {"crest2_x": 304.0, "crest2_depth": 376.0,
                                  "hang_off_tension": 146.6e3, "crest2_moment": 163.0e3},
    ("buoyancy_loss", "last"): {"crest3_x": 450.0, "crest3_depth": 425.0,
                                "hang_off_tension": 143.6e3, "crest3_moment": 119.2e3},
    ("current", "0"): {"hang_off_angle_from_vertical": 4.372, "max_moment": 228.6e3},
    ("current", "0.6"): {"hang_off_angle_from_vertical": 7.628, "max_moment": 232.1e3},
    ("current", "1.2"): {"hang_off_angle_from_vertical": 17.386, "max_moment": 250.8e3},
    ("moved_up", "0"): {"hang_off_tension": 142.5e3, "max_moment": 228.6e3},
    ("moved_up", "50"): {"hang_off_tension": 124.9e3, "max_moment": 253.4e3},
    ("moved_up", "100"): {"hang_off_tension": 107.2e3, "max_moment": 279.5e3},
}
CONTRADICTIONS = [
    "A3 intact hang-off tension: 142.5 kN (sections 2.2.1, 2.2.6) and 142.3 kN (section 2.2.4); "
    "we compare with 142.5 kN.",
    "Last crest with 20 % loss: the text says it drops 49 m but its coordinates differ by 36 m "
    "(389 -> 425 m); we compare with the coordinates.",
]
COLUMNS = ["study", "case", "quantity", "paper", "bvp", "vfife", "bvp_rel_err", "vfife_rel_err",
           "vfife_minus_bvp", "tolerance", "within"]


# ----------------------------------------------------------------------------- scenes
#: arc lengths [m] closer than this are the same station: a method's node at a section's
#: end (the VFIFE's s is a sum of element lengths, 266.65000000000007 for 266.65) must
#: count as inside it (without this the VFIFE's crest and lower maximum tension were read
#: one node, 1 m, away from the BVP's)
SAME_S = 1e-6


def buoy_indices(scene: Scene) -> list[int]:
    """Segment indices of the buoyancy sections, ordered FROM THE TOP (paper's numbering)."""
    return [i for i, s in reversed(list(enumerate(scene.segments))) if s.buoyancy > 0]


def with_hang_off_x(scene: Scene, xh: float) -> Scene:
    return scene.replace(ends=FixedEnds(anchor=(0.0, 0.0), hang_off=(xh, DEPTH)))


def layout(top_down: list[tuple[str, float]], base: Scene, buoyancy: float = BUOYANCY) -> Scene:
    """A scene with segments (kind, length) given from the top down, as in the paper."""
    proto = base.segments[0]
    segs = []
    for kind, L in reversed(top_down):
        segs.append(dataclasses.replace(proto, length=L, buoyancy=buoyancy if kind == "buoy" else 0.0,
                                        label=kind))
    return base.replace(segments=tuple(segs))


def a3_layout(gap: float = 100.0, moved_up: float = 0.0) -> list[tuple[str, float]]:
    """A3 from the top down. Shorter gaps keep the lowest section and the total length (the
    hanging section takes up the difference); moving the sections up by d shortens the
    hanging section and lengthens the lower section by d. Both are our reading of the text."""
    hang = 449.95 + 2 * (100.0 - gap) - moved_up
    lower = 199.95 + moved_up
    return [("hang", hang), ("buoy", 66.70), ("gap", gap), ("buoy", 66.70), ("gap", gap),
            ("buoy", 66.70), ("lower", lower)]


def sheared(scene: Scene, top_speed: float) -> Scene:
    if top_speed == 0.0:
        return scene
    return scene.replace(current=Current(heights=(0.0, DEPTH), speeds=(0.0, top_speed),
                                         heading_deg=180.0))


def with_buoyancy(scene: Scene, factors: dict[int, float]) -> Scene:
    """Multiply the buoyancy of the given segment indices by the given factors."""
    segs = list(scene.segments)
    for i, f in factors.items():
        segs[i] = dataclasses.replace(segs[i], buoyancy=segs[i].buoyancy * f)
    return scene.replace(segments=tuple(segs))


def calibrate_hang_off_x(log=print, solved: list | None = None) -> float:
    """X_h [m] such that A3 without current hangs off at 4.372 deg from vertical (BVP).
    ``solved``: a list to append each solve to, as (scene, 'bvp', result) (brentq returns
    a point it evaluated: the A3 case is among them)."""
    a3 = resolve("yu2021-a3")

    def resid(xh):
        sc = with_hang_off_x(a3, xh)
        res = solve_scene(sc, "bvp")
        if solved is not None:
            solved.append((sc, "bvp", res))
        if not res.converged:
            raise SolveFailed("bvp", res.status, f"calibration: bvp failed at X_h = {xh}: "
                              f"{res.message}")
        return 90.0 - res.summary()["hang_off_angle_deg"] - TARGET_ANGLE_FROM_VERTICAL

    xh = brentq(resid, 500.0, 750.0, xtol=1e-3)
    log(f"yu2021: calibrated hang-off offset X_h = {xh:.3f} m")
    return xh


# ----------------------------------------------------------------------------- quantities
def quantities(result, scene: Scene) -> dict:
    """The paper's quantities for one converged result (paper frame for positions)."""
    p = result.profile
    sm = result.summary()
    xh = scene.ends.hang_off[0]
    out = {"hang_off_tension": sm["hang_off_tension"], "max_moment": sm["max_moment"],
           "hang_off_angle_from_vertical": 90.0 - sm["hang_off_angle_deg"]}
    buoys = buoy_indices(scene)
    edges = np.concatenate([[0.0], np.cumsum([s.length for s in scene.segments])])
    if buoys:
        top_end = edges[buoys[0] + 1]
        sel = p.s <= top_end + SAME_S
        out["lower_max_tension"] = float(np.max(p.tension[sel]))
    for k, i in enumerate(buoys, start=1):
        sel = np.flatnonzero((p.s >= edges[i] - SAME_S) & (p.s <= edges[i + 1] + SAME_S))
        j = int(sel[np.argmax(p.y[sel])])
        # a vertex inside the section: the parabola's through the station and its two
        # neighbours (as the protocol's crests; the station alone is up to half a station
        # spacing off, 0.5 m on a 1 m VFIFE mesh); a shoulder: the section's end station
        sv, yv = (_parabolic_peak(p.s, p.y, j) if sel[0] < j < sel[-1]
                  else (float(p.s[j]), float(p.y[j])))
        out[f"crest{k}_x"] = float(xh - np.interp(sv, p.s, p.x))
        out[f"crest{k}_depth"] = float(DEPTH - yv)
        out[f"crest{k}_moment"] = float(np.interp(sv, p.s, p.moment))
    return out


# ----------------------------------------------------------------------------- running
def cases(xh: float) -> list[tuple[str, str, Scene]]:
    """(study, case, scene) for every case of the reproduction."""
    base = {k: with_hang_off_x(resolve(f"yu2021-a{k}"), xh) for k in "1234"}
    a3 = base["3"]
    out = [("layout", f"A{k}", sc) for k, sc in base.items()]
    for gap in (100.0, 75.0, 50.0):
        out.append(("gap", f"{gap:g}", layout(a3_layout(gap=gap), a3)))
    for k, sc in base.items():
        for f in (0.9, 1.1):
            out.append(("buoyancy", f"A{k} x{f:g}", with_buoyancy(sc, {i: f for i in buoy_indices(sc)})))
    for name, i in zip(("first", "middle", "last"), buoy_indices(a3)):
        out.append(("buoyancy_loss", name, with_buoyancy(a3, {i: 0.8})))
    for v in (0.0, 0.6, 1.2):
        out.append(("current", f"{v:g}", sheared(a3, v)))
    for d in (0.0, 50.0, 100.0):
        out.append(("moved_up", f"{d:g}", layout(a3_layout(moved_up=d), a3)))
    return out


def run(out_dir: str | Path = "reports/yu2021", methods=("bvp", "vfife"), log=print,
        element_length: float | None = None, note: str = "") -> pd.DataFrame:
    """Run every case with the given methods; write table.csv, report.md and figures, and
    with the VFIFE the dynamic study (:mod:`verification.studies.yu2021.dynamics`: dynamics.csv,
    dynamics.png and the report's section); ``note``: a sentence on contended timings."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    solved = []     # (scene, method, result): current 0 is A3, moved up 0 is gap 100
    xh = calibrate_hang_off_x(log, solved)
    stored = resolve("yu2021-a3").ends.hang_off[0]
    rows, results, timing, missing = [], {}, {m: 0.0 for m in methods}, []
    for study, case, sc in cases(xh):
        q = {}
        for m in methods:
            t = time.perf_counter()
            res, why = _solve(sc, m, element_length, solved)
            timing[m] += time.perf_counter() - t
            if res is None:       # said in the report beside the values the other gave
                missing.append(f"- {study}/{case}: no {m.upper()} values ({why}).")
                log(f"yu2021: {study}/{case} has no {m.upper()} values (in the report)")
                q[m] = {}
                continue
            results[(study, case, m)] = (res, sc)
            q[m] = quantities(res, sc)
        cond = (conditioning(results[(study, case, "bvp")][0], sc, buoy_indices(sc))
                if (study, case, "bvp") in results else None)
        paper = PAPER.get((study, case), {})
        names = list(paper) or ["hang_off_tension", "max_moment", "lower_max_tension",
                                "crest1_depth"]
        for name in names:
            row = {"study": study, "case": case, "quantity": name, "paper": paper.get(name)}
            for m in ("bvp", "vfife"):
                val = _value(q.get(m, {}), name, study, results, m)
                row[m] = val
                pv = row["paper"]
                row[f"{m}_rel_err"] = ((val - pv) / abs(pv)) if (val is not None and pv) else None
            row.update(_method_agreement(name, row, cond, results, q))
            rows.append(row)
    df = pd.DataFrame(rows, columns=COLUMNS)
    df.to_csv(out / "table.csv", index=False, float_format="%.8g")
    _figures(results, out, methods)
    dyn = run_dynamics(out, {f"A{k}": sheared(with_hang_off_x(resolve(f"yu2021-a{k}"), xh),
                                              TOP_SPEED) for k in "123"},
                       log, element_length, note=note) if "vfife" in methods else []
    _report(df, out, xh, stored, timing, time.perf_counter() - t0, methods, dyn, missing)
    return df


def _solve(sc: Scene, method: str, element_length, solved: list):
    """(result, '') of ``sc`` with ``method``, taken from ``solved`` (scene, method,
    result) when solved before, else solved and added to it; (None, reason) when it did
    not converge or was refused before solving."""
    res = next((r for s, k, r in solved if k == method and s == sc), None)
    if res is None:
        res = solve_scene(sc, method, element_length=element_length)
        if res.status is Status.REFUSED:
            return None, res.message
        solved.append((sc, method, res))
    return (res, "") if res.converged else (None, res.message)


def _method_agreement(name: str, row: dict, cond, results: dict, q: dict) -> dict:
    """VFIFE - BVP of one quantity, its tolerance (:mod:`.agreement`) and whether it is
    within (empty when a method gave no value)."""
    if cond is None or row.get("bvp") is None or row.get("vfife") is None:
        return {"vfife_minus_bvp": None, "tolerance": None, "within": None}
    parts = None
    if name == "lower_max_tension_ratio":
        ref_res, ref_sc = results[("gap", "100", "bvp")]
        ref = conditioning(ref_res, ref_sc, buoy_indices(ref_sc))
        parts = ((q["bvp"]["lower_max_tension"], cond["T_max"]),
                 (quantities(ref_res, ref_sc)["lower_max_tension"], ref["T_max"]))
    tol, _ = method_tolerance(name, cond, parts)
    d = row["vfife"] - row["bvp"]
    return {"vfife_minus_bvp": d, "tolerance": tol, "within": bool(abs(d) <= tol)}


def _value(q: dict, name: str, study: str, results: dict, method: str):
    if name == "lower_max_tension_ratio":
        ref = results.get(("gap", "100", method))
        if ref is None or "lower_max_tension" not in q:
            return None
        return q["lower_max_tension"] / quantities(*ref)["lower_max_tension"]
    return q.get(name)


def _figures(results: dict, out: Path, methods) -> None:
    for study in ("layout", "gap", "buoyancy_loss", "current", "moved_up"):
        fig, axes = new_figure(3, 1, (9, 11))
        for (st, case, m), (res, sc) in results.items():
            if st != study:
                continue
            p = res.profile
            style = "-" if m == "bvp" else "--"
            xh = sc.ends.hang_off[0]
            label = f"{case} {m}"
            axes[0, 0].plot(xh - p.x, DEPTH - p.y, style, label=label)
            axes[1, 0].plot(p.s[-1] - p.s, p.tension / 1e3, style, label=label)
            axes[2, 0].plot(p.s[-1] - p.s, p.moment / 1e3, style, label=label)
        axes[0, 0].invert_yaxis()
        axes[0, 0].set_xlabel("horizontal distance from the hang-off [m] (paper frame)")
        axes[0, 0].set_ylabel("depth below the hang-off [m]")
        if study == "layout":
            crest = PAPER[("layout", "A3")]
            axes[0, 0].plot([crest[f"crest{k}_x"] for k in (1, 2, 3)],
                            [crest[f"crest{k}_depth"] for k in (1, 2, 3)], "k*", ms=10,
                            label="paper A3 crests")
        axes[1, 0].set_ylabel("effective tension [kN]")
        axes[2, 0].set_ylabel("bending moment [kN m]")
        axes[2, 0].set_xlabel("arc length from the hang-off [m]")
        for ax in axes[:, 0]:
            ax.grid(alpha=0.3)
        axes[0, 0].legend(fontsize=7, ncol=2)
        save(fig, out / f"{study}.png")


def _report(df: pd.DataFrame, out: Path, xh: float, stored: float, timing: dict, total: float,
            methods, dynamics: list[str], missing: list[str]) -> None:
    has_vf = "vfife" in methods
    lines = [
        "# Yu et al. (2021): multi-buoy lazy-wave riser studies, BVP" + (" and VFIFE" if has_vf else ""),
        "",
        GENERATED_NOTE,
        "",
        "Flexible riser of Table 1 (docs/references.md, Yu et al. 2021): 1050 m in 500 m of "
        "water, buoyancy sections with 1130 N/m uplift. Frames converted: positions below are "
        "in the paper's frame (horizontal distance from the hang-off, depth below it).",
        "",
        "## Assumptions (the paper does not give these)",
        "",
        f"- Hang-off horizontal offset from the anchor X_h = **{xh:.3f} m**, calibrated once with "
        f"the BVP so that A3 without current hangs off at {TARGET_ANGLE_FROM_VERTICAL} deg from "
        f"vertical, and kept for every case (the built-in scenes store {stored:.2f} m).",
        "- No internal contents; seabed stiffness 1e5 N/m2 (a soft clay; not given), the same elastic seabed and extensible line for both methods.",
        "- Sheared current: linear from 0 at the seabed to the top speed at the surface, flowing "
        "towards the anchor side (the paper's +x is our -x).",
        "- Gap study: the lowest section and the total length are kept, the hanging section takes "
        "up the difference. Moved-up study: hanging section shortened and lower section "
        "lengthened by the move. Buoyancy study: +-10 % (the paper gives no values; trends only).",
        "- Crest of a section = highest point of the line within that buoyancy section; "
        "'lower-middle max tension' = largest tension below the top of the uppermost section.",
        "",
        "## Where the paper contradicts itself",
        "",
    ]
    lines += [f"- {c}" for c in CONTRADICTIONS]
    cmp = df[df.paper.notna()]
    lines += ["", "## Summary", ""]
    for m in methods:
        err = cmp[f"{m}_rel_err"].abs()
        if err.notna().any():
            i = err.idxmax()
            lines.append(f"- {m.upper()} vs paper: median |rel. diff| {pct(err.median(), 1)}, worst "
                         f"{pct(err.max(), 1)} ({cmp.loc[i, 'study']}/{cmp.loc[i, 'case']} "
                         f"{cmp.loc[i, 'quantity']}); wall time "
                         f"{timed(timing[m], '.1f')} for all cases.")
    if has_vf:
        both = df[df.bvp.notna() & df.vfife.notna()]
        if len(both):
            rel = ((both.vfife - both.bvp).abs() / both.bvp.abs().where(both.bvp != 0))
            lines.append(f"- VFIFE vs BVP over every reported quantity: worst |rel. diff| "
                         f"{pct(rel.max(), 2)}, median {pct(rel.median(), 2)}.")
            lines += within_lines(both)
    if missing:
        lines += ["- Cases a method gave no values for (their rows give the other alone):",
                  *("  " + m for m in missing)]
    lines.append(f"- Report generated in {timed(total, '.1f')}.")
    lines += ["", "Differences to the paper of a few percent are expected: the paper leaves "
              "the hang-off offset and the contents unstated (heavier contents lower the crests "
              "and raise the hang-off tension); nothing here is tuned to its numbers beyond the "
              "single calibration of X_h.", ""]
    for study in ("layout", "gap", "buoyancy", "buoyancy_loss", "current", "moved_up"):
        sub = df[df.study == study]
        lines += [f"## Study: {study}", ""]
        lines.append(md_table(["case", "quantity", "paper", "bvp", "vfife", "bvp rel. err",
                               "vfife rel. err"],
                              [(r.case, r.quantity, r.paper, r.bvp, r.vfife, pct(r.bvp_rel_err, 1),
                                pct(r.vfife_rel_err, 1)) for r in sub.itertuples()]))
        lines += ["", f"![{study}]({study}.png)" if study != "buoyancy" else "", ""]
    lines += dynamics
    lines += ["## Files", "", "`table.csv`: columns " + ", ".join(f"`{c}`" for c in COLUMNS) +
              "; tensions in N, moments in N m, positions in m (paper frame), angles in deg "
              "from vertical.", ""]
    (out / "report.md").write_text("\n".join(lines))


def index_row(d: Path):
    """(cases, worst agreement, verdict) of a reproduction directory."""
    if not (d / "table.csv").exists():
        return None
    df = pd.read_csv(d / "table.csv")
    cmp = df[df.paper.notna()]
    parts = []
    for m in ("bvp", "vfife"):
        col = cmp[f"{m}_rel_err"].abs()
        if col.notna().any():
            parts.append(f"{m.upper()} vs paper median {pct(col.median(), 1)}, worst "
                         f"{pct(col.max(), 1)}")
    both = df[df.bvp.notna() & df.vfife.notna()]
    if len(both):
        rel = ((both.vfife - both.bvp).abs() / both.bvp.abs())
        parts.append(f"VFIFE vs BVP worst {pct(rel.max(), 2)}")
    cases = f"{df[['study', 'case']].drop_duplicates().shape[0]} cases"
    return cases, "; ".join(parts), "reported (paper inputs incomplete)"


STUDY = Study("yu2021", (None,), lambda unit, out, note, full: run(out, note=note), index_row,
              seconds={None: 115})


"""Yu et al. (2021), section 2.3: hang-off heave of layouts A1, A2, A3, with the VFIFE.

Heave 1.5 m, 10 s, in the sheared current (1.2 m/s at the top, 0 at the seabed, the paper's
+x); the static study's scenes as they are (:mod:`verification.studies.yu2021.cases` builds them), plus
``[dynamics]``. Definitions, from the paper's text (section 2.3):

- max moment, max hang-off effective tension: "对稳定了的最大弯矩、最大有效张力(悬挂点处)":
  their largest values over a steady period (Figs. 14 and 15);
- lateral speed: "立管横向(y 方向)速度分量 ... 此时立管顶端施加的是垂向运动, 横向速度为 0"
  (Fig. 16: the lateral (y) velocity component; the top moves vertically, so its lateral
  speed is 0). The component that vanishes at a vertically moving top is horizontal, and
  the out-of-plane one vanishes everywhere in this planar case, so the paper's lateral (y)
  speed is the horizontal in-plane velocity: our v_x. Its Fig. 17 "纵向(x 方向)" component
  (English caption: "Vertical velocity component") is then the vertical one; the features
  the text gives for it are compared below as a check of that reading. "对达到稳定状态后的一个
  周期内的立管质点速度进行分析": the node velocities over one period after the steady state;
- peak location from the top: "立管自身的最大运动速度在 ... 距离立管顶部 420 m 处" with the
  hanging section "悬垂段为 550 m" beside it: the arc length from the hang-off to the node
  of the largest |v_x| over that period (refined by a parabola through three nodes);
- lateral speed range: "横向最大速度点的速度在 -0.5 ~ 0.5 m/s 之间": the speed at that node
  stays within +-this value, i.e. its largest |v_x| over the period (min and max are also
  reported).

Structural damping: Table 1 gives "结构阻尼系数 0.8" and eq. (1) has it as the factor mu of
the mass matrix, ``M x'' + mu M x' + ...`` (and ``mu I theta'``): a mass-proportional
coefficient [1/s] on the absolute velocity, what ``[dynamics] damping`` is. One difference:
our damping also multiplies the added mass (normal to the line), the paper's eq. (1) the
translational mass M_n (its added mass M_nf is a separate term), so normal to the line our
damping force is (m + m_a)/m times the paper's if M_n excludes it. The study uses 0.8 as
given and shows the answer with 0 (drag only) and with 0.8 m/(m + m_a) (the paper's force
normal to the line) beside it.
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np
import pandas as pd

from riser.results.profile import _parabolic_peak
from riser.model.scene import Dynamics, Scene, TopMotion
from riser.model.sections import segment_properties
from verification.pipeline import solve_scene
from verification.report.figures import new_figure, save
from verification.report.markdown import md_table, pct, timed

AMPLITUDE, PERIOD = 1.5, 10.0          # m, s: the hang-off heave
TOP_SPEED = 1.2                        # m/s at the surface
DAMPING = 0.8                          # 1/s, Table 1 read as eq. (1)'s mu
DURATION = 60.0                        # s: ramp (one period) + 5 periods; checked steady
OUTPUT_INTERVAL = 0.25                 # s: period/40 (also the statistics' sampling)
CASES = ("A1", "A2", "A3")
QUANTITIES = ("max_moment", "max_hang_off_tension", "lateral_speed_peak_from_top",
              "lateral_speed_range")
UNITS = dict(zip(QUANTITIES, ("N m", "N", "m", "m/s")))
PAPER = {   # section 2.3, SI
    "A1": {"max_moment": 161.2e3, "max_hang_off_tension": 230.2e3,
           "lateral_speed_peak_from_top": 420.0, "lateral_speed_range": 0.50},
    "A2": {"max_moment": 213.4e3, "max_hang_off_tension": 212.4e3,
           "lateral_speed_peak_from_top": 390.0, "lateral_speed_range": 0.49},
    "A3": {"max_moment": 234.2e3, "max_hang_off_tension": 200.7e3,
           "lateral_speed_peak_from_top": 374.0, "lateral_speed_range": 0.48},
}
#: Fig. 17 (vertical speed, the paper's x): first near-zero, peak, second near-zero, m from top
PAPER_VERTICAL = {"A1": (477.0, 584.0, 667.0), "A2": (433.0, 525.0, 586.0),
                  "A3": (400.0, 464.0, 516.0)}
#: the paper's static peak moment of A3 in the same current (section 2.2.5, 1.2 m/s) [N m]
PAPER_STATIC_CURRENT_MOMENT = {"A3": 250.8e3}
#: the layouts whose damping sensitivity is run (each run ~5 s)
SENSITIVITY_CASES = ("A1",)
COLUMNS = ("case", "quantity", "paper", "vfife", "rel_err")


def dynamic_scene(scene: Scene, damping: float = DAMPING, duration: float = DURATION,
                  output_interval: float = OUTPUT_INTERVAL) -> Scene:
    """``scene`` with the paper's heave (default ramp: one period), statistics over the last
    period and the node states saved."""
    return scene.replace(dynamics=Dynamics(
        duration=duration, output_interval=output_interval,
        top_motion=TopMotion(axis="y", amplitude=AMPLITUDE, period=PERIOD), damping=damping,
        statistics_start=duration - PERIOD, save_states=True))


def added_mass_share(scene: Scene) -> float:
    """m / (m + m_a) of the first segment (pipe + contents over that plus the added mass)."""
    p = segment_properties(scene)[0]
    return p.mass / (p.mass + p.added_mass)


# ----------------------------------------------------------------------------- quantities
def _window(t: np.ndarray, t0: float, t1: float) -> np.ndarray:
    return (t >= t0 - 1e-9) & (t <= t1 + 1e-9)


def lateral_speed(states: dict, t0: float, t1: float, axis: int = 0) -> dict:
    """The paper's lateral speed over the window [t0, t1] [s] from saved states (``t`` (k,),
    ``s`` (n,), ``v`` (k, n, 3)): ``amplitude`` (n,) = max |v[axis]| over the window per
    node; ``peak_s`` and ``peak_from_top`` [m] (s[-1] - peak_s: the hang-off is the last
    node) where it is largest; ``range`` [m/s], its largest |v| (at the peak node); ``v_min``,
    ``v_max`` [m/s] at that node; ``samples`` in the window."""
    sel = _window(np.asarray(states["t"]), t0, t1)
    s = np.asarray(states["s"], float)
    v = np.asarray(states["v"])[sel, :, axis]
    amp = np.max(np.abs(v), axis=0)
    j = int(np.argmax(amp))
    peak = _parabolic_peak(s, amp, j)[0]       # j is the largest: a concave parabola
    return {"amplitude": amp, "peak_s": peak, "peak_from_top": float(s[-1] - peak),
            "range": float(amp[j]), "v_min": float(v[:, j].min()),
            "v_max": float(v[:, j].max()), "samples": int(sel.sum())}


def vertical_features(states: dict, t0: float, t1: float) -> tuple[float, float, float]:
    """Fig. 17's features of the vertical speed amplitude, m from the top: the first
    near-zero (first local minimum below 20 % of the top's amplitude), the largest amplitude
    within 250 m below it, the next near-zero after that peak (NaN when absent)."""
    a = lateral_speed(states, t0, t1, axis=1)["amplitude"][::-1]
    s = np.asarray(states["s"], float)
    d = s[-1] - s[::-1]                      # from the top
    low = 0.2 * a[0]
    mins = [i for i in range(1, len(a) - 1) if a[i] <= a[i - 1] and a[i] <= a[i + 1]
            and a[i] < low]
    if not mins:
        return (math.nan,) * 3
    z1 = mins[0]
    zone = np.flatnonzero((d > d[z1]) & (d <= d[z1] + 250.0))
    if not len(zone):
        return d[z1], math.nan, math.nan
    p = int(zone[np.argmax(a[zone])])
    z2 = next((i for i in mins if i > p), None)
    return float(d[z1]), float(d[p]), float(d[z2]) if z2 is not None else math.nan


def period_values(res, t0: float, t1: float) -> dict:
    """The four quantities over [t0, t1] from a dynamic result's time series and states."""
    ts = res.dynamics.timeseries
    sel = _window(ts["time"], t0, t1)
    lat = lateral_speed(res.dynamics.states, t0, t1)
    i = int(np.argmax(np.where(sel, ts["max_moment"], -np.inf)))
    top = float(res.dynamics.states["s"][-1])
    return {"max_moment": float(ts["max_moment"][i]),
            "max_moment_from_top": top - float(ts["max_moment_s"][i]),
            "max_hang_off_tension": float(np.max(ts["hang_off_tension"][sel])),
            "min_hang_off_tension": float(np.min(ts["hang_off_tension"][sel])),
            "lateral_speed_peak_from_top": lat["peak_from_top"],
            "lateral_speed_range": lat["range"], "v_min": lat["v_min"], "v_max": lat["v_max"]}


def _segment_label(scene: Scene, s: float) -> str:
    """The label of the segment holding arc length s [m] (from the bottom end)."""
    top = 0.0
    for seg in scene.segments:
        top += seg.length
        if s <= top + 1e-9:
            return seg.label or ""
    return scene.segments[-1].label or ""


# ----------------------------------------------------------------------------- running
def _solve(case: str, scene: Scene, damping: float, element_length, duration: float, log):
    sc = dynamic_scene(scene, damping, duration)
    t = time.perf_counter()
    res = solve_scene(sc, "vfife", element_length=element_length)
    wall = time.perf_counter() - t
    if not res.converged:
        log(f"yu2021: dynamics {case} (damping {damping:g}) failed: {res.message}")
        return None
    last = period_values(res, duration - PERIOD, duration)
    prev = period_values(res, duration - 2 * PERIOD, duration - PERIOD)
    log(f"yu2021: dynamics {case} (damping {damping:g} 1/s) in {wall:.1f} s")
    return {"case": case, "damping": damping, "res": res, "last": last, "prev": prev,
            "where": _segment_label(scene, res.dynamics.states["s"][-1]
                                    - last["max_moment_from_top"]),
            "wall": wall, "dyn_wall": res.info.get("dynamic_wall_s", math.nan),
            "vertical": vertical_features(res.dynamics.states, duration - PERIOD, duration)}


def run(out_dir: str | Path, scenes: dict[str, Scene], log=print, element_length=None,
        duration: float = DURATION, sensitivity: bool = True, note: str = "") -> list[str]:
    """Run the dynamic study on ``scenes`` (case -> the static study's scene with the
    sheared current); write ``dynamics.csv`` and ``dynamics.png`` into ``out_dir`` and
    return the report's "Dynamics" section (Markdown lines)."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    runs = {c: _solve(c, sc, DAMPING, element_length, duration, log)
            for c, sc in scenes.items()}
    share = added_mass_share(next(iter(scenes.values())))
    alt = (0.0, round(DAMPING * share, 3)) if sensitivity else ()
    sens = {(c, d): _solve(c, sc, d, element_length, duration, log)
            for d in alt for c, sc in scenes.items() if c in SENSITIVITY_CASES}
    frame = table(runs)
    frame.to_csv(out / "dynamics.csv", index=False, float_format="%.8g")
    _figure(runs, out / "dynamics.png", duration)
    return _section(frame, runs, sens, share, duration, element_length,
                    time.perf_counter() - t0, note)


def table(runs: dict) -> pd.DataFrame:
    """The dynamics.csv rows: (case, quantity, paper, vfife, rel_err), SI units."""
    rows = []
    for case, r in runs.items():
        for q in QUANTITIES:
            paper = PAPER.get(case, {}).get(q)
            val = r["last"][q] if r is not None else None
            rel = (val - paper) / abs(paper) if (val is not None and paper) else None
            rows.append({"case": case, "quantity": q, "paper": paper, "vfife": val,
                         "rel_err": rel})
    return pd.DataFrame(rows, columns=list(COLUMNS))


def _figure(runs: dict, path: Path, duration: float) -> None:
    fig, ax = new_figure(2, 2, (12, 8.5))
    for case, r in runs.items():
        if r is None:
            continue
        ts, st = r["res"].dynamics.timeseries, r["res"].dynamics.states
        ax[0, 0].plot(ts["time"], ts["hang_off_tension"] / 1e3, lw=1.0, label=case)
        ax[0, 1].plot(ts["time"], ts["max_moment"] / 1e3, lw=1.0, label=case)
        top = st["s"][-1] - st["s"]
        for axis, a in ((0, ax[1, 0]), (1, ax[1, 1])):
            lat = lateral_speed(st, duration - PERIOD, duration, axis)
            line, = a.plot(top, lat["amplitude"], lw=1.2, label=f"{case} VFIFE")
            if axis == 0:
                p = PAPER[case]
                a.plot(p["lateral_speed_peak_from_top"], p["lateral_speed_range"], "*", ms=11,
                       color=line.get_color(), label=f"{case} paper peak")
            else:
                for k, d in enumerate(PAPER_VERTICAL[case]):
                    a.axvline(d, color=line.get_color(), ls=":" if k != 1 else "--", lw=0.9)
    for a in ax[0]:
        a.axvspan(duration - PERIOD, duration, color="0.9", zorder=0)
        a.set_xlabel("time t [s] (shaded: the period of the table)")
    ax[0, 0].set_ylabel("hang-off effective tension [kN]")
    ax[0, 1].set_ylabel("largest bending moment along the line [kN m]")
    ax[1, 0].set_ylabel("lateral (horizontal) speed amplitude max|v_x| [m/s]")
    ax[1, 1].set_ylabel("vertical speed amplitude max|v_y| [m/s]")
    ax[1, 1].set_title("paper (Fig. 17 text): near-zero dotted, peak dashed", fontsize=9)
    for a in ax[1]:
        a.set_xlabel("arc length from the hang-off [m] (last period)")
    for a in ax.ravel():
        a.grid(alpha=0.3)
        a.legend(fontsize=7, ncol=2)
    save(fig, path)


# ----------------------------------------------------------------------------- report
def _steady(runs: dict) -> tuple[float, float]:
    """Largest relative change of the force quantities and of the lateral speed, and the
    largest shift of the peak location [m], between the last two periods."""
    rel, shift = 0.0, 0.0
    for r in runs.values():
        if r is None:
            continue
        for q in ("max_moment", "max_hang_off_tension", "lateral_speed_range"):
            rel = max(rel, abs(r["last"][q] - r["prev"][q]) / abs(r["last"][q]))
        shift = max(shift, abs(r["last"]["lateral_speed_peak_from_top"]
                               - r["prev"]["lateral_speed_peak_from_top"]))
    return rel, shift


def _trend(ok: dict) -> list[str]:
    """A sentence comparing the change from A1 to A2 and A3 with the paper's."""
    if not all(c in ok for c in CASES):
        return []
    parts = []
    for q, name in (("max_moment", "max moment"), ("max_hang_off_tension",
                                                   "max hang-off tension")):
        ours = [ok[c]["last"][q] / ok["A1"]["last"][q] - 1.0 for c in CASES[1:]]
        paper = [PAPER[c][q] / PAPER["A1"][q] - 1.0 for c in CASES[1:]]
        parts.append(f"{name} {' / '.join(pct(v, 1) for v in paper)} (paper) and "
                     f"{' / '.join(pct(v, 1) for v in ours)} (VFIFE)")
    return ["From A1 to A2 / A3: " + "; ".join(parts) + ".", ""]


def _section(frame, runs, sens, share, duration, element_length, total, note) -> list[str]:
    ok = {c: r for c, r in runs.items() if r is not None}
    el = element_length if element_length is not None else next(
        (r["res"].info["element_length"] for r in ok.values()), math.nan)
    rel, shift = _steady(runs)
    lines = [
        "## Dynamics", "",
        f"Section 2.3 of the paper: hang-off heave {AMPLITUDE} m, period {PERIOD:g} s, in the "
        f"sheared current ({TOP_SPEED} m/s at the top, 0 at the seabed, towards the anchor "
        "side), layouts A1, A2, A3 as above (same calibrated hang-off offset, empty contents, "
        "seabed 1e5 N/m2). VFIFE only (the BVP has no dynamics).", "",
        "Setup and assumptions:", "",
        f"- Run: {duration:g} s from the static equilibrium, the heave ramped in over one "
        f"period (half-cosine), output every {OUTPUT_INTERVAL} s (period/40); the table is "
        f"taken over the last period ({duration - PERIOD:g}-{duration:g} s), the paper's "
        "'one period after the steady state'.",
        f"- Elements of {el:g} m (the paper's: 1 m); Morison drag on the relative "
        "velocity, added mass normal to the line, sea surface at 500 m (the top rises 1.5 m "
        "out of the water: that length carries its weight in air, no drag).",
        f"- Structural damping: Table 1's 0.8 read as eq. (1)'s mu (`M x'' + mu M x'`), a "
        f"mass-proportional coefficient, `[dynamics] damping = {DAMPING}` 1/s. Our damping "
        f"also acts on the added mass normal to the line: m/(m + m_a) = {share:.3f}, so "
        "if the paper's M_n is the pipe's mass alone, our damping force normal to the line "
        f"is {1 / share:.2f}x the paper's. Not tuned; the sensitivity is below.",
        "- Lateral speed = the paper's 'lateral (y) velocity component', which it says is 0 "
        "at the vertically moving top: the horizontal in-plane velocity (our v_x; the "
        "out-of-plane one is 0 in this planar case). Peak location = arc length from the "
        "hang-off to the node of the largest |v_x| over the last period (parabola through "
        "three nodes); range = that largest |v_x| (the paper: 'between -0.5 and 0.5 m/s').",
        "- Max moment: largest bending moment along the line over the period (Fig. 14); max "
        "hang-off tension: largest effective tension at the hang-off (Fig. 15).", "",
        md_table(["case", "quantity", "unit", "paper", "VFIFE", "rel. err"],
                 [(r.case, r.quantity, UNITS[r.quantity], r.paper, r.vfife, pct(r.rel_err, 1))
                  for r in frame.itertuples()]), "",
        "Static state (this run's start: the same scene and current) against the dynamics, "
        "and where the largest moment is:", "",
        md_table(["case", "static max moment [kN m]", "dynamic [kN m]", "paper dynamic",
                  "paper static, same current", "at (m from top)", "in",
                  "static hang-off tension [kN]", "dynamic min-max [kN]",
                  "v_x at the peak node min / max [m/s]"],
                 [(c, r["res"].summary()["max_moment"] / 1e3, r["last"]["max_moment"] / 1e3,
                   PAPER[c]["max_moment"] / 1e3,
                   PAPER_STATIC_CURRENT_MOMENT.get(c, math.nan) / 1e3,
                   r["last"]["max_moment_from_top"], r["where"],
                   r["res"].summary()["hang_off_tension"] / 1e3,
                   f"{r['last']['min_hang_off_tension'] / 1e3:.1f} - "
                   f"{r['last']['max_hang_off_tension'] / 1e3:.1f}",
                   f"{r['last']['v_min']:+.3f} / {r['last']['v_max']:+.3f}")
                  for c, r in ok.items()]), "",
        f"Steady state: between the last two periods the moment, hang-off tension and "
        f"lateral speed change by at most {100 * rel:.3f} % and the peak location by "
        f"{shift:.1f} m" + (" (steady)." if rel < 5e-3 and shift <= 5.0 else
                            " (NOT steady: lengthen the run)."), "",
        *_trend(ok), "Check of the axis reading: the paper's Fig. 17 component (x, 'vertical velocity "
        "component') against our vertical speed amplitude, m from the top (not in "
        "dynamics.csv):", "",
        md_table(["case", "first near-zero paper", "VFIFE", "peak paper", "VFIFE",
                  "second near-zero paper", "VFIFE"],
                 [(c, PAPER_VERTICAL[c][0], r["vertical"][0], PAPER_VERTICAL[c][1],
                   r["vertical"][1], PAPER_VERTICAL[c][2], r["vertical"][2])
                  for c, r in ok.items() if c in PAPER_VERTICAL]), "",
    ]
    if sens:
        rows = []
        for d in sorted({d for _, d in sens} | {DAMPING}):
            for c in sorted({c for c, _ in sens}):
                r = runs.get(c) if d == DAMPING else sens.get((c, d))
                if r is not None:
                    q = r["last"]
                    rows.append((c, d, q["max_moment"] / 1e3, q["max_hang_off_tension"] / 1e3,
                                 q["lateral_speed_peak_from_top"], q["lateral_speed_range"],
                                 pct(_steady({c: r})[0], 2)))
        lines += ["Damping sensitivity (the same runs with another damping; not in "
                  "dynamics.csv):", "",
                  md_table(["case", "damping [1/s]", "max moment [kN m]",
                            "max hang-off tension [kN]", "peak from top [m]", "range [m/s]",
                            "change over the last two periods"], rows), ""]
    failed = [c for c, r in list(runs.items()) + list(sens.items()) if r is None]
    if failed:
        lines += [f"Runs that did not converge (see the log; their cells are empty): {failed}.",
                  ""]
    warn = sorted({w.split(":")[0] for r in ok.values() for w in r["res"].warnings})
    if warn:
        lines += [f"Warnings of the runs: {', '.join(warn)} (in each run's summary; the top "
                  "leaving the water at the heave's crest is expected).", ""]
    walls = [r["wall"] for r in ok.values()]
    dyn_static = max((abs(r["last"]["max_moment"] / r["res"].summary()["max_moment"] - 1.0)
                      for r in ok.values()), default=math.nan)
    drag_only = ""
    for (c, d), r in sens.items():
        if d == 0.0 and r is not None and runs.get(c) is not None:
            change = r["last"]["max_hang_off_tension"] / runs[c]["last"][
                "max_hang_off_tension"] - 1.0
            drag_only = f": drag alone changes the {c} value by {pct(change, 1)}"
    each = ", ".join(f"{c} {timed(r['wall'], '.1f')}" for c, r in ok.items())
    sens_wall = sum(r["wall"] for r in sens.values() if r is not None)
    lines += [
        f"Time: {len(walls)} runs at damping {DAMPING} took {timed(sum(walls), '.1f')} "
        f"({each}; of which the "
        f"dynamics {timed(sum(r['dyn_wall'] for r in ok.values()), '.1f')}, the rest statics)"
        + (f", {len(sens)} sensitivity runs {timed(sens_wall, '.1f')}" if sens else "")
        + f"; the section {timed(total, '.1f')} in all." + (f" {note}" if note else ""), "",
        "Reading the differences: the heave barely changes the peak moment here (dynamic "
        f"within {100 * dyn_static:.1f} % of the static one in the same current), so the "
        "moment carries the "
        "static offset of this reproduction (the static peak moments of A1-A3 in the layout "
        "study above are over the paper's too, from the unstated hang-off offset and "
        "contents); the paper's own A3 "
        "dynamic maximum (234.2 kN m) is below its static peak in the same current (250.8 "
        "kN m, section 2.2.5), which a heave about that static state cannot give, so part of "
        "the moment difference is in the paper. The paper places the largest moment in the "
        "first buoyancy section; here: " + "; ".join(f"{c} {r['where']}" for c, r in
                                                     ok.items()) + ". The hang-off tension depends on what the "
        "paper's damping 0.8 multiplies (not stated; see the sensitivity" + drag_only + "); "
        "the lateral speed depends little on it. Nothing here is tuned to the paper's "
        "numbers.", "",
        "![dynamics](dynamics.png)", "",
        "`dynamics.csv`: columns " + ", ".join(f"`{c}`" for c in COLUMNS) + "; SI units "
        "(N m, N, m, m/s); `rel_err` = (vfife - paper) / |paper|.", ""]
    return lines

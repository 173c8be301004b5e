"""Liu, Ai, Sun & Jia (2021): a steel catenary riser conveying steady slug flow, with the
VFIFE, and its slug case by the ANCF too (``riser-verify reproduce liu2021`` ->
``reports/liu2021/``; the two methods: :mod:`verification.studies.liu2021.methods`).

The built-in scene ``liu2021-scr`` (docs/references.md, Liu et al. 2021) in three variants: uniform
flow (the same mean density and speed, no slug), the paper's slug (eta 0.25, L_s 80 m) and
the slug-length study L_s/D = 100, 160, 220, 280; each a static solve (the slug frozen at
t = 0) and a run of the paper's 2000 s of top surge 0.5 sin(2 pi t / 9) m. The BVP refuses
a slug and has no dynamics: the paper's quantities are the VFIFE's; the slug case is also
run by the ANCF (its ALE internal flow, ancf/flow.py) and the two methods' response along s
compared within tolerances measured from each method's coarser run (methods.csv).

Definitions of the paper's quantities (section 2-3 of the paper, our reading):

- top tension: the effective tension at the hang-off (the paper does not say which; the
  wall tension is reported beside it); its amplitude: (max - min) / 2 over a steady
  window, the last whole common period of the surge (9 s) and the slug (L_s / U);
- node 35 and node 75: the paper's "140 m and 300 m from the anchor" (315 elements of
  4 m: node i at 4 i m counting the anchor as node 0); the moment there is interpolated
  between our nodes (the same 4 m mesh: it is the node's);
- the dominant frequency at a station: the largest line of the amplitude spectrum of the
  moment over the steady window, mean removed;
- the mean touchdown moment: the mean of the moment at 140 m over the last whole slug
  periods within the second half of the run; the "static touchdown moment" the paper's
  36 % refers to: the static moment at 140 m with uniform flow.

Moments are magnitudes (the nodal |M| the VFIFE reports); at both stations the moment
stays far from zero over the runs (its minimum is in the report), so no sign is lost.
Nothing is tuned to the paper's numbers; the inputs it does not give are the scene's
stated assumptions (E 207 GPa, seabed 1e5 N/m2, no tangential drag).
"""

from __future__ import annotations

import dataclasses
import math
import time
from pathlib import Path

import numpy as np
import pandas as pd

from riser.model.scene import Scene
from verification.catalog import resolve
from verification.pipeline import solve_scene
from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, md_table, pct, timed

from ..study import Study
from . import methods
from .analysis import (
    COLUMNS,
    PAPER,
    Run,
    common_period,
    dynamic_quantities,
    slug_length_quantities,
    spectrum,
    static_quantities,
    table,
    whole_periods,
    window,
    youngs_modulus,
)

SCENE = "liu2021-scr"
DURATION = 2000.0                 # s, the paper's run
OUTPUT_INTERVAL = 0.5             # s: 18 samples per surge period, Nyquist 1 Hz
STATIONS = (140.0, 300.0)         # m from the anchor: the paper's nodes 35 and 75
SLUG_RATIOS = (100.0, 160.0, 220.0, 280.0)     # L_s / D of section 3
#: station pairs [m] of the travel-speed reading: 30 m apart (< L_s / 2 = 40 m) in the
#: hanging part, above the sag bend and below the top
LAG_PAIRS = tuple((s, s + 30.0) for s in (300.0, 400.0, 500.0, 600.0, 700.0, 800.0))


def flow_scene(base: Scene, slug_length: float | None, duration: float = DURATION,
               output_interval: float = OUTPUT_INTERVAL) -> Scene:
    """``base`` with the slug of length ``slug_length`` [m] (None: uniform flow of the same
    mean density and speed), the run shortened to ``duration`` [s] and the node states
    saved every ``output_interval`` [s]."""
    flow = base.internal_flow
    flow = dataclasses.replace(flow, slug_length=slug_length, density_amplitude=(
        flow.density_amplitude if slug_length is not None else 0.0))
    dyn = dataclasses.replace(base.dynamics, duration=duration,
                              output_interval=output_interval, save_states=True)
    return base.replace(internal_flow=flow, dynamics=dyn)


def _solve(label: str, scene: Scene, element_length, log) -> Run | None:
    t0 = time.perf_counter()
    res = solve_scene(scene, "vfife", element_length=element_length)
    wall = time.perf_counter() - t0
    if not res.converged:
        log(f"liu2021: {label} failed ({res.status.value}): {res.message}")
        return None
    st = res.dynamics.states
    dyn = res.info.get("dynamic_wall_s", math.nan)
    rtf = res.info.get("realtime_factor", math.nan)
    log(f"liu2021: {label} in {wall:.1f} s (dynamics {dyn:.1f} s, {rtf:.0f}x real time)")
    return Run(label, scene.internal_flow.slug_length, res.profile, np.asarray(st["t"]),
               np.asarray(res.dynamics.timeseries["hang_off_tension"]),
               np.asarray(st["moment"]), wall, dyn, rtf, tuple(res.warnings))


def steady_length(duration: float, periods) -> tuple[float, bool]:
    """(window [s], whole common periods?): the common period of ``periods`` [s] when it
    fits in the second half of the run, else the whole periods of the first (the surge)
    that fit there (a short test run)."""
    common = common_period(periods)
    if common <= 0.5 * duration + 1e-9:
        return common, True
    return whole_periods(periods[0], 0.5 * duration), False


def run(out_dir: str | Path = "reports/liu2021", log=print, duration: float = DURATION,
        element_length: float | None = None, ratios=SLUG_RATIOS, note: str = "",
        two_methods: bool | None = None) -> dict:
    """Run the study; write table.csv, report.md and the figures into ``out_dir``.
    ``duration`` [s] and ``element_length`` [m] shorten and coarsen it (tests); ``note``: a
    sentence on timings measured next to other work; ``two_methods``: the slug case by the
    VFIFE and the ANCF (methods.csv, methods.png; default: only in a run of the paper's
    whole duration, the study's). Returns the quantities."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    base = resolve(SCENE)
    diameter = base.line_types[base.segments[0].line_type].outer_diameter
    cases = [("uniform", None), ("slug", base.internal_flow.slug_length)]
    cases += [(f"Ls/D={r:g}", round(r * diameter, 9)) for r in ratios]
    runs = {label: _solve(label, flow_scene(base, ls, duration), element_length, log)
            for label, ls in cases}
    uni, slug = runs["uniform"], runs["slug"]
    slug_scene = flow_scene(base, slug.slug_length if slug else None, duration)
    period = base.internal_flow.slug_length / base.internal_flow.speed
    length, whole = steady_length(duration, (base.dynamics.top_motion.period, period))
    q = {"duration": duration, "whole_common": whole,
         "element_length": element_length or base.vfife.element_length,
         "static": static_quantities(uni, slug, slug_scene) if uni and slug else None,
         "dynamic": dynamic_quantities(uni, slug, slug_scene, length, STATIONS, LAG_PAIRS)
         if uni and slug else None, "ratios": {}, "runs": runs}
    for r, (label, ls) in zip(ratios, cases[2:]):
        if runs[label] is not None:
            q["ratios"][r] = slug_length_quantities(
                runs[label], base, whole_periods(ls / base.internal_flow.speed, 0.5 * duration))
    frame = table(q)
    frame.to_csv(out / "table.csv", index=False, float_format="%.8g")
    _figures(q, out)
    if two_methods is None:
        two_methods = duration >= DURATION
    q["methods"] = None
    if two_methods:
        cmp_scene = flow_scene(base, base.internal_flow.slug_length, methods.DURATION)
        cmp_runs = methods.solve_runs(cmp_scene, log, element_length)
        cmp = methods.compare(cmp_runs)
        if cmp is not None:
            cmp.to_csv(out / "methods.csv", index=False, float_format="%.8g")
        methods.figure(cmp_runs, out)
        q["methods"] = (cmp_runs, cmp, cmp_scene)
    q["total"] = time.perf_counter() - t0
    write_report(out, q, frame, note)
    return q


# ----------------------------------------------------------------------------- figures
def _figures(q: dict, out: Path) -> None:
    runs, dy = q["runs"], q["dynamic"]
    uni, slug = runs["uniform"], runs["slug"]
    if uni is None or slug is None:
        return
    length = dy["window"]
    fig, ax = new_figure(2, 1, (10, 7))
    for r in (uni, slug):
        first = r.t <= length + 1e-9
        ax[0, 0].plot(r.t[first], r.top_tension[first] / 1e3, lw=1.0, label=f"{r.label} flow")
        sel = window(r.t, r.t[-1] + r.dt, length)
        ax[1, 0].plot(r.t[sel], r.top_tension[sel] / 1e3, lw=1.0, label=f"{r.label} flow")
    ax[0, 0].set_title(f"the start: first {length:g} s (surge ramped in over one period)",
                       fontsize=9)
    ax[1, 0].set_title(f"the steady window of the table: last {length:g} s", fontsize=9)
    for a in ax[:, 0]:
        a.set_xlabel("time t [s]")
        a.set_ylabel("hang-off effective tension [kN]")
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    save(fig, out / "top_tension.png")

    fig, ax = new_figure(3, 1, (9, 10))
    for r in (uni, slug):
        p = r.profile
        ax[0, 0].plot(p.s, p.tension / 1e3, lw=1.0, label=f"{r.label} flow")
        ax[1, 0].plot(p.s, p.moment / 1e3, lw=1.0, label=f"{r.label} flow")
    ax[2, 0].plot(uni.s, (slug.profile.moment - uni.profile.moment) / 1e3, lw=1.0,
                  label="moment: slug - uniform [kN m]")
    ax[2, 0].plot(uni.s, (slug.profile.tension - uni.profile.tension) / 1e3, lw=1.0,
                  label="tension: slug - uniform [kN]")
    ax[0, 0].set_ylabel("static effective tension [kN]")
    ax[1, 0].set_ylabel("static bending moment [kN m]")
    ax[2, 0].set_ylabel("difference")
    for a in ax[:, 0]:
        a.axvline(uni.profile.tdp_s, color="0.5", ls=":", lw=0.9)
        a.set_xlabel("arc length from the anchor s [m] (dotted: touchdown, uniform flow)")
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    save(fig, out / "static.png")

    fig, ax = new_figure(2, 2, (12, 8))
    for k, s0 in enumerate(STATIONS):
        for r in (uni, slug):
            m = r.station(s0, length)
            tw = r.t[window(r.t, r.t[-1] + r.dt, length)]
            ax[0, k].plot(tw, m / 1e3, lw=0.9, label=f"{r.label} flow")
            f, a = spectrum(m, r.dt)
            ax[1, k].plot(f, a / 1e3, lw=1.0, label=f"{r.label} flow")
        ax[0, k].set_title(f"s = {s0:g} m", fontsize=9)
        ax[0, k].set_xlabel("time t [s]")
        ax[0, k].set_ylabel("bending moment [kN m]")
        ax[1, k].axvline(dy["f_surge"], color="0.4", ls="--", lw=0.8, label="surge 1/9 Hz")
        ax[1, k].axvline(dy["f_slug"], color="0.4", ls=":", lw=0.8, label="slug U/L_s")
        ax[1, k].set_xlim(0.0, 0.4)
        ax[1, k].set_xlabel(f"frequency [Hz] (resolution {1 / length:.4f} Hz)")
        ax[1, k].set_ylabel("moment amplitude [kN m]")
    for a in ax.ravel():
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    save(fig, out / "moments.png")

    fig, ax = new_figure(1, 1, (8, 5))
    ls = q["ratios"]
    if ls:
        r = np.array(sorted(ls))
        mean = np.array([ls[k]["mean140"] for k in r]) / 1e3
        rng = np.array([ls[k]["range140"] for k in r]) / 1e3
        a = ax[0, 0]
        a.fill_between(r, mean - rng, mean + rng, color="C0", alpha=0.2,
                       label="VFIFE mean +- half-range")
        a.plot(r, mean, "o-", color="C0", label="VFIFE mean")
        a.plot(r, [ls[k]["static140"] / 1e3 for k in r], "s--", color="C2",
               label="VFIFE static (slug frozen at t = 0)")
        a.plot([100, 280], [101.06, 127.53], "k*", ms=11, label="paper mean (Fig. 10)")
        a.set_xlabel("slug length / outer diameter L_s / D")
        a.set_ylabel("moment at s = 140 m [kN m]")
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    save(fig, out / "slug_length.png")


# ----------------------------------------------------------------------------- report
def _setup(q: dict, base: Scene) -> list[str]:
    lt = base.line_types[base.segments[0].line_type]
    fl, dyn = base.internal_flow, base.dynamics
    dy = q["dynamic"]
    win = (f"the last {dy['window']:g} s, " + ("a whole number of both the surge and the "
           "slug periods" if q["whole_common"] else "whole surge periods only (the run is "
           "too short for a common period: NOT the paper's steady state)")) if dy else "-"
    return [
        "## What was run", "",
        f"Scene `{SCENE}` (docs/references.md, Liu et al. 2021): {base.segments[0].length:g} "
        "m of pipe, "
        f"anchor {base.ends.anchor}, hang-off {base.ends.hang_off} m in {base.water_depth:g} m "
        f"of water; D {lt.outer_diameter} m, D_i {lt.inner_diameter} m, {lt.mass_per_length} "
        f"kg/m in air; C_Dn {lt.drag_normal:g}, C_a {lt.added_mass:g} (C_m = 2); contents "
        f"{lt.contents_density} kg/m3 flowing at U = {fl.speed} m/s; slug eta "
        f"{fl.density_amplitude}, L_s {fl.slug_length:g} m, phase {fl.phase_deg:g} deg; top "
        f"surge {dyn.top_motion.amplitude} sin(2 pi t / {dyn.top_motion.period:g}) m along x "
        "(ramped in over one period). " + (
            "The paper's quantities by the VFIFE (the BVP refuses a slug and has no "
            "dynamics); the slug case also by the ANCF, below." if q.get("methods") else
            "VFIFE only: the BVP refuses a slug and has no dynamics (the ANCF's comparison "
            "runs with the whole study)."), "",
        "Assumptions (the paper does not give these; none is tuned to its numbers):", "",
        f"- Young's modulus {youngs_modulus(base) / 1e9:.4g} GPa (steel design value), so EI = "
        f"{lt.bending_stiffness:.3g} N m2 and EA = {lt.axial_stiffness:.3g} N.",
        f"- Seabed: linear elastic, {base.seabed.stiffness:g} N/m2 (the paper: 'soil "
        "stiffness', Elosta et al. 2013, no value); no seabed friction.",
        "- Tangential drag 0; no current; no structural damping (drag damps the run).",
        "- Internal flow as in vfife/flow.py: centrifugal (U^2 dmu/ds) and Coriolis "
        "(-2 mu U tau_t) forces, the nodes' mass and weight following the slug; the "
        "effective tension is the shape equations' (the wall tension beside it).",
        "- Uniform flow: the same mean density and speed without the slug (the paper's "
        "comparison case).", "",
        f"Runs: {len(q['runs'])} (uniform, slug L_s {fl.slug_length:g} m, and L_s/D = "
        f"{', '.join(f'{r:g}' for r in q['ratios'])}), each a static solve (the slug frozen at "
        f"t = 0) and {q['duration']:g} s of dynamics from it (the paper: 2000 s), "
        f"{q['element_length']:g} m elements "
        f"({round(base.segments[0].length / q['element_length'])} elements; the paper: 315), "
        f"states saved every {OUTPUT_INTERVAL} s. Steady window: "
        f"{win}.", ""]


def _explain(q: dict) -> list[str]:
    st, dy, ls = q["static"], q["dynamic"], q["ratios"]
    if not (st and dy):
        return []
    m140, m300 = dy["m140_slug"], dy["m300_slug"]
    lines = [
        "## Reading the differences", "",
        f"- Static top tension: {st['top_tension'] / 1e3:.1f} kN against the 1400 kN the "
        "paper's 0.27 % implies (1375-1426 kN within its rounding): the weight and the "
        "geometry fix it" + (", and they agree." if 3.78e3 / 0.00275 <= st["top_tension"]
                             <= 3.78e3 / 0.00265 else "; they do NOT agree."),
        f"- The slug in the statics (frozen at t = 0) changes the tension by at most "
        f"{pct(st['dT_rel'], 2)} of the top tension (the net weight of the unfinished slug "
        f"wave) and the moment by up to {st['dM'] / 1e3:.1f} kN m: the paper's 'identical "
        "tension, rippled moment'.",
        f"- Top tension amplitude: the slug adds "
        f"{(dy['range_slug'] - dy['range_uniform']) / 1e3:.2f} kN to the surge's "
        f"{dy['range_uniform'] / 1e3:.2f} kN (paper: 3.78 kN). The slug's line in the top "
        f"tension is {dy['top_slug_line_slug'] / 1e3:.2f} kN, against "
        f"{st['wave_weight'] / 1e3:.2f} kN for the quasi-static swing of the line's net "
        "slug weight (the mass of the unfinished wave on the line, eta mu0 g L_s / 2 pi); the "
        "(max - min) / 2 of the sum of the two lines is not their sum unless their peaks "
        "meet in the window. Read as max - min, our difference is "
        f"{2 * (dy['range_slug'] - dy['range_uniform']) / 1e3:.2f} kN.",
        f"- Frequencies: at 140 m the moment's largest line is at {m140['f']:.5f} Hz (surge "
        f"line {m140['surge'] / 1e3:.1f} kN m, slug line {m140['slug'] / 1e3:.1f} kN m), at "
        f"300 m at {m300['f']:.5f} Hz (slug {m300['slug'] / 1e3:.1f}, surge "
        f"{m300['surge'] / 1e3:.1f} kN m): " + ("the paper's finding (surge at node 35, slug "
        "at node 75), reproduced." if abs(m140["f"] - dy["f_surge"]) < 0.5 / dy["window"]
        and abs(m300["f"] - dy["f_slug"]) < 0.5 / dy["window"] else "NOT the paper's "
        "finding (surge at node 35, slug at node 75)."),
        f"- Touchdown moment: our static moment at 140 m is {st['M140'] / 1e3:.1f} kN m, "
        f"{140 - st['tdp_s']:.1f} m above our touchdown ({st['tdp_s']:.1f} m), where it rises "
        f"by {st['dMds140'] / 1e3:.1f} kN m per m: the station sits on the steep flank "
        "between the touchdown and the sag-bend peak "
        f"({st['peak_moment'] / 1e3:.0f} kN m at {st['peak_moment_s']:.0f} m; EI w / H = "
        f"{st['EIw_H'] / 1e3:.0f} kN m). The paper's touchdown position, soil model and E "
        "are not given; its 36 % implies a static moment of "
        f"{PAPER['static140'] / 1e3:.1f} kN m there, a value our static curve has at s = "
        f"{_where(q, PAPER['static140']):.1f} m, "
        f"{abs(st['tdp_s'] - _where(q, PAPER['static140'])):.1f} m from our touchdown. The "
        "comparison of the "
        "absolute moments at 140 m is therefore a comparison of touchdown positions, not "
        "of the slug model.",
    ]
    if 100.0 in ls and 280.0 in ls:
        d = ls[280.0]["mean140"] - ls[100.0]["mean140"]
        lines.append(
            f"- Slug length: our mean moment at 140 m changes by {d / 1e3:+.2f} kN m from "
            f"L_s/D 100 to 280 ({pct(d / st['M140'], 1)} of the static one; the paper: "
            f"+26.47 kN m, 36 %); its half-range goes from "
            f"{ls[100.0]['range140'] / 1e3:.1f} to {ls[280.0]['range140'] / 1e3:.1f} kN m. "
            "The slug is a zero-mean density wave: it moves the mean moment only through "
            "the nonlinearity of the response, so a large change of the mean needs a "
            "strongly nonlinear touchdown (the paper's soil model?) or a mean density that "
            "changes with L_s, which the paper says it keeps.")
    ok = abs(dy["speed"] / PAPER["speed"] - 1.0) < 0.05
    lines.append(
        f"- Travel speed: the slug's part of the moment travels at {dy['speed']:.3f} m/s "
        f"(U = {PAPER['speed']} m/s): " + ("the density wave moves with the flow in the "
                                           "model." if ok else "NOT the flow speed (a short "
                                           "window, or a model error to look into)."))
    return lines + [""]


def _where(q: dict, value: float) -> float:
    """The arc length [m] below the sag-bend peak where the static moment (uniform flow)
    first reaches ``value`` [N m]."""
    p = q["runs"]["uniform"].profile
    sel = (p.s >= p.tdp_s - 20.0) & (p.s <= q["static"]["peak_moment_s"])
    s, m = p.s[sel], p.moment[sel]
    j = int(np.argmax(m >= value))
    return float(np.interp(value, m[j - 1:j + 1], s[j - 1:j + 1])) if j > 0 else math.nan


def write_report(out: Path, q: dict, frame: pd.DataFrame, note: str) -> None:
    base = resolve(SCENE)
    ls = q["ratios"]
    speed = base.internal_flow.speed
    lines = ["# Liu, Ai, Sun & Jia (2021): steady slug flow in a steel catenary riser "
             "(VFIFE; the slug also by the ANCF)", "", GENERATED_NOTE, ""] + _setup(q, base) + [
        "## Results", "",
        md_table(["quantity", "paper", "computed", "rel. err", "note"],
                 [(r.quantity, r.paper, r.computed, pct(r.rel_err, 2), r.note)
                  for r in frame.itertuples()]), ""] + _explain(q)
    if ls:
        lines += ["## Slug-length study", "",
                  "Moment at s = 140 m (touchdown) and 300 m (hanging part) over the last whole "
                  "slug periods of each run (not in table.csv except the means):", "",
                  md_table(["L_s/D", "L_s [m]", "slug period [s]", "static at 140 m [kN m]",
                            "mean at 140 m [kN m]", "paper mean", "half-range at 140 m",
                            "slug line at 140 m", "half-range at 300 m", "slug line at 300 m",
                            "window [s]"],
                           [(r, v["L_s"], v["L_s"] / speed,
                             *(f"{v[k] / 1e3:.2f}" for k in ("static140", "mean140")),
                             PAPER["mean140"].get(r, math.nan) / 1e3,
                             *(f"{v[k] / 1e3:.2f}" for k in ("range140", "slug140", "range300",
                                                             "slug300")), v["window"])
                            for r, v in sorted(ls.items())]),
                  ""]
    if q.get("methods"):
        cmp_runs, cmp, cmp_scene = q["methods"]
        lines += methods.report_lines(cmp, cmp_runs, cmp_scene)
    ok = [r for r in q["runs"].values() if r is not None]
    lows = [float(r.moment[:, j].min()) for r in ok for j in
            (int(np.argmin(np.abs(r.s - s0))) for s0 in STATIONS)]
    lines += ["## Timings", "",
              md_table(["run", "wall [s]", "of which dynamics [s]", "real-time factor",
                        "warnings"],
                       [(r.label, timed(r.wall, ".1f", ""), timed(r.dyn_wall, ".1f", ""),
                         timed(r.realtime, ".0f", ""),
                         ", ".join(sorted({w.split(':')[0] for w in r.warnings})) or "-")
                        for r in ok]), "",
              f"The study took {timed(q['total'], '.1f')} in all (statics, dynamics, analysis and "
              "figures)." + (f" {note}" if note else ""),
              f"The smallest moment at the stations' nodes over every run is "
              f"{min(lows) / 1e3:.1f} kN m (magnitudes: no sign change).", ""]
    warned = {w: r.label for r in ok for w in r.warnings}
    lines += [f"Warning of run {lab}: `{w}`." for w, lab in warned.items()]
    if warned:
        lines += ["(The paper's 4 m mesh sits at the suite's resolution threshold, two "
                  "elements per bending length sqrt(EI/T) at the largest tension, the hang-off's "
                  "~1.4 MN: a frozen slug that adds weight tips it over.)", ""]
    failed = [k for k, r in q["runs"].items() if r is None]
    if failed:
        lines += [f"Runs that did not converge (their cells are empty): {failed}.", ""]
    lines += ["## Figures", "", "![top tension](top_tension.png)", "",
              "![static tension and moment](static.png)", "",
              "![moments at 140 m and 300 m](moments.png)", "",
              "![mean touchdown moment vs slug length](slug_length.png)", "",
              "## Files", "",
              "`table.csv`: columns " + ", ".join(f"`{c}`" for c in COLUMNS) + "; SI units "
              "(in each quantity's name); `rel_err` = computed / paper - 1 where the paper "
              "gives a number (derived ones say how in their note).", ""]
    (out / "report.md").write_text("\n".join(lines))


def index_row(d: Path):
    """(cases, worst agreement, verdict) of the study's directory, from its table.csv."""
    if not (d / "table.csv").exists():
        return None
    df = pd.read_csv(d / "table.csv")
    cmp = df[df.paper.notna() & df.computed.notna()]
    err = cmp.rel_err.abs()
    worst = cmp.loc[err.idxmax()] if len(cmp) else None
    agree = (f"{len(cmp)} quantities vs paper: median {pct(err.median(), 1)}, worst "
             f"{pct(worst.rel_err, 1)} ({worst.quantity})") if worst is not None else "-"
    two = d / "methods.csv"
    if two.exists():
        agree += "; " + methods.index_text(pd.read_csv(two))
    return ("uniform and slug flow, 4 slug lengths (VFIFE); the slug by VFIFE and ANCF",
            agree, "reported (paper inputs incomplete)")


#: measured time [s] of the study in ``reproduce liu2021`` alone on a 2-core machine: 100 s
#: for the VFIFE's six runs; with the slug by both methods (methods.py: the ANCF's two runs
#: are ~3/4 of its added cost) 273 s of CPU (9:09 wall beside three other jobs on 2 cores)
STUDY = Study("liu2021", (None,), lambda unit, out, note, full: run(out, note=note),
              index_row, seconds={None: 280})

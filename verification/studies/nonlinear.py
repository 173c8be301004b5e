"""The nonlinear time-domain study of ``riser-verify reproduce nonlinear``: the VFIFE against
the ANCF (:mod:`verification.comparison.nonlinear.protocol`) where the linear frequency
domain cannot follow, with tolerances measured from both methods' convergence; one unit per
group of cases into ``reports/nonlinear/UNIT/`` (each case's comparison files in its own
folder, ``cases.csv`` and ``report.md`` beside them).

Units and cases (the sea surface :data:`SURFACE_ABOVE` m above scr-steel's hang-off, as in
the dynamics study, so that a heave crest never lifts the top of the line into the air):

- ``scr-steel-heave``: scr-steel heaved at :data:`HEAVE_PERIOD` s, amplitudes 0.1, 1, 3 and
  6 m (the touchdown travelling; slack near the top of the range: the minimum tension and
  the touchdown's travel are rows). The convergence levels run at 1 m and 6 m; 0.1 m borrows
  1 m's relative tolerances, 3 m borrows 6 m's (:data:`BORROW`: the nearest measured
  amplitude above, the same line, mesh and step). The 1 m case carries
  scr-steel-fatigue's [design.fatigue] (the rainflow damage along s). The negative controls (drag, added mass,
  seabed stiffness +5 % in the ANCF only) run at 1 m, the seabed's at 6 m too. The frequency domain
  (``compare_dynamics``: the FD about the BVP's static state against the VFIFE's first
  harmonics, at twice the element length for cost, as the dynamics study's sweep) is reported
  beside, not judged: its departure is the nonlinearity the time domains resolve;
- ``yu2021-a3-surge``: Yu et al.'s lazy wave A3 surged :data:`SURGE_AMPLITUDE` m at
  :data:`SURGE_PERIOD` s (a vessel's slow drift of 3 % of the water depth: the hog and sag
  bends travel), with its convergence levels;
- ``lowe-langley``: the Lowe and Langley jumper in its wave (case 4, the scene's own
  [dynamics]), with its convergence levels;
- ``storm`` (:func:`run_storm`; measured: 982 s for both cases on this 2-core machine,
  the VFIFE's record 119 s, the ANCF's 479 s, with a test run beside): scr-steel-fatigue's line and vessel in Hs :data:`STORM_HS` m, Tp
  :data:`STORM_TP` s (the scene's 100 components and seed: the sea repeats every 467 s, so
  the :data:`STORM_RECORD` s record holds that realisation almost four times; 400
  components would not repeat within it but cost 4x the wave and vessel kinematics, which
  dominate the run: measured 22 of 26 s of a 30 s VFIFE run), at elements of
  :data:`STORM_H` (VFIFE, ANCF) m and the ANCF's step of its shortest component period /
  :data:`STORM_STEPS`, capped at the sampling interval (a fortieth of that period: the step
  the ANCF takes; the cost: the VFIFE's 1 m on a 1940 s run alone would take the study's
  budget), without [design] (the rainflow of 8000 series over the record would
  cost more than the run; the fatigue rows are heave-1m's). Its tolerances are measured on
  a short record of the same sea (:data:`STORM_SHORT` s, the ANCF's step refined from the
  case's) and borrowed, relative, by the 30-min record: an extreme over a longer record
  samples more of the same response, not a finer one. Each case's report gives both
  methods' most probable maxima over a 3 h storm beside their records' extremes
  (:func:`verification.comparison.nonlinear.report.extremes_markdown`, reported, not
  judged).

The wall times of every run go to ``runs.csv``'s ``wall_s`` (reports/timings.json, not the
committed report).
"""

from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

from riser.errors import SceneError, SolveFailed
from riser.physics.dynamics import Dynamics, TopMotion
from verification.catalog import resolve
from verification.comparison.nonlinear import report as nl_report
from verification.comparison.nonlinear.protocol import (compare_time_domain,
                                                        relative_tolerances)
from verification.report.markdown import GENERATED_NOTE, md_table

from .study import Study

#: the units of ``reproduce nonlinear``
UNITS = ("scr-steel-heave", "yu2021-a3-surge", "lowe-langley", "storm")
#: the sea surface above scr-steel's hang-off [m]
SURFACE_ABOVE = 20.0
HEAVE_PERIOD = 14.0
HEAVE_AMPLITUDES = (0.1, 1.0, 3.0, 6.0)
#: the heave amplitude [m] whose scene carries scr-steel-fatigue's [design.fatigue] (the
#: rainflow damage along s by both methods, with measured tolerances; the storm's record
#: leaves it out: the rainflow of 8000 series over 1800 s would cost more than the run)
FATIGUE_AMPLITUDE = 1.0
#: amplitude -> the measured amplitude it borrows its tolerances from
BORROW = {0.1: 1.0, 3.0: 6.0}
#: the heave cases' run: one period of ramp, SETTLE periods to settle, WINDOW periods
#: compared; sampled every period / SAMPLES
SETTLE, WINDOW, SAMPLES = 3, 3, 40
SURGE_AMPLITUDE, SURGE_PERIOD = 15.0, 60.0
STORM_HS, STORM_TP = 9.0, 14.0
#: the storm's record after its ramp (80 s) and 60 s to settle [s]; the short record of
#: its convergence levels
STORM_RECORD, STORM_SHORT = 1800.0, 200.0
STORM_RAMP, STORM_SETTLE = 80.0, 60.0
#: the storm's element lengths (VFIFE, ANCF) [m] and the ANCF's steps per shortest
#: component period
STORM_H = (4.0, 8.0)
STORM_STEPS = 25
CONTROLS = ("drag", "added_mass", "seabed")
#: the measured heave amplitudes' negative controls: all three at 1 m; the seabed's at
#: 6 m too, where the touchdown travels furthest (at 1 m it moves 17 m)
CONTROLS_AT = {1.0: CONTROLS, 6.0: ("seabed",)}


def _surface(sc):
    depth = sc.ends.hang_off[1] + SURFACE_ABOVE
    return sc.replace(**{"environment.water_depth": depth}) if sc.water_depth < depth else sc


def heave_scene(amplitude: float, fatigue: bool = False):
    """scr-steel heaved ``amplitude`` [m] at :data:`HEAVE_PERIOD`; ``fatigue``: with
    scr-steel-fatigue's [design] (its X65 strengths, S-N curve D in seawater with CP, SCF
    1.2), so that the envelopes carry the rainflow damage."""
    T = HEAVE_PERIOD
    sc = _surface(resolve("scr-steel"))
    if fatigue:
        f = resolve("scr-steel-fatigue")
        lt = f.line_types["steel"]
        sc = sc.replace(**{"line_types.steel.yield_strength": lt.yield_strength,
                           "line_types.steel.tensile_strength": lt.tensile_strength},
                        design=f.design)
    return sc.replace(dynamics=Dynamics(
        duration=(1 + SETTLE + WINDOW) * T, output_interval=T / SAMPLES,
        statistics_start=(1 + SETTLE) * T, save_states=True,
        top_motion=TopMotion(axis="y", amplitude=amplitude, period=T)))


def surge_scene():
    T = SURGE_PERIOD
    return resolve("yu2021-a3").replace(dynamics=Dynamics(
        duration=4 * T, output_interval=T / SAMPLES, statistics_start=2 * T,
        save_states=True, top_motion=TopMotion(axis="x", amplitude=SURGE_AMPLITUDE,
                                               period=T)))


def storm_scene(record: float):
    sc = resolve("scr-steel-fatigue").replace(design=None)
    start = STORM_RAMP + STORM_SETTLE
    return sc.replace(**{
        "environment.waves.spectrum.hs": STORM_HS, "environment.waves.spectrum.tp": STORM_TP,
        "environment.waves.ramp_time": STORM_RAMP,
        "dynamics.duration": start + record, "dynamics.statistics_start": start,
        "dynamics.output_interval": 0.5, "dynamics.save_states": True,
        "vfife.element_length": STORM_H[0], "ancf.element_length": STORM_H[1],
        "ancf.steps_per_period": STORM_STEPS})


def _case_row(name, comp, extra=None) -> dict:
    v, a = comp.vfife.measures, comp.ancf.measures
    row = {"case": name, "passed": comp.passed, "judged": len(comp.judged),
           "failed": sum(1 for r in comp.judged if not r["pass"]),
           "not_judged": sum(1 for r in comp.rows if not r["judged"]),
           "tolerances": "measured" if not comp.borrowed else f"borrowed: {comp.borrowed}"}
    for m, meas in (("vfife", v), ("ancf", a)):
        row[f"{m}_min_tension_n"] = meas.get(("tension min", "extreme along s"))
        row[f"{m}_touchdown_min_m"] = meas.get(("touchdown s min", "travel"))
        row[f"{m}_touchdown_max_m"] = meas.get(("touchdown s max", "travel"))
    worst = max(comp.judged, key=lambda r: r["abs_diff"] / r["tolerance"]
                if r["tolerance"] else 0.0, default=None)
    row["worst_row"] = "" if worst is None else f"{worst['quantity']} @ {worst['station']}"
    row["worst_ratio"] = (worst["abs_diff"] / worst["tolerance"]
                          if worst is not None and worst["tolerance"] else None)
    for c in CONTROLS:
        if c in comp.controls:
            row[f"control_{c}"] = ("fails" if comp.control_failed(c) else "passes") \
                if comp.controls[c][0] is not None else "not run"
    row["vfife_s"] = comp.vfife.wall_s
    row["ancf_s"] = comp.ancf.wall_s
    row.update(extra or {})
    return row


def _fd_rows(amplitudes, progress=None) -> dict:
    """amplitude -> {fd_hang_off_tension_amplitude_n, fd_vs_vfife_rel, ...}: the frequency
    domain against the VFIFE's first harmonics (``compare_dynamics``), not judged."""
    from verification.comparison.dynamic.protocol import compare_dynamics
    sc = heave_scene(amplitudes[0]).replace(dynamics=Dynamics(
        duration=2.0 * HEAVE_PERIOD, top_motion=TopMotion(axis="y", amplitude=amplitudes[0],
                                                           period=HEAVE_PERIOD)))
    dc = compare_dynamics(sc, amplitudes=tuple(amplitudes),
                          element_length=2.0 * sc.vfife.element_length, progress=progress)
    out = {}
    for r in dc.results:
        d = {}
        for w in r.rows:
            if w["quantity"] in ("hang_off_tension_amplitude", "moment_amplitude"):
                d[f"fd_{w['quantity']}"] = w["fd"]
                d[f"fd_vs_vfife_{w['quantity']}"] = w["rel_diff"]
        d["fd_s"] = r.fd_wall_s
        out[r.amplitude] = d
    return out


def _write_case(comp, folder: Path, title: str, note: str) -> None:
    nl_report.write(comp, folder, title=title, note=note)


def run_heave(out: Path, note: str) -> list[dict]:
    rows, rel = [], {}
    for a in (1.0, 6.0, 0.1, 3.0):
        sc = heave_scene(a, fatigue=a == FATIGUE_AMPLITUDE)
        name = f"heave-{a:g}m"
        try:
            if a in BORROW:
                src = BORROW[a]
                comp = compare_time_domain(
                    sc, convergence=False, tolerances=rel.get(src, {}),
                    borrowed=f"heave-{src:g}m (measured; the same line, mesh and step, the "
                    "nearest measured amplitude above)")
            else:
                comp = compare_time_domain(sc, controls=CONTROLS_AT[a])
                rel[a] = relative_tolerances(comp)
        except (SolveFailed, SceneError) as exc:     # a method failing is a finding
            rows.append({"case": name, "amplitude_m": a, "passed": False, "judged": 0,
                         "failed": 0, "not_judged": 0, "tolerances": f"run failed: {exc}"})
            continue
        _write_case(comp, out / name, f"scr-steel heaved {a:g} m at {HEAVE_PERIOD:g} s.", note)
        rows.append(_case_row(name, comp, {"amplitude_m": a}))
    try:
        fd = _fd_rows(HEAVE_AMPLITUDES)
    except Exception as exc:        # noqa: BLE001  the FD is reported, never the verdict
        fd = {a: {"fd_note": f"not run: {exc}"} for a in HEAVE_AMPLITUDES}
    for r in rows:
        r.update(fd.get(r["amplitude_m"], {}))
    return sorted(rows, key=lambda r: r["amplitude_m"])


def run_surge(out: Path, note: str) -> list[dict]:
    comp = compare_time_domain(surge_scene())
    _write_case(comp, out / "surge", f"yu2021-a3 surged {SURGE_AMPLITUDE:g} m at "
                f"{SURGE_PERIOD:g} s.", note)
    return [_case_row("surge", comp)]


def run_lowe_langley(out: Path, note: str) -> list[dict]:
    comp = compare_time_domain(resolve("lowe-langley-case4"))
    _write_case(comp, out / "case4", "Lowe and Langley's jumper in its wave (case 4: "
                "A 5 m, T 10 s), the scene's own [dynamics].", note)
    return [_case_row("case4", comp)]


def run_storm(out: Path, note: str) -> list[dict]:
    short = compare_time_domain(storm_scene(STORM_SHORT), ancf_dt_refine=True)
    _write_case(short, out / "short-record", f"The storm's first {STORM_SHORT:g} s (the "
                "convergence levels).", note)
    comp = compare_time_domain(storm_scene(STORM_RECORD), convergence=False,
                               tolerances=relative_tolerances(short),
                               borrowed=f"short-record ({STORM_SHORT:g} s of the same sea, "
                               "measured; relative to each row)")
    _write_case(comp, out / "record", f"The storm: Hs {STORM_HS:g} m, Tp {STORM_TP:g} s, "
                f"{STORM_RECORD:g} s of record.", note)
    return [_case_row("short-record", short), _case_row("record", comp)]


RUNNERS = {"scr-steel-heave": run_heave, "yu2021-a3-surge": run_surge,
           "lowe-langley": run_lowe_langley, "storm": run_storm}
TITLES = {"scr-steel-heave": f"scr-steel heaved at {HEAVE_PERIOD:g} s: 0.1, 1, 3 and 6 m",
          "yu2021-a3-surge": f"yu2021-a3 surged {SURGE_AMPLITUDE:g} m at {SURGE_PERIOD:g} s",
          "lowe-langley": "the Lowe and Langley jumper in its wave (case 4)",
          "storm": f"a storm on scr-steel-fatigue's line: Hs {STORM_HS:g} m, Tp {STORM_TP:g} s,"
                   f" {STORM_RECORD / 60:g} min of record"}


def run_unit(unit: str, out: Path, note: str = "", full: bool = False) -> str:
    t0 = time.perf_counter()
    folder = Path(out) / unit
    folder.mkdir(parents=True, exist_ok=True)
    rows = RUNNERS[unit](folder, note)
    table = pd.DataFrame(rows)
    table.to_csv(folder / "cases.csv", index=False, float_format="%.4g")
    (folder / "report.md").write_text(_markdown(unit, table, note))
    ok = bool(table["passed"].all())
    return (f"nonlinear {unit}: {len(table)} cases, {'PASS' if ok else 'FAIL'} "
            f"({time.perf_counter() - t0:.1f} s)")


def _markdown(unit: str, table: pd.DataFrame, note: str) -> str:
    lines = [f"# Nonlinear time domain by two methods: {TITLES[unit]}", "", GENERATED_NOTE, "",
             "The VFIFE against the ANCF (`riser-verify compare SCENE --time-domain`, "
             "docs/comparison.md): every judged row within its tolerance measured from both "
             "methods' convergence in element length and time step; the rows whose levels "
             "do not converge are reported, not judged (each case's `tolerances.csv`).", ""]
    if note:
        lines += [note, ""]
    body = []
    for _, r in table.iterrows():
        body.append((f"[{r['case']}]({r['case']}/report.md)",
                     "yes" if r["passed"] else "**no**", int(r["judged"]), int(r["failed"]),
                     int(r["not_judged"]), r.get("worst_row", ""),
                     "" if pd.isna(r.get("worst_ratio")) else f"{r['worst_ratio']:.2f}",
                     r["tolerances"]))
    lines += [md_table(["case", "pass", "judged", "failed", "not judged", "closest to its "
                        "tolerance", "|diff| / tolerance", "tolerances"], body), ""]
    mt = []
    for _, r in table.iterrows():
        mt.append((r["case"], *(f"{r[c] / 1e3:.1f}" if pd.notna(r.get(c)) else "" for c in
                                ("vfife_min_tension_n", "ancf_min_tension_n")),
                   *(f"{r[c]:.2f}" if pd.notna(r.get(c)) else "" for c in
                     ("vfife_touchdown_min_m", "vfife_touchdown_max_m",
                      "ancf_touchdown_min_m", "ancf_touchdown_max_m"))))
    lines += ["## Minimum tension and touchdown travel", "",
              md_table(["case", "min tension VFIFE [kN]", "ANCF [kN]", "touchdown s min "
                        "VFIFE [m]", "max", "ANCF min [m]", "max"], mt), ""]
    ctl = [c for c in CONTROLS if f"control_{c}" in table]
    if ctl:
        rows = [(r["case"], *(r.get(f"control_{c}") if isinstance(r.get(f"control_{c}"), str)
                              else "" for c in ctl)) for _, r in table.iterrows()]
        lines += ["## Negative controls", "", "The ANCF's scene alone changed by 5 % "
                  "(drag coefficients, added mass coefficient, seabed stiffness), compared "
                  "with the case's tolerances: each must fail on at least one case where its "
                  "effect matters (each case's `controls.csv`).", "",
                  md_table(["case", *ctl], rows), ""]
    if "fd_hang_off_tension_amplitude" in table:
        fd = [(r["case"], f"{r['fd_hang_off_tension_amplitude'] / 1e3:.2f}"
               if pd.notna(r.get("fd_hang_off_tension_amplitude")) else "",
               f"{100 * r['fd_vs_vfife_hang_off_tension_amplitude']:+.2f} %"
               if pd.notna(r.get("fd_vs_vfife_hang_off_tension_amplitude")) else "",
               f"{100 * r['fd_vs_vfife_moment_amplitude']:+.2f} %"
               if pd.notna(r.get("fd_vs_vfife_moment_amplitude")) else "")
              for _, r in table.iterrows()]
        lines += ["## The frequency domain beside", "", "The FD about the BVP's static "
                  "state against the VFIFE's first harmonics (`compare --dynamics`'s "
                  "protocol at twice the element length), reported, not judged: its "
                  "departure with the amplitude is the nonlinearity.", "",
                  md_table(["case", "FD hang-off T amplitude [kN]", "VFIFE vs FD: hang-off T",
                            "moment along s (largest)"], fd), ""]
    return "\n".join(lines)


def index_row(d: Path):
    f = d / "cases.csv"
    if not f.exists() or d.name not in UNITS:
        return None
    t = pd.read_csv(f)
    ratio = t["worst_ratio"].max() if "worst_ratio" in t else float("nan")
    ok = bool(t["passed"].astype(str).str.lower().eq("true").all())
    n = len(t)
    return (f"{n} case{'s' if n != 1 else ''}, VFIFE vs ANCF, {int(t['judged'].sum())} rows "
            f"judged, {int(t['not_judged'].sum())} not (not converged, or no measured "
            "tolerance)",
            f"largest |diff| / tolerance {ratio:.2f}" if pd.notna(ratio) else "",
            "pass" if ok else "fail")


STUDY = Study("nonlinear", UNITS, lambda unit, out, note, full: run_unit(unit, out, note, full),
              index_row, seconds={"scr-steel-heave": 740, "yu2021-a3-surge": 100,
                                  "lowe-langley": 60, "storm": 1000})

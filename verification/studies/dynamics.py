"""The dynamic study of ``riser-verify reproduce dynamics``: the response to a harmonic
hang-off motion by the frequency domain about the BVP static state and by the VFIFE's time
domain (:mod:`verification.comparison.dynamic.protocol`), one unit per scene into
``reports/dynamics/SCENE/``.

Per scene: heave (y) and surge (x) at two periods, each between two adjacent in-plane
natural periods of the scene (so that no case sits on a resonance, where the start-up
transient would outlast any affordable run; the modal periods are those of ``riser-verify
modes``), at the smallest amplitude; the amplitude sweep of the first heave case on the
issue's scenes (scr-steel, yu2021-a3), and that case's smallest amplitude at 2 and 4 times
the element length (the order of the difference); sway (z) on scr-steel. The two headline
cases (heave and surge at the first period) run at the scene's element length (1 m; the
jumper's 0.4 m), the others at twice it (:data:`COARSE`, their cost). The sea
surface is placed 20 m above the hang-off (a porch below the waterline): the frequency
domain has the line wholly in the water, and the VFIFE would otherwise lift the top of
the line into the air at every heave crest, a first-order change of the hang-off tension
that is not a discretisation difference.

About a 3D static state (:data:`THREE_D`, issue 50): heave and sway at one period between
two coupled natural periods, both at the scene's element length and judged, the ANCF's
time domain beside.

Files per scene: ``cases.csv`` (one row per case and amplitude: the rows of the dynamic
comparison and the FD and VFIFE times), ``convergence.csv`` (element_length_m and the
same differences), ``report.md``, the static comparison's files and one folder per case
with the dynamic comparison's files (:mod:`verification.comparison.dynamic.report`).
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pandas as pd

from verification.catalog import resolve
from verification.comparison.dynamic import report as dynamics_report
from verification.comparison.dynamic.protocol import compare_dynamics
from verification.comparison.static.protocol import compare, default_columns
from verification.comparison.static.report import write as write_static
from verification.runtime import stable
from verification.report.markdown import GENERATED_NOTE, md_table, pct, timed
from riser.physics.dynamics import Dynamics, TopMotion
from riser.errors import SceneError

from .study import Study

#: the jumper is an example scene (examples/scenes), the others built in
JUMPER = str(Path(__file__).resolve().parents[2] / "examples" / "scenes" /
             "flexible-jumper.toml")
#: scene -> (its two periods [s] with the in-plane natural periods they sit between)
PERIODS = {
    "scr-steel": ((14.0, "16.7 and 12.0 s"), (8.6, "9.54 and 7.84 s")),
    "yu2021-a3": ((12.4, "13.2 and 11.6 s"), (9.9, "10.4 and 9.48 s")),
    "wang2014-baseline": ((13.5, "14.4 and 12.8 s"), (15.7, "17.2 and 14.4 s")),
    "flexible-jumper": ((9.2, "10.9 and 7.77 s"), (6.9, "7.77 and 6.10 s")),
}
#: a scene about a 3D static state (issue 50: a current across the line's plane) -> its
#: period [s] with the coupled natural periods it sits between (``riser-verify modes``):
#: heave and sway there, both headline cases (the frequency domain about the 3D rod's state)
THREE_D = {"scr-steel-current-90": (14.0, "16.6 and 13.3 s, coupled modes 6 and 7")}
SCENES = tuple(PERIODS) + tuple(THREE_D)
#: the amplitude sweep [m] and the smallest amplitude
AMPLITUDES = (0.1, 0.3, 1.0, 3.0)
SMALL = AMPLITUDES[0]
#: scenes with the sweep and the element-length refinement (the issue's two)
SWEEP_SCENES = ("scr-steel", "yu2021-a3")
#: the coarsest element length of the refinement, times the scene's (beside the headline
#: heave case at 1 and the sweep at :data:`COARSE`)
REFINEMENT = 4.0
#: the element length of the cases beyond the two headline ones, times the scene's
COARSE = 2.0
#: the sea surface above the hang-off [m]
SURFACE_ABOVE = 20.0
ROWS = ("hang_off_tension_amplitude", "hang_off_tension_phase_deg", "tension_amplitude",
        "moment_amplitude", "moment_out_amplitude", "displacement_amplitude", "min_tension")


def study_scene(name: str):
    """The scene of the study: the built-in (or example) scene with the sea surface
    :data:`SURFACE_ABOVE` m above the hang-off."""
    sc = resolve(JUMPER if name == "flexible-jumper" else name)
    depth = sc.ends.hang_off[1] + SURFACE_ABOVE if hasattr(sc.ends, "hang_off") else None
    if sc.water_depth is not None and depth is not None and sc.water_depth < depth:
        sc = sc.replace(**{"environment.water_depth": depth})
    return sc


def cases(name: str) -> list[tuple[str, str, float, tuple, float]]:
    """(case name, axis, period, amplitudes, element-length factor) of one scene: the two
    headline cases (heave and surge at the first period, the smallest amplitude) at the
    scene's element length, the rest at :data:`COARSE` times it (their cost); a 3D static
    state's (:data:`THREE_D`) heave and sway at its period, both headline cases."""
    if name in THREE_D:
        t = THREE_D[name][0]
        return [(f"heave-{t:g}s", "y", t, (SMALL,), 1.0), (f"sway-{t:g}s", "z", t, (SMALL,), 1.0)]
    (t1, _), (t2, _) = PERIODS[name]
    out = [(f"heave-{t1:g}s", "y", t1, (SMALL,), 1.0), (f"surge-{t1:g}s", "x", t1, (SMALL,), 1.0),
           (f"heave-{t2:g}s", "y", t2, (SMALL,), COARSE),
           (f"surge-{t2:g}s", "x", t2, (SMALL,), COARSE)]
    if name in SWEEP_SCENES:
        out.insert(2, (f"heave-{t1:g}s-sweep", "y", t1, AMPLITUDES, COARSE))
    if name == "scr-steel":
        out.append((f"sway-{t1:g}s", "z", t1, (SMALL,), COARSE))
    return out


#: why the cases at the coarser elements are reported, not judged
COARSE_REASON = ("at twice the scene's element length (the cost): reported, not judged; "
                 "the protocol's bounds are for the scene's elements (1 m)")


def _reported_only(dc) -> None:
    """Mark the judged rows of ``dc`` reported (:data:`COARSE_REASON`)."""
    for r in dc.results:
        r.rows[:] = [row.judged(None, COARSE_REASON) if row.passed is not None else row
                     for row in r.rows]


def _with_motion(scene, axis: str, period: float, amplitude: float):
    return scene.replace(dynamics=Dynamics(duration=2.0 * period, top_motion=TopMotion(
        axis=axis, amplitude=amplitude, period=period)))


def _record(dc, case: str, h: float) -> list[dict]:
    out = []
    for r in dc.results:
        row = {"case": case, "axis": dc.axis, "period_s": dc.period,
               "amplitude_m": r.amplitude, "element_length_m": h,
               "passed": None if all(w["pass"] is None for w in r.rows) else r.passed,
               "fd_s": r.fd_wall_s, "vfife_s": r.vfife_wall_s,
               "warnings": "; ".join(r.warnings)}
        for w in r.rows:
            if w["quantity"] in ROWS:
                row[w["quantity"]] = w["rel_diff"]
        row["higher_harmonics"] = r.nonlinearity["hang_off_higher_harmonics"]
        if r.ancf is not None:          # the ANCF judged against the same FD
            row["ancf_passed"] = all(w["pass"] is not False for w in r.ancf_rows)
            row["ancf_s"] = r.ancf_wall_s
            for w in r.ancf_rows:
                if w["quantity"] in ROWS:
                    row[f"ancf_{w['quantity']}"] = w["rel_diff"]
        out.append(row)
    return out


def run_unit(name: str, out: Path, note: str = "", full: bool = False) -> str:
    """Every case of one scene into ``out/name``; returns the log line."""
    t0 = time.perf_counter()
    folder = Path(out) / name
    folder.mkdir(parents=True, exist_ok=True)
    scene = study_scene(name)
    comp = compare(scene, columns=default_columns(), paper_model=False)
    write_static(comp, folder)
    h = scene.vfife.element_length
    rows, conv = [], []
    for case, axis, period, amps, factor in cases(name):
        sc = _with_motion(scene, axis, period, amps[0])
        # the ANCF's time domain on the headline cases (their smallest amplitude)
        dc = compare_dynamics(sc, amplitudes=amps, element_length=factor * h, static=comp.bvp,
                              ancf="first" if factor == 1.0 else False)
        if factor != 1.0:
            _reported_only(dc)
        dynamics_report.write(dc, folder / case)
        rows += _record(dc, case, factor * h)
        if name in SWEEP_SCENES and case.startswith(f"heave-{PERIODS[name][0][0]:g}s"):
            # the refinement: the headline heave (1 h), the sweep's smallest amplitude
            # (COARSE h) and one run at REFINEMENT h
            conv += [r for r in _record(dc, case, factor * h) if r["amplitude_m"] == SMALL]
            if factor == COARSE:
                try:
                    dcf = compare_dynamics(sc, amplitudes=(SMALL,),
                                           element_length=REFINEMENT * h, static=comp.bvp,
                                           ancf=False)
                except SceneError as exc:         # too coarse for the period: said so
                    conv.append({"case": case, "element_length_m": REFINEMENT * h,
                                 "warnings": f"refused: {exc}"})
                    continue
                _reported_only(dcf)
                conv += _record(dcf, case, REFINEMENT * h)
    table = _quantised(pd.DataFrame(rows))
    table.to_csv(folder / "cases.csv", index=False, float_format="%.8g")
    conv_table = _quantised(pd.DataFrame(conv).sort_values("element_length_m")) if conv else None
    if conv_table is not None:
        conv_table.to_csv(folder / "convergence.csv", index=False, float_format="%.8g")
    (folder / "report.md").write_text(_markdown(name, scene, comp, table, conv_table, note))
    worst = _worst(_headline(table))
    return (f"dynamics {name}: {len(table)} case amplitudes, headline worst hang-off "
            f"tension {pct(worst['hang_off_tension_amplitude'])}, moment "
            f"{pct(worst['moment_amplitude'])} ({time.perf_counter() - t0:.1f} s)")


def _headline(table: pd.DataFrame) -> pd.DataFrame:
    """The rows of the headline cases: the smallest amplitude at the scene's (smallest)
    element length."""
    small = table[table["amplitude_m"] == SMALL]
    return small[small["element_length_m"] == small["element_length_m"].min()]


def _worst(table: pd.DataFrame) -> dict:
    """The largest |difference| of each row at the smallest amplitude."""
    small = table[table["amplitude_m"] == SMALL]
    return {q: float(small[q].abs().max()) if q in small and small[q].notna().any() else None
            for q in ROWS}


def _markdown(name, scene, comp, table, conv, note) -> str:
    head = _headline(table)
    ratio = (head["vfife_s"] / head["fd_s"]).median()
    if name in THREE_D:
        t1, b1 = THREE_D[name]
        periods = (f"The static state is 3D (the current across the line's plane): the "
                   f"frequency domain is about the 3D rod's state, its in- and out-of-plane "
                   f"motions coupled. Period {t1:g} s (between the coupled natural periods "
                   f"{b1})")
        judged = ("Judged: both cases (heave and sway at the smallest amplitude, the "
                  "scene's element length).")
    else:
        (t1, b1), (t2, b2) = PERIODS[name]
        periods = (f"Periods {t1:g} s (between the in-plane natural periods {b1}) and "
                   f"{t2:g} s (between {b2})")
        judged = ("Judged: the two headline cases (heave and surge at the first period, the "
                  "smallest amplitude) at the scene's element length; the others, at twice "
                  "it, and the sweep's larger amplitudes (the nonlinearity) are reported.")
    lines = [f"# Dynamic response by two methods: `{name}`", "", GENERATED_NOTE, "",
             f"Scene: {scene.title or name} (sea surface {SURFACE_ABOVE:g} m above the "
             f"hang-off). {periods}. Static comparison: "
             f"{'PASS' if comp.passed else 'FAIL'} (its files beside this report).", ""]
    if note:
        lines += [note, ""]
    lines += ["## Cases", "", "VFIFE vs frequency domain (FD): relative differences of the "
              "first-harmonic amplitudes (see each case's report for the rows' bases and "
              f"tolerances); phase in degrees. {judged}", ""]
    hdr = ["case", "A [m]", "h [m]", "hang-off T", "phase [deg]", "T along s", "M along s",
           "M out of plane", "displacement", "higher harmonics (T; dz in sway)", "FD [s]",
           "VFIFE [s]",
           "pass"]
    body = []
    for _, r in table.iterrows():
        body.append((f"[{r['case']}]({r['case']}/report.md)", r["amplitude_m"],
                     r["element_length_m"],
                     pct(r.get("hang_off_tension_amplitude")),
                     _deg(r.get("hang_off_tension_phase_deg")),
                     pct(r.get("tension_amplitude")), pct(r.get("moment_amplitude")),
                     pct(r.get("moment_out_amplitude")), pct(r.get("displacement_amplitude")),
                     pct(r["higher_harmonics"], 2), timed(r["fd_s"], ".2f", ""),
                     timed(r["vfife_s"], ".1f", ""),
                     {True: "yes", False: "**no**"}.get(r["passed"], "n/a")))
    lines += [md_table(hdr, body), "",
              f"Cost of the headline cases (the same answer, the scene's element length): "
              f"the frequency domain answers in {timed(head['fd_s'].median())} (median; "
              f"Richardson on two grids, the drag iterated), the VFIFE in "
              f"{timed(head['vfife_s'].median(), '.1f')}: a ratio of "
              f"{timed(ratio, '.0f', '')}, both measured in "
              "this run.", ""]
    if "ancf_passed" in table:
        an = table[table["ancf_passed"].notna()]
        lines += ["## The ANCF against the same frequency domain", "",
                  "The headline cases by the second time domain (ancf/: cubic elements at "
                  "its default length, implicit steps of T/100), judged with the same rows "
                  "and tolerances as the VFIFE (each case's report, its "
                  "`dynamic_agreement_ancf.csv`):", "",
                  md_table(["case", "A [m]", "hang-off T", "phase [deg]", "T along s",
                            "M along s", "M out of plane", "displacement", "ANCF [s]",
                            "VFIFE [s]", "pass"],
                           [(f"[{r['case']}]({r['case']}/report.md)", r["amplitude_m"],
                             pct(r.get("ancf_hang_off_tension_amplitude")),
                             _deg(r.get("ancf_hang_off_tension_phase_deg")),
                             pct(r.get("ancf_tension_amplitude")),
                             pct(r.get("ancf_moment_amplitude")),
                             pct(r.get("ancf_moment_out_amplitude")),
                             pct(r.get("ancf_displacement_amplitude")),
                             timed(r["ancf_s"], ".1f", ""), timed(r["vfife_s"], ".1f", ""),
                             {True: "yes", False: "**no**"}.get(r["ancf_passed"], "n/a"))
                            for _, r in an.iterrows()]), ""]
    if conv is not None:
        lines += ["## Refinement of the VFIFE", "", "The smallest amplitude of the sweep "
                  "case at three element lengths (the FD's own grid error is below 1e-4; a "
                  "change of sign means the difference is near the rounding of the "
                  "protocol, not in its asymptotic range):",
                  "", md_table(["element length [m]", "hang-off T", "T along s",
                                "M along s", "displacement", "VFIFE [s]", "note"],
                               [(r["element_length_m"],
                                 pct(r.get("hang_off_tension_amplitude")),
                                 pct(r.get("tension_amplitude")),
                                 pct(r.get("moment_amplitude")),
                                 pct(r.get("displacement_amplitude")),
                                 timed(r.get("vfife_s"), ".1f", ""),
                                 _note(r.get("warnings"))) for _, r in conv.iterrows()]), ""]
        order = _order(conv)
        if order:
            lines += [f"Observed order of the moment difference: {order}.", ""]
    return "\n".join(lines)


def _quantised(table: pd.DataFrame) -> pd.DataFrame:
    """The agreement columns rounded to the quanta their round-off justifies
    (:data:`verification.runtime.stable.QUANTA`, 0.05 % and 0.05 deg), so that the report's
    text and the CSV print the same stable numbers on any machine."""
    for col, q in stable.QUANTA["cases.csv"].items():
        if col in table:
            table[col] = (pd.to_numeric(table[col], errors="coerce") / q).round() * q
    return table


def _deg(value) -> str:
    """A phase difference [deg], blank when not defined (a first harmonic of zero)."""
    return f"{value:+.3f}" if value is not None and np.isfinite(value) else ""


def _note(text) -> str:
    """A refinement row's note: why it has no values (refused), else blank."""
    if isinstance(text, str) and text.startswith("refused"):
        return "refused: too coarse for the period (fewer than 20 elements a wave)"
    return ""


def _order(conv: pd.DataFrame) -> str:
    h = conv["element_length_m"].to_numpy(float)
    d = conv["moment_amplitude"].abs().to_numpy(float)
    ok = np.isfinite(d) & (d > 0)
    if ok.sum() < 2:
        return ""
    p = np.polyfit(np.log(h[ok]), np.log(d[ok]), 1)[0]
    return f"{p:.2f} (least squares of log |difference| over {int(ok.sum())} element lengths)"


def index_row(d: Path):
    """(cases, worst small-amplitude agreement, verdict) of one scene's folder."""
    f = d / "cases.csv"
    if not f.exists():
        return None
    table = pd.read_csv(f)
    w = _worst(_headline(table))
    small = table[table["amplitude_m"] == SMALL]
    judged = table["passed"].dropna().astype(str).str.lower()
    verdict = "pass" if (judged == "true").all() else "fail"
    return (f"{len(small)} motions, sweep {len(table) - len(small)} amplitudes",
            f"headline, largest VFIFE vs FD: hang-off T "
            f"{_abs_pct(w['hang_off_tension_amplitude'])}, "
            f"T along s {_abs_pct(w['tension_amplitude'])}, M along s "
            f"{_abs_pct(w['moment_amplitude'])}, displacement "
            f"{_abs_pct(w['displacement_amplitude'])}", verdict)


def _abs_pct(value) -> str:
    return "" if value is None else f"{100 * abs(value):.3f} %"


#: measured wall times [s] of the units in ``reproduce all`` (2 processes, 2 cores)
STUDY = Study("dynamics", SCENES, run_unit, index_row,
              seconds={"scr-steel": 240, "yu2021-a3": 120, "wang2014-baseline": 100,
                       "flexible-jumper": 60, "scr-steel-current-90": 420})

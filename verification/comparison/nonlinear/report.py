"""The files of ``compare SCENE --time-domain`` (:mod:`.protocol`): ``agreement.csv`` (one
row per compared quantity), ``tolerances.csv`` (the convergence measurements behind every
tolerance), ``runs.csv`` (each run's element length, time step and wall time: the wall
time goes to reports/timings.json in a study), ``controls.csv`` (the negative controls'
rows, when run), ``report.md`` (in an irregular sea with the extremes over the storm:
:func:`extremes_markdown`) and the overlaid figures ``timeseries.png`` and
``envelopes.png``. Numbers are written to 4 significant digits (a dynamic response's:
verification/runtime/stable.py, DYNAMIC_SIGNIFICANT)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd

from riser.design.extremes import SUMMARY_EXTREMES, summary_extreme
from verification.report.markdown import GENERATED_NOTE, md_table
from verification.runtime import outdir

FILES = outdir.TIME_DOMAIN
#: significant digits of the written numbers (module docstring)
DIGITS = 4
AGREEMENT = ("quantity", "station", "vfife", "ancf", "abs_diff", "rel_diff", "tolerance",
             "tolerance_reason", "judged", "pass")


def _r(v, digits: int = DIGITS):
    if v is None or isinstance(v, (bool, np.bool_, str)):
        return v
    v = float(v)
    if not math.isfinite(v) or v == 0.0:
        return v
    return round(v, digits - 1 - int(math.floor(math.log10(abs(v)))))


def _table(rows, columns) -> pd.DataFrame:
    return pd.DataFrame([{c: _r(r.get(c)) if c not in ("judged", "pass") else r.get(c)
                          for c in columns} for r in rows], columns=list(columns))


def verdict(row) -> str:
    return {True: "ok", False: "FAIL", None: "not judged"}[row["pass"]]


def console_lines(comp) -> list[str]:
    """Lines like ``compare``'s: one per judged row, then the counts."""
    out = []
    for r in comp.rows:
        if not r["judged"]:
            continue
        flag = "ok  " if r["pass"] else "FAIL"
        out.append(f"  {flag} {r['quantity'] + ' @ ' + r['station']:<60} |diff| "
                   f"{r['abs_diff']:.4g} <= {r['tolerance']:.4g}"
                   if r["pass"] else
                   f"  {flag} {r['quantity'] + ' @ ' + r['station']:<60} |diff| "
                   f"{r['abs_diff']:.4g} > {r['tolerance']:.4g}")
    nj = sum(1 for r in comp.rows if not r["judged"])
    out.append(f"  {len(comp.judged)} rows judged, {nj} not judged (tolerances.csv: why)")
    for name, (run, rows, why) in comp.controls.items():
        fails = sum(1 for r in rows if r["judged"] and not r["pass"])
        out.append(f"  negative control {name}: "
                   + (f"not run ({why})" if run is None else
                      f"{fails} judged rows fail -> {'fails, as it must' if fails else 'PASSES (the comparison cannot see it)'}"))
    return out


def runs_rows(comp) -> list[dict]:
    seen, out = set(), []
    runs = [comp.vfife, comp.ancf] + [r for rs in comp.levels.values() for r in rs] + [
        c[0] for c in comp.controls.values() if c[0] is not None]
    for r in runs:
        if (r.method, r.label) in seen:
            continue
        seen.add((r.method, r.label))
        out.append({"method": r.method, "run": r.label, "element_length": r.element_length,
                    "time_step": r.time_step, "wall_s": r.wall_s,
                    "failure": getattr(r, "failure", "")})
    return out


def write(comp, out: Path, title: str = "", note: str = "") -> None:
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    _table(comp.rows, AGREEMENT).to_csv(out / "agreement.csv", index=False)
    tcols = ("quantity", "station", "kind", "method", "parameter", "level_1", "level_2",
             "level_3", "value_1", "value_2", "value_3", "change_1", "change_2", "order",
             "error", "note")
    _table(comp.tolerances, tcols).to_csv(out / "tolerances.csv", index=False)
    pd.DataFrame(runs_rows(comp)).to_csv(out / "runs.csv", index=False)
    if comp.controls:
        crow = []
        for name, (run, rows, why) in comp.controls.items():
            for r in rows:
                crow.append({"control": name, **{c: r.get(c) for c in AGREEMENT}})
            if run is None:
                crow.append({"control": name, "tolerance_reason": f"not run: {why}"})
        _table(crow, ("control",) + AGREEMENT).to_csv(out / "controls.csv", index=False)
    plots(comp, out)
    (out / "report.md").write_text(markdown(comp, title, note))


def markdown(comp, title: str = "", note: str = "", heading: str = "#") -> str:
    sc = comp.scene
    dyn = sc.dynamics
    lines = [f"{heading} Time domain by two methods: `{sc.name}`", "", GENERATED_NOTE, ""]
    if title:
        lines += [title, ""]
    if note:
        lines += [note, ""]
    drive = (f"periodic, {comp.period:g} s (first harmonics compared)" if comp.period
             else "not periodic (no first harmonics)")
    lines += [f"The VFIFE (explicit, elements of {comp.vfife.element_length:g} m) against the "
              f"ANCF (implicit generalised-alpha, cubic elements of "
              f"{comp.ancf.element_length:g} m) on the scene's own [dynamics]: "
              f"{dyn.duration:g} s, window from {comp.start:g} s; drive {drive}. "
              f"**{'PASS' if comp.passed else 'FAIL'}**: {len(comp.judged)} rows judged "
              f"({sum(1 for r in comp.judged if not r['pass'])} outside their tolerance), "
              f"{sum(1 for r in comp.rows if not r['judged'])} not judged.", "",
              "Stations (picked on the VFIFE's static profile): "
              + ", ".join(f"{n} s = {s:.1f} m" for n, s in comp.stations) + ".", ""]
    if comp.borrowed:
        lines += [f"Tolerances borrowed: {comp.borrowed}", ""]
    else:
        lines += ["Tolerances measured (docs/comparison.md): each method at 4x, 2x and 1x "
                  "its default element length and time step (the VFIFE's step on its "
                  "coarsest mesh: its explicit step cannot be coarsened); a row's tolerance "
                  "is the sum of the four estimated discretisation errors; a row whose "
                  "levels do not converge (non-monotone, order < 0.5) is not judged, with "
                  "its numbers in `tolerances.csv`.", ""]
    body = [(r["quantity"], r["station"], f"{r['vfife']:.4g}", f"{r['ancf']:.4g}",
             f"{r['abs_diff']:.3g}", "" if r["rel_diff"] is None else f"{100 * r['rel_diff']:.3f} %",
             "" if r["tolerance"] is None else f"{r['tolerance']:.3g}",
             {True: "ok", False: "**FAIL**", None: "not judged"}[r["pass"]],
             r["tolerance_reason"]) for r in comp.rows]
    lines += [f"{heading}# Agreement", "", "SI units (N, N m, 1/m, m); a time series and an "
              "envelope along s are compared by the rms of their difference (their own "
              "columns: their rms).", "",
              md_table(["quantity", "station", "VFIFE", "ANCF", "|diff|", "rel", "tolerance",
                        "verdict", "reason"], body), ""]
    if comp.controls:
        lines += [f"{heading}# Negative controls", "", "The ANCF's scene alone changed by 5 %; "
                  "compared with the same tolerances, each must fail.", ""]
        crow = []
        for name, (run, rows, why) in comp.controls.items():
            fails = [r for r in rows if r["judged"] and not r["pass"]]
            worst = max(fails, key=lambda r: r["abs_diff"] / r["tolerance"]) if fails else None
            crow.append((name, "not run: " + why if run is None else str(len(fails)),
                         "" if worst is None else f"{worst['quantity']} @ {worst['station']}: "
                         f"{worst['abs_diff']:.3g} > {worst['tolerance']:.3g}",
                         "fails (as it must)" if fails else "**passes: not detected**"))
        lines += [md_table(["control", "judged rows failing", "largest excess", "outcome"],
                           crow), ""]
    lines += extremes_markdown(comp, heading)
    lines += ["![time series](timeseries.png)", "", "![envelopes](envelopes.png)", ""]
    return "\n".join(lines)


#: the report's unit of an SI unit and its size
REPORT_UNITS = {"N": ("kN", 1e3), "N m": ("kN m", 1e3), "-": ("-", 1.0)}


def extremes_markdown(comp, heading: str = "#") -> list[str]:
    """The extremes over the storm of both runs (an irregular sea: the recorder's
    ``dynamic_*_mpm`` figures, :mod:`riser.design.extremes`), side by side; [] without
    them (a periodic drive, or a run not kept)."""
    v, a = comp.vfife.result, comp.ancf.result
    if v is None or a is None:
        return []
    iv, ia = v.summary(), a.summary()
    storm = iv.get("dynamic_storm_duration")
    body = []
    for name, (_, si, label) in SUMMARY_EXTREMES.items():
        ev, ea = summary_extreme(iv, name), summary_extreme(ia, name)
        if ev is None or ea is None:
            continue
        unit, k = REPORT_UNITS[si]

        def f(e, key):
            return "" if e[key] is None else f"{e[key] / k:.4g}"

        def interval(e):
            return "" if e["low"] is None else f"{e['low'] / k:.4g} - {e['high'] / k:.4g}"
        body.append((label, unit, f(ev, "mpm"), interval(ev), f(ea, "mpm"), interval(ea),
                     "" if not ev["mpm"] else f"{ea['mpm'] / ev['mpm']:.3f}",
                     f(ev, "rayleigh"), f(ea, "rayleigh"), f(ev, "record"), f(ea, "record"),
                     f"{ev['peaks']:.0f} / {ea['peaks']:.0f}",
                     f"{ev['shape']:.2f} / {ea['shape']:.2f}"))
    if not body or storm is None:
        return []
    record = comp.scene.dynamics.duration - comp.start
    return [f"{heading}# Extremes over the storm ({storm:g} s)", "",
            f"The most probable maximum (MPM; of the least tension: minimum) over a storm "
            f"of D = {storm:g} s ({storm / 3600:.3g} h; `[design] storm_duration`, else "
            "3 h; docs/design.md, \"Extremes over a storm\"), each method from its own "
            f"record of {record:g} s, reported, not judged: a two-parameter Weibull fitted "
            "by maximum likelihood to the upper half of the record's peaks (a peak: the "
            "largest value between successive up-crossings of the mean; the troughs for "
            "the least tension), at N = D / Tz peaks; its 90 % interval a bootstrap of the peaks (seeded: it "
            "regenerates byte for byte; the fit's sampling error alone); beside it the "
            "Rayleigh form with the record's sigma and Tz and the record's own extreme.",
            "", md_table(["quantity", "unit", "VFIFE: Weibull MPM", "90 % interval",
                          "ANCF: Weibull MPM", "90 % interval", "ANCF / VFIFE",
                          "VFIFE: Rayleigh MPM", "ANCF: Rayleigh MPM",
                          "VFIFE: record's extreme", "ANCF: record's extreme",
                          "peaks VFIFE / ANCF", "Weibull k VFIFE / ANCF"], body), ""]


def plots(comp, out: Path) -> None:
    from verification.report.figures import new_figure, save
    v, a = comp.vfife.result, comp.ancf.result
    if v is None or a is None:
        return
    start = comp.start
    fig, axes = new_figure(3, 1, size=(9.0, 9.0))
    for res, lab, sty in ((v, "VFIFE", "-"), (a, "ANCF", "--")):
        ts = res.dynamics.timeseries
        axes[0, 0].plot(ts["time"], np.asarray(ts["hang_off_tension"]) / 1e3, sty, label=lab)
        st = res.dynamics.states
        td = [(n, s) for n, s in comp.stations if n != "hang-off"][:1]
        if td:
            name, s = td[0]
            j = int(np.argmin(np.abs(np.asarray(st["s"]) - s)))
            axes[1, 0].plot(st["t"], np.asarray(st["tension"])[:, j] / 1e3, sty,
                            label=f"{lab}, {name}")
            axes[2, 0].plot(st["t"], np.asarray(st["moment"])[:, j] / 1e3, sty,
                            label=f"{lab}, {name}")
    for ax, yl in zip(axes[:, 0], ("hang-off tension [kN]", "tension [kN]", "moment [kN m]")):
        ax.axvline(start, color="0.6", lw=0.8)
        ax.set_ylabel(yl)
        ax.legend(fontsize=8)
    axes[2, 0].set_xlabel("t [s]")
    save(fig, out / "timeseries.png")
    fig, axes = new_figure(3, 1, size=(9.0, 9.0))
    for res, lab, sty in ((v, "VFIFE", "-"), (a, "ANCF", "--")):
        e = res.dynamics.envelope
        axes[0, 0].plot(e["s"], np.asarray(e["tension_min"]) / 1e3, sty, label=f"{lab} min")
        axes[0, 0].plot(e["s"], np.asarray(e["tension_max"]) / 1e3, sty, label=f"{lab} max")
        axes[1, 0].plot(e["s"], np.asarray(e["moment_max"]) / 1e3, sty, label=lab)
        axes[2, 0].plot(e["s"], e["curvature_max"], sty, label=lab)
    for ax, yl in zip(axes[:, 0], ("tension [kN]", "max moment [kN m]",
                                   "max curvature [1/m]")):
        ax.set_ylabel(yl)
        ax.legend(fontsize=8)
    axes[2, 0].set_xlabel("s [m]")
    save(fig, out / "envelopes.png")

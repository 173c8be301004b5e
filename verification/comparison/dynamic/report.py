"""Files of a dynamic comparison (:mod:`.protocol`): the report, the CSV tables and the
plots, and the frequency domain's transfer functions.

Files (SI units; amplitudes of the first harmonic, ``rel_diff`` = VFIFE / FD - 1 or the
difference over the basis of the row's tolerance, see :data:`.protocol.TOLERANCES`):
``dynamic_agreement.csv`` (amplitude_m, quantity, fd, vfife, rel_diff, s, tolerance,
basis, pass), ``stations.csv`` (amplitude_m, station, s, fd_amplitude, vfife_amplitude,
rel_diff, phase_diff_deg), ``response.csv`` (amplitude_m, s, the FD's and the VFIFE's
tension [N], moment [N m] and displacement [m] amplitudes, the tension phases [deg]),
``transfer.csv`` (period_s, hang_off_tension_per_m [N/m], max_moment_per_m [N m/m],
max_curvature_per_m [1/m2]: the FD per unit motion), ``transfer_along_s.csv`` (period_s,
s, tension_per_m, moment_per_m, curvature_per_m: the same along s at 101 stations),
``response.png``, ``sweep.png``, ``transfer.png``; the static comparison's files beside
them (its report the first section of ``report.md``). The transfer functions are per unit
motion of the hang-off along one axis: a wave's or an orbit's comparison has none, and
its ``transfer*`` files are neither written nor linked (nor when no period of the sweep
converged).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from verification.methods import method
from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, fmt, md_table, pct_step, timed
from verification.runtime.stable import DYNAMIC_SIGNIFICANT, QUANTA

from .rows import DRIFT_LIMIT, TOLERANCES
from .protocol import (ORBIT, RAMP_PERIODS, SETTLE_PERIODS, WAVE, WINDOW_PERIODS,
                       DynamicComparison)

FILES = ("dynamic_agreement.csv", "stations.csv", "response.csv", "transfer.csv",
         "transfer_along_s.csv", "response.png", "sweep.png", "transfer.png", "report.md",
         "dynamic_agreement_ancf.csv")
#: the ANCF's rows against the FD (the columns of dynamic_agreement.csv, its values
#: under ``ancf``), written when the ANCF ran
ANCF_FILE = "dynamic_agreement_ancf.csv"
#: stations along s of ``transfer_along_s.csv`` (evenly spaced, the ends included)
TRANSFER_STATIONS = 101
#: periods of the transfer functions, as multiples of the motion's period
TRANSFER_SPAN = (0.5, 3.0)
TRANSFER_PERIODS = 24
PASS_WORD = {True: "yes", False: "**no**", None: "n/a"}
_QUANTITY = {"tension": "tension", "dz": "out-of-plane displacement"}


def transfer(dc: DynamicComparison) -> tuple[pd.DataFrame, pd.DataFrame]:
    """The FD's transfer functions per unit motion over :data:`TRANSFER_PERIODS` periods
    (geometric, :data:`TRANSFER_SPAN` times the motion's), the drag linearised at the
    smallest amplitude of the sweep: (the hang-off tension and the largest moment and
    curvature per period, the tension, moment and curvature amplitudes along s at
    :data:`TRANSFER_STATIONS` stations per period)."""
    if dc.axis in (WAVE, ORBIT):    # transfer functions per unit motion along one axis
        return pd.DataFrame(), pd.DataFrame()
    lo, hi = TRANSFER_SPAN
    periods = dc.period * np.geomspace(lo, hi, TRANSFER_PERIODS)
    amp = dc.results[0].amplitude
    rows, along = [], []
    for r in method("bvp").transfer(dc.matched, periods, dc.axis, static=dc.static,
                                    amplitude=amp, tolerance=1e-4, intervals=3000):
        if not r.converged:
            continue
        moment = np.abs(r.amplitudes["moment"]) + np.abs(r.amplitudes["moment_out"])
        rows.append({"period_s": r.period,
                     "hang_off_tension_per_m": float(abs(r.amplitudes["tension"][-1])),
                     "max_moment_per_m": float(np.max(moment)),
                     "max_curvature_per_m": float(np.max(np.abs(r.amplitudes["curvature"])))})
        s = np.linspace(r.s[0], r.s[-1], TRANSFER_STATIONS)
        along.append(pd.DataFrame({
            "period_s": r.period, "s": s,
            "tension_per_m": np.abs(r.at("tension", s)),
            "moment_per_m": np.abs(r.at("moment", s)) + np.abs(r.at("moment_out", s)),
            "curvature_per_m": np.abs(r.at("curvature", s))}))
    return pd.DataFrame(rows), (pd.concat(along, ignore_index=True) if along
                                else pd.DataFrame())


def frames(dc: DynamicComparison) -> dict:
    """The CSV tables of the comparison (see the module docstring)."""
    agree, stations, resp = [], [], []
    for r in dc.results:
        agree += [{"amplitude_m": r.amplitude, **{k: row[k] for k in (
            "quantity", "fd", "vfife", "rel_diff", "s", "tolerance", "basis", "pass")}}
            for row in r.rows]
        stations += [{"amplitude_m": r.amplitude, **st} for st in r.stations]
        s = r.vf["s"]
        q = {k: r.fd.at(k, s) for k in ("tension", "moment", "moment_out", "dx", "dy", "dz")}
        resp.append(pd.DataFrame({
            "amplitude_m": r.amplitude, "s": s,
            "fd_tension": np.abs(q["tension"]), "vfife_tension": r.vf["tension"].amplitude,
            "fd_tension_phase_deg": np.degrees(np.angle(q["tension"])),
            "vfife_tension_phase_deg": np.degrees(r.vf["tension"].phase),
            "fd_moment": np.abs(q["moment"]) + np.abs(q["moment_out"]),
            "vfife_moment": r.vf["moment"].amplitude + r.vf["moment_out"].amplitude,
            "fd_displacement": np.sqrt(sum(np.abs(q[k]) ** 2 for k in ("dx", "dy", "dz"))),
            "vfife_displacement": np.sqrt(sum(r.vf[k].amplitude ** 2
                                              for k in ("dx", "dy", "dz")))}))
    out = {"dynamic_agreement.csv": pd.DataFrame(agree),
           "stations.csv": pd.DataFrame(stations),
           "response.csv": pd.concat(resp, ignore_index=True)}
    ancf = [{"amplitude_m": r.amplitude, **{k: row[k] for k in (
        "quantity", "fd", "ancf", "rel_diff", "s", "tolerance", "basis", "pass")}}
        for r in dc.results for row in r.ancf_rows]
    if ancf:
        out[ANCF_FILE] = pd.DataFrame(ancf)
    return out


def write(dc: DynamicComparison, out: str | Path, static_markdown: str = "",
          peer_markdown: str = "") -> None:
    """Every file of the module docstring into ``out``; ``static_markdown``: the static
    comparison's report, the first section."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    tables = frames(dc)
    tables["transfer.csv"], tables["transfer_along_s.csv"] = transfer(dc)
    has_transfer = len(tables["transfer.csv"]) > 0
    if not has_transfer:    # nothing to write: no empty file, no empty plot, no link
        del tables["transfer.csv"], tables["transfer_along_s.csv"]
    for name, frame in tables.items():
        frame.to_csv(out / name, index=False, float_format="%.8g")
    _plots(dc, tables, out)
    (out / "report.md").write_text(markdown(dc, static_markdown, peer_markdown,
                                            transfer_written=has_transfer))


def markdown(dc: DynamicComparison, static_markdown: str = "", peer_markdown: str = "",
             heading: str = "#", transfer_written: bool | None = None) -> str:
    """report.md; ``transfer_written``: whether the transfer functions' files were
    written (default: a motion along one axis has them, a wave or an orbit not)."""
    if transfer_written is None:
        transfer_written = dc.axis not in (WAVE, ORBIT)
    sc = dc.scene
    verdict = "PASS" if dc.passed else "FAIL"
    with_ancf = any(r.ancf is not None for r in dc.results)
    lines = [f"{heading} Dynamic response, frequency domain vs VFIFE"
             + (" and ANCF" if with_ancf else "") + f": `{sc.name}`", "",
             GENERATED_NOTE, "", f"**Verdict: {verdict}** (the judged rows of every "
             "amplitude; the static comparison has its own verdict)", ""]
    amps = ', '.join(f'{r.amplitude:g}' for r in dc.results)
    if dc.axis == WAVE:
        tr = dc.scene.waves.trains[0]
        drive = (f"- Wave: Airy, period T = {dc.period:g} s, amplitude A = {amps} m, "
                 f"heading {tr.heading_deg:g} deg, phase lag {tr.phase_deg:g} deg at the "
                 "waves' origin; " + ("the hang-off moves with the vessel's RAOs"
                                      if dc.scene.vessel is not None else
                                      "the hang-off fixed") + (
                     "; the line loaded by the wave (Morison drag and inertia)"
                     if dc.scene.waves.line_loads else "; no wave load on the line") + "; no "
                 "transfer functions (they are per unit motion of the hang-off along one "
                 "axis; the response per unit wave amplitude at this period is `response.csv`'s "
                 "divided by A).")
    elif dc.axis == ORBIT:
        tm = dc.scene.dynamics.top_motion
        drive = (f"- Orbit: d_k(t) = A_k sin(2 pi t / T + phi_k), T = {dc.period:g} s, the "
                 f"scene's amplitudes (x, y, z) = ({', '.join(f'{v:g}' for v in tm.amplitudes)})"
                 f" m scaled so that the largest is A = {amps} m, phase leads "
                 f"({', '.join(f'{v:g}' for v in tm.phases_deg)}) deg; no transfer "
                 "functions (they are per unit motion along one axis).")
    else:
        drive = (f"- Motion: d(t) = A sin(2 pi t / T) along {dc.axis}, T = {dc.period:g} s, "
                 f"A = {amps} m.")
    three_d = not dc.matched.statics_planar
    lines += [drive,
              "- Frequency domain (`bvp/frequency/harmonic.py`): linearised about the BVP static "
              "state, drag by equal work per cycle (iterated), touchdown fixed at the static "
              "one, the line wholly in the water."
              + (" The static state is 3D: the rod linearised, in- and out-of-plane motion "
                 "coupled (`bvp/frequency/rod_harmonic.py`); the moments are the 3D "
                 "profile's columns in and out of the ends' plane, read off the time "
                 "domains sample by sample." if three_d else ""),
              f"- VFIFE: {dc.element_length:g} m elements, a ramp of "
              f"{dc.results[0].vf.get('ramp_periods', RAMP_PERIODS)} periods, "
              f"{SETTLE_PERIODS} periods to settle (doubled while the window's halves "
              f"differ by more than {DRIFT_LIMIT:.1%}), the first harmonic fitted over the last "
              f"{WINDOW_PERIODS} periods at every node (statics 10x tighter than the "
              "default: the static residual would ring as a free oscillation)."]
    lines += [f"- {n}" for n in dc.notes]
    if static_markdown:
        lines += ["", static_markdown]
    lines += ["", f"{heading}# Agreement per amplitude", ""]
    for r in dc.results:
        ratio = r.vfife_wall_s / max(r.fd_wall_s, 1e-9)
        lines += [f"Amplitude {r.amplitude:g} m: FD {timed(r.fd_wall_s)}, VFIFE "
                  f"{timed(r.vfife_wall_s, '.1f')} (ratio {timed(ratio, '.0f', '')})"
                  + (f"; warnings: {'; '.join(r.warnings)}" if r.warnings else "") + ".", ""]
        lines.append(md_table(
            ["quantity", "FD", "VFIFE", "VFIFE vs FD", "at s [m]", "tolerance", "basis",
             "pass"],
            [(f"`{w['quantity']}`", _dyn(w["fd"]), _dyn(w["vfife"]), _rel(w), w["s"],
              w["tolerance"], w["basis"], PASS_WORD[w["pass"]]) for w in r.rows]))
        lines += ["", md_table(["station", "s [m]", "FD tension amplitude [N]",
                                "VFIFE [N]", "relative", "phase VFIFE - FD [deg]"],
                               [(st["station"], st["s"], _dyn(st["fd_amplitude"]),
                                 _dyn(st["vfife_amplitude"]), pct_step(st["rel_diff"], _STEP),
                                 _deg(st["phase_diff_deg"])) for st in r.stations]), ""]
        nl = r.nonlinearity
        zone = nl["contact_zone"]
        where = ("at the hang-off" if nl["quantity"] == "tension"
                 else "where it is largest")
        lines += [f"Nonlinearity measured on the VFIFE's {_QUANTITY[nl['quantity']]}: "
                  f"higher harmonics {pct_step(nl['hang_off_higher_harmonics'], _STEP)} of the first "
                  f"{where} (at worst {pct_step(nl['max_higher_harmonics'], _STEP)} along s where the "
                  "first harmonic is a tenth of its peak or more); envelope / first harmonic "
                  f"{fmt(nl['hang_off_envelope_ratio'], DYNAMIC_SIGNIFICANT)} {where}; window drift "
                  f"{pct_step(nl['window_drift'], _STEP)} after {nl['settle_periods']} periods of "
                  "settling"
                  + (f"; contact zone s = {zone[0]:.1f} to {zone[1]:.1f} m" if zone else "")
                  + ".", ""]
        if r.ancf is not None:
            i = r.ancf_info
            lines += [f"The ANCF's time domain ({i['element_length']:g} m cubic elements, "
                      f"{i['integrator']} steps of {i['dynamic_time_step']:.3g} s, "
                      f"{i['newton_iterations_per_step']:.2f} Newton iterations a step, "
                      f"{r.ancf['settle_periods']} periods of settling; "
                      f"{timed(r.ancf_wall_s, '.1f')}) against the same FD, judged like "
                      "the VFIFE:", ""]
            lines.append(md_table(
                ["quantity", "FD", "ANCF", "ANCF vs FD", "at s [m]", "tolerance", "basis",
                 "pass"],
                [(f"`{w['quantity']}`", _dyn(w["fd"]), _dyn(w["ancf"]), _rel(w), w["s"],
                  w["tolerance"], w["basis"], PASS_WORD[w["pass"]]) for w in r.ancf_rows]))
            lines.append("")
    lines += [f"{heading}# Tolerances", "", md_table(
        ["quantity", "tolerance", "basis", "reason"],
        [(f"`{k}`", v[0], v[1], v[2]) for k, v in TOLERANCES.items()]), "",
        "Rows ending in `_contact_zone` are reported, not judged: where the static line "
        "lies within the motion's reach of the seabed the VFIFE's contact opens and closes "
        "over the cycle, the FD's stays as in the static state.", "",
        f"{heading}# Figures", "", "![response along s](response.png)", "",
        "![differences over the amplitude sweep](sweep.png)", "",
        *(["![transfer functions](transfer.png)", ""] if transfer_written else []),
        "Files: " + ", ".join(f"`{f}`" for f in FILES[:5]
                              if transfer_written or not f.startswith("transfer"))
        + (f", `{ANCF_FILE}`" if with_ancf else "") + ".",
        ""]
    if peer_markdown:
        lines.append(peer_markdown)
    return "\n".join(lines)


#: the step of a dynamic relative difference and of a phase [deg] in the text: the
#: quanta of dynamic_agreement.csv (another CPU moves a dynamic response in its 5th digit)
_STEP = QUANTA["dynamic_agreement.csv"]["rel_diff"]
_DEG_STEP = 0.05


def _dyn(value):
    """A dynamic response's value to the digits its CSV holds."""
    return value if not isinstance(value, float) else fmt(value, DYNAMIC_SIGNIFICANT)


def _deg(value) -> str:
    if value is None:
        return ""
    return f"{round(value / _DEG_STEP) * _DEG_STEP:+.2f}"


def _rel(w: dict) -> str:
    if w["rel_diff"] is None:
        return ""
    if w["quantity"].endswith("_deg"):
        return f"{_deg(w['rel_diff'])} deg"
    return pct_step(w["rel_diff"], _STEP)


def _plots(dc: DynamicComparison, tables: dict, out: Path) -> None:
    resp = tables["response.csv"]
    first = resp[resp["amplitude_m"] == dc.results[0].amplitude]
    fig, axes = new_figure(3, 1, (9, 10))
    for ax, key, label, scale in zip(axes[:, 0], ("tension", "moment", "displacement"),
                                     ("tension amplitude [kN]", "moment amplitude [kN m]",
                                      "displacement amplitude [m]"), (1e3, 1e3, 1.0)):
        ax.plot(first["s"], first[f"fd_{key}"] / scale, "-", lw=2.0, label="frequency domain")
        ax.plot(first["s"], first[f"vfife_{key}"] / scale, "--", lw=1.2, label="VFIFE")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0, 0].legend()
    axes[0, 0].set_title(f"{dc.scene.name}: first harmonic, A = {dc.results[0].amplitude:g} "
                         f"m along {dc.axis}, T = {dc.period:g} s")
    axes[2, 0].set_xlabel("arc length s [m]")
    save(fig, out / "response.png")
    agree = tables["dynamic_agreement.csv"]
    fig, axes = new_figure(1, 1, (8, 5))
    ax = axes[0, 0]
    for q in ("hang_off_tension_amplitude", "tension_amplitude", "moment_amplitude",
              "moment_out_amplitude", "displacement_amplitude"):
        sel = agree[agree["quantity"] == q]
        if len(sel):
            ax.plot(sel["amplitude_m"], np.abs(sel["rel_diff"].astype(float)) + 1e-7, "o-",
                    label=q)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("motion amplitude [m]")
    ax.set_ylabel("|VFIFE - FD| (relative, see the table)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    save(fig, out / "sweep.png")
    tr = tables.get("transfer.csv")
    if tr is None or not len(tr):
        return
    fig, axes = new_figure(2, 1, (8, 7))
    axes[0, 0].plot(tr["period_s"], tr["hang_off_tension_per_m"] / 1e3, "o-")
    axes[1, 0].plot(tr["period_s"], tr["max_moment_per_m"] / 1e3, "o-")
    for ax in axes[:, 0]:
        ax.axvline(dc.period, color="0.5", ls=":")
        ax.grid(alpha=0.3)
    axes[0, 0].set_ylabel("hang-off tension [kN per m]")
    axes[1, 0].set_ylabel("max moment [kN m per m]")
    axes[1, 0].set_xlabel("period [s]")
    axes[0, 0].set_title(f"{dc.scene.name}: frequency-domain transfer functions "
                         f"(motion along {dc.axis})")
    save(fig, out / "transfer.png")


def console_lines(dc: DynamicComparison) -> list[str]:
    out = []
    for r in dc.results:
        out.append(f"  amplitude {r.amplitude:g} m (FD {r.fd_wall_s:.2f} s, VFIFE "
                   f"{r.vfife_wall_s:.1f} s):")
        for w in r.rows:
            flag = {True: "ok  ", False: "FAIL", None: "n/a "}[w["pass"]]
            out.append(f"    {flag} {w['quantity']:<34} {_rel(w)}")
        if r.ancf is not None:
            out.append(f"    ANCF against the same FD ({r.ancf_wall_s:.1f} s):")
            for w in r.ancf_rows:
                flag = {True: "ok  ", False: "FAIL", None: "n/a "}[w["pass"]]
                out.append(f"    {flag} {w['quantity']:<34} {_rel(w)}")
        out += [f"    warning: {x}" for x in r.warnings]
    return out


"""Files of an irregular-sea comparison (:mod:`.protocol`): the report, the CSV
tables and the plots.

Files (SI units): ``sea_agreement.csv`` (quantity, fd, vfife, rel_diff = VFIFE / FD - 1 or
the difference over the basis, s, tolerance, basis, pass), ``sea_along_s.csv`` (s, the FD's
and the VFIFE's standard deviation of tension [N] and curvature [1/m]), ``spectra.csv``
(omega [rad/s], the wave spectrum S_eta [m2 s/rad], the hang-off tension's spectrum by
the FD and the VFIFE's record's periodogram [N2 s/rad] at the components' frequencies),
``sea_response.png``, ``spectra.png``, ``sea_tension.png`` (the VFIFE's record) and
``report.md`` (with the extremes over the storm: :func:`extremes_markdown`); the static
comparison's files beside them (its report the first section).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, md_table, pct, pct_step, timed
from verification.runtime.stable import QUANTA

from .protocol import TOLERANCE, SeaComparison

#: the columns of sea_agreement.csv (each row's, :class:`~..row.Row`)
SEA_COLUMNS = ("quantity", "fd", "vfife", "rel_diff", "s", "tolerance", "basis", "pass")
FILES = ("sea_agreement.csv", "sea_along_s.csv", "spectra.csv", "sea_response.png",
         "spectra.png", "sea_tension.png", "report.md")
PASS_WORD = {True: "yes", False: "**no**", None: "n/a"}


#: the step of a relative difference in the text: sea_agreement.csv's quantum (another
#: CPU moves a dynamic response in its 5th digit)
_STEP = QUANTA["sea_agreement.csv"]["rel_diff"]


def frames(sc: SeaComparison) -> dict:
    """The CSV tables (see the module docstring)."""
    fd, vf = sc.fd, sc.vf
    s = vf["s"]
    along = pd.DataFrame({
        "s": s, "fd_tension_std": np.interp(s, fd.s, fd.std["tension"]),
        "vfife_tension_std": vf["tension_std"],
        "fd_curvature_std": np.interp(s, fd.s, fd.std["curvature"]),
        "vfife_curvature_std": vf["curvature_std"]})
    vf_at = np.interp(fd.omega, vf["omega"], vf["density"])
    spectra = pd.DataFrame({"omega": fd.omega, "wave_density": fd.wave_density,
                            "fd_hang_off_tension_density": fd.spectra["tension"][:, -1],
                            "vfife_hang_off_tension_density": vf_at})
    return {"sea_agreement.csv": pd.DataFrame([r.record(SEA_COLUMNS) for r in sc.rows],
                                              columns=SEA_COLUMNS), "sea_along_s.csv": along,
            "spectra.csv": spectra}


def write(sc: SeaComparison, out: str | Path, static_markdown: str = "") -> None:
    """Every file of the module docstring into ``out``."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    tables = frames(sc)
    for name, frame in tables.items():
        frame.to_csv(out / name, index=False, float_format="%.8g")
    _plots(sc, tables, out)
    (out / "report.md").write_text(markdown(sc, static_markdown))


def markdown(sc: SeaComparison, static_markdown: str = "", heading: str = "#") -> str:
    sp = sc.matched.waves.spectrum
    verdict = "PASS" if sc.passed else "FAIL"
    vf = sc.vf
    lines = [f"{heading} Irregular sea, frequency domain vs VFIFE: `{sc.scene.name}`", "",
             GENERATED_NOTE, "", f"**Verdict: {verdict}** (the hang-off tension's standard "
             f"deviation within {TOLERANCE:.0%}; the static comparison has its own verdict)",
             "",
             f"- Sea: {sp.kind}, Hs = {sp.hs:g} m, Tp = {sp.tp:g} s, gamma "
             f"{sp.gamma_used:.3g}, {sp.components} components (seed {sp.seed}), heading "
             f"{sp.heading_deg:g} deg" if sp.kind != "table" else
             f"- Sea: a spectrum table, {sp.components} components (seed {sp.seed})",
             "- Frequency domain (`bvp/frequency/sea_response.py`): each component's harmonic "
             "response about the BVP static state, the drag linearised stochastically "
             f"(Gaussian relative velocity), {sc.fd.info.get('iterations')} iterations, "
             f"{timed(sc.fd_wall_s, '.1f')}.",
             f"- VFIFE: {sc.element_length:g} m elements, the same components; a ramp of "
             f"{sc.ramp_s:.4g} s and {sc.settle_s:.4g} s to settle, then a record of one "
             f"repeat period of the sea, {sc.record_s:.4g} s ({vf['samples']} samples), "
             f"{timed(sc.vfife_wall_s, '.1f')}. Over a whole repeat period the components are "
             "orthogonal: a linear response's record variance is the FD's sigma^2 without "
             "the sampling error of a random record; the halves of the record (each not a "
             "whole period) show the scatter a record half as long would have: "
             f"{pct_step(vf['std_halves'][0] / sc.fd.std['tension'][-1] - 1, _STEP)} and "
             f"{pct_step(vf['std_halves'][1] / sc.fd.std['tension'][-1] - 1, _STEP)} on the "
             "hang-off "
             "tension's std.", "- Zero-upcrossing periods 2 pi sqrt(m0 / m2) and most "
             "probable maxima over 3 h (Rayleigh: the peaks of a narrow-banded Gaussian "
             "response), each method from its own spectral moments: the FD's spectrum, the "
             "VFIFE's record's periodogram (the record's Tz counted from its upcrossings: "
             + (f"{vf['tz_counted']:.4g} s)." if vf.get("tz_counted") else "none).")]
    lines += [f"- {n}" for n in sc.notes]
    if static_markdown:
        lines += ["", static_markdown]
    rows = []
    for r in sc.rows:
        rel = "" if r["rel_diff"] is None else pct_step(r["rel_diff"], _STEP)
        tol = "" if r["tolerance"] is None else f"{r['tolerance']:g}"
        s = "" if r["s"] is None else f"{r['s']:.1f}"
        rows.append((f"`{r['quantity']}`", f"{r['fd']:.4g}",
                     "" if r["vfife"] is None else f"{r['vfife']:.4g}", rel, s, tol,
                     r["basis"], PASS_WORD[r["pass"]]))
    lines += ["", f"{heading}# Agreement", "", md_table(
        ("quantity", "FD", "VFIFE", "difference", "s [m]", "tolerance", "basis", "judged pass"),
        rows), ""]
    lines += extremes_markdown(sc, heading)
    lines += [f"{heading}# Figures", "",
        "![standard deviations along s](sea_response.png)", "",
        "![hang-off tension spectra](spectra.png)", "",
        "![the VFIFE's hang-off tension record](sea_tension.png)", "",
        "Files: " + ", ".join(f"`{f}`" for f in FILES[:3]) + ".", ""]
    return "\n".join(lines)


#: the report's unit of an SI unit and its size
REPORT_UNITS = {"N": ("kN", 1e3), "N m": ("kN m", 1e3), "-": ("-", 1.0)}


def _value(v, scale: float) -> str:
    return "" if v is None else f"{v / scale:.4g}"


def extremes_markdown(sc: SeaComparison, heading: str = "#") -> list[str]:
    """The section of the extremes over the storm (:func:`..protocol.extreme_rows`): the
    FD's Rayleigh MPM beside the VFIFE's Weibull MPM, its interval, its Rayleigh form and
    its record's own extreme; [] when there are none."""
    if not sc.extremes:
        return []
    d = sc.storm_s
    body = []
    for e in sc.extremes:
        unit, k = REPORT_UNITS[e["unit"]]
        interval = ("" if e["low"] is None or e["high"] is None else
                    f"{e['low'] / k:.4g} - {e['high'] / k:.4g}")
        ratio = ("" if e["fd"] is None or e["vfife"] is None or not e["fd"]
                 else f"{e['vfife'] / e['fd']:.3f}")
        body.append((e["label"], unit, _value(e["fd"], k), _value(e["vfife"], k),
                     interval, _value(e["rayleigh"], k), _value(e["record"], k),
                     "" if e["peaks"] is None else f"{e['peaks']:.0f}",
                     "" if e["shape"] is None else f"{e['shape']:.2f}", ratio))
    return [f"{heading}# Extremes over the storm ({d:g} s)", "",
            f"The most probable maximum (MPM; of the least tension: minimum) over a storm "
            f"of D = {d:g} s ({d / 3600:.3g} h; `[design] storm_duration`, else 3 h; "
            "docs/design.md, \"Extremes over a storm\"), reported, not judged. FD: the "
            "static value plus its Rayleigh MPM sigma sqrt(2 ln(D / Tz)) from its spectral "
            "moments, at the worst station (the utilisation: the MPMs of tension and moment "
            "combined in phase, an upper bound). VFIFE: a two-parameter Weibull fitted by "
            "maximum likelihood to the upper half of the peaks of its "
            f"{sc.record_s:.4g} s record (a peak: the largest value between successive "
            "up-crossings of the mean; the troughs for the least tension), at N = D / Tz "
            "peaks; its 90 % interval a bootstrap of the "
            "peaks (seeded: it regenerates byte for byte; the fit's sampling error alone, "
            "narrower than the scatter from one record to another); beside it the Rayleigh "
            "form with the record's own sigma and Tz, and the record's own extreme over "
            f"{sc.record_s:.4g} s.", "",
            md_table(("quantity", "unit", "FD: static + Rayleigh MPM", "VFIFE: Weibull MPM",
                      "90 % interval", "VFIFE: Rayleigh MPM", "VFIFE: record's extreme",
                      "peaks", "Weibull k", "VFIFE / FD"), body), ""]


def _plots(sc: SeaComparison, tables: dict, out: Path) -> None:
    a = tables["sea_along_s.csv"]
    fig, axes = new_figure(2, 1, (9, 7))
    for ax, key, label, scale in ((axes[0, 0], "tension", "std of tension [kN]", 1e3),
                                  (axes[1, 0], "curvature", "std of curvature [1/m]", 1.0)):
        ax.plot(a["s"], a[f"fd_{key}_std"] / scale, "-", lw=2.0, label="frequency domain")
        ax.plot(a["s"], a[f"vfife_{key}_std"] / scale, "--", lw=1.2, label="VFIFE record")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0, 0].legend()
    axes[0, 0].set_title(f"{sc.scene.name}: standard deviations along the line")
    axes[1, 0].set_xlabel("arc length s [m]")
    save(fig, out / "sea_response.png")
    sp = tables["spectra.csv"]
    fig, axes = new_figure(2, 1, (9, 7))
    axes[0, 0].plot(sp["omega"], sp["wave_density"], "-")
    axes[0, 0].set_ylabel("S_eta [m2 s/rad]")
    axes[0, 0].set_title(f"{sc.scene.name}: the sea and the hang-off tension")
    axes[1, 0].plot(sp["omega"], sp["fd_hang_off_tension_density"] / 1e6, "-", lw=2.0,
                    label="frequency domain")
    axes[1, 0].plot(sp["omega"], sp["vfife_hang_off_tension_density"] / 1e6, "o", ms=3,
                    label="VFIFE record (periodogram)")
    axes[1, 0].set_ylabel("S_T [kN2 s/rad]")
    axes[1, 0].set_xlabel("omega [rad/s]")
    axes[1, 0].legend()
    for ax in axes[:, 0]:
        ax.grid(alpha=0.3)
    save(fig, out / "spectra.png")
    fig, axes = new_figure(1, 1, (9, 3.5))
    axes[0, 0].plot(sc.vf["t"], sc.vf["tension"] / 1e3, "-", lw=0.8)
    axes[0, 0].set_xlabel("t [s]")
    axes[0, 0].set_ylabel("hang-off tension [kN]")
    axes[0, 0].set_title("the VFIFE's record (one repeat period of the sea)")
    save(fig, out / "sea_tension.png")


def console_lines(sc: SeaComparison) -> list[str]:
    out = [f"  sea: FD {sc.fd_wall_s:.1f} s, VFIFE {sc.vfife_wall_s:.1f} s (record "
           f"{sc.record_s:.4g} s)"]
    for r in sc.rows:
        flag = {True: "ok  ", False: "FAIL", None: "n/a "}[r["pass"]]
        rel = "" if r["rel_diff"] is None else pct(r["rel_diff"])
        out.append(f"    {flag} {r['quantity']:<32} FD {r['fd']:.5g}  VFIFE "
                   f"{r['vfife'] if r['vfife'] is None else format(r['vfife'], '.5g')}  "
                   f"{rel}")
    return out

"""The files of a scatter diagram's fatigue (:mod:`.fatigue`): ``fatigue_along_s.csv``
(s [m], per estimate the damage per year [1/year] and the life [years]),
``sea_states.csv`` (per sea state and estimate: the damage rate [1/s] and the share of
the damage per year [1/year] (probability x rate x a year) at the headline's touchdown
station and at the hang-off, the shares summing over the sea states to the headline's
damage per year; the estimate's own worst station in the touchdown zone and its rate;
the record, the wall time, the VFIFE's largest dynamic utilisation), ``stations.csv`` (the headline: damage per year at
the touchdown and the hang-off by each estimate, the ratios to the VFIFE's rainflow),
``fatigue.png``, ``report.md``. With ``[design] design_life`` the fatigue verdict
(:func:`.fatigue.verdicts`): ``fatigue_along_s.csv`` adds ``required_life_years`` (DFF x
design_life) and per estimate ``_fatigue_utilisation`` [-] and ``_fatigue_pass``,
report.md its section. ``summary.json`` (:func:`write_summary`, ``riser-verify fatigue``):
the inputs, the design's verdict and each estimate's worst station."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd

from riser.design.fatigue import SECONDS_PER_YEAR
from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, md_table, timed

from riser.design.fatigue import verdict_line

from .fatigue import (ANCF, ANCF_STEPS_PER_SHORTEST, DESIGN_ESTIMATE, ESTIMATES,
                      TOUCHDOWN_ZONE, ScatterFatigue, ancf_agreement, fd_utilisation,
                      figures_of, stations, verdicts, worst_in_zone)

#: the spectrum's name in the report
_KIND = {"jonswap": "JONSWAP", "pierson-moskowitz": "Pierson-Moskowitz"}
#: what each estimate is, for the report
TITLES = {"rainflow_vfife": "VFIFE time domain, rainflow",
          ANCF: "ANCF time domain (same realisation), rainflow",
          "rainflow_fd": "FD linear record (same realisation), rainflow",
          "dirlik_fd": "FD spectrum, Dirlik",
          "narrow_band_fd": "FD spectrum, narrow band (Rayleigh)"}


def station_table(result: ScatterFatigue) -> pd.DataFrame:
    """The headline rows: per estimate the damage per year and life at the touchdown
    (the VFIFE's worst station there, and the estimate's own worst station in the zone)
    and at the hang-off, and the ratio to the VFIFE's rainflow."""
    st = stations(result)
    rows = []
    ref_td = result.per_year["rainflow_vfife"][st["touchdown"]]
    ref_ho = result.per_year["rainflow_vfife"][st["hang_off"]]
    for e in result.estimates:
        d = result.per_year[e]
        own, own_s = worst_in_zone(result, e)
        rows.append({"estimate": e, "touchdown_s": float(result.s[st["touchdown"]]),
                     "touchdown_damage_per_year": float(d[st["touchdown"]]),
                     "touchdown_ratio": float(d[st["touchdown"]] / ref_td),
                     "own_worst_s": own_s, "own_worst_damage_per_year": own,
                     "own_worst_ratio": own / ref_td,
                     "hang_off_damage_per_year": float(d[st["hang_off"]]),
                     "hang_off_ratio": float(d[st["hang_off"]] / ref_ho)})
    return pd.DataFrame(rows)


def sea_state_table(result: ScatterFatigue) -> pd.DataFrame:
    """Per sea state: the figures of its runs and, per estimate, at the headline's stations
    (:func:`.fatigue.stations`: the touchdown's and the hang-off) the damage rate [1/s]
    and its share of the damage per year [1/year] (probability x rate x a year, the
    interpolation of :func:`.fatigue.damage_per_year`: the shares add up to the headline),
    and the estimate's own worst station in this sea state's touchdown zone."""
    rows = []
    head = stations(result)
    s_td, s_ho = float(result.s[head["touchdown"]]), float(result.s[head["hang_off"]])
    nan = float("nan")
    for st in result.states:
        cmp = st.comparison
        fig = figures_of(cmp)
        if fig is None:                          # left to the frequency domain
            row = {"hs": st.hs, "tp": st.tp, "probability": st.probability,
                   "record_s": nan, "ramp_s": nan, "settle_s": nan,
                   "element_length": result.element_length, "fd_wall_s": nan,
                   "vfife_wall_s": nan, "wall_s": st.wall_s,
                   "hang_off_tension_std_fd": nan, "hang_off_tension_std_vfife": nan,
                   "vfife_max_utilisation": nan, "vfife_max_utilisation_s": nan,
                   "fd_max_utilisation": nan, "fd_max_utilisation_s": nan,
                   "touchdown_range_m": nan}
        else:
            info = fig.info
            u_fd, u_fd_s = (fig.fd_max_utilisation if fig.fd_max_utilisation is not None
                            else fd_utilisation(cmp, st.record_s))
            row = {"hs": st.hs, "tp": st.tp, "probability": st.probability,
                   "record_s": st.record_s, "ramp_s": fig.ramp_s, "settle_s": fig.settle_s,
                   "element_length": fig.element_length, "fd_wall_s": fig.fd_wall_s,
                   "vfife_wall_s": fig.vfife_wall_s, "wall_s": st.wall_s,
                   "hang_off_tension_std_fd": fig.fd_hang_off_tension_std,
                   "hang_off_tension_std_vfife": fig.vfife_hang_off_tension_std,
                   "vfife_max_utilisation": info.get("dynamic_max_utilisation"),
                   "vfife_max_utilisation_s": info.get("dynamic_max_utilisation_s"),
                   "fd_max_utilisation": u_fd, "fd_max_utilisation_s": u_fd_s,
                   "touchdown_range_m": (_num(info.get("dynamic_max_touchdown_s"))
                                         - _num(info.get("dynamic_min_touchdown_s")))}
        row["touchdown_s"], row["hang_off_s"] = s_td, s_ho
        share = st.probability * SECONDS_PER_YEAR
        if ANCF in st.rates:
            row["ancf_wall_s"] = st.ancf_wall_s
            row["ancf_element_length"] = st.ancf_info.get("element_length")
            row["ancf_time_step"] = st.ancf_info.get("time_step")
            row["ancf_touchdown_range_m"] = st.ancf_info.get("touchdown_range_m")
        if result.screened:
            row["realisations"] = max(1, len(st.seeds)) if fig is not None else 0
            row["methods"] = " ".join(RUNS[e] for e in RUNS if e in st.rates)
        for e in result.estimates:
            if e not in st.rates:
                for k in ("touchdown_rate", "touchdown_damage_per_year", "hang_off_rate",
                          "hang_off_damage_per_year", "own_worst_rate", "own_worst_s"):
                    row[f"{e}_{k}"] = nan
                continue
            r = st.rates[e]
            zone = ((st.s >= st.tdp_s + TOUCHDOWN_ZONE[0])
                    & (st.s <= st.tdp_s + TOUCHDOWN_ZONE[1]))
            j = int(np.flatnonzero(zone)[np.argmax(r[zone])])
            at_td, at_ho = (float(np.interp(x, st.s, r)) for x in (s_td, s_ho))
            row[f"{e}_touchdown_rate"] = at_td
            row[f"{e}_touchdown_damage_per_year"] = share * at_td
            row[f"{e}_hang_off_rate"] = at_ho
            row[f"{e}_hang_off_damage_per_year"] = share * at_ho
            row[f"{e}_own_worst_rate"] = float(r[j])
            row[f"{e}_own_worst_s"] = float(st.s[j])
        rows.append(row)
    return pd.DataFrame(rows)


def _num(x) -> float:
    return float("nan") if x is None else float(x)


#: the methods a cell ran, by the estimates it has (sea_states.csv ``methods``)
RUNS = {"dirlik_fd": "fd", "rainflow_vfife": "vfife", ANCF: "ancf"}


def write(result: ScatterFatigue, out: Path, note: str = "", seconds: float = 0.0) -> dict:
    """Write the files into ``out``; returns the headline figures."""
    out.mkdir(parents=True, exist_ok=True)
    cols = {"s": result.s}
    ver = verdicts(result)
    if ver is not None:
        cols["required_life_years"] = np.full(len(result.s), ver[DESIGN_ESTIMATE]
                                              ["required_life"])
    for e in result.estimates:
        cols[f"{e}_damage_per_year"] = result.per_year[e]
        cols[f"{e}_life_years"] = result.life(e)
        if ver is not None:
            cols[f"{e}_fatigue_utilisation"] = ver[e]["fatigue_utilisation"]
            cols[f"{e}_fatigue_pass"] = ver[e]["fatigue_pass"]
    pd.DataFrame(cols).to_csv(out / "fatigue_along_s.csv", index=False, float_format="%.10g")
    ss = sea_state_table(result)
    ss.to_csv(out / "sea_states.csv", index=False, float_format="%.10g")
    tab = station_table(result)
    tab.to_csv(out / "stations.csv", index=False, float_format="%.10g")
    _plot(result, out / "fatigue.png")
    _report(result, ss, tab, out / "report.md", note, seconds, ver)
    d = tab.set_index("estimate")
    return {"touchdown_s": d.loc["rainflow_vfife", "touchdown_s"],
            "touchdown_rainflow": d.loc["rainflow_vfife", "touchdown_damage_per_year"],
            "touchdown_dirlik": d.loc["dirlik_fd", "touchdown_damage_per_year"],
            "ratio": d.loc["dirlik_fd", "touchdown_ratio"],
            "hang_off_ratio": d.loc["dirlik_fd", "hang_off_ratio"],
            "record_s": float(ss.record_s.dropna().iloc[0]),
            "ancf": ancf_agreement(result), "verdicts": ver}


def _finite(x):
    """A float for JSON: None for NaN and inf (summary.json holds no non-finite number)."""
    return float(x) if x is not None and math.isfinite(x) else None


def summary(result: ScatterFatigue, head: dict) -> dict:
    """summary.json of ``riser-verify fatigue``: the scene, the inputs of the verdict
    (``design_life`` [years], ``design_fatigue_factor``, ``required_life`` [years] = DFF x
    design_life), the design's verdict on :data:`.fatigue.DESIGN_ESTIMATE`
    (``max_fatigue_utilisation``, its ``_s`` [m], ``min_fatigue_life`` [years] there,
    ``fatigue_verdict`` 'pass' / 'fail'; None without a design_life), each estimate's
    least life and where (``estimates``; with a design_life its verdict's figures), the
    headline's touchdown and hang-off damage per year and the ANCF / VFIFE agreement's
    verdict; the cells each time domain ran (``cells_time_domain``, ``cells_ancf``), the
    screening's ``screen_share`` (None: every cell), ``record_length`` [s] and
    ``record_length_convergence`` (per record estimate and station the damage per year
    with half the record, the whole, their ratio; None with one realisation a cell).
    Non-finite numbers are None (a life without damage)."""
    d = result.scene.design
    ver = head.get("verdicts")
    dv = None if ver is None else ver[DESIGN_ESTIMATE]
    st = stations(result)
    per = {}
    for e in result.estimates:
        life = result.life(e)
        k = int(np.argmin(life))
        row = {"min_fatigue_life": _finite(life[k]), "min_fatigue_life_s": float(result.s[k])}
        if ver is not None:
            v = ver[e]
            row.update({"max_fatigue_utilisation": _finite(v["max_fatigue_utilisation"]),
                        "max_fatigue_utilisation_s": v["max_fatigue_utilisation_s"],
                        "stations_failing": int(np.count_nonzero(~v["fatigue_pass"])),
                        "fatigue_verdict": v["fatigue_verdict"]})
        per[e] = row
    agr = head.get("ancf")
    return {
        "scene": result.scene.name, "sea_states": len(result.states),
        "element_length": float(result.element_length),
        "design_life": d.design_life,
        "design_fatigue_factor": d.fatigue.design_fatigue_factor,
        "required_life": None if dv is None else dv["required_life"],
        "fatigue_estimate": DESIGN_ESTIMATE,
        "max_fatigue_utilisation": None if dv is None else _finite(dv["max_fatigue_utilisation"]),
        "max_fatigue_utilisation_s": None if dv is None else dv["max_fatigue_utilisation_s"],
        "min_fatigue_life": None if dv is None else _finite(dv["worst_life"]),
        "fatigue_verdict": None if dv is None else dv["fatigue_verdict"],
        "estimates": per,
        "touchdown_s": float(result.s[st["touchdown"]]) if "touchdown" in st else None,
        "touchdown_damage_per_year": _finite(head["touchdown_rainflow"]),
        "hang_off_damage_per_year": _finite(
            float(result.per_year[DESIGN_ESTIMATE][st["hang_off"]])),
        "ancf_agreement_verdict": None if agr is None else agr["verdict"],
        "cells_time_domain": sum(1 for st in result.states if "rainflow_vfife" in st.rates),
        "cells_ancf": sum(1 for st in result.states if fatigue_ancf(st)),
        "screen_share": None if result.screening is None else result.screening["share"],
        "record_length": result.scene.design.fatigue.record_length,
        "record_length_convergence": convergence(result) or None}


def fatigue_ancf(st) -> bool:
    return ANCF in st.rates


def write_summary(result: ScatterFatigue, head: dict, out: Path) -> dict:
    """Write ``summary.json`` (:func:`summary`) into ``out``; returns it."""
    from riser.design.verdicts import with_verdicts
    sm = with_verdicts(summary(result, head))          # design_fails: the fatigue check
    (Path(out) / "summary.json").write_text(json.dumps(sm, indent=2) + "\n")
    return sm


def console_lines(result: ScatterFatigue, head: dict) -> list[str]:
    """The verdict's console lines: the design's (:data:`.fatigue.DESIGN_ESTIMATE`) worst
    station and verdict, the other estimates' worst stations beside; without a
    design_life the one line saying there is no verdict."""
    ver = head.get("verdicts")
    if ver is None:
        return ["no design_life: no fatigue verdict ([design] design_life [years], with "
                "[design.fatigue] design_fatigue_factor, gives one)"]
    d = result.scene.design
    dff = d.fatigue.design_fatigue_factor
    lines = [f"{verdict_line(ver[DESIGN_ESTIMATE], d.design_life, dff)} "
             f"[{TITLES[DESIGN_ESTIMATE]}: the design's estimate]"]
    others = [f"{TITLES[e]} {ver[e]['max_fatigue_utilisation']:.3g} at s = "
              f"{ver[e]['max_fatigue_utilisation_s']:.1f} m ({ver[e]['fatigue_verdict']})"
              for e in result.estimates if e != DESIGN_ESTIMATE]
    if others:
        lines.append("the other estimates' largest fatigue utilisation: " + "; ".join(others))
    return lines


def _plot(result: ScatterFatigue, path: Path) -> None:
    fig, axes = new_figure(1, 2, size=(12.0, 4.8))
    st = stations(result)
    td = result.s[st["touchdown"]]
    styles = ("-", (0, (1, 1)), "--", "-.", ":") if ANCF in result.per_year else \
        ("-", "--", "-.", ":")
    for e, style in zip(result.estimates, styles):
        life = result.life(e)
        axes[0, 0].semilogy(result.s, life, linestyle=style, label=TITLES[e])
        near = (result.s > td - 60.0) & (result.s < td + 120.0)
        axes[0, 1].semilogy(result.s[near], life[near], linestyle=style, label=TITLES[e])
    axes[0, 0].set_title("fatigue life along the line")
    axes[0, 1].set_title("the touchdown zone")
    for ax in axes[0]:
        ax.set_xlabel("s from the anchor [m]")
        ax.set_ylabel("life [years]")
    axes[0, 1].legend(fontsize=8)
    save(fig, path)


def verdict_section(result: ScatterFatigue, ver: dict | None) -> list:
    """report.md's fatigue verdict (:func:`.fatigue.verdicts`): the criterion with its
    reference, the design's verdict and each estimate's worst station; one line without
    a design_life."""
    head = ["## Fatigue verdict", ""]
    if ver is None:
        return head + ["No `design_life`: no fatigue verdict (`[design] design_life` "
                       "[years] gives one, with `[design.fatigue] design_fatigue_factor`).",
                       ""]
    d = result.scene.design
    dff = d.fatigue.design_fatigue_factor
    dv = ver[DESIGN_ESTIMATE]
    rows = [(TITLES[e] + (" (the design's)" if e == DESIGN_ESTIMATE else ""),
             f"{v['max_fatigue_utilisation_s']:.1f}", f"{v['worst_life']:.4g}",
             f"{v['max_fatigue_utilisation']:.4g}",
             f"{int(np.count_nonzero(~v['fatigue_pass']))} of {len(v['fatigue_pass'])}",
             v["fatigue_verdict"]) for e, v in ver.items()]
    life, u = dv["worst_life"], dv["max_fatigue_utilisation"]
    where = ("no fatigue damage along the line" if math.isinf(life) else
             f"at s = {dv['max_fatigue_utilisation_s']:.1f} m the life {life:.4g} years "
             f"{'>=' if u <= 1.0 else '<'} the required {dv['required_life']:.4g} years, "
             f"fatigue utilisation {u:.4g}")
    return head + [
        f"**Verdict: {dv['fatigue_verdict']}** ({TITLES[DESIGN_ESTIMATE]}, the design's "
        f"estimate): {where}.", "",
        "The fatigue utilisation DFF x design_life / life at every station, at most 1 to "
        f"pass (DNV-OS-F201 Sec. 5 D 500, DNV-RP-F204: the damage over the design life "
        f"times the DFF at most 1): design life {d.design_life:g} years, DFF {dff:g}, "
        f"the required life {dv['required_life']:.4g} years. The verdict is the VFIFE's "
        "rainflow (the nonlinear time domain); the other estimates beside it, each at its "
        "own worst station.", "",
        md_table(["estimate", "worst s [m]", "life there [years]", "fatigue utilisation",
                  "stations failing", "verdict"], rows), ""]


def _report(result, ss: pd.DataFrame, tab: pd.DataFrame, path: Path, note: str,
            seconds: float, ver: dict | None = None) -> None:
    sc = result.scene
    fat = sc.design.fatigue
    head = tab.set_index("estimate")
    rows = [(TITLES[e], f"{r.touchdown_damage_per_year:.4g}",
             f"{r.touchdown_ratio:.3g}", f"{r.own_worst_damage_per_year:.4g} at "
             f"{r.own_worst_s:.1f} m", f"{r.hang_off_damage_per_year:.4g}",
             f"{r.hang_off_ratio:.3g}") for e, r in head.iterrows()]
    srows = [(f"{r.hs:g}", f"{r.tp:g}", f"{r.probability:g}", _f(r.record_s, ".1f"),
              _f(r.rainflow_vfife_touchdown_damage_per_year, ".4g"),
              _f(r.dirlik_fd_touchdown_damage_per_year, ".4g"),
              (f"{r.rainflow_vfife_own_worst_rate * SECONDS_PER_YEAR:.4g} at "
               f"{r.rainflow_vfife_own_worst_s:.1f} m"
               if _ok(r.rainflow_vfife_own_worst_rate) else "-"),
              _f(r.dirlik_fd_touchdown_rate / r.rainflow_vfife_touchdown_rate, ".3g"),
              _f(r.rainflow_fd_touchdown_rate / r.rainflow_vfife_touchdown_rate, ".3g"),
              _f(r.dirlik_fd_touchdown_rate / r.rainflow_fd_touchdown_rate, ".3g"),
              _f(r.dirlik_fd_hang_off_rate / r.rainflow_vfife_hang_off_rate, ".3g"),
              _f(r.touchdown_range_m, ".1f"), _f(r.vfife_max_utilisation, ".4f"),
              _f(r.fd_max_utilisation, ".4f"),
              timed(r.wall_s, ".0f", "")) for r in ss.itertuples()]
    total = ("**sum**" + (" (VFIFE: the cells it ran)" if result.screened else ""), "",
             f"{ss.probability.sum():g}", "",
             f"**{ss.rainflow_vfife_touchdown_damage_per_year.sum():.4g}**",
             f"**{ss.dirlik_fd_touchdown_damage_per_year.sum():.4g}**",
             *[""] * (len(srows[0]) - 6))
    td = head.loc["rainflow_vfife", "touchdown_s"]
    sp = sc.waves.spectrum
    text = [
        f"# Fatigue by two methods: {sc.name}", "", GENERATED_NOTE, "",
        f"{sc.title}. DNV-RP-C203 curve {fat.sn_curve} ({fat.environment}), SCF {fat.scf:g}, "
        f"{fat.points} points around the outer fibre (each station's worst), the wall's "
        f"thickness correction; VFIFE at {result.element_length:g} m elements. Each sea state "
        f"of the scatter diagram is the scene's {_KIND.get(sp.kind, sp.kind)} spectrum at "
        f"its Hs and Tp ({sp.components} components, "
        + (f"heading {sp.heading_deg:g} deg from the line's plane, "
           if sp.heading_deg % 360.0 else "")
        + (f"seed {sp.seed}" if not any(st.seeds for st in result.states) else
           f"each cell's realisations their own seeds, from the scene's seed {sp.seed}, the "
           "cell's Hs and Tp") + "); the VFIFE runs a "
        "ramp, a settling time and then one repeat period of the sea (`compare --dynamics`); the frequency domain (FD) solves "
        "the same components about the BVP's static state, the drag linearised "
        "stochastically.", "",
        *verdict_section(result, ver),
        "## Damage per year over the scatter diagram", "",
        f"At the touchdown (the VFIFE's worst station in the touchdown zone, s = {td:.1f} m) "
        "and at the hang-off; each estimate's own worst station in the zone beside. Ratios "
        "are to the VFIFE's rainflow.", "",
        md_table(["estimate", "touchdown damage/yr", "ratio", "own worst in the zone",
                  "hang-off damage/yr", "ratio"], rows), "",
        "## Per sea state", "",
        f"At the headline's touchdown station (s = {td:.1f} m) and hang-off: each sea "
        "state's share of the damage per year (its probability x its damage rate x a "
        "year), so that the shares add up to the headline's damage per year (the sum "
        "row); beside them the sea state's own worst VFIFE station in its touchdown zone "
        "(damage per year as if the sea state lasted the whole year, at its own s: these "
        "do not add up). Ratios are at the headline's station: Dirlik (FD) over "
        "rainflow (VFIFE) at the touchdown, split into the response model (the FD's linear "
        "record of the same realisation counted by rainflow, over the VFIFE's) and the "
        "spectral estimator (Dirlik over the FD record's rainflow); the same ratio at the "
        "hang-off; the touchdown's travel in the VFIFE run; the largest dynamic utilisation "
        "(DNV, functional = static, environmental = dynamic): the VFIFE's over its record, "
        "the FD's from the most probable maxima of tension and moment over the same "
        "duration, combined in phase (an upper bound).", "",
        md_table(["Hs [m]", "Tp [s]", "probability", "record [s]",
                  "VFIFE rainflow share /yr", "FD Dirlik share /yr",
                  "VFIFE own worst /yr (whole year in it)", "Dirlik / VFIFE", "model: FD / VFIFE rainflow",
                  "estimator: Dirlik / FD rainflow", "hang-off Dirlik / VFIFE",
                  "touchdown travel [m]", "VFIFE max utilisation", "FD max utilisation",
                  "wall [s]"], srows + [total]), "",
        "![fatigue life](fatigue.png)", "",
        *cells_section(result, ss), *record_section(result),
        *ancf_section(result, ss, head), reading(head), "",
        "Files: `stations.csv`, `sea_states.csv`, `fatigue_along_s.csv`. Run in "
        f"{timed(seconds, '.0f')}" + (f" ({note})" if note else "") + ".", ""]
    path.write_text("\n".join(text))


def ancf_section(result: ScatterFatigue, ss: pd.DataFrame, head: pd.DataFrame) -> list:
    """The two nonlinear time domains at the touchdown (:func:`.fatigue.ancf_agreement`):
    per sea state and in total the VFIFE's and the ANCF's damage per year at the
    headline's station, their ratio, the verdict; the FD's ratio to each; the ANCF's
    runs (none without the ANCF's column)."""
    agr = ancf_agreement(result)
    if agr is None:
        return []
    tol = agr["tolerance"]

    def judged(ratio):
        return "pass" if abs(ratio - 1.0) <= tol else "fail"
    rows = []
    by_cell = list(ss.itertuples())
    for a in agr["rows"]:
        r = by_cell[a["cell"]]
        fd = r.rainflow_fd_touchdown_damage_per_year
        rows.append((f"{r.hs:g}", f"{r.tp:g}", f"{a['vfife']:.4g}", f"{a['ancf']:.4g}",
                     f"{a['ratio']:.3f}", f"{a['own_ratio']:.3f}", judged(a["ratio"]),
                     f"{fd / a['vfife']:.3g}", f"{fd / a['ancf']:.3g}",
                     f"{r.touchdown_range_m:.1f}", f"{r.ancf_touchdown_range_m:.1f}",
                     f"{r.ancf_element_length:g} / {r.ancf_time_step:.3g}",
                     timed(r.ancf_wall_s, ".0f", "")))
    tt = agr["total"]
    rs = [by_cell[a["cell"]] for a in agr["rows"]]
    fd = (head.loc["rainflow_fd", "touchdown_damage_per_year"] if not result.screened
          else float(sum(r.rainflow_fd_touchdown_damage_per_year for r in rs)))
    rows.append(("**total**" + (f" ({len(rs)} cells)" if result.screened else ""), "", f"**{tt['vfife']:.4g}**", f"**{tt['ancf']:.4g}**",
                 f"**{tt['ratio']:.3f}**", f"{tt['own_ratio']:.3f}", judged(tt["ratio"]),
                 f"{fd / tt['vfife']:.3g}", f"{fd / tt['ancf']:.3g}", "", "", "", ""))
    return [
        "## Two nonlinear time domains at the touchdown: VFIFE against ANCF", "",
        f"**Verdict: {agr['verdict']}** (the touchdown's damage ANCF / VFIFE within "
        f"{100 * tol:.0f} % at each sea state and in total; the largest difference "
        f"{100 * (agr['worst_ratio'] - 1.0):+.1f} %). The ANCF (Liu et al.'s element, its "
        "own statics and implicit generalised-alpha time domain) runs exactly the VFIFE's "
        "scene of each sea state: the same realisation, ramp, settling and record, at the "
        "same element length, its time step the sea's shortest component period / "
        f"{ANCF_STEPS_PER_SHORTEST} (one step per sample of the recorder; the peak period "
        "/ 140 or finer); its stress record is counted by the same recorder and rainflow. "
        f"Damage per year at the headline's touchdown station (s = {agr['s']:.1f} m): "
        "each sea state's share and the total (judged); each method's own worst "
        "station in the zone beside (reported). A bound of 10 % on damage is 2-3 % on "
        "the stress range (damage goes as its 3rd to 5th power).", "",
        md_table(["Hs [m]", "Tp [s]", "VFIFE share /yr", "ANCF share /yr", "ANCF / VFIFE",
                  "own worst ANCF / VFIFE", "verdict", "FD rainflow / VFIFE",
                  "FD rainflow / ANCF", "travel VFIFE [m]", "travel ANCF [m]",
                  "ANCF element [m] / step [s]", "ANCF wall [s]"], rows), "",
        fd_reading(pd.DataFrame(rs), agr, fd), ""]


def fd_reading(ss: pd.DataFrame, agr: dict, fd_total: float) -> str:
    """The FD's linear record against both time domains at the touchdown, with the
    touchdown's travel: the figures, and what they say (worded from them); ``ss``: the
    rows of ``sea_states.csv`` of the cells the ANCF ran, in the order of its rows."""
    per = [r.rainflow_fd_touchdown_damage_per_year / a["vfife"]
           for r, a in zip(ss.itertuples(), agr["rows"])]
    travel = list(ss.touchdown_range_m)
    order = np.argsort(travel)
    grows = bool(np.all(np.diff(np.asarray(per)[order]) > 0.0))
    tt = agr["total"]
    text = ("The frequency domain against both time domains at the touchdown: its linear "
            "record of the same realisation, rainflow-counted alike, is "
            f"x{fd_total / tt['vfife']:.3g} the VFIFE's and x{fd_total / tt['ancf']:.3g} "
            "the ANCF's in total; per sea state (Hs "
            + ", ".join(f"{h:g}" for h in ss.hs) + " m) x"
            + ", x".join(f"{x:.3g}" for x in per) + " the VFIFE's, the touchdown "
            "travelling " + ", ".join(f"{x:.1f}" for x in travel) + " m in the VFIFE ("
            + ", ".join(f"{x:.1f}" for x in ss.ancf_touchdown_range_m) + " m in the ANCF). "
            "The FD linearises about the static state: its touchdown stays at the static "
            "point and the dynamic bending gathers there, while in a time domain the "
            "touchdown travels along the seabed and spreads the bending over the travel")
    text += (", so the ratio grows with the travel (the larger seas). " if grows else ". ")
    if agr["verdict"] == "pass":
        text += ("The two nonlinear methods, each with its own elements, time integration "
                 "and seabed contact (the VFIFE's at the nodes, the ANCF's at the Gauss "
                 "points), agree with each other within the tolerance"
                 + (" where the linear model does not: the FD's excess is its "
                    "linearisation, not either time domain." if abs(fd_total / tt["vfife"] - 1.0)
                    > agr["tolerance"] else "."))
    else:
        text += ("The two nonlinear methods differ by more than the tolerance (the table): "
                 "the touchdown's fatigue is not settled by them here.")
    return text


def reading(head: pd.DataFrame) -> str:
    """The paragraph that splits the ratios into the response model and the estimator,
    with the measured figures."""
    td = {e: head.loc[e, "touchdown_damage_per_year"] for e in ESTIMATES}
    ho = {e: head.loc[e, "hang_off_damage_per_year"] for e in ESTIMATES}
    return (
        "Reading it: the FD's own record of the same realisation, rainflow-counted as the "
        "VFIFE's is, differs from the VFIFE's only by the response model (the "
        "linearisation); Dirlik differs from that record only by the spectral estimator "
        "(and the one realisation's sampling: a record of a few tens of cycles). At the "
        f"touchdown Dirlik / VFIFE = {td['dirlik_fd'] / td['rainflow_vfife']:.3g} = model "
        f"{td['rainflow_fd'] / td['rainflow_vfife']:.3g} x estimator "
        f"{td['dirlik_fd'] / td['rainflow_fd']:.3g}; at the hang-off "
        f"{ho['dirlik_fd'] / ho['rainflow_vfife']:.3g} = model "
        f"{ho['rainflow_fd'] / ho['rainflow_vfife']:.3g} x estimator "
        f"{ho['dirlik_fd'] / ho['rainflow_fd']:.3g}. The linear model keeps the touchdown "
        "where the static state has it, so the dynamic bending gathers at that point "
        "(the FD's curvature standard deviation peaks there), while in the time domain the "
        "touchdown travels along the seabed (the travel column) and spreads the bending: "
        "a touchdown's fatigue rests on the time domain.")


def _ok(x) -> bool:
    return x is not None and math.isfinite(float(x))


def _f(x, spec: str) -> str:
    """``x`` formatted, or '-' (not run: NaN, None)."""
    return format(float(x), spec) if _ok(x) else "-"


def _at(result: ScatterFatigue, values, station: str) -> float:
    return float(values[stations(result)[station]])


def cells_section(result: ScatterFatigue, ss: pd.DataFrame) -> list:
    """report.md's cells and methods (a screened run, or cells of several realisations):
    the screening's choice, how each estimate's total is formed, and per cell its FD
    shares at the governing stations, the methods it ran, its realisations and record and
    the ratios of the time domains to the FD (:func:`.fatigue.damage_per_year`)."""
    if not result.screened or result.screening is None:
        return []
    scr = result.screening
    n = len(result.states)
    td_cells = [k for k, st in enumerate(result.states) if "rainflow_vfife" in st.rates]
    ancf_cells = [k for k, st in enumerate(result.states) if ANCF in st.rates]
    st_ = scr["stations"]
    if scr["share"] is None:
        how = (f"Every one of the {n} cells ran in the time domains (`--all`)"
               + (f", the ANCF on {len(ancf_cells)}" if ANCF in result.per_year else "") + ".")
    else:
        how = (f"The frequency domain (FD) ran on every one of the {n} cells. At the "
               f"governing stations, the FD's worst in the touchdown zone (s = "
               f"{st_['touchdown']:.1f} m) and the hang-off (s = {st_['hang_off']:.1f} m), the "
               "cells were taken in order of their share of the FD's (Dirlik's) damage per "
               f"year until they carried {100 * scr['share']:g} % of it at each: "
               f"{len(td_cells)} cells ran in the time domains (the VFIFE, with the FD's "
               "linear record of the same realisations)"
               + (f", the ANCF on {len(ancf_cells)} of them (the largest FD shares at the "
                  "touchdown; its first realisation, judged against the VFIFE's same one)"
                  if ANCF in result.per_year else "") + ".")
    formed = result.formed.get("rainflow_vfife", {})
    lines = ["## Cells and methods", "", how, ""]
    if formed.get("rest"):
        v = result.per_year["rainflow_vfife"]
        own = sum(result.states[k].probability * np.interp(
            result.s, result.states[k].s, result.states[k].rates["rainflow_vfife"])
            for k in formed["run"]) * SECONDS_PER_YEAR
        as_is = formed["fd_as_is"]
        lines += [
            "How the totals are formed: an estimate's damage per year is its own over the "
            "cells it ran plus, for each cell it did not run, that cell's FD (Dirlik) "
            "damage scaled at every station by the estimate's ratio to Dirlik over the "
            "cells it ran (the time domain's correction of the linear model, carried to "
            "the cells left out; docs/design.md). The cells the VFIFE ran carry "
            f"{100 * _at(result, own, 'touchdown') / _at(result, v, 'touchdown'):.1f} % of its "
            f"total at the touchdown and "
            f"{100 * _at(result, own, 'hang_off') / _at(result, v, 'hang_off'):.1f} % at the "
            "hang-off; counting the cells left out by their FD damage as it is instead "
            f"gives {_at(result, as_is, 'touchdown'):.4g} a year at the touchdown (x"
            f"{_at(result, as_is, 'touchdown') / _at(result, v, 'touchdown'):.3g} the "
            f"scaled total) and {_at(result, as_is, 'hang_off'):.4g} at the hang-off (x"
            f"{_at(result, as_is, 'hang_off') / _at(result, v, 'hang_off'):.3g}).", ""]
    rows = []
    for k, (st, r) in enumerate(zip(result.states, ss.itertuples())):
        ratio_td = r.rainflow_vfife_touchdown_rate / r.dirlik_fd_touchdown_rate
        ratio_ho = r.rainflow_vfife_hang_off_rate / r.dirlik_fd_hang_off_rate
        ancf = "-"
        if ANCF in st.rates:                     # on the records the ANCF ran
            s_td = float(result.s[stations(result)["touchdown"]])
            vf = st.pair_rates.get("rainflow_vfife", st.rates["rainflow_vfife"])
            ancf = (f"{np.interp(s_td, st.s, st.rates[ANCF]) / np.interp(s_td, st.s, vf):.3f}"
                    + (" (first realisation)" if st.pair_rates else ""))
        rows.append((str(k + 1), f"{st.hs:g}", f"{st.tp:g}", f"{st.probability:.4g}",
                     f"{100 * scr['shares']['touchdown'][k]:.2f}",
                     f"{100 * scr['shares']['hang_off'][k]:.2f}",
                     r.methods, str(r.realisations) if r.realisations else "-",
                     _f(r.record_s, ".0f"), _f(ratio_td, ".3g"), _f(ratio_ho, ".3g"), ancf))
    lines += [
        "Per cell: its share of the FD's damage per year at the two stations, the methods "
        "it ran, its realisations and time-domain record, and the time domain against the "
        "FD at the headline's stations (VFIFE rainflow / Dirlik: the correction the cells "
        "left to the FD get; ANCF / VFIFE at the touchdown).", "",
        md_table(["cell", "Hs [m]", "Tp [s]", "probability", "FD share touchdown [%]",
                  "FD share hang-off [%]", "methods", "realisations", "record [s]",
                  "VFIFE / Dirlik touchdown", "VFIFE / Dirlik hang-off",
                  "ANCF / VFIFE touchdown"], rows), ""]
    return lines


def convergence(result: ScatterFatigue) -> dict:
    """The damage per year with the first half of every cell's realisations over that
    with all of them, per record estimate at the touchdown and the hang-off (empty with
    one realisation a cell)."""
    out = {}
    for e, half in result.half_per_year.items():
        full = result.per_year[e]
        out[e] = {name: {"half": _at(result, half, name), "whole": _at(result, full, name),
                         "ratio": _at(result, half, name) / _at(result, full, name)}
                  for name in ("touchdown", "hang_off")}
    return out


def record_section(result: ScatterFatigue) -> list:
    """report.md's convergence with record length (``[design.fatigue] record_length``)."""
    if not result.screened:
        return []
    length = result.scene.design.fatigue.record_length
    td = [st for st in result.states if st.comparison is not None]
    counts = sorted({max(1, len(st.seeds)) for st in td})
    head = ["## Record length", ""]
    if length is None:
        return head + ["One repeat period of the sea a cell, the scene's seed "
                       "(`[design.fatigue] record_length` gives each cell realisations of "
                       "its own and the convergence with record length).", ""]
    records = [st.record_s for st in td]
    text = (f"`record_length` = {length:g} s: each cell ran {counts[0]}"
            + (f" to {counts[-1]}" if len(counts) > 1 else "") + " realisation(s) of one "
            "repeat period of its sea, each after its own ramp and settling, each with its "
            "own seed (from the scene's, the cell's Hs and Tp and the realisation); records "
            f"{min(records):.0f} to {max(records):.0f} s a cell.")
    conv = convergence(result)
    if not conv:
        return head + [text + " With one realisation a cell there is no second record "
                       "length to compare.", ""]
    rows = [(TITLES[e], name.replace("_", "-"), f"{c['half']:.4g}", f"{c['whole']:.4g}",
             f"{c['ratio']:.3f}") for e, by in conv.items() for name, c in by.items()]
    return head + [
        text + " The damage per year from the first half of every cell's realisations "
        "(ceil(n / 2)) against all of them, formed alike (the cells left to the FD scaled "
        "by the ratio of each):", "",
        md_table(["estimate", "station", "damage/yr, half the record",
                  "damage/yr, whole record", "half / whole"], rows), ""]


def run_lines(result: ScatterFatigue) -> list[str]:
    """The console lines of a run: where the units ran, which cells each method ran, the
    convergence with record length."""
    run = result.run
    n = len(result.states)
    td = sum(1 for st in result.states if "rainflow_vfife" in st.rates)
    an = sum(1 for st in result.states if ANCF in st.rates)
    lines = []
    if run:
        lines.append(f"{run['units']} unit(s) on {run['engine']}, {run['wall_s']:.0f} s")
    lines.append(f"cells: {n} by the frequency domain, {td} by the VFIFE (and the FD's "
                 f"record)" + (f", {an} by the ANCF" if an else "")
                 + ("" if td == n else "; the others' damage: their FD's, scaled by the "
                    "ratio of each estimate to it over the cells it ran (report.md)"))
    for e, by in convergence(result).items():
        lines.append(f"record length: {TITLES[e]}: damage with half the record / the whole "
                     f"{by['touchdown']['ratio']:.3f} at the touchdown, "
                     f"{by['hang_off']['ratio']:.3f} at the hang-off")
    return lines

"""The files of a scatter diagram's fatigue (:mod:`.fatigue`): ``fatigue_along_s.csv``
(s [m], per estimate the damage per year [1/year] and the life [years]),
``sea_states.csv`` (per sea state and estimate: the damage rate [1/s] and the share of
the damage per year [1/year] (probability x rate x a year) at the headline's touchdown
station and at the hang-off, the shares summing over the sea states to the headline's
damage per year; the estimate's own worst station in the touchdown zone and its rate;
the record, the wall time, the VFIFE's largest dynamic utilisation), ``stations.csv`` (the headline: damage per year at
the touchdown and the hang-off by each estimate, the ratios to the VFIFE's rainflow),
``fatigue.png``, ``report.md``."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from riser.design.fatigue import SECONDS_PER_YEAR
from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, md_table, timed

from .fatigue import (ESTIMATES, TOUCHDOWN_ZONE, ScatterFatigue, fd_utilisation, stations,
                      worst_in_zone)

#: the spectrum's name in the report
_KIND = {"jonswap": "JONSWAP", "pierson-moskowitz": "Pierson-Moskowitz"}
#: what each estimate is, for the report
TITLES = {"rainflow_vfife": "VFIFE time domain, rainflow",
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
    for e in ESTIMATES:
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
    interpolation of :func:`.fatigue.run_scatter`: the shares add up to the headline),
    and the estimate's own worst station in this sea state's touchdown zone."""
    rows = []
    head = stations(result)
    s_td, s_ho = float(result.s[head["touchdown"]]), float(result.s[head["hang_off"]])
    for st in result.states:
        cmp = st.comparison
        info = cmp.vfife_result.info
        u_fd, u_fd_s = fd_utilisation(cmp, st.record_s)
        row = {"hs": st.hs, "tp": st.tp, "probability": st.probability,
               "record_s": st.record_s, "ramp_s": cmp.ramp_s, "settle_s": cmp.settle_s,
               "element_length": cmp.element_length, "fd_wall_s": cmp.fd_wall_s,
               "vfife_wall_s": cmp.vfife_wall_s, "wall_s": st.wall_s,
               "hang_off_tension_std_fd": float(cmp.fd.std["tension"][-1]),
               "hang_off_tension_std_vfife": cmp.vf["std"],
               "vfife_max_utilisation": info.get("dynamic_max_utilisation"),
               "vfife_max_utilisation_s": info.get("dynamic_max_utilisation_s"),
               "fd_max_utilisation": u_fd, "fd_max_utilisation_s": u_fd_s,
               "touchdown_range_m": (info.get("dynamic_max_touchdown_s", np.nan)
                                     - info.get("dynamic_min_touchdown_s", np.nan))}
        row["touchdown_s"], row["hang_off_s"] = s_td, s_ho
        share = st.probability * SECONDS_PER_YEAR
        for e in ESTIMATES:
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


def write(result: ScatterFatigue, out: Path, note: str = "", seconds: float = 0.0) -> dict:
    """Write the files into ``out``; returns the headline figures."""
    out.mkdir(parents=True, exist_ok=True)
    cols = {"s": result.s}
    for e in ESTIMATES:
        cols[f"{e}_damage_per_year"] = result.per_year[e]
        cols[f"{e}_life_years"] = result.life(e)
    pd.DataFrame(cols).to_csv(out / "fatigue_along_s.csv", index=False, float_format="%.10g")
    ss = sea_state_table(result)
    ss.to_csv(out / "sea_states.csv", index=False, float_format="%.10g")
    tab = station_table(result)
    tab.to_csv(out / "stations.csv", index=False, float_format="%.10g")
    _plot(result, out / "fatigue.png")
    _report(result, ss, tab, out / "report.md", note, seconds)
    d = tab.set_index("estimate")
    return {"touchdown_s": d.loc["rainflow_vfife", "touchdown_s"],
            "touchdown_rainflow": d.loc["rainflow_vfife", "touchdown_damage_per_year"],
            "touchdown_dirlik": d.loc["dirlik_fd", "touchdown_damage_per_year"],
            "ratio": d.loc["dirlik_fd", "touchdown_ratio"],
            "hang_off_ratio": d.loc["dirlik_fd", "hang_off_ratio"],
            "record_s": float(ss.record_s.iloc[0])}


def _plot(result: ScatterFatigue, path: Path) -> None:
    fig, axes = new_figure(1, 2, size=(12.0, 4.8))
    st = stations(result)
    td = result.s[st["touchdown"]]
    for e, style in zip(ESTIMATES, ("-", "--", "-.", ":")):
        life = result.life(e)
        axes[0, 0].semilogy(result.s, life, style, label=TITLES[e])
        near = (result.s > td - 60.0) & (result.s < td + 120.0)
        axes[0, 1].semilogy(result.s[near], life[near], style, label=TITLES[e])
    axes[0, 0].set_title("fatigue life along the line")
    axes[0, 1].set_title("the touchdown zone")
    for ax in axes[0]:
        ax.set_xlabel("s from the anchor [m]")
        ax.set_ylabel("life [years]")
    axes[0, 1].legend(fontsize=8)
    save(fig, path)


def _report(result, ss: pd.DataFrame, tab: pd.DataFrame, path: Path, note: str,
            seconds: float) -> None:
    sc = result.scene
    fat = sc.design.fatigue
    head = tab.set_index("estimate")
    rows = [(TITLES[e], f"{r.touchdown_damage_per_year:.4g}",
             f"{r.touchdown_ratio:.3g}", f"{r.own_worst_damage_per_year:.4g} at "
             f"{r.own_worst_s:.1f} m", f"{r.hang_off_damage_per_year:.4g}",
             f"{r.hang_off_ratio:.3g}") for e, r in head.iterrows()]
    srows = [(f"{r.hs:g}", f"{r.tp:g}", f"{r.probability:g}", f"{r.record_s:.1f}",
              f"{r.rainflow_vfife_touchdown_damage_per_year:.4g}",
              f"{r.dirlik_fd_touchdown_damage_per_year:.4g}",
              f"{r.rainflow_vfife_own_worst_rate * SECONDS_PER_YEAR:.4g} at "
              f"{r.rainflow_vfife_own_worst_s:.1f} m",
              f"{r.dirlik_fd_touchdown_rate / r.rainflow_vfife_touchdown_rate:.3g}",
              f"{r.rainflow_fd_touchdown_rate / r.rainflow_vfife_touchdown_rate:.3g}",
              f"{r.dirlik_fd_touchdown_rate / r.rainflow_fd_touchdown_rate:.3g}",
              f"{r.dirlik_fd_hang_off_rate / r.rainflow_vfife_hang_off_rate:.3g}",
              f"{r.touchdown_range_m:.1f}", f"{r.vfife_max_utilisation:.4f}",
              f"{r.fd_max_utilisation:.4f}",
              timed(r.wall_s, ".0f", "")) for r in ss.itertuples()]
    total = ("**sum**", "", f"{ss.probability.sum():g}", "",
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
        f"its Hs and Tp ({sp.components} components, seed {sp.seed}); the VFIFE runs a "
        "ramp, a settling time and then one repeat period of the sea (`compare --dynamics`); the frequency domain (FD) solves "
        "the same components about the BVP's static state, the drag linearised "
        "stochastically.", "",
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
        reading(head), "",
        "Files: `stations.csv`, `sea_states.csv`, `fatigue_along_s.csv`. Run in "
        f"{timed(seconds, '.0f')}" + (f" ({note})" if note else "") + ".", ""]
    path.write_text("\n".join(text))


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

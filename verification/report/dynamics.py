"""The plots and the console summary of a VFIFE dynamic run (``riser-verify solve`` of a
scene with ``[dynamics]``): ``timeseries.png`` and ``envelope.png`` beside the CSV files.

Units in the figures: kN, kN m, m, s; the console lines choose mN to MN to keep three
significant digits (the files hold SI: N, N m).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from riser.results.result import DynamicsResult

from .figures import add_panel_below, new_figure, plan_view, save
from .units import with_unit

#: the figures written beside timeseries.csv and envelope.csv
FILES = ("timeseries.png", "envelope.png")
#: on a grounded line the minimum tension's place is drawn only where it is this fraction
#: of the hang-off tension below the touchdown's tension: a plot resolves ~1e-3 of its
#: axis, and on the seabed (uniform tension without friction, falling to the anchor with
#: it) the lowest node is round-off or the anchor, not a station of the response
BELOW_TOUCHDOWN = 1.0e-4
#: the label of the minimum tension's place on a grounded line
SUSPENDED_LABEL = "minimum tension, where in the suspended part (else not drawn)"


def suspended_min_tension_s(ts) -> np.ndarray | None:
    """The time series' ``min_tension_s`` [m] where the minimum lies in the suspended
    part of a grounded line (above the touchdown, and below the touchdown's tension by
    :data:`BELOW_TOUCHDOWN` of the hang-off tension), NaN elsewhere; None when the line
    never touches the seabed (the whole line's minimum is then a station of its own)."""
    td = np.asarray(ts["touchdown_s"], float)
    if not np.any(np.isfinite(td)):
        return None
    s_min = np.asarray(ts["min_tension_s"], float)
    t_min = np.asarray(ts["min_tension"], float)
    t_td = np.asarray(ts["touchdown_tension"], float)
    margin = BELOW_TOUCHDOWN * np.nanmax(np.abs(np.asarray(ts["hang_off_tension"], float)))
    with np.errstate(invalid="ignore"):
        keep = ~np.isfinite(td) | ((s_min > td) & (t_min < t_td - margin))
    return np.where(keep, s_min, np.nan)


def write_plots(dyn: DynamicsResult, out: Path, title: str, start: float,
                plan=None) -> None:
    """Time series (hang-off tension, touchdown, minimum tension, peak moment, hang-off
    position) and envelopes along s into ``out``; ``start`` [s] marks the statistics
    window's start. ``plan``: the static profile of a 3D line, whose plan view (x-z) the
    envelopes' figure adds below them (:func:`plan_lines`); None for a planar one."""
    ts, env = dyn.timeseries, dyn.envelope
    t = ts["time"]
    suspended = suspended_min_tension_s(ts)
    where_min = (("min_tension_s", 1.0, "minimum tension") if suspended is None else
                 (suspended, 1.0, SUSPENDED_LABEL))
    fig, ax = new_figure(3, 2, size=(11.0, 8.5))
    panels = [
        (ax[0, 0], [("hang_off_tension", 1e-3, "hang-off")], "effective tension [kN]"),
        (ax[0, 1], [("touchdown_s", 1.0, "touchdown")], "touchdown arc length s [m]"),
        (ax[1, 0], [("min_tension", 1e-3, "minimum along the line"),
                    ("touchdown_tension", 1e-3, "at the touchdown")], "effective tension [kN]"),
        (ax[1, 1], [("max_moment", 1e-3, "peak along the line")], "bending moment [kN m]"),
        (ax[2, 0], [("hang_off_x", 1.0, "x"), ("hang_off_y", 1.0, "y"),
                    ("hang_off_z", 1.0, "z")], "hang-off position - start [m]"),
        (ax[2, 1], [("max_moment_s", 1.0, "peak moment"), where_min],
         "where along the line, s [m]"),
    ]
    for a, series, label in panels:
        drawn = 0
        for key, f, name in series:
            v = np.asarray(ts[key] if isinstance(key, str) else key, float) * f
            if isinstance(key, str) and key.startswith("hang_off_") and key[-1] in "xyz":
                v = v - v[0]
            if np.any(np.isfinite(v)):
                a.plot(t, v, label=name, lw=1.0)
                drawn += 1
        if key is suspended and suspended is not None and not np.any(np.isfinite(v)):
            a.text(0.5, 0.05, "minimum tension on the seabed throughout: not drawn",
                   ha="center", va="bottom", transform=a.transAxes, fontsize=8)
        if not drawn:
            a.text(0.5, 0.5, "no seabed contact", ha="center", va="center",
                   transform=a.transAxes)
        if start > 0.0:
            a.axvline(start, color="0.5", ls="--", lw=0.8)
        a.set_xlabel("time t [s]")
        a.set_ylabel(label)
        a.grid(alpha=0.3)
        if drawn > 1 or any(not isinstance(k, str) for k, _, _ in series):
            a.legend(fontsize=8)
    fig.suptitle(f"{title}: time series (dashed: statistics start, {start:g} s)")
    save(fig, out / "timeseries.png")

    s = env["s"]
    fig, ax = new_figure(3, 1, size=(9.0, 8.5))
    ax[0, 0].fill_between(s, env["tension_min"] / 1e3, env["tension_max"] / 1e3, alpha=0.4,
                          label="min to max")
    ax[0, 0].axhline(0.0, color="k", lw=0.6)
    ax[0, 0].set_ylabel("effective tension [kN]")
    ax[1, 0].plot(s, env["moment_max"] / 1e3)
    ax[1, 0].set_ylabel("max bending moment [kN m]")
    ax[2, 0].plot(s, env["curvature_max"])
    ax[2, 0].set_ylabel("max curvature [1/m]")
    for a in ax[:, 0]:
        a.grid(alpha=0.3)
        a.set_xlabel("arc length s from the bottom end [m]")
    fig.suptitle(f"{title}: envelopes from t = {start:g} s")
    if plan is not None:
        plan_view(add_panel_below(fig, 4.0), plan_lines(plan, ts))
        fig.axes[-1].legend(fontsize=8)
    save(fig, out / "envelope.png")


def plan_lines(profile, ts) -> list:
    """The lines of a dynamic run's plan view: the static line (``profile``), the
    hang-off's track and each ``[dynamics] stations`` track (``station_K_x``,
    ``station_K_z``) over the run, (x, z, plot keywords) each."""
    lines = [(profile.x, profile.z, {"color": "k", "lw": 1.5, "label": "static line"}),
             (ts["hang_off_x"], ts["hang_off_z"], {"lw": 1.0, "label": "hang-off's track"})]
    k = 1
    while f"station_{k}_x" in ts:
        lines.append((ts[f"station_{k}_x"], ts[f"station_{k}_z"],
                      {"lw": 1.0, "label": "stations' tracks" if k == 1 else None,
                       "color": "C2"}))
        k += 1
    return lines


def fatigue_verdict_line(sm: dict, prefix: str = "") -> str:
    """The fatigue verdict's console line from a summary's keys (``design_life``,
    ``design_fatigue_factor``, ``{prefix}max_fatigue_utilisation`` and its ``_s``,
    ``{prefix}fatigue_verdict``; :func:`riser.design.fatigue.verdict_line`)."""
    from riser.design.fatigue import verdict_line
    life, dff, u = sm["design_life"], sm["design_fatigue_factor"], \
        sm[f"{prefix}max_fatigue_utilisation"]
    worst = math.inf if u == 0.0 else dff * life / u
    return verdict_line({"fatigue_verdict": sm[f"{prefix}fatigue_verdict"],
                         "max_fatigue_utilisation": u, "required_life": dff * life,
                         "max_fatigue_utilisation_s": sm[f"{prefix}max_fatigue_utilisation_s"],
                         "worst_life": worst}, life, dff)


def summary_lines(sm: dict) -> list[str]:
    """The console lines of a dynamic run's extremes (from summary.json's ``dynamic_*``
    keys), over the statistics window."""
    if "dynamic_max_hang_off_tension" not in sm:
        return []
    lines = [f"  dynamics, statistics from t = {sm['statistics_start']:g} to "
             f"{sm['statistics_end']:g} s (effects: {', '.join(sm.get('effects', []))}):",
             f"    hang-off tension {with_unit(sm['dynamic_min_hang_off_tension'], 'N')} to "
             f"{with_unit(sm['dynamic_max_hang_off_tension'], 'N')} (range "
             f"{with_unit(sm['dynamic_hang_off_tension_range'], 'N')})",
             f"    max moment {with_unit(sm['dynamic_max_moment'], 'N m')} at s = "
             f"{sm['dynamic_max_moment_s']:.1f} m (t = {sm['dynamic_max_moment_time']:.2f} s)",
             f"    min tension {with_unit(sm['dynamic_min_tension'], 'N')} "
             + (f"on the seabed (s = {sm['dynamic_min_tension_s']:.1f} m, at or below the "
                f"touchdown's {sm['dynamic_max_touchdown_s']:.1f} m)"
                if sm.get("dynamic_max_touchdown_s") is not None
                and sm["dynamic_min_tension_s"] <= sm["dynamic_max_touchdown_s"]
                else f"at s = {sm['dynamic_min_tension_s']:.1f} m")
             + f" (t = {sm['dynamic_min_tension_time']:.2f} s)"]
    if "dynamic_min_touchdown_s" in sm:
        lines.append(f"    touchdown s from {sm['dynamic_min_touchdown_s']:.1f} to "
                     f"{sm['dynamic_max_touchdown_s']:.1f} m")
    if "dynamic_max_utilisation" in sm:
        lines.append(f"    max utilisation ({sm['dynamic_design_code']}) "
                     f"{sm['dynamic_max_utilisation']:.4f} at s = "
                     f"{sm['dynamic_max_utilisation_s']:.1f} m (t = "
                     f"{sm['dynamic_max_utilisation_time']:.2f} s), von Mises "
                     f"{sm['dynamic_max_von_mises'] / 1e6:.1f} MPa")
    if "dynamic_min_fatigue_life" in sm:
        lines.append(f"    fatigue: Miner sum {sm['dynamic_max_fatigue_damage']:.3g} over the "
                     f"{sm['dynamic_fatigue_record_s']:.1f} s window at s = "
                     f"{sm['dynamic_min_fatigue_life_s']:.1f} m: life "
                     f"{sm['dynamic_min_fatigue_life']:.3g} years (the window repeated)")
    if sm.get("dynamic_fatigue_verdict") in ("pass", "fail"):
        lines.append(f"    {fatigue_verdict_line(sm, 'dynamic_')} (the window repeated)")
    lines.append(f"    {sm['dynamic_steps']} steps of {sm['dynamic_time_step']:.3g} s, "
                 f"{sm['realtime_factor']:.3g} x real time")
    return lines

"""Design checks (``riser-verify reproduce design``, issue 34): :mod:`.utilisation` (the
static DNV-ST-F201 utilisation along a steel catenary and a steel lazy wave by both
methods) and :mod:`.fatigue` with :mod:`.fatigue_report` (fatigue over a scatter diagram
by the two time domains' rainflow, the VFIFE's and the ANCF's (issue 47: judged against
each other at the touchdown), and the frequency domain's record and spectral estimates,
scr-steel-fatigue at the touchdown and the hang-off; and the same in seas 45 and 90 deg
off the line's plane, issue 50)."""

from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

from verification.catalog import resolve

from ..study import Study
from . import fatigue, fatigue_report, fatigue_scatter, utilisation

#: the fatigue in a sea off the line's plane (issue 50): unit -> the sea's heading [deg]
#: from the line's plane, on :data:`OBLIQUE_SCENE`
OBLIQUE = {"fatigue-45": 45.0, "fatigue-90": 90.0}
#: the units of the study, each a folder of reports/design/
UNITS = ("utilisation", "fatigue", *OBLIQUE)
#: the fatigue study's scene and the VFIFE's element length there [m]: 2 m, 0.6 of the
#: bending length at the touchdown; at 1 m the curvature's standard deviation there moves
#: by 0.8 % (measured: 4.754e-4 against 4.791e-4 1/m, Hs 3 m)
FATIGUE_SCENE = "scr-steel-fatigue"
FATIGUE_ELEMENT_LENGTH = 2.0
#: the scene of the oblique seas: FATIGUE_SCENE with RAOs at 0, 45 and 90 deg
OBLIQUE_SCENE = "scr-steel-fatigue-oblique"


def oblique_scene(unit: str):
    """:data:`OBLIQUE_SCENE` with its spectrum's heading the unit's (:data:`OBLIQUE`)."""
    sc = resolve(OBLIQUE_SCENE)
    sp = sc.waves.spectrum.replace(heading_deg=OBLIQUE[unit])
    return sc.replace(waves=sc.waves.replace(spectrum=sp))


def run_unit(unit: str, out: Path, note: str = "", full: bool = False) -> str:
    """Run one unit into ``out/unit``; returns the log line."""
    folder = Path(out) / unit
    if unit == "utilisation":
        return utilisation.run_unit(folder, note)
    if unit == "fatigue" or unit in OBLIQUE:
        t0 = time.perf_counter()
        scene = resolve(FATIGUE_SCENE) if unit == "fatigue" else oblique_scene(unit)
        res = fatigue_scatter.run_scatter(scene, FATIGUE_ELEMENT_LENGTH)
        head = fatigue_report.write(res, folder, note, time.perf_counter() - t0)
        agr = head["ancf"]
        return (f"design/{unit}: touchdown damage/yr rainflow (VFIFE) "
                f"{head['touchdown_rainflow']:.3g}, (ANCF) x{agr['total']['ratio']:.3f} "
                f"(worst x{agr['worst_ratio']:.3f}: {agr['verdict']}), "
                f"Dirlik (FD) {head['touchdown_dirlik']:.3g}"
                f" (x{head['ratio']:.3g}); hang-off x{head['hang_off_ratio']:.3g}; records "
                f"{min(st.record_s for st in res.states):.0f} to "
                f"{max(st.record_s for st in res.states):.0f} s")
    raise ValueError(f"unknown unit {unit!r} of design")


def index_row(d: Path):
    """(cases, worst agreement, verdict) of one unit's folder."""
    if (d / "cases.csv").exists():
        df = pd.read_csv(d / "cases.csv")
        worst = df["rel_diff"].abs().max()
        return (f"{len(df)} scenes", f"max utilisation BVP vs VFIFE within "
                f"{100 * worst:.4f} % (tolerance {100 * df.tolerance.iloc[0]:.2g} %)",
                "pass" if (df["verdict"] == "pass").all() else "fail")
    if (d / "stations.csv").exists():
        st = pd.read_csv(d / "stations.csv").set_index("estimate")
        fd = (f"Dirlik (FD) / rainflow (VFIFE) {st.loc['dirlik_fd', 'touchdown_ratio']:.3g}, "
              f"hang-off {st.loc['dirlik_fd', 'hang_off_ratio']:.3g}")
        ss = pd.read_csv(d / "sea_states.csv")
        if fatigue.ANCF not in st.index:
            return (f"{len(ss)} sea states, 4 estimates", f"touchdown damage {fd}",
                    "reported")
        worst, ok = ancf_ratios(ss)
        return (f"{len(ss)} sea states, 5 estimates (time domains VFIFE and ANCF)",
                f"touchdown damage ANCF / VFIFE {st.loc[fatigue.ANCF, 'touchdown_ratio']:.3f}"
                f" in total, worst {worst:.3f} (tolerance {100 * fatigue.ANCF_TOLERANCE:.0f} %"
                f" each sea state and total); {fd}", "pass" if ok else "fail")
    return None


def ancf_ratios(ss: pd.DataFrame) -> tuple[float, bool]:
    """(the ratio ANCF / VFIFE of the touchdown's damage farthest from 1, all within
    :data:`.fatigue.ANCF_TOLERANCE`) over the sea states of ``sea_states.csv`` and their
    total (the shares at the headline's station add up to the total):
    :func:`.fatigue.ancf_agreement`'s verdict, read back from the files."""
    v = ss["rainflow_vfife_touchdown_damage_per_year"]
    a = ss[f"{fatigue.ANCF}_touchdown_damage_per_year"]
    ratios = list(a / v) + [float(a.sum() / v.sum())]
    worst = max(ratios, key=lambda r: abs(r - 1.0))
    return float(worst), bool(abs(worst - 1.0) <= fatigue.ANCF_TOLERANCE)


#: the units' declared times [s] (the progress's ETA): the fatigue's 230 s of the VFIFE
#: and the FD, and the ANCF's three sea states, about 500 s of CPU each (measured: 1403 s
#: of wall for Hs 1.5 m on the 2-core machine shared at about a third of a core)
STUDY = Study("design", UNITS, run_unit, index_row,
              seconds={"utilisation": 15, "fatigue": 1750, "fatigue-45": 1750,
                       "fatigue-90": 1750})

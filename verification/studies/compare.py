"""The comparison study of ``riser-verify reproduce compare``: every built-in scene but the
hard cases (the stress suite's) and the sea-state and design scenes (their studies')
compared by the protocol of
:mod:`verification.comparison.static.protocol`, one unit per scene into
``reports/compare/SCENE/`` (the files of ``riser-verify compare``)."""

from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

from riser.errors import SolveFailed
from verification.catalog import COMPARE_SCENES, resolve
from verification.comparison.static.protocol import compare
from verification.comparison.static.report import write
from verification.runtime.stable import QUANTA

from .study import Study



def run_unit(scene_name: str, out: Path, note: str = "", full: bool = False) -> str:
    """Compare one built-in scene into ``out/scene_name`` (``note``, ``full``: unused, the
    comparison has no timings to qualify and no dear part); returns the log line."""
    t0 = time.perf_counter()
    try:
        comp = compare(resolve(scene_name))
    except SolveFailed as exc:
        return f"compare {scene_name}: {exc}"
    write(comp, out / scene_name)
    return (f"compare {scene_name}: {'PASS' if comp.passed else 'FAIL'} "
            f"({time.perf_counter() - t0:.1f} s)")


def index_row(d: Path):
    """(cases, worst agreement, verdict) of one scene's comparison directory."""
    if not (d / "agreement.csv").exists():
        return None
    df = pd.read_csv(d / "agreement.csv")
    failed = df[~df["pass"].astype(bool)].quantity.tolist()
    rows = df.set_index("quantity")
    bases = {"configuration": "of depth", "tension": "of T_max", "moment": "of M_max"}
    # two significant digits: a difference of 8e-6 of the depth is "+0.00081 %", not the
    # "+0.00 %" a fixed two decimals printed (read as no difference at all)
    # a row shown but not judged (the moment of a line whose bending length the elements
    # cannot resolve: a chain) says so
    # a difference below the file's step (agreement.csv's rel_diff on multiples of 1e-6,
    # verification.runtime.stable.QUANTA) is said to be below it, never "+0 %"
    step = QUANTA["agreement.csv"]["rel_diff"]

    def pct(v: float) -> str:
        return f"{100.0 * v:+.2g} %" if v != 0.0 else f"below {100.0 * step:g} %"
    text = ", ".join(f"{q} {pct(rows.loc[q, 'rel_diff'])} {bases[q]}"
                     + (" (not judged)" if pd.isna(rows.loc[q, "pass"]) else "")
                     for q in bases if q in rows.index)
    if "tdp_x" in rows.index:
        tdp = rows.loc["tdp_x"]
        text += f", touchdown {tdp['vfife'] - tdp['bvp']:+.3f} m"
    judged = df[df["pass"].notna() & (df.tolerance > 0)]
    if len(judged):
        ratio = judged.abs_diff / judged.tolerance
        k = ratio.idxmax()
        text += f"; nearest its tolerance: {judged.quantity[k]} at {ratio[k]:.2f} of it"
    if failed:
        text += f"; outside tolerance: {', '.join(failed)}"
    return "1 scene", text, "pass" if not failed else "fail"


#: measured wall times [s] of the units in ``reproduce all`` (2 processes, 2 cores)
STUDY = Study("compare", COMPARE_SCENES, run_unit, index_row,
              seconds={"yu2021-a4": 12, "wang2014-current-neg1p5": 7, "wang2014-current-neg0p75": 7,
                       "wang2014-current-0p75": 7, "wang2014-current-1p5": 7, "yu2021-a2": 6,
                       "yu2021-a2-sheared": 6, "yu2021-a3": 5, "wang2014-baseline": 4,
                       "yu2021-a1": 2, "scr-steel": 2, "kang2015-jlay": 6,
                       "scr-steel-current-45": 8, "scr-steel-current-90": 7,
                       "scr-steel-current-turning": 9, "yu2021-a3-current-45": 8,
                       "yu2021-a3-current-90": 8, "yu2021-a3-current-turning": 13,
                       "yu2021-a3-hang-off-offset": 9, "ttr-steel": 8,
                       "lazy-wave-flex-joint": 6, "mooring-clump-weight": 10})


"""The modal study of ``riser-verify reproduce modes``: the natural modes of the Wang
baseline (its fixed-ends equivalent), Yu A3, the SCR and the clamped, tensioned TTR by the
BVP, the VFIFE and the ANCF (the command's columns), one unit per scene into
``reports/modes/SCENE/`` (the files of ``riser-verify modes``, see
:mod:`verification.comparison.modes`), against the target of issue 14 (issue 46 for the
ANCF): the first 10 in-plane and 10 out-of-plane modes within 0.5 % in frequency and
MAC >= 0.99 of the BVP's; about a 3D static state (issue 50) the first 20 coupled
modes."""

from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

from verification.catalog import resolve
from verification.comparison.modes import COLUMNS, TARGET_MAC, TARGET_REL_DIFF, run_modes

from .study import Study

#: the scenes of the study (issue 14's three, issue 46's TTR, and issue 50's three 3D
#: static states: a current across the plane, one turning with depth, a hang-off out of
#: the anchor's plane; their modes one coupled family)
MODES_SCENES = ("wang2014-baseline", "yu2021-a3", "scr-steel", "ttr-steel",
                "scr-steel-current-90", "yu2021-a3-current-turning",
                "yu2021-a3-hang-off-offset")
#: modes per plane
COUNT = 10


def run_unit(scene_name: str, out: Path, note: str = "", full: bool = False) -> str:
    """Modes of one built-in scene into ``out/scene_name``; returns the log line."""
    t0 = time.perf_counter()
    run = run_modes(resolve(scene_name), COUNT, Path(out) / scene_name, columns=COLUMNS)
    n_ok = sum(r.passed for r in run.rows)
    return (f"modes {scene_name}: {n_ok}/{len(run.rows)} pairs within the target "
            f"({time.perf_counter() - t0:.1f} s)")


def index_row(d: Path):
    """(cases, worst agreement, verdict) of one scene's modal directory."""
    if not (d / "agreement.csv").exists():
        return None
    df = pd.read_csv(d / "agreement.csv")
    text, ok = [], True
    for label, rel, mac in (("VFIFE", "rel_diff", "mac"),
                            ("ANCF", "ancf_rel_diff", "ancf_mac")):
        if rel not in df or df[rel].isna().all():
            continue
        meets = (df[rel].abs() <= TARGET_REL_DIFF) & (df[mac] >= TARGET_MAC)
        ok = ok and bool(meets.all())
        text.append(f"{label} frequency {100 * df[rel].abs().max():.3f} %, MAC >= "
                    f"{df[mac].min():.4f}")
    return f"{len(df)} mode pairs", "; ".join(text), "pass" if ok else "fail"


#: measured wall times [s] of the units in ``reproduce all`` (2 processes, 2 cores)
STUDY = Study("modes", MODES_SCENES, run_unit, index_row,
              seconds={"yu2021-a3": 50, "wang2014-baseline": 30, "scr-steel": 25,
                       "ttr-steel": 20, "scr-steel-current-90": 35,
                       "yu2021-a3-current-turning": 180, "yu2021-a3-hang-off-offset": 150})

"""The modal study of ``riser-verify reproduce modes``: the natural modes of the Wang
baseline (its fixed-ends equivalent), Yu A3 and the SCR by both methods, one unit per
scene into ``reports/modes/SCENE/`` (the files of ``riser-verify modes``, see
:mod:`verification.comparison.modes`), against the target of issue 14: the first 10 in-plane and 10
out-of-plane modes within 0.5 % in frequency and MAC >= 0.99."""

from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

from verification.catalog import resolve
from verification.comparison.modes import TARGET_MAC, TARGET_REL_DIFF, run_modes

from .study import Study

#: the scenes of the study (the issue's three)
MODES_SCENES = ("wang2014-baseline", "yu2021-a3", "scr-steel")
#: modes per plane
COUNT = 10


def run_unit(scene_name: str, out: Path, note: str = "", full: bool = False) -> str:
    """Modes of one built-in scene into ``out/scene_name``; returns the log line."""
    t0 = time.perf_counter()
    run = run_modes(resolve(scene_name), COUNT, Path(out) / scene_name)
    n_ok = sum(r.passed for r in run.rows)
    return (f"modes {scene_name}: {n_ok}/{len(run.rows)} pairs within the target "
            f"({time.perf_counter() - t0:.1f} s)")


def index_row(d: Path):
    """(cases, worst agreement, verdict) of one scene's modal directory."""
    if not (d / "agreement.csv").exists():
        return None
    df = pd.read_csv(d / "agreement.csv")
    worst = df["rel_diff"].abs().max()
    meets = (df["rel_diff"].abs() <= TARGET_REL_DIFF) & (df["mac"] >= TARGET_MAC)
    return (f"{len(df)} mode pairs", f"frequency {100 * worst:.3f} %, MAC >= "
            f"{df['mac'].min():.4f}", "pass" if bool(meets.all()) else "fail")


#: measured wall times [s] of the units in ``reproduce all`` (2 processes, 2 cores)
STUDY = Study("modes", MODES_SCENES, run_unit, index_row,
              seconds={"yu2021-a3": 40, "wang2014-baseline": 25, "scr-steel": 20})

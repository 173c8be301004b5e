"""Sea states (``riser-verify reproduce sea_states``, issue 33): :mod:`.lowe_langley` (the
Lowe and Langley jumper's wave cases 4-6 against the published series) and
:mod:`.two_methods` (the frequency domain against the VFIFE on a regular wave and on an
irregular sea)."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from ..study import Study
from . import lowe_langley, two_methods

#: the units of the study, each a folder of reports/sea_states/
UNITS = ("lowe-langley", "two-methods")


def run_unit(unit: str, out: Path, note: str = "", full: bool = False) -> str:
    """Run one unit into ``out/unit``; returns the log line."""
    folder = Path(out) / unit
    if unit == "lowe-langley":
        return lowe_langley.run_unit(folder, note)
    if unit == "two-methods":
        return two_methods.run_unit(folder, note)
    raise ValueError(f"unknown unit {unit!r} of sea_states")


def index_row(d: Path):
    """(cases, worst agreement, verdict) of one unit's folder."""
    if (d / "cases.csv").exists() and (d / "agreement.csv").exists():
        df = pd.read_csv(d / "cases.csv")
        ok = df[df["verdict"] != "failed"]
        if not len(ok):
            return (f"{len(df)} scenes", "no scene solved", "fail")
        k = int(ok["ratio_to_tolerance"].to_numpy().argmax())
        r = ok.iloc[k]
        worst = (f"FD vs VFIFE, nearest its tolerance: {r.nearest_tolerance} "
                 f"{100 * r.difference:+.2f} % ({r.ratio_to_tolerance:.2f} of it, {r.scene})")
        return (f"{len(df)} wave scenes", worst,
                "pass" if (df["verdict"] == "pass").all() else "fail")
    if (d / "cases.csv").exists():
        df = pd.read_csv(d / "cases.csv")
        ok = df[df["verdict"] != "failed"]
        worst = (f"hang-off tension within {ok.worst_kN.max():.2f} kN of the published "
                 f"series (tolerance {lowe_langley.TOLERANCE_KN:g} kN)" if len(ok) else
                 "no case solved")
        return (f"{len(df)} wave cases", worst,
                "pass" if (df["verdict"] == "pass").all() else "fail")
    return None


STUDY = Study("sea_states", UNITS, run_unit, index_row,
              seconds={"lowe-langley": 20, "two-methods": 90})

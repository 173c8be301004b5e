"""The end-condition study of ``riser-verify reproduce ends`` (issue 35): the end
conditions and point attachments against five closed forms, by both methods, one unit
(``None``) into ``reports/ends/``:

1. a top-tensioned riser in a uniform current (the hyperbolic tensioned beam);
2. a clamp at an angle and a top flex joint (the 4x4 linear closed form), two stiffnesses;
3. the tensioned pinned line's frequencies, omega^2 (m + m_a) = EI k^4 + T k^2;
4. a hanging chain with a free lower end (the zeros of J0), and its stretch;
5. a clump weight and a buoy on a cable (two elastic catenaries).

Files: ``closed_forms.csv`` (a row per checked quantity: the closed form, both methods,
their relative differences and the tests' tolerances), ``report.md``, ``deflection.png``
and ``chain_modes.png``. The scenes are built from their tables (:mod:`.scenes`), the cases
run in :mod:`.cases`, the files written by :mod:`.report`.
"""

from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

from ..study import Study
from .cases import run_all
from .report import METHODS, frame, nearest_tolerance, write


def run_unit(unit, out: Path, note: str = "", full: bool = False) -> str:
    """Run the five cases into ``out`` (``unit``: None; ``note``, ``full``: unused, the
    report states no timings and has no dear part); returns the log line."""
    t0 = time.perf_counter()
    rows, data = run_all()
    df = frame(rows)
    write(df, data, Path(out))
    return (f"ends: {int(df['pass'].sum())}/{len(df)} quantities within the tests' "
            f"tolerances ({time.perf_counter() - t0:.1f} s)")


def index_row(d: Path):
    """(cases, worst agreement, verdict) of the study's report directory."""
    if not ((d / "closed_forms.csv").exists() and (d / "report.md").exists()):
        return None
    df = pd.read_csv(d / "closed_forms.csv")
    parts = []
    for m, label in METHODS.items():
        k = df[f"{m}_rel_diff"].abs().idxmax()
        parts.append(f"{label} {df[f'{m}_rel_diff'][k]:+.1e} ({df.case[k]} "
                     f"{df.quantity[k]})")
    method, where, ratio = nearest_tolerance(df)
    return (f"{len(df)} quantities", f"worst: {', '.join(parts)}; nearest its tolerance: "
            f"{method} {where} at {ratio:.2f} of it",
            "pass" if bool(df["pass"].astype(bool).all()) else "fail")


#: measured wall time [s] of the unit (`reproduce ends` alone on a 2-core machine: 18.9 s)
STUDY = Study("ends", (None,), run_unit, index_row, seconds={None: 19})

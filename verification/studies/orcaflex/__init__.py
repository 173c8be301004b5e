"""The OrcaFlex study of ``riser-verify reproduce orcaflex`` (issue 51), one unit (``None``)
into ``reports/orcaflex/``:

1. public models with OrcaFlex's own static results, imported and solved by both methods
   (:mod:`.published`; two judged against tolerances, one reported);
2. the public corpus of text data files, every line imported or refused (:mod:`.corpus`);
3. every built-in scene's round trip scene -> OrcaFlex model -> scene (:mod:`.round_trip`).

Files: ``published.csv``, ``corpus.csv``, ``round_trip.csv``, ``profiles.png``,
``report.md`` (:mod:`.report`). Reading OrcaFlex's files needs PyYAML, the optional extra
``[orcaflex]``: without it the unit fails with the line that says how to install it.
"""

from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

from ..study import Study


def run_unit(unit, out: Path, note: str = "", full: bool = False) -> str:
    """Run the three parts into ``out`` (``unit``: None; ``note``, ``full``: unused, the
    report states no timings); returns the log line."""
    from riser.io.orcaflex.text_file import _yaml

    from . import corpus, published, report, round_trip
    _yaml()                       # the extra's one line, before anything runs
    t0 = time.perf_counter()
    rows, profiles = [], {}
    for model in published.MODELS:
        _, model_rows, results = published.solve(model)
        rows += model_rows
        profiles[model.name] = {m: res.profile for m, res in results.items()}
    pub = report.published_frame(rows)
    cor = report.corpus_frame(corpus.outcomes())
    trips = report.round_trip_frame(round_trip.built_in_round_trips())
    report.write(pub, profiles, cor, trips, Path(out))
    judged = pub[pub["pass"].astype(str) != "reported"]
    return (f"orcaflex: {int((judged['pass'].astype(str) == 'True').sum())}/{len(judged)} "
            f"judged quantities within tolerance of OrcaFlex's published statics; corpus "
            f"{int(cor['imported'].sum())} imports of {len(cor)}; round trip {int(trips['exported'].sum())}/{len(trips)} built-in "
            f"scenes ({time.perf_counter() - t0:.1f} s)")


def index_row(d: Path):
    """(cases, worst agreement, verdict) of the study's report directory."""
    if not ((d / "published.csv").exists() and (d / "report.md").exists()):
        return None
    df = pd.read_csv(d / "published.csv")
    judged = df[df["pass"].astype(str) != "reported"]
    parts = []
    for m, label in (("bvp", "BVP"), ("vfife", "VFIFE")):
        k = judged[f"{m}_rel_diff"].abs().idxmax()
        parts.append(f"{label} {judged[f'{m}_rel_diff'][k]:+.2%} ({judged.model[k]} "
                     f"{judged.quantity[k]})")
    trips = pd.read_csv(d / "round_trip.csv") if (d / "round_trip.csv").exists() else None
    rt = (f"; round trip {int(trips['exported'].sum())}/{len(trips)} built-in scenes"
          if trips is not None else "")
    reported = df.model.nunique() - judged.model.nunique()
    return (f"{df.model.nunique()} public models x {len(df) // df.model.nunique()} "
            f"quantities ({reported} reported, not judged)",
            f"against OrcaFlex: {', '.join(parts)}{rt}",
            "pass" if bool((judged["pass"].astype(str) == "True").all()) else "fail")


#: measured wall time [s] of the unit (`reproduce orcaflex` alone on a 2-core machine)
STUDY = Study("orcaflex", (None,), run_unit, index_row, seconds={None: 40})

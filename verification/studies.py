"""The registry of studies: ``reproduce`` and ``reports/README.md`` loop over it.

Adding a study means writing its module, with a ``STUDY`` (:class:`verification.study.Study`)
declaring its units of work, how to run one and its index row, and naming the module here.
"""

from __future__ import annotations

import time
from pathlib import Path

from . import compare_report, cost, stress, wang2014, yu2021
from .study import Study

#: name -> study, in the order ``reproduce all`` lists them
STUDIES: dict[str, Study] = {m.STUDY.name: m.STUDY
                             for m in (wang2014, yu2021, compare_report, stress, cost)}


def units(name: str) -> list[tuple[str, str | None]]:
    """(study, unit) pairs of ``reproduce NAME`` ('all': every study), longest first."""
    names = list(STUDIES) if name == "all" else [name]
    out = [(n, u) for n in names for u in STUDIES[n].units]
    return sorted(out, key=lambda su: -STUDIES[su[0]].unit_seconds(su[1]))


def run_unit(study: str, unit: str | None, out: str, note: str = "") -> str:
    """Run one unit into ``out`` (the study's report directory); returns a line for the
    log. Top level, with plain arguments, so that worker processes can run it."""
    t0 = time.perf_counter()
    line = STUDIES[study].run(unit, Path(out), note)
    if isinstance(line, str):
        return line
    return f"{study}: wrote {out}/ in {time.perf_counter() - t0:.1f} s"

"""The registry of studies: ``reproduce`` and ``reports/README.md`` loop over it.

Adding a study means writing its module, with a ``STUDY`` (:class:`verification.studies.study.Study`)
declaring its units of work, how to run one and its index row, and naming the module here.
The modules are imported when a study is first asked for, so that the command line starts
without loading the solvers and matplotlib (``riser-verify scenes`` in 0.4 s instead of
3.6 s).
"""

from __future__ import annotations

import importlib
import time
from pathlib import Path

from .study import Study

#: study name -> its module, in the order ``reproduce all`` lists them
STUDY_MODULES = {name: f"verification.studies.{name}" for name in (
    "wang2014", "yu2021", "liu2021", "kang2015", "compare", "cross_current", "stress", "cost",
    "modes", "dynamics", "sea_states", "design", "ends")}
#: the study names (``riser-verify reproduce NAME``)
STUDIES = tuple(STUDY_MODULES)
def study(name: str) -> Study:
    """The study ``name`` (its module's ``STUDY``)."""
    return importlib.import_module(STUDY_MODULES[name]).STUDY


def units(name: str, full: bool = False) -> list[tuple[str, str | None]]:
    """(study, unit) pairs of ``reproduce NAME`` ('all': every study), longest first
    (``full``: as long as with ``--full``)."""
    names = STUDIES if name == "all" else (name,)
    out = [(n, u) for n in names for u in study(n).units]
    return sorted(out, key=lambda su: -study(su[0]).unit_seconds(su[1], full))


def run_unit(name: str, unit: str | None, out: str, note: str = "",
             full: bool = False) -> str:
    """Run one unit into ``out`` (the study's report directory; ``full``: with the dear
    parts, ``--full``); returns a line for the log. Top level, with plain arguments, so
    that worker processes can run it."""
    t0 = time.perf_counter()
    line = study(name).run(unit, Path(out), note, full)
    if isinstance(line, str):
        return line
    return f"{name}: wrote {out}/ in {time.perf_counter() - t0:.1f} s"

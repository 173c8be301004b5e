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

from verification.runtime import outdir, stable
from verification.runtime.outdir import STUDY_FILES
from verification.report.markdown import committed_reports

from .study import Study

#: study name -> its module, in the order ``reproduce all`` lists them
STUDY_MODULES = {name: f"verification.studies.{name}" for name in (
    "wang2014", "yu2021", "liu2021", "kang2015", "compare", "cross_current", "stress", "cost",
    "modes", "dynamics", "sea_states", "design", "ends", "nonlinear", "orcaflex")}
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
             full: bool = False) -> tuple[str, dict]:
    """Run one unit into ``out`` (the study's report directory; ``full``: with the dear
    parts, ``--full``); returns (a line for the log, its timings: {"wall_s": the unit's
    wall time [s], "files": {file: the timings taken out of it}}). Top level, with plain
    arguments, so that worker processes can run it.

    The unit writes into a staging folder beside its report
    (:func:`~verification.runtime.outdir.staging_folder`); its CSV and JSON files are made
    machine-independent there (:func:`~verification.runtime.stable.stabilise`: timings out,
    floats to 6 significant digits; where the reports' text measured a time it says
    :data:`verification.report.markdown.TIMED`, :func:`~verification.report.markdown.timed`),
    and only then do they replace the old report
    (:func:`~verification.runtime.outdir.swap_in`). A unit that raises, or is
    interrupted, leaves the old report as it was."""
    t0 = time.perf_counter()
    st = study(name)
    outdir.discard_stale(out, unit)
    staging = outdir.staging_folder(unit, out)
    try:
        with committed_reports() as report_times:      # no timing in the reports' text
            line = st.run(unit, staging, note, full)
        staged = outdir.unit_folder(unit, staging)
        timings = stable.stabilise(staged) if st.stable else {}
        outdir.swap_in(staged, outdir.unit_folder(unit, out), STUDY_FILES[name])
    finally:
        outdir.discard(staging)
    wall = time.perf_counter() - t0
    record = {"wall_s": round(wall, 2), "files": timings,
              "report_times_s": [round(t, 4) for t in report_times]}
    if isinstance(line, str):
        return line.replace(str(staging), str(out)), record
    return f"{name}: wrote {out}/ in {wall:.1f} s", record

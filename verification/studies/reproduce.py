"""``riser-verify reproduce NAME``: run the units of one study or of every study on the
engine, longest first, and index the reports (``reports/README.md``). A unit that raises is
reported at the end; the others go on."""

from __future__ import annotations

import os
import time
from dataclasses import dataclass, field
from pathlib import Path

from verification.runtime import outdir
from verification.runtime.engine import Engine
from verification.runtime.progress import UnitTracker

from . import run_unit, study, units
from .index import write_index


@dataclass(frozen=True)
class Reproduction:
    """What ``reproduce`` did: the units run, the wall time [s], the worker processes, the
    failed units (one line each) and the index written (None after a failure, or for one
    study into ``--out``)."""

    units: int
    wall_s: float
    jobs: int
    failed: list[str] = field(default_factory=list)
    index: Path | None = None


def report_folder(name: str, base: Path | None, study_name: str) -> str:
    """Where a unit of ``study_name`` writes: ``reports/STUDY`` by default; under ``--out``
    BASE, ``BASE/STUDY`` for ``reproduce all`` and BASE itself for one study."""
    if base is None:
        return str(Path("reports") / study_name)
    return str(base / study_name if name == "all" else base)


def reproduce(name: str, *, out: Path | None = None, jobs: int = 1, full: bool = False,
              progress=None) -> Reproduction:
    """Regenerate the reports of study ``name`` ('all': every study) into ``out`` (default
    ``reports/``) with ``jobs`` worker processes; ``full``: the dear parts too
    (``--full``). ``progress``: the :class:`~verification.runtime.progress.Progress` the
    units' lines and the fraction done go to (None: quiet)."""
    todo = units(name, full)
    for study_name, unit in todo:            # no report of an earlier run survives a failure
        outdir.clear_unit(study_name, unit, report_folder(name, out, study_name))
    jobs = max(1, min(jobs, len(todo)))
    t0 = time.perf_counter()
    note = (f"Timings measured while `riser-verify reproduce {name}` ran other units in "
            f"{jobs - 1} more worker process(es) on this {os.cpu_count()}-core machine; run "
            "`riser-verify cost SCENE` alone for uncontended timings." if jobs > 1 else "")
    # progress: units done, weighted by the studies' declared seconds; the units' own
    # output is printed above the status line
    track = UnitTracker([study(n).unit_seconds(u, full) for n, u in todo], jobs)
    failed = []
    if progress is not None:
        progress.source = track
    work = [(n, u, report_folder(name, out, n), note, full) for n, u in todo]
    for i, line in Engine(jobs).map(run_unit, work, progress):
        if isinstance(line, BaseException):      # the others go on; said at the end
            failed.append(f"{todo[i][0]} {todo[i][1] or ''}".strip() + f": {line}")
            line = f"{failed[-1]} (FAILED)"
        if progress is not None:
            progress.log(line)
        track.done(i)
    index = None
    if not failed and (out is None or name == "all"):
        index = write_index(Path("reports") if out is None else out)
    return Reproduction(len(todo), time.perf_counter() - t0, jobs, failed, index)

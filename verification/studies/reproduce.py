"""``riser-verify reproduce NAME``: run the units of one study or of every study on the
engine, longest first, and index the reports (``reports/README.md``). A unit that raises is
reported at the end; the others go on."""

from __future__ import annotations

import json
import os
import time
from dataclasses import dataclass, field
from pathlib import Path

from verification.runtime import outdir
from verification.runtime.engine import Engine
from verification.runtime.progress import UnitTracker, clock_text

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


def check_folders(name: str, out: Path | None, todo) -> None:
    """Refuse before any solving (SceneError, exit 2, naming ``--out``) a report folder
    that is a file or cannot be written; old reports are not touched here: each unit
    replaces its own only when it succeeded (:func:`verification.studies.run_unit`)."""
    for study_name in dict.fromkeys(n for n, _ in todo):
        outdir.check_folder(report_folder(name, out, study_name))


def progress_line(done: int, total: int, elapsed: float, fraction: float | None) -> str:
    """``(k/N units, m:ss elapsed, ETA m:ss)`` after a finished unit: the ETA from the
    fraction of the declared seconds done (:class:`UnitTracker`), blank when unknown."""
    eta = (f", ETA {clock_text(elapsed * (1.0 - fraction) / fraction)}"
           if fraction and fraction > 0 and done < total else "")
    return f"({done}/{total} units, {clock_text(elapsed)} elapsed{eta})"


def reproduce(name: str, *, out: Path | None = None, jobs: int = 1, full: bool = False,
              progress=None) -> Reproduction:
    """Regenerate the reports of study ``name`` ('all': every study) into ``out`` (default
    ``reports/``) with ``jobs`` worker processes; ``full``: the dear parts too
    (``--full``). ``progress``: the :class:`~verification.runtime.progress.Progress` the
    units' lines and the fraction done go to (None: quiet). A line at once (the units, the
    expected time), then one per finished unit with the time elapsed and the ETA, on a
    terminal or not; a unit's report replaces the old one only when the unit succeeded."""
    todo = units(name, full)
    check_folders(name, out, todo)
    jobs = max(1, min(jobs, len(todo)))
    t0 = time.perf_counter()
    note = (f"Timings measured while `riser-verify reproduce {name}` ran other units in "
            f"{jobs - 1} more worker process(es) on this {os.cpu_count()}-core machine; run "
            "`riser-verify cost SCENE` alone for uncontended timings." if jobs > 1 else "")
    # progress: units done, weighted by the studies' declared seconds; the units' own
    # output is printed above the status line
    seconds = [study(n).unit_seconds(u, full) for n, u in todo]
    track = UnitTracker(seconds, jobs)
    failed, timings = [], {}
    if progress is not None:
        progress.source = track
        progress.log(f"reproduce {name}: {len(todo)} unit(s) on {jobs} process(es), "
                     f"expected ~{clock_text(sum(seconds) / jobs)} "
                     f"(the studies' declared times)")
    # the note qualifies timings, which the committed reports no longer hold: it goes to
    # timings.json with them, not into the reports (it names this machine's cores)
    work = [(n, u, report_folder(name, out, n), "", full) for n, u in todo]
    for k, (i, got) in enumerate(Engine(jobs).map(run_unit, work, progress), start=1):
        if isinstance(got, BaseException):      # the others go on; said at the end
            failed.append(f"{todo[i][0]} {todo[i][1] or ''}".strip() + f": {got}")
            line = f"{failed[-1]} (FAILED; its old report kept)"
        else:
            line, record = got
            timings[f"{todo[i][0]}/{todo[i][1] or ''}".rstrip("/")] = record
        track.done(i)
        elapsed = time.perf_counter() - t0
        if progress is not None:
            progress.log(f"{line} {progress_line(k, len(todo), elapsed, track()[1])}")
    index = None
    if not failed and (out is None or name == "all"):
        index = write_index(Path("reports") if out is None else out)
    wall = time.perf_counter() - t0
    write_timings(Path("reports") if out is None else out, name, jobs, wall, timings, note)
    return Reproduction(len(todo), wall, jobs, failed, index)


def write_timings(base: Path, name: str, jobs: int, wall: float, units: dict,
                  note: str = "") -> Path:
    """``BASE/timings.json``, outside the committed tree (``.gitignore``): the measured
    times [s] the committed reports leave out, by unit (``STUDY/UNIT``: its wall time and
    the timings taken out of each of its files, :mod:`verification.runtime.stable`) and
    the run's; a later run updates the units it ran, the others stay."""
    path = base / "timings.json"
    try:
        old = json.loads(path.read_text())
    except (OSError, ValueError):
        old = {}
    merged = dict(old.get("units", {})) if isinstance(old, dict) else {}
    merged.update(units)
    runs = (old.get("runs", []) if isinstance(old, dict) else [])[-9:]
    runs.append({"command": f"riser-verify reproduce {name}", "jobs": jobs,
                 "cpus": os.cpu_count(), "wall_s": round(wall, 1), "note": note})
    base.mkdir(parents=True, exist_ok=True)
    tmp = base / f".timings.json.partial-{os.getpid()}"
    tmp.write_text(json.dumps({"runs": runs, "units": dict(sorted(merged.items()))},
                              indent=1) + "\n")
    os.replace(tmp, path)
    return path

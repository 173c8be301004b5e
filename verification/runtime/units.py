"""Independent units of work run on an :class:`~.engine.Engine`, each kept as it finishes,
resumed by the next run: what ``sweep`` (its cases) and ``fatigue`` (its sea states'
runs) share.

:func:`run_units` hands the units to the engine, and as each comes back calls the
caller's ``keep`` with Ctrl-C held back (:func:`~.interrupts.held_interrupts`: a unit is
written and counted whole, or not at all), prints its line and keeps the progress
display's count and ETA (:class:`~.progress.UnitTracker`, rescaled to the first measured
unit, or before any unit runs to the median of an earlier run's). Ctrl-C at any moment
stops the engine's workers and raises :class:`Interrupted` with the units written so
far, which the command turns into its one line (exit 130).

A unit's record is kept in a file of its own, written under a temporary name and renamed
into place (:func:`write_record`), carrying a digest of the unit's inputs
(:func:`digest`); :func:`read_record` returns it only when the digest matches and the
unit did not end in an error, so the same command again skips exactly the units already
done with the same inputs. Imports nothing of ``verification`` outside ``runtime``.
"""

from __future__ import annotations

import contextlib
import hashlib
import heapq
import json
import os
import shutil
import statistics
import time
from pathlib import Path

from .interrupts import held_interrupts
from .progress import UnitTracker, scoped


class Interrupted(KeyboardInterrupt):
    """Ctrl-C while the units ran: ``finished`` of ``total`` units are kept (the next run
    skips them); the engine's workers are stopped."""

    def __init__(self, finished: int, total: int):
        super().__init__(f"{finished} of {total} cases")
        self.finished, self.total = finished, total


def duration_text(seconds: float) -> str:
    """'40 s', '12 min', '2 h 05 min'."""
    if seconds < 90:
        return f"{max(seconds, 1):.0f} s"
    if seconds < 90 * 60:
        return f"{seconds / 60:.0f} min"
    h, m = divmod(int(seconds / 60 + 0.5), 60)
    return f"{h} h {m:02d} min"


def makespan(seconds: list[float], workers: int) -> float:
    """The wall time [s] of units of ``seconds`` each, started in the given order on
    ``workers`` as they free up (equal units: their rounds, ceil(n / workers) x t)."""
    free = [0.0] * max(1, min(workers, len(seconds)))
    for s in seconds:
        heapq.heappush(free, heapq.heappop(free) + s)
    return max(free) if seconds else 0.0


def estimate_line(todo: int, workers: int, case_s: float, source: str,
                  noun: str = "case", each: str = "a case with every method",
                  weights: list[float] | None = None) -> str:
    """The wall time of ``todo`` units of ``case_s`` seconds each (``weights``: their
    relative costs, the unit of weight 1 taking ``case_s``) on ``workers`` at once: the
    units start in order as the workers free up."""
    w = max(1, min(workers, todo))
    seconds = [case_s * x for x in weights] if weights else [case_s] * todo
    total = makespan(seconds, w)
    return (f"estimate: about {duration_text(total)} for {todo} {noun}(s) on {w} "
            f"worker(s) ({case_s:.1f} s {each}, {source})")


def run_units(engine, fn, specs: list, keep, *, progress=None, names=None,
              noun: str = "case", each: str = "a case with every method",
              weights: list[float] | None = None, earlier: list[float] = (),
              resumed: int = 0, total: int | None = None, written=None,
              unit_progress: bool = False) -> float:
    """Run ``fn(spec)`` for every spec of ``specs`` on ``engine`` (open); return the wall
    time [s].

    ``keep(i, result)`` (``result``: the unit's return value or the exception it raised)
    stores unit ``i`` and returns ``(line, seconds)``: the console line and the unit's
    measured time (None: not a time to estimate from); it runs with Ctrl-C held back.
    ``progress``: a :class:`~.progress.Progress` (its ``log`` and status line) or None.
    ``weights``: the units' relative costs for the estimate and the bar (default equal).
    ``earlier``: the measured seconds of units an earlier run finished (the estimate
    before any unit runs: their median, for a unit of weight 1); ``resumed`` of ``total``
    units were skipped (said first). ``unit_progress``: in this process (``--jobs 1``) each
    unit is called ``fn(spec, progress)`` with a callback of its own (its solvers' fraction
    on the status line, and a Ctrl-C a library swallowed raised at its next report); on
    workers ``fn(spec)``. Ctrl-C raises :class:`Interrupted` (``written()`` units kept of
    ``total``)."""
    total = len(specs) + resumed if total is None else total
    names = names or [f"{noun}-{i}" for i in range(len(specs))]
    workers = engine.workers()
    here = engine.in_process
    plural = f"{noun}s"
    track = UnitTracker(list(weights) if weights else [1.0] * len(specs), workers,
                        what=plural, known=False)
    log = progress.log if progress is not None else (lambda line: None)
    if resumed:
        log(f"{resumed} of {len(specs) + resumed} {noun}(s) finished by an earlier run: "
            "skipped")
    if specs and earlier:
        unit_s = statistics.median(earlier)
        log(estimate_line(len(specs), workers, unit_s, f"the median of the {len(earlier)} "
                          "finished earlier", noun, each, weights))
        track.rescale(unit_s, weights)
    elif specs:
        log(f"{len(specs)} {noun}(s) to run on {min(workers, len(specs))} worker(s); the "
            f"estimate of the time follows the first {noun}")
    if progress is not None and not (here and unit_progress):
        progress.source = track
    if here and unit_progress and progress is not None:
        args = [(s, scoped(progress, f"{noun} {k + 1}/{len(specs)} {names[k]}"))
                for k, s in enumerate(specs)]
    else:
        args = [(s,) for s in specs]
    t0 = time.perf_counter()
    measured: list[float] = []
    try:
        with contextlib.closing(engine.map(fn, args, progress, names)) as results:
            for i, res in results:
                with held_interrupts():            # a unit is kept and counted, or not
                    line, seconds = keep(i, res)
                track.done(i)
                log(line)
                if seconds:
                    measured.append(seconds / (weights[i] if weights else 1.0))
                    if len(measured) == 1 and not earlier and len(specs) > 1:
                        log(estimate_line(len(specs), workers, measured[0], f"the first "
                                          f"{noun}", noun, each, weights))
                        track.rescale(measured[0], weights)
    except KeyboardInterrupt:
        raise Interrupted(written() if written is not None else 0, total) from None
    return time.perf_counter() - t0


def digest(*parts) -> str:
    """A short digest of a unit's inputs (their ``repr``: a frozen scene's is exact)."""
    return hashlib.sha256(repr(parts).encode()).hexdigest()[:16]


def write_record(path: Path, record: dict) -> None:
    """``record`` (JSON types; floats round-trip exactly) to ``path``, atomically: written
    under a temporary name and renamed, so that the file exists only whole."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(json.dumps(record) + "\n")
    os.replace(tmp, path)


def read_record(path: Path, digest_: str) -> dict | None:
    """The record at ``path`` when it holds ``digest_`` and no ``error``, else None (never
    run, run with other inputs, or failed: run it again)."""
    try:
        rec = json.loads(Path(path).read_text())
    except (OSError, ValueError):
        return None
    if not isinstance(rec, dict) or rec.get("digest") != digest_ or "error" in rec:
        return None
    return rec


def clear_stale(folder: Path, count: int) -> None:
    """Remove the numbered unit folders ``folder/NNNN`` of an earlier, longer run (index
    >= count)."""
    for sub in Path(folder).glob("[0-9][0-9][0-9][0-9]*"):
        if sub.is_dir() and sub.name.isdigit() and int(sub.name) >= count:
            shutil.rmtree(sub)

"""Running a sweep (``riser-verify sweep``): its cases on an :class:`~verification.runtime.engine.Engine`,
resumed from the case folders, then the sweep's tables, plots and report.

The output folder holds one folder per case (``cases/NNNN/``, written as each case comes
back: :mod:`verification.sweeps.case`) and the sweep's own files (:data:`OUTPUTS`), which
are removed before the cases run and written only once every case has a record: an
interrupted or failed run leaves the finished cases (the next run skips them) and no
table or report that could be taken for a complete one. An interrupt (Ctrl-C) stops the
engine and raises :class:`Interrupted`, which says how many cases are written.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from riser.results.result import Status
from verification.runtime.engine import Engine
from verification.runtime.units import (Interrupted, clear_stale, duration_text,  # noqa: F401
                                        estimate_line, run_units)

from .case import ERROR, case_folder, error_record, read_case, run_case, write_case
from .file import Sweep

#: the sweep's own files (``cases/`` aside), cleared before a run
OUTPUTS = ("cases.csv", "envelopes.csv", "report.md", "range_tension.png",
           "range_moment.png", "range_utilisation.png", "configurations.png")


def _case_seconds(records) -> list[float]:
    return [r["wall_time_s"] for r in records
            if "error" not in r and isinstance(r.get("wall_time_s"), (int, float))
            and r["wall_time_s"] > 0]


@dataclass
class SweepRun:
    sweep: Sweep
    records: list[dict]            # one per case, in case order
    resumed: int                   # cases skipped, finished by an earlier run
    ran: int                       # cases run now
    wall_time_s: float             # of the cases run now
    engine: str                    # where they ran
    workers: int                   # units at once
    hosts: list[str] = field(default_factory=list)

    @property
    def cases_per_minute(self) -> float | None:
        return 60.0 * self.ran / self.wall_time_s if self.ran and self.wall_time_s > 0 else None

    def failures(self) -> list[tuple[int, str, str, str]]:
        """(case, method, status, reason) of every method that did not converge."""
        return [(r["index"], m, d["status"], d.get("message", ""))
                for r in self.records for m, d in r["methods"].items()
                if d["status"] != Status.CONVERGED]

    def warned(self) -> list[tuple[int, str, list[str]]]:
        """(case, method, warnings) of every converged result outside its model's validity
        (riser/results/validity.py: strain, resolution, surface, seabed, compression)."""
        return [(r["index"], m, d["warnings"]) for r in self.records
                for m, d in r["methods"].items()
                if d["status"] == Status.CONVERGED and d.get("warnings")]

    def design_checked(self) -> bool:
        """Whether any converged result made a design check (riser.design.verdicts)."""
        return any("design_fails" in d for r in self.records for d in r["methods"].values())

    def design_failures(self) -> list[tuple[int, str, list[str]]]:
        """(case, method, failed checks) of every result that fails a design check
        (``design_fails``: the code check, a bend limit)."""
        return [(r["index"], m, d["design_fails"]) for r in self.records
                for m, d in r["methods"].items() if d.get("design_fails")]

    def disagreements(self) -> list[dict]:
        return [r for r in self.records
                if r.get("agreement", {}).get("assessed") and not r["agreement"]["passed"]]


def case_line(rec: dict, n: int) -> str:
    """The console line of a finished case."""
    parts = [f"{m} {d['status']}" + (f" {d['wall_time_s']:.1f} s" if d.get("wall_time_s")
                                       else "")
             for m, d in rec["methods"].items()]
    agr = rec.get("agreement")
    if agr and agr.get("assessed"):
        parts.append(f"agreement {'pass' if agr['passed'] else 'FAIL'} (worst "
                     f"{agr['worst_quantity']} at {agr['worst_ratio']:.2f} of its tolerance)")
    return f"case {rec['index']}/{n}: " + ", ".join(parts)


def run(sweep: Sweep, out: Path, engine: Engine, progress=None) -> SweepRun:
    """Run the cases of ``sweep`` not finished in ``out``, each into its own folder;
    return every case's record. The engine must be open.

    ``progress`` (a :class:`~verification.runtime.progress.Progress`) gets, before the
    first case, the estimate of the wall time (from the cases finished by an earlier run,
    else said to follow the first case, and then given from it: the cases run in rounds of
    the engine's workers), a line per case, and a :class:`UnitTracker` scaled to the
    measured time a case, whose fraction draws the bar and the ETA on a terminal. Ctrl-C
    stops the engine's workers and raises :class:`Interrupted` with the count of cases
    written."""
    out = Path(out)
    records: dict[int, dict] = {}
    todo = []
    for case in sweep.cases:
        rec = read_case(out, case.index, case.digest)
        if rec is None:
            todo.append(case)
        else:
            records[case.index] = rec
    resumed = len(records)
    specs = [{"index": c.index, "digest": c.digest, "scene": c.scene_dict,
              "methods": list(sweep.methods)} for c in todo]
    hosts: set[str] = set()

    def keep(i, res):
        spec = specs[i]
        if isinstance(res, BaseException):
            res = error_record(spec, f"the worker failed: {type(res).__name__}: {res}")
        write_case(out, res, _scene_text(sweep, sweep.cases[spec["index"]]))
        records[spec["index"]] = read_case(out, spec["index"], spec["digest"]) \
            or _without_profiles(res)
        hosts.add(str(res.get("worker", "")).split(":")[0])
        seconds = _case_seconds([res])
        return case_line(records[spec["index"]], len(sweep.cases)), \
            (seconds[0] if seconds else None)

    wall = run_units(engine, run_case, specs, keep, progress=progress,
                     names=[f"{sweep.name}-case-{s['index']:04d}" for s in specs],
                     earlier=_case_seconds(records.values()), resumed=resumed,
                     total=len(sweep.cases),
                     written=lambda: sum(1 for r in records.values() if "error" not in r))
    ordered = [records[c.index] for c in sweep.cases]
    return SweepRun(sweep, ordered, resumed, len(specs), wall, engine.describe(),
                    engine.workers(), sorted(h for h in hosts if h))


def _scene_text(sweep: Sweep, case) -> str:
    from riser.io.toml_text import dumps
    given = [f"  {k} = {json.dumps(v, default=str)}" for k, v in case.values.items()]
    return dumps(case.scene_dict, header=[f"Case {case.index} of the sweep {sweep.name} "
                                          f"({sweep.source}), base {sweep.base}:", *given])


def _without_profiles(rec: dict) -> dict:
    """A record that :func:`read_case` does not return (an error): kept as it came back,
    its methods marked as errors."""
    for d in rec["methods"].values():
        d.pop("profile", None)
        d.setdefault("status", ERROR)
    return rec


def finished_count(out: Path, sweep: Sweep) -> int:
    """How many cases of ``sweep`` have their record in ``out`` with their inputs (what a
    rerun skips), read from each ``case.json`` alone."""
    n = 0
    for case in sweep.cases:
        try:
            rec = json.loads((case_folder(out, case.index) / "case.json").read_text())
        except (OSError, ValueError):
            continue
        n += rec.get("digest") == case.digest and "error" not in rec
    return n


def clear_stale_cases(out: Path, count: int) -> None:
    """Remove case folders of an earlier, longer sweep in this folder (index >= count)."""
    clear_stale(Path(out) / "cases", count)

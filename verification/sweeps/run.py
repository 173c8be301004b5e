"""Running a sweep (``riser-verify sweep``): its cases on an :class:`~verification.runtime.engine.Engine`,
resumed from the case folders, then the sweep's tables, plots and report.

The output folder holds one folder per case (``cases/NNNN/``, written as each case comes
back: :mod:`verification.sweeps.case`) and the sweep's own files (:data:`OUTPUTS`), which
are removed before the cases run and written only once every case has a record: an
interrupted or failed run leaves the finished cases (the next run skips them) and no
table or report that could be taken for a complete one.
"""

from __future__ import annotations

import json
import shutil
import time
from dataclasses import dataclass, field
from pathlib import Path

from verification.runtime.engine import Engine
from verification.runtime.progress import UnitTracker

from .case import ERROR, error_record, read_case, run_case, write_case
from .file import Sweep

#: the sweep's own files (``cases/`` aside), cleared before a run
OUTPUTS = ("cases.csv", "envelopes.csv", "report.md", "range_tension.png",
           "range_moment.png", "configurations.png")


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
                if d["status"] != "converged"]

    def warned(self) -> list[tuple[int, str, list[str]]]:
        """(case, method, warnings) of every converged result outside its model's validity
        (riser/validity.py: strain, resolution, surface, seabed, compression)."""
        return [(r["index"], m, d["warnings"]) for r in self.records
                for m, d in r["methods"].items()
                if d["status"] == "converged" and d.get("warnings")]

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
    return every case's record. The engine must be open."""
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
    if resumed and progress is not None:
        progress.log(f"{resumed} of {len(sweep.cases)} case(s) finished by an earlier run: "
                     "skipped")
    specs = [{"index": c.index, "digest": c.digest, "scene": c.scene_dict,
              "methods": list(sweep.methods)} for c in todo]
    workers = engine.workers()
    track = UnitTracker([1.0] * len(specs), workers, what="cases")
    if progress is not None:
        progress.source = track
    t0 = time.perf_counter()
    hosts: set[str] = set()
    names = [f"{sweep.name}-case-{s['index']:04d}" for s in specs]
    for i, res in engine.map(run_case, [(s,) for s in specs], progress, names):
        spec = specs[i]
        if isinstance(res, BaseException):
            res = error_record(spec, f"the worker failed: {type(res).__name__}: {res}")
        write_case(out, res, _scene_text(sweep, sweep.cases[spec["index"]]))
        records[spec["index"]] = read_case(out, spec["index"], spec["digest"]) or \
            _without_profiles(res)
        hosts.add(str(res.get("worker", "")).split(":")[0])
        track.done(i)
        if progress is not None:
            progress.log(case_line(records[spec["index"]], len(sweep.cases)))
    wall = time.perf_counter() - t0
    ordered = [records[c.index] for c in sweep.cases]
    return SweepRun(sweep, ordered, resumed, len(specs), wall, engine.describe(), workers,
                    sorted(h for h in hosts if h))


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


def clear_stale_cases(out: Path, count: int) -> None:
    """Remove case folders of an earlier, longer sweep in this folder (index >= count)."""
    for folder in (out / "cases").glob("[0-9][0-9][0-9][0-9]*"):
        if folder.is_dir() and folder.name.isdigit() and int(folder.name) >= count:
            shutil.rmtree(folder)

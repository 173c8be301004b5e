"""``riser-verify bench --sweep [SWEEP]``: the sweep throughput of the engines, side by
side in one run, on the same sweep (default the built-in ``scr-envelope``, 12 cases).

Each engine runs the whole sweep into a fresh temporary folder (nothing skipped by resume)
through :func:`verification.sweeps.run.run`: one local worker (this process, as ``--jobs 1``),
two local worker processes, and a local Dask cluster of two workers
(:func:`verification.runtime.dask_local.local_cluster`; skipped, with the reason, without the
extra ``[cluster]``). Timed: the whole run with the engine's start (pool spawn, imports and
Numba cache load in fresh workers, the client's connection; the cluster's own start
apart), the time to the first case, and the steady state (the cases after the first
``workers`` ones). For the scaling plan: the Dask scheduler's overhead per task (``TASKS``
no-op tasks submitted one by one, as the engine submits cases) and what the submitting
process does per case (unpickle the record, :func:`write_case`, :func:`read_case`). Cases
per minute grow about linearly with workers until one of them saturates:
``N_max ~ case time / max(scheduler ms per task, client ms per case)``.
"""

from __future__ import annotations

import os
import pickle
import statistics
import sys
import tempfile
import time
import uuid
from pathlib import Path


WORKERS = 2                 # worker processes of the local pool and of the Dask cluster
TASKS, WARMUP_TASKS = 500, 20   # no-op tasks timed on the cluster, after the warm-up ones
IO_REPEATS = 5              # timed writes of one case record (median)
DASK_MISSING = "the optional extra [cluster] (dask.distributed) is not installed"


def _noop(i: int) -> int:
    """The trivial task of the overhead measurement (top level: pickled by reference)."""
    return i


class _Recorder:
    """The ``progress`` of :func:`verification.sweeps.run.run`: when each case came back."""

    def __init__(self, prog, label: str, n: int):
        self.prog, self.label, self.n = prog, label, n
        self.t0 = time.perf_counter()
        self.times: list[float] = []           # s from t0, one per case back
        self.source = None                     # sweep.run sets its tracker here

    def log(self, line: str, err: bool = False) -> None:
        if line.startswith("case "):
            self.times.append(time.perf_counter() - self.t0)
            self.prog(f"{self.label}: {len(self.times)}/{self.n} cases",
                      fraction=len(self.times) / self.n)

    def capture(self):                         # the engines' output goes above the line
        return self.prog.capture()

    def worker_options(self, ctx) -> dict:
        return self.prog.worker_options(ctx)


def _time_engine(sweep, engine, prog, label: str) -> dict:
    """Run the whole sweep on ``engine`` into a fresh folder; its timings."""
    from .run import run
    n = len(sweep.cases)
    with tempfile.TemporaryDirectory(prefix="riser-bench-sweep-") as tmp:
        rec = _Recorder(prog, label, n)
        try:
            engine.open()
            result = run(sweep, Path(tmp), engine, rec)
        finally:
            engine.close()
        wall = time.perf_counter() - rec.t0
    t, w = rec.times, result.workers
    gap = (t[-1] - t[w - 1]) / (n - w) if n > w else None     # s between cases, steady
    return {"engine": result.engine, "workers": w, "cases_run": result.ran,
            "cases_failed": sum(1 for r in result.records if "error" in r),
            "wall_time_s": wall, "cases_per_minute": 60.0 * n / wall, "first_case_s": t[0],
            "steady_cases_per_minute": 60.0 / gap if gap else None,
            "steady_wall_s_per_case": gap}


def _task_overhead(address: str) -> dict:
    """ms per no-op task on the cluster, submitted one by one with unique keys."""
    import distributed
    with distributed.Client(address, set_as_default=False, timeout=30) as client:
        client.gather([client.submit(_noop, i, pure=False) for i in range(WARMUP_TASKS)])
        token = uuid.uuid4().hex[:8]
        t0 = time.perf_counter()
        futures = [client.submit(_noop, i, key=f"noop-{i}-{token}") for i in range(TASKS)]
        client.gather(futures)
        wall = time.perf_counter() - t0
    return {"tasks": TASKS, "wall_s": wall, "ms_per_task": 1e3 * wall / TASKS}


def _record_io(sweep) -> dict:
    """One case solved here (:func:`run_case`); its record's size and what the submitting
    process does with it: unpickle, write_case, read_case (medians of IO_REPEATS)."""
    from .case import read_case, run_case, write_case
    from .run import _scene_text
    case = sweep.cases[0]
    rec = run_case({"index": case.index, "digest": case.digest, "scene": case.scene_dict,
                    "methods": list(sweep.methods)})
    blob = pickle.dumps(rec)
    text = _scene_text(sweep, case)
    times = {"unpickle": [], "write_case": [], "read_case": []}
    with tempfile.TemporaryDirectory(prefix="riser-bench-io-") as tmp:
        for k in range(IO_REPEATS):
            out = Path(tmp) / str(k)
            t0 = time.perf_counter()
            r = pickle.loads(blob)
            t1 = time.perf_counter()
            write_case(out, r, text)
            t2 = time.perf_counter()
            read_case(out, case.index, case.digest)
            times["unpickle"].append(t1 - t0)
            times["write_case"].append(t2 - t1)
            times["read_case"].append(time.perf_counter() - t2)
        disk = sum(p.stat().st_size for p in (Path(tmp) / "0").rglob("*") if p.is_file())
    ms = {f"{k}_ms": 1e3 * statistics.median(v) for k, v in times.items()}
    return {"record_bytes": len(blob), "bytes_on_disk": disk, **ms,
            "client_ms_per_case": sum(ms.values()), "repeats": IO_REPEATS}


def _dask(sweep, prog) -> tuple[dict, dict | None]:
    """The Dask engine's timings and the scheduler's overhead per task."""
    from verification.runtime.engine import Engine, EngineError, require_dask
    try:
        require_dask()                         # the optional extra [cluster]
    except EngineError:
        return {"skipped": DASK_MISSING}, {"skipped": DASK_MISSING}
    from verification.runtime.dask_local import local_cluster
    t0 = time.perf_counter()
    try:
        with local_cluster(WORKERS) as address:
            start = time.perf_counter() - t0
            try:
                timing = _time_engine(sweep, Engine(1, address), prog, "Dask cluster")
            except Exception as exc:           # noqa: BLE001 - recorded, the bench goes on
                timing = {"error": _one_line(exc)}
            timing["cluster_start_s"] = start
            prog("Dask cluster: scheduler overhead", fraction=None)
            try:
                return timing, _task_overhead(address)
            except Exception as exc:           # noqa: BLE001 - recorded
                return timing, {"error": _one_line(exc)}
    except Exception as exc:                   # noqa: BLE001 - the cluster did not start
        return {"error": _one_line(exc)}, None


def _one_line(exc: BaseException) -> str:
    return f"{type(exc).__name__}: {(str(exc).strip().splitlines() or ['no reason'])[0]}"


def _scaling(engines: dict, overhead: dict | None, io: dict) -> dict:
    one = engines["local_1"]                   # a failed case is no case time
    case_s = None if one["cases_failed"] else one["steady_wall_s_per_case"]
    task_ms = (overhead or {}).get("ms_per_task")
    client_ms = io["client_ms_per_case"]
    limits = {"client (unpickle, write_case, read_case)": client_ms}
    if task_ms is not None:
        limits["Dask scheduler"] = task_ms
    what, ms = max(limits.items(), key=lambda kv: kv[1])
    return {"case_time_s": case_s, "scheduler_ms_per_task": task_ms,
            "client_ms_per_case": client_ms, "bottleneck": what,
            "n_max_workers": case_s / (1e-3 * ms) if case_s else None,
            "n_max_workers_by": {k: case_s / (1e-3 * v) if case_s else None
                                 for k, v in limits.items()},
            "formula": "N_max ~ case_time / max(scheduler time per task, client time per "
                       "case); case_time: steady-state seconds per case on one worker"}


def measure(sweep, prog) -> dict:
    from verification.runtime.engine import Engine
    load0 = os.getloadavg()
    engines = {"local_1": _time_engine(sweep, Engine(1), prog, "1 local worker")}
    engines["local_2"] = _time_engine(sweep, Engine(min(WORKERS, len(sweep.cases))), prog,
                                      f"{WORKERS} local workers")
    engines["dask_2"], overhead = _dask(sweep, prog)
    prog("one case's record: size and write time", fraction=None)
    io = _record_io(sweep)
    base = engines["local_1"]["wall_time_s"]
    for e in engines.values():
        if "wall_time_s" in e:
            e["speed_up"] = base / e["wall_time_s"]
    return {"sweep": sweep.name, "source": sweep.source, "cases": len(sweep.cases),
            "methods": list(sweep.methods),
            "machine": {"cpu_count": os.cpu_count(), "load_average_1min_start": load0[0],
                        "load_average_1min_end": os.getloadavg()[0],
                        "python": sys.version.split()[0]},
            "engines": engines, "dask_overhead": overhead, "result_io": io,
            "scaling": _scaling(engines, overhead, io),
            "notes": [f"Measured on this machine, {os.cpu_count()} core(s): with 2 cores 2 "
                      "workers cannot exceed 2x, less when other processes run (load "
                      "averages). local_1 runs in this process (as --jobs 1), the others in "
                      "fresh processes, one BLAS thread each. wall_time_s includes the "
                      "engine's start, not the Dask cluster's own (cluster_start_s). Steady "
                      "state: the cases after the first `workers` ones. The scheduler "
                      "overhead is that of 2 local workers over loopback: N_max is an order "
                      "of magnitude."]}


def summary_lines(b: dict) -> list[str]:
    names = {"local_1": "1 local worker", "local_2": f"{WORKERS} local workers",
             "dask_2": f"Dask cluster, {WORKERS} workers"}
    m = b["machine"]
    lines = [f"sweep {b['sweep']}: {b['cases']} cases, methods {', '.join(b['methods'])}; "
             f"{m['cpu_count']} core(s), load average {m['load_average_1min_start']:.2f} at "
             f"the start, {m['load_average_1min_end']:.2f} at the end",
             f"{'engine':<26}{'wall [s]':>9}{'cases/min':>11}{'speed-up':>10}"
             f"{'1st case [s]':>14}{'steady/min':>12}"]
    for key, e in b["engines"].items():
        if "wall_time_s" not in e or e["cases_failed"]:
            why = e.get("skipped") or e.get("error") or f"{e['cases_failed']} case(s) failed"
            lines.append(f"{names[key]:<26}  {'' if 'skipped' in e else 'failed: '}{why}")
            continue
        steady = e["steady_cases_per_minute"]
        lines.append(f"{names[key]:<26}{e['wall_time_s']:>9.1f}{e['cases_per_minute']:>11.1f}"
                     f"{e['speed_up']:>9.2f}x{e['first_case_s']:>14.1f}"
                     f"{steady if steady is not None else float('nan'):>12.1f}")
    o, io, s = b["dask_overhead"] or {}, b["result_io"], b["scaling"]
    if "ms_per_task" in o:
        lines.append(f"Dask scheduler: {o['ms_per_task']:.2f} ms per task ({o['tasks']} no-op "
                     f"tasks in {o['wall_s']:.2f} s)")
    else:
        lines.append("Dask scheduler overhead: not measured "
                     f"({o.get('skipped') or o.get('error') or 'no cluster'})")
    lines.append(f"a case's record: {io['record_bytes'] / 1e3:.0f} kB pickled, "
                 f"{io['bytes_on_disk'] / 1e3:.0f} kB on disk; client per case "
                 f"{io['client_ms_per_case']:.1f} ms (unpickle {io['unpickle_ms']:.1f}, "
                 f"write_case {io['write_case_ms']:.1f}, read_case {io['read_case_ms']:.1f})")
    if s["n_max_workers"] is not None:
        lines.append(f"limit: N_max ~ {s['case_time_s']:.2f} s a case / "
                     f"{max(s['client_ms_per_case'], s['scheduler_ms_per_task'] or 0):.1f} ms "
                     f"({s['bottleneck']}) ~ {s['n_max_workers']:.0f} workers")
    return lines

"""The ``sweep`` command of the command line: load cases of a scene, solved by several
methods, on this machine's cores or a Dask cluster (:mod:`verification.sweeps.run`)."""

from __future__ import annotations

import os
from pathlib import Path

from riser.errors import SceneError
from verification.runtime import outdir

from .common import MAX_JOBS, Range, add_ranged, check_ranges, err, progress_for

#: --jobs of ``sweep``
JOBS = Range(1, MAX_JOBS, integer=True, what="local worker processes")


def _jobs(args) -> int:
    if args.jobs is None:
        return os.cpu_count() or 1
    check_ranges(args)
    if args.scheduler:
        raise SceneError("command line", "--jobs", "give --jobs (local workers) or "
                         "--scheduler (a Dask cluster's workers), not both")
    return args.jobs


def cmd_sweep(args) -> int:
    """``riser-verify sweep SWEEP.toml [--out DIR] [--jobs N] [--scheduler ADDRESS]``."""
    from verification.runtime.engine import Engine, EngineError
    from verification.sweeps.file import load_sweep
    from verification.sweeps.run import (OUTPUTS, Interrupted, clear_stale_cases,
                                         finished_count, run)
    jobs = _jobs(args)
    # the tables of an earlier run go first, so that a refusal leaves none behind (the
    # case folders stay: they are what a rerun resumes from)
    out = Path(args.out) if args.out else Path("out") / "sweeps" / Path(args.sweep).stem
    outdir.clear(out, OUTPUTS)
    sweep = load_sweep(args.sweep)                 # every case validated: exit 2 first
    engine = Engine(min(jobs, max(1, len(sweep.cases))), args.scheduler)
    total, result = len(sweep.cases), None
    try:
        engine.open()                              # before anything is written
    except EngineError as exc:
        err(str(exc))
        return exc.exit_code
    try:
        try:
            out.mkdir(parents=True, exist_ok=True)
            clear_stale_cases(out, total)
            print(f"sweep {sweep.name}: {total} case(s) of {sweep.base}, methods "
                  f"{', '.join(sweep.methods)}, on {engine.describe()}", flush=True)
            with progress_for(args, f"sweep {sweep.name}") as prog:
                result = run(sweep, out, engine, prog)
        finally:
            engine.close()
        from verification.sweeps.report import write
        files = write(result, out)
    except Interrupted as exc:
        raise KeyboardInterrupt(f"interrupted: {exc.finished} of {total} cases written to "
                                f"{out}; rerun the same command to resume") from None
    except KeyboardInterrupt:                      # starting, or writing the tables
        done = total if result is not None else finished_count(out, sweep)
        raise KeyboardInterrupt(f"interrupted: {done} of {total} cases written to {out}; "
                                "rerun the same command to resume") from None
    fails, bad, warned = result.failures(), result.disagreements(), result.warned()
    rate = result.cases_per_minute
    print(f"sweep {sweep.name}: ran {result.ran} case(s) in {result.wall_time_s:.1f} s"
          + (f" ({rate:.2f} cases per minute)" if rate else "")
          + (f", {result.resumed} skipped (finished earlier)" if result.resumed else ""))
    print(f"  {len(fails)} method run(s) without convergence, {len(bad)} case(s) where the "
          f"methods disagree, {len(warned)} result(s) with warnings"
          + (": see report.md" if fails or bad or warned else ""))
    print(f"  wrote {out}/: {', '.join(files)}, cases/")
    return 1 if fails or bad or (warned and args.strict) else 0


def add_parsers(sub) -> None:
    s = sub.add_parser("sweep", help="load cases of a scene (a sweep file), each solved by "
                       "several methods, with envelopes and the methods' agreement per case")
    s.add_argument("sweep", help="sweep file (.toml: base, methods, [[vary]] key/values)")
    s.add_argument("--out", help="output directory (default out/sweeps/SWEEP); a rerun "
                   "into it skips the finished cases")
    add_ranged(s, "--jobs", JOBS, default=None, metavar="N",
               help="local worker processes (default: this machine's cores)")
    s.add_argument("--scheduler", help="run the cases on a Dask cluster instead: its "
                   "scheduler's address, tcp://host:port (the optional extra [cluster]); "
                   "probed first: one line within seconds if it is not one")
    s.add_argument("--strict", action="store_true", help="exit 1 also when a result "
                   "carries warnings (outside its model's validity)")
    s.set_defaults(func=cmd_sweep)

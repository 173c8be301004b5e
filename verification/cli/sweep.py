"""The ``sweep`` command of the command line: load cases of a scene, solved by several
methods, on this machine's cores or a Dask cluster (:mod:`verification.sweeps.run`)."""

from __future__ import annotations

from pathlib import Path

from verification.runtime import outdir

from .common import add_engine, err, jobs_of, progress_for


def cmd_sweep(args) -> int:
    """``riser-verify sweep SWEEP.toml [--out DIR] [--jobs N] [--scheduler ADDRESS]``."""
    from verification.runtime.engine import Engine, EngineError
    from verification.sweeps.file import load_sweep
    from verification.sweeps.run import (OUTPUTS, Interrupted, clear_stale_cases,
                                         finished_count, run)
    jobs = jobs_of(args)
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
    design = result.design_failures()
    if result.design_checked():
        print(f"  design checks: {len({i for i, _, _ in design})} case(s) fail "
              + ("(design_fails: see report.md)" if design else "(every case passes)"))
        for i, m, lines in design:
            for line in lines:
                print(f"  design_fails: case {i} {m}: {line}")
    print(f"  wrote {out}/: {', '.join(files)}, cases/")
    if design and args.strict:
        err(f"sweep {sweep.name}: {len(design)} result(s) fail a design check and --strict")
    return 1 if fails or bad or ((warned or design) and args.strict) else 0


def add_parsers(sub) -> None:
    s = sub.add_parser("sweep", help="load cases of a scene (a sweep file), each solved by "
                       "several methods, with envelopes and the methods' agreement per case")
    s.add_argument("sweep", help="sweep file (.toml: base, methods, [[vary]] key/values)")
    s.add_argument("--out", help="output directory (default out/sweeps/SWEEP); a rerun "
                   "into it skips the finished cases")
    add_engine(s, "cases")
    s.add_argument("--strict", action="store_true", help="exit 1 also when a result "
                   "carries warnings (outside its model's validity) or fails a design check "
                   "(design_fails)")
    s.set_defaults(func=cmd_sweep)

"""The commands that regenerate reports: ``reproduce NAME``, ``stress``, ``cost SCENE``,
and ``regress`` (the built-in scenes against their stored summaries)."""

from __future__ import annotations

import os
from pathlib import Path

from riser.errors import SceneError
from verification.catalog import resolve
from verification.runtime import outdir
from verification.studies import STUDIES

from .common import MAX_JOBS, Range, add_ranged, check_ranges, err, out_folder, progress_for

#: --jobs of ``reproduce`` and --repeats of ``cost``
JOBS = Range(1, MAX_JOBS, integer=True, what="worker processes")
REPEATS = Range(1, 100, integer=True, what="timed runs per setting")


def cmd_reproduce(args) -> int:
    from verification.studies.reproduce import reproduce
    check_ranges(args)
    with progress_for(args, f"reproduce {args.name}") as prog:
        run = reproduce(args.name, out=Path(args.out) if args.out else None, jobs=args.jobs,
                        full=args.full, progress=prog)
    print(f"reproduce {args.name}: {run.units} unit(s) in {run.wall_s:.0f} s with {run.jobs} "
          "process(es)")
    for line in run.failed:
        err(line)
    if run.failed:
        return 1
    if run.index is not None:
        print(f"index: {run.index}")
    return 0


def cmd_regress(args) -> int:
    from verification import regress
    problems = regress.run(update=args.update, names=args.scenes or None)
    for line in problems:
        print(line)
    if problems:
        print(f"{len(problems)} regression difference(s); rerun with --update if intended")
        return 1
    return 0


def cmd_stress(args) -> int:
    from verification.studies import stress
    out = Path(args.out) if args.out else Path("reports") / "stress"
    known = stress.hard_scenes()
    for name in args.scenes or ():
        if name not in known:
            raise SceneError(name, "", f"not a hard scene (known: {', '.join(known)})")
    outdir.clear(out, outdir.STRESS)
    with progress_for(args, "stress") as prog:
        df = stress.run(out, names=args.scenes or None, log=prog.log, progress=prog)
    silent = df[df.outcome == "SILENT FAILURE"]
    print(f"stress: {len(df)} runs, {len(silent)} silent failure(s); wrote {out}/report.md")
    return 1 if len(silent) else 0


def cmd_cost(args) -> int:
    from verification.studies import cost
    outdir.clear(args.out, outdir.COST)
    check_ranges(args)
    scene = resolve(args.scene)
    out = out_folder(args, Path("reports") / "cost" / scene.name, outdir.COST)
    with progress_for(args, f"cost {scene.name}") as prog:
        prog("solving the reference and the first settings", fraction=0.0)
        st = cost.study(scene, repeats=args.repeats, quick=args.quick, progress=prog,
                        full=args.full)
    cost.write(st, out)
    print(f"{scene.name}: cost study of {len(st.runs)} runs in {st.elapsed_s:.0f} s; "
          f"wrote {out}/runs.csv, report.md")
    return 0


def add_parsers(sub) -> None:
    s = sub.add_parser("reproduce", help="regenerate a paper reproduction report")
    s.add_argument("name", choices=(*STUDIES, "all"))
    add_ranged(s, "--jobs", JOBS, default=min(2, os.cpu_count() or 1), metavar="N",
               help="worker processes (default: min(2, cores)); 1 runs serially")
    s.add_argument("--out", help="output directory (default reports/NAME)")
    s.add_argument("--full", action="store_true",
                   help="the cost study's full sweep (order sweep at tight tolerances, every "
                        "relaxation setting): 5-7 min a cost scene instead of 1.5-2.5")
    s.set_defaults(func=cmd_reproduce)
    s = sub.add_parser("regress", help="compare every built-in scene with its stored summary")
    s.add_argument("scenes", nargs="*", help="only these built-in scenes")
    s.add_argument("--update", action="store_true", help="rewrite the stored summaries")
    s.set_defaults(func=cmd_regress)
    s = sub.add_parser("stress", help="run the hard-case suite with both methods")
    s.add_argument("scenes", nargs="*", help="only these hard scenes")
    s.add_argument("--out", help="output directory (default reports/stress)")
    s.set_defaults(func=cmd_stress)
    s = sub.add_parser("cost", help="accuracy-versus-cost study of both methods on a scene")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--out", help="output directory (default reports/cost/SCENE)")
    add_ranged(s, "--repeats", REPEATS, default=3, metavar="N",
               help="timed runs per setting (median; default 3)")
    s.add_argument("--quick", action="store_true",
                   help="coarse subset of settings (development)")
    s.add_argument("--full", action="store_true",
                   help="full sweep: adds the order sweep at tight tolerances (the order fit, "
                        "the VFIFE limit) and every relaxation setting; 6-10x the time (4-5 "
                        "min a built-in scene)")
    s.set_defaults(func=cmd_cost)

"""Command line: ``riser-verify <command>``. Nothing imports this module.

A command imports the solvers, pandas and matplotlib only when it runs (inside its
function): loading them all costs ~3 s, and ``scenes`` or a bad-input error need none.

Exit codes: 0 success; 1 a solver did not converge, a comparison failed, or an unexpected
error (one line each, the reason printed); 2 bad input (a scene error naming the file and
key, or a scene the method cannot represent, refused before solving).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

from riser.errors import SceneError, SolveFailed, UnsupportedSceneError
from riser.result import METHODS

from . import outdir
from .catalog import list_builtin, resolve
from .progress import Progress, UnitTracker
from .studies import STUDIES


def _err(msg: str) -> None:
    print(f"error: {msg}", file=sys.stderr)


def _progress(args, label: str) -> Progress:
    """The progress display of a long command (on a terminal, unless ``--quiet``)."""
    return Progress(label, quiet=getattr(args, "quiet", False))


def _out(args, default: Path, names: tuple[str, ...]) -> Path:
    """The output folder: ``--out`` (cleared before the scene was read, so that bad input
    leaves nothing stale) or ``default`` (known once the scene is), cleared now of the
    files ``names`` an earlier run left."""
    if args.out:
        return Path(args.out)
    outdir.clear(default, names)
    return default


def cmd_scenes(args) -> int:
    items = list_builtin()
    width = max(len(n) for n, _ in items)
    for name, title in items:
        print(f"{name:<{width}}  {title}")
    return 0


def _check_overrides(scene, args) -> None:
    """Validate the command-line overrides exactly like their scene keys (the settings'
    one validator), naming the option: ``error: command line: --element-length: ...``."""
    from riser.validity import check_resolution
    options = {"--tolerance": ("bvp", "tolerance", getattr(args, "tolerance", None)),
               "--element-length": ("vfife", "element_length",
                                    getattr(args, "element_length", None))}
    for option, (table, key, value) in options.items():
        if value is None:
            continue
        try:
            getattr(scene, table).override(**{key: value})
            if key == "element_length":
                check_resolution(scene, value, source="command line", key=option)
        except SceneError as exc:
            raise SceneError("command line", option, exc.message) from None


def _warn(res, strict: bool) -> int:
    """Print a result's named warnings (stderr); with ``--strict`` they fail the run."""
    for w in res.warnings:
        print(f"warning: {res.method}: {w}", file=sys.stderr)
    if strict and res.warnings:
        _err(f"{res.method} on {res.scene}: {len(res.warnings)} warning(s) and --strict: the "
             "result is outside the model's validity (see summary.json 'warnings')")
        return 1
    return 0


def cmd_solve(args) -> int:
    from . import pipeline
    outdir.clear(args.out, outdir.SOLVE)      # before reading: bad input leaves nothing stale
    scene = resolve(args.scene)
    out = _out(args, Path("out") / scene.name / args.method, outdir.SOLVE)
    _check_overrides(scene, args)
    with _progress(args, f"solve {scene.name} [{args.method}]") as prog:
        res = pipeline.solve_scene(scene, args.method, tolerance=args.tolerance,
                                   element_length=args.element_length, progress=prog)
    res.write(out)
    if not res.converged:
        _err(f"{args.method} on {scene.name}: {res.status.value} ({res.status.meaning}): "
             f"{res.message}")
        return res.status.exit_code
    sm = res.summary()
    print(f"{scene.name} [{args.method}]: {res.message} in {res.wall_time_s:.3f} s")
    print(f"  hang-off tension {sm['hang_off_tension'] / 1e3:.2f} kN, angle "
          f"{sm['hang_off_angle_deg']:.3f} deg, at x = {sm['hang_off_x']:.2f} m, "
          f"y = {sm['hang_off_height']:.2f} m")
    if sm.get("tdp_x") is not None:
        print(f"  touchdown x = {sm['tdp_x']:.2f} m, tension {sm['tdp_tension'] / 1e3:.2f} kN")
    if res.dynamics is None:
        print(f"  max tension {sm['max_tension'] / 1e3:.2f} kN, max moment "
              f"{sm['max_moment'] / 1e3:.3f} kN m at s = {sm['max_moment_s']:.1f} m")
        print(f"  wrote {out}/profile.csv and summary.json")
        return _warn(res, args.strict)
    from .dynamics_report import summary_lines, write_plots
    write_plots(res.dynamics, out, f"{scene.name} [{args.method}]", sm["statistics_start"])
    print(f"  static: max tension {sm['max_tension'] / 1e3:.2f} kN, max moment "
          f"{sm['max_moment'] / 1e3:.3f} kN m at s = {sm['max_moment_s']:.1f} m")
    for line in summary_lines(sm):
        print(line)
    files = [f for f in outdir.SOLVE if (out / f).exists()]
    print(f"  wrote {out}/: {', '.join(files)}")
    return _warn(res, args.strict)


def cmd_reproduce(args) -> int:
    from .engine import Engine
    from .index import write_index
    from .studies import run_unit, study, units
    base = Path(args.out) if args.out else None

    def out_of(study_name: str) -> str:
        if base is None:
            return str(Path("reports") / study_name)
        return str(base / study_name if args.name == "all" else base)

    todo = units(args.name, args.full)
    for name, unit in todo:                   # no report of an earlier run survives a failure
        outdir.clear_unit(name, unit, out_of(name))
    jobs = max(1, min(args.jobs, len(todo)))
    t0 = time.perf_counter()
    note = (f"Timings measured while `riser-verify reproduce {args.name}` ran other units in "
            f"{jobs - 1} more worker process(es) on this {os.cpu_count()}-core machine; run "
            "`riser-verify cost SCENE` alone for uncontended timings." if jobs > 1 else "")
    # progress: units done, weighted by the studies' declared seconds; the units' own
    # output is printed above the status line. The units run on the sweep's engine.
    track = UnitTracker([study(n).unit_seconds(u, args.full) for n, u in todo], jobs)
    failed = []
    with _progress(args, f"reproduce {args.name}") as prog:
        prog.source = track
        work = [(*u, out_of(u[0]), note, args.full) for u in todo]
        for i, out in Engine(jobs).map(run_unit, work, prog):
            if isinstance(out, BaseException):      # the others go on; said at the end
                failed.append(f"{todo[i][0]} {todo[i][1] or ''}".strip() + f": {out}")
                out = f"{failed[-1]} (FAILED)"
            prog.log(out)
            track.done(i)
    print(f"reproduce {args.name}: {len(todo)} unit(s) in {time.perf_counter() - t0:.0f} s "
          f"with {jobs} process(es)")
    for line in failed:
        _err(line)
    if failed:
        return 1
    if base is None:
        print(f"index: {write_index(Path('reports'))}")
    elif args.name == "all":
        print(f"index: {write_index(base)}")
    return 0


def cmd_compare(args) -> int:
    from . import compare, compare_report
    outdir.clear(args.out, outdir.COMPARE)
    scene = resolve(args.scene)
    out = _out(args, Path("out") / scene.name / "compare", outdir.COMPARE)
    _check_overrides(scene, args)
    if args.peer:
        from .cli_moordyn import check_segment_length
        from .peer_moordyn import require
        check_segment_length(args.peer_segment_length, "--peer-segment-length", scene)
        require()                              # before solving: a clear message if missing
    with _progress(args, f"compare {scene.name}") as prog:
        comp = compare.compare(scene, element_length=args.element_length,
                               paper_model=not args.no_paper_model, progress=prog)
        if args.peer:
            from .compare_moordyn import peer_column
            peer_column(comp, out / "moordyn", segment_length=args.peer_segment_length,
                        progress=prog, agreement=compare.agreement)
    compare_report.write(comp, out)
    for r in comp.rows:
        flag = "ok  " if r["pass"] else "FAIL"
        rel = f"{100 * r['rel_diff']:+.4f} %" if r["rel_diff"] is not None else ""
        print(f"  {flag} {r['quantity']:<22} |diff| {r['abs_diff'] if r['abs_diff'] is not None else float('nan'):.6g} {rel}")
    if comp.analytic_note:
        print(f"  {comp.analytic_note}")
    if comp.moordyn is not None:
        from .compare_moordyn import summary_lines
        print("\n".join(summary_lines(comp)))
    print(f"{scene.name}: {'PASS' if comp.passed else 'FAIL'}; wrote {out}/agreement.csv, report.md")
    warned = max(_warn(comp.bvp, args.strict), _warn(comp.vfife, args.strict))
    peer_ok = comp.moordyn is None or comp.moordyn.converged
    return 0 if comp.passed and not warned and peer_ok else 1


#: most modes per plane the ``modes`` command computes (the BVP refines each one)
MAX_MODES = 50


def cmd_modes(args) -> int:
    from . import modes
    outdir.clear(args.out, modes.FILES)
    if not 1 <= args.count <= MAX_MODES:
        raise SceneError("command line", "--count", f"must be between 1 and {MAX_MODES} (modes "
                         f"per plane), got {args.count}")
    scene = resolve(args.scene)
    out = _out(args, Path("out") / scene.name / "modes", modes.FILES)
    with _progress(args, f"modes {scene.name}") as prog:
        run = modes.run_modes(scene, args.count, out, progress=prog)
    for line in modes.summary_lines(run):
        print(line)
    return 0 if run.all_meet else 1


def cmd_regress(args) -> int:
    from . import regress
    problems = regress.run(update=args.update, names=args.scenes or None)
    for line in problems:
        print(line)
    if problems:
        print(f"{len(problems)} regression difference(s); rerun with --update if intended")
        return 1
    return 0


def cmd_stress(args) -> int:
    from . import stress
    out = Path(args.out) if args.out else Path("reports") / "stress"
    known = stress.hard_scenes()
    for name in args.scenes or ():
        if name not in known:
            raise SceneError(name, "", f"not a hard scene (known: {', '.join(known)})")
    outdir.clear(out, outdir.STRESS)
    with _progress(args, "stress") as prog:
        df = stress.run(out, names=args.scenes or None, log=prog.log, progress=prog)
    silent = df[df.outcome == "SILENT FAILURE"]
    print(f"stress: {len(df)} runs, {len(silent)} silent failure(s); wrote {out}/report.md")
    return 1 if len(silent) else 0


#: the single-section scenes the bench times with the analytic method and the BVP
ANALYTIC_BENCH_SCENES = ("scr-steel", "kang2015-jlay")


def cmd_bench(args) -> int:
    if args.peer:
        from .cli_moordyn import cmd_bench_peer
        return cmd_bench_peer(args, _progress(args, "bench --peer moordyn"))
    if args.sweep:
        from .bench_sweep import cmd_bench_sweep
        return cmd_bench_sweep(args, _progress(args, "bench --sweep"))
    from analytic.bench import median_times as analytic_times
    from bvp.bench import median_times as bvp_times
    from bvp.bench import run_bench as bvp_bench
    from vfife.bench import format_table, run_bench

    from . import wang2014
    out = Path(args.out) if args.out else Path("reports") / "bench"
    outdir.clear(out, outdir.BENCH)
    bench = run_bench(out, wang2014.bench_scene())
    scenes = wang2014.SCENES
    bench["bvp"] = bvp_bench(resolve(scenes[0.0]), [resolve(n) for v, n in scenes.items() if v])
    print(format_table(bench))
    # the analytic method against the BVP on the same single-section scenes, side by side
    single = [resolve(n) for n in ANALYTIC_BENCH_SCENES]
    a_t, b_t = analytic_times(single), bvp_times(single)
    bench["analytic"] = {n: {"analytic_s": a_t[n], "bvp_s": b_t[n], "bvp_over_analytic":
                             b_t[n] / a_t[n]} for n in a_t}
    (out / "bench.json").write_text(json.dumps(bench, indent=2) + "\n")
    for n, r in bench["analytic"].items():
        print(f"analytic: {n} {1e3 * r['analytic_s']:.2f} ms a solve (median), BVP "
              f"{r['bvp_s']:.3f} s: BVP / analytic = {r['bvp_over_analytic']:.0f}")
    b = bench["bvp"]
    print(f"BVP: Wang baseline at tolerance 1e-6 {b['bvp_baseline_s']:.3f} s (median of "
          f"{b['bvp_baseline_runs']}, target < 0.5 s); Table 2 batch of {b['bvp_table2_solves']} "
          f"solves {b['bvp_table2_s']:.2f} s (target < 10 s)")
    print(f"wrote {out}/bench.json")
    return 0


def cmd_cost(args) -> int:
    from . import cost
    outdir.clear(args.out, outdir.COST)
    scene = resolve(args.scene)
    out = _out(args, Path("reports") / "cost" / scene.name, outdir.COST)
    with _progress(args, f"cost {scene.name}") as prog:
        prog("solving the reference and the first settings", fraction=0.0)
        st = cost.study(scene, repeats=args.repeats, quick=args.quick, progress=prog,
                        full=args.full)
    cost.write(st, out)
    print(f"{scene.name}: cost study of {len(st.runs)} runs in {st.elapsed_s:.0f} s; "
          f"wrote {out}/runs.csv, report.md")
    return 0


QUIET_HELP = ("no progress display (shown on stderr only when it is a terminal: a status "
              "line updated in place, with an ETA where the fraction done is known)")


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="riser-verify", description=(
        "Dual-method verification suite for deepwater risers (VFIFE and BVP)."))
    p.add_argument("-q", "--quiet", action="store_true", help=QUIET_HELP)
    sub = p.add_subparsers(dest="command", required=True)
    s = sub.add_parser("scenes", help="list the built-in scenes")
    s.set_defaults(func=cmd_scenes)
    s = sub.add_parser("solve", help="solve one scene with one method")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--method", choices=METHODS, default="bvp")
    s.add_argument("--out", help="output directory (default out/SCENE/METHOD)")
    s.add_argument("--tolerance", type=float, help="bvp: solve_bvp tolerance")
    s.add_argument("--element-length", type=float, help="vfife: element length [m]")
    s.add_argument("--strict", action="store_true",
                   help="exit 1 when the result carries warnings (outside the model's validity)")
    s.set_defaults(func=cmd_solve)
    s = sub.add_parser("reproduce", help="regenerate a paper reproduction report")
    s.add_argument("name", choices=(*STUDIES, "all"))
    s.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1),
                   help="worker processes (default: min(2, cores)); 1 runs serially")
    s.add_argument("--out", help="output directory (default reports/NAME)")
    s.add_argument("--full", action="store_true",
                   help="the cost study's full sweep (order sweep at tight tolerances, every "
                        "relaxation setting): 4-5 min a cost scene instead of 0.5-1")
    s.set_defaults(func=cmd_reproduce)
    s = sub.add_parser("compare", help="solve a scene with both methods and compare them")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--out", help="output directory (default out/SCENE/compare)")
    s.add_argument("--element-length", type=float, help="vfife element length [m]")
    s.add_argument("--no-paper-model", action="store_true",
                   help="skip the secondary comparison with the BVP's paper model (inextensible "
                        "line on a rigid seabed), which is not part of the verdict")
    s.add_argument("--strict", action="store_true",
                   help="exit 1 when either method's result carries warnings")
    s.add_argument("--peer", choices=("moordyn",), help="add a peer code's profile as a "
                   "further column (MoorDyn: the optional extra [moordyn]), not in the verdict")
    s.add_argument("--peer-segment-length", type=float, default=10.0,
                   help="MoorDyn segment length [m] (default 10)")
    s.set_defaults(func=cmd_compare)
    s = sub.add_parser("modes", help="natural modes about the static state, both methods")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--count", type=int, default=10,
                   help="modes per plane (in-plane and out-of-plane; default 10)")
    s.add_argument("--out", help="output directory (default out/SCENE/modes)")
    s.set_defaults(func=cmd_modes)
    s = sub.add_parser("regress", help="compare every built-in scene with its stored summary")
    s.add_argument("scenes", nargs="*", help="only these built-in scenes")
    s.add_argument("--update", action="store_true", help="rewrite the stored summaries")
    s.set_defaults(func=cmd_regress)
    s = sub.add_parser("stress", help="run the hard-case suite with both methods")
    s.add_argument("scenes", nargs="*", help="only these hard scenes")
    s.add_argument("--out", help="output directory (default reports/stress)")
    s.set_defaults(func=cmd_stress)
    s = sub.add_parser("bench", help="VFIFE kernel and solver benchmark")
    s.add_argument("--out", help="output directory (default reports/bench)")
    s.add_argument("--peer", choices=("moordyn",), help="instead: VFIFE against a peer code "
                   "on the same riser and mesh (moordyn.json; the optional extra [moordyn])")
    s.add_argument("--sweep", nargs="?", const="scr-envelope", help="instead: sweep "
                   "throughput (cases per minute) with 1 and 2 local workers and a local Dask "
                   "cluster of 2 workers (sweep.json; default: the built-in sweep scr-envelope)")
    s.set_defaults(func=cmd_bench)
    s = sub.add_parser("cost", help="accuracy-versus-cost study of both methods on a scene")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--out", help="output directory (default reports/cost/SCENE)")
    s.add_argument("--repeats", type=int, default=3,
                   help="timed runs per setting (median; default 3)")
    s.add_argument("--quick", action="store_true",
                   help="coarse subset of settings (development)")
    s.add_argument("--full", action="store_true",
                   help="full sweep: adds the order sweep at tight tolerances (the order fit, "
                        "the VFIFE limit) and every relaxation setting; 6-10x the time (4-5 "
                        "min a built-in scene)")
    s.set_defaults(func=cmd_cost)
    from . import cli_moordyn, cli_sweep
    cli_moordyn.add_parsers(sub)
    cli_sweep.add_parsers(sub)
    for name in ("solve", "compare", "modes", "stress", "cost", "reproduce", "bench", "sweep"):   # after the command
        sub.choices[name].add_argument("-q", "--quiet", action="store_true",
                                       default=argparse.SUPPRESS, help=QUIET_HELP)
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except (SceneError, UnsupportedSceneError) as exc:
        _err(str(exc))
        return 2
    except SolveFailed as exc:
        _err(f"{exc} ({exc.status.value})")
        return 1
    except KeyboardInterrupt:
        _err("interrupted")
        return 130
    except BrokenPipeError:        # the reader went away (`riser-verify scenes | head`)
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())   # no flush error
        return 141                 # 128 + SIGPIPE, as a shell pipeline reports it
    except Exception as exc:       # noqa: BLE001 - one line, never a traceback
        _err(f"unexpected {type(exc).__name__}: {exc} (please report it with the command)")
        return 1


if __name__ == "__main__":
    sys.exit(main())

"""Command line: ``riser-verify <command>``.

Exit codes: 0 success; 1 a solver did not converge (its message is printed); 2 bad input
(a scene error naming the file and key, or a scene the method cannot represent).
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

from riser.errors import SceneError, UnsupportedSceneError

METHODS = ("bvp", "vfife")
STUDIES = ("wang2014", "yu2021", "compare", "stress", "cost")
# scenes with a cross-method comparison report in reports/compare/ (reproduce compare|all)
COMPARE_SCENES = ("wang2014-baseline", "wang2014-current-neg1p5", "wang2014-current-neg0p75",
                  "wang2014-current-0p75", "wang2014-current-1p5", "scr-steel",
                  "yu2021-a1", "yu2021-a2", "yu2021-a2-sheared", "yu2021-a3", "yu2021-a4")


def _err(msg: str) -> None:
    print(f"error: {msg}", file=sys.stderr)


def cmd_scenes(args) -> int:
    from .catalog import list_builtin
    items = list_builtin()
    width = max(len(n) for n, _ in items)
    for name, title in items:
        print(f"{name:<{width}}  {title}")
    return 0


def solve_scene(scene, method: str, **options):
    """Solve ``scene`` with ``method``. A VFIFE run of a scene in a Wang form (touchdown
    tension, or hang-off height and angle) solves its fixed-ends equivalent: the hang-off at
    the BVP's top point and line added on an elastic seabed ahead of the touchdown (stated
    in the result's info); its arc lengths are reported in the scene's own coordinate,
    from the BVP touchdown (the added line has s < 0)."""
    if method == "bvp":
        import bvp
        return bvp.solve(scene, **{k: v for k, v in options.items() if k in ("tolerance",)})
    import dataclasses

    import vfife
    opts = {k: v for k, v in options.items() if k in ("element_length",)}
    if scene.ends.kind != "fixed":
        from vfife.ends import require_vfife_model

        from .equivalence import DEFAULT_SEABED_LENGTH, fixed_ends_via_bvp
        require_vfife_model(scene)
        fixed, note = fixed_ends_via_bvp(scene)
        res = vfife.solve(fixed, **opts)
        res.info["ends_conversion"] = (f"{note}; arc lengths s are measured from the BVP "
                                       f"touchdown (the added line has s < 0)")
        res.scene = scene.name
        if res.profile is not None:
            p = res.profile
            res.profile = dataclasses.replace(
                p, s=p.s - DEFAULT_SEABED_LENGTH,
                tdp_s=None if p.tdp_s is None else p.tdp_s - DEFAULT_SEABED_LENGTH)
        return res
    return vfife.solve(scene, **opts)


def cmd_solve(args) -> int:
    from .catalog import resolve
    scene = resolve(args.scene)
    options = {}
    if args.tolerance is not None:
        options["tolerance"] = args.tolerance
    if args.element_length is not None:
        options["element_length"] = args.element_length
    res = solve_scene(scene, args.method, **options)
    out = Path(args.out) if args.out else Path("out") / scene.name / args.method
    res.write(out)
    if not res.converged:
        _err(f"{args.method} did not converge on {scene.name}: {res.message}")
        return 1
    sm = res.summary()
    print(f"{scene.name} [{args.method}]: {res.message} in {res.wall_time_s:.3f} s")
    print(f"  hang-off tension {sm['hang_off_tension'] / 1e3:.2f} kN, angle "
          f"{sm['hang_off_angle_deg']:.3f} deg, at x = {sm['hang_off_x']:.2f} m, "
          f"y = {sm['hang_off_height']:.2f} m")
    if sm.get("tdp_x") is not None:
        print(f"  touchdown x = {sm['tdp_x']:.2f} m, tension {sm['tdp_tension'] / 1e3:.2f} kN")
    print(f"  max tension {sm['max_tension'] / 1e3:.2f} kN, max moment "
          f"{sm['max_moment'] / 1e3:.3f} kN m at s = {sm['max_moment_s']:.1f} m")
    for w in sm.get("warnings", []) or []:
        print(f"  warning: {w}")
    print(f"  wrote {out}/profile.csv and summary.json")
    return 0


# the units of work of ``reproduce``, longest first (measured wall times [s] of
# ``reproduce all`` in 2 processes on this 2-core machine): ``reproduce all --jobs N``
# hands them to N worker processes (longest-processing-time-first), each unit writing its
# own report directory
UNIT_SECONDS = {("cost", "yu2021-a2-sheared"): 294, ("cost", "wang2014-baseline"): 263,
                ("cost", "yu2021-a3"): 244, ("stress", None): 250, ("wang2014", None): 120,
                ("yu2021", None): 90}


def reproduce_units(name: str) -> list[tuple[str, str | None]]:
    """(study, scene or None) units of ``reproduce NAME``; 'all' is every study."""
    from .cost import COST_SCENES
    units = []
    for study_name in (STUDIES if name == "all" else (name,)):
        if study_name == "compare":
            units += [("compare", s) for s in COMPARE_SCENES]
        elif study_name == "cost":
            units += [("cost", s) for s in COST_SCENES]
        else:
            units.append((study_name, None))
    return sorted(units, key=lambda u: -UNIT_SECONDS.get(u, 15))


def run_unit(study_name: str, scene_name: str | None, out: str, note: str = "") -> str:
    """Run one unit of ``reproduce`` into ``out`` (the study's directory); returns a line
    for the log. Top level so that worker processes can run it."""
    t0 = time.perf_counter()
    out_dir = Path(out)
    if study_name == "wang2014":
        from . import wang2014
        wang2014.run(out_dir)
    elif study_name == "yu2021":
        from . import yu2021
        yu2021.run(out_dir)
    elif study_name == "compare":
        from . import compare, compare_report
        from .catalog import resolve
        try:
            comp = compare.compare(resolve(scene_name))
        except RuntimeError as exc:
            return f"compare {scene_name}: {exc}"
        compare_report.write(comp, out_dir / scene_name)
        return (f"compare {scene_name}: {'PASS' if comp.passed else 'FAIL'} "
                f"({time.perf_counter() - t0:.1f} s)")
    elif study_name == "stress":
        from . import stress
        stress.run(out_dir)
    elif study_name == "cost":
        from . import cost
        from .catalog import resolve
        st = cost.study(resolve(scene_name))
        if note:
            st.notes.append(note)
        cost.write(st, out_dir / scene_name)
        return f"cost {scene_name}: wrote {out_dir / scene_name}/ in {st.elapsed_s:.0f} s"
    return f"{study_name}: wrote {out_dir}/ in {time.perf_counter() - t0:.1f} s"


def cmd_reproduce(args) -> int:
    base = Path(args.out) if args.out else None

    def out_of(study_name: str) -> str:
        if base is None:
            return str(Path("reports") / study_name)
        return str(base / study_name if args.name == "all" else base)

    units = reproduce_units(args.name)
    jobs = max(1, min(args.jobs, len(units)))
    t0 = time.perf_counter()
    note = (f"Timings measured while `riser-verify reproduce {args.name}` ran other units in "
            f"{jobs - 1} more worker process(es) on this {os.cpu_count()}-core machine; run "
            "`riser-verify cost SCENE` alone for uncontended timings." if jobs > 1 else "")
    if jobs == 1:
        for u in units:
            print(run_unit(*u, out_of(u[0]), note), flush=True)
    else:
        import concurrent.futures as cf
        import multiprocessing as mp
        with cf.ProcessPoolExecutor(max_workers=jobs,
                                    mp_context=mp.get_context("spawn")) as pool:
            futures = [pool.submit(run_unit, *u, out_of(u[0]), note) for u in units]
            for f in cf.as_completed(futures):
                print(f.result(), flush=True)
    print(f"reproduce {args.name}: {len(units)} unit(s) in {time.perf_counter() - t0:.0f} s "
          f"with {jobs} process(es)")
    from .index import write_index
    if base is None:
        print(f"index: {write_index(Path('reports'))}")
    elif args.name == "all":
        print(f"index: {write_index(base)}")
    return 0


def cmd_compare(args) -> int:
    from . import compare, compare_report
    from .catalog import resolve
    scene = resolve(args.scene)
    comp = compare.compare(scene, element_length=args.element_length,
                           paper_model=not args.no_paper_model)
    out = Path(args.out) if args.out else Path("out") / scene.name / "compare"
    compare_report.write(comp, out)
    for r in comp.rows:
        flag = "ok  " if r["pass"] else "FAIL"
        rel = f"{100 * r['rel_diff']:+.4f} %" if r["rel_diff"] is not None else ""
        print(f"  {flag} {r['quantity']:<22} |diff| {r['abs_diff'] if r['abs_diff'] is not None else float('nan'):.6g} {rel}")
    print(f"{scene.name}: {'PASS' if comp.passed else 'FAIL'}; wrote {out}/agreement.csv, report.md")
    return 0 if comp.passed else 1


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
    df = stress.run(out, names=args.scenes or None)
    silent = df[df.outcome == "SILENT FAILURE"]
    print(f"stress: {len(df)} runs, {len(silent)} silent failure(s); wrote {out}/report.md")
    return 1 if len(silent) else 0


def cmd_bench(args) -> int:
    import json

    from bvp.bench import run_bench as bvp_bench
    from vfife.bench import format_table, run_bench

    from .catalog import resolve
    from .wang2014 import SCENES
    out = Path(args.out) if args.out else Path("reports") / "bench"
    bench = run_bench(out)
    bench["bvp"] = bvp_bench(resolve(SCENES[0.0]), [resolve(n) for v, n in SCENES.items() if v])
    (out / "bench.json").write_text(json.dumps(bench, indent=2) + "\n")
    print(format_table(bench))
    b = bench["bvp"]
    print(f"BVP: Wang baseline at tolerance 1e-6 {b['bvp_baseline_s']:.3f} s (median of "
          f"{b['bvp_baseline_runs']}, target < 0.5 s); Table 2 batch of {b['bvp_table2_solves']} "
          f"solves {b['bvp_table2_s']:.2f} s (target < 10 s)")
    print(f"wrote {out}/bench.json")
    return 0


def cmd_cost(args) -> int:
    from . import cost
    from .catalog import resolve
    scene = resolve(args.scene)
    out = Path(args.out) if args.out else Path("reports") / "cost" / scene.name
    st = cost.study(scene, repeats=args.repeats, quick=args.quick)
    cost.write(st, out)
    print(f"{scene.name}: cost study of {len(st.runs)} runs in {st.elapsed_s:.0f} s; "
          f"wrote {out}/runs.csv, report.md")
    return 0


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="riser-verify", description=(
        "Dual-method verification suite for deepwater risers (VFIFE and BVP)."))
    sub = p.add_subparsers(dest="command", required=True)
    s = sub.add_parser("scenes", help="list the built-in scenes")
    s.set_defaults(func=cmd_scenes)
    s = sub.add_parser("solve", help="solve one scene with one method")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--method", choices=METHODS, default="bvp")
    s.add_argument("--out", help="output directory (default out/SCENE/METHOD)")
    s.add_argument("--tolerance", type=float, help="bvp: solve_bvp tolerance")
    s.add_argument("--element-length", type=float, help="vfife: element length [m]")
    s.set_defaults(func=cmd_solve)
    s = sub.add_parser("reproduce", help="regenerate a paper reproduction report")
    s.add_argument("name", choices=STUDIES + ("all",))
    s.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1),
                   help="worker processes (default: min(2, cores)); 1 runs serially")
    s.add_argument("--out", help="output directory (default reports/NAME)")
    s.set_defaults(func=cmd_reproduce)
    s = sub.add_parser("compare", help="solve a scene with both methods and compare them")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--out", help="output directory (default out/SCENE/compare)")
    s.add_argument("--element-length", type=float, help="vfife element length [m]")
    s.add_argument("--no-paper-model", action="store_true",
                   help="skip the secondary comparison with the BVP's paper model (inextensible "
                        "line on a rigid seabed), which is not part of the verdict")
    s.set_defaults(func=cmd_compare)
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
    s.set_defaults(func=cmd_bench)
    s = sub.add_parser("cost", help="accuracy-versus-cost study of both methods on a scene")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--out", help="output directory (default reports/cost/SCENE)")
    s.add_argument("--repeats", type=int, default=3,
                   help="timed runs per setting (median; default 3)")
    s.add_argument("--quick", action="store_true",
                   help="coarse subset of settings (development)")
    s.set_defaults(func=cmd_cost)
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except (SceneError, UnsupportedSceneError) as exc:
        _err(str(exc))
        return 2
    except KeyboardInterrupt:
        _err("interrupted")
        return 130


if __name__ == "__main__":
    sys.exit(main())

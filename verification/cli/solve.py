"""``riser-verify scenes`` and ``riser-verify solve SCENE [--method M]``."""

from __future__ import annotations

from pathlib import Path

from riser.result import METHODS, Status
from verification.catalog import list_builtin, resolve
from verification.runtime import outdir

from .common import check_overrides, err, out_folder, print_warnings, progress_for


def cmd_scenes(args) -> int:
    items = list_builtin()
    width = max(len(n) for n, _ in items)
    for name, title in items:
        print(f"{name:<{width}}  {title}")
    return 0


def cmd_solve(args) -> int:
    from verification import pipeline
    outdir.clear(args.out, outdir.SOLVE)      # before reading: bad input leaves nothing stale
    scene = resolve(args.scene)
    out = out_folder(args, Path("out") / scene.name / args.method, outdir.SOLVE)
    check_overrides(scene, args)
    with progress_for(args, f"solve {scene.name} [{args.method}]") as prog:
        res = pipeline.solve_scene(scene, args.method, tolerance=args.tolerance,
                                   element_length=args.element_length, progress=prog)
    if res.status is Status.REFUSED:          # before solving, as bad input: nothing written
        err(res.message)
        return res.status.exit_code
    res.write(out)
    if not res.converged:
        err(f"{args.method} on {scene.name}: {res.status.value} ({res.status.meaning}): "
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
        return print_warnings(res, args.strict)
    from verification.report.dynamics import summary_lines, write_plots
    write_plots(res.dynamics, out, f"{scene.name} [{args.method}]", sm["statistics_start"])
    print(f"  static: max tension {sm['max_tension'] / 1e3:.2f} kN, max moment "
          f"{sm['max_moment'] / 1e3:.3f} kN m at s = {sm['max_moment_s']:.1f} m")
    for line in summary_lines(sm):
        print(line)
    files = [f for f in outdir.SOLVE if (out / f).exists()]
    print(f"  wrote {out}/: {', '.join(files)}")
    return print_warnings(res, args.strict)


def add_parsers(sub) -> None:
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

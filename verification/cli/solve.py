"""``riser-verify scenes`` and ``riser-verify solve SCENE [--method M]``."""

from __future__ import annotations

from pathlib import Path

from riser.results.result import Status
from verification.catalog import list_builtin, resolve
from verification.methods import METHODS
from verification.runtime import outdir

from .common import (ELEMENT_LENGTH, TOLERANCE, add_ranged, check_overrides, check_ranges, err,
                     out_folder, print_verdicts, print_warnings, progress_for)


def cmd_scenes(args) -> int:
    items = list_builtin()
    width = max(len(n) for n, _ in items)
    for name, title in items:
        print(f"{name:<{width}}  {title}")
    return 0


def cmd_solve(args) -> int:
    from verification import pipeline
    outdir.clear(args.out, outdir.SOLVE)      # before reading: bad input leaves nothing stale
    check_ranges(args)
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
    checked = res.profile.utilisation is not None or res.profile.bend_utilisation is not None
    if checked:
        from verification.report.design import write_plot
        write_plot(res.profile, res.dynamics.envelope if res.dynamics else None, out,
                   f"{scene.name} [{args.method}]")
    print(f"{scene.name} [{args.method}]: {res.message} in {res.wall_time_s:.3f} s")
    for line in summary_lines(sm, dynamic=res.dynamics is not None):
        print(line)
    if res.dynamics is None:
        extra = ", utilisation.png" if checked else ""
        print(f"  wrote {out}/profile.csv, summary.json{extra}")
        return _verdicts(res, sm, args.strict)
    from verification.report.dynamics import summary_lines as dynamic_lines, write_plots
    write_plots(res.dynamics, out, f"{scene.name} [{args.method}]", sm["statistics_start"],
                plan=None if scene.is_planar else res.profile)
    for line in dynamic_lines(sm):
        print(line)
    files = [f for f in outdir.SOLVE if (out / f).exists()]
    print(f"  wrote {out}/: {', '.join(files)}")
    return _verdicts(res, sm, args.strict)


def _verdicts(res, sm: dict, strict: bool) -> int:
    """The result's warnings and design verdicts; with ``--strict`` either fails the run."""
    warned = print_warnings(res, strict)
    return max(warned, print_verdicts(f"{res.method} on {res.scene}", sm, strict))


def summary_lines(sm: dict, dynamic: bool = False) -> list[str]:
    """The console lines of a static summary (``summary.json``'s keys, SI): forces in mN,
    N, kN or MN and moments in mN m to MN m as their size asks, with at least 3
    significant digits (a lab model's 1.12 N is not ``0.00 kN``)."""
    from verification.report.units import length, with_unit
    lines = [f"  hang-off tension {with_unit(sm['hang_off_tension'], 'N')}, angle "
             f"{sm['hang_off_angle_deg']:.3f} deg, at x = {length(sm['hang_off_x'])} m, "
             f"y = {length(sm['hang_off_height'])} m"]
    if sm.get("tdp_x") is not None:
        lines.append(f"  touchdown x = {length(sm['tdp_x'])} m, tension "
                     f"{with_unit(sm['tdp_tension'], 'N')}")
    lines.append(f"  {'static: ' if dynamic else ''}max tension "
                 f"{with_unit(sm['max_tension'], 'N')}, max moment "
                 f"{with_unit(sm['max_moment'], 'N m', decimals=3)} at s = "
                 f"{length(sm['max_moment_s'], decimals=1)} m")
    if sm.get("max_utilisation") is not None:           # a scene with [design]
        lines.append(f"  {'static: ' if dynamic else ''}max utilisation "
                     f"({sm['design_code']}) {sm['max_utilisation']:.4f} at s = "
                     f"{length(sm['max_utilisation_s'], decimals=1)} m, max von Mises "
                     f"{sm['max_von_mises'] / 1e6:.1f} MPa"
                     + ("" if sm["design_passes"] else ": FAILS the code check"))
    if sm.get("max_bend_utilisation") is not None:      # a bend limit on a line type
        lines.append(f"  {'static: ' if dynamic else ''}max bend utilisation (curvature "
                     f"against the line type's limit) {sm['max_bend_utilisation']:.4f} at s = "
                     f"{length(sm['max_bend_utilisation_s'], decimals=1)} m"
                     + ("" if sm["max_bend_utilisation"] <= 1.0 else
                        ": FAILS the bend limit"))
    if sm.get("max_lateral_offset") is not None:        # a 3D scene
        off = length(sm["max_lateral_offset"], scale=_span(sm))
        mom = with_unit(sm["max_moment_out_of_plane"], "N m", decimals=3,
                        scale=sm["max_moment"])
        lines.append(f"  {'static: ' if dynamic else ''}largest lateral excursion "
                     f"{off} m from the plane of the ends at "
                     f"s = {length(sm['max_lateral_offset_s'], decimals=1)} m; max "
                     f"out-of-plane moment {mom}" + (
                         " (0: below 1e-9 of the span, of the largest moment: round-off)"
                         if "0" in (off, mom.split()[0]) else ""))
    return lines


def _span(sm: dict) -> float:
    """The hang-off's larger coordinate [m]: the scale of a lateral offset's round-off."""
    return max(abs(sm.get("hang_off_x") or 0.0), abs(sm.get("hang_off_height") or 0.0))


def add_parsers(sub) -> None:
    s = sub.add_parser("scenes", help="list the built-in scenes")
    s.set_defaults(func=cmd_scenes)
    s = sub.add_parser("solve", help="solve one scene with one method")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--method", choices=METHODS, default="bvp")
    s.add_argument("--out", help="output directory (default out/SCENE/METHOD)")
    add_ranged(s, "--tolerance", TOLERANCE, metavar="TOL", help="bvp: solve_bvp tolerance")
    add_ranged(s, "--element-length", ELEMENT_LENGTH, metavar="H",
               help="vfife: element length [m]")
    s.add_argument("--strict", action="store_true",
                   help="exit 1 when the result carries warnings (outside the model's "
                        "validity) or a design check fails (design_fails: the code check, "
                        "fatigue against the design life, a bend limit)")
    s.set_defaults(func=cmd_solve)

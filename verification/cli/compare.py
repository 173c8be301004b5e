"""``riser-verify compare SCENE [--peer NAME]`` and ``riser-verify modes SCENE``."""

from __future__ import annotations

from pathlib import Path

from riser.errors import SceneError
from verification import peers
from verification.catalog import resolve
from verification.runtime import outdir

from .common import (ELEMENT_LENGTH, Range, add_ranged, check_overrides, check_ranges, out_folder,
                     print_verdicts, print_warnings, progress_for)

#: most modes per plane the ``modes`` command computes (the BVP refines each one)
MAX_MODES = 50
#: --count of ``modes``
COUNT = Range(1, MAX_MODES, integer=True, what="modes per plane")
#: each of --amplitudes [m]
AMPLITUDE = Range(0.0, 100.0, lo_open=True, unit="m", what="hang-off motion amplitude")
#: --peer-segment-length of ``compare`` (the peer checks it against the line too: at most
#: a tenth of it)
PEER_SEGMENT_LENGTH = Range(0.01, 1000.0, unit="m",
                            what="the peer's segment length, at most a tenth of the line")


def cmd_compare(args) -> int:
    if getattr(args, "time_domain", False):
        return cmd_compare_time_domain(args)
    if args.dynamics:
        return cmd_compare_dynamics(args)
    if args.amplitudes:
        from riser.errors import SceneError
        raise SceneError("command line", "--amplitudes", "only with --dynamics (the "
                         "amplitude sweep of the dynamic comparison)")
    from verification.comparison.static.protocol import compare, default_columns
    from verification.comparison.static.report import write
    files = outdir.COMPARE + tuple(f for name in peers.names() for f in peers.peer(name).files)
    outdir.clear(args.out, files)
    # with --peer, the peer checks its segment length against the line (a tenth of it)
    check_ranges(args, skip=("peer_segment_length",) if args.peer else ())
    scene = resolve(args.scene)
    out = out_folder(args, Path("out") / scene.name / "compare", files)
    check_overrides(scene, args)
    columns = default_columns()
    if args.peer:
        peer = peers.peer(args.peer)
        columns += (peer.column(scene, segment_length=args.peer_segment_length),)
        peer.require()                         # before solving: a clear message if missing
    with progress_for(args, f"compare {scene.name}") as prog:
        comp = compare(scene, element_length=args.element_length, columns=columns,
                       folder=out, paper_model=not args.no_paper_model, progress=prog)
    write(comp, out)
    for r in comp.rows:
        flag = {True: "ok  ", False: "FAIL", None: "n/a "}[r["pass"]]
        rel = f"{100 * r['rel_diff']:+.4f} %" if r["rel_diff"] is not None else ""
        diff = r["abs_diff"] if r["abs_diff"] is not None else float("nan")
        print(f"  {flag} {r['quantity']:<22} |diff| {diff:.6g} {rel}")
    for res in comp.columns.values():
        for line in res.column.console(res):
            print(line)
    print(f"{scene.name}: {'PASS' if comp.passed else 'FAIL'}; wrote {out}/agreement.csv, "
          "report.md")
    warned = max(print_warnings(comp.bvp, args.strict), print_warnings(comp.vfife, args.strict),
                 _verdicts((comp.bvp, comp.vfife), args.strict))
    return 0 if comp.passed and not warned and comp.columns_ok else 1


def _verdicts(results, strict: bool) -> int:
    """The design verdicts of each result (:func:`print_verdicts`): 1 when one fails and
    ``strict``."""
    codes = [print_verdicts(f"{r.method} on {r.scene}", r.summary(), strict)
             for r in results if r is not None and r.converged]
    return max(codes, default=0)


def parse_amplitudes(text: str | None) -> list[float] | None:
    """--amplitudes 'A,B,...' [m]: each > 0 and <= 100 m (a vessel's motion), at most 12."""
    from riser.errors import SceneError
    if not text:
        return None
    try:
        out = [float(a) for a in text.split(",")]
    except ValueError:
        raise SceneError("command line", "--amplitudes", f"{text!r} must be numbers in "
                         "metres separated by commas, e.g. 0.1,0.3,1,3") from None
    bad = [a for a in out if not (0.0 < a <= AMPLITUDE.hi)]
    if bad or not 1 <= len(out) <= 12:
        raise SceneError("command line", "--amplitudes", f"{text!r}: 1 to 12 amplitudes, "
                         f"each > 0 m and <= {AMPLITUDE.hi:g} m")
    return sorted(set(out))


def cmd_compare_dynamics(args) -> int:
    """``compare SCENE --dynamics``: the static comparison, then the scene's harmonic
    motion (or regular wave) by the frequency domain and the VFIFE
    (verification.comparison.dynamic.protocol); an irregular sea: cmd_compare_sea."""
    from verification.comparison.dynamic import report as dynamics_report
    from verification.comparison.sea import report as sea_report
    from verification.comparison.dynamic.protocol import check_motions, compare_dynamics
    from verification.comparison.static.protocol import compare, default_columns
    from verification.comparison.static.report import report_markdown, write
    from verification.comparison.sea.protocol import is_sea
    files = outdir.COMPARE + dynamics_report.FILES + sea_report.FILES + tuple(
        f for name in peers.names() for f in peers.peer(name).files)
    outdir.clear(args.out, files)
    check_ranges(args)
    amplitudes = parse_amplitudes(args.amplitudes)
    scene = resolve(args.scene)
    if is_sea(scene):
        return cmd_compare_sea(args, scene, files)
    check_motions(scene, amplitudes)          # before solving: exit 2 on a bad motion
    out = out_folder(args, Path("out") / scene.name / "compare-dynamics", files)
    check_overrides(scene, args)
    if args.peer:
        peers.peer(args.peer).require()
    with progress_for(args, f"compare {scene.name} --dynamics") as prog:
        comp = compare(scene, element_length=args.element_length, columns=default_columns(),
                       folder=out, paper_model=False, progress=prog)
        dc = compare_dynamics(scene, amplitudes=amplitudes, element_length=args.element_length,
                              static=comp.bvp, progress=prog, ancf=True)
        write(comp, out)
        peer_md, peer_lines = "", []
        if args.peer and peers.peer(args.peer).dynamic is not None:
            peer_md, peer_lines = peers.peer(args.peer).dynamic(dc, out, prog)
        dynamics_report.write(dc, out, report_markdown(comp, heading="##"), peer_md)
    print(f"{scene.name}: static comparison {'PASS' if comp.passed else 'FAIL'}")
    for line in dynamics_report.console_lines(dc) + peer_lines:
        print(line)
    print(f"{scene.name} dynamics: {'PASS' if dc.passed else 'FAIL'}; wrote "
          f"{out}/dynamic_agreement.csv, report.md")
    warned = max(print_warnings(comp.bvp, args.strict), print_warnings(comp.vfife, args.strict),
                 _verdicts((comp.bvp, comp.vfife), args.strict))
    dyn_warned = args.strict and any(r.warnings for r in dc.results)
    return 0 if comp.passed and dc.passed and not warned and not dyn_warned else 1


def cmd_compare_sea(args, scene, files) -> int:
    """``compare SCENE --dynamics`` of a scene with an irregular sea: the static
    comparison, then the sea by the frequency domain and the VFIFE's record
    (verification.comparison.sea.protocol)."""
    from verification.comparison.sea import report as sea_report
    from verification.comparison.static.protocol import compare, default_columns
    from verification.comparison.static.report import report_markdown, write
    from verification.comparison.sea.protocol import check_sea, compare_sea
    if args.amplitudes:
        raise SceneError("command line", "--amplitudes", "not with an irregular sea (its "
                         "Hs is the scene's)")
    if args.peer:
        raise SceneError("command line", "--peer", "not with an irregular sea (the peers "
                         "compare a harmonic response)")
    check_sea(scene)                           # before solving: exit 2
    out = out_folder(args, Path("out") / scene.name / "compare-dynamics", files)
    check_overrides(scene, args)
    with progress_for(args, f"compare {scene.name} --dynamics (sea)") as prog:
        comp = compare(scene, element_length=args.element_length, columns=default_columns(),
                       folder=out, paper_model=False, progress=prog)
        sc = compare_sea(scene, element_length=args.element_length, static=comp.bvp,
                         progress=prog)
        write(comp, out)
        sea_report.write(sc, out, report_markdown(comp, heading="##"))
    print(f"{scene.name}: static comparison {'PASS' if comp.passed else 'FAIL'}")
    for line in sea_report.console_lines(sc):
        print(line)
    print(f"{scene.name} sea: {'PASS' if sc.passed else 'FAIL'}; wrote "
          f"{out}/sea_agreement.csv, report.md")
    warned = max(print_warnings(comp.bvp, args.strict), print_warnings(comp.vfife, args.strict),
                 _verdicts((comp.bvp, comp.vfife, sc.vfife_result), args.strict))
    return 0 if comp.passed and sc.passed and not warned else 1


def cmd_compare_time_domain(args) -> int:
    """``compare SCENE --time-domain``: the VFIFE against the ANCF on the scene's own
    [dynamics], with tolerances measured from both methods' convergence
    (verification.comparison.nonlinear.protocol)."""
    from verification.comparison.nonlinear import report as nl_report
    from verification.comparison.nonlinear.protocol import check_scene, compare_time_domain
    for flag, given in (("--dynamics", args.dynamics), ("--amplitudes", args.amplitudes),
                        ("--peer", args.peer), ("--element-length", args.element_length),
                        ("--no-paper-model", args.no_paper_model)):
        if given:
            raise SceneError("command line", flag, "not with --time-domain (it runs the "
                             "scene's own [dynamics] at each method's [vfife]/[ancf] "
                             "element lengths and their refinements)")
    outdir.clear(args.out, nl_report.FILES)
    check_ranges(args)
    scene = resolve(args.scene)
    check_scene(scene)                          # before solving: exit 2
    out = out_folder(args, Path("out") / scene.name / "compare-time-domain", nl_report.FILES)
    with progress_for(args, f"compare {scene.name} --time-domain") as prog:
        comp = compare_time_domain(scene, progress=prog)
        nl_report.write(comp, out)
    for line in nl_report.console_lines(comp):
        print(line)
    print(f"{scene.name} time domain: {'PASS' if comp.passed else 'FAIL'}; wrote "
          f"{out}/agreement.csv, tolerances.csv, report.md")
    warned = max(print_warnings(comp.vfife.result, args.strict),
                 print_warnings(comp.ancf.result, args.strict),
                 _verdicts((comp.vfife.result, comp.ancf.result), args.strict))
    return 0 if comp.passed and not warned else 1


def cmd_modes(args) -> int:
    from verification.comparison import modes
    outdir.clear(args.out, modes.FILES)
    check_ranges(args)
    scene = resolve(args.scene)
    out = out_folder(args, Path("out") / scene.name / "modes", modes.FILES)
    with progress_for(args, f"modes {scene.name}") as prog:
        run = modes.run_modes(scene, args.count, out, progress=prog, columns=modes.COLUMNS)
    for line in modes.summary_lines(run):
        print(line)
    return 0 if run.all_meet else 1


def add_parsers(sub) -> None:
    s = sub.add_parser("compare", help="solve a scene with both methods and compare them")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--out", help="output directory (default out/SCENE/compare)")
    add_ranged(s, "--element-length", ELEMENT_LENGTH, metavar="H",
               help="vfife element length [m]")
    s.add_argument("--no-paper-model", action="store_true",
                   help="skip the secondary comparison with the BVP's paper model (inextensible "
                        "line on a rigid seabed), which is not part of the verdict")
    s.add_argument("--strict", action="store_true",
                   help="exit 1 when either method's result carries warnings or fails a "
                        "design check (design_fails)")
    s.add_argument("--peer", choices=peers.names(), help="add a peer code's profile as a "
                   "further column, not in the verdict (each peer is an optional extra: "
                   "pip install -e '.[NAME]')")
    add_ranged(s, "--peer-segment-length", PEER_SEGMENT_LENGTH, default=10.0, metavar="H",
               help="the peer's segment length [m] (default 10)")
    s.add_argument("--dynamics", action="store_true",
                   help="also compare the response to the scene's harmonic "
                        "[dynamics.top_motion]: frequency domain about the BVP static state "
                        "against the VFIFE's time domain (out/SCENE/compare-dynamics)")
    s.add_argument("--amplitudes", metavar="A,B,...",
                   help="with --dynamics: the amplitude sweep [m] (default the scene's "
                        "amplitude), e.g. 0.1,0.3,1,3")
    s.add_argument("--time-domain", action="store_true",
                   help="compare the VFIFE and the ANCF on the scene's own [dynamics] (time "
                        "series, envelopes, touchdown travel, fatigue) with tolerances "
                        "measured from both methods' convergence "
                        "(out/SCENE/compare-time-domain)")
    s.set_defaults(func=cmd_compare)
    s = sub.add_parser("modes", help="natural modes about the static state, both methods "
                       "(and the ANCF as a further column)")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    add_ranged(s, "--count", COUNT, default=10, metavar="N",
               help="modes per plane (in-plane and out-of-plane; default 10)")
    s.add_argument("--out", help="output directory (default out/SCENE/modes)")
    s.set_defaults(func=cmd_modes)

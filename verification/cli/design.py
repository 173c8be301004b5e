"""``riser-verify fatigue SCENE``: fatigue over the scene's scatter diagram by the
methods (the VFIFE's and the ANCF's rainflow, judged against each other at the
touchdown; the frequency domain's record and spectral estimates; see
:mod:`verification.studies.design.fatigue`)."""

from __future__ import annotations

import time
from pathlib import Path

from verification.catalog import resolve
from verification.runtime import outdir

from .common import (ELEMENT_LENGTH, Range, add_engine, add_ranged, check_overrides,
                     check_ranges, err, jobs_of, out_folder, print_verdicts, progress_for)

#: --share of ``fatigue``: the screening's share of the FD's damage
SHARE = Range(0.0, 1.0, lo_open=True, what="share of the frequency domain's damage")
#: the default --share (verification.studies.design.fatigue_scatter.DEFAULT_SHARE: not
#: imported here, the command line starts without the solvers)
DEFAULT_SHARE = 0.90
#: --ancf-cells of ``fatigue``
ANCF_CELLS = Range(0, 100000, integer=True, what="cells the ANCF runs")


def cmd_fatigue(args) -> int:
    from verification.runtime.engine import Engine, EngineError
    from verification.runtime.units import Interrupted
    from verification.studies.design import fatigue, fatigue_report, fatigue_scatter
    outdir.clear(args.out, outdir.FATIGUE)     # before reading: bad input leaves nothing stale
    check_ranges(args)
    jobs = jobs_of(args)
    scene = resolve(args.scene)
    check_overrides(scene, args)
    fatigue.require_fatigue(scene)
    out = out_folder(args, Path("out") / scene.name / "fatigue", outdir.FATIGUE)
    engine = Engine(jobs, args.scheduler)
    try:
        engine.open()                              # before anything is written
    except EngineError as exc:
        err(str(exc))
        return exc.exit_code
    cells = len(scene.design.fatigue.sea_states)
    share = None if args.all else args.share
    print(f"fatigue {scene.name}: {cells} sea state(s) on {engine.describe()}; "
          + ("the time domains on every cell" if share is None else
             f"the frequency domain on every cell, the time domains on those carrying "
             f"{100 * share:g} % of its damage at the touchdown and the hang-off (--all: "
             "every cell)"), flush=True)
    t0 = time.perf_counter()
    again = f"written to {out}/cells; rerun the same command to resume"
    try:
        try:
            with progress_for(args, f"fatigue {scene.name}") as prog:
                res = fatigue_scatter.run_scatter(scene, args.element_length, progress=prog,
                                                  engine=engine, out=out, share=share,
                                                  ancf_cells=args.ancf_cells)
        finally:
            engine.close()
        head = fatigue_report.write(res, out, seconds=time.perf_counter() - t0)
        sm = fatigue_report.write_summary(res, head, out)
    except Interrupted as exc:
        raise KeyboardInterrupt(f"interrupted: {exc.finished} of {exc.total} units "
                                f"{again}") from None
    except KeyboardInterrupt:                      # starting, or writing the report
        raise KeyboardInterrupt(f"interrupted: the units {again}") from None
    print(f"{scene.name}: fatigue over {len(res.states)} sea state(s), records "
          f"{head['record_s']:.0f} s to {max(st.record_s for st in res.states):.0f} s")
    for line in fatigue_report.run_lines(res):
        print(f"  {line}")
    print(f"  touchdown damage per year at s = {head['touchdown_s']:.1f} m (the VFIFE's worst in "
          f"the touchdown zone; report.md: each sea state's share): rainflow (VFIFE) "
          f"{head['touchdown_rainflow']:.4g}, "
          f"Dirlik (FD) {head['touchdown_dirlik']:.4g} (ratio {head['ratio']:.3g}); hang-off "
          f"ratio {head['hang_off_ratio']:.3g}")
    agr = head["ancf"]
    if agr is not None:
        per = ", ".join(f"Hs {r['hs']:g} m x{r['ratio']:.3f}" for r in agr["rows"])
        walls = ", ".join(f"{st.ancf_wall_s:.0f} s" for st in res.states
                          if st.ancf_wall_s is not None)
        print(f"  touchdown damage per year rainflow (ANCF, the same realisation) "
              f"{agr['total']['ancf']:.4g}: ANCF / VFIFE x{agr['total']['ratio']:.3f} in "
              f"total ({per}): {agr['verdict']} (within {100 * agr['tolerance']:.0f} % "
              f"each and in total); ANCF runs {walls}")
    for line in fatigue_report.console_lines(res, head):
        print(f"  {line}")
    print(f"  wrote {out}/: {', '.join(outdir.FATIGUE)}")
    return print_verdicts(f"fatigue on {scene.name}", sm, args.strict)


def add_parsers(sub) -> None:
    s = sub.add_parser("fatigue", help="fatigue over the scene's scatter diagram by both "
                                       "methods (rainflow and spectral)")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file with "
                                 "[design.fatigue] sea states and a wave spectrum")
    s.add_argument("--out", help="output directory (default out/SCENE/fatigue)")
    add_ranged(s, "--element-length", ELEMENT_LENGTH, metavar="H",
               help="vfife and ancf: element length [m] (default the VFIFE's of the "
                    "scene; the ANCF runs the same mesh length)")
    s.add_argument("--strict", action="store_true",
                   help="exit 1 when the fatigue check fails (design_fails: a station's "
                        "life below DFF x [design] design_life)")
    add_engine(s, "sea states' units")
    add_ranged(s, "--share", SHARE, default=DEFAULT_SHARE, metavar="F",
               help="screening: the time domains run on the cells carrying this share of "
                    "the frequency domain's damage per year at the touchdown and the "
                    "hang-off (default %(default)s)")
    s.add_argument("--all", action="store_true", help="the time domains on every cell "
                   "(no screening)")
    add_ranged(s, "--ancf-cells", ANCF_CELLS, default=None, metavar="N",
               help="the ANCF on the N time-domain cells of the largest FD damage at the "
                    "touchdown, on their first realisation (default: every time-domain "
                    "cell; 0: none)")
    s.set_defaults(func=cmd_fatigue)

"""``riser-verify fatigue SCENE``: fatigue over the scene's scatter diagram by both
methods (the VFIFE's rainflow, the frequency domain's spectral estimates; see
:mod:`verification.studies.design.fatigue`)."""

from __future__ import annotations

import time
from pathlib import Path

from verification.catalog import resolve
from verification.runtime import outdir

from .common import (ELEMENT_LENGTH, add_ranged, check_overrides, check_ranges, out_folder,
                     progress_for)


def cmd_fatigue(args) -> int:
    from verification.studies.design import fatigue, fatigue_report
    outdir.clear(args.out, outdir.FATIGUE)     # before reading: bad input leaves nothing stale
    check_ranges(args)
    scene = resolve(args.scene)
    check_overrides(scene, args)
    fatigue.require_fatigue(scene)
    out = out_folder(args, Path("out") / scene.name / "fatigue", outdir.FATIGUE)
    t0 = time.perf_counter()
    with progress_for(args, f"fatigue {scene.name}") as prog:
        res = fatigue.run_scatter(scene, args.element_length, progress=prog)
    head = fatigue_report.write(res, out, seconds=time.perf_counter() - t0)
    print(f"{scene.name}: fatigue over {len(res.states)} sea state(s), records "
          f"{head['record_s']:.0f} s to {max(st.record_s for st in res.states):.0f} s")
    print(f"  touchdown damage per year at s = {head['touchdown_s']:.1f} m (the VFIFE's worst in "
          f"the touchdown zone; report.md: each sea state's share): rainflow (VFIFE) "
          f"{head['touchdown_rainflow']:.4g}, "
          f"Dirlik (FD) {head['touchdown_dirlik']:.4g} (ratio {head['ratio']:.3g}); hang-off "
          f"ratio {head['hang_off_ratio']:.3g}")
    print(f"  wrote {out}/: {', '.join(outdir.FATIGUE)}")
    return 0


def add_parsers(sub) -> None:
    s = sub.add_parser("fatigue", help="fatigue over the scene's scatter diagram by both "
                                       "methods (rainflow and spectral)")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file with "
                                 "[design.fatigue] sea states and a wave spectrum")
    s.add_argument("--out", help="output directory (default out/SCENE/fatigue)")
    add_ranged(s, "--element-length", ELEMENT_LENGTH, metavar="H",
               help="vfife: element length [m] (default the scene's)")
    s.set_defaults(func=cmd_fatigue)

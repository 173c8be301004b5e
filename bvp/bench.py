"""Speed benchmark of the boundary-value solver (issue targets: the Wang baseline at
tolerance 1e-6 in under 0.5 s; Table 2, 10 forward + 4 inverse solves, in under 10 s)."""

from __future__ import annotations

import dataclasses
import statistics
import time

from riser.scene import HangOffAngleEnds, Scene

from .solver import solve


def _timed(scene: Scene, **kw) -> tuple[float, object]:
    t = time.perf_counter()
    res = solve(scene, **kw)
    return time.perf_counter() - t, res


def run_bench(baseline: Scene, current_scenes: list[Scene], repeats: int = 5) -> dict:
    """Median wall time of the baseline solve, and the Table 2 batch: every current scene
    forward with C_Dn as given and with C_Dn = 1.0 (10 solves with the baseline twice) plus
    the 4 current rows inverse (hang-off height and angle of the baseline)."""
    _timed(baseline)                                         # warm-up (imports, caches)
    times = [_timed(baseline, tolerance=1e-6)[0] for _ in range(repeats)]
    sm = solve(baseline).summary()
    t0 = time.perf_counter()
    n = 0
    for sc in [baseline] + list(current_scenes):
        for cdn in (None, 1.0):
            s = sc
            if cdn is not None:
                s = sc.replace(line_types={k: dataclasses.replace(v, drag_normal=cdn)
                                           for k, v in sc.line_types.items()})
            _timed(s)
            n += 1
    for sc in current_scenes:
        _timed(sc.replace(ends=HangOffAngleEnds(hang_off_height=sm["hang_off_height"],
                                                hang_off_angle_deg=sm["hang_off_angle_deg"])))
        n += 1
    return {"bvp_baseline_s": statistics.median(times), "bvp_baseline_runs": repeats,
            "bvp_table2_s": time.perf_counter() - t0, "bvp_table2_solves": n}


def median_times(scenes: list[Scene], repeats: int = 3) -> dict:
    """scene name -> median wall time [s] of ``repeats`` solves at the scene's settings
    (after one warm-up), for side-by-side ratios with the other methods."""
    out = {}
    for sc in scenes:
        _timed(sc)
        out[sc.name] = statistics.median(_timed(sc)[0] for _ in range(repeats))
    return out

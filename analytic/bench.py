"""Speed of the analytic method: the median wall time of a solve (closed forms, root
finding on H and the profile at every station) per scene."""

from __future__ import annotations

import statistics
import time

from riser.model.scene import Scene

from .solver import solve


def median_times(scenes: list[Scene], repeats: int = 21) -> dict:
    """scene name -> median wall time [s] of ``repeats`` solves (after one warm-up)."""
    out = {}
    for sc in scenes:
        solve(sc)
        times = []
        for _ in range(repeats):
            t = time.perf_counter()
            solve(sc)
            times.append(time.perf_counter() - t)
        out[sc.name] = statistics.median(times)
    return out

"""Speed benchmarks of the boundary-value solver: the Wang baseline at tolerance 1e-6 (target
under 0.5 s) and Table 2 (10 forward + 4 inverse solves, under 10 s), and the cost against
the number of segments of one line (:func:`segment_scaling`: a line of 100 segments in
about the time of the same line of 3). Scenes come in as arguments."""

from __future__ import annotations

import dataclasses
import math
import os
import pickle
import resource
import statistics
import subprocess
import sys
import time
import tracemalloc
from pathlib import Path

import numpy as np

from riser.model.scene import HangOffAngleEnds, Scene

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


def rod_ratios(planar: list[Scene], three_d: list[Scene], repeats: int = 3) -> dict:
    """The 3D rod's cost: on each planar scene the median time of the rod (``three_d=True``,
    the same solution to round-off) over the planar solve's, side by side in one run; on
    each 3D scene its median time (a scene with a current across its plane, solved only by
    the rod)."""
    out = {"planar": {}, "3d": {}}
    for sc in planar:
        _timed(sc), _timed(sc, three_d=True)
        tp = statistics.median(_timed(sc)[0] for _ in range(repeats))
        tr = statistics.median(_timed(sc, three_d=True)[0] for _ in range(repeats))
        out["planar"][sc.name] = {"planar_s": tp, "rod_s": tr, "rod_over_planar": tr / tp}
    for sc in three_d:
        _timed(sc)
        out["3d"][sc.name] = {"rod_s": statistics.median(_timed(sc)[0] for _ in range(repeats))}
    return out


def against_reference(scenes: list[Scene], repeats: int = 3) -> dict:
    """Each scene solved as the BVP solves it and as it did before issue 36 (scipy's own
    solve_bvp, unpruned: :func:`bvp.collocation.unpruned`; the grounded guess's grid
    scanned point by point, each point's end sampled: :data:`bvp.beam.guess.SCALAR_GRID`),
    alternately, best of
    ``repeats`` each: {"scenes": {name: {"reference_s", "bvp_s"}}, "reference_s", "bvp_s",
    "speed_up"} (the totals [s] and their ratio). The two give the same solution (the
    same guess; the factorisation's pivot order differs, tests/test_vfife_newton.py)."""
    from .collocation import unpruned
    from .beam.guess import SCALAR_GRID
    rows = {}
    for sc in scenes:
        best = {"reference_s": math.inf, "bvp_s": math.inf}
        for _ in range(repeats):
            with unpruned():
                SCALAR_GRID.on = True
                try:
                    best["reference_s"] = min(best["reference_s"], _timed(sc)[0])
                finally:
                    SCALAR_GRID.on = False
            best["bvp_s"] = min(best["bvp_s"], _timed(sc)[0])
        rows[sc.name] = best
    ref = sum(r["reference_s"] for r in rows.values())
    new = sum(r["bvp_s"] for r in rows.values())
    return {"scenes": rows, "reference_s": ref, "bvp_s": new, "speed_up": ref / new}


def reference_lines(rec: dict) -> list[str]:
    """The console's line on :func:`against_reference`."""
    return [f"BVP against its solver before issue 36 (scipy's own solve_bvp, the guess's "
            f"grid point by point), {len(rec['scenes'])} scenes side by side, best of each: "
            f"{rec['reference_s']:.2f} -> {rec['bvp_s']:.2f} s, x{rec['speed_up']:.2f}"]


def rod_lines(rec: dict) -> list[str]:
    """Console lines of :func:`rod_ratios`."""
    out = [f"BVP 3D rod on planar scenes (same solution): {n} {r['rod_s']:.3f} s vs planar "
           f"{r['planar_s']:.3f} s, rod / planar = {r['rod_over_planar']:.2f}"
           for n, r in rec["planar"].items()]
    out += [f"BVP 3D rod: {n} {r['rod_s']:.3f} s" for n, r in rec["3d"].items()]
    return out


# ------------------------------------------------------------ cost against the segment count
def split_segments(scene: Scene, count: int) -> Scene:
    """The same line in ``count`` segments (at least its own number): each segment cut into
    equal sub-segments, the longest pieces cut first. Same physics, more joints."""
    segs = scene.segments
    cuts = [1] * len(segs)
    while sum(cuts) < count:
        i = max(range(len(segs)), key=lambda k: segs[k].length / cuts[k])
        cuts[i] += 1
    out = [dataclasses.replace(s, length=s.length / c) for s, c in zip(segs, cuts)
           for _ in range(c)]
    return scene.replace(name=f"{scene.name}-{len(out)}-segments", segments=tuple(out))


def discrete_modules(scene: Scene, modules: int, fill: float = 0.3) -> Scene:
    """A lazy wave with its buoyancy as ``modules`` discrete modules, as engineers model
    them: the stretch from the first to the last segment with buoyancy becomes modules
    (``fill`` of the pitch long) and bare gaps, alternating, carrying the same total uplift
    [N] (2 modules - 1 + the other segments in all)."""
    segs = list(scene.segments)
    buoyant = [i for i, s in enumerate(segs) if s.buoyancy > 0.0]
    if not buoyant:
        raise ValueError(f"{scene.name}: no segment with buoyancy")
    i0, i1 = buoyant[0], buoyant[-1]
    zone = sum(s.length for s in segs[i0:i1 + 1])
    uplift = sum(s.buoyancy * s.length for s in segs[i0:i1 + 1])
    pitch = zone / (modules * fill + (modules - 1) * (1.0 - fill))
    lm = fill * pitch if modules > 1 else zone
    mid = []
    for k in range(modules):
        mid.append(dataclasses.replace(segs[i0], length=lm, buoyancy=uplift / (modules * lm),
                                       label=f"module {k + 1}"))
        if k < modules - 1:
            mid.append(dataclasses.replace(segs[i0], length=(1.0 - fill) * pitch,
                                           buoyancy=0.0, label="gap"))
    return scene.replace(name=f"{scene.name}-{modules}-modules",
                         segments=tuple(segs[:i0] + mid + segs[i1 + 1:]))


def _peak_rss_mb() -> float:
    """This process's peak resident set size [MB]: Linux's VmHWM (the high-water mark of
    this program's memory, reset by exec), else getrusage's ru_maxrss (on Linux it keeps
    the forking parent's peak across exec: a child of a 227 MB bench reported 227 MB
    whatever it solved; macOS reports bytes)."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return float(line.split()[1]) / 1e3          # kB
    except OSError:
        pass
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    return peak / (1e6 if sys.platform == "darwin" else 1e3)


def _measure(scene: Scene) -> dict:
    """In a fresh process: the solve's wall time (the second of two, the first warms the
    imports), the process's peak RSS [MB] before and after solving, and the peak of the
    Python allocations during a third solve (tracemalloc: numpy's arrays, scipy's among
    them; not SuperLU's C allocations)."""
    import scipy.integrate  # noqa: F401  (imported before the baseline is read)
    before = _peak_rss_mb()
    solve(scene)
    wall, res = _timed(scene)
    peak = _peak_rss_mb()
    tracemalloc.start()
    solve(scene)
    traced = tracemalloc.get_traced_memory()[1] / 1e6
    tracemalloc.stop()
    return {"segments": len(scene.segments), "status": res.status.value,
            "nodes": res.info.get("nodes"), "wall_s": wall, "peak_rss_mb": peak,
            "rss_before_mb": before, "traced_peak_mb": traced,
            "hang_off_tension": (float(res.profile.tension[-1]) if res.profile is not None
                                 else None)}


#: the child of :func:`measure_in_child`: a fresh interpreter that imports the BVP only
_CHILD = ("import pickle, sys; from bvp.bench import _measure; "
          "sys.stdout.buffer.write(pickle.dumps(_measure(pickle.load(sys.stdin.buffer))))")


def measure_in_child(scene: Scene) -> dict:
    """:func:`_measure` in a fresh interpreter (no other package loaded, whatever the
    caller has), so that its peak RSS is this solve's and the BVP's imports'."""
    root = str(Path(__file__).resolve().parent.parent)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [root] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p])}
    out = subprocess.run([sys.executable, "-c", _CHILD], input=pickle.dumps(scene),
                         capture_output=True, check=True, env=env)
    return pickle.loads(out.stdout)


def segment_scaling(lazy_wave: Scene, baseline: Scene,
                    counts: tuple[int, ...] = (3, 10, 30, 100),
                    modules: tuple[int, ...] = (1, 5, 25, 50)) -> dict:
    """The cost against the number of segments, each solve in a fresh process: three
    families of rows (segments, nodes, wall time, peak RSS): the same physics cut into
    more segments (``baseline``, e.g. the 3-segment Wang riser, and the ``lazy_wave``, at
    ``counts`` segments, the lazy wave from its own count up), and the lazy wave's buoyancy
    as discrete modules (``modules``: 2 m - 1 + 2 segments), and the ratios of the largest
    to the smallest of each family, measured side by side."""
    fams = {
        "same physics, " + baseline.name: [split_segments(baseline, n) for n in counts
                                           if n >= len(baseline.segments)],
        "same physics, " + lazy_wave.name: [split_segments(lazy_wave, n) for n in
                                            sorted({max(n, len(lazy_wave.segments))
                                                    for n in counts})],
        "discrete modules, " + lazy_wave.name: [discrete_modules(lazy_wave, m)
                                                for m in modules],
    }
    out = {}
    for fam, scenes in fams.items():
        rows = [measure_in_child(sc) for sc in scenes]
        segs = np.array([r["segments"] for r in rows], float)
        walls = np.array([r["wall_s"] for r in rows], float)
        out[fam] = {"rows": rows, "wall_ratio_last_over_first": rows[-1]["wall_s"] / rows[0]["wall_s"],
                    "segments_first_last": [rows[0]["segments"], rows[-1]["segments"]],
                    # the slope of log(wall) against log(segments) (issue 36)
                    "exponent": float(np.polyfit(np.log(segs), np.log(walls), 1)[0])}
    return out


def scaling_lines(record: dict) -> list[str]:
    """A console table of :func:`segment_scaling`."""
    lines = ["BVP cost against the segment count (each solve in a fresh process; peak RSS,"
             " the same before solving, and the solve's traced arrays):",
             f"  {'family':44s} {'segments':>8s} {'nodes':>6s} {'wall s':>7s} {'peak MB':>8s}"
             f" {'before':>7s} {'arrays':>7s}"]
    for fam, r in record.items():
        for row in r["rows"]:
            lines.append(f"  {fam:44s} {row['segments']:8d} {row['nodes'] or 0:6d} "
                         f"{row['wall_s']:7.2f} {row['peak_rss_mb']:8.0f} "
                         f"{row['rss_before_mb']:7.0f} {row['traced_peak_mb']:7.1f}")
        lines.append(f"  {fam:44s} time {r['segments_first_last'][1]} / "
                     f"{r['segments_first_last'][0]} segments: "
                     f"{r['wall_ratio_last_over_first']:.2f}"
                     + (f"; exponent {r['exponent']:.2f}" if "exponent" in r else ""))
    return lines

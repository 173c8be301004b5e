"""``riser-verify bench --fatigue [SCENE]``: the throughput of ``riser-verify fatigue`` on
the engines, side by side in one run, on the same scatter diagram.

Each engine runs the whole diagram into a fresh temporary folder (nothing resumed) through
:func:`.fatigue_scatter.run_scatter` with every cell in the time domains (``--all``: one
batch of units, no stage waiting for another) and without the ANCF: this process (as
``--jobs 1``), one local worker process, two local worker processes, and a local Dask
cluster of two workers (:func:`verification.runtime.dask_local.local_cluster`; skipped, with the
reason, without the extra ``[cluster]``). Timed: the whole run with the engine's start
(pool spawn, imports and Numba cache loads in fresh workers, the client's connection;
the cluster's own start apart). The damage per year along s of every engine is compared
with the first's, bit for bit (``identical``). The speed-up is over the one worker
process, which starts as the others do and has one BLAS thread as they have: this
process's default BLAS threads made the same units 10 % slower in one measurement on 2
cores (125 s against 113 s with ``OPENBLAS_NUM_THREADS=1``; equal, 107 s each, in a later
bench run), which a ratio over this process would count as parallelism; both ratios are
recorded.

The default diagram (:func:`bench_scene`) is ``scr-steel-fatigue``'s line and sea made
cheap: 12 wave components, 20 m elements, 8 stress points, six cells of Hs 1 to 6 m,
each two or three realisations of its sea (``record_length`` 60 s): 20 units of 3 to 9 s
each, about two minutes on one worker (the workers' start, spawn, imports and Numba's
cache, is then a small part of the run, as it is of a real diagram's).
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

WORKERS = 2                 # worker processes of the local pool and of the Dask cluster
DASK_MISSING = "the optional extra [cluster] (dask.distributed) is not installed"
#: the default diagram's record [s]: 2 or 3 realisations a cell (its sea repeats after 4 Tp)
RECORD_LENGTH = 60.0
#: the default diagram's cells (Hs [m], Tp [s], probability)
CELLS = ((1.0, 6.0, 0.15), (1.5, 7.0, 0.25), (2.0, 8.0, 0.25), (3.0, 10.0, 0.18),
         (4.5, 11.0, 0.12), (6.0, 13.0, 0.05))


def bench_scene():
    """The default diagram (module docstring)."""
    from riser.design.part import SeaState
    from verification.catalog import resolve
    sc = resolve("scr-steel-fatigue")
    sp = sc.waves.spectrum.replace(components=12)
    f = sc.design.fatigue.replace(points=8, record_length=RECORD_LENGTH, sea_states=tuple(
        SeaState(hs=h, tp=t, probability=p) for h, t, p in CELLS))
    return sc.replace(name="scr-steel-fatigue-bench", waves=sc.waves.replace(spectrum=sp),
                      vfife=sc.vfife.override(element_length=20.0),
                      design=sc.design.replace(fatigue=f))


class _Quiet:
    """The ``progress`` of :func:`.fatigue_scatter.run_scatter`: the units counted on the
    status line instead of a line each."""

    def __init__(self, prog, label: str):
        self.prog, self.label, self.units = prog, label, 0
        self.source = None

    def __call__(self, message, fraction=None):
        self.prog(f"{self.label}: {message}", fraction=fraction)

    def log(self, line: str, err: bool = False) -> None:
        if line.startswith("cell "):
            self.units += 1
            self.prog(f"{self.label}: {self.units} units back", fraction=None)

    def capture(self):
        return self.prog.capture()

    def worker_options(self, ctx) -> dict:
        return self.prog.worker_options(ctx)


def _time_engine(scene, engine, prog, label: str) -> tuple[dict, object]:
    """The whole diagram on ``engine`` into a fresh folder: (its timings, the result)."""
    from .fatigue_scatter import run_scatter
    with tempfile.TemporaryDirectory(prefix="riser-bench-fatigue-") as tmp:
        t0 = time.perf_counter()
        try:
            engine.open()
            res = run_scatter(scene, None, progress=_Quiet(prog, label), ancf=False,
                              engine=engine, out=Path(tmp), share=None)
        finally:
            engine.close()
        wall = time.perf_counter() - t0
    units = res.run["units"]
    return {"engine": res.run["engine"], "workers": res.run["workers"], "units": units,
            "wall_time_s": wall, "units_per_minute": 60.0 * units / wall}, res


def _dask(scene, prog) -> tuple[dict, object]:
    from verification.runtime.engine import Engine, EngineError, require_dask
    try:
        require_dask()
    except EngineError:
        return {"skipped": DASK_MISSING}, None
    from verification.runtime.dask_local import local_cluster
    t0 = time.perf_counter()
    try:
        with local_cluster(WORKERS) as address:
            start = time.perf_counter() - t0
            timing, res = _time_engine(scene, Engine(1, address), prog, "Dask cluster")
            timing["cluster_start_s"] = start
            return timing, res
    except Exception as exc:                   # noqa: BLE001 - recorded, the bench goes on
        return {"error": f"{type(exc).__name__}: "
                f"{(str(exc).strip().splitlines() or ['no reason'])[0]}"}, None


def measure(scene, prog) -> dict:
    """The three engines on ``scene`` (default :func:`bench_scene`), their speed-ups over
    one worker and whether their damage per year is identical to the first's."""
    from verification.runtime.engine import Engine
    load0 = os.getloadavg()
    scene = scene or bench_scene()
    engines, results = {}, {}
    engines["local_1"], results["local_1"] = _time_engine(scene, Engine(1), prog,
                                                          "this process")
    engines["local_1_process"], results["local_1_process"] = _time_engine(
        scene, Engine(1, pool=True), prog, "1 local worker")
    engines["local_2"], results["local_2"] = _time_engine(scene, Engine(WORKERS), prog,
                                                          f"{WORKERS} local workers")
    engines["dask_2"], results["dask_2"] = _dask(scene, prog)
    base = engines["local_1_process"]["wall_time_s"]
    here = engines["local_1"]["wall_time_s"]
    ref = results["local_1"].per_year
    for key, e in engines.items():
        if "wall_time_s" in e:
            e["speed_up"] = base / e["wall_time_s"]
            e["speed_up_over_this_process"] = here / e["wall_time_s"]
            got = results[key].per_year
            e["identical"] = set(got) == set(ref) and all(np.array_equal(got[k], ref[k])
                                                          for k in ref)
    cells = scene.design.fatigue.sea_states
    return {"scene": scene.name, "cells": len(cells), "units": engines["local_1"]["units"],
            "components": scene.waves.spectrum.components,
            "element_length": scene.vfife.element_length,
            "machine": {"cpu_count": os.cpu_count(), "load_average_1min_start": load0[0],
                        "load_average_1min_end": os.getloadavg()[0],
                        "python": sys.version.split()[0]},
            "engines": engines,
            "notes": [f"Measured on this machine, {os.cpu_count()} core(s): with 2 cores 2 "
                      "workers cannot exceed 2x, less when other processes run (the load "
                      "averages). local_1 runs in this process (as --jobs 1, with this "
                      "process's BLAS threads), the others in fresh worker processes, one "
                      "BLAS thread each; speed_up is over local_1_process (one worker "
                      "process: the same start and BLAS threads as the others, so the "
                      "ratio is the parallelism's alone), speed_up_over_this_process over "
                      "local_1 (what --jobs N gains over --jobs 1). Every engine runs every cell's "
                      "FD and one realisation of its time domain (VFIFE) as units, into a "
                      "fresh folder. wall_time_s includes the engine's start, not the Dask "
                      "cluster's own (cluster_start_s). identical: the damage per year "
                      "along s equal to local_1's, bit for bit."]}


def summary_lines(b: dict) -> list[str]:
    names = {"local_1": "this process (--jobs 1)", "local_1_process": "1 local worker",
             "local_2": f"{WORKERS} local workers",
             "dask_2": f"Dask cluster, {WORKERS} workers"}
    m = b["machine"]
    lines = [f"fatigue {b['scene']}: {b['cells']} cells, {b['units']} units "
             f"({b['components']} components, {b['element_length']:g} m elements); "
             f"{m['cpu_count']} core(s), load average {m['load_average_1min_start']:.2f} at "
             f"the start, {m['load_average_1min_end']:.2f} at the end",
             f"{'engine':<26}{'wall [s]':>9}{'units/min':>11}{'speed-up':>10}"
             f"{'identical':>11}   (speed-up over 1 local worker process; over --jobs 1)"]
    for key, e in b["engines"].items():
        if "wall_time_s" not in e:
            lines.append(f"{names[key]:<26}  {'' if 'skipped' in e else 'failed: '}"
                         f"{e.get('skipped') or e.get('error')}")
            continue
        lines.append(f"{names[key]:<26}{e['wall_time_s']:>9.1f}{e['units_per_minute']:>11.1f}"
                     f"{e['speed_up']:>9.2f}x{'yes' if e['identical'] else 'NO':>11}"
                     f"   ({e['speed_up_over_this_process']:.2f}x over --jobs 1)")
    return lines

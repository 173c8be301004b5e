"""The ANCF's rows of the methods' bench (``riser-verify bench``, bench.json ``ancf``),
beside the VFIFE's of :mod:`vfife.bench`, measured in the same run on the same scene
(the bench's Wang riser fixed at its hang-off) and the same dynamic run (a 1.5 m heave at
10 s, ramped over one period, for the VFIFE bench's duration):

- ``compile_s``: the first solve (statics and 1 s of the heave at :data:`WARM_UP_LENGTH`
  m) less the second one, in a fresh process with an empty Numba cache (the kernels'
  compilation); ``cache_load_s`` the same in this process (a cache load, or nothing when
  the kernels are loaded already);
- ``statics``: the Newton statics at :data:`STATIC_LENGTHS` (the ANCF's default 2 m, and
  1 m, the VFIFE bench's mesh): wall time, elements, Newton iterations, load steps, the
  force residual, the hang-off tension and the largest moment; the ratio of the wall time
  at 2 m to the VFIFE's statics at 1 m;
- ``dynamics``: the run at the ANCF's default element length and step (``[ancf]``, 2 m and
  period / 100, taken as period / 120: the step divides the sampling interval): its
  ``dynamic_wall_s``, steps and time step, Newton iterations a step, step halvings, the
  cost per element-step and per element and Newton iteration [us], per simulated second,
  and its ratio to the VFIFE's run of the same motion (1 m, the explicit step) per
  simulated second. Each method at its own default mesh and step, not at matched accuracy:
  the cost study (``riser-verify cost SCENE``, "The ANCF beside the VFIFE") compares them
  at the same accuracy.

The ANCF is reached through the registry (:func:`verification.methods.method`).
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from riser.model.scene import Dynamics, Scene, TopMotion
from verification.methods import method

#: the static runs' element lengths [m]: the ANCF's default and the VFIFE bench's
STATIC_LENGTHS = (2.0, 1.0)
#: the warm-up's element length [m] (a coarse mesh: the kernels, not the mesh, are timed)
WARM_UP_LENGTH = 50.0
#: the heave of the dynamic run (the VFIFE bench's)
HEAVE = TopMotion(axis="y", amplitude=1.5, period=10.0, ramp_time=10.0)


def _warm_up_scene(scene: Scene) -> Scene:
    return scene.replace(dynamics=Dynamics(duration=1.0, output_interval=0.5,
                                           top_motion=TopMotion(axis="y", amplitude=1.5,
                                                                period=10.0, ramp_time=1.0)))


def first_over_second(scene: Scene) -> float:
    """The first short solve of ``scene`` in this process less the second [s]: the
    kernels' compilation or cache load."""
    sc = _warm_up_scene(scene)
    walls = []
    for _ in range(2):
        t0 = time.perf_counter()
        method("ancf").solve(sc, element_length=WARM_UP_LENGTH)
        walls.append(time.perf_counter() - t0)
    return max(0.0, walls[0] - walls[1])


def cold_compile_s() -> float:
    """:func:`first_over_second` of the bench's scene in a fresh process with an empty
    Numba cache [s] (NaN if that process fails)."""
    code = ("from verification.bench.methods import bench_scene; "
            "from verification.bench.ancf import first_over_second; "
            "print(first_over_second(bench_scene()))")
    root = str(Path(__file__).resolve().parents[2])
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, NUMBA_CACHE_DIR=tmp)
        env["PYTHONPATH"] = root + os.pathsep + env.get("PYTHONPATH", "")
        out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                             text=True, timeout=900, cwd=root)
    try:
        return float(out.stdout.strip().splitlines()[-1])
    except (IndexError, ValueError):
        return float("nan")


def _statics(scene: Scene, h: float) -> dict:
    res = method("ancf").solve(scene, element_length=h)
    i = res.info
    ok = res.converged
    return {"element_length": h, "elements": i.get("elements"), "wall_s": res.wall_time_s,
            "converged": ok, "newton_iterations": i.get("newton_iterations"),
            "load_steps": i.get("load_steps"), "force_residual": i.get("force_residual"),
            "hang_off_tension": float(res.profile.tension[-1]) if ok else None,
            "max_moment": float(np.max(res.profile.moment)) if ok else None}


def _dynamics(scene: Scene, duration: float) -> dict:
    res = method("ancf").solve(scene.replace(dynamics=Dynamics(
        duration=duration, output_interval=1.0, top_motion=HEAVE)))
    i = res.info
    wall, steps = i.get("dynamic_wall_s"), i.get("dynamic_steps")
    ne, its = i.get("elements"), i.get("newton_iterations_per_step")
    out = {"duration_s": duration, "element_length": i.get("element_length"),
           "elements": ne, "steps_per_period": scene.ancf.steps_per_period,
           "time_step": i.get("dynamic_time_step"), "steps": steps, "wall_s": wall,
           "converged": res.converged, "newton_iterations_per_step": its,
           "step_halvings": i.get("step_halvings"), "integrator": i.get("integrator"),
           "motion": f"heave {HEAVE.amplitude:g} m, {HEAVE.period:g} s, ramped over one "
                     "period; the ANCF's default element length and step"}
    if res.converged and wall and steps and ne:
        out.update({"us_per_element_step": 1e6 * wall / (ne * steps),
                    "us_per_element_iteration": 1e6 * wall / (ne * steps * its)
                    if its else None,
                    "wall_s_per_simulated_s": wall / duration,
                    "realtime_factor": duration / wall})
    return out


def run(scene: Scene, vfife: dict) -> dict:
    """The ANCF's rows on ``scene`` (the bench's), beside the VFIFE's record ``vfife``
    (:func:`vfife.bench.run_bench`'s, measured before in the same run)."""
    cold = cold_compile_s()
    load = first_over_second(scene)
    statics = [_statics(scene, h) for h in STATIC_LENGTHS]
    vd = vfife.get("dynamics", {})
    duration = float(vd.get("duration_s", 30.0))
    dyn = _dynamics(scene, duration)
    out = {"compile_s": cold, "cache_load_s": load, "statics": statics, "dynamics": dyn}
    vs = vfife.get("static_wall_s")
    if vs and statics[0]["converged"]:
        out["statics_2m_over_vfife_1m"] = statics[0]["wall_s"] / vs
    vw, vsteps, ve = vd.get("wall_s"), vd.get("steps"), vfife.get("static_elements")
    if vw and vsteps and ve and "wall_s_per_simulated_s" in dyn:
        out["vfife_dynamics"] = {"element_length": 1.0, "elements": ve,
                                 "time_step": vd.get("time_step"), "steps": vsteps,
                                 "ns_per_element_step": 1e9 * vw / (ve * vsteps),
                                 "wall_s_per_simulated_s": vw / duration}
        out["dynamics_per_simulated_s_ancf_over_vfife"] = (
            dyn["wall_s_per_simulated_s"] / (vw / duration))
    return out


def summary_lines(record: dict) -> list[str]:
    """The console's lines on the bench's ``ancf`` record."""
    lines = [f"ANCF: compile, cold cache {record['compile_s']:.2f} s; cache load "
             f"{record['cache_load_s']:.2f} s"]
    st = ", ".join(f"{s['element_length']:g} m ({s['elements']} elements) {s['wall_s']:.3f} s, "
                   f"{s['newton_iterations']} Newton iterations" for s in record["statics"])
    ratio = record.get("statics_2m_over_vfife_1m")
    lines.append(f"ANCF statics: {st}" + (f"; 2 m / the VFIFE's 1 m x{ratio:.2f}"
                                          if ratio is not None else ""))
    d = record["dynamics"]
    if "wall_s_per_simulated_s" in d:
        line = (f"ANCF dynamics: {d['element_length']:g} m, step {d['time_step']:.4g} s "
                f"({d['steps']} steps, {d['newton_iterations_per_step']:.2f} Newton "
                f"iterations a step): {d['wall_s']:.2f} s for {d['duration_s']:g} s, "
                f"{d['wall_s_per_simulated_s']:.3f} s per simulated s, "
                f"{d['us_per_element_step']:.2f} us per element-step")
        v = record.get("vfife_dynamics")
        if v is not None:
            line += (f"; the VFIFE (1 m, step {v['time_step']:.3g} s) "
                     f"{v['wall_s_per_simulated_s']:.3f} s per simulated s, "
                     f"{v['ns_per_element_step']:.2f} ns per element-step: ANCF / VFIFE x"
                     f"{record['dynamics_per_simulated_s_ancf_over_vfife']:.2f} (each at its "
                     "default mesh and step; at matched accuracy: the cost study)")
        lines.append(line)
    else:
        lines.append("ANCF dynamics: did not complete")
    return lines

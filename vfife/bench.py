"""VFIFE benchmark: kernel cost per element-step, compile time, statics and dynamics at
1 m elements of a fixed-ends scene. ``run_bench(out_dir, scene)`` writes ``bench.json``;
``format_table(bench)`` renders it for stdout. The caller chooses the scene; the targets
and labels are those of the Wang baseline converted to fixed ends (the BVP's hang-off
point, 300 m of line on the seabed: ~2,900 elements at 1 m).

Kernel cost is measured on the scene at 1 m elements from its static state, single
thread, compilation excluded:
- ``planar``: planar kernel, no current (weight, bending, seabed);
- ``planar_drag``: planar kernel with an in-plane current (drag kernel on);
- ``spatial``: 3D kernel on the same planar scene without current;
- ``spatial_drag``: 3D kernel with an out-of-plane current (heading 90 deg, 1 m/s);
- ``planar_drag_surface``: as ``planar_drag`` with the sea surface on (10 m above the
  hang-off, so every node is checked and stays wet: the cost of the check itself);
- ``planar_drag_surface_waves``: as ``planar_drag_surface`` with a regular wave (4 m, 10
  s): the per-step cost of the waves (the kinematics' Taylor step and the inertia force);
  the whole cost of waves, with the kinematics' evaluation, is the wall time of dynamic
  runs with a regular wave and with a 100-component sea over still water
  (``effect_costs``);
- ``planar_drag_flow`` and ``planar_drag_slug``: as ``planar_drag`` with contents (800
  kg/m3) flowing at 2.5 m/s, steady or as a slug (eta 0.25, 80 m): the flow pass of a
  dynamic run (vfife/flow.py) against the same scene without [internal_flow].
The dynamic run has the still-water drag on, as every dynamic run in water.
"""

from __future__ import annotations

import dataclasses
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from riser.physics.internal_flow import InternalFlow
from riser.model.scene import Current, Dynamics, Scene, TopMotion
from riser.physics.waves import WaveSpectrum, WaveTrain, Waves

from .model import Model
from .solver import solve, warm_up
from .timestep import choose_step, critical_steps

def _cold_compile_s() -> float:
    """Compile time of all kernels in a fresh process with an empty Numba cache [s]."""
    code = ("import time; t=time.perf_counter(); from vfife.solver import warm_up; warm_up(); "
            "print(time.perf_counter()-t)")
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, NUMBA_CACHE_DIR=tmp)
        root = str(Path(__file__).resolve().parents[1])
        env["PYTHONPATH"] = root + os.pathsep + env.get("PYTHONPATH", "")
        out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                             text=True, timeout=600, cwd=root)
    try:
        return float(out.stdout.strip().splitlines()[-1])
    except (IndexError, ValueError):
        return float("nan")


def _kernel_ns(scene, static: Model, planar: bool, nsteps: int = 4000,
               surface: bool = False) -> float:
    m = Model(scene, static.mesh, rot_scale=1.0, added_mass=True, planar=planar,
              surface=surface, flow="dynamic" if scene.internal_flow is not None else None,
              waves=scene.waves is not None)
    m.X[:] = static.X
    m.D[:] = static.D
    if m.use_waves:
        m.waves.evaluate(m.X, 100.0)
    steps = critical_steps(static.mesh, rot_scale=1.0, tension=1e6, added_mass=True)
    dt, _ = choose_step(steps, 0.8)
    m.run(10, dt, 0.0)
    best = float("inf")
    for _ in range(3):
        t0 = time.perf_counter()
        m.run(nsteps, dt, 0.0)
        best = min(best, time.perf_counter() - t0)
    return best / (nsteps * static.mesh.ne) * 1e9


#: the bench's regular wave (per-step kernel cost and a dynamic run) and its sea
REGULAR = Waves(trains=(WaveTrain(height=4.0, period=10.0),), ramp_time=10.0)
SEA = Waves(spectrum=WaveSpectrum(kind="jonswap", hs=4.0, tp=10.0, components=100),
            ramp_time=10.0)


def _wave_costs(scene, surface: float, duration: float) -> dict:
    """Wall time of a dynamic run (duration [s], still water, 1 m elements, the surface
    10 m above the hang-off) with a regular wave and with a 100-component sea over the
    same run without waves: the whole cost of the waves (the kernels' Taylor step and
    inertia, and the kinematics' evaluation per interval, :mod:`vfife.dynamics.waves`)."""
    base = scene.replace(water_depth=surface, dynamics=Dynamics(duration=duration,
                                                                output_interval=0.5))
    walls = {}
    for key, waves in (("still", None), ("regular", REGULAR), ("sea", SEA)):
        r = solve(base.replace(waves=waves), element_length=1.0)
        walls[key] = r.info.get("dynamic_wall_s", float("nan"))
    return {"regular_wave_over_still_dynamics": walls["regular"] / walls["still"],
            "sea_100_components_over_still_dynamics": walls["sea"] / walls["still"]}


def run_bench(out_dir, scene: Scene, *, duration: float = 30.0) -> dict:
    """Benchmark the fixed-ends ``scene`` (no current, no [dynamics]: the bench adds them)
    and write ``out_dir/bench.json``; returns the dict."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    cold = _cold_compile_s()
    t0 = time.perf_counter()
    warm_up()
    cache_load = time.perf_counter() - t0

    stat = solve(scene, element_length=1.0)
    static_model = stat.solver_state
    planar_cur = scene.replace(current=Current(heights=(0.0,), speeds=(1.0,), heading_deg=0.0))
    spatial_cur = scene.replace(current=Current(heights=(0.0,), speeds=(1.0,), heading_deg=90.0))
    ns = {
        "planar": _kernel_ns(scene, static_model, True),
        "planar_drag": _kernel_ns(planar_cur, static_model, True),
        "spatial": _kernel_ns(scene, static_model, False),
        "spatial_drag": _kernel_ns(spatial_cur, static_model, False),
        # a sheared profile at one heading against one turning with height (the second,
        # z-component current pass of a turning profile: issue 32)
        "spatial_drag_profile": _kernel_ns(scene.replace(current=Current(
            heights=(0.0, 1500.0), speeds=(1.0, 1.0), heading_deg=90.0)), static_model, False),
        "spatial_drag_turning": _kernel_ns(scene.replace(current=Current(
            heights=(0.0, 1500.0), speeds=(1.0, 1.0), headings_deg=(90.0, 0.0))),
            static_model, False),
        "planar_drag_surface": _kernel_ns(
            planar_cur.replace(water_depth=float(static_model.X[1, -1]) + 10.0),
            static_model, True, surface=True),
    }
    # contents and a sea surface above the hang-off (the wall tension's sea pressure needs
    # a depth; the kernel runs without its surface path here, surface=False)
    full = scene.replace(line_types={k: dataclasses.replace(lt, contents_density=800.0)
                                     for k, lt in scene.line_types.items()},
                         water_depth=float(static_model.X[1, -1]) + 10.0)
    ns["planar_drag_flow"] = _kernel_ns(full.replace(
        current=planar_cur.current, internal_flow=InternalFlow(speed=2.5)), static_model, True)
    ns["planar_drag_slug"] = _kernel_ns(full.replace(
        current=planar_cur.current, internal_flow=InternalFlow(
            speed=2.5, density_amplitude=0.25, slug_length=80.0)), static_model, True)
    surface = float(static_model.X[1, -1]) + 10.0
    ns["planar_drag_surface_waves"] = _kernel_ns(
        planar_cur.replace(water_depth=surface, waves=REGULAR), static_model, True,
        surface=True)
    dyn_scene = scene.replace(dynamics=Dynamics(duration=duration, output_interval=1.0,
                                               top_motion=TopMotion(axis="y", amplitude=1.5,
                                                                    period=10.0,
                                                                    ramp_time=10.0)))
    dyn = solve(dyn_scene, element_length=1.0)
    waves = _wave_costs(scene, surface, duration)
    bench = {
        "machine": {"python": platform.python_version(), "processor": platform.processor()
                    or platform.machine(), "threads": 1},
        "kernel_ns_per_element_step": {"planar": ns["planar"],
                                       "spatial_drag": ns["spatial_drag"],
                                       "planar_drag": ns["planar_drag"],
                                       "spatial": ns["spatial"],
                                       "planar_drag_surface": ns["planar_drag_surface"],
                                       "planar_drag_flow": ns["planar_drag_flow"],
                                       "planar_drag_slug": ns["planar_drag_slug"],
                                       "spatial_drag_profile": ns["spatial_drag_profile"],
                                       "spatial_drag_turning": ns["spatial_drag_turning"],
                                       "planar_drag_surface_waves":
                                           ns["planar_drag_surface_waves"]},
        "compile_s": cold,
        "cache_load_s": cache_load,
        "static_wall_s": stat.wall_time_s,
        "static_elements": stat.info["elements"],
        "static_steps": stat.info["steps"],
        "static_residual": stat.info["force_residual"],
        "static_hang_off_tension": float(stat.profile.tension[-1]),
        "static_max_moment": float(np.max(stat.profile.moment)),
        "realtime_factor_1m": dyn.info.get("realtime_factor", float("nan")),
        "dynamics": {"duration_s": duration, "time_step": dyn.info.get("dynamic_time_step"),
                     "steps": dyn.info.get("dynamic_steps"),
                     "wall_s": dyn.info.get("dynamic_wall_s"), "converged": dyn.converged,
                     "motion": "heave 1.5 m, 10 s, ramped over one period, Wang baseline, 1 m elements"},
        "effect_costs": {
            "drag_on_over_off_planar": ns["planar_drag"] / ns["planar"],
            "drag_on_over_off_spatial": ns["spatial_drag"] / ns["spatial"],
            "spatial_over_planar": ns["spatial"] / ns["planar"],
            "surface_on_over_off_planar_drag": ns["planar_drag_surface"] / ns["planar_drag"],
            "flow_on_over_off_planar_drag": ns["planar_drag_flow"] / ns["planar_drag"],
            "slug_on_over_off_planar_drag": ns["planar_drag_slug"] / ns["planar_drag"],
            "turning_over_one_heading_spatial_drag": (ns["spatial_drag_turning"]
                                                      / ns["spatial_drag_profile"]),
            "waves_on_over_off_planar_drag_surface": (ns["planar_drag_surface_waves"]
                                                      / ns["planar_drag_surface"]),
            **waves,
        },
        "targets": {"kernel_ns_planar": 6.0, "kernel_ns_spatial_drag": 15.0,
                    "static_wall_s": 2.0, "realtime_factor_1m": 10.0},
    }
    (out / "bench.json").write_text(json.dumps(bench, indent=2) + "\n")
    return bench


def format_table(bench: dict) -> str:
    """Readable table of a bench dict (value, target, pass/fail)."""
    k = bench["kernel_ns_per_element_step"]
    t = bench["targets"]
    rows = [
        ("kernel planar [ns/element-step]", k["planar"], f"<= {t['kernel_ns_planar']:g}",
         k["planar"] <= t["kernel_ns_planar"]),
        ("kernel 3D + drag [ns/element-step]", k["spatial_drag"],
         f"<= {t['kernel_ns_spatial_drag']:g}", k["spatial_drag"] <= t["kernel_ns_spatial_drag"]),
        ("kernel planar + drag", k["planar_drag"], "", None),
        ("kernel 3D, no drag", k["spatial"], "", None),
        ("kernel planar + drag + sea surface", k["planar_drag_surface"], "", None),
        ("kernel planar + drag + internal flow", k["planar_drag_flow"], "", None),
        ("kernel planar + drag + slug flow", k["planar_drag_slug"], "", None),
        ("statics Wang 1 m [s]", bench["static_wall_s"], f"< {t['static_wall_s']:g}",
         bench["static_wall_s"] < t["static_wall_s"]),
        ("dynamics 1 m [x real time]", bench["realtime_factor_1m"],
         f">= {t['realtime_factor_1m']:g}", bench["realtime_factor_1m"] >= t["realtime_factor_1m"]),
        ("compile, cold cache [s]", bench["compile_s"], "", None),
        ("cache load [s]", bench["cache_load_s"], "", None),
    ]
    lines = [f"{'quantity':<38} {'value':>10}  {'target':<8} ok"]
    for name, v, tgt, ok in rows:
        lines.append(f"{name:<38} {v:>10.3f}  {tgt:<8} {'' if ok is None else ('yes' if ok else 'NO')}")
    e = bench["effect_costs"]
    lines.append(f"drag on/off: planar x{e['drag_on_over_off_planar']:.2f}, 3D "
                 f"x{e['drag_on_over_off_spatial']:.2f}; 3D/planar x{e['spatial_over_planar']:.2f}; "
                 f"sea surface on/off (planar + drag) x{e['surface_on_over_off_planar_drag']:.2f}; "
                 f"internal flow on/off (planar + drag) x{e['flow_on_over_off_planar_drag']:.2f}, "
                 f"slug x{e['slug_on_over_off_planar_drag']:.2f}; a current turning with "
                 f"height / one heading (3D + drag) "
                 f"x{e.get('turning_over_one_heading_spatial_drag', float('nan')):.2f}")
    if "waves_on_over_off_planar_drag_surface" in e:
        lines.append(f"waves on/off: kernel (planar + drag + surface) "
                     f"x{e['waves_on_over_off_planar_drag_surface']:.2f}; dynamic run with a "
                     f"regular wave / still water x{e['regular_wave_over_still_dynamics']:.2f}, "
                     f"with a 100-component sea x"
                     f"{e['sea_100_components_over_still_dynamics']:.2f}")
    return "\n".join(lines)

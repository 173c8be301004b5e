"""``riser-verify bench --peer moordyn``: VFIFE and MoorDyn side by side, in one run, on
the same riser and mesh (the bench's scene: the Wang baseline fixed at the paper's hang-off
with 300 m on the seabed, 2,900 m of line, three sections: three MoorDyn lines).

- **Dynamics** at 1 m: the bench's heave (1.5 m, 10 s period, ramped over one period),
  each code at its own stable step: VFIFE's (its step rule), MoorDyn's RK2 at
  ``STEP_FRACTION`` of its CFL-0.5 step (the CFL-0.5 step itself diverges on a riser with
  bending). Reported: the cost per node per step and the simulated seconds per wall
  second. MoorDyn starts from a short static solve (the cost of a step does not depend on
  the state); its hang-off is a Coupled point given the motion every ``COUPLING`` s.
- **Statics** at 10, 2 and 1 m: VFIFE's relaxation to its own tolerance (a force residual
  of 1e-3 of an element's weight, ten times tighter than MoorDyn is asked for) against
  MoorDyn's static solver (``Init``) run with a doubling pseudo-time until its force
  residual is within ``run.RESIDUAL_TOL`` (1 % of a node's weight) or the next run
  would exceed ``STATIC_BUDGET`` of wall time; the time of the first run that reached it.

Only ratios are quoted in docs/moordyn.md: absolute times differ 2-3x between machines.
"""

from __future__ import annotations

import math
import shutil
import tempfile
import time
from pathlib import Path

from riser.model.scene import Dynamics, Scene, TopMotion

from .run import RESIDUAL_TOL, STEP_FRACTION, _residual, _to_log, close, require, start

MESHES = (10.0, 2.0, 1.0)
DYNAMIC_MESH = 1.0
DURATION = 20.0          # s of simulated heave
COUPLING = 0.05          # s between hang-off positions given to MoorDyn
STATIC_BUDGET = 150.0    # s of wall time for MoorDyn's static solve at one mesh
MOTION = dict(axis="y", amplitude=1.5, period=10.0, ramp_time=10.0)


def _heave(t: float) -> tuple[float, float]:
    """Displacement [m] and velocity [m/s] of the bench's ramped heave at time t."""
    a, T, tr = MOTION["amplitude"], MOTION["period"], MOTION["ramp_time"]
    w = 2.0 * math.pi / T
    r, dr = (0.5 * (1 - math.cos(math.pi * t / tr)), 0.5 * math.pi / tr *
             math.sin(math.pi * t / tr)) if t < tr else (1.0, 0.0)
    return a * r * math.sin(w * t), a * (dr * math.sin(w * t) + r * w * math.cos(w * t))


def moordyn_statics(scene: Scene, h: float, work: Path, log) -> dict:
    """Doubling pseudo-time until the residual is within tolerance or out of budget."""
    import moordyn
    pseudo, spent, out = 125.0 if h >= 5 else 25.0, 0.0, {}
    rate = None
    while True:
        if rate is not None and rate * pseudo > STATIC_BUDGET - spent:
            out.setdefault("reached", False)
            break
        system, lines, files, wall, _ = start(scene, work, segment_length=h, pseudo_time=pseudo)
        res = _residual(moordyn, lines, files.scene, files)
        close(system, work)
        spent += wall
        rate = wall / pseudo
        log(f"  MoorDyn {h:g} m: {pseudo:g} s pseudo-time, {wall:.1f} s, residual "
            f"{100 * res:.3g} %")
        out = {"pseudo_time_s": pseudo, "wall_s": wall, "force_residual": res,
               "segments": sum(ln.segments for ln in files.export.deck.lines),
               "total_wall_s": spent}
        if res <= RESIDUAL_TOL:
            out["reached"] = True
            break
        pseudo *= 2.0
    return out


def moordyn_dynamics(scene: Scene, h: float, work: Path) -> dict:
    import cmoordyn
    import moordyn
    system, lines, files, _, _ = start(scene, work, segment_length=h, pseudo_time=20.0,
                                       hang_off="Coupled")
    dt = STEP_FRACTION * cmoordyn.get_dt(system)
    cmoordyn.set_dt(system, dt)
    top = files.export.deck.points[-1]
    nodes = sum(moordyn.GetLineN(ln) + 1 for ln in lines)
    t, ok = 0.0, True
    with _to_log(work / "moordyn.log"):
        t0 = time.perf_counter()
        try:
            while t < DURATION - 1e-9:
                d, v = _heave(t)
                moordyn.Step(system, [top.x, top.y, top.z + d], [0.0, 0.0, v], t, COUPLING)
                t += COUPLING
        except RuntimeError:
            ok = False
        wall = time.perf_counter() - t0
    close(system, work)
    steps = t / dt
    return {"time_step": dt, "steps": steps, "nodes": nodes, "wall_s": wall, "stable": ok,
            "simulated_s": t, "us_per_node_step": wall / steps / nodes * 1e6,
            "simulated_per_wall": t / wall}


def vfife_statics(scene: Scene, h: float) -> dict:
    from verification.methods import method
    res = method("vfife").solve(scene, element_length=h)
    return {"wall_s": res.wall_time_s, "force_residual": res.info["force_residual"],
            "elements": res.info["elements"], "converged": res.converged}


def vfife_dynamics(scene: Scene, h: float) -> dict:
    from verification.methods import method
    dyn = scene.replace(dynamics=Dynamics(duration=DURATION, output_interval=1.0,
                                          top_motion=TopMotion(**MOTION)))
    res = method("vfife").solve(dyn, element_length=h)
    i = res.info
    nodes = i["elements"] + 1
    return {"time_step": i["dynamic_time_step"], "steps": i["dynamic_steps"], "nodes": nodes,
            "wall_s": i["dynamic_wall_s"], "stable": res.converged, "simulated_s": DURATION,
            "us_per_node_step": i["dynamic_wall_s"] / i["dynamic_steps"] / nodes * 1e6,
            "simulated_per_wall": DURATION / i["dynamic_wall_s"]}


def run(scene: Scene, log=print) -> dict:
    """The side-by-side measurements and their ratios (MoorDyn / VFIFE)."""
    require()
    from vfife.solver import warm_up
    warm_up()
    work = Path(tempfile.mkdtemp(prefix="riser-moordyn-bench-"))
    try:
        log(f"dynamics at {DYNAMIC_MESH:g} m, {DURATION:g} s of heave")
        dyn = {"vfife": vfife_dynamics(scene, DYNAMIC_MESH),
               "moordyn": moordyn_dynamics(scene, DYNAMIC_MESH, work)}
        dyn["ratios"] = {
            "cost_per_node_step_moordyn_over_vfife": dyn["moordyn"]["us_per_node_step"]
            / dyn["vfife"]["us_per_node_step"],
            "time_step_vfife_over_moordyn": dyn["vfife"]["time_step"]
            / dyn["moordyn"]["time_step"],
            "speed_vfife_over_moordyn": dyn["vfife"]["simulated_per_wall"]
            / dyn["moordyn"]["simulated_per_wall"]}
        statics = {}
        for h in MESHES:
            log(f"statics at {h:g} m")
            v = vfife_statics(scene, h)
            m = moordyn_statics(scene, h, work, log)
            statics[f"{h:g}"] = {"vfife": v, "moordyn": m,
                                 "moordyn_over_vfife_wall": (m["wall_s"] / v["wall_s"]
                                                             if m.get("reached") else None)}
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return {"scene": scene.name, "dynamics": dyn, "statics": statics,
            "residual_tolerance_moordyn": RESIDUAL_TOL}


def summary_lines(b: dict) -> list[str]:
    d = b["dynamics"]
    v, m, r = d["vfife"], d["moordyn"], d["ratios"]
    out = [f"MoorDyn peer, dynamics at {DYNAMIC_MESH:g} m ({v['nodes']} nodes): VFIFE step "
           f"{v['time_step']:.3g} s, {v['us_per_node_step']:.3g} us/node/step, "
           f"{v['simulated_per_wall']:.3g} s simulated per wall s; MoorDyn step "
           f"{m['time_step']:.3g} s, {m['us_per_node_step']:.3g} us/node/step, "
           f"{m['simulated_per_wall']:.3g} s/s" + ("" if m["stable"] else " (DIVERGED)"),
           f"  ratios: cost per node-step MoorDyn/VFIFE {r['cost_per_node_step_moordyn_over_vfife']:.2f}, "
           f"step VFIFE/MoorDyn {r['time_step_vfife_over_moordyn']:.2f}, speed VFIFE/MoorDyn "
           f"{r['speed_vfife_over_moordyn']:.2f}"]
    for h, s in b["statics"].items():
        vv, mm = s["vfife"], s["moordyn"]
        got = (f"{mm['wall_s']:.1f} s ({mm['pseudo_time_s']:g} s pseudo-time, residual "
               f"{100 * mm['force_residual']:.2g} %)" if mm.get("reached") else
               f"not within {100 * RESIDUAL_TOL:g} % in {mm.get('total_wall_s', 0):.0f} s "
               f"(best {100 * mm.get('force_residual', float('nan')):.2g} %)")
        ratio = (f", MoorDyn/VFIFE {s['moordyn_over_vfife_wall']:.0f}"
                 if s["moordyn_over_vfife_wall"] else "")
        out.append(f"  statics at {h} m: VFIFE {vv['wall_s']:.2f} s (residual "
                   f"{vv['force_residual']:.2g}); MoorDyn {got}{ratio}")
    return out


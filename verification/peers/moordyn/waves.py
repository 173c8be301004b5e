"""MoorDyn (MoorDyn-C v2) in the scene's sea: a time-domain run of a scene with
``[environment.waves]`` (and a ``[vessel]`` or a ``[dynamics.top_motion]`` moving the
hang-off), MoorDyn summing the same wave components (``WaveKin 7``,
:mod:`riser.io.moordyn.waves`) and the hang-off prescribed as its Coupled point.

How it runs:

- **The sea**: the exported deck writes the scene's components (a spectrum's as its seed
  draws them) to ``wave_frequencies.txt``; MoorDyn-C sums them at every node (Airy,
  finite depth, Wheeler stretching; above the surface the surface's values). Its clock
  starts at 0 after Init, the scene's t = 0 of the dynamic run. The scene's half-cosine
  ramp is written as MoorDyn's ``waveKin_rampT`` (a linear ramp over the same time),
  except with a current, which MoorDyn's ramp would ramp too: its waves then start at
  full height (``ramp`` in the result says which).
- **Statics** as :func:`.harmonic.run_harmonic` (MoorDyn's static solver, still water: it
  runs without water kinematics). With a current the line is settled in it first with the
  hang-off held, in the still-water deck; its state is then saved and loaded into the
  same deck with its waves (MoorDyn's SaveState/LoadState, measured to restore the nodes
  exactly), whose clock starts at 0.
- **The hang-off**: :func:`riser.physics.hang_off_motion.hang_off_displacement` of the scene (the
  vessel's RAO motion in the same components, with the waves' ramp, or the top motion),
  given at every step as position and the step's mean velocity (as
  :mod:`.harmonic`); held without either.
- **The same sea, checked**: MoorDyn's own elevation at the waves' origin (GetWavesKin,
  which reports the sea without the ramp) against :func:`riser.physics.waves.elevation` of the
  scene's components without ramp, at every sample: ``sea_elevation_difference`` [m].

Axes: MoorDyn (X, Y, Z) = (x, -z, y - WtrDpth); positions come back in the scene's axes.
"""

from __future__ import annotations

import dataclasses
import math
import time
from pathlib import Path

import numpy as np

from riser.errors import SceneError
from riser.model.scene import Scene

from .run import (SETTLE_TIME, SPEED_TOL, STEP_FRACTION, _profile, _to_log, close,
                  coupled_statics, require, start)

#: samples per shortest wave period when the scene gives no output interval
SAMPLES_PER_PERIOD = 20
#: the first pseudo-time of MoorDyn's static solver [s] (as :mod:`.harmonic`)
PSEUDO_TIME = 250.0
#: MoorDyn's saved still-water state (current settled), loaded into the deck with waves
STATE_FILE = "still.state"


def _max_speed(moordyn, lines) -> float:
    return max(float(np.max(np.linalg.norm([moordyn.GetLineNodeVel(ln, i) for i in range(
        moordyn.GetLineN(ln) + 1)], axis=1))) for ln in lines)


def has_sea(scene: Scene) -> bool:
    """Whether MoorDyn's deck holds the scene's waves (waves that load the line)."""
    return scene.waves is not None and scene.waves.line_loads


def to_md(v) -> np.ndarray:
    """Scene (x, y, z) vectors (..., 3) -> MoorDyn's (X, Y, Z) directions (x, -z, y)."""
    v = np.asarray(v, float)
    return np.stack([v[..., 0], -v[..., 2], v[..., 1]], axis=-1)


def to_sea(system, files, scene: Scene, folder: Path, segment_length: float):
    """The still-water ``system`` (its statics done, settled in the current) handed to the
    same deck with the scene's waves: (system, lines, files) of the new one, whose clock is
    0 and state the old one's (see the module docstring). Closes ``system``."""
    import moordyn
    state = Path(folder) / STATE_FILE
    moordyn.SaveState(system, str(state))
    close(system, folder)
    depth = files.scene.water_depth
    pts = [(p.x, p.z + depth, -p.y) for p in files.export.deck.points[1:-1]]
    new, lines, wfiles, _, code = start(scene, Path(folder), segment_length=segment_length,
                                        pseudo_time=0.0, hang_off="Coupled", waves=True,
                                        joints=(pts or None, files.joints_from))
    if code not in (0, None):
        close(new, folder)
        raise RuntimeError(f"MoorDyn's Init of the deck with waves returned error {code}")
    moordyn.LoadState(new, str(state))
    return new, lines, wfiles


def run_waves(scene: Scene, folder, *, segment_length: float = 10.0, profile=None,
              duration: float | None = None, sample: float | None = None, log=None,
              pseudo_time: float = PSEUDO_TIME) -> dict:
    """Run ``scene`` in its sea in MoorDyn (see the module docstring).

    duration : simulated time [s] (default ``scene.dynamics.duration``); sample : the
    sampling interval [s] (default ``scene.dynamics.output_interval``, else the shortest
    wave period / :data:`SAMPLES_PER_PERIOD`); the rest as :func:`.harmonic.run_harmonic`.

    Returns a dict: 't' (k,) [s], 's' (n,) [m], 'tension' (k, n) [N] (the end nodes'
    force at the ends), 'position' (k, n, 3) [m], 'hang_off_tension' (k,) [N],
    'hang_off_force' (k,) [N] (|F_N - M_N a|, a the prescribed acceleration, as
    :mod:`.harmonic`), 'statistics_from' [s] (the scene's),
    'hang_off_displacement' (3, k) [m] (prescribed), 'elevation' (k,) [m] (MoorDyn's at the
    waves' origin) and 'elevation_scene' (k,) [m] (the scene's, both without ramp),
    'sea_elevation_difference' [m] (their largest difference), 'ramp' (what MoorDyn ramps),
    'components', 'wall_s', 'static_wall_s', 'static_force_residual', 'settle_sim_s',
    'time_step' [s], 'sample_interval' [s], 'stable', 'message'. MoorDyn's output goes to
    ``folder``/moordyn.log; the deck that ran the sea is ``folder``/deck.dat.
    """
    if scene.waves is None:
        raise SceneError(scene.name, "environment.waves", "the MoorDyn wave run needs waves")
    dyn = scene.dynamics
    if duration is None:
        if dyn is None:
            raise SceneError(scene.name, "dynamics.duration", "give the run's duration")
        duration = dyn.duration
    require()
    import cmoordyn
    import moordyn

    from riser.physics.hang_off_motion import HangOffPath, scene_components
    from riser.physics.waves import elevation

    say = log or (lambda msg: None)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    log_path = folder / "moordyn.log"
    log_path.write_text("")
    sea = has_sea(scene)
    current = scene.current is not None
    out = {"t": [], "s": np.zeros(0), "tension": [], "position": [], "elevation": [],
           "hang_off_force": [], "wall_s": 0.0,
           "statistics_from": dyn.statistics_from if dyn is not None else 0.0,
           "static_wall_s": 0.0, "static_force_residual": float("nan"),
           "settle_sim_s": 0.0, "time_step": float("nan"), "stable": True,
           "message": "completed"}
    try:
        system, lines, files, res, _, static_wall = coupled_statics(
            scene, folder, segment_length, profile, pseudo_time, say, sea and not current)
    except RuntimeError as exc:
        out.update(stable=False, message=f"MoorDyn's statics failed ({exc}; see {log_path})")
        return _arrays(out)
    fixed = files.scene
    depth = fixed.water_depth
    comp = scene_components(fixed)
    path = HangOffPath(fixed)
    plain = dataclasses.replace(comp, ramp_time=0.0)
    if sample is None:
        sample = (dyn.output_interval if dyn is not None and dyn.output_interval else
                  comp.shortest_period / SAMPLES_PER_PERIOD)
    n_samples = math.floor(duration / sample + 1e-9)
    dt0 = cmoordyn.get_dt(system)     # moordyn.GetDt returns None in 2.7
    per_sample = math.ceil(sample / (STEP_FRACTION * dt0) - 1e-9)
    dt = sample / per_sample
    cmoordyn.set_dt(system, dt)
    pt = files.export.deck.points[-1]
    top = np.array([pt.x, pt.y, pt.z])
    ox, oz = comp.origin
    out.update(static_wall_s=static_wall, static_force_residual=res, time_step=dt,
               sample_interval=sample, components=comp.size,
               ramp=("none: no waves on the line" if not sea else
                     f"linear over {comp.ramp_time:g} s (the scene: half cosine)"
                     if comp.ramp_time > 0.0 and not current else
                     "none: MoorDyn's waveKin_rampT would ramp the current too"
                     if comp.ramp_time > 0.0 else "none (the scene's ramp_time is 0)"))
    state = {"system": system, "lines": lines, "files": files}

    def take(t: float) -> None:
        p = _profile(moordyn, state["lines"], fixed, state["files"], {})
        end = state["lines"][-1]
        n_end = moordyn.GetLineN(end)
        d3 = to_md(path(np.array([t - dt, t, t + dt])).T)
        acc = (d3[0] - 2.0 * d3[1] + d3[2]) / dt ** 2
        force = np.array(moordyn.GetLineNodeForce(end, n_end))
        mass = np.array(moordyn.GetLineNodeM(end, n_end))
        out["hang_off_force"].append(float(np.linalg.norm(force - mass @ acc)))
        out["tension"].append(p.tension.copy())
        out["position"].append(np.stack([p.x, p.y, p.z], axis=1))
        waves = moordyn.GetWaves(state["system"])
        eta = moordyn.GetWavesKin(waves, ox, -oz, -0.5 * depth)[2] if sea else 0.0
        out["elevation"].append(float(eta))
        out["t"].append(t)
        out["s"] = p.s

    settle = 0.0
    t0 = time.perf_counter()
    try:
        with _to_log(log_path):
            x, v = list(top), [0.0, 0.0, 0.0]
            while current and settle < SETTLE_TIME:
                moordyn.Step(state["system"], x, v, settle, 1.0)   # 1 s, the hang-off held
                settle += 1.0
                if _max_speed(moordyn, lines) < SPEED_TOL:
                    break
            take(0.0)           # the settled state (LoadState refreshes MoorDyn's line
            if sea and current:  # outputs only at the next step): its sea's eta at t = 0
                new = to_sea(state["system"], files, scene, folder, segment_length)
                state.update(system=new[0], lines=new[1], files=new[2])
                cmoordyn.set_dt(state["system"], dt)
                out["elevation"][0] = float(moordyn.GetWavesKin(
                    moordyn.GetWaves(state["system"]), ox, -oz, -0.5 * depth)[2])
            for j in range(n_samples):
                tj = (j * per_sample + np.arange(per_sample + 1)) * dt
                d = to_md(path(tj).T)          # (m, 3) MoorDyn axes
                for i in range(per_sample):
                    moordyn.Step(state["system"], list(top + d[i]),
                                 list((d[i + 1] - d[i]) / dt), tj[i], dt)
                take((j + 1) * sample)
                if (j + 1) % 50 == 0:
                    say(f"moordyn: t = {(j + 1) * sample:.1f} / {duration:g} s")
    except RuntimeError as exc:
        last = out["t"][-1] if out["t"] else 0.0
        out.update(stable=False, message=f"MoorDyn stopped after t = {last:g} s in the "
                   f"waves ({exc}; see {log_path})")
    finally:
        out.update(wall_s=time.perf_counter() - t0, settle_sim_s=settle)
        close(state["system"], folder)
    out = _arrays(out)
    t = out["t"]
    out["hang_off_displacement"] = path(t)
    out["elevation_scene"] = (elevation(plain, ox, oz, t) if sea and t.size
                              else np.zeros_like(t))
    out["sea_elevation_difference"] = (float(np.max(np.abs(out["elevation"]
                                                           - out["elevation_scene"])))
                                       if t.size else float("nan"))
    return out


def _arrays(out: dict) -> dict:
    """The samples as arrays; NaN/inf unstable."""
    out["t"] = np.asarray(out["t"], float)
    n, k = len(out["s"]), len(out["t"])
    out["tension"] = np.asarray(out["tension"], float).reshape(k, n)
    out["position"] = np.asarray(out["position"], float).reshape(k, n, 3)
    out["elevation"] = np.asarray(out["elevation"], float)
    out["hang_off_force"] = np.asarray(out["hang_off_force"], float)
    out["hang_off_tension"] = out["tension"][:, -1] if n else np.zeros(0)
    if out["stable"] and not np.all(np.isfinite(out["tension"])):
        out.update(stable=False, message="MoorDyn's state holds NaN/inf")
    return out

"""MoorDyn (MoorDyn-C v2) as a dynamic third opinion: the scene's harmonic hang-off motion
([dynamics.top_motion]) driven through a Coupled hang-off point from MoorDyn's statics.

How it runs:

- **Start**: the scene's deck (:func:`.run.start`, a touchdown form converted to fixed
  ends first) with the hang-off a Coupled point at its static position; MoorDyn's static
  solver is run with a pseudo-time doubled from ``pseudo_time`` until the force residual
  (:func:`.run._residual`) is within :data:`.run.RESIDUAL_TOL` or the next run would pass
  :data:`.run.IC_BUDGET` of wall time (reported: ``static_force_residual``). With a
  current (which MoorDyn's static solver ignores) the line is then time-stepped with the
  hang-off held until its nodes move slower than :data:`.run.SPEED_TOL` (at most
  :data:`.run.SETTLE_TIME` simulated); the motion's clock starts after that.
- **Steps**: RK2 at most :data:`.run.STEP_FRACTION` of MoorDyn's CFL-0.5 step, as
  :func:`.bench.moordyn_dynamics`, shortened to divide the sampling interval exactly. The
  hang-off is given at **every time step**, not every :data:`.bench.COUPLING` s as in
  the bench (which measures cost only): MoorDyn moves a Coupled point as r(t_k + tau) =
  x_k + v_k tau over a call [t_k, t_k + c], so a motion given every c has its
  acceleration in velocity jumps at the calls; the axial wave carries each jump along
  10 m segments within a step, and the tension sampled at the end of a call misses the
  inertia of the line the hang-off accelerates. Measured on scr-steel (0.5 m heave, 12
  s): with c = 0.05 s the node forces at the samples gave 0.2 of the nodes' acceleration
  near the hang-off and the hang-off tension amplitude came out 5 % low, flat over the
  top 120 m; given every step, force / mass matches the acceleration within 0.5 %.
- **Motion**: d(t) of :func:`riser.physics.hang_off_motion.axis_displacement` (A sin(2 pi t / T) times the
  half-cosine ramp), given at t_k = k dt as x_k = top + d(t_k) e and v_k = (d(t_k + dt) -
  d(t_k)) / dt e, the central difference of d at the step's midpoint: the path is the
  continuous piecewise-linear interpolant of d(t) at the steps (the analytic d'(t_k)
  would leave a jump of ~ d'' dt^2 / 2 at every step).
- **Waves**: a scene with ``[environment.waves]`` loading the line runs in the same sea
  (MoorDyn's WaveKin 7 of its components, :mod:`.waves`: the deck with the waves from
  the start, or, with a current, the state settled in still water loaded into it).
- **Axes**: the deck places the line in MoorDyn's X-Z plane
  (:func:`riser.io.moordyn.deck_from_scene.export_scene`): MoorDyn (X, Y, Z) = (x, -z,
  y - WtrDpth). So the scene's axis 'x' (horizontal, anchor towards hang-off) is
  MoorDyn +X, 'y' (vertical up, seabed at y = 0) is MoorDyn +Z, 'z' (out of plane) is
  MoorDyn -Y; positions are mapped back with the inverse (:func:`.run._profile`).

What is sampled, every period / 40 from t = 0 (the static state) on, SI units:

- ``tension`` (k, n) [N]: at interior nodes MoorDyn's ``GetLineNodeTen`` (the mean of
  the two adjacent segments' tensions, EA strain plus the axial damping BA = -0.8 of
  critical of the deck; at a joint the mean across it); at the two end nodes the
  end-node force |``GetLineNodeForce``| (the end segment's tension plus the half
  segment's weight, buoyancy and drag). No internal pressure: the effective tension.
- ``hang_off_tension`` (k,) [N]: the end-node force at the hang-off (MoorDyn's FairTen
  output, = ``tension[:, -1]``), which leaves out the end node's inertia. Beside it:
  ``hang_off_force`` (k,) [N], the force the hang-off exerts on the line, |F_N - M_N a|
  (``GetLineNodeM``; a the prescribed acceleration, the second difference of d over a
  step), the lumped model's T(L) (on scr-steel 0.2 % above the end-node force's
  amplitude); ``hang_off_segment_tension`` (k,) [N], the top segment's (h/2 below).
- ``s`` (n,) [m]: the nodes' unstretched arc length from the bottom end, as the
  scene's s (the touchdown form's shift added back); ``position`` (k, n, 3) [m] in the
  scene's (x, y, z); ``hang_off_displacement`` (k,) [m] the prescribed d(t).
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from riser.errors import SceneError
from riser.physics.hang_off_motion import axis_displacement
from riser.model.scene import Scene
from verification.comparison.harmonics import fit

from .run import (SETTLE_TIME, SPEED_TOL, STEP_FRACTION, _profile, _to_log, close,
                  coupled_statics as _statics, require)
from .waves import has_sea, to_sea

#: samples per period of the motion (as the VFIFE's envelope sampling)
SAMPLES_PER_PERIOD = 40
#: the first pseudo-time of MoorDyn's static solver [s] (measured on scr-steel at 10 m:
#: 250 s leaves a residual of ~1 % of a node's weight, 500 s 0.47 % in 2.7 s)
PSEUDO_TIME = 250.0
#: scene axis -> (MoorDyn axis index, sign): MoorDyn (X, Y, Z) = (x, -z, y - WtrDpth)
MOORDYN_AXIS = {"x": (0, 1.0), "y": (2, 1.0), "z": (1, -1.0)}


def _max_speed(moordyn, lines) -> float:
    return max(float(np.max(np.linalg.norm([moordyn.GetLineNodeVel(ln, i) for i in range(
        moordyn.GetLineN(ln) + 1)], axis=1))) for ln in lines)


def run_harmonic(scene: Scene, folder, *, segment_length: float = 10.0, profile=None,
                 duration: float | None = None, log=None,
                 pseudo_time: float = PSEUDO_TIME) -> dict:
    """Run the scene's harmonic [dynamics.top_motion] in MoorDyn (see the module docstring).

    segment_length : MoorDyn segment length [m]. profile : a solved static profile of the
    fixed-ends scene to start the joints between MoorDyn lines from (default: the BVP's).
    duration : simulated time of the motion [s] (default ``scene.dynamics.duration``).
    log : ``log(message)`` for progress lines (default: none). pseudo_time : the first
    pseudo-time of MoorDyn's static solver [s].

    Returns a dict: 't' (k,) [s], 's' (n,) [m], 'tension' (k, n) [N], 'position'
    (k, n, 3) [m], 'hang_off_tension' (k,) [N], 'hang_off_force' (k,) [N],
    'hang_off_segment_tension' (k,) [N], 'hang_off_displacement' (k,) [m], 'wall_s' (the
    time-stepping's wall time [s]), 'static_wall_s', 'static_force_residual' (of the
    statics, before any settling in a current), 'static_pseudo_time_s', 'settle_sim_s',
    'time_step' [s] (also the coupling step), 'sample_interval' [s], 'stable' (False when
    MoorDyn raised: 'message' says where; the samples up to then are kept), 'message',
    'statistics_from' (``scene.dynamics.statistics_from``) [s]. MoorDyn's own output goes
    to ``folder``/moordyn.log.
    """
    dyn = scene.dynamics
    tm = dyn.top_motion if dyn is not None else None
    if tm is None or tm.times is not None or not tm.one_axis:
        raise SceneError(scene.name, "dynamics.top_motion", "the MoorDyn harmonic run needs "
                         "a harmonic top motion along one axis (axis, amplitude and period)")
    require()
    import cmoordyn
    import moordyn

    say = log or (lambda msg: None)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "moordyn.log").write_text("")
    duration = float(dyn.duration if duration is None else duration)
    sample = tm.period / SAMPLES_PER_PERIOD
    n_samples = math.floor(duration / sample + 1e-9)

    out = {"t": [], "s": np.zeros(0), "tension": [], "position": [],
           "hang_off_segment_tension": [], "hang_off_force": [], "wall_s": 0.0,
           "static_wall_s": 0.0, "static_force_residual": float("nan"),
           "static_pseudo_time_s": pseudo_time, "settle_sim_s": 0.0, "time_step": float("nan"),
           "sample_interval": sample, "stable": True, "message": "completed",
           "statistics_from": dyn.statistics_from}
    log_path = folder / "moordyn.log"
    sea = has_sea(scene)          # the scene's waves too: MoorDyn sums the same components
    try:
        system, lines, files, res, pseudo, static_wall = _statics(
            scene, folder, segment_length, profile, pseudo_time, say,
            waves=sea and scene.current is None)
    except RuntimeError as exc:
        out.update(stable=False, message=f"MoorDyn's statics failed ({exc}; see {log_path})")
        return _arrays(out, scene)
    out.update(static_wall_s=static_wall, static_force_residual=res,
               static_pseudo_time_s=pseudo)
    dt0 = cmoordyn.get_dt(system)     # moordyn.GetDt returns None in 2.7
    per_sample = math.ceil(sample / (STEP_FRACTION * dt0) - 1e-9)
    dt = sample / per_sample
    cmoordyn.set_dt(system, dt)
    out["time_step"] = dt
    pt = files.export.deck.points[-1]
    top = np.array([pt.x, pt.y, pt.z])
    axis = np.zeros(3)
    k_ax, sign = MOORDYN_AXIS[tm.axis]
    axis[k_ax] = sign

    info: dict = {}
    end = lines[-1]
    n_end = moordyn.GetLineN(end)

    def take(t: float) -> None:
        p = _profile(moordyn, lines, files.scene, files, info)
        d3 = axis_displacement(scene, np.array([t - dt, t, t + dt]))
        acc = (d3[0] - 2.0 * d3[1] + d3[2]) / dt ** 2 * axis
        force = np.array(moordyn.GetLineNodeForce(end, n_end))
        mass = np.array(moordyn.GetLineNodeM(end, n_end))
        out["hang_off_force"].append(float(np.linalg.norm(force - mass @ acc)))
        out["tension"].append(p.tension.copy())
        out["position"].append(np.stack([p.x, p.y, p.z], axis=1))
        out["hang_off_segment_tension"].append(info["hang_off_end_segment_tension"])
        out["t"].append(t)
        out["s"] = p.s

    clock = settle = 0.0
    t0 = time.perf_counter()
    try:
        with _to_log(log_path):
            x, v = list(top), [0.0, 0.0, 0.0]
            while files.scene.current is not None and settle < SETTLE_TIME:
                moordyn.Step(system, x, v, clock, 1.0)         # 1 s, the hang-off held
                clock = settle = clock + 1.0
                if _max_speed(moordyn, lines) < SPEED_TOL:
                    break
            take(0.0)           # (before a switch: LoadState refreshes the outputs later)
            if sea and files.scene.current is not None:    # settled in still water: the
                system, lines, files = to_sea(system, files, scene, folder, segment_length)
                cmoordyn.set_dt(system, dt)                 # same state, with the waves
                end = lines[-1]
            for j in range(n_samples):
                tj = (j * per_sample + np.arange(per_sample + 1)) * dt
                d = axis_displacement(scene, tj)
                for i in range(per_sample):
                    moordyn.Step(system, list(top + d[i] * axis),
                                 list((d[i + 1] - d[i]) / dt * axis), clock + tj[i], dt)
                take((j + 1) * sample)
                if (j + 1) % SAMPLES_PER_PERIOD == 0:
                    say(f"moordyn: t = {(j + 1) * sample:.1f} / {duration:g} s")
    except RuntimeError as exc:
        last = out["t"][-1] if out["t"] else 0.0
        out.update(stable=False, message=f"MoorDyn diverged after t = {last:g} s of the "
                   f"motion ({exc}; see {log_path})")
    finally:
        out.update(wall_s=time.perf_counter() - t0, settle_sim_s=settle)
        close(system, folder)
    return _arrays(out, scene)


def _arrays(out: dict, scene) -> dict:
    """The samples as arrays, the hang-off tension and displacement; NaN/inf unstable."""
    out["t"] = np.asarray(out["t"], float)
    n = len(out["s"])
    out["tension"] = np.asarray(out["tension"], float).reshape(len(out["t"]), n)
    out["position"] = np.asarray(out["position"], float).reshape(len(out["t"]), n, 3)
    for key in ("hang_off_segment_tension", "hang_off_force"):
        out[key] = np.asarray(out[key], float)
    out["hang_off_tension"] = out["tension"][:, -1] if n else np.zeros(0)
    out["hang_off_displacement"] = axis_displacement(scene, out["t"])
    if out["stable"] and not np.all(np.isfinite(out["tension"])):
        out.update(stable=False, message="MoorDyn's state holds NaN/inf")
    return out


def first_harmonics(run: dict, period: float) -> dict:
    """First harmonics (:func:`verification.comparison.harmonics.fit`, whole periods from
    ``run['statistics_from']`` to the last sample) of a :func:`run_harmonic` result:
    'hang_off_tension_amplitude' [N] and 'hang_off_tension_phase_deg' [deg] (arg Q_1,
    q = q_0 + Re(Q_1 e^{i w t}); a motion A sin(w t) has -90 deg), 'hang_off_tension_mean'
    [N], 'hang_off_force_amplitude' [N], 'tension_amplitude' (n,) [N] and 'tension_mean'
    (n,) [N] along s, 'periods' (whole periods fitted)."""
    t = run["t"]
    start = run["statistics_from"]
    top = fit(t, run["hang_off_tension"], period, start)
    along = fit(t, np.asarray(run["tension"]).T, period, start)
    force = fit(t, run["hang_off_force"], period, start)
    return {"hang_off_tension_amplitude": float(top.amplitude),
            "hang_off_tension_phase_deg": float(np.degrees(top.phase)),
            "hang_off_tension_mean": float(top.mean),
            "hang_off_force_amplitude": float(force.amplitude),
            "tension_amplitude": np.asarray(along.amplitude),
            "tension_mean": np.asarray(along.mean), "periods": top.periods}

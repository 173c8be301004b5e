"""Dynamic response from the static state with prescribed hang-off motion.

The static model's state is copied into a dynamic model with the physical masses:
pipe + contents, added mass normal to the axis (if the line types have C_a > 0) and the
rotational inertia scaled by ``[vfife] rotational_inertia_scale_dynamics`` (default 4:
the critical step then follows the axial wave, l/c, instead of l/(sqrt(3) c), 1.7x
faster; the rotary inertia of a pipe changes bending waves of length lambda by
~(2 pi r_g / lambda)^2 with r_g ~ D/2.8, i.e. < 1.5 % even for 10 m waves with the x4).

Hydrodynamics: a line moving through water always feels Morison drag on its velocity
relative to the water (the current's, zero in still water), normal and tangential, when
its line types have drag coefficients: the drag kernel runs in every dynamic run (effect
``drag``, or ``current_drag`` with a current), unlike the statics, which runs it only with
a current. Sea surface: with ``water_depth`` given, the part of the line above y =
water_depth is in air: its weight in air (m g, no buoyancy), no drag and no added mass,
node by node by the immersed fraction of the node's stretch of line (see
:func:`vfife.kernels.node_pass`; effect ``sea_surface``; the summary warns when a node
leaves the water). Damping: ``[dynamics]
damping`` [1/s], mass-proportional (structural; default 0), on top of the drag; the line
types' ``axial_damping`` BA [N s], the axial force's Kelvin-Voigt term BA d(eps)/dt (the
kernels' axial dashpot, eta = BA / l0 per element, explicit on the lagged velocity; the
critical step shrinks by sqrt(1 + zeta^2) - zeta, :mod:`vfife.timestep`).

Top motion: ``top0 + d(t)`` with d(t) (3,) from :class:`riser.physics.hang_off_motion.HangOffPath`, multiplied by
a half-cosine ramp over ``ramp_time`` (default one period of a harmonic motion: an
impulsive start rings the line axially for the whole run).

Outputs: see :mod:`riser.results.recorder` (time series every ``output_interval``,
envelopes and statistics from ``statistics_start``, states on request).

Checkpoints: a run can keep its complete state at a given time (:class:`Checkpoint`, a
copy of the model) and another run of the same scene, with a later duration and
statistics start, continue from it: bit for bit the run that started at t = 0, its
outputs from the checkpoint on (the dynamic comparison's settling: a window that has not
settled is taken again later without integrating the start-up a second time).
"""

from __future__ import annotations

import copy
import math
import time
from dataclasses import dataclass
from enum import StrEnum

import numpy as np

from riser.callbacks import with_fraction
from riser.physics.hang_off_motion import HangOffPath, scene_components

from .outputs import Recorder, nodal_state
from ..flow import lightest_mass_factor
from ..model import Model, max_speed_hint
from ..timestep import choose_step, critical_steps

#: the dynamics reports its progress this many times over the run (and at its end)
PROGRESS_REPORTS = 100


class DynamicsOutcome(StrEnum):
    """How a dynamic run ended."""

    #: the whole duration integrated
    OK = "ok"
    #: NaN/inf, a runaway speed or an energy growth the motion cannot explain
    BLOW_UP = "blow-up"


@dataclass
class Checkpoint:
    """A dynamic run's complete state at the end of envelope interval ``j`` (time ``t``
    [s]): the model (a copy), the kinetic energy then [J] and the energy guard's
    reference (None before its first interval), for :func:`run_dynamics` to continue
    from."""

    j: int
    t: float
    model: Model
    ke: float
    e0: float | None


def wave_speed_hint(scene, comp) -> float:
    """An upper bound of the waves' particle speed at the surface and of the vessel's
    hang-off speed [m/s] (for the explicit drag's step): sum of a omega of the components
    ``comp`` (x 2 with a vessel), 0 without waves (``comp`` None)."""
    if comp is None:
        return 0.0
    v = float(np.sum(comp.amplitude * comp.omega) / np.tanh(np.min(comp.k) * comp.depth))
    return 2.0 * v if scene.vessel is not None else v


def blow_up_cause(info: dict) -> str:
    """Most likely cause of a blow-up, from the run settings."""
    steps = info.get("critical_steps", {})
    dt = info.get("time_step", 0.0)
    causes = []
    if steps and dt > 0.95 * min(steps.values()):
        causes.append(f"time step {dt:.3g} s at the critical step "
                      f"({min(steps, key=steps.get)} {min(steps.values()):.3g} s): lower "
                      "[vfife] time_step_safety")
    if "drag" in steps and steps["drag"] < 3.0 * dt:
        causes.append("explicit drag near its stability limit (strong current or light line)")
    if info.get("emerging"):
        causes.append("a node leaving the water (no added mass there: a shorter stable step)")
    if "seabed" in steps and steps["seabed"] < 3.0 * dt:
        causes.append("seabed stiffness too high for the step")
    if not causes:
        causes.append("large top motion or a slack (compressed) line buckling; check the "
                      "static state and the motion amplitude")
    return "; ".join(causes)


def run_dynamics(scene, static: Model, planar: bool, progress=None, *,
                 checkpoint_at: float | None = None,
                 resume: Checkpoint | None = None, observers=()) -> tuple[Model, dict]:
    """Integrate the scene's [dynamics] from the static state ``static`` (its dead load,
    if any, carries over: :class:`vfife.model.Model`).

    ``checkpoint_at`` [s]: keep the state at the first sampling time at or after it as
    info['checkpoint'] (a :class:`Checkpoint`; None if the run ends before). ``resume``:
    continue from that checkpoint (a run of the same scene and static state) instead of
    starting at t = 0; the time series and states then start at the checkpoint's time.
    ``observers``: told of every sample (:class:`riser.results.recorder.Recorder`); their
    columns and figures join the envelope and the statistics.

    Returns (model at the end, info) where info holds 'timeseries' (dict of arrays),
    'envelope' (dict of arrays along s), 'states' (dict for npz, None unless
    ``save_states``), 'statistics' (the window's extremes, see
    :meth:`Recorder.statistics`), 'time_step', 'steps', 'status' (a
    :class:`DynamicsOutcome`),
    'message', 'wall_s', 'effects'. ``progress``: optional callable, called
    ``PROGRESS_REPORTS`` times over the run as ``progress(message, fraction=t /
    duration)`` (the last with 1.0), or ``progress(message)`` if it takes one argument.
    """
    report = with_fraction(progress)
    dyn = scene.dynamics
    vf = scene.vfife
    mesh = static.mesh
    added = any(scene.line_types[s.line_type].added_mass > 0.0 for s in scene.segments)
    rot_scale = vf.rotational_inertia_scale_dynamics
    if resume is None:
        model = Model(scene, mesh, rot_scale=rot_scale, added_mass=added, planar=planar,
                      drag=True, surface=True, flow="dynamic", dead_load=static.dead_load,
                      waves=True)
        model.X[:] = static.X
        model.D[:] = static.D
        model.set_axial_damping()      # the line types' BA (none: the pass stays off)
    else:
        model = copy.deepcopy(resume.model)
    tm = dyn.top_motion
    kseabed = scene.seabed.stiffness if scene.seabed is not None else 0.0
    tmax = float(np.max(np.abs(static.nodal_results()["element_tension"])))
    # a node that can leave the water loses its added mass: its transverse step is then
    # shorter by sqrt(m / (m + m_a)) (0.75 for Yu's flexible riser)
    reach = 0.0 if tm is None else tm.reach
    trough = 0.0
    comp = scene_components(scene) if scene.waves is not None else None
    if comp is not None:             # the surface comes down by the waves' amplitudes
        trough = float(np.sum(comp.amplitude))
        reach += trough if scene.vessel is not None else 0.0
    emerge = model.use_surface and (float(np.max(static.X[1])) + reach
                                    >= 0.99 * scene.water_depth - trough)
    steps = critical_steps(mesh, rot_scale=rot_scale, tension=1.5 * tmax,
                           added_mass=added and not emerge,
                           seabed_stiffness=kseabed, seabed_damping=model.cseabed,
                           drag_speed=2.0 * (max_speed_hint(scene) + wave_speed_hint(scene, comp))
                           if model.use_drag else 0.0,
                           mass_factor=lightest_mass_factor(scene),
                           axial_damping=model.eta)
    dt, limit = choose_step(steps, vf.time_step_safety)
    if vf.time_step is not None:          # user-fixed step (may exceed the critical)
        dt, limit = float(vf.time_step), "user ([vfife] time_step)"
    out_dt = dyn.output_interval
    env_dt = out_dt
    if tm is not None and tm.times is None:
        # envelope sampling at <= period/40, an exact divisor of the output interval
        env_dt = out_dt / math.ceil(out_dt / min(out_dt, tm.period / 40.0) - 1e-9)
    if model.use_waves or scene.vessel is not None:
        # the shortest wave period sampled 40 times, as a harmonic top motion's (and
        # within the kinematics' interval, vfife.dynamics.waves)
        shortest = min(2.0 * math.pi / float(np.max(comp.omega)) / 40.0, env_dt)
        env_dt = out_dt / math.ceil(out_dt / min(out_dt, shortest) - 1e-9)
    nsub = max(1, int(math.ceil(env_dt / dt - 1e-9)))
    dt = env_dt / nsub                       # step divides the sampling interval exactly
    n_env = int(round(dyn.duration / env_dt))
    per_out = max(1, int(round(out_dt / env_dt)))
    top0 = static.X[:, -1].copy()
    path = HangOffPath(scene)            # set up once, evaluated every interval
    elevation = None
    if model.use_waves:
        origin = model.waves.components.origin
        elevation = lambda t: model.waves.elevation(origin[0], origin[1], t)  # noqa: E731
    start = dyn.statistics_from if scene.waves is None or dyn.statistics_start is not None \
        else min(max(dyn.statistics_from, scene.waves.ramp), 0.5 * dyn.duration)
    rec = Recorder(mesh.s, start, dyn.save_states, scene.seabed is not None,
                   elevation=elevation, irregular=bool(scene.waves is not None
                                                       and scene.waves.spectrum is not None),
                   observers=observers, stations=dyn.stations)
    # what a blow-up message names as its likely cause
    cause = {"critical_steps": steps, "time_step": dt,
             "emerging": model.use_surface and not emerge}

    t0 = time.perf_counter()
    j0 = 0 if resume is None else resume.j
    if model.use_waves:       # the kinematics of the first interval (then at each sample)
        model.waves.evaluate(model.X, j0 * env_dt)
    rec.sample(j0 * env_dt, nodal_state(model), 0.0 if resume is None else resume.ke,
               j0 % per_out == 0)
    status, message = DynamicsOutcome.OK, "dynamics completed"
    e0 = None if resume is None else resume.e0
    checkpoint = None
    for j in range(j0, n_env):
        tj = np.linspace(j * env_dt, (j + 1) * env_dt, nsub + 1)
        disp = path(tj)
        k, res, mres, ke, st = model.run(nsub, dt, dyn.damping, top_disp=disp, top0=top0)
        t = (j + 1) * env_dt
        if st == 2 or not np.all(np.isfinite(model.X)):
            status = DynamicsOutcome.BLOW_UP
            message = (f"dynamics diverged (blow-up) at t = {t:.4g} s (NaN/inf or speed > "
                       "1000 m/s); likely cause: " + blow_up_cause(cause))
            break
        # energy-growth guard: kinetic energy far above the work the motion can put in
        if e0 is None:
            e0 = max(ke, 1.0)
        elif ke > 1e6 * e0 and ke > 1e3 * float(np.sum(model.mass)):
            status = DynamicsOutcome.BLOW_UP
            message = (f"dynamics diverged (blow-up, energy growth) at t = {t:.4g} s (kinetic "
                       f"energy {ke:.3g} J); likely cause: " + blow_up_cause(cause))
            break
        if model.use_waves:
            # the next interval's Taylor point, evaluated here so that the recorder sees
            # the surface at the sample's time (the same calls as at each interval's start)
            model.waves.evaluate(model.X, t)
        rec.sample(t, nodal_state(model), ke, (j + 1) % per_out == 0)
        if (checkpoint_at is not None and checkpoint is None
                and t >= checkpoint_at - 0.5 * env_dt):
            checkpoint = Checkpoint(j + 1, t, copy.deepcopy(model), ke, e0)
        if report is not None and ((j + 1) % max(1, n_env // PROGRESS_REPORTS) == 0
                                   or j + 1 == n_env):
            report(f"dynamics t = {t:.1f} / {dyn.duration:g} s", fraction=(j + 1) / n_env)
    wall = time.perf_counter() - t0
    info = {
        "timeseries": rec.timeseries(), "envelope": rec.envelope(),
        "states": rec.states_arrays(),
        "statistics": rec.statistics(dyn.duration),
        "time_step": dt, "step_limit": limit, "critical_steps": steps,
        "steps": model.steps, "status": status, "message": message, "wall_s": wall,
        "simulated_s": model.steps * dt,
        "realtime_factor": model.steps * dt / wall if wall > 0 else float("inf"),
        "effects": model.effects + (["top_motion"] if tm is not None else [])
        + (["vessel_motion"] if scene.vessel is not None else []),
        "ramp_time": tm.ramp if tm is not None else 0.0,
        "checkpoint": checkpoint,
    }
    return model, info

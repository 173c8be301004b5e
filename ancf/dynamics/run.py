"""The ANCF's time domain: the scene's [dynamics] integrated implicitly from the static
state (:mod:`ancf.dynamics.integrator`), its outputs recorded like every time domain's
(:class:`riser.results.recorder.Recorder`).

Hang-off: the prescribed path (:class:`riser.physics.hang_off_motion.HangOffPath`: the top
motion or the vessel's RAO motion, with its ramp) moves the hang-off node's position; a
tensioner's top keeps its height free and the heave moves its reference height. Loads:
weight, seabed (stiffness, damping, friction), Morison drag on the velocity relative to
the current whenever the line has drag coefficients (with or without current), the
scene's mass-proportional damping ``[dynamics] damping`` [1/s], the added mass across
the axis in the inertia. Time step: ``[ancf] time_step``, else the excitation's period /
``[ancf] steps_per_period`` (T/100 by default: the prototype's touchdown moment was
within 0.2 % of the converged one at T/100 and 1.1 % at T/50), made an exact divisor of
the sampling interval.

Outputs at the nodes: positions, velocities, tangents, and the tension and moment from
the section forces with each element's inertia (ancf/output.py).
"""

from __future__ import annotations

import math
import time

import numpy as np

from riser.callbacks import with_fraction
from riser.physics.hang_off_motion import HangOffPath, scene_components
from riser.results.recorder import NodalState, Recorder

from ..model import Model
from ..output import section_forces
from ..waves import WaveField
from .integrator import Integrator, Kinematic, Scheme

#: the dynamics reports its progress this many times over the run
PROGRESS_REPORTS = 100
#: the force tolerance of a step: the largest out-of-balance nodal force x the load scale
#: (an element's weight; the VFIFE's static tolerance). MEASURED on scr-steel heaved 1 m
#: at T/120: the predictor's residual 10, one correction 1e-4 to 3e-4, a second 1e-6 (the
#: Jacobian leaves out the added mass's turning with the axis and the waves' change
#: within a step: linear convergence); at 1e-3 the run takes one correction a step, its
#: hang-off tension range and largest moment within 0.01 % of the runs at 1e-6
STEP_TOLERANCE = 1e-3
#: Newton iterations of a step before it is halved
STEP_ITERATIONS = 25


def excitation_period(scene) -> float | None:
    """The shortest period [s] the run is driven at: a harmonic top motion's, else the
    shortest wave component's (regular or a spectrum's), else a series' shortest sample
    spacing x 10 (None: no excitation)."""
    dyn = scene.dynamics
    tm = dyn.top_motion
    if tm is not None and tm.times is None:
        return float(tm.period)
    if scene.waves is not None:
        comp = scene_components(scene)
        return float(2.0 * math.pi / np.max(comp.omega))
    if tm is not None:
        return 10.0 * float(np.min(np.diff(np.asarray(tm.times, float))))
    return None


def nodal_state(model: Model, integ: Integrator, st: Kinematic, z0: float,
                t_now: float = 0.0) -> NodalState:
    """The sample of the state ``st`` at the nodes at time ``t_now`` [s]."""
    d, n = model.d, model.mesh.n
    qn = st.q.reshape(n, 2 * d)
    vn = st.v.reshape(n, 2 * d)
    x = np.zeros((n, 3))
    x[:, :d] = qn[:, :d]
    if d == 2:
        x[:, 2] = z0
    v = np.zeros((n, 3))
    v[:, :d] = vn[:, :d]
    t = np.zeros((n, 3))
    t[:, :d] = qn[:, d:]
    t /= np.linalg.norm(t, axis=1)[:, None]
    Fe = np.zeros((model.mesh.ne, 4 * d))
    if integ.balance is None:            # the static state
        integ.inertia(st.q, st.a + integ.damping * st.v, Fe)
        F, m = section_forces(model, st.q, st.v, Fe)
    else:
        # the section forces of the balance the last step solved, at its alpha levels
        # (generalised-alpha balances the forces at t_{n+1-af} against the inertia at
        # t_{n+1-am}: the state at t_{n+1} is not in balance by itself, and its forces
        # read with a_{n+1} were 20 % high in the peaks of a jumper's top tension at
        # T/100); Newmark's levels are t_{n+1}. Generalised-alpha's forces at t_{n+1}
        # are extrapolated linearly from the last two balances (at t_{n+1-af} of each
        # step: second order, no phase lag of af h)
        F, m = _balance_forces(model, integ, integ.balance, Fe)
        prev = integ.previous
        if prev is not None and integ.scheme.af > 0.0:
            t_f, t1 = integ.balance[3], integ.balance[4]
            F0, m0 = _balance_forces(model, integ, prev, np.zeros_like(Fe))
            c = (t1 - t_f) / max(t_f - prev[3], 1e-300)
            F, m = F + c * (F - F0), m + c * (m - m0)
    tension = np.einsum("ij,ij->i", F, t)
    moment = np.linalg.norm(m, axis=1)
    EI = np.empty(n)
    EI[:-1] = model.mesh.EI
    EI[-1] = model.mesh.EI[-1]
    EI[1:-1] = np.minimum(model.mesh.EI[:-1], model.mesh.EI[1:])
    surface = np.full(n, float(model.scene.water_depth)
                      if model.scene.water_depth is not None else np.inf)
    if model.waves is not None:       # the instantaneous surface over each node
        surface = model.waves.elevations(x[:, 0], x[:, 2], t_now) + model.scene.water_depth
    return NodalState(x, v, t, tension, moment, moment / EI, -m, surface)


def _balance_forces(model: Model, integ: Integrator, balance, Fe: np.ndarray):
    """The section forces (F, m) at the nodes of a step's balance (its q, v and inertia)."""
    qf, vf, acc = balance[0], balance[1], balance[2]
    clock = None
    if model.flow is not None:           # the slug where that balance had it
        clock, model.flow.time = model.flow.time, balance[3]
    integ.inertia(qf, acc, Fe)
    out = section_forces(model, qf, vf, Fe)
    if clock is not None:
        model.flow.time = clock
    return out


def run_dynamics(scene, static: Model, q_static: np.ndarray, progress=None,
                 observers=()) -> dict:
    """Integrate the scene's [dynamics] from the static state ``q_static`` of ``static``.
    Returns info: 'timeseries', 'envelope', 'states', 'statistics', 'time_step', 'steps',
    'ok', 'message', 'wall_s', 'effects', 'newton_iterations' (per step, mean),
    'halvings', 'ramp_time'."""
    report = with_fraction(progress)
    dyn = scene.dynamics
    st_ = scene.ancf
    mesh, d = static.mesh, static.d
    model = Model(scene, mesh, d, current=True, dead_load=static.dead_load,
                  gauss_points=len(static.xg), dynamic=True)
    ends = model.ends
    last = mesh.n - 1
    top0 = q_static.reshape(mesh.n, 2 * d)[last, :d].copy()
    path = HangOffPath(scene)
    top_dofs = np.array([last * 2 * d + k for k in ends.top], int)
    anchor_dofs = np.array([k for k in ends.fixed if k < 2 * d and k < d], int)
    anchor_vals = q_static[anchor_dofs]

    def prescribed(t):
        disp = path(np.array([t]))[:, 0]
        vals = top0[list(ends.top)] + disp[list(ends.top)]
        return (np.concatenate([anchor_dofs, top_dofs]),
                np.concatenate([anchor_vals, vals]))

    field = None
    if scene.waves is not None and scene.waves.line_loads:
        field = WaveField(scene, model)
        model.set_waves(field)

    def set_time(t, q):
        if model.flow is not None:       # the slug's clock (ancf/flow.py)
            model.flow.time = t
        if ends.tensioner is not None:
            model.tensioner_shift = float(path(np.array([t]))[1, 0])
        if field is not None:
            field.evaluate(model, q, t)

    scheme = Scheme.of(st_.integrator, st_.rho_inf)
    integ = Integrator(model, scheme, dyn.damping, STEP_TOLERANCE, STEP_ITERATIONS,
                       prescribed, set_time)
    period = excitation_period(scene)
    dt_target = (float(st_.time_step) if st_.time_step is not None else
                 period / st_.steps_per_period if period is not None else
                 dyn.duration / 1000.0)
    out_dt = dyn.output_interval
    env_dt = out_dt
    if period is not None:
        env_dt = out_dt / math.ceil(out_dt / min(out_dt, period / 40.0) - 1e-9)
    nsub = max(1, int(math.ceil(env_dt / dt_target - 1e-9)))
    dt = env_dt / nsub
    n_env = int(round(dyn.duration / env_dt))
    per_out = max(1, int(round(out_dt / env_dt)))
    start = dyn.statistics_from if scene.waves is None or dyn.statistics_start is not None \
        else min(max(dyn.statistics_from, scene.waves.ramp), 0.5 * dyn.duration)
    elevation = None
    if field is not None:
        x0, z0w = field.comp.origin
        elevation = lambda t: field.elevation(x0, z0w, t)  # noqa: E731
    rec = Recorder(mesh.s, start, dyn.save_states, scene.seabed is not None,
                   elevation=elevation,
                   irregular=bool(scene.waves is not None and scene.waves.spectrum is not None),
                   observers=observers, stations=dyn.stations)
    z0 = float(scene.ends.anchor_point[2])
    state = Kinematic(q_static.copy(), np.zeros(model.N), np.zeros(model.N))
    t0 = time.perf_counter()
    rec.sample(0.0, nodal_state(model, integ, state, z0, 0.0), 0.0, True)
    ok, message = True, "dynamics completed"
    steps = 0
    for j in range(n_env):
        for k in range(nsub):
            t = j * env_dt + k * dt
            state, good, _ = integ.step(state, t, dt)
            steps += 1
            if not good:
                ok = False
                message = (f"dynamics failed at t = {t:.4g} s: Newton did not converge in "
                           f"{STEP_ITERATIONS} iterations even at the step / "
                           f"{2 ** 6} (the step {dt:.3g} s); a slack line or a motion too "
                           "large for the mesh")
                break
        if not ok:
            break
        tj = (j + 1) * env_dt
        rec.sample(tj, nodal_state(model, integ, state, z0, tj),
                   integ.kinetic_energy(state), (j + 1) % per_out == 0)
        if report is not None and ((j + 1) % max(1, n_env // PROGRESS_REPORTS) == 0
                                   or j + 1 == n_env):
            report(f"ancf dynamics t = {tj:.1f} / {dyn.duration:g} s",
                   fraction=(j + 1) / n_env)
    wall = time.perf_counter() - t0
    tm = dyn.top_motion
    return {"timeseries": rec.timeseries(), "envelope": rec.envelope(),
            "states": rec.states_arrays(), "statistics": rec.statistics(dyn.duration),
            "time_step": dt, "steps": steps, "ok": ok, "message": message, "wall_s": wall,
            "newton_iterations": integ.iterations / max(steps, 1),
            "halvings": integ.halvings, "integrator": scheme.name,
            "effects": model.effects + (["top_motion"] if tm is not None else [])
            + (["vessel_motion"] if scene.vessel is not None else [])
            + (["added_mass"] if np.any(mesh.added > 0) else []),
            "ramp_time": tm.ramp if tm is not None else 0.0}

"""The VFIFE's side of the dynamic comparison (:mod:`.protocol`): a run that settles,
and the first harmonics of its window.

Settling: the run integrates the ramp, :data:`SETTLE_PERIODS` periods and the window;
while the window's two halves disagree (:data:`.rows.DRIFT_LIMIT`) the settling
is doubled, up to :data:`MAX_SETTLE_PERIODS`. A doubled settling is the same run
integrated further: it continues from a checkpoint of the previous run taken at the end
of the new settling (:class:`vfife.dynamics.run.Checkpoint`; bit for bit the run started
again at t = 0, which it was before, without integrating the ramp and the settling a
second time: measured on scr-steel's sway at 14 s, settled after 24 periods, 108
periods integrated in all before, 46 now).
"""

from __future__ import annotations

import time

import numpy as np

from riser.errors import SolveFailed
from riser.model.frame import LinePlane, plane_columns
from riser.results.result import Status
from verification.methods import design_observers, method
from vfife.dynamics.run import DynamicsOutcome, run_dynamics

from .. import harmonics
from .rows import DRIFT_LIMIT

SETTLE_PERIODS = 6
#: the settling is doubled (up to :data:`MAX_SETTLE_PERIODS`) while the first harmonic of
#: the tension changes by more than :data:`.rows.DRIFT_LIMIT` of its peak between
#: the window's two halves (in still water the drag damps the start-up transient in
#: proportion to the amplitude: measured on the flexible jumper's 0.1 m heave, 0.16 %
#: drift after 9 periods and a moment 1.2 % off, 0.06 % and 0.66 % after 18)
MAX_SETTLE_PERIODS = 24


def settled_run(scene_for, period: float, ramp: int, axis: str, h: float, what: str,
                progress=None) -> tuple[dict, float]:
    """The VFIFE's harmonics (:func:`read_vfife`) of the run of ``scene_for(settle)`` (the
    scene with that many periods of settling; ``ramp`` periods of ramp; the period [s])
    at elements of ``h`` [m], the settling doubled while the window drifts (module
    docstring); (the dict with ``settle_periods``, ``ramp_periods``, ``max_utilisation``,
    ``static_s`` and ``static_y`` added, the VFIFE's wall time [s]). ``what`` names the
    run in a failure's message (SolveFailed)."""
    settle = SETTLE_PERIODS
    vs = scene_for(settle)
    t0 = time.perf_counter()
    v = method("vfife").solve(vs, element_length=h, progress=progress,
                              checkpoint_at=(ramp + 2 * settle) * period)
    wall = time.perf_counter() - t0
    if not v.converged:
        raise SolveFailed("vfife", v.status, f"vfife at {what}: {v.message}")
    states, ck = v.dynamics.states, v.dynamics.checkpoint
    utilisation = v.summary().get("dynamic_max_utilisation")      # with [design]
    vf = read_vfife(states, period, vs.dynamics.statistics_from, axis, static_plane(vs))
    while vf["drift"] > DRIFT_LIMIT and 2 * settle <= MAX_SETTLE_PERIODS and ck is not None:
        settle *= 2
        vs = scene_for(settle)
        t0 = time.perf_counter()
        _, dinfo = run_dynamics(vs, v.solver_state, v.solver_state.planar, progress,
                                checkpoint_at=(ramp + 2 * settle) * period, resume=ck,
                                observers=design_observers(vs))
        wall += time.perf_counter() - t0
        if dinfo["status"] is not DynamicsOutcome.OK:
            raise SolveFailed("vfife", Status.DIVERGED, f"vfife at {what}: "
                              f"{dinfo['message']}")
        states, ck = continued(states, dinfo["states"], ck.t), dinfo["checkpoint"]
        utilisation = dinfo["statistics"].get("dynamic_max_utilisation")
        vf = read_vfife(states, period, vs.dynamics.statistics_from, axis, static_plane(vs))
    vf.update({"settle_periods": settle, "ramp_periods": ramp,
               "max_utilisation": utilisation,
               "static_s": v.profile.s, "static_y": v.profile.y})
    return vf, wall


def static_plane(scene) -> LinePlane | None:
    """The ends' plane of a scene whose static state is 3D (its moments are read as the 3D
    profile's columns, :func:`moment_columns`), None for a planar static state (read as
    before: about z and the static in-plane normal)."""
    return None if scene.statics_planar else LinePlane.of(scene)


def continued(before: dict, after: dict, t: float) -> dict:
    """The states of a run (``before``, from t = 0) continued from its checkpoint at ``t``
    [s] (``after``, from ``t``): those before ``t``, then ``after``'s."""
    keep = before["t"] < t - 1e-9
    return {k: (v if k == "s" else np.concatenate([before[k][keep], after[k]]))
            for k, v in after.items()}


def read_vfife(states: dict, period: float, start: float, axis: str = "y",
               plane: LinePlane | None = None) -> dict:
    """First harmonics of the VFIFE's ``states`` (``DynamicsResult.states``, from t = 0)
    over the window from ``start`` [s]: per
    quantity (tension, moment: in-plane, about z; moment_out: about the static in-plane
    normal; dx, dy, dz) a :class:`..harmonics.Harmonics`; about a 3D static state
    (``plane``: the ends' plane, :func:`moment_columns`) the moments are the 3D profile's
    columns instead, sample by sample; ``s``; the window's minimum
    tension; ``drift``: the largest change of the tension amplitude (of the out-of-plane
    displacement for a motion along z, whose tension changes at second order only)
    between the window's two halves over its peak (the transient still decaying; the
    moment's is noisier: in heave its first harmonic can be small beside the
    transient's)."""
    st = states
    t, s, x = st["t"], st["s"], st["x"]
    x0 = x[0]
    tang = np.gradient(x0, s, axis=0)
    tang /= np.linalg.norm(tang, axis=1)[:, None]
    normal = np.stack([-tang[:, 1], tang[:, 0], np.zeros_like(s)], axis=1)
    mv = st["moment_vector"]
    if plane is None:
        moment, moment_out = mv[:, :, 2].T, np.einsum("kni,ni->nk", mv, normal)
    else:
        moment, moment_out = moment_columns(x, s, mv, plane)
    series = {"tension": st["tension"].T, "moment": moment, "moment_out": moment_out,
              "dx": x[:, :, 0].T, "dy": x[:, :, 1].T, "dz": x[:, :, 2].T}
    out = {k: harmonics.fit(t, q, period, start) for k, q in series.items()}
    sel = t >= start - 1e-9
    out["s"] = s
    out["min_tension"] = float(np.min(st["tension"][sel]))
    half = start + 0.5 * (t[-1] - start)
    first = t <= half + 1e-9
    drift = 0.0
    for key in (("dz",) if axis == "z" else ("tension",)):
        peak = float(np.max(out[key].amplitude))
        if peak > 1e-9 * max(float(np.max(np.abs(series[key]))), 1e-300):
            a = harmonics.fit(t[first], series[key][:, first], period, start).amplitude
            b = harmonics.fit(t, series[key], period, half).amplitude
            drift = max(drift, float(np.max(np.abs(a - b))) / peak)
    out["drift"], out["axis"] = drift, axis
    return out


def moment_columns(x: np.ndarray, s: np.ndarray, mv: np.ndarray, plane: LinePlane):
    """((n, k), (n, k)) [N m]: the bending moment's in-plane and out-of-plane columns of a
    3D profile (riser.model.frame.plane_columns: m . (b x t) and m . b, b = unit(t x e_n)
    of the ends' ``plane``) at every sample of the positions x (k, n, 3) [m] at arc
    lengths s (n,) [m], the tangent t the positions' derivative along s normalised, and
    the line's moment m = EI t x t' minus the recorded nodal moment vector mv (k, n, 3)
    (riser/results/recorder.py). The frame turns with the line, as the frequency
    domain's dM1, dM2 about a 3D static state do (bvp.frequency.rod_harmonic): a
    projection on the static frame would miss M2 sin(phi) dtheta and M1 sin(phi) dtheta,
    first order where the static state is tilted and bent."""
    tang = np.gradient(x, s, axis=1)
    tang /= np.linalg.norm(tang, axis=2)[:, :, None]
    k, n = x.shape[0], x.shape[1]
    flat = (-mv).reshape(k * n, 3)
    _, inplane, out = plane_columns(plane, x[:, :, 0].ravel(), x[:, :, 2].ravel(),
                                    tang.reshape(k * n, 3), flat)
    return inplane.reshape(k, n).T, out.reshape(k, n).T

"""The ANCF's side of the dynamic comparison (:mod:`.protocol`): the second time domain
against the same frequency domain, judged like the VFIFE (:mod:`.rows`, the same
tolerances), on the same motion, ramp, settling and window.

The run settles like the VFIFE's (:mod:`.vfife_side`): while the window's two halves
disagree (:data:`.rows.DRIFT_LIMIT`) the settling is doubled, up to
:data:`.vfife_side.MAX_SETTLE_PERIODS` (the ANCF keeps no checkpoint: a doubled settling
runs again from the static state; its implicit steps of T/100 make that cheap). Its
first harmonics are read off its states as the VFIFE's are (:func:`.vfife_side.read_vfife`:
the states' columns are the shared recorder's, riser/results/recorder.py).
"""

from __future__ import annotations

import time

from riser.errors import SolveFailed
from verification.methods import method

from .rows import DRIFT_LIMIT
from .vfife_side import MAX_SETTLE_PERIODS, SETTLE_PERIODS, read_vfife, static_plane


def settled_run(scene_for, period: float, ramp: int, axis: str, what: str,
                progress=None) -> tuple[dict, float, dict]:
    """The ANCF's harmonics of the run of ``scene_for(settle)`` at its default mesh and
    step, the settling doubled while the window drifts; (the dict with
    ``settle_periods``, ``ramp_periods``, ``max_utilisation``; its wall time [s]; the
    run's info: element length, time step, Newton iterations a step)."""
    settle = SETTLE_PERIODS
    wall = 0.0
    while True:
        vs = scene_for(settle)
        t0 = time.perf_counter()
        res = method("ancf").solve(vs, progress=progress)
        wall += time.perf_counter() - t0
        if not res.converged:
            raise SolveFailed("ancf", res.status, f"ancf at {what}: {res.message}")
        an = read_vfife(res.dynamics.states, period, vs.dynamics.statistics_from, axis,
                        static_plane(vs))
        if an["drift"] <= DRIFT_LIMIT or 2 * settle > MAX_SETTLE_PERIODS:
            break
        settle *= 2
    an.update({"settle_periods": settle, "ramp_periods": ramp,
               "max_utilisation": res.summary().get("dynamic_max_utilisation")})
    info = {k: res.info.get(k) for k in ("element_length", "dynamic_time_step",
                                         "newton_iterations_per_step", "integrator")}
    return an, wall, info

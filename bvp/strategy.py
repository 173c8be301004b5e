"""How the BVP is solved: a cold start from the catenary, and if that fails a continuation
in a load factor that scales the current speed and the buoyancy (``solve_bvp`` calls with
a trial node cap; the full cap only where the problem is genuinely fine)."""

from __future__ import annotations

import warnings

import numpy as np
from scipy.integrate import solve_bvp

from riser.result import Status
from riser.settings import BVPSettings

from .equations import IT, NSTATE


def _run(prob, tau: np.ndarray, Y: np.ndarray, p: np.ndarray, settings: BVPSettings):
    model = prob.model
    kw = dict(tol=settings.tolerance, max_nodes=settings.max_nodes)
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        if p.size:
            return solve_bvp(model.rhs, prob.bc, tau, Y, p=p, fun_jac=model.jac, **kw)
        return solve_bvp(lambda t, y: model.rhs(t, y, p), prob.bc, tau, Y,
                         fun_jac=lambda t, y: model.jac(t, y, p)[0], **kw)


TRIAL_MAX_NODES = 8000   # node cap for cold starts and continuation steps (a failing
                         # attempt at the full cap costs ~40 s; converged Wang runs use ~1k)


def solve_with_continuation(prob, tau0: np.ndarray, settings: BVPSettings,
                             continuation: bool):
    """Cold start from the catenary; if that fails, walk a load factor lam from 0 to 1
    that scales the current speed and the buoyancy (negative weights).

    Returns (solution or None, description of what was tried, failure status): the status
    is :attr:`Status.NO_EQUILIBRIUM` when the continuation stalled with the tension driven
    to zero, else :attr:`Status.NOT_CONVERGED` (meaningful only for a failed solution)."""
    trial = settings.replace(max_nodes=min(settings.max_nodes, TRIAL_MAX_NODES))
    fail = Status.NOT_CONVERGED
    Y0 = prob.guess(tau0)
    sol = _run(prob, tau0, Y0, prob.guess_p, trial)
    if good(sol, prob):
        return sol, "cold start from catenary", fail
    if "mesh nodes" in sol.message and trial.max_nodes < settings.max_nodes:
        # a genuinely fine problem (very flexible pipe): allow the full node cap once
        sol = _run(prob, tau0, Y0, prob.guess_p, settings)
        if good(sol, prob):
            return sol, "cold start from catenary (full node cap)", fail
    if "mesh nodes" in sol.message and trial.max_nodes >= settings.max_nodes:
        return sol, (f"the node cap max_nodes = {settings.max_nodes} is too small for "
                     f"tolerance {settings.tolerance:g}; raise [bvp] max_nodes"), fail
    if not continuation:
        return sol, "cold start only", fail
    model = prob.model
    w_target = model.w.copy()
    has_current = model.speed is not None
    has_buoy = bool(np.any(w_target < 0))
    if not (has_current or has_buoy):
        return sol, "cold start (no continuation parameter)", fail

    def set_lam(lam):
        model.drag_factor = lam
        model.w = np.where(w_target < 0, lam * w_target, w_target)

    set_lam(0.0)
    base = _run(prob, tau0, Y0, prob.guess_p, trial)
    if not good(base, prob):
        set_lam(1.0)
        return base, ("continuation failed: no solution even without current and "
                      "buoyancy"), fail
    lam, step, last = 0.0, 0.25, base
    while lam < 1.0:
        target = min(1.0, lam + step)
        set_lam(target)
        cand = _run(prob, tau0, last.sol(tau0), last.p if last.p is not None else prob.guess_p,
                    trial)
        if good(cand, prob):
            lam, last = target, cand
            step = min(step * 1.5, 0.5)
        else:
            step /= 2.0
            if step < 1.0 / 128:
                set_lam(1.0)
                Tmin = float(np.min(last.y[IT::NSTATE])) * model.scale[IT]
                Tmax = float(np.max(last.y[IT::NSTATE])) * model.scale[IT]
                why = (f"minimum tension there {Tmin / 1e3:.3g} kN of max {Tmax / 1e3:.3g} kN")
                if Tmin < 0.05 * Tmax:
                    why += (": the tension tends to zero, so probably no static equilibrium "
                            "of this form exists at the full load")
                    fail = Status.NO_EQUILIBRIUM
                return cand, (f"continuation in current/buoyancy stalled at load factor "
                              f"{lam:.3f}, {why}"), fail
    set_lam(1.0)
    if last.x.size >= trial.max_nodes:
        last = _run(prob, last.x, last.y, last.p if last.p is not None else prob.guess_p,
                    settings)
    return last, "continuation in current and buoyancy", fail


def good(sol, prob) -> bool:
    if not sol.success or not np.all(np.isfinite(sol.y)):
        return False
    if prob.form in ("hang_off_angle", "fixed_seabed", "fixed_liftoff"):
        l1 = sol.p[0] * prob.model.length_scale
        if l1 <= 0.0 or (prob.form != "hang_off_angle" and l1 > prob.first_total * (1 + 1e-9)):
            return False
    return True

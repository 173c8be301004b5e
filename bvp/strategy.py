"""How the BVP is solved: a cold start from the catenary, and if that fails a continuation
in a load factor that scales the current speed and the buoyancy, then (unilateral elastic
seabed) in the seabed stiffness (``solve_bvp`` calls with a trial node cap; the full cap
only where the problem is genuinely fine); and when it is not started at all (:func:`hopeless_span`, :func:`hopeless_start`: milliseconds, where a
hopeless ``solve_bvp`` run costs up to a minute or more)."""

from __future__ import annotations

import math
import warnings
from types import SimpleNamespace

import numpy as np

from riser.results.result import Status
from riser.model.scene import FixedEnds, Scene, TopTensionEnds
from riser.model.sections import segment_properties
from riser.model.settings import BVPSettings

from .collocation import solve_bvp
from .beam.equations import IT, IY, LiftOffOutside
from .beam.guess import (
    fold_back,
    metres,
    span_words,
    too_long_for_seabed,
    top_tension_reach,
    touchdown_beyond_first,
)


def _run(prob, tau: np.ndarray, Y: np.ndarray, p: np.ndarray, settings: BVPSettings):
    model = prob.model
    kw = dict(tol=settings.tolerance, max_nodes=settings.max_nodes)
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        try:
            if p.size:
                return solve_bvp(model.rhs, prob.bc, tau, Y, p=p, fun_jac=model.jac, **kw)
            return solve_bvp(lambda t, y: model.rhs(t, y, p), prob.bc, tau, Y,
                             fun_jac=lambda t, y: model.jac(t, y, p)[0], **kw)
        except LiftOffOutside as exc:
            # stopped at once: the Newton iterate left the form (bvp/beam/equations.py)
            return SimpleNamespace(success=False, status=3, message=str(exc), x=tau, y=Y,
                                   p=p, niter=0, sol=None, rms_residuals=None)


TRIAL_MAX_NODES = 8000   # node cap for cold starts and continuation steps (converged
                         # built-in scenes use 0.8k-4.4k nodes; a failing attempt costs
                         # ~0.1 ms a node and iteration, 1-5 s at the full cap)


def solve_with_continuation(prob, tau0: np.ndarray, settings: BVPSettings,
                             continuation: bool):
    """Cold start from the catenary; if that fails, walk a parameter lam from 0 to 1:
    first a load factor that scales the current speed and the buoyancy (negative
    weights), then, on an elastic seabed solved with the unilateral law everywhere
    (``fixed_elastic``), the seabed stiffness from none (the free-hanging catenary, exact
    for EI = 0) up to the scene's (:func:`_seabed_stiffness`): a start that dips far below
    the seabed (a taut line that stretches onto it, an anchor above the seabed) meets a
    stiff foundation otherwise, and the Newton iteration fails ('singular Jacobian').

    Returns (solution or None, description of what was tried, failure status): the status
    is :attr:`Status.NO_EQUILIBRIUM` when the load continuation stalled with the tension
    driven to zero, else :attr:`Status.NOT_CONVERGED` (meaningful only for a failed
    solution)."""
    # the trial cap leaves room to refine a starting mesh of many pieces
    trial = settings.replace(max_nodes=min(settings.max_nodes,
                                           max(TRIAL_MAX_NODES, 2 * tau0.size)))
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
    walks = [w for w in (_cross_loads(prob.model), _load_factor(prob.model),
                         _seabed_stiffness(prob)) if w is not None]
    if not walks:
        return sol, "cold start (no continuation parameter)", fail
    tried = []
    for walk in walks:
        cand, how, fail = _walk(prob, tau0, Y0, trial, settings, *walk)
        if cand is not None and good(cand, prob):
            return cand, "; ".join(tried + [how]), fail
        tried.append(how)
        sol = cand if cand is not None else sol
    return sol, "; ".join(tried), fail


def _load_factor(model):
    """(name, set_lam, where, largest step) of the continuation in current and buoyancy
    (``where(lam)`` says how far it went), None without either."""
    w_target = model.w.copy()
    if not model.has_current and not np.any(w_target < 0):
        return None

    def set_lam(lam):
        model.drag_factor = lam
        model.w = np.where(w_target < 0, lam * w_target, w_target)

    return "current/buoyancy", set_lam, lambda lam: f"load factor {lam:.3f}", 0.5


def _cross_loads(model):
    """(name, set_lam, where, largest step) of the continuation of the 3D rod
    (bvp/rod/equations.py) from its loads in the plane (the in-plane current: a planar
    problem) to the full ones, lam scaling the current and dead load across the plane;
    None for a planar model or one with nothing across its plane."""
    if not getattr(model, "cross_loads", False):
        return None

    def set_lam(lam):
        model.cross_factor = lam

    return "cross loads", set_lam, lambda lam: f"cross-load factor {lam:.3f}", 0.5


#: decades of seabed stiffness the continuation climbs after the first step from none
SEABED_DECADES = 8.0


def _seabed_stiffness(prob):
    """(name, set_lam, where, largest step) of the continuation in the seabed stiffness, k = 0 at lam = 0 and
    k 10^(-SEABED_DECADES (1 - lam)) above it (the foundation's stiffness spans decades:
    the sink depth w/k goes from metres to 0.1 mm), for the unilateral form only (the
    contact-zone form assumes contact from the anchor); None otherwise."""
    model = prob.model
    if prob.form != "fixed_elastic" or model.k_seabed <= 0.0:
        return None
    k_target = model.k_seabed

    def k_of(lam):
        return 0.0 if lam <= 0.0 else k_target * 10.0 ** (-SEABED_DECADES * (1.0 - lam))

    def set_lam(lam):
        model.k_seabed = k_of(lam)

    return "seabed stiffness", set_lam, lambda lam: (f"k = {k_of(lam):.3g} N/m2 of "
                                                     f"{k_target:.3g}"), 0.25


def _walk(prob, tau0, Y0, trial, settings, name, set_lam, where, max_step):
    """Walk lam from 0 to 1 with steps that grow on success (up to ``max_step``: 2
    decades of seabed stiffness, a failed step costs up to 5 s) and halve on failure;
    returns (solution at lam = 1 or the last candidate, what was done, status)."""
    model = prob.model
    fail = Status.NOT_CONVERGED
    set_lam(0.0)
    base = _run(prob, tau0, Y0, prob.guess_p, trial)
    if not good(base, prob):
        set_lam(1.0)
        return base, f"continuation in {name} failed: no solution at its start", fail
    lam, step, last = 0.0, 0.25, base
    while lam < 1.0:
        target = min(1.0, lam + step)
        set_lam(target)
        cand = _run(prob, tau0, last.sol(tau0), last.p if last.p is not None else prob.guess_p,
                    trial)
        if good(cand, prob):
            lam, last = target, cand
            step = min(step * 1.5, max_step)
            continue
        step /= 2.0
        if step < 1.0 / 128:
            set_lam(1.0)
            Tmin = float(np.min(last.y[IT::model.block])) * model.scale[IT]
            Tmax = float(np.max(last.y[IT::model.block])) * model.scale[IT]
            why = (f"minimum tension there {Tmin / 1e3:.3g} kN of max {Tmax / 1e3:.3g} kN")
            if Tmin < 0.05 * Tmax and name == "current/buoyancy":
                why += (": the tension tends to zero, so probably no static equilibrium "
                        "of this form exists at the full load")
                fail = Status.NO_EQUILIBRIUM
            return cand, f"continuation in {name} stalled at {where(lam)}, {why}", fail
    set_lam(1.0)
    if last.x.size >= trial.max_nodes:
        last = _run(prob, last.x, last.y, last.p if last.p is not None else prob.guess_p,
                    settings)
    return last, f"continuation in {name.replace('/', ' and ')}", fail


def good(sol, prob) -> bool:
    if not sol.success or not np.all(np.isfinite(sol.y)):
        return False
    m = prob.model
    if prob.form == "fixed_liftoff":
        # the lift-off point inside the segment its pieces were cut in
        s_L = sol.p[0] * m.length_scale
        return bool(m.starts[m.cut] < s_L < m.starts[m.cut + 1])
    if prob.form in ("hang_off_angle", "top_tension", "fixed_seabed"):
        # the forms (b) and J-lay may solve more than the file's first segment: the solver
        # says so (a warning, or no_equilibrium for the J-lay form)
        l1 = sol.p[0] * m.length_scale
        free = prob.form in ("hang_off_angle", "top_tension")
        if l1 <= 0.0 or (not free and l1 > prob.first_total * (1 + 1e-9)):
            return False
    return True


# ----------------------------------------------------------------- giving up early
#: forms whose start has one contact zone (or touchdown) at the bottom end only
ONE_CONTACT_FORMS = ("tdp_tension", "hang_off_angle", "top_tension", "fixed_seabed",
                     "fixed_lifted", "fixed_liftoff")
#: a starting catenary deeper than this fraction of the hang-off height [-] below the
#: seabed, away from the bottom contact, is a second touchdown the BVP's start does not
#: reach. Measured on hard-buoyancy-loss with the lost section's buoyancy B [N/m] (dip of
#: the catenary / 500 m, outcome, time on the 2-core machine): B = 600: clear by 3.6 m,
#: converged, 62 s; 560: 1.2 %, converged (touching the seabed), 268 s; 545: 1.9 %, failed,
#: 154 s; 530: 2.6 %, failed, 51 s; 515: 3.3 %, failed, 51 s; 500: 3.9 %, failed, 156 s;
#: 0 (the hard scene): 16 %, failed, 35-50 s. 3 % is 2.5 x the deepest dip seen to
#: converge; the built-in scenes' catenaries clear the seabed by 39 m or more.
SECOND_CONTACT_DEPTH = 0.03


def hopeless_span(scene: Scene) -> str:
    """Why a fixed-ends line on a seabed cannot have an equilibrium of the BVP's forms
    (too long for the span: it would fold back), or a J-lay top tension cannot hold a line
    that reaches the seabed (:func:`bvp.beam.guess.top_tension_reach`), else ''. Geometry and
    weights only, before any guess is built."""
    ends = scene.ends
    if isinstance(ends, TopTensionEnds):
        return _too_little_tension(scene)
    if not isinstance(ends, FixedEnds) or scene.seabed_model is None:
        return ""
    if ends.tensioner is not None:
        return ""              # the top's height is free (the tensioner's stroke): no span
    if scene.seabed_model == "rigid" and ends.anchor[1] != 0.0:
        return ""              # free-hanging form, no contact: see hopeless_start
    props = segment_properties(scene)
    return too_long_for_seabed([p.weight for p in props], [p.length for p in props],
                               ends.anchor, ends.hang_off)


def _too_little_tension(scene: Scene) -> str:
    """The J-lay form: why the top tension cannot hold the line from the hang-off height
    down to the seabed (with H -> 0 it hangs straight down), else ''."""
    props = segment_properties(scene)
    w = [p.weight for p in props]
    EA = [p.EA if scene.axial_model == "extensible" else math.inf for p in props]
    T, h = scene.ends.top_tension, scene.ends.hang_off_height
    reach = top_tension_reach(w, [p.length for p in props], EA, T)
    if h <= reach:
        return ""
    one = len(set(w)) == 1 and len(set(EA)) == 1
    how = (f"T/w{' + T^2/(2 w EA)' if math.isfinite(EA[0]) else ''} with w = "
           f"{w[0] / 1e3:.4g} kN/m" if one else "its segments' weights")
    return (f"no equilibrium: top_tension {T / 1e3:,.6g} kN cannot hold a line that reaches "
            f"the seabed from hang_off_height {metres(h)}: even with zero tension at the "
            f"touchdown it reaches at most {metres(reach)} ({how}); raise "
            "top_tension or lower the hang-off")


def hopeless_start(scene: Scene, prob, tau: np.ndarray) -> tuple[Status, str] | None:
    """(status, reason) when the starting catenary of ``prob`` shows that solve_bvp cannot
    end in a valid equilibrium of its form, else None:

    - a free-hanging form (no seabed contact) with a line heavier than water longer than
      any seabed could hold (:func:`bvp.beam.guess.too_long_for_seabed`): its catenary hangs
      far below the seabed y = 0 (:attr:`Status.NO_EQUILIBRIUM`);
    - a one-contact form whose catenary passes below the seabed by more than
      ``SECOND_CONTACT_DEPTH`` of the hang-off height away from the bottom contact: a
      second touchdown (:attr:`Status.REFUSED`: the BVP's forms hold one contact zone,
      from the anchor; an equilibrium with two contacts may exist, which ``--method
      vfife`` finds).
    """
    m = prob.model
    y = prob.guess(tau)[IY::m.block] * m.scale[IY]         # (blocks, nodes) [m]
    S = m.s_of(tau, prob.guess_p)                           # their arc lengths [m]
    if prob.form == "fixed_free" and getattr(scene.ends, "tensioner", None) is None:
        # a line no seabed could hold either (too long for the span); a shorter one that
        # dips below y = 0 is solved and warned about (below_seabed, riser.results.validity). A
        # tensioner frees the top's height (its stroke): no span bounds the line's length
        (xa, ya), (xh, yh) = ends = scene.ends.anchor, scene.ends.hang_off
        L = m.piece_lengths(prob.guess_p)
        if not too_long_for_seabed(m.w, L, *ends):
            return None
        i = np.unravel_index(int(np.argmin(y)), y.shape)
        why = ("the scene has no [seabed]" if scene.seabed is None else
               "the rigid seabed holds a line only with the anchor on it (y = 0)")
        return Status.NO_EQUILIBRIUM, (
            f"the line is too long for the span: {span_words(L, xh - xa, yh - ya)}; as a free "
            f"catenary it hangs to y = {metres(float(y[i]))} (at s = "
            f"{metres(float(S[i]))}), below the seabed y = 0 (this form has no "
            f"seabed contact: {why}), and on a seabed {fold_back(float(np.sum(L)), *ends)}: "
            "no static equilibrium of this form; shorten the line or move the hang-off away "
            "from the anchor")
    top = max(float(y[-1, -1]), 1.0)
    limit = max(1.0, SECOND_CONTACT_DEPTH * top)
    if prob.form == "fixed_lifted" and float(np.min(y)) < -limit:
        # no touchdown in the first segment: the free catenary from the anchor dips
        return Status.NOT_CONVERGED, (
            f"not solved: hanging free from the anchor, the line would pass "
            f"{metres(-float(np.min(y)))} below the seabed: "
            + touchdown_beyond_first(prob.first_total))
    depth, s = second_contact(prob, tau, y)
    if prob.form not in ONE_CONTACT_FORMS or depth <= limit:
        return None
    return Status.REFUSED, (
        f"the starting catenary (no bending, no current) passes {depth:.3g} m "
        f"below the seabed at s = {s:.1f} m, {100 * depth / top:.2g} % of the hang-off "
        f"height {top:,.0f} m: a second touchdown, which the BVP's start (one contact zone "
        "from the anchor) does not reach (solve_bvp fails on such starts after a minute or "
        "more); "
        "--method vfife solves contact anywhere")


def second_contact(prob, tau: np.ndarray, y: np.ndarray | None = None) -> tuple[float, float]:
    """(depth [m], arc length s [m]) of the deepest point of the starting catenary below
    the seabed beyond the first segment (and the contact zone) of the bottom contact;
    (0, nan) if none. ``y``: the guess's heights (blocks, nodes) [m] if already sampled."""
    m = prob.model
    if y is None:
        y = prob.guess(tau)[IY::m.block] * m.scale[IY]
    S = m.s_of(tau, prob.guess_p)
    first_end = m.zone_length(prob.guess_p) + m.piece_lengths(prob.guess_p)[0]
    beyond = S > first_end + 1e-9 * m.length_scale
    if not np.any(beyond) or float(np.min(y[beyond])) >= 0.0:
        return 0.0, math.nan
    i = int(np.argmin(np.where(beyond, y, np.inf)))
    return -float(y.flat[i]), float(S.flat[i])

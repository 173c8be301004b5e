"""Boundary-value solver of the multi-segment large-deformation beam (scipy ``solve_bvp``).

Public entry: :func:`solve` (scene -> :class:`riser.result.SolveResult`).

Ends (``scene.ends.kind``):

- ``tdp_tension`` (Wang form): touchdown at the origin with theta = 0, M = 0, T = T_TDP;
  M = 0 at the free top. The hang-off point is an output.
- ``hang_off_angle``: touchdown at the origin (theta = 0, M = 0); hang-off height and
  angle given, M = 0 there; the suspended length of the first segment is an unknown
  parameter, the TDP tension an output.
- ``fixed`` with a ``[seabed]`` and the anchor on it (y = 0): the grounded part from the
  anchor is straight and frictionless, its tension the TDP tension plus the tangential
  drag of the current at the seabed; the touchdown position
  (i.e. the suspended length of the first segment) is an unknown parameter; M = 0 at the
  touchdown and the hang-off, positions given.
- ``fixed`` otherwise: pinned-pinned free-hanging line, positions given and M = 0 at both.

Unknown T(0) is simply a free state value. Continuity of x, y, theta, M, F, T at every
joint closes the stacked system. Current drag is planar only.
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_bvp
from scipy.optimize import brentq, least_squares

from riser.errors import UnsupportedSceneError
from riser.profile import Profile
from riser.result import SolveResult
from riser.scene import Scene
from riser.sections import segment_properties

from .catenary import catenary_state
from .equations import IF, IM, IT, ITH, IX, IY, NSTATE, BeamModel
from .mesh import clustered_mesh

DEFAULTS = {"tolerance": 1.0e-6, "max_nodes": 30000, "initial_nodes": 400}


class BVPFailure(RuntimeError):
    """Raised internally when no starting guess or no solution can be found."""


@dataclass
class _Problem:
    """Everything solve_bvp needs for one scene, plus what is needed to build the profile."""

    model: BeamModel
    bc: object
    guess_p: np.ndarray
    form: str
    seabed_start: float = 0.0          # x of the anchor (form fixed+seabed)
    anchor_xy: tuple = (0.0, 0.0)
    first_total: float = 0.0           # full length of the first segment [m]
    guess: object = None               # callable(tau) -> scaled state (6n, m)
    notes: list = field(default_factory=list)


def effects_of(scene: Scene) -> list[str]:
    """Physical effects the BVP includes for this scene."""
    eff = ["weight", "bending"]
    if scene.current is not None:
        eff.append("current_drag")
    if scene.ends.kind != "fixed" or (scene.seabed is not None and scene.ends.anchor[1] == 0.0):
        eff.append("seabed")
    return eff


def solve(scene: Scene, *, tolerance: float | None = None, max_nodes: int | None = None,
          initial_nodes: int | None = None, continuation: bool = True) -> SolveResult:
    """Solve the static configuration of ``scene`` (see module docstring for the ends).

    Never raises on non-convergence: the result has ``converged=False`` and a message.
    Raises :class:`UnsupportedSceneError` for scenes the method cannot represent
    (out-of-plane current).
    """
    t0 = time.perf_counter()
    settings = {**DEFAULTS, **scene.bvp}
    if tolerance is not None:
        settings["tolerance"] = tolerance
    if max_nodes is not None:
        settings["max_nodes"] = max_nodes
    if initial_nodes is not None:
        settings["initial_nodes"] = initial_nodes
    if scene.current is not None and not scene.current.is_planar:
        raise UnsupportedSceneError(
            f"{scene.source}: environment.current.heading_deg: {scene.current.heading_deg:g} deg "
            "is out of plane; the bvp method is planar only (use --method vfife)")

    effects = effects_of(scene)
    info = {"tolerance": settings["tolerance"], "warnings": []}
    if scene.dynamics is not None:
        info["warnings"].append("bvp solves statics only: [dynamics] ignored")

    def fail(msg: str) -> SolveResult:
        return SolveResult("bvp", scene.name, False, msg, None, time.perf_counter() - t0,
                           effects, info)

    try:
        prob = _build_problem(scene)
    except BVPFailure as exc:
        return fail(str(exc))

    tau0 = clustered_mesh(settings["initial_nodes"])
    sol, how = _solve_with_continuation(prob, tau0, settings, continuation)
    info["strategy"] = how
    if sol is None or not _good(sol, prob):
        msg = sol.message if sol is not None else "no solution"
        return fail(f"solve_bvp did not converge ({msg}); tried: {how}")

    info["nodes"] = int(sol.x.size)
    info["iterations"] = int(sol.niter)
    info["residual"] = float(np.max(sol.rms_residuals))
    try:
        profile, checks = _profile(prob, sol, scene)
    except BVPFailure as exc:
        return fail(str(exc))
    info.update(checks)
    return SolveResult("bvp", scene.name, True, f"converged ({how})", profile,
                       time.perf_counter() - t0, effects, info)


# ---------------------------------------------------------------------------- set-up
def _build_problem(scene: Scene) -> _Problem:
    props = segment_properties(scene)
    n = len(props)
    EI = np.array([p.EI for p in props])
    w = np.array([p.weight for p in props])
    L = np.array([p.length for p in props])
    c_n = np.array([p.drag_normal_coef for p in props])
    c_t = np.array([p.drag_tangential_coef for p in props])
    ends = scene.ends
    speed = grad = None
    if scene.current is not None:
        sign = math.cos(math.radians(scene.current.heading_deg))   # +1 or -1 (planar)
        cur = scene.current
        speed = lambda y: sign * cur.speed(y)                     # noqa: E731
        grad = lambda y: sign * cur.speed_gradient(y)             # noqa: E731

    Wabs = float(np.sum(np.abs(w) * L)) or 1.0
    length_scale = float(np.sum(L))

    # ---- catenary starting guess for each form: (H, V0, suspended lengths, origin)
    form = ends.kind
    anchor = (0.0, 0.0)
    free_first = False
    if form == "tdp_tension":
        H, V0, Ls = ends.tdp_tension, 0.0, L.copy()
    elif form == "hang_off_angle":
        free_first = True
        H, V0, Ls = _guess_hang_off_angle(w, L, ends.hang_off_height,
                                          math.radians(ends.hang_off_angle_deg))
    else:
        anchor = ends.anchor
        dx = ends.hang_off[0] - anchor[0]
        dy = ends.hang_off[1] - anchor[1]
        lifted = False
        if scene.seabed is not None and anchor[1] == 0.0:
            try:
                H, V0, Ls = _guess_grounded(w, L, dx, dy)
                form = "fixed_seabed"
                free_first = True
            except BVPFailure:
                # no touchdown ahead of the anchor: the line may lift off at the anchor,
                # i.e. hang pinned there and rise from the seabed (checked after solving)
                lifted = True
        if form != "fixed_seabed":
            form = "fixed_lifted" if lifted else "fixed_free"
            H, V0, Ls = _guess_free_hanging(w, L, dx, dy)

    ox = anchor[0] + (L[0] - Ls[0] if form == "fixed_seabed" else 0.0)
    oy = anchor[1]
    cat_top_T = float(catenary_state(np.array([Ls.sum()]), w, Ls, H, V0)["tension"][0])
    Ts = max(cat_top_T, H, 1.0)
    wref = max(float(np.max(np.abs(w))), Ts / length_scale * 1e-3)
    EImax = float(np.max(EI))
    scale = np.array([length_scale, length_scale, 1.0, EImax * wref / Ts,
                      wref * math.sqrt(EImax / Ts), Ts])

    model = BeamModel(EI=EI, w=w, c_n=c_n, c_t=c_t, lengths=Ls if not free_first else L.copy(),
                      scale=scale, speed=speed, speed_gradient=grad,
                      free_first_length=free_first, length_scale=length_scale)
    if free_first:
        model.lengths = L.copy()
    p0 = np.array([Ls[0] / length_scale]) if free_first else np.zeros(0)

    def guess(tau: np.ndarray) -> np.ndarray:
        return _catenary_guess(tau, w, Ls, EI, H, V0, ox, oy, scale)

    # ---- boundary conditions (scaled residuals), ya/yb shape (6n,)
    sc = scale
    top = (n - 1) * NSTATE

    def continuity(ya, yb):
        return [yb[k * NSTATE + i] - ya[(k + 1) * NSTATE + i]
                for k in range(n - 1) for i in range(NSTATE)]

    if form == "tdp_tension":
        Tt = ends.tdp_tension / sc[IT]

        def bc(ya, yb, p=None):
            return np.array([ya[IX], ya[IY], ya[ITH], ya[IM], ya[IT] - Tt, *continuity(ya, yb),
                             yb[top + IM]])
    elif form == "hang_off_angle":
        Hh = ends.hang_off_height / sc[IY]
        alpha = math.radians(ends.hang_off_angle_deg)

        def bc(ya, yb, p):
            return np.array([ya[IX], ya[IY], ya[ITH], ya[IM], *continuity(ya, yb),
                             yb[top + IM], yb[top + IY] - Hh, yb[top + ITH] - alpha])
    elif form == "fixed_seabed":
        xa = anchor[0] / sc[IX]
        L0 = L[0] / sc[IX]
        xh, yh = ends.hang_off[0] / sc[IX], ends.hang_off[1] / sc[IY]

        def bc(ya, yb, p):
            # touchdown at x = anchor + grounded length = anchor + (L0 - suspended)
            return np.array([ya[IX] - (xa + L0 - p[0]), ya[IY], ya[ITH], ya[IM],
                             *continuity(ya, yb), yb[top + IM], yb[top + IX] - xh,
                             yb[top + IY] - yh])
    else:
        xa, ya0 = anchor[0] / sc[IX], anchor[1] / sc[IY]
        xh, yh = ends.hang_off[0] / sc[IX], ends.hang_off[1] / sc[IY]

        def bc(ya, yb, p=None):
            return np.array([ya[IX] - xa, ya[IY] - ya0, ya[IM], *continuity(ya, yb),
                             yb[top + IM], yb[top + IX] - xh, yb[top + IY] - yh])

    return _Problem(model=model, bc=bc, guess_p=p0, form=form, seabed_start=anchor[0],
                    anchor_xy=anchor, first_total=float(L[0]), guess=guess)


def _catenary_guess(tau, w, Ls, EI, H, V0, ox, oy, scale) -> np.ndarray:
    n = len(Ls)
    edges = np.concatenate([[0.0], np.cumsum(Ls)])
    Y = np.empty((n * NSTATE, tau.size))
    for k in range(n):
        s = edges[k] + Ls[k] * tau
        st = catenary_state(s, w, Ls, H, V0, ox, oy)
        kap = st["curvature"]
        M = EI[k] * kap
        # d(kappa)/ds for kappa = w H / (H^2 + V^2), dV/ds = w
        F = EI[k] * (-2.0 * w[k] ** 2 * H * st["V"] / (H * H + st["V"] ** 2) ** 2)
        rows = [st["x"], st["y"], st["theta"], M, F, st["tension"]]
        for i, r in enumerate(rows):
            Y[k * NSTATE + i] = r / scale[i]
    return Y


def _guess_hang_off_angle(w, L, height, alpha):
    """Suspended first length and H so that the catenary from the TDP reaches the given
    height with the given angle."""
    rest = float(np.sum(w[1:] * L[1:]))

    def forces(l1):
        Vtop = w[0] * l1 + rest
        return Vtop / math.tan(alpha), Vtop

    def resid(l1):
        H, Vtop = forces(l1)
        if H <= 0:
            return -height
        Ls = L.copy()
        Ls[0] = l1
        return float(catenary_state(np.array([Ls.sum()]), w, Ls, H, 0.0)["y"][0]) - height

    lo, hi = 1e-3 * L[0], 20.0 * max(L[0], height)
    grid = np.geomspace(lo, hi, 60)
    vals = [resid(g) for g in grid]
    for a, b, fa, fb in zip(grid[:-1], grid[1:], vals[:-1], vals[1:]):
        if fa * fb <= 0:
            l1 = brentq(resid, a, b, xtol=1e-9 * L[0])
            H, _ = forces(l1)
            Ls = L.copy()
            Ls[0] = l1
            return H, 0.0, Ls
    raise BVPFailure("no catenary with a touchdown reaches the given hang_off_height with "
                     "hang_off_angle_deg; check the angle, the height and the weights")


def _guess_grounded(w, L, dx, dy):
    """Catenary from a touchdown on the seabed (theta = 0) to a hang-off at (dx, dy) from the
    anchor, with the grounded length L[0] - l1 straight on the seabed."""
    def top(H, l1):
        Ls = L.copy()
        Ls[0] = l1
        st = catenary_state(np.array([Ls.sum()]), w, Ls, H, 0.0)
        return float(st["x"][0]) + (L[0] - l1), float(st["y"][0])

    def H_for(l1):
        f = lambda lh: top(math.exp(lh), l1)[1] - dy                # noqa: E731
        lo, hi = math.log(1e-6 * np.sum(np.abs(w) * L) + 1e-3), math.log(1e3 * np.sum(np.abs(w) * L) + 1e3)
        if f(lo) * f(hi) > 0:
            return None
        return math.exp(brentq(f, lo, hi, xtol=1e-12))

    def g(l1):
        H = H_for(l1)
        if H is None:
            return None
        return top(H, l1)[0] - dx

    grid = np.linspace(L[0], 1e-3 * L[0], 80)
    prev = None
    for l1 in grid:
        v = g(l1)
        if v is None:
            continue
        if prev is not None and prev[1] * v <= 0:
            f = lambda z: g(z) if g(z) is not None else 0.0         # noqa: E731
            l1s = brentq(f, l1, prev[0], xtol=1e-9 * L[0])
            Ls = L.copy()
            Ls[0] = l1s
            return H_for(l1s), 0.0, Ls
        prev = (l1, v)
    raise BVPFailure("no touchdown found within the first segment for the given anchor and "
                     "hang_off (the line is too short, too long or the first segment does not "
                     "reach the seabed): lengthen segments[0] or move the ends")


def _guess_free_hanging(w, L, dx, dy):
    """Catenary between two pinned ends: unknown H and the vertical force V0 at the anchor."""
    W = float(np.sum(np.abs(w) * L)) or 1.0
    total = float(np.sum(w * L))

    def resid(z):
        H = math.exp(z[0]) * W
        st = catenary_state(np.array([L.sum()]), w, L, H, z[1] * W)
        return [(st["x"][0] - dx) / L.sum(), (st["y"][0] - dy) / L.sum()]

    best = None
    for h0 in (0.05, 0.3, 1.0, 3.0):
        r = least_squares(resid, [math.log(h0), -0.5 * total / W], xtol=1e-14, ftol=1e-14)
        if best is None or r.cost < best.cost:
            best = r
    if best.cost > 1e-16:
        raise BVPFailure("no free-hanging catenary joins the anchor and the hang-off "
                         "(line too short for the span?)")
    return math.exp(best.x[0]) * W, best.x[1] * W, L.copy()


# ---------------------------------------------------------------------------- solving
def _run(prob: _Problem, tau: np.ndarray, Y: np.ndarray, p: np.ndarray, settings: dict):
    model = prob.model
    kw = dict(tol=settings["tolerance"], max_nodes=settings["max_nodes"])
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        if p.size:
            return solve_bvp(model.rhs, prob.bc, tau, Y, p=p, fun_jac=model.jac, **kw)
        return solve_bvp(lambda t, y: model.rhs(t, y, p), prob.bc, tau, Y,
                         fun_jac=lambda t, y: model.jac(t, y, p)[0], **kw)


TRIAL_MAX_NODES = 8000   # node cap for cold starts and continuation steps (a failing
                         # attempt at the full cap costs ~40 s; converged Wang runs use ~1k)


def _solve_with_continuation(prob: _Problem, tau0: np.ndarray, settings: dict,
                             continuation: bool):
    """Cold start from the catenary; if that fails, walk a load factor lam from 0 to 1
    that scales the current speed and the buoyancy (negative weights).

    Returns (solution or None, description of what was tried)."""
    trial = {**settings, "max_nodes": min(settings["max_nodes"], TRIAL_MAX_NODES)}
    Y0 = prob.guess(tau0)
    sol = _run(prob, tau0, Y0, prob.guess_p, trial)
    if _good(sol, prob):
        return sol, "cold start from catenary"
    if "mesh nodes" in sol.message and trial["max_nodes"] < settings["max_nodes"]:
        # a genuinely fine problem (very flexible pipe): allow the full node cap once
        sol = _run(prob, tau0, Y0, prob.guess_p, settings)
        if _good(sol, prob):
            return sol, "cold start from catenary (full node cap)"
    if "mesh nodes" in sol.message and trial["max_nodes"] >= settings["max_nodes"]:
        return sol, (f"the node cap max_nodes = {settings['max_nodes']} is too small for "
                     f"tolerance {settings['tolerance']:g}; raise [bvp] max_nodes")
    if not continuation:
        return sol, "cold start only"
    model = prob.model
    w_target = model.w.copy()
    has_current = model.speed is not None
    has_buoy = bool(np.any(w_target < 0))
    if not (has_current or has_buoy):
        return sol, "cold start (no continuation parameter)"

    def set_lam(lam):
        model.drag_factor = lam
        model.w = np.where(w_target < 0, lam * w_target, w_target)

    set_lam(0.0)
    base = _run(prob, tau0, Y0, prob.guess_p, trial)
    if not _good(base, prob):
        set_lam(1.0)
        return base, "continuation failed: no solution even without current and buoyancy"
    lam, step, last = 0.0, 0.25, base
    while lam < 1.0:
        target = min(1.0, lam + step)
        set_lam(target)
        cand = _run(prob, tau0, last.sol(tau0), last.p if last.p is not None else prob.guess_p,
                    trial)
        if _good(cand, prob):
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
                return cand, (f"continuation in current/buoyancy stalled at load factor "
                              f"{lam:.3f}, {why}")
    set_lam(1.0)
    if last.x.size >= trial["max_nodes"]:
        last = _run(prob, last.x, last.y, last.p if last.p is not None else prob.guess_p,
                    settings)
    return last, "continuation in current and buoyancy"


def _good(sol, prob: _Problem) -> bool:
    if not sol.success or not np.all(np.isfinite(sol.y)):
        return False
    if prob.form in ("hang_off_angle", "fixed_seabed"):
        l1 = sol.p[0] * prob.model.length_scale
        if l1 <= 0.0 or (prob.form == "fixed_seabed" and l1 > prob.first_total * (1 + 1e-9)):
            return False
    return True


# ---------------------------------------------------------------------------- output
def _profile(prob: _Problem, sol, scene: Scene) -> tuple[Profile, dict]:
    model = prob.model
    p = sol.p if sol.p is not None else np.zeros(0)
    Ls = model.segment_lengths(p)
    n = model.n_seg
    EI = model.EI
    lam_min = float(np.min(np.sqrt(EI / max(abs(float(np.max(sol.y[IT::NSTATE]))) * model.scale[IT], 1.0))))
    step = float(np.clip(lam_min / 8.0, 0.05, 0.5))
    cols = {k: [] for k in ("s", "x", "y", "theta", "M", "F", "T", "kappa")}
    s0 = 0.0
    grounded = 0.0
    if prob.form == "fixed_seabed":
        grounded = prob.first_total - Ls[0]
    for k in range(n):
        m = max(20, int(math.ceil(Ls[k] / step)))
        tau = np.union1d(np.linspace(0.0, 1.0, m + 1), sol.x)
        if k > 0:
            tau = tau[1:]
        Y = sol.sol(tau)[k * NSTATE:(k + 1) * NSTATE] * model.scale[:, None]
        cols["s"].append(grounded + s0 + Ls[k] * tau)
        cols["x"].append(Y[IX])
        cols["y"].append(Y[IY])
        cols["theta"].append(Y[ITH])
        cols["M"].append(Y[IM])
        cols["F"].append(Y[IF])
        cols["T"].append(Y[IT])
        cols["kappa"].append(Y[IM] / EI[k])
        s0 += Ls[k]
    c = {k: np.concatenate(v) for k, v in cols.items()}
    tdp_s = None
    checks: dict = {}
    if prob.form in ("tdp_tension", "hang_off_angle", "fixed_seabed", "fixed_lifted"):
        tdp_s = grounded
    if prob.form == "fixed_lifted":
        checks["lifted_off_anchor"] = True
        if c["theta"][0] < -1e-6:
            raise BVPFailure(
                "the line is too short to reach the seabed ahead of the anchor and would "
                f"leave the anchor downwards (angle {math.degrees(c['theta'][0]):.2f} deg): "
                "no touchdown in the first segment")
    if prob.form == "fixed_seabed" and grounded > 0.0:
        sg = np.linspace(0.0, grounded, max(2, int(math.ceil(grounded / 1.0)) + 1))[:-1]
        # grounded, straight and frictionless: T' = -f_t (eq. 2 with theta = M = F = 0), so
        # the tangential drag of the current at the seabed changes the tension linearly
        T0 = c["T"][0]
        f_t = 0.0
        if model.speed is not None:
            V0 = model.drag_factor * float(model.speed(np.array([0.0]))[0])
            f_t = float(model.c_t[0]) * abs(V0) * V0
        pre = {"s": sg, "x": prob.anchor_xy[0] + sg, "y": np.zeros_like(sg),
               "theta": np.zeros_like(sg), "M": np.zeros_like(sg), "F": np.zeros_like(sg),
               "T": T0 + f_t * (grounded - sg), "kappa": np.zeros_like(sg)}
        c = {k: np.concatenate([pre[k], c[k]]) for k in c}
    # joints are evaluated from both sides; drop stations closer than 1 um
    keep = np.concatenate([[True], np.diff(c["s"]) > 1e-6])
    c = {k: v[keep] for k, v in c.items()}
    checks["first_segment_suspended_length"] = float(Ls[0])
    if prob.form == "fixed_seabed":
        checks["grounded_length"] = float(grounded)
    prof = Profile(s=c["s"], x=c["x"], y=c["y"], z=np.zeros_like(c["s"]), theta=c["theta"],
                   tension=c["T"], moment=np.abs(c["M"]), shear=np.abs(c["F"]),
                   curvature=np.abs(c["kappa"]), tdp_s=tdp_s)
    if not prof.is_finite():
        raise BVPFailure("solution contains NaN or inf")
    # independent self-checks of the converged solution
    checks["equilibrium_residual"] = _equilibrium_residual(model, Ls, grounded, c)
    if tdp_s is not None:
        susp = c["s"] > tdp_s + 1e-9
        ymin = float(np.min(c["y"][susp])) if np.any(susp) else 0.0
        checks["min_suspended_height"] = ymin
        if ymin < -1e-2:
            i = int(np.argmin(np.where(susp, c["y"], np.inf)))
            raise BVPFailure(f"the suspended line passes {abs(ymin):.3g} m below the seabed at "
                             f"s = {c['s'][i]:.1f} m: a second touchdown, which this model "
                             "(one touchdown point) cannot represent")
    if scene.water_depth is not None and float(np.max(c["y"])) > scene.water_depth + 1e-3:
        i = int(np.argmax(c["y"]))
        raise BVPFailure(f"the line rises above the water surface (y = {c['y'][i]:.1f} m > "
                         f"water_depth {scene.water_depth:g} m at s = {c['s'][i]:.1f} m); the "
                         "model is fully submerged: reduce the buoyancy or the TDP tension")
    if checks["equilibrium_residual"] > 1e-3:
        raise BVPFailure(f"global force balance violated: residual "
                         f"{checks['equilibrium_residual']:.2e} of the max tension")
    return prof, checks


def _equilibrium_residual(model: BeamModel, Ls: np.ndarray, grounded: float, c: dict) -> float:
    """|P(top) - P(tdp) + integral of the external load| / max tension over the suspended
    line, where the internal force is P = T t - F n, t = (cos, sin), n = (-sin, cos), and
    weight and drag are integrated by the trapezoidal rule (an independent check of the
    collocation solution: O(ds^2) quadrature error)."""
    sel = c["s"] >= grounded - 1e-12
    s, y, th, T, F = (c[k][sel] for k in ("s", "y", "theta", "T", "F"))
    t = np.stack([np.cos(th), np.sin(th)])
    nrm = np.stack([-np.sin(th), np.cos(th)])
    P = T * t - F * nrm
    k = np.searchsorted(np.cumsum(Ls)[:-1], s - grounded, side="right")
    load = np.stack([np.zeros_like(s), -model.w[k]])
    if model.speed is not None:
        V = model.drag_factor * model.speed(y)
        Vn = -V * np.sin(th)
        Vt = V * np.cos(th)
        load = load + model.c_n[k] * np.abs(Vn) * Vn * nrm + model.c_t[k] * np.abs(Vt) * Vt * t
    res = P[:, -1] - P[:, 0] + np.trapezoid(load, s, axis=1)
    return float(np.hypot(*res) / max(np.max(np.abs(c["T"])), 1.0))

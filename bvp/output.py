"""From a converged collocation solution to the :class:`Profile`, with the independent
self-checks of the solution (global force balance, seabed, water surface)."""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from riser.profile import Profile

from .equations import IF, IM, IT, ITH, IX, IY, NSTATE, BeamModel
from .guess import BVPFailure, touchdown_beyond_first


def build_profile(prob, sol, water_depth: float | None) -> tuple[Profile, dict]:
    """Profile at stations every sqrt(EI/T)/8 (0.05-0.5 m) plus the collocation nodes,
    from the bottom end; the checks dict goes into the result's info."""
    model = prob.model
    p = sol.p if sol.p is not None else np.zeros(0)
    Ls = model.segment_lengths(p)
    n = model.n_seg
    EI = model.EI
    Tpeak = max(abs(float(np.max(sol.y[IT::NSTATE]))) * model.scale[IT], 1.0)
    step = float(np.clip(float(np.min(np.sqrt(EI / Tpeak))) / 8.0, 0.05, 0.5))
    cols = {k: [] for k in ("s", "x", "y", "theta", "M", "F", "T", "kappa")}
    s0 = 0.0
    strain = 0.0
    grounded = prob.first_total - Ls[0] if prob.form == "fixed_seabed" else 0.0
    for k in range(n):
        m = max(20, int(math.ceil(Ls[k] / step)))
        tau = np.union1d(np.linspace(0.0, 1.0, m + 1), sol.x)
        if k > 0:
            tau = tau[1:]
        Y = sol.sol(tau)[k * NSTATE:(k + 1) * NSTATE] * model.scale[:, None]
        cols["s"].append(grounded + s0 + Ls[k] * tau)
        for key, i in (("x", IX), ("y", IY), ("theta", ITH), ("M", IM), ("F", IF), ("T", IT)):
            cols[key].append(Y[i])
        cols["kappa"].append(Y[IM] / EI[k])
        strain = max(strain, float(np.max(np.abs(Y[IT]))) * float(model.inv_EA[k]))
        s0 += Ls[k]
    c = {k: np.concatenate(v) for k, v in cols.items()}
    tdp_s = None
    checks: dict = {"max_strain": strain}
    if prob.form in ("tdp_tension", "hang_off_angle", "top_tension", "fixed_seabed",
                     "fixed_lifted"):
        tdp_s = grounded
    if prob.form == "fixed_lifted":
        checks["lifted_off_anchor"] = True
        if c["theta"][0] < -1e-6:
            # too long for a line hanging free from the anchor (a line too long for the
            # span altogether is refused before solving: bvp.strategy.hopeless_span)
            raise BVPFailure(
                "the line would leave the anchor downwards, into the rigid seabed (angle "
                f"{math.degrees(c['theta'][0]):.2f} deg): "
                + touchdown_beyond_first(prob.first_total))
    if prob.form == "fixed_seabed" and grounded > 0.0:
        c = _with_grounded_part(prob, model, c, grounded)
    # joints are evaluated from both sides; drop stations closer than 1 um
    keep = np.concatenate([[True], np.diff(c["s"]) > 1e-6])
    c = {k: v[keep] for k, v in c.items()}
    checks["first_segment_suspended_length"] = float(Ls[0])
    if prob.form == "fixed_seabed":
        checks["grounded_length"] = float(grounded)
    if prob.form == "fixed_elastic":
        tdp_s = lift_off(prob, sol, Ls, c)
    if prob.form == "fixed_liftoff":
        tdp_s = float(Ls[0])
        checks["first_segment_suspended_length"] = float(Ls[1])
        zone = c["s"] <= tdp_s
        checks["contact_zone_max_height"] = float(np.max(c["y"][zone]))
    if tdp_s is not None and prob.form in ("fixed_elastic", "fixed_liftoff"):
        checks["grounded_length"] = float(tdp_s)
    prof = Profile(s=c["s"], x=c["x"], y=c["y"], z=np.zeros_like(c["s"]), theta=c["theta"],
                   tension=c["T"], moment=np.abs(c["M"]), shear=np.abs(c["F"]),
                   curvature=np.abs(c["kappa"]), tdp_s=tdp_s)
    if not prof.is_finite():
        raise BVPFailure("solution contains NaN or inf")
    # independent self-checks of the converged solution
    checks["equilibrium_residual"] = equilibrium_residual(model, Ls, grounded, c)
    if tdp_s is not None and prob.form not in ("fixed_elastic", "fixed_liftoff"):
        susp = c["s"] > tdp_s + 1e-9
        ymin = float(np.min(c["y"][susp])) if np.any(susp) else 0.0
        checks["min_suspended_height"] = ymin
        if ymin < -1e-2:
            i = int(np.argmin(np.where(susp, c["y"], np.inf)))
            raise BVPFailure(f"the suspended line passes {abs(ymin):.3g} m below the seabed at "
                             f"s = {c['s'][i]:.1f} m: a second touchdown, which this model "
                             "(rigid seabed, one touchdown point) cannot represent; "
                             "[model] seabed = \"elastic\" with fixed ends can")
    if water_depth is not None and float(np.max(c["y"])) > water_depth + 1e-3:
        i = int(np.argmax(c["y"]))
        raise BVPFailure(f"the line rises above the water surface (y = {c['y'][i]:.1f} m > "
                         f"water_depth {water_depth:g} m at s = {c['s'][i]:.1f} m); the "
                         "model is fully submerged: reduce the buoyancy or the TDP tension")
    if checks["equilibrium_residual"] > 1e-3:
        raise BVPFailure(f"global force balance violated: residual "
                         f"{checks['equilibrium_residual']:.2e} of the max tension")
    return prof, checks


def _with_grounded_part(prob, model: BeamModel, c: dict, grounded: float) -> dict:
    """Prepend the straight, frictionless grounded part of the rigid-seabed form: T' = -f_t
    (eq. 2 with theta = M = F = 0), so the tangential drag of the current at the seabed
    changes the tension linearly; x advances by (1 + T/EA) per unit unstretched length."""
    sg = np.linspace(0.0, grounded, max(2, int(math.ceil(grounded / 1.0)) + 1))[:-1]
    T0 = c["T"][0]
    f_t = grounded_drag(model)
    T = T0 + f_t * (grounded - sg)
    x = prob.anchor_xy[0] + sg + (T0 * sg + f_t * (grounded * sg - 0.5 * sg ** 2)) * model.inv_EA[0]
    z = np.zeros_like(sg)
    pre = {"s": sg, "x": x, "y": z, "theta": z, "M": z, "F": z, "T": T, "kappa": z}
    return {k: np.concatenate([pre[k], c[k]]) for k in c}


def grounded_drag(model: BeamModel) -> float:
    """Tangential drag per unit length [N/m] on a line lying along +x at y = 0."""
    if model.speed is None:
        return 0.0
    V0 = model.drag_factor * float(model.speed(np.array([0.0]))[0])
    return float(model.c_t[0]) * abs(V0) * V0


def lift_off(prob, sol, Ls: np.ndarray, c: dict) -> float | None:
    """Arc length [m] where the line, in contact (y <= 0) from its bottom end, first rises
    above the seabed: the root of y(s) = 0 on the collocation solution (None when the bottom
    end is not in contact or the whole line is)."""
    y = c["y"]
    if y[0] > 1e-9:                  # the anchor sits on y = 0 up to round-off
        return None
    up = np.flatnonzero(y[1:] > 0.0)
    if up.size == 0:
        return None
    j = int(up[0]) + 1
    sa, sb = float(c["s"][j - 1]), float(c["s"][j])
    edges = np.concatenate([[0.0], np.cumsum(Ls)])
    k = int(np.clip(np.searchsorted(edges, sb, side="left") - 1, 0, len(Ls) - 1))

    def height(s):
        tau = np.array([(s - edges[k]) / Ls[k]])
        return float(sol.sol(tau)[k * NSTATE + IY][0]) * prob.model.scale[IY]

    if height(sa) > 0.0 or height(sb) <= 0.0:
        return sa + (0.0 - y[j - 1]) / (y[j] - y[j - 1]) * (sb - sa)
    return brentq(height, sa, sb, xtol=1e-9)


def equilibrium_residual(model: BeamModel, Ls: np.ndarray, grounded: float, c: dict) -> float:
    """|P(top) - P(bottom) + integral of the external load| / max tension over the solved
    line (the rigid form's grounded part excluded), where the internal force is
    P = T t - F n, t = (cos, sin), n = (-sin, cos), and weight, drag and seabed reaction
    are integrated over the unstretched arc length by the trapezoidal rule (an independent
    check of the collocation solution: O(ds^2) quadrature error)."""
    def force(i):
        th = c["theta"][i]
        return c["T"][i] * np.array([np.cos(th), np.sin(th)]) - c["F"][i] * np.array(
            [-np.sin(th), np.cos(th)])

    edges = grounded + np.concatenate([[0.0], np.cumsum(Ls)])
    res = np.zeros(2)
    for k in range(len(Ls)):       # segment by segment: the weight jumps at the joints
        sel = (c["s"] >= edges[k] - 1e-6) & (c["s"] <= edges[k + 1] + 1e-6)
        s, y, th = c["s"][sel], c["y"][sel], c["theta"][sel]
        t = np.stack([np.cos(th), np.sin(th)])
        nrm = np.stack([-np.sin(th), np.cos(th)])
        load = np.stack([np.zeros_like(s), -model.w[k]
                         + model.seabed_reaction(y, model.linear_zone[k])])
        if model.speed is not None:
            V = model.drag_factor * model.speed(y)
            Vn = -V * np.sin(th)
            Vt = V * np.cos(th)
            load = load + model.c_n[k] * np.abs(Vn) * Vn * nrm + model.c_t[k] * np.abs(Vt) * Vt * t
        res += np.trapezoid(load, s, axis=1)
    i0 = int(np.searchsorted(c["s"], grounded - 1e-6))
    res += force(-1) - force(i0)
    return float(np.hypot(*res) / max(np.max(np.abs(c["T"])), 1.0))

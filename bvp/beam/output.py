"""From a converged collocation solution to the :class:`Profile`, with the independent
self-checks of the solution (global force balance, seabed, water surface)."""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from riser.results.profile import Profile

from .equations import IF, IM, IT, ITH, IX, IY, BeamModel
from .guess import BVPFailure, touchdown_beyond_first


def pieces(model: BeamModel, p: np.ndarray) -> list[dict]:
    """The solved line bottom first, one dict per piece of constant properties: ``block``
    (its rows of the state), ``seg`` (the segment), s0/s1 [m] from the bottom end of the
    solved line, t0/t1 its tau on the block's ``layout``, ``linear`` (the contact zone's
    spring law)."""
    out = []
    blocks = [(model.n_block - 1, model.layout, model.line_segs, model.piece_lengths(p),
               model.zone_length(p), False)]
    if model.split_first:
        blocks.insert(0, (0, model.zone_layout, model.zone_segs, model.zone_lengths(p), 0.0,
                          True))
    for block, lay, segs, L, s0, linear in blocks:
        edges = s0 + np.concatenate([[0.0], np.cumsum(L)])
        for i, k in enumerate(segs):
            out.append(dict(block=block, seg=int(k), s0=float(edges[i]), s1=float(edges[i + 1]),
                            t0=float(lay.edges[i]), t1=float(lay.edges[i + 1]), linear=linear,
                            layout=lay))
    return out


def _state(layout, sol, tau: np.ndarray) -> np.ndarray:
    """The scaled solution at tau, where a tau inside a joint's blend gap of ``layout``
    (a joint station) takes the sharp-joint value: the state at the gap's left node
    t_j - g continued with its slope there (the left piece's f), exact to O(g^2) where the
    blended solution inside the gap is O(g) off (bvp/beam/layout.py)."""
    tau = np.asarray(tau, float)
    gap = layout.in_gap(tau)
    if not np.any(gap):
        return sol.sol(tau)
    j = layout.edges[1:-1]
    i = np.clip(np.searchsorted(j, tau[gap]), 1, j.size)
    lo, hi = j[i - 1], j[np.minimum(i, j.size - 1)]
    near = np.where(np.abs(tau[gap] - lo) <= np.abs(tau[gap] - hi), lo, hi)
    left = near - layout.gap
    Y = sol.sol(tau)
    Y[:, gap] = sol.sol(left) + (tau[gap] - left) * sol.sol(left, 1)
    return Y


def _with_moment_peaks(layout, sol, tau: np.ndarray, rows: slice) -> np.ndarray:
    """``tau`` with a station added at every interior extremum of the moment, where the
    shear F = M' / (1 + eps) changes sign between two stations (its root on the
    collocation solution), so that a peak moment read off the profile does not depend on
    where the stations fall (a peak between stations h apart reads low by ~ h^2 M''/8)."""
    F = _state(layout, sol, tau)[rows][IF]
    flip = np.flatnonzero(F[:-1] * F[1:] < 0.0)
    if not flip.size:
        return tau

    def shear(t):
        return float(_state(layout, sol, np.array([t]))[rows][IF][0])

    roots = [brentq(shear, tau[i], tau[i + 1], xtol=1e-14) for i in flip]
    return np.union1d(tau, roots)


def build_profile(prob, sol, water_depth: float | None) -> tuple[Profile, dict]:
    """Profile at stations every sqrt(EI/T)/8 (0.05-0.5 m) plus the collocation nodes (but
    the node pairs of the joints' blends: a joint is one station, the middle of its pair)
    and the moment's extrema, from the bottom end; the checks dict goes into the result's
    info."""
    model = prob.model
    p = sol.p if sol.p is not None else np.zeros(0)
    parts = pieces(model, p)
    EI = model.EI
    cols = {k: [] for k in ("s", "x", "y", "theta", "M", "F", "T", "kappa")}
    strain = 0.0
    grounded = prob.first_total - parts[0]["s1"] if prob.form == "fixed_seabed" else 0.0
    for pc, s, Y in stations(prob, sol, parts, grounded, _with_moment_peaks):
        k = pc["seg"]
        cols["s"].append(s)
        for key, j in (("x", IX), ("y", IY), ("theta", ITH), ("M", IM), ("F", IF), ("T", IT)):
            cols[key].append(Y[j])
        cols["kappa"].append(Y[IM] / EI[k])
        strain = max(strain, float(np.max(np.abs(Y[IT]))) * float(model.inv_EA[k]))
    c = {k: np.concatenate(v) for k, v in cols.items()}
    checks: dict = {"max_strain": strain}
    if prob.form == "fixed_seabed" and grounded > 0.0:
        c = _with_grounded_part(prob, model, c, grounded)
    # drop stations closer than 1 um
    keep = np.concatenate([[True], np.diff(c["s"]) > 1e-6])
    c = {k: v[keep] for k, v in c.items()}
    tdp_s = contact_checks(prob, sol, c, grounded, c["theta"][0], checks)
    prof = Profile(s=c["s"], x=c["x"], y=c["y"], z=np.zeros_like(c["s"]), theta=c["theta"],
                   tension=c["T"], moment=np.abs(c["M"]), shear=np.abs(c["F"]),
                   curvature=np.abs(c["kappa"]), tdp_s=tdp_s)
    if not prof.is_finite():
        raise BVPFailure("solution contains NaN or inf")
    # independent self-checks of the converged solution
    checks["equilibrium_residual"] = equilibrium_residual(model, parts, grounded, c)
    height_checks(prob, c, tdp_s, water_depth, checks)
    return prof, checks


def stations(prob, sol, parts: list, grounded: float, peaks):
    """(piece, s [m], the SI state (block, k)) at the profile's stations of each piece
    (bvp.beam.output.pieces): every sqrt(EI/T_peak)/8 (0.05-0.5 m), the collocation nodes (but
    the joints' node pairs) and the joints of merged segments, and the extrema the
    function ``peaks(layout, sol, tau, rows) -> tau`` adds; s from the bottom end,
    ``grounded`` [m] ahead of the solved line (the rigid form's straight part)."""
    model = prob.model
    n = model.block
    Tpeak = max(abs(float(np.max(sol.y[IT::n]))) * model.scale[IT], 1.0)
    step = float(np.clip(float(np.min(np.sqrt(model.EI / Tpeak))) / 8.0, 0.05, 0.5))
    for i, pc in enumerate(parts):
        t0, t1, lay = pc["t0"], pc["t1"], pc["layout"]
        nodes = sol.x[(sol.x > t0) & (sol.x < t1)]
        nodes = nodes[~lay.in_gap(nodes)]
        m = max(20, int(math.ceil((pc["s1"] - pc["s0"]) / step)))
        # the joints inside a piece of merged identical segments are stations too
        inner = prob.joints[(prob.joints > grounded + pc["s0"])
                            & (prob.joints < grounded + pc["s1"])]
        tau = np.union1d(np.linspace(t0, t1, m + 1),
                         np.concatenate([nodes, t0 + (inner - grounded - pc["s0"])
                                         / (pc["s1"] - pc["s0"]) * (t1 - t0)]))
        if i > 0:
            tau = tau[1:]
        rows = slice(pc["block"] * n, (pc["block"] + 1) * n)
        tau = peaks(lay, sol, tau, rows)
        Y = _state(lay, sol, tau)[rows] * model.scale[:, None]
        yield pc, grounded + pc["s0"] + (pc["s1"] - pc["s0"]) * (tau - t0) / (t1 - t0), Y


def contact_checks(prob, sol, c: dict, grounded: float, angle0: float, checks: dict):
    """The touchdown (lift-off) arc length [m] of the solved form, None without one, and
    its figures into ``checks`` (first_segment_suspended_length, grounded_length,
    lifted_off_anchor, contact_zone_max_height); ``c`` the station columns (s, y),
    ``angle0`` [rad] the tangent's angle from the horizontal at the bottom end. Raises
    BVPFailure for a line that would leave a lifted anchor downwards."""
    model = prob.model
    p = sol.p if sol.p is not None else np.zeros(0)
    tdp_s = None
    if prob.form in ("tdp_tension", "hang_off_angle", "top_tension", "fixed_seabed",
                     "fixed_lifted"):
        tdp_s = grounded
    if prob.form == "fixed_lifted":
        checks["lifted_off_anchor"] = True
        if angle0 < -1e-6:
            # too long for a line hanging free from the anchor (a line too long for the
            # span altogether is refused before solving: bvp.strategy.hopeless_span)
            raise BVPFailure(
                "the line would leave the anchor downwards, into the rigid seabed (angle "
                f"{math.degrees(angle0):.2f} deg): " + touchdown_beyond_first(prob.first_total))
    # the part of segment 0 beyond the touchdown or lift-off point (0 when the contact
    # zone covers it); the first piece is segment 0 alone in the forms that solve for it
    checks["first_segment_suspended_length"] = (
        max(0.0, prob.first_total - model.zone_length(p)) if model.split_first
        else float(model.piece_lengths(p)[0]) if model.free_first_length
        else prob.first_total)
    if prob.form == "fixed_seabed":
        checks["grounded_length"] = float(grounded)
    if prob.form == "fixed_elastic":
        tdp_s = lift_off(prob, sol, p, c)
    if prob.form == "fixed_liftoff":
        tdp_s = model.zone_length(p)
        checks["contact_zone_max_height"] = float(np.max(c["y"][c["s"] <= tdp_s]))
    if tdp_s is not None and prob.form in ("fixed_elastic", "fixed_liftoff"):
        checks["grounded_length"] = float(tdp_s)
    return tdp_s


def height_checks(prob, c: dict, tdp_s, water_depth: float | None, checks: dict) -> None:
    """The self-checks of the solved heights: a rigid-seabed form's suspended line above
    the seabed (``min_suspended_height`` into ``checks``), the line below the surface, and
    the global force balance (``checks['equilibrium_residual']``, set by the caller);
    raises BVPFailure with the reason."""
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


def lift_off(prob, sol, p: np.ndarray, c: dict) -> float | None:
    """Arc length [m] where the line's first contact zone from the bottom (y <= 0; the
    anchor on y = 0 up to round-off, or further on for an anchor above the seabed) ends,
    rising above the seabed: the root of y(s) = 0 on the collocation solution (None when
    no point is in contact or the whole line is from there on). One block (the
    unilateral form)."""
    y = c["y"]
    on = np.flatnonzero(y <= 1e-9)
    if on.size == 0:
        return None
    up = np.flatnonzero(y[on[0] + 1:] > 0.0)
    if up.size == 0:
        return None
    j = int(on[0]) + int(up[0]) + 1
    sa, sb = float(c["s"][j - 1]), float(c["s"][j])
    model = prob.model

    def height(s):
        tau = model.tau_of(np.array([s]), p)
        return float(sol.sol(tau)[IY][0]) * model.scale[IY]

    if height(sa) > 0.0 or height(sb) <= 0.0:
        return sa + (0.0 - y[j - 1]) / (y[j] - y[j - 1]) * (sb - sa)
    return brentq(height, sa, sb, xtol=1e-9)


def equilibrium_residual(model: BeamModel, parts: list, grounded: float, c: dict) -> float:
    """|P(top) - P(bottom) + integral of the external load| / max tension over the solved
    line (the rigid form's grounded part excluded), where the internal force is
    P = T t - F n, t = (cos, sin), n = (-sin, cos), and weight, drag and seabed reaction
    are integrated over the unstretched arc length by the trapezoidal rule, piece by piece,
    plus the point attachments' forces (``parts``: bvp.beam.output.pieces; an independent check
    of the collocation solution: O(ds^2) quadrature error)."""
    def force(i):
        th = c["theta"][i]
        return c["T"][i] * np.array([np.cos(th), np.sin(th)]) - c["F"][i] * np.array(
            [-np.sin(th), np.cos(th)])

    res = np.zeros(2)
    for pc in parts:              # piece by piece: the weight jumps at the joints
        k = pc["seg"]
        sel = (c["s"] >= grounded + pc["s0"] - 1e-6) & (c["s"] <= grounded + pc["s1"] + 1e-6)
        s, y, th = c["s"][sel], c["y"][sel], c["theta"][sel]
        t = np.stack([np.cos(th), np.sin(th)])
        nrm = np.stack([-np.sin(th), np.cos(th)])
        load = np.stack([np.zeros_like(s), -model.w[k]
                         + model.seabed_reaction(y, pc["linear"])])
        if model.speed is not None:
            V = model.drag_factor * model.speed(y)
            Vn = -V * np.sin(th)
            Vt = V * np.cos(th)
            load = load + model.c_n[k] * np.abs(Vn) * Vn * nrm + model.c_t[k] * np.abs(Vt) * Vt * t
        res += np.trapezoid(load, s, axis=1)
        if model.point_w[k] != 0.0 or model.point_c[k] != 0.0:     # a point attachment
            yp = float(np.interp(grounded + pc["s0"], c["s"], c["y"]))
            V = (model.drag_factor * float(model.speed(np.array([yp]))[0])
                 if model.speed is not None else 0.0)
            res += np.array([model.point_c[k] * abs(V) * V, -model.point_w[k]])
    i0 = int(np.searchsorted(c["s"], grounded - 1e-6))
    res += force(-1) - force(i0)
    return float(np.hypot(*res) / max(np.max(np.abs(c["T"])), 1.0))

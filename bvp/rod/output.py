"""From a converged solution of the 3D rod (bvp/rod/equations.py) to the :class:`Profile`
in the scene's axes, with the rod's own self-checks (3D global force balance, seabed,
water surface): the counterpart of bvp/beam/output.py, whose stations, joint handling and
lift-off search it shares.

The rod is solved in its plane's frame (bvp/rod/problem.py): x' along the plane from the
anchor's x, z' across it. The profile's x, z are mapped back with the plane
(riser.model.frame.LinePlane.from_plane); ``lateral`` is z', ``moment_out_of_plane`` and
``moment_in_plane`` the moment vector m = M1 n2 - M2 n1 on b = unit(t x e_z') and on
b x t (riser.model.frame.plane_columns);
``moment`` is |m| = hypot(M1, M2), ``shear`` hypot(F1, F2), ``curvature`` |m| / EI and
``theta`` the tangent's angle from the horizontal (signed as the VFIFE signs it: beyond
the vertical when the tangent points back along the plane).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from riser.model.frame import LinePlane, elevation, plane_columns
from riser.results.profile import Profile

from ..beam.equations import IF, IM, IT, ITH, IX, IY
from ..beam.guess import BVPFailure
from ..beam.output import _state, contact_checks, height_checks, pieces, stations
from .equations import IF2, IM2, IPH, IZ, RodModel

_COLUMNS = ("s", "x", "y", "z", "th", "ph", "M1", "M2", "F1", "F2", "T")


def _with_moment_peaks(layout, sol, tau: np.ndarray, rows: slice) -> np.ndarray:
    """``tau`` with a station at every interior extremum of |m|: d(|m|^2)/ds / 2 =
    (1 + eps)(M1 F1 + M2 F2) (the frame's turning terms cancel), so where M1 F1 + M2 F2
    changes sign between two stations (its root on the collocation solution)."""
    def slope(Y):
        return Y[IM] * Y[IF] + Y[IM2] * Y[IF2]

    g = slope(_state(layout, sol, tau)[rows])
    flip = np.flatnonzero(g[:-1] * g[1:] < 0.0)
    if not flip.size:
        return tau

    def at(t):
        return float(slope(_state(layout, sol, np.array([t]))[rows])[0])

    return np.union1d(tau, [brentq(at, tau[i], tau[i + 1], xtol=1e-14) for i in flip])


def _frame(th, ph):
    return RodModel.frame(np.asarray(th, float), np.asarray(ph, float))


@dataclass(frozen=True)
class RodState:
    """The rod's converged static state at the profile's stations, in its plane's frame
    (x along the plane from the anchor's x, y up, z across it): the linearisations about
    a 3D state read it (bvp/modal/rod_family.py), as ``SolveResult.solver_state``.

    ``columns``: ``s`` [m], ``x``, ``y``, ``z`` [m], ``th``, ``ph`` [rad], ``M1``, ``M2``
    [N m], ``F1``, ``F2``, ``T`` [N] (bvp/rod/equations.py's states), ``EI`` [N m2],
    ``seg`` (the segment's index) and ``qx``, ``qy``, ``qz`` [N/m]: the static load of the
    current's drag (and a dead load's) per unstretched length, as the equations apply it at
    the static state (the weight and the seabed excluded). ``plane`` maps vectors back to
    the scene's axes."""

    columns: dict
    plane: LinePlane


def build_rod_profile(prob, sol, water_depth: float | None
                      ) -> tuple[Profile, dict, RodState]:
    """The profile of the rod's solution in the scene's axes, at the stations of
    bvp.beam.output.build_profile (the extrema of |m| among them), the checks for the
    result's info, and the :class:`RodState` at those stations."""
    model = prob.model
    p = sol.p if sol.p is not None else np.zeros(0)
    parts = pieces(model, p)
    cols = {k: [] for k in _COLUMNS + ("EI", "seg")}
    strain = 0.0
    grounded = prob.first_total - parts[0]["s1"] if prob.form == "fixed_seabed" else 0.0
    for pc, s, Y in stations(prob, sol, parts, grounded, _with_moment_peaks):
        k = pc["seg"]
        cols["s"].append(s)
        for key, j in (("x", IX), ("y", IY), ("z", IZ), ("th", ITH), ("ph", IPH),
                       ("M1", IM), ("M2", IM2), ("F1", IF), ("F2", IF2), ("T", IT)):
            cols[key].append(Y[j])
        cols["EI"].append(np.full(s.size, model.EI[k]))
        cols["seg"].append(np.full(s.size, k))
        strain = max(strain, float(np.max(np.abs(Y[IT]))) * float(model.inv_EA[k]))
    c = {k: np.concatenate(v) for k, v in cols.items()}
    checks: dict = {"max_strain": strain}
    if prob.form == "fixed_seabed" and grounded > 0.0:
        c = _with_grounded_part(prob, model, c, grounded)
    keep = np.concatenate([[True], np.diff(c["s"]) > 1e-6])
    c = {k: v[keep] for k, v in c.items()}
    t, n1, n2 = _frame(c["th"], c["ph"])
    theta = elevation(LinePlane(), t.T)            # in the plane's frame: x along it
    tdp_s = contact_checks(prob, sol, c, grounded, float(theta[0]), checks)
    moment = np.hypot(c["M1"], c["M2"])
    mvec = c["M1"] * n2 - c["M2"] * n1                      # (3, n), the plane's axes
    lateral, inplane, oop = plane_columns(LinePlane(), c["x"], c["z"], t.T, mvec.T)
    x, z = prob.plane.from_plane(c["x"] - prob.anchor_xy[0], c["z"])
    prof = Profile(s=c["s"], x=x, y=c["y"], z=z, theta=theta, tension=c["T"], moment=moment,
                   shear=np.hypot(c["F1"], c["F2"]), curvature=moment / c["EI"],
                   tdp_s=tdp_s, lateral=lateral, moment_in_plane=inplane,
                   moment_out_of_plane=oop)
    if not prof.is_finite():
        raise BVPFailure("solution contains NaN or inf")
    checks["equilibrium_residual"] = equilibrium_residual(model, parts, grounded, c, t, n1, n2)
    checks["max_tilt_deg"] = float(np.degrees(np.max(np.abs(c["ph"]))))
    height_checks(prob, c, tdp_s, water_depth, checks)
    q = static_drag(model, c, t, n1, n2)
    state = RodState({**c, "qx": q[0], "qy": q[1], "qz": q[2]}, prob.plane)
    return prof, checks, state


def static_drag(model: RodModel, c: dict, t, n1, n2) -> np.ndarray:
    """(3, n) [N/m]: the current's drag (tangential c_t |U.t| U.t t, normal c_n |U_n| U_n)
    and a dead load at the stations ``c`` (with ``seg``), in the plane's frame: the
    equations' load less the weight and the seabed."""
    out = np.zeros((3, c["s"].size))
    if model.dead_load is not None:
        out += model._dead()
    if model.has_drag:
        k = c["seg"].astype(int)
        ux, uz, _, _ = model.current(c["y"])
        U = np.stack([ux, np.zeros_like(ux), uz])
        Ut = np.sum(U * t, axis=0)
        U1, U2 = np.sum(U * n1, axis=0), np.sum(U * n2, axis=0)
        r = np.hypot(U1, U2)
        out += (np.asarray(model.c_t)[k] * np.abs(Ut) * Ut * t
                + np.asarray(model.c_n)[k] * r * (U1 * n1 + U2 * n2))
    return out


def _with_grounded_part(prob, model: RodModel, c: dict, grounded: float) -> dict:
    """Prepend the straight, frictionless grounded part of the rigid-seabed form, along the
    touchdown's heading phi(0) from the anchor: T' = -f_t, x advancing by (1 + T/EA)."""
    sg = np.linspace(0.0, grounded, max(2, int(math.ceil(grounded / 1.0)) + 1))[:-1]
    T0, ph0 = c["T"][0], c["ph"][0]
    d = np.array([math.cos(ph0), 0.0, math.sin(ph0)])
    ut = float(model.grounded_velocity() @ d)
    f_t = float(model.c_t[0]) * abs(ut) * ut
    T = T0 + f_t * (grounded - sg)
    r = sg + (T0 * sg + f_t * (grounded * sg - 0.5 * sg ** 2)) * model.inv_EA[0]
    z = np.zeros_like(sg)
    pre = {"s": sg, "x": prob.anchor_xy[0] + r * d[0], "y": z, "z": r * d[2], "th": z,
           "ph": np.full_like(sg, ph0), "M1": z, "M2": z, "F1": z, "F2": z, "T": T,
           "EI": np.full_like(sg, model.EI[0]), "seg": np.zeros_like(sg)}
    return {k: np.concatenate([pre[k], c[k]]) for k in c}


def equilibrium_residual(model: RodModel, parts: list, grounded: float, c: dict, t, n1,
                         n2) -> float:
    """|P(top) - P(bottom) + integral of the external load| / max tension over the solved
    line (the rigid form's grounded part excluded), P = T t - F1 n1 - F2 n2, the loads
    (weight, seabed, drag, dead load) integrated by the trapezoidal rule piece by piece:
    the 3D counterpart of bvp.beam.output.equilibrium_residual (O(ds^2) quadrature error)."""
    res = np.zeros(3)
    for pc in parts:
        k = pc["seg"]
        sel = (c["s"] >= grounded + pc["s0"] - 1e-6) & (c["s"] <= grounded + pc["s1"] + 1e-6)
        s, y = c["s"][sel], c["y"][sel]
        ts, n1s, n2s = t[:, sel], n1[:, sel], n2[:, sel]
        load = np.zeros((3, s.size))
        load[1] = -model.w[k] + (model.seabed_reaction(y, pc["linear"])
                                 if model.k_seabed > 0.0 else 0.0)
        if model.dead_load is not None:
            load += model._dead()
        if model.has_drag:
            ux, uz, _, _ = model.current(y)
            U = np.stack([ux, np.zeros_like(y), uz])
            Ut = np.sum(U * ts, axis=0)
            U1, U2 = np.sum(U * n1s, axis=0), np.sum(U * n2s, axis=0)
            r = np.hypot(U1, U2)
            load += (model.c_t[k] * np.abs(Ut) * Ut * ts
                     + model.c_n[k] * r * (U1 * n1s + U2 * n2s))
        res += np.trapezoid(load, s, axis=1)
    i0 = int(np.searchsorted(c["s"], grounded - 1e-6))

    def force(i):
        return c["T"][i] * t[:, i] - c["F1"][i] * n1[:, i] - c["F2"][i] * n2[:, i]

    res += force(-1) - force(i0)
    return float(np.linalg.norm(res) / max(np.max(np.abs(c["T"])), 1.0))

"""The five closed-form cases of the end-condition study, each by both methods.

Each case returns its rows (a dict per checked quantity: ``case``, ``quantity``, ``unit``,
``closed_form``, ``bvp``, ``vfife`` and the tolerances ``bvp_tol``, ``vfife_tol`` relative
to the closed form) and what its figure needs. The tolerances are those of
``tests/test_end_conditions.py`` and ``tests/test_attachments.py``; a test's absolute
tolerance is divided by the closed form's magnitude, and where a test holds the VFIFE to
the BVP (abs 1e-6 m) rather than to the closed form, the VFIFE's tolerance against the
closed form is the sum of the two (the triangle inequality).

The VFIFE statics use ``tolerance = 1e-5`` (largest out-of-balance force / one element's
load) where the tests do, in the statics checked against a closed form: the relaxation's
default stop (1e-3) leaves the light taut line about 4e-4 short of its deflection, its
lowest mode's stiffness being small against one element's load (case 1 solves it at the
default stop too, and the report states what it left in this run). The modal cases'
statics keep the default, as the tests do.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import fsolve
from scipy.special import jn_zeros

from riser.model.sections import segment_properties
from verification.methods import method

from . import scenes as S
from .scenes import EI, L, T

#: lambda = sqrt(T/EI) [1/m] of the tensioned line
LAMBDA = math.sqrt(T / EI)
#: the VFIFE's static tolerance where the tests set it (module docstring)
VFIFE_TOLERANCE = 1.0e-5
#: the flex joint's rotational stiffnesses [N m/rad] of case 2
FLEX_STIFFNESS = (2.0e6, 2.0e7)


def row(case, quantity, unit, closed, b, v, bvp_tol, vfife_tol) -> dict:
    return {"case": case, "quantity": quantity, "unit": unit, "closed_form": float(closed),
            "bvp": float(b), "vfife": float(v), "bvp_tol": float(bvp_tol),
            "vfife_tol": float(vfife_tol)}


def x_at(profile, y: float) -> float:
    """x [m] at height y of a vertical line (a cubic through its stations)."""
    keep = np.concatenate([[True], np.diff(profile.y) > 0.0])
    return float(CubicSpline(profile.y[keep], profile.x[keep])(y))


def at(profile, s: float, key: str) -> float:
    return float(np.interp(s, profile.s, getattr(profile, key)))


# --------------------------------------------------------------- 1: TTR in a current
def ttr_deflection(y):
    """The pinned-pinned tensioned beam under the uniform drag q: (w(y), w'(y))."""
    q = 0.5 * 1025.0 * 0.3 * 1.0 * S.CURRENT ** 2      # 1/2 rho D C_D V^2 of the scene
    y = np.asarray(y, dtype=float)
    c = math.cosh(LAMBDA * L / 2)
    w = q / (2 * T) * y * (L - y) + q * EI / T ** 2 * (np.cosh(LAMBDA * (y - L / 2)) / c - 1)
    dw = q / (2 * T) * (L - 2 * y) + q * EI / T ** 2 * LAMBDA * np.sinh(LAMBDA * (y - L / 2)) / c
    return w, dw


def ttr_current():
    sc = S.scene(S.vertical(current=S.CURRENT, name="ttr-current"))
    b = method("bvp").solve(sc).require()
    v = method("vfife").solve(sc, element_length=1.0, tolerance=VFIFE_TOLERANCE).require()
    rows = []
    for frac, tol in ((0.5, 2e-4), (0.2, 5e-4)):
        y = frac * L
        rows.append(row("ttr-current", f"x at y = {frac:g} L", "m", ttr_deflection(y)[0],
                        x_at(b.profile, y), x_at(v.profile, y), tol, tol))
    # the top slides: stretched by T/EA, less what the bow takes, 1/2 int w'^2 dy
    y = np.linspace(0.0, L, 20001)
    rise = L * T / S.EA - 0.5 * float(np.trapezoid(ttr_deflection(y)[1] ** 2, y))
    rows.append(row("ttr-current", "top's rise y_top - L", "m", rise,
                    b.profile.y[-1] - L, v.profile.y[-1] - L, 1e-6 / rise, 2e-6 / rise))
    # the relaxation's default stop on the same mesh: what the tolerance 1e-5 is for
    v3 = method("vfife").solve(sc, element_length=1.0).require()
    default = x_at(v3.profile, L / 2) / ttr_deflection(L / 2)[0] - 1.0
    return rows, {"bvp": b.profile, "vfife": v.profile, "default_stop_rel": default,
                  "default_tolerance": v3.info["tolerance"]}


# --------------------------------------------------------------- 2: clamp + flex joint
def clamp_closed_form(k: float, alpha: float):
    """(M(0), M(L), w(L/2)) of the unloaded tensioned beam clamped alpha from the vertical
    at the anchor, pinned on a rotational spring k about the vertical at the top."""
    lam, ch, sh = LAMBDA, math.cosh(LAMBDA * L), math.sinh(LAMBDA * L)
    A = np.array([[1.0, 0.0, 1.0, 0.0],
                  [0.0, 1.0, 0.0, lam],
                  [1.0, L, ch, sh],
                  [0.0, k, EI * lam * lam * ch + k * lam * sh,
                   EI * lam * lam * sh + k * lam * ch]])
    a, bb, c, d = np.linalg.solve(A, [0.0, math.tan(alpha), 0.0, 0.0])
    M0 = -EI * c * lam * lam
    ML = -EI * lam * lam * (c * ch + d * sh)
    w_mid = a + bb * L / 2 + c * math.cosh(lam * L / 2) + d * math.sinh(lam * L / 2)
    return M0, ML, w_mid


def clamp_case(k: float) -> str:
    """The case name of the flex joint k [N m/rad]: 'clamp-flex-k2e6'."""
    return f"clamp-flex-k{k:.0e}".replace("+0", "")


def clamp_flex(k: float):
    case = clamp_case(k)
    sc = S.scene(S.vertical(anchor_joint={"kind": "clamped", "direction_deg": 89.0},
                            hang_off_joint={"kind": "spring", "direction_deg": 90.0,
                                            "rotational_stiffness": k}, name=case))
    M0, ML, w_mid = clamp_closed_form(k, math.radians(1.0))
    b = method("bvp").solve(sc).require()
    v = method("vfife").solve(sc, element_length=0.5, tolerance=VFIFE_TOLERANCE).require()
    sb, sv = b.summary(), v.summary()
    data = None
    if k == FLEX_STIFFNESS[0]:
        # the same mesh relaxed ten times further: what the stop at 1e-5 leaves (report)
        v6 = method("vfife").solve(sc, element_length=0.5,
                                   tolerance=VFIFE_TOLERANCE / 10).require()
        data = {"x_mid_rel": x_at(v6.profile, L / 2) / w_mid - 1.0,
                "hang_off_moment_rel": v6.summary()["hang_off_moment"] / ML - 1.0}
    return [
        row(case, "anchor direction", "deg", 89.0, math.degrees(b.profile.theta[0]),
            math.degrees(v.profile.theta[0]), 1e-9 / 89.0, 1e-9 / 89.0),
        row(case, "anchor moment M(0)", "N m", M0, sb["anchor_moment"], sv["anchor_moment"],
            5e-4, 1e-3),
        # the VFIFE's end moments on the comparison's basis, the largest moment M(0)
        row(case, "hang-off moment M(L)", "N m", ML, sb["hang_off_moment"],
            sv["hang_off_moment"], 5e-4, 1e-3 * abs(M0 / ML)),
        row(case, "x at y = 0.5 L", "m", w_mid, x_at(b.profile, L / 2),
            x_at(v.profile, L / 2), 2e-3, 2e-3),
    ], data


# --------------------------------------------------------------- modes
def frequencies(modal, plane: str) -> np.ndarray:
    return np.array([m.frequency_hz for m in modal.modes if m.plane == plane])


def modes_of(sc, count: int, static_b, static_v):
    b = method("bvp").modes(sc, count, static=static_b)
    v = method("vfife").modes(sc, count, static=static_v)
    for name, res in (("BVP", b), ("VFIFE", v)):
        if not res.converged:
            raise RuntimeError(f"{sc.name}: the {name} modes: {res.message}")
    return {plane: (frequencies(b, plane), frequencies(v, plane))
            for plane in ("in_plane", "out_of_plane")}


def mode_rows(case, closed, found, bvp_tol, vfife_tol):
    return [row(case, f"f{n + 1} {plane.replace('_', '-')}", "Hz", f, fb[n], fv[n],
                bvp_tol, vfife_tol)
            for plane, (fb, fv) in found.items() for n, f in enumerate(closed)]


# --------------------------------------------------------------- 3: TTR frequencies
def ttr_modes():
    sc = S.scene(S.vertical(name="ttr-modes"))
    p = segment_properties(sc)[0]
    m = p.mass + p.added_mass
    closed = [math.sqrt((EI * k ** 4 + T * k ** 2) / m) / (2 * math.pi)
              for k in (n * math.pi / L for n in (1, 2, 3, 4))]
    found = modes_of(sc, 4, None, method("vfife").solve(sc, element_length=0.5).require())
    return mode_rows("ttr-modes", closed, found, 2e-4, 2e-3), None


# --------------------------------------------------------------- 4: hanging chain
def hanging_chain():
    sc = S.scene(S.hanging_chain())
    p = segment_properties(sc)[0]
    closed = jn_zeros(0, 5) / 2.0 * math.sqrt(p.weight / p.mass / L) / (2 * math.pi)
    b = method("bvp").solve(sc).require()
    v = method("vfife").solve(sc, element_length=0.5).require()
    found = modes_of(sc, 5, b, v)
    stretch = p.weight * L * L / (2.0 * S.EA)
    top = S.CHAIN_TOP - L
    rows = [row("hanging-chain", "free end's stretch", "m", stretch, top - b.profile.y[0],
                top - v.profile.y[0], 1e-6 / stretch, 2e-6 / stretch)]
    rows += mode_rows("hanging-chain", closed, found, 1e-4, 4e-3)
    return rows, {"closed": np.asarray(closed), "found": found}


# --------------------------------------------------------------- 5: attachments
def two_catenaries(W: float):
    """Irvine's elastic catenary either side of a point of net weight W [N]: (H, V0, the
    point's (x, y), the tension either side of it)."""
    w, ea, sp = S.CABLE_WEIGHT, S.CABLE_EA, S.S_P

    def reach(H, Va, a, b):
        Vb = Va + w * (b - a)
        return (H / w * (math.asinh(Vb / H) - math.asinh(Va / H)) + H * (b - a) / ea,
                H / w * (math.hypot(1.0, Vb / H) - math.hypot(1.0, Va / H))
                + (Va + Vb) * (b - a) / (2.0 * ea))

    def ends(z):
        H, V0 = z
        x1, y1 = reach(H, V0, 0.0, sp)
        x2, y2 = reach(H, V0 + w * sp + W, sp, S.CABLE_LENGTH)
        return [x1 + x2 - S.CABLE_SPAN, y1 + y2 - S.CABLE_RISE]

    H, V0 = fsolve(ends, [w * S.CABLE_LENGTH, 0.0], xtol=1e-13)
    x1, y1 = reach(H, V0, 0.0, sp)
    below = V0 + w * sp
    return H, V0, (x1, 10.0 + y1), (math.hypot(H, below), math.hypot(H, below + W))


def attachment(kind: str):
    case = f"{kind}-on-cable"
    sc = S.scene(S.cable(kind))
    W = sc.attachments[0].net_weight(sc.gravity, sc.water_density)
    H, V0, (xp, yp), (t_below, t_above) = two_catenaries(W)
    b = method("bvp").solve(sc).require()
    v = method("vfife").solve(sc, element_length=0.5, tolerance=VFIFE_TOLERANCE).require()
    pb, pv = b.profile, v.profile
    # the BVP's internal force |P| = hypot(T, F) either side of the point (its station at
    # s_p holds the side below, the next one the side above); the VFIFE's node: the mean
    i = int(np.flatnonzero(np.isclose(pb.s, S.S_P, rtol=0.0, atol=1e-9))[0])
    p_mean = 0.5 * (math.hypot(pb.tension[i], pb.shear[i])
                    + math.hypot(pb.tension[i + 1], pb.shear[i + 1]))
    j = int(np.argmin(np.abs(pv.s - S.S_P)))
    t_end = math.hypot(H, V0 + S.CABLE_WEIGHT * S.CABLE_LENGTH + W)
    return [
        row(case, "point x", "m", xp, at(pb, S.S_P, "x"), at(pv, S.S_P, "x"),
            1e-2 / abs(xp), 3e-3 / abs(xp)),
        row(case, "point y", "m", yp, at(pb, S.S_P, "y"), at(pv, S.S_P, "y"),
            1e-2 / abs(yp), 3e-3 / abs(yp)),
        row(case, "anchor tension", "N", math.hypot(H, V0), pb.tension[0], pv.tension[0],
            1e-4, 1e-4),
        row(case, "hang-off tension", "N", t_end, pb.tension[-1], pv.tension[-1], 1e-4, 1e-4),
        row(case, "force at the point, mean of its sides", "N", 0.5 * (t_below + t_above),
            p_mean, pv.tension[j], 2e-4, 2e-3),
    ], None


#: the cases in the order of the table: (name, function, its argument)
CASES = (("ttr-current", ttr_current, ()),
         *((clamp_case(k), clamp_flex, (k,)) for k in FLEX_STIFFNESS),
         ("ttr-modes", ttr_modes, ()),
         ("hanging-chain", hanging_chain, ()),
         *((f"{kind}-on-cable", attachment, (kind,)) for kind in S.ATTACHMENTS))


def run_all(log=None):
    """Every case: (rows, {case: its figure data})."""
    rows, data = [], {}
    for name, fn, args in CASES:
        r, d = fn(*args)
        rows += r
        if d is not None:
            data[name] = d
        if log is not None:
            log(name)
    return rows, data

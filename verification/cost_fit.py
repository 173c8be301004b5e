"""Quantities, errors and convergence fits of the cost study (:mod:`verification.cost`).

Everything here is arithmetic on solved profiles and numbers: the scalar quantities of a
profile and their relative errors, the Richardson limit of an element-length sequence,
the fitted order, the lengths that bound the asymptotic range, and the wording of the
order assessment. No solver is run.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from scipy.interpolate import CubicSpline

from riser.profile import Profile, summarize
from riser.scene import Scene

QUANTITIES = ("hang_off_tension", "tdp_tension", "tdp_x", "max_moment", "crest_height",
              "sag_height", "curve_distance")
QUANTITY_LABEL = {
    "hang_off_tension": "hang-off tension", "tdp_tension": "touchdown tension",
    "tdp_x": "touchdown position", "max_moment": "peak moment",
    "crest_height": "crest height(s)", "sag_height": "sag height(s)",
    "curve_distance": "curve distance (max)"}
#: expected order of the VFIFE static solution in element length (see the report text)
EXPECTED_ORDER = 2.0
#: a point enters the order fit only if its error is this many times the noise floor: its
#: log error is then uncertain by at most log(1.1) ~ 0.1, i.e. <= 0.1 in the order over a
#: factor-2.5 step of the element length
NOISE_MARGIN = 10.0
#: |fitted order - expected| beyond which the report explains the departure
ORDER_BAND = 0.3
#: errors above this are pre-asymptotic (unresolved boundary layers) and left out of the fit
PRE_ASYMPTOTIC = 1e-2
#: stations per interval of the reference profile when it is densified for the curve
#: distance (cubic spline in arc length): the chord error of the BVP output spacing d,
#: kappa d^2 / 8 (Wang baseline, d = 0.43 m: 5e-8 of the depth, as large as the VFIFE
#: error at 0.5 m), drops by 8^2
DENSIFY = 8


# ----------------------------------------------------------------------------- quantities
def raw_values(profile: Profile, ref_summary: dict | None = None) -> dict:
    """Scalar quantities of a profile (already in the reference arc length). Crests and sags
    are matched to the reference ones by arc length: keys crest1_height, sag1_height, ..."""
    sm = summarize(profile)
    out = {"hang_off_tension": sm["hang_off_tension"], "tdp_tension": sm["tdp_tension"],
           "tdp_x": sm["tdp_x"], "max_moment": sm["max_moment"]}
    ref = ref_summary or sm
    for kind in ("crests", "sags"):
        for i, cb in enumerate(ref[kind]):
            cand = sm[kind]
            c = min(cand, key=lambda c: abs(c["s"] - cb["s"])) if cand else None
            out[f"{kind[:-1]}{i + 1}_height"] = c["height"] if c else None
    return out


def family(q: str, values: dict) -> list[str]:
    """Raw keys of a quantity (crest_height: crest1_height, crest2_height, ...)."""
    if q in ("crest_height", "sag_height"):
        tag = q.split("_")[0]
        return sorted(k for k in values if k.startswith(tag) and k.endswith("_height"))
    return [q]


def norm(q: str, ref_values: dict, depth: float) -> float:
    """Normalising value of a quantity: the reference value (forces), else ``depth``."""
    if q in ("hang_off_tension", "tdp_tension", "max_moment"):
        v = ref_values.get(q)
        return abs(v) if v else float("nan")
    return depth


def rel_errors(values: dict, ref_values: dict, depth: float, norm_values=None) -> dict:
    """Relative errors per quantity family (max over crests/sags); None when undefined.
    Tensions and moment are normalised by ``norm_values`` (default ``ref_values``)."""
    out = {}
    nv = norm_values or ref_values
    for q in QUANTITIES:
        if q == "curve_distance":
            continue
        keys = family(q, ref_values)
        errs = []
        for k in keys:
            a, b = values.get(k), ref_values.get(k)
            if a is None or b is None:
                errs = None
                break
            errs.append(abs(a - b) / norm(q, nv, depth))
        out[q] = max(errs) if errs else None
    return out


def signed_errors(values: dict, ref_values: dict, depth: float) -> dict:
    """Signed relative errors (value - reference) per quantity family, of the member with
    the largest magnitude; None when undefined (no curve distance)."""
    out = {}
    for q in QUANTITIES:
        keys = family(q, ref_values) if q != "curve_distance" else []
        errs = [(values[k] - ref_values[k]) / norm(q, ref_values, depth) for k in keys
                if values.get(k) is not None and ref_values.get(k) is not None]
        out[q] = max(errs, key=abs) if errs and len(errs) == len(keys) else None
    return out


def densified(p: Profile, n: int = DENSIFY) -> Profile:
    """``p`` with ``n`` stations per interval, positions from cubic splines in arc length
    (for the curve distance to a polyline of the reference)."""
    t = np.linspace(0.0, 1.0, n + 1)[:-1]
    s = np.concatenate([(p.s[:-1, None] + t[None, :] * np.diff(p.s)[:, None]).ravel(),
                        p.s[-1:]])
    xyz = {k: CubicSpline(p.s, getattr(p, k))(s) for k in ("x", "y", "z")}
    return dataclasses.replace(p, s=s, **xyz, theta=np.interp(s, p.s, p.theta),
                               tension=np.interp(s, p.s, p.tension),
                               moment=np.interp(s, p.s, p.moment),
                               shear=np.interp(s, p.s, p.shear),
                               curvature=np.interp(s, p.s, p.curvature))


def distance(ref: Profile, p: Profile, depth: float) -> float:
    """Largest distance from the stations of ``p`` to the curve ``ref`` over their common
    arc length, relative to ``depth``."""
    from .compare import curve_distance
    lo, hi = max(ref.s[0], p.s[0]), min(ref.s[-1], p.s[-1])
    return curve_distance(ref, p, (lo, hi))[0] / depth


# ----------------------------------------------------------------------------- fits
def richardson(hs, qs) -> tuple[float, float | None]:
    """Limit and observed order from the three finest of ``hs`` (a constant refinement
    ratio is not required: the order solves (q1-q2)/(q2-q3) = (h1^p-h2^p)/(h2^p-h3^p)).
    Returns (limit, order); order None (limit = finest value) when the differences change
    sign or are zero, i.e. the sequence is not in its asymptotic range."""
    pts = sorted(zip(hs, qs))[:3]
    if len(pts) < 3:
        return (pts[0][1] if pts else float("nan")), None
    (h3, q3), (h2, q2), (h1, q1) = pts
    d12, d23 = q1 - q2, q2 - q3
    if d12 == 0.0 or d23 == 0.0 or (d12 > 0) != (d23 > 0):
        return q3, None
    target = d12 / d23

    def f(p):
        return (h1 ** p - h2 ** p) / (h2 ** p - h3 ** p) - target
    lo, hi = 0.2, 8.0
    if f(lo) * f(hi) > 0:
        return q3, None
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0:
            hi = mid
        else:
            lo = mid
    p = 0.5 * (lo + hi)
    C = d23 / (h2 ** p - h3 ** p)
    return q3 - C * h3 ** p, p


def richardson_limits(hs, values: list[dict]) -> tuple[dict, dict]:
    """Per raw key of ``values`` (aligned with ``hs``): (Richardson limit, order)."""
    keys = sorted({k for v in values for k in v if v.get(k) is not None})
    limits, orders = {}, {}
    for k in keys:
        ok = [(h, v[k]) for h, v in zip(hs, values) if v.get(k) is not None]
        if len(ok) >= 3:
            limits[k], orders[k] = richardson([h for h, _ in ok], [q for _, q in ok])
        elif ok:
            limits[k], orders[k] = min(ok)[1], None
    return limits, orders


def fit_order(hs, errs, floor: float = 0.0, ceiling: float = PRE_ASYMPTOTIC) -> dict:
    """Least-squares slope of log(err) vs log(h) over the points with
    floor < err <= ceiling (above the noise, in the asymptotic range).
    Returns {'order', 'points' (h used), 'r2'} (order None with fewer than 2 points)."""
    pts = [(h, e) for h, e in zip(hs, errs)
           if e is not None and np.isfinite(e) and max(floor, 0.0) < e <= ceiling]
    if len(pts) < 2:
        return {"order": None, "points": [h for h, _ in pts], "r2": None}
    x = np.log([h for h, _ in pts])
    y = np.log([e for _, e in pts])
    p, c = np.polyfit(x, y, 1)
    yhat = p * x + c
    ss = float(np.sum((y - y.mean()) ** 2))
    r2 = 1.0 - float(np.sum((y - yhat) ** 2)) / ss if ss > 0 else 1.0
    return {"order": float(p), "const": float(c), "points": [h for h, _ in pts], "r2": r2}


def element_length_fits(hs, errors: dict, floor: dict | None = None,
                        h_max: float = math.inf) -> dict:
    """Fitted order per quantity of an element-length sweep. ``errors[q]``: errors aligned
    with ``hs`` (against the reference); a point enters the fit if its element length is
    at most ``h_max`` (the asymptotic range) and its error above ``floor[q]``. Each fit
    also carries the local orders of successive lengths (see :func:`_fit_context`)."""
    fits = {}
    for q, errs in errors.items():
        use = [(h, e) for h, e in zip(hs, errs) if h <= h_max]
        fl = (floor or {}).get(q, 0.0)
        fits[q] = fit_order([h for h, _ in use], [e for _, e in use], fl)
        fits[q].update(_fit_context(hs, errs, h_max, fl))
        fits[q]["errors"] = [e for h, e in use if h in fits[q]["points"]]
    return fits


def _fit_context(hs, errs, h_max: float, floor: float) -> dict:
    """Local orders log(e1/e2)/log(h1/h2) of successive element lengths (all of them, for
    the report) and the largest error of the lengths in the asymptotic range (h <= h_max)
    when none of them is above the noise floor."""
    pts = list(zip(hs, errs))
    local = [(h1, h2, math.log(e1 / e2) / math.log(h1 / h2))
             for (h1, e1), (h2, e2) in zip(pts, pts[1:]) if e1 and e2 and e1 > 0 and e2 > 0]
    inside = [e for h, e in zip(hs, errs) if h <= h_max and e is not None]
    below = bool(inside) and max(inside) <= floor
    return {"local": local, "below_noise": max(inside) if below else None,
            "noise_margin": floor, "n_inside": len(inside)}


def pareto(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Non-dominated (time, error) points, sorted by time."""
    front, best = [], float("inf")
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front


# ----------------------------------------------------------------------------- lengths
def boundary_layer_length(scene: Scene, ref: Profile) -> float:
    """Length of the bending boundary layer at the touchdown [m]: sqrt(EI/T) with the
    touchdown (lift-off) tension of the BVP profile ``ref`` of ``scene`` and the EI of the
    section there (a line without touchdown: the lowest tension along the line). The
    quantities of the order fit are decided around the touchdown and the sag bend, where
    the tension is lowest and this length the longest (Wang baseline: 7.8 m; Yu A3: 27 m)."""
    EI, T = _touchdown_section(scene, ref)
    return math.sqrt(EI / max(T, 1e-9))


def foundation_length(scene: Scene, ref: Profile) -> float | None:
    """Foundation length (4 EI/k)^(1/4) [m] of the elastic seabed at the touchdown (None
    without a seabed): the length over which the grounded line settles into the seabed
    (Wang pipe on 1e5 N/m2: 4.4 m; Yu flexible pipe: 4.2 m)."""
    if scene.seabed is None or scene.seabed.stiffness <= 0.0:
        return None
    EI, _ = _touchdown_section(scene, ref)
    return (4.0 * EI / scene.seabed.stiffness) ** 0.25


def asymptotic_length(scene: Scene, ref: Profile) -> float:
    """Longest element length of the asymptotic range: the shorter of the bending boundary
    layer and the foundation length. Longer elements do not resolve the curvature of the
    touchdown, the sag bend or the contact zone, so their errors are pre-asymptotic."""
    lf = foundation_length(scene, ref)
    bl = boundary_layer_length(scene, ref)
    return min(bl, lf) if lf is not None else bl


def _touchdown_section(scene: Scene, ref: Profile) -> tuple[float, float]:
    """(EI [N m2], |T| [N]) at the touchdown of the BVP profile ``ref`` of ``scene`` (else at
    its lowest tension)."""
    from vfife.mesh import build_mesh
    mesh = build_mesh(scene, 10.0)
    mid = 0.5 * (mesh.s[1:] + mesh.s[:-1])
    if ref.tdp_s is not None:
        s0 = ref.tdp_s
    else:
        s0 = float(ref.s[int(np.argmin(np.abs(ref.tension)))])
    T = abs(float(np.interp(s0, ref.s, ref.tension)))
    return float(mesh.EI[int(np.argmin(np.abs(mid - s0)))]), T


def liftoff_interpolation(ref: Profile) -> dict | None:
    """Slope theta0 [rad] and curvature kappa0 [1/m] of the reference at its lift-off, and
    the coefficient C [m/m2] of the bound C h^2 on the error of a lift-off read off a
    polyline of nodes h apart by linear interpolation of the height (the chord of a curve
    of curvature kappa0 lies up to h^2 kappa0 / 8 off it, which moves the crossing of
    y = 0 by that over theta0). None without a lift-off."""
    if ref.tdp_s is None:
        return None
    th = abs(float(np.interp(ref.tdp_s, ref.s, ref.theta)))
    ka = float(np.interp(ref.tdp_s, ref.s, ref.curvature))
    if th <= 0.0:
        return None
    return {"theta0": th, "kappa0": ka, "coef": ka / (8.0 * th)}


# ----------------------------------------------------------------------------- assessment
def _why(q: str, c: dict, fit: dict) -> str:
    """Why the errors of ``q`` need not fall on one h^2 line, with the scene's numbers
    (``c``: see :func:`order_assessment`)."""
    kink = ""
    if c.get("theta0") is not None and c.get("stiffness"):
        kink = (f"the seabed reaction is lumped at the nodes (trapezoid rule): across the "
                f"element holding the lift-off, where k max(-y, 0) has its kink, the lumped "
                f"reaction exceeds the distributed one by k theta0 h^2 xi (1 - xi) / 2, up to "
                f"k theta0 h^2 / 8 = {c['stiffness'] * c['theta0'] / 8:.3g} h^2 N "
                f"(theta0 = {c['theta0']:.3g} rad at the lift-off, xi the lift-off's place "
                "in its element): O(h^2), but with a constant that changes from mesh to mesh")
    if q == "tdp_x" and c.get("coef") is not None:
        a, d = c["coef"], c.get("depth", 1.0)
        ratio = [e / (a * h * h / d) for h, e in zip(fit.get("points", []),
                                                      fit.get("errors", [])) if a > 0]
        env = (f"; the measured errors are {', '.join(f'{r:.2f}' for r in ratio)} x that "
               f"bound at {', '.join(f'{h:g}' for h in fit['points'])} m" if ratio else "")
        return (f"the lift-off is read off the nodal polyline by linear interpolation of the "
                f"heights; the reference crosses y = 0 at theta0 = {c['theta0']:.3g} rad with "
                f"curvature {c['kappa0']:.2g} 1/m, so the interpolation alone errs by "
                f"h^2 kappa0 xi (1 - xi) / (2 theta0), up to {a:.3g} h^2 m ({a / d:.2g} h^2 "
                f"of the depth, {a * 4.0 / d:.2g} at 2 m, {a / d:.2g} at 1 m), with xi the "
                "crossing's place between its two nodes, different on every mesh: O(h^2) "
                f"in envelope, erratic from one mesh to the next{env}")
    if q in ("tdp_tension", "hang_off_tension") and kink:
        return kink + ("; the touchdown tension is moreover taken at the VFIFE lift-off (see "
                       "touchdown position)" if q == "tdp_tension" else "")
    if q in ("crest_height", "sag_height"):
        kind = "crest" if q == "crest_height" else "sag bend"
        if c.get(f"n_{q}", 2) > 1:
            why = (f"the worst of several {kind}s: each converges at order 2 with its own "
                   "constant (whose sign can change), and the worst one can switch between "
                   "meshes")
        else:
            why = (f"a single {kind}, whose error is small (at most "
                   f"{max(fit.get('errors') or [0.0]):.1e} of the depth in the fit)")
    else:
        why = {"max_moment": "the peak moment is a maximum over the line: where two peaks "
                             "(sag bend, hog bend, touchdown region) are nearly equal, the "
                             "peak taken can change between meshes and the error jumps "
                             "between their error curves",
               "curve_distance": "a maximum over the line, whose place can move between "
                                 "meshes (touchdown region, sag or hog bend)"}.get(q, kink)
    return why + _touchdown_outlier(q, c, fit)


def worst_mesh(fit: dict) -> float | None:
    """Element length of the fit whose error relative to h^2 stands out (at least twice the
    median of the others), else None."""
    r = sorted((e / (h * h), h) for h, e in zip(fit.get("points", []), fit.get("errors", [])))
    if len(r) < 3:
        return None
    rest = [x for x, _ in r[:-1]]
    return r[-1][1] if r[-1][0] >= 2.0 * rest[len(rest) // 2] else None


def _touchdown_outlier(q: str, c: dict, fit: dict) -> str:
    h = worst_mesh(fit)
    if q in ("tdp_tension", "tdp_x") or h is None or h != c.get("touchdown_worst_mesh"):
        return ""
    return (f"; its largest error relative to h^2 is on the {h:g} m mesh, as the touchdown "
            "tension's: the touchdown's mesh-dependent error (see touchdown tension) "
            "carries into it")


def order_assessment(q: str, fit: dict, context: dict | None = None) -> str:
    """One phrase on a fitted order: expected, or why not. ``context``: numbers of the
    scene quoted in the explanation (theta0, kappa0, coef from
    :func:`liftoff_interpolation`, the seabed ``stiffness`` [N/m2], ``depth`` [m], the number
    of crests and sags ``n_crest_height``, ``n_sag_height``, ``touchdown_worst_mesh``:
    :func:`worst_mesh` of the touchdown tension)."""
    c = context or {}
    p, n = fit.get("order"), len(fit.get("points", []))
    if p is None and fit.get("below_noise") is not None:
        return (f"converged beyond measurement: every element length in the asymptotic "
                f"range errs by at most {fit['below_noise']:.1e}, below {NOISE_MARGIN:g}x "
                f"the noise (relaxation, reference) ({fit['noise_margin']:.1e}); nothing to "
                "fit")
    m = fit.get("n_inside", 0)
    if p is None and m < 2:
        return (f"not fitted: only {m} element length(s) lie within the asymptotic range "
                "(see the local orders)")
    if p is None:
        return (f"not fitted: {n} of the {m} element lengths in the asymptotic range err by "
                f"more than {NOISE_MARGIN:g}x the noise (relaxation, reference); the others "
                "are at it (see the local orders)")
    r2 = fit.get("r2") or 0.0
    on_order = abs(p - EXPECTED_ORDER) <= ORDER_BAND
    pts = set(fit.get("points", []))
    inner = [lp for a, b, lp in fit.get("local", []) if a in pts and b in pts]
    scatter = [lp for lp in inner if abs(lp - EXPECTED_ORDER) > 2.0 * ORDER_BAND]
    why = _why(q, c, fit) + _sign_changes(fit)
    if on_order and n >= 3 and r2 >= 0.9 and not scatter:
        return f"order {EXPECTED_ORDER:g}, as expected"
    if on_order and n >= 3:
        what = []
        if scatter:
            what.append(f"the local orders in the fit scatter ({min(inner):.2f} to "
                        f"{max(inner):.2f})")
        if r2 < 0.9:
            what.append(f"the errors scatter about the fitted line (R^2 {r2:.2f})")
        return (f"order {EXPECTED_ORDER:g} on average, but {' and '.join(what)}"
                + (f": {why}" if why else ""))
    if on_order:
        return (f"order {EXPECTED_ORDER:g}, as expected, but from two points only (no third "
                "to check the slope)")
    few = ", two points only" if n < 3 else ""
    head = f"differs (order {p:.2f}, R^2 {r2:.2f}{few})"
    return f"{head}: {why}" if why else head


def _sign_changes(fit: dict) -> str:
    """Where the signed error of the fitted lengths changes sign (its |value| dips near a
    zero crossing, and the local orders there mean nothing)."""
    pairs = list(zip(fit.get("points", []), fit.get("signed", [])))
    flips = [(a, b) for (a, sa), (b, sb) in zip(pairs, pairs[1:])
             if sa is not None and sb is not None and sa * sb < 0]
    if not flips:
        return ""
    where = ", ".join(f"{a:g}-{b:g} m" for a, b in flips)
    return (f"; the error changes sign ({where}; signed errors "
            f"{', '.join(f'{e:+.1e}' for _, e in pairs)} at "
            f"{', '.join(f'{h:g}' for h, _ in pairs)} m), so its magnitude dips near each "
            "zero crossing")

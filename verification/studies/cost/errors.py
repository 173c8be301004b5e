"""Errors of the cost study's quantities against a reference.

The scalar quantities of a profile are :func:`verification.quantities.raw_values`
(crests and sags matched by arc length: ``crest1_height``, ...); here they are grouped into
the study's quantities (:data:`QUANTITIES`, the crests and sags into one family each) and
turned into relative errors. Tensions and moment are relative to the reference value;
lengths and heights relative to the water depth (else the hang-off height).
"""

from __future__ import annotations

import dataclasses

import numpy as np
from scipy.interpolate import CubicSpline

from riser.results.profile import Profile
from verification.quantities import curve_distance

QUANTITIES = ("hang_off_tension", "tdp_tension", "tdp_x", "max_moment", "crest_height",
              "sag_height", "curve_distance")
QUANTITY_LABEL = {
    "hang_off_tension": "hang-off tension", "tdp_tension": "touchdown tension",
    "tdp_x": "touchdown position", "max_moment": "peak moment",
    "crest_height": "crest height(s)", "sag_height": "sag height(s)",
    "curve_distance": "curve distance (max)"}
#: stations per interval of the reference profile when it is densified for the curve
#: distance (cubic spline in arc length): the chord error of the BVP output spacing d,
#: kappa d^2 / 8 (Wang baseline, d = 0.43 m: 5e-8 of the depth, as large as the VFIFE
#: error at 0.5 m), drops by 8^2
DENSIFY = 8


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
    lo, hi = max(ref.s[0], p.s[0]), min(ref.s[-1], p.s[-1])
    return curve_distance(ref, p, (lo, hi))[0] / depth

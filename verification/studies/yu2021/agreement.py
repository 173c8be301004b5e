"""VFIFE against BVP on the Yu et al. (2021) quantities: the tolerance of each difference,
from the comparison protocol's (verification/comparison/tolerances.py), conditioned where
the quantity is read at an ill-conditioned point.

The study's quantities are not the protocol's rows: a crest is the highest point of the
line within a buoyancy section (a vertex, or a shoulder at the section's end), its
moment the bending moment read there, and the "lower maximum tension" the largest
tension below the top of the uppermost section. Their tolerances:

- tensions: the protocol's tension tolerance (0.1 % of the line's largest tension; the
  hang-off tension its own, 1e-4 of itself); a ratio of two tensions the sum of their
  relative tolerances;
- the peak moment and the hang-off angle: the protocol's;
- a crest's depth: the protocol's crest height (0.02 % of the depth);
- a crest's horizontal position: at a vertex, the feature tolerance angle / curvature
  (:func:`~verification.comparison.tolerances.feature_position_tolerance`: a flat crest's
  position is ill-conditioned); at a shoulder (the section's end), the configuration's;
- a crest's moment: the moment profile's tolerance plus the moment's slope times the
  crest's position tolerance
  (:func:`~verification.comparison.tolerances.feature_moment_tolerance`).

Lengths [m], forces [N], moments [N m], angles [deg]. Every tolerance is a function of the
BVP's solution, never of the VFIFE's.
"""

from __future__ import annotations

import math

import numpy as np

from verification.comparison.tolerances import (TOLERANCES, feature_moment_tolerance,
                                                feature_position_tolerance)

def conditioning(result, scene, buoys: list[int]) -> dict:
    """What the tolerances need from a converged BVP ``result`` of ``scene``: the water
    depth, the line's largest tension and moment, the hang-off tension, and per crest k
    (the k-th buoyancy section of ``buoys``, segment indices from the top, the paper's
    numbering) its curvature [1/m], the moment's slope [N m/m] there and whether it is a
    shoulder (the highest point at the section's end, not a vertex)."""
    p = result.profile
    sm = result.summary()
    out = {"depth": float(scene.water_depth), "T_max": float(np.max(np.abs(p.tension))),
           "M_max": float(np.max(p.moment)), "hang_off_tension": sm["hang_off_tension"]}
    slope = np.gradient(p.moment, p.s)
    edges = np.concatenate([[0.0], np.cumsum([g.length for g in scene.segments])])
    for k, i in enumerate(buoys, start=1):
        sel = np.flatnonzero((p.s >= edges[i] - 1e-6) & (p.s <= edges[i + 1] + 1e-6))
        j = int(sel[np.argmax(p.y[sel])])
        out[k] = {"curvature": float(p.curvature[j]), "slope": float(slope[j]),
                  "shoulder": j in (int(sel[0]), int(sel[-1]))}
    return out


def tolerance(name: str, cond: dict, ratio_parts: tuple | None = None) -> tuple[float, str]:
    """(tolerance, basis in words) of VFIFE - BVP for quantity ``name`` given the BVP's
    :func:`conditioning` ``cond``; ``ratio_parts``: for ``lower_max_tension_ratio`` the
    (value, T_max) of numerator and denominator cases."""
    T = TOLERANCES
    if name == "hang_off_tension":
        return T["hang_off_tension"][1] * abs(cond["hang_off_tension"]), "1e-4 of itself"
    if name == "lower_max_tension":
        return T["tension"][1] * cond["T_max"], "0.1 % of T_max"
    if name == "lower_max_tension_ratio":
        (a, ta), (b, tb) = ratio_parts
        rel = T["tension"][1] * (ta / a + tb / b)
        return rel * a / b, "sum of the two tensions' relative tolerances"
    if name == "max_moment":
        return T["max_moment"][1] * cond["M_max"], "0.2 % of M_max"
    if name == "hang_off_angle_from_vertical":
        return T["hang_off_angle_deg"][1], f"{T['hang_off_angle_deg'][1]:g} deg"
    k = int(name[len("crest")])
    crest = cond.get(k)
    if crest is None:
        return math.nan, "no such crest"
    if name.endswith("_depth"):
        return T["crest_height"][1] * cond["depth"], "0.02 % of depth"
    if name.endswith("_x"):
        if crest["shoulder"]:
            return (T["configuration"][1] * cond["depth"],
                    "configuration (a shoulder at the section end)")
        tol = feature_position_tolerance(crest["curvature"], T["crest_s"][1])
        return tol, f"angle / curvature (kappa {abs(crest['curvature']):.3g} 1/m)"
    if name.endswith("_moment"):
        if crest["shoulder"]:
            return T["moment"][1] * cond["M_max"], "0.5 % of M_max"
        tol = feature_moment_tolerance(cond["M_max"], crest["slope"], crest["curvature"])
        return tol, (f"0.5 % of M_max + |dM/ds| x angle / curvature (kappa "
                     f"{abs(crest['curvature']):.3g} 1/m)")
    return math.nan, "no tolerance"


def within_lines(both) -> list[str]:
    """``both``: the table.csv rows (a DataFrame) both methods gave. The report's statement on VFIFE - BVP against each quantity's tolerance
    (:mod:`.agreement`): how many are within, the nearest to its tolerance, and every one
    outside with its reason."""
    ratio = both.vfife_minus_bvp.abs() / both.tolerance
    i = ratio.idxmax()
    out = [f"- VFIFE - BVP against each quantity's tolerance (the comparison protocol's, "
           f"conditioned on the crest's curvature where a quantity is read at a crest: "
           f"`verification/studies/yu2021/agreement.py`): {int(both.within.sum())} of "
           f"{len(both)} within; the nearest, {both.loc[i, 'study']}/{both.loc[i, 'case']} "
           f"{both.loc[i, 'quantity']}, at {ratio[i]:.2f} of its tolerance."]
    for r in both[~both.within.astype(bool)].itertuples():
        out.append(f"  - outside: {r.study}/{r.case} {r.quantity}, VFIFE - BVP "
                   f"{r.vfife_minus_bvp:.4g} against {r.tolerance:.4g} (no stated cause)")
    return out

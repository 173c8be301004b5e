"""The analytic method as a third column of a comparison (``riser-verify compare``).

Where it applies (one section, no current; analytic/solver.py says what it refuses) the
analytic method solves the same matched scene as the BVP and the VFIFE, and every
agreement row gains ``analytic`` (its value) and ``analytic_rel_diff`` (the signed
(analytic - BVP) / basis, the basis of the row's tolerance). The verdict stays BVP
against VFIFE: the analytic solution is asymptotic, its error a property of the scene
(eps = sqrt(EI / (H L^2)), delta = w lambda / H), not a discretisation that refines away.
Measured on the Kang J-lay case (reports/kang2015/epsilon.csv) the composite's error
against the BVP falls as eps^2 in angle and position and about eps^3 in the peak moment.
"""

from __future__ import annotations

import analytic
from riser.errors import UnsupportedSceneError

from .pipeline import shifted


def third_column(matched, bvp_profile, s_shift: float, depth: float, rows: list[dict],
                 agreement):
    """Solve ``matched`` analytically and add its columns to ``rows`` in place;
    ``agreement`` is :func:`verification.compare.agreement` (passed in: compare calls this).

    Returns (result or None, note): the note says why it does not apply, or what was
    solved."""
    for r in rows:                           # empty unless it applies and converges
        r["analytic"] = r["analytic_rel_diff"] = None
    try:
        res = analytic.solve(matched)
    except UnsupportedSceneError as exc:
        reason = str(exc).split(": ", 1)[-1]
        return None, f"The analytic method does not apply to this scene ({reason})."
    if not res.converged:
        return res, f"The analytic method ended in {res.status.value}: {res.message}."
    arows = {r["quantity"]: r for r in agreement(bvp_profile, shifted(res.profile, s_shift),
                                                 depth, nodal=False)}
    for r in rows:
        a = arows.get(r["quantity"])
        r["analytic"] = a["vfife"] if a is not None else None
        r["analytic_rel_diff"] = a["rel_diff"] if a is not None else None
        r["analytic_diff"] = a["diff"] if a is not None else None
    i = res.info
    return res, (f"The analytic method ({i['analytic_model']}, {res.wall_time_s * 1e3:.2f} ms) "
                 f"solved the same scene: eps = {i['epsilon']:.3g}, delta = {i['delta']:.3g}, "
                 f"boundary layer {i['boundary_layer_length']:.3g} m.")

"""VFIFE against the BVP of the same model on the Table 2 quantities: each difference
against a tolerance of the comparison protocol (verification/comparison/tolerances.py).

Table 2's quantities are points of the protocol's rows, so each takes that row's
tolerance, on the same basis (the BVP's largest tension and moment of the same case, the
reference depth):

- S_L (the suspended length of the riser section) and X (the span from the touchdown to
  the hang-off, fixed in the VFIFE's scene) move with the touchdown: ``tdp_x``;
- Y_arch and Y_sag, the heights of the crest and the sag bend: ``crest_height``,
  ``sag_height``;
- T_TDP: ``tdp_tension``; T_max, the hang-off's tension: ``hang_off_tension``;
- M_max: ``max_moment``; the hang-off angle: ``hang_off_angle_deg``.

F_max, the largest shear force, has no protocol row (the protocol compares no shear). It
lies at the top of the buoyancy section, where the weight jumps from -w to +w and the
shear has a kink; the VFIFE's nodal shear there is extrapolated from each side
(vfife/recovery.py) and converges to the BVP's at second order in the element length
(tests/test_vfife_recovery.py): its difference is shown with that reason, not judged.
"""

from __future__ import annotations

import pandas as pd

from verification.comparison.tolerances import TOLERANCES
from verification.report.markdown import pct

#: Table 2 quantity -> the protocol row whose tolerance it takes
ROWS = {"S_L": "tdp_x", "X": "tdp_x", "Y_arch": "crest_height", "Y_sag": "sag_height",
        "T_TDP": "tdp_tension", "T_max": "hang_off_tension", "M_max": "max_moment",
        "hang_off_angle_deg": "hang_off_angle_deg"}
#: why a quantity is not judged
NOT_JUDGED = {"F_max": "no protocol row (the protocol compares no shear); the largest shear "
                       "lies at the weight jump atop the buoyancy section, where the VFIFE "
                       "recovers it from each side, second order in the element length "
                       "(tests/test_vfife_recovery.py)"}


def judged(mdf: pd.DataFrame, depth: float) -> pd.DataFrame:
    """The matched rows (``vfife_matched.csv``: current, quantity, bvp_matched, vfife) with
    ``diff`` (VFIFE - BVP, in the quantity's unit), ``tolerance`` (absolute, the same
    unit; NaN where not judged) and ``within`` (None where not judged). ``depth`` [m]: the
    reference depth of the protocol's ``of_depth`` tolerances."""
    out = mdf[mdf.quantity.isin(list(ROWS) + list(NOT_JUDGED))].copy()
    base = mdf.set_index(["current", "quantity"]).bvp_matched
    tols, within = [], []
    for r in out.itertuples():
        if r.quantity not in ROWS:
            tols.append(float("nan"))
            within.append(None)
            continue
        kind, value, _ = TOLERANCES[ROWS[r.quantity]]
        scale = {"abs": 1.0, "rel": abs(r.bvp_matched), "of_depth": depth,
                 "of_T_max": abs(base[(r.current, "T_max")]),
                 "of_M_max": abs(base[(r.current, "M_max")])}[kind]
        tols.append(value * scale)
        within.append(bool(abs(r.vfife - r.bvp_matched) <= value * scale))
    out["diff"] = out.vfife - out.bvp_matched
    out["tolerance"] = tols
    out["within"] = within
    return out


def summary_lines(table: pd.DataFrame) -> list[str]:
    """The report's statement on :func:`judged`: how many are within, the nearest to its
    tolerance, every one outside, and the rows not judged with their reason."""
    j = table[table.within.notna()]
    ratio = (j["diff"].abs() / j.tolerance)
    i = ratio.idxmax()
    lines = [f"- VFIFE - BVP against each quantity's tolerance (the comparison protocol's row "
             f"for each Table 2 quantity: `verification/studies/wang2014/agreement.py`): "
             f"{int(j.within.sum())} of {len(j)} within; the nearest, {j.quantity[i]} at "
             f"V0 = {j.current[i]:+g}, at {ratio[i]:.2f} of its tolerance."]
    for r in j[~j.within.astype(bool)].itertuples():
        lines.append(f"  - outside: {r.quantity} at V0 = {r.current:+g}, VFIFE - BVP "
                     f"{r.diff:.4g} against {r.tolerance:.4g} (no stated cause)")
    for name, why in NOT_JUDGED.items():
        sub = table[table.quantity == name]
        if len(sub):
            rel = (sub["diff"] / sub.bvp_matched.abs())
            k = rel.abs().idxmax()
            lines.append(f"  - not judged: {name}, worst {pct(rel[k])} at V0 = "
                         f"{sub.current[k]:+g}: {why}.")
    return lines

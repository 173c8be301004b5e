"""The agreement rows of two static profiles, the metric of every comparison.

The profiles are compared at the same arc length over the range both cover, at the VFIFE
nodes (where VFIFE defines its results), the BVP (stations every sqrt(EI/T)/8, at most
0.5 m) interpolated there; tension is the effective tension and moment the in-plane
bending moment signed with the curvature. A 3D scene (both profiles carry the lateral
offset from the line's plane) compares the moment vector: the row ``moment`` is the
largest magnitude of the difference of its two components across the tangent (in and out
of the plane, riser.model.frame.plane_columns), and adds the rows of the lateral offset (its
largest excursion, at the touchdown, the crests and the sags) and of the out-of-plane
moment (along s and its largest magnitude). Two artefacts of comparing a 1 m VFIFE mesh with
a continuous solution are kept out of the metrics, each measured (issue 11):

- VFIFE values between its nodes are only a linear interpolation: taking them at the BVP
  stations added h^2 |M''| / 8 with M'' ~ w cos(theta) (~65 N m on the Wang pipe; 0.49 %
  of M_max on hard-current-pos2p5, whose M_max is 11 kN m) to the moment metric. At the
  nodes it is 0.24 % there; the choice of interpolant for the BVP (linear, cubic, Akima)
  changes no metric by more than 1e-4 % of M_max.
- A VFIFE element force is constant and belongs to the element midpoint. The VFIFE
  recovers its nodal tension and shear to second order at every node (``vfife.recovery``:
  at a segment joint, where the tension has a kink, each side extrapolates its own
  elements), so the BVP is taken at the same arc length as a point value. (The former
  nodal mean was off by |dw| h / 4 at a weight jump: 0.17-0.20 % of T_max on the Yu
  risers at 1 m, 1.1 % of Yu A4's lower maximum tension; the BVP was then put through the
  same mean.) A peer that reports the mean of its two segments at a node (MoorDyn) asks
  for the BVP through that mean with ``nodal=True``
  (:func:`verification.quantities.nodal_average`).
"""

from __future__ import annotations

import numpy as np

from riser.results.profile import Profile, summarize
from riser.model.sections import segment_properties
from verification.pipeline import shifted
from verification.quantities import (
    curve_distance,
    match_feature,
    nodal_average,
    peak_location_offset,
    signed_moment,
)

from ..row import Row, Tolerance, Verdict
from ..tolerances import reason, scene_scales, tolerance, tolerance_value, unit

#: the columns of every agreement.csv; the further columns of a comparison (the analytic
#: method, a peer) each add ``NAME`` and ``NAME_rel_diff`` after them (.columns)
AGREEMENT_COLUMNS = ("quantity", "bvp", "vfife", "abs_diff", "rel_diff", "tolerance", "pass")


#: the rows of the bending moment: not judged on a line whose bending the elements cannot
#: resolve (see ``moment_reason`` of :func:`agreement`)
MOMENT_ROWS = ("moment", "max_moment", "max_moment_s", "moment_out_of_plane",
               "max_moment_out_of_plane")


def agreement(bvp_prof: Profile, vf_prof: Profile, depth: float,
              s_shift: float = 0.0, nodal: bool = False,
              moment_reason: str | None = None, ends=None, points=(),
              scene=None, names: tuple[str, str] = ("bvp", "vfife")) -> list[Row]:
    """The protocol's rows for two static profiles.

    Each row is a :class:`~..row.Row` with the two methods' values under ``names`` (the
    BVP's first; a further column's rows name their own method second: ``analytic``,
    ``moordyn``), ``diff`` the signed second - first in the row's unit, ``rel_diff`` over
    the basis of the row's tolerance (:func:`verification.comparison.tolerances.tolerance`;
    its label the tolerance's reason), ``at_s`` the arc length of the largest profile
    difference (BVP coordinate); as a mapping it reads as the :data:`AGREEMENT_COLUMNS`
    (``abs_diff`` = |second - first|, ``pass``). ``s_shift`` [m] is subtracted from the
    VFIFE arc lengths. ``nodal``: take the BVP tension through the mean of two segments at
    each node (module docstring; a MoorDyn profile); False (the VFIFE's second-order
    nodal values, the analytic method's) compares point values. ``moment_reason``: why the moment cannot be
    judged on this line (its bending length below the element,
    :func:`unresolved_bending`): the moment rows are then shown, not judged (``pass``
    None, the reason in ``note``). A crest's or sag's position row takes a tolerance
    conditioned on its curvature (the BVP's there; a flat feature's position is
    ill-conditioned, :func:`~..tolerances.feature_position_tolerance`). ``ends``: the
    scene's fixed ends, whose joints, tensioner and free anchor add the rows of what they
    make an output: the moment at a held end (``anchor_moment``, ``hang_off_moment``),
    the tensioned top's height (``hang_off_height``), the free end's position
    (``anchor_x``, ``anchor_height``). ``points``: the arc lengths [m] of point
    attachments (BVP coordinate), where the tension jumps: the tension row leaves their
    nodes out (the BVP's profile holds one side there, the VFIFE's node the mean of the
    two), and compares it at every other node. ``scene``: the scene both solved (the matched
    one); its scales bound the relative tolerances below
    (:func:`~..tolerances.scene_scales`, with the BVP hang-off tension; issue 44:
    round-off never fails a row); None: no floors."""
    rows: list[Row] = []
    first, second = names
    vf = shifted(vf_prof, s_shift)
    sb, sv = summarize(bvp_prof), summarize(vf)
    lo = max(bvp_prof.s[0], vf.s[0])
    hi = min(bvp_prof.s[-1], vf.s[-1])
    Tmax = max(float(np.max(np.abs(bvp_prof.tension))), 1.0)
    Mmax = max(float(np.max(bvp_prof.moment)), 1e-12)
    scales = {"depth": depth, "max_tension": Tmax, "max_moment": Mmax, **(
        scene_scales(scene, sb["hang_off_tension"], depth) if scene is not None else {})}

    def add(name, b, v, diff=None, at_s=None, note="", curvature=None, slope=0.0):
        """A row; ``diff`` is the signed difference (default v - b)."""
        t = tolerance(name, bvp_value=b, curvature=curvature, slope=slope, **scales)
        tol = Tolerance(t["tol"], t["basis"], t["basis_label"], t["label"], reason(name))
        if diff is None and (v is None or b is None):
            d, rel, verdict = None, None, Verdict.FAIL
        else:
            d = float(v - b) if diff is None else float(diff)
            rel = d / t["basis"] if t["basis"] else None
            verdict = Verdict.of(bool(abs(d) <= t["tol"]))
        if moment_reason and name in MOMENT_ROWS:
            verdict, note = Verdict.NOT_JUDGED, moment_reason
        rows.append(Row(name, {first: b, second: v}, unit(name), d, rel, tol, verdict, note,
                        at_s))

    dmax, drms, s_at = curve_distance(bvp_prof, vf, (lo, hi))
    add("configuration", None, None, diff=dmax, at_s=s_at)
    add("configuration_rms", None, None, diff=drms)
    # tension and moment at the VFIFE nodes, where VFIFE defines them (see module notes)
    sel = (vf.s >= lo - 1e-9) & (vf.s <= hi + 1e-9)
    grid = vf.s[sel]
    ref = (nodal_average(vf.s, bvp_prof.s, bvp_prof.tension) if nodal
           else np.interp(vf.s, bvp_prof.s, bvp_prof.tension))
    dT = vf.tension[sel] - ref[sel]
    for sp in points:                   # a jump: compared beside it, not on it
        dT = np.where(np.abs(grid - sp) < 1e-6, 0.0, dT)
    three_d = bvp_prof.is_3d and vf.is_3d
    # the signed in-plane moment (a 3D profile's moment_in_plane)
    dM = signed_moment(vf)[sel] - np.interp(grid, bvp_prof.s, signed_moment(bvp_prof))
    if three_d:
        # the moment vector's two components across the tangent, compared component by
        # component (its magnitude has a kink where it changes sign): the row is the
        # magnitude of the difference vector
        dMo = (vf.moment_out_of_plane[sel]
               - np.interp(grid, bvp_prof.s, bvp_prof.moment_out_of_plane))
        dM = np.hypot(dM, dMo)
    for name, d in (("tension", dT), ("moment", dM)):
        i = int(np.argmax(np.abs(d)))
        add(name, None, None, diff=float(d[i]), at_s=float(grid[i]))
    if three_d:
        i = int(np.argmax(np.abs(dMo)))
        add("moment_out_of_plane", None, None, diff=float(dMo[i]), at_s=float(grid[i]))

    add("hang_off_tension", sb["hang_off_tension"], sv["hang_off_tension"])
    if "hang_off_wall_tension" in sb and "hang_off_wall_tension" in sv:
        add("hang_off_wall_tension", sb["hang_off_wall_tension"], sv["hang_off_wall_tension"])
    add("hang_off_angle_deg", sb["hang_off_angle_deg"], sv["hang_off_angle_deg"])
    for name in end_rows(ends):
        add(name, sb[name], sv[name])
    if "max_utilisation" in sb and "max_utilisation" in sv:       # a scene with [design]
        add("max_utilisation", sb["max_utilisation"], sv["max_utilisation"],
            note=f"{sb['design_code']} at s = {sb['max_utilisation_s']:.1f} m (BVP)")
    if sb["tdp_x"] is not None:
        add("tdp_x", sb["tdp_x"], sv["tdp_x"])
        add("tdp_tension", sb["tdp_tension"], sv["tdp_tension"])
        if three_d and sb["tdp_lateral"] is not None:
            add("tdp_lateral", sb["tdp_lateral"], sv["tdp_lateral"])
    if three_d:
        add("max_lateral_offset", sb["max_lateral_offset"], sv["max_lateral_offset"],
            note=f"at s = {sb['max_lateral_offset_s']:.1f} m (BVP)")
    lateral_slope = (np.gradient(bvp_prof.lateral, bvp_prof.s) if three_d else None)
    for kind in ("crests", "sags"):
        tag = kind[:-1]
        for i, cb in enumerate(sb[kind]):
            cv = match_feature(cb, sv[kind]) or {"height": None, "s": None, "lateral": None}
            kappa = float(np.interp(cb["s"], bvp_prof.s, bvp_prof.curvature))
            add(f"{tag}{i + 1}_height", cb["height"], cv["height"])
            add(f"{tag}{i + 1}_s", cb["s"], cv["s"], curvature=kappa)
            if three_d:
                add(f"{tag}{i + 1}_lateral", cb["lateral"], cv["lateral"], curvature=kappa,
                    slope=float(np.interp(cb["s"], bvp_prof.s, lateral_slope)))
        if len(sv[kind]) != len(sb[kind]):
            n_b, n_v = len(sb[kind]), len(sv[kind])
            rows.append(Row(f"{kind}_count", {first: n_b, second: n_v}, "-", n_v - n_b, None,
                            Tolerance(0, None, "", "equal"), Verdict.FAIL))
    add("max_moment", sb["max_moment"], sv["max_moment"])
    if three_d:
        add("max_moment_out_of_plane", sb["max_moment_out_of_plane"],
            sv["max_moment_out_of_plane"])
    tol_peak, _ = tolerance_value("max_moment", bvp_value=sb["max_moment"], **scales)
    off = peak_location_offset(bvp_prof, vf, tol_peak)
    tie = abs(off - (sv["max_moment_s"] - sb["max_moment_s"])) > 1e-6
    add("max_moment_s", sb["max_moment_s"], sv["max_moment_s"], diff=off,
        note="between the nearest peaks within the max_moment tolerance of the maximum "
             "(a tie)" if tie else "")
    return rows


def end_rows(ends) -> list[str]:
    """The rows the end conditions of ``ends`` (a FixedEnds, or None) add (see
    :func:`agreement`)."""
    out = []
    joint = getattr(ends, "joint", None)
    if joint is None:
        return out
    if ends.free_anchor:
        out += ["anchor_x", "anchor_height"]
    elif joint("anchor") is not None:
        out.append("anchor_moment")
    if joint("hang_off") is not None:
        out.append("hang_off_moment")
    if ends.tensioner is not None:
        out.append("hang_off_height")
    return out


def unresolved_bending(scene, bvp_prof: Profile, element_length: float,
                       s_shift: float = 0.0) -> str | None:
    """Why the VFIFE's elements of ``element_length`` [m] cannot resolve the bending of
    the line ``scene`` (a chain, a rope, a slack cable), or None when they can.

    The bending length at a station is the shorter of the tension layer sqrt(EI/|T|) and
    the weight layer (EI/|w|)^(1/3) [m], over which the moment rises and falls; the line's
    longest, at its most resolvable station, is compared with the element: when even that
    is shorter than one element, no moment the VFIFE reports resolves the beam's, and a
    difference in the moment rows is the mesh, not a defect (measured: hard-flexible,
    EI 1e3 N m2, bending lengths 0.07-0.3 m on 1 m elements). ``bvp_prof`` in the arc
    length of ``scene``; ``s_shift`` [m] is subtracted from the s the reason quotes."""
    props = segment_properties(scene)
    ends = np.array([p.s_end for p in props])
    idx = np.clip(np.searchsorted(ends, bvp_prof.s, side="left"), 0, len(props) - 1)
    EI = np.array([p.EI for p in props])[idx]
    w = np.abs(np.array([p.weight for p in props]))[idx]
    T = np.maximum(np.abs(bvp_prof.tension), 1e-300)
    layer = np.minimum(np.sqrt(EI / T), np.cbrt(EI / np.maximum(w, 1e-300)))
    j = int(np.argmax(layer))
    if layer[j] >= element_length:
        return None
    return (f"not judged: the line's longest bending length, min(sqrt(EI/T), (EI/w)^(1/3)) "
            f"= {layer[j]:.3g} m at s = {bvp_prof.s[j] - s_shift:.1f} m, is shorter than the "
            f"{element_length:g} m element: the elements cannot resolve its moment (a chain, "
            "rope or slack cable; or elements too long for this line)")

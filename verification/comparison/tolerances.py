"""Agreement tolerances of the static VFIFE-vs-BVP comparison protocol: the one place they
live. One table per protocol, each in one module, each tolerance with its reason: the
dynamic protocol's in :data:`verification.comparison.dynamic.rows.TOLERANCES`, the
irregular sea's in :data:`verification.comparison.sea.protocol.TOLERANCE`, the MoorDyn
column's in :data:`verification.peers.moordyn.column.TOLERANCES`.

Both methods solve the same continuum model (extensible line on a unilateral Winkler
seabed of the scene's stiffness; see :mod:`verification.comparison.static.protocol`), so a tolerance only
has to cover the discretisation of each method, not a model difference. Each entry is
(kind, value, reason: the comment above it in one line, carried by each row's
:class:`~verification.comparison.row.Tolerance`):

- ``of_depth``: a fraction of the water depth (the hang-off height when the scene gives
  no depth);
- ``of_T_max`` / ``of_M_max``: a fraction of the largest BVP effective tension / bending
  moment along the line;
- ``rel``: a fraction of the BVP value of the quantity itself;
- ``abs``: absolute, in the quantity's unit (m or deg);
- ``feature_s``: the arc length of a crest or sag: the angle agreement over the feature's
  curvature, at least the value given (:func:`feature_position_tolerance`);
- ``feature_lateral``: the lateral offset at a crest or sag (3D): a fraction of the depth
  plus the lateral slope times the feature's position tolerance.

The relative difference of a row (``rel_diff`` of ``agreement.csv``) is the signed
(VFIFE - BVP) / basis with the same basis as its tolerance; absolute lengths are
normalised by the depth, absolute angles have no relative form.

TARGETS AND MEASUREMENT
-----------------------
The issue's targets at the default element length are upper bounds: configuration 0.02 %
of depth, tension 0.1 % of T_max, moment profile 0.5 % of M_max, touchdown x 0.5 m; no
value below is looser. The profile rows are the targets themselves; every scalar row is
the measured worst value times a stated margin (about 2-3: VFIFE stops its static
relaxation at a residual of 1e-3 of an element weight, so its results move by a fraction
of the measured difference from one build or mesh to the next), and never looser than
the profile target it is a point of. MEASURED (issue 11, ``/tmp/measure_compare.py``):
the 11 planar built-in scenes and the hard scenes that both methods solve (statics only,
[dynamics] dropped), at the default element length, 1 m; hard-coarse-elements (20 m),
hard-large-heave (2 m) and hard-long-dynamic (5 m) at 1 m (the same line as the Wang
baseline), hard-flexible's moment rows left out (EI = 1e3 N m2: the moment boundary
layers, sqrt(EI/T) ~ 0.07 m, are far below any practical element; a stability case).
Worst value of each row and its scene are quoted below. The profile metrics are taken
at the VFIFE nodes, the BVP interpolated there (issue 11 put the BVP tension through the
VFIFE's former nodal mean of two elements; since issue 29 the VFIFE recovers its nodal
tension to second order at the joints, ``vfife.recovery``, and both are point values;
see :mod:`verification.comparison.static.agreement`). Reasons: VFIFE positions and tension converge at least
as fast as the second order in the element length (Yu A1: configuration 0.0135 % ->
0.0022 % of depth from 1 m to 0.5 m); its moment, from element end rotations, carries a
first-order error at the sharpest moment peak, the seabed lift-off (foundation length
(4 EI/k)^(1/4) = 4.4 m on the Wang pipe, ~4 elements).
"""

from __future__ import annotations

import math
import re

TOLERANCES = {
    # Configuration: largest point-to-curve distance between the two lines. The target,
    # 0.02 % of depth. Measured worst 0.0135 % (Yu A1, 0.068 m of 500 m; 0.0022 % at
    # 0.5 m elements), Wang forms 0.0009-0.0016 %. A 5 % buoyancy change: 56x this.
    "configuration": ("of_depth", 2.0e-4,
                      "the target; measured worst 0.0135 % (Yu A1), a 5 % buoyancy change "
                      "56x this"),
    # rms of the same distance over the compared range: half the target. Measured worst
    # 0.0068 % (Yu A1).
    "configuration_rms": ("of_depth", 1.0e-4,
                          "half the target; measured worst 0.0068 % (Yu A1)"),
    # Effective tension at the VFIFE nodes. The target, 0.1 % of T_max. Measured worst
    # 0.018 % (Yu A1); 0.004 % on the Wang baseline.
    "tension": ("of_T_max", 1.0e-3,
                "the target; measured worst 0.018 % (Yu A1)"),
    # Signed in-plane bending moment at the VFIFE nodes. The target, 0.5 % of M_max.
    # Measured worst 0.45 % (hard-slack-touchdown, at the lift-off), 0.43 % hard-many-buoys,
    # 0.37 % Wang baseline: the first-order moment error of 1 m elements at the lift-off;
    # the margin is thin (a scene that needs more gets a shorter [vfife] element_length,
    # never a looser tolerance).
    "moment": ("of_M_max", 5.0e-3,
               "the target; measured worst 0.45 % (hard-slack-touchdown, the first-order "
               "moment error of 1 m elements at the lift-off)"),
    # Scalars. Hang-off tension, relative to itself: measured worst 2.8e-5 (Yu A2
    # sheared); x3.5 -> 1e-4.
    "hang_off_tension": ("rel", 1.0e-4,
                         "measured worst 2.8e-5 (Yu A2 sheared) x 3.5"),
    # with [internal_flow]: the wall tension is the effective tension plus terms both
    # methods evaluate alike (mu U^2, pressures at the hang-off height): the hang-off
    # tension's tolerance (measured 4.9e-5 on liu2021-scr with steady flow at 4 m elements)
    "hang_off_wall_tension": ("rel", 1.0e-4,
                              "the hang-off tension's (both add the same terms); measured "
                              "4.9e-5 (liu2021-scr, steady flow)"),
    # with [design]: the largest code-check utilisation, the same post-processing of each
    # method's tension and moment (riser/design). It is at most linear in the moment
    # (DNV: gamma M_d / M_k plus terms in T^2 and the pressures; API: the bending stress
    # in von Mises), so max_moment's 0.2 % carries over, relative to itself. Measured
    # (compare at the default mesh) 1.4e-5 on scr-steel-design, 6.8e-5 on
    # wang2014-lazy-wave-design.
    "max_utilisation": ("rel", 2.0e-3,
                        "max_moment's, carried over (at most linear in the moment); "
                        "measured 6.8e-5"),
    # ---- end conditions (issue 35): outputs of a held or free end. The moment at a
    # clamped or flex-jointed end is a point of the moment profile: its target. The
    # height of a tensioned top and the position of a free end are points of the
    # configuration: the crests' target. Measured: see docs/end-conditions.md.
    "anchor_moment": ("of_M_max", 5.0e-3,
                      "a point of the moment profile: its target"),
    "hang_off_moment": ("of_M_max", 5.0e-3,
                        "a point of the moment profile: its target"),
    "hang_off_height": ("of_depth", 2.0e-4,
                        "a point of the configuration: the crests' target"),
    "anchor_x": ("of_depth", 2.0e-4,
                 "a point of the configuration: the crests' target"),
    "anchor_height": ("of_depth", 2.0e-4,
                      "a point of the configuration: the crests' target"),
    # deg: measured worst 0.016 deg (Yu A1; 0.0008 deg at 0.5 m), 0.008 deg Yu A3, Wang
    # forms <= 0.0016 deg; x1.9 -> 0.03 deg (half the drag: 66x this).
    "hang_off_angle_deg": ("abs", 0.03,
                           "measured worst 0.016 deg (Yu A1) x 1.9; half the drag is 66x "
                           "this"),
    # m: measured worst 0.109 m (hard-slack-touchdown), 0.095 m hard-many-buoys, 0.025 m
    # Wang baseline (lift-off interpolated between 1 m nodes); x2.3 -> 0.25 m, inside the
    # 0.5 m target.
    "tdp_x": ("abs", 0.25,
              "measured worst 0.109 m (hard-slack-touchdown) x 2.3, inside the 0.5 m target"),
    # touchdown (lift-off) tension: measured worst 8.1e-5 of T_max (hard-many-buoys);
    # x2.5 -> 2e-4 of T_max.
    "tdp_tension": ("of_T_max", 2.0e-4,
                    "measured worst 8.1e-5 of T_max (hard-many-buoys) x 2.5"),
    # heights of crests and sag bends: points of the configuration, its target. Measured
    # worst 9.6e-5 of depth (Yu A1 crest), sags 7.6e-5 (Yu A3): margin x2.1.
    "crest_height": ("of_depth", 2.0e-4,
                     "a point of the configuration; measured worst 9.6e-5 of depth (Yu A1) "
                     "x 2.1"),
    "sag_height": ("of_depth", 2.0e-4,
                   "a point of the configuration; measured worst 7.6e-5 of depth (Yu A3) x "
                   "2.1"),
    # m; arc length of a crest/sag (parabolic vertex of the height): measured worst
    # 0.009 m (crests) and 0.015 m (sags, hard-slack-touchdown); x3.3 -> 0.05 m, the
    # floor of a tolerance conditioned on the feature's flatness (feature_s below: a
    # vertex sits where the angle crosses zero, so an angle difference moves it by the
    # angle over the curvature there; a flat crest's position is ill-conditioned)
    "crest_s": ("feature_s", 0.05,
                "measured worst 0.015 m x 3.3, the floor of the angle agreement over the "
                "feature's curvature"),
    "sag_s": ("feature_s", 0.05,
              "measured worst 0.015 m x 3.3, the floor of the angle agreement over the "
              "feature's curvature"),
    # the largest moment: measured worst 0.095 % of M_max (Yu A1); x2.1 -> 0.2 %.
    "max_moment": ("of_M_max", 2.0e-3,
                   "measured worst 0.095 % of M_max (Yu A1) x 2.1"),
    # m; location of the largest moment (parabolic vertex; peaks within the max_moment
    # tolerance of the maximum count as ties, see compare.peak_location_distance).
    # Measured worst 0.080 m (scr-steel); x2.5 -> 0.2 m.
    "max_moment_s": ("abs", 0.2,
                     "measured worst 0.080 m (scr-steel) x 2.5; peaks within max_moment's "
                     "tolerance are ties"),
    # ---- 3D rows (a profile with a lateral offset from the line's plane, issue 32): the
    # planar targets carried over, each a point or a component of a planar row. MEASURED
    # (issue 32) on the 7 3D built-in scenes and the 14 3D headings of `reproduce
    # cross_current`, 1 m elements; the planar rows there: moment 0.57 of its tolerance
    # (scr-steel-current-45), configuration 0.36 (yu2021-a3-current-90).
    # The bending moment vector's out-of-plane component along s: the moment profile's
    # target. Measured worst 0.0076 % of M_max (yu2021-a3 at 112.5 deg).
    "moment_out_of_plane": ("of_M_max", 5.0e-3,
                            "the moment profile's target; measured worst 0.0076 % of M_max"),
    # its largest magnitude: max_moment's tolerance. Measured worst 0.0070 % of M_max.
    "max_moment_out_of_plane": ("of_M_max", 2.0e-3,
                                "max_moment's; measured worst 0.0070 % of M_max"),
    # the largest lateral excursion from the line's plane: a point of the configuration,
    # its target. Measured worst 0.0030 % of depth (0.015 m of 129 m, yu2021-a3-current-90).
    "max_lateral_offset": ("of_depth", 2.0e-4,
                           "a point of the configuration; measured worst 0.0030 % of depth"),
    # m; the touchdown's lateral offset: the touchdown position's tolerance (tdp_x).
    # Measured worst 0.028 m (yu2021-a3-current-90).
    "tdp_lateral": ("abs", 0.25,
                    "the touchdown position's (tdp_x); measured worst 0.028 m"),
    # the lateral offset at a crest or sag: a point of the configuration (its target)
    # plus the lateral slope times the feature's position tolerance (feature_s: a flat
    # crest's position is ill-conditioned, and so is what is read there). Measured worst
    # 0.0033 % of depth (0.017 m, a crest of yu2021-a3-current-90).
    "crest_lateral": ("feature_lateral", 2.0e-4,
                      "a point of the configuration plus the slope times the position "
                      "tolerance; measured worst 0.0033 % of depth"),
    "sag_lateral": ("feature_lateral", 2.0e-4,
                    "a point of the configuration plus the slope times the position "
                    "tolerance; measured worst 0.0033 % of depth"),
}

#: the angle [deg] to which the two methods' lines agree along the line: the hang-off
#: angle's tolerance (measured worst 0.016 deg there); it conditions the position
#: tolerance of a feature (a crest, a sag: :func:`feature_position_tolerance`)
FEATURE_ANGLE_DEG = TOLERANCES["hang_off_angle_deg"][1]

#: unit of each quantity (the name with its digits removed: crest2_height -> crest_height)
UNITS = {
    "configuration": "m", "configuration_rms": "m", "tension": "N", "moment": "N m",
    "hang_off_tension": "N", "hang_off_wall_tension": "N", "max_utilisation": "-",
    "hang_off_angle_deg": "deg", "anchor_moment": "N m", "hang_off_moment": "N m",
    "hang_off_height": "m", "anchor_x": "m", "anchor_height": "m",
    "tdp_x": "m", "tdp_tension": "N",
    "crest_height": "m", "sag_height": "m", "crest_s": "m", "sag_s": "m",
    "max_moment": "N m", "max_moment_s": "m", "crests_count": "-", "sags_count": "-",
    "moment_out_of_plane": "N m", "max_moment_out_of_plane": "N m",
    "max_lateral_offset": "m", "tdp_lateral": "m", "crest_lateral": "m", "sag_lateral": "m",
}

_BASIS_LABEL = {"of_depth": "depth", "of_T_max": "T_max", "of_M_max": "M_max",
                "rel": "itself"}

# FLOORS (issue 44): a relative tolerance's basis is never below the scene's own scale of
# the quantity, so that round-off cannot cross it: a vertical TTR without current has
# moments of 1e-7 N m (BVP) and 4e-10 N m (VFIFE), which "M_max" alone judged -99.6 %.
# - moment scale w lambda^2 [N m]: w the largest submerged weight per length of the
#   line's segments [N/m], lambda [m] its bending length, the shorter of the tension
#   layer sqrt(EI/T) (T the BVP hang-off tension, the line's representative tension)
#   and the weight layer (EI/w)^(1/3) (the same layers as agreement.unresolved_bending);
#   the moment that a weight w puts on one bending length. A bent line's M_max exceeds
#   it (at a touchdown M = EI w / T_h, T_h < T), so the floor bites only where there is
#   no bending to speak of. On ttr-steel (w = 585 N/m, EI = 2.6e7 N m2, T = 1.6 MN):
#   lambda = 4.0 m, w lambda^2 = 9.4 kN m; the moment tolerance 47 N m.
# - tension scale w_net depth [N]: w_net the line's net submerged weight over its length
#   (buoyancy modules count against it): the weight of a line one depth long, the tension
#   a suspended line carries; floors T_max and a tension row taken relative to itself (a
#   tension near zero has no relative difference). The net, not the largest, weight: with
#   the largest, a lazy wave's floor exceeded its T_max (yu2021-a1: 2.4x the measured
#   tolerance), and a floor must not loosen a row whose own basis is sound.
# - length scale: the depth (already the basis of the length rows).
#: the row kinds whose basis each floor bounds below, by the row's unit
_FLOORED = {("of_M_max", "N m"): "moment", ("of_T_max", "N"): "tension",
            ("rel", "N"): "tension"}
_FLOOR_LABEL = {"moment": "w lambda^2", "tension": "w_net depth"}


def scene_scales(scene, hang_off_tension: float, depth: float) -> dict:
    """The floors of the relative tolerances of a static comparison of ``scene``:
    ``{"moment_floor": w lambda^2 [N m], "tension_floor": w_net depth [N]}`` (module notes,
    FLOORS) with ``hang_off_tension`` [N] the BVP's, ``depth`` [m] the comparison's."""
    from riser.model.sections import segment_properties
    props = segment_properties(scene)
    w = max(abs(p.weight) for p in props)
    EI = max(p.EI for p in props)
    if not (w > 0.0 and EI > 0.0):
        return {"moment_floor": 0.0, "tension_floor": 0.0}
    T = abs(hang_off_tension)
    lam = (EI / w) ** (1.0 / 3.0)
    if T > 0.0:
        lam = min(lam, math.sqrt(EI / T))
    w_net = abs(sum(p.weight * p.length for p in props)) / sum(p.length for p in props)
    return {"moment_floor": w * lam * lam, "tension_floor": w_net * depth}


def base_name(name: str) -> str:
    """The tolerance key of a row: digits removed (crest2_height -> crest_height)."""
    return re.sub(r"\d+", "", name)


def unit(name: str) -> str:
    return UNITS.get(base_name(name), "")


def feature_position_tolerance(curvature: float | None, floor: float) -> float:
    """The tolerance [m] on the arc length of a crest or sag of curvature ``curvature``
    [1/m] there (the BVP's): a vertex of the height y(s) sits where the tangent angle
    crosses zero, so an angle difference d_theta between the two lines moves it by
    d_theta / kappa. With d_theta the lines' angle agreement (:data:`FEATURE_ANGLE_DEG`):
    max(``floor``, d_theta / |kappa|); a flat crest (kappa -> 0) has an ill-conditioned
    position, and its tolerance grows accordingly."""
    if curvature is None or not abs(curvature) > 0.0:
        return float("inf")
    return max(floor, math.radians(FEATURE_ANGLE_DEG) / abs(curvature))


def feature_moment_tolerance(max_moment: float, moment_slope: float,
                             curvature: float | None) -> float:
    """The tolerance [N m] on the bending moment read at a crest or sag: the moment
    profile's (0.5 % of M_max) plus the moment's change over the feature's position
    tolerance, |dM/ds| x :func:`feature_position_tolerance` (a flat crest's moment is read
    at an ill-conditioned point)."""
    ds = feature_position_tolerance(curvature, TOLERANCES["crest_s"][1])
    return TOLERANCES["moment"][1] * max_moment + abs(moment_slope) * ds


def tolerance(name: str, *, bvp_value: float | None = 0.0, depth: float = 1.0,
              max_tension: float = 1.0, max_moment: float = 1.0,
              curvature: float | None = None, slope: float = 0.0,
              moment_floor: float = 0.0, tension_floor: float = 0.0) -> dict:
    """Tolerance of row ``name`` for a scene with these scales (``curvature`` [1/m]: the
    BVP's at a feature, for its position row; ``slope`` [-]: the BVP's d(lateral)/ds there,
    for its lateral row).

    Returns ``{"tol": absolute tolerance in the unit of the quantity, "label": e.g.
    '0.5 % of M_max', "basis": the value that normalises the relative difference (None
    when there is none), "basis_label": e.g. 'M_max'}``; :func:`reason` says why."""
    kind, value, _ = TOLERANCES[base_name(name)]
    u = unit(name)
    if kind == "feature_s":
        tol = feature_position_tolerance(curvature, value)
        label = (f"{value:g} {u}" if tol == value else
                 f"{FEATURE_ANGLE_DEG:g} deg / kappa = {tol:.3g} {u} (kappa "
                 f"{abs(curvature):.3g} 1/m)")
        return {"tol": tol, "label": label, "basis": None, "basis_label": ""}
    if kind == "feature_lateral":
        ds = feature_position_tolerance(curvature, TOLERANCES["crest_s"][1])
        tol = value * depth + abs(slope) * ds
        return {"tol": tol, "label": f"{100 * value:g} % of depth + |d lateral/ds| x "
                f"{ds:.3g} m = {tol:.3g} {u}", "basis": depth, "basis_label": "depth"}
    if kind == "abs":
        # an absolute tolerance has no basis: the row's difference stays in its unit, the
        # same normalisation as its tolerance (no relative difference is reported)
        return {"tol": value, "label": f"{value:g} {u}", "basis": None, "basis_label": ""}
    basis = {"of_depth": depth, "of_T_max": max_tension, "of_M_max": max_moment,
             "rel": abs(bvp_value or 0.0)}[kind]
    label = _BASIS_LABEL[kind]
    floor_kind = _FLOORED.get((kind, u))
    floor = {"moment": moment_floor, "tension": tension_floor}.get(floor_kind, 0.0)
    if floor > basis:                   # the scene's scale: round-off cannot cross it
        basis, label = floor, f"{_FLOOR_LABEL[floor_kind]} = {floor:.3g} {u} (floor)"
    return {"tol": value * basis, "label": f"{100 * value:g} % of {label}",
            "basis": basis if basis else None,
            "basis_label": _FLOOR_LABEL[floor_kind] if label.endswith("(floor)")
            else label}


def reason(name: str) -> str:
    """Why row ``name``'s tolerance is what it is (the table's third field)."""
    return TOLERANCES[base_name(name)][2]


def tolerance_value(name: str, *, bvp_value: float = 0.0, depth: float = 1.0,
                    max_tension: float = 1.0, max_moment: float = 1.0,
                    curvature: float | None = None, **floors) -> tuple[float, str]:
    """(absolute tolerance, description) for quantity ``name`` (see :func:`tolerance`)."""
    t = tolerance(name, bvp_value=bvp_value, depth=depth, max_tension=max_tension,
                  max_moment=max_moment, curvature=curvature, **floors)
    return t["tol"], t["label"]

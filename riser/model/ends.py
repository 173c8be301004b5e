"""The boundary conditions of a scene (table ``[ends]``): one of four forms, each a small
frozen class. Test the form with ``isinstance`` (``isinstance(scene.ends, FixedEnds)``);
``kind`` is the form's name in messages and summary.json ('tdp_tension',
'hang_off_angle', 'top_tension', 'fixed').

The forms other than :class:`FixedEnds` are the Wang family: the touchdown at the origin
on a rigid seabed, inextensible by default (``Scene.axial_model``, ``Scene.seabed_model``).
Coordinates [m]: x from the anchor/touchdown towards the hang-off, y up from the seabed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

from ..spec import MAX_COORDINATE, Part, Spec, check_fields, part_error, spec

#: the largest tension [N]
MAX_TENSION = 1.0e9


class Ends(Part):
    """Base of the end forms (not built itself): :class:`TdpTensionEnds`,
    :class:`HangOffAngleEnds`, :class:`TopTensionEnds`, :class:`FixedEnds`."""

    kind: ClassVar[str] = ""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        raise TypeError("Ends is the base of the end forms: build TdpTensionEnds, "
                        "HangOffAngleEnds, TopTensionEnds or FixedEnds")


def _height(doc: str):
    return spec(gt=0.0, le=MAX_COORDINATE, unit="m", also="<= water_depth", doc=doc)


@dataclass(frozen=True)
class TdpTensionEnds(Ends):
    """Touchdown at the origin with tension ``tdp_tension`` [N]; the top is free (the
    hang-off point is an output)."""

    kind: ClassVar[str] = "tdp_tension"
    tdp_tension: float = spec(gt=0.0, le=MAX_TENSION, unit="N",
                              doc="effective tension at the touchdown point")


@dataclass(frozen=True)
class HangOffAngleEnds(Ends):
    """Hang-off height [m] and angle from the horizontal [deg] given (the file may give
    the angle from the vertical, :data:`FILE_KEYS`); the first segment's suspended length
    is solved (its length in the file is ``segments[0].length``)."""

    kind: ClassVar[str] = "hang_off_angle"
    hang_off_height: float = _height("height of the hang-off above the seabed")
    hang_off_angle_deg: float = spec(gt=0.0, le=90.0, unit="deg",
                                     key="hang_off_angle_from_horizontal_deg",
                                     doc="hang-off angle from the horizontal (or give "
                                         "hang_off_angle_from_vertical_deg)")


@dataclass(frozen=True)
class TopTensionEnds(Ends):
    """The J-lay form: touchdown at the origin on a rigid seabed (theta = 0, M = 0 there);
    hang-off height [m] and effective tension ``top_tension`` [N] given, M = 0 at the
    hang-off. The first segment's suspended length is solved (its length in the file,
    ``segments[0].length``, is the pipe available: the suspended part plus what lies on
    the seabed); the hang-off x, the angle and the TDP tension are outputs."""

    kind: ClassVar[str] = "top_tension"
    hang_off_height: float = _height("height of the hang-off above the seabed "
                                     "(with top_tension)")
    top_tension: float = spec(gt=0.0, le=MAX_TENSION, unit="N",
                              doc="effective tension at the hang-off (J-lay)")


#: the kinds of an end joint (``free``: the anchor end only)
JOINT_KINDS = ("pinned", "clamped", "spring", "free")
#: the largest rotational stiffness of an end joint [N m/rad]
MAX_ROTATIONAL_STIFFNESS = 1.0e12


@dataclass(frozen=True)
class EndJoint(Part):
    """How an end of a fixed-ends line holds its rotation (tables ``[ends.anchor_joint]``
    and ``[ends.hang_off_joint]``; an end without one is pinned).

    ``kind``: ``pinned`` (moment-free), ``clamped`` (the line's tangent at the end points
    along ``direction_deg``), ``spring`` (a flex joint: the end moment is
    -rotational_stiffness x (the end's rotation from ``direction_deg``), linear), or
    ``free`` (the anchor end only: no force and no moment, the line hangs from the
    hang-off; the anchor position is then not given). ``direction_deg`` is the neutral
    direction of the line's tangent at the end, from +x towards +y in the line's plane,
    pointing along increasing s (from the anchor towards the hang-off): 90 is vertical
    upwards, a catenary's hang-off has 60-89.

    Sign of the spring: with theta the tangent's angle [rad] and M = EI dtheta/ds the
    bending moment, the hang-off gives M(L) = -k (theta(L) - theta_0) and the anchor
    M(0) = +k (theta(0) - theta_0): the joint's moment opposes the end's rotation.
    """

    kind: str = spec("pinned", "string", choices=JOINT_KINDS,
                     doc="pinned, clamped, spring (flex joint) or free (anchor only)")
    direction_deg: float | None = spec(None, gt=-180.0, le=180.0, unit="deg",
                                       also="required by clamped and spring",
                                       doc="neutral direction of the tangent, from +x "
                                           "towards +y (90: vertical up)")
    rotational_stiffness: float | None = spec(None, gt=0.0, le=MAX_ROTATIONAL_STIFFNESS,
                                              unit="N m/rad", also="required by spring",
                                              doc="flex joint stiffness (linear)")

    def __post_init__(self) -> None:
        check_fields(self)
        error = part_error(self)
        needs_direction = self.kind in ("clamped", "spring")
        if needs_direction and self.direction_deg is None:
            raise error("direction_deg", f"required by kind = '{self.kind}' (the neutral "
                        "direction of the tangent, deg from +x towards +y)")
        if not needs_direction and self.direction_deg is not None:
            raise error("direction_deg", f"only with kind = 'clamped' or 'spring', not "
                        f"'{self.kind}'")
        if self.kind == "spring" and self.rotational_stiffness is None:
            raise error("rotational_stiffness", "required by kind = 'spring' (> 0 N m/rad)")
        if self.kind != "spring" and self.rotational_stiffness is not None:
            raise error("rotational_stiffness", "only with kind = 'spring', not "
                        f"'{self.kind}'")

    @property
    def direction(self) -> float:
        """The neutral direction [rad] (clamped and spring joints)."""
        return math.radians(self.direction_deg)

    @property
    def holds_rotation(self) -> bool:
        """A clamped or spring joint (a moment at the end)."""
        return self.kind in ("clamped", "spring")


@dataclass(frozen=True)
class Tensioner(Part):
    """The hang-off of a top-tensioned riser (table ``[ends.tensioner]``): the top end is
    held in x and z at the hang-off and free to slide vertically, pulled up by the
    tensioner with the vertical force F = top_tension - stiffness (y_top - y_hang_off) [N]
    (the vertical component of the effective tension at the top end; with stiffness 0 a
    constant-tension tensioner). The top's height is an output (its stroke y_top -
    y_hang_off is reported); in dynamics the vessel's heave moves the tensioner's
    reference height, surge and sway the top."""

    top_tension: float = spec(gt=0.0, le=MAX_TENSION, unit="N",
                              doc="vertical force of the tensioner at the hang-off height")
    stiffness: float = spec(0.0, ge=0.0, le=1.0e10, unit="N/m",
                            doc="tensioner stiffness (0: constant tension)")

    def force(self, stroke: float) -> float:
        """The tensioner's upward force [N] with the top ``stroke`` [m] above the
        hang-off height."""
        return self.top_tension - self.stiffness * stroke


@dataclass(frozen=True)
class FixedEnds(Ends):
    """Anchor and hang-off positions [m] given: (x, y) in the x-y plane, or (x, y, z) for
    a line whose hang-off is out of the anchor's plane (z out of plane; two entries mean
    z = 0). The line's plane is the vertical plane through the two ends
    (:attr:`plane_heading_deg`)."""

    kind: ClassVar[str] = "fixed"
    anchor: tuple[float, ...] = spec(kind="numbers", length=(2, 3), ge=-MAX_COORDINATE,
                                     le=MAX_COORDINATE, unit="m",
                                     also="y >= 0, <= water_depth; with a "
                                          "[seabed], a y within 5 % of the bottom line's "
                                          "outer diameter is put on it (y = 0)",
                                     doc="(x, y) or (x, y, z) of the bottom end")
    hang_off: tuple[float, ...] = spec(kind="numbers", length=(2, 3), ge=-MAX_COORDINATE,
                                       le=MAX_COORDINATE, unit="m",
                                       also="x >= anchor x (= only for a vertical "
                                            "chord), 0 < y <= water_depth",
                                       doc="(x, y) or (x, y, z) of the top end")
    anchor_joint: EndJoint | None = spec(None, "part", part=EndJoint,
                                         doc="the anchor's rotation (default pinned)")
    hang_off_joint: EndJoint | None = spec(None, "part", part=EndJoint,
                                           doc="the hang-off's rotation (default pinned)")
    tensioner: Tensioner | None = spec(None, "part", part=Tensioner,
                                       doc="a top tensioner instead of a fixed hang-off "
                                           "height")

    def __post_init__(self) -> None:
        check_fields(self)
        error = part_error(self)
        (xa, ya, _), (xh, yh, _) = self.anchor_point, self.hang_off_point
        if ya < 0.0:
            raise error("anchor[1]", f"must be >= 0 (the seabed is y = 0), got {ya:g}")
        if yh <= 0.0:
            raise error("hang_off[1]", "must be > 0 (the hang-off cannot be at or below the "
                        f"seabed y = 0), got {yh:g}")
        if xh < xa or (xh == xa and yh <= ya):
            raise error("hang_off[0]", f"must be >= anchor[0] = {xa:g} (x points from the "
                        "anchor towards the hang-off; equal only with the hang-off above "
                        f"the anchor), got {xh:g}")
        if self.hang_off_joint is not None and self.hang_off_joint.kind == "free":
            raise error("hang_off_joint.kind", "'free' is for the anchor end only (the "
                        "line hangs from its hang-off)")

    @property
    def free_anchor(self) -> bool:
        """The anchor end is free (no force, no moment): a hanging line."""
        return self.anchor_joint is not None and self.anchor_joint.kind == "free"

    @property
    def plain(self) -> bool:
        """Both ends pinned at their positions (no joint, no tensioner)."""
        return all(j is None or j.kind == "pinned"
                   for j in (self.anchor_joint, self.hang_off_joint)) and self.tensioner is None

    def joint(self, end: str) -> EndJoint | None:
        """The joint of ``end`` ('anchor' or 'hang_off'), None when pinned."""
        j = self.anchor_joint if end == "anchor" else self.hang_off_joint
        return None if j is None or j.kind == "pinned" else j

    @property
    def anchor_point(self) -> tuple[float, float, float]:
        """(x, y, z) of the anchor [m] (z = 0 when the scene gives (x, y))."""
        return _point(self.anchor)

    @property
    def hang_off_point(self) -> tuple[float, float, float]:
        """(x, y, z) of the hang-off [m] (z = 0 when the scene gives (x, y))."""
        return _point(self.hang_off)

    @property
    def in_plane(self) -> bool:
        """True when both ends lie in one plane z = const (the x-y plane, shifted)."""
        return self.anchor_point[2] == self.hang_off_point[2]

    @property
    def plane_heading_deg(self) -> float:
        """Heading of the line's plane [deg]: the direction from the anchor to the hang-off
        in the horizontal plane, from +x towards +z (0 for ends in one plane z = const;
        within (-90, 90) since x points towards the hang-off)."""
        (xa, _, za), (xh, _, zh) = self.anchor_point, self.hang_off_point
        if xh == xa:                  # a vertical chord (a TTR): the plane of z = const
            return 0.0 if zh == za else math.copysign(90.0, zh - za)
        return math.degrees(math.atan2(zh - za, xh - xa))


def _point(p) -> tuple[float, float, float]:
    return (float(p[0]), float(p[1]), float(p[2]) if len(p) > 2 else 0.0)


#: the end forms, in the order of the key tables
END_FORMS = (TdpTensionEnds, HangOffAngleEnds, TopTensionEnds, FixedEnds)

#: the key of ``[ends]`` that is no field: the hang-off angle from the vertical, converted
#: to hang_off_angle_deg = 90 - it on reading
FILE_KEYS = {
    "hang_off_angle_from_vertical_deg": Spec(ge=0.0, lt=90.0, unit="deg", optional=True,
                                             doc="hang-off angle from the vertical (or "
                                                 "give ..._from_horizontal_deg)"),
}

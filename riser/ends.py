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

from .environment import MAX_COORDINATE
from .spec import Part, Spec, check_fields, part_error, spec

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
                                       also="x > anchor x, 0 < y <= water_depth",
                                       doc="(x, y) or (x, y, z) of the top end")

    def __post_init__(self) -> None:
        check_fields(self)
        error = part_error(self)
        (xa, ya, _), (xh, yh, _) = self.anchor_point, self.hang_off_point
        if ya < 0.0:
            raise error("anchor[1]", f"must be >= 0 (the seabed is y = 0), got {ya:g}")
        if yh <= 0.0:
            raise error("hang_off[1]", "must be > 0 (the hang-off cannot be at or below the "
                        f"seabed y = 0), got {yh:g}")
        if xh <= xa:
            raise error("hang_off[0]", f"must be > anchor[0] = {xa:g} (x points from the "
                        f"anchor towards the hang-off), got {xh:g}")

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

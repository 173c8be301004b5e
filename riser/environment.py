"""The sea around the line: the current (scene table ``[environment.current]``) and the
seabed (``[seabed]``). Heights y [m] are measured up from the seabed (y = 0); each field's
range, unit and meaning is its spec (:mod:`riser.spec`), checked on construction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .spec import Part, check_fields, part_error, spec

#: the largest coordinate or height [m] (100 km)
MAX_COORDINATE = 1.0e5


@dataclass(frozen=True)
class Current(Part):
    """Current profile: speed [m/s] piecewise linear in height y [m], constant beyond.
    Heights are measured up from the seabed (>= 0); the scene checks that they stay below
    the surface (``Scene.current_reference_height``).

    Speeds are signed along ``heading_deg`` (0 = +x, in plane; 90 = +z, out of plane), so a
    current that reverses with height is expressed with speeds of both signs.
    """

    heights: tuple[float, ...] = spec(kind="numbers", ge=0.0, le=MAX_COORDINATE,
                                      unit="m", also="strictly increasing; <= water_depth "
                                      "(without it, <= the hang-off height the ends give)",
                                      doc="heights y of the profile's points, up from the "
                                          "seabed")
    speeds: tuple[float, ...] = spec(kind="numbers", ge=-10.0, le=10.0, unit="m/s",
                                     also="as many as heights",
                                     doc="signed speed along the heading at each height")
    heading_deg: float = spec(0.0, ge=-360.0, le=360.0, unit="deg",
                              doc="direction: 0 = +x (in plane), 90 = +z (out of plane)")

    def __post_init__(self) -> None:
        check_fields(self)
        error, h = part_error(self), self.heights
        if len(self.speeds) != len(h):
            raise error("speeds", f"must have as many entries as heights ({len(h)}), got "
                        f"{len(self.speeds)}")
        for i in range(1, len(h)):
            if not h[i] > h[i - 1]:
                raise error(f"heights[{i}]", f"must be > heights[{i - 1}] = {h[i - 1]:g} "
                            f"(strictly increasing), got {h[i]:g}")

    @property
    def is_planar(self) -> bool:
        """True when the current lies in the x-y plane (heading 0 or 180 deg)."""
        return abs(math.sin(math.radians(self.heading_deg))) < 1e-12

    @property
    def direction(self) -> np.ndarray:
        """Unit vector of the heading in (x, y, z)."""
        h = math.radians(self.heading_deg)
        return np.array([math.cos(h), 0.0, math.sin(h)])

    def speed(self, y: Any) -> np.ndarray:
        """Signed speed [m/s] along the heading at height(s) y [m]."""
        return np.interp(y, self.heights, self.speeds)

    def speed_gradient(self, y: Any) -> np.ndarray:
        """d(speed)/dy [1/s], piecewise constant, zero outside the given heights."""
        h = np.asarray(self.heights)
        v = np.asarray(self.speeds)
        y = np.asarray(y, dtype=float)
        if len(h) < 2:
            return np.zeros_like(y)
        slopes = np.diff(v) / np.diff(h)
        idx = np.clip(np.searchsorted(h, y, side="right") - 1, 0, len(h) - 2)
        out = slopes[idx]
        return np.where((y < h[0]) | (y > h[-1]), 0.0, out)

    @property
    def max_abs_speed(self) -> float:
        return max(abs(v) for v in self.speeds)


@dataclass(frozen=True)
class Seabed(Part):
    """Flat seabed at y = 0: penalty stiffness [N/m per m of line = N/m2], Coulomb friction,
    damping as a fraction of critical for the contact spring (the dynamic methods: the
    VFIFE and the frequency domain, each applying at most critical)."""

    stiffness: float = spec(gt=0.0, le=1.0e12, unit="N/m2",
                            doc="penalty stiffness per metre of line per metre of "
                                "penetration")
    friction: float = spec(0.0, ge=0.0, le=5.0, doc="Coulomb friction coefficient")
    damping: float = spec(0.0, ge=0.0, le=10.0,
                          doc="contact damping, fraction of critical (dynamics; "
                              "applied up to 1)")

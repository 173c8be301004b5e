"""The sea around the line: the current (scene table ``[environment.current]``) and the
seabed (``[seabed]``). Heights y [m] are measured up from the seabed (y = 0); each field's
range, unit and meaning is its spec (:mod:`riser.spec`), checked on construction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..spec import MAX_COORDINATE, Part, check_fields, part_error, spec


@dataclass(frozen=True)
class Current(Part):
    """Current profile: a velocity in the horizontal plane at each height y [m], piecewise
    linear in y between the given heights, constant beyond them. Heights are measured up
    from the seabed (>= 0); the scene checks that they stay below the surface
    (``Scene.current_reference_height``).

    Direction: one ``heading_deg`` for the whole profile (0 = +x, in plane; 90 = +z, out of
    plane), the speeds signed along it, so that a current that reverses with height is
    speeds of both signs; or ``headings_deg``, one heading per height (a profile that turns
    with depth). Between two heights the velocity vector is interpolated component by
    component (x and z, as MoorDyn interpolates its current profile): with one heading that
    is the speed interpolated along it.
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
                              also="not with headings_deg",
                              doc="direction of the whole profile: 0 = +x (in plane), "
                                  "90 = +z (out of plane)")
    headings_deg: tuple[float, ...] | None = spec(None, "numbers", ge=-360.0, le=360.0,
                                                  unit="deg",
                                                  also="as many as heights; not with "
                                                       "heading_deg",
                                                  default_doc="none (one heading_deg)",
                                                  doc="direction at each height, a profile "
                                                      "that turns with depth (0 = +x, "
                                                      "90 = +z)")

    def __post_init__(self) -> None:
        check_fields(self)
        error, h = part_error(self), self.heights
        if len(self.speeds) != len(h):
            raise error("speeds", f"must have as many entries as heights ({len(h)}), got "
                        f"{len(self.speeds)}")
        if self.headings_deg is not None:
            if len(self.headings_deg) != len(h):
                raise error("headings_deg", f"must have as many entries as heights "
                            f"({len(h)}), got {len(self.headings_deg)}")
            if self.heading_deg != 0.0:
                raise error("headings_deg", "give heading_deg (one direction) or "
                            "headings_deg (one per height), not both")
        for i in range(1, len(h)):
            if not h[i] > h[i - 1]:
                raise error(f"heights[{i}]", f"must be > heights[{i - 1}] = {h[i - 1]:g} "
                            f"(strictly increasing), got {h[i]:g}")

    @property
    def turns(self) -> bool:
        """True when the profile gives a heading per height (``headings_deg``)."""
        return self.headings_deg is not None

    @property
    def headings(self) -> tuple[float, ...]:
        """The heading at each height [deg]."""
        return self.headings_deg if self.turns else (self.heading_deg,) * len(self.heights)

    @property
    def is_planar(self) -> bool:
        """True when the current lies in the x-y plane at every height (every heading 0
        or 180 deg)."""
        return all(abs(math.sin(math.radians(hd))) < 1e-12 for hd in self.headings)

    @property
    def direction(self) -> np.ndarray:
        """Unit vector of the (single) heading in (x, y, z); for a turning profile, of
        its first height."""
        h = math.radians(self.headings[0])
        return np.array([math.cos(h), 0.0, math.sin(h)])

    def speed(self, y: Any) -> np.ndarray:
        """Signed speed [m/s] along the heading at height(s) y [m] (one heading; a
        turning profile: the magnitude of :meth:`velocity`)."""
        if self.turns:
            ux, uz = self.velocity(y)
            return np.hypot(ux, uz)
        return np.interp(y, self.heights, self.speeds)

    @property
    def components(self) -> tuple[np.ndarray, np.ndarray]:
        """(ux, uz) [m/s]: the velocity's x and z components at the given heights."""
        h = np.radians(np.asarray(self.headings, float))
        v = np.asarray(self.speeds, float)
        return v * np.cos(h), v * np.sin(h)

    def velocity(self, y: Any) -> tuple[np.ndarray, np.ndarray]:
        """(ux, uz) [m/s]: the current's x and z components at height(s) y [m],
        interpolated component by component (one heading: the speed along it times the
        heading's cosine and sine)."""
        if not self.turns:
            v = self.speed(y)
            h = math.radians(self.heading_deg)
            return v * math.cos(h), v * math.sin(h)
        ux, uz = self.components
        return np.interp(y, self.heights, ux), np.interp(y, self.heights, uz)

    def velocity_gradient(self, y: Any) -> tuple[np.ndarray, np.ndarray]:
        """d(ux, uz)/dy [1/s], piecewise constant, zero outside the given heights."""
        ux, uz = self.components
        return _slope(self.heights, ux, y), _slope(self.heights, uz, y)

    @property
    def max_abs_speed(self) -> float:
        return max(abs(v) for v in self.speeds)


def _slope(heights, values, y: Any) -> np.ndarray:
    """d(values)/dy of the piecewise-linear profile through (heights, values), zero
    outside the heights."""
    h = np.asarray(heights, float)
    v = np.asarray(values, float)
    y = np.asarray(y, dtype=float)
    if len(h) < 2:
        return np.zeros_like(y)
    slopes = np.diff(v) / np.diff(h)
    idx = np.clip(np.searchsorted(h, y, side="right") - 1, 0, len(h) - 2)
    out = slopes[idx]
    return np.where((y < h[0]) | (y > h[-1]), 0.0, out)


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

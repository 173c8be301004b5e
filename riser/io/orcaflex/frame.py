"""The scene's frame in OrcaFlex's global axes, shared by the import and its parts.

OrcaFlex: X, Y horizontal, Z up, the still surface at ``WaterSurfaceZ``; a direction (of
waves, current, a vessel's heading) is measured from X towards Y (anticlockwise seen from
above). The scene: x horizontal from the bottom end towards the hang-off, y up from the
seabed, z = x cross y. With the line's plane at azimuth alpha (from the bottom end
towards the top end, from X towards Y) the scene's axes are x = (cos a, sin a, 0), y =
(0, 0, 1), z = (sin a, -cos a, 0) (OrcaFlex's -Y for a line along +X), so a direction
theta of OrcaFlex is the scene's heading alpha - theta (from +x towards +z).

The seabed: OrcaFlex's contact is at the line's outer surface (a node touches the seabed
when its centre is within half the contact diameter of it), the scene's at the line's
centre. The scene's seabed is therefore OrcaFlex's raised by the contact radius r of the
bottom line type: y = Z - (Z_seabed + r), the water depth h - r, the surface where it
was. The anchor OrcaFlex lays on its seabed (z = r above it) is then on the scene's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..angles import wrap_deg


@dataclass(frozen=True)
class Frame:
    """The scene's frame: the bottom end's global position [m] (X, Y), the plane's
    azimuth [deg], the scene's seabed height Z_0 [m] in OrcaFlex's axes (OrcaFlex's
    seabed plus the contact radius) and the water depth of the scene [m]."""

    x0: float
    y0: float
    alpha_deg: float
    z_seabed: float
    depth: float

    @property
    def ex(self) -> tuple[float, float]:
        a = math.radians(self.alpha_deg)
        return math.cos(a), math.sin(a)

    def point(self, X: float, Y: float, Z: float) -> tuple[float, float, float]:
        """The scene's (x, y, z) [m] of OrcaFlex's global point (X, Y, Z) [m]."""
        cx, sx = self.ex
        dx, dy = X - self.x0, Y - self.y0
        return dx * cx + dy * sx, Z - self.z_seabed, dx * sx - dy * cx

    def plan(self, X: float, Y: float) -> tuple[float, float]:
        """The scene's horizontal (x, z) [m] of OrcaFlex's (X, Y)."""
        x, _, z = self.point(X, Y, 0.0)
        return x, z

    def direction(self, theta_deg: float) -> float:
        """The scene's heading [deg] (from +x towards +z, in (-180, 180]) of OrcaFlex's
        direction ``theta_deg`` (from X towards Y): alpha - theta."""
        return wrap_deg(self.alpha_deg - theta_deg)

"""The line's plane: the vertical plane through the anchor and the hang-off, and the
quantities of a 3D line measured from it (lateral offset, out-of-plane bending moment).

Coordinates (SI, [m]): x horizontal towards the hang-off, y up from the seabed, z out of
plane (right-handed). The plane passes through the anchor (x_a, z_a) with the heading
psi = atan2(z_h - z_a, x_h - x_a) from +x towards +z (:attr:`riser.model.ends.FixedEnds.
plane_heading_deg`; 0 for a planar scene and for the touchdown forms, whose plane is x-y).
Its in-plane horizontal axis is e_xi = (cos psi, 0, sin psi) and its normal, the lateral
axis, e_n = (-sin psi, 0, cos psi) = e_xi x e_y. A heading h of the current (from +x
towards +z) is h - psi in the plane's frame.

These are geometry and result definitions shared by the methods (as the profile is), not
physics: each method solves its own equations and reports its positions, tangents and
moment vectors; :func:`out_of_plane_columns` turns them into the two columns every 3D
profile carries.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .ends import FixedEnds


@dataclass(frozen=True)
class LinePlane:
    """The vertical plane through (``x0``, ``z0``) [m] at heading ``heading_deg`` [deg]."""

    x0: float = 0.0
    z0: float = 0.0
    heading_deg: float = 0.0

    @classmethod
    def of(cls, scene) -> "LinePlane":
        """The plane of a scene: through its fixed ends, else the x-y plane."""
        e = scene.ends
        if isinstance(e, FixedEnds):
            xa, _, za = e.anchor_point
            return cls(xa, za, e.plane_heading_deg)
        return cls()

    @property
    def psi(self) -> float:
        return math.radians(self.heading_deg)

    @property
    def normal(self) -> np.ndarray:
        """The lateral unit vector e_n = (-sin psi, 0, cos psi)."""
        return np.array([-math.sin(self.psi), 0.0, math.cos(self.psi)])

    def vector_to_plane(self, vx, vz):
        """The horizontal components (along e_xi, along e_n) of vectors with components
        (vx, vz) along x and z (a velocity, a load, a tangent)."""
        c, s = math.cos(self.psi), math.sin(self.psi)
        return c * vx + s * vz, -s * vx + c * vz

    def vector_from_plane(self, vxi, vzeta):
        """The x and z components of vectors with components (vxi, vzeta) along e_xi and
        e_n (the inverse of :meth:`vector_to_plane`)."""
        c, s = math.cos(self.psi), math.sin(self.psi)
        return c * vxi - s * vzeta, s * vxi + c * vzeta

    def to_plane(self, x, z):
        """(xi, zeta) [m]: the distance along the plane from the anchor and the signed
        lateral offset (towards +e_n) of points (x, z)."""
        return self.vector_to_plane(np.asarray(x, float) - self.x0,
                                    np.asarray(z, float) - self.z0)

    def from_plane(self, xi, zeta):
        """(x, z) [m] of points at (xi, zeta) in the plane's frame (inverse of
        :meth:`to_plane`)."""
        c, s = math.cos(self.psi), math.sin(self.psi)
        xi, zeta = np.asarray(xi, float), np.asarray(zeta, float)
        return self.x0 + c * xi - s * zeta, self.z0 + s * xi + c * zeta

    def lateral(self, x, z) -> np.ndarray:
        """Signed lateral offset [m] of points (x, z) from the plane."""
        return self.to_plane(x, z)[1]


def out_of_plane_columns(plane: LinePlane, x, z, tangents, moments):
    """(lateral [m], moment_out_of_plane [N m]) along a 3D line: the signed distance of
    each station from ``plane`` and the bending moment that bends the line out of it,
    m . b with b = unit(t x e_n) (t the unit tangent (n, 3), m the bending-moment vector
    (n, 3) [N m]): for a line lying in the plane, EI times its curvature towards e_n, with
    that sign (positive when the line curves towards +e_n). Where the tangent is along
    e_n (never for a riser) b is undefined and the column is 0."""
    t = np.asarray(tangents, float)
    m = np.asarray(moments, float)
    b = np.cross(t, plane.normal)
    nb = np.linalg.norm(b, axis=1)
    b = b / np.where(nb > 1e-12, nb, 1.0)[:, None]
    oop = np.where(nb > 1e-12, np.einsum("ij,ij->i", m, b), 0.0)
    return plane.lateral(x, z), oop


def plane_columns(plane: LinePlane, x, z, tangents, moments):
    """(lateral [m], moment_in_plane [N m], moment_out_of_plane [N m]) along a 3D line:
    :func:`out_of_plane_columns` and the moment about the in-plane bending axis,
    m . (b x t), signed as the planar moment (EI times the curvature of the line's
    projection on its plane, positive when it turns up away from the plane's x axis):
    with the out-of-plane moment, the moment vector's two components across the tangent,
    so that two lines can be compared component by component (a magnitude has a kink
    where the moment changes sign)."""
    t = np.asarray(tangents, float)
    m = np.asarray(moments, float)
    lateral, oop = out_of_plane_columns(plane, x, z, t, m)
    b = np.cross(t, plane.normal)
    nb = np.linalg.norm(b, axis=1)
    b = b / np.where(nb > 1e-12, nb, 1.0)[:, None]
    inplane = np.where(nb > 1e-12, np.einsum("ij,ij->i", m, np.cross(b, t)), 0.0)
    return lateral, inplane, oop


def elevation(plane: LinePlane, tangents) -> np.ndarray:
    """The tangent's angle from the horizontal [rad] of unit tangents (n, 3) in the scene's
    axes, beyond the vertical (above pi/2) when the tangent points back along the plane
    (towards the anchor): the planar convention, measured in the line's plane."""
    t = np.asarray(tangents, float)
    along = plane.vector_to_plane(t[:, 0], t[:, 2])[0]
    return np.arctan2(t[:, 1], np.copysign(np.hypot(t[:, 0], t[:, 2]), along))

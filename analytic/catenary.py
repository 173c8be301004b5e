"""The extensible elastic catenary in closed form (Irvine 1981), in unstretched arc length.

A line of submerged weight w [N/m, > 0] and axial stiffness EA [N] (``inf``: inextensible)
with no bending stiffness carries a constant horizontal force H [N] and a vertical force
V(sigma) = V0 + w sigma [N] at unstretched arc length sigma [m] from its start point, where
it is V0. With strain T/EA and T = sqrt(H^2 + V^2):

    x(sigma) = (H/w) [asinh(V/H) - asinh(V0/H)] + H sigma / EA
    y(sigma) = (H/w) [sqrt(1 + (V/H)^2) - sqrt(1 + (V0/H)^2)] + (V0 sigma + w sigma^2/2) / EA
    theta = atan(V/H),   dtheta/dsigma = w H / (H^2 + V^2)

(x towards the hang-off, y up, theta from the horizontal). Measured from the vertex
(V0 = 0) this is the touchdown catenary; sigma may be negative (the catenary continued
past its vertex). The bending moment of the "catenary model" is EI dtheta/dsigma (curvature
per unstretched length, the convention of both numerical methods).

Second-order outer solution (:meth:`Catenary.bending_correction`). With bending the
outer equation is EI theta'' = (1 + T/EA)(H sin(theta) - V cos(theta)); putting
theta = theta0 + theta2 with tan(theta0) = V/H gives, to O(eps^2),

    theta2 = EI theta0'' / ((1 + T0/EA) T0)

and the positions move by dy2/dsigma = (EI/w) theta0' theta0'' and
dx2/dsigma = -(EI/H) sigma theta0' theta0'' (EA drops out). From the vertex, with
u = w sigma / H:

    dy2 = (EI / (2 w)) (theta0'(sigma)^2 - (w/H)^2)            (-> -EI w / (2 H^2) far up)
    dx2 = 2 (EI w / H^2) G(u),  G(u) = [atan(u) + u (u^2 - 1) / (1 + u^2)^2] / 8

The height change cancels the touchdown layer's vertex lift y_v = EI w / (2 H^2) (rigid
seabed): the top of an inextensible beam with a moment-free hang-off then obeys the exact
first integral T - w y + EI kappa^2 / 2 = H, i.e. H = T_top - w Y + EI kappa_top^2 / 2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Catenary:
    """One catenary piece: H [N], V0 [N] at its start, w [N/m], EA [N] (inf allowed)."""

    H: float
    V0: float
    w: float
    EA: float = math.inf

    def V(self, sigma):
        return self.V0 + self.w * np.asarray(sigma, float)

    def x(self, sigma):
        s = np.asarray(sigma, float)
        H, w = self.H, self.w
        return (H / w) * (np.arcsinh(self.V(s) / H) - math.asinh(self.V0 / H)) + H * s / self.EA

    def y(self, sigma):
        s = np.asarray(sigma, float)
        H, w = self.H, self.w
        return ((H / w) * (np.hypot(1.0, self.V(s) / H) - math.hypot(1.0, self.V0 / H))
                + (self.V0 * s + 0.5 * w * s * s) / self.EA)

    def theta(self, sigma):
        return np.arctan2(self.V(sigma), self.H)

    def tension(self, sigma):
        return np.hypot(self.H, self.V(sigma))

    def curvature(self, sigma):
        """dtheta/dsigma [1/m] per unstretched length (positive: the line bends upwards)."""
        V = self.V(sigma)
        return self.w * self.H / (self.H * self.H + V * V)

    def curvature_slope(self, sigma):
        """d2theta/dsigma2 [1/m2]."""
        V = self.V(sigma)
        d = self.H * self.H + V * V
        return -2.0 * self.w * self.w * self.H * V / (d * d)


def vertex_height(H: float, w: float, EA: float, length: float) -> float:
    """Height [m] gained over unstretched ``length`` [m] from the vertex."""
    return float(Catenary(H, 0.0, w, EA).y(length))


def vertex_length_for_height(H: float, w: float, EA: float, height: float) -> float:
    """The unstretched length [m] from the vertex that rises by ``height`` [m] >= 0.

    With u = w L / H and z = sqrt(1 + u^2): w h / H = z - 1 + (H / (2 EA)) (z^2 - 1), a
    quadratic in z (closed form; z = 1 + w h / H when inextensible)."""
    r = w * height / H
    e = H / (2.0 * EA)
    if e == 0.0:
        z = 1.0 + r
    else:
        # e z^2 + z - (1 + e + r) = 0, positive root, written without cancellation
        c = 1.0 + e + r
        z = 2.0 * c / (1.0 + math.sqrt(1.0 + 4.0 * e * c))
    return (H / w) * math.sqrt(max(z * z - 1.0, 0.0))


def bending_correction(cat: Catenary, EI: float, sigma):
    """The O(eps^2) outer correction from the vertex (module docstring) of a vertex
    catenary (V0 = 0): dx2, dy2 [m], theta2 [rad] and its slope dtheta2/dsigma [1/m]."""
    if cat.V0 != 0.0:
        raise ValueError("the bending correction is written from the vertex (V0 = 0)")
    s = np.asarray(sigma, float)
    H, w, EA = cat.H, cat.w, cat.EA
    u = w * s / H
    k1 = cat.curvature(s)
    dy = (EI / (2.0 * w)) * (k1 * k1 - (w / H) ** 2)
    dx = 2.0 * EI * w / (H * H) * (np.arctan(u) + u * (u * u - 1.0) / (1.0 + u * u) ** 2) / 8.0
    T0 = cat.tension(s)
    c = 1.0 + T0 / EA
    k2 = cat.curvature_slope(s)
    d = H * H + (w * s) ** 2
    k3 = -2.0 * w ** 3 * H * (H * H - 3.0 * (w * s) ** 2) / d ** 3
    cT = c * T0
    dcT = (1.0 + 2.0 * T0 / EA) * w * (w * s) / T0
    th2 = EI * k2 / cT
    dth2 = EI * (k3 / cT - k2 * dcT / (cT * cT))
    return dx, dy, th2, dth2

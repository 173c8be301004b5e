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
        """Span [m] from the start: (H/w) [asinh(b) - asinh(a)] + H sigma / EA, a = V0/H,
        b = V/H, in a form without cancellation (:func:`_asinh_difference`)."""
        s = np.asarray(sigma, float)
        a, b = self.V0 / self.H, self.V(s) / self.H
        return s * _asinh_difference(a, b, self.w * s / self.H) + self.H * s / self.EA

    def y(self, sigma):
        """Rise [m] from the start: (H/w) [sqrt(1 + b^2) - sqrt(1 + a^2)] + (V0 sigma +
        w sigma^2 / 2) / EA, written as sigma (a + b) / (sqrt(1 + a^2) + sqrt(1 + b^2)):
        no cancellation when w sigma << H (a taut line) and no division by w."""
        s = np.asarray(sigma, float)
        a, b = self.V0 / self.H, self.V(s) / self.H
        return (s * (a + b) / (np.hypot(1.0, a) + np.hypot(1.0, b))
                + (self.V0 * s + 0.5 * self.w * s * s) / self.EA)

    def theta(self, sigma):
        return np.arctan2(self.V(sigma), self.H)

    def tension(self, sigma):
        return np.hypot(self.H, self.V(sigma))

    def curvature(self, sigma):
        """dtheta/dsigma [1/m] per unstretched length (positive: the line bends upwards):
        w H / (H^2 + V^2), written in the ratios w/H and V/H (no overflow or underflow of
        the squares of the forces)."""
        v = self.V(sigma) / self.H
        return (self.w / self.H) / (1.0 + v * v)

    def curvature_slope(self, sigma):
        """d2theta/dsigma2 [1/m2]: -2 w^2 H V / (H^2 + V^2)^2, in the ratios."""
        v = self.V(sigma) / self.H
        d = 1.0 + v * v
        return -2.0 * (self.w / self.H) ** 2 * v / (d * d)


def _asinh_difference(a, b, d):
    """(asinh(b) - asinh(a)) / d [-] with d = b - a given directly (w sigma / H, not the
    difference of a and b) and 1 / sqrt(1 + a^2) where d = 0, without the
    cancellation of the plain difference when b - a = w sigma / H is small against a, b (a
    taut line: a taut 20 m line of 1e-6 N/m lost 11 of its 16 digits). Where a, b have one
    sign, asinh(b) - asinh(a) = asinh(z), z = (b - a) D, D = (a + b) / (b sqrt(1 + a^2) +
    a sqrt(1 + b^2)) > 0, and asinh(z) / z is evaluated directly; where they differ in sign
    the plain difference adds two terms of one sign (no cancellation)."""
    a, b, d = np.broadcast_arrays(np.asarray(a, float), np.asarray(b, float),
                                  np.asarray(d, float))
    ra, rb = np.hypot(1.0, a), np.hypot(1.0, b)
    same = (a >= 0.0) == (b >= 0.0)
    den = b * ra + a * rb
    ok = same & (den != 0.0)
    D = np.where(ok, (a + b) / np.where(ok, den, 1.0), 1.0)
    z = d * D
    nz = z != 0.0
    ratio = np.where(nz, np.arcsinh(z) / np.where(nz, z, 1.0), 1.0)
    plain_ok = ~same & (d != 0.0)
    plain = (np.arcsinh(b) - np.arcsinh(a)) / np.where(plain_ok, d, 1.0)
    # same sign: asinh(z) / (b - a) = D asinh(z) / z (at b = a, a = 0: D = 1 = 1/sqrt(1+0))
    same_val = np.where(ok, D * ratio, 1.0 / ra)
    return np.where(same, same_val, plain)


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
    # everything in the ratios w/H and u = w sigma / H: no division by w, and no square
    # of a force that could underflow or overflow (a nearly weightless line)
    k = w / H
    u = k * s
    p = 1.0 + u * u
    # (EI / (2 w)) (theta0'^2 - (w/H)^2) with theta0' = (w/H) / p, without the cancellation
    dy = -(EI * k / (2.0 * H)) * u * u * (2.0 + u * u) / (p * p)
    dx = 2.0 * EI * k / H * (np.arctan(u) + u * (u * u - 1.0) / (p * p)) / 8.0
    T0 = cat.tension(s)
    c = 1.0 + T0 / EA
    k2 = cat.curvature_slope(s)
    k3 = -2.0 * k ** 3 * (1.0 - 3.0 * u * u) / (p * p * p)
    cT = c * T0
    # d(c T)/dsigma / (c T), with T0 = H sqrt(p): (1 + 2 T0/EA) / c * (w/H) u / p
    dlog = (1.0 + 2.0 * T0 / EA) / c * k * u / p
    th2 = EI * k2 / cT
    dth2 = EI * (k3 - k2 * dlog) / cT
    return dx, dy, th2, dth2

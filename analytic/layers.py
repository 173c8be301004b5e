"""Boundary layers of the heavy beam: the touchdown layer and the layer at a pinned end.

Derivation (planar, no current; s unstretched arc length; c = 1 + H/EA). Away from its
ends a riser of bending stiffness EI is the catenary of :mod:`analytic.catenary` to
O(eps^2), eps = sqrt(EI / (H L^2)): the bending term EI theta'' is eps^2 smaller than
H sin(theta). Near the touchdown the catenary cannot meet the seabed's conditions (its
moment jumps from 0 to EI w/H), and the beam adjusts over lambda = sqrt(EI / (c H)).
There the angle is small, delta = w lambda / H (0.03 for Kang's pipe), so with
theta = y'/c, T = H, the moment balance EI theta'' = c F and the shear balance
F' = H theta' - w + p linearise to

    y'''' - a y'' + b y = -q   in contact (p = -k y, y < 0)      a = c H / EI
    y'''' - a y''       = -q   suspended   (y > 0)                q = c^2 w / EI,
                                                                 b = c^2 k / EI

(k [N/m2] the Winkler stiffness of the seabed). Taking s = 0 at the lift-off point
(y = 0), the suspended solution that does not grow into the outer region is

    y = A0 + A1 s + q s^2 / (2 a) + C exp(-sqrt(a) s),

whose polynomial part is the inner limit of the outer catenary: a catenary with its
vertex at s_v = -A1 a / q along the line and at height y_v = A0 - A1^2 a / (2 q). In
contact the solution decaying into the seabed is -w/k + D1 phi1 + D2 phi2 with
phi = exp(r s), r^4 - a r^2 + b = 0, Re r > 0 (a pair of damped waves when a^2 < 4b).
Continuity of y, y', y'', y''' at s = 0 and y(0) = 0 on both sides fix the five
constants. On a rigid seabed (k -> inf) the contact side is y = 0 and the suspended side
meets y = y' = y'' = 0 (theta = 0, M = 0; a concentrated reaction w lambda acts at the
touchdown): C = -q/a^2, s_v = lambda, y_v = w lambda^2 c / (2 H)... exactly
y_v = q / (2 a^2). The correction C exp(-s/lambda) adds to the angle y_c'/c, to the moment
EI y_c''/c and to the shear EI y_c'''/c^2; it is the composite of matched asymptotic
expansions (outer + inner - common part, Van Dyke). Its error is O(delta^2) relative in
the layer (sin, cos linearised; T = H there) and O(eps^2) outside, plus the O(eps^2 L)
the outer problem leaves when it places the vertex (see analytic/forms.py).

A pinned end (moment-free hang-off, or a pinned anchor of a free-hanging line) meets a
catenary whose moment EI kappa_o is not zero. Linearising about the catenary angle,
EI phi'' = c_e T_e phi, so the composite adds kappa = -kappa_o(end) exp(-d / lambda_e),
theta = -/+ kappa_o(end) lambda_e exp(-d / lambda_e) (d the distance from the end,
lambda_e = sqrt(EI / (c_e T_e))): zero moment at the end, an angle change of O(eps) of
the catenary's curvature there, a position change of O(eps^2) (neglected).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


def layer_length(EI: float, T: float, EA: float) -> float:
    """The length [m] of a bending layer under effective tension T [N]:
    sqrt(EI / ((1 + T/EA) T)) (lambda at the touchdown with T = H, lambda_e at an end)."""
    return math.sqrt(EI / ((1.0 + T / EA) * T))


@dataclass(frozen=True)
class TouchdownLayer:
    """The touchdown layer of a line with horizontal force H [N], weight w [N/m], EI
    [N m2], EA [N] (inf allowed), on a seabed of stiffness k [N/m2] (None: rigid).

    s_v [m], y_v [m]: the outer catenary's vertex from the lift-off point along the line
    and above the seabed surface. ``end`` [m] (optional): a second end of the beam part,
    where the correction's moment is forced to zero (Kang's piecewise model, where the
    catenary takes over with its own moment); None for a semi-infinite layer."""

    H: float
    w: float
    EI: float
    EA: float
    k: float | None
    s_v: float
    y_v: float
    C: float
    B: float
    end: float | None
    roots: tuple
    D: tuple

    @property
    def c(self) -> float:
        return 1.0 + self.H / self.EA

    @property
    def length(self) -> float:
        """lambda = sqrt(EI / (c H)) [m], the layer's length scale."""
        return layer_length(self.EI, self.H, self.EA)

    def correction(self, s: np.ndarray) -> tuple[np.ndarray, ...]:
        """y, y', y'', y''' of the correction C exp(-s/lambda) (+ B exp((s - end)/lambda)) at
        ``s`` >= 0 from the lift-off point. The second term belongs to the beam part
        [0, end] only and is 0 beyond ``end`` (where the catenary takes over and the caller
        drops the correction; evaluated there it would overflow on a short layer)."""
        r = 1.0 / self.length
        s = np.asarray(s, float)
        e1 = self.C * np.exp(-r * s)
        if self.end is not None:
            e2 = np.where(s <= self.end,
                          self.B * np.exp(r * np.minimum(s - self.end, 0.0)), 0.0)
        else:
            e2 = 0.0 * s
        return e1 + e2, r * (e2 - e1), r * r * (e1 + e2), r ** 3 * (e2 - e1)

    def grounded(self, s: np.ndarray) -> tuple[np.ndarray, ...]:
        """y, y', y'', y''' of the line in contact at ``s`` <= 0 (zeros on a rigid seabed)."""
        s = np.asarray(s, float)
        if self.k is None:
            z = np.zeros_like(s)
            return z, z, z, z
        out = [np.full_like(s, -self.w / self.k), *(np.zeros_like(s) for _ in range(3))]
        for n in range(4):
            out[n] = out[n] + _basis(self.roots, s, n) @ np.asarray(self.D)
        return tuple(out)


def _basis(roots: tuple, s: np.ndarray, n: int) -> np.ndarray:
    """n-th derivatives of the two real decaying solutions in contact, shape (len(s), 2):
    exp(r1 s), exp(r2 s) for real roots, Re and Im of exp(r s) for a complex pair."""
    r1, r2 = roots
    if isinstance(r1, complex):
        v = r1 ** n * np.exp(r1 * s)
        return np.stack([v.real, v.imag], axis=-1)
    return np.stack([r1 ** n * np.exp(r1 * s), r2 ** n * np.exp(r2 * s)], axis=-1)


def _contact_roots(a: float, b: float) -> tuple:
    """The two roots of r^4 - a r^2 + b = 0 with Re r > 0 (one of a complex pair)."""
    disc = a * a - 4.0 * b
    if abs(disc) <= 1e-12 * a * a:           # a double root: split it (no effect at 1e-6)
        disc = -1e-10 * a * a
    if disc > 0.0:
        return (math.sqrt(0.5 * (a + math.sqrt(disc))), math.sqrt(0.5 * (a - math.sqrt(disc))))
    r = complex(0.5 * a, 0.5 * math.sqrt(-disc)) ** 0.5
    return (r if r.real > 0 else -r, None)


def touchdown_layer(H: float, w: float, EI: float, EA: float, k: float | None,
                    end: float | None = None) -> TouchdownLayer:
    """Solve the touchdown layer (module docstring) for horizontal force H [N]."""
    c = 1.0 + H / EA
    a, q = c * H / EI, c * c * w / EI
    ra = math.sqrt(a)
    eE = math.exp(-ra * end) if end is not None else 0.0
    # unknowns: A0, A1, C, B, D1, D2
    rows, rhs = [], []
    # the suspended side at s = 0: y, y', y'', y''' (B's terms carry exp(-sqrt(a) end))
    sus = [[1.0, 0.0, 1.0, eE], [0.0, 1.0, -ra, ra * eE], [0.0, 0.0, a, a * eE],
           [0.0, 0.0, -a * ra, a * ra * eE]]
    poly = [0.0, 0.0, q / a, 0.0]              # the particular solution's y..y''' at 0
    roots, D = (None, None), (0.0, 0.0)
    if k is None:
        for n in range(3):                      # y = y' = y'' = 0 at the touchdown
            rows.append(sus[n] + [0.0, 0.0])
            rhs.append(-poly[n])
    else:
        b = c * c * k / EI
        roots = _contact_roots(a, b)
        g = _basis(roots, np.zeros(1), 0)[0]
        rows.append([0.0, 0.0, 0.0, 0.0, *g])   # contact side: y(0) = 0
        rhs.append(w / k)
        rows.append(sus[0] + [0.0, 0.0])        # suspended side: y(0) = 0
        rhs.append(0.0)
        for n in (1, 2, 3):                     # continuity of y', y'', y'''
            g = _basis(roots, np.zeros(1), n)[0]
            rows.append([-v for v in sus[n]] + list(g))
            rhs.append(poly[n])
    # the beam part's far end: no moment correction there (B = -C exp(-sqrt(a) end)), else B = 0
    rows.append([0.0, 0.0, eE, 1.0, 0.0, 0.0])
    rhs.append(0.0)
    M = np.array(rows)
    keep = [0, 1, 2, 3] + ([4, 5] if k is not None else [])
    sol = np.linalg.solve(M[:, keep], np.array(rhs))
    A0, A1, C, B = sol[:4]
    if k is not None:
        D = (float(sol[4]), float(sol[5]))
    s_v = -A1 * a / q
    y_v = A0 - A1 * A1 * a / (2.0 * q)
    return TouchdownLayer(H, w, EI, EA, k, float(s_v), float(y_v), float(C), float(B), end,
                          roots, D)


def pinned_end_correction(d: np.ndarray, kappa_end: float, lam: float):
    """Curvature [1/m], angle magnitude [rad] and curvature slope magnitude [1/m2] added at
    distance ``d`` [m] from a moment-free end where the catenary's curvature is
    ``kappa_end`` [1/m], over the end layer's length ``lam`` [m] (module docstring): the
    curvature is -kappa_end exp(-d/lam); its integral away from the end gives the angle
    kappa_end lam exp(-d/lam) (sign by the caller: the angle turns against the curvature's
    jump), its derivative kappa_end/lam exp(-d/lam)."""
    e = np.exp(-np.asarray(d, float) / lam)
    return -kappa_end * e, kappa_end * lam * e, kappa_end / lam * e


@dataclass(frozen=True)
class AnchorLayer:
    """The laid line's layer at an anchor pinned at y = 0 on an elastic seabed, where the
    line away from it rests at -w/k: y = -w/k + E1 phi1 + E2 phi2 with phi = exp(-r s)
    (the contact roots of :func:`touchdown_layer`), y(0) = 0 and M(0) = 0. Its length is
    about (4 EI / k)^(1/4), the beam-on-elastic-foundation length (Hetenyi)."""

    roots: tuple
    E: tuple
    w: float
    k: float

    @property
    def length(self) -> float:
        return 1.0 / min(abs(r.real) for r in self.roots if r is not None)

    def correction(self, s: np.ndarray) -> tuple[np.ndarray, ...]:
        """y + w/k, y', y'', y''' at ``s`` >= 0 from the anchor."""
        s = np.asarray(s, float)
        return tuple((-1.0) ** n * (_basis(self.roots, -s, n) @ np.asarray(self.E))
                     for n in range(4))


def anchor_layer(H: float, w: float, EI: float, EA: float, k: float) -> AnchorLayer:
    """Solve :class:`AnchorLayer` for horizontal force H [N] on seabed stiffness k [N/m2]."""
    c = 1.0 + H / EA
    roots = _contact_roots(c * H / EI, c * c * k / EI)
    z = np.zeros(1)
    M = np.array([_basis(roots, z, 0)[0], _basis(roots, z, 2)[0]])
    E = np.linalg.solve(M, np.array([w / k, 0.0]))
    return AnchorLayer(roots, (float(E[0]), float(E[1])), w, k)

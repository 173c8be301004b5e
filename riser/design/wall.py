"""The pipe wall along the line: its section at each station, the pressures on it, the
wall tension and the stresses (SI: [m], [Pa], [N], [N m]).

Section at a station (its segment's line type): outer diameter D, inner d, wall t = (D -
d) / 2, steel area A_s = pi (D^2 - d^2) / 4, second moment I = pi (D^4 - d^4) / 64,
Young's modulus E = EI / I (the line type's bending stiffness over the wall's geometric
I: exactly the given modulus for a pipe given by its wall and material), SMYS f_y, SMTS
f_u.

Pressures (gauge): outside p_e = rho_w g (h - y) (h the water depth), inside p_i = p_top
+ rho_c g (y_top - y) (p_top the design's :meth:`~riser.design.part.Design.top_pressure`,
rho_c the contents' density, y_top the hang-off's height).

Wall tension: T_w = T_e + mu U^2 + p_i A_i - p_e A_o, from the effective tension T_e the
methods solve for (Sparsholt; with internal flow the momentum flux mu U^2 as in
:mod:`riser.physics.internal_flow`).

Stresses, thick wall (Lame), at radius r (r_i <= r <= r_o):
    sigma_h = (p_i r_i^2 - p_e r_o^2) / (r_o^2 - r_i^2) + (p_i - p_e) r_i^2 r_o^2 / ((r_o^2 - r_i^2) r^2)
    sigma_r = (p_i r_i^2 - p_e r_o^2) / (r_o^2 - r_i^2) - (p_i - p_e) r_i^2 r_o^2 / ((r_o^2 - r_i^2) r^2)
(sigma_r = -p_i at r_i, -p_e at r_o); axial sigma_a = T_w / A_s + sigma_b with the bending
stress at the point of angle phi around the section, measured from the in-plane normal n
(the normal in the line's plane, to the left of the tangent: upwards on a riser rising to
the hang-off) towards the plane's normal e_n,
    sigma_b = -(r / I) (M_in cos phi + M_out sin phi),
M_in the bending moment signed as the planar moment (EI times the curvature, positive
when the line turns towards n: the fibre on n's side is then in compression) and M_out
the out-of-plane moment (:mod:`riser.model.frame`). Von Mises of the three principal stresses
(no torsion, no shear: the methods carry no torque on these lines and the shear stress
of the shear force is ~1e-3 of the bending stress on a riser):
    sigma_vm = sqrt(((sigma_a - sigma_h)^2 + (sigma_h - sigma_r)^2 + (sigma_r - sigma_a)^2) / 2).
The largest over the section is at an extreme fibre of the bending (sigma_vm is convex in
sigma_a): :func:`stresses` evaluates the inner and outer surfaces on the tension and the
compression side of the resultant moment.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np



@dataclass(frozen=True)
class Wall:
    """The wall at stations (arrays (n,), SI; see the module docstring)."""

    outer_diameter: np.ndarray
    inner_diameter: np.ndarray
    yield_strength: np.ndarray
    tensile_strength: np.ndarray
    youngs_modulus: np.ndarray
    contents_density: np.ndarray

    @property
    def thickness(self) -> np.ndarray:
        return 0.5 * (self.outer_diameter - self.inner_diameter)

    @property
    def area(self) -> np.ndarray:
        """A_s [m2], the steel area."""
        return math.pi / 4.0 * (self.outer_diameter ** 2 - self.inner_diameter ** 2)

    @property
    def inertia(self) -> np.ndarray:
        """I [m4], the wall's second moment of area."""
        return math.pi / 64.0 * (self.outer_diameter ** 4 - self.inner_diameter ** 4)

    @property
    def bore_area(self) -> np.ndarray:
        return math.pi / 4.0 * self.inner_diameter ** 2

    @property
    def outer_area(self) -> np.ndarray:
        return math.pi / 4.0 * self.outer_diameter ** 2

    def take(self, index) -> "Wall":
        """The wall at some of its stations (an index or slice of the arrays)."""
        return Wall(**{f.name: getattr(self, f.name)[index] for f in dataclasses.fields(self)})


def wall_at(scene, s) -> Wall:
    """The wall of the segments at arc lengths ``s`` [m] from the bottom end (a station
    on a segment boundary takes the lower segment's section). Needs the bores and
    strengths [design] requires (:func:`riser.design.part.check_design`)."""
    s = np.atleast_1d(np.asarray(s, float))
    ends = np.cumsum([seg.length for seg in scene.segments])
    idx = np.clip(np.searchsorted(ends, s, side="left"), 0, len(ends) - 1)
    lts = [scene.line_types[seg.line_type] for seg in scene.segments]

    def column(get):
        return np.array([get(lt) for lt in lts], float)[idx]

    D = column(lambda lt: lt.outer_diameter)
    d = column(lambda lt: lt.inner_diameter or 0.0)
    inertia = math.pi / 64.0 * (D ** 4 - d ** 4)
    return Wall(outer_diameter=D, inner_diameter=d,
                yield_strength=column(lambda lt: lt.yield_strength or np.nan),
                tensile_strength=column(lambda lt: lt.tensile_strength or np.nan),
                youngs_modulus=column(lambda lt: lt.bending_stiffness) / inertia,
                contents_density=column(lambda lt: lt.contents_density))


def pressures(scene, wall: Wall, y, y_top: float,
              top_pressure: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(p_i, p_e) [Pa, gauge] at heights ``y`` [m] with the hang-off at ``y_top`` [m];
    ``top_pressure`` [Pa] the contents' at the hang-off (default the design's,
    :meth:`riser.design.part.Design.top_pressure`)."""
    y = np.asarray(y, float)
    g = scene.gravity
    if top_pressure is None:
        top_pressure = scene.design.top_pressure(scene)
    p_e = scene.water_density * g * (scene.water_depth - y)
    p_i = top_pressure + wall.contents_density * g * (y_top - y)
    return p_i, p_e


def wall_tension(scene, wall: Wall, tension, p_i, p_e) -> np.ndarray:
    """T_w [N] from the effective tension [N] and the pressures [Pa] (module docstring;
    the contents' mass per length mu = rho_c pi d^2 / 4 of the wall's bore)."""
    flux = 0.0
    if scene.internal_flow is not None:
        mu = wall.contents_density * math.pi / 4.0 * wall.inner_diameter ** 2
        flux = mu * scene.internal_flow.speed ** 2
    return np.asarray(tension, float) + flux + p_i * wall.bore_area - p_e * wall.outer_area


def lame(wall: Wall, p_i, p_e, r) -> tuple[np.ndarray, np.ndarray]:
    """(sigma_h, sigma_r) [Pa] at radius ``r`` [m] of the thick wall (Lame)."""
    ri2, ro2 = (0.5 * wall.inner_diameter) ** 2, (0.5 * wall.outer_diameter) ** 2
    mean = (p_i * ri2 - p_e * ro2) / (ro2 - ri2)
    ring = (p_i - p_e) * ri2 * ro2 / ((ro2 - ri2) * np.asarray(r, float) ** 2)
    return mean + ring, mean - ring


def von_mises(sa, sh, sr) -> np.ndarray:
    """sigma_vm [Pa] of the principal stresses (axial, hoop, radial) [Pa]."""
    return np.sqrt(0.5 * ((sa - sh) ** 2 + (sh - sr) ** 2 + (sr - sa) ** 2))


@dataclass(frozen=True)
class Stresses:
    """Stresses along the line (arrays (n,) [Pa]): ``axial`` T_w / A_s, ``bending`` the
    largest bending stress M r_o / I, ``hoop`` and ``radial`` at the inner surface (the
    larger hoop stress under a net internal pressure), ``von_mises`` the largest over the
    section; ``wall_tension`` [N]."""

    wall_tension: np.ndarray
    axial: np.ndarray
    bending: np.ndarray
    hoop: np.ndarray
    radial: np.ndarray
    von_mises: np.ndarray


def stresses(wall: Wall, wall_tension_n, moment, p_i, p_e) -> Stresses:
    """The stresses of :class:`Stresses` from the wall tension [N], the bending moment's
    magnitude [N m] and the pressures [Pa] (arrays of one shape; the largest von Mises
    over the four extreme fibres, see the module docstring)."""
    m = np.abs(np.asarray(moment, float))
    axial = np.asarray(wall_tension_n, float) / wall.area
    worst = np.zeros_like(axial)
    for r in (0.5 * wall.inner_diameter, 0.5 * wall.outer_diameter):
        sh, sr = lame(wall, p_i, p_e, r)
        sb = m * r / wall.inertia
        for sign in (1.0, -1.0):
            worst = np.maximum(worst, von_mises(axial + sign * sb, sh, sr))
    sh_i, sr_i = lame(wall, p_i, p_e, 0.5 * wall.inner_diameter)
    return Stresses(wall_tension=np.asarray(wall_tension_n, float), axial=axial,
                    bending=m * 0.5 * wall.outer_diameter / wall.inertia, hoop=sh_i,
                    radial=sr_i, von_mises=worst)


def fibre_stress(wall: Wall, wall_tension_n, moment_in, moment_out, angles) -> np.ndarray:
    """Axial stress [Pa] at the outer fibre at ``angles`` [rad] (p,) around the section
    (module docstring): arrays (..., n) of the wall tension [N] and the two moment
    components [N m] give (..., n, p)."""
    r = 0.5 * wall.outer_diameter
    c, s = np.cos(angles), np.sin(angles)
    bend = -(r / wall.inertia)[..., None] * (np.asarray(moment_in)[..., None] * c
                                             + np.asarray(moment_out)[..., None] * s)
    return (np.asarray(wall_tension_n) / wall.area)[..., None] + bend

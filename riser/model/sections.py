"""Derived section properties per segment, computed once and read by both solvers.

Only *inputs* are derived here (stiffness, weight, drag and added-mass coefficients);
each solver implements its own force laws and equations, so a dual-method check does
not share the physics it is meant to verify.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .scene import Scene


@dataclass(frozen=True)
class SegmentProperties:
    """Properties of one segment, all per unit length of unstretched line.

    Attributes
    ----------
    s_start, s_end : arc length of the segment ends from the bottom end [m].
    EA : axial stiffness [N]; EI : bending stiffness [N m2].
    BA : internal axial damping [N s]: the axial force gains BA d(eps)/dt, eps the axial
        strain (Kelvin-Voigt, MoorDyn's BA); 0 none.
    mass : structural + contents mass [kg/m] (no added mass).
    rotary_inertia : polar mass moment of inertia per length of the pipe wall [kg m].
    weight : submerged weight w [N/m], positive downwards (negative = buoyant).
    drag_normal_coef : 0.5 rho D C_Dn [kg/m2]; normal drag force per length is
        drag_normal_coef * |u_n| u_n for the relative normal velocity u_n.
    drag_tangential_coef : 0.5 rho pi D C_Dt [kg/m2] (Wang et al. eq. (4): uses the perimeter).
    added_mass : C_a rho pi D^2 / 4 [kg/m], acting normal to the pipe axis.
    fluid_mass : rho pi D^2 / 4 [kg/m], the water of the hydrodynamic section: the
        Froude-Krylov coefficient of the fluid inertia in waves (the added mass is C_a
        times it).
    """

    s_start: float
    s_end: float
    EA: float
    EI: float
    mass: float
    rotary_inertia: float
    weight: float
    drag_normal_coef: float
    drag_tangential_coef: float
    added_mass: float
    fluid_mass: float
    BA: float = 0.0

    @property
    def length(self) -> float:
        return self.s_end - self.s_start


def segment_properties(scene: Scene) -> list[SegmentProperties]:
    """Section properties of every segment of ``scene``, bottom first.

    Submerged weight w = (m + m_contents) g - rho_w g pi D^2 / 4 - buoyancy, where the
    displaced volume uses the line type's outer diameter D. The line type's
    ``submerged_weight`` (a datasheet's weight in water) replaces m g - rho_w g pi D^2 / 4;
    the segment's ``submerged_weight`` replaces the whole sum; ``weight_scale`` multiplies
    the result. Drag and added mass use the hydrodynamic diameter: the segment's, else the
    line type's ``hydro_diameter``, else D. A section given without its bore (inner
    diameter unknown) has its rotary inertia taken as a solid round section's.
    """
    g = scene.gravity
    rho = scene.water_density
    out: list[SegmentProperties] = []
    s0 = 0.0
    for seg in scene.segments:
        lt = scene.line_types[seg.line_type]
        D = lt.outer_diameter
        d = lt.inner_diameter if lt.inner_diameter is not None else 0.0
        contents = lt.contents_density * math.pi / 4.0 * d * d
        mass = lt.mass_per_length + contents
        if seg.submerged_weight is not None:
            w = seg.submerged_weight
        else:
            empty = (lt.submerged_weight if lt.submerged_weight is not None else
                     lt.mass_per_length * g - rho * g * math.pi / 4.0 * D * D)
            w = empty + contents * g - seg.buoyancy
        w *= seg.weight_scale
        Dh = seg.hydro_diameter or lt.hydro_diameter or D
        # polar moment of the wall per length: m_wall (D^2 + d^2) / 8
        rot = lt.mass_per_length * (D * D + d * d) / 8.0
        out.append(SegmentProperties(
            s_start=s0, s_end=s0 + seg.length, EA=lt.axial_stiffness,
            EI=lt.bending_stiffness, mass=mass, rotary_inertia=rot, weight=w,
            drag_normal_coef=0.5 * rho * Dh * lt.drag_normal,
            drag_tangential_coef=0.5 * rho * math.pi * Dh * lt.drag_tangential,
            added_mass=lt.added_mass * rho * math.pi / 4.0 * Dh * Dh,
            fluid_mass=rho * math.pi / 4.0 * Dh * Dh, BA=lt.axial_damping,
        ))
        s0 += seg.length
    return out


def segment_index(scene: Scene, s, lengths=None):
    """Index of the segment holding each arc length ``s`` [m] from the bottom end (a
    station on a boundary takes the lower segment; ``lengths``: the segment lengths as
    solved, default the scene's: a touchdown form's first segment is its suspended part)."""
    ends = np.cumsum(lengths if lengths is not None else [g.length for g in scene.segments])
    return np.clip(np.searchsorted(ends, np.asarray(s, float), side="left"), 0,
                   len(ends) - 1)


#: Young's modulus [Pa] and wall density [kg/m3] ranges in which a line type with a bore
#: is recognised as steel without a ``yield_strength`` (carbon and low-alloy steels: E
#: 190-215 GPa, density 7,750-7,900; titanium, 110 GPa and 4,500, and aluminium, 70 GPa and
#: 2,700, fall outside)
STEEL_MODULUS = (1.9e11, 2.2e11)
STEEL_DENSITY = (7.6e3, 8.1e3)
#: the SMYS [Pa] assumed for steel recognised without ``yield_strength``: API 5L X65
#: (448 MPa), the usual grade of steel risers; a line type's yield_strength replaces it
DEFAULT_STEEL_SMYS = 4.48e8
#: E [Pa] assumed for a line type with ``yield_strength`` but no bore to derive E from EI
STEEL_YOUNGS_MODULUS = 2.07e11


@dataclass(frozen=True)
class BendingLimit:
    """How far a line type may bend: ``strain`` the elastic limit of the bending strain
    (OD/2) kappa [-] of a steel wall, SMYS / E (None: not steel), with the ``E`` [Pa] and
    ``smys`` [Pa] used and ``basis``, a phrase saying where they come from; ``radius`` the
    ``minimum_bend_radius`` [m] (None: not set)."""

    strain: float | None
    E: float | None
    smys: float | None
    basis: str
    radius: float | None

    def strain_radius(self, outer_diameter: float) -> float | None:
        """The bend radius [m] at which the wall reaches the elastic limit, (OD/2) / strain."""
        return None if self.strain is None else 0.5 * outer_diameter / self.strain


def wall_modulus(lt) -> float | None:
    """Young's modulus [Pa] of a line type's wall derived from its section, EI / I with I =
    pi (D^4 - d^4) / 64 (None without a bore: the wall is unknown)."""
    d = lt.inner_diameter
    if d is None:
        return None
    D = lt.outer_diameter
    return lt.bending_stiffness / (math.pi * (D ** 4 - d ** 4) / 64.0)


def bending_limit(lt) -> BendingLimit:
    """The bending limits of line type ``lt`` (see :class:`BendingLimit`). Steel is a line
    type with ``yield_strength`` (E from EI and the wall, else
    :data:`STEEL_YOUNGS_MODULUS` assumed) or a bore whose wall has E and density in
    :data:`STEEL_MODULUS` and :data:`STEEL_DENSITY` (then SMYS :data:`DEFAULT_STEEL_SMYS`
    assumed)."""
    E = wall_modulus(lt)
    fy = lt.yield_strength
    radius = lt.minimum_bend_radius
    if fy is not None:
        if E is None:
            return BendingLimit(fy / STEEL_YOUNGS_MODULUS, STEEL_YOUNGS_MODULUS, fy,
                                f"yield_strength {fy / 1e6:.4g} MPa, E "
                                f"{STEEL_YOUNGS_MODULUS / 1e9:g} GPa assumed (no bore)",
                                radius)
        return BendingLimit(fy / E, E, fy, f"yield_strength {fy / 1e6:.4g} MPa, E "
                            f"{E / 1e9:.4g} GPa from EI and the wall", radius)
    if E is not None and STEEL_MODULUS[0] <= E <= STEEL_MODULUS[1]:
        D, d = lt.outer_diameter, lt.inner_diameter
        rho = lt.mass_per_length / (math.pi * (D * D - d * d) / 4.0)
        if STEEL_DENSITY[0] <= rho <= STEEL_DENSITY[1]:
            return BendingLimit(DEFAULT_STEEL_SMYS / E, E, DEFAULT_STEEL_SMYS,
                                f"steel recognised (E {E / 1e9:.4g} GPa from EI and the "
                                f"wall, density {rho:.4g} kg/m3): SMYS "
                                f"{DEFAULT_STEEL_SMYS / 1e6:g} MPa (API 5L X65) assumed, "
                                "set yield_strength", radius)
    return BendingLimit(None, E, None, "", radius)

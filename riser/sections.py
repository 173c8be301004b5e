"""Derived section properties per segment, computed once and read by both solvers.

Only *inputs* are derived here (stiffness, weight, drag and added-mass coefficients);
each solver implements its own force laws and equations, so a dual-method check does
not share the physics it is meant to verify.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .scene import Scene


@dataclass(frozen=True)
class SegmentProperties:
    """Properties of one segment, all per unit length of unstretched line.

    Attributes
    ----------
    s_start, s_end : arc length of the segment ends from the bottom end [m].
    EA : axial stiffness [N]; EI : bending stiffness [N m2].
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
            fluid_mass=rho * math.pi / 4.0 * Dh * Dh,
        ))
        s0 += seg.length
    return out

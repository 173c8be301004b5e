"""Point attachments on a line (table ``[[attachments]]``): clump weights, discrete buoys
and floats, as MoorDyn's points hold them (mass, displaced volume, C_D A, C_a).

An attachment at the unstretched arc length ``s`` [m] from the bottom end exerts on the
line the point force (SI; x towards the hang-off, y up)

    f = (0, (rho V - m) g)  +  1/2 rho (C_D A) |u| u,

u the current's velocity relative to the point (statics: the current there), and in
dynamics adds its mass m and its added mass C_a rho V (isotropic, MoorDyn's point) to the
line's inertia there. The line's internal force jumps across it by -f (the BVP's jump
conditions; the VFIFE's nodal load on the node at s).
"""

from __future__ import annotations

from dataclasses import dataclass

from .ends import FixedEnds
from ..spec import Part, check_fields, spec

#: the largest mass of an attachment [kg] and its largest displaced volume [m3]
MAX_MASS = 1.0e7
MAX_VOLUME = 1.0e4


@dataclass(frozen=True)
class Attachment(Part):
    """One point attachment (a clump weight: mass > rho V; a buoy: rho V > mass)."""

    s: float = spec(ge=0.0, unit="m", also="<= the line's length",
                    doc="unstretched arc length from the bottom end")
    mass: float = spec(0.0, ge=0.0, le=MAX_MASS, unit="kg", doc="mass in air")
    volume: float = spec(0.0, ge=0.0, le=MAX_VOLUME, unit="m3", doc="displaced volume")
    drag_area: float = spec(0.0, ge=0.0, le=1.0e4, unit="m2",
                            doc="drag coefficient times area, C_D A (isotropic)")
    added_mass_coefficient: float = spec(0.0, ge=0.0, le=10.0,
                                         doc="C_a: added mass C_a rho V (isotropic)")
    label: str = spec("", "string", doc="free text naming the attachment in reports")

    def __post_init__(self) -> None:
        check_fields(self)

    def net_weight(self, gravity: float, water_density: float) -> float:
        """Weight less buoyancy [N], positive down (a buoy's is negative)."""
        return (self.mass - water_density * self.volume) * gravity

    def drag_coefficient(self, water_density: float) -> float:
        """0.5 rho C_D A [kg/m]: the drag force is this times |u| u."""
        return 0.5 * water_density * self.drag_area

    def added_mass(self, water_density: float) -> float:
        """C_a rho V [kg]."""
        return self.added_mass_coefficient * water_density * self.volume


def check_attachments(scene) -> None:
    """The attachments fit the scene (raises ``scene.error``): each on the line, on a
    fixed-ends planar scene (the weight against a tensioner or a free end's buoyancy is
    checked before solving: :func:`riser.results.validity.check_end_loads`)."""
    atts = scene.attachments
    if isinstance(atts, list):
        object.__setattr__(scene, "attachments", tuple(atts))
        atts = scene.attachments
    if not isinstance(atts, tuple):
        raise scene.error("attachments", f"must be a tuple of Attachment, got "
                          f"{type(atts).__name__}")
    for i, a in enumerate(atts):
        if not isinstance(a, Attachment):
            raise scene.error(f"attachments[{i}]", f"must be an Attachment, got "
                              f"{type(a).__name__}")
    if not atts:
        return
    length = scene.total_length
    e = scene.ends
    free = isinstance(e, FixedEnds) and e.free_anchor
    for i, a in enumerate(atts):
        if not (0.0 < a.s < length or (a.s == 0.0 and free)):
            raise scene.error(f"attachments[{i}].s", f"must be inside the line, > 0 and < "
                              f"its length {length:g} m (0 only at a free anchor end), got "
                              f"{a.s:g}")
    if not isinstance(e, FixedEnds):
        raise scene.error("attachments", f"need fixed ends (anchor + hang_off); the "
                          f"'{e.kind}' form has its touchdown on a rigid seabed")
    far = scene.out_of_plane()
    if far is not None:
        raise scene.error("attachments", f"need a planar scene ({far[1]}, {far[0]}): the "
                          "3D rod and the 3D kernels carry no point loads")

"""OrcaFlex's units systems, as factors to SI (m, kg, N, s).

``General.UnitsSystem``: ``SI`` is OrcaFlex's m, te, s, kN (not the SI base units: a
mass per length in te/m, a force in kN, a density in te/m3, EI in kN m2); ``User`` takes
``LengthUnits``, ``MassUnits``, ``ForceUnits`` (and ``TimeUnits``, s) and the
acceleration of gravity ``g`` (in its length unit per s2; 9.80665 m/s2 otherwise) from
the file;
another system (``US``) is refused, naming it. Each factor is the
exact definition of the unit (the international foot and pound, the standard gravity in
the pound-force), so every carried number converts exactly up to the last digit of a
float. Temperature units are not read (no carried item has one).
"""

from __future__ import annotations

from dataclasses import dataclass

from .text_file import Model, ModelError, get, number

#: length units -> m
LENGTH = {"m": 1.0, "cm": 0.01, "mm": 0.001, "km": 1000.0, "ft": 0.3048, "in": 0.0254}
#: mass units -> kg (te the metric tonne; lb and lbm the avoirdupois pound)
MASS = {"te": 1000.0, "kg": 1.0, "lbm": 0.45359237, "lb": 0.45359237}
#: force units -> N (lbf with the standard gravity 9.80665 m/s2; kips and kpf 1000 lbf)
FORCE = {"kN": 1000.0, "N": 1.0, "MN": 1.0e6, "lbf": 4.4482216152605,
         "kips": 4448.2216152605, "kpf": 4448.2216152605}
#: the named systems: (length, mass, force)
SYSTEMS = {"si": ("m", "te", "kN")}


#: OrcaFlex's acceleration of gravity in its SI units system [m/s2] (the standard gravity)
GRAVITY = 9.80665


@dataclass(frozen=True)
class Units:
    """The model's units: the factor of each unit to SI, how the file named them, and
    the acceleration of gravity [m/s2] (OrcaFlex's standard one, or a User system's g)."""

    length: float
    mass: float
    force: float
    label: str
    gravity: float = GRAVITY

    @property
    def density(self) -> float:
        """mass / length^3 -> kg/m3 (OrcaFlex's te/m3 in SI)."""
        return self.mass / self.length ** 3

    @property
    def mass_per_length(self) -> float:
        return self.mass / self.length

    @property
    def stiffness_per_area(self) -> float:
        """force / length / length^2 -> N/m/m2 (the seabed's normal stiffness)."""
        return self.force / self.length ** 3

    @property
    def moment(self) -> float:
        """force x length -> N m."""
        return self.force * self.length

    @property
    def ei(self) -> float:
        """force x length^2 -> N m2."""
        return self.force * self.length ** 2


def units_of(model: Model) -> Units:
    """The units of ``model`` (``General.UnitsSystem``; SI when the file gives none, as
    OrcaFlex's default)."""
    general = model.section("General") or {}
    src = model.source
    system = get(general, "UnitsSystem")
    system = "SI" if system is None else str(system)
    if system.lower() in SYSTEMS:
        names = SYSTEMS[system.lower()]
    elif system.lower() == "user":
        names = tuple(str(get(general, k, default=d)) for k, d in
                      (("LengthUnits", "m"), ("MassUnits", "te"), ("ForceUnits", "kN")))
        time = str(get(general, "TimeUnits", default="s"))
        if time != "s":
            raise ModelError(src, "General.TimeUnits", f"{time!r}: only seconds (s) are read")
    else:
        raise ModelError(src, "General.UnitsSystem", f"{system!r}: not an OrcaFlex units "
                         "system this import reads (SI, or User with its units named)")
    for kind, table, name in zip(("LengthUnits", "MassUnits", "ForceUnits"),
                                 (LENGTH, MASS, FORCE), names):
        if name not in table:
            raise ModelError(src, f"General.{kind}", f"{name!r}: not a unit this import "
                             f"reads ({', '.join(table)})")
    g = GRAVITY
    if system.lower() == "user" and get(general, "g") is not None:
        g = number(get(general, "g"), src, "General.g") * LENGTH[names[0]]
        if not 1.0 <= g <= 30.0:
            raise ModelError(src, "General.g", f"must be between 1 and 30 m/s2, got {g:g}")
    return Units(LENGTH[names[0]], MASS[names[1]], FORCE[names[2]],
                 f"{system} ({names[0]}, {names[1]}, {names[2]}, s)", g)

"""The scene: an immutable description of one line and its environment (read from a
file by :mod:`riser.io.scene_file`).

Conventions (SI throughout): x horizontal from the anchor/touchdown towards the
hang-off, y vertical up with the seabed at y = 0 (the surface at y = water_depth),
z out of plane (right-handed); arc length s from the bottom end. Angles are from the
horizontal unless the name says otherwise.

The key set is a contract documented in README.md; every value is checked for type,
finiteness and a plausible range, and every error names the file and the key path.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .errors import SceneError
from .internal_flow import InternalFlow
from .settings import MAX_SEGMENT_LENGTH, AnalyticSettings, BVPSettings, VFIFESettings

# Plausible ranges: wide enough for any real riser, narrow enough to catch unit slips
# (mm instead of m, kN instead of N, GPa instead of Pa). One place for all of them.
LIMITS = {
    "gravity": (1.0, 30.0),               # m/s2
    "water_density": (500.0, 2000.0),     # kg/m3
    "water_depth": (1.0, 12000.0),        # m
    "speed": 10.0,                        # |current| m/s
    "diameter": 5.0,                      # m
    "density": 25000.0,                   # kg/m3 (tungsten is 19300)
    "mass_per_length": 1.0e4,             # kg/m
    "youngs_modulus": (1.0e6, 1.0e13),    # Pa
    "stiffness": 1.0e14,                  # N or N m2
    "length": MAX_SEGMENT_LENGTH,         # m per segment
    "line_load": 1.0e5,                   # N/m
    "tension": 1.0e9,                     # N
    "coordinate": 1.0e5,                  # m
    "seabed_stiffness": 1.0e12,           # N/m2
}


@dataclass(frozen=True)
class LineType:
    """Cross-section and material of a line: a pipe, a cable, a chain, a jumper.

    Attributes: outer_diameter [m], the displacement (buoyancy) diameter; inner_diameter
    [m] (None when the section is given by its properties alone: only contents need it);
    mass_per_length of the line in air, without contents [kg/m]; axial_stiffness EA [N]
    (None when not given: only an inextensible model may omit it); bending_stiffness EI
    [N m2]; torsional_stiffness GJ [N m2]; drag_normal, drag_tangential, added_mass [-];
    contents_density [kg/m3]; hydro_diameter [m], the diameter of drag and added mass
    (None: the outer diameter); submerged_weight [N/m, positive down], the empty line's
    weight in water when given (replaces m g - rho_w g pi D^2 / 4); max_strain [-], the
    axial strain T/EA beyond which a result carries a warning; compression: False for a
    line that cannot carry effective compression (chain, rope, slack cable).
    """

    name: str
    outer_diameter: float
    inner_diameter: float | None
    mass_per_length: float
    axial_stiffness: float | None
    bending_stiffness: float
    torsional_stiffness: float
    drag_normal: float = 1.0
    drag_tangential: float = 0.0
    added_mass: float = 1.0
    contents_density: float = 0.0
    hydro_diameter: float | None = None
    submerged_weight: float | None = None
    max_strain: float = 0.01
    compression: bool = True


@dataclass(frozen=True)
class Segment:
    """A length of one line type, ordered from the bottom end to the hang-off.

    buoyancy: extra uplift of buoyancy modules [N/m]; submerged_weight: override of the
    submerged weight [N/m, positive down]; weight_scale: factor on the submerged weight
    (e.g. -1 for Wang et al.'s buoyancy section w_e = -w_r); hydro_diameter: diameter for
    drag and added mass [m] (None = the line type's outer diameter).
    """

    line_type: str
    length: float
    buoyancy: float = 0.0
    submerged_weight: float | None = None
    weight_scale: float = 1.0
    hydro_diameter: float | None = None
    label: str = ""


@dataclass(frozen=True)
class Current:
    """Current profile: speed [m/s] piecewise linear in height y [m], constant beyond.

    Speeds are signed along ``heading_deg`` (0 = +x, in plane; 90 = +z, out of plane), so a
    current that reverses with height is expressed with speeds of both signs.
    """

    heights: tuple[float, ...]
    speeds: tuple[float, ...]
    heading_deg: float = 0.0

    @property
    def is_planar(self) -> bool:
        """True when the current lies in the x-y plane (heading 0 or 180 deg)."""
        return abs(math.sin(math.radians(self.heading_deg))) < 1e-12

    @property
    def direction(self) -> np.ndarray:
        """Unit vector of the heading in (x, y, z)."""
        h = math.radians(self.heading_deg)
        return np.array([math.cos(h), 0.0, math.sin(h)])

    def speed(self, y: Any) -> np.ndarray:
        """Signed speed [m/s] along the heading at height(s) y [m]."""
        return np.interp(y, self.heights, self.speeds)

    def speed_gradient(self, y: Any) -> np.ndarray:
        """d(speed)/dy [1/s], piecewise constant, zero outside the given heights."""
        h = np.asarray(self.heights)
        v = np.asarray(self.speeds)
        y = np.asarray(y, dtype=float)
        if len(h) < 2:
            return np.zeros_like(y)
        slopes = np.diff(v) / np.diff(h)
        idx = np.clip(np.searchsorted(h, y, side="right") - 1, 0, len(h) - 2)
        out = slopes[idx]
        return np.where((y < h[0]) | (y > h[-1]), 0.0, out)

    @property
    def max_abs_speed(self) -> float:
        return max(abs(v) for v in self.speeds)


@dataclass(frozen=True)
class Seabed:
    """Flat seabed at y = 0: penalty stiffness [N/m per m of line = N/m2], Coulomb friction,
    damping as a fraction of critical for the contact spring (VFIFE only)."""

    stiffness: float
    friction: float = 0.0
    damping: float = 0.0


@dataclass(frozen=True)
class Ends:
    """Boundary conditions; ``kind`` is one of

    - 'tdp_tension': touchdown at the origin with tension ``tdp_tension`` [N], top free;
    - 'hang_off_angle': hang-off height [m] and angle from the horizontal [deg] given
      (``hang_off_angle_deg``; the file may give it from the vertical, converted on
      reading), the first segment's suspended length solved (its length in the file is
      ``segments[0].length``);
    - 'top_tension' (the J-lay form): touchdown at the origin on a rigid seabed (theta = 0,
      M = 0 there); hang-off height [m] and effective tension ``top_tension`` [N] given,
      M = 0 at the hang-off; the first segment's suspended length is solved (its length in
      the file, ``segments[0].length``, is the pipe available: the suspended part plus
      what lies on the seabed); the hang-off x, the angle and the TDP tension are outputs;
    - 'fixed': anchor and hang-off positions (x, y) [m] given.

    The forms other than 'fixed' are the Wang family: inextensible on a rigid seabed by
    default (``Scene.axial_model``, ``Scene.seabed_model``).
    """

    kind: str
    tdp_tension: float | None = None
    hang_off_height: float | None = None
    hang_off_angle_deg: float | None = None
    anchor: tuple[float, float] | None = None
    hang_off: tuple[float, float] | None = None
    top_tension: float | None = None


@dataclass(frozen=True)
class TopMotion:
    """Prescribed hang-off motion along ``axis`` ('x', 'y' or 'z'): harmonic (amplitude
    [m], period [s]: d = A sin(2 pi t / T)) or a time series (times [s], displacements
    [m], linearly interpolated). ``ramp_time`` [s]: the motion is multiplied by the
    half-cosine ramp 0.5 (1 - cos(pi t / t_r)) up to t_r; None (the default) means one
    period of a harmonic motion and no ramp for a time series (which starts where it says);
    0 turns the ramp off (an impulsive start)."""

    axis: str
    amplitude: float = 0.0
    period: float = 0.0
    times: tuple[float, ...] | None = None
    displacements: tuple[float, ...] | None = None
    ramp_time: float | None = None

    @property
    def ramp(self) -> float:
        """The ramp duration applied [s] (see the class docstring)."""
        if self.ramp_time is not None:
            return float(self.ramp_time)
        return float(self.period) if self.times is None else 0.0


@dataclass(frozen=True)
class Dynamics:
    """Dynamic run from the static state: duration and output interval [s].

    damping : mass-proportional damping coefficient [1/s] (structural; the hydrodynamic
        drag is always on in water, see vfife/dynamics.py).
    statistics_start : [s] envelopes and statistics are taken from this time on; None
        means the end of the top motion's ramp (0 without a ramp, or when the ramp is not
        shorter than the run).
    save_states : write every node's position and velocity at the output times
        (``states.npz``).
    """

    duration: float
    output_interval: float
    top_motion: TopMotion | None = None
    damping: float = 0.0
    statistics_start: float | None = None
    save_states: bool = False

    @property
    def statistics_from(self) -> float:
        """The time [s] from which envelopes and statistics are taken."""
        if self.statistics_start is not None:
            return float(self.statistics_start)
        ramp = self.top_motion.ramp if self.top_motion is not None else 0.0
        return ramp if ramp < self.duration else 0.0


@dataclass(frozen=True)
class Scene:
    """A validated riser scene. ``source`` is the file it came from (for messages)."""

    name: str
    line_types: dict[str, LineType]
    segments: tuple[Segment, ...]
    ends: Ends
    title: str = ""
    provenance: str = ""
    gravity: float = 9.81
    water_density: float = 1025.0
    water_depth: float | None = None
    current: Current | None = None
    seabed: Seabed | None = None
    dynamics: Dynamics | None = None
    internal_flow: InternalFlow | None = None
    bvp: BVPSettings = field(default_factory=BVPSettings)
    analytic: AnalyticSettings = field(default_factory=AnalyticSettings)
    vfife: VFIFESettings = field(default_factory=VFIFESettings)
    model: dict = field(default_factory=dict)
    source: str = "<scene>"

    @property
    def axial_model(self) -> str:
        """'extensible' (strain T/EA) or 'inextensible' (the Wang limit): the [model] axial
        key, else 'inextensible' for the Wang end forms and 'extensible' for fixed ends."""
        return self.model.get("axial", "extensible" if self.ends.kind == "fixed"
                              else "inextensible")

    @property
    def seabed_model(self) -> str | None:
        """'elastic' (unilateral Winkler foundation of [seabed] stiffness), 'rigid' (a
        touchdown point with theta = M = 0 on y = 0: the Wang limit), or None (fixed ends
        without a [seabed]). The Wang end forms are rigid by construction."""
        if self.ends.kind != "fixed":
            return "rigid"
        if self.seabed is None:
            return None
        return self.model.get("seabed", "elastic")

    def continuum_model(self) -> dict:
        """The continuum model of the scene, as a result reports it: ``axial``,
        ``seabed`` and, on an elastic seabed, ``seabed_stiffness`` [N/m2]."""
        out = {"axial": self.axial_model, "seabed": self.seabed_model}
        if self.seabed_model == "elastic":
            out["seabed_stiffness"] = self.seabed.stiffness
        return out

    @property
    def total_length(self) -> float:
        """Unstretched length of the whole line [m]."""
        return float(sum(seg.length for seg in self.segments))

    @property
    def is_planar(self) -> bool:
        """True when nothing drives out-of-plane motion."""
        return (self.current is None or self.current.is_planar) and (
            self.dynamics is None or self.dynamics.top_motion is None
            or self.dynamics.top_motion.axis != "z")

    def replace(self, **changes: Any) -> "Scene":
        """A copy with some fields changed (Scene is immutable)."""
        return dataclasses.replace(self, **changes)


def require_axial_stiffness(scene: Scene, message: str) -> None:
    """Raise :class:`SceneError` naming the first line type without EA (``message`` says
    why it is needed)."""
    for name, lt in scene.line_types.items():
        if lt.axial_stiffness is None:
            raise SceneError(scene.source, f"line_types.{name}.axial_stiffness", message)

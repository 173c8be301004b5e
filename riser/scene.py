"""Scene files: TOML -> validated, immutable :class:`Scene`.

Conventions (SI throughout): x horizontal from the anchor/touchdown towards the
hang-off, y vertical up with the seabed at y = 0 (the surface at y = water_depth),
z out of plane (right-handed); arc length s from the bottom end. Angles are from the
horizontal unless the name says otherwise.

The key set is a contract documented in README.md; every value is checked for type,
finiteness and a plausible range, and every error names the file and the key path.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .errors import SceneError
from .tomlread import Table

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
    "length": 5.0e4,                      # m per segment
    "line_load": 1.0e5,                   # N/m
    "tension": 1.0e9,                     # N
    "coordinate": 1.0e5,                  # m
    "seabed_stiffness": 1.0e12,           # N/m2
}


@dataclass(frozen=True)
class LineType:
    """Cross-section and material of a pipe.

    Attributes: outer/inner diameter [m]; mass_per_length of the pipe wall [kg/m];
    axial_stiffness EA [N] (None when not given: only an inextensible model may omit it);
    bending_stiffness EI [N m2]; torsional_stiffness GJ [N m2];
    drag_normal, drag_tangential, added_mass [-]; contents_density [kg/m3].
    """

    name: str
    outer_diameter: float
    inner_diameter: float
    mass_per_length: float
    axial_stiffness: float | None
    bending_stiffness: float
    torsional_stiffness: float
    drag_normal: float = 1.0
    drag_tangential: float = 0.0
    added_mass: float = 1.0
    contents_density: float = 0.0


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
    - 'hang_off_angle': hang-off height [m] and angle from horizontal [deg] given;
    - 'fixed': anchor and hang-off positions (x, y) [m] given.
    """

    kind: str
    tdp_tension: float | None = None
    hang_off_height: float | None = None
    hang_off_angle_deg: float | None = None
    anchor: tuple[float, float] | None = None
    hang_off: tuple[float, float] | None = None


@dataclass(frozen=True)
class TopMotion:
    """Prescribed hang-off motion along ``axis``: harmonic (amplitude [m], period [s]) or a
    time series (times [s], displacements [m], linearly interpolated)."""

    axis: str
    amplitude: float = 0.0
    period: float = 0.0
    times: tuple[float, ...] | None = None
    displacements: tuple[float, ...] | None = None
    ramp_time: float = 0.0

    def displacement(self, t: float) -> float:
        """Displacement [m] at time t [s] (smooth ramp over ``ramp_time`` if set)."""
        if self.times is not None:
            d = float(np.interp(t, self.times, self.displacements))
        else:
            d = self.amplitude * math.sin(2.0 * math.pi * t / self.period)
        if self.ramp_time > 0.0 and t < self.ramp_time:
            d *= 0.5 * (1.0 - math.cos(math.pi * t / self.ramp_time))
        return d


@dataclass(frozen=True)
class Dynamics:
    """Dynamic run from the static state: duration and output interval [s]."""

    duration: float
    output_interval: float
    top_motion: TopMotion | None = None
    damping: float = 0.0          # mass-proportional damping coefficient [1/s]


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
    bvp: dict = field(default_factory=dict)
    vfife: dict = field(default_factory=dict)
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
        import dataclasses
        return dataclasses.replace(self, **changes)


# ---------------------------------------------------------------------- loading
def load_scene(path: str | Path) -> Scene:
    """Read and validate a scene file; raise :class:`SceneError` on any problem."""
    path = Path(path)
    source = path.name
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise SceneError(str(path), "", f"cannot read file ({exc.strerror or exc})") from None
    return parse_scene(text, source)


def parse_scene(text: str, source: str = "<scene>") -> Scene:
    """Parse TOML text into a validated :class:`Scene`."""
    try:
        data = tomllib.loads(text)
    except ValueError as exc:   # TOMLDecodeError, or int() refusing a > 4300-digit integer
        raise SceneError(source, "", f"not valid TOML ({exc})") from None
    return scene_from_dict(data, source)


def scene_from_dict(data: dict, source: str = "<scene>") -> Scene:
    """Validate a parsed scene dictionary (the structure of the TOML file)."""
    root = Table(data, "", source)
    name = root.string("name", pattern=r"[a-z0-9][a-z0-9-]*")
    title = root.string("title", "")
    provenance = root.string("source", "")

    env = root.table("environment") or Table({}, "environment", source)
    gravity = env.number("gravity", 9.81, ge=LIMITS["gravity"][0], le=LIMITS["gravity"][1], unit="m/s2")
    water_density = env.number("water_density", 1025.0, ge=LIMITS["water_density"][0],
                               le=LIMITS["water_density"][1], unit="kg/m3")
    water_depth = env.number("water_depth", None, ge=LIMITS["water_depth"][0],
                             le=LIMITS["water_depth"][1], unit="m")
    cur_t = env.table("current")
    current = _read_current(cur_t) if cur_t is not None else None
    env.finish()

    sb_t = root.table("seabed")
    seabed = None
    if sb_t is not None:
        seabed = Seabed(
            stiffness=sb_t.number("stiffness", gt=0.0, le=LIMITS["seabed_stiffness"], unit="N/m2"),
            friction=sb_t.number("friction", 0.0, ge=0.0, le=5.0),
            damping=sb_t.number("damping", 0.0, ge=0.0, le=10.0),
        )
        sb_t.finish()

    lt_root = root.table("line_types", required=True)
    if not lt_root.data:
        raise SceneError(source, "line_types", "at least one line type is required")
    line_types: dict[str, LineType] = {}
    for lt_name in list(lt_root.data):
        sub = lt_root.table(lt_name)
        line_types[lt_name] = _read_line_type(sub, lt_name)
    lt_root.finish()

    segments = tuple(_read_segment(t, line_types) for t in root.array_of_tables("segments"))

    ends_t = root.table("ends", required=True)
    ends = _read_ends(ends_t)

    dyn_t = root.table("dynamics")
    dynamics = _read_dynamics(dyn_t) if dyn_t is not None else None

    model_t = root.table("model")
    model = _read_model(model_t) if model_t is not None else {}
    bvp_t = root.table("bvp")
    bvp = _read_bvp(bvp_t) if bvp_t is not None else {}
    vf_t = root.table("vfife")
    vfife = _read_vfife(vf_t) if vf_t is not None else {}
    root.finish()

    scene = Scene(name=name, title=title, provenance=provenance, gravity=gravity,
                  water_density=water_density, water_depth=water_depth, current=current,
                  seabed=seabed, line_types=line_types, segments=segments, ends=ends,
                  dynamics=dynamics, bvp=bvp, vfife=vfife, model=model, source=source)
    _check_model(scene)
    _check_geometry(scene)
    return scene


def _read_current(t: Table) -> Current:
    heights = t.numbers("heights", ge=-LIMITS["coordinate"], le=LIMITS["coordinate"], unit="m")
    speeds = t.numbers("speeds", ge=-LIMITS["speed"], le=LIMITS["speed"], unit="m/s")
    heading = t.number("heading_deg", 0.0, ge=-360.0, le=360.0, unit="deg")
    t.finish()
    if len(heights) != len(speeds):
        raise t.error("speeds", f"must have as many entries as heights ({len(heights)}), got {len(speeds)}")
    for i in range(1, len(heights)):
        if not heights[i] > heights[i - 1]:
            raise t.error(f"heights[{i}]", f"must be > heights[{i - 1}] = {heights[i - 1]:g} "
                          f"(strictly increasing), got {heights[i]:g}")
    return Current(heights=heights, speeds=speeds, heading_deg=heading)


def _read_line_type(t: Table, name: str) -> LineType:
    D = t.number("outer_diameter", gt=0.0, le=LIMITS["diameter"], unit="m")
    if t.has("wall_thickness") and t.has("inner_diameter"):
        raise t.error("inner_diameter", "give either wall_thickness or inner_diameter, not both")
    if t.has("inner_diameter"):
        d = t.number("inner_diameter", ge=0.0, lt=D, unit="m")
    else:
        wt = t.number("wall_thickness", gt=0.0, unit="m")
        if wt > D / 2:
            raise t.error("wall_thickness", f"must be <= the radius {D / 2:g} m, got {wt:g}")
        d = D - 2.0 * wt
    area = math.pi / 4.0 * (D * D - d * d)
    inertia = math.pi / 64.0 * (D ** 4 - d ** 4)

    if t.has("density") and t.has("mass_per_length"):
        raise t.error("mass_per_length", "give either density or mass_per_length, not both")
    if t.has("mass_per_length"):
        mass = t.number("mass_per_length", gt=0.0, le=LIMITS["mass_per_length"], unit="kg/m")
    else:
        rho = t.number("density", gt=0.0, le=LIMITS["density"], unit="kg/m3")
        mass = rho * area

    lo, hi = LIMITS["youngs_modulus"]
    E = t.number("youngs_modulus", None, ge=lo, le=hi, unit="Pa")
    smax = LIMITS["stiffness"]
    if E is None and not t.has("bending_stiffness"):
        raise t.error("bending_stiffness", "required when youngs_modulus is not given")
    # axial_stiffness may be missing here: _check_model requires it for an extensible model
    EA = t.number("axial_stiffness", None if E is None else E * area, gt=0.0, le=smax, unit="N")
    EI = t.number("bending_stiffness", None if E is None else E * inertia, gt=0.0, le=smax,
                  unit="N m2")
    poisson = t.number("poisson_ratio", 0.3, ge=0.0, le=0.5)
    G = t.number("shear_modulus", None, gt=0.0, le=hi, unit="Pa")
    if G is not None:
        gj_default = G * 2.0 * inertia
    else:
        # GJ = G * 2I with G = E / (2 (1 + nu)); without E, use EI / (1 + nu).
        gj_default = EI / (1.0 + poisson)
    GJ = t.number("torsional_stiffness", gj_default, gt=0.0, le=smax, unit="N m2")
    lt = LineType(
        name=name, outer_diameter=D, inner_diameter=d, mass_per_length=mass,
        axial_stiffness=EA, bending_stiffness=EI, torsional_stiffness=GJ,
        drag_normal=t.number("drag_normal", 1.0, ge=0.0, le=10.0),
        drag_tangential=t.number("drag_tangential", 0.0, ge=0.0, le=10.0),
        added_mass=t.number("added_mass", 1.0, ge=0.0, le=10.0),
        contents_density=t.number("contents_density", 0.0, ge=0.0, le=LIMITS["density"],
                                  unit="kg/m3"),
    )
    t.finish()
    return lt


def _read_segment(t: Table, line_types: dict[str, LineType]) -> Segment:
    lt = t.string("line_type")
    if lt not in line_types:
        raise t.error("line_type", f"unknown line type {lt!r} (defined: {', '.join(map(repr, line_types))})")
    L = LIMITS["line_load"]
    seg = Segment(
        line_type=lt,
        length=t.number("length", gt=0.0, le=LIMITS["length"], unit="m"),
        buoyancy=t.number("buoyancy", 0.0, ge=-L, le=L, unit="N/m"),
        submerged_weight=t.number("submerged_weight", None, ge=-L, le=L, unit="N/m"),
        weight_scale=t.number("weight_scale", 1.0, ge=-100.0, le=100.0),
        hydro_diameter=t.number("hydro_diameter", None, gt=0.0, le=LIMITS["diameter"], unit="m"),
        label=t.string("label", ""),
    )
    t.finish()
    return seg


_END_FORMS = {
    "tdp_tension": ("tdp_tension",),
    "hang_off_angle": ("hang_off_height", "hang_off_angle_deg"),
    "fixed": ("anchor", "hang_off"),
}


def _read_ends(t: Table) -> Ends:
    present = [kind for kind, keys in _END_FORMS.items() if any(t.has(k) for k in keys)]
    if not present:
        raise t.error("", "give one of: tdp_tension; hang_off_height + hang_off_angle_deg; "
                      "anchor + hang_off")
    if len(present) > 1:
        keys = [k for kind in present for k in _END_FORMS[kind] if t.has(k)]
        raise t.error(keys[-1], f"more than one [ends] form given ({', '.join(keys)}); "
                      "use exactly one")
    kind = present[0]
    C = LIMITS["coordinate"]
    if kind == "tdp_tension":
        ends = Ends(kind, tdp_tension=t.number("tdp_tension", gt=0.0, le=LIMITS["tension"], unit="N"))
    elif kind == "hang_off_angle":
        ends = Ends(kind,
                    hang_off_height=t.number("hang_off_height", gt=0.0, le=C, unit="m"),
                    hang_off_angle_deg=t.number("hang_off_angle_deg", gt=0.0, le=90.0, unit="deg"))
    else:
        anchor = t.numbers("anchor", length=2, ge=-C, le=C, unit="m")
        hang = t.numbers("hang_off", length=2, ge=-C, le=C, unit="m")
        if anchor[1] < 0.0:
            raise t.error("anchor[1]", f"must be >= 0 (the seabed is y = 0), got {anchor[1]:g}")
        if hang[1] <= 0.0:
            raise t.error("hang_off[1]", f"must be > 0 (the hang-off cannot be at or below the "
                          f"seabed y = 0), got {hang[1]:g}")
        if hang[0] <= anchor[0]:
            raise t.error("hang_off[0]", f"must be > anchor[0] = {anchor[0]:g} (x points from "
                          f"the anchor towards the hang-off), got {hang[0]:g}")
        ends = Ends(kind, anchor=anchor, hang_off=hang)
    t.finish()
    return ends


def _read_dynamics(t: Table) -> Dynamics:
    duration = t.number("duration", gt=0.0, le=1.0e6, unit="s")
    interval = t.number("output_interval", min(1.0, duration), gt=0.0, le=duration, unit="s")
    damping = t.number("damping", 0.0, ge=0.0, le=100.0, unit="1/s")
    motion = None
    tm = t.table("top_motion")
    if tm is not None:
        axis = tm.string("axis", choices=("x", "y", "z"))
        ramp = tm.number("ramp_time", 0.0, ge=0.0, le=duration, unit="s")
        if tm.has("times") or tm.has("displacements"):
            times = tm.numbers("times", min_length=2, ge=0.0, le=1.0e6, unit="s")
            disp = tm.numbers("displacements", length=len(times), ge=-1000.0, le=1000.0, unit="m")
            for i in range(1, len(times)):
                if not times[i] > times[i - 1]:
                    raise tm.error(f"times[{i}]", "must be strictly increasing")
            motion = TopMotion(axis=axis, times=times, displacements=disp, ramp_time=ramp)
        else:
            motion = TopMotion(axis=axis,
                               amplitude=tm.number("amplitude", ge=0.0, le=1000.0, unit="m"),
                               period=tm.number("period", gt=0.0, le=1.0e4, unit="s"),
                               ramp_time=ramp)
        tm.finish()
    t.finish()
    return Dynamics(duration=duration, output_interval=interval, top_motion=motion, damping=damping)


def _read_bvp(t: Table) -> dict:
    out = {
        "tolerance": t.number("tolerance", 1.0e-6, ge=1.0e-12, le=1.0e-1),
        "max_nodes": t.integer("max_nodes", 30000, ge=100, le=1_000_000),
        "initial_nodes": t.integer("initial_nodes", 400, ge=20, le=100_000),
    }
    t.finish()
    return out


MODEL_CHOICES = {"axial": ("extensible", "inextensible"), "seabed": ("elastic", "rigid")}


def _read_model(t: Table) -> dict:
    out = {key: t.string(key, None, choices=choices) for key, choices in MODEL_CHOICES.items()}
    t.finish()
    return {k: v for k, v in out.items() if v is not None}


def _check_model(scene: Scene) -> None:
    """The [model] choices fit the end form, the seabed and the line types."""
    src = scene.source
    wang = scene.ends.kind != "fixed"
    if scene.model.get("seabed") == "elastic" and wang:
        raise SceneError(src, "model.seabed", f"'elastic' needs fixed ends (anchor + hang_off); "
                         f"the '{scene.ends.kind}' form puts the touchdown on a rigid seabed "
                         "(use 'rigid' or omit the key)")
    if "seabed" in scene.model and not wang and scene.seabed is None:
        raise SceneError(src, "model.seabed", "needs a [seabed] table (with its stiffness)")
    if scene.axial_model == "extensible":
        why = "the default for fixed ends" if "axial" not in scene.model else "[model] axial"
        require_axial_stiffness(scene, f"required for the extensible model ({why}): give it "
                                "[N] or youngs_modulus, or set [model] axial = \"inextensible\"")


def require_axial_stiffness(scene: Scene, message: str) -> None:
    """Raise :class:`SceneError` naming the first line type without EA (``message`` says
    why it is needed)."""
    for name, lt in scene.line_types.items():
        if lt.axial_stiffness is None:
            raise SceneError(scene.source, f"line_types.{name}.axial_stiffness", message)


def _read_vfife(t: Table) -> dict:
    out = {
        "element_length": t.number("element_length", 1.0, gt=0.0, le=1000.0, unit="m"),
        "time_step_safety": t.number("time_step_safety", 0.8, gt=0.0, le=1.0),
        "static_tolerance": t.number("static_tolerance", 1.0e-3, gt=0.0, le=1.0),
        "max_steps": t.integer("max_steps", 5_000_000, ge=1, le=10**9),
        "coarse_element_length": t.number("coarse_element_length", 10.0, gt=0.0, le=1000.0,
                                          unit="m"),
        "rotational_inertia_scale": t.number("rotational_inertia_scale", 4.0, ge=1.0, le=1.0e6),
        "seabed_length": t.number("seabed_length", None, ge=0.0, le=LIMITS["length"], unit="m"),
        # dynamics: factor on the physical rotational inertia (1 = physical; the VFIFE
        # default 4 makes the step axial-limited, see vfife/dynamics.py)
        "rotational_inertia_scale_dynamics": t.number("rotational_inertia_scale_dynamics", 4.0,
                                                      gt=0.0, le=1.0e6),
        # dynamics: fixed time step [s] instead of safety x critical step (expert use)
        "time_step": t.number("time_step", None, gt=0.0, le=10.0, unit="s"),
        # statics: fixed relaxation step [s] instead of safety x critical step (expert use;
        # above the critical step the relaxation diverges and says so)
        "static_time_step": t.number("static_time_step", None, gt=0.0, le=10.0, unit="s"),
        # ends whose rotation is clamped (default: both pinned, moment-free)
        "clamped_ends": t.strings("clamped_ends", None, choices=("bottom", "top")),
    }
    t.finish()
    return {k: v for k, v in out.items() if v is not None}


def _check_geometry(scene: Scene) -> None:
    """Physically impossible but well-formed scenes are rejected before solving."""
    e = scene.ends
    src = scene.source
    if e.kind == "fixed":
        chord = math.hypot(e.hang_off[0] - e.anchor[0], e.hang_off[1] - e.anchor[1])
        # an extensible line no longer than the chord is taut (it stretches); only the
        # inextensible model cannot reach
        if scene.axial_model == "inextensible" and scene.total_length <= chord:
            raise SceneError(src, "segments", f"line length {scene.total_length:g} m is not longer "
                             f"than the distance {chord:g} m between anchor and hang_off: too "
                             "short for an inextensible line ([model] axial = \"extensible\" "
                             "lets it stretch)")
        if scene.water_depth is not None and e.hang_off[1] > scene.water_depth:
            raise SceneError(src, "ends.hang_off[1]", f"must be <= water_depth "
                             f"{scene.water_depth:g} m (the model is fully submerged), "
                             f"got {e.hang_off[1]:g}")
    if e.kind == "hang_off_angle":
        if scene.water_depth is not None and e.hang_off_height > scene.water_depth:
            raise SceneError(src, "ends.hang_off_height", f"must be <= water_depth "
                             f"{scene.water_depth:g} m, got {e.hang_off_height:g}")
        if scene.total_length <= e.hang_off_height:
            raise SceneError(src, "segments", f"line length {scene.total_length:g} m cannot reach "
                             f"the hang-off height {e.hang_off_height:g} m")

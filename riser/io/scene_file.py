"""Reading a scene file: TOML -> validated :class:`riser.scene.Scene`.

Every check raises :class:`~riser.errors.SceneError` naming the file, the key path and the
allowed range (one line on the command line). Well-formed but physically impossible scenes
(a line too short to reach its hang-off, an inextensible line shorter than its chord) are
refused here, before any solver runs.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

from ..errors import SceneError
from ..internal_flow import check_internal_flow, read_internal_flow
from ..scene import (
    LIMITS,
    Current,
    Dynamics,
    Ends,
    LineType,
    Scene,
    Seabed,
    Segment,
    TopMotion,
    require_axial_stiffness,
)
from ..settings import AnalyticSettings, BVPSettings, VFIFESettings
from .toml_table import Table


# ---------------------------------------------------------------------- loading
def load_scene(path: str | Path) -> Scene:
    """Read and validate a scene file, UTF-8 TOML text of at most 1 MB (a UTF-8 byte-order
    mark is accepted); raise :class:`SceneError` on any problem, including a file that is
    not one: missing, a directory or device, unreadable, binary, UTF-16 or Latin-1."""
    path = Path(path)
    where, limit = str(path), 1_000_000
    try:
        if path.is_dir():
            raise SceneError(where, "", "is a directory, not a scene file (a .toml file)")
        if path.exists() and not path.is_file():
            raise SceneError(where, "", "is not a regular file (a scene is a .toml file)")
        with path.open("rb") as fh:
            data = fh.read(limit + 1)
    except OSError as exc:
        raise SceneError(where, "", f"cannot read file ({exc.strerror or exc})") from None
    kinds = {b"\x89PNG": "a PNG image", b"PK\x03\x04": "a zip archive", b"%PDF": "a PDF file",
             b"\x1f\x8b": "a gzip archive", b"\x7fELF": "an executable", b"\xff\xd8\xff":
             "a JPEG image", b"\xff\xfe\x00\x00": "UTF-32 text", b"\x00\x00\xfe\xff":
             "UTF-32 text", b"\xff\xfe": "UTF-16 text", b"\xfe\xff": "UTF-16 text"}
    kind = next((k for m, k in kinds.items() if data.startswith(m)), None)
    if kind is None and b"\x00" in data:
        kind = "binary data or UTF-16 text (it holds NUL bytes)"
    if kind is not None:
        raise SceneError(where, "", f"is {kind}, not a scene: a scene is TOML text in UTF-8"
                         + (" (save it as UTF-8)" if "text" in kind else ""))
    if len(data) > limit:
        raise SceneError(where, "", f"is larger than {limit // 1_000_000} MB, too large for "
                         "a scene file (TOML text of a few kB)")
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[:exc.start].count(b"\n") + 1
        raise SceneError(where, "", f"is not UTF-8 text (byte 0x{data[exc.start]:02x} on line "
                         f"{line}; Latin-1 or Windows-1252?): save it as UTF-8") from None
    return parse_scene(text, path.name)


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
    flow_t = root.table("internal_flow")
    flow = read_internal_flow(flow_t) if flow_t is not None else None

    model_t = root.table("model")
    model = _read_model(model_t) if model_t is not None else {}
    bvp = BVPSettings.read(root.table("bvp"))
    analytic = AnalyticSettings.read(root.table("analytic"))
    vfife = VFIFESettings.read(root.table("vfife"))
    root.finish()

    scene = Scene(name=name, title=title, provenance=provenance, gravity=gravity,
                  water_density=water_density, water_depth=water_depth, current=current,
                  seabed=seabed, line_types=line_types, segments=segments, ends=ends,
                  dynamics=dynamics, internal_flow=flow, bvp=bvp, analytic=analytic, vfife=vfife,
                  model=model, source=source)
    if flow is not None:
        check_internal_flow(scene)
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
    """A line type from its section properties (OD, mass per length, EA, EI: a cable, a
    chain, a flexible pipe) or from its wall and material (a steel pipe)."""
    D = t.number("outer_diameter", gt=0.0, le=LIMITS["diameter"], unit="m")
    d = _read_bore(t, D)
    wall = "wall_thickness or inner_diameter (the wall's area)"
    area = 0.0 if d is None else math.pi / 4.0 * (D * D - d * d)
    inertia = 0.0 if d is None else math.pi / 64.0 * (D ** 4 - d ** 4)
    if t.has("density") and t.has("mass_per_length"):
        raise t.error("mass_per_length", "give either density or mass_per_length, not both")
    if d is None and t.has("density"):
        raise t.error("density", f"needs {wall}; give mass_per_length [kg/m] instead")
    if d is None and not t.has("mass_per_length"):
        raise t.error("mass_per_length", f"required: give it [kg/m] (with axial_stiffness and "
                      f"bending_stiffness), or {wall} with density")
    if t.has("mass_per_length"):
        mass = t.number("mass_per_length", gt=0.0, le=LIMITS["mass_per_length"], unit="kg/m")
    else:
        rho = t.number("density", gt=0.0, le=LIMITS["density"], unit="kg/m3")
        mass = rho * area

    lo, hi = LIMITS["youngs_modulus"]
    E = t.number("youngs_modulus", None, ge=lo, le=hi, unit="Pa")
    if E is not None and d is None:
        raise t.error("youngs_modulus", f"needs {wall}; give axial_stiffness [N] and "
                      "bending_stiffness [N m2] instead")
    smax = LIMITS["stiffness"]
    if E is None and not t.has("bending_stiffness"):
        raise t.error("bending_stiffness", "required when youngs_modulus is not given")
    # axial_stiffness may be missing here: _check_model requires it for an extensible model
    EA = t.number("axial_stiffness", None if E is None else E * area, gt=0.0, le=smax, unit="N")
    EI = t.number("bending_stiffness", None if E is None else E * inertia, gt=0.0, le=smax,
                  unit="N m2")
    poisson = t.number("poisson_ratio", 0.3, ge=0.0, le=0.5)
    G = t.number("shear_modulus", None, gt=0.0, le=hi, unit="Pa")
    if G is not None and d is None:
        raise t.error("shear_modulus", f"needs {wall}; give torsional_stiffness [N m2] instead")
    # GJ = G * 2I; with G = E / (2 (1 + nu)) that is EI / (1 + nu)
    gj_default = G * 2.0 * inertia if G is not None else EI / (1.0 + poisson)
    GJ = t.number("torsional_stiffness", gj_default, gt=0.0, le=smax, unit="N m2")
    contents = t.number("contents_density", 0.0, ge=0.0, le=LIMITS["density"], unit="kg/m3")
    if contents > 0.0 and d is None:
        raise t.error("contents_density", "needs inner_diameter or wall_thickness (the bore "
                      "that holds the contents)")
    L = LIMITS["line_load"]
    lt = LineType(
        name=name, outer_diameter=D, inner_diameter=d, mass_per_length=mass,
        axial_stiffness=EA, bending_stiffness=EI, torsional_stiffness=GJ,
        drag_normal=t.number("drag_normal", 1.0, ge=0.0, le=10.0),
        drag_tangential=t.number("drag_tangential", 0.0, ge=0.0, le=10.0),
        added_mass=t.number("added_mass", 1.0, ge=0.0, le=10.0),
        contents_density=contents,
        hydro_diameter=t.number("hydro_diameter", None, gt=0.0, le=LIMITS["diameter"], unit="m"),
        submerged_weight=t.number("submerged_weight", None, ge=-L, le=L, unit="N/m"),
        max_strain=t.number("max_strain", 0.01, gt=0.0, le=1.0),
        compression=t.boolean("compression", True),
    )
    t.finish()
    return lt


def _read_bore(t: Table, D: float) -> float | None:
    """The inner diameter [m] from wall_thickness or inner_diameter; None when neither is
    given (a section given by its properties)."""
    if t.has("wall_thickness") and t.has("inner_diameter"):
        raise t.error("inner_diameter", "give either wall_thickness or inner_diameter, not both")
    if t.has("inner_diameter"):
        return t.number("inner_diameter", ge=0.0, lt=D, unit="m")
    if t.has("wall_thickness"):
        wt = t.number("wall_thickness", gt=0.0, unit="m")
        if wt > D / 2:
            raise t.error("wall_thickness", f"must be <= the radius {D / 2:g} m, got {wt:g}")
        return D - 2.0 * wt
    return None


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


#: the hang-off angle of form (b), by the reference it is measured from; the key must
#: say which (a riser's hang-off angle is usually quoted from the vertical)
ANGLE_KEYS = ("hang_off_angle_from_horizontal_deg", "hang_off_angle_from_vertical_deg")

#: the keys of each form; hang_off_height belongs to two: without top_tension it is form
#: (b)'s (alone, it asks for its angle)
_END_FORMS = {
    "tdp_tension": ("tdp_tension",),
    "hang_off_angle": ("hang_off_height", *ANGLE_KEYS),
    "top_tension": ("hang_off_height", "top_tension"),
    "fixed": ("anchor", "hang_off"),
}


def _read_ends(t: Table) -> Ends:
    if t.has("hang_off_angle_deg"):
        raise t.error("hang_off_angle_deg", "ambiguous: say which angle it is, "
                      "hang_off_angle_from_horizontal_deg or hang_off_angle_from_vertical_deg")
    present = [kind for kind, keys in _END_FORMS.items()
               if any(t.has(k) for k in keys if k != "hang_off_height") or (
                   kind == "hang_off_angle" and t.has("hang_off_height")
                   and not t.has("top_tension"))]
    if not present:
        raise t.error("", "give one of: tdp_tension; hang_off_height + "
                      "hang_off_angle_from_horizontal_deg (or _from_vertical_deg); "
                      "hang_off_height + top_tension; anchor + hang_off")
    if len(present) > 1:
        keys = list(dict.fromkeys(k for kind in present for k in _END_FORMS[kind] if t.has(k)))
        raise t.error(keys[-1], f"more than one [ends] form given ({', '.join(keys)}); "
                      "use exactly one")
    kind = present[0]
    C = LIMITS["coordinate"]
    if kind == "tdp_tension":
        ends = Ends(kind, tdp_tension=t.number("tdp_tension", gt=0.0, le=LIMITS["tension"], unit="N"))
    elif kind == "hang_off_angle":
        height = t.number("hang_off_height", gt=0.0, le=C, unit="m")
        ends = Ends(kind, hang_off_height=height, hang_off_angle_deg=_read_angle(t))
    elif kind == "top_tension":
        top = t.number("top_tension", gt=0.0, le=LIMITS["tension"], unit="N")
        if not t.has("hang_off_height"):
            raise t.error("hang_off_height", "required with top_tension (the J-lay form: "
                          "the hang-off height [m] and the effective tension there [N])")
        height = t.number("hang_off_height", gt=0.0, le=C, unit="m")
        ends = Ends(kind, hang_off_height=height, top_tension=top)
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


def _read_angle(t: Table) -> float:
    """The hang-off angle from the horizontal [deg], given from either reference."""
    given = [k for k in ANGLE_KEYS if t.has(k)]
    if len(given) != 1:
        why = (" (both given)" if given else " with hang_off_height (or top_tension with "
               "it: the J-lay form)")
        raise t.error(ANGLE_KEYS[0], "give exactly one of hang_off_angle_from_horizontal_deg "
                      "and hang_off_angle_from_vertical_deg" + why)
    if given[0] == ANGLE_KEYS[0]:
        return t.number(ANGLE_KEYS[0], gt=0.0, le=90.0, unit="deg")
    return 90.0 - t.number(ANGLE_KEYS[1], ge=0.0, lt=90.0, unit="deg")


def _read_dynamics(t: Table) -> Dynamics:
    duration = t.number("duration", gt=0.0, le=1.0e6, unit="s")
    interval = t.number("output_interval", min(1.0, duration), gt=0.0, le=duration, unit="s")
    damping = t.number("damping", 0.0, ge=0.0, le=100.0, unit="1/s")
    stats = t.number("statistics_start", None, ge=0.0, lt=duration, unit="s")
    save = t.boolean("save_states", False)
    motion = None
    tm = t.table("top_motion")
    if tm is not None:
        axis = tm.string("axis", choices=("x", "y", "z"))
        ramp = tm.number("ramp_time", None, ge=0.0, le=duration, unit="s")
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
            if ramp is None and motion.period >= duration:
                raise t.error("duration", f"must be > {motion.period:g} s, the default ramp "
                              "(one period of top_motion), got "
                              f"{duration:g}; or set top_motion.ramp_time (0: no ramp)")
        tm.finish()
    t.finish()
    return Dynamics(duration=duration, output_interval=interval, top_motion=motion,
                    damping=damping, statistics_start=stats, save_states=save)


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
    if e.kind in ("hang_off_angle", "top_tension"):
        if scene.water_depth is not None and e.hang_off_height > scene.water_depth:
            raise SceneError(src, "ends.hang_off_height", f"must be <= water_depth "
                             f"{scene.water_depth:g} m, got {e.hang_off_height:g}")
        if scene.total_length <= e.hang_off_height:
            raise SceneError(src, "segments", f"line length {scene.total_length:g} m cannot reach "
                             f"the hang-off height {e.hang_off_height:g} m")

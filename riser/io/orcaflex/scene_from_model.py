"""One line of an OrcaFlex model -> a scene (``riser-verify import-orcaflex``).

What a scene holds: one line from a bottom end (an anchor, or a free end) to a hang-off
(fixed in space, or on a vessel), made of sections of line types, with point attachments,
in one environment. So the OrcaFlex line must run between two of: ``Anchored``,
``Fixed``, a vessel (its position in the vessel's axes), or ``Free`` at its lower end.
Every number carried is converted exactly from the file's units
(:mod:`riser.io.orcaflex.units`) and said in the scene's comments; every item that would
change the line's physics and that the scene cannot hold is refused with one line naming
the OrcaFlex item and its value (exit 2), never dropped: a drag coefficient varying with
Reynolds number (variable data), nonlinear EA or EI, lift, slam, limited compression,
Rayleigh damping, contents pressure or flow, a sloping or non-elastic seabed, an end on
a buoy or on another line, an end released, a vessel that is not moved by its RAOs alone,
a wave that is not Airy, JONSWAP or ISSC as given (:mod:`.sea`), a current turning with
depth, and so on (docs/orcaflex.md lists them). Items that do not change the line's
statics or dynamics (drawing, results limits, solver settings, other objects of the
model) are listed in the notes.

Mapping (the frame: :mod:`.frame`):

- a line type (``General``): ``outer_diameter`` = OD, ``inner_diameter`` = ID (when >
  0), ``mass_per_length`` = MassPerUnitLength, ``axial_stiffness`` = EA,
  ``bending_stiffness`` = EI (x; y ~ or equal), ``drag_normal`` = Cd (normal),
  ``drag_tangential`` = Cd (axial) x D_axial / D_h (OrcaFlex's axial drag acts on pi
  D_axial, the scene's on pi D_h), ``added_mass`` = Ca (normal) x (OD / D_h)^2 (OrcaFlex's
  added mass is on the displaced area, the scene's on D_h's), ``hydro_diameter`` = D_h,
  OrcaFlex's normal drag diameter when it differs from OD; ``minimum_bend_radius`` =
  MinRadius; ``torsional_stiffness`` = GJ when the line includes torsion. A
  ``Homogeneous pipe``: the same from its material (``density``, ``youngs_modulus``,
  ``poisson_ratio``);
- the line's contents (``ContentsDensity``) -> ``contents_density`` of its line types;
- sections (End A to End B) -> ``[[segments]]`` from the bottom end; the shortest
  ``TargetSegmentLength`` -> ``[vfife] element_length`` (the VFIFE's mesh is uniform);
- the ends: End connection stiffness 0 -> pinned, Infinity -> clamped, else a flex joint
  (``kind = "spring"``, kN m/deg -> N m/rad), its neutral direction from the end's
  azimuth and declination; ``Free`` -> ``[ends.anchor_joint] kind = "free"``;
- attachments of clump types -> ``[[attachments]]`` (:mod:`.attachments`);
- the seabed: stiffness = SeabedNormalStiffness x the bottom line type's contact
  diameter (OrcaFlex's force per unit area of contact), ``friction`` = the bottom line
  type's lateral friction coefficient, ``damping`` = SeabedDamping / 100;
- the environment: density, depth, current, waves, the vessel's RAOs (:mod:`.sea`);
  g = 9.80665 m/s2, OrcaFlex's.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from ...errors import SceneError
from ...model.scene import Scene
from ..angles import wrap_deg
from ..scene_file import scene_from_dict
from ..toml_text import dumps
from ..toml_text import key as toml_key
from .attachments import attachments
from .frame import Frame
from .line_types import contact_diameter, line_type
from .sea import current, dynamics, max_current_speed, trains_of, vessel_motion, waves
from .text_file import Model, ModelError, get, number, read_model, table
from .units import GRAVITY, Units, units_of


#: connection names that are no object
FIXED, ANCHORED, FREE = "fixed", "anchored", "free"


def import_model(path: str | Path, line: str | None = None, name: str | None = None,
                 statics: bool = False) -> tuple[str, Scene, list[str]]:
    """Read the OrcaFlex text data file at ``path`` and import its line ``line`` (the
    model's only line when None): (the scene's TOML text, the validated scene, the notes
    written into it). Raise :class:`~.text_file.ModelError` naming the OrcaFlex item."""
    path = Path(path)
    model = read_model(path)
    data, notes, comments = scene_dict(model, line, _scene_name(name or path.stem), statics)
    header = [f"Imported from the OrcaFlex model {path.name} (line {data['title']!r}) by "
              "riser-verify import-orcaflex.", *notes]
    text = dumps(data, header=[_printable(h) for h in header],
                 comments={k: [_printable(c) for c in v] for k, v in comments.items()})
    try:
        scene = scene_from_dict(data, f"{path.name} (imported)")
    except SceneError as exc:
        raise ModelError(str(path), _item_of(exc.key, data["title"]), f"the imported scene "
                         f"is refused: {exc.key}: {exc.message}") from None
    return text, scene, notes


#: the scene's tables -> the OrcaFlex items they come from (a refusal of the imported
#: scene names the item)
SCENE_ITEMS = {"attachments": "{line}.Attachment", "environment.current":
               "Environment.RefCurrentDirection", "environment.waves": "Environment.WaveTrains",
               "environment": "Environment", "seabed": "Environment.SeabedNormalStiffness",
               "ends": "{line}.Connection", "segments": "{line}.Sections",
               "vessel": "Vessels", "dynamics": "General.StageDuration"}


def _item_of(key: str, line: str) -> str:
    """The OrcaFlex item a scene key came from (a line type's: ``LineTypes[NAME]``)."""
    lines = f"Lines[{line}]"
    if key.startswith("line_types."):
        name = key[len("line_types."):].split(".")[0].strip('"')
        return f"LineTypes[{name}]"
    for prefix, item in SCENE_ITEMS.items():
        if key == prefix or key.startswith((prefix + ".", prefix + "[")):
            return item.format(line=lines)
    return lines


def _printable(text: str) -> str:
    return "".join(c if c.isprintable() else f"\\x{ord(c):02x}" for c in text)


def _scene_name(stem: str) -> str:
    s = re.sub(r"[^a-z0-9-]+", "-", stem.lower()).strip("-")
    return s if s and s[0].isalnum() else "orcaflex-model"


def pick_line(model: Model, name: str | None) -> dict:
    """The line to import: ``name``, or the model's only line."""
    lines = model.objects("Lines")
    if not lines:
        raise ModelError(model.source, "Lines", "the model has no line to import")
    if name is not None:
        return model.named("Lines", name, "--line")
    if len(lines) > 1:
        names = ", ".join(repr(str(ln.get("Name"))) for ln in lines)
        raise ModelError(model.source, "Lines", f"the model holds {len(lines)} lines "
                         f"({names}): choose one with --line NAME")
    return lines[0]


def _require(obj: dict, key: str, allowed: tuple, src: str, item: str,
             why: str, default=None) -> None:
    """Refuse ``obj[key]`` unless it is one of ``allowed`` (strings compared in any case;
    a missing key takes ``default``)."""
    v = get(obj, key, default=default)
    norm = v.lower() if isinstance(v, str) else v
    ok = [a.lower() if isinstance(a, str) else a for a in allowed]
    if norm not in ok:
        raise ModelError(src, f"{item}.{key}", f"{v!r}: {why}")


def _yes(v) -> bool:
    return v is True or (isinstance(v, str) and v.strip().lower() in ("yes", "true"))


def scene_dict(model: Model, line_name: str | None, name: str,
               statics: bool = False) -> tuple[dict, list, dict]:
    """The scene structure of the line, the notes and the comment lines of its tables;
    ``statics``: leave out the waves, the vessel's RAOs and the stages (with a note)."""
    src = model.source
    u = units_of(model)
    ln = pick_line(model, line_name)
    lname = str(ln.get("Name"))
    item = f"Lines[{lname}]"
    notes: list[str] = [f"Units: {u.label} -> SI (m, kg, N, s); every value below is "
                        "converted from them."]
    comments: dict[str, list[str]] = {}
    _check_line_options(ln, src, item, notes)
    env = model.section("Environment") or {}
    sections = _sections(ln, u, src, item)
    depth, z_surface, depth_item = _depth(env, u, src)
    ends = _ends(model, ln, u, src, item, z_surface - depth)
    a, b = ends                      # End A, End B: each a dict (see _ends)
    if a["kind"] == FREE and b["kind"] == FREE:
        raise ModelError(src, f"{item}.Connection", "both ends are Free: a scene's line "
                         "hangs from a hang-off")
    if a["kind"] == FREE or (b["kind"] != FREE and a["Z"] < b["Z"]):
        bottom, top = a, b
    else:
        bottom, top = b, a
    if top["kind"] == FREE or (bottom["kind"] == FREE and bottom["Z"] >= top["Z"]):
        raise ModelError(src, f"{item}.Connection[{bottom['end']}]", "Free: a free end must "
                         "be below the other (the scene's line hangs from its hang-off)")
    from_b = bottom["end"] == "End B"
    # the line from the bottom end: End B first when End A is the top
    segs = list(reversed(sections)) if from_b else list(sections)
    used = list(dict.fromkeys(s["type"] for s in segs))
    contents = _contents(ln, u, src, item, notes)
    carry_waves = not statics and bool(trains_of(env))
    nu = number(get(env, "KinematicViscosity", default=1.35e-6), src,
                "Environment.KinematicViscosity")
    if not nu > 0.0:
        raise ModelError(src, "Environment.KinematicViscosity", f"must be > 0, got {nu:g}")
    re_max = None if carry_waves else max_current_speed(env, u, src) / (nu * u.length ** 2)
    types, type_notes = {}, {}
    lt_objs = {}
    for tname in used:
        obj = model.named("LineTypes", tname, f"{item}.LineType")
        lt_objs[tname] = obj
        types[tname], type_notes[tname] = line_type(
            model, obj, u, _yes(get(ln, "IncludeTorsion")), re_max)
        if contents > 0.0:
            if "inner_diameter" not in types[tname]:
                raise ModelError(src, f"LineTypes[{tname}].ID", "the line has contents "
                                 f"(ContentsDensity) but this line type no bore (ID)")
            types[tname]["contents_density"] = contents
    # the frame: the plane through the ends, the seabed raised by the contact radius
    bottom_type = lt_objs[segs[0]["type"]]
    r_contact = contact_diameter(bottom_type, u, src) / 2.0
    free = bottom["kind"] == FREE
    dX, dY = top["X"] - bottom["X"], top["Y"] - bottom["Y"]
    span = math.hypot(dX, dY)
    alpha = math.degrees(math.atan2(dY, dX)) if span > 1e-9 else 0.0
    z_seabed_of = z_surface - depth
    frame = Frame(bottom["X"], bottom["Y"], wrap_deg(alpha), z_seabed_of + r_contact,
                  depth - r_contact)
    if span <= 1e-9:
        notes.append("The two ends are vertically aligned: the scene's x-y plane is "
                     "OrcaFlex's X-Z plane.")
    xb, yb, _ = frame.point(bottom["X"], bottom["Y"], bottom["Z"])
    xt, yt, zt = frame.point(top["X"], top["Y"], top["Z"])
    if not free and yb < -1e-9:
        raise ModelError(src, f"{item}.Connection[{bottom['end']}]", f"{bottom['what']} at Z "
                         f"= {bottom['Z']:.12g} m puts the line {-yb:.6g} m into OrcaFlex's "
                         f"seabed (its contact is at the outer surface: the end's centre "
                         f"must be at least the contact radius {r_contact:g} m above the "
                         "seabed); the scene's anchor is on or above its seabed: raise the "
                         "end or make it Anchored at z = the contact radius")
    if top["Z"] > z_surface + 1e-9:
        raise ModelError(src, f"{item}.Connection[{top['end']}]", f"the end is above the "
                         f"still surface (Z = {top['Z']:g} m > {z_surface:g} m): the scene's "
                         "line is submerged")
    data: dict = {"name": name, "title": lname,
                  "source": f"OrcaFlex model {Path(src).name}, line {lname}",
                  "environment": {"gravity": u.gravity,
                                  "water_density": _density(env, u, src),
                                  "water_depth": frame.depth}}
    comments["environment"] = [
        f"water_density = Environment.Density x {u.density:g} kg/m3 per file unit; gravity "
        f"{u.gravity:.12g} m/s2, OrcaFlex's" + (" (General.g)" if u.gravity != GRAVITY
                                                else " standard gravity"),
        f"water_depth = {depth_item} ({depth:.12g} m) - the bottom line type's contact radius "
        f"({r_contact:.12g} m): OrcaFlex's seabed contact is at the line's outer surface, "
        "the scene's at its centre, so the scene's seabed is OrcaFlex's raised by the "
        "contact radius (the surface stays where it is)"]
    cur = current(env, frame, u, src, notes)
    if cur:
        data["environment"]["current"] = cur
    wv = waves(model, env, frame, u, src, notes) if carry_waves else None
    if wv:
        data["environment"]["waves"] = wv
    elif statics and trains_of(env):
        notes.append("--statics: the waves, the vessel's RAOs and the dynamic stages are "
                     "left out (" + ", ".join(f"{get(t, 'WaveType')}" for t in
                                              trains_of(env)) + ").")
    data["line_types"] = types
    for tname in used:
        comments[f"line_types.{toml_key(tname)}"] = type_notes[tname]
    data["segments"] = [{"line_type": s["type"], "length": s["length"],
                         "label": f"OrcaFlex section {s['index'] + 1}"} for s in segs]
    element = min(s["target"] for s in segs if s["target"] is not None) \
        if any(s["target"] is not None for s in segs) else None
    xb, yb, xt, yt, zt = (v + 0.0 for v in (xb, yb, xt, yt, zt))      # no -0.0
    ends_data: dict = {"anchor": [xb, yb] if abs(_z(frame, bottom)) < 1e-12 else
                       [xb, yb, _z(frame, bottom)],
                       "hang_off": [xt, yt] if abs(zt) < 1e-12 else [xt, yt, zt]}
    if abs(zt) < 1e-12 and len(ends_data["anchor"]) == 3:
        ends_data["hang_off"] = [xt, yt, zt]
    joints = {}
    for end, key in ((bottom, "anchor_joint"), (top, "hang_off_joint")):
        j = _joint(end, frame, u, src, item, from_b, notes)
        if j is not None:
            joints[key] = j
    if free:
        joints["anchor_joint"] = {"kind": "free"}
        notes.append(f"{bottom['end']} is Free: [ends.anchor_joint] kind = 'free', the "
                     "anchor its starting position.")
    ends_data.update(joints)
    data["ends"] = ends_data
    comments["ends"] = [
        f"anchor = {bottom['end']} ({bottom['what']}), hang_off = {top['end']} "
        f"({top['what']}); the plane's azimuth {frame.alpha_deg:.12g} deg from OrcaFlex's X "
        f"towards Y; x from the anchor, y = Z + {-frame.z_seabed:.12g} m"]
    total = sum(s["length"] for s in segs)
    atts, att_comments = attachments(model, ln, u, total, from_b, src, item, notes,
                                     flow=bool(cur) or bool(wv), dynamic=bool(wv))
    if atts:
        data["attachments"] = atts
        comments.update(att_comments)
    if not free:
        sb = _seabed(env, bottom_type, u, src, notes)
        if sb:
            data["seabed"] = sb
    elif _seabed_stiffness(env, u, src) > 0.0:
        notes.append("The line hangs from its hang-off with a free lower end: OrcaFlex's "
                     "seabed is not carried (a scene's hanging line clears the seabed).")
    if element is not None:
        data["vfife"] = {"element_length": element}
        targets = sorted({s["target"] for s in segs if s["target"] is not None})
        comments["vfife"] = [
            "element_length = the shortest TargetSegmentLength of the sections "
            f"({', '.join(f'{t:.12g}' for t in targets)} m): the VFIFE's mesh is uniform"]
    ves = vessel_motion(model, top, frame, u, src, bool(wv), notes)
    if ves:
        data["vessel"] = ves
    dyn = dynamics(model, u, src, bool(wv), notes)
    if dyn:
        data["dynamics"] = dyn
    others = []
    for sec in ("Lines", "6DBuoys", "3DBuoys", "Shapes", "Links", "Winches", "Constraints",
                "Vessels"):
        if not isinstance(model.section(sec), list):
            continue
        names = [str(o.get("Name")) for o in model.objects(sec)]
        names = [n for n in names if not (sec == "Lines" and n == lname) and
                 not (sec == "Vessels" and n == top.get("vessel"))]
        if names:
            others.append(f"{sec}: {', '.join(names)}")
    if others:
        notes.append("Not imported (other objects of the model; this line is not "
                     "connected to them): " + "; ".join(others) + ".")
    return data, notes, comments


def _z(frame: Frame, end: dict) -> float:
    return frame.point(end["X"], end["Y"], end["Z"])[2]


def _check_line_options(ln: dict, src: str, item: str, notes: list[str]) -> None:
    _require(ln, "Representation", ("Finite element",), src, item,
             "only a finite-element line is imported", default="Finite element")
    _require(ln, "DragFormulation", ("Standard",), src, item,
             "the suite's drag is the standard (cross-flow) Morison drag", default="Standard")
    for k in ("StaticsVIV", "DynamicsVIV"):
        _require(ln, k, ("None",), src, item, "vortex-induced vibration is not modelled",
                 default="None")
    _require(ln, "PyModel", ("(none)",), src, item, "a Python user model is not carried",
             default="(none)")
    _require(ln, "LengthAndEndOrientations", ("Explicit",), src, item,
             "only explicit section lengths and end orientations are read",
             default="Explicit")
    if not _yes(get(ln, "IncludedInStatics", default="Yes")):
        raise ModelError(src, f"{item}.IncludedInStatics", "No: the line is left out of "
                         "OrcaFlex's statics; the suite solves its equilibrium")
    if _yes(get(ln, "IncludeTorsion")):
        notes.append("The line includes torsion: its line types' GJ -> torsional_stiffness.")
    notes.append("OrcaFlex's statics methods (StaticsStep1/2, seabed friction policy, "
                 "lay azimuth) are not carried: the suite solves the same equilibrium "
                 "its own way.")


def _sections(ln: dict, u: Units, src: str, item: str) -> list[dict]:
    rows = table(ln, ("LineType", "Length"), src, item)
    listed = get(ln, "Sections")
    if not rows and isinstance(listed, list) and all(isinstance(r, dict) for r in listed):
        rows = listed                      # OrcaFlex 11.6's list form of the sections
    if not rows:
        raise ModelError(src, f"{item}.LineType, Length", "the line has no sections")
    out = []
    for k, r in enumerate(rows):
        it = f"{item}.Sections[{k + 1}]"
        t = get(r, "LineType")
        if t is None:
            raise ModelError(src, f"{it}.LineType", "no line type")
        if get(r, "Length") is None:
            raise ModelError(src, f"{it}.Length", "~: a section whose length comes from its "
                             "line type's profile is not carried")
        length = number(get(r, "Length"), src, f"{it}.Length") * u.length
        if not length > 0.0 or not math.isfinite(length):
            raise ModelError(src, f"{it}.Length", f"must be > 0, got {length:g} m")
        target = get(r, "TargetSegmentLength")
        nseg = get(r, "NumberOfSegments")
        tl = None
        if target is not None:
            tl = number(target, src, f"{it}.TargetSegmentLength") * u.length
        elif nseg is not None:
            tl = length / number(nseg, src, f"{it}.NumberOfSegments")
        if tl is not None and not (tl > 0.0 and math.isfinite(tl)):
            tl = None
        out.append({"index": k, "type": str(t), "length": length, "target": tl})
    return out


def _contents(ln: dict, u: Units, src: str, item: str, notes: list[str]) -> float:
    """The contents' density [kg/m3] (0: none)."""
    method = get(ln, "ContentsMethod", default="Uniform")
    if str(method).lower() != "uniform":
        raise ModelError(src, f"{item}.ContentsMethod", f"{method!r}: only uniform "
                         "contents are carried")
    for k in ("ContentsPressure", "ContentsFlowRate"):
        v = number(get(ln, k), src, f"{item}.{k}", allow_none=True)
        if v:
            why = ("internal pressure changes the wall tension and, through the Poisson "
                   "effect, the line's length: not modelled by the suite's statics" if
                   k == "ContentsPressure" else "the contents' flow (the suite's "
                   "[internal_flow] is a speed; set the flow in the scene by hand)")
            raise ModelError(src, f"{item}.{k}", f"{v:g}: {why}")
    rho = number(get(ln, "ContentsDensity"), src, f"{item}.ContentsDensity",
                 allow_none=True) or 0.0
    if rho < 0.0:
        raise ModelError(src, f"{item}.ContentsDensity", f"must be >= 0, got {rho:g}")
    if rho > 0.0:
        notes.append(f"Contents: ContentsDensity {rho:.12g} -> contents_density "
                     f"{rho * u.density:.12g} kg/m3 of each line type.")
    return rho * u.density


def _depth(env: dict, u: Units, src: str) -> tuple[float, float, str]:
    """(water depth [m], the surface's Z [m], the item it came from)."""
    z_surf = (number(get(env, "WaterSurfaceZ"), src, "Environment.WaterSurfaceZ",
                     allow_none=True) or 0.0) * u.length
    key = "SeabedOriginDepth" if get(env, "SeabedOriginDepth") is not None else "WaterDepth"
    v = get(env, key)
    if v is None:
        raise ModelError(src, "Environment.SeabedOriginDepth", "the model gives no water "
                         "depth (SeabedOriginDepth or WaterDepth)")
    depth = number(v, src, f"Environment.{key}") * u.length
    if not depth > 0.0:
        raise ModelError(src, f"Environment.{key}", f"must be > 0, got {depth:g} m")
    _require(env, "SeabedType", ("Flat",), src, "Environment",
             "only a flat seabed is carried (a profile or 3D seabed is not)", default="Flat")
    slope = number(get(env, "SeabedSlope"), src, "Environment.SeabedSlope",
                   allow_none=True) or 0.0
    if slope != 0.0:
        raise ModelError(src, "Environment.SeabedSlope", f"{slope:g} deg: the scene's "
                         "seabed is horizontal")
    return depth, z_surf, f"Environment.{key}"


def _density(env: dict, u: Units, src: str) -> float:
    _require(env, "VerticalDensityVariation", ("Constant",), src, "Environment",
             "only a constant sea density is carried", default="Constant")
    if get(env, "HorizontalWaterDensityFactor") is not None:
        raise ModelError(src, "Environment.HorizontalWaterDensityFactor", "a density "
                         "varying horizontally is not carried")
    rho = number(get(env, "Density", default=1.025), src, "Environment.Density")
    return rho * u.density


def _ends(model: Model, ln: dict, u: Units, src: str, item: str,
          z_seabed: float) -> list[dict]:
    """End A and End B: each {end, kind, what, X, Y, Z (global, m), azimuth, declination
    (deg, global), stiffness (N m/rad or None: 0 / inf), row}; ``z_seabed``: OrcaFlex's
    seabed's Z [m] (an Anchored end's z is above it)."""
    cols = ("Connection", "ConnectionX", "ConnectionY", "ConnectionZ")
    rows = table(ln, cols, src, item)
    if rows is None:
        raise ModelError(src, f"{item}.Connection", "the line has no end connections "
                         "(Connection, ConnectionX, ConnectionY, ConnectionZ)")
    if len(rows) != 2:
        raise ModelError(src, f"{item}.Connection", f"has {len(rows)} rows; a line has two "
                         "ends (End A, End B)")
    stiff = (table(ln, ("ConnectionxBendingStiffness",), src, item)
             or table(ln, ("ConnectionStiffnessX",), src, item))
    ends = []
    for k, (r, end) in enumerate(zip(rows, ("End A", "End B"))):
        it = f"{item}.Connection[{end}]"
        conn = str(get(r, "Connection"))
        rel = get(r, "ConnectionzRelativeTo")
        if get(r, "ConnectionReleaseStage") is not None:
            raise ModelError(src, f"{it}.ReleaseStage", f"{get(r, 'ConnectionReleaseStage')}"
                             ": an end released during the simulation is not modelled")
        x, y, z = (number(get(r, c), src, f"{it}.{c}", allow_none=(conn.lower() == FREE))
                   for c in cols[1:])
        az = number(get(r, "ConnectionAzimuth", "ConnectionAzm"), src, f"{it}.Azimuth",
                    allow_none=True)
        dec = number(get(r, "ConnectionDeclination", "ConnectionDec"), src,
                     f"{it}.Declination", allow_none=True)
        e = {"end": end, "row": r, "azimuth": az, "declination": dec}
        low = conn.lower()
        if low == FIXED:
            if rel is not None and str(rel).lower() not in ("global",):
                raise ModelError(src, f"{it}.zRelativeTo", f"{rel!r}: only a Fixed end's "
                                 "global position is read")
            e.update(kind=FIXED, what="Fixed", X=x * u.length, Y=y * u.length,
                     Z=z * u.length)
        elif low == ANCHORED:
            if rel is not None and str(rel).lower() not in ("seabed",):
                raise ModelError(src, f"{it}.zRelativeTo", f"{rel!r}: an Anchored end's z "
                                 "is read relative to the seabed (OrcaFlex's default)")
            e.update(kind=ANCHORED, what="Anchored", X=x * u.length, Y=y * u.length,
                     Z=z_seabed + z * u.length)
        elif low == FREE:
            if None in (x, y, z):
                raise ModelError(src, it, "a Free end needs its starting position")
            e.update(kind=FREE, what="Free", X=x * u.length, Y=y * u.length, Z=z * u.length)
        else:
            vessels = [str(v.get("Name")) for v in model.objects("Vessels")]
            if conn not in vessels:
                kinds = ("a 6D buoy" if conn in _names(model, "6DBuoys") else
                         "a 3D buoy" if conn in _names(model, "3DBuoys") else
                         "another line" if conn in _names(model, "Lines") or
                         re.search(r"(?i)end [ab]$", conn) else
                         "a shape" if conn in _names(model, "Shapes") else "no vessel")
                raise ModelError(src, it, f"{conn!r} ({kinds}): a scene's ends are "
                                 "anchored, fixed, free or on a vessel")
            if rel is not None:
                raise ModelError(src, f"{it}.zRelativeTo", f"{rel!r}: a vessel end's "
                                 "position is read in the vessel's axes")
            vx, vy, vz, psi = _vessel_place(model, conn, u, src)
            lx, ly, lz = x * u.length, y * u.length, z * u.length
            c, s = math.cos(math.radians(psi)), math.sin(math.radians(psi))
            e.update(kind="vessel", what=f"vessel {conn}", vessel=conn,
                     local=(lx, ly, lz), psi=psi,
                     X=vx + c * lx - s * ly, Y=vy + s * lx + c * ly, Z=vz + lz)
        if stiff is not None and k < len(stiff):
            e["stiffness"] = _end_stiffness(stiff[k], u, src, it)
        else:
            e["stiffness"] = 0.0
        ends.append(e)
    return ends


def _names(model: Model, section: str) -> list[str]:
    got = model.section(section)
    return [str(o.get("Name")) for o in got] if isinstance(got, list) else []


def _vessel_place(model: Model, name: str, u: Units, src: str):
    """A vessel's (X, Y, Z) [m] and heading [deg]; refused when rolled or pitched."""
    v = model.named("Vessels", name, "Connection")
    it = f"Vessels[{name}]"
    pos = get(v, "InitialPosition")
    if pos is None:
        pos = [get(v, "InitialX", default=0.0), get(v, "InitialY", default=0.0),
               get(v, "InitialZ", default=0.0)]
    if not isinstance(pos, list) or len(pos) != 3:
        raise ModelError(src, f"{it}.InitialPosition", "must be [X, Y, Z]")
    X, Y, Z = (number(p, src, f"{it}.InitialPosition") * u.length for p in pos)
    ori = get(v, "Orientation")
    if ori is None:
        ori = [get(v, "InitialRotation1", "InitialHeel", default=0.0),
               get(v, "InitialRotation2", "InitialTrim", default=0.0),
               get(v, "InitialHeading", default=0.0)]
    rx, ry, rz = (number(o, src, f"{it}.Orientation", allow_none=True) or 0.0 for o in ori)
    if rx or ry:
        raise ModelError(src, f"{it}.Orientation", f"[{rx:g}, {ry:g}, {rz:g}] deg: a heeled "
                         "or trimmed vessel is not carried (its end positions would turn)")
    return X, Y, Z, rz


def _end_stiffness(row: dict, u: Units, src: str, item: str) -> float:
    """The end's bending stiffness [N m/rad] (0 pinned, inf clamped); x and y equal."""
    vals = list(row.values())
    for v in vals[:2]:
        if isinstance(v, str) and v.strip().lower() not in ("infinity", "~") and \
                not _float_text(v):
            raise ModelError(src, f"{item}.BendingStiffness", f"refers to variable data "
                             f"{v!r} (a nonlinear end stiffness): the scene's flex joint is "
                             "linear")
    kx = number(vals[0], src, f"{item}.BendingStiffness", allow_none=True, allow_inf=True) \
        if vals else None
    ky = number(vals[1], src, f"{item}.BendingStiffness", allow_none=True,
                allow_inf=True) if len(vals) > 1 else None
    kx = 0.0 if kx is None else kx
    if ky is not None and ky != kx:
        raise ModelError(src, f"{item}.BendingStiffness", f"x {kx:g} and y {ky:g} differ: "
                         "the scene's flex joint is isotropic")
    if math.isinf(kx):
        return math.inf
    if kx < 0.0:
        raise ModelError(src, f"{item}.BendingStiffness", f"must be >= 0, got {kx:g}")
    return kx * u.moment * 180.0 / math.pi          # per degree -> per radian


def _float_text(v: str) -> bool:
    try:
        float(v)
        return True
    except ValueError:
        return False


def _joint(end: dict, frame: Frame, u: Units, src: str, item: str, reverse: bool,
           notes: list[str]) -> dict | None:
    """The scene's end joint of an end with bending stiffness (None: pinned)."""
    k = end["stiffness"]
    if end["kind"] == FREE or k == 0.0:
        return None
    it = f"{item}.Connection[{end['end']}]"
    az, dec = end["azimuth"], end["declination"]
    if az is None or dec is None:
        raise ModelError(src, it, "an end with bending stiffness needs its azimuth and "
                         "declination (the joint's neutral direction)")
    if end["kind"] == "vessel":
        az = az + end["psi"]                     # the vessel's axes -> global
    a, d = math.radians(az), math.radians(dec)
    vec = (math.sin(d) * math.cos(a), math.sin(d) * math.sin(a), math.cos(d))   # A -> B
    if reverse:                  # the scene's s runs from End B: along B -> A
        vec = tuple(-c for c in vec)
    cx, sx = frame.ex
    vx = vec[0] * cx + vec[1] * sx
    vz = vec[0] * sx - vec[1] * cx
    if abs(vz) > 1e-9:
        raise ModelError(src, it, f"azimuth {end['azimuth']:g} deg: the end's neutral "
                         "direction leaves the plane of the ends; a scene's joint turns in "
                         "its plane")
    direction = math.degrees(math.atan2(vec[2], vx))
    if math.isinf(k):
        notes.append(f"{end['end']}: bending stiffness Infinity -> a clamped end.")
        return {"kind": "clamped", "direction_deg": direction}
    notes.append(f"{end['end']}: bending stiffness {k * math.pi / 180.0 / u.moment:.12g} "
                 f"(force x length per degree) -> a flex joint of {k:.12g} N m/rad.")
    return {"kind": "spring", "direction_deg": direction, "rotational_stiffness": k}


def _seabed_stiffness(env: dict, u: Units, src: str) -> float:
    k = number(get(env, "SeabedNormalStiffness"), src, "Environment.SeabedNormalStiffness",
               allow_none=True)
    return (k or 0.0) * u.stiffness_per_area


def _seabed(env: dict, bottom_type: dict, u: Units, src: str, notes: list[str]) -> dict | None:
    model = get(env, "SeabedModel", default="Elastic")
    if str(model).lower() != "elastic":
        raise ModelError(src, "Environment.SeabedModel", f"{model!r}: only OrcaFlex's "
                         "linear elastic seabed is carried (the scene's Winkler seabed)")
    k = _seabed_stiffness(env, u, src)
    if k == 0.0:
        notes.append("SeabedNormalStiffness 0: no seabed contact.")
        return None
    d = contact_diameter(bottom_type, u, src)
    out = {"stiffness": k * d}
    tname = str(bottom_type.get("Name"))
    mu = number(get(bottom_type, "SeabedLateralFrictionCoefficient"), src,
                f"LineTypes[{tname}].SeabedLateralFrictionCoefficient", allow_none=True)
    ax = number(get(bottom_type, "SeabedAxialFrictionCoefficient"), src,
                f"LineTypes[{tname}].SeabedAxialFrictionCoefficient", allow_none=True)
    if ax is not None and mu is not None and ax != mu:
        raise ModelError(src, f"LineTypes[{tname}].SeabedAxialFrictionCoefficient",
                         f"{ax:g} differs from the lateral {mu:g}: the scene's friction is "
                         "one Coulomb coefficient")
    if mu:
        out["friction"] = mu
    damp = number(get(env, "SeabedDamping"), src, "Environment.SeabedDamping",
                  allow_none=True)
    if damp:
        out["damping"] = damp / 100.0
    notes.append(f"Seabed: stiffness = SeabedNormalStiffness ({k:.12g} N/m/m2) x the bottom "
                 f"line type's contact diameter ({d:.12g} m) = {k * d:.12g} N/m2"
                 + (f"; friction {mu:g} (the bottom line type's)" if mu else "")
                 + (f"; damping {damp:g} % of critical -> {damp / 100.0:g}" if damp else "")
                 + ". OrcaFlex's shear stiffness (the friction's elastic slip) is not carried.")
    return out

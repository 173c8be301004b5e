"""Reading a scene file: TOML -> validated :class:`riser.model.scene.Scene`.

The reader checks what the file adds to the model: TOML types, required and unknown keys,
which end form the keys of ``[ends]`` select, and the file-only conveniences (the wall and
material of a line type instead of its section properties, the hang-off angle from the
vertical). Ranges and the rules between keys are the parts' own (:mod:`riser.spec`,
``Scene.__post_init__``), checked when the reader builds them, so a file and a
``scene.replace`` give the same :class:`~riser.errors.SceneError`: one line naming the
file, the key path and the allowed range. Well-formed but physically impossible scenes (a
line too short to reach its hang-off, an inextensible line shorter than its chord) are
refused before any solver runs.
"""

from __future__ import annotations

import errno
import math
import os
import stat
import tomllib
from pathlib import Path

from ..design.part import Design, Fatigue, SeaState
from ..model.ends import FILE_KEYS as ENDS_FILE_KEYS
from ..model.attachments import Attachment
from ..model.ends import (
    EndJoint,
    FixedEnds,
    HangOffAngleEnds,
    TdpTensionEnds,
    Tensioner,
    TopTensionEnds,
)
from ..errors import SceneError
from ..model.line import BORE, FILE_KEYS, POISSON_RATIO, LineType, Segment, check_bore
from ..model.scene import (
    MODEL_KEYS,
    Current,
    Dynamics,
    InternalFlow,
    Scene,
    Seabed,
    TopMotion,
)
from ..model.settings import ANCFSettings, AnalyticSettings, BVPSettings, VFIFESettings
from ..spec import specs
from ..physics.vessel import RAOTable, Vessel
from ..physics.waves import WaveSpectrum, WaveTrain, Waves
from .toml_table import Table

# ---------------------------------------------------------------------- loading
#: the longest name of one file or folder most file systems take [bytes]
NAME_MAX = 255


#: the errors :func:`path_problem` reports: a name too long, a component that is a file,
#: a loop of links, a folder that may not be searched
PATH_ERRORS = (errno.ENAMETOOLONG, errno.ENOTDIR, errno.ELOOP, errno.EACCES)


def path_problem(path: str | Path, errors: tuple[int, ...] = PATH_ERRORS) -> str | None:
    """Why ``path`` cannot even be looked at (one of ``errors``), or None: ``Path.exists``
    and ``Path.is_file`` raise OSError on a name too long or a loop of links instead of
    answering."""
    try:
        os.stat(path)
    except FileNotFoundError:
        # a missing folder above hides a name too long below it (ENOENT comes first)
        if (errno.ENAMETOOLONG in errors
                and any(len(os.fsencode(part)) > NAME_MAX for part in Path(path).parts)):
            return os.strerror(errno.ENAMETOOLONG)
        return None
    except OSError as exc:
        if exc.errno in errors:
            return exc.strerror or str(exc)
    except ValueError as exc:                       # an embedded NUL
        return str(exc)
    return None


def is_file(path: str | Path) -> bool:
    """``Path(path).is_file()`` that answers False instead of raising (see
    :func:`path_problem`)."""
    try:
        return Path(path).is_file()
    except (OSError, ValueError):
        return False


def read_file_bytes(path: str | Path, what: str, limit: int) -> bytes:
    """The bytes of a regular file of at most ``limit`` bytes; :class:`SceneError` naming
    the file otherwise: missing, a name the file system refuses, a directory, a FIFO or
    device (never opened: it could block or never end), unreadable, too large. ``what``:
    the input's name in the messages ("a scene file", "a MoorDyn input file"). Shared by
    every reader of an input file (scenes, sweeps, MoorDyn decks)."""
    path = Path(path)
    where = str(path)
    problem = path_problem(path)
    if problem is not None:
        raise SceneError(where, "", f"cannot read file ({problem})")
    try:
        st = path.stat()
        if stat.S_ISDIR(st.st_mode):
            raise SceneError(where, "", f"is a directory, not {what}")
        if not stat.S_ISREG(st.st_mode):
            raise SceneError(where, "", f"is not a regular file (a pipe or a device), not "
                             f"{what}")
        with path.open("rb") as fh:
            data = fh.read(limit + 1)
    except OSError as exc:
        raise SceneError(where, "", f"cannot read file ({exc.strerror or exc})") from None
    if len(data) > limit:
        raise SceneError(where, "", f"is larger than {limit / 1e6:g} MB, too large for {what}")
    return data


def read_text(path: str | Path, what: str = "a scene", limit: int = 1_000_000) -> str:
    """The UTF-8 text of a TOML input file of at most ``limit`` bytes (a byte-order mark
    is accepted; :func:`read_file_bytes` for what is not a file); :class:`SceneError`
    naming the file on binary, UTF-16 or Latin-1 content. ``what``: the input's name in
    the messages ("a scene", "a sweep")."""
    where = str(path)
    data = read_file_bytes(path, f"{what} file (a .toml file)", limit)
    kinds = {b"\x89PNG": "a PNG image", b"PK\x03\x04": "a zip archive", b"%PDF": "a PDF file",
             b"\x1f\x8b": "a gzip archive", b"\x7fELF": "an executable", b"\xff\xd8\xff":
             "a JPEG image", b"\xff\xfe\x00\x00": "UTF-32 text", b"\x00\x00\xfe\xff":
             "UTF-32 text", b"\xff\xfe": "UTF-16 text", b"\xfe\xff": "UTF-16 text"}
    kind = next((k for m, k in kinds.items() if data.startswith(m)), None)
    if kind is None and b"\x00" in data:
        kind = "binary data or UTF-16 text (it holds NUL bytes)"
    if kind is not None:
        raise SceneError(where, "", f"is {kind}, not {what}: {what} is TOML text in UTF-8"
                         + (" (save it as UTF-8)" if "text" in kind else ""))
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[:exc.start].count(b"\n") + 1
        raise SceneError(where, "", f"is not UTF-8 text (byte 0x{data[exc.start]:02x} on line "
                         f"{line}; Latin-1 or Windows-1252?): save it as UTF-8") from None


def load_scene(path: str | Path) -> Scene:
    """Read and validate a scene file (:func:`read_text`: UTF-8 TOML text of at most
    1 MB); raise :class:`SceneError` on any problem, including a file that is not one."""
    return parse_scene(read_text(path), Path(path).name)


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
    values = root.fields(Scene)                       # name, title, source
    env = root.table("environment") or Table({}, "environment", source)
    values.update(env.fields(Scene, "environment"))
    cur_t = env.table("current")
    if cur_t is not None:
        if cur_t.has("heading_deg") and cur_t.has("headings_deg"):
            raise cur_t.error("headings_deg", "give heading_deg (one direction) or "
                              "headings_deg (one per height), not both")
        values["current"] = _read_part(cur_t, Current)
    waves_t = env.table("waves")
    if waves_t is not None:
        values["waves"] = _read_waves(waves_t)
    env.finish()

    sb_t = root.table("seabed")
    if sb_t is not None:
        values["seabed"] = _read_part(sb_t, Seabed)

    lt_root = root.table("line_types", required=True)
    values["line_types"] = {name: _read_line_type(lt_root.table(name), name)
                            for name in list(lt_root.data)}
    lt_root.finish()
    values["segments"] = tuple(_read_part(t, Segment) for t in root.array_of_tables("segments"))
    values["attachments"] = tuple(_read_part(t, Attachment)
                                  for t in root.array_of_tables("attachments", required=False))
    values["ends"] = _read_ends(root.table("ends", required=True))

    vessel_t = root.table("vessel")
    if vessel_t is not None:
        values["vessel"] = _read_vessel(vessel_t)
    dyn_t = root.table("dynamics")
    if dyn_t is not None:
        values["dynamics"] = _read_dynamics(dyn_t)
    flow_t = root.table("internal_flow")
    if flow_t is not None:
        values["internal_flow"] = _read_sub_tables(flow_t, InternalFlow, required={
            "slug": ("density_amplitude", "slug_length")})
    design_t = root.table("design")
    if design_t is not None:
        values["design"] = _read_design(design_t)
    model_t = root.table("model")
    if model_t is not None:
        values["model"] = {key: model_t.value(key, sp) for key, sp in MODEL_KEYS.items()
                           if model_t.has(key)}
        model_t.finish()
    for name, cls in (("bvp", BVPSettings), ("analytic", AnalyticSettings),
                      ("vfife", VFIFESettings), ("ancf", ANCFSettings)):
        t = root.table(name)
        if t is not None:
            values[name] = _read_sub_tables(t, cls)
    root.finish()
    return Scene(**values, source=source)


def _read_part(t: Table, cls):
    """The part ``cls`` of the fields of table ``t``."""
    values = t.fields(cls)
    t.finish()
    return t.build(cls, **values)


def _read_sub_tables(t: Table, cls, required: dict | None = None):
    """The part ``cls`` of table ``t`` and its sub-tables ([vfife.expert],
    [internal_flow.slug]); ``required``: the keys a given sub-table must hold."""
    values = t.fields(cls)
    for sub in dict.fromkeys(sp.table for _, sp in specs(cls) if sp.table):
        sub_t = t.table(sub)
        if sub_t is not None:
            values.update(sub_t.fields(cls, sub, required=(required or {}).get(sub, ())))
            sub_t.finish()
    t.finish()
    return t.build(cls, **values)


def _read_line_type(t: Table, name: str) -> LineType:
    """A line type from its section properties (OD, mass per length, EA, EI: a cable, a
    chain, a flexible pipe) or from its wall and material (a steel pipe)."""
    sp = dict(specs(LineType))
    D = t.value("outer_diameter", sp["outer_diameter"], checked=True)
    d = _read_bore(t, D, sp["inner_diameter"])
    wall = f"{BORE} (the wall's area)"
    area = 0.0 if d is None else math.pi / 4.0 * (D * D - d * d)
    inertia = 0.0 if d is None else math.pi / 64.0 * (D ** 4 - d ** 4)
    if t.has("density") and t.has("mass_per_length"):
        raise t.error("mass_per_length", "give either density or mass_per_length, not both")
    if d is None and t.has("density"):
        raise t.error("density", f"needs {wall}; give mass_per_length [kg/m] instead")
    if d is None and not t.has("mass_per_length"):
        raise t.error("mass_per_length", f"required: give it [kg/m] (with axial_stiffness and "
                      f"bending_stiffness), or {wall} with density")
    values = {"name": name, "outer_diameter": D, "inner_diameter": d}
    if not t.has("mass_per_length"):
        values["mass_per_length"] = t.value("density", FILE_KEYS["density"], checked=True) * area
    E = t.value("youngs_modulus", FILE_KEYS["youngs_modulus"], None, checked=True)
    if E is not None and d is None:
        raise t.error("youngs_modulus", f"needs {wall}; give axial_stiffness [N] and "
                      "bending_stiffness [N m2] instead")
    if E is None and not t.has("bending_stiffness"):
        raise t.error("bending_stiffness", "required when youngs_modulus is not given")
    # axial_stiffness may be missing here: Scene requires it for an extensible model
    if E is not None:
        values["axial_stiffness"] = t.value("axial_stiffness", sp["axial_stiffness"], E * area)
        values["bending_stiffness"] = t.value("bending_stiffness", sp["bending_stiffness"],
                                              E * inertia)
    else:
        values["bending_stiffness"] = t.value("bending_stiffness", sp["bending_stiffness"])
    EI = values["bending_stiffness"]
    poisson = t.value("poisson_ratio", FILE_KEYS["poisson_ratio"], POISSON_RATIO, checked=True)
    G = t.value("shear_modulus", FILE_KEYS["shear_modulus"], None, checked=True)
    if G is not None and d is None:
        raise t.error("shear_modulus", f"needs {wall}; give torsional_stiffness [N m2] instead")
    # GJ = G * 2I; with G = E / (2 (1 + nu)) that is EI / (1 + nu)
    values["torsional_stiffness"] = t.value(
        "torsional_stiffness", sp["torsional_stiffness"],
        G * 2.0 * inertia if G is not None else EI / (1.0 + poisson))
    values.update(t.fields(LineType, names=tuple(n for n in sp if n not in values)))
    t.finish()
    return t.build(LineType, **values)


def _read_bore(t: Table, D: float, sp) -> float | None:
    """The inner diameter [m] from wall_thickness or inner_diameter; None when neither is
    given (a section given by its properties)."""
    if t.has("wall_thickness") and t.has("inner_diameter"):
        raise t.error("inner_diameter", "give either wall_thickness or inner_diameter, not both")
    if t.has("inner_diameter"):
        d = t.value("inner_diameter", sp, checked=True)
        check_bore(D, d, t.error)
        return d
    if t.has("wall_thickness"):
        wt = t.value("wall_thickness", FILE_KEYS["wall_thickness"], checked=True)
        if wt > D / 2:
            raise t.error("wall_thickness", f"must be <= the radius {D / 2:g} m, got {wt:g}")
        return D - 2.0 * wt
    return None


#: the hang-off angle of form (b), by the reference it is measured from; the key must
#: say which (a riser's hang-off angle is usually quoted from the vertical)
ANGLE_KEYS = ("hang_off_angle_from_horizontal_deg", "hang_off_angle_from_vertical_deg")

#: the keys of each form; hang_off_height belongs to two: without top_tension it is form
#: (b)'s (alone, it asks for its angle)
_END_FORMS = {
    TdpTensionEnds: ("tdp_tension",),
    HangOffAngleEnds: ("hang_off_height", *ANGLE_KEYS),
    TopTensionEnds: ("hang_off_height", "top_tension"),
    FixedEnds: ("anchor", "hang_off"),
}


def _read_ends(t: Table):
    if t.has("hang_off_angle_deg"):
        raise t.error("hang_off_angle_deg", "ambiguous: say which angle it is, "
                      "hang_off_angle_from_horizontal_deg or hang_off_angle_from_vertical_deg")
    present = [form for form, keys in _END_FORMS.items()
               if any(t.has(k) for k in keys if k != "hang_off_height") or (
                   form is HangOffAngleEnds and t.has("hang_off_height")
                   and not t.has("top_tension"))]
    if not present:
        raise t.error("", "give one of: tdp_tension; hang_off_height + "
                      "hang_off_angle_from_horizontal_deg (or _from_vertical_deg); "
                      "hang_off_height + top_tension; anchor + hang_off")
    if len(present) > 1:
        keys = list(dict.fromkeys(k for form in present for k in _END_FORMS[form] if t.has(k)))
        raise t.error(keys[-1], f"more than one [ends] form given ({', '.join(keys)}); "
                      "use exactly one")
    form = present[0]
    if form is HangOffAngleEnds:
        sp = dict(specs(HangOffAngleEnds))
        values = {"hang_off_height": t.value("hang_off_height", sp["hang_off_height"]),
                  "hang_off_angle_deg": _read_angle(t, sp["hang_off_angle_deg"])}
    elif form is TopTensionEnds:
        values = t.fields(TopTensionEnds, names=("top_tension",))
        if not t.has("hang_off_height"):
            raise t.error("hang_off_height", "required with top_tension (the J-lay form: "
                          "the hang-off height [m] and the effective tension there [N])")
        values.update(t.fields(TopTensionEnds, names=("hang_off_height",)))
    else:
        values = t.fields(form)
    for name, cls in (("anchor_joint", EndJoint), ("hang_off_joint", EndJoint),
                      ("tensioner", Tensioner)):
        if form is not FixedEnds:            # the joints and the tensioner hold fixed ends
            if t.has(name):
                raise t.error(name, "needs the fixed-ends form of [ends] (anchor + hang_off)")
            continue
        sub = t.table(name)
        if sub is not None:
            values[name] = _read_part(sub, cls)
    t.finish()
    return t.build(form, **values)


def _read_angle(t: Table, horizontal) -> float:
    """The hang-off angle from the horizontal [deg], given from either reference."""
    given = [k for k in ANGLE_KEYS if t.has(k)]
    if len(given) != 1:
        why = (" (both given)" if given else " with hang_off_height (or top_tension with "
               "it: the J-lay form)")
        raise t.error(ANGLE_KEYS[0], "give exactly one of hang_off_angle_from_horizontal_deg "
                      "and hang_off_angle_from_vertical_deg" + why)
    if given[0] == ANGLE_KEYS[0]:
        return t.value(ANGLE_KEYS[0], horizontal)
    return 90.0 - t.value(ANGLE_KEYS[1], ENDS_FILE_KEYS[ANGLE_KEYS[1]], checked=True)


def _read_waves(t: Table) -> Waves:
    """[environment.waves]: its keys, [[...trains]] and [...spectrum]."""
    values = t.fields(Waves)
    values["trains"] = tuple(_read_part(tr, WaveTrain)
                             for tr in t.array_of_tables("trains", required=False))
    sp = t.table("spectrum")
    if sp is not None:
        values["spectrum"] = _read_part(sp, WaveSpectrum)
    t.finish()
    return t.build(Waves, **values)


def _read_vessel(t: Table) -> Vessel:
    """[vessel] and its [[vessel.raos]] tables."""
    values = t.fields(Vessel)
    values["raos"] = tuple(_read_part(r, RAOTable) for r in t.array_of_tables("raos"))
    t.finish()
    return t.build(Vessel, **values)


def _read_design(t: Table) -> Design:
    """[design], its [design.fatigue] and [[design.fatigue.sea_states]]."""
    values = t.fields(Design)
    fat = t.table("fatigue")
    if fat is not None:
        cells = tuple(_read_part(c, SeaState)
                      for c in fat.array_of_tables("sea_states", required=False))
        values["fatigue"] = fat.build(Fatigue, **fat.fields(Fatigue), sea_states=cells)
        fat.finish()
    t.finish()
    return t.build(Design, **values)


def _read_dynamics(t: Table) -> Dynamics:
    values = t.fields(Dynamics)
    tm = t.table("top_motion")
    if tm is not None:
        per_axis = any(tm.has(f"displacements_{k}") for k in "xyz")
        if per_axis:                                  # a series per axis
            required = ("times",)
        elif tm.has("times") or tm.has("displacements"):
            required = ("axis", "times", "displacements")
        elif tm.has("amplitudes"):                    # an orbit
            required = ("amplitudes", "period")
        else:
            required = ("axis", "amplitude", "period")
        # every key given: the part's own checks name what does not belong to the form
        motion = tm.fields(TopMotion, required=required)
        tm.finish()
        values["top_motion"] = tm.build(TopMotion, **motion)
    t.finish()
    return t.build(Dynamics, **values)

"""Scene builders shared by the test modules.

Plain functions that return a scene as the scene file gives it: a dict of its tables (what
:func:`riser.io.scene_file.scene_from_dict` reads, i.e. a parsed TOML file) or TOML text
(:func:`riser.io.scene_file.parse_scene`), with keyword overrides; :func:`scene` and
:func:`rod` turn them into Scenes. Scenes are built through the file format only, never
with the ``Scene``/``Ends`` constructors: a test then sees exactly what a user's file
gives, and does not depend on how those classes are built.

- :func:`pipe`, :func:`small_pipe`: line type tables (keyword overrides; None removes a key);
- :func:`line`: one segment of one line type between fixed ends, further tables by keyword;
- :func:`straight`: a weightless line stretched horizontally between ends at one height;
- :func:`catenary`: a 150 m catenary riser with a touchdown on an elastic seabed;
- :func:`rod_toml` / :func:`rod`: the 1 cm rod of the closed-form tests (TOML);
- :func:`steel_line_toml`: the 110 m steel line with ``[design]`` of the design tests (TOML);
- :func:`scene`: dict -> Scene.
"""

from __future__ import annotations

import copy

from riser.io.scene_file import parse_scene, scene_from_dict

#: gravity [m/s2] and water density [kg/m3] the builders state (the scene file's defaults)
ENVIRONMENT = {"gravity": 9.81, "water_density": 1025.0}


def pipe(**keys) -> dict:
    """A ``[line_types.NAME]`` table: by default a 0.3 m pipe with a 0.25 m bore, 100 kg/m,
    EA 1e9 N and EI 1e7 N m2; ``keys`` override or add keys, a key given None is removed
    (e.g. ``inner_diameter=None`` for a solid section)."""
    table = {"outer_diameter": 0.3, "inner_diameter": 0.25, "mass_per_length": 100.0,
             "axial_stiffness": 1.0e9, "bending_stiffness": 1.0e7}
    table.update(keys)
    return {k: v for k, v in table.items() if v is not None}


def small_pipe(**keys) -> dict:
    """:func:`pipe` of a 0.1 m pipe with a 0.05 m bore, 20 kg/m, EA 1e7 N, EI 1e3 N m2,
    added mass and normal drag coefficients 1 (the line of :func:`catenary`)."""
    return pipe(**{"outer_diameter": 0.1, "inner_diameter": 0.05, "mass_per_length": 20.0,
                   "axial_stiffness": 1.0e7, "bending_stiffness": 1.0e3, "added_mass": 1.0,
                   "drag_normal": 1.0, **keys})


def line(length: float, anchor, hang_off, *, line_type: dict | None = None,
         submerged_weight: float | None = None, name: str = "t",
         environment: dict | None = None, **tables) -> dict:
    """A scene dict: one segment of ``length`` [m] of line type ``p`` (``line_type``, default
    :func:`pipe`) from the fixed ``anchor`` to the fixed ``hang_off`` ((x, y) [m]).
    ``submerged_weight`` [N/m]: the segment's, instead of the line type's; ``environment``:
    the ``[environment]`` table (omitted: the file's defaults, :data:`ENVIRONMENT`);
    ``tables``: further top-level tables (``seabed``, ``dynamics``, ``vfife``,
    ``internal_flow``, ...), a table given None is left out."""
    segment = {"line_type": "p", "length": length}
    if submerged_weight is not None:
        segment["submerged_weight"] = submerged_weight
    data = {"name": name,
            "line_types": {"p": copy.deepcopy(line_type) if line_type is not None else pipe()},
            "segments": [segment],
            "ends": {"anchor": list(anchor), "hang_off": list(hang_off)}}
    if environment is not None:
        data["environment"] = copy.deepcopy(environment)
    data.update({k: copy.deepcopy(v) for k, v in tables.items() if v is not None})
    return data


def straight(length: float, span: float, *, height: float = 50.0, **kw) -> dict:
    """A weightless (submerged weight 0) line of unstretched ``length`` [m] between fixed
    ends ``span`` [m] apart at the same ``height`` [m]: straight, stretched when
    ``length < span``; ``kw`` as for :func:`line`."""
    return line(length, (0.0, height), (span, height), submerged_weight=0.0, **kw)


def catenary(*, line_type: dict | None = None, seabed: dict | None = None, **kw) -> dict:
    """A small catenary riser with a touchdown (solved in a fraction of a second): 150 m of
    line (default :func:`small_pipe`, submerged weight 100 N/m) from an anchor at the
    origin on an elastic seabed (``seabed``, default k = 1e5 N/m2) to a hang-off at
    (100, 60) m; ``kw`` as for :func:`line`."""
    kw.setdefault("submerged_weight", 100.0)
    return line(150.0, (0.0, 0.0), (100.0, 60.0),
                line_type=line_type if line_type is not None else small_pipe(),
                seabed=seabed if seabed is not None else {"stiffness": 1.0e5}, **kw)


def scene(data: dict, source: str = "test"):
    """The Scene of a scene dict (read as a file's tables, validated as a file is)."""
    return scene_from_dict(data, source)


ROD = """\
name = "{name}"
[environment]
gravity = 9.81
water_density = 1025.0
{seabed}
[line_types.rod]
outer_diameter = 0.01
inner_diameter = 0.0
mass_per_length = {mass}
axial_stiffness = {EA}
bending_stiffness = {EI}
[[segments]]
line_type = "rod"
length = {L}
[ends]
{ends}
{extra}
"""


def rod_toml(*, mass, EI, L, ends: str, EA=1.0e9, name: str = "rod", seabed=None,
             extra: str = "") -> str:
    """TOML of a 1 cm solid rod (water density 1025 kg/m3, g 9.81 m/s2) of ``mass`` [kg/m],
    ``EA`` [N], ``EI`` [N m2] and length ``L`` [m]; ``ends``: the ``[ends]`` table's lines
    (e.g. ``"tdp_tension = 1.0e4"``); ``seabed``: its stiffness [N/m2] (None: no
    ``[seabed]``); ``extra``: further tables (e.g. ``'[model]\\naxial = "inextensible"'``).
    Numbers are written as ``str`` gives them."""
    return ROD.format(name=name, mass=mass, EA=EA, EI=EI, L=L, ends=ends, extra=extra,
                      seabed=f"[seabed]\nstiffness = {seabed!r}" if seabed is not None else "")


def rod(**kw):
    """The Scene of :func:`rod_toml` (source ``rod.toml``)."""
    return parse_scene(rod_toml(**kw), "rod.toml")


def steel_line_toml(name: str, *, line_type: str = "", design: str = "", tail: str = "") -> str:
    """The 110 m steel pipe (8 in, 19.1 mm wall, X65 strengths) from a seabed anchor to a
    hang-off 80 m across and 50 m up in 60 m of water, with an empty-or-given ``[design]``
    table, as TOML text: the line of the design-check, fatigue-verdict, bend-limit and
    station tests. ``line_type``: more lines of ``[line_types.steel]``; ``design``: lines of
    ``[design]``; ``tail``: tables after it. Each ends in a newline."""
    return f"""
name = "{name}"
[environment]
water_depth = 60.0
[seabed]
stiffness = 1.0e5
[line_types.steel]
outer_diameter = 0.2032
wall_thickness = 0.0191
density = 7860.0
youngs_modulus = 2.06e11
yield_strength = 4.48e8
tensile_strength = 5.31e8
{line_type}[[segments]]
line_type = "steel"
length = 110.0
[ends]
anchor = [0.0, 0.0]
hang_off = [80.0, 50.0]
[design]
{design}{tail}"""

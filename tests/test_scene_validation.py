"""Scene-file loader: the issue-2 contract (section 2) and its validation errors.

Every bad scene must end in ONE line ``scene.toml: <key path>: <what is allowed>``
(a :class:`SceneError`), never a traceback; the CLI turns it into exit code 2.
"""

from __future__ import annotations

import json
import math
import re
import tomllib

import pytest

from riser.errors import SceneError
from riser.io.scene_file import load_scene, parse_scene
from riser.model.scene import FixedEnds
from riser.model.sections import segment_properties
from verification.catalog import builtin_paths

SRC = "scene.toml"

# The built-in wang2014-baseline scene (tdp_tension form), comments dropped.
WANG = """\
name = "wang2014-baseline"
title = "Wang et al. (2014) steel lazy-wave riser, baseline, no current"
source = "Wang, Duan & Tian (2014), Appl. Math. Mech. 35(9), Tables 1-2"

[environment]
gravity = 9.8
water_density = 1024.0

[line_types.steel]
outer_diameter = 0.2032
wall_thickness = 0.0191
density = 7860.0
youngs_modulus = 2.06e11
drag_normal = 1.0
drag_tangential = 0.03

[[segments]]
line_type = "steel"
length = 390.00
label = "lower catenary O-A"

[[segments]]
line_type = "steel"
length = 520.0
weight_scale = -1.0
label = "buoyancy section A-C"

[[segments]]
line_type = "steel"
length = 1690.0
label = "upper catenary C-E"

[ends]
tdp_tension = 160000.0
"""

# Fixed-ends variant (form (c)) with every optional table: water depth, current, seabed,
# inner_diameter + mass_per_length + explicit stiffnesses, segment options, [bvp].
# Line length 1000 m > chord hypot(600, 500) = 781 m.
FIXED = """\
name = "fixed-ends"

[environment]
gravity = 9.81
water_density = 1025.0
water_depth = 500.0

[environment.current]
heights = [0.0, 500.0]
speeds = [0.0, 1.2]
heading_deg = 0.0

[seabed]
stiffness = 1.0e5
friction = 0.3

[line_types.steel]
outer_diameter = 0.2032
inner_diameter = 0.165
mass_per_length = 86.8
axial_stiffness = 2.0e9
bending_stiffness = 1.0e7
drag_normal = 1.0
drag_tangential = 0.03
added_mass = 1.0
contents_density = 800.0

[[segments]]
line_type = "steel"
length = 400.0
buoyancy = 100.0
hydro_diameter = 0.5
label = "lower"

[[segments]]
line_type = "steel"
length = 600.0
submerged_weight = 300.0
label = "upper"

[ends]
anchor = [0.0, 0.0]
hang_off = [600.0, 500.0]

[bvp]
tolerance = 1.0e-6
max_nodes = 30000
"""

BASES = {"wang": WANG, "fixed": FIXED}


def mutate(base: str, old: str, new: str) -> str:
    """Replace the single occurrence of ``old`` (so a typo in a case cannot pass silently)."""
    assert base.count(old) == 1, f"{old!r} occurs {base.count(old)} times in the baseline"
    return base.replace(old, new)


def drop_segments(text: str) -> str:
    return re.sub(r"\[\[segments\]\][^\[]*", "", text)


def load_error(text: str) -> str:
    """The message of the SceneError that parsing ``text`` must raise, checked for form."""
    with pytest.raises(SceneError) as info:
        parse_scene(text, SRC)
    msg = str(info.value)
    assert "\n" not in msg and "\r" not in msg, f"error is not one line: {msg!r}"
    assert msg.startswith(f"{SRC}: "), msg
    return msg


# ------------------------------------------------------------------ 1. each validation rule
W, F = "wang", "fixed"
CASES = [
    # (id, base, old, new, key path, hints that must appear in the message)
    # unknown keys, one per table kind
    ("unknown-root", W, 'name = "wang2014-baseline"\n', 'name = "wang2014-baseline"\ncolour = "red"\n',
     "colour", ["unknown key", "known keys here"]),
    ("unknown-environment", W, "gravity = 9.8\n", "gravity = 9.8\ngravty = 9.8\n",
     "environment.gravty", ["unknown key"]),
    ("unknown-current", F, "heading_deg = 0.0\n", "heading_deg = 0.0\nheading = 0.0\n",
     "environment.current.heading", ["unknown key"]),
    ("unknown-seabed", F, "friction = 0.3\n", "friction = 0.3\nfriction_coef = 0.3\n",
     "seabed.friction_coef", ["unknown key"]),
    ("unknown-line-type", W, "drag_normal = 1.0\n", "drag_normal = 1.0\nCd = 1.0\n",
     "line_types.steel.Cd", ["unknown key"]),
    ("unknown-segment", W, "length = 1690.0\n", "length = 1690.0\nlenght = 5.0\n",
     "segments[2].lenght", ["unknown key"]),
    ("unknown-ends", W, "tdp_tension = 160000.0\n", "tdp_tension = 160000.0\ntdp_angle = 5.0\n",
     "ends.tdp_angle", ["unknown key"]),
    ("unknown-ends-fixed", F, "hang_off = [600.0, 500.0]\n", "hang_off = [600.0, 500.0]\nfairlead = 1.0\n",
     "ends.fairlead", ["unknown key"]),
    ("unknown-bvp", F, "tolerance = 1.0e-6\n", "tolerance = 1.0e-6\ntol = 1.0e-6\n",
     "bvp.tol", ["unknown key"]),
    # missing required keys
    ("missing-name", W, 'name = "wang2014-baseline"\n', "", "name", ["required key is missing"]),
    ("missing-line_types", W, "[line_types.steel]", "[materials.steel]",
     "line_types", ["required table is missing"]),
    ("missing-segment-length", W, "length = 520.0\n", "", "segments[1].length", ["required"]),
    ("missing-segment-line_type", W, 'line_type = "steel"\nlength = 520.0', "length = 520.0",
     "segments[1].line_type", ["required"]),
    ("missing-outer_diameter", W, "outer_diameter = 0.2032\n", "",
     "line_types.steel.outer_diameter", ["required"]),
    # without a wall dimension the density cannot give a mass (issue 13: a section may be
    # given by mass_per_length, EA and EI alone)
    ("missing-wall-or-inner", W, "wall_thickness = 0.0191\n", "",
     "line_types.steel.density", ["needs wall_thickness or inner_diameter", "mass_per_length"]),
    ("missing-density-or-mass", W, "density = 7860.0\n", "", "line_types.steel.density", ["required"]),
    # the Wang base is inextensible (its end form's default): only EI is needed
    ("missing-youngs-or-stiffnesses", W, "youngs_modulus = 2.06e11\n", "",
     "line_types.steel.bending_stiffness", ["required when youngs_modulus is not given"]),
    ("missing-axial-stiffness-extensible", F, "axial_stiffness = 2.0e9\n", "",
     "line_types.steel.axial_stiffness", ["required for the extensible model",
                                          "default for fixed ends", "inextensible"]),
    ("missing-bending-stiffness", F, "bending_stiffness = 1.0e7\n", "",
     "line_types.steel.bending_stiffness", ["required when youngs_modulus is not given"]),
    ("missing-current-heights", F, "heights = [0.0, 500.0]\n", "",
     "environment.current.heights", ["required"]),
    ("missing-seabed-stiffness", F, "stiffness = 1.0e5\n", "", "seabed.stiffness", ["required"]),
    ("missing-hang_off", F, "hang_off = [600.0, 500.0]\n", "", "ends.hang_off", ["required"]),
    ("missing-hang_off_angle", W, "tdp_tension = 160000.0", "hang_off_height = 1586.3",
     "ends.hang_off_angle_from_horizontal_deg", ["exactly one", "_from_vertical_deg"]),
    ("missing-ends-form", W, "tdp_tension = 160000.0", "",
     "ends", ["give one of", "tdp_tension", "anchor + hang_off"]),
    # wrong types
    ("string-for-number", W, "length = 390.00", 'length = "390"',
     "segments[0].length", ["must be a number, got a string"]),
    ("bool-for-number", W, "outer_diameter = 0.2032", "outer_diameter = true",
     "line_types.steel.outer_diameter", ["must be a number, got a boolean"]),
    ("date-for-number", W, "density = 7860.0", "density = 2024-01-01",
     "line_types.steel.density", ["must be a number"]),
    ("number-for-name", W, 'name = "wang2014-baseline"', "name = 5", "name", ["must be a string"]),
    ("number-for-line_type", W, 'line_type = "steel"\nlength = 390.00', "line_type = 3\nlength = 390.00",
     "segments[0].line_type", ["must be a string"]),
    ("number-for-label", W, 'label = "upper catenary C-E"', "label = 1.0",
     "segments[2].label", ["must be a string"]),
    ("table-for-array", F, "heights = [0.0, 500.0]", "heights = { a = 0.0 }",
     "environment.current.heights", ["must be an array"]),
    ("number-for-array", F, "anchor = [0.0, 0.0]", "anchor = 0.0", "ends.anchor", ["must be an array"]),
    ("string-in-array", F, "speeds = [0.0, 1.2]", 'speeds = [0.0, "1.2"]',
     "environment.current.speeds[1]", ["must be a number"]),
    ("short-array", F, "anchor = [0.0, 0.0]", "anchor = [0.0]", "ends.anchor", ["must have 2 or 3 entries"]),
    ("number-for-table", W, "[environment]\ngravity = 9.8\nwater_density = 1024.0\n", "environment = 5\n",
     "environment", ["must be a table"]),
    ("array-for-ends-table", W, "[ends]", "[[ends]]", "ends", ["must be a table"]),
    ("float-for-integer", F, "max_nodes = 30000", "max_nodes = 3.0e4", "bvp.max_nodes",
     ["must be an integer"]),
    # non-positive lengths / diameters / densities / stiffnesses
    ("length-negative", W, "length = 1690.0", "length = -5", "segments[2].length", ["must be > 0", "got -5"]),
    ("length-zero", W, "length = 390.00", "length = 0.0", "segments[0].length", ["must be > 0"]),
    ("outer-diameter-zero", W, "outer_diameter = 0.2032", "outer_diameter = 0.0",
     "line_types.steel.outer_diameter", ["must be > 0"]),
    ("outer-diameter-negative", W, "outer_diameter = 0.2032", "outer_diameter = -0.2",
     "line_types.steel.outer_diameter", ["must be > 0"]),
    ("wall-zero", W, "wall_thickness = 0.0191", "wall_thickness = 0.0",
     "line_types.steel.wall_thickness", ["must be > 0"]),
    ("inner-diameter-negative", F, "inner_diameter = 0.165", "inner_diameter = -0.1",
     "line_types.steel.inner_diameter", ["must be >= 0"]),
    ("density-zero", W, "density = 7860.0", "density = 0.0", "line_types.steel.density", ["must be > 0"]),
    ("density-negative", W, "density = 7860.0", "density = -7860.0",
     "line_types.steel.density", ["must be > 0"]),
    ("mass-negative", F, "mass_per_length = 86.8", "mass_per_length = -1.0",
     "line_types.steel.mass_per_length", ["must be > 0"]),
    ("water-density-zero", W, "water_density = 1024.0", "water_density = 0.0",
     "environment.water_density", ["must be >= 500"]),
    ("contents-density-negative", F, "contents_density = 800.0", "contents_density = -1.0",
     "line_types.steel.contents_density", ["must be >= 0"]),
    ("hydro-diameter-zero", F, "hydro_diameter = 0.5", "hydro_diameter = 0.0",
     "segments[0].hydro_diameter", ["must be > 0"]),
    ("bending-stiffness-zero", F, "bending_stiffness = 1.0e7", "bending_stiffness = 0.0",
     "line_types.steel.bending_stiffness", ["must be > 0"]),
    ("tdp-tension-zero", W, "tdp_tension = 160000.0", "tdp_tension = 0.0", "ends.tdp_tension", ["must be > 0"]),
    ("seabed-stiffness-negative", F, "stiffness = 1.0e5", "stiffness = -1.0e5",
     "seabed.stiffness", ["must be > 0"]),
    # NaN / inf (TOML nan, inf)
    ("length-nan", W, "length = 520.0", "length = nan", "segments[1].length", ["must be a finite number"]),
    ("diameter-inf", W, "outer_diameter = 0.2032", "outer_diameter = inf",
     "line_types.steel.outer_diameter", ["must be a finite number"]),
    ("youngs-nan", W, "youngs_modulus = 2.06e11", "youngs_modulus = -nan",
     "line_types.steel.youngs_modulus", ["must be a finite number"]),
    ("density-minus-inf", W, "density = 7860.0", "density = -inf",
     "line_types.steel.density", ["must be a finite number"]),
    ("gravity-nan", W, "gravity = 9.8", "gravity = nan", "environment.gravity", ["must be a finite number"]),
    ("height-nan", F, "heights = [0.0, 500.0]", "heights = [0.0, nan]",
     "environment.current.heights[1]", ["must be a finite number"]),
    ("anchor-inf", F, "anchor = [0.0, 0.0]", "anchor = [inf, 0.0]", "ends.anchor[0]", ["must be a finite number"]),
    ("tension-overflow-float", W, "tdp_tension = 160000.0", "tdp_tension = 1e999",
     "ends.tdp_tension", ["must be a finite number"]),
    ("tension-huge-integer", W, "tdp_tension = 160000.0", "tdp_tension = 1" + "0" * 400,
     "ends.tdp_tension", ["must be a finite number"]),
    # section geometry
    ("wall-thicker-than-radius", W, "wall_thickness = 0.0191", "wall_thickness = 0.15",
     "line_types.steel.wall_thickness", ["must be <= the radius 0.1016 m", "got 0.15"]),
    ("inner-not-below-outer", F, "inner_diameter = 0.165", "inner_diameter = 0.2032",
     "line_types.steel.inner_diameter", ["must be < 0.2032 m"]),
    ("wall-and-inner", W, "wall_thickness = 0.0191\n", "wall_thickness = 0.0191\ninner_diameter = 0.165\n",
     "line_types.steel.inner_diameter", ["either wall_thickness or inner_diameter, not both"]),
    ("density-and-mass", W, "density = 7860.0\n", "density = 7860.0\nmass_per_length = 86.8\n",
     "line_types.steel.mass_per_length", ["either density or mass_per_length, not both"]),
    # current arrays
    ("heights-unsorted", F, "heights = [0.0, 500.0]", "heights = [500.0, 0.0]",
     "environment.current.heights[1]", ["strictly increasing", "must be > heights[0] = 500"]),
    ("heights-repeated", F, "heights = [0.0, 500.0]", "heights = [100.0, 100.0]",
     "environment.current.heights[1]", ["strictly increasing"]),
    ("speeds-too-many", F, "speeds = [0.0, 1.2]", "speeds = [0.0, 1.2, 1.5]",
     "environment.current.speeds", ["as many entries as heights (2), got 3"]),
    ("speeds-too-few", F, "speeds = [0.0, 1.2]", "speeds = [1.2]",
     "environment.current.speeds", ["as many entries as heights (2), got 1"]),
    ("heights-empty", F, "heights = [0.0, 500.0]", "heights = []",
     "environment.current.heights", ["at least 1"]),
    ("speed-too-fast", F, "speeds = [0.0, 1.2]", "speeds = [0.0, 12.0]",
     "environment.current.speeds[1]", ["must be <= 10 m/s"]),
    ("heading-out-of-range", F, "heading_deg = 0.0", "heading_deg = 400.0",
     "environment.current.heading_deg", ["must be <= 360 deg"]),
    # references and [ends] forms
    ("unknown-line-type-ref", W, 'line_type = "steel"\nlength = 520.0', 'line_type = "titanium"\nlength = 520.0',
     "segments[1].line_type", ["unknown line type 'titanium'", "'steel'"]),
    ("ends-tdp-and-angle", W, "tdp_tension = 160000.0", "tdp_tension = 160000.0\nhang_off_height = 1500.0\n"
     "hang_off_angle_from_horizontal_deg = 80.0", "ends.hang_off_angle_from_horizontal_deg", ["more than one [ends] form", "exactly one"]),
    ("ends-tdp-and-fixed", F, "anchor = [0.0, 0.0]", "tdp_tension = 1.0e5\nanchor = [0.0, 0.0]",
     "ends.hang_off", ["more than one [ends] form", "tdp_tension"]),
    ("ends-angle-and-fixed", F, "anchor = [0.0, 0.0]", "hang_off_height = 400.0\nanchor = [0.0, 0.0]",
     "ends.hang_off", ["more than one [ends] form", "hang_off_height"]),
    ("angle-over-90", W, "tdp_tension = 160000.0", "hang_off_height = 1500.0\nhang_off_angle_from_horizontal_deg = 95.0",
     "ends.hang_off_angle_from_horizontal_deg", ["must be <= 90 deg"]),
    ("angle-from-vertical-90", W, "tdp_tension = 160000.0", "hang_off_height = 1500.0\n"
     "hang_off_angle_from_vertical_deg = 90.0", "ends.hang_off_angle_from_vertical_deg",
     ["must be < 90 deg"]),
    # issue 13: an angle whose reference is not named is ambiguous, and two are too many
    ("angle-ambiguous", W, "tdp_tension = 160000.0", "hang_off_height = 1500.0\n"
     "hang_off_angle_deg = 12.0", "ends.hang_off_angle_deg", ["ambiguous", "_from_vertical_deg"]),
    ("angle-both-references", W, "tdp_tension = 160000.0", "hang_off_height = 1500.0\n"
     "hang_off_angle_from_vertical_deg = 12.0\nhang_off_angle_from_horizontal_deg = 78.0",
     "ends.hang_off_angle_from_horizontal_deg", ["exactly one", "both given"]),
    # [model]: the continuum model (docs/theory.md, "One model, two methods")
    ("model-axial-unknown", F, "[bvp]", "[model]\naxial = \"stretchy\"\n[bvp]", "model.axial",
     ["must be one of 'extensible', 'inextensible'"]),
    ("model-elastic-seabed-wang-form", W, "tdp_tension = 160000.0",
     "tdp_tension = 160000.0\n[model]\nseabed = \"elastic\"", "model.seabed",
     ["needs fixed ends", "rigid"]),
    # geometry of fixed ends
    # an extensible line may be taut (it stretches); an inextensible one cannot reach
    ("line-shorter-than-chord", F, "hang_off = [600.0, 500.0]",
     "hang_off = [900.0, 500.0]\n[model]\naxial = \"inextensible\"",
     "segments", ["line length 1000 m is not longer than the distance 1029.56 m",
                  "inextensible"]),
    ("line-shorter-than-height", W, "tdp_tension = 160000.0",
     "hang_off_height = 3000.0\nhang_off_angle_from_horizontal_deg = 80.0", "segments", ["cannot reach", "3000"]),
    ("hang-off-below-seabed", F, "hang_off = [600.0, 500.0]", "hang_off = [600.0, -10.0]",
     "ends.hang_off[1]", ["must be > 0", "seabed"]),
    ("hang-off-on-seabed", F, "hang_off = [600.0, 500.0]", "hang_off = [600.0, 0.0]",
     "ends.hang_off[1]", ["must be > 0", "seabed"]),
    ("hang-off-above-surface", F, "hang_off = [600.0, 500.0]", "hang_off = [600.0, 600.0]",
     "ends.hang_off[1]", ["must be <= water_depth 500 m"]),
    ("hang-off-height-above-surface", F, "anchor = [0.0, 0.0]\nhang_off = [600.0, 500.0]",
     "hang_off_height = 600.0\nhang_off_angle_from_horizontal_deg = 80.0", "ends.hang_off_height",
     ["must be <= water_depth 500 m"]),
    ("hang-off-behind-anchor", F, "hang_off = [600.0, 500.0]", "hang_off = [-600.0, 500.0]",
     "ends.hang_off[0]", ["must be >= anchor[0] = 0"]),
    ("anchor-below-seabed", F, "anchor = [0.0, 0.0]", "anchor = [0.0, -1.0]",
     "ends.anchor[1]", ["must be >= 0", "seabed"]),
    # unit slips by ~1e3, caught by the plausible ranges
    ("diameter-in-mm", W, "outer_diameter = 0.2032", "outer_diameter = 203.2",
     "line_types.steel.outer_diameter", ["must be <= 5 m", "got 203.2"]),
    ("wall-in-mm", W, "wall_thickness = 0.0191", "wall_thickness = 19.1",
     "line_types.steel.wall_thickness", ["radius"]),
    ("youngs-in-GPa", W, "youngs_modulus = 2.06e11", "youngs_modulus = 206",
     "line_types.steel.youngs_modulus", ["must be >= 1e+06 Pa", "got 206"]),
    ("length-in-mm", W, "length = 1690.0", "length = 1690000.0", "segments[2].length", ["must be <= 50000 m"]),
    ("mass-in-g-per-m", F, "mass_per_length = 86.8", "mass_per_length = 86800.0",
     "line_types.steel.mass_per_length", ["must be <= 10000 kg/m"]),
    ("water-density-in-t-per-m3", W, "water_density = 1024.0", "water_density = 1.024",
     "environment.water_density", ["must be >= 500 kg/m3"]),
    ("tension-in-mN", W, "tdp_tension = 160000.0", "tdp_tension = 1.6e11",
     "ends.tdp_tension", ["must be <= 1e+09 N"]),
    # name pattern
    ("name-uppercase-space", W, 'name = "wang2014-baseline"', 'name = "Wang 2014"', "name", ["must match"]),
    ("name-leading-dash", W, 'name = "wang2014-baseline"', 'name = "-wang"', "name", ["must match"]),
    ("name-empty", W, 'name = "wang2014-baseline"', 'name = ""', "name", ["must match"]),
    ("name-underscore", W, 'name = "wang2014-baseline"', 'name = "wang_2014"', "name", ["must match"]),
    # keys that cannot be printed on one line as they are (quoted in the message)
    ("unknown-key-with-newline", W, "tdp_tension = 160000.0", 'tdp_tension = 160000.0\n"a\\nb" = 1',
     "ends.'a\\nb'", ["unknown key"]),
]


@pytest.mark.parametrize("case_id,base,old,new,path,hints", CASES, ids=[c[0] for c in CASES])
def test_validation_rule(case_id, base, old, new, path, hints):
    # protects: each issue-2 validation rule gives one line "scene.toml: <exact key path>: <allowed>"
    msg = load_error(mutate(BASES[base], old, new))
    assert msg.startswith(f"{SRC}: {path}: "), msg
    for hint in hints:
        assert hint in msg, msg


def test_missing_segments_array():
    # protects: a scene without [[segments]] names the missing array
    msg = load_error(drop_segments(WANG))
    assert msg.startswith(f"{SRC}: segments: required array of tables is missing"), msg


def test_segments_as_plain_table():
    # protects: [segments] (a table) instead of [[segments]] is a type error, not a traceback
    msg = load_error(drop_segments(WANG) + '\n[segments]\nline_type = "steel"\nlength = 10.0\n')
    assert msg.startswith(f"{SRC}: segments: must be an array of tables"), msg


def test_missing_ends_table():
    # protects: a scene without [ends] names the missing table
    msg = load_error(mutate(WANG, "[ends]\ntdp_tension = 160000.0\n", ""))
    assert msg.startswith(f"{SRC}: ends: required table is missing"), msg


@pytest.mark.parametrize("bad", [
    pytest.param(('name = "wang2014-baseline"', 'name = "wang2014-baseline'), id="unterminated-string"),
    pytest.param(("gravity = 9.8\n", "gravity = 9.8\ngravity = 9.8\n"), id="duplicate-key"),
    pytest.param(("length = 390.00", "length = 390.00.0"), id="bad-number"),
    pytest.param(("[ends]", "[ends"), id="unclosed-header"),
    pytest.param(("tdp_tension = 160000.0", "tdp_tension = " + "9" * 5000), id="int-over-4300-digits"),
])
def test_invalid_toml(bad):
    # protects: TOML syntax errors (and integers Python refuses to parse) are one-line SceneErrors
    msg = load_error(mutate(WANG, *bad))
    assert msg.startswith(f"{SRC}: not valid TOML ("), msg


def test_unknown_line_type_with_unprintable_names_stays_one_line():
    # protects: the "defined: ..." list of line types cannot break the one-line error
    text = mutate(WANG, "[line_types.steel]", '[line_types."a\\nb"]\nouter_diameter = 0.2\n'
                  "wall_thickness = 0.01\ndensity = 7800.0\nyoungs_modulus = 2e11\n\n[line_types.steel]")
    text = text.replace('line_type = "steel"\nlength = 390.00', 'line_type = "x"\nlength = 390.00')
    msg = load_error(text)
    assert msg.startswith(f"{SRC}: segments[0].line_type: unknown line type 'x'"), msg


# ------------------------------------------------------------------ 2. generated mutation table
def dump_toml(data: dict) -> str:
    """A minimal TOML writer for scene dictionaries (scalars, arrays, tables, arrays of tables)."""
    def key(k):
        return k if re.fullmatch(r"[A-Za-z0-9_-]+", k) else json.dumps(k)

    def value(v):
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, str):
            return json.dumps(v)
        if isinstance(v, float):
            if math.isnan(v):
                return "nan"
            if math.isinf(v):
                return "inf" if v > 0 else "-inf"
            return repr(v)
        if isinstance(v, int):
            return str(v)
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        if isinstance(v, dict):
            return "{ " + ", ".join(f"{key(k)} = {value(x)}" for k, x in v.items()) + " }"
        raise TypeError(type(v))

    def is_aot(v):
        return isinstance(v, list) and v and all(isinstance(x, dict) for x in v)

    def table(d, prefix):
        lines = [f"{key(k)} = {value(v)}" for k, v in d.items()
                 if not isinstance(v, dict) and not is_aot(v)]
        for k, v in d.items():
            name = ".".join(key(p) for p in prefix + [k])
            if isinstance(v, dict):
                lines += ["", f"[{name}]"] + table(v, prefix + [k])
            elif is_aot(v):
                for item in v:
                    lines += ["", f"[[{name}]]"] + table(item, prefix + [k])
        return lines

    return "\n".join(table(data, [])) + "\n"


def path_str(path: tuple) -> str:
    out = ""
    for p in path:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else p)
    return out


def leaves(node, path=()):
    """Every leaf of a parsed scene: scalars, arrays of numbers, and the arrays' elements."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from leaves(v, path + (k,))
    elif isinstance(node, list) and node and all(isinstance(x, dict) for x in node):
        for i, v in enumerate(node):
            yield from leaves(v, path + (i,))
    else:
        yield path, node
        if isinstance(node, list):
            for i, v in enumerate(node):
                yield path + (i,), v


# Leaves whose removal must be an error naming them (the rest are optional, or are a
# whole-array element whose removal is caught as a length mismatch).
REQUIRED = {
    "wang": {"name", "line_types.steel.outer_diameter", "line_types.steel.wall_thickness",
             "line_types.steel.density", "line_types.steel.youngs_modulus",
             "segments[0].line_type", "segments[0].length", "segments[1].line_type",
             "segments[1].length", "segments[2].line_type", "segments[2].length",
             "ends.tdp_tension"},
    "fixed": {"name", "environment.current.heights", "environment.current.speeds",
              "seabed.stiffness", "line_types.steel.outer_diameter",
              "line_types.steel.inner_diameter", "line_types.steel.mass_per_length",
              "line_types.steel.axial_stiffness",
              "line_types.steel.bending_stiffness", "segments[0].line_type",
              "segments[0].length", "segments[1].line_type", "segments[1].length",
              "ends.anchor", "ends.hang_off"},
}
# Where the blamed key is another one than the mutated leaf, by design.
BLAMED = {
    # the youngs_modulus alternative is reported by the stiffness the (inextensible) Wang
    # model needs
    ("wang", "line_types.steel.youngs_modulus", "removed"): "line_types.steel.bending_stiffness",
    # a missing [ends] key leaves no form at all
    ("wang", "ends.tdp_tension", "removed"): "ends",
    # the other form of a pair is required (issue 13: no wall dimension is needed for a
    # section given by its properties; the Wang base's density needs its wall_thickness)
    ("wang", "line_types.steel.wall_thickness", "removed"): "line_types.steel.density",
    ("fixed", "line_types.steel.mass_per_length", "removed"): "line_types.steel.density",
    # the fixed base holds contents: its bore is needed, and named by the contents
    ("fixed", "line_types.steel.inner_diameter", "removed"): "line_types.steel.contents_density",
}
REMOVED = object()
VARIANTS = {
    "removed": REMOVED, "string": "Not Valid", "bool": True, "minus1": -1, "zero": 0,
    "nan": float("nan"), "1e30": 1e30, "unknown-sibling": "unknown",
}


def mutation_cases():
    for base_name, text in BASES.items():
        for path, original in leaves(tomllib.loads(text)):
            for variant in VARIANTS:
                if variant == "unknown-sibling" and isinstance(path[-1], int):
                    continue            # an array element has no sibling keys
                yield pytest.param(base_name, path, original, variant,
                                   id=f"{base_name}:{path_str(path)}:{variant}")


@pytest.mark.parametrize("base_name,path,original,variant", list(mutation_cases()))
def test_mutation_table(base_name, path, original, variant):
    # protects: no single-leaf mutation of a valid scene escapes as anything but a one-line SceneError
    data = tomllib.loads(BASES[base_name])
    parent = data
    for p in path[:-1]:
        parent = parent[p]
    if variant == "removed":
        del parent[path[-1]]
    elif variant == "unknown-sibling":
        parent["zz_unknown_key"] = 1.0
    else:
        parent[path[-1]] = VARIANTS[variant]
    text = dump_toml(data)
    name = path_str(path)
    is_element = isinstance(path[-1], int)
    numeric = isinstance(original, (int, float)) and not isinstance(original, bool)
    must_fail = (
        variant in ("bool", "nan", "1e30", "unknown-sibling")
        or (variant == "removed" and name in REQUIRED[base_name])
        or (variant == "string" and not isinstance(original, str))
        or (variant in ("minus1", "zero") and not numeric)
    )
    # optional keys may be left out, and free-text keys take any string
    must_load = ((variant == "removed" and not is_element and name not in REQUIRED[base_name])
                 or (variant == "string" and name.split(".")[-1] in ("title", "source", "label")))
    try:
        parse_scene(text, SRC)
    except SceneError as exc:
        msg = str(exc)
        assert "\n" not in msg and "\r" not in msg, msg
        assert msg.startswith(f"{SRC}: "), msg
        assert not must_load, f"{name} {variant}: optional/free-text but rejected: {msg}"
        if variant == "unknown-sibling":
            blamed = path_str(path[:-1] + ("zz_unknown_key",))
        elif variant == "removed" and is_element:
            blamed = path_str(path[:-2])            # a length check on a sibling array
        else:
            blamed = BLAMED.get((base_name, name, variant), name)
        assert msg.startswith(f"{SRC}: {blamed}"), f"{msg!r} does not name {blamed}"
    else:
        assert not must_fail, f"{name} {variant}: loaded but must be rejected"


def test_mutation_table_covers_every_key():
    # protects: the generated table really walks every leaf of both baselines
    ids = {p.id for p in mutation_cases()}
    assert "wang:segments[2].length:nan" in ids
    assert "fixed:environment.current.heights[1]:zero" in ids
    assert "fixed:bvp.max_nodes:unknown-sibling" in ids
    assert len(ids) > 300


def test_baselines_round_trip_through_dumper():
    # protects: the mutation table starts from valid scenes and the writer preserves them
    for text in BASES.values():
        data = tomllib.loads(text)
        assert tomllib.loads(dump_toml(data)) == data
        parse_scene(dump_toml(data), SRC)


# ------------------------------------------------------------------ 3. command line
@pytest.mark.parametrize("old,new,expected", [
    pytest.param("length = 1690.0", "length = -5", "error: scene.toml: segments[2].length: must be > 0 m, got -5",
                 id="negative-length"),
    pytest.param("length = 520.0", "length = nan", "error: scene.toml: segments[1].length: must be a finite",
                 id="nan"),
    pytest.param("gravity = 9.8\n", "gravity = 9.8\ngravty = 9.8\n",
                 "error: scene.toml: environment.gravty: unknown key", id="unknown-key"),
    pytest.param("[ends]", "[ends", "error: scene.toml: not valid TOML (", id="invalid-toml"),
])
def test_cli_bad_scene_exit_2(tmp_path, old, new, expected, run_cli):
    # protects: a bad scene file -> exit 2 and exactly one "error: scene.toml: ..." line, no traceback
    scene = tmp_path / "scene.toml"
    scene.write_text(mutate(WANG, old, new))
    out_dir = tmp_path / "out"
    code, out, err = run_cli(["solve", str(scene), "--out", str(out_dir)])
    assert code == 2
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith(expected), err
    assert "Traceback" not in err + out
    assert not out_dir.exists()


def test_cli_missing_file_exit_2(tmp_path, run_cli):
    # protects: a scene path that does not exist -> exit 2 with one error line
    code, out, err = run_cli(["solve", str(tmp_path / "nope.toml"), "--out", str(tmp_path / "o")])
    assert code == 2
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and "nope.toml" in lines[0], err
    assert "cannot read file" in lines[0]


def test_cli_unknown_builtin_exit_2(tmp_path, run_cli):
    # protects: a name that is neither a file nor a built-in scene -> exit 2 with one error line
    code, out, err = run_cli(["solve", "no-such-scene", "--out", str(tmp_path / "o")])
    assert code == 2
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: no-such-scene: no such file"), err


def test_cli_touchdown_form_in_a_cross_current_bvp_exit_2(tmp_path, run_cli):
    # protects: bvp refuses a touchdown form under a current across its plane at the
    # seabed (a rigid frictionless seabed cannot hold the grounded line) with exit 2
    scene = tmp_path / "scene.toml"
    scene.write_text(mutate(WANG, "[line_types.steel]", "[environment.current]\nheights = [0.0]\n"
                            "speeds = [0.5]\nheading_deg = 90.0\n\n[line_types.steel]"))
    code, out, err = run_cli(["solve", str(scene), "--method", "bvp", "--out", str(tmp_path / "o")])
    assert code == 2
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: scene.toml: "), err
    assert "frictionless seabed" in lines[0] and "environment.current" in lines[0]
    assert "Traceback" not in err + out


# ------------------------------------------------------------------ 4. valid scenes
@pytest.mark.parametrize("path", sorted(builtin_paths().values()), ids=lambda p: p.stem)
def test_builtin_scene_loads(path):
    # protects: every shipped scene is valid and named after its file
    scene = load_scene(path)
    assert scene.name == path.stem
    assert scene.source == path.name
    assert scene.total_length > 0 and scene.segments


def test_builtin_wang_matches_module_baseline():
    # protects: the WANG string in this module is the shipped baseline (same parsed scene)
    shipped = load_scene(builtin_paths()["wang2014-baseline"])
    assert parse_scene(WANG, "wang2014-baseline.toml") == shipped


def test_optional_tables_accepted():
    # protects: the fixed-ends baseline with every optional table loads with the given values
    scene = parse_scene(FIXED, SRC)
    assert scene.water_depth == 500.0 and scene.seabed.stiffness == 1.0e5
    assert scene.current.heights == (0.0, 500.0) and scene.current.is_planar
    assert isinstance(scene.ends, FixedEnds) and scene.ends.hang_off == (600.0, 500.0)
    assert scene.bvp.max_nodes == 30000


def test_inner_diameter_and_mass_per_length_equivalent():
    # protects: inner_diameter / mass_per_length give the same section as wall_thickness / density
    D, wt, rho, E = 0.2032, 0.0191, 7860.0, 2.06e11
    d = D - 2.0 * wt                                  # 0.165 m
    A = math.pi / 4.0 * (D**2 - d**2)                 # closed form, 0.0110468 m2
    I = math.pi / 64.0 * (D**4 - d**4)
    alt = mutate(WANG, "wall_thickness = 0.0191", "inner_diameter = 0.165")
    alt = mutate(alt, "density = 7860.0", f"mass_per_length = {rho * A!r}")
    p_ref = segment_properties(parse_scene(WANG, SRC))
    p_alt = segment_properties(parse_scene(alt, SRC))
    assert len(p_ref) == len(p_alt) == 3
    for a, b in zip(p_ref, p_alt):
        for q in ("EA", "EI", "weight", "mass"):
            assert getattr(a, q) == pytest.approx(getattr(b, q), rel=1e-12), q
        assert a.EA == pytest.approx(E * A, rel=1e-12)
        assert a.EI == pytest.approx(E * I, rel=1e-12)


def test_wang_submerged_weight_by_hand():
    # protects: the baseline weight against the hand formula w = (rho_s A - rho_w pi D^2/4) g
    # By hand: D = 0.2032, d = 0.2032 - 2*0.0191 = 0.165; D^2 = 0.04129024, d^2 = 0.027225;
    # A = pi/4 * 0.01406524 = 0.01104681 m2; rho_s A = 7860 * A = 86.82796 kg/m;
    # rho_w pi D^2/4 = 1024 * 0.03242928 = 33.20758 kg/m; (86.82796 - 33.20758) * 9.8 = 525.480 N/m.
    props = segment_properties(parse_scene(WANG, SRC))
    assert props[0].weight == pytest.approx(525.48, abs=0.01)
    assert props[1].weight == pytest.approx(-525.48, abs=0.01)     # weight_scale = -1
    assert props[2].weight == pytest.approx(525.48, abs=0.01)


@pytest.mark.parametrize("value,path,hint", [
    ('["middle"]', "vfife.clamped_ends[0]", "must be one of 'bottom', 'top', got 'middle'"),
    ('"bottom"', "vfife.clamped_ends", "must be an array of strings (allowed: 'bottom', 'top')"),
    ('[1]', "vfife.clamped_ends[0]", "must be a string (allowed: 'bottom', 'top')"),
    ('["top", "top"]', "vfife.clamped_ends[1]", "'top' given twice"),
])
def test_clamped_ends_validation(value, path, hint):
    # protects: [vfife] clamped_ends takes only "bottom" / "top", one line naming the key
    msg = load_error(FIXED + f"\n[vfife]\nclamped_ends = {value}\n"
                     if "[vfife]" not in FIXED else
                     FIXED.replace("[vfife]\n", f"[vfife]\nclamped_ends = {value}\n"))
    assert msg.startswith(f"{SRC}: {path}: "), msg
    assert hint in msg, msg


def test_clamped_ends_accepted():
    # protects: the valid forms load (default: none clamped)
    text = (FIXED.replace("[vfife]\n", '[vfife]\nclamped_ends = ["bottom", "top"]\n')
            if "[vfife]" in FIXED else FIXED + '\n[vfife]\nclamped_ends = ["bottom", "top"]\n')
    assert parse_scene(text, SRC).vfife.clamped_ends == ("bottom", "top")
    assert parse_scene(FIXED, SRC).vfife.clamped_ends == ()


# ------------------------------------------------------------------ 5. scene.replace == the file
# issue 28 item 4: a scene built in code is checked as its file is. Each case: the file's
# mutation and the same change through Scene.replace (a field, or a key path into a part);
# both give the same one line, key path and source.
REPLACE_CASES = [
    ("negative-segment-length", F, "length = 600.0", "length = -5",
     {"segments[1].length": -5}, "segments[1].length: must be > 0 m, got -5"),
    ("nan-water-depth", F, "water_depth = 500.0", "water_depth = nan",
     {"water_depth": math.nan}, "environment.water_depth: must be a finite number, got nan"),
    ("negative-gravity", W, "gravity = 9.8", "gravity = -9.81", {"gravity": -9.81},
     "environment.gravity: must be >= 1 m/s2, got -9.81"),
    ("hang-off-below-the-anchor", F, "hang_off = [600.0, 500.0]", "hang_off = [600.0, -10.0]",
     {"ends.hang_off": (600.0, -10.0)}, "ends.hang_off[1]: must be > 0 (the hang-off cannot "
     "be at or below the seabed y = 0), got -10"),
    ("hang-off-below-the-anchor-one-entry", F, "hang_off = [600.0, 500.0]",
     "hang_off = [600.0, -10.0]", {"ends.hang_off[1]": -10.0}, "ends.hang_off[1]: must be > 0"),
    ("hang-off-behind-the-anchor", F, "hang_off = [600.0, 500.0]", "hang_off = [-600.0, 500.0]",
     {"ends.hang_off": (-600.0, 500.0)}, "ends.hang_off[0]: must be >= anchor[0] = 0"),
    ("anchor-below-the-seabed", F, "anchor = [0.0, 0.0]", "anchor = [0.0, -1.0]",
     {"ends.anchor": (0.0, -1.0)}, "ends.anchor[1]: must be >= 0 (the seabed is y = 0)"),
    ("hang-off-above-the-surface", F, "water_depth = 500.0", "water_depth = 400.0",
     {"water_depth": 400.0}, "ends.hang_off[1]: must be <= water_depth 400 m"),
    ("unknown-line-type", F, 'line_type = "steel"\nlength = 600.0',
     'line_type = "titanium"\nlength = 600.0', {"segments[1].line_type": "titanium"},
     "segments[1].line_type: unknown line type 'titanium' (defined: 'steel')"),
    ("line-type-range", F, "drag_normal = 1.0", "drag_normal = 12.0",
     {"line_types.steel.drag_normal": 12.0}, "line_types.steel.drag_normal: must be <= 10"),
    ("bore-not-inside", F, "inner_diameter = 0.165", "inner_diameter = 0.2032",
     {"line_types.steel.inner_diameter": 0.2032}, "line_types.steel.inner_diameter: must be < "
     "0.2032 m"),
    ("current-speeds-count", F, "speeds = [0.0, 1.2]", "speeds = [0.0, 1.2, 1.5]",
     {"environment.current.speeds": (0.0, 1.2, 1.5)},
     "environment.current.speeds: must have as many entries as heights (2), got 3"),
    ("current-heights-order", F, "heights = [0.0, 500.0]", "heights = [500.0, 0.0]",
     {"current.heights": (500.0, 0.0)}, "environment.current.heights[1]: must be > heights[0]"),
    ("seabed-stiffness", F, "stiffness = 1.0e5", "stiffness = -1.0e5",
     {"seabed.stiffness": -1.0e5}, "seabed.stiffness: must be > 0 N/m2"),
    ("tdp-tension", W, "tdp_tension = 160000.0", "tdp_tension = 1.6e11",
     {"ends.tdp_tension": 1.6e11}, "ends.tdp_tension: must be <= 1e+09 N"),
    ("inextensible-shorter-than-chord", F, "hang_off = [600.0, 500.0]",
     "hang_off = [900.0, 500.0]\n[model]\naxial = \"inextensible\"",
     {"ends.hang_off": (900.0, 500.0), "model": {"axial": "inextensible"}},
     "segments: line length 1000 m is not longer than the distance 1029.56 m"),
    ("model-choice", F, "[bvp]", "[model]\naxial = \"stretchy\"\n[bvp]",
     {"model": {"axial": "stretchy"}}, "model.axial: must be one of 'extensible'"),
    ("extensible-without-ea", F, "axial_stiffness = 2.0e9\n", "",
     {"line_types.steel.axial_stiffness": None},
     "line_types.steel.axial_stiffness: required for the extensible model"),
    ("bvp-setting", F, "tolerance = 1.0e-6", "tolerance = 0.5", {"bvp.tolerance": 0.5},
     "bvp.tolerance: must be <= 0.1, got 0.5"),
    ("expert-setting", F, "max_nodes = 30000\n", "max_nodes = 30000\n[vfife.expert]\n"
     "static_damping = 0.0\n", {"vfife.expert.static_damping": 0.0},
     "vfife.expert.static_damping: must be > 0, got 0"),
]


@pytest.mark.parametrize("case_id,base,old,new,changes,says", REPLACE_CASES,
                         ids=[c[0] for c in REPLACE_CASES])
def test_replace_gives_the_files_error(case_id, base, old, new, changes, says):
    # protects: scene.replace(...) is refused with the same one line as the file
    from_file = load_error(mutate(BASES[base], old, new))
    scene = parse_scene(BASES[base], SRC)
    with pytest.raises(SceneError) as info:
        scene.replace(**changes)
    from_replace = str(info.value)
    assert from_replace == from_file, (from_replace, from_file)
    assert from_file.startswith(f"{SRC}: {says}"), from_file


def test_dynamics_replace_gives_the_files_error():
    # protects: a [dynamics] whose default ramp (one period) is not shorter than the run
    dyn = "\n[dynamics]\nduration = 5.0\n[dynamics.top_motion]\naxis = \"y\"\namplitude = 1.0\n"
    from_file = load_error(WANG + dyn + "period = 10.0\n")
    scene = parse_scene(WANG + dyn + "period = 4.0\n", SRC)
    with pytest.raises(SceneError) as info:
        scene.replace(**{"dynamics.top_motion.period": 10.0})
    assert str(info.value) == from_file
    assert from_file.startswith(f"{SRC}: dynamics.duration: must be > 10 s, the default ramp")


def test_a_part_given_whole_to_replace_names_its_own_field():
    # a part built in code is checked when it is built, before the scene sees it: its own
    # field and source; the key path form gives the scene's path and source
    from riser.model.scene import FixedEnds
    scene = parse_scene(FIXED, SRC)
    with pytest.raises(SceneError) as info:
        scene.replace(ends=FixedEnds(anchor=(0.0, 0.0), hang_off=(600.0, -10.0)))
    assert (info.value.source, info.value.key) == ("<FixedEnds>", "hang_off[1]")


def test_replace_paths_change_one_value_and_keep_the_rest():
    scene = parse_scene(FIXED, SRC)
    new = scene.replace(**{"segments[0].length": 450.0, "environment.current.speeds": (0.0, 1.0),
                           "line_types.steel.drag_normal": 1.2, "vfife.static_damping": 4.0,
                           "ends.hang_off[0]": 650.0}, gravity=9.8)
    assert new.segments[0].length == 450.0 and new.segments[1] == scene.segments[1]
    assert new.current.speeds == (0.0, 1.0) and new.current.heights == scene.current.heights
    assert new.line_types["steel"].drag_normal == 1.2 and new.ends.hang_off == (650.0, 500.0)
    assert new.vfife.static_damping == 4.0 and new.gravity == 9.8
    assert scene.segments[0].length == 400.0                       # the original is unchanged
    for bad, says in (({"segments[5].length": 1.0}, "no such key in segments (it has 2"),
                      ({"ends.tdp_tension": 1.0}, "no such key in ends (known keys here: "
                                                  "anchor, hang_off, anchor_joint, hang_off_joint, "
                                                  "tensioner)"),
                      ({"dynamics.duration": 1.0}, "no such key in dynamics (not given"),
                      ({"colour": "red"}, "not a field or key path of the scene")):
        with pytest.raises(SceneError) as info:
            scene.replace(**bad)
        assert str(info.value).startswith(f"{SRC}: {next(iter(bad))}: {says}"), info.value


#: keys of the file that are no field of the model (the reader derives the section from
#: them, or converts the angle): Scene.replace has no path to them
FILE_ONLY = {"wall_thickness", "density", "youngs_modulus", "poisson_ratio", "shear_modulus",
             "hang_off_angle_from_vertical_deg"}
REPLACE_VARIANTS = {"string": "Not Valid", "bool": True, "minus1": -1, "zero": 0,
                    "nan": float("nan"), "1e30": 1e30}


def replace_mutation_cases():
    for base_name, text in BASES.items():
        for path, _ in leaves(tomllib.loads(text)):
            if len(path) > 1 and path[-1] not in FILE_ONLY:    # root keys: name, title, source
                for variant in REPLACE_VARIANTS:
                    yield pytest.param(base_name, path, variant,
                                       id=f"{base_name}:{path_str(path)}:{variant}")


@pytest.mark.parametrize("base_name,path,variant", list(replace_mutation_cases()))
def test_replace_mutation_table(base_name, path, variant):
    # protects: every leaf of both baselines set to a bad (or good) value by a key path of
    # Scene.replace gives what the file gives: the same line, or a scene
    data = tomllib.loads(BASES[base_name])
    parent = data
    for p in path[:-1]:
        parent = parent[p]
    parent[path[-1]] = REPLACE_VARIANTS[variant]
    outcomes = []
    for build in (lambda: parse_scene(dump_toml(data), SRC),
                  lambda: parse_scene(BASES[base_name], SRC).replace(
                      **{path_str(path): REPLACE_VARIANTS[variant]})):
        try:
            build()
            outcomes.append("loads")
        except SceneError as exc:
            outcomes.append(str(exc))
    assert outcomes[0] == outcomes[1]

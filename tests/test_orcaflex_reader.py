"""The OrcaFlex text data file reader and its mapping to a scene, on small hand-written
models (riser.io.orcaflex; ``riser-verify import-orcaflex``).

Each model is written into ``tmp_path`` in OrcaFlex's own layout (the fixtures in
tests/data/orcaflex show it): sections ``General``, ``VariableData``, ``Environment``,
``VesselTypes``, ``Vessels``, ``LineTypes``, ``Lines``; tables as one key naming the
columns over rows that may be shorter than the header. Checked: the units (SI's te, kN
and a User system's ft, lb, kpf/lbf converted exactly), the frame (the plane through the
ends, the seabed raised by the contact radius), the current, the end stiffness, a drag
coefficient from variable data, include files, and the refusals through the command line
(one line ``error: ...``, exit 2). No solver runs.
"""

from __future__ import annotations

import dataclasses
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from extras import needs_yaml
from riser.errors import SceneError
from riser.io.orcaflex.scene_from_model import import_model
from riser.io.orcaflex.text_file import ModelError, read_model
from riser.io.scene_file import load_scene
from verification.cli import main

pytestmark = needs_yaml

REPO = Path(__file__).resolve().parents[1]

# ------------------------------------------------------------------------ the models
#: OrcaFlex's SI system as the file gives it
SI = """\
  UnitsSystem: SI"""

#: a User system in feet and pounds (the a05 fixtures' block); {force}: kpf or lbf
USER = """\
  UnitsSystem: User
  LengthUnits: ft
  MassUnits: lb
  ForceUnits: {force}
  g: 32.1740485564304
  TemperatureUnits: °C"""

#: the model, every dimensional number written <<value|dimension>> in OrcaFlex's SI units
#: (m, te, kN, s): written as it is for SI, converted for a User system (_convert)
TEMPLATE = """\
%YAML 1.1
# Type: Model
# Program: OrcaFlex 11.6b
---
General:
  # Units
{units}
  # Stages
  StageDuration:
    - 10
    - 100
{variable}Environment:
  # Sea
  WaterSurfaceZ: 0
  KinematicViscosity: <<1.35e-6|L2/T>>
  # Sea density
  VerticalDensityVariation: Constant
  Density: <<1.025|M/L3>>
  # Seabed
  SeabedType: Flat
  SeabedOrigin: [0, 0]
  SeabedOriginDepth: <<100|L>>
  SeabedSlopeDirection: 0
  SeabedSlope: 0
  SeabedModel: Elastic
  SeabedNormalStiffness: <<100|F/L3>>
{waves}  # Current
  MultipleCurrentDataCanBeDefined: No
  CurrentModel: Variation scheme
  VerticalCurrentVariationMethod: Interpolated
  RefCurrentSpeed: <<{ref_speed}|L/T>>
  RefCurrentDirection: {ref_direction}
  CurrentDepth, CurrentFactor, CurrentRotation:
{current}VesselTypes:
  - Name: Vessel Type1
    Length: <<103|L>>
Vessels:
  - Name: FPSO
    VesselType: Vessel Type1
    Length: ~
    InitialPosition: [0, 0, 0]
    Orientation: [0, 0, {heading}]
    PrimaryMotion: None
    SuperimposedMotion: None
LineTypes:
  - Name: Pipe
    Category: General
    # Geometry and mass
    OD: <<0.3556|L>>
    ID: <<0.254|L>>
    CentreOfMass: [0, 0]
    MassPerUnitLength: <<0.1842262|M/L>>
    # Limits
    CompressionIsLimited: No
    MinRadius: [<<3.675|L>>, ~]
    # Structure
    EI: [<<124.86942768|F*L2>>, ~]
    EA: <<711.2e3|F>>
    ExpansionTable: None
    # Added mass, inertia and slam
    Ca: [1, ~, 0]
    Cm: [~, ~, ~]
    Cs: 0
    Ce: 0
    # Drag and lift
    Cd: [{cd}, ~, 0.008]
    Cl: 0
    NormalDragLiftDiameter: ~
    AxialDragLiftDiameter: ~
    # Friction
    SeabedLateralFrictionCoefficient: 0.5
    SeabedAxialFrictionCoefficient: ~
    # Structural damping
    RayleighDampingCoefficients: (no damping)
Lines:
{lines}"""

#: the current's rows: the last one (120 m) deeper than the seabed (100 m)
CURRENT = """\
    - [0, 1, 0]
    - [<<70|L>>, 0.9, 0]
    - [<<120|L>>, 0.3, 0]
"""

#: a line from the vessel (End A, heading 90) to an anchor (End B) in no vertical plane
#: of OrcaFlex's axes: End A at the vessel's (5, -10, -7.5) is global (10, 5, -7.5); End
#: B on the seabed at (130, 55), its centre the contact radius OD/2 above it
RISER = """\
  - Name: Riser
    IncludeTorsion: No
    TopEnd: End A
    LengthAndEndOrientations: Explicit
    Representation: Finite element
    PyModel: (none)
    DragFormulation: Standard
    StaticsVIV: None
    DynamicsVIV: None
    # End connections
    Connection, ConnectionX, ConnectionY, ConnectionZ, ConnectionAzimuth, ConnectionDeclination, ConnectionGamma, ConnectionReleaseStage, ConnectionzRelativeTo:
      - [{end_a}]
      - [{end_b}]
    # End connection stiffness
    ConnectionxBendingStiffness, ConnectionyBendingStiffness:
      - {stiff_a}
      - {stiff_b}
    # Sections
    LineType, Length, TargetSegmentLength:
      - [Pipe, <<150|L>>, <<5|L>>]
      - [Pipe, <<50|L>>, <<2|L>>]
    # Contents
    ContentsMethod: Uniform
    ContentsDensity: 0
    ContentsPressure: 0
    ContentsFlowRate: 0
    # Statics
    IncludedInStatics: Yes
    StaticsStep1: Catenary
    StaticsStep2: Full statics
"""
VESSEL_END = "FPSO, <<5|L>>, <<-10|L>>, <<-7.5|L>>, 0, 171.5, 0, ~"
ANCHOR_END = "Anchored, <<130|L>>, <<55|L>>, <<0.1778|L>>, 0, 90, 0, ~"

#: an Airy wave train (for the refusals that depend on the waves being carried)
AIRY = """\
  # Waves
  WaveTrains:
    - Name: Wave 1
      WaveType: Airy
      WaveDirection: 180
      WaveHeight: <<4|L>>
      WavePeriod: 8
      WaveOrigin: [0, 0]
      WaveTimeOrigin: 0
  WaveKinematicsCutoffDepth: Infinity
"""

#: a Reynolds-number table of Cd: constant 1.2 up to Re = 240e3, then falling
VARIABLE_CD = """\
VariableData:
  Dragcoefficient:
    - Name: Generic Drag
      IndependentValue, DependentValue:
        - [10e3, 1.2]
        - [50e3, 1.2]
        - [240e3, 1.2]
        - [255e3, 1.19]
        - [300e3, 1.16]
        - [380e3, 0.8]
        - [25e6, 0.7]
"""

#: SI (m, te, kN) -> the User system: ft, lb and the force unit (exact definitions)
FT, LB, LBF = 0.3048, 0.45359237, 4.4482216152605
FORCE = {"kpf": 1000.0 * LBF, "lbf": LBF}


def _factors(force: float) -> dict[str, float]:
    """Per dimension: one OrcaFlex SI file unit in the User file's units."""
    te, kn = 1000.0 / LB, 1000.0 / force
    return {"L": 1.0 / FT, "L/T": 1.0 / FT, "L2/T": 1.0 / FT ** 2, "M/L": te * FT,
            "M/L3": te * FT ** 3, "F": kn, "F*L2": kn / FT ** 2, "F/L3": kn * FT ** 3,
            "F*L": kn / FT}


def _convert(text: str, factors: dict[str, float] | None) -> str:
    def one(m):
        value, dim = m.group(1), m.group(2)
        return value if factors is None else repr(float(value) * factors[dim])
    return re.sub(r"<<([^|>]+)\|([^>]+)>>", one, text)


def model_text(units: str = "SI", *, current: str = CURRENT, ref_speed: float = 0.5,
               ref_direction: float = 180, waves: str = "", variable: str = "",
               cd: str = "1.2", heading: float = 90, end_a: str = VESSEL_END,
               end_b: str = ANCHOR_END, stiff_a: str = "[0, ~]", stiff_b: str = "[0, ~]",
               lines: str | None = None) -> str:
    """The model's text: ``units`` SI, or ``kpf``/``lbf`` for the User system in ft, lb
    and that force unit."""
    lines = RISER.format(end_a=end_a, end_b=end_b, stiff_a=stiff_a, stiff_b=stiff_b) \
        if lines is None else lines
    text = TEMPLATE.format(units=SI if units == "SI" else USER.format(force=units),
                           variable=variable, waves=waves, ref_speed=ref_speed,
                           ref_direction=ref_direction, current=current, heading=heading,
                           cd=cd, lines=lines)
    return _convert(text, None if units == "SI" else _factors(FORCE[units]))


def write(folder: Path, text: str, name: str = "model.yml") -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def refusal(path: Path, **kw) -> ModelError:
    with pytest.raises(ModelError) as info:
        import_model(path, **kw)
    return info.value


# ------------------------------------------------------------------------------ units
def test_si_units_convert_exactly(tmp_path):
    """te/m -> kg/m, kN -> N, kN m2 -> N m2, te/m3 -> kg/m3: one product by 1000 each.
    rel 1e-15: the importer's product is the exact product rounded (0.5 ulp), the literal
    the exact decimal rounded (0.5 ulp): at most 1 ulp apart (2.2e-16 relative)."""
    _, scene, notes = import_model(write(tmp_path, model_text()))
    lt = scene.line_types["Pipe"]
    assert lt.mass_per_length == pytest.approx(184.2262, rel=1e-15)
    assert lt.axial_stiffness == pytest.approx(711.2e6, rel=1e-15)
    assert lt.bending_stiffness == pytest.approx(124869.42768, rel=1e-15)
    assert scene.water_density == pytest.approx(1025.0, rel=1e-15)
    # the lengths and diameters are metres already: the very numbers of the file
    assert lt.outer_diameter == 0.3556 and lt.inner_diameter == 0.254
    assert lt.minimum_bend_radius == 3.675
    assert scene.gravity == 9.80665                       # OrcaFlex's standard gravity
    assert [s.length for s in scene.segments] == [50.0, 150.0]      # from End B (anchor)
    assert scene.vfife.element_length == 2.0
    assert any("Units: SI" in n for n in notes)


def _leaves(obj, path=""):
    """(key path, value) of every number and string in a scene (dataclasses, dicts,
    tuples)."""
    if dataclasses.is_dataclass(obj):
        for f in dataclasses.fields(obj):
            yield from _leaves(getattr(obj, f.name), f"{path}.{f.name}")
    elif isinstance(obj, dict):
        for k in sorted(obj):
            yield from _leaves(obj[k], f"{path}[{k}]")
    elif isinstance(obj, (list, tuple)):
        yield (f"{path}#len", len(obj))
        for k, v in enumerate(obj):
            yield from _leaves(v, f"{path}[{k}]")
    else:
        yield path, obj


@pytest.mark.parametrize("force", ["kpf", "lbf"])
def test_user_units_give_the_si_scene(force, tmp_path):
    """The same model in ft, lb, kpf (or lbf) and g = 32.1740485564304 ft/s2: the same
    scene to rel 1e-12 (each number is converted SI -> User here and back by the importer,
    each way a few roundings of exact factors: ~1e-15; the g literal has 15 digits:
    1.4e-15)."""
    (tmp_path / "si").mkdir()
    (tmp_path / "user").mkdir()
    _, si, _ = import_model(write(tmp_path / "si", model_text()))
    _, us, notes = import_model(write(tmp_path / "user", model_text(force)))
    assert any(f"User (ft, lb, {force}, s)" in n for n in notes)
    a, b = dict(_leaves(si)), dict(_leaves(us))
    assert a.keys() == b.keys()
    checked = 0
    for key, va in a.items():
        vb = b[key]
        if key in (".source",):
            continue
        if isinstance(va, float) and not isinstance(va, bool):
            assert vb == pytest.approx(va, rel=1e-12, abs=1e-12), key
            checked += 1
        else:
            assert vb == va, key
    assert checked > 30                        # the line types, ends, current, seabed...
    assert us.gravity == pytest.approx(9.80665, rel=1e-12)


def test_us_units_system_is_refused(tmp_path):
    text = model_text().replace("UnitsSystem: SI", "UnitsSystem: US")
    exc = refusal(write(tmp_path, text))
    assert exc.key == "General.UnitsSystem"
    assert "'US'" in exc.message


# ------------------------------------------------------------------------------ frame
def test_frame_of_a_vessel_end_and_an_anchor(tmp_path):
    """End A on a vessel at heading 90 (its (5, -10, -7.5) is global (10, 5, -7.5)), End
    B anchored at (130, 55) at z = OD/2: the hang-off's x is the horizontal distance
    between the ends (hypot(120, 50) = 130), its y the height above the scene's seabed
    (OrcaFlex's at -100 raised by OD/2 = 0.1778); the anchor at (0, 0). Tolerances: the
    plane's cos/sin from atan2 and a few subtractions round at 1e-16 relative; 1e-12."""
    _, scene, _ = import_model(write(tmp_path, model_text()))
    r = 0.3556 / 2.0
    assert scene.water_depth == pytest.approx(100.0 - r, rel=1e-12)
    xa, ya = scene.ends.anchor[:2]
    xh, yh = scene.ends.hang_off[:2]
    assert (xa, ya) == (0.0, 0.0)            # z = OD/2 on OrcaFlex's seabed: y = 0 exactly
    assert xh == pytest.approx(math.hypot(130.0 - 10.0, 55.0 - 5.0), rel=1e-12)
    assert yh == pytest.approx(-7.5 - (-100.0 + r), rel=1e-12)
    # both ends in the plane: no z (out of plane) given
    assert len(scene.ends.anchor) == 2 and len(scene.ends.hang_off) == 2
    # the anchor is End B: the scene's segments run from End B
    assert [s.label for s in scene.segments] == ["OrcaFlex section 2", "OrcaFlex section 1"]


def test_anchor_into_the_seabed_is_refused(tmp_path):
    """An Anchored end at z = 0 has its centre on OrcaFlex's seabed, half the contact
    diameter below the scene's: refused naming the end."""
    text = model_text(end_b="Anchored, <<130|L>>, <<55|L>>, 0, 0, 90, 0, ~")
    exc = refusal(write(tmp_path, text))
    assert exc.key == "Lines[Riser].Connection[End B]"


# ---------------------------------------------------------------------------- current
#: a line along +X: End A fixed 100 m from the anchor (End B) in +X
ALONG_X = dict(end_a="Fixed, <<100|L>>, 0, <<-10|L>>, 180, 160, 0, ~",
               end_b="Anchored, 0, 0, <<0.1778|L>>, 180, 90, 0, ~")


def test_current_cut_at_the_seabed_and_its_heading(tmp_path):
    """The rows at depth 0, 70 and 120 m of a 100 m sea (the scene's seabed at 99.8222):
    the last row becomes the profile's linear value at the scene's seabed; the direction
    90 (towards +Y) of a line along +X is the scene's heading 0 - 90 = -90. rel 1e-12:
    the interpolation's few roundings."""
    _, scene, _ = import_model(write(tmp_path, model_text(ref_direction=90, **ALONG_X)))
    h = 100.0 - 0.1778
    cur = scene.current
    assert cur.heading_deg == -90.0
    assert not cur.turns
    assert len(cur.heights) == 3
    assert cur.heights[0] == 0.0
    assert cur.heights[1] == pytest.approx(h - 70.0, rel=1e-12)
    assert cur.heights[2] == pytest.approx(h, rel=1e-12)
    v_seabed = 0.5 * (0.9 + (0.3 - 0.9) * (h - 70.0) / (120.0 - 70.0))
    assert cur.speeds[0] == pytest.approx(v_seabed, rel=1e-12)
    assert cur.speeds[1:] == pytest.approx([0.45, 0.5], rel=1e-12)


@pytest.mark.parametrize("direction, heading", [(0, 0.0), (90, -90.0), (180, 180.0),
                                                (270, 90.0)])
def test_current_heading_is_azimuth_minus_direction(direction, heading, tmp_path):
    _, scene, _ = import_model(write(tmp_path, model_text(ref_direction=direction,
                                                          **ALONG_X)))
    assert scene.current.heading_deg == pytest.approx(heading, abs=1e-12)   # wrap's fmod


def test_current_turning_with_depth_is_refused(tmp_path):
    turning = CURRENT.replace("[<<70|L>>, 0.9, 0]", "[<<70|L>>, 0.9, 15]")
    exc = refusal(write(tmp_path, model_text(current=turning)))
    assert exc.key == "Environment.CurrentRotation"


# ---------------------------------------------------------------------- end stiffness
def test_end_stiffness_zero_is_pinned(tmp_path):
    _, scene, _ = import_model(write(tmp_path, model_text(**ALONG_X)))
    assert scene.ends.anchor_joint is None and scene.ends.hang_off_joint is None


def test_end_stiffness_infinity_is_clamped_along_the_end_direction(tmp_path):
    """Declination 160 at End A (azimuth 180: towards the anchor, 20 deg from the
    vertical): the tangent from the anchor up is 70 deg; End B horizontal (declination
    90): 0 deg. abs 1e-12 deg: sin/cos/atan2 round-off."""
    _, scene, notes = import_model(write(tmp_path, model_text(
        stiff_a="[Infinity, ~]", stiff_b="[Infinity, ~]", **ALONG_X)))
    top, bottom = scene.ends.hang_off_joint, scene.ends.anchor_joint
    assert top.kind == "clamped" and bottom.kind == "clamped"
    assert top.direction_deg == pytest.approx(70.0, abs=1e-12)
    assert bottom.direction_deg == pytest.approx(0.0, abs=1e-12)
    assert any("Infinity -> a clamped end" in n for n in notes)


def test_end_stiffness_per_degree_is_a_flex_joint_per_radian(tmp_path):
    """[10, ~] kN m/deg -> 10e3 x 180 / pi N m/rad; rel 1e-15: the same three operations
    (exact products, one division) in the same order."""
    _, scene, _ = import_model(write(tmp_path, model_text(stiff_a="[10, ~]", **ALONG_X)))
    joint = scene.ends.hang_off_joint
    assert joint.kind == "spring"
    assert joint.rotational_stiffness == pytest.approx(10e3 * 180.0 / math.pi, rel=1e-15)
    assert joint.direction_deg == pytest.approx(70.0, abs=1e-12)
    assert scene.ends.anchor_joint is None


def test_end_stiffness_x_and_y_different_is_refused(tmp_path):
    exc = refusal(write(tmp_path, model_text(stiff_a="[10, 20]", **ALONG_X)))
    assert exc.key == "Lines[Riser].Connection[End A].BendingStiffness"


# ------------------------------------------------------------------ variable-data Cd
def test_variable_cd_within_its_constant_stretch_is_carried_in_statics(tmp_path):
    """Current 0.5 m/s: Re = 0.5 x 0.3556 / 1.35e-6 = 1.3e5 < 240e3, the end of the
    table's constant 1.2; the model's Airy wave is left out by --statics."""
    path = write(tmp_path, model_text(variable=VARIABLE_CD, cd="Generic Drag", waves=AIRY))
    text, scene, notes = import_model(path, statics=True)
    assert scene.line_types["Pipe"].drag_normal == 1.2
    assert scene.waves is None and scene.dynamics is None
    assert any("--statics" in n for n in notes)
    assert "Cd = 1.2 from the variable data 'Generic Drag'" in text   # said in the scene


def test_variable_cd_beyond_its_constant_stretch_is_refused(tmp_path):
    """Current 1 m/s: Re = 2.6e5 > 240e3, where the table's Cd changes."""
    path = write(tmp_path, model_text(variable=VARIABLE_CD, cd="Generic Drag",
                                      ref_speed=1.0))
    exc = refusal(path, statics=True)
    assert exc.key == "LineTypes[Pipe].Cd"
    assert "Re = " in exc.message


def test_variable_cd_with_an_airy_wave_is_refused_without_statics(tmp_path):
    path = write(tmp_path, model_text(variable=VARIABLE_CD, cd="Generic Drag", waves=AIRY))
    exc = refusal(path)
    assert exc.key == "LineTypes[Pipe].Cd"
    assert "--statics" in exc.message


# ---------------------------------------------------------------------- include files
def _split_line_types(text: str) -> tuple[str, str]:
    """(the model without its LineTypes section, the section's list of objects)."""
    start, end = text.index("LineTypes:\n"), text.index("Lines:\n")
    section = text[start:end]
    objects = "\n".join(ln[2:] for ln in section.splitlines()[1:]) + "\n"
    return text[:start] + text[end:], objects


def _line_type_values(scene) -> dict:
    return dataclasses.asdict(scene.line_types["Pipe"])


def test_top_level_include_files(tmp_path):
    """A model given as a top-level list of ``- includefile:`` items: their sections
    merged in order."""
    whole = model_text()
    _, ref, _ = import_model(write(tmp_path, whole, "whole.yml"))
    rest, objects = _split_line_types(whole)
    body = rest.split("---\n", 1)[1]
    write(tmp_path, "%YAML 1.1\n---\n" + body, "body.yml")
    write(tmp_path, "%YAML 1.1\n---\nLineTypes:\n" + "\n".join(
        "  " + ln for ln in objects.splitlines()) + "\n", "types.yml")
    top = write(tmp_path, "%YAML 1.1\n---\n- includefile: body.yml\n"
                "- includefile: types.yml\n", "top.yml")
    model = read_model(top)
    assert [Path(p).name for p in model.included] == ["body.yml", "types.yml"]
    _, scene, _ = import_model(top)
    assert _line_type_values(scene) == _line_type_values(ref)
    assert scene.ends == ref.ends


def test_include_file_item_inside_line_types(tmp_path):
    """``LineTypes: - includefile: types.yml``: its objects spliced into the list, read
    relative to the including file's folder."""
    whole = model_text()
    _, ref, _ = import_model(write(tmp_path, whole, "whole.yml"))
    rest, objects = _split_line_types(whole)
    (tmp_path / "parts").mkdir()
    write(tmp_path / "parts", "%YAML 1.1\n---\n" + objects, "types.yml")
    text = rest.replace("Lines:\n", "LineTypes:\n  - includefile: parts/types.yml\nLines:\n")
    _, scene, _ = import_model(write(tmp_path, text))
    assert _line_type_values(scene) == _line_type_values(ref)


def test_include_file_as_a_section_mapping(tmp_path):
    rest, objects = _split_line_types(model_text())
    write(tmp_path, "%YAML 1.1\n---\n" + objects, "types.yml")
    text = rest.replace("Lines:\n", "LineTypes:\n  includefile: types.yml\nLines:\n")
    _, scene, _ = import_model(write(tmp_path, text))
    assert scene.line_types["Pipe"].mass_per_length == pytest.approx(184.2262, rel=1e-15)


def test_missing_include_file_is_refused_naming_it(tmp_path):
    rest, _ = _split_line_types(model_text())
    text = rest.replace("Lines:\n", "LineTypes:\n  - includefile: nowhere.yml\nLines:\n")
    exc = refusal(write(tmp_path, text))
    assert "includefile" in exc.key and "LineTypes" in exc.key
    assert "nowhere.yml" in exc.message


def test_file_including_itself_is_refused(tmp_path):
    rest, _ = _split_line_types(model_text())
    text = rest.replace("Lines:\n", "LineTypes:\n  - includefile: model.yml\nLines:\n")
    exc = refusal(write(tmp_path, text))
    assert "includes itself" in exc.message and "model.yml" in exc.message


# -------------------------------------------------------------- refusals, command line
def _cli_error(capsys, args: list[str]) -> str:
    """Run the command; it must print one line ``error: ...`` and return 2."""
    capsys.readouterr()
    assert main(args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert err[0].startswith("error:"), err
    return err[0]


TWO_LINES = RISER + RISER.replace("Name: Riser", "Name: Second riser")


@pytest.mark.parametrize("case", ["binary", "lfs", "basefile", "not-yaml", "no-sections",
                                  "two-lines", "no-such-line"])
def test_refusals_are_one_line_exit_2(case, tmp_path, capsys):
    args = []
    path = tmp_path / "model.yml"
    if case == "binary":
        path = tmp_path / "model.dat"
        path.write_bytes(b"\x08ORCAFLEX" + b"\x00" * 64 + b"\x01\x02")
        words = ["binary"]
    elif case == "lfs":
        path.write_text("version https://git-lfs.github.com/spec/v1\n"
                        "oid sha256:4d7a214614ab2935c943f9e0ff69d22eadbb8f32b1258daaa5e2ca24d17e2393\n"
                        "size 12345\n")
        words = ["Git LFS"]
    elif case == "basefile":
        path.write_text("%YAML 1.1\n---\nBaseFile: base.yml\nGeneral:\n  StageDuration[1]: 10\n")
        words = ["BaseFile", "base.yml"]
    elif case == "not-yaml":
        path.write_text("OrcaFlex model\n  Lines: [unclosed\n: : :\n")
        words = ["not a YAML"]
    elif case == "no-sections":
        path.write_text("%YAML 1.1\n---\nname: a scene\nvalues: [1, 2, 3]\n")
        words = ["no OrcaFlex model"]
    elif case == "two-lines":
        rest = model_text(lines=TWO_LINES.format(end_a=VESSEL_END, end_b=ANCHOR_END,
                                                 stiff_a="[0, ~]", stiff_b="[0, ~]"))
        path.write_text(_convert(rest, None))
        words = ["'Riser'", "'Second riser'", "--line"]
    else:
        path.write_text(model_text())
        args = ["--line", "Nonesuch"]
        words = ["Nonesuch", "Riser"]
    err = _cli_error(capsys, ["import-orcaflex", str(path), *args])
    for w in words:
        assert w in err, (w, err)
    assert not list(tmp_path.glob("*.toml"))              # nothing written


def test_missing_pyyaml_is_one_line_naming_the_extra(tmp_path):
    path = write(tmp_path, model_text())
    code = ("import sys; sys.modules['yaml'] = None\n"
            "from verification.cli import main\n"
            f"sys.exit(main(['import-orcaflex', {str(path)!r}]))")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(REPO), os.environ.get("PYTHONPATH", "")]))
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=REPO, env=env, timeout=60)
    assert run.returncode == 2, run.stderr
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1, lines
    assert lines[0].startswith("error:")
    assert "pip install" in lines[0] and "[orcaflex]" in lines[0]


# ------------------------------------------------------------------- the written scene
def _section_values(scene) -> tuple:
    return (tuple(sorted((k, dataclasses.astuple(v)) for k, v in scene.line_types.items())),
            tuple((s.line_type, s.length) for s in scene.segments),
            scene.ends, scene.water_depth, scene.water_density, scene.gravity,
            scene.current, scene.seabed)


def test_cli_writes_the_scene_beside_the_model(tmp_path, capsys):
    path = write(tmp_path, model_text())
    capsys.readouterr()
    assert main(["import-orcaflex", str(path)]) == 0
    out = capsys.readouterr().out
    written = tmp_path / "model.toml"
    assert written.is_file() and str(written) in out
    _, scene, _ = import_model(path)
    back = load_scene(written)
    # the TOML's numbers are written with repr: the very floats back
    assert _section_values(back) == _section_values(scene)
    assert back.total_length == 200.0


def test_cli_out_folder(tmp_path, capsys):
    path = write(tmp_path, model_text(variable=VARIABLE_CD, cd="Generic Drag", waves=AIRY))
    folder = tmp_path / "scenes"
    folder.mkdir()
    assert main(["import-orcaflex", str(path), "--out", str(folder), "--statics"]) == 0
    back = load_scene(folder / "model.toml")
    _, scene, _ = import_model(path, statics=True)
    assert _section_values(back) == _section_values(scene)
    assert back.line_types["Pipe"].drag_normal == 1.2
    assert not (tmp_path / "model.toml").exists()


def test_cli_scene_error_is_a_scene_error():
    """ModelError is the suite's SceneError: the command line's one-line refusals."""
    assert issubclass(ModelError, SceneError)


# ------------------------------------------------------------ homogeneous pipe (bugs)
HOMOGENEOUS = """\
  - Name: Pipe
    Category: Homogeneous pipe
    # Geometry and density
    OD: 0.3556
    ID: 0.254
    MaterialDensity: 7.85
    # Structure
    E: 207e6
    PoissonRatio: 0.3
    ExpansionTable: None
    # Drag, lift, added mass and slam
    Cdn: 0.9
    Cdz: 0.008
    Cl: 0
    Can: 1.5
    Caz: 0
    Cs: 0
    Ce: 0
    # Friction
    SeabedLateralFrictionCoefficient: 0.5
    # Structural damping
    RayleighDampingCoefficients: (no damping)
{coating}"""


def _homogeneous(coating: str = "") -> str:
    text = model_text()
    start, end = text.index("  - Name: Pipe\n"), text.index("Lines:\n")
    return text[:start] + HOMOGENEOUS.format(coating=coating) + text[end:]


def test_homogeneous_pipe_reads_cdn_and_can(tmp_path):
    _, scene, _ = import_model(write(tmp_path, _homogeneous()))
    lt = scene.line_types["Pipe"]
    assert lt.drag_normal == 0.9
    assert lt.added_mass == 1.5


def test_homogeneous_pipe_coating_is_carried_or_refused(tmp_path):
    coating = "    CoatingThickness: 0.05\n    CoatingMaterialDensity: 0.9\n"
    try:
        _, scene, _ = import_model(write(tmp_path, _homogeneous(coating)))
    except ModelError as exc:
        assert "Coating" in exc.key
        return
    assert scene.line_types["Pipe"].outer_diameter == pytest.approx(0.3556 + 0.1)

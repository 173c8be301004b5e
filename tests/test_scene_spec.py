"""The field specs (riser/spec.py): every part of a scene checks itself on construction,
the key tables of docs/scene-files.md are generated from the specs, the built-in scenes
load to the values an independent reading of their files gives, and the model modules
do not import the file formats.

Regenerating the docs' key tables after a spec change: ``python -m riser.model.spec_docs``, or
run this module with ``REGENERATE_SCENE_KEYS=1`` (test_docs_key_tables_match_the_specs
then rewrites the block between the markers before comparing).
"""

from __future__ import annotations

import dataclasses
import math
import os
import timeit
import tomllib
from pathlib import Path

import pytest

import riser
from riser.model import spec_docs
from riser.physics.dynamics import Dynamics, TopMotion
from riser.model.ends import Ends, FixedEnds, HangOffAngleEnds, TdpTensionEnds, TopTensionEnds
from riser.physics.environment import Current, Seabed
from riser.errors import SceneError
from riser.physics.internal_flow import InternalFlow
from riser.io.scene_file import load_scene
from riser.model.line import LineType, Segment
from riser.model.settings import AnalyticSettings, BVPSettings, VFIFESettings
from verification.catalog import builtin_paths

ROOT = Path(__file__).resolve().parents[1]


# ------------------------------------------------------------------ the docs' key tables
def test_docs_key_tables_match_the_specs():
    page = ROOT / "docs" / "scene-files.md"
    if os.environ.get("REGENERATE_SCENE_KEYS") == "1":
        spec_docs.update_docs(page)
    text = page.read_text(encoding="utf-8")
    assert spec_docs.with_block(text, spec_docs.scene_keys_markdown()) == text, (
        "the key tables of docs/scene-files.md differ from the specs: run "
        "python -m riser.model.spec_docs")


def test_the_generator_covers_every_table_and_key():
    md = spec_docs.scene_keys_markdown()
    for table in ("[environment]", "[environment.current]", "[seabed]", "[line_types.NAME]",
                  "[[segments]]", "[model]", "[dynamics]", "[dynamics.top_motion]",
                  "[internal_flow]", "[internal_flow.slug]", "[bvp]", "[analytic]",
                  "[vfife]", "[vfife.expert]"):
        assert f"#### `{table}`" in md, table
    assert md.count("#### `[ends]: ") == 4
    for key in ("`wall_thickness`", "`hang_off_angle_from_vertical_deg`", "`static_damping`",
                "`slug_length`", "`source`"):
        assert key in md, key
    assert "| `length` | number | required | > 0, <= 50000 | m |" in md


def test_the_block_is_replaced_between_the_markers_only():
    text = f"# T\n\nbefore\n{spec_docs.BEGIN}\nold\n{spec_docs.END}\nafter\n"
    new = spec_docs.with_block(text, "new\n")
    assert new == f"# T\n\nbefore\n{spec_docs.BEGIN}\nnew\n{spec_docs.END}\nafter\n"
    with pytest.raises(ValueError):
        spec_docs.with_block("no markers\n", "new\n")


# ------------------------------------------------------------------ parts built alone
def error_of(build) -> SceneError:
    with pytest.raises(SceneError) as info:
        build()
    assert "\n" not in str(info.value)
    return info.value


PIPE = dict(name="p", outer_diameter=0.3, inner_diameter=0.25, mass_per_length=100.0,
            axial_stiffness=1e9, bending_stiffness=1e7, torsional_stiffness=7e6)


@pytest.mark.parametrize("build,source,key,message", [
    (lambda: Segment(line_type="p", length=-5.0), "<Segment>", "length",
     "must be > 0 m, got -5"),
    (lambda: LineType(**{**PIPE, "inner_diameter": 0.3}), "<LineType>", "inner_diameter",
     "must be < 0.3 m, got 0.3"),
    (lambda: LineType(**{**PIPE, "drag_normal": math.nan}), "<LineType>", "drag_normal",
     "must be a finite number, got nan"),
    (lambda: LineType(**{**PIPE, "inner_diameter": None, "contents_density": 800.0}),
     "<LineType>", "contents_density", "needs inner_diameter or wall_thickness"),
    (lambda: Current(heights=(0.0, 100.0), speeds=(1.0,)), "<Current>", "speeds",
     "must have as many entries as heights (2), got 1"),
    (lambda: Current(heights=(100.0, 0.0), speeds=(1.0, 1.0)), "<Current>", "heights[1]",
     "must be > heights[0] = 100 (strictly increasing), got 0"),
    (lambda: Seabed(stiffness=-1.0), "<Seabed>", "stiffness", "must be > 0 N/m2, got -1"),
    (lambda: TdpTensionEnds(tdp_tension=0.0), "<TdpTensionEnds>", "tdp_tension",
     "must be > 0 N, got 0"),
    (lambda: HangOffAngleEnds(hang_off_height=100.0, hang_off_angle_deg=95.0),
     "<HangOffAngleEnds>", "hang_off_angle_from_horizontal_deg", "must be <= 90 deg, got 95"),
    (lambda: TopTensionEnds(hang_off_height=-1.0, top_tension=1e6), "<TopTensionEnds>",
     "hang_off_height", "must be > 0 m, got -1"),
    (lambda: FixedEnds(anchor=(0.0, 0.0), hang_off=(-600.0, 500.0)), "<FixedEnds>",
     "hang_off[0]", "must be >= anchor[0] = 0 (x points from the anchor towards the hang-off"),
    (lambda: FixedEnds(anchor=(0.0,), hang_off=(600.0, 500.0)), "<FixedEnds>", "anchor",
     "must have 2 or 3 entries, got 1"),
    (lambda: TopMotion(axis="w", amplitude=1.0, period=10.0), "<TopMotion>", "axis",
     "must be one of 'x', 'y', 'z', got 'w'"),
    (lambda: TopMotion(axis="y", times=(0.0, 2.0, 1.0), displacements=(0.0, 1.0, 0.0)),
     "<TopMotion>", "times[2]", "must be strictly increasing"),
    (lambda: Dynamics(duration=5.0, top_motion=TopMotion(axis="y", amplitude=1.0,
                                                         period=10.0)),
     "<Dynamics>", "duration", "must be > 10 s, the default ramp"),
    (lambda: InternalFlow(speed=1.0, density_amplitude=1.0, slug_length=10.0),
     "<InternalFlow>", "slug.density_amplitude", "must be < 1, got 1"),
    (lambda: BVPSettings(tolerance=0.5), "<BVPSettings>", "bvp.tolerance",
     "must be <= 0.1, got 0.5"),
    (lambda: VFIFESettings(static_damping=0.0), "<VFIFESettings>",
     "vfife.expert.static_damping", "must be > 0, got 0"),
    (lambda: AnalyticSettings(model="exact"), "<AnalyticSettings>", "analytic.model",
     "must be one of 'composite', 'piecewise', 'catenary', got 'exact'"),
], ids=lambda v: v if isinstance(v, str) and not v.startswith("<") and " " not in v else "")
def test_a_part_built_alone_names_its_own_field(build, source, key, message):
    exc = error_of(build)
    assert (exc.source, exc.key) == (source, key), str(exc)
    assert exc.message.startswith(message), str(exc)


def test_parts_store_arrays_as_tuples_and_normalise_nothing_else():
    cur = Current(heights=[0, 100], speeds=[0.5, 1])
    assert cur.heights == (0, 100) and isinstance(cur.heights, tuple)
    assert Segment(line_type="p", length=100).length == 100        # an int stays an int
    dyn = Dynamics(duration=0.5)
    assert dyn.output_interval == 0.5 and Dynamics(duration=30.0).output_interval == 1.0


def test_part_replace_is_checked_and_names_unknown_fields():
    seg = Segment(line_type="p", length=10.0)
    assert seg.replace(length=20.0).length == 20.0
    assert error_of(lambda: seg.replace(length=0.0)).key == "length"
    assert error_of(lambda: seg.replace(lenght=1.0)).message.startswith("unknown field")
    assert error_of(lambda: dataclasses.replace(seg, length=math.inf)).key == "length"


# ------------------------------------------------------------------ the end forms
def test_the_end_forms_are_classes_with_the_kind_strings_of_summary_json():
    forms = {TdpTensionEnds(tdp_tension=1e5): "tdp_tension",
             HangOffAngleEnds(hang_off_height=100.0, hang_off_angle_deg=80.0): "hang_off_angle",
             TopTensionEnds(hang_off_height=100.0, top_tension=1e6): "top_tension",
             FixedEnds(anchor=(0.0, 0.0), hang_off=(50.0, 100.0)): "fixed"}
    for ends, kind in forms.items():
        assert ends.kind == kind and isinstance(ends, Ends)
        with pytest.raises(dataclasses.FrozenInstanceError):
            ends.kind = "fixed"
    with pytest.raises(TypeError, match="base of the end forms"):
        Ends("fixed", anchor=(0.0, 0.0), hang_off=(1.0, 1.0))
    for name in ("Ends", "TdpTensionEnds", "HangOffAngleEnds", "TopTensionEnds", "FixedEnds"):
        assert name in riser.__all__ and getattr(riser, name) is globals()[name]


# ------------------------------------------------------------------ built-in scenes
def expected_scene(data: dict) -> dict:
    """What a scene file holds, read with tomllib and the scene-file rules of README.md
    (defaults, the wall and material of a line type, the angle from the vertical):
    independent of riser.spec and riser.io. Settings are compared in the test."""
    env = data.get("environment", {})
    out = {"name": data["name"], "title": data.get("title", ""),
           "provenance": data.get("source", ""), "gravity": env.get("gravity", 9.81),
           "water_density": env.get("water_density", 1025.0),
           "water_depth": env.get("water_depth"), "model": data.get("model", {})}
    cur = env.get("current")
    out["current"] = None if cur is None else {
        "heights": tuple(cur["heights"]), "speeds": tuple(cur["speeds"]),
        "heading_deg": cur.get("heading_deg", 0.0),
        "headings_deg": tuple(cur["headings_deg"]) if "headings_deg" in cur else None}
    sb = data.get("seabed")
    out["seabed"] = None if sb is None else {"stiffness": sb["stiffness"], "friction": sb.get(
        "friction", 0.0), "damping": sb.get("damping", 0.0)}
    out["line_types"] = {name: expected_line_type(name, t) for name, t in data["line_types"].items()}
    out["segments"] = tuple({"line_type": s["line_type"], "length": s["length"],
                             "buoyancy": s.get("buoyancy", 0.0),
                             "submerged_weight": s.get("submerged_weight"),
                             "weight_scale": s.get("weight_scale", 1.0),
                             "hydro_diameter": s.get("hydro_diameter"),
                             "label": s.get("label", "")} for s in data["segments"])
    e = dict(data["ends"])
    if "hang_off_angle_from_vertical_deg" in e:
        e["hang_off_angle_deg"] = 90.0 - e.pop("hang_off_angle_from_vertical_deg")
    if "hang_off_angle_from_horizontal_deg" in e:
        e["hang_off_angle_deg"] = e.pop("hang_off_angle_from_horizontal_deg")
    out["ends"] = {k: tuple(v) if isinstance(v, list) else v for k, v in e.items()}
    if "anchor" in e:                    # fixed ends: the end conditions' sub-tables
        for key in ("anchor_joint", "hang_off_joint"):
            j = e.get(key)
            out["ends"][key] = None if j is None else {
                "kind": j.get("kind", "pinned"), "direction_deg": j.get("direction_deg"),
                "rotational_stiffness": j.get("rotational_stiffness")}
        t = e.get("tensioner")
        out["ends"]["tensioner"] = None if t is None else {
            "top_tension": t["top_tension"], "stiffness": t.get("stiffness", 0.0)}
    dyn = data.get("dynamics")
    out["dynamics"] = None if dyn is None else expected_dynamics(dyn)
    out["waves"] = expected_waves(env.get("waves"))
    out["vessel"] = expected_vessel(data.get("vessel"))
    flow = data.get("internal_flow")
    out["internal_flow"] = None if flow is None else {
        "speed": flow["speed"], "top_pressure": flow.get("top_pressure", 0.0),
        "density_amplitude": flow.get("slug", {}).get("density_amplitude", 0.0),
        "slug_length": flow.get("slug", {}).get("slug_length"),
        "phase_deg": flow.get("slug", {}).get("phase_deg", 0.0)}
    out["design"] = expected_design(data.get("design"))
    out["attachments"] = tuple({"s": a["s"], "mass": a.get("mass", 0.0),
                                "volume": a.get("volume", 0.0),
                                "drag_area": a.get("drag_area", 0.0),
                                "added_mass_coefficient": a.get("added_mass_coefficient", 0.0),
                                "label": a.get("label", "")}
                               for a in data.get("attachments", []))
    return out


def expected_design(d: dict | None) -> dict | None:
    """[design], [design.fatigue] and its sea states with the documented defaults."""
    if d is None:
        return None
    f = d.get("fatigue")
    fatigue = None if f is None else {
        "sn_curve": f.get("sn_curve", "D"), "environment": f.get("environment", "seawater-cp"),
        "scf": f.get("scf", 1.0), "points": f.get("points", 16),
        "thickness": f.get("thickness"),
        "design_fatigue_factor": f.get("design_fatigue_factor", 1.0),
        "record_length": f.get("record_length"),
        "sea_states": tuple({"hs": c["hs"], "tp": c["tp"], "probability": c["probability"]}
                            for c in f.get("sea_states", []))}
    return {"bending_strain_limit": d.get("bending_strain_limit"),
            "code": d.get("code", "dnv-st-f201"), "safety_class": d.get("safety_class", "normal"),
            "load_class": d.get("load_class", "operating"), "gamma_f": d.get("gamma_f", 1.1),
            "gamma_e": d.get("gamma_e", 1.3), "gamma_m": d.get("gamma_m", 1.15),
            "alpha_u": d.get("alpha_u", 0.96), "alpha_fab": d.get("alpha_fab", 1.0),
            "ovality": d.get("ovality", 0.005),
            "corrosion_allowance": d.get("corrosion_allowance", 0.0),
            "storm_duration": d.get("storm_duration", 10800.0),
            "internal_pressure": d.get("internal_pressure"), "fatigue": fatigue,
            "design_life": d.get("design_life")}


def _numbers(v):
    return None if v is None else tuple(float(x) for x in v)


def expected_waves(w: dict | None) -> dict | None:
    """[environment.waves] with the defaults docs/scene-files.md states."""
    if w is None:
        return None
    sp = w.get("spectrum")
    spectrum = None if sp is None else {
        "kind": sp["kind"], "hs": sp.get("hs"), "tp": sp.get("tp"), "gamma": sp.get("gamma"),
        "omega": _numbers(sp.get("omega")), "density": _numbers(sp.get("density")),
        "heading_deg": sp.get("heading_deg", 0.0), "spreading": sp.get("spreading", "none"),
        "spreading_exponent": sp.get("spreading_exponent"),
        "components": sp.get("components", 200),
        "omega_min": sp.get("omega_min"), "omega_max": sp.get("omega_max"),
        "seed": sp.get("seed", 1)}
    trains = tuple({"height": t["height"], "period": t["period"],
                    "heading_deg": t.get("heading_deg", 0.0), "phase_deg": t.get("phase_deg", 0.0)}
                   for t in w.get("trains", []))
    return {"trains": trains, "spectrum": spectrum, "stretching": w.get("stretching", "wheeler"),
            "origin": _numbers(w.get("origin")), "line_loads": w.get("line_loads", True),
            "ramp_time": w.get("ramp_time")}


def expected_vessel(v: dict | None) -> dict | None:
    """[vessel] and its [[vessel.raos]] as the file gives them."""
    if v is None:
        return None
    raos = tuple({k: (tuple(x) if isinstance(x, list) else x) for k, x in r.items()}
                 for r in v["raos"])
    return {"raos": raos, "heading_deg": v.get("heading_deg", 0.0),
            "hang_off_on_vessel": _numbers(v.get("hang_off_on_vessel", [0.0, 0.0, 0.0]))}


def expected_line_type(name: str, t: dict) -> dict:
    D = t["outer_diameter"]
    d = t.get("inner_diameter", D - 2.0 * t["wall_thickness"] if "wall_thickness" in t else None)
    area = 0.0 if d is None else math.pi / 4.0 * (D * D - d * d)
    inertia = 0.0 if d is None else math.pi / 64.0 * (D ** 4 - d ** 4)
    E = t.get("youngs_modulus")
    EI = t.get("bending_stiffness", None if E is None else E * inertia)
    G = t.get("shear_modulus")
    return {"name": name, "outer_diameter": D, "inner_diameter": d,
            "mass_per_length": t.get("mass_per_length", t.get("density", 0.0) * area),
            "axial_stiffness": t.get("axial_stiffness", None if E is None else E * area),
            "bending_stiffness": EI,
            "torsional_stiffness": t.get("torsional_stiffness", G * 2.0 * inertia
                                         if G is not None
                                         else EI / (1.0 + t.get("poisson_ratio", 0.3))),
            "axial_damping": t.get("axial_damping", 0.0),
            "drag_normal": t.get("drag_normal", 1.0),
            "drag_tangential": t.get("drag_tangential", 0.0),
            "added_mass": t.get("added_mass", 1.0),
            "contents_density": t.get("contents_density", 0.0),
            "hydro_diameter": t.get("hydro_diameter"),
            "submerged_weight": t.get("submerged_weight"),
            "max_strain": t.get("max_strain", 0.01), "compression": t.get("compression", True),
            "yield_strength": t.get("yield_strength"),
            "tensile_strength": t.get("tensile_strength"),
            "minimum_bend_radius": t.get("minimum_bend_radius")}


def expected_dynamics(dyn: dict) -> dict:
    tm = dyn.get("top_motion")
    motion = None if tm is None else {
        "axis": tm.get("axis"), "amplitude": tm.get("amplitude", 0.0),
        "period": tm.get("period", 0.0),
        "times": tuple(tm["times"]) if "times" in tm else None,
        "displacements": tuple(tm["displacements"]) if "displacements" in tm else None,
        "amplitudes": _numbers(tm.get("amplitudes")),
        "phases_deg": _numbers(tm.get("phases_deg", [0.0, 0.0, 0.0])),
        **{f"displacements_{k}": _numbers(tm.get(f"displacements_{k}")) for k in "xyz"},
        "ramp_time": tm.get("ramp_time")}
    return {"duration": dyn["duration"],
            "output_interval": dyn.get("output_interval", min(1.0, dyn["duration"])),
            "top_motion": motion, "damping": dyn.get("damping", 0.0),
            "statistics_start": dyn.get("statistics_start"),
            "save_states": dyn.get("save_states", False),
            "stations": _numbers(dyn.get("stations"))}


def as_data(value):
    """A scene's values as plain data (dataclasses as dicts, keeping floats bit for bit)."""
    if dataclasses.is_dataclass(value):
        return {f.name: as_data(getattr(value, f.name)) for f in dataclasses.fields(value)}
    if isinstance(value, dict):
        return {k: as_data(v) for k, v in value.items()}
    if isinstance(value, tuple):
        return tuple(as_data(v) for v in value)
    return value


def same(a, b) -> bool:
    """Equal values of equal types (0.0 is not 0; floats compared bit for bit)."""
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, tuple) and isinstance(b, tuple):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return type(a) is type(b) and (a == b or (a != a and b != b))


@pytest.mark.parametrize("path", sorted(builtin_paths().values()), ids=lambda p: p.stem)
def test_builtin_scene_holds_what_its_file_says(path):
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    scene = load_scene(path)
    got = as_data(scene)
    for part in ("bvp", "analytic", "vfife", "ancf"):
        table = dict(data.get(part, {}))
        table.update(table.pop("expert", {}))
        default = as_data(type(getattr(scene, part))())
        assert same(got.pop(part), {**default, **{k: tuple(v) if isinstance(v, list) else v
                                                   for k, v in table.items()}}), part
    assert got.pop("source") == path.name
    assert got["ends"] == {**as_data(scene.ends)} and scene.ends.kind in (
        "tdp_tension", "hang_off_angle", "top_tension", "fixed")
    expected = expected_scene(data)
    for key in expected:
        assert same(got[key], expected[key]), (key, got[key], expected[key])
    assert set(got) == set(expected)


# ------------------------------------------------------------------ layering and cost
def test_building_a_scene_is_cheap():
    # the cost study and sweeps build many scenes: a replace (all checks of the scene, none
    # of its unchanged parts) well below a millisecond (measured ~30 us)
    scene = load_scene(builtin_paths()["yu2021-a3"])
    n = 200
    per = timeit.timeit(lambda: scene.replace(gravity=9.8), number=n) / n
    assert per < 1e-3, per

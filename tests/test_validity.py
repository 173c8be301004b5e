"""A result outside the model is never a silent exit 0 (issue 13): overrides validated like
their scene keys, resolution and motion refused before solving, named warnings after
solving (riser/results/validity.py), ``--strict``, and the honesty of form (b)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from riser.results import validity
from riser.io.scene_file import parse_scene
from riser.results.profile import Profile
from verification.catalog import builtin_paths
from verification.pipeline import solve_scene

SCENES = Path(__file__).resolve().parents[1] / "verification" / "scenes"
NAMED = re.compile(r"^[a-z_]+: ")


def edited(tmp_path, builtin: str, *pairs, name="edited.toml") -> str:
    """A copy of a built-in scene file with text replaced (old, new pairs)."""
    text = builtin_paths()[builtin].read_text()
    for old, new in pairs:
        assert old in text, old
        text = text.replace(old, new)
    path = tmp_path / name
    path.write_text(text)
    return str(path)


# ----------------------------------------------------------------- refused before solving
@pytest.mark.parametrize("argv,key,words", [
    # the CLI option is checked against the scene key's range (riser/model/settings.py), and
    # named as the option
    (["solve", "scr-steel", "--method", "vfife", "--element-length", "5000"],
     "command line: --element-length", ["must be <= 1000 m", "got 5000"]),
    (["solve", "scr-steel", "--method", "vfife", "--element-length", "0"],
     "command line: --element-length", ["must be > 0"]),
    (["solve", "scr-steel", "--tolerance", "5"], "command line: --tolerance", ["<= 0.1"]),
    # 900 m elements on a 2,000 m SCR put the touchdown at x = 0 before issue 13
    (["solve", "scr-steel", "--method", "vfife", "--element-length", "900"],
     "command line: --element-length", ["at least 10 elements", "<= 200 m"]),
    # a careless 1e-9 m would ask for 2e12 elements: refused instead of running for ever
    (["solve", "scr-steel", "--method", "vfife", "--element-length", "1e-9"],
     "command line: --element-length", ["must be >= 0.02 m", "at most 100,000 elements"]),
    (["compare", "wang2014-baseline", "--element-length", "300"],
     "command line: --element-length", ["at least 10 elements"]),
])
def test_overrides_refused_like_their_keys(run_cli, tmp_path, argv, key, words):
    code, out, err = run_cli([*argv, "--out", str(tmp_path / "o")])
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {key}: "), err
    for w in words:
        assert w in lines[0]
    assert not (tmp_path / "o" / "profile.csv").exists()


def test_coarse_elements_in_scene_file_refused(run_cli, tmp_path):
    # the same rule from the scene key, fixed ends and a Wang form (before its BVP)
    path = edited(tmp_path, "scr-steel", ("[ends]", "[vfife]\nelement_length = 900.0\n\n[ends]"))
    code, _, err = run_cli(["solve", path, "--method", "vfife", "--out", str(tmp_path / "o")])
    assert code == 2 and "edited.toml: vfife.element_length: must be <= 200 m" in err
    path = edited(tmp_path, "yu2021-a3", ("[ends]", "[vfife]\nelement_length = 40.0\n\n[ends]"),
                  name="yu.toml")
    code, _, err = run_cli(["solve", path, "--method", "vfife", "--out", str(tmp_path / "o")])
    # yu2021-a3's shortest segment is 66.7 m: two elements need <= 33.35 m
    assert code == 2 and "yu.toml: vfife.element_length: must be <= 33.35 m" in err


def test_heave_out_of_the_water_modelled_and_warned(run_cli, tmp_path):
    # 20 m of heave on a hang-off 13.7 m below the surface lifts the top 6.3 m out of the
    # water: the dynamics models the sea surface (weight in air above it) and says so
    path = edited(tmp_path, "hard-large-heave", ("amplitude = 6.0", "amplitude = 20.0"),
                  ("duration = 60.0", "duration = 12.0"),
                  ("element_length = 2.0", "element_length = 10.0"))
    out = tmp_path / "o"
    code, _, err = run_cli(["solve", path, "--method", "vfife", "--out", str(out)])
    assert code == 0, err
    sm = json.loads((out / "summary.json").read_text())
    assert "sea_surface" in sm["effects"]
    above = [w for w in sm["warnings"] if w.startswith("above_surface: ")]
    assert above and "leave the water" in above[0] and "during the dynamics" in above[0]


# ----------------------------------------------------------------- named warnings after
def test_large_strain_in_dynamics_warned_and_strict(run_cli, tmp_path):
    # the 6 m heave started impulsively: T/EA reaches 0.13 % during the dynamics (from the
    # envelope), beyond a 0.04 % limit the static state (0.037 %) stays below. (It was 300
    # m of surge in 8 s, 235 m/s: refused now as an implausible top motion.)
    path = edited(tmp_path, "hard-large-heave",
                  ("ramp_time = 8.0 }", "ramp_time = 0.0 }"),
                  ("drag_tangential = 0.03", "drag_tangential = 0.03\nmax_strain = 4e-4"),
                  ("duration = 60.0", "duration = 3.0"), ("element_length = 2.0", "element_length = 5.0"))
    out = tmp_path / "o"
    code, _, err = run_cli(["solve", path, "--method", "vfife", "--out", str(out)])
    assert code == 0
    warnings = json.loads((out / "summary.json").read_text())["warnings"]
    strain = [w for w in warnings if w.startswith("axial_strain: ")]
    assert strain and "during the dynamics" in strain[0]
    assert "warning: vfife: axial_strain: " in err
    code, _, err = run_cli(["solve", path, "--method", "vfife", "--out", str(out), "--strict"])
    assert code == 1 and "--strict" in err.splitlines()[-1]


#: 900 m of line between ends 460 m apart, no [seabed]: it sags 174 m below y = 0
SAG = """
name = "sag"
[environment]
water_depth = 500.0
[line_types.c]
outer_diameter = 0.2
mass_per_length = 50.0
axial_stiffness = 1e9
bending_stiffness = 1e4
[[segments]]
line_type = "c"
length = 900.0
[ends]
anchor = [0.0, 50.0]
hang_off = [300.0, 400.0]
"""


def test_line_below_seabed_without_seabed_warned():
    # fixed ends, no [seabed]: 900 m of line between ends 460 m apart sags below y = 0
    sc = parse_scene(SAG, "sag.toml")
    res = solve_scene(sc, "vfife", element_length=5.0)
    assert res.converged
    below = [w for w in res.warnings if w.startswith("below_seabed: ")]
    assert below and "no [seabed]" in below[0]


def synthetic(scene_text_keys=""):
    return parse_scene(f"""
name = "syn"
[environment]
water_depth = 100.0
[seabed]
stiffness = 1e5
[line_types.c]
outer_diameter = 0.1
mass_per_length = 20.0
axial_stiffness = 1e8
bending_stiffness = 1e3
{scene_text_keys}
[[segments]]
line_type = "c"
length = 300.0
[ends]
anchor = [0.0, 0.0]
hang_off = [200.0, 90.0]
""", "syn.toml")


@pytest.mark.parametrize("keys,y,t,name", [
    # each check fires on its own, with its name; the thresholds are those of
    # riser/results/validity.py (surface: y > water_depth; elastic seabed: deeper than D;
    # compression: below -1e-3 of the largest tension, only when compression = false)
    ("", [0.0, 50.0, 100.5], [1e4, 2e4, 3e4], "above_surface"),
    ("", [-0.15, 50.0, 90.0], [1e4, 2e4, 3e4], "below_seabed"),
    ("compression = false", [0.0, 50.0, 90.0], [-100.0, 2e4, 3e4], "compression"),
    ("max_strain = 0.0002", [0.0, 50.0, 90.0], [1e4, 2e4, 3e4], "axial_strain"),
    ("", [0.0, 50.0, 90.0], [1e4, 2e4, 3e4], None),
    # a pipe takes compression; noise below 1e-3 of T_max is not compression
    ("", [0.0, 50.0, 90.0], [-100.0, 2e4, 3e4], None),
    ("compression = false", [0.0, 50.0, 90.0], [-20.0, 2e4, 3e4], None),
])
def test_each_check_named(keys, y, t, name):
    sc = synthetic(keys)
    s = np.array([0.0, 150.0, 300.0])
    y, t = np.array(y), np.array(t)
    got = validity.line_warnings(sc, s, y, y, t, t)
    assert [w.split(":")[0] for w in got] == ([name] if name else [])


def test_nonfinite_profile_is_a_failure():
    z = np.zeros(3)
    p = Profile(s=np.arange(3.0), x=z, y=z, z=z, theta=z, tension=np.array([1.0, np.nan, 1.0]),
                moment=z, shear=z, curvature=z)
    assert "non-finite tension" in validity.nonfinite(p)
    assert validity.nonfinite(Profile(s=np.arange(3.0), x=z, y=z, z=z, theta=z, tension=z,
                                      moment=z, shear=z, curvature=z)) is None


# ----------------------------------------------------------------- form (b) honesty
def test_form_b_says_the_first_segment_was_solved(run_cli, tmp_path):
    # the Wang baseline given by its hang-off (1586.3 m, 11.12 deg from the vertical):
    # the first segment's suspended length is solved (389.97 m; the file gives 390 m)
    path = edited(tmp_path, "wang2014-baseline", ("tdp_tension = 160000.0", "hang_off_height = "
                  "1586.3\nhang_off_angle_from_vertical_deg = 11.12"))
    out = tmp_path / "o"
    code, stdout, _ = run_cli(["solve", path, "--out", str(out)])
    sm = json.loads((out / "summary.json").read_text())
    assert code == 0 and sm["hang_off_angle_deg"] == pytest.approx(78.88, abs=1e-9)
    assert "segments[0] suspended length solved: 389.9" in stdout
    assert "the file gives 390 m" in sm["message"] and sm["first_segment_length_in_file"] == 390.0
    assert sm["warnings"] == []
    # 12 deg entered from the horizontal (meant from the vertical): a 12 km line, warned
    path = edited(tmp_path, "wang2014-baseline", ("tdp_tension = 160000.0", "hang_off_height = "
                  "1586.3\nhang_off_angle_from_horizontal_deg = 12.0"), name="b12.toml")
    code, _, err = run_cli(["solve", path, "--out", str(out)])
    sm = json.loads((out / "summary.json").read_text())
    assert code == 0 and sm["first_segment_suspended_length"] > 10000.0
    assert [w.split(":")[0] for w in sm["warnings"]] == ["first_segment_length"]
    assert "warning: bvp: first_segment_length:" in err
    code, _, _ = run_cli(["solve", path, "--out", str(out), "--strict"])
    assert code == 1


def test_builtin_warnings_are_named():
    # every warning a solver emits starts with its name (docs/theory.md), checked on
    # warnings each method really emits, on a case made to produce them: the VFIFE on
    # scr-steel in 50 m elements (longer than half the bending length sqrt(EI/T) = 3.4 m
    # and than a quarter of (EI/|w|)^(1/3) = 26.5 m: both limits), the BVP on scr-steel with
    # a 0.01 % strain limit (T/EA reaches 0.037 % at the hang-off), the analytic method on a
    # 900 m line hung from ends 460 m apart without a seabed (174 m below y = 0)
    scr = (SCENES / "scr-steel.toml").read_text()
    strained = scr.replace("drag_tangential = 0.03", "drag_tangential = 0.03\nmax_strain = 1e-4")
    assert strained != scr
    cases = [(parse_scene(scr, "scr-steel.toml"), "vfife", {"element_length": 50.0},
              ["resolution", "resolution"]),
             (parse_scene(strained, "strained.toml"), "bvp", {}, ["axial_strain"]),
             (parse_scene(SAG, "sag.toml"), "analytic", {}, ["below_seabed"])]
    for scene, method, kw, names in cases:
        res = solve_scene(scene, method, **kw)
        assert res.converged, (method, res.message)
        assert [w.split(":")[0] for w in res.warnings] == names, (method, res.warnings)
        for w in res.warnings:
            assert NAMED.match(w), w

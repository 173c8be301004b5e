"""Careless input to the model is never a silent wrong answer (issue: the careless model):
a Wang-form scene solved by the VFIFE says what it solved and carries the BVP's warnings;
current heights above the surface, an anchor above the water, implausible top motions
and a vertical top motion into the seabed are refused before solving with one line
naming the key; an anchor typed a hair above the seabed is put on it (with a note); the
VFIFE reports its touchdown whenever line lies on the seabed.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from riser.errors import SceneError
from riser.io.scene_file import parse_scene
from riser.results.result import SolveResult, Status
from riser.model.transform import fixed_ends_scene
from verification.catalog import builtin_paths
from verification.pipeline import VfifeEquivalent, conversion_warnings

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "scenes"


def text_of(scene: str, *pairs) -> str:
    """A built-in scene's (or an example's, 'examples/NAME') file text with text replaced
    (old, new pairs; each old must be there)."""
    path = (EXAMPLES / f"{scene.split('/', 1)[1]}.toml" if scene.startswith("examples/")
            else builtin_paths()[scene])
    text = path.read_text()
    for old, new in pairs:
        assert old in text, old
        text = text.replace(old, new)
    return text


def written(tmp_path, scene: str, *pairs, name: str = "edited.toml") -> str:
    """:func:`text_of` written to ``tmp_path / name``; returns the path."""
    path = tmp_path / name
    path.write_text(text_of(scene, *pairs))
    return str(path)


def refused(run_cli, path: str, *argv) -> str:
    """The one line of a scene refused before solving (exit 2); returns it."""
    code, out, err = run_cli(["solve", path, *argv, "--out", str(Path(path).parent / "o")])
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and lines[0].startswith("error: "), (code, out, err)
    assert "Traceback" not in err
    return lines[0]


def summary(out) -> dict:
    return json.loads((Path(out) / "summary.json").read_text())


# ------------------------------------------------------------------ 1. the conversion
WANG_B = "tdp_tension = 160000.0"
#: the Wang baseline given by its hang-off, 1586.3 m high at 11.12 deg from the vertical
AS_MEANT = "hang_off_height = 1586.3\nhang_off_angle_from_vertical_deg = 11.12"
#: ... with the angle typed from the horizontal instead (12 deg)
TYPED = "hang_off_height = 1586.3\nhang_off_angle_from_horizontal_deg = 12.0"


def test_vfife_of_a_wang_form_carries_the_bvp_warnings_and_says_what_it_solved(run_cli,
                                                                              tmp_path):
    # The BVP solves 12 deg from the horizontal with a 12 km first segment (+2997 %,
    # warned first_segment_length) at 33,484 kN; the VFIFE's fixed-ends equivalent, an
    # extensible line between the same ends, lays km of it on the seabed and ends at 19.4
    # deg with 11,951 kN. It exited 0 with no word of either; now it carries the BVP's
    # warning, the conversion note in its message and an ends_conversion warning.
    path = written(tmp_path, "wang2014-baseline", (WANG_B, TYPED), name="b12.toml")
    out = tmp_path / "v"
    code, stdout, err = run_cli(["solve", path, "--method", "vfife", "--element-length", "5",
                                 "--out", str(out)])
    assert code == 0, err
    sm = summary(out)
    names = [w.split(":")[0] for w in sm["warnings"]]
    assert "first_segment_length" in names and "ends_conversion" in names, sm["warnings"]
    conv = next(w for w in sm["warnings"] if w.startswith("ends_conversion: "))
    assert "hang-off angle 19.4" in conv and "against 12.000 deg" in conv
    assert "beyond 0.5 deg" in conv and "beyond 1 %" in conv and "different problem" in conv
    assert "12 deg from the horizontal" in conv
    first = next(w for w in sm["warnings"] if w.startswith("first_segment_length: "))
    assert "conversion to fixed ends" in first
    assert "warning: vfife: ends_conversion:" in err
    assert "warning: vfife: first_segment_length:" in err
    # the message says the model solved (the conversion note), on the console too
    assert "hang_off_angle ends converted to fixed ends" in sm["message"]
    assert "hang_off_angle ends converted to fixed ends" in stdout
    assert abs(sm["hang_off_angle_deg"] - 12.0) > 5.0            # the departure is real
    code, _, err = run_cli(["solve", path, "--method", "vfife", "--element-length", "5",
                            "--out", str(out), "--strict"])
    assert code == 1 and "--strict" in err.splitlines()[-1]


def test_vfife_of_a_consistent_wang_form_is_not_warned(run_cli, tmp_path):
    # the same riser as meant (11.12 deg from the vertical): the conversion's model
    # difference moves the angle by thousandths of a degree, far inside the tolerance
    path = written(tmp_path, "wang2014-baseline", (WANG_B, AS_MEANT), name="b.toml")
    out = tmp_path / "v"
    code, stdout, err = run_cli(["solve", path, "--method", "vfife", "--element-length", "2",
                                 "--out", str(out)])
    assert code == 0, err
    sm = summary(out)
    assert [w.split(":")[0] for w in sm["warnings"]] == ["resolution"], sm["warnings"]
    assert sm["hang_off_angle_deg"] == pytest.approx(78.88, abs=0.05)
    assert "hang_off_angle ends converted to fixed ends" in stdout


def test_conversion_carries_the_bvp_warnings_but_not_what_the_vfife_models():
    # the BVP's ignored_input ([dynamics], seabed friction) names what the VFIFE does
    # model: not carried; its first_segment_length is, even on a failed VFIFE run
    scene = parse_scene(text_of("wang2014-baseline", (WANG_B, TYPED)), "b12.toml")
    paper = SolveResult("bvp", scene.name, Status.CONVERGED, "", warnings=[
        "ignored_input: bvp solves statics only: [dynamics] ignored",
        "first_segment_length: segments[0] suspended length solved: 12079.221 m"])
    failed = SolveResult("vfife", scene.name, Status.NOT_CONVERGED, "steps")
    got = conversion_warnings(scene, VfifeEquivalent(scene, 300.0, "note", paper), failed)
    assert len(got) == 1 and got[0].startswith("first_segment_length: segments[0]")
    assert got[0].endswith("that the conversion to fixed ends started from)")


# ------------------------------------------------------------------ 2. current heights
CURRENT = ("speeds = [0.2, 0.8]", "speeds = [0.3, 1.0]")


def test_current_heights_above_the_water_depth_refused(run_cli, tmp_path):
    # [0, 1500] m in 150 m of water gave the surface 0.37 m/s, not the 1.0 m/s meant
    path = written(tmp_path, "examples/power-cable", CURRENT,
                   ("heights = [0.0, 150.0]", "heights = [0.0, 1500.0]"), name="km.toml")
    line = refused(run_cli, path)
    assert "environment.current.heights[1]: must be <= 150 m, the water depth" in line
    assert "got 1500" in line


def test_current_heights_without_water_depth_refer_to_the_hang_off(run_cli, tmp_path):
    # no water_depth: the hang-off height (140 m) is the reference (docs/scene-files.md)
    path = written(tmp_path, "examples/power-cable", CURRENT,
                   ("water_depth = 150.0", ""),
                   ("heights = [0.0, 150.0]", "heights = [0.0, 1500.0]"), name="nodepth.toml")
    line = refused(run_cli, path)
    assert "environment.current.heights[1]: must be <= 140 m, the hang-off height" in line
    assert "give water_depth" in line
    # up to the hang-off it is accepted
    text = text_of("examples/power-cable", CURRENT, ("water_depth = 150.0", ""),
                   ("heights = [0.0, 150.0]", "heights = [0.0, 140.0]"))
    assert parse_scene(text, "ok.toml").current.heights == (0.0, 140.0)


def test_current_heights_below_the_seabed_refused(run_cli, tmp_path):
    # heights typed down from the surface (negative): the whole line saw the speed of 0 m
    path = written(tmp_path, "examples/power-cable", CURRENT,
                   ("heights = [0.0, 150.0]", "heights = [-150.0, 0.0]"), name="neg.toml")
    assert "environment.current.heights[0]: must be >= 0 m, got -150" in refused(run_cli, path)


def test_touchdown_form_without_depth_keeps_its_current_through_the_conversion():
    # a touchdown-tension scene has no hang-off height to check against before solving;
    # its fixed-ends equivalent cuts the profile at the solved hang-off, with the same
    # speeds along the line (the converted scene passes the check)
    text = text_of("wang2014-current-0p75", ("heights = [0.0]", "heights = [0.0, 5000.0]"),
                   ("speeds = [0.75]", "speeds = [0.0, 1.0]"))
    scene = parse_scene(text, "w.toml")
    fixed = fixed_ends_scene(scene, (1625.0, 1586.3), 300.0)
    assert fixed.current.heights == (0.0, 1586.3)
    y = np.linspace(0.0, 1586.3, 50)
    assert np.allclose(fixed.current.speed(y), scene.current.speed(y), rtol=0, atol=1e-12)


def test_anchor_above_the_water_refused(run_cli, tmp_path):
    # an anchor above the surface was accepted (only the hang-off was checked)
    path = written(tmp_path, "scr-steel", ("anchor = [0.0, 0.0]", "anchor = [0.0, 1200.0]"),
                   name="up.toml")
    line = refused(run_cli, path)
    assert "ends.anchor[1]: must be <= water_depth 1000 m" in line and "got 1200" in line


# ------------------------------------------------------------------ 3. the anchor
def test_anchor_a_millimetre_above_the_seabed_is_put_on_it(run_cli, tmp_path):
    # 1 mm above the seabed: the BVP took 7.7 s of continuation and the VFIFE 200,000
    # steps, neither reporting the touchdown of the 515 m of line on the seabed. Within 5 %
    # of the pipe's diameter (10 mm) the anchor is put on the seabed, with a note.
    path = written(tmp_path, "scr-steel", ("anchor = [0.0, 0.0]", "anchor = [0.0, 0.001]"),
                   name="a1mm.toml")
    for method in ("bvp", "vfife"):
        out = tmp_path / method
        code, stdout, err = run_cli(["solve", path, "--method", method, "--out", str(out)])
        assert code == 0, err
        sm = summary(out)
        assert "put on it (y = 0)" in sm["message"] and "put on it (y = 0)" in stdout
        assert sm["scene_notes"] and "ends.anchor[1] = 0.001 m" in sm["scene_notes"][0]
        assert sm["tdp_x"] == pytest.approx(514.7, abs=0.5), method
        assert sm["warnings"] == [], (method, sm["warnings"])
    scene = parse_scene(Path(path).read_text(), "a1mm.toml")
    assert scene.ends.anchor == (0.0, 0.0) and scene.anchor_snapped_from == 0.001
    assert scene.replace(gravity=9.8).notes == scene.notes          # kept by a replace
    assert scene.replace(**{"ends.anchor": [0.0, 0.5]}).notes == ()
    # beyond the tolerance (0.0102 m) the anchor stays where it is given
    far = parse_scene(text_of("scr-steel", ("anchor = [0.0, 0.0]", "anchor = [0.0, 0.02]")),
                      "a2cm.toml")
    assert far.ends.anchor == (0.0, 0.02) and far.notes == ()
    # without a [seabed] there is nothing to put it on
    free = parse_scene(text_of("scr-steel", ("[seabed]\nstiffness = 1.0e5", ""),
                               ("anchor = [0.0, 0.0]", "anchor = [0.0, 0.001]")), "f.toml")
    assert free.ends.anchor == (0.0, 0.001) and free.notes == ()


@pytest.mark.parametrize("method", ["vfife", "bvp"])
def test_both_methods_report_the_touchdown_of_a_lifted_anchor(run_cli, tmp_path, method):
    # an anchor 0.5 m above the seabed (beyond the tolerance): the line reaches the seabed
    # near the anchor and lies on it up to its touchdown at x = 514.7 m, which neither
    # method reported (their touchdown searches started at the anchor only). The two
    # agree within compare's tdp_x tolerance (0.25 m) and tdp_tension's (2e-4 of T_max)
    path = written(tmp_path, "scr-steel", ("anchor = [0.0, 0.0]", "anchor = [0.0, 0.5]"),
                   name="lifted.toml")
    out = tmp_path / "v"
    code, stdout, err = run_cli(["solve", path, "--method", method, "--out", str(out)])
    assert code == 0, err
    sm = summary(out)
    assert sm["tdp_x"] == pytest.approx(514.7, abs=0.25) and "touchdown x = 514." in stdout
    assert sm["tdp_tension"] == pytest.approx(316.7e3, abs=2e-4 * 842e3)


# ------------------------------------------------------------------ 4. the top motion
LARGE_HEAVE = 'axis = "y", amplitude = 6.0, period = 8.0, ramp_time = 8.0'


def test_implausible_top_motion_refused_before_solving(run_cli, tmp_path):
    # 300 m in 1 s: a peak speed of 1885 m/s, which the dynamics blamed on "explicit drag
    # near its stability limit"; now one line naming the key, before any solving
    path = written(tmp_path, "hard-large-heave",
                   (LARGE_HEAVE, 'axis = "x", amplitude = 300.0, period = 1.0, ramp_time = 1.0'),
                   name="fast.toml")
    line = refused(run_cli, path, "--method", "vfife")
    assert "dynamics.top_motion.amplitude: peak speed 2 pi amplitude / period = 1885 m/s" in line
    assert "must be <= 20 m/s" in line


@pytest.mark.parametrize("motion,key,words", [
    # a vibration, not a vessel: 0.5 m in 0.2 s accelerates at 493 m/s2 (50 g)
    ('axis = "y", amplitude = 0.5, period = 0.2, ramp_time = 1.0', "dynamics.top_motion.period",
     ["493.5 m/s2", "must be <= 20 m/s2"]),
    # a step of 5 m in 10 ms
    ('axis = "y", times = [0.0, 10.0, 10.01], displacements = [0.0, 0.0, 5.0]',
     "dynamics.top_motion.displacements[2]", ["500 m/s", "must be <= 20 m/s"]),
    # a series that starts away from the static position without a ramp: a jump at t = 0
    ('axis = "y", times = [0.0, 10.0], displacements = [3.0, 3.0]',
     "dynamics.top_motion.displacements[0]", ["must be 0 m without a ramp", "got 3"]),
])
def test_implausible_top_motions(motion, key, words):
    text = text_of("hard-large-heave", (LARGE_HEAVE, motion))
    with pytest.raises(SceneError) as exc:
        parse_scene(text, "m.toml")
    msg = str(exc.value)
    assert exc.value.key == key and "\n" not in msg, msg
    for w in words:
        assert w in msg, msg
    # the plausible ones solve as before: a 6 m heave in 8 s peaks at 4.7 m/s
    ok = parse_scene(text_of("hard-large-heave"), "ok.toml").dynamics.top_motion
    assert ok.peak_speed == pytest.approx(2 * math.pi * 6.0 / 8.0)


def test_vertical_top_motion_into_the_seabed_refused(run_cli, tmp_path):
    # the power cable's hang-off is 140 m up: a 200 m heave drives it through the seabed
    path = tmp_path / "heave.toml"
    path.write_text(text_of("examples/power-cable") + "\n[dynamics]\nduration = 300.0\n"
                    'top_motion = { axis = "y", amplitude = 200.0, period = 100.0 }\n')
    line = refused(run_cli, str(path), "--method", "vfife")
    assert "dynamics.top_motion.amplitude: moves the hang-off 200 m down from its height " \
           "140 m" in line and "must be < 140 m down" in line

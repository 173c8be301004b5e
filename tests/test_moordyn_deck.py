"""MoorDyn v2 decks in and out (issue 17, items 1 and 2); no moordyn package needed.

The round trip (export, then import) is checked against the scene's own physics: the
section properties per metre that both methods read (riser.model.sections), the ends, the
environment, the seabed and the current vector at every height, to input precision
(numbers are written with repr, so only the equivalent-diameter arithmetic rounds: 1e-12).
Bad decks must give one line naming the deck line, exit 2.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from riser.errors import UnsupportedSceneError
from riser.io.moordyn.deck import DeckError, parse_deck, read_deck
from riser.io.moordyn.deck_from_scene import export_scene
from riser.io.moordyn.scene_from_deck import import_deck
from riser.io.scene_file import parse_scene
from riser.model.scene import FixedEnds
from riser.model.sections import segment_properties
from verification.catalog import builtin_paths, resolve
from verification.cli import main
from verification.peers.moordyn.deck import export

RTOL = 1e-12   # repr-exact numbers; the equivalent diameter's sqrt and squares round


def _props_at(scene, s):
    for p in segment_properties(scene):
        if p.s_start <= s <= p.s_end:
            return p
    raise AssertionError(s)


def assert_same_physics(a, b):
    """Scene b solves the same problem as scene a (segments may be merged)."""
    assert b.gravity == a.gravity and b.water_density == a.water_density
    if a.water_depth is not None:
        assert b.water_depth == pytest.approx(a.water_depth, rel=RTOL)
    assert isinstance(a.ends, FixedEnds) and isinstance(b.ends, FixedEnds)
    # the deck is placed with the anchor at x = 0: compare relative positions
    ax, bx = a.ends.hang_off[0] - a.ends.anchor[0], b.ends.hang_off[0] - b.ends.anchor[0]
    assert bx == pytest.approx(ax, rel=RTOL, abs=1e-9)
    assert b.ends.anchor[1] == pytest.approx(a.ends.anchor[1], abs=1e-9)
    assert b.ends.hang_off[1] == pytest.approx(a.ends.hang_off[1], rel=RTOL)
    assert b.total_length == pytest.approx(a.total_length, rel=RTOL)
    edges = sorted({p.s_start for p in segment_properties(a)} | {a.total_length})
    for s in (np.array(edges[:-1]) + np.array(edges[1:])) / 2.0:
        pa, pb = _props_at(a, s), _props_at(b, s)
        for q in ("EA", "EI", "mass", "weight", "drag_normal_coef", "drag_tangential_coef",
                  "added_mass"):
            assert getattr(pb, q) == pytest.approx(getattr(pa, q), rel=RTOL, abs=1e-9), (s, q)
    if a.seabed is None:
        assert b.seabed is None
    else:
        for q in ("stiffness", "friction", "damping"):
            assert getattr(b.seabed, q) == pytest.approx(getattr(a.seabed, q), rel=RTOL,
                                                         abs=1e-12)
    if a.current is None:
        assert b.current is None
        return
    for y in np.linspace(-10.0, a.ends.hang_off[1] + 10.0, 57):
        ua = a.current.speed(y) * a.current.direction
        ub = b.current.speed(y) * b.current.direction
        np.testing.assert_allclose(ub, ua, rtol=0, atol=1e-12)


@pytest.mark.parametrize("name", ["scr-steel", "yu2021-a3", "yu2021-a2-sheared",
                                  "wang2014-baseline", "wang2014-current-0p75"])
def test_round_trip_of_built_in_scenes(name, tmp_path):
    """Export then import: the same physics (the lazy waves Wang and Yu A3, the SCR, and
    two with a current, one of them reversed (heading 180))."""
    files = export(resolve(name), tmp_path / f"{name}.dat", segment_length=10.0)
    text, back, _ = import_deck(files.deck_path)
    assert_same_physics(files.scene, back)
    assert parse_scene(text).name == back.name           # the written file reads back
    # a touchdown-form scene is exported as its fixed-ends conversion, with the note
    if not isinstance(resolve(name).ends, FixedEnds):
        assert "Converted from the 'tdp_tension' form" in files.export.text
        assert files.s_shift > 0


def test_buoyancy_section_is_an_equivalent_section(tmp_path):
    """Yu A3's buoyancy modules: the deck's Diam, Cd, Ca give the scene's weight, drag and
    added mass per metre by MoorDyn's own formulas (written out here by hand)."""
    scene = resolve("yu2021-a3")
    ex = export_scene(scene, segment_length=10.0)
    g, rho = scene.gravity, scene.water_density
    buoy = ex.deck.line_types["flexible_s2"]
    p = segment_properties(scene)[1]                   # buoyancy section 3
    assert (buoy.mass - rho * math.pi / 4 * buoy.diameter ** 2) * g == pytest.approx(p.weight, rel=1e-12)
    assert 0.5 * rho * buoy.diameter * buoy.Cd == pytest.approx(p.drag_normal_coef, rel=1e-12)
    assert buoy.Ca * rho * math.pi / 4 * buoy.diameter ** 2 == pytest.approx(p.added_mass, rel=1e-12)
    assert buoy.mass == pytest.approx(p.mass, rel=1e-15)           # the inertia is kept
    assert p.weight < 0 and buoy.diameter > scene.line_types["flexible"].outer_diameter
    assert "hinges" in ex.text and "equivalent section" in ex.text
    # 7 segments alternate: 7 lines, 6 free points between two fixed ends
    assert [pt.attachment for pt in ex.deck.points] == ["Fixed"] + ["Free"] * 6 + ["Fixed"]


def test_adjacent_equal_segments_are_one_line():
    """A joint is a hinge in MoorDyn: none is added where the scene has no change."""
    text = builtin_paths()["scr-steel"].read_text().replace(
        'length = 2000.0\nlabel = "riser"',
        'length = 1200.0\n\n[[segments]]\nline_type = "steel"\nlength = 800.0')
    scene = parse_scene(text)
    assert len(scene.segments) == 2
    assert len(export_scene(scene).deck.lines) == 1


def test_rotated_deck_imports_to_the_same_scene(tmp_path):
    """The scene's x-y plane is the vertical plane through the two ends, whatever the deck's
    heading: turn an exported deck (points and current) by 30 deg about Z."""
    scene = resolve("yu2021-a2-sheared")
    ex = export_scene(scene, segment_length=10.0)
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    deck = ex.text.splitlines()
    out = []
    section = None
    for line in deck:
        if line.startswith("---"):
            section = line
        tok = line.split()
        if section and "POINTS" in section and tok and tok[0].isdigit():
            x, y = float(tok[2]), float(tok[3])
            tok[2], tok[3] = repr(c * x - s * y), repr(s * x + c * y)
            line = "  ".join(tok)
        out.append(line)
    (tmp_path / "deck.dat").write_text("\n".join(out) + "\n")
    prof = ex.current_profile.splitlines()
    rows = []
    for line in prof[3:]:
        z, ux, uy, uz = map(float, line.split())
        rows.append(f"{z!r} {c * ux - s * uy!r} {s * ux + c * uy!r} 0.0")
    (tmp_path / "current_profile.txt").write_text("\n".join(prof[:3] + rows) + "\n")
    _, back, _ = import_deck(tmp_path / "deck.dat")
    assert_same_physics(scene, back)


# --------------------------------------------------------------------- bad input
GOOD = export_scene(resolve("scr-steel"), segment_length=100.0).text


def _line_of(text: str, pattern: str) -> int:
    return next(i for i, l in enumerate(text.splitlines(), 1) if re.search(pattern, l))


def _bad(text, tmp_path, capsys, profile=None):
    """Run import-moordyn on ``text``: exit 2, one line on stderr, no scene written."""
    path = tmp_path / "bad.dat"
    path.write_text(text)
    if profile is not None:
        (tmp_path / "current_profile.txt").write_text(profile)
    assert main(["import-moordyn", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("error: ")
    assert not (tmp_path / "bad.toml").exists()
    return err


BAD = {
    # name: (edit of the good deck, the line the error must name, words it must hold)
    "syntax error": (lambda t: t.replace("  86.8279", "  8x6.8279"), r"^steel ", "not a number"),
    "missing EI": (lambda t: re.sub(r"(?m)^(steel(?:\s+\S+){4})\s+\S+", r"\1", t), r"^steel ",
                   "EI is missing"),
    "EI zero": (lambda t: re.sub(r"(?m)^(steel(?:\s+\S+){4})\s+\S+", r"\1  0", t), r"^steel ",
                "EI: must be > 0"),
    "rod": (lambda t: t.replace("---------------------- POINTS",
                                "---------------------- RODS ----\nID RodType Att Xa Ya Za Xb Yb Zb N Out\n"
                                "(#) (-) (-) (m) (m) (m) (m) (m) (m) (-) (-)\n"
                                "1 can Fixed 0 0 -10 0 0 -5 4 -\n"
                                "---------------------- POINTS"), r"^1 can Fixed", "rod"),
    "body": (lambda t: t.replace("---------------------- POINTS",
                                 "---------------------- BODIES ----\nID Att X0 Y0 Z0 r0 p0 y0 M CG I V CdA Ca\n"
                                 "(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m2) (m3) (m2) (-)\n"
                                 "1 coupled 0 0 0 0 0 0 0 0 0 0 0 0\n"
                                 "---------------------- POINTS"), r"^1 coupled", "body"),
    "third fixed end": (lambda t: t.replace("2  Fixed  1500", "2  Free  1500").replace(
        "1  steel  1  2  2000  20  -", "1  steel  1  2  1000  10  -\n2  steel  2  3  500  5  -\n"
        "3  steel  2  4  500  5  -").replace("---------------------- LINES",
                                             "3  Fixed  1600  0  0  0  0  0  0\n4  Fixed  1700  0  0  0  0  0  0\n"
                                             "---------------------- LINES"), r"^2  Free", "joins 3"),
    "coupled without position": (lambda t: t.replace("2  Fixed  1500  0  0", "2  Coupled  -  -  -"),
                                 r"^2  Coupled", "no position"),
    "mass on a fixed end": (lambda t: t.replace("2  Fixed  1500  0  0  0  0",
                                                "2  Fixed  1500  0  0  500  0"),
                            r"^2  Fixed", "on a fixed or coupled end"),
    "rod end attachment": (lambda t: t.replace("1  steel  1  2  2000", "1  steel  1  R1A  2000"),
                           r"^1  steel", "rod end"),
    "waves": (lambda t: t.replace("0                        writeLog", "0 writeLog\n2 WaveKin"),
              r"^2 WaveKin", "waves"),
    # MoorDyn v1's lines (UnstrLen third); its headers (NODE PROPERTIES, SOLVER OPTIONS)
    # are v2 headers to MoorDyn-C 2.7 (tests/test_moordyn_decks.py)
    "v1 deck": (lambda t: t.replace("ID   LineType   AttachA   AttachB   UnstrLen",
                                    "Line LineType   UnstrLen NumSegs NodeAnch").replace(
        "1  steel  1  2  2000  20  -", "1  steel  2000.0  20  1  2  -"), r"^1  steel",
                "MoorDyn v1's layout"),
    # no WtrDpth and no point below the surface: MoorDyn-C's depth is 0
    "no depth": (lambda t: re.sub(r"(?m)^\S+\s+WtrDpth.*\n", "", t).replace(
        "1  Fixed  0  0  -1000", "1  Fixed  0  0  0"), None, "water depth must be > 0"),
}


@pytest.mark.parametrize("case", list(BAD))
def test_bad_deck_one_line_naming_the_deck_line(case, tmp_path, capsys):
    edit, pattern, words = BAD[case]
    text = edit(GOOD)
    assert text != GOOD, "the edit must change the deck"
    err = _bad(text, tmp_path, capsys)
    assert words in err, err
    if pattern is not None:
        assert f"bad.dat: line {_line_of(text, pattern)}: " in err, err


def test_vertical_current_is_refused(tmp_path, capsys):
    """A current that turns with depth imports (tests/test_moordyn_3d.py); one with a
    vertical component is still refused, naming its row."""
    text = GOOD.replace("0                        writeLog", "0 writeLog\n1 Currents")
    profile = "h\nh\nh\n-1000 0.5 0 0\n-500 0.2 0.3 0.1\n0 1.0 0 0\n"
    err = _bad(text, tmp_path, capsys, profile)
    assert "current_profile.txt: line 5: uz = 0.1: a vertical current" in err


def test_missing_current_file_is_refused(tmp_path, capsys):
    text = GOOD.replace("0                        writeLog", "0 writeLog\n1 Currents")
    err = _bad(text, tmp_path, capsys)
    assert "Currents = 1 needs current_profile.txt" in err


def test_deck_values_outside_scene_ranges_name_the_deck_line(tmp_path, capsys):
    """A valid deck whose value a scene refuses (a 7 m diameter): the scene's rule, at the
    deck's line."""
    text = GOOD.replace("steel  0.2032", "steel  7.0")
    err = _bad(text, tmp_path, capsys)
    assert f"line {_line_of(text, r'^steel ')}: line_types.steel.outer_diameter" in err


def test_export_refuses_what_moordyn_cannot_hold():
    flow = resolve("scr-steel")
    with pytest.raises(UnsupportedSceneError, match="inextensible"):
        export_scene(flow.replace(model={"axial": "inextensible"}))
    with pytest.raises(UnsupportedSceneError, match="MoorDyn needs fixed ends"):
        export_scene(resolve("wang2014-baseline"))


def test_cli_round_trip(tmp_path, capsys):
    """export-moordyn then import-moordyn from the command line; the imported scene solves
    (BVP) to the original's hang-off tension."""
    deck = tmp_path / "scr.dat"
    assert main(["export-moordyn", "scr-steel", "--out", str(deck), "--segment-length", "50"]) == 0
    assert main(["import-moordyn", str(deck)]) == 0
    assert (tmp_path / "scr.toml").exists()
    assert read_deck(deck).lines[0].segments == 40
    assert main(["export-moordyn", "scr-steel", "--segment-length", "0"]) == 2
    assert "--segment-length" in capsys.readouterr().err
    # fewer than ten segments over the 2000 m line, or none: refused before solving
    assert main(["export-moordyn", "scr-steel", "--segment-length", "500"]) == 2
    assert main(["compare", "scr-steel", "--peer", "moordyn", "--peer-segment-length", "0",
                 "--out", str(tmp_path / "c")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and all("must be between 0.01 and 200 m" in e for e in err)
    assert not (tmp_path / "c" / "agreement.csv").exists()
    assert parse_deck(GOOD).options["wtrdpth"][0] == "1000.0"
    with pytest.raises(DeckError, match="line 4: section 'Points' appears twice"):
        parse_deck("---- POINTS ----\nh\nh\n---- POINTS ----\n")
    # the same problem: the BVP gives the same hang-off tension (1e-9: a tenth of the
    # collocation tolerance; the inputs agree to 1e-15)
    from riser.io.scene_file import load_scene
    from verification.pipeline import solve_scene
    t0 = solve_scene(resolve("scr-steel"), "bvp").summary()["hang_off_tension"]
    t1 = solve_scene(load_scene(tmp_path / "scr.toml"), "bvp").summary()["hang_off_tension"]
    assert t1 == pytest.approx(t0, rel=1e-9)

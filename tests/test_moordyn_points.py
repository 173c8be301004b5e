"""MoorDyn points <-> scene attachments (``[[attachments]]``); no moordyn package needed but
for the last test.

A MoorDyn free point with a mass M, volume V, CdA and Ca joining two lines is a scene
attachment at the joint's arc length (the unstretched lengths of the lines below it):
mass = M, volume = V, drag_area = CdA, added_mass_coefficient = Ca. A free point at the
bottom end of a chain hanging from one fixed end is a free anchor (``[ends.anchor_joint]
kind = "free"``) with its attachment at s = 0. The export splits the line at every
attachment into MoorDyn lines meeting at the point.

Tolerances: the numbers of a point are copied (written with repr, read with float), so
they are compared exactly (==); an arc length read back is a sum of line lengths, each
written with repr, so it rounds in the last bits of a few additions: 1e-9 m (the round
trip's promise; the rounding is ~1e-13 m on lines of 1e3 m).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from riser.errors import UnsupportedSceneError
from riser.io.moordyn.deck import parse_deck
from riser.io.moordyn.deck_from_scene import SNAP, export_scene
from riser.io.moordyn.scene_from_deck import import_deck
from riser.io.scene_file import parse_scene
from riser.model.sections import segment_properties
from verification.cli import main

# A steel riser (the exported scr-steel deck's line type) in three MoorDyn lines written
# out of order, one reversed: a clump weight on point 2 (s = 800 m) and a buoy on point 4
# (s = 800 + 600 = 1400 m).
DECK = """\
--------------------- MoorDyn Input File ------------------------------------
A steel riser with a clump weight and a buoy
---------------------- LINE TYPES --------------------------------------------------------
TypeName   Diam   Mass/m   EA   BA/-zeta   EI   Cd   Ca   CdAx   CaAx
(name)     (m)    (kg/m)   (N)  (N-s/-)   (N-m^2) (-)  (-)  (-)    (-)
steel  0.2032  86.82795539703044  2275643614.7313323  -0.8  9744766.776111541  1  1  0.03  0
---------------------- POINTS -----------------------------------------------
ID   Attachment   X   Y   Z   Mass   Volume   CdA   Ca
(#)  (-)          (m) (m) (m) (kg)   (m^3)    (m^2) (-)
1  Fixed  0  0  -1000  0  0  0  0
2  Free  600  0  -600  5000.5  0.6375  1.25  0.9
3  Fixed  1500  0  0  0  0  0  0
4  Free  1050  0  -300  200  7.5  3.5  1.1
---------------------- LINES ------------------------------------------------
ID   LineType   AttachA   AttachB   UnstrLen   NumSegs   LineOutputs
(#)  (name)     (#)       (#)       (m)        (-)       (-)
1  steel  1  2  800  40  -
2  steel  4  2  600  30  -
3  steel  4  3  600  30  -
---------------------- OPTIONS -----------------------------------------
0                        writeLog     - no log file
9.81                     g            - gravity (m/s^2)
1025.0                   rho          - water density (kg/m^3)
1000.0                   WtrDpth      - water depth (m)
492125.9842519685        kBot         - seabed stiffness (Pa/m)
0.0                      cBot         - seabed damping (Pa-s/m)
---------------------- OUTPUTS -----------------------------------------
AnchTen1
FairTen3
------------------------- need this line --------------------------------
"""

# The same line type hanging 100 m from a fixed point with a 4 t clump on its free end
# (MoorDyn's pendulum, with bending stiffness), the end 10 m off the vertical.
HANGING = """\
--------------------- MoorDyn Input File ------------------------------------
A line hanging from a fixed point, a clump on its free end
---------------------- LINE TYPES --------------------------------------------------------
TypeName   Diam   Mass/m   EA   BA/-zeta   EI   Cd   Ca   CdAx   CaAx
(name)     (m)    (kg/m)   (N)  (N-s/-)   (N-m^2) (-)  (-)  (-)    (-)
steel  0.2032  86.82795539703044  2275643614.7313323  -0.8  9744766.776111541  1  1  0.03  0
---------------------- POINTS -----------------------------------------------
ID   Attachment   X   Y   Z   Mass   Volume   CdA   Ca
(#)  (-)          (m) (m) (m) (kg)   (m^3)    (m^2) (-)
1  Fixed  0  0  -20  0  0  0  0
2  Free  10  0  -119  4000  0.5  0.8  1.0
---------------------- LINES ------------------------------------------------
ID   LineType   AttachA   AttachB   UnstrLen   NumSegs   LineOutputs
(#)  (name)     (#)       (#)       (m)        (-)       (-)
1  steel  2  1  100  20  -
---------------------- OPTIONS -----------------------------------------
1000.0                   WtrDpth      - water depth (m)
------------------------- need this line --------------------------------
"""

# A scene with a clump weight and a buoy on a two-section line, made for export
SCENE = """\
name = "points"
[environment]
water_depth = 500.0
[line_types.pipe]
outer_diameter = 0.2032
mass_per_length = 86.8
axial_stiffness = 2.3e9
bending_stiffness = 9.7e6
drag_normal = 1.0
drag_tangential = 0.03
added_mass = 1.0
[line_types.light]
outer_diameter = 0.3
mass_per_length = 80.0
axial_stiffness = 2.3e9
bending_stiffness = 9.7e6
drag_normal = 1.2
drag_tangential = 0.03
added_mass = 1.0
[[segments]]
line_type = "pipe"
length = 400.0
[[segments]]
line_type = "light"
length = 250.0
[[segments]]
line_type = "pipe"
length = 300.0
[seabed]
stiffness = 1.0e5
[ends]
anchor = [0.0, 0.0]
hang_off = [600.0, 480.0]
[[attachments]]
s = 333.3
mass = 8000.0
volume = 1.02
drag_area = 1.7
added_mass_coefficient = 0.95
label = "clump weight"
[[attachments]]
s = 777.7
mass = 1500.0
volume = 6.25
drag_area = 4.2
added_mass_coefficient = 1.05
label = "buoy"
"""

ATT_KEYS = ("mass", "volume", "drag_area", "added_mass_coefficient")


def _write(tmp_path, text, name="deck.dat"):
    path = tmp_path / name
    path.write_text(text)
    return path


def _line_of(text: str, pattern: str) -> int:
    return next(i for i, line in enumerate(text.splitlines(), 1) if re.search(pattern, line))


def _refused(tmp_path, capsys, text, pattern, words):
    """import-moordyn of ``text``: exit 2, one line naming the deck line and ``words``."""
    path = _write(tmp_path, text)
    out = tmp_path / "scene.toml"
    assert main(["import-moordyn", str(path), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("error: "), err
    assert words in err, err
    assert f"deck.dat: line {_line_of(text, pattern)}: " in err, err
    assert not out.exists()
    return err


# ---------------------------------------------------------------------------- import
def test_clump_and_buoy_between_lines_import_as_attachments(tmp_path):
    text, scene, notes = import_deck(_write(tmp_path, DECK))
    a, b = scene.attachments
    # s: the unstretched lengths below each point (line 2 is reversed: 4 -> 2)
    assert (a.s, b.s) == (800.0, 1400.0)
    assert (a.mass, a.volume, a.drag_area, a.added_mass_coefficient) == (5000.5, 0.6375, 1.25, 0.9)
    assert (b.mass, b.volume, b.drag_area, b.added_mass_coefficient) == (200.0, 7.5, 3.5, 1.1)
    assert (a.label, b.label) == ("MoorDyn point 2", "MoorDyn point 4")
    assert [seg.length for seg in scene.segments] == [800.0, 600.0, 600.0]
    # the scene file holds them, with the mapping as a comment, and reads back the same
    assert text.count("\n[[attachments]]\n") == 2
    assert (f"# MoorDyn point 2 (Free, deck line {_line_of(DECK, '^2  Free')}): mass = M, "
            "volume = V, drag_area = CdA, added_mass_coefficient = Ca, at s = 800 m") in text
    assert parse_scene(text).attachments == scene.attachments
    assert any("MoorDyn point 2 at s = 800 m" in n for n in notes)


def test_free_point_without_loads_is_a_plain_joint(tmp_path):
    """A free point with M = V = CdA = Ca = 0 is a hinge joint, as before: no attachment."""
    text = DECK.replace("2  Free  600  0  -600  5000.5  0.6375  1.25  0.9",
                        "2  Free  600  0  -600  0  0  0  0")
    _, scene, _ = import_deck(_write(tmp_path, text))
    assert [a.s for a in scene.attachments] == [1400.0]


def test_free_bottom_end_with_a_clump_is_a_free_anchor(tmp_path):
    text, scene, notes = import_deck(_write(tmp_path, HANGING))
    e = scene.ends
    assert e.free_anchor and scene.seabed is None          # a hanging line clears it
    assert e.anchor == (0.0, 881.0) and e.hang_off == (10.0, 980.0)   # y = Z + 1000
    (a,) = scene.attachments
    assert (a.s, a.mass, a.volume, a.drag_area, a.added_mass_coefficient) == (
        0.0, 4000.0, 0.5, 0.8, 1.0)
    assert '[ends.anchor_joint]\nkind = "free"' in text
    assert any("free end" in n for n in notes)
    # straight below the fixed point: the x-y plane is MoorDyn's X-Z plane, x = 0
    _, scene, _ = import_deck(_write(tmp_path, HANGING.replace("2  Free  10  0", "2  Free  0  0")))
    assert scene.ends.hang_off == (0.0, 980.0)


REFUSED = {
    # name: (deck, the deck line the refusal names (a regex), words it must hold)
    "a point load on a joint": (
        DECK.replace("4  Free  1050  0  -300  200  7.5  3.5  1.1",
                     "4  Free  1050  0  -300  200  7.5  0  0  -5e4  3.5  1.1"),
        r"^4  Free", "steady force FX FY FZ (a point load)"),
    "a mass on a fixed end": (
        DECK.replace("3  Fixed  1500  0  0  0  0  0  0", "3  Fixed  1500  0  0  900  0  0  0"),
        r"^3  Fixed", "on a fixed or coupled end"),
    "a branch: a free end beside two fixed ends": (
        DECK.replace("---------------------- LINES", "5  Free  900  0  -700  10  0  0  0\n"
                     "---------------------- LINES").replace(
            "3  steel  4  3  600  30  -", "3  steel  4  3  600  30  -\n4  steel  4  5  50  5  -"),
        r"^4  Free", "joins 3 line end(s)"),
    "a dangling free end": (
        DECK.replace("---------------------- LINES", "5  Free  900  0  -700  10  0  0  0\n"
                     "6  Free  950  0  -700  10  0  0  0\n---------------------- LINES").replace(
            "3  steel  4  3  600  30  -", "3  steel  4  3  600  30  -\n4  steel  5  6  50  5  -"),
        r"^5  Free", "joins 1 line end(s)"),
    "a free end above its fixed end": (
        HANGING.replace("1  Fixed  0  0  -20", "1  Fixed  0  0  -200"), r"^2  Free",
        "must lie below that fixed end"),
    "a free end reaching the seabed (the scene's rule, at the free point's line)": (
        HANGING.replace("1000.0                   WtrDpth", "115.0 WtrDpth"), r"^2  Free",
        "ends.anchor_joint.kind"),
    "a negative mass (the scene's range, at the point's line)": (
        DECK.replace("200  7.5  3.5  1.1", "-200  7.5  3.5  1.1"), r"^4  Free",
        "attachments[1].mass"),
}


@pytest.mark.parametrize("case", list(REFUSED))
def test_what_a_scene_cannot_hold_is_refused_in_one_line(case, tmp_path, capsys):
    text, pattern, words = REFUSED[case]
    _refused(tmp_path, capsys, text, pattern, words)


# ---------------------------------------------------------------------------- export
def test_export_writes_each_attachment_as_a_free_point():
    scene = parse_scene(SCENE)
    h = 20.0
    ex = export_scene(scene, segment_length=h)
    pts, lines = ex.deck.points, ex.deck.lines
    # sections [0, 400] [400, 650] [650, 950] split at 333.3 and 777.7: five lines
    assert ex.line_span == [(0.0, 333.3), (333.3, 400.0), (400.0, 650.0), (650.0, 777.7),
                            (777.7, 950.0)]
    assert ex.line_segments == [[0], [0], [1], [2], [2]]
    assert [p.attachment for p in pts] == ["Fixed"] + ["Free"] * 4 + ["Fixed"]
    clump, buoy = pts[1], pts[4]
    assert (clump.mass, clump.volume, clump.CdA, clump.Ca) == (8000.0, 1.02, 1.7, 0.95)
    assert (buoy.mass, buoy.volume, buoy.CdA, buoy.Ca) == (1500.0, 6.25, 4.2, 1.05)
    assert all((p.mass, p.volume, p.CdA, p.Ca) == (0.0,) * 4 for p in (pts[0], pts[2], pts[3], pts[5]))
    # without a solved profile the free points start on the chord at their s (MoorDyn
    # X = x, Z = y - WtrDpth); 1e-9 m: s/L x the chord, a division and a product
    for p, s in ((clump, 333.3), (buoy, 777.7)):
        assert (p.x, p.y, p.z) == pytest.approx((600.0 * s / 950.0, 0.0,
                                                 480.0 * s / 950.0 - 500.0), abs=1e-9)
    # each line ends and starts at its point; no segment longer than h
    assert [(ln.attach_a, ln.attach_b) for ln in lines] == [(str(k), str(k + 1)) for k in range(1, 6)]
    for ln, (s0, s1) in zip(lines, ex.line_span):
        assert ln.length == pytest.approx(s1 - s0, abs=1e-12)
        assert ln.segments == math.ceil(ln.length / h - 1e-9) and ln.length / ln.segments <= h
    assert ex.deck.outputs == ["AnchTen1", "FairTen5"]
    # the deck text reads back with the same points (numbers written with repr)
    back = parse_deck(ex.text)
    assert [(p.mass, p.volume, p.CdA, p.Ca) for p in back.points] == \
        [(p.mass, p.volume, p.CdA, p.Ca) for p in pts]
    assert "Attachments are free points" in ex.text


def test_attachment_on_a_section_joint_uses_that_joint():
    """An attachment where two sections meet adds no line: the joint's point holds it."""
    scene = parse_scene(SCENE.replace("s = 333.3", "s = 400.0"))
    ex = export_scene(scene, segment_length=20.0)
    assert [s0 for s0, _ in ex.line_span] == [0.0, 400.0, 650.0, 777.7]
    assert ex.deck.points[1].mass == 8000.0


@pytest.mark.parametrize("s", ["333.3", repr(333.3 + SNAP / 2)])
def test_attachments_at_one_point_are_merged(s):
    """Two attachments at one s (or within SNAP of each other): one point, no line between."""
    ex = export_scene(parse_scene(SCENE.replace("s = 777.7", f"s = {s}")), segment_length=20.0)
    assert len(ex.deck.lines) == 4
    p = ex.deck.points[1]
    assert (p.mass, p.volume, p.CdA) == (9500.0, 1.02 + 6.25, 1.7 + 4.2)
    # the added mass Ca rho V of the two: 1e-15 relative, one division
    assert p.Ca * p.volume == pytest.approx(0.95 * 1.02 + 1.05 * 6.25, rel=1e-15)
    assert "merged into point 2" in ex.text


def test_free_anchor_exports_as_a_free_point(tmp_path):
    _, scene, _ = import_deck(_write(tmp_path, HANGING))
    ex = export_scene(scene, segment_length=10.0)
    first = ex.deck.points[0]
    assert first.attachment == "Free" and (first.mass, first.volume, first.CdA, first.Ca) == (
        4000.0, 0.5, 0.8, 1.0)
    assert ex.deck.options["kbot"][0] == "0"          # no seabed under a hanging line


def test_export_refuses_an_attachment_on_a_fixed_end():
    scene = parse_scene(SCENE.replace("s = 777.7", f"s = {950.0 - SNAP / 2!r}"))
    with pytest.raises(UnsupportedSceneError) as info:
        export_scene(scene)
    msg = str(info.value)
    assert len(msg.splitlines()) == 1 and "of a fixed end" in msg and "'buoy'" in msg


# ------------------------------------------------------------------------ round trip
def _same_line(a, b):
    """Scene b has scene a's section properties along the whole line (segments split at
    the points): 1e-12 relative, the equivalent-diameter arithmetic of the export."""
    assert b.total_length == pytest.approx(a.total_length, abs=1e-9)
    edges = sorted({p.s_start for p in segment_properties(a)} | {a.total_length}
                   | {p.s_start for p in segment_properties(b)})
    for s in (np.array(edges[:-1]) + np.array(edges[1:])) / 2.0:
        pa = next(p for p in segment_properties(a) if p.s_start <= s <= p.s_end)
        pb = next(p for p in segment_properties(b) if p.s_start <= s <= p.s_end)
        for q in ("EA", "EI", "mass", "weight", "drag_normal_coef", "added_mass"):
            assert getattr(pb, q) == pytest.approx(getattr(pa, q), rel=1e-12), (s, q)


def _same_attachments(a, b):
    assert len(a.attachments) == len(b.attachments)
    for x, y in zip(sorted(a.attachments, key=lambda t: t.s),
                    sorted(b.attachments, key=lambda t: t.s)):
        assert abs(x.s - y.s) <= 1e-9                   # a sum of repr-written lengths
        assert [getattr(x, k) for k in ATT_KEYS] == [getattr(y, k) for k in ATT_KEYS]


@pytest.mark.parametrize("edit", [None, ("s = 333.3", "s = 400.0"),
                                  ("s = 333.3", "s = 0.1"), ("s = 777.7", "s = 949.9")])
def test_round_trip_gives_the_same_attachments(edit, tmp_path):
    """Scene -> deck -> scene: the same attachments (s to 1e-9 m, values exactly), on the
    same line; an attachment inside a section, on a section joint, near either end."""
    scene = parse_scene(SCENE.replace(*edit) if edit else SCENE)
    ex = export_scene(scene, segment_length=20.0)
    text, back, _ = import_deck(_write(tmp_path, ex.text))
    _same_attachments(scene, back)
    _same_line(scene, back)
    assert parse_scene(text).attachments == back.attachments


def test_round_trip_of_a_free_anchor(tmp_path):
    _, scene, _ = import_deck(_write(tmp_path, HANGING))
    ex = export_scene(scene, segment_length=10.0)
    _, back, _ = import_deck(_write(tmp_path, ex.text, "back.dat"))
    _same_attachments(scene, back)
    assert back.ends == scene.ends


def test_cli_import_export_import(tmp_path, capsys):
    """import-moordyn, export-moordyn of the scene file it wrote, import-moordyn again: the
    same attachment (a hanging line, one MoorDyn line: no joints to start from a solve)."""
    deck = _write(tmp_path, HANGING, "hanging.dat")
    assert main(["import-moordyn", str(deck)]) == 0
    first = parse_scene((tmp_path / "hanging.toml").read_text())
    again = tmp_path / "again.dat"
    assert main(["export-moordyn", str(tmp_path / "hanging.toml"), "--out", str(again),
                 "--segment-length", "5"]) == 0
    assert main(["import-moordyn", str(again)]) == 0
    _same_attachments(first, parse_scene((tmp_path / "again.toml").read_text()))


# ------------------------------------------------------------------- MoorDyn-C itself
# A suspended chain (no seabed contact) with a 10 t clump half way along it
CLUMP = """\
name = "clump-statics"
[environment]
water_depth = 150.0
[line_types.chain]
outer_diameter = 0.137
mass_per_length = 126.0
axial_stiffness = 5.8e8
bending_stiffness = 1.0e3
drag_normal = 2.4
drag_tangential = 1.15
added_mass = 1.0
[[segments]]
line_type = "chain"
length = 300.0
[ends]
anchor = [0.0, 10.0]
hang_off = [250.0, 145.0]
[[attachments]]
s = 150.0
mass = 10000.0
volume = 1.27
drag_area = 2.0
added_mass_coefficient = 1.0
label = "clump"
"""


def test_moordyn_statics_tension_jumps_by_the_clump_weight(tmp_path):
    """MoorDyn-C's statics of the exported deck: the tension jumps across the clump's
    point by its net weight W = (M - rho V) g along the line.

    T1, T2 are the forces the two lines put on the point (MoorDyn's end-node forces, the
    tension there with the end node's half segment folded in, as the peer reads its end
    tensions). The point's balance T2 t2 - T1 t1 = W e_y projected on the bisector of the
    two tangents gives T2 - T1 = W sin(a) / cos(k/2), a the bisector's angle above the
    horizontal and k the kink (6 deg here: 0.56 % from W sin(a) alone). 1 %: MoorDyn's
    static solution is accepted at the peer's force residual of 1 % of a node's load
    (verification/peers/moordyn/run.py, RESIDUAL_TOL), and so is the point's balance
    here. The point's added mass Ca rho V is read back from MoorDyn's mass matrix."""
    moordyn = pytest.importorskip("moordyn", reason="the optional extra moordyn (MoorDyn-C "
                                  "v2) is not installed: pip install -e '.[moordyn]'")
    from verification.peers.moordyn import run

    scene = parse_scene(CLUMP)
    clump = scene.attachments[0]
    w = clump.net_weight(scene.gravity, scene.water_density)
    # 20 m segments and 12000 s of pseudo-time: converged in about a second (the free
    # point from the chord; the BVP's start is not needed)
    system, lines, files, _, code = run.start(scene, tmp_path, segment_length=20.0,
                                              pseudo_time=12000.0, joints=(None, "the chord"))
    try:
        assert code in (0, None)
        assert run._residual(moordyn, lines, files.scene, files) <= run.RESIDUAL_TOL
        (k,) = [i for i, p in enumerate(files.export.deck.points) if p.mass]
        assert files.export.line_span[k] == (150.0, 300.0)
        f1 = np.array(moordyn.GetLineNodeForce(lines[k - 1], moordyn.GetLineN(lines[k - 1])))
        f2 = np.array(moordyn.GetLineNodeForce(lines[k], 0))
        point = moordyn.GetPoint(system, k + 1)
        assert np.linalg.norm(moordyn.GetPointForce(point)) <= run.RESIDUAL_TOL * w
        t1, t2 = np.linalg.norm(f1), np.linalg.norm(f2)
        u1, u2 = -f1 / t1, f2 / t2                    # the line's direction, up the line
        bis = (u1 + u2) / np.linalg.norm(u1 + u2)
        a = math.atan2(bis[2], math.hypot(bis[0], bis[1]))
        half_kink = 0.5 * math.acos(min(1.0, float(u1 @ u2)))
        assert t2 - t1 == pytest.approx(w * math.sin(a) / math.cos(half_kink), rel=0.01)
        # out of the plane (MoorDyn's Y) the point's mass is M + Ca rho V and the two end
        # nodes' (m + Ca_line rho A) l / 2 (MoorDyn's lumped masses); 1e-9: arithmetic
        lt = files.export.deck.line_types["chain"]
        node = sum((lt.mass + lt.Ca * scene.water_density * math.pi / 4 * lt.diameter ** 2)
                   * ln.length / ln.segments / 2.0 for ln in files.export.deck.lines[k - 1:k + 1])
        expect = clump.mass + clump.added_mass(scene.water_density) + node
        assert moordyn.GetPointM(point)[1][1] == pytest.approx(expect, rel=1e-9)
    finally:
        run.close(system, tmp_path)

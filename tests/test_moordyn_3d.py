"""MoorDyn decks and the MoorDyn peer on 3D scenes (issue "Both methods in 3D").

Import and export need no moordyn package: a current that turns with depth imports as
``headings_deg`` (the headings worked out by hand from the rows below), a deck whose ends
lie along any horizontal direction imports, and a 3D scene (hang-off out of the anchor's
plane, a turning current) exports with its points and velocity components mapped by the
documented convention (MoorDyn (X, Y, Z) = (x, -z, y - WtrDpth)) and imports back to the
same line and current, turned by the plane's heading (the importer puts the ends in the
x-y plane), to input precision (1e-12).

The peer tests need the optional extra [moordyn] and are skipped with that reason without
it: MoorDyn on a taut line under a cross current against the closed form of a taut string,
and on a small 3D line (hang-off out of plane, a current turning with depth) against the
VFIFE's 3D solution.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from riser.io.moordyn.deck import parse_deck
from riser.io.moordyn.deck_from_scene import export_scene
from riser.io.moordyn.scene_from_deck import import_deck
from riser.io.scene_file import load_scene, parse_scene
from riser.model.sections import segment_properties
from verification.catalog import resolve
from verification.cli import main

from extras import needs_moordyn

RTOL = 1e-12        # repr-exact numbers: only the trigonometry and the sqrt round

#: the scr-steel deck: point 1 at (0, 0, -1000), point 2 at (1500, 0, 0), depth 1000 m
GOOD = export_scene(resolve("scr-steel"), segment_length=100.0).text
CURRENTS = GOOD.replace("0                        writeLog", "0 writeLog\n1 Currents")
HEADER = "--- current profile ---\nz ux uy uz\n(m) (m/s) (m/s) (m/s)\n"


def _import(tmp_path, deck: str, rows: str):
    (tmp_path / "deck.dat").write_text(deck)
    (tmp_path / "current_profile.txt").write_text(HEADER + rows)
    text, scene, notes = import_deck(tmp_path / "deck.dat")
    assert parse_scene(text).current == scene.current         # the file reads back
    return scene, notes


def _turned(deck: str, deg: float) -> str:
    """The deck with its points turned by ``deg`` about MoorDyn's Z."""
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    out, section = [], ""
    for line in deck.splitlines():
        if line.startswith("---"):
            section = line
        tok = line.split()
        if "POINTS" in section and tok and tok[0].isdigit():
            x, y = float(tok[2]), float(tok[3])
            tok[2], tok[3] = repr(c * x - s * y), repr(s * x + c * y)
            line = "  ".join(tok)
        out.append(line)
    return "\n".join(out) + "\n"


# ------------------------------------------------------------------------ import
def test_turning_current_imports_with_its_headings(tmp_path):
    """Ends along +X: the scene's x is X and its z is x cross y = X cross Z = -Y, so a row
    (ux, uy) is (ux, -uy) in the scene: (0.5, 0) -> 0.5 m/s at 0 deg; (0.3, 0.3) -> 0.3
    sqrt(2) at -45 deg; (0, -1) -> 1 m/s at 90 deg. Heights y = Z + 1000."""
    rows = "-1000 0.5 0 0\n-500 0.3 0.3 0\n0 0 -1.0 0\n"
    scene, notes = _import(tmp_path, CURRENTS, rows)
    cur = scene.current
    assert cur.turns and cur.heading_deg == 0.0
    assert cur.heights == (0.0, 500.0, 1000.0)
    np.testing.assert_allclose(cur.headings_deg, [0.0, -45.0, 90.0], rtol=0, atol=1e-12)
    np.testing.assert_allclose(cur.speeds, [0.5, 0.3 * math.sqrt(2.0), 1.0], rtol=RTOL)
    assert not scene.is_planar
    assert any("turns with depth, headings -45 to 90 deg" in n for n in notes)
    # the same deck turned by 90 deg about Z (ends along +Y): x is Y, z = Y cross Z = X,
    # so (ux, uy) is (uy, ux): (0, 0.5) at 90 deg, (0.3, 0.3) at 45, (-1, 0) at 180
    turned, _ = _import(tmp_path, _turned(CURRENTS, 90.0), rows)
    np.testing.assert_allclose(turned.current.headings_deg, [90.0, 45.0, 180.0], rtol=0,
                               atol=1e-12)
    np.testing.assert_allclose(turned.current.speeds, cur.speeds, rtol=RTOL)
    assert turned.ends.anchor == pytest.approx((0.0, 0.0), abs=1e-9)
    assert turned.ends.hang_off == pytest.approx((1500.0, 1000.0), rel=RTOL)


def test_one_direction_keeps_heading_and_signed_speeds(tmp_path):
    """A profile along one line (reversing with depth) is not a turning one: heading_deg
    of its largest row and speeds signed along it, as before 3D scenes. Rows (0.3, 0.4)
    and (-0.6, -0.8) are (0.3, -0.4) and (-0.6, 0.8) in the scene: heading atan2(0.8,
    -0.6) = 126.87 deg, speeds -0.5 and 1.0."""
    scene, _ = _import(tmp_path, CURRENTS, "-1000 0.3 0.4 0\n0 -0.6 -0.8 0\n")
    cur = scene.current
    assert not cur.turns
    assert cur.heading_deg == pytest.approx(math.degrees(math.atan2(0.8, -0.6)), rel=RTOL)
    np.testing.assert_allclose(cur.speeds, [-0.5, 1.0], rtol=RTOL)


def test_a_row_without_current_takes_its_neighbours_heading(tmp_path):
    """A still row has no direction: it takes the nearest row's (below first), so no turn
    is invented; its velocity stays 0."""
    scene, _ = _import(tmp_path, CURRENTS, "-1000 0 0 0\n-500 0.5 0 0\n0 0 0.5 0\n")
    cur = scene.current
    np.testing.assert_allclose(cur.headings_deg, [0.0, 0.0, -90.0], atol=1e-12)
    np.testing.assert_allclose(cur.speeds, [0.0, 0.5, 0.5], rtol=RTOL)


@pytest.mark.parametrize("deg", [-60.0, 90.0, 135.0, 180.0, 225.0])
def test_ends_along_any_heading_import(deg, tmp_path):
    """Nothing refuses a deck because its ends are not along MoorDyn's X: turned about Z,
    the deck imports to the same ends (the line's plane is the scene's x-y plane)."""
    (tmp_path / "deck.dat").write_text(_turned(GOOD, deg))
    _, scene, _ = import_deck(tmp_path / "deck.dat")
    assert scene.ends.anchor == pytest.approx((0.0, 0.0), abs=1e-9)
    assert scene.ends.hang_off == pytest.approx((1500.0, 1000.0), rel=RTOL)
    assert scene.is_planar


# ------------------------------------------------------------------------ export
#: a 3D scene: two sections (a free point between two MoorDyn lines), the hang-off 60 m
#: out of the anchor's plane (the line's plane at atan2(60, 80) = 36.87 deg), a current
#: turning from 10 to 120 deg with height
SCENE_3D = """
name = "three-d"
[environment]
gravity = 9.81
water_density = 1025.0
water_depth = 100.0
[environment.current]
heights = [0.0, 40.0, 100.0]
speeds = [0.2, 0.5, 0.4]
headings_deg = [10.0, 60.0, 120.0]
[seabed]
stiffness = 1.0e5
[line_types.p]
outer_diameter = 0.1
inner_diameter = 0.05
mass_per_length = 20.0
axial_stiffness = 1.0e7
bending_stiffness = 1.0e3
added_mass = 1.0
drag_normal = 1.0
[[segments]]
line_type = "p"
length = 60.0
[[segments]]
line_type = "p"
length = 90.0
buoyancy = 50.0
[ends]
anchor = [10.0, 0.0, 5.0]
hang_off = [90.0, 80.0, 65.0]
"""


def test_3d_export_maps_points_and_velocity(tmp_path):
    """The deck's points are (x, -z, y - 100) of the scene's ends and of the joint on the
    chord (60 m of 150 m along it); current_profile.txt holds, at Z = y - 100, the
    velocity (v cos h, -v sin h, 0) of each height."""
    scene = parse_scene(SCENE_3D)
    ex = export_scene(scene, segment_length=5.0)
    pts = [(p.x, p.y, p.z) for p in ex.deck.points]
    f = 60.0 / 150.0
    expect = [(10.0, -5.0, -100.0), (10.0 + 80.0 * f, -(5.0 + 60.0 * f), 80.0 * f - 100.0),
              (90.0, -65.0, -20.0)]
    np.testing.assert_allclose(pts, expect, rtol=RTOL, atol=1e-12)
    assert [p.attachment for p in ex.deck.points] == ["Fixed", "Free", "Fixed"]
    rows = np.array([[float(v) for v in r.split()]
                     for r in ex.current_profile.splitlines()[3:]])
    h = np.radians([10.0, 60.0, 120.0])
    v = np.array([0.2, 0.5, 0.4])
    np.testing.assert_allclose(rows, np.stack([[-100.0, -60.0, 0.0], v * np.cos(h),
                                               -v * np.sin(h), [0.0] * 3], axis=1),
                               rtol=RTOL, atol=1e-15)
    assert parse_deck(ex.text).options["currents"][0] == "1"


def test_3d_round_trip(tmp_path):
    """Export then import: the same line (section properties per metre, lengths), the ends
    turned into the x-y plane (anchor (0, 0), hang-off (hypot(80, 60), 80) = (100, 80)),
    and the same current velocity at every height, turned by the plane's heading psi =
    atan2(60, 80): (ux cos psi + uz sin psi, -ux sin psi + uz cos psi)."""
    scene = parse_scene(SCENE_3D)
    assert not scene.is_planar
    ex = export_scene(scene, segment_length=5.0)
    (tmp_path / "deck.dat").write_text(ex.text)
    (tmp_path / "current_profile.txt").write_text(ex.current_profile)
    text, back, _ = import_deck(tmp_path / "deck.dat")
    assert parse_scene(text).current == back.current
    assert back.ends.anchor == pytest.approx((0.0, 0.0), abs=1e-12)
    assert back.ends.hang_off == pytest.approx((100.0, 80.0), rel=RTOL)
    assert back.total_length == pytest.approx(150.0, rel=RTOL)
    for pa, pb in zip(segment_properties(scene), segment_properties(back)):
        assert (pb.s_start, pb.s_end) == pytest.approx((pa.s_start, pa.s_end), rel=RTOL)
        for q in ("EA", "EI", "mass", "weight", "drag_normal_coef", "drag_tangential_coef",
                  "added_mass"):
            assert getattr(pb, q) == pytest.approx(getattr(pa, q), rel=RTOL, abs=1e-9), q
    assert back.seabed.stiffness == pytest.approx(scene.seabed.stiffness, rel=RTOL)
    psi = math.atan2(60.0, 80.0)
    np.testing.assert_allclose(back.current.headings_deg,
                               np.array([10.0, 60.0, 120.0]) - math.degrees(psi), atol=1e-12)
    y = np.linspace(-10.0, 110.0, 61)
    ux, uz = scene.current.velocity(y)
    bx, bz = back.current.velocity(y)
    np.testing.assert_allclose(bx, ux * math.cos(psi) + uz * math.sin(psi), atol=1e-12)
    np.testing.assert_allclose(bz, -ux * math.sin(psi) + uz * math.cos(psi), atol=1e-12)


def test_3d_cli_round_trip(tmp_path, capsys):
    """export-moordyn then import-moordyn of a 3D scene file (one line: no joint to
    start) from the command line."""
    one = SCENE_3D.replace("length = 60.0\n[[segments]]\nline_type = \"p\"\nlength = 90.0\n"
                           "buoyancy = 50.0", "length = 150.0")
    (tmp_path / "three-d.toml").write_text(one)
    deck = tmp_path / "deck" / "three-d.dat"
    assert main(["export-moordyn", str(tmp_path / "three-d.toml"), "--out", str(deck),
                 "--segment-length", "5"]) == 0
    assert (deck.parent / "current_profile.txt").exists()
    assert main(["import-moordyn", str(deck)]) == 0
    back = load_scene(deck.with_suffix(".toml"))
    assert back.current.turns and back.ends.hang_off == pytest.approx((100.0, 80.0))
    capsys.readouterr()


# ------------------------------------------------------------------------ the peer
def _taut_scene(L0: float, U: float) -> str:
    """A neutrally buoyant line between ends 100 m apart at one height, 60 m out of the
    anchor's plane, under a uniform current normal to the line's plane."""
    psi = math.degrees(math.atan2(60.0, 80.0))
    return f"""
name = "taut-cross"
[environment]
water_depth = 100.0
[environment.current]
heights = [0.0, 100.0]
speeds = [{U!r}, {U!r}]
heading_deg = {psi + 90.0!r}
[line_types.p]
outer_diameter = 0.1
mass_per_length = 20.0
axial_stiffness = 1.0e7
bending_stiffness = 10.0
drag_normal = 1.0
drag_tangential = 0.0
added_mass = 1.0
[[segments]]
line_type = "p"
length = {L0!r}
submerged_weight = 0.0
[ends]
anchor = [0.0, 50.0, 0.0]
hang_off = [80.0, 50.0, 60.0]
"""


@needs_moordyn
def test_taut_line_in_a_cross_current_against_the_closed_form(tmp_path):
    """The closed form of a taut string under a uniform normal load q = rho Cd D U^2 / 2:
    a parabola of sag d = q L^2 / (8 H), H = EA (arc / L0 - 1), arc = L (1 + 8/3 (d/L)^2),
    end tension sqrt(H^2 + (q L/2)^2), curvature q / H towards the chord (the out-of-plane
    moment -EI q / H at mid-span: the line curves towards -e_n). Measured at 5 m
    segments: sag -0.11 %, end tension -0.076 %, moment -0.14 %. Tolerances: 1 % on the
    sag and the moment (MoorDyn stops at a force residual up to 1 % of a node's load;
    the closed form leaves out the drag's cos^2 of the slope 4 d/L = 0.03, 0.09 %); 0.3 %
    on the tension (the sag's stretch is 7 % of it)."""
    from verification.peers.moordyn.run import run
    L0, U, L, EA, EI = 99.8, 0.5, 100.0, 1.0e7, 10.0
    scene = parse_scene(_taut_scene(L0, U))
    q = 0.5 * 1025.0 * 1.0 * 0.1 * U * U
    d = 1.0
    for _ in range(100):                      # fixed point: converges in a few steps
        H = EA * (L * (1.0 + 8.0 / 3.0 * (d / L) ** 2) / L0 - 1.0)
        d = q * L * L / (8.0 * H)
    peer = run(scene, tmp_path, segment_length=5.0)
    assert peer.converged, peer.message
    p = peer.profile
    assert p.is_3d and p.moment_out_of_plane is not None
    assert np.ptp(p.y) < 1e-6                           # weightless: stays at y = 50
    mid = np.isclose(p.s, L0 / 2)                       # node 10 of 20
    assert mid.sum() == 1
    assert p.lateral[mid][0] == pytest.approx(d, rel=1e-2)          # towards the current
    assert p.tension[-1] == pytest.approx(math.hypot(H, q * L / 2), rel=3e-3)
    assert p.moment_out_of_plane[mid][0] == pytest.approx(-EI * q / H, rel=1e-2)
    # the positions are in the scene's frame: the ends where the scene has them
    assert (p.x[-1], p.y[-1], p.z[-1]) == pytest.approx((80.0, 50.0, 60.0), abs=1e-6)


#: a small 3D line for the peer against the VFIFE: 120 m, the hang-off 20 m out of the
#: anchor's plane, a current turning from +x to +z with height (seconds for both)
SMALL_3D = """
name = "small-3d"
[environment]
gravity = 9.81
water_density = 1025.0
water_depth = 100.0
[environment.current]
heights = [0.0, 50.0, 100.0]
speeds = [0.3, 0.6, 0.8]
headings_deg = [0.0, 45.0, 90.0]
[line_types.p]
outer_diameter = 0.1
inner_diameter = 0.05
mass_per_length = 20.0
axial_stiffness = 1.0e7
bending_stiffness = 1.0e3
added_mass = 1.0
drag_normal = 1.0
[[segments]]
line_type = "p"
length = 120.0
[ends]
anchor = [0.0, 10.0]
hang_off = [80.0, 90.0, 20.0]
"""


@needs_moordyn
def test_peer_on_a_3d_line_against_the_vfife(tmp_path):
    """MoorDyn (5 m segments) against the VFIFE's 3D solution (1 m elements): hang-off
    tension (the end-node force) within 0.3 % and the lateral offset along the line
    within 1 % of its largest value (0.96 m). Measured: -0.052 % and 0.43 mm (0.045 %).
    Margins: MoorDyn stops at a force residual up to 1 % of a node's load, and its 5 m
    lumping moves the nodes by less than that (the VFIFE's own error is far smaller)."""
    import vfife
    from verification.peers.moordyn.run import run
    scene = parse_scene(SMALL_3D)
    v = vfife.solve(scene)
    assert v.converged, v.message
    peer = run(scene, tmp_path, segment_length=5.0)
    assert peer.converged, peer.message
    p, vp = peer.profile, v.profile
    assert p.tension[-1] == pytest.approx(vp.tension[-1], rel=3e-3)
    big = float(np.max(np.abs(vp.lateral)))
    assert big > 0.5                                     # the current moves it sideways
    diff = p.lateral - np.interp(p.s, vp.s, vp.lateral)
    assert np.max(np.abs(diff)) < 1e-2 * big
    # the frame: the ends on the scene's points, lateral 0 there
    assert (p.x[-1], p.y[-1], p.z[-1]) == pytest.approx((80.0, 90.0, 20.0), abs=1e-6)
    assert p.lateral[0] == pytest.approx(0.0, abs=1e-9)
    assert p.lateral[-1] == pytest.approx(0.0, abs=1e-6)


@needs_moordyn
def test_compare_peer_on_a_3d_scene(tmp_path, capsys):
    """compare --peer moordyn on a 3D scene: MoorDyn's rows include the lateral offset
    along the line, its profile.csv carries the 3D columns, nothing is refused."""
    import pandas as pd
    path = tmp_path / "small-3d.toml"
    path.write_text(SMALL_3D)
    out = tmp_path / "o"
    rc = main(["compare", str(path), "--peer", "moordyn", "--peer-segment-length", "5",
               "--out", str(out), "--no-paper-model"])
    cap = capsys.readouterr()
    text = cap.out
    assert rc in (0, 1) and "unexpected" not in cap.err, cap.err    # 1: the verdict's
    assert "moordyn: converged" in text
    rows = pd.read_csv(out / "moordyn" / "agreement.csv")
    assert {"lateral", "max_lateral_offset", "hang_off_tension"} <= set(rows.quantity)
    by = rows.set_index("quantity")
    assert abs(by.loc["hang_off_tension", "rel_diff"]) < 3e-3
    assert abs(by.loc["lateral", "diff"]) < 1e-2
    prof = pd.read_csv(out / "moordyn" / "profile.csv")
    assert {"lateral", "moment_in_plane", "moment_out_of_plane"} <= set(prof.columns)

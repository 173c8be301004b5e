"""MoorDyn as a peer (issue 17, items 3 and 4): ``compare --peer moordyn``.

Needs the optional package ``moordyn`` (``pip install -e '.[moordyn]'``; CI installs it);
every test but the first is skipped with that reason without it. The scene is the
built-in steel catenary riser at 20 m MoorDyn segments (100 segments: seconds a run; a
short stiff line converges far more slowly in MoorDyn's static solver, see docs/moordyn.md). The reference is the BVP on the same scene; the tolerances are MoorDyn's own
(verification/peers/moordyn/column.py) or tighter where the test says why.
"""

from __future__ import annotations

import sys

import numpy as np
import pytest

from riser.io.scene_file import parse_scene
from verification.catalog import builtin_paths
from verification.cli import main
from verification.pipeline import solve_scene

SMALL = builtin_paths()["scr-steel"].read_text()     # 2000 m in 1000 m of water
H = 20.0            # MoorDyn segment length [m]: 100 segments, seconds a run
BUDGET = 60.0       # s of wall time for MoorDyn's static solver


def test_missing_moordyn_is_one_line_before_solving(tmp_path, capsys, monkeypatch):
    """Without the package: exit 2 and the install command, before any solve."""
    monkeypatch.setitem(sys.modules, "moordyn", None)     # import moordyn -> ImportError
    path = tmp_path / "small.toml"
    path.write_text(SMALL)
    assert main(["compare", str(path), "--peer", "moordyn", "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "pip install -e '.[moordyn]'" in err[0]
    assert not (tmp_path / "o" / "agreement.csv").exists()
    assert main(["bench", "--peer", "moordyn", "--out", str(tmp_path / "b")]) == 2


moordyn = pytest.importorskip("moordyn", reason="the optional extra [moordyn] is not installed")

from verification.peers.moordyn.run import RESIDUAL_TOL, run  # noqa: E402


@pytest.fixture(scope="module")
def small():
    scene = parse_scene(SMALL)
    return scene, solve_scene(scene, "bvp")


def test_static_state_against_the_bvp(small, tmp_path):
    """MoorDyn's statics of the exported deck against the BVP of the scene: the end-node
    force is the hang-off tension T(L) (0.1 %; w h/2 of a 20 m segment is 0.6 % of T:
    the lumped-mass end node carries it); the end-segment tension is lower by about that
    half segment's weight; the configuration within 0.5 % of depth."""
    scene, b = small
    peer = run(scene, tmp_path, segment_length=H, budget=BUDGET)
    assert peer.converged, peer.message
    assert peer.info["force_residual"] <= RESIDUAL_TOL
    T_L = b.profile.tension[-1]
    info = peer.info
    assert info["hang_off_end_node_force"] == pytest.approx(T_L, rel=1e-3)
    half = 525.7 * H / 2 * np.sin(b.profile.theta[-1])        # N: w h/2 sin(theta)
    gap = info["hang_off_end_node_force"] - info["hang_off_end_segment_tension"]
    assert gap == pytest.approx(half, rel=0.2)
    p = peer.profile
    assert p.s[0] == pytest.approx(0.0) and p.s[-1] == pytest.approx(2000.0)
    assert len(p.s) == 101
    y_bvp = np.interp(p.s, b.profile.s, b.profile.y)
    assert np.max(np.abs(p.y - y_bvp)) < 5e-3 * 1000.0
    # moment = EI x curvature, 0 at the pinned ends
    EI = scene.line_types["steel"].bending_stiffness
    np.testing.assert_allclose(p.moment, EI * p.curvature, rtol=1e-12)
    assert p.moment[0] == p.moment[-1] == 0.0
    # the deck and MoorDyn's log are kept, nothing printed by MoorDyn reached the terminal
    assert (tmp_path / "deck.dat").exists() and (tmp_path / "moordyn.log").exists()


def test_current_is_settled_by_time_stepping(small, tmp_path):
    """MoorDyn's static solver ignores the current; the peer time-steps with it on until
    the line stops, and the result meets the BVP with the same current (the hang-off
    tension to 0.3 %; without the current it differs by more than that)."""
    scene, _ = small
    cur = parse_scene(SMALL.replace("water_depth = 1000.0", "water_depth = 1000.0\n"
                                    "[environment.current]\nheights = [0.0, 1000.0]\n"
                                    "speeds = [0.3, 1.0]"))
    b = solve_scene(cur, "bvp")
    peer = run(cur, tmp_path, segment_length=H, budget=BUDGET)
    assert peer.converged, peer.message
    assert peer.info["settle_sim_s"] > 0 and peer.info["settle_wall_s"] > 0
    T_cur, T_still = b.profile.tension[-1], solve_scene(scene, "bvp").profile.tension[-1]
    assert abs(T_cur - T_still) > 3e-3 * T_cur                 # the current matters here
    assert peer.info["hang_off_end_node_force"] == pytest.approx(T_cur, rel=3e-3)
    x_bvp = np.interp(peer.profile.s, b.profile.s, b.profile.x)
    assert np.max(np.abs(peer.profile.x - x_bvp)) < 5e-3 * 1000.0


def test_joint_between_lines_is_a_hinge(tmp_path):
    """Two sections: two MoorDyn lines joined by a free point, whose curvature is 0 (the
    report names the BVP moment there)."""
    two = parse_scene(SMALL.replace('length = 2000.0', 'length = 1200.0\n\n[[segments]]\n'
                                    'line_type = "steel"\nlength = 800.0\nbuoyancy = 100.0'))
    peer = run(two, tmp_path, segment_length=H, budget=BUDGET)
    assert peer.converged, peer.message
    j = int(np.argmin(np.abs(peer.profile.s - 1200.0)))
    assert peer.profile.s[j] == pytest.approx(1200.0) and peer.profile.curvature[j] == 0.0
    assert peer.profile.curvature[j - 1] > 0.0 and peer.profile.curvature[j + 1] > 0.0


def test_compare_peer_cli(tmp_path, capsys):
    """compare --peer moordyn: the peer's files and the two agreement.csv columns."""
    import pandas as pd
    path = tmp_path / "small.toml"
    path.write_text(SMALL)
    out = tmp_path / "o"
    rc = main(["compare", str(path), "--peer", "moordyn", "--peer-segment-length", "20",
               "--out", str(out), "--no-paper-model"])
    text = capsys.readouterr().out
    assert rc == 0, text
    assert "moordyn: converged" in text
    df = pd.read_csv(out / "agreement.csv")
    assert list(df.columns[-2:]) == ["moordyn", "moordyn_rel_diff"]
    peer = pd.read_csv(out / "moordyn" / "agreement.csv")
    assert {"configuration", "tension", "moment", "hang_off_tension",
            "hang_off_segment_tension"} <= set(peer.quantity)
    assert (out / "moordyn" / "profile.csv").exists()
    assert "MoorDyn (peer column)" in (out / "report.md").read_text()

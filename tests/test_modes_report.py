"""The cross-method modal report (verification/comparison/modes.py): its files and the agreement of
the two methods' modes."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from riser.io.scene_file import scene_from_dict
from riser.results.modes import COUPLED, PLANES, ModalResult, Mode, out_of_plane_share
from riser.results.result import Status
from verification.catalog import resolve
from verification.comparison import modes as vm

try:                                   # the BVP's modal analysis (written in parallel)
    import bvp.modal.modes  # noqa: F401
    HAVE_BVP_MODES = True
except ImportError:                    # pragma: no cover - until bvp/modal/modes.py exists
    HAVE_BVP_MODES = False
needs_bvp = pytest.mark.skipif(not HAVE_BVP_MODES, reason="bvp.modal.modes is not importable yet")


def small_scene():
    """120 m of line, 40 m of it on an elastic seabed, 4 m elements: seconds to analyse."""
    return scene_from_dict({
        "name": "small",
        "line_types": {"p": {"outer_diameter": 0.2, "inner_diameter": 0.15,
                             "mass_per_length": 60.0, "axial_stiffness": 5e8,
                             "bending_stiffness": 2e5, "added_mass": 1.0}},
        "seabed": {"stiffness": 1e5},
        "segments": [{"line_type": "p", "length": 120.0, "submerged_weight": 300.0}],
        "ends": {"anchor": [0.0, 0.0], "hang_off": [90.0, 50.0]},
        "vfife": {"element_length": 4.0}}, "test")


def read_csv(path):
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    return rows[0], rows[1:]


def fake(method, freqs, flip=False):
    """A ModalResult with sine shapes of the given frequencies (one plane each)."""
    s = np.linspace(0.0, 100.0, 51 if method == "bvp" else 26)
    modes = []
    for plane in PLANES:
        for j, f in enumerate(freqs, start=1):
            shape = np.zeros((len(s), 3))
            shape[:, 1 if plane == "in_plane" else 2] = np.sin(j * np.pi * s / 100.0)
            modes.append(Mode(plane, j, f, s, -shape if flip else shape))
    return ModalResult(method, "fake", Status.CONVERGED, "ok", modes)


def test_pairing_frequency_difference_and_mac():
    rows = vm.pair_rows(fake("bvp", [0.1, 0.2]), fake("vfife", [0.1002, 0.21], flip=True))
    assert [(r["plane"], r["mode"]) for r in rows] == [
        ("in_plane", 1), ("in_plane", 2), ("out_of_plane", 1), ("out_of_plane", 2)]
    assert rows[0]["rel_diff"] == pytest.approx(0.002)
    # the same sine on another grid: MAC 1 whatever the sign (linear interpolation of a
    # 2-node-per-4-m sine: 1 - MAC ~ (h k)^4 ~ 1e-6)
    assert rows[0]["mac"] == pytest.approx(1.0, abs=1e-5)
    assert rows[0].passed and not rows[1].passed              # 5 % is outside 0.5 %


@needs_bvp
def test_run_modes_writes_the_files(tmp_path):
    run = vm.run_modes(small_scene(), 3, out=tmp_path)
    assert all(r.converged for r in run.results.values()), \
        [r.message for r in run.results.values()]
    header, rows = read_csv(tmp_path / "modes.csv")
    assert header == ["method", "plane", "mode", "frequency_hz", "period_s"]
    assert len(rows) == 2 * 2 * 3
    assert {r[0] for r in rows} == {"bvp", "vfife"} and {r[1] for r in rows} == set(PLANES)
    for r in rows:
        assert float(r[4]) == pytest.approx(1.0 / float(r[3]), rel=1e-9)
    header, rows = read_csv(tmp_path / "agreement.csv")
    assert header == ["plane", "mode", "bvp_frequency_hz", "vfife_frequency_hz", "rel_diff",
                      "mac"]
    assert len(rows) == 2 * 3
    # a planar static state: the two planes' shape plots, not the coupled family's
    planar = [f for f in vm.FILES if f != "mode_shapes_coupled.png"]
    for f in planar:
        assert (tmp_path / f).is_file() and (tmp_path / f).stat().st_size > 0, f
    assert run.files == planar and not (tmp_path / "mode_shapes_coupled.png").exists()
    text = (tmp_path / "report.md").read_text()
    assert "0.5 %" in text and "MAC >= 0.99" in text and "Out-of-plane" in text
    lines = vm.summary_lines(run)
    assert lines[0].startswith("small") and any("pairs within 0.5 %" in x for x in lines)


def test_coupled_modes_are_paired_by_number_and_written_as_one_family(tmp_path):
    # what the files say of a coupled family (a 3D static state), from two made-up results
    # (no solve): the pairs by number, plane "coupled" in both CSV files, one plot, the
    # BVP's shares in the report; a pair whose shapes differ (mode 2: x against z) fails
    # on its MAC whatever its frequency
    s = np.linspace(0.0, 100.0, 51)
    hump = np.sin(np.pi * s / 100.0)

    def mode(k, f, comp):
        shape = np.zeros((s.size, 3))
        shape[:, comp] = hump
        return Mode(COUPLED, k, f, s, shape)

    def result(name, f2, comp2):
        modes = [mode(1, 0.1, 2), mode(2, f2, comp2)]
        return ModalResult(name, "made-up", Status.CONVERGED, "ok", modes,
                           info={"out_of_plane_share": [out_of_plane_share(m) for m in modes]})

    bvp, vf = result("bvp", 0.2, 0), result("vfife", 0.2004, 2)
    run = vm.ModesRun("made-up", {"bvp": bvp, "vfife": vf}, vm.pair_rows(bvp, vf))
    vm.write(run, tmp_path)
    assert [(r["plane"], r["mode"], r.passed) for r in run.rows] == [
        ("coupled", 1, True), ("coupled", 2, False)]
    assert run.rows[1]["mac"] < 1e-12 and abs(run.rows[1].rel_diff - 0.002) < 1e-12
    _, rows = read_csv(tmp_path / "agreement.csv")
    assert [(r[0], r[1]) for r in rows] == [("coupled", "1"), ("coupled", "2")]
    _, rows = read_csv(tmp_path / "modes.csv")
    assert {r[1] for r in rows} == {"coupled"} and len(rows) == 4
    assert run.files == ["modes.csv", "agreement.csv", "report.md", "mode_shapes_coupled.png"]
    text = (tmp_path / "report.md").read_text()
    assert "## Coupled (x, y, z) about the 3D static state" in text
    assert "| 1 | 1.000 | 0.1 |" in text and "| 2 | 0.000 | 0.2 |" in text   # the shares


@needs_bvp
@pytest.mark.slow
def test_a_3d_static_state_is_one_coupled_family_in_the_files(tmp_path):
    # the small scene in a 1 m/s current across its plane (a 3D static state): 2 x 1
    # coupled modes a method, in the CSV files as plane "coupled", the coupled plot
    # instead of the two planes', the shares in the report. The ANCF agrees with the BVP
    # within the target (measured 0.011 %, MAC 1.0000); the VFIFE's lumped seabed springs
    # resolve this short heavy line's touchdown node by node (O(h), not monotone: its
    # worst pair +1.7 % at 4 m, 0.2 % at 2 m, 0.5 % at 1 m; in plane, heading 0, -1.5 %,
    # -1.0 %, +0.6 %), so its rows are not judged here: the built-in 3D scenes judge them
    # (tests/test_vfife_modes_3d.py, reports/modes/)
    data = {"name": "small-3d", "line_types": {"p": {
        "outer_diameter": 0.2, "inner_diameter": 0.15, "mass_per_length": 60.0,
        "axial_stiffness": 5e8, "bending_stiffness": 2e5, "added_mass": 1.0,
        "drag_normal": 1.0}},
        "environment": {"current": {"heights": [0.0, 50.0], "speeds": [1.0, 1.0],
                                    "heading_deg": 90.0}},
        "seabed": {"stiffness": 1e5},
        "segments": [{"line_type": "p", "length": 120.0, "submerged_weight": 300.0}],
        "ends": {"anchor": [0.0, 0.0], "hang_off": [90.0, 50.0]},
        "vfife": {"element_length": 4.0}}
    run = vm.run_modes(scene_from_dict(data, "test"), 1, out=tmp_path, columns=vm.COLUMNS)
    assert all(r.converged for r in run.results.values()), vm.summary_lines(run)
    assert len(run.columns["ancf"]) == 2 and all(r.passed for r in run.columns["ancf"])
    _, rows = read_csv(tmp_path / "modes.csv")
    assert len(rows) == 3 * 2 and {r[1] for r in rows} == {"coupled"}
    _, rows = read_csv(tmp_path / "agreement.csv")
    assert [(r[0], r[1]) for r in rows] == [("coupled", "1"), ("coupled", "2")]
    assert run.files == ["modes.csv", "agreement.csv", "report.md", "mode_shapes_coupled.png"]
    text = (tmp_path / "report.md").read_text()
    assert "## Coupled (x, y, z) about the 3D static state" in text and "out-of-plane share" in text
    shares = run.results["bvp"].info["out_of_plane_share"]
    assert any(0.01 < x < 0.99 for x in shares), shares        # the current couples them


@needs_bvp
def test_scr_steel_methods_agree(tmp_path):
    """Both methods on scr-steel with 5 m VFIFE elements (and the BVP at its default):
    within the target, 0.5 % and MAC 0.99. Measured: out of plane -0.002 to -0.03 % (the
    VFIFE's O(h^2) discretisation, growing with n^2); in plane +0.11 to +0.2 % (the lumped
    seabed springs resolve the touchdown to one element: O(h), -0.02 % at 1 m); MAC >=
    0.999."""
    sc = resolve("scr-steel")
    sc = sc.replace(vfife=sc.vfife.replace(element_length=5.0))
    run = vm.run_modes(sc, 10, out=None)
    assert len(run.rows) == 20
    bad = [r for r in run.rows if not r.passed]
    assert not bad, bad
    assert run.all_meet and run.files == []


def test_modes_command_refuses_a_bad_count(run_cli, tmp_path):
    # the option is checked before any solving, and named in the one-line error
    code, _, err = run_cli(["modes", "scr-steel", "--count", "0", "--out", str(tmp_path)])
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "command line: --count: must be between 1 and 50" in lines[0]

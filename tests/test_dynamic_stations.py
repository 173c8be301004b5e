"""Issue 48, item 5: ``[dynamics] stations`` (tension, moment, curvature, position and, with
[design], utilisation at chosen arc lengths in timeseries.csv) and the plan view (x-z) of
a 3D line in the figures of ``solve`` and ``compare``.

- refusals: a station outside the line, negative, given twice, more than 50, not a
  number: exit 2, one line naming ``dynamics.stations[i]`` (or ``dynamics.stations``) and
  the allowed range; a touchdown form's stations move with its conversion to fixed ends;
- a short VFIFE run (and the ANCF's) with stations at nodes, at the ends and between
  nodes: at a node the columns are the node's own values (the saved states, bit for bit),
  at the ends the hang-off's columns, between nodes the linear interpolation of the
  states (numpy's interp, an independent path), the first row the static profile's
  values (utilisation included), and the window's extremes inside the envelope;
- plan view: the envelopes' figure of a dynamic run and the configurations' figure of a
  comparison get a panel x-z (z seen from above) for a 3D line, none for a planar one.

Time: ~6 s on a loaded 2-core machine (load 5), half of it imports (matplotlib, pandas)
the other test files share: a 4 s VFIFE run of a 110 m line at 5 m elements and the
ANCF's (~1 s warm), the figures built without being written, the refusals build scenes
only; the slow test runs ``riser-verify solve`` (both methods) and ``compare`` on a planar
and a 3D scene (~30 s).
"""

from __future__ import annotations

import struct
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from riser.errors import SceneError
from riser.io.scene_file import parse_scene
from riser.model.transform import fixed_ends_scene
from riser.physics.dynamics import MAX_STATIONS, Dynamics
from riser.results.recorder import TIMESERIES, station_weights
from verification import cli
from verification.catalog import resolve
from verification.methods import method

from builders import steel_line_toml

LINE = steel_line_toml("stations", line_type="drag_normal = 1.0\n",
                       tail="[vfife]\nelement_length = 5.0\n[ancf]\nelement_length = 5.0\n")
#: the 3D variant: a current across the plane of the ends
CURRENT_90 = """
[environment.current]
heights = [0.0, 60.0]
speeds = [0.3, 0.6]
heading_deg = 90.0
"""
#: node, between nodes (twice), the hang-off, the anchor: in this order
STATIONS = [20.0, 21.0, 55.3, 110.0, 0.0]


def dynamics(stations=STATIONS, duration=4.0, extra="save_states = true\n") -> str:
    return (f"[dynamics]\nduration = {duration}\noutput_interval = 0.5\n{extra}"
            f"stations = {list(stations)!r}\n[dynamics.top_motion]\naxis = \"y\"\n"
            "amplitude = 0.5\nperiod = 2.0\n")


def refusal(text: str, tmp_path, capsys) -> str:
    """``riser-verify solve`` on the scene ``text``: exit 2, one line on stderr."""
    path = tmp_path / "scene.toml"
    path.write_text(text)
    code = cli.main(["solve", str(path), "--method", "vfife", "--out",
                     str(tmp_path / "out"), "-q"])
    err = capsys.readouterr().err
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


# --------------------------------------------------------------------------- refusals
@pytest.mark.parametrize("stations, key, says", [
    ([10.0, 110.5], "dynamics.stations[1]", "must be within [0, 110] m"),
    ([-1.0], "dynamics.stations[0]", "must be >= 0 m, got -1"),
    ([5.0, 7.0, 5.0], "dynamics.stations[2]", "5 m given twice (stations[0])"),
    ([float(i) for i in range(MAX_STATIONS + 1)], "dynamics.stations",
     f"must have at most {MAX_STATIONS} entries"),
    (["a"], "dynamics.stations[0]", "must be a number"),
])
def test_stations_refused_naming_the_key_and_range(stations, key, says, tmp_path, capsys):
    text = LINE + dynamics(stations=[]).replace("stations = []", f"stations = {stations!r}"
                                                .replace("'", '"'))
    line = refusal(text, tmp_path, capsys)
    assert f"{key}: " in line and says in line, line


def test_the_line_end_and_every_node_are_accepted():
    sc = parse_scene(LINE + dynamics(stations=[110.0, 0.0, 37.5]))
    assert sc.dynamics.stations == (110.0, 0.0, 37.5)
    assert parse_scene(LINE + "[dynamics]\nduration = 4.0\n").dynamics.stations is None


def test_touchdown_form_stations_move_with_the_conversion():
    """A touchdown form's s is measured from its touchdown: the fixed-ends copy adds
    ``seabed_length`` at the bottom, so its stations move up by it; one beyond the
    suspended length the conversion keeps is refused naming the key."""
    base = resolve("wang2014-baseline")
    sc = base.replace(dynamics=Dynamics(duration=10.0, stations=(0.0, 1500.0)))
    fixed = fixed_ends_scene(sc, (1600.0, 1586.3), 300.0, first_segment_length=390.0)
    assert fixed.dynamics.stations == (300.0, 1800.0)
    far = base.replace(dynamics=Dynamics(duration=10.0, stations=(0.0, 2500.0)))
    with pytest.raises(SceneError, match=r"dynamics\.stations\[1\]: must be within "
                                         r"\[0, 2400\] m"):
        fixed_ends_scene(far, (1600.0, 1586.3), 300.0, first_segment_length=190.0)


def test_station_weights_are_exact_at_nodes():
    s = np.array([0.0, 0.3, 1.7, 2.0])
    i, w = station_weights(s, [0.0, 0.3, 1.0, 2.0])
    assert list(i) == [0, 1, 1, 2] and list(w[[0, 1, 3]]) == [0.0, 0.0, 1.0]
    assert w[2] == pytest.approx(0.7 / 1.4)


# ------------------------------------------------------------------ the time domains
@pytest.fixture(scope="module")
def runs():
    sc = parse_scene(LINE + dynamics())
    return {m: method(m).solve(sc) for m in ("vfife", "ancf")}


COLUMNS = ("tension", "moment", "curvature", "x", "y", "z", "utilisation")


@pytest.mark.parametrize("name", ["vfife", "ancf"])
def test_station_columns_follow_the_others(runs, name):
    res = runs[name]
    assert res.converged, res.message
    ts = res.dynamics.timeseries
    names = list(ts)
    assert tuple(names[:len(TIMESERIES)]) == TIMESERIES
    assert names[len(TIMESERIES):] == [f"station_{k}_{q}" for k in range(1, 6)
                                       for q in COLUMNS]
    assert res.summary()["stations"] == STATIONS


@pytest.mark.parametrize("name", ["vfife", "ancf"])
def test_station_values_at_nodes_ends_and_between(runs, name):
    res = runs[name]
    ts, st = res.dynamics.timeseries, res.dynamics.states
    s = st["s"]
    for k, sk in enumerate(STATIONS, start=1):
        j = np.flatnonzero(s == sk)
        for q, arr in (("tension", st["tension"]), ("moment", st["moment"]),
                       ("x", st["x"][:, :, 0]), ("y", st["x"][:, :, 1]),
                       ("z", st["x"][:, :, 2])):
            got = ts[f"station_{k}_{q}"]
            if j.size:                       # at a node: the node's own value
                np.testing.assert_array_equal(got, arr[:, j[0]], err_msg=f"{k} {q}")
            else:                            # between nodes: linear in s
                want = np.array([np.interp(sk, s, row) for row in arr])
                np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-9 * np.max(
                    np.abs(arr)), err_msg=f"{k} {q}")
    # the hang-off (station 4) is the hang-off's own columns
    for q in ("x", "y", "z", "tension"):
        key = f"hang_off_{q}"
        np.testing.assert_array_equal(ts[f"station_4_{q}"], ts[key])


def test_vfife_first_row_is_the_static_profile_and_the_window_within_the_envelope(runs):
    """Independent of the states: the first row (t = 0, the static state) against the
    static profile interpolated along s (the VFIFE's profile is at its nodes), the
    utilisation against the static design check's; the window's samples inside the
    envelope at the node stations."""
    res = runs["vfife"]
    ts, env, p = res.dynamics.timeseries, res.dynamics.envelope, res.profile
    for k, sk in enumerate(STATIONS, start=1):
        for q in COLUMNS:
            ref = np.interp(sk, p.s, getattr(p, q))
            assert ts[f"station_{k}_{q}"][0] == pytest.approx(ref, rel=1e-9, abs=1e-9), (k, q)
    window = ts["time"] >= res.info["statistics_start"] - 1e-9
    j = int(np.flatnonzero(env["s"] == 20.0)[0])
    for q, lo, hi in (("tension", "tension_min", "tension_max"),
                      ("moment", None, "moment_max"), ("curvature", None, "curvature_max"),
                      ("utilisation", None, "utilisation_max")):
        v = ts[f"station_1_{q}"][window]
        assert np.max(v) <= env[hi][j] * (1 + 1e-12), q
        if lo is not None:
            assert np.min(v) >= env[lo][j] * (1 + 1e-12) if env[lo][j] < 0 else \
                np.min(v) >= env[lo][j] * (1 - 1e-12), q


def test_without_design_no_utilisation_and_without_stations_nothing(runs):
    sc = parse_scene(LINE.replace("[design]\n", "") + dynamics(duration=2.5, extra=""))
    ts = method("vfife").solve(sc).dynamics.timeseries
    assert [k for k in ts if k.startswith("station_1_")] == [
        f"station_1_{q}" for q in COLUMNS[:-1]]
    sc = parse_scene(LINE + "[dynamics]\nduration = 2.5\noutput_interval = 0.5\n")
    res = method("vfife").solve(sc)
    assert tuple(res.dynamics.timeseries) == TIMESERIES and "stations" not in res.summary()


# ----------------------------------------------------------------------- plan views
def _captured(monkeypatch, module) -> dict:
    """name -> figure of every figure ``module`` saves (its ``save`` replaced)."""
    import matplotlib.pyplot as plt
    figs: dict = {}

    def keep(fig, path):
        if Path(path).name in figs:
            plt.close(figs[Path(path).name])
        figs[Path(path).name] = fig
    monkeypatch.setattr(module, "save", keep)
    return figs


def test_dynamic_envelopes_get_the_plan_view_of_a_3d_line_only(runs, monkeypatch, tmp_path):
    from verification.report import dynamics as report
    res = runs["vfife"]
    figs = _captured(monkeypatch, report)
    report.write_plots(res.dynamics, tmp_path, "t", 2.0)
    assert len(figs["envelope.png"].axes) == 3             # planar: as before
    report.write_plots(res.dynamics, tmp_path, "t", 2.0, plan=res.profile)
    axes = figs["envelope.png"].axes
    assert len(axes) == 4 and axes[-1].get_xlabel() == "x [m]"
    assert axes[-1].get_ylabel().startswith("z [m]") and axes[-1].yaxis_inverted()
    # the static line, the hang-off's track and one track per station
    assert len(axes[-1].lines) == 2 + len(STATIONS)


def test_compare_configurations_get_the_plan_view_of_a_3d_line_only(runs, monkeypatch,
                                                                    tmp_path):
    from verification.comparison.static import report
    p = runs["vfife"].profile
    flat = SimpleNamespace(profile=p)
    z = 0.01 * p.s * (p.s[-1] - p.s)
    bent = SimpleNamespace(profile=p.replace(z=z, lateral=z, moment_in_plane=p.moment,
                                             moment_out_of_plane=0 * p.moment))
    figs = _captured(monkeypatch, report)
    for prof, count in ((flat, 1), (bent, 2)):
        comp = SimpleNamespace(bvp=prof, vfife=prof, s_shift=0.0, paper=None, columns={},
                               scene=SimpleNamespace(name="t"))
        report._plots(comp, tmp_path)
        axes = figs["configurations.png"].axes
        assert len(axes) == count
    assert axes[1].get_xlabel() == "x [m]" and len(axes[1].lines) == 2
    np.testing.assert_array_equal(axes[1].lines[0].get_ydata(), z)


def _png_size(path: Path) -> tuple[int, int]:
    with open(path, "rb") as fh:
        head = fh.read(24)
    return struct.unpack(">II", head[16:24])


@pytest.mark.slow
def test_solve_and_compare_write_the_plan_view_of_a_3d_scene(tmp_path):
    """The command line end to end: the 3D scene's envelope.png and configurations.png
    are taller by the plan panel (4 in at 110 dpi) than the planar scene's; the ANCF's
    run writes the stations' columns too; twice the same bytes."""
    for name, text in (("planar", LINE), ("3d", LINE + CURRENT_90)):
        path = tmp_path / f"{name}.toml"
        path.write_text(text + dynamics(duration=3.0, extra=""))
        for m in ("vfife", "ancf"):
            assert cli.main(["solve", str(path), "--method", m, "--out",
                             str(tmp_path / name / m), "-q"]) in (0, 1)
            head = (tmp_path / name / m / "timeseries.csv").read_text().splitlines()[0]
            assert head.endswith("station_5_utilisation"), head
        assert cli.main(["compare", str(path), "--out", str(tmp_path / name / "compare"),
                         "-q"]) in (0, 1)
    w, h = _png_size(tmp_path / "planar" / "vfife" / "envelope.png")
    w3, h3 = _png_size(tmp_path / "3d" / "vfife" / "envelope.png")
    assert w3 == w and h3 == h + 440
    w, h = _png_size(tmp_path / "planar" / "compare" / "configurations.png")
    w3, h3 = _png_size(tmp_path / "3d" / "compare" / "configurations.png")
    assert w3 == w and h3 == h + 440
    again = tmp_path / "again"
    assert cli.main(["solve", str(tmp_path / "3d.toml"), "--method", "vfife", "--out",
                     str(again), "-q"]) in (0, 1)
    assert (again / "envelope.png").read_bytes() == (
        tmp_path / "3d" / "vfife" / "envelope.png").read_bytes()


if __name__ == "__main__":
    sys.exit(pytest.main([__file__, "-n", "0"]))

"""The dynamic study of Yu et al. (2021) (verification/studies/yu2021/dynamics.py): the lateral-speed
extraction on synthetic states with a known answer, and the dynamics.csv contract on a
coarse, short run (~10 s); the full-resolution steady-state check is marked slow."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from verification.catalog import resolve
from verification.studies.yu2021 import dynamics as yd
from verification.studies.yu2021.cases import sheared, with_hang_off_x

XH = 613.456        # the calibrated hang-off offset of the static study (reports/yu2021)


def synthetic_states(s0: float, peak: float, k: float, bias: float):
    """States on a non-uniform mesh: v_x = A(s) (sin(2 pi t / 10) + bias) with the parabola
    A(s) = peak - k (s - s0)^2 (>= 0), sampled every 0.25 s over 0-60 s; a larger v_x
    before t = 50 s (outside the window) and a large v_y everywhere (another axis)."""
    s = np.concatenate([np.arange(0.0, 600.0, 1.0), np.arange(600.0, 1050.01, 0.7)])
    t = np.arange(0.0, 60.0 + 1e-9, 0.25)
    amp = np.maximum(peak - k * (s - s0) ** 2, 0.0)
    v = np.zeros((len(t), len(s), 3))
    v[:, :, 0] = np.outer(np.sin(2 * math.pi * t / 10.0) + bias, amp)
    v[t < 49.9, 100, 0] = 5.0            # a transient at s = 100 m, before the window
    v[:, :, 1] = 3.0                     # vertical: not the lateral axis
    return {"t": t, "s": s, "v": v, "x": np.zeros_like(v)}


@pytest.mark.parametrize("s0", [300.4, 500.0, 640.35])   # between 1 m nodes, on one, 0.7 m mesh
def test_lateral_speed_is_exact_on_a_parabolic_amplitude(s0):
    st = synthetic_states(s0, peak=0.5, k=1e-4, bias=0.1)
    lat = yd.lateral_speed(st, 50.0, 60.0)
    s = st["s"]
    j = int(np.argmin(np.abs(s - s0)))            # the node nearest the peak
    a_j = 0.5 - 1e-4 * (s[j] - s0) ** 2           # its amplitude, from the formula
    # the amplitude is a parabola in s, so the three-point vertex is exact: only round-off
    # (1e-9 m on ~1000 m) separates it from s0
    assert lat["peak_from_top"] == pytest.approx(s[-1] - s0, abs=1e-9)
    # sin = +1 and -1 are sampled (t = 52.5 and 57.5 s): the extremes are exact
    assert lat["v_max"] == pytest.approx(1.1 * a_j, rel=1e-12)
    assert lat["v_min"] == pytest.approx(-0.9 * a_j, rel=1e-12)
    assert lat["range"] == pytest.approx(1.1 * a_j, rel=1e-12)
    assert lat["samples"] == 41                   # 50.0, 50.25, ..., 60.0
    # the whole run would pick the transient at s = 100 m instead
    assert yd.lateral_speed(st, 0.0, 60.0)["peak_s"] == pytest.approx(100.0)


def test_added_mass_share_of_the_yu_pipe():
    # Table 1: pipe 3297.8567 kg/m3 on the 0.409 / 0.317 m wall, empty; C_a = 1 on the
    # 0.409 m displacement in 1024 kg/m3 water
    m = 3297.8567 * math.pi / 4 * (0.409 ** 2 - 0.317 ** 2)
    ma = 1024.0 * math.pi / 4 * 0.409 ** 2
    assert yd.added_mass_share(resolve("yu2021-a1")) == pytest.approx(m / (m + ma), rel=1e-9)


def test_dynamics_csv_has_the_contract_columns(tmp_path):
    # A1 on 10 m elements for 30 s (ramp + 2 periods): the file's form, not its values
    scene = sheared(with_hang_off_x(resolve("yu2021-a1"), XH), yd.TOP_SPEED)
    lines = yd.run(tmp_path, {"A1": scene}, log=lambda *_: None, element_length=10.0,
                   duration=30.0, sensitivity=False)
    df = pd.read_csv(tmp_path / "dynamics.csv")
    assert list(df.columns) == ["case", "quantity", "paper", "vfife", "rel_err"]
    assert list(df.quantity) == ["max_moment", "max_hang_off_tension",
                                 "lateral_speed_peak_from_top", "lateral_speed_range"]
    assert set(df.case) == {"A1"}
    # docs/references.md, Yu et al. 2021, in SI: 161.2 kN m, 230.2 kN, 420 m, +-0.50 m/s
    assert list(df.paper) == [161.2e3, 230.2e3, 420.0, 0.50]
    assert np.allclose(df.rel_err, (df.vfife - df.paper) / df.paper.abs(), rtol=1e-6)
    assert (tmp_path / "dynamics.png").exists()
    assert lines[0] == "## Dynamics"


def test_the_top_moves_vertically_at_the_prescribed_speed(tmp_path):
    # independent kinematics: the hang-off's vertical speed amplitude is 2 pi A / T =
    # 0.94248 m/s (sampled at its peaks, t = 20, 30 s; the central-difference velocity is
    # the mid-step one, off by (omega dt / 2)^2 / 2 < 1e-6), its lateral speed is 0
    scene = sheared(with_hang_off_x(resolve("yu2021-a1"), XH), yd.TOP_SPEED)
    from verification.pipeline import solve_scene
    res = solve_scene(yd.dynamic_scene(scene, duration=30.0), "vfife", element_length=10.0)
    assert res.converged, res.message
    st = res.dynamics.states
    vert = yd.lateral_speed(st, 20.0, 30.0, axis=1)["amplitude"]
    lat = yd.lateral_speed(st, 20.0, 30.0, axis=0)
    assert vert[-1] == pytest.approx(2 * math.pi * 1.5 / 10.0, rel=1e-4)
    assert lat["amplitude"][-1] == 0.0 and lat["amplitude"][0] == 0.0   # pinned ends
    # the table's values are the summary's statistics over the same last period
    last = yd.period_values(res, 20.0, 30.0)
    sm = res.summary()
    assert last["max_moment"] == pytest.approx(sm["dynamic_max_moment"], rel=1e-12)
    assert last["max_hang_off_tension"] == pytest.approx(sm["dynamic_max_hang_off_tension"],
                                                         rel=1e-12)


@pytest.mark.slow
def test_a1_at_one_metre_is_steady_after_sixty_seconds():
    # the study's own run (1 m elements, 60 s, damping 0.8): the last two periods agree
    # (the report's criterion: 0.5 % on the forces and the speed, 5 m on the location)
    scene = sheared(with_hang_off_x(resolve("yu2021-a1"), XH), yd.TOP_SPEED)
    r = yd._solve("A1", scene, yd.DAMPING, None, yd.DURATION, lambda *_: None)
    for q in ("max_moment", "max_hang_off_tension", "lateral_speed_range"):
        assert abs(r["last"][q] / r["prev"][q] - 1.0) < 5e-3, q
    assert abs(r["last"]["lateral_speed_peak_from_top"]
               - r["prev"]["lateral_speed_peak_from_top"]) <= 5.0

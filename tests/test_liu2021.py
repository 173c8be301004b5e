"""The Liu et al. (2021) slug-flow study (verification/studies/liu2021/): the
signal analysis on synthetic signals with a known answer, the table.csv contract on a
short coarse run (~3 s), and (slow) the paper's qualitative findings on the full study."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from verification.studies import STUDIES, study
from verification.studies.liu2021 import analysis as la
from verification.studies.liu2021 import cases as liu

DT = 0.5                                   # s, the study's output interval


def test_common_period_and_whole_periods():
    # the steady windows of the study: surge 9 s with slug 32 s (L_s 80 m at 2.5 m/s) has
    # the common period 288 s; 25.6 s (L_s/D 160) 1152 s; rational arithmetic: exact
    assert la.common_period((9.0, 32.0)) == 288.0
    assert la.common_period((9.0, 25.6)) == pytest.approx(1152.0, rel=1e-12)
    assert la.whole_periods(44.8, 1000.0) == pytest.approx(985.6, rel=1e-12)
    assert la.whole_periods(50.0, 30.0) == 50.0            # at least one period
    assert liu.steady_length(2000.0, (9.0, 32.0)) == (288.0, True)
    assert liu.steady_length(60.0, (9.0, 32.0)) == (27.0, False)


@pytest.mark.parametrize("a_surge, a_slug", [(3.0, 5.0), (5.0, 3.0)])
def test_dominant_frequency_picks_the_larger_of_two_lines(a_surge, a_slug):
    # the station moments' two lines (surge 1/9 Hz, slug 1/32 Hz) on a 288 s window of
    # whole periods of both, plus a mean: both fall on bins, so the amplitudes are exact
    # to round-off (1e-9) and the larger line is the one picked, whichever it is
    t = DT * np.arange(576)
    y = 170.0 + a_surge * np.sin(2 * math.pi * t / 9.0) + a_slug * np.cos(
        2 * math.pi * t / 32.0 + 0.3)
    f, amp = la.dominant_frequency(y, DT)
    big = max(a_surge, a_slug)
    assert f == pytest.approx(1 / 9.0 if a_surge > a_slug else 1 / 32.0, abs=1e-12)
    assert amp == pytest.approx(big, rel=1e-9)
    assert la.amplitude_at(y, DT, 1 / 9.0) == pytest.approx(a_surge, rel=1e-9)
    assert la.amplitude_at(y, DT, 1 / 32.0) == pytest.approx(a_slug, rel=1e-9)
    freqs, spec = la.spectrum(y, DT)
    assert spec[0] == 0.0                       # the mean is not a line
    assert freqs[1] == pytest.approx(1 / 288.0)  # resolution 1 / window


def test_half_range_over_a_window_ignores_the_transient():
    # a sine of period 8 s sampled every 0.5 s hits its crests and troughs: (max - min) / 2
    # is its amplitude exactly; a spike before the window (the ramp-in) must not count,
    # and the half-open window of 288 s holds exactly 576 samples
    t = np.arange(0.0, 2000.0 + 1e-9, DT)
    y = 4.0 * np.sin(2 * math.pi * t / 8.0)
    y[t < 100.0] += 50.0
    sel = la.window(t, t[-1] + DT, 288.0)
    assert sel.sum() == 576
    assert la.half_range(y[sel]) == pytest.approx(4.0, rel=1e-12)
    assert la.half_range(y) == pytest.approx(29.0, rel=1e-12)     # (54 - -4) / 2


@pytest.mark.parametrize("v", [2.5, 2.3, 2.77, -2.1])
def test_lag_of_a_travelling_pattern_gives_its_speed(v):
    # f(s - v t) (three incommensurate wavelengths, so no shorter false period) sampled at
    # 300 and 330 m: the series at 330 m trails by 30 / v. On the 0.5 s grid the parabola
    # through the correlation peak leaves < 0.2 % on v (measured 3e-5 to 1.2e-3), so 0.5 %;
    # |30 / v| < 16 s = max_lag, the study's half slug period
    def f(x):
        return (np.sin(2 * math.pi * x / 80.0) + 0.4 * np.sin(2 * math.pi * x / 29.0 + 1.0)
                + 0.2 * np.cos(2 * math.pi * x / 13.0))
    t = np.arange(0.0, 600.0, DT)
    tau = la.lag(f(300.0 - v * t), f(330.0 - v * t), DT, 16.0)
    assert 30.0 / tau == pytest.approx(v, rel=5e-3)
    # the same through travel_speed on a (k, n) field of nodes 4 m apart (330 m between
    # nodes: the interpolation of a smooth field adds < 0.1 %)
    s = np.arange(0.0, 1260.01, 4.0)
    field = f(s[None, :] - v * t[:, None])
    speeds = la.travel_speed(field, s, DT, [(300.0, 330.0), (402.0, 432.0)], 16.0)
    assert speeds == pytest.approx([v, v], rel=5e-3)


def test_at_station_interpolates_between_nodes():
    # a field linear in s is reproduced exactly between nodes (and on a node)
    s = np.array([0.0, 4.0, 8.0, 12.0])
    vals = np.outer([1.0, 2.0], 10.0 + 3.0 * s)
    assert la.at_station(vals, s, 5.0) == pytest.approx([25.0, 50.0], rel=1e-12)
    assert la.at_station(vals, s, 12.0) == pytest.approx([46.0, 92.0], rel=1e-12)


QUANTITIES = [
    "static_top_effective_tension_uniform_N", "static_top_wall_tension_uniform_N",
    "static_tension_slug_vs_uniform_max_rel", "static_moment_slug_ripple_max_N_m",
    "top_tension_amplitude_uniform_N", "top_tension_amplitude_slug_N",
    "top_tension_amplitude_slug_minus_uniform_N",
    "top_tension_amplitude_difference_rel_static",
    "top_tension_peak_to_peak_slug_minus_uniform_N",
    "moment_140m_dominant_frequency_Hz", "moment_140m_slug_to_surge_line_ratio",
    "moment_300m_dominant_frequency_Hz", "moment_300m_slug_to_surge_line_ratio",
    "static_moment_140m_uniform_N_m", "static_touchdown_s_uniform_m",
    "static_peak_moment_uniform_N_m", "static_peak_moment_s_uniform_m",
    "sag_bend_moment_estimate_EIw_over_H_N_m", "mean_moment_140m_LsD100_N_m",
    "mean_moment_140m_LsD160_N_m", "mean_moment_140m_LsD220_N_m",
    "mean_moment_140m_LsD280_N_m", "mean_moment_140m_LsD280_minus_LsD100_rel_static",
    "slug_travel_speed_m_s"]


@pytest.fixture(scope="module")
def coarse(tmp_path_factory):
    """The study on 5 m elements (8 per 40 m slug, the fewest allowed) for 60 s (six
    runs, ~6 s): its files, not its values."""
    out = tmp_path_factory.mktemp("liu2021")
    q = liu.run(out, log=lambda *_: None, duration=60.0, element_length=5.0)
    return out, q


def test_table_csv_contract(coarse):
    # the columns and rows the report, the index and the lead's review read; rel_err is
    # computed / paper - 1 where the paper has a number (the CSV's 8 digits of computed
    # leave ~1e-8 absolute on the ratio, so atol 1e-7)
    out, _ = coarse
    df = pd.read_csv(out / "table.csv")
    assert list(df.columns) == ["quantity", "paper", "computed", "rel_err", "note"]
    assert list(df.quantity) == QUANTITIES
    assert df.computed.notna().all() and df.note.notna().all()
    both = df.paper.notna()
    assert np.allclose(df.rel_err[both], df.computed[both] / df.paper[both] - 1.0,
                       rtol=1e-6, atol=1e-7)
    assert df.rel_err[~both].isna().all()
    paper = dict(zip(df.quantity, df.paper))
    # docs/references.md, Liu et al. 2021: 3.78 kN = 0.27 %; 101.06 / 127.53 kN m, 36 %;
    # U 2.5 m/s
    assert paper["top_tension_amplitude_slug_minus_uniform_N"] == 3780.0
    assert paper["static_top_effective_tension_uniform_N"] == pytest.approx(1.4e6)
    assert paper["mean_moment_140m_LsD100_N_m"] == 101060.0
    assert paper["mean_moment_140m_LsD280_N_m"] == 127530.0
    assert paper["mean_moment_140m_LsD280_minus_LsD100_rel_static"] == 0.36
    assert paper["slug_travel_speed_m_s"] == 2.5
    for name in ("report.md", "top_tension.png", "static.png", "moments.png",
                 "slug_length.png"):
        assert (out / name).exists(), name


def test_index_row_reads_the_table_back(coarse):
    # reports/README.md's line comes from table.csv, and the study is in the registry
    out, _ = coarse
    cases, agreement, verdict = liu.index_row(out)
    assert "slug" in cases and "vs paper" in agreement and verdict.startswith("reported")
    assert liu.index_row(out / "missing") is None
    assert "liu2021" in STUDIES and study("liu2021") is liu.STUDY


@pytest.mark.slow
def test_full_study_reproduces_the_qualitative_findings(tmp_path):
    # the paper's findings on the full study (~90 s): surge-dominated moment at 140 m,
    # slug-dominated at 300 m (exact bins of the 288 s window), the slug travelling at U
    # (median of six pairs, 2 %: the spread of the pairs is 1.5 %), the static top tension
    # within the rounding of the paper's 0.27 % (1375-1426 kN), the steady window steady
    q = liu.run(tmp_path, log=lambda *_: None)
    dy, st = q["dynamic"], q["static"]
    assert dy["window"] == 288.0 and dy["samples"] == 576
    assert dy["m140_slug"]["f"] == pytest.approx(1 / 9.0, abs=1e-9)
    assert dy["m300_slug"]["f"] == pytest.approx(1 / 32.0, abs=1e-9)
    assert dy["speed"] == pytest.approx(2.5, rel=0.02)
    assert 1375e3 < st["top_tension"] < 1426e3
    # with the slug frozen at t = 0 the top tension drops by about the weight of the
    # unfinished wave, eta mu0 g sin(k L) / k = -2.01 kN (1260 m = 15.75 slugs); 5 %: the
    # wave's weight on the seabed rests on the soil (the suspended part's integral of
    # dw sin(theta) is -1.94 kN) and the end node's tension is extrapolated from the wavy
    # field (measured -2.02 and -2.07 kN with two versions of the kernels)
    assert st["dT"] == pytest.approx(st["net_slug_weight"], rel=0.05)
    assert st["net_slug_weight"] == pytest.approx(-2.0e3, rel=0.02)
    assert dy["steady_uniform"] < 5e-3 and dy["steady_slug"] < 5e-3

"""What the reports say (issue 44, the report items): numbers that never print 30 decimals,
a fatigue report whose per-sea-state rows add up to its headline and that names the
scene's component count, no empty transfer files for a wave, no noise for the minimum
tension's place on a grounded line."""

from __future__ import annotations

import math
import re
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from riser.design.fatigue import SECONDS_PER_YEAR
from verification.catalog import resolve
from verification.comparison.dynamic import report as dynamics_report
from verification.comparison.dynamic.protocol import WAVE
from verification.report import dynamics as dyn_report
from verification.report.units import MAX_DIGITS, length, with_unit
from verification.studies.design import fatigue_report
from verification.studies.design.fatigue import ESTIMATES, ScatterFatigue, SeaStateFatigue


def _significant(text: str) -> int:
    """Significant digits of the number that starts ``text`` (fixed or scientific)."""
    mantissa = re.match(r"-?([0-9.]+)", text).group(1).replace(".", "").lstrip("0")
    return len(mantissa)


# -- numbers -------------------------------------------------------------------------

def test_the_issues_tiny_numbers_print_in_scientific_notation():
    # the issue's two prints: x = 0.0000000000000000000000000000228 m, 0.000000344 mN m
    assert length(2.28e-29) == "2.28e-29"
    assert with_unit(3.44e-10, "N m") == "3.44e-10 N m"
    # and the round-off floor: 1e-9 of the quantity's scale (the profiles' 10 digits)
    assert length(2.28e-29, scale=1500.0) == "0"
    assert with_unit(3.44e-10, "N m", scale=1.0e5) == "0 N m"
    assert with_unit(2.0e-3, "N m", scale=1.0e5) == "2.00 mN m"     # 2e-8 of it: kept


@pytest.mark.parametrize("exponent", range(-30, 13))
def test_no_magnitude_prints_more_than_seven_digits_or_loses_its_value(exponent):
    # every decade from 1e-30 to 1e12: at most MAX_DIGITS significant digits, and the
    # printed number read back (with its prefix) is the value to its 3 shown digits
    # (half a unit of the third digit: 5e-3 relative)
    value = -1.234567891 * 10.0 ** exponent
    prefixes = {"M": 1e6, "k": 1e3, "m": 1e-3, "": 1.0}
    for text in (with_unit(value, "N"), with_unit(value, "N m", decimals=3)):
        number, unit = text.split(" ", 1)
        assert _significant(number) <= MAX_DIGITS, text
        back = float(number) * prefixes[unit[:-1] if unit in ("MN", "kN", "mN") else
                                        unit[:-3] if unit.endswith(" m") and
                                        len(unit) > 3 else ""]
        assert math.isclose(back, value, rel_tol=5e-3), text
    text = length(value)
    assert _significant(text) <= MAX_DIGITS and math.isclose(float(text), value,
                                                             rel_tol=5e-3), text


def test_a_lab_models_force_keeps_its_digits():
    # the units' own promise (issue 30) still holds: 1.1 N is never 0.00 kN
    assert with_unit(1.1213, "N") == "1.12 N" and with_unit(0.2479, "N") == "247.90 mN"
    assert length(1500.0) == "1500.00" and length(123456.789) == "123456.8"   # 7 digits


# -- the timeseries panel of a grounded line -------------------------------------------

def _grounded_series(compression: bool) -> dict:
    """A grounded line's time series: the touchdown at s = 300 m with 2 kN there, the
    line's minimum on the seabed (uniform tension: its place jumps between the nodes),
    and, with ``compression``, a slack of -5 kN at s = 320 m at two samples."""
    rng = np.random.default_rng(0)
    k = 50
    ts = {"time": np.arange(k) * 0.5, "touchdown_s": np.full(k, 300.0),
          "touchdown_tension": np.full(k, 2000.0), "hang_off_tension": np.full(k, 1.0e6),
          "min_tension": np.full(k, 2000.0 - 1e-6), "min_tension_s": rng.uniform(0, 300, k)}
    if compression:
        ts["min_tension"][[10, 11]] = -5000.0
        ts["min_tension_s"][[10, 11]] = 320.0
    return ts


def test_the_minimum_tensions_place_on_the_seabed_is_not_drawn():
    s = dyn_report.suspended_min_tension_s(_grounded_series(compression=False))
    assert np.all(np.isnan(s))          # the seabed's noise: nothing drawn


def test_a_slack_in_the_suspended_part_is_drawn_where_it_is():
    s = dyn_report.suspended_min_tension_s(_grounded_series(compression=True))
    assert np.flatnonzero(np.isfinite(s)).tolist() == [10, 11] and np.all(s[[10, 11]] == 320.0)


def test_a_line_off_the_seabed_keeps_the_whole_lines_minimum():
    ts = _grounded_series(compression=False)
    ts["touchdown_s"][:] = np.nan
    assert dyn_report.suspended_min_tension_s(ts) is None


def test_the_console_says_the_minimum_is_on_the_seabed():
    sm = {"dynamic_max_hang_off_tension": 1e6, "statistics_start": 0.0, "statistics_end": 9.0,
          "dynamic_min_hang_off_tension": 9e5, "dynamic_hang_off_tension_range": 1e5,
          "dynamic_max_moment": 1e3, "dynamic_max_moment_s": 310.0,
          "dynamic_max_moment_time": 1.0, "dynamic_min_tension": 2000.0,
          "dynamic_min_tension_s": 123.4, "dynamic_min_tension_time": 2.0,
          "dynamic_min_touchdown_s": 290.0, "dynamic_max_touchdown_s": 305.0,
          "dynamic_steps": 10, "dynamic_time_step": 1e-3, "realtime_factor": 1.0}
    line = next(x for x in dyn_report.summary_lines(sm) if "min tension" in x)
    assert "on the seabed" in line and "305.0" in line
    sm["dynamic_min_tension_s"] = 320.0
    line = next(x for x in dyn_report.summary_lines(sm) if "min tension" in x)
    assert "at s = 320.0 m" in line and "seabed" not in line


# -- the fatigue report ----------------------------------------------------------------

def _scatter(components: int) -> ScatterFatigue:
    """scr-steel-fatigue with ``components`` wave components and three sea states whose
    damage rates along s peak at different stations (the headline's station is none of
    them), with stand-ins for the runs' figures the report prints."""
    sc = resolve("scr-steel-fatigue")
    sc = sc.replace(waves=sc.waves.replace(
        spectrum=sc.waves.spectrum.replace(components=components)))
    s = np.linspace(0.0, 2000.0, 401)
    tdp = 500.0
    cmp = SimpleNamespace(vfife_result=SimpleNamespace(info={
        "dynamic_max_utilisation": 0.3, "dynamic_max_utilisation_s": 1990.0,
        "dynamic_max_touchdown_s": 520.0, "dynamic_min_touchdown_s": 480.0}),
        ramp_s=80.0, settle_s=60.0, element_length=5.0, fd_wall_s=1.0, vfife_wall_s=9.0,
        fd=SimpleNamespace(std={"tension": np.array([1.0, 2.0])}), vf={"std": 2.1})
    states = []
    for (hs, tp, p), peak in zip(((1.5, 8.0, 0.6), (3.0, 10.0, 0.3), (5.0, 12.0, 0.1)),
                                 (470.0, 540.0, 610.0)):
        base = hs ** 3 * 1e-10 * np.exp(-((s - peak) / 40.0) ** 2) + 1e-13 * s / 2000.0
        rates = {e: base * f for e, f in zip(ESTIMATES, (1.0, 3.0, 3.2, 3.5))}
        states.append(SeaStateFatigue(hs, tp, p, s, rates, 300.0, cmp, 10.0, tdp))
    # the damage per year of the module's docstring, summed here independently
    per_year = {e: sum(st.probability * st.rates[e] for st in states) * SECONDS_PER_YEAR
                for e in ESTIMATES}
    return ScatterFatigue(sc, states, s, per_year, 5.0)


def test_the_per_sea_state_shares_add_up_to_the_headline(tmp_path, monkeypatch):
    monkeypatch.setattr(fatigue_report, "fd_utilisation", lambda cmp, d: (0.25, 1990.0))
    res = _scatter(components=37)
    head = fatigue_report.write(res, tmp_path)
    ss = pd.read_csv(tmp_path / "sea_states.csv")
    st = pd.read_csv(tmp_path / "stations.csv").set_index("estimate")
    for e in ESTIMATES:
        # the shares at the headline's station sum to its damage per year (10 digits of
        # the CSV files: 1e-9)
        assert math.isclose(ss[f"{e}_touchdown_damage_per_year"].sum(),
                            st.loc[e, "touchdown_damage_per_year"], rel_tol=1e-9)
        assert math.isclose(ss[f"{e}_hang_off_damage_per_year"].sum(),
                            st.loc[e, "hang_off_damage_per_year"], rel_tol=1e-9)
    # the rows are at the headline's station; each sea state's own worst is its peak
    assert np.allclose(ss.touchdown_s, head["touchdown_s"])
    assert ss.rainflow_vfife_own_worst_s.tolist() == [470.0, 540.0, 610.0]
    text = (tmp_path / "report.md").read_text()
    assert "37 components, seed 1" in text and "100 components" not in text
    total = st.loc["rainflow_vfife", "touchdown_damage_per_year"]
    assert f"**{total:.4g}**" in text and "add up to the headline" in text
    assert "do not add up" in text      # the own-worst column says it is not a share


# -- transfer functions of a wave --------------------------------------------------------

def _wave_comparison():
    """A wave comparison of jumper-wave with stand-in results (one amplitude, no rows):
    what write() and markdown() read of it, without running the methods."""
    sc = resolve("jumper-wave")
    nl = {"contact_zone": None, "quantity": "tension", "hang_off_higher_harmonics": 0.01,
          "max_higher_harmonics": 0.02, "hang_off_envelope_ratio": 1.0, "window_drift": 0.0,
          "settle_periods": 4}
    r = SimpleNamespace(amplitude=0.25, fd_wall_s=1.0, vfife_wall_s=20.0, warnings=[],
                        rows=[], stations=[], nonlinearity=nl, vf={}, ancf=None, ancf_rows=[])
    dc = SimpleNamespace(axis=WAVE, scene=sc, matched=sc, period=sc.waves.trains[0].period,
                         element_length=1.0, results=[r], notes=[], passed=True)
    s = np.linspace(0.0, 100.0, 5)
    resp = pd.DataFrame({"amplitude_m": 0.25, "s": s, **{
        f"{m}_{q}": np.ones_like(s) for m in ("fd", "vfife")
        for q in ("tension", "moment", "displacement")}})
    tables = {"dynamic_agreement.csv": pd.DataFrame({
        "quantity": ["hang_off_tension_amplitude"], "amplitude_m": [0.25],
        "rel_diff": [0.002]}), "stations.csv": pd.DataFrame(), "response.csv": resp}
    return dc, tables


def test_a_wave_comparison_writes_and_links_no_transfer_files(tmp_path, monkeypatch):
    # the issue's case: compare --dynamics on a wave scene wrote an empty transfer.csv
    # and transfer.png and linked them; a wave drives no motion along one axis, so the
    # per-unit-motion transfer functions do not exist: nothing written, nothing linked,
    # and the report says why
    dc, tables = _wave_comparison()
    monkeypatch.setattr(dynamics_report, "frames", lambda d: dict(tables))
    dynamics_report.write(dc, tmp_path)
    names = {p.name for p in tmp_path.iterdir()}
    assert {"response.png", "sweep.png", "report.md", "response.csv"} <= names
    assert not {n for n in names if n.startswith("transfer")}, names
    text = (tmp_path / "report.md").read_text()
    assert "transfer.png" not in text and "transfer.csv" not in text
    assert "no transfer functions" in text
    # every file the report links exists
    for link in re.findall(r"\]\(([^)]+)\)|`([a-z_]+\.(?:csv|png))`", text):
        name = link[0] or link[1]
        assert (tmp_path / name).exists(), name

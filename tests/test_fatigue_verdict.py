"""The fatigue verdict (issue 48, item 1): ``[design] design_life`` [years] with
``[design.fatigue] design_fatigue_factor`` (DFF) turns the fatigue life along the line
into a verdict, fatigue_utilisation = DFF x design_life / life <= 1 at every station
(DNV-OS-F201 Sec. 5 D 500, DNV-RP-F204; riser/design/fatigue.py ``fatigue_verdict``).

- hand vectors of the pure function and its console line;
- the key's refusals (one line naming it and its range, exit 2) and its warning without
  [design.fatigue];
- a dynamic run's verdict (riser/design/dynamic.py): by hand on a synthetic record, and
  in a VFIFE solve's summary and envelope (a 110 m line, 12 s of heave: ~1 s);
- ``riser-verify fatigue``'s files, summary.json and console on stand-in runs (the
  scatter diagram's solvers replaced: no solver, < 1 s).

Time: about 2 s (one VFIFE solve of ~1 s; the rest builds scenes and writes files).
"""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from riser.design.dynamic import DynamicDesign
from riser.design.fatigue import SECONDS_PER_YEAR, fatigue_verdict, verdict_line
from riser.io.scene_file import parse_scene
from riser.io.toml_text import dumps
from verification.catalog import resolve
from verification.report.dynamics import fatigue_verdict_line
from verification.studies.design import fatigue_report, fatigue_scatter
from verification.studies.design.fatigue import (ANCF, DESIGN_ESTIMATE, ESTIMATES,
                                                 ScatterFatigue, SeaStateFatigue, verdicts)

from builders import steel_line_toml

ROOT = Path(__file__).resolve().parents[1]

LINE = steel_line_toml("fatigue-verdict", design="design_life = 20.0\n")
FATIGUE = """
[design.fatigue]
sn_curve = "F"
environment = "free-corrosion"
scf = 1.3
points = 8
design_fatigue_factor = 10.0
"""
DYNAMICS = """
[dynamics]
duration = 12.0
output_interval = 0.5
[dynamics.top_motion]
axis = "y"
amplitude = 0.5
period = 6.0
"""


# ------------------------------------------------------------------ the pure function
def test_hand_vector_fails_at_the_first_station():
    # life [0.72, 50, inf] years, design life 20 years, DFF 10: the required life is
    # 10 x 20 = 200 years; utilisation 200 / 0.72 = 277.777..., 200 / 50 = 4, and 0 where
    # there is no damage (life inf): fail at the first station (s = 512.3 m)
    v = fatigue_verdict([512.3, 900.0, 1990.0], [0.72, 50.0, math.inf], 20.0, 10.0)
    assert v["required_life"] == 200.0
    np.testing.assert_allclose(v["fatigue_utilisation"], [2000.0 / 7.2, 4.0, 0.0],
                               rtol=1e-15)
    assert v["fatigue_utilisation"][0] == pytest.approx(277.78, abs=0.005)
    assert v["fatigue_pass"].tolist() == [False, False, True]
    assert v["max_fatigue_utilisation"] == pytest.approx(277.7777777777778, rel=1e-15)
    assert v["max_fatigue_utilisation_s"] == 512.3 and v["worst_life"] == 0.72
    assert v["fatigue_verdict"] == "fail"
    assert verdict_line(v, 20.0, 10.0) == (
        "fatigue verdict: FAIL at s = 512.3 m: life 0.72 years < DFF 10 x design life 20 "
        "years = 200 years (fatigue utilisation 278)")


def test_hand_vector_passes_and_the_bound_is_inclusive():
    # life [1000, 250, 200] years, design life 25 years, DFF 8: required 200 years;
    # utilisation 0.2, 0.8 and exactly 1 (life = the required life: passes, <= 1); the
    # worst station is the last (the least life)
    v = fatigue_verdict([10.0, 20.0, 30.0], [1000.0, 250.0, 200.0], 25.0, 8.0)
    np.testing.assert_allclose(v["fatigue_utilisation"], [0.2, 0.8, 1.0], rtol=1e-15)
    assert v["fatigue_pass"].all() and v["fatigue_verdict"] == "pass"
    assert v["max_fatigue_utilisation_s"] == 30.0 and v["max_fatigue_utilisation"] == 1.0
    assert verdict_line(v, 25.0, 8.0) == (
        "fatigue verdict: PASS: the least life 200 years at s = 30.0 m >= DFF 8 x design "
        "life 25 years = 200 years (fatigue utilisation 1)")
    # 1 % short of the required life (198 years): 200 / 198 = 1.0101 > 1 fails
    v = fatigue_verdict([0.0, 1.0], [198.0, math.inf], 25.0, 8.0)
    assert v["fatigue_verdict"] == "fail" and v["fatigue_pass"].tolist() == [False, True]
    assert v["max_fatigue_utilisation"] == pytest.approx(200.0 / 198.0, rel=1e-15)


def test_no_damage_zero_life_and_nan():
    # no damage anywhere: utilisation 0 everywhere, a pass, the line says so
    v = fatigue_verdict([0.0, 5.0], [math.inf, math.inf], 20.0, 3.0)
    assert v["fatigue_utilisation"].tolist() == [0.0, 0.0] and v["fatigue_verdict"] == "pass"
    assert verdict_line(v, 20.0, 3.0) == ("fatigue verdict: PASS: no fatigue damage along "
                                          "the line (DFF 3 x design life 20 years = 60 years)")
    # a life of 0: utilisation inf, the worst
    v = fatigue_verdict([0.0, 5.0], [100.0, 0.0], 20.0, 1.0)
    assert math.isinf(v["fatigue_utilisation"][1]) and v["fatigue_pass"].tolist() == [
        True, False]
    assert v["max_fatigue_utilisation_s"] == 5.0 and v["fatigue_verdict"] == "fail"
    # a NaN life (no result) does not pass and ranks as the worst
    v = fatigue_verdict([0.0, 5.0, 9.0], [10.0, 100.0, math.nan], 20.0, 1.0)
    assert v["fatigue_pass"].tolist() == [False, True, False]
    assert v["max_fatigue_utilisation_s"] == 9.0 and v["fatigue_verdict"] == "fail"
    with pytest.raises(ValueError, match="equal 1D arrays"):
        fatigue_verdict([0.0, 1.0], [1.0], 20.0, 1.0)


# ------------------------------------------------------------------ the key
@pytest.mark.parametrize("value, message", [
    ("0.0", "must be > 0 years, got 0"), ("-20.0", "must be > 0 years, got -20"),
    ("250.0", "must be <= 200 years, got 250"), ('"20"', "must be a number, got a string"),
    ("true", "must be a number, got a boolean")])
def test_a_bad_design_life_is_one_line_exit_2(tmp_path, run_cli, value, message):
    p = tmp_path / "bad.toml"
    p.write_text(LINE.replace("design_life = 20.0", f"design_life = {value}") + FATIGUE)
    code, out, err = run_cli(["solve", str(p), "--out", str(tmp_path / "o")])
    assert code == 2
    assert err.strip().splitlines() == [f"error: bad.toml: design.design_life: {message}"]
    assert not (tmp_path / "o" / "profile.csv").exists()


def test_the_key_its_default_and_its_warning():
    sc = parse_scene(LINE + FATIGUE)
    assert sc.design.design_life == 20.0 and sc.design.fatigue.design_fatigue_factor == 10.0
    assert parse_scene(LINE.replace("design_life = 20.0\n", "")).design.design_life is None
    # a design life without [design.fatigue]: nothing to judge, said by name
    from riser.design.part import design_warnings
    assert design_warnings(sc) == []
    assert design_warnings(parse_scene(LINE)) == [
        "ignored_input: design.design_life = 20 years needs [design.fatigue] (the S-N "
        "curve): no fatigue verdict"]
    with pytest.raises(Exception, match=r"design_life: must be <= 200 years, got 201"):
        sc.design.replace(design_life=201.0)


# ------------------------------------------------------------------ a dynamic run
def _record(scene, design_life):
    """A DynamicDesign fed 41 samples of a straight line along x (stations 0..4 m) bent
    harmonically about z, the amplitude growing along s (none at s = 0)."""
    scene = scene.replace(design=scene.design.replace(design_life=design_life))
    s = np.arange(5.0)
    dd = DynamicDesign(scene, s)
    x = np.zeros((5, 3))
    x[:, 0], x[:, 1] = s, 10.0
    t = np.zeros((5, 3))
    t[:, 0] = 1.0
    for k in range(41):
        m = np.zeros((5, 3))
        m[:, 2] = 2.0e4 * s * math.sin(2.0 * math.pi * k / 10.0)
        dd.sample(0.25 * k, x, t, np.full(5, 1.0e5), m, window=True)
    return dd


def test_the_dynamic_verdict_by_hand_on_a_record():
    sc = parse_scene(LINE + FATIGUE)
    dd = _record(sc, 20.0)
    life = dd.fatigue()["fatigue_life"]
    # the station without bending has no damage: life inf, utilisation 0
    assert math.isinf(life[0])
    u = dd.envelope()["fatigue_utilisation"]
    np.testing.assert_allclose(u[1:], 10.0 * 20.0 / life[1:], rtol=1e-15)
    assert u[0] == 0.0
    st = dd.statistics()
    k = int(np.argmax(u))
    assert k == 4                                    # the largest bending
    assert st["dynamic_max_fatigue_utilisation"] == u[k]
    assert st["dynamic_max_fatigue_utilisation_s"] == 4.0
    assert st["dynamic_fatigue_verdict"] == ("pass" if u[k] <= 1.0 else "fail")
    assert st["design_life"] == 20.0 and st["design_fatigue_factor"] == 10.0
    # a design life just above / below the one the worst life allows flips the verdict
    allowed = life[k] / 10.0
    assert _record(sc, 0.99 * allowed).statistics()["dynamic_fatigue_verdict"] == "pass"
    assert _record(sc, 1.01 * allowed).statistics()["dynamic_fatigue_verdict"] == "fail"
    # without a design life: the damage and the life as before, no verdict
    plain = _record(sc, None)
    assert plain.verdict() is None
    assert "fatigue_utilisation" not in plain.envelope()
    assert not any("fatigue_utilisation" in k or "verdict" in k or k == "design_life"
                   for k in plain.statistics())
    np.testing.assert_array_equal(plain.fatigue()["fatigue_life"], life)


def test_a_vfife_run_states_the_verdict_in_its_summary_and_envelope():
    # the registry hands the design checks to the VFIFE's recorder (~1 s)
    from verification.methods import method
    from verification.report.dynamics import summary_lines
    res = method("vfife").solve(parse_scene(LINE + FATIGUE + DYNAMICS),
                                element_length=2.0).require()
    env, sm = res.dynamics.envelope, res.summary()
    life = np.asarray(env["fatigue_life"])
    np.testing.assert_allclose(env["fatigue_utilisation"], 200.0 / life, rtol=1e-14)
    # the worst station is the least life's, where the record's damage is largest
    assert sm["dynamic_max_fatigue_utilisation_s"] == sm["dynamic_min_fatigue_life_s"]
    assert sm["dynamic_max_fatigue_utilisation"] == pytest.approx(
        200.0 / sm["dynamic_min_fatigue_life"], rel=1e-14)
    # a fraction of a year's life in this 6 s record of 0.5 m heave: fails 200 years
    assert sm["dynamic_min_fatigue_life"] < 200.0 and sm["dynamic_fatigue_verdict"] == "fail"
    assert (sm["design_life"], sm["design_fatigue_factor"]) == (20.0, 10.0)
    line = [x for x in summary_lines(sm) if "fatigue verdict" in x]
    assert line == [f"    {fatigue_verdict_line(sm, 'dynamic_')} (the window repeated)"]
    assert line[0].startswith(f"    fatigue verdict: FAIL at s = "
                              f"{sm['dynamic_max_fatigue_utilisation_s']:.1f} m: life ")


# ------------------------------------------------------------------ riser-verify fatigue
def _scene(design_life=20.0, dff=10.0):
    sc = resolve("scr-steel-fatigue")
    d = sc.design
    return sc.replace(design=d.replace(design_life=design_life, fatigue=d.fatigue.replace(
        design_fatigue_factor=dff)))


def _scatter(scene) -> ScatterFatigue:
    """scr-steel-fatigue's three sea states with stand-in damage rates: a touchdown peak
    at s = 540 m, the ANCF's 0.98 of the VFIFE's, the FD's 3x and more; the VFIFE's peak
    damage per year 1 / 0.72 (a life of 0.72 years: the issue's)."""
    s = np.linspace(0.0, 2000.0, 401)
    cmp = SimpleNamespace(vfife_result=SimpleNamespace(info={
        "dynamic_max_utilisation": 0.3, "dynamic_max_utilisation_s": 1990.0,
        "dynamic_max_touchdown_s": 560.0, "dynamic_min_touchdown_s": 520.0}),
        ramp_s=80.0, settle_s=60.0, element_length=2.0, fd_wall_s=1.0, vfife_wall_s=9.0,
        fd=SimpleNamespace(std={"tension": np.array([1.0, 2.0])}), vf={"std": 2.1})
    # each sea state the same shape, its probability-weighted sum a peak of 1 / 0.72 a year
    shape = np.exp(-((s - 540.0) / 40.0) ** 2) + 1e-6
    rate = shape / 0.72 / SECONDS_PER_YEAR / (1.0 + 1e-6)
    states = []
    for hs, tp, p in ((1.5, 8.0, 0.6), (3.0, 10.0, 0.3), (5.0, 12.0, 0.1)):
        rates = {e: rate * k for e, k in zip(ESTIMATES, (1.0, 3.0, 3.2, 3.5))}
        rates[ANCF] = rate * 0.98
        states.append(SeaStateFatigue(hs, tp, p, s, rates, 300.0, cmp, 10.0, 500.0, 20.0,
                                      {"element_length": 2.0, "time_step": 0.02,
                                       "touchdown_range_m": 38.0}))
    per_year = {e: sum(st.probability * st.rates[e] for st in states) * SECONDS_PER_YEAR
                for e in (*ESTIMATES, ANCF)}
    return ScatterFatigue(scene, states, s, per_year, 2.0)


@pytest.fixture
def no_figures(monkeypatch):
    monkeypatch.setattr(fatigue_report, "fd_utilisation", lambda cmp, d: (0.25, 1990.0))
    monkeypatch.setattr(fatigue_report, "_plot", lambda res, path: None)   # 3 s of figure


def test_the_fatigue_files_carry_the_verdict(tmp_path, no_figures):
    res = _scatter(_scene())
    ver = verdicts(res)
    assert list(ver) == list(res.estimates)
    # the VFIFE's least life is 0.72 years at s = 540 m: 200 / 0.72 = 277.78, fail
    v = ver[DESIGN_ESTIMATE]
    assert v["worst_life"] == pytest.approx(0.72, rel=1e-12)
    assert v["max_fatigue_utilisation"] == pytest.approx(277.78, abs=0.005)
    assert v["max_fatigue_utilisation_s"] == 540.0 and v["fatigue_verdict"] == "fail"
    head = fatigue_report.write(res, tmp_path)
    sm = fatigue_report.write_summary(res, head, tmp_path)
    assert json.loads((tmp_path / "summary.json").read_text()) == sm
    assert sm["design_life"] == 20.0 and sm["design_fatigue_factor"] == 10.0
    assert sm["required_life"] == 200.0 and sm["fatigue_estimate"] == "rainflow_vfife"
    assert sm["max_fatigue_utilisation"] == v["max_fatigue_utilisation"]
    assert sm["max_fatigue_utilisation_s"] == 540.0 and sm["fatigue_verdict"] == "fail"
    assert sm["min_fatigue_life"] == pytest.approx(0.72, rel=1e-12)
    # every estimate beside it: the ANCF's 1 / 0.98 longer life, the FD's 3x shorter
    assert sm["estimates"][ANCF]["max_fatigue_utilisation"] == pytest.approx(
        0.98 * 200.0 / 0.72, rel=1e-12)
    assert sm["estimates"]["rainflow_fd"]["max_fatigue_utilisation"] == pytest.approx(
        3.0 * 200.0 / 0.72, rel=1e-12)
    along = pd.read_csv(tmp_path / "fatigue_along_s.csv")
    assert (along["required_life_years"] == 200.0).all()
    for e in res.estimates:
        np.testing.assert_allclose(along[f"{e}_fatigue_utilisation"],
                                   200.0 / along[f"{e}_life_years"], rtol=1e-9)
        assert along[f"{e}_fatigue_pass"].dtype == bool
        assert (along[f"{e}_fatigue_pass"] == (along[f"{e}_fatigue_utilisation"]
                                               <= 1.0)).all()
    text = (tmp_path / "report.md").read_text()
    assert "## Fatigue verdict" in text and "**Verdict: fail**" in text
    assert "at s = 540.0 m the life 0.72 years < the required 200 years" in text
    lines = fatigue_report.console_lines(res, head)
    assert lines[0] == ("fatigue verdict: FAIL at s = 540.0 m: life 0.72 years < DFF 10 x "
                        "design life 20 years = 200 years (fatigue utilisation 278) [VFIFE "
                        "time domain, rainflow: the design's estimate]")
    # a design life the life reaches (0.72 / 10 x 0.99 years): pass
    res = _scatter(_scene(design_life=0.99 * 0.072))
    assert verdicts(res)[DESIGN_ESTIMATE]["fatigue_verdict"] == "pass"


def test_without_a_design_life_no_verdict_said_once(tmp_path, no_figures):
    res = _scatter(_scene(design_life=None))
    assert verdicts(res) is None
    head = fatigue_report.write(res, tmp_path)
    sm = fatigue_report.write_summary(res, head, tmp_path)
    for key in ("design_life", "max_fatigue_utilisation", "max_fatigue_utilisation_s",
                "fatigue_verdict", "required_life"):
        assert sm[key] is None, key
    assert sm["design_fatigue_factor"] == 10.0
    assert sm["estimates"][DESIGN_ESTIMATE]["min_fatigue_life"] == pytest.approx(0.72)
    along = pd.read_csv(tmp_path / "fatigue_along_s.csv")
    assert not any("utilisation" in c or "pass" in c or "required" in c for c in along)
    assert fatigue_report.console_lines(res, head) == [
        "no design_life: no fatigue verdict ([design] design_life [years], with "
        "[design.fatigue] design_fatigue_factor, gives one)"]
    text = (tmp_path / "report.md").read_text()
    assert text.count("no fatigue verdict") == 1
    assert "## Fatigue verdict\n\nNo `design_life`: no fatigue verdict" in text


def test_the_fatigue_command_prints_the_verdict_and_writes_summary_json(
        tmp_path, run_cli, monkeypatch, no_figures):
    # the command on a scene file with a design life, the scatter diagram's runs
    # replaced by the stand-ins (the real ones take half an hour)
    data = tomllib.loads((ROOT / "verification/scenes/design/scr-steel-fatigue.toml")
                         .read_text())
    data["design"]["design_life"] = 20.0
    data["design"]["fatigue"]["design_fatigue_factor"] = 10.0
    path = tmp_path / "scr-steel-fatigue.toml"
    path.write_text(dumps(data))
    monkeypatch.setattr(fatigue_scatter, "run_scatter",
                        lambda scene, h=None, progress=None, ancf=True, **engine: _scatter(scene))
    code, out, err = run_cli(["fatigue", str(path), "--out", str(tmp_path / "o"), "-q"])
    assert code == 0, err
    assert ("  fatigue verdict: FAIL at s = 540.0 m: life 0.72 years < DFF 10 x design life "
            "20 years = 200 years (fatigue utilisation 278)") in out
    sm = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert sm["fatigue_verdict"] == "fail" and sm["max_fatigue_utilisation_s"] == 540.0
    # the named result (issue 48.2): printed, in summary.json; exit 0 without --strict
    assert out.splitlines()[-1].startswith("  design_fails: fatigue on scr-steel-fatigue: "
                                           "fatigue: fatigue utilisation")
    assert "summary.json" in out.splitlines()[-2]
    assert sm["design_fails"] == [out.splitlines()[-1].split(
        "fatigue on scr-steel-fatigue: ", 1)[1]]
    code, out, err = run_cli(["fatigue", str(path), "--out", str(tmp_path / "s"), "-q",
                              "--strict"])
    assert code == 1 and "1 design check(s) fail and --strict" in err

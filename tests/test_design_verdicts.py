"""Issue 48 (2): a failed design check is a named result (``design_fails``), printed
always, and with ``--strict`` exit 1 in ``solve``, ``compare`` and ``sweep`` (``fatigue``:
tests/test_fatigue_verdict.py).

The failing scene is scr-steel-design at a design pressure of 160 MPa instead of 20 MPa:
at the hang-off the net internal pressure, 160 MPa, is twice the burst resistance over
the factors, p_b / (gamma_m gamma_SC) = 2 t / (D - t) x f_cb x 2 / sqrt(3) / (1.15 x
1.14) = 0.2075 x 430 MPa x 1.1547 / 1.311 = 78.6 MPa (f_cb = alpha_u SMYS = 0.96 x 448
MPa), so the line fails DNV's check whatever its tension and moment add (the code gives
2.45); at 20 MPa it passes with a wide margin (0.12). The verdict does not hang on a
rounding either way.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from riser.design.verdicts import checks_made, design_failures, with_verdicts
from verification.cli import main

ROOT = Path(__file__).resolve().parents[1]
DESIGN = ROOT / "verification" / "scenes" / "design" / "scr-steel-design.toml"


def _burst_scene(folder: Path) -> Path:
    text = DESIGN.read_text()
    assert "internal_pressure = 2.0e7" in text
    f = folder / "burst.toml"
    f.write_text(text.replace("internal_pressure = 2.0e7", "internal_pressure = 1.6e8"))
    return f


# ----------------------------------------------------------------- the verdicts by hand
def test_no_check_made_is_no_verdict():
    assert checks_made({"max_tension": 1.0}) == ()
    assert "design_fails" not in with_verdicts({"max_tension": 1.0})


def test_each_check_fails_above_one_and_passes_at_one():
    sm = {"design_code": "dnv-st-f201", "max_utilisation": 1.0, "max_utilisation_s": 12.0,
          "dynamic_max_utilisation": 1.0000001, "dynamic_max_utilisation_s": 5.0,
          "dynamic_max_utilisation_time": 42.0,
          "fatigue_verdict": "pass", "dynamic_fatigue_verdict": "fail",
          "dynamic_max_fatigue_utilisation": 277.78, "dynamic_max_fatigue_utilisation_s": 512.3,
          "max_bend_utilisation": 0.5, "dynamic_max_bend_utilisation": 1.2}
    assert checks_made(sm) == ("code_check", "fatigue", "bend_limit")
    fails = design_failures(sm)
    # a utilisation of exactly 1 passes (the codes' criteria are <= 1)
    assert [f.split(":")[0] for f in fails] == ["code_check", "fatigue", "bend_limit"]
    assert "at s = 5.0 m, t = 42 s" in fails[0] and "dynamic" in fails[0]
    assert "277.8" in fails[1] and "at s = 512.3 m" in fails[1]
    assert "1.2 > 1" in fails[2]
    assert with_verdicts(dict(sm))["design_fails"] == fails


def test_a_nan_or_missing_value_is_not_a_check():
    # a NaN utilisation (a station the check cannot judge) is no verdict, not a pass
    assert checks_made({"max_utilisation": float("nan")}) == ()
    assert design_failures({"max_utilisation": float("nan")}) == []


# ----------------------------------------------------------------- the commands
def test_solve_prints_the_failed_check_and_strict_fails_the_run(tmp_path, capsys):
    scene = _burst_scene(tmp_path)
    code = main(["solve", str(scene), "--out", str(tmp_path / "a"), "-q"])
    out = capsys.readouterr().out
    assert code == 0 and "design_fails: bvp on scr-steel-design: code_check: utilisation" in out
    sm = json.loads((tmp_path / "a" / "summary.json").read_text())
    assert sm["max_utilisation"] > 2.0 and sm["design_fails"][0].startswith("code_check")
    code = main(["solve", str(scene), "--out", str(tmp_path / "b"), "-q", "--strict"])
    cap = capsys.readouterr()
    assert code == 1 and "design check(s) fail and --strict" in cap.err
    # the passing scene: the checks said to pass, exit 0 with --strict
    code = main(["solve", str(DESIGN), "--out", str(tmp_path / "c"), "-q", "--strict"])
    out = capsys.readouterr().out
    assert code == 0 and "design checks pass: bvp on scr-steel-design: code_check" in out
    assert json.loads((tmp_path / "c" / "summary.json").read_text())["design_fails"] == []


@pytest.mark.slow          # two cases and the sweep's figures: ~7 s
def test_sweep_counts_the_failing_cases_and_strict_fails_it(tmp_path, capsys):
    f = tmp_path / "sw.toml"
    f.write_text('base = "scr-steel-design"\nmethods = ["bvp"]\n[[vary]]\n'
                 'key = "design.internal_pressure"\nvalues = [2.0e7, 1.6e8]\n')
    code = main(["sweep", str(f), "--out", str(tmp_path / "o"), "--jobs", "1", "-q"])
    out = capsys.readouterr().out
    assert code == 0 and "design checks: 1 case(s) fail" in out
    assert "design_fails: case 1 bvp: code_check" in out
    env = (tmp_path / "o" / "envelopes.csv").read_text().splitlines()
    assert env[0].endswith("utilisation_max,utilisation_max_case")
    assert (tmp_path / "o" / "range_utilisation.png").exists()
    report = (tmp_path / "o" / "report.md").read_text()
    assert "## Design checks" in report and "1 case(s) fail a design check" in report
    code = main(["sweep", str(f), "--out", str(tmp_path / "o"), "--jobs", "1", "-q",
                 "--strict"])                       # resumed: the verdicts from case.json
    cap = capsys.readouterr()
    assert code == 1 and "fail a design check and --strict" in cap.err


@pytest.mark.slow
def test_compare_strict_fails_on_a_failed_code_check(tmp_path, capsys):
    scene = _burst_scene(tmp_path)
    code = main(["compare", str(scene), "--out", str(tmp_path / "c"), "-q",
                 "--no-paper-model"])
    out = capsys.readouterr().out
    assert code == 0 and "design_fails: vfife on scr-steel-design: code_check" in out
    code = main(["compare", str(scene), "--out", str(tmp_path / "d"), "-q",
                 "--no-paper-model", "--strict"])
    assert code == 1


def test_a_bend_limit_fails_the_run_with_strict(tmp_path, capsys):
    # scr-steel's touchdown bends to R = 604.9 m (its curvature column): an MBR of 1000 m
    # is a bend utilisation 1000 / 604.9 = 1.653 there, above 1
    text = (ROOT / "verification" / "scenes" / "scr-steel.toml").read_text()
    assert "[line_types.steel]\n" in text
    f = tmp_path / "mbr.toml"
    f.write_text(text.replace("[line_types.steel]\n", "[line_types.steel]\n"
                              "minimum_bend_radius = 1000.0\n"))
    code = main(["solve", str(f), "--out", str(tmp_path / "o"), "-q", "--strict"])
    out = capsys.readouterr().out
    sm = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert sm["max_bend_utilisation"] == pytest.approx(1.6531, abs=1e-4)
    assert code == 1
    assert sm["design_fails"] == [out.split("design_fails: bvp on scr-steel: ", 1)[1]
                                  .splitlines()[0]]
    assert sm["design_fails"][0].startswith("bend_limit: curvature utilisation 1.653 > 1")

"""A scatter diagram's fatigue as units of work (issue 49,
verification/studies/design/fatigue_scatter.py): the cells' seeds, the screening, how the
totals are formed, and the runner's resume and interrupt on stand-in units in this
process (the real units on every engine, bit for bit: tests/test_fatigue_engines.py,
slow).

The stand-in unit returns, for a cell (Hs, Tp) and a realisation's seed, damage rates of
a touchdown peak at s = 540 m growing as Hs^3, the record estimates scaled by a factor of
the seed (so that the realisations differ and the order of their sum shows), the FD's 3
to 3.5 times the VFIFE's: every figure below follows from it by hand.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from riser.design.fatigue import SECONDS_PER_YEAR
from riser.errors import SolveFailed
from verification.catalog import resolve
from verification.runtime.engine import Engine
from verification.runtime.units import Interrupted, makespan
from verification.studies.design import fatigue_report, fatigue_scatter
from verification.studies.design.fatigue import ANCF, ancf_agreement, damage_per_year
from verification.studies.design.fatigue_scatter import (cell_seed, realisations, screen,
                                                          seeds)

S = np.linspace(0.0, 2000.0, 201)


def _scene(record_length=None, cells=((1.5, 8.0, 0.6), (3.0, 10.0, 0.3), (5.0, 12.0, 0.1))):
    from riser.design.part import SeaState
    sc = resolve("scr-steel-fatigue")
    f = sc.design.fatigue.replace(record_length=record_length, sea_states=tuple(
        SeaState(hs=h, tp=t, probability=p) for h, t, p in cells))
    return sc.replace(design=sc.design.replace(fatigue=f))


def _base(hs):
    return hs ** 3 * (1e-10 * np.exp(-((S - 540.0) / 40.0) ** 2) + 1e-13)


def _factor(seed):
    return 1.0 if seed is None else 1.0 + (seed % 97) / 200.0


def _fake(calls, fail=None, interrupt_at=None):
    """A stand-in for :func:`fatigue_scatter.run_unit` (see the module docstring)."""
    def unit(spec, progress=None):
        calls.append((spec["kind"], spec["cell"], spec.get("realisation")))
        if interrupt_at is not None and len(calls) == interrupt_at:
            raise KeyboardInterrupt
        rec = {"kind": spec["kind"], "cell": spec["cell"], "digest": spec["digest"],
               "realisation": spec.get("realisation"), "seed": spec.get("seed"),
               "wall_s": 1.0 + spec["cell"], "s": S.tolist(), "tdp_s": 500.0}
        if fail is not None and fail == (spec["kind"], spec["cell"]):
            return {**rec, "error": "SolveFailed: stand-in", "error_kind": "SolveFailed",
                    "message": "vfife in the sea diverged (stand-in)"}
        b = _base(spec["hs"])
        if spec["kind"] == "fd":
            rec.update(rates={"dirlik_fd": (3.2 * b).tolist(),
                              "narrow_band_fd": (3.5 * b).tolist()}, fd_wall_s=1.0,
                       element_length=2.0)
            return rec
        f = _factor(spec["seed"])
        rates = {"rainflow_vfife": (b * f).tolist(), "rainflow_fd": (3.0 * b * f).tolist()}
        if spec["ancf"]:
            rates[ANCF] = (0.98 * b * f).tolist()
            rec.update(ancf_wall_s=5.0, ancf_info={"element_length": 2.0, "time_step": 0.02,
                                                   "touchdown_range_m": 30.0})
        rec.update(rates=rates, record_s=100.0 + spec["cell"], figures={
            "info": {"dynamic_max_utilisation": 0.3, "dynamic_max_utilisation_s": 1990.0,
                     "dynamic_min_touchdown_s": 520.0, "dynamic_max_touchdown_s": 560.0},
            "ramp_s": 80.0, "settle_s": 60.0, "element_length": 2.0, "fd_wall_s": 1.0,
            "vfife_wall_s": 2.0, "fd_hang_off_tension_std": 1.0,
            "vfife_hang_off_tension_std": 1.1, "fd_max_utilisation": [0.25, 1990.0]})
        return rec
    return unit


@pytest.fixture
def stand_in(monkeypatch):
    calls = []
    monkeypatch.setattr(fatigue_scatter, "run_unit", _fake(calls))
    monkeypatch.setattr(fatigue_scatter, "realisations",
                        lambda scene, cell: 1 if scene.design.fatigue.record_length is None
                        else math.ceil(scene.design.fatigue.record_length / (10 * cell.tp)))
    return calls


# ------------------------------------------------------------------ seeds
def test_each_cell_has_its_own_seeds_from_the_cell_alone(monkeypatch):
    monkeypatch.setattr(fatigue_scatter, "realisations", lambda scene, cell: 3)
    sc = _scene(record_length=1000.0)
    mine = {(c.hs, c.tp): seeds(sc, c) for c in sc.design.fatigue.sea_states}
    flat = [x for v in mine.values() for x in v]
    assert len(set(flat)) == 9 and all(0 <= x < 2 ** 63 for x in flat)
    # the scatter diagram in another order, another probability: the same seeds per cell
    other = _scene(record_length=1000.0, cells=((5.0, 12.0, 0.2), (1.5, 8.0, 0.5),
                                                (3.0, 10.0, 0.3)))
    assert {(c.hs, c.tp): seeds(other, c) for c in other.design.fatigue.sea_states} == mine
    assert mine[(3.0, 10.0)][1] == cell_seed(1, 3.0, 10.0, 1)
    # the scene's seed enters; without record_length the scene's own seed (no list)
    assert cell_seed(2, 3.0, 10.0, 1) != cell_seed(1, 3.0, 10.0, 1)
    assert seeds(_scene(), _scene().design.fatigue.sea_states[0]) == ()


def test_realisations_cover_the_record_length():
    sc = _scene(record_length=700.0)
    cell = sc.design.fatigue.sea_states[1]               # Tp 10 s: 100 comps, 333.3 s
    assert realisations(sc, cell) == 3
    assert realisations(_scene(record_length=666.0), cell) == 2
    assert realisations(_scene(), cell) == 1


# ------------------------------------------------------------------ screening, totals
def _states(ran):
    """Stand-in states: the FD's everywhere, the record estimates on the cells ``ran``."""
    from verification.studies.design.fatigue import SeaStateFatigue
    out = []
    for k, (hs, p) in enumerate(((1.0, 0.5), (2.0, 0.3), (3.0, 0.15), (4.0, 0.05))):
        b = _base(hs)
        rates = {"dirlik_fd": 3.0 * b, "narrow_band_fd": 3.5 * b}
        if k in ran:                                    # ratios that vary along s
            rates["rainflow_vfife"] = b * (0.3 + 0.1 * k) * (1.0 + 0.2 * k * S / 2000.0)
        out.append(SeaStateFatigue(hs, 10.0, p, S, rates, 100.0, None, 1.0, 500.0))
    return out


def test_the_screening_takes_the_cells_carrying_the_share_at_each_station():
    states = _states(range(4))
    # at the touchdown the FD's shares go as p Hs^3: 0.5, 2.4, 4.05, 3.2 (/10.15)
    scr = screen(states, 0.90, None)
    w = np.array([0.5, 2.4, 4.05, 3.2]) / 10.15
    assert scr["stations"]["touchdown"] == 540.0 and scr["stations"]["hang_off"] == 2000.0
    assert scr["shares"]["touchdown"] == pytest.approx(list(w), rel=1e-12)
    assert scr["cells"] == [1, 2, 3]                   # 0.399 + 0.315 + 0.236 >= 0.9
    assert screen(states, 0.5, None)["cells"] == [2, 3]
    assert screen(states, None, None)["cells"] == [0, 1, 2, 3]
    assert screen(states, 0.9, 1)["ancf_cells"] == [2]  # the largest touchdown share
    assert screen(states, 0.9, 1, ancf=False)["ancf_cells"] == []


def test_a_cell_left_out_counts_its_fd_damage_scaled_by_the_run_cells_ratio():
    states = _states([1, 2])
    per, how = damage_per_year(states, S, ["rainflow_vfife", "dirlik_fd"])
    y = SECONDS_PER_YEAR
    mine = sum(states[k].probability * states[k].rates["rainflow_vfife"] for k in (1, 2))
    ref = sum(states[k].probability * states[k].rates["dirlik_fd"] for k in (1, 2))
    rest = sum(states[k].probability * states[k].rates["dirlik_fd"] for k in (0, 3))
    np.testing.assert_allclose(per["rainflow_vfife"], (mine + mine / ref * rest) * y,
                               rtol=1e-12)
    np.testing.assert_allclose(how["rainflow_vfife"]["fd_as_is"], (mine + rest) * y,
                               rtol=1e-12)
    assert how["rainflow_vfife"]["run"] == [1, 2] and how["rainflow_vfife"]["rest"] == [0, 3]
    # every cell run: the plain sum, exactly the old expression
    full = damage_per_year(states, S, ["dirlik_fd"])[0]["dirlik_fd"]
    assert np.array_equal(full, sum(st.probability * np.interp(S, st.s, st.rates["dirlik_fd"])
                                    for st in states) * y)


# ------------------------------------------------------------------ the runner
def _run(out, share=None, ancf_cells=None, record_length=None, h=None):
    return fatigue_scatter.run_scatter(_scene(record_length), h, engine=Engine(1), out=out,
                                       share=share, ancf_cells=ancf_cells)


def test_the_runner_screens_resumes_and_forms_the_totals(tmp_path, stand_in):
    res = _run(tmp_path, share=0.9, ancf_cells=1, record_length=150.0)
    # 3 FD units; the FD's touchdown shares 0.6x1.5^3 : 0.3x27 : 0.1x125 -> cells 2, 3 carry
    # 90 %; realisations ceil(150 / 10 Tp): 2 and 2; the ANCF on cell 3's first
    assert sorted(c for c in stand_in if c[0] == "fd") == [("fd", k, None) for k in range(3)]
    assert sorted(c for c in stand_in if c[0] == "td") == [("td", 1, 0), ("td", 1, 1),
                                                           ("td", 2, 0), ("td", 2, 1)]
    assert res.screening["cells"] == [1, 2] and res.screening["ancf_cells"] == [2]
    st = res.states[1]
    f = [_factor(x) for x in st.seeds]
    np.testing.assert_allclose(st.rates["rainflow_vfife"], _base(3.0) * (f[0] + f[1]) / 2,
                               rtol=1e-12)
    np.testing.assert_allclose(st.half_rates["rainflow_vfife"], _base(3.0) * f[0], rtol=1e-12)
    assert "rainflow_vfife" not in res.states[0].rates and res.states[0].comparison is None
    # the ANCF on cell 3's first realisation, judged against the VFIFE's same one
    agr = ancf_agreement(res)
    assert [r["cell"] for r in agr["rows"]] == [2] and agr["total"]["ratio"] == pytest.approx(0.98)
    # a rerun into the folder runs nothing and gives the same damage, bit for bit
    before = len(stand_in)
    again = _run(tmp_path, share=0.9, ancf_cells=1, record_length=150.0)
    assert len(stand_in) == before
    for e in res.per_year:
        assert np.array_equal(res.per_year[e], again.per_year[e]), e
    # another element length: every unit's inputs changed, every unit runs again
    _run(tmp_path, share=0.9, ancf_cells=1, record_length=150.0, h=3.0)
    assert len(stand_in) == 2 * before


def test_an_interrupted_run_resumes_to_the_same_damage(tmp_path, monkeypatch, stand_in):
    whole = _run(tmp_path / "whole", share=None, record_length=150.0)
    calls = []
    monkeypatch.setattr(fatigue_scatter, "run_unit", _fake(calls, interrupt_at=5))
    with pytest.raises(Interrupted) as got:
        _run(tmp_path / "cut", share=None, record_length=150.0)
    assert (got.value.finished, got.value.total) == (4, 9)      # 3 FD + 6 realisations
    assert len(list((tmp_path / "cut" / "cells").glob("*/*.json"))) == 4
    monkeypatch.setattr(fatigue_scatter, "run_unit", _fake(calls))
    resumed = _run(tmp_path / "cut", share=None, record_length=150.0)
    assert len(calls) == 5 + 5                     # the 5th again, and the 4 left
    for e in whole.per_year:
        assert np.array_equal(whole.per_year[e], resumed.per_year[e]), e


def test_a_failed_unit_is_said_after_the_others_ran_and_rerun_next_time(tmp_path,
                                                                         monkeypatch):
    calls = []
    monkeypatch.setattr(fatigue_scatter, "run_unit", _fake(calls, fail=("td", 1)))
    with pytest.raises(SolveFailed, match=r"1 of 6 unit\(s\) failed; the first: cell 2 "
                       r"\(Hs 3 m, Tp 10 s\) td: vfife in the sea diverged"):
        fatigue_scatter.run_scatter(_scene(), None, engine=Engine(1), out=tmp_path)
    assert len(calls) == 6                         # every unit ran
    monkeypatch.setattr(fatigue_scatter, "run_unit", _fake(calls))
    fatigue_scatter.run_scatter(_scene(), None, engine=Engine(1), out=tmp_path)
    assert calls[6:] == [("td", 1, 0)]             # only the failed one again


def test_the_report_says_which_cells_each_method_ran(tmp_path, monkeypatch, stand_in):
    monkeypatch.setattr(fatigue_report, "_plot", lambda res, path: None)
    res = _run(tmp_path, share=0.9, ancf_cells=1, record_length=150.0)
    head = fatigue_report.write(res, tmp_path)
    sm = fatigue_report.write_summary(res, head, tmp_path)
    text = (tmp_path / "report.md").read_text()
    assert "## Cells and methods" in text and "## Record length" in text
    assert "2 cells ran in the time domains" in text and "the ANCF on 1 of them" in text
    assert "| 1 | 1.5 | 8 | 0.6 |" in text and "| fd | - | - | - | - | - |" in text
    assert sm["cells_time_domain"] == 2 and sm["cells_ancf"] == 1 and sm["screen_share"] == 0.9
    conv = sm["record_length_convergence"]["rainflow_vfife"]["touchdown"]
    assert conv["ratio"] == pytest.approx(conv["half"] / conv["whole"])
    lines = fatigue_report.run_lines(res)
    assert lines[1].startswith("cells: 3 by the frequency domain, 2 by the VFIFE")


# ------------------------------------------------------------------ the command line
def test_the_options_are_checked_before_anything_runs(run_cli, tmp_path):
    code, _, err = run_cli(["fatigue", "scr-steel-fatigue", "--jobs", "2", "--scheduler",
                            "tcp://127.0.0.1:1", "--out", str(tmp_path / "a")])
    assert code == 2 and "--jobs: give --jobs (local workers) or --scheduler" in err
    code, _, err = run_cli(["fatigue", "scr-steel-fatigue", "--share", "0", "--out",
                            str(tmp_path / "b")])
    assert code == 2 and "--share: must be > 0 and <= 1" in err
    from verification.cli.design import DEFAULT_SHARE
    assert DEFAULT_SHARE == fatigue_scatter.DEFAULT_SHARE


def test_the_estimate_of_unequal_units_is_their_schedule():
    assert makespan([3.0, 1.0, 1.0, 1.0], 2) == 3.0
    assert makespan([1.0] * 5, 2) == 3.0          # equal units: ceil(n / w) rounds


# ------------------------------------------------------------------ the realistic diagram
def _haver_nyhus(hs_edges, tp_edges) -> np.ndarray:
    """The probabilities of the bins of the joint model of Haver and Nyhus (1986),
    northern North Sea (WAFO's pdfseastate's parameters): Hs lognormal (mean 0.836 and
    variance 0.376 of ln Hs) up to 3.27 m, Weibull (scale 2.82 m, shape 1.547) above; ln Tp
    given Hs normal, mean 1.59 + 0.42 ln(Hs + 2), variance 0.005 + 0.09 exp(-0.13
    Hs^1.34). Gauss-Legendre in Hs (the switch a node's edge), the lognormal's CDF in Tp."""
    from scipy.special import erf
    x, w = np.polynomial.legendre.leggauss(64)
    out = np.zeros((len(hs_edges) - 1, len(tp_edges) - 1))
    for i, (lo, hi) in enumerate(zip(hs_edges[:-1], hs_edges[1:])):
        for a, b in ([(lo, hi)] if not lo < 3.27 < hi else [(lo, 3.27), (3.27, hi)]):
            h = 0.5 * (b - a) * x + 0.5 * (b + a)
            f = np.where(h <= 3.27,
                         np.exp(-(np.log(h) - 0.836) ** 2 / 0.752)
                         / np.sqrt(2 * np.pi * 0.376) / h,
                         1.547 / 2.82 * (h / 2.82) ** 0.547 * np.exp(-(h / 2.82) ** 1.547))
            m = 1.59 + 0.42 * np.log(h + 2.0)
            v = 0.005 + 0.09 * np.exp(-0.13 * h ** 1.34)
            cdf = [0.5 * (1 + erf((np.log(t) - m) / np.sqrt(2 * v))) for t in tp_edges]
            for j in range(len(tp_edges) - 1):
                out[i, j] += np.sum(f * 0.5 * (b - a) * w * (cdf[j + 1] - cdf[j]))
    return out


def test_the_realistic_diagram_is_the_published_model_discretised():
    sc = resolve("scr-steel-fatigue-scatter")
    he, te = np.arange(0.0, 11.0, 1.0), np.arange(2.0, 22.0, 2.0)
    p = _haver_nyhus(he, te)
    assert p.sum() == pytest.approx(0.998, abs=1e-3)     # the model's mass up to 10 m, 20 s
    steep = math.sqrt(2 * math.pi * 15 / 9.81)
    want = [(0.5 * (he[i] + he[i + 1]), 0.5 * (te[j] + te[j + 1]), p[i, j])
            for i in range(p.shape[0]) for j in range(p.shape[1])
            if (p[i, j] >= 0.0025 or (he[i] >= 8.0 and p[i, j] >= 0.0005))
            and 0.5 * (te[j] + te[j + 1]) / math.sqrt(0.5 * (he[i] + he[i + 1])) >= steep]
    kept = sum(c[2] for c in want)
    got = sc.design.fatigue.sea_states
    assert len(got) == len(want) == 43 and kept == pytest.approx(0.977, abs=1e-3)
    for cell, (hs, tp, q) in zip(got, want):
        assert (cell.hs, cell.tp) == (hs, tp)
        assert cell.probability == pytest.approx(q / kept, abs=1e-6)
    assert sc.design.fatigue.record_length == 300.0 and sc.waves.spectrum.components == 50

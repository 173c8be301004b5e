"""The typed comparison row (verification/comparison/row.py): each method's value under
its own name, a three-state verdict, frozen, and read as the files' columns."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from riser.results.profile import Profile
from verification.comparison.row import Row, Tolerance, Verdict
from verification.comparison.static.agreement import AGREEMENT_COLUMNS, agreement


def arc(radius: float, n: int) -> Profile:
    """A quarter circle of ``radius`` [m] as a profile (s the arc length)."""
    t = np.linspace(0.0, np.pi / 2, n)
    s = radius * t
    one = np.ones_like(s)
    return Profile(s=s, x=radius * np.cos(t), y=radius * np.sin(t), z=0 * s, theta=t,
                   tension=1000.0 * one + s, moment=10.0 * np.sin(2 * t), shear=one,
                   curvature=one / radius)


def test_a_further_column_carries_its_value_under_its_own_name():
    # the analytic method's rows against the BVP: its value is under "analytic"; no row
    # of it answers "vfife" (the key the analytic and MoorDyn values once travelled under)
    p, q = arc(100.0, 400), arc(100.0, 400)
    q = q.replace(tension=q.tension * 1.01)                 # +1 % everywhere
    rows = agreement(p, q, depth=100.0, names=("bvp", "analytic"))
    top = next(r for r in rows if r.quantity == "hang_off_tension")
    assert top.methods == ("bvp", "analytic")
    # the exact difference: 1 % of the hang-off tension 1000 + 100 pi / 2
    assert top.value("analytic") - top.value("bvp") == pytest.approx(
        0.01 * (1000.0 + 50.0 * np.pi), rel=1e-12)
    assert top.diff == pytest.approx(top.value("analytic") - top.value("bvp"), rel=1e-12)
    with pytest.raises(KeyError):
        top["vfife"]
    assert top.verdict is Verdict.FAIL and top["pass"] is False      # 1 % > 1e-4 of itself


def test_the_verdict_has_three_states_and_reads_as_the_pass_column():
    assert [Verdict.of(x) for x in (True, False, None)] == [
        Verdict.PASS, Verdict.FAIL, Verdict.NOT_JUDGED]
    assert [v.passed for v in Verdict] == [True, False, None]
    # a moment the elements cannot resolve: shown, not judged, its reason in the note
    p = arc(100.0, 400)
    rows = agreement(p, p.replace(moment=p.moment * 3.0), depth=100.0,
                     moment_reason="not judged: bending length below the element")
    m = next(r for r in rows if r.quantity == "moment")
    assert m.verdict is Verdict.NOT_JUDGED and m["pass"] is None
    assert m.note.startswith("not judged") and m["reason"] == m.note
    assert m.tolerance.value > 0 and m.tolerance.reason        # still shown with its bound


def test_a_row_is_frozen_and_its_record_is_the_csv_columns():
    p = arc(100.0, 400)
    row = agreement(p, p, depth=100.0)[0]
    with pytest.raises(dataclasses.FrozenInstanceError):
        row.verdict = Verdict.FAIL
    rec = row.record(AGREEMENT_COLUMNS)
    assert list(rec) == list(AGREEMENT_COLUMNS)
    assert rec["abs_diff"] == abs(row.diff) and rec["pass"] is row.passed
    assert rec["tolerance"] == row.tolerance.value


def test_every_static_tolerance_has_its_reason():
    p = arc(100.0, 400)
    rows = agreement(p, p.replace(x=p.x + 0.01), depth=100.0)
    assert rows and all(r.tolerance is not None and r.tolerance.reason for r in rows)


def test_a_relative_bound_reads_as_the_dynamic_files_columns():
    r = Row("hang_off_tension_amplitude", {"fd": 100.0, "vfife": 100.3}, "", None, 0.003,
            Tolerance(0.005, None, "of the FD amplitude", "", "the issue's bound",
                      relative=True), Verdict.PASS, at_s=12.5)
    assert (r["fd"], r["vfife"], r["s"], r["basis"], r["tolerance"], r["pass"]) == (
        100.0, 100.3, 12.5, "of the FD amplitude", 0.005, True)
    assert r["reason"] == "the issue's bound"
    assert r.judged(None, "above the smallest amplitude")["reason"] == \
        "above the smallest amplitude"

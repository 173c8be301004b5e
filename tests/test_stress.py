"""Hard cases (fast subset): each method converges and passes its own checks, or stops
with a clear, classified reason; never a NaN, an exception or a violated equilibrium."""

from __future__ import annotations

import pytest

from verification import stress

FAST = [
    ("hard-flexible", "bvp", "converged"),             # bending length << 1 m: stiff BVP layer
    ("hard-flexible", "vfife", "converged"),
    ("hard-deep-scr", "bvp", "converged"),             # 3000 m deep, 4000 m long SCR
    ("hard-current-reversing", "bvp", "converged"),    # drag changes sign along the line
    ("hard-out-of-plane-current", "bvp", "refused"),   # planar method must say so
    ("hard-slack-touchdown", "bvp", "converged"),      # TDP tension ~3 % of the top
]


@pytest.mark.parametrize("name,method,expected", FAST, ids=[f"{n}-{m}" for n, m, _ in FAST])
def test_hard_case_outcome(name, method, expected):
    row, res = stress.run_one(name, method)
    assert row["outcome"] == expected, row["message"]
    if expected == "refused":
        assert "planar only" in row["message"]
    else:
        assert res.profile.is_finite()


def test_outcome_never_silent_on_bad_geometry(tmp_path):
    # a line that cannot reach the hang-off is rejected by the loader, a classified
    # failure rather than an exception
    bad = tmp_path / "short.toml"
    text = (stress.HARD_DIR / "hard-deep-scr.toml").read_text().replace(
        "length = 4000.0", "length = 3000.0")
    bad.write_text(text)
    row, _ = stress.run_one(str(bad), "bvp")
    assert row["outcome"] == "failed"
    assert "shorter than the distance" in row["message"]

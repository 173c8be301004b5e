"""Hard cases (fast subset): each method converges and passes its own checks, or stops
with a clear, classified reason; never a NaN, an exception or a violated equilibrium."""

from __future__ import annotations

import math

import pytest

import bvp
from riser.io.scene_file import load_scene
from verification.studies import stress

FAST = [
    ("hard-flexible", "bvp", "converged"),             # bending length << 1 m: stiff BVP layer
    ("hard-flexible", "vfife", "converged"),
    ("hard-deep-scr", "bvp", "converged"),             # 3000 m deep, 4000 m long SCR
    ("hard-current-reversing", "bvp", "converged"),    # drag changes sign along the line
    ("hard-out-of-plane-current", "bvp", "converged"),  # 3D: the BVP's 3D rod
    ("hard-slack-touchdown", "bvp", "converged"),      # TDP tension ~3 % of the top
]


# hard-flexible-bvp is slow (6 s): test_bvp.py::test_catenary_limit_touchdown_form covers a
# BVP bending layer far below 1 m (1 cm on 1000 m), in under 1 s
SLOW = {("hard-flexible", "bvp")}
CASES = [pytest.param(n, m, e, id=f"{n}-{m}", marks=[pytest.mark.slow] if (n, m) in SLOW else [])
         for n, m, e in FAST]


@pytest.mark.parametrize("name,method,expected", CASES)
def test_hard_case_outcome(name, method, expected):
    row, res = stress.run_one(name, method)
    assert row["outcome"] == expected, row["message"]
    assert res.profile.is_finite()
    if name == "hard-out-of-plane-current":       # 3D: pushed sideways, lateral columns
        assert res.summary()["max_lateral_offset"] > 10.0


def test_outcome_never_silent_on_bad_geometry(tmp_path):
    # a line 3000 m long between ends 3311 m apart: an inextensible line cannot reach the
    # hang-off and is rejected by the loader, a classified failure rather than an exception
    bad = tmp_path / "short.toml"
    text = (stress.HARD_DIR / "hard-deep-scr.toml").read_text().replace(
        "length = 4000.0", "length = 3000.0") + '\n[model]\naxial = "inextensible"\n'
    bad.write_text(text)
    row, _ = stress.run_one(str(bad), "bvp")
    assert row["outcome"] == "failed"
    assert "not longer than the distance" in row["message"]


def test_taut_steel_line_is_solved_with_a_strain_warning(tmp_path):
    # the same line, extensible (the default for fixed ends), is a taut line that stretches
    # 10 %: solved, but never silently: the strain T/EA = chord / L - 1 + O(w L / T) is
    # reported, far beyond a steel pipe's elastic range
    taut = tmp_path / "taut.toml"
    taut.write_text((stress.HARD_DIR / "hard-deep-scr.toml").read_text().replace(
        "length = 4000.0", "length = 3000.0"))
    res = bvp.solve(load_scene(taut))
    assert res.converged, res.message
    chord = math.hypot(1400.0, 3000.0)
    # weight adds w L sin / (2 EA) ~ 0.3 % of the strain on average: 2 % of it covers it
    assert res.info["max_strain"] == pytest.approx(chord / 3000.0 - 1.0, rel=2e-2)
    assert any(w.startswith("axial_strain: ") for w in res.warnings)

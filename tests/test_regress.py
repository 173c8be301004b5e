"""Stored summaries of every built-in scene (the hard cases excepted: see test_stress.py) (verification/regression/*.json), both methods.

The store is regenerated only by `riser-verify regress --update`; a change in any solver
output beyond the tolerances in verification/regress.py fails here, naming the scene,
the method and the quantity.
"""

from __future__ import annotations

import copy
import json

import pytest

from verification import regress
SCENES = sorted(regress.regression_scenes())


@pytest.mark.parametrize("name", SCENES)
def test_builtin_scene_matches_store(name):
    path = regress.STORE / f"{name}.json"
    assert path.exists(), f"no stored summary for {name}: run `riser-verify regress --update`"
    stored = json.loads(path.read_text())
    assert regress.diff(stored, regress.snapshot(name)) == []


def test_diff_names_scene_method_and_quantity():
    # negative control of the checker: a stored hang-off tension off by 0.1 % is reported
    stored = json.loads((regress.STORE / "wang2014-baseline.json").read_text())
    changed = copy.deepcopy(stored)
    changed["bvp"]["hang_off_tension"] *= 1.001
    lines = regress.diff(changed, stored)
    assert len(lines) == 1
    assert lines[0].startswith("wang2014-baseline: bvp.hang_off_tension:")

"""The dynamic response's targets (issue 31), recomputed: on scr-steel and yu2021-a3 under
heave and surge at the sweep's smallest amplitude (0.1 m) and the study's first period,
the VFIFE at 1 m elements against the frequency domain: first-harmonic hang-off tension
amplitude within 0.5 % and the moment amplitude along the line (outside the contact
zone) within 1 % of its peak. The scenes are the study's (``reproduce dynamics``: the sea
surface 20 m above the hang-off). Slow: ~3-4 min on 2 cores (four VFIFE runs of 300-500 s
of simulated time at 1 m elements)."""

from __future__ import annotations

import pytest

from verification.comparison.dynamic.protocol import compare_dynamics
from verification.studies.dynamics import PERIODS, SMALL, _with_motion, study_scene

pytestmark = pytest.mark.slow


@pytest.mark.parametrize("name", ["scr-steel", "yu2021-a3"])
@pytest.mark.parametrize("axis", ["y", "x"])
def test_issue_targets_at_the_smallest_amplitude(name, axis):
    period = PERIODS[name][0][0]
    comp = compare_dynamics(_with_motion(study_scene(name), axis, period, SMALL))
    rows = {r["quantity"]: r for r in comp.results[0].rows}
    # the issue's bounds (the protocol's own tolerances are the same numbers)
    assert abs(rows["hang_off_tension_amplitude"]["rel_diff"]) <= 0.005, rows
    assert abs(rows["moment_amplitude"]["rel_diff"]) <= 0.01, rows["moment_amplitude"]
    assert comp.passed, [r for r in rows.values() if r["pass"] is False]

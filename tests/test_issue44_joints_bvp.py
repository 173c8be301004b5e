"""Issue 44, "False verdicts": a flexible riser on a flex joint converges to a PASS at the
element length the resolution advice gives; the BVP solves a top-tensioned riser whose
pipe is as long as the hang-off height (the tensioner frees the top's height); the BVP
solves a chain whose clump weight lies on the seabed in seconds.

Units SI: lengths [m], forces [N], moments [N m]; s from the bottom end."""

from __future__ import annotations

import math
import time

import pytest

import bvp
import vfife
from verification import compare, resolve


def failing(comp):
    return [(r["quantity"], r["abs_diff"], r["tolerance"]) for r in comp.rows if not r["pass"]]


def by_name(rows):
    return {r["quantity"]: r for r in rows}


# ------------------------------------------------- (b) a TTR as long as the hang-off height
def test_a_ttr_as_long_as_its_hang_off_height_is_solved_by_the_bvp_and_agrees():
    # the input: ttr-steel with its pipe 990 m long between a wellhead at y = 0 and
    # a hang-off 990 m up: the BVP refused it ("too long for the span"), though the
    # tensioner lets the top rise. Now both methods solve it and the
    # comparison passes on the protocol's own tolerances (the independent source: the
    # VFIFE, which never had the pre-check)
    length = 990.0
    sc = resolve("ttr-steel").replace(**{"segments[0].length": length})
    comp = compare(sc, paper_model=False)
    assert comp.passed, failing(comp)
    # the top rises above the hang-off by the stroke the tensioner's balance asks: the
    # top's force top_tension - k stroke = the line's vertical end force (tension at the
    # top times sin of its angle), checked to 1e-6 of the force (the BVP's tolerance)
    b = comp.bvp
    stroke = float(b.profile.y[-1]) - 990.0
    assert stroke > length - 990.0 - 1.0          # the pipe stretches and its top rises
    t = sc.ends.tensioner
    prof = b.profile
    angle = math.atan2(float(prof.y[-1] - prof.y[-2]), float(prof.x[-1] - prof.x[-2]))
    vertical_force = float(prof.tension[-1]) * math.sin(angle)
    assert vertical_force == pytest.approx(t.top_tension - t.stiffness * stroke, rel=1e-4)

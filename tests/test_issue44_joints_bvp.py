"""Issue 44, "False verdicts": a flexible riser on a flex joint converges to a PASS at the
element length the resolution advice gives; the BVP solves a top-tensioned riser whose
pipe is as long as the hang-off height (the tensioner frees the top's height); the BVP
solves a chain whose clump weight lies on the seabed in seconds.

Units SI: lengths [m], forces [N], moments [N m]; s from the bottom end."""

from __future__ import annotations

import math
import time
from pathlib import Path

import pytest

import bvp
import vfife
from riser.io.scene_file import load_scene
from verification import compare, resolve
from verification.methods import method
from vfife.solver import HELD_END_FRACTION


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


# ------------------------------------------------- (c) a clump weight lying on the seabed
def test_a_clump_weight_on_the_seabed_is_solved_in_seconds_by_the_bvp():
    # the input: mooring-clump-weight with its clump moved from s = 700 m (hanging
    # 56 m above the seabed) to s = 400 m, where it lies on the seabed (the touchdown is
    # ~579 m from the anchor). The contact-zone start cannot carry a point load on the
    # grounded part and failed after minutes (measured 198 s on the loaded 2-core machine,
    # 41 s idle per the issue) before the unilateral form solved it; now the unilateral
    # form is chosen at once (2.5 s loaded). 60 s is 20 x the measured time yet a third
    # of the old cost: it fails if the slow path comes back
    sc = resolve("mooring-clump-weight").replace(**{"attachments[0].s": 400.0})
    t0 = time.perf_counter()
    r = bvp.solve(sc)
    took = time.perf_counter() - t0
    assert r.converged, r.message
    assert took < 60.0
    prof = r.profile
    # the clump lies on the seabed: within 1 m of y = 0 at s = 400 m (it sinks into the
    # elastic seabed by its weight / stiffness, ~0.4 m) and the line is grounded there
    i = int(abs(prof.s - 400.0).argmin())
    assert abs(float(prof.y[i])) < 1.0


# ------------------------------------------------- (a) a flexible riser on a flex joint
FLEX = Path(__file__).parent / "scenes_issue44" / "flexible-flex-joint.toml"


def test_flex_joint_moment_converges_at_second_order_and_the_advice_passes():
    # the issue's input: Yu A3's lazy wave on a flex joint with a flexible pipe's EI
    # (1e5 N m2; the bending length at the joint 0.84 m). compare FAILed at the length
    # the resolution warning advised (0.42 m, half the layer: joint moment 0.94 % off).
    # Independent source: the BVP (its joint moment does not depend on the VFIFE mesh).
    sc = load_scene(FLEX)
    b = bvp.solve(sc)
    Mb = b.summary()["hang_off_moment"]
    err = {}
    for h in (0.5, 0.25):
        t0 = time.perf_counter()
        v = vfife.solve(sc, element_length=h)
        # Newton finishes every mesh from 1 m down (the 0.25 m statics relaxed for 1.7e6
        # steps, 93 s, when one coarse mesh's Newton stopped): 60 s is 20 x the measured
        assert v.converged and time.perf_counter() - t0 < 60.0
        err[h] = v.summary()["hang_off_moment"] / Mb - 1.0
    # second order: halving h divides the error by 4 (measured 3.95); 3.3-4.7 brackets
    # orders 1.7-2.2
    assert 3.3 < err[0.5] / err[0.25] < 4.7, err
    # the advice at the joint (vfife.solver.HELD_END_FRACTION of the layer, rounded down)
    warn = [w for w in v.warnings if "flex joint at the hang-off" in w]
    assert len(warn) == 1, v.warnings
    advised = float(warn[0].split("use <= ")[1].split(" m")[0])
    lam = math.sqrt(1.0e5 / b.summary()["hang_off_tension"])
    assert advised <= HELD_END_FRACTION * lam
    assert advised == pytest.approx(HELD_END_FRACTION * lam, rel=0.1)
    # ... passes the whole protocol (PASS, every row), and warns no more; the ANCF, judged
    # in the same verdict, at the length its own resolution warning advises for this
    # flexible line (its bending length sqrt(EI/T) 0.84 m at the joint; at its default 2 m
    # the moment near the touchdown was 0.7 % of M_max off)
    a = method("ancf").solve(sc)
    advice = [w for w in a.warnings if w.startswith("resolution:")]
    assert len(advice) == 1, a.warnings
    h_ancf = float(advice[0].split("use <= ")[1].split(" m")[0])
    comp = compare(sc.replace(**{"vfife.element_length": advised,
                                 "ancf.element_length": h_ancf}), paper_model=False)
    assert comp.passed, failing(comp)
    assert not [w for w in comp.vfife.warnings if "flex joint" in w]


def test_a_clump_weight_on_the_seabed_agrees_between_the_methods():
    # the same grounded clump compared (independent source: the BVP). At 1 m elements one
    # row fails: the tension at the nodes next to the clump, 300 N = 0.114 % of T_max
    # (tolerance 0.1 %), where the clump presses the chain 0.37 m into the seabed and the
    # tension dips over ~3 m (the string-on-foundation length sqrt(T / (k D))); at 0.5 m
    # 155 N, 0.059 %: PASS, every row (the protocol's rule: a scene that needs it gets a
    # shorter element, never a looser tolerance)
    sc = resolve("mooring-clump-weight").replace(**{"attachments[0].s": 400.0,
                                                    "vfife.element_length": 0.5})
    comp = compare(sc, paper_model=False)
    assert comp.passed, failing(comp)
    t = by_name(comp.rows)["tension"]
    assert abs(t["abs_diff"]) < 0.75 * t["tolerance"]       # measured 0.59 of it

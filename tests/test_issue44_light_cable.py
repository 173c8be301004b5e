"""Issue 44 ("False verdicts"): a light power cable's statics converge by Newton's finish.

The fixture (tests/scenes_issue44/light-cable-span.toml): a dynamic power cable (36.7 kg/m,
EI 2e4 N m2, EA 5e8 N, OD 0.13 m) hung as a 600 m mid-water span, 0.5 m elements, over a
seabed with Coulomb friction 0.5 that it never touches. The scene's friction alone used to
switch Newton's finish off for the whole solve (friction makes an equilibrium in contact
path-dependent), so every mesh was relaxed: with the dynamic protocol's tightened
tolerances 3.9e5 steps, 7.2 s; a longer span that just touches the seabed crept for 5e6
steps without converging. Newton now applies wherever the friction is not engaged.

References: the BVP of the same scene (hang-off tension), the frictionless scene (the same
equilibrium: friction does nothing above the seabed), the relaxation's own equilibrium.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import bvp
import vfife
from verification.catalog import resolve
from verification.comparison.dynamic.protocol import tightened_statics
from vfife.statics.equilibrium import friction_engaged

FIXTURE = Path(__file__).parent / "scenes_issue44" / "light-cable-span.toml"


def _static(scene):
    """The scene without its [dynamics] (statics only)."""
    return scene.replace(dynamics=None)


def test_light_cable_span_statics_by_newton_at_the_protocols_tolerance():
    # the dynamic protocol's static state (tolerances x 0.1): the relaxation on the 10 m
    # mesh only (the same steps as a 2 m solve), Newton on 2 m and 0.5 m in a few
    # iterations; the figure was millions of relaxation steps
    sc = _static(resolve(str(FIXTURE)))
    tight = sc.replace(**tightened_statics(sc))
    v = vfife.solve(tight).require()
    stages = v.info["static_stages"]
    assert [st["element_length"] for st in stages] == [10.0, 2.0, 0.5]
    assert v.info["static_newton_failed"] is None
    assert all(st["steps"] == 0 and st["newton_iterations"] <= 8 for st in stages[1:]), stages
    assert v.info["steps"] == stages[0]["steps"]
    # the steps of the coarse relaxation alone: a 600 m line on 60 elements (measured
    # 12,911 steps; before, 3.9e5 over the three meshes)
    assert v.info["steps"] < 50_000
    # the BVP's hang-off tension: the comparison's tolerance, 1e-4 of itself (Newton's
    # discrete equilibrium at 0.5 m; scr-steel's is 2e-8 from the BVP's at 0.25 m)
    b = bvp.solve(sc).require()
    assert v.profile.tension[-1] == pytest.approx(b.profile.tension[-1], rel=1e-4)
    # clear of the seabed (the friction never engaged): the lowest node ~60 m up
    assert float(np.min(v.profile.y)) > 10.0


def test_unused_friction_changes_nothing():
    # the same scene without friction (Newton's finish was used before this issue): the
    # same discrete equilibrium, to the round-off of Newton's polish (1e-9 of the
    # tension, far below the 1e-4 of the comparison)
    sc = _static(resolve(str(FIXTURE)))
    with_f = vfife.solve(sc).require()
    without = vfife.solve(sc.replace(**{"seabed.friction": 0.0})).require()
    assert with_f.info["steps"] == without.info["steps"]
    np.testing.assert_allclose(with_f.profile.tension, without.profile.tension, rtol=1e-9)
    np.testing.assert_allclose(with_f.profile.y, without.profile.y, rtol=0, atol=1e-9)


def test_friction_in_contact_keeps_the_relaxation():
    # friction engaged (a node on the seabed): the equilibrium is the relaxation's
    # (path-dependent), Newton's frictionless one is not used. The fixture's coarse state
    # is clear of the seabed; pushing one node 1 cm into it engages the friction, and a
    # scene without a friction coefficient never does
    sc = _static(resolve(str(FIXTURE)))
    model = vfife.solve(sc, element_length=10.0).require().solver_state
    assert not friction_engaged(sc, model)
    model.X[1, model.mesh.n // 2] = -0.01
    assert friction_engaged(sc, model)
    assert not friction_engaged(sc.replace(**{"seabed.friction": 0.0}), model)


def test_a_touchdown_with_friction_is_relaxed():
    # a riser resting on the seabed with friction 0.5: every mesh relaxed, no Newton
    # iteration (scr-steel on its 2 m default against the 10 m coarse mesh)
    sc = resolve("scr-steel").replace(**{"seabed.friction": 0.5})
    v = vfife.solve(sc, element_length=4.0).require()
    stages = v.info["static_stages"]
    assert len(stages) > 1
    assert not any("newton_iterations" in st for st in stages), stages
    assert all(st["steps"] > 0 for st in stages)


@pytest.mark.slow
def test_light_cable_dynamic_comparison_passes_at_the_advised_length_and_small_amplitude():
    # the issue's `compare --dynamics` of the light cable. Measured (issue 44): at the
    # tester's 0.5 m elements and 0.5 m heave the moment amplitude (0.76 N m, its peak at
    # mid-span) is 2.17 % apart, and 2.17 % again at the advised 0.23 m: not the mesh but
    # the FD's linearised drag (the VFIFE's higher harmonics reach 7.2 % of the first along
    # s), which the protocol judges at the sweep's smallest amplitude only. At 0.1 m heave
    # and the element length the resolution warning advises (0.5 sqrt(EI/T) = 0.23 m; the
    # 0.5 m elements left the top's moment layer 1.3 % off) every row passes (moment 0.29
    # %, tension 5e-5). Independent source: the frequency domain about the BVP's statics.
    # ~5 min (the VFIFE's 0.23 m elements over 24 periods)
    from verification.comparison.dynamic.protocol import compare_dynamics
    sc = resolve(str(FIXTURE))
    v = vfife.solve(_static(sc))
    advice = [w for w in v.warnings if "moment peaks" in w]
    assert len(advice) == 1, v.warnings
    h = float(advice[0].split("use <= ")[1].split(" m")[0])
    assert h == pytest.approx(0.23, abs=0.005)
    comp = compare_dynamics(sc, amplitudes=(0.1,), element_length=h)
    bad = [(r["quantity"], r["rel_diff"]) for res in comp.results for r in res.rows
           if r["pass"] is False]
    assert comp.passed, bad

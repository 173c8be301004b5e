"""Issue 51: public OrcaFlex models imported and solved by both methods against OrcaFlex's
own published static results (verification/studies/orcaflex/published.py: the models,
the numbers, their source and the tolerances with their reasons).

Orcina's example A01 "Catenary riser" (a flexible riser from an FPSO to an anchor, 130 m in
100 m of water, a sheared current) and A01 "Lazy wave riser" (its distributed-buoyancy
line, 190 m, slightly out of its plane: solved in 3D), OrcaFlex 11.6b statics. Measured
(BVP / VFIFE at the models' 0.5 m and 1 m segments): top tension +0.008 % / +0.007 % and
-0.006 % / -0.007 %, least tension -0.022 % / -0.011 % and -0.134 % / -0.028 %, peak moment
+0.20 % / +0.27 % and +0.34 % / +0.47 %, anchor tension +0.29 % / +0.27 % and +1.33 % /
+1.29 % (OrcaFlex's as-laid seabed friction, which the suite's statics do not model).
"""

from __future__ import annotations

import pytest

from extras import needs_yaml
from verification.pipeline import solve_scene

pytestmark = needs_yaml


def _check(name: str, method: str) -> None:
    from verification.studies.orcaflex.published import MODELS, QUANTITIES, imported
    model = next(m for m in MODELS if m.name == name)
    assert model.tolerance is not None          # a judged model (the steep wave: reported)
    scene, _ = imported(model)
    res = solve_scene(scene, method).require()
    s = res.summary()
    bad = []
    for q, (key, _) in QUANTITIES.items():
        ref = model.results[q]
        rel = (s[key] / 1000.0 - ref) / abs(ref)
        if abs(rel) > model.tolerance[q]:
            bad.append(f"{q}: {s[key] / 1000.0:.6g} vs OrcaFlex {ref:.6g} ({rel:+.3%}, "
                       f"tolerance {model.tolerance[q]:.1%})")
    assert not bad, bad


@pytest.mark.parametrize("method", ["bvp", "vfife"])
def test_a01_catenary_riser_against_orcaflex_statics(method):
    _check("a01-catenary-riser", method)


def test_a01_lazy_wave_riser_against_orcaflex_statics_vfife():
    _check("a01-lazy-wave-riser", "vfife")


@pytest.mark.slow
def test_a01_lazy_wave_riser_against_orcaflex_statics_bvp():
    # the 3D rod (the line's plane is 0.47 deg off the current's): 6.5 s
    _check("a01-lazy-wave-riser", "bvp")


def test_the_imported_catenary_carries_the_models_numbers_exactly():
    # every carried number against the fixture's, converted by hand (OrcaFlex SI: te, kN, m):
    # no solver; exact to the last digit of a float product (== or 1 ulp)
    from verification.studies.orcaflex.published import MODELS, imported
    scene, notes = imported(MODELS[0])
    lt = scene.line_types['10" flexible variable Cd']
    assert lt.outer_diameter == 0.3556 and lt.inner_diameter == 0.254
    assert lt.mass_per_length == pytest.approx(184.2262, rel=1e-15)
    assert lt.axial_stiffness == 711.2e3 * 1000.0
    assert lt.bending_stiffness == 124.86942768 * 1000.0
    # Cd: the Reynolds table 'Generic Drag' is 1.2 up to Re = 2.4e5; the current's fastest
    # flow, 0.7 m/s on 0.3556 m at nu = 1.35e-6 m2/s, is Re = 1.84e5 (statics only)
    assert lt.drag_normal == 1.2 and lt.drag_tangential == 0.008 and lt.added_mass == 1.0
    assert lt.contents_density == 1000.0
    assert scene.water_density == 1025.0 and scene.gravity == 9.80665
    # the seabed raised by the contact radius OD/2: depth 100 - 0.1778; the anchor (0.1778
    # above OrcaFlex's seabed, its underside on it) on the scene's seabed
    assert scene.water_depth == pytest.approx(100.0 - 0.1778, abs=1e-12)
    assert tuple(scene.ends.anchor) == (0.0, 0.0)
    # End A on the FPSO at (37, 0, -7.5) in its axes, the vessel at X = -35: X = 2;
    # End B at X = 57: 55 m apart, the hang-off 92.3222 m above the scene's seabed
    assert scene.ends.hang_off[0] == pytest.approx(55.0, abs=1e-12)
    assert scene.ends.hang_off[1] == pytest.approx(100.0 - 7.5 - 0.1778, abs=1e-12)
    assert scene.seabed.stiffness == pytest.approx(100.0 * 1000.0 * 0.3556, rel=1e-15)
    assert scene.seabed.friction == 0.0          # taken off for the comparison
    # the current: 0.7 m/s x (1, 0.9, 0.3) at depths 0, 70, 100 m; the 100 m row below the
    # scene's seabed replaced by the value at it: 0.7 (0.9 + (0.3 - 0.9) (99.8222 - 70) / 30)
    c = scene.current
    assert c.heading_deg == 0.0                  # towards -X = from the anchor to the top
    assert c.speeds[-2:] == pytest.approx((0.63, 0.7), rel=1e-15)
    assert c.speeds[0] == pytest.approx(0.7 * (0.9 - 0.6 * 29.8222 / 30.0), rel=1e-12)
    assert [s.length for s in scene.segments] == [20.0, 20.0, 90.0]
    assert scene.vfife.element_length == 0.5

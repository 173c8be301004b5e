"""Issue 51: every built-in scene exported to an OrcaFlex text data file and imported back
(verification/studies/orcaflex/round_trip.py: what is compared) is the same scene, or its
export is refused naming the scene key OrcaFlex's subset cannot express.

Measured: 36 of 49 built-in scenes exported; the worst differences over them: section
properties 9e-16 (relative), geometry 7e-15 m, joints 4e-14 deg, seabed 1.4e-16, the
environment, the vessel's RAOs and the attachments 0; the wall's polar inertia of the 20
scenes with buoyancy sections or weight overrides up to 0.76 (the displacement diameter
that gives their weight: documented, the one property the round trip changes).
"""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import pytest

from extras import needs_yaml
from verification.catalog import builtin_paths, resolve

ROOT = Path(__file__).resolve().parents[1]

#: the built-in scenes the export refuses, and the key each refusal names
REFUSED = {
    "hard-large-heave": "dynamics.top_motion", "hard-long-dynamic": "dynamics.top_motion",
    "kang2015-jlay": "ends", "liu2021-scr": "internal_flow",
    "scr-steel-current-turning": "environment.current.headings_deg",
    "yu2021-a3-current-turning": "environment.current.headings_deg",
    "ttr-steel": "ends.tensioner",
    **{n: "ends" for n in ("wang2014-baseline", "wang2014-current-0p75",
                           "wang2014-current-1p5", "wang2014-current-neg0p75",
                           "wang2014-current-neg1p5", "wang2014-lazy-wave-design")},
}

#: the largest difference each category may show: float round-off of the unit factors
#: (x 1000 between N and kN, kg and te: the export picks the float that reads back
#: exactly, a few ulps elsewhere) and of the frame's shift by the contact radius (y + r -
#: r): 1e-12 relative, 1e-9 m and deg absolute, a thousand times the measured worst
LIMITS = {"sections": 1e-12, "geometry": 1e-9, "environment": 1e-9, "vessel": 1e-9,
          "attachments": 1e-9, "joints": 1e-9, "seabed": 1e-12}


@needs_yaml
@pytest.mark.parametrize("name", sorted(builtin_paths()))
def test_a_built_in_scene_comes_back_from_orcaflex_or_is_refused_by_its_key(name):
    from verification.studies.orcaflex.round_trip import round_trip
    scene = resolve(name)
    trip = round_trip(scene)
    if name in REFUSED:
        assert trip.refused is not None and trip.refused.startswith(REFUSED[name] + ":"), \
            trip.refused
        return
    assert trip.refused is None, trip.refused
    assert set(trip.worst) >= {"sections", "geometry", "seabed"} or scene.seabed is None
    for cat, d in trip.worst.items():
        if cat == "rotary_inertia":
            assert trip.own_segments          # only where a segment has its own weight
            continue
        assert d <= LIMITS[cat], (cat, d)


def test_the_round_trip_compares_what_it_claims():
    # the negative control: a changed EA, a moved hang-off, another current heading and
    # a stiffer joint are each seen by the comparison (the test above could not fail
    # otherwise)
    from verification.studies.orcaflex.round_trip import compare
    a = resolve("lazy-wave-flex-joint")
    lt = a.line_types[a.segments[0].line_type]
    b = a.replace(line_types={**a.line_types, lt.name: lt.replace(
        axial_stiffness=lt.axial_stiffness * (1 + 1e-9))})
    assert compare(a, b)[0]["sections"] == pytest.approx(1e-9, rel=1e-3)
    e = a.ends
    moved = a.replace(ends=e.replace(hang_off=(e.hang_off[0] + 1e-6, e.hang_off[1])))
    assert compare(a, moved)[0]["geometry"] == pytest.approx(1e-6, rel=1e-3)
    j = e.hang_off_joint
    stiff = a.replace(ends=e.replace(hang_off_joint=j.replace(
        rotational_stiffness=j.rotational_stiffness * 1.001)))
    assert compare(a, stiff)[0]["joints"] == pytest.approx(1e-3, rel=1e-2)
    c = resolve("scr-steel-current-45")
    turned = c.replace(current=c.current.replace(heading_deg=c.current.heading_deg + 0.5))
    assert compare(c, turned)[0]["environment"] == pytest.approx(0.5, rel=1e-9)


def test_the_export_needs_no_yaml_library_and_refuses_in_one_line(tmp_path):
    # export-orcaflex writes its text by hand: it runs without PyYAML; a scene it cannot
    # express is one line naming the key, exit 2 (one process: the imports cost 3 s)
    code = ("import sys; sys.modules['yaml'] = None; from verification.cli import main; "
            f"a = main(['export-orcaflex', 'scr-steel', '--out', r'{tmp_path}/']); "
            f"b = main(['export-orcaflex', 'wang2014-baseline', '--out', r'{tmp_path}/']); "
            "print(a, b)")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                         text=True, timeout=120)
    assert out.stdout.split()[-2:] == ["0", "2"], (out.stdout, out.stderr)
    text = (tmp_path / "scr-steel.yml").read_text()
    assert text.startswith("%YAML 1.1\n") and "\nLines:\n" in text
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and ": ends: " in lines[0]


@needs_yaml
def test_a_round_tripped_scene_solves_to_the_same_statics(tmp_path):
    # the scene and its round trip solve to the same equilibrium (BVP): the same physics
    # to float round-off, so the same result to the solver's own tolerance (1e-6 relative
    # collocation residual: 1e-7 on the tensions and the moment); the anchor at x = 0 in
    # both (jumper-sea's is there already; a jumper with a current, waves and a vessel
    # whose statics need neither): one solve each, 0.3 s
    from riser.io.orcaflex.model_from_scene import export_model
    from riser.io.orcaflex.scene_from_model import import_model
    from verification.pipeline import solve_scene
    a = resolve("jumper-sea")
    path = tmp_path / "m.yml"
    path.write_text(export_model(a)[0])
    _, b, _ = import_model(path)
    ra, rb = (solve_scene(s, "bvp").require().summary() for s in (a, b))
    for key in ("hang_off_tension", "bottom_tension", "max_moment"):
        assert rb[key] == pytest.approx(ra[key], rel=1e-7), key
    assert math.isclose(rb["hang_off_angle_deg"], ra["hang_off_angle_deg"], abs_tol=1e-6)

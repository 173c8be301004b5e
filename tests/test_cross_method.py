"""Cross-method regression: VFIFE against the BVP under the comparison protocol.

The reference is the other solver (independent discretisation: collocation against an
explicit lumped-mass relaxation) of the same continuum model, an extensible line on the
scene's elastic seabed. Every comparison here runs at the protocol's default element
length (1 m; a few seconds each) and is asserted against the protocol's tolerances
(verification/comparison/tolerances.py, where each is justified by the measurement of issue 11).
"""

from __future__ import annotations

import dataclasses

import pandas as pd
import pytest

from riser.model.scene import FixedEnds
from riser.model.settings import VFIFESettings
from riser.model.transform import DEFAULT_SEABED_STIFFNESS
from verification.catalog import resolve
from verification.comparison.static.agreement import AGREEMENT_COLUMNS
from verification.comparison.static.protocol import compare
from verification.comparison.static.report import report_markdown, write


def failing(comp):
    return [(r["quantity"], r["abs_diff"], r["tolerance"]) for r in comp.rows if not r["pass"]]


def by_name(rows):
    return {r["quantity"]: r for r in rows}


@pytest.fixture(scope="module")
def wang():
    # the Wang baseline (touchdown-tension form) at the default 1 m VFIFE mesh
    return compare(resolve("wang2014-baseline"))


def test_wang_form_is_compared_like_with_like(wang):
    # a Wang form: the BVP solves the paper model once, the scene is converted once, and
    # BOTH methods solve the converted scene, extensible on the soft-clay seabed
    ms = wang.matched_scene
    assert isinstance(ms.ends, FixedEnds) and wang.vfife_scene is ms
    assert wang.bvp.model == {"axial": "extensible", "seabed": "elastic",
                                      "seabed_stiffness": DEFAULT_SEABED_STIFFNESS}
    assert wang.paper.model == {"axial": "inextensible", "seabed": "rigid"}
    # the conversion: hang-off at the paper-model top point, anchor 300 m ahead of the
    # touchdown on the seabed, the first segment 300 m longer than its suspended length
    sp = wang.paper.summary()
    assert ms.ends.hang_off == pytest.approx((sp["hang_off_x"], sp["hang_off_height"]))
    assert ms.ends.anchor == (-VFIFESettings().seabed_length, 0.0)
    assert ms.segments[0].length == pytest.approx(
        wang.paper.info["first_segment_suspended_length"] + VFIFESettings().seabed_length)
    assert ms.seabed.stiffness == DEFAULT_SEABED_STIFFNESS


def test_wang_baseline_passes_at_the_default_mesh(wang):
    # every row within the protocol's tolerance (issue 11 targets: configuration 0.02 %
    # of depth, tension 0.1 % of T_max, moment 0.5 % of M_max, touchdown x 0.5 m)
    assert wang.passed, failing(wang)
    rows = by_name(wang.rows)
    # the largest moment difference (measured 0.37 % of M_max, issue 11) is VFIFE's
    # first-order moment error where the moment is sharpest: on the seabed next to the
    # lift-off, within the foundation length (4 EI/k)^(1/4) (4.4 m, ~4 elements)
    ms = wang.matched_scene
    foundation = (4.0 * ms.line_types["steel"].bending_stiffness / ms.seabed.stiffness) ** 0.25
    assert foundation == pytest.approx(4.4, abs=0.05)
    lift_off = wang.bvp.profile.tdp_s - wang.s_shift
    assert lift_off - foundation <= rows["moment"]["at_s"] <= lift_off + 1.0


def test_wang_arc_lengths_in_the_scene_coordinate(wang):
    # reported arc lengths are the scene's own (from the paper-model touchdown): the
    # converted scene's s minus the 300 m added. The crest of the extensible line lies
    # within its stretch (T/EA ~ 4e-4 x 770 m ~ 0.3 m) of the paper-model crest; without
    # the shift it would be 300 m off
    rows = by_name(wang.rows)
    assert wang.s_shift == VFIFESettings().seabed_length
    assert wang.bvp.profile.s[0] == pytest.approx(0.0, abs=1e-9)      # solved: from the anchor
    crest_paper = wang.paper.summary()["crests"][0]["s"]
    assert rows["crest1_s"]["bvp"] == pytest.approx(crest_paper, abs=1.0)
    assert rows["crest1_s"]["vfife"] == pytest.approx(crest_paper, abs=1.0)
    assert any("300 m of line added" in n and "measured from that BVP touchdown" in n
               for n in wang.notes)


def test_wang_paper_model_section_is_secondary(wang):
    # the paper model (inextensible, rigid seabed) against the same VFIFE run: reported,
    # not the verdict. Its touchdown is x = 0 by construction, the soft seabed moves the
    # lift-off ~5 m (measured; ~ the 4.4 m foundation length): that model difference is
    # an order of magnitude above the matched difference, which is why the verdict is
    # the matched comparison
    paper = by_name(wang.paper_rows)
    matched = by_name(wang.rows)
    assert wang.paper.summary()["tdp_x"] == pytest.approx(0.0, abs=1e-6)
    assert paper["tdp_x"]["diff"] == pytest.approx(wang.vfife.summary()["tdp_x"], abs=1e-9)
    assert abs(paper["tdp_x"]["diff"]) > 10.0 * abs(matched["tdp_x"]["diff"])
    assert not all(r["pass"] for r in wang.paper_rows) and wang.passed


def test_wang_report_and_agreement_csv(wang, tmp_path):
    write(wang, tmp_path)
    df = pd.read_csv(tmp_path / "agreement.csv")
    # contract with other tools: the protocol's columns, then the analytic column's two and
    # the ANCF's (judged: issue 46)
    assert tuple(df.columns) == AGREEMENT_COLUMNS + ("analytic", "analytic_rel_diff", "ancf",
                                                     "ancf_rel_diff")
    t = df.set_index("quantity")
    # rel_diff is the signed (VFIFE - BVP) / basis with the basis of the tolerance:
    # recomputed here from the profiles the solvers wrote
    T_max = wang.bvp.profile.tension.max()
    tension = by_name(wang.rows)["tension"]
    assert t.loc["tension", "rel_diff"] == pytest.approx(tension["diff"] / T_max, rel=1e-6)
    # (the CSV holds 8 significant digits: each of the bvp and vfife columns of 831 kN is
    # rounded by up to 5e-9 of itself, so their difference over bvp is known to 1e-8; the
    # VFIFE's Newton finish puts it 0.06 N from the BVP's, a relative 7.6e-8)
    ho = t.loc["hang_off_tension"]
    assert ho["rel_diff"] == pytest.approx((ho["vfife"] - ho["bvp"]) / ho["bvp"], abs=1.2e-8)
    # (likewise the crest's 363 m heights to 2e-6 m each: their difference over the depth
    # to 3e-9; measured -3.7e-9, 6 um)
    crest = t.loc["crest1_height"]
    assert crest["rel_diff"] == pytest.approx((crest["vfife"] - crest["bvp"]) / wang.depth,
                                              abs=3e-9)
    # every row has a relative form except those with an absolute tolerance (angle, touchdown
    # x, arc lengths of crests, sags and the peak moment): same normalisation as the tolerance
    absolute = ("hang_off_angle_deg", "tdp_x", "crest1_s", "sag1_s", "max_moment_s")
    assert t["rel_diff"].isna().tolist() == [q in absolute for q in t.index]
    md = (tmp_path / "report.md").read_text()
    assert "**Verdict: PASS**" in md
    assert "Paper model (limit), not part of the verdict" in md
    assert md.index("touchdown x") < md.index("# Agreement")              # headline first
    assert md == report_markdown(wang)


def test_fixed_ends_scene_single_segment():
    # steel catenary riser (fixed ends on its own soft seabed): solved as it is by both
    # methods; the paper model is the same scene with [model] inextensible + rigid
    comp = compare(resolve("scr-steel"))
    assert comp.s_shift == 0.0 and comp.matched_scene is comp.scene
    assert comp.bvp.model["axial"] == "extensible"
    assert comp.paper.model == {"axial": "inextensible", "seabed": "rigid"}
    assert comp.passed, failing(comp)


def test_two_buoy_sheared_current():
    # two buoyancy sections (1130 N/m weight jumps at the joints) and a sheared current
    # (drag in both methods); the tension at the joints is where the nodal-average
    # operator matters (compare.nodal_average)
    comp = compare(resolve("yu2021-a2-sheared"), paper_model=False)
    assert comp.passed, failing(comp)


def _buoyancy_plus_5pct(scene):
    segs = tuple(dataclasses.replace(s, weight_scale=s.weight_scale * 1.05) if s.weight_scale < 0
                 else s for s in scene.segments)
    return scene.replace(segments=segs)


def _drag_halved(scene):
    return scene.replace(line_types={k: dataclasses.replace(v, drag_normal=0.5 * v.drag_normal,
                                                            drag_tangential=0.5 * v.drag_tangential)
                                     for k, v in scene.line_types.items()})


def test_negative_control_buoyancy(wang):
    # the same comparison with 5 % more buoyancy in VFIFE only must fail, and on the
    # configuration (the crest rises by metres), rows that pass without the change
    comp = compare(resolve("wang2014-baseline"), paper_model=False,
                   vfife_modifier=_buoyancy_plus_5pct)
    assert not comp.passed
    names = {q for q, _, _ in failing(comp)}
    assert {"configuration", "crest1_height"} <= names
    ok = by_name(wang.rows)
    assert ok["configuration"]["pass"] and ok["crest1_height"]["pass"]
    assert by_name(comp.rows)["configuration"]["abs_diff"] > 10.0 * ok["configuration"]["tolerance"]


# slow (9 s): covered by test_negative_control_buoyancy (a VFIFE-only change fails the
# protocol) and test_regress.py::test_builtin_scene_matches_store[wang2014-current-1p5]
@pytest.mark.slow
def test_negative_control_drag_halved():
    # half the drag in VFIFE only, current +1.5 m/s: the configuration and the hang-off
    # angle must fail, and they pass without the change
    scene = resolve("wang2014-current-1p5")
    comp = compare(scene, paper_model=False, vfife_modifier=_drag_halved)
    assert not comp.passed
    names = {q for q, _, _ in failing(comp)}
    assert {"configuration", "hang_off_angle_deg"} <= names
    ok = by_name(compare(scene, paper_model=False).rows)
    assert ok["configuration"]["pass"] and ok["hang_off_angle_deg"]["pass"]


# ------------------------------------------------------------------ every supported scene
# Hard scenes left out, each for a stated reason (verification/comparison/tolerances.py /
# the closing note of issue 11):
# hard-flexible: EI = 1e3 N m2, bending length sqrt(EI/T) ~ 0.04-0.07 m, far below any
#   practical VFIFE element: its moment is unresolved at 1 m (21 % of a 3.3 N m M_max);
# hard-buoyancy-loss, hard-current-neg2p5: the BVP does not converge (stated failure);
# hard-coarse-elements, hard-large-heave, hard-long-dynamic set their own element length
# (20, 2, 5 m) for their stress purpose; their statics are compared at the 1 m default.
HARD_COMPARED = ("hard-coarse-elements", "hard-current-pos2p5", "hard-current-reversing",
                 "hard-deep-scr", "hard-large-buoyancy", "hard-large-heave",
                 "hard-long-dynamic", "hard-many-buoys", "hard-out-of-plane-current",
                 "hard-slack-touchdown", "hard-stiff")
BUILTIN = ("wang2014-baseline", "wang2014-current-neg1p5", "wang2014-current-neg0p75",
           "wang2014-current-0p75", "wang2014-current-1p5", "scr-steel", "yu2021-a1",
           "yu2021-a2", "yu2021-a2-sheared", "yu2021-a3", "yu2021-a4",
           # 3D (issue 32): both methods in 3D, the planar protocol's tolerances
           "scr-steel-current-45", "scr-steel-current-90", "scr-steel-current-turning",
           "yu2021-a3-current-45", "yu2021-a3-current-90", "yu2021-a3-current-turning",
           "yu2021-a3-hang-off-offset")


@pytest.mark.slow
@pytest.mark.parametrize("name", BUILTIN + HARD_COMPARED)
def test_every_supported_scene_passes_at_1m(name):
    # issue 11's targets at the default element length: configuration <= 0.02 % of depth,
    # tension <= 0.1 % of T_max, moment <= 0.5 % of M_max, touchdown <= 0.5 m (the
    # protocol's tdp_x tolerance is tighter), every scalar row inside its tolerance
    comp = compare(resolve(name), element_length=1.0, paper_model=False)
    assert comp.passed, failing(comp)

"""The Kang, Zhang & Zhang (2015) J-lay study (verification/studies/kang2015/):
the paper's findings as numbers from the analytic method and the BVP of the J-lay form
(fast, ~1 s), the table.csv contract on a small run without the VFIFE (5 cases, 2 EI of
the epsilon sweep, ~4 s), and (slow) the full study with the VFIFE (~30 s)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import bvp
from riser.model.sections import segment_properties
from verification.runtime import outdir
from verification.studies import STUDIES, study
from verification.studies.kang2015 import cases as k
from verification.studies.kang2015.report import catenary_overestimate_estimate

LABELS = [("base", "base")] + [("wet_weight", f"w={w}kN/m") for w in
                               ("1.50", "1.55", "1.60", "1.65", "1.70")] + [
    ("bending_stiffness", f"EI={e}e8") for e in ("1.0", "1.5", "2.0", "2.5", "3.0")]
SMALL = {"base", "w=1.50kN/m", "w=1.70kN/m", "EI=1.0e8", "EI=3.0e8"}


def test_the_cases_are_the_papers():
    # docs/references.md, Kang et al. 2015: w 1.50..1.70 kN/m at the section's EI, EI
    # 1.0..3.0e8 N m2 at the section's w; the base case is the scene (w 1617.2 N/m, EI 2.0e8
    # from E 2.07e11)
    cs = k.cases()
    assert [(c.study, c.label) for c in cs] == LABELS
    base = segment_properties(cs[0].scene)[0]
    assert base.weight == pytest.approx(1617.2, abs=0.1)
    assert base.EI == pytest.approx(2.0e8, rel=1e-3)
    for c in cs[1:]:
        p = segment_properties(c.scene)[0]
        if c.study == "wet_weight":
            assert p.weight == pytest.approx(float(c.label[2:6]) * 1e3, rel=1e-12)
            assert (p.EI, p.EA) == (base.EI, base.EA)
        else:
            assert p.EI == pytest.approx(float(c.label[3:6]) * 1e8, rel=1e-12)
            assert (p.weight, p.EA) == (base.weight, base.EA)
        assert c.scene.ends == cs[0].scene.ends


@pytest.fixture(scope="module")
def jlay():
    """{label: (catenary, composite, piecewise, bvp) results} of the J-lay form (~0.5 s)."""
    return {c.label: (*(k.analytic_model(c.scene, m) for m in ("catenary", "composite",
                                                                 "piecewise")),
                      bvp.solve(c.scene)) for c in k.cases()}


def test_catenary_overestimates_the_peak_moment_and_jumps_at_the_touchdown(jlay):
    # Kang's finding 1. The catenary's moment is EI w/H at the touchdown (its vertex) and 0
    # on the seabed; the beam removes that jump over the layer, exp(-s/lambda), while the
    # catenary's curvature falls as 1/(1 + (delta x)^2): the linearised layer predicts an
    # overestimate of ~delta^2 ln^2(delta^2), 2.2 % at the base case's delta = 0.030. So
    # 1-5 % on the base case (measured +2.33 %), and the estimate within 15 % of the
    # measurement in every case (it neglects the tension's growth w y and the O(delta^2) of
    # the layer: measured 4-11 % above it for delta 0.017..0.054)
    for label, (cat, co, _, b) in jlay.items():
        mc, mb = k.peak(cat.profile)[0], k.peak(b.profile)[0]
        rel = mc / mb - 1.0
        est, x_peak = catenary_overestimate_estimate(co.info["delta"])
        assert 0.0 < rel / est - 1.0 < 0.15, (label, rel, est)
        if label == "base":
            assert 0.01 < rel < 0.05
            # the beam's peak ~5 lambda up: the estimate's x within 5 % of the BVP's
            lam = co.info["boundary_layer_length"]
            assert k.peak(b.profile)[1] / lam == pytest.approx(x_peak, rel=0.05)
        # the jump: EI w/H just above the touchdown, 0 below (the rigid seabed); the BVP
        # has M = 0 at its touchdown (to its collocation tolerance)
        p0 = segment_properties(next(c.scene for c in k.cases() if c.label == label))[0]
        H = cat.info["horizontal_tension"]
        assert k.moment_jump(cat.profile) == pytest.approx(p0.EI * p0.weight / H, rel=1e-9)
        assert k.peak(cat.profile) == pytest.approx((mc, 0.0))
        assert abs(k.moment_jump(b.profile)) < 1e-6 * mb


def test_peak_moment_grows_with_wet_weight_and_ei(jlay):
    # Kang's finding 3, in the composite and the BVP (and the catenary, EI w/H): strictly
    # increasing along each family. EI x3 gives the catenary exactly x3 and the beams a
    # little less, 3 (1 + r_1e8) / (1 + r_3e8) = 2.952 with the catenary overestimates r
    # (1.43 % and 3.08 %): between 2.9 and 3
    for prefix in ("w=", "EI="):
        fam = [v for lab, v in jlay.items() if lab.startswith(prefix)]
        for j in range(4):                          # catenary, composite, piecewise, BVP
            peaks = [k.peak(v[j].profile)[0] for v in fam]
            assert np.all(np.diff(peaks) > 0.0), (prefix, j, peaks)
        if prefix == "EI=":
            assert k.peak(fam[-1][0].profile)[0] / k.peak(fam[0][0].profile)[0] == \
                pytest.approx(3.0, rel=1e-9)
            assert 2.9 < k.peak(fam[-1][3].profile)[0] / k.peak(fam[0][3].profile)[0] < 3.0


def test_piecewise_equals_the_composite_below_the_top_layer(jlay):
    # Kang's finding 2. The piecewise model is the composite without the pinned-top layer:
    # the same outer solution and touchdown layer (its beam part ends at s_E = 19..34
    # lambda, where the layer's correction is < e^-19 of EI w/H), and at the top the catenary's moment
    # EI kappa_top instead of 0. The composite's top correction decays as EI kappa_top
    # exp(-d / lambda_top), so more than 10 top-layer lengths below the hang-off the two
    # differ by at most EI kappa_top e^-10 (0.38 N m on the base case; 10 % margin for the
    # O(eps^2) part of the top curvature); at the top by EI kappa_top = EI w H / T_top^2
    # (to the O(eps^2) bending correction of the curvature, 2e-5 measured: 1e-4)
    for label, (cat, co, pw, b) in jlay.items():
        pc, pp = co.profile, pw.profile
        assert np.array_equal(pc.s, pp.s)
        lam_top = co.info["top_layer_length"]
        p0 = segment_properties(next(c.scene for c in k.cases() if c.label == label))[0]
        H, T_top = co.info["horizontal_tension"], pc.tension[-1]
        m_top = p0.EI * p0.weight * H / T_top ** 2
        assert m_top == pytest.approx(p0.EI * cat.profile.curvature[-1], rel=1e-6)
        below = (pc.s[-1] - pc.s) > 10.0 * lam_top
        assert np.max(np.abs(pp.moment - pc.moment)[below]) < 1.1 * m_top * math.exp(-10.0)
        assert pp.moment[-1] - pc.moment[-1] == pytest.approx(m_top, rel=1e-4)
        assert pc.moment[-1] == 0.0 and abs(b.profile.moment[-1]) < 1e-6 * m_top
        assert pw.info["piecewise_s_E"] > 15.0 * co.info["boundary_layer_length"]


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    """The study on 5 cases (the base and each family's ends) without the VFIFE, 2 EI in
    the epsilon sweep, 3 timing repeats: its files, not its values."""
    out = tmp_path_factory.mktemp("kang2015")
    q = k.run(out, log=lambda *_: None, with_vfife=False, stiffnesses=(1e7, 1e8), repeats=3,
              subset=SMALL)
    return out, q


def test_table_csv_contract(small):
    out, _ = small
    df = pd.read_csv(out / "table.csv")
    assert list(df.columns) == ["study", "case", "quantity", "catenary", "analytic", "bvp",
                                "vfife"]
    per_case = [*k.QUANTITIES, *(f"{q}_matched" for q in k.QUANTITIES),
                "max_moment_rel_to_bvp", "max_moment_rel_to_bvp_matched"]
    for st, lab in LABELS:
        if lab in SMALL:
            rows = df[(df.study == st) & (df.case == lab)]
            assert list(rows.quantity) == per_case, lab
    assert set(df.study) == {"base", "wet_weight", "bending_stiffness"}
    fam = df[df.case.str.contains(" vs ")]
    assert set(fam.case) == {"w=1.70kN/m vs w=1.50kN/m", "EI=3.0e8 vs EI=1.0e8"}
    assert {"max_moment_increasing", "max_moment_ratio_last_to_first_matched",
            "shape_max_distance_m", "span_change_m"} <= set(fam.quantity)
    # the paper model's rows never hold a VFIFE value; the BVP is the reference (0)
    paper = df[~df.quantity.str.endswith("_matched")]
    assert paper.vfife.isna().all()
    assert (df[df.quantity.str.startswith("max_moment_rel_to_bvp")].bvp == 0.0).all()
    assert df[df.quantity.isin(per_case)][["catenary", "analytic", "bvp"]].notna().all().all()
    written = {p.name for p in out.iterdir()}
    assert written == set(outdir.STUDY_FILES["kang2015"])
    pw = pd.read_csv(out / "piecewise.csv")
    assert len(pw) == len(SMALL) and {"s_E_m", "piecewise_top_moment_N_m"} <= set(pw.columns)
    eps = pd.read_csv(out / "epsilon.csv")
    assert list(eps.EI_N_m2) == [1e7, 1e8]
    assert {f"{m}_{e}" for m in ("composite", "catenary") for e in
            ("max_moment_rel_err", "top_angle_err_deg", "hang_off_x_err_m")} <= set(eps.columns)


def test_index_row_and_registry(small, tmp_path):
    # the findings as booleans of table.csv: 1. the catenary's peak moment above the BVP's
    # in every case; 3. the peak moment strictly increasing along both families in the
    # three methods run here (VFIFE off); 4. the two EI's shapes within 1 % of the depth
    # (3000 m). The verdict is read from the same table: it says reproduced, and not once
    # one catenary overestimate is made negative in a copy of the table.
    out, _ = small
    df = pd.read_csv(out / "table.csv")
    rel = df[df.quantity == "max_moment_rel_to_bvp"]
    assert len(rel) == len(SMALL) and (rel.catenary > 0.0).all()
    inc = df[df.quantity.isin(["max_moment_increasing", "max_moment_increasing_matched"])]
    assert len(inc) == 4 and (inc[["catenary", "analytic", "bvp"]] == 1.0).all().all()
    shape = df[df.quantity == "shape_max_distance_m"]
    assert len(shape) == 1 and shape.bvp.iloc[0] < 0.01 * 3000.0
    cases, agreement, verdict = k.index_row(out)
    assert cases.startswith(f"{len(SMALL)} cases") and "vs BVP" in agreement
    assert verdict == "paper trends reproduced (its tables lost)"
    broken = df.copy()
    broken.loc[rel.index[0], "catenary"] = -1e-3
    broken.to_csv(tmp_path / "table.csv", index=False)
    assert k.index_row(tmp_path)[2] == "paper trends NOT all reproduced"
    assert k.index_row(out / "missing") is None
    assert "kang2015" in STUDIES and study("kang2015") is k.STUDY


@pytest.mark.slow
def test_full_study(tmp_path):
    # the whole study with the VFIFE on 1 m elements (~30 s): every finding reproduced;
    # the VFIFE's peak moment on the matched model within 0.05 % of the matched BVP's
    # (measured <= 0.013 %); the epsilon slopes near the orders the report states
    # (composite angle 2, moment ~3; catenary angle and hang-off x 1)
    q = k.run(tmp_path, log=lambda *_: None)
    df = q["table"]
    relm = df[df.quantity == "max_moment_rel_to_bvp_matched"]
    assert len(relm) == 11 and relm.vfife.abs().max() < 5e-4
    inc = df[df.quantity.str.startswith("max_moment_increasing")][list(k.METHODS)]
    assert (inc.stack().dropna() == 1.0).all() and inc.notna().sum().sum() == 14
    assert k.index_row(Path(tmp_path))[2] == "paper trends reproduced (its tables lost)"
    sl = q["slopes"]
    assert sl[("composite", "top_angle_err_deg")][0] == pytest.approx(2.0, abs=0.15)
    assert 2.5 < sl[("composite", "max_moment_rel_err")][0] < 3.5
    for err in ("top_angle_err_deg", "hang_off_x_err_m"):
        assert sl[("catenary", err)][0] == pytest.approx(1.0, abs=0.1)
    shape = df[df.quantity == "shape_max_distance_m"].bvp.iloc[0]
    assert shape < 0.01 * 3000.0

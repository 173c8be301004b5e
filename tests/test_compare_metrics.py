"""The comparison protocol's metrics against exact geometry (no solver involved)."""

from __future__ import annotations

import numpy as np
import pytest

from riser.results.profile import Profile, summarize
from verification.comparison.static.agreement import agreement
from verification.comparison.tolerances import tolerance_value
from verification.quantities import curve_distance


def arc(radius: float, n: int, z: float = 0.0, phase: float = 0.0) -> Profile:
    """Quarter circle of the given radius as a Profile (s = arc length)."""
    t = np.linspace(0.0, np.pi / 2, n) + phase
    s = radius * (t - phase)
    one = np.ones_like(s)
    return Profile(s=s, x=radius * np.cos(t), y=radius * np.sin(t), z=z * one, theta=t,
                   tension=1000.0 * one + s, moment=10.0 * np.sin(2 * (t - phase)),
                   shear=one, curvature=one / radius)


def test_curve_distance_concentric_arcs():
    # the distance from any point of a circle of radius 101 to one of radius 100 is 1,
    # and the polyline projection makes it exact up to the chord sag (R dt^2 / 8 ~ 2e-5 m)
    ref, other = arc(100.0, 2000), arc(101.0, 300)
    dmax, drms, _ = curve_distance(ref, other, (0.0, 200.0))
    assert dmax == pytest.approx(1.0, abs=1e-4)
    assert drms == pytest.approx(1.0, abs=1e-4)


def test_curve_distance_out_of_plane_offset():
    # a 3 m out-of-plane offset is a 3 m distance (3D metric, not a planar one)
    dmax, _, _ = curve_distance(arc(100.0, 500), arc(100.0, 500, z=3.0), (0.0, 200.0))
    assert dmax == pytest.approx(3.0, abs=1e-9)


def test_agreement_identical_profiles_pass_and_shift():
    # a profile compared with itself (shifted in s by 50 m, as after the fixed-ends
    # conversion) has zero differences and passes every row
    p = arc(100.0, 800)
    q = arc(100.0, 800)
    q = q.replace(s=q.s + 50.0)
    rows = agreement(p, q, depth=100.0, s_shift=50.0)
    assert all(r["pass"] for r in rows), rows
    by = {r["quantity"]: r for r in rows}
    assert by["tension"]["abs_diff"] == pytest.approx(0.0, abs=1e-9)
    assert by["configuration"]["abs_diff"] == pytest.approx(0.0, abs=1e-9)


def test_agreement_detects_tension_offset():
    # negative control of the metric itself: +1 % tension everywhere must fail the 0.1 %
    # rule; rel_diff is signed (VFIFE - BVP) / T_max: +1 % of the top tension = T_max
    p, q = arc(100.0, 800), arc(100.0, 800)
    q = q.replace(tension=q.tension * 1.01)
    by = {r["quantity"]: r for r in agreement(p, q, depth=100.0)}
    assert not by["tension"]["pass"]
    assert by["tension"]["rel_diff"] == pytest.approx(0.01, rel=1e-6)
    # and the sign follows VFIFE - BVP
    q = q.replace(tension=p.tension * 0.99)
    by = {r["quantity"]: r for r in agreement(p, q, depth=100.0)}
    assert by["tension"]["rel_diff"] == pytest.approx(-0.01, rel=1e-6)
    assert by["tension"]["diff"] < 0.0 and by["tension"]["abs_diff"] > 0.0


def _line(n: int = 2001, dx: float = 0.0) -> Profile:
    """A straight 200 m line along x with a touchdown at s = 50 m; tension 2000 - s N (so
    T_max = 2000 N at the bottom and the hang-off tension is 1800 N), moment 10 sin N m."""
    s = np.linspace(0.0, 200.0, n)
    one = np.ones_like(s)
    return Profile(s=s, x=s + dx, y=0 * s, z=0 * s, theta=1e-6 * s, tension=2000.0 - s,
                   moment=10.0 + 5.0 * np.sin(s / 20.0), shear=one, curvature=one, tdp_s=50.0)


def test_rel_diff_has_the_basis_of_the_tolerance():
    # each row's signed relative difference uses the basis of its tolerance (docs/comparison.md,
    # tolerances.py): the hang-off tension relative to itself (1800 N, not T_max = 2000 N),
    # the moment rows to M_max, heights to the depth, touchdown tension to T_max
    p = _line()
    q = _line(dx=0.3)                       # whole line 0.3 m further along x
    q = q.replace(tension=p.tension + 9.0)  # +9 N everywhere
    q = q.replace(moment=p.moment - 0.015)  # -0.015 N m everywhere (M_max = 15 N m)
    by = {r["quantity"]: r for r in agreement(p, q, depth=60.0)}
    assert by["hang_off_tension"]["rel_diff"] == pytest.approx(9.0 / 1800.0, rel=1e-9)
    assert by["tension"]["rel_diff"] == pytest.approx(9.0 / 2000.0, rel=1e-9)
    assert by["tdp_tension"]["rel_diff"] == pytest.approx(9.0 / 2000.0, rel=1e-9)
    mmax = float(p.moment.max())
    assert by["moment"]["rel_diff"] == pytest.approx(-0.015 / mmax, rel=1e-6)
    assert by["max_moment"]["rel_diff"] == pytest.approx(-0.015 / mmax, rel=1e-6)
    assert by["tdp_x"]["diff"] == pytest.approx(0.3, abs=1e-9)
    # an absolute tolerance (0.25 m) has no basis: no relative form, the same
    # normalisation as the tolerance
    assert by["tdp_x"]["rel_diff"] is None
    # the tolerance is stated in the same basis: rel_diff / (tolerance / basis) is the
    # fraction of the tolerance used, whatever the basis
    for q_name in ("tension", "moment", "hang_off_tension", "tdp_tension", "max_moment"):
        r = by[q_name]
        assert r["abs_diff"] / r["tolerance"] == pytest.approx(
            abs(r["rel_diff"]) * r["basis"] / r["tolerance"], rel=1e-9)
    # 9 N is 0.5 % of the hang-off tension: over its tolerance (0.01 %); 0.015 N m is
    # 0.1 % of M_max: inside the moment (0.5 %) and peak-moment (0.2 %) tolerances
    assert not by["hang_off_tension"]["pass"]
    assert by["moment"]["pass"] and by["max_moment"]["pass"]


def test_tolerances_within_the_issue_targets():
    # issue 11: at the default element length configuration <= 0.02 % of depth, tension
    # <= 0.1 % of T_max, moment profile <= 0.5 % of M_max, touchdown x <= 0.5 m; no
    # tolerance may be looser than its target
    kw = dict(depth=1000.0, max_tension=1e6, max_moment=1e5)
    assert tolerance_value("configuration", **kw)[0] <= 2e-4 * 1000.0
    assert tolerance_value("tension", **kw)[0] <= 1e-3 * 1e6
    assert tolerance_value("moment", **kw)[0] <= 5e-3 * 1e5
    assert tolerance_value("tdp_x", **kw)[0] <= 0.5
    assert tolerance_value("crest2_height", **kw)[0] <= 2e-4 * 1000.0
    assert tolerance_value("max_moment", bvp_value=1e5, **kw)[0] <= 5e-3 * 1e5


def _comparison(rows, paper_rows=()):
    from riser.results.result import SolveResult, Status
    from verification.catalog import resolve
    from verification.comparison.static.protocol import Comparison
    sc = resolve("wang2014-baseline")
    res = SolveResult("bvp", sc.name, Status.CONVERGED, "ok", _line(), info={"nodes": 10})
    return Comparison(sc, sc, 0.0, 100.0, res, res, list(rows), matched_scene=sc,
                      paper=res, paper_rows=list(paper_rows), notes=[])


def test_agreement_csv_columns_are_the_contract():
    # agreement.csv is read by other tools (reports index): exactly these columns, in
    # this order, whatever extra keys the rows carry for the report; each further column
    # that ran appends its two (NAME, NAME_rel_diff: the analytic method's, empty where it
    # does not apply; a peer's with --peer NAME), the first seven unchanged
    from verification.comparison.static.agreement import AGREEMENT_COLUMNS
    from verification.comparison.static.columns import ColumnResult
    p = _line()
    comp = _comparison(agreement(p, _line(dx=0.1), depth=60.0))
    assert AGREEMENT_COLUMNS == ("quantity", "bvp", "vfife", "abs_diff", "rel_diff",
                                 "tolerance", "pass")
    assert tuple(comp.frame().columns) == AGREEMENT_COLUMNS
    # a column's values land in its two columns, on its rows only
    col = type("Peer", (), {"name": "peer"})()
    comp.columns["peer"] = ColumnResult(col, values={"tension": (1.5, 0.25)})
    df = comp.frame().set_index("quantity")
    assert tuple(df.reset_index().columns) == AGREEMENT_COLUMNS + ("peer", "peer_rel_diff")
    assert (df.loc["tension", "peer"], df.loc["tension", "peer_rel_diff"]) == (1.5, 0.25)
    assert df["peer"].drop("tension").isna().all()


def test_verdict_ignores_the_paper_model_rows_and_report_reads():
    from verification.comparison.static.report import report_markdown
    p = _line()
    q = _line()
    q = q.replace(tension=p.tension * (1.0 + 1e-14))   # round-off, not a difference
    rows = agreement(p, q, depth=60.0)
    assert all(r["pass"] for r in rows)
    far = agreement(p, _line(dx=30.0), depth=60.0)    # 30 m apart: fails
    assert not all(r["pass"] for r in far)
    comp = _comparison(rows, far)
    assert comp.passed                          # the paper-model rows are not the verdict
    md = report_markdown(comp)
    assert "**Verdict: PASS**" in md
    assert "Paper model (limit), not part of the verdict" in md
    table = md.split("# Agreement (the verdict)")[1].split("# Paper model")[0]
    header = table.strip().splitlines()[0]
    for col in ("unit", "VFIFE - BVP", "relative", "tolerance", "tolerance basis"):
        assert f" {col} |" in header
    line = next(l for l in table.splitlines() if l.startswith("| `tension`"))
    cells = [c.strip() for c in line.strip("|").split("|")]
    # a 2e-11 N difference on a 2000 N basis is round-off: printed as 0, relative 0
    assert cells[1] == "N" and cells[4].startswith("0") and cells[5] == "0"
    assert cells[7] == "0.1 % of T_max"
    line = next(l for l in table.splitlines() if l.startswith("| `moment`"))
    assert "0.5 % of M_max" in line
    # the worst differences lead the report, before the tables
    head = md.split("# Agreement")[0]
    for name in ("configuration", "effective tension", "bending moment", "touchdown x"):
        assert name in head


def test_summary_crest_refinement():
    # y = 50 - (s - 30.3)^2 sampled every metre: the parabolic vertex is exact
    s = np.arange(0.0, 61.0)
    y = 50.0 - (s - 30.3) ** 2 / 10.0
    one = np.ones_like(s)
    p = Profile(s=s, x=s, y=y, z=0 * s, theta=0 * s, tension=one, moment=one, shear=one,
                curvature=one)
    crests = summarize(p)["crests"]
    assert len(crests) == 1
    assert crests[0]["s"] == pytest.approx(30.3, abs=1e-9)
    assert crests[0]["height"] == pytest.approx(50.0, abs=1e-9)


def _two_peaks(a1: float, a2: float, s=None) -> Profile:
    """A profile whose moment has two Gaussian peaks of heights a1 (s = 100 m) and a2
    (s = 400 m)."""
    s = np.linspace(0.0, 500.0, 5001) if s is None else s
    m = a1 * np.exp(-((s - 100.0) / 10.0) ** 2) + a2 * np.exp(-((s - 400.0) / 10.0) ** 2)
    one = np.ones_like(s)
    return Profile(s=s, x=s, y=0 * s, z=0 * s, theta=0 * s, tension=one, moment=m,
                   shear=0 * s, curvature=0 * s)


def test_peak_location_ties_are_not_a_300_m_error():
    from verification.quantities import peak_location_distance
    # two peaks within 0.01 % of each other: which one is 'the' maximum is decided by
    # noise, so the location distance is that of the nearest near-maximum peaks (0 m)
    b, v = _two_peaks(1000.0, 999.9), _two_peaks(999.9, 1000.0)
    assert peak_location_distance(b, v, tol=20.0) == pytest.approx(0.0, abs=1e-9)
    # a real difference (10 % apart, beyond the tolerance) is still 300 m
    b, v = _two_peaks(1000.0, 900.0), _two_peaks(900.0, 1000.0)
    assert peak_location_distance(b, v, tol=20.0) == pytest.approx(300.0, abs=0.2)


def test_peak_location_tie_is_said_in_the_row():
    # the same tie through agreement(): the max_moment_s values are 300 m apart, the row's
    # difference is that of the nearest near-maximum peaks (0) and it says so
    b, v = _two_peaks(1000.0, 999.9), _two_peaks(999.9, 1000.0)
    row = {r["quantity"]: r for r in agreement(b, v, depth=100.0)}["max_moment_s"]
    assert row["vfife"] - row["bvp"] == pytest.approx(300.0, abs=0.2)
    assert row["diff"] == pytest.approx(0.0, abs=1e-6) and row["pass"]
    assert "tie" in row["note"]


def test_peak_location_is_refined_between_stations():
    from verification.quantities import peak_location_offset
    # the peak at s = 100 m sampled every 1 m from s = 0.4 m: the nearest station is 0.4 m
    # off; the parabola through three stations of a Gaussian of width 10 m puts it within
    # O(h^2) of the vertex (~0.003 m measured; the 0.5 m location tolerance must not be
    # eaten by the mesh)
    fine = _two_peaks(1000.0, 10.0)
    coarse = _two_peaks(1000.0, 10.0, s=np.arange(0.4, 500.0, 1.0))
    assert abs(peak_location_offset(fine, coarse, tol=1.0)) < 0.01


def test_moment_metric_does_not_fill_in_a_zero_crossing():
    # the same signed moment M = 1000 sin(s / 10) on a fine and on a coarse grid (a zero at
    # s = 10 pi): interpolating |M| of the coarse grid fills in the V of the zero by up to
    # slope x half the spacing (~100 N m here); the signed comparison leaves only the
    # linear-interpolation error of the smooth curve (1000 h^2 / (8 * 100) ~ 2 N m)
    def prof(n):
        s = np.linspace(0.0, 60.0, n)
        theta = -10.0 * np.cos(s / 10.0) / 1.0e4       # d(theta)/ds has the sign of M
        m = 1000.0 * np.sin(s / 10.0)
        one = np.ones_like(s)
        return Profile(s=s, x=s, y=0 * s, z=0 * s, theta=theta, tension=1e5 * one,
                       moment=np.abs(m), shear=0 * s, curvature=np.abs(m) / 1e4)
    rows = {r["quantity"]: r for r in agreement(prof(6001), prof(31), depth=100.0)}
    assert rows["moment"]["abs_diff"] < 5.0


# ------------------------------------------------------------- features and bending length
def _crest(kappa: float, tilt: float = 0.0, n: int = 4001) -> Profile:
    """A 400 m line through a crest of curvature ``kappa`` [1/m] at s = 200 m: theta =
    -kappa (s - 200) + ``tilt`` [rad] (an angle offset moves the vertex, where theta = 0, by
    tilt / kappa), positions integrated exactly from theta (straight-line segments of the
    circular arc's chord directions are not needed: the heights' vertex is where theta
    crosses zero)."""
    s = np.linspace(0.0, 400.0, n)
    th = -kappa * (s - 200.0) + tilt
    x = np.concatenate([[0.0], np.cumsum(np.diff(s) * np.cos(0.5 * (th[1:] + th[:-1])))])
    y = 100.0 + np.concatenate([[0.0], np.cumsum(np.diff(s) * np.sin(0.5 * (th[1:] + th[:-1])))])
    one = np.ones_like(s)
    return Profile(s=s, x=x, y=y, z=0 * s, theta=th, tension=1000.0 * one,
                   moment=1.0e3 * kappa * one, shear=0 * one, curvature=kappa * one)


@pytest.mark.parametrize("kappa", [1e-2, 1e-3, 1e-4])
def test_crest_position_tolerance_is_the_angle_over_the_curvature(kappa):
    # closed form: tilting a crest's angle by d moves its vertex by d / kappa; the position
    # row's tolerance is max(0.05 m, FEATURE_ANGLE / kappa), so a tilt of 0.9 of the
    # feature angle passes at any curvature and one of 1.5 of it fails where the angle
    # term governs (at kappa 1e-2, 1.5 x 0.03 deg / kappa = 0.079 m > 0.05 m: it fails too)
    from verification.comparison.tolerances import FEATURE_ANGLE_DEG
    d = np.radians(FEATURE_ANGLE_DEG)
    ref = _crest(kappa)
    for factor, passes in ((0.9, True), (1.5, False)):
        rows = {r["quantity"]: r for r in agreement(ref, _crest(kappa, factor * d), 500.0)}
        row = rows["crest1_s"]
        # the vertex moved by the closed form's amount (to the parabola fit of 0.1 m stations)
        assert row["diff"] == pytest.approx(factor * d / kappa, rel=1e-3)
        assert row["tolerance"] == pytest.approx(max(0.05, d / kappa), rel=1e-9)
        assert row["pass"] is passes, (kappa, factor, row)


def test_a_moment_the_elements_cannot_resolve_is_shown_not_judged():
    # a chain-like line: EI 10 N m2 under 1e5 N has a bending length sqrt(EI/T) = 0.01 m,
    # below a 1 m element: the moment rows are not judged (pass None, the reason noted),
    # the others still are; a steel pipe's (EI 1e8: 31.6 m) are judged
    from riser.io.scene_file import scene_from_dict
    from verification.comparison.static.agreement import MOMENT_ROWS, unresolved_bending
    def line(EI):
        return scene_from_dict({"name": "l", "line_types": {"c": {
            "outer_diameter": 0.1, "mass_per_length": 10.0, "axial_stiffness": 1e9,
            "bending_stiffness": EI}}, "segments": [{"line_type": "c", "length": 200.0}],
            "ends": {"anchor": [0.0, 10.0], "hang_off": [199.0, 10.0]}}, "t")
    p = _line()
    p = p.replace(tension=1.0e5 + 0 * p.s)
    reason = unresolved_bending(line(10.0), p, 1.0)
    assert reason is not None and "0.01 m" in reason and "1 m element" in reason
    assert unresolved_bending(line(1e8), p, 1.0) is None
    q = _line()
    q = q.replace(moment=q.moment * 3.0)            # a moment far outside its tolerance
    q = q.replace(tension=p.tension)
    rows = agreement(p, q, 60.0, moment_reason=reason)
    for r in rows:
        if r["quantity"] in MOMENT_ROWS:
            assert r["pass"] is None and r["note"] == reason
        else:
            assert r["pass"] is not None
    judged = agreement(p, q, 60.0)
    assert not {r["quantity"]: r for r in judged}["moment"]["pass"]   # it would fail

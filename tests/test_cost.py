"""Cost study: the VFIFE convergence order in element length against the matched BVP is
pinned, plus the helpers.

Both methods solve the same continuum model (extensible line, elastic Winkler seabed), so
the VFIFE error against a tight BVP solution is its discretisation error (plus a
relaxation error kept far below it by tight static and creep tolerances). Expected order
2: the VFIFE line is a chain of straight elements with lumped nodal weight and seabed
reaction; element forces are constant along an element (they belong to its midpoint) and
the bending moment comes from the element-end rotations relative to the chord. Each is a
midpoint / central-difference approximation of the continuous beam, so positions, nodal
moments and interior tensions are O(h^2), and so is the peak moment, located by a
parabola through the nodal values. A first-order regression (e.g. the weight lumped at
one element end, or moments taken at element midpoints and assigned to nodes) would give
~1 and fail the bands below.

Two small scenes keep the default run short (~10 s for this file):

- ``hanging_line``: pinned at both ends at the same height, no seabed; bending length
  sqrt(EI/T) ~ 12 m. Orders vs the BVP at 20, 10, 5, 2.5 m.
- ``touchdown_line``: anchor on a soft seabed (k = 1e3 N/m2, foundation length
  (4 EI/k)^(1/4) = 14.1 m, bending length 32 m at the lift-off), hang-off 120 m up; the
  whole cost-study pipeline (``cost.study`` with a few settings) at 8, 4, 2, 1 m.
"""

from __future__ import annotations

import math

import pytest

import builders
import bvp
import vfife
from riser.model.scene import FixedEnds, TdpTensionEnds
from verification.quantities import raw_values
from verification.studies import cost
from verification.studies.cost import assessment, fits, records, settings
from verification.studies.cost.errors import rel_errors
from verification.studies.cost.touchdown import (
    asymptotic_length,
    boundary_layer_length,
    foundation_length,
)

LENGTHS = (20.0, 10.0, 5.0, 2.5)
TOUCHDOWN_LENGTHS = (8.0, 4.0, 2.0, 1.0)


def hanging_line():
    """240 m of :func:`builders.pipe` (500 N/m) hanging between ends 200 m apart at 100 m."""
    return builders.scene(builders.line(
        240.0, (0.0, 100.0), (200.0, 100.0), name="hanging-line", submerged_weight=500.0,
        line_type=builders.pipe(drag_normal=1.0, drag_tangential=0.0, added_mass=1.0)))


def touchdown_line():
    """300 m of :func:`builders.pipe` (500 N/m) from an anchor on a soft seabed to a
    hang-off at (220, 120) m."""
    return builders.scene(builders.line(
        300.0, (0.0, 0.0), (220.0, 120.0), name="touchdown-line", submerged_weight=500.0,
        seabed={"stiffness": 1.0e3}))


@pytest.fixture(scope="module")
def hanging():
    """Errors of VFIFE (static tolerance 1e-6: relaxation error ~1e-7, far below the
    discretisation error at 5 m, ~6e-4) against the BVP at tolerance 1e-9."""
    sc = hanging_line()
    ref = bvp.solve(sc, tolerance=1e-9)
    assert ref.converged, ref.message
    rv = raw_values(ref.profile)
    errors = {q: [] for q in ("hang_off_tension", "max_moment", "sag_height")}
    for h in LENGTHS:
        res = vfife.solve(sc, element_length=h, tolerance=1e-6)
        assert res.converged, res.message
        e = rel_errors(raw_values(res.profile, ref.summary()), rv, 100.0)
        for q in errors:
            errors[q].append(e[q])
    return fits.element_length_fits(LENGTHS, errors)


@pytest.mark.parametrize("quantity", ["max_moment", "sag_height"])
def test_vfife_order_is_two_against_the_bvp(hanging, quantity):
    """Measured: 2.00 (peak moment), 2.00 (sag height), local orders 2.01, 2.00, 2.00.
    Band [1.8, 2.3]: the 20 m point is just outside the bending length (pre-asymptotic,
    +0.3 at most in the fit)."""
    fit = hanging[quantity]
    assert fit["points"] == list(LENGTHS)
    assert 1.8 <= fit["order"] <= 2.3, fit
    errs = fit["errors"]
    assert all(a > b for a, b in zip(errs, errs[1:]))     # monotone convergence


def test_hang_off_tension_at_least_second_order(hanging):
    """Measured 3.0: the end value extrapolated from two midpoint values is more accurate
    than second order here."""
    fit = hanging["hang_off_tension"]
    assert fit["order"] >= 1.8, fit


@pytest.fixture(scope="module")
def touchdown():
    """The cost study on ``touchdown_line`` with a handful of runs (~6 s): BVP at 1e-6 and
    1e-9 (the reference), the order sweep at the study's tight tolerances and its
    relaxation check at 2 m."""
    S = settings.Setting
    tight = {"max_steps": 50_000_000, "creep_tolerance": settings.TIGHT_CREEP}
    sets = [S("bvp", "tolerance", t, {"tolerance": t}) for t in (1e-6, 1e-9)]
    sets += [S("vfife", "element_length_tight", h,
               {"element_length": h, "tolerance": settings.TIGHT_TOLERANCE}, tight)
             for h in TOUCHDOWN_LENGTHS]
    sets.append(S("vfife", "element_length_tight_check", 2.0,
                  {"element_length": 2.0, "tolerance": settings.TIGHT_TOLERANCE / 10},
                  {**tight, "creep_tolerance": settings.TIGHT_CREEP / 10}))
    return cost.study(touchdown_line(), repeats=1, settings=sets, progress=False)


def test_study_reference_is_the_matched_bvp(touchdown):
    st = touchdown
    assert st.reference.setting.value == 1e-9
    assert st.fixed_scene is st.scene                 # fixed ends: solved as given
    # the asymptotic range is bounded by the foundation length (4 EI/k)^(1/4) = 14.1 m
    assert st.foundation_length == pytest.approx((4.0 * 1e7 / 1e3) ** 0.25, rel=1e-9)
    assert st.asymptotic == pytest.approx(st.foundation_length)
    assert st.boundary_layer > st.foundation_length
    # noise floors far below the smallest error in the fit (1 m)
    assert st.sweep_noise["max_moment"] < 1e-3 * st.orders["max_moment"]["errors"][-1]
    assert st.bvp_self["max_moment"] < 1e-7


@pytest.mark.parametrize("quantity,band", [("max_moment", (1.8, 2.2)),
                                           ("curve_distance", (1.7, 2.3)),
                                           ("tdp_tension", (1.6, 2.3))])
def test_touchdown_order_is_two_against_the_bvp(touchdown, quantity, band):
    """Measured over 8, 4, 2, 1 m: 1.98 (peak moment, local orders 2.06, 1.84, 2.09), 1.94
    (curve distance to the densified BVP curve, local 1.64-2.33); 1.87 over 4, 2, 1 m
    (touchdown tension, local 1.95, 1.78; its 8 m error, 1.1e-2, is above the
    pre-asymptotic ceiling 1e-2). The peak moment sits 21 m above the lift-off, beyond the
    reach of the contact kink (see below), hence its tight band; the touchdown tension is
    taken at the lift-off, hence the wider one."""
    fit = touchdown.orders[quantity]
    assert len(fit["points"]) >= 3, fit
    assert band[0] <= fit["order"] <= band[1], fit


def test_touchdown_position_converges_inside_its_h2_envelope(touchdown):
    """The lift-off is read off the nodal polyline by linear interpolation of the heights
    (and the lumped seabed reaction has a kink inside the element holding it), so its
    error is O(h^2) with a constant that changes from mesh to mesh: local orders -1.4 to
    3.4. What is pinned is the envelope: every error within the asymptotic range is at
    most the interpolation bound h^2 kappa0 / (8 theta0) of the BVP lift-off (theta0 =
    0.12 rad, kappa0 = 0.013 1/m: 0.013 h^2 m), measured 0.10, 1.06, 0.40, 0.93 x the
    bound at 8, 4, 2, 1 m; 1.3x allows for the kink's share. A first-order touchdown
    (error ~ h) with the measured error at 4 m would be 2x over it at 1 m."""
    st = touchdown
    lo = st.liftoff
    assert lo["theta0"] == pytest.approx(0.123, rel=0.01)
    fit = st.orders["tdp_x"]
    assert fit["points"] == list(TOUCHDOWN_LENGTHS)
    for h, e in zip(fit["points"], fit["errors"]):
        assert e <= 1.3 * lo["coef"] * h * h / st.depth, (h, e)
    text = assessment.order_assessment("tdp_x", fit, {"depth": st.depth, **lo})
    assert "linear interpolation" in text and "x that bound at 8, 4, 2, 1 m" in text


def test_study_writes_the_csv_contract(touchdown, tmp_path):
    import pandas as pd
    cost.write(touchdown, tmp_path)
    df = pd.read_csv(tmp_path / "runs.csv")
    assert tuple(df.columns) == records.RUN_COLUMNS + records.EXTRA_COLUMNS
    assert tuple(df.columns[:12]) == (
        "method", "setting", "value", "wall_time_s", "compile_time_s", "err_hang_off_tension",
        "err_tdp_tension", "err_tdp_x", "err_max_moment", "err_crest_height",
        "err_sag_height", "err_curve_distance")
    text = (tmp_path / "report.md").read_text()
    assert "model difference (VFIFE limit vs BVP)" not in text     # the old floor column
    assert "VFIFE limit vs BVP reference" in text and "Observed VFIFE order" in text


def test_wang_form_scene_is_converted_for_both_methods():
    """A Wang-form scene: both methods solve its fixed-ends equivalent on the elastic
    seabed, in the same arc length (a 300 m misalignment would show as errors ~1). At 10 m
    (measured in the full study: peak moment 2.8e-4, touchdown position 2.1e-3, curve
    distance 1.4e-5)."""
    from verification.catalog import resolve
    S = settings.Setting
    sets = [S("bvp", "tolerance", 1e-4, {"tolerance": 1e-4}),
            S("vfife", "element_length", 10.0, {"element_length": 10.0})]
    st = cost.study(resolve("wang2014-baseline"), repeats=1, settings=sets, progress=False)
    assert isinstance(st.scene.ends, TdpTensionEnds)
    assert isinstance(st.fixed_scene.ends, FixedEnds)
    assert st.fixed_scene.seabed_model == "elastic" and st.fixed_scene.axial_model == \
        "extensible"
    assert st.reference.profile.s[0] == 0.0                       # from the anchor
    assert st.ref_values["tdp_x"] == pytest.approx(4.83, abs=0.01)  # lift-off, elastic bed
    vf = st.runs[-1]
    assert vf.errors["max_moment"] < 1e-3 and vf.errors["hang_off_tension"] < 1e-4
    assert vf.errors["curve_distance"] < 1e-4 and vf.errors["tdp_x"] < 5e-3
    # the paper's own model (inextensible, rigid seabed) differs, and is only reported
    assert abs(st.paper_difference["hang_off_tension"]) > 1e-5


def test_richardson_recovers_a_known_limit():
    hs = [4.0, 2.0, 1.0, 0.5]
    qs = [3.0 + 0.7 * h ** 2 for h in hs]
    lim, p = fits.richardson(hs, qs)
    assert lim == pytest.approx(3.0, rel=1e-9)
    assert p == pytest.approx(2.0, abs=1e-6)
    # non-constant ratio, order 1.5
    hs = [20.0, 10.0, 5.0, 2.0, 1.0]
    qs = [1.0 - 0.1 * h ** 1.5 for h in hs]
    lim, p = fits.richardson(hs, qs)
    assert lim == pytest.approx(1.0, rel=1e-9) and p == pytest.approx(1.5, abs=1e-6)
    # non-monotone: no order, limit = finest value
    assert fits.richardson([4.0, 2.0, 1.0], [1.0, 2.0, 1.5]) == (1.5, None)


def test_fit_order_excludes_noise_and_pre_asymptotic_points():
    hs = [20.0, 10.0, 5.0, 2.0, 1.0]
    errs = [0.2, 1e-3, 2.5e-4, 4e-5, 1e-9]
    f = fits.fit_order(hs, errs, floor=1e-8)
    assert f["points"] == [10.0, 5.0, 2.0]
    assert f["order"] == pytest.approx(2.0, abs=0.01)


def test_pareto_front():
    pts = [(1.0, 1e-2), (2.0, 1e-3), (3.0, 5e-3), (0.5, 1e-1), (4.0, 1e-4)]
    assert fits.pareto(pts) == [(0.5, 1e-1), (1.0, 1e-2), (2.0, 1e-3), (4.0, 1e-4)]


def test_progress_reports_runs_done_and_the_share_of_the_predicted_cost():
    # the study tells k/N runs and the fraction of the predicted cost done; the terminal
    # display (verification.runtime.progress.Progress) draws the bar and the ETA from it
    from verification.runtime.progress import RunCounter
    calls = []
    p = RunCounter([1.0, 3.0, 2.0, 2.0], lambda m, fraction=None: calls.append((m, fraction)))
    p.step("a")
    p.step("b")
    assert calls[-1] == ("2/4 runs (b)", pytest.approx(4.0 / 8.0))   # (1 + 3) of 8
    p.plan([4.0])                   # the rest re-planned: one run to come
    p.step("c")
    assert calls[-1] == ("3/3 runs (c)", pytest.approx(1.0))
    RunCounter([1.0], None).step("quiet")        # no callback: nothing to tell, no error


def test_cli_has_cost_command():
    from verification.cli import build_parser
    args = build_parser().parse_args(["cost", "wang2014-baseline", "--repeats", "1"])
    assert args.func.__name__ == "cmd_cost" and args.repeats == 1 and not args.full
    assert build_parser().parse_args(["cost", "yu2021-a3", "--full"]).full
    assert build_parser().parse_args(["reproduce", "all", "--full"]).full
    assert not build_parser().parse_args(["reproduce", "all"]).full


def test_reproduce_schedules_the_cost_units_by_their_sweep():
    """``reproduce all`` starts the longest units first, by each unit's declared time for
    the sweep asked for: ``--full``'s full cost sweep lengthens the three cost units and
    moves each of them forward in the order (the fast sweep puts them behind the longest
    studies: the design's fatigue by three methods, the nonlinear time domains)."""
    from verification import studies
    for full in (False, True):
        order = studies.units("all", full)
        secs = [studies.study(s).unit_seconds(u, full) for s, u in order]
        assert secs == sorted(secs, reverse=True)
    fast, slow = studies.units("all"), studies.units("all", full=True)
    cost = [u for s, u in fast if s == "cost"]
    assert len(cost) == 3
    for u in cost:
        assert studies.study("cost").unit_seconds(u, True) > \
            studies.study("cost").unit_seconds(u, False)
        assert slow.index(("cost", u)) < fast.index(("cost", u)), u
    assert "cost" not in [s for s, _ in fast[:3]]


def _key(s):
    return (s.method, s.setting, s.value)


def test_fast_sweep_is_the_full_sweep_without_its_dear_rows():
    """``riser-verify cost SCENE`` (and ``reproduce all``) runs the fast sweep: the full
    sweep's rows in the same order, without the BVP mesh rows, the relaxation settings but
    the 5 m coarse mesh, and the order sweep at tight tolerances with its check; ``--full``
    runs every row."""
    from verification.catalog import resolve
    sc = resolve("yu2021-a3")
    full = settings.default_settings(sc, asymptotic=4.2, full=True)
    fast = settings.default_settings(sc, asymptotic=4.2)
    keys = [_key(s) for s in fast]
    assert keys == [_key(s) for s in full if _key(s) in set(keys)]      # same order
    kinds = {s.setting for s in fast}
    assert kinds == {"tolerance", "element_length", "coarse_element_length",
                     "dynamics_1s_element_length"}
    assert [s.value for s in fast if s.setting == "tolerance"] == list(settings.BVP_TOLERANCES)
    assert [s.value for s in fast if s.setting == "element_length"] == \
        list(settings.ELEMENT_LENGTHS)
    assert [s.value for s in fast if s.setting == "coarse_element_length"] == [5.0]
    dear = {"initial_nodes", "max_nodes", "time_step_safety", "static_tolerance",
            "rotational_inertia_scale", "element_length_tight", "element_length_tight_check"}
    assert dear <= {s.setting for s in full}
    assert len(full) - len(fast) == sum(1 for s in full if s.setting in dear) + 2  # 2, 20 m


def test_fast_sweep_report_says_what_needs_full(tmp_path):
    """The fast sweep fits no order and extrapolates no VFIFE limit (it has no order sweep),
    and its report says which sections need ``--full`` instead of showing numbers there."""
    import pandas as pd
    st = cost.study(touchdown_line(), repeats=1, element_lengths=(8.0, 4.0), progress=False)
    assert st.sweep == "fast" and not st.has_order_sweep
    assert not st.orders and not st.vfife_limit and not st.noise_floor
    assert all(not r.self_errors for r in st.runs if r.method == "vfife")
    assert st.bvp_self                                    # the BVP's own uncertainty is there
    assert "statics_tight" not in st.scaling and "statics" in st.scaling
    cost.write(st, tmp_path)
    text = (tmp_path / "report.md").read_text()
    assert "**Fast sweep, not the full study.**" in text
    assert text.count("**Needs `--full`") == 2          # the limit and the order sections
    assert "| fitted order |" not in text and "| VFIFE Richardson order |" not in text
    assert "| quantity | BVP reference uncertainty |\n" in text
    assert "`statics tight` row (the cost of the order sweep) needs `--full`" in text
    df = pd.read_csv(tmp_path / "runs.csv")
    assert "element_length_tight" not in set(df.setting)
    assert df[df.method == "vfife"].filter(like="self_").isna().all().all()
    assert df[df.method == "bvp"]["self_max_moment"].notna().all()
    assert "--full" in cost.report.index_row(tmp_path)[2]


def test_asymptotic_length_of_the_converted_wang_baseline():
    """sqrt(EI/T) at the lift-off and (4 EI/k)^(1/4) from independent inputs: EI of the
    steel tube (E pi/64 (Do^4 - Di^4), Table 1), the touchdown tension 160 kN (an input of
    the Wang form; the converted scene's lift-off tension is 159.87 kN: the elastic seabed
    and the stretch move it by 8e-4, 4e-4 in the root, hence rel=1e-3) and the seabed
    stiffness 1e5 N/m2. The asymptotic range ends at the shorter, the foundation length."""
    from verification.catalog import resolve
    from verification.pipeline import vfife_equivalent
    vf = vfife_equivalent(resolve("wang2014-baseline")).scene
    ref = bvp.solve(vf).profile
    do, t = 0.2032, 0.0191
    ei = 2.06e11 * math.pi / 64.0 * (do ** 4 - (do - 2 * t) ** 4)
    assert boundary_layer_length(vf, ref) == pytest.approx(math.sqrt(ei / 160000.0),
                                                            rel=1e-3)
    lf = (4.0 * ei / 1e5) ** 0.25
    assert foundation_length(vf, ref) == pytest.approx(lf, rel=1e-9)
    assert asymptotic_length(vf, ref) == pytest.approx(lf, rel=1e-9)


def test_order_sweep_has_three_lengths_in_the_asymptotic_range():
    """The order sweep (element_length_tight) runs ORDER_LENGTHS (20 ... 1 m, with 4, 3
    and 1.5 m: five lengths within the built-in scenes' 4.2-4.4 m), and finer ones only
    while fewer than three lie within the asymptotic range."""
    from verification.catalog import resolve
    sc = resolve("yu2021-a3")

    def tight(asym):
        return [s.value for s in settings.default_settings(sc, asymptotic=asym, full=True)
                if s.setting == "element_length_tight"]
    assert tight(27.0) == list(settings.ORDER_LENGTHS)
    assert tight(4.2) == list(settings.ORDER_LENGTHS)        # 4, 3, 2, 1.5, 1 in the fit
    assert tight(1.2) == [*settings.ORDER_LENGTHS, 0.5]      # 1 and 0.5: all there is
    check = [s for s in settings.default_settings(sc, full=True)
             if s.setting == "element_length_tight_check"]
    assert len(check) == 1
    assert check[0].solve_kwargs["tolerance"] == pytest.approx(settings.TIGHT_TOLERANCE / 10)
    assert check[0].vfife_changes["creep_tolerance"] == pytest.approx(settings.TIGHT_CREEP / 10)


def test_order_assessment_explains_departures():
    ok = {"order": 2.1, "points": [5.0, 2.0, 1.0], "r2": 0.99}
    assert "as expected" in assessment.order_assessment("max_moment", ok)
    two = {"order": 2.1, "points": [5.0, 2.0], "r2": 1.0}
    assert "two points only" in assessment.order_assessment("max_moment", two)
    low = {"order": 0.7, "points": [4.0, 2.0, 1.0], "r2": 0.95, "errors": [4e-4, 1e-4, 3e-5]}
    ctx = {"theta0": 0.0042, "kappa0": 1.4e-3, "coef": 1.4e-3 / (8 * 0.0042),
           "depth": 1586.3, "stiffness": 1e5}
    text = assessment.order_assessment("tdp_x", low, ctx)
    assert text.startswith("differs (order 0.70, R^2 0.95): the lift-off is read off the "
                           "nodal polyline")
    assert "0.0417 h^2 m" in text and "0.95, 0.95, 1.14 x that bound at 4, 2, 1 m" in text
    assert "the seabed reaction is lumped at the nodes" in assessment.order_assessment(
        "hang_off_tension", low, ctx)
    # a sign change of the error is pointed out with the signed errors
    low["signed"] = [4e-4, -1e-4, 3e-5]
    assert "changes sign (4-2 m, 2-1 m; signed errors +4.0e-04, -1.0e-04, +3.0e-05" in \
        assessment.order_assessment("max_moment", low)
    # a single sag whose worst mesh is the touchdown's worst (yu2021-a2-sheared, measured)
    sag = {"order": 1.55, "r2": 0.13, "points": [4.0, 3.0, 2.0, 1.5, 1.0],
           "errors": [7.9e-7, 7.6e-6, 1.3e-8, 8.4e-7, 2.2e-7]}
    tdp = {"points": sag["points"], "errors": [2.7e-5, 1.3e-3, 1.6e-4, 1.7e-4, 3.8e-5]}
    assert fits.worst_mesh(tdp) == 3.0 and fits.worst_mesh(sag) == 3.0
    assert fits.worst_mesh({"points": [4.0, 2.0, 1.0], "errors": [1.6e-3, 4e-4, 1e-4]}) is None
    text = assessment.order_assessment("sag_height", sag, {"n_sag_height": 1,
                                                           "touchdown_worst_mesh": 3.0})
    assert text.startswith("differs (order 1.55, R^2 0.13): a single sag bend")
    assert "on the 3 m mesh, as the touchdown tension's" in text
    # on order on average, but the points scatter about the line
    loose = {"order": 2.0, "points": [4.0, 2.0, 1.0], "r2": 0.6}
    assert assessment.order_assessment("max_moment", loose).startswith(
        "order 2 on average, but the errors scatter about the fitted line (R^2 0.60)")
    assert assessment.order_assessment("sag_height", {"order": None, "points": []}).startswith(
        "not fitted")


def test_order_assessment_flags_scattered_local_orders():
    """A fit near 2 over local orders 1.2, 1.2, 3.1 is not reported as plainly second
    order."""
    fit = {"order": 1.92, "points": [20.0, 10.0, 5.0, 2.0], "r2": 0.93,
           "local": [(20.0, 10.0, 1.24), (10.0, 5.0, 1.16), (5.0, 2.0, 3.10)]}
    text = assessment.order_assessment("sag_height", fit)
    assert text.startswith("order 2 on average, but the local orders in the fit scatter")
    fit["local"] = [(20.0, 10.0, 1.93), (10.0, 5.0, 1.97), (5.0, 2.0, 1.86)]
    assert assessment.order_assessment("sag_height", fit) == "order 2, as expected"

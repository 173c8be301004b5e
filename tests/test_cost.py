"""Cost study: the VFIFE convergence order in element length is pinned, plus the helpers.

Expected order 2: the VFIFE line is a chain of straight elements with lumped nodal weight;
element forces are constant along an element (they belong to its midpoint) and the
bending moment comes from the element-end rotations relative to the chord. Each is a
midpoint / central-difference approximation of the continuous beam, so positions, nodal
moments (average of the two element-end moments) and interior tensions (average of two
midpoint values) are O(h^2), and so is the peak moment, located by a parabola through the
nodal values. The scene is a single-segment line hanging between two pinned ends at the
same height (no seabed: no contact noise) with a bending length sqrt(EI/T) ~ 12 m, and a
static tolerance of 1e-6 so that the relaxation error (~1e-7) is far below the
discretisation error at 5 m (~6e-4). Measured: 2.005 (peak moment), 2.005 (sag height),
3.0 (hang-off tension: the end value extrapolated from two midpoint values is more
accurate than second order here). Band [1.8, 2.3] for moment and sag: the 20 m point is
just outside the bending length (pre-asymptotic, +0.3 at most in the fit); a first-order
regression (e.g. lumping the weight at one element end, or moments taken at element
midpoints and assigned to nodes) would give ~1 and fail.
"""

from __future__ import annotations

import io

import numpy as np
import pytest

import vfife
from riser.scene import scene_from_dict
from verification import cost

LENGTHS = (20.0, 10.0, 5.0, 2.5)


def hanging_line():
    d = {"name": "hanging-line", "environment": {"gravity": 9.81, "water_density": 1025.0},
         "line_types": {"p": {"outer_diameter": 0.3, "inner_diameter": 0.25,
                              "mass_per_length": 100.0, "axial_stiffness": 1e9,
                              "bending_stiffness": 1e7, "drag_normal": 1.0,
                              "drag_tangential": 0.0, "added_mass": 1.0}},
         "segments": [{"line_type": "p", "length": 240.0, "submerged_weight": 500.0}],
         "ends": {"anchor": [0.0, 100.0], "hang_off": [200.0, 100.0]}}
    return scene_from_dict(d, "test")


@pytest.fixture(scope="module")
def sweep():
    sc = hanging_line()
    values = []
    for h in LENGTHS:
        res = vfife.solve(sc, element_length=h, tolerance=1e-6)
        assert res.converged, res.message
        values.append(cost.raw_values(res.profile))
    norms = {"hang_off_tension": abs(values[-1]["hang_off_tension"]),
             "max_moment": abs(values[-1]["max_moment"]),
             "tdp_tension": 1.0, "tdp_x": 100.0, "crest_height": 100.0, "sag_height": 100.0}
    return cost.element_length_order(LENGTHS, values, norms)


@pytest.mark.parametrize("quantity", ["max_moment", "sag_height"])
def test_vfife_order_is_two(sweep, quantity):
    limits, rorders, self_err, fits = sweep
    fit = fits[quantity]
    assert fit["points"] == [20.0, 10.0, 5.0]
    assert 1.8 <= fit["order"] <= 2.3, fit
    key = "max_moment" if quantity == "max_moment" else "sag1_height"
    assert 1.8 <= rorders[key] <= 2.3        # three-grid Richardson order (10, 5, 2.5 m)
    errs = self_err[quantity]
    assert all(a > b for a, b in zip(errs, errs[1:]))     # monotone convergence


def test_hang_off_tension_at_least_second_order(sweep):
    fit = sweep[3]["hang_off_tension"]
    assert fit["order"] >= 1.8, fit


def test_richardson_recovers_a_known_limit():
    hs = [4.0, 2.0, 1.0, 0.5]
    qs = [3.0 + 0.7 * h ** 2 for h in hs]
    lim, p = cost.richardson(hs, qs)
    assert lim == pytest.approx(3.0, rel=1e-9)
    assert p == pytest.approx(2.0, abs=1e-6)
    # non-constant ratio, order 1.5
    hs = [20.0, 10.0, 5.0, 2.0, 1.0]
    qs = [1.0 - 0.1 * h ** 1.5 for h in hs]
    lim, p = cost.richardson(hs, qs)
    assert lim == pytest.approx(1.0, rel=1e-9) and p == pytest.approx(1.5, abs=1e-6)
    # non-monotone: no order, limit = finest value
    assert cost.richardson([4.0, 2.0, 1.0], [1.0, 2.0, 1.5]) == (1.5, None)


def test_fit_order_excludes_noise_and_pre_asymptotic_points():
    hs = [20.0, 10.0, 5.0, 2.0, 1.0]
    errs = [0.2, 1e-3, 2.5e-4, 4e-5, 1e-9]
    f = cost.fit_order(hs, errs, floor=1e-8)
    assert f["points"] == [10.0, 5.0, 2.0]
    assert f["order"] == pytest.approx(2.0, abs=0.01)


def test_pareto_front():
    pts = [(1.0, 1e-2), (2.0, 1e-3), (3.0, 5e-3), (0.5, 1e-1), (4.0, 1e-4)]
    assert cost.pareto(pts) == [(0.5, 1e-1), (1.0, 1e-2), (2.0, 1e-3), (4.0, 1e-4)]


def test_progress_reports_done_total_elapsed_remaining():
    buf = io.StringIO()
    p = cost.Progress(4, "x", stream=buf)
    p.step("a")
    p.step("b")
    line = buf.getvalue().splitlines()[-1]
    assert "2/4 runs" in line and "elapsed" in line and "remaining" in line


def test_cli_has_cost_command():
    from verification.cli import build_parser
    args = build_parser().parse_args(["cost", "wang2014-baseline", "--repeats", "1"])
    assert args.func.__name__ == "cmd_cost" and args.repeats == 1


def test_boundary_layer_is_the_touchdown_bending_length():
    """sqrt(EI/T_tdp) for the Wang baseline from independent inputs: EI of the steel tube
    (E pi/64 (Do^4 - Di^4), Table 1) and the touchdown tension, an input of the scene
    (160 kN). 1e-6: the BVP reproduces its own touchdown-tension input to round-off."""
    import math

    import bvp
    from verification.catalog import resolve
    from verification.equivalence import DEFAULT_SEABED_LENGTH, fixed_ends_via_bvp
    sc = resolve("wang2014-baseline")
    vf, _ = fixed_ends_via_bvp(sc)
    do, t = 0.2032, 0.0191
    ei = 2.06e11 * math.pi / 64.0 * (do ** 4 - (do - 2 * t) ** 4)
    bl = cost.boundary_layer_length(vf, DEFAULT_SEABED_LENGTH, bvp.solve(sc).profile)
    assert bl == pytest.approx(math.sqrt(ei / 160000.0), rel=1e-6)


def test_order_sweep_has_three_lengths_in_the_asymptotic_range():
    """The order sweep (element_length_tight) runs 20 ... 1 m, and 0.5 m only when fewer
    than three lengths between its finest and the boundary layer would enter the fit."""
    from verification.catalog import resolve
    sc = resolve("yu2021-a3")

    def tight(bl):
        return [s.value for s in cost.default_settings(sc, boundary_layer=bl)
                if s.setting == "element_length_tight"]
    assert tight(27.0) == [20.0, 10.0, 5.0, 2.0, 1.0]       # 20, 10, 5, 2 in the fit
    assert tight(7.8) == [20.0, 10.0, 5.0, 2.0, 1.0, 0.5]   # 5, 2, 1 in the fit
    check = [s for s in cost.default_settings(sc) if s.setting == "element_length_tight_check"]
    assert len(check) == 1
    assert check[0].solve_kwargs["tolerance"] == pytest.approx(cost.TIGHT_TOLERANCE / 10)
    assert check[0].vfife_changes["creep_tolerance"] == pytest.approx(cost.TIGHT_CREEP / 10)


def test_order_assessment_explains_departures():
    ok = {"order": 2.1, "points": [5.0, 2.0, 1.0], "r2": 0.99}
    assert "as expected" in cost.order_assessment("max_moment", ok)
    two = {"order": 2.1, "points": [5.0, 2.0], "r2": 1.0}
    assert "two points only" in cost.order_assessment("max_moment", two)
    low = {"order": 0.7, "points": [20.0, 10.0, 5.0], "r2": 0.95}
    assert cost.order_assessment("tdp_x", low).startswith("differs: the line meets")
    assert cost.order_assessment("sag_height", {"order": None, "points": []}).startswith(
        "not fitted")


def test_order_assessment_flags_scattered_local_orders():
    """A fit near 2 over local orders 1.2, 1.2, 3.1 (yu2021-a2-sheared sag heights) is not
    reported as plainly second order."""
    fit = {"order": 1.92, "points": [20.0, 10.0, 5.0, 2.0], "r2": 0.93,
           "local": [(20.0, 10.0, 1.24), (10.0, 5.0, 1.16), (5.0, 2.0, 3.10)]}
    text = cost.order_assessment("sag_height", fit)
    assert text.startswith("order 2 on average, but the local orders in the fit scatter")
    fit["local"] = [(20.0, 10.0, 1.93), (10.0, 5.0, 1.97), (5.0, 2.0, 1.86)]
    assert cost.order_assessment("sag_height", fit) == "order 2, as expected"

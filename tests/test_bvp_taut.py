"""Taut and nearly taut lines of any weight by the BVP (issue 29).

The start of a line between pinned ends is the elastic catenary, solved by two nested,
bracketed root finds (``bvp.beam.catenary.pinned``) in cancellation-free closed forms
(``bvp.beam.catenary._segment_offsets``); where the catenary dips into an elastic seabed the
unilateral form walks the seabed stiffness up from none (``bvp.strategy``). Checked here
against an independent closed form: Irvine's elastic catenary written out below in 40-digit
arithmetic (the standard library's ``decimal``) and solved by Newton's method with its
analytic Jacobian, started from the BVP's own end forces (the start only picks the root;
the equations decide it).

Before: 0.5 N/m lines 1e-5 longer or shorter than the chord failed ("no free-hanging
catenary found"), lines stretched onto a seabed ended in "singular Jacobian" or "maximum
number of mesh nodes exceeded": 79 of the 320 lines of the grid below.
"""

from __future__ import annotations

import itertools
import math
from decimal import Decimal, localcontext

import numpy as np
import pytest

from builders import line, scene, small_pipe
import bvp
from bvp.beam.catenary import _segment_offsets, end_offsets, end_offsets_rows, \
    horizontal_tensions, pinned

DIGITS = 40                                     # of the closed form (decimal)


def _d(v):
    """A float (or int) as the Decimal of the same value, exactly."""
    return Decimal(float(v)) if not isinstance(v, (Decimal, int)) else Decimal(v)


def _asinh(x):
    """asinh of a Decimal in the current context: sign(x) ln(|x| + sqrt(x^2 + 1)), the
    odd symmetry sparing negative x the cancellation of x + sqrt(x^2 + 1)."""
    r = abs(x)
    r = (r + (r * r + 1).sqrt()).ln()
    return -r if x < 0 else r


# ------------------------------------------------------------------ the closed form
def irvine(w, L, EA, dx, dy, H0, V00):
    """(H, V0) of the elastic catenary of one segment (weight w [N/m], unstretched length
    L [m], EA [N]) from (0, 0) to (dx, dy) [m], by Newton's method in 40 digits from
    (H0, V00) [N]; and its x(s), y(s) [m]."""
    with localcontext(prec=DIGITS):
        w, L, EA, dx, dy = (_d(v) for v in (w, L, EA, dx, dy))

        def x_of(H, V0, s):
            return H / w * (_asinh((V0 + w * s) / H) - _asinh(V0 / H)) + H * s / EA

        def y_of(H, V0, s):
            V = V0 + w * s
            return (H / w * ((1 + (V / H) ** 2).sqrt() - (1 + (V0 / H) ** 2).sqrt())
                    + (V0 * s + w * s * s / 2) / EA)

        def jacobian(H, V0):
            # d(x, y)/d(H, V0) at s = L, with a = V0 / H, b = (V0 + w L) / H,
            # Ta = sqrt(1 + a^2), Tb = sqrt(1 + b^2); symmetric (dx/dV0 = dy/dH)
            a, b = V0 / H, (V0 + w * L) / H
            Ta, Tb = (1 + a * a).sqrt(), (1 + b * b).sqrt()
            xH = (_asinh(b) - _asinh(a) - (b / Tb - a / Ta)) / w + L / EA
            xV = (1 / Tb - 1 / Ta) / w
            yV = (b / Tb - a / Ta) / w + L / EA
            return xH, xV, xV, yV

        H, V0 = _d(H0), _d(V00)
        for _ in range(60):
            fx, fy = x_of(H, V0, L) - dx, y_of(H, V0, L) - dy
            xH, xV, yH, yV = jacobian(H, V0)
            det = xH * yV - xV * yH
            dH, dV = (yV * fx - xV * fy) / det, (xH * fy - yH * fx) / det
            while H - dH <= 0:                       # keep H > 0: shorten the step
                dH, dV = dH / 2, dV / 2
            H, V0 = H - dH, V0 - dV
            if abs(dH) + abs(dV) <= Decimal("1e-30") * (abs(H) + abs(V0)):
                break
        else:
            raise AssertionError(f"Irvine's Newton did not converge: step {dH}, {dV}")

    def at(f, s):
        with localcontext(prec=DIGITS):
            return float(f(H, V0, _d(s)))

    return H, V0, (lambda s: at(x_of, s)), (lambda s: at(y_of, s))


def _taut(slack, EA, w=0.5, EI=1.0, hang_off=(100.0, 50.0), anchor=(0.0, 0.0), seabed=None):
    """One segment between fixed ends, (1 + slack) times the chord long (slack < 0: it
    must stretch), small pipe of EI [N m2], EA [N], submerged weight w [N/m]."""
    chord = math.hypot(hang_off[0] - anchor[0], hang_off[1] - anchor[1])
    return scene(line(chord * (1.0 + slack), anchor, hang_off, submerged_weight=w,
                      line_type=small_pipe(axial_stiffness=EA, bending_stiffness=EI),
                      seabed=seabed))


# ------------------------------------------------------------------ the closed forms in bvp
def test_the_segment_offsets_have_no_cancellation():
    # random segments from a slack hanging line to one 1e8 times tauter than its weight,
    # buoyant ones and lines through their vertex, against 50-digit arithmetic: relative to
    # the segment length, at most 1e-15 (measured 4.9e-16); the former formula H/w (asinh b
    # - asinh a) erred by up to 0.44 of the length on these samples (1.8 % at
    # w ds / H = 1.5e-9, V/H = -3e5: the digits of w ds / H lost in the difference)
    rng = np.random.default_rng(7)
    worst = 0.0
    with localcontext(prec=50):
        for _ in range(2000):
            H = 10 ** rng.uniform(-3, 8)
            w = rng.choice([-1.0, 1.0]) * 10 ** rng.uniform(-6, 4)
            ds = 10 ** rng.uniform(-3, 3.5)
            Va = rng.choice([-1.0, 1.0]) * 10 ** rng.uniform(-4, 8)
            if rng.random() < 0.2:
                Va = -w * ds * rng.uniform(0.0, 1.0)          # through the vertex
            dx, dy = _segment_offsets(np.array([ds]), w, H, Va, 0.0)
            Hd, wd, dsd, Vad = _d(H), _d(w), _d(ds), _d(Va)
            a, b = Vad / Hd, (Vad + wd * dsd) / Hd
            ex = Hd / wd * (_asinh(b) - _asinh(a))
            ey = Hd / wd * ((1 + b * b).sqrt() - (1 + a * a).sqrt())
            worst = max(worst, float(abs(_d(dx[0]) - ex) / dsd),
                        float(abs(_d(dy[0]) - ey) / dsd))
    assert worst < 1e-15, worst


def test_a_near_weightless_segment_is_straight_without_a_warning():
    """w = 1e-306 N/m (a fuzzed input): H / w overflows in the branch that is not used;
    the offsets are the straight segment's along (H, V) and no RuntimeWarning leaks (the
    deck fuzzer met one)."""
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        dx, dy = _segment_offsets(np.array([10.0]), np.array([1e-306]), 1e5,
                                  np.array([1.0]), np.array([0.0]))
    # a straight line along the force (H, V) = (1e5, 1) N; round-off only
    assert dx[0] == pytest.approx(10.0 / math.hypot(1.0, 1e-5), rel=1e-13)
    assert dy[0] == pytest.approx(10.0 * 1e-5 / math.hypot(1.0, 1e-5), rel=1e-9)


@pytest.mark.parametrize("slack, EA", [(1e-2, 1e9), (1e-5, 1e9), (0.0, 1e9), (-1e-5, 1e9),
                                       (-1e-3, 1e9), (1e-5, 1e6), (-1e-3, 1e6)])
def test_the_pinned_catenary_is_found_slack_to_stretched(slack, EA):
    # the former least-squares search failed from 1e-5 slack on at EA = 1e9, w = 0.5 N/m
    chord = math.hypot(100.0, 50.0)
    L = chord * (1.0 + slack)
    H, V0 = pinned(np.array([0.5]), np.array([L]), 100.0, 50.0, np.array([EA]))
    Hc, Vc, _, _ = irvine(0.5, L, EA, 100.0, 50.0, H, V0)
    assert H == pytest.approx(float(Hc), rel=1e-10)
    assert V0 == pytest.approx(float(Vc), rel=1e-10, abs=1e-10 * float(Hc))
    x, y = end_offsets([0.5], [L], H, V0, [EA])
    assert abs(x - 100.0) + abs(y - 50.0) < 1e-9 * L


def test_the_pinned_catenary_of_a_buoyant_multi_segment_line():
    # weights of both signs and three stiffnesses: the nested searches need no one sign
    w, L, EA = np.array([300.0, -150.0, 200.0]), np.array([400.0, 300.0, 800.0]), \
        np.array([1e9, 5e8, 2e9])
    H, V0 = pinned(w, L, 1200.0, 600.0, EA)
    x, y = end_offsets(w, L, H, V0, EA)
    assert abs(x - 1200.0) < 1e-9 and abs(y - 600.0) < 1e-9
    assert pinned(w, L, -5.0, 600.0, EA) is None            # needs the hang-off ahead


def test_the_grid_of_starting_catenaries_at_once_equals_one_at_a_time():
    # bvp/guess.grounded finds its bracket with every grid row at once: each row's end
    # and its H must be those of the scalar end_offsets and a Brent search on the same
    # bracket (a lazy wave: weights of both signs; rows from the first segment whole to
    # almost all of it grounded)
    from scipy.optimize import brentq
    w = np.array([900.0, -600.0, 900.0])       # segments 800, 400 and 1000 m
    rows = np.array([[l1, 400.0, 1000.0] for l1 in np.linspace(800.0, 0.8, 9)])
    H = np.geomspace(1e4, 1e7, 9)
    x, y = end_offsets_rows(w, rows, H)
    for i in range(9):
        xs, ys = end_offsets(w, rows[i], H[i], 0.0)
        # the same formulas on the same numbers: equal to the sums' rounding
        assert abs(x[i] - xs) <= 1e-12 * rows[i].sum() and abs(y[i] - ys) <= 1e-12 * rows[i].sum()
    lo, hi = math.log(1e-3), math.log(1e9)
    Hb = horizontal_tensions(w, rows, 1200.0, lo, hi)
    for i in range(9):
        f = lambda lh: end_offsets(w, rows[i], math.exp(lh), 0.0)[1] - 1200.0  # noqa: E731
        if f(lo) * f(hi) > 0:
            assert np.isnan(Hb[i])                 # no H lifts this line's end to 1200 m
        else:                                      # both to xtol 1e-12 in log H
            assert Hb[i] == pytest.approx(math.exp(brentq(f, lo, hi, xtol=1e-12)), rel=1e-11)
    assert np.isfinite(Hb).sum() == 7              # both kinds of row met (measured 7 of 9)


# ------------------------------------------------------------------ the BVP on taut lines
TAUT = [(s, EA) for EA in (1e9, 1e6) for s in (1e-2, 1e-3, 1e-4, 1e-5, 0.0, -1e-5, -1e-3)]


@pytest.mark.parametrize("slack, EA", TAUT, ids=[f"slack{s:g}-EA{EA:g}" for s, EA in TAUT])
def test_a_taut_light_line_is_the_elastic_catenary(slack, EA):
    # 0.5 N/m over a 112 m chord, 1 % slack to 0.1 % stretch. EI = 1 N m2 makes bending a
    # correction of order EI / (H L^2) <= 7e-7 (H >= 118 N), so the elastic catenary is
    # the reference to 1e-4: measured 1e-8 .. 8e-6 in the end tensions and 4e-7 .. 7e-6 of
    # the sag in the shape (with EI = 1e3 the bending itself is 1e-4 .. 7e-3)
    sc = _taut(slack, EA)
    r = bvp.solve(sc)
    assert r.converged, r.message
    p = r.profile
    H0, V00 = p.tension[0] * math.cos(p.theta[0]), p.tension[0] * math.sin(p.theta[0])
    L = sc.segments[0].length
    H, V0, x_of, y_of = irvine(0.5, L, EA, 100.0, 50.0, H0, V00)
    with localcontext(prec=DIGITS):
        top = float((H ** 2 + (V0 + Decimal("0.5") * _d(L)) ** 2).sqrt())
        bottom = float((H ** 2 + V0 ** 2).sqrt())
    assert p.tension[-1] == pytest.approx(top, rel=1e-4)
    assert p.tension[0] == pytest.approx(bottom, rel=1e-4)
    s = p.s[:: max(1, p.s.size // 300)]
    xs, ys = np.array([x_of(v) for v in s]), np.array([y_of(v) for v in s])
    sag = float(np.max(0.5 * xs - ys))                     # below the chord y = x / 2
    assert sag > 0.0
    i = np.searchsorted(p.s, s)
    assert np.max(np.hypot(p.x[i] - xs, p.y[i] - ys)) < 1e-4 * sag


@pytest.mark.parametrize("slack", [1e-2, 1e-4, -1e-3])
def test_a_taut_light_line_agrees_with_the_vfife(slack):
    # the independent method at its defaults (1 m elements): measured 1.4e-5 .. 4e-5 in the
    # hang-off tension; 2e-4 leaves room for its stopping rule (issue 29, item 2)
    import vfife
    sc = _taut(slack, 1e6)
    b, v = bvp.solve(sc), vfife.solve(sc)
    assert b.converged and v.converged, (b.message, v.message)
    assert v.profile.tension[-1] == pytest.approx(b.profile.tension[-1], rel=2e-4)


# ------------------------------------------------------------------ onto a seabed
@pytest.mark.parametrize("anchor", [(0.0, 0.0), (0.0, 5.0)])
def test_a_line_stretched_onto_an_elastic_seabed_is_solved(anchor):
    # 10 N/m, EA 1e6, 0.1 % shorter than the chord to (1000, 50): stretched, it still sags
    # 54 m below the seabed as a free catenary; before, "singular Jacobian". Now the seabed
    # stiffness is walked up from none. In contact the line sinks w / k = 0.1 mm; the
    # global force balance closes; its tension falls towards the anchor by the seabed's
    # share of the weight
    sc = _taut(-1e-3, 1e6, w=10.0, EI=1e3, hang_off=(1000.0, 50.0), anchor=anchor,
               seabed={"stiffness": 1e5})
    r = bvp.solve(sc)
    assert r.converged, r.message
    assert "continuation in seabed stiffness" in r.message
    p = r.profile
    assert np.min(p.y) == pytest.approx(-1e-4, rel=0.15)     # w / k, and a lift-off bump
    assert np.sum(p.y < 0.0) > 100                           # a real contact zone
    assert r.info["equilibrium_residual"] < 1e-6


def test_a_line_too_long_for_its_span_on_a_seabed_is_no_equilibrium():
    # 1 % slack between (0, 0) and (1000, 10): more than 1,000 m along the seabed and 10 m
    # up; a stated no_equilibrium, not a failure to converge
    r = bvp.solve(_taut(1e-2, 1e9, w=10.0, EI=1e3, hang_off=(1000.0, 10.0),
                        seabed={"stiffness": 1e5}))
    assert r.status.value == "no_equilibrium"
    assert "too long for the span" in r.message


# ------------------------------------------------------------------ the grid of issue 29
GRID = list(itertools.product([(100.0, 50.0), (800.0, 600.0), (1000.0, 10.0), (1000.0, 50.0)],
                              [0.5, 10.0], [1e6, 1e9], [-1e-3, -1e-5, 1e-5, 1e-4, 1e-2],
                              [(0.0, 0.0), (0.0, 5.0)], [False, True]))


@pytest.mark.slow
def test_the_taut_line_grid_converges_wherever_an_equilibrium_exists():
    # 320 lines: EI 1e3 N m2, OD 0.1 m; before 79 failed (issue 29), measured now: 312
    # converged, 8 no_equilibrium (the 1 % longer lines from (0, 0) to (1000, 10): longer
    # than 1,000 m along y = 0 plus 10 m up, with or without a seabed); ~210 s on 2 cores.
    # The global force balance of each (relative to the larger of the largest tension and
    # the line's weight: a slack light line on the seabed carries 21 N for 505 N of weight)
    # closes to 1e-5, measured <= 3.5e-6
    bad = []
    for ho, w, EA, slack, anchor, seabed in GRID:
        r = bvp.solve(_taut(slack, EA, w=w, EI=1e3, hang_off=ho, anchor=anchor,
                            seabed={"stiffness": 1e5} if seabed else None))
        length = math.hypot(ho[0] - anchor[0], ho[1] - anchor[1]) * (1 + slack)
        if (length > anchor[1] + ho[0] + ho[1] and r.status.value == "no_equilibrium"
                and "too long" in r.message):
            continue
        if not r.converged:
            bad.append((ho, w, EA, slack, anchor, seabed, r.status.value, r.message[:120]))
            continue
        T = float(np.max(np.abs(r.profile.tension)))
        balance = r.info["equilibrium_residual"] * T / max(T, w * length)
        if balance > 1e-5:
            bad.append((ho, w, EA, slack, anchor, seabed, "force balance", balance))
    assert not bad, bad


@pytest.mark.parametrize("name", ["scr-steel", "yu2021-a3"])
def test_the_grid_at_once_gives_the_guess_of_the_point_by_point_scan(name):
    # the bench's reference (bvp.beam.guess.SCALAR_GRID: the scan before issue 36, each grid
    # point's H by Brent and the end by sampling the catenary's state) and the grid at
    # once find the same bracket and then the same root by the same scalar search: the
    # same guess, so the same solve, bit for bit
    from bvp.beam.guess import SCALAR_GRID
    from verification.catalog import resolve
    import bvp
    sc = resolve(name)
    a = bvp.solve(sc).require()
    SCALAR_GRID.on = True
    try:
        b = bvp.solve(sc).require()
    finally:
        SCALAR_GRID.on = False
    for key in ("s", "x", "y", "tension", "moment"):
        assert np.array_equal(getattr(a.profile, key), getattr(b.profile, key)), key

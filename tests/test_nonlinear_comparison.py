"""The time-domain comparison of the VFIFE against the ANCF (``compare SCENE --time-domain``,
verification/comparison/nonlinear/): the tolerance arithmetic on synthetic levels (closed
forms of q(h) = q* + C h^p), the refusals, the stations on a static profile; slow: one small
case end to end, which passes, and a negative control, which must fail."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from verification.comparison.nonlinear import stations
from verification.comparison.nonlinear.tolerances import (FLOOR, combine, estimate,
                                                          observed_order)


def test_coarsened_levels_of_a_second_order_quantity():
    # q(h) = 1 + 0.1 h^2 at h = 4, 2, 1: changes 1.2 and 0.3, order 2 exactly; the error
    # of the default (h = 1) is 0.1, the last change 0.3 bounds it (the rule for p >= 1)
    e = estimate("m", "element length", (4.0, 2.0, 1.0), [1 + 0.1 * h ** 2 for h in (4, 2, 1)])
    assert e.order == pytest.approx(2.0, abs=1e-9)
    assert e.error == pytest.approx(0.3, rel=1e-12)
    assert e.error >= 0.1
    assert e.converged


def test_slow_order_takes_richardson():
    # q = h^0.7: the last change underestimates the error at h = 1 (exactly 1): Richardson
    # from the three levels gives it back to round-off
    e = estimate("m", "time step", (4.0, 2.0, 1.0), [h ** 0.7 for h in (4.0, 2.0, 1.0)],
                 scale=100.0)
    assert e.order == pytest.approx(0.7, abs=1e-9)
    assert e.note == "Richardson"
    assert e.error == pytest.approx(1.0, rel=1e-9)


def test_refined_levels_estimate_the_coarsest():
    # a refinement from the default dt = 1: q = 5 + 0.2 dt (order 1): the error of the
    # default is 0.2 exactly, Richardson from the default
    e = estimate("ancf", "time step", (1.0, 0.5, 0.25), [5 + 0.2 * d for d in (1, .5, .25)],
                 default="coarsest")
    assert e.order == pytest.approx(1.0, abs=1e-9)
    assert e.error == pytest.approx(0.2, rel=1e-9)


def test_uneven_levels_recover_the_order():
    # a step made a divisor of the sampling interval: levels 0.35, 0.175, 0.1167 (ratios 2
    # and 1.5); q = dt^2 gives order 2 back, and the error at the finest dt^2 exactly
    h = np.array([0.35, 0.175, 0.35 / 3])
    assert observed_order(h, h[0] ** 2 - h[1] ** 2, h[1] ** 2 - h[2] ** 2) == pytest.approx(
        2.0, abs=1e-9)
    e = estimate("ancf", "time step", h, list(h ** 2), scale=1.0)
    assert e.error == pytest.approx(max(h[1] ** 2 - h[2] ** 2, h[2] ** 2), rel=1e-6)


def test_not_converged_levels_are_never_judged():
    # non-monotone (the change flips sign) and too slow an order (0.3 < 0.5): no error,
    # and the row they make is "not judged", with the numbers
    flip = estimate("vfife", "element length", (4, 2, 1), [1.0, 1.2, 1.1])
    slow = estimate("vfife", "element length", (4, 2, 1), [h ** 0.3 for h in (4, 2, 1)])
    assert not flip.converged and "non-monotone" in flip.note
    assert not slow.converged and slow.order == pytest.approx(0.3, abs=1e-9)
    ok = estimate("ancf", "time step", (4, 2, 1), [1 + 0.1 * h ** 2 for h in (4, 2, 1)])
    t = combine([flip, ok])
    assert t.value is None and t.reason.startswith("not judged: not converged (vfife")
    assert "0.2" in t.reason                     # the changes are stated


def test_changes_below_the_floor_are_noise_and_sum():
    # changes below FLOOR x the scale: converged, the error at least the floor; the row's
    # tolerance is the sum of the parts, the largest named
    tiny = estimate("vfife", "time step", (4, 2, 1), [1.0, 1.0 + 1e-7, 1.0], scale=1.0)
    assert tiny.converged and tiny.error == pytest.approx(FLOOR)
    big = estimate("ancf", "element length", (4, 2, 1), [1 + 0.1 * h ** 2 for h in (4, 2, 1)])
    t = combine([tiny, big])
    assert t.value == pytest.approx(0.3 + FLOOR)
    assert t.reason.startswith("ancf element length dominates")


def test_arrays_use_the_rms_of_their_changes():
    # a series q(t; h) = sin t + 0.01 h^2 cos t: the rms of a change is 0.01 (dh^2)/sqrt 2
    t = np.linspace(0, 2 * np.pi, 4001)[:-1]
    lv = [np.sin(t) + 0.01 * h ** 2 * np.cos(t) for h in (4, 2, 1)]
    e = estimate("m", "element length", (4, 2, 1), lv)
    assert e.order == pytest.approx(2.0, abs=1e-9)
    assert e.error == pytest.approx(0.03 / np.sqrt(2), rel=1e-6)


def lazy_wave_profile():
    """A synthetic lazy wave: on the seabed to s = 100 m, then y = 40 + 0.5 u - 60 sin(2 pi
    u / 400) (u = s - 100 m): a sag bend (y' = 0 at cos = 0.531, u = 64.4 m) and a hog
    bend (u = 335.6 m) before the hang-off at s = 500 m."""
    s = np.linspace(0.0, 500.0, 501)
    u = s - 100.0
    y = np.where(s < 100, -1e-3, 40 + 0.5 * u - 60 * np.sin(2 * np.pi * u / 400))
    return SimpleNamespace(s=s, y=y, curvature=np.gradient(np.gradient(y, s), s), tdp_s=100.0)


def test_stations_on_a_lazy_wave():
    p = lazy_wave_profile()
    got = dict(stations.pick(p, (SimpleNamespace(s=300.0, label="buoy"),), h=1.0))
    assert got["hang-off"] == 500.0 and got["touchdown"] == 100.0
    # the sag and hog bends: the interior extrema of y, read off the profile itself
    i_sag = np.argmin(np.where((p.s > 120) & (p.s < 300), p.y, np.inf))
    i_hog = np.argmax(np.where((p.s > 300) & (p.s < 480), p.y, -np.inf))
    assert got["sag bend"] == p.s[i_sag] and got["hog bend"] == p.s[i_hog]
    assert abs(got["sag bend"] - 164.4) < 1 and abs(got["hog bend"] - 435.6) < 1
    assert got["attachment buoy"] == 300.0


def test_stations_on_a_catenary():
    # a catenary on the seabed: no interior extremum; the sag bend is the largest static
    # curvature above the touchdown
    s = np.linspace(0, 1000, 1001)
    k = np.where(s > 300, 1e-3 * np.exp(-(s - 310) / 50), 0.0)
    p = SimpleNamespace(s=s, y=np.clip(s - 300, 0, None) ** 1.5 / 20, curvature=k,
                        tdp_s=300.0)
    got = stations.pick(p, (), h=1.0)
    assert [n for n, _ in got] == ["hang-off", "touchdown", "sag bend"]
    assert dict(got)["sag bend"] == 302.0      # the first node 2 h past the touchdown


def test_time_domain_refusals(run_cli):
    code, out, err = run_cli(["compare", "scr-steel", "--time-domain"])
    assert code == 2 and err.count("\n") == 1 and "dynamics" in err
    code, out, err = run_cli(["compare", "scr-steel", "--time-domain", "--dynamics"])
    assert code == 2 and "--dynamics" in err and "--time-domain" in err
    code, out, err = run_cli(["compare", "scr-steel", "--time-domain", "--peer", "moordyn"])
    assert code == 2 and "--peer" in err


@pytest.mark.slow
def test_small_case_passes_and_a_control_fails():
    """The Lowe and Langley jumper in its wave (170 m, its own 50 s of [dynamics]), both
    methods at their levels: every judged row within its measured tolerance; the ANCF's drag
    5 % higher (the wave's load on the jumper is drag-dominated) fails the comparison."""
    from verification.catalog import resolve
    from verification.comparison.nonlinear.protocol import compare_time_domain
    comp = compare_time_domain(resolve("lowe-langley-case4"), controls=("drag",))
    assert len(comp.judged) >= 5, [r["tolerance_reason"] for r in comp.rows]
    assert comp.passed, [(r["quantity"], r["station"], r["abs_diff"], r["tolerance"])
                         for r in comp.judged if not r["pass"]]
    assert comp.control_failed("drag")

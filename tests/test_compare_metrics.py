"""The comparison protocol's metrics against exact geometry (no solver involved)."""

from __future__ import annotations

import numpy as np
import pytest

from riser.profile import Profile, summarize
from verification.compare import agreement, curve_distance


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
    q.s = q.s + 50.0
    rows = agreement(p, q, depth=100.0, s_shift=50.0)
    assert all(r["pass"] for r in rows), rows
    by = {r["quantity"]: r for r in rows}
    assert by["tension"]["abs_diff"] == pytest.approx(0.0, abs=1e-9)
    assert by["configuration"]["abs_diff"] == pytest.approx(0.0, abs=1e-9)


def test_agreement_detects_tension_offset():
    # negative control of the metric itself: +1 % tension everywhere must fail the 0.5 % rule
    p, q = arc(100.0, 800), arc(100.0, 800)
    q.tension = q.tension * 1.01
    by = {r["quantity"]: r for r in agreement(p, q, depth=100.0)}
    assert not by["tension"]["pass"]
    assert by["tension"]["rel_diff"] == pytest.approx(0.01, rel=1e-6)


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


def _two_peaks(a1: float, a2: float) -> Profile:
    """A profile whose moment has two Gaussian peaks of heights a1 (s = 100 m) and a2
    (s = 400 m)."""
    s = np.linspace(0.0, 500.0, 5001)
    m = a1 * np.exp(-((s - 100.0) / 10.0) ** 2) + a2 * np.exp(-((s - 400.0) / 10.0) ** 2)
    one = np.ones_like(s)
    return Profile(s=s, x=s, y=0 * s, z=0 * s, theta=0 * s, tension=one, moment=m,
                   shear=0 * s, curvature=0 * s)


def test_peak_location_ties_are_not_a_300_m_error():
    from verification.compare import peak_location_distance
    # two peaks within 0.01 % of each other: which one is 'the' maximum is decided by
    # noise, so the location distance is that of the nearest near-maximum peaks (0 m)
    b, v = _two_peaks(1000.0, 999.9), _two_peaks(999.9, 1000.0)
    assert peak_location_distance(b, v, tol=20.0) == pytest.approx(0.0, abs=1e-9)
    # a real difference (10 % apart, beyond the 2 % tolerance) is still 300 m
    b, v = _two_peaks(1000.0, 900.0), _two_peaks(900.0, 1000.0)
    assert peak_location_distance(b, v, tol=20.0) == pytest.approx(300.0, abs=0.2)


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

"""A vessel's RAOs between its tables' headings (riser/physics/vessel.py,
``Vessel.complex_rao``): the amplitude and the unwrapped phase linear in the heading,
periodic over 360 deg, as they are linear in the period between a table's rows.

The references are written here: the amplitude and phase interpolated by hand, and the
complex-linear rule (the mean of the complex values, the rule before) as the negative
control that a phase passing through +-180 deg exposes.
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from riser.physics.vessel import DOFS, RAOTable, Vessel
from verification.catalog import builtin_paths, resolve


def table(heading, amp=(1.0, 1.0), phase=(0.0, 0.0), periods=(5.0, 15.0)):
    """One RAO table: every DOF the same ``amp`` (m/m or deg/m) and ``phase`` [deg]."""
    return RAOTable(heading_deg=heading, periods=periods, **{d: amp for d in DOFS},
                    **{f"{d}_phase_deg": phase for d in DOFS})


def lag(z: complex) -> float:
    """The phase lag [deg] of R e^{-i phi}, in [0, 360)."""
    return math.degrees(-cmath.phase(z)) % 360.0


def complex_linear(tabs, T, rel):
    """The complex-linear rule between the two tables around ``rel`` [deg] (the
    negative control): (1 - w) R0 + w R1 of the tables' complex RAOs."""
    tabs = sorted(tabs, key=lambda t: t.heading_deg % 360.0)
    hs = [t.heading_deg % 360.0 for t in tabs]
    j = max(i for i, h in enumerate(hs) if h <= rel % 360.0) if rel % 360.0 >= hs[0] else -1
    t0, t1 = tabs[j % len(tabs)], tabs[(j + 1) % len(tabs)]
    span = (t1.heading_deg - t0.heading_deg) % 360.0 or 360.0
    w = ((rel - t0.heading_deg) % 360.0) / span
    return (1.0 - w) * t0.complex_rao([T])[:, 0] + w * t1.complex_rao([T])[:, 0]


def test_phase_through_180_gives_the_midway_phase_not_a_collapse():
    """Tables at 0 and 90 deg, amplitude 1, phase lags 100 and -100 (= 260) deg: halfway
    (45 deg) the phase is 180 deg (the shorter way, through +-180) and the amplitude 1,
    exactly. The complex-linear rule gives |cos 100 deg| = 0.17: the amplitude collapses
    (asserted here to be caught by the same check); the phase linear the long way (100
    -> 260 read as 100 -> -100) would give 0 deg."""
    tabs = (table(0.0, phase=(100.0, 100.0)), table(90.0, phase=(-100.0, -100.0)))
    R = Vessel(raos=tabs).complex_rao([10.0], [45.0])[:, 0]
    for j, dof in enumerate(DOFS):
        unit = math.radians(1.0) if j >= 3 else 1.0
        assert abs(R[j]) == pytest.approx(unit, rel=1e-14), dof
        assert lag(R[j]) == pytest.approx(180.0, abs=1e-12), dof
    bad = complex_linear(tabs, 10.0, 45.0)
    assert abs(bad[2]) == pytest.approx(abs(math.cos(math.radians(100.0))), rel=1e-12)
    assert not abs(bad[2]) == pytest.approx(1.0, rel=0.1)        # the check catches it
    # a quarter of the way: the phase 100 + 0.25 x 160 = 140 deg, amplitude linear too
    tabs2 = (table(0.0, amp=(2.0, 2.0), phase=(100.0, 100.0)),
             table(90.0, amp=(4.0, 4.0), phase=(-100.0, -100.0)))
    R = Vessel(raos=tabs2).complex_rao([10.0], [22.5])[2, 0]
    assert abs(R) == pytest.approx(2.5, rel=1e-14)
    assert lag(R) == pytest.approx(140.0, abs=1e-12)


def test_periodic_over_360_and_relative_to_the_vessel_heading():
    """Tables at 90 and 270 deg relative to the surge axis: a wave at 0 (or 360, or -360)
    lies halfway between 270 and 90 across 360 deg; with the vessel turned by 30 deg a
    wave at 30 deg is the same relative heading. Amplitudes 1 and 3 -> 2; lags 170 and
    -170 -> 180 (through +-180 again)."""
    tabs = (table(90.0, amp=(1.0, 1.0), phase=(170.0, 170.0)),
            table(270.0, amp=(3.0, 3.0), phase=(-170.0, -170.0)))
    R = Vessel(raos=tabs).complex_rao([8.0, 8.0, 8.0, 8.0], [0.0, 360.0, -360.0, 180.0])
    for i in range(3):
        assert abs(R[0, i]) == pytest.approx(2.0, rel=1e-14)
        assert lag(R[0, i]) == pytest.approx(180.0, abs=1e-12)
    assert abs(R[0, 3]) == pytest.approx(2.0, rel=1e-14)           # 180: halfway 90 -> 270
    assert lag(R[0, 3]) == pytest.approx(180.0, abs=1e-12)
    turned = Vessel(raos=tabs, heading_deg=30.0).complex_rao([8.0], [30.0])
    assert turned[0, 0] == pytest.approx(R[0, 0], abs=1e-15)


def test_bilinear_in_period_and_heading():
    """Between two periods and two headings the amplitude and the unwrapped phase are
    bilinear: at (T, beta) a quarter of the way in each, the closed form
    sum w_T w_b value over the four corners (phases unwrapped along the periods first,
    then the shorter way between the tables)."""
    t0 = table(0.0, amp=(1.0, 3.0), phase=(10.0, 350.0))     # along T: 10 -> -10 (unwrap)
    t1 = table(60.0, amp=(2.0, 6.0), phase=(40.0, 20.0))
    R = Vessel(raos=(t0, t1)).complex_rao([7.5], [15.0])[2, 0]
    wt, wb = 0.25, 0.25
    amp = (1 - wb) * ((1 - wt) * 1.0 + wt * 3.0) + wb * ((1 - wt) * 2.0 + wt * 6.0)
    p0 = (1 - wt) * 10.0 + wt * -10.0
    p1 = (1 - wt) * 40.0 + wt * 20.0
    phase = (1 - wb) * p0 + wb * p1
    assert abs(R) == pytest.approx(amp, rel=1e-14)
    assert lag(R) == pytest.approx(phase % 360.0, abs=1e-12)


def test_the_builtin_scenes_rao_motion_is_unchanged():
    """Every built-in scene with a [vessel] gets the same RAOs at its waves' components
    as the complex-linear rule gave (each has one table, or its waves at the tables'
    headings): no committed report moves with the interpolation rule."""
    checked = 0
    for name in builtin_paths():
        sc = resolve(name)
        if sc.vessel is None:
            continue
        comp = sc.waves.components(sc.water_depth, sc.gravity, (0.0, 0.0))
        T, beta = 2.0 * math.pi / comp.omega, np.degrees(comp.heading)
        new = sc.vessel.complex_rao(T, beta)
        rel = beta - sc.vessel.heading_deg
        old = np.stack([complex_linear(sc.vessel.raos, t, r) if len(sc.vessel.raos) > 1
                        else sc.vessel.raos[0].complex_rao([t])[:, 0]
                        for t, r in zip(T, rel)], axis=1)
        assert np.array_equal(new, old), name
        checked += 1
    assert checked >= 3

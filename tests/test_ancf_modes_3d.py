"""The ANCF's natural modes about a 3D static state (ancf/modal.py: one coupled family).

About a static state out of the ends' plane (a current across it, a hang-off out of the
anchor's plane) the in-plane and out-of-plane motions couple, and ``solve_modes`` solves
one eigenproblem for the ``2 count`` lowest modes (``riser.results.modes.COUPLED``). The
VFIFE's 3D modes are not there to compare with yet; each test below asserts the coupled
path against an independent source, with a control that misses the same tolerance by a
factor of 10 or more where one is needed to show the test can fail:

1. Consistency: the coupled path forced on a planar state (``coupled=True``) solves the
   same K and M, block-diagonal there, as one problem: its frequencies are the two
   families' merged and sorted, to the eigensolver's round-off.
2. The planar limit: a current of 1e-3 m/s across the plane of a small catenary gives
   coupled frequencies equal to the planar families' of the same line without current.
   The frequencies are even in the cross drag (the mirror z -> -z turns the current
   around and leaves them unchanged), so they move as (U^2)^2 = U^4: measured 1.3e-6 at
   0.01 m/s, hence 1.3e-10 at 1e-3 m/s; the static solves' stopping rule adds up to
   8e-10 (measured at the default [ancf] static_tolerance). Tolerance 1e-8. Control: the
   U^4 law itself, the change at 0.03 m/s 81 times the change at 0.01 m/s (measured 80.99
   to 81.11, the scatter the statics' 8e-10 floor gives on a 1.3e-6 change); a coupled
   path that dropped the current's state (or the coupling) would not scale so.
3. A closed form about a genuinely 3D state: a weightless string stretched between pinned
   ends at one height (tests/test_ancf_modes.py's taut string) in a uniform current
   across its plane, normal drag only. The drag is normal to the line, so the tension T is
   uniform along it, and the deflected line lies in the horizontal plane of its ends, with
   tan(theta) = (c/T)(s - L0/2) (c = rho D C_dn U^2 / 2) and the chord condition
   span = (1 + T/EA)(2 T / c) asinh(c L0 / (2 T)), solved for T. The vertical motion is
   normal to that plane (the reflection y -> 2 h - y decouples it exactly) and the dead
   load has no vertical component, so the vertical modes are a string's:
   f_n = n / (2 L0) sqrt(T / ((1 + T/EA)(m + m_a))). EI = 1 N m2 raises f_n by
   (n pi / L)^2 EI / (2 T) = 1.4e-7 at n = 6 (measured 2.5e-9 to 1.8e-7 for n = 1..6 at
   2 m elements, the EI term and the cubic elements). Tolerance 1e-6 (the taut string's).
   Control: the string's closed form with the tension without current (T0 = EA strain,
   the current adds 27 %) misses by 12.7 %.
4. Rotation: the small catenary with its hang-off turned about the vertical through the
   anchor by 30 deg (a state with z up to 50 m and the slopes' z components) is the
   planar catenary turned: the same frequencies (measured within 3e-11; tolerance 1e-8,
   the statics' floor of 2), and each mode's out-of-plane share the planar mode's turned,
   sin^2(a) x its x fraction + cos^2(a) x its z fraction (tolerance 1e-8).
5. The tangent about a 3D state (a 0.3 m/s cross current on the small catenary): K is
   symmetric before the symmetrisation (measured 8e-17 of its largest entry; tolerance
   1e-12) and is the derivative of the drag-off residual (central differences of step
   1e-6 along random directions; measured 3e-9 to 6e-9 of max|K v|, tolerance 1e-6).
   Control: the drag's own tangent (its quasi-steady stiffness, not modelled: the drag
   a dead load; the tangent with the drag on less the one with it off) is not symmetric:
   max|D - D^T| = 1.8 max|D| (asserted > 0.1).
6. scr-steel-current-90 (the built-in 3D scene): the contract (2 count coupled modes
   numbered 1..2 count by frequency, their shares in ``info``), and its mirror image
   (heading -90 deg) has the same frequencies (measured 2e-11; tolerance 1e-8, the
   statics' floor) and shares (measured 7e-10 in the close pair 5/6; tolerance 1e-6).

Runtime: about 2 s (test 6 about 1 s of it, each test under 1 s; measured with
``python -m pytest -n 0 --durations=0 tests/test_ancf_modes_3d.py``).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import ancf
import ancf.modal as am
import builders
from riser.model.sections import segment_properties
from riser.results.modes import COUPLED, mac, out_of_plane_share
from riser.results.result import Status
from verification.catalog import resolve

MERGE_RTOL = 1e-10      # test 1: eigensolver round-off (the same matrices)
PLANAR_LIMIT_RTOL = 1e-8  # test 2: U^4 = 1.3e-10 plus the statics' floor 8e-10
QUARTIC_RTOL = 0.01      # test 2's control: 10 x the 0.1 % scatter of the ratio
STRING_RTOL = 1e-6       # test 3: the EI term and the elements (<= 1.8e-7)
ROTATION_RTOL = 1e-8     # test 4: the statics' floor (measured 3e-11)
MIRROR_RTOL = 1e-8       # test 6: the statics' floor (measured 2e-11)


def frequencies(res, plane) -> np.ndarray:
    return np.array([m.frequency_hz for m in res.family(plane)])


def merged_planar(res, count: int) -> list:
    """The lowest ``count`` modes of a planar result's two families, by frequency."""
    return sorted(res.modes, key=lambda m: m.frequency_hz)[:count]


def cross_current(speed: float, heading: float = 90.0) -> dict:
    """An [environment] table with a uniform current of ``speed`` [m/s] at ``heading``."""
    return {"current": {"heights": [0.0], "speeds": [speed], "heading_deg": heading}}


def catenary(**kw):
    """builders.catenary: 150 m on an elastic seabed, 75 elements of 2 m (0.1 s a solve)."""
    return builders.scene(builders.catenary(**kw))


def assert_contract(res, count: int) -> None:
    """2 count coupled modes numbered 1..2 count by increasing frequency, their shares in
    info, the message."""
    assert res.status is Status.CONVERGED, res.message
    assert [m.plane for m in res.modes] == [COUPLED] * 2 * count
    assert [m.number for m in res.modes] == list(range(1, 2 * count + 1))
    f = [m.frequency_hz for m in res.modes]
    assert f == sorted(f) and f[0] > 0.0
    assert res.family(COUPLED) == res.modes
    shares = res.info["out_of_plane_share"]
    assert shares == [out_of_plane_share(m) for m in res.modes]
    assert all(-1e-12 <= x <= 1.0 + 1e-12 for x in shares)     # round-off
    assert res.message.startswith(f"{2 * count} coupled modes about the ")


# ------------------------------------------------------------------ 1. consistency
def test_the_coupled_path_on_a_planar_state_merges_the_two_families():
    sc = catenary()
    static = ancf.solve(sc)
    planar = am.solve_modes(sc, 8, static=static)            # 8 a family: enough to merge
    both = am.solve_modes(sc, 4, static=static, coupled=True)
    assert_contract(both, 4)
    assert "planar static state" in both.message and both.info["coupling"] == 0.0
    ref = merged_planar(planar, 8)
    np.testing.assert_allclose(frequencies(both, COUPLED), [m.frequency_hz for m in ref],
                               rtol=MERGE_RTOL)
    for m, r, share in zip(both.modes, ref, both.info["out_of_plane_share"]):
        assert mac(m.shape, r.shape) > 1.0 - MERGE_RTOL, (m.number, r.plane)
        assert share == pytest.approx(float(r.plane == "out_of_plane"), abs=MERGE_RTOL)
    # the default keeps the two families on a planar state, and coupled=False refuses a
    # 3D one before solving
    assert am.solve_modes(sc, 2, static=static).family(COUPLED) == []
    out = am.solve_modes(catenary(environment=cross_current(0.3)), 2, coupled=False)
    assert out.status is Status.REFUSED and "heading" in out.message, out.message


# ------------------------------------------------------------------ 2. the planar limit
def coupled_change(speed: float, planar_f: np.ndarray, count: int) -> np.ndarray:
    res = am.solve_modes(catenary(environment=cross_current(speed)), count)
    assert_contract(res, count)
    assert "3D static state" in res.message and res.info["static_dimension"] == 3
    return frequencies(res, COUPLED) / planar_f - 1.0, res


def test_a_tiny_current_across_the_plane_gives_the_planar_frequencies():
    planar = am.solve_modes(catenary(), 8)
    ref = merged_planar(planar, 8)
    f0 = np.array([m.frequency_hz for m in ref])
    diff, res = coupled_change(1e-3, f0, 4)
    assert np.max(np.abs(diff)) < PLANAR_LIMIT_RTOL, diff
    assert res.info["coupling"] > 0.0                        # solved as 3D all the same
    for m, r, share in zip(res.modes, ref, res.info["out_of_plane_share"]):
        assert mac(m.shape, r.shape) > 1.0 - PLANAR_LIMIT_RTOL
        assert share == pytest.approx(float(r.plane == "out_of_plane"),
                                      abs=PLANAR_LIMIT_RTOL)
    # control: the change is even in the cross drag, U^4 (module docstring)
    d1, _ = coupled_change(0.01, f0, 4)
    d3, _ = coupled_change(0.03, f0, 4)
    assert np.min(np.abs(d1)) > 10 * PLANAR_LIMIT_RTOL       # seen (3.7e-7 to 1.3e-6)
    np.testing.assert_allclose(d3 / d1, 81.0, rtol=QUARTIC_RTOL)


# ------------------------------------------------------------------ 3. a closed form
def test_a_string_in_a_cross_current_has_string_modes_normal_to_its_deflection():
    span, strain, EA, U = 100.0, 1e-3, 1e8, 1.0
    L0 = span / (1.0 + strain)
    lt = {"outer_diameter": 0.2, "mass_per_length": 10.0, "axial_stiffness": EA,
          "bending_stiffness": 1.0, "added_mass": 1.0, "max_strain": 0.1,
          "drag_normal": 1.0, "drag_tangential": 0.0}
    sc = builders.scene(builders.straight(L0, span, height=10.0, line_type=lt,
                                          environment=cross_current(U)))
    p = segment_properties(sc)[0]
    c = p.drag_normal_coef * U * U                  # rho D C_dn / 2 U^2 [N/m]
    T = brentq(lambda T: (1 + T / EA) * (2 * T / c) * math.asinh(c * L0 / (2 * T)) - span,
               1e3, 1e7, xtol=1e-9, rtol=1e-15)
    static = ancf.solve(sc)
    assert static.converged, static.message
    # the 3D statics: the uniform tension of the closed form (measured 3e-9)
    np.testing.assert_allclose(static.profile.tension, T, rtol=1e-7)
    res = am.solve_modes(sc, 6, static=static)
    assert_contract(res, 6)
    assert res.info["static_lateral_extent_m"] > 0.5         # deflected 1.0 m across

    def vertical_share(m):
        return float(np.sum(m.shape[:, 1] ** 2) / np.sum(m.shape ** 2))

    vertical = [m for m in res.modes if vertical_share(m) > 1.0 - 1e-9]
    assert len(vertical) == 6                                 # the others: x and z only
    assert all(vertical_share(m) < 1e-9 for m in res.modes if m not in vertical)
    n = np.arange(1, 7)

    def string(T):
        return n / (2.0 * L0) * np.sqrt(T / ((1.0 + T / EA) * (p.mass + p.added_mass)))

    fv = np.array([m.frequency_hz for m in vertical])
    np.testing.assert_allclose(fv, string(T), rtol=STRING_RTOL)
    for m, k in zip(vertical, n):                             # sin(n pi s / L0) along y
        assert mac(m.shape[:, 1], np.sin(k * math.pi * m.s / L0)) > 1.0 - 1e-9
    # control: the tension without the current
    assert np.min(np.abs(fv / string(EA * strain) - 1.0)) > 0.1


# ------------------------------------------------------------------ 4. rotation
def test_a_catenary_turned_out_of_its_plane_keeps_its_modes():
    a = math.radians(30.0)
    data = builders.catenary()
    data["ends"]["hang_off"] = [100.0 * math.cos(a), 60.0, 100.0 * math.sin(a)]
    turned = am.solve_modes(builders.scene(data), 4)
    assert_contract(turned, 4)
    assert turned.info["static_lateral_extent_m"] == pytest.approx(50.0, rel=1e-9)
    ref = merged_planar(am.solve_modes(catenary(), 8), 8)
    np.testing.assert_allclose(frequencies(turned, COUPLED), [m.frequency_hz for m in ref],
                               rtol=ROTATION_RTOL)
    for share, r in zip(turned.info["out_of_plane_share"], ref):
        total = np.trapezoid(np.sum(r.shape ** 2, axis=1), r.s)
        expect = (math.sin(a) ** 2 * np.trapezoid(r.shape[:, 0] ** 2, r.s)
                  + math.cos(a) ** 2 * np.trapezoid(r.shape[:, 2] ** 2, r.s)) / total
        assert share == pytest.approx(expect, abs=ROTATION_RTOL)
    # the turned in-plane mode is the control: its share is neither 0 nor 1 (0.24)
    assert any(0.1 < x < 0.9 for x in turned.info["out_of_plane_share"])


# ------------------------------------------------------------------ 5. the tangent
def test_the_tangent_about_a_3d_state_is_symmetric_and_the_residuals_derivative():
    sc = catenary(environment=cross_current(0.3))
    static = ancf.solve(sc)
    assert static.converged and static.info["dimension"] == 3, static.message
    model, q = static.solver_state
    lin = am.linearise(model, am.state_3d(model, q))
    assert lin.asymmetry < 1e-12 and lin.coupling > 1e-3
    assert not lin.model.use_drag and lin.contacts > 0        # drag off, seabed springs on
    rng = np.random.default_rng(7)
    h = 1e-6
    for _ in range(3):
        v = rng.standard_normal(lin.model.N)
        Kv = lin.K @ v
        fd = (lin.model.residual(lin.q + h * v, tangent=False)[0]
              - lin.model.residual(lin.q - h * v, tangent=False)[0]) / (2.0 * h)
        assert np.max(np.abs(fd - Kv)) < 1e-6 * np.max(np.abs(Kv))
    # control: the drag's own (quasi-steady) tangent, the difference of the tangents with
    # the drag on and off, is not symmetric
    drag = am.Model(sc, model.mesh, 3, current=True)
    _, Kd, _ = drag.residual(lin.q)
    _, K0, _ = lin.model.residual(lin.q)
    D = am.band_to_sparse(Kd - K0, drag.kl)
    assert float(abs(D - D.T).max()) > 0.1 * float(abs(D).max())


# ------------------------------------------------------------------ 6. a built-in scene
def test_scr_steel_current_90_and_its_mirror_image():
    sc = resolve("scr-steel-current-90")
    res = am.solve_modes(sc, 3)
    assert_contract(res, 3)
    assert "3D static state" in res.message and res.info["asymmetry"] < 1e-12
    mirror = am.solve_modes(sc.replace(**{"environment.current.heading_deg": -90.0}), 3)
    assert_contract(mirror, 3)
    np.testing.assert_allclose(frequencies(mirror, COUPLED), frequencies(res, COUPLED),
                               rtol=MIRROR_RTOL)
    np.testing.assert_allclose(mirror.info["out_of_plane_share"],
                               res.info["out_of_plane_share"], atol=1e-6)
    # the mirror turns z: each shape's z component changes sign against x and y
    for m, r in zip(mirror.modes, res.modes):
        flipped = r.shape * np.array([1.0, 1.0, -1.0])
        assert mac(m.shape, flipped) > 1.0 - 1e-6

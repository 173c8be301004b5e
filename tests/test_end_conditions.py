"""End conditions (issue 35): a top tensioner, clamped and flex-jointed ends, a free lower
end, against closed forms and between the two methods.

Every line here is vertical (anchor straight below the hang-off) and, except the hanging
chain, weightless (submerged weight 0): its effective tension is then the tensioner's
top_tension all along, and the small lateral motion of the line obeys the tensioned beam

    EI w'''' - T w'' = q(y)      (w the x deflection [m], y up, q [N/m] the lateral load)

whose solutions are closed forms (hyperbolic functions). The BVP and the VFIFE solve the
large-deflection, extensible line: they differ from the linear closed form by the slope
squared and the stretch T/EA (each stated where a tolerance is set).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.interpolate import CubicSpline
from scipy.special import jn_zeros

import bvp
import vfife
from bvp.modal.modes import solve_modes as bvp_modes
from riser.errors import SceneError
from riser.model.sections import segment_properties
from verification.studies.ends import scenes as ends_scenes
from verification.studies.ends.cases import clamp_closed_form
from vfife.modal.modes import solve_modes as vfife_modes

from builders import line, pipe, scene

L = 100.0              # [m] the vertical line's length
T = 1.0e5              # [N] the tensioner's pull = the tension of a weightless line
EI = 1.0e7             # [N m2] (lambda L = L sqrt(T/EI) = 10: bending and tension matter)
LAMBDA = math.sqrt(T / EI)


def vertical(*, anchor_joint=None, hang_off_joint=None, tensioner=True, **kw) -> dict:
    """A weightless vertical line of L from (0, 0) to (0, L), pulled by a tensioner of T
    (no seabed: the anchor holds it)."""
    data = line(L, (0.0, 0.0), (0.0, L), submerged_weight=0.0,
                line_type=pipe(drag_normal=1.0, drag_tangential=0.0),
                environment={"water_depth": 200.0, **kw.pop("environment", {})}, **kw)
    if tensioner:
        data["ends"]["tensioner"] = {"top_tension": T}
    if anchor_joint:
        data["ends"]["anchor_joint"] = anchor_joint
    if hang_off_joint:
        data["ends"]["hang_off_joint"] = hang_off_joint
    return data


def x_at(profile, y: float) -> float:
    """x [m] at height y of a vertical line's profile (a cubic through its stations: a
    linear interpolation errs by the station spacing squared times the curvature)."""
    keep = np.concatenate([[True], np.diff(profile.y) > 0.0])
    return float(CubicSpline(profile.y[keep], profile.x[keep])(y))


# ------------------------------------------------------------------ lateral load
def test_a_tensioned_beam_in_a_uniform_current_is_the_hyperbolic_closed_form():
    # uniform current V along +x on the vertical line: the normal drag q = 0.5 rho D C_D
    # V^2 [N/m] along +x. Pinned-pinned, w = q/(2T) y (L - y) + q EI/T^2 [cosh(lambda
    # (y - L/2)) / cosh(lambda L/2) - 1].
    V = 0.3
    sc = scene(vertical(environment={"current": {"heights": [0.0, 200.0],
                                                 "speeds": [V, V]}}))
    q = 0.5 * 1025.0 * 0.3 * 1.0 * V * V

    def closed(y):
        return (q / (2.0 * T) * y * (L - y)
                + q * EI / T ** 2 * (math.cosh(LAMBDA * (y - L / 2)) / math.cosh(LAMBDA * L / 2)
                                     - 1.0))

    w_mid = closed(L / 2)
    b = bvp.solve(sc).require()
    # the relaxation's default stop (out-of-balance 1e-3 of an element's drag, 14 N) leaves
    # this light taut line 4e-4 short of its deflection (the lowest mode's stiffness is
    # small); 1e-5 takes it to 3e-5 of the BVP's
    v = vfife.solve(sc, element_length=1.0, tolerance=1e-5).require()
    # q = 13.8 N/m, w_mid = 0.16 m, slope <= 0.0064: the drag's sin(theta) and the arc
    # length differ from the linear beam's by the slope squared (4e-5; at 0.8 m/s, slope
    # 0.045, the BVP was 1.4e-3 below it); the stretch T/EA = 1e-4 lengthens the span and
    # spreads the load and the bending per unit height (each 1e-4): measured -3.5e-4 at
    # 0.2 L, -0.4e-4 at mid-height, both methods
    for res in (b, v):
        assert x_at(res.profile, L / 2) == pytest.approx(w_mid, rel=2e-4)
        assert x_at(res.profile, 0.2 * L) == pytest.approx(closed(0.2 * L), rel=5e-4)
    # the two methods on the same extensible model (measured 2e-5)
    for y in (0.2 * L, 0.5 * L, 0.8 * L):
        assert x_at(v.profile, y) == pytest.approx(x_at(b.profile, y), rel=1e-4)
    # the top slides: the line stretched by T/EA, less what the bow takes, 1/2 int w'^2
    # dy (6.5e-4 m; the closed form's slope by central differences, error ~1e-10 m)
    y = np.linspace(0.0, L, 4001)
    slope = (np.array([closed(v + 1e-4) for v in y]) - np.array([closed(v - 1e-4) for v in y])
             ) / 2e-4
    top = L * (1.0 + T / 1.0e9) - 0.5 * float(np.trapezoid(slope ** 2, y))
    assert b.profile.y[-1] == pytest.approx(top, abs=1e-6)
    assert v.profile.y[-1] == pytest.approx(b.profile.y[-1], abs=1e-6)


# ------------------------------------------------------------------ clamped, flex joint
@pytest.mark.parametrize("k", [2.0e6, 2.0e7])
def test_a_clamp_at_an_angle_and_a_flex_joint_are_the_closed_form(k):
    # anchor clamped alpha from the vertical (towards +x), hang-off on a flex joint k
    # [N m/rad] about the vertical; no load. w = A + B y + C cosh(lambda y) + D sinh(lambda
    # y) with w(0) = 0, w'(0) = tan(alpha), w(L) = 0 and, from M = EI dtheta/ds =
    # -EI w'' and M(L) = -k (theta(L) - 90 deg) = k w'(L): EI w''(L) + k w'(L) = 0.
    alpha = math.radians(1.0)
    sc = scene(vertical(anchor_joint={"kind": "clamped", "direction_deg": 89.0},
                        hang_off_joint={"kind": "spring", "direction_deg": 90.0,
                                        "rotational_stiffness": k}))
    # the closed form, written once in the ends study (its report's reference), of the
    # same line
    assert (ends_scenes.L, ends_scenes.T, ends_scenes.EI) == (L, T, EI)
    M0, ML, w_mid = clamp_closed_form(k, alpha)
    b = bvp.solve(sc).require()
    v = vfife.solve(sc, element_length=0.5, tolerance=1e-5).require()   # see above
    sb, sv = b.summary(), v.summary()
    # the linear beam against the large rotation and the stretch: relative alpha^2 ~ 3e-4
    # and T/EA = 1e-4 (measured 7e-5 and 1.4e-4); the VFIFE's end moments on the
    # comparison's basis, the largest moment M(0) (measured 2.5e-4 of it at 0.5 m)
    assert sb["anchor_moment"] == pytest.approx(M0, rel=5e-4)
    assert sb["hang_off_moment"] == pytest.approx(ML, rel=5e-4)
    assert sv["anchor_moment"] == pytest.approx(M0, abs=1e-3 * abs(M0))
    assert sv["hang_off_moment"] == pytest.approx(ML, abs=1e-3 * abs(M0))
    for res in (b, v):
        assert x_at(res.profile, L / 2) == pytest.approx(w_mid, rel=2e-3)
    assert math.degrees(b.profile.theta[0]) == pytest.approx(89.0, abs=1e-9)
    # the spring's law at the top, in the BVP's own state
    assert sb["hang_off_moment"] == pytest.approx(
        -k * (b.profile.theta[-1] - math.pi / 2), rel=1e-6)


# ------------------------------------------------------------------ modes
def test_a_tensioned_pinned_beam_has_the_closed_form_frequencies():
    # weightless, uniform tension T: omega_n^2 (m + m_a) = EI k^4 + T k^2, k = n pi / L,
    # for the lateral modes in and out of the plane (the tensioner only frees the top's
    # axial motion: the axial modes are far above, sqrt(EA/m)/(2L) = 16 Hz)
    sc = scene(vertical())
    p = segment_properties(sc)[0]
    m = p.mass + p.added_mass
    f = [math.sqrt((EI * k ** 4 + T * k ** 2) / m) / (2 * math.pi)
         for k in (n * math.pi / L for n in (1, 2, 3, 4))]
    b = bvp_modes(sc, 4)
    assert b.converged, b.message
    v = vfife_modes(sc, 4, static=vfife.solve(sc, element_length=0.5).require())
    assert v.converged, v.message
    for plane in ("in_plane", "out_of_plane"):
        fb = [x.frequency_hz for x in b.modes if x.plane == plane]
        fv = [x.frequency_hz for x in v.modes if x.plane == plane]
        # BVP: the stretched length L (1 + T/EA) and the mass per unstretched length,
        # 1e-4; the VFIFE's lumped masses: (n pi h / L)^2 / 12 = 1.3e-3 at n = 4, h = 0.5 m
        assert fb == pytest.approx(f, rel=2e-4)
        assert fv == pytest.approx(f, rel=2e-3)


def hanging_chain() -> dict:
    data = line(L, (0.0, 60.0), (0.0, 170.0), submerged_weight=200.0,
                line_type=pipe(bending_stiffness=1.0, added_mass=0.0),
                environment={"water_depth": 200.0})
    data["ends"]["anchor_joint"] = {"kind": "free"}
    return data


def test_a_hanging_chain_has_the_bessel_frequencies_by_both_methods():
    # a heavy line hanging free: omega_n = (j_0n / 2) sqrt(g_e / L), j_0n the zeros of J0,
    # g_e = w / m (the submerged weight over the mass: no added mass here). The chain
    # limit EI -> 0: EI = 1 N m2 moves mode 5 by 5.1e-5 (the BVP, either family)
    sc = scene(hanging_chain())
    p = segment_properties(sc)[0]
    f = jn_zeros(0, 5) / 2.0 * math.sqrt(p.weight / p.mass / L) / (2 * math.pi)
    st = bvp.solve(sc).require()
    assert st.profile.tension[0] == pytest.approx(0.0, abs=1e-6 * p.weight * L)
    assert st.profile.y[0] == pytest.approx(170.0 - L * (1 + p.weight * L / 2e9), abs=1e-6)
    b = bvp_modes(sc, 5, static=st)
    assert b.converged, b.message
    vst = vfife.solve(sc, element_length=0.5).require()
    assert vst.profile.y[0] == pytest.approx(st.profile.y[0], abs=1e-6)
    v = vfife_modes(sc, 5, static=vst)
    assert v.converged, v.message
    for plane in ("in_plane", "out_of_plane"):
        fb = np.array([x.frequency_hz for x in b.modes if x.plane == plane])
        fv = np.array([x.frequency_hz for x in v.modes if x.plane == plane])
        assert fb == pytest.approx(f, rel=1e-4)
        # the lumped chain at 0.5 m: second order, -2.6e-3 at mode 5 (measured)
        assert fv == pytest.approx(f, rel=4e-3)


# ------------------------------------------------------------------ bad input
@pytest.mark.parametrize("ends, match", [
    ({"hang_off_joint": {"kind": "free"}}, r"hang_off_joint.kind: 'free' is for the anchor"),
    ({"hang_off_joint": {"kind": "spring", "direction_deg": 90.0,
                         "rotational_stiffness": -1.0}}, r"rotational_stiffness: must be > 0"),
    ({"anchor_joint": {"kind": "clamped"}}, r"anchor_joint.direction_deg: required"),
    ({"anchor_joint": {"kind": "pinned", "direction_deg": 90.0}},
     r"direction_deg: only with kind = 'clamped' or 'spring'"),
    ({"tensioner": {"top_tension": -5.0}}, r"tensioner.top_tension: must be > 0"),
])
def test_bad_end_conditions_are_one_line_naming_the_key(ends, match):
    data = vertical(tensioner=False)
    data["ends"].update(ends)
    with pytest.raises(SceneError, match=match):
        scene(data)


def test_a_tensioner_weaker_than_the_line_is_refused_before_solving():
    data = vertical()
    data["segments"][0]["submerged_weight"] = 2000.0        # 2e5 N > T = 1e5 N
    with pytest.raises(SceneError, match=r"top_tension: must exceed the submerged weight "
                                         r"of the line and its attachments 200000 N"):
        bvp.solve(scene(data))
    with pytest.raises(SceneError, match=r"top_tension: must exceed"):
        vfife.solve(scene(data))


def test_a_free_end_that_reaches_the_seabed_or_a_joint_out_of_plane_is_refused():
    data = hanging_chain()
    data["segments"][0]["length"] = 200.0
    with pytest.raises(SceneError, match=r"anchor_joint.kind: 'free': the line \(200 m\)"):
        scene(data)
    data = vertical(environment={"current": {"heights": [0.0, 200.0], "speeds": [1, 1],
                                             "heading_deg": 30.0}})
    with pytest.raises(SceneError, match=r"ends.tensioner.top_tension: needs a planar scene"):
        scene(data)


# ------------------------------------------------------------------ dynamics
def test_a_hanging_chain_released_in_its_first_mode_swings_at_the_bessel_frequency():
    # the VFIFE's time domain with the free end integrated (vfife.kernels._end_translation):
    # released in its first in-plane mode it swings at (j_01 / 2) sqrt(g_e / L); the
    # time-domain model against its own modal analysis to the zero-crossing reading
    # (1e-3 over 6 periods), and both against the closed form to the 1 m mesh's
    # discretisation (-4e-5 at mode 1)
    from vfife.modal.modes import free_vibration
    sc = scene(hanging_chain())
    p = segment_properties(sc)[0]
    f1 = jn_zeros(0, 1)[0] / 2.0 * math.sqrt(p.weight / p.mass / L) / (2 * math.pi)
    out = free_vibration(sc, "in_plane", 1, static=vfife.solve(sc, element_length=1.0))
    assert out["rel_diff"] == pytest.approx(0.0, abs=1e-3)
    assert out["frequency_hz"] == pytest.approx(f1, rel=2e-3)
    with pytest.raises(ValueError, match="3D kernels hold their ends pinned"):
        free_vibration(sc, "out_of_plane", 1)


def test_a_tensioner_follows_the_heave_with_its_stiffness():
    # a weightless vertical line on a tensioner of stiffness k_t, heaved slowly (period
    # 100 s, far above the axial period 2 L sqrt(m/EA) = 0.06 s and the lateral ones):
    # the tensioner and the line are two springs in series, so the pull swings about
    # top_tension by k_t A (EA/L) / (EA/L + k_t) = k_t A / 1.01; read at the top element
    k_t, A = 1.0e5, 0.5
    data = vertical(dynamics={"duration": 260.0, "output_interval": 0.5,
                              "top_motion": {"axis": "y", "amplitude": A,
                                             "period": 100.0, "ramp_time": 10.0}})
    data["ends"]["tensioner"]["stiffness"] = k_t
    res = vfife.solve(scene(data), element_length=2.0).require()
    ts = res.dynamics.timeseries
    t = np.asarray(ts["time"])
    T_top = np.asarray(ts["hang_off_tension"])[t >= 50.0]       # after the 10 s ramp
    # quasi-static: the line's inertia (m L A' omega^2 with the top's motion A' = 5 mm:
    # 0.2 N) and the drag (~1e-3 N) against 5e4 N; the 0.5 s samples' phase error
    # (1 - cos(pi 0.5 / 100) = 1.2e-4)
    spring = 1.0e9 / L
    assert 0.5 * (T_top.max() - T_top.min()) == pytest.approx(
        k_t * A * spring / (spring + k_t), rel=2e-4)
    # the mean: the static pull, top_tension less k_t times the stroke the line's stretch
    # makes (F L / EA): F = T / (1 + k_t / (EA/L))
    assert 0.5 * (T_top.max() + T_top.min()) == pytest.approx(T / (1.0 + k_t / spring),
                                                              rel=1e-6)

"""Point attachments (issue 35): a clump weight and a buoy on a cable between two pinned
ends against the two-catenary closed form, both methods; the bad inputs.

Closed form (Irvine's elastic catenary, EI = 0, written here independently of the
suite's catenary code): the horizontal force H is the same along the line, the vertical
force V(s) = V0 + w s + W [s > s_p] grows with the weight w [N/m] and jumps by the point's
net weight W = (m - rho V) g [N]; a piece from s_a to s_b with V_a at its start reaches

    dx = H/w [asinh(V_b/H) - asinh(V_a/H)] + H (s_b - s_a) / EA
    dy = H/w [sqrt(1 + (V_b/H)^2) - sqrt(1 + (V_a/H)^2)] + (V_a + V_b)(s_b - s_a) / (2 EA)

so the line is two catenaries of one H with a kink at the point, and (H, V0) follow from
the hang-off's position. The methods solve a line with a little bending stiffness
(EI = 1 N m2: a bending length sqrt(EI/T) of a centimetre) and no current.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import bvp
import vfife
from riser.errors import SceneError
from verification.studies.ends import cases as ends_cases
from verification.studies.ends import scenes as S

from builders import line, pipe, scene

W_LINE = 200.0         # [N/m] the cable's submerged weight
EA = 1.0e8             # [N]
LENGTH, SPAN, RISE = 150.0, 110.0, 50.0
S_P = 90.0             # [m] the attachment's arc length from the anchor


def cable(**attachment) -> dict:
    data = line(LENGTH, (0.0, 10.0), (SPAN, 10.0 + RISE), submerged_weight=W_LINE,
                line_type=pipe(bending_stiffness=1.0, axial_stiffness=EA),
                environment={"water_depth": 200.0})
    data["attachments"] = [{"s": S_P, **attachment}]
    return data


def two_catenaries(W: float):
    """(H, V0, the point's (x, y), the tension either side of it): the closed form of the
    module docstring, written once in the ends study (its report's reference), for the
    cable here (its dimensions are the study's: asserted)."""
    assert (S.CABLE_LENGTH, S.CABLE_SPAN, S.CABLE_RISE, S.CABLE_WEIGHT, S.CABLE_EA,
            S.S_P) == (LENGTH, SPAN, RISE, W_LINE, EA, S_P)
    return ends_cases.two_catenaries(W)


def at(profile, s: float, key: str) -> float:
    return float(np.interp(s, profile.s, getattr(profile, key)))


@pytest.mark.parametrize("kind, attachment", [
    ("clump", {"mass": 2000.0, "volume": 0.25}),          # W = +17.1 kN
    ("buoy", {"mass": 500.0, "volume": 1.5}),             # W = -10.2 kN: a kink upwards
])
def test_a_point_on_a_cable_is_the_two_catenary_closed_form(kind, attachment):
    sc = scene(cable(**attachment))
    W = sc.attachments[0].net_weight(sc.gravity, sc.water_density)
    H, V0, (xp, yp), (T_below, T_above) = two_catenaries(W)
    b = bvp.solve(sc).require()
    v = vfife.solve(sc, element_length=0.5, tolerance=1e-5).require()
    # EI = 1 N m2 against the cable: the bending length l = sqrt(EI/T) (1.4-1.8 cm) rounds
    # the kink and the ends, which moves the point in proportion to l (BVP measured: clump
    # 1.4 mm, 0.8 mm, the end tensions 5e-6, 9e-6; buoy 1.4 mm, 7.4 mm, 6e-5; the limit
    # is the next test); the VFIFE's 0.5 m elements do not resolve l, its line is the
    # cable's to its discretisation (measured <= 0.9 mm, 1.5e-5)
    for res, tol_T, tol_x in ((b, 1e-4, 1e-2), (v, 1e-4, 3e-3)):
        p = res.profile
        assert at(p, S_P, "x") == pytest.approx(xp, abs=tol_x)
        assert at(p, S_P, "y") == pytest.approx(yp, abs=tol_x)
        assert p.tension[-1] == pytest.approx(math.hypot(H, V0 + W_LINE * LENGTH + W),
                                              rel=tol_T)
        assert p.tension[0] == pytest.approx(math.hypot(H, V0), rel=tol_T)
    # the jump: the BVP's internal force |P| = hypot(T, F) either side of the point (its
    # station at s_p holds the side below, the next one, 0.1 mm on, the side above; the
    # line's weight changes |P| by 0.02 N over it). Not T alone: within the bending
    # length the tangent turns through the kink and the shear F carries part of P
    pb = b.profile
    i = int(np.flatnonzero(np.isclose(pb.s, S_P, rtol=0.0, atol=1e-9))[0])
    # (the bending length's share as above: buoy 7e-5)
    assert math.hypot(pb.tension[i], pb.shear[i]) == pytest.approx(T_below, rel=2e-4)
    assert pb.s[i + 1] - S_P < 1e-3
    assert math.hypot(pb.tension[i + 1], pb.shear[i + 1]) == pytest.approx(T_above,
                                                                           rel=2e-4)
    # the VFIFE's node at the point: the mean of the two sides
    i = int(np.argmin(np.abs(v.profile.s - S_P)))
    assert v.profile.s[i] == pytest.approx(S_P, abs=1e-9)
    assert v.profile.tension[i] == pytest.approx(0.5 * (T_below + T_above), rel=2e-3)


def test_the_bvp_tends_to_the_two_catenaries_as_the_bending_stiffness_vanishes():
    # the point's offset from the cable's closed form is the bending length's doing:
    # proportional to l = sqrt(EI/T), so a quarter of the EI halves it (measured 2.00 on
    # the buoy; EI below ~0.5 N m2 the BVP's cold start does not converge: a limit of
    # the method here, not of the model)
    errs = []
    for EI in (4.0, 1.0):
        data = cable(mass=500.0, volume=1.5)
        data["line_types"]["p"]["bending_stiffness"] = EI
        sc = scene(data)
        _, _, (xp, yp), _ = two_catenaries(sc.attachments[0].net_weight(sc.gravity,
                                                                          sc.water_density))
        p = bvp.solve(sc).require().profile
        errs.append(math.hypot(at(p, S_P, "x") - xp, at(p, S_P, "y") - yp))
    assert errs[0] / errs[1] == pytest.approx(2.0, rel=0.03)


def test_a_point_load_closes_the_bvps_force_balance():
    # the BVP's independent check (bvp/beam/output.py): the ends' forces against the line's
    # weight and the point's, integrated; to round-off
    res = bvp.solve(scene(cable(mass=2000.0, volume=0.25, drag_area=1.0))).require()
    assert res.info["equilibrium_residual"] < 1e-8


def test_an_attachments_drag_in_a_current_agrees_between_the_methods():
    data = cable(mass=2000.0, volume=0.25, drag_area=3.0)
    data["environment"]["current"] = {"heights": [0.0, 200.0], "speeds": [0.5, 1.0]}
    sc = scene(data)
    b = bvp.solve(sc).require()
    v = vfife.solve(sc, element_length=0.5, tolerance=1e-5).require()
    for key in ("x", "y"):
        assert at(v.profile, S_P, key) == pytest.approx(at(b.profile, S_P, key), abs=5e-3)
    assert v.profile.tension[-1] == pytest.approx(b.profile.tension[-1], rel=2e-4)
    # without the point's drag the point sits elsewhere: the test sees the drag
    data["attachments"][0]["drag_area"] = 0.0
    b0 = bvp.solve(scene(data)).require()
    assert abs(at(b0.profile, S_P, "x") - at(b.profile, S_P, "x")) > 0.05


@pytest.mark.parametrize("attachment, match", [
    ({"s": 151.0, "mass": 1.0}, r"attachments\[0\].s: must be inside the line, > 0 and < "
                                r"its length 150 m"),
    ({"s": 0.0, "mass": 1.0}, r"attachments\[0\].s: must be inside the line"),
    ({"s": 10.0, "mass": -1.0}, r"attachments\[0\].mass: must be >= 0"),
    ({"s": 10.0, "volume": 2e4}, r"attachments\[0\].volume: must be <= 10000"),
])
def test_bad_attachments_are_one_line_naming_the_key(attachment, match):
    data = cable()
    data["attachments"] = [attachment]
    with pytest.raises(SceneError, match=match):
        scene(data)


def test_a_buoy_that_floats_a_hanging_line_is_refused_before_solving():
    data = line(50.0, (0.0, 100.0), (0.0, 160.0), submerged_weight=W_LINE,
                environment={"water_depth": 200.0})
    data["ends"]["anchor_joint"] = {"kind": "free"}
    data["attachments"] = [{"s": 20.0, "volume": 2.0}]            # 20 kN of uplift
    sc = scene(data)
    for method in (bvp, vfife):
        with pytest.raises(SceneError, match=r"attachments\[0\].volume: lifts the hanging "
                                             r"line"):
            method.solve(sc)


def test_attachments_out_of_plane_or_on_a_rigid_seabed_are_refused():
    data = cable(mass=100.0)
    data["environment"]["current"] = {"heights": [0.0, 200.0], "speeds": [1.0, 1.0],
                                      "heading_deg": 45.0}
    with pytest.raises(SceneError, match=r"attachments: need a planar scene"):
        scene(data)
    data = cable(mass=100.0)
    data["ends"]["anchor"] = [0.0, 0.0]
    data["seabed"] = {"stiffness": 1e5}
    data["model"] = {"seabed": "rigid", "axial": "extensible"}
    res = bvp.solve(scene(data))
    assert res.status.value == "refused" and "attachments" in res.message


def test_two_attachments_at_one_point_are_their_sum():
    """Found by the feature fuzz (tests/test_fuzz_features.py): two attachments at the same
    s gave the VFIFE a zero-length element (NaN direction, a LinAlgError). They share a
    node now; both methods give the line of one attachment carrying their sum (the same
    equations: the only difference is the sum's round-off)."""
    data = cable(mass=2000.0, volume=0.25)
    data["attachments"].append({"s": S_P, "mass": 500.0, "volume": 1.5})
    split = scene(data)
    merged = scene(cable(mass=2500.0, volume=1.75))
    for solve in (bvp.solve, lambda sc: vfife.solve(sc, element_length=2.0)):
        a, b = solve(split).require().profile, solve(merged).require().profile
        assert a.tension[-1] == pytest.approx(b.tension[-1], rel=1e-9)
        assert at(a, S_P, "y") == pytest.approx(at(b, S_P, "y"), abs=1e-6)

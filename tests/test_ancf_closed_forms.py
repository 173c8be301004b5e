"""Closed forms of the ANCF statics (:func:`ancf.solve`): three statements that do not
come from the method, each computed here from its own equations with scipy, each with a
negative control (the same solve with an input 1 % off, or the closed form without an
effect the line has, must fail the same tolerance by a factor of 10 or more: the test can
fail), and a convergence study in the element length.

1. The large-deflection cantilever (Bisshopp & Drucker 1945; docs/references.md): a
   weightless line clamped horizontally at the hang-off (``[ends.hang_off_joint]
   kind = "clamped", direction_deg = 0``), its anchor end free
   (``kind = "free"``) and loaded there by a tip load P straight down (a point attachment
   of mass P/g at s = 0, which a free anchor allows, riser/model/attachments.py; the
   ``dead_load`` is per length, not a point load). s runs from the free tip to the clamp,
   x from the tip towards the clamp, y up: the tip hangs below the clamp. With theta the
   tangent's angle and M = EI dtheta/ds (per unstretched length, the ANCF's model), the
   part of the line between the tip and s carries P, so the force at s is (0, P), the
   tension T = P sin(theta), the strain T / EA, and

       EI theta'' = -P (1 + P sin(theta) / EA) cos(theta),  theta'(0) = 0,  theta(L) = 0,

   the extensible elastica, solved by shooting on theta(0) (solve_ivp, rtol 1e-12, and
   brentq): w = y(L) - y(0) and u = L - (x(L) - x(0)). Its inextensible limit reproduces
   the table w/L = 0.30172, 0.49346, 0.71379, 0.81061 and u/L = 0.05643, 0.16064, 0.38763,
   0.55500 at alpha = P L^2 / EI = 1, 2, 5, 10 to the table's rounding (5e-6; measured
   <= 4.4e-6), and EA = 1e6 P moves w/L and u/L by < 3e-6 (so the table is also the
   ANCF's target to 1e-5). The ANCF is compared with the extensible curve, exact for its
   model.

   The public solve (the solver's own straight start, the clamp's direction imposed on
   it) is checked once at alpha = 2; the convergence study gives the solver a start of
   its own (monkeypatching ``ancf.solver.straight_start``): the exact elastica of a load
   0.2 % below the load solved, so Newton still has to move the tip by 4e-4 to 6e-4 L
   (over 10 x the tolerance; a solver that returned its start would fail), and the
   negative control starts from the same kind of start of its own load. (Written when
   the solver neither imposed a clamp's direction on its start nor passed the stiff
   line's first Newton step, which raises |R| 1e4-fold through the axial strain though
   it lowers the energy: both mended, ancf/solver.py and ancf/statics/newton.py.)

2. The elastic catenary between fixed (pinned) ends, no seabed, EI = 0.01 N m2 (bending
   length sqrt(EI/T) = 1.3 mm, far below the elements: the string limit; the bending
   correction is linear in EI, measured 6.7e-8 of the end tensions at EI = 1 N m2, so
   7e-10 here). Closed form (Irvine): with Q the load per unstretched length of fixed
   direction (the weight w and an optional dead load qx, Q = |(qx, -w)|), X along the
   normal to the load and Y against it, H the force along X and V(s) = V0 + Q s,

       X(s) = H s / EA + H / Q [asinh(V(s)/H) - asinh(V0/H)]
       Y(s) = (V0 s + Q s^2 / 2) / EA + H / Q [sqrt(1 + (V(s)/H)^2) - sqrt(1 + (V0/H)^2)]

   with (H, V0) from X(L), Y(L) = the chord (scipy least_squares, here, not the
   catenary of ancf/statics/start.py). End tensions sqrt(H^2 + V^2); the sag is the vertical
   distance from the chord at mid-span. With qx = 0.3 w the load tilts and the ANCF's own
   catenary start (weight only) is up to 3.1 m off: Newton has to move the line.

3. A weightless straight line between pinned ends at one height, unstretched length L0
   over the span S (L0 = S: no pretension; L0 < S: pretension EA (S/L0 - 1)), under a
   small uniform transverse dead load q (down). Small-slope beam-string, exact for the
   pinned ends as a sine series (w the deflection, down):

       EI' w'''' - H w'' = q',   w = sum_{n odd} 4 q' / (n pi) / (EI' k^4 + H k^2) sin(k x),
       k = n pi / S,

   with the ANCF's per-unstretched-length model read in x: EI' = EI (1 + eps) (the
   curvature per unstretched length) and q' = q / (1 + eps), eps = H / EA; H from the
   stretch of the immovable ends, S + 1/2 int w'^2 dx = L0 + L0 / EA (H + q' mean(w)) (the
   tension along the line is H + q' (S/2 - x) w': its mean exceeds H by q' mean(w)). The
   three cases: a beam (no pretension: H is the membrane tension, 0.27 N; at H = 0 the
   series is 5 q S^4 / (384 EI) at mid-span), a beam-string (lambda S = 10) and a string
   (EI = 0.01 N m2: q S^2 / (8 H)).

The derivatives of the element's energy are checked in tests/unit/ancf/test_ancf_element.py.
Runtime: about 5 s (some 40 solves of 10 to 80 elements; 13 s with a cold Numba cache).
"""

from __future__ import annotations

import math

import builders
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq, least_squares

import ancf
import ancf.solver as ancf_solver

G = 9.81                # [m/s2] the builders' gravity


# ================================================================== 1. the cantilever
CL = 10.0               # [m] cantilever length
CEI = 1.0e4             # [N m2]
EA_OVER_P = 1.0e6       # the inextensible limit: EA = 1e6 P
TABLE = {1: (0.30172, 0.05643), 2: (0.49346, 0.16064), 5: (0.71379, 0.38763),
         10: (0.81061, 0.55500)}     # alpha: (w/L, u/L), Bisshopp & Drucker
TABLE_ROUNDING = 5.0e-6
#: [-] |w - w_ref| / L and |u - u_ref| / L at 40 elements. Measured (the 2D element,
#: 5 Gauss points, tolerance 1e-10): 3.5e-8, 3.3e-7, 3.6e-6, 1.7e-5 (w) and 9.8e-9,
#: 1.5e-7, 2.4e-6, 1.2e-5 (u) at alpha = 1, 2, 5, 10; the nodal values of the cubic
#: Hermite elements converge at h^6 (2p: Galerkin superconvergence at the nodes; measured
#: orders 5.6-5.9 from 40 to 80 elements), the large rotations at alpha = 10 still
#: pre-asymptotic at 20-40 (order 4.0). The reference is exact to 1e-9 (shooting).
CANTILEVER_TOL = 3.0e-5
#: the least order from 20 to 40 elements (measured 5.9, 5.8, 5.1, 4.0 at alpha = 1, 2, 5,
#: 10; the h^6 asymptote is only reached from 40 elements at alpha = 10)
CANTILEVER_ORDER = 3.5


def tip_load(alpha: float) -> float:
    return alpha * CEI / CL ** 2


def elastica(P: float, EA: float):
    """The extensible elastica of the cantilever (module docstring): the dense solution
    of (theta, theta', x, y) over s in [0, L] from the tip."""
    def rhs(s, z):
        th, om, _, _ = z
        stretch = 1.0 + P * math.sin(th) / EA
        return [om, -P * stretch * math.cos(th) / CEI, stretch * math.cos(th),
                stretch * math.sin(th)]

    def shoot(theta0, dense=False):
        return solve_ivp(rhs, (0.0, CL), [theta0, 0.0, 0.0, 0.0], method="DOP853",
                         rtol=1e-12, atol=1e-14, dense_output=dense)

    # theta(L) < 0 for a tip angle near 0 (the line bends down past the clamp's
    # direction), theta(L) = pi/2 > 0 at pi/2 (a vertical line stays vertical)
    theta0 = brentq(lambda t: shoot(t).y[0, -1], 1e-9, 0.5 * math.pi - 1e-12, xtol=1e-15)
    return shoot(theta0, dense=True)


def deflections(sol) -> tuple[float, float]:
    """(w/L, u/L) of an elastica."""
    return sol.y[3, -1] / CL, (CL - sol.y[2, -1]) / CL


def cantilever_scene(P: float, EA: float):
    data = builders.line(CL, (0.0, 0.0), (CL, CL + 1.0),
                         line_type=builders.pipe(bending_stiffness=CEI, axial_stiffness=EA),
                         submerged_weight=0.0,
                         environment={"gravity": G, "water_density": 1025.0})
    data["ends"]["anchor_joint"] = {"kind": "free"}
    data["ends"]["hang_off_joint"] = {"kind": "clamped", "direction_deg": 0.0}
    data["attachments"] = [{"s": 0.0, "mass": P / G}]      # net weight P, down
    return builders.scene(data)


def elastica_start(sol, P: float, EA: float):
    """A replacement of ``ancf.solver.straight_start``: the nodes on the elastica ``sol``
    hung from the hang-off, slopes (1 + T/EA) t."""
    def start(scene, mesh, d):
        assert d == 2
        th, _, x, y = sol.sol(mesh.s)
        hx, hy = scene.ends.hang_off_point[:2]
        stretch = 1.0 + P * np.sin(th) / EA
        q = np.column_stack([hx - (sol.y[2, -1] - x), hy - (sol.y[3, -1] - y),
                             stretch * np.cos(th), stretch * np.sin(th)])
        return q, P * np.sin(th)
    return start


def solve_cantilever(monkeypatch, P: float, EA: float, elements: int):
    """ANCF statics of the cantilever of tip load P, started from the elastica of 0.998 P
    (module docstring)."""
    monkeypatch.setattr(ancf_solver, "straight_start",
                        elastica_start(elastica(0.998 * P, EA), 0.998 * P, EA))
    res = ancf.solve(cantilever_scene(P, EA), element_length=CL / elements, tolerance=1e-10)
    assert res.converged, res.message
    return res


def measured(profile) -> tuple[float, float]:
    """(w/L, u/L) of an ANCF profile (s from the tip)."""
    return ((profile.y[-1] - profile.y[0]) / CL,
            (CL - (profile.x[-1] - profile.x[0])) / CL)


def test_the_elastica_reference_is_bisshopp_and_druckers_table():
    for alpha, (w, u) in TABLE.items():
        P = tip_load(alpha)
        wi, ui = deflections(elastica(P, math.inf))
        assert wi == pytest.approx(w, abs=TABLE_ROUNDING)
        assert ui == pytest.approx(u, abs=TABLE_ROUNDING)
        # the extensibility of EA = 1e6 P (measured <= 8e-7)
        we, ue = deflections(elastica(P, EA_OVER_P * P))
        assert abs(we - wi) < 3e-6 and abs(ue - ui) < 3e-6
    # control: the elastica of a load 1 % off misses the table (measured >= 1.2e-3)
    wx, ux = deflections(elastica(1.01 * tip_load(10), math.inf))
    assert max(abs(wx - TABLE[10][0]), abs(ux - TABLE[10][1])) > 100 * TABLE_ROUNDING


def test_the_public_solve_of_the_clamped_cantilever_is_the_elastica():
    alpha, elements = 2, 20
    P = tip_load(alpha)
    EA = EA_OVER_P * P
    res = ancf.solve(cantilever_scene(P, EA), element_length=CL / elements, tolerance=1e-10)
    assert res.converged, res.message
    # the clamp holds the tangent horizontal (measured: 90 deg, vertical)
    assert res.profile.theta[-1] == pytest.approx(0.0, abs=1e-9)
    w, u = measured(res.profile)
    wr, ur = deflections(elastica(P, EA))
    # at 20 elements alpha = 2: measured 1.8e-5 and 8.5e-6 from the clamped start
    assert abs(w - wr) < 2 * CANTILEVER_TOL and abs(u - ur) < 2 * CANTILEVER_TOL


@pytest.mark.parametrize("alpha", sorted(TABLE))
def test_the_large_deflection_cantilever_is_the_elastica(alpha, monkeypatch):
    P = tip_load(alpha)
    EA = EA_OVER_P * P
    wr, ur = deflections(elastica(P, EA))
    errors = {}
    for elements in (10, 20, 40):
        res = solve_cantilever(monkeypatch, P, EA, elements)
        w, u = measured(res.profile)
        errors[elements] = (abs(w - wr), abs(u - ur))
        p = res.profile
        # the clamp holds: the tangent at the hang-off along +x
        assert p.theta[-1] == pytest.approx(0.0, abs=1e-12)
        # section forces against statics, exact for any shape (no discretisation in
        # them, only the Newton stop: the residual <= 16 x the round-off floor, 1.5e-7 P
        # at 40 elements; measured <= 3e-8 P): the tension and the shear at the tip are
        # P sin(theta0), P cos(theta0), the moment at the nodes P (x - x_tip)
        th0 = p.theta[0]
        assert p.tension[0] == pytest.approx(P * math.sin(th0), abs=1e-6 * P)
        assert p.shear[0] == pytest.approx(P * math.cos(th0), abs=1e-6 * P)
        nodes = np.isclose(np.mod(p.s * elements / CL + 0.5, 1.0), 0.5)
        assert nodes.sum() == elements + 1
        assert np.max(np.abs(p.moment[nodes] - P * (p.x[nodes] - p.x[0]))) < 1e-6 * P * CL
    # 40 elements: the closed form to CANTILEVER_TOL, and so the table to it plus its
    # rounding and the extensibility (< 3e-6)
    assert max(errors[40]) < CANTILEVER_TOL, errors
    w40 = wr - errors[40][0]
    assert abs(w40 - TABLE[alpha][0]) < CANTILEVER_TOL + TABLE_ROUNDING + 3e-6
    # convergence: order >= CANTILEVER_ORDER from 20 to 40 elements in both
    for k in (0, 1):
        order = math.log2(errors[20][k] / errors[40][k])
        assert order > CANTILEVER_ORDER, (k, errors)
    # negative control: the same solve with a tip load 1 % heavier (its own start)
    # against the nominal elastica misses by 2.5e-3, 2.8e-3, 2.6e-3, 2.1e-3 (the larger of
    # w and u, measured): 70 x the tolerance or more
    res = solve_cantilever(monkeypatch, 1.01 * P, EA, 40)
    w, u = measured(res.profile)
    assert max(abs(w - wr), abs(u - ur)) > 10 * CANTILEVER_TOL


# ================================================================== 2. the elastic catenary
ANCHOR = np.array([0.0, 20.0])
HANG_OFF = np.array([100.0, 60.0])
CAT_L = 130.0           # [m]
CAT_W = 100.0           # [N/m] submerged weight
CAT_EA = 1.0e7          # [N] (stretch w L / EA = 1.3e-3: the elasticity is visible)
CAT_EI = 0.01           # [N m2] the string limit (module docstring)
#: relative errors of the end tensions at 40 elements (3.25 m). Measured 2.3e-8 and
#: 1.4e-8 (weight), 1.2e-8 and 1.0e-8 (tilted load); order 4 in the element length down
#: to the bending correction 7e-10; the Newton stop (16 x the round-off floor, 3e-9 of
#: the load per element, 325 N: 1e-6 N per node) is 2e-10 of the tension
CAT_TENSION_TOL = 1.0e-7
#: relative error of the mid-span sag at 40 elements: measured 1.7e-6 and 4.3e-7 (the
#: profile's positions inside an element are its cubic: order 4 there, against 4.3-4.8 at
#: the nodes); the sag is read off a cubic spline through the 0.5 m samples (1e-10)
CAT_SAG_TOL = 5.0e-6
#: the largest distance of a profile sample from the closed form, / L, at 40 elements:
#: measured 4.2e-7 and 2.7e-7
CAT_POSITION_TOL = 1.0e-6


def elastic_catenary(load, EA: float = CAT_EA, L: float = CAT_L):
    """(H, V0, Q, positions(s) (k, 2), tension(s)) of the elastic catenary from ANCHOR to
    HANG_OFF under ``load`` = (qx, qy) [N/m] per unstretched length (module docstring)."""
    q = np.asarray(load, float)
    Q = float(np.hypot(*q))
    up = -q / Q
    e1 = np.array([up[1], -up[0]])          # X: normal to the load, towards the hang-off
    chord = HANG_OFF - ANCHOR
    DX, DY = float(chord @ e1), float(chord @ up)
    assert DX > 0.0

    def XY(H, V0, s):
        V = V0 + Q * s
        X = H * s / EA + H / Q * (np.arcsinh(V / H) - math.asinh(V0 / H))
        Y = ((V0 * s + Q * s * s / 2.0) / EA
             + H / Q * (np.sqrt(1.0 + (V / H) ** 2) - math.sqrt(1.0 + (V0 / H) ** 2)))
        return X, Y

    def gap(p):
        X, Y = XY(math.exp(p[0]), p[1], L)
        return [(X - DX) / L, (Y - DY) / L]

    sol = least_squares(gap, [math.log(Q * L / 2.0), -Q * L / 4.0], method="lm",
                        xtol=1e-15, ftol=1e-15, gtol=1e-15)
    assert np.max(np.abs(sol.fun)) < 1e-12, sol.fun
    H, V0 = math.exp(sol.x[0]), float(sol.x[1])

    def positions(s):
        X, Y = XY(H, V0, np.asarray(s, float))
        return ANCHOR[None, :] + np.outer(X, e1) + np.outer(Y, up)

    def tension(s):
        return np.hypot(H, V0 + Q * np.asarray(s, float))

    return H, V0, Q, positions, tension


def mid_sag(x, y) -> float:
    """Vertical distance [m] below the chord at mid-span of a curve y(x) (a cubic spline
    through the samples)."""
    xm = 0.5 * (ANCHOR[0] + HANG_OFF[0])
    return 0.5 * (ANCHOR[1] + HANG_OFF[1]) - float(CubicSpline(x, y)(xm))


def closed_sag(positions) -> float:
    xm = 0.5 * (ANCHOR[0] + HANG_OFF[0])
    s = brentq(lambda v: positions([v])[0, 0] - xm, 0.0, CAT_L, xtol=1e-13)
    return 0.5 * (ANCHOR[1] + HANG_OFF[1]) - float(positions([s])[0, 1])


def solve_catenary(elements: int, weight: float = CAT_W, qx: float = 0.0):
    data = builders.line(CAT_L, tuple(ANCHOR), tuple(HANG_OFF),
                         line_type=builders.small_pipe(bending_stiffness=CAT_EI,
                                                       axial_stiffness=CAT_EA),
                         submerged_weight=weight)
    res = ancf.solve(builders.scene(data), element_length=CAT_L / elements,
                     dead_load=(qx, 0.0, 0.0), tolerance=1e-10)
    assert res.converged, res.message
    assert not res.profile.is_3d
    return res


def catenary_errors(res, positions, tension) -> dict:
    p = res.profile
    assert np.all(np.diff(p.x) > 0.0)
    ref = positions(p.s)
    return {"anchor_tension": p.tension[0] / float(tension(0.0)) - 1.0,
            "hang_off_tension": p.tension[-1] / float(tension(CAT_L)) - 1.0,
            "sag": mid_sag(p.x, p.y) / closed_sag(positions) - 1.0,
            "position": float(np.max(np.hypot(p.x - ref[:, 0], p.y - ref[:, 1]))) / CAT_L}


def within(err: dict) -> bool:
    return (abs(err["anchor_tension"]) < CAT_TENSION_TOL
            and abs(err["hang_off_tension"]) < CAT_TENSION_TOL
            and abs(err["sag"]) < CAT_SAG_TOL and err["position"] < CAT_POSITION_TOL)


@pytest.mark.parametrize("qx", [0.0, 0.3 * CAT_W], ids=["weight", "tilted_load"])
def test_a_catenary_between_fixed_ends_is_the_elastic_catenary(qx):
    _, _, _, positions, tension = elastic_catenary((qx, -CAT_W))
    errs = {n: catenary_errors(solve_catenary(n, qx=qx), positions, tension)
            for n in (20, 40, 80)}
    assert within(errs[40]), errs[40]
    # convergence: order >= 3 in the end tensions from 20 to 40 and from 40 to 80
    # elements (measured 4.7, 4.4 and 4.1, 4.0; weight; 4.6 and 3.9 tilted: order 4, the
    # 80-element figure 1e-9 over the bending correction 7e-10)
    for key in ("anchor_tension", "hang_off_tension"):
        for coarse, fine in ((20, 40), (40, 80)):
            assert abs(errs[coarse][key]) > 8.0 * abs(errs[fine][key]), (key, errs)
    # negative controls, same tolerance: the inextensible catenary (tensions 7.1e-4 and
    # 8.6e-4 off, sag 1.9e-3: the test sees the stretch) and the same solve with a 1 %
    # heavier weight (the tensions 1 % off)
    _, _, _, pos_inext, ten_inext = elastic_catenary((qx, -CAT_W), EA=1e16)
    bad = catenary_errors(solve_catenary(40, qx=qx), pos_inext, ten_inext)
    assert abs(bad["anchor_tension"]) > 1000 * CAT_TENSION_TOL, bad
    assert not within(bad)
    bad = catenary_errors(solve_catenary(40, weight=1.01 * CAT_W, qx=qx), positions, tension)
    assert abs(bad["hang_off_tension"]) > 1000 * CAT_TENSION_TOL, bad


# ================================================================== 3. beam, string, both
SPAN = 20.0             # [m]
HEIGHT = 5.0            # [m] of both ends
LOAD = 0.1              # [N/m] transverse dead load (down)
ODD = np.arange(1, 40001, 2)
CASES = {               # EI [N m2], EA [N], pretension [N]
    "beam": (1.0e5, 1.0e7, 0.0),
    "beam_string": (4.0e3, 1.0e7, 1.0e3),
    "string": (1.0e-2, 1.0e7, 1.0e3),
}
#: relative error of the mid-span deflection and tension at 40 elements: the small-slope
#: theory's own error, O(slope^2) with the largest slope 3.3e-4 (beam), 8.0e-4, 1.0e-3:
#: slope^2 <= 1e-6 = BEAM_TOL / 2. Measured 6.0e-8, 1.0e-9, 7.8e-8 (deflection) and 2.3e-8, 1.4e-7,
#: 1.7e-7 (tension); the discretisation at 40 elements (order 4-8) is below them
BEAM_TOL = 2.0e-6
#: relative error of the mid-span moment: the beam's 2.0e-8 (measured); the beam-string's
#: M = q S^2/8 - H w(S/2) is 12.7 x smaller than each of its terms, which amplifies the
#: deflection's error: 12.7 x BEAM_TOL (measured 4.0e-7)
MOMENT_TOL = {"beam": BEAM_TOL, "beam_string": 13.0 * BEAM_TOL}


def beam_string(q: float, EI: float, EA: float, L0: float):
    """(H [N], mid-span deflection [m], mid-span moment [N m], largest slope) of the
    small-slope beam-string between immovable pinned ends (module docstring)."""
    k = ODD * math.pi / SPAN
    sign = np.where((ODD // 2) % 2 == 0, 1.0, -1.0)        # sin(n pi / 2)

    def parts(H):
        eps = H / EA
        qx, EIx = q / (1.0 + eps), EI * (1.0 + eps)
        return qx, EIx, 4.0 * qx / (ODD * math.pi) / (EIx * k ** 4 + H * k ** 2)

    def gap(H):
        qx, _, wn = parts(H)
        mean_w = float(np.sum(wn * 2.0 / k)) / SPAN
        return (SPAN + 0.25 * SPAN * float(np.sum(k ** 2 * wn ** 2))
                - L0 - L0 / EA * (H + qx * mean_w))

    H = brentq(gap, 0.0, 1.0e6, xtol=1e-15, rtol=1e-15)
    _, EIx, wn = parts(H)
    return (H, float(np.sum(wn * sign)), float(EIx * np.sum(wn * k ** 2 * sign)),
            float(np.sum(wn * k)))


def series(q, EI, H, x):
    """The pinned beam-string's deflection at x for a given H (no stretch terms)."""
    k = ODD * math.pi / SPAN
    return float(np.sum(4.0 * q / (ODD * math.pi) / (EI * k ** 4 + H * k ** 2)
                        * np.sin(k * x)))


def test_the_beam_string_series_has_the_textbook_limits():
    # H -> 0: 5 q S^4 / (384 EI); EI -> 0: q S^2 / (8 H); the truncation at n = 40000 is
    # 1e-18 of them
    assert series(1.0, 1.0e5, 0.0, SPAN / 2) == pytest.approx(
        5.0 * SPAN ** 4 / (384.0 * 1.0e5), rel=1e-12)
    assert series(1.0, 1.0e-12, 1.0e3, SPAN / 2) == pytest.approx(
        SPAN ** 2 / (8.0 * 1.0e3), rel=1e-12)
    # control: the other limit's formula is 100 % off
    assert abs(series(1.0, 1.0e5, 0.0, SPAN / 2) / (5.0 * SPAN ** 4 / (384.0 * 2.0e5)) - 1.0) > 0.5


def solve_straight(name: str, q: float, elements: int = 40):
    EI, EA, pre = CASES[name]
    L0 = SPAN / (1.0 + pre / EA)
    data = builders.straight(L0, SPAN, height=HEIGHT,
                             line_type=builders.small_pipe(bending_stiffness=EI,
                                                           axial_stiffness=EA))
    res = ancf.solve(builders.scene(data), element_length=L0 / elements,
                     dead_load=(0.0, -q, 0.0), tolerance=1e-10)
    assert res.converged, res.message
    p = res.profile
    i = int(np.argmin(np.abs(p.s - 0.5 * L0)))
    assert p.s[i] == pytest.approx(0.5 * L0, abs=1e-9)
    assert p.x[i] == pytest.approx(0.5 * SPAN, abs=1e-9)     # symmetry
    return HEIGHT - p.y[i], p.tension[i], p.moment[i], L0


@pytest.mark.parametrize("name", sorted(CASES))
def test_a_straight_line_under_a_uniform_transverse_load_is_the_beam_string(name):
    EI, EA, pre = CASES[name]
    w, T, M, L0 = solve_straight(name, LOAD)
    H, w_ref, M_ref, slope = beam_string(LOAD, EI, EA, L0)
    assert slope < 1.0e-3                       # slope^2 < 1e-6 = BEAM_TOL / 2
    assert w == pytest.approx(w_ref, rel=BEAM_TOL)
    assert T == pytest.approx(H, rel=BEAM_TOL)
    if name in MOMENT_TOL:      # the string's moment, EI = 0.01 N m2, is 1e-6 N m: no test
        assert M == pytest.approx(M_ref, rel=MOMENT_TOL[name])
    # negative control: the same solve with the load 1 % higher misses the nominal
    # closed form's deflection by 1 % (measured 1.00e-2, 0.997e-2, 0.997e-2)
    w_bad, _, _, _ = solve_straight(name, 1.01 * LOAD)
    assert abs(w_bad / w_ref - 1.0) > 1000 * BEAM_TOL
    # and the closed forms without the effect each case turns on miss the ANCF:
    if name == "beam":
        # the linear beam without the membrane tension of its immovable ends: 1.1e-4
        assert abs(w / (5.0 * LOAD * SPAN ** 4 / (384.0 * EI)) - 1.0) > 50 * BEAM_TOL
    elif name == "string":
        # the string of the pretension alone (without the sag's own stretch): 1.8e-3
        assert abs(w / (LOAD * SPAN ** 2 / (8.0 * pre)) - 1.0) > 500 * BEAM_TOL
    else:
        # the string of the same tension without bending: 7.9e-2
        assert abs(w / (LOAD * SPAN ** 2 / (8.0 * H)) - 1.0) > 1000 * BEAM_TOL

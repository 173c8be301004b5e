"""The analytic method (analytic/): its closed forms against numerical integration, its
boundary layers against their limits, and its answers against the BVP, with the
eps-scaling of its error pinned.

eps = sqrt(EI / (H L^2)) (L the suspended length), delta = w lambda / H."""

from __future__ import annotations

import dataclasses
import math
import subprocess
import sys

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid

import analytic
import bvp
from analytic.catenary import Catenary, bending_correction, vertex_length_for_height
from analytic.layers import anchor_layer, touchdown_layer
from riser.results.result import Status
from riser.model.scene import FixedEnds, HangOffAngleEnds, TopTensionEnds
from riser.model.sections import segment_properties
from riser.model.settings import AnalyticSettings
from verification.catalog import builtin_paths, resolve

KANG = "kang2015-jlay"


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "verification.cli", *args],
                          capture_output=True, text=True, timeout=120)


# ------------------------------------------------------------------ closed forms
def test_catenary_closed_form_integrates_its_own_ode():
    """x, y of the extensible catenary equal the integral of (1 + T/EA)(cos, sin) theta
    with tan(theta) = V/H; the length-for-height inverse is exact. Trapezoid error on
    0.01 m steps is ~1e-9 m."""
    cat = Catenary(3.0e5, -2.0e5, 1500.0, 2.0e9)
    s = np.linspace(0.0, 2000.0, 200001)
    th, T = cat.theta(s), cat.tension(s)
    c = 1.0 + T / cat.EA
    assert np.max(np.abs(cumulative_trapezoid(c * np.cos(th), s, initial=0) - cat.x(s))) < 1e-6
    assert np.max(np.abs(cumulative_trapezoid(c * np.sin(th), s, initial=0) - cat.y(s))) < 1e-6
    v = Catenary(3.0e5, 0.0, 1500.0, 2.0e9)
    L = vertex_length_for_height(v.H, v.w, v.EA, 1234.5)
    assert float(v.y(L)) == pytest.approx(1234.5, rel=1e-12)


def test_bending_correction_closed_form():
    """The O(eps^2) outer correction's closed forms (catenary.py docstring) against the
    integrals they solve: dy2' = (1+T0/EA) cos(theta0) theta2, dx2' = -(1+T0/EA)
    sin(theta0) theta2, and theta2' by differences (trapezoid/difference errors ~1e-9)."""
    cat, EI = Catenary(8.0e5, 0.0, 1600.0, 8.0e9), 2.0e8
    s = np.linspace(0.0, 3000.0, 300001)
    dx, dy, th2, dth2 = bending_correction(cat, EI, s)
    c, t0 = 1.0 + cat.tension(s) / cat.EA, cat.theta(s)
    assert np.max(np.abs(cumulative_trapezoid(c * np.cos(t0) * th2, s, initial=0) - dy)) < 1e-8
    assert np.max(np.abs(cumulative_trapezoid(-c * np.sin(t0) * th2, s, initial=0) - dx)) < 1e-8
    assert np.max(np.abs(np.gradient(th2, s) - dth2)) < 1e-6 * np.max(np.abs(dth2))
    # far up the height change tends to -EI w / (2 H^2), the rigid layer's vertex lift
    assert dy[-1] == pytest.approx(-EI * cat.w / (2 * cat.H ** 2), rel=0.01)


# ------------------------------------------------------------------ boundary layers
def test_rigid_touchdown_layer_closed_form():
    """Rigid seabed: the vertex is lambda = sqrt(EI/(cH)) along the line and
    q/(2 a^2) = c w lambda^2 / (2 H) up (layers.py docstring), exactly."""
    H, w, EI, EA = 8.3e5, 1617.0, 2.0e8, 8.8e9
    lay = touchdown_layer(H, w, EI, EA, None)
    c = 1.0 + H / EA
    lam = math.sqrt(EI / (c * H))
    assert lay.s_v == pytest.approx(lam, rel=1e-12)
    assert lay.y_v == pytest.approx(c * w * lam ** 2 / (2 * H), rel=1e-12)
    y, y1, y2, _ = lay.correction(np.zeros(1))
    # with the polynomial part y(0) = y'(0) = y''(0) = 0: y = A0 + C = 0 needs A0 = -C
    assert y2[0] + c * w / H == pytest.approx(0.0, abs=1e-15)      # M(0) = 0


def test_elastic_touchdown_layer_solves_its_equations_and_tends_to_rigid():
    """The elastic layer satisfies y'''' - a y'' + b y = -q in contact (finite differences,
    h = 0.05 m: truncation ~h^2 y'''''' and round-off ~1e-16 y / h^4, both < 1e-5 q),
    rests at -w/k far from the touchdown (120 m: 13 decay lengths), and its vertex shift
    tends to the rigid lambda as k grows (the rigid seabed is its limit): the gap is about
    the foundation length (4 EI / k)^(1/4), so it falls by 100^(1/4) = 3.16 per factor 100
    of k (measured 3.17; 10 % allowed for the next-order term)."""
    H, w, EI, EA = 8.3e5, 1617.0, 2.0e8, math.inf
    lay = touchdown_layer(H, w, EI, EA, 1.0e5)
    a, b, q = H / EI, 1.0e5 / EI, w / EI
    h = 0.05
    s = np.arange(-120.0, -1.0, h)
    y = lay.grounded(s)[0]
    d4 = (y[4:] - 4 * y[3:-1] + 6 * y[2:-2] - 4 * y[1:-3] + y[:-4]) / h ** 4
    d2 = (y[3:-1] - 2 * y[2:-2] + y[1:-3]) / h ** 2
    resid = d4 - a * d2 + b * y[2:-2] + q
    assert np.max(np.abs(resid)) < 1e-4 * q
    assert y[0] == pytest.approx(-w / 1.0e5, rel=1e-3)
    assert np.all(lay.grounded(np.linspace(-50, -1e-3, 500))[0] < 0.0)   # in contact
    lam = math.sqrt(EI / H)
    gaps = [lam - touchdown_layer(H, w, EI, EA, k).s_v for k in (1e6, 1e8, 1e10)]
    assert 0 < gaps[2] < gaps[1] < gaps[0] and gaps[2] < 0.05 * lam
    assert gaps[1] / gaps[2] == pytest.approx(100 ** 0.25, rel=0.1)


def test_anchor_layer_meets_its_conditions():
    """An anchor pinned at y = 0 on the elastic seabed: y(0) = 0, M(0) = 0, the rest
    position -w/k a few foundation lengths away (exp(-10) ~ 5e-5)."""
    lay = anchor_layer(3.2e5, 526.0, 9.75e6, 1.3e9, 1.0e5)
    y, y1, y2, _ = lay.correction(np.array([0.0, 10 * lay.length]))
    assert y[0] - 526.0 / 1.0e5 == pytest.approx(0.0, abs=1e-12)
    assert y2[0] == pytest.approx(0.0, abs=1e-12)
    assert abs(y[1]) < 1e-4 * 526.0 / 1.0e5


# ------------------------------------------------------------------ against the BVP
def _both(scene):
    b, a = bvp.solve(scene), analytic.solve(scene)
    assert b.converged and a.converged, (b.message, a.message)
    return b.summary(), a.summary(), a


def test_kang_jlay_against_bvp():
    """Kang's J-lay (eps 4.4e-3): the composite's peak touchdown moment and top angle
    against the BVP (issue target 2 %; measured 5e-5 and 1e-4 deg, inside the BVP's own
    1e-6 collocation tolerance times the moment's sensitivity), and the exact first
    integral of the inextensible beam with a moment-free top, H = T_top - w Y, to 1e-6
    (the outer's bending correction makes the composite keep it)."""
    sc = resolve(KANG)
    sb, sa, res = _both(sc)
    assert sa["max_moment"] == pytest.approx(sb["max_moment"], rel=5e-4)
    assert abs(sa["hang_off_angle_deg"] - sb["hang_off_angle_deg"]) < 2e-3
    assert abs(sa["hang_off_x"] - sb["hang_off_x"]) < 0.1           # eps^3 L ~ 0.3 mm x 10^2
    w = segment_properties(sc)[0].weight
    assert res.info["horizontal_tension"] == pytest.approx(5.681e6 - w * 3000.0, rel=2e-6)
    assert sa["tdp_tension"] == pytest.approx(sb["tdp_tension"], rel=1e-5)
    assert res.wall_time_s < 0.05                                    # closed form: ms


def test_scr_fixed_ends_elastic_seabed_against_bvp():
    """The built-in SCR (fixed ends, extensible, 1e5 N/m2 seabed, eps 3.7e-3): peak
    moment, touchdown, hang-off tension and angle against the BVP, closer than the VFIFE
    at 1 m (its differences: 2e-4, 5 mm, 2e-5, 6e-4 deg)."""
    sb, sa, _ = _both(resolve("scr-steel"))
    assert sa["max_moment"] == pytest.approx(sb["max_moment"], rel=1e-4)
    assert abs(sa["tdp_x"] - sb["tdp_x"]) < 0.01
    assert sa["hang_off_tension"] == pytest.approx(sb["hang_off_tension"], rel=2e-5)
    assert abs(sa["hang_off_angle_deg"] - sb["hang_off_angle_deg"]) < 1e-3


@pytest.mark.parametrize("ends", [HangOffAngleEnds(hang_off_height=1000.0,
                                                   hang_off_angle_deg=70.0),
                                  FixedEnds(anchor=(0.0, 100.0), hang_off=(800.0, 1000.0))],
                         ids=["hang_off_angle", "free_hanging"])
def test_other_forms_against_bvp(ends):
    """The Wang angle form (rigid, inextensible) and a free-hanging line between pinned
    ends (no seabed): peak moment to 2e-4 (the free line's outer has no bending
    correction: O(eps^2) = 1e-5 of the span in position, 2e-4 of T in tension)."""
    sc = resolve("scr-steel")
    seg = dataclasses.replace(sc.segments[0], length=1300.0)
    sc = sc.replace(ends=ends, seabed=None, model={},
                    segments=(seg,) if isinstance(ends, FixedEnds) else sc.segments)
    sb, sa, _ = _both(sc)
    assert sa["max_moment"] == pytest.approx(sb["max_moment"], rel=2e-4)
    assert sa["hang_off_tension"] == pytest.approx(sb["hang_off_tension"], rel=3e-4)
    assert abs(sa["hang_off_angle_deg"] - sb["hang_off_angle_deg"]) < 0.01


def test_epsilon_scaling_of_the_error():
    """The error against the BVP as eps grows by sqrt(10) (EI 1e8 -> 1e9 on Kang's J-lay,
    BVP tolerance 1e-8 so that its own error is far below): the catenary's span error is
    O(eps) (slope 1.0 measured), the composite's top angle O(eps^2) (2.0) and its peak
    moment about O(eps^3) (2.6 over this interval, 2.8 fitted over eps 3e-4..1e-2 in
    reports/kang2015). The bounds leave 0.1-0.3 for the next-order terms; a composite
    without the outer bending correction or the layer's vertex shift is O(eps) in angle
    and O(eps^2) in the moment and fails them."""
    base = resolve(KANG)
    lt_name = base.segments[0].line_type
    rows = []
    for EI in (1.0e8, 1.0e9):
        lt = dataclasses.replace(base.line_types[lt_name], bending_stiffness=EI)
        sc = base.replace(line_types={lt_name: lt}, bvp=base.bvp.replace(tolerance=1e-8))
        sb, sa, res = _both(sc)
        cat = analytic.solve(sc.replace(analytic=AnalyticSettings(model="catenary"))).summary()
        rows.append((res.info["epsilon"], abs(sa["max_moment"] / sb["max_moment"] - 1),
                     abs(sa["hang_off_angle_deg"] - sb["hang_off_angle_deg"]),
                     abs(cat["hang_off_x"] - sb["hang_off_x"])))
    (e1, m1, a1, x1), (e2, m2, a2, x2) = rows
    slope = lambda v1, v2: math.log(v2 / v1) / math.log(e2 / e1)     # noqa: E731
    assert 0.8 < slope(x1, x2) < 1.2
    assert 1.7 < slope(a1, a2) < 2.3
    assert slope(m1, m2) > 2.5


def test_piecewise_and_catenary_models():
    """Kang's piecewise model equals the composite below its top layer and keeps the
    catenary's moment EI kappa at the top (Kang's separation moment); the catenary model
    has the moment jump EI w / H at the touchdown and overestimates the peak moment."""
    sc = resolve(KANG)
    comp = analytic.solve(sc)
    pw = analytic.solve(sc.replace(analytic=AnalyticSettings(model="piecewise")))
    cat = analytic.solve(sc.replace(analytic=AnalyticSettings(model="catenary")))
    H, w, EI = comp.info["horizontal_tension"], segment_properties(sc)[0].weight, 2.0e8
    below = comp.profile.s < comp.profile.s[-1] - 20 * comp.info["top_layer_length"]
    m_pw = np.interp(comp.profile.s, pw.profile.s, pw.profile.moment)
    assert np.max(np.abs(m_pw - comp.profile.moment)[below]) < 1e-6 * comp.summary()["max_moment"]
    assert comp.profile.moment[-1] < 1e-9 * comp.summary()["max_moment"]
    kappa_top = w * math.cos(math.radians(pw.summary()["hang_off_angle_deg"])) ** 2 / H
    assert pw.profile.moment[-1] == pytest.approx(EI * kappa_top, rel=1e-3)
    assert cat.profile.moment[0] == pytest.approx(EI * w / H, rel=1e-3)
    assert 1.01 < cat.summary()["max_moment"] / comp.summary()["max_moment"] < 1.05


# ------------------------------------------------------------------ refusals
@pytest.mark.parametrize("scene,key", [("yu2021-a3", "segments[1]"),
                                       ("wang2014-current-0p75", "environment.current")])
def test_refusals_exit_2(scene, key, tmp_path):
    """A multi-segment lazy wave and a current scene: refused before solving, one line
    naming the key, exit 2, no profile written."""
    r = _cli("solve", scene, "--method", "analytic", "--out", str(tmp_path / "o"))
    assert r.returncode == 2, r.stderr
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and key in lines[0] and "Traceback" not in r.stderr
    assert not (tmp_path / "o" / "profile.csv").exists()


def test_jlay_tension_too_small_is_no_equilibrium(tmp_path):
    """A top tension below w Y (4.85 MN for Kang's pipe in 3000 m) cannot hold a line that
    reaches the seabed: status no_equilibrium, exit 1, one line saying so."""
    sc = resolve(KANG)
    res = analytic.solve(sc.replace(ends=TopTensionEnds(top_tension=4.0e6,
                                                        hang_off_height=3000.0)))
    assert res.status is Status.NO_EQUILIBRIUM and res.message.startswith("no equilibrium")
    path = tmp_path / "low.toml"
    path.write_text(builtin_paths()[KANG].read_text().replace("5.681e6", "4.0e6"))
    r = _cli("solve", str(path), "--method", "analytic", "--out", str(tmp_path / "o"))
    assert r.returncode == 1 and "no equilibrium" in r.stderr and "Traceback" not in r.stderr


@pytest.mark.parametrize("table,key", [('[analytic]\nmodel = "exact"\n', "analytic.model"),
                                       ("[analytic]\ncurvature_threshold = -1.0\n",
                                        "analytic.curvature_threshold"),
                                       ('[analytic]\nmodel = "piecewise"\n'
                                        "curvature_threshold = 0.5\n",
                                        "analytic.curvature_threshold")])
def test_bad_analytic_settings_exit_2(table, key, tmp_path):
    """A model that does not exist, a negative threshold (read with the scene), and a
    threshold above the catenary's touchdown curvature w/H = 1.95e-3 1/m (the beam part
    would be empty; refused once H is known, before the profile): one line naming the
    key, exit 2."""
    path = tmp_path / "bad.toml"
    path.write_text(builtin_paths()[KANG].read_text() + "\n" + table)
    r = _cli("solve", str(path), "--method", "analytic", "--out", str(tmp_path / "o"))
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert r.returncode == 2 and len(lines) == 1 and key in lines[0], r.stderr


def test_piecewise_threshold_beyond_the_hang_off_warns():
    """A threshold below the catenary's top curvature (w H / T_top^2 = 4.2e-5 1/m on
    Kang's pipe) puts the switch point beyond the hang-off: named warning, no silent
    model change; the default w/(2H) switches 528 m up the line, no warning."""
    sc = resolve(KANG)
    low = analytic.solve(sc.replace(analytic=AnalyticSettings(model="piecewise",
                                                              curvature_threshold=1e-5)))
    assert any(w.startswith("piecewise_threshold:") for w in low.warnings)
    default = analytic.solve(sc.replace(analytic=AnalyticSettings(model="piecewise")))
    assert not default.warnings and default.info["piecewise_s_E"] < default.profile.s[-1]

"""The design checks against hand computations from the codes' formulas (riser/design):
DNV-OS-F201's combined loading (pure tension, pure bending, internal and external
pressure alone, a combined case), API RP 2RD's von Mises check, the thick-wall stresses
and the wall tension, the dynamic load effects, and the refusals of bad [design] input.

The section of every vector: the Wang et al. steel pipe, D = 0.2032 m, t = 0.0191 m
(D / t = 10.64 < 15, so beta = 0.4 + q_h), X65: SMYS 448 MPa, SMTS 531 MPa; alpha_U 0.96
gives f_y = 430.08 MPa, f_u = 509.76 MPa; safety class normal: gamma_SC gamma_m = 1.14 x
1.15 = 1.311. Hand values (written out below, from a calculator):
  alpha_c (q_h = 0) = 0.6 + 0.4 x 509.76 / 430.08 = 1.074107
  T_k = f_y alpha_c pi (D - t) t = 430.08e6 x 1.074107 x pi x 0.1841 x 0.0191 = 5.10310 MN
  M_k = f_y alpha_c (D - t)^2 t = 430.08e6 x 1.074107 x 0.1841^2 x 0.0191 = 299.046 kN m
  p_b = (2 / sqrt 3)(2 t / (D - t)) min(f_y, f_u / 1.15) = 1.154701 x 0.207496 x 430.08e6
      = 103.045 MPa
"""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest

from riser.design import api_2rd, dnv_f201
from riser.design.checks import static_columns
from riser.design.part import Design
from riser.design.wall import Wall, lame, stresses, wall_tension
from riser.errors import SceneError
from riser.io.scene_file import parse_scene

D, T_WALL = 0.2032, 0.0191
SMYS, SMTS = 448e6, 531e6
GAMMA = 1.14 * 1.15
#: the hand values of the module docstring (6 significant digits: the assertions allow
#: 1e-5 relative, the rounding of the hand values)
TK, MK, PB = 5.10310e6, 299.046e3, 103.045e6
HAND = 1e-5


def wall(n=1, E=2.06e11) -> Wall:
    def a(v):
        return np.full(n, v)
    return Wall(a(D), a(D - 2 * T_WALL), a(SMYS), a(SMTS), a(E), a(0.0))


def util(**kw):
    args = {"p_ld": 0.0, "p_e": 0.0, "M_d": 0.0, "T_ed": 0.0, **kw}
    return float(dnv_f201.utilisation(Design(), wall(), **args)[0])


def test_pure_tension():
    # gamma_SC gamma_m (T_ed / T_k)^2: 1.311 x (2 / 5.10310)^2 = 0.201370
    assert util(T_ed=2.0e6) == pytest.approx(GAMMA * (2.0e6 / TK) ** 2, rel=HAND)
    assert util(T_ed=2.0e6) == pytest.approx(0.201370, rel=HAND)
    # compression enters squared, as the criterion writes it
    assert util(T_ed=-2.0e6) == pytest.approx(util(T_ed=2.0e6), rel=1e-15)


def test_pure_bending():
    # gamma_SC gamma_m |M_d| / M_k: 1.311 x 100 / 299.046 = 0.438394
    assert util(M_d=1.0e5) == pytest.approx(0.438394, rel=HAND)
    assert util(M_d=-1.0e5) == pytest.approx(0.438394, rel=HAND)
    assert util(M_d=1.0e5) == pytest.approx(GAMMA * 1.0e5 / MK, rel=HAND)


def test_internal_pressure_only():
    # ((p_ld - p_e) / p_b)^2 = (20 / 103.045)^2 = 0.0376707
    assert util(p_ld=25.0e6, p_e=5.0e6) == pytest.approx(0.0376707, rel=HAND)
    # at p_ld = p_b the pressure term alone is 1: the criterion's burst limit
    assert util(p_ld=PB) == pytest.approx(1.0, rel=HAND)


def test_external_pressure_only_against_the_collapse_cubic():
    # net external overpressure alone: gamma_SC gamma_m (p_e - p_min) / p_c (the root of
    # the criterion's sum of squares), p_c the root in (0, min(p_el, p_p)) of
    # (p - p_el)(p^2 - p_p^2) = p p_el p_p f0 D / t, solved here with numpy's roots
    E, nu, f0 = 2.06e11, 0.3, 0.005
    fy = SMYS * 0.96
    p_el = 2 * E * (T_WALL / D) ** 3 / (1 - nu ** 2)       # 376.0 MPa
    p_p = 2 * fy * T_WALL / D                              # 80.85 MPa
    k = p_el * p_p * f0 * D / T_WALL
    roots = np.roots([1.0, -p_el, -(p_p ** 2) - k, p_el * p_p ** 2])
    pc = min(r.real for r in roots if abs(r.imag) < 1e-6 * abs(r) and 0 < r.real <= p_p)
    assert p_el == pytest.approx(376.0e6, rel=1e-3) and p_p == pytest.approx(80.85e6, rel=1e-3)
    got = util(p_ld=1.0e6, p_e=11.0e6)
    assert got == pytest.approx(GAMMA * 10.0e6 / pc, rel=1e-12)
    # without ovality p_c is the smaller of the elastic and plastic collapse pressures
    no_ovality = Design(ovality=0.0)
    u0 = dnv_f201.utilisation(no_ovality, wall(), 0.0, 10.0e6, 0.0, 0.0)[0]
    assert u0 == pytest.approx(GAMMA * 10.0e6 / min(p_el, p_p), rel=1e-12)


def test_combined_case_by_hand():
    # M_d 60 kN m, T_ed 1.5 MN, p_ld - p_e = 30 MPa (internal):
    # r = 30 / 103.045 = 0.291135; q_h = r 2 / sqrt 3 = 0.336174; beta = 0.736174
    # alpha_c = 1 - beta + beta 509.76 / 430.08 = 1.136389
    # M_k = 299.046 x 1.136389 / 1.074107 = 316.386 kN m; T_k = 5.10310 x 1.057985 = 5.39900 MN
    # U = 1.311 [ (60 / 316.386) sqrt(1 - r^2) + (1.5 / 5.39900)^2 ] + r^2
    #   = 1.311 [0.189642 x 0.956682 + 0.0771890] + 0.0847596 = 0.423805
    r = 30.0e6 / PB
    q_h = r * 2 / math.sqrt(3)
    beta = 0.4 + q_h
    a_c = 1 - beta + beta * SMTS / SMYS
    hand = GAMMA * ((60e3 / (MK * a_c / 1.074107)) * math.sqrt(1 - r * r)
                    + (1.5e6 / (TK * a_c / 1.074107)) ** 2) + r * r
    assert hand == pytest.approx(0.423805, rel=2e-5)
    assert util(p_ld=32.0e6, p_e=2.0e6, M_d=60e3, T_ed=1.5e6) == pytest.approx(hand, rel=HAND)


def test_external_and_internal_forms_meet_at_zero_net_pressure():
    # the reported utilisation is continuous at p_ld = p_e (module docstring)
    below = util(p_ld=10.0e6 - 1.0, p_e=10.0e6, M_d=50e3, T_ed=1e6)
    above = util(p_ld=10.0e6 + 1.0, p_e=10.0e6, M_d=50e3, T_ed=1e6)
    assert below == pytest.approx(above, rel=1e-6)


def test_slender_pipe_has_no_strain_hardening():
    # D / t2 > 60: beta = 0, alpha_c = 1: M_k = f_y (D - t)^2 t
    thin = Wall(*(np.array([v]) for v in (1.0, 1.0 - 2 * 0.015, SMYS, SMTS, 2.06e11, 0.0)))
    u = dnv_f201.utilisation(Design(), thin, 0.0, 0.0, 1.0e5, 0.0)[0]
    assert u == pytest.approx(GAMMA * 1.0e5 / (SMYS * 0.96 * 0.985 ** 2 * 0.015), rel=1e-12)


def test_api_von_mises_by_hand():
    design = Design(code="api-rp-2rd", load_class="extreme")
    w = wall()
    area = math.pi / 4 * (D ** 2 - (D - 2 * T_WALL) ** 2)          # 0.0110469 m2
    # pure tension: sigma_vm = T / A; C_f C_a SMYS = 1.2 x 2/3 x 448 = 358.4 MPa
    st = stresses(w, np.array([2.0e6]), np.array([0.0]), 0.0, 0.0)
    assert st.von_mises[0] == pytest.approx(2.0e6 / area, rel=1e-12)
    assert api_2rd.utilisation(design, w, st.von_mises)[0] == pytest.approx(
        2.0e6 / 0.0110469 / 358.4e6, rel=HAND)
    # pure bending: sigma_b = M r_o / I at the outer fibre
    inertia = math.pi / 64 * (D ** 4 - (D - 2 * T_WALL) ** 4)
    st = stresses(w, np.array([0.0]), np.array([1.0e5]), 0.0, 0.0)
    assert st.von_mises[0] == pytest.approx(1.0e5 * D / 2 / inertia, rel=1e-12)
    # the survival class allows 1.5 / 1.2 times more
    assert api_2rd.allowable(Design(code="api-rp-2rd", load_class="survival"), w)[0] == \
        pytest.approx(1.5 * 2 / 3 * SMYS)


def test_lame_and_von_mises_under_pressure():
    w = wall()
    ri, ro = (D - 2 * T_WALL) / 2, D / 2
    p_i, p_e = 30.0e6, 10.0e6
    sh_i, sr_i = lame(w, p_i, p_e, ri)
    sh_o, sr_o = lame(w, p_i, p_e, ro)
    assert sr_i[0] == pytest.approx(-p_i, rel=1e-12) and sr_o[0] == pytest.approx(-p_e, rel=1e-12)
    # the mean hoop stress over the wall is the thin-wall balance (p_i r_i - p_e r_o) / t
    r = np.linspace(ri, ro, 20001)
    mean = np.trapezoid(lame(w, p_i, p_e, r)[0], r) / (ro - ri)
    assert mean == pytest.approx((p_i * ri - p_e * ro) / T_WALL, rel=1e-8)
    # pressure alone with closed ends (wall tension from the end caps): von Mises at the
    # bore by hand, the three principal stresses
    tw = wall_tension_alone = p_i * math.pi * ri ** 2 - p_e * math.pi * ro ** 2
    st = stresses(w, np.array([tw]), np.array([0.0]), p_i, p_e)
    sa = wall_tension_alone / (math.pi * (ro ** 2 - ri ** 2))
    hand = math.sqrt(((sa - sh_i[0]) ** 2 + (sh_i[0] - sr_i[0]) ** 2 + (sr_i[0] - sa) ** 2) / 2)
    assert st.von_mises[0] == pytest.approx(hand, rel=1e-12)


SCENE = """
name = "design-case"
[environment]
water_depth = 1000.0
[seabed]
stiffness = 1.0e5
[line_types.steel]
outer_diameter = 0.2032
wall_thickness = 0.0191
density = 7860.0
youngs_modulus = 2.06e11
contents_density = 800.0
yield_strength = 4.48e8
tensile_strength = 5.31e8
[[segments]]
line_type = "steel"
length = 2000.0
[ends]
anchor = [0.0, 0.0]
hang_off = [1500.0, 1000.0]
[design]
internal_pressure = 2.0e7
"""


def test_wall_tension_and_pressures_along_the_line():
    sc = parse_scene(SCENE)
    y = np.array([0.0, 500.0, 1000.0])
    cols = static_columns(sc, np.array([0.0, 1000.0, 2000.0]), y, np.full(3, 5.0e5),
                          np.zeros(3))
    ri2, ro2 = (0.2032 - 0.0382) ** 2 / 4, 0.2032 ** 2 / 4
    g = 9.81
    for k, yk in enumerate(y):
        p_i = 2.0e7 + 800.0 * g * (1000.0 - yk)
        p_e = 1025.0 * g * (1000.0 - yk)
        assert cols["wall_tension"][k] == pytest.approx(
            5.0e5 + p_i * math.pi * ri2 - p_e * math.pi * ro2, rel=1e-12)
    w = Wall(*(np.array([v]) for v in (0.2032, 0.165, SMYS, SMTS, 2.06e11, 800.0)))
    assert wall_tension(sc, w, 0.0, 1.0, 0.0)[0] == pytest.approx(math.pi * ri2, rel=1e-12)


def test_static_design_both_methods_agree():
    # the two methods' largest utilisation: the same post-processing of tensions and
    # moments that agree to 0.1 % of T_max and 0.5 % of M_max at 2 m elements; measured
    # 0.116664 (BVP) and 0.116673 (VFIFE): 1e-4 relative. Through the method registry,
    # which runs the design checks after each method's solve
    from verification.methods import method
    sc = parse_scene(SCENE)
    b = method("bvp").solve(sc).require().summary()
    v = method("vfife").solve(sc, element_length=2.0).require().summary()
    assert b["design_code"] == "dnv-st-f201" and b["design_passes"]
    assert v["max_utilisation"] == pytest.approx(b["max_utilisation"], rel=1e-3)
    assert 0.05 < b["max_utilisation"] < 0.5


BAD = [
    ("[design]\nsafety_class = \"medium\"", "design.safety_class"),
    ("[design]\ncode = \"asme\"", "design.code"),
    ("[design]\n[design.fatigue]\nsn_curve = \"Z\"", "design.fatigue.sn_curve"),
    ("[design]\n[design.fatigue]\n[[design.fatigue.sea_states]]\nhs = 2.0\ntp = 8.0\n"
     "probability = 0.5\n", "design.fatigue.sea_states"),
    ("[design]\ncorrosion_allowance = 0.02", "design.corrosion_allowance"),
]


@pytest.mark.parametrize("extra,key", BAD)
def test_bad_design_input_names_its_key(extra, key):
    text = SCENE.split("[design]")[0] + extra
    with pytest.raises(SceneError) as exc:
        parse_scene(text)
    assert exc.value.key == key


def test_design_needs_the_wall_and_the_strengths():
    no_yield = SCENE.replace("yield_strength = 4.48e8\n", "")
    with pytest.raises(SceneError) as exc:
        parse_scene(no_yield)
    assert exc.value.key == "line_types.steel.yield_strength"
    swapped = SCENE.replace("4.48e8", "6.0e8")
    with pytest.raises(SceneError) as exc:
        parse_scene(swapped)
    assert exc.value.key == "line_types.steel.yield_strength" and "tensile" in str(exc.value)
    props = SCENE.replace("wall_thickness = 0.0191\ndensity = 7860.0\nyoungs_modulus = 2.06e11\n"
                          "contents_density = 800.0\n", "mass_per_length = 88.0\naxial_stiffness"
                          " = 2.3e9\nbending_stiffness = 9.5e6\n")
    with pytest.raises(SceneError) as exc:
        parse_scene(props)
    assert exc.value.key == "line_types.steel.inner_diameter"


def test_cli_bad_design_is_one_line_exit_2(tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text(SCENE.replace("[design]", "[design]\nsafety_class = \"medium\""))
    r = subprocess.run([sys.executable, "-m", "verification.cli", "solve", str(p)],
                       capture_output=True, text=True)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "design.safety_class" in lines[0] and "Traceback" not in r.stderr

"""The ANCF's natural modes (ancf/modal.py): closed forms, the BVP on the built-in risers,
and the ANCF as a further column of ``riser-verify modes``.

Closed forms (docs/references.md, "Modal analysis"), each with a
negative control that must miss the same tolerance by a factor of 10 or more (the test
can fail):

1. A taut string, f_n = n / (2 L) sqrt(T / m): a weightless line (submerged weight 0)
   stretched 1e-3 between pinned ends at one height, with C_a = 1: its transverse modes,
   in and out of the plane, carry the mass and the added mass, m + m_a per unstretched
   length, over the stretched length L (m + m_a) L0 / L per stretched length (the BVP's
   closed form, tests/test_bvp_modes.py). EI = 1 N m2 raises f_n by (n pi / L)^2 EI /
   (2 T) = 1.8e-7 at n = 6; the cubic elements (2 m) add < 5e-8 (measured 5e-9 to 2.2e-7
   for n = 1..6 at 2 m, 1.8e-7 at n = 6 at 0.5 m: the EI term). Tolerance 1e-6.
   Controls: the closed form with m alone (the added mass left out) is 105 % high; the
   same line stretched 1 % more (T 1 % higher) misses the nominal closed form by 0.5 %.
2. A chain hanging from a fixed point, its lower end free (``[ends.anchor_joint] kind =
   "free"``), no seabed: omega_n = (j_0n / 2) sqrt(g_e / L), g_e = w / m (no added mass),
   j_0n the zeros of J0, in both planes, and the shapes J0(j_0n sqrt(x / L)), x the
   height above the free end. EI = 1 N m2 moves mode 5 by 5e-5 (the BVP's measure,
   tests/test_end_conditions.py) and the stretch w L / EA = 2e-5; measured -5.6e-6 to
   +5.5e-5 at 2 m elements (+5.1e-5 at 0.5 m: the EI term, not the mesh). Tolerance
   1e-4. Control: the same chain 1 % heavier misses the nominal closed form by 0.5 %.

Against the BVP (``verification.methods.method("bvp").modes``) on scr-steel, yu2021-a3,
wang2014-baseline (its fixed-ends equivalent, ``verification.pipeline.vfife_equivalent``,
as ``riser-verify modes`` takes it) and ttr-steel (a clamped wellhead, a tensioner, a
sheared current whose static drag is a dead load), the first 5 modes per plane (10 in the
slow test), the target of the modal protocol: within 0.5 % in frequency and MAC >= 0.99.
Measured, 10 modes per plane at the default 2 m elements (ANCF / BVP - 1):

- scr-steel: in plane +0.0038 to +0.0046 %, out of plane -4e-8; MAC >= 0.9999994;
- yu2021-a3: in plane -0.0003 to -0.021 %, out of plane < 1e-7; MAC >= 0.999995;
- wang2014-baseline: in plane -0.0011 to -0.018 %, out of plane < 2e-8; MAC >= 0.999999;
- ttr-steel: +1.1e-7 in both planes; MAC 1 to 1e-8.

The in-plane differences are the seabed contact: the ANCF's Winkler springs act at the
Gauss points below y = 0, so the grounded length is resolved to a Gauss interval, an
error of either sign bounded by the element length (yu2021-a3's in-plane mode 3, the
touchdown's mode: -0.021 % at 2 m, -0.067 % at 0.75 m, +0.022 % at 0.5 m, +0.0004 % at
0.25 m; the static touchdowns agree to 1 cm); the BVP splits its pieces at the lift-off
point. Out of plane (no contact term) the two agree to the BVP's tolerance.

ttr-steel and the BVP: the BVP's modal analysis ended ``not_converged`` there, rejecting
some in-plane modes whose refinement was right: its box-scheme guess applied the end rows'
coefficients unscaled to the states it scales (mended in bvp/modal/equations.py, found by
this comparison: its guess of in-plane mode 1 was 18 % off with the tensioner's mixed row).

A flex joint is isotropic out of plane (riser/model/ends.py; the BVP's B + k psi = 0):
the ANCF adds the joint's out-of-plane stiffness k / |r'|^2 at the joint's slope z. On
lazy-wave-flex-joint its out-of-plane modes agree with the BVP's to < 1e-6; without that
term they are 0.06 to 0.36 % low (the control).

Runtime: about 45 s (the BVP's modes dominate: 1 to 12 s a scene); the slow test 75 s.
"""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest
from scipy.special import j0, jn_zeros

import ancf
import ancf.modal as am
import builders
from riser.model.sections import segment_properties
from riser.results.modes import PLANES, mac
from riser.results.result import Status
from verification.catalog import resolve
from verification.comparison import modes as vm
from verification.comparison.modes import TARGET_MAC, TARGET_REL_DIFF, pair_rows
from verification.methods import method
from verification.pipeline import vfife_equivalent

STRING_RTOL = 1e-6       # see the module docstring
CHAIN_RTOL = 1e-4
SCENES = ("scr-steel", "yu2021-a3", "wang2014-baseline", "ttr-steel")
#: the scenes where the BVP's modal analysis rejects modes on its box-scheme guess (the
#: module docstring)


def frequencies(res, plane):
    return np.array([m.frequency_hz for m in res.family(plane)])


# ------------------------------------------------------------------ closed forms
def taut_string(strain=1e-3, *, EA=1e8, m=10.0, D=0.2, Ca=1.0):
    """A weightless 100 m span stretched by ``strain`` between pinned ends at 10 m."""
    span = 100.0
    L0 = span / (1.0 + strain)
    lt = {"outer_diameter": D, "mass_per_length": m, "axial_stiffness": EA,
          "bending_stiffness": 1.0, "added_mass": Ca, "max_strain": 0.1}
    return builders.scene(builders.straight(L0, span, height=10.0, line_type=lt)), L0, span


def string_frequencies(n, L0, span, T, mass):
    """f_n [Hz] of a string of ``mass`` per unstretched length L0 stretched to span."""
    return np.asarray(n) / (2.0 * span) * np.sqrt(T / (mass * L0 / span))


def test_a_taut_string_has_the_string_frequencies_with_the_added_mass():
    sc, L0, span = taut_string()
    res = am.solve_modes(sc, 6)
    assert res.converged, res.message
    p = segment_properties(sc)[0]
    assert p.added_mass > 3.0 * p.mass                   # C_a rho pi D^2 / 4 = 32 kg/m
    T = 1e8 * (span / L0 - 1.0)
    n = np.arange(1, 7)
    exact = string_frequencies(n, L0, span, T, p.mass + p.added_mass)
    for plane in PLANES:
        np.testing.assert_allclose(frequencies(res, plane), exact, rtol=STRING_RTOL)
        # the shapes: sin(n pi s / L0) across the line (y in plane, z out of it)
        comp = 1 if plane == "in_plane" else 2
        for mode in res.family(plane)[:3]:
            ref = np.sin(mode.number * math.pi * mode.s / L0)
            assert mac(mode.shape[:, comp], ref) > 1 - 1e-9
            assert np.max(np.abs(mode.shape[:, [c for c in range(3) if c != comp]])) < 1e-6
    # negative controls: the closed form without the added mass ...
    bare = string_frequencies(n, L0, span, T, p.mass)
    assert np.min(np.abs(frequencies(res, "in_plane") / bare - 1.0)) > 10 * STRING_RTOL
    # ... and the line stretched 1 % more against the nominal closed form (+0.5 %)
    tauter = am.solve_modes(taut_string(1.01e-3)[0], 6)
    assert tauter.converged, tauter.message
    miss = np.abs(frequencies(tauter, "in_plane") / exact - 1.0)
    assert np.min(miss) > 10 * STRING_RTOL and np.min(miss) == pytest.approx(5e-3, rel=0.02)


def hanging_chain(weight=200.0):
    """100 m of chain-like line (EI 1 N m2, no added mass) hanging from (0, 170) m, its
    lower end free, no seabed (tests/test_end_conditions.py's chain)."""
    data = builders.line(100.0, (0.0, 60.0), (0.0, 170.0), submerged_weight=weight,
                         line_type=builders.pipe(bending_stiffness=1.0, added_mass=0.0),
                         environment={"water_depth": 200.0})
    data["ends"]["anchor_joint"] = {"kind": "free"}
    return builders.scene(data)


def test_a_hanging_chain_with_a_free_end_has_the_bessel_frequencies():
    sc = hanging_chain()
    p = segment_properties(sc)[0]
    L = 100.0
    zeros = jn_zeros(0, 5)
    exact = zeros / 2.0 * math.sqrt(p.weight / p.mass / L) / (2.0 * math.pi)
    res = am.solve_modes(sc, 5)
    assert res.converged, res.message
    assert res.info["fixed"] == 3                  # the hang-off's x, y, z (3D model)
    for plane in PLANES:
        np.testing.assert_allclose(frequencies(res, plane), exact, rtol=CHAIN_RTOL)
        # the shapes, lateral (x in plane, z out of it): J0(j_0n sqrt(x / L)), x the
        # height above the free end (s from the free end, to the stretch 2e-5)
        comp = 0 if plane == "in_plane" else 2
        for mode in res.family(plane)[:3]:
            ref = j0(zeros[mode.number - 1] * np.sqrt(np.clip(mode.s / L, 0.0, 1.0)))
            assert mac(mode.shape[:, comp], ref) > 1 - 1e-6, (plane, mode.number)
    # negative control: the chain 1 % heavier against the nominal closed form (+0.5 %)
    heavy = am.solve_modes(hanging_chain(202.0), 5)
    assert heavy.converged, heavy.message
    miss = np.abs(frequencies(heavy, "in_plane") / exact - 1.0)
    assert np.min(miss) > 10 * CHAIN_RTOL


# ------------------------------------------------------------------ against the BVP
def bvp_modes(name: str, scene, count: int):
    """The BVP's modes of ``scene`` (converged: ttr-steel's too, since its box-scheme guess
    scales the end rows, bvp/modal/equations.py)."""
    b = method("bvp").modes(scene, count)
    assert b.converged, (name, b.message)
    return b


def compare_with_bvp(ancf_res, bvp_res, count: int) -> list:
    """(plane, mode, rel_diff, mac) of the ANCF's first ``count`` modes per plane against
    the BVP's, each asserted within the target."""
    rows = [r for r in pair_rows(bvp_res, ancf_res, "ancf") if r["mode"] <= count]
    assert len(rows) == 2 * count
    for r in rows:
        assert abs(r.rel_diff) <= TARGET_REL_DIFF and r["mac"] >= TARGET_MAC, \
            (r["plane"], r["mode"], r.rel_diff, r["mac"])
    return [(r["plane"], r["mode"], r.rel_diff, r["mac"]) for r in rows]


def ancf_and_bvp(name: str, count: int):
    scene = vfife_equivalent(resolve(name)).scene
    a = method("ancf").modes(scene, count)
    assert a.converged, a.message
    assert a.info["asymmetry"] < 1e-12 and a.info["coupling"] == 0.0
    return a, bvp_modes(name, scene, count)


# the default run's two cheapest scenes (the lazy waves' BVP modes take 20-45 s each): the
# slow test below runs all four at ten modes per plane
@pytest.mark.parametrize("name", [n if n in ("scr-steel", "ttr-steel")
                                  else pytest.param(n, marks=pytest.mark.slow)
                                  for n in SCENES])
def test_the_first_modes_agree_with_the_bvp(name):
    a, b = ancf_and_bvp(name, 5)
    rows = compare_with_bvp(a, b, 5)
    if name == "ttr-steel":
        assert a.info["drag_as_dead_load"]          # its current: the drag a dead load
    # tighter than the target, as measured (the module docstring): out of plane
    assert max(abs(r[2]) for r in rows if r[0] == "out_of_plane") < 1e-6


@pytest.mark.slow
@pytest.mark.parametrize("name", SCENES)
def test_ten_modes_per_plane_agree_with_the_bvp(name):
    a, b = ancf_and_bvp(name, 10)
    compare_with_bvp(a, b, 10)


@pytest.mark.slow          # 30 s (two BVP modal analyses)
def test_a_flex_joint_is_isotropic_out_of_plane():
    # lazy-wave-flex-joint (k = 1.5e6 N m/rad at the hang-off): the out-of-plane modes
    # agree with the BVP's to < 1e-6 (measured <= 8e-8), in plane within the target
    # (measured -3e-6 to -2.1e-4)
    scene = resolve("lazy-wave-flex-joint")
    a = am.solve_modes(scene, 3)
    b = method("bvp").modes(scene, 3)
    assert a.converged and b.converged, (a.message, b.message)
    rows = compare_with_bvp(a, b, 3)
    out = [r for r in rows if r[0] == "out_of_plane"]
    assert max(abs(r[2]) for r in out) < 1e-6
    # negative control: the joint's out-of-plane stiffness left out, 0.06 to 0.36 % low
    # (measured -5.9e-4 at mode 1)

    class PlanarJoint(am.Model):
        def __init__(self, *args, **kw):
            super().__init__(*args, **kw)
            self.ends.springs = []       # the 3D model's joint: its in-plane term too,
            # which the out-of-plane family does not see (decoupled at a planar state)

    mp = pytest.MonkeyPatch()
    try:
        mp.setattr(am, "Model", PlanarJoint)
        c = am.solve_modes(scene, 3)
    finally:
        mp.undo()
    miss = frequencies(c, "out_of_plane") / frequencies(b, "out_of_plane") - 1.0
    assert np.all(miss < -5e-4)                      # >= 500 x the agreement's 1e-6


# ------------------------------------------------------------------ the method
def test_the_modes_are_reproducible_and_take_a_static_result():
    sc = hanging_chain()
    a = am.solve_modes(sc, 4)
    b = am.solve_modes(sc, 4, static=ancf.solve(sc))
    assert [m.frequency_hz for m in a.modes] == [m.frequency_hz for m in b.modes]
    assert all(np.array_equal(x.shape, y.shape) for x, y in zip(a.modes, b.modes))
    with pytest.raises(ValueError, match="static must be an ancf result"):
        am.solve_modes(sc, 4, static=method("bvp").solve(sc))
    with pytest.raises(ValueError, match="count must be >= 1"):
        am.solve_modes(sc, 0)


def test_what_the_modes_refuse():
    # a static state out of plane where the two planar families are asked for (coupled=
    # False; by default it is the coupled family, tests/test_ancf_modes_3d.py), flowing
    # contents, and a scene the ANCF refuses (a Wang form: the command converts it first)
    out = am.solve_modes(resolve("scr-steel-current-90"), 3, coupled=False)
    assert out.status is Status.REFUSED and "planar" in out.message, out.message
    out = am.solve_modes(resolve("liu2021-scr"), 3)          # 2.5 m/s
    assert out.status is Status.REFUSED and "internal_flow.speed" in out.message
    out = am.solve_modes(resolve("wang2014-baseline"), 3)
    assert out.status is Status.REFUSED and "fixed ends" in out.message
    assert method("ancf").modes is not None


# ------------------------------------------------------------------ the modes command
def small_scene():
    """120 m of line, 40 m of it on an elastic seabed (tests/test_modes_report.py's)."""
    return builders.scene({
        "name": "small",
        "line_types": {"p": {"outer_diameter": 0.2, "inner_diameter": 0.15,
                             "mass_per_length": 60.0, "axial_stiffness": 5e8,
                             "bending_stiffness": 2e5, "added_mass": 1.0}},
        "seabed": {"stiffness": 1e5},
        "segments": [{"line_type": "p", "length": 120.0, "submerged_weight": 300.0}],
        "ends": {"anchor": [0.0, 0.0], "hang_off": [90.0, 50.0]},
        "vfife": {"element_length": 4.0}})


def read_csv(path):
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    return rows[0], rows[1:]


def test_the_modes_command_shows_the_ancf_as_a_further_column(tmp_path):
    assert vm.COLUMNS == ("ancf",)
    run = vm.run_modes(small_scene(), 3, out=tmp_path, columns=vm.COLUMNS)
    assert set(run.results) == {"bvp", "vfife", "ancf"} and set(run.columns) == {"ancf"}
    assert all(r.converged for r in run.results.values())
    assert len(run.rows) == 6 and all(set(r.values) == {"bvp", "vfife"} for r in run.rows)
    assert len(run.columns["ancf"]) == 6 and all(r.passed for r in run.columns["ancf"])
    assert all(set(r.values) == {"bvp", "ancf"} for r in run.columns["ancf"])
    # the VFIFE at 4 m elements misses in plane (+0.8 to +1.5 %: its lumped seabed
    # springs), the ANCF at 2 m does not (-0.02 to +0.002 %)
    assert not run.all_meet and not all(r.passed for r in run.rows)
    header, rows = read_csv(tmp_path / "modes.csv")
    assert header == list(vm.MODES_COLUMNS)
    assert sum(r[0] == "ancf" for r in rows) == 6 and len(rows) == 18
    header, rows = read_csv(tmp_path / "agreement.csv")
    assert header == list(vm.AGREEMENT_COLUMNS) + ["ancf_frequency_hz", "ancf_rel_diff",
                                                   "ancf_mac"]
    assert len(rows) == 6
    for r, row in zip(rows, run.columns["ancf"]):
        assert (r[0], int(r[1])) == (row["plane"], row["mode"])
        assert float(r[6]) == pytest.approx(row.value("ancf"), rel=1e-9)
        assert float(r[2]) == pytest.approx(row.value("bvp"), rel=1e-9)
    text = (tmp_path / "report.md").read_text()
    assert "ANCF f [Hz]" in text and "ANCF MAC" in text and "6 of 6 ANCF-BVP" in text
    lines = vm.summary_lines(run)
    assert any(x.startswith("  ancf: 6/6 pairs with the bvp") for x in lines), lines
    # the verdict: the two methods' rows and the column's
    run.rows = [r.judged(True) for r in run.rows]
    assert run.all_meet
    run.columns["ancf"] = [run.columns["ancf"][0].judged(False), *run.columns["ancf"][1:]]
    assert not run.all_meet


def test_a_column_that_refuses_the_scene_is_shown_not_judged():
    # [vfife] clamped_ends: the BVP and the VFIFE clamp the ends' modes, the ANCF refuses
    # it (give the end a clamped joint)
    sc = small_scene()
    sc = sc.replace(vfife=sc.vfife.replace(clamped_ends=("top",)))
    run = vm.run_modes(sc, 2, columns=("ancf",))
    assert run.results["ancf"].status is Status.REFUSED
    assert run.columns == {} and run.all_meet == (all(r.passed for r in run.rows)
                                                  and run.results["bvp"].converged
                                                  and run.results["vfife"].converged)
    assert any("ancf: refused the scene" in x for x in vm.summary_lines(run))
    assert "the ANCF refused the scene" in vm.markdown(run)

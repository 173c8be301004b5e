"""Bending limits as a design check (issue 48, item 3; riser/design/bending.py): the bend
utilisation along s, kappa MBR for a flexible or cable, (OD/2) kappa over the allowable
bending strain (SMYS / E, or [design] bending_strain_limit) for a steel wall; by hand,
through every method's registry solve (profile.csv and summary.json), over a dynamic
run's envelope (envelope.csv and the dynamic_ keys), and in utilisation.png."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from riser.design import bending
from riser.errors import SceneError
from riser.io.scene_file import parse_scene
from riser.results.profile import Profile
from riser.results.result import DynamicsResult, SolveResult, Status
from verification.methods import method

from builders import steel_line_toml

#: a steel line of 110 m with [design] (tests/builders.py) and its top
#: heaving 0.5 m in 6 s for 12 s
LINE = steel_line_toml("design-dynamics")
DYNAMICS = """
[dynamics]
duration = 12.0
output_interval = 0.5
[dynamics.top_motion]
axis = "y"
amplitude = 0.5
period = 6.0
"""
#: a cable of 250 m from an anchor on the seabed to a hang-off 90 m above it, touching
#: down; ``{keys}`` the line type's limits
CABLE = """
name = "cable"
[environment]
water_depth = 100.0
[seabed]
stiffness = 1e5
[line_types.c]
outer_diameter = 0.2
mass_per_length = 60.0
axial_stiffness = 1e8
bending_stiffness = 1e4
{keys}
[[segments]]
line_type = "c"
length = 250.0
[ends]
anchor = [0.0, 0.0]
hang_off = [180.0, 90.0]
"""
#: a steel pipe by its wall and material: OD 0.3 m, SMYS 450 MPa, E 207 GPa
STEEL = """
name = "steel"
[environment]
water_depth = 100.0
[line_types.p]
outer_diameter = 0.3
wall_thickness = 0.02
density = 7850.0
youngs_modulus = 2.07e11
yield_strength = 4.5e8
tensile_strength = 5.35e8
{keys}
[[segments]]
line_type = "p"
length = 150.0
[ends]
anchor = [0.0, 0.0]
hang_off = [100.0, 90.0]
{design}
"""
#: the steel pipe's factor by hand: eps_y = SMYS / E = 450e6 / 207e9 = 2.1739e-3, and
#: u = (OD/2) kappa / eps_y = 0.15 kappa 207e9 / 450e6 = 69.0 m x kappa
STEEL_FACTOR = 0.15 * 207e9 / 450e6


# ------------------------------------------------------------------------ by hand
def test_mbr_by_hand():
    # MBR 5 m: kappa 0.1 1/m (R = 10 m) -> 0.5; kappa 0.2 (R = MBR) -> 1; the sign of the
    # curvature does not matter
    sc = parse_scene(CABLE.format(keys="minimum_bend_radius = 5.0"), "c.toml")
    u = bending.bend_utilisation(sc, np.array([0.0, 100.0, 250.0]),
                                 np.array([0.1, -0.2, 0.0]))
    np.testing.assert_allclose(u, [0.5, 1.0, 0.0], rtol=1e-15)


def test_steel_strain_by_hand():
    # OD 0.3 m, SMYS 450 MPa, E 207 GPa: kappa 0.01 1/m is a bending strain of 0.15 %,
    # 0.0015 / 0.0021739 = 0.69 of the elastic limit; R = 69 m is the limit itself
    sc = parse_scene(STEEL.format(keys="", design=""), "s.toml")
    assert STEEL_FACTOR == pytest.approx(69.0, rel=1e-14)
    u = bending.bend_utilisation(sc, np.array([10.0, 50.0]), np.array([0.01, 1.0 / 69.0]))
    np.testing.assert_allclose(u, [0.69, 1.0], rtol=1e-12)


def test_design_bending_strain_limit_replaces_smys_over_e():
    # an allowable bending strain of 0.3 %: the same 0.15 % is 0.5
    sc = parse_scene(STEEL.format(keys="", design="[design]\nbending_strain_limit = 0.003"),
                     "s.toml")
    assert sc.design.bending_strain_limit == 0.003
    u = bending.bend_utilisation(sc, np.array([10.0]), np.array([0.01]))
    assert u[0] == pytest.approx(0.5, rel=1e-14)
    # without the key the elastic limit SMYS / E
    plain = parse_scene(STEEL.format(keys="", design="[design]"), "s.toml")
    assert bending.bend_utilisation(plain, np.array([10.0]), np.array([0.01]))[0] == \
        pytest.approx(0.69, rel=1e-12)


@pytest.mark.parametrize("value", [0.0, -0.001, 0.06])
def test_bending_strain_limit_out_of_range_refused(value):
    with pytest.raises(SceneError, match="bending_strain_limit"):
        parse_scene(STEEL.format(keys="", design=f"[design]\nbending_strain_limit = {value}"),
                    "s.toml")


def test_both_limits_the_larger_governs():
    # a steel line type with an MBR too: 100 m against its 69 m of elastic limit -> 100 m
    sc = parse_scene(STEEL.format(keys="minimum_bend_radius = 100.0", design=""), "s.toml")
    assert bending.bend_utilisation(sc, np.array([10.0]), np.array([0.01]))[0] == \
        pytest.approx(1.0, rel=1e-14)
    sc = parse_scene(STEEL.format(keys="minimum_bend_radius = 20.0", design=""), "s.toml")
    assert bending.bend_utilisation(sc, np.array([10.0]), np.array([0.01]))[0] == \
        pytest.approx(0.69, rel=1e-12)


def test_no_limit_is_zero_and_the_segment_lookup():
    # a cable without a limit (0: "no limit") below a steel pipe (69 m); a station on the
    # boundary takes the lower segment, as the warnings and the wall do
    text = STEEL.format(keys="", design="").replace(
        "[[segments]]", "[line_types.c]\nouter_diameter = 0.2\nmass_per_length = 60.0\n"
        "axial_stiffness = 1e8\nbending_stiffness = 1e4\n[[segments]]\nline_type = \"c\"\n"
        "length = 50.0\n[[segments]]", 1).replace("length = 150.0", "length = 100.0")
    sc = parse_scene(text, "two.toml")
    s = np.array([0.0, 50.0, 50.1, 150.0])
    np.testing.assert_allclose(bending.factors(sc, s), [0.0, 0.0, STEEL_FACTOR,
                                                        STEEL_FACTOR], rtol=1e-12)
    # the lengths as solved (a touchdown form's suspended first segment) move the boundary
    np.testing.assert_allclose(bending.factors(sc, s, [40.0, 100.0]),
                               [0.0, STEEL_FACTOR, STEEL_FACTOR, STEEL_FACTOR], rtol=1e-12)
    assert bending.solved_lengths(sc, {"first_segment_suspended_length": 40.0}) == [40.0,
                                                                                   100.0]
    assert bending.solved_lengths(sc, {}) is None


def test_applies_only_where_the_scene_states_a_limit():
    assert not bending.applies(parse_scene(CABLE.format(keys=""), "c.toml"))
    assert bending.applies(parse_scene(CABLE.format(keys="minimum_bend_radius = 5.0"),
                                       "c.toml"))
    assert bending.applies(parse_scene(STEEL.format(keys="", design=""), "s.toml"))
    # a steel wall recognised by its modulus and density alone (X65 assumed): the
    # bending_strain warning, no column
    recognised = STEEL.format(keys="", design="").replace("yield_strength = 4.5e8\n", "") \
        .replace("tensile_strength = 5.35e8\n", "")
    assert not bending.applies(parse_scene(recognised, "s.toml"))


def _result(profile, envelope=None, info=None):
    dyn = None if envelope is None else DynamicsResult({}, envelope, None)
    return SolveResult("hand", "cable", Status.CONVERGED, "by hand", profile=profile,
                       info=dict(info or {}), dynamics=dyn)


def test_with_bending_by_hand():
    # static: the column and its largest; dynamic: the envelope's curvature_max times the
    # factor, where and when the curvature was largest
    sc = parse_scene(CABLE.format(keys="minimum_bend_radius = 5.0"), "c.toml")
    s = np.array([0.0, 100.0, 250.0])
    z = np.zeros(3)
    p = Profile(s=s, x=s, y=z, z=z, theta=z, tension=z + 1.0, moment=z, shear=z,
                curvature=np.array([0.02, -0.1, 0.0]))
    env = {"s": s, "curvature_max": np.array([0.05, 0.3, 0.01]),
           "curvature_max_time": np.array([1.0, 2.5, 3.0])}
    res = bending.with_bending(sc, _result(p, env, {"first": 1}))
    np.testing.assert_allclose(res.profile.bend_utilisation, [0.1, 0.5, 0.0], rtol=1e-15)
    np.testing.assert_allclose(res.dynamics.envelope["bend_utilisation_max"],
                               [0.25, 1.5, 0.05], rtol=1e-15)
    sm = res.summary()
    assert sm["max_bend_utilisation"] == pytest.approx(0.5) and sm["max_bend_utilisation_s"] == 100.0
    assert sm["dynamic_max_bend_utilisation"] == pytest.approx(1.5)
    assert sm["dynamic_max_bend_utilisation_s"] == 100.0
    assert sm["dynamic_max_bend_utilisation_time"] == 2.5
    assert sm["first"] == 1                                 # the method's info kept
    # a window without samples (curvature_max -inf): no value, no keys
    empty = {"s": s, "curvature_max": np.full(3, -np.inf),
             "curvature_max_time": np.full(3, np.nan)}
    res = bending.with_bending(sc, _result(p, empty))
    assert np.all(np.isnan(res.dynamics.envelope["bend_utilisation_max"]))
    assert "dynamic_max_bend_utilisation" not in res.summary()
    # no limit stated: the result itself
    plain = parse_scene(CABLE.format(keys=""), "c.toml")
    r0 = _result(p, env)
    assert bending.with_bending(plain, r0) is r0


# --------------------------------------------------------- through the methods
@pytest.mark.parametrize("name", ["bvp", "analytic",
                                  pytest.param("ancf", marks=pytest.mark.slow)])
def test_every_method_gets_the_column(name, tmp_path):
    # the registry's solve adds the column to each method's own curvature, without
    # [design]; the three methods' largest agree (the touchdown's bend, 0.42 of MBR 5 m)
    sc = parse_scene(CABLE.format(keys="minimum_bend_radius = 5.0"), "c.toml")
    res = method(name).solve(sc).require()
    p = res.profile
    np.testing.assert_allclose(p.bend_utilisation, 5.0 * np.abs(p.curvature), rtol=1e-15)
    sm = res.summary()
    i = int(np.argmax(p.bend_utilisation))
    assert sm["max_bend_utilisation"] == p.bend_utilisation[i]
    assert sm["max_bend_utilisation_s"] == p.s[i]
    assert sm["max_bend_utilisation"] == pytest.approx(0.42, rel=0.02)
    assert "max_utilisation" not in sm                     # no [design]: no code check
    res.write(tmp_path)
    with open(tmp_path / "profile.csv") as fh:
        header = next(csv.reader(fh))
    assert header[-1] == "bend_utilisation" and "utilisation" not in header


def test_no_limit_no_column():
    res = method("analytic").solve(parse_scene(CABLE.format(keys=""), "c.toml")).require()
    assert res.profile.bend_utilisation is None
    assert not any("bend" in k for k in res.summary())


def test_design_scene_gets_both_checks():
    # [design] on the steel line (SMYS 448 MPa, E 206 GPa, OD 0.2032 m): the column beside
    # the code's utilisation, after it
    sc = parse_scene(LINE)
    res = method("bvp").solve(sc).require()
    p = res.profile
    c = 0.5 * 0.2032 * 2.06e11 / 4.48e8
    np.testing.assert_allclose(p.bend_utilisation, c * np.abs(p.curvature), rtol=1e-9)
    assert p.utilisation is not None


def test_dynamic_envelope_column():
    # a VFIFE run of 12 s (the top heaving 0.5 m in 6 s) on the steel line without
    # [design]: its yield_strength states the limit; the envelope's column is the factor
    # times curvature_max, the summary's largest where and when the curvature was
    sc = parse_scene(LINE.replace("[design]\n", "") + DYNAMICS)
    res = method("vfife").solve(sc, element_length=2.0).require()
    env, sm = res.dynamics.envelope, res.summary()
    c = 0.5 * 0.2032 * 2.06e11 / 4.48e8
    np.testing.assert_allclose(env["bend_utilisation_max"], c * env["curvature_max"],
                               rtol=1e-9)
    j = int(np.argmax(env["bend_utilisation_max"]))
    assert sm["dynamic_max_bend_utilisation"] == env["bend_utilisation_max"][j]
    assert sm["dynamic_max_bend_utilisation_s"] == env["s"][j]
    assert sm["dynamic_max_bend_utilisation_time"] == env["curvature_max_time"][j]
    # the heave bends the line beyond its static state
    assert sm["dynamic_max_bend_utilisation"] > sm["max_bend_utilisation"]
    assert "utilisation_max" not in env                     # no [design]: no code check


@pytest.mark.slow
def test_dynamic_envelope_both_time_domains_agree(tmp_path):
    # the VFIFE and the ANCF on the same run (with [design]): their largest bend
    # utilisation within 1 % (measured 1.3579 and 1.3557), envelope.csv carries the column
    sc = parse_scene(LINE + DYNAMICS)
    got = {}
    for name in ("vfife", "ancf"):
        res = method(name).solve(sc, element_length=2.0).require()
        got[name] = res.summary()["dynamic_max_bend_utilisation"]
        res.write(tmp_path / name)
        with open(tmp_path / name / "envelope.csv") as fh:
            header = next(csv.reader(fh))
        assert "bend_utilisation_max" in header and "utilisation_max" in header
    assert got["ancf"] == pytest.approx(got["vfife"], rel=0.01)


@pytest.mark.slow
def test_utilisation_plot(tmp_path):
    # with the code check: two panels, the bend curves on the utilisation's; without it:
    # the bend utilisation alone (slow: matplotlib's import, 1.7 s)
    from verification.report.design import write_plot
    s = np.linspace(0.0, 100.0, 11)
    z = np.zeros_like(s)
    p = Profile(s=s, x=s, y=z, z=z, theta=z, tension=z, moment=z, shear=z, curvature=z,
                bend_utilisation=s / 100.0)
    env = {"s": s, "bend_utilisation_max": s / 50.0}
    write_plot(p, env, tmp_path, "bend only")
    assert (tmp_path / "utilisation.png").stat().st_size > 0
    both = p.replace(utilisation=s / 200.0, von_mises=s * 1e6, design_code="dnv-st-f201")
    (tmp_path / "b").mkdir()
    write_plot(both, {**env, "utilisation_max": s / 100.0, "von_mises_max": s * 2e6},
               tmp_path / "b", "both")
    assert (tmp_path / "b" / "utilisation.png").stat().st_size > 0

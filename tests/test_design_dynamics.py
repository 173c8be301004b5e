"""Design checks of dynamic runs and fatigue along the line (riser/design/dynamic.py,
fatigue.py): the functional/environmental split by hand, the circumferential stress
record's rainflow damage against n / N, the spectral damage along s against the
narrow-band closed form, the turning-point reduction against the full count, and a VFIFE
run with [design] (its envelope, its summary, and nothing of it without [design])."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest

import vfife
from riser.design import dnv_f201
from riser.design.dynamic import DynamicDesign
from riser.design.fatigue import SECONDS_PER_YEAR, spectral, stress_transfer, time_domain
from riser.design.rainflow_damage import cycles_of, reversals
from riser.design.sn_curves import sn_curve
from riser.design.spectral_fatigue import closed_form_narrow_band
from riser.design.wall import wall_at
from riser.io.scene_file import parse_scene

from builders import steel_line_toml

LINE = steel_line_toml("design-dynamics")
FATIGUE = """
[design.fatigue]
sn_curve = "F"
environment = "free-corrosion"
scf = 1.3
points = 8
"""
DYNAMICS = """
[dynamics]
duration = 12.0
output_interval = 0.5
[dynamics.top_motion]
axis = "y"
amplitude = 0.5
period = 6.0
"""


def straight(n):
    """Positions, tangents of a planar line along x (its in-plane moment is M_z)."""
    x = np.zeros((n, 3))
    x[:, 0] = np.arange(n, dtype=float)
    x[:, 1] = 10.0
    t = np.zeros((n, 3))
    t[:, 0] = 1.0
    return x, t


def moments(mz):
    m = np.zeros((len(mz), 3))
    m[:, 2] = mz
    return m


def test_functional_and_environmental_split_by_hand():
    sc = parse_scene(LINE)
    s = np.array([10.0, 20.0, 30.0])
    dd = DynamicDesign(sc, s)
    x, t = straight(3)
    T_f, M_f = np.array([4e5, 5e5, 6e5]), np.array([10e3, -20e3, 5e3])
    dd.sample(0.0, x, t, T_f, moments(M_f), window=False)          # the static state
    T, M = np.array([4.5e5, 4.0e5, 6.2e5]), np.array([25e3, -5e3, -8e3])
    dd.sample(1.0, x, t, T, moments(M), window=True)
    # by hand: M_d = |1.1 M_F + 1.3 (M - M_F)|, T_ed = 1.1 T_F + 1.3 (T - T_F); the
    # pressures at y = 10 m with the hang-off (the last station) at the same height
    m_d = np.abs(1.1 * M_f + 1.3 * (M - M_f))
    t_ed = 1.1 * T_f + 1.3 * (T - T_f)
    p_e = 1025.0 * 9.81 * 50.0
    hand = dnv_f201.utilisation(sc.design, wall_at(sc, s), 0.0, p_e, m_d, t_ed)
    np.testing.assert_allclose(dd.u_max, hand, rtol=1e-12)
    stats = dd.statistics()
    assert stats["dynamic_max_utilisation"] == pytest.approx(float(np.max(hand)), rel=1e-12)
    assert stats["dynamic_max_utilisation_time"] == 1.0


def test_reversals_keep_the_rainflow_cycles():
    rng = np.random.default_rng(3)
    x = np.round(np.cumsum(rng.normal(size=5000)), 1)      # rounded: plateaus and repeats
    import rainflow
    full = np.array([(r, c) for r, _m, c, _a, _b in rainflow.extract_cycles(x)])
    r_full, c_full = full.T
    r_red, c_red = cycles_of(x)
    np.testing.assert_array_equal(r_full, r_red)
    np.testing.assert_array_equal(c_full, c_red)
    assert reversals(x).size < 0.8 * x.size


def test_constant_amplitude_bending_gives_n_over_N():
    # M = M0 cos(2 pi t / T) over n whole periods from a crest to a crest: n full cycles
    # of the range 2 M0 r_o / I at the points phi = 0 and pi (the helper's exact case)
    sc = parse_scene(LINE + FATIGUE)
    s = np.array([50.0])
    n_cycles, per = 7, 64
    tt = np.linspace(0.0, n_cycles * 6.0, n_cycles * per + 1)
    m0 = 30e3
    m_in = (m0 * np.cos(2 * math.pi * tt / 6.0))[:, None]
    tw = np.full_like(m_in, 5e5)
    out = time_domain(sc, s, tw, m_in, np.zeros_like(m_in), float(tt[-1]))
    w = wall_at(sc, s)
    rng = 2 * m0 * 0.1016 / w.inertia[0]
    curve = sn_curve("F", "free-corrosion")
    expected = n_cycles / curve.cycles(rng, 0.0191, 1.3)
    assert out["fatigue_damage"][0] == pytest.approx(float(expected), rel=1e-12)
    assert out["fatigue_angle_deg"][0] in (0.0, 180.0)
    assert out["fatigue_life"][0] == pytest.approx(tt[-1] / expected / SECONDS_PER_YEAR,
                                                   rel=1e-12)


def test_spectral_damage_of_a_single_component_is_the_narrow_band_closed_form():
    # one wave component drives a moment amplitude: the stress at phi = 0 is a pure
    # sinusoid of variance a^2 / 2, its spectrum one line; the narrow-band damage rate of
    # a single-slope curve is nu0 (2 sqrt(2 m0))^m Gamma(1 + m/2) / a (Rayleigh ranges of
    # a Gaussian process with that spectrum)
    sc = parse_scene(LINE + FATIGUE)
    s = np.array([50.0])
    omega = np.array([0.5, 0.6, 0.7])
    amp_m = np.zeros((3, 1), complex)
    amp_m[1, 0] = 20e3
    zero = np.zeros_like(amp_m)
    q = stress_transfer(sc, s, zero, amp_m, zero, zero)
    out = spectral(sc, s, omega, 0.1, q)
    w = wall_at(sc, s)
    sigma_amp = 20e3 * 0.1016 / w.inertia[0] * 1.3          # the SCF on the range
    curve = sn_curve("F", "free-corrosion")
    hand = closed_form_narrow_band(sigma_amp ** 2 / 2, 0.6 / (2 * math.pi), curve.m1,
                                   curve.log_a1)
    assert out["fatigue_rate_narrow_band"][0] == pytest.approx(hand, rel=1e-4)
    # a line spectrum has gamma = 1: Dirlik tends to the narrow band
    assert out["fatigue_rate_dirlik"][0] == pytest.approx(hand, rel=1e-2)


def test_the_wall_tension_moves_with_the_heave():
    # dT_w = g (rho_w A_o - rho_c A_i) dy: a metre of heave at no tension change
    sc = parse_scene(LINE + FATIGUE)
    s = np.array([50.0])
    one = np.ones((1, 1), complex)
    zero = np.zeros_like(one)
    q = stress_transfer(sc, s, zero, zero, zero, one)
    w = wall_at(sc, s)
    expected = 9.81 * 1025.0 * w.outer_area[0] / w.area[0]
    np.testing.assert_allclose(q[0, 0, :].real, expected, rtol=1e-12)


def test_vfife_dynamic_run_with_design():
    # the registry hands the design checks to the VFIFE's recorder as an observer
    from verification.methods import method
    sc = parse_scene(LINE + FATIGUE + DYNAMICS)
    res = method("vfife").solve(sc, element_length=2.0).require()
    env, sm = res.dynamics.envelope, res.summary()
    assert sm["dynamic_max_utilisation"] == pytest.approx(float(np.max(env["utilisation_max"])))
    # the top motion adds to the static utilisation somewhere along the line
    assert sm["dynamic_max_utilisation"] > sm["max_utilisation"]
    assert np.all(np.isfinite(env["fatigue_damage"])) and sm["dynamic_max_fatigue_damage"] > 0
    assert sm["dynamic_fatigue_record_s"] == pytest.approx(sm["statistics_end"]
                                                           - sm["statistics_start"], abs=0.5)
    # effects on demand: without [design] no design columns, no design keys
    plain = vfife.solve(parse_scene(LINE.replace("[design]\n", "") + DYNAMICS),
                        element_length=2.0).require()
    assert "utilisation_max" not in plain.dynamics.envelope
    assert not any("utilisation" in k for k in plain.summary())
    assert plain.profile.utilisation is None


def test_cli_fatigue_without_sea_states_is_one_line_exit_2(tmp_path):
    p = tmp_path / "no-sea.toml"
    p.write_text(LINE + FATIGUE)
    r = subprocess.run([sys.executable, "-m", "verification.cli", "fatigue", str(p)],
                       capture_output=True, text=True)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "design.fatigue.sea_states" in lines[0]


def sea_state(spectrum_keys: str = "") -> str:
    """A JONSWAP sea (Hs 2 m, Tp 9 s, further spectrum keys as given) and its one cell of
    the scatter diagram (TOML)."""
    return ("\n[environment.waves]\n[environment.waves.spectrum]\nkind = \"jonswap\"\n"
            f"hs = 2.0\ntp = 9.0\n{spectrum_keys}[[design.fatigue.sea_states]]\nhs = 2.0\n"
            "tp = 9.0\nprobability = 1.0\n")


def test_fatigue_by_two_methods_takes_an_oblique_sea_but_not_a_3d_static_state():
    # a sea from any heading about a planar static state is taken (the FD's sea response
    # carries the out-of-plane moment, tests/test_fatigue_headings.py); a current across
    # the plane (a 3D static state: the sea response is about a planar one) is refused
    # before solving, naming the current
    from riser.errors import SceneError
    from verification.studies.design.fatigue import require_fatigue
    sea = sea_state("heading_deg = 30.0\n")
    require_fatigue(parse_scene(LINE + FATIGUE + sea))
    current = ("\n[environment.current]\nheights = [0.0, 60.0]\nspeeds = [0.5, 0.5]\n"
               "heading_deg = 90.0\n")
    with pytest.raises(SceneError) as exc:
        require_fatigue(parse_scene(LINE + FATIGUE + sea + current))
    assert exc.value.key.startswith("environment.current"), exc.value


def test_harmonic_cycle_utilisation_by_hand():
    # without a dynamic part the cycle's utilisation is the static one (gamma_F on all);
    # a tension harmonic Q_T alone peaks where the factored tension gamma_F T_0 +
    # gamma_E |Q_T| is largest (DNV's criterion grows with |T_ed|): by hand with the
    # criterion at that tension (72 phases: the grid holds phi = 0 exactly)
    from riser.design.checks import harmonic_columns, static_columns
    sc = parse_scene(LINE)
    s = np.array([20.0, 40.0, 60.0])
    y = np.array([5.0, 20.0, 50.0])
    T0, M0 = np.array([3e5, 4e5, 5e5]), np.array([2e4, -1e4, 5e3])
    zero = {k: np.zeros(3, complex) for k in ("tension", "moment", "moment_out", "dy")}
    still = harmonic_columns(sc, s, y, T0, M0, zero)
    stat = static_columns(sc, s, y, T0, M0)
    np.testing.assert_allclose(still["utilisation"], stat["utilisation"], rtol=1e-12)
    amp = dict(zero, tension=np.array([5e4, 5e4j, -5e4], complex))
    cyc = harmonic_columns(sc, s, y, T0, M0, amp)
    p_e = 1025.0 * 9.81 * (60.0 - y)
    hand = dnv_f201.utilisation(sc.design, wall_at(sc, s), 0.0, p_e, 1.1 * np.abs(M0),
                                1.1 * T0 + 1.3 * 5e4)
    np.testing.assert_allclose(cyc["utilisation"], hand, rtol=1e-12)


def test_fatigue_by_two_methods_refuses_a_line_without_a_seabed():
    # the report's stations are the touchdown zone and the hang-off: a scene without a
    # [seabed] (a mid-water span, a TTR on a wellhead) has no touchdown; it was a KeyError
    # in the report after the whole scatter diagram. Now refused before solving, naming
    # the key
    from riser.errors import SceneError
    from verification.studies.design.fatigue import require_fatigue
    text = LINE + FATIGUE + sea_state()
    start = text.index("[seabed]")
    end = text.index("\n[", start + 1)
    sc = parse_scene(text[:start] + text[end + 1:])
    assert sc.seabed is None
    with pytest.raises(SceneError) as exc:
        require_fatigue(sc)
    assert exc.value.key == "seabed"


def test_a_run_continued_from_a_checkpoint_keeps_its_design_checks():
    # the dynamic comparison continues an unsettled VFIFE run from a checkpoint, outside
    # the registry's solve: the same observer (verification.methods.design_observers)
    # gives the continued run its utilisation; without it the figure is missing (the
    # negative control), as it was after the design checks left the method
    from verification.methods import design_observers, method
    from vfife.dynamics.run import run_dynamics
    sc = parse_scene(LINE + DYNAMICS)
    first = method("vfife").solve(sc, element_length=2.0, checkpoint_at=6.0).require()
    ck, model = first.dynamics.checkpoint, first.solver_state
    _, with_obs = run_dynamics(sc, model, model.planar, resume=ck,
                               observers=design_observers(sc))
    _, without = run_dynamics(sc, model, model.planar, resume=ck)
    u = with_obs["statistics"]["dynamic_max_utilisation"]
    # the continued window's largest utilisation: at least the static one (the motion's
    # increment over the static state is positive somewhere over a cycle)
    assert math.isfinite(u) and u >= first.summary()["max_utilisation"]
    assert "dynamic_max_utilisation" not in without["statistics"]

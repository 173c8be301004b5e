"""The line types' internal axial damping ``axial_damping`` (BA [N s], MoorDyn's BA: the axial
force N = EA eps + BA d(eps)/dt, Kelvin-Voigt) in the two time domains, the frequency domain
and the MoorDyn deck, against independent sources:

- the closed form of the axial rod: a taut straight line between fixed ends rings at its
  first axial mode omega_1 = (pi / L) sqrt(EA / m) and, damped, decays at the ratio
  zeta_1 = BA omega_1 / (2 EA) (m u_tt = EA u_ss + BA u_sst, separated in sin(pi s / L));
  undamped, it does not decay;
- the ANCF's damping forces differentiated by central differences (its consistent
  Jacobian in the implicit step);
- the statics do not see it (a damping force vanishes at rest);
- the VFIFE's explicit step shrinks by the damped factor sqrt(1 + zeta^2) - zeta of the
  central difference's stability limit, so a large BA runs stably;
- the frequency domain's complex axial stiffness against the Kelvin-Voigt rod's exact
  harmonic response;
- MoorDyn-C: its damping ratio converted to BA as its Line.cpp does, the deck's BA kept
  both ways, and (slow) the Lowe and Langley jumper's axial ringing decaying in the VFIFE
  and the ANCF as in MoorDyn-C with the same BA.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import least_squares

import ancf
import vfife
from ancf import banded
from ancf.element import damping_pass

from builders import pipe, scene, straight
from extras import needs_moordyn

# ------------------------------------------------------------------ the axial rod
#: the rod: 100 m of 100 kg/m with EA 1e7 N, stretched by 0.1 m between fixed ends at one
#: height, weightless, without drag or added mass: axial waves at c = sqrt(EA / m) = 316 m/s
L, EA, M = 100.0, 1.0e7, 100.0
OMEGA_1 = math.pi / L * math.sqrt(EA / M)        # 9.935 rad/s
PERIOD_1 = 2.0 * math.pi / OMEGA_1               # 0.632 s
#: the hang-off's step along the line [m] (strain 1e-4 on the pretension's 1e-3)
STEP = 0.01
#: BA giving the first mode 2 % of critical damping
BA_2PC = 2.0 * 0.02 * EA / OMEGA_1


def rod(BA: float, periods: int = 8, **ancf_settings):
    """The rod set ringing: the hang-off moved by STEP along the line with a half-cosine
    ramp of half the first mode's period, then held. The odd modes n >= 3 are then left
    at rest (the ramp's acceleration, cos(pi t / tau) on [0, tau], has no component at
    omega_n tau = n pi for odd n > 1), the even ones do not move the midpoint: the
    midpoint's axial motion is the first mode alone. States every T_1 / 40."""
    line_type = pipe(mass_per_length=M, axial_stiffness=EA, drag_normal=0.0, added_mass=0.0,
                     axial_damping=BA)
    duration = periods * PERIOD_1
    dynamics = {"duration": duration, "output_interval": PERIOD_1 / 40.0, "save_states": True,
                "top_motion": {"times": [0.0, duration], "displacements_x": [STEP, STEP],
                               "ramp_time": 0.5 * PERIOD_1}}
    # VFIFE 2 m elements (50): its lumped masses put omega_1 -1.6e-4 off; ANCF 10 m
    # elements (cubic) and Newmark's average acceleration (no numerical damping) at T_1 / 60
    ancf_table = {"element_length": 10.0, "integrator": "newmark",
                  "time_step": PERIOD_1 / 60.0, **ancf_settings}
    return scene(straight(L, L + 0.1, line_type=line_type, dynamics=dynamics,
                          vfife={"element_length": 2.0}, ancf=ancf_table))


def midpoint_mode(result) -> tuple[float, float, float]:
    """(zeta, omega [rad/s], rms misfit / amplitude) of the midpoint's axial displacement
    after the first period fitted by A exp(-zeta omega t) cos(omega_d t + phi) + c (least
    squares; omega_d = omega sqrt(1 - zeta^2)): the logarithmic decrement per period is
    2 pi zeta / sqrt(1 - zeta^2)."""
    st = result.dynamics.states
    t, s, x = st["t"], st["s"], st["x"]
    i = int(np.argmin(np.abs(s - 0.5 * L)))
    sel = t > PERIOD_1
    tt, u = t[sel], x[sel, i, 0] - x[0, i, 0]

    def misfit(p):
        A, zeta, omega, phase, c = p
        wd = omega * math.sqrt(max(1.0 - zeta * zeta, 0.0))
        return A * np.exp(-zeta * omega * tt) * np.cos(wd * tt + phase) + c - u

    amp = float(np.max(np.abs(u - u.mean())))
    best = min((least_squares(misfit, [amp, 0.01, OMEGA_1, ph, float(u.mean())])
                for ph in np.linspace(-3.0, 3.0, 7)), key=lambda r: r.cost)
    A, zeta, omega, _, _ = best.x
    return float(zeta), float(omega), float(np.sqrt(2.0 * best.cost / tt.size) / abs(A))


SOLVERS = {"vfife": vfife.solve, "ancf": ancf.solve}


@pytest.mark.parametrize("method", ["vfife", "ancf"])
@pytest.mark.parametrize("damped", [False, True], ids=["BA=0", "BA"])
def test_the_axial_rod_decays_at_the_closed_forms_rate(method, damped):
    # zeta_1 = BA omega_1 / (2 EA) = 0.02 (log decrement 0.1257 per period). Measured over 7
    # periods: VFIFE 0.0200071, ANCF 0.0199889 (3.6e-4 and 5.6e-4 off); undamped |zeta| <
    # 1e-6. Tolerance 1 % of zeta_1: the discretisations' frequency errors (VFIFE -1.6e-4,
    # ANCF -5.2e-4 of omega_1 (Newmark's period elongation at T / 60); zeta_1 is
    # proportional to omega_1) and the fit's misfit (1.1e-3 of the amplitude, the even
    # modes' trace and the sampling) are ten times smaller; a BA off by a factor of the element length, or the damping missing from a
    # method, misses by far more. Undamped: |zeta| < 2e-4 (1 % of the damped figure): no
    # decay the model does not have. omega_1 within 0.1 % (the same discretisation errors).
    BA = BA_2PC if damped else 0.0
    res = SOLVERS[method](rod(BA))
    assert res.converged, res.message
    zeta, omega, misfit = midpoint_mode(res)
    assert misfit < 0.01, misfit           # one damped mode describes the motion
    assert abs(omega / OMEGA_1 - 1.0) < 1e-3, omega
    zeta_1 = BA * OMEGA_1 / (2.0 * EA)
    if damped:
        assert abs(zeta / zeta_1 - 1.0) < 0.01, (zeta, zeta_1)
    else:
        assert abs(zeta) < 2e-4, zeta


@pytest.mark.parametrize("method", ["vfife", "ancf"])
def test_the_statics_do_not_see_the_damping(method):
    # a damping force vanishes at rest: the static profile bit for bit the undamped one's
    a = SOLVERS[method](rod(0.0).replace(dynamics=None))
    b = SOLVERS[method](rod(1.0e6).replace(dynamics=None))
    assert a.converged and b.converged
    for key in ("x", "y", "tension", "moment"):
        assert np.array_equal(getattr(a.profile, key), getattr(b.profile, key)), key


def test_a_large_BA_shortens_the_vfifes_step_and_stays_stable():
    # BA 2e6 N s: the zig-zag mode of the 2 m elements (omega_max = sqrt(2 (k_l + k_r) /
    # m_i) = 316 rad/s, k = EA / l, m_i = M l) gets zeta = 2 (BA / l) / (m_i omega_max) =
    # 31.6: the damped limit 2 (sqrt(1 + zeta^2) - zeta) / omega_max is 1 / 63 of the
    # undamped one (von Neumann on the lagged-velocity dashpot, vfife/timestep.py). The run
    # must take that step and stay bounded; the control: at the undamped limit's step it
    # blows up (within 0.03 s, measured).
    BA = 2.0e6
    res = vfife.solve(rod(BA, periods=1))
    assert res.converged, res.message
    h, m_i = 2.0, M * 2.0
    om = math.sqrt(2.0 * (2.0 * EA / h) / m_i)
    zeta = 2.0 * (BA / h) / (m_i * om)
    limit = 2.0 * (math.sqrt(1.0 + zeta * zeta) - zeta) / om
    # the step: [vfife] time_step_safety (0.8) x the limit, shortened to divide the
    # output interval (T_1 / 40, some 100 steps: at most 1 % shorter)
    dt = res.info["dynamic_time_step"]
    assert res.info["dynamic_step_limit"] == "axial"
    assert 0.99 * 0.8 * limit <= dt <= 0.8 * limit * (1.0 + 1e-12), (dt, limit)
    x = res.dynamics.states["x"]
    assert np.all(np.isfinite(x)) and float(np.max(np.abs(x[:, :, 1] - x[0, :, 1]))) < 1e-3
    sc = rod(BA, periods=1)
    fixed = sc.replace(vfife=sc.vfife.replace(time_step=0.8 * h / math.sqrt(EA / M)))
    assert not vfife.solve(fixed).converged


# ------------------------------------------------------------------ the ANCF's Jacobian
XG, WG = np.polynomial.legendre.leggauss(5)
XG, WG = 0.5 * (XG + 1.0), 0.5 * WG


def _state(d, n=4, seed=1):
    """A bent, stretched 3-element line and random rates (the element tests' shape)."""
    rng = np.random.default_rng(seed)
    s = np.linspace(0.0, 6.0, n)
    q = np.zeros((n, 2 * d))
    q[:, 0] = 2.0 * np.sin(s / 3.0) + s
    q[:, 1] = 0.5 * s ** 1.5
    if d == 3:
        q[:, 2] = 0.3 * np.cos(s)
    t = np.gradient(q[:, :d], s, axis=0)
    t /= np.linalg.norm(t, axis=1)[:, None]
    q[:, d:] = 1.002 * t + 0.02 * rng.standard_normal((n, d))
    return q.ravel(), rng.standard_normal(q.size), np.diff(s)


def _damping(q, v, d, l0, BA, cK=0.0, cC=0.0):
    kl = banded.half_bandwidth(d)
    F = np.zeros(q.size)
    K = banded.zeros(q.size, kl)
    power = damping_pass(q, v, d, l0, BA, XG, WG, cK, cC, F, K, kl, np.zeros((0, 4 * d)))
    return F, banded.to_dense(K, kl), power


@pytest.mark.parametrize("d", [2, 3])
def test_the_ancf_damping_jacobians_are_its_derivatives(d):
    # central differences (h = 1e-6 on O(1) coordinates: truncation ~1e-12, round-off
    # ~1e-10 of the entries); measured 3e-10 (2D) and 7e-10 (3D) of the largest entry
    q, v, l0 = _state(d)
    BA = np.array([3.0e4, 1.0e4, 5.0e4])
    F, Kq, power = _damping(q, v, d, l0, BA, 1.0, 0.0)
    _, Kv, _ = _damping(q, v, d, l0, BA, 0.0, 1.0)
    h = 1e-6
    Kq_fd = np.zeros_like(Kq)
    Kv_fd = np.zeros_like(Kv)
    for i in range(q.size):
        e = np.zeros(q.size)
        e[i] = h
        Kq_fd[:, i] = (_damping(q + e, v, d, l0, BA)[0]
                       - _damping(q - e, v, d, l0, BA)[0]) / (2 * h)
        Kv_fd[:, i] = (_damping(q, v + e, d, l0, BA)[0]
                       - _damping(q, v - e, d, l0, BA)[0]) / (2 * h)
    assert np.max(np.abs(Kq - Kq_fd)) < 1e-7 * np.max(np.abs(Kq))
    assert np.max(np.abs(Kv - Kv_fd)) < 1e-7 * np.max(np.abs(Kv))
    # the force is the dissipation's: F . v = int BA (d eps / dt)^2 ds >= 0
    assert abs(float(F @ v) - power) < 1e-12 * abs(power) and power > 0.0


# ------------------------------------------------------------------ the frequency domain
@pytest.mark.parametrize("period", [None, 0.25], ids=["resonance", "0.25s"])
def test_the_frequency_domains_rod_has_the_complex_axial_stiffness(period):
    # The rod driven along its axis at the hang-off, D e^{i omega t}: u = D sin(k s) /
    # sin(k L), k^2 = m omega^2 / (EA + i omega BA), and the axial force (EA + i omega BA)
    # u' (the Kelvin-Voigt rod, no other damping). At the first resonance the damping
    # alone bounds the response (undamped it is singular). The box scheme, Richardson
    # extrapolated, on a smooth axial wave: measured 5e-12 (resonance, where BA = 0 puts
    # the amplitude 1e6 times higher) and 2e-12 of the peaks; tolerance 1e-6. The control: the same BA read as a damping of EA (not its
    # rate) misses by far (checked below with EA + BA instead of EA + i omega BA).
    from bvp.frequency.harmonic import solve_harmonic

    sc = rod(BA_2PC)
    sc = sc.replace(dynamics=sc.dynamics.replace(top_motion=None))
    omega = OMEGA_1 if period is None else 2.0 * math.pi / period
    D = 1.0e-3
    r = solve_harmonic(sc, 2.0 * math.pi / omega, np.array([D, 0.0, 0.0], complex))
    assert r.converged, r.message
    stiff = EA + 1j * omega * BA_2PC
    k = np.sqrt(M * omega ** 2 / stiff)
    exact_u = D * np.sin(k * r.s) / np.sin(k * L)
    exact_t = stiff * D * k * np.cos(k * r.s) / np.sin(k * L)
    err_u = np.max(np.abs(r.amplitudes["dx"] - exact_u)) / np.max(np.abs(exact_u))
    err_t = np.max(np.abs(r.amplitudes["tension"] - exact_t)) / np.max(np.abs(exact_t))
    assert err_u < 1e-6 and err_t < 1e-6, (err_u, err_t)
    wrong = EA + BA_2PC
    kw = np.sqrt(M * omega ** 2 / wrong + 0j)
    wrong_t = wrong * D * kw * np.cos(kw * r.s) / np.sin(kw * L)
    assert np.max(np.abs(r.amplitudes["tension"] - wrong_t)) > 1e-2 * np.max(np.abs(exact_t))


# ------------------------------------------------------------------ MoorDyn decks
TWO_LINES = """\
--------------------- MoorDyn Input File ------------------------------------
two lines of one type, joined by a free point
---------------------- LINE TYPES ------------------------------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
main  0.396  165.0  500.0e6  {ba}  120.8e3  1.0  1.0  0.0  0.0
---------------------- POINTS --------------------------------
ID Type X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1  Fixed   -100  0  -55  0  0  0  0
2  Free    -50   0  -60  0  0  0  0
3  Fixed   0     0  -5   0  0  0  0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1  main  1  2  80  {n1}  -
2  main  2  3  90  36  -
---------------------- OPTIONS -----------------------------------------
100        WtrDpth       water depth (m)
1000.0     WtrDnsty      water density (kg/m^3)
9.807      g             gravity (m/s^2)
------------------------- need this line --------------------------------------
"""


def _import(tmp_path, ba: str, n1: int = 32):
    from riser.io.moordyn.scene_from_deck import import_deck

    path = tmp_path / "two.dat"
    path.write_text(TWO_LINES.format(ba=ba, n1=n1))
    return import_deck(path)


def test_moordyn_s_damping_ratio_becomes_its_ba(tmp_path):
    # MoorDyn-C's Line::initialize (source/Line.cpp): a negative BA is minus a damping
    # ratio zeta, c = zeta (L / N) sqrt(E rho) [Pa s], E = EA / A, rho = (Mass/m) / A, and
    # the damping force c A d(eps)/dt: BA = zeta (L / N) sqrt(EA Mass/m), written out here.
    # Both lines 2.5 m segments (80 / 32, 90 / 36): one line type, 0.5 x 2.5 x sqrt(500e6
    # x 165) = 359,035 N s (rounding of two operations: 1e-15)
    _, sc, notes = _import(tmp_path, "-0.5")
    expected = 0.5 * 2.5 * math.sqrt(500.0e6 * 165.0)
    assert sc.line_types["main"].axial_damping == pytest.approx(expected, rel=1e-14)
    assert any("damping ratio" in n for n in notes)
    # segments of 80 / 20 = 4 m and 2.5 m: a line type per line, each with its own BA
    _, sc, notes = _import(tmp_path, "-0.5", n1=20)
    assert [seg.line_type for seg in sc.segments] == ["main_line1", "main_line2"]
    got = [sc.line_types[seg.line_type].axial_damping for seg in sc.segments]
    assert got == pytest.approx([0.5 * 4.0 * math.sqrt(500.0e6 * 165.0), expected],
                                rel=1e-14)
    # a BA in N s is kept as written; none stays none
    _, sc, _ = _import(tmp_path, "2.5e5")
    assert sc.line_types["main"].axial_damping == 2.5e5
    _, sc, _ = _import(tmp_path, "0")
    assert sc.line_types["main"].axial_damping == 0.0


def test_the_moordyn_export_keeps_the_ba(tmp_path):
    # export then import: BA written with repr and read back exactly; a line type without
    # axial_damping keeps MoorDyn's numerical damping -0.8 (as before the key), with no note
    from riser.io.moordyn.deck_from_scene import export_scene
    from riser.io.moordyn.scene_from_deck import import_deck
    from verification.catalog import resolve

    base = resolve("lowe-langley-case6").replace(dynamics=None)
    ba = 123456.789
    sc = base.replace(**{"line_types.main.axial_damping": ba})
    ex = export_scene(sc, segment_length=2.5, waves=False)
    assert ex.deck.line_types["main"].BA == repr(ba) and "BA [N s]" in ex.text
    (tmp_path / "deck.dat").write_text(ex.text)
    _, back, _ = import_deck(tmp_path / "deck.dat")
    assert back.line_types["main"].axial_damping == ba
    plain = export_scene(base, segment_length=2.5, waves=False)
    assert plain.deck.line_types["main"].BA == "-0.8" and "BA [N s]" not in plain.text


# ------------------------------------------------------------------ MoorDyn as the peer
def _ringing(t, tension, windows):
    """RMS [N] of the hang-off tension's content above 4 Hz (the axial modes; the sea's
    10 s wave and its harmonics below 1 Hz removed by a 4th-order Butterworth high-pass,
    forwards and backwards) in each time window (a, b) [s]."""
    from scipy.signal import butter, sosfiltfilt

    sos = butter(4, 4.0, "highpass", fs=1.0 / (t[1] - t[0]), output="sos")
    h = sosfiltfilt(sos, tension)
    return np.array([np.sqrt(np.mean(h[(t >= a) & (t < b)] ** 2)) for a, b in windows])


@needs_moordyn
@pytest.mark.slow
def test_the_jumpers_axial_ringing_decays_as_moordyns(tmp_path, monkeypatch):
    # The Lowe and Langley jumper in its wave (case 6, Wheeler stretching, MoorDyn-C's
    # WaveKin 7: tests/test_moordyn_waves.py) started impulsively (no ramp): the hang-off
    # tension rings at the line's axial modes (10.8 and 15.9 Hz). BA = 5e4 N s in the
    # scene, written into MoorDyn's deck as it is (2.5 m segments). The ringing's RMS
    # in 2 s windows, measured (kN):
    #   window          2-4    5-7    8-10   11-13  14-16  17-19
    #   VFIFE BA=0      0.706  0.670  0.605  0.597  0.561  0.511
    #   VFIFE BA        0.379  0.246  0.122  0.082  0.061  0.034
    #   MoorDyn-C BA    0.372  0.245  0.126  0.085  0.065  0.036
    #   ANCF BA         0.377  0.244  0.127  0.087  0.067  0.036
    # (the ANCF: 2 m elements, Newmark's average acceleration at 5 ms, no numerical
    # damping; its default T / 100 of the wave, 0.1 s, does not resolve 10.8 Hz)
    # Each window of both within 20 % of MoorDyn's (measured within 6.2 % and 3.1 %: the two discretisations'
    # axial frequencies differ, and the decay rate BA omega^2 / (2 EA) goes as their
    # square, over 2.5 m lumped segments against 1 m elements); the undamped VFIFE keeps
    # 79 % of its ringing over 12 s (drag alone) where both damped lose 83-84 %: the control
    # fails the same test. MoorDyn-C's RK2 steps at 0.06 of its CFL step (the peer's 0.3
    # relied on its -0.8 of critical: with 5e4 N s its segments' zig-zag grew and blew up
    # at t = 0.14 s). About 130 s (MoorDyn's statics 65 s, its 20 s of sea 25 s, the ANCF
    # 25 s).
    import verification.peers.moordyn.waves as md_waves
    from verification.catalog import resolve

    monkeypatch.setattr(md_waves, "STEP_FRACTION", 0.06)
    windows = [(2, 4), (5, 7), (8, 10), (11, 13), (14, 16), (17, 19)]

    def scene(BA):
        sc = resolve("lowe-langley-case6").replace(
            **{"waves.stretching": "wheeler", "waves.ramp_time": 0.0,
               "line_types.main.axial_damping": BA})
        return sc.replace(dynamics=sc.dynamics.replace(duration=20.0, output_interval=0.01,
                                                       statistics_start=0.0))

    def vfife_ringing(BA):
        res = vfife.solve(scene(BA))
        assert res.converged, res.message
        ts = res.dynamics.timeseries
        return _ringing(ts["time"], ts["hang_off_tension"], windows)

    damped, undamped = vfife_ringing(5.0e4), vfife_ringing(0.0)
    md = md_waves.run_waves(scene(5.0e4), tmp_path, segment_length=2.5, sample=0.01)
    assert md["stable"], md["message"]
    peer = _ringing(md["t"], md["hang_off_tension"], windows)
    print("ringing [kN] VFIFE", np.round(damped / 1e3, 3), "MoorDyn", np.round(peer / 1e3, 3),
          "VFIFE BA=0", np.round(undamped / 1e3, 3))
    assert np.all(np.abs(damped / peer - 1.0) < 0.2), damped / peer
    sc = scene(5.0e4)
    res = ancf.solve(sc.replace(ancf=sc.ancf.replace(time_step=0.005, integrator="newmark")))
    assert res.converged, res.message
    ts = res.dynamics.timeseries
    implicit = _ringing(ts["time"], ts["hang_off_tension"], windows)
    print("ringing [kN] ANCF", np.round(implicit / 1e3, 3))
    assert np.all(np.abs(implicit / peer - 1.0) < 0.2), implicit / peer
    assert damped[4] / damped[0] < 0.25 and peer[4] / peer[0] < 0.25
    assert undamped[4] / undamped[0] > 0.5


@pytest.mark.parametrize("value, words", [(-1.0, ">= 0"), (2.0e8, "10 s x axial_stiffness")])
def test_a_bad_axial_damping_is_refused_in_one_line(value, words):
    # the rod's EA 1e7 N: BA / EA above 10 s (2e8 N s: 20 s) is a unit slip, not a damping
    from riser.errors import SceneError

    with pytest.raises(SceneError) as err:
        rod(value)
    message = str(err.value)
    assert "line_types.p.axial_damping" in message and words in message
    assert "\n" not in message

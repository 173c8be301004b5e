"""Closed forms and exact balances of the frequency-domain harmonic response
(``bvp.frequency.harmonic.solve_harmonic``).

1. A weightless taut line (segment ``submerged_weight = 0``: the static line is exactly
   straight, tension EA (chord/L - 1) everywhere), pinned moment-free ends, no seabed, no
   drag, mass-proportional damping c_s: the transverse response to a transverse end
   motion D is the tensioned beam's, written out exactly below (its string limit
   D sin(k s)/sin(k L) when EI -> 0), the axial response to an axial motion the rod's.
2. The same line by the VFIFE in the time domain, first harmonic by
   ``verification.comparison.harmonics.fit``.
3. Undamped, drag off (scr-steel): the response's poles are the natural frequencies of
   ``bvp.modal.modes.solve_modes``.
4. With drag in still water (scr-steel): the work the hang-off does on the line per cycle
   equals the energy the drag (linearised, and nonlinear on the same velocity amplitude)
   and the structural and seabed dampers dissipate.

Convention (riser/results/response.py): q(s, t) = q0 + Re(Q e^{i omega t}); the motion's complex
amplitudes D = (D_x, D_y, D_z) [m]; s the unstretched arc length from the anchor.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

from builders import line, scene, small_pipe, straight
from poles import secant_pole
import bvp
from bvp.frequency import equations as he
from bvp.frequency.harmonic import solve_harmonic
from bvp.modal.equations import build_pieces
from bvp.modal.modes import solve_modes
from riser.physics.dynamics import Dynamics
from riser.physics.hang_off_motion import motion_amplitudes
from riser.model.sections import segment_properties
from verification.catalog import resolve
from verification.comparison.harmonics import fit

# ------------------------------------------------------------------ the taut line
L = 100.0                     # m, unstretched
CHORD = 100.1                 # m: strain 1e-3, T = EA 1e-3 = 1e4 N (small_pipe: EA 1e7 N)
ALPHA = math.radians(35.0)    # inclination of the chord (the in-plane rotation terms act)
C_S = 0.02                    # 1/s, [dynamics] damping: keeps the resonances finite
T_DIR = np.array([math.cos(ALPHA), math.sin(ALPHA), 0.0])      # along the line
N_DIR = np.array([-math.sin(ALPHA), math.cos(ALPHA), 0.0])     # in-plane normal


def taut_scene(EI: float, damping: float = C_S):
    """The weightless line (small_pipe: m 20 kg/m, m_a = rho pi D^2/4 = 8.05 kg/m, EA 1e7
    N) of bending stiffness EI [N m2] from (0, 10) to the chord's end at ALPHA, no drag,
    no seabed, no surface (no water_depth)."""
    anchor = (0.0, 10.0)
    top = (CHORD * math.cos(ALPHA), 10.0 + CHORD * math.sin(ALPHA))
    return scene(line(L, anchor, top, submerged_weight=0.0,
                      line_type=small_pipe(drag_normal=0.0, drag_tangential=0.0,
                                           bending_stiffness=EI),
                      dynamics={"duration": 10.0, "damping": damping}))


def section(sc):
    p = segment_properties(sc)[0]
    return p.mass, p.mass + p.added_mass, p.EA


def beam_transverse(s, D, T, EI, EA, mn, omega, cs):
    """Exact transverse amplitude of the tensioned extensible beam (pinned, moment-free
    ends, u(0) = 0, u(L) = D). The model (bvp/modal/modes.py, both families on a straight line,
    kappa = F = 0): w' = e psi, psi' = B/EI, B' = e (T psi - Q), Q' = -mn W2 w with
    e = 1 + T/EA and W2 = omega^2 - i omega c_s, i.e. (EI/e^2) u'''' - (T/e) u'' = mn W2 u
    in unstretched s. Roots of the characteristic equation: +-i k (the string's wave) and
    +-mu (the bending boundary layer, 1/mu ~ sqrt(EI/T)); the moment-free ends give
    u = D/(1 + r) [sin(k s)/sin(k L) + r sinh(mu s)/sinh(mu L)], r = k^2/mu^2.
    Returns (u, k)."""
    e = 1.0 + T / EA
    a, b = EI / e ** 2, T / e
    w2 = mn * (omega ** 2 - 1j * omega * cs)
    root = np.sqrt(b * b + 4.0 * a * w2)
    k2, mu2 = 2.0 * w2 / (b + root), (b + root) / (2.0 * a)
    k, mu = np.sqrt(k2), np.sqrt(mu2)
    r = k2 / mu2
    layer = np.exp(mu * (s - L)) * -np.expm1(-2.0 * mu * s) / -np.expm1(-2.0 * mu * L)
    return D / (1.0 + r) * (np.sin(k * s) / np.sin(k * L) + r * layer), k


def string_k(T, EA, mn, omega, cs):
    """The string's wavenumber per unstretched length: k^2 = e mn (omega^2 - i omega c_s)
    / T. (mn/e is the mass per stretched length and e L the stretched length; the
    textbook k^2 = mn W2 / T holds in stretched length. At this 1e-3 strain leaving e out
    shifts k L by 5e-4 of itself: 1e-4 of the response at 30 s, 3.0 % and 5.9 % at the
    first two damped resonances.)"""
    e = 1.0 + T / EA
    return np.sqrt(e * mn * (omega ** 2 - 1j * omega * cs) / T)


def resonance(n, T, EI, EA, mn):
    """Undamped period [s] of the n-th transverse mode sin(n pi s/L) (exact for the
    pinned tensioned beam): mn omega^2 = (T/e) k^2 + (EI/e^2) k^4, k = n pi/L."""
    e, k = 1.0 + T / EA, n * math.pi / L
    return 2.0 * math.pi / math.sqrt((T / e * k * k + EI / e ** 2 * k ** 4) / mn)


def normal_parts(r):
    """(u_n, u_t, w) of a response on the taut line: in-plane normal and axial, z."""
    d = np.stack([r.amplitudes[k] for k in ("dx", "dy", "dz")], axis=1)
    return d @ N_DIR, d @ T_DIR, d[:, 2]


@pytest.fixture(scope="module")
def taut():
    """(scene, static) of the taut line for EI = 1e3 N m2 (bending length sqrt(EI/T) =
    0.32 m, the wavelengths >= 19 m here) and EI = 1 N m2 (1 cm: the string limit)."""
    out = {}
    for EI in (1.0e3, 1.0):
        sc = taut_scene(EI)
        st = bvp.solve(sc)
        assert st.converged, st.message
        # exactly straight and uniform: the closed forms' static state
        assert np.ptp(st.profile.tension) < 1e-6 and np.ptp(st.profile.theta) < 1e-12
        out[EI] = (sc, st)
    return out


def _periods(EI):
    sc = taut_scene(EI)
    _, mn, EA = section(sc)
    T = EA * (CHORD / L - 1.0)
    return [30.0, resonance(1, T, EI, EA, mn), 8.0, resonance(2, T, EI, EA, mn), 3.0, 2.0]


@pytest.mark.parametrize("period", _periods(1.0e3), ids=lambda p: f"{p:.4g}s")
@pytest.mark.parametrize("plane", ["in_plane", "out_of_plane"])
def test_taut_line_transverse_exact(taut, period, plane):
    """The transverse amplitude against the exact tensioned beam, at periods off and at
    the first two (damped) resonances; the tension and the other family stay at rest."""
    sc, st = taut[1.0e3]
    _, mn, EA = section(sc)
    T = float(st.profile.tension[-1])
    D = N_DIR if plane == "in_plane" else np.array([0.0, 0.0, 1.0])
    r = solve_harmonic(sc, period, D.astype(complex), static=st)
    assert r.converged, r.message
    un, ut, w = normal_parts(r)
    u = un if plane == "in_plane" else w
    exact, k = beam_transverse(r.s, 1.0, T, 1.0e3, EA, mn, 2.0 * math.pi / period, C_S)
    err = np.max(np.abs(u - exact)) / np.max(np.abs(exact))
    # The box scheme is second order and solve_harmonic extrapolates its grid and the
    # halved one (Richardson): fourth order. Measured <= 4.7e-10 at 2 s (k L = 17) and at
    # the resonances (amplified 19 times by c_s = 0.02), 1.3e-12 at 30 s; the exact
    # closed form itself is good to ~1e-14.
    assert err < 1e-8, (period, plane, err)
    if abs(k.real * L - round(k.real * L / math.pi) * math.pi) < 1e-3:
        assert np.max(np.abs(u)) > 10.0          # a resonance, the damping keeps it finite
    # First order, a transverse motion of a straight line neither stretches it nor moves
    # the other family (kappa = F = 0 decouple the axial rows): both are exactly 0 in the
    # model; measured |dT| <= 1.2e-8 N and |u| <= 1.1e-13 m (roundoff), against T |D|/L =
    # 100 N and |D| = 1 m.
    other = w if plane == "in_plane" else un
    assert np.max(np.abs(ut)) < 1e-9 and np.max(np.abs(other)) < 1e-9
    assert np.max(np.abs(r.amplitudes["tension"])) < 1e-6 * T / L


@pytest.mark.parametrize("period", _periods(1.0), ids=lambda p: f"{p:.4g}s")
def test_taut_string_transfer_function(taut, period):
    """EI = 1 N m2 (bending length 1 cm against wavelengths >= 19 m): the string's
    u = D sin(k s)/sin(k L), k^2 = e (m + m_a)(omega^2 - i omega c_s)/T, out of plane
    and in plane (the normal component)."""
    sc, st = taut[1.0]
    _, mn, EA = section(sc)
    T = float(st.profile.tension[-1])
    omega = 2.0 * math.pi / period
    k = string_k(T, EA, mn, omega, C_S)
    # The string leaves out EI: it shifts k by EI k^2/(2 e T) and adds the boundary layer
    # of relative size r = EI k^2/(e T); a shift of k L moves the response by up to
    # |k L| / |sin k L| times it (the resonances). Bound: r (1 + |k L|/|sin k L|), which
    # the error stays under by a factor 2.0-3.8 at every period here (measured
    # 1.2e-8 ... 2.5e-5, scaling with EI: x1000 at EI = 1e3); plus 1e-8 for the grid
    # (test above).
    EI = 1.0
    bound = (EI * abs(k) ** 2 / ((1.0 + T / EA) * T)
             * (1.0 + abs(k * L) / abs(np.sin(k * L)))) + 1e-8
    for D in (N_DIR, np.array([0.0, 0.0, 1.0])):
        r = solve_harmonic(sc, period, D.astype(complex), static=st)
        assert r.converged, r.message
        un, _, w = normal_parts(r)
        u = un if D[2] == 0.0 else w
        exact = np.sin(k * r.s) / np.sin(k * L)
        err = np.max(np.abs(u - exact)) / np.max(np.abs(exact))
        assert err < bound, (period, D, err, bound)


@pytest.mark.parametrize("period", [5.0, 1.0, None, 0.2], ids=["5s", "1s", "resonance",
                                                                "0.2s"])
def test_taut_line_axial_exact(taut, period):
    """An axial end motion: the rod u'' = -(m W2/EA) u with the mass m alone (the added
    mass acts normal to the axis only), u = D sin(k s)/sin(k L), dT = EA u' (the model:
    u_t' = dT/EA, dT' = -m W2 u_t on a straight line)."""
    sc, st = taut[1.0e3]
    m, _, EA = section(sc)
    if period is None:                       # first axial resonance, k L = pi: 0.283 s
        period = 2.0 * L * math.sqrt(m / EA)
    D = 1.0e-3
    r = solve_harmonic(sc, period, (D * T_DIR).astype(complex), static=st)
    assert r.converged, r.message
    un, ut, w = normal_parts(r)
    omega = 2.0 * math.pi / period
    k = np.sqrt(m * (omega ** 2 - 1j * omega * C_S) / EA)
    exact = D * np.sin(k * r.s) / np.sin(k * L)
    tension = EA * D * k * np.cos(k * r.s) / np.sin(k * L)
    err_u = np.max(np.abs(ut - exact)) / np.max(np.abs(exact))
    err_t = np.max(np.abs(r.amplitudes["tension"] - tension)) / np.max(np.abs(tension))
    # Richardson-extrapolated box scheme (the axial wave is smooth: no boundary layer):
    # measured <= 3e-13 off resonance, 1.0e-8 at it (amplified 707 times by c_s).
    assert err_u < 1e-7 and err_t < 1e-7, (period, err_u, err_t)
    assert np.max(np.abs(un)) < 1e-9 * D and np.max(np.abs(w)) == 0.0   # roundoff: 1e-14 D


# ------------------------------------------------------------------ the VFIFE
def test_taut_line_vfife_first_harmonic():
    """The VFIFE's first harmonic of the transverse displacement (horizontal weightless
    line, y motion A sin(omega t), 1 m elements) against the exact transfer function."""
    from vfife.solver import solve

    period, A, cs = 15.0, 0.01, 0.2
    sc = scene(straight(L, CHORD, line_type=small_pipe(drag_normal=0.0,
                                                       drag_tangential=0.0),
                        vfife={"element_length": 1.0},
                        dynamics={"duration": 150.0, "damping": cs, "save_states": True,
                                  "output_interval": period / 24.0,
                                  "top_motion": {"axis": "y", "amplitude": A,
                                                 "period": period}}))
    res = solve(sc)
    assert res.converged, res.message
    states = res.dynamics.states
    t, s = states["t"], states["s"]
    q = states["x"][:, :, 1] - res.profile.y[None, :]
    h = fit(t, q.T, period, start=105.0)            # the last 3 periods
    _, mn, EA = section(sc)
    T = float(res.profile.tension[0])
    D = motion_amplitudes("y", A)[1]
    exact, _ = beam_transverse(s, D, T, 1.0e3, EA, mn, 2.0 * math.pi / period, cs)
    err = np.max(np.abs(h.first - exact)) / np.max(np.abs(exact))
    # Measured (k L = 2.28 - 0.52i): 3.3e-5 with 1 m elements (the same against
    # solve_harmonic), 1.7e-4 with 2 m; 6.8e-6 with 0.5 m (a 180 s run): the lumped-mass
    # chain's second-order dispersion, ~(k h)^2/24 in k, amplified by the transfer
    # function's slope. The start-up transient decays as exp(-c_s t/2): ~e^-10 of the
    # response when the window opens at 105 s (the fit's residual: 9e-6 of the
    # amplitude, the 2nd and 3rd harmonics 5e-6 of the first); the geometric nonlinearity
    # (the stretch (u')^2/2 changes T, EA/T = 1000) scales as A^2: 2e-4 at A = 0.05 m,
    # ~1e-5 at 0.01 m. Tolerance: 4.5x the measured error, below the 2 m elements' (the
    # test sees the element length).
    assert err < 1.5e-4, err
    assert np.max(h.residual) < 1e-4 * np.max(np.abs(exact))


# ------------------------------------------------------------------ poles at the modes
@pytest.fixture(scope="module")
def scr_undamped():
    """scr-steel without drag or damping (no [dynamics]): its static state and its
    first three natural modes of each family."""
    sc = resolve("scr-steel").replace(**{"line_types.steel.drag_normal": 0.0,
                                         "line_types.steel.drag_tangential": 0.0})
    st = bvp.solve(sc)
    assert st.converged, st.message
    modes = solve_modes(sc, count=3, static=st)
    assert modes.converged, modes.message
    return sc, st, modes


def _pole(sc, st, mode, intervals):
    """The FD's pole near ``mode``: the zero of 1/Q(omega^2) by the secant method from
    omega_n^2 (1 -+ 1e-3); Q the hang-off tension per unit x motion (in plane) or dz per
    unit z motion at the mode's antinode (out of plane). Undamped, Q is real (D real)."""
    in_plane = mode.plane == "in_plane"
    D = np.array([1.0, 0.0, 0.0] if in_plane else [0.0, 0.0, 1.0], complex)
    s_peak = mode.s[np.argmax(np.abs(mode.shape[:, 2]))]

    def g(lam):
        r = solve_harmonic(sc, 2.0 * math.pi / math.sqrt(lam), D, static=st,
                           intervals=intervals, check_grid=False)
        assert r.converged, r.message
        q = r.amplitudes["tension"][-1] if in_plane else r.at("dz", s_peak)
        assert abs(q.imag) <= 1e-9 * abs(q.real)
        return 1.0 / q.real

    return secant_pole(g, mode.omega, f"{mode.plane} mode {mode.number}")


def test_poles_at_the_natural_frequencies(scr_undamped):
    """Drag off, no damping: the response's poles (hang-off tension per unit x motion in
    plane, displacement per unit z motion out of plane) are the modal frequencies."""
    sc, st, modes = scr_undamped
    for mode in modes.modes:
        rel = [(_pole(sc, st, mode, n) - mode.omega) / mode.omega for n in (3000, 6000)]
        # Without the Richardson step (check_grid=False) the box scheme's poles are
        # second order in the grid: measured +3.8e-7 ... +1.1e-5 at 3000 intervals and
        # +9.4e-8 ... +2.8e-6 at 6000 (in-plane mode 3 the largest), each ratio
        # 3.981-4.000; their extrapolation (4 e_6000 - e_3000)/3 agrees with solve_modes
        # (solve_bvp-refined, ~1e-9) to 9e-11 ... 1.4e-8, the rest the next order's
        # (ratios 3.98 rather than 4: 0.02/3 e_6000). Tolerances 3x-4x.
        assert abs(rel[0]) < 3e-5 and abs(rel[1]) < 1e-5, (mode.plane, mode.number, rel)
        assert 3.8 < rel[0] / rel[1] < 4.2, (mode.plane, mode.number, rel)
        extrapolated = (4.0 * rel[1] - rel[0]) / 3.0
        assert abs(extrapolated) < 5e-8, (mode.plane, mode.number, rel, extrapolated)


# ------------------------------------------------------------------ energy balance
@pytest.fixture(scope="module")
def scr_drag():
    """scr-steel with its drag (C_Dn 1, C_Dt 0.03) in still water, the surface raised to
    1100 m (a heave of the hang-off at 1000 m is refused at water_depth 1000 m); its
    static state (without a current it does not depend on the drag)."""
    sc = resolve("scr-steel").replace(**{"environment.water_depth": 1100.0})
    st = bvp.solve(sc)
    assert st.converged, st.message
    return sc, st


def _end_derivative(s, q, points=5):
    """dq/ds at s[-1] by the polynomial through the last ``points`` nodes (the grid is
    refined towards the end to an eighth of the bending length)."""
    ds = s[-points:] - s[-1]
    return (np.polyfit(ds, q[-points:].real, points - 1)[-2]
            + 1j * np.polyfit(ds, q[-points:].imag, points - 1)[-2])


def hang_off_work(sc, st, r) -> tuple[float, float]:
    """Work per cycle [J per cycle] of the hang-off on the line, total and that of its z
    force. P = T t - F n (bvp/modal/modes.py) is the force of the part above s on the part
    below: P(L) is the hang-off's force on the line. First order: dP = (dT + F0 dtheta)
    t0 + (T0 dtheta - dF) n0 (dt = dtheta n, dn = -dtheta t) with dtheta = (-sn dx' + c
    dy')/e (the in-plane rows), and z: Q = T0 psi - (B' + EI kappa0^2 psi)/e with psi =
    w'/e (the out-of-plane rows). With f = Re(F e^{iwt}) and v = Re(i w D e^{iwt}), the
    work per cycle is int f.v dt = pi Im(F . conj(D))."""
    s, a, D = r.s, r.amplitudes, r.motion
    p = segment_properties(sc)[-1]
    top = build_pieces(sc, st.profile)[-1]
    at = top.static(np.array([s[-1]]))
    T0, F0, th0, kap0 = (float(at[k][0]) for k in ("T", "F", "theta", "kappa"))
    e = 1.0 + T0 / p.EA
    c0, s0 = math.cos(th0), math.sin(th0)
    dth = (-s0 * _end_derivative(s, a["dx"]) + c0 * _end_derivative(s, a["dy"])) / e
    Pt = a["tension"][-1] + F0 * dth
    Pn = T0 * dth - a["shear"][-1]
    psi = _end_derivative(s, a["dz"]) / e
    Q = T0 * psi - (_end_derivative(s, a["moment_out"]) + p.EI * kap0 ** 2 * psi) / e
    F = np.array([Pt * c0 - Pn * s0, Pt * s0 + Pn * c0, Q])
    return (math.pi * float(np.imag(np.sum(F * np.conj(D)))),
            math.pi * float(np.imag(Q * np.conj(D[2]))))


def dissipation(sc, st, r, cs, zeta) -> dict:
    """Energy dissipated per cycle [J] on the response r, integrated over s piece by piece
    (the static state's and the seabed's coefficients jump at the piece ends) by 4-point
    Gauss-Legendre on every interval of the response's grid, the amplitudes interpolated
    by a cubic spline per piece (a trapezoid on the nodes erred by 1e-6 with the drag and
    by 1.6 % on the seabed, whose contact zone bends over ~3 m: (EI/k)^(1/4)).

    'nonlinear': the Morison drag on the response's velocity v (still water: the relative
    velocity is -v): c_n int |v_perp|^3 dt + c_t int |v_t|^3 dt over a cycle, the normal
    speed 2D (in-plane normal and z) by 256 phases, the tangential one in closed form
    (int |A cos|^3 dt = (8/3) A^3 / omega); 'linear': the equivalent linear dampers of
    bvp.frequency.equations on the same velocity amplitudes, pi omega C |u|^2; both plus the
    structural damping -c_s (m along the axis, m + m_a normal) v, pi omega c_s m |u|^2,
    and the seabed dashpot 2 zeta sqrt(k (m + m_a)) on dy in the static contact zone.
    'z': the out-of-plane share (c_n <|v_perp| v_z^2> and c_s (m + m_a) |w|^2)."""
    omega = r.omega
    p = segment_properties(sc)[0]
    m, mn = p.mass, p.mass + p.added_mass
    c_n, c_t = p.drag_normal_coef, p.drag_tangential_coef
    phase = np.exp(2j * np.pi * np.arange(256) / 256)[None, :]
    xg, wg = np.polynomial.legendre.leggauss(4)
    out = dict.fromkeys(("nonlinear", "linear", "z", "dampers", "seabed"), 0.0)
    for pc in build_pieces(sc, st.profile):
        sel = (r.s >= pc.s0 - 1e-9) & (r.s <= pc.s1 + 1e-9)
        nodes = r.s[sel]
        h = np.diff(nodes)
        s = ((nodes[:-1] + 0.5 * h)[:, None] + 0.5 * h[:, None] * xg[None, :]).ravel()
        weight = (0.5 * h[:, None] * wg[None, :]).ravel()
        dx, dy, w = (CubicSpline(nodes, r.amplitudes[k][sel])(s) for k in ("dx", "dy", "dz"))
        theta = pc.spl["theta"](s)
        c, sn = np.cos(theta), np.sin(theta)
        un, ut = -sn * dx + c * dy, c * dx + sn * dy
        vn, vz = ((1j * omega * u[:, None] * phase).real for u in (un, w))
        speed = np.sqrt(vn * vn + vz * vz)
        nonlinear = (c_n * np.mean(speed ** 3, axis=1) * r.period
                     + c_t * 8.0 / 3.0 * (omega * np.abs(ut)) ** 3 / omega)
        zero = np.zeros(s.size)
        Cn, Cz, Ct = he.equivalent_coefficients(
            zero, zero, 1j * omega * un, 1j * omega * w, 1j * omega * ut,
            np.full(s.size, c_n), np.full(s.size, c_t))
        linear = math.pi * omega * (Cn * np.abs(un) ** 2 + Cz * np.abs(w) ** 2
                                    + Ct * np.abs(ut) ** 2)
        dampers = math.pi * omega * cs * (m * np.abs(ut) ** 2
                                          + mn * (np.abs(un) ** 2 + np.abs(w) ** 2))
        seabed = (math.pi * omega * 2.0 * zeta * math.sqrt(pc.k * mn) * np.abs(dy) ** 2
                  if pc.contact else zero)
        z = (c_n * np.mean(speed * vz * vz, axis=1) * r.period
             + math.pi * omega * cs * mn * np.abs(w) ** 2)
        for key, f in (("nonlinear", nonlinear + dampers + seabed),
                       ("linear", linear + dampers + seabed), ("z", z),
                       ("dampers", dampers), ("seabed", seabed)):
            out[key] += float(np.sum(f * weight))
    return out


@pytest.mark.parametrize("period, D, cs, zeta, drag", [
    (12.0, (2.0, 0.0, 0.0), 0.0, 0.0, True),            # surge: drag only
    (20.0, (0.0, 0.0, 3.0), 0.0, 0.0, True),            # sway: out of plane only
    (8.0, (1.0, 1.0j, 1.0), 0.05, 0.1, True),           # all three out of phase, dampers
    (12.0, (0.0, 2.0j, 0.0), 0.0, 1.0, False),          # heave: the seabed dashpot alone
], ids=["surge", "sway", "oblique-damped", "heave-seabed"])
def test_hang_off_work_is_the_dissipation(scr_drag, period, D, cs, zeta, drag):
    """Per cycle, the hang-off's work on the line = the energy dissipated by the drag
    (linearised, and nonlinear on the FD's velocity amplitude: equal by the equal-work
    definition, per direction), the structural damping and the seabed dashpot; the
    out-of-plane work = its own share."""
    sc, st = scr_drag
    changes = {"seabed.damping": zeta}
    if not drag:
        changes.update({"line_types.steel.drag_normal": 0.0,
                        "line_types.steel.drag_tangential": 0.0})
    sc = sc.replace(dynamics=Dynamics(duration=10.0, damping=cs) if cs else None, **changes)
    r = solve_harmonic(sc, period, np.asarray(D, complex), static=st)
    assert r.converged, r.message
    work, work_z = hang_off_work(sc, st, r)
    d = dissipation(sc, st, r, cs, zeta)
    # Measured |work/dissipation - 1|: surge 2.2e-7, sway 6.2e-8, oblique-damped 6.5e-8
    # (z's share 7e-9), nonlinear and linear alike (they differ by <= 1.7e-9: the
    # coefficients' 128 phases): the response's grid and the drag's fixed point
    # (tolerance 1e-6 on the coefficients). Heave on the seabed alone 1.9e-5: the spline
    # between the nodes (0.67 m) of the contact zone's short bends, fourth order (7e-7 at
    # twice the nodes). Tolerances: ~10x.
    tol = 2e-6 if drag else 2e-4
    for key in ("nonlinear", "linear"):
        assert abs(work / d[key] - 1.0) < tol, (key, work, d)
    if D[2]:
        assert abs(work_z / d["z"] - 1.0) < tol, (work_z, d)
    if cs:
        # the structural damping carries ~10 % of it, the seabed dashpot 2e-5 (too
        # little to check here: the heave case does)
        assert d["dampers"] > 0.05 * work, d
    if not drag:
        assert d["seabed"] == pytest.approx(d["nonlinear"]), d

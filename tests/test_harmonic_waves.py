"""The frequency domain with waves (``bvp.frequency.wave_loads``, ``bvp.frequency.harmonic.solve_harmonic`` of a
regular train, ``bvp.frequency.sea_response.solve_sea``), each check against a source independent
of the code under test:

1. the BVP's wave kinematics: the deep-water limit, the finite-depth closed form written
   out here, the free-surface conditions (the dispersion relation of riser.physics.waves'
   wave numbers) and continuity, the phase against riser.physics.waves.elevation;
2. the wave load: the exact response of a taut weightless line to the Morison inertia
   load of a wave travelling along it (the pinned tensioned beam, solved here), and to
   the drag and inertia of a deep-water orbit across it (a circular relative velocity:
   the drag is then linear, c_n U);
3. the vessel's path: one train moving the hang-off by a unit heave RAO (line loads off)
   gives the response to the equivalent top motion, the wave's phase at the RAO origin
   computed here;
4. the irregular sea without drag: the standard deviation equals sqrt(sum |Q_j|^2 / 2)
   of solve_harmonic per component (two routes); the stochastic linearisation's
   Gaussian expectations against adaptive quadrature; the statistics against their
   definitions.

Conventions: q(s, t) = q0 + Re(Q e^{i omega t}); a component's elevation Re(a e^{-i (k
xi + eps)} e^{i omega t}) (riser/physics/waves.py).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from builders import catenary, line, scene, small_pipe
import bvp
from bvp.frequency import sea_response as sr
from bvp.frequency import wave_loads as wl
from bvp.frequency.harmonic import solve_harmonic
from riser.physics.hang_off_motion import scene_components
from riser.results.result import Status
from riser.model.sections import segment_properties
from riser.physics.waves import Waves, WaveTrain, elevation, wave_numbers

G = 9.81


def train(depth, period, heading=0.0, phase=0.0, height=2.0, origin=(0.0, 0.0)):
    """The components of one regular train (riser.physics.waves)."""
    waves = Waves(trains=(WaveTrain(height=height, period=period, heading_deg=heading,
                                    phase_deg=phase),))
    return waves.components(depth, G, origin)


# ------------------------------------------------------------------ 1. kinematics
def test_deep_water_limit_without_overflow():
    """k h = 1257 (4 s in 5000 m; cosh(k h) overflows a double): |u_h| = |u_y| = a omega
    e^{k (y - h)}, u_y a quarter period ahead of u_h."""
    h = 5000.0
    comp = train(h, 4.0)
    k, w = comp.k[0], comp.omega[0]
    assert k * h > 700.0
    y = h - np.linspace(0.0, 40.0, 41)
    u, acc = wl.kinematics(comp, 0, np.zeros(y.size), y, np.zeros(y.size))
    exact = 1.0 * w * np.exp(k * (y - h))
    # the dropped term e^{-k (y + h)} is e^-2500 (0 in double precision): round-off only
    # (measured 0 and 1.1e-16)
    assert np.max(np.abs(np.abs(u[0]) / exact - 1.0)) < 1e-13
    assert np.max(np.abs(u[1] / (1j * u[0]) - 1.0)) < 1e-13
    assert np.max(np.abs(acc - 1j * w * u)) < 1e-13 * np.max(np.abs(u)) * w
    assert np.all(u[2] == 0.0)                 # heading 0: nothing along z


@pytest.mark.parametrize("depth, period", [(10.0, 14.0), (20.0, 8.0), (60.0, 9.0)])
def test_finite_depth_closed_form_and_phase(depth, period):
    """k h = 0.45, 1.4, 3.0: u_h = a omega cosh(k y)/sinh(k h), u_y = i a omega sinh(k
    y)/sinh(k h) (numpy's cosh, sinh directly) at points off the origin on a 30 deg
    heading, phased as riser.physics.waves.elevation says."""
    comp = train(depth, period, heading=30.0, phase=40.0, height=3.0, origin=(5.0, -2.0))
    k, w, b = comp.k[0], comp.omega[0], math.radians(30.0)
    rng = np.random.default_rng(3)
    x, z = rng.uniform(-50, 50, 20), rng.uniform(-50, 50, 20)
    y = rng.uniform(0.0, depth, 20)
    u, _ = wl.kinematics(comp, 0, x, y, z)
    A = wl.elevation_amplitude(comp, 0, x, z)
    # the phase: Re(A e^{i omega t}) is riser.physics.waves' elevation at every t past its ramp
    # (two periods); measured <= 1.2e-14 m (a = 1.5 m)
    for t in (100.0, 101.3, 104.1):
        eta = elevation(comp, x, z, t)
        assert np.max(np.abs((A * np.exp(1j * w * t)).real - eta)) < 1e-12
    uh = w * np.cosh(k * y) / np.sinh(k * depth) * A
    uy = 1j * w * np.sinh(k * y) / np.sinh(k * depth) * A
    # both forms are exact; they differ by round-off (measured <= 8e-16 relative)
    assert np.max(np.abs(u[0] - uh * math.cos(b))) < 1e-13 * np.max(np.abs(uh))
    assert np.max(np.abs(u[2] - uh * math.sin(b))) < 1e-13 * np.max(np.abs(uh))
    assert np.max(np.abs(u[1] - uy)) < 1e-13 * np.max(np.abs(uh))
    # above the mean level: the mean level's value
    top, _ = wl.kinematics(comp, 0, x[:1], np.array([depth + 1.0]), z[:1])
    lvl, _ = wl.kinematics(comp, 0, x[:1], np.array([depth]), z[:1])
    assert np.array_equal(top, lvl)


@pytest.mark.parametrize("depth, period", [(15.0, 10.0), (100.0, 7.0)])
def test_surface_conditions_and_continuity(depth, period):
    """At the mean level the linear free-surface conditions: u_y = d eta/dt (kinematic)
    and d u_h/dt = -g d eta/d xi (dynamic, the pressure constant there), which together
    hold only if omega^2 = g k tanh(k h): the kinematics against riser.physics.waves' dispersion
    relation. Below, continuity d u_x/dx + d u_y/dy = 0 (central differences)."""
    comp = train(depth, period, phase=25.0)
    k, w = comp.k[0], comp.omega[0]
    x = np.array([3.0])
    u, acc = wl.kinematics(comp, 0, x, np.array([depth]), np.zeros(1))
    A = wl.elevation_amplitude(comp, 0, x, 0.0)
    # round-off: the Newton wave number satisfies its relation to round-off (measured 0
    # and 3e-16)
    assert abs(u[1][0] - 1j * w * A[0]) < 1e-12 * w
    assert abs(acc[0][0] - (-G * (-1j * k) * A[0])) < 1e-12 * G * k
    # continuity by central differences of step d = 1 mm: truncation and round-off,
    # measured 1.2e-9 (15 m) and 1.6e-11 (100 m) of k omega; a sign slip in u_y would
    # leave 2 (cosh/sinh) ~ 10 of it
    d = 1e-3
    y0 = np.array([0.4 * depth])
    ux = [wl.kinematics(comp, 0, x + e, y0, np.zeros(1))[0][0][0] for e in (d, -d)]
    uy = [wl.kinematics(comp, 0, x, y0 + e, np.zeros(1))[0][1][0] for e in (d, -d)]
    div = (ux[0] - ux[1] + uy[0] - uy[1]) / (2.0 * d)
    assert abs(div) < 1e-7 * k * w, abs(div)


# ------------------------------------------------------------------ 2. the wave load
def beam_response(s, L, EI, T, EA, mn_w2, load, kappa):
    """Exact response u(s) of the pinned, moment-free tensioned beam (EI/e^2) u'''' -
    (T/e) u'' - mn_w2 u = load e^{-i kappa s} on [0, L] (unstretched s, e = 1 + T/EA; the
    transverse equation of both families on a straight line, tests/test_harmonic_closed_
    forms.py): the particular solution plus sin, cos (the string's wave k) and the two
    boundary layers e^{-mu s}, e^{mu (s - L)}, fitted to u = u'' = 0 at both ends."""
    e = 1.0 + T / EA
    a, b = EI / e ** 2, T / e
    root = np.sqrt(b * b + 4.0 * a * mn_w2 + 0j)
    k, mu = np.sqrt(2.0 * mn_w2 / (b + root)), np.sqrt((b + root) / (2.0 * a))
    P = a * kappa ** 4 + b * kappa ** 2 - mn_w2

    def part(q, d=0):
        return load * (-1j * kappa) ** d * np.exp(-1j * kappa * q) / P

    def basis(q, d=0):
        f = -k * k if d else 1.0
        g = mu * mu if d else 1.0
        return np.array([f * np.sin(k * q), f * np.cos(k * q), g * np.exp(-mu * q),
                         g * np.exp(mu * (q - L))])

    M = np.array([basis(0.0), basis(L), basis(0.0, 2), basis(L, 2)])
    c = np.linalg.solve(M, -np.array([part(0.0), part(L), part(0.0, 2), part(L, 2)]))
    return part(s) + c @ basis(s)


def taut_wave_scene(L, chord, depth_y, waves, *, drag=0.0, EA=1.0e7):
    """A weightless line (small_pipe: D 0.1 m, C_a 1, EI 1e3 N m2) of length L [m]
    stretched horizontally to ``chord`` [m] at height ``depth_y`` [m] in 100 m of water,
    pinned ends, no damping, the wave table ``waves``."""
    env = {"water_depth": 100.0, "waves": waves}
    return scene(line(L, (0.0, depth_y), (chord, depth_y), submerged_weight=0.0,
                      line_type=small_pipe(drag_normal=drag, drag_tangential=0.0,
                                           axial_stiffness=EA),
                      environment=env))


def test_inertia_load_of_a_wave_along_the_line():
    """A 8 s wave (H 2 m, phase 30 deg) travelling along a taut horizontal line 40 m
    below the surface, no drag: the vertical load (1 + C_a) rho pi D^2/4 a_y(x) varies
    along the line as e^{-i k x(s)}, x = s chord/L; the response is the beam's exact one.
    The horizontal flow is tangential: its acceleration loads the line axially by the
    Froude-Krylov force rho A a_x, which the tension balances."""
    L, chord, y0, h = 100.0, 100.1, 60.0, 100.0
    sc = taut_wave_scene(L, chord, y0, {"trains": [{"height": 2.0, "period": 8.0,
                                                    "phase_deg": 30.0}]})
    st = bvp.solve(sc)
    assert st.converged, st.message
    r = solve_harmonic(sc, static=st)
    assert r.converged, r.message
    assert r.period == 8.0 and np.all(r.motion == 0.0)
    p = segment_properties(sc)[0]
    T = float(st.profile.tension[-1])
    w = 2.0 * math.pi / 8.0
    k = float(wave_numbers([w], h, G)[0])
    inertia = (1.0 + 1.0) * 1025.0 * math.pi * 0.1 ** 2 / 4.0
    # a_y = (i w)^2 sinh(k y)/sinh(k h) a e^{-i (k (x - x0) + eps)}, x0 = chord (hang-off)
    load = (inertia * -w * w * math.sinh(k * y0) / math.sinh(k * h)
            * np.exp(-1j * (-k * chord + math.radians(30.0))))
    exact = beam_response(r.s, L, p.EI, T, p.EA, (p.mass + p.added_mass) * w * w, load,
                          k * chord / L)
    err = np.max(np.abs(r.amplitudes["dy"] - exact)) / np.max(np.abs(exact))
    # Richardson-extrapolated box scheme against the exact solution: measured 1.7e-11
    # (the load's wave, 100 m long, is resolved by ~0.03 m steps; the unextrapolated
    # grids differ by 1.3e-4). A load along x(s) unstretched (kappa = k) would be off by
    # k L 1e-3 = 6e-3, a missing Froude-Krylov term (C_a in place of 1 + C_a) by 50 %.
    assert err < 1e-9, err
    # Along the line the horizontal acceleration loads it axially by the Froude-Krylov
    # force rho A a_x alone (no axial added mass): the tension amplitude balances it,
    # dT/ds = -rho A a_x, up to the line's axial inertia m omega^2 dx (dx ~ 2e-5 m: 4e-4
    # of the load) and the grid's first differences (1e-4): tolerance 2e-3.
    ax = (1j * w * w * math.cosh(k * y0) / math.sinh(k * h)      # i omega u_x, u_x in phase with eta
          * np.exp(-1j * (k * (r.s * chord / L - chord) + math.radians(30.0))))
    q_t = 1025.0 * math.pi * 0.1 ** 2 / 4.0 * ax
    dT = np.gradient(r.amplitudes["tension"], r.s)
    assert np.max(np.abs(dT + q_t)) < 2e-3 * np.max(np.abs(q_t))
    assert r.info["wave"]["line_loads"] and not r.info["wave"]["vessel"]


def test_drag_and_inertia_of_a_deep_water_orbit_across_the_line():
    """A 4 s wave (k h = 25: deep) travelling along +z across a very taut horizontal line
    5 m below the surface: in the line's normal plane (y, z) the flow is a circle of
    constant speed U = a omega e^{k (y - h)}, so the drag on the line at rest is exactly
    linear, c_n U u; the load C u + M i omega u is uniform (the line lies on a crest
    line). The response of each family is the beam's with the damping i omega c_n U.
    The line moves a little (|omega u| / U = 2.7e-4): the FD's equivalent coefficients
    see that motion, the closed form does not."""
    L, y0, h = 20.0, 95.0, 100.0
    sc = taut_wave_scene(L, 1.001 * L, y0, {"trains": [{"height": 2.0, "period": 4.0,
                                                       "heading_deg": 90.0}]},
                         drag=1.0, EA=1.0e10)
    st = bvp.solve(sc)
    assert st.converged, st.message
    r = solve_harmonic(sc, static=st)
    assert r.converged, r.message
    p = segment_properties(sc)[0]
    T = float(st.profile.tension[-1])
    w = 2.0 * math.pi / 4.0
    k = float(wave_numbers([w], h, G)[0])
    U = w * math.exp(k * (y0 - h))
    C = p.drag_normal_coef * U
    inertia = 2.0 * 1025.0 * math.pi * 0.1 ** 2 / 4.0
    mn_w2 = (p.mass + p.added_mass) * w * w - 1j * w * C
    ratio = 0.0
    for name, flow in (("dy", 1j * U), ("dz", U)):            # u_y, u_z at the line
        exact = beam_response(r.s, L, p.EI, T, p.EA, mn_w2, (C + 1j * w * inertia) * flow,
                              0.0)
        err = np.max(np.abs(r.amplitudes[name] - exact)) / np.max(np.abs(exact))
        ratio = np.max(np.abs(w * r.amplitudes[name])) / U
        # The line's own velocity perturbs the relative velocity by |omega u| / U and the
        # coefficients by about as much: measured err = 0.41 ratio (1.1e-4), and 0.41
        # ratio again at 10x and 6x the motion (EA 1e9; L = 50 m): first order in it.
        # A wrong drag (a factor 8/(3 pi) or sqrt 2 on C) or inertia (1 + C_a -> C_a)
        # would be off by > 10 %.
        assert err < ratio, (name, err, ratio)
    assert 1e-4 < ratio < 1e-3


# ------------------------------------------------------------------ 3. the vessel path
def rao_table(heave=1.0, surge=0.0, surge_phase=0.0):
    """One [[vessel.raos]] table of heading 0, constant over 1-40 s."""
    zero = [0.0, 0.0]
    return {"heading_deg": 0.0, "periods": [1.0, 40.0],
            "surge": [surge] * 2, "surge_phase_deg": [surge_phase] * 2,
            "sway": zero, "sway_phase_deg": zero, "heave": [heave] * 2,
            "heave_phase_deg": zero, "roll": zero, "roll_phase_deg": zero,
            "pitch": zero, "pitch_phase_deg": zero, "yaw": zero, "yaw_phase_deg": zero}


def test_vessel_heave_is_the_equivalent_top_motion():
    """One train (H 3 m, 9 s, phase 50 deg, line loads off) and a vessel with a unit heave
    RAO of phase 0 whose RAO origin is 12 m behind the hang-off (lever arm 12 m along
    surge): the hang-off heaves by a e^{-i (k (-12) + eps)} (the wave at the RAO origin);
    the catenary's response (drag on, linearised on that amplitude) is that of the top
    motion given directly."""
    H, period, eps = 3.0, 9.0, math.radians(50.0)
    waves = {"line_loads": False, "trains": [{"height": H, "period": period,
                                             "phase_deg": 50.0}]}
    sc = scene(catenary(environment={"water_depth": 100.0, "waves": waves},
                        vessel={"hang_off_on_vessel": [12.0, 0.0, 0.0],
                                "raos": [rao_table()]}))
    plain = scene(catenary(environment={"water_depth": 100.0}))
    st = bvp.solve(plain)
    assert st.converged, st.message
    k = float(wave_numbers([2.0 * math.pi / period], 100.0, G)[0])
    D = np.array([0.0, 0.5 * H * np.exp(-1j * (k * -12.0 + eps)), 0.0])
    r_wave = solve_harmonic(sc, static=st)
    r_top = solve_harmonic(plain, period, D, static=st)
    assert r_wave.converged and r_top.converged, (r_wave.message, r_top.message)
    assert r_wave.info["drag_linearised"] and r_wave.info["iterations"] > 1
    # the same equations on the same motion (measured: identical bit for bit, the
    # motion's phase included; the bound leaves room for round-off in the phase)
    assert np.max(np.abs(r_wave.motion - D)) < 1e-14
    for key, q in r_top.amplitudes.items():
        peak = np.max(np.abs(q))
        assert np.max(np.abs(r_wave.amplitudes[key] - q)) <= 1e-12 * peak, key


def test_troughs_below_the_line_are_refused():
    """The FD has the line wholly in water: a trough below the hang-off (at 60 m in 61 m
    of water, H 4 m) is refused before solving, in one line naming the waves."""
    waves = {"trains": [{"height": 4.0, "period": 9.0}]}
    sc = scene(catenary(environment={"water_depth": 61.0, "waves": waves}))
    r = solve_harmonic(sc)
    assert r.status == Status.REFUSED
    assert "environment.waves" in r.message and "\n" not in r.message
    sea = {"spectrum": {"kind": "jonswap", "hs": 2.0, "tp": 10.0, "components": 4}}
    rs = sr.solve_sea(scene(catenary(environment={"water_depth": 61.0, "waves": sea})))
    assert rs.status == Status.REFUSED and "environment.waves" in rs.message


# ------------------------------------------------------------------ 4. the irregular sea
def sea_scene(drag: float, components: int = 8):
    """The catenary (150 m, touchdown on an elastic seabed, structural damping 0.05/s) in
    100 m of water under a JONSWAP sea (Hs 2 m, Tp 10 s), from a vessel heaving 1 m/m
    and surging 0.5 m/m a quarter period later."""
    env = {"water_depth": 100.0, "waves": {"spectrum": {
        "kind": "jonswap", "hs": 2.0, "tp": 10.0, "components": components}}}
    return scene(catenary(line_type=small_pipe(drag_normal=drag), environment=env,
                          vessel={"raos": [rao_table(1.0, 0.5, 90.0)]},
                          dynamics={"duration": 10.0, "damping": 0.05}))


@pytest.fixture(scope="module")
def sea_static():
    st = bvp.solve(sea_scene(0.0))
    assert st.converged, st.message
    return st


def test_sea_without_drag_is_the_sum_of_harmonic_responses(sea_static):
    """Drag off, the sea's standard deviations equal sqrt(sum_j |Q_j|^2 / 2) of
    solve_harmonic on one train per component (height 2 a_j, period 2 pi / omega_j, phase
    eps_j), on the same grid (solve_sea's 1500 intervals: solve_harmonic halves its
    ``intervals`` without the Richardson step); each transfer function too."""
    sc = sea_scene(0.0)
    r = sr.solve_sea(sc, static=sea_static)
    assert r.converged, r.message
    comp = scene_components(sc)
    total = {k: 0.0 for k in ("tension", "curvature", "dx", "dy")}
    for j in range(comp.size):
        one = Waves(trains=(WaveTrain(height=2.0 * comp.amplitude[j],
                                      period=2.0 * math.pi / comp.omega[j],
                                      phase_deg=math.degrees(comp.phase[j])),))
        h = solve_harmonic(sc.replace(waves=one), static=sea_static, intervals=3000,
                           check_grid=False)
        assert h.converged, h.message
        assert np.array_equal(h.s, r.s)
        for key in total:
            q = h.amplitudes[key]
            total[key] = total[key] + 0.5 * np.abs(q) ** 2
            a = comp.amplitude[j] * np.exp(-1j * comp.phase[j])
            # the same linear equations on the same grid: round-off (measured 3e-16 of the
            # peak)
            assert np.max(np.abs(r.transfer[key][j] * a - q)) < 1e-11 * np.max(np.abs(q))
    for key, var in total.items():
        err = np.max(np.abs(r.std[key] - np.sqrt(var))) / np.max(np.sqrt(var))
        assert err < 1e-11, (key, err)                 # measured 0: round-off
    assert r.info["iterations"] == 1 and not r.info["drag_linearised"]


def test_sea_statistics_with_drag(sea_static):
    """Drag on (C_Dn 1): the fixed point settles; the statistics are those of their
    definitions from the response spectra (m0 = int S d omega, Tz = 2 pi sqrt(m0 / m2),
    Rayleigh's most probable maximum sigma sqrt(2 ln(D / Tz))); the drag damps the
    response (dy's deviation below the drag-free one)."""
    sc = sea_scene(1.0)
    r = sr.solve_sea(sc, static=sea_static, duration=3 * 3600.0)
    assert r.converged, r.message
    assert r.info["drag_linearised"] and r.info["iterations"] > 2
    free = sr.solve_sea(sea_scene(0.0), static=sea_static)
    for key in ("tension", "curvature", "dy"):
        S = r.spectra[key]
        m0 = np.sum(S, axis=0) * r.d_omega
        m2 = np.sum(r.omega[:, None] ** 2 * S, axis=0) * r.d_omega
        # the spectra are the |Q|^2 / (2 d omega) the deviations are summed from:
        # round-off
        assert np.allclose(r.std[key], np.sqrt(m0), rtol=1e-12, atol=0.0)
        # where the response is nil (the moment-free hang-off's curvature): no crossings
        # (Tz undefined), no maximum
        live = m2 > 0.0
        assert np.all(np.isnan(r.tz[key][~live])) and np.all(r.mpm[key][~live] == 0.0)
        assert live[-1] == (key != "curvature")
        tz = 2.0 * math.pi * np.sqrt(m0[live] / m2[live])
        assert np.allclose(r.tz[key][live], tz, rtol=1e-12)
        assert np.allclose(r.mpm[key][live],
                           np.sqrt(m0[live]) * np.sqrt(2.0 * np.log(10800.0 / tz)),
                           rtol=1e-12)
        assert np.allclose(r.significant[key], 2.0 * r.std[key], rtol=0.0, atol=0.0)
    assert np.max(r.std["dy"]) < np.max(free.std["dy"])
    # the transfer functions per unit wave amplitude times the wave's density: the spectra
    H = r.transfer["tension"]
    assert np.allclose(r.spectra["tension"], np.abs(H) ** 2 * r.wave_density[:, None],
                       rtol=1e-12)


@pytest.mark.parametrize("mu", [0.0, 0.4, -1.3])
def test_stochastic_coefficients_against_quadrature(mu):
    """The Gaussian expectations of the stochastic linearisation against adaptive
    quadrature of their definitions: tangential C_t = c_t E[f(v) X] / sigma^2 (the
    least-squares form, v = mu + X, f = |v| v: equal to E[f'] by Stein's lemma); normal
    C_n, C_z = c_n E[|v| + v_j^2 / |v|] over a correlated 2D Gaussian (dblquad in polar
    coordinates about v = 0, where the integrand is smooth); the planar case: C_n =
    c_n sqrt(8/pi) sigma in still water."""
    var = 0.7
    sig = math.sqrt(var)

    def dens(x):
        return math.exp(-0.5 * x * x / var) / math.sqrt(2.0 * math.pi * var)

    ls = integrate.quad(lambda x: abs(mu + x) * (mu + x) * x * dens(x), -12 * sig,
                        12 * sig, points=[-mu], epsabs=1e-13, epsrel=1e-12)[0] / var
    _, _, Ct = sr.gaussian_coefficients(np.zeros(1), np.array([mu]), 0.0, 0.0, 0.0, var,
                                        1.0, 1.0)
    # the quadrature's tolerance 1e-12 (measured 3e-16: the closed form is exact)
    assert abs(Ct[0] - ls) < 1e-9 * abs(ls)
    Cn, Cz, _ = sr.gaussian_coefficients(np.array([0.0]), np.zeros(1), var, 0.0, 0.0, 0.0,
                                         1.0, 1.0)
    assert abs(Cn[0] - math.sqrt(8.0 / math.pi) * sig) < 1e-14
    assert abs(Cz[0] - 0.5 * Cn[0]) < 1e-14
    S = np.array([[0.9, 0.25], [0.25, 0.4]])
    P, det = np.linalg.inv(S), np.linalg.det(S)

    def g(r, ph, j):
        v = r * np.array([math.cos(ph), math.sin(ph)])
        x = v - np.array([mu, 0.0])
        p = math.exp(-0.5 * x @ P @ x) / (2.0 * math.pi * math.sqrt(det))
        return r * r * (1.0 + v[j] ** 2 / (r * r)) * p

    R = abs(mu) + 12.0
    ref = [integrate.dblquad(lambda r, ph: g(r, ph, j), 0.0, 2.0 * math.pi, 0.0, R,
                             epsabs=1e-11, epsrel=1e-10)[0] for j in (0, 1)]
    Cn, Cz, _ = sr.gaussian_coefficients(np.array([mu]), np.zeros(1), S[0, 0], S[1, 1],
                                         S[0, 1], 0.0, 1.0, 1.0)
    # the angle's trapezoidal rule is spectral on this smooth periodic integrand:
    # measured <= 2.2e-16 of the value; the bound is dblquad's tolerance (1e-10) with room
    assert abs(Cn[0] / ref[0] - 1.0) < 1e-8 and abs(Cz[0] / ref[1] - 1.0) < 1e-8

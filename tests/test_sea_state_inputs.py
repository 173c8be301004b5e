"""Sea-state inputs (riser/physics/waves.py, riser/physics/vessel.py, riser/physics/hang_off_motion.py) and the
VFIFE's wave kinematics (vfife.kernels.wave_pass), each against an independent source: the
dispersion relation, the Airy closed forms, the spectra's moments, the synthesised record's
statistics, today's harmonic top motion, and one-line refusals of bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest

import vfife
from riser.errors import SceneError
from riser.physics.hang_off_motion import hang_off_displacement
from riser.io.scene_file import scene_from_dict
from riser.physics.vessel import DOFS, RAOTable, Vessel
from riser.physics.waves import WaveSpectrum, WaveTrain, Waves, elevation, wave_numbers
from vfife import kernels

from builders import catenary, scene

G = 9.81


# ------------------------------------------------------------------ dispersion, kinematics
@pytest.mark.parametrize("period, depth", [(10.0, 1000.0), (10.0, 50.0), (6.0, 10.0),
                                           (20.0, 30.0)])
def test_dispersion_solves_omega2_equals_gk_tanh_kh(period, depth):
    """Newton's k satisfies omega^2 = g k tanh(k h) to round-off (1e-12 relative)."""
    w = 2.0 * math.pi / period
    k = float(wave_numbers([w], depth, G)[0])
    assert w * w == pytest.approx(G * k * math.tanh(k * depth), rel=1e-12)


def test_dispersion_limits():
    """Deep water k = omega^2 / g; shallow water k = omega / sqrt(g h) (kh = 0.01: the
    limit's error ~ (kh)^2 / 6 = 2e-5)."""
    w = 2.0 * math.pi / 8.0
    assert wave_numbers([w], 5000.0, G)[0] == pytest.approx(w * w / G, rel=1e-12)
    h = 0.01 ** 2 * G / w ** 2                    # k h ~ 0.01
    assert wave_numbers([w], h, G)[0] == pytest.approx(w / math.sqrt(G * h), rel=1e-4)


def _kernel(amp, period, heading_deg, phase_deg, x, y, z, t, depth, wheeler=False):
    comp = Waves(trains=(WaveTrain(2 * amp, period, heading_deg, phase_deg),)).components(
        depth, G, (0.0, 0.0))
    out = np.zeros((21, np.size(x)))
    kernels.wave_pass(np.atleast_1d(np.asarray(x, float)), np.atleast_1d(np.asarray(y, float)),
                      np.atleast_1d(np.asarray(z, float)), t, comp.amplitude, comp.omega,
                      comp.k, comp.phase, np.cos(comp.heading), np.sin(comp.heading), 0.0,
                      0.0, depth, wheeler, out)
    return out, comp


@pytest.mark.parametrize("depth", [30.0, 2000.0])
def test_kernel_kinematics_match_airy_closed_forms(depth):
    """Finite and deep water: velocity and acceleration at points below the mean level
    against Airy's closed forms written here (theta = omega t - k x' - eps; u_h = a omega
    cosh(k y)/sinh(k h) cos theta, u_y = -a omega sinh(k y)/sinh(k h) sin theta, the
    accelerations their time derivatives), to round-off (1e-12 of a omega)."""
    a, T, hd, ph = 1.5, 9.0, 30.0, 40.0
    y = np.linspace(0.2, 0.95, 7) * depth
    x = np.linspace(-40.0, 60.0, 7)
    z = np.linspace(5.0, -20.0, 7)
    t = 13.7
    out, comp = _kernel(a, T, hd, ph, x, y, z, t, depth, wheeler=False)
    k, w = comp.k[0], comp.omega[0]
    b = math.radians(hd)
    th = w * t - k * (x * math.cos(b) + z * math.sin(b)) - math.radians(ph)
    C = np.cosh(k * y) / np.sinh(k * depth) if depth < 100 else np.exp(k * (y - depth))
    S = np.sinh(k * y) / np.sinh(k * depth) if depth < 100 else np.exp(k * (y - depth))
    uh, uy = a * w * C * np.cos(th), -a * w * S * np.sin(th)
    ah, ay = -a * w * w * C * np.sin(th), -a * w * w * S * np.cos(th)
    scale = a * w
    for row, ref in ((0, uh * math.cos(b)), (1, uy), (2, uh * math.sin(b)),
                     (3, ah * math.cos(b)), (4, ay), (5, ah * math.sin(b)),
                     (6, a * np.cos(th))):
        assert np.max(np.abs(out[row] - ref)) < 1e-12 * scale * max(1.0, w), row


def test_vertical_velocity_is_the_surface_rate_and_derivatives_are_exact():
    """At the mean level the vertical velocity is d eta / dt (the kinematic surface
    condition of linear theory); the Taylor rows are the exact time derivatives (a
    central difference of the values at +-1 ms agrees to its O(dt^2) 1e-6)."""
    depth, t, dt = 80.0, 5.3, 1e-3
    x, y, z = np.array([12.0]), np.array([depth]), np.array([0.0])
    out, _ = _kernel(2.0, 7.0, 0.0, 10.0, x, y, z, t, depth)
    lo, _ = _kernel(2.0, 7.0, 0.0, 10.0, x, y, z, t - dt, depth)
    hi, _ = _kernel(2.0, 7.0, 0.0, 10.0, x, y, z, t + dt, depth)
    assert out[1, 0] == pytest.approx((hi[6, 0] - lo[6, 0]) / (2 * dt), rel=1e-6)
    for r in range(7):
        assert out[7 + r, 0] == pytest.approx((hi[r, 0] - lo[r, 0]) / (2 * dt), rel=1e-5,
                                              abs=1e-9)


def test_wheeler_stretching_maps_the_crest_to_the_mean_level():
    """Wheeler: the velocity at the crest equals linear theory's at the mean level; under
    the crest at y the value of y h / (h + eta)."""
    depth, T, a = 60.0, 8.0, 2.0
    crest = np.array([depth + a])                 # eta = a at x = 0, t = 0, phase 0
    out, comp = _kernel(a, T, 0.0, 0.0, [0.0], crest, [0.0], 0.0, depth, wheeler=True)
    k, w = comp.k[0], comp.omega[0]
    assert out[0, 0] == pytest.approx(a * w / math.tanh(k * depth), rel=1e-12)
    y = np.array([40.0])
    out, _ = _kernel(a, T, 0.0, 0.0, [0.0], y, [0.0], 0.0, depth, wheeler=True)
    ys = y[0] * depth / (depth + a)
    assert out[0, 0] == pytest.approx(a * w * math.cosh(k * ys) / math.sinh(k * depth),
                                      rel=1e-12)


# ------------------------------------------------------------------ spectra
@pytest.mark.parametrize("kind, hs, tp", [("jonswap", 4.0, 10.0), ("pierson-moskowitz", 6.0, 12.0),
                                           ("jonswap", 2.0, 6.0)])
def test_spectrum_variance_is_hs2_over_16(kind, hs, tp):
    """m0 = Hs^2 / 16 for the continuous spectrum (DNV's normalisation 1 - 0.287 ln gamma
    is good to ~1 %: tolerance 2 %), and the components' sum of a^2 / 2 equals the
    spectrum's integral over their range to the midpoint rule's 1e-3."""
    sp = WaveSpectrum(kind=kind, hs=hs, tp=tp)
    assert sp.moment(0) == pytest.approx(hs * hs / 16.0, rel=0.02)
    comp = Waves(spectrum=sp).components(1000.0, G, (0.0, 0.0))
    lo, hi = sp.omega_range
    w = np.linspace(lo, hi, 20001)
    part = np.trapezoid(sp.density_at(w), w)
    assert np.sum(comp.amplitude ** 2) / 2.0 == pytest.approx(part, rel=1e-3)
    assert part > 0.99 * sp.moment(0)             # the default range keeps > 99 %


def test_jonswap_gamma_default_is_dnvs():
    """DNV-RP-C205: gamma 5 at Tp/sqrt(Hs) <= 3.6, 1 at >= 5, exp(5.75 - 1.15 r) between."""
    assert WaveSpectrum(kind="jonswap", hs=9.0, tp=10.5).gamma_used == 5.0     # r = 3.5
    assert WaveSpectrum(kind="jonswap", hs=4.0, tp=11.0).gamma_used == 1.0     # r = 5.5
    r = 12.0 / 3.0
    assert WaveSpectrum(kind="jonswap", hs=9.0, tp=12.0).gamma_used == pytest.approx(
        math.exp(5.75 - 1.15 * r))


def test_synthesised_record_has_the_target_variance_and_spectrum():
    """A record over the realisation's repeat period 2 pi / d omega: its variance is the
    components' sum a^2 / 2 exactly (the components are orthogonal over it; 1e-9), its
    periodogram returns each component's a^2 / 2 in its own bin, and the same seed gives
    the same record, another seed another."""
    sp = WaveSpectrum(kind="jonswap", hs=3.0, tp=9.0, components=64, seed=7)
    comp = Waves(spectrum=sp, ramp_time=0.0).components(500.0, G, (0.0, 0.0))
    dw = sp.component_omegas()[1]
    period = 2.0 * math.pi / dw
    n = 8192
    t = np.arange(n) * period / n
    eta = elevation(comp, 0.0, 0.0, t)
    assert np.var(eta) == pytest.approx(np.sum(comp.amplitude ** 2) / 2.0, rel=1e-9)
    power = np.abs(np.fft.rfft(eta) / n) ** 2 * 2.0      # a^2 / 2 per bin
    bins = np.rint(comp.omega / dw).astype(int)          # omega_j = m_j d omega
    assert np.allclose(power[bins], comp.amplitude ** 2 / 2.0, rtol=1e-9, atol=1e-15)
    again = Waves(spectrum=sp).components(500.0, G, (0.0, 0.0))
    assert np.array_equal(again.phase, comp.phase)
    other = Waves(spectrum=sp.replace(seed=8)).components(500.0, G, (0.0, 0.0))
    assert not np.array_equal(other.phase, comp.phase)


# ------------------------------------------------------------------ vessel, RAOs
def _rao(heading=0.0, **dofs):
    periods = (2.0, 30.0)
    values = {d: dofs.get(d, (0.0, 0.0)) for d in DOFS}
    phases = {f"{d}_phase_deg": dofs.get(f"{d}_phase_deg", (0.0, 0.0)) for d in DOFS}
    return RAOTable(heading_deg=heading, periods=periods, **values, **phases)


def _wave_scene(vessel: Vessel, train: WaveTrain, *, loads=False, duration=30.0,
                top_motion=None):
    data = catenary(environment={"water_depth": 200.0})
    data["dynamics"] = {"duration": duration, "output_interval": 0.1}
    if top_motion is not None:
        data["dynamics"]["top_motion"] = top_motion
        return scene(data)
    s = scene(data)
    return s.replace(waves=Waves(trains=(train,), line_loads=loads, ramp_time=train.period),
                     vessel=vessel)


def test_unit_heave_rao_reproduces_the_harmonic_top_motion_exactly():
    """A vessel of unit heave RAO (phase lag 0) in a wave of amplitude A, period T and
    phase lag 90 deg at the hang-off, waves loading only the vessel, moves the hang-off by
    A cos(omega t - pi/2) = A sin(omega t) with the ramp of one period: today's harmonic
    heave. The paths agree to round-off (5e-15 m); the VFIFE's time series then agree to
    1e-5 of the peak tension, not to the bit: this light catenary on its seabed amplifies
    round-off (today's motion with its amplitude changed by 1e-14 moves the tension by
    3.7e-7 of its peak within 30 s, measured), and the two paths differ by round-off."""
    A, T = 1.5, 9.0
    train = WaveTrain(2 * A, T, 0.0, 90.0)
    waved = _wave_scene(Vessel(raos=(_rao(heave=(1.0, 1.0)),)), train)
    today = _wave_scene(None, None, top_motion={"axis": "y", "amplitude": A, "period": T})
    t = np.linspace(0.0, 30.0, 3001)
    assert np.max(np.abs(hang_off_displacement(waved, t)
                         - hang_off_displacement(today, t))) < 1e-12
    a, b = vfife.solve(waved), vfife.solve(today)
    assert a.converged and b.converged
    ta, tb = a.dynamics.timeseries, b.dynamics.timeseries
    assert np.max(np.abs(ta["hang_off_tension"] - tb["hang_off_tension"])) <= 1e-5 * np.max(
        np.abs(tb["hang_off_tension"]))


def test_rao_phase_is_a_lag_behind_the_crest_at_the_rao_origin():
    """OrcaFlex's convention, pinned: surge RAO 2 m/m with a 60 deg lag moves the vessel
    by 2 a cos(omega t - 60 deg) when the crest passes its RAO origin at t = 0; the
    hang-off 10 m above it on a pitch RAO of 1 deg/m (phase 0) moves along x by
    -10 theta... (theta x r with r along heave: pitch about sway +z turns +y into -x)."""
    A, T = 1.0, 10.0
    train = WaveTrain(2 * A, T, 0.0, 0.0)
    v = Vessel(raos=(_rao(surge=(2.0, 2.0), surge_phase_deg=(60.0, 60.0)),))
    s = _wave_scene(v, train)
    w = 2 * math.pi / T
    t = np.array([25.0, 27.5, 31.0])                       # after the ramp
    d = hang_off_displacement(s, t)
    assert d[0] == pytest.approx(2 * A * np.cos(w * t - math.radians(60.0)), abs=1e-12)
    v2 = Vessel(raos=(_rao(pitch=(1.0, 1.0)),), hang_off_on_vessel=(0.0, 10.0, 0.0))
    d2 = hang_off_displacement(_wave_scene(v2, train), t)
    assert d2[0] == pytest.approx(-10.0 * math.radians(1.0) * A * np.cos(w * t), abs=1e-12)
    assert np.max(np.abs(d2[1:])) < 1e-12


def test_rao_interpolates_linearly_in_period_and_heading():
    """Amplitude and phase linear in the period between the table's rows; between two
    heading tables linear in the heading (halfway: the mean)."""
    t0 = RAOTable(heading_deg=0.0, periods=(5.0, 15.0), **{d: (0.0, 1.0) for d in DOFS},
                  **{f"{d}_phase_deg": (0.0, 90.0) for d in DOFS})
    r = t0.complex_rao([10.0])
    assert abs(r[2, 0]) == pytest.approx(0.5)
    assert -np.angle(r[2, 0]) == pytest.approx(math.radians(45.0))
    t90 = t0.replace(heading_deg=90.0, heave=(0.0, 3.0))
    both = Vessel(raos=(t0, t90)).complex_rao([15.0], [45.0])
    assert abs(both[2, 0]) == pytest.approx(2.0)


# ------------------------------------------------------------------ bad input
def _data(**waves):
    data = catenary(environment={"water_depth": 200.0, "waves": waves})
    return data


@pytest.mark.parametrize("waves, key, words", [
    ({"trains": [{"height": 30.0, "period": 4.0}]}, "environment.waves.trains[0].height",
     "breaks"),
    ({"spectrum": {"kind": "jonswap", "hs": 12.0, "tp": 8.0}}, "environment.waves.spectrum.tp",
     "steeper sea breaks"),
    ({"spectrum": {"kind": "jonswap", "hs": 40.0, "tp": 20.0}}, "environment.waves.spectrum.hs",
     "<= 30"),
    ({"spectrum": {"kind": "table", "omega": [0.5, 1.0], "density": [0.0, 0.0]}},
     "environment.waves.spectrum.density", "no energy"),
    ({"spectrum": {"kind": "table", "omega": [1.0, 0.5], "density": [1.0, 1.0]}},
     "environment.waves.spectrum.omega[1]", "strictly increasing"),
    ({"spectrum": {"kind": "jonswap", "hs": 2.0, "tp": 9.0, "seed": 1.5}},
     "environment.waves.spectrum.seed", "integer"),
    ({}, "environment.waves.trains", "at least one"),
])
def test_bad_waves_one_line_naming_the_key(waves, key, words):
    with pytest.raises(SceneError) as err:
        scene_from_dict(_data(**waves), "w.toml")
    text = str(err.value)
    assert key in text and words in text and "\n" not in text, text


def test_bad_vessel_one_line_naming_the_key():
    train = {"trains": [{"height": 2.0, "period": 9.0, "heading_deg": 90.0}]}
    data = _data(**train)
    rao = {"heading_deg": 0.0, "periods": [5.0, 20.0]}
    for d in DOFS:
        rao[d] = [0.0, 0.0]
        rao[f"{d}_phase_deg"] = [0.0, 0.0]
    missing = dict(rao)
    del missing["pitch"]
    cases = [({"raos": [missing]}, "vessel.raos[0].pitch", "required"),
             ({"raos": [{**rao, "periods": [20.0, 5.0]}]}, "vessel.raos[0].periods[1]",
              "strictly increasing"),
             ({"raos": [rao]}, "vessel.raos", "no RAO table for the waves' heading 90")]
    for vessel, key, words in cases:
        with pytest.raises(SceneError) as err:
            scene_from_dict({**data, "vessel": vessel}, "v.toml")
        text = str(err.value)
        assert key in text and words in text and "\n" not in text, text
    with pytest.raises(SceneError, match="needs \\[environment.waves\\]"):
        scene_from_dict({**catenary(), "vessel": {"raos": [rao]}}, "v.toml")


# ------------------------------------------------------------------ response statistics
def test_most_probable_maximum_of_a_gaussian_record():
    """A synthesised JONSWAP elevation over its repeat period: the counted zero-upcrossing
    period matches Rice's Tz = 2 pi sqrt(m0 / m2) of its components (a record of ~150
    crossings counts them to ~2 %: tolerance 3 %), and the 3 h MPM is mean + std
    sqrt(2 ln(10800 / Tz)) with the record's own std and Tz (exact)."""
    from riser.results.recorder import most_probable_maximum
    sp = WaveSpectrum(kind="jonswap", hs=4.0, tp=10.0, components=200, seed=3)
    comp = Waves(spectrum=sp, ramp_time=0.0).components(1000.0, G, (0.0, 0.0))
    period = 2.0 * math.pi / sp.component_omegas()[1]
    t = np.arange(0.0, period, 0.1)
    x = 1000.0 + elevation(comp, 0.0, 0.0, t)
    m0 = np.sum(comp.amplitude ** 2) / 2.0
    m2 = np.sum(comp.omega ** 2 * comp.amplitude ** 2) / 2.0
    out = most_probable_maximum(t, x)
    assert out["hang_off_tension_tz"] == pytest.approx(2 * math.pi * math.sqrt(m0 / m2),
                                                       rel=0.03)
    expect = np.mean(x) + np.std(x) * math.sqrt(2 * math.log(10800.0 / out[
        "hang_off_tension_tz"]))
    assert out["hang_off_tension_mpm_3h"] == pytest.approx(expect, rel=1e-12)

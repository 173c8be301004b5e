"""Short-crested seas: a spectrum's directional spreading ([environment.waves.spectrum]
``spreading``, ``spreading_exponent``; riser/physics/waves.py) and what reads it.

(a) The spreading functions against quadrature written here: the normalisation, the
    cumulative distribution and its inverse, E[cos phi] and E[cos 2 phi] (cos2s: s / (s +
    1) and s (s - 1) / ((s + 1) (s + 2)); cosn: E[cos^2 phi] = (n + 1) / (n + 2), so E[cos
    2 phi] = n / (n + 2), by Wallis' recursion int cos^(n+2) = (n + 1) / (n + 2) int cos^n).
(b) The closed-form check: the variance of the horizontal water particle velocity u_x,
    u_z at a fixed point, sum_j a_j^2 / 2 |H_j|^2 over the components the code builds,
    against int S(omega) |H(omega)|^2 d omega times E[cos^2], E[sin^2] of the spreading;
    its convergence with the number of components (~1/N), and negative controls (a
    long-crested sea has no u_z; a wrong exponent fails; a random order of the strata
    converges like 1/sqrt(N)).
(c) The draw: a long-crested sea is the same sea as before to the bit, a spread sea has the
    long-crested sea's phases, and its directions fill every stratum once.
(d) The inputs refused with one line naming the key; the scene is 3D; a vessel's RAO
    tables must cover the spread.
(e) The peers and methods: MoorDyn-C sums the exported spread sea (its own kinematics,
    GetWavesKin, against the closed form); the BVP frequency domain takes it (slow); the
    VFIFE and the ANCF run in it, out of plane only when it is spread (slow).
"""

from __future__ import annotations

import copy
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from riser.errors import SceneError
from riser.io.moordyn.deck_from_scene import export_scene
from riser.io.scene_file import scene_from_dict
from riser.physics.waves import WaveSpectrum, Waves

from builders import catenary, line, small_pipe
from extras import needs_moordyn

ROOT = Path(__file__).resolve().parents[1]
G = 9.81
DEPTH = 100.0
#: the fixed point of the closed-form check: 20 m below the mean level
Y_POINT = 80.0


def spectrum(**keys) -> WaveSpectrum:
    base = {"kind": "jonswap", "hs": 4.0, "tp": 10.0, "heading_deg": 30.0,
            "spreading": "cos2s", "spreading_exponent": 4.0, "components": 200, "seed": 1}
    base.update(keys)
    return WaveSpectrum(**base)


def components(sp: WaveSpectrum):
    return Waves(spectrum=sp).components(DEPTH, G, (0.0, 0.0))


# ------------------------------------------------------------------ (a) the functions
def _shape(kind: str, e: float):
    """The unnormalised spreading function and its support, written here."""
    if kind == "cos2s":
        return (lambda p: math.cos(0.5 * p) ** (2.0 * e)), math.pi
    return (lambda p: math.cos(p) ** e), 0.5 * math.pi


def _integral(f, a, b):
    return quad(f, a, b, epsabs=1e-12, epsrel=1e-12, limit=200)[0]


@pytest.mark.parametrize("kind, e", [("cos2s", 1.0), ("cos2s", 4.0), ("cos2s", 75.0),
                                     ("cosn", 1.0), ("cosn", 2.0), ("cosn", 30.0)])
def test_spreading_function_against_quadrature(kind, e):
    """Density, distribution, inverse and moments against adaptive quadrature of the
    shape cos^(2s)(phi / 2) or cos^n(phi) normalised here. Quadrature to ~1e-13 and the
    incomplete beta function to ~1e-14 (scipy): tolerance 1e-10. A wrong constant (Gamma
    of the wrong argument), a cos2s integrated over +-90 deg or a cosn over +-180 would be
    off by > 1e-2."""
    sp = spectrum(spreading=kind, spreading_exponent=e)
    shape, lim = _shape(kind, e)
    total = _integral(shape, -lim, lim)
    for p in (-0.9 * lim, -0.3, 0.0, 0.2, 0.7 * lim):
        assert sp.spreading_density(p) == pytest.approx(shape(p) / total, rel=1e-10)
        F = _integral(shape, -lim, p) / total
        assert sp.spreading_cdf(p) == pytest.approx(F, abs=1e-10)
    for q in (1e-4, 0.03, 0.3, 0.5, 0.77, 0.999):            # the inverse, in probability
        p = float(sp.spreading_angle(q))
        assert _integral(shape, -lim, p) / total == pytest.approx(q, abs=1e-10)
    if kind == "cosn":
        assert sp.spreading_density(0.6 * math.pi) == 0.0             # nothing beyond 90
        assert sp.spreading_cdf(-0.6 * math.pi) == 0.0 and sp.spreading_cdf(1.9) == 1.0
    c1 = _integral(lambda p: shape(p) * math.cos(p), -lim, lim) / total
    c2 = _integral(lambda p: shape(p) * math.cos(2.0 * p), -lim, lim) / total
    assert sp.spreading_moments() == pytest.approx((c1, c2), abs=1e-10)
    if kind == "cos2s":      # the closed forms of the brief
        assert (c1, c2) == pytest.approx((e / (e + 1.0), e * (e - 1.0) / ((e + 1.0) * (e + 2.0))),
                                         abs=1e-10)
    else:                    # Wallis: E[cos^2] = (n + 1) / (n + 2)
        assert c2 == pytest.approx(e / (e + 2.0), abs=1e-10)


# ------------------------------------------------------------------ (b) the closed form
def _horizontal_velocity_variances(comp, y=Y_POINT):
    """(var u_x, var u_z, var of the horizontal speed along the heading) [m2/s2] at height
    y: sum_j a_j^2 / 2 |H_j|^2, H_j = omega cosh(k y) / sinh(k h) (cos b_j, sin b_j) (Airy,
    written here with cosh and sinh), from the code's components."""
    w, k, h = comp.omega, comp.k, comp.depth
    H = w * np.cosh(k * y) / np.sinh(k * h)
    v = 0.5 * comp.amplitude ** 2 * H ** 2
    return (float(np.sum(v * np.cos(comp.heading) ** 2)),
            float(np.sum(v * np.sin(comp.heading) ** 2)), float(np.sum(v)))


def _closed_form(sp: WaveSpectrum, lo: float, hi: float, y=Y_POINT):
    """int_lo^hi S(omega) |H(omega)|^2 d omega by adaptive quadrature, k of each omega by
    a root of omega^2 = g k tanh(k h) found here."""
    def k_of(w):
        return brentq(lambda k: G * k * math.tanh(k * DEPTH) - w * w, 1e-9, 10.0, xtol=1e-15)

    def integrand(w):
        k = k_of(w)
        return float(sp.density_at(w)) * (w * math.cosh(k * y) / math.sinh(k * DEPTH)) ** 2
    return quad(integrand, lo, hi, points=[sp.peak_omega], epsabs=0.0, epsrel=1e-11,
                limit=400)[0]


def _expected(kind, e, mean_deg):
    """(E[cos^2 theta], E[sin^2 theta]) of the direction theta = mean + phi, from the
    closed-form moments (written here): E[cos^2] = (1 + cos 2 mean E[cos 2 phi]) / 2."""
    c2 = e * (e - 1.0) / ((e + 1.0) * (e + 2.0)) if kind == "cos2s" else e / (e + 2.0)
    ex = 0.5 * (1.0 + math.cos(math.radians(2.0 * mean_deg)) * c2)
    return ex, 1.0 - ex


def _sampling_errors(kind, e, n, seeds, mean=30.0):
    """Relative errors of the directional share of var u_x and var u_z (the sum over the
    long-crested sum of the same components, against E[cos^2], E[sin^2])."""
    ex, ez = _expected(kind, e, mean)
    out = []
    for seed in seeds:
        vx, vz, v = _horizontal_velocity_variances(components(spectrum(
            spreading=kind, spreading_exponent=e, components=n, seed=seed, heading_deg=mean)))
        out.append((vx / v / ex - 1.0, vz / v / ez - 1.0))
    return np.array(out)


@pytest.mark.parametrize("kind, e", [("cos2s", 4.0), ("cosn", 2.0)])
def test_spread_sea_variance_is_the_closed_form(kind, e):
    """var u_x and var u_z at a point 20 m down under a JONSWAP (Hs 4 m, Tp 10 s) spread
    about 30 deg, 400 components, seed 1: against int S |H|^2 d omega (over the
    components' cells) times E[cos^2], E[sin^2] of the spreading.

    Tolerance: the directional sampling's error at 400 components, measured over 40 seeds
    (docs/short-crested-seas.md): RMS 3.4e-3 / 5.2e-3 (cos2s 4, u_x / u_z), 1.9e-3 /
    3.2e-3 (cosn 2), the largest 1.4e-2 (seed 1: 4.0e-3 / 6.0e-3 and 1.7e-3 / 2.9e-3);
    the frequency midpoint rule adds 2e-10 (measured: the sum of the same components
    long-crested against the integral; the integrand vanishes at both ends of the range,
    so the rule converges far faster than h^2). 2e-2 holds every seed measured; the
    moments of the wrong exponent (5 for 4, 3 for 2) are 4.4 % and 6.8 % off on u_z
    (2.7 % and 3.7 % on u_x), asserted to fail below."""
    sp = spectrum(spreading=kind, spreading_exponent=e, components=400)
    comp = components(sp)
    w, dw = sp.component_omegas()
    integral = _closed_form(sp, w[0] - 0.5 * dw, w[-1] + 0.5 * dw)
    vx, vz, v = _horizontal_velocity_variances(comp)
    assert v == pytest.approx(integral, rel=1e-7)          # midpoint rule (measured 2e-10)
    ex, ez = _expected(kind, e, 30.0)
    assert vx == pytest.approx(integral * ex, rel=2e-2)
    assert vz == pytest.approx(integral * ez, rel=2e-2)
    # negative control: the moments of the wrong exponent are outside the tolerance
    wx, wz = _expected(kind, e + 1.0, 30.0)
    assert abs(vz / (integral * wz) - 1.0) > 2e-2
    assert abs(vx / (integral * wx) - 1.0) > 2e-2 or abs(vz / (integral * wz) - 1.0) > 2e-2


def test_long_crested_sea_has_no_cross_component():
    """Negative control: the same sea long-crested at 0 deg has E[sin^2] = 0: u_z's
    variance is exactly 0 and u_x takes the whole (sin 0 = 0 to the bit); at 30 deg the
    shares are cos^2 30, sin^2 30 to round-off."""
    vx, vz, v = _horizontal_velocity_variances(components(spectrum(spreading="none",
                                                                   spreading_exponent=None,
                                                                   heading_deg=0.0)))
    assert vz == 0.0 and vx == v
    vx, vz, v = _horizontal_velocity_variances(components(spectrum(spreading="none",
                                                                   spreading_exponent=None)))
    assert vx / v == pytest.approx(0.75, rel=1e-13) and vz / v == pytest.approx(0.25, rel=1e-13)


def test_directional_sampling_converges_like_one_over_n():
    """The stratified directions in the Kronecker order converge like 1/N: the RMS error
    (seeds 1-20) of the directional share falls by > 4 from 200 to 1600 components
    (measured 4.8 for cos2s 4: 6.0e-3 -> 1.24e-3 on u_x; 1/N would give 8, 1/sqrt(N)
    2.8, and the Latin hypercube below measures 3.4 over 40 seeds); the same strata in a
    random order (a Latin hypercube) are asserted at least 3 times worse at 1600
    (measured 21 times: 2.6e-2)."""
    seeds = range(1, 21)
    e200 = np.sqrt(np.mean(_sampling_errors("cos2s", 4.0, 200, seeds) ** 2, axis=0))
    e1600 = np.sqrt(np.mean(_sampling_errors("cos2s", 4.0, 1600, seeds) ** 2, axis=0))
    assert np.all(e200 / e1600 > 4.0), (e200, e1600)
    # the Latin hypercube: the code's own quantiles, in a random order of the strata
    sp = spectrum(components=1600)
    w, dw = sp.component_omegas()
    k = np.array([brentq(lambda kk: G * kk * math.tanh(kk * DEPTH) - x * x, 1e-9, 10.0)
                  for x in w])
    v = sp.density_at(w) * dw * (w * np.cosh(k * Y_POINT) / np.sinh(k * DEPTH)) ** 2
    ex = _expected("cos2s", 4.0, 30.0)[0]
    lhs = []
    for seed in seeds:
        rng = np.random.default_rng(seed)
        q = (rng.permutation(w.size) + rng.uniform(size=w.size)) / w.size
        th = math.radians(30.0) + sp.spreading_angle(q)
        lhs.append(np.sum(v * np.cos(th) ** 2) / np.sum(v) / ex - 1.0)
    assert math.sqrt(np.mean(np.square(lhs))) > 3.0 * e1600[0]


# ------------------------------------------------------------------ (c) the draw
def test_long_crested_sea_is_the_same_to_the_bit_and_spread_keeps_its_phases():
    """spreading = 'none' draws nothing more: the phases are PCG64(seed)'s first N uniform
    draws on [0, 2 pi) (written here), every heading the sea's. A spread sea of the same
    seed has the same amplitudes, frequencies and phases; only the headings differ, and
    its directions fill each of the N strata of probability exactly once."""
    n = 300
    flat = components(spectrum(spreading="none", spreading_exponent=None, components=n, seed=7))
    rng = np.random.Generator(np.random.PCG64(7))
    assert np.array_equal(flat.phase, rng.uniform(0.0, 2.0 * math.pi, n))
    assert np.all(flat.heading == math.radians(30.0))
    for kind, e in (("cos2s", 4.0), ("cosn", 2.0)):
        sp = spectrum(spreading=kind, spreading_exponent=e, components=n, seed=7)
        spread = components(sp)
        for name in ("amplitude", "omega", "k", "phase"):
            assert np.array_equal(getattr(spread, name), getattr(flat, name)), name
        q = sp.spreading_cdf(spread.heading - math.radians(30.0))
        assert sorted(np.floor(q * n).astype(int)) == list(range(n))
        again = components(sp)
        assert np.array_equal(again.heading, spread.heading)          # reproducible
        other = components(sp.replace(seed=8))
        assert not np.array_equal(other.heading, spread.heading)


# ------------------------------------------------------------------ (d) inputs, scene
def _data(spec: dict, **tables) -> dict:
    return catenary(environment={"water_depth": 200.0,
                                 "waves": {"spectrum": {"kind": "jonswap", "hs": 2.0,
                                                        "tp": 9.0, **spec}}}, **tables)


@pytest.mark.parametrize("spec, key, words", [
    ({"spreading": "cos2s"}, "environment.waves.spectrum.spreading_exponent",
     "required with spreading = 'cos2s'"),
    ({"spreading_exponent": 2.0}, "environment.waves.spectrum.spreading_exponent",
     "only with spreading"),
    ({"spreading": "cosn", "spreading_exponent": 0.5},
     "environment.waves.spectrum.spreading_exponent", "must be >= 1"),
    ({"spreading": "cos2s", "spreading_exponent": 150.0},
     "environment.waves.spectrum.spreading_exponent", "must be <= 100"),
    ({"spreading": "cos4"}, "environment.waves.spectrum.spreading", "must be one of"),
    ({"spreading": "cosn", "spreading_exponent": "2"},
     "environment.waves.spectrum.spreading_exponent", "must be a number"),
])
def test_bad_spreading_one_line_naming_the_key(spec, key, words):
    with pytest.raises(SceneError) as err:
        scene_from_dict(_data(spec), "w.toml")
    text = str(err.value)
    assert err.value.key == key and words in text and "\n" not in text, text


def test_spread_sea_makes_the_scene_3d():
    flat = scene_from_dict(_data({}), "w.toml")
    assert flat.is_planar
    spread = scene_from_dict(_data({"spreading": "cosn", "spreading_exponent": 2.0}), "w.toml")
    assert not spread.is_planar and spread.statics_planar
    assert spread.out_of_plane()[0] == "environment.waves.spectrum.spreading"


def _rao(heading):
    dofs = {d: [0.1, 0.1] for d in ("surge", "sway", "heave", "roll", "pitch", "yaw")}
    phases = {f"{d}_phase_deg": [0.0, 0.0] for d in dofs}
    return {"heading_deg": heading, "periods": [2.0, 30.0], **dofs, **phases}


def test_vessel_rao_tables_must_cover_the_spread():
    """One RAO table covers its own heading only: a spread sea about it is refused naming
    vessel.raos and the spread; tables every 90 deg cover any direction (within 45 deg)."""
    def data(headings):
        d = _data({"spreading": "cos2s", "spreading_exponent": 4.0, "heading_deg": 0.0},
                  dynamics={"duration": 30.0})
        d["vessel"] = {"raos": [_rao(h) for h in headings]}
        return d
    with pytest.raises(SceneError) as err:
        scene_from_dict(data([0.0]), "w.toml")
    assert err.value.key == "vessel.raos" and "spread sea (cos2s about 0 deg)" in str(err.value)
    sc = scene_from_dict(data([0.0, 90.0, 180.0, 270.0]), "w.toml")
    assert not sc.is_planar


# ------------------------------------------------------------------ (e) MoorDyn, methods
def _moordyn_scene():
    waves = {"spectrum": {"kind": "jonswap", "hs": 2.0, "tp": 8.0, "components": 24,
                          "heading_deg": 20.0, "spreading": "cos2s",
                          "spreading_exponent": 2.0, "seed": 3},
             "origin": [35.0, -12.0], "ramp_time": 0.0}
    env = {"gravity": G, "water_density": 1025.0, "water_depth": 60.0, "waves": waves}
    return scene_from_dict(line(70.0, (10.0, 0.0), (50.0, 50.0), line_type=small_pipe(),
                                environment=env))


def test_moordyn_export_writes_each_components_direction():
    """The deck's wave_frequencies.txt holds one row per component with MoorDyn's
    direction beta = -heading (its Y = -z), so the rows carry the spread: as many distinct
    directions as components, spanning the draw."""
    scene = _moordyn_scene()
    ex = export_scene(scene, segment_length=7.0)
    rows = np.array([[float(v) for v in ln.split()] for ln in ex.wave_frequencies.splitlines()])
    comp = scene.waves.components(60.0, G, (50.0, 0.0))
    order = np.argsort(comp.omega, kind="stable")
    assert rows.shape == (comp.size + 1, 4)
    assert np.allclose(rows[1:, 3], np.remainder(-comp.heading[order] + math.pi,
                                                 2.0 * math.pi) - math.pi, atol=1e-12)
    assert len(set(rows[1:, 3])) == comp.size
    assert any("short-crested" in n for n in ex.notes)


@needs_moordyn
def test_moordyn_sums_the_exported_spread_sea(tmp_path):
    """MoorDyn-C 2.7's own kinematics of the exported spread sea (GetWavesKin: elevation
    and velocity at points and times) against the closed form of the scene's components
    (Airy, Wheeler, written here): each component's direction is honoured. MoorDyn's
    wave number is its own root (4e-8): tolerance 1e-6 of the largest value, as
    tests/test_moordyn_waves.py measures; a direction mirrored (beta = +heading) moves u_z
    by its whole size."""
    import moordyn
    scene = _moordyn_scene()
    ex = export_scene(scene, segment_length=7.0)
    (tmp_path / "deck.dat").write_text(ex.text)
    (tmp_path / "wave_frequencies.txt").write_text(ex.wave_frequencies)
    comp = scene.waves.components(60.0, G, (50.0, 0.0))
    h = comp.depth
    system = moordyn.Create(str(tmp_path / "deck.dat"))
    moordyn.SetVerbosity(system, moordyn.LEVEL_ERR)
    try:
        assert moordyn.Init(system, [], []) == 0
        waves = moordyn.GetWaves(system)
        worst, scale = np.zeros(2), np.zeros(2)
        for x, y, z in ((0.0, 30.0, 0.0), (35.0, 50.0, -12.0), (80.0, 57.0, 30.0)):
            psi = (-comp.k * ((x - comp.origin[0]) * np.cos(comp.heading)
                              + (z - comp.origin[1]) * np.sin(comp.heading)) - comp.phase)
            eta = float(np.sum(comp.amplitude * np.cos(psi)))          # t = 0
            ys = min(h * y / (h + eta), h)
            uh = comp.omega * comp.amplitude * np.cosh(comp.k * ys) / np.sinh(comp.k * h) \
                * np.cos(psi)
            u = np.array([np.sum(uh * np.cos(comp.heading)),
                          np.sum(-comp.omega * comp.amplitude * np.sinh(comp.k * ys)
                                 / np.sinh(comp.k * h) * np.sin(psi)),
                          np.sum(uh * np.sin(comp.heading))])
            u_md, _, zeta, _ = moordyn.GetWavesKin(waves, x, -z, y - h)
            u_md = np.array([u_md[0], u_md[2], -u_md[1]])
            worst = np.maximum(worst, [abs(zeta - eta), np.max(np.abs(u_md - u))])
            scale = np.maximum(scale, [np.sum(comp.amplitude),
                                       np.sum(comp.omega * comp.amplitude
                                              / np.tanh(comp.k * h))])
            assert abs(u[2]) > 1e-3 * scale[1]          # the spread's u_z is there
        assert np.all(worst < 1e-6 * scale), worst / scale
    finally:
        moordyn.Close(system)


def _jumper(spread: bool, duration: float = 5.0) -> dict:
    data = tomllib.loads((ROOT / "verification/scenes/waves/jumper-sea.toml").read_text())
    sp = data["environment"]["waves"]["spectrum"]
    sp.update(components=30, hs=4.0)
    if spread:
        sp.update(spreading="cos2s", spreading_exponent=2.0)
    data["environment"]["waves"]["ramp_time"] = 2.0
    data["dynamics"] = {"duration": duration, "output_interval": 0.1, "save_states": True}
    return data


@pytest.mark.slow
def test_bvp_sea_response_takes_a_spread_sea():
    """The frequency domain's sea response sums each component with its own heading
    (bvp/frequency/wave_loads.py: u_z = u_h sin b; the out-of-plane family): a spread sea
    is not refused, its out-of-plane standard deviation is there, and a long-crested head
    sea has none (exactly 0)."""
    from bvp.frequency.sea_response import solve_sea
    stds = {}
    for spread in (False, True):
        r = solve_sea(scene_from_dict(_jumper(spread), "jumper.toml"), intervals=600)
        assert r.converged, r.message
        stds[spread] = float(np.max(r.std["dz"])), float(np.max(r.std["dy"]))
    assert stds[False][0] == 0.0
    assert stds[True][0] > 0.2 * stds[True][1]       # measured 1.2 x the in-plane dy


@pytest.mark.slow
def test_vfife_and_ancf_run_in_a_spread_sea():
    """5 s of the jumper in a spread JONSWAP (Hs 4 m, 30 components, cos2s s = 2): both
    time domains run in 3D (Scene.is_planar False), finite, and the line moves out of its
    plane; the same sea long-crested at 0 deg moves it in plane only (z exactly constant).
    Both sum each component with its own heading (vfife.kernels.wave_pass, ancf.waves.airy):
    their out-of-plane motions agree within 30 % at s = 120 m (measured 8 %: two
    independent meshes and integrators over 5 s; a component heading dropped by one of
    them, u_z = 0, would leave that method's line in plane)."""
    import ancf
    import vfife
    peaks = {}
    for spread in (False, True):
        sc = scene_from_dict(_jumper(spread), "jumper.toml")
        assert sc.is_planar is (not spread)
        for name, mod in (("vfife", vfife), ("ancf", ancf)):
            res = mod.solve(sc)
            assert res.converged, res.message
            st = res.dynamics.states
            assert np.all(np.isfinite(st["x"]))
            dz = st["x"][:, :, 2] - st["x"][0, :, 2]
            dy = st["x"][:, :, 1] - st["x"][0, :, 1]
            if not spread:
                assert np.max(np.abs(dz)) == 0.0, name
                continue
            assert np.max(np.abs(dz)) > 0.1 * np.max(np.abs(dy)), name
            peaks[name] = np.max(np.abs([np.interp(120.0, st["s"], row) for row in dz]))
    assert peaks["ancf"] == pytest.approx(peaks["vfife"], rel=0.3), peaks

"""VFIFE modal analysis (vfife/modal/modes.py, vfife/modal/tangent.py): closed forms, the added mass,
the free vibration of the time-domain model, refusals and the scr-steel riser.

Every tolerance says where it comes from. The lumped-mass chain's own dispersion is
known in closed form (a string of N elements: f_n = (N / (pi L)) sqrt(T/mu) sin(n pi /
2N)), so most checks compare with the discrete formula tightly and with the continuum
within the discretisation error.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import builders
import vfife
from riser.results.modes import PLANES
from verification.catalog import resolve
from vfife.modal.modes import free_vibration, solve_modes


def straight(length, span, *, EA, EI, mass=10.0, D=0.02, d=0.01, ca=0.0, hydro=None,
             h=1.0):
    """A neutrally buoyant line between fixed ends at the same height, ``span`` apart."""
    lt = {"outer_diameter": D, "inner_diameter": d, "mass_per_length": mass,
          "axial_stiffness": EA, "bending_stiffness": EI, "added_mass": ca}
    if hydro:
        lt["hydro_diameter"] = hydro
    return builders.scene(builders.straight(length, span, height=50.0, name="straight",
                                            line_type=lt, vfife={"element_length": h}))


def catenary(tolerance=1.0e-6, current=None):
    """150 m of line from an anchor on an elastic seabed to a hang-off 60 m up, 2 m
    elements, relaxed to ``tolerance`` element weights."""
    return builders.scene(builders.catenary(
        name="catenary", environment={"current": current} if current else None,
        vfife={"element_length": 2.0, "static_tolerance": tolerance}))


def freqs(res, plane):
    return np.array([m.frequency_hz for m in res.family(plane)])


# ------------------------------------------------------------------ closed forms
def test_taut_string():
    """f_n = n / (2L) sqrt(T / mu), mu the mass per stretched length."""
    L0, EA, m, EI, T = 100.0, 1e7, 10.0, 1.0, 1e4
    L = L0 * (1.0 + T / EA)
    N = 100
    sc = straight(L0, L, EA=EA, EI=EI, mass=m)
    res = solve_modes(sc, 10)
    assert res.converged, res.message
    mu = m * L0 / L
    n = np.arange(1, 11)
    x = n * math.pi / (2 * N)
    f_cont = n / (2 * L) * math.sqrt(T / mu)
    f_disc = N / (math.pi * L) * math.sqrt(T / mu) * np.sin(x)
    for plane in PLANES:
        f = freqs(res, plane)
        # the lumped chain's dispersion sin(x)/x - 1 ~ -x^2/6 (-0.41 % at n = 10): within it
        # (+5 %) and 1e-5 for the terms below
        assert np.all(np.abs(f / f_cont - 1.0) <= 1.05 * x ** 2 / 6 + 1e-5), plane
        # the discrete chain exactly, but for the bending stiffness (EI/T)(n pi/L)^2 / 2
        # <= 4.9e-6 and the rotary inertia -(n pi r_g/L)^2 / 2 >= -1.5e-6: 1e-5
        assert np.all(np.abs(f / f_disc - 1.0) < 1e-5), plane
    # the in-plane and out-of-plane strings are the same string (transverse modes only:
    # the first axial mode is sqrt(EA/T) ~ 32 times higher)
    assert np.allclose(freqs(res, "in_plane"), freqs(res, "out_of_plane"), rtol=1e-9)
    assert res.info["asymmetry"] < 1e-8 and res.info["coupling"] == 0.0


def test_pinned_beam_and_rotary_inertia():
    """omega_n = (n pi / L)^2 sqrt(EI / m), with the rotary inertia of the (Rayleigh) beam:
    x (1 - (n pi r_g / L)^2 / 2), r_g^2 = J' / m the diametral gyration radius."""
    L, EI, m, D, d, h = 10.0, 1e4, 10.0, 0.02, 0.01, 0.1
    sc = straight(L, L, EA=1e10, EI=EI, mass=m, D=D, d=d, h=h)
    static = vfife.solve(sc)
    assert static.converged
    n = np.arange(1, 11)
    k = n * math.pi / L
    f_eb = k ** 2 * math.sqrt(EI / m) / (2 * math.pi)
    rg2 = 0.5 * (D * D + d * d) / 8.0           # (m_wall (D^2 + d^2) / 8) / 2 / m
    theta = n * math.pi * h / L
    out = {}
    for scale in (1.0, 4.0):
        res = solve_modes(sc, 10, static=static, rot_scale=scale)
        assert res.converged, res.message
        f_rayleigh = f_eb * (1.0 - 0.5 * scale * k ** 2 * rg2)
        for plane in PLANES:
            f = freqs(res, plane)
            # lumped-mass cubic elements: -theta^4/1440 to leading order (theta = n pi h /
            # L; -6.8e-6 at n = 10); twice that
            assert np.all(np.abs(f / f_rayleigh - 1.0) <= theta ** 4 / 720 + 1e-9), plane
        out[scale] = freqs(res, "out_of_plane")
    # x4 rotational inertia (the dynamics' default) shifts by 3/2 (k r_g)^2 (-4.6e-4 at
    # n = 10 here; ~1e-7 for riser modes, which are 100 times longer than this beam)
    shift = out[4.0] / out[1.0] - 1.0
    assert shift == pytest.approx(-1.5 * k ** 2 * rg2, rel=0.02)


def test_added_mass_acts_normal_to_the_axis():
    """Transverse modes scale by sqrt(m / (m + m_a)), the axial ones do not move."""
    L0, EA, m, T = 100.0, 2e5, 10.0, 1e4
    L = L0 * (1.0 + T / EA)
    N = 50
    base = dict(EA=EA, EI=1.0, mass=m, hydro=0.1, h=L0 / N)
    dry = solve_modes(straight(L0, L, ca=0.0, **base), 10)
    wet = solve_modes(straight(L0, L, ca=1.0, **base), 10)
    ma = 1025.0 * math.pi / 4 * 0.1 ** 2          # C_a rho pi D_h^2 / 4 [kg/m]
    ratio = math.sqrt(m / (m + ma))
    # out of plane every mode is transverse; K is the same, M scales exactly on the
    # translations (the rotary inertia, unscaled, is 1e-6 of the kinetic energy): 1e-6
    assert np.allclose(freqs(wet, "out_of_plane") / freqs(dry, "out_of_plane"), ratio,
                       rtol=1e-6)

    def axial(res):
        return [mo for mo in res.family("in_plane")
                if np.max(np.abs(mo.shape[:, 0])) > np.max(np.abs(mo.shape[:, 1]))]

    ax_dry, ax_wet = axial(dry), axial(wet)
    # sqrt(EA/T) = 4.5: the first axial mode lies among the first 10 in-plane modes
    assert ax_dry and ax_wet
    # axial: the chain's formula f = (N / (pi L0)) sqrt(EA/m) sin(pi / 2N) exactly (the
    # element's axial stiffness is EA/l0 along the chord); 1e-6 for the eigensolver
    f_ax = N / (math.pi * L0) * math.sqrt(EA / m) * math.sin(math.pi / (2 * N))
    assert ax_dry[0].frequency_hz == pytest.approx(f_ax, rel=1e-6)
    assert ax_wet[0].frequency_hz == pytest.approx(f_ax, rel=1e-6)
    tr_dry = [mo.frequency_hz for mo in dry.family("in_plane") if mo not in ax_dry]
    tr_wet = [mo.frequency_hz for mo in wet.family("in_plane") if mo not in ax_wet]
    k = min(len(tr_dry), len(tr_wet))
    assert np.allclose(np.array(tr_wet[:k]) / np.array(tr_dry[:k]), ratio, rtol=1e-6)


# ------------------------------------------------------------------ time domain
def test_free_vibration_matches_the_eigenfrequencies():
    """The time-domain model released in mode 1 (in plane: with seabed contact and added
    mass; out of plane) vibrates at the eigenfrequency. Default rotational inertia of the
    dynamics (x4), the eigenproblem with the same."""
    sc = catenary()
    static = vfife.solve(sc)
    assert static.converged, static.message
    modes = solve_modes(sc, 1, static=static)
    for plane in PLANES:
        fv = free_vibration(sc, plane, 1, static=static, periods=6)
        assert fv["rot_scale"] == sc.vfife.rotational_inertia_scale_dynamics
        # time integration (omega dt)^2 / 24 < 1e-7, zero crossings over 5 periods sampled
        # 40 times a period ~1e-6, linearisation about a state relaxed to 1e-6 element
        # weights ~1e-6 (measured +2.6e-6 in plane, -7.6e-7 out of plane; relaxed to the
        # default 1e-3 element weights: 9e-5 and 1.1e-4): 2e-5
        assert abs(fv["rel_diff"]) < 2e-5, (plane, fv)
        # the x4 rotational inertia against the physical one (solve_modes' default):
        # -3/2 (k r_g)^2, measured -4.4e-6 in plane and -7e-7 out of plane here: 1e-5
        f1 = modes.family(plane)[0].frequency_hz
        assert fv["modal_frequency_hz"] == pytest.approx(f1, rel=1e-5)
        assert fv["modal_frequency_hz"] < f1


def test_free_vibration_scr_steel():
    """The same on the scr-steel riser at 5 m elements (~2 s of time integration)."""
    sc = resolve("scr-steel")
    sc = sc.replace(vfife=sc.vfife.replace(element_length=5.0, static_tolerance=1e-5))
    static = vfife.solve(sc)
    for plane in PLANES:
        fv = free_vibration(sc, plane, 1, static=static, periods=4)
        # as above (measured 9e-7 in plane, 1e-7 out of plane; 2e-5 when relaxed to the
        # default 1e-3): 1e-5
        assert abs(fv["rel_diff"]) < 1e-5, (plane, fv)


# ------------------------------------------------------------------ contract, refusals
def test_scr_steel_ten_plus_ten_modes():
    sc = resolve("scr-steel")
    sc = sc.replace(vfife=sc.vfife.replace(element_length=5.0))
    res = solve_modes(sc, 10)
    assert res.converged, res.message
    assert res.method == "vfife" and res.scene == "scr-steel"
    assert [m.plane for m in res.modes] == ["in_plane"] * 10 + ["out_of_plane"] * 10
    for plane in PLANES:
        fam = res.family(plane)
        assert [m.number for m in fam] == list(range(1, 11))
        f = freqs(res, plane)
        assert np.all(np.diff(f) > 0.0) and f[0] > 0.0
        for m in fam:
            assert m.shape.shape == (len(m.s), 3) and m.s[0] == 0.0
            assert m.s[-1] == pytest.approx(2000.0)
            assert np.max(np.abs(m.shape)) == pytest.approx(1.0)
            assert m.shape.ravel()[np.argmax(np.abs(m.shape))] == pytest.approx(1.0)
            if plane == "in_plane":
                assert np.all(m.shape[:, 2] == 0.0)
            else:
                assert np.all(m.shape[:, :2] == 0.0)
            assert np.all(m.shape[[0, -1]] == 0.0)        # fixed ends
    # the tangent stiffness is the Hessian of an energy: symmetric to round-off
    assert res.info["asymmetry"] < 1e-8
    assert res.info["coupling"] == 0.0 and res.info["negative_eigenvalues"] == 0
    assert res.info["contact_nodes"] > 50          # ~500 m on the seabed, 5 m elements
    assert res.wall_time_s < 5.0


def test_refuses_wang_form_and_out_of_plane_state():
    res = solve_modes(resolve("wang2014-baseline"))
    assert res.status.value == "refused" and "fixed ends" in res.message and not res.modes
    sc = catenary(1e-3, current={"heights": [0.0], "speeds": [0.5], "heading_deg": 90.0})
    # a 3D static state: the coupled family (tests/test_vfife_modes_3d.py), or refused when
    # the two planar families are asked for
    res = solve_modes(sc, 2, coupled=False)
    assert res.status.value == "refused" and "not planar" in res.message
    res = solve_modes(sc, 2)
    assert res.converged and {m.plane for m in res.modes} == {"coupled"}, res.message
    with pytest.raises(ValueError, match="count"):
        solve_modes(catenary(1e-3), 0)

"""BVP modal analysis (bvp/modal/modes.py): closed forms of a taut string, a pinned beam and the
normal-only added mass, a real riser, and the refusals.

Every closed form is the exact eigenvalue of a straight, weightless line between pinned,
moment-free ends: in the model (moment on the unstretched length, stretch e = 1 + T/EA)
a transverse mode of wavenumber k = n pi / L0 on the unstretched length L0 has

    omega^2 = (EI k^4 + e T k^2) / (e^2 m_n),

the textbook pinned beam under tension written with the stretched length L = e L0 and the
mass per stretched length m_n / e (f = n/(2L) sqrt(T/(m_n/e)) for EI -> 0), and an axial
mode omega = k sqrt(EA / m). The modes are computed by solve_bvp at its default tolerance
1e-6 on the relative collocation residual; the frequency converges much faster than the
residual (a refinement to 1e-8 changes the scr-steel frequencies by < 1e-9), so 1e-6 is
a safe relative tolerance: it would catch any modelling error (a missing e, m instead of
m + m_a: percent-level) and is 100x the collocation's observed frequency error.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import builders
import bvp
from bvp.modal.modes import solve_modes
from riser.results.modes import PLANES
from verification.catalog import resolve

RTOL = 1e-6          # see the module docstring


def straight_line(length, span, *, EA=1e8, EI=1.0, mass=10.0, D=0.2, Ca=0.0, vfife=None):
    """A weightless (submerged weight 0) line stretched horizontally between fixed ends
    at height 10 m, no seabed."""
    lt = {"outer_diameter": D, "mass_per_length": mass, "axial_stiffness": EA,
          "bending_stiffness": EI, "added_mass": Ca, "max_strain": 0.1}
    return builders.scene(builders.straight(length, span, height=10.0, line_type=lt,
                                            vfife=vfife or None))


def beam_frequencies(n, L0, T, EA, EI, m_n):
    """Exact transverse frequencies [Hz] of the model (module docstring)."""
    k = np.asarray(n) * math.pi / L0
    e = 1.0 + T / EA
    return np.sqrt((EI * k ** 4 + e * T * k ** 2) / (e * e * m_n)) / (2.0 * math.pi)


def frequencies(res, plane):
    return np.array([m.frequency_hz for m in res.family(plane)])


def test_taut_string():
    """f_n = n/(2L) sqrt(T/m) with L and m of the stretched string (docs/references.md,
    Modal analysis): strain 1e-3 of EA = 1e8 N gives T = 1e5 N; EI = 1 N m2 raises f by
    (n pi/L)^2 EI/(2T) < 2e-7 for n <= 6, inside RTOL. Both families are the same string."""
    L0, span, EA, m = 100.0 / 1.001, 100.0, 1e8, 10.0
    res = solve_modes(straight_line(L0, span, EA=EA, mass=m), 6)
    assert res.converged, res.message
    T = EA * (span / L0 - 1.0)
    n = np.arange(1, 7)
    string = n / (2.0 * span) * np.sqrt(T / (m * L0 / span))
    assert np.max(beam_frequencies(n, L0, T, EA, 1.0, m) / string - 1.0) < 2e-7   # EI
    for plane in PLANES:
        np.testing.assert_allclose(frequencies(res, plane), string, rtol=RTOL)
        # shapes: sin(n pi s / L0) along y (in plane) or z (out of plane)
        mode = res.family(plane)[1]
        comp = 1 if plane == "in_plane" else 2
        ref = np.sin(2 * math.pi * mode.s / L0)
        assert abs(np.dot(mode.shape[:, comp], ref)) / (
            np.linalg.norm(mode.shape[:, comp]) * np.linalg.norm(ref)) > 1 - 1e-6


def test_pinned_beam():
    """omega_n = (n pi / L)^2 sqrt(EI/m) (docs/references.md, Modal analysis): ends at the
    unstretched length, so T = 0 (the BVP gives |T| ~ 1e-9 N, a relative effect T L^2/EI ~
    1e-9); EA = 1e9 N puts the first axial mode (158 Hz) far above the tenth bending mode
    (0.5 Hz)."""
    L, EI, m = 100.0, 1e4, 10.0
    res = solve_modes(straight_line(L, L, EA=1e9, EI=EI), 6)
    assert res.converged, res.message
    n = np.arange(1, 7)
    exact = (n * math.pi / L) ** 2 * math.sqrt(EI / m) / (2.0 * math.pi)
    for plane in PLANES:
        np.testing.assert_allclose(frequencies(res, plane), exact, rtol=RTOL)


def test_clamped_ends():
    """[vfife] clamped_ends fixes the rotation: the clamped-clamped beam, omega_n =
    (beta_n L)^2 / L^2 sqrt(EI/m) with beta_n L the roots of cos x cosh x = 1 (4.7300,
    7.8532, 10.9956; Blevins, Formulas for natural frequency and mode shape, table 8-1),
    and the clamped-pinned beam (tan x = tanh x: 3.9266, 7.0686, 10.2102)."""
    from scipy.optimize import brentq
    L, EI, m = 100.0, 1e4, 10.0
    # characteristic equation and the bracket of its n-th root (clear of tan's poles)
    roots = {"both": (lambda x: math.cos(x) * math.cosh(x) - 1.0, 0.5),
             "bottom": (lambda x: math.tan(x) - math.tanh(x), 0.25)}
    for ends, (f, shift) in roots.items():
        clamped = ["bottom", "top"] if ends == "both" else ["bottom"]
        res = solve_modes(straight_line(L, L, EA=1e9, EI=EI, vfife={"clamped_ends": clamped}),
                          3)
        assert res.converged, res.message
        beta = [brentq(f, (n + shift) * math.pi - 0.5, (n + shift) * math.pi + 0.5)
                for n in range(1, 4)]
        exact = np.array(beta) ** 2 / L ** 2 * math.sqrt(EI / m) / (2.0 * math.pi)
        for plane in PLANES:
            np.testing.assert_allclose(frequencies(res, plane), exact, rtol=RTOL)


def test_added_mass_is_normal_only():
    """A taut string with C_a = 1: its transverse modes (both planes) carry m + m_a, its
    axial mode m alone. Strain 5 % (T = 5e6 N) brings the first axial mode, f = 1/(2 L0)
    sqrt(EA/m) = 16.6 Hz, down to the 10th in-plane mode (the 10th out-of-plane mode is
    transverse, 17.6 Hz); EI = 1e3 N m2 keeps the bending layer sqrt(EI/T) = 14 mm
    resolvable (its correction is in the closed form)."""
    L0, span, EA, EI, m, D = 100.0 / 1.05, 100.0, 1e8, 1e3, 10.0, 0.2
    sc = straight_line(L0, span, EA=EA, EI=EI, mass=m, D=D, Ca=1.0)
    ma = 1025.0 * math.pi / 4.0 * D * D
    res = solve_modes(sc, 10)
    assert res.converged, res.message
    T = EA * (span / L0 - 1.0)
    bending = beam_frequencies(np.arange(1, 11), L0, T, EA, EI, m + ma)
    np.testing.assert_allclose(frequencies(res, "out_of_plane"), bending, rtol=RTOL)
    f_in = frequencies(res, "in_plane")
    np.testing.assert_allclose(f_in[:9], bending[:9], rtol=RTOL)
    axial = 1.0 / (2.0 * L0) * math.sqrt(EA / m)
    assert f_in[9] == pytest.approx(axial, rel=RTOL)
    shape = res.family("in_plane")[9].shape
    assert np.max(np.abs(shape[:, 1])) < 1e-6 and np.max(np.abs(shape[:, 0])) == 1.0


def test_shallow_sag_cable_irvine():
    """A sagging elastic cable (Irvine & Caughey 1974; Irvine, Cable Structures, 1981,
    ch. 4): horizontal tension H, c = sqrt(H/m), span l; out-of-plane and antisymmetric
    in-plane modes are strings, omega = n pi c / l and 2 n pi c / l; the symmetric
    in-plane ones solve tan(x/2) = x/2 - (4/lambda^2)(x/2)^3, x = omega l / c, with
    lambda^2 = (w l / H)^2 l / (H L_e / EA), L_e = int (ds/dx)^3 dx. This checks the
    in-plane terms of a curved line: the symmetric modes carry the stretching coupling
    (lambda^2 = 130 here: the first is 6 % below its inextensible value and 2.7x the
    string's). Tolerance: the theory drops terms of order (d/l)^2; at sag d/l = 0.037 the
    largest difference is 0.7 % (2.3x larger at d/l = 0.049, as (d/l)^2): 1.5 %."""
    from scipy.optimize import brentq
    l, w, m, EA = 100.0, 100.0, 10.0, 5e7
    lt = {"outer_diameter": 0.1, "mass_per_length": m, "added_mass": 0.0,
          "axial_stiffness": EA, "bending_stiffness": 10.0}
    sc = builders.scene(builders.line(100.3, (0.0, 50.0), (l, 50.0), line_type=lt,
                                      submerged_weight=w))
    static = bvp.solve(sc)
    assert static.converged, static.message
    p = static.profile
    H = float(np.mean(p.tension * np.cos(p.theta)))
    assert 0.03 < (50.0 - p.y.min()) / l < 0.04                      # shallow sag
    lam2 = (w * l / H) ** 2 * l * EA / (H * np.trapezoid(np.cos(p.theta) ** -3, p.x))
    assert 100.0 < lam2 < 160.0
    res = solve_modes(sc, 6, static=static)
    assert res.converged, res.message
    c = math.sqrt(H / m)

    def g(x):
        return math.tan(x / 2) - x / 2 + 4.0 / lam2 * (x / 2) ** 3

    sym = [brentq(g, (2 * k + 1) * math.pi + 1e-9, (2 * k + 3) * math.pi - 1e-9)
           for k in range(3)]
    anti = [2 * n * math.pi for n in (1, 2, 3)]
    in_plane = np.sort(np.array(sym + anti)) * c / l / (2 * math.pi)
    out_of_plane = np.arange(1, 7) * math.pi * c / l / (2 * math.pi)
    np.testing.assert_allclose(frequencies(res, "in_plane"), in_plane, rtol=0.015)
    np.testing.assert_allclose(frequencies(res, "out_of_plane"), out_of_plane, rtol=0.015)


def test_scr_steel_modes():
    """A real riser (2000 m SCR on an elastic seabed): 10 + 10 modes, each refined by
    solve_bvp from its box-scheme guess (MAC > 0.9 checked inside), increasing."""
    sc = resolve("scr-steel")
    static = bvp.solve(sc)
    res = solve_modes(sc, 10, static=static)
    assert res.converged, res.message
    for plane in PLANES:
        fam = res.family(plane)
        assert [m.number for m in fam] == list(range(1, 11))
        f = frequencies(res, plane)
        assert np.all(np.diff(f) > 0.0) and f[0] > 0.0
        for mode in fam:
            assert mode.shape.shape == (mode.s.size, 3)
            assert np.max(np.abs(mode.shape)) == 1.0 and np.all(np.diff(mode.s) > 0)
            other = [0, 1] if plane == "out_of_plane" else [2]
            assert np.all(mode.shape[:, other] == 0.0)
    # the box-scheme guess (second order, ~0.7 m grid) is within 1e-4 of the refined value
    assert all(abs(c["frequency_hz"] / c["guess_hz"] - 1.0) < 1e-4 for c in res.info["modes"])
    assert res.info["max_collocation_residual"] <= 1e-6 * 1.01
    # the contact zone is a piece of its own (the spring k acts there only)
    assert res.info["pieces"][0][2] and not res.info["pieces"][-1][2]


def test_refusals():
    res = solve_modes(resolve("wang2014-baseline"))
    assert res.status.value == "refused" and "fixed ends" in res.message and not res.modes
    sc = straight_line(100.0 / 1.001, 100.0)
    cur = builders.scene(builders.line(
        99.9, (0.0, 10.0), (100.0, 10.0),
        line_type={"outer_diameter": 0.2, "mass_per_length": 10.0, "axial_stiffness": 1e8,
                   "bending_stiffness": 1.0},
        environment={"current": {"heights": [0.0, 10.0], "speeds": [1.0, 1.0],
                                 "heading_deg": 90.0}}))
    # a 3D static state is analysed: the coupled family (tests/test_bvp_modes_3d.py)
    res = solve_modes(cur, 2)
    assert res.converged and {m.plane for m in res.modes} == {"coupled"}, res.message
    with pytest.raises(ValueError):
        solve_modes(sc, 0)

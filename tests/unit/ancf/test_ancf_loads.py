"""The ANCF's state-dependent loads (seabed contact, drag on the relative velocity in a
sheared current, the sea surface's band at y = 0.3 m with its lost buoyancy) and their
linearisation against central differences of the loads
themselves, in 2D and 3D: dF/dq (through the tangent and the current's height) and
dF/dv (the relative velocity)."""

from __future__ import annotations

import numpy as np
import pytest

from ancf import banded
from ancf.loads import Drag, Seabed, Surface, Waves, load_pass

XG, WG = np.polynomial.legendre.leggauss(5)
XG, WG = 0.5 * (XG + 1.0), 0.5 * WG


def _line(d, seed=3):
    rng = np.random.default_rng(seed)
    n = 5
    s = np.linspace(0.0, 8.0, n)
    q = np.zeros((n, 2 * d))
    q[:, 0] = s
    q[:, 1] = 0.4 * np.sin(s) + 0.05        # dips below the seabed y = 0 in places
    if d == 3:
        q[:, 2] = 0.2 * s
    q[:, d:] = np.gradient(q[:, :d], s, axis=0) + 0.01 * rng.standard_normal((n, d))
    v = 0.3 * rng.standard_normal((n, 2 * d))
    return q.ravel(), v.ravel(), np.diff(s)


def _loads(q, v, d, l0, lin=(0.0, 0.0), seabed=True, drag=True, surface=True):
    ne = l0.size
    heights = np.array([-1.0, 0.2, 1.0])
    comps = np.zeros((d, 3))
    comps[0] = [0.5, 1.0, 1.5]
    if d == 3:
        comps[2] = [0.0, 0.4, -0.3]
    slopes = np.ascontiguousarray(np.diff(comps, axis=1) / np.diff(heights)[None, :])
    kl = banded.half_bandwidth(d)
    # a wave field at the Gauss points (frozen in a step: only the drag's relative velocity
    # and the inertia's direction depend on the state)
    npts = ne * XG.size
    WU = 0.2 * np.cos(np.arange(npts * d, dtype=float)).reshape(npts, d)
    WA = 0.1 * np.sin(np.arange(npts * d, dtype=float)).reshape(npts, d)
    WS = np.full(npts, 0.35)
    F = np.zeros(q.size)
    K = banded.zeros(q.size, kl)
    load_pass(q, v, d, l0, XG, WG, Seabed(seabed, 1e4, np.full(ne, 50.0), 0.3, 0.01),
              Drag(drag, np.full(ne, 60.0), np.full(ne, 8.0), heights, comps, slopes),
              Surface(surface, 0.3, np.full(ne, 0.2), np.full(ne, 400.0)),
              Waves(True, WU, WA, WS, np.full(ne, 80.0), np.full(ne, 40.0)), lin[0], lin[1],
              F, K, kl, np.zeros((0, 4 * d)))
    return F, banded.to_dense(K, kl)


@pytest.mark.parametrize("d", [2, 3])
@pytest.mark.parametrize("which", ["q", "v"])
def test_the_loads_linearisation_is_their_derivative(d, which):
    q, v, l0 = _line(d)
    F, K = _loads(q, v, d, l0, (1.0, 0.0) if which == "q" else (0.0, 1.0))
    h = 1e-7
    K_fd = np.zeros_like(K)
    for i in range(q.size):
        qp, qm, vp, vm = q.copy(), q.copy(), v.copy(), v.copy()
        if which == "q":
            qp[i] += h
            qm[i] -= h
        else:
            vp[i] += h
            vm[i] -= h
        Fp, _ = _loads(qp, vp, d, l0)
        Fm, _ = _loads(qm, vm, d, l0)
        K_fd[:, i] = -(Fp - Fm) / (2 * h)        # the kernel adds -dF (the residual's)
    # the loads are piecewise smooth (contact and the current's profile have kinks): a
    # difference straddling a kink errs by O(1) in that entry; at h = 1e-7 on this state
    # none does (the state's heights are not within 1e-7 of a kink), so the smooth
    # pieces' truncation and round-off, ~1e-7 relative, set the bound
    assert np.max(np.abs(K - K_fd)) < 1e-5 * np.max(np.abs(K))
    assert np.max(np.abs(F)) > 0.0

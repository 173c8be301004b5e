"""The ANCF element's elastic forces and tangent against central differences of its
strain energy (an independent evaluation: the energy alone, differentiated numerically),
in 2D and 3D, stretched and compressed, straight and bent."""

from __future__ import annotations

import numpy as np
import pytest

from ancf import banded
from ancf.element import elastic_pass, element_fields

XG, WG = np.polynomial.legendre.leggauss(5)
XG, WG = 0.5 * (XG + 1.0), 0.5 * WG


def _state(d, n=4, seed=1, stretch=1.0):
    rng = np.random.default_rng(seed)
    s = np.linspace(0.0, 6.0, n)
    q = np.zeros((n, 2 * d))
    q[:, 0] = 2.0 * np.sin(s / 3.0) + s
    q[:, 1] = 0.5 * s ** 1.5
    if d == 3:
        q[:, 2] = 0.3 * np.cos(s)
    q[:, :d] += 0.05 * rng.standard_normal((n, d))
    # slopes: the chord direction, scaled by the stretch, perturbed
    t = np.gradient(q[:, :d], s, axis=0)
    t /= np.linalg.norm(t, axis=1)[:, None]
    q[:, d:] = stretch * t + 0.02 * rng.standard_normal((n, d))
    l0 = np.diff(s)
    return q.ravel(), l0


def _forces(q, d, l0, EA, EI, hessian=False):
    N = q.size
    kl = banded.half_bandwidth(d)
    F = np.zeros(N)
    K = banded.zeros(N, kl)
    e = elastic_pass(q, d, l0, EA, EI, XG, WG, hessian, F, K, kl, np.zeros((0, 4 * d)))
    return e, F, banded.to_dense(K, kl)


@pytest.mark.parametrize("d", [2, 3])
@pytest.mark.parametrize("stretch", [1.003, 0.995])
def test_forces_and_tangent_are_the_energys_derivatives(d, stretch):
    q, l0 = _state(d, stretch=stretch)
    ne = l0.size
    # a steel-like ratio of EA to EI: both terms matter at this element length
    EA = np.full(ne, 5.0e5)
    EI = np.full(ne, 2.0e4)
    _, F, K = _forces(q, d, l0, EA, EI, True)
    h = 1e-6
    F_fd = np.zeros_like(F)
    K_fd = np.zeros_like(K)
    for i in range(q.size):
        qp, qm = q.copy(), q.copy()
        qp[i] += h
        qm[i] -= h
        ep, Fp, _ = _forces(qp, d, l0, EA, EI)
        em, Fm, _ = _forces(qm, d, l0, EA, EI)
        F_fd[i] = (ep - em) / (2 * h)
        K_fd[:, i] = (Fp - Fm) / (2 * h)
    # central differences of a smooth energy: truncation h^2 |e'''| ~ 1e-12 relative,
    # round-off eps |e| / h ~ 1e-10 relative: 1e-6 of the largest entry is 1e4 x both
    assert np.max(np.abs(F - F_fd)) < 1e-6 * np.max(np.abs(F))
    assert np.max(np.abs(K - K_fd)) < 1e-6 * np.max(np.abs(K))
    assert np.allclose(K, K.T, atol=1e-9 * np.max(np.abs(K)))


@pytest.mark.parametrize("d", [2, 3])
def test_compression_makes_the_tangent_indefinite(d):
    # a straight line compressed by 0.5 %: the geometric stiffness EA eps / |a| (I - t t^T)
    # is negative across the axis and outweighs a soft bending stiffness (EI (pi/L)^2 ~
    # 1e-1 N against EA eps ~ 2.5e3 N), so the tangent has negative eigenvalues (why LU and
    # no Cholesky); the control: the same line stretched by 0.5 % has none
    def tangent(stretch):
        n = 5
        s = np.linspace(0.0, 8.0, n)
        q = np.zeros((n, 2 * d))
        q[:, 0] = stretch * s
        q[:, d] = stretch
        _, _, K = _forces(q.ravel(), d, np.diff(s), np.full(n - 1, 5e5), np.full(n - 1, 1.0),
                          True)
        return K

    Kc, Kt = tangent(0.995), tangent(1.005)
    assert np.min(np.linalg.eigvalsh(Kc)) < -1.0
    assert np.min(np.linalg.eigvalsh(Kt)) > -1e-9 * np.max(np.abs(Kt))


@pytest.mark.parametrize("d", [2, 3])
def test_a_rigid_motion_costs_no_energy(d):
    # an unstretched line (|r'| = 1) turned and moved as a body: zero force, zero energy;
    # a negative control: the same line stretched by 1e-3 carries EA 1e-3
    s = np.linspace(0.0, 10.0, 6)
    R = np.eye(d)
    c, sn = np.cos(0.7), np.sin(0.7)
    R[:2, :2] = [[c, -sn], [sn, c]]
    q = np.zeros((6, 2 * d))
    q[:, 0] = s
    q[:, d] = 1.0
    q[:, :d] = q[:, :d] @ R.T + 3.0
    q[:, d:] = q[:, d:] @ R.T
    l0 = np.diff(s)
    EA, EI = np.full(5, 1e9), np.full(5, 1e7)
    e, F, _ = _forces(q.ravel(), d, l0, EA, EI)
    assert abs(e) < 1e-12 and np.max(np.abs(F)) < 1e-3
    q2 = q.copy()
    q2[:, :d] *= 1.001
    q2[:, d:] *= 1.001
    r, a, b, T, kappa = element_fields(q2.ravel(), d, l0, EA, EI, 2, 0.3)
    assert T == pytest.approx(1e9 * 1e-3, rel=1e-9) and kappa < 1e-12


def test_a_circular_arc_has_its_curvature():
    # a unit-speed circle of radius R sampled with exact positions and slopes: the cubic
    # Hermite curvature is 1/R to the interpolation's error (h / R)^4 / ... at h/R = 0.1
    R0, n = 20.0, 8
    th = np.linspace(0.0, 0.7, n)
    q = np.zeros((n, 4))
    q[:, 0], q[:, 1] = R0 * np.sin(th), R0 * (1 - np.cos(th))
    q[:, 2], q[:, 3] = np.cos(th), np.sin(th)
    l0 = np.diff(th) * R0
    EA, EI = np.full(n - 1, 1e9), np.full(n - 1, 1e7)
    for e in range(n - 1):
        for xi in (0.0, 0.25, 0.5, 0.9):
            *_, T, kappa = element_fields(q.ravel(), 2, l0, EA, EI, e, xi)
            # the Hermite arc's speed and curvature are within (h/R)^2 / 24 ~ 4e-4 of
            # the circle's at h / R = 0.1
            assert kappa == pytest.approx(1.0 / R0, rel=2e-3)
            assert abs(T) < 1e9 * 2e-3

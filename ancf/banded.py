"""The ANCF's global matrices in LAPACK's general band storage, and their solve.

The generalised coordinates are stored node by node (2 d per node, :mod:`ancf.element`),
so an element couples 4 d consecutive unknowns and every matrix of the method (tangent,
mass, damping) is banded with kl = ku = 4 d - 1 diagonals on each side. Storage as
LAPACK's ``dgbsv`` takes it: ``ab`` of shape (3 kl + 1, N) with A[i, j] in ab[2 kl + i - j,
j] (the first kl rows are the LU factor's fill). Solved by banded LU with partial pivoting
(the tangent is indefinite in compression: no Cholesky), O(N kl^2).
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import lapack


def half_bandwidth(d: int) -> int:
    """kl = ku of the matrices of a d-dimensional line (7 planar, 11 in 3D)."""
    return 4 * d - 1


def zeros(n: int, kl: int) -> np.ndarray:
    """An empty band matrix of ``n`` unknowns."""
    return np.zeros((3 * kl + 1, n))


def add_diagonal_block(ab: np.ndarray, kl: int, i0: int, block: np.ndarray) -> None:
    """A[i0:i0+m, i0:i0+m] += block (m <= kl + 1)."""
    m = block.shape[0]
    for i in range(m):
        for j in range(m):
            ab[2 * kl + i - j, i0 + j] += block[i, j]


def get(ab: np.ndarray, kl: int, i: int, j: int) -> float:
    return ab[2 * kl + i - j, j] if abs(i - j) <= kl else 0.0


def to_dense(ab: np.ndarray, kl: int) -> np.ndarray:
    """The full matrix (tests and small problems)."""
    n = ab.shape[1]
    out = np.zeros((n, n))
    for j in range(n):
        for i in range(max(0, j - kl), min(n, j + kl + 1)):
            out[i, j] = ab[2 * kl + i - j, j]
    return out


def window(ab: np.ndarray, kl: int, i0: int, i1: int) -> np.ndarray:
    """The dense block A[i0:i1, i0:i1]."""
    m = i1 - i0
    out = np.zeros((m, m))
    for i in range(m):
        for j in range(m):
            if abs(i - j) <= kl:
                out[i, j] = ab[2 * kl + i - j, i0 + j]
    return out


def set_window(ab: np.ndarray, kl: int, i0: int, block: np.ndarray) -> None:
    """A[i0:i0+m, i0:i0+m] = block inside the band (entries outside it must be zero)."""
    m = block.shape[0]
    for i in range(m):
        for j in range(m):
            if abs(i - j) <= kl:
                ab[2 * kl + i - j, i0 + j] = block[i, j]


def fix(ab: np.ndarray, kl: int, dofs) -> None:
    """Rows and columns of ``dofs`` replaced by the identity's (a prescribed unknown)."""
    n = ab.shape[1]
    for i in dofs:
        for j in range(max(0, i - kl), min(n, i + kl + 1)):
            ab[2 * kl + i - j, j] = 0.0        # row i
            ab[2 * kl + j - i, i] = 0.0        # column i
        ab[2 * kl, i] = 1.0


def solve(ab: np.ndarray, kl: int, rhs: np.ndarray):
    """x with A x = rhs, or None when the matrix is singular (LAPACK info > 0). ``ab`` is
    overwritten by its factor."""
    _, _, x, info = lapack.dgbsv(kl, kl, ab, rhs.reshape(-1, 1), overwrite_ab=1,
                                  overwrite_b=0)
    if info != 0:
        return None
    return x[:, 0]

"""``solve_bvp`` with its Newton matrix pruned of structural zeros before each
factorisation.

scipy's collocation (``scipy.integrate._bvp``) assembles the Newton matrix from a dense
n x n block of df/dy per mesh interval and factorises it with SuperLU. The riser
equations' blocks are mostly structural zeros (bvp/beam/equations.py: 6 states, 13 of the 36
entries of d(a u')/du nonzero; the contact-zone form's two blocks do not interact at all;
the modes' 7 states fewer still), stored as explicit zeros that SuperLU orders and
eliminates like any other entry. Dropping them (``eliminate_zeros``) leaves the matrix
the same and its factorisation smaller: measured 1.5-2.2x on a whole solve (issue 36),
the results equal to round-off (the factorisation's pivot order changes, not its
arithmetic's accuracy).

How: scipy's module imports ``splu`` by name; :func:`solve_bvp` swaps that name for a
pruning wrapper for the duration of one call (and restores it). Where scipy no longer has
that name (a future version), the call is scipy's own, unpruned: slower, not different.
"""

from __future__ import annotations

import contextlib
import threading

from scipy.integrate import _bvp
from scipy.integrate import solve_bvp as _solve_bvp
from scipy.sparse.linalg import splu as _splu

_LOCK = threading.RLock()


def _pruned_splu(J, *args, **kwargs):
    """SuperLU of ``J`` (CSC) without its explicit zeros."""
    J.eliminate_zeros()
    return _splu(J, *args, **kwargs)


@contextlib.contextmanager
def _pruned():
    if getattr(_bvp, "splu", None) is not _splu:
        yield                      # scipy changed, or already pruned by an outer call
        return
    with _LOCK:
        _bvp.splu = _pruned_splu
        try:
            yield
        finally:
            _bvp.splu = _splu


_PLAIN = threading.local()


@contextlib.contextmanager
def unpruned():
    """scipy's own factorisation inside the block (a test comparing two solves' Newton
    paths bit for bit: the pruned pattern's pivot order depends on the states' count)."""
    _PLAIN.on = True
    try:
        yield
    finally:
        _PLAIN.on = False


def solve_bvp(*args, **kwargs):
    """:func:`scipy.integrate.solve_bvp`, its Newton matrices pruned (module docstring)."""
    if getattr(_PLAIN, "on", False):
        return _solve_bvp(*args, **kwargs)
    with _pruned():
        return _solve_bvp(*args, **kwargs)

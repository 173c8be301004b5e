"""Newton's method on the VFIFE's discrete static equilibrium (issue 36): a planar model
near equilibrium is finished in a few iterations whose cost grows linearly with the node
count, where the explicit relaxation's steps grow with 1/h (its cost with N^2).

The equations are the VFIFE's own: the out-of-balance force and moment of every free node
are read off one step of the model's own kernels (:meth:`vfife.model.Model.run`) from
rest with unit masses and a tiny step dt (:func:`out_of_balance`: the step's velocity is
dt times the force, exactly the kernel's weight, buoyancy, drag, seabed, end conditions
and attachments, none of them written again here). The tangent is the element energy's
Hessian of :mod:`vfife.tangent` plus the seabed's springs in contact: the drag (a follower
load) and the tensioner's dead pull are frozen in it, so Newton converges quadratically on
the elements' stiffness and linearly on the drag's share. The linear system is the
banded (block-tridiagonal) stiffness of a line: one sparse LU, O(N).

Planar models only (x, y and the rotation about z per node); a step that does not lower
the residual is halved (up to 6 times); after ``max_iter`` iterations without meeting the
tolerance the caller falls back on the relaxation.
"""

from __future__ import annotations

import time

import numpy as np
import scipy.sparse.linalg as spla

from .model import Model
from .tangent import NDOF, linearise, rotate

#: Newton steps after the tolerance is met (each kept only where it lowers the residual):
#: quadratic convergence takes the state from the tolerance to the round-off in one, so
#: that what is reported is the discrete equilibrium itself, not a state somewhere within
#: the tolerance of it (a weightless line's tolerance, 1e-6 EA, left a beam's tension 2e-5
#: N off zero and its frequencies 1e-8 off the closed form)
POLISH = 1
#: the pseudo time step [s] of the residual evaluation: the positions move by dt^2 F / 1 kg
#: (restored after), the velocity is dt F to the rounding of one product
_DT = 1.0e-10


def out_of_balance(model: Model) -> tuple[np.ndarray, np.ndarray]:
    """(forces (2, n) [N], moments (n,) [N m]) out of balance at the model's state: zero at
    the held degrees of freedom (a pinned end's translation, a clamped end's rotation)."""
    saved = {k: getattr(model, k).copy() for k in ("X", "V", "D", "W", "im", "imd", "jinv",
                                                   "mass")}
    model.V[:] = 0.0
    model.W[:] = 0.0
    model.im[:] = 1.0
    model.imd[:] = 0.0
    held = model.jinv == 0.0
    model.jinv[:] = np.where(held, 0.0, 1.0)
    steps = model.steps
    model.run(1, _DT, 0.0)
    model.steps = steps
    F = model.V[:2].copy() / _DT
    M = model.W[2].copy() / _DT
    for k, v in saved.items():
        getattr(model, k)[:] = v
    if model.ends[4] == 0.0:                 # a pinned anchor holds its translation
        F[:, 0] = 0.0
    F[0, -1] = 0.0                           # the hang-off's x is held, and its y
    if model.ends[5] == 0.0:                 # unless a tensioner frees it
        F[1, -1] = 0.0
    M[held] = 0.0
    return F, M


def solve(model: Model, tol_force: float, tol_moment: float, max_iter: int = 30) -> dict:
    """Newton iterations on ``model`` (planar, near equilibrium) until the largest nodal
    force < ``tol_force`` [N] and moment < ``tol_moment`` [N m]. Returns a dict:
    converged, iterations, residual (the largest force) and moment_residual, wall_s."""
    if not model.planar:
        raise ValueError("vfife Newton statics: planar models only")
    t0 = time.perf_counter()
    n = model.mesh.n

    def norms():
        F, M = out_of_balance(model)
        return F, M, float(np.max(np.hypot(F[0], F[1]))), float(np.max(np.abs(M)))

    F, M, rf, rm = norms()
    it = 0
    polish = POLISH
    while it < max_iter and (not (rf < tol_force and rm < tol_moment) or polish > 0):
        if rf < tol_force and rm < tol_moment:
            polish -= 1        # met: one more step takes it to the round-off (quadratic)
        tan = linearise(model)
        free = tan.family("in_plane")
        g = np.zeros(NDOF * n)
        g[0::NDOF] = F[0]
        g[1::NDOF] = F[1]
        g[3::NDOF] = M
        K = tan.K[free][:, free].tocsc()
        dq = np.zeros(NDOF * n)
        dq[free] = spla.spsolve(K, g[free])
        X0, D0 = model.X.copy(), model.D.copy()
        alpha, before = 1.0, max(rf / tol_force, rm / tol_moment)
        for _ in range(7):
            model.X[0] = X0[0] + alpha * dq[0::NDOF]
            model.X[1] = X0[1] + alpha * dq[1::NDOF]
            model.D[:] = rotate(D0, np.array([0.0, 0.0, 1.0])[:, None],
                                alpha * dq[3::NDOF])
            F, M, rf, rm = norms()
            if max(rf / tol_force, rm / tol_moment) < before:
                break
            alpha *= 0.5
        else:
            model.X[:], model.D[:] = X0, D0
            F, M, rf, rm = norms()
            break
        if polish < POLISH:
            break
        it += 1
    return {"converged": bool(rf < tol_force and rm < tol_moment), "iterations": it,
            "residual": rf, "moment_residual": rm, "wall_s": time.perf_counter() - t0}

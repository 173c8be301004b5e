"""Newton's method on the VFIFE's discrete static equilibrium (issue 36): a planar model
near equilibrium is finished in a few iterations whose cost grows linearly with the node
count, where the explicit relaxation's steps grow with 1/h (its cost with N^2).

The equations are the VFIFE's own: the out-of-balance force and moment of every free node
are read off one step of the model's own kernels (:meth:`vfife.model.Model.run`) from
rest with unit masses and a tiny step dt (:func:`out_of_balance`: the step's velocity is
dt times the force, exactly the kernel's weight, buoyancy, drag, seabed, end conditions
and attachments, none of them written again here). The tangent is the element energy's
Hessian of :mod:`vfife.modal.tangent` plus the seabed's springs in contact: the drag (a follower
load) and the tensioner's dead pull are frozen in it, so Newton converges quadratically on
the elements' stiffness and linearly on the drag's share. The linear system is the
banded (block-tridiagonal) stiffness of a line: one sparse LU, O(N).

Planar models: x, y and the rotation about z per node. A 3D model (a current out of the
plane): x, y, z and the rotations about two axes normal to each node's director
(:func:`vfife.modal.tangent.normal_axes`; the twist is not a DOF of the model), the directors turned by the
rotation vector the two make. A step that does not lower the residual is halved (up to 6
times); after ``max_iter`` iterations without meeting the tolerance the caller falls back
on the relaxation.
"""

from __future__ import annotations

import time

import numpy as np
import scipy.sparse.linalg as spla

from ..model import Model
from ..modal.tangent import NDOF, linearise, normal_axes, rotate

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
    """(forces [N], moments [N m]) out of balance at the model's state: planar (2, n) and
    (n,) (about z), 3D (3, n) and (3, n); zero at the held degrees of freedom (a pinned
    end's translation, a clamped end's rotation)."""
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
    planar = model.planar
    F = (model.V[:2] if planar else model.V).copy() / _DT
    M = (model.W[2] if planar else model.W).copy() / _DT
    for k, v in saved.items():
        getattr(model, k)[:] = v
    if model.ends[4] == 0.0:                 # a pinned anchor holds its translation
        F[:, 0] = 0.0
    F[0, -1] = 0.0                           # the hang-off's x (and z) is held, and its y
    F[2:, -1] = 0.0
    if model.ends[5] == 0.0:                 # unless a tensioner frees it
        F[1, -1] = 0.0
    if planar:
        M[held] = 0.0
    else:
        M[:, held] = 0.0
    return F, M


def _turned(D0: np.ndarray, basis: np.ndarray, r3: np.ndarray, r4: np.ndarray) -> np.ndarray:
    """Directors D0 turned by the rotation vector r3 basis[:, 0] + r4 basis[:, 1]."""
    phi = r3 * basis[:, 0].T + r4 * basis[:, 1].T
    angle = np.linalg.norm(phi, axis=0)
    axis = phi / np.where(angle > 0.0, angle, 1.0)
    return rotate(D0, axis, angle)


def solve(model: Model, tol_force: float, tol_moment: float, max_iter: int = 30) -> dict:
    """Newton iterations on ``model`` (near equilibrium) until the largest nodal force <
    ``tol_force`` [N] and moment < ``tol_moment`` [N m]. Returns a dict: converged,
    iterations, residual (the largest force) and moment_residual, wall_s."""
    t0 = time.perf_counter()
    n = model.mesh.n
    planar = model.planar

    def norms():
        F, M = out_of_balance(model)
        if planar:
            return F, M, float(np.max(np.hypot(F[0], F[1]))), float(np.max(np.abs(M)))
        return (F, M, float(np.max(np.linalg.norm(F, axis=0))),
                float(np.max(np.linalg.norm(M, axis=0))))

    F, M, rf, rm = norms()
    it = 0
    polish = POLISH
    while it < max_iter and (not (rf < tol_force and rm < tol_moment) or polish > 0):
        if rf < tol_force and rm < tol_moment:
            polish -= 1        # met: one more step takes it to the round-off (quadratic)
        basis = None if planar else normal_axes(model.D)
        tan = linearise(model, basis)
        g = np.zeros(NDOF * n)
        if planar:
            free = tan.family("in_plane")
            g[0::NDOF], g[1::NDOF], g[3::NDOF] = F[0], F[1], M
        else:
            free = np.setdiff1d(np.arange(NDOF * n), tan.fixed)
            g[0::NDOF], g[1::NDOF], g[2::NDOF] = F
            g[3::NDOF] = np.einsum("in,ni->n", M, tan.basis[:, 0])
            g[4::NDOF] = np.einsum("in,ni->n", M, tan.basis[:, 1])
        K = tan.K[free][:, free].tocsc()
        dq = np.zeros(NDOF * n)
        dq[free] = spla.spsolve(K, g[free])
        X0, D0 = model.X.copy(), model.D.copy()
        alpha, before = 1.0, max(rf / tol_force, rm / tol_moment)
        for _ in range(7):
            for k in range(2 if planar else 3):
                model.X[k] = X0[k] + alpha * dq[k::NDOF]
            if planar:
                model.D[:] = rotate(D0, np.array([0.0, 0.0, 1.0])[:, None],
                                    alpha * dq[3::NDOF])
            else:
                model.D[:] = _turned(D0, tan.basis, alpha * dq[3::NDOF], alpha * dq[4::NDOF])
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

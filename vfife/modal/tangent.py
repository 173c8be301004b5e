"""Linearisation of the VFIFE model about a static state: tangent stiffness and mass.

Degrees of freedom, 5 per node i, global index ``5 i + k``: the translations x, y, z
(k = 0, 1, 2) and two rotations of the director about the unit axes ``basis[i, 0]`` and
``basis[i, 1]`` (k = 3, 4), both perpendicular to the director (the twist is not a DOF of
the model: :mod:`vfife.kernels`). For a planar static state (z = 0, directors in the x-y
plane) ``basis[i, 0] = e_z`` (the in-plane rotation) and ``basis[i, 1] = e_z x d_i`` (it
tips the director out of the plane). A 3D state's axes are :func:`normal_axes` (Newton's
statics out of plane, vfife/statics/newton.py, and the coupled modes about a 3D state,
vfife/modal/modes.py): any two unit axes normal to the director span the same rotations,
so the eigenvalues do not depend on the choice.

Stiffness: the Hessian of the element strain energy, by central differences of the
kernel's own element forces and moments (:func:`vfife.kernels.element_pass`, the function
the time integration calls), element by element: every element is evaluated in its own
frame (positions relative to its end a, so the differences do not lose digits to
coordinates ~1 km) and its 10 DOFs (two end translations, two end rotations) are
perturbed one at a time in all elements at once (40 calls in all, see :data:`STEP`). The
element forces are the exact gradient of the element energy and the moments are the
generalised forces of rotations perpendicular to the director, so the result is the
energy's Hessian in these coordinates: symmetric at any state, planar or 3D (the
second-order term of two rotations about unit axes a, b normal to the director d is
g.(a x (b x d)) = -(g.d)(a.b), g the energy's gradient in d: symmetric in a and b, since
a.d = b.d = 0). Weight and the static drag of a current (in or across the plane) are
constant nodal forces, dead loads (no stiffness: the drag is frozen at its static value,
the model stated in :mod:`bvp.modal.modes`, whose rotating-frame equations carry the
matching terms); the seabed adds its linear spring ``k x tributary length`` [N/m] in y at
the nodes in contact (y < 0), nothing laterally; friction, the drag's dependence on the
motion and damping are not in this undamped linearisation.

Mass: per node ``m I + m_a (I - d d^T)`` (pipe + contents, the added mass normal to the
director, exactly as the kernels integrate it) and the rotational inertia ``J`` on both
rotations (the model's, ``rot_scale`` x the physical diametral inertia).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from .. import kernels
from ..model import Model

#: DOFs per node: x, y, z, rotation about basis[0], rotation about basis[1]
NDOF = 5
#: relative step of the central differences: translations h = STEP x element length,
#: rotations h = STEP rad, extrapolated from h and 2h (Richardson). A plain central
#: difference has the error ~ EA STEP^2 / 2 in the transverse stiffness x l (the stretch
#: h^2 / 2l of a transverse step times EA/l: a spurious tension of 0.5 N at EA = 1e10 and
#: STEP = 1e-5, visible in a tension-free beam); extrapolated, ~EA STEP^4 (1e-6 N) and the
#: round-off ~eps EA / STEP (~1e-2 N, random) in the element frame.
STEP = 1.0e-4
#: DOF families of a planar state (indices within a node's 5 DOFs)
FAMILY_DOFS = {"in_plane": (0, 1, 3), "out_of_plane": (2, 4)}


@dataclass
class Tangent:
    """Linearised model: ``K`` and ``M`` (5n x 5n, CSR) on all DOFs, ``fixed`` the DOFs held
    (end translations, clamped end rotations), the rotation ``basis`` (n, 2, 3), and checks:
    ``asymmetry`` (largest |K - K^T| scaled by sqrt(K_ii K_jj)) and ``coupling`` (the same
    scaled measure of the in-plane/out-of-plane block; 0 for a planar state)."""

    K: sp.csr_matrix
    M: sp.csr_matrix
    fixed: np.ndarray
    basis: np.ndarray
    contact: np.ndarray
    asymmetry: float = 0.0
    coupling: float = 0.0
    info: dict = field(default_factory=dict)

    def free_dofs(self) -> np.ndarray:
        """All the free global DOF indices (sorted): the coupled problem of a 3D state."""
        return np.setdiff1d(np.arange(self.K.shape[0]), self.fixed)

    def family(self, plane: str) -> np.ndarray:
        """Free global DOF indices of one family (sorted)."""
        n = self.basis.shape[0]
        idx = (NDOF * np.arange(n)[:, None] + np.asarray(FAMILY_DOFS[plane])[None, :]).ravel()
        return np.sort(idx[~np.isin(idx, self.fixed)])


def dynamic_model(scene, static: Model, rot_scale: float = 1.0, planar: bool | None = None
                  ) -> Model:
    """A Model with the physical masses built the way :func:`vfife.dynamics.run.run_dynamics`
    builds it (added mass if a line type has C_a > 0, the rotational inertia ``rot_scale``
    x physical), holding the static state of ``static`` (positions, directors; at rest).
    Without the drag and the sea surface of the dynamics: the static drag enters the
    linearisation as a dead load, which has no stiffness (nothing to build), and the
    added mass is the contract's (:mod:`riser.results.modes`) all along the line."""
    added = any(scene.line_types[s.line_type].added_mass > 0.0 for s in scene.segments)
    model = Model(scene, static.mesh, rot_scale=rot_scale, added_mass=added,
                  planar=static.planar if planar is None else planar)
    model.X[:] = static.X
    model.D[:] = static.D
    return model


def planar_basis(D: np.ndarray) -> np.ndarray:
    """(n, 2, 3) rotation axes perpendicular to the directors D (3, n) of a planar state:
    e_z and e_z x d."""
    n = D.shape[1]
    B = np.zeros((n, 2, 3))
    B[:, 0, 2] = 1.0
    B[:, 1, 0] = -D[1]
    B[:, 1, 1] = D[0]
    B[:, 1] /= np.linalg.norm(B[:, 1], axis=1)[:, None]
    return B


def normal_axes(D: np.ndarray) -> np.ndarray:
    """(n, 2, 3) unit axes normal to the directors D (3, n) of a 3D state: e_z made normal
    to d (e_x where d is within 26 deg of e_z), and d x that axis."""
    ref = np.zeros_like(D)
    near = np.abs(D[2]) > 0.9
    ref[2, ~near] = 1.0
    ref[0, near] = 1.0
    a = ref - np.sum(ref * D, axis=0) * D
    a /= np.linalg.norm(a, axis=0)
    b = np.cross(D, a, axis=0)
    return np.stack([a.T, b.T], axis=1)


def rotate(D: np.ndarray, axis: np.ndarray, angle) -> np.ndarray:
    """Directors D (3, n) rotated by ``angle`` [rad] ((n,) or scalar) about unit axes
    ``axis`` (3, n) perpendicular to them: cos a d + sin a (axis x d)."""
    return np.cos(angle) * D + np.sin(angle) * np.cross(axis, D, axis=0)


def _element_forces(model: Model, Xa, Xb, Da, Db, Ba, Bb) -> np.ndarray:
    """Generalised element end forces (ne, 10) by the kernel: force on a (3), on b (3),
    moment on a about Ba[0], Ba[1], on b about Bb[0], Bb[1]. Xa, Xb, Da, Db (3, ne)
    element-frame positions and directors; the elements are laid out as 2 ne nodes with a
    dummy (zero-stiffness) element between consecutive elements."""
    ne = Xa.shape[1]
    P = np.empty((3, 2 * ne))
    P[:, 0::2] = Xa
    P[:, 1::2] = Xb
    Dd = np.empty((3, 2 * ne))
    Dd[:, 0::2] = Da
    Dd[:, 1::2] = Db
    m = 2 * ne - 1
    l0 = np.ones(m)
    kax = np.zeros(m)
    kb = np.zeros(m)
    l0[0::2] = model.l0
    kax[0::2] = model.kax
    kb[0::2] = model.kb
    f = [np.zeros(m) for _ in range(9)]
    p = [np.ascontiguousarray(r) for r in (*P, *Dd)]
    kernels.element_pass(*p, l0, kax, kb, *f)
    F = np.stack(f[0:3])[:, 0::2]
    MA = np.stack(f[3:6])[:, 0::2]
    MB = np.stack(f[6:9])[:, 0::2]
    return np.concatenate([F, -F, np.einsum("in,nki->kn", MA, Ba),
                           np.einsum("in,nki->kn", MB, Bb)]).T


def element_stiffness(model: Model, basis: np.ndarray) -> np.ndarray:
    """(ne, 10, 10) element tangent stiffness -dQ/dq in the element DOFs (x_a, x_b,
    rotations of a about basis[a], of b about basis[b]), by central differences."""
    X, D = model.X, model.D
    Xa = np.zeros_like(X[:, :-1])                 # element frame: end a at the origin
    Xb = X[:, 1:] - X[:, :-1]
    Da, Db = D[:, :-1], D[:, 1:]
    Ba, Bb = basis[:-1], basis[1:]
    ne = Xb.shape[1]
    ke = np.empty((ne, 10, 10))

    def column(k: int, step: float) -> np.ndarray:
        """-dQ/dq_k by central differences of step ``step`` (x l0 for translations)."""
        h = step * model.l0 if k < 6 else np.full(ne, step)
        Q = []
        for sgn in (1.0, -1.0):
            xa, xb, da, db = Xa.copy(), Xb.copy(), Da, Db
            if k < 3:
                xa[k] += sgn * h
            elif k < 6:
                xb[k - 3] += sgn * h
            elif k < 8:
                da = rotate(Da, Ba[:, k - 6].T, sgn * step)
            else:
                db = rotate(Db, Bb[:, k - 8].T, sgn * step)
            Q.append(_element_forces(model, xa, xb, da, db, Ba, Bb))
        return -(Q[0] - Q[1]) / (2.0 * h)[:, None]

    for k in range(10):     # Richardson: the h^2 error of the central difference cancels
        ke[:, :, k] = (4.0 * column(k, STEP) - column(k, 2.0 * STEP)) / 3.0
    return ke


def _scaled_max(A: sp.spmatrix, drow: np.ndarray, dcol: np.ndarray) -> float:
    """max |A_ij| / sqrt(|drow_i dcol_j|) (0 for an empty A): entries against the
    diagonal stiffnesses of their two DOFs."""
    A = sp.coo_matrix(A)
    if A.nnz == 0:
        return 0.0
    sr, sc = (np.where(d == 0.0, 1.0, np.sqrt(np.abs(d))) for d in (drow, dcol))
    return float(np.max(np.abs(A.data) / (sr[A.row] * sc[A.col])))


def linearise(model: Model, basis: np.ndarray | None = None) -> Tangent:
    """Tangent stiffness and mass of ``model`` about its current (static) state."""
    n, ne = model.mesh.n, model.mesh.ne
    basis = planar_basis(model.D) if basis is None else basis
    ke = element_stiffness(model, basis)
    e = np.arange(ne)
    dofs = np.concatenate([NDOF * e[:, None] + np.arange(3), NDOF * (e + 1)[:, None]
                           + np.arange(3), NDOF * e[:, None] + np.array([3, 4]),
                           NDOF * (e + 1)[:, None] + np.array([3, 4])], axis=1)   # (ne, 10)
    rows = np.repeat(dofs, 10, axis=1).ravel()
    cols = np.tile(dofs, (1, 10)).ravel()
    N = NDOF * n
    K = sp.coo_matrix((ke.ravel(), (rows, cols)), shape=(N, N)).tocsr()
    contact = np.zeros(n, bool)
    if model.use_seabed:
        contact[1:-1] = model.X[1, 1:-1] < 0.0
        spring = np.zeros((n, NDOF))
        spring[:, 1] = np.where(contact, model.kst, 0.0)
        K = (K + sp.diags(spring.ravel())).tocsr()
    # mass, a 5 x 5 block per node: m I + m_a (I - d d^T) on the translations, J on the
    # rotations
    d = model.D.T
    blocks = np.zeros((n, NDOF, NDOF))
    blocks[:, :3, :3] = ((model.mass + model.madd)[:, None, None] * np.eye(3)
                         - model.madd[:, None, None] * np.einsum("ni,nj->nij", d, d))
    blocks[:, 3, 3] = blocks[:, 4, 4] = model.jrot
    M = sp.bsr_matrix((blocks, np.arange(n), np.arange(n + 1)), shape=(N, N)).tocsr()
    # the end conditions (vfife.end_conditions): a free anchor's translations and a
    # tensioned top's height are free, the tensioner a vertical spring; a flex joint a
    # rotational spring about both axes normal to the end's director (isotropic); the
    # dead loads (weight, the tensioner's top_tension) add no stiffness
    ends = model.ends
    top = NDOF * (n - 1)
    fixed = ([] if ends[4] > 0.0 else [0, 1, 2]) + [top, top + 2]
    springs = np.zeros(N)
    if ends[5] > 0.0:
        springs[top + 1] = ends[7]
    else:
        fixed.append(top + 1)
    for i, k in ((0, ends[0]), (n - 1, ends[2])):
        springs[NDOF * i + 3] += k
        springs[NDOF * i + 4] += k
    if np.any(springs != 0.0):
        K = (K + sp.diags(springs)).tocsr()
    for end in model.clamped:
        i = 0 if end == "bottom" else n - 1
        fixed += [NDOF * i + 3, NDOF * i + 4]
    tan = Tangent(K, M, np.array(sorted(fixed)), basis, contact)
    diag = K.diagonal()
    tan.asymmetry = _scaled_max(K - K.T, diag, diag)
    ip, op = tan.family("in_plane"), tan.family("out_of_plane")
    tan.coupling = _scaled_max(K[ip][:, op], diag[ip], diag[op])
    tan.K = ((K + K.T) * 0.5).tocsr()
    tan.info = {"dofs": N, "contact_nodes": int(contact.sum())}
    return tan


"""Natural modes of the ANCF model about its static state (undamped).

:func:`solve_modes` linearises the ANCF's discrete model (:mod:`ancf.model`) about its
static equilibrium and solves the generalised eigenproblem

    K x = omega^2 M x

for the lowest modes, the model of :mod:`riser.results.modes` (the one the BVP's and the
VFIFE's modal analyses share): about a planar static state the two families of
:data:`~riser.results.modes.PLANES`, each solved on its own; about a 3D static state
(``Scene.statics_planar`` False: a current across the line's plane or turning with depth,
a hang-off out of the anchor's plane) one family, :data:`~riser.results.modes.COUPLED`,
of twice as many modes from one eigenproblem on all the free unknowns (below).

- **K**, the tangent of the residual, :meth:`ancf.model.Model.residual` at the static
  state: the Hessian of the extensible elastica's strain energy (the tension's geometric
  stiffness, the bending, the stretch), the seabed's Winkler springs where the line lies
  in it (a vertical spring k per unit length, nothing laterally: the friction's term
  vanishes at rest), the flex joints' and the tensioner's stiffness (:mod:`ancf.ends`).
  Undamped, as docs/theory.md "Modes in a current" states for the other methods: the
  static drag of a current is held as a dead load (fixed in magnitude and direction, the
  weight's kind of load), which has no stiffness, so the tangent is taken on a Model
  with the drag off (``use_drag`` False) about the state solved *with* the drag; the
  drag's linearisation (its quasi-steady stiffness and its damping) does not enter. With
  the drag off every term of K is an energy's Hessian, so K is symmetric; its measured
  asymmetry (round-off of the assembly, ~1e-16 of its largest entry) is reported in
  ``info['asymmetry']`` and removed by taking (K + K^T)/2; an asymmetry above
  :data:`MAX_ASYMMETRY` (a non-conservative term: not expected) fails the analysis
  instead of being symmetrised away.
- **M**, the consistent mass matrix of :func:`ancf.mass.mass_pass`: int N^T (m I + m_a
  (I - t t^T)) N ds with m the pipe and contents, m_a the added mass normal to the axis
  only (t the static tangent), plus each point attachment's mass and (isotropic) added
  mass on its node's position unknowns. No rotary inertia (gradient-deficient elements
  have none; the BVP neglects it too).

Both families from one 3D model: the planar static state (d = 2, or d = 3 with z and the
slopes' z components zero) is embedded in a d = 3 Model of the same mesh, where the
in-plane unknowns (the x, y components of the positions and slopes) and the out-of-plane
ones (z) decouple exactly (``info['coupling']``, 0 at a planar state) and each family is
solved on its own. Out of plane, an end joint is isotropic (riser/model/ends.py; the BVP's
``B + k psi = 0``, bvp/modal/ends.py): the planar flex joint of :mod:`ancf.ends` acts on
the in-plane angle only, so its out-of-plane stiffness, the Hessian k / |r'|^2 of
k/2 psi^2 (psi = r'_z / |r'| the tangent's tilt out of the plane), is added here at the
joint's slope z unknown.

About a 3D static state the same K and M are taken, term by term, of the 3D model about
the 3D state the statics solved (its d = 3 unknowns as they are): the elastica's Hessian
(its axial part with the slope's own length |r'|, the bending part with the 3D
curvature), the Winkler springs where the line lies in the seabed (vertical, nothing
laterally), the weight and the static drag of the current (its component across the plane
too) dead loads without stiffness, the added mass across the 3D tangent. The in-plane and
out-of-plane unknowns then couple (``info['coupling']`` > 0), so they are not split: one
generalised eigenproblem on all the free unknowns gives the ``2 count`` lowest modes,
numbered 1..2 count by frequency, each with its ``out_of_plane_share``
(:func:`riser.results.modes.out_of_plane_share`, the fraction of its squared displacement
along z) in ``info['out_of_plane_share']``. The ends of a 3D scene are pinned (joints and
a tensioner need a planar scene, riser/model/end_checks.py); the joint's out-of-plane
stiffness above is the Hessian about a planar state only, so a joint about a 3D state is
refused. ``solve_modes(..., coupled=True)`` solves a planar state the same way (one
family: its frequencies are the two families' merged, the check of
tests/test_ancf_modes_3d.py).

Ends: the prescribed unknowns (``model.ends.fixed``, in the clamped nodes' rotated slope
basis: K and M are rotated there, :func:`ancf.ends.rotate`) are removed; the free anchor
fixes none. Eigenpairs by ``scipy.sparse.linalg.eigsh`` in shift-invert mode about 0 on
the sparse matrices (a reproducible ARPACK start), dense ``scipy.linalg.eigh`` for a small
family.

Mode shapes (both paths): the displacement of the line's points, the positions of the
eigenvector interpolated by the elements' own cubic Hermite functions at the nodes and at
most :data:`ancf.output.OUTPUT_SPACING` apart (the static profile's samples), (k, 3) x, y,
z, ``normalise_shape``d; ``s`` the unstretched arc length.
"""

from __future__ import annotations

import inspect
import math
import time

import numpy as np
import scipy.linalg as sl
import scipy.sparse as sp
import scipy.sparse.linalg as sla

from riser.callbacks import with_fraction
from riser.errors import UnsupportedSceneError
from riser.model.scene import Scene
from riser.results.modes import (COUPLED, PLANES, ModalResult, Mode, normalise_shape,
                                 out_of_plane_share)
from riser.results.result import SolveResult, Status

from . import banded
from .element import shape
from .ends import rotate, unrotate
from .mass import mass_pass
from .model import Model
from .output import OUTPUT_SPACING
from .solver import require_ancf, solve

#: a static state is planar when |z - z_anchor| stays below this x the line's length and
#: the slopes' z components below this
PLANAR_TOL = 1.0e-9
#: the largest relative asymmetry max|K - K^T| / max|K| symmetrised as round-off
MAX_ASYMMETRY = 1.0e-9
#: seed of ARPACK's start vector (as vfife/modal/modes.py: the same model gives the same
#: digits on every call)
ARPACK_SEED = 20240530
#: the unknowns of a node in 3D: r (0, 1, 2), r' (3, 4, 5); each family's components
FAMILY_COMPONENTS = {"in_plane": (0, 1, 3, 4), "out_of_plane": (2, 5)}


def solve_modes(scene: Scene, count: int = 10, *, static: SolveResult | None = None,
                progress=None, coupled: bool | None = None) -> ModalResult:
    """The ``count`` lowest in-plane and out-of-plane modes of the ANCF model of the
    fixed-ends ``scene`` about its static state, or about a 3D static state the ``2 count``
    lowest coupled modes (module docstring).

    static : a converged :func:`ancf.solve` result of ``scene`` (its ``solver_state`` the
        static (Model, q)); solved here when None, without the scene's [dynamics].
    coupled : None (default): two families about a planar static state
        (``scene.statics_planar``), one coupled family about a 3D one; True: one coupled
        family whatever the state (a planar one too); False: the two families only (a 3D
        static state is refused).
    A scene the ANCF does not take (:func:`ancf.solver.require_ancf`) or flowing contents
    give a ``refused`` result; a static solve that fails gives its status and no modes; a
    negative eigenvalue (an unstable static state) gives ``not_converged`` with the modes
    found. Never raises on a failure (a bad ``count`` or ``static`` is ValueError; a scene
    with bad input, SceneError, as the solve)."""
    if count < 1:
        raise ValueError(f"count must be >= 1, got {count}")
    if static is not None and static.method != "ancf":
        raise ValueError(f"static must be an ancf result, got a {static.method} one")
    try:
        return _solve_modes(scene, count, static, progress, coupled)
    except UnsupportedSceneError as exc:
        return ModalResult("ancf", scene.name, Status.REFUSED, str(exc))


def _solve_modes(scene: Scene, count: int, static, progress, coupled) -> ModalResult:
    """:func:`solve_modes`, raising UnsupportedSceneError for what it refuses."""
    if scene.internal_flow is not None and scene.internal_flow.speed != 0.0:
        raise UnsupportedSceneError(
            f"{scene.source}: internal_flow.speed: modes do not model flowing contents (the "
            "Coriolis force makes the modes complex); set the speed to 0 for the modes of "
            "the line with its contents at rest")
    still = scene.replace(dynamics=None) if scene.dynamics is not None else scene
    require_ancf(still)
    three_d = not still.statics_planar
    if coupled is None:
        coupled = three_d
    if three_d and not coupled:
        key, why = still.out_of_plane(statics=True)
        raise UnsupportedSceneError(
            f"{scene.source}: {key}: {why}; modes in two families (coupled=False) are "
            "analysed about a planar static state only (out of plane the in-plane and "
            "out-of-plane modes couple)")
    report = with_fraction(progress)
    if static is None:
        if report is not None:
            report("ancf modes: static state", fraction=0.0)
        static = solve(still, progress=progress)
        if static.status is Status.REFUSED:
            raise UnsupportedSceneError(static.message)
    static_s = static.wall_time_s
    if not static.converged:
        return ModalResult("ancf", scene.name, static.status,
                           f"no static state to analyse: {static.message}",
                           info={"static_wall_time_s": static_s})
    model, q = static.solver_state
    if report is not None:
        report("ancf modes: tangent stiffness, mass and eigenvalues", fraction=0.5)
    t0 = time.perf_counter()
    q3 = state_3d(model, q) if coupled else planar_state(model, q, scene.name)
    lin = linearise(model, q3)
    if lin.asymmetry > MAX_ASYMMETRY:
        return ModalResult("ancf", scene.name, Status.NOT_CONVERGED,
                           f"the tangent is not symmetric (max|K - K^T| = {lin.asymmetry:.3g}"
                           " x max|K|): a non-conservative term entered it",
                           wall_time_s=time.perf_counter() - t0,
                           info={"static_wall_time_s": static_s, "asymmetry": lin.asymmetry})
    samples = sample_points(model.mesh)
    modes, negative = [], 0
    families = ((COUPLED, lin.free, 2 * count),) if coupled else \
        tuple((plane, lin.family(plane), count) for plane in PLANES)
    for plane, idx, wanted in families:
        try:
            lam, vec = eigenpairs(lin, idx, wanted)
        except (RuntimeError, ValueError, sla.ArpackError) as exc:
            return ModalResult("ancf", scene.name, Status.NOT_CONVERGED,
                               f"{plane} eigenvalues failed: {exc}",
                               wall_time_s=time.perf_counter() - t0,
                               info={"static_wall_time_s": static_s})
        negative += int(np.sum(lam < 0.0))
        for j in range(len(lam)):
            u = sample_shape(samples, model.mesh.n, vec[:, j])
            f = math.sqrt(max(lam[j], 0.0)) / (2.0 * math.pi)
            modes.append(Mode(plane, j + 1, f, samples[0], normalise_shape(u)))
    wall = time.perf_counter() - t0
    mesh = model.mesh
    info = {"static_wall_time_s": static_s, "nodes": mesh.n, "elements": mesh.ne,
            "element_length": float(np.max(mesh.l0)), "unknowns": lin.model.N,
            "fixed": len(lin.model.ends.fixed), "asymmetry": lin.asymmetry,
            "coupling": lin.coupling, "contact_nodes": lin.contacts,
            "negative_eigenvalues": negative, "static_dimension": model.d,
            "added_mass": bool(np.any(mesh.added > 0.0) or np.any(mesh.point_added > 0.0)),
            "point_masses": int(np.count_nonzero(mesh.point_mass + mesh.point_added)),
            "drag_as_dead_load": bool(model.use_drag
                                      or getattr(model, "use_point_drag", False)),
            "force_residual": static.info.get("force_residual")}
    where = f"({mesh.ne} elements of {info['element_length']:.3g} m)"
    if coupled:
        info["out_of_plane_share"] = [out_of_plane_share(m) for m in modes]
        info["static_lateral_extent_m"] = lateral_extent(lin)
        state = "the 3D static state" if three_d else \
            "the planar static state, solved as one family"
        msg = f"{len(modes)} coupled modes about {state} {where}"
    else:
        n_in = sum(m.plane == PLANES[0] for m in modes)
        msg = (f"{n_in} in-plane and {len(modes) - n_in} out-of-plane modes about the "
               f"static state {where}")
    if negative:
        return ModalResult("ancf", scene.name, Status.NOT_CONVERGED,
                           msg + f"; {negative} negative eigenvalue(s): the static state is "
                           "not stable", modes, wall, info)
    return ModalResult("ancf", scene.name, Status.CONVERGED, msg, modes, wall, info)


# ------------------------------------------------------------------ the linearisation
class Linearised:
    """K and M (scipy CSC, in the clamped nodes' rotated slope basis) of the 3D ``model``
    about ``q`` (its unknowns), with ``free`` the indices of the unknowns not prescribed,
    ``asymmetry`` (before the symmetrisation) and ``coupling`` (the largest entry of the
    in-plane / out-of-plane blocks of K and M over the largest of each), ``contacts``
    the nodes in the seabed (y < 0)."""

    def __init__(self, model: Model, q: np.ndarray, K, M, asymmetry: float,
                 coupling: float, contacts: int):
        self.model = model
        self.q = q
        self.K = K
        self.M = M
        self.asymmetry = asymmetry
        self.coupling = coupling
        self.contacts = contacts
        fixed = np.zeros(model.N, bool)
        fixed[model.ends.fixed] = True
        self.free = np.flatnonzero(~fixed)

    def family(self, plane: str) -> np.ndarray:
        """The free unknowns of one family."""
        comp = np.zeros(6, bool)
        comp[list(FAMILY_COMPONENTS[plane])] = True
        return self.free[comp[self.free % 6]]


def planar_state(model: Model, q: np.ndarray, name: str) -> np.ndarray:
    """The static state ``q`` of ``model`` as 3D unknowns (n * 6,): z the anchor's and
    the slopes' z components 0. Raises UnsupportedSceneError when a 3D state is not planar
    (:data:`PLANAR_TOL`)."""
    n, d = model.mesh.n, model.d
    z0 = float(model.scene.ends.anchor_point[2])
    Q = np.asarray(q, float).reshape(n, 2 * d)
    out = np.zeros((n, 6))
    out[:, 0:2] = Q[:, 0:2]
    out[:, 3:5] = Q[:, d:d + 2]
    if d == 3:
        length = float(model.mesh.s[-1])
        dz = float(np.max(np.abs(Q[:, 2] - z0)))
        az = float(np.max(np.abs(Q[:, 5])))
        if dz > PLANAR_TOL * length or az > PLANAR_TOL:
            raise UnsupportedSceneError(
                f"{name}: modes: the static state is not planar (|z - z_anchor| up to "
                f"{dz:.3g} m, slope z up to {az:.3g}); only planar states are analysed")
    out[:, 2] = z0
    return out.ravel()


def state_3d(model: Model, q: np.ndarray) -> np.ndarray:
    """The static state ``q`` of ``model`` as 3D unknowns (n * 6,) for the coupled
    analysis: a 3D state as it is (no check, no rounding of z), a planar one (d = 2)
    embedded at the anchor's z."""
    if model.d == 3:
        return np.array(q, float)
    return planar_state(model, q, model.scene.name)


def lateral_extent(lin: "Linearised") -> float:
    """The largest |z - z_anchor| [m] of the nodes of the state ``lin`` is taken about."""
    z0 = float(lin.model.scene.ends.anchor_point[2])
    return float(np.max(np.abs(lin.q.reshape(-1, 6)[:, 2] - z0)))


def mass_matrix(model: Model, q: np.ndarray) -> np.ndarray:
    """The band mass matrix of ``model`` at ``q``: the consistent line mass with the added
    mass across the axis (:func:`ancf.mass.mass_pass`, coefficient 1, no inertial force)
    and the point attachments' mass and added mass on their nodes' position unknowns."""
    mesh, d, kl = model.mesh, model.d, model.kl
    M = banded.zeros(model.N, kl)
    mass_pass(q, np.zeros(0), d, mesh.l0, mesh.mass, mesh.added, model.xg, model.wg, 1.0,
              M, kl, np.zeros(0), model._none, model.use_surface, model.ysurf, model.band)
    M[2 * kl] += model.point_mass
    return M


def band_to_sparse(ab: np.ndarray, kl: int) -> sp.csc_matrix:
    """The CSC matrix of a band matrix in :mod:`ancf.banded`'s storage (A[i, j] in
    ab[2 kl + i - j, j]: column-aligned diagonals, scipy's DIA layout)."""
    n = ab.shape[1]
    rows = np.arange(kl, 3 * kl + 1)
    return sp.dia_matrix((ab[rows], 2 * kl - rows), shape=(n, n)).tocsc()


def linearise(static_model: Model, q3: np.ndarray) -> Linearised:
    """K and M of the 3D model of ``static_model``'s scene and mesh about the embedded
    static state ``q3`` (module docstring)."""
    scene, mesh = static_model.scene, static_model.mesh
    model = Model(scene, mesh, 3, current=False, gauss_points=len(static_model.xg))
    model.use_drag = False                 # the static drag is a dead load: no stiffness
    kl, N = model.kl, model.N
    _, K, _ = model.residual(q3)
    # the joints' out-of-plane stiffness (isotropic joint): k / |r'|^2 at the slope's z,
    # the Hessian of k/2 psi^2 about a planar state (r'_z = 0) only
    for node, k, _ in model.ends.springs:
        i = model.ends.dof(node, 3)
        if abs(q3[i + 2]) > PLANAR_TOL * math.hypot(q3[i], q3[i + 1]):
            raise UnsupportedSceneError(
                f"{scene.name}: modes: the flex joint at node {node} leans out of the plane "
                f"(slope z {q3[i + 2]:.3g}); its stiffness is modelled about a planar "
                "state only")
        a2 = float(q3[i] ** 2 + q3[i + 1] ** 2 + q3[i + 2] ** 2)
        K[2 * kl, i + 2] += k / a2
    M = mass_matrix(model, q3)
    contacts = 0
    if model.use_seabed:
        contacts = int(np.sum(q3.reshape(-1, 6)[:, 1] < 0.0))
    rotate(model.ends, K, np.zeros(N), kl)
    rotate(model.ends, M, np.zeros(N), kl)
    Ks, Ms = band_to_sparse(K, kl), band_to_sparse(M, kl)
    kmax = float(abs(Ks).max())
    asym = float(abs(Ks - Ks.T).max()) / kmax if kmax > 0.0 else 0.0
    Ks = (0.5 * (Ks + Ks.T)).tocsc()
    Ms = (0.5 * (Ms + Ms.T)).tocsc()       # symmetric by construction (the same products)
    inp = np.flatnonzero(np.isin(np.arange(N) % 6, FAMILY_COMPONENTS["in_plane"]))
    out = np.flatnonzero(np.isin(np.arange(N) % 6, FAMILY_COMPONENTS["out_of_plane"]))
    coupling = 0.0
    for A in (Ks, Ms):
        big = float(abs(A).max())
        block = A[inp][:, out]
        if big > 0.0 and block.nnz:
            coupling = max(coupling, float(abs(block).max()) / big)
    return Linearised(model, q3, Ks, Ms, asym, coupling, contacts)


def arpack_start(size: int) -> dict:
    """Keyword arguments of a reproducible ``eigsh``: the start vector ``v0`` (uniform in
    [-1, 1]) from a generator seeded with :data:`ARPACK_SEED` and, where scipy takes one,
    that generator as ``rng`` for ARPACK's restarts."""
    rng = np.random.default_rng(ARPACK_SEED)
    kw = {"v0": rng.uniform(-1.0, 1.0, size)}
    if "rng" in inspect.signature(sla.eigsh).parameters:
        kw["rng"] = rng
    return kw


def family_eigen(lin: Linearised, plane: str, count: int):
    """The ``count`` lowest eigenpairs of one family of a planar state (:func:`eigenpairs`
    on its free unknowns)."""
    return eigenpairs(lin, lin.family(plane), count)


def eigenpairs(lin: Linearised, idx: np.ndarray, count: int):
    """The ``count`` lowest eigenpairs of K x = omega^2 M x restricted to the free unknowns
    ``idx`` (a planar family's, or all of them: the coupled family): (omega^2 (k,)
    [rad2/s2], vectors (N, k) on all unknowns in the global basis, zero on the prescribed
    ones), by increasing frequency. Dense ``eigh`` for a small problem, else ARPACK in
    shift-invert mode about 0 from :func:`arpack_start`."""
    K = lin.K[idx][:, idx].tocsc()
    M = lin.M[idx][:, idx].tocsc()
    k = min(count, len(idx) - 1)
    if len(idx) <= max(64, 3 * count):          # tiny: dense
        lam, vec = sl.eigh(K.toarray(), M.toarray())
        lam, vec = lam[:k], vec[:, :k]
    else:
        lam, vec = sla.eigsh(K, k=k, M=M, sigma=0.0, which="LM", **arpack_start(len(idx)))
    order = np.argsort(lam)
    full = np.zeros((lin.model.N, k))
    full[idx] = vec[:, order]
    for j in range(k):
        unrotate(lin.model.ends, full[:, j])
    return lam[order], full


def sample_points(mesh):
    """(s (k,) [m], element (k,), Hermite weights (k, 4)) of the shapes' samples: the
    nodes and points inside each element at most OUTPUT_SPACING apart."""
    sub = np.maximum(1, np.ceil(mesh.l0 / OUTPUT_SPACING - 1e-9).astype(int))
    s_list, e_list, w_list = [], [], []
    for e in range(mesh.ne):
        L = float(mesh.l0[e])
        for j in range(sub[e]):
            xi = j / sub[e]
            N, _, _ = shape(xi, L)
            s_list.append(mesh.s[e] + xi * L)
            e_list.append(e)
            w_list.append(N)
    N, _, _ = shape(1.0, float(mesh.l0[-1]))
    s_list.append(mesh.s[-1])
    e_list.append(mesh.ne - 1)
    w_list.append(N)
    return np.array(s_list), np.array(e_list), np.array(w_list)


def sample_shape(samples, n: int, x: np.ndarray) -> np.ndarray:
    """The displacement (k, 3) of the 3D eigenvector ``x`` (global basis, n nodes) at the
    ``samples`` of :func:`sample_points`: the element's cubic Hermite interpolation of
    its nodal positions and slopes."""
    _, e, w = samples
    X = x.reshape(n, 6)
    return (w[:, 0:1] * X[e, :3] + w[:, 1:2] * X[e, 3:] + w[:, 2:3] * X[e + 1, :3]
            + w[:, 3:4] * X[e + 1, 3:])

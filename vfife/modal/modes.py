"""Natural modes of the VFIFE's discrete model about its static state, and their check
against the model's own time integration.

:func:`solve_modes` linearises the lumped-mass beam model about the static equilibrium
(:mod:`vfife.modal.tangent`: the Hessian of the element energy by central differences of the
kernel's element forces, the seabed springs at the nodes in contact, the lumped mass
pipe + contents, the added mass normal to the director) and solves ``K phi = omega^2 M
phi`` for the lowest modes with ``scipy.sparse.linalg.eigsh`` (shift-invert about 0).
Undamped: the static drag of a current is held as a dead load (its static nodal forces,
fixed: no stiffness, the model of :mod:`bvp.modal.modes`); no drag damping, friction or contact
damping.

Rotational inertia: the physical diametral inertia of the pipe wall (``rot_scale`` 1),
kept as a DOF mass rather than condensed: it is what the continuum (Rayleigh) beam has,
and the generalised problem stays sparse (condensing the rotations needs K_rr^-1, which is
dense). The lower modes do not care: rotary inertia lowers a mode of wavenumber k by
(k r_g)^2 / 2, r_g^2 = J' / (m + m_a) (3e-7 for the 10th in-plane mode of scr-steel). The
time-domain model runs with ``[vfife] rotational_inertia_scale_dynamics`` (default 4);
``solve_modes(..., rot_scale=4)`` gives the modes of that model: lower by 3/2 (k r_g)^2,
at most 3e-6 over the first 10+10 modes of scr-steel and wang2014-baseline, 2e-5 for
yu2021-a3 (a 0.41 m flexible pipe).

A planar static state (z and the directors' z within :data:`PLANAR_TOL`): the in-plane
(x, y, rotation about z) and out-of-plane (z, rotation about e_z x d) DOFs decouple
exactly there (the coupling block is checked and reported in ``info['coupling']``) and
each family (:data:`riser.results.modes.PLANES`) is solved on its own, ``count`` modes
each. A 3D static state (a current across the line's plane or turning with depth, a
hang-off out of the anchor's plane): the linearisation is the same, about the 3D state,
its two rotations about :func:`vfife.modal.tangent.normal_axes` of each director, and the
motions couple: one eigenproblem on all the free DOFs gives the ``2 count`` lowest modes,
one family :data:`riser.results.modes.COUPLED` numbered by frequency, each with its
``out_of_plane_share`` in ``info`` (the share of its squared translations along z).
:func:`free_vibration` releases the static state displaced in the shape of one mode and
integrates the model freely (:meth:`Model.run`, no drag, no damping, no top motion; about
a 3D state in a current, the static drag held as a dead load): the frequency of the
response's projection on the mode is the check of the eigen-solution.
"""

from __future__ import annotations

import inspect
import math
import time

import numpy as np
import scipy.linalg as sl
import scipy.sparse.linalg as sla

from riser.callbacks import with_fraction
from riser.errors import UnsupportedSceneError
from riser.results.modes import (COUPLED, PLANES, ModalResult, Mode, normalise_shape,
                                 out_of_plane_share)
from riser.results.result import Status

from .. import kernels
from ..ends import require_fixed_ends
from ..model import Model
from ..solver import solve
from .tangent import NDOF, Tangent, dynamic_model, linearise, normal_axes, rotate
from ..timestep import choose_step, critical_steps

#: a static state is planar when |z| and |d_z| stay below this (x the line length for z)
PLANAR_TOL = 1.0e-9

#: seed of ARPACK's start vector. Left to itself scipy starts from a random vector (a
#: fresh generator on every call in recent scipy; in older ones a seed that advances with
#: every call of the process), so two analyses of the same model differed in the last
#: digits (1e-13 to 1e-10); a fixed start repeats them bit for bit
#: (tests/test_reproducible.py).
ARPACK_SEED = 20240530


def arpack_start(size: int) -> dict:
    """Keyword arguments of a reproducible ``eigsh``: the start vector ``v0`` (uniform in
    [-1, 1], as scipy's own, from a generator seeded with :data:`ARPACK_SEED`) and, where
    scipy takes one (recent versions), that generator as ``rng`` for the random restarts
    ARPACK may ask for after finding an invariant subspace."""
    rng = np.random.default_rng(ARPACK_SEED)
    kw = {"v0": rng.uniform(-1.0, 1.0, size)}
    if "rng" in inspect.signature(sla.eigsh).parameters:
        kw["rng"] = rng
    return kw


def static_state(scene, static=None, progress=None):
    """The converged static VFIFE result of ``scene`` (``static`` when given). The scene's
    [dynamics] is dropped: the modes are about the static state. Raises
    UnsupportedSceneError for a scene without fixed ends; returns (result, its wall time
    [s])."""
    require_fixed_ends(scene)
    if static is not None:
        return static, static.wall_time_s
    t0 = time.perf_counter()
    res = solve(scene.replace(dynamics=None), progress=progress)
    return res, time.perf_counter() - t0


def out_of_plane_extent(model: Model) -> tuple[float, float]:
    """(largest |z| [m], largest |d_z| [-]) of the state of ``model``."""
    return float(np.max(np.abs(model.X[2]))), float(np.max(np.abs(model.D[2])))


def is_planar(model: Model) -> bool:
    """True when the state of ``model`` stays in the x-y plane: |z| <= :data:`PLANAR_TOL`
    x the line's length and |d_z| <= :data:`PLANAR_TOL`."""
    z, dz = out_of_plane_extent(model)
    return not (z > PLANAR_TOL * float(np.sum(model.l0)) or dz > PLANAR_TOL)


def require_planar(model: Model, name: str) -> None:
    """Raise UnsupportedSceneError when the static state leaves the x-y plane."""
    z, dz = out_of_plane_extent(model)
    if not is_planar(model):
        raise UnsupportedSceneError(
            f"{name}: modes: the static state is not planar (|z| up to {z:.3g} m, director "
            f"z up to {dz:.3g}); only planar states are analysed (an out-of-plane current "
            "couples the in-plane and out-of-plane modes)")


def family_eigen(tan: Tangent, plane: str, count: int):
    """The ``count`` lowest eigenpairs of one family: (omega^2 (k,), vectors (5n, k) on all
    DOFs, zero on the others), by increasing frequency."""
    return lowest_eigen(tan, tan.family(plane), count)


def coupled_eigen(tan: Tangent, count: int):
    """The ``count`` lowest eigenpairs of the coupled problem on all the free DOFs (a 3D
    state): (omega^2 (k,), vectors (5n, k), zero on the fixed DOFs), by increasing
    frequency."""
    return lowest_eigen(tan, tan.free_dofs(), count)


def lowest_eigen(tan: Tangent, idx: np.ndarray, count: int):
    """The ``count`` lowest eigenpairs of ``K phi = omega^2 M phi`` restricted to the DOFs
    ``idx`` (sorted global indices): (omega^2 (k,) [rad2/s2], vectors (5n, k) on all DOFs,
    zero off ``idx``), by increasing frequency; k = min(count, len(idx) - 1). Dense for a
    tiny problem, else ARPACK shift-invert about 0 from a fixed start
    (:func:`arpack_start`)."""
    K = tan.K[idx][:, idx].tocsc()
    M = tan.M[idx][:, idx].tocsc()
    k = min(count, len(idx) - 1)
    if len(idx) <= max(64, 3 * count):          # tiny: dense
        lam, vec = sl.eigh(K.toarray(), M.toarray())
        lam, vec = lam[:k], vec[:, :k]
    else:
        lam, vec = sla.eigsh(K, k=k, M=M, sigma=0.0, which="LM", **arpack_start(len(idx)))
    order = np.argsort(lam)
    full = np.zeros((tan.K.shape[0], k))
    full[idx] = vec[:, order]
    return lam[order], full


def solve_modes(scene, count: int = 10, *, static=None, progress=None,
                rot_scale: float = 1.0, coupled: bool | None = None) -> ModalResult:
    """The natural modes of the VFIFE model of the fixed-ends ``scene`` about its static
    state: the ``count`` lowest in-plane and the ``count`` lowest out-of-plane modes about a
    planar state, the ``2 count`` lowest coupled modes about a 3D one (module docstring).

    static : a converged :func:`vfife.solve` result of ``scene`` (solved here when None;
        its ``solver_state`` is the static Model). rot_scale : factor on the physical
        rotational inertia (1; the dynamics use ``[vfife] rotational_inertia_scale_dynamics``).
    coupled : None (default) by the static state (:func:`is_planar`); True the coupled
        problem on all the free DOFs whatever the state (about a planar state its modes are
        the two families' merged by frequency: a check of the coupled path); False the two
        planar families only (a 3D state is then refused).
    A scene without fixed ends or with flowing contents gives a ``refused`` result; a
    static solve that fails gives a result with its status and no modes. Shapes: the
    nodal translations (n, 3) [-], global x, y, z; ``s`` the mesh's unstretched arc length
    [m].
    """
    if count < 1:
        raise ValueError(f"count must be >= 1, got {count}")
    try:
        return _solve_modes(scene, count, static, progress, rot_scale, coupled)
    except UnsupportedSceneError as exc:
        return ModalResult("vfife", scene.name, Status.REFUSED, str(exc))


def _solve_modes(scene, count: int, static, progress, rot_scale: float,
                 coupled: bool | None) -> ModalResult:
    """:func:`solve_modes`, raising UnsupportedSceneError for what it refuses."""
    if scene.internal_flow is not None and scene.internal_flow.speed != 0.0:
        raise UnsupportedSceneError(
            f"{scene.source}: internal_flow.speed: modes do not model flowing contents (the "
            "Coriolis force makes the modes complex); set the speed to 0 for the modes of "
            "the line with its contents at rest")
    report = with_fraction(progress)
    res, static_s = static_state(scene, static, progress)
    if not res.converged:
        return ModalResult("vfife", scene.name, res.status,
                           f"no static state to analyse: {res.message}",
                           info={"static_wall_time_s": static_s})
    if coupled or (coupled is None and not is_planar(res.solver_state)):
        return _coupled_modes(scene, count, res, static_s, report, rot_scale)
    return _planar_modes(scene, count, res, static_s, report, rot_scale)


def _planar_modes(scene, count: int, res, static_s: float, report,
                  rot_scale: float) -> ModalResult:
    """The ``count`` lowest modes of each planar family (:data:`PLANES`) about the planar
    static state of ``res``, ``static_s`` [s] its wall time; UnsupportedSceneError for a
    3D state."""
    require_planar(res.solver_state, scene.name)
    if report is not None:
        report("vfife modes: tangent stiffness and eigenvalues")
    t0 = time.perf_counter()
    model = dynamic_model(scene, res.solver_state, rot_scale)
    tan = linearise(model)
    n, s = model.mesh.n, model.mesh.s.copy()
    modes, negative = [], 0
    for plane in PLANES:
        try:
            lam, vec = family_eigen(tan, plane, count)
        except (RuntimeError, ValueError, sla.ArpackError) as exc:
            return ModalResult("vfife", scene.name, Status.NOT_CONVERGED,
                               f"{plane} eigenvalues failed: {exc}",
                               wall_time_s=time.perf_counter() - t0,
                               info={"static_wall_time_s": static_s})
        negative += int(np.sum(lam < 0.0))
        modes += _modes_of(plane, lam, vec, n, s)
    wall = time.perf_counter() - t0
    msg = (f"{sum(m.plane == PLANES[0] for m in modes)} in-plane and "
           f"{sum(m.plane == PLANES[1] for m in modes)} out-of-plane modes about the static "
           f"state ({n} nodes)")
    if negative:
        msg += f"; {negative} negative eigenvalue(s): the static state is not stable"
    info = _info(static_s, model, tan, rot_scale, negative, res)
    return ModalResult("vfife", scene.name, Status.CONVERGED, msg, modes, wall, info)


def _modes_of(plane: str, lam: np.ndarray, vec: np.ndarray, n: int,
              s: np.ndarray) -> list[Mode]:
    """The modes of eigenpairs (omega^2 ``lam`` (k,) [rad2/s2], ``vec`` (5n, k)) numbered
    1..k in ``plane``: the frequency [Hz] (0 for a negative eigenvalue) and the nodal
    translations at the mesh's arc lengths ``s`` [m], ``normalise_shape``d."""
    out = []
    for j in range(len(lam)):
        shape = vec[:, j].reshape(n, NDOF)[:, :3]
        f = math.sqrt(max(lam[j], 0.0)) / (2.0 * math.pi)
        out.append(Mode(plane, j + 1, f, s, normalise_shape(shape)))
    return out


def _info(static_s: float, model: Model, tan: Tangent, rot_scale: float, negative: int,
          res) -> dict:
    """The figures of a modal analysis of ``model`` (its tangent ``tan``) about the static
    result ``res`` (``static_s`` [s] its wall time), both paths' keys in their order."""
    return {"static_wall_time_s": static_s, "nodes": model.mesh.n,
            "element_length": float(np.max(model.l0)),
            "rot_scale": rot_scale, "asymmetry": tan.asymmetry, "coupling": tan.coupling,
            "contact_nodes": tan.info["contact_nodes"], "negative_eigenvalues": negative,
            "added_mass": bool(np.any(model.madd > 0.0)),
            "force_residual": res.info.get("force_residual")}


def _coupled_modes(scene, count: int, res, static_s: float, report,
                   rot_scale: float) -> ModalResult:
    """The ``2 count`` lowest modes of the coupled problem (:data:`COUPLED`) about the
    static state of ``res`` (3D, or planar when forced), ``static_s`` [s] its wall time: the
    tangent about that state with the rotations about :func:`normal_axes` of its directors,
    one eigenproblem on all the free DOFs. ``info`` holds each mode's
    ``out_of_plane_share`` (in mode order), ``static_state`` ('3d' or 'planar') and the
    state's largest |z| [m] and |d_z|."""
    static_model = res.solver_state
    three_d = not is_planar(static_model)
    if report is not None:
        report("vfife modes: tangent stiffness and eigenvalues (coupled)")
    t0 = time.perf_counter()
    model = dynamic_model(scene, static_model, rot_scale)
    tan = linearise(model, normal_axes(model.D))
    n, s = model.mesh.n, model.mesh.s.copy()
    try:
        lam, vec = coupled_eigen(tan, 2 * count)
    except (RuntimeError, ValueError, sla.ArpackError) as exc:
        return ModalResult("vfife", scene.name, Status.NOT_CONVERGED,
                           f"{COUPLED} eigenvalues failed: {exc}",
                           wall_time_s=time.perf_counter() - t0,
                           info={"static_wall_time_s": static_s})
    negative = int(np.sum(lam < 0.0))
    modes = _modes_of(COUPLED, lam, vec, n, s)
    wall = time.perf_counter() - t0
    z, dz = out_of_plane_extent(static_model)
    msg = (f"{len(modes)} coupled modes about the {'3D' if three_d else 'planar'} static "
           f"state ({n} nodes; |z| up to {z:.3g} m)")
    if negative:
        msg += f"; {negative} negative eigenvalue(s): the static state is not stable"
    info = {**_info(static_s, model, tan, rot_scale, negative, res),
            "static_state": "3d" if three_d else "planar",
            "out_of_plane_z_m": z, "out_of_plane_director_z": dz,
            "out_of_plane_share": [out_of_plane_share(m) for m in modes]}
    return ModalResult("vfife", scene.name, Status.CONVERGED, msg, modes, wall, info)


def held_drag(model: Model) -> np.ndarray:
    """The static drag of a current as a dead load (3, n) [N], global x, y, z: the nodal
    forces that hold the state of ``model`` (at rest, its static state) in equilibrium
    without the drag, i.e. minus the sum at each free node of the elements' forces (the
    kernel's :func:`vfife.kernels.element_pass`), the weight and the seabed's reaction
    (the kernels' spring ``-kst min(y, 0)`` along y). At a static equilibrium in a current
    this is the static drag, plus the static solve's residual, which it absorbs (the
    released state is an equilibrium to round-off); zero at the end nodes (held)."""
    n, ne = model.mesh.n, model.mesh.ne
    f = [np.zeros(ne) for _ in range(9)]
    rows = [np.ascontiguousarray(r) for r in (*model.X, *model.D)]
    kernels.element_pass(*rows, model.l0, model.kax, model.kb, *f)
    F = np.stack(f[:3])                        # force of element e on its node e (end a)
    g = np.zeros((3, n))
    g[:, 1:-1] = F[:, 1:] - F[:, :-1]
    g[1, 1:-1] -= model.wload[1:-1] + model.kst[1:-1] * np.minimum(model.X[1, 1:-1], 0.0)
    return -g


def _excited_model(scene, static_model: Model, tan: Tangent, vec: np.ndarray,
                   amplitude: float, rot_scale: float, planar: bool,
                   hold_drag: bool = False) -> Model:
    """Dynamic model released from the static state + ``amplitude`` x the mode ``vec``
    (translations scaled to a largest component of ``amplitude`` [m]), drag, friction and
    contact damping off; ``hold_drag``: the static drag held as a dead load
    (:func:`held_drag`, computed at the static state before the release)."""
    model = dynamic_model(scene, static_model, rot_scale, planar=planar)
    if hold_drag:
        model.P = held_drag(model)
        model.use_dead = True
    n = model.mesh.n
    v = vec.reshape(n, NDOF)
    a = amplitude / float(np.max(np.abs(v[:, :3])))
    model.X += a * v[:, :3].T
    D = model.D
    for k in range(2):
        D = rotate(D, tan.basis[:, k].T, a * v[:, 3 + k])
    model.D[:] = D / np.linalg.norm(D, axis=0)
    model.use_drag = False
    model.mu = 0.0
    model.cseabed = np.zeros(n)
    return model


def free_vibration(scene, plane: str = "in_plane", number: int = 1, *, static=None,
                   rot_scale: float | None = None, periods: float = 6.0,
                   amplitude: float | None = None) -> dict:
    """Frequency of the free vibration of the time-domain model released in mode
    ``number`` of ``plane`` (one of :data:`PLANES` about a planar static state, or
    :data:`COUPLED`: the coupled problem of :func:`solve_modes`, about a 3D or a planar
    state): the static state displaced by the mode (translations and rotations, largest
    translation ``amplitude`` [m], default 1e-5 x the line length), integrated by
    :meth:`Model.run` for ``periods`` periods with no damping, drag, friction or top
    motion. The frequency is read from the upward zero crossings of the mass-weighted
    projection of the translations on the mode (linear interpolation).

    rot_scale : rotational inertia factor of the time-domain model (default the scene's
        ``rotational_inertia_scale_dynamics``; the eigen-solution is computed with the same).
    Returns frequency_hz (measured), modal_frequency_hz, rel_diff, time_step, steps, wall_s.
    A coupled mode runs on the 3D kernels, with the static drag of a current held as a
    dead load (:func:`held_drag`: the modes' model of the drag), so a 3D state in a
    current is checked about its own equilibrium. A planar family with a current raises
    ValueError: the planar check releases the line without its drag, and the static state
    would then not be an equilibrium (the line would drift, not vibrate about it); the
    coupled check applies.
    """
    coupled = plane == COUPLED
    if not coupled and plane not in PLANES:
        raise ValueError(f"plane must be one of {PLANES + (COUPLED,)}, got {plane!r}")
    if not coupled and scene.current is not None and scene.current.max_abs_speed > 0.0:
        raise ValueError(f"{scene.name}: free vibration: the scene has a current, whose "
                         "static drag the released model (no drag) does not carry; the "
                         f"check applies without current (or to the '{COUPLED}' modes, "
                         "which hold it as a dead load)")
    if plane != "in_plane" and not getattr(scene.ends, "plain", True):
        raise ValueError(f"{scene.name}: free vibration {plane.replace('_', ' ')}: the 3D "
                         "kernels hold their ends pinned (a joint, a tensioner or a free "
                         "end is the planar kernels'); the check applies in plane")
    res, _ = static_state(scene, static)
    if not res.converged:
        raise ValueError(f"{scene.name}: no static state: {res.message}")
    if not coupled:
        require_planar(res.solver_state, scene.name)
    rs = scene.vfife.rotational_inertia_scale_dynamics if rot_scale is None else rot_scale
    static_model = res.solver_state
    if coupled:
        tan = linearise(dynamic_model(scene, static_model, rs), normal_axes(static_model.D))
        lam, vec = coupled_eigen(tan, number)
    else:
        tan = linearise(dynamic_model(scene, static_model, rs))
        lam, vec = family_eigen(tan, plane, number)
    f_modal = math.sqrt(lam[number - 1]) / (2.0 * math.pi)
    phi = vec[:, number - 1]
    L = float(np.sum(static_model.l0))
    amp = 1.0e-5 * L if amplitude is None else amplitude
    model = _excited_model(scene, static_model, tan, phi, amp, rs,
                           planar=static_model.planar and plane == "in_plane",
                           hold_drag=coupled and scene.current is not None
                           and scene.current.max_abs_speed > 0.0)
    mesh = model.mesh
    tmax = float(np.max(np.abs(static_model.nodal_results()["element_tension"])))
    steps = critical_steps(mesh, rot_scale=rs, tension=1.5 * tmax,
                           added_mass=bool(np.any(model.madd > 0.0)),
                           seabed_stiffness=model.kseabed)
    dt, _ = choose_step(steps, scene.vfife.time_step_safety)
    period = 1.0 / f_modal
    nsub = max(1, int(period / 40.0 / dt))          # ~40 samples a period
    nsamp = int(math.ceil(periods * period / (nsub * dt)))
    n = mesh.n
    # mass-weighted projection of the translations on the mode
    wt = (tan.M @ phi).reshape(n, NDOF)[:, :3].T
    X0 = static_model.X.copy()
    q = np.empty(nsamp + 1)
    q[0] = float(np.sum(wt * (model.X - X0)))
    t0 = time.perf_counter()
    for j in range(nsamp):
        *_, status = model.run(nsub, dt, 0.0)
        if status == 2:
            raise RuntimeError(f"{scene.name}: free vibration blew up at step {model.steps}")
        q[j + 1] = float(np.sum(wt * (model.X - X0)))
    wall = time.perf_counter() - t0
    t = np.arange(nsamp + 1) * nsub * dt
    q -= np.mean(q)
    up = np.nonzero((q[:-1] < 0.0) & (q[1:] >= 0.0))[0]
    tc = t[up] - q[up] * (t[up + 1] - t[up]) / (q[up + 1] - q[up])
    if len(tc) < 2:
        raise RuntimeError(f"{scene.name}: free vibration: fewer than two zero crossings")
    f = (len(tc) - 1) / (tc[-1] - tc[0])
    return {"frequency_hz": f, "modal_frequency_hz": f_modal, "rel_diff": f / f_modal - 1.0,
            "rot_scale": rs, "time_step": dt, "steps": model.steps, "wall_s": wall,
            "crossings": len(tc)}

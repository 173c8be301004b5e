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

Only planar static states: the in-plane (x, y, rotation about z) and out-of-plane (z,
rotation about e_z x d) DOFs decouple exactly there (the coupling block is checked and
reported in ``info['coupling']``) and each family is solved on its own.
:func:`free_vibration` releases the static state displaced in the shape of one mode and
integrates the model freely (:meth:`Model.run`, no drag, no damping, no top motion): the
frequency of the response's projection on the mode is the check of the eigen-solution.
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
from riser.results.modes import PLANES, ModalResult, Mode, normalise_shape
from riser.results.result import Status

from ..ends import require_fixed_ends
from ..model import Model
from ..solver import solve
from .tangent import NDOF, Tangent, dynamic_model, linearise, rotate
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


def require_planar(model: Model, name: str) -> None:
    """Raise UnsupportedSceneError when the static state leaves the x-y plane."""
    L = float(np.sum(model.l0))
    z = float(np.max(np.abs(model.X[2])))
    dz = float(np.max(np.abs(model.D[2])))
    if z > PLANAR_TOL * L or dz > PLANAR_TOL:
        raise UnsupportedSceneError(
            f"{name}: modes: the static state is not planar (|z| up to {z:.3g} m, director "
            f"z up to {dz:.3g}); only planar states are analysed (an out-of-plane current "
            "couples the in-plane and out-of-plane modes)")


def family_eigen(tan: Tangent, plane: str, count: int):
    """The ``count`` lowest eigenpairs of one family: (omega^2 (k,), vectors (5n, k) on all
    DOFs, zero on the others), by increasing frequency."""
    idx = tan.family(plane)
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
                rot_scale: float = 1.0) -> ModalResult:
    """The ``count`` lowest in-plane and out-of-plane modes of the VFIFE model of the
    fixed-ends ``scene`` about its static state.

    static : a converged :func:`vfife.solve` result of ``scene`` (solved here when None;
        its ``solver_state`` is the static Model). rot_scale : factor on the physical
        rotational inertia (1; the dynamics use ``[vfife] rotational_inertia_scale_dynamics``).
    A scene without fixed ends, with flowing contents or with a non-planar static state
    gives a ``refused`` result; a static solve that fails gives a result with its status
    and no modes. Shapes: the nodal translations (n, 3), ``s`` the mesh's unstretched arc
    length.
    """
    if count < 1:
        raise ValueError(f"count must be >= 1, got {count}")
    try:
        return _solve_modes(scene, count, static, progress, rot_scale)
    except UnsupportedSceneError as exc:
        return ModalResult("vfife", scene.name, Status.REFUSED, str(exc))


def _solve_modes(scene, count: int, static, progress, rot_scale: float) -> ModalResult:
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
        for j in range(len(lam)):
            shape = vec[:, j].reshape(n, NDOF)[:, :3]
            f = math.sqrt(max(lam[j], 0.0)) / (2.0 * math.pi)
            modes.append(Mode(plane, j + 1, f, s, normalise_shape(shape)))
    wall = time.perf_counter() - t0
    msg = (f"{sum(m.plane == PLANES[0] for m in modes)} in-plane and "
           f"{sum(m.plane == PLANES[1] for m in modes)} out-of-plane modes about the static "
           f"state ({n} nodes)")
    if negative:
        msg += f"; {negative} negative eigenvalue(s): the static state is not stable"
    info = {"static_wall_time_s": static_s, "nodes": n,
            "element_length": float(np.max(model.l0)),
            "rot_scale": rot_scale, "asymmetry": tan.asymmetry, "coupling": tan.coupling,
            "contact_nodes": tan.info["contact_nodes"], "negative_eigenvalues": negative,
            "added_mass": bool(np.any(model.madd > 0.0)),
            "force_residual": res.info.get("force_residual")}
    return ModalResult("vfife", scene.name, Status.CONVERGED, msg, modes, wall, info)


def _excited_model(scene, static_model: Model, tan: Tangent, vec: np.ndarray,
                   amplitude: float, rot_scale: float, planar: bool) -> Model:
    """Dynamic model released from the static state + ``amplitude`` x the mode ``vec``
    (translations scaled to a largest component of ``amplitude`` [m]), drag, friction and
    contact damping off."""
    model = dynamic_model(scene, static_model, rot_scale, planar=planar)
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
    ``number`` of ``plane``: the static state displaced by the mode (translations and
    rotations, largest translation ``amplitude`` [m], default 1e-5 x the line length),
    integrated by :meth:`Model.run` for ``periods`` periods with no damping, drag,
    friction or top motion. The frequency is read from the upward zero crossings of the
    mass-weighted projection of the translations on the mode (linear interpolation).

    rot_scale : rotational inertia factor of the time-domain model (default the scene's
        ``rotational_inertia_scale_dynamics``; the eigen-solution is computed with the same).
    Returns frequency_hz (measured), modal_frequency_hz, rel_diff, time_step, steps, wall_s.
    A scene with a current raises ValueError: released without its drag (the time-domain
    model cannot hold the drag as the modes' dead load) the static state is not an
    equilibrium, and the line would drift, not vibrate about it.
    """
    if scene.current is not None and scene.current.max_abs_speed > 0.0:
        raise ValueError(f"{scene.name}: free vibration: the scene has a current, whose "
                         "static drag the released model (no drag) does not carry; the "
                         "check applies without current")
    if plane == "out_of_plane" and not getattr(scene.ends, "plain", True):
        raise ValueError(f"{scene.name}: free vibration out of plane: the 3D kernels hold "
                         "their ends pinned (a joint, a tensioner or a free end is the "
                         "planar kernels'); the check applies in plane")
    res, _ = static_state(scene, static)
    if not res.converged:
        raise ValueError(f"{scene.name}: no static state: {res.message}")
    require_planar(res.solver_state, scene.name)
    rs = scene.vfife.rotational_inertia_scale_dynamics if rot_scale is None else rot_scale
    static_model = res.solver_state
    tan = linearise(dynamic_model(scene, static_model, rs))
    lam, vec = family_eigen(tan, plane, number)
    f_modal = math.sqrt(lam[number - 1]) / (2.0 * math.pi)
    phi = vec[:, number - 1]
    L = float(np.sum(static_model.l0))
    amp = 1.0e-5 * L if amplitude is None else amplitude
    model = _excited_model(scene, static_model, tan, phi, amp, rs,
                           planar=static_model.planar and plane == "in_plane")
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

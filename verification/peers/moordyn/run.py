"""MoorDyn (MoorDyn-C v2, the optional extra ``[moordyn]``) as a peer: the static state of
a scene's exported deck, read back as a profile in the scene's coordinates.

How MoorDyn is run (MoorDyn-C 2.7, measured in issue 17):

- **Statics**: ``moordyn.Init``'s stationary solver, a pseudo-time relaxation from MoorDyn's
  own catenary start (the free points from the deck). Its ``threshIC`` stops it when its
  mean acceleration stalls, which with bending happens long before equilibrium, so the deck
  sets ``threshIC`` tiny and the run is bounded by ``TmaxIC`` [s of pseudo-time] instead;
  the result is then checked here, not trusted: the **force residual** is the largest net
  force on an interior node (MoorDyn's ``GetLineNodeForce``, which sums tension, bending,
  weight, seabed and drag) over that node's load q l, q its submerged weight |w| or, when
  larger, its normal drag in the largest current speed (a light line held out by the
  current).
- **Waves** (``[environment.waves]``) are not in the static deck: MoorDyn's statics are
  still water, as the scene's (the deck says so); a dynamic run writes them
  (:mod:`.waves`).
- **A current** is not applied by MoorDyn's static solver (MoorDyn-C 2.7 runs it without
  water kinematics): the state is then time-stepped with the current on (RK2, at 0.3 of
  MoorDyn's CFL-0.5 step: that step is unstable in dynamics on a riser with bending) until
  the motion stops: the largest node speed below ``SPEED_TOL`` and the force residual below
  the tolerance at one check. The simulated and wall times it took are reported.
- **Outputs**, per node: position; tension, MoorDyn's ``GetLineNodeTen`` (interior nodes:
  the mean of the two adjacent segment tensions; at a joint between lines the same mean
  across the joint), and at the two ends **the end-node force** |``GetLineNodeForce``|, the
  force on the fixed point, which MoorDyn's FairTen output channel writes; the
  end-segment tension (``GetLineFairTen``, half a segment below the end) is kept beside
  it in ``info``; curvature ``GetLineNodeCurv`` (4 sin(a/2)/(l1 + l2), 0 at pinned ends
  and at joints, which are hinges); moment = EI x curvature, signed with the turning
  direction in the x-y plane.
- **A 3D scene** (the hang-off out of the anchor's plane, a current out of the x-y plane
  or turning with depth) runs the same way: the deck holds the 3D points and current
  (:mod:`riser.io.moordyn.deck_from_scene`) and MoorDyn solves in 3D. Its profile then
  carries ``lateral``, ``moment_in_plane`` and ``moment_out_of_plane``
  (:func:`riser.model.frame.plane_columns`): MoorDyn gives no moment vector, so the node's is
  rebuilt as its Line.cpp bends the node, EI x GetLineNodeCurv about the axis q_{i-1} x
  q_i of its two segments' directions (0 at the ends and joints, where the curvature
  is), with the node's tangent along q_{i-1} + q_i; the shear is |dM/ds| of that vector.

MoorDyn prints to the process's stdout from C++; everything it prints goes to
``moordyn.log`` in the run's folder instead.
"""

from __future__ import annotations

import contextlib
import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from riser.errors import SceneError
from riser.model.frame import LinePlane, plane_columns
from riser.results.profile import Profile
from riser.results.result import Status
from riser.model.scene import Scene
from riser.results.recorder import touchdown_s

from .deck import DeckFiles, export

#: the force residual (net force on an interior node / its load, :func:`_residual`) accepted as
#: static equilibrium: 1 % of a node's weight moves the tension by far less than the
#: comparison's tolerances (measured: 0.02 % of the hang-off tension on the SCR)
RESIDUAL_TOL = 0.01
#: node speed [m/s] below which the motion under a current has stopped
SPEED_TOL = 1.0e-3
#: first pseudo-time of the static solver [s], the wall time [s] its doublings may take,
#: and the simulated time [s] allowed to settle in a current
IC_TIME = 3000.0
IC_BUDGET = 300.0
SETTLE_TIME = 3000.0
#: the dynamic step as a fraction of MoorDyn's CFL-0.5 step (0.5 and 0.2-0.25 blew up on
#: the 10 m SCR deck; 0.15-0.18 ran)
STEP_FRACTION = 0.3

MISSING = ("the MoorDyn peer needs the optional package moordyn (MoorDyn-C v2): "
           "pip install -e '.[moordyn]'")


def require() -> None:
    """Raise a one-line :class:`SceneError` (exit 2) when moordyn cannot be imported."""
    try:
        import moordyn  # noqa: F401
    except ImportError:
        raise SceneError("command line", "--peer moordyn", MISSING) from None


@dataclass
class PeerRun:
    """A MoorDyn run: status, message, the profile (scene coordinates, s of the original
    scene), ``info`` (times, residuals, both end tensions, mesh), the deck files."""

    status: Status
    message: str
    profile: Profile | None
    info: dict = field(default_factory=dict)
    files: DeckFiles | None = None

    @property
    def converged(self) -> bool:
        return self.status is Status.CONVERGED


@contextlib.contextmanager
def _to_log(path: Path):
    """Send what C++ code prints (file descriptors 1 and 2) to ``path``."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o644)
    os.dup2(fd, 1)
    os.dup2(fd, 2)
    os.close(fd)
    try:
        yield
    finally:
        try:
            import ctypes
            ctypes.CDLL(None).fflush(None)
        except (OSError, AttributeError):
            pass
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for f in saved:
            os.close(f)


def start(scene: Scene, folder: Path, *, segment_length: float, pseudo_time: float,
          profile=None, hang_off: str = "Fixed", waves: bool = False, joints=None):
    """Export ``scene`` to ``folder``/deck.dat, then MoorDyn's Create and Init (its static
    solver for ``pseudo_time`` s; a Coupled hang-off starts at its deck position):
    (system, lines, deck files, Init's wall time [s], Init's return code). ``waves``: the
    deck holds the scene's waves (WaveKin 7; MoorDyn-C's static solver runs without them,
    its clock starts at 0 after Init); still water otherwise. ``joints``: the free points'
    (positions, origin) instead of a solve (:func:`.deck.export`)."""
    import moordyn
    files = export(scene, folder / "deck.dat", segment_length=segment_length,
                   profile=profile, hang_off=hang_off, waves=waves, joints=joints,
                   ic={"TmaxIC": pseudo_time, "threshIC": 1e-12, "dtIC": 10.0})
    top = files.export.deck.points[-1]
    x0 = [top.x, top.y, top.z] if hang_off == "Coupled" else []
    with _to_log(folder / "moordyn.log"):
        system = moordyn.Create(str(files.deck_path))
        moordyn.SetVerbosity(system, moordyn.LEVEL_ERR)
        t0 = time.perf_counter()
        code = moordyn.Init(system, x0, [0.0] * len(x0))
        wall = time.perf_counter() - t0
    lines = [moordyn.GetLine(system, k + 1) for k in range(len(files.export.deck.lines))]
    return system, lines, files, wall, code


def coupled_statics(scene, folder, segment_length, profile, pseudo, log, waves: bool = False):
    """MoorDyn's statics with a Coupled hang-off, the pseudo-time doubled as in
    :func:`.run.run`: (system, lines, files, residual, pseudo-time, wall time in all).
    ``waves``: the deck holds the scene's waves (its statics are still water)."""
    import moordyn
    spent = 0.0
    while True:
        system, lines, files, wall, code = start(scene, folder, segment_length=segment_length,
                                                 pseudo_time=pseudo, profile=profile,
                                                 hang_off="Coupled", waves=waves)
        spent += wall
        if code not in (0, None):
            close(system, folder)
            raise RuntimeError(f"MoorDyn's Init returned error {code}")
        res = _residual(moordyn, lines, files.scene, files)
        log(f"moordyn: statics {pseudo:g} s of pseudo-time, {wall:.1f} s, residual "
            f"{100 * res:.2g} % of a node's weight")
        if res <= RESIDUAL_TOL or spent + 2.0 * wall > IC_BUDGET:
            return system, lines, files, res, pseudo, spent
        close(system, folder)
        pseudo *= 2.0


def close(system, folder: Path) -> None:
    import moordyn
    with _to_log(Path(folder) / "moordyn.log"):
        moordyn.Close(system)


def run(scene: Scene, folder: Path, *, segment_length: float = 10.0, profile=None,
        ic_time: float = IC_TIME, budget: float = IC_BUDGET,
        settle_time: float = SETTLE_TIME, progress=None) -> PeerRun:
    """Export ``scene`` to ``folder``/deck.dat and solve its statics with MoorDyn.

    segment_length : MoorDyn segment length [m]. profile : a solved profile of the
    fixed-ends scene to start the free points from (default: the BVP's). ic_time : the
    first pseudo-time of the static solver [s], doubled (a new run: MoorDyn's solver
    cannot be resumed) while the force residual is above :data:`RESIDUAL_TOL` and the next
    run fits in ``budget`` s of wall time; settle_time : simulated time allowed to settle
    in a current [s].
    """
    require()
    import moordyn

    now = progress or (lambda msg, fraction=None: None)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "moordyn.log").write_text("")
    pseudo, spent = ic_time, 0.0
    while True:
        now(f"moordyn: static solve, {pseudo:g} s of pseudo-time")
        system, lines, files, wall, code = start(scene, folder, segment_length=segment_length,
                                                 pseudo_time=pseudo, profile=profile)
        spent += wall
        if code not in (0, None):
            close(system, folder)
            return PeerRun(Status.DIVERGED, f"MoorDyn's Init returned error {code} (see "
                           f"{folder / 'moordyn.log'})", None, {}, files)
        res = _residual(moordyn, lines, files.scene, files)
        if (res <= RESIDUAL_TOL or files.scene.current is not None
                or spent + 2.0 * wall > budget):
            break
        close(system, folder)
        pseudo *= 2.0
    fixed = files.scene
    info: dict = {"segment_length": segment_length, "segments": sum(
        ln.segments for ln in files.export.deck.lines), "ic_pseudo_time_s": pseudo,
        "ic_wall_s": wall, "ic_total_wall_s": spent, "ic_force_residual": res}
    try:
        if fixed.current is not None:
            status, msg = _settle(moordyn, system, lines, fixed, files, info, settle_time,
                                  folder / "moordyn.log", now)
            if status is not Status.CONVERGED:
                return PeerRun(status, msg, None, info, files)
        prof = _profile(moordyn, lines, fixed, files, info)
    finally:
        close(system, folder)
    res = info.get("force_residual", res)
    info["force_residual"] = res
    if not prof.is_finite():
        return PeerRun(Status.DIVERGED, "MoorDyn's state holds NaN/inf", None, info, files)
    if res > RESIDUAL_TOL:
        return PeerRun(Status.NOT_CONVERGED, f"MoorDyn's static solver stopped after "
                       f"{pseudo:g} s of pseudo-time ({wall:.1f} s; {spent:.1f} s in all, "
                       f"budget {budget:g} s) with a force residual of {100 * res:.2g} % of "
                       f"a node's load (accepted: {100 * RESIDUAL_TOL:g} %); raise the "
                       "budget or coarsen the segments", prof, info, files)
    how = (f"settled in the current after {info['settle_sim_s']:g} s simulated "
           f"({info['settle_wall_s']:.1f} s)" if fixed.current is not None else
           f"static solver {pseudo:g} s of pseudo-time ({wall:.1f} s; {spent:.1f} s in all)")
    return PeerRun(Status.CONVERGED, f"{how}, force residual {100 * res:.2g} % "
                   "of a node's load", prof, info, files)


def _nodes(moordyn, line):
    n = moordyn.GetLineN(line)
    return n, np.array([moordyn.GetLineNodePos(line, i) for i in range(n + 1)])


def _residual(moordyn, lines, scene: Scene, files: DeckFiles) -> float:
    """Largest |net force| on an interior node over its load q l, q the larger of the
    segment's submerged weight |w| and its normal drag in the largest current speed
    (drag_normal_coef U_max^2 [N/m]; the weight alone unless a neutrally buoyant or light
    line is held out by the current)."""
    worst = 0.0
    for line, idx in zip(lines, files.export.line_segments):
        n = moordyn.GetLineN(line)
        q = _load(scene, idx[0])
        length = moordyn.GetLineUnstretchedLength(line) / n
        for i in range(1, n):
            f = np.linalg.norm(moordyn.GetLineNodeForce(line, i))
            worst = max(worst, f / max(q * length, 1e-9))
    return float(worst)


def _load(scene: Scene, seg: int) -> float:
    """The load per metre [N/m] a node's residual is measured against (:func:`_residual`)."""
    from riser.model.sections import segment_properties
    p = segment_properties(scene)[seg]
    u = 0.0 if scene.current is None else scene.current.max_abs_speed
    return max(abs(p.weight), p.drag_normal_coef * u * u)


def _settle(moordyn, system, lines, scene, files, info, limit, log, now):
    """Time-step with the current on until the motion stops (see the module docstring)."""
    import cmoordyn  # moordyn.GetDt returns None in 2.7 (its wrapper drops the value)
    dt0 = cmoordyn.get_dt(system)
    cmoordyn.set_dt(system, STEP_FRACTION * dt0)
    info["dynamic_step_s"] = STEP_FRACTION * dt0
    t, chunk = 0.0, 1.0
    t0 = time.perf_counter()
    while t < limit:
        try:
            with _to_log(log):          # MoorDyn's prints; the progress line stays on stderr
                moordyn.Step(system, [], [], t, chunk)
        except RuntimeError as exc:
            return Status.DIVERGED, f"MoorDyn diverged in the current at t = {t:g} s ({exc})"
        t += chunk
        speed = max(float(np.max(np.linalg.norm(
            [moordyn.GetLineNodeVel(ln, i) for i in range(moordyn.GetLineN(ln) + 1)],
            axis=1))) for ln in lines)
        if int(t) % 20 == 0:
            now(f"moordyn: settling in the current, t = {t:g} s, max speed "
                f"{speed:.2g} m/s", fraction=t / limit)
        if speed < SPEED_TOL:
            res = _residual(moordyn, lines, scene, files)
            if res <= RESIDUAL_TOL:
                info.update(settle_sim_s=t, settle_wall_s=time.perf_counter() - t0,
                            force_residual=res, settle_speed=speed)
                return Status.CONVERGED, ""
    info.update(settle_sim_s=t, settle_wall_s=time.perf_counter() - t0)
    return Status.NOT_CONVERGED, (f"MoorDyn still moved after {limit:g} s simulated in the "
                                  f"current (max node speed {speed:.2g} m/s, stop at "
                                  f"{SPEED_TOL:g})")


def _profile(moordyn, lines, scene: Scene, files: DeckFiles, info: dict) -> Profile:
    """The MoorDyn state as a profile of the original scene (see the module docstring)."""
    depth = scene.water_depth if scene.water_depth is not None else scene.ends.hang_off[1]
    S, P, T, K, EI = [], [], [], [], []
    seg_T = []
    for k, (line, (s0, s1)) in enumerate(zip(lines, files.export.line_span)):
        n, pos = _nodes(moordyn, line)
        ten = np.array([np.linalg.norm(moordyn.GetLineNodeTen(line, i)) for i in range(n + 1)])
        curv = np.array([moordyn.GetLineNodeCurv(line, i) for i in range(n + 1)])
        ei = files.export.deck.line_types[files.export.deck.lines[k].line_type].EI
        s = s0 + (s1 - s0) * np.arange(n + 1) / n
        seg_T.append((ten[0], ten[-1]))            # the end segments' tensions
        if k > 0:                                  # a joint: MoorDyn's interior-node rule
            T[-1] = 0.5 * (seg_T[k - 1][1] + ten[0])
            S.append(s[1:]), P.append(pos[1:]), T.extend(ten[1:]), K.extend(curv[1:])
            EI.extend([ei] * n)
        else:
            S.append(s), P.append(pos), T.extend(ten), K.extend(curv), EI.extend([ei] * (n + 1))
    s = np.concatenate(S) - files.s_shift
    pos = np.concatenate(P)
    x, y, z = pos[:, 0], pos[:, 2] + depth, -pos[:, 1]
    tension = np.array(T)
    first, last = lines[0], lines[-1]
    f_bot = float(np.linalg.norm(moordyn.GetLineNodeForce(first, 0)))
    f_top = float(np.linalg.norm(moordyn.GetLineNodeForce(last, moordyn.GetLineN(last))))
    info.update(hang_off_end_node_force=f_top, hang_off_end_segment_tension=float(seg_T[-1][1]),
                anchor_end_node_force=f_bot, anchor_end_segment_tension=float(seg_T[0][0]))
    tension[0], tension[-1] = f_bot, f_top
    d = np.diff(pos, axis=0)
    seg_dir = d / np.linalg.norm(d, axis=1)[:, None]
    tang = np.vstack([seg_dir[:1], seg_dir[:-1] + seg_dir[1:], seg_dir[-1:]])
    theta = np.arctan2(tang[:, 2], np.hypot(tang[:, 0], tang[:, 1]))
    turn = np.zeros(len(s))                         # sign of d(theta)/ds in the x-y plane
    turn[1:-1] = np.sign(seg_dir[:-1, 0] * seg_dir[1:, 2] - seg_dir[:-1, 2] * seg_dir[1:, 0])
    curvature = np.array(K)
    moment = np.array(EI) * curvature
    tdp = touchdown_s(s, y, scene.seabed is not None)
    if scene.statics_planar:
        shear = np.abs(np.gradient(moment * np.where(turn < 0, -1.0, 1.0), s))
        return Profile(s=s, x=x, y=y, z=z, theta=theta, tension=tension, moment=moment,
                       shear=shear, curvature=curvature, tdp_s=tdp)
    # 3D: MoorDyn's bending moment vector at a node, EI kappa along q_{i-1} x q_i (the
    # rotation axis its Line.cpp bends about), and the tangents, both to the scene's axes
    axis = np.zeros_like(pos)
    axis[1:-1] = np.cross(seg_dir[:-1], seg_dir[1:])
    norm = np.linalg.norm(axis, axis=1)
    axis /= np.where(norm > 1e-300, norm, 1.0)[:, None]
    m_vec = _to_scene(moment[:, None] * axis)
    shear = np.linalg.norm(np.gradient(m_vec, s, axis=0), axis=1)
    unit = tang / np.linalg.norm(tang, axis=1)[:, None]
    lateral, inplane, oop = plane_columns(LinePlane.of(scene), x, z, _to_scene(unit), m_vec)
    return Profile(s=s, x=x, y=y, z=z, theta=theta, tension=tension, moment=moment,
                   shear=shear, curvature=curvature, tdp_s=tdp, lateral=lateral,
                   moment_in_plane=inplane, moment_out_of_plane=oop)


def _to_scene(v: np.ndarray) -> np.ndarray:
    """Vectors (n, 3) in MoorDyn's (X, Y, Z) -> the scene's (x, y, z) = (X, Z, -Y) (a
    rotation: cross products map alike)."""
    return np.stack([v[:, 0], v[:, 2], -v[:, 1]], axis=1)

"""Frequency-domain response to a harmonic hang-off motion about the BVP static state.

Public entry: :func:`solve_harmonic` (scene, period, motion -> :class:`riser.results.response.
HarmonicResponse`); :func:`transfer_sweep` for the transfer functions over periods.

Model: the linearised extensible beam of :mod:`bvp.modal.modes` (in plane [dx, dy, dtheta, dM,
dF, dT], out of plane [w, psi, B, Q]; mass m along the axis, m + m_a normal to it, the
seabed a vertical spring where the static line lies in it) with the damping and the drag
of :mod:`bvp.frequency.equations` (structural damping as the VFIFE's ``[dynamics]
damping``, the seabed's contact damping, Morison drag linearised by equal work over a
cycle about the static current). The touchdown stays where the static state has it: the
grounded part is the static contact zone on its linear springs (no lift-off or
touch-down over the cycle, no friction: a small-motion model). The line is wholly in the
water (no sea surface: a motion that lifts the hang-off out of it is refused).

Ends: the bottom end fixed in space; the hang-off moves by the complex amplitudes
``motion`` = (D_x, D_y, D_z) [m]; both moment-free (dM = B = 0), or keeping their
direction where ``[vfife] clamped_ends`` says so (the static state is the BVP's).

Waves (:mod:`bvp.frequency.wave_loads`): a scene with one regular train (no spectrum) and no
``motion`` given is driven by that wave: the hang-off moves as the vessel's RAOs say (at
rest without a vessel; a harmonic ``[dynamics.top_motion]`` of the same period adds to
it) and, unless ``line_loads`` is false, the line carries the wave's drag and Morison
inertia, the inhomogeneous term of :func:`bvp.frequency.equations.wave_forcing`. A trough
below the static line's highest point is refused. An irregular sea:
:mod:`bvp.frequency.sea_response`.

A 3D static state (the BVP's rod, ``SolveResult.solver_state`` a
:class:`bvp.rod.output.RodState`: a scene whose current or hang-off leaves the ends'
plane, or a planar scene solved with ``three_d=True``) is linearised as the rod, in- and
out-of-plane motion coupled in one family of ten states, with the same damping, drag
linearisation, waves, ends, grid and fixed point (:mod:`bvp.frequency.rod_harmonic`).

Method: the box scheme (midpoint rule, second order) on a grid with nodes at every
piece end, refined geometrically towards them down to an eighth of the bending length
sqrt(EI/T); one sparse complex LU per family per iteration. The drag coefficients depend
on the response's velocity amplitude: fixed-point iteration under-relaxed by
:data:`RELAXATION` (the drag-dominated limit C ~ 1/C is then solved in one step) until the
largest change of a coefficient is below ``tolerance`` times the largest coefficient.
``info['grid_change']``: the largest change of the tension and moment amplitudes (over
their peaks) when the grid is halved: the discretisation error's estimate.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
from scipy.sparse.linalg import splu

from riser.errors import UnsupportedSceneError
from riser.physics.hang_off_motion import motion_amplitudes
from riser.results.response import HarmonicResponse
from riser.results.result import SolveResult, Status
from riser.model.scene import Scene

from . import equations as he
from . import rod_harmonic as rh
from . import wave_loads as wl
from ..modal.equations import (FAMILIES, Piece, box_matrix, build_pieces,
                              require_linearisable)
from ..modal.rod_family import rod_pieces
from ..rod.output import RodState

#: under-relaxation of the drag coefficients' fixed point
RELAXATION = 0.5
#: default grid intervals over the line (before the end refinement)
INTERVALS = 6000
#: a response quantity whose peak is below this fraction of its scale is zero at first
#: order (round-off; :func:`_richardson`'s grid change leaves it out)
FIRST_ORDER_ZERO = 1e-9


def solve_harmonic(scene: Scene, period: float | None = None, motion=None, *,
                   static: SolveResult | None = None, tolerance: float = 1e-6,
                   max_iterations: int = 200, intervals: int = INTERVALS,
                   check_grid: bool = True) -> HarmonicResponse:
    """The harmonic response of the fixed-ends ``scene`` to the hang-off motion
    ``motion`` (complex amplitudes x, y, z [m]) of ``period`` [s] (see the module
    docstring). Without ``motion``: the scene's single regular wave train when it has one
    (its period; the vessel's motion and the line's wave loads), else its harmonic
    ``[dynamics.top_motion]`` (its period when ``period`` is None). A given ``motion`` is
    the hang-off's alone (the scene's waves are not applied). A scene the model does not
    represent gives a ``refused`` result; a drag linearisation that does not settle in
    ``max_iterations`` a ``not_converged`` one with the count and the last change.
    ``static``: the BVP's static result to linearise about (solved here when None; the
    rod's, a 3D state, for a scene whose static state is 3D, ValueError otherwise): the
    rod's state is linearised as the rod (:mod:`bvp.frequency.rod_harmonic`)."""
    t0 = time.perf_counter()
    name = scene.name
    try:
        period, motion, wave = wl.drive(scene, period, motion)
        require_harmonic(scene, motion)
        if wave is not None:
            ends = max(scene.ends.anchor_point[1], scene.ends.hang_off_point[1])
            wl.require_submerged(scene, wave, ends, "the line's highest end")
    except UnsupportedSceneError as exc:
        return HarmonicResponse("bvp", name, Status.REFUSED, str(exc), period or 0.0)
    if not period > 0.0:
        raise ValueError(f"period must be > 0 s, got {period}")
    if static is None:
        from ..solver import solve
        static = solve(scene)
    if not static.converged:
        return HarmonicResponse("bvp", name, static.status, "the static solution did not "
                                f"converge: {static.message}", period, motion)
    forcing = None
    if wave is not None:
        try:
            wl.require_submerged(scene, wave, float(np.max(static.profile.y)),
                                 "the static line's highest point")
        except UnsupportedSceneError as exc:
            return HarmonicResponse("bvp", name, Status.REFUSED, str(exc), period, motion)
        if scene.waves.line_loads:
            forcing = wl.LineFlow(scene, static.profile, wave, 0)
    state = static.solver_state
    if scene.out_of_plane(statics=True) is not None and not isinstance(state, RodState):
        raise ValueError("static must be the bvp's 3D rod result of the scene")
    if isinstance(state, RodState):      # the 3D rod's state: the coupled family
        pieces = rod_pieces(scene, static.profile, state)

        def on_grid(s, start=None):
            return rh.solve_on_grid(scene, state, pieces, period, motion, tolerance,
                                    max_iterations, s, start=start, forcing=forcing)
    else:
        pieces = build_pieces(scene, static.profile)

        def on_grid(s, start=None):
            return _solve(scene, pieces, period, motion, tolerance, max_iterations, s,
                          start=start, forcing=forcing)
    coarse_s = grid(pieces, intervals // 2)
    coarse = on_grid(coarse_s)
    out = coarse
    if coarse.converged and check_grid:
        fine_s = np.sort(np.concatenate([coarse_s, 0.5 * (coarse_s[1:] + coarse_s[:-1])]))
        fine = on_grid(fine_s, start=coarse.info.pop("coefficients"))
        out = fine if not fine.converged else _richardson(fine, coarse)
    out.info.pop("coefficients", None)
    if wave is not None:
        out.info["wave"] = {"period": period, "height": 2.0 * float(wave.amplitude[0]),
                            "heading_deg": math.degrees(float(wave.heading[0])),
                            "phase_deg": math.degrees(float(wave.phase[0])),
                            "line_loads": forcing is not None,
                            "vessel": scene.vessel is not None}
    out.info["static_wall_time_s"] = static.wall_time_s
    return out.replace(wall_time_s=time.perf_counter() - t0)


def transfer_sweep(scene: Scene, periods, axis: str, *, static: SolveResult | None = None,
                   amplitude: float = 1.0, **kw) -> list[HarmonicResponse]:
    """Responses per unit motion along ``axis`` over ``periods`` [s] (the transfer
    functions; with drag the response is not linear in the amplitude: ``amplitude`` [m]
    sets the one the drag is linearised at, and the amplitudes are divided by it)."""
    if static is None:
        from ..solver import solve
        static = solve(scene)
    out = []
    for p in periods:
        r = solve_harmonic(scene, p, motion_amplitudes(axis, amplitude), static=static,
                           check_grid=False, **kw)
        if r.converged:
            r = r.replace(amplitudes={k: v / amplitude for k, v in r.amplitudes.items()},
                          motion=r.motion / amplitude)
        out.append(r)
    return out


def require_wave(scene: Scene, three_d: bool = True) -> None:
    """Refuse, before solving (UnsupportedSceneError), a regular-wave scene the frequency
    domain does not represent: the checks of :func:`solve_harmonic` that need no static
    state (the drive, :func:`require_harmonic` with ``three_d``, a trough below the line's
    highest end)."""
    _, motion, wave = wl.drive(scene, None, None)
    require_harmonic(scene, motion, three_d)
    if wave is not None:
        ends = max(scene.ends.anchor_point[1], scene.ends.hang_off_point[1])
        wl.require_submerged(scene, wave, ends, "the line's highest end")


def require_harmonic(scene: Scene, motion: np.ndarray, three_d: bool = True,
                     who: str = "the frequency domain") -> None:
    """Refuse what the frequency-domain model does not represent (before solving);
    ``three_d``: a 3D static state is linearised (the rod's, :mod:`bvp.frequency.
    rod_harmonic`: the harmonic response), else refused (False: the irregular sea's
    planar model, :mod:`bvp.frequency.sea_response`); ``who`` names the analysis in the
    messages."""
    src = scene.source
    require_linearisable(scene, who, three_d=three_d)
    if not scene.ends.plain:
        raise UnsupportedSceneError(
            f"{src}: ends: the frequency domain holds both ends pinned in place; a joint, "
            "a tensioner or a free end is in the VFIFE's time domain and the modes only")
    if scene.attachments:
        raise UnsupportedSceneError(
            f"{src}: attachments: the frequency domain has no point masses or loads; a "
            "point attachment's dynamics are the VFIFE's time domain only")
    fl = scene.internal_flow
    if fl is not None and (fl.speed != 0.0 or fl.has_slug):
        raise UnsupportedSceneError(
            f"{src}: internal_flow: flowing contents or a slug are not harmonic about a "
            "static state; the frequency domain needs contents at rest")
    top_y = scene.ends.hang_off[1]
    if scene.water_depth is not None and top_y + abs(motion[1]) > scene.water_depth + 1e-9:
        raise UnsupportedSceneError(
            f"{src}: dynamics.top_motion.amplitude: the hang-off at y = {top_y:g} m rises "
            f"to {top_y + abs(motion[1]):g} m, above the sea surface at water_depth = "
            f"{scene.water_depth:g} m: the frequency domain has the line wholly in the "
            "water (lower the amplitude, or place the surface above the hang-off)")


# ------------------------------------------------------------------ the solution
def grid(pieces: list[Piece], intervals: int) -> np.ndarray:
    """Grid nodes: every piece end, ~``intervals`` over the line in proportion to the
    pieces' lengths, refined geometrically (x 1.25) towards each piece end from an
    eighth of the piece's bending length sqrt(EI / T_max)."""
    L = pieces[-1].s1 - pieces[0].s0
    nodes = [np.array([pieces[0].s0])]
    for pc in pieces:
        nk = max(8, int(math.ceil(intervals * pc.length / L)))
        u = np.linspace(0.0, 1.0, nk + 1)[1:]
        T = float(np.max(np.abs(pc.spl["T"](np.linspace(pc.s0, pc.s1, 33)))))
        lb = math.sqrt(pc.EI / T) if T > 0.0 else pc.length
        h = pc.length / nk
        if lb / 8.0 < h:
            steps = (lb / 8.0) * 1.25 ** np.arange(64)
            steps = np.cumsum(steps[steps < h])
            steps = steps[steps < 0.25 * pc.length] / pc.length
            u = np.unique(np.concatenate([u, steps, 1.0 - steps]))
        nodes.append(pc.s0 + pc.length * u[u > 0.0])
    return np.unique(np.concatenate(nodes))


def _fields(scene: Scene, pieces: list[Piece], s: np.ndarray, which: np.ndarray) -> dict:
    """Static flow and section fields at the points s (piece index ``which``)."""
    theta, y = np.empty(s.size), np.empty(s.size)
    c_n, c_t = np.empty(s.size), np.empty(s.size)
    csb = np.zeros(s.size)
    for i, pc in enumerate(pieces):
        sel = which == i
        st = pc.static(s[sel])
        theta[sel], y[sel] = st["theta"], st["y"]
        c_n[sel], c_t[sel] = pc.c_n, pc.c_t
        csb[sel] = he.contact_dashpot(scene, pc)
    cur = scene.current
    if cur is not None:
        V, Vp = cur.velocity(y)[0], cur.velocity_gradient(y)[0]     # in plane: x
    else:
        V, Vp = np.zeros(s.size), np.zeros(s.size)
    vn0, vt0 = -V * np.sin(theta), V * np.cos(theta)
    return {"theta": theta, "y": y, "V": V, "Vp": Vp, "c_n": c_n, "c_t": c_t, "csb": csb,
            "vn0": vn0, "vt0": vt0, "ft0": c_t * np.abs(vt0) * vt0,
            "ba_ea": he.damping_times(scene, pieces, s, which)}


@dataclass
class Setup:
    """What the responses on one grid share, whatever the frequency: the grid ``s`` (N +
    1,) [m], its steps ``h`` and midpoints ``mid`` (N,), the piece of each midpoint
    ``which``, the static fields ``f`` at the midpoints (:func:`_fields`; the drag
    coefficients Cn, Cz, Ct [N s/m2] are set in it by the caller), the undamped (A, B)
    per family ``ops``, the structural damping ``c_s`` [1/s] and the clamped ends."""

    pieces: list
    s: np.ndarray
    h: np.ndarray
    mid: np.ndarray
    which: np.ndarray
    f: dict
    ops: dict
    c_s: float
    clamped: tuple

    @property
    def has_drag(self) -> bool:
        return bool(np.any(self.f["c_n"] > 0.0) or np.any(self.f["c_t"] > 0.0))


def prepare(scene: Scene, pieces: list[Piece], s: np.ndarray) -> Setup:
    """The :class:`Setup` of the grid ``s``."""
    h = np.diff(s)
    mid = s[:-1] + 0.5 * h
    ends_at = np.array([pc.s1 for pc in pieces])
    which = np.clip(np.searchsorted(ends_at, mid), 0, len(pieces) - 1)
    ops = {}
    for plane, fam in FAMILIES.items():
        A = np.zeros((mid.size, fam.n, fam.n))
        B = np.zeros_like(A)
        for i, pc in enumerate(pieces):
            sel = which == i
            a, b = fam.matrices(pc, mid[sel])
            A[sel], B[sel] = np.moveaxis(a, -1, 0), np.moveaxis(b, -1, 0)
        ops[plane] = (A, B)
    c_s = scene.dynamics.damping if scene.dynamics is not None else 0.0
    return Setup(pieces, s, h, mid, which, _fields(scene, pieces, mid, which), ops, c_s,
                 tuple(scene.vfife.clamped_ends))


def respond(setup: Setup, omega: float, motion: np.ndarray, flow: dict | None = None):
    """The states (Y (N + 1, 6), Z (N + 1, 4)) [SI] at the grid's nodes for the circular
    frequency omega [rad/s], the hang-off motion (3,) complex [m] and the wave's flow at
    the midpoints (:meth:`bvp.frequency.wave_loads.LineFlow.at`, or None), with the drag
    coefficients in ``setup.f``."""
    out = []
    for plane in FAMILIES:
        g = he.wave_forcing(plane, flow, setup.f) if flow is not None else None
        out.append(_family(setup, plane, omega, motion, g))
    return out[0], out[1]


def start_coefficients(setup: Setup, flow: dict | None):
    """The drag coefficients (Cn, Cz, Ct) of the line at rest in the static current and
    the wave's flow (the small-amplitude values in a current, ~0 in still water)."""
    f = setup.f
    zero = np.zeros(setup.mid.size, complex)
    a = (flow["un"], flow["uz"], flow["ut"]) if flow is not None else (zero, zero, zero)
    return he.equivalent_coefficients(f["vn0"], f["vt0"], *a, f["c_n"], f["c_t"])


def _solve(scene, pieces, period, motion, tol, max_iter, s, start=None,
           forcing=None) -> HarmonicResponse:
    """The response on the grid ``s``; ``start``: drag coefficients (s_mid, Cn, Cz, Ct)
    of a coarser grid to start from (interpolated); ``forcing``: the wave's
    :class:`bvp.frequency.wave_loads.LineFlow` (None: no wave load)."""
    omega = 2.0 * math.pi / period
    setup = prepare(scene, pieces, s)
    f, mid = setup.f, setup.mid
    flow = forcing.at(mid, f["theta"], f["y"]) if forcing is not None else None
    Cn, Cz, Ct = start_coefficients(setup, flow)
    if start is not None:
        Cn, Cz, Ct = (np.interp(mid, start[0], c) for c in start[1:])
    has_drag = setup.has_drag
    change, it = np.inf, 0
    for it in range(1, max_iter + 1):
        f.update(Cn=Cn, Cz=Cz, Ct=Ct)
        Y, Z = respond(setup, omega, motion, flow)
        if not has_drag:
            change = 0.0
            break
        Ym, Zm = 0.5 * (Y[1:] + Y[:-1]), 0.5 * (Z[1:] + Z[:-1])
        new = he.equivalent_coefficients(f["vn0"], f["vt0"],
                                         *he.relative_velocity(Ym, Zm, omega, f, flow),
                                         f["c_n"], f["c_t"])
        old = (Cn, Cz, Ct)
        top = max(float(np.max(np.abs(c))) for c in new) or 1.0
        change = max(float(np.max(np.abs(n - o))) for n, o in zip(new, old)) / top
        Cn, Cz, Ct = (o + RELAXATION * (n - o) for n, o in zip(new, old))
        if change <= tol:
            break
    info = {"iterations": it, "last_change": change, "tolerance": tol,
            "grid_nodes": int(s.size), "drag_linearised": has_drag,
            "max_drag_coefficient": float(max(np.max(Cn), np.max(Ct))) if has_drag else 0.0}
    if change > tol:
        return HarmonicResponse("bvp", scene.name, Status.NOT_CONVERGED,
                                f"the drag linearisation did not settle in {it} iterations "
                                f"(last relative change of a coefficient {change:.3g}, "
                                f"tolerance {tol:g})", period, motion, info=info)
    info["coefficients"] = (mid, Cn, Cz, Ct)
    return _result(scene, pieces, period, motion, s, Y, Z, info)


def _family(setup: Setup, plane: str, omega: float, motion: np.ndarray,
            g: np.ndarray | None = None) -> np.ndarray:
    """States (N + 1, n) of one family by the box scheme (see the module docstring);
    ``g`` (N, n): the inhomogeneous term at the midpoints [SI] (None: none)."""
    fam = FAMILIES[plane]
    pieces, s, h = setup.pieces, setup.s, setup.h
    n, N = fam.n, h.size
    b0 = fam.clamped if "bottom" in setup.clamped else fam.pinned
    b1 = fam.clamped if "top" in setup.clamped else fam.pinned
    driven = [(k, i) for k, i in enumerate(b1)
              if fam.disp[i] is not None and motion[fam.disp[i]] != 0.0]
    loaded = g is not None and bool(np.any(g != 0.0))
    if not driven and not loaded:
        return np.zeros((N + 1, n), complex)      # neither moved nor loaded
    A, B = setup.ops[plane]
    K = (he.in_plane if plane == "in_plane" else he.out_of_plane)(A, B, omega, setup.c_s,
                                                                  setup.f)
    sc = he.response_scales(pieces, fam, omega, s[-1] - s[0])
    K = K * sc[None, None, :] / sc[None, :, None]
    eye = np.eye(n)[None]
    hh = 0.5 * h[:, None, None]
    M = box_matrix(-eye - hh * K, eye - hh * K, (b0, b1), 1.0 + 0.0j)
    rhs = np.zeros((N + 1) * n, complex)
    if loaded:
        # the box rows Y[j+1] - Y[j] - h K Ymid = h g_mid, scaled as K: g / sc
        rhs[len(b0):len(b0) + N * n] = (h[:, None] * g / sc[None, :]).ravel()
    for k, i in driven:
        rhs[len(b0) + N * n + k] = motion[fam.disp[i]] / sc[i]
    # the matrix is block-bidiagonal with the end rows: no fill-reducing ordering needed
    Y = splu(M, permc_spec="NATURAL").solve(rhs)
    return Y.reshape(N + 1, n) * sc[None, :]


def _result(scene, pieces, period, motion, s, Y, Z, info) -> HarmonicResponse:
    EI = np.empty(s.size)
    T0, M0 = np.empty(s.size), np.empty(s.size)
    ends_at = np.array([pc.s1 for pc in pieces])
    which = np.clip(np.searchsorted(ends_at, s - 1e-12), 0, len(pieces) - 1)
    for i, pc in enumerate(pieces):
        sel = which == i
        EI[sel] = pc.EI
        st = pc.static(s[sel])
        T0[sel], M0[sel] = st["T"], pc.EI * st["kappa"]
    amps = {"dx": Y[:, 0], "dy": Y[:, 1], "dz": Z[:, 0], "tension": Y[:, 5],
            "moment": Y[:, 3], "moment_out": Z[:, 2], "curvature": Y[:, 3] / EI,
            "shear": Y[:, 4]}
    ok = all(np.all(np.isfinite(v)) for v in amps.values())
    status = Status.CONVERGED if ok else Status.DIVERGED
    msg = (f"converged: harmonic response at {period:g} s ({info['iterations']} drag "
           "iterations)" if ok else "the linear solve gave NaN/inf (a singular system: "
           "the period at an undamped natural period?)")
    return HarmonicResponse("bvp", scene.name, status, msg, period, motion, s, amps,
                            {"tension": T0, "moment": M0}, info=info)


def _richardson(fine: HarmonicResponse, coarse: HarmonicResponse) -> HarmonicResponse:
    """The second-order box scheme extrapolated from the grid and its bisection, at the
    coarse nodes: R = F + (F - C) / 3 (every node of the coarse grid is a fine one).
    ``info['grid_change']``: the largest |F - C| of the tension and moment amplitudes
    over their peaks (the fine grid's own error is about a third of it, the
    extrapolation's far less), of those not zero at first order (a peak above
    :data:`FIRST_ORDER_ZERO` of the static tension's largest, a moment's of the larger
    moment's peak: the 3D rod's in-plane response to a sway at a planar state is
    round-off, ~1e-20, the planar families' exactly 0)."""
    change = 0.0
    amps = {}
    peaks = {k: float(np.max(np.abs(F[::2]))) for k, F in fine.amplitudes.items()}
    floor = {"tension": FIRST_ORDER_ZERO * float(np.max(np.abs(fine.static["tension"])))}
    floor["moment"] = floor["moment_out"] = FIRST_ORDER_ZERO * max(
        peaks.get("moment", 0.0), peaks.get("moment_out", 0.0))
    for k, F in fine.amplitudes.items():
        Fc, C = F[::2], coarse.amplitudes[k]
        amps[k] = Fc + (Fc - C) / 3.0
        peak = peaks[k]
        if k in ("tension", "moment", "moment_out") and peak > floor[k]:
            change = max(change, float(np.max(np.abs(Fc - C))) / peak)
    info = dict(fine.info, grid_change=change, grid_nodes=int(coarse.s.size),
                extrapolated="Richardson, grids of %d and %d nodes" % (coarse.s.size,
                                                                      fine.s.size))
    return HarmonicResponse(fine.method, fine.scene, fine.status, fine.message, fine.period,
                            fine.motion, coarse.s, amps, coarse.static, info=info)

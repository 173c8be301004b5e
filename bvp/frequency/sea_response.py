"""The irregular sea in the frequency domain: the response about the BVP static state to
the components of a wave spectrum, with the drag linearised stochastically.

Public entry: :func:`solve_sea` (scene -> :class:`SeaResponse`); :func:`gaussian_coefficients`
(the stochastic linearisation of the drag).

Model: the linearised line of :mod:`bvp.frequency.harmonic` (its box scheme, its damping and its
seabed), each wave component j of the scene's spectrum (:mod:`riser.physics.waves`: amplitude
a_j, circular frequency omega_j, steps d omega) solved as a harmonic response with the
component's line loads (:mod:`bvp.frequency.wave_loads`, unless ``line_loads`` is false) and the
hang-off motion its vessel RAOs give. Q_j(s) is the complex amplitude of a quantity; its
transfer function H_j = Q_j / (a_j e^{-i eps_j}) [unit per m of wave amplitude] (phase
referred to a crest at the waves' origin). The response is the Gaussian process sum_j
Re(Q_j e^{i omega_j t}) with the one-sided spectrum S_Q(omega_j) = |H_j|^2 S_eta(omega_j)
= |Q_j|^2 / (2 d omega) [unit^2 s/rad] and the moments m_n = sum_j omega_j^n |Q_j|^2 / 2.

Drag, stochastically linearised (Atalik and Utku; Borgman): the relative velocity v = v_0
+ sum_j Re(R_j e^{i omega_j t}) (v_0 the static current's, R_j the component's relative
velocity amplitude: the wave's flow minus the line's velocity, with the current's own
terms of :func:`bvp.frequency.equations.relative_velocity`) is Gaussian; the drag f(v) is
replaced by the linear law with the expected Jacobian, C_j = E[d f_j / d v_j], which is the
least-squares linearisation E[f(v) v'] / sigma^2 of each direction (Stein's lemma). Per
direction, with sigma the standard deviation of the oscillating part:

- tangential, f_t = c_t |v_t| v_t: C_t = 2 c_t E|v_t0 + X|, X ~ N(0, sigma_t^2), in closed
  form 2 c_t [sigma sqrt(2/pi) e^{-v_t0^2 / 2 sigma^2} + v_t0 erf(v_t0 / (sigma sqrt 2))]
  (still water: c_t sqrt(8/pi) sigma_t; no wave: the deterministic 2 c_t |v_t0|);
- normal, f = c_n |v| v in the plane (n, z) normal to the line: C_n = c_n E[|v| + v_n^2 /
  |v|], C_z = c_n E[|v| + v_z^2 / |v|] over the joint Gaussian (v_n, v_z) of mean (v_n0,
  0) and covariance from the components. A planar response (no z part): C_n = 2 c_n
  E|v_n0 + X| (still water c_n sqrt(8/pi) sigma_n), C_z = half of it, in closed form. Else
  in polar coordinates about v = 0: the radial integral in closed form, the angle by the
  trapezoidal rule on :data:`ANGLES` points (spectral: the integrand is smooth and
  periodic; exact to ~1e-13 against a 2D adaptive quadrature), the covariance's smaller
  eigenvalue floored at :data:`MINOR_FLOOR` times the larger (where it acts, C_n within
  1e-4 and C_z within 1e-3 of the exact value: far below the linearisation's own error).

The mean drag increment of the waves over the current's (a drift load) is left out: the
static state is the current's alone. The coefficients are iterated to a fixed point,
under-relaxed by :data:`RELAXATION`, until the largest change is below ``tolerance``
times the largest coefficient; all components are solved on every iteration.

Statistics per s: the standard deviation sigma = sqrt(m0); the significant amplitude 2
sigma (half the significant double amplitude 4 sigma, as Hs = 4 sqrt(m0) of the
elevation); the mean zero-up-crossing period Tz = 2 pi sqrt(m0 / m2); the most probable
maximum over a duration D of a narrow-banded Gaussian response (Rayleigh maxima, N = D /
Tz cycles): sigma sqrt(2 ln N) (0 where the response is nil; N < 1 is taken as 1).

Grid: :func:`bvp.frequency.harmonic.grid` of ``intervals`` (default 1500, coarser than the harmonic
response's and without the Richardson step: n_components solves per iteration). Measured
on a 150 m catenary riser with a touchdown (tests/test_harmonic_waves.py's scene, drag
on): against a 6000-interval grid the standard deviations differ by 4e-4 (tension), 1e-3
(dy) and 1.2e-2 (curvature, the touchdown's short bends; second order: a quarter of it
at 3000); the fixed point's default tolerance 1e-4 moves them by ~1e-5. Cost: one
sparse LU per family per component per iteration (~3 ms each at 1500 intervals).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
from scipy.special import erf, ndtr

from riser.errors import UnsupportedSceneError
from riser.physics.hang_off_motion import scene_components, vessel_amplitudes
from riser.results.result import SolveResult, Status
from riser.model.scene import Scene

from . import equations as he
from . import wave_loads as wl
from .harmonic import grid, prepare, require_harmonic, respond
from ..modal.equations import build_pieces

#: the quantities of a sea response (as :data:`riser.results.response.QUANTITIES`)
QUANTITIES = ("dx", "dy", "dz", "tension", "moment", "moment_out", "curvature")
#: default grid intervals over the line
INTERVALS = 1500
#: under-relaxation of the drag coefficients' fixed point
RELAXATION = 0.5
#: angles of the polar quadrature of the 2D Gaussian expectation
ANGLES = 2048
#: the covariance's smaller eigenvalue is at least this fraction of the larger
MINOR_FLOOR = 1e-4
#: below this variance [m2/s2] a direction does not oscillate (the deterministic limit)
TINY_VARIANCE = 1e-18


@dataclass
class SeaResponse:
    """The response to an irregular sea (see the module docstring; SI units, the
    quantities of :data:`QUANTITIES` with the units of :data:`riser.results.response.UNITS`).

    ``s`` (n_s,) [m]; ``omega`` (n_w,) [rad/s] the components' frequencies, ``d_omega``
    [rad/s] their step; ``wave_density`` (n_w,) S_eta [m2 s/rad]; per quantity name:
    ``transfer`` (n_w, n_s) complex H [unit/m], ``spectra`` (n_w, n_s) S_Q [unit^2
    s/rad], and (n_s,) each ``std`` sigma, ``significant`` 2 sigma, ``tz`` [s] and ``mpm``
    (the most probable maximum over ``duration`` [s], about the static value).
    ``static``: the static tension [N] and moment [N m] at s."""

    method: str
    scene: str
    status: Status
    message: str
    duration: float = 10800.0
    s: np.ndarray = field(default_factory=lambda: np.zeros(0))
    omega: np.ndarray = field(default_factory=lambda: np.zeros(0))
    d_omega: float = 0.0
    wave_density: np.ndarray = field(default_factory=lambda: np.zeros(0))
    transfer: dict = field(default_factory=dict)
    spectra: dict = field(default_factory=dict)
    std: dict = field(default_factory=dict)
    significant: dict = field(default_factory=dict)
    tz: dict = field(default_factory=dict)
    mpm: dict = field(default_factory=dict)
    static: dict = field(default_factory=dict)
    wall_time_s: float = 0.0
    info: dict = field(default_factory=dict)

    @property
    def converged(self) -> bool:
        return self.status == Status.CONVERGED


def solve_sea(scene: Scene, static: SolveResult | None = None, duration: float = 10800.0,
              *, tolerance: float = 1e-4, max_iterations: int = 100,
              intervals: int = INTERVALS, progress=None) -> SeaResponse:
    """The frequency-domain response of the fixed-ends ``scene`` to its irregular sea
    (``[environment.waves.spectrum]``, no regular trains beside it, no top motion), the
    most probable maxima over ``duration`` [s] (see the module docstring). ``progress``:
    the ``progress(message, fraction=None)`` convention (riser/callbacks.py), called per
    iteration. Refused (before solving) what the model does not represent."""
    t0 = time.perf_counter()
    name = scene.name
    try:
        comp = _require_sea(scene)
    except UnsupportedSceneError as exc:
        return SeaResponse("bvp", name, Status.REFUSED, str(exc), duration)
    if not duration > 0.0:
        raise ValueError(f"duration must be > 0 s, got {duration}")
    if static is None:
        from ..solver import solve
        static = solve(scene)
    if not static.converged:
        return SeaResponse("bvp", name, static.status, "the static solution did not "
                           f"converge: {static.message}", duration)
    try:
        wl.require_submerged(scene, comp, float(np.max(static.profile.y)),
                             "the static line's highest point")
    except UnsupportedSceneError as exc:
        return SeaResponse("bvp", name, Status.REFUSED, str(exc), duration)
    pieces = build_pieces(scene, static.profile)
    setup = prepare(scene, pieces, grid(pieces, intervals))
    f, mid, n = setup.f, setup.mid, comp.size
    motions = vessel_amplitudes(scene, comp)[1]
    flows = [None] * n
    if scene.waves.line_loads:
        line = wl.LineFlow(scene, static.profile, comp, 0)
        flows = [line.at(mid, f["theta"], f["y"], j) for j in range(n)]
    zero = np.zeros(mid.size, complex)
    start = [(fl["un"], fl["uz"], fl["ut"]) if fl is not None else (zero, zero, zero)
             for fl in flows]
    Cn, Cz, Ct = gaussian_coefficients(f["vn0"], f["vt0"], *_covariances(start),
                                       f["c_n"], f["c_t"])
    EI = np.array([pieces[i].EI for i in _node_pieces(pieces, setup.s)])
    Q = {k: np.zeros((n, setup.s.size), complex) for k in QUANTITIES}
    change, it = np.inf, 0
    for it in range(1, max_iterations + 1):
        f.update(Cn=Cn, Cz=Cz, Ct=Ct)
        rel = []
        for j in range(n):
            w = float(comp.omega[j])
            Y, Z = respond(setup, w, motions[:, j], flows[j])
            for key, v in (("dx", Y[:, 0]), ("dy", Y[:, 1]), ("dz", Z[:, 0]),
                           ("tension", Y[:, 5]), ("moment", Y[:, 3]),
                           ("moment_out", Z[:, 2]), ("curvature", Y[:, 3] / EI)):
                Q[key][j] = v
            if setup.has_drag:
                Ym, Zm = 0.5 * (Y[1:] + Y[:-1]), 0.5 * (Z[1:] + Z[:-1])
                rel.append(he.relative_velocity(Ym, Zm, w, f, flows[j]))
        if not setup.has_drag:
            change = 0.0
            break
        new = gaussian_coefficients(f["vn0"], f["vt0"], *_covariances(rel),
                                    f["c_n"], f["c_t"])
        old = (Cn, Cz, Ct)
        top = max(float(np.max(np.abs(c))) for c in new) or 1.0
        change = max(float(np.max(np.abs(a - b))) for a, b in zip(new, old)) / top
        Cn, Cz, Ct = (o + RELAXATION * (a - o) for a, o in zip(new, old))
        if progress is not None:
            progress(f"sea response: drag iteration {it}, change {change:.3g}",
                     min(1.0, max(0.0, math.log(max(change, tolerance))
                                         / math.log(tolerance))))
        if change <= tolerance:
            break
    info = {"iterations": it, "last_change": change, "tolerance": tolerance,
            "components": n, "grid_nodes": int(setup.s.size),
            "drag_linearised": setup.has_drag, "static_wall_time_s": static.wall_time_s}
    if change > tolerance:
        return SeaResponse("bvp", name, Status.NOT_CONVERGED,
                           f"the stochastic drag linearisation did not settle in {it} "
                           f"iterations (last relative change of a coefficient "
                           f"{change:.3g}, tolerance {tolerance:g})", duration, info=info,
                           wall_time_s=time.perf_counter() - t0)
    out = _statistics(scene, comp, setup.s, Q, duration, info)
    out.static = _static(pieces, setup.s)
    out.wall_time_s = time.perf_counter() - t0
    out.info["wall_time_s"] = out.wall_time_s
    return out


def _require_sea(scene: Scene):
    """The components of the scene's sea; UnsupportedSceneError (one line) for what the
    sea response does not represent."""
    src, waves = scene.source, scene.waves
    if waves is None or waves.spectrum is None:
        raise UnsupportedSceneError(f"{src}: environment.waves.spectrum: the sea response "
                                    "needs an irregular sea (a regular train: "
                                    "bvp.frequency.harmonic.solve_harmonic)")
    if waves.trains:
        raise UnsupportedSceneError(f"{src}: environment.waves.trains: the sea response "
                                    "takes the spectrum alone (solve a train with "
                                    "bvp.frequency.harmonic.solve_harmonic; the responses add)")
    if scene.dynamics is not None and scene.dynamics.top_motion is not None:
        raise UnsupportedSceneError(f"{src}: dynamics.top_motion: not beside a sea in the "
                                    "sea response (the vessel moves the hang-off)")
    require_harmonic(scene, np.zeros(3, complex), three_d=False,
                     who="the sea response (bvp.frequency.sea_response)")
    comp = scene_components(scene)
    top = max(scene.ends.anchor_point[1], scene.ends.hang_off_point[1])
    wl.require_submerged(scene, comp, top, "the line's highest end")
    return comp


def _covariances(rel):
    """(S_nn, S_zz, S_nz, S_tt) (m,) [m2/s2] of the oscillating relative velocity from
    the components' complex amplitudes ``rel`` [(a_n, a_z, a_t), ...]: sum of Re(a
    conj(b)) / 2."""
    snn = szz = snz = stt = 0.0
    for a_n, a_z, a_t in rel:
        snn = snn + 0.5 * np.abs(a_n) ** 2
        szz = szz + 0.5 * np.abs(a_z) ** 2
        snz = snz + 0.5 * (a_n * np.conj(a_z)).real
        stt = stt + 0.5 * np.abs(a_t) ** 2
    return snn, szz, snz, stt


def mean_abs(mu, variance) -> np.ndarray:
    """E|mu + X| for X ~ N(0, variance): sigma sqrt(2/pi) e^{-mu^2/(2 sigma^2)} + mu
    erf(mu / (sigma sqrt 2)); |mu| where the variance is nil."""
    mu = np.asarray(mu, float)
    var = np.broadcast_to(np.asarray(variance, float), mu.shape)
    sig = np.sqrt(np.maximum(var, TINY_VARIANCE))
    val = (sig * math.sqrt(2.0 / math.pi) * np.exp(-0.5 * (mu / sig) ** 2)
           + mu * erf(mu / (sig * math.sqrt(2.0))))
    return np.where(var > TINY_VARIANCE, val, np.abs(mu))


def gaussian_coefficients(v_n0, v_t0, snn, szz, snz, stt, c_n, c_t):
    """The stochastically linearised drag coefficients (C_n, C_z, C_t) [N s/m2] at m
    points (see the module docstring): the static relative speeds v_n0, v_t0 [m/s], the
    (co)variances S_nn, S_zz, S_nz, S_tt [m2/s2] of the oscillating relative velocity,
    the drag coefficients c_n, c_t [kg/m2]."""
    m = np.asarray(v_n0).size
    snn, szz, snz, stt = (np.broadcast_to(np.asarray(v, float), (m,))
                          for v in (snn, szz, snz, stt))
    Ct = 2.0 * c_t * mean_abs(v_t0, stt)
    e = mean_abs(v_n0, snn)
    Cn, Cz = 2.0 * c_n * e, c_n * e
    other = (szz > TINY_VARIANCE) | (np.abs(snz) > TINY_VARIANCE)
    for idx in np.array_split(np.flatnonzero(other), max(1, int(np.sum(other)) // 256)):
        if idx.size:
            en, ez = _polar(np.asarray(v_n0, float)[idx], snn[idx], szz[idx], snz[idx])
            cn = np.broadcast_to(np.asarray(c_n, float), (m,))[idx]
            Cn[idx], Cz[idx] = cn * en, cn * ez
    return Cn, Cz, Ct


def _polar(m_n, snn, szz, snz):
    """(E[|v| + v_n^2/|v|], E[|v| + v_z^2/|v|]) for v ~ N((m_n, 0), [[snn, snz], [snz,
    szz]]) (arrays of k): polar coordinates about v = 0, v = r (cos phi, sin phi). With P
    the inverse covariance, a = d.P.d, b = d.P.m, c = m.P.m, the radial integral
    int_0^inf r^2 e^{-(a r^2 - 2 b r + c)/2} dr = a^{-3/2} [e^{(beta^2 - c)/2} sqrt(2 pi)
    Phi(beta) (1 + beta^2) + beta e^{-c/2}], beta = b / sqrt(a), and the density's
    1 / (2 pi sqrt(det)); the angle by the trapezoidal rule."""
    half = 0.5 * (snn - szz)
    l1 = 0.5 * (snn + szz) + np.sqrt(half * half + snz * snz)
    l2 = snn + szz - l1
    lift = np.maximum(MINOR_FLOOR * l1 - l2, 0.0)
    pnn, pzz = snn + lift, szz + lift
    det = pnn * pzz - snz * snz
    inv = (pzz / det, -snz / det, pnn / det)                 # P_nn, P_nz, P_zz
    phi = 2.0 * math.pi * np.arange(ANGLES) / ANGLES
    c, s = np.cos(phi)[None, :], np.sin(phi)[None, :]
    a = inv[0][:, None] * c * c + 2.0 * inv[1][:, None] * c * s + inv[2][:, None] * s * s
    b = (inv[0][:, None] * c + inv[1][:, None] * s) * m_n[:, None]
    c0 = (inv[0] * m_n * m_n)[:, None]
    beta = b / np.sqrt(a)
    radial = (np.exp(0.5 * (beta * beta - c0)) * math.sqrt(2.0 * math.pi) * ndtr(beta)
              * (1.0 + beta * beta) + beta * np.exp(-0.5 * c0)) * a ** -1.5
    scale = 1.0 / np.sqrt(det)
    return (scale * np.mean((1.0 + c * c) * radial, axis=1),
            scale * np.mean((1.0 + s * s) * radial, axis=1))


def _node_pieces(pieces, s):
    ends_at = np.array([pc.s1 for pc in pieces])
    return np.clip(np.searchsorted(ends_at, s - 1e-12), 0, len(pieces) - 1)


def _static(pieces, s) -> dict:
    """Static tension [N] and in-plane moment [N m] at the nodes s."""
    which = _node_pieces(pieces, s)
    T0, M0 = np.empty(s.size), np.empty(s.size)
    for i, pc in enumerate(pieces):
        sel = which == i
        st = pc.static(s[sel])
        T0[sel], M0[sel] = st["T"], pc.EI * st["kappa"]
    return {"tension": T0, "moment": M0}


def _statistics(scene, comp, s, Q, duration, info) -> SeaResponse:
    """The spectra and statistics of the amplitudes Q (name -> (n_w, n_s) complex)."""
    dw = scene.waves.spectrum.component_omegas()[1]
    a = comp.amplitude * np.exp(-1j * comp.phase)
    w = comp.omega[:, None]
    out = SeaResponse("bvp", scene.name, Status.CONVERGED, "", duration, s,
                      comp.omega.copy(), dw, comp.amplitude ** 2 / (2.0 * dw), info=info)
    ok = True
    for key, q in Q.items():
        power = 0.5 * np.abs(q) ** 2                       # |Q_j|^2 / 2 per component
        m0, m2 = np.sum(power, axis=0), np.sum(w * w * power, axis=0)
        sigma = np.sqrt(m0)
        with np.errstate(divide="ignore", invalid="ignore"):
            tz = np.where(m2 > 0.0, 2.0 * math.pi * np.sqrt(m0 / m2), np.nan)
            cycles = np.maximum(duration / tz, 1.0)
            mpm = np.where(m2 > 0.0, sigma * np.sqrt(2.0 * np.log(cycles)), 0.0)
        out.transfer[key] = q / a[:, None]
        out.spectra[key] = power / dw
        out.std[key], out.significant[key] = sigma, 2.0 * sigma
        out.tz[key], out.mpm[key] = tz, mpm
        ok = ok and bool(np.all(np.isfinite(q)))
    if not ok:
        out.status = Status.DIVERGED
        out.message = ("the linear solve gave NaN/inf (a singular system: a component at "
                       "an undamped natural frequency?)")
    else:
        out.message = (f"converged: sea response, {comp.size} components "
                       f"({info['iterations']} drag iterations)")
    return out

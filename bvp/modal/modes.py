"""Natural modes of small vibration about the BVP static solution (undamped).

Public entry: :func:`solve_modes` (fixed-ends scene -> :class:`riser.results.modes.ModalResult`).

Model (the one the VFIFE's modal analysis linearises, see ``riser/results/modes.py``)
-------------------------------------------------------------------------------
SI units; s [m] the unstretched arc length from the bottom end; x towards the hang-off,
y up from the seabed, z out of plane. The static state is the converged BVP profile
(x, y, theta, M, F, T; ``bvp/beam/equations.py``), planar (no out-of-plane current). The
line's motion obeys, per unit unstretched length,

    dP/ds + q = m (a.t) t + (m + m_a) (a - (a.t) t)           (force; a = d2r/dt2)
    dM/ds + dr/ds x P = 0                                     (moment; no rotary inertia)
    M = EI t x dt/ds,  |dr/ds| = 1 + eps,  eps = T / EA,  T = P.t

with m the pipe + contents mass and m_a = C_a rho pi D^2/4 the added mass, normal to the
axis only; q the dead weight (0, -w, 0), the seabed reaction (0, p, 0), p = k max(-y, 0)
(``riser.model.sections``), and the static drag of an in-plane current frozen as a dead load:
q_d = f_n n0 + f_t t0 with f_n = c_n |V_n| V_n, V_n = -V sin theta0, f_t = c_t |V_t| V_t,
V_t = V cos theta0 (``bvp/beam/equations.py``) at the static tangent and height of each
material point, fixed in magnitude and direction while the line moves (the VFIFE's
constant nodal forces). No torsion: the moment EI t x t' is perpendicular to the axis
(the VFIFE does not integrate twist). Undamped: the drag's dependence on the line's
velocity (damping) and on its direction and height (a quasi-steady drag stiffness) is not
modelled, nor friction. Small harmonic motion e^{i omega t} about the static state,
linearised: weight and drag are dead loads (no linear term in x, y; in the rotating frame
their components turn, d(q.n) = -(q.t) dtheta and d(q.t) = (q.n) dtheta), the seabed a
vertical spring k per unit length where the static line lies in it (dp = -k dy), nothing
laterally.

In plane (t = (c, sn) = (cos theta, sin theta), n = (-sn, c), kappa = M/EI,
e = 1 + T/EA), state [dx, dy, dtheta, dM, dF, dT] (the linearisation of
``bvp/beam/equations.py``, the static T, M, F, theta, p of the profile as coefficients):

    dx' = -e sn dtheta + c dT/EA          dy' = e c dtheta + sn dT/EA
    dtheta' = dM/EI                       dM' = e dF + F dT/EA
    dF' = kappa dT + T dM/EI + ((w - p) sn - f_t) dtheta - k c dy + omega^2 (m + m_a) u_n
    dT' = -kappa dF - F dM/EI + ((w - p) c - f_n) dtheta + k sn dy - omega^2 m u_t

with u_t = c dx + sn dy and u_n = -sn dx + c dy (k only in contact). The f_n, f_t terms
are the dead drag's turning components (static F' = T kappa + q.n, T' = -F kappa - q.t
with q.n = (p - w) c + f_n, q.t = (p - w) sn + f_t). Left out, the drag turns with the
line (a follower load), not the VFIFE's model: 1.5 % off on a light power cable's first
in-plane mode in a 1 m/s current, whatever the mesh (``tests/test_modes_current.py``).

Out of plane, state [w, psi, B, Q]: w the z displacement, psi the z component of the unit
tangent, B the bending moment about the in-plane normal n, Q = dP.z the z shear force.
Derivation: (1) t = r'/|r'|, r' = e t0 + w' z, so psi = w'/e and the stretch, hence T,
is unchanged to first order (the families decouple: z -> -z is a symmetry of the planar
state). (2) dM = EI (dt x t0' + t0 x dt') with dt = psi z, t0' = kappa n:
dM = -EI psi' n - EI kappa psi t0; define B = EI psi' (dM.n = -B); the t0 part is M0
rotated with the tangent (dM.t + M0.dt = 0: still no torsion). (3) Linearise the moment
balance: dM' + dr' x P0 + r0' x dP = 0 with P0 = T t0 - F n, dr' = e psi z,
dP = Q z: its t0 component, B kappa - (M0 psi)' + e F psi = 0, holds identically (M0' =
e F, B kappa = M0 psi'); its n component gives B'. (4) The z force balance:
Q' = -omega^2 (m + m_a) w (no lateral seabed; the weight and the in-plane drag have no z
part, and a dead load does not tilt with the line: no drag term out of plane). Hence

    w' = e psi,   psi' = B/EI,   B' = e (T psi - Q) - EI kappa^2 psi,
    Q' = -omega^2 (m + m_a) w,

i.e. the potential energy 1/2 int(EI psi'^2 - EI kappa^2 psi^2 + T w'^2/e) ds: the
-EI kappa^2 psi^2 term is |t'|^2 = theta'^2 cos^2(phi) + phi'^2 of a torsion-free rod
tilted out of its plane by phi = psi.

Ends: pinned in space (dx = dy = 0, w = 0) and moment-free (dM = 0, B = 0), as the BVP's
fixed ends are; an end in ``[vfife] clamped_ends`` keeps its direction (dtheta = 0,
psi = 0) instead (the static state is the BVP's, moment-free at both ends).

Method: for each family a box scheme (``bvp/modal/equations.py``) on a ~3000-interval
grid gives approximate eigenpairs; each is refined by ``solve_bvp`` on the stacked pieces
(segments split at the lift-off point: segment k over tau in [0, 1]) with omega an
unknown parameter and the extra state I(s) = int (m u_t^2 + (m + m_a) u_n^2) ds / N,
I(0) = 0, I(L) = 1 (N the guess's value). The refined frequency is the result; a mode is
accepted when solve_bvp converged, its shape has MAC >= 0.9 with its guess, its frequency
is within 5 % of the guess's, and no two refined modes coincide. The states are scaled
for solve_bvp by the guess, and at least 1 % of the largest term of their derivative
over a length 1/k (near the string limit, a bending length sqrt(EI/T) far below the
wavelength, the shear rows are small differences of large terms). At the
default tolerance 1e-6 the frequencies are converged to ~1e-9 (a 1e-8 refinement of
scr-steel moves none by more than 7e-10).
Mode shapes: the displacement (x, y, z) at the collocation nodes, ``normalise_shape``d.
Rotary inertia is neglected (a relative effect ~(r_g k)^2 < 1e-5 for riser modes).

``ModalResult.info``: ``static_wall_time_s``, ``tolerance``, ``pieces`` ((s0, s1,
contact) of each piece) and per mode (``modes``: plane, number, guess_hz,
frequency_hz, nodes, collocation_residual, mac_with_guess), with
``max_collocation_residual`` and ``min_mac_with_guess``.
"""

from __future__ import annotations

import dataclasses
import time

import numpy as np

from riser.callbacks import with_fraction
from riser.errors import UnsupportedSceneError
from riser.results.modes import (COUPLED, PLANES, ModalResult, Mode, mac, normalise_shape,
                                 out_of_plane_share, shape_at)
from riser.results.result import SolveResult, Status
from riser.model.scene import Scene

from ..collocation import solve_bvp
from ..mesh import clustered_mesh
from ..rod.output import RodState
from .ends import modal_ends
from .equations import (FAMILIES, Family, Piece, box_modes, build_pieces,
                              require_linearisable)
from .rod_family import ROD_FAMILY, rod_ends, rod_pieces, to_scene_axes

#: a refined mode must keep MAC >= this with its box-scheme guess ...
MIN_MAC_WITH_GUESS = 0.9
#: ... and a frequency within this fraction of the guess's
MAX_GUESS_SHIFT = 0.05
#: a state's scale is at least this fraction of its derivative's largest term over 1/k
#: (see :func:`_scales`)
TERM_FRACTION = 0.01


def solve_modes(scene: Scene, count: int = 10, *, static: SolveResult | None = None,
                progress=None, tolerance: float = 1e-6, max_nodes: int = 10000,
                grid_intervals: int = 3000) -> ModalResult:
    """``count`` in-plane and ``count`` out-of-plane natural modes of the fixed-ends
    ``scene`` about its BVP static solution ``static`` (solved here when None).

    ``tolerance``: solve_bvp's on the relative collocation residual; ``max_nodes``: its
    node cap per mode (at most 1e7 / states^2: memory); ``grid_intervals``: the
    box-scheme grid of the starting modes. Modes are numbered by refined frequency (by
    their guesses' order when some failed). Ends that are not fixed, an out-of-plane
    current (the static state would not be planar), a rigid seabed (no linear stiffness)
    or flowing contents give a ``refused`` result. Never raises on non-convergence: the
    status says what failed."""
    try:
        _require_modal(scene)
    except UnsupportedSceneError as exc:
        return ModalResult("bvp", scene.name, Status.REFUSED, str(exc))
    if count < 1:
        raise ValueError(f"count must be >= 1, got {count}")
    if static is not None and static.method != "bvp":
        raise ValueError(f"static must be a bvp result, got a {static.method} one")
    progress = with_fraction(progress)
    if static is None:
        from ..solver import solve
        if progress:
            progress("bvp modes: static solution", fraction=0.0)
        static = solve(scene)
    info = {"static_wall_time_s": static.wall_time_s, "tolerance": tolerance}
    t0 = time.perf_counter()

    def result(status, msg, modes=()):
        return ModalResult("bvp", scene.name, status, msg, list(modes),
                           time.perf_counter() - t0, info)

    if not static.converged:
        return result(static.status, f"the static solution did not converge: "
                      f"{static.message}")
    state = static.solver_state
    if scene.out_of_plane(statics=True) is not None and not isinstance(state, RodState):
        raise ValueError("static must be the bvp's 3D rod result of the scene")
    if isinstance(state, RodState):      # the 3D rod's state (a 3D scene's): coupled
        pieces = rod_pieces(scene, static.profile, state)
        families = [(ROD_FAMILY, rod_ends(scene), 2 * count)]
        info["static_state"] = "3d"
    else:
        pieces = build_pieces(scene, static.profile, dead_drag=True)
        top = pieces[-1].static(np.array([pieces[-1].s1]))
        top_static = {k: float(top[k][0]) for k in ("theta", "T", "F")}
        families = [(FAMILIES[plane], modal_ends(scene, plane, top_static), count)
                    for plane in PLANES]
        info["static_state"] = "planar"
    info["pieces"] = [(round(p.s0, 6), round(p.s1, 6), bool(p.contact)) for p in pieces]
    modes, failures, checks = [], [], []
    done, total = 0, 2 * count
    for fam, ends, wanted in families:
        plane = fam.plane
        lam, grid, states = box_modes(pieces, fam, ends, wanted, grid_intervals)
        if lam.size and lam[0] <= 0.0:
            return result(Status.NOT_CONVERGED, f"{plane}: the static state is not stable "
                          f"(omega^2 = {lam[0]:.3g} rad2/s2 <= 0): no vibration modes")
        if lam.size < wanted:
            return result(Status.NOT_CONVERGED, f"{plane}: the box scheme found only "
                          f"{lam.size} real modes of the {wanted} asked")
        found = []
        for i in range(wanted):
            if progress:
                progress(f"bvp modes: {plane} {i + 1}/{wanted}", fraction=done / total)
            ok, why, mode, check = _refine(pieces, fam, ends, lam[i], grid, states[i],
                                           i + 1, tolerance, max_nodes)
            done += 1
            checks.append(check)
            if ok:
                found.append(mode)
            else:
                failures.append(f"{plane} mode {i + 1}: {why}")
        failed = len(failures)
        failures.extend(_coincident(found))
        found.sort(key=lambda m: m.frequency_hz)
        if len(found) == wanted and len(failures) == failed:
            found = [Mode(plane, j + 1, m.frequency_hz, m.s, m.shape)
                     for j, m in enumerate(found)]
        if plane == COUPLED:             # back to the scene's axes, and each mode's share
            found = [dataclasses.replace(m, shape=normalise_shape(to_scene_axes(m.shape,
                                                                                state)))
                     for m in found]
            info["out_of_plane_share"] = [out_of_plane_share(m) for m in found]
        modes.extend(found)
    info["modes"] = checks
    info["max_collocation_residual"] = max(c["collocation_residual"] for c in checks)
    info["min_mac_with_guess"] = min(c["mac_with_guess"] for c in checks)
    if failures:
        return result(Status.NOT_CONVERGED, "; ".join(failures), modes)
    what = (f"{len(modes)} coupled modes about the 3D static state"
            if info["static_state"] == "3d" else
            f"{count} in-plane and {count} out-of-plane modes")
    return result(Status.CONVERGED, f"converged: {what} (solve_bvp refinement of box-scheme "
                  "guesses)", modes)


def _require_modal(scene: Scene) -> None:
    """Refuse what the linearisation does not represent (before solving)."""
    require_linearisable(scene, "bvp modes", three_d=True)
    if scene.attachments:
        raise UnsupportedSceneError(
            f"{scene.source}: attachments: the bvp modes have no point masses (the VFIFE's "
            "modes carry them: --method vfife)")
    if scene.internal_flow is not None and scene.internal_flow.speed != 0.0:
        raise UnsupportedSceneError(
            f"{scene.source}: internal_flow.speed: modes do not model flowing contents (the "
            "Coriolis force makes the modes complex); set the speed to 0 for the modes of "
            "the line with its contents at rest")


def _coincident(found: list[Mode]) -> list[str]:
    """Refined modes that converged to the same mode (the same frequency to 1e-6 and
    MAC > 0.9; a degenerate pair, two shapes of one frequency, is not one)."""
    out = []
    for i in range(len(found)):
        for j in range(i + 1, len(found)):
            a, b = found[i], found[j]
            if (abs(a.frequency_hz - b.frequency_hz) <= 1e-6 * b.frequency_hz
                    and mac(a.shape, shape_at(b, a.s)) > MIN_MAC_WITH_GUESS):
                out.append(f"{a.plane} modes {a.number} and {b.number} converged to the same "
                           f"mode ({a.frequency_hz:.6g} Hz)")
    return out


def _refine(pieces: list[Piece], fam: Family, ends: tuple, lam0: float, grid: np.ndarray,
            Y0: np.ndarray, number: int, tol: float, max_nodes: int):
    """solve_bvp refinement of one box-scheme mode (lam0 [rad2/s2], states Y0 (n, N+1) on
    ``grid``). Returns (ok, why, Mode, check dict)."""
    n, npc = fam.n, len(pieces)
    nz = n + 1                                      # + the normalisation integral
    # solve_bvp's collocation Jacobian holds ~2 (states)^2 nonzeros per node: <= 2e7
    max_nodes = int(min(max_nodes, 1e7 / (npc * nz) ** 2))
    om0 = float(np.sqrt(lam0))
    Lk = np.array([pc.length for pc in pieces])
    sc = _scales(pieces, fam, grid, Y0, lam0, tol)
    # the normalisation: N = int u^T W u ds of the guess (trapezoidal on the grid)
    dens = np.zeros(grid.size)
    for pc in pieces:
        sel = (grid >= pc.s0) & (grid <= pc.s1)
        W = fam.mass(pc, grid[sel])
        dens[sel] = np.einsum("ik,ijk,jk->k", Y0[:, sel], W, Y0[:, sel])
    cum = np.concatenate([[0.0], np.cumsum(0.5 * (dens[1:] + dens[:-1]) * np.diff(grid))])
    norm = float(cum[-1])
    cache = {}

    def coeffs(tau):
        key = tau.tobytes()
        if key not in cache:
            if len(cache) > 8:
                cache.clear()
            out = []
            for pc, L in zip(pieces, Lk):
                s = pc.s0 + L * tau
                A, B = fam.matrices(pc, s)
                out.append((A * sc[None, :, None] / sc[:, None, None],
                            B * sc[None, :, None] / sc[:, None, None],
                            fam.mass(pc, s) * sc[:, None, None] * sc[None, :, None]))
            cache[key] = out
        return cache[key]

    def fun(tau, Z, p):
        lam = (p[0] * om0) ** 2
        d = np.empty_like(Z)
        for k, (A, B, W) in enumerate(coeffs(tau)):
            y = Z[k * nz:k * nz + n]
            d[k * nz:k * nz + n] = Lk[k] * np.einsum("ijm,jm->im", A + lam * B, y)
            d[k * nz + n] = Lk[k] * np.einsum("im,ijm,jm->m", y, W, y) / norm
        return d

    def fun_jac(tau, Z, p):
        lam = (p[0] * om0) ** 2
        m = tau.size
        J = np.zeros((npc * nz, npc * nz, m))
        Jp = np.zeros((npc * nz, 1, m))
        for k, (A, B, W) in enumerate(coeffs(tau)):
            y = Z[k * nz:k * nz + n]
            r = slice(k * nz, k * nz + n)
            J[r, r] = Lk[k] * (A + lam * B)
            J[k * nz + n, r] = Lk[k] * 2.0 * np.einsum("ijm,jm->im", W, y) / norm
            Jp[r, 0] = Lk[k] * 2.0 * p[0] * om0 ** 2 * np.einsum("ijm,jm->im", B, y)
        return J, Jp

    last = (npc - 1) * nz
    # the end rows on the scaled states, each row normalised by its largest coefficient
    b0, b1 = ([[(i, c * sc[i]) for i, c in row] for row in side] for side in ends)
    b0, b1 = ([[(i, c / max(abs(c) for _, c in row)) for i, c in row] for row in side]
              for side in (b0, b1))

    def bc(za, zb, p):
        res = ([sum(c * za[i] for i, c in row) for row in b0]
               + [sum(c * zb[last + i] for i, c in row) for row in b1])
        res += [zb[k * nz + i] - za[(k + 1) * nz + i] for k in range(npc - 1)
                for i in range(nz)]
        res += [za[n], zb[last + n] - 1.0]
        return np.array(res)

    # initial mesh: ~24 nodes per half-wave of the guess (on the unit interval of every
    # piece: generous), refined towards the ends
    half_waves = _half_waves(fam, Y0)
    tau = _end_refined(clustered_mesh(int(np.clip(24 * half_waves, 80, max_nodes // 4))),
                       pieces)
    Z = np.zeros((npc * nz, tau.size))
    for k, pc in enumerate(pieces):
        s = pc.s0 + Lk[k] * tau
        for i in range(n):
            Z[k * nz + i] = np.interp(s, grid, Y0[i]) / sc[i]
        Z[k * nz + n] = np.interp(s, grid, cum) / norm
    sol = solve_bvp(fun, bc, tau, Z, p=np.array([1.0]), fun_jac=fun_jac, tol=tol,
                    max_nodes=max_nodes)
    f_guess = om0 / (2.0 * np.pi)
    res = float(np.max(sol.rms_residuals)) if sol.rms_residuals is not None else np.nan
    check = {"plane": fam.plane, "number": number, "guess_hz": f_guess,
             "nodes": int(sol.x.size), "collocation_residual": res, "mac_with_guess": 0.0}
    freq = abs(float(sol.p[0])) * om0 / (2.0 * np.pi)
    check["frequency_hz"] = freq
    s_out, shape = _shape(pieces, fam, sol, sc)
    ref = fam.shape(np.array([np.interp(s_out, grid, Y0[i]) for i in range(n)]))
    check["mac_with_guess"] = mac(shape, ref)
    mode = Mode(fam.plane, number, freq, s_out, normalise_shape(shape))
    if sol.status != 0:
        return False, f"solve_bvp did not converge ({sol.message})", mode, check
    if not np.all(np.isfinite(shape)) or not np.isfinite(freq):
        return False, "solve_bvp returned NaN/inf", mode, check
    if check["mac_with_guess"] < MIN_MAC_WITH_GUESS:
        return (False, "the refined shape is not the guess's (MAC "
                f"{check['mac_with_guess']:.3f} < {MIN_MAC_WITH_GUESS})", mode, check)
    if abs(freq - f_guess) > MAX_GUESS_SHIFT * f_guess:
        return (False, f"the refined frequency {freq:.6g} Hz is more than "
                f"{MAX_GUESS_SHIFT:.0%} from the guess's {f_guess:.6g} Hz", mode, check)
    return True, "", mode, check


def _half_waves(fam: Family, Y0: np.ndarray) -> int:
    """Half-waves of the guess's displacement (sign changes + 1, the largest component)."""
    out = 1
    for i, c in enumerate(fam.disp):
        if c is not None:
            u = Y0[i]
            u = u[np.abs(u) > 1e-3 * np.max(np.abs(u))]
            out = max(out, int(np.sum(np.diff(np.sign(u)) != 0)) + 1)
    return out


def _scales(pieces: list[Piece], fam: Family, grid: np.ndarray, Y0: np.ndarray,
            lam0: float, tol: float) -> np.ndarray:
    """Scale of each state for solve_bvp: its largest value in the guess, and at least
    :data:`TERM_FRACTION` of the rms (along the line) of the largest single term of its
    derivative times the mode's length 1/k, and enough that rounding that term over a
    piece stays below 1 % of the tolerance.

    Why: near the string limit (a bending length sqrt(EI/T) far below the wavelength) the
    shear rows are small differences of large terms (T dM/EI and the inertia in plane,
    e T psi and Q out of plane). Scaled by their own small size, the residual would
    measure them against the rounding and the cubic-spline roughness of the static
    coefficients amplified by T psi / (B k): solve_bvp then adds nodes for ever (a line
    with EI = 1e3 N m2, hard-flexible: 27 s and 3600 nodes for one mode instead of 0.5 s
    and 860 nodes, the same frequency to 1e-10)."""
    ell = (grid[-1] - grid[0]) / (np.pi * _half_waves(fam, Y0))
    sc = np.max(np.abs(Y0), axis=1)
    floor = 100.0 * np.finfo(float).eps / tol
    sq = np.zeros(fam.n)
    for pc in pieces:
        sel = (grid >= pc.s0) & (grid <= pc.s1)
        A, B = fam.matrices(pc, grid[sel])
        terms = np.abs(A + lam0 * B) * np.abs(Y0[None, :, sel])
        sc = np.maximum(sc, floor * pc.length * np.max(terms, axis=(1, 2)))
        big = np.max(terms, axis=1)
        sq += np.trapezoid(big ** 2, grid[sel], axis=1)
    sc = np.maximum(sc, TERM_FRACTION * ell * np.sqrt(sq / (grid[-1] - grid[0])))
    # a state the mode does not move (the axial states of a vertical line's lateral mode,
    # decoupled by symmetry: its guess is round-off) is scaled at 1e-6 of the largest:
    # at 1e-9 its round-off stalled solve_bvp (a hanging chain's in-plane modes)
    absent = np.max(np.abs(Y0), axis=1) < 1e-9 * np.max(np.abs(Y0))
    sc = np.where(absent, np.maximum(sc, 1e-6 * np.max(sc)), sc)
    return np.maximum(sc, 1e-9 * np.max(sc))


def _end_refined(tau: np.ndarray, pieces: list[Piece]) -> np.ndarray:
    """``tau`` with nodes added geometrically towards both ends of the unit interval down
    to a quarter of the shortest bending length sqrt(EI/T) of a piece (the boundary layers
    at the ends, the joints and the lift-off point)."""
    r = 1.0
    for pc in pieces:
        T = pc.spl["T"](np.linspace(pc.s0, pc.s1, 33))
        T = T[T > 0.0]
        if T.size:
            r = min(r, float(np.sqrt(pc.EI / np.max(T))) / pc.length)
    extra = r * 0.25 * 2.0 ** np.arange(0, 60)
    extra = extra[extra < tau[1]]
    return np.unique(np.concatenate([tau, extra, 1.0 - extra]))


def _shape(pieces: list[Piece], fam: Family, sol, sc: np.ndarray):
    """(s (k,), displacement (k, 3)) at the collocation nodes, the joints once."""
    nz = fam.n + 1
    s_all, u_all = [], []
    for k, pc in enumerate(pieces):
        tau = sol.x if k == 0 else sol.x[1:]
        Y = sol.y[k * nz:k * nz + fam.n] if k == 0 else sol.y[k * nz:k * nz + fam.n, 1:]
        s_all.append(pc.s0 + pc.length * tau)
        u_all.append(fam.shape(Y * sc[:, None]))
    return np.concatenate(s_all), np.concatenate(u_all)

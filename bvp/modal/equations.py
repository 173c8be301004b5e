"""The linearised free-vibration equations about the BVP static solution, and a box-scheme
eigen-solver that gives the starting modes (the model and its derivation are in the
docstring of :mod:`bvp.modal.modes`).

The line is cut into *pieces*: the scene's segments, split where the static line enters
or leaves the seabed, so that every coefficient is smooth on a piece and jumps only at
its ends. On a piece the static state (theta, T, kappa = M/EI, F, y) is a cubic spline in
s of the converged profile; the perturbation obeys y' = (A(s) + omega^2 B(s)) y. The
weight and the seabed reaction are in A; the static drag of a current is, as a dead load,
when the pieces are built with ``dead_drag`` (:func:`build_pieces`).

Families (``FAMILIES``): ``in_plane`` with the state [dx, dy, dtheta, dM, dF, dT] and
``out_of_plane`` with the state [w, psi, B, Q] (z displacement, z component of the unit
tangent, bending moment about the in-plane normal, z shear force).
"""

from __future__ import annotations

import inspect
import math
from dataclasses import dataclass, field

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.sparse import coo_matrix
from scipy.sparse.linalg import LinearOperator, eigs, splu

from riser.results.profile import Profile
from riser.errors import UnsupportedSceneError
from riser.model.scene import FixedEnds, Scene
from riser.model.sections import segment_properties


@dataclass
class Piece:
    """One smooth stretch of line [s0, s1] [m]: section values (EI [N m2], 1/EA [1/N],
    mass m and normal added mass ma [kg/m], submerged weight w [N/m]), the seabed law of
    the static solve (``k`` [N/m2]) and whether the static line lies in it (``contact``:
    the linearised spring k acts on dy), the splines of the static state, and the static
    drag: the coefficients ``c_n`` = 0.5 rho D C_Dn and ``c_t`` = 0.5 rho pi D C_Dt
    [kg/m2] and ``speed`` (the signed in-plane current along +x [m/s] at height y; None:
    no current), as in ``bvp/beam/equations.py``."""

    s0: float
    s1: float
    EI: float
    inv_EA: float
    m: float
    ma: float
    w: float
    k: float
    contact: bool
    spl: dict = field(repr=False, default_factory=dict)
    c_n: float = 0.0
    c_t: float = 0.0
    speed: object = field(repr=False, default=None)

    @property
    def length(self) -> float:
        return self.s1 - self.s0

    def static(self, s: np.ndarray) -> dict:
        """Static state at arc lengths ``s``: theta, T, kappa, F, y, the seabed reaction p
        [N/m], the linearised spring kc [N/m2] (k in contact, else 0) and the static drag
        per unstretched length f_n along n and f_t along t [N/m] (``bvp/beam/equations.py``:
        f_n = c_n |V_n| V_n, V_n = -V sin theta; f_t = c_t |V_t| V_t, V_t = V cos theta)."""
        out = {key: f(s) for key, f in self.spl.items()}
        y = out["y"]
        if self.speed is None:
            out["f_n"] = out["f_t"] = np.zeros_like(y)
        else:
            V = self.speed(y)
            vn, vt = -V * np.sin(out["theta"]), V * np.cos(out["theta"])
            out["f_n"] = self.c_n * np.abs(vn) * vn
            out["f_t"] = self.c_t * np.abs(vt) * vt
        out["p"] = self.reaction(y)
        out["kc"] = self.k if self.contact else 0.0
        return out

    def reaction(self, y: np.ndarray) -> np.ndarray:
        """The seabed's static reaction [N/m] at heights ``y`` [m]: its linear branch
        -k y in a contact piece (as the static solve), the unilateral k max(-y, 0)
        elsewhere."""
        return -self.k * y if self.contact else self.k * np.maximum(-y, 0.0)


@dataclass(frozen=True)
class Family:
    """One family of modes: its state names, the displacement rows, the end conditions."""

    plane: str
    names: tuple
    disp: tuple            # state index -> shape component (x, y, z) for displacements
    pinned: tuple          # states zero at a pinned, moment-free end
    clamped: tuple         # states zero at a clamped end

    @property
    def n(self) -> int:
        return len(self.names)

    def matrices(self, pc: Piece, s: np.ndarray):
        """(A, B), each (n, n, m): y' = (A + omega^2 B) y at arc lengths s."""
        st = pc.static(s)
        m = s.size
        c, sn = np.cos(st["theta"]), np.sin(st["theta"])
        T, kap, F = st["T"], st["kappa"], st["F"]
        e1 = 1.0 + T * pc.inv_EA
        mn = pc.m + pc.ma
        A = np.zeros((self.n, self.n, m))
        B = np.zeros_like(A)
        if self.plane == "in_plane":
            dx, dy, dth, dM, dF, dT = range(6)
            A[dx, dth] = -e1 * sn
            A[dx, dT] = c * pc.inv_EA
            A[dy, dth] = e1 * c
            A[dy, dT] = sn * pc.inv_EA
            A[dth, dM] = 1.0 / pc.EI
            A[dM, dF] = e1
            A[dM, dT] = F * pc.inv_EA
            A[dF, dT] = kap
            A[dF, dM] = T / pc.EI
            # the dead loads turn with the frame: d(q.n) = -(q.t) dtheta, d(q.t) = (q.n)
            # dtheta, q = (0, p - w) + f_n n + f_t t (the drag frozen at its static value)
            A[dF, dth] = (pc.w - st["p"]) * sn - st["f_t"]
            A[dF, dy] = -st["kc"] * c
            A[dT, dF] = -kap
            A[dT, dM] = -F / pc.EI
            A[dT, dth] = (pc.w - st["p"]) * c - st["f_n"]
            A[dT, dy] = st["kc"] * sn
            B[dF, dx] = -mn * sn
            B[dF, dy] = mn * c
            B[dT, dx] = -pc.m * c
            B[dT, dy] = -pc.m * sn
        else:
            w, psi, bm, q = range(4)
            A[w, psi] = e1
            A[psi, bm] = 1.0 / pc.EI
            A[bm, psi] = e1 * T - pc.EI * kap * kap
            A[bm, q] = -e1
            B[q, w] = -mn
        return A, B

    def mass(self, pc: Piece, s: np.ndarray) -> np.ndarray:
        """(n, n, m): u^T W u is the kinetic-energy density / omega^2 (m along the axis,
        m + ma normal to it)."""
        W = np.zeros((self.n, self.n, s.size))
        mn = pc.m + pc.ma
        if self.plane == "in_plane":
            th = pc.spl["theta"](s)
            c, sn = np.cos(th), np.sin(th)
            W[0, 0] = pc.m * c * c + mn * sn * sn
            W[1, 1] = pc.m * sn * sn + mn * c * c
            W[0, 1] = W[1, 0] = (pc.m - mn) * c * sn
        else:
            W[0, 0] = mn
        return W

    def shape(self, Y: np.ndarray) -> np.ndarray:
        """(k, 3) displacement components x, y, z of states Y (n, k)."""
        out = np.zeros((Y.shape[1], 3))
        for i, comp in enumerate(self.disp):
            if comp is not None:
                out[:, comp] = Y[i]
        return out


FAMILIES = {
    "in_plane": Family("in_plane", ("dx", "dy", "dtheta", "dM", "dF", "dT"),
                       (0, 1, None, None, None, None), (0, 1, 3), (0, 1, 2)),
    "out_of_plane": Family("out_of_plane", ("w", "psi", "B", "Q"), (2, None, None, None),
                           (0, 2), (0, 1)),
}


def require_linearisable(scene: Scene, who: str, three_d: bool = False) -> None:
    """Refuse, before solving, a scene whose static state cannot be linearised here:
    ends that are not fixed, an out-of-plane current (a 3D static state; unless
    ``three_d``: the analysis linearises the 3D rod, bvp/modal/rod_family.py), a rigid
    seabed (no linear stiffness). ``who`` names the analysis in the message ('bvp modes',
    'the frequency domain')."""
    src = scene.source
    if not isinstance(scene.ends, FixedEnds):
        raise UnsupportedSceneError(
            f"{src}: ends: {who} need(s) fixed ends (anchor + hang_off), the scene gives the "
            f"'{scene.ends.kind}' form (convert it with "
            "verification.pipeline.vfife_equivalent)")
    why = scene.out_of_plane(statics=True)
    if why is not None and not three_d:
        raise UnsupportedSceneError(
            f"{src}: {why[0]}: {why[1]}: the static state is not planar, {who} "
            "linearise(s) about a planar one (the coupled modes and the harmonic "
            "response linearise a 3D static state; the VFIFE's time domain solves it)")
    if scene.seabed_model == "rigid":
        raise UnsupportedSceneError(
            f"{src}: model.seabed: 'rigid' has no linear stiffness (a touchdown point); "
            f"{who} need(s) the elastic seabed")


# ------------------------------------------------------------------ static line -> pieces
def _signed(magnitude: np.ndarray, of: np.ndarray, s: np.ndarray) -> np.ndarray:
    """``magnitude`` signed with the slope of ``of`` along s (a cubic spline's derivative)."""
    return magnitude * np.sign(CubicSpline(s, of)(s, 1))


def build_pieces(scene: Scene, profile: Profile, dead_drag: bool = False) -> list[Piece]:
    """The pieces of the static ``profile`` of ``scene`` (see the module docstring).

    Moment and shear are magnitudes in a profile: the moment takes the sign of dtheta/ds,
    the shear that of dM/ds (M' = (1 + eps) F).

    ``dead_drag``: the pieces carry the static drag of the scene's in-plane current, and
    :meth:`Family.matrices` holds it as a dead load (fixed in direction: the terms
    -f_t dtheta in dF' and -f_n dtheta in dT'), the model of :mod:`bvp.modal.modes`. False (the
    default): the drag's terms are left to the caller, as a linearisation of the drag
    itself (a Morison increment d(q.n) = df_n already holds the turning of the flow, so
    the dead-load terms would count it twice)."""
    props = segment_properties(scene)
    speed = None
    cur = scene.current
    if dead_drag and cur is not None and cur.max_abs_speed > 0.0:
        def speed(y):                     # the x component (in plane)
            return cur.velocity(y)[0]
    extensible = scene.axial_model == "extensible"
    k = scene.seabed.stiffness if scene.seabed_model == "elastic" else 0.0
    s_all = profile.s
    breaks = _contact_breaks(profile) if k > 0.0 else []
    pieces = []
    for p in props:
        sel = (s_all >= p.s_start - 1e-9) & (s_all <= p.s_end + 1e-9)
        idx = np.flatnonzero(sel)
        keep = np.concatenate([[True], np.diff(s_all[idx]) > 1e-4])  # thin near-duplicates
        idx = idx[keep]
        s = s_all[idx]
        th = profile.theta[idx]
        kap = _signed(profile.curvature[idx], th, s)
        F = _signed(profile.shear[idx], p.EI * kap, s)
        spl = {"theta": CubicSpline(s, th), "T": CubicSpline(s, profile.tension[idx]),
               "kappa": CubicSpline(s, kap), "F": CubicSpline(s, F),
               "y": CubicSpline(s, profile.y[idx])}
        inv_EA = 1.0 / p.EA if extensible and p.EA else 0.0
        cuts = [p.s_start] + [b for b in breaks if p.s_start + 1e-3 < b < p.s_end - 1e-3]
        cuts.append(p.s_end)
        for a, b in zip(cuts[:-1], cuts[1:]):
            mid = 0.5 * (a + b)
            in_zone = profile.tdp_s is not None and b <= profile.tdp_s + 1e-6 \
                and profile.y[0] <= 1e-9
            contact = k > 0.0 and (in_zone or float(spl["y"](mid)) < 0.0)
            pieces.append(Piece(a, b, p.EI, inv_EA, p.mass, p.added_mass, p.weight, k,
                                contact, spl, p.drag_normal_coef, p.drag_tangential_coef,
                                speed))
    return pieces


def _contact_breaks(profile: Profile) -> list[float]:
    """Arc lengths where the static line enters or leaves the seabed: the lift-off point
    of the contact zone at the bottom end (the BVP's ``tdp_s``) and any crossing of y = 0
    beyond it."""
    s, y = profile.s, profile.y
    out = []
    start = 0.0
    if profile.tdp_s is not None and y[0] <= 1e-9:
        out.append(float(profile.tdp_s))
        start = float(profile.tdp_s) + 1e-6
    beyond = s > start
    sb, yb = s[beyond], y[beyond]
    for j in np.flatnonzero(np.signbit(yb[1:]) != np.signbit(yb[:-1])):
        if yb[j] == yb[j + 1]:
            continue
        cand = sb[j] + (0.0 - yb[j]) / (yb[j + 1] - yb[j]) * (sb[j + 1] - sb[j])
        if not out or cand - out[-1] > 1e-2:
            out.append(float(cand))
    return out


# ------------------------------------------------------------------ box scheme guesses
def state_scales(pieces: list[Piece], fam: Family, count: int) -> np.ndarray:
    """Typical size of each state for a unit displacement over a wavelength l (the line
    over count + 1): rotations 1/l, moments EI/l^2, forces T/l (a string's shear)."""
    L = pieces[-1].s1 - pieces[0].s0
    ell = L / (count + 1)
    EI = max(pc.EI for pc in pieces)
    Tmax = max(float(np.max(np.abs(pc.spl["T"](np.linspace(pc.s0, pc.s1, 9)))))
               for pc in pieces)
    Tref = max(Tmax, EI / ell ** 2)
    if fam.plane == "in_plane":
        return np.array([1.0, 1.0, 1.0 / ell, EI / ell ** 2, Tref / ell, Tref / ell])
    if fam.plane == "out_of_plane":
        return np.array([1.0, 1.0 / ell, EI / ell ** 2, Tref / ell])
    # the coupled family (bvp/modal/rod_family.py): the in-plane six, then z, phi, M2, F2
    return np.array([1.0, 1.0, 1.0 / ell, EI / ell ** 2, Tref / ell, Tref / ell,
                     1.0, 1.0 / ell, EI / ell ** 2, Tref / ell])


#: seed of ARPACK's start vector: scipy otherwise starts from a random vector (a fresh
#: one on every call), and the refined modes then differed in the last digits from run to
#: run; a fixed start repeats them bit for bit (tests/test_reproducible.py).
ARPACK_SEED = 20240530


def _arpack_start(size: int) -> dict:
    """``eigs`` keywords of a reproducible start: ``v0`` uniform in [-1, 1] (as scipy's
    own) from a generator seeded with :data:`ARPACK_SEED`, and that generator as ``rng``
    (ARPACK's random restarts) where scipy takes one."""
    rng = np.random.default_rng(ARPACK_SEED)
    kw = {"v0": rng.uniform(-1.0, 1.0, size)}
    if "rng" in inspect.signature(eigs).parameters:
        kw["rng"] = rng
    return kw


def box_matrix(left: np.ndarray, right: np.ndarray, ends: tuple, end_value: float):
    """The sparse (CSC) matrix of the box scheme on N intervals of a state of n: the rows
    of the end conditions first (``ends`` = (rows at s = 0, rows at s = L), each row
    ((state, coefficient), ...) of a linear form on the end's state, bvp/modal/ends.py, or
    a state index held at zero; the coefficients times ``end_value``), then per interval j
    the n rows ``left[j] Y[j] + right[j] Y[j+1]`` (``left``, ``right``: (N, n, n), real or
    complex); unknowns Y[0], ..., Y[N] in order. The same pattern serves the modes'
    stiffness and mass and the harmonic response."""
    N, n = left.shape[0], left.shape[1]
    b0, b1 = (_rows(b) for b in ends)
    r0 = len(b0)
    R = np.broadcast_to(r0 + np.arange(N)[:, None, None] * n + np.arange(n)[None, :, None],
                        (N, n, n))
    C = np.broadcast_to(np.arange(N)[:, None, None] * n + np.arange(n)[None, None, :],
                        (N, n, n))
    er, ec, ev = [], [], []
    for base, col0, rows in ((0, 0, b0), (r0 + N * n, N * n, b1)):
        for r, row in enumerate(rows):
            for i, coef in row:
                er.append(base + r)
                ec.append(col0 + i)
                ev.append(end_value * coef)
    rows = np.concatenate([np.asarray(er, int), R.ravel(), R.ravel()])
    cols = np.concatenate([np.asarray(ec, int), C.ravel(), (C + n).ravel()])
    vals = np.concatenate([np.asarray(ev), left.ravel(), right.ravel()])
    size = (N + 1) * n
    return coo_matrix((vals, (rows, cols)), shape=(size, size)).tocsc()


def _rows(b) -> tuple:
    """End rows from rows or state indices (bvp/modal/ends.py)."""
    return tuple(((int(r), 1.0),) if np.isscalar(r) else tuple(r) for r in b)


def box_modes(pieces: list[Piece], fam: Family, ends: tuple, count: int,
              intervals: int = 3000):
    """Approximate lowest ``count`` (+ a few) modes by the box scheme (midpoint rule on
    every interval of a grid with nodes at the piece ends: second order):
    (Y[j+1] - Y[j]) / h = (A + lam B)(s_mid) (Y[j] + Y[j+1]) / 2, with the end rows
    ``ends`` = (states zero at s = 0, states zero at s = L); a sparse generalised
    eigenproblem K Y = lam M Y solved by shift-invert below zero.

    Returns (lam (k,) [rad2/s2] ascending, grid s (N+1,), states (k, n, N+1) in SI)."""
    n = fam.n
    L = pieces[-1].s1 - pieces[0].s0
    s = [np.array([pieces[0].s0])]
    which = []
    for i, pc in enumerate(pieces):
        nk = max(16, int(math.ceil(intervals * pc.length / L)))
        s.append(pc.s0 + pc.length * np.arange(1, nk + 1) / nk)
        which.append(np.full(nk, i))
    s = np.concatenate(s)
    which = np.concatenate(which)
    h = np.diff(s)
    mid = s[:-1] + 0.5 * h
    N = h.size
    A = np.zeros((N, n, n))
    Bm = np.zeros((N, n, n))
    for i, pc in enumerate(pieces):
        sel = which == i
        a, b = fam.matrices(pc, mid[sel])
        A[sel] = np.moveaxis(a, -1, 0)
        Bm[sel] = np.moveaxis(b, -1, 0)
    sc = state_scales(pieces, fam, count)
    A = A * sc[None, None, :] / sc[None, :, None]
    Bm = Bm * sc[None, None, :] / sc[None, :, None]
    # the end rows on the scaled states: sum c_i Y_i = sum (c_i sc_i) (Y_i / sc_i), as the
    # refinement (bvp.modal.modes) scales them. Unscaled, a mixed row (a tensioner's, the
    # top inclined by a current) weighed its states wrongly: ttr-steel's guess of in-plane
    # mode 1 was 18 % off and the guess checks rejected correctly refined modes
    ends = tuple(tuple(tuple((i, c * sc[i]) for i, c in row) for row in _rows(side))
                 for side in ends)
    eye = np.eye(n)[None]
    hh = 0.5 * h[:, None, None]
    K = box_matrix(-eye - hh * A, eye - hh * A, ends, 1.0)
    M = box_matrix(hh * Bm, hh * Bm, ends, 0.0)
    size = (N + 1) * n
    # shift: a tenth of a string's first eigenvalue below zero (every eigenvalue of a
    # stable static state is positive, so the nearest to the shift are the lowest)
    mmax = max(pc.m + pc.ma for pc in pieces)
    lam_est = (math.pi / L) ** 2 * sc[-1] * (L / (count + 1)) / mmax
    sigma = -0.1 * lam_est
    lu = splu((K - sigma * M).tocsc())
    op = LinearOperator((size, size), matvec=lambda v: lu.solve(M @ v), dtype=float)
    want = min(count + 4, size - 2)
    mu, vec = eigs(op, k=want, which="LM", ncv=min(size - 1, max(2 * want + 1, 40)),
                   **_arpack_start(size))
    lam = sigma + 1.0 / mu
    order = np.argsort(lam.real)
    lam, vec = lam[order], vec[:, order]
    keep = np.abs(lam.imag) <= 1e-6 * np.abs(lam.real)
    lam, vec = lam.real[keep], vec[:, keep]
    states = []
    for v in vec.T:
        v = v * np.exp(-1j * np.angle(v[np.argmax(np.abs(v))]))
        Y = v.real.reshape(N + 1, n).T * sc[:, None]
        disp = max(float(np.max(np.abs(Y[i]))) for i, c in enumerate(fam.disp)
                   if c is not None)
        states.append(Y / disp)
    return lam, s, np.array(states)

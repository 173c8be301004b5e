"""The frequency domain about the 3D rod's static state: the damped, forced linearisation
of the rod (bvp/rod/equations.py), in- and out-of-plane motion coupled in one family of
ten states, and its harmonic response on one grid (:func:`solve_on_grid`, which
:func:`bvp.frequency.harmonic.solve_harmonic` calls for a 3D static state).

Conventions: SI units, in the axes of the ends' plane (riser.model.frame.LinePlane: x
along it from the anchor, y up, z across it; the scene's hang-off motion is turned into
them by ``vector_to_plane`` and the response's displacements back by
``vector_from_plane``); s [m] the unstretched arc length from the bottom end; a harmonic
quantity is q_0(s) + Re(Q(s) e^{i omega t}) (riser.results.response). The state is the
rod's, perturbed (bvp/modal/rod_family.py):

    u = [dx, dy, dtheta, dM1, dF1, dT, dz, dphi, dM2, dF2]

The undamped operator is :class:`bvp.modal.rod_family.RodFamily`'s, exactly (the complex
step Jacobian of ``rod_rhs`` about the static state, its seabed spring and the inertia
omega^2 M0 dr, M0 = m t t^T + (m + m_a)(I - t t^T)): u' = (A + omega^2 B) u. It holds the
static load dead (fixed in the plane's axes at each material point): the weight, the
seabed reaction and the current's drag. The frequency domain keeps the weight and the
seabed dead (global axes) and treats the drag as Morison drag on the relative velocity,
linearised; it adds, as the planar frequency domain (bvp/frequency/equations.py) does:

- structural damping c_s [1/s] (``[dynamics] damping``): omega^2 B -> (omega^2 - i omega
  c_s) B;
- internal axial damping (BA [N s], Kelvin-Voigt): the strain's increment dT / (EA + i
  omega BA), so the rows that take dT / EA (dx', dy', dz', dM1', dM2': the stretch
  e = 1 + T/EA) take it times 1 / (1 + i omega BA / EA);
- the seabed's contact damping c_sb = 2 zeta sqrt(k (m + m_a)) beside the spring where
  the static line lies in it: k -> k + i omega c_sb on dy (the dead vertical reaction's
  increment dq = -(k + i omega c_sb) dy e_y, in the rows of F1, F2, T by n1, n2, -t);
- Morison drag on the relative velocity v = U(y) + u_w - i omega dr (U the current in the
  plane's axes, u_w the wave's flow, i omega dr the line's velocity): normal part
  f_perp = c_n |v_perp| v_perp, tangential f_t = c_t |v_t| v_t (c_n = 0.5 rho D C_Dn,
  c_t = 0.5 rho pi D C_Dt, per unstretched length, as the static rod applies them).

The drag's frame components. The load q = f_t t + f_1 n1 + f_2 n2 with f_1, f_2, f_t
functions of the frame components V_j = v . e_j of the relative velocity: its frame
components are q . n1 = f_1 etc. exactly, so in the rod's rows (F1' += q . n1, F2' += q .
n2, T' -= q . t) their increments are df_1, df_2, df_t: the frame's turning is in dV_j,
not in a turning of a dead load (it cancels between the load vector's rotation and the
frame's, as in the planar frequency domain). So the dead drag's turning that A holds,
q_d . de_j/dtheta dtheta + q_d . de_j/dphi dphi in those rows (q_d the static drag,
:func:`static_drag`), is taken out of A, and the rows gain df instead, with

    dV_j = (dU/dy . e_j) dy + U . (de_j/dtheta dtheta + de_j/dphi dphi)
           - i omega e_j . dr + u_w . e_j,        e_j in (n1, n2, t),

the frame's derivatives t_theta = cos(phi) n1, t_phi = n2, n1_theta = (-cos theta,
-sin theta, 0), n1_phi = 0, n2_theta = -sin(phi) n1, n2_phi = -t (bvp/rod/equations.py).
Then (df_1, df_2) = C_perp (dV_1, dV_2) and df_t = C_t dV_t.

Equivalent linearisation (equal work per cycle, per principal direction): about the
static normal relative flow v0 = (V_1, V_2) (in the n1-n2 plane) the directions are
e = v0 / |v0| and its perpendicular e_perp in the normal plane,

    C_perp = C_par e e^T + C_cross e_perp e_perp^T,

with (C_par, C_cross, C_t) the planar :func:`bvp.frequency.equations.
equivalent_coefficients` of the static speed v_n0 -> |v0| along e, the oscillating
amplitudes a_n -> a . e (along the flow) and a_z -> a . e_perp (across it), v_t0 -> V_t
and a_t. In still water (|v0| <= :data:`bvp.frequency.equations.TINY_SPEED`) e is the
major axis of the oscillation's ellipse in the normal plane (the eigenvector of Re(a
a^H)): no basis makes the per-direction coefficients isotropic (a circular orbit alone
gives C_par = C_cross), their values depend on the basis for any other oscillation, and
only the ellipse's own axes make the oscillation's components uncorrelated (<w_par
w_cross> = 0 over the cycle), which a diagonal C_perp assumes. The result then does not
depend on the frame (tests/test_frequency_3d.py). The planar frequency domain takes the
fixed (n, z) instead: the same wherever the oscillation in the normal plane is
rectilinear (a motion along one axis at a planar state: e = n1 or n2), not for an orbit
of the hang-off in still water, where the principal axes agree better with the VFIFE's
time domain (measured on the 420 m catenary of tests/test_dynamic_compare.py, an orbit of
(0.1, 0.2, 0.14 at 90 deg) m at 5.8 s: the out-of-plane moment 0.9 % off the VFIFE's
against 3.3 %). With a static flow, at a planar state with the flow in plane, e = +-n1
and this is the planar frequency domain term for term (C_n = C_par, C_z = C_cross;
w = dz, psi = dphi, B = dM2, Q = T dphi - dF2).

Waves: the wave's flow (:meth:`bvp.frequency.wave_loads.LineFlow.at_frame`: its
components along t, n1, n2 of the static line) is in dV_j, and its acceleration loads
the line through the fluid inertia, (1 + C_a) rho A normal to it and rho A along it (the
planar model's): the inhomogeneous term g of u' = K u + g, g_F1 = C_11 u_1 + C_12 u_2 +
M a_1, g_F2 = C_21 u_1 + C_22 u_2 + M a_2, g_T = -(C_t u_t + M_t a_t).

Ends: the bottom fixed in space, the top moving by the motion's components in the
plane's axes; moment-free (dM1 = dM2 = 0) or keeping its direction (dtheta = dphi = 0)
per ``[vfife] clamped_ends`` (:data:`ROD_FAMILY`'s pinned and clamped rows). The box
scheme, the grid and the drag coefficients' fixed point are the planar frequency
domain's (:mod:`bvp.frequency.harmonic`).

Outputs (:class:`riser.results.response.HarmonicResponse`): dx, dy, dz in the scene's
axes; ``tension`` dT; ``moment`` dM1 and ``moment_out`` dM2, the increments of the 3D
profile's ``moment_in_plane`` and ``moment_out_of_plane`` columns (riser.model.frame.
plane_columns: for the rod's tangent, |phi| < 90 deg, b = unit(t x e_z) = -n1 and
b x t = n2, so the columns are m . n2 = M1 and m . (-n1) = M2 of m = M1 n2 - M2 n1
identically, and their increments dM1 and dM2 hold the frame's turning);
``curvature`` dM1 / EI; ``shear`` dF1 (the in-plane shear component). ``static``: the
tension T, the moment in the plane M1 and out of it M2 at the nodes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import solve_banded

from riser.model.scene import Scene
from riser.model.sections import segment_properties
from riser.results.response import HarmonicResponse
from riser.results.result import Status

from . import equations as he
from ..modal.equations import Piece
from ..modal.rod_family import (IF1, IF2, IM1, IM2, IPH, IT, ITH, IX, IY, IZ, ROD_FAMILY)
from ..rod.equations import RodModel
from ..rod.problem import plane_current

#: under-relaxation of the drag coefficients' fixed point (the planar one's)
RELAXATION = 0.5
#: the rows the strain dT / EA enters (the stretch e = 1 + T / EA), softened by the
#: axial damping
STRETCH_ROWS = (IX, IY, IZ, IM1, IM2)
#: the displacement states (x, y, z)
DISP = (IX, IY, IZ)


def frame_derivatives(th: np.ndarray, ph: np.ndarray):
    """((t, n1, n2), (t_theta, n1_theta, n2_theta), (t_phi, n1_phi, n2_phi)), each (3, m),
    the rod's frame and its derivatives by theta and phi [1/rad] (module docstring)."""
    t, n1, n2 = RodModel.frame(th, ph)
    c, s, sp = np.cos(th), np.sin(th), np.sin(ph)
    zero = np.zeros_like(th)
    d_th = (np.cos(ph) * n1, np.stack([-c, -s, zero]), -sp * n1)
    d_ph = (n2, np.zeros_like(n1), -t)
    return (t, n1, n2), d_th, d_ph


def static_drag(c_n, c_t, U: np.ndarray, frame) -> tuple[np.ndarray, np.ndarray]:
    """(the frame components (f_t, f_1, f_2) (3, m), the drag vector (3, m)) [N/m]: the
    static drag of the current U (3, m) [m/s] in the plane's axes on the line of frame
    (t, n1, n2): f_t = c_t |V_t| V_t, (f_1, f_2) = c_n |V_perp| (V_1, V_2), V_j = U . e_j
    (the static rod's, bvp/rod/equations.py)."""
    t, n1, n2 = frame
    Vt, V1, V2 = (np.sum(U * e, axis=0) for e in (t, n1, n2))
    r = np.hypot(V1, V2)
    f = np.stack([c_t * np.abs(Vt) * Vt, c_n * r * V1, c_n * r * V2])
    return f, f[0] * t + f[1] * n1 + f[2] * n2


@dataclass
class RodSetup:
    """What the responses on one grid share, whatever the frequency: the grid ``s`` (N +
    1,) [m], its steps ``h`` and midpoints ``mid`` (N,), the piece of each midpoint
    ``which``; at the midpoints (arrays (N, ...)): the undamped ``A``, ``B`` (N, 10, 10) of
    :data:`ROD_FAMILY` (the static drag held dead), the dead drag's turning ``turn`` (N,
    10, 10) that A holds (:func:`operator` takes it out), the relative velocity's increment
    ``Gr`` (the current's part: (N, 3, 10), rows (n1, n2, t)) and ``Gv`` (the line's
    velocity's, to be multiplied by i omega), the static flow ``V`` (N, 3) (V_1, V_2, V_t)
    [m/s], the drag coefficients ``c_n``, ``c_t`` [kg/m2], the seabed dashpot ``csb``
    [N s/m2] with the vertical's frame rows ``ey`` (N, 10) (n1_y, n2_y, -t_y in the rows
    of F1, F2, T), the axial damping times ``ba_ea`` [s], the frame ``frame`` (t, n1, n2)
    each (3, N) in the plane's axes, the heights ``y`` [m] and the static drag's frame
    components ``static_drag`` (3, N) (f_t, f_1, f_2) [N/m] (:func:`static_drag`); the
    structural damping ``c_s`` [1/s] and the clamped ends."""

    pieces: list
    s: np.ndarray
    h: np.ndarray
    mid: np.ndarray
    which: np.ndarray
    A: np.ndarray
    B: np.ndarray
    turn: np.ndarray
    Gr: np.ndarray
    Gv: np.ndarray
    V: np.ndarray
    c_n: np.ndarray
    c_t: np.ndarray
    csb: np.ndarray
    ey: np.ndarray
    ba_ea: np.ndarray
    frame: tuple
    y: np.ndarray
    c_s: float
    clamped: tuple
    static_drag: np.ndarray

    @property
    def has_drag(self) -> bool:
        return bool(np.any(self.c_n > 0.0) or np.any(self.c_t > 0.0))


def prepare(scene: Scene, state, pieces: list[Piece], s: np.ndarray) -> RodSetup:
    """The :class:`RodSetup` of the grid ``s`` about the rod's static ``state``
    (bvp/rod/output.RodState) on its ``pieces`` (bvp.modal.rod_family.rod_pieces)."""
    h = np.diff(s)
    mid = s[:-1] + 0.5 * h
    m = mid.size
    ends_at = np.array([pc.s1 for pc in pieces])
    which = np.clip(np.searchsorted(ends_at, mid), 0, len(pieces) - 1)
    A = np.zeros((m, 10, 10))
    B = np.zeros_like(A)
    th, ph, y = np.empty(m), np.empty(m), np.empty(m)
    csb = np.zeros(m)
    for i, pc in enumerate(pieces):
        sel = which == i
        a, b = ROD_FAMILY.matrices(pc, mid[sel])
        A[sel], B[sel] = np.moveaxis(a, -1, 0), np.moveaxis(b, -1, 0)
        th[sel], ph[sel], y[sel] = pc.spl["th"](mid[sel]), pc.spl["ph"](mid[sel]), \
            pc.spl["y"](mid[sel])
        csb[sel] = he.contact_dashpot(scene, pc)
    props = segment_properties(scene)
    seg = np.clip(np.searchsorted(np.array([p.s_end for p in props]), mid), 0,
                  len(props) - 1)
    c_n = np.array([p.drag_normal_coef for p in props])[seg]
    c_t = np.array([p.drag_tangential_coef for p in props])[seg]
    frame, d_th, d_ph = frame_derivatives(th, ph)
    velocity, gradient, _ = plane_current(scene, state.plane)
    U, Up = np.zeros((3, m)), np.zeros((3, m))
    if velocity is not None:
        U[0], U[2] = (np.asarray(v, float) * np.ones(m) for v in velocity(y))
        Up[0], Up[2] = (np.asarray(v, float) * np.ones(m) for v in gradient(y))
    # the dead drag's turning, which ROD_FAMILY's A holds (module docstring): the rows
    # q_d . n1, q_d . n2, -q_d . t differentiated by theta and phi
    f0, qd = static_drag(c_n, c_t, U, frame)
    t, n1, n2 = frame
    turn = np.zeros_like(A)
    for row, k, sign in ((IF1, 1, 1.0), (IF2, 2, 1.0), (IT, 0, -1.0)):
        turn[:, row, ITH] = sign * np.sum(qd * d_th[k], axis=0)
        turn[:, row, IPH] = sign * np.sum(qd * d_ph[k], axis=0)
    # the relative velocity's frame components' increments, rows (n1, n2, t)
    Gr, Gv = np.zeros((m, 3, 10)), np.zeros((m, 3, 10))
    for j, k in enumerate((1, 2, 0)):
        Gr[:, j, IY] = np.sum(Up * frame[k], axis=0)
        Gr[:, j, ITH] = np.sum(U * d_th[k], axis=0)
        Gr[:, j, IPH] = np.sum(U * d_ph[k], axis=0)
        for col, comp in zip(DISP, range(3)):
            Gv[:, j, col] = -frame[k][comp]
    V = np.stack([np.sum(U * n1, axis=0), np.sum(U * n2, axis=0), np.sum(U * t, axis=0)],
                 axis=1)
    ey = np.zeros((m, 10))
    ey[:, IF1], ey[:, IF2], ey[:, IT] = n1[1], n2[1], -t[1]
    c_s = scene.dynamics.damping if scene.dynamics is not None else 0.0
    return RodSetup(pieces, s, h, mid, which, A, B, turn, Gr, Gv, V, c_n, c_t, csb, ey,
                    he.damping_times(scene, pieces, mid, which), frame, y, c_s,
                    tuple(scene.vfife.clamped_ends), f0)


# ------------------------------------------------------------------ the operator
def operator(setup: RodSetup, omega: float, C: dict | None) -> np.ndarray:
    """Complex (N, 10, 10) K of u' = K u + g at the midpoints for the circular frequency
    omega [rad/s] and the drag coefficients ``C`` (C11, C12, C22, Ct [N s/m2], each (N,):
    C_perp in the n1-n2 basis and C_t; module docstring). ``C`` None: the undamped
    operator of the modes, ROD_FAMILY's A + omega^2 B exactly (the static drag a dead
    load, no damping): its poles are :func:`bvp.modal.modes.solve_modes`' coupled modes."""
    if C is None:
        return (setup.A + omega ** 2 * setup.B).astype(complex)
    iw = 1j * omega
    K = (setup.A - setup.turn + (omega ** 2 - iw * setup.c_s) * setup.B).astype(complex)
    K[:, :, IY] -= iw * (setup.csb[:, None] * setup.ey)
    H = setup.Gr + iw * setup.Gv                   # (N, 3, 10): d(V_1, V_2, V_t) / du
    K[:, IF1] += C["C11"][:, None] * H[:, 0] + C["C12"][:, None] * H[:, 1]
    K[:, IF2] += C["C12"][:, None] * H[:, 0] + C["C22"][:, None] * H[:, 1]
    K[:, IT] -= C["Ct"][:, None] * H[:, 2]
    if np.any(setup.ba_ea):                        # the complex axial stiffness EA + i w BA
        soft = 1.0 / (1.0 + iw * setup.ba_ea)
        for row in STRETCH_ROWS:
            K[:, row, IT] *= soft
    return K


def wave_forcing(flow: dict, C: dict) -> np.ndarray:
    """The wave's inhomogeneous term g (N, 10) complex [N/m in the force rows] from its
    flow on the line (:meth:`bvp.frequency.wave_loads.LineFlow.at_frame`) and the drag
    coefficients ``C`` (module docstring)."""
    g = np.zeros((flow["u1"].size, 10), complex)
    g[:, IF1] = C["C11"] * flow["u1"] + C["C12"] * flow["u2"] + flow["inertia"] * flow["a1"]
    g[:, IF2] = C["C12"] * flow["u1"] + C["C22"] * flow["u2"] + flow["inertia"] * flow["a2"]
    g[:, IT] = -(C["Ct"] * flow["ut"] + flow["inertia_t"] * flow["at"])
    return g


def relative_velocity(setup: RodSetup, Um: np.ndarray, omega: float,
                      flow: dict | None = None) -> np.ndarray:
    """(N, 3) complex amplitudes (a_1, a_2, a_t) [m/s] of the oscillating relative
    velocity's frame components at the midpoints from the states Um (N, 10) there, plus
    the wave's flow when given."""
    a = np.einsum("mjk,mk->mj", setup.Gr + 1j * omega * setup.Gv, Um)
    if flow is not None:
        a = a + np.stack([flow["u1"], flow["u2"], flow["ut"]], axis=1)
    return a


def coefficients(setup: RodSetup, a: np.ndarray) -> dict:
    """The equivalent drag coefficients (C11, C12, C22, Ct) [N s/m2] for the oscillating
    relative velocity a (N, 3) (:func:`relative_velocity`) about the static flow (module
    docstring: the principal directions e, e_perp in the normal plane, the planar
    coefficients along them)."""
    V1, V2, Vt = setup.V[:, 0], setup.V[:, 1], setup.V[:, 2]
    r = np.hypot(V1, V2)
    a1, a2, at = a[:, 0], a[:, 1], a[:, 2]
    flowing = r > he.TINY_SPEED
    # still water: the major axis of the oscillation's ellipse, Re(a a^H)'s eigenvector
    S11, S22 = np.abs(a1) ** 2, np.abs(a2) ** 2
    S12 = (a1 * np.conj(a2)).real
    alpha = 0.5 * np.arctan2(2.0 * S12, S11 - S22)
    safe = np.where(flowing, r, 1.0)
    e1 = np.where(flowing, V1 / safe, np.cos(alpha))
    e2 = np.where(flowing, V2 / safe, np.sin(alpha))
    a_par = e1 * a1 + e2 * a2
    a_cross = -e2 * a1 + e1 * a2
    Cp, Cc, Ct = he.equivalent_coefficients(r, Vt, a_par, a_cross, at, setup.c_n,
                                            setup.c_t)
    return {"C11": Cp * e1 * e1 + Cc * e2 * e2, "C12": (Cp - Cc) * e1 * e2,
            "C22": Cp * e2 * e2 + Cc * e1 * e1, "Ct": Ct}


#: the coefficients' names, in the order they are stored and interpolated
COEFFICIENTS = ("C11", "C12", "C22", "Ct")


def largest(C: dict) -> np.ndarray:
    """(N,) [N s/m2] the larger principal value of C_perp (the 2 x 2 C11, C12, C22)."""
    half = 0.5 * (C["C11"] - C["C22"])
    return 0.5 * (C["C11"] + C["C22"]) + np.hypot(half, C["C12"])


def respond(setup: RodSetup, omega: float, motion: np.ndarray, C: dict | None,
            flow: dict | None = None) -> np.ndarray:
    """The states (N + 1, 10) [SI] at the grid's nodes for the circular frequency omega
    [rad/s], the hang-off motion (3,) complex [m] in the plane's axes, the drag
    coefficients ``C`` (None: the modes' undamped operator, :func:`operator`; no wave
    then) and the wave's flow at the midpoints (or None), by the box scheme of the planar
    frequency domain (the midpoint rule; the states scaled by
    :func:`bvp.frequency.equations.response_scales`)."""
    fam, pieces, s, h = ROD_FAMILY, setup.pieces, setup.s, setup.h
    n, N = fam.n, h.size
    b0 = fam.clamped if "bottom" in setup.clamped else fam.pinned
    b1 = fam.clamped if "top" in setup.clamped else fam.pinned
    driven = [(k, i) for k, i in enumerate(b1)
              if fam.disp[i] is not None and motion[fam.disp[i]] != 0.0]
    if C is None and flow is not None:
        raise ValueError("the modes' undamped operator (C None) carries no wave load")
    g = wave_forcing(flow, C) if flow is not None else None
    loaded = g is not None and bool(np.any(g != 0.0))
    if not driven and not loaded:
        return np.zeros((N + 1, n), complex)      # neither moved nor loaded
    K = operator(setup, omega, C)
    sc = he.response_scales(pieces, fam, omega, s[-1] - s[0])
    K = K * sc[None, None, :] / sc[None, :, None]
    eye = np.eye(n)[None]
    hh = 0.5 * h[:, None, None]
    lu, ab = box_banded(-eye - hh * K, eye - hh * K, b0, b1)
    rhs = np.zeros((N + 1) * n, complex)
    if loaded:
        rhs[len(b0):len(b0) + N * n] = (h[:, None] * g / sc[None, :]).ravel()
    for k, i in driven:
        rhs[len(b0) + N * n + k] = motion[fam.disp[i]] / sc[i]
    Y = solve_banded(lu, ab, rhs, overwrite_ab=True, overwrite_b=True, check_finite=False)
    return Y.reshape(N + 1, n) * sc[None, :]


def box_banded(left: np.ndarray, right: np.ndarray, b0: tuple, b1: tuple):
    """((l, u), ab): the box scheme's matrix of :func:`bvp.modal.equations.box_matrix`
    (the end rows ``b0`` (state indices held at s = 0) first, then per interval j the n
    rows ``left[j] Y[j] + right[j] Y[j+1]``, then the rows ``b1`` at s = L; unknowns
    Y[0], ..., Y[N]) in LAPACK's band storage, ab[u + row - col, col], for
    scipy.linalg.solve_banded (partial pivoting; a block-bidiagonal matrix of n states has
    l = r0 + n - 1 and u = 2 n - 1 - r0 with r0 = len(b0) end rows at s = 0, so the
    solve costs O(N n^3) without the sparse matrix's assembly and ordering: ten times
    less than the sparse LU for the ten states)."""
    N, n = left.shape[0], left.shape[1]
    r0 = len(b0)
    lo, up = r0 + n - 1, max(2 * n - 1 - r0, n - 1)
    size = (N + 1) * n
    ab = np.zeros((lo + up + 1, size), complex)
    rows = r0 + np.arange(N)[:, None, None] * n + np.arange(n)[None, :, None]
    cols = np.arange(N)[:, None, None] * n + np.arange(n)[None, None, :]
    rows = np.broadcast_to(rows, (N, n, n))
    ab[up + rows - cols, cols] = left
    ab[up + rows - cols - n, cols + n] = right
    for r, i in enumerate(b0):
        ab[up + r - i, i] = 1.0
    for r, i in enumerate(b1):
        ab[up + (r0 + N * n + r) - (N * n + i), N * n + i] = 1.0
    return (lo, up), ab


def start_coefficients(setup: RodSetup, flow: dict | None) -> dict:
    """The drag coefficients of the line at rest in the static current and the wave's
    flow (the small-amplitude values in a current, ~0 in still water)."""
    zero = np.zeros((setup.mid.size, 3), complex)
    a = zero if flow is None else np.stack([flow["u1"], flow["u2"], flow["ut"]], axis=1)
    return coefficients(setup, a)


def plane_motion(state, motion: np.ndarray) -> np.ndarray:
    """The hang-off motion (3,) complex [m] from the scene's axes to the plane's."""
    along, across = state.plane.vector_to_plane(motion[0], motion[2])
    return np.array([along, motion[1], across], complex)


def solve_on_grid(scene: Scene, state, pieces: list[Piece], period: float,
                  motion: np.ndarray, tol: float, max_iter: int, s: np.ndarray,
                  start=None, forcing=None, setup: RodSetup | None = None
                  ) -> HarmonicResponse:
    """The response on the grid ``s`` about the rod's static ``state`` (the counterpart
    of the planar :func:`bvp.frequency.harmonic._solve`): ``motion`` (3,) complex [m] in
    the scene's axes; ``start``: drag coefficients (s_mid, C11, C12, C22, Ct) of a coarser
    grid to start from (interpolated); ``forcing``: the wave's
    :class:`bvp.frequency.wave_loads.LineFlow` (None: no wave load); ``setup``: a
    :class:`RodSetup` of ``s`` already built (None: built here). The drag coefficients'
    fixed point is the planar one's (under-relaxed by :data:`RELAXATION`, until the
    largest change of a coefficient is below ``tol`` times the largest)."""
    omega = 2.0 * math.pi / period
    if setup is None:
        setup = prepare(scene, state, pieces, s)
    mid = setup.mid
    flow = (forcing.at_frame(mid, setup.y, setup.frame, state.plane)
            if forcing is not None else None)
    drive = plane_motion(state, motion)
    C = start_coefficients(setup, flow)
    if start is not None:
        C = {k: np.interp(mid, start[0], c) for k, c in zip(COEFFICIENTS, start[1:])}
    has_drag = setup.has_drag
    change, it = np.inf, 0
    for it in range(1, max_iter + 1):
        Y = respond(setup, omega, drive, C, flow)
        if not has_drag:
            change = 0.0
            break
        new = coefficients(setup, relative_velocity(setup, 0.5 * (Y[1:] + Y[:-1]), omega,
                                                    flow))
        top = max(float(np.max(np.abs(new[k]))) for k in COEFFICIENTS) or 1.0
        change = max(float(np.max(np.abs(new[k] - C[k]))) for k in COEFFICIENTS) / top
        C = {k: C[k] + RELAXATION * (new[k] - C[k]) for k in COEFFICIENTS}
        if change <= tol:
            break
    info = {"iterations": it, "last_change": change, "tolerance": tol,
            "grid_nodes": int(s.size), "drag_linearised": has_drag,
            "max_drag_coefficient": (float(max(np.max(largest(C)), np.max(C["Ct"])))
                                     if has_drag else 0.0),
            "static_state": "3d"}
    if change > tol:
        return HarmonicResponse("bvp", scene.name, Status.NOT_CONVERGED,
                                f"the drag linearisation did not settle in {it} iterations "
                                f"(last relative change of a coefficient {change:.3g}, "
                                f"tolerance {tol:g})", period, motion, info=info)
    info["coefficients"] = (mid,) + tuple(C[k] for k in COEFFICIENTS)
    return result(scene, state, pieces, period, motion, s, Y, info)


def result(scene: Scene, state, pieces: list[Piece], period: float, motion: np.ndarray,
           s: np.ndarray, Y: np.ndarray, info: dict) -> HarmonicResponse:
    """The :class:`HarmonicResponse` of the states Y (N + 1, 10) at the nodes s (module
    docstring: the outputs)."""
    EI = np.empty(s.size)
    T0, M10, M20 = np.empty(s.size), np.empty(s.size), np.empty(s.size)
    ends_at = np.array([pc.s1 for pc in pieces])
    which = np.clip(np.searchsorted(ends_at, s - 1e-12), 0, len(pieces) - 1)
    for i, pc in enumerate(pieces):
        sel = which == i
        EI[sel] = pc.EI
        T0[sel], M10[sel], M20[sel] = (pc.spl[k](s[sel]) for k in ("T", "M1", "M2"))
    dx, dz = state.plane.vector_from_plane(Y[:, IX], Y[:, IZ])
    amps = {"dx": dx, "dy": Y[:, IY], "dz": dz, "tension": Y[:, IT], "moment": Y[:, IM1],
            "moment_out": Y[:, IM2], "curvature": Y[:, IM1] / EI, "shear": Y[:, IF1]}
    ok = all(np.all(np.isfinite(v)) for v in amps.values())
    status = Status.CONVERGED if ok else Status.DIVERGED
    msg = (f"converged: harmonic response at {period:g} s about the 3D static state "
           f"({info['iterations']} drag iterations)" if ok else "the linear solve gave "
           "NaN/inf (a singular system: the period at an undamped natural period?)")
    return HarmonicResponse("bvp", scene.name, status, msg, period, motion, s, amps,
                            {"tension": T0, "moment": M10, "moment_out": M20}, info=info)

"""The linearised free vibration about a 3D static state of the rod (bvp/rod/equations.py):
in- and out-of-plane motion coupled, one family of ten states.

The model is :mod:`bvp.modal.modes`' (undamped; the weight, the static drag of the current
and a dead load held as dead loads, fixed in magnitude and direction at each material
point; the seabed a vertical spring k per unit length where the static line lies in it;
the mass m along the axis and m + m_a normal to it), about the rod's static state instead
of the planar beam's. SI units, in the frame of the ends' plane (riser.model.frame.
LinePlane: x along it from the anchor, y up, z across it); s [m] from the bottom end.

State (the rod's ten, perturbed, in its order):

    u = [dx, dy, dtheta, dM1, dF1, dT, dz, dphi, dM2, dF2]

The rod's equations are u' = f(u; q) with the load q per unstretched length a vector in
the plane's axes (bvp/rod/equations.py: the frame (t, n1, n2) turns with theta and phi,
and f holds q only as q.n1, q.n2 and -q.t in the rows of F1, F2 and T). Perturbed about the
static state u0 with q = q0 + dq,

    du' = (df/du) du + (df/dq) dq,   dq = -k_c dy e_y + omega^2 M0 dr,
    M0 = m t0 t0^T + (m + m_a) (I - t0 t0^T),   dr = (dx, dy, dz),

q0 the static load (weight, seabed reaction, drag, dead load) fixed in the plane's axes:
the turning of its projections with the frame is in df/du (a dead load, as the planar
family's ``d(q.n) = -(q.t) dtheta``). df/du is taken by the complex step (exact to
rounding: f is analytic in the angles, moments and forces; x, y, z enter only through the
load), df/dq is the frame's rows (n1, n2, -t). At phi = M2 = F2 = 0 this is the planar
in-plane family and the out-of-plane one of :mod:`bvp.modal.equations` term for term (their
states: w = dz, psi = dphi, B = dM2 and Q = T dphi - dF2), which the tests check.

Ends: pinned in space and moment-free (dx = dy = dz = 0, dM1 = dM2 = 0: the static moment
is zero at the rod's pinned ends, so the moment vector's perturbation is dM1 n2 - dM2 n1);
an end in ``[vfife] clamped_ends`` keeps its direction (dtheta = dphi = 0 instead). The
3D rod's ends are plain (a scene refuses joints and tensioners out of plane), so these are
all the forms.

Mode shapes are mapped back to the scene's axes (the plane's :meth:`vector_from_plane`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.interpolate import CubicSpline

from riser.model.scene import Scene
from riser.model.sections import segment_properties
from riser.results.modes import COUPLED

from .equations import Family, Piece, _contact_breaks

#: the ten states (the rod's order, bvp/rod/equations.py)
NAMES = ("dx", "dy", "dtheta", "dM1", "dF1", "dT", "dz", "dphi", "dM2", "dF2")
IX, IY, ITH, IM1, IF1, IT, IZ, IPH, IM2, IF2 = range(10)
#: the displacement states, as (x, y, z) in the plane's axes
DISP = (IX, IY, IZ)
#: the complex step [the state's own unit]: f is analytic, so the derivative is exact to
#: rounding for any small step (no subtraction)
COMPLEX_STEP = 1.0e-30
#: the static-state columns splined along every piece (bvp/rod/output.RodState)
SPLINED = ("th", "ph", "M1", "M2", "F1", "F2", "T", "y", "qx", "qy", "qz")


def rod_rhs(th, ph, M1, M2, F1, F2, T, q, EI: float, inv_EA: float) -> np.ndarray:
    """(10, m) the rod's derivatives (bvp/rod/equations.py) at the states given (each (m,),
    real or complex) under the load ``q`` (3, m) [N/m] in the plane's axes: the function
    whose Jacobian :class:`RodFamily` takes (written here from the equations, not the
    static solver's scaled code)."""
    c, sn, cp, sp = np.cos(th), np.sin(th), np.cos(ph), np.sin(ph)
    tp = sp / cp
    e1 = 1.0 + T * inv_EA
    t = (cp * c, cp * sn, sp)
    n1 = (-sn, c, 0.0 * c)
    n2 = (-sp * c, -sp * sn, cp)

    def dot(a, b):
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]

    out = np.empty((10,) + np.shape(th), dtype=np.result_type(th, ph, M1, T, q))
    out[IX] = e1 * cp * c
    out[IY] = e1 * cp * sn
    out[IZ] = e1 * sp
    out[ITH] = M1 / (EI * cp)
    out[IPH] = M2 / EI
    out[IM1] = e1 * F1 + M1 * M2 * tp / EI
    out[IM2] = e1 * F2 - M1 * M1 * tp / EI
    out[IF1] = T * M1 / EI + F2 * M1 * tp / EI + dot(q, n1)
    out[IF2] = T * M2 / EI - F1 * M1 * tp / EI + dot(q, n2)
    out[IT] = -F1 * M1 / EI - F2 * M2 / EI - dot(q, t)
    return out


def static_load(pc: Piece, st: dict) -> np.ndarray:
    """(3, m) [N/m]: the static load at the stations ``st`` of ``pc``: the weight, the
    seabed's reaction (its linear branch in a contact piece, as the static solve) and the
    drag (and dead load) the static state carries."""
    return np.stack([st["qx"], st["qy"] + pc.reaction(st["y"]) - pc.w, st["qz"]])


@dataclass(frozen=True)
class RodFamily(Family):
    """The coupled family of a 3D static state (see the module docstring)."""

    def matrices(self, pc: Piece, s: np.ndarray):
        """(A, B), each (10, 10, m): u' = (A + omega^2 B) u at arc lengths s."""
        st = {k: f(s) for k, f in pc.spl.items()}
        q = static_load(pc, st)
        args = [st[k] for k in ("th", "ph", "M1", "M2", "F1", "F2", "T")]
        cols = (ITH, IPH, IM1, IM2, IF1, IF2, IT)
        A = np.zeros((10, 10, s.size))
        for j, col in enumerate(cols):
            z = [a.astype(complex) for a in args]
            z[j] = z[j] + 1j * COMPLEX_STEP
            A[:, col] = rod_rhs(*z, q, pc.EI, pc.inv_EA).imag / COMPLEX_STEP
        t, n1, n2 = _frame(st["th"], st["ph"])
        dfdq = np.zeros((10, 3, s.size))          # the rows of F1, F2, T: n1, n2, -t
        dfdq[IF1], dfdq[IF2], dfdq[IT] = n1, n2, -t
        if pc.contact:                            # the seabed spring: dq_y = -k dy
            A[:, IY] += -pc.k * dfdq[:, 1]
        M0 = _mass_matrix(pc, t)
        B = np.zeros_like(A)
        B[:, list(DISP)] = np.einsum("iam,abm->ibm", dfdq, M0)
        return A, B

    def mass(self, pc: Piece, s: np.ndarray) -> np.ndarray:
        """(10, 10, m): u^T W u = dr^T M0 dr, the kinetic-energy density / omega^2."""
        t, _, _ = _frame(pc.spl["th"](s), pc.spl["ph"](s))
        W = np.zeros((10, 10, s.size))
        W[np.ix_(DISP, DISP)] = _mass_matrix(pc, t)
        return W


def _frame(th, ph):
    c, sn, cp, sp = np.cos(th), np.sin(th), np.cos(ph), np.sin(ph)
    return (np.stack([cp * c, cp * sn, sp]), np.stack([-sn, c, np.zeros_like(th)]),
            np.stack([-sp * c, -sp * sn, cp]))


def _mass_matrix(pc: Piece, t: np.ndarray) -> np.ndarray:
    """(3, 3, m): m t t^T + (m + m_a)(I - t t^T) at unit tangents t (3, m)."""
    tt = np.einsum("am,bm->abm", t, t)
    eye = np.eye(3)[:, :, None]
    return pc.m * tt + (pc.m + pc.ma) * (eye - tt)


ROD_FAMILY = RodFamily(COUPLED, NAMES, (0, 1, None, None, None, None, 2, None, None, None),
                       (IX, IY, IZ, IM1, IM2), (IX, IY, IZ, ITH, IPH))


def rod_pieces(scene: Scene, profile, state) -> list[Piece]:
    """The pieces of the rod's static ``state`` (bvp/rod/output.RodState) of ``scene``:
    its segments, split where the line enters or leaves the seabed (``profile``'s
    lift-off point and crossings of y = 0, as the planar pieces), each with cubic splines
    of :data:`SPLINED` in ``spl``."""
    props = segment_properties(scene)
    c = state.columns
    k = scene.seabed.stiffness if scene.seabed_model == "elastic" else 0.0
    breaks = _contact_breaks(profile) if k > 0.0 else []
    extensible = scene.axial_model == "extensible"
    pieces = []
    for i, p in enumerate(props):
        idx = np.flatnonzero(c["seg"] == i)
        keep = np.concatenate([[True], np.diff(c["s"][idx]) > 1e-4])
        idx = idx[keep]
        s = c["s"][idx]
        spl = {key: CubicSpline(s, c[key][idx]) for key in SPLINED}
        inv_EA = 1.0 / p.EA if extensible and p.EA else 0.0
        cuts = [p.s_start] + [b for b in breaks if p.s_start + 1e-3 < b < p.s_end - 1e-3]
        cuts.append(p.s_end)
        for a, b in zip(cuts[:-1], cuts[1:]):
            mid = 0.5 * (a + b)
            in_zone = (profile.tdp_s is not None and b <= profile.tdp_s + 1e-6
                       and profile.y[0] <= 1e-9)
            contact = k > 0.0 and (in_zone or float(spl["y"](mid)) < 0.0)
            pieces.append(Piece(a, b, p.EI, inv_EA, p.mass, p.added_mass, p.weight, k,
                                contact, spl))
    return pieces


def rod_ends(scene: Scene) -> tuple:
    """(bottom rows, top rows) of the coupled family: pinned and moment-free, or clamped
    (``[vfife] clamped_ends``); see the module docstring."""
    clamped = tuple(scene.vfife.clamped_ends)
    out = []
    for name in ("bottom", "top"):
        held = ROD_FAMILY.clamped if name in clamped else ROD_FAMILY.pinned
        out.append(tuple(((int(i), 1.0),) for i in held))
    return tuple(out)


def to_scene_axes(shape: np.ndarray, state) -> np.ndarray:
    """A mode's displacement (k, 3) in the plane's axes, in the scene's."""
    vx, vz = state.plane.vector_from_plane(shape[:, 0], shape[:, 2])
    return np.stack([vx, shape[:, 1], vz], axis=1)

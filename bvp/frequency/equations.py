"""The damped, forced linearisation about the BVP static state: the complex coefficient
matrices of the harmonic response and the equivalent linearisation of the drag.

The undamped operator y' = (A + omega^2 B) y is :mod:`bvp.modal.equations`' (its
derivation in :mod:`bvp.modal.modes`). A harmonic motion e^{i omega t} adds (SI units; c =
cos theta, sn = sin theta of the static tangent; V(y) the in-plane current speed along +x
[m/s], V' = dV/dy; u_t = c dx + sn dy, u_n = -sn dx + c dy):

- structural damping, mass-proportional as the VFIFE's ``[dynamics] damping`` c_s [1/s]
  (the force -c_s times the inertia of the velocity): omega^2 B -> (omega^2 - i omega c_s) B;
- the line types' internal axial damping (Kelvin-Voigt, MoorDyn's BA [N s], the axial
  force EA eps + BA d(eps)/dt, as both time domains apply it): the strain's increment is
  dT / (EA + i omega BA), the complex axial stiffness, so the rows of dx', dy' and dM'
  that take dT / EA take it times EA / (EA + i omega BA) = 1 / (1 + i omega BA / EA);
- the seabed's contact damping (a dashpot 2 zeta sqrt(k (m + m_a)) [N s/m2] beside the
  spring k where the static line lies in the seabed, zeta at most 1 as the VFIFE applies
  it): k -> k + i omega c_sb;
- Morison drag on the relative velocity (current minus line velocity), normal part
  f_n = c_n |V_perp| V_perp and tangential f_t = c_t |V_t| V_t (c_n = 0.5 rho D C_Dn,
  c_t = 0.5 rho pi D C_Dt, per unstretched length, as in :mod:`bvp.beam.equations`). Its
  increment about the static flow (V_n0 = -V sn, V_t0 = V c, V_z0 = 0) is linear in the
  increments of the relative velocity

      dV_n = -V' sn dy - V c dtheta - i omega u_n      (the normal flow turns with the line)
      dV_t =  V' c dy - V sn dtheta - i omega u_t
      dV_z = -V c psi - i omega w                      (out of plane: the tilted tangent)

  with the equivalent coefficients C_n, C_t, C_z of :func:`equivalent_coefficients`:
  df_n = C_n dV_n, df_t = C_t dV_t, df_z = C_z dV_z. In the rotating-frame equations the
  increment of the load's normal component is d(q.n) = df_n and of its tangential one
  d(q.t) = df_t (the frame's turning cancels between the load vector's rotation and the
  frame's), so dF' += df_n, dT' -= df_t; out of plane the z force balance gains
  -df_z - f_t0 psi (the tangential drag f_t0 along the tilted tangent).

Waves (:mod:`bvp.frequency.wave_loads`): the fluid velocity of a wave component (complex amplitudes
u_wn, u_wz, u_wt on the static line) adds to the relative velocity, dV_n += u_wn, dV_z +=
u_wz, dV_t += u_wt, and its acceleration loads the line through the fluid inertia:
normal (a_wn, a_wz) with (1 + C_a) rho pi D^2 / 4 = M [kg/m] (Froude-Krylov and added
mass), tangential (a_wt) with rho pi D^2 / 4 = M_t (the axial Froude-Krylov force alone,
as the VFIFE applies it: see docs/theory.md, Waves). The load increment is then df_n =
C_n dV_n + M a_wn, df_z = C_z dV_z + M a_wz, df_t = C_t dV_t + M_t a_wt: the part of the
line's own motion stays in the operator K, the wave's part is the inhomogeneous term g of
y' = K y + g (:func:`wave_forcing`): g_F = C_n u_wn + M a_wn, g_T = -(C_t u_wt + M_t
a_wt), g_Q = -(C_z u_wz + M a_wz).

Equivalent linearisation ("equal work per cycle" per direction): for the relative
velocity v(phi) = v_0 + Re(a e^{i phi}) (a the complex amplitude of dV), the coefficient
of direction j is C_j = c <f_j(v) ~v_j> / <~v_j^2>, averaged over a cycle of phi: the
linear damper C_j ~v_j does the same work over a cycle as the drag does on the
oscillating velocity. Small amplitude about a current: C_n = 2 c_n |V_n0|, C_z = c_n
|V_n0|, C_t = 2 c_t |V_t0| (the derivative); still water: C = c (8 / (3 pi)) |a| (the
classical Lorentz-Borgman value). Never a finite difference of |v| v at v = 0.
"""

from __future__ import annotations

import math

import numpy as np

from riser.model.sections import segment_properties

from ..modal.equations import state_scales

#: phases of the cycle average (trapezoidal on a periodic integrand; the averaged
#: products are |cos|^3-like, smooth enough that 128 phases agree with 4096 to ~1e-6 and
#: the dissipation with the nonlinear drag's to 2e-9, tests/test_harmonic_closed_forms.py)
PHASES = 128
#: a velocity amplitude below this [m/s] is replaced by it (the small-amplitude limit)
TINY_SPEED = 1e-9


def equivalent_coefficients(v_n0: np.ndarray, v_t0: np.ndarray, a_n: np.ndarray,
                            a_z: np.ndarray, a_t: np.ndarray, c_n: np.ndarray,
                            c_t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(C_n, C_z, C_t) [N s/m2] at m points: the static relative normal and tangential
    speeds v_n0, v_t0 [m/s] (real), the complex amplitudes a_n, a_z, a_t [m/s] of the
    oscillating relative velocity, the drag coefficients c_n, c_t [kg/m2] (see the module
    docstring)."""
    phi = 2.0 * np.pi * np.arange(PHASES) / PHASES
    e = np.exp(1j * phi)[None, :]

    def osc(a):
        a = np.where(np.abs(a) < TINY_SPEED, TINY_SPEED, a)
        return (a[:, None] * e).real

    wn, wz, wt = osc(a_n), osc(a_z), osc(a_t)
    vn = v_n0[:, None] + wn
    speed = np.sqrt(vn * vn + wz * wz)
    Cn = c_n * np.mean(speed * vn * wn, axis=1) / np.mean(wn * wn, axis=1)
    Cz = c_n * np.mean(speed * wz * wz, axis=1) / np.mean(wz * wz, axis=1)
    vt = v_t0[:, None] + wt
    Ct = c_t * np.mean(np.abs(vt) * vt * wt, axis=1) / np.mean(wt * wt, axis=1)
    return Cn, Cz, Ct


def in_plane(A: np.ndarray, B: np.ndarray, omega: float, c_s: float, f: dict) -> np.ndarray:
    """Complex (m, 6, 6) operator of the in-plane state [dx, dy, dtheta, dM, dF, dT] from
    the undamped (A, B) (each (m, 6, 6)) and the flow fields ``f`` at the m points
    (theta, V, Vp, Cn, Ct, csb: the seabed dashpot, 0 off contact; ba_ea: the internal
    axial damping's BA / EA [s], absent or 0 without)."""
    dx, dy, dth, dM, dF, dT = 0, 1, 2, 3, 4, 5
    K = A + (omega ** 2 - 1j * omega * c_s) * B
    K = K.astype(complex)
    c, sn = np.cos(f["theta"]), np.sin(f["theta"])
    V, Vp, Cn, Ct = f["V"], f["Vp"], f["Cn"], f["Ct"]
    iw = 1j * omega
    K[:, dF, dx] += Cn * iw * sn
    K[:, dF, dy] += Cn * (-Vp * sn - iw * c) - iw * f["csb"] * c
    K[:, dF, dth] += -Cn * V * c
    K[:, dT, dx] += Ct * iw * c
    K[:, dT, dy] += Ct * (-Vp * c + iw * sn) + iw * f["csb"] * sn
    K[:, dT, dth] += Ct * V * sn
    ba_ea = f.get("ba_ea")
    if ba_ea is not None and np.any(ba_ea):    # the complex axial stiffness EA + i omega BA
        soft = 1.0 / (1.0 + iw * ba_ea)
        for row in (dx, dy, dM):                # dx', dy', dM' take dT / EA
            K[:, row, dT] *= soft
    return K


def out_of_plane(A: np.ndarray, B: np.ndarray, omega: float, c_s: float,
                 f: dict) -> np.ndarray:
    """Complex (m, 4, 4) operator of the out-of-plane state [w, psi, B, Q] (see
    :func:`in_plane`; f also holds ``Cz`` and the static tangential drag ``ft0`` [N/m])."""
    w, psi, q = 0, 1, 3
    K = (A + (omega ** 2 - 1j * omega * c_s) * B).astype(complex)
    Vt0 = f["V"] * np.cos(f["theta"])
    K[:, q, psi] += f["Cz"] * Vt0 - f["ft0"]
    K[:, q, w] += 1j * omega * f["Cz"]
    return K


def wave_forcing(plane: str, flow: dict, f: dict) -> np.ndarray:
    """The wave's inhomogeneous term g (m, n) complex of y' = K y + g (SI units of the
    states' derivatives: [N/m] in the force rows) for ``plane`` ('in_plane' or
    'out_of_plane'), from the wave's flow on the line (:meth:`bvp.frequency.wave_loads.LineFlow.at`:
    un, ut, uz [m/s], an, at, az [m/s2], inertia, inertia_t [kg/m]) and the drag
    coefficients Cn, Cz, Ct of ``f`` (see the module docstring): drag and the normal
    inertia (1 + C_a) rho A a_n in the normal rows, drag and the axial Froude-Krylov force
    rho A a_t in the tension row."""
    m = flow["un"].size
    if plane == "in_plane":
        g = np.zeros((m, 6), complex)
        g[:, 4] = f["Cn"] * flow["un"] + flow["inertia"] * flow["an"]      # dF'
        g[:, 5] = -(f["Ct"] * flow["ut"] + flow["inertia_t"] * flow["at"])  # dT'
    else:
        g = np.zeros((m, 4), complex)
        g[:, 3] = -(f["Cz"] * flow["uz"] + flow["inertia"] * flow["az"])   # Q'
    return g


def relative_velocity(Y: np.ndarray, Z: np.ndarray, omega: float, f: dict,
                      flow: dict | None = None):
    """Complex amplitudes (a_n, a_z, a_t) [m/s] of the oscillating relative velocity at
    the m points from the in-plane states Y (m, 6) and out-of-plane states Z (m, 4),
    plus the wave's flow (un, uz, ut [m/s] of :func:`wave_forcing`) when given."""
    c, sn = np.cos(f["theta"]), np.sin(f["theta"])
    V, Vp = f["V"], f["Vp"]
    dx, dy, dth = Y[:, 0], Y[:, 1], Y[:, 2]
    iw = 1j * omega
    a_n = -Vp * sn * dy - V * c * dth - iw * (-sn * dx + c * dy)
    a_t = Vp * c * dy - V * sn * dth - iw * (c * dx + sn * dy)
    a_z = -V * c * Z[:, 1] - iw * Z[:, 0]
    if flow is not None:
        a_n, a_z, a_t = a_n + flow["un"], a_z + flow["uz"], a_t + flow["ut"]
    return a_n, a_z, a_t


def contact_dashpot(scene, piece) -> float:
    """The seabed's contact damping c_sb = 2 zeta sqrt(k (m + m_a)) [N s/m2] of ``piece``
    (a :class:`bvp.modal.equations.Piece`: its k, m, m_a) where the static line lies in
    the seabed, 0 elsewhere; zeta the scene's contact damping ratio as the VFIFE applies
    it: at most critical (more only slows the contact down;
    riser.physics.environment.Seabed.damping)."""
    sb = scene.seabed
    zeta = min(sb.damping, 1.0) if sb is not None else 0.0
    if piece.contact and zeta > 0.0:
        return 2.0 * zeta * math.sqrt(piece.k * (piece.m + piece.ma))
    return 0.0


def damping_times(scene, pieces, s: np.ndarray, which: np.ndarray) -> np.ndarray:
    """BA / EA [s] at the points s (on ``pieces[which]``): the line types' internal axial
    damping over their axial stiffness (0 where the line is inextensible), the time
    constant of the complex axial stiffness EA + i omega BA (:func:`in_plane`)."""
    props = segment_properties(scene)
    ends = np.array([p.s_end for p in props])
    seg = np.clip(np.searchsorted(ends, s), 0, len(props) - 1)
    ba = np.array([p.BA for p in props])[seg]
    inv_ea = np.array([pc.inv_EA for pc in pieces])[which]
    return ba * inv_ea


def response_scales(pieces, fam, omega: float, L: float) -> np.ndarray:
    """The state scales of a harmonic response at ``omega`` [rad/s] on ``pieces`` of the
    family ``fam`` over the grid's length ``L`` [m] (:func:`bvp.modal.equations.
    state_scales` over the wavelength of a taut string at the largest top tension and the
    largest mass: as many half-waves as fit in the line, at least one)."""
    wave = 2.0 * math.pi * math.sqrt(max(float(np.max(np.abs(pc.spl["T"](pc.s1))))
                                         for pc in pieces) / max(pc.m + pc.ma
                                                                 for pc in pieces)) / omega
    return state_scales(pieces, fam, max(1, int(2.0 * L / wave)))

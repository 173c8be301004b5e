"""Critical time steps of the explicit central-difference scheme.

For the lumped-mass chain the highest frequencies are bounded per node (Gershgorin on
M^-1/2 K M^-1/2, exact for a uniform chain):

- axial: omega^2 = 2 (EA_l/l_l + EA_r/l_r) / m_i  -> uniform: dt = l sqrt(m'/EA) = l / c;
- rotation: omega^2 = (6 EI_l/l_l + 6 EI_r/l_r) / J_i -> uniform with physical diametral
  inertia J = rho I l: dt = l / (sqrt(3) c);
- bending (transverse zig-zag) plus string stiffness:
  omega^2 = 48 EI / (m' l^4) + 4 T / (m' l^2)  -> dt ~ l^2 sqrt(m' / (12 EI));
- seabed contact: the spring k_s [N/m2] acts in the same (transverse) direction as the
  bending zig-zag, so it adds to it (exact for a straight line on the seabed):
  omega^2 = 48 EI / (m' l^4) + 4 T / (m' l^2) + k_s / m'; the contact damping c_s is an
  explicit (lagged-velocity) force, which lowers the limit of central differences to
  dt < 2 (sqrt(1 + zeta^2) - zeta) / omega with zeta = c_s / (2 m omega)
  (von Neumann analysis of v+ = v + dt (-k x - c v) / m, x+ = x + dt v+);
- axial dashpot (eta [N s/m] per element on the elongation rate, explicit on the lagged
  velocity: the statics' relaxation damping, and the dynamics' internal axial damping
  eta = BA / l0 of the line types' ``axial_damping``, Kelvin-Voigt): the axial zig-zag
  mode gets the nodal damping 2 (eta_l + eta_r) [N s/m], i.e. zeta = (eta_l + eta_r) /
  (m_i omega_axial), and the axial limit becomes 2 (sqrt(1 + zeta^2) - zeta) /
  omega_axial (same von Neumann analysis as the contact);
- Morison drag (explicit, linearised): dt < 2 m_i / (c_dn |u|) with |u| the largest
  expected relative speed.

The step is ``safety * min(...)``; every candidate is reported.
"""

from __future__ import annotations

import numpy as np

from .mesh import Mesh


def node_sum(per_element) -> np.ndarray:
    """Per-node sum of a per-element quantity over the (one or two) elements meeting at
    each node: the Gershgorin row sum of an element stiffness or damping."""
    e = np.asarray(per_element, float)
    out = np.zeros(e.shape[0] + 1)
    out[:-1] += e
    out[1:] += e
    return out


def nodal_stiffness(mesh: Mesh, tension=0.0) -> dict:
    """Gershgorin row sums per node: 'axial' (EA/l from each adjacent element) [N/m],
    'rotation' (6 EI/l, plus a flex joint's stiffness at an end) [N m/rad] and 'transverse' (bending zig-zag 24 EI/l^3 plus string
    2 |T|/l) [N/m]; ``tension`` [N] scalar or (ne,)."""
    T = np.broadcast_to(np.abs(np.asarray(tension, float)), mesh.l0.shape)
    rotation = node_sum(6.0 * mesh.EI / mesh.l0)
    rotation[0] += mesh.end_springs[0]             # flex joints at the ends
    rotation[-1] += mesh.end_springs[1]
    return {"axial": node_sum(mesh.EA / mesh.l0),
            "rotation": rotation,
            "transverse": node_sum(24.0 * mesh.EI / mesh.l0 ** 3 + 2.0 * T / mesh.l0)}


def damped_factor(zeta):
    """Factor on 2/omega of the central-difference limit with an explicit viscous force
    of damping ratio zeta: sqrt(1 + zeta^2) - zeta (1 at zeta = 0)."""
    zeta = np.asarray(zeta, float)
    return np.sqrt(1.0 + zeta * zeta) - zeta


def critical_steps(mesh: Mesh, *, rot_scale: float, tension: float = 0.0,
                   added_mass: bool = False, seabed_stiffness: float = 0.0,
                   seabed_damping=0.0, drag_speed: float = 0.0,
                   axial_damping=0.0, mass_factor: float = 1.0) -> dict:
    """Critical time steps [s] of ``mesh`` (dict: axial, rotation, bending, seabed, drag).

    seabed_damping : nodal contact damping [N s/m] ((n,) or scalar), as used by the
    kernels (see :attr:`vfife.model.Model.cseabed`); 'seabed' is the transverse limit
    with the contact spring and this damping on this mesh.
    axial_damping : axial dashpot coefficients eta [N s/m] per element ((ne,) or scalar:
    the statics' dashpot, the dynamics' BA / l0); 'axial' then includes its explicit
    damping, so a large BA shortens the step instead of blowing the run up.
    mass_factor : factor on the pipe + contents mass (a slug lightens the nodes it passes,
    see :func:`vfife.flow.lightest_mass_factor`).
    """
    m_pl = mass_factor * mesh.mass_pl + (mesh.added_pl if added_mass else 0.0)
    m = mesh.lump(mass_factor * mesh.mass_pl)   # axial direction: no added mass
    mt = mesh.lump(m_pl)                   # transverse
    J = rot_scale * mesh.lump(mesh.rot_pl)
    k = nodal_stiffness(mesh, tension)
    sa, sr, st = k["axial"], k["rotation"], k["transverse"]
    eta = np.broadcast_to(np.asarray(axial_damping, float), mesh.l0.shape)
    se = node_sum(eta)
    om_a = np.sqrt(2.0 * sa / m)
    zeta_a = se / (m * om_a)
    out = {
        "axial": float(np.min(2.0 * damped_factor(zeta_a) / om_a)),
        "rotation": float(np.min(2.0 / np.sqrt(sr / J))),
        "bending": float(np.min(2.0 / np.sqrt(st / mt))),
    }
    if seabed_stiffness > 0.0:
        om = np.sqrt((st + seabed_stiffness * mesh.trib) / mt)
        zeta = np.broadcast_to(np.asarray(seabed_damping, float), om.shape) / (2.0 * mt * om)
        out["seabed"] = float(np.min(2.0 * damped_factor(zeta) / om))
    if drag_speed > 0.0:
        cd = mesh.lump(mesh.cdn_pl + mesh.cdt_pl)
        out["drag"] = float(np.min(2.0 * mt / np.maximum(cd * drag_speed, 1e-300)))
    return out


def choose_step(steps: dict, safety: float) -> tuple[float, str]:
    """(time step [s], name of the limiting criterion)."""
    name = min(steps, key=steps.get)
    return safety * steps[name], name

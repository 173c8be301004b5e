"""The ANCF's end conditions of a fixed-ends scene ([ends], riser/model/ends.py), as
constraints on the generalised coordinates and energies of the ends.

Node 0 is the anchor end, node n - 1 the hang-off; a node's unknowns are its position r
(d components) and slope r' (d). A pinned end fixes r; a free anchor fixes nothing; a
tensioner fixes the hang-off's horizontal position and adds the potential of its pull,
-F_0 y + k/2 (y - y_ref)^2 (so the vertical force F_0 - k (y - y_ref) on the top); a
clamped joint fixes r and the slope's direction: the slope's components across the
joint's direction t_0 (in the line's plane: d - 1 of them) are zero, applied in the
node's rotated slope basis (t_0, n_0[, e_z]); a flex joint adds the energy
k/2 (phi - phi_0)^2 with phi = atan2(r'_y, r'_x) the tangent's angle in the line's plane
(joints and tensioners need a planar scene, riser/model/end_checks.py), which gives the
end moment -k (phi - phi_0) at the hang-off and +k (phi - phi_0) at the anchor
(EndJoint's sign).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from riser.errors import UnsupportedSceneError
from riser.model.ends import FixedEnds
from riser.model.scene import Scene

from . import banded


@dataclass
class EndConditions:
    """Constraints of one mesh: ``fixed`` the global indices of prescribed unknowns (in
    the rotated basis at a clamped node), ``rotations`` {node: R (d, d)} the slope bases
    of clamped nodes (columns t_0, n_0[, e_z]), ``springs`` [(node, k [N m/rad], phi_0
    [rad])], ``tensioner`` (node, F_0 [N], k [N/m], y_ref [m]) or None, ``top`` the hang-off
    node's prescribed position components (indices into its r)."""

    d: int
    n: int
    fixed: list = field(default_factory=list)
    rotations: dict = field(default_factory=dict)
    springs: list = field(default_factory=list)
    tensioner: tuple | None = None
    top: tuple = ()

    def dof(self, node: int, k: int) -> int:
        return node * 2 * self.d + k


def require_ancf_ends(scene: Scene) -> None:
    """Raise :class:`UnsupportedSceneError` for ends this method does not take: a Wang
    form (solved after the pipeline's conversion), a BVP-only limit, ``[vfife]
    clamped_ends`` (a clamp in the direction of the VFIFE's own start)."""
    if not isinstance(scene.ends, FixedEnds):
        raise UnsupportedSceneError(
            f"{scene.source}: ends: ancf needs fixed ends (anchor + hang_off) but the scene "
            f"gives the '{scene.ends.kind}' form; the command line converts it with the "
            "bvp method first (riser.model.transform.fixed_ends_scene)")
    if scene.model.get("axial") == "inextensible":
        raise UnsupportedSceneError(
            f"{scene.source}: model.axial: 'inextensible' is a limit only the bvp method "
            "solves; the ancf elements stretch (use 'extensible' or --method bvp)")
    if scene.model.get("seabed") == "rigid":
        raise UnsupportedSceneError(
            f"{scene.source}: model.seabed: 'rigid' is a limit only the bvp method solves; "
            "the ancf seabed is an elastic penalty of [seabed] stiffness")
    if scene.vfife.clamped_ends:
        raise UnsupportedSceneError(
            f"{scene.source}: vfife.clamped_ends: clamps an end in the direction of the "
            "VFIFE's own starting shape; for the ancf give the end a joint ([ends."
            "anchor_joint] or [ends.hang_off_joint], kind = 'clamped', direction_deg)")


def end_conditions(scene: Scene, n: int, d: int) -> EndConditions:
    """The constraints of ``scene``'s ends on a mesh of ``n`` nodes in dimension ``d``."""
    e = scene.ends
    out = EndConditions(d, n)
    last = n - 1
    if not e.free_anchor:
        out.fixed += [out.dof(0, k) for k in range(d)]
    if e.tensioner is not None:
        t = e.tensioner
        out.fixed += [out.dof(last, k) for k in range(d) if k != 1]
        out.tensioner = (last, t.top_tension, t.stiffness, float(e.hang_off[1]))
        out.top = tuple(k for k in range(d) if k != 1)
    else:
        out.fixed += [out.dof(last, k) for k in range(d)]
        out.top = tuple(range(d))
    for node, end in ((0, "anchor"), (last, "hang_off")):
        joint = e.joint(end)
        if joint is None or joint.kind == "free":
            continue
        if joint.kind == "clamped":
            c, s = math.cos(joint.direction), math.sin(joint.direction)
            R = np.eye(d)
            R[:2, :2] = [[c, -s], [s, c]]
            out.rotations[node] = R
            out.fixed += [out.dof(node, d + k) for k in range(1, d)]
        elif joint.kind == "spring":
            out.springs.append((node, joint.rotational_stiffness, joint.direction))
    out.fixed = sorted(set(out.fixed))
    return out


def end_energy(ends: EndConditions, q: np.ndarray, F: np.ndarray, K: np.ndarray | None,
               kl: int, y_ref_shift: float = 0.0) -> float:
    """Add the flex joints' and the tensioner's forces to ``F`` (the energy's gradient)
    and tangents to the band matrix ``K``; returns their energy [J]. ``y_ref_shift`` [m]
    moves the tensioner's reference height (the vessel's heave in dynamics)."""
    d = ends.d
    energy = 0.0
    for node, k, phi0 in ends.springs:
        i = ends.dof(node, d)
        ax, ay = q[i], q[i + 1]
        g = ax * ax + ay * ay
        phi = math.atan2(ay, ax)
        dphi = math.remainder(phi - phi0, 2.0 * math.pi)
        energy += 0.5 * k * dphi * dphi
        grad = np.array([-ay, ax]) / g                # d phi / d(a_x, a_y)
        F[i:i + 2] += k * dphi * grad
        if K is not None:
            # d2 phi / da2
            H = np.array([[2 * ax * ay, ay * ay - ax * ax],
                          [ay * ay - ax * ax, -2 * ax * ay]]) / (g * g)
            banded.add_diagonal_block(K, kl, i, k * (np.outer(grad, grad) + dphi * H))
    if ends.tensioner is not None:
        node, F0, kt, yref = ends.tensioner
        i = ends.dof(node, 1)
        dy = q[i] - (yref + y_ref_shift)
        energy += -F0 * q[i] + 0.5 * kt * dy * dy
        F[i] += -F0 + kt * dy
        if K is not None:
            K[2 * kl, i] += kt
    return energy


def rotate(ends: EndConditions, K: np.ndarray | None, R_vec: np.ndarray, kl: int) -> None:
    """Put the residual ``R_vec`` and the band matrix ``K`` in the rotated slope basis of the
    clamped nodes (K' = T^T K T, R' = T^T R; T the identity elsewhere)."""
    d = ends.d
    for node, Rm in ends.rotations.items():
        i = ends.dof(node, d)
        R_vec[i:i + d] = Rm.T @ R_vec[i:i + d]
        if K is None:
            continue
        N = K.shape[1]
        i0 = max(0, i - kl)
        i1 = min(N, i + d + kl)
        W = banded.window(K, kl, i0, i1)
        T = np.eye(i1 - i0)
        j = i - i0
        T[j:j + d, j:j + d] = Rm
        banded.set_window(K, kl, i0, T.T @ W @ T)


def unrotate(ends: EndConditions, dq: np.ndarray) -> None:
    """An increment solved in the rotated basis back to the global one."""
    d = ends.d
    for node, Rm in ends.rotations.items():
        i = ends.dof(node, d)
        dq[i:i + d] = Rm @ dq[i:i + d]

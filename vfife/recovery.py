"""Nodal values of the element resultants, second order at every node (output only).

A VFIFE element carries a constant axial force N and shear force Q (the transverse force
pair of its end moments), which approximate the tension and shear of the continuum at the
element's midpoint to second order in the element length h. What a node reports:

- **ordinary interior node** (the two elements have the same section and loads): the
  linear interpolation of the two elements' values between their midpoints, i.e. their
  mean for equal lengths. Second order wherever the field is smooth.
- **joint node**, where anything per length changes between its two elements (the
  submerged weight, EA, EI, the mass, the added mass, the diameter through the drag
  coefficients or the rotary inertia: a segment joint): the field has a kink there (T' =
  w sin(theta) - Q kappa jumps with w and with kappa = M / EI, Q' = w cos(theta) - T kappa
  likewise), and the mean of the two elements is off by |d(T')| h / 4 (|dw sin(theta)| h
  / 4 at a weight jump: 0.17-0.20 % of T_max on the Yu lazy waves, 1130 N/m of buoyancy,
  at 1 m; 1.1 % of Yu A4's 'lower maximum tension', now 0.02 %).
  Each side extrapolates its own two nearest elements linearly to the node (an O(h^2)
  estimate of the continuous value from that side) and the node takes the mean of the two
  estimates (both estimate the same continuous value). A side with a single element (a
  one-element segment between two joints) gives its element value (first order there).
- **end node**: the one-sided linear extrapolation of the two end elements.

The shear is recovered as a vector (component-wise, then its magnitude): the magnitude
has a V-shaped zero where the shear changes sign (at a moment peak) and averaging
magnitudes there reports the mean of the two sides instead of ~0.

The bending moment needs no recovery: an element's end moments are nodal values, and the
two elements meeting at a free node balance there (their difference is the node's
out-of-balance moment), so the node reports their mean (the end element's at an end); it
is continuous at a joint (M is C1 there, M' = Q): measured on Yu A4 against the BVP, its
largest error at the eight joints is 48, 11, 3.1 N m at 2, 1, 0.5 m elements (second order,
like the tension there now: 25, 8.0, 2.4 N). The curvature M / EI jumps with EI at a
joint: the node reports the larger of its two one-sided values, M / min(EI), so that a
curvature peak at a joint is not cut.

Not covered: a load that changes inside an element (the sea surface of a dynamic run,
smeared over the node's band by the wet fraction; the lift-off of a stiff seabed, where
the shear has a kink between nodes): the mean is O(h) within one element of it. The
tension is C1 at the lift-off (T' = w sin(theta) is continuous there). A point attachment
(a concentrated load) makes its node a joint: the tension and the shear jump there, and
the node reports the mean of the two sides' estimates, the mean of the two limits.

The recovery is a fixed sparse linear map from element values to nodes (:class:`Recovery`,
built once per mesh); the equations of motion use the element forces and never this.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from .mesh import Mesh

#: the per-element properties whose change between two elements makes their node a joint
JOINT_PROPERTIES = ("weight_pl", "EA", "EI", "mass_pl", "rot_pl", "added_pl", "cdn_pl",
                    "cdt_pl")


def joint_nodes(mesh: Mesh) -> np.ndarray:
    """(n,) bool: the interior nodes whose two elements differ in any property of
    :data:`JOINT_PROPERTIES` (relative difference above 1e-12), and the nodes of point
    attachments (the tension and shear jump there: each side's estimate, their mean)."""
    out = np.zeros(mesh.n, bool)
    for name in JOINT_PROPERTIES:
        v = np.asarray(getattr(mesh, name), float)
        scale = np.maximum(np.maximum(np.abs(v[1:]), np.abs(v[:-1])), 1e-300)
        out[1:-1] |= np.abs(v[1:] - v[:-1]) > 1e-12 * scale
    out[1:-1] |= mesh.point_nodes[1:-1]
    return out


class Recovery:
    """The linear map from element values (ne,) to nodal values (n,) of the module
    docstring: ``matrix`` (n, ne) sparse, ``joints`` (n,) bool."""

    def __init__(self, mesh: Mesh):
        s = np.asarray(mesh.s, float)
        ne = mesh.ne
        mid = 0.5 * (s[1:] + s[:-1])
        self.joints = joint_nodes(mesh)
        rows: list[int] = []
        cols: list[int] = []
        vals: list[float] = []

        def put(i: int, weights: dict) -> None:
            for e, w in weights.items():
                rows.append(i)
                cols.append(e)
                vals.append(w)

        def side(i: int, near: int, far: int) -> dict:
            """Linear extrapolation to node i from element ``near`` (adjacent to i) and
            ``far`` (the next one on the same side); its value alone without ``far``."""
            if far < 0 or far >= ne:
                return {near: 1.0}
            a = (s[i] - mid[near]) / (mid[near] - mid[far])
            return {near: 1.0 + a, far: -a}

        def combine(*sides: dict) -> dict:
            out: dict = {}
            for d in sides:
                for e, w in d.items():
                    out[e] = out.get(e, 0.0) + w / len(sides)
            return out

        if ne == 1:
            put(0, {0: 1.0})
            put(1, {0: 1.0})
        else:
            # a side's second element must lie in the same run of equal properties
            put(0, side(0, 0, 1 if not self.joints[1] else -1))
            put(mesh.n - 1, side(mesh.n - 1, ne - 1, ne - 2 if not self.joints[ne - 1] else -1))
            for i in range(1, mesh.n - 1):
                left, right = i - 1, i
                if self.joints[i]:
                    far_l = i - 2 if (i - 2 >= 0 and not self.joints[i - 1]) else -1
                    far_r = i + 1 if (i + 1 < ne and not self.joints[i + 1]) else -1
                    put(i, combine(side(i, left, far_l), side(i, right, far_r)))
                else:
                    t = (s[i] - mid[left]) / (mid[right] - mid[left])
                    put(i, {left: 1.0 - t, right: t})
        self.matrix = sp.csr_matrix((vals, (rows, cols)), shape=(mesh.n, ne))

    def scalar(self, values: np.ndarray) -> np.ndarray:
        """Nodal values (n,) of the element values (ne,)."""
        return self.matrix @ np.asarray(values, float)

    def vectors(self, values: np.ndarray) -> np.ndarray:
        """Nodal vectors (k, n) of the element vectors (k, ne), component by component."""
        return (self.matrix @ np.asarray(values, float).T).T

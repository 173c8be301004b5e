"""ANCF (absolute nodal coordinate formulation) riser solver: the method of Liu et al.
(2021), implemented here independently.

Gradient-deficient beam elements (each node carries its position r and slope r' = dr/ds,
cubic Hermite interpolation between nodes, :mod:`ancf.element`): the extensible elastica
with the axial strain eps = |r'| - 1 (effective tension T = EA eps) and the bending moment
M = EI kappa, kappa the tangent's rotation per unstretched length (the model of the
other methods, docs/theory.md "The ANCF"); the loads per unstretched length
integrated by Gauss quadrature: submerged weight, the Winkler seabed p = k max(-y, 0) with
its damping and friction, Morison drag on the velocity relative to the current
(:mod:`ancf.loads`). Statics by Newton-Raphson with a line search and load stepping from
the elastic catenary (:mod:`ancf.statics.newton`); global matrices banded, solved by LU
(:mod:`ancf.banded`). A planar scene is solved with two components per vector, a 3D one
with three.

Public API: ``solve(scene, *, element_length=None, tolerance=None, progress=None,
dead_load=None)`` -> :class:`riser.results.result.SolveResult`; the inextensible line and
the rigid seabed are BVP-only limits and refused, as are the Wang end forms (the pipeline
converts them to fixed ends first).
"""

from .solver import solve

__all__ = ["solve"]

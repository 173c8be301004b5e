"""VFIFE (vector form intrinsic finite element) riser solver, Numba kernels.

Point masses with rotational degrees of freedom joined by massless space beams; every
step removes the rigid-body motion of each element against its chord (fictitious
reverse motion) and computes the pure deformation (elongation, bending rotations of the
end directors relative to the chord) and the internal forces; explicit central
differences. Statics by dynamic relaxation with mesh sequencing, dynamics with a
prescribed hang-off motion. See :mod:`vfife.kernels` for the equations and
:func:`vfife.solve` for the entry point.

Continuum model (the same as the BVP's, docs/theory.md "One model, two methods"; implemented
here independently): s is the unstretched arc length; the axial force of an element is
N = EA (l - l0) / l0, i.e. strain eps = T / EA from the effective tension; bending
moments come from the end rotations per unstretched length, M = EI dtheta/ds; weight, drag
and the seabed reaction are lumped to the nodes over their unstretched tributary lengths,
so they are forces per unit unstretched length; the seabed is the unilateral,
frictionless (unless ``friction``) Winkler foundation p = k max(-y, 0) [N/m] at each node.
The inextensible line and the rigid seabed are BVP-only limits: :func:`solve` refuses a
scene asking for them (``[model]``).

Public API: ``solve(scene, *, element_length=None, tolerance=None, progress=None)``,
``riser.transform.fixed_ends_scene(scene, hang_off_xy, seabed_length)``.
"""

from .solver import solve

__all__ = ["solve"]

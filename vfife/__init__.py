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

3D: a scene with a current out of the x-y plane (one heading, or ``headings_deg``
turning with height), a hang-off out of the anchor's plane or a top motion along z is
stepped by the 3D kernels; its profile carries ``lateral`` and ``moment_out_of_plane``
(from the vertical plane through the ends, :mod:`riser.model.frame`). A planar scene runs the
planar kernels.

Public API: ``solve(scene, *, element_length=None, tolerance=None, progress=None,
dead_load=None)`` (``dead_load``: an optional uniform load (qx, qy, qz) [N/m] of fixed
direction added to the weight, for closed-form checks),
``riser.model.transform.fixed_ends_scene(scene, hang_off_xy, seabed_length)``.
"""

from .solver import solve

__all__ = ["solve"]

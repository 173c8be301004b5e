"""VFIFE (vector form intrinsic finite element) riser solver, Numba kernels.

Point masses with rotational degrees of freedom joined by massless space beams; every
step removes the rigid-body motion of each element against its chord (fictitious
reverse motion) and computes the pure deformation (elongation, bending rotations of the
end directors relative to the chord) and the internal forces; explicit central
differences. Statics by dynamic relaxation with mesh sequencing, dynamics with a
prescribed hang-off motion. See :mod:`vfife.kernels` for the equations and
:func:`vfife.solve` for the entry point.

Public API: ``solve(scene, *, element_length=None, tolerance=None, progress=None)``,
``riser.transform.fixed_ends_scene(scene, hang_off_xy, seabed_length)``.
"""

from .solver import solve

__all__ = ["solve"]

"""Boundary conditions the VFIFE solver accepts, and turning a touchdown-form scene into one."""

from __future__ import annotations

import dataclasses

from riser.errors import UnsupportedSceneError
from riser.scene import Ends, Scene, Seabed

#: Default seabed stiffness [N/m per m of line = N/m2] added by :func:`fixed_ends_scene`.
#: Under a steel riser of ~500 N/m submerged weight it penetrates ~0.5 mm (< 1 cm for any
#: line lighter than 10 kN/m), close to the rigid seabed of the boundary-value model,
#: while its contact frequency stays far below the axial one (no effect on the step).
DEFAULT_SEABED_STIFFNESS = 1.0e6


def require_fixed_ends(scene: Scene) -> None:
    """Raise :class:`UnsupportedSceneError` unless the scene has fixed ends."""
    if scene.ends.kind != "fixed":
        raise UnsupportedSceneError(
            f"{scene.source}: ends: vfife needs fixed ends (anchor + hang_off) but the scene "
            f"gives the '{scene.ends.kind}' form; solve it with the bvp method first and "
            f"convert it with vfife.fixed_ends_scene(scene, hang_off_xy, seabed_length) "
            f"(the CLI does this for you)")


def fixed_ends_scene(scene: Scene, hang_off_xy, seabed_length: float,
                     seabed_stiffness: float | None = None) -> Scene:
    """A fixed-ends copy of a touchdown-form scene ('tdp_tension' or 'hang_off_angle').

    The anchor is put on the seabed at (-seabed_length, 0), the first (bottom) segment is
    lengthened by ``seabed_length`` [m] so that the touchdown stays near x = 0, and the
    hang-off is fixed at ``hang_off_xy`` = (x, y) [m] (e.g. the BVP's top point). If the
    scene has no [seabed], one is added with ``seabed_stiffness`` [N/m2] (default
    :data:`DEFAULT_SEABED_STIFFNESS` = 1e6 N/m2: < 1 cm penetration under the pipe weight),
    no friction and 0.1 of critical contact damping (it only speeds up the static
    relaxation and damps contact chatter; no effect on the equilibrium).
    """
    if seabed_length < 0.0:
        raise ValueError(f"seabed_length must be >= 0, got {seabed_length}")
    hx, hy = float(hang_off_xy[0]), float(hang_off_xy[1])
    segs = list(scene.segments)
    segs[0] = dataclasses.replace(segs[0], length=segs[0].length + float(seabed_length))
    seabed = scene.seabed
    if seabed is None:
        k = DEFAULT_SEABED_STIFFNESS if seabed_stiffness is None else float(seabed_stiffness)
        seabed = Seabed(stiffness=k, friction=0.0, damping=0.1)
    elif seabed_stiffness is not None:
        seabed = dataclasses.replace(seabed, stiffness=float(seabed_stiffness))
    ends = Ends("fixed", anchor=(-float(seabed_length), 0.0), hang_off=(hx, hy))
    return scene.replace(segments=tuple(segs), ends=ends, seabed=seabed)

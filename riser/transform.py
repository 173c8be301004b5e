"""Scene transformations shared by the solvers' callers (inputs only, no solver physics)."""

from __future__ import annotations

import dataclasses

from .scene import Ends, Scene, Seabed

#: Floor of the penalty stiffness [N/m2] given to a scene without a seabed: the Wang pipe
#: (526 N/m) then sinks 5 mm.
MIN_SEABED_STIFFNESS = 1.0e5


def rigid_seabed_stiffness(EI: float, element_length: float) -> float:
    """Penalty stiffness [N/m2] as rigid as a mesh of ``element_length`` [m] can resolve.

    A beam of bending stiffness EI [N m2] on an elastic foundation of stiffness k bends
    over the length (4 EI / k)^(1/4); setting it equal to the element length gives
    k = 4 EI / l^4 (3.9e7 N/m2 for the Wang pipe at 1 m). A stiffer spring changes nothing
    the mesh can see; a softer one spreads the touchdown kink of a rigid seabed over
    several elements (1e5 N/m2: 4.4 m, a 10 % of M_max moment difference at the TDP on the
    Wang riser). The contact frequency stays below the axial one, so the time step is not
    limited by it.
    """
    return max(MIN_SEABED_STIFFNESS, 4.0 * EI / element_length ** 4)


def fixed_ends_scene(scene: Scene, hang_off_xy, seabed_length: float, *,
                     first_segment_length: float | None = None,
                     element_length: float | None = None,
                     seabed_stiffness: float | None = None) -> Scene:
    """Fixed-ends copy of a touchdown-form scene ('tdp_tension' or 'hang_off_angle').

    The hang-off is fixed at ``hang_off_xy`` = (x, y) [m] (e.g. the BVP's top point), the
    anchor is put on the seabed at (-seabed_length, 0), and the first (bottom) segment gets
    the length ``first_segment_length + seabed_length`` (default: its own length, i.e. the
    suspended length of the touchdown form), so that the touchdown stays near x = 0.
    Without a [seabed] the scene gets one of ``seabed_stiffness`` [N/m2] (default
    :func:`rigid_seabed_stiffness` of the first segment's EI at ``element_length``, itself
    defaulting to the scene's [vfife] element length or 1 m), no friction, and 0.1 of
    critical contact damping (it speeds up the static relaxation and damps contact chatter;
    no effect on the equilibrium).
    """
    if seabed_length < 0.0:
        raise ValueError(f"seabed_length must be >= 0, got {seabed_length}")
    segs = list(scene.segments)
    first = segs[0].length if first_segment_length is None else float(first_segment_length)
    segs[0] = dataclasses.replace(segs[0], length=first + float(seabed_length))
    seabed = scene.seabed
    if seabed is None:
        if seabed_stiffness is None:
            el = element_length or scene.vfife.get("element_length", 1.0)
            EI = scene.line_types[scene.segments[0].line_type].bending_stiffness
            seabed_stiffness = rigid_seabed_stiffness(EI, el)
        seabed = Seabed(stiffness=float(seabed_stiffness), friction=0.0, damping=0.1)
    elif seabed_stiffness is not None:
        seabed = dataclasses.replace(seabed, stiffness=float(seabed_stiffness))
    ends = Ends("fixed", anchor=(-float(seabed_length), 0.0),
                hang_off=(float(hang_off_xy[0]), float(hang_off_xy[1])))
    return scene.replace(segments=tuple(segs), ends=ends, seabed=seabed)

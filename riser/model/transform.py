"""Scene transformations shared by the solvers' callers (inputs only, no solver physics)."""

from __future__ import annotations

import dataclasses

import numpy as np

from .scene import (
    SURFACE_ROUND_OFF,
    Current,
    FixedEnds,
    Scene,
    Seabed,
    require_axial_stiffness,
)

#: Seabed stiffness [N/m2] (force per metre of line per metre of penetration) given to a
#: touchdown-form scene without a [seabed] when it becomes a fixed-ends scene: a soft
#: clay, OrcaFlex's default normal stiffness of 100 kN/m/m2 over a 1 m contact width. It is
#: a property of the soil, not of a mesh: both methods solve the converted scene on it.
#: The Wang pipe (526 N/m) sinks 5 mm into it and bends over the foundation length
#: (4 EI/k)^(1/4) = 4.4 m.
DEFAULT_SEABED_STIFFNESS = 1.0e5


def fixed_ends_scene(scene: Scene, hang_off_xy, seabed_length: float, *,
                     first_segment_length: float | None = None,
                     seabed_stiffness: float | None = None) -> Scene:
    """Fixed-ends copy of a touchdown-form scene (:class:`~riser.model.ends.TdpTensionEnds`,
    :class:`~riser.model.ends.HangOffAngleEnds` or :class:`~riser.model.ends.TopTensionEnds`).

    The hang-off is fixed at ``hang_off_xy`` = (x, y) or (x, y, z) [m] (e.g. the BVP's
    top point; z where a current out of plane moved it sideways), the
    anchor is put on the seabed at (-seabed_length, 0), and the first (bottom) segment gets
    the length ``first_segment_length + seabed_length`` (default: its own length, i.e. the
    suspended length of the touchdown form), so that the touchdown stays near x = 0.
    Without a [seabed] the scene gets one of ``seabed_stiffness`` [N/m2] (default
    :data:`DEFAULT_SEABED_STIFFNESS`), no friction, and 0.1 of critical contact damping (it
    speeds up the static relaxation and damps contact chatter; no effect on the
    equilibrium). The copy is the model both methods can solve: extensible on the elastic
    seabed ([model] keys dropped, the fixed-ends defaults), so every line type needs EA.
    Without a water depth the copy's current heights must not pass its hang-off (the
    reference of a scene without a surface, ``Scene.current_reference_height``): a
    touchdown-tension scene's profile is cut at the solved hang-off height, with the speed
    there (the same speeds along the whole line).
    """
    require_axial_stiffness(scene, "required to convert the scene to fixed ends on an elastic "
                            "seabed (the extensible model both methods solve)")
    if seabed_length < 0.0:
        raise ValueError(f"seabed_length must be >= 0, got {seabed_length}")
    segs = list(scene.segments)
    first = segs[0].length if first_segment_length is None else float(first_segment_length)
    segs[0] = dataclasses.replace(segs[0], length=first + float(seabed_length))
    seabed = scene.seabed
    if seabed is None:
        if seabed_stiffness is None:
            seabed_stiffness = DEFAULT_SEABED_STIFFNESS
        seabed = Seabed(stiffness=float(seabed_stiffness), friction=0.0, damping=0.1)
    elif seabed_stiffness is not None:
        seabed = dataclasses.replace(seabed, stiffness=float(seabed_stiffness))
    ends = FixedEnds(anchor=(-float(seabed_length), 0.0),
                     hang_off=tuple(float(v) for v in hang_off_xy))
    current = scene.current
    if scene.water_depth is None and current is not None:
        current = _cut_at(current, float(hang_off_xy[1]))
    return scene.replace(segments=tuple(segs), ends=ends, seabed=seabed, model={},
                         current=current, dynamics=_shifted_stations(
                             scene, sum(g.length for g in segs) - seabed_length,
                             float(seabed_length)))


def _shifted_stations(scene: Scene, suspended: float, shift: float):
    """``scene.dynamics`` with its ``stations`` moved by ``shift`` [m] (the line added at
    the bottom end), on the ``suspended`` length [m] from the touchdown to the hang-off
    that the conversion keeps; a station beyond it is refused."""
    dyn = scene.dynamics
    if dyn is None or dyn.stations is None:
        return dyn
    for i, v in enumerate(dyn.stations):
        if v > suspended * (1.0 + 1e-12):
            raise scene.error(f"dynamics.stations[{i}]", f"must be within [0, "
                              f"{suspended:g}] m, the line from the touchdown to the "
                              f"hang-off the BVP solved for the {scene.ends.kind} form "
                              f"(arc lengths s of a touchdown form are measured from its "
                              f"touchdown), got {v:g}")
    return dyn.replace(stations=tuple(min(v + shift, suspended + shift)
                                      for v in dyn.stations))


def _cut_at(current: Current, top: float) -> Current:
    """``current`` with its heights above ``top`` [m] replaced by one point at ``top``
    carrying the profile's speed there (the same speeds at and below ``top``)."""
    h = current.heights
    if h[-1] <= top * (1.0 + SURFACE_ROUND_OFF):
        return current
    keep = [i for i, y in enumerate(h) if y < top]
    heights = tuple(h[i] for i in keep) + (top,)
    if current.turns:            # the velocity at top, component by component
        ux, uz = (float(v) for v in current.velocity(top))
        heading = float(np.degrees(np.arctan2(uz, ux)))
        return current.replace(heights=heights,
                               speeds=tuple(current.speeds[i] for i in keep)
                               + (float(np.hypot(ux, uz)),),
                               headings_deg=tuple(current.headings_deg[i] for i in keep)
                               + (heading,))
    speed = float(np.interp(top, h, current.speeds))
    return current.replace(heights=heights,
                           speeds=tuple(current.speeds[i] for i in keep) + (speed,))

"""Turning a scene into an equivalent one another method can solve.

The VFIFE solver needs both ends fixed in space; the Wang forms (TDP tension given, or
hang-off height and angle given) leave the hang-off point as an output. The equivalent
fixed-ends scene puts the hang-off at the BVP's top point and lays extra line on a seabed
ahead of the touchdown, so that the touchdown is free to move.
"""

from __future__ import annotations

import dataclasses

from riser.scene import Ends, Scene, Seabed

# Extra line on the seabed ahead of the BVP touchdown [m]: the touchdown of a penalty
# seabed moves by a few metres at most, so ~10 bending lengths is ample.
DEFAULT_SEABED_LENGTH = 300.0
# Penalty stiffness [N/m2] when the scene has no seabed: the Wang pipe (526 N/m) then
# sinks 5 mm, small against the 3-8 m bending boundary layer at the touchdown.
DEFAULT_SEABED_STIFFNESS = 1.0e5


def fixed_ends_scene(scene: Scene, hang_off: tuple[float, float], tdp_suspended_first: float,
                     seabed_length: float = DEFAULT_SEABED_LENGTH,
                     seabed_stiffness: float | None = None) -> Scene:
    """Fixed-ends equivalent of ``scene``.

    The first segment gets length ``tdp_suspended_first + seabed_length`` (its suspended
    part in the BVP solution plus line on the seabed), the anchor sits on the seabed at
    x = -seabed_length (so the BVP touchdown stays at x = 0) and the hang-off at
    ``hang_off`` (x, y) [m].
    """
    segs = list(scene.segments)
    segs[0] = dataclasses.replace(segs[0], length=tdp_suspended_first + seabed_length)
    seabed = scene.seabed or Seabed(stiffness=seabed_stiffness or DEFAULT_SEABED_STIFFNESS)
    return scene.replace(segments=tuple(segs), seabed=seabed,
                         ends=Ends("fixed", anchor=(-seabed_length, 0.0),
                                   hang_off=(float(hang_off[0]), float(hang_off[1]))))


def fixed_ends_via_bvp(scene: Scene, seabed_length: float = DEFAULT_SEABED_LENGTH):
    """Solve ``scene`` with the BVP and return (fixed-ends scene, note for the summary)."""
    import bvp
    res = bvp.solve(scene)
    if not res.converged:
        raise RuntimeError(f"cannot build the fixed-ends scene: the BVP did not converge "
                           f"({res.message})")
    sm = res.summary()
    fixed = fixed_ends_scene(scene, (sm["hang_off_x"], sm["hang_off_height"]),
                             sm["first_segment_suspended_length"], seabed_length)
    note = (f"{scene.ends.kind} ends converted to fixed ends: hang-off at the BVP top point "
            f"({sm['hang_off_x']:.3f}, {sm['hang_off_height']:.3f}) m, anchor on the seabed "
            f"{seabed_length:g} m ahead of the BVP touchdown (that much line added to "
            f"segments[0])")
    return fixed, note

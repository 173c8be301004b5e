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
# Floor of the penalty stiffness [N/m2] when the scene has no seabed: the Wang pipe
# (526 N/m) then sinks 5 mm.
MIN_SEABED_STIFFNESS = 1.0e5


def rigid_seabed_stiffness(EI: float, element_length: float) -> float:
    """Penalty stiffness [N/m2] that is as rigid as the mesh can resolve.

    A beam of bending stiffness EI [N m2] on an elastic foundation of stiffness k bends
    over the length (4 EI / k)^(1/4); setting it equal to the element length gives
    k = 4 EI / l^4 (3.9e7 N/m2 for the Wang pipe at 1 m). A stiffer spring changes nothing
    the mesh can see; a softer one spreads the touchdown kink of the rigid-seabed BVP over
    several elements (1e5 N/m2: 4.4 m, a 10 % of M_max moment difference at the TDP).
    The contact frequency stays below the axial one, so it does not limit the time step.
    """
    return max(MIN_SEABED_STIFFNESS, 4.0 * EI / element_length ** 4)


def fixed_ends_scene(scene: Scene, hang_off: tuple[float, float], tdp_suspended_first: float,
                     seabed_length: float = DEFAULT_SEABED_LENGTH,
                     element_length: float | None = None) -> Scene:
    """Fixed-ends equivalent of ``scene``.

    The first segment gets length ``tdp_suspended_first + seabed_length`` (its suspended
    part in the BVP solution plus line on the seabed), the anchor sits on the seabed at
    x = -seabed_length (so the BVP touchdown stays at x = 0) and the hang-off at
    ``hang_off`` (x, y) [m]. A scene without a seabed gets one of
    :func:`rigid_seabed_stiffness` for the VFIFE element length (default: the scene's).
    """
    segs = list(scene.segments)
    segs[0] = dataclasses.replace(segs[0], length=tdp_suspended_first + seabed_length)
    if scene.seabed is None:
        el = element_length or scene.vfife.get("element_length", 1.0)
        EI = scene.line_types[scene.segments[0].line_type].bending_stiffness
        seabed = Seabed(stiffness=rigid_seabed_stiffness(EI, el))
    else:
        seabed = scene.seabed
    return scene.replace(segments=tuple(segs), seabed=seabed,
                         ends=Ends("fixed", anchor=(-seabed_length, 0.0),
                                   hang_off=(float(hang_off[0]), float(hang_off[1]))))


def fixed_ends_via_bvp(scene: Scene, seabed_length: float = DEFAULT_SEABED_LENGTH,
                       element_length: float | None = None):
    """Solve ``scene`` with the BVP and return (fixed-ends scene, note for the summary)."""
    import bvp
    res = bvp.solve(scene)
    if not res.converged:
        raise RuntimeError(f"cannot build the fixed-ends scene: the BVP did not converge "
                           f"({res.message})")
    sm = res.summary()
    fixed = fixed_ends_scene(scene, (sm["hang_off_x"], sm["hang_off_height"]),
                             sm["first_segment_suspended_length"], seabed_length,
                             element_length)
    note = (f"{scene.ends.kind} ends converted to fixed ends: hang-off at the BVP top point "
            f"({sm['hang_off_x']:.3f}, {sm['hang_off_height']:.3f}) m, anchor on a seabed of "
            f"stiffness {fixed.seabed.stiffness:.3g} N/m2 "
            f"{seabed_length:g} m ahead of the BVP touchdown (that much line added to "
            f"segments[0])")
    return fixed, note

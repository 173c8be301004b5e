"""Turning a scene into an equivalent one another method can solve.

The VFIFE solver needs both ends fixed in space; the Wang forms (TDP tension given, or
hang-off height and angle given) leave the hang-off point as an output. The equivalent
fixed-ends scene puts the hang-off at the BVP's top point and lays extra line on a seabed
ahead of the touchdown, so that the touchdown is free to move.
"""

from __future__ import annotations

from riser.scene import Scene
from riser.transform import fixed_ends_scene

# Extra line on the seabed ahead of the BVP touchdown [m]: the touchdown of a penalty
# seabed moves by a few metres at most, so ~10 bending lengths is ample.
DEFAULT_SEABED_LENGTH = 300.0


def fixed_ends_via_bvp(scene: Scene, seabed_length: float = DEFAULT_SEABED_LENGTH,
                       element_length: float | None = None):
    """Solve ``scene`` with the BVP and return (fixed-ends scene, note for the summary)."""
    import bvp
    res = bvp.solve(scene)
    if not res.converged:
        raise RuntimeError(f"cannot build the fixed-ends scene: the BVP did not converge "
                           f"({res.message})")
    sm = res.summary()
    fixed = fixed_ends_scene(scene, (sm["hang_off_x"], sm["hang_off_height"]), seabed_length,
                             first_segment_length=sm["first_segment_suspended_length"],
                             element_length=element_length)
    note = (f"{scene.ends.kind} ends converted to fixed ends: hang-off at the BVP top point "
            f"({sm['hang_off_x']:.3f}, {sm['hang_off_height']:.3f}) m, anchor on a seabed of "
            f"stiffness {fixed.seabed.stiffness:.3g} N/m2 "
            f"{seabed_length:g} m ahead of the BVP touchdown (that much line added to "
            f"segments[0])")
    return fixed, note

"""Turning a scene into an equivalent one another method can solve.

The VFIFE solver needs both ends fixed in space; the Wang forms (TDP tension given, or
hang-off height and angle given) leave the hang-off point as an output. The equivalent
fixed-ends scene puts the hang-off at the BVP's top point and lays extra line on an
elastic seabed ahead of the touchdown, so that the touchdown is free to move; it is the
model both methods solve (extensible, elastic seabed), see riser/transform.py.
"""

from __future__ import annotations

from riser.scene import Scene
from riser.transform import fixed_ends_scene

# Extra line on the seabed ahead of the BVP touchdown [m]: the lift-off on the elastic
# seabed moves by about one foundation length (4 EI/k)^(1/4), a few metres, so ~60 of them
# is ample.
DEFAULT_SEABED_LENGTH = 300.0


def fixed_ends_from_bvp(scene: Scene, bvp_result,
                        seabed_length: float = DEFAULT_SEABED_LENGTH) -> Scene:
    """The fixed-ends equivalent of a converged BVP result of ``scene``: hang-off at the
    BVP top point, ``seabed_length`` [m] of line added to segments[0] on the elastic
    seabed ahead of the BVP touchdown (anchor at x = -seabed_length, y = 0)."""
    sm = bvp_result.summary()
    return fixed_ends_scene(scene, (sm["hang_off_x"], sm["hang_off_height"]), seabed_length,
                            first_segment_length=sm["first_segment_suspended_length"])


def fixed_ends_note(scene: Scene, fixed: Scene, seabed_length: float) -> str:
    """One sentence saying how ``scene`` was converted into ``fixed``."""
    xh, yh = fixed.ends.hang_off
    return (f"{scene.ends.kind} ends converted to fixed ends: hang-off at the BVP top point "
            f"({xh:.3f}, {yh:.3f}) m, anchor on a seabed of stiffness "
            f"{fixed.seabed.stiffness:.3g} N/m2 {seabed_length:g} m ahead of the BVP "
            f"touchdown (that much line added to segments[0])")


def fixed_ends_via_bvp(scene: Scene, seabed_length: float = DEFAULT_SEABED_LENGTH):
    """Solve ``scene`` with the BVP and return (fixed-ends scene, note for the summary)."""
    import bvp
    res = bvp.solve(scene)
    if not res.converged:
        raise RuntimeError(f"cannot build the fixed-ends scene: the BVP did not converge "
                           f"({res.message})")
    fixed = fixed_ends_from_bvp(scene, res, seabed_length)
    return fixed, fixed_ends_note(scene, fixed, seabed_length)

"""Boundary conditions the VFIFE solver accepts, and turning a touchdown-form scene into one."""

from __future__ import annotations

from riser.errors import UnsupportedSceneError
from riser.scene import Scene

def require_fixed_ends(scene: Scene) -> None:
    """Raise :class:`UnsupportedSceneError` unless the scene has fixed ends."""
    if scene.ends.kind != "fixed":
        raise UnsupportedSceneError(
            f"{scene.source}: ends: vfife needs fixed ends (anchor + hang_off) but the scene "
            f"gives the '{scene.ends.kind}' form; solve it with the bvp method first and "
            f"convert it with riser.transform.fixed_ends_scene(scene, hang_off_xy, seabed_length) "
            f"(the CLI does this for you)")

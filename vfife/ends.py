"""Boundary conditions and continuum models the VFIFE solver accepts."""

from __future__ import annotations

from riser.errors import UnsupportedSceneError
from riser.model.scene import FixedEnds, Scene


def require_fixed_ends(scene: Scene) -> None:
    """Raise :class:`UnsupportedSceneError` unless the scene has fixed ends and asks for the
    model the VFIFE elements are: extensible (strain T/EA) on an elastic (penalty) seabed.
    The inextensible line and the rigid seabed are BVP limits only."""
    if not isinstance(scene.ends, FixedEnds):
        raise UnsupportedSceneError(
            f"{scene.source}: ends: vfife needs fixed ends (anchor + hang_off) but the scene "
            f"gives the '{scene.ends.kind}' form; solve it with the bvp method first and "
            f"convert it with riser.model.transform.fixed_ends_scene(scene, hang_off_xy, seabed_length) "
            f"(the CLI does this for you)")
    require_vfife_model(scene)


def require_vfife_model(scene: Scene) -> None:
    """Raise :class:`UnsupportedSceneError` if the scene's [model] explicitly asks for a
    BVP-only limit (also for a Wang-form scene, before its fixed-ends conversion, which
    would otherwise solve the extensible line on an elastic seabed instead)."""
    if scene.model.get("axial") == "inextensible":
        raise UnsupportedSceneError(
            f"{scene.source}: model.axial: 'inextensible' is a limit only the bvp method "
            "solves; the vfife elements stretch (use 'extensible' or --method bvp)")
    if scene.model.get("seabed") == "rigid":
        raise UnsupportedSceneError(
            f"{scene.source}: model.seabed: 'rigid' is a limit only the bvp method solves; "
            "the vfife seabed is an elastic penalty of [seabed] stiffness (use 'elastic' or "
            "--method bvp)")

"""The rules between a fixed-ends scene's end conditions (``[ends.anchor_joint]``,
``[ends.hang_off_joint]``, ``[ends.tensioner]``) and the rest of the scene, checked when
the scene is built (:class:`riser.model.scene.Scene`): one line naming the key.

What the methods model (docs/scene-files.md, "End conditions"): a joint or a tensioner in
a planar scene; the 3D rod and the 3D kernels hold their ends pinned, so a scene out of
its plane with one is refused rather than solved with pinned ends. The tensioner's pull
against the line's weight is checked before solving (:func:`riser.results.validity.check_end_loads`:
it needs the section properties).
"""

from __future__ import annotations

from .ends import FixedEnds


def check_end_conditions(scene) -> None:
    """Refuse end conditions the scene cannot have (raises ``scene.error``)."""
    e = scene.ends
    if not isinstance(e, FixedEnds) or e.plain:
        return
    key = _first_key(e)
    far = scene.out_of_plane()
    if far is not None:
        raise scene.error(key, f"needs a planar scene ({far[1]}, {far[0]}): the 3D rod "
                          "and the 3D kernels hold their ends pinned")
    if e.free_anchor:
        _check_free_anchor(scene, e)


def _first_key(e: FixedEnds) -> str:
    for name in ("anchor_joint", "hang_off_joint", "tensioner"):
        part = getattr(e, name)
        if part is not None and getattr(part, "kind", "") != "pinned":
            return f"ends.{name}" + (".kind" if name != "tensioner" else ".top_tension")
    return "ends"


def _check_free_anchor(scene, e: FixedEnds) -> None:
    if e.tensioner is not None:
        raise scene.error("ends.tensioner", "a tensioner with a free anchor end: nothing "
                          "holds the line down (a hanging line hangs from a fixed hang-off)")
    if scene.seabed is not None:
        raise scene.error("ends.anchor_joint.kind", "'free' with a [seabed]: the free end "
                          "is not modelled on the seabed (remove [seabed] for a hanging "
                          "line)")
    length = scene.total_length
    top = e.hang_off_point[1]
    if length >= top:
        raise scene.error("ends.anchor_joint.kind", f"'free': the line ({length:g} m) is "
                          f"as long as the hang-off's height above the seabed ({top:g} m); "
                          "a hanging line with a free end must clear the seabed")

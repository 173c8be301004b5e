"""A line's attachments -> ``[[attachments]]``.

An OrcaFlex clump (``ClumpTypes``: Mass, Volume, DragArea and Cd per local axis, Ca per
axis) attached on the line's axis (x = y = 0) at arc length z from End A or End B is the
scene's point attachment at s (from the scene's bottom end): mass = Mass, volume =
Volume, drag_area = Cd x DragArea, added_mass_coefficient = Ca (OrcaFlex's clump: weight
(M - rho V) g, drag 1/2 rho Cd A |v| v, added mass Ca rho V, as the scene's). The scene's
attachment is isotropic: the three axes' Cd x DragArea, and their Ca, must be equal.
Other attachment kinds (drag chains, flex joints, bend stiffeners, buoys) are refused.
"""

from __future__ import annotations

from .text_file import Model, ModelError, get, number, table
from .units import Units

COLUMNS = ("AttachmentType", "Attachmentx", "Attachmenty", "Attachmentz")


def attachments(model: Model, ln: dict, u: Units, total: float, from_b: bool, src: str,
                item: str, notes: list[str], flow: bool = True,
                dynamic: bool = True) -> tuple[list[dict], dict]:
    """The scene's attachments of line ``ln`` (``total`` its length [m]; ``from_b``: the
    scene's s runs from End B) and the comment lines of each; ``flow``: the scene has a
    current or waves (drag acts), ``dynamic``: it carries dynamics (added mass acts)."""
    rows = table(ln, COLUMNS, src, item)
    if not rows:
        return [], {}
    out, comments = [], {}
    clumps = {str(c.get("Name")): c for c in model.objects("ClumpTypes")}
    for k, r in enumerate(rows):
        it = f"{item}.Attachment[{k + 1}]"
        tname = str(get(r, "AttachmentType"))
        if tname not in clumps:
            other = next((sec for sec in ("DragChainTypes", "FlexJointTypes",
                                          "StiffenerTypes", "BendStiffenerTypes",
                                          "SupportTypes", "6DBuoys", "3DBuoys")
                          if tname in [str(o.get("Name")) for o in model.objects(sec)]
                          if isinstance(model.section(sec), list)), None)
            what = f"a {other[:-5] if other.endswith('Types') else other} item" if other \
                else "not a clump type of the model"
            raise ModelError(src, f"{it}.AttachmentType", f"{tname!r} ({what}): only clump "
                             "attachments (point masses, buoyancy, drag) are carried")
        for c in ("Attachmentx", "Attachmenty"):
            off = number(get(r, c), src, f"{it}.{c}", allow_none=True) or 0.0
            if off != 0.0:
                raise ModelError(src, f"{it}.{c}", f"{off:g}: an attachment off the line's "
                                 "axis is not carried (the scene's sits on the axis)")
        z = number(get(r, "Attachmentz"), src, f"{it}.Attachmentz") * u.length
        rel = str(get(r, "AttachmentzRelativeTo", "AttachmentzRel", default="End A"))
        if rel.lower() not in ("end a", "end b"):
            raise ModelError(src, f"{it}.AttachmentzRelativeTo", f"{rel!r}: only arc "
                             "lengths from End A or End B are read")
        from_a = z if rel.lower() == "end a" else total - z
        s = total - from_a if from_b else from_a
        c = clumps[tname]
        cit = f"ClumpTypes[{tname}]"
        mass = number(get(c, "Mass"), src, f"{cit}.Mass") * u.mass
        vol = (number(get(c, "Volume"), src, f"{cit}.Volume", allow_none=True) or 0.0) \
            * u.length ** 3
        area = _three(get(c, "DragArea"), src, f"{cit}.DragArea")
        cd = _three(get(c, "Cd"), src, f"{cit}.Cd")
        ca = _three(get(c, "Ca"), src, f"{cit}.Ca")
        cda = [a * d * u.length ** 2 for a, d in zip(area, cd)]
        if max(cda) != min(cda):
            if flow:
                raise ModelError(src, f"{cit}.Cd", f"Cd x DragArea per axis {cda}: the "
                                 "scene's attachment drag is isotropic (equal on the three "
                                 "axes)")
            notes.append(f"{cit}: drag per axis {cda} m2 not carried (no current or waves: "
                         "no drag acts); drag_area = 0")
            cda = [0.0] * 3
        if max(ca) != min(ca):
            if dynamic:
                raise ModelError(src, f"{cit}.Ca", f"{ca}: the scene's attachment added mass "
                                 "is isotropic (equal on the three axes)")
            notes.append(f"{cit}: added mass per axis {ca} not carried (the scene is static)")
            ca = [0.0] * 3
        off = get(c, "Offset")
        if isinstance(off, list) and any(number(o, src, f"{cit}.Offset", allow_none=True)
                                         for o in off):
            raise ModelError(src, f"{cit}.Offset", f"{off}: an offset clump is not carried")
        key = f"attachments[{len(out)}]"
        out.append({"s": s, "mass": mass, "volume": vol, "drag_area": cda[0],
                    "added_mass_coefficient": ca[0],
                    "label": str(get(r, "AttachmentName", default=None) or tname)})
        comments[key] = [f"OrcaFlex attachment {k + 1} (clump type {tname}) at z = "
                         f"{z / u.length:.12g} from {rel}: mass = Mass, volume = Volume, "
                         "drag_area = Cd x DragArea, added_mass_coefficient = Ca"]
    notes.append(f"{len(out)} clump attachment(s) -> [[attachments]] (Height and AlignWith "
                 "not carried: the scene's clump is submerged and isotropic).")
    return out, comments


def _three(v, src: str, item: str) -> list[float]:
    """OrcaFlex's per-axis [x, y, z] (or one value; ~ the same as the previous)."""
    vals = v if isinstance(v, list) else [v]
    out = []
    for k in range(3):
        x = vals[k] if k < len(vals) else None
        x = number(x, src, item, allow_none=True)
        out.append(out[-1] if x is None and out else (0.0 if x is None else x))
    return out

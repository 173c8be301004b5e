"""The round trip scene -> OrcaFlex text data file -> scene, and how far the two scenes
differ (:func:`round_trip`), for the built-in scenes (:func:`built_in_round_trips`).

What is compared (the import puts the anchor at x = 0 and the line's plane through its
two ends, so a 3D scene comes back turned into that plane and every scene translated):

- ``sections``: every derived section property of every segment (EA, EI, mass, weight,
  drag and added-mass coefficients, fluid mass; :func:`riser.model.sections.segment_properties`),
  relative; except the wall's polar inertia of a segment written with its own
  displacement diameter (a buoyancy section, a weight override: ``rotary_inertia``,
  reported apart: the scene derives it from the displacement diameter);
- ``geometry``: the hang-off relative to the anchor (horizontal distance, height), the
  water depth, gravity, density, the element length [m or relative];
- ``environment``: the current's heights and speeds, its heading turned by the plane's;
  the waves' heights, periods, headings, phase lags (modulo 360 deg) and origin's
  distance; the sea's Hs, Tp, gamma, components and seed;
- ``vessel``: its heading, lever arm and every RAO amplitude and phase (modulo 360);
- ``attachments``, ``joints``, ``seabed``: each number.

Each category's worst difference is relative to the value (absolute for angles [deg]
and positions [m], which have no scale of their own).
"""

from __future__ import annotations

import math
import tempfile
from dataclasses import dataclass, field, fields
from pathlib import Path

from riser.errors import SceneError
from riser.io.orcaflex.model_from_scene import export_model
from riser.io.orcaflex.scene_from_model import import_model
from riser.model.scene import Scene
from riser.model.sections import segment_properties


@dataclass
class RoundTrip:
    """A scene's round trip: ``refused`` the export's one line (None: exported), the
    worst difference per category, and the segments written with their own line type."""

    scene: str
    refused: str | None = None
    worst: dict = field(default_factory=dict)
    own_segments: list[int] = field(default_factory=list)

    @property
    def largest(self) -> float:
        return max(self.worst.values(), default=0.0)


def _rel(a: float, b: float) -> float:
    if a == b:
        return 0.0
    return abs(a - b) / max(abs(a), abs(b))


def _angle(a: float, b: float) -> float:
    """|a - b| modulo 360 [deg]."""
    d = math.fmod(a - b, 360.0)
    return min(abs(d), 360.0 - abs(d))


def _plane_heading(scene: Scene) -> float:
    """The heading [deg] of the chord from the anchor to the hang-off in the scene's x-z
    plane (0 for a planar scene): the import's x axis."""
    e = scene.ends
    a, h = e.anchor_point, e.hang_off_point
    return math.degrees(math.atan2(h[2] - a[2], h[0] - a[0]))


def compare(a: Scene, b: Scene) -> tuple[dict, list[int]]:
    """The worst difference per category between ``a`` and its round trip ``b``."""
    worst: dict[str, float] = {}

    def put(cat: str, d: float) -> None:
        worst[cat] = max(worst.get(cat, 0.0), d)

    own = [k for k, s in enumerate(a.segments)
           if s.buoyancy or s.submerged_weight is not None or s.weight_scale != 1.0
           or s.hydro_diameter is not None
           or a.line_types[s.line_type].submerged_weight is not None]
    pa, pb = segment_properties(a), segment_properties(b)
    if len(pa) != len(pb):
        put("sections", math.inf)
    for k, (x, y) in enumerate(zip(pa, pb)):
        for f in fields(x):
            d = _rel(getattr(x, f.name), getattr(y, f.name))
            put("rotary_inertia" if (f.name == "rotary_inertia" and k in own) else
                "sections", d)
    ea, eb = a.ends, b.ends
    ra = [h - q for h, q in zip(ea.hang_off_point, ea.anchor_point)]
    rb = [h - q for h, q in zip(eb.hang_off_point, eb.anchor_point)]
    put("geometry", abs(math.hypot(ra[0], ra[2]) - math.hypot(rb[0], rb[2])))
    put("geometry", abs(ra[1] - rb[1]))
    put("geometry", abs(ea.anchor_point[1] - eb.anchor_point[1]))
    for name in ("gravity", "water_density", "water_depth"):
        put("geometry", _rel(getattr(a, name) or 0.0, getattr(b, name) or 0.0))
    put("geometry", _rel(a.vfife.element_length, b.vfife.element_length))
    turn = _plane_heading(a)
    if (a.current is None) != (b.current is None):
        put("environment", math.inf)
    elif a.current is not None:
        ca, cb = a.current, b.current
        if len(ca.heights) != len(cb.heights):
            put("environment", math.inf)
        for x, y in zip(ca.heights, cb.heights):
            put("environment", abs(x - y))
        for x, y in zip(ca.speeds, cb.speeds):
            put("environment", _rel(x, y))
        put("environment", _angle(ca.heading_deg - turn, cb.heading_deg))
    wa, wb = a.waves, b.waves
    if (wa is None) != (wb is None):
        put("environment", math.inf)
    elif wa is not None:
        if len(wa.trains) != len(wb.trains) or (wa.spectrum is None) != (wb.spectrum is None):
            put("environment", math.inf)
        for x, y in zip(wa.trains, wb.trains):
            put("environment", _rel(x.height, y.height))
            put("environment", _rel(x.period, y.period))
            put("environment", _angle(x.heading_deg - turn, y.heading_deg))
            put("environment", _angle(x.phase_deg, y.phase_deg))
        if wa.spectrum is not None and wb.spectrum is not None:
            sa, sb = wa.spectrum, wb.spectrum
            for name in ("hs", "tp", "gamma_used"):
                put("environment", _rel(getattr(sa, name), getattr(sb, name)))
            put("environment", _angle(sa.heading_deg - turn, sb.heading_deg))
            put("environment", 0.0 if (sa.components, sa.seed, sa.kind) ==
                (sb.components, sb.seed, sb.kind) else math.inf)
        put("environment", _rel(wa.ramp, wb.ramp))
        put("environment", 0.0 if wa.stretching == wb.stretching else math.inf)
    va, vb = a.vessel if wa is not None else None, b.vessel
    if (va is None) != (vb is None):
        put("vessel", math.inf)
    elif va is not None:
        put("vessel", _angle(va.heading_deg - turn, vb.heading_deg))
        for x, y in zip(va.hang_off_on_vessel, vb.hang_off_on_vessel):
            put("vessel", abs(x - y))
        ta = sorted(va.raos, key=lambda t: (t.heading_deg - turn) % 360.0)
        tb = sorted(vb.raos, key=lambda t: t.heading_deg % 360.0)
        if len(ta) != len(tb):
            put("vessel", math.inf)
        for x, y in zip(ta, tb):
            put("vessel", _angle(x.heading_deg - turn, y.heading_deg))
            for p, q in zip(x.periods, y.periods):
                put("vessel", _rel(p, q))
            for dof in ("surge", "sway", "heave", "roll", "pitch", "yaw"):
                for p, q in zip(getattr(x, dof), getattr(y, dof)):
                    put("vessel", _rel(p, q))
                for p, q in zip(getattr(x, f"{dof}_phase_deg"), getattr(y, f"{dof}_phase_deg")):
                    put("vessel", _angle(p, q))
    if len(a.attachments) != len(b.attachments):
        put("attachments", math.inf)
    for x, y in zip(a.attachments, b.attachments):
        put("attachments", abs(x.s - y.s))
        for name in ("mass", "volume", "drag_area", "added_mass_coefficient"):
            put("attachments", _rel(getattr(x, name), getattr(y, name)))
    for end in ("anchor_joint", "hang_off_joint"):
        ja, jb = getattr(ea, end), getattr(eb, end)
        ka = ja.kind if ja is not None else "pinned"
        kb = jb.kind if jb is not None else "pinned"
        if ka != kb:
            put("joints", math.inf)
        elif ka in ("clamped", "spring"):
            put("joints", _angle(ja.direction_deg, jb.direction_deg))
            if ka == "spring":
                put("joints", _rel(ja.rotational_stiffness, jb.rotational_stiffness))
    sa, sb = a.seabed, b.seabed
    if (sa is None) != (sb is None):
        put("seabed", math.inf)
    elif sa is not None:
        for name in ("stiffness", "friction", "damping"):
            put("seabed", _rel(getattr(sa, name), getattr(sb, name)))
    return worst, own


def round_trip(scene: Scene, folder: Path | None = None) -> RoundTrip:
    """Export ``scene``, import the file back (into ``folder``, else a temporary one) and
    compare (:func:`compare`); a refused export gives its one line."""
    try:
        text, _ = export_model(scene)
    except SceneError as exc:
        return RoundTrip(scene.name, refused=f"{exc.key}: {exc.message}")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(folder or tmp) / f"{scene.name}.yml"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        _, back, _ = import_model(path, name=scene.name)
    worst, own = compare(scene, back)
    return RoundTrip(scene.name, worst=worst, own_segments=own)


def built_in_round_trips() -> list[RoundTrip]:
    """The round trip of every built-in scene, by name."""
    from verification.catalog import builtin_paths, resolve
    return [round_trip(resolve(name)) for name in sorted(builtin_paths())]

"""The scene: an immutable, self-validating description of one line and its environment
(read from a file by :mod:`riser.io.scene_file`, or built in code).

Conventions (SI throughout): x horizontal from the anchor/touchdown towards the
hang-off, y vertical up with the seabed at y = 0 (the surface at y = water_depth),
z out of plane (right-handed); arc length s from the bottom end. Angles are from the
horizontal unless the name says otherwise.

Every part checks its fields on construction (:mod:`riser.spec`); :class:`Scene` checks
its own fields and the rules between parts (segments name existing line types, the ends
fit the line and the water depth, the [model] fits the ends, the flow fits the bores), so
``Scene(...)``, ``scene.replace(...)`` and the scene file give the same one-line
:class:`~riser.errors.SceneError` naming the key path (``segments[2].length``) and the
scene's ``source``.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

from .attachments import Attachment, check_attachments
from ..design.part import Design, check_design
from ..physics.dynamics import Dynamics, TopMotion, check_output_size, check_stations
from .end_checks import check_end_conditions
from .ends import (
    END_FORMS,
    Ends,
    FixedEnds,
    HangOffAngleEnds,
    TdpTensionEnds,
    TopTensionEnds,
)
from ..physics.environment import Current, Seabed
from ..errors import SceneError
from ..physics.internal_flow import InternalFlow, check_internal_flow
from ..physics.sea_state import check_sea_state, sea_state_out_of_plane
from .line import LineType, Segment
from .scene_paths import replaced
from .settings import ANCFSettings, AnalyticSettings, BVPSettings, VFIFESettings
from ..spec import Spec, check, check_fields, spec
from ..physics.vessel import Vessel
from ..physics.waves import Waves

__all__ = [
    "END_FORMS",
    "MODEL_KEYS",
    "Current",
    "Dynamics",
    "Ends",
    "FixedEnds",
    "HangOffAngleEnds",
    "InternalFlow",
    "LineType",
    "Scene",
    "Seabed",
    "Segment",
    "TdpTensionEnds",
    "TopMotion",
    "TopTensionEnds",
    "require_axial_stiffness",
]

ENV = "environment"
#: a hang-off above the surface by less than this fraction of the water depth is at the
#: surface: a scene converted to fixed ends takes the BVP's top point, which meets a
#: hang-off height at the surface to round-off (1 ulp above it for kang2015-jlay)
SURFACE_ROUND_OFF = 1e-12

#: an anchor of a scene with a [seabed] less than this fraction of the bottom line type's
#: outer diameter above the seabed is put on it (y = 0, with a note in ``Scene.notes``):
#: 1 cm for a 0.2 m pipe, about twice its static penetration into a soft clay (w / k = 5 mm
#: for the Wang pipe on 1e5 N/m2). An anchor typed 1 mm above the seabed otherwise
#: makes a different problem: a line hanging from the anchor onto the seabed, with no
#: touchdown of the anchor's contact zone (the BVP's lift-off form and every report of
#: the touchdown start from an anchor at y = 0).
ANCHOR_SNAP_FRACTION = 0.05

#: the keys of [model]: the continuum model, when not the end form's default
MODEL_KEYS = {
    "axial": Spec(kind="string", choices=("extensible", "inextensible"), optional=True,
                  default_doc="extensible (fixed ends), inextensible (other forms)",
                  doc="strain T/EA, or the inextensible limit (the Wang model)"),
    "seabed": Spec(kind="string", choices=("elastic", "rigid"), optional=True,
                   default_doc="elastic (fixed ends with a [seabed]), rigid (other forms)",
                   doc="Winkler foundation of [seabed] stiffness, or the rigid limit"),
}


@dataclass(frozen=True)
class Scene:
    """A validated riser scene. ``source`` is the file it came from (for messages);
    ``provenance`` is the file's ``source`` key (where the data come from)."""

    name: str = spec(kind="string", pattern=r"[a-z0-9][a-z0-9-]*",
                     doc="the scene's name: lowercase letters, digits and dashes")
    line_types: dict[str, LineType]
    segments: tuple[Segment, ...]
    ends: Ends = spec(kind="part", part=Ends)
    title: str = spec("", "string", doc="one line saying what the scene is")
    provenance: str = spec("", "string", key="source",
                           doc="where the data come from (a paper, its tables)")
    gravity: float = spec(9.81, ge=1.0, le=30.0, unit="m/s2", table=ENV,
                          doc="acceleration of gravity")
    water_density: float = spec(1025.0, ge=500.0, le=2000.0, unit="kg/m3", table=ENV,
                                doc="density of the sea water")
    water_depth: float | None = spec(None, ge=1.0, le=12000.0, unit="m", table=ENV,
                                     also=">= the hang-off height",
                                     default_doc="none (no surface)",
                                     doc="height of the surface above the seabed")
    current: Current | None = spec(None, "part", part=Current, table=ENV)
    waves: Waves | None = spec(None, "part", part=Waves, table=ENV)
    vessel: Vessel | None = spec(None, "part", part=Vessel)
    seabed: Seabed | None = spec(None, "part", part=Seabed)
    dynamics: Dynamics | None = spec(None, "part", part=Dynamics)
    internal_flow: InternalFlow | None = spec(None, "part", part=InternalFlow)
    design: Design | None = spec(None, "part", part=Design)
    attachments: tuple[Attachment, ...] = ()
    bvp: BVPSettings = spec(kind="part", part=BVPSettings, default_factory=BVPSettings)
    analytic: AnalyticSettings = spec(kind="part", part=AnalyticSettings,
                                      default_factory=AnalyticSettings)
    vfife: VFIFESettings = spec(kind="part", part=VFIFESettings,
                                default_factory=VFIFESettings)
    ancf: ANCFSettings = spec(kind="part", part=ANCFSettings, default_factory=ANCFSettings)
    model: dict = field(default_factory=dict)
    source: str = "<scene>"
    #: the anchor height [m] the input gave when the scene put the anchor on the seabed
    #: (no field: not a key of the file; kept by :meth:`replace` while the anchor is)
    _anchor_given = None

    def __post_init__(self) -> None:
        if not isinstance(self.source, str):
            raise TypeError(f"Scene.source must be a string, got {self.source!r}")
        check_fields(self, error=self.error)
        for key, value in self.model.items():
            if key not in MODEL_KEYS:
                raise self.error(f"model.{key}", "unknown key (known keys here: "
                                 f"{', '.join(MODEL_KEYS)})")
            check(MODEL_KEYS[key], value, f"model.{key}", self.error)
        self._check_line()
        if self.internal_flow is not None:
            check_internal_flow(self)
        self._check_model()
        self._snap_anchor()
        self._check_geometry()
        check_end_conditions(self)
        check_attachments(self)
        self._check_current()
        self._check_top_motion()
        check_sea_state(self)
        check_output_size(self)
        check_stations(self)
        check_design(self)

    def error(self, key: str, message: str) -> SceneError:
        """A SceneError of this scene's source naming ``key``."""
        return SceneError(self.source, key, message)

    def _check_line(self) -> None:
        """Line types named by their keys; segments, each of a defined line type."""
        if not isinstance(self.line_types, dict) or not self.line_types:
            raise self.error("line_types", "at least one line type is required")
        for key, lt in self.line_types.items():
            if not isinstance(lt, LineType):
                raise self.error(f"line_types.{key}", "must be a LineType, got "
                                 f"{type(lt).__name__}")
            if lt.name != key:
                raise self.error(f"line_types.{key}", f"holds the line type named "
                                 f"{lt.name!r}: a line type's name is its key")
        if isinstance(self.segments, list):
            object.__setattr__(self, "segments", tuple(self.segments))
        if not isinstance(self.segments, tuple) or not self.segments:
            raise self.error("segments", "must have at least one entry")
        for i, seg in enumerate(self.segments):
            if not isinstance(seg, Segment):
                raise self.error(f"segments[{i}]", f"must be a Segment, got "
                                 f"{type(seg).__name__}")
            if seg.line_type not in self.line_types:
                raise self.error(f"segments[{i}].line_type", f"unknown line type "
                                 f"{seg.line_type!r} (defined: "
                                 f"{', '.join(map(repr, self.line_types))})")

    def _check_model(self) -> None:
        """The [model] choices fit the end form, the seabed and the line types."""
        wang = not isinstance(self.ends, FixedEnds)
        if self.model.get("seabed") == "elastic" and wang:
            raise self.error("model.seabed", "'elastic' needs fixed ends (anchor + hang_off); "
                             f"the '{self.ends.kind}' form puts the touchdown on a rigid "
                             "seabed (use 'rigid' or omit the key)")
        if "seabed" in self.model and not wang and self.seabed is None:
            raise self.error("model.seabed", "needs a [seabed] table (with its stiffness)")
        if self.axial_model == "extensible":
            why = "the default for fixed ends" if "axial" not in self.model else "[model] axial"
            require_axial_stiffness(self, f"required for the extensible model ({why}): give "
                                    "it [N] or youngs_modulus, or set [model] axial = "
                                    "\"inextensible\"")

    def _snap_anchor(self) -> None:
        """Put an anchor within :data:`ANCHOR_SNAP_FRACTION` of the bottom line's diameter
        above a [seabed] on it (y = 0), remembering the given height for :attr:`notes`."""
        e = self.ends
        if not (isinstance(e, FixedEnds) and self.seabed is not None
                and 0.0 < e.anchor[1] <= self.anchor_snap_tolerance):
            return
        object.__setattr__(self, "_anchor_given", float(e.anchor[1]))
        object.__setattr__(self, "ends", dataclasses.replace(
            e, anchor=(e.anchor[0], 0.0, *e.anchor[2:])))

    @property
    def anchor_snapped_from(self) -> float | None:
        """The anchor height [m] the input gave when the scene put the anchor on the
        seabed (within :attr:`anchor_snap_tolerance`), else None; said by :attr:`notes`."""
        return self._anchor_given

    @property
    def anchor_snap_tolerance(self) -> float:
        """[m] An anchor at most this high above a [seabed] is put on it:
        :data:`ANCHOR_SNAP_FRACTION` of the bottom segment's outer diameter."""
        bottom = self.line_types[self.segments[0].line_type]
        return ANCHOR_SNAP_FRACTION * bottom.outer_diameter

    @property
    def notes(self) -> tuple[str, ...]:
        """Sentences on what the scene changed of its input (an anchor put on the seabed);
        a result of the scene says them."""
        if self.anchor_snapped_from is None:
            return ()
        note = (f"note: ends.anchor[1] = {self.anchor_snapped_from:g} m is within "
                f"{self.anchor_snap_tolerance:.3g} m ({ANCHOR_SNAP_FRACTION:g} of the bottom "
                "line's outer diameter) of the seabed, so the anchor was put on it (y = 0)")
        return (note,)

    @property
    def current_reference_height(self) -> tuple[float, str] | None:
        """The highest height [m] a current profile may name, and what it is: the water
        depth; without one, the highest end the scene gives (the hang-off height of forms
        (b) and (d), the higher of the fixed ends); None for the touchdown-tension form
        without a water depth (its hang-off is an output)."""
        e = self.ends
        if self.water_depth is not None:
            return self.water_depth, "the water depth (environment.water_depth)"
        why = ("with no environment.water_depth the hang-off is the highest point the "
               "current acts on; give water_depth for a profile up to the surface")
        if isinstance(e, FixedEnds):
            top, which = max((e.hang_off[1], "hang-off"), (e.anchor[1], "anchor"))
            return top, f"the {which} height ({why})"
        if isinstance(e, (HangOffAngleEnds, TopTensionEnds)):
            return e.hang_off_height, f"the hang-off height ({why})"
        return None

    def _check_current(self) -> None:
        """The current's heights lie between the seabed (y = 0, the spec) and the surface
        (:attr:`current_reference_height`): a profile typed in the wrong frame (from the
        surface, in km) would otherwise be read far from the line, silently."""
        ref = self.current_reference_height
        if self.current is None or ref is None:
            return
        top, what = ref
        for i, h in enumerate(self.current.heights):
            if h > top * (1.0 + SURFACE_ROUND_OFF):
                raise self.error(f"environment.current.heights[{i}]", f"must be <= {top:g} m, "
                                 f"{what}: heights are measured up from the seabed y = 0; "
                                 f"got {h:g}")

    def _check_top_motion(self) -> None:
        """A vertical top motion keeps the hang-off above the seabed (where the scene gives
        the hang-off height)."""
        dyn, e = self.dynamics, self.ends
        tm = None if dyn is None else dyn.top_motion
        if tm is None or not tm.moves("y"):
            return
        if isinstance(e, FixedEnds):
            top = e.hang_off[1]
        elif isinstance(e, (HangOffAngleEnds, TopTensionEnds)):
            top = e.hang_off_height
        else:
            return
        low = tm.lowest_displacement
        if top + low <= 0.0:
            ys = tm.series.get("y")
            key = (("amplitudes[1]" if tm.is_orbit else "amplitude") if ys is None else
                   f"displacements{'' if tm.one_axis else '_y'}[{ys.index(min(ys))}]")
            raise self.error(f"dynamics.top_motion.{key}", f"moves the hang-off {-low:g} m "
                             f"down from its height {top:g} m, to or below the seabed y = 0: "
                             f"must be < {top:g} m down")

    def _check_geometry(self) -> None:
        """Physically impossible but well-formed scenes are refused before solving."""
        e, depth, length = self.ends, self.water_depth, self.total_length
        surface = None if depth is None else depth * (1.0 + SURFACE_ROUND_OFF)
        if isinstance(e, FixedEnds):
            chord = math.dist(e.anchor_point, e.hang_off_point)
            # an extensible line no longer than the chord is taut (it stretches); only the
            # inextensible model cannot reach
            if (self.axial_model == "inextensible" and length <= chord
                    and e.tensioner is None and not e.free_anchor):
                raise self.error("segments", f"line length {length:g} m is not longer than "
                                 f"the distance {chord:g} m between anchor and hang_off: too "
                                 "short for an inextensible line ([model] axial = "
                                 "\"extensible\" lets it stretch)")
            if depth is not None and e.hang_off[1] > surface:
                raise self.error("ends.hang_off[1]", f"must be <= water_depth {depth:g} m "
                                 f"(the model is fully submerged), got {e.hang_off[1]:g}")
            if depth is not None and e.anchor[1] > surface:
                raise self.error("ends.anchor[1]", f"must be <= water_depth {depth:g} m "
                                 f"(the model is fully submerged), got {e.anchor[1]:g}")
        if isinstance(e, (HangOffAngleEnds, TopTensionEnds)):
            if depth is not None and e.hang_off_height > surface:
                raise self.error("ends.hang_off_height", f"must be <= water_depth {depth:g} "
                                 f"m, got {e.hang_off_height:g}")
            if length <= e.hang_off_height:
                raise self.error("segments", f"line length {length:g} m cannot reach the "
                                 f"hang-off height {e.hang_off_height:g} m")

    @property
    def axial_model(self) -> str:
        """'extensible' (strain T/EA) or 'inextensible' (the Wang limit): the [model] axial
        key, else 'inextensible' for the Wang end forms and 'extensible' for fixed ends."""
        return self.model.get("axial", "extensible" if isinstance(self.ends, FixedEnds)
                              else "inextensible")

    @property
    def seabed_model(self) -> str | None:
        """'elastic' (unilateral Winkler foundation of [seabed] stiffness), 'rigid' (a
        touchdown point with theta = M = 0 on y = 0: the Wang limit), or None (fixed ends
        without a [seabed]). The Wang end forms are rigid by construction."""
        if not isinstance(self.ends, FixedEnds):
            return "rigid"
        if self.seabed is None:
            return None
        return self.model.get("seabed", "elastic")

    def continuum_model(self) -> dict:
        """The continuum model of the scene, as a result reports it: ``axial``,
        ``seabed`` and, on an elastic seabed, ``seabed_stiffness`` [N/m2]."""
        out = {"axial": self.axial_model, "seabed": self.seabed_model}
        if self.seabed_model == "elastic":
            out["seabed_stiffness"] = self.seabed.stiffness
        return out

    @property
    def total_length(self) -> float:
        """Unstretched length of the whole line [m]."""
        return float(sum(seg.length for seg in self.segments))

    @property
    def is_planar(self) -> bool:
        """True when nothing drives out-of-plane motion: the ends in one plane z = const,
        the current in the x-y plane at every height, no top motion along z."""
        return self.out_of_plane() is None

    @property
    def statics_planar(self) -> bool:
        """True when the static equilibrium lies in one vertical plane: the ends in one
        plane z = const and the current in the x-y plane (a top motion along z moves a
        planar static state out of its plane: the dynamics are 3D, the statics not)."""
        return self.out_of_plane(statics=True) is None

    def out_of_plane(self, statics: bool = False) -> tuple[str, str] | None:
        """(key, reason) of the first input that makes the scene 3D (a hang-off out of the
        anchor's plane, a current out of the x-y plane, a top motion along z; with
        ``statics``, the first that makes its static state 3D), or None for a planar
        scene."""
        e, cur = self.ends, self.current
        if isinstance(e, FixedEnds) and not e.in_plane:
            return ("ends.hang_off", f"the hang-off is at z = {e.hang_off_point[2]:g} m, the "
                    f"anchor at z = {e.anchor_point[2]:g} m: out of the anchor's plane")
        if cur is not None and not cur.is_planar:
            if cur.turns:
                return ("environment.current.headings_deg", "the current turns out of the "
                        "x-y plane (headings " + ", ".join(f"{h:g}" for h in cur.headings)
                        + " deg)")
            return ("environment.current.heading_deg", f"the current's heading "
                    f"{cur.heading_deg:g} deg is out of the x-y plane")
        tm = None if self.dynamics is None else self.dynamics.top_motion
        if tm is not None and tm.moves("z") and not statics:
            key = ("axis" if tm.one_axis else "amplitudes" if tm.is_orbit
                   else "displacements_z")
            return (f"dynamics.top_motion.{key}", "the hang-off moves along z, out of plane")
        return None if statics else sea_state_out_of_plane(self)

    def replace(self, **changes: Any) -> Scene:
        """A checked copy with some fields changed (Scene is immutable).

        A key is a field (``gravity=9.8``, ``ends=FixedEnds(...)``) or a key path into a
        part, as in the scene file (``**{"segments[2].length": 5.0}``, ``"ends.hang_off"``,
        ``"environment.current.speeds"``, ``"line_types.steel.drag_normal"``,
        ``"vfife.expert.static_damping"``): the part is rebuilt and a bad value is named
        by its key path, exactly as the file would name it."""
        new = dataclasses.replace(self, **replaced(self, changes))
        if (self._anchor_given is not None and new._anchor_given is None
                and new.ends == self.ends and new.seabed is not None):
            object.__setattr__(new, "_anchor_given", self._anchor_given)   # still put there
        return new


def require_axial_stiffness(scene: Scene, message: str) -> None:
    """Raise :class:`SceneError` naming the first line type without EA (``message`` says
    why it is needed)."""
    for name, lt in scene.line_types.items():
        if lt.axial_stiffness is None:
            raise SceneError(scene.source, f"line_types.{name}.axial_stiffness", message)

"""Shared riser model: scene files, solver settings, section properties and the result
contract of every method (the only code the methods share)."""

from .errors import SceneError, SolveFailed, UnsupportedSceneError
from .io.scene_file import load_scene, parse_scene, scene_from_dict
from .results.profile import Profile, summarize
from .results.result import DynamicsResult, SolveResult, Status
from .model.scene import (
    Current,
    Dynamics,
    Ends,
    FixedEnds,
    HangOffAngleEnds,
    InternalFlow,
    LineType,
    Scene,
    Seabed,
    Segment,
    TdpTensionEnds,
    TopMotion,
    TopTensionEnds,
)
from .model.sections import SegmentProperties, segment_properties
from .model.settings import AnalyticSettings, BVPSettings, VFIFESettings

__all__ = [
    "AnalyticSettings",
    "BVPSettings",
    "Current",
    "Dynamics",
    "DynamicsResult",
    "Ends",
    "FixedEnds",
    "HangOffAngleEnds",
    "InternalFlow",
    "LineType",
    "Profile",
    "Scene",
    "SceneError",
    "Seabed",
    "Segment",
    "SegmentProperties",
    "SolveFailed",
    "SolveResult",
    "Status",
    "TdpTensionEnds",
    "TopMotion",
    "TopTensionEnds",
    "UnsupportedSceneError",
    "VFIFESettings",
    "load_scene",
    "parse_scene",
    "scene_from_dict",
    "segment_properties",
    "summarize",
]

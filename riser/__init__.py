"""Shared riser model: scene files, solver settings, section properties and the result
contract of every method (the only code the methods share)."""

from .errors import SceneError, SolveFailed, UnsupportedSceneError
from .io.scene_file import load_scene, parse_scene, scene_from_dict
from .profile import Profile, summarize
from .result import DynamicsResult, SolveResult, Status
from .scene import Current, Dynamics, Ends, LineType, Scene, Seabed, Segment, TopMotion
from .sections import SegmentProperties, segment_properties
from .settings import BVPSettings, VFIFESettings

__all__ = [
    "SceneError", "SolveFailed", "UnsupportedSceneError", "Profile", "summarize",
    "DynamicsResult", "SolveResult", "Status", "Current", "Dynamics", "Ends", "LineType",
    "Scene", "Seabed", "Segment", "TopMotion", "load_scene", "parse_scene",
    "scene_from_dict", "SegmentProperties", "segment_properties", "BVPSettings",
    "VFIFESettings",
]

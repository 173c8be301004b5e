"""Shared riser model: scene files, section properties and the result types of both solvers."""

from .errors import SceneError, UnsupportedSceneError
from .profile import Profile, summarize
from .result import SolveResult
from .scene import (Current, Dynamics, Ends, LineType, Scene, Seabed, Segment, TopMotion,
                    load_scene, parse_scene, scene_from_dict)
from .sections import SegmentProperties, segment_properties

__all__ = [
    "SceneError", "UnsupportedSceneError", "Profile", "summarize", "SolveResult", "Current",
    "Dynamics", "Ends", "LineType", "Scene", "Seabed", "Segment", "TopMotion", "load_scene",
    "parse_scene", "scene_from_dict", "SegmentProperties", "segment_properties",
]

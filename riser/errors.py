"""Errors raised for bad input, shared by every package.

A :class:`SceneError` always carries the file name and the key path of the
offending entry, so the command line can print it as one line, e.g.::

    scene.toml: segments[2].length: must be > 0, got -5
"""

from __future__ import annotations


class SceneError(ValueError):
    """Invalid scene input: names the file, the key path and what is allowed."""

    def __init__(self, source: str, key: str, message: str):
        self.source = source
        self.key = key
        self.message = message
        super().__init__(f"{source}: {key}: {message}" if key else f"{source}: {message}")


class UnsupportedSceneError(ValueError):
    """A valid scene that a particular solver cannot handle (e.g. 3D current for the BVP)."""


class SolveFailed(RuntimeError):
    """A solve that a larger job depends on did not converge (e.g. the BVP a fixed-ends
    conversion starts from, or one method of a comparison). ``method`` names the method
    and ``status`` (a :class:`riser.result.Status`) says how it ended."""

    def __init__(self, method: str, status, message: str):
        self.method = method
        self.status = status
        super().__init__(message)

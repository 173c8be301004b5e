"""Angles as the file formats write them (MoorDyn decks, OrcaFlex text data files)."""

from __future__ import annotations

import math


def wrap_deg(deg: float) -> float:
    """An angle [deg] in (-180, 180] (never -0.0)."""
    d = math.fmod(deg, 360.0)
    if d <= -180.0:
        d += 360.0
    elif d > 180.0:
        d -= 360.0
    return d + 0.0

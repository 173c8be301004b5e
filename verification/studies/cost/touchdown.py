"""Touchdown physics of the cost study: the lengths that bound the asymptotic range of
the element-length sweep (bending boundary layer, seabed foundation length), and the
slope and curvature of the reference at its lift-off, which bound the error of a lift-off
read off a polyline."""

from __future__ import annotations

import math

import numpy as np

from riser.results.profile import Profile
from riser.model.scene import Scene
from vfife.mesh import build_mesh


def boundary_layer_length(scene: Scene, ref: Profile) -> float:
    """Length of the bending boundary layer at the touchdown [m]: sqrt(EI/T) with the
    touchdown (lift-off) tension of the BVP profile ``ref`` of ``scene`` and the EI of the
    section there (a line without touchdown: the lowest tension along the line). The
    quantities of the order fit are decided around the touchdown and the sag bend, where
    the tension is lowest and this length the longest (Wang baseline: 7.8 m; Yu A3: 27 m)."""
    EI, T = _touchdown_section(scene, ref)
    return math.sqrt(EI / max(T, 1e-9))


def foundation_length(scene: Scene, ref: Profile) -> float | None:
    """Foundation length (4 EI/k)^(1/4) [m] of the elastic seabed at the touchdown (None
    without a seabed): the length over which the grounded line settles into the seabed
    (Wang pipe on 1e5 N/m2: 4.4 m; Yu flexible pipe: 4.2 m)."""
    if scene.seabed is None or scene.seabed.stiffness <= 0.0:
        return None
    EI, _ = _touchdown_section(scene, ref)
    return (4.0 * EI / scene.seabed.stiffness) ** 0.25


def asymptotic_length(scene: Scene, ref: Profile) -> float:
    """Longest element length of the asymptotic range: the shorter of the bending boundary
    layer and the foundation length. Longer elements do not resolve the curvature of the
    touchdown, the sag bend or the contact zone, so their errors are pre-asymptotic."""
    lf = foundation_length(scene, ref)
    bl = boundary_layer_length(scene, ref)
    return min(bl, lf) if lf is not None else bl


def _touchdown_section(scene: Scene, ref: Profile) -> tuple[float, float]:
    """(EI [N m2], |T| [N]) at the touchdown of the BVP profile ``ref`` of ``scene`` (else at
    its lowest tension)."""
    mesh = build_mesh(scene, 10.0)
    mid = 0.5 * (mesh.s[1:] + mesh.s[:-1])
    if ref.tdp_s is not None:
        s0 = ref.tdp_s
    else:
        s0 = float(ref.s[int(np.argmin(np.abs(ref.tension)))])
    T = abs(float(np.interp(s0, ref.s, ref.tension)))
    return float(mesh.EI[int(np.argmin(np.abs(mid - s0)))]), T


def liftoff_interpolation(ref: Profile) -> dict | None:
    """Slope theta0 [rad] and curvature kappa0 [1/m] of the reference at its lift-off, and
    the coefficient C [m/m2] of the bound C h^2 on the error of a lift-off read off a
    polyline of nodes h apart by linear interpolation of the height (the chord of a curve
    of curvature kappa0 lies up to h^2 kappa0 / 8 off it, which moves the crossing of
    y = 0 by that over theta0). None without a lift-off."""
    if ref.tdp_s is None:
        return None
    th = abs(float(np.interp(ref.tdp_s, ref.s, ref.theta)))
    ka = float(np.interp(ref.tdp_s, ref.s, ref.curvature))
    if th <= 0.0:
        return None
    return {"theta0": th, "kappa0": ka, "coef": ka / (8.0 * th)}

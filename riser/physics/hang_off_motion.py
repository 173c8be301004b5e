"""The prescribed displacement of the hang-off [m] in time: the scene's
``[dynamics.top_motion]`` along its axis, or the vessel's motion in the waves through its
RAOs (:mod:`riser.physics.vessel`). An input every dynamic method applies as it is given (the
same path for the VFIFE, the MoorDyn peer and the frequency domain's amplitudes).

:class:`HangOffPath` does the per-scene work once (the wave components, the RAOs
interpolated per component) and is then evaluated at any times: a time-stepping loop
builds it once and calls it every interval.

Conventions: SI; (x, y, z) the scene's axes; t [s] from the start of the dynamic run.
"""

from __future__ import annotations

import math

import numpy as np


def hang_off_point(scene) -> tuple[float, float, float]:
    """(x, y, z) [m] of the scene's static hang-off (fixed ends' point, else the end
    form's (x, y) in the plane z = 0)."""
    e = scene.ends
    return e.hang_off_point if hasattr(e, "hang_off_point") else (*e.hang_off, 0.0)


def scene_components(scene):
    """The scene's wave components (:meth:`riser.physics.waves.Waves.components` in its water
    depth and gravity), phases referred to the waves' origin, by default the hang-off's
    static (x, z)."""
    x, _, z = hang_off_point(scene)
    return scene.waves.components(scene.water_depth, scene.gravity, (x, z))


def top_motion_displacement(scene, t) -> np.ndarray:
    """(3, nt) displacement [m] of the scene's top motion at times t [s] (along its axis,
    an orbit or a series per axis, :meth:`riser.physics.dynamics.TopMotion.displacement`, times
    the half-cosine ramp; zeros without one)."""
    t = np.atleast_1d(np.asarray(t, float))
    dyn = scene.dynamics
    tm = dyn.top_motion if dyn is not None else None
    if tm is None:
        return np.zeros((3, t.size))
    return tm.displacement(t) * half_cosine_ramp(t, tm.ramp)[None, :]


def axis_displacement(scene, t) -> np.ndarray:
    """The top motion's displacement d(t) [m] along its one axis at times t [s] (harmonic
    A sin(2 pi t / T) or the time series, times the half-cosine ramp; zeros without
    one). A motion along several axes has no one axis: ValueError."""
    t = np.asarray(t, float)
    dyn = scene.dynamics
    tm = dyn.top_motion if dyn is not None else None
    if tm is None:
        return np.zeros_like(t)
    if not tm.one_axis:
        raise ValueError("a motion along several axes: use top_motion_displacement")
    return top_motion_displacement(scene, t)["xyz".index(tm.axis)].reshape(t.shape)


def half_cosine_ramp(t, ramp: float) -> np.ndarray:
    """0.5 (1 - cos(pi t / ramp)) up to ``ramp`` [s], 1 after it (1 everywhere for ramp
    <= 0)."""
    t = np.asarray(t, float)
    if ramp <= 0.0:
        return np.ones_like(t)
    return 0.5 * (1.0 - np.cos(math.pi * np.minimum(t, ramp) / ramp))


def vessel_amplitudes(scene, comp=None) -> tuple[np.ndarray, np.ndarray]:
    """(omega (m,) [rad/s], complex amplitudes (3, m) [m]) of the hang-off's displacement
    for each wave component (``comp``: the scene's, :func:`scene_components`, when None):
    Re(D_j e^{i omega_j t}) summed over j is the motion without its ramp; zeros without a
    vessel. The component's phase at the RAO origin (the hang-off's static position minus
    the vessel's lever arm) sets D_j = a_j H_j e^{-i(k_j (r_o - r_0) . e_j + eps_j)}, H_j
    the (3,) hang-off RAO of :meth:`riser.physics.vessel.Vessel.hang_off_amplitudes`."""
    comp = scene_components(scene) if comp is None else comp
    vessel = scene.vessel
    if vessel is None:
        return comp.omega, np.zeros((3, comp.size), complex)
    origin = np.asarray(hang_off_point(scene), float) - vessel.lever_arm()
    dx, dz = origin[0] - comp.origin[0], origin[2] - comp.origin[1]
    phase = comp.k * (dx * np.cos(comp.heading) + dz * np.sin(comp.heading)) + comp.phase
    H = vessel.hang_off_amplitudes(2.0 * math.pi / comp.omega, np.degrees(comp.heading))
    return comp.omega, H * (comp.amplitude * np.exp(-1j * phase))[None, :]


class HangOffPath:
    """The scene's prescribed hang-off path, set up once: ``path(t)`` is the (3, nt)
    displacement [m] at times t [s]: the top motion (an axis, an orbit, a series per
    axis), or the vessel's RAO
    motion times the waves' ramp (zeros with neither)."""

    def __init__(self, scene):
        self.scene = scene
        dyn = scene.dynamics
        self.top_motion = dyn.top_motion if dyn is not None else None
        self.vessel = None
        if self.top_motion is None and scene.vessel is not None:
            self.vessel = vessel_amplitudes(scene) + (scene.waves.ramp,)

    def __call__(self, t) -> np.ndarray:
        t = np.atleast_1d(np.asarray(t, float))
        out = np.zeros((3, t.size))
        if self.top_motion is not None:
            out = top_motion_displacement(self.scene, t)
        elif self.vessel is not None:
            omega, D, ramp = self.vessel
            out = (D @ np.exp(1j * np.outer(omega, t))).real * half_cosine_ramp(t, ramp)
        return out


def hang_off_displacement(scene, t) -> np.ndarray:
    """(3, nt) displacement [m] of the hang-off at times t [s] (:class:`HangOffPath`)."""
    return HangOffPath(scene)(t)


def motion_amplitudes(axis: str, amplitude: float) -> np.ndarray:
    """The complex amplitudes (x, y, z) [m] of d(t) = A sin(omega t) along ``axis``."""
    out = np.zeros(3, complex)
    out["xyz".index(axis)] = -1j * amplitude
    return out

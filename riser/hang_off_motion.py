"""The prescribed displacement of the hang-off [m] in time: the scene's
``[dynamics.top_motion]`` along its axis, or the vessel's motion in the waves through its
RAOs (:mod:`riser.vessel`). An input every dynamic method applies as it is given (the
same path for the VFIFE, the MoorDyn peer and the frequency domain's amplitudes).

Conventions: SI; (x, y, z) the scene's axes; t [s] from the start of the dynamic run.
"""

from __future__ import annotations

import math

import numpy as np


def axis_displacement(scene, t) -> np.ndarray:
    """The top motion's displacement d(t) [m] along its axis at times t [s] (harmonic A
    sin(2 pi t / T) or the time series, times the half-cosine ramp; zeros without one)."""
    t = np.asarray(t, float)
    dyn = scene.dynamics
    tm = dyn.top_motion if dyn is not None else None
    if tm is None:
        return np.zeros_like(t)
    if tm.times is not None:
        d = np.interp(t, tm.times, tm.displacements)
    else:
        d = tm.amplitude * np.sin(2.0 * math.pi * t / tm.period)
    ramp = tm.ramp
    if ramp > 0.0:
        r = np.where(t < ramp, 0.5 * (1.0 - np.cos(math.pi * np.minimum(t, ramp) / ramp)),
                     1.0)
        d = d * r
    return d


def vessel_amplitudes(scene) -> tuple[np.ndarray, np.ndarray]:
    """(omega (m,) [rad/s], complex amplitudes (3, m) [m]) of the hang-off's displacement
    for each wave component: Re(D_j e^{i omega_j t}) summed over j is the motion without
    its ramp. The component's phase at the RAO origin (the hang-off's static position
    minus the vessel's lever arm) sets D_j = a_j H_j e^{-i(k_j (r_o - r_0) . e_j +
    eps_j)}, H_j the (3,) hang-off RAO of :meth:`riser.vessel.Vessel.hang_off_amplitudes`."""
    vessel, waves = scene.vessel, scene.waves
    hang = scene.ends.hang_off_point if hasattr(scene.ends, "hang_off_point") else None
    if hang is None:
        x, y = scene.ends.hang_off
        hang = (x, y, 0.0)
    comp = waves.components(scene.water_depth, scene.gravity, (hang[0], hang[2]))
    origin = np.asarray(hang, float) - vessel.lever_arm()
    dx, dz = origin[0] - comp.origin[0], origin[2] - comp.origin[1]
    phase = comp.k * (dx * np.cos(comp.heading) + dz * np.sin(comp.heading)) + comp.phase
    H = vessel.hang_off_amplitudes(2.0 * math.pi / comp.omega, np.degrees(comp.heading))
    return comp.omega, H * (comp.amplitude * np.exp(-1j * phase))[None, :]


def hang_off_displacement(scene, t) -> np.ndarray:
    """(3, nt) displacement [m] of the hang-off at times t [s]: the top motion along its
    axis, or the vessel's RAO motion times the waves' ramp (zeros with neither)."""
    t = np.atleast_1d(np.asarray(t, float))
    out = np.zeros((3, t.size))
    dyn = scene.dynamics
    tm = dyn.top_motion if dyn is not None else None
    if tm is not None:
        out["xyz".index(tm.axis)] = axis_displacement(scene, t)
        return out
    if scene.vessel is not None:
        omega, D = vessel_amplitudes(scene)
        e = np.exp(1j * np.outer(omega, t))                 # (m, nt)
        out = (D @ e).real
        comp_ramp = scene.waves.ramp
        if comp_ramp > 0.0:
            r = np.minimum(t, comp_ramp) / comp_ramp
            out = out * (0.5 * (1.0 - np.cos(math.pi * r)))[None, :]
    return out

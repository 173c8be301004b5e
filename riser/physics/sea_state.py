"""The rules between the waves, the vessel and the rest of a scene (called by
:class:`riser.model.scene.Scene` on construction; one-line :class:`~riser.errors.SceneError`
naming the key)."""

from __future__ import annotations

import math

import numpy as np

from .dynamics import MAX_TOP_ACCELERATION, MAX_TOP_SPEED
from .hang_off_motion import vessel_amplitudes
from .vessel import DOFS, MAX_ROTATION_DEG
from .waves import steepness_error

#: a vessel RAO table covers wave headings up to this far from its own [deg]
RAO_HEADING_REACH = 90.0
#: an irregular sea's largest motion in standard deviations of its record: 4 (the
#: significant wave height is 4 sigma, and the waves' crest check takes Hs as the most
#: probable largest crest of hours); regular trains add their amplitudes (their peak
#: when their phases meet)
SEA_PEAK_SIGMAS = 4.0


def check_sea_state(scene) -> None:
    """Waves need the surface (``water_depth``), trains below the breaking limit and
    troughs above the seabed; a vessel needs waves, no [dynamics.top_motion] beside it and
    RAO tables that cover the waves' headings."""
    waves, vessel, err = scene.waves, scene.vessel, scene.error
    if waves is not None:
        h = scene.water_depth
        if h is None:
            raise err("environment.waves", "needs environment.water_depth (the mean sea "
                      "surface the waves move about)")
        for i, tr in enumerate(waves.trains):
            why = steepness_error(tr, h, scene.gravity)
            if why is not None:
                raise err(f"environment.waves.trains[{i}].height", why)
        crest = sum(0.5 * tr.height for tr in waves.trains)
        if waves.spectrum is not None and waves.spectrum.kind != "table":
            crest += waves.spectrum.hs          # ~ the most probable largest crest of hours
        if crest >= h:
            raise err("environment.waves", f"the troughs reach the seabed: the waves' "
                      f"crest amplitude {crest:g} m (the trains' half heights, plus Hs of a "
                      f"sea) must be < water_depth = {h:g} m")
        check_wave_ramp(scene)
    if vessel is None:
        return
    if waves is None:
        raise err("vessel", "needs [environment.waves] (the vessel moves with the waves "
                  "through its RAOs)")
    if not hasattr(scene.ends, "hang_off_point"):
        raise err("vessel", "needs fixed ends ([ends] anchor + hang_off): with "
                  f"the {scene.ends.kind} form the hang-off's position is an output of the static "
                  "solve, and the RAO motion's wave phases need it before solving (give "
                  "[dynamics.top_motion] instead, or the static hang-off as ends.hang_off)")
    tm = scene.dynamics.top_motion if scene.dynamics is not None else None
    if tm is not None:
        raise err("dynamics.top_motion", "not with [vessel]: the vessel's RAOs move the "
                  "hang-off (give one or the other)")
    headings, spread = list(waves.headings), []
    sp = waves.spectrum
    if sp is not None and sp.spread:        # a spread sea: its components' own headings
        headings.pop()
        comp = waves.components(h, scene.gravity, (0.0, 0.0))
        spread = [math.degrees(b) for b, lab in zip(comp.heading, comp.labels)
                  if lab == "spectrum"]
    rel = [(hd - vessel.heading_deg) % 360.0 for hd in headings + spread]
    tabs = [t.heading_deg % 360.0 for t in vessel.raos]
    for i, (hd, r) in enumerate(zip(headings + spread, rel)):
        gap = min(min(abs(r - t), 360.0 - abs(r - t)) for t in tabs)
        if (len(tabs) == 1 and gap > 1e-9) or gap > RAO_HEADING_REACH:
            what = ("the one RAO table's heading" if len(tabs) == 1
                    else f"every RAO table's heading (> {RAO_HEADING_REACH:g} deg)")
            whose = ("the waves' heading" if i < len(headings) else
                     f"the heading of a component of the spread sea ({sp.spreading} about "
                     f"{sp.heading_deg:g} deg)")
            fmt = "g" if i < len(headings) else ".4g"
            raise err("vessel.raos", f"no RAO table for {whose} {hd:{fmt}} deg "
                      f"({r:{fmt}} deg relative to the vessel's surge axis): it differs from "
                      f"{what} ({', '.join(f'{t:g}' for t in tabs)} deg); give a table "
                      "for that heading")
    check_vessel_motion(scene)


def check_wave_ramp(scene) -> None:
    """The waves' ramp fits in a dynamic run, as a top motion's must: a given
    ``ramp_time`` <= ``duration`` (5000 s in a 40 s run applied 0.016 % of the wave). The
    default ramp (two longest periods) is not held to the duration: the frequency domain
    reads [dynamics] for its damping only, with a nominal duration."""
    waves, dyn, err = scene.waves, scene.dynamics, scene.error
    if dyn is None:
        return
    if waves.ramp_time is not None and waves.ramp_time > dyn.duration:
        raise err("environment.waves.ramp_time", f"must be <= dynamics.duration = "
                  f"{dyn.duration:g} s, got {waves.ramp_time:g} (the waves would reach "
                  f"{100.0 * _ramp_at(dyn.duration, waves.ramp_time):.2g} % of their "
                  "height by the end of the run)")


def _ramp_at(t: float, ramp: float) -> float:
    """The half-cosine ramp's factor at time t [s] of a ramp of ``ramp`` [s]."""
    return 0.5 * (1.0 - math.cos(math.pi * min(t, ramp) / ramp))


def _peak(q: np.ndarray, sea: np.ndarray) -> float:
    """The peak of a sum of harmonics of amplitudes ``q`` (m,) >= 0: the trains' sum, plus
    :data:`SEA_PEAK_SIGMAS` standard deviations of the sea's components (``sea`` (m,) bool)."""
    return float(np.sum(q[~sea]) + SEA_PEAK_SIGMAS * np.sqrt(0.5 * np.sum(q[sea] ** 2)))


def check_vessel_motion(scene) -> None:
    """The hang-off path the vessel's RAOs give in the scene's waves (trains and sea)
    passes the plausibility limits of a [dynamics.top_motion] (peak speed
    :data:`~riser.physics.dynamics.MAX_TOP_SPEED`, acceleration
    :data:`~riser.physics.dynamics.MAX_TOP_ACCELERATION`: the resultant of the axes, an upper
    bound as an orbit's) and rotates the vessel by at most :data:`MAX_ROTATION_DEG` in
    roll, pitch and yaw (the small-rotation model). Refused naming the RAO table (the
    nearest in heading to the wave component that moves the most), the DOF and the period.
    """
    vessel, err = scene.vessel, scene.error
    comp = scene.waves.components(scene.water_depth, scene.gravity, (0.0, 0.0))
    omega, D = vessel_amplitudes(scene)
    sea = np.array([lab == "spectrum" for lab in comp.labels], bool)
    periods = 2.0 * math.pi / omega
    R = vessel.complex_rao(periods, np.degrees(comp.heading))     # (6, m), rotations rad/m
    a = comp.amplitude
    arms = np.ones(6)                  # a DOF's displacement of the hang-off per unit RAO
    r = vessel.lever_arm()
    axes = vessel.axes()[[0, 2, 1]]    # surge, sway, heave axes in the scene's (x, y, z)
    for k in range(3):
        arms[3 + k] = float(np.linalg.norm(np.cross(axes[k], r)))
    norm = np.sqrt(np.sum(np.abs(D) ** 2, axis=0))
    sea_note = (f" ({SEA_PEAK_SIGMAS:g} standard deviations of the sea" + (", plus the "
                "trains' amplitudes)" if np.any(~sea) else ")")) if np.any(sea) else ""
    for k in range(3, 6):
        theta = np.degrees(np.abs(R[k]) * a)
        peak = _peak(theta, sea)
        if peak > MAX_ROTATION_DEG:
            j = int(np.argmax(theta))
            raise err(_table_key(vessel, comp, j, DOFS[k]), f"the waves rotate the vessel by "
                      f"{peak:.4g} deg in {DOFS[k]}{sea_note}, most at the period "
                      f"{periods[j]:.4g} s (RAO {math.degrees(abs(R[k, j])):.4g} deg/m): "
                      f"must be <= "
                      f"{MAX_ROTATION_DEG:g} deg, the small-rotation vessel model (d = u + "
                      "theta x r; a vessel rolls or pitches by ~2-8 deg in a survival "
                      "storm): check the RAO's unit [deg/m] and periods [s]")
    for what, n, limit, unit in (("peak speed", 1, MAX_TOP_SPEED, "m/s"),
                                 ("peak acceleration", 2, MAX_TOP_ACCELERATION, "m/s2")):
        q = omega ** n * norm
        peak = _peak(q, sea)
        if peak > limit:
            j = int(np.argmax(q))
            k = int(np.argmax(np.abs(R[:, j]) * arms))
            rao = abs(R[k, j]) if k < 3 else math.degrees(abs(R[k, j]))
            raise err(_table_key(vessel, comp, j, DOFS[k]), f"the vessel moves the hang-off "
                      f"at a {what} of {peak:.4g} {unit}{sea_note}, most of it {DOFS[k]} "
                      f"(RAO {rao:.4g} {'m/m' if k < 3 else 'deg/m'}) at the period "
                      f"{periods[j]:.4g} s: must be <= {limit:g} {unit}, the limit of a "
                      "[dynamics.top_motion] (a vessel moves its hang-off at up to ~5 m/s "
                      "and ~0.3 g in a survival storm): check the RAO's units and periods")


def _table_key(vessel, comp, j: int, dof: str) -> str:
    """``vessel.raos[i].dof`` of the RAO table nearest in heading to component ``j``."""
    rel = (math.degrees(comp.heading[j]) - vessel.heading_deg) % 360.0
    gaps = [min(abs(rel - t.heading_deg % 360.0), 360.0 - abs(rel - t.heading_deg % 360.0))
            for t in vessel.raos]
    return f"vessel.raos[{int(np.argmin(gaps))}].{dof}"


def sea_state_out_of_plane(scene) -> tuple[str, str] | None:
    """(key, reason) when the waves or the vessel's motion leave the x-y plane, else
    None (see :meth:`riser.model.scene.Scene.out_of_plane`)."""
    waves = scene.waves
    if waves is None:
        return None
    sp = waves.spectrum
    if sp is not None and sp.spread:
        return ("environment.waves.spectrum.spreading", f"the sea is short-crested "
                f"({sp.spreading} about {sp.heading_deg:g} deg): its components travel out "
                "of the x-y plane")
    if not waves.is_planar:
        return ("environment.waves", "a wave travels out of the x-y plane (headings "
                + ", ".join(f"{h:g}" for h in waves.headings) + " deg)")
    if scene.vessel is not None and scene.water_depth is not None:
        # (no depth: check_sea_state refuses the waves; the end checks may ask first)
        comp = waves.components(scene.water_depth, scene.gravity, (0.0, 0.0))
        amp = scene.vessel.hang_off_amplitudes(2.0 * math.pi / comp.omega,
                                               np.degrees(comp.heading))
        if np.any(np.abs(amp[2]) > 1e-12):
            return ("vessel", "the vessel moves the hang-off along z (sway, roll, yaw or a "
                    "lever arm out of plane)")
    return None

"""The rules between the waves, the vessel and the rest of a scene (called by
:class:`riser.scene.Scene` on construction; one-line :class:`~riser.errors.SceneError`
naming the key)."""

from __future__ import annotations

import math

import numpy as np

from .waves import steepness_error

#: a vessel RAO table covers wave headings up to this far from its own [deg]
RAO_HEADING_REACH = 90.0


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
    if vessel is None:
        return
    if waves is None:
        raise err("vessel", "needs [environment.waves] (the vessel moves with the waves "
                  "through its RAOs)")
    tm = scene.dynamics.top_motion if scene.dynamics is not None else None
    if tm is not None:
        raise err("dynamics.top_motion", "not with [vessel]: the vessel's RAOs move the "
                  "hang-off (give one or the other)")
    rel = [(hd - vessel.heading_deg) % 360.0 for hd in waves.headings]
    tabs = [t.heading_deg % 360.0 for t in vessel.raos]
    for hd, r in zip(waves.headings, rel):
        gap = min(min(abs(r - t), 360.0 - abs(r - t)) for t in tabs)
        if (len(tabs) == 1 and gap > 1e-9) or gap > RAO_HEADING_REACH:
            what = ("the one RAO table's heading" if len(tabs) == 1
                    else f"every RAO table's heading (> {RAO_HEADING_REACH:g} deg)")
            raise err("vessel.raos", f"no RAO table for the waves' heading {hd:g} deg "
                      f"({r:g} deg relative to the vessel's surge axis): it differs from "
                      f"{what} ({', '.join(f'{t:g}' for t in tabs)} deg); give a table "
                      "for that heading")


def sea_state_out_of_plane(scene) -> tuple[str, str] | None:
    """(key, reason) when the waves or the vessel's motion leave the x-y plane, else
    None (see :meth:`riser.scene.Scene.out_of_plane`)."""
    waves = scene.waves
    if waves is None:
        return None
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

"""Bending limits as a design check: the curvature utilisation along the line,
``bend_utilisation`` [-], static (profile.csv) and over a dynamic run's statistics window
(envelope.csv's ``bend_utilisation_max``).

Each line type may bend to a limit of its own (:func:`riser.model.sections.bending_limit`):

- a flexible pipe or cable with ``minimum_bend_radius`` (MBR [m], its datasheet's, for
  the condition analysed): u = kappa MBR, 1 at the bend radius 1/kappa = MBR;
- a steel wall: u = (OD/2) kappa / eps_allow, the bending strain of the outer fibre
  against the allowable bending strain eps_allow, by default the elastic limit SMYS / E
  (E from EI and the wall; SMYS the line type's ``yield_strength``, or X65 assumed for a
  wall recognised as steel without one, as the ``bending_strain`` warning does);
  ``[design] bending_strain_limit`` replaces it for every steel line type;
- a line type with both: the larger of the two (both are limits the line must keep);
- neither: 0, "no limit" (chain, rope, a line without a stated limit).

The check is post-processing of every method's results alike (run once after the solve
by the method registry, ``verification/methods.py``): the utilisation is a fixed factor
per station times |kappa| (:func:`factors`), so the largest over a dynamic run's window
is the factor times the envelope's ``curvature_max``, reached at its
``curvature_max_time``. The column exists when the scene states a limit (:func:`applies`:
a line type in use with ``minimum_bend_radius`` or ``yield_strength``, which [design]
requires); a line of no stated limit (a steel recognised by its modulus and density
alone) keeps only the named warnings of :mod:`riser.results.validity`.

summary.json: ``max_bend_utilisation`` and ``max_bend_utilisation_s`` [m] (static: the
profile's stations); a dynamic run adds ``dynamic_max_bend_utilisation``,
``dynamic_max_bend_utilisation_s`` [m] and ``dynamic_max_bend_utilisation_time`` [s].
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..model.sections import bending_limit, segment_index

#: the profile column, the envelope column and the summary keys of the check
COLUMN = "bend_utilisation"
ENVELOPE_COLUMN = "bend_utilisation_max"


def applies(scene) -> bool:
    """True when ``scene`` states a bending limit: a line type in use with
    ``minimum_bend_radius`` or ``yield_strength`` (every line type of a scene with
    [design] has one)."""
    used = {seg.line_type for seg in scene.segments}
    return any(scene.line_types[n].minimum_bend_radius is not None
               or scene.line_types[n].yield_strength is not None for n in used)


def segment_factor(lt, strain_limit: float | None = None) -> float:
    """The factor c [m] of line type ``lt`` with u = c |kappa| (see the module docstring):
    max(MBR, (OD/2) / eps_allow), 0 without a limit. ``strain_limit``: the allowable
    bending strain replacing a steel wall's elastic limit SMYS / E (None: SMYS / E)."""
    lim = bending_limit(lt)
    c = 0.0 if lim.radius is None else float(lim.radius)
    if lim.strain is not None:
        eps = lim.strain if strain_limit is None else strain_limit
        c = max(c, 0.5 * lt.outer_diameter / eps)
    return c


def factors(scene, s, lengths=None) -> np.ndarray:
    """The factor c [m] at each station ``s`` [m] (``lengths``: the segment lengths as
    solved, :func:`riser.model.sections.segment_index`) with u = c |kappa|."""
    design = scene.design
    eps = None if design is None else getattr(design, "bending_strain_limit", None)
    per_segment = np.array([segment_factor(scene.line_types[g.line_type], eps)
                            for g in scene.segments])
    return per_segment[segment_index(scene, s, lengths)]


def bend_utilisation(scene, s, curvature, lengths=None) -> np.ndarray:
    """The bend utilisation [-] at stations ``s`` [m] bent to ``curvature`` [1/m] (its
    magnitude is used): c |kappa|, 0 at a station without a limit."""
    return factors(scene, s, lengths) * np.abs(np.asarray(curvature, float))


def solved_lengths(scene, info: dict):
    """The segment lengths a method solved (a touchdown form's first segment is its
    suspended part, ``info["first_segment_suspended_length"]``), else None: the scene's."""
    first = info.get("first_segment_suspended_length")
    if first is None:
        return None
    return [float(first)] + [g.length for g in scene.segments[1:]]


def dynamic_statistics(s, u, times=None) -> dict:
    """summary.json's ``dynamic_max_bend_utilisation`` (+ ``_s`` [m], ``_time`` [s]) of an
    envelope's ``bend_utilisation_max`` ``u`` at stations ``s`` (``times``: the
    envelope's ``curvature_max_time``); {} when the window holds no sample."""
    u = np.asarray(u, float)
    if u.size == 0 or not np.any(np.isfinite(u)):
        return {}
    j = int(np.nanargmax(np.where(np.isfinite(u), u, np.nan)))
    t = None if times is None or not np.isfinite(times[j]) else float(times[j])
    return {"dynamic_max_bend_utilisation": float(u[j]),
            "dynamic_max_bend_utilisation_s": float(s[j]),
            "dynamic_max_bend_utilisation_time": t}


def with_bending(scene, result):
    """A method's :class:`riser.results.result.SolveResult` of ``scene`` with the bend
    check: the profile's ``bend_utilisation`` and, for a dynamic run, the envelope's
    ``bend_utilisation_max`` and the ``dynamic_max_bend_utilisation`` keys in ``info``
    (``result`` itself when the scene states no limit or there is no profile)."""
    if result.profile is None or not applies(scene):
        return result
    p = result.profile
    u = bend_utilisation(scene, p.s, p.curvature, solved_lengths(scene, result.info))
    changes = {"profile": p.replace(bend_utilisation=u)}
    dyn = result.dynamics
    if dyn is not None and "curvature_max" in dyn.envelope:
        env = dict(dyn.envelope)
        k = np.asarray(env["curvature_max"], float)
        ue = np.where(np.isfinite(k), bend_utilisation(scene, env["s"], np.where(
            np.isfinite(k), k, 0.0)), np.nan)
        env[ENVELOPE_COLUMN] = ue
        changes["dynamics"] = dataclasses.replace(dyn, envelope=env)
        changes["info"] = {**result.info, **dynamic_statistics(
            env["s"], ue, env.get("curvature_max_time"))}
    return result.replace(**changes)

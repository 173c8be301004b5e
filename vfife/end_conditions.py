"""The VFIFE's end conditions of a fixed-ends scene (``[ends.anchor_joint]``,
``[ends.hang_off_joint]``, ``[ends.tensioner]``; riser/model/ends.py), as the planar kernels
take them (:data:`vfife.kernels.END_SLOTS`), and the straight starting shape of the lines
the catenary start does not describe (a vertical chord, a tensioned top, a free end).

Node 0 is the anchor end, node n - 1 the hang-off. A clamped joint fixes its node's
rotation (infinite rotational inertia, the director set along the joint's direction); a
flex joint adds the moment -k (phi - phi_0) about z to its node, phi the director's angle
from +x (the kernels); a free anchor integrates node 0's translation; a tensioner
integrates the top's height under its pull top_tension - stiffness (y - y_ref), y_ref the
hang-off height moved by the prescribed heave.
"""

from __future__ import annotations

import math

import numpy as np

from riser.model.ends import FixedEnds
from riser.model.scene import Scene
from riser.model.sections import segment_properties

from .kernels import END_SLOTS


def end_array(scene: Scene) -> np.ndarray:
    """The kernels' ``ends`` array of ``scene`` (zeros: both ends pinned in place)."""
    out = np.zeros(END_SLOTS)
    e = scene.ends
    if not isinstance(e, FixedEnds):
        return out
    for j, end in enumerate(("anchor", "hang_off")):
        joint = e.joint(end)
        if joint is not None and joint.kind == "spring":
            out[2 * j] = joint.rotational_stiffness
            out[2 * j + 1] = joint.direction
    out[4] = 1.0 if e.free_anchor else 0.0
    if e.tensioner is not None:
        out[5:10] = (1.0, e.tensioner.top_tension, e.tensioner.stiffness, e.hang_off[1],
                     e.hang_off[1])
    return out


def clamped_ends(scene: Scene) -> tuple[str, ...]:
    """The clamped ends ('bottom', 'top'): ``[vfife] clamped_ends`` (the direction of the
    start) and the clamped joints (their own direction, :func:`joint_directions`)."""
    out = list(scene.vfife.clamped_ends)
    e = scene.ends
    if isinstance(e, FixedEnds):
        for end, name in (("anchor", "bottom"), ("hang_off", "top")):
            joint = e.joint(end)
            if joint is not None and joint.kind == "clamped" and name not in out:
                out.append(name)
    return tuple(out)


def joint_directions(scene: Scene, D: np.ndarray) -> np.ndarray:
    """The directors (n, 3) with the end nodes of clamped joints turned to the joints'
    directions (in the x-y plane; the scenes with joints are planar)."""
    e = scene.ends
    if not isinstance(e, FixedEnds):
        return D
    D = np.array(D, float)
    for j, end in ((0, "anchor"), (-1, "hang_off")):
        joint = e.joint(end)
        if joint is not None and joint.kind == "clamped":
            D[j] = (math.cos(joint.direction), math.sin(joint.direction), 0.0)
    return D


def needs_straight_start(scene: Scene) -> bool:
    """A scene the catenary start does not fit: a vertical chord, a tensioner, a free
    anchor."""
    e = scene.ends
    return isinstance(e, FixedEnds) and (e.tensioner is not None or e.free_anchor
                                         or e.anchor_point[0] == e.hang_off_point[0])


def straight_start(scene: Scene, s_nodes: np.ndarray):
    """(X (n, 3), D (n, 3), element tensions [N], a tension scale H [N]) of a straight
    line stretched by the tension of a vertical line, T(s) = T_0 + integral of w:
    a free anchor hangs straight down from the hang-off (T_0 = 0); a tensioned line runs
    from the anchor towards the hang-off with T at the top the tensioner's pull (its top
    where the stretched length ends); a vertical chord between fixed ends is put on the
    chord with the tension whose stretch fits it."""
    e = scene.ends
    props = segment_properties(scene)
    s = np.asarray(s_nodes, float)
    smid = 0.5 * (s[1:] + s[:-1])
    w = np.zeros_like(smid)
    ea = np.zeros_like(smid)
    for p in props:
        sel = smid >= p.s_start - 1e-9
        w[sel] = p.weight
        ea[sel] = p.EA
    dl = np.diff(s)
    below = np.concatenate([[0.0], np.cumsum(w * dl)])[:-1] + 0.5 * w * dl  # weight below
    a, h = np.asarray(e.anchor_point, float), np.asarray(e.hang_off_point, float)
    if e.free_anchor:
        T = below
    elif e.tensioner is not None:
        T = below + e.tensioner.top_tension - float(np.sum(w * dl))
    else:
        # the bottom tension whose stretch makes the line as long as the chord
        chord = float(np.linalg.norm(h - a))
        T0 = (chord - float(np.sum(dl))) / float(np.sum(dl / ea)) - float(
            np.sum(below * dl / ea)) / float(np.sum(dl / ea))
        T = below + T0
    stretched = np.concatenate([[0.0], np.cumsum(dl * (1.0 + T / ea))])
    if e.free_anchor:
        u = np.array([0.0, 1.0, 0.0])
        start = h - stretched[-1] * u
    else:
        u = (h - a) / np.linalg.norm(h - a)
        if e.tensioner is not None:           # the top at the hang-off's x: along the chord
            u = _towards(a, h, stretched[-1])
        start = a
    X = start[None, :] + stretched[:, None] * u[None, :]
    if not e.free_anchor:
        X[0] = a
    if e.tensioner is None:
        X[-1] = h
    D = np.repeat(u[None, :], len(s), axis=0)
    return X, D, T, float(max(np.max(np.abs(T)), 1.0))


def _towards(a: np.ndarray, h: np.ndarray, length: float) -> np.ndarray:
    """The unit vector from ``a`` to the point of the hang-off's x and z whose distance
    from ``a`` is ``length`` (straight up from the hang-off's horizontal offset)."""
    horiz = math.hypot(h[0] - a[0], h[2] - a[2])
    up = math.sqrt(max(length * length - horiz * horiz, 0.0))
    v = np.array([h[0] - a[0], up, h[2] - a[2]])
    return v / np.linalg.norm(v)

"""The boundary-value problem of a scene: the model on one domain, its boundary conditions,
the starting guess and the starting mesh (what ``solve_bvp`` needs, and what the profile
is built from).

The model's pieces are the scene's segments with runs of identical segments merged
(:func:`merged_runs`: a joint without a jump in any property needs no mesh pair; the
profile still has a station at every joint). Forms (``_Problem.form``; the end forms in
bvp/solver.py): ``tdp_tension``,
``hang_off_angle`` and ``top_tension`` (touchdown at the origin; in the last two the
suspended length of the first segment is the parameter p), and the fixed-ends forms
``fixed_seabed`` (rigid seabed, anchor on it: the touchdown is p), ``fixed_liftoff``
(elastic seabed, anchor on it: a contact zone [0, s_L] and the rest of the line as two
blocks joined at the lift-off point s_L = p, where y = 0), ``fixed_elastic`` (the
unilateral foundation everywhere), ``fixed_lifted`` and ``fixed_free`` (pinned ends).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from riser.model.scene import (
    FixedEnds,
    HangOffAngleEnds,
    Scene,
    TdpTensionEnds,
    TopTensionEnds,
)
from riser.model.sections import segment_properties

from . import guess as guesses
from .catenary import catenary_state, end_offsets
from .equations import IF, IM, IT, ITH, IX, IY, NSTATE, BeamModel
from .guess import BVPFailure
from .layout import Layout
from .points import GUESS_LENGTH, bending_weights, guess_arrays, split_at_points
from .output import grounded_drag


@dataclass
class _Problem:
    """Everything solve_bvp needs for one scene, plus what is needed to build the profile."""

    model: BeamModel
    bc: object
    guess_p: np.ndarray
    form: str
    anchor_xy: tuple = (0.0, 0.0)
    first_total: float = 0.0           # full length of the first segment [m]
    guess: object = None               # callable(tau) -> scaled state (6 blocks, m)
    joints: np.ndarray = None          # s [m] of the scene's joints (merged ones included)
    segments: int = 1                  # the scene's segment count
    plane: object = None               # the 3D rod's riser.model.frame.LinePlane (None: planar)

    def mesh(self, nodes: int) -> np.ndarray:
        """The starting mesh on tau (bvp.beam.layout.Layout.mesh) for ``nodes`` on the line."""
        return self.model.layout.mesh(nodes)


def build_problem(scene: Scene, split: bool = True) -> _Problem:
    """The problem of ``scene``. ``split``: on an elastic seabed with the anchor on it,
    solve the contact zone (linear spring) and the rest of the line as two blocks joined
    at an unknown lift-off point with y = 0 (see bvp/beam/equations.py)."""
    props = segment_properties(scene)
    n = len(props)
    seg = split_at_points(scene, {
        "EI": np.array([p.EI for p in props]),
        "EA": (np.array([p.EA for p in props], float) if scene.axial_model == "extensible"
               else np.full(n, np.inf)),
        "w": np.array([p.weight for p in props]),
        "L": np.array([p.length for p in props]),
        "c_n": np.array([p.drag_normal_coef for p in props]),
        "c_t": np.array([p.drag_tangential_coef for p in props])})
    EI, EA, w, L, c_n, c_t, pw, pc = (seg[k] for k in ("EI", "EA", "w", "L", "c_n", "c_t",
                                                       "point_w", "point_c"))
    ends = scene.ends
    seg_ends = np.cumsum([p.length for p in props])    # the scene's joints (and end) [m]
    first_total = float(L[0])
    # pieces: runs of identical segments merged (a joint without a jump is no joint); the
    # first segment stays alone where its length is the form's parameter; a point
    # attachment is a piece of its own
    separate_first = isinstance(ends, (HangOffAngleEnds, TopTensionEnds)) or (
        isinstance(ends, FixedEnds) and scene.seabed_model == "rigid")
    groups = merged_runs(np.stack([EI, EA, w, c_n, c_t, pw, pc, L == 0.0]), separate_first)
    heads = np.array([g[0] for g in groups])
    EI, EA, w, c_n, c_t, pw, pc = (a[heads] for a in (EI, EA, w, c_n, c_t, pw, pc))
    L = np.array([float(np.sum(L[g])) for g in groups])
    n = len(groups)
    # the starting catenary's weights and lengths: a point's piece carries its weight
    w_line, L_model = w, L
    w, L = guess_arrays(w, L, pw)
    w_bend = bending_weights(w_line, L_model) if np.any(L_model == 0.0) else None
    speed = grad = None
    if scene.current is not None:
        cur = scene.current            # its x component (in plane: heading 0 or 180 deg)
        speed = lambda y: cur.velocity(y)[0]                      # noqa: E731
        grad = lambda y: cur.velocity_gradient(y)[0]              # noqa: E731

    length_scale = float(np.sum(L_model))
    k_seabed = scene.seabed.stiffness if scene.seabed_model == "elastic" else 0.0

    # ---- catenary starting guess for each form: (H, V0, suspended lengths, origin); the
    # problem's form is the end form's kind, a fixed-ends one refined below (its boundary
    # conditions: fixed_seabed, fixed_liftoff, fixed_elastic, fixed)
    form = ends.kind
    anchor = (0.0, 0.0)
    free_first = False
    extensible = scene.axial_model == "extensible"
    cat_EA = None             # the elastic catenary between pinned ends (else inextensible)
    if isinstance(ends, TdpTensionEnds):
        H, V0, Ls = ends.tdp_tension, 0.0, L.copy()
    elif isinstance(ends, HangOffAngleEnds):
        free_first = True
        H, V0, Ls = guesses.hang_off_angle(w, L, ends.hang_off_height,
                                           math.radians(ends.hang_off_angle_deg))
    elif isinstance(ends, TopTensionEnds):
        free_first = True
        H, V0, Ls = guesses.top_tension(w, L, ends.hang_off_height, ends.top_tension)
    else:
        anchor = ends.anchor
        dx = ends.hang_off[0] - anchor[0]
        dy = ends.hang_off[1] - anchor[1]
        on_seabed = scene.seabed is not None and anchor[1] == 0.0
        # the elastic catenary between pinned ends (the grounded guess is inextensible)
        cat_EA = EA if extensible else None
        if ends.free_anchor:
            # a line hanging from its hang-off: the catenary hanging down from it (its
            # bottom end found from the top)
            form = "fixed_hanging"
            H, V0, Ls = guesses.hanging(w, L)
            ex, ey = end_offsets(w, L, H, V0, cat_EA)
            anchor = (ends.hang_off[0] - ex, ends.hang_off[1] - ey)
        elif ends.tensioner is not None or dx == 0.0:
            # a top-tensioned or vertical line: no touchdown ahead of the anchor
            form = ("fixed_elastic" if k_seabed > 0.0 else
                    "fixed_lifted" if on_seabed else "fixed_free")
            H, V0, Ls = (guesses.tensioned(w, L, dx, ends.tensioner.top_tension, cat_EA)
                         if ends.tensioner is not None else guesses.vertical(w, L, dy, cat_EA))
        else:
            form, free_first, cat_EA, (H, V0, Ls) = _pinned_form(
                w, L, dx, dy, on_seabed, k_seabed, split, cat_EA)
        if form == "fixed_seabed" and ends.joint("anchor") is not None:
            raise BVPFailure("the anchor lies on a rigid seabed with line on it ahead of "
                             "the touchdown: its joint (ends.anchor_joint) holds nothing; "
                             "give the anchor pinned or a [seabed] stiffness")

    grounded = (float(np.sum(L - Ls))
                if form in ("fixed_seabed", "fixed_elastic", "fixed_liftoff") else 0.0)
    ox = anchor[0] + grounded
    oy = anchor[1]
    cat_top_T = float(catenary_state(np.array([Ls.sum()]), w, Ls, H, V0)["tension"][0])
    Ts = max(cat_top_T, H, 1.0)
    wref = max(float(np.max(np.abs(w_line))), Ts / length_scale * 1e-3)
    EImax = float(np.max(EI))
    scale = np.array([length_scale, length_scale, 1.0, EImax * wref / Ts,
                      wref * math.sqrt(EImax / Ts), Ts])

    sink = max(float(w_line[0]), 0.0) / k_seabed if k_seabed > 0.0 else 0.0
    split_first = form == "fixed_liftoff"
    cut, zone_layout = 0, None
    if split_first:
        # block 0: the contact zone [0, s_L], segments 0 .. cut - 1 and part of segment
        # cut; block 1: the line from s_L (its first piece the rest of segment cut)
        Lm = L_model
        starts = np.concatenate([[0.0], np.cumsum(Lm)])
        cut = int(np.clip(np.searchsorted(starts, grounded, side="left") - 1, 0, n - 1))
        grounded = float(np.clip(grounded, starts[cut] + 1e-3 * Lm[cut],
                                 starts[cut + 1] - 1e-3 * Lm[cut]))   # inside segment cut
        zone_layout = Layout.proportional(np.concatenate([Lm[:cut],
                                                          [grounded - starts[cut]]]))
        start = np.concatenate([[starts[cut + 1] - grounded], Lm[cut + 1:]])
        p0 = np.array([grounded / length_scale])
    else:
        start = Ls.copy() if free_first else L_model.copy()
        p0 = np.array([Ls[0] / length_scale]) if free_first else np.zeros(0)
    model = BeamModel(EI=EI, EA=EA, w=w_line, c_n=c_n, c_t=c_t, lengths=L_model.copy(),
                      scale=scale, point_w=pw, point_c=pc,
                      k_seabed=k_seabed, speed=speed, speed_gradient=grad,
                      free_first_length=free_first or split_first, split_first=split_first,
                      length_scale=length_scale, layout=Layout.proportional(start),
                      zone_layout=zone_layout, cut=cut)
    # the line lying on the seabed ahead of the touchdown (elastic forms), sunk by w/k
    zone = (grounded, sink) if form in ("fixed_elastic", "fixed_liftoff") else (0.0, 0.0)

    def guess(tau: np.ndarray) -> np.ndarray:
        tau = np.asarray(tau, float)
        S = model.s_of(tau, p0)
        return np.concatenate([
            guesses.state_guess(s, model.segment_at(tau, b), w, Ls, EI, H, V0, ox, oy, scale,
                                *zone, EA=cat_EA, w_bend=w_bend)
            for b, s in enumerate(S)])

    return _Problem(model=model, bc=boundary_conditions(form, scene, model, L_model),
                    guess_p=p0,
                    form=form, anchor_xy=anchor, first_total=first_total, guess=guess,
                    joints=seg_ends[:-1], segments=len(seg_ends))


def _pinned_form(w, L, dx, dy, on_seabed, k_seabed, split, cat_EA):
    """(form, free_first, the guess's EA, (H, V0, Ls)) of a line between two fixed ends
    with the hang-off ahead of the anchor (dx > 0)."""
    found = None
    if on_seabed:
        try:
            found = guesses.grounded(w, L, dx, dy, anywhere=k_seabed > 0.0)
        except BVPFailure:
            pass
    if found is not None:
        Ls = found[2]
        if k_seabed > 0.0:
            # a contact zone of at least a metre ahead of the anchor, else unilateral
            # throughout
            # a point attachment (bvp/beam/points.py: a piece of GUESS_LENGTH in the guess) on
            # the grounded part: the contact zone carries no point load, its split start
            # fails (measured: a clump on the seabed of mooring-clump-weight cost minutes
            # before the unilateral form); solve the unilateral law throughout at once
            grounded_point = bool(np.any((L <= GUESS_LENGTH) & (Ls < L)))
            form = ("fixed_liftoff" if split and float(np.sum(L - Ls)) > 1.0
                    and not grounded_point else "fixed_elastic")
            return form, False, None, found
        return "fixed_seabed", True, None, found
    # no touchdown ahead of the anchor: the line may lift off at the anchor, i.e. hang
    # pinned there and rise from the seabed (checked after solving)
    form = ("fixed_elastic" if k_seabed > 0.0 else "fixed_lifted" if on_seabed
            else "fixed_free")
    return form, False, cat_EA, guesses.free_hanging(w, L, dx, dy, cat_EA)


def anchor_rotation(ends, sc):
    """The anchor's rotational condition on the scaled bottom state: M = 0 (pinned),
    theta = theta_0 (clamped) or M = k (theta - theta_0) (a flex joint; see
    :class:`riser.model.ends.EndJoint` for the sign)."""
    return _rotation(ends.joint("anchor"), sc, 0, +1.0)


def end_conditions(ends, sc, top: int):
    """(rotation, height) conditions at the hang-off on the scaled top state: the
    rotation as :func:`anchor_rotation` with M(L) = -k (theta - theta_0); the height y =
    y_h, or with a tensioner the vertical force of the line's end, P_y = T sin theta - F
    cos theta [N], equal to the tensioner's top_tension - stiffness (y - y_h)."""
    rot = _rotation(ends.joint("hang_off"), sc, top, -1.0)
    yh = ends.hang_off[1]
    t = ends.tensioner
    if t is None:
        return rot, lambda y: y[top + IY] - yh / sc[IY]

    def height(y):
        th = y[top + ITH]
        pull = y[top + IT] * sc[IT] * np.sin(th) - y[top + IF] * sc[IF] * np.cos(th)
        return (pull - t.force(y[top + IY] * sc[IY] - yh)) / sc[IT]
    return rot, height


def _rotation(joint, sc, at: int, sign: float):
    if joint is None or joint.kind == "free":     # a free end: M = 0 (its bc holds it)
        return lambda y: y[at + IM]
    th0 = joint.direction
    if joint.kind == "clamped":
        return lambda y: y[at + ITH] - th0
    k = joint.rotational_stiffness / sc[IM]
    return lambda y: y[at + IM] - sign * k * (y[at + ITH] - th0)


def merged_runs(props: np.ndarray, separate_first: bool) -> list[np.ndarray]:
    """Runs of consecutive segments whose properties (rows of ``props``: EI, EA, w, c_n,
    c_t per segment) are all equal, as arrays of segment indices; the first segment a run
    of its own with ``separate_first``."""
    runs = [[0]]
    for k in range(1, props.shape[1]):
        same = np.array_equal(props[:, k], props[:, k - 1])
        if same and not (separate_first and k == 1):
            runs[-1].append(k)
        else:
            runs.append([k])
    return [np.array(r) for r in runs]


def boundary_conditions(form: str, scene: Scene, model: BeamModel, L: np.ndarray):
    """bc(ya, yb[, p]) -> scaled residuals; ya/yb have shape (6 blocks,): the bottom end is
    block 0 at tau = 0, the top the last block at tau = 1."""
    ends = scene.ends
    sc = model.scale
    top = (model.n_block - 1) * NSTATE

    if form == "tdp_tension":
        Tt = ends.tdp_tension / sc[IT]

        def bc(ya, yb, p=None):
            return np.array([ya[IX], ya[IY], ya[ITH], ya[IM], ya[IT] - Tt, yb[top + IM]])
    elif form in ("hang_off_angle", "top_tension"):
        Hh = ends.hang_off_height / sc[IY]
        # the third condition at the top: the angle (form b) or the tension (J-lay)
        i3, v3 = ((ITH, math.radians(ends.hang_off_angle_deg)) if form == "hang_off_angle"
                  else (IT, ends.top_tension / sc[IT]))

        def bc(ya, yb, p):
            return np.array([ya[IX], ya[IY], ya[ITH], ya[IM],
                             yb[top + IM], yb[top + IY] - Hh, yb[top + i3] - v3])
    elif form == "fixed_seabed":
        xa = ends.anchor[0]
        xh = ends.hang_off[0] / sc[IX]
        L0 = float(L[0])
        rot_t, height_t = end_conditions(ends, sc, top)

        def bc(ya, yb, p):
            # touchdown at x = anchor + the stretched grounded length (L0 - suspended):
            # integral of 1 + T/EA with T = T_tdp + f_t (g - s) along the grounded part
            g = L0 - p[0] * model.length_scale
            T0 = ya[IT] * sc[IT]
            reach = g + (T0 * g + 0.5 * grounded_drag(model) * g * g) * model.inv_EA[0]
            return np.array([ya[IX] - (xa + reach) / sc[IX], ya[IY], ya[ITH], ya[IM],
                             rot_t(yb), yb[top + IX] - xh, height_t(yb)])
    elif form == "fixed_liftoff":
        xa = ends.anchor[0] / sc[IX]
        xh = ends.hang_off[0] / sc[IX]
        rot_t, height_t = end_conditions(ends, sc, top)
        rot_a = anchor_rotation(ends, sc)

        def bc(ya, yb, p):
            # anchor pinned on y = 0; the zone's end joins the line's start; y = 0 at the
            # lift-off point (the end of the contact zone)
            return np.array([ya[IX] - xa, ya[IY], rot_a(ya),
                             *(yb[:NSTATE] - ya[NSTATE:]),
                             rot_t(yb), yb[top + IX] - xh, height_t(yb), yb[IY]])
    else:
        xa, ya0 = ends.anchor[0] / sc[IX], ends.anchor[1] / sc[IY]
        xh = ends.hang_off[0] / sc[IX]
        rot_t, height_t = end_conditions(ends, sc, top)
        rot_a = anchor_rotation(ends, sc)
        if form == "fixed_hanging":
            def bc(ya, yb, p=None):
                # the free end: no force (T = F = 0), no moment
                return np.array([ya[IT], ya[IF], ya[IM],
                                 rot_t(yb), yb[top + IX] - xh, height_t(yb)])
        else:
            def bc(ya, yb, p=None):
                return np.array([ya[IX] - xa, ya[IY] - ya0, rot_a(ya),
                                 rot_t(yb), yb[top + IX] - xh, height_t(yb)])
    return bc

"""The 3D boundary-value problem of a scene: the planar problem (bvp/beam/problem.py) of the
scene in its plane's frame, lifted to the rod of bvp/rod/equations.py.

The plane's frame (riser.model.frame.LinePlane): the vertical plane through the anchor and the
hang-off, x along it from the anchor, z across it. In that frame the two ends lie in the
x-y plane, so the planar problem of the scene with its ends rotated into the plane and no
current (:func:`in_plane_scene`) gives everything the rod shares with it: the pieces, the
layout on tau, the end form, the scales, the starting catenary (lifted with z = phi =
M2 = F2 = 0) and the free-length parameter. The rod adds the current at every height in
the plane's components (a heading h is h - psi there) and its own boundary conditions,
the planar ones plus z, phi and M2 (:func:`rod_boundary_conditions`). The touchdown forms
(Wang's) have no chord: their plane is the x-y plane, with the touchdown tangent along +x.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from riser.model.frame import LinePlane
from riser.model.scene import FixedEnds, Scene

from ..beam.equations import IM, IT, ITH, IX, IY, NSTATE, BeamModel
from ..beam.problem import _Problem, build_problem
from .equations import IM2, IPH, IZ, NROD, RodModel, rod_scale


def in_plane_scene(scene: Scene) -> tuple[Scene, LinePlane]:
    """(the scene in its plane's frame with no current, the plane): fixed ends become
    (x_a, y_a) and (x_a + the horizontal distance between the ends, y_h); the touchdown
    forms are already in their plane."""
    plane = LinePlane.of(scene)
    e = scene.ends
    if isinstance(e, FixedEnds):
        (xa, ya, za), (xh, yh, zh) = e.anchor_point, e.hang_off_point
        ends = FixedEnds(anchor=(xa, ya), hang_off=(xa + math.hypot(xh - xa, zh - za), yh))
        return scene.replace(ends=ends, current=None), plane
    return scene.replace(current=None), plane


def plane_current(scene: Scene, plane: LinePlane):
    """(velocity, velocity_gradient, across): the current's components (along the plane,
    across it) [m/s] and their height gradients [1/s] at heights y [m] as callables, and
    whether any height has a component across the plane; (None, None, False) without
    a current."""
    cur = scene.current
    if cur is None:
        return None, None, False

    def velocity(y):
        return plane.vector_to_plane(*cur.velocity(y))

    def gradient(y):
        return plane.vector_to_plane(*cur.velocity_gradient(y))

    across = plane.vector_to_plane(*cur.components)[1]
    return velocity, gradient, bool(np.any(np.abs(across) > 0.0))


def build_rod_problem(scene: Scene, split: bool = True, dead_load=None) -> _Problem:
    """The 3D problem of ``scene`` (the planar problem of :func:`in_plane_scene` lifted;
    ``split`` as for :func:`bvp.beam.problem.build_problem`). ``dead_load``: a uniform load
    (qx, qy, qz) [N/m] per unstretched length in the scene's axes (closed-form checks).
    The problem's ``plane`` maps its solution back to the scene's axes."""
    flat, plane = in_plane_scene(scene)
    prob = build_problem(flat, split)
    m = prob.model
    velocity, gradient, across = plane_current(scene, plane)
    dead = None
    if dead_load is not None:
        qx, qy, qz = (float(v) for v in dead_load)
        q_xi, q_n = plane.vector_to_plane(qx, qz)
        dead = np.array([q_xi, qy, q_n])
        across = across or dead[2] != 0.0
    shared = {f.name: getattr(m, f.name) for f in dataclasses.fields(BeamModel)}
    shared.update(scale=rod_scale(m.scale), speed=None, speed_gradient=None)
    rod = RodModel(**shared, velocity=velocity, velocity_gradient=gradient, dead_load=dead,
                   cross_loads=across)
    planar_guess = prob.guess

    def guess(tau: np.ndarray) -> np.ndarray:
        return lift(planar_guess(tau), rod.n_block)

    return dataclasses.replace(prob, model=rod, guess=guess, plane=plane,
                               bc=rod_boundary_conditions(prob.form, flat, rod, m.lengths))


def lift(Y: np.ndarray, blocks: int) -> np.ndarray:
    """A planar state (6 blocks, m) as the rod's (10 blocks, m): z = phi = M2 = F2 = 0."""
    out = np.zeros((NROD * blocks, Y.shape[1]))
    for b in range(blocks):
        out[b * NROD:b * NROD + NSTATE] = Y[b * NSTATE:(b + 1) * NSTATE]
    return out


def elevation(Y: np.ndarray) -> float:
    """Angle of the rod's tangent from the horizontal [rad] of a scaled state (its first
    block): atan2(cos phi sin theta, |the horizontal part|)."""
    th, ph = Y[ITH], Y[IPH]
    return math.atan2(math.cos(ph) * math.sin(th),
                      math.hypot(math.cos(ph) * math.cos(th), math.sin(ph)))


def rod_boundary_conditions(form: str, scene: Scene, model: RodModel, L: np.ndarray):
    """bc(ya, yb[, p]) -> scaled residuals of the rod (the planar conditions of
    bvp.beam.problem.boundary_conditions, with z = 0 at the ends of the plane's frame, phi = 0
    where theta is given and M2 = 0 where M1 is); ``scene`` is the in-plane scene."""
    ends = scene.ends
    sc = model.scale
    top = (model.n_block - 1) * NROD
    free = (IX, IY, IZ, ITH, IPH, IM, IM2)            # the touchdown at the origin along +x

    if form == "tdp_tension":
        Tt = ends.tdp_tension / sc[IT]

        def bc(ya, yb, p=None):
            return np.array([*(ya[i] for i in free), ya[IT] - Tt, yb[top + IM],
                             yb[top + IM2]])
    elif form in ("hang_off_angle", "top_tension"):
        Hh = ends.hang_off_height / sc[IY]
        angle = form == "hang_off_angle"
        target = (math.radians(ends.hang_off_angle_deg) if angle
                  else ends.top_tension / sc[IT])

        def bc(ya, yb, p):
            third = (elevation(yb[top:]) if angle else yb[top + IT]) - target
            return np.array([*(ya[i] for i in free), yb[top + IM], yb[top + IM2],
                             yb[top + IY] - Hh, third])
    elif form == "fixed_seabed":
        xa = ends.anchor[0]
        xh, yh = ends.hang_off[0] / sc[IX], ends.hang_off[1] / sc[IY]
        L0 = float(L[0])
        U0 = model.grounded_velocity()

        def bc(ya, yb, p):
            # the grounded line straight from the anchor along the touchdown's heading
            # phi(0) (theta = 0 there): its stretched length with the tangential drag
            g = L0 - p[0] * model.length_scale
            T0 = ya[IT] * sc[IT]
            d = np.array([math.cos(ya[IPH]), 0.0, math.sin(ya[IPH])])
            ut = float(U0 @ d)
            f_t = float(model.c_t[0]) * abs(ut) * ut
            reach = g + (T0 * g + 0.5 * f_t * g * g) * model.inv_EA[0]
            return np.array([ya[IX] - (xa + reach * d[0]) / sc[IX], ya[IZ] - reach * d[2]
                             / sc[IZ], ya[IY], ya[ITH], ya[IM], ya[IM2], yb[top + IM],
                             yb[top + IM2], yb[top + IX] - xh, yb[top + IY] - yh,
                             yb[top + IZ]])
    elif form == "fixed_liftoff":
        xa = ends.anchor[0] / sc[IX]
        xh, yh = ends.hang_off[0] / sc[IX], ends.hang_off[1] / sc[IY]

        def bc(ya, yb, p):
            return np.array([ya[IX] - xa, ya[IY], ya[IZ], ya[IM], ya[IM2],
                             *(yb[:NROD] - ya[NROD:]),
                             yb[top + IM], yb[top + IM2], yb[top + IX] - xh,
                             yb[top + IY] - yh, yb[top + IZ], yb[IY]])
    else:
        xa, ya0 = ends.anchor[0] / sc[IX], ends.anchor[1] / sc[IY]
        xh, yh = ends.hang_off[0] / sc[IX], ends.hang_off[1] / sc[IY]

        def bc(ya, yb, p=None):
            return np.array([ya[IX] - xa, ya[IY] - ya0, ya[IZ], ya[IM], ya[IM2],
                             yb[top + IM], yb[top + IM2], yb[top + IX] - xh,
                             yb[top + IY] - yh, yb[top + IZ]])
    return bc


#: the forms whose grounded line lies straight on a rigid, frictionless seabed
RIGID_GROUNDED_FORMS = ("tdp_tension", "hang_off_angle", "top_tension")


def rigid_grounded_across(scene: Scene) -> str:
    """Why a 3D scene's rigid-seabed form cannot be solved, else '': its grounded line
    lies straight on a frictionless rigid seabed (Wang's forms, fixed ends on a rigid
    seabed with the anchor on it), which holds no load across it, so a current at the
    seabed (y = 0) out of the plane has no equilibrium there."""
    if scene.seabed_model != "rigid" or scene.current is None:
        return ""
    e = scene.ends
    if isinstance(e, FixedEnds) and e.anchor_point[1] != 0.0:
        return ""                     # hangs free from the anchor: nothing grounded
    ux, uz = (float(v) for v in scene.current.velocity(0.0))
    if math.hypot(ux, uz) == 0.0 or scene.statics_planar:
        return ""
    return ("environment.current: the current at the seabed (y = 0: "
            f"{math.hypot(ux, uz):.3g} m/s) acts on the grounded line, which the rigid, "
            "frictionless seabed of this form keeps straight and cannot hold against a "
            "load out of its plane: no equilibrium of this form; use fixed ends on the "
            "elastic seabed ([model] seabed = \"elastic\" with a [seabed])")

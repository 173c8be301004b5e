"""Starting shapes of the VFIFE's static solution (vfife/statics/equilibrium.py): the first mesh's
(the extensible catenary through the fixed ends, a straight line for a vertical,
tensioned or hanging line) and a finer mesh's (the coarser equilibrium interpolated)."""

from __future__ import annotations

import math

import numpy as np

from ..end_conditions import joint_directions, needs_straight_start, straight_start
from ..mesh import Mesh, catenary_shape, interpolate_state
from ..model import Model


def catenary_start(scene, mesh: Mesh, h: float, knobs, info: dict):
    """The first mesh's start: the extensible catenary through the fixed ends, or, when it
    is unusable (it misses the hang-off, or its buoyant part dips more than 1 % of the
    hang-off height below the seabed), the catenary of a uniform line of the mean |w|,
    whose weight is then ramped to the scene's (continuation in buoyancy; the start only,
    not the equilibrium). ``h`` [m]: the mesh's element length. Returns (X, D, element
    tensions [N], the catenary's H [N], the ramp (uniform weight [N/m], steps) or ()); the
    catenary's figures go into ``info``."""
    if needs_straight_start(scene):
        # a vertical, tensioned or free-hanging line: the straight stretched line
        X, D, tensions, H = straight_start(scene, mesh.s)
        info["start"] = "straight"
        return X, joint_directions(scene, D), tensions, H, ()
    X, D, cinfo = catenary_shape(scene, mesh.s)
    D = joint_directions(scene, D)
    span = math.dist(scene.ends.anchor_point, scene.ends.hang_off_point)
    height = max(abs(float(scene.ends.hang_off[1])), 1.0)
    ramp = ()
    if knobs.continuation_steps > 0 and (cinfo["catenary_misfit_m"] > 1e-3 * span
                                         or cinfo["catenary_below_seabed_m"] > 0.01 * height):
        # the EI = 0 start is unusable (its buoyant part dips far below the seabed, which
        # clamping onto it makes far too short, or it misses the hang-off)
        wu = float(np.sum(np.abs(mesh.weight_pl) * mesh.l0) / np.sum(mesh.l0))
        info["continuation"] = (
            f"the EI = 0 catenary start passed {cinfo['catenary_below_seabed_m']:.3g} m "
            f"below the seabed (misfit {cinfo['catenary_misfit_m']:.3g} m): started "
            f"from a uniform line of {wu:.4g} N/m and ramped the weight to the "
            f"scene's in {knobs.continuation_steps} steps on the {h:g} m mesh")
        X, D, cinfo = catenary_shape(scene, mesh.s, uniform_weight=wu)
        D = joint_directions(scene, D)
        ramp = (wu, knobs.continuation_steps)
    tensions = cinfo.pop("element_tension")
    info.update(cinfo)
    return X, D, tensions, cinfo["catenary_H"], ramp


def interpolated_start(scene, coarse: Model, mesh: Mesh):
    """A finer mesh's start: the coarser equilibrium interpolated (cubic spline in s; linear
    where the spline overshoots below the seabed), clamped ends keeping their direction.
    Returns (X, D, element tensions [N] interpolated to the new elements' midpoints)."""
    X, D = interpolate_state(coarse.mesh.s, coarse.positions(), mesh.s)
    for end in coarse.clamped:          # a clamped end keeps its direction
        j = 0 if end == "bottom" else -1
        D[j] = coarse.D[:, j]
    if scene.seabed is not None:
        # the cubic spline overshoots below the seabed around the touchdown kink (7 cm
        # from a 10 m mesh): with a stiff seabed (1e10 N/m2) that penetration launches the
        # nodes at > 1 km/s; take the linear interpolation there
        ylin = np.interp(mesh.s, coarse.mesh.s, coarse.X[1])
        X[:, 1] = np.where(X[:, 1] < 0.0, np.maximum(X[:, 1], ylin), X[:, 1])
    Nc = coarse.nodal_results()["element_tension"]
    sc_mid = 0.5 * (coarse.mesh.s[1:] + coarse.mesh.s[:-1])
    return X, D, np.interp(0.5 * (mesh.s[1:] + mesh.s[:-1]), sc_mid, Nc)

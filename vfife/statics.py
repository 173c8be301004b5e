"""Static equilibrium by dynamic relaxation with mesh sequencing.

Scheme ('catenary + coarse-to-fine dynamic relaxation'):

1. starting shape: the multi-segment extensible catenary through the fixed ends
   (:func:`vfife.mesh.catenary_shape`), laid on the seabed up to its touchdown;
2. relax it on a coarse mesh (``coarse_element_length``, default 10 m) with viscous
   mass-proportional damping;
3. interpolate (cubic spline in unstretched arc length) to the fine mesh and relax again.

Fictitious parts that do not change the equilibrium: the rotational inertia is scaled by
``rotational_inertia_scale`` (default 4, which makes the step axial-limited), no added
mass, and the damping c [1/s] is a multiple of the estimated fundamental frequency
(``STATIC_DAMPING`` x 2 omega_1, overdamped: the catenary start is already close in the
long modes, the relaxation removes the short-wave bending and seabed errors).
Converged when the largest nodal out-of-balance force (free nodes) is below
``tolerance`` x the weight of one element, and the largest nodal moment below the same
fraction of that weight x the element length.
"""

from __future__ import annotations

import math
import time

import numpy as np

from .mesh import Mesh, build_mesh, catenary_shape, interpolate_state
from .model import Model
from .timestep import choose_step, critical_steps

#: damping of the relaxation as a multiple of critical damping of the fundamental mode
STATIC_DAMPING = 10.0


def fundamental_omega(mesh: Mesh, tension: float) -> float:
    """Rough fundamental circular frequency [rad/s] of the line: taut string plus beam,
    omega_1 = pi/L sqrt(T/m) + (pi/L)^2 sqrt(EI/m) with mean m, EI and tension T."""
    L = float(np.sum(mesh.l0))
    m = float(np.sum(mesh.mass_pl * mesh.l0)) / L
    EI = float(np.sum(mesh.EI * mesh.l0)) / L
    k = math.pi / L
    return k * math.sqrt(max(tension, 0.0) / m) + k * k * math.sqrt(EI / m)


def weight_scale(mesh: Mesh) -> float:
    """One element's weight [N] for the residual scale: max |w| l0 (EA-strain-free
    fallback for weightless lines: 1e-6 EA l0/l0 = 1e-6 EA)."""
    w = float(np.max(np.abs(mesh.weight_pl * mesh.l0)))
    return w if w > 0.0 else 1e-6 * float(np.max(mesh.EA))


def relax(model: Model, dt: float, c: float, tol: float, max_steps: int,
          chunk: int = 20000, progress=None, label: str = "") -> dict:
    """Relax ``model`` to equilibrium; returns a dict (steps, residual (relative),
    moment_residual (relative), status 'converged' | 'max_steps' | 'blow-up', wall_s)."""
    wl = weight_scale(model.mesh)
    h = float(np.max(model.mesh.l0))
    tol_f = tol * wl
    tol_m = tol * wl * h
    t0 = time.perf_counter()
    done = 0
    status = "max_steps"
    res = mres = float("nan")
    while done < max_steps:
        nstep = min(chunk, max_steps - done)
        k, res, mres, ke, st = model.run(nstep, dt, c, tol_f=tol_f, tol_m=tol_m)
        done += k
        if progress is not None:
            progress(f"{label} relaxation: {done} steps, residual {res / wl:.3g} x element "
                     f"weight")
        if st == 1:
            status = "converged"
            break
        if st == 2:
            status = "blow-up"
            break
    return {"steps": done, "residual": res / wl, "moment_residual": mres / (wl * h),
            "status": status, "wall_s": time.perf_counter() - t0, "dt": dt, "damping": c}


def solve_static(scene, element_length: float, tolerance: float, planar: bool,
                 progress=None) -> tuple[Model, dict]:
    """Static equilibrium of a fixed-ends scene; returns (fine model, info dict)."""
    vf = scene.vfife
    safety = vf.get("time_step_safety", 0.8)
    rot_scale = vf.get("rotational_inertia_scale", 4.0)
    max_steps = int(vf.get("max_steps", 5_000_000))
    h_coarse = vf.get("coarse_element_length", 10.0)
    kseabed = scene.seabed.stiffness if scene.seabed is not None else 0.0
    info: dict = {"static_scheme": "catenary start, dynamic relaxation, mesh sequencing "
                  f"{h_coarse:g} m -> {element_length:g} m, viscous damping "
                  f"{STATIC_DAMPING:g} x critical of mode 1, rotational inertia x{rot_scale:g}"}
    stages = [h_coarse, element_length] if h_coarse > 1.5 * element_length else [element_length]
    model = None
    total_steps = 0
    for h in stages:
        mesh = build_mesh(scene, h)
        if model is None:
            X, D, cinfo = catenary_shape(scene, mesh.s)
            info.update(cinfo)
            tension = cinfo["catenary_H"]
        else:
            X, D = interpolate_state(model.mesh.s, model.positions(), mesh.s)
        new = Model(scene, mesh, rot_scale=rot_scale, added_mass=False, planar=planar)
        new.set_state(X, D)
        steps = critical_steps(mesh, rot_scale=rot_scale, tension=2.0 * tension,
                               seabed_stiffness=kseabed)
        dt, limit = choose_step(steps, safety)
        c = STATIC_DAMPING * 2.0 * fundamental_omega(mesh, tension)
        r = relax(new, dt, c, tolerance, max_steps - total_steps, progress=progress,
                  label=f"{h:g} m mesh")
        total_steps += r["steps"]
        info.setdefault("stages", []).append({"element_length": h, "elements": mesh.ne,
                                              "time_step": dt, "step_limit": limit,
                                              **{k: r[k] for k in ("steps", "residual",
                                                                   "status", "wall_s",
                                                                   "damping")}})
        model = new
        if r["status"] == "blow-up":
            break
        tension = float(np.mean(np.abs(model.nodal_results()["element_tension"])))
    last = info["stages"][-1]
    info.update({"steps": total_steps, "residual": last["residual"],
                 "moment_residual": r["moment_residual"], "time_step": last["time_step"],
                 "status": last["status"], "critical_steps": steps, "step_limit": last["step_limit"]})
    return model, info

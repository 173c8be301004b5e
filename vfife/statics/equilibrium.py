"""Static equilibrium by dynamic relaxation with mesh sequencing.

Scheme ('catenary + coarse-to-fine dynamic relaxation'):

1. starting shape: the multi-segment extensible catenary through the fixed ends
   (:func:`vfife.mesh.catenary_shape`), laid on the seabed up to its touchdown;
2. relax it on a coarse mesh (``coarse_element_length``, default 10 m) with viscous
   mass-proportional damping;
3. interpolate (cubic spline in unstretched arc length) to the next mesh, at most 4x
   finer (:func:`mesh_sequence`: 10 -> 4 -> 1 m, 10 -> 2 -> 0.5 m), and relax again with
   heavier mass-proportional damping; repeat down to the requested element length
   (yu2021-a2-sheared at 0.5 m: 34 s with 10 -> 0.5 m, 5.7 s with 10 -> 2 -> 0.5 m).
   Each finer mesh is solved by Newton's method instead, planar or 3D
   (:func:`newton_stage`, vfife/statics/newton.py: O(N) a mesh, the relaxation's N^2 gone), and
   relaxed only where Newton does not converge or where seabed friction is engaged (a node
   in contact with a friction coefficient: the relaxation's path-dependent equilibrium). A
   scene's friction alone does not turn Newton off: a line clear of the seabed never
   engages it (issue 44: a light cable's mid-water span over a seabed with friction 0.5
   relaxed for 5e6 steps at 0.5 m elements and did not converge; :func:`newton_applies`).

Both starting shapes are made length-consistent first (:func:`vfife.mesh.length_consistent`:
every chord exactly l0 (1 + N/EA) with the start's tension N, the hang-off kept by small
rotations of the suspended chords): sampling a curve at the nodes shortens the chords by
~(l kappa)^2/24, which costs EA x that strain of force, so a stiff line started with
1e2-1e6 element weights of out-of-balance force, and took far more than sqrt(EA) x the
steps (lazy catenary at 2.5 m, EA x100: 20x the steps of EA x1) or diverged.

Fictitious parts that do not change the equilibrium (they only scale the inertia or
vanish at rest; the out-of-balance force does not count the fictitious damping forces):

- the rotational inertia is scaled by ``rotational_inertia_scale`` (default 4, which
  makes the step axial-limited); no added mass;
- mass-proportional damping c [1/s], a multiple of the estimated fundamental frequency
  omega_1: ``static_damping`` (3) x 2 omega_1 on the coarse mesh (or a single-stage run
  from the catenary); on the fine mesh ``static_damping_fine`` (30) x 2 omega_1
  (``static_damping_current``, 10, with a current: the drag load changes with the mesh
  along the whole line) until the force residual is met, because its start, the
  interpolated coarse equilibrium, is wrong mostly in short waves, which decay at c/2;
  if the long modes still creep after four windows of the creep check, the fine stage
  goes on at the coarse damping, under which they decay at omega^2 / c (yu2021-a3 at 1 m:
  4.8e6 steps at 30 x throughout, 7.5e5 with the switch);
- convergence: force residual below the tolerance *and* the displacement still to come
  (Aitken estimate from windows of steps, see :func:`vfife.statics.relaxation.relax`) below
  ``creep_tolerance`` (1e-5) x the line length, on every stage. The force test alone
  stopped the Wang riser with a current ~1 m of touchdown travel short of its equilibrium
  (moment difference to the BVP 5.8 % instead of 2.5 %) and made results depend on the
  path (start, rounding);
- an axial dashpot per element on the elongation rate (stiffness-proportional damping of
  the axial modes, ``static_axial_damping`` = 0.1 of critical at the highest axial frequency;
  :func:`axial_dashpot`), included in the critical step (x (sqrt(1.01) - 0.1) = 0.905).
  Without it the step count does not scale with EA: the nearly undamped axial modes pile
  up the round-off of the position updates into a residual floor ~ EA^1.25 (Wang
  baseline at 1 m, EA x10: stalls at ~2e-3 element weights, never converging).

Fictitious static inertia (:func:`vfife.statics.relaxation.static_inertia`, knob
``static_fictitious_inertia``, default on): the step is the axial one of the physical
masses, and each node whose own bending/string, seabed-spring or rotational
stiffness would need a smaller step gets the larger mass or rotational inertia that makes
it stable at that step (Gershgorin row bound). Stiff pipe (hard-stiff, EI 1e9: rotation
x63, bending x4.3) converges in ~0.3e6 steps instead of failing after 5e6. The contact
damping is raised to critical (``static_contact_damping``) on every stage: undamped, a node
resting on the penalty spring can bounce without end, since the explicit step across the
contact kink feeds it energy (hard-coarse-elements, a spring resolved by ~1.6 rad per step:
1.14 element weights after 5e6 steps, now 4.3e4 steps; yu2021-a3 at 4 m with a 1e-7 creep
test, a well resolved spring: a period-10-step limit cycle of one node, stuck at 0.8
element weights for 1.5e7 steps, now 7.8e5 steps). Every stage is treated alike.

Unusable catenary start (it misses the hang-off, or its buoyant part dips more than 1 %
of the hang-off height below the seabed, e.g. 100 % buoyancy loss in one section: a
second touchdown): start from the catenary of a uniform line of the mean |w| and ramp the
weight to the scene's in ``static_weight_continuation_steps`` (10) loose relaxations on the
first mesh (continuation in buoyancy; the equilibrium is that of the full weight).

The knobs named here are the ``[vfife.expert]`` settings of the scene
(:class:`riser.model.settings.VFIFESettings`, where their defaults and ranges are written;
``creep_tolerance`` = 0 turns the creep test off, ``static_axial_damping`` = 0 the
dashpot). The relaxation takes ~sqrt(EA) steps
(the axial wave sets the step; the relaxation time is set by the damping and the
transverse modes, not by EA).
Converged when the largest nodal out-of-balance force (free nodes) is below
``tolerance`` x the weight of one element, and the largest nodal moment below the same
fraction of that weight x the element length (never below the round-off of the element
forces), with the creep test on every mesh and, on the final mesh, the tests on the
change still to come of the element tensions (``tension_tolerance``, 1e-5 of the largest)
and end moments (``moment_tolerance``, 5e-4): they bound the error of what is reported,
which the force and creep tests do not on a taut line (see :func:`vfife.statics.relaxation.relax`).
"""

from __future__ import annotations

import math

import numpy as np

from . import newton
from .knobs import RelaxationKnobs, scheme_text
from ..mesh import Mesh, build_mesh, length_consistent
from ..model import Model
from .relaxation import (
    RelaxOutcome,
    Tolerances,
    divergence_message,
    relax,
    roundoff_floor,
    static_inertia,
    weight_scale,
)
from .starts import catenary_start, interpolated_start
from ..timestep import choose_step, critical_steps, node_sum


def axial_dashpot(mesh: Mesh, zeta: float) -> np.ndarray:
    """Axial dashpot coefficients eta = beta EA/l0 [N s/m] per element (statics only).

    Stiffness-proportional damping of the axial modes, beta = 2 zeta / omega_max: damping
    ratio ``zeta`` at the highest axial (zig-zag) frequency of the mesh,
    omega_max = max_i sqrt(2 (k_l + k_r) / m_i), and zeta omega / omega_max below it.
    Why: with the mass-proportional damping alone (c/2 ~ 0.7 1/s against omega_max ~ 1e4 -
    1e5 1/s) the axial modes are almost undamped and integrate the round-off of the
    position updates (ulp(x) ~ 2e-13 m per step) into a force noise
    ~ 2 EA/l ulp(x) / sqrt(c dt) at every node, which grows like EA^1.25 and stalls the
    residual above the tolerance for stiff lines (EA x10: ~2e-3 element weights).
    The dashpot force is eta times the elongation rate: it vanishes at rest and is not
    counted in the out-of-balance force, so the equilibrium is unchanged. Its explicit
    (lagged-velocity) force lowers the axial critical step by sqrt(1 + zeta^2) - zeta
    (see :func:`vfife.timestep.critical_steps`).
    """
    if zeta <= 0.0:
        return np.zeros(mesh.ne)
    ka = mesh.EA / mesh.l0
    sa = node_sum(ka)
    om = float(np.max(np.sqrt(2.0 * sa / mesh.lump(mesh.mass_pl))))
    return 2.0 * zeta / om * ka


def fundamental_omega(mesh: Mesh, tension: float) -> float:
    """Rough fundamental circular frequency [rad/s] of the line: taut string plus beam,
    omega_1 = pi/L sqrt(T/m) + (pi/L)^2 sqrt(EI/m) with mean m, EI and tension T."""
    L = float(np.sum(mesh.l0))
    m = float(np.sum(mesh.mass_pl * mesh.l0)) / L
    EI = float(np.sum(mesh.EI * mesh.l0)) / L
    k = math.pi / L
    return k * math.sqrt(max(tension, 0.0) / m) + k * k * math.sqrt(EI / m)


def mesh_sequence(h_coarse: float, h: float, ratio: float = 4.0) -> list[float]:
    """Element lengths [m] of the mesh sequence from ``h_coarse`` down to ``h``: each mesh at
    most ``ratio`` times finer than the one before (h x ratio^k below ``h_coarse``), no
    sequence when ``h_coarse`` is within 1.5 x ``h``. Why intermediate meshes: the long
    modes of a buoyant line move between the 10 m and the 1 m equilibrium (buoyancy
    sections whose ends fall inside a coarse element), and a fine mesh creeps after
    them at omega^2 / c; on a mesh 4x coarser the same creep costs ~1/16 of the work and
    what is left for the next mesh is ~16x smaller (the O(h^2) discretisation)."""
    if h_coarse <= 1.5 * h:
        return [h]
    out = [h]
    while out[-1] * ratio < h_coarse / 1.5:
        out.append(out[-1] * ratio)
    return [h_coarse] + out[:0:-1] + [h]


def stage_model(scene, mesh: Mesh, X, D, tensions, tension: float, knobs: RelaxationKnobs,
                planar: bool, dead_load=None):
    """The model of one mesh stage, started at (X, D) made length-consistent with the
    element ``tensions`` [N] (see :func:`vfife.mesh.length_consistent`), with its axial
    dashpot, contact damping, fictitious inertia and time step. ``tension`` [N]: the
    line's representative tension (critical steps). Returns (model, dt [s], what limits
    it, the critical steps, the fictitious inertia's figures). ``dead_load``: see
    :class:`vfife.model.Model`."""
    # element lengths consistent with the tension (stretch l0 (1 + N/EA)): a stiff line
    # must not start with chord-length errors
    free = None
    if scene.seabed is not None:
        free = ~((X[:-1, 1] <= 1e-6) & (X[1:, 1] <= 1e-6))
    X = length_consistent(X, mesh.l0 * (1.0 + tensions / mesh.EA), free)
    model = Model(scene, mesh, rot_scale=knobs.rot_scale, added_mass=False, planar=planar,
                  flow="static", dead_load=dead_load)
    model.set_state(X, D)
    model.set_axial_dashpot(axial_dashpot(mesh, knobs.axial_damping))
    # critical steps of the mesh actually relaxed, with its contact spring and damping and
    # the axial dashpot
    steps = critical_steps(mesh, rot_scale=knobs.rot_scale, tension=2.0 * tension,
                           seabed_stiffness=knobs.seabed_stiffness,
                           seabed_damping=model.cseabed, axial_damping=model.eta)
    iinfo: dict = {}
    if knobs.fictitious:
        if knobs.seabed_stiffness > 0.0:
            # critical contact damping (it vanishes at rest): undamped, a node resting on
            # the penalty spring can bounce without end (module docstring); the fictitious
            # contact mass of static_inertia keeps the damped spring stable at the step
            model.seabed_zeta = max(model.seabed_zeta, min(knobs.contact_damping, 1.0))
        contact = None
        if scene.seabed is not None:
            band = 0.1 * max(abs(float(scene.ends.hang_off[1])), 1.0)
            contact = X[:, 1] < band
        dt, mass, J, iinfo = static_inertia(
            mesh, rot_scale=knobs.rot_scale, tension=2.0 * np.max(np.abs(tensions)),
            safety=knobs.safety, seabed_stiffness=knobs.seabed_stiffness,
            seabed_zeta=model.seabed_zeta, contact=contact, axial_damping=model.eta)
        limit = "axial (fictitious inertia elsewhere)"
        model.set_static_inertia(mass, J)
    else:
        dt, limit = choose_step(steps, knobs.safety)
    if knobs.fixed_time_step is not None:     # expert: fixed step (may exceed the critical)
        dt, limit = float(knobs.fixed_time_step), "user ([vfife] static_time_step)"
    return model, dt, limit, steps, iinfo


def weight_ramp(model: Model, dt: float, c: float, ramp: tuple, budget: int, label: str,
                progress=None) -> int:
    """Ramp the weight from the uniform line's to the scene's in ``ramp`` = (uniform weight
    [N/m], steps) loose relaxations at damping ``c`` [1/s]; returns the steps taken (the
    model ends with the scene's weight)."""
    w_true = model.wload.copy()
    w_uniform = model.mesh.lump(np.full(model.mesh.ne, ramp[0]))
    taken = 0
    for j in range(1, ramp[1]):
        lam = j / ramp[1]
        model.wload = (1.0 - lam) * w_uniform + lam * w_true
        rr = relax(model, dt, c, Tolerances(1e-2), max(1, budget // (4 * ramp[1])),
                   progress=progress,
                   label=f"{label}, weight ramp {lam:.2f}")
        taken += rr["steps"]
        if rr["status"] is RelaxOutcome.BLOW_UP:
            break
    model.wload = w_true
    return taken


def relax_stage(model: Model, dt: float, omega1: float, first: bool, tolerance: float,
                budget: int, knobs: RelaxationKnobs, label: str, progress=None,
                last: bool = True) -> dict:
    """Relax one mesh stage (:func:`vfife.statics.relaxation.relax`). The first stage (or a
    single-stage run from the catenary) at the coarse damping. A fine stage of a sequence:
    heavy damping until the force residual is met (the short waves of the interpolated
    start decay at c/2); if the long modes still creep after a few windows, the coarse
    damping for them (they decay at omega^2 / c): buoyancy sections whose ends fall inside
    a coarse element move the long modes on the fine mesh (yu2021-a3 at 1 m took 4.8e6
    steps at 30 x, 7.4e5 at 3 x), while short waves need the heavy damping (Wang baseline:
    3.6e4 at 30 x, 4.2e5 at 3 x; hard-stiff stalls at 1.4e-3 at 3 x).
    ``last``: the mesh whose results are reported, the only one with the tests on the
    tension and moment still to come (a coarser mesh only gives the next one its start)."""
    tol = Tolerances(tolerance, knobs.creep_tol_m if knobs.creep_tol_m > 0 else None,
                     knobs.tension_tol if (last and knobs.tension_tol > 0) else None,
                     knobs.moment_tol if (last and knobs.moment_tol > 0) else None)
    if first:
        return relax(model, dt, knobs.damping * 2.0 * omega1, tol, budget,
                     progress=progress, label=label)
    c = (knobs.damping_current if model.use_drag else knobs.damping_fine) * 2.0 * omega1
    r = relax(model, dt, c, tol, budget, progress=progress, label=label,
              creep_windows=4 if tol.windowed else None)
    if r["status"] is RelaxOutcome.CREEPING and budget > r["steps"]:
        r2 = relax(model, dt, knobs.damping * 2.0 * omega1, tol, budget - r["steps"],
                   progress=progress, label=f"{label}, long modes")
        r2["steps"] += r["steps"]
        r2["wall_s"] += r["wall_s"]
        r2["damping"] = f"{c:.3g} then {r2['damping']:.3g}"
        r = r2
    return r


def friction_engaged(scene, model: Model | None) -> bool:
    """True when seabed friction acts on ``model``'s state: the scene's seabed has a
    friction coefficient and a node of the line is in contact (y <= 0 [m], the kernels'
    penetration test: the friction force is mu times the contact force, zero above the
    seabed). Where it acts the equilibrium depends on the path (the relaxation's); None
    (no state yet): the scene's friction alone."""
    if scene.seabed is None or scene.seabed.friction <= 0.0:
        return False
    return model is None or bool(np.min(model.X[1]) <= 0.0)


def newton_applies(scene, knobs: RelaxationKnobs, model: Model | None = None) -> bool:
    """Newton's method finishes the statics (vfife/statics/newton.py): ``[vfife.expert]
    static_newton`` and no seabed friction engaged on the coarser equilibrium ``model``
    (:func:`friction_engaged`; a line clear of the seabed never feels the friction, and
    Newton's equilibrium is then exactly the relaxation's)."""
    return bool(knobs.newton and not friction_engaged(scene, model))


def newton_stage(scene, coarse: Model, h: float, tension: float, knobs: RelaxationKnobs,
                 planar: bool, dead_load, tolerance: float, info: dict, label: str = "",
                 progress=None):
    """The final mesh (``h`` [m]) started from the ``coarse`` equilibrium and finished by
    Newton's method: (model, the stage's result) when it converged (the stage appended to
    ``info``), else None (the caller relaxes the sequence). The tolerances are the
    relaxation's: ``tolerance`` x one element's load (force), x its length (moment), no
    less than the round-off floor."""
    mesh = build_mesh(scene, h)
    X, D, tensions = interpolated_start(scene, coarse, mesh)
    new, dt, limit, steps, iinfo = stage_model(scene, mesh, X, D, tensions, tension,
                                               knobs, planar, dead_load)
    wl, hmax = weight_scale(new), float(np.max(mesh.l0))
    floor_f, floor_m = roundoff_floor(new)
    if progress is not None:
        progress(f"vfife statics: {label}, Newton")
    out = newton.solve(new, max(tolerance * wl, floor_f), max(tolerance * wl * hmax, floor_m))
    if out["converged"] and friction_engaged(scene, new):
        # Newton ignores the friction (the out-of-balance force from rest has none): a
        # node it sets on the seabed would carry the relaxation's path-dependent friction
        info["newton_failed"] = (f"{label}: Newton's equilibrium touches the seabed, whose "
                                 "friction it does not model; relaxed instead")
        return None
    if not out["converged"]:
        info["newton_failed"] = (f"{label}: Newton's method stopped at {out['residual'] / wl:.3g}"
                                 f" x element weight after {out['iterations']} iterations; "
                                 "relaxed instead")
        return None
    r = {"steps": 0, "residual": out["residual"] / wl,
         "moment_residual": out["moment_residual"] / (wl * hmax), "creep_m": 0.0,
         "tension_to_come": 0.0, "moment_to_come": 0.0, "status": RelaxOutcome.CONVERGED,
         "wall_s": out["wall_s"], "damping": 0.0, **iinfo}
    info["stages"].append(
        {"element_length": h, "elements": mesh.ne, "time_step": dt, "step_limit": limit,
         "critical_steps": steps, "newton_iterations": out["iterations"],
         **{k: r[k] for k in ("steps", "residual", "status", "wall_s", "damping", "creep_m",
                              "tension_to_come", "moment_to_come")},
         **{k: r[k] for k in ("dt_axial", "mass_factor_max", "rot_factor_max") if k in r}})
    return new, r


def solve_static(scene, element_length: float, tolerance: float, planar: bool,
                 progress=None, dead_load=None) -> tuple[Model, dict]:
    """Static equilibrium of a fixed-ends scene; returns (fine model, info dict).
    ``progress``: optional callable(message), told of each mesh stage's relaxation;
    ``dead_load``: optional uniform load (qx, qy, qz) [N/m] added to the weight
    (:class:`vfife.model.Model`; the starting shape ignores it).

    Per mesh of the sequence (module docstring): its start (the catenary on the first,
    the coarser equilibrium interpolated on the next), its model and step
    (:func:`stage_model`), the weight ramp where the catenary start was unusable, and the
    relaxation (:func:`relax_stage`)."""
    knobs = RelaxationKnobs.of(scene)
    stages = mesh_sequence(knobs.coarse_element_length, element_length)
    next_damping = (knobs.damping_current if (scene.current is not None
                                              and scene.current.max_abs_speed > 0.0)
                    else knobs.damping_fine)
    info: dict = {"static_scheme": scheme_text(knobs, stages, next_damping)}
    model = None
    total_steps = 0
    tension = 0.0                     # the line's representative tension [N], per stage
    for si, h in enumerate(stages):
        label = f"{h:g} m mesh ({si + 1}/{len(stages)})"      # progress messages
        if si > 0 and newton_applies(scene, knobs, model):
            # each finer mesh from the coarser equilibrium by Newton's method: O(N) a mesh
            # (vfife/statics/newton.py); the relaxation where it does not converge, and Newton
            # again on the next mesh from that relaxed equilibrium (a flexible riser on a
            # flex joint: Newton stopped on the 4 m mesh from the 10 m one, and the 1 m
            # and 0.25 m meshes relaxed for 1.7e6 steps, 93 s; now 4 m relaxed, 1 m and
            # 0.25 m by Newton)
            fine = newton_stage(scene, model, h, tension, knobs, planar, dead_load,
                                tolerance, info, label, progress)
            if fine is not None:
                model, r = fine
                tension = float(np.mean(np.abs(model.nodal_results()["element_tension"])))
                continue
        mesh = build_mesh(scene, h)
        ramp = ()
        if model is None:
            X, D, tensions, tension, ramp = catenary_start(scene, mesh, h, knobs, info)
        else:
            X, D, tensions = interpolated_start(scene, model, mesh)
        new, dt, limit, steps, iinfo = stage_model(scene, mesh, X, D, tensions, tension,
                                                   knobs, planar, dead_load)
        # the coarse stage only provides a starting shape: at most half of the budget
        budget = knobs.max_steps - total_steps
        if si < len(stages) - 1:
            budget = max(1, budget // 2)
        om1 = fundamental_omega(mesh, tension)
        if si == 0 and ramp:
            pre = weight_ramp(new, dt, knobs.damping * 2.0 * om1, ramp, budget, label,
                              progress)
            budget = max(1, budget - pre)
            total_steps += pre
        r = relax_stage(new, dt, om1, si == 0, tolerance, budget, knobs, label, progress,
                        last=si == len(stages) - 1)
        r.update(iinfo)
        total_steps += r["steps"]
        info.setdefault("stages", []).append(
            {"element_length": h, "elements": mesh.ne, "time_step": dt, "step_limit": limit,
             "critical_steps": steps,
             **{k: r[k] for k in ("steps", "residual", "status", "wall_s", "damping",
                                  "creep_m", "tension_to_come", "moment_to_come")},
             **{k: r[k] for k in ("dt_axial", "mass_factor_max", "rot_factor_max") if k in r}})
        model = new
        if r["status"] is RelaxOutcome.BLOW_UP:
            info["diverged"] = divergence_message(scene, h, dt, limit, steps, r["steps"])
            break
        tension = float(np.mean(np.abs(model.nodal_results()["element_tension"])))

    last = info["stages"][-1]
    info.update({"steps": total_steps, "residual": last["residual"],
                 "moment_residual": r["moment_residual"], "time_step": last["time_step"],
                 "status": last["status"], "critical_steps": steps,
                 "step_limit": last["step_limit"], "creep_m": last["creep_m"],
                 "creep_tolerance_m": knobs.creep_tol_m,
                 "tension_to_come": last["tension_to_come"],
                 "moment_to_come": last["moment_to_come"],
                 "tension_tolerance": knobs.tension_tol,
                 "moment_tolerance": knobs.moment_tol})
    return model, info

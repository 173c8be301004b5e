"""Static equilibrium by dynamic relaxation with mesh sequencing.

Scheme ('catenary + coarse-to-fine dynamic relaxation'):

1. starting shape: the multi-segment extensible catenary through the fixed ends
   (:func:`vfife.mesh.catenary_shape`), laid on the seabed up to its touchdown;
2. relax it on a coarse mesh (``coarse_element_length``, default 10 m) with viscous
   mass-proportional damping;
3. interpolate (cubic spline in unstretched arc length) to the fine mesh and relax again
   with heavier mass-proportional damping.

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
  omega_1: ``STATIC_DAMPING`` (10) x 2 omega_1 on the coarse mesh (overdamped: the
  catenary start is already close in the long modes), ``STATIC_DAMPING_FINE`` (30) x
  2 omega_1 on the fine mesh (its start, the interpolated coarse equilibrium, is wrong
  mostly in short waves, which decay at c/2: Wang baseline at 1 m, 34k fine steps
  against 92k with 10 x), except with a current, where the fine mesh stays at
  ``STATIC_DAMPING``: the drag load changes with the mesh along the whole line, the
  fine stage must move long modes (decaying at omega^2 / c), and 30 x took 2.5-4x the
  steps of 10 x (Wang with currents -1.5 to +1.5 m/s at 1 m). (An adaptive c, critical
  for the motion under way from its Rayleigh quotient, was tried and dropped: it stops on a
  zero crossing of an underdamped long mode, 2-4 m from the equilibrium on
  yu2021-a2-sheared, with the force residual below the tolerance);
- an axial dashpot per element on the elongation rate (stiffness-proportional damping of
  the axial modes, ``AXIAL_DAMPING`` = 0.1 of critical at the highest axial frequency;
  :func:`axial_dashpot`), included in the critical step (x (sqrt(1.01) - 0.1) = 0.905).
  Without it the step count does not scale with EA: the nearly undamped axial modes pile
  up the round-off of the position updates into a residual floor ~ EA^1.25 (Wang
  baseline at 1 m, EA x10: stalls at ~2e-3 element weights, never converging).

Fictitious static inertia (:func:`vfife.relaxation.static_inertia`, knob
``static_fictitious_inertia``, default on): the step is the axial one of the physical
masses, and each node whose own bending/string, seabed-spring (final mesh) or rotational
stiffness would need a smaller step gets the larger mass or rotational inertia that makes
it stable at that step (Gershgorin row bound). Stiff pipe (hard-stiff, EI 1e9: rotation
x63, bending x4.3) converges in 0.68e6 steps instead of failing after 5e6. Where the
seabed spring alone would limit the step on the final mesh (long elements: 20 m), the
contact damping is raised to critical (``static_contact_damping``): a node resting on a
penalty spring resolved by ~1.6 rad per step bounced without end (hard-coarse-elements:
1.14 element weights after 5e6 steps; now 4.3e4 steps). Coarse stages of a sequence keep
the seabed-limited step (their result is only a start).

Unusable catenary start (it misses the hang-off, or its buoyant part dips more than 1 %
of the hang-off height below the seabed, e.g. 100 % buoyancy loss in one section: a
second touchdown): start from the catenary of a uniform line of the mean |w| and ramp the
weight to the scene's in ``static_weight_continuation_steps`` (10) loose relaxations on the
first mesh (continuation in buoyancy; the equilibrium is that of the full weight).
A kinetic-damping driver (``static_relaxation = "kinetic"``, :mod:`vfife.relaxation`) is
available but not the default: with the global kinetic energy, the high-frequency content
of the start triggers a reset every ~3 steps and the relaxation stalls.

Programmatic knobs (``scene.vfife`` entries, not in the scene file schema):
``static_damping``, ``static_damping_fine``, ``static_axial_damping`` (0 turns the
dashpot off). The relaxation takes ~sqrt(EA) steps (the axial wave sets the step; the
relaxation time is set by the damping and the transverse modes, not by EA).
Converged when the largest nodal out-of-balance force (free nodes) is below
``tolerance`` x the weight of one element, and the largest nodal moment below the same
fraction of that weight x the element length.
"""

from __future__ import annotations

import math
import time

import numpy as np

from .mesh import Mesh, build_mesh, catenary_shape, interpolate_state, length_consistent
from .model import Model
from .relaxation import static_inertia
from .timestep import choose_step, critical_steps

#: damping of the relaxation as a multiple of critical damping of the fundamental mode
STATIC_DAMPING = 10.0
#: ... starting value on the fine mesh of a mesh sequence
STATIC_DAMPING_FINE = 30.0
#: contact damping ratio of the seabed spring in statics (at least; the scene's if higher)
STATIC_CONTACT_DAMPING = 1.0
#: steps of the continuation in weight/buoyancy used when the catenary start is unusable
WEIGHT_CONTINUATION_STEPS = 10
#: damping ratio of the axial dashpot at the highest axial frequency of the mesh (statics)
AXIAL_DAMPING = 0.1


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
    sa = np.zeros(mesh.n)
    sa[:-1] += ka
    sa[1:] += ka
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
        if st == 2 or not (np.all(np.isfinite(model.X)) and np.all(np.isfinite(model.D))):
            status = "blow-up"
            break
    return {"steps": done, "residual": res / wl, "moment_residual": mres / (wl * h),
            "status": status, "wall_s": time.perf_counter() - t0, "dt": dt, "damping": c}


def relax_kinetic(model: Model, dt: float, tol: float, max_steps: int, chunk: int = 20000,
                  progress=None, label: str = "") -> dict:
    """Relax ``model`` with kinetic damping (:meth:`Model.run_kinetic`); returns the dict of
    :func:`relax` plus the number of kinetic-energy resets."""
    wl = weight_scale(model.mesh)
    h = float(np.max(model.mesh.l0))
    tol_f = tol * wl
    tol_m = tol * wl * h
    t0 = time.perf_counter()
    done = 0
    resets = 0
    status = "max_steps"
    res = mres = float("nan")
    while done < max_steps:
        nstep = min(chunk, max_steps - done)
        k, res, mres, ke, st, nr, _, _, gap = model.run_kinetic(nstep, dt, tol_f=tol_f,
                                                                 tol_m=tol_m)
        done += k
        resets += nr
        if progress is not None:
            progress(f"{label} relaxation: {done} steps, residual {res / wl:.3g} x element "
                     f"weight, {resets} kinetic-energy resets")
        if st == 1:
            status = "converged"
            break
        if st == 2 or not (np.all(np.isfinite(model.X)) and np.all(np.isfinite(model.D))):
            status = "blow-up"
            break
    return {"steps": done, "residual": res / wl, "moment_residual": mres / (wl * h),
            "status": status, "wall_s": time.perf_counter() - t0, "dt": dt, "damping": 0.0,
            "resets": resets}


def divergence_message(scene, h: float, dt: float, limit: str, steps: dict,
                       nstep: int) -> str:
    """Message for a relaxation that diverged (NaN/inf or runaway speeds), naming the
    likely cause from the step and the critical steps of the mesh being relaxed."""
    crit = min(steps.values())
    name = min(steps, key=steps.get)
    head = (f"static relaxation diverged (NaN/inf or runaway speed) after {nstep} steps on "
            f"the {h:g} m mesh with time step {dt:.3g} s (critical: {name} {crit:.3g} s)")
    if dt > crit:
        if limit.startswith("user"):
            cause = (f"the fixed [vfife] static_time_step {dt:.3g} s is {dt / crit:.3g} x the "
                     f"critical step; remove it or use <= {0.8 * crit:.3g} s")
        else:
            cause = ("[vfife] time_step_safety too high for the critical-step estimate; "
                     "lower it")
    elif "seabed" in steps and steps["seabed"] <= 1.05 * crit:
        cause = (f"the seabed contact (stiffness {scene.seabed.stiffness:.3g} N/m2, damping "
                 f"{scene.seabed.damping:g} of critical) limits the step; lower "
                 "[vfife] time_step_safety or the seabed stiffness")
    else:
        cause = ("an impossible or badly started geometry (line much longer or shorter than "
                 "the span, a slack line buckling); check the ends and segment lengths, or "
                 "lower [vfife] time_step_safety")
    return f"{head}; likely cause: {cause}"


def solve_static(scene, element_length: float, tolerance: float, planar: bool,
                 progress=None) -> tuple[Model, dict]:
    """Static equilibrium of a fixed-ends scene; returns (fine model, info dict)."""
    vf = scene.vfife
    safety = vf.get("time_step_safety", 0.8)
    rot_scale = vf.get("rotational_inertia_scale", 4.0)
    max_steps = int(vf.get("max_steps", 5_000_000))
    h_coarse = vf.get("coarse_element_length", 10.0)
    zeta_a = float(vf.get("static_axial_damping", AXIAL_DAMPING))
    cfac = float(vf.get("static_damping", STATIC_DAMPING))
    cfac_fine = float(vf.get("static_damping_fine", STATIC_DAMPING_FINE))
    scheme = str(vf.get("static_relaxation", "viscous"))
    fictitious = bool(vf.get("static_fictitious_inertia", True))
    zeta_c = float(vf.get("static_contact_damping", STATIC_CONTACT_DAMPING))
    cont_steps = int(vf.get("static_weight_continuation_steps", WEIGHT_CONTINUATION_STEPS))

    kseabed = scene.seabed.stiffness if scene.seabed is not None else 0.0
    stages = [h_coarse, element_length] if h_coarse > 1.5 * element_length else [element_length]
    damp = (f"{cfac:g} x ({h_coarse:g} m), {cfac_fine:g} x ({element_length:g} m)"
            if len(stages) > 1 else f"{cfac:g} x")
    if scene.current is not None and scene.current.max_abs_speed > 0.0:
        damp = f"{cfac:g} x (with a current)"
    damp += " critical of mode 1"
    info: dict = {"static_scheme": "catenary start, dynamic relaxation, mesh sequencing "
                  f"{h_coarse:g} m -> {element_length:g} m, viscous mass-proportional damping "
                  f"{damp}, axial dashpot {zeta_a:g} x critical at the "
                  f"highest axial frequency (stiffness-proportional), rotational inertia "
                  f"x{rot_scale:g}"
                  + (", fictitious nodal masses and rotational inertias where the bending, "
                     "rotation or seabed spring would limit the step below the axial one "
                     "(contact damping 1 x critical on a final mesh where the seabed spring "
                     "would)" if fictitious else "")
                  + (", kinetic damping" if scheme == "kinetic" else "")
                  + ", length-consistent starting shapes; fictitious inertia "
                  "and damping only, the equilibrium and the out-of-balance force "
                  "(fictitious damping not counted) are unchanged"}
    fixed_dt = vf.get("static_time_step")
    model = None
    total_steps = 0
    for si, h in enumerate(stages):
        mesh = build_mesh(scene, h)
        if model is None:
            X, D, cinfo = catenary_shape(scene, mesh.s)
            span = float(np.hypot(*(np.asarray(scene.ends.hang_off, float)
                                    - np.asarray(scene.ends.anchor, float))))
            height = max(abs(float(scene.ends.hang_off[1])), 1.0)
            ramp = ()
            if cont_steps > 0 and (cinfo["catenary_misfit_m"] > 1e-3 * span
                                   or cinfo["catenary_below_seabed_m"] > 0.01 * height):
                # the EI = 0 start is unusable (its buoyant part dips far below the seabed,
                # which clamping onto it makes far too short, or it misses the hang-off):
                # start from the catenary of a uniform line and ramp the weight to the
                # scene's (continuation in buoyancy; the start only, not the equilibrium)
                wu = float(np.sum(np.abs(mesh.weight_pl) * mesh.l0) / np.sum(mesh.l0))
                info["continuation"] = (
                    f"the EI = 0 catenary start passed {cinfo['catenary_below_seabed_m']:.3g} m "
                    f"below the seabed (misfit {cinfo['catenary_misfit_m']:.3g} m): started "
                    f"from a uniform line of {wu:.4g} N/m and ramped the weight to the "
                    f"scene's in {cont_steps} steps on the {h:g} m mesh")
                X, D, cinfo = catenary_shape(scene, mesh.s, uniform_weight=wu)
                ramp = (wu, cont_steps)
            Ne = cinfo.pop("element_tension")
            info.update(cinfo)
            tension = cinfo["catenary_H"]
        else:
            X, D = interpolate_state(model.mesh.s, model.positions(), mesh.s)
            for end in model.clamped:          # a clamped end keeps its direction
                j = 0 if end == "bottom" else -1
                D[j] = model.D[:, j]
            if scene.seabed is not None:
                # the cubic spline overshoots below the seabed around the touchdown kink
                # (7 cm from a 10 m mesh): with a stiff seabed (1e10 N/m2) that penetration
                # launches the nodes at > 1 km/s; take the linear interpolation there
                ylin = np.interp(mesh.s, model.mesh.s, model.X[1])
                X[:, 1] = np.where(X[:, 1] < 0.0, np.maximum(X[:, 1], ylin), X[:, 1])
            Nc = model.nodal_results()["element_tension"]
            sc_mid = 0.5 * (model.mesh.s[1:] + model.mesh.s[:-1])
            Ne = np.interp(0.5 * (mesh.s[1:] + mesh.s[:-1]), sc_mid, Nc)
        # element lengths consistent with the tension (stretch l0 (1 + N/EA)): a stiff line
        # must not start with chord-length errors (see :func:`length_consistent`)
        free = None
        if scene.seabed is not None:
            free = ~((X[:-1, 1] <= 1e-6) & (X[1:, 1] <= 1e-6))
        X = length_consistent(X, mesh.l0 * (1.0 + Ne / mesh.EA), free)
        new = Model(scene, mesh, rot_scale=rot_scale, added_mass=False, planar=planar)
        new.set_state(X, D)
        new.set_axial_dashpot(axial_dashpot(mesh, zeta_a))
        # critical steps of the mesh actually relaxed, with its contact spring and damping
        # and the axial dashpot
        steps = critical_steps(mesh, rot_scale=rot_scale, tension=2.0 * tension,
                               seabed_stiffness=kseabed, seabed_damping=new.cseabed,
                               axial_damping=new.eta)
        # the coarse stage only provides a starting shape: at most half of the budget
        budget = max_steps - total_steps
        if si < len(stages) - 1:
            budget = max(1, budget // 2)
        iinfo: dict = {}
        last = si == len(stages) - 1
        # step of the contact spring alone (physical mass), against the axial step
        spring_step = (float(np.min(2.0 / np.sqrt(kseabed * mesh.trib / mesh.lump(mesh.mass_pl))))
                       if kseabed > 0.0 else math.inf)
        if fictitious and last and spring_step < steps["axial"]:
            # the contact spring would set the step (long elements on a stiff seabed): the
            # contact nodes get fictitious mass instead, and contact damping, because a
            # node resting on a penalty spring resolved by ~1 step per radian bounces
            # without end (hard-coarse-elements, 20 m: 1.14 element weights after 5e6
            # steps); it vanishes at rest
            new.seabed_zeta = max(new.seabed_zeta, min(zeta_c, 1.0))
        if fictitious:
            contact = None
            if scene.seabed is not None:
                band = 0.1 * max(abs(float(scene.ends.hang_off[1])), 1.0)
                contact = X[:, 1] < band
            dt, mass, J, iinfo = static_inertia(
                mesh, rot_scale=rot_scale, tension=2.0 * np.max(np.abs(Ne)), safety=safety,
                seabed_stiffness=kseabed if last else 0.0, seabed_zeta=new.seabed_zeta,
                contact=contact, axial_damping=new.eta)
            limit = "axial (fictitious inertia elsewhere)"
            if not last and "seabed" in steps:
                # coarse stage of a sequence: the seabed still sets the step as before (its
                # result is only a start; kept so the stored 1 m equilibria do not move)
                dt = min(dt, safety * steps["seabed"])
            new.set_static_inertia(mass, J)
        else:
            dt, limit = choose_step(steps, safety)
        if fixed_dt is not None:              # expert: fixed step (may exceed the critical)
            dt, limit = float(fixed_dt), "user ([vfife] static_time_step)"
        if si == 0 and ramp:
            wl_true = new.wload.copy()
            wl_uni = mesh.lump(np.full(mesh.ne, ramp[0]))
            pre = 0
            for j in range(1, ramp[1]):
                lam = j / ramp[1]
                new.wload = (1.0 - lam) * wl_uni + lam * wl_true
                cf = cfac * 2.0 * fundamental_omega(mesh, tension)
                rr = relax(new, dt, cf, 1e-2, max(1, budget // (4 * ramp[1])),
                           label=f"{h:g} m mesh, weight ramp {lam:.2f}")
                pre += rr["steps"]
                if rr["status"] == "blow-up":
                    break
            new.wload = wl_true
            budget = max(1, budget - pre)
            total_steps += pre
        if scheme == "kinetic":
            r = relax_kinetic(new, dt, tolerance, budget, progress=progress,
                              label=f"{h:g} m mesh")
        else:
            # a single-stage run (no coarse mesh) starts from the catenary: coarse damping
            cf = cfac_fine if si > 0 and not new.use_drag else cfac
            c = cf * 2.0 * fundamental_omega(mesh, tension)
            r = relax(new, dt, c, tolerance, budget, progress=progress, label=f"{h:g} m mesh")
        r.update(iinfo)
        total_steps += r["steps"]
        info.setdefault("stages", []).append({"element_length": h, "elements": mesh.ne,
                                              "time_step": dt, "step_limit": limit,
                                              "critical_steps": steps,
                                              **{k: r[k] for k in ("steps", "residual",
                                                                   "status", "wall_s",
                                                                   "damping")},
                                              **{k: r[k] for k in ("resets", "dt_axial",
                                                                   "mass_factor_max",
                                                                   "rot_factor_max")
                                                 if k in r}})
        model = new
        if r["status"] == "blow-up":
            info["diverged"] = divergence_message(scene, h, dt, limit, steps, r["steps"])
            break
        tension = float(np.mean(np.abs(model.nodal_results()["element_tension"])))
    last = info["stages"][-1]
    info.update({"steps": total_steps, "residual": last["residual"],
                 "moment_residual": r["moment_residual"], "time_step": last["time_step"],
                 "status": last["status"], "critical_steps": steps,
                 "step_limit": last["step_limit"]})
    return model, info

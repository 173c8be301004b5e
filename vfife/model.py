"""Thin state layer around the kernels: arrays of one mesh, the active effects, stepping.

A :class:`Model` holds the nodal state (3D arrays always; a planar scene is stepped by
the planar kernels on 2D copies, see :meth:`Model.run`), the lumped nodal properties and
the flags of the active effects, so that a scene without current does no drag work, a
current that does not turn with height no work on its z component, a static run no
added-mass work, a run without a dead load no dead-load work, and a planar scene no
out-of-plane work.
"""

from __future__ import annotations

import math

import numpy as np

from riser.physics.internal_flow import contents_mass_per_length
from riser.model.scene import Scene

from . import kernels
from .end_conditions import clamped_ends, end_array
from .flow import flow_arrays
from .mesh import Mesh
from .recovery import Recovery
from .dynamics.waves import WaveLoads

#: largest contact damping ratio used by the explicit step (scene values above are clamped)
MAX_CONTACT_ZETA = 1.0


class Model:
    """Arrays for the kernels, component-major: ``X, V, D, W`` are (3, n) (see
    :mod:`vfife.kernels`); :meth:`positions` and :meth:`directors` give (n, 3) copies.

    Parameters
    ----------
    scene, mesh : the fixed-ends scene and its mesh.
    rot_scale : factor on the physical rotational inertia (statics: a fictitious inertia
        that does not change the equilibrium; dynamics: as the scene says, default 1).
    added_mass : include the added mass normal to the axis (dynamics only).
    planar : step with the planar kernels (the scene has nothing out of plane).
    drag : run the Morison drag kernel. None (statics): only with a current of non-zero
        speed; the dynamics passes True whenever the line types have drag coefficients (a
        line moving through still water feels drag on its own velocity).
    surface : model the sea surface at ``water_depth`` (dynamics; needs a water depth):
        the part of a node's segment above it carries its weight in air, with no
        buoyancy, drag or added mass (see :func:`vfife.kernels.node_pass`).
    flow : the scene's [internal_flow] (see :mod:`vfife.flow`): 'dynamic' runs the flow
        pass every step (masses, weights, gradient and Coriolis forces at the model's
        ``time`` [s]); 'static' freezes a slug's weight at t = 0 and runs no flow kernel;
        None ignores the flow.
    dead_load : optional (qx, qy, qz) [N/m per unit unstretched length, global axes]: a
        uniform load of fixed direction added to the weight (which acts along -y), lumped
        to the nodes by their tributary lengths (``P`` (3, n) [N]); none (None or all
        zero) runs no dead-load work. It does not follow the line's shape (unlike drag),
        so a line under it has a closed form (tests). A z component needs ``planar``
        False.
    waves : load the line with the scene's waves (dynamics; :mod:`vfife.dynamics.waves`), when the
        scene has waves with ``line_loads``; otherwise no wave kernel runs.
    """

    def __init__(self, scene: Scene, mesh: Mesh, *, rot_scale: float, added_mass: bool,
                 planar: bool, drag: bool | None = None, surface: bool = False,
                 flow: str | None = None, dead_load=None, waves: bool = False):
        self.scene = scene
        self.mesh = mesh
        self.planar = planar
        n, ne = mesh.n, mesh.ne
        self.X = np.zeros((3, n))
        self.V = np.zeros((3, n))
        self.D = np.zeros((3, n))
        self.D[0] = 1.0
        self.W = np.zeros((3, n))
        self.l0 = mesh.l0.copy()
        self.kax = mesh.EA / mesh.l0
        self.kb = mesh.EI / mesh.l0
        # the point attachments: their mass and (isotropic, dynamics) added mass on their
        # nodes' inertia, their net weight on the nodes' weight
        mass_air = mesh.lump(mesh.mass_pl) + mesh.point_mass
        self.mass = mass_air + (mesh.point_added if added_mass else 0.0)
        self.madd = mesh.lump(mesh.added_pl) if added_mass else np.zeros(n)
        self.im = 1.0 / (self.mass + self.madd)
        self.imd = 1.0 / self.mass - self.im
        self.clamped = clamped_ends(scene)
        self.ends = end_array(scene)
        self._set_rotational_inertia(rot_scale * mesh.lump(mesh.rot_pl))
        self.wload = mesh.lump(mesh.weight_pl) + mesh.point_weight
        self.trib = mesh.trib
        self.cdn = mesh.lump(mesh.cdn_pl)
        self.cdt = mesh.lump(mesh.cdt_pl)
        self.cdp = mesh.point_drag.copy()
        self.use_points = bool(np.any(self.cdp > 0.0))
        cur = scene.current
        self.has_current = bool(cur is not None and cur.max_abs_speed > 0.0)
        self.use_drag = self.has_current if drag is None else bool(
            drag and (np.any(self.cdn > 0.0) or np.any(self.cdt > 0.0)
                      or np.any(self.cdp > 0.0)))
        # a current that turns with height: its x components along cdir = e_x (U) and its
        # z components (Uz), each interpolated in height (vfife.kernels.run); one heading:
        # the signed speed along it, Uz = 0
        self.turning = bool(cur is not None and cur.turns)
        self.speeds_z = np.zeros(1)
        if cur is None:
            self.heights = np.zeros(1)
            self.speeds = np.zeros(1)
            self.cdir = np.array([1.0, 0.0, 0.0])
        elif self.turning:
            self.heights = np.asarray(cur.heights, float)
            ux, uz = cur.components
            self.speeds = np.asarray(ux, float)
            self.speeds_z = np.asarray(uz, float)
            self.cdir = np.array([1.0, 0.0, 0.0])
        else:
            self.heights = np.asarray(cur.heights, float)
            self.speeds = np.asarray(cur.speeds, float)
            self.cdir = np.asarray(cur.direction, float)
        # current profile slopes (d speed / d height) for the branch-free lookup
        self.slopes = _slopes(self.heights, self.speeds)
        self.slopes_z = _slopes(self.heights, self.speeds_z) if self.turning else np.zeros(1)
        self.U = np.zeros(n)
        self.Uz = np.zeros(n)
        self._set_dead_load(dead_load)
        self.R = np.zeros((2, n))       # scratch: squared nodal residuals
        sb = scene.seabed
        self.use_seabed = sb is not None
        self.kseabed = sb.stiffness if sb is not None else 0.0
        self.kst = self.kseabed * self.trib         # seabed spring per node [N/m]
        self.mu = sb.friction if sb is not None else 0.0
        # contact damping: a fraction zeta of critical for the contact spring, clamped at
        # critical (MAX_CONTACT_ZETA): the explicit damping force shortens the stable step
        # by sqrt(1 + zeta^2) - zeta (0.41 at zeta = 1, 0.05 at the scene limit 10) and
        # more than critical damping only slows the contact down
        zeta = min(sb.damping, MAX_CONTACT_ZETA) if sb is not None else 0.0
        self.seabed_zeta = zeta
        self.cseabed = 2.0 * zeta * np.sqrt(self.kseabed * self.trib * (self.mass + self.madd))
        self.vfric = 0.01          # [m/s] Coulomb friction regularisation speed
        self.use_surface = bool(surface and scene.water_depth is not None)
        # the surface's height at each node [m] (the mean level; with waves the kernels
        # take the instantaneous one, vfife.dynamics.waves)
        self.ysurf = np.full(n, float(scene.water_depth) if self.use_surface else math.inf)
        self.wair = scene.gravity * mass_air   # weight in air [N] (pipe + contents, points)
        self.iair = 1.0 / self.mass
        self.dnode = _node_diameters(scene, mesh)
        k = 2 if planar else 3
        self.F = np.zeros((k, ne))
        self.MA = np.zeros((k - 1 if planar else 3, ne))
        self.MB = np.zeros_like(self.MA)
        # axial dashpot per element [N s/m] (statics only, see vfife.statics.equilibrium; zero and not
        # run unless set with :meth:`set_axial_dashpot`)
        self.eta = np.zeros(ne)
        self.use_dashpot = False
        # the dynamics' internal axial damping (BA, :meth:`set_axial_damping`): its force
        # is part of the axial force the results report (the statics' dashpot is not)
        self.damped_tension = False
        self.Q = np.zeros((k, ne))
        self.steps = 0
        self._recovery: Recovery | None = None
        self.time = 0.0                 # [s] the flow's clock (dynamics)
        self._set_flow(flow)
        wv = scene.waves
        self.use_waves = bool(waves and wv is not None and wv.line_loads)
        self.waves = WaveLoads(scene, mesh) if self.use_waves else None
        # full-size placeholders without waves, as FL and P: the vectorised node passes
        # guard their SIMD loops with runtime overlap checks over every array they may
        # read, sized by the node count; with a (7, 1) placeholder the checks' outcome,
        # so the loop taken (SIMD or scalar, which round differently), could depend on
        # where the heap put it
        n = mesh.n
        self.WT = self.waves.WT if self.use_waves else np.zeros((21, n))
        self.WV = self.waves.WV if self.use_waves else np.zeros((7, n))
        self.cin = self.waves.cin if self.use_waves else np.zeros((2, n))
        self.PW = np.zeros((3, n))

    def _set_flow(self, mode: str | None) -> None:
        """Arrays of the internal-flow pass (see :mod:`vfife.flow`)."""
        fl = self.scene.internal_flow
        self.FL = np.zeros((6, self.mesh.n))
        self.flow_mode = mode if fl is not None else None
        self.use_flow = fl is not None and mode == "dynamic"
        self.has_slug = fl is not None and fl.has_slug and mode is not None
        self.fpar, self.fnodes = (flow_arrays(self.scene, self.mesh, self.mass, self.wload)
                                  if self.use_flow else (np.zeros(5), np.zeros((5, 1))))
        if self.has_slug and mode == "static":     # the slug's weight frozen at t = 0
            mu0 = contents_mass_per_length(self.scene)
            mu = mu0 * fl.density_factor(self.mesh.s, 0.0)
            self.wload = self.wload + (mu - mu0) * self.trib * self.scene.gravity

    def _set_dead_load(self, dead_load) -> None:
        """The nodal dead load ``P`` (3, n) [N] of a uniform load (qx, qy, qz) [N/m]."""
        self.dead_load = checked_dead_load(dead_load)
        self.P = np.zeros((3, self.mesh.n))
        if self.dead_load is not None:
            if self.planar and self.dead_load[2] != 0.0:
                raise ValueError("dead_load: a z component needs the 3D kernels "
                                 "(planar=False)")
            self.P = np.outer(self.dead_load, self.trib)
        self.use_dead = self.dead_load is not None

    def set_axial_dashpot(self, eta) -> None:
        """Axial dashpot coefficients [N s/m] per element (scalar or (ne,)); all zero turns
        the dashpot pass off."""
        self.eta = np.broadcast_to(np.asarray(eta, float), self.l0.shape).copy()
        self.use_dashpot = bool(np.any(self.eta > 0.0))

    def set_axial_damping(self) -> None:
        """The line types' internal axial damping BA [N s] (Kelvin-Voigt, dynamics): the
        dashpot eta = BA / l0 [N s/m] per element on the elongation rate, so the axial force
        is EA eps + BA d(eps)/dt with eps = l / l0 - 1; its force is then part of the
        tension of :meth:`nodal_results`."""
        self.set_axial_dashpot(self.mesh.BA / self.mesh.l0)
        self.damped_tension = self.use_dashpot

    def _set_rotational_inertia(self, jrot) -> None:
        """Nodal rotational inertias [kg m2] and their inverses used by the kernels.
        Clamped ends ([vfife] clamped_ends) do not rotate: infinite rotational inertia
        (jinv = 0); the director keeps the direction it has in the state the model is
        given (see :meth:`set_state` and docs/scene-files.md, Solver settings)."""
        self.jrot = np.asarray(jrot, float).copy()
        self.jinv = 1.0 / self.jrot
        for end in self.clamped:
            self.jinv[0 if end == "bottom" else -1] = 0.0

    def set_static_inertia(self, mass, jrot) -> None:
        """Fictitious nodal masses [kg] and rotational inertias [kg m2] (statics only, see
        :func:`vfife.statics.relaxation.static_inertia`): isotropic (no added mass), the contact
        damping re-scaled so that its damping ratio stays the scene's."""
        self.mass = np.asarray(mass, float).copy()
        self.madd = np.zeros(self.mesh.n)
        self.im = 1.0 / self.mass
        self.imd = np.zeros(self.mesh.n)
        self._set_rotational_inertia(jrot)
        self.cseabed = 2.0 * self.seabed_zeta * np.sqrt(self.kseabed * self.trib * self.mass)

    # -------------------------------------------------------------- effects
    @property
    def effects(self) -> list[str]:
        out = ["weight", "axial", "bending"]
        if self.use_seabed:
            out.append("seabed")
            if self.mu > 0.0:
                out.append("seabed_friction")
        if self.use_drag:
            out.append("current_drag" if self.has_current else "drag")
        if self.use_surface:
            out.append("sea_surface")
        if self.flow_mode is not None:       # a steady flow in statics: no force (Fylling)
            out.append("slug_flow" if self.has_slug else "internal_flow")
        if np.any(self.madd > 0.0):
            out.append("added_mass")
        if self.use_dead:
            out.append("dead_load")
        if self.use_waves:
            out.append("waves")
        return out

    def positions(self) -> np.ndarray:
        return self.X.T.copy()

    def directors(self) -> np.ndarray:
        return self.D.T.copy()

    def set_state(self, X: np.ndarray, D: np.ndarray) -> None:
        """Positions and directors from (n, 3) arrays; velocities zero."""
        self.X[:] = np.asarray(X, float).T
        Dn = np.asarray(D, float) / np.linalg.norm(D, axis=1)[:, None]
        self.D[:] = Dn.T
        self.V[:] = 0.0
        self.W[:] = 0.0

    # -------------------------------------------------------------- the kernel's groups
    def kernel_groups(self, top0: np.ndarray, top_disp: np.ndarray) -> tuple:
        """The arrays of :func:`vfife.kernels.run` in its groups (State, Line, Sea, Effects,
        Scratch, Flow, Ends), built on each call from the attributes (an attribute may be
        replaced between calls: a mesh sequence, a relaxation's inertia, the waves on)."""
        K = kernels
        return (K.State(self.X, self.V, self.D, self.W),
                K.Line(self.l0, self.kax, self.kb, self.mass, self.im, self.imd, self.jinv,
                       self.jrot, self.wload, self.kst, self.eta, self.wair, self.iair,
                       self.madd, self.trib, self.dnode, self.cin, self.cdn, self.cdt,
                       self.cdp),
                K.Sea(self.heights, self.speeds, self.slopes,
                      self.cdir[:2].copy() if self.planar else self.cdir, self.speeds_z,
                      self.slopes_z, self.cdir, self.cseabed, self.mu, self.vfric,
                      self.ysurf, self.WT, self.P),
                K.Effects(self.use_drag, self.turning, self.use_dashpot, self.use_surface,
                          self.use_flow, self.use_dead, self.use_waves, self.use_points),
                K.Scratch(self.F, self.MA, self.MB, self.U, self.Uz, self.R, self.Q, self.FL,
                          self.WV, self.PW),
                K.Flow(self.time, self.fpar, self.fnodes),
                K.Ends(self.ends, top0, top_disp))

    # -------------------------------------------------------------- stepping
    def run(self, nsteps: int, dt: float, c: float, *, top_disp: np.ndarray | None = None,
            top0: np.ndarray | None = None, tol_f: float = -1.0, tol_m: float = -1.0,
            vmax: float = 1.0e3):
        """Advance up to ``nsteps`` steps of ``dt`` [s] with damping ``c`` [1/s]; the
        hang-off follows ``top0 + top_disp[:, k]`` (top_disp (3, nsteps + 1) [m]; default:
        stays put). With waves, the kinematics' Taylor coefficients must have been set at
        the start of the call (:meth:`vfife.dynamics.waves.WaveLoads.evaluate`).
        Returns (steps, force residual [N], moment residual [N m], kinetic energy [J],
        status 0 done / 1 converged / 2 blow-up)."""
        if top_disp is None:
            top_disp = np.zeros((3, nsteps + 1))
        top0 = self.X[:, -1].copy() if top0 is None else np.asarray(top0, float)
        out = kernels.run(nsteps, self.planar, *self.kernel_groups(top0, top_disp), dt, c,
                          tol_f, tol_m, vmax)
        self.steps += int(out[0])
        if self.use_flow:
            self.time += int(out[0]) * dt
        return out

    # -------------------------------------------------------------- results
    def element_state(self):
        """(N [N], Ma, Mb (3, ne) [N m], Q [N], l [m], S (3, ne) [N]) of the current state
        (:func:`vfife.kernels.element_state`)."""
        return kernels.element_state(self.X, self.D, self.l0, self.kax, self.kb)

    @property
    def recovery(self) -> Recovery:
        """The element-to-node map of the nodal results (:mod:`vfife.recovery`), built once
        per model."""
        if self._recovery is None:
            self._recovery = Recovery(self.mesh)
        return self._recovery

    def nodal_results(self) -> dict:
        """Tension [N], moment [N m], shear [N] and curvature [1/m] at the nodes, the
        moment vector (``moment_vector``, (3, n) [N m], global x, y, z: the end moment of the
        elements on the node, -EI t x t', so minus the signed in-plane bending of a planar
        line is its z component) and the element tensions
        (``element_tension``, (ne,)).

        Second order at every node (:mod:`vfife.recovery`): the element tension and shear
        vector belong to the element midpoint and are interpolated to an ordinary node,
        extrapolated from each side to a joint (where the weight or the section changes)
        and from the end elements to an end. Nodal moment = mean of the end moments of the
        two elements meeting there (they balance in equilibrium); curvature = moment / EI,
        the larger side's at a joint (min EI). With the internal axial damping
        (:meth:`set_axial_damping`) the tension holds its force BA d(eps)/dt.
        """
        N, Ma, Mb, Q, L, S = self.element_state()
        if self.damped_tension:        # + BA d(eps)/dt = eta e . (v_b - v_a)
            dX = self.X[:, 1:] - self.X[:, :-1]
            N = N + self.eta * np.sum(dX * (self.V[:, 1:] - self.V[:, :-1]), axis=0) / L
        n = self.mesh.n
        rec = self.recovery
        M = np.zeros((3, n))
        cnt = np.zeros(n)
        M[:, :-1] += Ma
        M[:, 1:] -= Mb         # the end-b moment acts with the opposite sense on the node
        cnt[:-1] += 1
        cnt[1:] += 1
        M /= cnt
        mom = np.linalg.norm(M, axis=0)
        EI_n = np.full(n, np.inf)
        EI_n[:-1] = self.mesh.EI
        EI_n[1:] = np.minimum(EI_n[1:], self.mesh.EI)
        shear = np.linalg.norm(rec.vectors(S), axis=0)
        return {"tension": rec.scalar(N), "moment": mom, "shear": shear,
                "curvature": mom / EI_n, "element_tension": N, "moment_vector": M}

    def energy(self) -> dict:
        """Kinetic, strain and gravity energies [J] of the current state (numpy, for tests;
        'gravity' holds the dead load's potential -P.X too)."""
        N, Ma, Mb, Q, L, _ = self.element_state()
        V, D, W = self.V.T, self.D.T, self.W.T
        ke = 0.5 * np.sum(self.mass[:, None] * V ** 2)
        if np.any(self.madd > 0):
            vn = V - np.sum(V * D, axis=1)[:, None] * D
            ke += 0.5 * np.sum(self.madd[:, None] * vn ** 2)
        ke += 0.5 * np.sum(self.jrot[:, None] * W ** 2)
        ua = 0.5 * np.sum(self.kax * (L - self.l0) ** 2)
        X = self.X.T
        e = (X[1:] - X[:-1]) / L[:, None]
        pa = np.cross(e, D[:-1])
        pb = np.cross(e, D[1:])
        ub = np.sum(self.kb * (2 * np.sum(pa * pa, 1) + 2 * np.sum(pa * pb, 1)
                               + 2 * np.sum(pb * pb, 1)))
        ug = np.sum(self.wload * X[:, 1]) - np.sum(self.P * self.X)
        return {"kinetic": float(ke), "axial": float(ua), "bending": float(ub),
                "gravity": float(ug), "total": float(ke + ua + ub + ug)}


def checked_dead_load(dead_load) -> tuple[float, float, float] | None:
    """A dead load (qx, qy, qz) [N/m] as three floats, None for none (None or all zero);
    ValueError unless three finite numbers."""
    if dead_load is None:
        return None
    q = np.asarray(dead_load, float)
    if q.shape != (3,) or not np.all(np.isfinite(q)):
        raise ValueError(f"dead_load: (qx, qy, qz) [N/m], three finite numbers, got "
                         f"{dead_load!r}")
    return tuple(float(v) for v in q) if np.any(q != 0.0) else None


def _slopes(heights: np.ndarray, values: np.ndarray) -> np.ndarray:
    """d value / d height [1/s] of each interval of a current profile (one entry, 0, for a
    single height), for the branch-free lookup of :func:`vfife.kernels.current_pass`."""
    return np.diff(values) / np.diff(heights) if len(heights) > 1 else np.zeros(1)


def _node_diameters(scene: Scene, mesh: Mesh) -> np.ndarray:
    """Outer diameter [m] at the nodes (a joint node takes the larger of its segments')."""
    ends = np.cumsum([seg.length for seg in scene.segments])
    d = np.array([scene.line_types[seg.line_type].outer_diameter for seg in scene.segments])
    lo = np.clip(np.searchsorted(ends, mesh.s, side="left"), 0, len(d) - 1)
    hi = np.clip(np.searchsorted(ends, mesh.s, side="right"), 0, len(d) - 1)
    return np.maximum(d[lo], d[hi])


def max_speed_hint(scene: Scene) -> float:
    """Largest current speed [m/s] plus a top-motion speed bound (for the drag step)."""
    v = scene.current.max_abs_speed if scene.current is not None else 0.0
    dyn = scene.dynamics
    if dyn is not None and dyn.top_motion is not None:
        v += dyn.top_motion.peak_speed        # harmonic 2 pi A / T, a series' steepest
    return v

"""The BVP's own linear wave kinematics and the wave forcing of its frequency domain
(:mod:`bvp.frequency.harmonic`, :mod:`bvp.frequency.sea_response`): the fluid velocity and acceleration of
each Airy component on the static line, the Morison inertia coefficient of the line, the
hang-off motion a vessel gives each component, and the refusal of a sea whose troughs
uncover the line.

Independent code: this module reads only the wave *inputs* of :mod:`riser.physics.waves` (the
components: amplitude, omega, k, phase, heading, origin, depth) and computes its own
kinematics (the VFIFE has its own, as the principle of independent methods asks).

Conventions (SI units; :mod:`riser.physics.waves`, :mod:`riser.results.response`): y up from the seabed,
the mean surface at y = h (``water_depth``); a component's elevation is
Re(A(x, z) e^{i omega t}) with the complex amplitude

    A(x, z) = a e^{-i (k xi + eps)},   xi = (x - x0) cos(beta) + (z - z0) sin(beta)

(beta the heading, the direction of travel; (x0, z0) the waves' origin; eps the phase
lag). Linear (Airy) theory in water of depth h gives the complex amplitudes of the
fluid velocity

    u_h = omega cosh(k y) / sinh(k h) A       along (cos beta, 0, sin beta)
    u_y = i omega sinh(k y) / sinh(k h) A     (a quarter period ahead: u_y = d eta/dt at
                                                the surface)

and the acceleration i omega u. The ratios are written as (e^{k (y - h)} +- e^{-k (y +
h)}) / (1 - e^{-2 k h}): no overflow at large k h, and the deep-water limit e^{k (y - h)}
exactly. A point above the mean level takes the mean level's value (the frequency domain
has its line wholly submerged: :func:`require_submerged`).

On the static line (tangent t = (cos theta, sin theta, 0), in-plane normal n = (-sin
theta, cos theta, 0), z out of plane) the flow's components are u_n = u . n, u_t = u . t,
u_z, and likewise the acceleration. The Morison inertia per unstretched length acts
normal to the line only: (1 + C_a) rho (pi D^2 / 4) times the normal acceleration
(Froude-Krylov plus added mass; D the hydrodynamic diameter, C_a the added-mass
coefficient, as the added mass m_a of :mod:`bvp.modal.equations`: ``rho pi D^2/4 +
m_a``). The tangential Froude-Krylov force is left out (a slender line).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.interpolate import CubicSpline

from riser.errors import SceneError, UnsupportedSceneError
from riser.physics.hang_off_motion import scene_components, vessel_amplitudes
from riser.results.profile import Profile
from riser.results.response import harmonic_motion_vector
from riser.model.scene import Scene
from riser.model.sections import segment_properties
from riser.physics.waves import WaveComponents

#: tolerance of the submergence check [m]
SUBMERGENCE_SLACK = 1e-9


# ------------------------------------------------------------------ the kinematics
def depth_ratios(k: float, y, depth: float) -> tuple[np.ndarray, np.ndarray]:
    """(cosh(k y) / sinh(k h), sinh(k y) / sinh(k h)) at heights y [m] (clipped to [0,
    h]) for the wave number k [1/m] and depth h [m], written overflow-free."""
    y = np.clip(np.asarray(y, float), 0.0, depth)
    den = -math.expm1(-2.0 * k * depth)
    up = np.exp(k * (y - depth))
    down = np.exp(-k * (y + depth))
    return (up + down) / den, (up - down) / den


def elevation_amplitude(comp: WaveComponents, j: int, x, z) -> np.ndarray:
    """Complex elevation amplitude A [m] of component j at horizontal points (x, z) [m]
    (see the module docstring)."""
    b = comp.heading[j]
    xi = ((np.asarray(x, float) - comp.origin[0]) * math.cos(b)
          + (np.asarray(z, float) - comp.origin[1]) * math.sin(b))
    return comp.amplitude[j] * np.exp(-1j * (comp.k[j] * xi + comp.phase[j]))


def kinematics(comp: WaveComponents, j: int, x, y, z) -> tuple[np.ndarray, np.ndarray]:
    """(velocity [m/s], acceleration [m/s2]) of component j, each (3, m) complex
    amplitudes along x, y, z, at the points (x, y, z) [m] (arrays of m)."""
    A = elevation_amplitude(comp, j, x, z)
    w, b = comp.omega[j], comp.heading[j]
    ch, sh = depth_ratios(comp.k[j], y, comp.depth)
    uh = w * ch * A
    u = np.stack([uh * math.cos(b), 1j * w * sh * A, uh * math.sin(b)])
    return u, 1j * w * u


# ------------------------------------------------------------------ the static line
def line_points(profile: Profile):
    """A function s -> (x, z) [m] of the static line (cubic splines of the profile over
    the unstretched arc length; near-duplicate nodes at segment joints thinned)."""
    s = profile.s
    keep = np.concatenate([[True], np.diff(s) > 1e-9])
    sx = CubicSpline(s[keep], profile.x[keep])
    sz = CubicSpline(s[keep], profile.z[keep])
    return lambda q: (sx(q), sz(q))


def inertia_coefficients(scene: Scene) -> list[tuple[float, float, float, float]]:
    """Per segment (s_start, s_end [m], (1 + C_a) rho A, rho A [kg/m]), A = pi D^2 / 4 of
    the hydrodynamic diameter (:func:`riser.model.sections.segment_properties`' fluid and added
    masses): the fluid inertia coefficients per unstretched length normal to the line (the
    Froude-Krylov force plus the added mass) and along it (the Froude-Krylov force of the
    axial pressure gradient alone: a line has no axial added mass)."""
    return [(p.s_start, p.s_end, p.fluid_mass + p.added_mass, p.fluid_mass)
            for p in segment_properties(scene)]


class LineFlow:
    """The flow of one wave component on the static line, at arc lengths chosen later
    (:meth:`at`): built once per static state."""

    def __init__(self, scene: Scene, profile: Profile, comp: WaveComponents, j: int):
        self.comp, self.j = comp, j
        self.points = line_points(profile)
        self.segments = inertia_coefficients(scene)

    def inertia(self, s: np.ndarray, which: int = 2) -> np.ndarray:
        """(1 + C_a) rho A (``which`` 2, normal) or rho A (3, tangential) [kg/m] at arc
        lengths s."""
        out = np.empty(s.size)
        for row in self.segments:
            a, b = row[0], row[1]
            out[(s >= a - 1e-9) & (s <= b + 1e-9)] = row[which]
        return out

    def at(self, s: np.ndarray, theta: np.ndarray, y: np.ndarray, j: int | None = None) -> dict:
        """The flow's complex amplitudes at arc lengths s [m] of the static line of
        tangent angle theta [rad] and height y [m] (the caller's static fields): normal,
        tangential and z velocity ``un``, ``ut``, ``uz`` [m/s], normal, tangential and z
        acceleration ``an``, ``at``, ``az`` [m/s2], and the inertia coefficients
        ``inertia`` (normal) and ``inertia_t`` (tangential) [kg/m]; ``j``: another
        component than the flow's own."""
        x, z = self.points(s)
        u, acc = kinematics(self.comp, self.j if j is None else j, x, y, z)
        c, sn = np.cos(theta), np.sin(theta)
        return {"un": -sn * u[0] + c * u[1], "ut": c * u[0] + sn * u[1], "uz": u[2],
                "an": -sn * acc[0] + c * acc[1], "at": c * acc[0] + sn * acc[1],
                "az": acc[2], "inertia": self.inertia(s), "inertia_t": self.inertia(s, 3)}

    def at_frame(self, s: np.ndarray, y: np.ndarray, frame, plane) -> dict:
        """The flow's complex amplitudes on a 3D static line (:mod:`bvp.frequency.
        rod_harmonic`) at arc lengths s [m] and heights y [m]: the velocity's components
        ``ut``, ``u1``, ``u2`` [m/s] and the acceleration's ``at``, ``a1``, ``a2`` [m/s2]
        along the rod's frame ``frame`` = (t, n1, n2), each (3, m) in the axes of
        ``plane`` (riser.model.frame.LinePlane: x along the plane, y up, z across it; the
        kinematics, in the scene's axes, are turned into them by the plane's
        ``vector_to_plane``), and the inertia coefficients ``inertia`` (normal) and
        ``inertia_t`` (tangential) [kg/m]. At a planar state (n2 = e_z, the plane the x-y
        plane) u1, u2, ut are :meth:`at`'s un, uz, ut."""
        x, z = self.points(s)
        u, acc = kinematics(self.comp, self.j, x, y, z)
        out = {"inertia": self.inertia(s), "inertia_t": self.inertia(s, 3)}
        for name, v in (("u", u), ("a", acc)):
            along, across = plane.vector_to_plane(v[0], v[2])
            w = (along, v[1], across)
            for key, e in zip(("t", "1", "2"), frame):
                out[name + key] = e[0] * w[0] + e[1] * w[1] + e[2] * w[2]
        return out


# ------------------------------------------------------------------ the scene's waves
def trough(comp: WaveComponents) -> float:
    """The depth [m] below the mean level the troughs reach: the regular trains'
    amplitudes summed, plus Hs = 4 sqrt(m0) of an irregular sea's components (the most
    probable largest trough of a few hours ~ Hs, as riser.physics.sea_state takes the crest)."""
    sea = np.array([lab == "spectrum" for lab in comp.labels], bool)
    if sea.size != comp.size:
        sea = np.zeros(comp.size, bool)
    m0 = 0.5 * float(np.sum(comp.amplitude[sea] ** 2))
    return float(np.sum(comp.amplitude[~sea])) + 4.0 * math.sqrt(m0)


def require_submerged(scene: Scene, comp: WaveComponents, top: float, what: str) -> None:
    """UnsupportedSceneError (one line) when the troughs (:func:`trough`) reach below the
    height ``top`` [m] of the line's highest point (``what`` names it): the frequency
    domain has the line wholly in the water."""
    h, d = scene.water_depth, trough(comp)
    if top > h - d + SUBMERGENCE_SLACK:
        raise UnsupportedSceneError(
            f"{scene.source}: environment.waves: the troughs reach y = {h - d:g} m (water "
            f"depth {h:g} m less {d:g} m), below {what} at y = {top:g} m: the frequency "
            "domain has the line wholly in the water (lower the waves or the line)")


def regular_wave(scene: Scene, profile: Profile | None = None, s=None, theta=None, y=None):
    """The scene's single regular train (no spectrum; UnsupportedSceneError otherwise):
    (period [s], hang-off motion (3,) complex [m], flow) where flow is the
    :class:`LineFlow` of the train on ``profile`` (None without a profile or when
    ``line_loads`` is false), evaluated at arc lengths ``s`` (with the static tangent
    angle ``theta`` and height ``y`` there) when those are given."""
    waves = scene.waves
    if waves is None or len(waves.trains) != 1 or waves.spectrum is not None:
        raise UnsupportedSceneError(
            f"{scene.source}: environment.waves: the harmonic response solves one regular "
            "train (give exactly one [[environment.waves.trains]] and no spectrum; an "
            "irregular sea: bvp.frequency.sea_response.solve_sea)")
    comp = scene_components(scene)
    period = float(waves.trains[0].period)
    motion = vessel_amplitudes(scene, comp)[1][:, 0]
    flow = None
    if profile is not None and waves.line_loads:
        flow = LineFlow(scene, profile, comp, 0)
        if s is not None:
            flow = flow.at(np.asarray(s, float), np.asarray(theta, float),
                           np.asarray(y, float))
    return period, motion, flow


def drive(scene: Scene, period, motion):
    """What drives a harmonic response (:func:`bvp.frequency.harmonic.solve_harmonic`): (period [s],
    hang-off motion (3,) complex [m], the wave's components or None). A given ``motion``
    is the hang-off's alone (period: the given one, else the scene's single train's, else
    its top motion's); without one, the scene's single regular train (its vessel motion
    plus a harmonic top motion of the same period) or else its top motion.
    UnsupportedSceneError for what the scene lacks; ValueError for a ``period`` other
    than the train's."""
    waves = scene.waves
    if motion is not None:
        if period is None and waves is not None and len(waves.trains) == 1 \
                and waves.spectrum is None:
            period = waves.trains[0].period
        elif period is None:
            period = top_motion(scene)[1]
        return period, np.asarray(motion, complex).reshape(3), None
    if waves is None:
        vector, own = top_motion(scene)
        return (own if period is None else period), vector, None
    own, motion, _ = regular_wave(scene)
    if period is not None and abs(period - own) > 1e-12 * own:
        raise ValueError(f"period {period:g} s: the scene's wave train has {own:g} s (give "
                         "no period, or a motion to solve another)")
    tm = scene.dynamics.top_motion if scene.dynamics is not None else None
    if tm is not None:
        vector, tm_period = top_motion(scene)
        if abs(tm_period - own) > 1e-12 * own:
            raise UnsupportedSceneError(
                f"{scene.source}: dynamics.top_motion.period: {tm_period:g} s beside a wave "
                f"train of {own:g} s: one harmonic response has one period (give them "
                "the same period, or drop one)")
        motion = motion + vector
    return own, motion, scene_components(scene)


def top_motion(scene: Scene) -> tuple[np.ndarray, float]:
    """((3,) complex amplitudes [m], period [s]) of the scene's harmonic motion, along one
    axis or an orbit (:func:`riser.results.response.harmonic_motion_vector`; refused as
    unsupported without one)."""
    try:
        return harmonic_motion_vector(scene)
    except SceneError as exc:
        raise UnsupportedSceneError(str(exc)) from None

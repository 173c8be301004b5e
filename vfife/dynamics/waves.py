"""Wave loads of the VFIFE: the kinematics at the nodes, stepped in time.

The scene's waves (:mod:`riser.physics.waves`, its components and conventions) load the line by
Morison's equation: the drag on the velocity relative to the water (current plus the
waves' particle velocity, normal and tangential) and the
fluid inertia force rho A ((1 + C_a) a_n + a_t), A = pi D^2 / 4 (D the hydrodynamic
diameter, as the added mass and the drag take it), a_n and a_t the fluid
acceleration's parts normal and tangential to the line, each times the node's immersed
fraction under the instantaneous surface (the sea surface of the kinematics, y = h + eta
at the node). The tangential part is the Froude-Krylov force of the axial pressure
gradient, which the effective tension's bookkeeping puts on the line as it puts the
buoyancy (the added mass is normal only, C_a along the axis being 0 for a line); MoorDyn
applies the same rho V (1 + C_at) a_t with its axial C_at (0 in the decks here). The VFIFE computes its own Airy
kinematics (:func:`vfife.kernels.wave_pass`), with the stretching the scene names, and its
own loads (:func:`vfife.kernels.wave_load_pass`, every step: the node passes take them as
their dead load and leave their own drag off, so that a run without waves runs exactly the
node passes it ran before; folding the wave terms into the node passes had stopped them
vectorising, 2.6x slower in statics without any wave).

Time stepping: summing every component at every node and step would cost the components'
number times a node pass. The kinematics are evaluated once per interval of at most
:data:`KINEMATICS_PER_PERIOD`-th of the shortest component period (at the nodes'
positions at its start) with their first and second time derivatives, and every step
takes the quadratic Taylor polynomial (:func:`vfife.kernels.wave_taylor`): its error at
the interval's end is (omega tau)^3 / 6 of the amplitude, 5e-4 at 1/20 of the period
(the first harmonic's error, an average over the interval, smaller still). The ramp
([environment.waves] ramp_time, a half cosine) multiplies the kinematics, its derivatives
by the product rule.
"""

from __future__ import annotations

import math

import numpy as np

from riser.physics.hang_off_motion import scene_components

from .. import kernels

#: kinematics intervals per shortest component period (see the module docstring)
KINEMATICS_PER_PERIOD = 20


class WaveLoads:
    """The arrays of the wave kernels for one model: components, the inertia
    coefficients ``cin`` (2, n) [kg] (normal, tangential), the Taylor coefficients ``WT``
    (21, n) and the current values ``WV`` (7, n)."""

    def __init__(self, scene, mesh):
        comp = scene_components(scene)
        self.components = comp
        self.depth = float(scene.water_depth)
        self.amp = comp.amplitude.copy()
        self.omega = comp.omega.copy()
        self.k = comp.k.copy()
        self.phase = comp.phase.copy()
        self.cosb = np.cos(comp.heading)
        self.sinb = np.sin(comp.heading)
        self.wheeler = comp.stretching == "wheeler"
        self.ramp_time = comp.ramp_time
        # normal: Froude-Krylov + added mass; along the axis: Froude-Krylov alone
        self.cin = np.vstack([mesh.lump(mesh.fluid_pl + mesh.added_pl),
                              mesh.lump(mesh.fluid_pl)])
        n = mesh.n
        self.WT = np.zeros((21, n))
        self.WV = np.zeros((7, n))
        self.WV[6] = self.depth

    @property
    def interval(self) -> float:
        """The longest interval [s] between two evaluations of the kinematics."""
        return float(2.0 * math.pi / np.max(self.omega)) / KINEMATICS_PER_PERIOD

    def evaluate(self, X: np.ndarray, t: float) -> None:
        """Fill ``WT`` at the node positions X (3, n) [m] and time t [s], ramp included."""
        WT = self.WT
        kernels.wave_pass(X[0], X[1], X[2], t, self.amp, self.omega, self.k, self.phase,
                          self.cosb, self.sinb, self.components.origin[0],
                          self.components.origin[1], self.depth, self.wheeler, WT)
        r, r1, r2 = _ramp(t, self.ramp_time)
        if (r, r1, r2) != (1.0, 0.0, 0.0):
            v, d1, d2 = WT[0:7].copy(), WT[7:14].copy(), WT[14:21].copy()
            WT[0:7] = r * v
            WT[7:14] = r1 * v + r * d1
            WT[14:21] = r2 * v + 2.0 * r1 * d1 + r * d2
        WT[6] += self.depth

    def elevation(self, x: float, z: float, t: float) -> float:
        """The surface elevation [m] at (x, z) [m] and t [s] (the kernel's sum, ramped)."""
        out = np.zeros((21, 1))
        kernels.wave_pass(np.array([x]), np.array([self.depth]), np.array([z]), t,
                          self.amp, self.omega, self.k, self.phase, self.cosb, self.sinb,
                          self.components.origin[0], self.components.origin[1],
                          self.depth, self.wheeler, out)
        return float(_ramp(t, self.ramp_time)[0] * out[6, 0]) + 0.0     # no -0 at t = 0


def _ramp(t: float, ramp: float) -> tuple[float, float, float]:
    """The half-cosine ramp 0.5 (1 - cos(pi t / t_r)) and its first two derivatives."""
    if ramp <= 0.0 or t >= ramp:
        return 1.0, 0.0, 0.0
    a = math.pi / ramp
    return 0.5 * (1.0 - math.cos(a * t)), 0.5 * a * math.sin(a * t), 0.5 * a * a * math.cos(a * t)

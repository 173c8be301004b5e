"""The harmonic response to a harmonic hang-off motion: the contract of a frequency-domain
solution and of the first harmonic read off a time-domain one.

A harmonic motion of the hang-off, ``d(t) = Re(D e^{i omega t})`` per axis (x, y, z) with
complex amplitudes D [m] (a motion A sin(omega t) along an axis is D = -i A), drives a
response whose first harmonic at arc length s is ``q(s, t) = q_0(s) + Re(Q(s) e^{i omega
t})``: ``Q`` complex, amplitude |Q|, phase arg(Q) [rad] (the same convention as
:mod:`verification.comparison.harmonics`, which reads it off a time series).

Conventions: SI units; x horizontal towards the hang-off, y up from the seabed, z out of
plane; s [m] the unstretched arc length from the bottom end. Displacements are those of
the material points (Lagrangian), tension the effective tension, ``moment`` the in-plane
bending moment (about z, EI dtheta/ds: positive when the line turns anticlockwise), and
``moment_out`` the bending moment about the static in-plane normal (the out-of-plane
bending).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from ..errors import SceneError
from ..physics.hang_off_motion import motion_amplitudes
from .result import Status

#: the response quantities along s (``HarmonicResponse`` fields, ``response.csv`` columns)
QUANTITIES = ("dx", "dy", "dz", "tension", "moment", "moment_out", "curvature", "shear")
#: their units
UNITS = {"dx": "m", "dy": "m", "dz": "m", "tension": "N", "moment": "N m",
         "moment_out": "N m", "curvature": "1/m", "shear": "N"}


@dataclass(frozen=True)
class HarmonicResponse:
    """One harmonic response (see the module docstring).

    method : 'bvp' (frequency domain) or the time-domain method read off. status: a
    :class:`~riser.results.result.Status`. period [s]; motion (3,) complex amplitudes of the
    hang-off motion [m] along x, y, z. ``s`` (n,) [m]; ``amplitudes`` maps each name of
    :data:`QUANTITIES` to a complex (n,) array; ``static`` holds the static tension [N]
    and in-plane moment [N m] at s. ``info``: figures of the solution (iterations of the
    drag linearisation, grid change, wall time). Frozen: a changed copy is
    :meth:`replace`'s."""

    method: str
    scene: str
    status: Status
    message: str
    period: float = 0.0
    motion: np.ndarray = field(default_factory=lambda: np.zeros(3, complex))
    s: np.ndarray = field(default_factory=lambda: np.zeros(0))
    amplitudes: dict = field(default_factory=dict)
    static: dict = field(default_factory=dict)
    wall_time_s: float = 0.0
    info: dict = field(default_factory=dict)

    @property
    def converged(self) -> bool:
        return self.status == Status.CONVERGED

    def replace(self, **changes) -> HarmonicResponse:
        """A copy with ``changes`` (fields by name)."""
        return dataclasses.replace(self, **changes)

    @property
    def omega(self) -> float:
        return 2.0 * np.pi / self.period

    def at(self, name: str, s) -> np.ndarray:
        """Complex amplitude of ``name`` interpolated (real and imaginary parts) at s."""
        q = self.amplitudes[name]
        return np.interp(s, self.s, q.real) + 1j * np.interp(s, self.s, q.imag)


def harmonic_motion(scene) -> tuple[str, float, float]:
    """(axis, amplitude [m], period [s]) of the scene's harmonic [dynamics.top_motion];
    SceneError (one line, exit 2) when it has none or a time series (the harmonic
    response, of either method, needs a harmonic motion)."""
    dyn = scene.dynamics
    tm = dyn.top_motion if dyn is not None else None
    if tm is None:
        raise SceneError(scene.source, "dynamics.top_motion", "required by the harmonic "
                         "response (a harmonic hang-off motion: axis, amplitude, period)")
    if tm.times is not None:
        raise SceneError(scene.source, "dynamics.top_motion.times", "the harmonic response "
                         "needs a harmonic motion (amplitude and period), not a time series: "
                         "the frequency domain is harmonic")
    if not tm.one_axis:
        raise SceneError(scene.source, "dynamics.top_motion.amplitudes", "this takes a "
                         "harmonic motion along one axis (axis, amplitude, period), not an "
                         "orbit (harmonic_motion_vector takes both)")
    return tm.axis, tm.amplitude, tm.period


def harmonic_motion_vector(scene) -> tuple[np.ndarray, float]:
    """((3,) complex amplitudes [m], period [s]) of the scene's harmonic
    [dynamics.top_motion], along one axis or an orbit (d = Re(D e^{i omega t})); the
    refusals of :func:`harmonic_motion` for none or a time series."""
    dyn = scene.dynamics
    tm = dyn.top_motion if dyn is not None else None
    if tm is not None and tm.is_orbit:
        return tm.complex_amplitudes(), float(tm.period)
    axis, amplitude, period = harmonic_motion(scene)
    return motion_amplitudes(axis, amplitude), period

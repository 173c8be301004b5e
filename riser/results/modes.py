"""The modal-analysis result shared by the methods (undamped modes about the static state).

Each method computes the natural modes of small vibration about *its own* static
equilibrium of the same scene, with the same mass per length (pipe + contents, and the
added mass ``C_a rho pi D^2/4`` normal to the axis only), the same tension, bending
stiffness and seabed contact (the elastic seabed linearised: a vertical spring of the
scene's stiffness [N/m2] under the grounded part, nothing laterally; the static drag of a
current held as a dead load (its static value, fixed in direction); no drag damping or
friction). About a planar static state the in-plane (x, y) and out-of-plane (z) motions
decouple and each family is numbered from its lowest frequency (:data:`PLANES`). About a
3D static state (a current across the line's plane or turning with depth, a hang-off out
of the anchor's plane) they couple: the modes form one family, :data:`COUPLED`, numbered
from the lowest frequency, twice as many as a family's ``count`` (a method asked for
``count`` modes a family returns ``2 count`` coupled ones).

Conventions: SI units; x horizontal towards the hang-off, y up from the seabed, z out of
plane; ``s`` [m] the unstretched arc length from the bottom end. A mode shape is the
displacement amplitude of the line's points, (k, 3) components x, y, z, scaled so that
its largest component magnitude is 1 and its largest-magnitude component is positive
(the sign is otherwise arbitrary). The modal assurance criterion :func:`mac` compares
two shapes on the same arc lengths.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .result import Status

#: the two families of a planar static state (``Mode.plane``; ``modes.csv`` ``plane``)
PLANES = ("in_plane", "out_of_plane")
#: the one family of a 3D static state (``Mode.plane``; ``modes.csv`` ``plane``)
COUPLED = "coupled"


def out_of_plane_share(mode: "Mode") -> float:
    """The fraction of a mode's squared displacement that is along z, integrated along
    the line (trapezoidal in s, so that a method's mesh does not weigh it): 0 for an
    in-plane mode, 1 for an out-of-plane one. z is the scene's axis (out of the x-y
    plane; for ends out of that plane a share of the in-plane motion counts too)."""
    shape = np.asarray(mode.shape, float)
    total = float(np.trapezoid(np.sum(shape ** 2, axis=1), mode.s))
    return float(np.trapezoid(shape[:, 2] ** 2, mode.s) / total) if total > 0.0 else 0.0


@dataclass(frozen=True)
class Mode:
    """One natural mode: ``plane`` (one of :data:`PLANES`, or :data:`COUPLED`),
    ``number`` (1-based within its plane, by frequency), ``frequency_hz`` [Hz], ``s``
    (k,) [m] and ``shape`` (k, 3) [-] (see the module docstring)."""

    plane: str
    number: int
    frequency_hz: float
    s: np.ndarray
    shape: np.ndarray

    @property
    def period_s(self) -> float:
        """Natural period [s]."""
        return 1.0 / self.frequency_hz if self.frequency_hz > 0.0 else float("inf")

    @property
    def omega(self) -> float:
        """Circular frequency [rad/s]."""
        return 2.0 * np.pi * self.frequency_hz


@dataclass
class ModalResult:
    """Outcome of one modal analysis.

    method : 'bvp' or 'vfife'. scene : the scene's name.
    status : :class:`~riser.results.result.Status` (converged only with ``modes`` filled).
    message : how it ended, the reason for a failure.
    modes : the modes found, in-plane first, each family by increasing frequency.
    wall_time_s : [s] of the modal analysis (the static solve excluded, it is in info).
    info : method figures (static solve time, sizes, residuals, checks).
    """

    method: str
    scene: str
    status: Status
    message: str
    modes: list[Mode] = field(default_factory=list)
    wall_time_s: float = 0.0
    info: dict = field(default_factory=dict)

    @property
    def converged(self) -> bool:
        return self.status == Status.CONVERGED

    def family(self, plane: str) -> list[Mode]:
        """The modes of one plane, by number."""
        return sorted((m for m in self.modes if m.plane == plane), key=lambda m: m.number)


def normalise_shape(shape: np.ndarray) -> np.ndarray:
    """``shape`` scaled to a largest component magnitude of 1, that component positive."""
    shape = np.asarray(shape, float)
    flat = shape.ravel()
    i = int(np.argmax(np.abs(flat)))
    return shape / flat[i] if flat[i] != 0.0 else shape


def mac(a: np.ndarray, b: np.ndarray) -> float:
    """Modal assurance criterion |a.b|^2 / ((a.a)(b.b)) of two shapes sampled at the same
    points (any array shape; 1 = the same shape up to a factor, 0 = orthogonal)."""
    a = np.asarray(a, float).ravel()
    b = np.asarray(b, float).ravel()
    den = float(np.dot(a, a) * np.dot(b, b))
    return float(np.dot(a, b) ** 2 / den) if den > 0.0 else 0.0


def shape_at(mode: Mode, s: np.ndarray) -> np.ndarray:
    """The mode's shape (3 components) linearly interpolated at arc lengths ``s`` [m]."""
    s = np.asarray(s, float)
    return np.stack([np.interp(s, mode.s, mode.shape[:, j]) for j in range(3)], axis=1)

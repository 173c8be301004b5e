"""The result contract shared by every method, and writing it to disk.

Every run ends in one :class:`Status`. ``converged`` is the only status with a profile;
every other one carries the reason in ``message``. A scene a method cannot represent is
refused before solving: the solver raises :class:`~riser.errors.UnsupportedSceneError`
(a bad scene, :class:`~riser.errors.SceneError`) and a caller that keeps a row for it
(the stress suite) records :attr:`Status.REFUSED`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from pathlib import Path

from .profile import Profile, summarize, write_json

#: the methods that fill this contract (``SolveResult.method``)
METHODS = ("bvp", "vfife", "analytic")


class Status(str, Enum):
    """How a run ended (the value is written to summary.json as ``status``)."""

    CONVERGED = "converged"
    REFUSED = "refused"
    NO_EQUILIBRIUM = "no_equilibrium"
    DIVERGED = "diverged"
    NOT_CONVERGED = "not_converged"

    @property
    def meaning(self) -> str:
        return _MEANING[self]

    @property
    def exit_code(self) -> int:
        """The command line's exit code: 0 converged, 2 refused (bad input), 1 otherwise."""
        return {Status.CONVERGED: 0, Status.REFUSED: 2}.get(self, 1)


_MEANING = {
    Status.CONVERGED: "met the method's own convergence test; the result is inside the "
                      "model's validity (warnings say where it is doubtful)",
    Status.REFUSED: "the scene is outside what the method represents; said before solving",
    Status.NO_EQUILIBRIUM: "stopped with evidence that no static equilibrium of that form "
                           "exists (e.g. the tension driven to zero under the load)",
    Status.DIVERGED: "the iteration blew up (NaN/inf or runaway speed); the message names "
                     "the likely cause",
    Status.NOT_CONVERGED: "stopped at a limit (steps, mesh nodes) before meeting the "
                          "tolerance; the message says which and what to raise",
}


@dataclass(frozen=True)
class DynamicsResult:
    """Arrays of a dynamic run (VFIFE), for programmatic use; the files
    ``timeseries.csv``, ``envelope.csv`` and ``states.npz`` hold the same (columns and
    units: :mod:`vfife.dynamic_outputs` and the README's "Dynamics").

    timeseries : column -> (k,) array, sampled every output interval from t = 0.
    envelope : column -> (n,) array along the line (``s`` [m]; extremes over the
        statistics window).
    states : ``t`` (k,), ``s`` (n,), ``x`` (k, n, 3) [m], ``v`` (k, n, 3) [m/s]; None
        unless ``[dynamics] save_states``.
    """

    timeseries: dict
    envelope: dict
    states: dict | None


@dataclass
class SolveResult:
    """Outcome of one solve.

    Attributes
    ----------
    method : 'bvp', 'vfife' or 'analytic'.
    scene : scene name.
    status : how the run ended (:class:`Status`).
    message : why it stopped (always filled; the reason for a failure).
    profile : the static :class:`Profile`; None unless converged.
    wall_time_s : solver wall time [s] (Numba compilation excluded where the solver says so).
    effects : names of the physical effects that were active (e.g. 'weight', 'current_drag').
    model : the continuum model solved: ``axial`` ('extensible' | 'inextensible'), ``seabed``
        ('elastic' | 'rigid' | None) and, on an elastic seabed, ``seabed_stiffness`` [N/m2].
    warnings : statements on a converged result's validity (long elements, large strain,
        ignored inputs).
    info : solver-specific figures that go into summary.json (residuals named for what
        they measure, nodes, elements, time step, steps, ...).
    dynamics : the arrays of a dynamic run, else None.
    solver_state : the method's final static state for programmatic use (VFIFE: the
        :class:`vfife.model.Model` at equilibrium), else None; not written.
    extra_files : name -> callable(path) writing additional outputs (e.g. timeseries.csv).
    """

    method: str
    scene: str
    status: Status
    message: str
    profile: Profile | None = None
    wall_time_s: float = 0.0
    effects: list[str] = field(default_factory=list)
    model: dict = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    info: dict = field(default_factory=dict)
    dynamics: DynamicsResult | None = None
    solver_state: object = None
    extra_files: dict = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.status = Status(self.status)
        if self.status is not Status.CONVERGED:
            self.profile = None

    @property
    def converged(self) -> bool:
        return self.status is Status.CONVERGED

    def summary(self) -> dict:
        """summary.json content: run facts, the profile's features, then solver info."""
        out = {"method": self.method, "scene": self.scene, "status": self.status.value,
               "converged": self.converged, "message": self.message,
               "wall_time_s": self.wall_time_s, "effects": list(self.effects),
               "model": dict(self.model), "warnings": list(self.warnings)}
        if self.profile is not None:
            out.update(summarize(self.profile))
        out.update(self.info)
        return out

    def write(self, out_dir: str | Path) -> None:
        """Write summary.json always; profile.csv (and extra files) only when converged."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        if self.converged and self.profile is not None:
            self.profile.write_csv(out / "profile.csv")
            for name, writer in self.extra_files.items():
                writer(out / name)
        else:
            for stale in ["profile.csv", *self.extra_files]:
                (out / stale).unlink(missing_ok=True)
        write_json(self.summary(), out / "summary.json")

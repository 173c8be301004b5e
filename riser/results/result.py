"""The result contract shared by every method, and writing it to disk.

Every run ends in one :class:`Status`. ``converged`` is the only status with a profile;
every other one carries the reason in ``message``. A scene a method cannot represent is
refused before solving: the solver returns a result of status ``refused`` (one path for
every method; :meth:`SolveResult.require` raises it as
:class:`~riser.errors.UnsupportedSceneError` where a caller needs a converged result). A
bad scene raises :class:`~riser.errors.SceneError` (bad input, before any method runs).
Results are frozen: a caller that reports one differently (e.g. in another arc length)
builds a new one with :meth:`SolveResult.replace`.
"""

from __future__ import annotations

import csv
import dataclasses
from dataclasses import dataclass, field
from enum import Enum
from pathlib import Path

import numpy as np

from ..design.verdicts import with_verdicts
from ..errors import SolveFailed, UnsupportedSceneError
from .profile import Profile, summarize, write_json


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


#: the files of a dynamic run (:meth:`DynamicsResult.write`)
DYNAMIC_FILES = ("timeseries.csv", "envelope.csv", "states.npz")


@dataclass(frozen=True)
class DynamicsResult:
    """Arrays of a dynamic run (VFIFE), for programmatic use; the files
    ``timeseries.csv``, ``envelope.csv`` and ``states.npz`` hold the same (columns and
    units: :mod:`riser.results.recorder` and docs/results.md).

    timeseries : column -> (k,) array, sampled every output interval from t = 0.
    envelope : column -> (n,) array along the line (``s`` [m]; extremes over the
        statistics window).
    states : ``t`` (k,), ``s`` (n,), ``x`` (k, n, 3) [m], ``v`` (k, n, 3) [m/s],
        ``tension`` (k, n) [N], ``moment`` (k, n) [N m], ``moment_vector`` (k, n, 3)
        [N m] (global components); None unless
        ``[dynamics] save_states``.
    checkpoint : the run's state at the time asked for (``vfife.solve(checkpoint_at=)``,
        a :class:`vfife.dynamics.run.Checkpoint`) to continue the run from; else None.
    """

    timeseries: dict
    envelope: dict
    states: dict | None
    checkpoint: object = None

    def write(self, out_dir: str | Path) -> list[str]:
        """timeseries.csv and envelope.csv (10 significant digits, empty for NaN), and
        states.npz with the states; returns the names written."""
        out = Path(out_dir)
        _write_columns(self.timeseries, out / "timeseries.csv")
        _write_columns(self.envelope, out / "envelope.csv")
        names = ["timeseries.csv", "envelope.csv"]
        if self.states is not None:
            np.savez_compressed(out / "states.npz", **self.states)
            names.append("states.npz")
        return names


def _write_columns(columns: dict, path: Path) -> None:
    """A CSV of equal-length columns (name -> array), values with 10 significant digits."""
    names = list(columns)
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(names)
        for row in zip(*(columns[k] for k in names)):
            w.writerow([f"{v:.10g}" if np.isfinite(v) else "" for v in row])


@dataclass(frozen=True)
class SolveResult:
    """Outcome of one solve (frozen: built once by the method; see :meth:`replace`).

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

    def __post_init__(self) -> None:
        object.__setattr__(self, "status", Status(self.status))
        if self.status is not Status.CONVERGED:
            object.__setattr__(self, "profile", None)

    @classmethod
    def refused(cls, method: str, scene, reason: UnsupportedSceneError | str) -> "SolveResult":
        """The result of a method that refuses ``scene`` before solving, with the reason
        (an :class:`UnsupportedSceneError` a check raised, or its text)."""
        return cls(method, scene.name, Status.REFUSED, str(reason),
                   model=scene.continuum_model())

    @property
    def converged(self) -> bool:
        return self.status is Status.CONVERGED

    def require(self) -> "SolveResult":
        """This result when it converged; else raise :class:`UnsupportedSceneError` (refused:
        bad input for this method, exit 2) or :class:`SolveFailed` carrying the status."""
        if self.converged:
            return self
        if self.status is Status.REFUSED:
            raise UnsupportedSceneError(self.message)
        raise SolveFailed(self.method, self.status, f"{self.method} on {self.scene}: "
                          f"{self.status.value}: {self.message}")

    def replace(self, **changes) -> "SolveResult":
        """A copy with some fields changed (the result itself is frozen)."""
        return dataclasses.replace(self, **changes)

    def summary(self) -> dict:
        """summary.json content: run facts, the profile's features, then solver info."""
        out = {"method": self.method, "scene": self.scene, "status": self.status.value,
               "converged": self.converged, "message": self.message,
               "wall_time_s": self.wall_time_s, "effects": list(self.effects),
               "model": dict(self.model), "warnings": list(self.warnings)}
        if self.profile is not None:
            out.update(summarize(self.profile))
        out.update(self.info)
        return with_verdicts(out)                 # design_fails: the failed checks

    def write(self, out_dir: str | Path) -> None:
        """Write summary.json always; profile.csv (and a dynamic run's files) only when
        converged (a failed run removes them, so none of an earlier run is left)."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        if self.converged and self.profile is not None:
            self.profile.write_csv(out / "profile.csv")
            if self.dynamics is not None:
                self.dynamics.write(out)
        else:
            for stale in ("profile.csv", *DYNAMIC_FILES):
                (out / stale).unlink(missing_ok=True)
        write_json(self.summary(), out / "summary.json")

"""The solve result shared by both methods, and writing it to disk."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from .profile import Profile, summarize, write_json


@dataclass
class SolveResult:
    """Outcome of one solve.

    Attributes
    ----------
    method : 'bvp' or 'vfife'.
    scene : scene name.
    converged : True only when the solver met its own convergence test.
    message : why it stopped (always filled; the reason for a failure).
    profile : the static :class:`Profile`, or None when not converged.
    wall_time_s : solver wall time [s] (Numba compilation excluded where the solver says so).
    effects : names of the physical effects that were active (e.g. 'weight', 'current_drag').
    info : solver-specific figures that go into summary.json (residual, nodes, elements,
        time_step, steps, ...).
    extra_files : name -> callable(path) writing additional outputs (e.g. timeseries.csv).
    """

    method: str
    scene: str
    converged: bool
    message: str
    profile: Profile | None = None
    wall_time_s: float = 0.0
    effects: list[str] = field(default_factory=list)
    info: dict = field(default_factory=dict)
    extra_files: dict = field(default_factory=dict)

    def summary(self) -> dict:
        """summary.json content: run facts, solver info, then the profile's features."""
        out = {"method": self.method, "scene": self.scene, "converged": self.converged,
               "message": self.message, "wall_time_s": self.wall_time_s,
               "effects": list(self.effects)}
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

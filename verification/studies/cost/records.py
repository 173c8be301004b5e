"""The records of the cost study: one run (:class:`Run`), the whole study
(:class:`CostStudy`), and their tables (the columns of ``runs.csv`` and ``values.csv``)."""

from __future__ import annotations

import math
import statistics
from dataclasses import dataclass, field

import pandas as pd

from riser.results.profile import Profile
from riser.model.scene import Scene

from .errors import QUANTITIES
from .settings import Setting

RUN_COLUMNS = ("method", "setting", "value", "wall_time_s", "compile_time_s",
               *(f"err_{q}" for q in QUANTITIES))
EXTRA_COLUMNS = ("converged", "repeats", "size", "steps", *(f"self_{q}" for q in QUANTITIES),
                 "message")


@dataclass
class Run:
    """One setting solved and timed, with its quantities and errors."""

    setting: Setting
    times: list = field(default_factory=list)
    converged: bool = False
    message: str = ""
    compile_time_s: float = 0.0
    size: int | None = None          # BVP nodes / VFIFE elements
    steps: int | None = None
    values: dict = field(default_factory=dict)     # raw scalar quantities
    profile: Profile | None = None
    errors: dict = field(default_factory=dict)     # vs the BVP reference
    self_errors: dict = field(default_factory=dict)

    @property
    def wall_time_s(self) -> float:
        return float(statistics.median(self.times)) if self.times else float("nan")

    @property
    def method(self) -> str:
        return "vfife" if self.setting.method.startswith("vfife") else "bvp"


@dataclass
class CostStudy:
    scene: Scene                     # as given
    fixed_scene: Scene               # the fixed-ends scene both methods solve
    depth: float
    repeats: int
    runs: list
    reference: Run
    ref_values: dict
    paper_difference: dict = field(default_factory=dict)  # Wang form vs the reference
    bvp_self: dict = field(default_factory=dict)       # quantity -> rel. uncertainty of ref
    vfife_limit: dict = field(default_factory=dict)    # raw key -> Richardson limit
    vfife_richardson_order: dict = field(default_factory=dict)
    limit_vs_reference: dict = field(default_factory=dict)   # quantity -> rel. difference
    orders: dict = field(default_factory=dict)         # quantity -> fit dict
    noise_floor: dict = field(default_factory=dict)    # quantity -> rel. relaxation error
    sweep_noise: dict = field(default_factory=dict)    # ... of the order sweep
    boundary_layer: float = math.inf                    # [m], sqrt(EI/T) at the touchdown
    foundation_length: float | None = None              # [m], (4 EI/k)^(1/4)
    asymptotic: float = math.inf                        # [m], fit range h <= this
    liftoff: dict | None = None                         # see touchdown.liftoff_interpolation
    order_sweep: str = ""
    order_setting: str = ""
    scaling: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)
    elapsed_s: float = 0.0
    sweep: str = "full"              # 'fast' (default), 'full' (--full), 'quick', 'given'
    dynamics: object = None          # the dynamic sweep (dynamics.DynStudy), or None
    ancf_dynamics: object = None     # the ANCF's beside it (dynamics_ancf.AncfStudy), or None

    @property
    def has_order_sweep(self) -> bool:
        """Whether the order sweep (``element_length_tight`` rows) was run: the fast sweep
        leaves it to ``--full``."""
        return any(r.setting.setting == "element_length_tight" for r in self.runs)

    def frame(self) -> pd.DataFrame:
        """``runs.csv``: one row per run (:data:`RUN_COLUMNS`, then :data:`EXTRA_COLUMNS`)."""
        rows = []
        for r in self.runs:
            s = r.setting
            row = {"method": r.method if s.method != "vfife-dyn" else "vfife",
                   "setting": s.setting, "value": s.value, "wall_time_s": r.wall_time_s,
                   "compile_time_s": r.compile_time_s}
            for q in QUANTITIES:
                row[f"err_{q}"] = r.errors.get(q)
            row.update({"converged": r.converged, "repeats": len(r.times), "size": r.size,
                        "steps": r.steps})
            for q in QUANTITIES:
                row[f"self_{q}"] = r.self_errors.get(q)
            row["message"] = r.message
            rows.append(row)
        return pd.DataFrame(rows, columns=RUN_COLUMNS + EXTRA_COLUMNS)

    def values_frame(self) -> pd.DataFrame:
        """``values.csv``: the raw quantities of the reference and of every run."""
        keys = sorted({k for r in self.runs for k in r.values})
        rows = [{"method": r.method, "setting": r.setting.setting, "value": r.setting.value,
                 **{k: r.values.get(k) for k in keys}} for r in self.runs if r.values]
        rows.insert(0, {"method": "reference", "setting": "bvp tolerance",
                        "value": self.reference.setting.value,
                        **{k: self.ref_values.get(k) for k in keys}})
        return pd.DataFrame(rows)

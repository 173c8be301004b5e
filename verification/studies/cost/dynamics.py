"""The dynamic part of the cost study: what a dynamic VFIFE run costs, and how accurate it
is, against its element length and time-step factor.

Every run starts from the VFIFE static state of its element length (the study's
``static_cache``, solved here when the static sweep has none) and moves the hang-off by
the same heave (:data:`HEAVE_AMPLITUDE` m at :data:`HEAVE_PERIOD` s, the default ramp of
one period, like the dynamic study of Yu et al. 2021) for :data:`DURATION` s; the
statistics window is :data:`STATISTICS_START` s to the end for every run, so only the
discretisation changes. Quantities (:data:`QUANTITIES`): the hang-off tension amplitude
(half the range of the hang-off tension over the window) and the peak moment (the largest
nodal moment over the window), both sampled at the same times (period / 40) on every mesh.

Sweep (:func:`dynamic_settings`): the element lengths at the scene's own
``[vfife] time_step_safety`` (the factor on the critical step, 0.8 by default), down to the
finest length whose reference run (factor :data:`REFERENCE_FACTOR`) is predicted to cost
at most the sweep's budget of element-steps; at the finest length also the factors of
:data:`FINEST_FACTORS`, at the next-coarser one :data:`REFERENCE_FACTOR`; ``--full`` adds
20 m, a larger budget, factor 0.6 at the finest and the step-factor sweep
:data:`ORDER_FACTORS` at :data:`ORDER_LENGTH` m (the observed order in the time step).
The analysis is in :mod:`verification.studies.cost.dynamics_analysis`, the report section in
:mod:`verification.studies.cost.dynamics_report`.
"""

from __future__ import annotations

import math
import statistics
import time
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from riser.model.scene import Dynamics, FixedEnds, Scene, TopMotion
from verification.methods import method
from vfife.dynamics.run import DynamicsOutcome, run_dynamics
from vfife.mesh import build_mesh
from vfife.timestep import critical_steps

#: the load of every run: heave of the hang-off (Yu et al. 2021's dynamic study)
HEAVE_AMPLITUDE = 1.5
HEAVE_PERIOD = 10.0
#: simulated time [s]: the ramp (one period), one period to settle, two in the window
DURATION = 40.0
STATISTICS_START = 20.0
OUTPUT_INTERVAL = 1.0
QUANTITIES = ("amplitude", "peak_moment")
QUANTITY_LABEL = {"amplitude": "hang-off tension amplitude", "peak_moment": "peak moment"}
#: the smallest step factor: the reference run's, at the finest element length
REFERENCE_FACTOR = 0.4
#: the largest step factor tried (just below the critical step)
FAST_FACTOR = 0.95
#: element lengths [m] tried, coarse to fine, by sweep
LENGTHS = {"fast": (10.0, 5.0, 2.0, 1.0, 0.5), "full": (20.0, 10.0, 5.0, 2.0, 1.0, 0.5, 0.25),
           "quick": (20.0, 10.0, 5.0)}
#: budget [element-steps] of the reference run, which sets the finest element length: at
#: ~8 ns per element-step (2-core machine) 1.6e9 is ~13 s (fast) and 6.4e9 ~50 s (full).
#: Measured: Wang baseline 1 m (fast) and 0.5 m (full); Yu scenes 0.5 m and 0.25 m.
BUDGET = {"fast": 1.6e9, "full": 6.4e9, "quick": 1e12}
#: the factors run at the finest length besides the scene's (the last: the reference's)
FINEST_FACTORS = {"fast": (FAST_FACTOR, REFERENCE_FACTOR),
                  "quick": (FAST_FACTOR, REFERENCE_FACTOR),
                  "full": (FAST_FACTOR, 0.6, REFERENCE_FACTOR)}
#: the step-factor sweep of ``--full`` (observed order in the time step), at one length
ORDER_LENGTH = 2.0
ORDER_FACTORS = (0.95, 0.6, 0.4, 0.2)
#: what the fast sweep runs of the dynamics, and what ``--full`` adds (the report says it)
FAST_DYNAMICS = (f"the dynamic sweep ({DURATION:g} s of a {HEAVE_AMPLITUDE:g} m heave at "
                 f"{HEAVE_PERIOD:g} s from the static state: element lengths 10 m down to "
                 f"the finest within a budget of {BUDGET['fast']:.2g} element-steps, step "
                 f"factors {FAST_FACTOR:g} and {REFERENCE_FACTOR:g} at the finest)")
FULL_DYNAMICS = (f"the wider dynamic sweep (20 m, finer lengths within "
                 f"{BUDGET['full']:.2g} element-steps, factor 0.6 at the finest, and step "
                 f"factors {', '.join(f'{f:g}' for f in ORDER_FACTORS)} at {ORDER_LENGTH:g} "
                 "m for the "
                 "observed order in the time step)")

CSV_COLUMNS = ("element_length", "time_step_factor", "time_step", "steps", "wall_s",
               "hang_off_tension_amplitude", "peak_moment", "err_amplitude",
               "err_peak_moment")
CSV_EXTRA = ("elements", "peak_moment_s", "nodes_above_surface", "repeats", "converged",
             "reference", "message")


class CpuClock:
    """An observer of a time domain's recorder (:class:`riser.results.recorder.Recorder`):
    the process's CPU time [s] from the run's first sample (the static state at t = 0) to
    its last. One per run; the cost study clocks both methods' dynamic runs with it."""

    def __init__(self):
        self.first: float | None = None
        self.last: float | None = None

    def start(self, s) -> None:
        pass

    def sample(self, t, x, tangents, tension, moment_vectors, window) -> None:
        now = time.process_time()
        if self.first is None:
            self.first = now
        self.last = now

    def envelope(self) -> dict:
        return {}

    def statistics(self) -> dict:
        return {}

    @property
    def seconds(self) -> float:
        return (self.last - self.first) if self.first is not None else float("nan")


@dataclass(frozen=True)
class DynSetting:
    """One dynamic run: element length [m] and time-step factor (``[vfife]
    time_step_safety``)."""

    element_length: float
    factor: float


@dataclass
class DynRun:
    """One dynamic run, timed (median of ``times`` [s]), with its quantities and errors."""

    setting: DynSetting
    times: list = field(default_factory=list)
    cpus: list = field(default_factory=list)         # CpuClock seconds per repeat
    loop_walls: list = field(default_factory=list)   # the run's own info['wall_s']
    converged: bool = False
    message: str = ""
    elements: int | None = None
    time_step: float | None = None
    steps: int | None = None
    amplitude: float | None = None
    peak_moment: float | None = None
    peak_moment_s: float | None = None
    nodes_above_surface: int | None = None
    errors: dict = field(default_factory=dict)       # quantity -> relative error

    @property
    def wall_s(self) -> float:
        return float(statistics.median(self.times)) if self.times else float("nan")

    @property
    def cpu_s(self) -> float:
        """Median CPU time [s] of the run's time loop (:class:`CpuClock`)."""
        return float(statistics.median(self.cpus)) if self.cpus else float("nan")

    @property
    def loop_wall_s(self) -> float:
        """Median wall time [s] of the run's time loop (its info['wall_s'], the solve's
        ``dynamic_wall_s``: without the model's set-up, which ``wall_s`` includes)."""
        return float(statistics.median(self.loop_walls)) if self.loop_walls else float("nan")

    @property
    def h(self) -> float:
        return self.setting.element_length

    @property
    def factor(self) -> float:
        return self.setting.factor

    @property
    def method(self) -> str:
        return "vfife"

    def label(self) -> str:
        return f"{self.h:g} m, factor {self.factor:g}"

    def value(self, q: str) -> float | None:
        return getattr(self, q)


@dataclass
class DynStudy:
    """The dynamic sweep of one scene and what :func:`~verification.studies.cost.dynamics_analysis.
    analyse` makes of it (reference, errors, orders, step-factor effect, cost)."""

    runs: list
    default_factor: float
    sweep: str                       # 'fast', 'full', 'quick' or 'given'
    surface: dict | None = None      # the hang-off at the sea surface (see surface_piercing)
    static_s: dict = field(default_factory=dict)   # h -> s of statics solved for it here
    reference: dict = field(default_factory=dict)  # quantity -> see dynamics_analysis
    ref_run: DynRun | None = None
    orders: dict = field(default_factory=dict)
    step: list = field(default_factory=list)
    step_verdict: dict = field(default_factory=dict)
    dt_order: dict = field(default_factory=dict)
    scaling: dict = field(default_factory=dict)
    elapsed_s: float = 0.0           # wall time of the whole dynamic sweep [s]

    def frame(self) -> pd.DataFrame:
        """``dynamics.csv``: one row per run (:data:`CSV_COLUMNS`, then :data:`CSV_EXTRA`)."""
        rows = []
        ref = self.ref_run if any(v.get("kind") == "finest" for v in self.reference.values()) \
            else None
        for r in self.runs:
            rows.append({
                "element_length": r.h, "time_step_factor": r.factor,
                "time_step": r.time_step, "steps": r.steps, "wall_s": r.wall_s,
                "hang_off_tension_amplitude": r.amplitude, "peak_moment": r.peak_moment,
                "err_amplitude": r.errors.get("amplitude"),
                "err_peak_moment": r.errors.get("peak_moment"),
                "elements": r.elements, "peak_moment_s": r.peak_moment_s,
                "nodes_above_surface": r.nodes_above_surface, "repeats": len(r.times),
                "converged": r.converged, "reference": r is ref,
                "message": r.message})
        return pd.DataFrame(rows, columns=CSV_COLUMNS + CSV_EXTRA)


def motion() -> Dynamics:
    """The ``[dynamics]`` of every run of the sweep."""
    return Dynamics(duration=DURATION, output_interval=OUTPUT_INTERVAL,
                    top_motion=TopMotion(axis="y", amplitude=HEAVE_AMPLITUDE,
                                         period=HEAVE_PERIOD),
                    statistics_start=STATISTICS_START)


def element_steps(scene: Scene, h: float, factor: float) -> float:
    """Predicted cost of a run [element-steps]: elements x DURATION / (factor x the smallest
    critical step of the unstressed mesh: axial, rotation, bending with added mass)."""
    mesh = build_mesh(scene, h)
    added = any(scene.line_types[s.line_type].added_mass > 0.0 for s in scene.segments)
    cs = critical_steps(mesh, rot_scale=scene.vfife.rotational_inertia_scale_dynamics,
                        added_mass=added)
    return mesh.ne * DURATION / (factor * min(cs.values()))


def dynamic_settings(scene: Scene, sweep: str = "fast", lengths=None) -> list[DynSetting]:
    """The runs of the dynamic sweep (see the module docstring): the element lengths of
    :data:`LENGTHS` (or ``lengths``) down to the finest within :data:`BUDGET` at the
    scene's factor, the factors of :data:`FINEST_FACTORS` at the finest, the reference
    factor at the next-coarser length, and (``full``) :data:`ORDER_FACTORS` at
    :data:`ORDER_LENGTH`."""
    f0 = scene.vfife.time_step_safety
    lengths = tuple(sorted(lengths, reverse=True)) if lengths else LENGTHS[sweep]
    keep = [h for h in lengths
            if element_steps(scene, h, REFERENCE_FACTOR) <= BUDGET[sweep]] or [lengths[0]]
    hs = [h for h in lengths if h >= min(keep)]
    out = [DynSetting(h, f0) for h in hs]
    out += [DynSetting(hs[-1], f) for f in FINEST_FACTORS[sweep]]
    if len(hs) >= 2:
        out.append(DynSetting(hs[-2], REFERENCE_FACTOR))
    if sweep == "full" and ORDER_LENGTH in hs:
        out += [DynSetting(ORDER_LENGTH, f) for f in ORDER_FACTORS]
    seen, unique = set(), []
    for s in out:
        if (s.element_length, s.factor) not in seen:
            seen.add((s.element_length, s.factor))
            unique.append(s)
    return unique


def predicted_cost(scene: Scene, s: DynSetting) -> float:
    """Predicted wall time [s] of a run (the progress estimate): ~8 ns per element-step."""
    return 8e-9 * element_steps(scene, s.element_length, s.factor)


def surface_piercing(scene: Scene) -> dict | None:
    """The hang-off's height below the sea surface [m] when the heave brings the line
    through it (|depth - hang-off height| < amplitude), else None."""
    if scene.water_depth is None or not isinstance(scene.ends, FixedEnds):
        return None
    below = float(scene.water_depth - scene.ends.hang_off[1])
    return {"below": below} if abs(below) < HEAVE_AMPLITUDE else None


def static_state(scene: Scene, h: float, static_cache: dict, static_s: dict):
    """The converged static result at element length ``h`` (from ``static_cache``, else
    solved here with the default settings and cached, its time in ``static_s``)."""
    res = static_cache.get(h)
    if res is None:
        t0 = time.perf_counter()
        try:
            res = method("vfife").solve(scene, element_length=h)
        except (RuntimeError, ValueError, FloatingPointError):
            res = None
        static_s[h] = time.perf_counter() - t0
        static_cache[h] = res
    return res if res is not None and res.converged else None


def run_dynamic(s: DynSetting, scene: Scene, repeats: int, static_cache: dict,
                static_s: dict, repeat_below: float = 2.0) -> DynRun:
    """Run ``s`` from the static state of its element length; runs longer than
    ``repeat_below`` [s] are timed once, shorter ones as the median of ``repeats``."""
    run = DynRun(s)
    res = static_state(scene, s.element_length, static_cache, static_s)
    if res is None:
        run.message = "no converged static state"
        return run
    vf = scene.vfife.replace(time_step_safety=s.factor, time_step=None)
    sc = scene.replace(dynamics=motion(), vfife=vf)
    for i in range(max(1, repeats)):
        clock = CpuClock()
        t0 = time.perf_counter()
        _, info = run_dynamics(sc, res.solver_state, bool(sc.is_planar), observers=(clock,))
        run.times.append(time.perf_counter() - t0)
        run.cpus.append(clock.seconds)
        run.loop_walls.append(float(info["wall_s"]))
        if i == 0:
            _record(run, info, sc, res.info.get("elements"))
        if not run.converged or run.times[-1] > repeat_below:
            break
    return run


def _record(run: DynRun, info: dict, scene: Scene, elements) -> None:
    st = info["statistics"]
    run.elements, run.time_step, run.steps = elements, info["time_step"], info["steps"]
    run.message = info["message"]
    rng = st.get("dynamic_hang_off_tension_range")
    run.converged = info["status"] is DynamicsOutcome.OK and rng is not None and math.isfinite(rng)
    if not run.converged:
        return
    run.amplitude = 0.5 * rng
    run.peak_moment = st.get("dynamic_max_moment")
    run.peak_moment_s = st.get("dynamic_max_moment_s")
    if scene.water_depth is not None:
        y_max = np.asarray(info["envelope"]["y_max"])[1:-1]      # the free nodes
        run.nodes_above_surface = int(np.sum(y_max > scene.water_depth))

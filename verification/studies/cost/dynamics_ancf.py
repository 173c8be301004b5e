"""The ANCF's dynamic sweep of the cost study, beside the VFIFE's
(:mod:`verification.studies.cost.dynamics`): the same motion (:func:`~.dynamics.motion`:
a 1.5 m heave at 10 s for 40 s from the static state), the same statistics window and
sampling (period / 40) and the same quantities (the hang-off tension amplitude and the
peak moment), against the ANCF's element length and steps per period.

Every run is one solve through the registry (``method("ancf").solve``: the Newton statics
of its own mesh, then the implicit dynamics); only the dynamic run is timed: its wall time
(``info['dynamic_wall_s']``) and the process's CPU time from the run's first sample (the
static state, t = 0) to its last (:class:`CpuClock`, an observer of the run's recorder).
The VFIFE's runs are clocked by the same observer (:func:`~.dynamics.run_dynamic`), so
the two methods' CPU times span the same part of a run.

Steps per period (``[ancf] steps_per_period``): :data:`GRID_STEPS` and
:data:`REFERENCE_STEPS`, multiples of 40 because the ANCF makes its step an exact divisor
of the sampling interval (period / 40 = 0.25 s): 25, 50, 100 and 200 a period would be
run as 40, 80, 120 and 200 (the default, 100, runs at period / 120). Sweep
(:func:`ancf_settings`): the element lengths of :data:`LENGTHS` down to the finest whose
reference run (:data:`REFERENCE_STEPS`) is predicted within :data:`BUDGET`
element-steps; the coarser lengths at every step count of :data:`GRID_STEPS` (the one next
to the finest at :data:`NEXT_STEPS`), the finest at the last of them and at
:data:`REFERENCE_STEPS` (its change between the two is the reference's step
uncertainty). The analysis beside the VFIFE's is in
:mod:`verification.studies.cost.dynamics_ancf_analysis`, its report section in
:mod:`verification.studies.cost.dynamics_ancf_report`.
"""

from __future__ import annotations

import math
import statistics
import time
from dataclasses import dataclass, field

import pandas as pd

from ancf.mesh import build_mesh
from riser.errors import SceneError
from riser.model.scene import Dynamics, Scene, TopMotion
from riser.results import validity
from riser.results.result import Status
from verification.methods import method

from .dynamics import DURATION, HEAVE_AMPLITUDE, HEAVE_PERIOD, CpuClock, motion

#: element lengths [m] tried, coarse to fine, by sweep (cubic elements: several times the
#: VFIFE's for the same accuracy)
LENGTHS = {"fast": (16.0, 8.0, 4.0, 2.0), "full": (16.0, 8.0, 4.0, 2.0, 1.0),
           "quick": (16.0, 8.0)}
#: steps per period of the coarser lengths (multiples of 40: the module docstring)
GRID_STEPS = {"fast": (40, 80, 160), "full": (40, 80, 160, 320), "quick": (40,)}
#: steps per period of the length next to the finest (None: the whole grid): the fast
#: sweep runs it at the grid's last only, which gives the reference's mesh change and
#: keeps the sweep's time near the VFIFE's (scr-steel: 9 runs, ~50 s; with 4 m over the
#: whole grid 11 runs, 62 s). Its finest is 2 m, not 4 m, because a reference at 4 m was
#: not sharp enough on scr-steel: 4 m at period / 320 is 0.11 % above 2 m at period / 640
#: in the peak moment (its estimate said 0.075 %), and the VFIFE's 2 m, 0.58 % from the
#: sharp limit, read 0.48 % against it.
NEXT_STEPS = {"fast": (160,), "full": None, "quick": None}
#: steps per period of the reference run (at the finest length)
REFERENCE_STEPS = {"fast": 320, "full": 640, "quick": 80}
#: budget [element-steps] of the reference run, which sets the finest length: at ~10 us
#: per element-step (one Newton iteration a step at period / 160 and finer; a 2-core
#: machine) 2e6 is ~20 s (fast), 4e6 ~40 s (full). Measured on scr-steel (2,000 m):
#: 2 m at period / 320 (1000 elements, 1280 steps) 13 s, at period / 640 27 s; 1 m at
#: period / 320 23 s. So the fast sweep's finest is 2 m on lines up to ~3,100 m (every
#: built-in cost scene), the full sweep's 1 m on lines up to ~1,550 m (Yu's 1,050 m).
BUDGET = {"fast": 2.0e6, "full": 4.0e6, "quick": 1e12}
#: predicted wall time [s] per element-step (the progress estimate)
SECONDS_PER_ELEMENT_STEP = 1.0e-5
#: what the ANCF sweep runs, in words (the report says it)
FAST_ANCF = (f"the ANCF's dynamic sweep (the same motion; element lengths "
             f"{', '.join(f'{h:g}' for h in LENGTHS['fast'])} m down to the finest whose "
             f"reference run is within {BUDGET['fast']:.2g} element-steps, the coarser ones "
             f"at {', '.join(map(str, GRID_STEPS['fast']))} steps a period (the one next to "
             f"the finest at {', '.join(map(str, NEXT_STEPS['fast']))}), the finest at "
             f"{GRID_STEPS['fast'][-1]} and {REFERENCE_STEPS['fast']})")
FULL_ANCF = (f"the wider ANCF sweep ({LENGTHS['full'][-1]:g} m within "
             f"{BUDGET['full']:.2g} element-steps, {GRID_STEPS['full'][-1]} steps a period "
             f"at every coarser length, {REFERENCE_STEPS['full']} at the finest)")


@dataclass(frozen=True)
class AncfSetting:
    """One ANCF dynamic run: element length [m] and steps per period of the heave."""

    element_length: float
    steps_per_period: int


@dataclass
class AncfRun:
    """One ANCF dynamic run, timed (medians of ``walls`` and ``cpus`` [s]), with its
    quantities; its errors are filled by the analysis."""

    setting: AncfSetting
    walls: list = field(default_factory=list)      # info['dynamic_wall_s'] per repeat
    cpus: list = field(default_factory=list)       # CpuClock seconds per repeat
    converged: bool = False
    refused: bool = False            # the ANCF refused the scene (the message says why)
    message: str = ""
    elements: int | None = None
    time_step: float | None = None
    steps: int | None = None
    newton_iterations_per_step: float | None = None
    step_halvings: int | None = None
    integrator: str = ""
    amplitude: float | None = None
    peak_moment: float | None = None
    peak_moment_s: float | None = None
    errors: dict = field(default_factory=dict)        # quantity -> vs the common reference
    self_errors: dict = field(default_factory=dict)   # quantity -> vs the ANCF's own

    method = "ancf"

    @property
    def h(self) -> float:
        return self.setting.element_length

    @property
    def steps_per_period(self) -> int:
        return self.setting.steps_per_period

    @property
    def wall_s(self) -> float:
        return float(statistics.median(self.walls)) if self.walls else float("nan")

    @property
    def cpu_s(self) -> float:
        return float(statistics.median(self.cpus)) if self.cpus else float("nan")

    def value(self, q: str) -> float | None:
        return getattr(self, q)

    def label(self) -> str:
        return f"{self.h:g} m, {self.steps_per_period} steps a period"


@dataclass
class AncfStudy:
    """The ANCF's sweep of one scene and what
    :func:`~verification.studies.cost.dynamics_ancf_analysis.analyse` makes of it beside
    the VFIFE's: its own reference, the common reference of both methods, the picks."""

    runs: list
    sweep: str                     # 'fast', 'full', 'quick' or 'given'
    reference: dict = field(default_factory=dict)   # quantity -> the ANCF's own reference
    common: dict = field(default_factory=dict)      # quantity -> the common reference
    vfife_errors: dict = field(default_factory=dict)  # id(VFIFE run) -> {q: error}
    picks: list = field(default_factory=list)       # see dynamics_ancf_analysis.picks
    own_picks: dict = field(default_factory=dict)   # method -> each own study's pick
    elapsed_s: float = 0.0         # wall time of the ANCF sweep [s], statics included
    warm_up_s: float = 0.0         # the warm-up solve before it [s] (warm_up)


def per_simulated_second(seconds: float) -> float:
    """A dynamic run's time [s] per simulated second (the sweep's :data:`DURATION`)."""
    return seconds / DURATION


def _elements(scene: Scene, h: float) -> int:
    return int(build_mesh(scene, h).ne)


def element_steps(scene: Scene, s: AncfSetting) -> float:
    """Predicted cost of a run [element-steps]: elements x steps (period / steps per
    period, made a divisor of the sampling interval)."""
    return _elements(scene, s.element_length) * DURATION * _steps_per_period(
        s.steps_per_period) / HEAVE_PERIOD


def _steps_per_period(n: int) -> int:
    """The steps a period the ANCF runs for ``n`` asked: a multiple of 40 (the sampling
    interval is period / 40, the step an exact divisor of it)."""
    return 40 * max(1, math.ceil(n / 40 - 1e-9))


def _resolves(scene: Scene, h: float) -> bool:
    try:
        validity.check_resolution(scene, h, key="ancf.element_length")
    except SceneError:
        return False
    return True


def ancf_settings(scene: Scene, sweep: str = "fast") -> list[AncfSetting]:
    """The runs of the ANCF's sweep (the module docstring): lengths the line takes
    (:func:`riser.results.validity.check_resolution`), coarse to fine."""
    lengths = [h for h in LENGTHS[sweep] if _resolves(scene, h)]
    if not lengths:
        return []
    ref_n = REFERENCE_STEPS[sweep]
    keep = [h for h in lengths
            if element_steps(scene, AncfSetting(h, ref_n)) <= BUDGET[sweep]] or [lengths[0]]
    finest = min(keep)
    coarser = [h for h in lengths if h > finest]
    out = []
    for h in coarser:
        steps = NEXT_STEPS[sweep] if h == coarser[-1] and NEXT_STEPS[sweep] else \
            GRID_STEPS[sweep]
        out += [AncfSetting(h, n) for n in steps]
    out += [AncfSetting(finest, GRID_STEPS[sweep][-1]), AncfSetting(finest, ref_n)]
    seen, unique = set(), []
    for s in out:
        if s not in seen:
            seen.add(s)
            unique.append(s)
    return unique


def predicted_cost(scene: Scene, s: AncfSetting) -> float:
    """Predicted wall time [s] of a run (the progress estimate)."""
    return SECONDS_PER_ELEMENT_STEP * element_steps(scene, s)


def run_scene(scene: Scene, s: AncfSetting) -> Scene:
    """The scene of run ``s``: the sweep's motion, the ANCF's mesh and step."""
    return scene.replace(dynamics=motion(), ancf=scene.ancf.replace(
        element_length=s.element_length, steps_per_period=s.steps_per_period,
        time_step=None))


def warm_up(scene: Scene, s: AncfSetting) -> float:
    """Wall time [s] of one short solve of ``s`` (statics and 1 s of the heave) before the
    timed runs: the ANCF's Numba kernels compiled (or loaded from the on-disk cache), in no
    run's time, as the VFIFE's warm-up."""
    short = Dynamics(duration=1.0, output_interval=0.5, top_motion=TopMotion(
        axis="y", amplitude=HEAVE_AMPLITUDE, period=HEAVE_PERIOD, ramp_time=1.0))
    t0 = time.perf_counter()
    try:
        method("ancf").solve(run_scene(scene, s).replace(dynamics=short))
    except (SceneError, RuntimeError, ValueError, FloatingPointError):
        pass                           # the timed runs say what fails
    return time.perf_counter() - t0


def run_ancf(s: AncfSetting, scene: Scene, repeats: int,
             repeat_below: float = 2.0) -> AncfRun:
    """Solve ``s`` (statics and dynamics) on ``scene``; runs whose dynamics take longer
    than ``repeat_below`` [s] are timed once, shorter ones as the median of ``repeats``."""
    run = AncfRun(s)
    sc = run_scene(scene, s)
    for i in range(max(1, repeats)):
        clock = CpuClock()
        try:
            res = method("ancf").solve(sc, observers=(clock,))
        except (SceneError, RuntimeError, ValueError, FloatingPointError) as exc:
            run.message = f"{type(exc).__name__}: {exc}"
            return run
        if i == 0:
            _record(run, res)
        if not run.converged:
            run.refused = res.status is Status.REFUSED
            return run
        run.walls.append(float(res.info["dynamic_wall_s"]))
        run.cpus.append(clock.seconds)
        if run.walls[-1] > repeat_below:
            break
    return run


def _record(run: AncfRun, res) -> None:
    info = res.info
    run.message = res.message
    run.elements = info.get("elements")
    run.time_step = info.get("dynamic_time_step")
    run.steps = info.get("dynamic_steps")
    run.newton_iterations_per_step = info.get("newton_iterations_per_step")
    run.step_halvings = info.get("step_halvings")
    run.integrator = info.get("integrator", "")
    rng = info.get("dynamic_hang_off_tension_range")
    run.converged = bool(res.converged and rng is not None and math.isfinite(rng)
                         and "dynamic_wall_s" in info)
    if not run.converged:
        return
    run.amplitude = 0.5 * rng
    run.peak_moment = info.get("dynamic_max_moment")
    run.peak_moment_s = info.get("dynamic_max_moment_s")


#: ``dynamics_ancf.csv``: both methods' runs against the common reference, the ANCF's
#: first; the timing columns (wall and CPU seconds, and per simulated second) are named
#: as :data:`verification.runtime.stable.TIMING_NAMES` knows them
CSV_COLUMNS = ("method", "element_length", "steps_per_period", "time_step_factor",
               "time_step", "steps", "elements", "newton_iterations_per_step",
               "step_halvings", "wall_s", "cpu_s", "wall_s_per_simulated_s",
               "cpu_s_per_simulated_s", "hang_off_tension_amplitude", "peak_moment",
               "err_amplitude", "err_peak_moment", "self_err_amplitude",
               "self_err_peak_moment")
CSV_EXTRA = ("peak_moment_s", "repeats", "converged", "reference", "picked", "integrator",
             "message")


def frame(st: AncfStudy, vfife_runs: list) -> pd.DataFrame:
    """``dynamics_ancf.csv``: one row per ANCF run and per VFIFE dynamic run
    (:data:`CSV_COLUMNS`, then :data:`CSV_EXTRA`); ``err_*`` against the common reference,
    ``self_err_*`` against the method's own (the VFIFE's: its ``dynamics.csv`` errors)."""
    refs = {id(c["run"]) for c in st.common.values() if c.get("run") is not None}
    picked = {id(p[m][1]) for p in st.picks for m in ("vfife", "ancf")
              if p.get(m) and p[m][0] == "run"}
    rows = []
    for r in st.runs:
        rows.append({
            "method": "ancf", "element_length": r.h, "steps_per_period": r.steps_per_period,
            "time_step": r.time_step, "steps": r.steps, "elements": r.elements,
            "newton_iterations_per_step": r.newton_iterations_per_step,
            "step_halvings": r.step_halvings, "wall_s": r.wall_s, "cpu_s": r.cpu_s,
            "wall_s_per_simulated_s": per_simulated_second(r.wall_s),
            "cpu_s_per_simulated_s": per_simulated_second(r.cpu_s),
            "hang_off_tension_amplitude": r.amplitude, "peak_moment": r.peak_moment,
            **{f"err_{q}": r.errors.get(q) for q in ("amplitude", "peak_moment")},
            **{f"self_err_{q}": r.self_errors.get(q) for q in ("amplitude", "peak_moment")},
            "peak_moment_s": r.peak_moment_s, "repeats": len(r.walls),
            "converged": r.converged, "reference": id(r) in refs, "picked": id(r) in picked,
            "integrator": r.integrator, "message": r.message})
    for r in vfife_runs:
        errs = st.vfife_errors.get(id(r), {})
        rows.append({
            "method": "vfife", "element_length": r.h, "time_step_factor": r.factor,
            "time_step": r.time_step, "steps": r.steps, "elements": r.elements,
            "wall_s": r.loop_wall_s, "cpu_s": r.cpu_s,
            "wall_s_per_simulated_s": per_simulated_second(r.loop_wall_s),
            "cpu_s_per_simulated_s": per_simulated_second(r.cpu_s),
            "hang_off_tension_amplitude": r.amplitude, "peak_moment": r.peak_moment,
            **{f"err_{q}": errs.get(q) for q in ("amplitude", "peak_moment")},
            **{f"self_err_{q}": r.errors.get(q) for q in ("amplitude", "peak_moment")},
            "peak_moment_s": r.peak_moment_s, "repeats": len(r.times),
            "converged": r.converged, "reference": id(r) in refs, "picked": id(r) in picked,
            "integrator": "central differences", "message": r.message})
    return pd.DataFrame(rows, columns=CSV_COLUMNS + CSV_EXTRA)

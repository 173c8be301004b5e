"""Property-based fuzzing of the newer features and their combinations (issue 44, part 6):
waves (regular trains, spectra, tables), a vessel and its RAO tables, top motions (harmonic,
time series, orbits, a series per axis), [design] and [design.fatigue] with their scatter
diagrams, end joints, a tensioner, point attachments, currents at any heading or turning
with depth, [internal_flow].

Each input is a built-in scene (the seeds: every built-in and example scene) onto which
1-4 *features* are grafted: a feature table harvested from another seed (so that the
combinations the seeds never meet are tried: a vessel on a TTR, attachments in a sea, a
scatter diagram on a lazy wave) or generated here with values drawn across and beyond
each key's range (an RAO twenty times too large, a ramp longer than the run, a corrosion
allowance equal to the wall, an output interval of a microsecond). Then, half the time,
the existing mutations of ``fuzz_strategies.mutate_dict`` on top.

Oracle (as the other fuzz tests): every input is read as `riser-verify solve FILE` reads it
and ends accepted (with no NaN or inf in the scene) or refused with one line naming the
key; any traceback, multi-line refusal or NaN is a finding. An accepted scene with a
[dynamics] table also has its hang-off path evaluated over the run (finite, or refused in
one line), and a sample of the accepted ones is solved: the analytic method at once, the
VFIFE's statics, and the VFIFE's dynamics cut to a few seconds (within a budget, capped in
elements): converged without NaN, or a status with its reason.

Default run: 300 inputs; ``-m slow``: 10,000 inputs (``RISER_FUZZ_SCALE`` scales them).
The outcome classes are printed (``-s``) and counted in the closing note of issue 44.
"""

from __future__ import annotations

import copy
import math
import tomllib

import numpy as np
import pytest
from fuzz_strategies import (
    MAX_LENGTH,
    SEED_PATHS,
    PROJECT_ERRORS,
    Input,
    Mutated,
    Tally,
    _f,
    _head,
    _where,
    apply_text_ops,
    check_refusal,
    mutate_dict,
    read_written,
    run_fuzz,
    scale,
    seed_dicts,
    solve_outcome,
    time_limit,
    OverBudget,
    write_toml,
)
from hypothesis import strategies as st

from riser.model.scene import FixedEnds
from verification.catalog import resolve

SEEDS = seed_dicts(SEED_PATHS)

#: the feature tables a seed may carry, by their path in the scene file
FEATURE_PATHS = [("environment", "waves"), ("environment", "current"), ("vessel",),
                 ("dynamics",), ("design",), ("ends", "anchor_joint"),
                 ("ends", "hang_off_joint"), ("ends", "tensioner"), ("attachments",),
                 ("internal_flow",), ("seabed",)]


def _harvest() -> dict[tuple, list]:
    """path -> the feature tables the seeds carry there (each once)."""
    out: dict[tuple, list] = {p: [] for p in FEATURE_PATHS}
    for data in SEEDS.values():
        for path in FEATURE_PATHS:
            node = data
            for key in path:
                node = node.get(key) if isinstance(node, dict) else None
                if node is None:
                    break
            if node is not None and node not in out[path]:
                out[path].append(copy.deepcopy(node))
    return out


HARVEST = _harvest()


# ============================================================================ generated features
@st.composite
def _num(draw, lo: float, hi: float, *, wild: tuple = ()):
    """A number in [lo, hi], or one time in twenty one of the wild values (out of range,
    zero, negative, huge): a feature has several numbers, and most inputs should get past
    the reader to the checks behind it."""
    if draw(st.integers(0, 19)) == 0:
        return draw(st.sampled_from(list(wild) or [0.0, -1.0, 1e9, 1e-9]))
    return draw(_f(lo, hi))


@st.composite
def wave_table(draw) -> dict:
    kind = draw(st.sampled_from(["train", "trains", "jonswap", "pm", "table"]))
    out: dict = {}
    if draw(st.booleans()):
        out["ramp_time"] = draw(_num(0.0, 200.0, wild=(5000.0, 1e4, 0.0, 1e-3)))
    if draw(st.integers(0, 4)) == 0:
        out["stretching"] = draw(st.sampled_from(["wheeler", "vertical", "linear"]))
    if draw(st.integers(0, 4)) == 0:
        out["line_loads"] = draw(st.booleans())
    if kind in ("train", "trains"):
        trains = []
        for _ in range(1 if kind == "train" else draw(st.integers(2, 3))):
            trains.append({"height": draw(_num(0.1, 30.0, wild=(40.0, 0.0, 60.0))),
                           "period": draw(_num(3.0, 25.0, wild=(1.0, 0.5, 100.0))),
                           "heading_deg": draw(st.sampled_from([0.0, 45.0, 90.0, 180.0,
                                                                -30.0, 400.0]))})
        out["trains"] = trains
    else:
        spec: dict = {"kind": {"jonswap": "jonswap", "pm": "pierson-moskowitz",
                               "table": "table"}[kind]}
        if kind == "table":
            n = draw(st.integers(2, 6))
            om = sorted(draw(st.lists(_f(0.1, 3.0), min_size=n, max_size=n, unique=True)))
            spec["omega"] = om
            spec["density"] = draw(st.lists(_num(0.0, 5.0), min_size=n, max_size=n))
        else:
            spec["hs"] = draw(_num(0.5, 15.0, wild=(30.0, 0.0, 20.0)))
            spec["tp"] = draw(_num(4.0, 20.0, wild=(2.0, 1.0, 50.0)))
            if kind == "jonswap" and draw(st.booleans()):
                spec["gamma"] = draw(_num(1.0, 7.0, wild=(0.5, 20.0)))
        spec["components"] = draw(st.sampled_from([4, 20, 50, 100, 3, 6000]))
        spec["seed"] = draw(st.integers(0, 5))
        if draw(st.integers(0, 3)) == 0:
            spec["heading_deg"] = draw(st.sampled_from([0.0, 30.0, 90.0, 180.0]))
        out["spectrum"] = spec
    return out


DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")


@st.composite
def vessel_table(draw) -> dict:
    n = draw(st.integers(2, 5))
    periods = sorted(draw(st.lists(_f(2.0, 30.0), min_size=n, max_size=n, unique=True)))
    if draw(st.integers(0, 6)) == 0:
        periods = periods[::-1]                               # unsorted: refused
    raos = []
    for heading in draw(st.sampled_from([[0.0], [0.0, 90.0], [180.0], [0.0, 45.0, 90.0]])):
        table: dict = {"heading_deg": heading, "periods": periods}
        for dof in DOFS:
            rotation = dof in ("roll", "pitch", "yaw")
            # a realistic table (<= 1.2 m/m, <= 3 deg/m), or one far too large
            big = draw(st.integers(0, 5)) == 0
            hi = (60.0 if rotation else 20.0) if big else (3.0 if rotation else 1.2)
            table[dof] = draw(st.lists(_f(0.0, hi), min_size=n, max_size=n))
            table[f"{dof}_phase_deg"] = draw(st.lists(_f(-360.0, 360.0), min_size=n,
                                                      max_size=n))
        raos.append(table)
    out = {"heading_deg": draw(st.sampled_from([0.0, 90.0, 180.0, 30.0])),
           "hang_off_on_vessel": [draw(_f(-60.0, 60.0)), draw(_f(-20.0, 5.0)),
                                  draw(_f(-20.0, 20.0))],
           "raos": raos}
    return out


@st.composite
def dynamics_table(draw) -> dict:
    duration = draw(_num(5.0, 120.0, wild=(0.1, 1e6)))
    out: dict = {"duration": duration}
    if draw(st.booleans()):
        out["output_interval"] = draw(st.sampled_from([0.1, 0.5, 1.0, 1e-6, 1e-4,
                                                        duration, 2 * duration]))
    if draw(st.integers(0, 3)) == 0:
        out["damping"] = draw(_num(0.0, 1.0, wild=(100.0, -0.1)))
    if draw(st.integers(0, 3)) == 0:
        out["statistics_start"] = draw(_f(0.0, 1.2 * duration))
    kind = draw(st.sampled_from(["none", "harmonic", "series", "orbit", "axes"]))
    if kind == "none":
        return out
    tm: dict = {}
    if kind == "harmonic":
        tm = {"axis": draw(st.sampled_from(["x", "y", "z", "q"])),
              "amplitude": draw(_num(0.0, 5.0, wild=(50.0, 0.0, 1000.0))),
              "period": draw(_num(3.0, 30.0, wild=(0.1, 1.0)))}
    elif kind == "orbit":
        tm = {"amplitudes": [draw(_num(0.0, 3.0)) for _ in range(3)],
              "phases_deg": [draw(_f(-360.0, 360.0)) for _ in range(3)],
              "period": draw(_num(4.0, 20.0, wild=(0.2,)))}
    else:
        n = draw(st.integers(2, 6))
        times = sorted(draw(st.lists(_f(0.0, duration), min_size=n, max_size=n,
                                     unique=True)))
        if kind == "series":
            tm = {"axis": draw(st.sampled_from(["x", "y", "z"])), "times": times,
                  "displacements": [0.0] + draw(st.lists(_num(-2.0, 2.0), min_size=n - 1,
                                                         max_size=n - 1))}
        else:
            tm = {"times": times}
            for ax in draw(st.sampled_from([("x",), ("x", "y"), ("x", "y", "z"), ("z",)])):
                tm[f"displacements_{ax}"] = [0.0] + draw(st.lists(
                    _num(-2.0, 2.0), min_size=n - 1, max_size=n - 1))
    if draw(st.booleans()):
        tm["ramp_time"] = draw(_num(0.0, duration, wild=(5000.0, 2 * duration)))
    out["top_motion"] = tm
    return out


@st.composite
def design_table(draw) -> dict:
    out: dict = {"code": draw(st.sampled_from(["dnv-st-f201", "api-rp-2rd", "dnv-os-f201"]))}
    if draw(st.booleans()):
        out["load_class"] = draw(st.sampled_from(["operating", "extreme", "survival"]))
    if draw(st.booleans()):
        out["safety_class"] = draw(st.sampled_from(["low", "normal", "high"]))
    if draw(st.booleans()):
        out["corrosion_allowance"] = draw(st.sampled_from([0.0, 0.001, 0.003, 0.0191,
                                                           0.0254, 0.02, 0.1]))
    if draw(st.booleans()):
        out["internal_pressure"] = draw(_num(0.0, 5e7, wild=(2e8, -1.0)))
    if draw(st.booleans()):
        fatigue: dict = {"sn_curve": draw(st.sampled_from(["D", "F1", "B1", "X"])),
                         "scf": draw(_num(1.0, 2.0, wild=(0.5, 0.0)))}
        states = []
        for _ in range(draw(st.integers(0, 4))):
            states.append({"hs": draw(_num(0.5, 8.0, wild=(20.0, 0.0))),
                           "tp": draw(_num(5.0, 16.0, wild=(2.0, 3.0))),
                           "probability": draw(_num(0.0, 1.0, wild=(1.5, -0.1)))})
        if states:
            fatigue["sea_states"] = states
        out["fatigue"] = fatigue
    return out


@st.composite
def joint_table(draw) -> dict:
    kind = draw(st.sampled_from(["pinned", "clamped", "spring", "free", "rigid"]))
    out: dict = {"kind": kind}
    if kind in ("clamped", "spring") or draw(st.integers(0, 5)) == 0:
        # degrees, or now and then radians typed by mistake (1.5708)
        out["direction_deg"] = draw(st.sampled_from([90.0, 80.0, 45.0, 1.5708, 0.0, 200.0]))
    if kind == "spring" or draw(st.integers(0, 5)) == 0:
        out["rotational_stiffness"] = draw(_num(1e4, 1e8, wild=(0.0, -1.0, 1e13)))
    return out


@st.composite
def tensioner_table(draw) -> dict:
    return {"top_tension": draw(_num(1e4, 5e6, wild=(0.0, 1.0, 1e10))),
            "stiffness": draw(_num(0.0, 1e6, wild=(-1.0, 1e11)))}


@st.composite
def attachments_table(draw) -> list:
    out = []
    for _ in range(draw(st.integers(1, 3))):
        a: dict = {"s_fraction": draw(_num(0.02, 0.98, wild=(0.0, 1.0, -0.1, 1.5)))}
        if draw(st.booleans()):
            a["mass"] = draw(_num(0.0, 2e4))
        if draw(st.booleans()):
            a["volume"] = draw(_num(0.0, 30.0))
        if draw(st.booleans()):
            a["drag_area"] = draw(_num(0.0, 5.0))
        out.append(a)
    return out


@st.composite
def current_table(draw) -> dict:
    n = draw(st.integers(2, 4))
    heights = sorted(draw(st.lists(_f(0.0, 1.0), min_size=n, max_size=n, unique=True)))
    heights = [round(h, 6) for h in heights]          # fractions of the depth: scaled below
    if len(set(heights)) < n:
        heights = [i / (n - 1) for i in range(n)]
    out: dict = {"heights": heights,
                 "speeds": draw(st.lists(_num(-1.5, 1.5, wild=(10.0, 11.0)), min_size=n,
                                         max_size=n))}
    if draw(st.booleans()):
        out["headings_deg"] = draw(st.lists(st.sampled_from([0.0, 45.0, 90.0, 180.0]),
                                            min_size=n, max_size=n))
    else:
        out["heading_deg"] = draw(st.sampled_from([0.0, 30.0, 90.0, 135.0, 180.0, -90.0]))
    return out


GENERATORS = {("environment", "waves"): wave_table(), ("vessel",): vessel_table(),
              ("dynamics",): dynamics_table(), ("design",): design_table(),
              ("ends", "anchor_joint"): joint_table(), ("ends", "hang_off_joint"): joint_table(),
              ("ends", "tensioner"): tensioner_table(), ("attachments",): attachments_table(),
              ("environment", "current"): current_table()}


def _line_length(data: dict) -> float:
    try:
        return float(sum(seg["length"] for seg in data.get("segments", [])))
    except (TypeError, KeyError, ValueError):
        return 1000.0


def _depth(data: dict) -> float:
    env = data.get("environment") or {}
    ends = data.get("ends") or {}
    for v in (env.get("water_depth"), (ends.get("hang_off") or [0, None])[1],
              ends.get("hang_off_height")):
        if isinstance(v, (int, float)) and v > 0:
            return float(v)
    return 1000.0


def _fit(data: dict, path: tuple, value):
    """A generated feature scaled to the seed: attachments' s from fractions of the line's
    length, a current's heights from fractions of the depth."""
    if path == ("attachments",):
        L = _line_length(data)
        for a in value:
            a["s"] = a.pop("s_fraction") * L
    elif path == ("environment", "current"):
        D = _depth(data)
        value["heights"] = [h * D for h in value["heights"]]
    return value


def _graft(data: dict, path: tuple, value) -> None:
    node = data
    for key in path[:-1]:
        nxt = node.get(key)
        if not isinstance(nxt, dict):
            nxt = {}
            node[key] = nxt
        node = nxt
    node[path[-1]] = value


def _couple(draw, data: dict, steps: list) -> None:
    """Most of the time, what a grafted feature needs beside it (so that the input gets
    past the reader's cross-part rules to the checks behind them): a vessel gets waves and
    no top motion; waves or a vessel get a run to move."""
    env = data.setdefault("environment", {})
    if "vessel" in data and "waves" not in env:
        env["waves"] = _fit(data, ("environment", "waves"), draw(wave_table()))
        steps.append("with generated waves for the vessel")
    if "vessel" in data and isinstance(data.get("dynamics"), dict):
        if data["dynamics"].pop("top_motion", None) is not None:
            steps.append("top motion dropped for the vessel")
    if ("vessel" in data or "waves" in env) and "dynamics" not in data:
        data["dynamics"] = {"duration": draw(_num(10.0, 100.0))}
        steps.append("with a [dynamics] run")
    if "water_depth" not in env and ("waves" in env):
        env["water_depth"] = _depth(data)
        steps.append("with the water depth")


@st.composite
def featured_inputs(draw) -> Input:
    """A seed with 1-4 features grafted (harvested from another seed or generated), then,
    half the time, mutated."""
    name = draw(st.sampled_from(sorted(SEEDS)))
    data = copy.deepcopy(SEEDS[name])
    steps = []
    for _ in range(draw(st.integers(1, 4))):
        path = draw(st.sampled_from(FEATURE_PATHS))
        harvested = HARVEST.get(path) or []
        if path in GENERATORS and (not harvested or draw(st.booleans())):
            value = _fit(data, path, draw(GENERATORS[path]))
            steps.append(f"generated {'.'.join(path)}")
        elif harvested:
            value = copy.deepcopy(draw(st.sampled_from(harvested)))
            steps.append(f"grafted {'.'.join(path)}")
        else:
            continue
        _graft(data, path, value)
    if draw(st.integers(0, 3)) > 0:
        _couple(draw, data, steps)
    if draw(st.booleans()):
        m = mutate_dict(draw, data, n_max=2)
    else:
        m = Mutated(data, [])
    text = write_toml(m.data)
    tomllib.loads(text)                  # the writer's own check: a bug here is the test's
    text, more, must = apply_text_ops(draw, text, m.text_ops)
    describe = f"the built-in {name}; " + "; ".join(steps + m.steps + more)
    return Input(text, describe, files={"scene.toml": text},
                 must_refuse=m.must_refuse or must)


# ============================================================================ the checks
#: a dynamic fuzz solve: at most this many elements, this long a run (s) and this budget (s)
DYN_MAX_ELEMENTS = 100
DYN_MAX_DURATION = 3.0
DYN_BUDGET = 40.0


class FeatureFuzz:
    """Reads each input; evaluates the hang-off path of a dynamic scene; solves a sample."""

    def __init__(self, kind: str, folder, *, static_every: int, static_max: int,
                 dynamic_every: int, dynamic_max: int):
        self.tally = Tally(kind)
        self.dir = folder
        self.accepted = 0
        self.dynamic_accepted = 0
        self.static_every, self.static_max = static_every, static_max
        self.dynamic_every, self.dynamic_max = dynamic_every, dynamic_max
        self.static_solved = self.dynamic_solved = 0

    def __call__(self, inp: Input) -> None:
        scene = read_written(self.tally, inp, self.dir)
        if scene is None:
            return
        self.accepted += 1
        solve_outcome(self.tally, "analytic", scene, inp, budget=20.0)
        if scene.dynamics is not None and isinstance(scene.ends, FixedEnds):
            # (a touchdown form's hang-off is known after its conversion to fixed ends,
            # which the pipeline does before any dynamic run)
            self.dynamic_accepted += 1
            self._path(scene, inp)
        if scene.total_length > MAX_LENGTH or not isinstance(scene.ends, FixedEnds):
            return
        if self.accepted % self.static_every == 0 and self.static_solved < self.static_max:
            self.static_solved += 1
            solve_outcome(self.tally, "vfife", scene, inp, budget=30.0)
        if (scene.dynamics is not None and self.dynamic_accepted % self.dynamic_every == 0
                and self.dynamic_solved < self.dynamic_max):
            self.dynamic_solved += 1
            self._dynamic(scene, inp)

    def _path(self, scene, inp: Input) -> None:
        """The hang-off's prescribed path over the run: finite, or refused in one line."""
        from riser.physics.hang_off_motion import HangOffPath
        counts = self.tally.solve.setdefault("hang-off path", __import__("collections").Counter())
        try:
            with time_limit(10.0):
                t = np.linspace(0.0, scene.dynamics.duration, 201)
                d = np.asarray(HangOffPath(scene)(t), dtype=float)
        except OverBudget:
            counts["over budget"] += 1
            self.tally.note("hang-off path over budget", "HangOffPath", "10 s", inp)
            return
        except PROJECT_ERRORS as exc:
            if check_refusal(self.tally, exc, inp):
                counts["refused by the method"] += 1
            else:
                counts["finding"] += 1
            return
        except Exception as exc:             # noqa: BLE001
            counts["finding"] += 1
            self.tally.finding("traceback in the hang-off path", _where(exc), _head(exc), inp)
            return
        if not np.all(np.isfinite(d)):
            counts["finding"] += 1
            self.tally.finding("NaN in the hang-off path", "HangOffPath", "non-finite", inp)
            return
        counts["converged"] += 1

    def _dynamic(self, scene, inp: Input) -> None:
        """The VFIFE's dynamics, cut to a few seconds on a coarse mesh."""
        dyn = scene.dynamics
        duration = min(dyn.duration, DYN_MAX_DURATION)
        # in this order: each step keeps the run valid (statistics_start < duration,
        # output_interval <= duration)
        changes = {"dynamics.statistics_start": 0.0,
                   "dynamics.output_interval": max(min(dyn.output_interval, duration),
                                                   duration / 20),
                   "dynamics.duration": duration}
        h = max(scene.vfife.element_length, scene.total_length / DYN_MAX_ELEMENTS)
        try:
            if dyn.top_motion is not None and dyn.top_motion.ramp > duration:
                changes = {"dynamics.top_motion.ramp_time": duration, **changes}
            cut = scene.replace(**changes)
            cut = cut.replace(**{"vfife.element_length": h})
        except PROJECT_ERRORS as exc:          # the cut itself refused: not the solver's
            self.tally.note("dynamic cut refused", _where(exc), _head(exc), inp)
            return
        except Exception as exc:               # noqa: BLE001
            self.tally.note("dynamic cut not applicable", _where(exc), _head(exc), inp)
            return
        solve_dynamic_outcome(self.tally, cut, inp, DYN_BUDGET)


def solve_dynamic_outcome(tally: Tally, scene, inp: Input, budget: float) -> str:
    """fuzz_strategies.solve_outcome with the dynamics kept (it drops them)."""
    import collections

    import vfife
    from riser.results.result import Status
    counts = tally.solve.setdefault("vfife dynamics", collections.Counter())
    try:
        with time_limit(budget):
            res = vfife.solve(scene)
    except OverBudget:
        counts["over budget"] += 1
        tally.note("vfife dynamics over budget", "vfife", f"{budget:g} s", inp)
        return "over budget"
    except PROJECT_ERRORS as exc:
        ok = check_refusal(tally, exc, inp)
        counts["refused by the method" if ok else "finding"] += 1
        return "refused by the method" if ok else "finding"
    except Exception as exc:                   # noqa: BLE001
        counts["finding"] += 1
        tally.finding("traceback in a dynamic vfife.solve", _where(exc), _head(exc), inp)
        return "finding"
    if res.status is Status.CONVERGED:
        dyn = res.dynamics
        # NaN is the documented "none" of the touchdown columns (a line off the seabed at
        # that time: docs/results.md); anywhere else it is a defect
        bad = [k for k, v in (dyn.timeseries if dyn else {}).items()
               if not k.startswith("touchdown_") and np.asarray(v).dtype.kind == "f"
               and not np.all(np.isfinite(v))]
        if res.profile is None or dyn is None or bad:
            counts["finding"] += 1
            tally.finding("converged dynamic run with a defect", "vfife",
                          f"profile {res.profile is not None}, dynamics {dyn is not None}, "
                          f"non-finite {bad[:4]}", inp)
            return "finding"
        counts["converged"] += 1
        return "converged"
    if not str(res.message or "").strip():
        counts["finding"] += 1
        tally.finding("dynamic run failed without a reason", "vfife", res.status.value, inp)
        return "finding"
    counts["refused by the method" if res.status is Status.REFUSED else "not converged"] += 1
    return res.status.value


def test_features_are_harvested():
    """The fuzz's footing: the seeds carry every feature it grafts."""
    missing = [".".join(p) for p in FEATURE_PATHS if not HARVEST[p]]
    assert not missing, missing


def test_fuzz_features(tmp_path):
    """300 scenes with features grafted and generated, reproducible: no finding."""
    fuzz = FeatureFuzz("features", tmp_path, static_every=40, static_max=3,
                       dynamic_every=25, dynamic_max=2)
    run_fuzz(featured_inputs(), fuzz, max_examples=300)
    fuzz.tally.check()


@pytest.mark.slow
def test_fuzz_features_slow(tmp_path):
    """10,000 scenes with features (x RISER_FUZZ_SCALE), ~40 VFIFE statics and ~40 short
    VFIFE dynamic runs among them."""
    n = max(1, math.ceil(10_000 * scale()))
    fuzz = FeatureFuzz("features (slow)", tmp_path, static_every=60,
                       static_max=max(1, n // 250), dynamic_every=40,
                       dynamic_max=max(1, n // 250))
    run_fuzz(featured_inputs(), fuzz, max_examples=n)
    fuzz.tally.check()


@pytest.mark.parametrize("seed", ["wang2014-current-neg1p5", "kang2015-jlay", "wang2014-baseline"])
@pytest.mark.parametrize("table", ["tensioner", "anchor_joint", "hang_off_joint"])
def test_a_joint_or_tensioner_needs_fixed_ends(tmp_path, seed, table):
    """The fuzz's first finding (a traceback: TdpTensionEnds got a tensioner): a joint or a
    tensioner under a touchdown, angle or J-lay [ends] is refused in one line naming it."""
    from riser.errors import SceneError
    data = copy.deepcopy(SEEDS[seed])
    data["ends"][table] = ({"top_tension": 1.6e6} if table == "tensioner"
                           else {"kind": "clamped", "direction_deg": 90.0})
    path = tmp_path / "scene.toml"
    path.write_text(write_toml(data), encoding="utf-8")
    with pytest.raises(SceneError) as err:
        resolve(str(path))
    msg = str(err.value)
    assert "\n" not in msg and f"ends.{table}" in msg, msg


def test_a_vessel_with_a_joint_and_no_water_depth_is_one_line(tmp_path):
    """The fuzz's finding (a TypeError in riser/waves.wave_numbers): the end checks asked
    whether the vessel's motion leaves the plane before the sea-state checks had refused
    waves without a water depth. Now the refusal names the missing depth."""
    from riser.errors import SceneError
    data = copy.deepcopy(SEEDS["jumper-vessel-wave"])
    data["ends"]["hang_off_joint"] = {"kind": "spring", "direction_deg": 80.0,
                                      "rotational_stiffness": 1e6}
    del data["environment"]["water_depth"]
    path = tmp_path / "scene.toml"
    path.write_text(write_toml(data), encoding="utf-8")
    with pytest.raises(SceneError, match="water_depth") as err:
        resolve(str(path))
    assert "\n" not in str(err.value)

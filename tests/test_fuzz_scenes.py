"""Property-based fuzzing of scene files (issue 30, part 5): generated scenes and mutations
of the built-in ones, read as the command line reads them (``verification.catalog.resolve``
on a file), and a sample of the accepted ones solved by the three methods within a budget.
Every input ends accepted (and, if solved, converged or not converged with a reason) or
refused with one line naming the key; anything else is a finding (``fuzz_strategies``).

Default run: 240 inputs and 73 names or paths;
``-m slow``: 6000 inputs (``RISER_FUZZ_SCALE`` scales it).
"""

from __future__ import annotations

import copy
import math
import tomllib
from pathlib import Path

import pytest
from fuzz_strategies import (
    MAX_LENGTH,
    SEED_PATHS,
    Input,
    Mutated,
    Tally,
    apply_text_ops,
    generated_scene,
    mutate_dict,
    read_written,
    run_fuzz,
    run_path_fuzz,
    scale,
    seed_dicts,
    solve_outcome,
    write_toml,
)
from hypothesis import strategies as st

from riser.model.scene import FixedEnds
from verification.catalog import resolve

SEEDS = seed_dicts(SEED_PATHS)


@st.composite
def scene_inputs(draw) -> Input:
    """A scene file: a built-in scene or a generated one, mutated (or, for some generated
    ones, as generated)."""
    kind = draw(st.sampled_from(["seed", "seed", "seed", "generated", "generated", "plain"]))
    if kind == "seed":
        name = draw(st.sampled_from(sorted(SEEDS)))
        base, what = SEEDS[name], f"the built-in {name}"
    else:
        base, what = draw(generated_scene()), "a generated scene"
    m = Mutated(copy.deepcopy(base), []) if kind == "plain" else mutate_dict(draw, base)
    text = write_toml(m.data)
    tomllib.loads(text)                  # the writer's own check: a bug here is the test's
    text, steps, must = apply_text_ops(draw, text, m.text_ops)
    steps = m.steps + steps
    return Input(text, f"{what}; " + ("; ".join(steps) or "unmutated"),
                 files={"scene.toml": text}, must_refuse=m.must_refuse or must)


class SceneFuzz:
    """Reads each input as `riser-verify solve FILE` does; solves a sample of the accepted."""

    def __init__(self, kind: str, folder: Path, bvp_every: int, bvp_max: int,
                 vfife_every: int, vfife_max: int):
        self.tally = Tally(kind)
        self.dir = folder
        self.accepted = 0
        self.eligible = {"bvp": 0, "vfife": 0}     # accepted scenes a method could solve
        self.solved = {"bvp": 0, "vfife": 0}
        self.solves = {"bvp": (bvp_every, bvp_max), "vfife": (vfife_every, vfife_max)}

    def __call__(self, inp: Input) -> None:
        scene = read_written(self.tally, inp, self.dir)
        if scene is None:
            return
        self.accepted += 1
        solve_outcome(self.tally, "analytic", scene, inp, budget=20.0)     # milliseconds
        if scene.total_length > MAX_LENGTH or len(scene.segments) > 12:
            return
        for method, (every, most) in self.solves.items():
            if method == "vfife" and not isinstance(scene.ends, FixedEnds):
                solve_outcome(self.tally, method, scene, inp)       # refused at once
                continue
            self.eligible[method] += 1
            if self.eligible[method] % every == 0 and self.solved[method] < most:
                self.solved[method] += 1
                solve_outcome(self.tally, method, scene, inp, budget=30.0)


def test_seeds_are_accepted_and_written_back_equal():
    """The fuzz's own footing: every seed reads as is, and the TOML writer gives it back."""
    assert len(SEEDS) >= 10
    for path in SEED_PATHS:
        data = tomllib.loads(path.read_text(encoding="utf-8-sig"))
        assert tomllib.loads(write_toml(data)) == data, path
        resolve(str(path))


def test_fuzz_scenes(tmp_path):
    """240 generated scene files, reproducible: no finding; counts printed."""
    fuzz = SceneFuzz("scenes", tmp_path, bvp_every=8, bvp_max=6, vfife_every=6, vfife_max=4)
    run_fuzz(scene_inputs(), fuzz, max_examples=240)
    fuzz.tally.check()


@pytest.mark.slow
def test_fuzz_scenes_slow(tmp_path):
    """6000 generated scene files (x RISER_FUZZ_SCALE), ~100 BVP and ~40 VFIFE solves."""
    n = max(1, math.ceil(6000 * scale()))
    fuzz = SceneFuzz("scenes (slow)", tmp_path, bvp_every=15, bvp_max=max(1, n // 60),
                     vfife_every=12, vfife_max=max(1, n // 150))
    run_fuzz(scene_inputs(), fuzz, max_examples=n)
    fuzz.tally.check()


def test_fuzz_scene_paths(tmp_path):
    """33 odd names and special files (a FIFO, a directory, a link loop, binary, UTF-16,
    a name too long for the file system, ...) and 40 generated names where
    a scene file is expected."""
    run_path_fuzz("scene paths", resolve, tmp_path, 40).check()

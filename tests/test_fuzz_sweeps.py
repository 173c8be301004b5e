"""Property-based fuzzing of sweep files (issue 30, part 5): generated sweeps over built-in
and generated base scenes, and mutations of the built-in sweeps (bad key paths, bases,
methods, zips, products over the case limit, and the generic mutations of
``fuzz_strategies``), read as ``riser-verify sweep`` reads them
(``verification.sweeps.file.load_sweep``), a sample of the accepted cases solved.

Default run: 120 inputs and 73 names or paths;
``-m slow``: 2000 inputs (``RISER_FUZZ_SCALE`` scales it).
"""

from __future__ import annotations

import copy
import dataclasses
import math
import shutil
import tomllib
from pathlib import Path
from typing import Any

import pytest
from fuzz_strategies import (
    MAX_LENGTH,
    SPECIAL_STRINGS,
    Input,
    Tally,
    apply_text_ops,
    check_scene,
    generated_scene,
    mutate_dict,
    read_outcome,
    run_fuzz,
    run_path_fuzz,
    scale,
    seed_dicts,
    solve_outcome,
    write_toml,
)
from hypothesis import strategies as st

from riser.io.scene_file import parse_scene
from riser.model.scene import FixedEnds
from verification.catalog import builtin_paths
from verification.sweeps.file import MAX_CASES, SWEEP_DIR, load_sweep

SEEDS = seed_dicts(SWEEP_DIR.glob("*.toml"))
#: built-in scenes a generated sweep varies (small and quick to validate)
BASES = [n for n in ("scr-steel", "yu2021-a3", "yu2021-a1", "wang2014-baseline",
                     "kang2015-jlay", "hard-deep-scr", "liu2021-scr") if n in builtin_paths()]
BASE_DICTS = seed_dicts(builtin_paths()[n] for n in BASES)

#: key paths a sweep must refuse (syntax, a value's child, an index past the end, the fixed
#: roots name and dynamics)
BAD_KEYS = ["", " ", ".", "a..b", "segments[", "segments[-1].length", "segments[99].length",
            "segments.length", "ends.hang_off.x", "ends.hang_off[0]", "name",
            "dynamics.duration", "Segments[0]]", "segments[0 ].length", "segments[1e2].length",
            "\u00e9.x", "a b", "segments[0].length.x", "ends[0]"]
BAD_BASES: list[Any] = ["scr-stel", "", " ", "missing.toml", 42, ["scr-steel"], "../nope/x.toml",
                        "x" * 300, "/dev/null", ".", "verification", "scr-steel\u0000", True,
                        {"a": 1}, "nested/dir/", "\n"]
BAD_METHODS: list[Any] = [[], "bvp", ["bvp", "bvp"], ["BVP"], ["moordyn"], [1], [["bvp"]],
                          ["bvp", None] if False else ["bvp", ""], {}, True]


def sweep_keys(scene: dict) -> list[tuple[str, Any]]:
    """(dotted key path, value) of every value of a scene a sweep may vary."""
    out: list[tuple[str, Any]] = []

    def walk(node: dict, prefix: str) -> None:
        for k, v in node.items():
            key = f"{prefix}.{k}" if prefix else k
            if isinstance(v, dict):
                walk(v, key)
            elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
                for i, item in enumerate(v):
                    walk(item, f"{key}[{i}]")
            else:
                out.append((key, v))

    walk(scene, "")
    return [(k, v) for k, v in out if k.split(".")[0].split("[")[0] not in ("name", "dynamics")]


def perturbed(draw, v: Any) -> Any:
    """A value near ``v`` of its type (most of a sweep's values are plausible)."""
    if isinstance(v, bool):
        return draw(st.booleans())
    if isinstance(v, (int, float)):
        return type(v)(v * draw(st.sampled_from([0.9, 1.0, 1.1, 0.5, 2.0]))) if v else \
            draw(st.sampled_from([0.0, 0.1, 1.0]))
    if isinstance(v, list):
        f = draw(st.sampled_from([0.95, 1.0, 1.05]))
        return [x * f if isinstance(x, (int, float)) and not isinstance(x, bool) else x
                for x in v]
    if isinstance(v, str):               # a label, a title, a name: any text
        return draw(st.sampled_from(SPECIAL_STRINGS)) if draw(st.booleans()) else v
    return v


@st.composite
def generated_sweep(draw) -> tuple[dict, dict]:
    """A sweep over a built-in scene, or over a generated scene file beside it."""
    files: dict = {}
    if draw(st.integers(0, 3)) == 0:
        scene = draw(generated_scene(name="fz-base"))
        base, base_dict = "base.toml", scene
        files["base.toml"] = write_toml(scene)
    else:
        base = draw(st.sampled_from(BASES))
        base_dict = BASE_DICTS[base]
        if draw(st.integers(0, 5)) == 0:
            base = str(builtin_paths()[base])               # an absolute path
    keys = sweep_keys(base_dict)
    d: dict = {"base": base}
    if draw(st.booleans()):
        d["methods"] = draw(st.sampled_from([["bvp"], ["vfife"], ["analytic"], ["bvp", "vfife"],
                                             ["vfife", "bvp", "analytic"]]))
    zip_all = draw(st.integers(0, 4)) == 0
    if zip_all:
        d["zip"] = True
    chosen = draw(st.lists(st.sampled_from(keys), min_size=1, max_size=3,
                           unique_by=lambda kv: kv[0]))
    n = draw(st.integers(1, 3))
    vary = []
    for i, (key, v) in enumerate(chosen):
        zipped = i > 0 and draw(st.integers(0, 3)) == 0
        count = n if zip_all or zipped else draw(st.integers(1, 3))
        if zipped:
            count = len(vary[-1]["values"])
        item = {"key": key, "values": [perturbed(draw, v) for _ in range(count)]}
        if zipped:
            item["zip"] = True
        vary.append(item)
    if draw(st.integers(0, 4)) == 0 and "title" not in {c[0] for c in chosen}:
        vary.append({"key": "title", "values": draw(st.lists(st.sampled_from(
            [s for s in SPECIAL_STRINGS if len(s) < 100]), min_size=1, max_size=2))})
    rest = [kv for kv in keys if kv[0] not in {c[0] for c in chosen}]
    if rest and draw(st.booleans()):
        key, v = draw(st.sampled_from(rest))
        d["set"] = {key: perturbed(draw, v)}
    d["vary"] = vary
    return d, files


def expected_cases(d: dict) -> int:
    """The number of cases of an accepted sweep, as docs/sweeps.md defines it."""
    zip_all = d.get("zip", False)
    dims: list[int] = []
    for v in d["vary"]:
        if (zip_all or v.get("zip", False)) and dims:
            continue
        dims.append(len(v["values"]))
    return math.prod(dims)


def sweep_op(draw, d: dict) -> tuple[str, str]:
    """One sweep-specific mutation, applied last: (step, what the reader must refuse)."""
    vary = d.get("vary")
    ok = (isinstance(vary, list) and vary and all(isinstance(v, dict) for v in vary)
          and all(isinstance(v.get("key"), str) for v in vary))
    op = draw(st.sampled_from(["bad_key", "bad_base", "bad_methods", "huge", "zip_mismatch",
                               "dup_key", "set_varied", "values_scalar", "none", "none",
                               "none", "none", "none"]))
    if op == "bad_base":
        d["base"] = draw(st.sampled_from(BAD_BASES))
        return f"base = {d['base']!r}", f"base {d['base']!r}"
    if op == "bad_methods":
        d["methods"] = draw(st.sampled_from(BAD_METHODS))
        return f"methods = {d['methods']!r}", f"methods {d['methods']!r}"
    if not ok:
        return "", ""
    i = draw(st.integers(0, len(vary) - 1))
    if op == "bad_key":
        vary[i]["key"] = draw(st.sampled_from(BAD_KEYS))
        return f"vary[{i}].key = {vary[i]['key']!r}", f"vary[{i}].key {vary[i]['key']!r}"
    if op == "huge":
        d.pop("zip", None)
        d["vary"] = [{"key": vary[0]["key"], "values": [vary[0].get("values", [0])] * 320},
                     {"key": vary[0]["key"] + "x", "values": [1.0] * 320}]
        return "two vary lists of 320 values", f"{320 * 320} cases > {MAX_CASES}"
    if op == "zip_mismatch" and len(vary) > 1 and isinstance(vary[i].get("values"), list) \
            and i > 0 and isinstance(vary[i - 1].get("values"), list):
        vary[i]["zip"] = True
        vary[i]["values"] = vary[i]["values"] + [vary[i]["values"][0]] * (
            len(vary[i - 1]["values"]) + 1 - len(vary[i]["values"]))
        return f"vary[{i}] zipped with a longer list", "zipped lists of unequal length"
    if op == "dup_key" and len(vary) > 1:
        vary[i]["key"] = vary[i - 1]["key"] if i else vary[1]["key"]
        return f"vary[{i}].key repeated", "a key varied twice"
    if op == "set_varied":
        d["set"] = {vary[i]["key"]: 1.0}
        return f"set also sets {vary[i]['key']!r}", "a key set and varied"
    if op == "values_scalar":
        vary[i]["values"] = draw(st.sampled_from([1.0, "x", {}, True]))
        return f"vary[{i}].values = {vary[i]['values']!r}", "values not an array"
    return "", ""


@st.composite
def sweep_inputs(draw) -> Input:
    kind = draw(st.sampled_from(["seed", "seed", "generated", "generated", "plain", "plain"]))
    if kind == "seed":
        name = draw(st.sampled_from(sorted(SEEDS)))
        data, files, what = copy.deepcopy(SEEDS[name]), {}, f"the built-in sweep {name}"
    else:
        data, files = draw(generated_sweep())
        what = "a generated sweep"
    steps: list[str] = []
    must, text_ops = "", []
    if kind != "plain":
        m = mutate_dict(draw, data, n_max=2, free_tables={("set",)})
        data, steps, text_ops = m.data, list(m.steps), m.text_ops
        must = m.must_refuse
        step, why = sweep_op(draw, data)
        if step:
            steps.append(step)
            must = must or why
    text = write_toml(data)
    tomllib.loads(text)
    text, tsteps, tmust = apply_text_ops(draw, text, text_ops)
    files = {"sweep.toml": text, **files}
    return Input(text, f"{what} ({data.get('base')!r}); " + ("; ".join(steps + tsteps)
                                                            or "unmutated"),
                 files=files, must_refuse=must or tmust)


class SweepFuzz:
    def __init__(self, kind: str, folder: Path, solve_every: int, solve_max: int):
        self.tally = Tally(kind)
        self.dir = folder / "sweep"
        self.accepted = 0
        self.solve_every, self.solve_max, self.solved = solve_every, solve_max, 0

    def __call__(self, inp: Input) -> None:
        shutil.rmtree(self.dir, ignore_errors=True)
        self.dir.mkdir(parents=True)
        for name, content in inp.files.items():
            (self.dir / name).write_text(content, encoding="utf-8")
        sweep = read_outcome(self.tally, inp, lambda: load_sweep(self.dir / "sweep.toml"))
        if sweep is None:
            return
        data = tomllib.loads(inp.text.lstrip("\ufeff"))
        want = expected_cases(data)
        if len(sweep.cases) != want:
            self.tally.accepted_finding("wrong number of cases", "verification/sweeps/file.py",
                               f"{len(sweep.cases)} cases, the file makes {want}", inp)
            return
        for case in sweep.cases:
            if not check_scene(self.tally, case.scene, inp):
                return
        for case in sweep.cases[:30]:    # the case's scene.toml a sweep writes reads back
            try:
                text = scene_text(sweep, case)
                back = parse_scene(text, "scene.toml")
            except Exception as exc:     # noqa: BLE001
                self.tally.accepted_finding("a case's scene.toml does not read back",
                                   "verification/sweeps/run.py (riser/io/toml_text.py)",
                                   f"{type(exc).__name__}: {str(exc)[:300]}", inp)
                return
            if dataclasses.replace(back, source=case.scene.source) != case.scene:
                self.tally.accepted_finding("a case's scene.toml reads back to another scene",
                                   "verification/sweeps/run.py (riser/io/toml_text.py)",
                                   f"case {case.index}: {_first_difference(back, case.scene)}",
                                   inp)
                return
        self.accepted += 1
        case = sweep.cases[len(sweep.cases) // 2]
        solve_outcome(self.tally, "analytic", case.scene, inp, budget=20.0)   # milliseconds
        if self.accepted % self.solve_every or self.solved >= self.solve_max:
            return
        method = sweep.methods[self.solved % len(sweep.methods)]
        if method == "analytic":
            method = "bvp"
        if method == "vfife" and not isinstance(case.scene.ends, FixedEnds):
            method = "bvp"
        if case.scene.total_length <= MAX_LENGTH:
            self.solved += 1
            solve_outcome(self.tally, method, case.scene, inp, budget=30.0)


def scene_text(sweep, case) -> str:
    """The text of a case's scene.toml, as the sweep writes it."""
    from verification.sweeps import run
    if hasattr(run, "_scene_text"):
        return run._scene_text(sweep, case)
    from riser.io.toml_text import dumps
    return dumps(case.scene_dict)


def _first_difference(a, b, path: str = "") -> str:
    if dataclasses.is_dataclass(a) and dataclasses.is_dataclass(b) and type(a) is type(b):
        for f in dataclasses.fields(a):
            if f.name != "source" and getattr(a, f.name) != getattr(b, f.name):
                return _first_difference(getattr(a, f.name), getattr(b, f.name),
                                         f"{path}.{f.name}".lstrip("."))
    if isinstance(a, (tuple, list)) and isinstance(b, (tuple, list)) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            if x != y:
                return _first_difference(x, y, f"{path}[{i}]")
    if isinstance(a, dict) and isinstance(b, dict) and a.keys() == b.keys():
        for k in a:
            if a[k] != b[k]:
                return _first_difference(a[k], b[k], f"{path}.{k}")
    return f"{path}: {a!r:.80} read back, {b!r:.80} in the sweep"


def test_seed_sweeps_are_accepted():
    assert len(SEEDS) >= 2 and BASES
    for name in SEEDS:
        assert load_sweep(name).cases


def test_fuzz_sweeps(tmp_path):
    """120 generated sweep files, reproducible: no finding; counts printed."""
    fuzz = SweepFuzz("sweeps", tmp_path, solve_every=6, solve_max=4)
    run_fuzz(sweep_inputs(), fuzz, max_examples=120)
    fuzz.tally.check()


@pytest.mark.slow
def test_fuzz_sweeps_slow(tmp_path):
    """2000 generated sweep files (x RISER_FUZZ_SCALE), ~40 case solves."""
    n = max(1, math.ceil(2000 * scale()))
    fuzz = SweepFuzz("sweeps (slow)", tmp_path, solve_every=15, solve_max=max(1, n // 50))
    run_fuzz(sweep_inputs(), fuzz, max_examples=n)
    fuzz.tally.check()


def test_fuzz_sweep_paths(tmp_path):
    """33 odd names and special files (a FIFO, a directory, a link loop, binary, UTF-16,
    a name too long for the file system, ...) and 40 generated names where
    a sweep file is expected."""
    run_path_fuzz("sweep paths", load_sweep, tmp_path, 40).check()

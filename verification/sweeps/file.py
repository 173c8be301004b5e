"""Reading a sweep file: TOML -> the validated list of load cases.

A sweep file (the contract; docs/sweeps.md)::

    base = "yu2021-a3"             # a built-in scene name, or a scene file (relative to
                                   # the sweep file's folder)
    methods = ["bvp", "vfife"]     # any of verification.methods.METHODS; default both
    zip = false                    # true: pair all the vary lists instead of their product
    [set]                          # optional: keys set in every case (e.g. a current's
    "environment.current.heights" = [0.0, 500.0]   # heights when the base has none)
    [[vary]]
    key = "ends.hang_off"          # a dotted key path into the scene file; arrays of
    values = [[613.42, 500.0], [633.42, 500.0]]   # tables indexed: segments[1].buoyancy
    [[vary]]
    key = "segments[3].buoyancy"
    values = [1130.0, 904.0]
    zip = true                     # this list pairs with the one before it (one dimension)

The cases are the product of the dimensions (the first varies slowest); a ``vary`` with
``zip = true`` joins the dimension before it, and a top-level ``zip = true`` pairs every
list. Each case is the base scene's TOML with the values put in, validated by the scene
reader exactly as a scene file, before anything runs: an invalid case raises one
:class:`~riser.errors.SceneError` naming the sweep file, the case index and its key. A
sweep solves statics: the base's ``[dynamics]`` are dropped (said in the report).
"""

from __future__ import annotations

import copy
import hashlib
import itertools
import json
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from riser.results import validity
from riser.errors import SceneError
from riser.io.scene_file import is_file, load_scene, path_problem, read_text, scene_from_dict
from riser.model.scene import Scene
from verification.catalog import builtin_paths, resolve
from verification.methods import METHODS

from . import inert

#: the most cases one sweep file may expand to (each is validated before anything runs,
#: about 1 ms each)
MAX_CASES = 100_000
#: bump when a case's result files change meaning: finished cases of another format rerun
CASE_FORMAT = 1
#: the built-in sweeps (``riser-verify sweep NAME``)
SWEEP_DIR = Path(__file__).parent / "builtin"
#: scene keys a sweep neither varies nor sets
FIXED_ROOTS = ("dynamics", "name")
_STEP = re.compile(r"^([A-Za-z_][A-Za-z0-9_-]*)(?:\[(\d+)\])?$")


@dataclass(frozen=True)
class Vary:
    key: str                      # the dotted key path, as written
    values: tuple                 # its values, as parsed from TOML
    zip: bool = False             # pairs with the vary before it


@dataclass(frozen=True)
class Case:
    index: int
    values: dict                  # key -> value of this case (every vary key)
    scene_dict: dict              # the case's scene file, as parsed TOML
    scene: Scene                  # validated
    digest: str                   # identifies the case's inputs (resume)


@dataclass
class Sweep:
    name: str                     # the sweep file's stem
    source: str                   # the sweep file as given (a path or a built-in name)
    base: str                     # as written in the file
    base_scene: Scene
    methods: tuple[str, ...]
    vary: tuple[Vary, ...]
    fixed: dict                   # [set]: key -> value
    cases: list[Case] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    builtin: bool = False         # a built-in sweep (verification/sweeps/builtin/)

    @property
    def keys(self) -> tuple[str, ...]:
        return tuple(v.key for v in self.vary)


def split_key(key: str) -> list[tuple[str, int | None]]:
    """``"segments[1].buoyancy"`` -> [("segments", 1), ("buoyancy", None)]; raises
    ValueError naming what is wrong."""
    if not isinstance(key, str) or not key.strip():
        raise ValueError("must be a non-empty dotted key path, e.g. \"ends.hang_off\"")
    steps = []
    for part in key.split("."):
        m = _STEP.match(part)
        if m is None:
            raise ValueError(f"{part!r} is not a key (letters, digits, '_' or '-', and an "
                             "optional [index] for an array of tables, e.g. segments[1])")
        steps.append((m.group(1), None if m.group(2) is None else int(m.group(2))))
    return steps


def set_value(data: dict, key: str, value) -> None:
    """Put ``value`` at the dotted ``key`` of the parsed scene ``data``, creating missing
    tables (the scene reader then says what else they need); raises ValueError when the
    path runs through a value or past the end of an array of tables."""
    steps = split_key(key)
    node, where = data, ""
    for n, (name, index) in enumerate(steps):
        last = n == len(steps) - 1
        where = f"{where}.{name}" if where else name
        if index is not None:
            arr = node.get(name)
            if not isinstance(arr, list) or not all(isinstance(t, dict) for t in arr):
                raise ValueError(f"{where} is not an array of tables in the base scene, so "
                                 f"{where}[{index}] does not exist")
            if index >= len(arr):
                raise ValueError(f"{where} has {len(arr)} "
                                 f"{'entry' if len(arr) == 1 else 'entries'} in the base "
                                 f"scene (indices 0 to {len(arr) - 1}), so {where}[{index}] "
                                 "does not exist")
            where = f"{where}[{index}]"
            if last:
                arr[index] = value
                return
            node = arr[index]
            continue
        if last:
            node[name] = value
            return
        if name not in node:
            node[name] = {}
        elif isinstance(node[name], list) and all(isinstance(t, dict) for t in node[name]):
            raise ValueError(f"{where} is an array of tables: index it, e.g. {where}[0]")
        elif not isinstance(node[name], dict):
            raise ValueError(f"{where} is a value in the base scene, not a table, so it has "
                             "no keys below it")
        node = node[name]


def _root(key: str) -> str:
    return key.split(".")[0].split("[")[0]


def _flatten(table: dict, prefix: str = "") -> dict:
    """``[set]`` as dotted key paths: an unquoted dotted key (``environment.current.heights
    = ...``, which TOML reads as nested tables) sets that one key, as the quoted form
    does, instead of replacing the base's whole ``[environment]``."""
    out = {}
    for key, value in table.items():
        path = f"{prefix}.{key}" if prefix else key
        if isinstance(value, dict) and value:
            out.update(_flatten(value, path))
        else:
            out[path] = value
    return out


def _read_base(base, folder: Path, source: str) -> tuple[Scene, dict]:
    if not isinstance(base, str) or not base.strip():
        raise SceneError(source, "base", "must be a built-in scene name or a scene file path "
                         f"(a string), got {json.dumps(base)[:60]}")
    path = folder / base
    if not is_file(path):
        path = builtin_paths().get(base, Path(base))
    if not is_file(path):
        try:
            resolve(base)                         # its one-line reason and near-miss hint
        except SceneError as exc:
            raise SceneError(source, "base", str(exc)) from None
    scene = load_scene(path)                      # its own errors first, naming its file
    return scene, tomllib.loads(read_text(path))


def _read_vary(data, source: str) -> tuple[Vary, ...]:
    if "vary" not in data:
        raise SceneError(source, "vary", "required: at least one [[vary]] table with key and "
                         "values")
    items = data["vary"]
    if not isinstance(items, list) or not items or not all(isinstance(t, dict) for t in items):
        raise SceneError(source, "vary", "must be one or more [[vary]] tables (key, values, "
                         "optional zip)")
    out, seen = [], set()
    for i, t in enumerate(items):
        where = f"vary[{i}]"
        extra = sorted(set(t) - {"key", "values", "zip"})
        if extra:
            raise SceneError(source, f"{where}.{extra[0]}", "unknown key (known keys here: "
                             "key, values, zip)")
        if "key" not in t:
            raise SceneError(source, f"{where}.key", "required key is missing")
        try:
            split_key(t["key"])
        except ValueError as exc:
            raise SceneError(source, f"{where}.key", str(exc)) from None
        if t["key"] in seen:
            raise SceneError(source, f"{where}.key", f"{t['key']!r} is varied twice")
        if _root(t["key"]) in FIXED_ROOTS:
            raise SceneError(source, f"{where}.key", f"{t['key']!r} cannot be varied: a sweep "
                             "solves statics and names its cases itself")
        seen.add(t["key"])
        values = t.get("values")
        if not isinstance(values, list):
            raise SceneError(source, f"{where}.values", "required: an array of the values "
                             f"{t['key']} takes, one per case")
        if not values:
            raise SceneError(source, f"{where}.values", "is empty: give at least one value")
        z = t.get("zip", False)
        if not isinstance(z, bool):
            raise SceneError(source, f"{where}.zip", "must be true or false")
        if z and i == 0:
            raise SceneError(source, f"{where}.zip", "the first vary has no list before it "
                             "to pair with")
        out.append(Vary(t["key"], tuple(values), z))
    return tuple(out)


def _combinations(vary: tuple[Vary, ...], zip_all: bool, source: str) -> list[tuple]:
    """Index tuples into each vary's values, one per case (first dimension slowest)."""
    dims: list[list[int]] = []                # each dimension: the vary indices in it
    for i, v in enumerate(vary):
        if zip_all or v.zip:
            if dims:
                dims[-1].append(i)
                continue
        dims.append([i])
    for dim in dims:
        n = len(vary[dim[0]].values)
        for i in dim[1:]:
            if len(vary[i].values) != n:
                what = "zip = true pairs every list" if zip_all else "zip = true pairs it"
                raise SceneError(source, f"vary[{i}].values", f"has {len(vary[i].values)} "
                                 f"values, vary[{dim[0]}] has {n}: {what}, so they need "
                                 "equal lengths")
    count = 1
    for dim in dims:
        count *= len(vary[dim[0]].values)
    if count > MAX_CASES:
        raise SceneError(source, "vary", f"expands to {count} cases, more than "
                         f"{MAX_CASES}: split the sweep")
    out = []
    for pick in itertools.product(*(range(len(vary[d[0]].values)) for d in dims)):
        idx = [0] * len(vary)
        for dim, k in zip(dims, pick):
            for i in dim:
                idx[i] = k
        out.append(tuple(idx))
    return out


def case_digest(scene_dict: dict, methods) -> str:
    text = json.dumps({"scene": scene_dict, "methods": list(methods), "format": CASE_FORMAT},
                      sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def builtin_sweeps() -> dict[str, Path]:
    """Built-in sweep name -> file (``verification/sweeps/builtin/``)."""
    return {p.stem: p for p in sorted(SWEEP_DIR.glob("*.toml"))}


def resolve_sweep(name_or_path: str | Path) -> Path:
    """A sweep file by path, else a built-in sweep by name; :class:`SceneError` if neither."""
    path = Path(name_or_path)
    if (path_problem(path) is not None or path.exists() or path.suffix == ".toml"
            or len(path.parts) > 1):
        return path
    found = builtin_sweeps().get(str(name_or_path))
    if found is None:
        raise SceneError(str(name_or_path), "", "no such file and no built-in sweep of that "
                         f"name (built-in: {', '.join(builtin_sweeps())})")
    return found


def load_sweep(name_or_path: str | Path) -> Sweep:
    """Read, expand and validate a sweep file (a path or a built-in sweep's name); raises
    :class:`SceneError` (one line)."""
    path = resolve_sweep(name_or_path)
    source = str(name_or_path)
    try:
        text = read_text(path, "a sweep")     # never a FIFO or device: it could block
    except SceneError as exc:
        raise SceneError(source, "", exc.message) from None
    try:
        data = tomllib.loads(text)
    except ValueError as exc:
        raise SceneError(source, "", f"not valid TOML ({exc})") from None
    extra = sorted(set(data) - {"base", "methods", "vary", "zip", "set"})
    if extra:
        raise SceneError(source, extra[0], "unknown key (known keys here: base, methods, set, "
                         "vary, zip)")
    if "base" not in data:
        raise SceneError(source, "base", "required key is missing (a built-in scene name or a "
                         "scene file)")
    methods = data.get("methods", ["bvp", "vfife"])
    if (not isinstance(methods, list) or not methods
            or not all(isinstance(m, str) and m in METHODS for m in methods)
            or len(set(methods)) != len(methods)):
        raise SceneError(source, "methods", f"must be a non-empty list of distinct methods "
                         f"from {list(METHODS)}, got {json.dumps(methods)[:80]}")
    zip_all = data.get("zip", False)
    if not isinstance(zip_all, bool):
        raise SceneError(source, "zip", "must be true or false")
    fixed = data.get("set", {})
    if not isinstance(fixed, dict):
        raise SceneError(source, "set", "must be a table of \"key.path\" = value")
    vary = _read_vary(data, source)
    fixed = _flatten(fixed)
    for key in fixed:
        try:
            split_key(key)
        except ValueError as exc:
            raise SceneError(source, f'set."{key}"', str(exc)) from None
        if key in {v.key for v in vary}:
            raise SceneError(source, f'set."{key}"', "is also varied: give it in one place")
        if _root(key) in FIXED_ROOTS:
            raise SceneError(source, f'set."{key}"', "cannot be set: a sweep solves statics "
                             "and names its cases itself")
    base_scene, base_dict = _read_base(data["base"], path.parent, source)
    _refuse_inert(source, base_scene, vary, fixed, methods)
    sweep = Sweep(path.stem, source, data["base"], base_scene, tuple(methods), vary, fixed,
                  builtin=path.parent == SWEEP_DIR and not Path(name_or_path).exists())
    if base_dict.pop("dynamics", None) is not None:
        sweep.notes.append("The base scene's [dynamics] are ignored: a sweep solves the "
                           "static equilibrium of each case.")
    for key, value in fixed.items():
        try:
            set_value(base_dict, key, copy.deepcopy(value))
        except ValueError as exc:
            raise SceneError(source, f'set."{key}"', str(exc)) from None
    for index, pick in enumerate(_combinations(vary, zip_all, source)):
        sweep.cases.append(_case(sweep, base_dict, index, pick))
    return sweep


def _refuse_inert(source: str, base_scene: Scene, vary, fixed: dict, methods) -> None:
    """A varied or set key that cannot change what a sweep case solves: one SceneError
    (:mod:`verification.sweeps.inert`)."""
    keys = [v.key for v in vary] + list(fixed)
    converts = inert.converts(base_scene, keys, methods)
    named = [(f"vary[{i}].key", v.key) for i, v in enumerate(vary)]
    for where, key in named + [(f'set."{k}"', k) for k in fixed]:
        why = inert.why_inert(key, methods, converts)
        if why is not None:
            raise SceneError(source, where, inert.message(key, why))


def presolve_checks(scene: Scene, methods) -> None:
    """What the methods check of a scene before solving it (raising SceneError, as a
    plain ``solve`` of it is refused, exit 2): a tensioner's pull against the line's
    weight and a free end's buoyancy (both methods: riser.results.validity.check_end_loads), the
    VFIFE's element length against the line, its segments and a slug
    (riser.results.validity.check_resolution)."""
    validity.check_end_loads(scene)
    if "vfife" in methods:
        validity.check_resolution(scene, scene.vfife.element_length)


def _case(sweep: Sweep, base_dict: dict, index: int, pick: tuple) -> Case:
    data = copy.deepcopy(base_dict)
    values = {}
    for i, (v, k) in enumerate(zip(sweep.vary, pick)):
        values[v.key] = v.values[k]
        try:
            set_value(data, v.key, copy.deepcopy(v.values[k]))
        except ValueError as exc:
            raise SceneError(sweep.source, f"vary[{i}].key", str(exc)) from None
    given = ", ".join(f"{k} = {json.dumps(x, default=str)}" for k, x in values.items())
    try:
        scene = scene_from_dict(data, f"case {index}")
    except SceneError as exc:
        fixed = next((k for k in sweep.fixed if exc.key == k or exc.key.startswith(k + ".")
                      or exc.key.startswith(k + "[")), None)
        if fixed is not None and fixed not in values:   # a [set] value, the same in every case
            raise SceneError(sweep.source, f'set."{fixed}"', f"{exc.key}: {exc.message}") \
                from None
        hint = ""
        if "required key is missing" in exc.message and exc.key.rsplit(".", 1)[0] in \
                {v.key.rsplit(".", 1)[0] for v in sweep.vary}:
            hint = (f" (the base scene has no {exc.key.rsplit('.', 1)[0]}: set its other "
                    "keys in every case under [set])")
        raise SceneError(sweep.source, f"case {index} ({given}): {exc.key}",
                         exc.message + hint) from None
    try:                                   # the methods' own checks before solving
        presolve_checks(scene, sweep.methods)
    except SceneError as exc:
        raise SceneError(sweep.source, f"case {index} ({given}): {exc.key}",
                         exc.message) from None
    return Case(index, values, data, scene, case_digest(data, sweep.methods))

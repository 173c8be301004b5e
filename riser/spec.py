"""Field specs: the type, allowed range, unit and meaning of every key of a scene, written
once and checked on every construction.

Each part of a scene (:class:`~riser.model.line.LineType`, :class:`~riser.model.line.Segment`, the
current, the seabed, the end forms, the dynamics, the internal flow, the solver settings
and the scene itself) is a frozen dataclass whose fields are declared with :func:`spec`.
Its ``__post_init__`` calls :func:`check_fields` (then its own cross-field checks), so a
part built in code, by ``dataclasses.replace`` or ``Scene.replace``, is refused with the
same one-line :class:`~riser.errors.SceneError` as the scene file that holds the value.
The reader (:mod:`riser.io.scene_file`) checks only what the file adds: TOML types,
unknown keys, which end form the keys select and the file-only conveniences.

Key paths. A part's error names the key relative to its own table (``length``,
``hang_off[0]``) and has the source ``<ClassName>``; where a scene builds a part
(:func:`prefixed`) the error gets the part's place (``segments[2].length``,
``ends.hang_off[0]``, ``environment.current.speeds``) and the scene's source. The solver
settings are tables with a name of their own (``KEY_PREFIX``: ``bvp``, ``analytic``,
``vfife``): their errors always carry it (``vfife.expert.static_damping``).

A default is written once, as the field's default; the key tables of docs/scene-files.md
are generated from these specs (:mod:`riser.model.spec_docs`).
"""

from __future__ import annotations

import contextlib
import dataclasses
import math
import numbers
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from .errors import SceneError

#: the largest coordinate or height [m] (100 km): the range of every position key
MAX_COORDINATE = 1.0e5

#: the kinds of value a spec describes ('part': a nested part, checked by its own class)
KINDS = ("number", "integer", "boolean", "string", "numbers", "strings", "part")


@dataclass(frozen=True)
class Spec:
    """What one key holds.

    kind : one of :data:`KINDS`.
    gt, ge, lt, le : bounds of a number (of each entry of 'numbers'; ge/le of an integer).
    unit : SI unit of the value ('' for a dimensionless one).
    doc : one line of meaning, for the key tables.
    choices : the allowed strings ('string', and each entry of 'strings').
    pattern : a regular expression a 'string' must match in full.
    length, min_length : the exact number of entries of 'numbers' (or a tuple of the
        allowed numbers) / the least number.
    optional : None is accepted (the field's default is None).
    table : the sub-table of the part's table holding the key ('expert', 'slug',
        'environment' for the scene's environment fields), '' for the part's own table.
    key : the key in the file when it is not the field's name.
    default_doc : the default as the key tables say it, when the field's default value is
        not what a reader should see ('min(1 s, duration)', 'required (harmonic)').
    also : further constraints in words, checked by the part's cross-field checks.
    part : the class (or classes) of a 'part'.
    """

    kind: str = "number"
    gt: float | None = None
    ge: float | None = None
    lt: float | None = None
    le: float | None = None
    unit: str = ""
    doc: str = ""
    choices: tuple[str, ...] | None = None
    pattern: str | None = None
    length: int | tuple[int, ...] | None = None
    min_length: int = 1
    optional: bool = False
    table: str = ""
    key: str = ""
    default_doc: str = ""
    also: str = ""
    part: Any = None

    def path(self, name: str) -> str:
        """The key path in the part's table of the field ``name`` (``expert.static_damping``)."""
        return join(self.table, self.key or name)


def spec(default: Any = dataclasses.MISSING, kind: str = "number", *,
         default_factory: Any = dataclasses.MISSING, **options: Any):
    """A dataclass field carrying its :class:`Spec` (``options``: the Spec's attributes).
    No default: a required key. A default of None: an optional key (None = not given)."""
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
    options.setdefault("optional", default is None)
    return dataclasses.field(default=default, default_factory=default_factory,
                             metadata={"spec": Spec(kind=kind, **options)})


def join(prefix: str, key: str) -> str:
    """``prefix`` and ``key`` as one key path (``segments[2]`` + ``length``, ``heights`` +
    ``[1]``)."""
    if not prefix:
        return key
    if not key:
        return prefix
    return prefix + key if key.startswith("[") else f"{prefix}.{key}"


def type_name(value: Any) -> str:
    """The TOML-ish name of a value's type, for messages ('a string', 'an array')."""
    if value is None:
        return "None"
    if isinstance(value, bool):
        return "a boolean"
    for kind, name in ((numbers.Integral, "an integer"), (numbers.Real, "a number"),
                       (str, "a string"), ((list, tuple), "an array"), (dict, "a table")):
        if isinstance(value, kind):
            return name
    return type(value).__name__


Error = Callable[[str, str], Exception]


def check_number(value: Any, error: Error, name: str, *, gt: float | None = None,
                 ge: float | None = None, lt: float | None = None, le: float | None = None,
                 unit: str = "") -> float:
    """``value`` as a float when it is a finite real within the bounds (inclusive for
    ge/le); else ``error(name, message)`` is raised."""
    u = f" {unit}" if unit else ""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise error(name, f"must be a number, got {type_name(value)}")
    try:
        value = float(value)
    except OverflowError:
        raise error(name, "must be a finite number, got an integer too large for a float") from None
    if not math.isfinite(value):
        raise error(name, f"must be a finite number, got {value}")
    if gt is not None and not value > gt:
        raise error(name, f"must be > {gt:g}{u}, got {value:g}")
    if ge is not None and not value >= ge:
        raise error(name, f"must be >= {ge:g}{u}, got {value:g}")
    if lt is not None and not value < lt:
        raise error(name, f"must be < {lt:g}{u}, got {value:g}")
    if le is not None and not value <= le:
        raise error(name, f"must be <= {le:g}{u}, got {value:g}")
    return value


def parse(sp: Spec, value: Any, name: str, error: Error) -> Any:
    """The type check of a value read from a file (no range): numbers become floats,
    arrays tuples. Raises ``error(name, message)``."""
    kind = sp.kind
    if kind == "number":
        if isinstance(value, bool) or not isinstance(value, numbers.Real):
            raise error(name, f"must be a number, got {type_name(value)}")
        try:
            return float(value)
        except OverflowError:
            raise error(name, "must be a finite number, got an integer too large for a "
                        "float") from None
    if kind == "numbers":
        if not isinstance(value, (list, tuple)):
            raise error(name, f"must be an array of numbers, got {type_name(value)}")
        item = dataclasses.replace(sp, kind="number")
        return tuple(parse(item, v, f"{name}[{i}]", error) for i, v in enumerate(value))
    return check(sp, value, name, error)        # the other kinds: the type is the check


def check(sp: Spec, value: Any, name: str, error: Error) -> Any:
    """``value`` checked against ``sp`` (type, finiteness, range): the value to store (an
    array as a tuple, else ``value`` itself). Raises ``error(name, message)``."""
    if value is None and sp.optional:
        return None
    kind = sp.kind
    if kind == "number":
        check_number(value, error, name, gt=sp.gt, ge=sp.ge, lt=sp.lt, le=sp.le, unit=sp.unit)
        return value
    if kind == "integer":
        if isinstance(value, bool) or not isinstance(value, numbers.Integral):
            raise error(name, f"must be an integer, got {type_name(value)}")
        if sp.ge is not None and value < sp.ge:
            raise error(name, f"must be >= {sp.ge}, got {value}")
        if sp.le is not None and value > sp.le:
            raise error(name, f"must be <= {sp.le}, got {value}")
        return value
    if kind == "boolean":
        if not isinstance(value, bool):
            raise error(name, f"must be true or false, got {type_name(value)}")
        return value
    if kind == "string":
        if not isinstance(value, str):
            raise error(name, f"must be a string, got {type_name(value)}")
        if sp.choices is not None and value not in sp.choices:
            raise error(name, f"must be one of {_quoted(sp.choices)}, got {value!r}")
        if sp.pattern is not None and not re.fullmatch(sp.pattern, value):
            raise error(name, f"must match {sp.pattern}, got {value!r}")
        return value
    if kind == "numbers":
        return _check_numbers(sp, value, name, error)
    if kind == "strings":
        return _check_strings(sp, value, name, error)
    if not isinstance(value, sp.part):
        classes = sp.part if isinstance(sp.part, tuple) else (sp.part,)
        raise error(name, f"must be a {' or '.join(c.__name__ for c in classes)}, got "
                    f"{type_name(value)}")
    return value


def _quoted(choices) -> str:
    return ", ".join(repr(c) for c in choices)


def _check_numbers(sp: Spec, value: Any, name: str, error: Error) -> tuple:
    if not isinstance(value, (list, tuple)):
        raise error(name, f"must be an array of numbers, got {type_name(value)}")
    lengths = sp.length if isinstance(sp.length, tuple) else (sp.length,)
    if sp.length is not None and len(value) not in lengths:
        raise error(name, f"must have {' or '.join(map(str, lengths))} entries, got "
                    f"{len(value)}")
    if len(value) < sp.min_length:
        raise error(name, f"must have at least {sp.min_length} entries, got {len(value)}")
    for i, item in enumerate(value):
        check_number(item, error, f"{name}[{i}]", gt=sp.gt, ge=sp.ge, lt=sp.lt, le=sp.le,
                     unit=sp.unit)
    return tuple(value)


def _check_strings(sp: Spec, value: Any, name: str, error: Error) -> tuple:
    allowed = f" (allowed: {_quoted(sp.choices)})" if sp.choices else ""
    if not isinstance(value, (list, tuple)):
        raise error(name, f"must be an array of strings{allowed}, got {type_name(value)}")
    for i, item in enumerate(value):
        if not isinstance(item, str):
            raise error(f"{name}[{i}]", f"must be a string{allowed}, got {type_name(item)}")
        if sp.choices is not None and item not in sp.choices:
            raise error(f"{name}[{i}]", f"must be one of {_quoted(sp.choices)}, got {item!r}")
        if item in value[:i]:
            raise error(f"{name}[{i}]", f"{item!r} given twice")
    return tuple(value)


# ---------------------------------------------------------------------- parts
_SPECS: dict[type, tuple[tuple[str, Spec], ...]] = {}


def specs(cls) -> tuple[tuple[str, Spec], ...]:
    """(field name, Spec) of every specified field of a part class, in field order."""
    out = _SPECS.get(cls)
    if out is None:
        out = _SPECS[cls] = tuple((f.name, f.metadata["spec"]) for f in dataclasses.fields(cls)
                                  if "spec" in f.metadata)
    return out


def source_of(part: Any) -> str:
    """The source named by the errors of a part built alone (``<Segment>``)."""
    return f"<{type(part).__name__}>"


def part_error(part: Any) -> Error:
    """The error factory of ``part``: its source, its KEY_PREFIX before the key."""
    prefix, source = getattr(part, "KEY_PREFIX", ""), source_of(part)
    return lambda key, message: SceneError(source, join(prefix, key), message)


def check_fields(part: Any, skip: tuple[str, ...] = (), error: Error | None = None) -> None:
    """Check every specified field of ``part`` (a frozen dataclass) against its spec and
    store arrays as tuples; ``skip``: fields the part checks itself; ``error``: the error
    factory (default :func:`part_error`). Raises SceneError."""
    error = error or part_error(part)
    for name, sp in specs(type(part)):
        if name in skip:
            continue
        value = getattr(part, name)
        stored = check(sp, value, sp.path(name), error)
        if stored is not value:
            object.__setattr__(part, name, stored)


@contextlib.contextmanager
def prefixed(prefix: str, source: str):
    """Re-raise a SceneError of a part built inside this block with the part's place in
    the scene before its key and the scene's ``source``."""
    try:
        yield
    except SceneError as exc:
        raise SceneError(source, join(prefix, exc.key), exc.message) from None


class Part:
    """Base of the parts of a scene: checked on construction, ``replace`` for a copy."""

    #: the prefix of the part's own key paths (the solver settings: their table)
    KEY_PREFIX = ""
    #: what :meth:`replace` calls a name that is no field
    UNKNOWN = "unknown field"

    def __post_init__(self) -> None:
        check_fields(self)

    def replace(self, **changes: Any):
        """A checked copy with some fields changed (the part is immutable)."""
        names = [f.name for f in dataclasses.fields(self)]
        unknown = sorted(set(changes) - set(names))
        if unknown:
            raise part_error(self)(unknown[0], f"{self.UNKNOWN} (known: {', '.join(names)})")
        return dataclasses.replace(self, **changes)

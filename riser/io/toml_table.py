"""Typed, path-aware reading of TOML tables with one-line errors.

Every value read through :class:`Table` is checked for type, finiteness and an
allowed range; keys that were never read are reported as unknown. Errors name the
file and the key path (``segments[2].length``) and raise :class:`SceneError`.
"""

from __future__ import annotations

import math
import re
from typing import Any

from ..errors import SceneError

MISSING = object()


def _type_name(value: Any) -> str:
    return {bool: "a boolean", int: "an integer", float: "a number", str: "a string",
            list: "an array", dict: "a table"}.get(type(value), type(value).__name__)


class Table:
    """A TOML table being validated.

    Parameters
    ----------
    data : dict
        The parsed table.
    path : str
        Key path of this table inside the file ('' for the root, 'segments[2]', ...).
    source : str
        File name used in error messages.
    """

    def __init__(self, data: Any, path: str, source: str):
        self.source = source
        self.path = path
        if not isinstance(data, dict):
            raise SceneError(source, path or "(root)", f"must be a table, got {_type_name(data)}")
        self.data = data
        self._used: set[str] = set()

    # ------------------------------------------------------------------ helpers
    def key(self, name: str) -> str:
        if not name:
            return self.path
        if not name.isprintable():
            name = repr(name)          # keep the error on one line (e.g. a key with a newline)
        return f"{self.path}.{name}" if self.path else name

    def error(self, name: str, message: str) -> SceneError:
        return SceneError(self.source, self.key(name), message)

    def has(self, name: str) -> bool:
        return name in self.data

    def _raw(self, name: str, default: Any) -> Any:
        self._used.add(name)
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, "required key is missing")
            return default
        return self.data[name]

    # ------------------------------------------------------------------ typed getters
    def number(self, name: str, default: Any = MISSING, *, gt: float | None = None,
               ge: float | None = None, lt: float | None = None, le: float | None = None,
               unit: str = "") -> Any:
        """A finite float within the given bounds (bounds are inclusive for ge/le)."""
        value = self._raw(name, default)
        if value is default and name not in self.data:
            return value
        return check_number(value, self.error, name, gt=gt, ge=ge, lt=lt, le=le, unit=unit)

    def string(self, name: str, default: Any = MISSING, *, choices: tuple[str, ...] | None = None,
               pattern: str | None = None) -> Any:
        value = self._raw(name, default)
        if value is default and name not in self.data:
            return value
        if not isinstance(value, str):
            raise self.error(name, f"must be a string, got {_type_name(value)}")
        if choices is not None and value not in choices:
            raise self.error(name, f"must be one of {', '.join(repr(c) for c in choices)}, got {value!r}")
        if pattern is not None:
            if not re.fullmatch(pattern, value):
                raise self.error(name, f"must match {pattern}, got {value!r}")
        return value

    def boolean(self, name: str, default: Any = MISSING) -> Any:
        value = self._raw(name, default)
        if value is default and name not in self.data:
            return value
        if not isinstance(value, bool):
            raise self.error(name, f"must be true or false, got {_type_name(value)}")
        return value

    def integer(self, name: str, default: Any = MISSING, *, ge: int | None = None,
                le: int | None = None) -> Any:
        value = self._raw(name, default)
        if value is default and name not in self.data:
            return value
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.error(name, f"must be an integer, got {_type_name(value)}")
        if ge is not None and value < ge:
            raise self.error(name, f"must be >= {ge}, got {value}")
        if le is not None and value > le:
            raise self.error(name, f"must be <= {le}, got {value}")
        return value

    def numbers(self, name: str, default: Any = MISSING, *, length: int | None = None,
                min_length: int = 1, **bounds: Any) -> Any:
        """A list of finite floats, each within ``bounds``."""
        value = self._raw(name, default)
        if value is default and name not in self.data:
            return value
        if not isinstance(value, list):
            raise self.error(name, f"must be an array of numbers, got {_type_name(value)}")
        if length is not None and len(value) != length:
            raise self.error(name, f"must have {length} entries, got {len(value)}")
        if len(value) < min_length:
            raise self.error(name, f"must have at least {min_length} entries, got {len(value)}")
        out = []
        for i, item in enumerate(value):
            out.append(check_number(item, self.error, f"{name}[{i}]", **bounds))
        return tuple(out)

    def strings(self, name: str, default: Any = MISSING, *,
                choices: tuple[str, ...] | None = None, unique: bool = True) -> Any:
        """A list of strings, each one of ``choices`` (if given), without repeats."""
        value = self._raw(name, default)
        if value is default and name not in self.data:
            return value
        allowed = f" (allowed: {', '.join(repr(c) for c in choices)})" if choices else ""
        if not isinstance(value, list):
            raise self.error(name, f"must be an array of strings{allowed}, got "
                             f"{_type_name(value)}")
        for i, item in enumerate(value):
            if not isinstance(item, str):
                raise self.error(f"{name}[{i}]", f"must be a string{allowed}, got "
                                 f"{_type_name(item)}")
            if choices is not None and item not in choices:
                raise self.error(f"{name}[{i}]", f"must be one of "
                                 f"{', '.join(repr(c) for c in choices)}, got {item!r}")
            if unique and item in value[:i]:
                raise self.error(f"{name}[{i}]", f"{item!r} given twice")
        return tuple(value)

    def table(self, name: str, required: bool = False) -> "Table | None":
        self._used.add(name)
        if name not in self.data:
            if required:
                raise self.error(name, "required table is missing")
            return None
        return Table(self.data[name], self.key(name), self.source)

    def array_of_tables(self, name: str, required: bool = True) -> list["Table"]:
        self._used.add(name)
        if name not in self.data:
            if required:
                raise self.error(name, "required array of tables is missing")
            return []
        value = self.data[name]
        if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
            raise self.error(name, f"must be an array of tables ([[{name}]]), got {_type_name(value)}")
        if required and not value:
            raise self.error(name, "must have at least one entry")
        return [Table(v, f"{self.key(name)}[{i}]", self.source) for i, v in enumerate(value)]

    def finish(self, allowed_extra: tuple[str, ...] = ()) -> None:
        """Raise on the first key that was never read (an unknown key)."""
        for name in self.data:
            if name not in self._used and name not in allowed_extra:
                known = ", ".join(sorted(self._used)) or "none"
                raise self.error(name, f"unknown key (known keys here: {known})")


def check_number(value: Any, error, name: str, *, gt: float | None = None, ge: float | None = None,
                 lt: float | None = None, le: float | None = None, unit: str = "") -> float:
    """Check that ``value`` is a finite real within bounds; ``error(name, msg)`` builds the error."""
    u = f" {unit}" if unit else ""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise error(name, f"must be a number, got {_type_name(value)}")
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

"""Typed, path-aware reading of TOML tables with one-line errors.

A :class:`Table` checks what the file adds to the model: the TOML type of each value read
(by the key's :class:`~riser.spec.Spec`: numbers become floats, arrays tuples), required
keys, and unknown keys (keys that were never read). Ranges are the parts' own checks
(:mod:`riser.spec`), applied when the reader builds them (:meth:`Table.build`); a value
the reader computes with (an outer diameter, a wall thickness) is checked on reading
(``checked=True``). Errors name the file and the key path (``segments[2].length``) and
raise :class:`SceneError`.
"""

from __future__ import annotations

from dataclasses import MISSING as NO_DEFAULT
from typing import Any

from ..errors import SceneError
from ..spec import Spec, check, parse, prefixed, specs, type_name

MISSING = object()


class Table:
    """A TOML table being read.

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
            raise SceneError(source, path or "(root)", f"must be a table, got {type_name(data)}")
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

    # ------------------------------------------------------------------ values
    def value(self, name: str, sp: Spec, default: Any = MISSING, *, checked: bool = False) -> Any:
        """The value of key ``name`` of the type ``sp`` says (``default`` when it is
        absent; MISSING: a required key); ``checked``: its range too."""
        self._used.add(name)
        if name not in self.data:
            if default is MISSING:
                raise self.error(name, "required key is missing")
            return default
        value = parse(sp, self.data[name], name, self.error)
        return check(sp, value, name, self.error) if checked else value

    def fields(self, cls, table: str = "", *, names: tuple[str, ...] | None = None,
               required: tuple[str, ...] = ()) -> dict:
        """The values given in this table of the specified fields of the part class
        ``cls`` that sit in its sub-table ``table`` ('' its own), or only ``names``;
        a field without a default, or in ``required``, must be given."""
        defaults = cls.__dataclass_fields__
        out = {}
        for name, sp in specs(cls):
            if sp.kind == "part" or sp.table != table or (names is not None
                                                          and name not in names):
                continue
            f = defaults[name]
            no_default = f.default is NO_DEFAULT and f.default_factory is NO_DEFAULT
            key = sp.key or name
            if name in required or self.has(key) or (no_default and not sp.optional):
                out[name] = self.value(key, sp)
            else:
                self._used.add(key)
                if no_default:                  # optional, and None when not given
                    out[name] = None
        return out

    def build(self, cls, **values: Any):
        """``cls(**values)``: a part of this table, its errors named in the file."""
        with prefixed("" if cls.KEY_PREFIX else self.path, self.source):
            return cls(**values)

    # ------------------------------------------------------------------ tables
    def table(self, name: str, required: bool = False) -> Table | None:
        self._used.add(name)
        if name not in self.data:
            if required:
                raise self.error(name, "required table is missing")
            return None
        return Table(self.data[name], self.key(name), self.source)

    def array_of_tables(self, name: str, required: bool = True) -> list[Table]:
        self._used.add(name)
        if name not in self.data:
            if required:
                raise self.error(name, "required array of tables is missing")
            return []
        value = self.data[name]
        if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
            raise self.error(name, f"must be an array of tables ([[{name}]]), got "
                             f"{type_name(value)}")
        if required and not value:
            raise self.error(name, "must have at least one entry")
        return [Table(v, f"{self.key(name)}[{i}]", self.source) for i, v in enumerate(value)]

    def finish(self) -> None:
        """Raise on the first key that was never read (an unknown key)."""
        for name in self.data:
            if name not in self._used:
                known = ", ".join(sorted(self._used)) or "none"
                raise self.error(name, f"unknown key (known keys here: {known})")

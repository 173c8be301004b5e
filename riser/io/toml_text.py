"""Writing a scene's TOML text (the reader is :mod:`tomllib`; this is its small inverse for
the structures a scene file holds: scalars, number lists, tables, nested tables and arrays
of tables). Floats are written with ``repr`` and read back bit for bit."""

from __future__ import annotations

import math
import re

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k: str) -> str:
    return k if _BARE.match(k) else _string(k)


def key(k: str) -> str:
    """``k`` as a TOML key: bare when it can be, quoted otherwise (the form of the table
    paths that :func:`dumps`'s ``comments`` are keyed by, e.g. ``line_types."10\" pipe"``)."""
    return _key(k)


def _value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if not math.isfinite(v):
            raise ValueError(f"cannot write {v!r} to a scene file")
        return repr(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    raise TypeError(f"cannot write a {type(v).__name__} to a scene file")


#: TOML's short escapes; every other control character is written as \\uXXXX
_ESCAPES = {"\\": "\\\\", '"': '\\"', "\b": "\\b", "\t": "\\t", "\n": "\\n",
            "\f": "\\f", "\r": "\\r"}


def _string(v: str) -> str:
    """A TOML basic string of ``v`` that reads back to ``v``: quotes, backslashes and
    every control character (U+0000-U+001F, U+007F) escaped (a label with a raw \\x01
    made a case's scene.toml unreadable; a newline was turned into a space)."""
    out = []
    for ch in v:
        if ch in _ESCAPES:
            out.append(_ESCAPES[ch])
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04X}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def _comment_lines(notes) -> list[str]:
    """Comment lines of ``notes``: a note's line breaks and control characters (which end
    or break a TOML comment) become spaces."""
    clean = ["".join(" " if (ord(c) < 0x20 and c != "\t") or ord(c) == 0x7F else c
                     for c in str(n)) if n else n for n in notes or ()]
    return [f"# {n}" if n else "#" for n in clean]


def dumps(data: dict, *, header=(), comments: dict | None = None) -> str:
    """TOML text of ``data``. ``header`` lines become comments at the top; ``comments``
    maps a table path (``"seabed"``, ``"line_types.pipe"``, ``"segments[2]"``) to comment
    lines written above that table."""
    comments = comments or {}
    out = _comment_lines(header)
    if out:
        out.append("")
    _table(data, "", out, comments)
    return "\n".join(out).rstrip() + "\n"


def _table(data: dict, path: str, out: list[str], comments: dict) -> None:
    scalars = {k: v for k, v in data.items()
               if not isinstance(v, dict) and not _is_table_array(v)}
    for k, v in scalars.items():
        out.append(f"{_key(k)} = {_value(v)}")
    for k, v in data.items():
        sub = f"{path}.{_key(k)}" if path else _key(k)
        if isinstance(v, dict):
            has_scalars = any(not isinstance(x, dict) and not _is_table_array(x)
                              for x in v.values())
            if has_scalars or not v:
                out.append("")
                out += _comment_lines(comments.get(sub))
                out.append(f"[{sub}]")
            _table(v, sub, out, comments)
        elif _is_table_array(v):
            for i, item in enumerate(v):
                out.append("")
                out += _comment_lines(comments.get(f"{sub}[{i}]"))
                out.append(f"[[{sub}]]")
                _table(item, sub, out, comments)


def _is_table_array(v) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)

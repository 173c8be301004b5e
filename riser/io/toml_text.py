"""Writing a scene's TOML text (the reader is :mod:`tomllib`; this is its small inverse for
the structures a scene file holds: scalars, number lists, tables, nested tables and arrays
of tables). Floats are written with ``repr`` and read back bit for bit."""

from __future__ import annotations

import math
import re

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k: str) -> str:
    return k if _BARE.match(k) else '"' + k.replace("\\", "\\\\").replace('"', '\\"') + '"'


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
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"').replace("\n", " ") + '"'
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    raise TypeError(f"cannot write a {type(v).__name__} to a scene file")


def _comment_lines(notes) -> list[str]:
    return [f"# {n}" if n else "#" for n in notes or ()]


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

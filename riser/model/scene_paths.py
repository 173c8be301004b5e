"""Key paths into a scene, for :meth:`riser.model.scene.Scene.replace`: the scene file's paths
(``segments[2].length``, ``ends.hang_off``, ``ends.hang_off[1]``,
``environment.current.speeds``, ``line_types.steel.drag_normal``,
``dynamics.top_motion.period``, ``vfife.expert.static_damping``) or the same with the
attribute names (``current.speeds``, ``vfife.static_damping``).

The part a path ends in is rebuilt (and so checked) inside :func:`riser.spec.prefixed`:
a bad value is named by its key path in the file and the scene's source.
"""

from __future__ import annotations

import dataclasses
import re
from typing import Any

from ..errors import SceneError
from ..spec import join, prefixed, specs

_STEP = re.compile(r"([^.\[\]]+)(?:\[(\d+)\])?")


def replaced(scene: Any, changes: dict) -> dict:
    """The field changes of ``scene`` that ``changes`` (fields or key paths) ask for."""
    names = [f.name for f in dataclasses.fields(scene)]
    out: dict = {}
    for key, value in changes.items():
        if key in names:
            out[key] = value
            continue
        steps = _split(scene.source, key)
        if steps[0] == ("environment", None) and len(steps) > 1:
            steps = steps[1:]                   # the file's table of the environment fields
        attr, index = steps[0]
        if attr not in names:
            raise SceneError(scene.source, key, "not a field or key path of the scene (fields: "
                             f"{', '.join(names)})")
        scene_specs = dict(specs(type(scene)))
        place = scene_specs[attr].path(attr) if attr in scene_specs else attr
        where = _Where(scene.source, key)
        out[attr] = where.set(out.get(attr, getattr(scene, attr)), index, steps[1:], value,
                              place)
    return out


def _split(source: str, key: str) -> list[tuple[str, int | None]]:
    steps = []
    for part in key.split("."):
        m = _STEP.fullmatch(part)
        if m is None:
            raise SceneError(source, key, "not a key path (e.g. segments[2].length)")
        steps.append((m.group(1), None if m.group(2) is None else int(m.group(2))))
    return steps


class _Where:
    """Rebuilding the parts along one key path of a scene."""

    def __init__(self, source: str, key: str):
        self.source, self.key = source, key

    def unknown(self, place: str, what: str) -> SceneError:
        return SceneError(self.source, self.key, f"no such key in {place or 'the scene'} "
                          f"({what})")

    def set(self, obj: Any, index: int | None, rest: list, value: Any, place: str) -> Any:
        """``obj`` (at ``place`` in the file) with the entry ``index`` and then the path
        ``rest`` set to ``value``."""
        if index is not None:
            if not isinstance(obj, tuple) or index >= len(obj):
                n = len(obj) if isinstance(obj, tuple) else 0
                raise self.unknown(place, f"it has {n} entries")
            item = self.set(obj[index], None, rest, value, f"{place}[{index}]")
            return obj[:index] + (item,) + obj[index + 1:]
        if not rest:
            return value
        name, sub = rest[0]
        if isinstance(obj, dict):
            if name not in obj:
                raise self.unknown(place, f"defined: {', '.join(map(repr, obj))}")
            return {**obj, name: self.set(obj[name], sub, rest[1:], value, join(place, name))}
        if obj is None or not dataclasses.is_dataclass(obj):
            raise self.unknown(place, "not given: set the whole table")
        fields = dict(specs(type(obj)))
        tables = {sp.table for sp in fields.values() if sp.table}
        if name in tables and sub is None and len(rest) > 1:    # [vfife.expert], [..slug]
            rest = rest[1:]
            name, sub = rest[0]
        by_key = {sp.key: n for n, sp in fields.items() if sp.key}
        name = by_key.get(name, name)
        if name not in fields:
            raise self.unknown(place, f"known keys here: {', '.join(fields)}")
        child = self.set(getattr(obj, name), sub, rest[1:], value,
                         join(place, fields[name].path(name)))
        with prefixed("" if getattr(obj, "KEY_PREFIX", "") else place, self.source):
            return dataclasses.replace(obj, **{name: child})

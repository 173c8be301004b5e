"""Reading an OrcaFlex text data file (``.yml``, or a ``.dat`` saved as text) as OrcaFlex
writes it: YAML 1.1 (``Yes``/``No``, ``~`` for a default, ``Infinity``), sections
``General``, ``VariableData``, ``Environment``, ``VesselTypes``, ``Vessels``,
``LineTypes``, ``Lines``, ...; objects as lists of mappings with a ``Name``; tables as
one key naming the columns (``LineType, Length, TargetSegmentLength:``) over rows of
values; ``includefile`` directives, resolved relative to the file that holds them.

PyYAML (the optional extra ``[orcaflex]``) parses the YAML; this module only resolves
the include files and reads the tables. A binary data file (OrcaFlex's own ``.dat``/
``.sim``), a file that is not YAML, an include that is missing or includes itself: one
line naming the file and the item (:class:`ModelError`, a
:class:`~riser.errors.SceneError`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

from ...errors import SceneError

#: the largest text data file read [bytes] (Orcina's example models with their vessel
#: tables are 100-500 kB; a 50 MB file is not a model to cross-check one line of)
MAX_BYTES = 50_000_000

INSTALL = ("reading OrcaFlex text data files needs PyYAML, the optional extra [orcaflex]: "
           "pip install -e '.[orcaflex]' (or pip install pyyaml)")


class ModelError(SceneError):
    """Invalid or unsupported OrcaFlex model content: names the file and the OrcaFlex
    item (``Lines[Catenary Hose].Connection[End A]``)."""


@dataclass
class Model:
    """An OrcaFlex model read from its text data file: its sections after the include
    files are resolved, the file's path, and the files included (in order)."""

    sections: dict
    source: str
    included: list[str] = field(default_factory=list)

    def section(self, name: str) -> dict | list | None:
        """A section by its name, in any letter case (OrcaFlex reads names so)."""
        for k, v in self.sections.items():
            if isinstance(k, str) and k.lower() == name.lower():
                return v
        return None

    def objects(self, section: str) -> list[dict]:
        """The named objects of a section (``Lines``, ``LineTypes``): a list of mappings,
        each with its ``Name``."""
        got = self.section(section)
        if got is None:
            return []
        if not isinstance(got, list) or not all(isinstance(o, dict) for o in got):
            raise ModelError(self.source, section, "must be a list of objects, each with a "
                             "Name (as OrcaFlex writes a text data file)")
        return got

    def named(self, section: str, name: str, item: str) -> dict:
        """The object ``name`` of ``section``; ``item`` names what refers to it."""
        for o in self.objects(section):
            if str(o.get("Name")) == name:
                return o
        known = ", ".join(str(o.get("Name")) for o in self.objects(section)) or "none"
        raise ModelError(self.source, item, f"refers to {name!r}, which is not in {section} "
                         f"(defined: {known})")


def _yaml():
    try:
        import yaml
    except ImportError:
        raise SceneError("import-orcaflex", "", INSTALL) from None
    return yaml


def _loader(yaml):
    """A safe YAML 1.1 loader (libyaml's when PyYAML has it) that keeps OrcaFlex's mappings
    in file order and reads a key written twice as an error (OrcaFlex never writes one
    twice)."""

    base = getattr(yaml, "CSafeLoader", yaml.SafeLoader)    # libyaml's parser: 10x faster

    class Loader(base):
        pass

    def mapping(loader, node):
        loader.flatten_mapping(node)
        out = {}
        for knode, vnode in node.value:
            key = loader.construct_object(knode, deep=True)
            if isinstance(key, list):
                key = tuple(key)
            if key in out:
                raise yaml.constructor.ConstructorError(
                    None, None, f"the key {key!r} is written twice", knode.start_mark)
            out[key] = loader.construct_object(vnode, deep=True)
        return out
    Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, mapping)
    return Loader


def _text(path: Path, item: str, source: str) -> str:
    try:
        if path.is_dir():
            raise ModelError(source, item, f"{path} is a folder, not an OrcaFlex data file")
        size = path.stat().st_size
        if size > MAX_BYTES:
            raise ModelError(source, item, f"{path.name} is {size:,} bytes; at most "
                             f"{MAX_BYTES:,} are read")
        raw = path.read_bytes()
    except FileNotFoundError:
        raise ModelError(source, item, f"no such file: {path}") from None
    except OSError as exc:
        raise ModelError(source, item, f"cannot read {path} ({exc.strerror or exc})") from None
    if raw.startswith(b"version https://git-lfs"):
        raise ModelError(str(path), "", "is a Git LFS pointer, not the model: fetch the file "
                         "itself (git lfs pull)")
    if raw.startswith(b"\xef\xbb\xbf"):
        raw = raw[3:]
    if b"\x00" in raw[:4096]:
        raise ModelError(str(path), "", "is a binary OrcaFlex data file: open it in OrcaFlex "
                         "and save it as a text data file (File > Save as, type .yml), then "
                         "import that")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        try:
            return raw.decode("cp1252")       # OrcaFlex on Windows: a degree sign, a name
        except UnicodeDecodeError:
            raise ModelError(str(path), "", f"is neither UTF-8 nor Windows-1252 text (byte "
                             f"{exc.start}): a binary OrcaFlex data file? Save it from "
                             "OrcaFlex as a text data file (.yml)") from None


def _parse(path: Path, item: str, source: str):
    yaml = _yaml()
    text = _text(path, item, source)
    try:
        docs = [d for d in yaml.load_all(text, Loader=_loader(yaml)) if d is not None]
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
        where = f"line {mark.line + 1}" if mark is not None else ""
        what = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        raise ModelError(str(path), where, f"not a YAML text data file ({what})") from None
    if not docs:
        raise ModelError(str(path), "", "is empty: no OrcaFlex model in it")
    if len(docs) > 1:
        raise ModelError(str(path), "", f"holds {len(docs)} YAML documents; an OrcaFlex "
                         "text data file holds one model")
    return docs[0]


def _include_target(obj) -> str | None:
    """The path of an ``includefile`` directive (a mapping of that one key), else None."""
    if isinstance(obj, dict) and len(obj) == 1:
        (k, v), = obj.items()
        if isinstance(k, str) and k.lower() == "includefile":
            return str(v)
    return None


def read_model(path: str | Path) -> Model:
    """The OrcaFlex model of the text data file at ``path``, its include files resolved:
    a top-level list of ``- includefile: FILE`` items (each a model's sections, merged in
    order), an ``includefile`` item in a section's list of objects (its objects, or its
    one object, spliced in), or an ``IncludeFile: FILE`` key in a mapping (its keys put
    there). A ``BaseFile`` (a variation of another model) is refused."""
    path = Path(path)
    model = Model({}, str(path))
    top = _parse(path, "", str(path))
    for part in (top if isinstance(top, list) else [top]):
        for k in (part if isinstance(part, dict) else {}):
            low = k.lower() if isinstance(k, str) else ""
            if low == "basefile":
                raise ModelError(str(path), "BaseFile", f"{part[k]}: a variation of another "
                                 "model is not read: open it in OrcaFlex and save the whole "
                                 "model as a text data file")
            if low == "restartingfrom":
                raise ModelError(str(path), "RestartingFrom", f"{part[k]}: a restart "
                                 "analysis, whose model is in its parent: open the parent in "
                                 "OrcaFlex and save it as a text data file")
    stack = [path.resolve()]
    model.sections = _as_sections(_resolve(top, path, model, stack, ""), model, str(path))
    if not any(isinstance(k, str) and k.lower() in ("lines", "linetypes", "environment",
                                                    "general")
               for k in model.sections):
        raise ModelError(str(path), "", "is YAML but no OrcaFlex model: no General, "
                         "Environment, LineTypes or Lines section")
    return model


def _as_sections(obj, model: Model, item: str) -> dict:
    if isinstance(obj, dict):
        return obj
    if isinstance(obj, list) and all(isinstance(o, dict) for o in obj):
        merged: dict = {}
        for part in obj:
            for k, v in part.items():
                if k in merged and isinstance(merged[k], list) and isinstance(v, list):
                    merged[k] = merged[k] + v
                elif k in merged and isinstance(merged[k], dict) and isinstance(v, dict):
                    merged[k] = {**merged[k], **v}
                else:
                    merged[k] = v
        return merged
    raise ModelError(model.source, "", f"{item}: is not an OrcaFlex model (its top level "
                     "must be a mapping of sections)")


def _resolve(obj, here: Path, model: Model, stack: list[Path], item: str):
    """``obj`` with its include directives replaced by the files' content."""
    if isinstance(obj, list):
        out = []
        for k, o in enumerate(obj):
            target = _include_target(o)
            if target is None:
                out.append(_resolve(o, here, model, stack, f"{item}[{k}]"))
                continue
            got = _include(target, here, model, stack,
                           f"{item}[{k}].includefile" if item else f"includefile[{k}]")
            out.extend(got if isinstance(got, list) else [got])
        return out
    if isinstance(obj, dict):
        target = _include_target(obj)
        if target is not None and item:      # a section written as `NAME: {includefile: F}`
            return _include(target, here, model, stack, f"{item}.includefile")
        out = {}
        for k, v in obj.items():
            if isinstance(k, str) and k.lower() == "includefile" and len(obj) > 1:
                got = _include(str(v), here, model, stack, f"{item}.{k}")
                if not isinstance(got, dict):
                    raise ModelError(model.source, f"{item}.{k}", f"{v}: an IncludeFile "
                                     "among an object's keys must hold keys (a mapping)")
                out.update(got)
                continue
            out[k] = _resolve(v, here, model, stack, f"{item}.{k}" if item else str(k))
        return out
    return obj


def _include(target: str, here: Path, model: Model, stack: list[Path], item: str):
    name = target.replace("\\", "/")
    path = Path(name) if Path(name).is_absolute() else here.parent / name
    full = path.resolve()
    if full in stack:
        raise ModelError(model.source, item, f"{target} includes itself (through "
                         f"{' -> '.join(p.name for p in stack)})")
    if len(stack) > 20:
        raise ModelError(model.source, item, f"{target}: include files nested more than 20 "
                         "deep")
    doc = _parse(path, item, model.source)
    model.included.append(str(path))
    stack.append(full)
    try:
        return _resolve(doc, path, model, stack, item)
    finally:
        stack.pop()


# ------------------------------------------------------------------- values and tables
def key_of(obj: dict, *names: str):
    """The first of ``names`` present in ``obj`` (any letter case), or None."""
    lower = {k.lower(): k for k in obj if isinstance(k, str)}
    for n in names:
        if n.lower() in lower:
            return lower[n.lower()]
    return None


def get(obj: dict, *names: str, default=None):
    """The value of the first of ``names`` in ``obj`` (any letter case), else ``default``."""
    k = key_of(obj, *names)
    return obj[k] if k is not None else default


def number(value, source: str, item: str, allow_none: bool = False,
           allow_inf: bool = False) -> float | None:
    """``value`` as a finite float (OrcaFlex's numbers; PyYAML leaves ``711.2e3`` a
    string); ``Infinity``/``-Infinity`` only when ``allow_inf`` (an end's stiffness, a
    limit), ``~`` (None: OrcaFlex's default) only when ``allow_none``; NaN never."""
    if value is None:
        if allow_none:
            return None
        raise ModelError(source, item, "is ~ (OrcaFlex's default, which this import does "
                         "not know here): give the number")
    got = None
    if isinstance(value, bool):
        got = None
    elif isinstance(value, (int, float)):
        got = float(value)
    elif isinstance(value, str):
        t = value.strip().lower()
        got = {"infinity": math.inf, "+infinity": math.inf, "inf": math.inf,
               "-infinity": -math.inf, "-inf": -math.inf}.get(t)
        if got is None:
            try:
                got = float(t)
            except ValueError:
                got = None
    if got is None or math.isnan(got):
        raise ModelError(source, item, f"must be a number, got {value!r}")
    if math.isinf(got) and not allow_inf:
        raise ModelError(source, item, f"must be finite, got {value!r}")
    return got


def table(obj: dict, columns: tuple[str, ...], source: str, item: str) -> list[dict] | None:
    """The rows of the table in ``obj`` whose key names the columns ``columns`` (any
    letter case; the key may name more columns, and its rows may be shorter: the missing
    values are None, OrcaFlex's ``~``), each row a mapping column -> value; None when
    ``obj`` has no such table. A key naming only the first column, holding one row as a
    list or a value, is read as that row (OrcaFlex writes a one-column table so)."""
    want = [c.lower() for c in columns]
    for k, v in obj.items():
        if not isinstance(k, str):
            continue
        names = [n.strip() for n in k.split(",")]
        low = [n.lower() for n in names]
        if low[0] != want[0] or not set(want) <= set(low):
            continue
        if not isinstance(v, list):
            v = [[v]] if len(names) == 1 else [v]
        rows = []
        for r, row in enumerate(v):
            if len(names) == 1 and not isinstance(row, list):
                row = [row]
            if not isinstance(row, list):
                raise ModelError(source, f"{item}.{k}[{r}]", "a table row must be a list of "
                                 f"{len(names)} values")
            if len(row) > len(names):
                raise ModelError(source, f"{item}.{k}[{r}]", f"has {len(row)} values for "
                                 f"{len(names)} columns")
            rows.append({n: (row[i] if i < len(row) else None) for i, n in enumerate(names)})
        return rows
    return None

"""The key tables of docs/scene-files.md, generated from the field specs (:mod:`riser.spec`).

:func:`scene_keys_markdown` returns one Markdown table per scene table (key, type,
default, allowed range, unit, meaning), in the order of a scene file. The docs hold it
between the lines :data:`BEGIN` and :data:`END`; tests/test_scene_spec.py fails when the
block differs from the generator's output. After changing a spec, regenerate the block::

    python -m riser.model.spec_docs            # rewrite the block in docs/scene-files.md
    python -m riser.model.spec_docs --check    # exit 1 when the block is out of date

(or ``update_docs()`` from Python). Only the lines between the markers are written.
"""

from __future__ import annotations

import dataclasses
import sys
from pathlib import Path

from .attachments import Attachment
from ..design.part import Design, Fatigue, SeaState
from ..physics.dynamics import Dynamics, TopMotion
from .ends import FILE_KEYS as ENDS_FILE_KEYS
from .ends import (
    EndJoint,
    FixedEnds,
    HangOffAngleEnds,
    TdpTensionEnds,
    Tensioner,
    TopTensionEnds,
)
from ..physics.environment import Current, Seabed
from ..physics.internal_flow import SLUG, InternalFlow
from .line import FILE_KEYS as LINE_TYPE_FILE_KEYS
from .line import LineType, Segment
from .scene import ENV, MODEL_KEYS, Scene
from .settings import EXPERT, ANCFSettings, AnalyticSettings, BVPSettings, VFIFESettings
from ..spec import Spec, specs
from ..physics.vessel import RAOTable, Vessel
from ..physics.waves import WaveSpectrum, WaveTrain, Waves

BEGIN = "<!-- BEGIN generated: scene keys -->"
END = "<!-- END generated: scene keys -->"
#: the page the block lives in (a source checkout)
DOC = Path(__file__).resolve().parents[2] / "docs" / "scene-files.md"

_TYPES = {"number": "number", "integer": "integer", "boolean": "boolean", "string": "string",
          "numbers": "array of numbers", "strings": "array of strings"}


def _rows(cls, table: str = "", extra: dict | None = None) -> list[tuple[str, Spec, object]]:
    """(key, spec, default) of the fields of ``cls`` in its sub-table ``table`` ('' its
    own), then the file-only keys ``extra``."""
    fields = {f.name: f for f in dataclasses.fields(cls)}
    out = []
    for name, sp in specs(cls):
        if sp.kind == "part" or sp.table != table:
            continue
        f = fields[name]
        default = (f.default_factory() if f.default_factory is not dataclasses.MISSING
                   else f.default)
        out.append((sp.key or name, sp, default))
    out += [(key, sp, None) for key, sp in (extra or {}).items()]
    return out


#: (heading, rows) of every scene table, in the order of a scene file
def _tables() -> list[tuple[str, list]]:
    return [
        ("top level", _rows(Scene)),
        (f"[{ENV}]", _rows(Scene, ENV)),
        (f"[{ENV}.current]", _rows(Current)),
        (f"[{ENV}.waves]", _rows(Waves)),
        (f"[[{ENV}.waves.trains]]", _rows(WaveTrain)),
        (f"[{ENV}.waves.spectrum]", _rows(WaveSpectrum)),
        ("[seabed]", _rows(Seabed)),
        ("[line_types.NAME]", _rows(LineType, extra=LINE_TYPE_FILE_KEYS)),
        ("[[segments]]", _rows(Segment)),
        ("[[attachments]]", _rows(Attachment)),
        ("[ends]: touchdown tension", _rows(TdpTensionEnds)),
        ("[ends]: hang-off height and angle", _rows(HangOffAngleEnds, extra=ENDS_FILE_KEYS)),
        ("[ends]: J-lay, hang-off height and top tension", _rows(TopTensionEnds)),
        ("[ends]: fixed ends", _rows(FixedEnds)),
        ("[ends.anchor_joint], [ends.hang_off_joint]", _rows(EndJoint)),
        ("[ends.tensioner]", _rows(Tensioner)),
        ("[model]", [(key, sp, None) for key, sp in MODEL_KEYS.items()]),
        ("[dynamics]", _rows(Dynamics)),
        ("[dynamics.top_motion]", _rows(TopMotion)),
        ("[vessel]", _rows(Vessel)),
        ("[[vessel.raos]]", _rows(RAOTable)),
        ("[internal_flow]", _rows(InternalFlow)),
        ("[design]", _rows(Design)),
        ("[design.fatigue]", _rows(Fatigue)),
        ("[[design.fatigue.sea_states]]", _rows(SeaState)),
        (f"[internal_flow.{SLUG}]", _rows(InternalFlow, SLUG)),
        ("[bvp]", _rows(BVPSettings)),
        ("[analytic]", _rows(AnalyticSettings)),
        ("[vfife]", _rows(VFIFESettings)),
        (f"[vfife.{EXPERT}]", _rows(VFIFESettings, EXPERT)),
        ("[ancf]", _rows(ANCFSettings)),
    ]


def _value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return f"{v:g}"
    if isinstance(v, str):
        return f'"{v}"'
    if isinstance(v, tuple):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    return str(v)


def _default(sp: Spec, default) -> str:
    if sp.default_doc:
        return sp.default_doc
    if default is dataclasses.MISSING:
        return "not set" if sp.optional else "required"
    return "not set" if default is None else _value(default)


def _range(sp: Spec) -> str:
    """The allowed values in words, as the error messages say them."""
    parts = [f"{op} {_value(b)}" for op, b in
             ((">", sp.gt), (">=", sp.ge), ("<", sp.lt), ("<=", sp.le)) if b is not None]
    bounds = ", ".join(parts)
    if sp.kind == "numbers":
        n = (f"{' or '.join(map(str, sp.length))} entries" if isinstance(sp.length, tuple)
             else f"{sp.length} entries" if sp.length else
             f"at least {sp.min_length} entries" if sp.min_length > 1 else "")
        bounds = ", ".join(x for x in (n, f"each {bounds}" if bounds else "") if x)
    elif sp.kind in ("string", "strings") and sp.choices:
        bounds = ("each " if sp.kind == "strings" else "") + "one of " + ", ".join(
            f"`{c}`" for c in sp.choices) + (", no repeats" if sp.kind == "strings" else "")
    elif sp.pattern:
        bounds = f"matches `{sp.pattern}`"
    text = "; ".join(x for x in (bounds, sp.also) if x)
    return text or "any"


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def scene_keys_markdown() -> str:
    """The key tables of a scene file, one per table (Markdown, ending in a newline)."""
    out = []
    for heading, rows in _tables():
        out += [f"#### `{heading}`" if heading.startswith("[") else f"#### {heading}", "",
                "| key | type | default | allowed range | unit | meaning |",
                "|---|---|---|---|---|---|"]
        for key, sp, default in rows:
            out.append("| " + " | ".join(_cell(c) for c in (
                f"`{key}`", _TYPES[sp.kind], _default(sp, default), _range(sp),
                sp.unit or "-", sp.doc)) + " |")
        out.append("")
    return "\n".join(out)


def with_block(text: str, generated: str) -> str:
    """``text`` with the lines between :data:`BEGIN` and :data:`END` replaced by
    ``generated``; raises ValueError when the markers are not there once each."""
    if text.count(BEGIN) != 1 or text.count(END) != 1 or text.index(BEGIN) > text.index(END):
        raise ValueError(f"the page must hold the lines {BEGIN} and {END} once each, in order")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    return f"{head}{BEGIN}\n{generated}{END}{tail}"


def update_docs(path: Path = DOC, *, check: bool = False) -> bool:
    """Whether the generated block of ``path`` was out of date; rewrite it unless
    ``check``."""
    text = path.read_text(encoding="utf-8")
    new = with_block(text, scene_keys_markdown())
    if new != text and not check:
        path.write_text(new, encoding="utf-8")
    return new != text


def main(argv: list[str]) -> int:
    check = "--check" in argv
    stale = update_docs(check=check)
    if check and stale:
        print(f"{DOC}: the scene-key tables are out of date: run python -m riser.model.spec_docs",
              file=sys.stderr)
        return 1
    print(f"{DOC}: " + ("rewritten" if stale else "up to date"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

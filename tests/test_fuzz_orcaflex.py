"""Property-based fuzzing of OrcaFlex text data files (issue 51): the public models that
import (tests/data/orcaflex: the A01 catenary riser, the A01 lazy-wave riser's two lines,
the A01 steep-wave riser's line 1) with 1 to 4 values replaced (by ~, a word, a negative,
zero, a huge number, NaN, Infinity, a list, a mapping, a boolean) or their text cut,
a line dropped, a NUL or a tab put in; each read as ``riser-verify import-orcaflex``
reads it, with and without ``--statics``. Every outcome is an imported scene whose TOML
text reads back to the same scene, or a refusal (a SceneError: one line naming the file
and the OrcaFlex item); never another exception (which the command line would print as
"unexpected ... please report").

Default run: 60 inputs (3 s); ``-m slow``: 3000 (measured: 401 imported, 2599 refused,
no other exception).
"""

from __future__ import annotations

import copy
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from extras import needs_yaml

pytestmark = needs_yaml

DATA = Path(__file__).resolve().parent / "data" / "orcaflex"
#: (fixture, line) of the public models that import (with --statics)
MODELS = [("a01-catenary-riser.yml", "Catenary Hose"),
          ("a01-lazy-wave-riser.yml", '10" Lazy Wave Distributed'),
          ("a01-lazy-wave-riser.yml", '10" Lazy Wave Discrete'),
          ("a01-steep-wave-riser.yml", '10" Steep Wave1')]
VALUES = [None, "abc", -1.0, 0, 0.0, 1e30, -1e-9, float("nan"), "Infinity", "-Infinity",
          [], {}, [1, 2], ["a", None, 3], {"a": 1}, True, "~", "1,5", "711.2e3"]


def _leaves(o, path=()):
    if isinstance(o, dict):
        for k, v in o.items():
            yield from _leaves(v, path + (k,))
    elif isinstance(o, list) and o:
        for i, v in enumerate(o):
            yield from _leaves(v, path + (i,))
    else:
        yield path


def _set(o, path, v):
    for p in path[:-1]:
        o = o[p]
    o[path[-1]] = v


_BASE: dict = {}


def _base(name: str):
    import yaml
    if name not in _BASE:
        doc = yaml.safe_load((DATA / name).read_text())
        _BASE[name] = (doc, list(_leaves(doc)))
    return _BASE[name]


@st.composite
def inputs(draw):
    import yaml
    fixture, line = draw(st.sampled_from(MODELS))
    doc, leaves = _base(fixture)
    doc = copy.deepcopy(doc)
    for _ in range(draw(st.integers(1, 4))):
        path = leaves[draw(st.integers(0, len(leaves) - 1))]
        try:
            _set(doc, path, draw(st.sampled_from(VALUES)))
        except (KeyError, IndexError, TypeError):
            pass                                   # an earlier change took the branch
    text = "%YAML 1.1\n---\n" + yaml.safe_dump(doc, sort_keys=False, allow_unicode=True)
    cut = draw(st.sampled_from(["none", "truncate", "drop-line", "nul", "tab", "crlf"]))
    if cut == "truncate":
        text = text[:draw(st.integers(0, len(text)))]
    elif cut == "drop-line":
        rows = text.splitlines(keepends=True)
        del rows[draw(st.integers(0, len(rows) - 1))]
        text = "".join(rows)
    elif cut == "nul":
        k = draw(st.integers(0, len(text)))
        text = text[:k] + "\x00" + text[k:]
    elif cut == "tab":
        k = draw(st.integers(0, len(text)))
        text = text[:k] + "\t" + text[k:]
    elif cut == "crlf":
        text = text.replace("\n", "\r\n")
    return text, line, draw(st.booleans())


def _check(tmp_path, case, tally):
    from riser.errors import SceneError
    from riser.io.orcaflex.scene_from_model import import_model
    from riser.io.scene_file import parse_scene
    from riser.model.sections import segment_properties
    text, line, statics = case
    path = tmp_path / "model.yml"
    path.write_bytes(text.encode("utf-8"))
    try:
        toml, scene, _ = import_model(path, line=line, statics=statics)
    except SceneError as exc:
        assert str(exc).startswith(str(path)) and "\n" not in str(exc), str(exc)
        tally["refused"] += 1
        return
    back = parse_scene(toml, "back.toml")
    assert segment_properties(back) == segment_properties(scene)
    assert back.ends == scene.ends
    tally["imported"] += 1


def _run(tmp_path, n):
    tally = {"imported": 0, "refused": 0}

    @settings(max_examples=n, deadline=None, derandomize=True,
              suppress_health_check=list(HealthCheck))
    @given(inputs())
    def run(case):
        _check(tmp_path, case, tally)
    run()
    print(f"OrcaFlex fuzz: {tally['imported']} imported, {tally['refused']} refused of {n}")
    # both outcomes occur: a fuzz that only refuses (or only imports) tests nothing
    assert tally["imported"] > 0 and tally["refused"] > 0, tally


def test_fuzz_orcaflex_models(tmp_path):
    _run(tmp_path, 60)


@pytest.mark.slow
def test_fuzz_orcaflex_models_slow(tmp_path):
    _run(tmp_path, 3000)

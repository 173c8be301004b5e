"""The public OrcaFlex corpus (tests/data/orcaflex, SOURCES.md): every line of every
fixture imported with and without --statics, its outcome against the table below.

A refusal must name the OrcaFlex item (``ModelError.key``) given in the table, and that
item must really be unsupported in the file: :func:`evidence` reads the raw model and
checks the named item's value (a variable-data Cd with waves carried, a 6D buoy end, a
trimmed vessel, ...), so a refusal that names an item the import should have carried
fails. Every import gives a validated scene whose total length is the file's section
lengths converted to metres. ``pytest -s`` prints a summary.
"""

from __future__ import annotations

import collections
import math
import re
from pathlib import Path

import pytest

from extras import needs_yaml
from riser.io.orcaflex.scene_from_model import import_model
from riser.io.orcaflex.sea import trains_of
from riser.io.orcaflex.text_file import ModelError, get, number, read_model, table
from riser.io.orcaflex.units import units_of
from riser.model.scene import Scene

pytestmark = needs_yaml

DATA = Path(__file__).resolve().parent / "data" / "orcaflex"

#: the files that are no model: the refusal's key
NOT_MODELS = {"basefile-includefile-variation.yml": "BaseFile",
              "basefile-patch-supports.yml": "BaseFile",
              "restart-file.yml": "RestartingFrom"}

OK = "ok"
CD = 'LineTypes[10" flexible].Cd'
#: (fixture, line) -> (outcome without --statics, with --statics): "ok" or the key
EXPECTED = {
    ("a01-catenary-riser.yml", "Catenary Hose"):
        ('LineTypes[10" flexible variable Cd].Cd', OK),
    ("a01-lazy-wave-riser.yml", '10" Lazy Wave Distributed'): (CD, OK),
    ("a01-lazy-wave-riser.yml", '10" Lazy Wave Discrete'): (CD, "ClumpTypes[Module].Cd"),
    ("a01-pliant-wave-riser.yml", '10" Pliant Simple'):
        ('LineTypes[10"Product].Cd', 'Lines[10" Pliant Simple].Attachment'),
    ("a01-pliant-wave-riser.yml", '10" Pliant Detailed Up'):
        ('Lines[10" Pliant Detailed Up].Connection[End B]',) * 2,
    ("a01-pliant-wave-riser.yml", '10" Pliant Detailed Dn'):
        ('Lines[10" Pliant Detailed Dn].Connection[End A]',) * 2,
    ("a01-pliant-wave-riser.yml", "Tether Pliant Detailed"):
        ("Lines[Tether Pliant Detailed].Connection[End B]",) * 2,
    ("a01-steep-wave-riser.yml", '10" Steep Wave1'): (CD, OK),
    ("a01-steep-wave-riser.yml", "TopEnd BSR"):
        ("Lines[TopEnd BSR].Sections[2].Length",) * 2,
    ("a01-steep-wave-riser.yml", "Seabed End BSR"):
        ("Lines[Seabed End BSR].Sections[2].Length",) * 2,
    ("a01-steep-wave-riser.yml", '10" Steep Wave'):
        (CD, 'Lines[10" Steep Wave].Attachment[1].AttachmentType'),
    ("a05-catenary-semisub.yml", "Riser with Flexjoint"): ("Vessels[Semi].Orientation",) * 2,
    ("a05-catenary-semisub.yml", "Riser with TSJ"): ("Vessels[Semi].Orientation",) * 2,
    ("a05-lazy-wave-fpso.yml", "Riser with Flexjoint"):
        ("Lines[Riser with Flexjoint].Connection[End A].BendingStiffness",) * 2,
    ("c07-metocean-buoy-mooring.yml", "Mooring"): ("Lines[Mooring].Connection[End A]",) * 2,
    ("fowt-moorings-jonswap.yml", "Mooring1"): ("LineTypes[R4 Chain 114mm].EI",) * 2,
    ("fowt-moorings-jonswap.yml", "Mooring2"): ("LineTypes[R4 Chain 114mm].EI",) * 2,
    ("fowt-moorings-jonswap.yml", "Mooring3"): ("LineTypes[R4 Chain 114mm].EI",) * 2,
    ("fowt-moorings-jonswap.yml", "ExportCable"): ("Lines[ExportCable].Connection[End B]",) * 2,
}
CASES = [(f, ln, st) for (f, ln) in EXPECTED for st in (False, True)]


def _fixtures() -> list[str]:
    return sorted(p.name for p in DATA.glob("*.yml"))


def test_corpus_counts():
    """11 files: 8 models with 19 lines, and the 3 files that are no model."""
    names = _fixtures()
    assert len(names) == 11
    models = [n for n in names if n not in NOT_MODELS]
    assert set(NOT_MODELS) <= set(names)
    lines = {(n, str(ln.get("Name"))) for n in models
             for ln in read_model(DATA / n).objects("Lines")}
    assert len(models) == 8 and len(lines) == 19
    assert lines == set(EXPECTED)            # the table covers every line, and no other


@pytest.mark.parametrize("name", sorted(NOT_MODELS))
def test_files_that_are_no_model_are_refused(name):
    with pytest.raises(ModelError) as info:
        read_model(DATA / name)
    assert info.value.key == NOT_MODELS[name]


# ----------------------------------------------------------------- the refusals' proof
def _objects(model, section: str) -> dict[str, dict]:
    got = model.section(section)
    return {str(o.get("Name")): o for o in got} if isinstance(got, list) else {}


def _line(model, name: str) -> dict:
    return _objects(model, "Lines")[name]


def _variable_names(model, kind: str) -> set[str]:
    vd = model.section("VariableData") or {}
    return {str(t.get("Name")) for t in (get(vd, kind) or [])}


def _connection_rows(model, ln: dict) -> list[dict]:
    return table(ln, ("Connection", "ConnectionX", "ConnectionY", "ConnectionZ"),
                 model.source, "")


def _global_xyz(model, row: dict) -> tuple[float, float, float]:
    """An end's global position in the file's units (anchored: z above the seabed is
    not converted here: only Fixed and vessel ends are asked for)."""
    x, y, z = (number(get(row, c), model.source, c) for c in
               ("ConnectionX", "ConnectionY", "ConnectionZ"))
    conn = str(get(row, "Connection"))
    vessels = _objects(model, "Vessels")
    if conn in vessels:
        v = vessels[conn]
        vx, vy, vz = (number(c, "", "") for c in get(v, "InitialPosition"))
        psi = math.radians(number(get(v, "Orientation")[2], "", ""))
        return (vx + math.cos(psi) * x - math.sin(psi) * y,
                vy + math.sin(psi) * x + math.cos(psi) * y, vz + z)
    return x, y, z


def evidence(model, key: str, line: str, statics: bool, message: str) -> str:
    """Why the item ``key`` of the raw model is one the scene cannot hold (an
    AssertionError when it is not): read from the file, not from the importer."""
    src = model.source
    line_types, clumps = _objects(model, "LineTypes"), _objects(model, "ClumpTypes")
    m = re.fullmatch(r"LineTypes\[(.+)\]\.Cd", key)
    if m:
        cd = get(line_types[m[1]], "Cd")[0]
        assert cd in _variable_names(model, "Dragcoefficient"), cd
        values = {r[1] for r in _variable_rows(model, cd)}
        assert len(values) > 1, "a constant table would be carried"
        if not statics:
            assert trains_of(model.section("Environment") or {}), "no waves: carried"
        else:
            assert "Re = " in message
        return f"Cd from variable data ({cd})"
    m = re.fullmatch(r"LineTypes\[(.+)\]\.EI", key)
    if m:
        ei = get(line_types[m[1]], "EI")
        assert number(ei[0], src, key) == 0.0
        return "EI 0 (chain)"
    m = re.fullmatch(r"ClumpTypes\[(.+)\]\.Cd", key)
    if m:
        c = clumps[m[1]]
        area, cd = _per_axis(get(c, "DragArea")), _per_axis(get(c, "Cd"))
        cda = [a * d for a, d in zip(area, cd)]
        assert max(cda) != min(cda), cda
        env = model.section("Environment") or {}
        assert number(get(env, "RefCurrentSpeed"), src, key) > 0.0     # drag acts
        return "clump drag anisotropic"
    m = re.fullmatch(r"Vessels\[(.+)\]\.Orientation", key)
    if m:
        ori = get(_objects(model, "Vessels")[m[1]], "Orientation")
        assert any(number(o, src, key) != 0.0 for o in ori[:2]), ori
        return "vessel heeled or trimmed"
    m = re.fullmatch(r"Lines\[(.+)\]\.Sections\[(\d+)\]\.Length", key)
    if m:
        sections = get(_line(model, m[1]), "Sections")
        assert get(sections[int(m[2]) - 1], "Length") is None
        return "section length from a profile"
    m = re.fullmatch(r"Lines\[(.+)\]\.Attachment\[(\d+)\]\.AttachmentType", key)
    if m:
        rows = table(_line(model, m[1]), ("AttachmentType",), src, key)
        kind = str(get(rows[int(m[2]) - 1], "AttachmentType"))
        assert kind not in clumps and kind in _objects(model, "StiffenerTypes"), kind
        return "stiffener attachment"
    m = re.fullmatch(r"Lines\[(.+)\]\.Connection\[End ([AB])\]\.BendingStiffness", key)
    if m:
        rows = table(_line(model, m[1]), ("ConnectionxBendingStiffness",), src, key)
        k = get(rows["AB".index(m[2])], "ConnectionxBendingStiffness")
        assert k in _variable_names(model, "Bendingconnectionstiffness"), k
        return "nonlinear end stiffness (variable data)"
    m = re.fullmatch(r"Lines\[(.+)\]\.Connection\[End ([AB])\]", key)
    if m:
        row = _connection_rows(model, _line(model, m[1]))["AB".index(m[2])]
        conn = str(get(row, "Connection"))
        if conn in _objects(model, "6DBuoys"):
            return "end on a 6D buoy"
        # a Fixed end whose centre is below the scene's seabed (OrcaFlex's + OD/2)
        assert conn == "Fixed", conn
        u = units_of(model)
        env = model.section("Environment") or {}
        depth = number(get(env, "SeabedOriginDepth", "WaterDepth"), src, key) * u.length
        z = number(get(row, "ConnectionZ"), src, key) * u.length
        ltype = line_types[_sections(model, _line(model, m[1]))[-1 if m[2] == "B" else 0][0]]
        r = number(get(ltype, "OD"), src, key) * u.length / 2.0
        assert z < -depth + r, (z, depth, r)
        return "fixed end below the scene's seabed"
    m = re.fullmatch(r"Lines\[(.+)\]\.Attachment", key)
    if m:
        # the scene refused: clump attachments with a current out of the line's plane
        ln = _line(model, m[1])
        assert table(ln, ("AttachmentType",), src, key), "no attachments"
        assert "attachments" in message and "out of the x-y plane" in message
        a, b = (_global_xyz(model, r) for r in _connection_rows(model, ln))
        azimuth = math.degrees(math.atan2(a[1] - b[1], a[0] - b[0]))
        env = model.section("Environment") or {}
        theta = number(get(env, "RefCurrentDirection"), src, key)
        off = math.sin(math.radians(azimuth - theta))
        assert abs(off) > 0.1, (azimuth, theta)
        return "attachments with a current out of the plane"
    raise AssertionError(f"no evidence rule for {key!r}")


def _per_axis(values) -> list[float]:
    """OrcaFlex's [x, y, z] with ~ meaning the previous axis' value."""
    out = []
    for v in values:
        out.append(out[-1] if v is None else number(v, "", ""))
    return out


def _variable_rows(model, name: str) -> list[tuple[float, float]]:
    vd = model.section("VariableData") or {}
    for t in get(vd, "Dragcoefficient") or []:
        if str(t.get("Name")) == name:
            rows = table(t, ("IndependentValue", "DependentValue"), model.source, name)
            return [(number(r["IndependentValue"], "", ""), number(r["DependentValue"], "", ""))
                    for r in rows]
    raise AssertionError(name)


def _sections(model, ln: dict) -> list[tuple[str, float]]:
    """(line type, length in the file's units) of each section, End A first."""
    rows = table(ln, ("LineType", "Length"), model.source, "") or get(ln, "Sections")
    return [(str(get(r, "LineType")), number(get(r, "Length"), model.source, "Length"))
            for r in rows]


# --------------------------------------------------------------------------- the runs
SUMMARY: collections.Counter = collections.Counter()


@pytest.mark.parametrize("fixture, line, statics", CASES,
                         ids=[f"{f[:-4]}-{ln}-{'statics' if st else 'dynamics'}"
                              for f, ln, st in CASES])
def test_corpus_line(fixture, line, statics):
    path = DATA / fixture
    want = EXPECTED[(fixture, line)][statics]
    try:
        _, scene, _ = import_model(path, line=line, statics=statics)
    except ModelError as exc:
        SUMMARY[f"refused: {exc.key}"] += 1
        assert want != OK, f"refused {exc.key}: {exc.message}"
        assert exc.key == want, exc.message
        why = evidence(read_model(path), exc.key, line, statics, exc.message)
        print(f"{fixture} / {line} / statics={statics}: refused {exc.key} ({why})")
        return
    SUMMARY["imported"] += 1
    assert want == OK, f"imported, expected the refusal {want}"
    assert isinstance(scene, Scene)
    model = read_model(path)
    u = units_of(model)
    total = sum(length for _, length in _sections(model, _line(model, line))) * u.length
    # rel 1e-12: the same lengths summed in another order (End B first) and converted
    assert scene.total_length == pytest.approx(total, rel=1e-12)
    print(f"{fixture} / {line} / statics={statics}: imported, {scene.total_length:g} m")


def test_corpus_summary():
    """Runs after the lines (file order): prints the tally of outcomes (``-s``). Under
    pytest-xdist the tally is per worker, so it is only printed, not asserted."""
    if not SUMMARY:
        pytest.skip("the corpus runs were on other workers")
    print("\nOrcaFlex corpus: imports and refusals by item")
    for what, n in sorted(SUMMARY.items()):
        print(f"  {n:3d}  {what}")
    expected = collections.Counter(
        "imported" if w == OK else f"refused: {w}"
        for outcomes in EXPECTED.values() for w in outcomes)
    if sum(SUMMARY.values()) == len(CASES):
        assert SUMMARY == expected

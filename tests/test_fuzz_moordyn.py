"""Property-based fuzzing of MoorDyn v2 decks (issue 30, part 5): generated line-only decks
(a chain of 1 to 4 lines between two fixed or coupled ends, 1 to 3 line types, options, a
steady current profile), each with one mutation (a comma decimal, a token that is no
number, NaN or inf, a column dropped or added, a row or section dropped, duplicated or
swapped, a misspelt or v1 header, an unknown option, a bad attachment or ID, an unclosed
OUTPUTS, a broken current profile, the text's line ends, tabs, byte-order mark, NUL bytes,
truncation), read as ``riser-verify import-moordyn`` reads them
(``riser.io.moordyn.scene_from_deck.import_deck``); the scene file it would write must read
back to the same scene; a sample of the accepted ones solved.

Default run: 200 inputs and 73 names or paths;
``-m slow``: 4000 inputs (``RISER_FUZZ_SCALE`` scales it).
"""

from __future__ import annotations

import copy
import dataclasses
import math
import re
import shutil
from pathlib import Path

import pytest
from fuzz_strategies import (
    Input,
    Tally,
    _f,
    check_scene,
    read_outcome,
    run_fuzz,
    run_path_fuzz,
    scale,
    solve_outcome,
)
from hypothesis import strategies as st

from riser.io.moordyn.deck import OPTION_KEYS, SECTIONS, TEXT_OPTIONS
from riser.io.moordyn.scene_from_deck import import_deck
from riser.io.scene_file import parse_scene

TITLES = {"line_types": "LINE TYPES", "points": "POINTS", "lines": "LINES",
          "options": "OPTIONS", "outputs": "OUTPUTS"}
HEADERS = {
    "line_types": ["TypeName   Diam   Mass/m   EA   BA/-zeta   EI   Cd   Ca   CdAx   CaAx",
                   "(name)     (m)    (kg/m)   (N)  (N-s/-)   (N-m^2) (-)  (-)  (-)    (-)"],
    "points": ["ID   Attachment   X   Y   Z   Mass   Volume   CdA   Ca",
               "(#)  (-)          (m) (m) (m) (kg)   (m^3)    (m^2) (-)"],
    "lines": ["ID   LineType   AttachA   AttachB   UnstrLen   NumSegs   LineOutputs",
              "(#)  (name)     (#)       (#)       (m)        (-)       (-)"],
    "options": [], "outputs": []}
#: the columns a row needs (the line outputs may be left out)
REQUIRED = {"line_types": 10, "points": 9, "lines": 6, "options": 2, "outputs": 1}
#: tokens put in place of a value: not numbers, not finite, and numbers only Python reads
NOT_NUMBERS = ["x", "1.2.3", "0x10", "1d3", "\u221e", "--1", "1e", "1..0", "e5", "1_000",
               "1_0.5"]
NON_FINITE = ["nan", "NaN", "inf", "-inf", "1e400", "Infinity", "-1e999"]
#: numbers Python's float() reads and C's atof (MoorDyn) does not: other digits than ASCII
PYTHON_ONLY = ["\uff11", "\u0661\u0662", "\uff15.\uff10"]
ODD_NUMBERS = ["-1", "0", "-0", "+5", ".5", "5.", "1E+3", "1e-300", "1e300", "1e15", "7"]


@dataclasses.dataclass
class Row:
    section: str
    tokens: list[str]
    tail: str = ""                   # an option's description


@dataclasses.dataclass
class Deck:
    front: list[str]
    sections: list[tuple[str, list[str], list[Row]]]   # (title, table header lines, rows)
    closed: bool = True
    profile: str | None = None
    raw_ops: list[str] = dataclasses.field(default_factory=list)

    def rows(self, section: str) -> list[Row]:
        return [r for t, _, rows in self.sections if t == TITLES.get(section, section)
                for r in rows]

    def render(self) -> str:
        out = list(self.front)
        for title, head, rows in self.sections:
            out.append(f"---------------------- {title} ------------------------------")
            out.extend(head)
            for r in rows:
                out.append("  ".join(r.tokens) + (f"   {r.tail}" if r.tail else ""))
            if title == "OUTPUTS" and self.closed:
                out.append("------------------------- need this line -------------------")
        return "\n".join(out) + "\n"


def num(x: float) -> str:
    return repr(float(x)) if x != int(x) or abs(x) >= 1e15 else str(int(x))


@st.composite
def generated_deck(draw) -> tuple[Deck, dict]:
    """A line-only MoorDyn v2 deck that imports (mostly), and facts about it."""
    depth = draw(_f(30.0, 1500.0))
    h = depth * draw(_f(0.3, 1.0))                       # top height above the seabed
    span = draw(_f(0.1, 2.0)) * h
    heading = draw(_f(-math.pi, math.pi))
    x0, y0 = draw(_f(-500.0, 500.0)), draw(_f(-500.0, 500.0))
    chord = math.hypot(span, h)
    total = chord * draw(st.sampled_from([1.005, 1.02, 1.1, 1.3, 1.6, 2.0]))
    ntypes, nlines = draw(st.integers(1, 3)), draw(st.integers(1, 4))
    names = draw(st.lists(st.sampled_from(["chain", "rope", "steel", "poly", "riser", "a",
                                           "T1", "Line-2", "x_y", "\u00e9", "ctl\x01x",
                                           "q\"uote", "back\\slash", "a.b", "[x]"]),
                          min_size=ntypes, max_size=ntypes, unique=True))
    types = []
    for name in names:
        d = draw(_f(0.02, 0.5))
        mass = math.pi / 4 * d * d * 1025.0 * draw(_f(1.2, 8.0))          # sinks
        row = [name, num(round(d, 4)), num(round(mass, 3)),
               num(draw(st.sampled_from([1e7, 5e8, 2e9, 1e10]))),
               draw(st.sampled_from(["-0.8", "0", "1e4", "-1"])),
               num(draw(st.sampled_from([10.0, 1e3, 1e5, 1e7]))),
               num(draw(st.sampled_from([0.0, 1.0, 1.2, 2.4]))),
               num(draw(st.sampled_from([0.0, 1.0]))),
               num(draw(st.sampled_from([0.0, 0.03, 0.4]))),
               num(draw(st.sampled_from([0.0, 0.5])))]
        if draw(st.integers(0, 5)) == 0:
            row += draw(st.sampled_from([["0"], ["0.8", "0.2", "0.3"]]))
        types.append(Row("line_types", row))
    # points: the anchor, the joints, the top, and maybe a spare point, in a shuffled order
    roles = ["anchor"] + ["joint"] * (nlines - 1) + ["top"]
    if draw(st.integers(0, 4)) == 0:
        roles.append(draw(st.sampled_from(["spare-free", "spare-fixed"])))
    order = draw(st.permutations(roles))
    ids = {}
    for i, role in enumerate(order):
        ids.setdefault(role, []).append(i + 1)
    points = []
    top_kind = draw(st.sampled_from(["Fixed", "Coupled", "Vessel", "fixed"]))
    joint_n = 0
    for i, role in enumerate(order):
        if role == "anchor":
            f, kind, z = 0.0, draw(st.sampled_from(["Fixed", "Anchor", "fixed"])), -depth
        elif role == "top":
            f, kind, z = 1.0, top_kind, -depth + h
        elif role == "joint":
            joint_n += 1
            f, kind, z = joint_n / nlines, "Free", -depth + h * joint_n / nlines * 0.5
        else:
            f, kind, z = 0.5, "Free" if role == "spare-free" else "Fixed", -depth / 2
        x = x0 + f * span * math.cos(heading)
        y = y0 + f * span * math.sin(heading)
        points.append(Row("points", [str(i + 1), kind, num(round(x, 6)), num(round(y, 6)),
                                     num(round(z, 6)), "0", "0", "0", "0"]))
    chain = [ids["anchor"][0]] + ids.get("joint", []) + [ids["top"][0]]
    parts = [draw(_f(0.2, 1.0)) for _ in range(nlines)]
    lines = []
    for k in range(nlines):
        a, b = chain[k], chain[k + 1]
        if draw(st.integers(0, 3)) == 0:
            a, b = b, a                                      # a reversed line
        length = total * parts[k] / sum(parts)
        lines.append(Row("lines", [str(k + 1), draw(st.sampled_from(names)), str(a), str(b),
                                   num(round(length, 4)),
                                   str(draw(st.sampled_from([1, 5, 20, 50]))), "-"]))
    options = [Row("options", ["0", "writeLog"], "- no log file"),
               Row("options", [num(round(depth, 4)), "WtrDpth"], "- water depth (m)")]
    for key, values in (("g", [9.81, 9.8]), ("rho", [1025.0, 1024.0]),
                        ("kBot", [0.0, 3e6, 1e5]), ("cBot", [0.0, 3e5]),
                        ("FrictionCoefficient", [0.0, 0.5]), ("dtM", [0.001]),
                        ("TmaxIC", [2000.0]), ("threshIC", [0.0001])):
        if draw(st.booleans()):
            options.append(Row("options", [num(draw(st.sampled_from(values))), key],
                               f"- {key}"))
    profile = None
    if draw(st.integers(0, 4)) == 0:
        options.append(Row("options", ["1", "Currents"], "- steady current"))
        u, psi = draw(_f(-1.5, 1.5)), draw(_f(-math.pi, math.pi))
        zs = [-depth, -depth / 2, 0.0]
        rows = [f"{num(round(z, 6))} {num(round(u * (1 + z / depth) * math.cos(psi), 6))} "
                f"{num(round(u * (1 + z / depth) * math.sin(psi), 6))} 0" for z in zs]
        profile = "--- current profile ---\nz ux uy uz\n(m) (m/s) (m/s) (m/s)\n" + \
            "\n".join(rows) + "\n"
    outputs = [Row("outputs", ["FairTen1"]), Row("outputs", ["AnchTen1"])]
    front = ["--------------------- MoorDyn Input File ------------------------------------",
             draw(st.sampled_from(["a generated deck", "Mooring \u00e9 \"quoted\" \\ title",
                                   "tab\there", "ctrl \x01 char", "  ", "! a comment"]))]
    deck = Deck(front, [(TITLES[s], list(HEADERS[s]), rows) for s, rows in (
        ("line_types", types), ("points", points), ("lines", lines), ("options", options),
        ("outputs", outputs))], profile=profile)
    facts = {"roles": {i + 1: role for i, role in enumerate(order)}}
    return deck, facts


def point_used(deck: Deck, pid: str) -> bool:
    return any(pid in (r.tokens[2:4] if len(r.tokens) > 3 else []) for r in deck.rows("lines"))


#: options the import reads (the others MoorDyn's numerics, not carried, or skipped)
USED_OPTIONS = {"wtrdpth", "g", "gravity", "rho", "wtrdnsty", "kbot", "kb", "cbot", "cb",
                "frictioncoefficient", "currents", "wavekin"}


def strict(deck: Deck, row: Row, col: int, comma: bool) -> bool:
    """Whether the importer must refuse a malformed value (``comma``: a number written with
    a comma, which MoorDyn-C would read as another number) in this column of this row."""
    if row.section == "line_types":      # BA/-zeta is not carried (a number with a comma
        used = any(len(r.tokens) > 1 and r.tokens[1] == row.tokens[0]   # is refused there)
                   for r in deck.rows("lines"))
        return used and (1 <= col <= 10 and col != 4 or col == 4 and comma)
    if row.section == "points":
        if col in (0, 5, 6, 7, 8):
            return True
        if col in (2, 3, 4) and len(row.tokens) > 1:
            if comma:
                return True
            kind = re.sub(r"\d+$", "", row.tokens[1].lower())
            fixed = kind in ("fixed", "fix", "anchor", "coupled", "vessel", "ves", "cpld",
                             "fairlead")
            return fixed and point_used(deck, row.tokens[0])
        return False
    if row.section == "lines":
        return col in (0, 4, 5)
    if row.section == "options":
        if col != 0 or len(row.tokens) < 2:
            return False
        key = row.tokens[1].lower()
        if comma:
            return key in OPTION_KEYS and key not in TEXT_OPTIONS
        return key in USED_OPTIONS
    return False


def is_section_header(title: str) -> bool:
    """Whether a header line with ``title`` opens a section (a key phrase as a word)."""
    up = re.sub(r"\s+", " ", title.upper())
    return any(re.search(rf"(?<![A-Z]){k}(?![A-Z])", up) for k in SECTIONS)


NUMERIC_COLS = {"line_types": range(1, 13), "points": (0, 2, 3, 4, 5, 6, 7, 8),
                "lines": (0, 4, 5), "options": (0,)}


def _python_number(tok: str) -> float | None:
    try:
        return float(tok)
    except ValueError:
        return None


@st.composite
def deck_inputs(draw) -> Input:
    deck, facts = draw(generated_deck())
    op = draw(st.sampled_from([
        "none", "comma", "comma", "token", "token", "token", "drop_token", "drop_token",
        "add_token", "drop_row", "dup_row", "swap_rows", "drop_section", "dup_section",
        "misspell_header", "v1_header", "no_closing", "swap_sections", "unknown_option",
        "attach", "point_kind", "id", "profile", "text", "text"]))
    must, note, step = "", "", op
    all_rows = [(s, r) for s, _, rows in deck.sections for r in rows]
    data_rows = [r for _, r in all_rows if r.section in NUMERIC_COLS]
    if op in ("comma", "token"):
        row = draw(st.sampled_from(data_rows))
        cols = [c for c in NUMERIC_COLS[row.section] if c < len(row.tokens)]
        col = draw(st.sampled_from(cols))
        old = row.tokens[col]
        if op == "comma":
            new = old.replace(".", ",", 1) if "." in old else old + ",5"
            bad = True
        else:
            new = draw(st.sampled_from(NOT_NUMBERS + NON_FINITE + PYTHON_ONLY + ODD_NUMBERS))
            v = _python_number(new)
            bad = v is None or not math.isfinite(v) or "_" in new or new in PYTHON_ONLY
        row.tokens[col] = new
        step = f"{row.section} row {row.tokens[0]!r}: column {col} {old!r} -> {new!r}"
        if bad and strict(deck, row, col, op == "comma"):
            must = (f"{new!r} (MoorDyn-C reads it as another number, or none) in column {col}"
                    f" of a {row.section} row")
        elif bad:
            note = f"{new!r} in column {col} of a {row.section} row accepted (not used)"
    elif op == "drop_token":
        row = draw(st.sampled_from(data_rows))
        col = draw(st.integers(0, len(row.tokens) - 1))
        del row.tokens[col]
        step = f"{row.section} row: column {col} dropped ({len(row.tokens)} left)"
        if len(row.tokens) < REQUIRED[row.section] and row.section != "options":
            must = f"a {row.section} row of {len(row.tokens)} columns"
    elif op == "add_token":
        row = draw(st.sampled_from(data_rows))
        row.tokens.insert(draw(st.integers(0, len(row.tokens))), draw(st.sampled_from(
            ["0", "1.0", "x", "-"])))
        step = f"{row.section} row: a column added ({len(row.tokens)})"
    elif op == "drop_row":
        s, r = draw(st.sampled_from(all_rows))
        next(rows for t, _, rows in deck.sections if t == s).remove(r)
        step = f"{s} row {' '.join(r.tokens)[:40]!r} dropped"
    elif op == "dup_row":
        s, r = draw(st.sampled_from(all_rows))
        rows = next(rows for t, _, rows in deck.sections if t == s)
        rows.insert(rows.index(r) + 1, copy.deepcopy(r))
        step = f"{s} row {' '.join(r.tokens)[:40]!r} duplicated"
        if s in ("LINE TYPES", "POINTS", "LINES"):
            must = f"a duplicated {s} row"
    elif op == "swap_rows":
        s = draw(st.sampled_from(["POINTS", "LINES"]))
        rows = next(rows for t, _, rows in deck.sections if t == s)
        if len(rows) > 1:
            i = draw(st.integers(0, len(rows) - 2))
            rows[i], rows[i + 1] = rows[i + 1], rows[i]
            step = f"{s} rows {i + 1} and {i + 2} swapped"
            must = "IDs out of order"
    elif op == "drop_section":
        i = draw(st.integers(0, len(deck.sections) - 1))
        title = deck.sections.pop(i)[0]
        step = f"section {title} dropped"
        if title not in ("OUTPUTS", "OPTIONS"):
            must = f"no {title} section"
    elif op == "dup_section":
        i = draw(st.integers(0, len(deck.sections) - 1))
        deck.sections.insert(i + 1, copy.deepcopy(deck.sections[i]))
        step = f"section {deck.sections[i][0]} twice"
        must = "a section twice"
    elif op == "misspell_header":
        i = draw(st.integers(1, len(deck.sections) - 1))
        title = deck.sections[i][0]
        new = draw(st.sampled_from([title[:-1], title + "X", title.replace(" ", "_"),
                                    title.lower() + " ZZ", "OPTION", "LINE TYPE"]))
        deck.sections[i] = (new, *deck.sections[i][1:])
        step = f"header {title!r} -> {new!r}"
        if not is_section_header(new):
            must = f"the rows after the misspelt header {new!r}"
    elif op == "v1_header":
        i = draw(st.integers(0, len(deck.sections) - 1))
        deck.sections[i] = (draw(st.sampled_from(["LINE PROPERTIES", "NODE PROPERTIES",
                                                  "SOLVER OPTIONS"])), *deck.sections[i][1:])
        step = f"section {deck.sections[i][0]!r} given a v1 header"
    elif op == "no_closing":
        deck.closed = False
        step = "OUTPUTS not closed"
    elif op == "swap_sections":
        i = draw(st.integers(0, len(deck.sections) - 2))
        deck.sections[i], deck.sections[i + 1] = deck.sections[i + 1], deck.sections[i]
        step = f"sections {deck.sections[i + 1][0]} and {deck.sections[i][0]} swapped"
    elif op == "unknown_option":
        key = draw(st.sampled_from(["dtMM", "WaterDepth", "depth", "kbott", "x"]))
        next(rows for t, _, rows in deck.sections if t == "OPTIONS").append(
            Row("options", ["1", key]))
        step = f"option {key!r}"
        facts["unknown_option"] = key
    elif op == "attach":
        row = draw(st.sampled_from(deck.rows("lines")))
        col = draw(st.sampled_from([2, 3]))
        new = draw(st.sampled_from(["99", "0", "-1", "R1A", "Body1", "1.5", "x"]))
        step = f"line {row.tokens[0]}: Attach{'AB'[col - 2]} {row.tokens[col]} -> {new}"
        row.tokens[col] = new
        must = f"line attached to {new!r}"
    elif op == "point_kind":
        row = draw(st.sampled_from(deck.rows("points")))
        new = draw(st.sampled_from(["Body1", "Turbine", "R2B", "Free", "Coupled", "Fixed",
                                    "vessel", "FREE", "point"]))
        step = f"point {row.tokens[0]}: {row.tokens[1]} -> {new}"
        row.tokens[1] = new
        if new in ("Body1", "Turbine", "R2B"):
            must = f"a point attached to {new!r}"
    elif op == "id":
        s = draw(st.sampled_from(["points", "lines"]))
        row = draw(st.sampled_from(deck.rows(s)))
        new = draw(st.sampled_from(["0", "-1", "99", "1.5", "x", "1e0"]))
        step = f"{s} ID {row.tokens[0]} -> {new}"
        if new in ("1.5", "1e0") and row.tokens[0] == "1":
            note = f"ID {new!r} taken as 1 (as MoorDyn-C's atoi would)"
        elif new != row.tokens[0]:
            must = f"{s} ID {new!r}"
        row.tokens[0] = new
    elif op == "profile":
        if deck.profile is None:
            deck.sections[3][2].append(Row("options", ["1", "Currents"]))
            step = "Currents 1 without current_profile.txt"
            must = "no current profile"
        else:
            lines = deck.profile.splitlines()
            how = draw(st.sampled_from(["uz", "comma", "nan", "short", "empty", "dup", "turn"]))
            if how == "uz":
                lines[-1] = lines[-1].rsplit(" ", 1)[0] + " 0.1"
            elif how == "comma":
                lines[-1] = lines[-1].replace(".", ",", 1) if "." in lines[-1] else \
                    lines[-1].replace(" ", ",5 ", 1)
            elif how == "nan":
                lines[-1] = "nan 0 0 0"
            elif how == "short":
                lines[-1] = lines[-1].split()[0]
            elif how == "empty":
                lines = lines[:3]
            elif how == "dup":
                lines.append(lines[-1])
            else:
                z = lines[-2].split()[0]
                lines[-2] = f"{z} 0.3 -0.7 0"
            deck.profile = "\n".join(lines) + "\n"
            step = f"current profile: {how}"
            if how in ("uz", "nan", "short", "empty", "dup", "comma"):
                must = f"current profile {how}"
    text = deck.render()
    if op == "text":
        how = draw(st.sampled_from(["crlf", "tabs", "bom", "nul", "truncate", "empty",
                                    "latin1", "garbage_after", "comment_row"]))
        step = f"text: {how}"
        if how == "crlf":
            text = text.replace("\n", "\r\n")
        elif how == "tabs":
            text = text.replace("  ", "\t")
        elif how == "bom":
            text = "\ufeff" + text
        elif how == "nul":
            i = draw(st.integers(0, len(text)))
            text = text[:i] + "\x00" + text[i:]
            must = "NUL byte"
        elif how == "truncate":
            text = text[:draw(st.integers(0, len(text)))]
        elif how == "empty":
            text = ""
            must = "an empty deck"
        elif how == "latin1":
            text = text.replace("a generated deck", "d\u00e9j\u00e0 vu")
        elif how == "garbage_after":
            text += "random words after the end 1 2 3\n"
        else:
            lines = text.splitlines()
            i = draw(st.integers(0, len(lines) - 1))
            lines[i] = "! " + lines[i]
            text = "\n".join(lines) + "\n"
    files = {"deck.dat": text}
    if deck.profile is not None and not (op == "profile" and must == "no current profile"):
        files["current_profile.txt"] = deck.profile
    return Input(text, f"a generated deck; {step}", files=files, must_refuse=must,
                 notes_if_accepted=note, facts=facts)


class DeckFuzz:
    def __init__(self, kind: str, folder: Path, solve_every: int, solve_max: int):
        self.tally = Tally(kind)
        self.dir = folder / "deck"
        self.accepted = 0
        self.solve_every, self.solve_max, self.solved = solve_every, solve_max, 0

    def __call__(self, inp: Input) -> None:
        shutil.rmtree(self.dir, ignore_errors=True)
        self.dir.mkdir(parents=True)
        for name, content in inp.files.items():
            data = content.encode("latin-1") if "d\u00e9j\u00e0" in content and \
                name == "deck.dat" else content.encode("utf-8")
            (self.dir / name).write_bytes(data)
        path = self.dir / "deck.dat"
        got = read_outcome(self.tally, inp, lambda: import_deck(path),
                           nlines=len(inp.text.splitlines()) + 1)
        if got is None:
            return
        text, scene, notes = got
        if not check_scene(self.tally, scene, inp):
            return
        unknown = inp.facts.get("unknown_option")
        if unknown and not any(unknown in n for n in notes):
            self.tally.accepted_finding("an option skipped without a note",
                                        "riser/io/moordyn/options.py",
                                        f"option {unknown!r} accepted, no note names it", inp)
            return
        try:                         # the scene file import-moordyn writes must read back
            back = parse_scene(text, "deck.toml")
        except Exception as exc:     # noqa: BLE001
            self.tally.accepted_finding("the written scene file does not read back",
                                        "riser/io/moordyn/scene_from_deck.py",
                                        f"{type(exc).__name__}: {str(exc)[:300]}", inp)
            return
        if dataclasses.replace(back, source=scene.source) != scene:
            self.tally.accepted_finding("the written scene file reads back to another scene",
                                        "riser/io/moordyn/scene_from_deck.py", "scene differs",
                                        inp)
            return
        self.accepted += 1
        solve_outcome(self.tally, "analytic", scene, inp, budget=20.0)          # milliseconds
        if self.accepted % self.solve_every == 0 and self.solved < self.solve_max:
            method = ("bvp", "vfife")[self.solved % 2]
            self.solved += 1
            solve_outcome(self.tally, method, scene, inp, budget=30.0)


def test_fuzz_moordyn_decks(tmp_path):
    """200 generated MoorDyn decks, reproducible: no finding; counts printed."""
    fuzz = DeckFuzz("moordyn decks", tmp_path, solve_every=7, solve_max=6)
    run_fuzz(deck_inputs(), fuzz, max_examples=200)
    fuzz.tally.check()


@pytest.mark.slow
def test_fuzz_moordyn_decks_slow(tmp_path):
    """4000 generated MoorDyn decks (x RISER_FUZZ_SCALE), ~60 solves."""
    n = max(1, math.ceil(4000 * scale()))
    fuzz = DeckFuzz("moordyn decks (slow)", tmp_path, solve_every=25, solve_max=max(1, n // 65))
    run_fuzz(deck_inputs(), fuzz, max_examples=n)
    fuzz.tally.check()


def test_fuzz_deck_paths(tmp_path):
    """33 odd names and special files (a FIFO, a directory, a link loop, binary, UTF-16,
    a name too long for the file system, ...) and 40 generated names where
    a deck file is expected."""
    run_path_fuzz("deck paths", import_deck, tmp_path, 40).check()

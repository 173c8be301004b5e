"""The MoorDyn v2 input file ("deck"): reading it into tables and writing one.

Only the text format lives here (its writing is :func:`riser.io.moordyn.deck_from_scene.format_deck`),
not its meaning for a riser (:mod:`riser.io.moordyn.options`, :mod:`riser.io.moordyn.scene_from_deck`,
:mod:`riser.io.moordyn.deck_from_scene`). The format is the one MoorDyn-C 2.7 reads
(source/MoorDyn2.cpp, ``ReadInFile`` and ``findStartOfSection``; moordyn.readthedocs.io,
"The V2 Input File"):

- free front matter, then sections. A **section header** is any line holding ``---``
  and one of MoorDyn's key phrases (``SECTIONS``, any case: "SOLVER OPTIONS" is the
  OPTIONS section, "CONNECTION PROPERTIES" the POINTS, as MoorDyn-C reads them);
- a section ends at the next line holding ``---``: another header or a terminator such as
  ``---- need this line ----``. A row after a terminator is read by no section of
  MoorDyn-C, so it is refused here (a misspelt header, or dashes inside an option's
  description, which end MoorDyn's OPTIONS there);
- a table section has two header lines (names, units) before its rows; ``!``, ``#`` and
  ``%`` start a comment; OPTIONS rows are ``value key [description]``.

Every problem raises :class:`DeckError`, one line naming the deck file and the line number,
e.g. ``riser.dat: line 12: line type 'pipe': EI: 'x' is not a number``. A problem of a line
type is kept and raised only if a line uses that type (MoorDyn reads the others too).

MoorDyn's coordinates: X, Y horizontal, Z up with the still water surface at Z = 0 and the
seabed at Z = -WtrDpth; SI units (m, kg, N, s).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

from ...errors import one_line
from ..scene_file import read_file_bytes
from .tokens import (  # noqa: F401 - the format's names, importable from here too
    C_OPTIONS,
    CANONICAL,
    OPTION_KEYS,
    ORDER,
    SECTIONS,
    TEXT_OPTIONS,
    DeckError,
    comma_message,
    is_comma_number,
    is_number,
    number,
)

#: the columns of a v2 line type after its name (10 to 13 columns with the name; MoorDyn
#: reads them by position, whatever the header says)
LINE_TYPE_COLUMNS = ("Diam", "Mass/m", "EA", "BA/-zeta", "EI", "Cd", "Ca", "CdAx", "CaAx")
LINE_TYPE_VIV = ("Cl", "dF", "cF")
POINT_COLUMNS = ("X", "Y", "Z", "Mass", "Volume", "CdA", "Ca")
#: the columns of a 12-column point row (MoorDyn-C reads FX FY FZ when 12 are given)
POINT_COLUMNS_12 = ("X", "Y", "Z", "Mass", "Volume", "FX", "FY", "FZ", "CdA", "Ca")


@dataclass(frozen=True)
class DeckLineType:
    """A LINE TYPES row: name; diameter [m] (volume-equivalent); mass [kg/m]; EA [N];
    BA/-zeta (kept as written: N s, or minus a fraction of critical); EI [N m2]; Cd, Ca,
    CdAx, CaAx [-]; Cl [-] (VIV lift, 0 = off); ``line`` its line number."""

    name: str
    diameter: float
    mass: float
    EA: float
    BA: str
    EI: float
    Cd: float
    Ca: float
    CdAx: float
    CaAx: float
    Cl: float = 0.0
    line: int = 0


@dataclass(frozen=True)
class DeckPoint:
    """A POINTS row: id; attachment as written (Fixed, Coupled, Free, Body2, ...); x, y,
    z [m] (None when not given as numbers); mass [kg], volume [m3], CdA [m2], Ca [-]; the
    steady force FX FY FZ [N] of a 12-column row."""

    id: int
    attachment: str
    x: float | None
    y: float | None
    z: float | None
    mass: float = 0.0
    volume: float = 0.0
    CdA: float = 0.0
    Ca: float = 0.0
    line: int = 0
    force: tuple[float, float, float] = (0.0, 0.0, 0.0)

    @property
    def kind(self) -> str:
        """'fixed', 'coupled', 'free' or 'other' (body- or rod-relative), as MoorDyn-C
        reads the attachment (its letters, any case)."""
        a = re.sub(r"\d+$", "", self.attachment.lower())
        if a in ("fixed", "fix", "anchor"):
            return "fixed"
        if a in ("coupled", "vessel", "ves", "cpld", "fairlead"):
            return "coupled"
        if a in ("free", "connect", "con", "point"):
            return "free"
        return "other"


@dataclass(frozen=True)
class DeckLine:
    """A LINES row: id, line type name, the attachments of end A (bottom) and end B as
    written (a point id, or R1A for a rod end), unstretched length [m], segments."""

    id: int
    line_type: str
    attach_a: str
    attach_b: str
    length: float
    segments: int
    outputs: str = "-"
    line: int = 0


@dataclass
class Deck:
    """A parsed deck. ``options`` maps the lower-case option name as written to (value as
    written, line), the last row of that name; ``option_rows`` every OPTIONS row in order
    (name as written, '' for a row without a name; value; line); ``line_type_errors`` the
    problem of each line type that cannot be read (raised if a line uses it); ``other``
    maps the name of a section this suite cannot hold (bodies, rods, ...) to the line
    number of its first row; ``outputs`` the OUTPUTS channels; ``notes`` what the reading
    noticed (sections out of order)."""

    source: str
    front: list[str] = field(default_factory=list)
    line_types: dict[str, DeckLineType] = field(default_factory=dict)
    line_type_errors: dict[str, DeckError] = field(default_factory=dict)
    points: list[DeckPoint] = field(default_factory=list)
    lines: list[DeckLine] = field(default_factory=list)
    options: dict[str, tuple[str, int]] = field(default_factory=dict)
    option_rows: list[tuple[str, str, int]] = field(default_factory=list)
    outputs: list[str] = field(default_factory=list)
    other: dict[str, int] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    def option_entry(self, key: str) -> tuple[str, int, str] | None:
        """(value, line, name as written) of the option ``key`` as MoorDyn-C reads it: the
        last row among the option's name and its aliases; None when none is given."""
        canon = CANONICAL.get(key.lower(), key)
        names = {a.lower() for a in (canon, *C_OPTIONS.get(canon, ()))} or {key.lower()}
        got = [(v, no, k) for k, (v, no) in self.options.items() if k in names]
        if not got:
            return None
        value, no, k = max(got, key=lambda e: e[1])
        return value, no, next((n for n, _, line in self.option_rows if line == no and no), k)

    def option(self, key: str, default: float | None = None) -> float | None:
        """The numeric value of option ``key`` (any alias), or ``default``."""
        got = self.option_entry(key)
        return default if got is None else float(got[0])

    def option_line(self, key: str) -> int:
        got = self.option_entry(key)
        return 0 if got is None else got[1]


# ---------------------------------------------------------------------------- reading
def read_deck(path: str | Path) -> Deck:
    """Read a MoorDyn v2 deck from a file (UTF-8 or Latin-1 text of at most 5 MB)."""
    text, where = read_text(path, "a MoorDyn input file")
    return parse_deck(text, where)


def read_text(path: str | Path, what: str, limit: int = 5_000_000) -> tuple[str, str]:
    """(the text of a regular file of at most ``limit`` bytes, UTF-8 or else Latin-1, the
    file's name as messages print it: control characters escaped); a one-line error
    otherwise (:func:`riser.io.scene_file.read_file_bytes`: a folder, a pipe or device,
    which is never opened, a file too large; here also binary data)."""
    where = one_line(str(path))
    data = read_file_bytes(path, what, limit)
    if b"\x00" in data:
        raise DeckError(where, 0, f"is binary data (it holds NUL bytes), not {what} (plain "
                        "text)")
    try:
        return data.decode("utf-8-sig"), where
    except UnicodeDecodeError:
        return data.decode("latin-1"), where


def _section_of(line: str) -> str | None:
    """The section a line holding ``---`` opens (its key phrase, any case), else None."""
    up = re.sub(r"\s+", " ", line.upper())
    for key, name in SECTIONS.items():
        if re.search(rf"(?<![A-Z]){key}(?![A-Z])", up):
            return name
    return None


def _strip_comment(line: str) -> str:
    return re.split(r"[!#%]", line, maxsplit=1)[0].strip()


def parse_deck(text: str, source: str = "<deck>") -> Deck:
    """Parse deck text into a :class:`Deck`; raise :class:`DeckError` naming the line."""
    deck = Deck(source=source)
    section: str | None = None
    skip = 0          # table header lines still to skip
    seen: list[str] = []
    closed: tuple[int, str, str] | None = None     # (line, text, section) of a terminator
    names: list[str] = []                           # the column names of the table
    for no, raw in enumerate(text.splitlines(), start=1):
        if "---" in raw:                            # MoorDyn-C: a header or a terminator
            name = _section_of(raw)
            if name is None:
                if not seen:
                    deck.front.append(raw)          # a decorative title line
                elif section is not None:
                    closed = (no, raw.strip(), section)
                    section = None
                continue
            if name in seen:
                head = re.sub(r"\s+", " ", raw.strip("- \t")).title()
                raise DeckError(source, no, f"section '{head}' appears twice")
            if seen and ORDER.index(name) < ORDER.index(seen[-1]):
                deck.notes.append(f"Section {name.replace('_', ' ').upper()} (line {no}) "
                                  f"comes after {seen[-1].replace('_', ' ').upper()}: "
                                  "MoorDyn-C finds each section anywhere and reads it; "
                                  "MoorDyn-F reads them in its order only.")
            seen.append(name)
            section, closed, names = name, None, []
            skip = 2 if name not in ("options", "outputs") else 0
            continue
        if section is None:
            if not seen:
                deck.front.append(raw)
            elif _strip_comment(raw) and closed is not None:
                c_no, c_text, c_sec = closed
                raise DeckError(source, no, f"a row after line {c_no} ({c_text[:60]!r}), "
                                f"which holds '---' and so ends the {c_sec.upper()} section "
                                "without opening another: MoorDyn reads no row from there "
                                "to the next section header (a misspelt header, or dashes "
                                "in a description?)")
            continue
        if skip:
            skip -= 1
            body = _strip_comment(raw)
            if body and _numbers_only(body.split()[1:]) and len(body.split()) > 2:
                raise DeckError(source, no, f"a data row where the {section.replace('_', ' ')}"
                                " table's header lines belong: a table starts with two lines "
                                "(column names, then units) before its rows")
            if skip == 1:
                names = raw.split()
            continue
        body = _strip_comment(raw)
        if not body:
            continue
        if section == "lines" and _v1_lines(names, body.split()):
            raise DeckError(source, no, "a line in MoorDyn v1's layout (Line LineType "
                            "UnstrLen NumSegs NodeAnch NodeFair Flags): this reads v2 "
                            "decks (ID LineType AttachA AttachB UnstrLen NumSegs "
                            "LineOutputs), as MoorDyn-C 2.7 does: convert the deck to v2")
        tokens = body.split()
        bad = next((c for tok in tokens for c in tok if not c.isprintable()), None)
        if bad is not None and section != "outputs":
            raise DeckError(source, no, f"holds the control character U+{ord(bad):04X}: a "
                            "MoorDyn deck is plain text (is the file damaged?)")
        _ROW[section](deck, tokens, no)
    if "lines" not in seen:
        raise DeckError(source, 0, "has no LINES section (a MoorDyn deck needs at least one "
                        "line; is this a MoorDyn v2 input file?)")
    return deck


def _v1_lines(names: list[str], tok: list[str]) -> bool:
    """A LINES row of MoorDyn v1: UnstrLen as the third column (by its header, or a length
    there with two point numbers after the segment count)."""
    if len(names) > 2 and names[2].lower().startswith("unstrlen"):
        return True
    return (len(tok) >= 6 and is_number(tok[2]) and not tok[2].isdigit()
            and tok[4].isdigit() and tok[5].isdigit())


def _numbers_only(tokens) -> bool:
    return bool(tokens) and all(is_number(t) for t in tokens)


def _row_line_type(deck: Deck, tok: list[str], no: int) -> None:
    src = deck.source
    name = tok[0]
    n = len(tok) - 1
    if n == 8:
        raise DeckError(src, no, f"line type '{name}' has 9 columns (MoorDyn v1's layout); a "
                        "v2 line type has 10 (TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx "
                        "CaAx): the bending stiffness EI is missing. Refused, not taken as 0: "
                        "every method here solves a beam (give EI > 0 [N m2])")
    if n < 9:
        raise DeckError(src, no, f"line type '{name}' has {n + 1} columns; a v2 line type has "
                        "10 (TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx), or up to "
                        "13 with the VIV columns Cl dF cF")
    if name in deck.line_types or name in deck.line_type_errors:
        first = deck.line_types[name].line if name in deck.line_types else \
            deck.line_type_errors[name].line
        raise DeckError(src, no, f"line type '{name}' is defined twice (first on line "
                        f"{first})")
    try:
        deck.line_types[name] = _line_type(src, tok, no)
    except DeckError as exc:        # raised only if a line uses this type
        deck.line_type_errors[name] = exc


def _line_type(src: str, tok: list[str], no: int) -> DeckLineType:
    name = tok[0]
    what = f"line type '{name}'"
    ea = tok[3]
    if is_comma_number(ea):
        raise DeckError(src, no, comma_message(f"{what}: EA", ea))
    if not is_number(ea):
        kind = "viscoelastic (static|dynamic)" if "|" in ea else "nonlinear (a curve file)"
        raise DeckError(src, no, f"{what}: EA: {ea!r} is a {kind} stiffness; only a "
                        "constant EA [N] can be imported")
    ei = tok[5]
    if not is_number(ei) and not is_comma_number(ei):
        raise DeckError(src, no, f"{what}: EI: {ei!r} is a nonlinear bending stiffness (a "
                        "curve file) or not a number; only a constant EI [N m2] can be "
                        "imported")
    v = {c: number(src, no, f"{what}: {c}", t, ge=0.0)
         for c, t in zip(LINE_TYPE_COLUMNS, tok[1:10]) if c != "BA/-zeta"}
    for c in ("Diam", "Mass/m", "EA"):
        if v[c] <= 0.0:
            raise DeckError(src, no, f"{what}: {c}: must be > 0, got {v[c]:g}")
    if v["EI"] <= 0.0:
        raise DeckError(src, no, f"{what}: EI: must be > 0 [N m2], got {v['EI']:g}: a line "
                        "without bending stiffness is a cable model, and every method here "
                        "solves a beam (refused, not taken as 0)")
    ba = tok[4]
    for part in ba.split("|"):
        if is_comma_number(part):
            raise DeckError(src, no, comma_message(f"{what}: BA/-zeta", part))
        if not is_number(part) or not math.isfinite(float(part)):
            raise DeckError(src, no, f"{what}: BA/-zeta: {ba!r} is not a finite number (N s, "
                            "or minus a fraction of critical damping)")
    cl = number(src, no, f"{what}: Cl", tok[10], ge=0.0) if len(tok) > 10 else 0.0
    return DeckLineType(name=name, diameter=v["Diam"], mass=v["Mass/m"], EA=v["EA"], BA=ba,
                        EI=v["EI"], Cd=v["Cd"], Ca=v["Ca"], CdAx=v["CdAx"], CaAx=v["CaAx"],
                        Cl=cl, line=no)


def _row_id(deck: Deck, tok: list[str], no: int, kind: str, columns: str, count: int) -> int:
    """The ID of a POINTS or LINES row, checked with the row's column count."""
    need = len(columns.split()) - (kind == "line")       # a line's outputs may be left out
    if len(tok) < need:
        raise DeckError(deck.source, no, f"{kind} row has {len(tok)} columns; a v2 {kind} "
                        f"has {len(columns.split())} ({columns})")
    rid = int(number(deck.source, no, f"{kind} ID", tok[0], gt=0.0))
    if rid != count + 1:
        raise DeckError(deck.source, no, f"{kind} ID {tok[0]}: IDs must run 1, 2, 3, ... in "
                        f"order (expected {count + 1})")
    return rid


def _row_point(deck: Deck, tok: list[str], no: int) -> None:
    src = deck.source
    pid = _row_id(deck, tok, no, "point", "ID Attachment X Y Z Mass Volume CdA Ca",
                  len(deck.points))
    xyz = []
    for c, t in zip("XYZ", tok[2:5]):
        if is_comma_number(t):
            raise DeckError(src, no, comma_message(f"point {pid}: {c}", t))
        xyz.append(number(src, no, f"point {pid}: {c}", t) if is_number(t) else None)
    cols = POINT_COLUMNS_12 if len(tok) >= 12 else POINT_COLUMNS
    v = {c: number(src, no, f"point {pid}: {c}", t) for c, t in zip(cols[3:], tok[5:])}
    deck.points.append(DeckPoint(pid, tok[1], *xyz, v["Mass"], v["Volume"], v["CdA"], v["Ca"],
                                 line=no, force=tuple(v.get(f, 0.0) for f in ("FX", "FY", "FZ"))))


def _row_line(deck: Deck, tok: list[str], no: int) -> None:
    src = deck.source
    lid = _row_id(deck, tok, no, "line", "ID LineType AttachA AttachB UnstrLen NumSegs "
                  "LineOutputs", len(deck.lines))
    length = number(src, no, f"line {lid}: UnstrLen", tok[4], gt=0.0)
    nseg = number(src, no, f"line {lid}: NumSegs", tok[5], ge=1.0)
    if nseg != int(nseg):
        raise DeckError(src, no, f"line {lid}: NumSegs: must be a whole number, got {tok[5]}")
    deck.lines.append(DeckLine(lid, tok[1], tok[2], tok[3], length, int(nseg),
                               tok[6] if len(tok) > 6 else "-", line=no))


def _row_option(deck: Deck, tok: list[str], no: int) -> None:
    """An OPTIONS row, kept as written: MoorDyn-C skips a row without a name, and what an
    option means is :mod:`riser.io.moordyn.options`'s."""
    if len(tok) < 2:
        deck.option_rows.append(("", tok[0], no))
        return
    value, key = tok[0], tok[1]
    deck.option_rows.append((key, value, no))
    deck.options[key.lower()] = (value, no)


def _row_output(deck: Deck, tok: list[str], no: int) -> None:
    deck.outputs.append(tok[0])


def _row_other(section: str):
    def row(deck: Deck, tok: list[str], no: int) -> None:
        deck.other.setdefault(section, no)
    return row


_ROW = {"line_types": _row_line_type, "points": _row_point, "lines": _row_line,
        "options": _row_option, "outputs": _row_output,
        **{s: _row_other(s) for s in ("rod_types", "bodies", "rods", "failure", "control",
                                      "external_loads")}}

"""The MoorDyn v2 input file ("deck"): reading it into tables and writing one.

Only the text format lives here (its writing is :func:`riser.io.moordyn.deck_from_scene.format_deck`),
not its meaning for a riser (:mod:`riser.io.moordyn.scene_from_deck`, :mod:`riser.io.moordyn.deck_from_scene`). The format is MoorDyn-C v2's
(moordyn.readthedocs.io, "The V2 Input File"): free front matter, then sections opened by a
header of dashes around a key phrase, in this order: LINE TYPES, ROD TYPES, BODIES, RODS,
POINTS, LINES, (FAILURE, CONTROL, EXTERNAL LOADS), OPTIONS, OUTPUTS; a table section has
two header lines (names, units) before its rows; ``!``, ``#`` and ``%`` start a comment;
OPTIONS rows are ``value key [description]``; a dashed line ends the OUTPUTS.

Every problem raises :class:`DeckError`, one line naming the deck file and the line number,
e.g. ``riser.dat: line 12: line type 'pipe': EI: 'x' is not a number``.

MoorDyn's coordinates: X, Y horizontal, Z up with the still water surface at Z = 0 and the
seabed at Z = -WtrDpth; SI units (m, kg, N, s).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

from ...errors import SceneError


class DeckError(SceneError):
    """Invalid or unsupported MoorDyn deck content: names the file and the line number
    (``line`` 0 when the problem is the file as a whole)."""

    def __init__(self, source: str, line: int, message: str):
        super().__init__(source, f"line {line}" if line else "", message)
        self.line = line


#: section key phrases (upper case, as MoorDyn matches them) -> section name
SECTIONS = {
    "LINE TYPES": "line_types", "LINE DICTIONARY": "line_types",
    "ROD TYPES": "rod_types", "ROD DICTIONARY": "rod_types",
    "BODIES": "bodies", "BODY LIST": "bodies", "BODY PROPERTIES": "bodies",
    "RODS": "rods", "ROD LIST": "rods", "ROD PROPERTIES": "rods",
    "POINTS": "points", "POINT LIST": "points", "POINT PROPERTIES": "points",
    "LINES": "lines", "LINE LIST": "lines",
    "FAILURE": "failure", "CONTROL": "control", "EXTERNAL LOADS": "external_loads",
    "OPTIONS": "options", "OUTPUTS": "outputs",
}
#: headers of the v1 format, refused with a pointer to v2
V1_SECTIONS = ("NODE PROPERTIES", "CONNECTION PROPERTIES", "LINE PROPERTIES", "SOLVER OPTIONS")

#: the OPTIONS keys MoorDyn-C 2.x reads (and MoorDyn-F's, which C ignores), lower case ->
#: the spelling written; values that are not numbers are listed in TEXT_OPTIONS
OPTION_KEYS = {k.lower(): k for k in (
    "writeLog", "dtM", "CFL", "tScheme", "g", "gravity", "rho", "rhoW", "WtrDpth", "kBot",
    "kb", "cBot", "cb", "dtIC", "TmaxIC", "CdScaleIC", "threshIC", "WaveKin", "dtWave",
    "waveKin_rampT", "Currents", "UnifyCurrentGrid", "WriteUnits", "FrictionCoefficient",
    "FricDamp", "StatDynFricScale", "dtOut", "SeafloorFile", "ICgenDynamic",
    "disableOutput", "disableOutTime", "Echo", "WaterKin", "MU_KT", "MU_KA", "MC", "CV",
    "inertialF", "inertialF_rampT", "OutSwitch", "ICDfac", "ICthresh", "ICTmax")}
TEXT_OPTIONS = ("tscheme", "seafloorfile", "waterkin", "echo")

#: the columns of a v2 line type after its name (10 to 13 columns with the name)
LINE_TYPE_COLUMNS = ("Diam", "Mass/m", "EA", "BA/-zeta", "EI", "Cd", "Ca", "CdAx", "CaAx")
LINE_TYPE_VIV = ("Cl", "dF", "cF")
POINT_COLUMNS = ("X", "Y", "Z", "Mass", "Volume", "CdA", "Ca")


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
    z [m] (None when not given as numbers); mass [kg], volume [m3], CdA [m2], Ca [-]."""

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

    @property
    def kind(self) -> str:
        """'fixed', 'coupled', 'free' or 'other' (body- or rod-relative)."""
        a = self.attachment.lower()
        if a in ("fixed", "fix", "anchor"):
            return "fixed"
        if a in ("coupled", "vessel", "vec", "ves", "cpld", "fairlead"):
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
    """A parsed deck. ``options`` maps the lower-case key to (value as written, line);
    ``other`` maps the name of a section this suite cannot hold (bodies, rods, ...) to the
    line number of its first row; ``outputs`` the OUTPUTS channels."""

    source: str
    front: list[str] = field(default_factory=list)
    line_types: dict[str, DeckLineType] = field(default_factory=dict)
    points: list[DeckPoint] = field(default_factory=list)
    lines: list[DeckLine] = field(default_factory=list)
    options: dict[str, tuple[str, int]] = field(default_factory=dict)
    outputs: list[str] = field(default_factory=list)
    other: dict[str, int] = field(default_factory=dict)

    def option(self, key: str, default: float | None = None) -> float | None:
        """The numeric value of option ``key`` (any spelling), or ``default``."""
        got = self.options.get(key.lower())
        return default if got is None else float(got[0])

    def option_line(self, key: str) -> int:
        got = self.options.get(key.lower())
        return 0 if got is None else got[1]


# ---------------------------------------------------------------------------- reading
def read_deck(path: str | Path) -> Deck:
    """Read a MoorDyn v2 deck from a file (UTF-8 or Latin-1 text of at most 5 MB)."""
    path = Path(path)
    where = str(path)
    try:
        if path.is_dir():
            raise DeckError(where, 0, "is a directory, not a MoorDyn input file")
        data = path.read_bytes()[:5_000_001]
    except OSError as exc:
        raise DeckError(where, 0, f"cannot read file ({exc.strerror or exc})") from None
    if len(data) > 5_000_000:
        raise DeckError(where, 0, "is larger than 5 MB, too large for a MoorDyn input file")
    if b"\x00" in data:
        raise DeckError(where, 0, "is binary data (it holds NUL bytes), not a MoorDyn input "
                        "file (plain text)")
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        text = data.decode("latin-1")
    return parse_deck(text, where)


def _header(line: str) -> str | None:
    """The key phrase of a section header line (dashes around words), else None."""
    s = line.strip()
    if not s.startswith("---"):
        return None
    return re.sub(r"\s+", " ", s.strip("- \t")).upper()


def _strip_comment(line: str) -> str:
    return re.split(r"[!#%]", line, maxsplit=1)[0].strip()


def parse_deck(text: str, source: str = "<deck>") -> Deck:
    """Parse deck text into a :class:`Deck`; raise :class:`DeckError` naming the line."""
    deck = Deck(source=source)
    section: str | None = None
    skip = 0          # table header lines still to skip
    ended = False
    seen: list[str] = []
    for no, raw in enumerate(text.splitlines(), start=1):
        head = _header(raw)
        if head is not None:
            if section == "outputs":
                ended = True
                break
            if any(v1 in head for v1 in V1_SECTIONS):
                raise DeckError(source, no, f"section '{head.title()}' is MoorDyn v1 format; "
                                "this reads v2 decks (POINTS and LINES with AttachA/AttachB, "
                                "OPTIONS): convert the deck to v2")
            name = next((v for k, v in SECTIONS.items() if head == k or head.startswith(k + " ")
                         or head.endswith(" " + k) or f" {k} " in f" {head} "), None)
            if name is None:
                if section is None and not seen:
                    deck.front.append(raw)       # a decorative title line
                    continue
                raise DeckError(source, no, f"unknown section header '{head.title()}' (a v2 "
                                "deck has: " + ", ".join(dict.fromkeys(
                                    k.title() for k in SECTIONS)) + ")")
            if name in seen:
                raise DeckError(source, no, f"section '{head.title()}' appears twice")
            seen.append(name)
            section = name
            skip = 2 if name not in ("options", "outputs") else 0
            continue
        if section is None:
            deck.front.append(raw)
            continue
        if skip:
            skip -= 1
            body = _strip_comment(raw)
            if body and _numbers_only(body.split()[1:]) and len(body.split()) > 2:
                raise DeckError(source, no, f"a data row where the {section.replace('_', ' ')}"
                                " table's header lines belong: a table starts with two lines "
                                "(column names, then units) before its rows")
            continue
        body = _strip_comment(raw)
        if not body:
            continue
        _ROW[section](deck, body.split(), no)
    if "lines" not in seen:
        raise DeckError(source, 0, "has no LINES section (a MoorDyn deck needs at least one "
                        "line; is this a MoorDyn v2 input file?)")
    if "options" not in seen:
        raise DeckError(source, 0, "has no OPTIONS section (WtrDpth and the other settings)")
    if section == "outputs" and not ended:
        raise DeckError(source, 0, "the OUTPUTS section is not closed by a line of dashes "
                        "(MoorDyn stops reading there)")
    return deck


def _numbers_only(tokens) -> bool:
    return bool(tokens) and all(_is_number(t) for t in tokens)


def _is_number(tok: str) -> bool:
    try:
        float(tok)
        return True
    except ValueError:
        return False


def _number(source: str, no: int, what: str, tok: str, *, ge: float | None = None,
            gt: float | None = None) -> float:
    """A finite number from a token, else a DeckError naming ``what``."""
    try:
        v = float(tok)
    except ValueError:
        raise DeckError(source, no, f"{what}: {tok!r} is not a number") from None
    if not math.isfinite(v):
        raise DeckError(source, no, f"{what}: must be finite, got {tok}")
    if ge is not None and v < ge:
        raise DeckError(source, no, f"{what}: must be >= {ge:g}, got {tok}")
    if gt is not None and v <= gt:
        raise DeckError(source, no, f"{what}: must be > {gt:g}, got {tok}")
    return v


def _row_line_type(deck: Deck, tok: list[str], no: int) -> None:
    src = deck.source
    name = tok[0]
    n = len(tok) - 1
    if n == 8:
        raise DeckError(src, no, f"line type '{name}' has 9 columns; a v2 line type has 10 "
                        "(TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx): the bending "
                        "stiffness EI is missing. Refused, not taken as 0: every method here "
                        "solves a beam (give EI > 0 [N m2])")
    if n < 9 or n > 12:
        raise DeckError(src, no, f"line type '{name}' has {n + 1} columns; a v2 line type has "
                        "10 (TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx), or up to "
                        "13 with the VIV columns Cl dF cF")
    if name in deck.line_types:
        raise DeckError(src, no, f"line type '{name}' is defined twice (first on line "
                        f"{deck.line_types[name].line})")
    what = f"line type '{name}'"
    if not _is_number(tok[3]):
        raise DeckError(src, no, f"{what}: EA: {tok[3]!r} is a nonlinear or viscoelastic "
                        "stiffness (a table file or EA_static|EA_dynamic); only a constant EA "
                        "[N] can be imported")
    v = {c: _number(src, no, f"{what}: {c}", t, ge=0.0)
         for c, t in zip(LINE_TYPE_COLUMNS, tok[1:10]) if c != "BA/-zeta"}
    for c in ("Diam", "Mass/m", "EA"):
        if v[c] <= 0.0:
            raise DeckError(src, no, f"{what}: {c}: must be > 0, got {v[c]:g}")
    if v["EI"] <= 0.0:
        raise DeckError(src, no, f"{what}: EI: must be > 0 [N m2], got {v['EI']:g}: a line "
                        "without bending stiffness is a cable model, and every method here "
                        "solves a beam (refused, not taken as 0)")
    ba = tok[4]
    if not all(_is_number(p) for p in ba.split("|")):
        raise DeckError(src, no, f"{what}: BA/-zeta: {ba!r} is not a number (N s, or minus "
                        "a fraction of critical damping)")
    cl = _number(src, no, f"{what}: Cl", tok[10], ge=0.0) if n >= 10 else 0.0
    deck.line_types[name] = DeckLineType(
        name=name, diameter=v["Diam"], mass=v["Mass/m"], EA=v["EA"], BA=ba, EI=v["EI"],
        Cd=v["Cd"], Ca=v["Ca"], CdAx=v["CdAx"], CaAx=v["CaAx"], Cl=cl, line=no)


def _row_id(deck: Deck, tok: list[str], no: int, kind: str, columns: str, count: int) -> int:
    """The ID of a POINTS or LINES row, checked with the row's column count."""
    need = len(columns.split()) - (kind == "line")       # a line's outputs may be left out
    if len(tok) < need:
        raise DeckError(deck.source, no, f"{kind} row has {len(tok)} columns; a v2 {kind} "
                        f"has {len(columns.split())} ({columns})")
    rid = int(_number(deck.source, no, f"{kind} ID", tok[0], gt=0.0))
    if rid != count + 1:
        raise DeckError(deck.source, no, f"{kind} ID {tok[0]}: IDs must run 1, 2, 3, ... in "
                        f"order (expected {count + 1})")
    return rid


def _row_point(deck: Deck, tok: list[str], no: int) -> None:
    src = deck.source
    pid = _row_id(deck, tok, no, "point", "ID Attachment X Y Z Mass Volume CdA Ca",
                  len(deck.points))
    xyz = [float(t) if _is_number(t) else None for t in tok[2:5]]
    rest = [_number(src, no, f"point {pid}: {c}", t)
            for c, t in zip(POINT_COLUMNS[3:], tok[5:9])]
    deck.points.append(DeckPoint(pid, tok[1], *xyz, *rest, line=no))


def _row_line(deck: Deck, tok: list[str], no: int) -> None:
    src = deck.source
    lid = _row_id(deck, tok, no, "line", "ID LineType AttachA AttachB UnstrLen NumSegs "
                  "LineOutputs", len(deck.lines))
    length = _number(src, no, f"line {lid}: UnstrLen", tok[4], gt=0.0)
    nseg = _number(src, no, f"line {lid}: NumSegs", tok[5], ge=1.0)
    if nseg != int(nseg):
        raise DeckError(src, no, f"line {lid}: NumSegs: must be a whole number, got {tok[5]}")
    deck.lines.append(DeckLine(lid, tok[1], tok[2], tok[3], length, int(nseg),
                               tok[6] if len(tok) > 6 else "-", line=no))


def _row_option(deck: Deck, tok: list[str], no: int) -> None:
    src = deck.source
    if len(tok) < 2:
        raise DeckError(src, no, f"option row {tok[0]!r} has no key: an option is written "
                        "'value key [description]'")
    value, key = tok[0], tok[1]
    k = key.lower()
    if k not in OPTION_KEYS:
        raise DeckError(src, no, f"unknown option {key!r} (MoorDyn's options: "
                        + ", ".join(sorted(OPTION_KEYS.values(), key=str.lower)) + ")")
    if k not in TEXT_OPTIONS:
        _number(src, no, f"option {key}", value)
    if k in deck.options:
        raise DeckError(src, no, f"option {key} given twice (first on line "
                        f"{deck.options[k][1]})")
    deck.options[k] = (value, no)


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

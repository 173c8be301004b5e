"""The words of a MoorDyn deck as MoorDyn-C 2.7 reads them: its section key phrases and
option names, numbers (C's ``atof``, which stops at the first character it cannot read: a
number written with a comma, ``1,5e9``, is 1 to MoorDyn-C, so it is refused here, naming
the line), and the error naming a deck line."""

from __future__ import annotations

import math
import re

from ...errors import SceneError


class DeckError(SceneError):
    """Invalid or unsupported MoorDyn deck content: names the file and the line number
    (``line`` 0 when the problem is the file as a whole)."""

    def __init__(self, source: str, line: int, message: str):
        super().__init__(source, f"line {line}" if line else "", message)
        self.line = line


#: section key phrases (as MoorDyn-C 2.7 matches them, in any case) -> section name;
#: CONTROL and EXTERNAL LOADS are MoorDyn-F's
SECTIONS = {
    "LINE TYPES": "line_types", "LINE DICTIONARY": "line_types",
    "ROD TYPES": "rod_types", "ROD DICTIONARY": "rod_types",
    "BODIES": "bodies", "BODY LIST": "bodies", "BODY PROPERTIES": "bodies",
    "RODS": "rods", "ROD LIST": "rods", "ROD PROPERTIES": "rods",
    "POINTS": "points", "POINT LIST": "points", "POINT PROPERTIES": "points",
    "CONNECTION PROPERTIES": "points", "NODE PROPERTIES": "points",
    "LINES": "lines", "LINE LIST": "lines", "LINE PROPERTIES": "lines",
    "FAILURE": "failure", "CONTROL": "control", "EXTERNAL LOADS": "external_loads",
    "OPTIONS": "options", "OUTPUTS": "outputs", "OUTPUT": "outputs",
}

#: MoorDyn's order of the sections (MoorDyn-F's reading order; MoorDyn-C finds each anywhere)
ORDER = ("line_types", "rod_types", "bodies", "rods", "points", "lines", "failure", "control",
         "external_loads", "options", "outputs")

#: the options MoorDyn-C 2.7 reads (source/MoorDyn2.cpp, ``readOptionsLine``; it compares
#: names in lower case, and of a name and its aliases the last row wins): the spelling
#: written -> its aliases. Any other name MoorDyn-C skips ("Unrecognized option").
C_OPTIONS = {
    "writeLog": (), "dtM": ("DT",), "CFL": (), "tScheme": (), "g": ("gravity",),
    "rho": ("WtrDnsty",), "WtrDpth": (), "kBot": ("kb",), "cBot": ("cb",),
    "dtIC": ("ICdt",), "TmaxIC": ("ICTmax",), "CdScaleIC": ("ICDfac",),
    "threshIC": ("ICthresh",), "ICgenDynamic": ("GenDynamicIC",), "fileIC": ("ICfile",),
    "WaveKin": (), "dtWave": (), "waveKin_rampT": (), "Currents": (),
    "UnifyCurrentGrid": (), "WriteUnits": (), "FrictionCoefficient": (), "FricDamp": (),
    "StatDynFricScale": (), "dtOut": (), "SeafloorFile": (), "disableOutput": (),
    "disableOutTime": ()}
#: lower-case name (any alias) -> the spelling of its option in C_OPTIONS
CANONICAL = {a.lower(): k for k, aliases in C_OPTIONS.items() for a in (k, *aliases)}
#: lower-case name -> the spelling written (the deck writer's table)
OPTION_KEYS = {a.lower(): a for k, aliases in C_OPTIONS.items() for a in (k, *aliases)}
#: options whose value is a word or a file name, not a number
TEXT_OPTIONS = ("tscheme", "seafloorfile", "fileic", "icfile")

_COMMA_NUMBER = re.compile(r"[+-]?[\d.,]*\d[\d.,]*(?:[eE][+-]?\d+)?")
_C_PREFIX = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")


def is_comma_number(tok: str) -> bool:
    """A number written with a comma (``1,5e9``, ``1,500``)."""
    return "," in tok and _COMMA_NUMBER.fullmatch(tok) is not None


def comma_message(what: str, tok: str) -> str:
    """Why a number with a comma is refused: MoorDyn reads C numbers (``atof``), which stop
    at the comma, so MoorDyn-C would silently take the digits before it."""
    head = _C_PREFIX.match(tok)
    taken = float(head.group()) if head else 0.0
    fix = f"; as a decimal comma it is {tok.replace(',', '.')}" if tok.count(",") == 1 else ""
    return (f"{what}: {tok!r} is a number with a comma (a decimal comma or a thousands "
            f"separator): MoorDyn reads numbers with a decimal point only, and stops at the "
            f"comma (MoorDyn-C would take {taken:g}){fix}")


def is_number(tok: str) -> bool:
    """A token Python reads as a number and C reads whole: ASCII only (Python also reads
    other scripts' digits), no ``_`` digit separators."""
    if "_" in tok or not tok.isascii():
        return False
    try:
        float(tok)
        return True
    except ValueError:
        return False


def number(source: str, no: int, what: str, tok: str, *, ge: float | None = None,
            gt: float | None = None) -> float:
    """A finite number from a token, else a DeckError naming ``what``."""
    if is_comma_number(tok):
        raise DeckError(source, no, comma_message(what, tok))
    if not is_number(tok):
        raise DeckError(source, no, f"{what}: {tok!r} is not a number")
    v = float(tok)
    if not math.isfinite(v):
        raise DeckError(source, no, f"{what}: must be finite, got {tok}")
    if ge is not None and v < ge:
        raise DeckError(source, no, f"{what}: must be >= {ge:g}, got {tok}")
    if gt is not None and v <= gt:
        raise DeckError(source, no, f"{what}: must be > {gt:g}, got {tok}")
    return v

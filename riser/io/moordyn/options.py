"""A MoorDyn deck's OPTIONS as MoorDyn-C 2.7 reads them, and what a scene makes of them.

MoorDyn-C 2.7 (source/MoorDyn2.cpp): the ``MoorDyn`` constructor sets the environment's
defaults (``env->g = 9.80665; env->WtrDpth = 0.; env->rho_w = 1025.; env->kb = 3.0e6;
env->cb = 3.0e5; FrictionCoefficient 0, FricDamp 200, StatDynFricScale 1``), then
``readOptionsLine`` reads the names of :data:`~riser.io.moordyn.deck.C_OPTIONS` in lower
case (the density as ``rho``, ``Rho`` or ``WtrDnsty``, never ``rhoW``, MoorDyn-F's name);
the last row of a name and its aliases wins; any other name is skipped with the warning
"Unrecognized option". While reading the points, a point below the seabed lowers it:
``WtrDpth`` becomes the depth of the deepest point ("Water depth set to point N z
position"). Measured on moordyn 2.7.2 (the weight per metre of a line with each option).

``WaveKin`` 7 (summed wave components, :mod:`riser.io.moordyn.waves`) is honoured with its
``waveKin_rampT``; any other value but 0 is refused. Each option is honoured, refused (one
line naming the deck line and the feature), or read and not carried with a note
(MoorDyn's numerics, initial-condition solver and output, which the scene's methods do
not share); names MoorDyn-C does not read are skipped as it skips them, with a note.
"""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field

from .deck import Deck
from .tokens import CANONICAL, TEXT_OPTIONS, DeckError, comma_message, is_comma_number, is_number

#: MoorDyn-C 2.7's defaults of what a scene needs (source/MoorDyn2.cpp, the MoorDyn
#: constructor; WtrDpth 0 is then lowered to the deepest point)
DEFAULTS = {"g": 9.80665, "rho": 1025.0, "WtrDpth": 0.0, "kBot": 3.0e6, "cBot": 3.0e5,
            "FrictionCoefficient": 0.0, "FricDamp": 200.0, "StatDynFricScale": 1.0,
            "WaveKin": 0.0, "Currents": 0.0, "waveKin_rampT": 0.0}
SOURCE = "MoorDyn-C 2.7, source/MoorDyn2.cpp"
#: read and not carried: MoorDyn's time stepping, initial-condition solver and output
NUMERICS = ("writeLog", "dtM", "CFL", "tScheme", "dtIC", "TmaxIC", "CdScaleIC", "threshIC",
            "ICgenDynamic", "fileIC", "dtOut", "WriteUnits", "disableOutput",
            "disableOutTime", "dtWave", "waveKin_rampT", "UnifyCurrentGrid")
#: the options that change the physics (lower case): a name MoorDyn-C does not read that
#: is close to one of these is refused as a misspelling
PHYSICS = {k.lower(): k for k in (
    "g", "gravity", "rho", "WtrDnsty", "WtrDpth", "kBot", "cBot", "FrictionCoefficient",
    "FricDamp", "StatDynFricScale", "Currents", "WaveKin", "SeafloorFile")}
#: names MoorDyn-C 2.7 does not read (it warns "Unrecognized option"), with what they are
NOT_READ = {
    "rhow": "MoorDyn-F's water density", "depth": "MoorPy's water depth",
    "waterkin": "MoorDyn-F's water kinematics file",
    "mu_kt": "MoorDyn-F's transverse seabed friction coefficient",
    "mu_ka": "MoorDyn-F's axial seabed friction coefficient",
    "mc": "MoorDyn-F's static/dynamic friction ratio", "cv": "MoorDyn-F's friction damping",
    "inertialf": "MoorDyn-F's inertial coupled forces",
    "inertialf_rampt": "MoorDyn-F's inertial-force ramp time",
    "outswitch": "MoorDyn-F's output switch", "echo": "MoorDyn v1's echo flag"}


@dataclass
class Options:
    """What a scene takes from the OPTIONS: each value [SI] with the deck line it came from
    (0: MoorDyn-C's default), ``depth`` None when WtrDpth is not given; the notes."""

    g: float
    g_line: int
    rho: float
    rho_line: int
    depth: float | None
    depth_line: int
    kbot: float
    kbot_line: int
    cbot: float
    cbot_line: int
    friction: float
    currents: int
    currents_line: int
    notes: list[str] = field(default_factory=list)
    wavekin: int = 0
    wavekin_line: int = 0
    wave_ramp: float | None = None
    wave_ramp_line: int = 0

    def given(self, what: str) -> str:
        """'(deck line N)' or "(MoorDyn-C's default)" for g, rho, kbot, cbot."""
        line = getattr(self, f"{what}_line")
        return f"(deck line {line})" if line else "(MoorDyn-C's default)"


def _value(deck: Deck, key: str) -> tuple[float, int]:
    """(numeric value, line) of an option as MoorDyn-C reads it, or (default, 0)."""
    got = deck.option_entry(key)
    if got is None:
        return DEFAULTS[key], 0
    value, no, name = got
    if is_comma_number(value):
        raise DeckError(deck.source, no, comma_message(f"option {name}", value))
    if not is_number(value):
        raise DeckError(deck.source, no, f"option {name}: {value!r} is not a number")
    v = float(value)
    if not math.isfinite(v):
        raise DeckError(deck.source, no, f"option {name}: must be finite, got {value}")
    return v, no


def read_options(deck: Deck) -> Options:
    """The options of ``deck`` as MoorDyn-C 2.7 reads them; refuse what a scene cannot
    hold, naming the deck line."""
    src = deck.source
    notes: list[str] = []
    got = deck.option_entry("WaveKin")
    seven = got is not None and is_number(got[0]) and float(got[0]) == 7.0
    _check_rows(deck, notes, carried=("waveKin_rampT",) if seven else ())
    wavekin, wavekin_line = _value(deck, "WaveKin")
    if wavekin not in (0.0, 7.0):
        raise DeckError(src, wavekin_line, f"option WaveKin = {wavekin:g}: waves other than "
                        "MoorDyn-C's summed components (WaveKin 7, wave_frequencies.txt) "
                        "cannot be imported: a scene's waves are Airy components, not "
                        "kinematics given through the API (1) or on a grid (2, 3)")
    ramp, ramp_line = None, 0
    if wavekin and deck.option_entry("waveKin_rampT") is not None:
        ramp, ramp_line = _value(deck, "waveKin_rampT")
        if ramp < 0.0:
            raise DeckError(src, ramp_line, f"option waveKin_rampT = {ramp:g}: must be >= 0 "
                            "s")
    sea = deck.option_entry("SeafloorFile")
    if sea is not None:
        raise DeckError(src, sea[1], f"option SeafloorFile ({sea[0]}): a seafloor file "
                        "(bathymetry) cannot be imported: a scene's seabed is flat")
    g, g_line = _value(deck, "g")
    rho, rho_line = _value(deck, "rho")
    depth, depth_line = _value(deck, "WtrDpth")
    kbot, kbot_line = _value(deck, "kBot")
    cbot, cbot_line = _value(deck, "cBot")
    friction, _ = _value(deck, "FrictionCoefficient")
    currents, currents_line = _value(deck, "Currents")
    if friction:
        scale, no = _value(deck, "StatDynFricScale")
        if scale != 1.0:
            raise DeckError(src, no, f"option StatDynFricScale = {scale:g}: a static friction "
                            "other than the dynamic one cannot be imported: a scene's seabed "
                            "friction is one Coulomb coefficient")
        damp, no = _value(deck, "FricDamp")
        notes.append(f"Seabed friction {friction:g}: MoorDyn ramps it in over a sliding speed "
                     f"of 1/FricDamp = {1.0 / damp if damp else float('inf'):g} m/s "
                     f"({'deck line ' + str(no) if no else 'the default FricDamp 200'}), the "
                     "VFIFE over 0.01 m/s; the BVP has no friction.")
    elif any(deck.option_entry(k) for k in ("FricDamp", "StatDynFricScale")):
        notes.append("FricDamp and StatDynFricScale have no effect without friction "
                     "(FrictionCoefficient 0).")
    rho_names = "rho, Rho or WtrDnsty"
    notes.append(f"Water density {rho:g} kg/m3 " + (
        f"from option {deck.option_entry('rho')[2]} (deck line {rho_line})." if rho_line else
        f"(MoorDyn-C's default, {SOURCE}: the deck gives none of {rho_names})."))
    notes.append(f"Gravity {g:g} m/s2 " + (
        f"from option {deck.option_entry('g')[2]} (deck line {g_line})." if g_line else
        f"(MoorDyn-C's default, {SOURCE}: the deck gives neither g nor gravity)."))
    return Options(g, g_line, rho, rho_line, depth if depth_line else None, depth_line,
                   kbot, kbot_line, cbot, cbot_line, friction, int(currents), currents_line,
                   notes, int(wavekin), wavekin_line, ramp, ramp_line)


def _check_rows(deck: Deck, notes: list[str], carried: tuple[str, ...] = ()) -> None:
    """Notes on the rows as MoorDyn-C reads them: rows without a name, repeated options,
    names it does not read, options read and not carried (but those ``carried``, with
    waves); a comma number is refused."""
    src = deck.source
    seen: dict[str, list[int]] = {}
    ignored: list[str] = []
    for name, value, no in deck.option_rows:
        if not name:
            notes.append(f"Deck line {no} ({value!r}) has no option name: MoorDyn-C skips "
                         "it, and so does this import.")
            continue
        k = name.lower()
        canon = CANONICAL.get(k)
        if canon is None:
            what = NOT_READ.get(k)
            near = None if what else difflib.get_close_matches(k, list(PHYSICS), 1, 0.75)
            if near:
                raise DeckError(src, no, f"option {name!r} is not one MoorDyn-C 2.7 reads "
                                "(it warns 'Unrecognized option' and goes on without it), "
                                f"and it looks like a misspelt {PHYSICS[near[0]]}, which "
                                "changes the physics: write the option's name as MoorDyn "
                                "reads it")
            notes.append(f"Option {name} = {value} (deck line {no})"
                         + (f", {what}," if what else "") + " is not one MoorDyn-C 2.7 reads "
                         "(it warns 'Unrecognized option' and goes on): skipped here too.")
            continue
        if k not in TEXT_OPTIONS and is_comma_number(value):
            raise DeckError(src, no, comma_message(f"option {name}", value))
        seen.setdefault(canon, []).append(no)
        if canon in NUMERICS and canon not in carried:
            ignored.append(f"{name} (line {no})")
    for canon, lines in seen.items():
        if len(lines) > 1:
            value, no, name = deck.option_entry(canon)
            notes.append(f"Option {canon} is given {len(lines)} times (deck lines "
                         f"{', '.join(map(str, lines))}): MoorDyn-C takes the last, "
                         f"{name} = {value} (line {no}).")
    if ignored:
        notes.append("Read and not carried (MoorDyn's time stepping, initial-condition "
                     "solver and output; the scene's methods have their own): "
                     + ", ".join(ignored) + ".")

"""Waves in a MoorDyn deck: MoorDyn-C's ``WaveKin 7`` (summed wave components) and its
``wave_frequencies.txt``, read into a scene's ``[environment.waves]`` trains and written
from a scene's components (:meth:`riser.physics.waves.Waves.components`, the same realisation).

MoorDyn-C 2.7's conventions (its source, ``source/Waves.cpp`` ``Waves::setup``,
``source/Waves/WaveSpectrum.cpp`` ``spectrumFromFile``, ``source/Waves/SpectrumKin.cpp``;
each measured on moordyn 2.7.2 with ``GetWavesKin``, tests/test_moordyn_waves.py):

- the file is ``wave_frequencies.txt`` in the deck's folder, read line by line: every line
  is a component ``omega Re Im [beta]`` (omega [rad/s], the complex amplitude A [m], the
  direction of travel beta [rad] from +X towards +Y, 0 when not given; a line of 5 or more
  columns has its 4th column ignored, beta = 0). No comment and no empty line (MoorDyn-C
  stops on them: "should have 3 or 4 columns"); at least two lines; the first at 0 rad/s
  ("The first shall be 0 rad/s"); |beta| <= 2 pi. Numbers are C++ ``stod``: a prefix is
  read (``1,5`` is 1), so a number with a comma is refused here as in the deck;
- the sea: eta = sum |A| sin(omega t - k (X cos beta + Y sin beta) + arg A), the phase
  referred to X = Y = 0, k of the finite-depth dispersion omega^2 = g k tanh(k WtrDpth)
  (measured: within 4e-8 of the exact root, exact in deep water); each component as given
  (no interpolation, any order, repeated frequencies allowed);
- kinematics: linear (Airy) theory with Wheeler stretching, z in [-h, eta] mapped onto
  [-h, 0] with the total elevation eta; above the surface the surface's values (the
  stretched height held at 0: measured on 2.7.2; later sources return zero there); the
  acceleration is the local one at the stretched height;
- t is MoorDyn's own clock (0 at Init, advanced by each Step's dt; the t given to Step is
  not used); ``waveKin_rampT`` ramps the water velocity and acceleration *linearly* from 0
  over that time, the current's with the waves (measured: 1.04 % of the drag at a tenth of
  the ramp, (1/10)^2), not what ``GetWavesKin`` reports.

The scene's convention (:mod:`riser.physics.waves`): eta = a cos(omega t - k d - eps), d = (x - x0)
cos b + (z - z0) sin b, eps the phase lag at the origin (x0, z0). With the deck's frame of
:mod:`riser.io.moordyn.scene_from_deck` (x along the ends' horizontal direction e_x from
the bottom end B, z along e_z = (e_x,Y, -e_x,X)): a = |A|, eps = 90 deg - arg A, the
heading b = atan2(d . e_z, d . e_x) with d = (cos beta, sin beta), and the origin is
MoorDyn's X = Y = 0, at x0 = -B . e_x, z0 = -B . e_z. Written (the export's frame X = x,
Y = -z): beta = -b and arg A = 90 deg - eps + k (x0 cos b + z0 sin b), the phase carried
from the scene's origin to MoorDyn's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from ..angles import wrap_deg
from .deck import Deck, read_text
from .tokens import DeckError, comma_message, is_comma_number, is_number

#: the component file MoorDyn-C's WaveKin 7 reads from the deck's folder
WAVE_FILE = "wave_frequencies.txt"
#: MoorDyn-C 2.7's direction limit [rad] (|beta| <= 2 pi)
BETA_LIMIT = 2.0 * math.pi
WHAT = "a MoorDyn wave-frequencies file"


@dataclass(frozen=True)
class Component:
    """One row of wave_frequencies.txt: omega [rad/s], the complex amplitude [m], beta
    [rad] (MoorDyn's direction, as MoorDyn-C takes it), and its line number."""

    omega: float
    amplitude: complex
    beta: float
    line: int


def read_components(path: Path, deck: Deck, wavekin_line: int,
                    notes: list[str]) -> tuple[list[Component], str]:
    """The rows of ``path`` as MoorDyn-C 2.7 reads them, and the file's name as messages
    print it; :class:`DeckError` naming the file and line (a missing file names the
    deck's WaveKin line) for what MoorDyn-C refuses and for negative or unsorted
    frequencies."""
    if not path.exists():
        raise DeckError(deck.source, wavekin_line, f"WaveKin = 7 needs {WAVE_FILE} beside "
                        "the deck (No such file or directory)")
    text, where = read_text(path, WHAT)
    rows: list[Component] = []
    ignored: list[int] = []
    for no, raw in enumerate(text.splitlines(), start=1):
        tok = raw.split()
        if len(tok) < 3 or tok[0][0] in "#!%":
            what = ("an empty line" if not tok else "a comment" if tok[0][0] in "#!%"
                    else f"{len(tok)} column(s)")
            raise DeckError(where, no, f"{what}: MoorDyn-C 2.7 reads every line of "
                            f"{WAVE_FILE} as a component 'omega Re Im [beta]' (3 or 4 "
                            "numbers; no comments, no empty lines) and stops here")
        vals = []                      # MoorDyn-C reads beta only from a 4-column line
        for name, t in zip(("omega", "Re", "Im", "beta"), tok if len(tok) == 4 else tok[:3]):
            if is_comma_number(t):
                raise DeckError(where, no, comma_message(name, t))
            if not is_number(t):
                raise DeckError(where, no, f"{name}: {t!r} is not a number")
            v = float(t)
            if not math.isfinite(v):
                raise DeckError(where, no, f"{name}: must be finite, got {t}")
            vals.append(v)
        omega, re_, im_ = vals[:3]
        beta = vals[3] if len(vals) == 4 else 0.0
        if len(tok) > 4:
            ignored.append(no)
        if abs(beta) > BETA_LIMIT:
            raise DeckError(where, no, f"beta = {beta:g} rad: MoorDyn-C refuses a direction "
                            "beyond +-2 pi (radians)")
        if omega < 0.0:
            raise DeckError(where, no, f"omega = {omega:g} rad/s: a frequency must be >= 0")
        if rows and omega < rows[-1].omega:
            raise DeckError(where, no, f"omega = {omega:g} rad/s after {rows[-1].omega:g} "
                            f"(line {rows[-1].line}): the frequencies must be in increasing "
                            "order (as MoorDyn-C's WaveKin 2 requires of the same file)")
        rows.append(Component(omega, complex(re_, im_), beta, no))
    if len(rows) < 2:
        raise DeckError(where, len(rows), f"MoorDyn-C needs at least two lines in {WAVE_FILE}"
                        " (the first at 0 rad/s)")
    if rows[0].omega != 0.0:
        raise DeckError(where, rows[0].line, f"omega = {rows[0].omega:g} rad/s: the first "
                        "line must be at 0 rad/s (MoorDyn-C: 'The first shall be 0 rad/s')")
    for r in rows:
        if r.omega == 0.0 and r.amplitude != 0.0:
            raise DeckError(where, r.line, "a component at 0 rad/s with an amplitude other "
                            "than 0 is a steady offset of the mean level; a scene's mean "
                            "surface is at water_depth")
    if ignored:
        notes.append(f"{WAVE_FILE}: line(s) {', '.join(map(str, ignored))} have more than 4 "
                     "columns: MoorDyn-C 2.7 reads a direction only from a line of exactly 4, "
                     "so those components travel along +X (beta = 0), as imported.")
    return rows, where


def waves_table(rows: list[Component], where: str, bottom: tuple[float, float],
                ex: tuple[float, float], ramp: float | None, ramp_line: int,
                has_current: bool, notes: list[str], keys: dict) -> dict:
    """The scene's ``[environment.waves]`` of the components (see the module docstring),
    one train per component of amplitude > 0; ``keys`` gets each train's key -> (file,
    line) for errors. ``bottom``: MoorDyn (X, Y) of the bottom end, ``ex`` the ends'
    horizontal direction; ``ramp``: waveKin_rampT [s] (None: not given)."""
    ez = (ex[1], -ex[0])
    x0 = -(bottom[0] * ex[0] + bottom[1] * ex[1])
    z0 = -(bottom[0] * ez[0] + bottom[1] * ez[1])
    trains = []
    for r in rows:
        a = abs(r.amplitude)
        if a == 0.0:
            continue
        d = (math.cos(r.beta), math.sin(r.beta))
        heading = math.degrees(math.atan2(d[0] * ez[0] + d[1] * ez[1],
                                          d[0] * ex[0] + d[1] * ex[1]))
        lag = wrap_deg(90.0 - math.degrees(math.atan2(r.amplitude.imag, r.amplitude.real)))
        keys[f"environment.waves.trains[{len(trains)}]"] = (where, r.line)
        trains.append({"height": 2.0 * a, "period": 2.0 * math.pi / r.omega,
                       "heading_deg": wrap_deg(heading), "phase_deg": lag})
    if not trains:
        raise DeckError(where, 0, "holds no component with an amplitude (every Re and Im "
                        "is 0): give the waves, or WaveKin 0")
    skipped = len(rows) - len(trains)
    notes.append(
        f"Waves from {Path(where).name} (WaveKin 7): {len(trains)} component(s) -> "
        "[[environment.waves.trains]], height 2|A|, period 2 pi / omega, heading MoorDyn's "
        "direction beta turned into the scene's frame, phase lag 90 deg - arg A (MoorDyn-C "
        "sums |A| sin(omega t - k (X cos beta + Y sin beta) + arg A), the scene a cos(omega t "
        f"- k d - phase)), referred to MoorDyn's X = Y = 0, the scene's origin ({x0:.6g}, "
        f"{z0:.6g}); {skipped} line(s) of zero amplitude skipped (the first, at 0 rad/s, "
        "MoorDyn-C requires). Stretching 'wheeler': MoorDyn-C stretches its kinematics to "
        "the instantaneous surface (and continues the surface's values above it).")
    table = {"trains": trains, "origin": [x0 + 0.0, z0 + 0.0], "stretching": "wheeler"}
    if ramp is None or ramp == 0.0:
        table["ramp_time"] = 0.0
        notes.append("waveKin_rampT not given (MoorDyn-C's default 0): the waves start at "
                     "full height at t = 0, and so does the scene's (ramp_time 0).")
    else:
        table["ramp_time"] = ramp
        notes.append(f"waveKin_rampT = {ramp:g} s (deck line {ramp_line}) -> ramp_time: "
                     "MoorDyn-C ramps the water kinematics linearly over it, the scene by a "
                     "half cosine" + (", and MoorDyn ramps the current with them, which the "
                     "scene holds steady" if has_current else "") + ".")
    return table


def wave_file_text(scene) -> tuple[str, list[str]]:
    """``wave_frequencies.txt`` of a fixed-ends ``scene`` with waves (its components, the
    spectrum's included, in the export's frame X = x, Y = -z), and the notes on what
    MoorDyn-C's WaveKin 7 does not represent as the scene does."""
    waves = scene.waves
    hang = scene.ends.hang_off_point
    comp = waves.components(scene.water_depth, scene.gravity, (hang[0], hang[2]))
    x0, z0 = comp.origin
    rows = []
    for a, w, k, eps, b in zip(comp.amplitude, comp.omega, comp.k, comp.phase, comp.heading):
        d0 = x0 * math.cos(b) + z0 * math.sin(b)
        phi = 0.5 * math.pi - eps + k * d0
        phi = math.remainder(phi, 2.0 * math.pi)
        beta = math.remainder(-b, 2.0 * math.pi) + 0.0
        rows.append((float(w), a * math.cos(phi), a * math.sin(phi), beta))
    rows.sort(key=lambda r: r[0])
    lines = ["0.0 0.0 0.0 0.0"] + [" ".join(repr(float(v)) for v in r) for r in rows]
    notes = [f"Waves: WaveKin 7, {len(rows)} component(s) in {WAVE_FILE} (omega [rad/s], "
             "Re A, Im A [m], beta [rad]; the first line at 0 rad/s as MoorDyn-C requires): "
             "the scene's components (a spectrum's as its seed draws them), A = a e^(i "
             "(90 deg - phase + k d0)), beta = -heading (Y = -z), the phase carried from the "
             f"scene's wave origin ({x0:.6g}, {z0:.6g}) to MoorDyn's X = Y = 0 (d0 its "
             "distance along the heading). MoorDyn-C's k is the finite-depth root to 4e-8."]
    if waves.stretching != "wheeler":
        notes.append(f"The scene's stretching '{waves.stretching}' is not represented: "
                     "MoorDyn-C's WaveKin 7 stretches by Wheeler (the kinematics above the "
                     "mean level differ; below the troughs they are the same).")
    if len(set(map(float, comp.heading))) > 1:
        notes.append("Several headings: each component carries its own beta (MoorDyn-C "
                     "sums them; a short-crested sea is the sum of its components).")
    sp = waves.spectrum
    if sp is not None and sp.spread:
        notes.append(f"The spectrum is short-crested ({sp.spreading}, exponent "
                     f"{sp.spreading_exponent:g}, about {sp.heading_deg:g} deg): its "
                     "components travel at the directions its seed draws "
                     "(riser.physics.waves), each row its own beta; MoorDyn-C's "
                     "SpectrumKin sums them with a direction per component, the same sea.")
    return "\n".join(lines) + "\n", notes

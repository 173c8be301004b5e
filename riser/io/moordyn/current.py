"""MoorDyn's steady current profile (``Currents 1``, current_profile.txt beside the deck)
-> a scene's ``[environment.current]`` (:func:`read_current`, for
:mod:`riser.io.moordyn.scene_from_deck`; the writing is
:func:`riser.io.moordyn.deck_from_scene._current_profile`).

Rows ``z ux uy uz`` after three header lines, uz = 0; (ux, uy) turned into the scene's
frame (x along the ends' horizontal direction ``ex``, z = x cross y) at the height y = z +
WtrDpth: one direction at every depth gives ``heading_deg`` and speeds signed along it; a
profile that turns with depth ``headings_deg`` (one per row) and the magnitudes.
"""

from __future__ import annotations

import math
from pathlib import Path

from .deck import Deck, read_text
from .options import Options
from .tokens import DeckError, comma_message, is_comma_number


def read_current(deck: Deck, opts: Options, path: Path, ex, depth: float,
             notes: list[str]) -> dict | None:
    """The scene's [environment.current] from MoorDyn's steady current profile."""
    mode = opts.currents
    if mode == 0:
        return None
    if mode != 1:
        raise DeckError(deck.source, opts.currents_line, f"option Currents = {mode:g}: only 1 "
                        "(a steady profile, current_profile.txt) can be imported; a scene's "
                        "current is steady and depth-dependent")
    if not path.exists():
        raise DeckError(deck.source, opts.currents_line, f"Currents = 1 needs "
                        f"{path.name} beside the deck (No such file or directory)")
    text, where = read_text(path, "a MoorDyn current profile")
    rows = text.splitlines()
    ez = (ex[1], -ex[0])
    table = []
    for no, raw in enumerate(rows[3:], start=4):
        tok = raw.split("!")[0].split()
        if not tok:
            continue
        if len(tok) < 2:
            raise DeckError(where, no, "a row is 'z ux [uy [uz]]' [m, m/s]")
        for c, t in zip(("z", "ux", "uy", "uz"), tok):
            if is_comma_number(t):
                raise DeckError(where, no, comma_message(c, t))
        try:
            z, ux, uy, uz = (float(t) for t in (tok + ["0", "0"])[:4])
        except ValueError:
            raise DeckError(where, no, f"{raw.strip()!r}: not numbers (z ux uy uz)") from None
        if not all(map(math.isfinite, (z, ux, uy, uz))):
            raise DeckError(where, no, "values must be finite")
        if uz:
            raise DeckError(where, no, f"uz = {uz:g}: a vertical current cannot be imported")
        table.append((z + depth, ux * ex[0] + uy * ex[1], ux * ez[0] + uy * ez[1], no))
    if not table:
        raise DeckError(where, 0, "holds no current rows (after its three header lines)")
    table.sort()
    for a, b in zip(table, table[1:]):
        if b[0] == a[0]:
            raise DeckError(where, b[3], f"depth {b[0] - depth:g} m given twice")
    below = [r for r in table if r[0] < 0.0]
    if below:       # rows below the seabed: the profile's value at the seabed instead
        above = [r for r in table if r[0] >= 0.0]
        a, b = below[-1], (above[0] if above else below[-1])
        f = 0.0 if b[0] == a[0] else -a[0] / (b[0] - a[0])
        seabed = (0.0, a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]), a[3])
        table = ([] if above and above[0][0] == 0.0 else [seabed]) + above
        notes.append(f"{path.name}: {len(below)} row(s) below the seabed (Z < -WtrDpth) "
                     "replaced by the profile's value at the seabed (no node lies below).")
    ref = max(table, key=lambda r: math.hypot(r[1], r[2]))
    umax = math.hypot(ref[1], ref[2])
    if umax == 0.0:
        return None
    dx, dz = ref[1] / umax, ref[2] / umax
    if any(abs(ux * dz - uz * dx) > 1e-9 * umax for _, ux, uz, _ in table):
        return _turning(table, path, notes)
    heading = math.degrees(math.atan2(dz, dx))
    notes.append(f"Current from {path.name}: heading {heading:.6g} deg from the scene's x "
                 "towards its z.")
    return {"heights": [r[0] for r in table], "speeds": [r[1] * dx + r[2] * dz for r in table],
            "heading_deg": heading}


def _turning(table: list[tuple], path: Path, notes: list[str]) -> dict:
    """A profile that turns with depth: ``headings_deg``, the heading of each row's
    (ux, uz) from the scene's x towards its z, and its speed, the magnitude (a row without
    current takes the heading of the nearest row with one, below it first: its
    components stay 0, and no turn is invented)."""
    speeds = [math.hypot(ux, uz) for _, ux, uz, _ in table]
    headings = [math.degrees(math.atan2(uz, ux)) if v else None
                for (_, ux, uz, _), v in zip(table, speeds)]
    for i, h in enumerate(headings):
        if h is None:
            near = sorted((k for k, hk in enumerate(headings) if hk is not None),
                          key=lambda k: (abs(k - i), k > i))
            headings[i] = headings[near[0]]
    notes.append(f"Current from {path.name}: it turns with depth, headings "
                 f"{min(headings):.6g} to {max(headings):.6g} deg (from the scene's x "
                 "towards its z): headings_deg, one per height, the velocity interpolated "
                 "component by component as MoorDyn does.")
    return {"heights": [r[0] for r in table], "speeds": speeds, "headings_deg": headings}

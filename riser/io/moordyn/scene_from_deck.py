"""A MoorDyn v2 deck -> a scene (``riser-verify import-moordyn``).

What a scene holds: one line from a bottom end to a hang-off, both fixed, made of
segments. So the deck must describe one chain of lines joined end to end by free points
(MoorDyn's joints, which are hinges: see docs/moordyn.md), between two fixed or coupled points
at their deck positions. Everything else is refused before anything is written, one line
naming the deck line: bodies, rods, failures, external loads, waves other than summed
components (WaveKin 7: :mod:`riser.io.moordyn.waves`), a seafloor file, a
third fixed end, a point with a mass, a volume or drag (a clump weight or a float), a
coupled point with no position, a branch or a loop, a line type that a used line cannot
have (no bending stiffness, a nonlinear EA), a number written with a comma.

Mapping (MoorDyn -> scene; MoorDyn's Z is up from the still surface, the scene's y up from
the seabed, so y = Z + WtrDpth):

- the vertical plane through the two ends becomes the x-y plane, x from the bottom end
  towards the hang-off; the scene's z is x cross y (MoorDyn's -Y for an end pair along +X);
- a line type: outer_diameter = Diam (MoorDyn's volume-equivalent diameter),
  mass_per_length = Mass/m, axial_stiffness = EA, bending_stiffness = EI, drag_normal =
  Cd (on d l), drag_tangential = CdAx (on pi d l, the scene's convention too), added_mass =
  Ca; CaAx and the VIV lift Cl have no scene key and are dropped with a note;
- the seabed: MoorDyn's contact force per metre is kBot d times the penetration, so the
  scene's stiffness [N/m2] is kBot x Diam of the bottom line; cBot becomes the damping as
  a fraction of critical, cBot d / (2 sqrt(k (m + m_a))) (the VFIFE definition); the
  friction is FrictionCoefficient;
- a steady current (``Currents 1``) is read from current_profile.txt beside the deck
  (MoorDyn's convention): rows ``z ux uy uz`` with uz = 0, the horizontal velocity
  (ux, uy) turned into the scene's frame (x along the ends' horizontal direction, z =
  x cross y): one direction at every depth gives ``heading_deg`` and speeds signed along
  it; a profile that turns with depth gives ``headings_deg`` (one per row) and the
  speeds (magnitudes). Points and current are turned alike, so a deck turned about Z
  imports to the same scene;
- the options as MoorDyn-C 2.7 reads them (:mod:`riser.io.moordyn.options`): its defaults
  g = 9.80665 m/s2 and a density of 1025 kg/m3 when the deck gives none, the water depth
  lowered to the deepest point as MoorDyn-C lowers it. Where each value came from is
  written as a comment in the scene file.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from ...errors import SceneError
from ...scene import Scene
from ..scene_file import scene_from_dict
from ..toml_text import dumps
from .deck import Deck, DeckPoint, read_deck, read_text
from .options import Options, read_options
from .tokens import DeckError, comma_message, is_comma_number
from .waves import WAVE_FILE, read_components, waves_table


def import_deck(path: str | Path, name: str | None = None) -> tuple[str, Scene, list[str]]:
    """Read the deck at ``path``: (the scene's TOML text, the validated scene, the notes
    that were written into it as comments). The scene's name is ``name`` or the deck's
    file name, made a valid scene name (lower case, digits, dashes), whatever file the
    scene is written to. Raise :class:`DeckError` naming the deck line."""
    path = Path(path)
    deck = read_deck(path)
    name = _scene_name(name or path.stem)
    data, notes, where, env_comments = scene_dict(deck, name,
                                                  path.parent / "current_profile.txt",
                                                  path.parent / WAVE_FILE)
    header = [f"Imported from the MoorDyn deck {path.name} by riser-verify import-moordyn.",
              *notes]
    text = dumps(data, header=[_printable(h) for h in header],
                 comments={"environment": [_printable(c) for c in env_comments]})
    try:
        scene = scene_from_dict(data, f"{path.name} (imported)")
    except SceneError as exc:   # a value outside a scene's range: name the deck line (or
        hits = [p for p in where if exc.key == p or exc.key.startswith((f"{p}.", f"{p}["))]
        got = where[max(hits, key=len)] if hits else 0      # the wave file's), the longest
        src, line = got if isinstance(got, tuple) else (str(path), got)     # key matching
        raise DeckError(src, line, f"{exc.key}: {exc.message}") from None
    return text, scene, notes


def _printable(text: str) -> str:
    """A comment line: a character TOML does not allow in a comment written as \\xNN."""
    return "".join(c if c.isprintable() else f"\\x{ord(c):02x}" for c in text)


def _scene_name(stem: str) -> str:
    s = re.sub(r"[^a-z0-9-]+", "-", stem.lower()).strip("-")
    return s if s and s[0].isalnum() else "moordyn-deck"


def _refuse_sections(deck: Deck) -> None:
    why = {"bodies": "a body (a 6-DOF rigid body) is not part of a riser scene",
           "rods": "a rod (a rigid or pinned cylinder) is not part of a riser scene",
           "failure": "line failures are not modelled",
           "external_loads": "external loads on points, rods or bodies are not modelled"}
    for sec, no in sorted(deck.other.items(), key=lambda kv: kv[1]):
        if sec in why:
            raise DeckError(deck.source, no, f"{sec.replace('_', ' ').upper()}: {why[sec]}; "
                            "a scene holds one line of segments between two fixed ends")


_POINT_REF = re.compile(r"(?i)(?:p|point|c|con)?(\d+)")
_ROD_END = re.compile(r"(?i)r(?:od)?\d+[ab]")


def _chain(deck: Deck) -> tuple[list[tuple[int, bool]], DeckPoint, DeckPoint]:
    """The lines in order from the bottom end, each (index, reversed), and the two ends."""
    src = deck.source
    if not deck.lines:
        raise DeckError(src, 0, "has no lines (the LINES table is empty)")
    npt = len(deck.points)
    ends: dict[int, list[tuple[int, str]]] = {}
    for i, ln in enumerate(deck.lines):
        if ln.line_type not in deck.line_types and ln.line_type not in deck.line_type_errors:
            raise DeckError(src, ln.line, f"line {ln.id}: unknown line type {ln.line_type!r}"
                            f" (defined: {', '.join(deck.line_types) or 'none'})")
        for end, att in (("A", ln.attach_a), ("B", ln.attach_b)):
            ref = _POINT_REF.fullmatch(att)
            if ref is None:
                what = "a rod end, R#A/R#B," if _ROD_END.fullmatch(att) else "not a point"
                raise DeckError(src, ln.line, f"line {ln.id}: Attach{end} {att!r} is {what} "
                                "and cannot be imported (a point ID, as 3 or P3)")
            pid = int(ref.group(1))
            if not 1 <= pid <= npt:
                raise DeckError(src, ln.line, f"line {ln.id}: Attach{end} = {pid}: no such "
                                f"point (IDs 1..{npt})")
            ends.setdefault(pid, []).append((i, end))
    fixed = []
    for p in deck.points:
        att = ends.get(p.id, [])
        if p.kind == "other":
            raise DeckError(src, p.line, f"point {p.id}: attachment {p.attachment!r} (a body "
                            "or rod) cannot be imported; use Fixed, Coupled or Free")
        if p.kind in ("fixed", "coupled"):
            if None in (p.x, p.y, p.z):
                raise DeckError(src, p.line, f"point {p.id} ({p.attachment}) has no position "
                                "(X Y Z must be numbers): a scene's ends are fixed positions")
            if att:
                fixed.append(p)
                if len(fixed) > 2:
                    raise DeckError(src, p.line, f"point {p.id} is a third fixed or coupled "
                                    "end; a scene has two (the anchor and the hang-off)")
            if len(att) > 1:
                raise DeckError(src, p.line, f"point {p.id} ({p.attachment}) holds "
                                f"{len(att)} lines; a scene's ends each hold one")
        elif att:
            if p.mass or p.volume or p.CdA or p.Ca:
                raise DeckError(src, p.line, f"point {p.id}: a free point with mass, volume, "
                                "CdA or Ca (a clump weight or a float) cannot be imported: "
                                "a scene's joints carry no point loads")
            if any(p.force):
                raise DeckError(src, p.line, f"point {p.id}: a free point with a steady force "
                                "FX FY FZ (a point load) cannot be imported: a scene's "
                                "joints carry no point loads")
            if len(att) != 2:
                raise DeckError(src, p.line, f"point {p.id} (free) joins {len(att)} line "
                                "end(s); a scene is one chain: a free point joins exactly two")
    if len(fixed) < 2:
        raise DeckError(src, 0, f"has {len(fixed)} fixed or coupled line end(s); a scene "
                        "needs two (the anchor and the hang-off)")
    bottom, top = sorted(fixed, key=lambda p: (p.z, p.id))
    order: list[tuple[int, bool]] = []
    pid, used = bottom.id, set()
    while pid != top.id:
        nxt = [(i, e) for i, e in ends[pid] if i not in used]
        if not nxt:
            break
        i, end = nxt[0]
        used.add(i)
        ln = deck.lines[i]
        order.append((i, end == "B"))
        pid = int(_POINT_REF.fullmatch(ln.attach_b if end == "A" else ln.attach_a).group(1))
    if pid != top.id or len(used) != len(deck.lines):
        stray = next(ln for k, ln in enumerate(deck.lines) if k not in used)
        raise DeckError(src, stray.line, f"line {stray.id} is not on the chain from point "
                        f"{bottom.id} to point {top.id}; a scene is one line of segments")
    return order, bottom, top


def _depth(deck: Deck, opts: Options, notes: list[str]) -> tuple[float, int, str]:
    """The water depth as MoorDyn-C 2.7 takes it: WtrDpth (default 0), lowered to the
    deepest point; (depth, its deck line, where it came from)."""
    given = opts.depth
    depth, line = (given, opts.depth_line) if given is not None else (0.0, 0)
    origin = f"option WtrDpth (deck line {line})" if given is not None else ""
    deep = min((p for p in deck.points if p.z is not None), key=lambda p: (p.z, p.id),
               default=None)
    if deep is not None and deep.z < -depth:
        was = (f"WtrDpth = {given:g} m (deck line {line}) is above point {deep.id} (Z = "
               f"{deep.z:g} m, deck line {deep.line})" if given is not None else
               f"The deck gives no WtrDpth (MoorDyn-C's default 0 m); its deepest point is "
               f"point {deep.id} (Z = {deep.z:g} m, deck line {deep.line})")
        depth, line = -deep.z, deep.line
        origin = (f"the depth of point {deep.id} (deck line {deep.line}), to which MoorDyn-C "
                  "lowers its seabed")
        notes.append(f"{was}: MoorDyn-C lowers its seabed to that point ('Water depth set to "
                     f"point {deep.id} z position'), and so does this import: water depth "
                     f"{depth:g} m.")
    if depth <= 0.0:
        raise DeckError(deck.source, line, "the water depth must be > 0 m: give WtrDpth [m] "
                        "(the seabed is at Z = -WtrDpth; without it MoorDyn-C takes the "
                        "depth of the deepest point)")
    return depth, line, origin


def scene_dict(deck: Deck, name: str, current_file: Path | None,
               wave_file: Path | None = None) -> tuple[dict, list[str], dict, list[str]]:
    """The scene structure of a deck, the notes, key prefix -> deck line (or (file, line)
    of the wave file, for errors), and the comment lines of its [environment] (where g,
    the density and the depth came from)."""
    _refuse_sections(deck)
    opts = read_options(deck)
    notes = [*deck.notes, *opts.notes]
    order, bottom, top = _chain(deck)
    used_types = list(dict.fromkeys(deck.lines[i].line_type for i, _ in order))
    for tname in used_types:                 # a type no line uses may hold anything
        if tname in deck.line_type_errors:
            raise deck.line_type_errors[tname]
    depth, depth_line, depth_from = _depth(deck, opts, notes)
    where: dict[str, int] = {"environment.water_depth": depth_line}
    dx, dy = top.x - bottom.x, top.y - bottom.y
    span = math.hypot(dx, dy)
    if span < 1e-9:
        raise DeckError(deck.source, top.line, f"points {bottom.id} and {top.id} are "
                        "vertically aligned: a scene's hang-off lies at a larger x than its "
                        "anchor")
    ex = (dx / span, dy / span)
    ya, yh = bottom.z + depth, top.z + depth
    if yh > depth + 1e-9:
        raise DeckError(deck.source, top.line, f"point {top.id} is above the still water "
                        f"surface (Z = {top.z:g} > 0); the scene's line is submerged")
    where["ends"] = top.line
    where.update({"environment.gravity": opts.g_line,
                  "environment.water_density": opts.rho_line})
    data: dict = {"name": name,
                  "title": _title(deck, name),
                  "source": f"MoorDyn v2 deck {Path(deck.source).name}",
                  "environment": {"gravity": opts.g, "water_density": opts.rho,
                                  "water_depth": depth}}
    current = _current(deck, opts, current_file, ex, depth, notes) if current_file else None
    if current:
        data["environment"]["current"] = current
        where["environment.current"] = opts.currents_line
    if opts.wavekin == 7:           # waves (riser.io.moordyn.waves); the origin: MoorDyn's 0
        rows, wfile = read_components(wave_file or Path(deck.source).parent / WAVE_FILE,
                                      deck, opts.wavekin_line, notes)
        where["environment.waves"] = opts.wavekin_line
        data["environment"]["waves"] = waves_table(
            rows, wfile, (bottom.x, bottom.y), ex, opts.wave_ramp, opts.wave_ramp_line,
            bool(current), notes, where)
    data["line_types"] = {}
    for tname in used_types:
        lt = deck.line_types[tname]
        data["line_types"][tname] = {
            "outer_diameter": lt.diameter, "mass_per_length": lt.mass,
            "axial_stiffness": lt.EA, "bending_stiffness": lt.EI, "drag_normal": lt.Cd,
            "drag_tangential": lt.CdAx, "added_mass": lt.Ca}
        where[f"line_types.{tname}"] = lt.line
        if lt.CaAx:
            notes.append(f"line type {tname}: CaAx = {lt.CaAx:g} dropped (the scene has no "
                         "axial added mass; it affects dynamics only)")
        if lt.Cl:
            notes.append(f"line type {tname}: VIV lift Cl = {lt.Cl:g} dropped (not modelled)")
        if lt.BA not in ("0", "0.0"):
            notes.append(f"line type {tname}: BA/-zeta = {lt.BA} dropped (MoorDyn's internal "
                         "axial damping, dynamics only; the scene's line has none)")
    data["segments"] = []
    for k, (i, rev) in enumerate(order):
        ln = deck.lines[i]
        data["segments"].append({"line_type": ln.line_type, "length": ln.length,
                                 "label": f"MoorDyn line {ln.id}" + (" (reversed)" if rev
                                                                     else "")})
        where[f"segments[{k}]"] = ln.line
    data["ends"] = {"anchor": [0.0, max(ya, 0.0)], "hang_off": [span, yh]}
    seabed = _seabed(deck, opts, deck.line_types[deck.lines[order[0][0]].line_type], notes)
    if seabed:
        data["seabed"] = seabed
        where["seabed"] = opts.kbot_line
    notes.append(f"Ends: point {bottom.id} ({bottom.attachment}) -> anchor, point {top.id} "
                 f"({top.attachment}) -> hang-off, horizontal direction ({ex[0]:.6g}, "
                 f"{ex[1]:.6g}) of MoorDyn's X-Y plane; y = Z + WtrDpth.")
    if len(order) > 1:
        notes.append(f"{len(order)} MoorDyn lines joined by free points, which are hinges in "
                     "MoorDyn (no moment); the scene's segments are continuous beams.")
    notes.append("MoorDyn mesh, not carried: " + ", ".join(
        f"line {deck.lines[i].id} {deck.lines[i].segments} segments" for i, _ in order))
    env_comments = [
        f"water_density {opts.rho:g} kg/m3 {opts.given('rho')}, gravity {opts.g:g} m/s2 "
        f"{opts.given('g')}: as MoorDyn-C 2.7 reads the deck (its defaults 1025 kg/m3 and "
        "9.80665 m/s2; the density from rho, Rho or WtrDnsty, never rhoW)",
        f"water_depth {depth:g} m: {depth_from or 'option WtrDpth'}"]
    return data, notes, where, env_comments


def _title(deck: Deck, name: str) -> str:
    """The first line of the front matter that is text, printable characters only."""
    for f in deck.front:
        f = "".join(c if c.isprintable() else " " for c in f).strip()
        if f and f[0] not in "-!#%":
            return f[:200]
    return f"MoorDyn deck {name}"


def _seabed(deck: Deck, opts: Options, lt, notes: list[str]) -> dict | None:
    kbot, cbot = opts.kbot, opts.cbot
    if kbot < 0.0 or cbot < 0.0:
        raise DeckError(deck.source, opts.kbot_line if kbot < 0 else opts.cbot_line,
                        "kBot and cBot must be >= 0")
    if kbot == 0.0:
        notes.append("kBot = 0: no seabed contact.")
        return None
    k = kbot * lt.diameter
    # d * d, not d ** 2: a huge diameter gives inf (refused by the scene's range check),
    # where ** raised OverflowError
    madd = lt.Ca * opts.rho * math.pi / 4.0 * lt.diameter * lt.diameter
    zeta = cbot * lt.diameter / (2.0 * math.sqrt(k * (lt.mass + madd)))
    notes.append(f"Seabed: stiffness = kBot x Diam of the bottom line ({lt.name}) = "
                 f"{kbot:g} x {lt.diameter:g} = {k:g} N/m2"
                 + ("" if opts.kbot_line else " (kBot not given: MoorDyn-C's default)")
                 + f"; damping = cBot d / (2 sqrt(k (m + m_a))) = {zeta:.6g} of critical"
                 + ("" if opts.cbot_line else " (cBot: MoorDyn-C's default)") + ".")
    if len({t.diameter for t in deck.line_types.values()}) > 1:
        notes.append("MoorDyn's contact per metre is kBot x d of each line: lines of another "
                     "diameter on the seabed would have another stiffness there.")
    return {"stiffness": k, "friction": opts.friction, "damping": min(zeta, 10.0)}


def _current(deck: Deck, opts: Options, path: Path, ex, depth: float,
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

"""A MoorDyn v2 deck -> a scene (``riser-verify import-moordyn``).

What a scene holds: one line from a bottom end to a hang-off, both fixed, made of
segments. So the deck must describe one chain of lines joined end to end by free points
(MoorDyn's joints, which are hinges: see docs/moordyn.md), between two fixed or coupled points
at their deck positions. Everything else is refused before anything is written, one line
naming the deck line: bodies, rods, failures, external loads, waves, a seafloor file, a
third fixed end, a point with a mass, a volume or drag (a clump weight or a float), a
coupled point with no position, a branch or a loop.

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
  (MoorDyn's convention): rows ``z ux uy uz``, one direction at every depth.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from ...errors import SceneError
from ...scene import Scene
from ..scene_file import scene_from_dict
from ..toml_text import dumps
from .deck import Deck, DeckError, DeckPoint, read_deck

#: MoorDyn-C's defaults of the options a scene needs (docs: "Options")
DEFAULTS = {"g": 9.81, "rho": 1025.0, "kbot": 3.0e6, "cbot": 3.0e5}
_ALIASES = {"g": ("g", "gravity"), "rho": ("rho", "rhow"), "kbot": ("kbot", "kb"),
            "cbot": ("cbot", "cb")}


def _opt(deck: Deck, key: str) -> tuple[float, int, bool]:
    """(value, line, given) of an option by any of its spellings."""
    for k in _ALIASES.get(key, (key,)):
        if k in deck.options:
            return float(deck.options[k][0]), deck.options[k][1], True
    return DEFAULTS.get(key, 0.0), 0, False


def import_deck(path: str | Path, name: str | None = None) -> tuple[str, Scene, list[str]]:
    """Read the deck at ``path``: (the scene's TOML text, the validated scene, the notes
    that were written into it as comments). Raise :class:`DeckError` naming the deck line."""
    path = Path(path)
    deck = read_deck(path)
    name = name or _scene_name(path.stem)
    data, notes, where = scene_dict(deck, name, path.parent / "current_profile.txt")
    header = [f"Imported from the MoorDyn deck {path.name} by riser-verify import-moordyn.",
              *notes]
    text = dumps(data, header=header)
    try:
        scene = scene_from_dict(data, f"{path.name} (imported)")
    except SceneError as exc:   # a value outside a scene's range: name the deck line
        line = next((no for prefix, no in where.items() if exc.key.startswith(prefix)), 0)
        raise DeckError(str(path), line, f"{exc.key}: {exc.message}") from None
    return text, scene, notes


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
    for key, what in (("wavekin", "waves"), ("seafloorfile", "a seafloor file (bathymetry)"),
                      ("waterkin", "water kinematics (MoorDyn-F)")):
        if key in deck.options and deck.options[key][0] not in ("0", "0.0", "none", "None",
                                                                '""', "''"):
            raise DeckError(deck.source, deck.options[key][1], f"option {key}: {what} cannot "
                            "be imported: a scene has a still surface, a flat seabed and a "
                            "steady current")


def _chain(deck: Deck) -> tuple[list[tuple[int, bool]], DeckPoint, DeckPoint]:
    """The lines in order from the bottom end, each (index, reversed), and the two ends."""
    src = deck.source
    if not deck.lines:
        raise DeckError(src, 0, "has no lines (the LINES table is empty)")
    npt = len(deck.points)
    ends: dict[int, list[tuple[int, str]]] = {}
    for i, ln in enumerate(deck.lines):
        if ln.line_type not in deck.line_types:
            raise DeckError(src, ln.line, f"line {ln.id}: unknown line type {ln.line_type!r}"
                            f" (defined: {', '.join(deck.line_types) or 'none'})")
        for end, att in (("A", ln.attach_a), ("B", ln.attach_b)):
            if not att.isdigit():
                raise DeckError(src, ln.line, f"line {ln.id}: Attach{end} {att!r} is not a "
                                "point ID (a rod end, R#A/R#B, cannot be imported)")
            pid = int(att)
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
            if len(att) != 2:
                raise DeckError(src, p.line, f"point {p.id} (free) joins {len(att)} line "
                                "ends; a scene is one chain: a free point joins exactly two")
            if p.mass or p.volume or p.CdA or p.Ca:
                raise DeckError(src, p.line, f"point {p.id}: a free point with mass, volume, "
                                "CdA or Ca (a clump weight or a float) cannot be imported: "
                                "a scene's joints carry no point loads")
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
        pid = int(ln.attach_b if end == "A" else ln.attach_a)
    if pid != top.id or len(used) != len(deck.lines):
        stray = next(ln for k, ln in enumerate(deck.lines) if k not in used)
        raise DeckError(src, stray.line, f"line {stray.id} is not on the chain from point "
                        f"{bottom.id} to point {top.id}; a scene is one line of segments")
    return order, bottom, top


def scene_dict(deck: Deck, name: str, current_file: Path | None
               ) -> tuple[dict, list[str], dict[str, int]]:
    """The scene structure of a deck, the notes, and key prefix -> deck line (for errors)."""
    src = deck.source
    _refuse_sections(deck)
    depth_given = "wtrdpth" in deck.options
    depth = deck.option("WtrDpth")
    if not depth_given or depth <= 0.0:
        raise DeckError(src, deck.option_line("WtrDpth"), "option WtrDpth: the water depth "
                        "[m] must be given and > 0 (the seabed is at Z = -WtrDpth)")
    order, bottom, top = _chain(deck)
    notes: list[str] = []
    where: dict[str, int] = {"environment.water_depth": deck.option_line("WtrDpth")}
    dx, dy = top.x - bottom.x, top.y - bottom.y
    span = math.hypot(dx, dy)
    if span < 1e-9:
        raise DeckError(src, top.line, f"points {bottom.id} and {top.id} are vertically "
                        "aligned: a scene's hang-off lies at a larger x than its anchor")
    ex = (dx / span, dy / span)
    ya, yh = bottom.z + depth, top.z + depth
    if ya < -1e-9:
        raise DeckError(src, bottom.line, f"point {bottom.id} is {-ya:g} m below the seabed "
                        f"(Z = {bottom.z:g} < -WtrDpth = {-depth:g})")
    if yh > depth + 1e-9:
        raise DeckError(src, top.line, f"point {top.id} is above the still water surface (Z = "
                        f"{top.z:g} > 0); the scene's line is submerged")
    where["ends"] = top.line
    g, g_line, _ = _opt(deck, "g")
    rho, rho_line, _ = _opt(deck, "rho")
    where.update({"environment.gravity": g_line, "environment.water_density": rho_line})
    data: dict = {"name": name,
                  "title": next((f.strip() for f in deck.front if f.strip() and
                                 f.strip()[0] not in "-!#%"), f"MoorDyn deck {name}")[:200],
                  "source": f"MoorDyn v2 deck {Path(src).name}",
                  "environment": {"gravity": g, "water_density": rho, "water_depth": depth}}
    current = _current(deck, current_file, ex, depth, notes) if current_file else None
    if current:
        data["environment"]["current"] = current
        where["environment.current"] = deck.option_line("Currents")

    used_types = list(dict.fromkeys(deck.lines[i].line_type for i, _ in order))
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
    data["segments"] = []
    for k, (i, rev) in enumerate(order):
        ln = deck.lines[i]
        data["segments"].append({"line_type": ln.line_type, "length": ln.length,
                                 "label": f"MoorDyn line {ln.id}" + (" (reversed)" if rev
                                                                     else "")})
        where[f"segments[{k}]"] = ln.line
    data["ends"] = {"anchor": [0.0, max(ya, 0.0)], "hang_off": [span, yh]}
    seabed = _seabed(deck, deck.line_types[deck.lines[order[0][0]].line_type], rho, notes)
    if seabed:
        data["seabed"] = seabed
        where["seabed"] = deck.option_line("kBot")
    notes.append(f"Ends: point {bottom.id} ({bottom.attachment}) -> anchor, point {top.id} "
                 f"({top.attachment}) -> hang-off, horizontal direction ({ex[0]:.6g}, "
                 f"{ex[1]:.6g}) of MoorDyn's X-Y plane; y = Z + WtrDpth.")
    if len(order) > 1:
        notes.append(f"{len(order)} MoorDyn lines joined by free points, which are hinges in "
                     "MoorDyn (no moment); the scene's segments are continuous beams.")
    notes.append("MoorDyn mesh, not carried: " + ", ".join(
        f"line {deck.lines[i].id} {deck.lines[i].segments} segments" for i, _ in order))
    return data, notes, where


def _seabed(deck: Deck, lt, rho: float, notes: list[str]) -> dict | None:
    kbot, _, kgiven = _opt(deck, "kbot")
    cbot, _, cgiven = _opt(deck, "cbot")
    if kbot < 0.0 or cbot < 0.0:
        raise DeckError(deck.source, deck.option_line("kBot" if kbot < 0 else "cBot"),
                        "kBot and cBot must be >= 0")
    if kbot == 0.0:
        notes.append("kBot = 0: no seabed contact.")
        return None
    k = kbot * lt.diameter
    madd = lt.Ca * rho * math.pi / 4.0 * lt.diameter ** 2
    zeta = cbot * lt.diameter / (2.0 * math.sqrt(k * (lt.mass + madd)))
    fric = deck.option("FrictionCoefficient", 0.0)
    mu_t, mu_a = deck.option("MU_KT", None), deck.option("MU_KA", None)
    if mu_t is not None or mu_a is not None:
        if mu_t != mu_a or "frictioncoefficient" in deck.options:
            raise DeckError(deck.source, deck.option_line("MU_KT") or deck.option_line("MU_KA"),
                            "MU_KT and MU_KA (MoorDyn-F): the scene has one friction "
                            "coefficient; give FrictionCoefficient, or equal MU_KT and MU_KA")
        fric = mu_t
    notes.append(f"Seabed: stiffness = kBot x Diam of the bottom line ({lt.name}) = "
                 f"{kbot:g} x {lt.diameter:g} = {k:g} N/m2"
                 + ("" if kgiven else " (kBot not given: MoorDyn's default)")
                 + f"; damping = cBot d / (2 sqrt(k (m + m_a))) = {zeta:.6g} of critical"
                 + ("" if cgiven else " (cBot: MoorDyn's default)") + ".")
    if len({t.diameter for t in deck.line_types.values()}) > 1:
        notes.append("MoorDyn's contact per metre is kBot x d of each line: lines of another "
                     "diameter on the seabed would have another stiffness there.")
    return {"stiffness": k, "friction": fric, "damping": min(zeta, 10.0)}


def _current(deck: Deck, path: Path, ex, depth: float, notes: list[str]) -> dict | None:
    """The scene's [environment.current] from MoorDyn's steady current profile."""
    mode = deck.option("Currents", 0.0)
    if mode == 0:
        return None
    if mode != 1:
        raise DeckError(deck.source, deck.option_line("Currents"), f"option Currents = "
                        f"{mode:g}: only 1 (a steady profile, current_profile.txt) can be "
                        "imported; a scene's current is steady and depth-dependent")
    where = str(path)
    try:
        rows = path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError as exc:
        raise DeckError(deck.source, deck.option_line("Currents"), f"Currents = 1 needs "
                        f"{path.name} beside the deck ({exc.strerror or exc})") from None
    ez = (ex[1], -ex[0])
    table = []
    for no, raw in enumerate(rows[3:], start=4):
        tok = raw.split("!")[0].split()
        if not tok:
            continue
        if len(tok) < 2:
            raise DeckError(where, no, "a row is 'z ux [uy [uz]]' [m, m/s]")
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
    ref = max(table, key=lambda r: math.hypot(r[1], r[2]))
    umax = math.hypot(ref[1], ref[2])
    if umax == 0.0:
        return None
    dx, dz = ref[1] / umax, ref[2] / umax
    for y, ux, uz, no in table:
        if abs(ux * dz - uz * dx) > 1e-9 * umax:
            raise DeckError(where, no, "the current turns with depth; a scene's current has "
                            "one heading (speeds of either sign along it)")
    heading = math.degrees(math.atan2(dz, dx))
    notes.append(f"Current from {path.name}: heading {heading:.6g} deg from the scene's x "
                 "towards its z.")
    return {"heights": [r[0] for r in table], "speeds": [r[1] * dx + r[2] * dz for r in table],
            "heading_deg": heading}

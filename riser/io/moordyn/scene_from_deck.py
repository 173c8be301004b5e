"""A MoorDyn v2 deck -> a scene (``riser-verify import-moordyn``).

What a scene holds: one line from a bottom end to a hang-off, made of segments, with point
attachments. So the deck must describe one chain of lines joined end to end by free points
(MoorDyn's joints, hinges: see docs/moordyn.md) between two fixed or coupled points at
their deck positions, or hanging from one of them with a free bottom end. Everything else
is refused before anything is written, one line naming the deck line: bodies, rods,
failures, external loads, waves other than summed components (WaveKin 7:
:mod:`riser.io.moordyn.waves`), a seafloor file, a third fixed end, a steady force on a
point, a mass, volume or drag on a fixed or coupled end, a free end above the fixed one, a
coupled point with no position, a branch or a loop, a line type that a used line cannot
have (no bending stiffness, a nonlinear EA), a number written with a comma.

Mapping (MoorDyn -> scene; MoorDyn's Z is up from the still surface, the scene's y up from
the seabed, so y = Z + WtrDpth):

- the vertical plane through the two ends becomes the x-y plane, x from the bottom end
  towards the hang-off; the scene's z is x cross y (MoorDyn's -Y for an end pair along +X);
- a line type: outer_diameter = Diam (MoorDyn's volume-equivalent diameter),
  mass_per_length = Mass/m, axial_stiffness = EA, bending_stiffness = EI, drag_normal =
  Cd (on d l), drag_tangential = CdAx (on pi d l, the scene's convention too), added_mass =
  Ca, axial_damping = BA (N s; a negative BA/-zeta, a damping ratio, converted with each
  line's segment length as MoorDyn-C converts it: :func:`axial_damping_of`); CaAx and the
  VIV lift Cl have no scene key and are dropped with a note;
- a free point with M, V, CdA or Ca (a clump weight, a buoy) -> an ``[[attachments]]``
  entry at its arc length s (the unstretched lengths of the lines below it; 0 at a free
  bottom end, which becomes ``[ends.anchor_joint] kind = "free"`` at its deck position,
  the seabed dropped: a hanging line clears it): mass = M, volume = V, drag_area = CdA,
  added_mass_coefficient = Ca (MoorDyn's point: weight (M - rho V) g, drag 1/2 rho CdA
  |u| u, added mass Ca rho V, as the scene's);
- the seabed: MoorDyn's contact force per metre is kBot d times the penetration, so the
  scene's stiffness [N/m2] is kBot x Diam of the bottom line; cBot becomes the damping as
  a fraction of critical, cBot d / (2 sqrt(k (m + m_a))) (the VFIFE definition); the
  friction is FrictionCoefficient;
- a steady current (``Currents 1``) from current_profile.txt beside the deck: rows ``z ux
  uy uz`` with uz = 0, (ux, uy) turned into the scene's frame: one direction at every
  depth gives ``heading_deg`` and speeds signed along it; a profile that turns with depth
  ``headings_deg`` (one per row) and the speeds. Points and current are turned alike;
- the options as MoorDyn-C 2.7 reads them (:mod:`riser.io.moordyn.options`): g = 9.80665
  m/s2 and 1025 kg/m3 when the deck gives none, the water depth lowered to the deepest
  point as MoorDyn-C lowers it. Where each value came from is a comment in the scene file.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from ...errors import SceneError
from ...model.scene import Scene
from ..scene_file import scene_from_dict
from ..toml_text import dumps
from .current import read_current
from .deck import Deck, DeckPoint, read_deck
from .options import Options, read_options
from .tokens import DeckError
from .waves import WAVE_FILE, read_components, waves_table


def import_deck(path: str | Path, name: str | None = None) -> tuple[str, Scene, list[str]]:
    """Read the deck at ``path``: (the scene's TOML text, the validated scene, the notes
    that were written into it as comments). The scene's name is ``name`` or the deck's
    file name, made a valid scene name (lower case, digits, dashes), whatever file the
    scene is written to. Raise :class:`DeckError` naming the deck line."""
    path = Path(path)
    deck = read_deck(path)
    name = _scene_name(name or path.stem)
    data, notes, where, comments = scene_dict(deck, name, path.parent / "current_profile.txt",
                                              path.parent / WAVE_FILE)
    header = [f"Imported from the MoorDyn deck {path.name} by riser-verify import-moordyn.",
              *notes]
    text = dumps(data, header=[_printable(h) for h in header],
                 comments={k: [_printable(c) for c in v] for k, v in comments.items()})
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


def _loads(p: DeckPoint) -> bool:
    """The point carries a mass, a volume or drag (a clump weight, a buoy)."""
    return bool(p.mass or p.volume or p.CdA or p.Ca)


def _chain(deck: Deck) -> tuple[list[tuple[int, bool]], DeckPoint, DeckPoint, list[DeckPoint]]:
    """The lines in order from the bottom end, each (index, reversed), the two ends (the
    bottom one may be a free point: a hanging line) and the free points joining the lines
    (the k-th between lines k and k + 1)."""
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
    fixed, loose = [], []
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
                if _loads(p) or any(p.force):
                    raise DeckError(src, p.line, f"point {p.id} ({p.attachment}): a mass, "
                                    "volume, CdA, Ca or force on a fixed or coupled end "
                                    "cannot be imported: a scene's fixed ends carry no "
                                    "point loads (attachments sit on the line)")
            if len(att) > 1:
                raise DeckError(src, p.line, f"point {p.id} ({p.attachment}) holds "
                                f"{len(att)} lines; a scene's ends each hold one")
        elif att:
            if any(p.force):
                raise DeckError(src, p.line, f"point {p.id}: a free point with a steady force "
                                "FX FY FZ (a point load) cannot be imported: a scene's "
                                "attachments carry weight, buoyancy and drag only")
            if len(att) == 1:
                loose.append(p)
            elif len(att) != 2:
                raise DeckError(src, p.line, f"point {p.id} (free) joins {len(att)} line "
                                "end(s); a scene is one chain: a free point joins exactly two")
    if len(fixed) == 1 and len(loose) == 1:     # a hanging line: its free end at the bottom
        (bottom,), (top,) = loose, fixed
        if None in (bottom.x, bottom.y, bottom.z):
            raise DeckError(src, bottom.line, f"point {bottom.id} (free) has no position (X "
                            "Y Z must be numbers): a free end starts from its deck position")
        if bottom.z >= top.z:
            raise DeckError(src, bottom.line, f"point {bottom.id} (free) is the free end of "
                            f"the chain from point {top.id}: it must lie below that fixed "
                            "end (a scene's free end is its bottom end: the line hangs "
                            "from its hang-off)")
    elif loose:
        p = loose[0]
        raise DeckError(src, p.line, f"point {p.id} (free) joins 1 line end(s); a scene is "
                        "one chain between two fixed ends (or hanging from one, its free end "
                        "below): a free point joins exactly two")
    elif len(fixed) < 2:
        raise DeckError(src, 0, f"has {len(fixed)} fixed or coupled line end(s); a scene "
                        "needs two (the anchor and the hang-off)")
    else:
        bottom, top = sorted(fixed, key=lambda p: (p.z, p.id))
    order: list[tuple[int, bool]] = []
    joints: list[DeckPoint] = []
    pid, used = bottom.id, set()
    while pid != top.id:
        nxt = [(i, e) for i, e in ends[pid] if i not in used]
        if not nxt:
            break
        if order:
            joints.append(deck.points[pid - 1])
        i, end = nxt[0]
        used.add(i)
        ln = deck.lines[i]
        order.append((i, end == "B"))
        pid = int(_POINT_REF.fullmatch(ln.attach_b if end == "A" else ln.attach_a).group(1))
    if pid != top.id or len(used) != len(deck.lines):
        stray = next(ln for k, ln in enumerate(deck.lines) if k not in used)
        raise DeckError(src, stray.line, f"line {stray.id} is not on the chain from point "
                        f"{bottom.id} to point {top.id}; a scene is one line of segments")
    return order, bottom, top, joints


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
               wave_file: Path | None = None) -> tuple[dict, list[str], dict, dict]:
    """The scene structure of a deck, the notes, key prefix -> deck line (or (file, line)
    of the wave file, for errors), and the comment lines above its tables (for dumps: where
    g, the density and the depth came from, what each attachment was)."""
    _refuse_sections(deck)
    opts = read_options(deck)
    notes = [*deck.notes, *opts.notes]
    order, bottom, top, joints = _chain(deck)
    free = bottom.kind == "free"
    used_types = list(dict.fromkeys(deck.lines[i].line_type for i, _ in order))
    for tname in used_types:                 # a type no line uses may hold anything
        if tname in deck.line_type_errors:
            raise deck.line_type_errors[tname]
    depth, depth_line, depth_from = _depth(deck, opts, notes)
    where: dict[str, int] = {"environment.water_depth": depth_line}
    dx, dy = top.x - bottom.x, top.y - bottom.y
    span = math.hypot(dx, dy)
    if span < 1e-9 and not free:
        raise DeckError(deck.source, top.line, f"points {bottom.id} and {top.id} are "
                        "vertically aligned: a scene's hang-off lies at a larger x than its "
                        "anchor")
    ex = (dx / span, dy / span) if span >= 1e-9 else (1.0, 0.0)
    if span < 1e-9:                 # a line hanging straight down: MoorDyn's X-Z plane
        span = 0.0
        notes.append(f"The free end (point {bottom.id}) lies below point {top.id}: the "
                     "scene's x-y plane is MoorDyn's X-Z plane.")
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
    current = read_current(deck, opts, current_file, ex, depth, notes) if current_file \
        else None
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
    seg_types = _axial_damping(deck, order, data["line_types"], where, notes)
    data["segments"] = []
    for k, (i, rev) in enumerate(order):
        ln = deck.lines[i]
        data["segments"].append({"line_type": seg_types[k], "length": ln.length,
                                 "label": f"MoorDyn line {ln.id}" + (" (reversed)" if rev
                                                                     else "")})
        where[f"segments[{k}]"] = ln.line
    data["ends"] = {"anchor": [0.0, max(ya, 0.0)], "hang_off": [span, yh]}
    comments = {"environment": [
        f"water_density {opts.rho:g} kg/m3 {opts.given('rho')}, gravity {opts.g:g} m/s2 "
        f"{opts.given('g')}: as MoorDyn-C 2.7 reads the deck (its defaults 1025 kg/m3 and "
        "9.80665 m/s2; the density from rho, Rho or WtrDnsty, never rhoW)",
        f"water_depth {depth:g} m: {depth_from or 'option WtrDpth'}"]}
    if free:
        data["ends"]["anchor_joint"] = {"kind": "free"}
        where["ends.anchor_joint"] = bottom.line
        notes.append(f"Point {bottom.id} (Free) is a free end: [ends.anchor_joint] kind = "
                     "'free', the anchor its starting position; MoorDyn's seabed is not "
                     "carried (a scene's hanging line clears the seabed).")
    _attachments(deck, order, bottom if free else None, joints, data, where, comments, notes)
    seabed = None if free else _seabed(deck, opts, deck.line_types[deck.lines[order[0][0]]
                                                                   .line_type], notes)
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
    return data, notes, where, comments


def axial_damping_of(lt, length: float, segments: int) -> float:
    """The internal axial damping BA [N s] MoorDyn-C gives a line of type ``lt`` (BA/-zeta
    as written), unstretched length ``length`` [m] and ``segments`` segments: a BA >= 0 as
    it is; a negative one is minus a damping ratio zeta of the segment's axial mode,
    MoorDyn-C's Line::initialize c = zeta (L / N) sqrt(E rho) [Pa s] with E = EA / A and
    rho = (Mass/m) / A, i.e. BA = c A = zeta (L / N) sqrt(EA Mass/m)."""
    ba = float(lt.BA)
    if ba >= 0.0:
        return ba
    return -ba * length / segments * math.sqrt(lt.EA * lt.mass)


def _axial_damping(deck: Deck, order, types: dict, where: dict,
                   notes: list[str]) -> list[str]:
    """Each used line type's ``axial_damping`` (BA/-zeta: :func:`axial_damping_of`) set in
    ``types``, and the line type of each segment (in ``order``). A negative BA depends on
    the line's segment length: lines of one type with different segment lengths get a
    line type each (``NAME_lineID``), with a note. A viscoelastic BA (``static|dynamic``)
    is dropped with a note."""
    seg_types = [deck.lines[i].line_type for i, _ in order]
    for tname in list(types):
        lt = deck.line_types[tname]
        if "|" in lt.BA:
            notes.append(f"line type {tname}: BA/-zeta = {lt.BA} dropped (a viscoelastic "
                         "line's damping; the scene's axial damping is one BA)")
            continue
        ks = [k for k, (i, _) in enumerate(order) if deck.lines[i].line_type == tname]
        values = [axial_damping_of(lt, deck.lines[order[k][0]].length,
                                   deck.lines[order[k][0]].segments) for k in ks]
        if float(lt.BA) < 0.0:
            notes.append(f"line type {tname}: BA/-zeta = {lt.BA}, a damping ratio of the "
                         "segment's axial mode: axial_damping = zeta (L / N) sqrt(EA Mass/m) "
                         "of each line, as MoorDyn-C converts it (" + ", ".join(
                             f"line {deck.lines[order[k][0]].id}: {v:.6g} N s"
                             for k, v in zip(ks, values)) + ")")
        if all(v == values[0] for v in values):
            if values[0] > 0.0:
                types[tname]["axial_damping"] = values[0]
            continue
        base = types.pop(tname)
        line = where.pop(f"line_types.{tname}")
        for k, v in zip(ks, values):
            name = f"{tname}_line{deck.lines[order[k][0]].id}"
            types[name] = {**base, "axial_damping": v}
            where[f"line_types.{name}"] = line
            seg_types[k] = name
        notes.append(f"line type {tname}: its lines' segment lengths differ, so do their "
                     "BA: a line type per line (" + ", ".join(
                         seg_types[k] for k in ks) + ")")
    return seg_types


def _attachments(deck: Deck, order, free_end: DeckPoint | None, joints: list[DeckPoint],
                 data: dict, where: dict, comments: dict, notes: list[str]) -> None:
    """``[[attachments]]`` of the free points with a mass, volume or drag: each at its arc
    length, the unstretched lengths of the lines below it (0 at a free bottom end)."""
    placed = [(0.0, free_end)] if free_end is not None else []
    s = 0.0
    for (i, _), p in zip(order, joints):
        s += deck.lines[i].length
        placed.append((s, p))
    atts = []
    for si, p in placed:
        if not _loads(p):
            continue
        key = f"attachments[{len(atts)}]"
        atts.append({"s": si, "mass": p.mass, "volume": p.volume, "drag_area": p.CdA,
                     "added_mass_coefficient": p.Ca, "label": f"MoorDyn point {p.id}"})
        where[key] = p.line
        comments[key] = [f"MoorDyn point {p.id} ({p.attachment}, deck line {p.line}): mass = "
                         "M, volume = V, drag_area = CdA, added_mass_coefficient = Ca, at s ="
                         f" {si:.12g} m " + ("(the free bottom end)" if si == 0.0 else
                                             "(the unstretched lengths of the lines below)")]
    if atts:
        data["attachments"] = atts
        notes.append("Free points with a mass, volume or drag -> [[attachments]]: " + ", ".join(
            f"{a['label']} at s = {a['s']:.12g} m" for a in atts) + " (M, V, CdA, Ca -> mass, "
            "volume, drag_area, added_mass_coefficient).")


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

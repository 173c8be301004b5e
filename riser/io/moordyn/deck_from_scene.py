"""A fixed-ends scene -> a MoorDyn v2 deck (``riser-verify export-moordyn``, and the deck the
MoorDyn peer runs).

One MoorDyn line per run of segments with the same section (adjacent equal segments are
merged: a joint between MoorDyn lines is a hinge, so none is added where the scene has
none), split at each attachment; free points join them, fixed points hold the anchor and
the hang-off (a free anchor end, ``[ends.anchor_joint] kind = "free"``, is a free point).

Attachments (``[[attachments]]``): each is MoorDyn's free point at its arc length s, the
lines ending and starting there, with M = mass, V = volume, CdA = drag_area, Ca =
added_mass_coefficient (MoorDyn's point: weight (M - rho V) g, drag 1/2 rho CdA |u| u,
added mass Ca rho V, the scene's; a hinge, as every joint). An attachment within
:data:`SNAP` of a joint between sections sits on that joint; attachments at one point are
merged (masses, volumes and drag areas added, Ca weighted by volume), with a note. Each
line gets ceil(L / segment_length) segments, so no segment is longer than the segment
length.

Equivalent sections. MoorDyn ties weight, buoyancy, drag and added mass to one diameter d
and the mass per length m: w = (m - rho pi d^2 / 4) g, normal drag on d l, tangential drag
on pi d l, added mass Ca rho pi d^2 / 4. A scene segment has its own weight w (buoyancy
modules, a weight override, contents), its hydrodynamic diameter D_h and its mass m. The
deck keeps m (the inertia) and chooses d from the displaced area A = (m g - w) / (rho g),
d = sqrt(4 A / pi), then Cd' = Cd D_h / d, CdAx' = CdAx D_h / d, Ca' = Ca D_h^2 / d^2, so
that weight, drag and added mass per metre equal the scene's. For a bare pipe d = D.

Axial damping: a line type's ``axial_damping`` is written as its BA [N s] (MoorDyn's
internal damping is the scene's Kelvin-Voigt term, EA eps + BA d(eps)/dt); a line type
without it gets BA/-zeta = -``damping`` (0.8 of critical per segment by default: MoorDyn's
numerical damping, which its statics need; a note says so).

Coordinates: the scene's x -> MoorDyn X, the scene's y (up from the seabed) -> Z = y -
WtrDpth, the scene's z -> -Y (both frames right-handed). The seabed: kBot = k / d of the
bottom line, cBot from the damping fraction (see :mod:`riser.io.moordyn.scene_from_deck`, the exact
inverse). A current is written to ``current_profile.txt`` (``Currents 1``), which MoorDyn
reads from the deck's folder: the velocity's components (u_x, -u_z, 0) at each of the
scene's heights, which MoorDyn interpolates component by component as the scene does.

A 3D scene (a hang-off out of the anchor's plane: ends given as (x, y, z); a current out of
the x-y plane or turning with depth) is written with the same mapping: its points at their
3D positions, its current row by row. The importer turns the vertical plane through the
ends into the x-y plane, so export then import gives back the line and the current turned
by the plane's heading.

Waves (``[environment.waves]`` with line loads) are written as MoorDyn-C's WaveKin 7 and
``wave_frequencies.txt`` beside the deck, the scene's components one per line
(:mod:`riser.io.moordyn.waves`, which also says what MoorDyn-C does not represent).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ...errors import UnsupportedSceneError
from ...model.scene import FixedEnds, Scene
from ...model.sections import segment_properties
from .deck import OPTION_KEYS, Deck, DeckLine, DeckLineType, DeckPoint
from .waves import wave_file_text

#: the initial-condition settings written to a deck (MoorDyn-C's stationary solver):
#: the time it may run [s], the residual acceleration it stops at [m/s2] and the interval
#: of its checks [s]; see verification/peers/moordyn/run.py for what they mean
IC_OPTIONS = {"TmaxIC": 2000.0, "threshIC": 1.0e-4, "dtIC": 1.0}
#: an attachment this close [m] to a joint between sections is put on it (far below the
#: 1e-9 m to which export then import gives back its s; no line of 1e-9 m)
SNAP = 1.0e-10


@dataclass
class ExportedDeck:
    """The deck text, the current profile's text (None without a current), the notes
    written into the deck, for each MoorDyn line the scene segments it holds and its arc
    length [s0, s1] [m] from the scene's bottom end, and the text of wave_frequencies.txt
    (None without waves in the deck)."""

    text: str
    current_profile: str | None
    notes: list[str]
    deck: Deck
    line_segments: list[list[int]] = field(default_factory=list)
    line_span: list[tuple[float, float]] = field(default_factory=list)
    wave_frequencies: str | None = None


def _check(scene: Scene) -> None:
    why = None
    if not isinstance(scene.ends, FixedEnds):
        why = (f"the '{scene.ends.kind}' form: MoorDyn needs fixed ends (the command "
               "converts a touchdown-form scene first; a library caller uses "
               "verification.pipeline.vfife_equivalent)")
    elif scene.axial_model != "extensible":
        why = "[model] axial = 'inextensible': MoorDyn's lines are extensible (EA)"
    elif scene.seabed_model == "rigid":
        why = "[model] seabed = 'rigid': MoorDyn's seabed is an elastic foundation (kBot)"
    elif scene.internal_flow is not None:
        why = "[internal_flow]: MoorDyn has no internal flow"
    else:
        e = scene.ends
        held = [f"[ends.{k}_joint] kind = '{jt.kind}'" for k in ("anchor", "hang_off")
                if (jt := e.joint(k)) is not None and jt.kind != "free"]
        held += ["[ends.tensioner]"] if e.tensioner is not None else []
        if held:
            why = (f"{', '.join(held)}: MoorDyn's points are pinned in place (no end moment, "
                   "no tensioner); written as pinned they would be another line")
    if why:
        raise UnsupportedSceneError(f"cannot export {scene.name} to MoorDyn: {why}")


def _section(scene: Scene, props, seg) -> tuple:
    """(d, m, EA, EI, Cd, Ca, CdAx, BA) of the equivalent MoorDyn section of one segment
    (BA [N s] the line type's axial_damping, 0 without)."""
    g, rho = scene.gravity, scene.water_density
    lt = scene.line_types[seg.line_type]
    area = (props.mass * g - props.weight) / (rho * g)
    if area <= 0.0:
        raise UnsupportedSceneError(
            f"cannot export {scene.name} to MoorDyn: segment '{seg.label or seg.line_type}' "
            f"weighs {props.weight:g} N/m in water, more than its {props.mass * g:g} N/m in "
            "air; MoorDyn's line has no equivalent diameter for it")
    d = math.sqrt(4.0 * area / math.pi)
    dh = seg.hydro_diameter or lt.hydro_diameter or lt.outer_diameter
    return (d, props.mass, props.EA, props.EI, lt.drag_normal * dh / d,
            lt.added_mass * (dh / d) ** 2, lt.drag_tangential * dh / d, props.BA)


def export_scene(scene: Scene, *, segment_length: float | None = None,
                 joints: list[tuple[float, float, float]] | None = None,
                 hang_off: str = "Fixed", damping: float = 0.8,
                 ic: dict | None = None, notes: tuple[str, ...] = (),
                 waves: bool = True) -> ExportedDeck:
    """The MoorDyn deck of a fixed-ends ``scene``.

    segment_length : MoorDyn segment length [m] (default: the scene's VFIFE element
        length); each line gets ceil(L / segment_length) segments.
    joints : scene (x, y, z) [m] of the joints between MoorDyn lines, from a solved
        profile: MoorDyn's initial guess for its free points (default: along the chord).
    hang_off : the hang-off point's attachment, 'Fixed' or 'Coupled' (driven by a caller).
    damping : the axial damping written as BA/-zeta = -damping (a fraction of critical
        per segment; MoorDyn's damping, not the scene's) for a line type without
        ``axial_damping``; one with it is written with its BA [N s] (the scene's damping,
        which the importer reads back exactly).
    ic : overrides of :data:`IC_OPTIONS`.
    notes : lines put first among the deck's comments (e.g. how the scene was converted).
    waves : write the scene's waves (WaveKin 7 and wave_frequencies.txt,
        :mod:`riser.io.moordyn.waves`); False: still water (MoorDyn's statics).
    """
    _check(scene)
    props = segment_properties(scene)
    h = float(scene.vfife.element_length if segment_length is None else segment_length)
    depth = scene.water_depth if scene.water_depth is not None else scene.ends.hang_off[1]
    notes = [*notes, "Written by riser-verify export-moordyn. Coordinates: X = the scene's x, Z = y - "
             f"WtrDpth (seabed at Z = {-depth:g} m), Y = -z.",
             "Each line type is the equivalent section of its segments: the mass per metre "
             "is the scene's (pipe, contents, modules); Diam is the volume-equivalent "
             "diameter sqrt(4 (m g - w) / (rho g pi)) that gives the scene's submerged "
             "weight w; Cd, CdAx and Ca are scaled by D_h/Diam, (D_h/Diam) and "
             "(D_h/Diam)^2 so that drag and added mass per metre equal the scene's for its "
             "hydrodynamic diameter D_h.",
             "Joints between lines are free points, which MoorDyn treats as hinges (no "
             "moment); adjacent segments with the same section are one line."]
    if scene.water_depth is None:
        notes.append("The scene gives no water depth: WtrDpth is the hang-off height (the "
                     "hang-off at the surface).")
    # group adjacent equal sections
    groups: list[tuple[tuple, list[int]]] = []
    for i, (seg, p) in enumerate(zip(scene.segments, props)):
        sec = _section(scene, p, seg)
        if groups and groups[-1][0] == sec:
            groups[-1][1].append(i)
        else:
            groups.append((sec, [i]))
    deck = Deck(source=f"{scene.name}.dat",
                front=[f"{scene.name}: {scene.title}" if scene.title else scene.name])
    names: dict[tuple, str] = {}
    for sec, idx in groups:
        if sec in names:
            continue
        base = scene.segments[idx[0]].line_type
        lt = scene.line_types[base]
        name = base if abs(sec[0] - lt.outer_diameter) < 1e-12 * lt.outer_diameter \
            and base not in deck.line_types else f"{base}_s{idx[0] + 1}"
        name = "".join(c if c.isalnum() or c in "_-." else "_" for c in name)
        names[sec] = name
        d, m, EA, EI, Cd, Ca, CdAx, BA = sec
        deck.line_types[name] = DeckLineType(name, d, m, EA,
                                             _g(BA) if BA > 0.0 else f"{-abs(damping):g}",
                                             EI, Cd, Ca, CdAx, 0.0)
    if any(sec[7] > 0.0 for sec, _ in groups):
        notes.append("BA/-zeta: a line type with axial_damping is written with it, BA [N s] "
                     "(MoorDyn's internal axial damping, the scene's: EA eps + BA "
                     "d(eps)/dt)" + ("; one without it with -" + f"{abs(damping):g}" +
                                     " (a fraction of critical per segment, MoorDyn's "
                                     "numerical damping, not the scene's)"
                                     if any(sec[7] == 0.0 for sec, _ in groups) else "")
                     + ".")
    # the lines: the runs of equal sections split at the attachments
    pieces, loads = _pieces(scene, props, groups, notes)
    edges = {props[idx[0]].s_start for _, idx in groups} | {props[-1].s_end}
    # points: anchor, joints, hang-off (scene -> MoorDyn coordinates)
    def md(x, y, z=0.0):
        return (x, -z, y - depth)

    a, b = scene.ends.anchor_point, scene.ends.hang_off_point
    s_edges = [p[1] for p in pieces] + [pieces[-1][2]]
    total = s_edges[-1]
    pts = [md(*a)]
    for k in range(1, len(pieces)):
        if joints is not None:
            pts.append(md(*joints[k - 1]))
        else:
            f = s_edges[k] / total
            pts.append(md(*(p + f * (q - p) for p, q in zip(a, b))))
    pts.append(md(*b))
    free = scene.ends.free_anchor
    kinds = ["Free" if free else "Fixed"] + ["Free"] * (len(pieces) - 1) + [hang_off]
    deck.points = [DeckPoint(i + 1, kind, *p, *loads.get(i, (0.0,) * 4))
                   for i, (kind, p) in enumerate(zip(kinds, pts))]
    spans = []
    for k, (sec, s0, s1, idx) in enumerate(pieces):
        whole = s0 in edges and s1 in edges          # a run of whole segments: their sum
        length = sum(scene.segments[i].length for i in idx) if whole else s1 - s0
        n = max(1, math.ceil(length / h - 1e-9))
        deck.lines.append(DeckLine(k + 1, names[sec], str(k + 1), str(k + 2), length, n, "-"))
        spans.append((s0, s1))
    opts = _options(scene, deck, groups[0][0], depth, notes, ic)
    sea = _sea(scene, waves, opts, notes)
    deck.options = {k: (v, 0) for k, v in opts.items()}
    deck.outputs = ["AnchTen1", f"FairTen{len(pieces)}"]
    profile = _current_profile(scene, depth) if scene.current is not None else None
    if scene.dynamics is not None or scene.vessel is not None:
        notes.append("The scene's [dynamics] and [vessel] (top motion, RAOs, duration) are "
                     "not exported: a deck holds no motion of a coupled point (the MoorDyn "
                     "peer prescribes it).")
    if any(lt.compression for lt in scene.line_types.values()):
        notes.append("MoorDyn's segments carry no compression (slack at zero strain); the "
                     "scene's pipe does: the two differ wherever the effective tension is "
                     "negative.")
    text = format_deck(deck, comments=notes, option_notes=_OPTION_NOTES)
    return ExportedDeck(text, profile, notes, deck, [p[3] for p in pieces], spans, sea)


def _pieces(scene: Scene, props, groups, notes: list[str]) -> tuple[list, dict]:
    """The MoorDyn lines, (section, s0, s1, the scene segments in it), from the runs of
    equal sections split at the attachments, and the point loads: point index -> (M, V,
    CdA, Ca) of the attachments there."""
    edges = [props[idx[0]].s_start for _, idx in groups] + [props[-1].s_end]
    cuts: list[float] = []          # one cut per point: those within SNAP are one point
    for s in sorted(a.s for a in scene.attachments):
        if min(abs(s - e) for e in edges + cuts[-1:]) > SNAP:
            cuts.append(s)
    pieces = []
    for k, (sec, _) in enumerate(groups):
        s = [edges[k], *(c for c in cuts if edges[k] < c < edges[k + 1]), edges[k + 1]]
        pieces += [(sec, s0, s1, [i for i, p in enumerate(props)
                                  if p.s_start < s1 and p.s_end > s0])
                   for s0, s1 in zip(s, s[1:])]
    ends = [p[1] for p in pieces] + [pieces[-1][2]]
    at: dict[int, list] = {}
    for a in scene.attachments:
        at.setdefault(min(range(len(ends)), key=lambda i: abs(ends[i] - a.s)), []).append(a)
    loads = {}
    for i, atts in at.items():
        if i == len(ends) - 1 or (i == 0 and not scene.ends.free_anchor):
            raise UnsupportedSceneError(
                f"cannot export {scene.name} to MoorDyn: attachment "
                f"'{atts[0].label or atts[0].s}' at s = {atts[0].s:g} m is within {SNAP:g} m "
                "of a fixed end, where MoorDyn's point holds no load")
        vol = sum(a.volume for a in atts)
        ca = atts[0].added_mass_coefficient if len(atts) == 1 else (sum(
            a.added_mass_coefficient * a.volume for a in atts) / vol if vol else 0.0)
        loads[i] = (sum(a.mass for a in atts), vol, sum(a.drag_area for a in atts), ca)
        if len(atts) > 1:
            notes.append(f"Attachments {', '.join(a.label or f's = {a.s:g} m' for a in atts)}"
                         f" at one point (s = {ends[i]:g} m): merged into point {i + 1}, "
                         "masses, volumes and drag areas added, Ca weighted by volume.")
    if scene.attachments:
        notes.append("Attachments are free points (MoorDyn's Mass, Volume, CdA, Ca = the "
                     "scene's mass, volume, drag_area, added_mass_coefficient): " + ", ".join(
                         f"point {i + 1} at s = {ends[i]:.12g} m" for i in sorted(loads))
                     + "; lines end and start there.")
    short = min(s1 - s0 for _, s0, s1, _ in pieces)
    if scene.attachments and short < 1e-3 * ends[-1]:
        notes.append(f"The shortest line is {short:g} m (an attachment near a joint): "
                     "MoorDyn's time step follows its shortest segment.")
    return pieces, loads


def _sea(scene: Scene, waves: bool, opts: dict, notes: list[str]) -> str | None:
    """WaveKin 7 and the text of wave_frequencies.txt of the scene's waves, or None
    (none, still water asked, or waves that move the vessel only)."""
    w = scene.waves
    if w is None:
        return None
    if not waves:
        notes.append("The scene's waves are not in this deck: still water (MoorDyn's "
                     "statics, and the current's settling, run without them).")
        return None
    if not w.line_loads:
        notes.append("The scene's waves move the vessel only ([environment.waves] "
                     "line_loads = false): no WaveKin, the line in still water.")
        return None
    text, wave_notes = wave_file_text(scene)
    opts["wavekin"] = "7"
    notes.extend(wave_notes)
    if w.ramp > 0.0 and scene.current is None:
        opts["wavekin_rampt"] = repr(float(w.ramp))
        notes.append(f"waveKin_rampT = {w.ramp:g} s: MoorDyn-C ramps the water kinematics "
                     "linearly over it, the scene by a half cosine (the same after it).")
    elif w.ramp > 0.0:
        notes.append(f"The scene's ramp ({w.ramp:g} s) is not written: MoorDyn-C's "
                     "waveKin_rampT would ramp the current with the waves (measured on "
                     "2.7.2), so MoorDyn's waves start at full height at t = 0.")
    return text


_OPTION_NOTES = {
    "writelog": "- no log file", "g": "- gravity (m/s^2)", "rho": "- water density (kg/m^3)",
    "wtrdpth": "- water depth (m)", "kbot": "- seabed stiffness (Pa/m) = scene k / d",
    "cbot": "- seabed damping (Pa-s/m) from the scene's fraction of critical",
    "frictioncoefficient": "- seabed friction coefficient",
    "currents": "- 1: steady current from current_profile.txt in this folder",
    "tmaxic": "- max time of the IC generation (s)",
    "threshic": "- IC convergence threshold (m/s^2)", "dtic": "- IC check interval (s)",
    "wavekin": "- 7: summed wave components from wave_frequencies.txt in this folder",
    "wavekin_rampt": "- linear ramp of the water kinematics (s)"}


def _options(scene: Scene, deck: Deck, sec0: tuple, depth: float, notes: list[str],
             ic: dict | None) -> dict:
    d0, m0, *_ = sec0
    opts = {"writelog": "0", "g": repr(scene.gravity), "rho": repr(scene.water_density),
            "wtrdpth": repr(float(depth))}
    if scene.seabed is None:
        opts.update(kbot="0", cbot="0")
        notes.append("The scene has no seabed: kBot = 0 (no contact).")
    else:
        k = scene.seabed.stiffness
        opts["kbot"] = repr(k / d0)
        # the same critical damping as the importer reads back: 2 zeta sqrt(k (m + m_a))
        madd = sec0[5] * scene.water_density * math.pi / 4.0 * d0 * d0
        opts["cbot"] = repr(2.0 * scene.seabed.damping * math.sqrt(k * (m0 + madd)) / d0)
        if scene.seabed.friction:
            opts["frictioncoefficient"] = repr(scene.seabed.friction)
        if any(abs(lt.diameter - d0) > 1e-12 for lt in deck.line_types.values()):
            notes.append("kBot = k / d of the bottom line; MoorDyn's contact per metre is "
                         "kBot x d of each line, so another line on the seabed would have "
                         "another stiffness there.")
    if scene.current is not None:
        opts["currents"] = "1"
    for key, value in {**IC_OPTIONS, **(ic or {})}.items():
        opts[key.lower()] = repr(float(value))
    return opts


def _current_profile(scene: Scene, depth: float) -> str:
    """MoorDyn's current_profile.txt: three header lines, then 'z ux uy uz' rows, the
    velocity's components at each of the scene's heights (MoorDyn interpolates them
    component by component, as the scene does: :meth:`riser.physics.environment.Current.velocity`),
    the scene's (x, z) mapped to MoorDyn's (X, -Y)."""
    cur = scene.current
    if cur.turns:
        what = ("turning with depth, headings " + ", ".join(f"{h:g}" for h in cur.headings)
                + " deg")
        ux, uz = cur.components
        rows = zip(cur.heights, ux, uz)
    else:       # one heading: today's arithmetic, the same digits as before 3D scenes
        what = f"speeds along heading {cur.heading_deg:g} deg"
        h = math.radians(cur.heading_deg)
        rows = ((y, u * math.cos(h), u * math.sin(h)) for y, u in zip(cur.heights, cur.speeds))
    lines = ["--------------------- MoorDyn steady currents File ---------------------",
             f"Current of scene {scene.name}: {what}, piecewise linear in depth, constant "
             "beyond",
             "z (m), ux (m/s), uy (m/s), uz (m/s)"]
    for y, ux, uz in rows:
        lines.append(f"{y - depth!r} {float(ux)!r} {-float(uz)!r} 0.0")
    return "\n".join(lines) + "\n"


# ------------------------------------------------------------------ the deck's text
def _g(v: float) -> str:
    """A number written to full double precision (round-trips exactly), short when it can."""
    return repr(float(v)) if v != int(v) or abs(v) >= 1e15 else str(int(v))


def format_deck(deck: Deck, *, comments: list[str] = (), option_notes: dict | None = None
                ) -> str:
    """The text of a v2 deck. ``comments`` go into the front matter; ``option_notes`` maps
    an option key to its description text."""
    notes = option_notes or {}
    out = ["--------------------- MoorDyn Input File ------------------------------------"]
    out += [f for f in deck.front if f.strip() and not f.strip().startswith("---")]
    out += [f"! {c}" if c else "!" for c in comments]
    out.append("---------------------- LINE TYPES ----------------------------------------"
               "----------------")
    out.append("TypeName   Diam   Mass/m   EA   BA/-zeta   EI   Cd   Ca   CdAx   CaAx")
    out.append("(name)     (m)    (kg/m)   (N)  (N-s/-)   (N-m^2) (-)  (-)  (-)    (-)")
    for lt in deck.line_types.values():
        out.append("  ".join([lt.name, _g(lt.diameter), _g(lt.mass), _g(lt.EA), lt.BA,
                              _g(lt.EI), _g(lt.Cd), _g(lt.Ca), _g(lt.CdAx), _g(lt.CaAx)]))
    out.append("---------------------- POINTS ------------------------------------------"
               "-----")
    out.append("ID   Attachment   X   Y   Z   Mass   Volume   CdA   Ca")
    out.append("(#)  (-)          (m) (m) (m) (kg)   (m^3)    (m^2) (-)")
    for p in deck.points:
        out.append("  ".join([str(p.id), p.attachment, _g(p.x), _g(p.y), _g(p.z),
                              _g(p.mass), _g(p.volume), _g(p.CdA), _g(p.Ca)]))
    out.append("---------------------- LINES -------------------------------------------"
               "-----")
    out.append("ID   LineType   AttachA   AttachB   UnstrLen   NumSegs   LineOutputs")
    out.append("(#)  (name)     (#)       (#)       (m)        (-)       (-)")
    for ln in deck.lines:
        out.append("  ".join([str(ln.id), ln.line_type, ln.attach_a, ln.attach_b,
                              _g(ln.length), str(ln.segments), ln.outputs]))
    out.append("---------------------- OPTIONS -----------------------------------------")
    for k, (value, _) in deck.options.items():
        key = OPTION_KEYS[k]
        out.append(f"{value:<24} {key:<12} {notes.get(k, '')}".rstrip())
    out.append("---------------------- OUTPUTS -----------------------------------------")
    out += deck.outputs
    out.append("------------------------- need this line --------------------------------")
    return "\n".join(out) + "\n"

"""A scene -> an OrcaFlex text data file (``riser-verify export-orcaflex``): the line and
its environment as OrcaFlex loads them, so that OrcaFlex can be run on exactly what the
suite solved. Written as text (no YAML library needed), in OrcaFlex's units system
``SI`` (m, te, s, kN), its keys and its table layout; the import
(:mod:`riser.io.orcaflex.scene_from_model`) reads it back to the same scene (the round
trip: tests/test_orcaflex_round_trip.py).

Mapping, the inverse of the import (frames: :mod:`.frame`): OrcaFlex's X = the scene's x,
Y = -z, Z = y - water_depth (the surface at Z = 0); OrcaFlex's seabed is the scene's
lowered by the bottom line type's contact radius r (its contact is at the line's outer
surface), at depth water_depth + r; End A is the hang-off (``Fixed``, or on a vessel),
End B the anchor (``Anchored`` at r above the seabed with a ``[seabed]``, ``Fixed``
without, or ``Free``); the sections run from End A. A segment whose weight the line type
alone does not give (``buoyancy``, ``submerged_weight``, ``weight_scale``, a
``hydro_diameter`` of its own, a line type's ``submerged_weight``) gets a line type of
its own with the displacement diameter that gives that weight, its normal and axial drag
diameters at the scene's hydrodynamic diameter, Ca scaled to the scene's added mass and
its contact diameter at the line type's OD: the same weight, drag, added mass and seabed
contact per metre. Contents of one density on every line type are the line's contents;
otherwise they are added to each line type's mass per length (the same mass and weight).

Refused (one line naming the scene key, exit 2): a touchdown end form (a, b, d: export the
fixed-ends scene), a tensioner, the inextensible or rigid-seabed model, a line type
without EA or with axial damping, internal flow, a prescribed top motion, structural
damping, a current turning with depth, a spread or tabulated sea, a scene without a water
depth (OrcaFlex needs its surface). Not written, said in the file's header: the design
checks, the methods' settings other than the element length, the output stations.
"""

from __future__ import annotations

import math

from ...errors import SceneError
from ...model.ends import FixedEnds
from ...model.scene import Scene
from ...model.sections import segment_properties

#: OrcaFlex's gravity in its SI units system [m/s2]
GRAVITY = 9.80665
#: OrcaFlex's units (SI): kg per te, N per kN (the import's factors)
TE, KN = 1000.0, 1000.0


def _num(v: float) -> str:
    """A float OrcaFlex reads back bit for bit (repr), Infinity for inf."""
    if math.isinf(v):
        return "Infinity" if v > 0 else "-Infinity"
    r = repr(float(v))
    return r[:-2] if r.endswith(".0") and "e" not in r else r


def exact(v: float, forward) -> float:
    """The float x nearest ``v`` / (the import's factor) for which the import's
    ``forward(x)`` gives back ``v`` bit for bit (a unit's factor rounds: 124869.42768 N m2
    written as 124.86942768 kN m2 would read back 1 ulp off), tried over the few floats
    around the plain quotient; that quotient when none does."""
    if v == 0.0 or not math.isfinite(v):
        return v
    x0 = v / forward(1.0) if forward(1.0) != 0.0 else v
    best, cand = x0, [x0]
    up = down = x0
    for _ in range(8):
        up, down = math.nextafter(up, math.inf), math.nextafter(down, -math.inf)
        cand += [up, down]
    for c in cand:
        if forward(c) == v:
            # the shortest repr among the candidates that round-trip
            best = min((d for d in cand if forward(d) == v), key=lambda d: len(repr(d)))
            break
    return best


def _si(v: float, factor: float) -> float:
    """``v`` [SI] in OrcaFlex's unit of ``factor`` [SI per unit], read back exactly."""
    return exact(v, lambda x: x * factor)


def _row(values) -> str:
    return "[" + ", ".join(v if isinstance(v, str) else _num(v) for v in values) + "]"


def _name(text: str) -> str:
    """A name as a YAML scalar OrcaFlex reads (quoted when it needs to be)."""
    safe = text and all(c.isalnum() or c in " _-.()+/\"" for c in text) and \
        text[0].isalpha() and text.strip() == text and ":" not in text
    if safe and text.lower() not in ("yes", "no", "true", "false", "on", "off", "null", "~"):
        return text
    return "'" + text.replace("'", "''") + "'"


def refuse(scene: Scene, key: str, why: str):
    raise SceneError(scene.source, key, f"cannot be exported to OrcaFlex: {why}")


def _check(scene: Scene) -> None:
    if not isinstance(scene.ends, FixedEnds):
        refuse(scene, "ends", "a touchdown end form; OrcaFlex's line has its two ends in "
               "place: give fixed ends (anchor, hang_off), e.g. the hang-off the BVP solves")
    if scene.ends.tensioner is not None:
        refuse(scene, "ends.tensioner", "a tensioner is not written (OrcaFlex models one "
               "with a winch or a link)")
    if scene.axial_model != "extensible":
        refuse(scene, "model.axial", "the inextensible limit (OrcaFlex's line stretches)")
    if scene.seabed is not None and scene.seabed_model == "rigid":
        refuse(scene, "model.seabed", "a rigid seabed (OrcaFlex's is elastic)")
    if scene.water_depth is None:
        refuse(scene, "environment.water_depth", "OrcaFlex needs a sea surface: give the "
               "water depth")
    if scene.internal_flow is not None:
        refuse(scene, "internal_flow", "internal flow is not written")
    if scene.current is not None and scene.current.headings_deg is not None:
        refuse(scene, "environment.current.headings_deg", "a current turning with depth "
               "(OrcaFlex interpolates its speed and direction, the scene its components)")
    d = scene.dynamics
    if d is not None and d.top_motion is not None:
        refuse(scene, "dynamics.top_motion", "a prescribed top motion is not written (a "
               "vessel moved by its RAOs is)")
    if d is not None and d.damping > 0.0:
        refuse(scene, "dynamics.damping", "mass-proportional structural damping is not "
               "written")
    w = scene.waves
    if w is not None:
        sp = w.spectrum
        if sp is not None and (sp.kind == "table" or sp.spreading != "none" or
                               sp.omega_min is not None or sp.omega_max is not None):
            refuse(scene, "environment.waves.spectrum", "only a long-crested JONSWAP or "
                   "Pierson-Moskowitz sea on its default frequency range is written")
        if not w.line_loads:
            refuse(scene, "environment.waves.line_loads", "waves that load the vessel only")
    for name, lt in scene.line_types.items():
        if lt.axial_stiffness is None:
            refuse(scene, f"line_types.{name}.axial_stiffness", "OrcaFlex needs EA")
        if lt.axial_damping > 0.0:
            refuse(scene, f"line_types.{name}.axial_damping", "OrcaFlex has no axial "
                   "(Kelvin-Voigt) damping of this form")


def export_model(scene: Scene) -> tuple[str, list[str]]:
    """The OrcaFlex text data file of ``scene`` and the notes written in its header."""
    _check(scene)
    notes: list[str] = []
    depth = scene.water_depth
    segs = list(scene.segments)
    props = segment_properties(scene)
    bottom_lt = scene.line_types[segs[0].line_type]
    r = bottom_lt.outer_diameter / 2.0
    ends = scene.ends
    ax = list(ends.anchor) + [0.0] * (3 - len(ends.anchor))
    hx = list(ends.hang_off) + [0.0] * (3 - len(ends.hang_off))

    def glob(p):                         # the scene's (x, y, z) -> OrcaFlex's (X, Y, Z)
        return p[0], -p[2] if p[2] else 0.0, p[1] - depth

    g = scene.gravity
    if g != GRAVITY:
        notes.append(f"The scene's gravity {g:g} m/s2 is not OrcaFlex's standard 9.80665: "
                     "written in OrcaFlex's User units (m, te, kN) with g.")
    rho = scene.water_density
    contents = {scene.line_types[s.line_type].contents_density for s in segs}
    one_contents = len(contents) == 1
    # line types: the scene's, or one per segment whose weight or drag diameter differ
    types: dict[str, dict] = {}
    seg_types = []
    for k, (seg, p) in enumerate(zip(segs, props)):
        lt = scene.line_types[seg.line_type]
        D = lt.outer_diameter
        dh = seg.hydro_diameter or lt.hydro_diameter or D
        bore = lt.inner_diameter or 0.0
        m_cont = lt.contents_density * math.pi / 4.0 * bore * bore
        mass = lt.mass_per_length + (0.0 if one_contents else m_cont)
        m_all = lt.mass_per_length + m_cont
        own = (seg.buoyancy != 0.0 or seg.submerged_weight is not None or
               seg.weight_scale != 1.0 or seg.hydro_diameter is not None or
               lt.submerged_weight is not None)
        od = D
        if own:
            area = (m_all * g - p.weight) / (rho * g)       # displaced area [m2]
            if not area > 0.0:
                refuse(scene, f"segments[{k}]", f"its weight {p.weight:g} N/m exceeds its "
                       "mass's weight in air: no displacement diameter gives it")
            od = math.sqrt(4.0 * area / math.pi)
        name = seg.line_type if not own else f"{seg.line_type} (segment {k + 1})"
        if name not in types:
            types[name] = {
                "OD": od, "ID": bore if bore > 0.0 else None, "MassPerUnitLength": _si(mass, TE),
                "EA": _si(lt.axial_stiffness, KN), "EI": _si(lt.bending_stiffness, KN),
                "GJ": _si(lt.torsional_stiffness, KN),
                "Cd": (lt.drag_normal, lt.drag_tangential),
                "Ca": lt.added_mass * (dh / od) ** 2,
                "dh": dh, "contact": D if od != D else None,
                "MinRadius": lt.minimum_bend_radius}
        seg_types.append(name)
        if own:
            notes.append(f"segments[{k}]: line type '{name}' with OD {od:.12g} m (the "
                         f"displacement that gives its weight {p.weight:.12g} N/m), drag "
                         f"diameters {dh:.12g} m, Ca scaled to the scene's added mass, "
                         f"contact diameter {D:.12g} m.")
    if not one_contents:
        notes.append("The line types' contents differ: each one's contents mass is in its "
                     "MassPerUnitLength (OrcaFlex's contents are one per line).")
    out: list[str] = []
    w = out.append
    w("%YAML 1.1")
    w("# Type: Model")
    w(f"# Program: riser-verify export-orcaflex (scene {scene.name})")
    for n in _header_notes(scene, notes):
        w(f"# {n}")
    w("---")
    w("General:")
    if g == GRAVITY:
        w("  UnitsSystem: SI")
    else:                        # OrcaFlex's User units: SI's m, te, kN with the scene's g
        w("  UnitsSystem: User")
        w("  LengthUnits: m")
        w("  MassUnits: te")
        w("  ForceUnits: kN")
        w(f"  g: {_num(g)}")
    dyn = scene.dynamics
    waves = scene.waves
    tb = waves.ramp if waves is not None else 0.0
    if dyn is not None:
        w("  StageDuration:")
        w(f"    - {_num(tb if waves is not None else (dyn.statistics_start or 0.0))}")
        rest = dyn.duration - (tb if waves is not None else (dyn.statistics_start or 0.0))
        w(f"    - {_num(rest)}")
        if dyn.output_interval:
            w(f"  TargetLogSampleInterval: {_num(dyn.output_interval)}")
    elif waves is not None:
        w("  StageDuration:")
        w(f"    - {_num(tb)}")
        w(f"    - {_num(max(tb, 1.0))}")
    w("Environment:")
    w("  WaterSurfaceZ: 0")
    w(f"  Density: {_num(_si(rho, TE))}")
    w("  SeabedType: Flat")
    w("  SeabedOrigin: [0, 0]")
    w(f"  SeabedOriginDepth: {_num(depth + r)}")
    w("  SeabedSlopeDirection: 0")
    w("  SeabedSlope: 0")
    w("  SeabedModel: Elastic")
    sb = scene.seabed
    w(f"  SeabedNormalStiffness: {_num(_seabed_k(sb, bottom_lt))}")
    if sb is not None and sb.damping > 0.0:
        w(f"  SeabedDamping: {_num(sb.damping * 100.0)}")
    if waves is not None:
        _write_waves(scene, w, tb, hx)
    c = scene.current
    if c is not None:
        w("  MultipleCurrentDataCanBeDefined: No")
        w("  CurrentModel: Variation scheme")
        w("  CurrentRamped: No")
        w("  VerticalCurrentVariationMethod: Interpolated")
        w("  RefCurrentSpeed: 1")
        w(f"  RefCurrentDirection: {_num(-c.heading_deg + 0.0)}")
        w("  CurrentDepth, CurrentFactor, CurrentRotation:")
        for h, v in sorted(zip(c.heights, c.speeds), key=lambda hv: -hv[0]):
            w(f"    - {_row([depth - h, v, 0.0])}")
    else:
        w("  RefCurrentSpeed: 0")
    w("  WindSpeed: 0")
    vessel = scene.vessel if waves is not None else None
    if vessel is not None:
        _write_vessel_type(scene, w)
    if vessel is not None:
        psi = -vessel.heading_deg + 0.0
        surge, heave, sway = vessel.hang_off_on_vessel
        local = (surge, -sway, heave)
        HX, HY, HZ = glob(hx)
        c_, s_ = math.cos(math.radians(psi)), math.sin(math.radians(psi))
        vx = HX - (c_ * local[0] - s_ * local[1])
        vy = HY - (s_ * local[0] + c_ * local[1])
        vz = HZ - local[2]
        w("Vessels:")
        w("  - Name: Vessel1")
        w("    VesselType: Vessel type1")
        w("    Draught: Draught1")
        w(f"    InitialPosition: {_row([vx, vy, vz])}")
        w(f"    Orientation: {_row([0.0, 0.0, psi])}")
        w("    IncludedInStatics: None")
        w("    PrimaryMotion: None")
        w("    SuperimposedMotion: RAOs + harmonics")
    if scene.attachments:
        w("ClumpTypes:")
        for i, a in enumerate(scene.attachments):
            w(f"  - Name: Clump{i + 1}")
            w(f"    Mass: {_num(_si(a.mass, TE))}")
            w(f"    Volume: {_num(a.volume)}")
            w(f"    Height: {_num(max(a.volume, 1e-3) ** (1.0 / 3.0))}")
            w("    AlignWith: Global axes")
            w(f"    DragArea: {_row([a.drag_area] * 3)}")
            w("    Cd: [1, 1, 1]")
            w(f"    Ca: {_row([a.added_mass_coefficient] * 3)}")
    w("LineTypes:")
    friction = sb.friction if sb is not None else 0.0
    for name, t in types.items():
        w(f"  - Name: {_name(name)}")
        w("    Category: General")
        w(f"    OD: {_num(t['OD'])}")
        w(f"    ID: {_num(t['ID']) if t['ID'] is not None else '~'}")
        w(f"    MassPerUnitLength: {_num(t['MassPerUnitLength'])}")
        w("    CompressionIsLimited: No")
        mr = t["MinRadius"]
        w(f"    MinRadius: [{_num(mr) if mr is not None else '~'}, ~]")
        w(f"    EI: [{_num(t['EI'])}, ~]")
        w(f"    EA: {_num(t['EA'])}")
        w(f"    GJ: {_num(t['GJ'])}")
        w(f"    OuterContactDiameter: {_num(t['contact']) if t['contact'] else '~'}")
        w(f"    Ca: [{_num(t['Ca'])}, ~, 0]")
        w("    Cm: [~, ~, ~]")
        w("    Cs: 0")
        w("    Ce: 0")
        w(f"    Cd: [{_num(t['Cd'][0])}, ~, {_num(t['Cd'][1])}]")
        w("    Cl: 0")
        dh = t["dh"]
        same = dh == t["OD"]
        w(f"    NormalDragLiftDiameter: {'~' if same else _num(dh)}")
        w(f"    AxialDragLiftDiameter: {'~' if same else _num(dh)}")
        w(f"    SeabedLateralFrictionCoefficient: {_num(friction)}")
        w("    SeabedAxialFrictionCoefficient: ~")
        w("    RayleighDampingCoefficients: (no damping)")
    _write_line(scene, w, types, seg_types, segs, glob, ax, hx, r, one_contents,
                vessel, contents)
    return "\n".join(out) + "\n", notes


def _seabed_k(sb, lt) -> float:
    """SeabedNormalStiffness [kN/m/m2] that the import multiplies back (x 1000 x the
    contact diameter) to the scene's stiffness [N/m2]; 0 without a seabed."""
    if sb is None:
        return 0.0
    d = lt.outer_diameter
    return exact(sb.stiffness, lambda x: x * KN * d)


def _header_notes(scene: Scene, notes: list[str]) -> list[str]:
    out = [f"Scene: {scene.name}" + (f" ({scene.title})" if scene.title else ""),
           "OrcaFlex's seabed is the scene's lowered by the bottom line type's contact "
           "radius (OrcaFlex's contact is at the outer surface, the scene's at the centre)."]
    if scene.design is not None:
        out.append("Not written: the [design] checks (OrcaFlex's code checks are set up in "
                   "its post-processing).")
    if scene.dynamics is not None and (scene.dynamics.stations or scene.dynamics.save_states):
        out.append("Not written: the output stations and states of [dynamics].")
    return out + notes


def _write_waves(scene: Scene, w, tb: float, hx) -> None:
    wv = scene.waves
    ox, oz = wv.origin if wv.origin is not None else (hx[0], hx[2])
    w(f"  KinematicStretchingMethod: {'Wheeler' if wv.stretching == 'wheeler' else 'Vertical'}"
      " stretching")
    w("  WaveTrains:")
    for i, tr in enumerate(wv.trains):
        omega = 2.0 * math.pi / tr.period
        t0 = math.radians(tr.phase_deg) / omega - tb
        w(f"    - Name: Wave{i + 1}")
        w("      WaveType: Airy")
        w(f"      WaveDirection: {_num(-tr.heading_deg + 0.0)}")
        w(f"      WaveHeight: {_num(tr.height)}")
        w(f"      WavePeriod: {_num(tr.period)}")
        w(f"      WaveOrigin: {_row([ox, -oz + 0.0])}")
        w(f"      WaveTimeOrigin: {_num(t0)}")
    sp = wv.spectrum
    if sp is not None:
        i = len(wv.trains)
        w(f"    - Name: Wave{i + 1}")
        if sp.kind == "jonswap":
            w("      WaveType: JONSWAP")
            w("      WaveJONSWAPParameters: Partially specified")
        else:
            w("      WaveType: ISSC")
        w(f"      WaveDirection: {_num(-sp.heading_deg + 0.0)}")
        w(f"      WaveHs: {_num(sp.hs)}")
        w(f"      WaveTp: {_num(sp.tp)}")
        if sp.kind == "jonswap":
            w(f"      WaveGamma: {_num(sp.gamma_used)}")
        w(f"      WaveOrigin: {_row([ox, -oz + 0.0])}")
        w(f"      WaveTimeOrigin: {_num(-tb)}")
        w(f"      WaveNumberOfComponents: {sp.components}")
        w(f"      WaveSeed: {sp.seed}")


def _write_vessel_type(scene: Scene, w) -> None:
    v = scene.vessel
    w("VesselTypes:")
    w("  - Name: Vessel type1")
    for k, d in (("RAOResponseUnits", "degrees"), ("RAOWaveUnit", "amplitude"),
                 ("WavesReferredToBy", "period (s)"), ("RAOPhaseConvention", "lags"),
                 ("RAOPhaseUnitsConvention", "degrees"),
                 ("RAOPhaseRelativeToConvention", "crest"), ("SurgePositive", "forward"),
                 ("SwayPositive", "port"), ("HeavePositive", "up"),
                 ("RollPositiveStarboard", "down"), ("PitchPositiveBow", "down"),
                 ("YawPositiveBow", "port"), ("Symmetry", "None")):
        w(f"    {k}: {d}")
    w("    Draughts:")
    w("      - Name: Draught1")
    w("        DisplacementRAOs:")
    w("          RAOOrigin: [0, 0, 0]")
    w("          PhaseOrigin: [~, ~, ~]")
    w("          RAOs:")
    cols = ", ".join(["RAOPeriodOrFrequency"] + [f"RAO{d}{p}" for d in
                                                  ("Surge", "Sway", "Heave", "Roll", "Pitch",
                                                   "Yaw") for p in ("Amp", "Phase")])
    for t in v.raos:
        w(f"            - RAODirection: {_num(-t.heading_deg + 0.0)}")
        w(f"              {cols}:")
        for i, T in enumerate(t.periods):
            row = [T]
            for dof in ("surge", "sway", "heave", "roll", "pitch", "yaw"):
                ph = getattr(t, f"{dof}_phase_deg")[i]
                if dof in ("sway", "pitch"):           # y = -sway, pitch = -pitch
                    ph -= 180.0
                row += [getattr(t, dof)[i], ph]
            w(f"                - {_row(row)}")


def _write_line(scene: Scene, w, types, seg_types, segs, glob, ax, hx, r, one_contents,
                vessel, contents) -> None:
    ends = scene.ends
    w("Lines:")
    w(f"  - Name: {_name(scene.name)}")
    w("    IncludeTorsion: Yes")
    w("    TopEnd: End A")
    w("    Representation: Finite element")
    w("    DragFormulation: Standard")
    w("    StaticsVIV: None")
    w("    DynamicsVIV: None")
    A = glob(hx)
    B = glob(ax)
    chord = tuple(b - a for a, b in zip(A, B))                 # A -> B
    rows = []
    for end, joint, pos, where in (("A", ends.hang_off_joint, A, hx),
                                   ("B", ends.anchor_joint, B, ax)):
        kind = joint.kind if joint is not None else "pinned"
        if kind in ("clamped", "spring") and joint.direction_deg is not None:
            d = math.radians(joint.direction_deg)
            vec = (-math.cos(d), 0.0, -math.sin(d))            # along s reversed: A -> B
            if abs(ax[2] - hx[2]) > 0.0:
                refuse(scene, f"ends.{'hang_off' if end == 'A' else 'anchor'}_joint",
                       "a joint of a 3D scene")
        else:
            vec = chord
        n = math.sqrt(sum(c * c for c in vec)) or 1.0
        vec = tuple(c / n for c in vec)
        dec = math.degrees(math.acos(max(-1.0, min(1.0, vec[2]))))
        az = math.degrees(math.atan2(vec[1], vec[0])) if abs(vec[2]) < 1.0 else 0.0
        if end == "A":
            if vessel is not None:
                psi = -vessel.heading_deg + 0.0
                surge, heave, sway = vessel.hang_off_on_vessel
                rows.append(["Vessel1", surge, -sway + 0.0, heave, az - psi, dec, 0.0, "~",
                             "~"])
            else:
                rows.append(["Fixed", *pos, az, dec, 0.0, "~", "~"])
        elif kind == "free":
            rows.append(["Free", *pos, az, dec, 0.0, "~", "~"])
        elif scene.seabed is not None:
            rows.append(["Anchored", pos[0], pos[1], where[1] + r, az, dec, 0.0, "~", "~"])
        else:
            rows.append(["Fixed", *pos, az, dec, 0.0, "~", "~"])
    w("    Connection, ConnectionX, ConnectionY, ConnectionZ, ConnectionAzimuth, "
      "ConnectionDeclination, ConnectionGamma, ConnectionReleaseStage, ConnectionzRelativeTo:")
    for row in rows:
        w(f"      - {_row(row)}")
    w("    ConnectionxBendingStiffness, ConnectionyBendingStiffness:")
    for joint in (ends.hang_off_joint, ends.anchor_joint):
        kind = joint.kind if joint is not None else "pinned"
        k = (math.inf if kind == "clamped" else
             exact(joint.rotational_stiffness, lambda x: x * KN * 180.0 / math.pi)
             if kind == "spring" else 0.0)
        w(f"      - [{_num(k)}, ~]")
    h = scene.vfife.element_length
    w("    LineType, Length, TargetSegmentLength:")
    for name, seg in reversed(list(zip(seg_types, segs))):
        w(f"      - [{_name(name)}, {_num(seg.length)}, {_num(h)}]")
    if scene.attachments:
        total = scene.total_length
        w("    AttachmentType, Attachmentx, Attachmenty, Attachmentz, AttachmentzRelativeTo:")
        for i, a in enumerate(scene.attachments):
            w(f"      - [Clump{i + 1}, 0, 0, {_num(total - a.s)}, End A]")
    w("    ContentsMethod: Uniform")
    rho_c = next(iter(contents)) if one_contents else 0.0
    w(f"    ContentsDensity: {_num(_si(rho_c, TE))}")
    w("    ContentsPressure: 0")
    w("    ContentsFlowRate: 0")
    w("    IncludedInStatics: Yes")
    w("    StaticsStep1: Catenary")
    w("    StaticsStep2: Full statics")

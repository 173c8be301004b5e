"""OrcaFlex's current, waves, the vessel's RAOs and the simulation's stages -> the scene's
``[environment.current]``, ``[environment.waves]``, ``[vessel]`` and ``[dynamics]``.

- Current (``CurrentModel: Variation scheme``, interpolated): the speed at each row is
  RefCurrentSpeed x CurrentFactor, at the height of the row's depth above the scene's
  seabed; one direction RefCurrentDirection + CurrentRotation for every row -> the
  scene's ``heading_deg`` (:mod:`.frame`). A row below the scene's seabed is replaced by
  the profile's value at the seabed (linear, as both interpolate). A profile whose
  direction turns with depth is refused: OrcaFlex interpolates the speed and the
  direction between rows, the scene the velocity's components.
- Waves: each ``Airy`` train -> a ``[[environment.waves.trains]]`` (height, period,
  heading, the phase lag at the waves' origin: OrcaFlex puts a crest at WaveOrigin at
  WaveTimeOrigin, its simulation starts at minus the build-up's duration, the scene's at
  0, so the lag is omega (WaveTimeOrigin + build-up)); a ``JONSWAP`` sea given by Hs, Tp
  and gamma (``WaveJONSWAPParameters: Partially specified``) or an ``ISSC`` sea given by
  Hs and Tp -> ``[environment.waves.spectrum]`` (the parameters exact; the scene's
  JONSWAP is normalised as DNV-RP-C205, its Hs within 0.2 % of the given for gamma <= 5;
  its components are the scene's equal frequency steps, not OrcaFlex's discretisation:
  another realisation of the sea). Stream-function, Stokes and cnoidal waves, spreading, time histories
  and other spectra are refused. The ramp: the build-up stage (OrcaFlex ramps the waves
  and the vessel's motion over it; the scene's ramp is a half-cosine).
- The vessel's displacement RAOs (the draught's ``DisplacementRAOs``), when the line hangs
  from a vessel moved by them (``PrimaryMotion: None``, superimposed motion by RAOs):
  OrcaFlex's conventions of its vessel type (units, phase lags or leads, relative to the
  crest or the trough, signs of each degree of freedom) converted to OrcaFlex's own, its
  symmetry expanded into tables, then to the scene's axes (surge, heave, sway = -y;
  pitch negated; headings negated: riser/physics/vessel.py). RAO rows at period 0 and
  at an infinite period are left out (said in the notes: below and beyond the scene's
  shortest and longest period its RAOs are constant).
- Dynamics: the stages' total duration, the build-up as ``statistics_start``, the log's
  sample interval as ``output_interval``.
"""

from __future__ import annotations

import math

from ..angles import wrap_deg
from .frame import Frame
from .text_file import Model, ModelError, get, number, table
from .units import Units


def _current_rows(env: dict, src: str):
    rows = table(env, ("CurrentDepth", "CurrentFactor"), src, "Environment")
    if rows is None:
        rows = [{"CurrentDepth": 0.0, "CurrentFactor": 1.0, "CurrentRotation": 0.0}]
    return rows


def max_current_speed(env: dict, u: Units, src: str) -> float:
    """The current's fastest speed [m/s] anywhere in its profile (0: none)."""
    ref = number(get(env, "RefCurrentSpeed"), src, "Environment.RefCurrentSpeed",
                 allow_none=True) or 0.0
    fac = [abs(number(get(r, "CurrentFactor"), src, "Environment.CurrentFactor"))
           for r in _current_rows(env, src)]
    return abs(ref) * u.length * max(fac)


def current(env: dict, frame: Frame, u: Units, src: str, notes: list[str]) -> dict | None:
    ref = number(get(env, "RefCurrentSpeed"), src, "Environment.RefCurrentSpeed",
                 allow_none=True) or 0.0
    if ref == 0.0:
        return None
    if str(get(env, "MultipleCurrentDataCanBeDefined", default="No")).lower() in ("yes",
                                                                                   "true"):
        raise ModelError(src, "Environment.MultipleCurrentDataCanBeDefined", "Yes: only "
                         "one current is read")
    model = get(env, "CurrentModel", default="Variation scheme")
    if str(model).lower() != "variation scheme":
        raise ModelError(src, "Environment.CurrentModel", f"{model!r}: only a current "
                         "profile (variation scheme) is read")
    method = get(env, "VerticalCurrentVariationMethod", "CurrentMethod",
                 default="Interpolated")
    if str(method).lower() != "interpolated":
        raise ModelError(src, "Environment.VerticalCurrentVariationMethod", f"{method!r}: "
                         "only an interpolated profile is carried (a power law is not)")
    if get(env, "HorizontalCurrentFactor") is not None:
        raise ModelError(src, "Environment.HorizontalCurrentFactor", "a current varying "
                         "horizontally is not carried")
    theta0 = number(get(env, "RefCurrentDirection"), src, "Environment.RefCurrentDirection",
                    allow_none=True) or 0.0
    rows = _current_rows(env, src)
    pts = []
    rot = set()
    for k, r in enumerate(rows):
        it = f"Environment.CurrentDepth[{k}]"
        d = number(get(r, "CurrentDepth"), src, it) * u.length
        f = number(get(r, "CurrentFactor"), src, it)
        rot.add(number(get(r, "CurrentRotation"), src, it, allow_none=True) or 0.0)
        pts.append((frame.depth - d, ref * u.length * f))   # height above the scene's seabed
    if len(rot) > 1:
        raise ModelError(src, "Environment.CurrentRotation", f"{sorted(rot)}: a current "
                         "turning with depth is not carried (OrcaFlex interpolates the speed "
                         "and the direction between rows, the scene the velocity's "
                         "components)")
    pts.sort()
    for k in range(1, len(pts)):
        if pts[k][0] == pts[k - 1][0]:
            raise ModelError(src, "Environment.CurrentDepth", "two rows at one depth")
    cut = [p for p in pts if p[0] > 0.0]
    below = [p for p in pts if p[0] <= 0.0]
    if below:
        if cut:
            (y0, v0), (y1, v1) = below[-1], cut[0]
            v_sb = v0 + (v1 - v0) * (0.0 - y0) / (y1 - y0)
        else:
            v_sb = below[-1][1]
        cut = [(0.0, v_sb)] + cut
        if len(below) > 1 or below[-1][0] < 0.0:
            notes.append("Current rows at or below the scene's seabed -> the profile's "
                         f"value there ({v_sb:.12g} m/s at height 0; linear, exact).")
    cut = [p for p in cut if p[0] <= frame.depth + 1e-9]
    heights = [min(p[0], frame.depth) for p in cut]
    theta = theta0 + rot.pop()
    out = {"heights": heights, "speeds": [p[1] for p in cut],
           "heading_deg": frame.direction(theta)}
    notes.append(f"Current: RefCurrentSpeed x CurrentFactor at each row's depth, direction "
                 f"{theta:g} deg (OrcaFlex, towards) -> heading {out['heading_deg']:.12g} deg "
                 "in the scene." + (" CurrentRamped: the scene's current is steady." if
                                    str(get(env, "CurrentRamped", default="No")).lower()
                                    in ("yes", "true") else ""))
    return out


def trains_of(env: dict) -> list[dict]:
    trains = get(env, "WaveTrains")
    if isinstance(trains, list):
        return trains
    if get(env, "WaveType") is not None:           # an older file: one train in Environment
        return [env]
    return []


def build_up(model: Model, src: str) -> float:
    """The build-up stage's duration [s] (stage 0), 0 without stages."""
    general = model.section("General") or {}
    stages = get(general, "StageDuration")
    if isinstance(stages, list) and stages:
        return number(stages[0], src, "General.StageDuration[0]")
    return 0.0


def waves(model: Model, env: dict, frame: Frame, u: Units, src: str,
          notes: list[str]) -> dict | None:
    trains = trains_of(env)
    if not trains:
        return None
    tb = build_up(model, src)
    out: dict = {"trains": []}
    origins = set()
    stretch = str(get(env, "KinematicStretchingMethod", default="Vertical stretching")).lower()
    for k, t in enumerate(trains):
        it = f"Environment.WaveTrains[{get(t, 'Name', default=k)}]"
        kind = str(get(t, "WaveType"))
        low = kind.lower()
        direction = number(get(t, "WaveDirection", default=0.0), src, f"{it}.WaveDirection")
        heading = frame.direction(direction)
        ox, oy = (get(t, "WaveOrigin") or [0.0, 0.0])[:2]
        origins.add((number(ox, src, f"{it}.WaveOrigin") * u.length,
                     number(oy, src, f"{it}.WaveOrigin") * u.length))
        t0 = number(get(t, "WaveTimeOrigin", default=0.0), src, f"{it}.WaveTimeOrigin")
        for key in ("WaveNumberOfSpectralDirections", "WaveDirectionSpreadingExponent"):
            n = get(t, key)
            if n is not None and key.endswith("Directions") and number(n, src, it) > 1:
                raise ModelError(src, f"{it}.{key}", f"{n}: a spread sea is not carried")
        if low == "airy":
            H = number(get(t, "WaveHeight"), src, f"{it}.WaveHeight") * u.length
            T = number(get(t, "WavePeriod"), src, f"{it}.WavePeriod")
            lag = math.degrees(2.0 * math.pi / T * (t0 + tb))
            out["trains"].append({"height": H, "period": T, "heading_deg": heading,
                                  "phase_deg": wrap_deg(lag)})
        elif low in ("jonswap", "issc"):
            if "spectrum" in out:
                raise ModelError(src, it, "a second irregular sea: the scene holds one")
            hs = number(get(t, "WaveHs"), src, f"{it}.WaveHs") * u.length
            tp = number(get(t, "WaveTp"), src, f"{it}.WaveTp", allow_none=True)
            if tp is None:
                raise ModelError(src, f"{it}.WaveTp", "the sea's peak period is not given "
                                 "(only Tz): give Tp")
            sp: dict = {"kind": "jonswap" if low == "jonswap" else "pierson-moskowitz",
                        "hs": hs, "tp": tp, "heading_deg": heading}
            if low == "jonswap":
                par = str(get(t, "WaveJONSWAPParameters", default="Partially specified"))
                if par.lower() != "partially specified":
                    raise ModelError(src, f"{it}.WaveJONSWAPParameters", f"{par!r}: only a "
                                     "JONSWAP sea given by Hs, Tp and gamma (Partially "
                                     "specified) is carried")
                sp["gamma"] = number(get(t, "WaveGamma"), src, f"{it}.WaveGamma")
            n = get(t, "WaveNumberOfComponents")
            if n is not None:
                sp["components"] = int(number(n, src, f"{it}.WaveNumberOfComponents"))
            seed = get(t, "WaveSeed")
            if seed is not None:
                sp["seed"] = int(number(seed, src, f"{it}.WaveSeed"))
            out["spectrum"] = sp
            notes.append(f"{it}: a {kind} sea (Hs {hs:g} m, Tp {tp:g} s"
                         + (f", gamma {sp['gamma']:g}" if "gamma" in sp else "")
                         + "): the scene's spectrum of these parameters (a JONSWAP "
                         "normalised as DNV-RP-C205, 1 - 0.287 ln gamma: its Hs within 0.2 % "
                         "of the given for gamma <= 5, not OrcaFlex's normalisation digit for "
                         "digit), its own components (equal frequency steps) and random "
                         "phases: another realisation than OrcaFlex's.")
        else:
            raise ModelError(src, f"{it}.WaveType", f"{kind!r}: the scene's waves are Airy "
                             "trains and JONSWAP or ISSC seas (a nonlinear regular wave, "
                             "another spectrum or a time history is not carried); import "
                             "with --statics to leave the waves out")
    if len(origins) > 1:
        raise ModelError(src, "Environment.WaveTrains", "the trains have different "
                         "WaveOrigin: the scene refers every phase to one origin")
    if not out["trains"]:
        del out["trains"]
    (OX, OY), = origins
    out["origin"] = list(frame.plan(OX, OY))
    if "wheeler" in stretch:
        out["stretching"] = "wheeler"
    elif "vertical" in stretch:
        out["stretching"] = "vertical"
    else:
        raise ModelError(src, "Environment.KinematicStretchingMethod", f"{stretch!r}: the "
                         "scene's stretching is Wheeler or vertical")
    if tb > 0.0:
        out["ramp_time"] = tb
    cut = get(env, "WaveKinematicsCutoffDepth")
    if cut is not None and not math.isinf(number(cut, src, "Environment."
                                                           "WaveKinematicsCutoffDepth",
                                                 allow_inf=True)):
        raise ModelError(src, "Environment.WaveKinematicsCutoffDepth", f"{cut}: a cut-off "
                         "of the wave kinematics is not carried")
    notes.append(f"Waves: phases referred to WaveOrigin, the lag omega (WaveTimeOrigin + the "
                 f"build-up {tb:g} s): the scene's run starts where OrcaFlex's build-up "
                 "does; the ramp is the build-up (the scene's half-cosine).")
    return out


def dynamics(model: Model, u: Units, src: str, has_waves: bool,
             notes: list[str]) -> dict | None:
    """``[dynamics]`` from the stages, when the scene has waves."""
    if not has_waves:
        return None
    general = model.section("General") or {}
    stages = get(general, "StageDuration")
    if not isinstance(stages, list) or not stages:
        raise ModelError(src, "General.StageDuration", "the model has waves but no stages")
    dur = [number(s, src, "General.StageDuration") for s in stages]
    out = {"duration": sum(dur), "statistics_start": dur[0]}
    dt = number(get(general, "TargetLogSampleInterval"), src,
                "General.TargetLogSampleInterval", allow_none=True)
    if dt:
        out["output_interval"] = dt
    notes.append(f"Dynamics: the stages ({', '.join(f'{d:g}' for d in dur)} s) -> duration "
                 f"{sum(dur):g} s, statistics from the build-up's end ({dur[0]:g} s); "
                 "OrcaFlex's integration settings are not carried (the VFIFE's time step is "
                 "its own).")
    return out


# ------------------------------------------------------------------------- the vessel
#: OrcaFlex's own sign conventions (the vessel type's keys and their default values)
CONVENTIONS = {"SurgePositive": "forward", "SwayPositive": "port", "HeavePositive": "up",
               "RollPositiveStarboard": "down", "PitchPositiveBow": "down",
               "YawPositiveBow": "port"}
DOF = ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")


def vessel_motion(model: Model, top: dict, frame: Frame, u: Units, src: str,
                  has_waves: bool, notes: list[str]) -> dict | None:
    """``[vessel]`` when the hang-off is on a vessel moved by its RAOs in the waves."""
    if top.get("kind") != "vessel":
        return None
    name = top["vessel"]
    v = model.named("Vessels", name, "Connection")
    it = f"Vessels[{name}]"
    prim = str(get(v, "PrimaryMotion", default="None"))
    sup = str(get(v, "SuperimposedMotion", default="None"))
    if not has_waves:
        notes.append(f"The hang-off is on vessel {name}, held at its initial position (no "
                     "waves carried: its RAOs move nothing).")
        return None
    if prim.lower() != "none":
        raise ModelError(src, f"{it}.PrimaryMotion", f"{prim!r}: a vessel whose motion "
                         "OrcaFlex computes is not carried (the scene's vessel moves by its "
                         "RAOs alone)")
    if sup.lower() == "none":
        notes.append(f"Vessel {name}: no superimposed motion: the hang-off is fixed.")
        return None
    if "rao" not in sup.lower():
        raise ModelError(src, f"{it}.SuperimposedMotion", f"{sup!r}: only displacement "
                         "RAOs are carried")
    vt_name = str(get(v, "VesselType"))
    vt = model.named("VesselTypes", vt_name, f"{it}.VesselType")
    vit = f"VesselTypes[{vt_name}]"
    draughts = get(vt, "Draughts")
    if isinstance(draughts, list) and draughts:
        want = get(v, "Draught")
        dr = next((d for d in draughts if want is None or str(d.get("Name")) == str(want)),
                  None)
        if dr is None:
            raise ModelError(src, f"{it}.Draught", f"{want!r} is not a draught of {vt_name}")
        dit = f"{vit}.Draughts[{dr.get('Name')}]"
    else:
        dr, dit = vt, vit
    raos = get(dr, "DisplacementRAOs")
    if not isinstance(raos, dict):
        raise ModelError(src, f"{dit}.DisplacementRAOs", "the vessel type has no "
                         "displacement RAOs")
    po = get(raos, "PhaseOrigin")
    if isinstance(po, list) and any(p is not None for p in po):
        raise ModelError(src, f"{dit}.DisplacementRAOs.PhaseOrigin", f"{po}: phases "
                         "referred to a point other than the RAO origin are not carried")
    origin = [number(c, src, f"{dit}.DisplacementRAOs.RAOOrigin") * u.length
              for c in (get(raos, "RAOOrigin") or [0.0, 0.0, 0.0])]
    tables = _rao_tables(vt, raos, u, src, f"{dit}.DisplacementRAOs", notes)
    lx, ly, lz = (top["local"][i] - origin[i] for i in range(3))
    out = {"heading_deg": frame.direction(top["psi"]),
           "hang_off_on_vessel": [lx, lz, -ly],
           "raos": tables}
    notes.append(f"Vessel {name} ({vt_name}): heading {top['psi']:g} deg -> "
                 f"{out['heading_deg']:.12g} deg in the scene; the hang-off's lever arm from "
                 "the RAO origin in (surge, heave, sway = -y); RAOs to the scene's axes "
                 "(sway and pitch negated, headings negated).")
    return out


def _rao_tables(vt: dict, raos: dict, u: Units, src: str, item: str,
                notes: list[str]) -> list[dict]:
    """The scene's RAO tables of OrcaFlex's ``raos`` under the vessel type's conventions."""
    conv = {k: str(get(vt, k, default=d)).lower() for k, d in CONVENTIONS.items()}
    sign = [1.0 if conv[k] == d else -1.0 for k, d in CONVENTIONS.items()]
    resp = str(get(vt, "RAOResponseUnits", default="degrees")).lower()
    rot_unit = 1.0 if resp.startswith("deg") else 180.0 / math.pi
    wave = str(get(vt, "RAOWaveUnit", default="amplitude")).lower()
    per_amp = 1.0 if wave == "amplitude" else 2.0          # per wave height: x 2
    by = str(get(vt, "WavesReferredToBy", default="period (s)")).lower()
    lags = str(get(vt, "RAOPhaseConvention", default="lags")).lower() == "lags"
    ph_unit = 1.0 if str(get(vt, "RAOPhaseUnitsConvention",
                             default="degrees")).lower().startswith("deg") else 180 / math.pi
    rel = str(get(vt, "RAOPhaseRelativeToConvention", default="crest")).lower()
    if rel not in ("crest", "trough"):
        raise ModelError(src, f"{item}.RAOPhaseRelativeToConvention", f"{rel!r}: only "
                         "phases relative to the crest or the trough are read")
    shift = 0.0 if rel == "crest" else 180.0
    sym = str(get(vt, "Symmetry", default="None")).lower()
    if sym not in ("none", "xz plane", "yz plane", "xz and yz planes"):
        raise ModelError(src, f"{item}.Symmetry", f"{sym!r}: not a symmetry this import "
                         "expands")
    lst = get(raos, "RAOs")
    if not isinstance(lst, list) or not lst:
        raise ModelError(src, f"{item}.RAOs", "no RAO tables")
    cols = ["RAOPeriodOrFrequency"] + [f"RAO{d}{p}" for d in DOF for p in ("Amp", "Phase")]
    ofx: dict[float, list] = {}       # OrcaFlex's conventions: direction -> rows
    dropped = set()
    for k, t in enumerate(lst):
        d = number(get(t, "RAODirection"), src, f"{item}.RAOs[{k}].RAODirection")
        rows = table(t, tuple(cols), src, f"{item}.RAOs[{k}]")
        if rows is None:
            raise ModelError(src, f"{item}.RAOs[{k}]", "no RAO table (RAOPeriodOrFrequency, "
                             "RAOSurgeAmp, RAOSurgePhase, ...)")
        out = []
        for r in rows:
            x = number(get(r, cols[0]), src, f"{item}.RAOs[{k}]", allow_inf=True)
            if by.startswith("period"):
                T = x
            elif "rad/s" in by:
                T = math.inf if x == 0.0 else 2.0 * math.pi / x
            elif "hz" in by:
                T = math.inf if x == 0.0 else 1.0 / x
            else:
                raise ModelError(src, f"{item}.WavesReferredToBy", f"{by!r}: not read")
            if not (T > 0.0 and math.isfinite(T)):
                dropped.add("0" if T == 0.0 else "Infinity")
                continue
            vals = []
            for j, dof in enumerate(DOF):
                a = number(get(r, f"RAO{dof}Amp"), src, f"{item}.RAOs[{k}]") * per_amp
                p = number(get(r, f"RAO{dof}Phase"), src, f"{item}.RAOs[{k}]") * ph_unit
                p = (p if lags else -p) + shift
                if j >= 3:
                    a = a * rot_unit / u.length      # deg per file length -> deg/m
                if sign[j] < 0.0:
                    p += 180.0
                vals.append((a, p))
            out.append((T, vals))
        out.sort(key=lambda r: r[0])
        ofx[d] = out
    # symmetry: mirror images (OrcaFlex's axes): xz plane y -> -y: sway, roll, yaw negated
    mirrors = []
    if sym in ("xz plane", "xz and yz planes"):
        mirrors.append((lambda d: -d, (1, 3, 5)))
    if sym in ("yz plane", "xz and yz planes"):
        mirrors.append((lambda d: 180.0 - d, (0, 4, 5)))
    for f, neg in mirrors:
        for d, rows in list(ofx.items()):
            m = wrap_deg(f(d))
            if any(abs(wrap_deg(m - e)) < 1e-9 for e in ofx):
                continue
            ofx[m] = [(T, [(a, p + 180.0 if j in neg else p) for j, (a, p) in enumerate(v)])
                      for T, v in rows]
    if dropped:
        notes.append(f"RAO rows at period {' and '.join(sorted(dropped))} left out: the scene "
                     "holds its RAOs constant below its shortest and beyond its longest "
                     "period.")
    tables = []
    for d in sorted(ofx, key=lambda d: wrap_deg(-d)):
        rows = ofx[d]
        entry: dict = {"heading_deg": wrap_deg(-d), "periods": [T for T, _ in rows]}
        for j, name in enumerate(("surge", "sway", "heave", "roll", "pitch", "yaw")):
            flip = name in ("sway", "pitch")          # sway = -y, pitch = -pitch
            entry[name] = [v[j][0] for _, v in rows]
            entry[f"{name}_phase_deg"] = [v[j][1] + (180.0 if flip else 0.0)
                                          for _, v in rows]
        tables.append(entry)
    return tables

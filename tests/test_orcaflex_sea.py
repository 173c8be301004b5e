"""Issue 51: the waves and the vessel's RAOs of an OrcaFlex model, imported, move the
scene's hang-off and its sea as OrcaFlex's conventions say (riser/io/orcaflex/sea.py),
checked against the motion worked by hand in OrcaFlex's own terms, not through the
import's formulas:

- OrcaFlex's wave (Orcina, "Wave data"): a train of direction theta (the direction of
  travel, from global X towards Y) puts a crest at WaveOrigin at WaveTimeOrigin; its
  simulation starts at minus the build-up stage, the scene's at 0;
- OrcaFlex's vessel ("Vessel types: conventions"): x forward, y to port, z up; pitch a
  rotation about y, positive bow down; a displacement RAO (amplitude R, phase phi of the
  file's convention) gives the response R a cos(omega t - phi_lag) to a crest at the RAO
  origin at t = 0, phi_lag = phi (lags) or -phi (leads).

The model: a vessel at heading psi = 30 deg carrying End A at (40, 5, -8) in its axes
(from the RAO origin (0, 0, 0)), End B anchored at an azimuth of 200 deg from End A, a
wave travelling at 75 deg (45 deg off the bow, port side), and RAO tables in radians,
leads and frequency (rad/s), which the import converts to OrcaFlex's own (degrees, lags,
period). No solver runs.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from extras import needs_yaml

pytestmark = needs_yaml

PSI = 30.0                      # the vessel's heading [deg]
LOCAL = (40.0, 5.0, -8.0)       # End A in the vessel's axes [m]
THETA = 75.0                    # the wave's direction [deg]
BETA = THETA - PSI              # relative to the bow: 45 deg
H, T = 2.0, 10.0                # wave height [m] and period [s]
T0, TB = 1.5, 20.0              # WaveTimeOrigin, build-up [s]
OMEGA = 2.0 * math.pi / T
HEAVE = (0.8, 0.6)              # heave RAO [m/m] and its phase LEAD [rad]
PITCH = (0.02, -1.1)            # pitch RAO [rad/m] and its phase LEAD [rad]
SURGE = (0.3, 2.0)


def _rao_row(w: float) -> str:
    # RAOPeriodOrFrequency, then (amplitude, phase) of surge, sway, heave, roll, pitch, yaw
    return (f"[{w!r}, {SURGE[0]}, {SURGE[1]}, 0, 0, {HEAVE[0]}, {HEAVE[1]}, 0, 0, "
            f"{PITCH[0]}, {PITCH[1]}, 0, 0]")


def _model(tmp_path):
    # the RAOs are the same at every frequency given and at both directions 0 and 90: the
    # scene's interpolation (in period and heading) then gives exactly these numbers at
    # the wave's period and relative direction 45 deg
    rows = "\n".join(f"              - {_rao_row(w)}" for w in (0.2, 0.5, 1.0, 2.0))
    col = ("RAOPeriodOrFrequency, RAOSurgeAmp, RAOSurgePhase, RAOSwayAmp, RAOSwayPhase, "
           "RAOHeaveAmp, RAOHeavePhase, RAORollAmp, RAORollPhase, RAOPitchAmp, RAOPitchPhase, "
           "RAOYawAmp, RAOYawPhase")
    tables = "\n".join(f"          - RAODirection: {d}\n            {col}:\n{rows}"
                       for d in (0, 90))
    c, s = math.cos(math.radians(PSI)), math.sin(math.radians(PSI))
    ax, ay = c * LOCAL[0] - s * LOCAL[1], s * LOCAL[0] + c * LOCAL[1]    # End A, global
    az = math.radians(200.0)
    bx, by = ax + 150.0 * math.cos(az), ay + 150.0 * math.sin(az)
    text = f"""%YAML 1.1
---
General:
  UnitsSystem: SI
  StageDuration:
    - {TB}
    - 60
  TargetLogSampleInterval: 0.5
Environment:
  WaterSurfaceZ: 0
  Density: 1.025
  SeabedType: Flat
  SeabedOriginDepth: 100
  SeabedSlope: 0
  SeabedModel: Elastic
  SeabedNormalStiffness: 100
  KinematicStretchingMethod: Wheeler stretching
  WaveTrains:
    - Name: Wave1
      WaveType: Airy
      WaveDirection: {THETA}
      WaveHeight: {H}
      WavePeriod: {T}
      WaveOrigin: [10, -20]
      WaveTimeOrigin: {T0}
  RefCurrentSpeed: 0
VesselTypes:
  - Name: VT
    RAOResponseUnits: radians
    RAOWaveUnit: amplitude
    WavesReferredToBy: frequency (rad/s)
    RAOPhaseConvention: leads
    RAOPhaseUnitsConvention: radians
    RAOPhaseRelativeToConvention: crest
    Symmetry: None
    Draughts:
      - Name: D1
        DisplacementRAOs:
          RAOOrigin: [0, 0, 0]
          PhaseOrigin: [~, ~, ~]
          RAOs:
{tables}
Vessels:
  - Name: V
    VesselType: VT
    Draught: D1
    InitialPosition: [0, 0, 0]
    Orientation: [0, 0, {PSI}]
    PrimaryMotion: None
    SuperimposedMotion: RAOs + harmonics
LineTypes:
  - Name: Pipe
    Category: General
    OD: 0.3
    ID: 0.2
    MassPerUnitLength: 0.1
    EI: [50, ~]
    EA: 500e3
    Cd: [1.2, ~, 0.008]
    Ca: [1, ~, 0]
Lines:
  - Name: Riser
    Connection, ConnectionX, ConnectionY, ConnectionZ:
      - [V, {LOCAL[0]}, {LOCAL[1]}, {LOCAL[2]}]
      - [Anchored, {bx!r}, {by!r}, 0.15]
    LineType, Length, TargetSegmentLength:
      - [Pipe, 180, 2]
"""
    path = tmp_path / "sea.yml"
    path.write_text(text)
    return path


def test_the_hang_off_moves_as_orcaflex_says(tmp_path):
    from riser.io.orcaflex.scene_from_model import import_model
    _, scene, _ = import_model(_model(tmp_path))
    v, w = scene.vessel, scene.waves
    # OrcaFlex by hand: per metre of wave amplitude, a crest at the RAO origin at t = 0,
    # response R cos(omega t - phi_lag), phi_lag = -lead. Pitch theta about the vessel's y
    # (port) moves the point r = LOCAL by theta (y x r) = theta (r_z, 0, -r_x): along the
    # bow by theta r_z and up by -theta r_x; surge along the bow; heave up
    lag = {k: -p for k, p in (("surge", SURGE[1]), ("heave", HEAVE[1]),
                              ("pitch", PITCH[1]))}
    along_bow = (SURGE[0] * np.exp(-1j * lag["surge"]) +
                 PITCH[0] * LOCAL[2] * np.exp(-1j * lag["pitch"]))
    up = HEAVE[0] * np.exp(-1j * lag["heave"]) - PITCH[0] * LOCAL[0] * np.exp(-1j * lag["pitch"])
    # the bow (cos psi, sin psi) in the scene's (x, z): x = (cos a, sin a), z = (sin a,
    # -cos a), a the plane's azimuth (from the anchor, at 200 deg from End A: 20 deg)
    a = math.radians(20.0)
    p = math.radians(PSI)
    bow = (math.cos(p) * math.cos(a) + math.sin(p) * math.sin(a),
           math.cos(p) * math.sin(a) - math.sin(p) * math.cos(a))
    want = np.array([along_bow * bow[0], up, along_bow * bow[1]])
    heading = w.trains[0].heading_deg
    got = v.hang_off_amplitudes([T], [heading])[:, 0]
    # the import's conversions are exact; the scene interpolates nothing here (equal
    # tables and rows): agreement to round-off of a few products, 1e-12 m per m
    assert np.allclose(got, want, rtol=0.0, atol=1e-12), (got, want)
    assert heading == pytest.approx(20.0 - THETA, abs=1e-12)     # alpha - theta


def test_the_wave_crest_passes_where_and_when_orcaflex_puts_it(tmp_path):
    # OrcaFlex: a crest at WaveOrigin (10, -20) at WaveTimeOrigin 1.5 s of its time, which
    # starts at -20 s (the build-up): the scene's elevation there at t = 1.5 + 20 s is the
    # crest (amplitude H/2), a quarter period later zero. The scene's elevation function
    # is the one its solvers load the line with
    from riser.io.orcaflex.scene_from_model import import_model
    from riser.physics.waves import elevation
    _, scene, _ = import_model(_model(tmp_path))
    comp = scene.waves.components(scene.water_depth, scene.gravity, (0.0, 0.0))
    ox, oz = scene.waves.origin
    t = T0 + TB
    assert scene.waves.ramp == TB                  # ramp ends at OrcaFlex's time 0 < t
    assert float(elevation(comp, ox, oz, t)) == pytest.approx(H / 2.0, abs=1e-9)
    assert float(elevation(comp, ox, oz, t + T / 4.0)) == pytest.approx(0.0, abs=1e-9)
    # the origin: OrcaFlex's (10, -20) in the scene's frame, whose x runs from the anchor
    # at 20 deg: a point the wave reaches a time (its distance along 75 deg) / c later
    assert scene.dynamics.duration == TB + 60.0 and scene.dynamics.statistics_start == TB
    assert scene.dynamics.output_interval == 0.5


def test_xz_symmetry_mirrors_the_tables_as_orcaflex_does(tmp_path):
    # Symmetry: xz plane: a table at direction d stands for -d too, with sway, roll and
    # yaw (the motions that change sign in the mirror y -> -y) reversed. The scene's
    # headings are OrcaFlex's negated, and its sway is OrcaFlex's -y: at +45 and -45 deg
    # the heave and the surge are the same, the sway reversed
    from riser.io.orcaflex.scene_from_model import import_model
    path = _model(tmp_path)
    text = path.read_text().replace("Symmetry: None", "Symmetry: xz plane")
    # give the 90 deg table a sway of 0.5 (lead 0.3 rad)
    lines = text.splitlines()
    out, in90 = [], False
    for ln in lines:
        if "RAODirection: 90" in ln:
            in90 = True
        if ln.startswith("Vessels:"):
            in90 = False
        if in90 and ln.strip().startswith("- ["):
            vals = ln.strip()[3:-1].split(", ")
            vals[3], vals[4] = "0.5", "0.3"
            ln = ln[:ln.index("- [") + 3] + ", ".join(vals) + "]"
        out.append(ln)
    path.write_text("\n".join(out) + "\n")
    _, scene, _ = import_model(path)
    tabs = {round(t.heading_deg, 9): t for t in scene.vessel.raos}
    assert set(tabs) == {0.0, -90.0, 90.0}          # 0 (its own mirror), 90 and its mirror
    r_a = tabs[-90.0].complex_rao([T])[:, 0]        # OrcaFlex's +90: scene -90
    r_b = tabs[90.0].complex_rao([T])[:, 0]         # its mirror
    assert r_a[2] == pytest.approx(r_b[2], abs=1e-12)          # heave
    assert r_a[0] == pytest.approx(r_b[0], abs=1e-12)          # surge
    assert r_a[1] == pytest.approx(-r_b[1], abs=1e-12)         # sway reversed
    assert abs(r_a[1]) == pytest.approx(0.5, abs=1e-12)

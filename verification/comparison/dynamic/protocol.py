"""The dynamic comparison: the frequency-domain response about the BVP static state
(:mod:`bvp.frequency.harmonic`) against the first harmonic of the VFIFE's time domain, for a
harmonic hang-off motion, over a sweep of amplitudes.

Both methods solve the same fixed-ends scene (a touchdown form converted once, as in the
static protocol) with the same motion d(t) = A sin(2 pi t / T) along one axis. The VFIFE
run: a half-cosine ramp of :data:`RAMP_PERIODS` periods, or :data:`RAMP_FUNDAMENTALS`
times the line's longest natural period if longer (:func:`ramp_periods`);
:data:`SETTLE_PERIODS` periods for the start-up transient to decay (drag is the only
damping of a still-water line, and at small amplitude it is light: a transient of the
lowest modes lasts tens of periods), doubled while the window's two halves disagree
(:data:`.rows.DRIFT_LIMIT`; the run continued, :mod:`.vfife_side`); then
a window of :data:`WINDOW_PERIODS` periods sampled :data:`SAMPLES_PER_PERIOD` times a
period; its statics are converged :data:`STATIC_TIGHTENING` times tighter than the
default, because the static residual is released as a free oscillation whose size does
not scale with the amplitude (measured on yu2021-a3 at 2 m elements: 15 mm of free motion
from the default tolerances, 1.5 mm at a tenth of them). At every node the window is
fitted by least squares (:mod:`..harmonics`): mean, first harmonic, 2nd and 3rd harmonics
and the envelope, so that the nonlinearity is measured, not hidden.

Rows (:mod:`.rows`; VFIFE against FD, each with its tolerance and reason): the hang-off
tension's first-harmonic amplitude and phase; along s, the largest difference of the
tension, bending moment and displacement amplitudes over the FD's peak (the moment outside
the contact zone: where the static line lies within the motion's reach of the seabed the
VFIFE's contact opens and closes, which the FD's fixed contact zone does not, so there
the difference is reported, not judged); the minimum tension over the cycle. Stations
(hang-off, touchdown, sag bends, crests): amplitude and phase of the tension, reported.
A response whose FD minimum tension goes below zero is slack over the cycle: outside the
linear model, named ``slack_over_cycle``, rows not judged.

A 3D static state (a current or a hang-off out of the ends' plane): the FD linearises the
BVP's 3D rod (:mod:`bvp.frequency.rod_harmonic`), and the moments of both sides are the 3D
profile's columns in and out of the ends' plane (riser.model.frame.plane_columns), read
off the time domains sample by sample (:func:`.vfife_side.moment_columns`); the rows and
their tolerances are the planar protocol's (measured on scr-steel-current-90, heave and
sway of 0.1 m at 14 s with 1 m elements: every judged row within them, the VFIFE's and
the ANCF's).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from riser.physics.dynamics import Dynamics, TopMotion
from riser.errors import SceneError, SolveFailed, UnsupportedSceneError
from riser.physics.hang_off_motion import motion_amplitudes
from riser.results.response import HarmonicResponse, harmonic_motion
from riser.results.result import Status
from riser.model.scene import FixedEnds, Scene
from verification.methods import method
from verification.pipeline import vfife_equivalent

from .rows import ABOVE_SMALLEST, agreement_rows, nonlinearity, station_rows
from . import ancf_side
from .vfife_side import SETTLE_PERIODS, settled_run

RAMP_PERIODS = 3
#: the ramp lasts at least this many of the line's longest natural period (see
#: :func:`ramp_periods`)
RAMP_FUNDAMENTALS = 2.0
WINDOW_PERIODS = 12
SAMPLES_PER_PERIOD = 40
#: the VFIFE's static tolerances (force, tension, moment, creep) times this
STATIC_TIGHTENING = 0.1
#: the shortest period as a multiple of the time a transverse wave takes over one VFIFE
#: element: below ~20 elements a wavelength the lumped masses misrepresent the wave
MIN_ELEMENTS_PER_WAVE = 20

@dataclass
class AmplitudeResult:
    """One amplitude of the sweep: the FD response, the VFIFE's fit, the rows."""

    amplitude: float
    fd: HarmonicResponse
    vf: dict
    rows: list
    stations: list
    nonlinearity: dict
    warnings: list = field(default_factory=list)
    vfife_wall_s: float = 0.0
    fd_wall_s: float = 0.0
    #: the ANCF's time domain judged like the VFIFE (None: not run), its rows, wall
    #: time [s] and run figures (element length, time step, Newton iterations a step)
    ancf: dict | None = None
    ancf_rows: list = field(default_factory=list)
    ancf_wall_s: float = 0.0
    ancf_info: dict = field(default_factory=dict)

    @property
    def passed(self) -> bool:
        return all(r["pass"] is not False for r in self.rows + self.ancf_rows)


@dataclass
class DynamicComparison:
    """The dynamic comparison of one scene: the motion (axis, period), the results per
    amplitude, the static BVP result it linearised about, notes."""

    scene: Scene
    matched: Scene
    axis: str
    period: float
    element_length: float
    results: list
    static: object
    notes: list = field(default_factory=list)

    @property
    def passed(self) -> bool:
        return all(r.passed for r in self.results)


#: the ``axis`` of a comparison driven by a regular wave (and the vessel's motion in it)
WAVE = "wave"
#: the axis label of a comparison driven by an orbit (a harmonic motion along several
#: axes, [dynamics.top_motion] amplitudes); its amplitudes scale the orbit by its
#: largest axis amplitude
ORBIT = "orbit"


def is_wave(scene: Scene) -> bool:
    """True when the comparison is driven by the scene's waves (a regular train)."""
    return scene.waves is not None


def wave_scene(scene: Scene, amplitude: float, ramp_time: float | None = None) -> Scene:
    """``scene`` with its one regular train at ``amplitude`` [m] (half the height) and the
    waves' ramp ``ramp_time`` [s] (None: unchanged)."""
    w = scene.waves
    tr = w.trains[0].replace(height=2.0 * amplitude)
    new = w.replace(trains=(tr,), ramp_time=w.ramp_time if ramp_time is None else ramp_time)
    return scene.replace(waves=new)


def require_one_drive(scene: Scene) -> None:
    """Refuse a top motion beside the waves (SceneError naming the key): a comparison in
    waves has one drive, the waves, with a [vessel] for the hang-off's motion."""
    if scene.dynamics is not None and scene.dynamics.top_motion is not None:
        raise SceneError(scene.source, "dynamics.top_motion", "not with waves in the "
                         "dynamic comparison (one drive: the waves, with a [vessel] for "
                         "the hang-off's motion)")


def check_waves(scene: Scene, amplitudes=None) -> tuple[str, float, list[float]]:
    """(:data:`WAVE`, period [s], the wave amplitudes [m] sorted) of a comparison driven
    by the scene's one regular train: every amplitude checked before solving (the
    train's own limits, the frequency domain's line in the water). An irregular sea is
    compared by :mod:`..sea.protocol`; several trains or a top motion beside the waves are
    refused (one period, one drive). SceneError naming the key (exit 2)."""
    w = scene.waves
    if w.spectrum is not None or len(w.trains) != 1:
        raise SceneError(scene.source, "environment.waves", "the harmonic comparison takes "
                         "one regular train (an irregular sea: its own comparison, several "
                         "trains: one at a time)")
    require_one_drive(scene)
    tr = w.trains[0]
    amps = sorted(amplitudes) if amplitudes else [0.5 * tr.height]
    for a in amps:
        ws = wave_scene(scene, a)                        # its checks, its key
        if isinstance(scene.ends, FixedEnds):
            method("bvp").require_wave(ws)
    return WAVE, tr.period, amps


def check_motions(scene: Scene, amplitudes=None) -> tuple[str, float, list[float]]:
    """(axis, period [s], the amplitudes [m] sorted) of the comparison, every amplitude
    checked before anything is solved: a harmonic motion (:func:`riser.results.response.
    harmonic_motion`), plausible (the top motion's own limits) and, for fixed ends, the
    frequency domain's (the hang-off kept in the water); a scene with waves: its regular
    train (:func:`check_waves`, axis :data:`WAVE`, wave amplitudes). SceneError /
    UnsupportedSceneError naming the key (exit 2)."""
    if is_wave(scene):
        return check_waves(scene, amplitudes)
    tm = scene.dynamics.top_motion if scene.dynamics is not None else None
    if tm is not None and tm.is_orbit:
        axis, amp0, period = ORBIT, max(tm.amplitudes), tm.period
    else:
        axis, amp0, period = harmonic_motion(scene)
    amps = sorted(amplitudes) if amplitudes else [amp0]
    for a in amps:
        if axis == ORBIT:                                          # its checks, its key
            scene.replace(**{"dynamics.top_motion.amplitudes": orbit_amplitudes(tm, a)})
        else:
            scene.replace(**{"dynamics.top_motion.amplitude": a})
        if isinstance(scene.ends, FixedEnds):
            method("bvp").require_harmonic(scene, motion_vector(scene, axis, a))
    return axis, period, amps


def orbit_amplitudes(tm: TopMotion, a: float) -> tuple[float, ...]:
    """The orbit's (x, y, z) amplitudes [m] scaled so that the largest is ``a`` [m]."""
    f = a / max(tm.amplitudes)
    return tuple(f * v for v in tm.amplitudes)


def motion_vector(scene: Scene, axis: str, a: float) -> np.ndarray:
    """(3,) complex amplitudes [m] of the comparison's motion at amplitude ``a`` [m]:
    along ``axis``, or the scene's orbit scaled to ``a`` (:data:`ORBIT`)."""
    if axis != ORBIT:
        return motion_amplitudes(axis, a)
    tm = scene.dynamics.top_motion
    return tm.complex_amplitudes() * (a / max(tm.amplitudes))


def check_period(scene: Scene, period: float, element_length: float, static) -> None:
    """Refuse a period shorter than :data:`MIN_ELEMENTS_PER_WAVE` VFIFE elements per
    transverse wavelength at the lowest tension of the suspended line (SceneError naming
    the key)."""
    p = static.profile
    m = max(scene.line_types[s.line_type].mass_per_length for s in scene.segments)
    hung = p.s >= (p.tdp_s or 0.0)               # on the seabed no transverse wave runs
    t_low = max(float(np.min(p.tension[hung])), 1e-3 * float(np.max(p.tension)))
    wave = math.sqrt(t_low / m) * period
    if wave < MIN_ELEMENTS_PER_WAVE * element_length:
        shortest = MIN_ELEMENTS_PER_WAVE * element_length / math.sqrt(t_low / m)
        raise SceneError(scene.source, "dynamics.top_motion.period", f"{period:g} s makes a "
                         f"transverse wave of {wave:.3g} m at the lowest tension, fewer than "
                         f"{MIN_ELEMENTS_PER_WAVE} VFIFE elements of {element_length:g} m; "
                         f"must be >= {shortest:.3g} s (or refine [vfife] element_length)")


def ramp_periods(scene: Scene, period: float, static) -> tuple[int, float | None]:
    """(ramp length in periods, the line's longest natural period [s]): at least
    :data:`RAMP_PERIODS`, and :data:`RAMP_FUNDAMENTALS` times the longest natural period
    (the first in-plane or out-of-plane mode of the BVP's modal analysis about the same
    static state). Why: the harmonic response shifts the line's mean position (at second
    order); a ramp short against the lowest natural period switches that shift on
    suddenly and rings the lowest modes, which the drag of a small amplitude hardly damps
    (measured on yu2021-a3, lowest period 149 s, heave 0.1 m at 12.4 s: a 3-period ramp
    left the moment 7 % of its peak off after 36 periods; a ramp of 24 periods, 0.9 %)."""
    modes = method("bvp").modes(scene, 1, static=static)
    longest = max((m.period_s for m in modes.modes), default=None)
    if longest is None:
        return RAMP_PERIODS, None
    return max(RAMP_PERIODS, math.ceil(RAMP_FUNDAMENTALS * longest / period)), longest


def dynamic_scene(scene: Scene, axis: str, amplitude: float, period: float,
                  settle: int = SETTLE_PERIODS, ramp: int = RAMP_PERIODS) -> Scene:
    """``scene`` with the protocol's [dynamics] (see the module docstring; a ``ramp`` of
    that many periods, ``settle`` periods between the ramp and the window) and tighter
    statics."""
    dyn = scene.dynamics
    total = (ramp + settle + WINDOW_PERIODS) * period
    if axis == ORBIT:
        tm = dyn.top_motion
        motion = TopMotion(amplitudes=orbit_amplitudes(tm, amplitude), period=period,
                           phases_deg=tm.phases_deg, ramp_time=ramp * period)
    else:
        motion = None if axis == WAVE else TopMotion(axis=axis, amplitude=amplitude,
                                                     period=period, ramp_time=ramp * period)
    new = Dynamics(duration=total, output_interval=period / SAMPLES_PER_PERIOD,
                   top_motion=motion, damping=dyn.damping if dyn is not None else 0.0,
                   statistics_start=(ramp + settle) * period,
                   save_states=True)
    if axis == WAVE:
        scene = wave_scene(scene, amplitude, ramp * period)
    return scene.replace(dynamics=new, **tightened_statics(scene))


def tightened_statics(scene: Scene) -> dict:
    """The VFIFE's static tolerances :data:`STATIC_TIGHTENING` times the scene's, as
    ``Scene.replace`` key paths (see the module docstring)."""
    vf, f = scene.vfife, STATIC_TIGHTENING
    return {"vfife.static_tolerance": vf.static_tolerance * f,
            "vfife.expert.tension_tolerance": vf.tension_tolerance * f,
            "vfife.expert.moment_tolerance": vf.moment_tolerance * f,
            "vfife.expert.creep_tolerance": vf.creep_tolerance * f}


def compare_dynamics(scene: Scene, *, amplitudes=None, element_length: float | None = None,
                     static=None, fd_modifier=None, vfife_modifier=None,
                     progress=None, ancf: bool | str = False) -> DynamicComparison:
    """Compare the scene's harmonic motion by both methods at each of ``amplitudes`` [m]
    (default the scene's). ``static``: the BVP static result of the matched scene (solved
    here when None). ``fd_modifier``/``vfife_modifier`` (Scene -> Scene) alter one
    method's scene only (the negative controls). ``ancf``: also run the ANCF's time
    domain and judge it against the FD like the VFIFE (:mod:`.ancf_side`): True at every
    amplitude, "first" at the first (the linear limit) only, False (the default: the
    callers that want it say so, ``compare --dynamics`` does) not. Raises
    SceneError for a scene the comparison cannot take (no harmonic motion, a period too
    short, the FD refusing), SolveFailed when a method fails."""
    now = progress or (lambda msg: None)
    axis, period, amps = check_motions(scene, amplitudes)
    eq = vfife_equivalent(scene)
    matched = eq.scene
    notes = [f"The scene was converted: {eq.note}."] if eq.note else []
    h = element_length or matched.vfife.element_length
    if static is None:
        now("bvp: static state")
        static = method("bvp").solve(matched)
    if not static.converged:
        raise SolveFailed("bvp", static.status, f"bvp statics: {static.message}")
    check_period(matched, period, h, static)
    now("bvp: the longest natural period (the ramp's length)")
    ramp, longest = ramp_periods(matched, period, static)
    notes.append(f"The ramp lasts {ramp} periods ({ramp * period:g} s): at least "
                 f"{RAMP_FUNDAMENTALS:g} times the longest natural period "
                 + (f"({longest:.4g} s)." if longest else "(the modal analysis failed: "
                    f"{RAMP_PERIODS} periods)."))
    if matched.seabed is not None and matched.seabed.friction > 0.0:
        notes.append(f"The seabed friction ({matched.seabed.friction:g}) is in the VFIFE only: "
                     "the frequency domain has the grounded line on vertical springs, free "
                     "along the seabed (a small-motion model); the difference near and on "
                     "the seabed includes it.")
    results = []
    for k, a in enumerate(amps):
        fd_scene = matched if fd_modifier is None else fd_modifier(matched)
        now(f"frequency domain: amplitude {a:g} m ({k + 1}/{len(amps)})")
        if axis == WAVE:
            fd = method("bvp").harmonic(wave_scene(fd_scene, a),
                                        static=static if fd_modifier is None else None)
        else:
            fd = method("bvp").harmonic(fd_scene, period, motion_vector(matched, axis, a),
                                        static=static if fd_modifier is None else None)
        if fd.status is Status.REFUSED:
            raise UnsupportedSceneError(fd.message)
        if not fd.converged:
            raise SolveFailed("bvp", fd.status, f"frequency domain: {fd.message}")
        def scene_for(settle, a=a):
            vs = dynamic_scene(matched, axis, a, period, settle, ramp)
            return vs if vfife_modifier is None else vfife_modifier(vs)

        now(f"vfife: amplitude {a:g} m ({k + 1}/{len(amps)})")
        vf, wall = settled_run(scene_for, period, ramp, axis, h, f"amplitude {a:g} m",
                               progress)
        rows, zone, warns = agreement_rows(matched, fd, vf, static)
        if k > 0:                  # the linear limit is judged; the rest measures nonlinearity
            rows = [row.judged(None, ABOVE_SMALLEST) if row.passed is not None else row
                    for row in rows]
        res = AmplitudeResult(a, fd, vf, rows, station_rows(fd, vf, static),
                              nonlinearity(vf, zone), warns, wall, fd.wall_time_s)
        if ancf is True or (ancf == "first" and k == 0):
            def ancf_scene(settle, a=a):
                return dynamic_scene(matched, axis, a, period, settle, ramp)

            now(f"ancf: amplitude {a:g} m ({k + 1}/{len(amps)})")
            an, an_wall, an_info = ancf_side.settled_run(ancf_scene, period, ramp, axis,
                                                         f"amplitude {a:g} m", progress)
            an_rows, _, an_warns = agreement_rows(matched, fd, an, static, method="ancf")
            if k > 0:
                an_rows = [row.judged(None, ABOVE_SMALLEST) if row.passed is not None
                           else row for row in an_rows]
            res.ancf, res.ancf_rows, res.ancf_wall_s, res.ancf_info = (an, an_rows, an_wall,
                                                                      an_info)
            res.warnings.extend(w for w in an_warns if w.startswith("window_drift"))
        results.append(res)
    return DynamicComparison(scene, matched, axis, period, h, results, static, notes)

"""A dynamic run from the static state (scene table ``[dynamics]``) and the prescribed
motion of the hang-off (``[dynamics.top_motion]``). Times in s, displacements in m; each
field's range, unit and meaning is its spec (:mod:`riser.spec`), checked on
construction with the cross-field rules (a ramp within the run, times increasing, a
plausible motion: :data:`MAX_TOP_SPEED`, :data:`MAX_TOP_ACCELERATION`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .hang_off_motion import motion_amplitudes
from ..spec import Part, check_fields, part_error, spec

HARMONIC = "required (harmonic)"
SERIES = "required (time series)"

#: the fastest plausible hang-off motion [m/s]. The hang-off moves with its vessel: in a
#: survival storm (Hs ~ 15 m, Tp ~ 15 s) a semisubmersible or an FPSO heaves or surges by
#: up to ~10 m at periods of 12-16 s, a peak speed of 2 pi 10 / 12 = 5.2 m/s (a porch on
#: a roll arm adds little). 20 m/s is four times that: a faster motion is a unit or typing
#: error (mm as m, a period in minutes), which the explicit dynamics would otherwise run
#: into a blow-up blamed on something else (1885 m/s: "drag near its stability limit").
MAX_TOP_SPEED = 20.0
#: the largest plausible acceleration (2 pi / T)^2 A of a harmonic hang-off motion
#: [m/s2], about 2 g: the vessel motions above accelerate the hang-off by at most
#: (2 pi / 12)^2 10 = 2.7 m/s2 (0.3 g); a short period with a small amplitude (0.5 m in
#: 0.2 s: 490 m/s2) is a vibration, not a vessel motion.
MAX_TOP_ACCELERATION = 20.0
#: a time series' first displacement beyond this [m] without a ramp is a jump at t = 0
START_JUMP = 1e-9
#: the most output samples a dynamic run may take (duration / output_interval + 1): each
#: is held in memory and written to timeseries.csv, ~:data:`SAMPLE_MEMORY` and
#: :data:`SAMPLE_FILE` bytes, so 1e6 samples are ~0.45 GB and ~0.22 GB (a 3-hour storm
#: sampled every 0.02 s is 540,000; the built-in scenes take at most 4,000); 1e-6 s in a
#: 40 s run (4e7 samples, ~18 GB) ran out of memory writing nothing
MAX_OUTPUT_SAMPLES = 1_000_000
#: memory of one output sample [B]: ~14 time-series columns as Python floats (32 B)
SAMPLE_MEMORY = 14 * 32
#: timeseries.csv bytes of one output sample: ~14 values of 10 significant digits (~16 B)
SAMPLE_FILE = 14 * 16
#: the most memory the saved states (``save_states``) may take [B]: 11 float64 per node
#: and sample (position, velocity, moment vector, tension, moment), held until written
MAX_STATES_MEMORY = 2.0e9
STATE_BYTES = 11 * 8
#: the most stations ``[dynamics] stations`` may name: each adds
#: :data:`STATION_COLUMNS` columns to timeseries.csv (50 stations: 350 columns beside the
#: run's 12 to 13)
MAX_STATIONS = 50
#: timeseries.csv columns of one station: tension, moment, curvature, x, y, z and, with
#: [design], the utilisation (riser/results/recorder.py)
STATION_COLUMNS = 7


@dataclass(frozen=True)
class TopMotion(Part):
    """Prescribed hang-off motion, one of four forms (d [m] in the scene's axes):

    - along ``axis`` ('x', 'y' or 'z'), harmonic: d = A sin(2 pi t / T) (``amplitude``,
      ``period``);
    - along ``axis``, a time series (``times`` [s], ``displacements`` [m], linearly
      interpolated; amplitude and period stay 0);
    - an orbit (several axes, one period): d_k = A_k sin(2 pi t / T + phi_k) for k = x,
      y, z (``amplitudes``, ``period``, ``phases_deg`` phase leads [deg]);
    - a time series per axis (``times`` with ``displacements_x``, ``displacements_y``,
      ``displacements_z``, each optional: an axis not given stays still).

    ``ramp_time`` [s]: the motion is multiplied by the half-cosine ramp 0.5 (1 - cos(pi
    t / t_r)) up to t_r; None (the default) means one period of a harmonic motion and no
    ramp for a time series (which starts where it says); 0 turns the ramp off (an
    impulsive start)."""

    axis: str | None = spec(None, "string", choices=("x", "y", "z"),
                            default_doc="required (one axis)",
                            doc="direction of a motion along one axis")
    amplitude: float = spec(0.0, ge=0.0, le=1000.0, unit="m", default_doc=HARMONIC,
                            also=f"peak speed 2 pi A / T <= {MAX_TOP_SPEED:g} m/s; "
                                 "along y, < the hang-off height",
                            doc="amplitude of d = A sin(2 pi t / T)")
    period: float = spec(0.0, gt=0.0, le=1.0e4, unit="s", default_doc=HARMONIC,
                         also=f"peak acceleration (2 pi / T)^2 A <= {MAX_TOP_ACCELERATION:g} "
                              "m/s2",
                         doc="period T of the harmonic motion")
    times: tuple[float, ...] | None = spec(None, "numbers", min_length=2, ge=0.0, le=1.0e6,
                                           unit="s", also="strictly increasing",
                                           default_doc=SERIES,
                                           doc="times of a time series (instead of "
                                               "amplitude and period)")
    displacements: tuple[float, ...] | None = spec(None, "numbers", ge=-1000.0, le=1000.0,
                                                   unit="m", also="as many as times; at most "
                                                   f"{MAX_TOP_SPEED:g} m/s between points; "
                                                   "the first 0 without a ramp",
                                                   default_doc=SERIES,
                                                   doc="displacement at each time")
    amplitudes: tuple[float, ...] | None = spec(None, "numbers", length=3, ge=0.0, le=1000.0,
                                                unit="m", default_doc="required (orbit)",
                                                doc="(x, y, z) amplitudes of an orbit "
                                                    "d_k = A_k sin(2 pi t / T + phi_k)")
    phases_deg: tuple[float, ...] = spec((0.0, 0.0, 0.0), "numbers", length=3, ge=-360.0,
                                         le=360.0, unit="deg",
                                         doc="(x, y, z) phase leads phi_k of an orbit")
    displacements_x: tuple[float, ...] | None = spec(None, "numbers", ge=-1000.0, le=1000.0,
                                                     unit="m", also="as many as times",
                                                     doc="x displacement at each time (a "
                                                         "series per axis)")
    displacements_y: tuple[float, ...] | None = spec(None, "numbers", ge=-1000.0, le=1000.0,
                                                     unit="m", also="as many as times",
                                                     doc="y displacement at each time")
    displacements_z: tuple[float, ...] | None = spec(None, "numbers", ge=-1000.0, le=1000.0,
                                                     unit="m", also="as many as times",
                                                     doc="z displacement at each time")
    ramp_time: float | None = spec(None, ge=0.0, unit="s", also="<= duration",
                                   default_doc="one period (harmonic); 0 (time series)",
                                   doc="half-cosine ramp of the motion; 0: no ramp")

    def __post_init__(self) -> None:
        error = part_error(self)
        per_axis = tuple(k for k in "xyz" if getattr(self, f"displacements_{k}") is not None)
        series = self.times is not None or self.displacements is not None or bool(per_axis)
        check_fields(self, skip=("amplitude", "period") if series else ())
        orbit = self.amplitudes is not None
        if orbit or per_axis:
            if self.axis is not None:
                raise error("axis", "not with " + ("amplitudes (an orbit moves along its "
                            "amplitudes' axes)" if orbit else "displacements_x/_y/_z (a "
                            "series per axis)"))
        elif self.axis is None:
            raise error("axis", "required: the direction of a motion along one axis (or give "
                        "amplitudes for an orbit, displacements_x/_y/_z for a series per axis)")
        if not series:
            if orbit and self.amplitude != 0.0:
                raise error("amplitude", "not with amplitudes (an orbit gives one per axis)")
            self._check_harmonic_plausible(error)
            return
        for name in ("amplitude", "period", "amplitudes"):
            if getattr(self, name) not in (0.0, None):
                raise error(name, "not with times and displacements (a time series has "
                            "neither amplitude nor period)")
        if per_axis and self.displacements is not None:
            raise error("displacements", "not with displacements_x/_y/_z (one axis, or a "
                        "series per axis)")
        if self.times is None:
            raise error("times", "required with " + ("displacements_" + per_axis[0]
                        if per_axis else "displacements") + " (a time series)")
        if not per_axis and self.displacements is None:
            raise error("displacements", "required with times (a time series)")
        n = len(self.times)
        for k, d in self.series.items():
            name = "displacements" if self.axis is not None else f"displacements_{k}"
            if len(d) != n:
                raise error(name, f"must have {n} entries, got {len(d)}")
        for i in range(1, n):
            if not self.times[i] > self.times[i - 1]:
                raise error(f"times[{i}]", "must be strictly increasing")
        self._check_series_plausible(error)

    @property
    def series(self) -> dict:
        """axis -> displacements [m] of a time series (one axis or several); {} for a
        harmonic motion."""
        if self.times is None:
            return {}
        if self.axis is not None:
            return {self.axis: self.displacements}
        return {k: getattr(self, f"displacements_{k}") for k in "xyz"
                if getattr(self, f"displacements_{k}") is not None}

    @property
    def is_orbit(self) -> bool:
        """True for a harmonic motion along several axes (``amplitudes``)."""
        return self.amplitudes is not None

    @property
    def one_axis(self) -> bool:
        """True for a motion along one ``axis`` (harmonic or a series)."""
        return self.axis is not None

    def moves(self, axis: str) -> bool:
        """Whether the motion has a component along ``axis`` ('x', 'y', 'z')."""
        if self.axis is not None:
            return self.axis == axis
        if self.amplitudes is not None:
            return self.amplitudes["xyz".index(axis)] > 0.0
        return axis in self.series

    def complex_amplitudes(self):
        """(3,) complex amplitudes D [m] of a harmonic motion, d(t) = Re(D e^{i omega t}):
        A sin(omega t + phi) is Re(-i A e^{i phi} e^{i omega t})."""
        if self.amplitudes is None:
            return motion_amplitudes(self.axis, self.amplitude)
        return np.array([-1j * a * np.exp(1j * math.radians(phi))
                         for a, phi in zip(self.amplitudes, self.phases_deg)])

    def displacement(self, t):
        """(3, nt) displacement [m] at times t [s] without the ramp."""
        t = np.atleast_1d(np.asarray(t, float))
        out = np.zeros((3, t.size))
        if self.times is None:
            wt = 2.0 * math.pi * t / self.period
            if self.is_orbit:
                for k in range(3):
                    out[k] = self.amplitudes[k] * np.sin(wt + math.radians(self.phases_deg[k]))
            else:                                 # A sin(omega t), as it always was
                out["xyz".index(self.axis)] = self.amplitude * np.sin(wt)
            return out
        for k, d in self.series.items():
            out["xyz".index(k)] = np.interp(t, self.times, d)
        return out

    @property
    def resultant_amplitude(self) -> float:
        """sqrt(sum A_k^2) [m] of a harmonic motion (A of one axis)."""
        if self.amplitudes is not None:
            return math.sqrt(sum(a * a for a in self.amplitudes))
        return float(self.amplitude)

    def _check_harmonic_plausible(self, error) -> None:
        """Refuse a harmonic motion faster than :data:`MAX_TOP_SPEED` or accelerating
        beyond :data:`MAX_TOP_ACCELERATION` (a unit or typing error, not a vessel); an
        orbit by its resultant amplitude (an upper bound of its peak speed)."""
        a, period = self.resultant_amplitude, self.period
        key = "amplitudes" if self.is_orbit else "amplitude"
        speed = 2.0 * math.pi * a / period
        given = f"(amplitude {a:g} m, period {period:g} s)"
        if speed > MAX_TOP_SPEED:
            raise error(key, f"peak speed 2 pi amplitude / period = {speed:.4g} m/s "
                        f"{given} must be <= {MAX_TOP_SPEED:g} m/s, the fastest plausible "
                        "hang-off motion (a vessel heaves or surges at up to ~5 m/s in a "
                        "survival storm): check amplitude [m] and period [s]")
        acc = (2.0 * math.pi / period) ** 2 * a
        if acc > MAX_TOP_ACCELERATION:
            raise error("period", f"peak acceleration (2 pi / period)^2 amplitude = "
                        f"{acc:.4g} m/s2 {given} must be <= {MAX_TOP_ACCELERATION:g} m/s2 "
                        "(about 2 g; a vessel accelerates its hang-off by at most ~0.3 g): "
                        "check amplitude [m] and period [s]")

    def _check_series_plausible(self, error) -> None:
        """Refuse a time series with a segment faster than :data:`MAX_TOP_SPEED` (the
        resultant of its axes), or one that jumps at t = 0 (a first displacement other
        than 0 without a ramp: the hang-off starts from its static position)."""
        t, series = self.times, self.series
        name = (lambda k: "displacements") if self.axis is not None else (
            lambda k: f"displacements_{k}")
        for i in range(1, len(t)):
            speed = math.sqrt(sum((d[i] - d[i - 1]) ** 2 for d in series.values())) / (
                t[i] - t[i - 1])
            if speed > MAX_TOP_SPEED:
                k = max(series, key=lambda a: abs(series[a][i] - series[a][i - 1]))
                d = series[k]
                raise error(f"{name(k)}[{i}]", f"moves the hang-off at {speed:.4g} m/s "
                            f"from times[{i - 1}] = {t[i - 1]:g} s to times[{i}] = {t[i]:g} "
                            f"s ({d[i - 1]:g} m to {d[i]:g} m): must be <= "
                            f"{MAX_TOP_SPEED:g} m/s, the fastest plausible hang-off motion "
                            "(a vessel heaves or surges at up to ~5 m/s in a survival "
                            "storm): check times [s] and displacements [m]")
        for k, d in series.items():
            if abs(d[0]) > START_JUMP and self.ramp == 0.0:
                raise error(f"{name(k)}[0]", "must be 0 m without a ramp (the hang-off starts "
                            "from its static position, and the series holds its first "
                            "displacement from t = 0: a jump at the start), got "
                            f"{d[0]:g}; start the series at 0 or set ramp_time")

    @property
    def peak_speed(self) -> float:
        """Peak speed [m/s] of the motion without its ramp: 2 pi A / T (harmonic; an
        orbit's resultant amplitude, an upper bound), the steepest segment of a time
        series (the resultant of its axes)."""
        if self.times is None:
            return 2.0 * math.pi * self.resultant_amplitude / self.period
        t, series = self.times, self.series
        return max(math.sqrt(sum((d[i] - d[i - 1]) ** 2 for d in series.values()))
                   / (t[i] - t[i - 1]) for i in range(1, len(t)))

    @property
    def reach(self) -> float:
        """The largest displacement [m] from the static hang-off (an upper bound for an
        orbit: its resultant amplitude)."""
        if self.times is None:
            return self.resultant_amplitude
        n = len(self.times)
        return max(math.sqrt(sum(d[i] ** 2 for d in self.series.values())) for i in range(n))

    @property
    def lowest_displacement(self) -> float:
        """The lowest vertical displacement [m] the motion reaches, ramp included (<= 0):
        -A_y (harmonic), min(0, displacements along y) (a ramp scales the series towards
        0); 0 without a vertical part."""
        if not self.moves("y"):
            return 0.0
        if self.times is None:
            return -float(self.amplitudes[1] if self.is_orbit else self.amplitude)
        low = min(self.series["y"])
        return min(0.0, low) if self.ramp > 0.0 else float(low)

    @property
    def ramp(self) -> float:
        """The ramp duration applied [s] (see the class docstring)."""
        if self.ramp_time is not None:
            return float(self.ramp_time)
        return float(self.period) if self.times is None else 0.0


@dataclass(frozen=True)
class Dynamics(Part):
    """Dynamic run from the static state: duration and output interval [s].

    damping : mass-proportional damping coefficient [1/s] (structural; the hydrodynamic
        drag is always on in water, see vfife/dynamics/run.py).
    statistics_start : [s] envelopes and statistics are taken from this time on; None
        means the end of the top motion's ramp (0 without a ramp, or when the ramp is not
        shorter than the run).
    save_states : write every node's position and velocity at the output times
        (``states.npz``).
    stations : arc lengths [m] from the bottom end (the scene's own coordinate) whose
        tension, moment, curvature, position and, with [design], utilisation
        timeseries.csv adds (``station_K_*``, K = 1, 2, ... in the order given:
        :mod:`riser.results.recorder`); within the line (:func:`check_stations`).
    """

    duration: float = spec(gt=0.0, le=1.0e6, unit="s", doc="length of the run")
    output_interval: float | None = spec(None, gt=0.0, unit="s", also="<= duration; at most "
                                         f"{MAX_OUTPUT_SAMPLES:,} samples",
                                         default_doc="min(1 s, duration)",
                                         doc="time between outputs")
    top_motion: TopMotion | None = spec(None, "part", part=TopMotion,
                                        doc="prescribed hang-off motion")
    damping: float = spec(0.0, ge=0.0, le=100.0, unit="1/s",
                          doc="mass-proportional structural damping")
    statistics_start: float | None = spec(None, ge=0.0, unit="s", also="< duration",
                                          default_doc="the end of the ramp",
                                          doc="envelopes and statistics from this time on")
    save_states: bool = spec(False, "boolean", also="at most 2 GB of states",
                             doc="write every node's state at the output times "
                                 "(states.npz)")
    stations: tuple[float, ...] | None = spec(None, "numbers", ge=0.0, unit="m",
                                              also="<= the line's length; at most "
                                              f"{MAX_STATIONS}, none twice",
                                              default_doc="none",
                                              doc="arc lengths from the bottom end whose "
                                                  "tension, moment, curvature, position "
                                                  "(and utilisation) timeseries.csv adds")

    def __post_init__(self) -> None:
        check_fields(self)
        error, duration = part_error(self), self.duration
        if self.output_interval is None:
            object.__setattr__(self, "output_interval", min(1.0, duration))
        elif self.output_interval > duration:
            raise error("output_interval", f"must be <= {duration:g} s, got "
                        f"{self.output_interval:g}")
        samples = math.floor(duration / self.output_interval + 1e-9) + 1.0 \
            if math.isfinite(duration / self.output_interval) else math.inf
        if samples > MAX_OUTPUT_SAMPLES:
            raise error("output_interval", f"gives {samples:.4g} output samples in "
                        f"{duration:g} s (~{_size(samples * SAMPLE_MEMORY)} of memory, "
                        f"~{_size(samples * SAMPLE_FILE)} of timeseries.csv): must give at "
                        f"most {MAX_OUTPUT_SAMPLES:,} samples, output_interval >= "
                        f"{duration / (MAX_OUTPUT_SAMPLES - 1):.3g} s, got "
                        f"{self.output_interval:g}")
        if self.stations is not None:
            self._check_stations(error, samples)
        if self.statistics_start is not None and not self.statistics_start < duration:
            raise error("statistics_start", f"must be < {duration:g} s, got "
                        f"{self.statistics_start:g}")
        motion = self.top_motion
        if motion is None:
            return
        if motion.ramp_time is not None and motion.ramp_time > duration:
            raise error("top_motion.ramp_time", f"must be <= {duration:g} s, got "
                        f"{motion.ramp_time:g}")
        if motion.times is None and motion.ramp_time is None and motion.period >= duration:
            raise error("duration", f"must be > {motion.period:g} s, the default ramp (one "
                        f"period of top_motion), got {duration:g}; or set "
                        "top_motion.ramp_time (0: no ramp)")

    def _check_stations(self, error, samples: float) -> None:
        """At most :data:`MAX_STATIONS` stations, none twice, and their time-series
        columns within the memory of :data:`MAX_OUTPUT_SAMPLES` samples without them."""
        n = len(self.stations)
        if n > MAX_STATIONS:
            raise error("stations", f"must have at most {MAX_STATIONS} entries (each adds "
                        f"{STATION_COLUMNS} columns to timeseries.csv), got {n}")
        for i, v in enumerate(self.stations):
            if v in self.stations[:i]:
                raise error(f"stations[{i}]", f"{v:g} m given twice (stations"
                            f"[{self.stations.index(v)}])")
        columns = SAMPLE_MEMORY // 32 + STATION_COLUMNS * n
        if samples * columns > MAX_OUTPUT_SAMPLES * (SAMPLE_MEMORY // 32):
            raise error("stations", f"{n} stations ({STATION_COLUMNS * n} columns) at "
                        f"{samples:.4g} output samples are ~{_size(samples * columns * 32)} "
                        f"of memory: must be <= {_size(MAX_OUTPUT_SAMPLES * SAMPLE_MEMORY)}; "
                        "raise output_interval or give fewer stations")

    @property
    def output_samples(self) -> int:
        """The number of output samples [-]: every output interval from t = 0 to the
        duration."""
        return int(math.floor(self.duration / self.output_interval + 1e-9)) + 1

    @property
    def statistics_from(self) -> float:
        """The time [s] from which envelopes and statistics are taken."""
        if self.statistics_start is not None:
            return float(self.statistics_start)
        ramp = self.top_motion.ramp if self.top_motion is not None else 0.0
        return ramp if ramp < self.duration else 0.0


def check_output_size(scene) -> None:
    """With ``save_states`` the states of every node at every output time fit in
    :data:`MAX_STATES_MEMORY` (the nodes from the scene's [vfife] element_length; a
    command line's --element-length is the solver's to check)."""
    dyn = scene.dynamics
    if dyn is None or not dyn.save_states:
        return
    nodes = math.ceil(scene.total_length / scene.vfife.element_length - 1e-9) + 1
    size = float(dyn.output_samples) * nodes * STATE_BYTES
    if size > MAX_STATES_MEMORY:
        raise scene.error("dynamics.save_states", f"{dyn.output_samples:,} output samples "
                          f"of {nodes:,} nodes (vfife.element_length "
                          f"{scene.vfife.element_length:g} m) are ~{_size(size)} of states "
                          f"in memory: must be <= {_size(MAX_STATES_MEMORY)}; raise "
                          "dynamics.output_interval, or set save_states = false")


def check_stations(scene) -> None:
    """Each ``[dynamics] stations`` arc length within the line, [0, its length] (the
    scene's own coordinate, from the bottom end)."""
    dyn = scene.dynamics
    if dyn is None or dyn.stations is None:
        return
    length = scene.total_length
    for i, v in enumerate(dyn.stations):
        if v > length:
            raise scene.error(f"dynamics.stations[{i}]", f"must be within [0, {length:g}] m "
                              f"(an arc length from the bottom end, the line's length "
                              f"{length:g} m), got {v:g}")


def _size(nbytes: float) -> str:
    """A byte count in kB, MB, GB or TB (decimal)."""
    for unit, scale in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if nbytes >= scale:
            return f"{nbytes / scale:.3g} {unit}"
    return f"{nbytes:.0f} B"

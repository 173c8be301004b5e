"""A dynamic run from the static state (scene table ``[dynamics]``) and the prescribed
motion of the hang-off (``[dynamics.top_motion]``). Times in s, displacements in m; each
field's range, unit and meaning is its spec (:mod:`riser.spec`), checked on
construction with the cross-field rules (a ramp within the run, times increasing, a
plausible motion: :data:`MAX_TOP_SPEED`, :data:`MAX_TOP_ACCELERATION`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .spec import Part, check_fields, part_error, spec

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


@dataclass(frozen=True)
class TopMotion(Part):
    """Prescribed hang-off motion along ``axis`` ('x', 'y' or 'z'): harmonic (amplitude
    [m], period [s]: d = A sin(2 pi t / T)) or a time series (times [s], displacements
    [m], linearly interpolated; amplitude and period stay 0). ``ramp_time`` [s]: the
    motion is multiplied by the half-cosine ramp 0.5 (1 - cos(pi t / t_r)) up to t_r; None
    (the default) means one period of a harmonic motion and no ramp for a time series
    (which starts where it says); 0 turns the ramp off (an impulsive start)."""

    axis: str = spec(kind="string", choices=("x", "y", "z"), doc="direction of the motion")
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
    ramp_time: float | None = spec(None, ge=0.0, unit="s", also="<= duration",
                                   default_doc="one period (harmonic); 0 (time series)",
                                   doc="half-cosine ramp of the motion; 0: no ramp")

    def __post_init__(self) -> None:
        error = part_error(self)
        series = self.times is not None or self.displacements is not None
        check_fields(self, skip=("amplitude", "period") if series else ())
        if not series:
            self._check_harmonic_plausible(error)
            return
        for name in ("amplitude", "period"):
            if getattr(self, name) != 0.0:
                raise error(name, "not with times and displacements (a time series has "
                            "neither amplitude nor period)")
        for name, other in (("times", "displacements"), ("displacements", "times")):
            if getattr(self, name) is None:
                raise error(name, f"required with {other} (a time series)")
        n = len(self.times)
        if len(self.displacements) != n:
            raise error("displacements", f"must have {n} entries, got {len(self.displacements)}")
        for i in range(1, n):
            if not self.times[i] > self.times[i - 1]:
                raise error(f"times[{i}]", "must be strictly increasing")
        self._check_series_plausible(error)

    def _check_harmonic_plausible(self, error) -> None:
        """Refuse a harmonic motion faster than :data:`MAX_TOP_SPEED` or accelerating
        beyond :data:`MAX_TOP_ACCELERATION` (a unit or typing error, not a vessel)."""
        a, period = self.amplitude, self.period
        speed = 2.0 * math.pi * a / period
        given = f"(amplitude {a:g} m, period {period:g} s)"
        if speed > MAX_TOP_SPEED:
            raise error("amplitude", f"peak speed 2 pi amplitude / period = {speed:.4g} m/s "
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
        """Refuse a time series with a segment faster than :data:`MAX_TOP_SPEED`, or one
        that jumps at t = 0 (a first displacement other than 0 without a ramp: the
        hang-off starts from its static position)."""
        t, d = self.times, self.displacements
        for i in range(1, len(t)):
            speed = abs(d[i] - d[i - 1]) / (t[i] - t[i - 1])
            if speed > MAX_TOP_SPEED:
                raise error(f"displacements[{i}]", f"moves the hang-off at {speed:.4g} m/s "
                            f"from times[{i - 1}] = {t[i - 1]:g} s to times[{i}] = {t[i]:g} "
                            f"s ({d[i - 1]:g} m to {d[i]:g} m): must be <= "
                            f"{MAX_TOP_SPEED:g} m/s, the fastest plausible hang-off motion "
                            "(a vessel heaves or surges at up to ~5 m/s in a survival "
                            "storm): check times [s] and displacements [m]")
        if abs(d[0]) > START_JUMP and self.ramp == 0.0:
            raise error("displacements[0]", "must be 0 m without a ramp (the hang-off starts "
                        "from its static position, and the series holds its first "
                        "displacement from t = 0: a jump at the start), got "
                        f"{d[0]:g}; start the series at 0 or set ramp_time")

    @property
    def peak_speed(self) -> float:
        """Peak speed [m/s] of the motion without its ramp: 2 pi A / T (harmonic), the
        steepest segment of a time series."""
        if self.times is None:
            return 2.0 * math.pi * self.amplitude / self.period
        t, d = self.times, self.displacements
        return max(abs(d[i] - d[i - 1]) / (t[i] - t[i - 1]) for i in range(1, len(t)))

    @property
    def lowest_displacement(self) -> float:
        """The lowest displacement [m] the motion reaches, ramp included (<= 0): -A
        (harmonic), min(0, displacements) (a ramp scales the series towards 0)."""
        if self.times is None:
            return -float(self.amplitude)
        low = min(self.displacements)
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
        drag is always on in water, see vfife/dynamics.py).
    statistics_start : [s] envelopes and statistics are taken from this time on; None
        means the end of the top motion's ramp (0 without a ramp, or when the ramp is not
        shorter than the run).
    save_states : write every node's position and velocity at the output times
        (``states.npz``).
    """

    duration: float = spec(gt=0.0, le=1.0e6, unit="s", doc="length of the run")
    output_interval: float | None = spec(None, gt=0.0, unit="s", also="<= duration",
                                         default_doc="min(1 s, duration)",
                                         doc="time between outputs")
    top_motion: TopMotion | None = spec(None, "part", part=TopMotion,
                                        doc="prescribed hang-off motion")
    damping: float = spec(0.0, ge=0.0, le=100.0, unit="1/s",
                          doc="mass-proportional structural damping")
    statistics_start: float | None = spec(None, ge=0.0, unit="s", also="< duration",
                                          default_doc="the end of the ramp",
                                          doc="envelopes and statistics from this time on")
    save_states: bool = spec(False, "boolean", doc="write every node's state at the "
                                                   "output times (states.npz)")

    def __post_init__(self) -> None:
        check_fields(self)
        error, duration = part_error(self), self.duration
        if self.output_interval is None:
            object.__setattr__(self, "output_interval", min(1.0, duration))
        elif self.output_interval > duration:
            raise error("output_interval", f"must be <= {duration:g} s, got "
                        f"{self.output_interval:g}")
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

    @property
    def statistics_from(self) -> float:
        """The time [s] from which envelopes and statistics are taken."""
        if self.statistics_start is not None:
            return float(self.statistics_start)
        ramp = self.top_motion.ramp if self.top_motion is not None else 0.0
        return ramp if ramp < self.duration else 0.0

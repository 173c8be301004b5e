"""A dynamic run from the static state (scene table ``[dynamics]``) and the prescribed
motion of the hang-off (``[dynamics.top_motion]``). Times in s, displacements in m; each
field's range, unit and meaning is its spec (:mod:`riser.spec`), checked on
construction with the cross-field rules (a ramp within the run, times increasing).
"""

from __future__ import annotations

from dataclasses import dataclass

from .spec import Part, check_fields, part_error, spec

HARMONIC = "required (harmonic)"
SERIES = "required (time series)"


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
                            doc="amplitude of d = A sin(2 pi t / T)")
    period: float = spec(0.0, gt=0.0, le=1.0e4, unit="s", default_doc=HARMONIC,
                         doc="period T of the harmonic motion")
    times: tuple[float, ...] | None = spec(None, "numbers", min_length=2, ge=0.0, le=1.0e6,
                                           unit="s", also="strictly increasing",
                                           default_doc=SERIES,
                                           doc="times of a time series (instead of "
                                               "amplitude and period)")
    displacements: tuple[float, ...] | None = spec(None, "numbers", ge=-1000.0, le=1000.0,
                                                   unit="m", also="as many as times",
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

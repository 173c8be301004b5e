"""What a dynamic run records, every time-domain method alike: time series, envelopes along
s and statistics over a window (the result contract of ``SolveResult.dynamics``; each
method samples its own state into a :class:`NodalState`).

Sampling: :class:`Recorder` is called every envelope interval (at most period/40 of a
harmonic top motion, an exact divisor of the output interval; see vfife/dynamics/run.py
and ancf/dynamics/run.py).
Every call updates the statistics and the envelopes when its time is at or after the
window start (``[dynamics] statistics_start``, default the end of the ramp); the time
series and the states take the calls at the output times, from t = 0.

Time series (one row per output time; SI units, s from the bottom end):
    time [s]; hang_off_x, hang_off_y, hang_off_z [m] (hang-off position);
    hang_off_tension [N] (effective tension at the hang-off node);
    touchdown_s [m], touchdown_tension [N] (the last node from the bottom in contact,
    refined to y = 0; empty when the line is off the seabed or there is none);
    min_tension [N], min_tension_s [m] (the lowest effective tension along the whole
    line, negative = compression, and where); max_moment [N m], max_moment_s [m];
    kinetic_energy [J] (translations and rotations).
Envelopes (one row per node): s [m], tension_min, tension_max [N], moment_max [N m],
curvature_max [1/m], y_min, y_max [m] (height extremes: seabed and surface clearance),
submergence_min [m] (the least depth of the node below the instantaneous sea surface,
negative above it; empty without water_depth), and the times [s] the window first reached
tension_min, curvature_max and submergence_min (tension_min_time, curvature_max_time,
submergence_min_time: the "when" of riser.results.validity.dynamic_warnings).
Stations (``[dynamics] stations``, s_K [m] in the order given, K = 1, 2, ...): after
the columns above (and ``wave_elevation``), per station ``station_K_tension`` [N],
``station_K_moment`` [N m], ``station_K_curvature`` [1/m], ``station_K_x``,
``station_K_y``, ``station_K_z`` [m] and the quantities its observers give at the nodes
(``station_quantities``: the design checks' ``station_K_utilisation`` [-]); each
interpolated linearly in s between the two nodes around s_K (a node's own value at a
node; :func:`station_weights`).
States (``[dynamics] save_states``): t (k,), s (n,), x (k, n, 3) [m], v (k, n, 3) [m/s],
tension (k, n) [N] (effective) and moment (k, n) [N m] at the nodes, and moment_vector
(k, n, 3) [N m] (the nodal moment's global x, y, z components, -EI t x t': minus the
signed in-plane bending of a planar line is its z component).
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np

from ..design.extremes import storm_statistics

TIMESERIES = ("time", "hang_off_x", "hang_off_y", "hang_off_z", "hang_off_tension",
              "touchdown_s", "touchdown_tension", "min_tension", "min_tension_s",
              "max_moment", "max_moment_s", "kinetic_energy")
#: time-series columns that hold an arc length [m]
ARC_LENGTH_COLUMNS = ("touchdown_s", "min_tension_s", "max_moment_s")
#: summary keys (:meth:`Recorder.statistics`) that hold an arc length [m]
ARC_LENGTH_KEYS = ("dynamic_min_touchdown_s", "dynamic_max_touchdown_s",
                   "dynamic_min_tension_s", "dynamic_max_moment_s", "dynamic_max_tension_s",
                   "stations")
#: the quantities of a station's time-series columns (``station_K_<quantity>``), then
#: those of the observers (``station_quantities``)
STATION_QUANTITIES = ("tension", "moment", "curvature", "x", "y", "z")
ENVELOPE = ("s", "tension_min", "tension_max", "moment_max", "curvature_max", "y_min",
            "y_max", "submergence_min", "tension_min_time", "curvature_max_time",
            "submergence_min_time", "tension_mean", "tension_std", "curvature_mean",
            "curvature_std")


def touchdown_s(s: np.ndarray, y: np.ndarray, has_seabed: bool) -> float | None:
    """Arc length [m] of the touchdown point: the end towards the hang-off of the first
    contact zone from the bottom (nodes with y <= 0), refined by linear interpolation of
    the height to the crossing of y = 0; None without a seabed or when no node is on it.
    An anchor above the seabed whose line reaches it further on has its touchdown there
    too (it reported none before, however much line lay on the seabed)."""
    if not has_seabed:
        return None
    on = np.flatnonzero(y <= 0.0)
    if on.size == 0:
        return None
    s, y = s[on[0]:], y[on[0]:]
    contact = y <= 0.0
    i = int(np.argmin(contact)) - 1 if not np.all(contact) else len(s) - 1
    if i < 0:
        return None
    if i + 1 < len(s) and y[i + 1] > y[i]:
        return float(s[i] + (0.0 - y[i]) / (y[i + 1] - y[i]) * (s[i + 1] - s[i]))
    return float(s[i])


def station_column(k: int, quantity: str) -> str:
    """The time-series column of ``quantity`` at the station ``stations[k]`` (counted from
    0): ``station_{k + 1}_{quantity}``."""
    return f"station_{k + 1}_{quantity}"


def station_weights(s: np.ndarray, stations) -> tuple[np.ndarray, np.ndarray]:
    """(i, w) of the linear interpolation at ``stations`` [m] between nodes at ``s`` [m]
    (increasing): value = (1 - w) a[i] + w a[i + 1], w in [0, 1] (0 at a node, whose own
    value it is; a station beyond the ends takes the end node's)."""
    s = np.asarray(s, float)
    st = np.asarray(stations, float)
    i = np.clip(np.searchsorted(s, st, side="right") - 1, 0, max(len(s) - 2, 0))
    if len(s) < 2:
        return i, np.zeros(len(st))
    w = np.clip((st - s[i]) / (s[i + 1] - s[i]), 0.0, 1.0)
    return i, w


#: one sample of a line's state at its output stations (n,) (a method's nodes): positions
#: x, velocities v, unit tangents t (n, 3) [m, m/s, -]; effective tension [N], bending
#: moment magnitude [N m] and curvature [1/m] (n,); moment_vector (n, 3) [N m], the nodal
#: moment -EI t x t' (minus the line's bending moment: the states file's convention);
#: surface (n,) [m], the sea surface's height over each station (inf without one)
NodalState = namedtuple("NodalState", "x v t tension moment curvature moment_vector surface")


class Recorder:
    """Collects the outputs of one dynamic run (see the module docstring).

    s : (n,) node arc lengths [m]; start : the statistics window's start [s];
    save_states : keep the node positions and velocities at the output times;
    has_seabed : the scene has a seabed (touchdown outputs).
    observers : objects told of every sample, whose columns and figures join the run's
        (the caller's post-processing, e.g. the design checks of riser.design.dynamic,
        which this method never imports): ``start(s)`` once with the stations [m];
        ``sample(t, x, tangents, tension, moment_vectors, window)`` at every sample
        (positions (n, 3) [m], unit tangents (n, 3), effective tension (n,) [N], the
        line's bending-moment vectors EI t x t' (n, 3) [N m], inside the statistics
        window or not; the first call is the static state); ``envelope()`` -> columns
        along s; ``statistics()`` -> summary figures; optionally ``station_quantities``
        (names) and ``nodal(name)`` -> (n,) its value at the nodes in the latest sample,
        which the stations' columns interpolate. One fresh set per run.
    stations : arc lengths [m] (in ``s``'s coordinate) whose time-series columns follow
        the others (``station_K_*``, see the module docstring).
    """

    def __init__(self, s: np.ndarray, start: float, save_states: bool, has_seabed: bool,
                 elevation=None, irregular: bool = False, observers=(), stations=None):
        self.s = np.asarray(s, float)
        self.start = float(start)
        self.save_states = save_states
        self.has_seabed = has_seabed
        self.elevation = elevation
        self.irregular = irregular
        self.observers = tuple(observers)
        # the storm of the most probable maxima [s]: an observer's storm_duration (the
        # [design] table's, riser.design.dynamic.DynamicDesign), else 3 h
        self.storm_duration = next((float(o.storm_duration) for o in self.observers
                                    if getattr(o, "storm_duration", None)), STORM_DURATION)
        self.times: list[float] = []              # the window's sample times
        n = len(self.s)
        self.columns = TIMESERIES + (("wave_elevation",) if elevation is not None else ())
        self.stations = np.asarray(() if stations is None else stations, float)
        self.station_at = station_weights(self.s, self.stations)
        self.station_quantities = STATION_QUANTITIES + tuple(
            q for obs in self.observers for q in getattr(obs, "station_quantities", ()))
        self.columns += tuple(station_column(k, q) for k in range(len(self.stations))
                              for q in self.station_quantities)
        self.ts = {k: [] for k in self.columns}
        # sums of the window for the mean and standard deviation along s
        self.sums = {k: np.zeros(n) for k in ("T", "T2", "K", "K2")}
        self.env = {"tension_min": np.full(n, np.inf), "tension_max": np.full(n, -np.inf),
                    "moment_max": np.full(n, -np.inf), "curvature_max": np.full(n, -np.inf),
                    "y_min": np.full(n, np.inf), "y_max": np.full(n, -np.inf),
                    "submergence_min": np.full(n, np.inf),
                    "tension_min_time": np.full(n, np.nan),
                    "curvature_max_time": np.full(n, np.nan),
                    "submergence_min_time": np.full(n, np.nan)}
        self.states = {"t": [], "x": [], "v": [], "tension": [], "moment": [],
                       "moment_vector": []}
        self.stats: dict = {}
        self.samples = 0
        self.top_tension: list[float] = []       # the window's hang-off tension samples
        self.line_min_tension: list[float] = []  # the least tension along s, each sample
        self.line_max_moment: list[float] = []   # the largest moment along s, each sample

        for obs in self.observers:
            obs.start(self.s)

    def sample(self, t: float, state: NodalState, ke: float, record: bool) -> None:
        """Take the line's ``state`` at time ``t`` [s] (kinetic energy ``ke`` [J]);
        ``record``: an output time (time series, states)."""
        T, M, K = state.tension, state.moment, state.curvature
        y = state.x[:, 1]
        top = state.x[-1]
        td = touchdown_s(self.s, y, self.has_seabed)
        td_t = float(np.interp(td, self.s, T)) if td is not None else np.nan
        i_min, i_mom = int(np.argmin(T)), int(np.argmax(M))
        row = {"time": t, "hang_off_x": top[0], "hang_off_y": top[1], "hang_off_z": top[2],
               "hang_off_tension": T[-1], "touchdown_s": np.nan if td is None else td,
               "touchdown_tension": td_t, "min_tension": T[i_min],
               "min_tension_s": self.s[i_min], "max_moment": M[i_mom],
               "max_moment_s": self.s[i_mom], "kinetic_energy": ke}
        if self.elevation is not None:
            row["wave_elevation"] = self.elevation(t)
        window = t >= self.start - 1e-9
        if window:
            sub = state.surface - y
            e = self.env
            for key, later in (("tension_min", T < e["tension_min"]),
                               ("curvature_max", K > e["curvature_max"]),
                               ("submergence_min", sub < e["submergence_min"])):
                e[key + "_time"][later] = t      # the first time the extreme is reached
            np.minimum(e["submergence_min"], sub, out=e["submergence_min"])
            self._window(row, T, M, K, y)
        if self.observers:
            # the line's bending moment EI t x t' is minus the nodal moment vector
            x, tangents, mv = state.x, state.t, -state.moment_vector
            for obs in self.observers:
                obs.sample(t, x, tangents, T, mv, window)
        if record and len(self.stations):
            self._at_stations(row, state)
        if record:
            for k in self.columns:
                self.ts[k].append(float(row[k]))
            if self.save_states:
                self.states["t"].append(t)
                self.states["x"].append(np.array(state.x, float))
                self.states["v"].append(np.array(state.v, float))
                self.states["tension"].append(np.array(T, float))
                self.states["moment"].append(np.array(M, float))
                self.states["moment_vector"].append(np.array(state.moment_vector, float))

    def _at_stations(self, row: dict, state: NodalState) -> None:
        """The stations' columns of ``row``: the nodal values interpolated linearly."""
        i, w = self.station_at
        nodal = {"tension": state.tension, "moment": state.moment,
                 "curvature": state.curvature, "x": state.x[:, 0], "y": state.x[:, 1],
                 "z": state.x[:, 2]}
        for obs in self.observers:
            for q in getattr(obs, "station_quantities", ()):
                nodal[q] = obs.nodal(q)
        for q in self.station_quantities:
            a = np.asarray(nodal[q], float)
            values = (1.0 - w) * a[i] + w * a[np.minimum(i + 1, len(a) - 1)]
            for k, v in enumerate(values):
                row[station_column(k, q)] = v

    def _window(self, row: dict, T, M, K, y) -> None:
        e = self.env
        np.minimum(e["tension_min"], T, out=e["tension_min"])
        np.maximum(e["tension_max"], T, out=e["tension_max"])
        np.maximum(e["moment_max"], M, out=e["moment_max"])
        np.maximum(e["curvature_max"], K, out=e["curvature_max"])
        np.minimum(e["y_min"], y, out=e["y_min"])
        np.maximum(e["y_max"], y, out=e["y_max"])
        sums = self.sums
        sums["T"] += T
        sums["T2"] += T * T
        sums["K"] += K
        sums["K2"] += K * K
        st = self.stats
        self.samples += 1
        self.top_tension.append(float(row["hang_off_tension"]))
        self.line_min_tension.append(float(row["min_tension"]))
        self.line_max_moment.append(float(row["max_moment"]))
        self.times.append(float(row["time"]))
        for key, value, pick in (("max_hang_off_tension", row["hang_off_tension"], max),
                                 ("min_hang_off_tension", row["hang_off_tension"], min),
                                 ("min_touchdown_s", row["touchdown_s"], min),
                                 ("max_touchdown_s", row["touchdown_s"], max)):
            if np.isfinite(value):
                st[key] = float(value) if key not in st else pick(st[key], float(value))
        if "min_tension" not in st or row["min_tension"] < st["min_tension"]:
            st["min_tension"], st["min_tension_s"] = float(row["min_tension"]), float(
                row["min_tension_s"])
            st["min_tension_time"] = float(row["time"])
        if "max_moment" not in st or row["max_moment"] > st["max_moment"]:
            st["max_moment"], st["max_moment_s"] = float(row["max_moment"]), float(
                row["max_moment_s"])
            st["max_moment_time"] = float(row["time"])

    def timeseries(self) -> dict:
        return {k: np.asarray(v, float) for k, v in self.ts.items()}

    def envelope(self) -> dict:
        """The envelopes along s, and the window's mean and standard deviation of the
        tension [N] and curvature [1/m] (``tension_mean``, ``tension_std``,
        ``curvature_mean``, ``curvature_std``; population statistics of the samples)."""
        out = {"s": self.s.copy(), **{k: v.copy() for k, v in self.env.items()}}
        sub = out["submergence_min"]
        sub[~np.isfinite(sub)] = np.nan             # no surface: an empty column
        n = max(self.samples, 1)
        for q, key in (("T", "tension"), ("K", "curvature")):
            mean = self.sums[q] / n
            out[f"{key}_mean"] = mean
            out[f"{key}_std"] = np.sqrt(np.maximum(self.sums[q + "2"] / n - mean * mean, 0.0))
        for obs in self.observers:
            out.update(obs.envelope())
        return out

    def states_arrays(self) -> dict | None:
        if not self.save_states:
            return None
        return {"t": np.asarray(self.states["t"]), "s": self.s.copy(),
                **{k: np.asarray(self.states[k]) for k in ("x", "v", "tension", "moment",
                                                           "moment_vector")}}

    def statistics(self, end: float) -> dict:
        """The extremes of the window from the start to ``end`` [s] (``dynamic_*`` keys of
        summary.json; [N], [N m], [m], [s]); ``stations`` [m], the arc lengths of the
        ``station_K_*`` columns (K - 1 the index)."""
        st = dict(self.stats)
        out = {"statistics_start": self.start, "statistics_end": end,
               "statistics_samples": self.samples}
        if len(self.stations):       # the arc lengths [m] of the station_K_* columns
            out["stations"] = [float(v) for v in self.stations]
        if "max_hang_off_tension" in st:
            st["hang_off_tension_range"] = st["max_hang_off_tension"] - st[
                "min_hang_off_tension"]
        if self.top_tension:
            x = np.asarray(self.top_tension)
            st["hang_off_tension_mean"] = float(np.mean(x))
            st["hang_off_tension_std"] = float(np.std(x))
            if self.irregular:
                st.update(most_probable_maximum(np.asarray(self.times), x))
                # the extremes over the storm (riser.design.extremes: a Weibull fit of
                # the upper half of the peaks, its bootstrap interval, the Rayleigh form):
                # the hang-off tension, the least tension and the largest moment along s
                st.update(storm_statistics(self.times, {
                    "hang_off_tension": (x, False),
                    "min_tension": (self.line_min_tension, True),
                    "max_moment": (self.line_max_moment, False)}, self.storm_duration))
        if len(self.env["tension_max"]) and np.isfinite(self.env["tension_max"][0]):
            j = int(np.argmax(self.env["tension_max"]))
            st["max_tension"], st["max_tension_s"] = float(self.env["tension_max"][j]), float(
                self.s[j])
        out.update({f"dynamic_{k}": v for k, v in st.items()})
        for obs in self.observers:
            out.update(obs.statistics())
        return out


#: the storm duration of the most probable maximum [s] (3 h, the design storm's)
STORM_DURATION = 10800.0


def most_probable_maximum(t: np.ndarray, x: np.ndarray) -> dict:
    """Statistics of an irregular response record x at times t [s] (``dynamic_*`` keys):
    the mean zero-upcrossing period Tz [s] (upcrossings of the mean counted in the record)
    and the most probable maximum over :data:`STORM_DURATION` by the Rayleigh
    distribution of the peaks of a narrow-banded Gaussian process, mean + std sqrt(2
    ln(D / Tz)) (a broad-banded or non-Gaussian response, a slack line or a seabed
    contact that opens, is outside that model: the record's own max is given beside)."""
    mean, std = float(np.mean(x)), float(np.std(x))
    up = np.flatnonzero((x[:-1] < mean) & (x[1:] >= mean))
    span = float(t[-1] - t[0]) if len(t) > 1 else 0.0
    if len(up) < 2 or std == 0.0 or span <= 0.0:
        return {}
    tz = float(t[up[-1]] - t[up[0]]) / (len(up) - 1)
    n = STORM_DURATION / tz
    return {"hang_off_tension_tz": tz,
            "hang_off_tension_mpm_3h": mean + std * float(np.sqrt(2.0 * np.log(n)))}

"""What a dynamic run records: time series, envelopes along s and statistics over a window.

Sampling: :class:`Recorder` is called every envelope interval (at most period/40 of a
harmonic top motion, an exact divisor of the output interval; see vfife/dynamics/run.py).
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
States (``[dynamics] save_states``): t (k,), s (n,), x (k, n, 3) [m], v (k, n, 3) [m/s],
tension (k, n) [N] (effective) and moment (k, n) [N m] at the nodes, and moment_vector
(k, n, 3) [N m] (the nodal moment's global x, y, z components, -EI t x t': minus the
signed in-plane bending of a planar line is its z component).
"""

from __future__ import annotations

import numpy as np

TIMESERIES = ("time", "hang_off_x", "hang_off_y", "hang_off_z", "hang_off_tension",
              "touchdown_s", "touchdown_tension", "min_tension", "min_tension_s",
              "max_moment", "max_moment_s", "kinetic_energy")
#: time-series columns that hold an arc length [m]
ARC_LENGTH_COLUMNS = ("touchdown_s", "min_tension_s", "max_moment_s")
#: summary keys (:meth:`Recorder.statistics`) that hold an arc length [m]
ARC_LENGTH_KEYS = ("dynamic_min_touchdown_s", "dynamic_max_touchdown_s",
                   "dynamic_min_tension_s", "dynamic_max_moment_s", "dynamic_max_tension_s")
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


def _surface(model) -> np.ndarray:
    """The sea surface's height [m] over every node of ``model`` as the run has it: the
    waves' depth + eta at the node (evaluated at the sample's time), else the still water
    level, inf without a surface (no water_depth)."""
    return model.waves.WT[6] if model.use_waves else model.ysurf


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
        along s; ``statistics()`` -> summary figures. One fresh set per run.
    """

    def __init__(self, s: np.ndarray, start: float, save_states: bool, has_seabed: bool,
                 elevation=None, irregular: bool = False, observers=()):
        self.s = np.asarray(s, float)
        self.start = float(start)
        self.save_states = save_states
        self.has_seabed = has_seabed
        self.elevation = elevation
        self.irregular = irregular
        self.observers = tuple(observers)
        self.times: list[float] = []              # the window's sample times
        n = len(self.s)
        self.columns = TIMESERIES + (("wave_elevation",) if elevation is not None else ())
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

        for obs in self.observers:
            obs.start(self.s)

    def sample(self, t: float, model, ke: float, record: bool) -> None:
        """Take the state of ``model`` at time ``t`` [s] (kinetic energy ``ke`` [J]);
        ``record``: an output time (time series, states)."""
        r = model.nodal_results()
        T, M, K = r["tension"], r["moment"], r["curvature"]
        y = model.X[1]
        top = model.X[:, -1]
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
            sub = _surface(model) - y
            e = self.env
            for key, later in (("tension_min", T < e["tension_min"]),
                               ("curvature_max", K > e["curvature_max"]),
                               ("submergence_min", sub < e["submergence_min"])):
                e[key + "_time"][later] = t      # the first time the extreme is reached
            np.minimum(e["submergence_min"], sub, out=e["submergence_min"])
            self._window(row, T, M, K, y)
        if self.observers:
            # the line's bending moment EI t x t' is minus the nodal moment vector
            x, tangents, mv = model.positions(), model.directors(), -r["moment_vector"].T
            for obs in self.observers:
                obs.sample(t, x, tangents, T, mv, window)
        if record:
            for k in self.columns:
                self.ts[k].append(float(row[k]))
            if self.save_states:
                self.states["t"].append(t)
                self.states["x"].append(model.positions())
                self.states["v"].append(model.V.T.copy())
                self.states["tension"].append(T.copy())
                self.states["moment"].append(M.copy())
                self.states["moment_vector"].append(r["moment_vector"].T.copy())

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
        summary.json; [N], [N m], [m], [s])."""
        st = dict(self.stats)
        out = {"statistics_start": self.start, "statistics_end": end,
               "statistics_samples": self.samples}
        if "max_hang_off_tension" in st:
            st["hang_off_tension_range"] = st["max_hang_off_tension"] - st[
                "min_hang_off_tension"]
        if self.top_tension:
            x = np.asarray(self.top_tension)
            st["hang_off_tension_mean"] = float(np.mean(x))
            st["hang_off_tension_std"] = float(np.std(x))
            if self.irregular:
                st.update(most_probable_maximum(np.asarray(self.times), x))
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

"""The design checks of a dynamic run, sample by sample (:class:`DynamicDesign`): the
largest utilisation and von Mises stress along the line over the statistics window, and
the record of wall tension and moment components that fatigue counts
(:func:`riser.design.fatigue.time_domain`).

An observer of a time-domain method's recorder (the method never imports it: the method
registry, ``verification/methods.py``, hands it over): :meth:`DynamicDesign.start` with
the stations, then :meth:`DynamicDesign.sample` with each state (positions, tangents,
effective tension and bending-moment vectors at the stations, SI); the first sample is
the static state, the functional load effect of the checks
(:mod:`riser.design.checks`). The moment vectors are resolved across the tangent into the
in-plane and out-of-plane components of :mod:`riser.model.frame` (the line's plane through its
ends).
"""

from __future__ import annotations

import numpy as np

from ..model.frame import LinePlane, plane_columns
from . import dnv_f201
from .checks import utilisation
from .extremes import storm_statistics
from .fatigue import fatigue_verdict, time_domain
from .wall import pressures, stresses, wall_at, wall_tension


class DynamicDesign:
    """Design checks over a dynamic run of ``scene`` (which has a [design]) at the
    recorder's stations ``s`` [m] (:meth:`start`, or given here); with ``[design.fatigue]``
    it keeps the window's record (wall tension [N], in-plane and out-of-plane moments
    [N m] at every station and sample)."""

    def __init__(self, scene, s=None):
        self.scene, self.design = scene, scene.design
        # the storm of the most probable maxima [s] (the recorder takes it from here)
        self.storm_duration = float(self.design.storm_duration)
        self.irregular = scene.waves is not None and scene.waves.spectrum is not None
        if s is not None:
            self.start(s)

    def start(self, s) -> None:
        """The stations' arc lengths ``s`` [m], before the first sample."""
        scene = self.scene
        self.s = np.asarray(s, float)
        self.wall = wall_at(scene, self.s)
        # the resistances that do not change with the loads: once, not every sample
        self.fixed = (dnv_f201.resistances(self.design, self.wall)
                      if self.design.code == "dnv-st-f201" else None)
        self.plane = LinePlane.of(scene)
        self.static = None
        n = len(self.s)
        self.u_max = np.full(n, -np.inf)
        self.vm_max = np.full(n, -np.inf)
        self.peak = {"utilisation": -np.inf, "von_mises": -np.inf}
        self.where: dict = {}
        self.keep = self.design.fatigue is not None
        self.record: list[np.ndarray] = []
        self.times: list[float] = []
        self.u_line: list[float] = []     # the largest utilisation along s, each sample
        self.u_times: list[float] = []
        self._fatigue: dict | None = None         # the record's count, once

    def components(self, x, tangents, moment_vectors):
        """(M_in, M_out) [N m] of bending-moment vectors (n, 3) at stations with positions
        ``x`` (n, 3) and unit tangents (n, 3) (:func:`riser.model.frame.plane_columns`)."""
        _, m_in, m_out = plane_columns(self.plane, x[:, 0], x[:, 2], tangents, moment_vectors)
        return m_in, m_out

    #: the quantity at the nodes that the recorder interpolates to ``[dynamics] stations``
    #: (``station_K_utilisation``, :meth:`nodal`)
    station_quantities = ("utilisation",)

    def sample(self, t: float, x, tangents, tension, moment_vectors, window: bool) -> None:
        """Take a state at time ``t`` [s]: positions x (n, 3) [m], unit tangents (n, 3),
        effective tension (n,) [N], bending-moment vectors (n, 3) [N m] (the line's,
        EI t x t'); ``window``: inside the statistics window."""
        T = np.asarray(tension, float)
        m_in, m_out = self.components(np.asarray(x, float), tangents, moment_vectors)
        if self.static is None:
            self.static = (T.copy(), m_in.copy(), m_out.copy())
        self.latest = (np.asarray(x, float)[:, 1], T, m_in, m_out, None)
        if not window:
            return
        u, st, tw = self._checks(*self.latest[:4])
        self.latest = self.latest[:4] + (u,)
        np.maximum(self.u_max, u, out=self.u_max)
        np.maximum(self.vm_max, st.von_mises, out=self.vm_max)
        self.u_line.append(float(np.max(u)))
        self.u_times.append(float(t))
        for key, values in (("utilisation", u), ("von_mises", st.von_mises)):
            i = int(np.argmax(values))
            if values[i] > self.peak[key]:
                self.peak[key] = float(values[i])
                self.where[key] = (float(self.s[i]), float(t))
        if self.keep:
            self.record.append(np.stack([tw, m_in, m_out]))
            self.times.append(float(t))

    def _checks(self, y, T, m_in, m_out):
        """(utilisation [-], the wall's stresses, wall tension [N]) at the stations of a
        state: heights y [m], effective tension T [N], moments m_in, m_out [N m]; the
        load effects over the static state's (the first sample's) with gamma_f, gamma_e."""
        wall, d = self.wall, self.design
        p_i, p_e = pressures(self.scene, wall, y, float(y[-1]))
        tw = wall_tension(self.scene, wall, T, p_i, p_e)
        st = stresses(wall, tw, np.hypot(m_in, m_out), p_i, p_e)
        T_f, in_f, out_f = self.static
        g_f, g_e = d.gamma_f, d.gamma_e
        m_d = np.hypot(g_f * in_f + g_e * (m_in - in_f), g_f * out_f + g_e * (m_out - out_f))
        t_ed = g_f * T_f + g_e * (T - T_f)
        return utilisation(d, wall, p_i, p_e, m_d, t_ed, st.von_mises, self.fixed), st, tw

    def nodal(self, quantity: str) -> np.ndarray:
        """``quantity`` (``utilisation`` [-]) at the recorder's nodes (``s``) in the
        latest sample, inside the statistics window or not (the recorder interpolates it
        to ``[dynamics] stations``)."""
        if quantity != "utilisation":
            raise KeyError(quantity)
        if self.latest[4] is None:
            self.latest = self.latest[:4] + (self._checks(*self.latest[:4])[0],)
        return self.latest[4]

    def envelope(self) -> dict:
        """Envelope columns along s: ``utilisation_max`` [-], ``von_mises_max`` [Pa], and
        with fatigue those of :func:`riser.design.fatigue.time_domain`; with a
        ``design_life`` also ``fatigue_utilisation`` [-] (:meth:`verdict`)."""
        out = {"utilisation_max": self.u_max.copy(), "von_mises_max": self.vm_max.copy()}
        fat = self.fatigue()
        if fat is not None:
            out.update({k: v for k, v in fat.items() if np.ndim(v) == 1})
        v = self.verdict()
        if v is not None:
            out["fatigue_utilisation"] = v["fatigue_utilisation"]
        return out

    def fatigue(self) -> dict | None:
        """The time-domain fatigue of the window's record (None without
        ``[design.fatigue]`` or with fewer than 3 samples); computed once."""
        if not self.keep or len(self.times) < 3:
            return None
        if self._fatigue is None:
            rec = np.asarray(self.record)                     # (k, 3, n)
            duration = self.times[-1] - self.times[0]
            self._fatigue = time_domain(self.scene, self.s, rec[:, 0], rec[:, 1], rec[:, 2],
                                        duration)
        return self._fatigue

    def verdict(self) -> dict | None:
        """The fatigue verdict of the window's record repeated (its life along s against
        ``[design] design_life`` x DFF, :func:`riser.design.fatigue.fatigue_verdict`);
        None without a ``design_life`` or without the record's fatigue."""
        fat = self.fatigue()
        life = self.design.design_life
        if fat is None or life is None:
            return None
        return fatigue_verdict(self.s, fat["fatigue_life"], life,
                               self.design.fatigue.design_fatigue_factor)

    def statistics(self) -> dict:
        """summary.json's ``dynamic_`` design figures: the largest utilisation and von
        Mises stress [Pa], where [m] and when [s], whether the line passes; with fatigue
        the worst station's damage over the record and its life [years]; with a
        ``design_life`` the inputs ``design_life`` [years] and ``design_fatigue_factor``
        and the verdict (:meth:`verdict`): ``dynamic_max_fatigue_utilisation``, its
        ``_s`` [m], ``dynamic_fatigue_verdict`` ('pass' / 'fail')."""
        out = {"dynamic_design_code": self.design.code}
        for key in ("utilisation", "von_mises"):
            if key in self.where:
                s, t = self.where[key]
                out.update({f"dynamic_max_{key}": self.peak[key],
                            f"dynamic_max_{key}_s": s, f"dynamic_max_{key}_time": t})
        if "utilisation" in self.where:
            out["dynamic_design_passes"] = bool(self.peak["utilisation"] <= 1.0)
            if self.irregular:     # its most probable maximum over the storm
                ext = storm_statistics(self.u_times, {"max_utilisation": (self.u_line, False)},
                                       self.storm_duration)
                out.update({f"dynamic_{k}": v for k, v in ext.items() if k != "storm_duration"})
        fat = self.fatigue()
        if fat is not None:
            out.update({f"dynamic_{k}": v for k, v in fat.items() if np.ndim(v) == 0})
        v = self.verdict()
        if v is not None:
            out.update({"design_life": self.design.design_life,
                        "design_fatigue_factor": self.design.fatigue.design_fatigue_factor,
                        "dynamic_max_fatigue_utilisation": v["max_fatigue_utilisation"],
                        "dynamic_max_fatigue_utilisation_s": v["max_fatigue_utilisation_s"],
                        "dynamic_fatigue_verdict": v["fatigue_verdict"]})
        return out

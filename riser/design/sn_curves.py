"""DNV-RP-C203 (2016 edition) S-N curves of welded steel details.

A curve gives the number of cycles N to failure under a constant stress range S:

    log10 N = log_a1 - m1 log10 S        for N <= n_switch
    log10 N = log_a2 - m2 log10 S        for N >  n_switch

with S in MPa (the standard's tables). The three environments are the standard's:

- ``air``: Table 2-1, two slopes (m1 = 3, or 4 for B1/B2; m2 = 5), the slope changing
  at N = 1e7;
- ``seawater-cp``: in seawater with cathodic protection, Table 2-2, the same m1, m2,
  log a2 and k as in air, a lower log a1, the slope changing at N = 1e6;
- ``free-corrosion``: in seawater without protection, Table 2-4, one slope m = 3.

Thickness effect (RP-C203 eq. 2.4.3): for a wall thicker than the reference thickness
t_ref (25 mm for welded connections other than tubular joints) the stress range is
replaced by S (t / t_ref)^k; a wall of t <= t_ref takes no correction (no credit for
thin walls). A stress concentration factor ``scf`` multiplies the nominal range.

Every public function takes and returns stresses in Pa; the MPa of the tables stay inside.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

ENVIRONMENTS = ("air", "seawater-cp", "free-corrosion")
CURVE_NAMES = ("B1", "B2", "C", "C1", "C2", "D", "E", "F", "F1", "F3", "G", "W1", "W2",
               "W3")

#: Pa per MPa (the tables' unit)
MPA = 1.0e6
#: RP-C203's reference thickness of welded connections other than tubular joints [m]
T_REF = 0.025
#: N at the slope change: in air (Table 2-1) and in seawater with CP (Table 2-2)
N_SWITCH_AIR = 1.0e7
N_SWITCH_SEAWATER_CP = 1.0e6

#: Table 2-1 (air): name -> (m1, log a1, log a2, k); m2 = 5 for all
_AIR = {
    "B1": (4.0, 15.117, 17.146, 0.00),
    "B2": (4.0, 14.885, 16.856, 0.00),
    "C": (3.0, 12.592, 16.320, 0.05),
    "C1": (3.0, 12.449, 16.081, 0.10),
    "C2": (3.0, 12.301, 15.835, 0.15),
    "D": (3.0, 12.164, 15.606, 0.20),
    "E": (3.0, 12.010, 15.350, 0.20),
    "F": (3.0, 11.855, 15.091, 0.25),
    "F1": (3.0, 11.699, 14.832, 0.25),
    "F3": (3.0, 11.546, 14.576, 0.25),
    "G": (3.0, 11.398, 14.330, 0.25),
    "W1": (3.0, 11.261, 14.101, 0.25),
    "W2": (3.0, 11.107, 13.845, 0.25),
    "W3": (3.0, 10.970, 13.617, 0.25),
}
#: Table 2-2 (seawater with cathodic protection): name -> log a1 (the rest as in air)
_SEAWATER_CP_LOG_A1 = {
    "B1": 14.917, "B2": 14.685, "C": 12.192, "C1": 12.049, "C2": 11.901, "D": 11.764,
    "E": 11.610, "F": 11.455, "F1": 11.299, "F3": 11.146, "G": 10.998, "W1": 10.861,
    "W2": 10.707, "W3": 10.570,
}
#: Table 2-4 (free corrosion, one slope m = 3): name -> (log a, k)
_FREE_CORROSION = {
    "B1": (12.436, 0.00), "B2": (12.262, 0.00), "C": (12.115, 0.15),
    "C1": (11.972, 0.15), "C2": (11.824, 0.15), "D": (11.687, 0.20),
    "E": (11.533, 0.20), "F": (11.378, 0.25), "F1": (11.222, 0.25),
    "F3": (11.068, 0.25), "G": (10.921, 0.25), "W1": (10.784, 0.25),
    "W2": (10.630, 0.25), "W3": (10.493, 0.25),
}
M2 = 5.0
M_FREE_CORROSION = 3.0


@dataclass(frozen=True)
class SNCurve:
    """One DNV-RP-C203 S-N curve (the tables' constants: S in MPa).

    ``m2``, ``log_a2`` and ``n_switch`` are None for a single-slope curve (free
    corrosion). ``k`` is the thickness exponent, ``t_ref`` the reference thickness [m].
    """

    name: str
    environment: str
    m1: float
    log_a1: float
    m2: float | None = None
    log_a2: float | None = None
    n_switch: float | None = None
    k: float = 0.0
    t_ref: float = T_REF

    @property
    def two_slopes(self) -> bool:
        """Whether the curve bends at ``n_switch`` (air and seawater with CP)."""
        return self.n_switch is not None

    @property
    def switch_stress(self) -> float:
        """The stress range at the slope change [Pa] (from the first branch; no thickness
        correction). A single-slope curve has none: ``nan``."""
        if not self.two_slopes:
            return float("nan")
        return 10.0 ** ((self.log_a1 - np.log10(self.n_switch)) / self.m1) * MPA

    def thickness_factor(self, thickness: float | None) -> float:
        """(t / t_ref)^k for t > t_ref, else 1 (eq. 2.4.3); ``thickness`` in m."""
        if thickness is None or thickness <= self.t_ref:
            return 1.0
        return float((thickness / self.t_ref) ** self.k)

    def cycles(self, stress_range, thickness: float | None = None,
               scf: float = 1.0) -> np.ndarray:
        """Cycles to failure N of the nominal stress ranges ``stress_range`` [Pa].

        The range is multiplied by ``scf`` and by the thickness factor, converted to MPa
        and read off the branch it falls on: the first branch for ranges at or above the
        switch range (N <= n_switch), the second below. A zero range gives ``inf``.
        Vectorised: returns an array of the shape of ``stress_range``.
        """
        s = np.asarray(stress_range, dtype=float) * (scf * self.thickness_factor(thickness)
                                                     / MPA)
        if np.any(s < 0.0):
            raise ValueError("stress ranges must be >= 0")
        with np.errstate(divide="ignore"):
            log_s = np.log10(s)                         # -inf for a zero range
            log_n = self.log_a1 - self.m1 * log_s
            if self.two_slopes:
                beyond = log_n > np.log10(self.n_switch)
                log_n = np.where(beyond, self.log_a2 - self.m2 * log_s, log_n)
        return 10.0 ** log_n

    def stress_range_at(self, n_cycles, thickness: float | None = None) -> np.ndarray:
        """The stress range [Pa] that fails in ``n_cycles`` cycles (the inverse of
        :meth:`cycles` with scf = 1): the thickness factor divides the table's range."""
        log_n = np.log10(np.asarray(n_cycles, dtype=float))
        log_s = (self.log_a1 - log_n) / self.m1
        if self.two_slopes:
            beyond = log_n > np.log10(self.n_switch)
            log_s = np.where(beyond, (self.log_a2 - log_n) / self.m2, log_s)
        return 10.0 ** log_s * MPA / self.thickness_factor(thickness)


def _build() -> dict[tuple[str, str], SNCurve]:
    """The tables as curves keyed (environment, name)."""
    out = {}
    for name, (m1, log_a1, log_a2, k) in _AIR.items():
        out["air", name] = SNCurve(name, "air", m1, log_a1, M2, log_a2, N_SWITCH_AIR, k)
        out["seawater-cp", name] = SNCurve(name, "seawater-cp", m1,
                                           _SEAWATER_CP_LOG_A1[name], M2, log_a2,
                                           N_SWITCH_SEAWATER_CP, k)
    for name, (log_a, k) in _FREE_CORROSION.items():
        out["free-corrosion", name] = SNCurve(name, "free-corrosion", M_FREE_CORROSION,
                                              log_a, k=k)
    return out


#: every curve of the three tables, keyed (environment, name)
CURVES: dict[tuple[str, str], SNCurve] = _build()


def sn_curve(name: str, environment: str) -> SNCurve:
    """The curve ``name`` (e.g. ``"D"``) of ``environment`` (one of ENVIRONMENTS).

    Raises KeyError naming the known curves and environments for an unknown one.
    """
    try:
        return CURVES[environment, name]
    except KeyError:
        raise KeyError(f"no DNV-RP-C203 S-N curve {name!r} in {environment!r}: known "
                       f"curves {', '.join(CURVE_NAMES)}; environments "
                       f"{', '.join(ENVIRONMENTS)}") from None

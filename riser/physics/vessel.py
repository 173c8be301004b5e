"""The vessel the hang-off hangs from (scene table ``[vessel]``): its displacement RAOs
per wave heading (``[[vessel.raos]]``) and the hang-off's place on it. The vessel moves
with the scene's waves (:mod:`riser.physics.waves`): each wave component moves it by its RAO, and
the hang-off follows the vessel's rigid-body motion at its lever arm.

Axes (SI; angles in degrees). The vessel's axes are the scene's rotated about the vertical
by ``heading_deg``: surge along (cos psi, 0, sin psi), heave along +y (up), sway along
(-sin psi, 0, cos psi) (the scene's +z at psi = 0); roll, yaw and pitch are right-handed
rotations about the surge, heave and sway axes. The RAO table's ``heading_deg`` is the
waves' direction of travel relative to the surge axis, measured as the scene's headings
(from surge towards sway). OrcaFlex (x forward, y port, z up) converts by: sway = -y,
pitch = -pitch, roll and yaw as they are, headings negated.

RAOs: amplitude per metre of wave amplitude ([m/m] for surge, sway, heave, [deg/m] for
roll, pitch, yaw) and a *phase lag* [deg] relative to the wave crest at the vessel's RAO
origin, OrcaFlex's convention: a component eta = a cos(omega t - epsilon_o) at the RAO
origin moves the vessel by R a cos(omega t - epsilon_o - phi_R) in that degree of
freedom. Between the given periods the amplitude and the (unwrapped) phase are linear in
the period, constant beyond them; between headings likewise the amplitude and the
unwrapped phase are linear in the heading, periodic over 360 deg (the two neighbouring
tables' values at the component's period, the phase from one to the other the shorter
way round, np.unwrap's rule for consecutive values, as along the periods: a phase that
passes through +-180 deg between two tables goes through 180 deg, where the complex
values' mean would shrink the amplitude); one table: every heading.

Motion of the hang-off: d = u + theta x r (small rotations: |theta| << 1 rad, a
displacement error of ~|theta|^2 |r| / 2, stated in the docs; a scene refuses
rotations beyond :data:`MAX_ROTATION_DEG`), u the RAO origin's
translation, theta its rotation vector and r the lever arm ``hang_off_on_vessel`` from
the RAO origin to the hang-off; the ramp is the waves' (``[environment.waves]
ramp_time``). The hang-off's direction (a clamped end) is not turned by the vessel's
rotation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .dynamics import MAX_TOP_ACCELERATION, MAX_TOP_SPEED
from ..spec import Part, check_fields, part_error, spec

#: the degrees of freedom of an RAO table, translations then rotations
DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
#: the largest rotation amplitude [deg] of the vessel in a scene's waves (checked by
#: :func:`riser.physics.sea_state.check_vessel_motion`). The hang-off's path is linear in the
#: rotation, d = u + theta x r: its error, ~|theta|^2 |r| / 2, is 1.5 % of the lever arm
#: at 10 deg (sin theta departs from theta by 0.5 %) and grows as theta^2 beyond. Moored
#: vessels rotate less: an FPSO or a semisubmersible pitches or rolls by ~2-8 deg in a
#: survival storm; a larger amplitude is an RAO in the wrong unit (deg/m typed for rad/m
#: is 57 times too large), for the wrong period, or a vessel outside the small-rotation
#: model.
MAX_ROTATION_DEG = 10.0


def _dof_field(name: str, rotation: bool):
    unit = "deg/m" if rotation else "m/m"
    also = "one per period; in the waves, " + (
        f"the rotation <= {MAX_ROTATION_DEG:g} deg" if rotation else
        f"the hang-off <= {MAX_TOP_SPEED:g} m/s, {MAX_TOP_ACCELERATION:g} m/s2")
    return spec(kind="numbers", ge=0.0, le=100.0, unit=unit, also=also,
                doc=f"{name} RAO amplitude per metre of wave amplitude")


def _phase_field(name: str):
    return spec(kind="numbers", ge=-3600.0, le=3600.0, unit="deg", also="one per period",
                doc=f"{name} phase lag behind the wave crest at the RAO origin")


@dataclass(frozen=True)
class RAOTable(Part):
    """Displacement RAOs of one wave heading (see the module docstring)."""

    heading_deg: float = spec(ge=-360.0, le=360.0, unit="deg",
                              doc="wave direction relative to the vessel's surge axis")
    periods: tuple[float, ...] = spec(kind="numbers", ge=0.5, le=200.0, unit="s",
                                      also="strictly increasing",
                                      doc="wave periods of the table")
    surge: tuple[float, ...] = _dof_field("surge", False)
    surge_phase_deg: tuple[float, ...] = _phase_field("surge")
    sway: tuple[float, ...] = _dof_field("sway", False)
    sway_phase_deg: tuple[float, ...] = _phase_field("sway")
    heave: tuple[float, ...] = _dof_field("heave", False)
    heave_phase_deg: tuple[float, ...] = _phase_field("heave")
    roll: tuple[float, ...] = _dof_field("roll", True)
    roll_phase_deg: tuple[float, ...] = _phase_field("roll")
    pitch: tuple[float, ...] = _dof_field("pitch", True)
    pitch_phase_deg: tuple[float, ...] = _phase_field("pitch")
    yaw: tuple[float, ...] = _dof_field("yaw", True)
    yaw_phase_deg: tuple[float, ...] = _phase_field("yaw")

    def __post_init__(self) -> None:
        check_fields(self)
        error, p = part_error(self), self.periods
        for i in range(1, len(p)):
            if not p[i] > p[i - 1]:
                raise error(f"periods[{i}]", f"must be > periods[{i - 1}] = {p[i - 1]:g} s "
                            f"(strictly increasing), got {p[i]:g}")
        for dof in DOFS:
            for name in (dof, f"{dof}_phase_deg"):
                if len(getattr(self, name)) != len(p):
                    raise error(name, f"must have one entry per period ({len(p)}), got "
                                f"{len(getattr(self, name))}")

    def amplitude_phase(self, periods) -> tuple[np.ndarray, np.ndarray]:
        """((6, n) amplitudes R [m/m; rotations rad/m], (6, n) phase lags phi [rad]) at
        ``periods`` [s]: amplitude and unwrapped phase linear in the period, constant
        beyond the table."""
        T = np.asarray(periods, float)
        amps = np.empty((6, T.size))
        phases = np.empty((6, T.size))
        for j, dof in enumerate(DOFS):
            amp = np.interp(T, self.periods, getattr(self, dof))
            ph = np.unwrap(np.radians(getattr(self, f"{dof}_phase_deg")))
            phases[j] = np.interp(T, self.periods, ph)
            amps[j] = np.radians(amp) if j >= 3 else amp
        return amps, phases

    def complex_rao(self, periods) -> np.ndarray:
        """(6, n) complex RAOs R e^{-i phi} at ``periods`` [s] (rotations in rad/m):
        amplitude and unwrapped phase linear in the period, constant beyond the table."""
        amps, phases = self.amplitude_phase(periods)
        return amps * np.exp(-1j * phases)


@dataclass(frozen=True)
class Vessel(Part):
    """The vessel: its heading, the hang-off's lever arm, its RAO tables (see the module
    docstring); ``raos`` is read from ``[[vessel.raos]]``."""

    raos: tuple[RAOTable, ...] = field(default=())
    heading_deg: float = spec(0.0, ge=-360.0, le=360.0, unit="deg",
                              doc="direction of the surge axis: 0 = +x, 90 = +z")
    hang_off_on_vessel: tuple[float, ...] = spec((0.0, 0.0, 0.0), "numbers", length=3,
                                                 ge=-500.0, le=500.0, unit="m",
                                                 doc="(surge, heave, sway) lever arm from "
                                                     "the RAO origin to the hang-off")

    def __post_init__(self) -> None:
        check_fields(self)
        error = part_error(self)
        if isinstance(self.raos, list):
            object.__setattr__(self, "raos", tuple(self.raos))
        if not self.raos:
            raise error("raos", "give at least one [[vessel.raos]] table (the vessel's "
                        "RAOs for a wave heading)")
        seen = []
        for i, tab in enumerate(self.raos):
            if not isinstance(tab, RAOTable):
                raise error(f"raos[{i}]", f"must be an RAOTable, got {type(tab).__name__}")
            h = tab.heading_deg % 360.0
            if any(abs(h - o) < 1e-9 for o in seen):
                raise error(f"raos[{i}].heading_deg", f"heading {tab.heading_deg:g} deg "
                            "given twice")
            seen.append(h)

    def axes(self) -> np.ndarray:
        """(3, 3) unit vectors of surge, heave, sway (rows) in the scene's (x, y, z)."""
        p = math.radians(self.heading_deg)
        return np.array([[math.cos(p), 0.0, math.sin(p)], [0.0, 1.0, 0.0],
                         [-math.sin(p), 0.0, math.cos(p)]])

    def lever_arm(self) -> np.ndarray:
        """The lever arm r (3,) from the RAO origin to the hang-off in the scene's axes."""
        return np.asarray(self.hang_off_on_vessel, float) @ self.axes()

    def complex_rao(self, periods, headings_deg) -> np.ndarray:
        """(6, n) complex RAOs for wave components of ``periods`` [s] travelling at scene
        ``headings_deg`` (each (n,)): amplitude and unwrapped phase linear between the
        tables' relative headings, periodic over 360 deg (the module docstring)."""
        T = np.atleast_1d(np.asarray(periods, float))
        rel = (np.atleast_1d(np.asarray(headings_deg, float)) - self.heading_deg) % 360.0
        tabs = sorted(self.raos, key=lambda t: t.heading_deg % 360.0)
        if len(tabs) == 1:
            return tabs[0].complex_rao(T)
        hs = np.array([t.heading_deg % 360.0 for t in tabs])
        amps, phases = (np.stack(v) for v in zip(*(t.amplitude_phase(T) for t in tabs)))
        j = np.searchsorted(hs, rel, side="right") - 1          # the table below (periodic)
        j0, j1 = j % len(hs), (j + 1) % len(hs)
        h0 = hs[j0]
        span = np.where((hs[j1] - h0) % 360.0 == 0.0, 360.0, (hs[j1] - h0) % 360.0)
        w = ((rel - h0) % 360.0) / span                           # (n,) in [0, 1)
        i = np.arange(T.size)
        a0, a1 = amps[j0, :, i].T, amps[j1, :, i].T               # (6, n)
        p0, p1 = phases[j0, :, i].T, phases[j1, :, i].T
        p1 = np.unwrap(np.stack([p0, p1]), axis=0)[1]             # the shorter way round
        return ((1.0 - w) * a0 + w * a1) * np.exp(-1j * ((1.0 - w) * p0 + w * p1))

    def hang_off_amplitudes(self, periods, headings_deg) -> np.ndarray:
        """(3, n) complex amplitudes of the hang-off's displacement (x, y, z) [m] per metre
        of wave amplitude at the RAO origin, for each component: u + theta x r."""
        R = self.complex_rao(periods, headings_deg)
        ax = self.axes()                          # rows: surge, heave, sway
        trans = ax[0][:, None] * R[0] + ax[2][:, None] * R[1] + ax[1][:, None] * R[2]
        rot = ax[0][:, None] * R[3] + ax[2][:, None] * R[4] + ax[1][:, None] * R[5]
        r = self.lever_arm()
        return trans + np.cross(rot.T, r).T

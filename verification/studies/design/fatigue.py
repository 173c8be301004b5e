"""Fatigue by two methods over a scatter diagram (``riser-verify reproduce design``, unit
``fatigue``; ``riser-verify fatigue SCENE``): for each sea state of the scene's
``[[design.fatigue.sea_states]]`` the irregular-sea comparison of
:mod:`verification.comparison.sea.protocol` (the frequency domain about the BVP static
state, the VFIFE's time domain over one repeat period of the same realisation), and the
fatigue damage along the line by four estimates:

- ``rainflow_vfife``: rainflow counts of the VFIFE's stress record (the time domain, the
  nonlinear model: drag, seabed contact and geometry as they are);
- ``rainflow_fd``: rainflow counts of the frequency domain's own record of the same
  realisation (its linear response to the same components with the same phases, over the
  same repeat period): against ``rainflow_vfife`` this isolates the response model (the
  linearisation), the counting being the same;
- ``dirlik_fd`` and ``narrow_band_fd``: the spectral estimates from the frequency
  domain's stress spectrum (Dirlik 1985; Rayleigh ranges): against ``rainflow_fd`` this
  isolates the spectral estimator on this realisation (the record has exactly the
  spectrum's variance, but its ranges are one sample of the distribution).

Stresses: the outer fibre's axial stress at the design's ``points`` around the section
(:mod:`riser.design.fatigue`); each station reports its worst point. Damage per year:
sum over the sea states of probability x damage rate x a year; life = 1 / damage per
year (the design fatigue factor divides it for the allowable life).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from riser.design.checks import amplitude_columns
from riser.design.fatigue import SECONDS_PER_YEAR, spectral, stress_transfer
from riser.design.rainflow_damage import series_damage
from riser.design.sn_curves import sn_curve
from riser.design.wall import wall_at
from riser.errors import SceneError, UnsupportedSceneError
from riser.physics.hang_off_motion import scene_components
from verification.comparison.sea.protocol import compare_sea

#: the four estimates, in the order of the reports
ESTIMATES = ("rainflow_vfife", "rainflow_fd", "dirlik_fd", "narrow_band_fd")
#: samples of the FD's record per shortest component period (the VFIFE samples 40)
FD_SAMPLES_PER_SHORTEST = 40
#: the touchdown zone searched for the touchdown's worst station: from this far below the
#: static touchdown to this far above it [m]
TOUCHDOWN_ZONE = (-50.0, 150.0)


@dataclass
class SeaStateFatigue:
    """The fatigue of one sea state: damage rates [1/s] along ``s`` per estimate, the
    comparison it came from and the figures of the runs."""

    hs: float
    tp: float
    probability: float
    s: np.ndarray
    rates: dict
    record_s: float
    comparison: object
    wall_s: float
    tdp_s: float | None


@dataclass
class ScatterFatigue:
    """The scatter diagram's fatigue: per sea state, and the damage per year along s."""

    scene: object
    states: list
    s: np.ndarray
    per_year: dict = field(default_factory=dict)
    element_length: float = 0.0

    def life(self, estimate: str) -> np.ndarray:
        """Fatigue life [years] along s of an estimate."""
        d = self.per_year[estimate]
        with np.errstate(divide="ignore"):
            return np.where(d > 0.0, 1.0 / np.where(d > 0.0, d, 1.0), np.inf)


def require_fatigue(scene) -> None:
    """The scene has a [design.fatigue] with sea states and an irregular sea (the
    spectrum each cell rescales) and is planar: else a one-line SceneError naming the
    key."""
    d = scene.design
    if d is None or d.fatigue is None:
        raise SceneError(scene.source, "design.fatigue", "required: the S-N curve and the "
                         "scatter diagram of the fatigue assessment")
    if not d.fatigue.sea_states:
        raise SceneError(scene.source, "design.fatigue.sea_states", "required: at least "
                         "one [[design.fatigue.sea_states]] (hs, tp, probability)")
    if scene.waves is None or scene.waves.spectrum is None or \
            scene.waves.spectrum.kind == "table":
        raise SceneError(scene.source, "environment.waves.spectrum", "required: a JONSWAP "
                         "or Pierson-Moskowitz spectrum (each sea state sets its hs and tp)")
    if scene.seabed_model is None:
        raise SceneError(scene.source, "seabed", "required: the fatigue by two methods "
                         "reports the touchdown zone and the hang-off (a line without a "
                         "[seabed] has no touchdown)")
    oop = scene.out_of_plane()
    if oop is not None:
        raise SceneError(scene.source, oop[0], f"the fatigue by two methods takes a planar "
                         f"scene (the frequency domain's sea response carries the in-plane "
                         f"moment only): {oop[1]}")


def sea_state_scene(scene, cell):
    """``scene`` with its spectrum's Hs and Tp those of the scatter diagram's ``cell``."""
    sp = scene.waves.spectrum.replace(hs=cell.hs, tp=cell.tp)
    return scene.replace(waves=scene.waves.replace(spectrum=sp))


def fd_amplitudes(cmp, s) -> tuple:
    """The FD's complex amplitudes (n_w, n) at stations ``s`` [m] of the effective tension,
    the in-plane moment and the vertical displacement per component (transfer times the
    component's complex amplitude a e^{-i eps}), interpolated linearly from its grid."""
    fd, scene = cmp.fd, cmp.matched
    comp = scene_components(scene)
    a = comp.amplitude * np.exp(-1j * comp.phase)

    def at(key):
        h = fd.transfer[key]
        re = np.array([np.interp(s, fd.s, row.real) for row in h])
        im = np.array([np.interp(s, fd.s, row.imag) for row in h])
        return (re + 1j * im) * a[:, None]
    return at("tension"), at("moment"), at("dy"), comp.omega


def fd_record_damage(scene, s, q_sigma, omega, start: float, record: float) -> np.ndarray:
    """Rainflow damage [-] along s of the FD's linear stress record over [start, start +
    record) [s]: q_sigma (n_w, n, p) complex fibre-stress amplitudes [Pa]; each station's
    worst point."""
    fat = scene.design.fatigue
    curve = sn_curve(fat.sn_curve, fat.environment)
    wall = wall_at(scene, s)
    dt = 2.0 * math.pi / float(np.max(omega)) / FD_SAMPLES_PER_SHORTEST
    t = start + dt * np.arange(int(round(record / dt)))
    rot = np.exp(1j * np.outer(t, omega))                                  # (n_t, n_w)
    out = np.zeros(len(s))
    for i in range(len(s)):
        series = (rot @ q_sigma[:, i, :]).real                              # (n_t, p)
        thick = fat.thickness or float(wall.thickness[i])
        out[i] = max(float(series_damage(series[:, j], curve, thick, fat.scf))
                     for j in range(series.shape[1]))
    return out


def run_sea_state(scene, cell, element_length: float | None, progress=None) -> SeaStateFatigue:
    """The four estimates of one sea state (module docstring)."""
    t0 = time.perf_counter()
    sc = sea_state_scene(scene, cell)
    cmp = compare_sea(sc, element_length=element_length, progress=progress)
    res = cmp.vfife_result
    env = res.dynamics.envelope
    s = np.asarray(env["s"], float)
    record = float(res.info["dynamic_fatigue_record_s"])
    h_t, h_m, h_dy, omega = fd_amplitudes(cmp, s)
    q = stress_transfer(cmp.matched, s, h_t, h_m, np.zeros_like(h_m), h_dy)
    spec = spectral(cmp.matched, s, omega, cmp.fd.d_omega, q)
    start = cmp.ramp_s + cmp.settle_s
    rates = {"rainflow_vfife": np.asarray(env["fatigue_damage"]) / record,
             "rainflow_fd": fd_record_damage(cmp.matched, s, q, omega, start,
                                             cmp.record_s) / cmp.record_s,
             "dirlik_fd": spec["fatigue_rate_dirlik"],
             "narrow_band_fd": spec["fatigue_rate_narrow_band"]}
    tdp = cmp.static.profile.tdp_s
    return SeaStateFatigue(cell.hs, cell.tp, cell.probability, s, rates, record, cmp,
                           time.perf_counter() - t0, tdp)


def run_scatter(scene, element_length: float | None = None, progress=None) -> ScatterFatigue:
    """Every sea state of the scene's scatter diagram, and the damage per year."""
    require_fatigue(scene)
    states = []
    cells = scene.design.fatigue.sea_states
    for k, cell in enumerate(cells):
        if progress is not None:
            progress(f"sea state {k + 1}/{len(cells)}: Hs {cell.hs:g} m, Tp {cell.tp:g} s")
        states.append(run_sea_state(scene, cell, element_length, progress))
        if states[0].tdp_s is None:
            raise UnsupportedSceneError(f"{scene.source}: the static line does not touch "
                                        "the seabed: the fatigue by two methods reports "
                                        "the touchdown zone and the hang-off")
    s = states[0].s
    per_year = {e: sum(st.probability * np.interp(s, st.s, st.rates[e]) for st in states)
                * SECONDS_PER_YEAR for e in ESTIMATES}
    h = states[0].comparison.element_length
    return ScatterFatigue(scene, states, s, per_year, h)


def stations(result: ScatterFatigue) -> dict:
    """The reported stations: ``touchdown`` (the largest VFIFE damage in the touchdown
    zone, :data:`TOUCHDOWN_ZONE` about the BVP's static touchdown) and ``hang_off`` (the
    top station), as indices into ``result.s``."""
    s = result.s
    out = {"hang_off": len(s) - 1}
    tdp = result.states[0].tdp_s
    if tdp is not None:
        zone = np.flatnonzero((s >= tdp + TOUCHDOWN_ZONE[0]) & (s <= tdp + TOUCHDOWN_ZONE[1]))
        if zone.size:
            out["touchdown"] = int(zone[np.argmax(result.per_year["rainflow_vfife"][zone])])
    return out


def worst_in_zone(result: ScatterFatigue, estimate: str) -> tuple[float, float]:
    """(largest damage per year, its s [m]) of ``estimate`` in the touchdown zone: each
    method's own worst station (the linear model's peak sits where the static touchdown
    bends, the time domain's is spread by the moving touchdown)."""
    s, d = result.s, result.per_year[estimate]
    tdp = result.states[0].tdp_s
    zone = np.flatnonzero((s >= tdp + TOUCHDOWN_ZONE[0]) & (s <= tdp + TOUCHDOWN_ZONE[1]))
    j = int(zone[np.argmax(d[zone])])
    return float(d[j]), float(s[j])



def fd_utilisation(cmp, duration: float) -> tuple[float, float]:
    """(largest utilisation, its s [m]) of the frequency domain's response: the static
    state plus the most probable maxima of tension and moment over ``duration`` [s]
    (Rayleigh: sigma sqrt(2 ln(duration / Tz))), combined in phase
    (:func:`riser.design.checks.amplitude_columns`)."""
    p, fd = cmp.static.profile, cmp.fd

    def mpm(key):
        sigma = np.interp(p.s, fd.s, fd.std[key])
        tz = np.interp(p.s, fd.s, np.nan_to_num(fd.tz[key], nan=np.inf))
        with np.errstate(divide="ignore", invalid="ignore"):
            n = np.where(np.isfinite(tz) & (tz > 0.0), duration / tz, 1.0)
        return sigma * np.sqrt(2.0 * np.log(np.maximum(n, 1.0)))
    cols = amplitude_columns(cmp.matched, p.s, p.y, p.tension, p.moment, mpm("tension"),
                             mpm("moment"))
    j = int(np.argmax(cols["utilisation"]))
    return float(cols["utilisation"][j]), float(p.s[j])

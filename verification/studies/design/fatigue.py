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
  spectrum's variance, but its ranges are one sample of the distribution);
- ``rainflow_ancf`` (issue 47): rainflow counts of the ANCF's stress record, the second
  nonlinear time domain, run on exactly the VFIFE's scene (the same realisation, ramp,
  settling and record, :func:`ancf_run_scene`) at the same element length, counted by
  the same shared recorder and design observer: against ``rainflow_vfife`` this is the
  nonlinear model solved by two independent methods, judged at the touchdown within
  :data:`ANCF_TOLERANCE` (:func:`ancf_agreement`).

Stresses: the outer fibre's axial stress at the design's ``points`` around the section
(:mod:`riser.design.fatigue`); each station reports its worst point. Damage per year:
sum over the sea states of probability x damage rate x a year; life = 1 / damage per
year.

The verdict (:func:`verdicts`, with ``[design] design_life``): per estimate the fatigue
utilisation DFF x design_life / life along s (:func:`riser.design.fatigue.fatigue_verdict`)
and its worst station; the design's verdict is :data:`DESIGN_ESTIMATE`'s, the others are
shown beside it.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from types import SimpleNamespace

import numpy as np

from riser.design.checks import amplitude_columns
from riser.design.fatigue import (SECONDS_PER_YEAR, fatigue_verdict, spectral,
                                  stress_transfer)
from riser.design.rainflow_damage import series_damage
from riser.design.sn_curves import sn_curve
from riser.design.wall import wall_at
from riser.errors import SceneError, SolveFailed
from riser.physics.hang_off_motion import scene_components
from riser.results.result import Status
from verification.comparison.sea.protocol import compare_sea, sea_run_scene
from verification.methods import method

#: the four estimates every run has, in the order of the reports
ESTIMATES = ("rainflow_vfife", "rainflow_fd", "dirlik_fd", "narrow_band_fd")
#: the ANCF's rainflow (the second time domain): reported beside the VFIFE's when run
ANCF = "rainflow_ancf"
#: the bound on the touchdown's damage, ANCF against VFIFE, at each sea state and in
#: total (the issue's): damage goes as the stress range to the S-N slope m = 3 to 5, so
#: 10 % of damage is 2-3 % of the stress, the two time domains' agreement in the moment
#: at the touchdown (the dynamic comparison's tolerances are 0.5-1 % in amplitudes)
ANCF_TOLERANCE = 0.10
#: the ANCF's time steps per period of the sea's shortest component (its default is 100
#: of the excitation's period; here that is the shortest of 100 components, 2.3 s at Tp
#: 8 s: T/100 is Tp/350, 23 500 implicit steps a sea state, an hour each at the 0.16 s
#: a step measured on the shared 2-core machine, most of it the Airy kinematics of 100
#: components at 5000 Gauss points, ancf/waves.py). 40 is the
#: recorder's sampling (every time domain samples the shortest wave period 40 times,
#: the step divides it): one step a sample, Tp/140, about Tz/100 of the stress record
ANCF_STEPS_PER_SHORTEST = 40
#: samples of the FD's record per shortest component period (the VFIFE samples 40)
FD_SAMPLES_PER_SHORTEST = 40
#: the touchdown zone searched for the touchdown's worst station: from this far below the
#: static touchdown to this far above it [m]
TOUCHDOWN_ZONE = (-50.0, 150.0)
#: the estimate the design's fatigue verdict is given on: the VFIFE's rainflow, the
#: nonlinear time domain (the touchdown's travel, the seabed contact and the drag as they
#: are; the FD's linear touchdown overestimates its damage many times, the report shows)
DESIGN_ESTIMATE = "rainflow_vfife"


@dataclass
class SeaStateFatigue:
    """The fatigue of one sea state: damage rates [1/s] along ``s`` per estimate (only the
    estimates run on it: a cell the screening left to the frequency domain has the FD's
    spectral ones), the comparison it came from (or its :class:`RunFigures`; None
    without a time domain) and the figures of the runs. ``seeds``: the seeds of its
    realisations (:mod:`.fatigue_scatter`; empty: one, the scene's own seed);
    ``half_rates``: the record estimates' rates over the first half of the realisations
    (the convergence with record length); ``pair_rates``: the VFIFE's rainflow over the
    realisations the ANCF ran, when it ran fewer (the two judged on the same records)."""

    hs: float
    tp: float
    probability: float
    s: np.ndarray
    rates: dict
    record_s: float
    comparison: object
    wall_s: float
    tdp_s: float | None
    ancf_wall_s: float | None = None     # the ANCF's run [s] (None: not run)
    ancf_info: dict = field(default_factory=dict)   # its mesh, step, touchdown travel
    seeds: tuple = ()
    half_rates: dict = field(default_factory=dict)
    pair_rates: dict = field(default_factory=dict)   # the VFIFE's over the ANCF's records


@dataclass
class RunFigures:
    """What the reports read of a sea state's runs (:func:`figures_of`): plain values, so
    that a worker returns them instead of the comparison. ``info``: the VFIFE's
    ``dynamic_max_utilisation`` (+ ``_s``), ``dynamic_min_touchdown_s`` and
    ``dynamic_max_touchdown_s``; ``fd_max_utilisation``: (value, s [m]) of
    :func:`fd_utilisation` over the record, or None (computed by the report)."""

    info: dict
    ramp_s: float
    settle_s: float
    element_length: float
    fd_wall_s: float
    vfife_wall_s: float
    fd_hang_off_tension_std: float
    vfife_hang_off_tension_std: float
    fd_max_utilisation: tuple | None = None


#: the VFIFE's figures a :class:`RunFigures` keeps
FIGURE_KEYS = ("dynamic_max_utilisation", "dynamic_max_utilisation_s",
               "dynamic_min_touchdown_s", "dynamic_max_touchdown_s")


def figures_of(cmp) -> RunFigures | None:
    """The :class:`RunFigures` of a comparison (:func:`compare_sea`'s, or any object with
    its attributes); a RunFigures as it is; None for None (no time domain run)."""
    if cmp is None or isinstance(cmp, RunFigures):
        return cmp
    info = cmp.vfife_result.info
    return RunFigures({k: info.get(k) for k in FIGURE_KEYS}, cmp.ramp_s, cmp.settle_s,
                      cmp.element_length, cmp.fd_wall_s, cmp.vfife_wall_s,
                      float(cmp.fd.std["tension"][-1]), cmp.vf["std"])


@dataclass
class ScatterFatigue:
    """The scatter diagram's fatigue: per sea state, and the damage per year along s.

    ``formed``: per estimate how its total is formed (:func:`damage_per_year`: the cells
    it ran, those left to the FD scaled); ``screening``: what the screening chose
    (:func:`.fatigue_scatter.screen`; None: every cell ran every method);
    ``half_per_year``: the damage per year from the first half of every cell's
    realisations (the convergence with record length; empty with one realisation a
    cell); ``run``: the engine's figures (where the units ran, how many, the wall time)."""

    scene: object
    states: list
    s: np.ndarray
    per_year: dict = field(default_factory=dict)
    element_length: float = 0.0
    formed: dict = field(default_factory=dict)
    screening: dict | None = None
    half_per_year: dict = field(default_factory=dict)
    run: dict = field(default_factory=dict)

    @property
    def screened(self) -> bool:
        """Whether a cell was left out by a method, or a cell ran several realisations:
        the reports then say which cells each method ran and how the totals are formed."""
        return any(h["rest"] for h in self.formed.values()) or \
            any(len(st.seeds) > 1 for st in self.states)

    @property
    def estimates(self) -> tuple:
        """The estimates of this result in the order of the reports: the VFIFE's
        rainflow, the ANCF's beside it when it was run, then the FD's three."""
        return estimates_of(self.per_year)

    def life(self, estimate: str) -> np.ndarray:
        """Fatigue life [years] along s of an estimate."""
        d = self.per_year[estimate]
        with np.errstate(divide="ignore"):
            return np.where(d > 0.0, 1.0 / np.where(d > 0.0, d, 1.0), np.inf)


def verdicts(result: ScatterFatigue) -> dict | None:
    """The fatigue verdict of each estimate (:func:`riser.design.fatigue.fatigue_verdict`
    of its life along s against ``[design] design_life`` x ``design_fatigue_factor``), in
    the order of the reports; None without a ``design_life``. The design's verdict is
    that of :data:`DESIGN_ESTIMATE`."""
    d = result.scene.design
    if d.design_life is None:
        return None
    dff = d.fatigue.design_fatigue_factor
    return {e: fatigue_verdict(result.s, result.life(e), d.design_life, dff)
            for e in result.estimates}


def estimates_of(columns) -> tuple:
    """:data:`ESTIMATES` with :data:`ANCF` after the VFIFE's when ``columns`` has it."""
    return (ESTIMATES[:1] + ((ANCF,) if ANCF in columns else ()) + ESTIMATES[1:])


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
    oop = scene.out_of_plane(statics=True)
    if oop is not None:
        raise SceneError(scene.source, oop[0], f"the fatigue by two methods takes a planar "
                         f"static state (the frequency domain's sea response is about a "
                         f"planar one; a sea from any heading is taken): {oop[1]}")


def sea_state_scene(scene, cell):
    """``scene`` with its spectrum's Hs and Tp those of the scatter diagram's ``cell``."""
    sp = scene.waves.spectrum.replace(hs=cell.hs, tp=cell.tp)
    return scene.replace(waves=scene.waves.replace(spectrum=sp))


def fd_amplitudes(cmp, s) -> tuple:
    """The FD's complex amplitudes (n_w, n) at stations ``s`` [m] of the effective tension,
    the in-plane moment, the out-of-plane moment (a sea off the line's plane bends it
    across: the frequency domain's out-of-plane family) and the vertical displacement per
    component (transfer times the component's complex amplitude a e^{-i eps}),
    interpolated linearly from its grid; and the components' omega [rad/s]."""
    fd, scene = cmp.fd, cmp.matched
    comp = scene_components(scene)
    a = comp.amplitude * np.exp(-1j * comp.phase)

    def at(key):
        h = fd.transfer[key]
        re = np.array([np.interp(s, fd.s, row.real) for row in h])
        im = np.array([np.interp(s, fd.s, row.imag) for row in h])
        return (re + 1j * im) * a[:, None]
    return at("tension"), at("moment"), at("moment_out"), at("dy"), comp.omega


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


def ancf_run_scene(cmp):
    """The scene the VFIFE ran in the comparison ``cmp`` (:func:`compare_sea`: the matched
    scene with the ramp, settling and one repeat period as its [dynamics]): the ANCF runs
    exactly it, the same realisation and record; its time step
    :data:`ANCF_STEPS_PER_SHORTEST` steps of the shortest component's period unless the
    scene sets ``[ancf] time_step`` or ``steps_per_period``."""
    vs = sea_run_scene(cmp.matched, cmp.ramp_s, cmp.settle_s, cmp.record_s)
    a = vs.ancf
    if a.time_step is None and a.steps_per_period == type(a)().steps_per_period:
        vs = vs.replace(ancf=a.override(steps_per_period=ANCF_STEPS_PER_SHORTEST))
    return vs


def run_ancf(cmp, s, progress=None) -> tuple[np.ndarray, float, dict]:
    """The ANCF's rainflow damage rate [1/s] at stations ``s`` [m] on the VFIFE's scene of
    ``cmp`` (:func:`ancf_run_scene`) at the VFIFE's element length (the same mesh
    length: the same model); (rate, wall time [s], info: element length, time step,
    steps, record, touchdown travel). Raises SolveFailed when the ANCF fails or
    refuses."""
    vs = ancf_run_scene(cmp)
    if progress is not None:
        progress(f"ancf: {vs.dynamics.duration:.0f} s in the sea")
    t0 = time.perf_counter()
    res = method("ancf").solve(vs, element_length=cmp.element_length, progress=progress)
    wall = time.perf_counter() - t0
    if not res.converged:
        what = "refused" if res.status is Status.REFUSED else "failed"
        raise SolveFailed("ancf", res.status, f"ancf in the sea {what}: {res.message}")
    env, info = res.dynamics.envelope, res.info
    record = float(info["dynamic_fatigue_record_s"])
    rate = np.interp(s, np.asarray(env["s"], float),
                     np.asarray(env["fatigue_damage"], float)) / record
    out = {"element_length": info.get("element_length"),
           "time_step": info.get("dynamic_time_step"), "steps": info.get("dynamic_steps"),
           "record_s": record,
           "newton_iterations_per_step": info.get("newton_iterations_per_step"),
           "touchdown_range_m": (info.get("dynamic_max_touchdown_s", np.nan)
                                 - info.get("dynamic_min_touchdown_s", np.nan))}
    return rate, wall, out


def spectral_rates(matched, fd, s) -> dict:
    """The FD's spectral estimates (``dirlik_fd``, ``narrow_band_fd``: damage rates
    [1/s]) at stations ``s`` [m] from its sea response ``fd`` about the static state of
    ``matched`` (they do not depend on the realisation's phases)."""
    h_t, h_m, h_mo, h_dy, omega = fd_amplitudes(SimpleNamespace(fd=fd, matched=matched), s)
    q = stress_transfer(matched, s, h_t, h_m, h_mo, h_dy)
    spec = spectral(matched, s, omega, fd.d_omega, q)
    return {"dirlik_fd": spec["fatigue_rate_dirlik"],
            "narrow_band_fd": spec["fatigue_rate_narrow_band"]}


def record_rates(cmp) -> tuple[np.ndarray, dict, float]:
    """(stations s [m], the record estimates' damage rates [1/s] ``rainflow_vfife`` and
    ``rainflow_fd``, the VFIFE's record [s]) of a sea comparison ``cmp``: the VFIFE's
    rainflow over its record, and the rainflow of the FD's linear record of the same
    realisation over the same window."""
    res = cmp.vfife_result
    env = res.dynamics.envelope
    s = np.asarray(env["s"], float)
    record = float(res.info["dynamic_fatigue_record_s"])
    h_t, h_m, h_mo, h_dy, omega = fd_amplitudes(cmp, s)
    q = stress_transfer(cmp.matched, s, h_t, h_m, h_mo, h_dy)
    start = cmp.ramp_s + cmp.settle_s
    rates = {"rainflow_vfife": np.asarray(env["fatigue_damage"]) / record,
             "rainflow_fd": fd_record_damage(cmp.matched, s, q, omega, start,
                                             cmp.record_s) / cmp.record_s}
    return s, rates, record


def run_sea_state(scene, cell, element_length: float | None, progress=None,
                  ancf: bool = False) -> SeaStateFatigue:
    """The estimates of one sea state (module docstring) in this process; ``ancf``: with
    the ANCF's. (A scatter diagram runs its sea states as units of work:
    :mod:`.fatigue_scatter`, the same computations.)"""
    t0 = time.perf_counter()
    sc = sea_state_scene(scene, cell)
    cmp = compare_sea(sc, element_length=element_length, progress=progress)
    s, rates, record = record_rates(cmp)
    spec = spectral_rates(cmp.matched, cmp.fd, s)
    rates = {"rainflow_vfife": rates["rainflow_vfife"], "rainflow_fd": rates["rainflow_fd"],
             **spec}
    tdp = cmp.static.profile.tdp_s
    ancf_wall, ancf_info = None, {}
    if ancf:
        rates[ANCF], ancf_wall, ancf_info = run_ancf(cmp, s, progress)
    return SeaStateFatigue(cell.hs, cell.tp, cell.probability, s, rates, record, cmp,
                           time.perf_counter() - t0, tdp, ancf_wall, ancf_info)


#: the estimate every cell has (the FD's, cheap): the reference by which the damage of a
#: cell not run by a record estimate is formed (:func:`damage_per_year`)
REFERENCE = "dirlik_fd"


def damage_per_year(states, s, estimates, half: bool = False) -> tuple[dict, dict]:
    """(damage per year [1/year] along ``s`` per estimate, how each total is formed).

    An estimate run on every cell: sum over the cells of probability x rate x a year.
    One run on some cells only (the screening, :mod:`.fatigue_scatter`): the cells it ran
    as they are, plus the others' FD damage (:data:`REFERENCE`, Dirlik's) scaled at each
    station by the ratio of the estimate to the FD over the cells it ran,

        D_e(s) = Y [sum_run p r_e(s) + K_e(s) sum_rest p r_FD(s)],
        K_e(s) = sum_run p r_e(s) / sum_run p r_FD(s),

    so that the cells left out contribute as the run cells' model-to-FD ratio says (the
    FD's linear touchdown overestimates there, the ratio brings that down). The second
    value per estimate: ``run`` (its cells, indices), ``rest`` and, at every station,
    ``fd_as_is`` (the total with the cells left out counted by the FD as it is: the
    other choice, shown beside). ``half``: from the states' ``half_rates`` (the first
    half of each cell's realisations; an estimate without them is left out)."""
    out, how = {}, {}
    for e in estimates:
        have = (lambda st: e in st.half_rates) if half else (lambda st: e in st.rates)
        rate = (lambda st: st.half_rates[e]) if half else (lambda st: st.rates[e])
        run = [k for k, st in enumerate(states) if have(st)]
        if not run:
            continue
        if len(run) == len(states):
            out[e] = sum(st.probability * np.interp(s, st.s, rate(st)) for st in states) \
                * SECONDS_PER_YEAR
            how[e] = {"run": run, "rest": [], "fd_as_is": out[e]}
            continue
        rest = [k for k in range(len(states)) if k not in run]

        def total(cells, of):
            return sum(states[k].probability * np.interp(s, states[k].s, of(states[k]))
                       for k in cells)
        mine = total(run, rate)
        ref = total(run, lambda st: st.rates[REFERENCE])
        others = total(rest, lambda st: st.rates[REFERENCE])
        with np.errstate(divide="ignore", invalid="ignore"):
            k_e = np.where(ref > 0.0, mine / np.where(ref > 0.0, ref, 1.0), 0.0)
        out[e] = (mine + k_e * others) * SECONDS_PER_YEAR
        how[e] = {"run": run, "rest": rest, "ratio": k_e,
                  "fd_as_is": (mine + others) * SECONDS_PER_YEAR}
    return out, how


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


def ancf_agreement(result: ScatterFatigue) -> dict | None:
    """The touchdown's damage ANCF against VFIFE (None without the ANCF's column): per
    sea state its share of the damage per year at the headline's touchdown station
    (:func:`stations`: the same station for both) and the ratio ANCF / VFIFE, the same
    for the total over the scatter diagram, and each method's own worst station in the
    touchdown zone beside (reported); the verdict passes when every ratio at the
    headline's station, each sea state's and the total's, is within
    :data:`ANCF_TOLERANCE` of 1. When the ANCF ran some of the cells only (the
    screening's ``ancf_cells``), the rows are those cells (``cell``: the index of each)
    and the total is theirs: the sum of the shares over the cells both methods ran."""
    if ANCF not in result.per_year:
        return None
    j = stations(result)["touchdown"]
    s_td = float(result.s[j])
    rows = []
    both = [k for k, st in enumerate(result.states)
            if ANCF in st.rates and "rainflow_vfife" in st.rates]
    def rate(st, e):                 # the VFIFE's over the records the ANCF ran
        return st.pair_rates.get(e, st.rates[e])
    for k in both:
        st = result.states[k]
        share = st.probability * SECONDS_PER_YEAR
        v, a = (share * float(np.interp(s_td, st.s, rate(st, e))) for e in
                ("rainflow_vfife", ANCF))
        zone = (st.s >= st.tdp_s + TOUCHDOWN_ZONE[0]) & (st.s <= st.tdp_s + TOUCHDOWN_ZONE[1])
        own = {e: float(np.max(rate(st, e)[zone])) for e in ("rainflow_vfife", ANCF)}
        rows.append({"hs": st.hs, "tp": st.tp, "vfife": v, "ancf": a, "ratio": a / v,
                     "own_ratio": own[ANCF] / own["rainflow_vfife"], "cell": k})
    if len(both) == len(result.states) and not any(st.pair_rates for st in result.states):
        v, a = (float(result.per_year[e][j]) for e in ("rainflow_vfife", ANCF))
        own_ratio = (worst_in_zone(result, ANCF)[0]
                     / worst_in_zone(result, "rainflow_vfife")[0])
    else:
        s, tdp = result.s, result.states[0].tdp_s
        sub = {e: sum(result.states[k].probability * np.interp(
            s, result.states[k].s, rate(result.states[k], e)) for k in both)
            * SECONDS_PER_YEAR for e in ("rainflow_vfife", ANCF)}
        v, a = (float(sub[e][j]) for e in ("rainflow_vfife", ANCF))
        zone = (s >= tdp + TOUCHDOWN_ZONE[0]) & (s <= tdp + TOUCHDOWN_ZONE[1])
        own_ratio = float(np.max(sub[ANCF][zone]) / np.max(sub["rainflow_vfife"][zone]))
    total = {"vfife": v, "ancf": a, "ratio": a / v, "own_ratio": own_ratio,
             "cells": len(both)}
    worst = max([r["ratio"] for r in rows] + [total["ratio"]], key=lambda r: abs(r - 1.0))
    return {"s": s_td, "rows": rows, "total": total, "worst_ratio": worst,
            "tolerance": ANCF_TOLERANCE,
            "verdict": "pass" if abs(worst - 1.0) <= ANCF_TOLERANCE else "fail"}

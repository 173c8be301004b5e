"""The irregular-sea comparison: the frequency domain's stochastic response
(:func:`bvp.frequency.sea_response.solve_sea` about the BVP static state, the drag linearised
stochastically) against the statistics of the VFIFE's time domain in the same sea (the
same components: the scene's seeded realisation).

The VFIFE run: the waves' half-cosine ramp (:func:`..dynamic.protocol.ramp_periods` of the peak
period: at least 3 peak periods and twice the line's longest natural period, as the
harmonic comparison's), :data:`SETTLE_PEAK_PERIODS` peak periods for the start-up
transient to decay, then a record of one repeat period of the sea, 2 pi / d omega: over it
the components are orthogonal (their frequencies are multiples of d omega,
:mod:`riser.physics.waves`), so the record's variance of a linear response is exactly the sum of
the components' (the FD's sigma^2), with no sampling error of a random record. What is
left between the methods is the drag's linearisation (stochastic against the nonlinear
drag), the discretisations and the transient. The record's two halves are reported as a
measure of what a shorter record would scatter by (each half is not a whole repeat
period).

Rows: the hang-off tension's standard deviation (judged: :data:`TOLERANCE`, the issue's
bound) and, reported, the standard deviations of the tension and curvature along s (the
largest difference over the FD's peak), the hang-off tension's zero-upcrossing period and
3 h most probable maximum (Rayleigh, each from its spectral moments: the FD's spectrum,
the VFIFE's record's periodogram), and the record's halves.

Extremes over the storm (``[design] storm_duration``, else 3 h; :func:`extreme_rows`,
reported, not judged): the hang-off tension's maximum, the least tension along the line,
the largest moment along it and, with [design], the largest utilisation. The FD's: the
static value plus (minus) its Rayleigh MPM sigma sqrt(2 ln(D / Tz)) from its spectral
moments at each station, the worst station's; the VFIFE's: the most probable maximum of
its record by a Weibull fit of the peaks (:mod:`riser.design.extremes`, the recorder's
``dynamic_*_mpm`` figures), its bootstrap interval, its Rayleigh form and the record's
own extreme. The FD's utilisation combines the MPMs of tension and moment in phase
(:func:`riser.design.checks.amplitude_columns`: an upper bound).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from bvp.frequency.sea_response import SeaResponse
from riser.design.extremes import (SUMMARY_EXTREMES, rayleigh_mpm, storm_duration,
                                   summary_extreme)
from riser.physics.dynamics import Dynamics
from riser.errors import SceneError, SolveFailed, UnsupportedSceneError
from riser.results.result import Status
from riser.model.scene import Scene
from verification.methods import method
from verification.pipeline import vfife_equivalent

from ..row import Row, Tolerance, Verdict
from ..dynamic.protocol import (RAMP_FUNDAMENTALS, RAMP_PERIODS, ramp_periods, require_one_drive,
                       tightened_statics)

#: the issue's bound on the hang-off tension's standard deviation (relative)
TOLERANCE = 0.05
#: peak periods for the transient to decay after the ramp
SETTLE_PEAK_PERIODS = 6
#: time-series samples per shortest component period
SAMPLES_PER_SHORTEST = 10
#: the storm duration of the rows ``hang_off_tension_mpm_3h`` [s] (the storm of the
#: extremes is the scene's, :func:`riser.design.extremes.storm_duration`)
STORM = 10800.0


def is_sea(scene: Scene) -> bool:
    """True when the scene's waves hold an irregular sea (this comparison)."""
    return scene.waves is not None and scene.waves.spectrum is not None


@dataclass
class SeaComparison:
    """The irregular-sea comparison of one scene (see the module docstring)."""

    scene: Scene
    matched: Scene
    fd: SeaResponse
    vf: dict
    rows: list
    element_length: float
    record_s: float
    ramp_s: float
    settle_s: float
    static: object
    notes: list = field(default_factory=list)
    fd_wall_s: float = 0.0
    vfife_wall_s: float = 0.0
    vfife_result: object = None       # the VFIFE's SolveResult of the run (its dynamics)
    storm_s: float = STORM            # the storm of the extremes [s]
    extremes: list = field(default_factory=list)    # :func:`extreme_rows`

    @property
    def passed(self) -> bool:
        return all(r["pass"] is not False for r in self.rows)


def check_sea(scene: Scene) -> None:
    """Refuse before solving what this comparison cannot take: a sea with regular trains
    or a top motion beside it (one drive). SceneError naming the key (exit 2)."""
    w = scene.waves
    if w.trains:
        raise SceneError(scene.source, "environment.waves.trains", "not with a spectrum in "
                         "the dynamic comparison (the irregular sea alone: one drive)")
    require_one_drive(scene)


def repeat_period(scene: Scene) -> float:
    """The sea's repeat period 2 pi / d omega [s]."""
    return 2.0 * math.pi / scene.waves.spectrum.component_omegas()[1]


def sea_run_scene(scene: Scene, ramp: float, settle: float, record: float) -> Scene:
    """``scene`` with the comparison's [dynamics] (ramp, settle, one record) and the
    waves' ramp, statics 10x tighter (as the harmonic comparison's)."""
    sp = scene.waves.spectrum
    shortest = 2.0 * math.pi / float(np.max(sp.component_omegas()[0]))
    dyn = scene.dynamics
    new = Dynamics(duration=ramp + settle + record,
                   output_interval=shortest / SAMPLES_PER_SHORTEST,
                   damping=dyn.damping if dyn is not None else 0.0,
                   statistics_start=ramp + settle)
    return scene.replace(dynamics=new, waves=scene.waves.replace(ramp_time=ramp),
                         **tightened_statics(scene))


def compare_sea(scene: Scene, *, element_length: float | None = None, static=None,
                progress=None) -> SeaComparison:
    """Compare the scene's irregular sea by both methods (see the module docstring).
    Raises SceneError / UnsupportedSceneError for a scene the comparison cannot take,
    SolveFailed when a method fails."""
    now = progress or (lambda msg: None)
    check_sea(scene)
    eq = vfife_equivalent(scene)
    matched = eq.scene
    notes = [f"The scene was converted: {eq.note}."] if eq.note else []
    h = element_length or matched.vfife.element_length
    if static is None:
        now("bvp: static state")
        static = method("bvp").solve(matched)
    if not static.converged:
        raise SolveFailed("bvp", static.status, f"bvp statics: {static.message}")
    now("frequency domain: the sea's components, drag linearised stochastically")
    storm = storm_duration(matched)
    fd = method("bvp").sea(matched, static=static, duration=storm)
    if fd.status is Status.REFUSED:
        raise UnsupportedSceneError(fd.message)
    if not fd.converged:
        raise SolveFailed("bvp", fd.status, f"frequency domain (sea): {fd.message}")
    tp = 2.0 * math.pi / matched.waves.spectrum.peak_omega
    periods, longest = ramp_periods(matched, tp, static)
    ramp = periods * tp
    settle = SETTLE_PEAK_PERIODS * tp
    record = repeat_period(matched)
    notes.append(f"VFIFE run: a ramp of {periods} peak periods, {ramp:.4g} s (at least "
                 f"{RAMP_PERIODS} and {RAMP_FUNDAMENTALS:g} times the longest natural period, "
                 + (f"{longest:.4g} s" if longest else "unknown: the modal analysis failed")
                 + f"), {settle:.4g} s to settle, then one repeat period of the sea, "
                 f"{record:.4g} s.")
    vs = sea_run_scene(matched, ramp, settle, record)
    now(f"vfife: {vs.dynamics.duration:.0f} s in the sea")
    t0 = time.perf_counter()
    v = method("vfife").solve(vs, element_length=h, progress=progress)
    wall = time.perf_counter() - t0
    if not v.converged:
        raise SolveFailed("vfife", v.status, f"vfife in the sea: {v.message}")
    vf = read_record(v, ramp + settle)
    rows = agreement_rows(fd, vf, static)
    extremes = extreme_rows(matched, fd, v.summary(), static)
    rows += [_row(f"{e['name']}_mpm", e["fd"], e["vfife"], None, "of the FD value (static "
                  "+ Rayleigh MPM; VFIFE: Weibull MPM) over the storm", False)
             for e in extremes]
    return SeaComparison(scene, matched, fd, vf, rows, h, record, ramp, settle, static,
                         notes, fd.wall_time_s, wall, v, storm, extremes)


def read_record(res, start: float) -> dict:
    """The VFIFE's record statistics from ``start`` [s]: the hang-off tension series (t,
    tension), its std and mean, the std of the two halves, the std of tension and
    curvature along s (``s``), the periodogram of the hang-off tension (``omega``,
    ``density`` [N2 s/rad]) and from its moments, as the FD's from its spectrum, Tz = 2 pi
    sqrt(m0 / m2) and the 3 h MPM (the summary's Tz, counted on the record, beside as
    ``tz_counted``)."""
    ts, env, info = res.dynamics.timeseries, res.dynamics.envelope, res.info
    sel = ts["time"] >= start - 1e-9
    t, x = ts["time"][sel], ts["hang_off_tension"][sel]
    t, x = t[:-1], x[:-1]                        # one repeat period: drop the closing point
    half = len(x) // 2
    n = len(x)
    dt = float(t[1] - t[0])
    spec = np.fft.rfft(x - np.mean(x)) / n
    omega = 2.0 * math.pi * np.fft.rfftfreq(n, dt)
    d_omega = 2.0 * math.pi / (n * dt)
    density = 2.0 * np.abs(spec) ** 2 / d_omega      # one-sided, variance per rad/s
    density[0] = 0.0
    m0 = float(np.sum(density) * d_omega)
    m2 = float(np.sum(omega ** 2 * density) * d_omega)
    tz = 2.0 * math.pi * math.sqrt(m0 / m2) if m2 > 0.0 else None
    mpm = (float(np.mean(x)) + math.sqrt(m0) * math.sqrt(2.0 * math.log(max(STORM / tz, 1.0)))
           if tz else None)
    return {"t": t, "tension": x, "std": float(np.std(x)), "mean": float(np.mean(x)),
            "std_halves": (float(np.std(x[:half])), float(np.std(x[half:]))),
            "tz": tz, "mpm_3h": mpm, "tz_counted": info.get("dynamic_hang_off_tension_tz"),
            "s": env["s"], "tension_std": env["tension_std"],
            "curvature_std": env["curvature_std"], "omega": omega, "density": density,
            "record_s": float(n * dt), "samples": n}


def agreement_rows(fd: SeaResponse, vf: dict, static) -> list[Row]:
    """The rows of the comparison (see the module docstring)."""
    T0 = float(static.profile.tension[-1])
    fd_std = float(fd.std["tension"][-1])
    rows = [_row("hang_off_tension_std", fd_std, vf["std"], TOLERANCE, "of the FD value",
                 True)]
    for key in ("tension", "curvature"):
        q_fd = np.interp(vf["s"], fd.s, fd.std[key])
        peak = float(np.max(q_fd))
        diff = np.abs(vf[f"{key}_std"] - q_fd)
        k = int(np.argmax(diff))
        rows.append(Row(f"{key}_std_along_s",
                        {"fd": peak, "vfife": float(np.max(vf[f"{key}_std"]))}, "", None,
                        float(diff[k]) / peak if peak > 0 else None,
                        Tolerance(None, None, "largest difference over the FD's peak",
                                  relative=True), at_s=float(vf["s"][k])))
    fd_tz = float(fd.tz["tension"][-1])
    rows.append(_row("hang_off_tension_tz_s", fd_tz, vf["tz"], None, "of the FD value",
                     False))
    rows.append(_row("hang_off_tension_mpm_3h", T0 + rayleigh_mpm(
        fd.std["tension"][-1], fd.tz["tension"][-1], STORM), vf["mpm_3h"], None,
        "of the FD value (static + MPM)", False))
    for i, half in enumerate(vf["std_halves"]):
        rows.append(_row(f"hang_off_tension_std_half_{i + 1}", fd_std, half, None,
                         "of the FD value (half the record)", False))
    return rows


def _row(name, fd_value, vf_value, tol, basis, judged) -> Row:
    """A row of the VFIFE's value against the FD's, relative (``basis``: its label)."""
    rel = (vf_value / fd_value - 1.0) if (fd_value and vf_value is not None) else None
    ok = None if not judged else (rel is not None and abs(rel) <= tol)
    return Row(name, {"fd": fd_value, "vfife": vf_value}, "", None, rel,
               Tolerance(tol, None, basis, relative=True), Verdict.of(ok))


def fd_extremes(scene, fd: SeaResponse, static) -> dict:
    """name -> the FD's extreme over its storm (``fd.mpm``, over ``fd.duration``: the
    static state plus the Rayleigh MPM at each station, the worst station's; the module
    docstring): ``hang_off_tension`` [N] at the hang-off, ``min_tension`` [N] (the least
    of T_0 - MPM along s), ``max_moment`` [N m] (the largest of |M_0| + MPM), and with
    [design] ``max_utilisation`` [-] (the MPMs of tension and moment combined in phase on
    the static profile's stations)."""
    out = {"hang_off_tension": float(static.profile.tension[-1]) + float(
        fd.mpm["tension"][-1]),
        "min_tension": float(np.min(fd.static["tension"] - fd.mpm["tension"])),
        "max_moment": float(np.max(np.abs(fd.static["moment"]) + fd.mpm["moment"]))}
    if scene.design is not None:
        from riser.design.checks import amplitude_columns
        p = static.profile
        cols = amplitude_columns(scene, p.s, p.y, p.tension, p.moment,
                                 np.interp(p.s, fd.s, fd.mpm["tension"]),
                                 np.interp(p.s, fd.s, fd.mpm["moment"]))
        out["max_utilisation"] = float(np.max(cols["utilisation"]))
    return out


def extreme_rows(scene, fd: SeaResponse, info: dict, static) -> list[dict]:
    """The extremes over the storm (module docstring), one dict a quantity of
    :data:`riser.design.extremes.SUMMARY_EXTREMES` that the FD or the VFIFE has:
    ``name``, ``label``, ``unit`` (SI), ``fd`` (static + Rayleigh MPM), ``vfife`` (its
    Weibull MPM), ``low``, ``high`` (its 90 % interval), ``rayleigh`` (its record's
    Rayleigh MPM), ``record`` (its record's extreme), ``peaks``, ``shape`` (the Weibull's
    k); None where missing. ``info``: the VFIFE's summary (``dynamic_*`` figures)."""
    fde = fd_extremes(scene, fd, static)
    rows = []
    for name, (_, unit, label) in SUMMARY_EXTREMES.items():
        td = summary_extreme(info, name)
        if name not in fde and td is None:
            continue
        td = td or dict.fromkeys(("mpm", "low", "high", "rayleigh", "record", "peaks",
                                  "shape"))
        rows.append({"name": name, "label": label, "unit": unit, "fd": fde.get(name),
                     "vfife": td.pop("mpm"), **td})
    return rows

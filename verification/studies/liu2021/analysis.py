"""Signal analysis of the Liu et al. (2021) reproduction (:mod:`verification.studies.liu2021.cases`):
small pure functions on uniformly sampled time series, tested on synthetic signals with a
known answer (``tests/test_liu2021.py``).

Conventions: ``t`` [s] the sample times, ``dt`` [s] their spacing; a window is half-open,
``[end - length, end)``, so that a window of whole periods holds exactly whole periods of
samples and every periodic component of those periods falls on a frequency bin (no
leakage between the surge and the slug lines).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import pandas as pd

from riser.physics.internal_flow import contents_mass_per_length
from riser.model.sections import segment_properties


def common_period(periods, max_denominator: int = 1000) -> float:
    """The shortest time [s] that is a whole number of every period in ``periods`` [s]
    (least common multiple of their rational approximations with denominators up to
    ``max_denominator``): 288 s for the surge 9 s and the slug 32 s."""
    fr = [Fraction(p).limit_denominator(max_denominator) for p in periods]
    num = math.lcm(*(f.numerator for f in fr))
    den = math.gcd(*(f.denominator for f in fr))
    return float(Fraction(num, den))


def whole_periods(period: float, limit: float) -> float:
    """The longest whole number (at least 1) of ``period`` [s] not longer than ``limit``
    [s]; ``period`` itself when even one does not fit."""
    return period * max(1, math.floor(limit / period + 1e-9))


def window(t: np.ndarray, end: float, length: float) -> np.ndarray:
    """Boolean mask of the samples of ``t`` [s] in the half-open window [end - length, end)
    (1e-9 s tolerance on the edges)."""
    t = np.asarray(t, float)
    return (t >= end - length - 1e-9) & (t < end - 1e-9)


def half_range(y) -> float:
    """(max - min) / 2 of ``y``: the amplitude of an oscillation about its mid-value."""
    y = np.asarray(y, float)
    return 0.5 * float(np.max(y) - np.min(y))


def spectrum(y, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """(f [Hz], amplitude) of the single-sided amplitude spectrum of ``y`` sampled every
    ``dt`` [s], mean removed: a sinusoid a sin(2 pi f0 t) whose f0 is a bin frequency
    (whole periods in the window) has amplitude a at f0. Bin 0 (the mean) is 0."""
    y = np.asarray(y, float)
    n = len(y)
    amp = 2.0 * np.abs(np.fft.rfft(y - y.mean())) / n
    if n % 2 == 0:
        amp[-1] *= 0.5                         # the Nyquist bin has no mirror
    amp[0] = 0.0
    return np.fft.rfftfreq(n, dt), amp


def dominant_frequency(y, dt: float) -> tuple[float, float]:
    """(f [Hz], amplitude) of the largest line of :func:`spectrum` (bin resolution
    1 / (n dt))."""
    f, amp = spectrum(y, dt)
    i = int(np.argmax(amp))
    return float(f[i]), float(amp[i])


def amplitude_at(y, dt: float, freq: float) -> float:
    """Amplitude of the component of ``y`` (mean removed) at ``freq`` [Hz]: the projection
    on cos and sin over the window, exact for a sinusoid with whole periods in it."""
    y = np.asarray(y, float)
    t = dt * np.arange(len(y))
    c = np.sum((y - y.mean()) * np.exp(-2j * math.pi * freq * t))
    return float(2.0 * abs(c) / len(y))


def lag(a, b, dt: float, max_lag: float) -> float:
    """Delay tau [s] of ``b`` behind ``a`` (b(t) ~ a(t - tau)) with |tau| <= ``max_lag``:
    the peak of the cross-correlation of the mean-removed signals (each lag's sum divided
    by its overlap), refined by the parabola through the peak and its neighbours. A
    periodic signal of period P gives tau modulo P: keep ``max_lag`` below P / 2."""
    a = np.asarray(a, float) - np.mean(a)
    b = np.asarray(b, float) - np.mean(b)
    n = len(a)
    kmax = min(int(math.floor(max_lag / dt + 1e-9)), n - 2)
    ks = np.arange(-kmax, kmax + 1)
    c = np.array([np.dot(a[max(0, -k):n - max(0, k)], b[max(0, k):n - max(0, -k)])
                  / (n - abs(k)) for k in ks])
    j = int(np.argmax(c))
    off = 0.0
    if 0 < j < len(c) - 1:
        den = c[j - 1] - 2.0 * c[j] + c[j + 1]
        if den < 0.0:
            off = 0.5 * (c[j - 1] - c[j + 1]) / den
    return float((ks[j] + off) * dt)


def at_station(values: np.ndarray, s: np.ndarray, s0: float) -> np.ndarray:
    """Time series at arc length ``s0`` [m] of nodal ``values`` (k, n) on nodes ``s`` (n,)
    [m], by linear interpolation between the two nodes around it."""
    values = np.asarray(values, float)
    s = np.asarray(s, float)
    j = int(np.clip(np.searchsorted(s, s0) - 1, 0, len(s) - 2))
    w = (s0 - s[j]) / (s[j + 1] - s[j])
    return (1.0 - w) * values[:, j] + w * values[:, j + 1]


def travel_speed(diff: np.ndarray, s: np.ndarray, dt: float, pairs, max_lag: float):
    """Travel speeds [m/s] of a pattern in the nodal time series ``diff`` (k, n) on nodes
    ``s`` [m] sampled every ``dt`` [s]: for each (s1, s2) of ``pairs`` [m] (s2 > s1),
    (s2 - s1) / :func:`lag` of the series at s2 behind the one at s1. Returns an array
    (one speed per pair; inf for a zero lag)."""
    out = []
    for s1, s2 in pairs:
        tau = lag(at_station(diff, s, s1), at_station(diff, s, s2), dt, max_lag)
        out.append((s2 - s1) / tau if tau != 0.0 else math.inf)
    return np.asarray(out, float)


def peak_near(s: np.ndarray, values: np.ndarray, lo: float, hi: float) -> tuple[float, float]:
    """(s [m], value) of the largest ``values`` with lo <= s <= hi (the node's)."""
    s = np.asarray(s, float)
    sel = np.flatnonzero((s >= lo) & (s <= hi))
    j = sel[int(np.argmax(np.asarray(values)[sel]))]
    return float(s[j]), float(values[j])


# ----------------------------------------------------------------------------- the study's
@dataclass
class Run:
    """What the study keeps of one VFIFE run (SI units).

    label : the case; slug_length : L_s [m] (None: uniform flow); profile : the static
    :class:`~riser.results.profile.Profile`; t : (k,) output times [s]; top_tension : (k,) hang-off
    effective tension [N]; moment : (k, n) nodal bending moment magnitudes [N m] on the
    nodes ``profile.s``; wall, dyn_wall : wall time of the whole solve and of its dynamics
    [s]; realtime : simulated over dynamic wall time; warnings : the result's warnings.
    """

    label: str
    slug_length: float | None
    profile: object
    t: np.ndarray
    top_tension: np.ndarray
    moment: np.ndarray
    wall: float
    dyn_wall: float
    realtime: float
    warnings: tuple = ()

    @property
    def dt(self) -> float:
        return float(self.t[1] - self.t[0])

    @property
    def s(self) -> np.ndarray:
        return self.profile.s

    def station(self, s0: float, length: float) -> np.ndarray:
        """Moment [N m] at s0 [m] over the last ``length`` [s] of the run."""
        sel = window(self.t, self.t[-1] + self.dt, length)
        return at_station(self.moment[sel], self.s, s0)


def steady_change(y_last, y_prev, stat) -> float:
    """|stat(last) / stat(previous) - 1|: how much a window statistic still changes."""
    a, b = stat(y_last), stat(y_prev)
    return abs(a / b - 1.0) if b else math.inf


def youngs_modulus(scene) -> float:
    """E = EI / I [Pa] of the first line type (I of its annulus D, D_i [m4])."""
    lt = scene.line_types[scene.segments[0].line_type]
    return lt.bending_stiffness / (math.pi / 64.0 * (lt.outer_diameter ** 4
                                                      - (lt.inner_diameter or 0.0) ** 4))


def static_quantities(uni: Run, slug: Run, scene) -> dict:
    """The static rows: top tensions [N], slug vs uniform differences, the touchdown
    moments [N m] and the catenary estimate of the sag-bend moment EI w / H (w the
    submerged weight with contents [N/m], H the horizontal tension at the hang-off [N])."""
    pu, ps = uni.profile, slug.profile
    prop = segment_properties(scene)[0]
    flow = scene.internal_flow
    mu0 = contents_mass_per_length(scene)
    top = float(pu.tension[-1])
    dT, dM = ps.tension - pu.tension, ps.moment - pu.moment
    i, j = int(np.argmax(np.abs(dT))), int(np.argmax(np.abs(dM)))
    hang = pu.s >= (pu.tdp_s or 0.0) + 100.0
    k = 2.0 * math.pi / slug.slug_length
    L = float(pu.s[-1] - pu.s[0])
    psi = math.radians(flow.phase_deg)
    cos_th = np.cos(pu.theta)
    mom_g = np.gradient(pu.moment, pu.s)
    H = float(pu.tension[-1] * cos_th[-1])
    s_pk, m_pk = peak_near(pu.s, pu.moment, pu.tdp_s or 0.0, pu.s[-1])
    return {
        "top_tension": top, "top_wall_tension": float(pu.wall_tension[-1]),
        "mu_u2": mu0 * flow.speed ** 2, "tdp_s": pu.tdp_s, "tdp_s_slug": ps.tdp_s,
        "dT_rel": float(abs(dT[i]) / top), "dT_s": float(pu.s[i]), "dT": float(dT[i]),
        # net weight of the frozen wave eta mu0 g cos(k s + psi) over the line [N]
        "net_slug_weight": flow.density_amplitude * mu0 * scene.gravity
        * (math.sin(k * L + psi) - math.sin(psi)) / k,
        "wave_weight": flow.density_amplitude * mu0 * scene.gravity / k,
        "dM": float(abs(dM[j])), "dM_s": float(pu.s[j]), "dM_hanging": float(
            np.max(np.abs(dM[hang]))),
        # quasi-static ripple of a tensioned beam under the normal part of the weight wave
        # dw = eta mu0 g of wavenumber k: M = EI dw cos(theta) / (T + EI k^2)
        "dM_estimate": float(np.max(prop.EI * flow.density_amplitude * mu0 * scene.gravity
                                    * cos_th[hang] / (pu.tension[hang] + prop.EI * k * k))),
        "M140": float(np.interp(140.0, pu.s, pu.moment)),
        "dMds140": float(np.interp(140.0, pu.s, mom_g)),
        "peak_moment": m_pk, "peak_moment_s": s_pk, "peak_flat": float(np.ptp(
            pu.s[pu.moment >= 0.99 * m_pk])), "peak_moment_slug": float(
            np.max(ps.moment)), "H": H, "w": prop.weight, "EI": prop.EI,
        "E": youngs_modulus(scene),
        "EIw_H": prop.EI * prop.weight / H,
    }


def dynamic_quantities(uni: Run, slug: Run, scene, length: float, stations,
                       pairs) -> dict:
    """The dynamic rows over the last ``length`` [s] of the uniform and slug runs: top
    tension half-ranges [N], the moment spectra at ``stations`` [m] (dominant frequency
    [Hz], surge and slug lines [N m]), the travel speed [m/s] of the slug's part of the
    moment (slug minus uniform) between the station ``pairs`` [m], and the steadiness
    (the same statistics over the window before)."""
    surge = 1.0 / scene.dynamics.top_motion.period
    f_slug = scene.internal_flow.speed / slug.slug_length
    dt = slug.dt
    end = slug.t[-1] + dt
    last, prev = window(slug.t, end, length), window(slug.t, end - length, length)
    out = {"window": length, "dt": dt, "f_surge": surge, "f_slug": f_slug,
           "samples": int(last.sum())}
    for r in (uni, slug):
        tt = r.top_tension
        out[f"range_{r.label}"] = half_range(tt[last])
        out[f"steady_{r.label}"] = steady_change(tt[last], tt[prev], half_range)
        out[f"top_slug_line_{r.label}"] = amplitude_at(tt[last], dt, f_slug)
        out[f"top_surge_line_{r.label}"] = amplitude_at(tt[last], dt, surge)
        for s0 in stations:
            m = r.station(s0, length)
            f, a = dominant_frequency(m, dt)
            out[f"m{s0:g}_{r.label}"] = {
                "f": f, "amp": a, "surge": amplitude_at(m, dt, surge),
                "slug": amplitude_at(m, dt, f_slug), "mean": float(m.mean()),
                "min": float(m.min()), "max": float(m.max())}
    diff = slug.moment[last] - uni.moment[last]
    speeds = travel_speed(diff, slug.s, dt, pairs, 0.5 / f_slug)
    out.update({"speeds": speeds, "speed": float(np.median(speeds))})
    return out


def slug_length_quantities(r: Run, scene, length: float) -> dict:
    """One run of the slug-length study: mean, half-range and slug line of the moment at
    140 m and 300 m [N m] over the last ``length`` [s], the static (frozen slug) moment at
    140 m and the mean's change from the window before."""
    f_slug = scene.internal_flow.speed / r.slug_length
    dt = r.dt
    end = r.t[-1] + dt
    m140 = r.station(140.0, length)
    prev = at_station(r.moment[window(r.t, end - length, length)], r.s, 140.0)
    m300 = r.station(300.0, length)
    return {"L_s": r.slug_length, "window": length, "mean140": float(m140.mean()),
            "range140": half_range(m140), "slug140": amplitude_at(m140, dt, f_slug),
            "range300": half_range(m300), "slug300": amplitude_at(m300, dt, f_slug),
            "static140": float(np.interp(140.0, r.s, r.profile.moment)),
            "steady": steady_change(m140, prev, np.mean)}


# ----------------------------------------------------------------------------- table.csv
COLUMNS = ("quantity", "paper", "computed", "rel_err", "note")
#: the paper's numbers (SI); derived ones say how in their row's note
PAPER = {"top_tension": 3.78e3 / 0.0027, "range_diff": 3.78e3, "range_diff_rel": 0.0027,
         "f140": 1.0 / 9.0, "f300": 2.5 / 80.0, "mean140": {100.0: 101.06e3, 280.0: 127.53e3},
         "mean_diff_rel": 0.36, "static140": (127.53e3 - 101.06e3) / 0.36, "speed": 2.5}
MODEL_NOTE = ("inputs the paper leaves out: E (207 GPa assumed), the soil model and "
              "stiffness (1e5 N/m2 linear assumed), tangential drag (0 assumed); their "
              "ALE-ANCF with Newmark (dt 0.05 s) against our VFIFE")


def table(q: dict) -> pd.DataFrame:
    """The rows of table.csv from the study's quantities ``q`` (see
    :func:`verification.studies.liu2021.cases.run`); cells of runs that failed are empty."""
    st, dy, ls = q.get("static"), q.get("dynamic"), q.get("ratios", {})
    rows = []

    def row(name, paper, value, note):
        rel = value / paper - 1.0 if (paper is not None and value is not None) else None
        rows.append({"quantity": name, "paper": paper, "computed": value, "rel_err": rel,
                     "note": note})

    g = st or {}
    k = lambda key: g.get(key) if st else None  # noqa: E731
    lo, hi = 3.78e3 / 0.00275, 3.78e3 / 0.00265
    row("static_top_effective_tension_uniform_N", PAPER["top_tension"], k("top_tension"),
        f"paper: derived, 3.78 kN = 0.27 % of the static top tension gives 1400 kN "
        f"({lo / 1e3:.0f}-{hi / 1e3:.0f} kN within the rounding of 0.27 %); the paper does "
        "not say effective or wall tension; weight and geometry fix it, E barely matters")
    if st:
        row("static_top_wall_tension_uniform_N", None, g["top_wall_tension"],
            f"T_w = T_e + mu U^2 + p_i A_i - p_o A_o at the hang-off 10 m deep, contents' "
            f"gauge pressure 0 there (not given): mu U^2 = {g['mu_u2']:.0f} N, the sea "
            "pressure on the outer area lowers it")
        row("static_tension_slug_vs_uniform_max_rel", None, g["dT_rel"],
            f"largest |T_slug - T_uniform| / uniform top tension, at s = {g['dT_s']:.0f} m "
            f"({g['dT'] / 1e3:+.2f} kN); the paper: 'almost identical'. About the net weight "
            f"of the frozen slug over the line, {g['net_slug_weight'] / 1e3:+.2f} kN "
            "(1260 m is not a whole number of slug lengths; the part on the seabed rests on "
            "the soil)")
        row("static_moment_slug_ripple_max_N_m", None, g["dM"],
            f"largest |M_slug - M_uniform|, at s = {g['dM_s']:.0f} m (sag bend); "
            f"{g['dM_hanging'] / 1e3:.1f} kN m at most in the hanging part (from 100 m above "
            f"the touchdown), where a tensioned beam under the weight wave, EI dw cos(theta) / "
            f"(T + EI k^2), gives {g['dM_estimate'] / 1e3:.1f} kN m; the paper: 'obvious "
            "local ripples'")
    if dy:
        w = dy["window"]
        for lab in ("uniform", "slug"):
            row(f"top_tension_amplitude_{lab}_N", None, dy[f"range_{lab}"],
                f"(max - min) / 2 of the hang-off effective tension over the last {w:g} s "
                f"(changes by {100 * dy[f'steady_{lab}']:.2f} % from the {w:g} s before)")
        d = dy["range_slug"] - dy["range_uniform"]
        row("top_tension_amplitude_slug_minus_uniform_N", PAPER["range_diff"], d,
            f"the slug's own line in the top tension is {dy['top_slug_line_slug'] / 1e3:.2f} "
            f"kN (quasi-static net weight of one slug wave eta mu0 g L_s / (2 pi) = "
            f"{st['wave_weight'] / 1e3:.2f} kN); {MODEL_NOTE}" if st else MODEL_NOTE)
        row("top_tension_amplitude_difference_rel_static", PAPER["range_diff_rel"],
            d / st["top_tension"] if st else None,
            "the difference over the uniform-flow static top tension (effective), as the paper")
        row("top_tension_peak_to_peak_slug_minus_uniform_N", PAPER["range_diff"], 2.0 * d,
            "the other reading of the paper's 'fluctuation amplitude' of the top tension: "
            "max - min; it calls the surge's 0.5 m (a sine's amplitude) an amplitude too, "
            "hence (max - min) / 2 in the rows above")
        for s0, key in ((140.0, "f140"), (300.0, "f300")):
            m = dy[f"m{s0:g}_slug"]
            what = "surge 1/9 Hz" if key == "f140" else "slug U / L_s = 0.03125 Hz"
            row(f"moment_{s0:g}m_dominant_frequency_Hz", PAPER[key], m["f"],
                f"slug flow, largest line of the moment spectrum over the last {w:g} s "
                f"(resolution {1 / w:.5f} Hz); the paper: dominated by the {what}")
            row(f"moment_{s0:g}m_slug_to_surge_line_ratio", None, m["slug"] / m["surge"],
                f"slug line {m['slug'] / 1e3:.2f} kN m over surge line {m['surge'] / 1e3:.2f} "
                f"kN m (uniform flow: surge line {dy[f'm{s0:g}_uniform']['surge'] / 1e3:.2f} "
                "kN m); the paper gives no amplitudes")
    if st:
        row("static_moment_140m_uniform_N_m", PAPER["static140"], g["M140"],
            f"paper: derived, (127.53 - 101.06) kN m = 36 % of it; our touchdown is at s = "
            f"{g['tdp_s']:.1f} m and the moment at 140 m rises {g['dMds140'] / 1e3:.1f} kN m "
            "per m of s there: a touchdown 1 m further out changes it by as much. The "
            "touchdown depends on the soil model and stiffness (not given)")
        row("static_touchdown_s_uniform_m", None, g["tdp_s"],
            "arc length from the anchor of the last node on the seabed, refined to y = 0")
        row("static_peak_moment_uniform_N_m", None, g["peak_moment"],
            f"largest static moment (sag bend), slug frozen at t = 0: "
            f"{g['peak_moment_slug'] / 1e3:.1f} kN m")
        row("static_peak_moment_s_uniform_m", None, g["peak_moment_s"],
            f"where (a flat peak: within 1 % of it over {g['peak_flat']:.0f} m of s)")
        row("sag_bend_moment_estimate_EIw_over_H_N_m", None, g["EIw_H"],
            f"catenary estimate EI w / H with EI {g['EI']:.3g} N m2 (E {g['E'] / 1e9:g} GPa "
            f"assumed), w "
            f"{g['w']:.0f} N/m (pipe + contents - buoyancy), H {g['H'] / 1e3:.0f} kN (at the "
            f"hang-off); a sag-bend peak of the paper's ~100 kN m would need EI "
            f"{1e5 * g['H'] / g['w']:.3g} N m2 (E {1e5 / g['EIw_H'] * g['E'] / 1e9:.0f} GPa) at "
            "this "
            "weight and tension, or the paper's node 35 is not at the peak")
    for r, v in sorted(ls.items()):
        row(f"mean_moment_140m_LsD{r:g}_N_m", PAPER["mean140"].get(r), v["mean140"],
            f"mean over the last {v['window']:g} s (whole slug periods; changes by "
            f"{100 * v['steady']:.2f} % from the window before); half-range "
            f"{v['range140'] / 1e3:.1f} kN m; the paper: Fig. 10 ('kN' in its text)")
    if 100.0 in ls and 280.0 in ls:
        row("mean_moment_140m_LsD280_minus_LsD100_rel_static", PAPER["mean_diff_rel"],
            (ls[280.0]["mean140"] - ls[100.0]["mean140"]) / st["M140"] if st else None,
            "difference of the two means over the static moment at 140 m (uniform flow); a "
            "zero-mean density wave cannot shift the mean moment much in a model that is "
            "close to linear about the static state")
    if dy:
        sp = dy["speeds"]
        row("slug_travel_speed_m_s", PAPER["speed"], dy["speed"],
            f"median over {len(sp)} station pairs 30 m apart in the hanging part "
            f"({sp.min():.3f}-{sp.max():.3f} m/s): cross-correlation lag of the slug's part "
            "of the moment (slug run minus uniform run, the surge removed); the paper gives "
            "v_i = 2.5 m/s as input: a check of the model, not of the paper")
    return pd.DataFrame(rows, columns=list(COLUMNS))



"""Fatigue along the line: the damage of the outer fibre's axial stress at ``points``
stations around the circumference (``[design.fatigue]``), in the time domain (rainflow
counts of a record, :mod:`riser.design.rainflow_damage`) and in the frequency domain
(narrow band and Dirlik of the stress spectrum, :mod:`riser.design.spectral_fatigue`),
against the DNV-RP-C203 S-N curve of the design (:mod:`riser.design.sn_curves`).

Stress at the point of angle phi (:func:`riser.design.wall.fibre_stress`): sigma = T_w /
A_s - (r_o / I)(M_in cos phi + M_out sin phi), the points phi_j = 2 pi j / points from the
in-plane normal. The wall tension's dynamic part includes the pressures' change with the
height (T_w = T_e + p_i A_i - p_e A_o at the instantaneous y): dT_w = dT_e + g (rho_w A_o
- rho_c A_i) dy. Each station reports its worst point.

The verdict (:func:`fatigue_verdict`, with ``[design] design_life``): the fatigue
utilisation DFF x design_life / life along s, passing at most 1 (DNV-OS-F201 Sec. 5 D 500,
DNV-RP-F204).

Units: the damage of a record is dimensionless; a life is in years of
:data:`SECONDS_PER_YEAR`; a damage rate in 1/s.
"""

from __future__ import annotations

import math

import numpy as np

from .rainflow_damage import series_damage
from .sn_curves import sn_curve
from .spectral_fatigue import dirlik_damage_rate, narrow_band_damage_rate
from .wall import fibre_stress, wall_at

#: a Julian year [s]
SECONDS_PER_YEAR = 365.25 * 86400.0
#: stations of a chunk of the time-domain stress array (memory: k x chunk x points)
CHUNK = 64


def angles(points: int) -> np.ndarray:
    """The points' angles phi_j = 2 pi j / points [rad] from the in-plane normal."""
    return 2.0 * math.pi * np.arange(points) / points


def life_years(damage, seconds: float) -> np.ndarray:
    """The life [years] of a damage accumulated over ``seconds`` [s] (inf for none)."""
    d = np.asarray(damage, float)
    with np.errstate(divide="ignore"):
        return np.where(d > 0.0, seconds / np.where(d > 0.0, d, 1.0) / SECONDS_PER_YEAR,
                        np.inf)


def fatigue_verdict(s, life, design_life: float, dff: float) -> dict:
    """The fatigue verdict along the line: the life ``life`` (n,) [years] at stations
    ``s`` (n,) [m] against the design life ``design_life`` [years] with the design fatigue
    factor ``dff`` [-].

    The criterion (DNV-OS-F201 (2010) Sec. 5 D 500, fatigue limit state, and DNV-RP-F204
    (2010) Sec. 2: the accumulated fatigue damage over the design life times the DFF
    shall not exceed 1, D_fat x DFF <= 1): with a constant damage rate 1 / life per year,
    the damage over the design life is design_life / life, so the check is

        fatigue_utilisation = DFF x design_life / life <= 1,

    i.e. the life must reach the required life DFF x design_life (the issue's
    "allowable"). A station without damage (life inf) has utilisation 0; a life of 0,
    utilisation inf; a NaN life a NaN utilisation, which does not pass and ranks as the
    worst station.

    Returns ``required_life`` [years] (DFF x design_life), ``fatigue_utilisation`` (n,)
    [-], ``fatigue_pass`` (n,) bool (utilisation <= 1), the worst station (the largest
    utilisation; the first of equal ones): ``max_fatigue_utilisation`` [-],
    ``max_fatigue_utilisation_s`` [m], ``worst_life`` [years] (its life), and
    ``fatigue_verdict``: 'pass' when every station passes, else 'fail'."""
    s = np.asarray(s, float)
    life = np.asarray(life, float)
    if s.shape != life.shape or life.ndim != 1 or life.size == 0:
        raise ValueError(f"s and life must be equal 1D arrays, got {s.shape} and "
                         f"{life.shape}")
    required = float(design_life) * float(dff)
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.where(np.isinf(life), 0.0, required / np.where(life > 0.0, life, 0.0))
    u = np.where(np.isnan(life), np.nan, u)
    ok = u <= 1.0                                   # NaN: False
    k = int(np.argmax(np.where(np.isnan(u), np.inf, u)))
    return {"required_life": required, "fatigue_utilisation": u, "fatigue_pass": ok,
            "max_fatigue_utilisation": float(u[k]), "max_fatigue_utilisation_s": float(s[k]),
            "worst_life": float(life[k]),
            "fatigue_verdict": "pass" if bool(np.all(ok)) else "fail"}


def verdict_line(verdict: dict, design_life: float, dff: float) -> str:
    """The console line of a :func:`fatigue_verdict`: the worst station and the verdict
    (``fatigue verdict: FAIL at s = 512.3 m: life 0.72 years < DFF 10 x design life 20
    years = 200 years (fatigue utilisation 278)``)."""
    v, life = verdict, verdict["worst_life"]
    u, s, req = v["max_fatigue_utilisation"], v["max_fatigue_utilisation_s"], v["required_life"]
    rule = f"DFF {dff:g} x design life {design_life:g} years = {req:.4g} years"
    if v["fatigue_verdict"] == "pass" and math.isinf(life):
        return f"fatigue verdict: PASS: no fatigue damage along the line ({rule})"
    if v["fatigue_verdict"] == "pass":
        return (f"fatigue verdict: PASS: the least life {life:.3g} years at s = {s:.1f} m "
                f">= {rule} (fatigue utilisation {u:.3g})")
    sign = "<" if u > 1.0 else "?"                  # NaN: no comparison
    return (f"fatigue verdict: FAIL at s = {s:.1f} m: life {life:.3g} years {sign} {rule} "
            f"(fatigue utilisation {u:.3g})")


def time_domain(scene, s, wall_tension, moment_in, moment_out, duration: float) -> dict:
    """Rainflow fatigue of a record: arrays (k, n) of the wall tension [N] and the moment
    components [N m] at stations ``s`` (n,) [m] over ``duration`` [s]. Returns, along s,
    ``fatigue_damage`` (the worst point's Miner sum over the record), ``fatigue_life``
    [years] and ``fatigue_angle_deg`` (the worst point), and the scalars
    ``fatigue_record_s``, ``max_fatigue_damage``, ``min_fatigue_life`` [years] and
    ``min_fatigue_life_s`` [m]."""
    fat = scene.design.fatigue
    curve = sn_curve(fat.sn_curve, fat.environment)
    wall = wall_at(scene, s)
    phi = angles(fat.points)
    n = len(wall.outer_diameter)
    damage = np.zeros(n)
    worst = np.zeros(n)
    for a in range(0, n, CHUNK):
        b = min(a + CHUNK, n)
        sig = fibre_stress(wall.take(slice(a, b)), wall_tension[:, a:b], moment_in[:, a:b],
                           moment_out[:, a:b], phi)                       # (k, c, p)
        for i in range(a, b):
            thick = fat.thickness or float(wall.thickness[i])
            d = np.array([series_damage(sig[:, i - a, j], curve, thick, fat.scf)
                          for j in range(fat.points)])
            j = int(np.argmax(d))
            damage[i], worst[i] = d[j], math.degrees(phi[j])
    life = life_years(damage, duration)
    k = int(np.argmax(damage))
    return {"fatigue_damage": damage, "fatigue_life": life, "fatigue_angle_deg": worst,
            "fatigue_record_s": float(duration), "max_fatigue_damage": float(damage[k]),
            "min_fatigue_life": float(life[k]), "min_fatigue_life_s": float(s[k])}


def stress_transfer(scene, s, h_tension, h_moment_in, h_moment_out, h_dy) -> np.ndarray:
    """Complex amplitudes (n_w, n, p) of the fibre stress [Pa] per unit of the inputs'
    normalisation, from the complex amplitudes (n_w, n) of the effective tension [N], the
    two moment components [N m] and the vertical displacement [m] at stations ``s``
    (the wall tension's change with the height, module docstring)."""
    fat = scene.design.fatigue
    wall = wall_at(scene, s)
    g = scene.gravity
    h_tw = np.asarray(h_tension) + g * (scene.water_density * wall.outer_area
                                        - wall.contents_density * wall.bore_area) * h_dy
    phi = angles(fat.points)
    r = 0.5 * wall.outer_diameter
    out = (h_tw / wall.area)[..., None] - (r / wall.inertia)[:, None] * (
        np.asarray(h_moment_in)[..., None] * np.cos(phi)
        + np.asarray(h_moment_out)[..., None] * np.sin(phi))
    return out


def spectral(scene, s, omega, d_omega: float, amplitudes) -> dict:
    """Spectral fatigue of a linear response: ``amplitudes`` (n_w, n, p) the complex fibre
    stress [Pa] of each wave component (frequencies ``omega`` [rad/s], step ``d_omega``;
    the stress spectrum S(omega_j) = |amplitude_j|^2 / (2 d omega)). Returns along s the
    worst point's damage rates [1/s] by the narrow band (``fatigue_rate_narrow_band``)
    and Dirlik (``fatigue_rate_dirlik``), their lives [years] (``fatigue_life_...``) and
    the worst point's angle by Dirlik (``fatigue_angle_deg``)."""
    fat = scene.design.fatigue
    curve = sn_curve(fat.sn_curve, fat.environment)
    wall = wall_at(scene, s)
    spec = np.abs(np.asarray(amplitudes)) ** 2 / (2.0 * d_omega)            # (n_w, n, p)
    n, p = spec.shape[1], spec.shape[2]
    nb, dk, worst = np.zeros(n), np.zeros(n), np.zeros(n)
    phi = angles(p)
    for i in range(n):
        thick = fat.thickness or float(wall.thickness[i])
        rates_nb = np.empty(p)
        rates_dk = np.empty(p)
        for j in range(p):
            S = spec[:, i, j]
            if not np.any(S > 0.0):
                rates_nb[j] = rates_dk[j] = 0.0
                continue
            rates_nb[j] = narrow_band_damage_rate(omega, S, curve, thick, fat.scf, d_omega)
            rates_dk[j] = dirlik_damage_rate(omega, S, curve, thick, fat.scf, d_omega)
        j = int(np.argmax(rates_dk))
        dk[i], worst[i] = rates_dk[j], math.degrees(phi[j])
        nb[i] = float(np.max(rates_nb))
    return {"fatigue_rate_narrow_band": nb, "fatigue_rate_dirlik": dk,
            "fatigue_life_narrow_band": life_years(nb, 1.0),
            "fatigue_life_dirlik": life_years(dk, 1.0), "fatigue_angle_deg": worst}

"""DNV-OS-F201 (2010) Sec. 5 D: the LRFD combined-loading criterion of a metallic riser
pipe (DNV-ST-F201, 2018, keeps the 2010 criteria), as OrcaFlex's page "Code checks: DNV OS
F201" restates them with their clauses. SI units: [m], [Pa], [N], [N m].

Inputs at a station: the wall (outer diameter D, nominal wall t, SMYS, SMTS, E), the
local internal design pressure p_ld and the local external pressure p_e [Pa], the design
bending moment M_d [N m] and design effective tension T_ed [N]:

- design load effects (Sec. 5 B 200, load combination a of Table 5-2): M_d =
  gamma_F M_F + gamma_E M_E, T_ed = gamma_F T_eF + gamma_E T_eE, the functional part the
  static state, the environmental part the dynamic increment (:mod:`riser.design.checks`);
- wall for the resistances (Sec. 5 C 203): t_2 = t - t_corr;
- characteristic material strengths (Sec. 5 C 303, Table 5-5 without temperature
  derating): f_y = SMYS alpha_U, f_u = SMTS alpha_U;
- burst resistance (Sec. 5 D 200, as the combined loading uses it): p_b(t) = (2 / sqrt 3) (2 t / (D - t)) min(f_y, f_u / 1.15);
- plastic resistances (Sec. 5 D 200): M_k = f_y alpha_c (D - t_2)^2 t_2, T_k = f_y
  alpha_c pi (D - t_2) t_2, with the flow-stress parameter alpha_c = (1 - beta) + beta f_u
  / f_y, beta = (0.4 + q_h) for D / t_2 < 15, (0.4 + q_h)(60 - D / t_2) / 45 for 15 <= D /
  t_2 <= 60, 0 above, and q_h = (p_ld - p_e) / p_b(t_2) 2 / sqrt 3 under a net internal
  overpressure, else 0;
- collapse resistance (Sec. 5 D 400): (p_c - p_el)(p_c^2 - p_p^2) = p_c p_el
  p_p f_0 D / t_2, p_el = 2 E (t_2 / D)^3 / (1 - nu^2), p_p = 2 f_y alpha_fab t_2 / D,
  the root between 0 and min(p_el, p_p);
- combined loading, net internal overpressure (Sec. 5 D 200):
      gamma_SC gamma_m [ (|M_d| / M_k) sqrt(1 - ((p_ld - p_e) / p_b)^2) + (T_ed / T_k)^2 ]
        + ((p_ld - p_e) / p_b)^2 <= 1;
- combined loading, net external overpressure (Sec. 5 D 200):
      (gamma_SC gamma_m)^2 [ |M_d| / M_k + (T_ed / T_k)^2 ]^2
        + (gamma_SC gamma_m)^2 ((p_e - p_min) / p_c)^2 <= 1,
  with p_min the local minimum internal pressure, taken as p_ld.

The utilisation reported is the left-hand side of the internal-overpressure criterion and
the square root of the external one's (that criterion is a sum of squares; its root is linear in the loads as the internal
one is, and the two agree at p_ld = p_e): <= 1 passes either way. Factors (the design's
defaults): gamma_SC 1.04 / 1.14 / 1.26 for the safety classes low / normal / high (Table
5-3), gamma_m 1.15 (Table 5-4), gamma_F 1.1, gamma_E 1.3 (Table 5-2), alpha_U 0.96,
alpha_fab 1.0 (seamless), f_0 0.005, nu 0.3. The condition factor gamma_c (Table 5-11)
is taken as 1.
"""

from __future__ import annotations

import math

import numpy as np

#: gamma_SC by safety class (DNV-OS-F201 Table 5-3)
GAMMA_SC = {"low": 1.04, "normal": 1.14, "high": 1.26}
#: Poisson's ratio of the elastic collapse pressure
POISSON = 0.3
#: bisection steps of the collapse pressure's cubic (2^-80 of its bracket: round-off)
BISECTIONS = 80


def burst_resistance(D, t, fy, fu):
    """p_b(t) [Pa] (Sec. 5 D 200)."""
    return 2.0 / math.sqrt(3.0) * (2.0 * t / (D - t)) * np.minimum(fy, fu / 1.15)


def collapse_resistance(D, t, E, fy, alpha_fab: float, f0: float, nu: float = POISSON):
    """p_c(t) [Pa] (Sec. 5 D 400): the root of (p - p_el)(p^2 - p_p^2) - p p_el p_p f0 D /
    t in (0, min(p_el, p_p)] by bisection (at p = 0 the cubic is p_el p_p^2 > 0, at the
    bracket's top it is <= 0)."""
    D, t, E, fy = np.broadcast_arrays(*(np.asarray(a, float) for a in (D, t, E, fy)))
    p_el = 2.0 * E * (t / D) ** 3 / (1.0 - nu * nu)
    p_p = 2.0 * fy * alpha_fab * t / D

    def cubic(p):
        return (p - p_el) * (p * p - p_p * p_p) - p * p_el * p_p * f0 * D / t

    lo, hi = np.zeros_like(p_el), np.minimum(p_el, p_p)
    for _ in range(BISECTIONS):
        mid = 0.5 * (lo + hi)
        up = cubic(mid) > 0.0
        lo, hi = np.where(up, mid, lo), np.where(up, hi, mid)
    return 0.5 * (lo + hi)


def flow_stress_factor(D, t2, fy, fu, q_h):
    """alpha_c (Sec. 5 D 200; beta by the slenderness D / t_2)."""
    slender = D / t2
    beta = np.where(slender < 15.0, 0.4 + q_h,
                    np.where(slender <= 60.0, (0.4 + q_h) * (60.0 - slender) / 45.0, 0.0))
    return (1.0 - beta) + beta * fu / fy


def resistances(design, wall) -> dict:
    """What does not change with the loads, at the wall's stations: t_2 [m], f_y, f_u
    [Pa], gamma_SC gamma_m, the burst p_b(t_2) and collapse p_c(t_2) resistances [Pa] (a
    dynamic run computes them once)."""
    t2 = wall.thickness - design.corrosion_allowance
    fy = wall.yield_strength * design.alpha_u
    fu = wall.tensile_strength * design.alpha_u
    return {"t2": t2, "fy": fy, "fu": fu,
            "gamma": GAMMA_SC[design.safety_class] * design.gamma_m,
            "p_b": burst_resistance(wall.outer_diameter, t2, fy, fu),
            "p_c": collapse_resistance(wall.outer_diameter, t2, wall.youngs_modulus, fy,
                                       design.alpha_fab, design.ovality)}


def utilisation(design, wall, p_ld, p_e, M_d, T_ed, fixed: dict | None = None) -> np.ndarray:
    """The combined-loading utilisation (module docstring) at stations: ``design`` the
    [design] part, ``wall`` a :class:`riser.design.wall.Wall`, pressures [Pa], design
    moment [N m] and effective tension [N] (arrays that broadcast); ``fixed``: the
    wall's :func:`resistances`, when already at hand."""
    r = fixed if fixed is not None else resistances(design, wall)
    D, t2, fy, fu, gamma = wall.outer_diameter, r["t2"], r["fy"], r["fu"], r["gamma"]
    p_ld, p_e = np.asarray(p_ld, float), np.asarray(p_e, float)
    M = np.abs(np.asarray(M_d, float))
    T = np.asarray(T_ed, float)
    over = (p_ld - p_e) / r["p_b"]
    internal = over >= 0.0
    q_h = np.where(internal, over * 2.0 / math.sqrt(3.0), 0.0)
    a_c = flow_stress_factor(D, t2, fy, fu, q_h)
    M_k = fy * a_c * (D - t2) ** 2 * t2
    T_k = fy * a_c * math.pi * (D - t2) * t2
    load = M / M_k
    u_int = (gamma * (load * np.sqrt(np.maximum(1.0 - over * over, 0.0)) + (T / T_k) ** 2)
             + over * over)
    u_ext = gamma * np.sqrt((load + (T / T_k) ** 2) ** 2 + ((p_e - p_ld) / r["p_c"]) ** 2)
    return np.where(internal, u_int, u_ext)

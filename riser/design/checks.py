"""The design checks of a result: stresses and the code's utilisation along the line
(static profile, and per sample of a dynamic run through :mod:`riser.design.dynamic`).

Load effects. A static result is all functional: M_d = gamma_F |M|, T_ed = gamma_F T_e.
In a dynamic run (or a frequency-domain response) the functional part is the static state
and the environmental part the increment over it: M_d = |gamma_F M_F + gamma_E (M -
M_F)| (moment vectors across the tangent: in-plane and out-of-plane components),
T_ed = gamma_F T_F + gamma_E (T - T_F) (effective tensions). API's von Mises check takes
the stresses unfactored. The pressures follow the line's heights (the sea's and the
contents' heads at the instantaneous y).

Columns (profile.csv with [design]; SI): ``wall_tension`` [N], ``stress_axial`` T_w /
A_s, ``stress_bending`` M r_o / I, ``stress_hoop`` (inner surface), ``von_mises`` (the
largest over the section) [Pa] and ``utilisation`` [-] (:data:`COLUMNS`).
"""

from __future__ import annotations

import numpy as np

from . import api_2rd, dnv_f201
from .wall import pressures, stresses, wall_at, wall_tension

#: the profile columns of the design checks, after ``wall_tension``
COLUMNS = ("stress_axial", "stress_bending", "stress_hoop", "von_mises", "utilisation")


def utilisation(design, wall, p_i, p_e, M_d, T_ed, von_mises, fixed=None) -> np.ndarray:
    """The code's utilisation: DNV's from the design loads M_d [N m], T_ed [N] and the
    pressures [Pa], API's from the (unfactored) von Mises stress [Pa]; ``fixed``: DNV's
    :func:`~riser.design.dnv_f201.resistances` of the wall, when at hand."""
    if design.code == "dnv-st-f201":
        return dnv_f201.utilisation(design, wall, p_i, p_e, M_d, T_ed, fixed)
    return api_2rd.utilisation(design, wall, von_mises)


def static_columns(scene, s, y, tension, moment) -> dict:
    """The design columns of a static profile (arc lengths ``s`` [m] of ``scene``,
    heights ``y`` [m] with the hang-off last, effective tension [N], moment magnitude
    [N m]): ``wall_tension`` and :data:`COLUMNS`."""
    y = np.asarray(y, float)
    wall = wall_at(scene, s)
    p_i, p_e = pressures(scene, wall, y, float(y[-1]))
    tw = wall_tension(scene, wall, tension, p_i, p_e)
    st = stresses(wall, tw, moment, p_i, p_e)
    g = scene.design.gamma_f
    u = utilisation(scene.design, wall, p_i, p_e, g * np.abs(moment),
                    g * np.asarray(tension, float), st.von_mises)
    return {"wall_tension": tw, "stress_axial": st.axial, "stress_bending": st.bending,
            "stress_hoop": st.hoop, "von_mises": st.von_mises, "utilisation": u}


def apply(scene, profile):
    """``profile`` (a :class:`riser.results.profile.Profile` of ``scene``, which has a
    [design]) with its design columns and ``design_code``."""
    cols = static_columns(scene, profile.s, profile.y, profile.tension, profile.moment)
    return profile.replace(**cols, design_code=scene.design.code)


def with_design(scene, result):
    """A method's :class:`riser.results.result.SolveResult` of ``scene`` with the design
    checks of its static profile (``result`` itself without [design] or a profile). Run
    once, after the solve, by the method registry (``verification/methods.py``): the
    checks post-process every method's results alike, and no method imports them."""
    if scene.design is None or result.profile is None:
        return result
    return result.replace(profile=apply(scene, result.profile))


def amplitude_columns(scene, s, y, tension, moment, tension_amp, moment_amp) -> dict:
    """The design columns of a frequency-domain response: the static state (effective
    tension [N], moment magnitude [N m] at stations ``s`` [m], heights ``y`` [m]) plus
    dynamic amplitudes (``tension_amp`` [N], ``moment_amp`` [N m]: a harmonic's, or a
    sea's most probable maxima) combined in phase at the worse sign (phases are not
    combined: an upper bound of the cycle's largest value). DNV: M_d = gamma_F |M| +
    gamma_E M_amp, T_ed the larger |gamma_F T +- gamma_E T_amp|; API: von Mises of the
    larger wall tension and the moment |M| + M_amp. Returns ``von_mises`` [Pa] and
    ``utilisation`` [-]."""
    y = np.asarray(y, float)
    wall = wall_at(scene, s)
    p_i, p_e = pressures(scene, wall, y, float(y[-1]))
    d = scene.design
    T, M = np.asarray(tension, float), np.abs(np.asarray(moment, float))
    dT, dM = np.abs(np.asarray(tension_amp, float)), np.abs(np.asarray(moment_amp, float))
    tw = wall_tension(scene, wall, T, p_i, p_e)
    vm = np.maximum(stresses(wall, tw + dT, M + dM, p_i, p_e).von_mises,
                    stresses(wall, tw - dT, M + dM, p_i, p_e).von_mises)
    t_ed = np.maximum(np.abs(d.gamma_f * T + d.gamma_e * dT),
                      np.abs(d.gamma_f * T - d.gamma_e * dT))
    u = utilisation(d, wall, p_i, p_e, d.gamma_f * M + d.gamma_e * dM, t_ed, vm)
    return {"von_mises": vm, "utilisation": u}


#: phases of a cycle sampled for the largest utilisation of a harmonic response
CYCLE_PHASES = 72


def harmonic_columns(scene, s, y, tension, moment_in, amplitudes: dict) -> dict:
    """The largest utilisation and von Mises stress over a cycle of a first-harmonic
    response q = q_0 + Re(Q e^{i phi}) at stations ``s`` [m]: the static heights ``y``
    [m], effective tension [N] and in-plane moment [N m] (signed; a planar static state,
    no out-of-plane moment), ``amplitudes`` the complex Q of ``tension``, ``moment``,
    ``moment_out`` [N m] and ``dy`` [m] (:mod:`riser.results.response`). The static state is the
    functional part, the harmonic the environmental one (as a dynamic run's samples);
    :data:`CYCLE_PHASES` phases, the largest kept (the phase grid's error in the peak is
    below 1 - cos(pi / 72) = 1e-3 of the dynamic part)."""
    y0 = np.asarray(y, float)
    wall = wall_at(scene, s)
    d = scene.design
    fixed = dnv_f201.resistances(d, wall) if d.code == "dnv-st-f201" else None
    T0, M0 = np.asarray(tension, float), np.asarray(moment_in, float)
    u_max = np.full(T0.shape, -np.inf)
    vm_max = np.full(T0.shape, -np.inf)
    for phi in 2.0 * np.pi * np.arange(CYCLE_PHASES) / CYCLE_PHASES:
        rot = np.exp(1j * phi)

        def part(key):
            return (np.asarray(amplitudes[key]) * rot).real
        y = y0 + part("dy")
        p_i, p_e = pressures(scene, wall, y, float(y[-1]))
        T = T0 + part("tension")
        m_in, m_out = M0 + part("moment"), part("moment_out")
        tw = wall_tension(scene, wall, T, p_i, p_e)
        st = stresses(wall, tw, np.hypot(m_in, m_out), p_i, p_e)
        m_d = np.hypot(d.gamma_f * M0 + d.gamma_e * part("moment"), d.gamma_e * m_out)
        t_ed = d.gamma_f * T0 + d.gamma_e * part("tension")
        u = utilisation(d, wall, p_i, p_e, m_d, t_ed, st.von_mises, fixed)
        np.maximum(u_max, u, out=u_max)
        np.maximum(vm_max, st.von_mises, out=vm_max)
    return {"utilisation": u_max, "von_mises": vm_max}

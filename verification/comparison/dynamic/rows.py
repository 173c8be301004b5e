"""The rows of the dynamic comparison (:mod:`.protocol`): the verdict rows with their
tolerances and reasons (:data:`TOLERANCES`), the stations, the contact zone and the
nonlinearity the VFIFE shows. VFIFE against the frequency domain (FD), first-harmonic
amplitudes (see :mod:`riser.results.response` for the convention)."""

from __future__ import annotations

import functools

import math

import numpy as np

from riser.design.checks import harmonic_columns
from riser.results.profile import waves
from riser.results.response import HarmonicResponse
from riser.model.scene import Scene
from riser.model.sections import segment_properties

from ..row import Row, Tolerance, Verdict

#: the first harmonic's change between the window's halves above which a run is said
#: not to have settled (see :mod:`.protocol`, where the settling is doubled on it)
DRIFT_LIMIT = 1e-3

#: why the rows of the larger amplitudes of a sweep are reported, not judged
ABOVE_SMALLEST = ("above the sweep's smallest amplitude: the difference measures the "
                  "nonlinearity the FD leaves out, reported, not judged")
#: name -> (tolerance, basis, reason)
TOLERANCES = {
    "hang_off_tension_amplitude": (
        0.005, "of the FD amplitude", "the issue's bound; the FD's grid error is < 1e-4 "
        "and the VFIFE's 1 m elements and window give ~1e-3 (measured on scr-steel)"),
    "hang_off_tension_phase_deg": (
        1.0, "deg", "a 0.5 % amplitude error of a complex response is ~0.3 deg of phase; "
        "a lag of one sample (9 deg) would fail"),
    "tension_amplitude": (
        0.01, "of its peak along s", "two discretisations of a response varying along s; "
        "the window's remaining transient is ~1e-3"),
    "moment_amplitude": (
        0.01, "of its peak along s (outside the contact zone)", "the issue's bound for "
        "curvature/moment"),
    "displacement_amplitude": (
        0.01, "of its peak along s", "as the tension"),
    "min_tension": (
        0.005, "of the static T_max", "the static agreement (1e-4 of T_max) plus the "
        "dynamic part's 1 %"),
}


def contact_zone(scene: Scene, fd: HarmonicResponse, static) -> tuple[float, float] | None:
    """The s range [m] where the seabed contact may open or close over the cycle: the
    static height within the FD's vertical motion amplitude of the seabed, widened by
    three of the larger of the bending length sqrt(EI/T) and the seabed's (4 EI / k)^1/4."""
    p = static.profile
    if p.tdp_s is None and float(np.min(p.y)) > 0.0:
        return None
    y0 = np.interp(fd.s, p.s, p.y)
    reach = np.abs(fd.amplitudes["dy"])
    near = np.abs(y0) < reach
    td = p.tdp_s if p.tdp_s is not None else float(fd.s[np.argmin(np.abs(y0))])
    i = j = int(np.argmin(np.abs(fd.s - td)))
    while i > 0 and near[i - 1]:                 # the run of such points around the
        i -= 1                                   # touchdown (not the anchor's)
    while j + 1 < fd.s.size and near[j + 1]:
        j += 1
    lo, hi = float(fd.s[i]), float(fd.s[j])
    k = scene.seabed.stiffness if scene.seabed is not None else 0.0
    T = max(float(np.interp(td, p.s, p.tension)), 1.0)
    EI = next((q.EI for q in segment_properties(scene) if q.s_start <= td <= q.s_end),
              segment_properties(scene)[0].EI)
    length = math.sqrt(EI / T)
    if k > 0.0:
        length = max(length, (4.0 * EI / k) ** 0.25)
    return max(lo - 3.0 * length, 0.0), min(hi + 3.0 * length, float(fd.s[-1]))


def _along(fd_q: np.ndarray, vf_q: np.ndarray, s: np.ndarray, keep=None):
    """(largest |VFIFE| - |FD| amplitude difference over the FD's peak, where [m])."""
    a, b = np.abs(fd_q), np.abs(vf_q)
    if keep is not None:
        a, b, s = a[keep], b[keep], s[keep]
    if a.size == 0:
        return None, None
    peak = float(np.max(np.abs(fd_q)))
    d = b - a
    i = int(np.argmax(np.abs(d)))
    return (float(d[i] / peak) if peak > 0 else 0.0), float(s[i])


#: why a row is not judged when the FD's first harmonic of its quantity is zero
FIRST_ORDER_ZERO = ("zero at first order (a motion across the plane changes the tension "
                    "and the in-plane bending at second order only): not judged")
#: below this fraction of its static scale a first harmonic is zero at first order
ZERO_FIRST_ORDER = 1e-9


def _row(name, fd_value, vf_value, rel, where=None, slack=False, judged=True,
         bound: str | None = None, method: str = "vfife") -> Row:
    """A verdict row, VFIFE against FD (``rel``: the relative difference; ``where`` [m]);
    its tolerance that of ``bound`` (default: the row's own name) in :data:`TOLERANCES`,
    judged relative; not judged when ``judged`` is False, the line goes slack (``slack``)
    or a first harmonic is zero at first order."""
    tol, basis, reason = TOLERANCES.get(bound or name, (None, "", "reported, not judged"))
    if rel is None and judged and fd_value is not None and fd_value == 0.0:
        judged, reason = False, FIRST_ORDER_ZERO
    elif not judged:
        reason = "reported, not judged"
    ok = None if (slack or not judged or tol is None or rel is None) else bool(abs(rel) <= tol)
    tolerance = (Tolerance(tol, None, basis, "", reason, relative=True) if judged
                 else Tolerance(None, None, basis, relative=True))
    return Row(name, {"fd": fd_value, method: vf_value}, "", None, rel, tolerance,
               Verdict.of(ok), "" if judged else reason, where)


def agreement_rows(scene: Scene, fd: HarmonicResponse, vf: dict, static,
                   method: str = "vfife"):
    """The verdict rows (see the module docstring), the contact zone and the warnings;
    ``vf`` the time domain's harmonics, its values under ``method``'s name (the VFIFE,
    or the ANCF judged alike)."""
    _row_ = functools.partial(_row, method=method)
    s = vf["s"]
    q = {k: fd.at(k, s) for k in ("tension", "moment", "moment_out", "dx", "dy", "dz")}
    T0 = np.interp(s, fd.s, fd.static["tension"])
    fd_min = float(np.min(T0 - np.abs(q["tension"])))
    warns = []
    slack = fd_min < 0.0
    if slack:
        warns.append(f"slack_over_cycle: the FD's minimum tension {fd_min:.4g} N is below "
                     "zero: the line goes slack over the cycle, outside the linear model")
    tmax = float(np.max(static.profile.tension))
    top_fd, top_vf = q["tension"][-1], vf["tension"].first[-1]
    if float(np.max(np.abs(q["tension"]))) <= ZERO_FIRST_ORDER * tmax:
        rows = [_row_(name, 0.0, value, None, s[-1]) for name, value in (
            ("hang_off_tension_amplitude", abs(top_vf)),
            ("hang_off_tension_phase_deg", math.degrees(np.angle(top_vf))),
            ("tension_amplitude", float(np.max(vf["tension"].amplitude))))]
    else:
        rows = [_row_("hang_off_tension_amplitude", abs(top_fd), abs(top_vf),
                     abs(top_vf) / abs(top_fd) - 1.0, s[-1], slack),
                _row_("hang_off_tension_phase_deg", math.degrees(np.angle(top_fd)),
                     math.degrees(np.angle(top_vf)),
                     wrap_deg(math.degrees(np.angle(top_vf) - np.angle(top_fd))), s[-1], slack)]
        rel, where = _along(q["tension"], vf["tension"].first, s)
        rows.append(_row_("tension_amplitude", float(np.max(np.abs(q["tension"]))),
                         float(np.max(vf["tension"].amplitude)), rel, where, slack))
    zone = contact_zone(scene, fd, static)
    keep = np.ones(s.size, bool) if zone is None else (s < zone[0]) | (s > zone[1])
    for name in ("moment", "moment_out"):
        if float(np.max(np.abs(q[name]))) == 0.0:
            continue
        rel, where = _along(q[name], vf[name].first, s, keep)
        rows.append(_row_(f"{name}_amplitude", float(np.max(np.abs(q[name][keep]))),
                         float(np.max(vf[name].amplitude[keep])), rel, where, slack,
                         bound="moment_amplitude"))
        if zone is not None:
            rel, where = _along(q[name], vf[name].first, s, ~keep)
            rows.append(_row_(f"{name}_amplitude_contact_zone", None, None, rel, where,
                             judged=False))
    disp_fd = np.sqrt(sum(np.abs(q[k]) ** 2 for k in ("dx", "dy", "dz")))
    disp_vf = np.sqrt(sum(vf[k].amplitude ** 2 for k in ("dx", "dy", "dz")))
    rel, where = _along(disp_fd, disp_vf, s)
    rows.append(_row_("displacement_amplitude", float(np.max(disp_fd)),
                     float(np.max(disp_vf)), rel, where, slack))
    rows.append(_row_("min_tension", fd_min, vf["min_tension"],
                     (vf["min_tension"] - fd_min) / tmax, None, slack))
    if scene.design is not None and vf.get("max_utilisation") is not None:
        rows.append(design_row(scene, fd, vf, s, method))
    if vf["drift"] > DRIFT_LIMIT:
        warns.append(f"window_drift: the {method.upper()}'s first harmonic changed by "
                     f"{vf['drift']:.2%} of its peak between the window's halves after "
                     f"{vf.get('settle_periods', '?')} periods of settling: "
                     "the start-up transient has not decayed")
    return rows, zone, warns


def station_rows(fd: HarmonicResponse, vf: dict, static) -> list[dict]:
    """Tension amplitude and phase at the hang-off, the touchdown, the sag bends and the
    crests of the static line (reported)."""
    p = static.profile
    crests, sags = waves(p)
    st = [("hang-off", float(p.s[-1]))]
    if p.tdp_s is not None:
        st.append(("touchdown", float(p.tdp_s)))
    st += [(f"sag bend {i + 1}", w["s"]) for i, w in enumerate(sags)]
    st += [(f"crest {i + 1}", w["s"]) for i, w in enumerate(crests)]
    s = vf["s"]
    out = []
    for name, sv in st:
        a = complex(fd.at("tension", sv))
        vt = vf["tension"].first
        b = complex(np.interp(sv, s, vt.real) + 1j * np.interp(sv, s, vt.imag))
        out.append({"station": name, "s": sv, "fd_amplitude": abs(a), "vfife_amplitude":
                    abs(b), "rel_diff": abs(b) / abs(a) - 1.0 if abs(a) > 0 else None,
                    "phase_diff_deg": wrap_deg(math.degrees(np.angle(b) - np.angle(a)))})
    return out


def nonlinearity(vf: dict, zone) -> dict:
    """How far the VFIFE's response is from harmonic: the higher harmonics over the first
    at the hang-off and at worst along s (where the first harmonic is a tenth of its peak
    or more), and the envelope (max - min)/2 over the first-harmonic amplitude; of the
    tension, or of the out-of-plane displacement for a motion along z (whose tension
    changes at second order only: ``quantity`` says which)."""
    key = "dz" if vf.get("axis") == "z" else "tension"
    q = vf[key]
    big = q.amplitude >= 0.1 * float(np.max(q.amplitude))
    # the largest free displacement (the hang-off's is the prescribed sine)
    i = int(np.argmax(q.amplitude[:-1])) if key == "dz" else -1
    return {"quantity": key, "hang_off_higher_harmonics": float(q.higher_ratio[i]),
            "max_higher_harmonics": float(np.max(q.higher_ratio[big])),
            "hang_off_envelope_ratio": float(q.half_range[i] / max(q.amplitude[i], 1e-300)),
            "contact_zone": zone, "window_drift": vf["drift"],
            "settle_periods": vf.get("settle_periods")}


def wrap_deg(deg: float) -> float:
    """An angle difference [deg] in [-180, 180)."""
    return (deg + 180.0) % 360.0 - 180.0


def design_row(scene: Scene, fd: HarmonicResponse, vf: dict, s,
               method: str = "vfife") -> Row:
    """With [design], the largest dynamic utilisation: the FD's over a cycle of its first
    harmonic about the static state (:func:`riser.design.checks.harmonic_columns`) against
    the VFIFE's largest over its window (every sample: its higher harmonics too);
    reported. A 3D static state has an out-of-plane static moment the FD's static
    record does not carry: not compared."""
    if not scene.statics_planar:
        return _row("max_utilisation_dynamic", None, vf["max_utilisation"], None,
                    judged=False, method=method)
    q = {k: fd.at(k, s) for k in ("tension", "moment", "moment_out", "dy")}
    y = np.interp(s, vf["static_s"], vf["static_y"])
    cols = harmonic_columns(scene, s, y, np.interp(s, fd.s, fd.static["tension"]),
                            np.interp(s, fd.s, fd.static["moment"]), q)
    j = int(np.argmax(cols["utilisation"]))
    fd_u = float(cols["utilisation"][j])
    return _row("max_utilisation_dynamic", fd_u, vf["max_utilisation"],
                vf["max_utilisation"] / fd_u - 1.0, float(s[j]), judged=False,
                method=method)

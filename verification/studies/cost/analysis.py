"""Analysis of the solved runs of a cost study: the reference's uncertainty, the VFIFE
relaxation errors, the observed order in element length, the VFIFE Richardson limit and
the self errors (:func:`analyse`); the cost exponents (:func:`cost_scaling`); and the
cheapest run reaching each accuracy (:func:`recommendations`)."""

from __future__ import annotations

import math

import numpy as np

from .errors import QUANTITIES, distance, rel_errors, signed_errors
from .fits import NOISE_MARGIN, element_length_fits, richardson_limits
from .records import CostStudy
from .settings import TIGHT_CREEP, TIGHT_TOLERANCE
from .touchdown import (
    asymptotic_length,
    boundary_layer_length,
    foundation_length,
    liftoff_interpolation,
)

#: accuracies of the recommendation table (relative errors)
TARGETS = (1e-2, 1e-3, 1e-4)


def _sweep(st: CostStudy, name: str) -> list:
    return sorted([r for r in st.runs if r.setting.method == "vfife"
                   and r.setting.setting == name and r.values],
                  key=lambda r: -r.setting.value)


def analyse(st: CostStudy) -> None:
    """Reference uncertainty, relaxation errors, orders, VFIFE limit and self errors."""
    depth = st.depth
    bvp_tol = sorted([r for r in st.runs if r.setting.method == "bvp" and r.values
                      and r.setting.setting == "tolerance"], key=lambda r: r.setting.value)
    # BVP: every run against the reference; the reference's own uncertainty is its change
    # from the next-finest tolerance
    for r in st.runs:
        if r.method == "bvp" and r.values:
            r.self_errors = dict(r.errors)
    if len(bvp_tol) >= 2:
        st.bvp_self = dict(bvp_tol[1].errors)
    default, tight = _sweep(st, "element_length"), _sweep(st, "element_length_tight")
    # relaxation error, measured against a run with both tolerances 10x tighter than the
    # order sweep's at the middle element length: of the default settings (noise_floor)
    # and of the order sweep (sweep_noise, part of the floor of the fit)
    check = next((r for r in st.runs if r.setting.setting == "element_length_tight_check"
                  and r.converged and r.values), None)
    if check is not None:
        hmid = check.setting.value
        for attr, rs in (("noise_floor", default), ("sweep_noise", tight)):
            base = next((r for r in rs if math.isclose(r.setting.value, hmid)), None)
            if base is not None:
                err = rel_errors(base.values, check.values, depth)
                err["curve_distance"] = distance(check.profile, base.profile, depth)
                setattr(st, attr, {q: (v if v is not None else 0.0) for q, v in err.items()})
    if len(tight) >= 3:
        order_sweep = tight
        label = (f"static tolerance {TIGHT_TOLERANCE:g} x element weight and creep tolerance "
                 f"{TIGHT_CREEP:g} x line length, mesh sequencing as by default")
        noise = st.sweep_noise
    elif st.has_order_sweep:      # fewer than three tight runs converged: fall back
        order_sweep, label, noise = default, "default static and creep tolerances", \
            st.noise_floor
    else:                         # the fast sweep has no order sweep: no orders, no limit
        order_sweep, label, noise = [], "", {}
    st.order_sweep = label
    st.order_setting = order_sweep[0].setting.setting if order_sweep else ""
    prof = st.reference.profile
    st.boundary_layer = boundary_layer_length(st.fixed_scene, prof)
    st.foundation_length = foundation_length(st.fixed_scene, prof)
    st.asymptotic = asymptotic_length(st.fixed_scene, prof)
    st.liftoff = liftoff_interpolation(prof)
    if len(order_sweep) < 2:
        return
    floor = {q: NOISE_MARGIN * max(noise.get(q, 0.0), st.bvp_self.get(q) or 0.0)
             for q in QUANTITIES}
    hs = [r.setting.value for r in order_sweep]
    errors = {q: [r.errors.get(q) for r in order_sweep] for q in QUANTITIES
              if any(r.errors.get(q) is not None for r in order_sweep)}
    st.orders = element_length_fits(hs, errors, floor, st.asymptotic)
    signed = [signed_errors(r.values, st.ref_values, depth) for r in order_sweep]
    for q, fit in st.orders.items():
        fit["signed"] = [sg.get(q) for h, sg in zip(hs, signed) if h in fit["points"]]
    # VFIFE's own limit (Richardson, three finest lengths): self errors, consistency check
    limits, rorders = richardson_limits(hs, [r.values for r in order_sweep])
    st.vfife_limit, st.vfife_richardson_order = limits, rorders
    st.limit_vs_reference = rel_errors(limits, st.ref_values, depth)
    for r in st.runs:
        if r.setting.method == "vfife" and r.values:
            r.self_errors.update(rel_errors(r.values, limits, depth, norm_values=st.ref_values))
    fin = order_sweep[-1].profile
    for r in st.runs:
        if r.setting.method == "vfife" and r.profile is not None:
            r.self_errors["curve_distance"] = distance(fin, r.profile, depth)


def cost_scaling(st: CostStudy) -> None:
    """Cost exponents: wall time ~ elements^a (statics, 1 s of dynamics), steps ~ n^b."""
    for kind, setting in (("statics", "element_length"),
                          ("statics_tight", "element_length_tight"),
                          ("dynamics_1s", "dynamics_1s_element_length")):
        rs = [r for r in st.runs if r.setting.setting == setting and r.converged and r.size
              and r.times]
        if len(rs) < 2:
            continue
        n = np.array([r.size for r in rs], float)
        t = np.array([r.wall_time_s for r in rs])
        out = {"elements": n.tolist(), "time": t.tolist()}
        out["exponent_all"] = float(np.polyfit(np.log(n), np.log(t), 1)[0])
        fine = n >= np.sort(n)[-min(3, len(n))]
        out["exponent_fine"] = float(np.polyfit(np.log(n[fine]), np.log(t[fine]), 1)[0])
        steps = np.array([r.steps or np.nan for r in rs], float)
        if np.all(np.isfinite(steps)):
            out["steps"] = steps.tolist()
            out["steps_exponent_fine"] = float(np.polyfit(np.log(n[fine]), np.log(steps[fine]),
                                                          1)[0])
            out["us_per_element_step"] = (1e6 * t / (n * steps)).tolist()
        st.scaling[kind] = out


def recommendations(st: CostStudy) -> list[dict]:
    """Cheapest converged run of each method reaching each target in each quantity, against
    the BVP reference (for the BVP: its error against its finest tolerance)."""
    out = []
    stat = [r for r in st.runs if r.converged and r.values and r.setting.method != "vfife-dyn"]
    for q in QUANTITIES:
        if all(r.errors.get(q) is None for r in stat):
            continue
        for tgt in TARGETS:
            row = {"quantity": q, "target": tgt}
            for method in ("bvp", "vfife"):
                ok = [r for r in stat if r.method == method and r.errors.get(q) is not None
                      and r.errors[q] <= tgt]
                if method == "bvp":   # the reference itself is not a recommendation
                    ok = [r for r in ok if r is not st.reference] or (
                        [st.reference] if st.reference in ok else [])
                row[method] = min(ok, key=lambda r: r.wall_time_s) if ok else None
            out.append(row)
    return out

"""What the dynamic sweep of the cost study says (:func:`analyse`): the reference of each
quantity and its uncertainty, the errors of every run, the observed order in element
length, the effect of the step factor (and, with ``--full``, its order), the cost scaling;
and the cheapest run reaching each accuracy (:func:`recommendations`). Numbers only; the
wording is in :mod:`verification.studies.cost.dynamics_report`.

Reference (per quantity): the run at the finest element length and the smallest step
factor of the sweep, unless the element-length sequence at the scene's factor is clean
enough for a Richardson limit: three finest lengths, an order within
:data:`RICHARDSON_ORDERS`, and a step-factor change at the finest length below
:data:`STEP_SHARE` of its last mesh change. Its uncertainty (an estimate): the larger of
its change from the next-coarser length (at the same factor) and from the scene's factor
at the same length (when that run failed: from the next-larger factor that completed there,
else the same change at the next-coarser length), or, for a Richardson limit, the size of
the extrapolation.
"""

from __future__ import annotations

import math

import numpy as np

from .analysis import TARGETS
from .dynamics import QUANTITIES, DynRun, DynStudy
from .fits import NOISE_MARGIN, PRE_ASYMPTOTIC, fit_order, richardson

#: orders accepted for a Richardson reference: the expected order 2 in h, +/- 0.5
RICHARDSON_ORDERS = (1.5, 2.5)
#: a Richardson reference needs the step-factor change at the finest length below this
#: share of the sequence's last mesh change
STEP_SHARE = 0.1
#: the step factor "matters" when its change at some length exceeds this share of the
#: mesh error there and :data:`MATTERS_ABOVE` (the finest accuracy judged: a smaller
#: change moves no recommendation)
MATTERS = 0.1
MATTERS_ABOVE = min(TARGETS)


def _ok(ds: DynStudy) -> list[DynRun]:
    return [r for r in ds.runs if r.converged and r.amplitude is not None]


def _at(runs, h: float, f: float) -> DynRun | None:
    return next((r for r in runs if math.isclose(r.h, h) and math.isclose(r.factor, f)),
                None)


def _rel(a, b, norm) -> float | None:
    if a is None or b is None or not norm:
        return None
    return abs(a - b) / abs(norm)


def analyse(ds: DynStudy) -> None:
    """Fill the reference, errors, orders, step effect, step order and cost scaling."""
    ok = _ok(ds)
    if not ok:
        return
    hmin = min(r.h for r in ok)
    ds.ref_run = min((r for r in ok if math.isclose(r.h, hmin)), key=lambda r: r.factor)
    seq = sorted((r for r in ok if math.isclose(r.factor, ds.default_factor)),
                 key=lambda r: -r.h)
    for q in QUANTITIES:
        ds.reference[q] = _reference(q, ds.ref_run, seq, ok, ds.default_factor)
    for r in ds.runs:
        r.errors = {q: _rel(r.value(q), ds.reference[q]["value"], ds.reference[q]["value"])
                    for q in QUANTITIES} if r in ok else {}
    _orders(ds, seq, ok)
    _step(ds, ok)
    _scaling(ds, seq, ok)


def _reference(q: str, ref: DynRun, seq: list, ok: list, default_factor: float) -> dict:
    value = ref.value(q)
    fine = _at(ok, ref.h, default_factor)
    step = _rel(fine.value(q), value, value) if fine is not None and fine is not ref else None
    coarser = sorted({r.h for r in ok if r.h > ref.h})
    step_at, step_factor = ref.h, default_factor
    if step is None:      # the run at the scene's factor failed: the next-larger factor that
        up = sorted((r for r in ok if math.isclose(r.h, ref.h) and r.factor > ref.factor),
                    key=lambda r: r.factor)     # completed there, else the next length's
        if up:
            step, step_factor = _rel(up[0].value(q), value, value), up[0].factor
        elif coarser:
            a, b = _at(ok, coarser[0], default_factor), _at(ok, coarser[0], ref.factor)
            if a is not None and b is not None and a is not b:
                step, step_at = _rel(a.value(q), b.value(q), value), coarser[0]
    nxt = None
    if coarser:
        nxt = _at(ok, coarser[0], ref.factor)
        mesh = _rel(nxt.value(q), value, value) if nxt is not None else None
        if mesh is None and fine is not None and _at(ok, coarser[0], fine.factor):
            mesh = _rel(_at(ok, coarser[0], fine.factor).value(q), fine.value(q), value)
    else:
        mesh = None
    out = {"kind": "finest", "value": value, "run": ref, "mesh_change": mesh,
           "step_change": step, "step_at": step_at, "step_factor": step_factor,
           "next_length": coarser[0] if coarser else None}
    parts = [u for u in (mesh, step) if u is not None]
    out["uncertainty"] = max(parts) if parts else None
    if len(seq) >= 3 and math.isclose(seq[-1].h, ref.h):
        hs = [r.h for r in seq[-3:]]
        qs = [r.value(q) for r in seq[-3:]]
        limit, p = richardson(hs, qs)
        last = abs(qs[-1] - qs[-2])
        out.update(richardson_order=p, richardson_lengths=hs)
        if (p is not None and RICHARDSON_ORDERS[0] <= p <= RICHARDSON_ORDERS[1]
                and (step or 0.0) * abs(value) <= STEP_SHARE * last):
            out.update(kind="richardson", value=limit,
                       uncertainty=max(abs(limit - qs[-1]) / abs(limit), step or 0.0))
    return out


def _orders(ds: DynStudy, seq: list, ok: list) -> None:
    """Order of the errors in element length over the sweep at the scene's factor (the
    reference's own length left out when it is the reference), above 10x the step change
    of the reference and at most the pre-asymptotic ceiling; local orders of successive
    lengths."""
    for q in QUANTITIES:
        ref = ds.reference[q]
        runs = [r for r in seq if not (ref["kind"] == "finest" and math.isclose(r.h, ref[
            "run"].h))]
        hs = [r.h for r in runs]
        errs = [r.errors.get(q) for r in runs]
        floor = NOISE_MARGIN * (ref.get("step_change") or 0.0)
        fit = fit_order(hs, errs, floor, PRE_ASYMPTOTIC)
        fit["local"] = [(h1, h2, math.log(e1 / e2) / math.log(h1 / h2))
                        for (h1, e1), (h2, e2) in zip(zip(hs, errs), zip(hs[1:], errs[1:]))
                        if e1 and e2]
        fit["floor"] = floor
        fit["lengths"], fit["errors"] = hs, errs
        ds.orders[q] = fit


def _step(ds: DynStudy, ok: list) -> None:
    """At each length run at two or more factors: the change of each quantity from the
    smallest factor there, against the mesh error of that length (at the finest length:
    its change from the next-coarser one); the verdict; and the order in the time step
    where three or more factors were run (Richardson in the factor)."""
    rows = []
    for h in sorted({r.h for r in ok}, reverse=True):
        at = sorted((r for r in ok if math.isclose(r.h, h)), key=lambda r: -r.factor)
        if len(at) < 2:
            continue
        base = at[-1]
        for r in at[:-1]:
            row = {"h": h, "factor": r.factor, "base_factor": base.factor, "run": r,
                   "base": base, "time_ratio": r.wall_s / base.wall_s if base.wall_s else None}
            for q in QUANTITIES:
                ref = ds.reference[q]
                row[q] = _rel(r.value(q), base.value(q), ref["value"])
                mesh = (ref.get("mesh_change") if math.isclose(h, ds.ref_run.h)
                        else _rel(base.value(q), ref["value"], ref["value"]))
                row[f"{q}_share"] = row[q] / mesh if mesh and row[q] is not None else None
            rows.append(row)
        if len(at) >= 3:
            for q in QUANTITIES:
                fs = [r.factor for r in at]
                lim, p = richardson(fs, [r.value(q) for r in at])
                dflt = _at(at, h, ds.default_factor)
                ds.dt_order.setdefault(q, []).append({
                    "h": h, "order": p, "factors": fs,
                    "default_error": _rel(dflt.value(q), lim, ds.reference[q]["value"])
                    if dflt is not None and p is not None else None})
    ds.step = rows
    for q in QUANTITIES:
        shares = [(row[f"{q}_share"], row) for row in rows if row[f"{q}_share"] is not None
                  and row[q] > MATTERS_ABOVE]
        changes = [(row[q], row) for row in rows if row[q] is not None]
        worst = max(shares, key=lambda x: x[0]) if shares else None
        ds.step_verdict[q] = {
            "matters": bool(worst and worst[0] > MATTERS),
            "worst_share": worst, "largest": max(changes, key=lambda x: x[0]) if changes
            else None}


def _scaling(ds: DynStudy, seq: list, ok: list) -> None:
    """Wall time ~ h^a at the scene's factor (all lengths, three finest) and the measured
    ns per element-step."""
    rs = [r for r in seq if r.times and r.elements and r.steps]
    out = {}
    if len(rs) >= 2:
        h = np.array([r.h for r in rs])
        t = np.array([r.wall_s for r in rs])
        out["exponent_all"] = float(np.polyfit(np.log(h), np.log(t), 1)[0])
        k = min(3, len(rs))
        out["exponent_fine"] = float(np.polyfit(np.log(h[-k:]), np.log(t[-k:]), 1)[0])
    per = [1e9 * r.wall_s / (r.elements * r.steps) for r in ok if r.elements and r.steps]
    if per:
        out["ns_per_element_step"] = float(np.median(per))
    ds.scaling = out


def recommendations(ds: DynStudy) -> list[dict]:
    """For each accuracy of :data:`~verification.studies.cost.analysis.TARGETS` and each quantity
    (and 'both'): the cheapest converged run within it (the reference run itself left out
    when it is the reference), or why none: 'uncertain' (the accuracy is below the
    reference's uncertainty) or 'not reached'."""
    ok = _ok(ds)
    out = []
    for tgt in TARGETS:
        row = {"target": tgt}
        for key in (*QUANTITIES, "both"):
            qs = QUANTITIES if key == "both" else (key,)
            unc = [ds.reference[q].get("uncertainty") for q in qs]
            if any(u is None or u > tgt for u in unc):
                row[key] = ("uncertain", max((u for u in unc if u is not None), default=None))
                continue
            cands = [r for r in ok if all(r.errors.get(q) is not None and r.errors[q] <= tgt
                                          for q in qs)
                     and not any(ds.reference[q]["kind"] == "finest" and r is ds.ref_run
                                 for q in qs)]
            best = min(cands, key=lambda r: r.wall_s) if cands else None
            row[key] = ("run", best) if best is not None else ("not reached", None)
        out.append(row)
    return out

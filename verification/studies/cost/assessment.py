"""The wording of the order assessment of the cost study: one phrase per fitted order,
saying that it is the expected one or why it departs, with the scene's numbers."""

from __future__ import annotations

from .fits import NOISE_MARGIN, worst_mesh

#: expected order of the VFIFE static solution in element length (see the report text)
EXPECTED_ORDER = 2.0
#: |fitted order - expected| beyond which the report explains the departure
ORDER_BAND = 0.3


def order_assessment(q: str, fit: dict, context: dict | None = None) -> str:
    """One phrase on a fitted order: expected, or why not. ``context``: numbers of the
    scene quoted in the explanation (theta0, kappa0, coef from
    :func:`verification.studies.cost.touchdown.liftoff_interpolation`, the seabed ``stiffness``
    [N/m2], ``depth`` [m], the number of crests and sags ``n_crest_height``,
    ``n_sag_height``, ``touchdown_worst_mesh``: :func:`verification.studies.cost.fits.worst_mesh`
    of the touchdown tension)."""
    c = context or {}
    p, n = fit.get("order"), len(fit.get("points", []))
    if p is None and fit.get("below_noise") is not None:
        return (f"converged beyond measurement: every element length in the asymptotic "
                f"range errs by at most {fit['below_noise']:.1e}, below {NOISE_MARGIN:g}x "
                f"the noise (relaxation, reference) ({fit['noise_margin']:.1e}); nothing to "
                "fit")
    m = fit.get("n_inside", 0)
    if p is None and m < 2:
        return (f"not fitted: only {m} element length(s) lie within the asymptotic range "
                "(see the local orders)")
    if p is None:
        return (f"not fitted: {n} of the {m} element lengths in the asymptotic range err by "
                f"more than {NOISE_MARGIN:g}x the noise (relaxation, reference); the others "
                "are at it (see the local orders)")
    r2 = fit.get("r2") or 0.0
    on_order = abs(p - EXPECTED_ORDER) <= ORDER_BAND
    pts = set(fit.get("points", []))
    inner = [lp for a, b, lp in fit.get("local", []) if a in pts and b in pts]
    scatter = [lp for lp in inner if abs(lp - EXPECTED_ORDER) > 2.0 * ORDER_BAND]
    why = _why(q, c, fit) + _sign_changes(fit)
    if on_order and n >= 3 and r2 >= 0.9 and not scatter:
        return f"order {EXPECTED_ORDER:g}, as expected"
    if on_order and n >= 3:
        what = []
        if scatter:
            what.append(f"the local orders in the fit scatter ({min(inner):.2f} to "
                        f"{max(inner):.2f})")
        if r2 < 0.9:
            what.append(f"the errors scatter about the fitted line (R^2 {r2:.2f})")
        return (f"order {EXPECTED_ORDER:g} on average, but {' and '.join(what)}"
                + (f": {why}" if why else ""))
    if on_order:
        return (f"order {EXPECTED_ORDER:g}, as expected, but from two points only (no third "
                "to check the slope)")
    few = ", two points only" if n < 3 else ""
    head = f"differs (order {p:.2f}, R^2 {r2:.2f}{few})"
    return f"{head}: {why}" if why else head


def _why(q: str, c: dict, fit: dict) -> str:
    """Why the errors of ``q`` need not fall on one h^2 line, with the scene's numbers
    (``c``: see :func:`order_assessment`)."""
    kink = ""
    if c.get("theta0") is not None and c.get("stiffness"):
        kink = (f"the seabed reaction is lumped at the nodes (trapezoid rule): across the "
                f"element holding the lift-off, where k max(-y, 0) has its kink, the lumped "
                f"reaction exceeds the distributed one by k theta0 h^2 xi (1 - xi) / 2, up to "
                f"k theta0 h^2 / 8 = {c['stiffness'] * c['theta0'] / 8:.3g} h^2 N "
                f"(theta0 = {c['theta0']:.3g} rad at the lift-off, xi the lift-off's place "
                "in its element): O(h^2), but with a constant that changes from mesh to mesh")
    if q == "tdp_x" and c.get("coef") is not None:
        a, d = c["coef"], c.get("depth", 1.0)
        ratio = [e / (a * h * h / d) for h, e in zip(fit.get("points", []),
                                                      fit.get("errors", [])) if a > 0]
        env = (f"; the measured errors are {', '.join(f'{r:.2f}' for r in ratio)} x that "
               f"bound at {', '.join(f'{h:g}' for h in fit['points'])} m" if ratio else "")
        return (f"the lift-off is read off the nodal polyline by linear interpolation of the "
                f"heights; the reference crosses y = 0 at theta0 = {c['theta0']:.3g} rad with "
                f"curvature {c['kappa0']:.2g} 1/m, so the interpolation alone errs by "
                f"h^2 kappa0 xi (1 - xi) / (2 theta0), up to {a:.3g} h^2 m ({a / d:.2g} h^2 "
                f"of the depth, {a * 4.0 / d:.2g} at 2 m, {a / d:.2g} at 1 m), with xi the "
                "crossing's place between its two nodes, different on every mesh: O(h^2) "
                f"in envelope, erratic from one mesh to the next{env}")
    if q in ("tdp_tension", "hang_off_tension") and kink:
        return kink + ("; the touchdown tension is moreover taken at the VFIFE lift-off (see "
                       "touchdown position)" if q == "tdp_tension" else "")
    if q in ("crest_height", "sag_height"):
        kind = "crest" if q == "crest_height" else "sag bend"
        if c.get(f"n_{q}", 2) > 1:
            why = (f"the worst of several {kind}s: each converges at order 2 with its own "
                   "constant (whose sign can change), and the worst one can switch between "
                   "meshes")
        else:
            why = (f"a single {kind}, whose error is small (at most "
                   f"{max(fit.get('errors') or [0.0]):.1e} of the depth in the fit)")
    else:
        why = {"max_moment": "the peak moment is a maximum over the line: where two peaks "
                             "(sag bend, hog bend, touchdown region) are nearly equal, the "
                             "peak taken can change between meshes and the error jumps "
                             "between their error curves",
               "curve_distance": "a maximum over the line, whose place can move between "
                                 "meshes (touchdown region, sag or hog bend)"}.get(q, kink)
    return why + _touchdown_outlier(q, c, fit)


def _touchdown_outlier(q: str, c: dict, fit: dict) -> str:
    h = worst_mesh(fit)
    if q in ("tdp_tension", "tdp_x") or h is None or h != c.get("touchdown_worst_mesh"):
        return ""
    return (f"; its largest error relative to h^2 is on the {h:g} m mesh, as the touchdown "
            "tension's: the touchdown's mesh-dependent error (see touchdown tension) "
            "carries into it")


def _sign_changes(fit: dict) -> str:
    """Where the signed error of the fitted lengths changes sign (its |value| dips near a
    zero crossing, and the local orders there mean nothing)."""
    pairs = list(zip(fit.get("points", []), fit.get("signed", [])))
    flips = [(a, b) for (a, sa), (b, sb) in zip(pairs, pairs[1:])
             if sa is not None and sb is not None and sa * sb < 0]
    if not flips:
        return ""
    where = ", ".join(f"{a:g}-{b:g} m" for a, b in flips)
    return (f"; the error changes sign ({where}; signed errors "
            f"{', '.join(f'{e:+.1e}' for _, e in pairs)} at "
            f"{', '.join(f'{h:g}' for h, _ in pairs)} m), so its magnitude dips near each "
            "zero crossing")

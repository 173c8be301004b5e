"""Root searches of the outer problem (analytic/forms.py), the validity of the
boundary-layer expansion, and the outcomes a form can end in.

Every root is bracketed before Brent's method runs (:func:`root`): the bracket widens
geometrically from an estimate until the function changes sign, within bounds the physics
sets (a free-hanging line's H below EA dx / L: its span is the projection of the line,
int cos(theta) ds > 0, plus the stretch H L / EA), and a bracket without a sign change,
or a closed form that is not finite inside it, ends in a stated reason (RootNotFound,
NoEquilibrium or Unsupported), never in scipy's ValueError.

Validity of the expansion (:func:`check_expansion`). The touchdown forms solve an outer
problem that carries the layers' terms (eps = lambda / L, delta = w lambda / H, lambda =
sqrt(EI / ((1 + H/EA) H)), L the suspended length). The neglected terms are O(eps^2) and
O(delta^2) relative; on a light line eps grows first: on a 1200 m line in the hang-off angle
form (EI 1e7 N m2, 350 m, 30 deg) the composite's hang-off tension was 1.6 % from the BVP at
eps = 0.10, 9 % at 0.195 and 19 % at 0.245 (~2.5 eps^2), and below about w = 0.08 N/m the
layered outer problem has no root at all (the BVP's equilibrium of a line of 1e-3 N/m is
in compression, held up by bending). delta (the catenary's angle one layer length above
the touchdown) matters later: Kang's J-lay peak moment was 0.15 % from the BVP at delta =
0.21, 5 % at 0.37 and 38 % at 0.68 (eps 0.03 .. 0.09). So a touchdown form is refused where
eps exceeds :data:`EPS_LIMIT` (the layers then cover a fifth of the line) or delta exceeds
:data:`DELTA_LIMIT` (the layer's angle reaches 0.5 rad, where its linearisation fails):
before the layered problem is solved when the catenary alone is beyond them, and the
layered root is only searched where both stay within them. A free-hanging line is held to
the same limits at its least tension (analytic/forms.py, ``_free``).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from .layers import layer_length


class NoEquilibrium(Exception):
    """No static equilibrium of the form exists (the message says why)."""


class Unsupported(Exception):
    """The scene is outside what the analytic method represents (the message says why);
    ``key``: the scene key it concerns (``ends`` unless given)."""

    def __init__(self, message: str, key: str = "ends"):
        super().__init__(message)
        self.key = key


class RootNotFound(Exception):
    """A root search of the outer problem found no solution in its bracket, or the closed
    forms were not finite inside it (the message says which): not evidence that no
    equilibrium exists (that is :class:`NoEquilibrium`)."""


#: eps and delta of the expansion above which a touchdown form is refused (module docstring)
EPS_LIMIT = 0.2
DELTA_LIMIT = 0.5


class _NotFinite(Exception):
    pass


def _value(f, x: float) -> float:
    """f(x) as a float; nan where the closed forms break down (an exception of the
    arithmetic or a math domain error, a nested search without a root, a value that is not
    finite)."""
    try:
        v = float(f(x))
    except (ArithmeticError, ValueError, RootNotFound, _NotFinite):
        return math.nan
    return v if math.isfinite(v) else math.nan


def brent(f, lo: float, hi: float, what: str, xtol: float) -> float:
    """brentq on a bracket with a sign change; a value that is not finite inside it (or no
    convergence) raises :class:`RootNotFound` with the place."""
    def g(x):
        v = _value(f, x)
        if math.isnan(v):
            raise _NotFinite(x)
        return v
    try:
        return brentq(g, lo, hi, xtol=xtol, rtol=4.0 * np.finfo(float).eps, maxiter=500)
    except _NotFinite as exc:
        raise RootNotFound(f"{what}: the closed forms are not finite at {exc.args[0]:.6g} "
                           f"inside the bracket [{lo:.6g}, {hi:.6g}]") from None
    except RuntimeError as exc:
        raise RootNotFound(f"{what}: {exc}") from None


def _toward_edge(f, good: float, bad: float, n: int = 80):
    """Finite points (x, f(x)) from ``good`` (f finite) towards ``bad`` (f nan), bisecting
    the edge of the domain where the closed forms hold."""
    for _ in range(n):
        mid = 0.5 * (good + bad)
        if mid in (good, bad):
            return
        v = _value(f, mid)
        if math.isnan(v):
            bad = mid
        else:
            good = mid
            yield mid, v


def _outward(f, x: float, factor: float, bound: float, tries: int):
    """Finite points (x, f(x)) from ``x`` outwards, x * factor each (factor < 1: towards 0)
    up to ``bound``; where f is not finite, the edge of its domain is approached instead."""
    for _ in range(tries):
        new = min(x * factor, bound) if factor > 1.0 else max(x * factor, bound)
        if new == x:
            return
        v = _value(f, new)
        if math.isnan(v):
            yield from _toward_edge(f, x, new)
            return
        x = new
        yield new, v


def root(f, lo: float, hi: float, what: str, *, lo_min: float = 0.0,
          hi_max: float = math.inf, factor: float = 2.0, tries: int = 200) -> float:
    """A root of f for a positive unknown, from the bracket [lo, hi] (0 < lo <= hi) widened
    geometrically (lo / factor down to ``lo_min``, hi * factor up to ``hi_max``) until f
    changes sign. Where f is not finite (nan: the closed forms or a nested search broke
    down, or the unknown left the domain where the model holds) the search bisects towards
    the edge of the finite domain instead of crossing it. No sign change within the bounds,
    or a value that is not finite inside the final bracket, raises :class:`RootNotFound`
    naming ``what``."""
    hi = min(hi, hi_max)
    lo = max(min(lo, hi), lo_min)
    flo, fhi = _value(f, lo), _value(f, hi)
    if math.isnan(flo) and math.isnan(fhi):
        raise RootNotFound(f"{what}: the closed forms are not finite at the start of the "
                           f"search ({lo:.6g} and {hi:.6g})")
    if math.isnan(flo):
        sides = {"lo": _toward_edge(f, hi, lo), "hi": _outward(f, hi, factor, hi_max, tries)}
        lo, flo = hi, fhi
    elif math.isnan(fhi):
        sides = {"lo": _outward(f, lo, 1.0 / factor, lo_min, tries),
                 "hi": _toward_edge(f, lo, hi)}
        hi, fhi = lo, flo
    else:
        sides = {"lo": _outward(f, lo, 1.0 / factor, lo_min, tries),
                 "hi": _outward(f, hi, factor, hi_max, tries)}
    xtol = 1e-300 + 4.0 * np.finfo(float).eps * lo
    if flo == 0.0 or fhi == 0.0:
        return lo if flo == 0.0 else hi
    if (flo < 0.0) != (fhi < 0.0):
        return brent(f, lo, hi, what, xtol)
    while sides:
        for side in list(sides):
            try:
                x, v = next(sides[side])
            except StopIteration:
                del sides[side]
                continue
            if v == 0.0:
                return x
            inner, finner = (lo, flo) if side == "lo" else (hi, fhi)
            if (v < 0.0) != (finner < 0.0):
                a, b = (x, inner) if side == "lo" else (inner, x)
                return brent(f, a, b, what, 1e-300 + 4.0 * np.finfo(float).eps * a)
            if side == "lo":
                lo, flo = x, v
            else:
                hi, fhi = x, v
    raise RootNotFound(f"no {what} in [{lo:.6g}, {hi:.6g}] (no change of sign)")


def expansion(line, H: float, suspended: float) -> tuple[float, float]:
    """eps = lambda / L and delta = w lambda / H of a touchdown solution with horizontal
    force H [N] and suspended length L [m] (what the result reports); ``line``: the
    analytic/forms.py Line (w, EI, EA)."""
    lam = layer_length(line.EI, H, line.EA)
    return (lam / suspended if suspended > 0.0 else math.inf), line.w * lam / H


def within_expansion(line, H: float, suspended: float) -> bool:
    """eps and delta (:func:`expansion`) within :data:`EPS_LIMIT` and :data:`DELTA_LIMIT`."""
    eps, delta = expansion(line, H, suspended)
    return eps <= EPS_LIMIT and delta <= DELTA_LIMIT


def check_expansion(line, H: float, suspended: float) -> None:
    """Refuse (:class:`Unsupported`) a line whose catenary solution (H [N], suspended length
    [m]) has eps or delta beyond :data:`EPS_LIMIT`, :data:`DELTA_LIMIT` (module
    docstring)."""
    if within_expansion(line, H, suspended):
        return
    eps, delta = expansion(line, H, suspended)
    raise Unsupported(_outside(line, eps, delta, H, suspended), key="segments[0]")


def _outside(line, eps: float, delta: float, H: float, suspended: float) -> str:
    return (f"the boundary-layer expansion does not hold for this line: its catenary "
            f"(H = {H:.4g} N, suspended length {suspended:.4g} m) has eps = "
            f"sqrt(EI/(H L^2)) = {eps:.3g} and delta = w lambda/H = {delta:.3g} (the method "
            f"needs eps <= {EPS_LIMIT:g} and delta <= {DELTA_LIMIT:g}): bending (EI = "
            f"{line.EI:.4g} N m2), not the weight ({line.w:.4g} N/m) and tension, shapes "
            "the line; use --method bvp "
            "(or [analytic] model = \"catenary\", which leaves bending out)")


def layered(line, H0: float, suspended0: float, search, what: str) -> float:
    """The root of the layered outer problem by ``search()`` (a :func:`root` call whose
    function gives nan where eps or delta exceed their limits), started from the
    catenary's H0 [N] and suspended length [m]: refused before the search when that
    catenary is already beyond the limit, and when the search finds no root."""
    check_expansion(line, H0, suspended0)
    try:
        return search()
    except RootNotFound as exc:
        eps, delta = expansion(line, H0, suspended0)
        raise Unsupported(
            f"the boundary-layer expansion has no solution for this line ({exc}) with eps <= "
            f"{EPS_LIMIT:g} and delta <= {DELTA_LIMIT:g} (its catenary: H = {H0:.4g} N, eps = "
            f"{eps:.3g}, delta = {delta:.3g}): bending shapes the line too much for the "
            "catenary with boundary layers; use --method bvp", key="segments[0]") from None


def near(f, H0: float, what: str):
    """The search of :func:`layered` for an unknown near the catenary's H0: from [H0/2,
    2 H0], within a factor 1000 of it (the layers move H by O(eps) relative)."""
    return lambda: root(f, 0.5 * H0, 2.0 * H0, what, lo_min=1e-3 * H0, hi_max=1e3 * H0)


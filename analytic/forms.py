"""The outer problem of each end form: the catenary that places the line, with the
touchdown layer's vertex shift (analytic/layers.py) in its conditions.

The layer puts the outer catenary's vertex s_v along the line beyond the lift-off point
and y_v above the seabed; between them the line is straight to O(delta^2), so the
horizontal distances are the stretched lengths c s. Each form is one equation in the
horizontal force H, solved by bracketing (scipy ``brentq``):

- ``tdp_tension`` (Wang): H = T_TDP; the whole line is suspended, the catenary's length
  is L - s_v.
- ``hang_off_angle``: tan(alpha) = w L_c / H and y_v + h(H, L_c) = Y.
- ``top_tension`` (J-lay): T_top^2 = H^2 + (w L_c)^2 and y_v + h(H, L_c) = Y. With
  M = 0 at a pinned top, T - w y + M^2 / (2 EI) is constant along an inextensible beam
  (dT/ds = w sin(theta) - F theta', EI theta'' = F), so H = T_top - w Y holds exactly for
  the beam, and a top tension T_top <= w Y (T_top + T_top^2/(2 EA) <= w Y extensible) has no
  equilibrium that reaches the seabed.
- ``fixed`` with the anchor on the seabed: the laid line (tension H, frictionless) plus
  the catenary span reach the hang-off: x_a + c (L - L_c) + X(H, L_c) = x_h with
  y_v + h(H, L_c) = y_h. When no line would be left on the seabed the line is lifted off
  the anchor: a free-hanging catenary.
- ``fixed`` free-hanging (no touchdown): the two-point catenary, H and the anchor's
  vertical force V_a from the two closure equations (nested ``brentq``: the vertical
  closure is monotonic in V_a at fixed H, the horizontal one in H).

h(H, L) and X(H, L) are the extensible catenary's rise and span from its vertex.

Roots, the expansion's validity and the outcomes (analytic/search.py): every root is
bracketed before Brent's method runs, and a touchdown form whose eps or delta exceeds
the limits of the expansion is refused.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .catenary import Catenary, bending_correction, vertex_length_for_height
from .layers import TouchdownLayer, layer_length, touchdown_layer
from .search import (
    DELTA_LIMIT,
    EPS_LIMIT,
    NoEquilibrium,
    RootNotFound,
    Unsupported,
    brent,
    check_expansion,
    layered,
    near,
    root,
    within_expansion,
)


@dataclass(frozen=True)
class Line:
    """The single section of the line: w [N/m], EI [N m2], EA [N] (inf: inextensible),
    total unstretched length [m], seabed stiffness k [N/m2] (None: rigid)."""

    w: float
    EI: float
    EA: float
    length: float
    k: float | None


@dataclass(frozen=True)
class Outer:
    """The solved outer problem.

    kind : 'touchdown' or 'free'. cat : the catenary (touchdown: from its vertex;
    free: from the anchor). layer : the touchdown layer (None when free, or for the
    catenary model, whose vertex is the touchdown). s_L, x_L : arc length and x of the
    lift-off point (touchdown) [m]; origin : (x, y) of the anchor (free) [m]; suspended :
    unstretched length from the lift-off point (or the anchor) to the hang-off [m]."""

    kind: str
    H: float
    cat: Catenary
    layer: TouchdownLayer | None
    s_L: float
    x_L: float
    suspended: float
    origin: tuple = (0.0, 0.0)

    @property
    def s_v(self) -> float:
        return _vertex(self.layer)[0]

    @property
    def y_v(self) -> float:
        return _vertex(self.layer)[1]


def _layer(line: Line, H: float, with_layer: bool, end=None):
    if not with_layer:
        return None
    return touchdown_layer(H, line.w, line.EI, line.EA, line.k, end)


def _vertex(layer) -> tuple[float, float]:
    return (layer.s_v, layer.y_v) if layer is not None else (0.0, 0.0)


def _top(line: Line, H: float, Lc: float, layer) -> tuple[float, float, float]:
    """Span, rise and angle of the outer solution from its vertex over unstretched
    ``Lc`` [m]: the catenary, plus its O(eps^2) bending correction when a layer is used."""
    cat = Catenary(H, 0.0, line.w, line.EA)
    x, y, th = float(cat.x(Lc)), float(cat.y(Lc)), float(cat.theta(Lc))
    if layer is not None:
        dx, dy, dth, _ = bending_correction(cat, line.EI, Lc)
        x, y, th = x + float(dx), y + float(dy), th + float(dth)
    return x, y, th


def _length_for_height(line: Line, H: float, height: float, layer) -> float:
    """The outer length from the vertex rising by ``height`` (fixed point on the bending
    correction, which varies slowly with the length)."""
    Lc = vertex_length_for_height(H, line.w, line.EA, max(height, 0.0))
    if layer is None:
        return Lc
    for _ in range(4):
        dy = float(bending_correction(Catenary(H, 0.0, line.w, line.EA), line.EI, Lc)[1])
        Lc = vertex_length_for_height(H, line.w, line.EA, max(height - dy, 0.0))
    return Lc


def tdp_tension(line: Line, T_tdp: float, with_layer: bool) -> Outer:
    H = T_tdp
    if with_layer:
        check_expansion(line, H, line.length)
    layer = _layer(line, H, with_layer)
    s_v, _ = _vertex(layer)
    if line.length <= s_v:
        raise NoEquilibrium(f"the line ({line.length:g} m) is shorter than the touchdown "
                            f"layer's vertex shift {s_v:.3g} m")
    cat = Catenary(H, 0.0, line.w, line.EA)
    return Outer("touchdown", H, cat, layer, 0.0, 0.0, line.length)


def hang_off_angle(line: Line, height: float, alpha: float, with_layer: bool,
                   top_layer: bool) -> Outer:
    """``top_layer``: the composite's moment-free layer at the hang-off turns the line by
    -kappa_top lambda_top there, so the outer solution ends at alpha + kappa_top lambda_top
    for the composite to meet the given angle (analytic/layers.py)."""
    w, EA, t = line.w, line.EA, math.tan(alpha)
    what = (f"horizontal tension that meets the hang-off height {height:g} m at "
            f"{math.degrees(alpha):g} deg")

    def target(H, L):
        if not top_layer:
            return alpha
        cat = Catenary(H, 0.0, w, EA)
        T = float(cat.tension(L))
        return alpha + float(cat.curvature(L)) * layer_length(line.EI, T, EA)

    def Lc(H, layer):
        # the outer angle at the top (with its bending correction) is alpha: below it at the
        # vertex (0 against alpha + the top layer's turn), above it far up (90 deg)
        L0 = H * t / w
        if layer is None:
            return L0
        return root(lambda L: _top(line, H, L, layer)[2] - target(H, L), 0.5 * L0,
                     2.0 * L0, f"outer length that ends at the hang-off angle (H = {H:.6g} N)")

    def f(H, layered=True):
        layer = _layer(line, H, with_layer and layered)
        L = Lc(H, layer)
        if layer is not None and not within_expansion(line, H, layer.s_v + L):
            return math.nan
        return _vertex(layer)[1] + _top(line, H, L, layer)[1] - height

    # the inextensible catenary: H = w Y / (sec(alpha) - 1), sec - 1 = 2 sin^2(a/2) / cos(a)
    flat = 2.0 * math.sin(0.5 * alpha) ** 2 / math.cos(alpha)
    H0 = w * height / flat if flat > 0.0 else math.inf
    if not (math.isfinite(H0) and H0 > 0.0):
        raise NoEquilibrium(
            f"no equilibrium: a hang-off angle of {math.degrees(alpha):.6g} deg from the "
            f"horizontal at {height:g} m needs a horizontal tension w Y / (sec(alpha) - 1) = "
            f"{H0:.6g} N (w = {w:.6g} N/m), beyond the floating-point range")
    try:
        H0 = root(lambda H: f(H, False), 0.5 * H0, 2.0 * H0, what)
    except RootNotFound as exc:
        raise RootNotFound(f"the catenary: {exc}") from None
    H = layered(line, H0, Lc(H0, None), near(f, H0, what), what) if with_layer else H0
    layer = _layer(line, H, with_layer)
    s_v, _ = _vertex(layer)
    return Outer("touchdown", H, Catenary(H, 0.0, w, EA), layer, 0.0, 0.0,
                 s_v + Lc(H, layer))


def top_tension(line: Line, height: float, T_top: float, with_layer: bool) -> Outer:
    w, EA = line.w, line.EA
    reach = T_top / w + T_top * T_top / (2.0 * w * EA)
    if height >= reach:
        raise NoEquilibrium(
            f"no equilibrium: a top tension of {T_top:.6g} N holds at most "
            f"{reach:.6g} m of this line above a touchdown (T_top/w"
            + (" + T_top^2/(2 w EA)" if math.isfinite(EA) else "")
            + f", w = {w:.6g} N/m); the hang-off height is {height:g} m: raise the top tension "
            f"above {w * height:.6g} N")
    what = f"horizontal tension for the top tension {T_top:g} N at {height:g} m"

    # the unknown is u = T_top - H (> 0): the suspended length sqrt(T_top^2 - H^2) / w =
    # sqrt(u (2 T_top - u)) / w has no cancellation when u << T_top (a light line: u ~ w Y)
    def Lc_u(u):
        return math.sqrt(max(u * (2.0 * T_top - u), 0.0)) / w

    def g(u, layer=True):
        H = T_top - u
        lay = _layer(line, H, with_layer and layer)
        L = Lc_u(u)
        if lay is not None and not within_expansion(line, H, lay.s_v + L):
            return math.nan
        return _vertex(lay)[1] + _top(line, H, L, lay)[1] - height

    # the catenary alone, in closed form: its rise from the vertex is (T - H)/w + (T^2 -
    # H^2)/(2 w EA), so w Y = u (1 + (2 T_top - u) / (2 EA)), a quadratic in u whose small
    # root is written without cancellation (real, as height < reach)
    a = 1.0 + T_top / EA
    u = 2.0 * w * height / (a + math.sqrt(max(a * a - 2.0 * w * height / EA, 0.0)))
    top = T_top * (1.0 - np.finfo(float).eps)
    u = min(u, top)
    H0, u0 = T_top - u, u
    if with_layer:
        u = layered(line, H0, Lc_u(u0), lambda: root(
            g, 0.5 * u0, min(2.0 * u0, top), what, lo_min=1e-3 * u0, hi_max=top), what)
    H = T_top - u
    layer = _layer(line, H, with_layer)
    s_v, _ = _vertex(layer)
    if s_v + Lc_u(u) > line.length:
        raise NoEquilibrium(
            f"no equilibrium: the suspended length {s_v + Lc_u(u):.6g} m exceeds the pipe "
            f"length {line.length:g} m (segments[0].length): the pipe cannot reach the "
            "seabed at this top tension")
    return Outer("touchdown", H, Catenary(H, 0.0, w, EA), layer, 0.0, 0.0, s_v + Lc_u(u))


def fixed(line: Line, anchor: tuple, hang_off: tuple, has_seabed: bool,
          with_layer: bool) -> Outer:
    """Fixed ends: a touchdown when the anchor is on the seabed (y = 0) and line is left
    on it, else the free-hanging two-point catenary."""
    on_seabed = has_seabed and anchor[1] == 0.0
    if on_seabed:
        try:
            return _fixed_touchdown(line, anchor, hang_off, with_layer)
        except _Lifted:
            pass
    return _free(line, anchor, hang_off, has_seabed, on_seabed, with_layer)


class _Lifted(Exception):
    pass


def _fixed_touchdown(line: Line, anchor, hang_off, with_layer: bool) -> Outer:
    w, EA, L = line.w, line.EA, line.length
    dx, Y = hang_off[0] - anchor[0], hang_off[1] - anchor[1]

    def parts(H, layer=True):
        lay = _layer(line, H, with_layer and layer)
        s_v, y_v = _vertex(lay)
        return lay, s_v, _length_for_height(line, H, Y - y_v, lay)

    def f(H, layer=True):
        lay, s_v, Lc = parts(H, layer)
        if lay is not None and not within_expansion(line, H, s_v + Lc):
            return math.nan
        return (1.0 + H / EA) * (L - Lc) + _top(line, H, Lc, lay)[0] - dx

    if L - Y <= 0.0 or f(1e-9 * w * L, False) > 0.0:
        if L - Y > 0.0:
            raise NoEquilibrium(
                f"no equilibrium: the line ({L:g} m) is longer than the hang-off height plus "
                f"the horizontal distance ({Y:g} + {dx:g} m): it would pile up on the seabed")
        raise _Lifted
    # the largest H with line left on the seabed: L_c(H) = L (no layer). L_c rises with H
    # from Y (hanging straight up) to infinity (inextensible) or to sqrt(2 Y EA / w) (the
    # stretch lets a flat catenary rise with less line): a line longer than that has none
    try:
        H_top = root(lambda H: vertex_length_for_height(H, w, EA, Y) - L, 1e-9 * w * L,
                      1e3 * w * L, "largest horizontal tension with line on the seabed",
                      lo_min=1e-300 * w * L)
    except RootNotFound:
        raise _Lifted from None
    if f(H_top, False) < 0.0:
        raise _Lifted
    H0 = root(lambda H: f(H, False), 1e-9 * w * L, H_top, "horizontal tension that reaches "
               "the hang-off position (catenary)", lo_min=1e-9 * w * L, hi_max=H_top)
    what = "horizontal tension that reaches the hang-off position"
    H = layered(line, H0, parts(H0, False)[2], near(f, H0, what), what) if with_layer else H0
    lay, s_v, Lc = parts(H)
    laid = L - Lc - s_v
    if laid < 0.0:
        raise _Lifted
    c = 1.0 + H / EA
    return Outer("touchdown", H, Catenary(H, 0.0, w, EA), lay, laid, anchor[0] + c * laid,
                 Lc + s_v, origin=tuple(anchor))


def _free(line: Line, anchor, hang_off, has_seabed: bool, on_seabed: bool,
          with_layer: bool = True) -> Outer:
    """The two-point catenary. At fixed H the end's height rises monotonically with the
    anchor's vertical force V_a, from -inf to inf (extensible; -L to L inextensible, and
    |dy| < L there): V_a(H) by a widening bracket. Along V_a(H) the end's x rises with H
    from 0 (the line hanging straight); it is the projection of the line, int cos(theta)
    ds > 0, plus the stretch H L / EA: at H = EA dx / L it is beyond dx, so a root lies
    below that bound (a taut line needs H >> w L: 5.7 kN, a tension of 114 kN, for w L =
    248 N on a 19.8 m line between ends 20.02 m apart); inextensible, x tends to
    sqrt(L^2 - dy^2) > dx.

    With layers (``with_layer``), the line must be held by its tension, not its bending:
    at the least tension T_min along the catenary (its vertex when that lies on the line,
    else an end), lambda = sqrt(EI / ((1 + T_min/EA) T_min)), eps = lambda / L within
    :data:`EPS_LIMIT` and delta = w lambda / T_min (the tension's change across that
    layer) within :data:`DELTA_LIMIT`, else refused: a slack line of little weight for
    its EI is a buckled beam, in compression in the BVP. Measured against the BVP
    (tests/test_analytic_edges.py), the end tensions of a converged free line are off by
    up to ~14 max(eps, delta)^2: the closure conditions leave out the end layers' O(eps^2
    L) shift of the outer catenary, a slack line's tension follows its slack, and at a
    low-tension end the tension changes across the layer."""
    w, EA, L = line.w, line.EA, line.length
    dx, dy = hang_off[0] - anchor[0], hang_off[1] - anchor[1]
    chord = math.hypot(dx, dy)
    if not math.isfinite(EA) and L <= chord:
        raise NoEquilibrium(f"the inextensible line ({L:g} m) cannot span the ends "
                            f"({chord:g} m apart)")

    def V_for(H):
        # vertical closure, monotonic increasing in V_a at fixed H
        g = lambda V: float(Catenary(H, V, w, EA).y(L)) - dy        # noqa: E731
        lo, hi = -w * L - 10 * H, 10 * H + w * L
        glo, ghi = g(lo), g(hi)
        width = hi - lo
        for _ in range(200):
            if glo <= 0.0 <= ghi:
                return brent(g, lo, hi, f"vertical force at the anchor (H = {H:.6g} N)",
                              xtol=1e-300 + 4.0 * np.finfo(float).eps * (H + w * L))
            if not (math.isfinite(glo) and math.isfinite(ghi)):
                break
            if glo > 0.0:
                lo, glo = lo - width, g(lo - width)
            if ghi < 0.0:
                hi, ghi = hi + width, g(hi + width)
            width *= 2.0
        raise RootNotFound(f"no vertical force at the anchor closes the height at "
                           f"H = {H:.6g} N")

    def f(H):
        return float(Catenary(H, V_for(H), w, EA).x(L)) - dx

    # start at the larger of the weight and the taut string's tension EA (chord/L - 1)
    # times the chord's cosine dx / chord
    start = max(w * L, EA * max(chord / L - 1.0, 0.0) * dx / chord
                if math.isfinite(EA) else 0.0)
    bound = 2.0 * EA * dx / L
    H = root(f, 1e-3 * start, start, "horizontal tension that spans the two end positions",
              lo_min=1e-300 * start, hi_max=bound, factor=4.0)
    Va = V_for(H)
    cat = Catenary(H, Va, w, EA)
    if with_layer:
        Vb = Va + w * L
        V_min = 0.0 if Va <= 0.0 <= Vb else min(abs(Va), abs(Vb))
        T_min = math.hypot(H, V_min)
        lam = layer_length(line.EI, T_min, EA)
        eps, delta = lam / L, w * lam / T_min
        if not (eps <= EPS_LIMIT and delta <= DELTA_LIMIT):
            raise Unsupported(
                f"the boundary-layer expansion does not hold for this line: its catenary "
                f"between the ends (least tension T = {T_min:.4g} N, length {L:g} m) has eps "
                f"= sqrt(EI/(T L^2)) = {eps:.3g} and delta = w lambda/T = {delta:.3g} (the "
                f"method needs eps <= {EPS_LIMIT:g} and delta <= {DELTA_LIMIT:g}): bending "
                f"(EI = {line.EI:.4g} N m2), not the tension, shapes the line; use --method "
                "bvp (or [analytic] model = \"catenary\", which leaves bending out)",
                key="segments[0]")
    if on_seabed and Va < 0.0:
        raise Unsupported("the line leaves the anchor downwards into the seabed and no "
                          "length is left to lie on it")
    # the lowest point: the vertex at sigma = -V_a / w, or the hang-off when beyond it
    low = anchor[1] + float(cat.y(L if -Va >= w * L else -Va / w)) if Va < 0.0 else 0.0
    if has_seabed and Va < 0.0 and low < -1e-9:
        raise Unsupported(
            f"the free-hanging catenary sags {-low:.3g} m "
            "below the seabed between the ends: a touchdown away from the anchor, which "
            "the analytic method does not represent")
    return Outer("free", H, cat, None, 0.0, anchor[0], L, origin=tuple(anchor))

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
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from scipy.optimize import brentq

from .catenary import Catenary, bending_correction, vertex_length_for_height
from .layers import TouchdownLayer, layer_length, touchdown_layer


class NoEquilibrium(Exception):
    """No static equilibrium of the form exists (the message says why)."""


class Unsupported(Exception):
    """The scene is outside what the analytic method represents (the message says why)."""


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


def _root(f, lo: float, hi: float, what: str) -> float:
    """brentq of f on [lo, hi], widening the bracket by factors of 2 (20 times)."""
    flo, fhi = f(lo), f(hi)
    for _ in range(20):
        if flo * fhi <= 0.0:
            return brentq(f, lo, hi, xtol=1e-12 * hi, rtol=1e-13, maxiter=200)
        lo, hi = lo / 2.0, hi * 2.0
        flo, fhi = f(lo), f(hi)
    raise NoEquilibrium(f"no horizontal tension satisfies {what}")


def tdp_tension(line: Line, T_tdp: float, with_layer: bool) -> Outer:
    H = T_tdp
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

    def target(H, L):
        if not top_layer:
            return alpha
        cat = Catenary(H, 0.0, w, EA)
        T = float(cat.tension(L))
        return alpha + float(cat.curvature(L)) * layer_length(line.EI, T, EA)

    def Lc(H, layer):
        # the outer angle at the top (with its bending correction) is alpha
        if layer is None:
            return H * t / w
        return brentq(lambda L: _top(line, H, L, layer)[2] - target(H, L), 0.5 * H * t / w,
                      2.0 * H * t / w, xtol=1e-12 * H * t / w)

    def f(H):
        layer = _layer(line, H, with_layer)
        return _vertex(layer)[1] + _top(line, H, Lc(H, layer), layer)[1] - height

    H0 = w * height / (1.0 / math.cos(alpha) - 1.0)
    H = _root(f, 0.5 * H0, 2.0 * H0, f"the hang-off height {height:g} m at "
              f"{math.degrees(alpha):g} deg")
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

    def Lc(H):
        return math.sqrt(max(T_top * T_top - H * H, 0.0)) / w

    def f(H, layer=True):
        lay = _layer(line, H, with_layer and layer)
        return _vertex(lay)[1] + _top(line, H, Lc(H), lay)[1] - height

    H0 = brentq(lambda H: f(H, False), 1e-9 * T_top, T_top, xtol=1e-12 * T_top)
    H = _root(f, 0.5 * H0, min(2.0 * H0, T_top * (1 - 1e-12)), f"the top tension "
              f"{T_top:g} N at {height:g} m") if with_layer else H0
    layer = _layer(line, H, with_layer)
    s_v, _ = _vertex(layer)
    if s_v + Lc(H) > line.length:
        raise NoEquilibrium(
            f"no equilibrium: the suspended length {s_v + Lc(H):.6g} m exceeds the pipe "
            f"length {line.length:g} m (segments[0].length): the pipe cannot reach the "
            "seabed at this top tension")
    return Outer("touchdown", H, Catenary(H, 0.0, w, EA), layer, 0.0, 0.0, s_v + Lc(H))


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
    return _free(line, anchor, hang_off, has_seabed, on_seabed)


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
        lay, _, Lc = parts(H, layer)
        return (1.0 + H / EA) * (L - Lc) + _top(line, H, Lc, lay)[0] - dx

    if L - Y <= 0.0 or f(1e-9 * w * L, False) > 0.0:
        if L - Y > 0.0:
            raise NoEquilibrium(
                f"no equilibrium: the line ({L:g} m) is longer than the hang-off height plus "
                f"the horizontal distance ({Y:g} + {dx:g} m): it would pile up on the seabed")
        raise _Lifted
    # the largest H with line left on the seabed: L_c(H) = L (no layer)
    H_top = brentq(lambda H: vertex_length_for_height(H, w, EA, Y) - L, 1e-9 * w * L,
                   1e3 * w * L) if vertex_length_for_height(1e3 * w * L, w, EA, Y) > L else None
    if H_top is None or f(H_top, False) < 0.0:
        raise _Lifted
    H0 = brentq(lambda H: f(H, False), 1e-9 * w * L, H_top, xtol=1e-12 * H_top)
    H = _root(f, 0.5 * H0, 2.0 * H0, "the hang-off position") if with_layer else H0
    lay, s_v, Lc = parts(H)
    laid = L - Lc - s_v
    if laid < 0.0:
        raise _Lifted
    c = 1.0 + H / EA
    return Outer("touchdown", H, Catenary(H, 0.0, w, EA), lay, laid, anchor[0] + c * laid,
                 Lc + s_v, origin=tuple(anchor))


def _free(line: Line, anchor, hang_off, has_seabed: bool, on_seabed: bool) -> Outer:
    w, EA, L = line.w, line.EA, line.length
    dx, dy = hang_off[0] - anchor[0], hang_off[1] - anchor[1]
    if not math.isfinite(EA) and L <= math.hypot(dx, dy):
        raise NoEquilibrium(f"the inextensible line ({L:g} m) cannot span the ends "
                            f"({math.hypot(dx, dy):g} m apart)")

    def V_for(H):
        # vertical closure, monotonic increasing in V_a at fixed H
        g = lambda V: float(Catenary(H, V, w, EA).y(L)) - dy        # noqa: E731
        lo, hi = -w * L - 10 * H, 10 * H + w * L
        return brentq(g, lo, hi, xtol=1e-12 * (H + w * L))

    def f(H):
        return float(Catenary(H, V_for(H), w, EA).x(L)) - dx

    H = _root(f, 1e-3 * w * L, w * L, "the two end positions")
    Va = V_for(H)
    cat = Catenary(H, Va, w, EA)
    if on_seabed and Va < 0.0:
        raise Unsupported("the line leaves the anchor downwards into the seabed and no "
                          "length is left to lie on it")
    if has_seabed and Va < 0.0 and anchor[1] + float(cat.y(-Va / w)) < -1e-9:
        raise Unsupported(
            f"the free-hanging catenary sags {-(anchor[1] + float(cat.y(-Va / w))):.3g} m "
            "below the seabed between the ends: a touchdown away from the anchor, which "
            "the analytic method does not represent")
    return Outer("free", H, cat, None, 0.0, anchor[0], L, origin=tuple(anchor))

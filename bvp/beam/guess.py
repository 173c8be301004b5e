"""Starting guesses of the beam solver: catenaries (EI = 0) for each end form.

Every guess returns the catenary's horizontal tension H [N], the vertical force V0 [N] at
its start and the suspended segment lengths Ls [m]; :func:`state_guess` samples the
scaled state at given arc lengths from it. The guesses only need to be close enough for
Newton's method. Between two pinned ends the catenary is elastic when the model is
(Irvine's, exact for EI = 0; :func:`bvp.beam.catenary.pinned` finds it from slack to taut), so
that a taut line, or one as long as its chord or shorter, has a starting tension that
carries its weight; the touchdown forms start from the inextensible catenary, and an
elastic seabed from the line lying on y = -w/k up to the touchdown, in any segment.
"""

from __future__ import annotations

import math
import threading

import numpy as np
from scipy.optimize import brentq, least_squares

from .catenary import catenary_state, end_offsets, end_offsets_rows, \
    horizontal_tensions, pinned


class BVPFailure(RuntimeError):
    """Raised internally when no starting guess or no solution can be found."""


class NoEquilibrium(BVPFailure):
    """A starting-guess search that shows no equilibrium of the form exists (the message
    starts with 'no equilibrium:')."""


def state_guess(s, seg, w, Ls, EI, H, V0, ox, oy, scale, grounded: float = 0.0,
                sink: float = 0.0, EA=None, w_bend=None) -> np.ndarray:
    """Scaled state (6, m) at the unstretched arc lengths ``s`` [m] from the bottom end
    (``seg``: the segment index at each, for its EI [N m2] and weight w [N/m]): the
    catenary of suspended segment lengths ``Ls`` [m] through (ox, oy) with forces (H, V0)
    [N] there. With ``grounded`` > 0 [m] the line first lies straight at y = oy - sink [m]
    from x = ox - grounded, tension H, for that length before the catenary. ``EA`` (per
    segment [N], None: inextensible) makes the catenary elastic. ``w_bend`` (per segment
    [N/m]): the weights of the bending terms M and F where they differ from ``w`` (a point
    attachment's short heavy segment: bvp/beam/points.py)."""
    sc = np.asarray(s, float) - grounded
    on = sc < 0.0
    st = catenary_state(np.maximum(sc, 0.0), w, Ls, H, V0, ox, oy, EA)
    EIk = np.asarray(EI, float)[seg]
    wk = np.asarray(w if w_bend is None else w_bend, float)[seg]
    M = EIk * (st["curvature"] if w_bend is None else wk * H / st["tension"] ** 2)
    # d(kappa)/ds for kappa = w H / (H^2 + V^2), dV/ds = w
    F = EIk * (-2.0 * wk ** 2 * H * st["V"] / (H * H + st["V"] ** 2) ** 2)
    rows = [np.where(on, ox + sc, st["x"]), np.where(on, oy - sink, st["y"]),
            np.where(on, 0.0, st["theta"]), np.where(on, 0.0, M), np.where(on, 0.0, F),
            np.where(on, H, st["tension"])]
    return np.stack([r / scale[i] for i, r in enumerate(rows)])


def hang_off_angle(w, L, height, alpha):
    """Suspended first length and H so that the catenary from the TDP reaches the given
    height with the given angle."""
    rest = float(np.sum(w[1:] * L[1:]))

    def forces(l1):
        Vtop = w[0] * l1 + rest
        return Vtop / math.tan(alpha), Vtop

    def resid(l1):
        H, _ = forces(l1)
        if H <= 0:
            return -height
        Ls = L.copy()
        Ls[0] = l1
        return float(catenary_state(np.array([Ls.sum()]), w, Ls, H, 0.0)["y"][0]) - height

    lo, hi = 1e-3 * L[0], 20.0 * max(L[0], height)
    grid = np.geomspace(lo, hi, 60)
    vals = [resid(g) for g in grid]
    for a, b, fa, fb in zip(grid[:-1], grid[1:], vals[:-1], vals[1:]):
        if fa * fb <= 0:
            l1 = brentq(resid, a, b, xtol=1e-9 * L[0])
            H, _ = forces(l1)
            Ls = L.copy()
            Ls[0] = l1
            return H, 0.0, Ls
    raise BVPFailure("no catenary with a touchdown reaches the given hang_off_height with "
                     "hang_off_angle_deg; check the angle, the height and the weights")


def top_tension(w, L, height, T_top):
    """The J-lay form: the inextensible catenary from a touchdown (V0 = 0) to the given
    height [m] with the given top tension [N]. T - w y is constant along a catenary, so
    H = T_top - sum of w_i * (the height gained in segment i): for one segment H = T - w h
    and the suspended length sqrt(h^2 + 2 h H / w); for several, a 1-D root find in H (for
    each H, the first segment's suspended length that reaches the height)."""
    w, L = np.asarray(w, float), np.asarray(L, float)
    if len(L) == 1:
        H = T_top - w[0] * height
        if not w[0] > 0.0 or H <= 0.0:
            raise NoEquilibrium(f"no equilibrium: top_tension {T_top / 1e3:,.6g} kN does not "
                                f"exceed the weight of a line hanging {metres(height)} "
                                f"({w[0] * height / 1e3:,.6g} kN)")
        return H, 0.0, np.array([math.sqrt(height ** 2 + 2.0 * height * H / w[0])])

    def top(H, l1):
        Ls = L.copy()
        Ls[0] = l1
        st = catenary_state(np.array([Ls.sum()]), w, Ls, H, 0.0)
        return float(st["y"][0]), float(st["tension"][0])

    def first_length(H):
        grid = np.geomspace(1e-6 * max(L[0], height), 20.0 * max(L[0], height), 80)
        vals = [top(H, g)[0] - height for g in grid]
        for a, b, fa, fb in zip(grid[:-1], grid[1:], vals[:-1], vals[1:]):
            if fa * fb <= 0:
                return brentq(lambda l1: top(H, l1)[0] - height, a, b, xtol=1e-9 * L[0])
        return None

    def resid(H):
        l1 = first_length(H)
        return None if l1 is None else top(H, l1)[1] - T_top

    prev = None
    for H in np.geomspace(1e-6 * T_top, T_top, 60):
        r = resid(H)
        if r is None:
            continue
        if prev is not None and prev[1] * r <= 0:
            Hs = brentq(lambda h: resid(h) if resid(h) is not None else 0.0, prev[0], H,
                        xtol=1e-12 * T_top)
            Ls = L.copy()
            Ls[0] = first_length(Hs)
            return Hs, 0.0, Ls
        prev = (H, r)
    raise NoEquilibrium(f"no equilibrium: no catenary from a touchdown reaches "
                        f"hang_off_height {metres(height)} with top_tension "
                        f"{T_top / 1e3:,.6g} kN (the top tension cannot hold the line)")


def top_tension_reach(w, L, EA, T_top) -> float:
    """The largest height [m] a line of submerged weights ``w`` [N/m] > 0, segment lengths
    ``L`` [m] (the first free) and axial stiffnesses ``EA`` [N] (inf: inextensible) can
    reach from a touchdown with the top tension ``T_top`` [N]; inf when a segment is
    buoyant (no simple bound).

    T' = w sin(theta) per unstretched length, so T_top - T_TDP = sum of w_i eta_i, eta_i
    the unstretched rise of segment i (eta_i <= L_i but the first's), and T_TDP = H -> 0 at
    the bound: the budget T_top bought rise at w_i a metre, cheapest first. One line type:
    T/w + T^2 / (2 w EA), the line hanging straight down (its stretch integrated); several:
    the rise times the largest stretch factor 1 + T_top / EA."""
    w, L, EA = (np.asarray(a, float) for a in (w, L, EA))
    if not np.all(w > 0.0):
        return math.inf
    if np.all(w == w[0]) and np.all(EA == EA[0]):
        return T_top / w[0] + T_top ** 2 / (2.0 * w[0] * EA[0])
    budget, rise = T_top, 0.0
    for i in np.argsort(w, kind="stable"):
        eta = budget / w[i] if i == 0 else min(L[i], budget / w[i])
        rise += eta
        budget -= w[i] * eta
        if budget <= 0.0:
            break
    return rise * (1.0 + T_top / float(np.min(EA)))


def suspended_lengths(L, g: float) -> np.ndarray:
    """Segment lengths [m] left hanging when the first ``g`` metres lie on the seabed."""
    L = np.asarray(L, float)
    starts = np.concatenate([[0.0], np.cumsum(L)])[:-1]
    return np.clip(starts + L - g, 0.0, L)


#: ``SCALAR_GRID.on = True`` (this thread): :func:`grounded` scans its grid point by point
#: and samples the catenary's state at its end, as before issue 36: the bench's reference
#: (the same guess, bit for bit)
SCALAR_GRID = threading.local()


def grounded(w, L, dx, dy, anywhere: bool = False):
    """Catenary from a touchdown on the seabed (theta = 0) to a hang-off at (dx, dy) from the
    anchor, the grounded length straight on the seabed: the touchdown in the first segment,
    or with ``anywhere`` (an elastic seabed) in a later one if none is found there.
    Returns (H [N], 0, the suspended segment lengths [m], 0 where a segment lies on the
    seabed)."""
    def top(H, Ls):
        # the catenary's end alone (its offsets: 2.2x cheaper than sampling its state
        # there, as the reference does; the same numbers bit for bit)
        if getattr(SCALAR_GRID, "on", False):
            st = catenary_state(np.array([np.sum(Ls)]), w, Ls, H, 0.0)
            ex, ey = float(st["x"][0]), float(st["y"][0])
        else:
            ex, ey = end_offsets(w, Ls, H, 0.0)
        return ex + float(np.sum(L - Ls)), ey

    lo, hi = math.log(1e-6 * np.sum(np.abs(w) * L) + 1e-3), math.log(1e3 * np.sum(np.abs(w) * L) + 1e3)

    def H_for(Ls):
        f = lambda lh: top(math.exp(lh), Ls)[1] - dy                # noqa: E731
        if f(lo) * f(hi) > 0:
            return None
        return math.exp(brentq(f, lo, hi, xtol=1e-12))

    def misses(rows):
        """g at every row of segment lengths at once (NaN: no H), to find the bracket;
        the root itself is found with the scalar g, as before this existed."""
        H = horizontal_tensions(w, rows, dy, lo, hi)
        ex = end_offsets_rows(w, rows, np.where(np.isnan(H), 1.0, H))[0]
        return np.where(np.isnan(H), np.nan, ex + np.sum(L - rows, axis=1) - dx)

    def g(Ls):
        H = H_for(Ls)
        if H is None:
            return None
        return top(H, Ls)[0] - dx

    def first(l1):
        Ls = L.copy()
        Ls[0] = l1
        return Ls

    def later(gl):                # gl: grounded length beyond the first segment
        return suspended_lengths(L, gl)

    searches = [(first, np.linspace(L[0], 1e-3 * L[0], 80), 1e-9 * L[0])]
    if anywhere and len(L) > 1:
        total = float(np.sum(L))
        searches.append((later, np.linspace(L[0], total - 1e-3 * L[-1], 80), 1e-9 * total))
    for lengths, grid, xtol in searches:
        prev = None
        if getattr(SCALAR_GRID, "on", False):       # the reference: point by point, lazily
            pairs = ((z, np.nan if (v := g(lengths(z))) is None else v) for z in grid)
        else:
            pairs = zip(grid, misses(np.array([lengths(z) for z in grid])))
        for z, v in pairs:
            if np.isnan(v):
                continue
            if prev is not None and prev[1] * v <= 0:
                def f(q, cut=lengths):
                    v = g(cut(q))
                    return v if v is not None else 0.0

                try:
                    zs = brentq(f, min(z, prev[0]), max(z, prev[0]), xtol=xtol)
                except ValueError:    # the scalar g has one sign there (g ~ 0 at z)
                    prev = (z, v)
                    continue
                return H_for(lengths(zs)), 0.0, lengths(zs)
            prev = (z, v)
    raise BVPFailure(no_touchdown_reason(w, L, dx, dy))


def free_hanging(w, L, dx, dy, EA=None):
    """Catenary between two pinned ends (elastic with ``EA`` [N] per segment, else
    inextensible): unknown H and the vertical force V0 at the anchor [N]. Bracketed root
    finds first (:func:`bvp.beam.catenary.pinned`: slack to taut, a line that must stretch
    included), else a least-squares fit in log H from several starts."""
    W = float(np.sum(np.abs(w) * L)) or 1.0
    total = float(np.sum(w * L))
    if EA is None and float(np.sum(L)) <= math.hypot(dx, dy):
        raise BVPFailure(f"the line is too short: {span_words(L, dx, dy)}, and an "
                         "inextensible line cannot stretch to join them")
    found = pinned(w, L, dx, dy, EA)
    if found is not None:
        return found[0], found[1], np.asarray(L, float).copy()

    def resid(z):
        H = math.exp(z[0]) * W
        st = catenary_state(np.array([L.sum()]), w, L, H, z[1] * W, EA=EA)
        return [(st["x"][0] - dx) / L.sum(), (st["y"][0] - dy) / L.sum()]

    best = None
    # a taut or nearly straight line: H of the stretch EA (chord / L - 1) is in range too
    for h0 in (0.05, 0.3, 1.0, 3.0, 30.0, 1e3, 1e5):
        r = least_squares(resid, [math.log(h0), -0.5 * total / W], xtol=1e-14, ftol=1e-14)
        if best is None or r.cost < best.cost:
            best = r
    if best.cost > 1e-16:
        short = float(np.sum(L)) <= math.hypot(dx, dy)
        raise BVPFailure(f"no free-hanging catenary found for {span_words(L, dx, dy)}"
                         + (" (the line is too short: it must stretch to join them)" if short
                            else " (the starting-guess search did not converge)"))
    return math.exp(best.x[0]) * W, best.x[1] * W, L.copy()


#: the horizontal tension of a vertical line's starting catenary, a fraction of the weight
#: (H = 0 is the catenary's singular limit; this H makes the line vertical to 1e-9 rad)
VERTICAL_H = 1.0e-9


def vertical(w, L, dy, EA=None):
    """(H, V0, Ls) of a line hanging between two ends on one vertical (a pinned TTR): H
    tiny (:data:`VERTICAL_H`), V0 [N] the anchor's vertical force that makes the line
    reach the height ``dy`` [m] (bracketed: the height rises with V0)."""
    W = float(np.sum(np.abs(w) * L)) or 1.0
    H = VERTICAL_H * W
    if EA is None and float(np.sum(L)) <= dy:
        raise BVPFailure(f"the line is too short: {span_words(L, 0.0, dy)}, and an "
                         "inextensible line cannot stretch to join them")

    def height(V0):
        return end_offsets(w, L, H, V0, EA)[1] - dy

    lo, hi = -W, W
    while height(hi) < 0.0:
        hi *= 2.0
    while height(lo) > 0.0:
        lo *= 2.0
    return H, brentq(height, lo, hi, xtol=1e-12 * W), np.asarray(L, float).copy()


def tensioned(w, L, dx, top_tension, EA=None):
    """(H, V0, Ls) of a line pulled up by a tensioner of vertical force ``top_tension``
    [N] from an anchor ``dx`` [m] behind the tensioner: V0 = top_tension - the weight, and
    H [N] that puts the top at dx (tiny for dx = 0; the top's height follows)."""
    W = float(np.sum(np.abs(w) * L)) or 1.0
    V0 = top_tension - float(np.sum(w * L))
    H = VERTICAL_H * W
    if dx > 0.0 and end_offsets(w, L, H, V0, EA)[0] < dx:
        hi = H
        while end_offsets(w, L, hi, V0, EA)[0] < dx:
            hi *= 4.0
        H = brentq(lambda h: end_offsets(w, L, h, V0, EA)[0] - dx, hi / 4.0, hi,
                   xtol=1e-12 * W)
    return H, V0, np.asarray(L, float).copy()


def hanging(w, L):
    """(H, V0, Ls) of a line hanging from its top with a free lower end: V0 near 0 (the
    free end's tension is zero; a thousandth of the weight keeps the starting catenary's
    curvature small) and H tiny."""
    W = float(np.sum(np.abs(w) * L)) or 1.0
    return VERTICAL_H * W, 1e-3 * W, np.asarray(L, float).copy()


# ------------------------------------------------------------- why a span has no form
def metres(x: float) -> str:
    """A length [m] for a message: thousands separated, 3 significant digits below 100 m."""
    return f"{x:,.0f} m" if abs(x) >= 100.0 else f"{x:.3g} m"


def span_words(L, dx: float, dy: float) -> str:
    """'2,000 m of line between ends 1,803 m apart (1,500 m across, 1,000 m up)'."""
    return (f"{metres(float(np.sum(L)))} of line between ends {metres(math.hypot(dx, dy))} apart "
            f"({metres(dx)} across, {metres(dy)} up)")


def too_long_for_seabed(w, L, anchor, hang_off) -> str:
    """Why a line heavier than water everywhere (w > 0 [N/m], lengths L [m]) is too long
    for fixed ends ``anchor``, ``hang_off`` (x, y) [m] above a seabed at y = 0, else ''.

    Such a line is convex where it hangs and straight where it lies (frictionless seabed,
    tension > 0), so it never turns back: it holds less than the path down to the seabed,
    along it and up to the hang-off, ya + dx + yh (reached only with vertical hanging
    parts). A longer line would have to fold back on itself: no equilibrium of the BVP's
    forms (one contact zone, x increasing along the line) exists. Stretch only adds length,
    so the unstretched length decides for an extensible line too.
    """
    w, L = np.asarray(w, float), np.asarray(L, float)
    if not np.all(w > 0.0):
        return ""      # a buoyant section can hold more line in a wave: no simple bound
    (xa, ya), (xh, yh) = anchor, hang_off
    if float(np.sum(L)) < ya + (xh - xa) + yh:
        return ""
    return (f"the line is too long for the span: {span_words(L, xh - xa, yh - ya)}; without "
            f"folding back on itself {fold_back(float(np.sum(L)), anchor, hang_off)}: no "
            "static equilibrium of this form; shorten the line or move the hang-off away from "
            "the anchor")


def fold_back(total: float, anchor, hang_off) -> str:
    """'it holds less than 2,500 m (1,500 m along the seabed, then 1,000 m straight up), so
    37,500 m would have to fold back' for ``total`` [m] of line between the ends [m]."""
    (xa, ya), (xh, yh) = anchor, hang_off
    most = ya + (xh - xa) + yh
    path = (f"down {metres(ya)} to the seabed, {metres(xh - xa)} along it" if ya > 0.0
            else f"{metres(xh - xa)} along the seabed") + f", then {metres(yh)} straight up"
    excess = (f", so {metres(total - most)} would have to fold back" if total - most >= 1.0
              else "")
    return f"it holds less than {metres(most)} ({path}){excess}"


def no_touchdown_reason(w, L, dx: float, dy: float) -> str:
    """Why no catenary with its touchdown in the first segment (grounded form) joins an
    anchor on the seabed to a hang-off at (dx, dy) [m] from it: too short, too long, or
    the touchdown beyond segments[0] (decided from the lengths and the free catenary)."""
    L = np.asarray(L, float)
    long_ = too_long_for_seabed(w, L, (0.0, 0.0), (dx, dy))
    if long_:
        return long_
    if float(np.sum(L)) <= math.hypot(dx, dy):
        return (f"no touchdown: the line is too short, no longer than the distance between "
                f"its ends ({span_words(L, dx, dy)})")
    try:
        V0 = free_hanging(w, L, dx, dy)[1]
    except BVPFailure:
        V0 = None
    if V0 is not None and V0 >= 0.0:
        return (f"no touchdown: the line is too short to reach the seabed ahead of the anchor "
                f"({span_words(L, dx, dy)}): hanging free, it rises from the anchor")
    if len(L) == 1:
        return (f"no touchdown found for {span_words(L, dx, dy)}, though it is longer than a "
                "line hanging free from the anchor (the search for the grounded catenary "
                "failed)")
    return f"{span_words(L, dx, dy)}: " + touchdown_beyond_first(float(L[0]))


def touchdown_beyond_first(first_length: float) -> str:
    """The reason of the rigid-seabed fixed-ends form when the line is too long to hang
    free from the anchor but has no touchdown within its first segment [m]."""
    return ("the line is longer than a line hanging free from the anchor, so part of it lies "
            f"on the seabed, but no touchdown was found within segments[0] "
            f"({metres(first_length)}), where this form (rigid seabed) puts it: lengthen "
            "segments[0] or use an elastic seabed")

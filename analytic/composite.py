"""The profile of the analytic method: outer catenary plus boundary layers.

Three models (``[analytic] model``), all on the outer solution of analytic/forms.py:

- ``catenary``: the catenary alone, M = EI kappa (no layer: the vertex is the touchdown;
  the moment jumps from 0 on the seabed to EI w / H there).
- ``composite``: outer + inner - common of the touchdown layer, and a moment-free layer at
  each pinned end (the hang-off; the anchor of a free-hanging line) (analytic/layers.py).
- ``piecewise`` (Kang et al. 2015): beam theory from the touchdown up to the point E where
  the catenary's curvature has fallen to ``curvature_threshold``, the catenary above it.
  The beam part is the touchdown layer on the finite interval [lift-off, E] with its
  moment correction zero at E, so shape, angle and moment are continuous there to the
  catenary's own; no layer at the top (the moment there is the catenary's, the
  separation moment Kang et al. argue a J-lay tower imposes).

Tension: T - w y / c + EI kappa^2 / (2 c) is constant across a layer (dT/ds = w sin(theta)
- F theta', EI theta'' = c F), so the composite tension is the catenary's plus
(w/c)(y - y_o) - EI (kappa^2 - kappa_o^2) / (2 c). Shear F = EI kappa' / (1 + T/EA).
"""

from __future__ import annotations

import math

import numpy as np

from riser.results.profile import Profile

from .forms import Line, Outer
from .catenary import bending_correction
from .layers import anchor_layer, layer_length, pinned_end_correction, touchdown_layer

#: stations per boundary-layer length, and the layer lengths they cover
PER_LAYER = 20
LAYER_SPAN = 25.0
#: the most evenly spaced stations along the line (a line longer than 200 km is sampled
#: more coarsely than every 2 m: a hang-off angle 1e-6 deg from the horizontal solved a
#: suspended length of 1e8 m, and 6e7 stations took 30 s and gigabytes)
MAX_STATIONS = 100_000


def stations(total: float, dense: list[tuple[float, float]]) -> np.ndarray:
    """Arc lengths over [0, total]: every min(2 m, total/1000) (at most MAX_STATIONS of
    them) plus, around each (centre, lam) of ``dense``, LAYER_SPAN lam on either side at
    lam / PER_LAYER."""
    n = min(int(math.ceil(total / min(2.0, total / 1000.0))), MAX_STATIONS)
    parts = [np.linspace(0.0, total, n + 1)]
    for centre, lam in dense:
        lo, hi = max(0.0, centre - LAYER_SPAN * lam), min(total, centre + LAYER_SPAN * lam)
        if hi > lo:
            parts.append(np.linspace(lo, hi, int(math.ceil((hi - lo) * PER_LAYER / lam)) + 1))
    return np.unique(np.concatenate(parts))


def build(outer: Outer, line: Line, model: str, total: float, *, pinned_top: bool = True,
          threshold: float | None = None) -> tuple[Profile, dict]:
    """The profile over [0, total] (unstretched arc length from the bottom end) and the
    figures worth reporting (s_E of the piecewise model, the layer lengths)."""
    w, EI, EA, H = line.w, line.EI, line.EA, outer.H
    info: dict = {}
    lam = layer_length(EI, H, EA)
    layer = outer.layer
    if outer.kind == "touchdown" and model == "piecewise":
        sig_E = math.sqrt(max(w * H / threshold - H * H, 0.0)) / w
        end = outer.s_v + sig_E
        info["piecewise_s_E"] = outer.s_L + end
        layer = touchdown_layer(H, w, EI, EA, line.k, end)
    T_top = float(outer.cat.tension(_sigma(outer, total)))
    lam_top = layer_length(EI, T_top, EA)
    dense = [(total, lam_top)]
    anchor = None
    if outer.kind == "touchdown":
        dense.append((outer.s_L, lam))
        if line.k is not None and outer.s_L > 0.0 and model != "catenary":
            # the anchor pinned at y = 0 holds the laid line up from its rest at -w/k
            anchor = anchor_layer(H, w, EI, EA, line.k)
            dense.append((0.0, anchor.length))
            info["anchor_layer_length"] = anchor.length
    else:
        lam0 = layer_length(EI, float(outer.cat.tension(0.0)), EA)     # the pinned anchor's
        dense.append((0.0, lam0))
    s = stations(total, dense)
    c = 1.0 + H / EA
    x, y, th, ka, ka1, T, yo, ko = (np.zeros_like(s) for _ in range(8))
    if outer.kind == "touchdown":
        sus = s >= outer.s_L
        sr = s[sus] - outer.s_L
        sig = sr - outer.s_v
        cat = outer.cat
        x[sus] = outer.x_L + c * outer.s_v + cat.x(sig)
        yo[sus] = outer.y_v + cat.y(sig)
        th[sus], ko[sus], ka1[sus], T[sus] = (cat.theta(sig), cat.curvature(sig),
                                              cat.curvature_slope(sig), cat.tension(sig))
        if outer.layer is not None:
            # the outer solution's O(eps^2) bending correction (analytic/catenary.py)
            dx2, dy2, th2, k2 = bending_correction(cat, EI, sig)
            x[sus] += dx2
            yo[sus] += dy2
            th[sus] += th2
            ko[sus] += k2
        if layer is not None:
            # the outer curvature at the lift-off differs from the layer's common part
            # w/H by O(delta^2) (the catenary's 1/(1+u^2), the bending correction's
            # -2 EI w^3/H^4): a second decaying term of that size makes the moment
            # continuous there (M = 0 at a rigid touchdown) and moves angle and height by
            # O(delta^3) and O(delta^3 lambda)
            k0 = cat.curvature(-outer.s_v) + bending_correction(cat, EI, -outer.s_v)[3]
            e = (w / H - float(k0)) * np.exp(-sr / layer.length)
            yo[sus] += c * layer.length ** 2 * e
            th[sus] -= layer.length * e
            ko[sus] += e
            ka1[sus] -= e / layer.length
        y[sus] = yo[sus]
        ka[sus] = ko[sus]
        if layer is not None:
            yc = layer.correction(sr)
            if model == "piecewise":
                beyond = s[sus] > info["piecewise_s_E"]
                yc = tuple(np.where(beyond, 0.0, v) for v in yc)
            y[sus] += yc[0]
            th[sus] += yc[1] / c
            ka[sus] += yc[2] / c
            ka1[sus] += yc[3] / c
        gr = ~sus
        g = (layer.grounded(s[gr] - outer.s_L) if layer is not None
             else tuple(np.zeros(int(gr.sum())) for _ in range(4)))
        if anchor is not None:
            ga = anchor.correction(s[gr])
            g = tuple(gi + ai for gi, ai in zip(g, ga))
        x[gr] = outer.x_L + c * (s[gr] - outer.s_L)
        y[gr], yo[gr] = g[0], g[0]
        th[gr], ka[gr], ko[gr], ka1[gr] = g[1] / c, g[2] / c, g[2] / c, g[3] / c
        T[gr] = H
    else:
        cat = outer.cat
        x[:] = outer.origin[0] + cat.x(s)
        y[:] = outer.origin[1] + cat.y(s)
        yo[:] = y
        th[:], ko[:], ka1[:], T[:] = (cat.theta(s), cat.curvature(s), cat.curvature_slope(s),
                                      cat.tension(s))
        ka[:] = ko
    if model == "composite":
        # moment-free ends: the hang-off (pinned), and the anchor of a free-hanging line
        dk, dth, dk1 = pinned_end_correction(total - s, float(ka[-1]), lam_top)
        if pinned_top:
            ka += dk
            th -= dth
            ka1 -= dk1
        if outer.kind == "free":
            dk, dth, dk1 = pinned_end_correction(s, float(ka[0]), lam0)
            ka += dk
            th += dth
            ka1 += dk1
            info["anchor_layer_length"] = lam0
        info["top_layer_length"] = lam_top
    # the first integral across the layers (module docstring)
    T = T + (w / c) * (y - yo) - EI * (ka * ka - ko * ko) / (2.0 * c)
    F = EI * ka1 / (1.0 + T / EA)
    tdp_s = outer.s_L if outer.kind == "touchdown" else None
    prof = Profile(s=s, x=x, y=y, z=np.zeros_like(s), theta=th, tension=T,
                   moment=np.abs(EI * ka), shear=np.abs(F), curvature=np.abs(ka), tdp_s=tdp_s)
    return prof, info


def _sigma(outer: Outer, s: float) -> float:
    """The catenary's own coordinate at the line's arc length ``s``."""
    if outer.kind == "touchdown":
        return s - outer.s_L - outer.s_v
    return s

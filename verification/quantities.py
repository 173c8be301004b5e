"""Quantities read off a static profile, shared by every study that compares profiles
(the comparison protocol, the accuracy-versus-cost study, the stress suite).

Arc lengths s [m] from the bottom end, positions [m], forces [N], moments [N m]. Each
function takes profiles already in a common arc-length coordinate (see
:func:`verification.pipeline.shifted`).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from riser.results.profile import Profile, _parabolic_peak, summarize
from riser.model.scene import Scene


def reference_depth(scene: Scene, bvp_summary: dict) -> float:
    """Length that normalises configuration differences [m]: the water depth, else the
    hang-off height above the seabed."""
    return float(scene.water_depth) if scene.water_depth else float(bvp_summary["hang_off_height"])


def curve_distance(ref: Profile, other: Profile, s_range: tuple[float, float],
                   s_shift: float = 0.0) -> tuple[float, float, float]:
    """(max, rms, s at max) of the distance from each ``other`` station in ``s_range`` to
    the polyline of ``ref`` [m] (point to curve, projected on the nearest two segments)."""
    P = np.stack([ref.x, ref.y, ref.z], axis=1)
    so = other.s - s_shift
    sel = (so >= s_range[0] - 1e-9) & (so <= s_range[1] + 1e-9)
    Q = np.stack([other.x[sel], other.y[sel], other.z[sel]], axis=1)
    tree = cKDTree(P)
    _, idx = tree.query(Q)
    best = np.full(len(Q), np.inf)
    for off in (-1, 0):
        i0 = np.clip(idx + off, 0, len(P) - 2)
        a, b = P[i0], P[i0 + 1]
        ab = b - a
        t = np.clip(np.einsum("ij,ij->i", Q - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab),
                                                                  1e-300), 0.0, 1.0)
        d = np.linalg.norm(Q - (a + t[:, None] * ab), axis=1)
        best = np.minimum(best, d)
    i = int(np.argmax(best))
    return float(best.max()), float(np.sqrt(np.mean(best ** 2))), float(so[sel][i])


def nodal_average(nodes: np.ndarray, s: np.ndarray, values: np.ndarray) -> np.ndarray:
    """``values`` (sampled at ``s``) as VFIFE reports an element force at its ``nodes``:
    taken at each element's midpoint, averaged over the two elements of an interior node,
    extrapolated linearly from the last two elements at an end node
    (``vfife.model.Model.nodal_results``)."""
    nodes = np.asarray(nodes, float)
    if len(nodes) < 3:
        return np.interp(nodes, s, values)
    e = np.interp(0.5 * (nodes[1:] + nodes[:-1]), s, values)
    out = np.empty(len(nodes))
    out[1:-1] = 0.5 * (e[1:] + e[:-1])
    out[0] = 1.5 * e[0] - 0.5 * e[1]
    out[-1] = 1.5 * e[-1] - 0.5 * e[-2]
    return out


def signed_moment(p: Profile) -> np.ndarray:
    """In-plane bending moment with the sign of the curvature d(theta)/ds [N m] for a planar
    profile (a 3D profile's ``moment_in_plane``; the magnitude otherwise). Interpolating the magnitude across a zero of the
    moment fills in the V of |M| between two stations: on the Wang riser with a current,
    where the moment changes sign at the first segment boundary, that alone made an 844 N m
    (1.8 % of M_max) 'difference' between 1 m VFIFE stations and the BVP."""
    if p.moment_in_plane is not None:          # a 3D profile: its in-plane component
        return np.asarray(p.moment_in_plane, float)
    m = np.asarray(p.moment, float)
    if np.ptp(np.asarray(p.z, float)) > 1e-9 or len(m) < 3:
        return m
    kappa = np.gradient(np.unwrap(np.asarray(p.theta, float)), np.asarray(p.s, float))
    return np.where(kappa < 0.0, -m, m)


def near_max_peaks(p: Profile, tol: float) -> np.ndarray:
    """Arc lengths [m] of the local maxima of the moment within ``tol`` [N m] of its
    largest value (the global maximum included), each refined to the vertex of the
    parabola through its station and the two neighbours (as the summary's max_moment_s):
    the station alone is up to half an element off (0.5 m on a 1 m VFIFE mesh)."""
    m = np.asarray(p.moment, float)
    s = np.asarray(p.s, float)
    inner = np.flatnonzero((m[1:-1] >= m[:-2]) & (m[1:-1] >= m[2:])) + 1
    idx = np.unique(np.concatenate([inner, [int(np.argmax(m))]]))
    idx = idx[m[idx] >= m.max() - tol]
    return np.array([_parabolic_peak(s, m, int(i))[0] for i in idx])


def peak_location_offset(bvp_prof: Profile, vf_prof: Profile, tol: float) -> float:
    """Signed offset s_VFIFE - s_BVP [m] between the nearest near-maximum moment peaks of
    the two methods (see :func:`peak_location_distance`)."""
    sb, sv = near_max_peaks(bvp_prof, tol), near_max_peaks(vf_prof, tol)
    d = sv[None, :] - sb[:, None]
    return float(d.flat[int(np.argmin(np.abs(d)))])


def peak_location_distance(bvp_prof: Profile, vf_prof: Profile, tol: float) -> float:
    """Distance [m] between the peak-moment locations of the two methods, allowing for
    ties: the peak location is only defined up to the peaks whose moments lie within the
    peak-moment tolerance ``tol`` of the maximum (the Wang baseline's crest and sag-bend
    moments are equal to 1e-5, 276 m apart), so this is the smallest distance between a
    near-maximum peak of one method and one of the other."""
    return abs(peak_location_offset(bvp_prof, vf_prof, tol))


def match_feature(item: dict, candidates: list[dict]) -> dict | None:
    """The candidate crest/sag nearest in arc length (None if there is none)."""
    if not candidates:
        return None
    return min(candidates, key=lambda c: abs(c["s"] - item["s"]))


def raw_values(profile: Profile, ref_summary: dict | None = None) -> dict:
    """Scalar quantities of a profile (already in the reference arc length). Crests and sags
    are matched to the reference ones by arc length: keys crest1_height, sag1_height, ..."""
    sm = summarize(profile)
    out = {"hang_off_tension": sm["hang_off_tension"], "tdp_tension": sm["tdp_tension"],
           "tdp_x": sm["tdp_x"], "max_moment": sm["max_moment"]}
    ref = ref_summary or sm
    for kind in ("crests", "sags"):
        for i, cb in enumerate(ref[kind]):
            cand = sm[kind]
            c = match_feature(cb, cand)
            out[f"{kind[:-1]}{i + 1}_height"] = c["height"] if c else None
    return out

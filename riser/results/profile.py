"""The result both solvers return: a static :class:`Profile` along the line, and its summary.

Conventions: s [m] from the bottom end (anchor or touchdown) to the hang-off; x, y, z [m]
(x towards the hang-off, y up from the seabed, z out of plane); ``theta`` [rad] the tangent
angle from the horizontal; ``tension`` the effective tension [N]; ``moment`` the bending
moment magnitude [N m]; ``shear`` the shear force magnitude [N]; ``curvature`` [1/m];
``wall_tension`` [N] the pipe wall's tension, only for a scene with [internal_flow] (see
:mod:`riser.physics.internal_flow`; the ``wall_tension`` column of profile.csv). A 3D scene's
profile (``Scene.is_planar`` False) carries ``lateral`` [m], the signed offset from the
line's plane (the vertical plane through the anchor and the hang-off), and the bending
moment's two components across the tangent, ``moment_in_plane`` [N m] (signed as the
planar moment) and ``moment_out_of_plane`` [N m] (the moment that bends the line out of
that plane) (:mod:`riser.model.frame`; the profile.csv columns of the same names).
"""

from __future__ import annotations

import csv
import dataclasses
import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

PROFILE_COLUMNS = ("s", "x", "y", "z", "tension", "moment", "shear", "curvature", "angle_deg")
#: the columns a profile carries only where they apply, after PROFILE_COLUMNS in this order
OPTIONAL_COLUMNS = ("wall_tension", "lateral", "moment_in_plane", "moment_out_of_plane",
                    "stress_axial", "stress_bending", "stress_hoop", "von_mises", "utilisation",
                    "bend_utilisation")


@dataclass(frozen=True)
class Profile:
    """Static configuration and internal forces sampled along the line (arrays of shape (n,)).

    ``tdp_s`` is the arc length of the touchdown point [m] (None for a free-hanging line);
    ``wall_tension`` [N] is set for scenes with internal flow or a [design]; the design
    columns (``stress_axial``, ``stress_bending``, ``stress_hoop``, ``von_mises`` [Pa],
    ``utilisation`` [-]) and ``design_code`` for a scene with a [design] only
    (:mod:`riser.design.checks`, applied after the solve: :meth:`replace`);
    ``bend_utilisation`` [-] for a scene that states a bending limit
    (:mod:`riser.design.bending`: kappa MBR, or the steel wall's (OD/2) kappa over its
    allowable bending strain; 0 where the line type has no limit).

    Frozen: a method builds it once; a changed copy is :meth:`replace`'s.
    """

    s: np.ndarray
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    theta: np.ndarray
    tension: np.ndarray
    moment: np.ndarray
    shear: np.ndarray
    curvature: np.ndarray
    tdp_s: float | None = None
    wall_tension: np.ndarray | None = None
    lateral: np.ndarray | None = None
    moment_in_plane: np.ndarray | None = None
    moment_out_of_plane: np.ndarray | None = None
    stress_axial: np.ndarray | None = None
    stress_bending: np.ndarray | None = None
    stress_hoop: np.ndarray | None = None
    von_mises: np.ndarray | None = None
    utilisation: np.ndarray | None = None
    bend_utilisation: np.ndarray | None = None
    design_code: str | None = None

    def __post_init__(self) -> None:
        for name in ("s", "x", "y", "z", "theta", "tension", "moment", "shear", "curvature"):
            object.__setattr__(self, name, np.asarray(getattr(self, name), dtype=float))
        for name in OPTIONAL_COLUMNS:
            if getattr(self, name) is not None:
                object.__setattr__(self, name, np.asarray(getattr(self, name), dtype=float))

    def replace(self, **changes) -> Profile:
        """A copy with ``changes`` (columns by name, ``tdp_s``, ``design_code``)."""
        return dataclasses.replace(self, **changes)

    @property
    def is_3d(self) -> bool:
        """True for the profile of a 3D scene (it carries the lateral offset)."""
        return self.lateral is not None

    def is_finite(self) -> bool:
        return all(np.all(np.isfinite(getattr(self, n))) for n in
                   ("s", "x", "y", "z", "theta", "tension", "moment", "shear", "curvature"))

    def write_csv(self, path: str | Path) -> None:
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            cols = [self.s, self.x, self.y, self.z, self.tension, self.moment, self.shear,
                    self.curvature, np.degrees(self.theta)]
            names = list(PROFILE_COLUMNS)
            for name in OPTIONAL_COLUMNS:
                if getattr(self, name) is not None:
                    names.append(name)
                    cols.append(getattr(self, name))
            w.writerow(names)
            for row in zip(*cols):
                w.writerow([f"{v:.10g}" for v in row])


def _parabolic_peak(s: np.ndarray, v: np.ndarray, i: int) -> tuple[float, float]:
    """Vertex (s, v) of the parabola through points i-1, i, i+1 (falls back to point i)."""
    if i <= 0 or i >= len(s) - 1:
        return float(s[i]), float(v[i])
    s0, s1, s2 = s[i - 1], s[i], s[i + 1]
    v0, v1, v2 = v[i - 1], v[i], v[i + 1]
    denom = (s0 - s1) * (s0 - s2) * (s1 - s2)
    if denom == 0.0:
        return float(s1), float(v1)
    a = (s2 * (v1 - v0) + s1 * (v0 - v2) + s0 * (v2 - v1)) / denom
    b = (s2 * s2 * (v0 - v1) + s1 * s1 * (v2 - v0) + s0 * s0 * (v1 - v2)) / denom
    if a == 0.0:
        return float(s1), float(v1)
    sv = -b / (2.0 * a)
    if not (s0 <= sv <= s2):
        return float(s1), float(v1)
    c = v1 - a * s1 * s1 - b * s1
    return float(sv), float(a * sv * sv + b * sv + c)


def waves(profile: Profile, min_prominence: float | None = None) -> tuple[list[dict], list[dict]]:
    """Crests (local maxima of y) and sag bends (local minima) of the suspended line.

    Only the part above the touchdown point is searched, end points excluded. Extrema
    whose height differs from the neighbouring extremum by less than ``min_prominence``
    [m] (default 1e-4 of the height range) are dropped as noise. Each entry is
    ``{"s", "x", "height"}`` with the vertex refined by a parabola through three samples
    (and ``lateral``, the offset from the line's plane there, on a 3D profile).
    """
    keep = np.concatenate([[True], np.diff(profile.s) > 0.0])     # ignore repeated stations
    s, x, y = profile.s[keep], profile.x[keep], profile.y[keep]
    lat = profile.lateral[keep] if profile.lateral is not None else None
    start = 0
    if profile.tdp_s is not None:
        start = int(np.searchsorted(s, profile.tdp_s + 1e-9))
    if len(s) - start < 3:
        return [], []
    yr = float(np.ptp(y)) if len(y) else 0.0
    tol = min_prominence if min_prominence is not None else 1e-4 * max(yr, 1e-9)
    # candidate extrema by sign change of the slope, then enforce alternation + prominence
    cand: list[tuple[int, str]] = []
    for i in range(max(start, 1), len(s) - 1):
        if y[i] > y[i - 1] and y[i] >= y[i + 1]:
            cand.append((i, "max"))
        elif y[i] < y[i - 1] and y[i] <= y[i + 1]:
            cand.append((i, "min"))
    changed = True
    while changed and cand:
        changed = False
        # neighbours of each extremum: previous/next extremum or the ends of the search range
        for k, (i, kind) in enumerate(cand):
            left = y[cand[k - 1][0]] if k > 0 else y[start]
            right = y[cand[k + 1][0]] if k + 1 < len(cand) else y[-1]
            if min(abs(y[i] - left), abs(y[i] - right)) < tol:
                del cand[k]
                changed = True
                break
        # merge equal-kind neighbours, keeping the more extreme one
        k = 0
        while k + 1 < len(cand):
            (i, a), (j, b) = cand[k], cand[k + 1]
            if a == b:
                keep_i = (y[i] >= y[j]) if a == "max" else (y[i] <= y[j])
                del cand[k + 1 if keep_i else k]
                changed = True
            else:
                k += 1
    crests, sags = [], []
    for i, kind in cand:
        sv, yv = _parabolic_peak(s, y, i)
        item = {"s": sv, "x": float(np.interp(sv, s, x)), "height": yv}
        if lat is not None:
            item["lateral"] = float(np.interp(sv, s, lat))
        (crests if kind == "max" else sags).append(item)
    return crests, sags


def summarize(profile: Profile) -> dict:
    """Scalar features of a static profile (see docs/results.md, summary.json)."""
    s = profile.s

    def peak(values: np.ndarray) -> tuple[float, float]:
        i = int(np.argmax(values))
        sv, v = _parabolic_peak(s, values, i)
        return max(v, float(values[i])), sv

    tmax, tmax_s = peak(profile.tension)
    mmax, mmax_s = peak(profile.moment)
    fmax, fmax_s = peak(profile.shear)
    crests, sags = waves(profile)
    tdp_x = tdp_t = None
    if profile.tdp_s is not None:
        tdp_x = float(np.interp(profile.tdp_s, s, profile.x))
        tdp_t = float(np.interp(profile.tdp_s, s, profile.tension))
    out = {
        "hang_off_tension": float(profile.tension[-1]),
        "hang_off_angle_deg": float(np.degrees(profile.theta[-1])),
        "hang_off_x": float(profile.x[-1]),
        "hang_off_height": float(profile.y[-1]),
        "hang_off_z": float(profile.z[-1]),
        "hang_off_moment": float(_signed_end_moment(profile, -1)),
        "anchor_moment": float(_signed_end_moment(profile, 0)),
        "anchor_x": float(profile.x[0]),
        "anchor_height": float(profile.y[0]),
        "bottom_tension": float(profile.tension[0]),
        "tdp_s": None if profile.tdp_s is None else float(profile.tdp_s),
        "tdp_x": tdp_x,
        "tdp_tension": tdp_t,
        "span": float(profile.x[-1] - (tdp_x if tdp_x is not None else profile.x[0])),
        "length": float(s[-1] - s[0]),
        "max_tension": tmax, "max_tension_s": tmax_s,
        "max_moment": mmax, "max_moment_s": mmax_s,
        "max_shear": fmax, "max_shear_s": fmax_s,
        "min_tension": float(np.min(profile.tension)),
        "crests": crests,
        "sags": sags,
    }
    if profile.wall_tension is not None:
        out["hang_off_wall_tension"] = float(profile.wall_tension[-1])
        out["max_wall_tension"] = float(np.max(profile.wall_tension))
    if profile.is_3d:
        out.update(lateral_summary(profile))
    if profile.utilisation is not None:
        iu, iv = int(np.argmax(profile.utilisation)), int(np.argmax(profile.von_mises))
        out.update({"design_code": profile.design_code,
                    "max_utilisation": float(profile.utilisation[iu]),
                    "max_utilisation_s": float(s[iu]),
                    "max_von_mises": float(profile.von_mises[iv]),
                    "max_von_mises_s": float(s[iv]),
                    "design_passes": bool(profile.utilisation[iu] <= 1.0)})
    if profile.bend_utilisation is not None:
        ib = int(np.argmax(profile.bend_utilisation))
        out.update({"max_bend_utilisation": float(profile.bend_utilisation[ib]),
                    "max_bend_utilisation_s": float(s[ib])})
    return out


def _signed_end_moment(profile: Profile, i: int) -> float:
    """The in-plane bending moment M = EI dtheta/ds [N m] at the end ``i`` (0 or -1),
    signed (a 3D profile's in-plane component)."""
    if profile.moment_in_plane is not None:
        return profile.moment_in_plane[i]
    if len(profile.s) < 3:
        return profile.moment[i]
    kappa = np.gradient(np.unwrap(profile.theta), profile.s)[i]
    return profile.moment[i] * (-1.0 if kappa < 0.0 else 1.0)


def lateral_summary(profile: Profile) -> dict:
    """The 3D figures of a profile: the largest lateral excursion from the line's plane
    (signed, [m]) and its arc length, the lateral offset at the touchdown, the largest
    out-of-plane bending moment magnitude [N m] and its arc length."""
    s, lat = profile.s, profile.lateral
    i = int(np.argmax(np.abs(lat)))
    sv, v = _parabolic_peak(s, np.abs(lat), i)
    out = {"max_lateral_offset": float(np.copysign(max(v, abs(lat[i])), lat[i])),
           "max_lateral_offset_s": sv,
           "tdp_lateral": (None if profile.tdp_s is None
                           else float(np.interp(profile.tdp_s, s, lat)))}
    m = np.abs(profile.moment_out_of_plane)
    j = int(np.argmax(m))
    sm, vm = _parabolic_peak(s, m, j)
    out.update({"max_moment_out_of_plane": max(vm, float(m[j])),
                "max_moment_out_of_plane_s": sm})
    return out


def _json_default(o):
    if isinstance(o, (np.floating, np.integer)):
        return o.item()
    if isinstance(o, np.ndarray):
        return o.tolist()
    raise TypeError(type(o).__name__)


def write_json(data: dict, path: str | Path) -> None:
    """Write ``data`` as indented JSON; NaN/inf are written as null (never as invalid JSON)."""
    def clean(v):
        if isinstance(v, float) and not math.isfinite(v):
            return None
        if isinstance(v, dict):
            return {k: clean(x) for k, x in v.items()}
        if isinstance(v, (list, tuple)):
            return [clean(x) for x in v]
        return v
    Path(path).write_text(json.dumps(clean(data), indent=2, default=_json_default) + "\n")

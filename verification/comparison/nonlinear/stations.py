"""The stations of the time-domain comparison, picked on the static profile: the hang-off,
the sag and hog bends, the touchdown's static position and the attachments.

- hang-off: the top node (s = the line's length);
- touchdown: the static profile's touchdown point (``Profile.tdp_s``), when it has one;
- sag bend: each interior local minimum of the height y(s) of the suspended line (a jumper's
  or a lazy wave's low point), else, on a line with a touchdown, the largest static curvature
  of the suspended part (a catenary's sag bend just above the touchdown);
- hog bend: each interior local maximum of y(s) (a lazy wave's arch);
- attachments: each attachment's s.
Stations closer than :data:`MIN_GAP` element lengths to an earlier one are dropped (the same
point twice). Arc lengths [m] from the bottom end.
"""

from __future__ import annotations

import numpy as np

#: stations closer than this many static element lengths merge (the first one named stays)
MIN_GAP = 2.0


def _interior_extrema(s, y, sign: float, clear: float) -> list[float]:
    """s of the interior strict local minima (sign +1) or maxima (-1) of y, at least
    ``clear`` [m] from both ends, the line off the seabed there (y > 0)."""
    v = sign * np.asarray(y, float)
    out = []
    for i in range(1, len(s) - 1):
        if v[i] < v[i - 1] and v[i] <= v[i + 1] and clear <= s[i] <= s[-1] - clear \
                and y[i] > 0.0:
            out.append(float(s[i]))
    return out


def pick(profile, attachments=(), h: float = 1.0) -> list[tuple[str, float]]:
    """(name, s [m]) of the stations of a static ``profile`` (riser.results.profile.Profile),
    with the scene's ``attachments`` (objects with ``s`` and ``label``); ``h`` [m] the
    static mesh's element length (merging)."""
    s, y = np.asarray(profile.s, float), np.asarray(profile.y, float)
    L = float(s[-1])
    out = [("hang-off", L)]
    clear = 5.0 * h
    sags = _interior_extrema(s, y, +1.0, clear)
    td = profile.tdp_s
    if td is not None:
        out.append(("touchdown", float(td)))
    if not sags and td is not None:
        k = np.asarray(profile.curvature, float)
        free = (s > td + h) & (s < L - clear)
        if np.any(free):
            sags = [float(s[free][int(np.argmax(np.abs(k[free])))])]
    hogs = _interior_extrema(s, y, -1.0, clear)
    cands = out + [("sag bend", v) for v in sags] + [("hog bend", v) for v in hogs] + [
        (f"attachment {getattr(a, 'label', '') or i + 1}", float(a.s))
        for i, a in enumerate(attachments)]
    kept: list[tuple[str, float]] = []
    for name, v in cands:
        if all(abs(v - w) >= MIN_GAP * h for _, w in kept):
            kept.append((name, v))
    for bend in ("sag bend", "hog bend"):       # numbered when there are several
        idx = [i for i, (n, _) in enumerate(kept) if n == bend]
        if len(idx) > 1:
            for k, i in enumerate(idx):
                kept[i] = (f"{bend} {k + 1}", kept[i][1])
    return kept

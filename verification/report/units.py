"""Console numbers with units that keep their significant digits: a force or moment
with the prefix mN to MN that shows at least three of them (a lab model's 1.1 N is never
``0.00 kN``), and lengths in metres."""

from __future__ import annotations

import math


#: console prefixes, largest first: (factor, prefix)
_PREFIXES = ((1.0e6, "M"), (1.0e3, "k"), (1.0, ""), (1.0e-3, "m"))


def with_unit(value, unit: str, decimals: int = 2, digits: int = 3) -> str:
    """``value`` [``unit``, SI: N or N m] with the prefix M, k, none or m that puts it in
    [1, 1000) (beyond: in MN or mN), printed with ``decimals`` decimals and at least
    ``digits`` significant digits: ``831.47 kN``, ``1.12 N``, ``45.30 mN m``, ``0.0123 mN``.
    Never rounds a lab model's 1.1 N to ``0.00 kN``."""
    if value is None:
        return "n/a"
    value = float(value)
    if not math.isfinite(value):
        return f"{value} {unit}"
    if value == 0.0:
        return f"0 {unit}"
    i = next((k for k, (f, _) in enumerate(_PREFIXES) if abs(value) >= f), len(_PREFIXES) - 1)
    while True:
        factor, prefix = _PREFIXES[i]
        x = value / factor
        places = max(decimals, digits - 1 - math.floor(math.log10(abs(x))))
        if i == 0 or abs(round(x, places)) < 1000.0:      # 999.996 N is 1.00 kN
            return f"{x:.{places}f} {prefix}{unit}"
        i -= 1


def length(value, decimals: int = 2, digits: int = 3) -> str:
    """A length [m] as a number of metres with ``decimals`` decimals and at least
    ``digits`` significant digits (``1500.00``, ``0.350``), without the unit."""
    if value is None:
        return "n/a"
    value = float(value)
    if not math.isfinite(value) or value == 0.0:
        return f"{value:.{decimals}f}"
    need = digits - 1 - math.floor(math.log10(abs(value)))
    return f"{value:.{max(decimals, need)}f}"

"""Console numbers with units that keep their significant digits, and no more than the
results hold: a force or moment with the prefix mN to MN that shows at least three of
them (a lab model's 1.1 N is never ``0.00 kN``), lengths in metres; never more than
:data:`MAX_DIGITS` significant digits, a magnitude below the smallest prefix (1 mN,
1 mN m) or below a millimetre in scientific notation (``3.44e-10 N m``, ``2.28e-29``),
and 0 for a value within round-off of its quantity's scale when the caller gives it."""

from __future__ import annotations

import math


#: console prefixes, largest first: (factor, prefix)
_PREFIXES = ((1.0e6, "M"), (1.0e3, "k"), (1.0, ""), (1.0e-3, "m"))
#: the most significant digits a console number shows: the solvers write their results
#: with 10 and the two methods agree to far fewer, so more would be noise
MAX_DIGITS = 7
#: values (and differences) at or below this fraction of their quantity's scale are
#: round-off and print as 0: the profiles hold 10 significant digits, so nothing below
#: ~1e-9 of a quantity's scale is reproducible (:mod:`verification.comparison.formatting`)
ROUND_OFF = 1.0e-9
#: a length [m] below this prints in scientific notation (a millimetre: fixed notation
#: with three significant digits would need more than five decimals)
SMALL_LENGTH = 1.0e-3


def below_round_off(value, scale) -> bool:
    """``value`` is round-off of ``scale`` (same unit; False without a positive scale)."""
    return scale is not None and scale > 0 and abs(value) <= ROUND_OFF * abs(scale)


def _fixed(x: float, places: int) -> str:
    """``x`` with ``places`` decimals, cut to :data:`MAX_DIGITS` significant digits
    (scientific notation when the integer part alone has more)."""
    lead = math.floor(math.log10(abs(x)))
    if lead >= MAX_DIGITS:
        return f"{x:.{MAX_DIGITS - 1}e}"
    return f"{x:.{max(0, min(places, MAX_DIGITS - 1 - lead))}f}"


def with_unit(value, unit: str, decimals: int = 2, digits: int = 3, scale=None) -> str:
    """``value`` [``unit``, SI: N or N m] with the prefix M, k, none or m that puts it in
    [1, 1000) (beyond: in MN or mN), printed with ``decimals`` decimals and at least
    ``digits`` (at most :data:`MAX_DIGITS`) significant digits: ``831.47 kN``,
    ``1.12 N``, ``45.30 mN m``, ``0.0123 mN``; below 1 mN (1 mN m) in scientific notation
    in the SI unit with ``digits`` digits (``3.44e-10 N m``); ``0 N`` when within
    :data:`ROUND_OFF` of ``scale`` (same unit; e.g. the largest moment for an
    out-of-plane moment). Never rounds a lab model's 1.1 N to ``0.00 kN``."""
    if value is None:
        return "n/a"
    value = float(value)
    if not math.isfinite(value):
        return f"{value} {unit}"
    if value == 0.0 or below_round_off(value, scale):
        return f"0 {unit}"
    if abs(value) < _PREFIXES[-1][0]:
        return f"{value:.{digits - 1}e} {unit}"
    i = next(k for k, (f, _) in enumerate(_PREFIXES) if abs(value) >= f)
    while True:
        factor, prefix = _PREFIXES[i]
        x = value / factor
        places = max(decimals, digits - 1 - math.floor(math.log10(abs(x))))
        if i == 0 or abs(round(x, places)) < 1000.0:      # 999.996 N is 1.00 kN
            return f"{_fixed(x, places)} {prefix}{unit}"
        i -= 1


def length(value, decimals: int = 2, digits: int = 3, scale=None) -> str:
    """A length [m] as a number of metres with ``decimals`` decimals and at least
    ``digits`` (at most :data:`MAX_DIGITS`) significant digits (``1500.00``, ``0.350``),
    without the unit; below :data:`SMALL_LENGTH` in scientific notation with ``digits``
    digits (``2.28e-29``); ``0`` when within :data:`ROUND_OFF` of ``scale`` [m] (e.g. the
    span for an offset)."""
    if value is None:
        return "n/a"
    value = float(value)
    if not math.isfinite(value):
        return f"{value}"
    if value == 0.0 or below_round_off(value, scale):
        return "0"
    if abs(value) < SMALL_LENGTH:
        return f"{value:.{digits - 1}e}"
    need = digits - 1 - math.floor(math.log10(abs(value)))
    return _fixed(value, max(decimals, need))

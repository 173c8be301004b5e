"""How the values and differences of agreement rows print in a comparison's report: a
difference below round-off of its basis prints as 0, a relative difference as a signed
percentage of the row's basis. (Console forces, moments and lengths:
:mod:`verification.report.units`.)"""

from __future__ import annotations

import math

import numpy as np

from verification.report.markdown import fmt
#: differences (and values) below this fraction of their basis are printed as 0: the
#: solvers write their profiles with 10 significant digits, so nothing below ~1e-9 of a
#: quantity's scale is reproducible from the files (one floor for the console's units too)
from verification.report.units import ROUND_OFF


def is_zero(value, scale) -> bool:
    """``value`` is round-off of ``scale``."""
    return scale is not None and scale > 0 and abs(value) <= ROUND_OFF * scale


def num(value, scale=None, digits: int = 6) -> str:
    """A number for the tables; 0 when below round-off of ``scale``."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return ""
    if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
        return str(int(value))
    if is_zero(value, scale):
        return "0"
    return fmt(float(value), digits)


def signed(value, scale=None, digits: int = 4) -> str:
    """A signed difference; 0 when below round-off of ``scale``."""
    if value is None:
        return ""
    if value == 0 or is_zero(value, scale):
        return "0"
    return f"{value:+.{digits}g}"


def relative(rel, basis_label: str = "") -> str:
    """A signed relative difference in % of its basis ('' when there is none)."""
    if rel is None:
        return ""
    if abs(rel) <= ROUND_OFF:
        return "0"
    return f"{100.0 * rel:+.3g} %" + (f" of {basis_label}" if basis_label else "")


def rel(r: dict) -> str:
    """Signed relative difference of row ``r`` in % of its basis ('' when it has none)."""
    return relative(r.get("rel_diff"), r.get("basis_label") or "")


def scale(r: dict):
    """Scale below which a value of row ``r`` is round-off: its basis, else its size."""
    if r.get("basis"):
        return r["basis"]
    vals = [abs(x) for x in (r.get("bvp"), r.get("vfife")) if x is not None]
    return max(vals) if vals else None


def where(r: dict) -> str:
    """' at s = ... m' for a row with an arc length, else ''."""
    return f" at s = {r['at_s']:.1f} m" if r.get("at_s") is not None else ""

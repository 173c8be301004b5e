"""The design verdicts of a result: which design checks fail (``design_fails``).

A check that fails is a named result, not a number to be read: every command prints it
(``design_fails: <check>: ...``, one line each), summary.json lists it under
``design_fails``, and with ``--strict`` the command exits 1 (``solve``, ``compare``,
``sweep`` and ``fatigue``). The checks, read from a result's summary keys (SI):

- ``code_check``: the code's utilisation (``[design] code``: DNV-ST-F201's combined
  loading or API RP 2RD's von Mises; :mod:`riser.design.checks`) above 1 anywhere on the
  line: the static profile's ``max_utilisation`` or a dynamic run's
  ``dynamic_max_utilisation`` (the largest over its statistics window);
- ``fatigue``: the fatigue utilisation DFF x design_life / life above 1 at a station
  (``fatigue_verdict`` of ``riser-verify fatigue``, ``dynamic_fatigue_verdict`` of a
  dynamic run's record; :mod:`riser.design.fatigue`);
- ``bend_limit``: the curvature utilisation above 1 (a bend radius below the line type's
  ``minimum_bend_radius``, or a steel wall's bending strain beyond its limit):
  ``max_bend_utilisation`` (static) or ``dynamic_max_bend_utilisation``.

A check that was not made (no ``[design]``, no ``design_life``, no bend limit) is absent,
not passed: :func:`checks_made` says which were.

Pure functions of the summary dictionary: the methods never import them (the result's
summary calls :func:`design_failures`).
"""

from __future__ import annotations

import math

#: the named checks, in the order they are printed
CHECKS = ("code_check", "fatigue", "bend_limit")


def _number(summary: dict, key: str) -> float | None:
    v = summary.get(key)
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        return None
    return float(v)


def _where(summary: dict, key: str) -> str:
    s, t = _number(summary, f"{key}_s"), _number(summary, f"{key}_time")
    return ("" if s is None else f" at s = {s:.1f} m") + ("" if t is None else
                                                          f", t = {t:.4g} s")


def checks_made(summary: dict) -> tuple[str, ...]:
    """The checks of :data:`CHECKS` the summary carries a value for."""
    made = []
    if any(_number(summary, k) is not None for k in ("max_utilisation",
                                                     "dynamic_max_utilisation")):
        made.append("code_check")
    if any(summary.get(k) in ("pass", "fail") for k in ("fatigue_verdict",
                                                        "dynamic_fatigue_verdict")):
        made.append("fatigue")
    if any(_number(summary, k) is not None for k in ("max_bend_utilisation",
                                                     "dynamic_max_bend_utilisation")):
        made.append("bend_limit")
    return tuple(made)


def design_failures(summary: dict) -> list[str]:
    """The failed design checks of a result's ``summary`` (summary.json's keys), one
    named line each (``<check>: ...``, without the ``design_fails:`` prefix); [] when every
    check made passes or none was made."""
    out = []
    code = summary.get("design_code") or summary.get("dynamic_design_code") or "the code"
    for key, what in (("max_utilisation", "static"), ("dynamic_max_utilisation",
                                                      "dynamic, over the statistics window")):
        u = _number(summary, key)
        if u is not None and u > 1.0:
            out.append(f"code_check: utilisation {u:.4g} > 1 ({code}, {what})"
                       f"{_where(summary, key)}")
    for prefix, what in (("", "scatter diagram"), ("dynamic_", "the run's record")):
        if summary.get(f"{prefix}fatigue_verdict") == "fail":
            u = _number(summary, f"{prefix}max_fatigue_utilisation")
            text = "" if u is None else f" {u:.4g}"
            out.append(f"fatigue: fatigue utilisation DFF x design life / life{text} > 1 "
                       f"({what}){_where(summary, f'{prefix}max_fatigue_utilisation')}")
    for key, what in (("max_bend_utilisation", "static"),
                      ("dynamic_max_bend_utilisation", "dynamic, over the statistics window")):
        u = _number(summary, key)
        if u is not None and u > 1.0:
            out.append(f"bend_limit: curvature utilisation {u:.4g} > 1 ({what})"
                       f"{_where(summary, key)}")
    return out


def with_verdicts(summary: dict) -> dict:
    """``summary`` with ``design_fails`` (the list of :func:`design_failures`) when any
    check of :data:`CHECKS` was made (a result without one keeps its keys as they were)."""
    if checks_made(summary):
        summary["design_fails"] = design_failures(summary)
    return summary

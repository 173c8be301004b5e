"""The progress-callback convention every method and command shares.

A long run reports through ``progress(message)`` or ``progress(message, fraction=f)``
(``f``: the fraction of the run done, 0..1, where the caller knows it). Methods call
:func:`with_fraction` once so that either kind of callable works.
"""

from __future__ import annotations

import inspect


def with_fraction(progress):
    """``progress`` as a callable ``f(message, fraction=None)``: itself when it takes a
    ``fraction`` keyword (or ``**kwargs``), else a wrapper dropping the fraction; None
    stays None."""
    if progress is None:
        return None
    try:
        params = inspect.signature(progress).parameters.values()
    except (TypeError, ValueError):
        params = ()
    if any(p.name == "fraction" or p.kind is p.VAR_KEYWORD for p in params):
        return progress
    return lambda message, fraction=None: progress(message)

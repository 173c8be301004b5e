"""What the VFIFE's dynamic run records: the shared recorder of every time domain
(:mod:`riser.results.recorder`: the time-series, envelope and states columns), fed with
the VFIFE's nodal state (:func:`nodal_state`)."""

from __future__ import annotations

import numpy as np

from riser.results.recorder import (ARC_LENGTH_COLUMNS, ARC_LENGTH_KEYS, ENVELOPE,  # noqa: F401
                                    TIMESERIES, NodalState, Recorder,
                                    most_probable_maximum, touchdown_s)


def nodal_state(model) -> NodalState:
    """The sample of the VFIFE ``model``'s state at its nodes (:class:`NodalState`)."""
    r = model.nodal_results()
    return NodalState(model.positions(), model.V.T.copy(), model.directors(), r["tension"],
                      r["moment"], r["curvature"], r["moment_vector"].T.copy(),
                      _surface(model))


def _surface(model) -> np.ndarray:
    """The sea surface's height [m] over every node of ``model`` as the run has it: the
    waves' depth + eta at the node (evaluated at the sample's time), else the still water
    level, inf without a surface (no water_depth)."""
    return model.waves.WT[6] if model.use_waves else model.ysurf

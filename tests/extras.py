"""Markers of the tests that need an optional extra (shared by the test files).

``needs_dask``: skip, with the reason, when the extra ``[cluster]`` (dask.distributed) is
not installed."""

from __future__ import annotations

import pytest

try:
    import distributed
except ImportError:
    distributed = None

needs_dask = pytest.mark.skipif(distributed is None, reason="the optional extra [cluster] "
                                "(dask.distributed) is not installed")

"""Markers of the tests that need an optional extra (shared by the test files).

``needs_dask``: skip, with the reason, when the extra ``[cluster]`` (dask.distributed) is
not installed; ``needs_moordyn``: the same for the extra ``[moordyn]`` (MoorDyn-C v2), in
a file whose other tests run without it; ``needs_yaml``: the extra ``[orcaflex]`` (PyYAML,
which reads OrcaFlex text data files)."""

from __future__ import annotations

import pytest

try:
    import distributed
except ImportError:
    distributed = None

needs_dask = pytest.mark.skipif(distributed is None, reason="the optional extra [cluster] "
                                "(dask.distributed) is not installed")

try:
    import moordyn
except ImportError:
    moordyn = None

needs_moordyn = pytest.mark.skipif(moordyn is None, reason="the optional extra [moordyn] "
                                   "(MoorDyn-C v2) is not installed")

try:
    import yaml
except ImportError:
    yaml = None

needs_yaml = pytest.mark.skipif(yaml is None, reason="the optional extra [orcaflex] (PyYAML) "
                                "is not installed")

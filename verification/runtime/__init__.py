"""Where and how work runs, independent of what it computes: :mod:`.engine` (units of work
in this process, a pool of local worker processes or a Dask cluster), :mod:`.dask_local` (a
local Dask scheduler and workers as processes, for the bench and the tests),
:mod:`.progress` (the terminal progress line built from the ``progress=`` callbacks) and
:mod:`.outdir` (the files each command writes, cleared before it runs).

Imports nothing of ``verification`` outside this folder (``tests/test_layers.py``).
"""

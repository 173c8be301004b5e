"""Writing generated reports: :mod:`.markdown` (the generated-file note, number formats,
tables), :mod:`.figures` (matplotlib off-screen) and :mod:`.dynamics` (the plots and
console lines of a dynamic run).

Imports nothing of ``verification`` outside this folder (``tests/test_layers.py``).
"""

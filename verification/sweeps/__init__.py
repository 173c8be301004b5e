"""Load-case sweeps (``riser-verify sweep SWEEP``): :mod:`.file` (the sweep file: base,
methods, ``[set]``, ``[[vary]]`` key paths and values, ``zip``; every case validated as a
scene before anything runs), :mod:`.case` (one case solved in a worker with no file
access, its record stored in the case's own folder: resume), :mod:`.run` (the cases on the
engine, resumed), :mod:`.report` (``cases.csv``, ``envelopes.csv``, range graphs,
``report.md``) and :mod:`.bench` (``bench --sweep``: throughput per engine). Built-in sweep
files are in ``builtin/``.

Never imports a study, a peer or the command line (``tests/test_layers.py``).
"""

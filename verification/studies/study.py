"""What a study declares so that ``reproduce`` can run it and ``reports/README.md`` can
index it (the registry is :mod:`verification.studies`).

A study writes into ``reports/<name>/``. Its units of work are independent pieces that
each write their own files (one per scene for the comparison and the cost study, a single
unit ``None`` for a paper reproduction); ``reproduce all --jobs N`` hands the units of every
study to N worker processes, longest first. ``--full`` runs the dear parts a study leaves
out by default (the cost study's order sweep and relaxation settings; the other studies
have none and ignore it).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

#: an index row: (report directory, cases, worst agreement, verdict)
IndexRow = tuple[Path, str, str, str]


@dataclass(frozen=True)
class Study:
    """A study of the registry.

    name : ``riser-verify reproduce NAME`` and the report directory ``reports/NAME``.
    units : the units of work (scene names, or ``(None,)`` for a single unit).
    run : ``run(unit, out_dir, note, full) -> str`` runs one unit into the study's directory
        ``out_dir`` and returns a line for the log; ``note`` is a sentence to put in a report
        whose timings were measured next to other work ('' when run alone); ``full``: the
        dear parts too (``--full``).
    index_row : ``index_row(report_dir) -> (cases, worst agreement, verdict) | None`` reads
        one report directory of the study back from its CSV files (None: not a report of
        this study).
    seconds : measured wall time [s] of each unit in ``reproduce all`` on 2 processes of a
        2-core machine, for the longest-first schedule (a unit not listed counts 15 s).
    full_seconds : the same with ``--full``, for the units it makes longer.
    stable : its CSV and JSON files are made machine-independent before they replace the
        old report (:mod:`verification.runtime.stable`: timings out, floats rounded);
        False for a study whose numbers are its timings (``cost``).
    """

    name: str
    units: tuple
    run: Callable[[str | None, Path, str, bool], str]
    index_row: Callable[[Path], tuple[str, str, str] | None]
    seconds: dict = field(default_factory=dict)
    full_seconds: dict = field(default_factory=dict)
    stable: bool = True

    def unit_seconds(self, unit, full: bool = False) -> float:
        """Expected wall time [s] of ``unit`` (``full``: with ``--full``)."""
        if full and unit in self.full_seconds:
            return self.full_seconds[unit]
        return self.seconds.get(unit, 15.0)

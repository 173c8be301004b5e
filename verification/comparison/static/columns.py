"""Further columns of a comparison beside the verdict (BVP against VFIFE), and the ANCF's,
judged with it.

A column is another solution of the same scene set beside the two methods: the analytic
method (:mod:`.analytic_column`) where it applies, and a peer code asked for on the
command line (a folder of ``verification/peers/``, e.g. MoorDyn), none of them part of the
verdict; and a further method of the suite, the ANCF (:mod:`.ancf_column`), whose rows
are judged (``ColumnResult.judged``). Every column is one instance of :class:`Column`, so the protocol, the report
and the command line treat them alike and never name one:

- ``name``: its ``agreement.csv`` columns ``NAME`` (its value of each verdict row) and
  ``NAME_rel_diff`` (its signed difference to the BVP over the row's basis), the folder
  of its files (``NAME/``) and the word the console and the report use;
- :meth:`Column.solve` runs it on a finished :class:`~.protocol.Comparison` and returns a
  :class:`ColumnResult`: its profile in the scene's arc length, its values of the verdict
  rows, its own rows against the BVP (with its own tolerances, or none), a note;
- :meth:`Column.markdown`, :meth:`Column.write` and :meth:`Column.console`: its section of
  ``report.md``, its files, its lines on the console.

A new peer is one folder of ``verification/peers/`` whose column implements this.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

from riser.results.profile import Profile


@dataclass(frozen=True)
class ColumnResult:
    """What one column gave on one comparison.

    column : the :class:`Column` that produced it (its report section and files).
    result : the column's own run (a :class:`~riser.results.result.SolveResult`, a peer's run
        record) or None when it does not apply; it has ``status``, ``message``, ``info``.
    profile : its static profile in the scene's arc length (None: no profile).
    values : verdict quantity -> (its value, its signed difference to the BVP over the
        row's basis); the agreement.csv columns ``NAME`` and ``NAME_rel_diff``.
    rows : its own rows against the BVP, for its report section and files
        (:class:`~verification.comparison.row.Row`: the BVP's value and its own, under its
        name).
    note : one paragraph: what it solved, or why it does not apply.
    ok : False when it was asked for and failed (the command exits 1); a column that does
        not apply to a scene is ok.
    judged : its rows are in the verdict (a method of the suite's: the ANCF), not only
        shown beside it (the analytic method, a peer).
    """

    column: "Column"
    result: Any = None
    profile: Profile | None = None
    values: dict = field(default_factory=dict)
    rows: list = field(default_factory=list)
    note: str = ""
    ok: bool = True
    judged: bool = False

    @property
    def name(self) -> str:
        return self.column.name

    def value(self, quantity: str) -> tuple[float | None, float | None]:
        """(value, relative difference to the BVP) of a verdict row, (None, None) if none."""
        return self.values.get(quantity, (None, None))


class Column(Protocol):
    """A further column of a comparison (see the module docstring)."""

    #: agreement.csv column names NAME and NAME_rel_diff; its files' folder
    name: str
    #: the plots' legend label
    label: str
    #: matplotlib style of its profile in the plots (e.g. ``{"ls": "-.", "lw": 1.0}``)
    style: dict
    #: which of the force plots (``tension``, ``moment``, ``shear``) show it
    forces: tuple[str, ...]
    #: the files it writes, relative to the comparison's folder (cleared before a run)
    files: tuple[str, ...]

    def solve(self, comp, folder: Path, progress=None) -> ColumnResult:
        """Run on the finished comparison ``comp`` (its files, if any, into ``folder``)."""

    def markdown(self, comp, res: ColumnResult, heading: str) -> list[str]:
        """Its section of report.md ([] for none)."""

    def write(self, comp, res: ColumnResult, out: Path) -> None:
        """Its files under the comparison's folder ``out``."""

    def console(self, res: ColumnResult) -> list[str]:
        """Its lines on the console after ``compare``."""

    def files_note(self) -> str:
        """What its agreement.csv columns hold, for the report's list of files."""


def verdict_values(rows: list, own_rows: list, name: str) -> dict:
    """The values a column gives the verdict rows ``rows``: quantity -> (its value, its
    rel_diff), for the quantities present in both. ``own_rows``: the rows of
    :func:`~.agreement.agreement` with the BVP's profile first and the column's second,
    its values under its ``name``."""
    mine = {r.quantity: r for r in own_rows}
    return {r.quantity: (mine[r.quantity].value(name), mine[r.quantity].rel_diff)
            for r in rows if r.quantity in mine}

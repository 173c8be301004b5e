"""One row of a comparison: a quantity, each method's value under the method's own name, the
difference, the tolerance with its reason, and a verdict. Every protocol builds these
(static, modal, dynamic, sea, the design rows of the static one, the peers' columns).

A row is frozen; :meth:`Row.replace` makes a changed copy. The difference is the second
method's value minus the first's (the first is the reference: the BVP in the static
protocol, the frequency domain in the dynamic ones), ``rel_diff`` the same over the basis
of the row's tolerance. The verdict has three states: :attr:`Verdict.PASS`,
:attr:`Verdict.FAIL` and :attr:`Verdict.NOT_JUDGED` (shown, with the reason in ``note``).

The files keep their columns: a row reads as a mapping of them (``row["bvp"]``,
``row["pass"]``: True, False or None; ``row["tolerance"]`` the bound's value), so that a
writer of ``agreement.csv`` picks the columns it names (:meth:`Row.record`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import Enum


class Verdict(str, Enum):
    """A row's verdict: within its tolerance, outside it, or shown and not judged."""

    PASS = "pass"
    FAIL = "fail"
    NOT_JUDGED = "not judged"

    @classmethod
    def of(cls, ok: bool | None) -> Verdict:
        """True -> PASS, False -> FAIL, None -> NOT_JUDGED."""
        return cls.NOT_JUDGED if ok is None else (cls.PASS if ok else cls.FAIL)

    @property
    def passed(self) -> bool | None:
        """The ``pass`` column: True, False, or None (empty) when not judged."""
        return None if self is Verdict.NOT_JUDGED else self is Verdict.PASS


@dataclass(frozen=True)
class Tolerance:
    """A row's bound and why it is what it is.

    value : the bound on |diff| in the row's unit (the static protocol's) or on |rel_diff|
        (the dynamic and sea protocols': ``relative``); None: no bound.
    basis : the magnitude a relative difference is taken over, in the row's unit (None
        where the protocol names it only: ``basis_label``).
    basis_label : what the basis is ("of the FD amplitude", "T_max").
    label : the bound as the report prints it ("0.1 % of T_max").
    reason : why it is what it is (measured, a paper's, the issue's bound).
    relative : ``value`` bounds ``rel_diff`` (else ``diff``).
    """

    value: float | None
    basis: float | None = None
    basis_label: str = ""
    label: str = ""
    reason: str = ""
    relative: bool = False


#: the mapping keys a row answers besides its methods' names (the files' columns)
_KEYS = ("quantity", "unit", "diff", "abs_diff", "rel_diff", "tolerance", "tol_label",
         "basis", "basis_label", "reason", "note", "at_s", "s", "pass", "reference")


@dataclass(frozen=True)
class Row(Mapping):
    """One row of a comparison (see the module docstring).

    quantity : the row's name (``hang_off_tension``, ``moment_amplitude``).
    values : method name -> its value (None: it has none, e.g. a row of a difference
        along s only); the first is the reference.
    unit : SI unit of the values and ``diff`` (``"-"`` for a count or a ratio).
    diff : signed difference, the second value minus the first (or given where the row
        is a difference along s), in ``unit``; None when one value is missing.
    rel_diff : ``diff`` over the tolerance's basis (None without a basis).
    tolerance : its :class:`Tolerance` (None: reported, not judged).
    verdict : :class:`Verdict`.
    note : why a row is not judged, or what the reader should know of it.
    at_s : the arc length [m] where a difference along s is largest (reference method's
        coordinate), else None.
    extra : further columns a protocol shows beside (the modal pair's ``plane``, ``mode``
        and ``mac``; MoorDyn's ``moordyn_vs_vfife``), read by name.
    """

    quantity: str
    values: Mapping[str, float | None]
    unit: str = ""
    diff: float | None = None
    rel_diff: float | None = None
    tolerance: Tolerance | None = None
    verdict: Verdict = Verdict.NOT_JUDGED
    note: str = ""
    at_s: float | None = None
    extra: Mapping[str, object] = field(default_factory=dict)

    # ---------------------------------------------------------------- by name
    @property
    def methods(self) -> tuple[str, ...]:
        """The methods' names, the reference first."""
        return tuple(self.values)

    def value(self, method: str) -> float | None:
        """The value of ``method`` (None when it has none)."""
        return self.values.get(method)

    @property
    def abs_diff(self) -> float | None:
        return None if self.diff is None else abs(self.diff)

    @property
    def passed(self) -> bool | None:
        """True, False, or None when not judged (the ``pass`` column)."""
        return self.verdict.passed

    def replace(self, **changes) -> Row:
        """A copy with ``changes`` (fields by name)."""
        return dataclasses.replace(self, **changes)

    def judged(self, ok: bool | None, note: str | None = None) -> Row:
        """A copy with the verdict of ``ok`` (None: not judged) and, if given, ``note``."""
        return self.replace(verdict=Verdict.of(ok), **({} if note is None else {"note": note}))

    # ---------------------------------------------------------------- as the files' columns
    def __getitem__(self, key: str):
        if key in self.values:
            return self.values[key]
        if key in self.extra:
            return self.extra[key]
        t = self.tolerance
        if key == "quantity":
            return self.quantity
        if key == "unit":
            return self.unit
        if key == "diff":
            return self.diff
        if key == "abs_diff":
            return self.abs_diff
        if key == "rel_diff":
            return self.rel_diff
        if key == "tolerance":
            return None if t is None else t.value
        if key == "tol_label":
            return "" if t is None else t.label
        if key == "basis":       # a number, or where the protocol names it only, its label
            return None if t is None else (t.basis if t.basis is not None
                                           else (t.basis_label or None))
        if key == "basis_label":
            return "" if t is None else t.basis_label
        if key == "reason":      # why not judged, else why the bound is what it is
            if (self.verdict is Verdict.NOT_JUDGED and self.note) or t is None:
                return self.note
            return t.reason
        if key == "reference":
            return self.methods[0]
        if key == "note":
            return self.note
        if key in ("at_s", "s"):
            return self.at_s
        if key == "pass":
            return self.passed
        raise KeyError(key)

    def __iter__(self):
        yield from self.values
        yield from self.extra
        yield from _KEYS

    def __len__(self) -> int:
        return len(self.values) + len(self.extra) + len(_KEYS)

    def record(self, columns) -> dict:
        """The row as a dict of ``columns`` (its files' columns; a column it has no value
        for is None)."""
        out = {}
        for c in columns:
            try:
                out[c] = self[c]
            except KeyError:
                out[c] = None
        return out

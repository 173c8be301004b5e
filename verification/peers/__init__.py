"""Peer codes: other programs that solve the same scene, shown as further columns of a
comparison (``compare --peer NAME``) and timed in the bench (``bench --peer NAME``), never
part of a verdict.

One folder per peer, found here by its folder: a package ``verification/peers/NAME/``
whose ``PEER`` is a :class:`Peer`. Delete the folder and only that peer is gone; add a
folder and the command line offers it. A peer's code package is an optional extra,
imported only inside the functions that run it, so listing the peers imports none.
Only the command line imports this package (``tests/test_layers.py``).
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass
from typing import Callable


@dataclass(frozen=True)
class Peer:
    """What a peer gives the command line.

    name : ``--peer NAME``, its agreement.csv columns and its files' folder.
    extra : the optional extra that installs its code (``pip install -e '.[EXTRA]'``).
    require : raises a one-line :class:`~riser.errors.SceneError` (exit 2) when its code
        is not installed, before anything runs.
    column : ``column(scene, segment_length)`` -> its
        :class:`~verification.comparison.static.columns.Column` for ``compare``, the options
        checked against the scene (``segment_length``: ``--peer-segment-length`` [m]).
    files : the files its column writes under a comparison's folder (cleared first).
    bench : ``bench(scene, log)`` -> the record of ``bench --peer`` on ``scene``;
        ``bench_lines(record)`` -> its console lines; written to ``bench_file``.
    add_commands : ``add_commands(subparsers)`` adds its own commands (None: none).
    dynamic : ``dynamic(comparison, folder, progress)`` -> (the Markdown section, the
        console lines) of its third opinion on a dynamic comparison (``compare --dynamics
        --peer``; None: it has none).
    """

    name: str
    extra: str
    require: Callable[[], None]
    column: Callable
    files: tuple[str, ...]
    bench: Callable
    bench_lines: Callable
    bench_file: str
    add_commands: Callable | None = None
    dynamic: Callable | None = None


def names() -> tuple[str, ...]:
    """The peers present: the packages in this folder (none is imported)."""
    return tuple(sorted(m.name for m in pkgutil.iter_modules(__path__) if m.ispkg))


def peer(name: str) -> Peer:
    """The peer ``name`` (its package's ``PEER``)."""
    return importlib.import_module(f"{__name__}.{name}").PEER

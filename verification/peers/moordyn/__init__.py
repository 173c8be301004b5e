"""MoorDyn-C v2 as a peer (the optional extra ``[moordyn]``, imported only inside the
functions that run it): :mod:`.deck` (a scene's deck, joints started from the BVP; the
segment length checked), :mod:`.run` (MoorDyn's statics of that deck, the current by
time-stepping, its state as a profile), :mod:`.waves` (a run in the scene's sea: the same
wave components, the hang-off moved by the vessel), :mod:`.column` (its column in
``compare --peer moordyn``: rows, its own tolerances, report section, files),
:mod:`.bench` (``bench --peer moordyn``) and :mod:`.commands` (``import-moordyn``,
``export-moordyn``)."""

from __future__ import annotations

from verification.peers import Peer

#: the files of its column under a comparison's folder (cleared before a run)
FILES = tuple(f"moordyn/{n}" for n in ("deck.dat", "deck.out", "current_profile.txt",
                                       "wave_frequencies.txt", "still.state",
                                       "moordyn.log", "agreement.csv", "profile.csv",
                                       "dynamic_agreement.csv"))

def _column(scene, segment_length: float = 10.0):
    from .column import MoorDynColumn
    from .deck import check_segment_length
    check_segment_length(segment_length, "--peer-segment-length", scene)
    return MoorDynColumn(segment_length=segment_length)


def _require() -> None:
    from .run import require
    require()


def _bench(scene, log=print) -> dict:
    from .bench import run
    return run(scene, log=log)


def _bench_lines(record: dict) -> list[str]:
    from .bench import summary_lines
    return summary_lines(record)


def _dynamic(dc, out, progress=None) -> tuple[str, list[str]]:
    from .dynamic_column import dynamic
    return dynamic(dc, out, progress)


def _add_commands(sub) -> None:
    from .commands import add_parsers
    add_parsers(sub)


PEER = Peer(name="moordyn", extra="moordyn", require=_require, column=_column,
            files=FILES, bench=_bench, bench_lines=_bench_lines,
            bench_file="moordyn.json", add_commands=_add_commands, dynamic=_dynamic)

"""``riser-verify bench``: the methods side by side (``bench.json``), or instead a peer
against the VFIFE (``bench --peer NAME``) or the sweep throughput (``bench --sweep``)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from verification import peers
from verification.runtime import outdir

from .common import progress_for


def cmd_bench(args) -> int:
    out = Path(args.out) if args.out else Path("reports") / "bench"
    if args.peer:
        return _bench_peer(args, out)
    if args.sweep:
        return _bench_sweep(args, out)
    if args.fatigue is not None:
        return _bench_fatigue(args, out)
    from verification.bench import methods
    outdir.clear(out, outdir.BENCH)
    record = methods.run(out)
    for line in methods.summary_lines(record):
        print(line)
    print(f"wrote {out}/bench.json")
    return 0


def _bench_peer(args, out: Path) -> int:
    """``bench --peer NAME``: OUT/NAME.json, beside bench.json (left alone)."""
    from verification.bench.methods import bench_scene
    peer = peers.peer(args.peer)
    peer.require()
    outdir.clear(out, (peer.bench_file,))
    out.mkdir(parents=True, exist_ok=True)
    with progress_for(args, f"bench --peer {peer.name}") as prog:
        record = peer.bench(bench_scene(), log=prog.log)
    (out / peer.bench_file).write_text(json.dumps(record, indent=2) + "\n")
    for line in peer.bench_lines(record):
        print(line)
    print(f"wrote {out}/{peer.bench_file}")
    return 0


def _bench_sweep(args, out: Path) -> int:
    """``bench --sweep [SWEEP]``: OUT/sweep.json."""
    from verification.sweeps.bench import measure, summary_lines
    from verification.sweeps.file import load_sweep
    outdir.clear(out, outdir.BENCH_SWEEP)
    sweep = load_sweep(args.sweep)
    with progress_for(args, "bench --sweep") as prog:
        record = measure(sweep, prog)
    failed = [f"{k}: {e['cases_failed']} case(s) failed" for k, e in record["engines"].items()
              if e.get("cases_failed")]
    return _write_engines(out, "sweep", record, summary_lines(record), failed)


def _bench_fatigue(args, out: Path) -> int:
    """``bench --fatigue [SCENE]``: OUT/fatigue.json."""
    from verification.catalog import resolve
    from verification.studies.design import fatigue
    from verification.studies.design.fatigue_bench import measure, summary_lines
    outdir.clear(out, outdir.BENCH_FATIGUE)
    scene = resolve(args.fatigue) if args.fatigue else None
    if scene is not None:
        fatigue.require_fatigue(scene)
    with progress_for(args, "bench --fatigue") as prog:
        record = measure(scene, prog)
    failed = [f"{k}: the damage along s differs from one local worker's"
              for k, e in record["engines"].items() if e.get("identical") is False]
    return _write_engines(out, "fatigue", record, summary_lines(record), failed)


def _write_engines(out: Path, name: str, record: dict, lines: list[str],
                   failed: list[str]) -> int:
    """``bench --NAME``'s record of its engines written to OUT/NAME.json, its summary
    printed; an engine that failed (its ``error``) or the ``failed`` found by the caller
    said on stderr, a line each: exit 1."""
    out.mkdir(parents=True, exist_ok=True)
    (out / f"{name}.json").write_text(json.dumps(record, indent=2) + "\n")
    for line in lines:
        print(line)
    print(f"wrote {out}/{name}.json")
    failed = [f"{k}: {e['error']}" for k, e in record["engines"].items()
              if "error" in e] + failed
    for f in failed:
        print(f"error: bench --{name}: {f}", file=sys.stderr)
    return 1 if failed else 0


def add_parsers(sub) -> None:
    s = sub.add_parser("bench", help="VFIFE kernel and solver benchmark")
    s.add_argument("--out", help="output directory (default reports/bench)")
    s.add_argument("--peer", choices=peers.names(), help="instead: VFIFE against a peer code "
                   "on the same riser and mesh (PEER.json; the peer's optional extra)")
    s.add_argument("--sweep", nargs="?", const="scr-envelope", help="instead: sweep "
                   "throughput (cases per minute) with 1 and 2 local workers and a local Dask "
                   "cluster of 2 workers (sweep.json; default: the built-in sweep scr-envelope)")
    s.add_argument("--fatigue", nargs="?", const="", metavar="SCENE", help="instead: "
                   "fatigue throughput (units per minute) with 1 and 2 local workers and a "
                   "local Dask cluster of 2 workers, every cell in the time domains, and "
                   "whether their damage along s is identical (fatigue.json; default: "
                   "scr-steel-fatigue's line on a cheap six-cell diagram)")
    s.set_defaults(func=cmd_bench)

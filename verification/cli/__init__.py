"""Command line: ``riser-verify <command>``. Parsing and printing only: each command calls
what it runs in the packages of ``verification/`` and prints what came back. Nothing
imports this package.

One module per command group: :mod:`.solve` (``scenes``, ``solve``), :mod:`.compare`
(``compare``, ``modes``), :mod:`.studies` (``reproduce``, ``stress``, ``cost``,
``regress``), :mod:`.bench` (``bench``), :mod:`.sweep` (``sweep``); a peer adds its own
commands (``verification/peers/NAME``). A command imports the solvers, pandas and
matplotlib only when it runs (inside its function): loading them all costs ~3 s, and
``scenes`` or a bad-input error need none.

Exit codes: 0 success; 1 a solver did not converge, a comparison failed, or an unexpected
error (one line each, the reason printed); 2 bad input (a scene error naming the file and
key, or a scene the method cannot represent, refused before solving); 130 interrupted.
"""

from __future__ import annotations

import argparse
import os
import sys

from riser.errors import SceneError, SolveFailed, UnsupportedSceneError
from verification import peers

from . import bench, compare, solve, studies, sweep
from .common import QUIET_HELP, err


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="riser-verify", description=(
        "Dual-method verification suite for deepwater risers (VFIFE and BVP)."))
    p.add_argument("-q", "--quiet", action="store_true", help=QUIET_HELP)
    sub = p.add_subparsers(dest="command", required=True)
    for group in (solve, studies, compare, bench, sweep):
        group.add_parsers(sub)
    for name in peers.names():
        add = peers.peer(name).add_commands
        if add is not None:
            add(sub)
    for name in ("solve", "compare", "modes", "stress", "cost", "reproduce", "bench", "sweep"):
        sub.choices[name].add_argument("-q", "--quiet", action="store_true",   # after it
                                       default=argparse.SUPPRESS, help=QUIET_HELP)
    return p


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except (SceneError, UnsupportedSceneError) as exc:
        err(str(exc))
        return 2
    except SolveFailed as exc:
        err(f"{exc} ({exc.status.value})")
        return 1
    except KeyboardInterrupt:
        err("interrupted")
        return 130
    except BrokenPipeError:        # the reader went away (`riser-verify scenes | head`)
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())   # no flush error
        return 141                 # 128 + SIGPIPE, as a shell pipeline reports it
    except Exception as exc:       # noqa: BLE001 - one line, never a traceback
        err(f"unexpected {type(exc).__name__}: {exc} (please report it with the command)")
        return 1

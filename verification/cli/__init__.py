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
key, an option out of its range or not understood, or a scene the method cannot
represent, refused before solving); 130 interrupted (one line, whatever the moment: while
the program starts, runs or exits; :mod:`verification.runtime.interrupts`).
"""

from __future__ import annotations

import sys

try:                             # Ctrl-C while the program loads: one line, 130
    from verification.runtime.interrupts import (arm_swallowed_interrupts,
                                                 caused_by_interrupt, count_interrupts,
                                                 end_interrupted, exit_quietly_on_interrupt,
                                                 interrupts_seen, keep_swallowed_interrupts,
                                                 reraise_interrupt)
    count_interrupts()           # from here on, no Ctrl-C is lost (see main), nor one
    keep_swallowed_interrupts()  # that lands in a finaliser or a callback of the imports
except KeyboardInterrupt:        # (a module of the standard library's imports only)
    print("error: interrupted", file=sys.stderr)
    raise SystemExit(130) from None
try:
    import argparse
    import os

    from riser.errors import SceneError, SolveFailed, UnsupportedSceneError, one_line
    from verification import peers

    from . import bench, compare, design, orcaflex, solve, studies, sweep
    from .common import QUIET_HELP, Parser, err
except BaseException as exc:     # noqa: BLE001 - a Ctrl-C, also one that Python wrapped:
    # a KeyboardInterrupt in a descriptor's __set_name__ while a class is created (a
    # dataclass field) comes out as "RuntimeError: Error calling __set_name__", the
    # interrupt its cause (measured once in 80 interrupts of the imports)
    if not caused_by_interrupt(exc):
        raise
    print("error: interrupted", file=sys.stderr)
    end_interrupted()            # its threads and atexit callbacks run, no finalisation


def build_parser() -> argparse.ArgumentParser:
    p = Parser(prog="riser-verify", description=(
        "Dual-method verification suite for deepwater risers (VFIFE and BVP)."))
    p.add_argument("-q", "--quiet", action="store_true", help=QUIET_HELP)
    sub = p.add_subparsers(dest="command", required=True)
    for group in (solve, studies, compare, design, bench, sweep, orcaflex):
        group.add_parsers(sub)
    for name in peers.names():
        add = peers.peer(name).add_commands
        if add is not None:
            add(sub)
    for name in ("solve", "compare", "modes", "stress", "cost", "reproduce", "bench", "sweep",
                 "fatigue"):
        sub.choices[name].add_argument("-q", "--quiet", action="store_true",   # after it
                                       default=argparse.SUPPRESS, help=QUIET_HELP)
    return p


def main(argv: list[str] | None = None) -> int:
    """Run ``riser-verify ARGV`` (None: the program's own arguments, and then a Ctrl-C
    while the interpreter exits ends it at once with 130, no traceback); the exit code.
    A Ctrl-C that a library caught on its way (the command then ran on to its end) still
    ends in 130, said in the line (:func:`~verification.runtime.interrupts.count_interrupts`:
    counted from the program's imports on)."""
    seen = 0 if argv is None else interrupts_seen()
    if argv is None:                     # the program: a Ctrl-C a library swallowed is
        arm_swallowed_interrupts()       # raised at the run's next progress report
    try:
        keep_swallowed_interrupts()
        code = _run(argv, seen)
    except KeyboardInterrupt as exc:     # the message says what was kept (sweep)
        if argv is None:                 # a second Ctrl-C now: 130 at once, no traceback
            exit_quietly_on_interrupt(True)
        err(str(exc) or "interrupted")
        code = 130
    else:
        if code != 130 and interrupts_seen() > seen:
            err(f"interrupted: the Ctrl-C was caught by a library on its way, and the command "
                f"ran on to its end (exit {code} without the Ctrl-C)")
            code = 130
        if argv is None:
            exit_quietly_on_interrupt(code == 130)
    if argv is None and code == 130:     # the program, interrupted: its threads and atexit
        end_interrupted()                # callbacks run, the interpreter's teardown skipped
    return code


def _run(argv: list[str] | None, seen: int) -> int:
    """The command's exit code; ``seen``: the Ctrl-Cs counted before it began (an error
    after a later one is that Ctrl-C's doing: one line, 130)."""
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as exc:            # --help (0), or the parser's one-line error (2)
        return exc.code if isinstance(exc.code, int) else 2
    try:
        return args.func(args)
    except (SceneError, UnsupportedSceneError, SolveFailed) as exc:
        if interrupts_seen() > seen:     # a swallowed Ctrl-C came first: its line alone
            return _interrupted(exc)
        if isinstance(exc, SolveFailed):
            err(f"{exc} ({exc.status.value})")
            return 1
        err(str(exc))
        return 2
    except BrokenPipeError:        # the reader went away (`riser-verify scenes | head`)
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())   # no flush error
        return 141                 # 128 + SIGPIPE, as a shell pipeline reports it
    except Exception as exc:       # noqa: BLE001 - one line, never a traceback
        reraise_interrupt(exc)     # Ctrl-C inside a Numba function (a SystemError): 130
        if interrupts_seen() > seen:   # a Ctrl-C a library turned into its own error (an
            return _interrupted(exc)   # extension module's import: an ImportError)
        err(f"unexpected {type(exc).__name__}: {exc} (please report it with the command)")
        return 1


def _interrupted(exc: Exception) -> int:
    """One line for an error that followed a Ctrl-C a library caught (the interrupt's doing,
    whatever the error says); 130."""
    err(f"interrupted: the Ctrl-C was caught by a library on its way, and the command then "
        f"failed ({type(exc).__name__}: {one_line(str(exc))[:200]})")
    return 130

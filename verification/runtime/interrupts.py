"""Ctrl-C (SIGINT) at any moment of a run: one line and exit 130, never a traceback.

An interrupt is a ``KeyboardInterrupt`` in the main thread, which the command line turns
into its one line. What printed tracebacks before was what runs *beside* that handler:

- worker processes started while Ctrl-C went to the terminal's whole process group: a
  spawned worker imports the project before its initializer ignores SIGINT, and printed
  its own traceback when it came then. :func:`sigint_blocked` is held while the pool
  starts its workers: a signal mask is inherited by the child across fork and exec (what
  ``multiprocessing.resource_tracker`` does for its own process), so a worker is born
  deaf to Ctrl-C and stays so (:func:`worker_ignores_sigint`);
- an interrupt in the middle of starting or stopping the pool (a spawn's pickled data cut
  in half, workers left running): :func:`held_interrupts` holds a Ctrl-C back until
  the start or the clean-up is complete, then raises it;
- a Ctrl-C while a Numba function runs: Numba's dispatcher turns the
  ``KeyboardInterrupt`` into ``SystemError: CPUDispatcher(...) returned a result with an
  exception set`` (the interrupt its ``__context__``), which a handler of ``Exception``
  took for an unexpected error (exit 1, measured in 1 of 10 interrupts of a dynamic
  solve): :func:`caused_by_interrupt` finds the interrupt in an exception's chain, and
  :func:`reraise_interrupt` raises it as the ``KeyboardInterrupt`` it was;
- a Ctrl-C while the interpreter exits (joining the pool's threads in ``atexit``):
  :func:`exit_quietly_on_interrupt`, installed by the command line once a command has
  ended; and for the last instants of the exit, when Python has put the default
  disposition back (the process died of SIGINT with no line, measured once in 22
  interrupts), SIGINT is ignored by an ``atexit`` callback registered when this module is
  imported, so that it runs after those of multiprocessing and distributed (imported
  later: ``atexit`` runs the last registered first).
- the interpreter's finalisation after an interrupted import: :func:`end_interrupted`
  ends the program without it, once the threads and ``atexit`` callbacks have run.

Imports nothing of ``verification``.
"""

from __future__ import annotations

import atexit
import contextlib
import os
import signal
import sys
import threading
from typing import NoReturn

_PROGRAM = False                 # exit_quietly_on_interrupt was called: the program exits
_SEEN = 0                        # Ctrl-C received by this process (count_interrupts)


def _main_thread() -> bool:
    return threading.current_thread() is threading.main_thread()


@contextlib.contextmanager
def held_interrupts():
    """Ctrl-C is noted, not raised, in the block; at its end handed to the handler before
    it (``KeyboardInterrupt`` for Python's default one; an enclosing hold notes it in its
    turn). Outside the main thread: nothing."""
    if not _main_thread():
        yield
        return
    got: list[int] = []

    def note(signum, frame):
        global _SEEN
        _SEEN += 1
        got.append(signum)
    previous = signal.signal(signal.SIGINT, note)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
        if got and previous is signal.default_int_handler:
            raise KeyboardInterrupt
        if got and callable(previous):           # an enclosing hold (or the exit's
            previous(signal.SIGINT, None)        # handler) is told: never dropped


def _counting_handler(signum, frame):
    """Python's default SIGINT handler (``KeyboardInterrupt``), counting first."""
    global _SEEN
    _SEEN += 1
    raise KeyboardInterrupt


def count_interrupts() -> None:
    """From now on every Ctrl-C is counted (:func:`interrupts_seen`) before it is raised,
    so that one caught on its way by a library is not lost: a ``KeyboardInterrupt``
    wrapped in another exception (a class being created: ``RuntimeError: Error calling
    __set_name__``) meets the ``except Exception`` of a library's optional import or
    fallback, and the command ran on to exit 0 as if no Ctrl-C had come (measured once
    in 50 interrupts of ``reproduce``). Only where Python's own handler is in place (not
    under ``nohup``, which ignores SIGINT, nor under a caller's handler); main thread."""
    if _main_thread() and signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        signal.signal(signal.SIGINT, _counting_handler)


def interrupts_seen() -> int:
    """How many Ctrl-C this process has received since :func:`count_interrupts`."""
    return _SEEN


_SURFACED = 0                    # _SEEN when raise_swallowed_interrupt last raised
_ARMED = False                   # arm_swallowed_interrupts was called: the program runs


def arm_swallowed_interrupts() -> None:
    """From now on :func:`raise_swallowed_interrupt` raises: called by the program
    (``riser-verify``) itself, whose Ctrl-C are all its own. Not in a process that calls
    the command line or the studies in-process (a test, a notebook): its earlier Ctrl-C,
    handled or not, are not a run's."""
    global _ARMED
    _ARMED = True


def raise_swallowed_interrupt() -> None:
    """In the main thread: raise ``KeyboardInterrupt`` when a Ctrl-C was counted
    (:func:`count_interrupts`) since the last one raised here. Called where a long run
    reports its progress (:class:`~verification.runtime.progress.Progress`): a solver
    reporting progress means the run goes on, so a Ctrl-C counted before was caught by a
    library on its way (an ``except Exception`` around a wrapped interrupt) and is raised
    again now, ending the run in 130 within one progress report instead of at its end (a
    fatigue run with both time domains went on for minutes: the 120 s of the interrupt
    test passed, once in 50 interrupts in CI). Each Ctrl-C is raised here at most once;
    only in the program (:func:`arm_swallowed_interrupts`)."""
    global _SURFACED
    if _ARMED and _SEEN > _SURFACED and _main_thread():
        _SURFACED = _SEEN
        raise KeyboardInterrupt


@contextlib.contextmanager
def sigint_blocked():
    """SIGINT blocked in this thread for the block: the processes it starts inherit the
    mask. A Ctrl-C meanwhile stays pending and is delivered at the end.

    multiprocessing's resource tracker is started first: starting it unblocks SIGINT in
    the calling thread when it has started its own process (``ensure_running`` in
    ``multiprocessing/resource_tracker.py``), which inside the block would undo it before
    the first worker is spawned (measured: the workers' SigBlk was 0 without this)."""
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    with contextlib.suppress(Exception):          # POSIX; idempotent once running
        from multiprocessing import resource_tracker
        resource_tracker.ensure_running()
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def worker_ignores_sigint() -> None:
    """In a worker process: SIGINT ignored (the submitting process handles Ctrl-C and
    stops the workers), then unblocked (a pending one is dropped)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})


def caused_by_interrupt(exc: BaseException | None) -> bool:
    """True when ``exc`` is, or was raised while handling or because of, a
    ``KeyboardInterrupt`` (its ``__cause__`` / ``__context__`` chain; each exception
    visited once)."""
    seen = set()
    while exc is not None and id(exc) not in seen:
        if isinstance(exc, KeyboardInterrupt):
            return True
        seen.add(id(exc))
        exc = exc.__cause__ or exc.__context__
    return False


def reraise_interrupt(exc: BaseException) -> None:
    """Raise ``KeyboardInterrupt`` (no chained traceback) when ``exc`` came of one
    (:func:`caused_by_interrupt`); otherwise return. Called first in a handler of
    ``Exception`` that would record the error and go on."""
    if caused_by_interrupt(exc):
        raise KeyboardInterrupt from None


#: seconds after a swallowed Ctrl-C that it is raised again (:func:`keep_swallowed_interrupts`)
RERAISE_DELAY_S = 0.01


def keep_swallowed_interrupts() -> None:
    """A Ctrl-C that lands in code whose exceptions Python cannot raise (a ``__del__``,
    a weakref or garbage-collector callback: "Exception ignored in ... KeyboardInterrupt")
    is raised again in the main thread a moment later (:func:`_thread.interrupt_main`
    from a timer thread: the signal's own path) instead of being printed and lost: the
    run ends in exit 130, not in exit 0 after finishing as if nothing came (measured
    once in 50 interrupts of a dynamic solve on a loaded machine, and a fatigue run that
    went on past 120 s). Installed by the command line before its imports: a Ctrl-C in
    importlib's module-lock callback while ``reproduce`` loaded was printed above the
    interrupt's line (2 of 50 interrupts in CI). Other unraisable exceptions go to the
    hook in place before. Idempotent."""
    previous = sys.unraisablehook
    if getattr(previous, "_keeps_interrupts", False):
        return

    def hook(unraisable):
        if unraisable.exc_type is not None and issubclass(unraisable.exc_type,
                                                          KeyboardInterrupt):
            # raised from here it would be ignored again: a thread raises it a moment
            # later, once the main thread is back in code that can raise (should it land
            # in such code again, this hook comes again)
            import _thread
            threading.Timer(RERAISE_DELAY_S, _thread.interrupt_main).start()
            return
        previous(unraisable)
    hook._keeps_interrupts = True
    sys.unraisablehook = hook


def exit_quietly_on_interrupt(said: bool) -> None:
    """From now on (a command has ended; the interpreter exits), a Ctrl-C ends the
    process at once with exit 130, printing ``error: interrupted`` unless ``said`` (the
    line was printed already). Only in the main thread of the program itself."""
    global _PROGRAM
    if not _main_thread():
        return
    _PROGRAM = True
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()

    def handler(signum, frame):
        if not said:
            with contextlib.suppress(Exception):
                sys.stdout.flush()
            with contextlib.suppress(Exception):
                os.write(2, b"error: interrupted\n")
        os._exit(130)
    signal.signal(signal.SIGINT, handler)


def end_interrupted() -> NoReturn:
    """End the program, interrupted, once its line is printed: its threads joined and its
    ``atexit`` callbacks run (the pool's workers stopped, multiprocessing's resources
    released), then exit 130 at once (``os._exit``), skipping the interpreter's
    finalisation. An import cut by a Ctrl-C can leave an extension module half made, and
    its teardown then killed the process (SIGABRT, "Fatal Python error: PyThreadState_Get:
    the function must be called with the GIL held", Python runtime state: finalizing),
    after the interrupt's line: measured once in 50 interrupts of ``fatigue`` in CI. What
    finalisation does beyond those callbacks (freeing modules and objects) the
    operating system does at exit. A Ctrl-C from here on is ignored: the run has ended."""
    with contextlib.suppress(Exception):
        signal.signal(signal.SIGINT, signal.SIG_IGN)
    shutdown = getattr(threading, "_shutdown", None)     # what the interpreter's exit runs
    if shutdown is not None and _main_thread():          # first: non-daemon threads joined,
        with contextlib.suppress(Exception):             # the pool's manager thread among
            shutdown()                                   # them (concurrent.futures)
    with contextlib.suppress(Exception):
        atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()
    os._exit(130)


@atexit.register
def _ignore_at_the_very_end() -> None:
    """The program's last ``atexit`` callback: SIGINT ignored from here to the end (the
    interpreter would reset a Python handler to the default, and a Ctrl-C now would
    kill the process without a word). In-process callers of ``main`` (tests) keep theirs."""
    if _PROGRAM and _main_thread():
        with contextlib.suppress(Exception):
            signal.signal(signal.SIGINT, signal.SIG_IGN)

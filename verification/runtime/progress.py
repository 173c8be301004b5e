"""The progress display of long command-line runs, and the callback protocol it serves.

The solvers know nothing of terminals: they call ``progress(message)`` and, where they
know the fraction of the run done, ``progress(message, fraction=f)`` (f in [0, 1], e.g.
the VFIFE dynamics at t / duration). :class:`Progress` is such a callable. On a terminal
it keeps one status line on stderr, redrawn in place (``\\r``) at most ~5 times a second:

    solve hard-long-dynamic [vfife]: dynamics t = 150.0 / 600 s [#####...............]  25%  0:28, ETA 1:24
    - compare wang2014-baseline: statics 1 m mesh (3/3): 20000 steps, residual 0.132 x element weight  0:02

(a bar and an ETA where the fraction is known, else a spinner and the elapsed time). A
ticker thread keeps the elapsed time moving while a call without a callback runs (the
BVP's ``solve_bvp``). It writes nothing when stderr is not a terminal or when ``quiet``;
normal output goes through :meth:`Progress.log`, which clears the line first.

Also here (with :func:`riser.callbacks.with_fraction`, re-exported):
:func:`scoped` (one part of a longer job), :class:`UnitTracker` (``k/N units`` of
``reproduce``, weighted by the studies' declared seconds) and the forwarding of the
output of worker processes and of in-process studies through :meth:`Progress.log`.
"""

from __future__ import annotations

import contextlib
import os
import queue as queue_mod
import shutil
import sys
import threading
import time

from riser.callbacks import with_fraction

from .interrupts import raise_swallowed_interrupt

#: seconds between two redraws (~5 per second)
INTERVAL = 0.2
_SPIN = "-\\|/"


def scoped(progress, prefix: str, lo: float = 0.0, hi: float | None = None):
    """A callback for one part of a longer job: messages prefixed with ``prefix``, the
    part's fractions mapped to [lo, hi] of the whole (a message without one, or with
    ``hi`` None, reports ``lo``). None when ``progress`` is None."""
    send = with_fraction(progress)
    if send is None:
        return None

    def report(message, fraction=None):
        f = lo if fraction is None or hi is None else lo + (hi - lo) * fraction
        send(f"{prefix}: {message}", fraction=f)
    return report


def clock_text(seconds: float) -> str:
    """``m:ss`` (``h:mm:ss`` from an hour)."""
    s = int(max(seconds, 0.0) + 0.5)
    h, rest = divmod(s, 3600)
    return f"{h}:{rest // 60:02d}:{rest % 60:02d}" if h else f"{rest // 60}:{rest % 60:02d}"


def _width(stream) -> int:
    """Columns of the line: ``$COLUMNS``, else the terminal ``stream`` is, else stdout's,
    else 100."""
    env = os.environ.get("COLUMNS", "")
    if env.isdigit() and int(env) > 0:
        return int(env)
    try:
        cols = os.get_terminal_size(stream.fileno()).columns
    except (AttributeError, ValueError, OSError):
        cols = 0
    return cols if cols > 0 else shutil.get_terminal_size((100, 24)).columns


def _isatty(stream) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


class Progress:
    """A status line on a terminal, usable as the callback ``progress(message, fraction=None)``.

    label : what runs (``solve X [vfife]``), shown before each message.
    stream : where the line goes (default stderr); nothing is written unless it is a
        terminal and not ``quiet``.
    interval : seconds between two redraws; clock : the time source (tests).
    As a context manager it starts the ticker (redraws while nothing calls back) and
    clears the line at the end, also on an error."""

    def __init__(self, label: str = "", message: str = "", *, stream=None,
                 quiet: bool = False, interval: float = INTERVAL, clock=time.monotonic):
        self.label, self.message = label, message
        self.stream = stream if stream is not None else sys.stderr
        self.out = sys.stdout            # where log() prints (captured now: see capture)
        self.enabled = not quiet and _isatty(self.stream)
        self.interval, self.clock = interval, clock
        self.t0 = clock()
        self.fraction = None
        self._anchor = None              # (time, fraction) the ETA is measured from
        self._last = -float("inf")       # time of the last redraw
        self._shown = 0                  # characters of the line on the screen
        self._spin = 0
        self._lock = threading.RLock()
        self._stop = threading.Event()
        self._thread = None
        self._queues: list = []          # worker output to forward (worker_options)
        self.source = None               # optional () -> (message, fraction), polled

    # -- the callback ---------------------------------------------------------------
    def __call__(self, message: str, fraction: float | None = None) -> None:
        """Set the message (and the fraction done, when known); redraw if due. A Ctrl-C
        that a library swallowed on its way is raised here (the run goes on: the
        solver reports), :func:`~verification.runtime.interrupts.raise_swallowed_interrupt`."""
        raise_swallowed_interrupt()
        with self._lock:
            self._update(message, fraction)
            final = fraction is not None and fraction >= 1.0
            if final or self.clock() - self._last >= self.interval:
                self._draw()

    def _update(self, message, fraction) -> None:
        now = self.clock()
        self.message = message
        if fraction is not None:
            fraction = min(max(float(fraction), 0.0), 1.0)
            if self.fraction is None or fraction < self.fraction:
                self._anchor = (now, fraction)      # a new phase: the ETA starts here
        self.fraction = fraction

    def eta(self) -> float | None:
        """Seconds still to go, from the rate of the fraction since the current phase's
        first fraction (a fraction lower than the last starts a phase); None: not known."""
        if self.fraction is None or self._anchor is None:
            return None
        ta, fa = self._anchor
        if self.fraction <= fa:
            return None
        return (self.clock() - ta) * (1.0 - self.fraction) / (self.fraction - fa)

    def line(self, width: int = 100) -> str:
        """The status line, at most ``width`` characters."""
        elapsed = clock_text(self.clock() - self.t0)
        head = f"{self.label}: {self.message}" if self.label and self.message else \
            (self.label or self.message)
        if self.fraction is None:
            head = f"{_SPIN[self._spin % len(_SPIN)]} {head}"
            tail = f"  {elapsed}"
        else:
            n = 20
            bar = "#" * int(n * self.fraction) + "." * (n - int(n * self.fraction))
            eta = self.eta()
            tail = (f" [{bar}] {100 * self.fraction:3.0f}%  {elapsed}"
                    + (f", ETA {clock_text(eta)}" if eta is not None else ""))
        room = width - len(tail)
        if len(head) > room:
            head = head[:max(room - 3, 0)] + "..."
        return head + tail

    # -- drawing ----------------------------------------------------------------------
    def _draw(self) -> None:
        if not self.enabled:
            return
        width = _width(self.stream) - 1
        text = self.line(max(width, 20))
        self._spin += 1
        self.stream.write("\r" + text.ljust(self._shown))
        self.stream.flush()
        self._shown = len(text)
        self._last = self.clock()

    def clear(self) -> None:
        """Take the line off the screen (the next call or tick draws it again)."""
        with self._lock:
            if self.enabled and self._shown:
                self.stream.write("\r" + " " * self._shown + "\r")
                self.stream.flush()
            self._shown = 0
            self._last = -float("inf")

    def log(self, line: str, err: bool = False) -> None:
        """Print ``line`` (to stdout, or stderr with ``err``) above the status line;
        printed whether or not the display is on. Usable as a study's ``log=``."""
        with self._lock:
            self.clear()
            out = self.stream if err else self.out
            print(line, file=out, flush=True)

    def tick(self) -> None:
        """Redraw if due: poll :attr:`source`, forward worker output."""
        with self._lock:
            self._forward()
            if self.source is not None:
                self._update(*self.source())
            if self.clock() - self._last >= self.interval:
                self._draw()

    def _run(self) -> None:
        while not self._stop.wait(self.interval / 2):
            self.tick()

    def __enter__(self) -> "Progress":
        if self.enabled:
            self._thread = threading.Thread(target=self._run, name="progress", daemon=True)
            self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def close(self) -> None:
        """Stop the ticker, forward what workers still said, clear the line."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
            self._thread = None
        with self._lock:
            self._forward()
            self.clear()

    # -- output of other writers while the line is shown ---------------------------------
    def capture(self):
        """Context manager: this process's stdout and stderr printed through
        :meth:`log` while the display is on (a study's own prints); else nothing."""
        if not self.enabled:
            return contextlib.nullcontext()
        stack = contextlib.ExitStack()
        stack.enter_context(contextlib.redirect_stdout(_Lines(lambda s: self.log(s))))
        stack.enter_context(contextlib.redirect_stderr(_Lines(lambda s: self.log(s, True))))
        return stack

    def worker_options(self, ctx) -> dict:
        """Keyword arguments of a ``ProcessPoolExecutor`` (multiprocessing context
        ``ctx``) whose workers send their stdout and stderr lines here, to be printed
        through :meth:`log`; {} when the display is off."""
        if not self.enabled:
            return {}
        q = ctx.Queue()
        self._queues.append(q)
        return {"initializer": forward_output, "initargs": (q,)}

    def _forward(self) -> None:
        for q in self._queues:
            while True:
                try:
                    err, line = q.get_nowait()
                except (queue_mod.Empty, OSError, ValueError):
                    break
                self.log(line, err)


class _Lines:
    """A text stream handing each complete line to ``emit``."""

    def __init__(self, emit):
        self.emit, self.buf = emit, ""

    def write(self, s: str) -> int:
        self.buf += s
        while "\n" in self.buf:
            line, self.buf = self.buf.split("\n", 1)
            self.emit(line)
        return len(s)

    def flush(self) -> None:
        pass

    def isatty(self) -> bool:
        return False


def forward_output(q) -> None:
    """Worker-process initializer: its stdout and stderr lines go to the queue ``q``
    as (is_stderr, line)."""
    sys.stdout = _Lines(lambda s: q.put((False, s)))
    sys.stderr = _Lines(lambda s: q.put((True, s)))


class RunCounter:
    """``k/N runs (what)`` of a sequence of runs of predicted relative costs ``weights``,
    told to ``progress(message, fraction=f)`` with f the share of the predicted cost done
    (a :class:`Progress` draws the bar and the ETA from it)."""

    def __init__(self, weights: list[float], progress, what: str = "runs"):
        self.weights = list(weights)
        self.send = with_fraction(progress)
        self.what = what
        self.done = 0

    @property
    def total(self) -> int:
        return len(self.weights)

    def plan(self, weights: list[float]) -> None:
        """Replace the runs still to come by runs of these predicted costs."""
        self.weights = self.weights[:self.done] + list(weights)

    def step(self, what: str) -> None:
        """One more run done (``what``: its one-line description)."""
        self.done += 1
        wd, wr = sum(self.weights[:self.done]), sum(self.weights[self.done:])
        if self.send is not None:
            self.send(f"{self.done}/{self.total} {self.what} ({what})",
                      fraction=wd / (wd + wr) if wd + wr > 0 else None)


class UnitTracker:
    """``k/N units`` of a run of independent units on ``jobs`` processes, and the fraction
    done weighted by each unit's expected ``seconds``: a finished unit counts its seconds,
    a running one the time it has run (up to 90 % of its seconds). Units start in the
    given order as processes free up. Set as a :class:`Progress`'s ``source``. With
    ``known`` False the seconds are placeholders: no fraction (a spinner, no ETA) until
    :meth:`rescale` gives the measured time of a unit."""

    def __init__(self, seconds: list[float], jobs: int, what: str = "units", clock=None,
                 known: bool = True):
        self.known = known               # False: no fraction (no bar, no ETA) until rescale
        self.seconds = [max(float(s), 1e-9) for s in seconds]
        self.total = sum(self.seconds)
        self.jobs, self.what = max(1, jobs), what
        self.clock = clock or time.monotonic
        now = self.clock()
        self.start = [now if i < self.jobs else None for i in range(len(seconds))]
        self.finished: set[int] = set()

    def rescale(self, seconds: float, weights: list[float] | None = None) -> None:
        """Every unit is now expected to take ``seconds`` (a measured time replacing the
        declared ones: the sweep's first case), or ``seconds`` times its relative weight
        (``weights``), so that the fraction done, and the ETA drawn from it, follow the
        real pace."""
        self.seconds = ([max(float(seconds), 1e-9)] * len(self.seconds) if weights is None
                        else [max(float(seconds) * w, 1e-9) for w in weights])
        self.total = sum(self.seconds)
        self.known = True

    def done(self, i: int) -> None:
        """Unit ``i`` finished: the next unit not yet started starts now."""
        self.finished.add(i)
        nxt = next((j for j, t in enumerate(self.start) if t is None), None)
        if nxt is not None:
            self.start[nxt] = self.clock()

    def __call__(self) -> tuple[str, float]:
        now = self.clock()
        work = sum(self.seconds[i] for i in self.finished)
        work += sum(min(now - t, 0.9 * s) for i, (t, s) in enumerate(zip(self.start, self.seconds))
                    if t is not None and i not in self.finished)
        return (f"{len(self.finished)}/{len(self.seconds)} {self.what} done",
                min(work / self.total, 1.0) if self.total > 0 and self.known else None)

"""The engine that runs independent units of work: ``sweep`` cases and ``reproduce`` units.

Three backends behind one call, :meth:`Engine.map`:

- ``jobs = 1``: in this process, one unit after another (output captured above the
  progress line);
- ``jobs = N > 1``: a pool of N local worker processes (spawned; one BLAS thread each,
  :data:`WORKER_ENV`, the workers being the parallelism);
- ``scheduler = "tcp://host:port"``: an existing Dask distributed cluster (the optional
  extra ``[cluster]``); the units run on its workers, wherever they are, so a unit must
  take and return plain picklable values and write no file itself when its results are
  to come back (the sweep's cases do so).

Units are independent: :meth:`Engine.map` yields ``(i, result)`` as each finishes, in
whatever order; a unit that raised yields ``(i, exception)`` and the others go on.
:meth:`Engine.open` probes the scheduler's address (a bounded comm handshake,
:mod:`.scheduler_probe`) and connects before anything is written, so that an address that
does not answer (exit 1), or answers but is not a Dask scheduler or is malformed (exit 2),
fails with :class:`EngineError` in one line within seconds and leaves no output behind.
An interrupt (Ctrl-C) at any moment of a local pool stops its workers and is raised as one
``KeyboardInterrupt`` (:mod:`.interrupts`).
"""

from __future__ import annotations

import concurrent.futures as cf
import contextlib
import multiprocessing as mp
import os
import time
import uuid
from dataclasses import dataclass, field

from .interrupts import (held_interrupts, reraise_interrupt, sigint_blocked,
                         worker_ignores_sigint)
from .scheduler_probe import PROBE_TIMEOUT_S, ProbeFailed, probe

#: environment of local worker processes, unless already set: one BLAS thread each (the
#: OpenBLAS threads of ``solve_bvp`` compete with the other worker: ``reproduce all`` on 2
#: cores took 317 s and 536 s of CPU with them, 308 s and 513 s without, with the same
#: numbers). Dask workers are started by their owner: docs/sweeps.md says to set it there.
WORKER_ENV = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}
#: seconds to wait for a Dask scheduler to answer (the client, and its first worker)
CONNECT_TIMEOUT_S = 10.0
#: seconds a local worker is given to end after SIGTERM when a run is interrupted
STOP_TIMEOUT_S = 5.0


class EngineError(RuntimeError):
    """The engine cannot run: one line, and its exit code: 1 for a scheduler that does not
    answer, no worker, the optional package missing; 2 (bad input) for an address that is
    malformed or is not a Dask scheduler's."""

    def __init__(self, message: str, exit_code: int = 1):
        super().__init__(message)
        self.exit_code = exit_code


def _address(address: str, distributed) -> tuple[str, str | None, int | None]:
    """(scheme, host, port) of a scheduler address; :class:`EngineError` (exit 2) naming
    ``--scheduler`` and the form when it is not one."""
    form = "tcp://HOST:PORT, as `dask scheduler` prints it, PORT 1 to 65535"
    if not address.startswith(("tcp://", "tls://", "inproc://", "ws://", "wss://")):
        raise EngineError(f"--scheduler: {address!r} is not a scheduler address ({form})",
                          exit_code=2)
    scheme, loc = distributed.comm.parse_address(address)
    if scheme == "inproc":
        return scheme, None, None
    try:
        host, port = distributed.comm.parse_host_port(loc)
    except ValueError as exc:
        raise EngineError(f"--scheduler: {address!r} is not a scheduler address ({exc}; "
                          f"{form})", exit_code=2) from None
    if not isinstance(port, int) or not 1 <= port <= 65535 or not host:
        raise EngineError(f"--scheduler: {address!r} is not a scheduler address ({form})",
                          exit_code=2)
    return scheme, host, port


def require_dask():
    """The ``distributed`` module, or :class:`EngineError` saying how to install it."""
    try:
        import distributed
    except ImportError:
        raise EngineError("--scheduler needs the optional extra [cluster] (dask.distributed): "
                          "pip install -e \".[cluster]\"") from None
    return distributed


def _worker_init(initializer, initargs) -> None:
    """A local worker ignores Ctrl-C (the submitting process handles it and stops the
    workers), then runs the progress display's initializer (output forwarding)."""
    worker_ignores_sigint()
    if initializer is not None:
        initializer(*initargs)


def _stop(pool) -> None:
    """Drop the queued units of a local pool and end its workers (SIGTERM, then SIGKILL
    after :data:`STOP_TIMEOUT_S`): no orphan outlives an interrupted run, and nothing of
    the pool holds the interpreter's exit (which joins the executor's manager thread)."""
    if pool is None:
        return
    procs = list((getattr(pool, "_processes", None) or {}).values())
    # the executor's manager thread, shutting down, closes its call queue and joins the
    # queue's feeder thread; with the workers terminated no one reads that pipe, and a
    # feeder blocked on a full pipe would hold the join, the manager thread, and the
    # interpreter's exit (which joins it) for ever: the queue's join is cancelled first
    # (its unsent items are dropped units of an interrupted run).
    queue = getattr(pool, "_call_queue", None)
    if queue is not None:
        queue.cancel_join_thread()
    results = getattr(pool, "_result_queue", None)     # shutdown() forgets these two
    manager = getattr(pool, "_executor_manager_thread", None)
    pool.shutdown(wait=False, cancel_futures=True)
    for proc in procs:
        proc.terminate()
    for proc in procs:
        proc.join(STOP_TIMEOUT_S)
        if proc.is_alive():
            proc.kill()
            proc.join(1.0)
    # A worker ended in the middle of sending its result (a case's profiles are ~0.5 MB,
    # written in several pieces) leaves the manager thread in recv() waiting for the
    # rest, for ever: this process holds the pipe's other write end. Closing it, with
    # every worker gone, makes that read end (EOF): the manager sees a broken pool and
    # ends. Seen as a sweep that printed its line and did not exit within 60 s of a
    # Ctrl-C 1 s after its start (twice in CI); reproduced with 200 MB results stopped
    # mid-send (4 of 5 hung) and by tests/test_engine_stop.py.
    writer = getattr(results, "_writer", None)
    if writer is not None:
        with contextlib.suppress(OSError):
            writer.close()
    # The manager thread, ending, closes its wake-up pipe; the interpreter's exit wakes
    # every executor's manager thread through that pipe (concurrent.futures.process.
    # _python_exit, in threading._shutdown) after checking it is open, without the lock
    # the closing takes: a thread still ending then made the exit print "Exception
    # ignored in: <module 'threading'> ... OSError: [Errno 9] Bad file descriptor" after
    # the interrupt's line (2 of 19 Ctrl-C of a sweep). It is joined here (bounded),
    # so that it has closed the pipe before the exit looks at it. (Taken before the
    # shutdown, which sets the attribute to None: read after it, the join was skipped,
    # and 1 interrupt of a sweep in 40 still printed it; seen with the thread alive at
    # the exit in 79 of 80 interrupts, the pipe closed a few ms before the exit's look.)
    if manager is not None:
        manager.join(STOP_TIMEOUT_S)
    _join_feeder(queue)


def _join_feeder(queue) -> None:
    """Until the call queue's feeder thread has ended (bounded by :data:`STOP_TIMEOUT_S`).

    The feeder, a daemon thread, holds the queue's two semaphores; ending, it drops them
    and their finaliser unlinks each and then tells multiprocessing's resource tracker. A
    feeder still ending at the interpreter's exit was frozen between the two: the run
    printed ``resource_tracker: There appear to be 1 leaked semaphore objects`` and
    ``[Errno 2] No such file or directory`` after the interrupt's line (2 of 50 Ctrl-C of
    a sweep in CI; the feeder was alive when the stop returned in 2 of 10 stops here). A
    feeder blocked on the full pipe (a unit's arguments larger than it, the workers gone)
    is freed by reading the pipe here: what it held are dropped units of the stopped run.
    """
    feeder = getattr(queue, "_thread", None)
    if feeder is None:
        return
    feeder.join(0.5)
    reader = getattr(queue, "_reader", None)
    deadline = time.monotonic() + STOP_TIMEOUT_S
    while feeder.is_alive() and reader is not None and time.monotonic() < deadline:
        with contextlib.suppress(OSError, EOFError):   # closed by the feeder as it ends
            while reader.poll(0.05):
                reader.recv_bytes()
        feeder.join(0.05)


@dataclass
class Engine:
    jobs: int = 1
    scheduler: str | None = None
    client: object = field(default=None, repr=False)
    #: ``jobs = 1`` in a pool of one worker process instead of this process (a bench's
    #: like-for-like baseline: the workers' start and their one BLAS thread each)
    pool: bool = False

    @property
    def in_process(self) -> bool:
        """The units run in this process, one after another."""
        return not self.scheduler and self.jobs == 1 and not self.pool

    def describe(self) -> str:
        if self.scheduler:
            return f"Dask cluster at {self.scheduler} ({self.workers()} worker(s))"
        if self.in_process:
            return "this process"
        if self.jobs == 1:
            return "1 local worker process"
        return f"{self.jobs} local worker processes"

    def workers(self) -> int:
        """How many units run at once."""
        if self.client is not None:
            info = self.client.scheduler_info()
            return max(1, sum(w.get("nthreads", 1) for w in info["workers"].values()))
        return self.jobs

    # ------------------------------------------------------------------ lifecycle
    def open(self) -> "Engine":
        """Connect to the scheduler (nothing to do locally); raises :class:`EngineError`:
        exit 2 for an address that is malformed or names something that is not a Dask
        scheduler, exit 1 for one that does not answer (or has no worker). Bounded: the
        probe (:mod:`.scheduler_probe`) takes at most :data:`PROBE_TIMEOUT_S`, so nothing
        here hangs or trusts a length from a server that is not a scheduler."""
        if not self.scheduler or self.client is not None:
            return self
        distributed = require_dask()
        scheme, host, port = _address(self.scheduler, distributed)
        timeout = min(PROBE_TIMEOUT_S, CONNECT_TIMEOUT_S)
        if scheme in ("tcp", "tls", "ws", "wss"):
            try:                                 # the full handshake on tcp://
                probe(self.scheduler, host, port, timeout, handshake=scheme == "tcp")
            except ProbeFailed as exc:
                raise EngineError(str(exc), exit_code=2 if exc.bad_input else 1) from None
        try:
            self.client = distributed.Client(self.scheduler, timeout=CONNECT_TIMEOUT_S,
                                             set_as_default=False)
        except Exception as exc:                 # noqa: BLE001 - one line, whatever failed
            raise EngineError(f"--scheduler {self.scheduler}: the scheduler does not answer "
                              f"within {CONNECT_TIMEOUT_S:g} s ({type(exc).__name__}: "
                              f"{str(exc).splitlines()[0] if str(exc) else 'no reason given'})"
                              "; start one with `dask scheduler` and workers with "
                              "`dask worker ADDRESS`") from None
        try:
            self.client.wait_for_workers(1, timeout=CONNECT_TIMEOUT_S)
        except Exception:                        # noqa: BLE001 - TimeoutError, a lost comm
            self.close()
            raise EngineError(f"--scheduler {self.scheduler}: the scheduler answers but has "
                              f"no worker after {CONNECT_TIMEOUT_S:g} s; start some with "
                              f"`dask worker {self.scheduler}`") from None
        return self

    def close(self) -> None:
        if self.client is not None:
            self.client.close()
            self.client = None

    def __enter__(self) -> "Engine":
        return self.open()

    def __exit__(self, *exc) -> None:
        self.close()

    # ------------------------------------------------------------------ running
    def map(self, fn, args: list[tuple], progress=None, names: list[str] | None = None):
        """Run ``fn(*a)`` for each ``a`` of ``args``; yield ``(i, result_or_exception)``
        as each finishes. ``progress``: the :class:`~verification.runtime.progress.Progress` whose
        ``capture`` (this process) or worker output forwarding (local pool) is used.
        ``names``: the units' keys on a Dask cluster (its dashboard shows them)."""
        if self.scheduler:
            yield from self._dask(fn, args, names)
        elif self.in_process:
            for i, a in enumerate(args):
                try:
                    if progress is not None:
                        with progress.capture():
                            out = fn(*a)
                    else:
                        out = fn(*a)
                except Exception as exc:           # the unit fails, not the run
                    reraise_interrupt(exc)         # unless it was a Ctrl-C (in Numba)
                    out = exc
                yield i, out
        else:
            yield from self._pool(fn, args, progress)

    def _pool(self, fn, args, progress):
        """The local pool. Its start (the workers spawned by the first submissions) and its
        clean-up run with Ctrl-C held back (:mod:`.interrupts`); the workers are born with
        SIGINT blocked, so an interrupt of the terminal's process group reaches only this
        process, which stops them."""
        for key, value in WORKER_ENV.items():       # before the workers start (spawn)
            os.environ.setdefault(key, value)
        ctx = mp.get_context("spawn")
        pool, futures = None, {}
        try:
            with held_interrupts(), sigint_blocked():
                opts = progress.worker_options(ctx) if progress is not None else {}
                pool = cf.ProcessPoolExecutor(
                    max_workers=self.jobs, mp_context=ctx, initializer=_worker_init,
                    initargs=(opts.get("initializer"), opts.get("initargs", ())))
                for i, a in enumerate(args[:self.jobs]):    # these spawn the workers
                    futures[pool.submit(fn, *a)] = i
            for i, a in enumerate(args[self.jobs:], start=self.jobs):
                futures[pool.submit(fn, *a)] = i
            for f in cf.as_completed(futures):
                try:
                    out = f.result()
                except Exception as exc:           # incl. a worker that died
                    out = exc
                yield futures[f], out
            pool.shutdown(wait=True)
        except BaseException:                      # interrupted (or closed): stop it all
            with held_interrupts():
                _stop(pool)
            raise

    def _dask(self, fn, args, names):
        distributed = require_dask()
        self.open()
        token = uuid.uuid4().hex[:8]           # unique keys: a rerun never meets old results
        keys = [f"{n}-{token}" for n in (names or [f"unit-{i}" for i in range(len(args))])]
        futures = {self.client.submit(fn, *a, key=k, pure=False): i
                   for i, (a, k) in enumerate(zip(args, keys))}
        try:
            for f in distributed.as_completed(list(futures), loop=self.client.loop):
                try:
                    out = f.result()
                except Exception as exc:           # incl. KilledWorker, a lost worker
                    out = exc
                yield futures[f], out
                f.release()
        except BaseException:                      # interrupted: cancel what is left
            self.client.cancel(list(futures))
            raise

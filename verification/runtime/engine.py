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
:meth:`Engine.open` connects to the scheduler before anything is written, so that an
address that does not answer fails with :class:`EngineError` (one line, exit 1) and
leaves no output behind.
"""

from __future__ import annotations

import concurrent.futures as cf
import multiprocessing as mp
import os
import signal
import uuid
from dataclasses import dataclass, field

#: environment of local worker processes, unless already set: one BLAS thread each (the
#: OpenBLAS threads of ``solve_bvp`` compete with the other worker: ``reproduce all`` on 2
#: cores took 317 s and 536 s of CPU with them, 308 s and 513 s without, with the same
#: numbers). Dask workers are started by their owner: docs/sweeps.md says to set it there.
WORKER_ENV = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}
#: seconds to wait for a Dask scheduler to answer
CONNECT_TIMEOUT_S = 10.0


class EngineError(RuntimeError):
    """The engine cannot run (a scheduler that does not answer, no worker, the optional
    package missing): one line, exit 1."""


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
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if initializer is not None:
        initializer(*initargs)


@dataclass
class Engine:
    jobs: int = 1
    scheduler: str | None = None
    client: object = field(default=None, repr=False)

    def describe(self) -> str:
        if self.scheduler:
            return f"Dask cluster at {self.scheduler} ({self.workers()} worker(s))"
        if self.jobs == 1:
            return "this process"
        return f"{self.jobs} local worker processes"

    def workers(self) -> int:
        """How many units run at once."""
        if self.client is not None:
            info = self.client.scheduler_info()
            return max(1, sum(w.get("nthreads", 1) for w in info["workers"].values()))
        return self.jobs

    # ------------------------------------------------------------------ lifecycle
    def open(self) -> "Engine":
        """Connect to the scheduler (nothing to do locally); raises :class:`EngineError`."""
        if not self.scheduler or self.client is not None:
            return self
        distributed = require_dask()
        if not self.scheduler.startswith(("tcp://", "tls://", "inproc://", "ws://", "wss://")):
            raise EngineError(f"--scheduler: {self.scheduler!r} is not a scheduler address "
                              "(tcp://host:port, as `dask scheduler` prints it)")
        try:
            host, port = distributed.comm.parse_host_port(
                distributed.comm.parse_address(self.scheduler)[1])
        except ValueError as exc:
            raise EngineError(f"--scheduler: {self.scheduler!r} is not a scheduler address "
                              f"({exc}; tcp://host:port, as `dask scheduler` prints it)") from None
        try:
            self.client = distributed.Client(self.scheduler, timeout=CONNECT_TIMEOUT_S,
                                             set_as_default=False)
        except (OSError, TimeoutError, ValueError) as exc:
            raise EngineError(f"--scheduler {self.scheduler}: the scheduler does not answer "
                              f"within {CONNECT_TIMEOUT_S:g} s ({type(exc).__name__}: "
                              f"{str(exc).splitlines()[0] if str(exc) else 'no reason given'})"
                              "; start one with `dask scheduler` and workers with "
                              "`dask worker ADDRESS`") from None
        try:
            self.client.wait_for_workers(1, timeout=CONNECT_TIMEOUT_S)
        except (TimeoutError, OSError):
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
        elif self.jobs == 1:
            for i, a in enumerate(args):
                try:
                    if progress is not None:
                        with progress.capture():
                            out = fn(*a)
                    else:
                        out = fn(*a)
                except Exception as exc:           # the unit fails, not the run
                    out = exc
                yield i, out
        else:
            yield from self._pool(fn, args, progress)

    def _pool(self, fn, args, progress):
        for key, value in WORKER_ENV.items():       # before the workers start (spawn)
            os.environ.setdefault(key, value)
        ctx = mp.get_context("spawn")
        opts = progress.worker_options(ctx) if progress is not None else {}
        pool = cf.ProcessPoolExecutor(max_workers=self.jobs, mp_context=ctx,
                                      initializer=_worker_init,
                                      initargs=(opts.get("initializer"), opts.get("initargs", ())))
        try:
            futures = {pool.submit(fn, *a): i for i, a in enumerate(args)}
            for f in cf.as_completed(futures):
                try:
                    out = f.result()
                except Exception as exc:           # incl. a worker that died
                    out = exc
                yield futures[f], out
        except BaseException:                      # interrupted: drop the queued units
            procs = list((getattr(pool, "_processes", None) or {}).values())
            pool.shutdown(wait=False, cancel_futures=True)
            for proc in procs:
                proc.terminate()                   # and the running ones: no orphans
            raise
        pool.shutdown(wait=True)

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

"""A real local Dask cluster for the tests and ``riser-verify bench --sweep``.

:func:`local_cluster` starts a scheduler and ``workers`` single-threaded workers as
separate processes, through the dask command line exactly as a user would on a cluster
(``dask scheduler``, ``dask worker``), run by this Python (``python -m dask``), with
:data:`verification.runtime.engine.WORKER_ENV` set for them (one BLAS thread each) and
the nanny's malloc setting left alone (:data:`NANNY_ENV`). It yields the
scheduler's address (``tcp://127.0.0.1:PORT``) once every worker is registered, and on
exit stops every process it started, also when the body raised: each runs in its own
process group (a worker's nanny and its worker process together), sent SIGTERM, then
SIGKILL after :data:`STOP_TIMEOUT_S`. Their logs go to a temporary folder, removed at the
end; a process that does not start raises :class:`RuntimeError` naming it, with the tail
of its log. ``distributed`` is imported only when a cluster is started (the optional extra
``[cluster]``).
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from .engine import WORKER_ENV

STOP_TIMEOUT_S = 10.0      # s a process is given to stop after SIGTERM, before SIGKILL
#: the workers' nanny without Dask's default MALLOC_TRIM_THRESHOLD_=65536 (its
#: pre-spawn-environ; None unsets it): glibc then trims the heap on every free of a 64 kB
#: block and maps every block above 128 kB afresh, and a fatigue unit (spectral damage
#: on grids of 8001 ranges, one array after another) ran 1.5 to 2 times slower on a
#: Dask worker than in a local process (measured: an FD unit 8.3-9.0 s against 4.3-5.4
#: s, 4.3-5.6 s with this). docs/sweeps.md says to start a cluster's workers so.
NANNY_ENV = {"DASK_DISTRIBUTED__NANNY__PRE_SPAWN_ENVIRON": "{'MALLOC_TRIM_THRESHOLD_': None}"}
LOG_TAIL = 12              # lines of its log quoted when a process did not start


def _tail(path: Path) -> str:
    try:
        return " | ".join(path.read_text(errors="replace").strip().splitlines()[-LOG_TAIL:])
    except OSError:
        return "(no log)"


def _stop(proc: subprocess.Popen) -> None:
    """SIGTERM (a nanny then closes its worker), wait, SIGKILL to the process group if
    it is still there; then SIGKILL to whatever of its group outlived it."""
    if proc.poll() is None:
        proc.terminate()
        try:
            proc.wait(STOP_TIMEOUT_S)
        except subprocess.TimeoutExpired:
            _kill_group(proc)
            with contextlib.suppress(subprocess.TimeoutExpired):
                proc.wait(STOP_TIMEOUT_S)
    _kill_group(proc)


def _kill_group(proc: subprocess.Popen) -> None:
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(proc.pid, signal.SIGKILL)    # its own group (start_new_session)


def _scheduler_address(path: Path) -> str | None:
    try:
        return json.loads(path.read_text())["address"]
    except (OSError, ValueError, KeyError):
        return None                            # not written yet, or half written


@contextlib.contextmanager
def local_cluster(workers: int = 2, timeout: float = 60.0):
    """Start a Dask scheduler and ``workers`` workers (1 thread each) on 127.0.0.1;
    yield the scheduler's address; stop them all on exit. ``timeout``: seconds for the
    scheduler and every worker to be up, else :class:`RuntimeError`."""
    import distributed  # the optional extra [cluster]
    logs = Path(tempfile.mkdtemp(prefix="riser-dask-"))
    sched_file = logs / "scheduler.json"
    env = {**NANNY_ENV, **os.environ, **WORKER_ENV}
    procs: list[tuple[str, subprocess.Popen, Path]] = []

    def start(name: str, args: list[str]) -> None:
        log = logs / f"{name}.log"
        with open(log, "wb") as f:
            procs.append((name, subprocess.Popen(
                [sys.executable, "-m", "dask", *args], stdout=f, stderr=subprocess.STDOUT,
                stdin=subprocess.DEVNULL, env=env, cwd=logs, start_new_session=True), log))

    def failed(what: str) -> RuntimeError:
        dead = [(n, p, log) for n, p, log in procs if p.poll() is not None]
        name, proc, log = dead[0] if dead else procs[-1]
        state = f"exited with code {proc.returncode}" if dead else "still running"
        return RuntimeError(f"local Dask cluster: {what} ({name} {state}; its log: "
                            f"{_tail(log)})")

    deadline = time.monotonic() + timeout
    try:
        start("scheduler", ["scheduler", "--scheduler-file", str(sched_file), "--host",
                            "127.0.0.1", "--port", "0", "--no-dashboard"])
        while (address := _scheduler_address(sched_file)) is None:
            if procs[0][1].poll() is not None or time.monotonic() > deadline:
                raise failed(f"the scheduler did not start within {timeout:g} s")
            time.sleep(0.1)
        for i in range(workers):
            start(f"worker-{i}", ["worker", "--scheduler-file", str(sched_file),
                                  "--nthreads", "1", "--nworkers", "1", "--no-dashboard",
                                  "--host", "127.0.0.1", "--name", f"worker-{i}",
                                  "--local-directory", str(logs / f"worker-{i}")])
        left = max(deadline - time.monotonic(), 1.0)
        try:
            with distributed.Client(address, timeout=left, set_as_default=False) as client:
                while len(client.scheduler_info()["workers"]) < workers:
                    if any(p.poll() is not None for _, p, _ in procs):
                        raise failed("a process stopped while the workers started")
                    if time.monotonic() > deadline:
                        raise failed(f"{len(client.scheduler_info()['workers'])} of "
                                     f"{workers} worker(s) registered after {timeout:g} s")
                    time.sleep(0.2)
        except (OSError, TimeoutError) as exc:
            raise failed(f"the scheduler at {address} does not answer "
                         f"({type(exc).__name__})") from None
        yield address
    finally:
        for _, proc, _ in reversed(procs):     # workers first, then the scheduler
            _stop(proc)
        shutil.rmtree(logs, ignore_errors=True)

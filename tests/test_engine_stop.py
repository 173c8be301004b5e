"""Stopping the local pool (an interrupted run) leaves nothing that holds the exit.

The interpreter's exit joins the process pool's manager thread. A worker killed in the
middle of sending its result (a case's profiles are ~0.5 MB, sent in pieces) left that
thread in ``recv()`` for ever, waiting for the rest of a message no one would write:
a sweep printed its ``error: interrupted`` line and never exited (seen twice in CI).
"""

from __future__ import annotations

import concurrent.futures as cf
import multiprocessing as mp
import os
import struct
import time

from verification.runtime import engine


def _square(x):
    return x * x


def _manager_ends(pool, half_message: bool) -> bool:
    """Run a unit (the workers up), optionally leave half a message in the result
    pipe, stop the pool; whether the manager thread ends within 10 s."""
    assert pool.submit(_square, 3).result(timeout=60) == 9
    thread = pool._executor_manager_thread
    if half_message:
        # the header of a 1 MB message and 16 bytes of it: what a writer killed
        # mid-send leaves (written here from this process, whose own write end is the
        # one a killed worker's message could not be finished through either)
        os.write(pool._result_queue._writer.fileno(),
                 struct.pack("!i", 1 << 20) + b"\x80" * 16)
        time.sleep(0.5)                      # the manager thread is in recv() now
        assert thread.is_alive()
    engine._stop(pool)
    thread.join(10.0)                        # ends at once; 10 s: a loaded machine
    return not thread.is_alive()


def test_a_result_cut_in_half_does_not_hold_the_manager_thread():
    pool = cf.ProcessPoolExecutor(max_workers=2, mp_context=mp.get_context("spawn"))
    assert _manager_ends(pool, half_message=True)


def test_stopping_an_idle_pool_ends_it():
    pool = cf.ProcessPoolExecutor(max_workers=2, mp_context=mp.get_context("spawn"))
    assert _manager_ends(pool, half_message=False)
    assert not any(p.is_alive() for p in mp.active_children())

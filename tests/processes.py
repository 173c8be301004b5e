"""Processes a command leaves behind (shared by the interrupt tests)."""

from __future__ import annotations

import subprocess
import time


def left_in_session(pid: int, wait: float = 10.0) -> list[str]:
    """The pids still running in the session ``pid`` led (a command started with
    ``start_new_session``), after up to ``wait`` s for them to end (the resource tracker
    ends on its own, a moment after the command)."""
    deadline = time.monotonic() + wait
    while True:
        left = subprocess.run(["pgrep", "-s", str(pid)], capture_output=True,
                              text=True).stdout.split()
        if not left or time.monotonic() > deadline:
            return left
        time.sleep(0.2)

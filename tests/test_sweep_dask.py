"""``riser-verify sweep --scheduler``: the same sweep on a real local Dask cluster (a
scheduler and two single-threaded workers started by the test through the dask command
line, :func:`verification.runtime.dask_local.local_cluster`) gives the same numbers as in this
process; an address that does not answer fails in one line before anything is written;
a Dask run resumes a folder of a local run.

Needs the optional extra ``[cluster]`` (dask.distributed), except the check of the
message given when it is missing. About 30 s, most of it the two sweeps of 4 cases.
"""

from __future__ import annotations

import csv
import json
import os
import shutil
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

from verification.runtime.engine import EngineError, require_dask

from extras import needs_dask

ROOT = Path(__file__).resolve().parents[1]

#: 2 hang-off offsets x 2 currents of the steel catenary riser: 4 cases of ~1-2 s each
SWEEP = """\
base = "scr-steel"
methods = ["bvp", "vfife"]

[set]
"environment.current.heights" = [0.0, 1000.0]

[[vary]]
key = "ends.hang_off"
values = [[1450.0, 1000.0], [1550.0, 1000.0]]

[[vary]]
key = "environment.current.speeds"
values = [[0.0, 0.0], [0.0, 1.0]]
"""
CASES = 4


def _cli(argv: list[str], connect_timeout_s: float | None = None):
    """``riser-verify ARGV`` in a fresh Python (what a user sees on stderr, logging of
    distributed included), optionally with a shorter scheduler connection timeout."""
    code = ("import sys, verification.runtime.engine as e\n"
            + (f"e.CONNECT_TIMEOUT_S = {connect_timeout_s!r}\n" if connect_timeout_s else "")
            + "from verification.cli import main\nsys.exit(main(sys.argv[1:]))\n")
    p = subprocess.run([sys.executable, "-c", code, *argv], cwd=ROOT, capture_output=True,
                       text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def _rows(path: Path) -> list[dict]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def _workers(out: Path) -> list[str]:
    """The ``worker`` (host:pid) of each case's case.json."""
    return [json.loads(p.read_text())["worker"]
            for p in sorted((out / "cases").glob("*/case.json"))]


@pytest.fixture(scope="module")
def sweep_file(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("sweep") / "small.toml"
    path.write_text(SWEEP)
    return path


@pytest.fixture(scope="module")
def local_run(sweep_file, tmp_path_factory):
    """The sweep run locally (``--jobs 1``) in a fresh process: (exit code, output folder).
    A first run fills Numba's cache, so that this run and the Dask workers execute the same
    cached kernels: a kernel compiled afresh and the same kernel loaded from the cache give
    VFIFE results that differ by ~3e-9 (measured: 15958.3726293 against 15958.3725783 N m
    on an SCR case), which a cold cache at the start of a test session would show here."""
    base = tmp_path_factory.mktemp("local")
    for name in ("prime", "out"):
        code, _, err = _cli(["sweep", str(sweep_file), "--jobs", "1", "--out",
                             str(base / name), "-q"])
        assert code in (0, 1), err
    return code, base / "out"


@pytest.fixture(scope="module")
def cluster():
    """The address of a local scheduler with two workers, stopped after the module."""
    from verification.runtime.dask_local import local_cluster
    with local_cluster(workers=2) as address:
        yield address


# ------------------------------------------------------------------ without the extra
def test_missing_distributed_says_how_to_install_it(monkeypatch, run_cli, sweep_file,
                                                    tmp_path):
    monkeypatch.setitem(sys.modules, "distributed", None)     # import distributed fails
    with pytest.raises(EngineError) as exc:
        require_dask()
    msg = str(exc.value)
    assert "[cluster]" in msg and "pip install" in msg and "\n" not in msg
    out = tmp_path / "out"
    code, _, err = run_cli(["sweep", str(sweep_file), "--scheduler", "tcp://127.0.0.1:9",
                            "--out", str(out)])
    assert code == 1
    assert err.splitlines() == [f"error: {msg}"]
    assert not out.exists()


def test_jobs_and_scheduler_together_are_refused(run_cli, sweep_file, tmp_path):
    out = tmp_path / "out"
    code, _, err = run_cli(["sweep", str(sweep_file), "--jobs", "2", "--scheduler",
                            "tcp://127.0.0.1:9", "--out", str(out)])
    assert code == 2
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error:") and "--jobs" in lines[0]
    assert not out.exists()


# ------------------------------------------------------------------ addresses that fail
@needs_dask
def test_a_scheduler_that_does_not_answer_fails_in_one_line(sweep_file, tmp_path):
    with socket.socket() as s:                 # a port nothing listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    address = f"tcp://127.0.0.1:{port}"
    out = tmp_path / "out"
    code, stdout, err = _cli(["sweep", str(sweep_file), "--scheduler", address, "--out",
                              str(out)], connect_timeout_s=2.0)
    assert code == 1, err
    lines = err.splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("error:") and address in lines[0]
    assert "does not answer" in lines[0]
    assert not out.exists() and stdout == ""


@needs_dask
@pytest.mark.parametrize("address, says", [
    ("localhost:8786", "'localhost:8786' is not a scheduler address"),   # no protocol
    ("tcp://127.0.0.1", "missing port"),                                  # no port
])
def test_a_malformed_address_fails_in_one_line(sweep_file, tmp_path, address, says):
    out = tmp_path / "out"
    code, stdout, err = _cli(["sweep", str(sweep_file), "--scheduler", address,
                              "--out", str(out)], connect_timeout_s=2.0)
    assert code == 2, err                      # bad input (it was exit 1)
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error:"), err
    assert address in lines[0] and says in lines[0]
    assert not out.exists() and stdout == ""


# ------------------------------------------------------------------ on a real cluster
@needs_dask
def test_a_dask_run_gives_the_numbers_of_a_local_run(local_run, cluster, sweep_file,
                                                     tmp_path, run_cli):
    local_code, local = local_run
    out = tmp_path / "dask"
    code, stdout, err = run_cli(["sweep", str(sweep_file), "--scheduler", cluster,
                                 "--out", str(out), "-q"])
    assert code == local_code and code in (0, 1), err
    assert f"ran {CASES} case(s)" in stdout
    for name in ("cases.csv", "envelopes.csv"):
        a, b = _rows(local / name), _rows(out / name)
        assert len(a) == len(b) > 0, name
        for ra, rb in zip(a, b):
            ra.pop("wall_time_s", None)
            rb.pop("wall_time_s", None)
            assert ra == rb, (name, ra["case"] if "case" in ra else ra.get("s"))
    rows = _rows(out / "cases.csv")
    assert len(rows) == 2 * CASES and {r["status"] for r in rows} == {"converged"}
    report = (out / "report.md").read_text()
    assert f"on Dask cluster at {cluster} (2 worker(s))" in report
    # each case ran in a worker process, not here; both workers took cases: the
    # scheduler gives a task to each idle worker at once (the cases are submitted
    # together, both workers registered before), and work stealing moves only tasks
    # that have not started, so each worker runs at least its first case
    pids = {w.rsplit(":", 1)[1] for w in _workers(out)}
    assert str(os.getpid()) not in pids
    assert len(pids) == 2, _workers(out)
    local_pids = {w.rsplit(":", 1)[1] for w in _workers(local)}   # --jobs 1: its process
    assert len(local_pids) == 1 and str(os.getpid()) not in local_pids


@needs_dask
def test_a_dask_run_resumes_a_local_run(local_run, cluster, sweep_file, tmp_path, run_cli):
    _, local = local_run
    out = tmp_path / "resumed"
    shutil.copytree(local, out)
    before = {p: p.read_text() for p in (out / "cases").glob("*/case.json")}
    code, stdout, err = run_cli(["sweep", str(sweep_file), "--scheduler", cluster,
                                 "--out", str(out), "-q"])
    assert code in (0, 1), err
    assert "ran 0 case(s)" in stdout and f"{CASES} skipped" in stdout
    assert {p: p.read_text() for p in (out / "cases").glob("*/case.json")} == before
    assert "nothing ran now" in (out / "report.md").read_text()
    a, b = _rows(local / "cases.csv"), _rows(out / "cases.csv")
    assert a == b                              # timings included: read from the cases


# ------------------------------------------------------------------ throughput (slow)
def _ours_cpu_s() -> tuple[float, dict]:
    """CPU seconds [user + system] of this process and its reaped children (the local
    pool's workers, once shut down), and of each live descendant (the Dask scheduler,
    nannies and workers), keyed by (pid, start time)."""
    import resource

    import psutil
    total = sum(getattr(resource.getrusage(who), f) for who in
                (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)
                for f in ("ru_utime", "ru_stime"))
    live = {}
    for proc in psutil.Process().children(recursive=True):
        try:
            t = proc.cpu_times()
            live[(proc.pid, proc.create_time())] = t.user + t.system
        except psutil.Error:                   # it ended meanwhile: reaped, or not ours
            pass
    return total, live


def _machine_busy_s() -> tuple[float, int]:
    """(CPU seconds the cores this process may run on have spent busy since boot, that
    number of cores). Busy: everything but idle and iowait, steal included (a virtual
    machine's core taken by the host is a core we do not get); guest time is already in
    user."""
    import psutil
    per = psutil.cpu_times(percpu=True)
    cpus = sorted(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else []
    mine = [per[i] for i in cpus] if cpus and max(cpus) < len(per) else per
    idle = ("idle", "iowait", "guest", "guest_nice")
    return sum(v for t in mine for k, v in t._asdict().items() if k not in idle), len(mine)


@needs_dask
@pytest.mark.slow
@pytest.mark.skipif((os.cpu_count() or 1) < 2, reason="throughput with 2 workers needs 2 cores")
def test_two_workers_raise_the_throughput_on_every_engine(monkeypatch, tmp_path):
    # riser-verify bench --sweep on the built-in scr-envelope (12 cases of ~1.6 s): two
    # workers must beat one on both engines, by as much as the cores left free by the
    # other processes of the machine allow. Measured per engine run (1 local worker, 2
    # local workers, the Dask cluster's 2 workers): the CPU time the machine's cores spent
    # busy, minus that of this process and its children (the pool's workers, the Dask
    # processes), is the other processes' load O [cores]. A run of k workers can use
    # min(k, C - O) of the C cores, so the ideal speed-up is
    #     S* = min(2, C - O_2) / min(1, C - O_1)
    # (2 on an idle 2-core machine; 4/3 with one busy process elsewhere: it takes 1 of 2
    # cores from one worker, 2/3 from two). Measured on an idle 2-core machine: 1.74x
    # (local) and 1.57x (Dask) of S* = 2, i.e. 87 % and 79 % of it (the pool's spawn,
    # imports and Numba cache loads; the Dask client and scheduler); the bound 0.65 S*
    # (1.3x on an idle machine) leaves 0.14 of S* for noise. It fails an engine that runs
    # the cases one at a time whenever the others leave it more than ~1.3 cores (serial:
    # ~0.87x < 0.65 S* for S* > 1.34; checked by hand with bench.WORKERS = 1, both engines
    # serial: 0.96x and 0.94x against S* = 1.99, failed); under a heavier load S* itself
    # shrinks to what can be told apart, and the message gives the loads. Upper bound:
    # more than 1.1 S* would be a timing error (the single worker slowed by something not
    # measured here). Measured under another engineer's load of ~1 core: local 1.24x of
    # S* = 1.27, Dask 1.40x of S* = 1.63 (the old fixed bound 1.3x failed there).
    from verification.runtime.progress import Progress
    from verification.sweeps import bench
    from verification.sweeps.file import load_sweep
    phases = []
    time_engine = bench._time_engine

    def measured(sweep, engine, prog, label):
        busy0, cores = _machine_busy_s()
        ours0, live0 = _ours_cpu_s()
        t0 = time.perf_counter()
        out = time_engine(sweep, engine, prog, label)
        wall = time.perf_counter() - t0
        busy1, _ = _machine_busy_s()
        ours1, live1 = _ours_cpu_s()
        ours = ours1 - ours0 + sum(v - live0.get(k, 0.0) for k, v in live1.items())
        phases.append({"label": label, "wall_s": wall, "ours_cores": ours / wall,
                       "others_cores": max(busy1 - busy0 - ours, 0.0) / wall, "cores": cores})
        return out

    monkeypatch.setattr(bench, "_time_engine", measured)
    # the built-in sweep's cases as heavy as they were measured (~1.6 s: the VFIFE's
    # relaxation on every mesh): with Newton's finish of the statics a case takes ~0.3 s
    # and the pool's spawn and imports, not the engines, decide the speed-up (1.09x)
    from verification.sweeps.file import builtin_sweeps
    text = builtin_sweeps()["scr-envelope"].read_text().replace(
        '[set]\n', '[set]\n"vfife.expert.static_newton" = false\n', 1)
    path = tmp_path / "scr-envelope.toml"
    path.write_text(text)
    with Progress("bench --sweep", quiet=True) as prog:
        b = bench.measure(load_sweep(str(path)), prog)
    e = b["engines"]
    assert all(e[k]["cases_run"] == 12 and e[k]["cases_failed"] == 0
               for k in ("local_1", "local_2", "dask_2")), e
    assert len(phases) == 3, phases                     # local_1, local_2, dask_2 in turn
    free = [max(p["cores"] - p["others_cores"], 0.1) for p in phases]
    for key, f in (("local_2", free[1]), ("dask_2", free[2])):
        ideal = min(2.0, f) / min(1.0, free[0])
        why = (key, round(e[key]["speed_up"], 3), "ideal", round(ideal, 3), phases)
        assert 0.65 * ideal < e[key]["speed_up"] < 1.1 * ideal, why
    assert 0.0 < b["dask_overhead"]["ms_per_task"] < 100.0   # a scheduler, not a timeout

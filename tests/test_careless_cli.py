"""The command line used carelessly: every run ends in one line and the right exit code.

1. ``sweep --scheduler`` at something that is not a Dask scheduler (a server that accepts
   and says nothing, as the dashboard's port; one that answers garbage, as an HTTP
   server): one line, exit 2, within the 10 s the README promises (it hung, or failed
   with ``MemoryError: Unable to allocate 3.07 EiB``); an unreachable address: exit 1.
2. Ctrl-C at any moment of a sweep (pool start-up, waiting, writing, the report): one line
   ``interrupted: N of M cases written to DIR; ...`` and exit 130, no traceback, no
   worker left behind, whether SIGINT reaches the process alone or, as from a terminal,
   its whole process group.
3. A folder that cannot be written: refused before any solving, one line naming --out,
   exit 2, for every command that writes.
4. Every numeric option refused out of its range (not clamped), naming the option and
   the range, exit 2.
5. A sweep says how many cases it runs and how long they should take, and on a terminal
   draws an ETA.
6. Console forces and moments keep their significant digits (a lab model's 1.1 N is not
   ``0.00 kN``).

Time: ~40 s on 2 loaded cores, most of it the 5 s probe of a silent server and the
interrupted sweeps (subprocesses); the many-delays interrupt test is marked slow.
"""

from __future__ import annotations

import errno
import json
import math
import os
import re
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from processes import left_in_session

from verification import cli
from verification.cli.common import Range, check_ranges
from verification.report.units import length, with_unit
from verification.runtime import interrupts, outdir, progress as pg
from verification.runtime.scheduler_probe import PROBE_TIMEOUT_S, ProbeFailed, probe
from verification.sweeps.run import duration_text, estimate_line

from extras import needs_dask

ROOT = Path(__file__).resolve().parents[1]
IS_ROOT = hasattr(os, "geteuid") and os.geteuid() == 0


def one_line(err: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("error: ") and "Traceback" not in err, err
    return lines[0]


def sweep_file(tmp_path: Path, n: int = 2, methods=("bvp",)) -> Path:
    """n vessel offsets of the steel catenary riser (each case < 1 s with the BVP)."""
    offsets = [[1460.0 + 10.0 * i, 1000.0] for i in range(n)]
    f = tmp_path / f"sweep-{n}.toml"
    f.write_text(f'base = "scr-steel"\nmethods = {json.dumps(list(methods))}\n'
                 f'[[vary]]\nkey = "ends.hang_off"\nvalues = {json.dumps(offsets)}\n')
    return f


# ====================================================== 1. an address that is not a scheduler
class Server:
    """A TCP server on 127.0.0.1 in a thread: on each connection it sends ``reply`` (None:
    nothing) and keeps the connection open until the test ends."""

    def __init__(self, reply: bytes | None):
        self.reply = reply
        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(8)
        self.port = self.sock.getsockname()[1]
        self.conns: list[socket.socket] = []
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self):
        while True:
            try:
                conn, _ = self.sock.accept()
            except OSError:
                return
            self.conns.append(conn)
            if self.reply is not None:
                conn.sendall(self.reply)

    def close(self):
        for c in self.conns:
            c.close()
        self.sock.close()


@pytest.fixture
def server(request):
    s = Server(request.param)
    yield s
    s.close()


GARBAGE = {
    "an HTTP reply": b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n",   # 3.07 EiB
    "a huge length": b"\xff" * 64,
    "a plausible length, then junk": (200).to_bytes(8, sys.byteorder) + b"\x93" * 200,
}


def sweep_at(run_cli, server, tmp_path):
    """Run a sweep with ``--scheduler`` at ``server``: (exit code, stdout, stderr, its one
    line, seconds taken, the --out folder, the address)."""
    out, address = tmp_path / "out", f"tcp://127.0.0.1:{server.port}"
    t0 = time.monotonic()
    code, stdout, err = run_cli(["sweep", str(sweep_file(tmp_path)), "--scheduler", address,
                                 "--out", str(out)])
    return code, stdout, err, one_line(err), time.monotonic() - t0, out, address


@needs_dask
@pytest.mark.parametrize("server", [None], indirect=True, ids=["silent (the dashboard's port)"])
def test_a_silent_server_is_refused_within_10_s(run_cli, server, tmp_path):
    code, stdout, err, line, took, out, address = sweep_at(run_cli, server, tmp_path)
    assert code == 2 and stdout == "", err
    assert f"--scheduler {address}: not a Dask scheduler" in line
    assert f"within {PROBE_TIMEOUT_S:g} s" in line and "tcp://HOST:8786" in line
    assert took < 10.0, took                       # measured: 5.0 s (the probe's timeout)
    assert not out.exists()


@needs_dask
@pytest.mark.parametrize("server", list(GARBAGE.values()), indirect=True, ids=list(GARBAGE))
def test_a_server_answering_garbage_is_refused_at_once(run_cli, server, tmp_path):
    code, stdout, err, line, took, out, _ = sweep_at(run_cli, server, tmp_path)
    assert code == 2 and stdout == "", err
    assert "not a Dask scheduler" in line and "answered" in line and "MemoryError" not in line
    assert took < 3.0, took                        # measured: ~0.01 s after the imports
    assert not out.exists()


@needs_dask
def test_an_unreachable_address_is_exit_1_and_a_malformed_one_exit_2(run_cli, tmp_path):
    with socket.socket() as s:                     # a port nothing listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    f = sweep_file(tmp_path)
    code, _, err = run_cli(["sweep", str(f), "--scheduler", f"tcp://127.0.0.1:{port}",
                            "--out", str(tmp_path / "a")])
    assert code == 1 and "does not answer" in one_line(err)
    for address in ("tcp://127.0.0.1:99999", "127.0.0.1:8786", "tcp://127.0.0.1:x"):
        code, _, err = run_cli(["sweep", str(f), "--scheduler", address,
                                "--out", str(tmp_path / "b")])
        line = one_line(err)
        assert code == 2 and "--scheduler" in line and "PORT 1 to 65535" in line, line


def test_the_probe_accepts_a_scheduler_handshake_and_sends_its_own():
    # what a scheduler sends on accepting a connection (distributed's framing): the probe
    # reads it and has sent its own
    import msgpack
    frame = msgpack.packb({"compression": None, "python": (3, 11, 7),
                           "pickle-protocol": 5}, use_bin_type=True)
    body = (1).to_bytes(8, sys.byteorder) + len(frame).to_bytes(8, sys.byteorder) + frame
    s = Server(len(body).to_bytes(8, sys.byteorder) + body)
    try:
        got = probe(f"tcp://127.0.0.1:{s.port}", "127.0.0.1", s.port, timeout=2.0)
        assert got["pickle-protocol"] == 5
        time.sleep(0.1)
        sent = s.conns[0].recv(4096)
        (size,) = (int.from_bytes(sent[:8], sys.byteorder),)
        assert size == len(sent) - 8                  # one framed message, our handshake
        assert b"pickle-protocol" in sent
    finally:
        s.close()
    with pytest.raises(ProbeFailed) as exc:           # and a silent one, bounded
        s2 = Server(None)
        try:
            t0 = time.monotonic()
            probe(f"tcp://127.0.0.1:{s2.port}", "127.0.0.1", s2.port, timeout=0.5)
        finally:
            s2.close()
    assert exc.value.bad_input and time.monotonic() - t0 < 2.0


# ============================================================ 2. Ctrl-C
def _interrupt(tmp_path: Path, delay: float, group: bool, n: int = 8) -> None:
    """Run a sweep of ``n`` BVP cases on 2 workers in a fresh process (its own session),
    wait for its first line, then ``delay`` s, then SIGINT to the process (or its whole
    group, as a terminal's Ctrl-C does); check the one line, exit 130, the count of cases
    said against the case folders, and that no process of it is left."""
    out = tmp_path / f"out-{delay}-{group}"
    code = "import sys\nfrom verification.cli import main\nsys.exit(main())\n"
    p = subprocess.Popen([sys.executable, "-c", code, "sweep",
                          str(sweep_file(tmp_path, n)), "--jobs", "2", "--out", str(out)],
                         cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         start_new_session=True)
    try:
        first = p.stdout.readline()               # "sweep NAME: n case(s) ...": started
        assert first.startswith("sweep "), first + p.stderr.read()
        time.sleep(delay)
        if group:
            os.killpg(p.pid, signal.SIGINT)
        else:
            p.send_signal(signal.SIGINT)
        stdout, stderr = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
    finished = "ran " in stdout and p.returncode in (0, 1)     # done before the signal
    if not finished:
        assert p.returncode == 130, (delay, group, stdout, stderr)
        line = one_line(stderr)
        assert line.startswith("error: interrupted"), line
        m = re.search(r"interrupted: (\d+) of (\d+) cases written to (.+?);", line)
        if m:
            written = len(list((out / "cases").glob("*/case.json")))
            assert (int(m[1]), int(m[2]), m[3]) == (written, n, str(out)), (line, written)
    left = left_in_session(p.pid)
    assert not left, f"processes left after the interrupt: {left}"


@pytest.mark.parametrize("delay, group", [(0.0, True), (2.0, False), (4.0, True)],
                         ids=["pool start-up, terminal", "waiting, process", "running, terminal"])
def test_an_interrupt_is_one_line_and_exit_130(tmp_path, delay, group):
    _interrupt(tmp_path, delay, group)


@pytest.mark.slow
@pytest.mark.parametrize("group", [False, True], ids=["process", "terminal"])
def test_an_interrupt_at_many_moments_is_one_line_and_exit_130(tmp_path, group):
    for delay in (0.0, 0.1, 0.3, 0.6, 1.0, 1.5, 2.5, 4.0, 6.0, 9.0, 12.0):
        _interrupt(tmp_path, delay, group)


def test_held_interrupts_raise_at_the_end_not_in_the_middle():
    steps = []
    with pytest.raises(KeyboardInterrupt):
        with interrupts.held_interrupts():
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(0.05)                       # the handler has run by now
            steps.append("the block went on")
    assert steps == ["the block went on"]


def test_workers_are_born_with_sigint_blocked():
    # the mask a pool's workers inherit (resource tracker started first: it unblocks it)
    import multiprocessing as mp
    ctx = mp.get_context("spawn")
    with interrupts.held_interrupts(), interrupts.sigint_blocked():
        child = ctx.Process(target=time.sleep, args=(2.0,))
        child.start()
    try:
        time.sleep(0.1)
        status = Path(f"/proc/{child.pid}/status").read_text()
        blocked = int(re.search(r"SigBlk:\s*([0-9a-f]+)", status)[1], 16)
        assert blocked & (1 << (signal.SIGINT - 1)), status
    finally:
        child.terminate()
        child.join()


def test_an_interrupt_while_the_interpreter_exits_is_one_line():
    code = ("from verification.runtime.interrupts import exit_quietly_on_interrupt\n"
            "import os, signal, time\nexit_quietly_on_interrupt(False)\n"
            "os.kill(os.getpid(), signal.SIGINT)\ntime.sleep(5)\n")
    p = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                       text=True, timeout=30)
    assert p.returncode == 130 and p.stderr == "error: interrupted\n", p.stderr


# ============================================================ 3. a folder that cannot be written
WRITERS = {
    "solve": ["solve", "scr-steel"],
    "compare": ["compare", "scr-steel"],
    "modes": ["modes", "scr-steel"],
    "cost": ["cost", "scr-steel"],
    "stress": ["stress", "hard-stiff"],
    "sweep": ["sweep", "scr-envelope", "--jobs", "1"],
    "bench": ["bench"],
    "bench --sweep": ["bench", "--sweep"],
    "reproduce": ["reproduce", "wang2014", "--jobs", "1"],
}


@pytest.fixture
def read_only(tmp_path, monkeypatch):
    """A folder this process cannot write: chmod 0o500; as root (who writes anyway),
    os.open and os.mkdir refuse, with EACCES, to create anything below it."""
    folder = tmp_path / "read-only"
    folder.mkdir()
    (folder / "notes.txt").write_text("the user's own file\n")
    folder.chmod(0o500)
    if IS_ROOT:
        real_open, real_mkdir = os.open, os.mkdir

        def below(path) -> bool:
            return str(folder) in str(os.fspath(path))

        def fake_open(path, flags, mode=0o777, *, dir_fd=None):
            if flags & os.O_CREAT and below(path):
                raise PermissionError(errno.EACCES, "Permission denied", str(path))
            return real_open(path, flags, mode, dir_fd=dir_fd)

        def fake_mkdir(path, mode=0o777, *, dir_fd=None):
            if below(path):
                raise PermissionError(errno.EACCES, "Permission denied", str(path))
            return real_mkdir(path, mode, dir_fd=dir_fd)
        monkeypatch.setattr(os, "open", fake_open)
        monkeypatch.setattr(os, "mkdir", fake_mkdir)
    yield folder
    monkeypatch.undo()
    folder.chmod(0o700)


@pytest.mark.parametrize("name", list(WRITERS))
def test_a_read_only_out_is_refused_before_anything_runs(run_cli, read_only, name):
    for out, says in ((read_only, "cannot be written: Permission denied"),
                      (read_only / "new" / "deeper", "cannot be created: ")):
        t0 = time.monotonic()
        code, stdout, err = run_cli([*WRITERS[name], "--out", str(out)])
        line = one_line(err)
        assert code == 2, (name, err)
        assert line.startswith(f"error: {out}: --out: {says}"), line
        assert "choose a folder you can write to" in line
        assert time.monotonic() - t0 < 20.0            # nothing solved: seconds of imports
        assert sorted(p.name for p in read_only.iterdir()) == ["notes.txt"]


@pytest.mark.skipif(not IS_ROOT, reason="root only: a folder root cannot write (sysfs)")
def test_as_root_a_really_unwritable_folder_is_refused(run_cli):
    # /sys refuses mkdir even to root (EPERM): the real OS error, no simulation
    try:
        os.mkdir("/sys/riser-verify-probe")
    except OSError:
        pass
    else:
        os.rmdir("/sys/riser-verify-probe")
        pytest.skip("this /sys accepts a new folder")
    code, _, err = run_cli(["solve", "scr-steel", "--out", "/sys/riser-verify-out"])
    assert code == 2 and "--out: cannot be created" in one_line(err)


def test_check_writable_leaves_nothing_behind(tmp_path):
    target = tmp_path / "a" / "b"
    outdir.check_writable(target)                     # created, probed and removed again
    assert list(tmp_path.iterdir()) == []
    (tmp_path / "c").mkdir()
    outdir.check_writable(tmp_path / "c")
    assert list((tmp_path / "c").iterdir()) == []


# ============================================================ 4. numeric options out of range
#: (command line before the option, option, range text, bad values)
OPTIONS = [
    (["solve", "scr-steel"], "--tolerance", "between 1e-12 and 0.1", ["0", "0.5", "nan", "x"]),
    (["solve", "scr-steel"], "--element-length", "> 0 m and <= 1000 m",
     ["0", "-1", "5000", "inf"]),
    (["compare", "scr-steel"], "--element-length", "> 0 m and <= 1000 m", ["0", "nan"]),
    (["fatigue", "scr-steel-fatigue"], "--element-length", "> 0 m and <= 1000 m",
     ["0", "nan"]),
    (["compare", "scr-steel"], "--peer-segment-length", "between 0.01 and 1000 m",
     ["0", "0.001", "2000", "nan"]),
    (["modes", "scr-steel"], "--count", "between 1 and 50", ["0", "51", "-3", "2.5"]),
    (["cost", "scr-steel"], "--repeats", "between 1 and 100", ["0", "101", "-1", "many"]),
    (["reproduce", "wang2014"], "--jobs", "between 1 and 1024", ["0", "2000", "two"]),
    (["sweep", "scr-envelope"], "--jobs", "between 1 and 1024", ["0", "-1", "1025", "1.5"]),
    (["fatigue", "scr-steel-fatigue"], "--jobs", "between 1 and 1024", ["0", "1025", "1.5"]),
    (["fatigue", "scr-steel-fatigue"], "--share", "> 0 and <= 1", ["0", "1.5", "nan"]),
    (["fatigue", "scr-steel-fatigue"], "--ancf-cells", "between 0 and 100000", ["-1", "2.5"]),
]


@pytest.mark.parametrize("before, option, allowed, bad", OPTIONS,
                         ids=[f"{o[0][0]} {o[1]}" for o in OPTIONS])
def test_an_option_out_of_range_is_refused_naming_it_and_its_range(run_cli, tmp_path, before,
                                                                   option, allowed, bad):
    for value in bad:
        code, stdout, err = run_cli([*before, option, value, "--out", str(tmp_path / "o")])
        line = one_line(err)
        assert code == 2, (option, value, err)
        assert line.startswith(f"error: command line: {option}: must be "), line
        assert allowed in line and "got" in line, line
        assert stdout == ""


def test_cost_repeats_0_is_refused_not_clamped(run_cli, tmp_path):
    code, _, err = run_cli(["cost", "scr-steel", "--repeats", "0", "--out", str(tmp_path)])
    assert code == 2 and one_line(err) == ("error: command line: --repeats: must be between "
                                           "1 and 100 (timed runs per setting), got 0")


def test_every_numeric_option_has_its_range_and_is_tested():
    parser = cli.build_parser()
    sub = next(a for a in parser._actions if hasattr(a, "choices") and
               isinstance(a.choices, dict))
    tested = {(o[0][0], o[1]) for o in OPTIONS}
    seen = set()
    peer_commands = {"import-moordyn", "export-moordyn"}    # the peer's own commands
    for name, p in sub.choices.items():
        for action in p._actions:
            numeric = action.type in (int, float) or hasattr(action, "range")
            if not numeric or name in peer_commands:
                continue
            assert hasattr(action, "range"), (name, action.option_strings)
            seen.add((name, action.option_strings[-1]))
    assert seen == tested


def test_the_ends_of_a_range_are_accepted():
    from argparse import Namespace
    r = Range(1, 50, integer=True, what="modes per plane")
    for v in (1, 50):
        check_ranges(Namespace(count=v, _ranges={"count": ("--count", r)}))
    open_range = Range(0.0, 1000.0, lo_open=True, unit="m")
    assert open_range.holds(1e-9) and open_range.holds(1000.0)
    assert not open_range.holds(0.0) and not open_range.holds(math.nan)


def test_a_parse_error_is_one_line_too(run_cli):
    for argv in (["solve"], ["solve", "scr-steel", "--method", "fem"], ["frobnicate"],
                 ["solve", "scr-steel", "--colour", "red"]):
        code, _, err = run_cli(argv)
        assert code == 2 and one_line(err).startswith("error: command line: "), argv


# ============================================================ 5. the estimate and the ETA
def test_a_sweep_estimates_its_time_before_and_draws_an_eta(run_cli, tmp_path, monkeypatch):
    monkeypatch.setattr(pg, "_isatty", lambda stream: True)  # capsys' stderr as a terminal
    f, out = sweep_file(tmp_path, 3), tmp_path / "out"
    code, stdout, err = run_cli(["sweep", str(f), "--jobs", "1", "--out", str(out)])
    assert code in (0, 1), err
    lines = stdout.splitlines()
    assert lines[0].startswith("sweep sweep-3: 3 case(s) of scr-steel")
    assert lines[1] == "3 case(s) to run on 1 worker(s); the estimate of the time follows the " \
                       "first case"
    first = next(i for i, ln in enumerate(lines) if ln.startswith("case "))
    est = lines[first + 1]
    m = re.fullmatch(r"estimate: about (.+) for 3 case\(s\) on 1 worker\(s\) \(([\d.]+) s a "
                     r"case with every method, the first case\)", est)
    assert m, est
    case_s = json.loads((out / "cases" / "0000" / "case.json").read_text())["wall_time_s"]
    assert m[1] == duration_text(3 * case_s) and m[2] == f"{case_s:.1f}"
    assert re.search(r"\rsweep sweep-3: \d/3 cases done \[[#.]{20}\] +\d+%  0:\d\d, ETA 0:\d\d",
                     err), err                     # the status line, with its ETA
    # a rerun with one case changed estimates from the cases finished before it starts
    f.write_text(f.read_text().replace("1480.0", "1485.0"))
    code, stdout, _ = run_cli(["sweep", str(f), "--jobs", "1", "--out", str(out)])
    lines = stdout.splitlines()
    est = next(i for i, ln in enumerate(lines) if ln.startswith("estimate:"))
    first = next(i for i, ln in enumerate(lines) if ln.startswith("case "))
    assert est < first and "for 1 case(s) on 1 worker(s)" in lines[est]
    assert "the median of the 2 finished earlier" in lines[est]


def test_the_estimate_of_a_large_sweep():
    # 10,000 cases of 1.6 s on 2 workers: 5000 rounds, 8000 s
    assert estimate_line(10_000, 2, 1.6, "the first case") == (
        "estimate: about 2 h 13 min for 10000 case(s) on 2 worker(s) (1.6 s a case with every "
        "method, the first case)")
    assert duration_text(40) == "40 s" and duration_text(600) == "10 min"


# ============================================================ 6. units that keep the digits
LAB = """\
name = "lab-cable"
title = "A 3 m model cable in a 1 m tank"
[environment]
water_depth = 1.0
[seabed]
stiffness = 1.0e4
[line_types.cable]
outer_diameter = 0.004
mass_per_length = 0.1
axial_stiffness = 2.0e5
bending_stiffness = 0.005
[[segments]]
line_type = "cable"
length = 3.0
[ends]
anchor = [0.0, 0.0]
hang_off = [2.4, 1.0]
"""


def _printed(stdout: str, label: str) -> tuple[float, str]:
    m = re.search(rf"{label} (-?[\d.]+) (mN|N|kN|MN)\b", stdout)
    assert m, stdout
    return float(m[1]), m[2]


@pytest.mark.parametrize("scene, unit", [("lab", "N"), ("scr-steel", "kN")])
def test_console_forces_keep_three_significant_digits(run_cli, tmp_path, scene, unit):
    if scene == "lab":
        (tmp_path / "lab.toml").write_text(LAB)
        scene = str(tmp_path / "lab.toml")
    out = tmp_path / "o"
    code, stdout, _ = run_cli(["solve", scene, "--method", "bvp", "--out", str(out)])
    assert code == 0, stdout
    sm = json.loads((out / "summary.json").read_text())
    factor = {"mN": 1e-3, "N": 1.0, "kN": 1e3, "MN": 1e6}
    for label, key in (("hang-off tension", "hang_off_tension"),
                       ("max tension", "max_tension"), ("touchdown x = [\\d.]+ m, tension",
                                                        "tdp_tension")):
        value, u = _printed(stdout, label)
        assert 1.0 <= abs(value) < 1000.0, (label, value, u)      # 3 digits at least
        assert value * factor[u] == pytest.approx(sm[key], rel=6e-3), (label, value, u)
    assert _printed(stdout, "hang-off tension")[1] == unit
    assert "0.00 kN" not in stdout and "0.000 kN m" not in stdout


def test_with_unit_chooses_the_prefix():
    assert with_unit(1.1213, "N") == "1.12 N"
    assert with_unit(0.2479, "N") == "247.90 mN"
    assert with_unit(831470.2, "N") == "831.47 kN"
    assert with_unit(2.5e7, "N") == "25.00 MN"
    assert with_unit(0.0127, "N m", decimals=3) == "12.700 mN m"
    assert with_unit(16109.0, "N m", decimals=3) == "16.109 kN m"
    assert with_unit(-2500.0, "N") == "-2.50 kN"
    assert with_unit(999.996, "N").endswith(" kN")
    assert with_unit(0.0, "N") == "0 N"
    assert length(0.35) == "0.350" and length(1500.0) == "1500.00"

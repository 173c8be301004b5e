"""Issue 44 (c): Ctrl-C at any moment ends every command in exit 130 and one line.

Found on main: a sweep printed ``Exception ignored in: <module 'threading'> ... OSError:
[Errno 9] Bad file descriptor`` after its line (2 of 19 interrupts: the pool's manager
thread, still ending, closed its wake-up pipe while the interpreter's exit wrote to it);
a VFIFE dynamic solve ended in exit 1 ``unexpected SystemError: CPUDispatcher(...)
returned a result with an exception set`` (1 of 10: Numba's dispatcher wraps a
KeyboardInterrupt raised in it). The outcome asserted is the issue's: exit 130, exactly
one line on stderr (``error: interrupted...``), no traceback, no process left.

The default suite sends one interrupt per command at a random moment and checks the two
mechanisms deterministically; the slow set sends 50 per command (random moments in the
first seconds of the program: its imports, the pool's start, the solve). Not covered: a
Ctrl-C while the interpreter itself starts, before the program's first line runs
(:func:`_wait_for_the_program`).
"""

from __future__ import annotations

import json
import os
import random
import signal
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from processes import left_in_session

from verification.cli import main
from verification.runtime import engine as engine_mod
from verification.runtime.engine import Engine
from verification.runtime.interrupts import caused_by_interrupt

ROOT = Path(__file__).resolve().parents[1]
CODE = "import sys\nfrom verification.cli import main\nsys.exit(main())\n"
#: seconds after the program's code starts (:func:`_wait_for_the_program`) within which
#: the interrupt comes (uniform): the imports (~2-3 s on a loaded machine), the engine's
#: start and the first seconds of the solve; every command here runs well beyond it (the
#: dynamic solve 13 s with a warm Numba cache, fatigue and reproduce ends ~20 s, the sweep
#: of 48 cases ~15 s on 2 workers)
WINDOW_S = 6.0
#: processes interrupted at once (each is mostly waiting for its imports or its workers)
AT_ONCE = 4


def _sweep_file(folder: Path) -> Path:
    """48 vessel offsets of the steel catenary riser, BVP only (each case < 1 s; 16 cases
    ended within the 6 s window on an idle machine: exit 0 before the signal)."""
    offsets = [[1420.0 + 2.5 * i, 1000.0] for i in range(48)]
    f = folder / "sweep-48.toml"
    f.write_text('base = "scr-steel"\nmethods = ["bvp"]\n[[vary]]\nkey = "ends.hang_off"\n'
                 f"values = {json.dumps(offsets)}\n")
    return f


def _commands(folder: Path) -> dict[str, list[str]]:
    return {"sweep": ["sweep", str(_sweep_file(folder)), "--jobs", "2"],
            # dynamic, VFIFE; at 1 m elements: 13 s with a warm Numba cache on an idle
            # machine (at its own 2 m, 5.4 s: an interrupt drawn late in the window came
            # after the run had ended, exit 0 - measured once in the default run)
            "solve": ["solve", "hard-large-heave", "--method", "vfife", "--element-length",
                      "1"],
            "fatigue": ["fatigue", "scr-steel-fatigue"],
            "reproduce": ["reproduce", "ends"]}


def interrupt_once(argv: list[str], delay: float, out: Path) -> dict:
    """Run ``riser-verify ARGV --out OUT`` in its own session, send SIGINT to its process
    group (a terminal's Ctrl-C) ``delay`` s after the launch; the outcome."""
    p = subprocess.Popen([sys.executable, "-c", CODE, *argv, "--out", str(out)], cwd=ROOT,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         start_new_session=True)
    try:
        _wait_for_the_program(p.pid)
        time.sleep(delay)
        with _suppress_lookup():
            os.killpg(p.pid, signal.SIGINT)
        stdout, stderr = p.communicate(timeout=120)
    finally:
        if p.poll() is None:
            with _suppress_lookup():
                os.killpg(p.pid, signal.SIGKILL)
            p.wait()
    left = left_in_session(p.pid)
    lines = stderr.strip().splitlines()
    ok = (p.returncode == 130 and len(lines) == 1 and lines[0].startswith("error: interrupted")
          and "Traceback" not in stderr and not left)
    return {"delay": round(delay, 3), "code": p.returncode, "ok": ok, "stderr": stderr[-2000:],
            "left": left}


def _wait_for_the_program(pid: int, timeout: float = 60.0) -> None:
    """Until the program's own code runs: numpy's library mapped into the process, which
    the command line imports first inside its interrupt handler (verification/cli/
    __init__.py). Before that the interpreter itself starts (``site`` and the installed
    ``.pth`` files, 0.1-0.5 s here), where no code of the program runs: CPython prints
    its own traceback for a Ctrl-C then (``Fatal Python error: init_import_site``),
    measured in 6 of 50 interrupts drawn from the launch on."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            if "numpy" in Path(f"/proc/{pid}/maps").read_text():
                return
        except OSError:                          # ended (or not yet readable)
            return
        time.sleep(0.005)


class _suppress_lookup:
    """The process (group) may be gone already: ProcessLookupError is no failure."""

    def __enter__(self):
        return self

    def __exit__(self, kind, value, tb):
        return kind is not None and issubclass(kind, ProcessLookupError)


def _batch(tmp_path: Path, name: str, n: int, seed: int) -> list[dict]:
    argv = _commands(tmp_path)[name]
    rng = random.Random(seed)                    # reproducible moments
    delays = [rng.uniform(0.0, WINDOW_S) for _ in range(n)]
    with ThreadPoolExecutor(AT_ONCE) as pool:
        runs = list(pool.map(lambda k: interrupt_once(argv, delays[k],
                                                      tmp_path / f"{name}-{k}"), range(n)))
    return runs


def _check(name: str, runs: list[dict]) -> None:
    good = sum(r["ok"] for r in runs)
    print(f"{name}: {good} of {len(runs)} interrupts ended in exit 130 with one line")
    bad = [r for r in runs if not r["ok"]]
    # each bad run in full (code, delay, processes left, its whole stderr): pytest cuts a
    # list of dicts to its first keys
    assert not bad, "\n".join(f"exit {r['code']} at {r['delay']} s, left {r['left']}, "
                               f"stderr:\n{r['stderr']}" for r in bad[:3])


@pytest.mark.parametrize("name", ["sweep", "solve", "fatigue", "reproduce"])
def test_one_interrupt_at_a_random_moment_is_one_line_and_exit_130(tmp_path, name):
    _check(name, _batch(tmp_path, name, 1, seed=hash(name) % 1000 + int(time.time())))


@pytest.mark.slow
@pytest.mark.parametrize("name", ["sweep", "solve", "fatigue", "reproduce"])
def test_fifty_interrupts_at_random_moments_are_one_line_and_exit_130(tmp_path, name):
    _check(name, _batch(tmp_path, name, 50, seed=44))


# ------------------------------------------------------------ the two mechanisms, directly
def _numba_like_error() -> SystemError:
    """The exception Numba's dispatcher raises when a KeyboardInterrupt comes while its
    function runs: a SystemError whose __context__ is the interrupt."""
    try:
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt:
            raise SystemError("CPUDispatcher(<function element_state>) returned a result "
                              "with an exception set")
    except SystemError as exc:
        return exc


def test_an_interrupt_wrapped_by_numba_is_an_interrupt_not_an_unexpected_error(monkeypatch,
                                                                            capsys):
    exc = _numba_like_error()
    assert caused_by_interrupt(exc) and not caused_by_interrupt(SystemError("other"))
    import verification.cli.solve as solve_cli

    def interrupted(args):
        raise exc
    monkeypatch.setattr(solve_cli, "cmd_solve", interrupted)
    code = main(["solve", "scr-steel"])
    err = capsys.readouterr().err
    assert code == 130 and err == "error: interrupted\n", (code, err)
    # the engine in this process re-raises it (a unit's other errors are its result)
    runs = Engine(1).map(lambda: (_ for _ in ()).throw(exc), [()])
    with pytest.raises(KeyboardInterrupt):
        list(runs)
    assert isinstance(list(Engine(1).map(lambda: 1 / 0, [()]))[0][1], ZeroDivisionError)


def test_an_interrupted_pool_leaves_no_manager_thread_for_the_exit():
    # the exit's wake-up of a manager thread still ending printed the threading traceback:
    # when the stop returns, the thread has ended (its pipe closed: the exit's wake-up is
    # skipped). Asserted at once, no join of the test's own: the stop read the thread
    # after the executor's shutdown had set it to None, skipped its join, and an earlier
    # form of this test, joining for 15 s itself, passed all the same
    import concurrent.futures as cf
    import multiprocessing as mp
    pool = cf.ProcessPoolExecutor(2, mp_context=mp.get_context("spawn"))
    pool.submit(time.sleep, 30.0)
    time.sleep(0.5)
    manager = pool._executor_manager_thread
    assert manager is not None and manager.is_alive()
    engine_mod._stop(pool)
    assert not manager.is_alive()


def test_an_interrupted_pool_leaves_no_feeder_thread_for_the_exit():
    # the call queue's feeder thread, still ending at the interpreter's exit, was frozen
    # between unlinking its semaphores and telling the resource tracker ("leaked
    # semaphore objects" after the interrupt's line, 2 of 50 in CI). A pool busy with
    # short units, stopped: on the old stop its feeder was still alive when the stop
    # returned in 5 of 12 such stops (all 8 passing by chance: ~1 %); now it has ended
    import concurrent.futures as cf
    import multiprocessing as mp
    alive = 0
    for _ in range(8):
        pool = cf.ProcessPoolExecutor(2, mp_context=mp.get_context("spawn"))
        for _ in range(20):
            pool.submit(time.sleep, 0.5)
        time.sleep(1.0)
        feeder = pool._call_queue._thread
        engine_mod._stop(pool)
        alive += feeder is not None and feeder.is_alive()
    assert alive == 0


_SWALLOWED = """
import os, signal, sys, threading, time
from verification.runtime.interrupts import keep_swallowed_interrupts
if sys.argv[1] == "kept":
    keep_swallowed_interrupts()
class Finaliser:                      # a __del__ that runs when the Ctrl-C comes
    def __del__(self):
        t = time.monotonic()
        while time.monotonic() - t < 0.3:
            pass
threading.Timer(0.1, os.kill, (os.getpid(), signal.SIGINT)).start()
try:
    x = Finaliser()
    del x                             # the interrupt lands in __del__: Python ignores it
    t = time.monotonic()
    while time.monotonic() - t < 3.0:
        pass
    print("finished")
except KeyboardInterrupt:
    print("interrupted")
"""


@pytest.mark.parametrize("mode, outcome", [("plain", "finished"), ("kept", "interrupted")])
def test_an_interrupt_landing_in_a_finaliser_is_raised_again(mode, outcome):
    # a Ctrl-C handled inside a __del__ (or a gc / weakref callback) is printed as
    # "Exception ignored" and lost: the run went on to exit 0 (once in 50 interrupts of a
    # dynamic solve in CI) or past the 120 s a fatigue run was given. The negative
    # control ("plain", Python's own behaviour) shows the loss; the command line's hook
    # raises it again in the main thread, well inside the 3 s of work that follow
    out = subprocess.run([sys.executable, "-c", _SWALLOWED, mode], cwd=ROOT,
                         capture_output=True, text=True, timeout=60)
    assert out.stdout.strip() == outcome, (out.stdout, out.stderr)
    assert ("Exception ignored" in out.stderr) == (mode == "plain"), out.stderr


def test_an_interrupt_in_a_nested_hold_reaches_the_outer_one():
    # held_interrupts inside another: the inner one hands its Ctrl-C to the outer one,
    # which raises it at its own end (it was dropped: neither raised)
    from verification.runtime.interrupts import held_interrupts
    with pytest.raises(KeyboardInterrupt):
        with held_interrupts():
            with held_interrupts():
                signal.raise_signal(signal.SIGINT)
            reached = True                       # the inner hold did not raise
    assert reached


_WRAPPED_IMPORT = """
import importlib.abc, importlib.util, sys
class Loader(importlib.abc.Loader):           # a module of the command line, loading
    def create_module(self, spec):
        return None
    def exec_module(self, module):
        if sys.argv[1] == "interrupt":        # what a dataclass field does with a Ctrl-C
            try:
                raise KeyboardInterrupt
            except KeyboardInterrupt as exc:
                raise RuntimeError("Error calling __set_name__ on 'Field'") from exc
        raise RuntimeError("a real defect of the imports")
class Finder(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path, target=None):
        if name == "verification.cli.bench":
            return importlib.util.spec_from_loader(name, Loader())
sys.meta_path.insert(0, Finder())
from verification.cli import main
"""


@pytest.mark.parametrize("mode", ["interrupt", "defect"])
def test_an_interrupt_wrapped_while_the_program_loads_is_one_line(mode):
    # a Ctrl-C in a descriptor's __set_name__ (a dataclass being created) reaches the
    # imports' handler as "RuntimeError: Error calling __set_name__" (a traceback and exit
    # 1, once in 80 interrupts of the imports): 130 and one line; any other error of the
    # imports is still a traceback (the negative control: not hidden as an interrupt)
    out = subprocess.run([sys.executable, "-c", _WRAPPED_IMPORT, mode], cwd=ROOT,
                         capture_output=True, text=True, timeout=60)
    if mode == "interrupt":
        assert (out.returncode, out.stderr) == (130, "error: interrupted\n")
    else:
        assert out.returncode == 1 and "a real defect of the imports" in out.stderr


_SWALLOWED_IN_THE_IMPORTS = """
import importlib.abc, importlib.util, signal, sys, time
class Finaliser:                              # what importlib's module-lock callback is
    def __del__(self):
        signal.raise_signal(signal.SIGINT)    # the Ctrl-C lands here: Python ignores it
class Loader(importlib.abc.Loader):           # a module of the command line, loading
    def create_module(self, spec):
        return None
    def exec_module(self, module):
        x = Finaliser()
        del x
        t = time.monotonic()                  # the rest of the imports
        while time.monotonic() - t < 1.0:
            pass
class Finder(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path, target=None):
        if name == "verification.cli.bench":
            return importlib.util.spec_from_loader(name, Loader())
sys.meta_path.insert(0, Finder())
from verification.cli import main
sys.argv = ["riser-verify", "scenes"]
sys.exit(main())
"""


def test_an_interrupt_swallowed_while_the_program_loads_is_one_line():
    # a Ctrl-C landing in importlib's module-lock callback while `reproduce` loaded was
    # printed as "Exception ignored in: <function _get_module_lock.<locals>.cb>" with its
    # traceback, above the interrupt's line (2 of 50 interrupts in CI): the hook that
    # raises such a Ctrl-C again is installed before the imports, so it ends them in 130
    # with the one line. Against the former code (the hook installed by main, after the
    # imports) this printed the ignored traceback (measured: the test fails there)
    out = subprocess.run([sys.executable, "-c", _SWALLOWED_IN_THE_IMPORTS], cwd=ROOT,
                         capture_output=True, text=True, timeout=60)
    assert (out.returncode, out.stderr) == (130, "error: interrupted\n"), out


_CAUGHT_ON_ITS_WAY = """
import signal, sys
import verification.cli as cli
if sys.argv[1] == "python":                   # Python's own handler: the control
    signal.signal(signal.SIGINT, signal.default_int_handler)
def command(argv, seen=0):                    # a library's `except` catches the Ctrl-C
    try:
        signal.raise_signal(signal.SIGINT)
        sum(range(1000))
    except Exception:
        pass
    except KeyboardInterrupt:
        pass
    print("ran on to its end")
    return 0
cli._run = command
sys.exit(cli.main())
"""


@pytest.mark.parametrize("handler, code", [("python", 0), ("counted", 130)])
def test_a_ctrl_c_caught_by_a_library_still_ends_in_130(handler, code):
    # a Ctrl-C caught on its way (wrapped, then met an `except Exception` of a library)
    # let `reproduce` run to exit 0 with no word (once in 50 interrupts in CI): with
    # Python's own handler (the control) that is what happens; the command line counts
    # every Ctrl-C and ends such a run in 130 with one line that says so
    out = subprocess.run([sys.executable, "-c", _CAUGHT_ON_ITS_WAY, handler], cwd=ROOT,
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == code, (out.stdout, out.stderr)
    assert out.stdout == "ran on to its end\n"
    if code == 130:
        assert len(out.stderr.splitlines()) == 1, out.stderr
        assert out.stderr.startswith("error: interrupted: the Ctrl-C was caught by a library")
    else:
        assert out.stderr == ""


# ------------------------------------------------- a Ctrl-C swallowed by a library on its way
def _swallow_one_interrupt(interrupts) -> None:
    """A Ctrl-C delivered to this process and caught by a library's ``except``: counted
    by the handler :func:`count_interrupts` installs, raised, swallowed."""
    try:
        interrupts._counting_handler(signal.SIGINT, None)
    except KeyboardInterrupt:
        pass


def test_a_swallowed_interrupt_is_raised_at_the_next_progress_report(monkeypatch):
    from verification.runtime import interrupts
    from verification.runtime.progress import Progress
    monkeypatch.setattr(interrupts, "_SEEN", interrupts._SEEN)
    monkeypatch.setattr(interrupts, "_SURFACED", interrupts._SEEN)
    monkeypatch.setattr(interrupts, "_ARMED", False)
    prog = Progress("test", quiet=True)
    _swallow_one_interrupt(interrupts)
    prog("not armed: a process that runs the studies in-process (a test) is not a run")
    monkeypatch.setattr(interrupts, "_SURFACED", interrupts._SEEN)
    monkeypatch.setattr(interrupts, "_ARMED", True)           # the program's main()
    prog = Progress("test", quiet=True)
    prog("before any Ctrl-C")                     # nothing counted: no interrupt
    _swallow_one_interrupt(interrupts)
    with pytest.raises(KeyboardInterrupt):        # the run went on: raised at its report
        prog("dynamics t = 1 s", fraction=0.1)
    prog("after it")                              # raised once, not at every report after
    # not outside the main thread (a ticker or a worker's forwarding thread)
    _swallow_one_interrupt(interrupts)
    raised = []

    def report():
        try:
            prog("from a thread")
        except KeyboardInterrupt:
            raised.append(True)
    t = threading.Thread(target=report)
    t.start()
    t.join()
    assert not raised
    with pytest.raises(KeyboardInterrupt):
        prog("main thread again")



@pytest.mark.parametrize("swallowed", [False, True])
def test_an_error_after_a_swallowed_interrupt_is_the_interrupt_in_one_line(monkeypatch, capsys,
                                                                          swallowed):
    # CI: a Ctrl-C while a command imported pandas came out as "ImportError: PyCapsule_Import
    # could not import module pandas"; the command said "unexpected ImportError", then the
    # interrupt's own line (two lines, not one). An error after a counted Ctrl-C is that
    # Ctrl-C's doing: one line, 130. Without the Ctrl-C (the control) it stays unexpected, 1.
    from verification.runtime import interrupts
    import verification.cli.solve as solve_cli
    monkeypatch.setattr(interrupts, "_SEEN", interrupts._SEEN)
    monkeypatch.setattr(interrupts, "_ARMED", False)

    def command(args):
        if swallowed:
            _swallow_one_interrupt(interrupts)
        raise ImportError('PyCapsule_Import could not import module "pandas"')
    monkeypatch.setattr(solve_cli, "cmd_solve", command)
    code = main(["solve", "scr-steel"])
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1, err
    if swallowed:
        assert code == 130 and err.startswith("error: interrupted: "), (code, err)
        assert "ImportError" in err
    else:
        assert code == 1 and err.startswith("error: unexpected ImportError"), (code, err)


_SWALLOWED_IN_RUN = """
import atexit, os, signal, sys, time
from verification.cli import main            # installs the counting handler
try:                                          # a library's except around a wrapped Ctrl-C
    os.kill(os.getpid(), signal.SIGINT)
    time.sleep(1.0)
except KeyboardInterrupt:
    pass
t0 = time.perf_counter()
out = sys.argv[1]                             # the program's own arguments (main() arms it)
sys.argv = ["riser-verify", "solve", "hard-large-heave", "--method", "vfife", "--out", out,
            "-q"]
# the program interrupted ends in main() (its atexit callbacks run): the seconds printed then
atexit.register(lambda: print(round(time.perf_counter() - t0, 1), flush=True))
sys.exit(main())
"""


@pytest.mark.slow
def test_a_run_after_a_swallowed_interrupt_ends_at_its_first_progress_report(tmp_path):
    # the dynamic solve runs ~40 s; ended by its first progress report (the statics' first,
    # within a few seconds of the start including the Numba kernels' load): 15 s is the
    # bound that separates "ended at once" from "ran on to its end" on a loaded machine
    p = subprocess.run([sys.executable, "-c", _SWALLOWED_IN_RUN, str(tmp_path / "o")],
                       cwd=ROOT, capture_output=True, text=True, timeout=300)
    seconds = p.stdout.split()[-1]
    assert p.returncode == 130 and float(seconds) < 15.0, (p.stdout, p.stderr[-2000:])
    assert p.stderr.strip() == "error: interrupted", p.stderr[-2000:]


# ------------------------------------------------- the interpreter's teardown after the line
_TEARDOWN = """
import atexit, os, sys, threading, _thread
class Teardown:           # what the interpreter's finalisation runs last: an extension module
    def __del__(self):    # half made by an interrupted import aborted the process there
        os.write(2, b"finalisation ran\\n")
keep = Teardown()
marker = sys.argv[1]
atexit.register(lambda: open(marker, "w").write("atexit ran"))
from verification.cli import main
if sys.argv[2] == "interrupt":                # a Ctrl-C while the command loads its solvers
    threading.Timer(0.2, _thread.interrupt_main).start()
sys.argv = ["riser-verify", *sys.argv[3:]]
sys.exit(main())
"""


@pytest.mark.parametrize("mode, argv, code", [
    ("interrupt", ["solve", "hard-large-heave", "--method", "vfife", "-q"], 130),
    ("none", ["scenes"], 0)])
def test_the_program_interrupted_ends_without_the_interpreters_teardown(tmp_path, mode, argv,
                                                                        code):
    # once in 50 interrupts of `fatigue` (CI) the line was followed by "Fatal Python error:
    # PyThreadState_Get ... Python runtime state: finalizing" and SIGABRT: the teardown of
    # what an interrupted import left half made. Interrupted, the program runs its atexit
    # callbacks (the pool's clean-up) and exits 130 without the teardown: an object freed
    # there says nothing. The control: a run that ends normally still has its teardown
    # (so the object would have spoken)
    marker = tmp_path / "atexit.txt"
    out = subprocess.run([sys.executable, "-c", _TEARDOWN, str(marker), mode, *argv,
                          "--out", str(tmp_path / "o")] if mode == "interrupt" else
                         [sys.executable, "-c", _TEARDOWN, str(marker), mode, *argv],
                         cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert out.returncode == code, out.stderr[-2000:]
    assert marker.read_text() == "atexit ran"
    if mode == "interrupt":
        assert out.stderr == "error: interrupted\n", out.stderr[-2000:]
    else:
        assert out.stderr == "finalisation ran\n", out.stderr[-2000:]

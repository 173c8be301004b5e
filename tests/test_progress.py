"""The progress display (verification/runtime/progress.py) and the callbacks that feed it.

The display is a status line on stderr redrawn in place, on a terminal only: these tests
give it a fake terminal (a StringIO that says it is a TTY) and a fake clock.
"""

from __future__ import annotations

import concurrent.futures as cf
import io
import multiprocessing as mp
from pathlib import Path

import pytest

from verification.runtime import progress as pg
from verification.runtime.progress import Progress, UnitTracker, scoped, with_fraction

ROOT = Path(__file__).resolve().parents[1]
LONG_DYNAMIC = ROOT / "verification" / "scenes" / "hard" / "hard-long-dynamic.toml"


class FakeTTY(io.StringIO):
    """A text stream that says it is a terminal."""

    def isatty(self):
        return True


class Clock:
    """A clock the test moves by hand."""

    def __init__(self):
        self.t = 0.0

    def __call__(self):
        return self.t


def draws(stream) -> list[str]:
    """The lines drawn on ``stream``, in order (each starts with a carriage return)."""
    return [p.rstrip() for p in stream.getvalue().split("\r") if p.strip()]


def test_line_updated_in_place_with_bar_and_eta():
    tty, clock = FakeTTY(), Clock()
    p = Progress("job", stream=tty, clock=clock)
    p("step 1", fraction=0.0)
    clock.t = 10.0
    p("step 2", fraction=0.25)     # 10 s for a quarter: 30 s to go
    out = tty.getvalue()
    assert out.startswith("\r") and "\n" not in out
    last = draws(tty)[-1]
    assert last.startswith("job: step 2") and "25%" in last and "[#####" in last
    assert "0:10" in last and "ETA 0:30" in last
    p.close()
    assert tty.getvalue().endswith("\r") and draws(tty)[-1] == last   # cleared: blanks only


def test_eta_restarts_with_each_phase_and_spinner_without_fraction():
    tty, clock = FakeTTY(), Clock()
    p = Progress("solve", stream=tty, clock=clock)
    p("statics: 20000 steps")
    assert "ETA" not in draws(tty)[-1] and draws(tty)[-1][0] in "-\\|/"
    clock.t = 100.0                 # a long statics: not counted in the dynamics' rate
    p("dynamics t = 6 / 600 s", fraction=0.01)
    clock.t = 101.0
    p("dynamics t = 12 / 600 s", fraction=0.02)
    assert p.eta() == pytest.approx(98.0)
    assert "ETA 1:38" in draws(tty)[-1]


def test_nothing_written_when_not_a_terminal_or_quiet():
    for p in (Progress("x", stream=io.StringIO()), Progress("x", stream=FakeTTY(), quiet=True)):
        with p:
            p("message", fraction=0.5)
            p("message", fraction=1.0)
            p.tick()
        assert p.stream.getvalue() == ""
        assert not p.enabled


def test_redraws_are_rate_limited_and_the_end_is_drawn():
    tty, clock = FakeTTY(), Clock()
    p = Progress("x", stream=tty, clock=clock, interval=0.2)
    for i in range(100):            # 100 calls within 0.1 s: one redraw
        clock.t = i * 0.001
        p(f"step {i}", fraction=i / 200)
    assert len(draws(tty)) == 1
    clock.t = 0.25                  # after the interval: redrawn
    p("step 100", fraction=0.6)
    assert len(draws(tty)) == 2
    clock.t = 0.26                  # the end is always drawn
    p("done", fraction=1.0)
    assert len(draws(tty)) == 3 and "100%" in draws(tty)[-1]


def test_long_messages_are_cut_to_the_width_keeping_the_eta():
    clock = Clock()
    p = Progress("label", stream=FakeTTY(), clock=clock)
    p("m" * 300, fraction=0.0)
    clock.t = 5.0
    p("m" * 300, fraction=0.5)
    line = p.line(80)
    assert len(line) <= 80 and line.endswith("ETA 0:05") and "..." in line


def test_log_clears_the_line_before_printing():
    tty, out = FakeTTY(), io.StringIO()
    p = Progress("x", stream=tty)
    p.out = out
    p("working")
    p.log("a result")
    assert out.getvalue() == "a result\n"
    assert tty.getvalue().endswith("\r" + " " * len(draws(tty)[0]) + "\r")
    quiet = Progress("x", stream=io.StringIO())
    quiet.out = out
    quiet.log("printed anyway")
    assert out.getvalue().endswith("printed anyway\n") and quiet.stream.getvalue() == ""


def test_capture_routes_prints_through_log():
    tty, out = FakeTTY(), io.StringIO()
    p = Progress("x", stream=tty)
    p.out = out
    p("working")
    with p.capture():
        print("from a study")
    assert out.getvalue() == "from a study\n"


def test_worker_output_is_forwarded():
    tty, out = FakeTTY(), io.StringIO()
    p = Progress("x", stream=tty)
    p.out = out
    ctx = mp.get_context("spawn")
    with cf.ProcessPoolExecutor(max_workers=1, mp_context=ctx, **p.worker_options(ctx)) as pool:
        pool.submit(print, "from a worker").result()
    p.close()
    assert out.getvalue() == "from a worker\n"
    assert Progress("x", stream=io.StringIO()).worker_options(ctx) == {}


def test_one_argument_callbacks_still_work():
    got = []
    with_fraction(got.append)("m", fraction=0.5)
    scoped(got.append, "part", 0.5, 1.0)("inner", fraction=0.5)
    assert got == ["m", "part: inner"]
    assert with_fraction(None) is None and scoped(None, "p") is None

    seen = []
    scoped(lambda m, fraction=None: seen.append((m, fraction)), "p", 0.5, 1.0)("i", 0.5)
    scoped(lambda m, fraction=None: seen.append((m, fraction)), "p", 0.5, 1.0)("j")
    assert seen == [("p: i", 0.75), ("p: j", 0.5)]


def test_unit_tracker_weights_by_declared_seconds():
    clock = Clock()
    t = UnitTracker([100.0, 50.0, 50.0], jobs=2, clock=clock)
    assert t() == ("0/3 units done", 0.0)
    clock.t = 40.0                  # units 0 and 1 running for 40 s each
    assert t()[1] == pytest.approx(80.0 / 200.0)
    clock.t = 50.0
    t.done(1)                       # unit 2 starts now
    clock.t = 60.0
    assert t() == ("1/3 units done", pytest.approx((50.0 + 60.0 + 10.0) / 200.0))
    clock.t = 500.0                 # overrunning units count 90 % of their seconds
    assert t()[1] == pytest.approx((50.0 + 90.0 + 45.0) / 200.0)


def test_dynamics_reports_increasing_fractions_ending_at_one():
    import vfife
    from riser.io.scene_file import load_scene
    from riser.model.scene import Dynamics, TopMotion
    base = load_scene(LONG_DYNAMIC)
    # the ramp within the run (the default, one period, would be longer than it)
    sc = base.replace(dynamics=Dynamics(duration=5.0, output_interval=1.0,
                                        top_motion=TopMotion(axis="y", amplitude=1.0,
                                                             period=10.0, ramp_time=5.0)))
    calls = []
    res = vfife.solve(sc, element_length=20.0,
                      progress=lambda m, fraction=None: calls.append((m, fraction)))
    assert res.converged, res.message
    fr = [f for m, f in calls if m.startswith("dynamics")]
    assert len(fr) >= 10 and fr[-1] == 1.0
    assert all(b > a for a, b in zip(fr, fr[1:]))
    assert all(f is None for m, f in calls if m.startswith("statics"))
    plain = []                      # a one-argument callback gets the same messages
    vfife.solve(sc, element_length=20.0, progress=plain.append)
    assert [m for m in plain if m.startswith("dynamics")] == \
        [m for m, f in calls if m.startswith("dynamics")]


def short_dynamic_scene(tmp_path) -> Path:
    text = LONG_DYNAMIC.read_text().replace("duration = 600.0", "duration = 5.0")
    text = text.replace("ramp_time = 10.0", "ramp_time = 2.0")
    path = tmp_path / "short-dynamic.toml"
    path.write_text(text.replace('name = "hard-long-dynamic"', 'name = "short-dynamic"'))
    return path


def test_cli_prints_no_progress_when_stderr_is_not_a_terminal(run_cli, tmp_path):
    scene = short_dynamic_scene(tmp_path)
    code, out, err = run_cli(["solve", str(scene), "--method", "vfife", "--out",
                              str(tmp_path / "o")])
    assert code == 0 and "short-dynamic [vfife]" in out
    assert "\r" not in out + err and "dynamics t" not in err and "statics" not in err


def test_cli_draws_on_a_terminal_unless_quiet(run_cli, tmp_path, monkeypatch):
    monkeypatch.setattr(pg, "_isatty", lambda stream: True)   # capsys' stderr as a terminal
    # a wide terminal: the line is cut to the terminal's width (80 columns under a test
    # runner's worker, which would cut the message asserted below)
    monkeypatch.setenv("COLUMNS", "200")
    scene = short_dynamic_scene(tmp_path)
    argv = ["solve", str(scene), "--method", "vfife", "--out", str(tmp_path / "o")]
    code, out, err = run_cli(argv)
    assert code == 0 and "\r" not in out
    assert "\rsolve short-dynamic [vfife]: dynamics t = 5.0 / 5 s [####################] 100%" \
        in err
    for quiet in (argv + ["--quiet"], ["--quiet"] + argv, ["-q"] + argv):
        code, out, err = run_cli(quiet)
        assert code == 0 and "\r" not in err and "dynamics t" not in err

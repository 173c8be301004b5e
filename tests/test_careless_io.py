"""Careless inputs found by fuzzing (issue 30): each ends in one line and exit 2, never a
traceback, a hang or an unreadable file. References: the message each must give, and
TOML's own reader (tomllib) for the writer's round trip."""

from __future__ import annotations

import os
import re
import time
import tomllib

import pytest

from riser.errors import ECHO_LIMIT, SceneError
from riser.io.toml_text import dumps
from vfife.solver import _to_come

LONG = "x" * 300            # a name longer than any file system's 255 bytes


def one_line_refusal(code, out, err) -> str:
    assert code == 2, (code, out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


# ------------------------------------------------------------------ the TOML writer
@pytest.mark.parametrize("text", ["a\u0001b", "x\ny", 'q"\\z', "tab\tend", "del\x7f", "é ü",
                                  "cr\r\nlf"])
def test_written_strings_and_keys_read_back_unchanged(text):
    # a label with a raw \x01 made a sweep case's scene.toml unreadable ("Illegal
    # character"); a newline became a space. Now TOML escapes, read back by tomllib
    data = {"title": text, "line_types": {text: {"outer_diameter": 0.3}}}
    back = tomllib.loads(dumps(data, header=[f"note {text}"]))
    assert back == data


# ------------------------------------------------------------------ names and special files
@pytest.mark.parametrize("argv", [["solve", LONG], ["compare", LONG], ["sweep", LONG],
                                  ["sweep", LONG, "--out", "{tmp}/o"],
                                  ["import-moordyn", LONG, "--out", "{tmp}/s.toml"]])
def test_a_name_too_long_for_the_file_system_is_refused(run_cli, tmp_path, argv, monkeypatch):
    # "unexpected OSError: [Errno 36] File name too long" (exit 1) from Path.is_file, the
    # sweep's default output folder out/sweeps/<name> and a sweep's base
    monkeypatch.chdir(tmp_path)
    line = one_line_refusal(*run_cli([a.replace("{tmp}", str(tmp_path)) for a in argv]))
    assert "too long" in line and len(line) < 2 * ECHO_LIMIT


def test_a_sweep_whose_base_has_a_name_too_long_is_refused(run_cli, tmp_path):
    sweep = tmp_path / "s.toml"
    sweep.write_text(f'base = "{LONG}"\n[[vary]]\nkey = "segments[0].length"\n'
                     "values = [2000.0]\n")
    line = one_line_refusal(*run_cli(["sweep", str(sweep), "--out", str(tmp_path / "o")]))
    assert "base" in line and "too long" in line


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes (POSIX)")
@pytest.mark.parametrize("command", ["sweep", "solve"])
def test_a_named_pipe_is_refused_not_read(run_cli, tmp_path, command):
    # `sweep FIFO` read the pipe and waited for a writer forever
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    t0 = time.perf_counter()
    line = one_line_refusal(*run_cli([command, str(fifo), "--out", str(tmp_path / "o")]))
    assert "not a regular file" in line and time.perf_counter() - t0 < 5.0


@pytest.mark.parametrize("command", ["solve", "sweep"])
def test_a_name_with_a_carriage_return_is_one_line(run_cli, tmp_path, command):
    # a script saved with CRLF line endings passes 'scr-steel.toml\r': echoed raw, the CR
    # broke the one-line refusal; it is shown as \r
    line = one_line_refusal(*run_cli([command, "scr-steel.toml\r", "--out",
                                      str(tmp_path / "o")]))
    assert "scr-steel.toml\\r" in line


def test_an_echoed_value_is_cut_to_the_echo_limit():
    # a 5,000-character path or value made a "one-line" refusal of pages
    msg = str(SceneError("a" * 5000, "segments[0].label", "b" * 5000))
    assert len(msg) < 5 * ECHO_LIMIT and "(5,000 characters)" in msg and "\n" not in msg


# ------------------------------------------------------------------ a deck's numbers
def test_a_deck_diameter_beyond_float_range_is_refused_not_overflowed(run_cli, tmp_path):
    # Diam 1e300: "unexpected OverflowError: (34, 'Numerical result out of range')" from
    # the added mass d ** 2; now the scene's own range check names the deck line
    deck = tmp_path / "scr.dat"
    assert run_cli(["export-moordyn", "scr-steel", "--out", str(deck)])[0] == 0
    lines = deck.read_text().splitlines()
    i = next(k for k, ln in enumerate(lines) if ln.startswith("TypeName")) + 2
    parts = lines[i].split()
    parts[1] = "1e300"
    lines[i] = "  ".join(parts)
    deck.write_text("\n".join(lines) + "\n")
    line = one_line_refusal(*run_cli(["import-moordyn", str(deck), "--out",
                                      str(tmp_path / "s.toml")]))
    assert re.search(r"line \d+", line) and "must be <=" in line


# ------------------------------------------------------------------ messages
def test_what_is_still_to_come_is_never_printed_as_inf():
    # the creeping message printed "an estimated inf m of displacement"
    assert "inf" not in _to_come(float("inf"), " m", "displacement")
    assert _to_come(0.012, " m", "displacement") == "an estimated 0.012 m of displacement"
    assert _to_come(float("nan"), "", "the largest tension") == "no test on the largest tension"

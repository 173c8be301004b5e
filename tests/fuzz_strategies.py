"""Shared pieces of the property-based fuzz tests (issue 30, part 5):
``tests/test_fuzz_scenes.py``, ``tests/test_fuzz_sweeps.py``, ``tests/test_fuzz_moordyn.py``.

Each test generates inputs with ``hypothesis`` (files built from scratch, and mutations of
the built-in scenes and sweeps: a key dropped, misspelled, duplicated or unknown, a value of
another type, sign or magnitude, NaN, inf, strings, lists; for MoorDyn decks, line-only v2
decks with comma decimals, missing sections, wrong column counts, ...), runs each through
the function the command line reads it with, in this process, and classifies the outcome:

- ``accepted``: the reader returned (then a few invariants of what it returned are checked:
  no NaN or inf anywhere in the accepted scene, and, by oracle, no input the reader must
  refuse: an unknown key, a value of the wrong type, a NaN, a row with too few columns);
- ``refused``: one of the project's own errors (:class:`~riser.errors.SceneError`,
  :class:`~riser.errors.UnsupportedSceneError`, :class:`~riser.errors.SolveFailed`) whose
  message is ONE line that names a key (the key path, or the deck line);
- for a sample of accepted inputs, the solvers (``bvp.solve``, ``vfife.solve``,
  ``analytic.solve``) within a size cap and a time budget: ``converged`` (every number of
  the profile and the summary finite, every warning named ``name: ...``), ``not converged``
  (a status other than converged, with its reason), ``refused by the method`` (with its
  reason), ``over budget`` (stopped by the budget: listed, not a finding);
- ``finding``: anything else: a traceback (an exception other than the project's own), a
  hang, a NaN accepted or in a converged result, a refusal of more than one line or naming
  no key, an input the reader must refuse accepted.

Notes are what is questionable but not against the stated standard (listed, not failing).
Counts per class are printed; a test fails on any finding, listing each with its input.

Environment: ``RISER_FUZZ_SCALE`` (default 1) scales the example counts of the slow tests
(e.g. 0.1 to estimate their time); ``RISER_FUZZ_DUMP=DIR`` writes the input of every finding
and note to DIR.
"""

from __future__ import annotations

import contextlib
import copy
import dataclasses
import math
import os
import re
import signal
import threading
import time
import tomllib
import traceback
from collections import Counter
from pathlib import Path
from typing import Any, Callable

import numpy as np
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from riser.errors import SceneError, SolveFailed, UnsupportedSceneError

ROOT = Path(__file__).resolve().parents[1]
#: the project's own error types: what a reader may raise for bad input ("refused")
PROJECT_ERRORS = (SceneError, UnsupportedSceneError, SolveFailed)
#: the packages of the project (the place a finding arises is the last frame in one)
PROJECT_DIRS = tuple(str(ROOT / d) + os.sep for d in ("riser", "bvp", "vfife", "analytic",
                                                      "verification"))
NAN, INF = float("nan"), float("inf")


def scale() -> float:
    """``RISER_FUZZ_SCALE`` (default 1): the factor on the slow tests' example counts."""
    try:
        return max(float(os.environ.get("RISER_FUZZ_SCALE", "1")), 1e-3)
    except ValueError:
        return 1.0


# ============================================================================ budget
class OverBudget(BaseException):
    """Raised by :func:`time_limit` (a BaseException, so that no ``except Exception`` of the
    code under test swallows it)."""


@contextlib.contextmanager
def time_limit(seconds: float | None):
    """Raise :class:`OverBudget` in this (main) thread after ``seconds`` of wall time."""
    if (not seconds or threading.current_thread() is not threading.main_thread()
            or not hasattr(signal, "setitimer")):
        yield
        return

    def handler(signum, frame):
        raise OverBudget(f"over the budget of {seconds:g} s")

    old = signal.signal(signal.SIGALRM, handler)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


# ============================================================================ outcomes
READ_CLASSES = ("accepted", "refused", "finding")
SOLVE_CLASSES = ("converged", "not converged", "refused by the method", "over budget",
                 "finding")


@dataclasses.dataclass
class Item:
    """A finding or a note: what, where, the exception head, the input, how often."""

    kind: str
    where: str
    detail: str
    describe: str
    text: str
    files: dict
    count: int = 1


def _where(exc: BaseException) -> str:
    """The last frame of the traceback inside the project (file:line in function), and the
    innermost frame when it lies elsewhere."""
    frames = traceback.extract_tb(exc.__traceback__)
    own = [f for f in frames if f.filename.startswith(PROJECT_DIRS)]
    out = []
    if own:
        f = own[-1]
        out.append(f"{os.path.relpath(f.filename, ROOT)}:{f.lineno} in {f.name}")
    if frames and (not own or frames[-1] is not own[-1]):
        f = frames[-1]
        out.append(f"(innermost {os.path.basename(f.filename)}:{f.lineno} in {f.name})")
    return " ".join(out) or "?"


def _head(exc: BaseException) -> str:
    msg = str(exc)
    return f"{type(exc).__name__}: {msg[:400]}" + (" ..." if len(msg) > 400 else "")


class Tally:
    """Counts of outcome classes, and the findings and notes, of one fuzz test."""

    def __init__(self, kind: str):
        self.kind = kind
        self.read: Counter = Counter()
        self.solve: dict[str, Counter] = {}
        self.findings: dict[tuple, Item] = {}
        self.notes: dict[tuple, Item] = {}
        self.inputs = 0
        self.t0 = time.perf_counter()
        self.longest_refusal = ""
        self.refusal_keys: Counter = Counter()
        self.log: list[str] = []             # every solve, printed with RISER_FUZZ_VERBOSE=1

    # --------------------------------------------------------------- recording
    def _item(self, store: dict, kind: str, where: str, detail: str, describe: str,
              text: str, files: dict | None) -> None:
        key = (kind, where, detail[:40] if kind.startswith("accepted") else "")
        if key in store:
            store[key].count += 1
            return
        store[key] = Item(kind, where, detail, describe, text, dict(files or {}))
        dump = os.environ.get("RISER_FUZZ_DUMP")
        if dump:
            what = "finding" if store is self.findings else "note"
            folder = Path(dump) / f"{self.kind}-{what}-{len(store):03d}"
            folder.mkdir(parents=True, exist_ok=True)
            (folder / "what.txt").write_text(f"{kind}\n{where}\n{detail}\n{describe}\n")
            for name, content in (files or {"input.txt": text}).items():
                (folder / name).write_text(content, encoding="utf-8", errors="surrogatepass")

    def finding(self, kind: str, where: str, detail: str, inp: "Input") -> None:
        self._item(self.findings, kind, where, detail, inp.describe, inp.text, inp.files)

    def accepted_finding(self, kind: str, where: str, detail: str, inp: "Input") -> None:
        """A finding about an input the reader accepted (it moves to the findings)."""
        self.read["accepted"] -= 1
        self.read["finding"] += 1
        self.finding(kind, where, detail, inp)

    def note(self, kind: str, where: str, detail: str, inp: "Input") -> None:
        self._item(self.notes, kind, where, detail, inp.describe, inp.text, inp.files)

    # --------------------------------------------------------------- report
    def report(self) -> str:
        dt = time.perf_counter() - self.t0
        lines = [f"fuzz {self.kind}: {self.inputs} generated inputs in {dt:.1f} s"]
        lines.append("  read:  " + ", ".join(f"{c} {self.read[c]}" for c in READ_CLASSES))
        for method, c in sorted(self.solve.items()):
            lines.append(f"  solve {method}: " + ", ".join(f"{k} {c[k]}" for k in SOLVE_CLASSES
                                                           if c[k] or k != "over budget"))
        if self.refusal_keys:
            top = ", ".join(f"{k} {n}" for k, n in self.refusal_keys.most_common(12))
            lines.append(f"  most refused keys: {top}")
        lines.append(f"  longest refusal: {len(self.longest_refusal)} characters")
        lines.append(f"  findings: {len(self.findings)} distinct "
                     f"({sum(i.count for i in self.findings.values())} inputs); notes: "
                     f"{len(self.notes)} distinct")
        if os.environ.get("RISER_FUZZ_VERBOSE"):
            lines.extend("  " + entry for entry in self.log)
        for title, store in (("FINDING", self.findings), ("note", self.notes)):
            for item in store.values():
                lines.append(f"  {title} [{item.kind}] x{item.count}: {item.detail}")
                lines.append(f"      at {item.where}")
                lines.append(f"      input: {item.describe}")
        return "\n".join(lines)

    def details(self, limit: int = 6, chars: int = 2500) -> str:
        """The findings with their inputs (for the assertion message)."""
        out = []
        for item in list(self.findings.values())[:limit]:
            out.append(f"--- [{item.kind}] {item.detail}\n    at {item.where}\n    input: "
                       f"{item.describe}")
            for name, content in (item.files or {"input": item.text}).items():
                out.append(f"    {name}:\n" + "\n".join("      " + ln for ln in
                                                        content[:chars].splitlines()))
        return "\n".join(out)

    def check(self) -> None:
        print("\n" + self.report())
        assert not self.findings, f"{len(self.findings)} finding(s):\n" + self.details()


@dataclasses.dataclass
class Input:
    """One generated input: the text handed to the reader (and other files beside it), what
    it is (seed and mutations), and what the reader must do with it by oracle
    (``must_refuse``: a reason, or '')."""

    text: str
    describe: str
    files: dict = dataclasses.field(default_factory=dict)
    must_refuse: str = ""
    notes_if_accepted: str = ""
    facts: dict = dataclasses.field(default_factory=dict)


#: a refusal whose key is empty must be about the file as a whole (or name a deck section,
#: an option, a scene key in its message)
FILE_LEVEL = re.compile(
    r"not valid TOML|NUL bytes|not UTF-8|UTF-16|UTF-32|too large|larger than|is a directory|"
    r"cannot read|binary|no such file|LINES|OPTIONS|OUTPUTS|POINTS|WtrDpth|fixed or coupled|"
    r"current rows|line_types|segments|ends|environment|seabed|current_profile")
#: what breaks a line on a terminal or in a log viewer
BREAKS = re.compile("[\n\r\x0b\x0c\x85\u2028\u2029]")


def check_refusal(tally: Tally, exc: BaseException, inp: Input, *, nlines: int | None = None,
                  path: str | None = None) -> bool:
    """A refusal is ONE line naming a key (or the deck line, or, for a problem of the file as
    a whole, what is missing): True; else a finding, False."""
    msg = str(exc)
    if len(msg) > len(tally.longest_refusal):
        tally.longest_refusal = msg
    key = getattr(exc, "key", None)
    if key:
        tally.refusal_keys[re.sub(r"\[\d+\]", "[i]", re.sub(r"^case \d+ \(.*\): ", "case: ",
                                                              key))[:60]] += 1
    if BREAKS.search(msg):
        tally.finding("refusal of more than one line", _where(exc), repr(msg[:200]), inp)
        return False
    if not msg.strip():
        tally.finding("refusal without a message", _where(exc), type(exc).__name__, inp)
        return False
    if "Traceback" in msg:
        tally.finding("traceback in a refusal", _where(exc), _head(exc), inp)
        return False
    if len(msg) > 1000:
        tally.note("refusal longer than 1000 characters", _where(exc), f"{len(msg)} characters: "
                   f"{msg[:150]} ...", inp)
    line = getattr(exc, "line", None)
    if line:                                          # a deck line: within the deck
        if nlines is not None and not 1 <= line <= nlines:
            tally.finding("refusal names a line outside the deck", _where(exc),
                          f"{_head(exc)} (the deck has {nlines} lines)", inp)
            return False
        return True
    if isinstance(exc, SceneError) and key:
        return True
    if path is not None and msg.startswith(str(path)[:40]):      # names the file given
        return True
    if FILE_LEVEL.search(msg) or re.search(r"\b[a-z_]+(\[\d+\])?\.[a-z_]+", msg):
        return True
    tally.finding("refusal names no key", _where(exc), _head(exc), inp)
    return False


def read_outcome(tally: Tally, inp: Input, read: Callable[[], Any], *, budget: float = 30.0,
                 nlines: int | None = None, path: str | None = None) -> Any:
    """Run ``read()`` and classify: the value read (accepted), or None."""
    tally.inputs += 1
    try:
        with time_limit(budget):
            value = read()
    except OverBudget:
        tally.read["finding"] += 1
        tally.finding("hang", "the reader", f"no answer within {budget:g} s", inp)
        return None
    except PROJECT_ERRORS as exc:
        ok = check_refusal(tally, exc, inp, nlines=nlines, path=path)
        tally.read["refused" if ok else "finding"] += 1
        return None
    except Exception as exc:            # noqa: BLE001 - every other exception is a finding
        tally.read["finding"] += 1
        tally.finding("traceback", _where(exc), _head(exc), inp)
        return None
    if inp.must_refuse:
        tally.read["finding"] += 1
        tally.finding("accepted what must be refused", "the reader", inp.must_refuse, inp)
        return None
    tally.read["accepted"] += 1
    if inp.notes_if_accepted:
        tally.note("accepted, questionable", "the reader", inp.notes_if_accepted, inp)
    return value


# ============================================================================ invariants
def read_written(tally: Tally, inp: Input, folder: Path):
    """Write ``inp``'s text to ``folder``/scene.toml and read it as ``riser-verify``
    would (:func:`read_outcome`, then :func:`check_scene`): the Scene, or None when it was
    refused (or a finding)."""
    from verification.catalog import resolve
    path = folder / "scene.toml"
    path.write_text(inp.text, encoding="utf-8")
    scene = read_outcome(tally, inp, lambda: resolve(str(path)))
    if scene is None or not check_scene(tally, scene, inp):
        return None
    return scene


def nonfinite_path(obj: Any, path: str = "", depth: int = 0) -> str | None:
    """The path of the first NaN or inf in a scene (dataclasses, tuples, dicts, arrays)."""
    if depth > 12:
        return None
    if isinstance(obj, bool) or obj is None or isinstance(obj, (str, int)):
        return None
    if isinstance(obj, float):
        return None if math.isfinite(obj) else path or "(value)"
    if isinstance(obj, np.ndarray):
        if obj.dtype.kind in "fc" and not np.all(np.isfinite(obj)):
            return path
        return None
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        for f in dataclasses.fields(obj):
            got = nonfinite_path(getattr(obj, f.name, None), f"{path}.{f.name}".lstrip("."),
                                 depth + 1)
            if got:
                return got
        return None
    if isinstance(obj, dict):
        for k, v in obj.items():
            got = nonfinite_path(v, f"{path}.{k}".lstrip("."), depth + 1)
            if got:
                return got
        return None
    if isinstance(obj, (list, tuple)):
        for i, v in enumerate(obj):
            got = nonfinite_path(v, f"{path}[{i}]", depth + 1)
            if got:
                return got
    return None


def check_scene(tally: Tally, scene: Any, inp: Input) -> bool:
    """An accepted scene holds no NaN or inf; else a finding. True when clean."""
    bad = nonfinite_path(scene)
    if bad:
        tally.accepted_finding("NaN or inf in an accepted scene", "the reader", f"at {bad}",
                               inp)
        return False
    return True


# ============================================================================ solving
#: the most VFIFE elements a fuzz solve may have (else its element length is raised), the
#: most static steps, the most BVP nodes, and the longest line a BVP fuzz solve takes
VFIFE_MAX_ELEMENTS = 300
VFIFE_MAX_STEPS = 500_000
BVP_MAX_NODES = 10_000
MAX_LENGTH = 6_000.0


def solve_outcome(tally: Tally, method: str, scene: Any, inp: Input, *, budget: float = 30.0
                  ) -> str:
    """Solve ``scene`` with ``method`` within the caps and the budget; classify."""
    import analytic
    import bvp
    import vfife

    counts = tally.solve.setdefault(method, Counter())
    kwargs: dict = {}
    try:
        if scene.dynamics is not None:
            scene = scene.replace(dynamics=None)             # statics only: the budget
        if method == "bvp":
            nodes = min(scene.bvp.max_nodes, BVP_MAX_NODES)
            if nodes >= scene.bvp.initial_nodes:
                kwargs["max_nodes"] = nodes
            fn = bvp.solve
        elif method == "vfife":
            if scene.vfife.max_steps > VFIFE_MAX_STEPS:
                scene = scene.replace(**{"vfife.max_steps": VFIFE_MAX_STEPS})
            h = scene.vfife.element_length
            if scene.total_length / h > VFIFE_MAX_ELEMENTS:
                kwargs["element_length"] = scene.total_length / VFIFE_MAX_ELEMENTS
            fn = vfife.solve
        else:
            fn = analytic.solve
    except PROJECT_ERRORS as exc:          # the caps themselves refused: not the solver's
        counts["refused by the method"] += 1
        tally.note("cap refused", _where(exc), _head(exc), inp)
        return "refused by the method"
    t0 = time.perf_counter()
    n = len(tally.log)
    outcome = _solve_classified(tally, counts, method, fn, scene, kwargs, inp, budget)
    why = " ".join(tally.log[n:])
    del tally.log[n:]
    tally.log.append(f"{method} {outcome} in {time.perf_counter() - t0:.2f} s: "
                     f"{scene.name} L={scene.total_length:.0f} {kwargs} | {inp.describe[:150]}"
                     + (f"\n      {why}" if why else ""))
    return outcome


def _solve_classified(tally, counts, method, fn, scene, kwargs, inp, budget) -> str:
    from riser.results.result import SolveResult, Status
    try:
        with time_limit(budget):
            res = fn(scene, **kwargs)
    except OverBudget:
        counts["over budget"] += 1
        tally.note(f"{method} over budget", method, f"stopped after {budget:g} s "
                   f"(caps {kwargs})", inp)
        return "over budget"
    except PROJECT_ERRORS as exc:
        if not check_refusal(tally, exc, inp):
            counts["finding"] += 1
            return "finding"
        counts["refused by the method"] += 1
        return "refused by the method"
    except Exception as exc:               # noqa: BLE001
        counts["finding"] += 1
        tally.finding(f"traceback in {method}.solve", _where(exc), _head(exc), inp)
        return "finding"
    if not isinstance(res, SolveResult) or not isinstance(res.status, Status):
        counts["finding"] += 1
        tally.finding(f"{method}.solve returned no SolveResult", method, repr(res)[:200], inp)
        return "finding"
    if res.status is Status.CONVERGED:
        problem = _converged_problem(res)
        if problem:
            counts["finding"] += 1
            tally.finding(f"{method}: converged result with a defect", method, problem, inp)
            return "finding"
        counts["converged"] += 1
        return "converged"
    msg = str(res.message or "")
    tally.log.append(f"{res.status.value}: {msg[:200]}")
    if not msg.strip():
        counts["finding"] += 1
        tally.finding(f"{method}: {res.status.value} without a reason", method, "empty message",
                      inp)
        return "finding"
    if re.search(r"(?<![A-Za-z/])(nan|inf)(?![A-Za-z/])", msg):
        tally.note(f"{method}: NaN or inf in the reason", method, msg[:200], inp)
    if BREAKS.search(msg):
        tally.note(f"{method}: {res.status.value} reason of more than one line", method,
                   repr(msg[:200]), inp)
    if res.status is Status.REFUSED:
        counts["refused by the method"] += 1
        return "refused by the method"
    counts["not converged"] += 1
    return "not converged"


def _converged_problem(res) -> str:
    """What is wrong with a converged result ('' when nothing)."""
    prof = res.profile
    if prof is None:
        return "converged without a profile"
    if not prof.is_finite():
        bad = [n for n in ("s", "x", "y", "z", "theta", "tension", "moment", "shear",
                           "curvature") if not np.all(np.isfinite(getattr(prof, n)))]
        return f"NaN or inf in the converged profile: {', '.join(bad)}"
    if prof.wall_tension is not None and not np.all(np.isfinite(prof.wall_tension)):
        return "NaN or inf in the converged wall tension"
    try:
        sm = res.summary()
    except Exception as exc:               # noqa: BLE001
        return f"summary() raised {_head(exc)} ({_where(exc)})"
    for k, v in sm.items():
        if isinstance(v, float) and not math.isfinite(v):
            return f"summary {k} = {v}"
    for w in res.warnings:
        if not re.match(r"^[a-z][a-z0-9_]*: \S", w) or "\n" in w:
            return f"warning not named 'name: ...' or not one line: {w[:120]!r}"
    return ""


# ============================================================================ TOML writing
_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _toml_str(s: str) -> str:
    out = []
    for ch in s:
        o = ord(ch)
        if ch == "\\":
            out.append("\\\\")
        elif ch == '"':
            out.append('\\"')
        elif o < 0x20 or o == 0x7F:
            out.append(f"\\u{o:04X}")
        elif 0xD800 <= o <= 0xDFFF:
            out.append("\\uFFFD")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def toml_key(k: str) -> str:
    return k if _BARE.match(k) else _toml_str(k)


def toml_value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        r = repr(v)
        return r if any(c in r for c in ".en") else r + ".0"
    if isinstance(v, str):
        return _toml_str(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{toml_key(k)} = {toml_value(x)}" for k, x in v.items()) + "}"
    raise TypeError(f"cannot write {type(v).__name__}")


def _is_aot(v: Any) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


def write_toml(d: dict) -> str:
    """TOML text of a parsed-TOML structure (scalars first, then tables, then arrays of
    tables), NaN and inf included: tomllib reads it back equal."""
    lines: list[str] = []

    def emit(table: dict, path: list[str]) -> None:
        for k, v in table.items():
            if not isinstance(v, dict) and not _is_aot(v):
                lines.append(f"{toml_key(k)} = {toml_value(v)}")
        for k, v in table.items():
            if isinstance(v, dict):
                lines.append("")
                lines.append("[" + ".".join(toml_key(p) for p in path + [k]) + "]")
                emit(v, path + [k])
        for k, v in table.items():
            if _is_aot(v):
                for item in v:
                    lines.append("")
                    lines.append("[[" + ".".join(toml_key(p) for p in path + [k]) + "]]")
                    emit(item, path + [k])

    emit(d, [])
    return "\n".join(lines).lstrip("\n") + "\n"


# ============================================================================ value pools
def _spec_bounds() -> list[float]:
    """Every bound of the scene's field specs, and the floats next to it (boundary values)."""
    out: set[float] = set()
    try:
        import riser.physics.dynamics
        import riser.model.ends
        import riser.physics.environment
        import riser.physics.internal_flow
        import riser.model.line
        import riser.model.scene
        import riser.model.settings
        mods = (riser.model.scene, riser.model.line, riser.model.ends, riser.physics.environment, riser.physics.dynamics,
                riser.model.settings, riser.physics.internal_flow)
        for mod in mods:
            for obj in vars(mod).values():
                if isinstance(obj, type) and dataclasses.is_dataclass(obj):
                    for f in dataclasses.fields(obj):
                        sp = f.metadata.get("spec")
                        for b in (getattr(sp, a, None) for a in ("gt", "ge", "lt", "le")):
                            if isinstance(b, (int, float)) and math.isfinite(b):
                                out.update({float(b), math.nextafter(b, INF),
                                            math.nextafter(b, -INF)})
    except Exception:                      # noqa: BLE001 - a pool, not a check
        pass
    return sorted(out)


SPECIAL_NUMBERS: list[Any] = [
    0, 0.0, -0.0, 1, -1, 2, 0.5, -0.5, 1e-12, 1e-300, 5e-324, -5e-324, 1e300, -1e300,
    1.7976931348623157e308, -1.7976931348623157e308, 2 ** 63 - 1, -(2 ** 63), 10 ** 400,
    -(10 ** 400), NAN, INF, -INF, 90, 360.0, 1e6, 1e9, 1e12, 1e15, 100000.0, 50000.0, 12000.0,
    3, 7, 100, 1000, 1e-3]
BOUNDS = _spec_bounds()
SPECIAL_STRINGS = [
    "", " ", "x", "1.0", "1,5", "nan", "inf", "true", "0x10", "a\nb", "tab\there", "\x01ctl",
    "\u00e9", "\u2603", "\u2028", "\U0001d54f", "x" * 2000, "scr-steel", "bottom", "top", "y",
    "z", "extensible", "inextensible", "rigid", "elastic", "composite", "piecewise", "Pipe",
    "steel", "flexible", "-", "--", "a-b", "A", "0"]
SPECIAL_LISTS: list[Any] = [
    [], [0.0], [1.0, 2.0], [0.0, 0.0, 0.0], [[0.0, 1.0]], ["a"], [NAN, 1.0], [1e300, 1e300],
    [True], [{}], [1, "a"], [0.0, -1.0], [2.0, 1.0], ["bottom", "bottom"], ["top"], [INF, 0.0]]
SPECIAL_TABLES: list[Any] = [{}, {"a": 1.0}, {"length": 1.0}, {"x": {"y": 1}}]


def category(v: Any) -> str:
    if isinstance(v, bool):
        return "bool"
    if isinstance(v, (int, float)):
        return "number"
    if isinstance(v, str):
        return "string"
    if isinstance(v, list):
        return "array"
    if isinstance(v, dict):
        return "table"
    return type(v).__name__


def has_nonfinite(v: Any) -> bool:
    if isinstance(v, float):
        return not math.isfinite(v)
    if isinstance(v, list):
        return any(has_nonfinite(x) for x in v)
    if isinstance(v, dict):
        return any(has_nonfinite(x) for x in v.values())
    return False


def _known_scene_keys() -> set[str]:
    """Every key name of a scene file (the generated key tables of docs/scene-files.md, and
    the tables' names): a misspelling that hits one is not an unknown key."""
    names = {"name", "title", "source", "environment", "current", "seabed", "line_types",
             "segments", "ends", "model", "dynamics", "top_motion", "internal_flow", "slug",
             "bvp", "analytic", "vfife", "expert", "hang_off_angle_deg"}
    try:
        text = (ROOT / "docs" / "scene-files.md").read_text()
        names.update(re.findall(r"^\| `([a-z_0-9]+)` \|", text, flags=re.M))
    except OSError:
        pass
    return names


KNOWN_KEYS = _known_scene_keys()


# ============================================================================ paths in a dict
Path_ = tuple


def all_paths(d: Any, path: Path_ = ()) -> list[Path_]:
    """Every path to a value inside ``d`` (tables, values, array entries)."""
    out: list[Path_] = []
    if isinstance(d, dict):
        for k, v in d.items():
            out.append(path + (k,))
            out.extend(all_paths(v, path + (k,)))
    elif isinstance(d, list):
        for i, v in enumerate(d):
            out.append(path + (i,))
            out.extend(all_paths(v, path + (i,)))
    return out


def table_paths(d: Any, path: Path_ = ()) -> list[Path_]:
    """Every path to a table (the root included)."""
    out: list[Path_] = [path] if isinstance(d, dict) else []
    if isinstance(d, dict):
        for k, v in d.items():
            out.extend(table_paths(v, path + (k,)))
    elif isinstance(d, list):
        for i, v in enumerate(d):
            out.extend(table_paths(v, path + (i,)))
    return out


def get_at(d: Any, path: Path_) -> Any:
    for p in path:
        d = d[p]
    return d


def set_at(d: Any, path: Path_, value: Any) -> None:
    get_at(d, path[:-1])[path[-1]] = value


def del_at(d: Any, path: Path_) -> None:
    parent = get_at(d, path[:-1])
    del parent[path[-1]]


def show(path: Path_) -> str:
    s = ""
    for p in path:
        s += f"[{p}]" if isinstance(p, int) else (f".{p}" if s else str(p))
    return s or "(root)"


def short(v: Any) -> str:
    r = repr(v)
    return r if len(r) <= 60 else r[:57] + "..."


def misspell(draw, key: str) -> str:
    how = draw(st.sampled_from(["swap", "drop", "double", "upper", "dash", "plural", "space",
                                "prefix"]))
    if how == "swap" and len(key) > 1:
        i = draw(st.integers(0, len(key) - 2))
        return key[:i] + key[i + 1] + key[i] + key[i + 2:]
    if how == "drop" and len(key) > 1:
        i = draw(st.integers(0, len(key) - 1))
        return key[:i] + key[i + 1:]
    if how == "double" and key:
        i = draw(st.integers(0, len(key) - 1))
        return key[:i] + key[i] + key[i:]
    if how == "upper":
        return key.upper() if key != key.upper() else key.lower()
    if how == "dash" and "_" in key:
        return key.replace("_", "-")
    if how == "plural":
        return key + "s"
    if how == "space":
        return key + " "
    return "x" + key


# ============================================================================ mutations
#: tables whose keys are names the user chooses (a new or renamed key there is no unknown key)
FREE_TABLES = {("line_types",), ("set",)}


_ABSENT = object()


def _lookup(d: Any, path: Path_) -> Any:
    try:
        return get_at(d, path)
    except (KeyError, IndexError, TypeError):
        return _ABSENT


@dataclasses.dataclass
class Mutated:
    """A mutated structure, the steps taken, and the claims of the oracle: (path, reason,
    the object put there, or None for a key that must still exist), which hold only while
    the later steps left that path as it was."""

    data: dict
    steps: list[str]
    claims: list = dataclasses.field(default_factory=list)
    text_ops: list[str] = dataclasses.field(default_factory=list)

    def claim(self, path: Path_, reason: str, obj: Any = None) -> None:
        self.claims.append((path, reason, obj))

    @property
    def must_refuse(self) -> str:
        for path, reason, obj in self.claims:
            now = _lookup(self.data, path)
            if now is _ABSENT:
                continue
            if obj is None or (now is obj and category(now) == category(obj)):
                return reason
        return ""


def _free(path: Path_, free_tables) -> bool:
    return tuple(p for p in path if not isinstance(p, int)) in free_tables


def mutate_dict(draw, data: dict, *, n_max: int = 3, free_tables=FREE_TABLES,
                extra_values: list | None = None, protect: tuple = ()) -> Mutated:
    """Apply 1..n_max random mutations to a copy of a parsed TOML structure; say which must
    make a reader refuse it (``must_refuse``) by oracle."""
    d = copy.deepcopy(data)
    m = Mutated(d, [])
    ops = ["drop", "retype", "number", "number", "number", "string", "list", "unknown",
           "misspell", "swap", "array", "dup_text", "nan", "text"]
    for _ in range(draw(st.integers(1, n_max))):
        op = draw(st.sampled_from(ops))
        paths = [p for p in all_paths(d) if p[:len(protect)] != protect or not protect]
        if not paths:
            break
        if op == "dup_text":
            m.text_ops.append("dup")
            continue
        if op == "text":
            m.text_ops.append(draw(st.sampled_from(["crlf", "bom", "nul", "truncate",
                                                    "tabs"])))
            continue
        if op == "drop":
            p = draw(st.sampled_from(paths))
            del_at(d, p)
            m.steps.append(f"drop {show(p)}")
            continue
        if op == "unknown":
            tp = draw(st.sampled_from(table_paths(d)))
            table = get_at(d, tp)
            name = draw(st.sampled_from(["zz_unknown", "lenght", "Length", "length ", "",
                                         "\u540d\u524d", "x.y", "speed_", "anchor2", "note"]))
            value = draw(st.sampled_from([1.0, "x", True, [1.0], {}]))
            if name in table:
                continue
            table[name] = value
            m.steps.append(f"add unknown key {show(tp + (name,))} = {short(value)}")
            if not _free(tp, free_tables) and name not in KNOWN_KEYS:
                m.claim(tp + (name,), f"unknown key {show(tp + (name,))}")
            continue
        if op == "misspell":
            keyed = [p for p in paths if isinstance(p[-1], str)]
            if not keyed:
                continue
            p = draw(st.sampled_from(keyed))
            table = get_at(d, p[:-1])
            new = misspell(draw, p[-1])
            if new == p[-1] or new in table:
                continue
            # keep the order of the table: rebuild it
            items = [(new if k == p[-1] else k, v) for k, v in table.items()]
            table.clear()
            table.update(items)
            m.steps.append(f"misspell {show(p)} as {new!r}")
            if not _free(p[:-1], free_tables) and new not in KNOWN_KEYS:
                m.claim(p[:-1] + (new,), f"misspelt key {show(p[:-1] + (new,))}")
            continue
        if op == "swap":
            leaves = [p for p in paths if not isinstance(get_at(d, p), (dict, list))]
            if len(leaves) < 2:
                continue
            a, b = draw(st.sampled_from(leaves)), draw(st.sampled_from(leaves))
            va, vb = get_at(d, a), get_at(d, b)
            set_at(d, a, vb)
            set_at(d, b, va)
            m.steps.append(f"swap {show(a)} and {show(b)}")
            continue
        if op == "array":
            arrays = [p for p in paths if isinstance(get_at(d, p), list)]
            if not arrays:
                continue
            p = draw(st.sampled_from(arrays))
            arr = get_at(d, p)
            how = draw(st.sampled_from(["empty", "dup_first", "drop_last", "reverse",
                                        "append_nan", "nest"]))
            if how == "empty":
                arr.clear()
            elif how == "dup_first" and arr:
                arr.insert(0, copy.deepcopy(arr[0]))
            elif how == "drop_last" and arr:
                arr.pop()
            elif how == "reverse":
                arr.reverse()
            elif how == "append_nan":
                nan = float("nan")
                arr.append(nan)
                m.claim(p + (len(arr) - 1,), f"NaN appended to {show(p)}", nan)
            elif how == "nest":
                set_at(d, p, [copy.deepcopy(arr)])
            m.steps.append(f"array {show(p)}: {how}")
            continue
        # value replacements
        p = draw(st.sampled_from(paths))
        old = get_at(d, p)
        if op == "number" or op == "nan":
            if op == "nan":
                new = draw(st.sampled_from([NAN, INF, -INF]))
            else:
                how = draw(st.sampled_from(["special", "bound", "negate", "scale", "special"]))
                num = old if category(old) == "number" else 1.0
                if how == "special":
                    new = draw(st.sampled_from(SPECIAL_NUMBERS + (extra_values or [])))
                elif how == "bound" and BOUNDS:
                    new = draw(st.sampled_from(BOUNDS))
                elif how == "negate":
                    new = -num
                else:
                    k = draw(st.sampled_from([-300, -12, -6, -3, -1, 1, 3, 6, 12, 300]))
                    try:
                        new = float(num) * 10.0 ** k
                    except OverflowError:
                        new = INF
        elif op == "string":
            new = draw(st.sampled_from(SPECIAL_STRINGS))
        elif op == "list":
            new = draw(st.sampled_from(SPECIAL_LISTS + [[old], [old, old]]))
        else:                                # retype
            pool = [v for v in (SPECIAL_NUMBERS[:6] + SPECIAL_STRINGS[:6] + SPECIAL_LISTS[:4]
                                + SPECIAL_TABLES + [True, False])
                    if category(v) != category(old)]
            new = draw(st.sampled_from(pool))
        new = copy.deepcopy(new)
        if isinstance(new, float):
            new = float(repr(new)) if math.isfinite(new) else float(new)   # its own object
        set_at(d, p, new)
        m.steps.append(f"set {show(p)} = {short(new)} (was {short(old)})")
        if has_nonfinite(new):
            m.claim(p, f"non-finite value at {show(p)}", new)
        else:
            orig = _lookup(data, p)              # the type the file had there, before any step
            if (orig is not _ABSENT and category(orig) != category(new)
                    and category(orig) in ("number", "bool", "string", "array")
                    and not _free(p[:-1], free_tables)):
                m.claim(p, f"{show(p)}: {category(new)} where the file has a "
                        f"{category(orig)}", new)
    return m


def apply_text_ops(draw, text: str, ops: list[str]) -> tuple[str, list[str], str]:
    """Text-level mutations (after writing): a duplicated line (a key or table given twice),
    CRLF line ends, a byte-order mark, tabs, a NUL character, a truncation; returns (text,
    steps, what the reader must refuse)."""
    steps, must = [], ""
    for op in ops:
        if op == "dup":
            lines = text.splitlines()
            cand = [i for i, ln in enumerate(lines) if ln.strip()]
            if not cand:
                continue
            i = draw(st.sampled_from(cand))
            lines.insert(i + 1, lines[i])
            text = "\n".join(lines) + "\n"
            steps.append(f"line {i + 1} duplicated: {lines[i][:60]!r}")
            if not lines[i].lstrip().startswith("[["):
                must = must or f"duplicated key or table (line {i + 2})"
        elif op == "crlf":
            text = text.replace("\n", "\r\n")
            steps.append("CRLF line ends")
        elif op == "bom":
            text = "\ufeff" + text
            steps.append("a byte-order mark")
        elif op == "tabs":
            text = text.replace(" = ", "\t=\t")
            steps.append("tabs around '='")
        elif op == "nul":
            i = draw(st.integers(0, len(text)))
            text = text[:i] + "\x00" + text[i:]
            steps.append(f"a NUL character at {i}")
            must = must or "a NUL character"
        elif op == "truncate":
            i = draw(st.integers(0, len(text)))
            text = text[:i]
            steps.append(f"truncated to {i} characters")
    return text, steps, must


#: the fuzzers' seeds: the built-in scenes and the examples' scenes
SEED_PATHS = sorted([*(ROOT / "verification" / "scenes").rglob("*.toml"),
                     *(ROOT / "examples" / "scenes").glob("*.toml")])


def seed_dicts(paths) -> dict[str, dict]:
    """name -> parsed TOML of each seed file."""
    out = {}
    for p in sorted(paths):
        try:
            out[Path(p).stem] = tomllib.loads(Path(p).read_text(encoding="utf-8-sig"))
        except (OSError, ValueError):
            continue
    return out


# ============================================================================ running
def run_fuzz(strategy, check: Callable[[Any], None], max_examples: int) -> None:
    """Run ``check`` on ``max_examples`` examples of ``strategy``: reproducible (derandomized,
    no example database), no deadline, no shrinking (the checks record, never raise)."""

    @settings(max_examples=max_examples, deadline=None, derandomize=True, database=None,
              phases=[Phase.explicit, Phase.generate], print_blob=False,
              suppress_health_check=list(HealthCheck))
    @given(strategy)
    def inner(example):
        check(example)

    inner()


# ============================================================================ scenes from scratch
def _f(lo: float, hi: float):
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


@st.composite
def generated_scene(draw, name: str = "fz-generated") -> dict:
    """A small scene built from scratch (a few hundred metres of line: cheap to solve): a
    line type given by its section or by its wall, 1 to 3 segments (buoyancy, weight
    overrides), one of the four end forms, optional seabed, current, model, settings,
    dynamics and internal flow. Mostly valid; the mutations make it otherwise."""
    h = draw(_f(20.0, 400.0))                                   # hang-off height
    depth = draw(st.one_of(st.none(), st.just(h), _f(h, 3.0 * h)))
    env: dict = {}
    if draw(st.booleans()):
        env["gravity"] = draw(st.sampled_from([9.81, 9.8, 9.80665]))
        env["water_density"] = draw(st.sampled_from([1025.0, 1024.0, 1000.0]))
    if depth is not None:
        env["water_depth"] = depth
    bore = draw(st.booleans())
    if draw(st.booleans()):
        D = draw(_f(0.05, 0.6))
        lt = {"outer_diameter": D, "wall_thickness": D * draw(_f(0.03, 0.2)),
              "density": draw(st.sampled_from([7850.0, 7860.0, 4500.0, 2000.0])),
              "youngs_modulus": draw(st.sampled_from([2.07e11, 1.1e11, 5e9]))}
        bore = True
    else:
        D = draw(_f(0.03, 0.6))
        lt = {"outer_diameter": D, "mass_per_length": draw(_f(2.0, 400.0)),
              "axial_stiffness": draw(st.sampled_from([1e7, 1e8, 5e8, 2e9, 1e10])),
              "bending_stiffness": draw(st.sampled_from([1e2, 1e3, 1e4, 1e5, 1e6, 1e7]))}
        if bore:
            lt["inner_diameter"] = D * draw(_f(0.3, 0.9))
    for key, lo, hi in (("drag_normal", 0.0, 2.5), ("drag_tangential", 0.0, 0.5),
                        ("added_mass", 0.0, 2.0)):
        if draw(st.booleans()):
            lt[key] = draw(_f(lo, hi))
    if draw(st.integers(0, 5)) == 0:
        lt["compression"] = False
    if draw(st.integers(0, 5)) == 0:
        lt["max_strain"] = draw(_f(0.001, 0.05))
    form = draw(st.sampled_from(["fixed", "fixed", "fixed", "fixed", "tdp", "angle", "jlay"]))
    seabed = None
    if form != "fixed" or draw(st.booleans()):
        seabed = {"stiffness": draw(st.sampled_from([1e3, 1e4, 1e5, 1e6, 1e7]))}
        if draw(st.integers(0, 3)) == 0:
            seabed["friction"] = draw(_f(0.0, 1.0))
        if draw(st.integers(0, 3)) == 0:
            seabed["damping"] = draw(_f(0.0, 1.0))
    if form == "fixed":
        span = draw(_f(0.05 * h, 2.5 * h))
        y0 = 0.0 if seabed is not None or draw(st.booleans()) else draw(_f(0.0, 0.3 * h))
        chord = math.hypot(span, h - y0)
        total = chord * draw(st.sampled_from([0.99, 1.0005, 1.01, 1.05, 1.2, 1.5, 2.0]))
        ends = {"anchor": [0.0, y0], "hang_off": [span, h]}
        if draw(st.integers(0, 3)) == 0:      # 3D: the hang-off out of the anchor's plane
            ends["hang_off"].append(draw(_f(-0.5 * span, 0.5 * span)))
            chord = math.hypot(chord, ends["hang_off"][2])
            total = max(total, chord * 1.0005)
    else:
        total = h * draw(_f(1.2, 4.0))
        if form == "tdp":
            ends = {"tdp_tension": draw(st.sampled_from([1e3, 1e4, 1e5, 1e6]))}
        elif form == "angle":
            ends = {"hang_off_height": h}
            if draw(st.booleans()):
                ends["hang_off_angle_from_horizontal_deg"] = draw(_f(5.0, 89.0))
            else:
                ends["hang_off_angle_from_vertical_deg"] = draw(_f(1.0, 85.0))
        else:
            ends = {"hang_off_height": h, "top_tension": draw(st.sampled_from([1e4, 1e5, 1e6,
                                                                              1e7]))}
    nseg = draw(st.integers(1, 3))
    parts = [draw(_f(0.1, 1.0)) for _ in range(nseg)]
    segments = []
    for part in parts:
        seg: dict = {"line_type": "pipe", "length": total * part / sum(parts)}
        extra = draw(st.integers(0, 7))
        if extra == 1:
            seg["buoyancy"] = draw(_f(0.0, 3000.0))
        elif extra == 2:
            seg["submerged_weight"] = draw(_f(-500.0, 2000.0))
        elif extra == 3:
            seg["weight_scale"] = draw(st.sampled_from([-1.0, 0.5, 2.0]))
        elif extra == 4:
            seg["hydro_diameter"] = draw(_f(0.05, 1.0))
        elif extra == 5:
            seg["label"] = draw(st.sampled_from(["lower", "buoyancy section", "\u00e9 top"]))
        segments.append(seg)
    data: dict = {"name": name, "title": "generated by the fuzz tests"}
    if env:
        data["environment"] = env
    if depth is not None and draw(st.integers(0, 3)) == 0:
        top = depth
        u = draw(_f(-2.0, 2.0))
        current = {"heights": [0.0, top], "speeds": [0.0, u]}
        if draw(st.integers(0, 3)) == 0:      # 3D: a current turning with depth
            current["headings_deg"] = [draw(_f(-180.0, 180.0)), draw(_f(-180.0, 180.0))]
        else:
            current["heading_deg"] = draw(st.sampled_from([0.0, 180.0, 90.0, 45.0, -30.0]))
        data.setdefault("environment", {})["current"] = current
    if seabed is not None:
        data["seabed"] = seabed
    data["line_types"] = {"pipe": lt}
    data["segments"] = segments
    data["ends"] = ends
    if draw(st.integers(0, 4)) == 0:
        model = {}
        if draw(st.booleans()):
            model["axial"] = draw(st.sampled_from(["extensible", "inextensible"]))
        if draw(st.booleans()):
            model["seabed"] = draw(st.sampled_from(["elastic", "rigid"]))
        data["model"] = model
    if draw(st.booleans()):
        el = total / draw(st.sampled_from([20, 50, 100, 200, 300]))
        data["vfife"] = {"element_length": min(el, 1000.0)}
        if draw(st.integers(0, 3)) == 0:
            data["vfife"]["static_tolerance"] = draw(st.sampled_from([1e-4, 1e-3, 1e-2]))
        if draw(st.integers(0, 4)) == 0:
            data["vfife"]["clamped_ends"] = draw(st.sampled_from([["bottom"], ["top"],
                                                                  ["bottom", "top"]]))
    if draw(st.integers(0, 3)) == 0:
        data["bvp"] = {"tolerance": draw(st.sampled_from([1e-8, 1e-6, 1e-4, 1e-3]))}
    if draw(st.integers(0, 4)) == 0:
        data["analytic"] = {"model": draw(st.sampled_from(["composite", "piecewise",
                                                           "catenary"]))}
    if draw(st.integers(0, 5)) == 0:
        dur = draw(_f(1.0, 100.0))
        motion = ({"axis": draw(st.sampled_from(["x", "y", "z"])), "amplitude": draw(_f(0.0, 5.0)),
                   "period": draw(_f(0.5, dur / 1.5))} if draw(st.booleans()) else
                  {"axis": "x", "times": [0.0, dur / 2, dur], "displacements": [0.0, 1.0, 0.0]})
        data["dynamics"] = {"duration": dur, "output_interval": dur / 10, "top_motion": motion}
    if bore and depth is not None and draw(st.integers(0, 5)) == 0:
        lt["contents_density"] = draw(st.sampled_from([800.0, 1000.0]))
        flow: dict = {"speed": draw(_f(-10.0, 10.0))}
        if draw(st.booleans()):
            flow["slug"] = {"density_amplitude": draw(_f(0.0, 0.9)),
                            "slug_length": draw(_f(10.0, 200.0))}
        data["internal_flow"] = flow
    return data


# ============================================================================ paths given
#: names and paths a command is given instead of a file that holds a scene, sweep or deck
ODD_NAMES = ["", " ", ".", "..", "/", "~", "-", "x" * 300, "a/" + "x" * 300, "x" * 5000,
             "scr-stel", "scr-steel.toml", "verification", "/dev/null",
             "\u00e9.toml", "C:\\x.toml", "scr-steel\n", "nonexistent.toml",
             "nested/missing/x.toml", "*", "?", "%s", "{}", "$HOME", "\udcff.toml"]


def special_files(folder: Path) -> list[str]:
    """Files that hold no scene, sweep or deck, made in ``folder``: empty, binary, UTF-16,
    Latin-1, a directory, a FIFO (a read blocks), a dangling link, a link loop."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "empty.toml").write_bytes(b"")
    (folder / "binary.toml").write_bytes(bytes(range(256)) * 4)
    (folder / "utf16.toml").write_bytes("name = 'x'\n".encode("utf-16"))
    (folder / "latin1.toml").write_bytes("title = 'caf\xe9'\n".encode("latin-1"))
    (folder / "dir.toml").mkdir(exist_ok=True)
    out = [str(folder / n) for n in ("empty.toml", "binary.toml", "utf16.toml",
                                     "latin1.toml", "dir.toml")]
    for name, make in (("fifo.toml", lambda p: os.mkfifo(p)),
                       ("dangling.toml", lambda p: p.symlink_to(folder / "missing")),
                       ("loop-a.toml", lambda p: (p.symlink_to(folder / "loop-b.toml"),
                                                  (folder / "loop-b.toml").symlink_to(p)))):
        p = folder / name
        try:
            if not p.is_symlink() and not p.exists():
                make(p)
            out.append(str(p))
        except (OSError, AttributeError):
            pass
    return out


def run_path_fuzz(kind: str, read: Callable[[str], Any], folder: Path, max_examples: int
                  ) -> Tally:
    """Give ``read`` every odd name and special file, then ``max_examples`` generated names;
    each must end accepted or refused (one line naming the file)."""
    tally = Tally(kind)

    def check(name: str) -> None:
        inp = Input(name, f"the name or path {name!r:.120}")
        read_outcome(tally, inp, lambda: read(name), budget=3.0, path=name)

    for name in ODD_NAMES + special_files(folder):
        check(name)
    run_fuzz(st.text(st.characters(blacklist_characters="\x00"), max_size=40), check,
             max_examples)
    return tally

"""What every command of the command line shares: the error line, the parser that says
a bad option in one line, the numeric options' ranges, the progress display, the output
folder, the overrides of scene settings and the printing of warnings."""

from __future__ import annotations

import argparse
import dataclasses
import math
import os
import re
import sys
from dataclasses import dataclass
from pathlib import Path

from riser.errors import SceneError
from verification.runtime import outdir
from verification.runtime.progress import Progress

QUIET_HELP = ("no progress display (shown on stderr only when it is a terminal: a status "
              "line updated in place, with an ETA where the fraction done is known)")


def err(msg: str) -> None:
    """Print one ``error:`` line on stderr."""
    print(f"error: {msg}", file=sys.stderr)


class Parser(argparse.ArgumentParser):
    """argparse with the suite's one-line error: ``error: command line: --repeats: ...``
    (exit 2), not the usage block; its subcommands' parsers are of this class too."""

    def error(self, message: str):
        m = re.match(r"argument ([^:]+): (.*)", message, re.S)
        text = f"{m.group(1).split('/')[-1]}: {m.group(2)}" if m else message
        text = " ".join(text.split())
        self.exit(2, f"error: command line: {text} (`{self.prog} --help` lists the options)\n")


def _g(x: float) -> str:
    return f"{x:g}"


@dataclass(frozen=True)
class Range:
    """The allowed values of a numeric option: ``lo`` to ``hi`` (``lo`` excluded with
    ``lo_open``), integers only with ``integer``; ``unit`` and ``what`` for the message.
    ``scene_key``: the option overrides that scene key, whose own check (its field spec,
    :func:`check_overrides`) refuses it, with this range appended; :func:`check_ranges`
    leaves it to that check."""

    lo: float
    hi: float
    integer: bool = False
    lo_open: bool = False
    unit: str = ""
    what: str = ""
    scene_key: str = ""

    def text(self) -> str:
        """'between 1 and 50', '> 0 m and <= 1000 m'."""
        u = f" {self.unit}" if self.unit else ""
        if self.lo_open:
            return f"> {_g(self.lo)}{u} and <= {_g(self.hi)}{u}"
        return f"between {_g(self.lo)} and {_g(self.hi)}{u}"

    def allowed(self) -> str:
        """'allowed: between 1 and 50, modes per plane'."""
        return f"allowed: {self.text()}" + (f", {self.what}" if self.what else "")

    def message(self, got: str, kind: bool = False) -> str:
        """``kind``: say what kind of number (the value given is not one)."""
        what = f" ({self.what})" if self.what else ""
        kind_text = ("an integer " if self.integer else "a number ") if kind else ""
        return f"must be {kind_text}{self.text()}{what}, got {got}"

    def parse(self, text: str):
        """The argparse ``type``: a number (the range is checked by :func:`check_ranges`,
        after the command has cleared its output folder)."""
        try:
            return int(text) if self.integer else float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(self.message(repr(text), kind=True)) from None

    def holds(self, value) -> bool:
        if not math.isfinite(value) or value > self.hi:
            return False
        return value > self.lo if self.lo_open else value >= self.lo


def spec_range(settings_class, name: str, what: str) -> Range:
    """The :class:`Range` of a solver setting, from its field spec (riser/model/settings.py)."""
    sp = next(f for f in dataclasses.fields(settings_class) if f.name == name).metadata["spec"]
    lo = sp.gt if sp.gt is not None else sp.ge
    return Range(lo, sp.le, integer=sp.kind == "integer", lo_open=sp.gt is not None,
                 unit=sp.unit, what=what, scene_key=f"{settings_class.KEY_PREFIX}.{name}")


def add_ranged(parser, flag: str, rng: Range, **kwargs):
    """``parser.add_argument(flag, ...)`` for a numeric option with its allowed range (in
    its help, checked by :func:`check_ranges`)."""
    help_text = kwargs.pop("help", "")
    action = parser.add_argument(flag, type=rng.parse, metavar=kwargs.pop(
        "metavar", flag.lstrip("-").split("-")[0].upper()),
        help=f"{help_text}; {rng.text()}".lstrip("; "), **kwargs)
    action.range = rng
    ranges = dict(parser.get_default("_ranges") or {})
    ranges[action.dest] = (flag, rng)
    parser.set_defaults(_ranges=ranges)
    return action


def check_ranges(args, skip: tuple[str, ...] = ()) -> None:
    """Every numeric option given within its range, else a one-line :class:`SceneError`
    naming the option and the range (exit 2): ``error: command line: --repeats: must be
    between 1 and 100 (timed runs per setting), got 0``. ``skip``: options (dests) that
    a narrower check of the command takes over (a range that depends on the scene)."""
    for dest, (flag, rng) in (getattr(args, "_ranges", None) or {}).items():
        if dest in skip or rng.scene_key:
            continue
        value = getattr(args, dest, None)
        if value is not None and not rng.holds(value):
            raise SceneError("command line", flag, rng.message(_g(value)))


#: the most worker processes --jobs accepts (sweep, fatigue, reproduce)
MAX_JOBS = 1024
#: --jobs of ``sweep`` and ``fatigue``
JOBS = Range(1, MAX_JOBS, integer=True, what="local worker processes")


def jobs_of(args) -> int:
    """The local workers of ``--jobs`` (default: this machine's cores); ``--jobs`` with
    ``--scheduler`` is refused (SceneError naming ``--jobs``, exit 2)."""
    if args.jobs is None:
        return os.cpu_count() or 1
    check_ranges(args)
    if args.scheduler:
        raise SceneError("command line", "--jobs", "give --jobs (local workers) or "
                         "--scheduler (a Dask cluster's workers), not both")
    return args.jobs


def add_engine(parser, what: str) -> None:
    """``--jobs N`` and ``--scheduler ADDRESS`` (the engine of ``sweep`` and ``fatigue``;
    ``what``: the units they run, for the help)."""
    add_ranged(parser, "--jobs", JOBS, default=None, metavar="N",
               help="local worker processes (default: this machine's cores)")
    parser.add_argument("--scheduler", help=f"run the {what} on a Dask cluster instead: its "
                        "scheduler's address, tcp://host:port (the optional extra "
                        "[cluster]); probed first: one line within seconds if it is not one")


def _settings_ranges() -> tuple[Range, Range]:
    from riser.model.settings import BVPSettings, VFIFESettings
    return (spec_range(BVPSettings, "tolerance", "the BVP's tolerance, [bvp] tolerance"),
            spec_range(VFIFESettings, "element_length",
                       "the VFIFE's element length, [vfife] element_length"))


#: --tolerance and --element-length: the ranges of their scene keys
TOLERANCE, ELEMENT_LENGTH = _settings_ranges()


def progress_for(args, label: str) -> Progress:
    """The progress display of a long command (on a terminal, unless ``--quiet``)."""
    return Progress(label, quiet=getattr(args, "quiet", False))


def out_folder(args, default: Path, names: tuple[str, ...]) -> Path:
    """The output folder: ``--out`` (cleared before the scene was read, so that bad input
    leaves nothing stale) or ``default`` (known once the scene is), cleared now of the
    files ``names`` an earlier run left."""
    if args.out:
        return Path(args.out)
    outdir.clear(default, names)
    return default


def check_overrides(scene, args) -> None:
    """Validate the command-line overrides exactly like their scene keys (the settings'
    one validator), naming the option: ``error: command line: --element-length: ...``."""
    from riser.results.validity import check_resolution
    options = {"--tolerance": ("bvp", "tolerance", getattr(args, "tolerance", None)),
               "--element-length": ("vfife", "element_length",
                                    getattr(args, "element_length", None))}
    ranges = {"--tolerance": TOLERANCE, "--element-length": ELEMENT_LENGTH}
    for option, (table, key, value) in options.items():
        if value is None:
            continue
        try:
            getattr(scene, table).override(**{key: value})
        except SceneError as exc:                 # the key's range: said with it
            raise SceneError("command line", option,
                             f"{exc.message} ({ranges[option].allowed()})") from None
        if key == "element_length":
            try:
                check_resolution(scene, value, source="command line", key=option)
            except SceneError as exc:             # the scene's own limits
                raise SceneError("command line", option, exc.message) from None


def print_verdicts(label: str, summary: dict, strict: bool) -> int:
    """Print the design verdicts of one result (``label``: e.g. ``vfife on scr-steel``;
    ``summary``: its summary.json keys, :mod:`riser.design.verdicts`): each failed check
    as a ``design_fails:`` line (stdout, always), or the checks made that pass; with
    ``--strict`` a failed check fails the run (exit code 1, said on stderr), else 0."""
    from riser.design.verdicts import checks_made, design_failures
    made = checks_made(summary)
    if not made:
        return 0
    fails = design_failures(summary)
    for line in fails:
        print(f"  design_fails: {label}: {line}")
    if not fails:
        print(f"  design checks pass: {label}: {', '.join(made)}")
        return 0
    if strict:
        err(f"{label}: {len(fails)} design check(s) fail and --strict (design_fails in "
            "summary.json)")
        return 1
    return 0


def print_warnings(res, strict: bool) -> int:
    """Print a result's named warnings (stderr); with ``--strict`` they fail the run (the
    exit code: 1, else 0)."""
    for w in res.warnings:
        print(f"warning: {res.method}: {w}", file=sys.stderr)
    if strict and res.warnings:
        err(f"{res.method} on {res.scene}: {len(res.warnings)} warning(s) and --strict: the "
            "result is outside the model's validity (see summary.json 'warnings')")
        return 1
    return 0

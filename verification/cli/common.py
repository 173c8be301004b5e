"""What every command of the command line shares: the error line, the progress display,
the output folder, the overrides of scene settings and the printing of warnings."""

from __future__ import annotations

import sys
from pathlib import Path

from riser.errors import SceneError
from verification.runtime import outdir
from verification.runtime.progress import Progress

QUIET_HELP = ("no progress display (shown on stderr only when it is a terminal: a status "
              "line updated in place, with an ETA where the fraction done is known)")


def err(msg: str) -> None:
    """Print one ``error:`` line on stderr."""
    print(f"error: {msg}", file=sys.stderr)


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
    from riser.validity import check_resolution
    options = {"--tolerance": ("bvp", "tolerance", getattr(args, "tolerance", None)),
               "--element-length": ("vfife", "element_length",
                                    getattr(args, "element_length", None))}
    for option, (table, key, value) in options.items():
        if value is None:
            continue
        try:
            getattr(scene, table).override(**{key: value})
            if key == "element_length":
                check_resolution(scene, value, source="command line", key=option)
        except SceneError as exc:
            raise SceneError("command line", option, exc.message) from None


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

"""The OrcaFlex commands: ``import-orcaflex`` (one line of an OrcaFlex text data file ->
a scene file, :mod:`riser.io.orcaflex.scene_from_model`) and ``export-orcaflex`` (a scene
-> an OrcaFlex text data file, :mod:`riser.io.orcaflex.model_from_scene`). Parsing and
printing only; bad input raises :class:`~riser.errors.SceneError` naming the file and the
OrcaFlex item (or the scene key), which the command line prints as one line, exit 2."""

from __future__ import annotations

from pathlib import Path

from verification.catalog import resolve
from verification.runtime.outdir import output_file, write_file


def cmd_import_orcaflex(args) -> int:
    """``riser-verify import-orcaflex MODEL.yml [--line NAME] [--out SCENE.toml]
    [--statics]``."""
    from riser.io.orcaflex.scene_from_model import import_model
    model = Path(args.model)
    out = output_file(args.out, model.with_suffix(".toml"), f"{model.stem}.toml", model,
                      "model")
    text, scene, notes = import_model(model, line=args.line, statics=args.statics)
    write_file(out, text)
    for n in notes:
        print(f"  {n}")
    print(f"{model.name}: line {scene.title!r}, {len(scene.segments)} section(s), "
          f"{scene.total_length:g} m; wrote {out}")
    return 0


def cmd_export_orcaflex(args) -> int:
    """``riser-verify export-orcaflex SCENE [--out MODEL.yml]``."""
    from riser.io.orcaflex.model_from_scene import export_model
    scene = resolve(args.scene)
    out = output_file(args.out, Path("out") / scene.name / "orcaflex" / f"{scene.name}.yml",
                      f"{scene.name}.yml")
    text, notes = export_model(scene)
    write_file(out, text)
    for n in notes:
        print(f"  {n}")
    print(f"{scene.name}: one OrcaFlex line, {len(scene.segments)} section(s); wrote {out}")
    return 0


def add_parsers(sub) -> None:
    """The import-orcaflex and export-orcaflex subcommands."""
    s = sub.add_parser("import-orcaflex", help="one line of an OrcaFlex text data file -> a "
                       "scene file (needs the extra [orcaflex]: PyYAML)")
    s.add_argument("model", help="OrcaFlex text data file (.yml, or a .dat saved as text); "
                   "its include files are read from its folder")
    s.add_argument("--line", help="the line to import (required when the model has more "
                   "than one)")
    s.add_argument("--out", help="scene file to write (default: beside the model, its name "
                   "with .toml)")
    s.add_argument("--statics", action="store_true", help="leave out the waves, the "
                   "vessel's RAOs and the stages (said in the scene's notes): the line's "
                   "statics, when the model's waves are not the suite's")
    s.set_defaults(func=cmd_import_orcaflex)
    s = sub.add_parser("export-orcaflex", help="a scene -> an OrcaFlex text data file")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--out", help="model to write (default out/SCENE/orcaflex/SCENE.yml)")
    s.set_defaults(func=cmd_export_orcaflex)

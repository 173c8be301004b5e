"""The MoorDyn deck commands, added to the command line by the peer
(:data:`verification.peers.moordyn.PEER`): ``import-moordyn`` (a deck -> a scene file,
:mod:`riser.io.moordyn`) and ``export-moordyn`` (a scene -> a deck, :mod:`.deck`). Parsing
and printing only; bad input raises :class:`~riser.errors.SceneError` (a deck error
names the deck line), which the command line prints as one line with exit 2."""

from __future__ import annotations

from pathlib import Path

from verification.catalog import resolve
from verification.runtime.outdir import output_file, write_file


def cmd_import_moordyn(args) -> int:
    """``riser-verify import-moordyn DECK [--out SCENE.toml]``. The scene is named after
    the deck, whatever the file it is written to (any name, in any folder; an existing
    folder or a path ending in a separator gets DECK.toml inside it)."""
    from riser.io.moordyn.scene_from_deck import import_deck
    deck = Path(args.deck)
    out = output_file(args.out, deck.with_suffix(".toml"), f"{deck.stem}.toml", deck, "deck")
    text, scene, notes = import_deck(deck)
    write_file(out, text)
    for n in notes:
        print(f"  {n}")
    print(f"{deck.name}: {len(scene.segments)} segment(s), {scene.total_length:g} m; wrote {out}")
    return 0


def cmd_export_moordyn(args) -> int:
    """``riser-verify export-moordyn SCENE [--out DECK] [--segment-length H]``."""
    from .deck import check_segment_length, export
    scene = resolve(args.scene)
    check_segment_length(args.segment_length, "--segment-length", scene)
    path = Path(args.out) if args.out else Path("out") / scene.name / "moordyn" / f"{scene.name}.dat"
    files = export(scene, path, segment_length=args.segment_length)
    ex = files.export
    lines = ", ".join(f"{ln.length:g} m x {ln.segments}" for ln in ex.deck.lines)
    print(f"{scene.name}: {len(ex.deck.lines)} MoorDyn line(s) ({lines} segments), free "
          f"points from {files.joints_from}; wrote {files.deck_path}"
          + "".join(f" and {p}" for p in (files.profile_path, files.waves_path) if p))
    return 0


def add_parsers(sub) -> None:
    """The import-moordyn and export-moordyn subcommands."""
    s = sub.add_parser("import-moordyn", help="a MoorDyn v2 deck -> a scene file")
    s.add_argument("deck", help="MoorDyn v2 input file (current_profile.txt beside it if "
                   "Currents = 1, wave_frequencies.txt if WaveKin = 7)")
    s.add_argument("--out", help="scene file to write, any name in any folder (default: "
                   "beside the deck, its name with .toml); the scene is named after the deck")
    s.set_defaults(func=cmd_import_moordyn)
    s = sub.add_parser("export-moordyn", help="a scene -> a MoorDyn v2 deck")
    s.add_argument("scene", help="built-in scene name or path to a .toml scene file")
    s.add_argument("--out", help="deck to write (default out/SCENE/moordyn/SCENE.dat); "
                   "current_profile.txt and wave_frequencies.txt go beside it")
    s.add_argument("--segment-length", type=float,
                   help="MoorDyn segment length [m] (default: the scene's VFIFE element length)")
    s.set_defaults(func=cmd_export_moordyn)

"""The public corpus of OrcaFlex text data files (``tests/data/orcaflex/``): every line of
every file imported twice, as it is and with ``--statics``; each outcome is an imported
scene or the refusal's OrcaFlex item."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from riser.errors import SceneError
from riser.io.orcaflex.scene_from_model import import_model
from riser.io.orcaflex.text_file import read_model

from .published import FIXTURES


@dataclass(frozen=True)
class Outcome:
    """One import: the file, the line ('' for a file refused as a whole), the mode
    ('full' or 'statics'), the item refused ('' when imported) and the message."""

    fixture: str
    line: str
    mode: str
    item: str
    message: str

    @property
    def imported(self) -> bool:
        return not self.item


def outcomes(folder: Path = FIXTURES) -> list[Outcome]:
    """Every import of the corpus, by file, line and mode."""
    out = []
    for path in sorted(folder.glob("*.yml")):
        try:
            lines = [str(o.get("Name")) for o in read_model(path).objects("Lines")]
        except SceneError as exc:
            out.append(Outcome(path.name, "", "file", exc.key or "(file)", exc.message))
            continue
        for line in lines:
            for mode in ("full", "statics"):
                try:
                    _, scene, _ = import_model(path, line=line, statics=mode == "statics")
                    out.append(Outcome(path.name, line, mode, "",
                                       f"{len(scene.segments)} section(s), "
                                       f"{scene.total_length:g} m"))
                except SceneError as exc:
                    out.append(Outcome(path.name, line, mode, exc.key, exc.message))
    return out

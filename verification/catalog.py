"""Built-in scenes shipped in ``verification/scenes/`` and name-or-path resolution."""

from __future__ import annotations

from pathlib import Path

from riser.errors import SceneError
from riser.scene import Scene
from riser.scene_file import load_scene

SCENE_DIR = Path(__file__).parent / "scenes"


def builtin_paths() -> dict[str, Path]:
    """Built-in scene name -> file (searched recursively, e.g. scenes/hard/)."""
    return {p.stem: p for p in sorted(SCENE_DIR.rglob("*.toml"))}


def resolve(name_or_path: str) -> Scene:
    """Load a built-in scene by name, or a scene file by path."""
    p = Path(name_or_path)
    if p.suffix == ".toml" or p.exists():
        return load_scene(p)
    paths = builtin_paths()
    if name_or_path in paths:
        return load_scene(paths[name_or_path])
    raise SceneError(name_or_path, "", "no such file and no built-in scene of that name "
                     "(`riser-verify scenes` lists them)")


def list_builtin() -> list[tuple[str, str]]:
    """(name, title) of every built-in scene."""
    out = []
    for name, path in builtin_paths().items():
        out.append((name, load_scene(path).title))
    return out

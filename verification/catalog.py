"""Built-in scenes shipped in ``verification/scenes/`` and name-or-path resolution."""

from __future__ import annotations

import difflib
from pathlib import Path

from riser.errors import SceneError
from riser.io.scene_file import is_file, load_scene, path_problem
from riser.scene import Scene

SCENE_DIR = Path(__file__).parent / "scenes"


def builtin_paths() -> dict[str, Path]:
    """Built-in scene name -> file (searched recursively, e.g. scenes/hard/)."""
    return {p.stem: p for p in sorted(SCENE_DIR.rglob("*.toml"))}


def resolve(name_or_path: str) -> Scene:
    """Load a scene file by path, else a built-in scene by name.

    An existing file wins over a built-in name; a built-in name wins over a directory of
    the same name (e.g. an output folder). Raises :class:`SceneError` (one line naming what
    was given) when it is neither, saying how to list the built-in names and, for a near
    miss, which one was probably meant.
    """
    p = Path(name_or_path)
    paths = builtin_paths()
    if is_file(p):
        return load_scene(p)
    if name_or_path in paths:
        return load_scene(paths[name_or_path])
    if path_problem(p) is not None or p.exists() or p.is_symlink():
        return load_scene(p)     # a name too long, a directory, a device, a dangling link
    near = difflib.get_close_matches(p.stem if p.suffix == ".toml" else name_or_path,
                                     list(paths), n=1, cutoff=0.75)
    hint = f"; did you mean the built-in '{near[0]}'?" if near else ""
    what = ("cannot read file (no such file)" if p.suffix == ".toml" or len(p.parts) > 1
            else "no such file and no built-in scene of that name")
    raise SceneError(name_or_path, "", f"{what}; a scene is a .toml file or a built-in name "
                     f"(`riser-verify scenes` lists them){hint}")


def list_builtin() -> list[tuple[str, str]]:
    """(name, title) of every built-in scene."""
    out = []
    for name, path in builtin_paths().items():
        out.append((name, load_scene(path).title))
    return out

"""Built-in scenes shipped in ``verification/scenes/`` and name-or-path resolution."""

from __future__ import annotations

import difflib
from pathlib import Path

from riser.errors import SceneError
from riser.io.scene_file import is_file, load_scene, path_problem
from riser.model.scene import Scene

SCENE_DIR = Path(__file__).parent / "scenes"

#: scenes with a comparison report in reports/compare/ (the compare study; the bench's BVP
#: reference runs them too): every built-in scene but the hard cases, which are the stress
#: suite's, and the flow case, liu2021's
COMPARE_SCENES = ("wang2014-baseline", "wang2014-current-neg1p5", "wang2014-current-neg0p75",
                  "wang2014-current-0p75", "wang2014-current-1p5", "scr-steel",
                  "yu2021-a1", "yu2021-a2", "yu2021-a2-sheared", "yu2021-a3", "yu2021-a4",
                  "kang2015-jlay",
                  # 3D (issue 32): currents out of the plane of the ends, turning with depth,
                  # a hang-off out of the anchor's plane
                  "scr-steel-current-45", "scr-steel-current-90", "scr-steel-current-turning",
                  "yu2021-a3-current-45", "yu2021-a3-current-90", "yu2021-a3-current-turning",
                  "yu2021-a3-hang-off-offset",
                  # end conditions and point attachments (issue 35): a top-tensioned riser
                  # clamped at the wellhead, a lazy wave on a flex joint, a chain mooring
                  # with a clump weight
                  "ttr-steel", "lazy-wave-flex-joint", "mooring-clump-weight")


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

"""MoorDyn decks in and out for the command line and the MoorDyn peer: the scene a deck
becomes, and the deck of any scene (a touchdown-form scene converted to fixed ends first,
exactly as both methods solve it, :func:`verification.pipeline.vfife_equivalent`)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from riser.errors import SceneError
from riser.io.moordyn.deck_from_scene import ExportedDeck, export_scene
from riser.io.moordyn.waves import WAVE_FILE
from riser.model.scene import FixedEnds, Scene
from verification import pipeline
from verification.runtime.interrupts import reraise_interrupt


def check_segment_length(value: float | None, option: str, scene) -> None:
    """A MoorDyn segment length given as ``option`` [m]: 0.01-1000 m and at least ten
    segments over the line (MoorDyn's tolerances are stated per segment length); raises a
    one-line :class:`SceneError` naming the option (exit 2, before anything runs)."""
    if value is None:
        return
    top = min(1000.0, scene.total_length / 10.0)
    if not 0.01 <= value <= top:
        raise SceneError("command line", option, f"must be between 0.01 and {top:g} m (at "
                         f"least ten segments over the {scene.total_length:g} m line), got "
                         f"{value:g}")


@dataclass
class DeckFiles:
    """An exported deck: the fixed-ends scene it describes, the export, the files written
    (the deck, current_profile.txt beside it with a current, wave_frequencies.txt with
    waves), the arc-length shift [m] from the fixed-ends scene back to the original
    scene's s (0 for fixed ends), and where the joints' initial positions came from."""

    scene: Scene
    export: ExportedDeck
    deck_path: Path | None
    profile_path: Path | None
    s_shift: float
    joints_from: str
    waves_path: Path | None = None


def fixed_scene(scene: Scene) -> tuple[Scene, float, str]:
    """(the fixed-ends scene MoorDyn solves, the arc-length shift, the conversion note)."""
    if isinstance(scene.ends, FixedEnds):
        return scene, 0.0, ""
    eq = pipeline.vfife_equivalent(scene)
    return eq.scene, eq.s_shift, eq.note


def joint_guess(scene: Scene, spans, profile=None) -> tuple[list | None, str]:
    """Scene (x, y, z) of the joints between MoorDyn lines, from ``profile`` (a solved
    profile of the fixed-ends scene) or a solve of it (the BVP's; the VFIFE's for a 3D
    scene); (None, reason) when neither is available (the export then puts them on the
    chord)."""
    if len(spans) < 2:
        return None, "no joints"
    how = "the given profile"
    if profile is None:
        method = "bvp" if scene.statics_planar else "vfife"
        try:
            res = pipeline.solve_scene(scene, method)
        except Exception as exc:    # noqa: BLE001 - only MoorDyn's first guess depends on it
            reraise_interrupt(exc)  # a Ctrl-C (in Numba) stops the export
            return None, f"the chord (the {method.upper()} failed: {exc})"
        if not res.converged:
            return None, (f"the chord (the {method.upper()} did not converge: "
                          f"{res.status.value})")
        profile, how = res.profile, f"the {method.upper()} solution"
    s = np.array([a for a, _ in spans[1:]])
    pts = [tuple(float(np.interp(si, profile.s, getattr(profile, c))) for c in "xyz")
           for si in s]
    return pts, how


def export(scene: Scene, path: Path | None, *, segment_length: float | None = None,
           profile=None, hang_off: str = "Fixed", ic: dict | None = None,
           waves: bool = True, joints=None) -> DeckFiles:
    """Export ``scene`` (any end form) and, when ``path`` is given, write the deck there and
    current_profile.txt and wave_frequencies.txt beside it (MoorDyn reads them from the
    deck's folder). ``waves``: False writes still water (MoorDyn's statics).
    ``joints``: (positions, where they came from) of the free points, instead of a solve
    (the same deck with and without its waves)."""
    fixed, shift, note = fixed_scene(scene)
    first = export_scene(fixed, segment_length=segment_length, hang_off=hang_off, ic=ic,
                         waves=waves)
    joints, how = joints or joint_guess(fixed, first.line_span, profile)
    notes = [f"Converted from the '{scene.ends.kind}' form: {note}"] if note else []
    if len(first.line_span) > 1:
        notes.append(f"The free points start from {how}.")
    ex = export_scene(fixed, segment_length=segment_length, joints=joints, hang_off=hang_off,
                      ic=ic, notes=tuple(notes), waves=waves)
    deck_path = profile_path = waves_path = None
    if path is not None:
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(ex.text)
        deck_path = path
        if ex.current_profile is not None:
            profile_path = path.parent / "current_profile.txt"
            profile_path.write_text(ex.current_profile)
        if ex.wave_frequencies is not None:
            waves_path = path.parent / WAVE_FILE
            waves_path.write_text(ex.wave_frequencies)
    return DeckFiles(fixed, ex, deck_path, profile_path, shift, how, waves_path)

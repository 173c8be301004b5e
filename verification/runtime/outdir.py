"""Output folders: a run never leaves another run's results beside its own.

Every command that writes into a folder first removes the files *it* writes (the names
below, and nothing else: a foreign file in the folder is kept, the folder itself is never
removed), before it reads its input. So a run that is refused (exit 2), fails (exit 1) or
is interrupted leaves no profile, table or report of an earlier run that could be taken
for its own; a failed solve still writes a ``summary.json`` stating the failure
(:meth:`riser.results.result.SolveResult.write`). The same step checks that the folder can be
written (:func:`check_writable`), so a read-only folder is bad input said before any
solving, not a lost result at the end.

The lists are checked against what the commands write (``tests/test_input_hygiene.py``
compares them with the committed ``reports/`` folders and a real solve): a new output file
must be added here.
"""

from __future__ import annotations

import contextlib
import errno
import os
from pathlib import Path

from riser.errors import SceneError
from riser.io.scene_file import path_problem

#: ``solve``: one result (SolveResult.write; the rest: a VFIFE dynamic run, its plots, and
#: states.npz with ``[dynamics] save_states``; utilisation.png with ``[design]``)
SOLVE = ("profile.csv", "summary.json", "timeseries.csv", "envelope.csv", "states.npz",
         "timeseries.png", "envelope.png", "utilisation.png")
#: ``compare`` (and each scene folder of ``reproduce compare``): the protocol's files and
#: one solve folder per method and for the analytic and ANCF columns (a peer's column adds its own
#: files: ``verification.peers.Peer.files``)
COMPARE = ("agreement.csv", "report.md", "configurations.png", "forces.png", "differences.png",
           *(f"{sub}/{name}" for sub in ("bvp", "vfife", "analytic", "ancf", "bvp_paper_model")
             for name in SOLVE))
#: ``cost`` (and each scene folder of ``reproduce cost``)
COST = ("runs.csv", "values.csv", "report.md", "error_vs_time.png",
        "error_vs_element_length.png", "time_vs_elements.png", "dynamics.csv",
        "dynamics_error.png", "dynamics_ancf.csv", "dynamics_ancf.png")
#: ``modes`` (and each scene folder of ``reproduce modes``)
MODES = ("modes.csv", "agreement.csv", "report.md", "mode_shapes_in_plane.png",
         "mode_shapes_out_of_plane.png", "mode_shapes_coupled.png")
#: of those, the plots of a planar static state's two families, and a 3D one's family
MODES_PLANAR_PLOTS = ("mode_shapes_in_plane.png", "mode_shapes_out_of_plane.png")
MODES_COUPLED_PLOTS = ("mode_shapes_coupled.png",)
#: each scene folder of ``reproduce cross_current``
CROSS_CURRENT = ("agreement.csv", "headings.csv", "headings.png", "report.md")
#: each unit folder of ``reproduce sea_states``: its files (two-methods: a folder per scene
#: holding its comparison's files); ``SEA_STATES`` all of them (what a unit clears)
SEA_STATES_UNITS = {
    "lowe-langley": ("tension.csv", "cases.csv", "tension.png", "report.md"),
    "two-methods": ("agreement.csv", "cases.csv", "report.md",
                    *(f"{scene}/{name}" for scene in ("jumper-wave", "jumper-wave-45",
                                                      "jumper-vessel-wave")
                      for name in ("dynamic_agreement.csv", "stations.csv", "response.csv",
                                   "transfer.csv", "transfer_along_s.csv", "response.png",
                                   "sweep.png", "transfer.png", "report.md",
                                   "dynamic_agreement_ancf.csv")),
                    *(f"jumper-sea/{name}" for name in (
                        "sea_agreement.csv", "sea_along_s.csv", "spectra.csv",
                        "sea_response.png", "spectra.png", "sea_tension.png",
                        "report.md")))}
SEA_STATES = tuple(dict.fromkeys(f for files in SEA_STATES_UNITS.values() for f in files))
#: each unit folder of ``reproduce design``: its files; ``DESIGN`` all of them
DESIGN_UNITS = {
    "utilisation": ("utilisation.csv", "cases.csv", "utilisation.png", "report.md"),
    "fatigue": ("stations.csv", "sea_states.csv", "fatigue_along_s.csv", "fatigue.png",
                "report.md")}
# the fatigue in seas 45 and 90 deg off the line's plane (issue 50): the fatigue's files
DESIGN_UNITS.update({unit: DESIGN_UNITS["fatigue"] for unit in ("fatigue-45", "fatigue-90")})
DESIGN = tuple(dict.fromkeys(f for files in DESIGN_UNITS.values() for f in files))
#: ``fatigue SCENE``: the fatigue unit's files and its summary.json (the verdict's keys);
#: its units' records in ``cells/`` are kept (a rerun resumes from them)
FATIGUE = DESIGN_UNITS["fatigue"] + ("summary.json",)
#: ``reproduce orcaflex``: public OrcaFlex models, the corpus, the round trip
ORCAFLEX = ("published.csv", "corpus.csv", "round_trip.csv", "profiles.png", "report.md")
#: ``reproduce ends``: the end conditions and attachments against their closed forms
ENDS = ("closed_forms.csv", "report.md", "deflection.png", "chain_modes.png")
#: ``stress`` and ``reproduce stress``
STRESS = ("summary.csv", "report.md")
#: ``bench``
BENCH = ("bench.json",)
#: ``bench --sweep``: the sweep throughput of the engines
BENCH_SWEEP = ("sweep.json",)
#: ``bench --fatigue``: the fatigue throughput of the engines
BENCH_FATIGUE = ("fatigue.json",)
#: ``compare SCENE --time-domain`` (verification.comparison.nonlinear.report.FILES)
TIME_DOMAIN = ("agreement.csv", "tolerances.csv", "runs.csv", "controls.csv", "report.md",
               "timeseries.png", "envelopes.png")
#: each unit folder of ``reproduce nonlinear``: its case folders (each with
#: :data:`TIME_DOMAIN`), ``cases.csv`` and ``report.md``; ``NONLINEAR`` all of them
NONLINEAR_CASES = {"scr-steel-heave": ("heave-0.1m", "heave-1m", "heave-3m", "heave-6m"),
                   "yu2021-a3-surge": ("surge",), "lowe-langley": ("case4",),
                   "storm": ("short-record", "record")}
NONLINEAR = ("cases.csv", "report.md") + tuple(dict.fromkeys(
    f"{case}/{name}" for cases in NONLINEAR_CASES.values() for case in cases
    for name in TIME_DOMAIN))
#: the files of each study of ``reproduce`` in its folder (compare and cost: in each
#: unit's subfolder ``NAME/SCENE``)
STUDY_FILES = {
    "wang2014": ("table2.csv", "drag_fit.csv", "vfife_matched.csv", "configurations.png",
                 "forces.png", "report.md"),
    "yu2021": ("table.csv", "report.md", "layout.png", "gap.png", "buoyancy_loss.png",
               "current.png", "moved_up.png", "dynamics.csv", "dynamics.png"),
    "liu2021": ("table.csv", "report.md", "top_tension.png", "static.png", "moments.png",
                "slug_length.png", "methods.csv", "methods.png"),
    "kang2015": ("table.csv", "piecewise.csv", "epsilon.csv", "report.md", "base.png",
                 "matched.png", "families.png", "epsilon.png"),
    "compare": COMPARE,
    "stress": STRESS,
    "cost": COST,
    "modes": MODES,
    "cross_current": CROSS_CURRENT,
    "sea_states": SEA_STATES,
    "design": DESIGN,
    "ends": ENDS,
    "nonlinear": NONLINEAR,
    "orcaflex": ORCAFLEX,
    # the static comparison of each scene (without the paper model) beside its cases
    "dynamics": ("cases.csv", "convergence.csv", "report.md") + tuple(
        f for f in COMPARE if not f.startswith("bvp_paper_model/")),
}


def output_file(out: str | None, default: Path, name: str, source: Path | None = None,
                what: str = "") -> Path:
    """The file a command writes: ``out`` (``--out``: any file name in any folder; an
    existing folder, or a path ending in a separator, gets ``name`` inside it), else
    ``default``. With ``source`` (the file read, called ``what``), a SceneError naming
    ``--out`` when the file written would be it."""
    path = Path(out) if out else default
    if out and (path.is_dir() or out.endswith(("/", "\\"))):
        path = path / name
    if source is not None and path.resolve() == source.resolve():
        raise SceneError("command line", "--out", f"{path} is the {what} itself; give "
                         "another file for the scene")
    return path


def write_file(path: Path, text: str, option: str = "--out") -> None:
    """Write ``text`` to ``path`` (its folders made); a SceneError naming ``option`` when
    it cannot be written."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    except OSError as exc:
        raise SceneError("command line", option, f"cannot write {path} "
                         f"({exc.strerror or exc})") from None


def check_writable(folder: str | Path) -> None:
    """Raise :class:`SceneError` (exit 2, naming ``--out``) unless files can be written in
    ``folder``: the folder is created if missing (and the folders above it), a probe file
    is written, flushed and deleted, and the folders created for the test are removed
    again. So a read-only or full folder is said before any solving, not found when the
    results are written (the results of a long run were lost to an ``unexpected OSError``).
    """
    base = Path(folder)
    created: list[Path] = []
    try:
        for d in reversed([base, *base.parents]):
            if not d.exists():
                try:
                    d.mkdir()
                except OSError as exc:
                    raise SceneError(str(base), "--out", f"cannot be created: {d}: "
                                     f"{exc.strerror or exc}; choose a folder you can write "
                                     "to") from None
                created.append(d)
        probe = base / f".riser-verify-write-test-{os.getpid()}"
        try:
            fd = os.open(probe, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
            try:
                os.write(fd, b"riser-verify: can this folder be written?\n")
                os.fsync(fd)
            finally:
                os.close(fd)
            os.unlink(probe)
        except OSError as exc:
            with contextlib.suppress(OSError):
                probe.unlink()
            raise SceneError(str(base), "--out", f"cannot be written: "
                             f"{exc.strerror or exc}; choose a folder you can write to") from None
    finally:
        for d in reversed(created):
            with contextlib.suppress(OSError):
                d.rmdir()


def check_folder(folder: str | Path) -> bool:
    """Raise :class:`SceneError` (exit 2, naming ``--out``) unless ``folder`` is, or can
    be, a folder that can be written (:func:`check_writable`); True when it exists
    (nothing is removed: :func:`clear` removes an earlier run's files)."""
    base = Path(folder)
    # a name too long or a loop of links: Path.exists would raise OSError (a file above
    # the folder is said below, with the file named)
    problem = path_problem(base, (errno.ENAMETOOLONG, errno.ELOOP))
    if problem is not None:
        raise SceneError(str(base), "--out", f"cannot be used: {problem}")
    if not base.exists():
        # it is created later: the nearest existing folder above it must be a folder
        above = next((a for a in base.parents if a.exists()), None)
        if above is not None and not above.is_dir():
            raise SceneError(str(base), "--out", f"cannot be created: {above} is a file, not "
                             "a folder")
        check_writable(base)
        return False
    if not base.is_dir():
        raise SceneError(str(base), "--out", "is a file, not a folder: give a folder for the "
                         "results (it is created if missing)")
    check_writable(base)
    return True


def clear(folder: str | Path | None, names: tuple[str, ...]) -> list[Path]:
    """Remove the files ``names`` (paths relative to ``folder``) left by an earlier run, and
    the subfolders among them that this leaves empty; returns the removed files.

    ``folder`` None (the command's default folder, not known yet): nothing to do. Raises
    :class:`SceneError` (exit 2, before any solving) when ``folder`` is not a folder (or
    cannot be one: a file where a folder above it should be), cannot be written
    (:func:`check_writable`: read-only, or cannot be created) or a stale file cannot be
    removed, so no old result survives unnoticed and no result is lost at the end.
    """
    if folder is None:
        return []
    base = Path(folder)
    if not check_folder(base):
        return []
    removed = []
    subfolders = set()
    for name in names:
        p = base / name
        if p.parent != base:
            subfolders.add(p.parent)
        if p.is_symlink() or p.is_file():
            try:
                p.unlink()
            except OSError as exc:
                raise SceneError(str(base), "--out", f"cannot remove {name} of an earlier run "
                                 f"({exc.strerror or exc}); remove it or choose another "
                                 "folder") from None
            removed.append(p)
    for sub in sorted(subfolders, key=lambda q: -len(q.parts)):
        try:
            sub.rmdir()                     # only when empty: foreign files keep it
        except OSError:
            pass
    return removed


def unit_folder(unit: str | None, study_folder: str | Path) -> Path:
    """The folder one unit of ``reproduce`` writes: ``study_folder/unit`` for the studies
    with a folder per unit, else ``study_folder``."""
    return Path(study_folder) / unit if unit is not None else Path(study_folder)


def staging_folder(unit: str | None, study_folder: str | Path) -> Path:
    """The temporary study folder a unit writes into before :func:`swap_in` (beside its
    report, so that the files move by a rename; ``.gitignore``: ``.partial-*``)."""
    return Path(study_folder) / f".partial-{unit or 'all'}-{os.getpid()}"


def swap_in(staged: str | Path, final: str | Path, names: tuple[str, ...]) -> list[str]:
    """Replace the report in ``final`` by the one a unit wrote into ``staged`` (only once it
    succeeded: an interrupted or failed unit never gets here, and its old report stays
    whole): each staged file moves over its old copy by ``os.replace`` (atomic per file),
    the files ``names`` of the old report that the new one has not are removed, foreign
    files are kept; ``staged`` is removed. Returns the files moved (relative paths)."""
    staged, final = Path(staged), Path(final)
    final.mkdir(parents=True, exist_ok=True)
    moved = []
    for p in sorted(q for q in staged.rglob("*") if q.is_file()):
        rel = p.relative_to(staged)
        (final / rel).parent.mkdir(parents=True, exist_ok=True)
        os.replace(p, final / rel)
        moved.append(rel.as_posix())
    clear(final, tuple(n for n in names if n not in set(moved)))
    discard(staged)
    return moved


def discard(staged: str | Path) -> None:
    """Remove a staging folder and everything in it (a failed or interrupted unit's)."""
    staged = Path(staged)
    if not staged.exists():
        return
    for p in sorted(staged.rglob("*"), key=lambda q: -len(q.parts)):
        with contextlib.suppress(OSError):
            p.rmdir() if p.is_dir() and not p.is_symlink() else p.unlink()
    with contextlib.suppress(OSError):
        staged.rmdir()


def discard_stale(study_folder: str | Path, unit: str | None) -> None:
    """Remove the staging folders an interrupted earlier run of ``unit`` left."""
    base = Path(study_folder)
    if base.is_dir():
        for p in base.glob(f".partial-{unit or 'all'}-*"):
            discard(p)


def clear_unit(study: str, unit: str | None, study_folder: str | Path) -> list[Path]:
    """Clear what one unit of ``reproduce`` writes: ``study_folder/unit`` for the studies
    with a folder per unit (compare, cost, modes, cross_current, sea_states, design), else
    ``study_folder``."""
    folder = Path(study_folder) / unit if unit is not None else Path(study_folder)
    return clear(folder, STUDY_FILES[study])

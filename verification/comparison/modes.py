"""Cross-method modal analysis: the natural modes of one scene by both methods, and their
agreement (``riser-verify modes SCENE [--count N] [--out DIR]``), with further methods'
modes as further columns (the command's :data:`COLUMNS`: the ANCF).

Both methods analyse the same fixed-ends scene, :func:`verification.pipeline.
vfife_equivalent` of the scene (a Wang-form scene is converted; its arc lengths are then
reported from the BVP touchdown, the converted s minus ``s_shift``), each about its own
static equilibrium (``bvp.modal.modes.solve_modes``, ``vfife.modal.modes.solve_modes``; the shared
model is stated in :mod:`riser.results.modes`, its equations in :mod:`bvp.modal.modes`: undamped, the
static drag of a current frozen as a dead load). Modes are paired by plane and number (about
a 3D static state the one ``coupled`` family, by number: two methods that order two close
modes differently fail on the MAC, never silently pass); the
agreement of a pair is the relative frequency difference of the VFIFE from the BVP and
the MAC of the two shapes interpolated on the VFIFE's nodes (inside the arc-length range
both cover). The target: |difference| <= 0.5 % and MAC >= 0.99.

A further column (``run_modes(..., columns=("ancf",))``, what the command passes:
:data:`COLUMNS`) is another method's modes of the same fixed-ends scene
(``ancf.modal.solve_modes``), paired with the BVP's the same way (its frequency over the
BVP's - 1, the MAC on its own samples) and judged with the same target: its rows
(``ModesRun.columns[NAME]``) are in the verdict (``all_meet``) unless the method refuses
the scene (then its result says why, and no row). The BVP-VFIFE rows (``ModesRun.rows``)
are unchanged by a column.

Files written into ``out``: see :data:`FILES`. ``modes.csv`` (columns ``method, plane,
mode, frequency_hz, period_s``; a further column's modes are rows of its method) and
``agreement.csv`` (``plane, mode, bvp_frequency_hz, vfife_frequency_hz, rel_diff, mac``,
then per further column ``NAME_frequency_hz, NAME_rel_diff, NAME_mac``) are read by other
tools: keep their columns (a further column's come after them).
"""

from __future__ import annotations

import csv
import dataclasses
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from riser.callbacks import with_fraction
from riser.errors import UnsupportedSceneError
from riser.results.modes import COUPLED, PLANES, ModalResult, mac, shape_at
from riser.results.result import Status
from verification.methods import method
from verification.pipeline import vfife_equivalent
from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, md_table, pct, timed
from verification.runtime import outdir

from .row import Row, Tolerance, Verdict

#: agreement target: largest |relative frequency difference| and smallest MAC
TARGET_REL_DIFF = 0.005
TARGET_MAC = 0.99
#: modes drawn per plane in the shape plots
PLOTTED = 4
#: the files ``run_modes`` writes (the ``modes`` command clears them first)
FILES = outdir.MODES
MODES_COLUMNS = ("method", "plane", "mode", "frequency_hz", "period_s")
AGREEMENT_COLUMNS = ("plane", "mode", "bvp_frequency_hz", "vfife_frequency_hz", "rel_diff",
                     "mac")
#: a further column's agreement.csv columns, after :data:`AGREEMENT_COLUMNS`
#: (``NAME_frequency_hz``, ...)
COLUMN_SUFFIXES = ("frequency_hz", "rel_diff", "mac")
#: the further methods the ``modes`` command shows beside the BVP and the VFIFE
COLUMNS = ("ancf",)
#: the methods' names in the report and on the console
LABELS = {"bvp": "BVP", "vfife": "VFIFE", "ancf": "ANCF"}
PLANE_TITLES = {"in_plane": "in-plane (x, y)", "out_of_plane": "out-of-plane (z)",
                COUPLED: "coupled (x, y, z) about the 3D static state"}
#: the families a run can hold: the two planes of a planar static state, or the one
#: coupled family of a 3D one (riser/results/modes.py)
FAMILIES = (*PLANES, COUPLED)


@dataclass
class ModesRun:
    """Outcome of :func:`run_modes`: the scene's name, the two :class:`ModalResult`
    (``results['bvp']``, ``results['vfife']``, arc lengths in the scene's coordinate; and
    a further column's, ``results['ancf']``), the
    agreement ``rows`` (a :class:`~.row.Row` per mode pair: the frequencies [Hz] of
    both, their relative difference, ``plane``, ``mode`` and ``mac`` beside; its verdict
    the target's, on both the frequency and the MAC), the
    conversion ``note`` and ``s_shift`` [m], the output folder and the files written;
    ``columns`` a further column's rows against the BVP by its name (the same Rows, its
    name instead of ``vfife``; absent when it refused the scene)."""

    scene: str
    results: dict[str, ModalResult]
    rows: list[Row]
    note: str = ""
    s_shift: float = 0.0
    out: Path | None = None
    files: list[str] = field(default_factory=list)
    wall_time_s: float = 0.0
    columns: dict[str, list[Row]] = field(default_factory=dict)

    @property
    def judged(self) -> tuple[str, ...]:
        """The methods in the verdict: the two, and the further columns that ran."""
        return ("bvp", "vfife", *self.columns)

    @property
    def all_meet(self) -> bool:
        """Every pair found by both methods meets the target and both converged (and so
        for every further column that did not refuse the scene)."""
        return (all(self.results[n].converged for n in self.judged if n in self.results)
                and bool(self.rows) and all(r.passed for r in self.rows)
                and all(r.passed for rows in self.columns.values() for r in rows))


def _shifted(res: ModalResult, s_shift: float) -> ModalResult:
    """``res`` with ``s_shift`` subtracted from every mode's arc lengths."""
    if s_shift:
        res.modes = [dataclasses.replace(m, s=m.s - s_shift) for m in res.modes]
    return res


#: the target of a mode pair, as a row's tolerance (its MAC judged with it)
TARGET = Tolerance(TARGET_REL_DIFF, None, "the BVP's frequency",
                   f"{100 * TARGET_REL_DIFF:g} % and MAC >= {TARGET_MAC:g}",
                   "two discretisations of one linearised model: the static agreement's "
                   "order (0.5 %), and shapes that are the same mode (MAC)", relative=True)


def pair_rows(bvp_res: ModalResult, vf_res: ModalResult, name: str = "vfife") -> list[Row]:
    """Agreement rows of the modes both results hold, by plane and number; ``vf_res`` is
    the result of the method ``name`` (its value's key in the rows)."""
    rows = []
    for plane in FAMILIES:
        vf_modes = {m.number: m for m in vf_res.family(plane)}
        for b in bvp_res.family(plane):
            v = vf_modes.get(b.number)
            if v is None:
                continue
            lo, hi = max(b.s[0], v.s[0]), min(b.s[-1], v.s[-1])
            s = v.s[(v.s >= lo) & (v.s <= hi)]
            m = mac(shape_at(b, s), shape_at(v, s))
            rel = v.frequency_hz / b.frequency_hz - 1.0 if b.frequency_hz > 0 else float("nan")
            rows.append(Row("frequency", {"bvp": b.frequency_hz, name: v.frequency_hz},
                            "Hz", v.frequency_hz - b.frequency_hz, rel, TARGET,
                            Verdict.of(bool(abs(rel) <= TARGET_REL_DIFF and m >= TARGET_MAC)),
                            extra={"plane": plane, "mode": b.number, "mac": m}))
    return rows


def run_modes(scene, count: int = 10, out: str | Path | None = None,
              progress=None, columns: tuple[str, ...] = ()) -> ModesRun:
    """Modes of ``scene`` by both methods, their agreement, and (``out`` given) the files
    :data:`FILES` in ``out``. ``columns``: further methods (names of
    :data:`verification.methods.METHODS` with modes; the command passes :data:`COLUMNS`),
    each paired with the BVP and judged with the same target (the module docstring).
    Raises SceneError / UnsupportedSceneError (refused before solving by the BVP or the
    VFIFE; a further column's refusal is its result's status) and SolveFailed (the BVP of
    a Wang-form scene's conversion failed); a modal analysis that fails is reported in its
    result's status."""
    if count < 1:
        raise ValueError(f"count must be >= 1, got {count}")
    columns = tuple(columns)
    for name in columns:
        if name in ("bvp", "vfife") or method(name).modes is None:
            raise ValueError(f"a further column must be a method with modes other than the "
                             f"bvp and the vfife, got {name!r}")
    say = with_fraction(progress) or (lambda message, fraction=None: None)
    t0 = time.perf_counter()
    say("modes: fixed-ends scene", fraction=0.0)
    eq = vfife_equivalent(scene)
    results = {}
    names = ("bvp", "vfife", *columns)
    for k, name in enumerate(names):
        say(f"modes: {name}", fraction=0.05 + 0.9 * k / len(names))
        res = method(name).modes(eq.scene, count, progress=progress)
        if res.status is Status.REFUSED and name not in columns:   # bad input for the modes
            raise UnsupportedSceneError(res.message)
        results[name] = _shifted(res, eq.s_shift)
        results[name].scene = scene.name
    run = ModesRun(scene.name, results, pair_rows(results["bvp"], results["vfife"]), eq.note,
                   eq.s_shift, Path(out) if out is not None else None)
    run.columns = {name: pair_rows(results["bvp"], results[name], name) for name in columns
                   if results[name].status is not Status.REFUSED}
    run.wall_time_s = time.perf_counter() - t0
    if out is not None:
        say("modes: writing the report", fraction=0.95)
        write(run, Path(out))
    return run


# ------------------------------------------------------------------ files
def _write_csv(path: Path, columns, rows) -> None:
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(columns)
        for row in rows:
            w.writerow([f"{v:.10g}" if isinstance(v, float) else v for v in row])


def keyed_rows(run: ModesRun) -> list[tuple[str, int, Row | None, dict]]:
    """(plane, mode, the BVP-VFIFE row or None, {column: its row or None}) of every mode
    pair of the run, by plane and number (the BVP-VFIFE rows' order)."""
    keys = [(r["plane"], r["mode"]) for r in run.rows]
    for rows in run.columns.values():
        keys += [(r["plane"], r["mode"]) for r in rows if (r["plane"], r["mode"]) not in keys]
    keys.sort(key=lambda k: (FAMILIES.index(k[0]), k[1]))
    base = {(r["plane"], r["mode"]): r for r in run.rows}
    cols = {name: {(r["plane"], r["mode"]): r for r in rows}
            for name, rows in run.columns.items()}
    return [(p, n, base.get((p, n)), {name: c.get((p, n)) for name, c in cols.items()})
            for p, n in keys]


def agreement_columns(run: ModesRun) -> tuple[str, ...]:
    """agreement.csv's columns: :data:`AGREEMENT_COLUMNS`, then each further column's."""
    return AGREEMENT_COLUMNS + tuple(f"{name}_{c}" for name in run.columns
                                     for c in COLUMN_SUFFIXES)


def _agreement_records(run: ModesRun):
    for plane, mode, r, further in keyed_rows(run):
        bvp = r.value("bvp") if r is not None else next(
            c.value("bvp") for c in further.values() if c is not None)
        rec = [plane, mode, bvp, *((r.value("vfife"), r.rel_diff, r["mac"]) if r is not None
                                   else (None, None, None))]
        for name, c in further.items():
            rec += [c.value(name), c.rel_diff, c["mac"]] if c is not None else [None] * 3
        yield rec


def write(run: ModesRun, out: Path) -> None:
    """Write :data:`FILES` for ``run`` into ``out`` (created if missing)."""
    out.mkdir(parents=True, exist_ok=True)
    _write_csv(out / "modes.csv", MODES_COLUMNS,
               ((name, m.plane, m.number, m.frequency_hz, m.period_s)
                for name, res in run.results.items() for m in res.modes))
    _write_csv(out / "agreement.csv", agreement_columns(run), _agreement_records(run))
    for plane in _families(run):
        plot_shapes(run, plane, out / f"mode_shapes_{plane}.png")
    (out / "report.md").write_text(markdown(run))
    run.files = [f for f in FILES if (out / f).exists()]


def _title(plane: str) -> str:
    """A family's section title (its first letter capital, the rest as written)."""
    t = PLANE_TITLES[plane]
    return t[0].upper() + t[1:]


#: what a report says of a coupled family, before its table
COUPLED_NOTE = ("The static state is 3D (out of the x-y plane): the in- and out-of-plane "
                "motions couple, and the modes form one family numbered by frequency, "
                "paired by number. The share is the BVP mode's squared displacement along "
                "z over its total, integrated along s (0 in plane, 1 across it).")


def _shares(run: ModesRun) -> dict[int, float]:
    """The BVP's out-of-plane share of each coupled mode, by number (empty without)."""
    res = run.results.get("bvp")
    shares = res.info.get("out_of_plane_share") if res is not None else None
    if not shares:
        return {}
    return {m.number: sh for m, sh in zip(res.family(COUPLED), shares)}


def _families(run: ModesRun) -> tuple[str, ...]:
    """The families of the run: the two planes (a planar static state, also when no method
    found a mode), or the coupled family of a 3D state when a method returned it."""
    coupled = any(m.plane == COUPLED for res in run.results.values() for m in res.modes)
    return (COUPLED,) if coupled else PLANES


def _aligned(shape: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """``shape`` with the sign that makes it point like ``ref`` (same samples)."""
    return -shape if float(np.sum(shape * ref)) < 0.0 else shape


def plot_shapes(run: ModesRun, plane: str, path: Path) -> None:
    """The first :data:`PLOTTED` modes of ``plane``, both methods, against s."""
    fams = {name: res.family(plane)[:PLOTTED] for name, res in run.results.items()}
    k = max(1, max(len(f) for f in fams.values()))
    fig, axes = new_figure(k, 1, size=(8.0, 2.2 * k + 0.6))
    comps = {"in_plane": (("x", 0), ("y", 1)), "out_of_plane": (("z", 2),)}.get(
        plane, (("x", 0), ("y", 1), ("z", 2)))
    colors = {"x": "tab:blue", "y": "tab:orange", "z": "tab:green"}
    for i in range(k):
        ax = axes[i][0]
        b = fams["bvp"][i] if i < len(fams["bvp"]) else None
        v = fams["vfife"][i] if i < len(fams["vfife"]) else None
        label = []
        if b is not None:
            for c, j in comps:
                ax.plot(b.s, b.shape[:, j], color=colors[c], lw=1.5, label=f"bvp {c}")
            label.append(f"bvp {b.frequency_hz:.5g} Hz")
        if v is not None:
            vs = v.shape if b is None else _aligned(v.shape, shape_at(b, v.s))
            every = max(1, len(v.s) // 60)
            for c, j in comps:
                ax.plot(v.s, vs[:, j], color=colors[c], ls="none", marker="o", ms=2.5,
                        markevery=every, label=f"vfife {c}")
            label.append(f"vfife {v.frequency_hz:.5g} Hz")
        for name in run.columns:
            fam = fams.get(name, [])
            a = fam[i] if i < len(fam) else None
            if a is None:
                continue
            ash = a.shape if b is None else _aligned(a.shape, shape_at(b, a.s))
            every = max(1, len(a.s) // 45)
            for c, j in comps:
                ax.plot(a.s, ash[:, j], color=colors[c], ls="none", marker="x", ms=3.0,
                        markevery=every, label=f"{name} {c}")
            label.append(f"{name} {a.frequency_hz:.5g} Hz")
        ax.set_title(f"{PLANE_TITLES[plane]} mode {i + 1}: " + ", ".join(label), fontsize=9)
        ax.set_ylabel("shape [-]")
        ax.grid(alpha=0.3)
        if i == 0:
            ax.legend(fontsize=7, ncol=4, loc="best")
    axes[-1][0].set_xlabel("arc length s [m]")
    fig.suptitle(f"{run.scene}: mode shapes, {PLANE_TITLES[plane]}", fontsize=10)
    save(fig, path)


def _result_line(name: str, res: ModalResult) -> str:
    static = res.info.get("static_wall_time_s")
    extra = f", static solve {timed(static)}" if static is not None else ""
    status = "" if res.converged else f"**{res.status.value}**: "
    return (f"- **{name}**: {status}{res.message} (modal analysis {timed(res.wall_time_s)}"
            f"{extra})")


def markdown(run: ModesRun) -> str:
    """The ``report.md`` of a modal analysis."""
    if run.columns or len(run.results) > 2:
        return _markdown_with_columns(run)
    n_ok = sum(r.passed for r in run.rows)
    lines = [f"# Natural modes: {run.scene}", "", GENERATED_NOTE, "",
             "Undamped modes of small vibration about the static state, by both methods "
             "(`riser/results/modes.py`: mass pipe + contents with the added mass normal to the axis, "
             "the elastic seabed as vertical springs where the line lies on it, the static "
             "drag of a current held as a dead load, fixed in magnitude and direction as the "
             "line moves; no drag damping or friction). Target: |frequency difference| <= "
             f"{100 * TARGET_REL_DIFF:g} % and MAC >= {TARGET_MAC:g}; difference = "
             "VFIFE / BVP - 1; MAC of the two shapes on the VFIFE nodes.", ""]
    if run.note:
        lines += [f"Scene conversion: {run.note}.", ""]
    lines += [_result_line(name, res) for name, res in run.results.items()]
    lines += ["", f"**{n_ok} of {len(run.rows)} mode pairs meet the target**"
              + ("." if run.all_meet or not run.rows else
                 " (see the rows marked no)."), ""]
    for plane in _families(run):
        rows = [r for r in run.rows if r["plane"] == plane]
        lines += [f"## {_title(plane)}", ""]
        if not rows:
            lines += ["No mode pair: a method found no mode of this plane.", ""]
            continue
        shares = _shares(run) if plane == COUPLED else {}
        share_head = ("out-of-plane share",) if shares else ()
        if shares:
            lines += [COUPLED_NOTE, ""]
        lines.append(md_table(
            ("mode", *share_head, "BVP f [Hz]", "VFIFE f [Hz]", "BVP T [s]", "VFIFE T [s]",
             "difference", "MAC", "meets target"),
            [(r["mode"], *((f"{shares.get(r['mode'], float('nan')):.3f}",) if shares else ()),
              r.value("bvp"), r.value("vfife"), 1.0 / r.value("bvp"), 1.0 / r.value("vfife"),
              pct(r.rel_diff), f"{r['mac']:.5f}", r.passed) for r in rows]))
        lines += ["", f"![{plane} mode shapes](mode_shapes_{plane}.png)", ""]
    lines += ["Periods are for VIV screening: a vortex-shedding frequency St U / D (St ~ 0.2) "
              "near a natural frequency flags the mode.", ""]
    return "\n".join(lines)


def _markdown_with_columns(run: ModesRun) -> str:
    """:func:`markdown` of a run with further columns: their frequencies, differences to
    the BVP and MACs beside the two methods' in each plane's table."""
    names = [n for n in run.results if n not in ("bvp", "vfife")]
    further = ", ".join(LABELS.get(n, n) for n in names)
    n_ok = sum(r.passed for r in run.rows)
    lines = [f"# Natural modes: {run.scene}", "", GENERATED_NOTE, "",
             "Undamped modes of small vibration about the static state, by both methods "
             f"and, as a further column, the {further} "
             "(`riser/results/modes.py`: mass pipe + contents with the added mass normal to the axis, "
             "the elastic seabed as vertical springs where the line lies on it, the static "
             "drag of a current held as a dead load, fixed in magnitude and direction as the "
             "line moves; no drag damping or friction). Target: |frequency difference| <= "
             f"{100 * TARGET_REL_DIFF:g} % and MAC >= {TARGET_MAC:g}; difference = "
             "VFIFE / BVP - 1; MAC of the two shapes on the VFIFE nodes. The further "
             f"column{'s' if len(names) > 1 else ''} ({further}) against the BVP with the "
             "same target and in the verdict: its frequency / BVP - 1, the MAC on its own "
             "samples.", ""]
    if run.note:
        lines += [f"Scene conversion: {run.note}.", ""]
    lines += [_result_line(name, res) for name, res in run.results.items()]
    for name in names:
        if name not in run.columns:
            lines.append(f"- the {LABELS.get(name, name)} refused the scene: not judged")
    total = len(run.rows) + sum(len(r) for r in run.columns.values())
    ok = n_ok + sum(r.passed for rows in run.columns.values() for r in rows)
    lines += ["", f"**{ok} of {total} mode pairs meet the target** ({n_ok} of "
              f"{len(run.rows)} VFIFE-BVP"
              + "".join(f", {sum(r.passed for r in rows)} of {len(rows)} "
                        f"{LABELS.get(n, n)}-BVP" for n, rows in run.columns.items())
              + ")" + ("." if run.all_meet or not total else " (see the rows marked no)."), ""]
    keyed = keyed_rows(run)
    for plane in _families(run):
        rows = [k for k in keyed if k[0] == plane]
        lines += [f"## {_title(plane)}", ""]
        if not rows:
            lines += ["No mode pair: a method found no mode of this plane.", ""]
            continue
        shares = _shares(run) if plane == COUPLED else {}
        if shares:
            lines += [COUPLED_NOTE, ""]
        header = ["mode", *(["out-of-plane share"] if shares else []), "BVP f [Hz]",
                  "VFIFE f [Hz]", "BVP T [s]", "VFIFE T [s]", "difference", "MAC",
                  "meets target"]
        for n in run.columns:
            lab = LABELS.get(n, n)
            header += [f"{lab} f [Hz]", f"{lab} difference", f"{lab} MAC",
                       f"{lab} meets target"]
        table = []
        for _, mode, r, cols in rows:
            bvp = r.value("bvp") if r is not None else next(
                c.value("bvp") for c in cols.values() if c is not None)
            cells = [mode, *([f"{shares.get(mode, float('nan')):.3f}"] if shares else []), bvp]
            if r is not None:
                cells += [r.value("vfife"), 1.0 / bvp, 1.0 / r.value("vfife"),
                          pct(r.rel_diff), f"{r['mac']:.5f}", r.passed]
            else:
                cells += [None, 1.0 / bvp, None, "", "", ""]
            for n, c in cols.items():
                cells += ([c.value(n), pct(c.rel_diff), f"{c['mac']:.5f}", c.passed]
                          if c is not None else [None, "", "", ""])
            table.append(cells)
        lines.append(md_table(header, table))
        lines += ["", f"![{plane} mode shapes](mode_shapes_{plane}.png)", ""]
    lines += ["Periods are for VIV screening: a vortex-shedding frequency St U / D (St ~ 0.2) "
              "near a natural frequency flags the mode.", ""]
    return "\n".join(lines)


def summary_lines(run: ModesRun) -> list[str]:
    """What the ``modes`` command prints: per method its outcome, then per plane the
    frequencies and the agreement (a further column's frequency, difference to the BVP
    and MAC after them), then the verdict and the files."""
    further = [n for n in run.results if n not in ("bvp", "vfife")]
    out = [f"{run.scene}: natural modes, both methods"
           + (f" and the {', '.join(further)}" if further else "")
           + (f" (arc lengths from the BVP touchdown, s_shift {run.s_shift:g} m)"
              if run.s_shift else "")]
    for name, res in run.results.items():
        out.append(f"  {name}: {res.status.value}, {len(res.modes)} modes in "
                   f"{res.wall_time_s:.2f} s" + ("" if res.converged else f": {res.message}"))
    keyed = keyed_rows(run)
    for plane in _families(run):
        rows = [k for k in keyed if k[0] == plane]
        if rows:
            out.append(f"  {PLANE_TITLES[plane]}: mode, bvp Hz, vfife Hz, period s, diff, MAC"
                       + "".join(f", {n} Hz, diff, MAC" for n in run.columns))
        for _, mode, r, cols in rows:
            if r is not None:
                line = (f"    {mode:2d}  {r.value('bvp'):.6g}  "
                        f"{r.value('vfife'):.6g}  {1.0 / r.value('bvp'):.4g}  "
                        f"{100 * r.rel_diff:+.3f} %  {r['mac']:.4f}")
                bad = [] if r.passed else ["vfife"]
            else:
                bvp = next(c.value("bvp") for c in cols.values() if c is not None)
                line = f"    {mode:2d}  {bvp:.6g}  -  {1.0 / bvp:.4g}  -  -"
                bad = []
            for n, c in cols.items():
                if c is None:
                    line += "  |  -"
                    continue
                line += (f"  |  {c.value(n):.6g}  {100 * c.rel_diff:+.3f} %  "
                         f"{c['mac']:.4f}")
                if not c.passed:
                    bad.append(n)
            out.append(line + (f"  (outside the target: {', '.join(bad)})"
                               if bad and run.columns else
                               "  (outside the target)" if bad else ""))
    n_ok = sum(r.passed for r in run.rows)
    out.append(f"  {n_ok}/{len(run.rows)} pairs within {100 * TARGET_REL_DIFF:g} % and MAC >= "
               f"{TARGET_MAC:g}")
    for n, rows in run.columns.items():
        out.append(f"  {n}: {sum(r.passed for r in rows)}/{len(rows)} pairs with the bvp "
                   f"within {100 * TARGET_REL_DIFF:g} % and MAC >= {TARGET_MAC:g}")
    for n in further:
        if n not in run.columns:
            out.append(f"  {n}: refused the scene, not judged")
    if run.out is not None and run.files:
        out.append(f"  wrote {run.out}/: {', '.join(run.files)}")
    return out

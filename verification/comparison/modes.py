"""Cross-method modal analysis: the natural modes of one scene by both methods, and their
agreement (``riser-verify modes SCENE [--count N] [--out DIR]``).

Both methods analyse the same fixed-ends scene, :func:`verification.pipeline.
vfife_equivalent` of the scene (a Wang-form scene is converted; its arc lengths are then
reported from the BVP touchdown, the converted s minus ``s_shift``), each about its own
static equilibrium (``bvp.modal.modes.solve_modes``, ``vfife.modal.modes.solve_modes``; the shared
model is stated in :mod:`riser.results.modes`, its equations in :mod:`bvp.modal.modes`: undamped, the
static drag of a current frozen as a dead load). Modes are paired by plane and number; the
agreement of a pair is the relative frequency difference of the VFIFE from the BVP and
the MAC of the two shapes interpolated on the VFIFE's nodes (inside the arc-length range
both cover). The target: |difference| <= 0.5 % and MAC >= 0.99.

Files written into ``out``: see :data:`FILES`. ``modes.csv`` (columns ``method, plane,
mode, frequency_hz, period_s``) and ``agreement.csv`` (``plane, mode, bvp_frequency_hz,
vfife_frequency_hz, rel_diff, mac``) are read by other tools: keep their columns.
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
from riser.results.modes import PLANES, ModalResult, mac, shape_at
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
PLANE_TITLES = {"in_plane": "in-plane (x, y)", "out_of_plane": "out-of-plane (z)"}


@dataclass
class ModesRun:
    """Outcome of :func:`run_modes`: the scene's name, the two :class:`ModalResult`
    (``results['bvp']``, ``results['vfife']``, arc lengths in the scene's coordinate), the
    agreement ``rows`` (a :class:`~.row.Row` per mode pair: the frequencies [Hz] of
    both, their relative difference, ``plane``, ``mode`` and ``mac`` beside; its verdict
    the target's, on both the frequency and the MAC), the
    conversion ``note`` and ``s_shift`` [m], the output folder and the files written."""

    scene: str
    results: dict[str, ModalResult]
    rows: list[Row]
    note: str = ""
    s_shift: float = 0.0
    out: Path | None = None
    files: list[str] = field(default_factory=list)
    wall_time_s: float = 0.0

    @property
    def all_meet(self) -> bool:
        """Every pair found by both methods meets the target and both converged."""
        return (all(r.converged for r in self.results.values()) and bool(self.rows)
                and all(r.passed for r in self.rows))


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


def pair_rows(bvp_res: ModalResult, vf_res: ModalResult) -> list[Row]:
    """Agreement rows of the modes both results hold, by plane and number."""
    rows = []
    for plane in PLANES:
        vf_modes = {m.number: m for m in vf_res.family(plane)}
        for b in bvp_res.family(plane):
            v = vf_modes.get(b.number)
            if v is None:
                continue
            lo, hi = max(b.s[0], v.s[0]), min(b.s[-1], v.s[-1])
            s = v.s[(v.s >= lo) & (v.s <= hi)]
            m = mac(shape_at(b, s), shape_at(v, s))
            rel = v.frequency_hz / b.frequency_hz - 1.0 if b.frequency_hz > 0 else float("nan")
            rows.append(Row("frequency", {"bvp": b.frequency_hz, "vfife": v.frequency_hz},
                            "Hz", v.frequency_hz - b.frequency_hz, rel, TARGET,
                            Verdict.of(bool(abs(rel) <= TARGET_REL_DIFF and m >= TARGET_MAC)),
                            extra={"plane": plane, "mode": b.number, "mac": m}))
    return rows


def run_modes(scene, count: int = 10, out: str | Path | None = None,
              progress=None) -> ModesRun:
    """Modes of ``scene`` by both methods, their agreement, and (``out`` given) the files
    :data:`FILES` in ``out``. Raises SceneError / UnsupportedSceneError (refused before
    solving) and SolveFailed (the BVP of a Wang-form scene's conversion failed); a modal
    analysis that fails is reported in its result's status."""
    if count < 1:
        raise ValueError(f"count must be >= 1, got {count}")
    say = with_fraction(progress) or (lambda message, fraction=None: None)
    t0 = time.perf_counter()
    say("modes: fixed-ends scene", fraction=0.0)
    eq = vfife_equivalent(scene)
    results = {}
    for k, name in enumerate(("bvp", "vfife")):
        say(f"modes: {name}", fraction=0.05 + 0.45 * k)
        res = method(name).modes(eq.scene, count, progress=progress)
        if res.status is Status.REFUSED:            # bad input for the modal analysis
            raise UnsupportedSceneError(res.message)
        results[name] = _shifted(res, eq.s_shift)
        results[name].scene = scene.name
    run = ModesRun(scene.name, results, pair_rows(results["bvp"], results["vfife"]), eq.note,
                   eq.s_shift, Path(out) if out is not None else None)
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


def write(run: ModesRun, out: Path) -> None:
    """Write :data:`FILES` for ``run`` into ``out`` (created if missing)."""
    out.mkdir(parents=True, exist_ok=True)
    _write_csv(out / "modes.csv", MODES_COLUMNS,
               ((name, m.plane, m.number, m.frequency_hz, m.period_s)
                for name, res in run.results.items() for m in res.modes))
    _write_csv(out / "agreement.csv", AGREEMENT_COLUMNS,
               ((r["plane"], r["mode"], r.value("bvp"), r.value("vfife"), r.rel_diff,
                 r["mac"]) for r in run.rows))
    for plane in PLANES:
        plot_shapes(run, plane, out / f"mode_shapes_{plane}.png")
    (out / "report.md").write_text(markdown(run))
    run.files = [f for f in FILES if (out / f).exists()]


def _aligned(shape: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """``shape`` with the sign that makes it point like ``ref`` (same samples)."""
    return -shape if float(np.sum(shape * ref)) < 0.0 else shape


def plot_shapes(run: ModesRun, plane: str, path: Path) -> None:
    """The first :data:`PLOTTED` modes of ``plane``, both methods, against s."""
    fams = {name: res.family(plane)[:PLOTTED] for name, res in run.results.items()}
    k = max(1, max(len(f) for f in fams.values()))
    fig, axes = new_figure(k, 1, size=(8.0, 2.2 * k + 0.6))
    comps = (("x", 0), ("y", 1)) if plane == "in_plane" else (("z", 2),)
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
    for plane in PLANES:
        rows = [r for r in run.rows if r["plane"] == plane]
        lines += [f"## {PLANE_TITLES[plane].capitalize()}", ""]
        if not rows:
            lines += ["No mode pair: a method found no mode of this plane.", ""]
            continue
        lines.append(md_table(
            ("mode", "BVP f [Hz]", "VFIFE f [Hz]", "BVP T [s]", "VFIFE T [s]", "difference",
             "MAC", "meets target"),
            [(r["mode"], r.value("bvp"), r.value("vfife"),
              1.0 / r.value("bvp"), 1.0 / r.value("vfife"),
              pct(r.rel_diff), f"{r['mac']:.5f}", r.passed) for r in rows]))
        lines += ["", f"![{plane} mode shapes](mode_shapes_{plane}.png)", ""]
    lines += ["Periods are for VIV screening: a vortex-shedding frequency St U / D (St ~ 0.2) "
              "near a natural frequency flags the mode.", ""]
    return "\n".join(lines)


def summary_lines(run: ModesRun) -> list[str]:
    """What the ``modes`` command prints: per method its outcome, then per plane the
    frequencies and the agreement, then the verdict and the files."""
    out = [f"{run.scene}: natural modes, both methods"
           + (f" (arc lengths from the BVP touchdown, s_shift {run.s_shift:g} m)"
              if run.s_shift else "")]
    for name, res in run.results.items():
        out.append(f"  {name}: {res.status.value}, {len(res.modes)} modes in "
                   f"{res.wall_time_s:.2f} s" + ("" if res.converged else f": {res.message}"))
    for plane in PLANES:
        rows = [r for r in run.rows if r["plane"] == plane]
        if rows:
            out.append(f"  {PLANE_TITLES[plane]}: mode, bvp Hz, vfife Hz, period s, diff, MAC")
        for r in rows:
            out.append(f"    {r['mode']:2d}  {r.value('bvp'):.6g}  "
                       f"{r.value('vfife'):.6g}  {1.0 / r.value('bvp'):.4g}  "
                       f"{100 * r.rel_diff:+.3f} %  {r['mac']:.4f}"
                       + ("" if r.passed else "  (outside the target)"))
    n_ok = sum(r.passed for r in run.rows)
    out.append(f"  {n_ok}/{len(run.rows)} pairs within {100 * TARGET_REL_DIFF:g} % and MAC >= "
               f"{TARGET_MAC:g}")
    if run.out is not None and run.files:
        out.append(f"  wrote {run.out}/: {', '.join(run.files)}")
    return out

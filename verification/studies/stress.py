"""Hard-case suite: every hard scene with both methods, and proof of no silent failure.

For each scene in ``verification/scenes/hard/`` and each method the outcome is one of

- ``converged``: the solver met its own test, and the checks below pass;
- ``refused``: the scene is outside the method (e.g. a second touchdown for the BVP),
  said with a clear message before solving;
- ``no equilibrium``: the solver stopped with evidence that the static problem of that
  form has no solution (e.g. the touchdown tension driven to zero under the load);
- ``failed``: it stopped with a stated reason;
- ``SILENT FAILURE``: anything else — NaN/inf in a returned profile, an exception instead
  of a message, a converged result that violates its own equilibrium check, unbounded
  dynamic energy. The suite exists to show there are none.

Checks on a converged result: finite profile; equilibrium residual (BVP: largest
collocation residual and the global force balance; VFIFE: largest nodal out-of-balance
force / one element's weight); dynamics: finite hang-off tension and a kinetic-energy
proxy (mean squared node speed) that does not grow over the last fifth of the run.
Where both methods converge, the comparison protocol's rows are counted.
"""

from __future__ import annotations

import math
import time
import traceback
from pathlib import Path

import numpy as np
import pandas as pd

from riser.errors import SceneError, SolveFailed
from riser.results.result import Status
from riser.model.scene import FixedEnds
from verification.catalog import SCENE_DIR, resolve
from verification.comparison.static.agreement import agreement, unresolved_bending
from verification.pipeline import solve_scene
from verification.quantities import reference_depth
from verification.report.markdown import GENERATED_NOTE, fmt, md_table, timed
from verification.runtime.interrupts import reraise_interrupt
from verification.runtime.progress import scoped

from .study import Study

HARD_DIR = SCENE_DIR / "hard"
COLUMNS = ["scene", "method", "outcome", "residual", "residual_kind", "wall_time_s", "agreement",
           "message"]
# A converged result must satisfy its own test: VFIFE residual in element weights (the
# solver's default tolerance is 1e-3; allow its own tolerance x 1.01), BVP collocation
# residual (solve_bvp tolerance) and global force balance (1e-4 of T_max).
BVP_EQUILIBRIUM_LIMIT = 1.0e-4


def hard_scenes() -> list[str]:
    return sorted(p.stem for p in HARD_DIR.glob("*.toml"))


#: the outcome a result's status gives (a converged result is checked further)
OUTCOME = {Status.CONVERGED: "converged", Status.REFUSED: "refused",
           Status.NO_EQUILIBRIUM: "no equilibrium", Status.DIVERGED: "failed",
           Status.NOT_CONVERGED: "failed"}


def run_one(name: str, method: str, progress=None) -> tuple[dict, object]:
    """Solve one scene with one method and classify the outcome; never raises.
    ``progress``: passed to :func:`~verification.pipeline.solve_scene`."""
    row = {"scene": name, "method": method, "residual": None, "residual_kind": "",
           "agreement": "", "message": ""}
    t0 = time.perf_counter()
    res = None
    try:
        scene = resolve(name)
        res = solve_scene(scene, method, progress=progress)
    except SceneError as exc:                      # bad input: stopped with its reason
        row.update(outcome="failed", message=str(exc))
    except SolveFailed as exc:
        row.update(outcome=OUTCOME[exc.status], message=str(exc))
    except Exception as exc:                       # noqa: BLE001 - the point is to catch it
        reraise_interrupt(exc)                     # a Ctrl-C (in Numba) is no outcome
        row.update(outcome="SILENT FAILURE",
                   message=f"exception {type(exc).__name__}: {exc} "
                           f"({traceback.format_exc(limit=2).splitlines()[-1]})")
    row["wall_time_s"] = time.perf_counter() - t0
    if res is None:
        return row, None
    row["message"] = res.message
    if not res.converged:            # a failed result holds no profile (riser.results.result)
        row["outcome"] = OUTCOME[res.status]
        return row, None
    problems = []
    if res.profile is None or not res.profile.is_finite():
        problems.append("non-finite profile")
    if method == "bvp":
        row["residual"] = res.info.get("equilibrium_residual")
        row["residual_kind"] = "force balance / T_max"
        if row["residual"] is None or row["residual"] > BVP_EQUILIBRIUM_LIMIT:
            problems.append(f"force balance {row['residual']}")
    else:
        row["residual"] = res.info.get("force_residual")
        row["residual_kind"] = "out-of-balance / element weight"
        tol = res.info.get("tolerance", 1e-3)
        if row["residual"] is None or not row["residual"] <= 1.01 * tol:
            problems.append(f"residual {row['residual']} above its tolerance {tol}")
        if res.dynamics is not None:
            problems += _dynamic_checks(res.dynamics)
    row["outcome"] = "SILENT FAILURE" if problems else "converged"
    if problems:
        row["message"] += " | " + "; ".join(problems)
    return row, res


def _dynamic_checks(dyn) -> list[str]:
    out = []
    T = np.asarray(dyn.timeseries.get("hang_off_tension", []), dtype=float)
    if T.size == 0 or not np.all(np.isfinite(T)):
        out.append("non-finite hang-off tension series")
    ke = np.asarray(dyn.timeseries.get("kinetic_energy", []), dtype=float)
    if len(ke) >= 10:
        k = len(ke)
        mid, last = ke[k // 5: 4 * k // 5], ke[4 * k // 5:]
        if not np.all(np.isfinite(ke)):
            out.append("non-finite kinetic energy")
        elif mid.size and last.max() > 4.0 * max(mid.max(), 1e-12):
            out.append(f"kinetic energy grows: last fifth {last.max():.3g} J vs "
                       f"{mid.max():.3g} J")
    return out


def run(out_dir: str | Path = "reports/stress", names: list[str] | None = None, log=print,
        progress=None) -> pd.DataFrame:
    """Run the hard-case suite; write ``summary.csv`` and ``report.md``. ``progress``:
    optional callable ``progress(message, fraction=None)`` (:mod:`verification.runtime.progress`),
    told of each run (fraction: runs done / runs)."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    todo = names or hard_scenes()
    for k, name in enumerate(todo):
        results = {}
        for method in ("bvp", "vfife"):
            i = 2 * k + (method == "vfife")
            row, res = run_one(name, method, scoped(
                progress, f"{i + 1}/{2 * len(todo)} {name} [{method}]", i / (2 * len(todo)),
                (i + 1) / (2 * len(todo))))
            results[method] = res
            rows.append(row)
            log(f"stress {name} [{method}]: {row['outcome']} ({row['wall_time_s']:.1f} s)")
        b, v = results["bvp"], results["vfife"]
        if b is None and v is not None and rows[-2]["outcome"] == "no equilibrium":
            sc = resolve(name)
            vs = v.summary()
            evidence = (f" | VFIFE finds an equilibrium outside the BVP's form: touchdown "
                        f"x = {vs['tdp_x']:.1f} m")
            if isinstance(sc.ends, FixedEnds):
                evidence += f" (anchor at x = {sc.ends.anchor[0]:g} m)"
            evidence += f", minimum tension {vs['min_tension'] / 1e3:.1f} kN"
            rows[-2]["message"] += evidence
        if b is not None and v is not None:
            # both profiles are in the scene's own arc length (solve_scene shifts the VFIFE's)
            sc = resolve(name)
            bending = unresolved_bending(sc, b.profile, v.info["element_length"])
            agr = agreement(b.profile, v.profile, reference_depth(sc, b.summary()),
                            moment_reason=bending, scene=sc)
            text = agreement_text(agr, v.warnings)
            for r in rows[-2:]:
                r["agreement"] = text
    df = pd.DataFrame(rows, columns=COLUMNS)
    df.to_csv(out / "summary.csv", index=False, float_format="%.6g")
    _report(df, out)
    return df


def agreement_text(rows: list[dict], vfife_warnings: list[str]) -> str:
    """One cell: the rows within their tolerance, those not judged and those outside, each
    with its reason: a row outside its tolerance is explained by the VFIFE's own
    resolution warning when it gave one, else said to have no stated cause."""
    failed = [r["quantity"] for r in rows if r["pass"] is False]
    skipped = [r for r in rows if r["pass"] is None]
    judged = len(rows) - len(skipped)
    text = f"{judged - len(failed)}/{judged} rows pass"
    if skipped:
        text += (f"; not judged: {', '.join(r['quantity'] for r in skipped)} "
                 f"({skipped[0]['note']})")
    if failed:
        why = [w for w in vfife_warnings if w.startswith("resolution:")]
        text += (f"; outside: {', '.join(failed)} ("
                 + ("the VFIFE's " + "; ".join(why) if why else "no stated cause") + ")")
    return text


def _report(df: pd.DataFrame, out: Path) -> None:
    silent = df[df.outcome == "SILENT FAILURE"]
    counts = df.outcome.value_counts().to_dict()
    lines = [
        "# Hard cases: numerical stability of both methods", "", GENERATED_NOTE, "",
        f"**{len(silent)} silent failure(s)** in {len(df)} runs "
        f"({', '.join(f'{k}: {v}' for k, v in sorted(counts.items()))}).", "",
        "Outcomes: `converged` (met its own test and the checks), `refused` (outside the "
        "method, said before solving), `no equilibrium` (stopped with evidence that no static "
        "solution of that form exists), `failed` (stopped with a stated reason), `SILENT "
        "FAILURE` (NaN, exception, violated equilibrium or growing energy: must never "
        "appear). Scenes: `verification/scenes/hard/`.", "",
        md_table(["scene", "method", "outcome", "residual", "time [s]", "agreement"],
                 [(r.scene, r.method, r.outcome, fmt(r.residual, 3) if r.residual is not None
                   and not (isinstance(r.residual, float) and math.isnan(r.residual)) else "",
                   timed(r.wall_time_s, ".2f", ""), r.agreement) for r in df.itertuples()]),
        "", "## Messages", "",
    ]
    for r in df.itertuples():
        lines.append(f"- `{r.scene}` [{r.method}] {r.outcome}: {r.message}")
    lines.append("")
    (out / "report.md").write_text("\n".join(lines))


def index_row(d: Path):
    """(cases, worst agreement, verdict) of a hard-case report directory."""
    if not ((d / "summary.csv").exists() and (d / "report.md").exists()):
        return None
    df = pd.read_csv(d / "summary.csv")
    silent = int((df.outcome == "SILENT FAILURE").sum())
    counts = ", ".join(f"{k} {v}" for k, v in sorted(df.outcome.value_counts().items()))
    return (f"{df.scene.nunique()} scenes x 2 methods", f"{silent} silent failures ({counts})",
            "pass" if not silent else "fail")


STUDY = Study("stress", (None,), lambda unit, out, note, full: run(out), index_row,
              seconds={None: 129})


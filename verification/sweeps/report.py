"""The sweep's tables, range graphs and report, built from the case records only
(:mod:`verification.sweeps.run`), so a resumed sweep writes the same files as a fresh one.

- ``cases.csv``: one row per case and method: ``case``, ``method``, the varied values (a
  column per vary key, named by the key; arrays and tables as JSON), ``status``,
  ``wall_time_s``, the summary quantities (:data:`~verification.sweeps.case.SUMMARY_KEYS`,
  SI units: N, N m, m, deg), ``warnings``, then the method agreement of the case, the same
  in both methods' rows: ``agreement`` (pass, FAIL, or blank when not assessed, with
  ``agreement_note`` saying why), ``worst_quantity`` and ``worst_ratio`` (its |difference|
  over its tolerance; > 1 fails), ``<q>_rel_diff`` for the rows of
  :data:`~verification.sweeps.case.AGREEMENT_KEYS` (VFIFE - BVP over the row's basis, as in
  ``compare``'s agreement.csv), ``tdp_x_diff`` (VFIFE - BVP touchdown x [m]), and
  ``message``.
- ``envelopes.csv``: per method, along s [m] (0.5 m stations, from the bottom end): the
  min and max over the cases of the effective tension [N] and of the bending moment
  magnitude [N m] (OrcaFlex's range graph of Effective Tension and Bend Moment), how many
  cases reach that s, and the case of each maximum.
- ``range_tension.png``, ``range_moment.png`` (every case thin, the envelope bold) and
  ``configurations.png``.
- ``report.md``: the sweep, its cases, the worst case per quantity, the method agreement,
  every disagreement and every failure with its reason.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd

from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, fmt, md_table

from .case import AGREEMENT_DIFF_KEYS, AGREEMENT_KEYS, DESIGN_KEYS, SUMMARY_KEYS
from .run import SweepRun

#: station spacing of envelopes.csv [m], and the most stations per method
STATION_SPACING = 0.5
MAX_STATIONS = 20_001
#: the worst case per quantity: (summary key, "max" or "min", label, unit)
WORST = (("hang_off_tension", "max", "hang-off tension", "kN"),
         ("max_tension", "max", "largest tension", "kN"),
         ("min_tension", "min", "smallest tension", "kN"),
         ("max_moment", "max", "largest bending moment", "kN m"),
         ("hang_off_angle_deg", "max", "hang-off angle from horizontal, largest", "deg"),
         ("hang_off_angle_deg", "min", "hang-off angle from horizontal, smallest", "deg"),
         ("tdp_x", "min", "touchdown x, nearest the anchor", "m"),
         ("tdp_x", "max", "touchdown x, farthest from the anchor", "m"))
_SCALE = {"kN": 1e-3, "kN m": 1e-3, "deg": 1.0, "m": 1.0}


def value_text(v) -> str:
    """A varied value as written in cases.csv (JSON for arrays and tables)."""
    return v if isinstance(v, str) else json.dumps(v, default=str)


def cases_frame(run: SweepRun) -> pd.DataFrame:
    keys = run.sweep.keys
    design = run.design_checked()
    rows = []
    for case, rec in zip(run.sweep.cases, run.records):
        agr = rec.get("agreement") or {}
        by_q = {r["quantity"]: r for r in agr.get("rows", [])}
        common = {"agreement": ("pass" if agr.get("passed") else "FAIL") if agr.get("assessed")
                  else "", "agreement_note": "" if agr.get("assessed") else agr.get("reason", ""),
                  "worst_quantity": agr.get("worst_quantity", ""),
                  "worst_ratio": agr.get("worst_ratio")}
        for q in AGREEMENT_KEYS:
            common[f"{q}_rel_diff"] = by_q.get(q, {}).get("rel_diff")
        for q in AGREEMENT_DIFF_KEYS:
            common[f"{q}_diff"] = by_q.get(q, {}).get("diff")
        for method, d in rec["methods"].items():
            sm = d.get("summary") or {}
            row = {"case": case.index, "method": method}
            row.update({k: value_text(case.values[k]) for k in keys})
            row.update({"status": d["status"], "wall_time_s": d.get("wall_time_s")})
            row.update({k: sm.get(k) for k in SUMMARY_KEYS})
            row["warnings"] = "; ".join(d.get("warnings", []))
            if design:
                row.update({k: sm.get(k) for k in DESIGN_KEYS})
                row["design_fails"] = "; ".join(d.get("design_fails") or [])
            row.update(common)
            row["message"] = d.get("message", "")
            rows.append(row)
    return pd.DataFrame(rows)


def _profiles(run: SweepRun, method: str):
    for rec in run.records:
        d = rec["methods"].get(method, {})
        if d.get("status") == "converged" and d.get("profile") is not None:
            yield rec["index"], d["profile"]


def envelopes_frame(run: SweepRun) -> pd.DataFrame:
    frames = []
    for method in run.sweep.methods:
        profs = list(_profiles(run, method))
        if not profs:
            continue
        length = max(float(np.max(p["s"])) for _, p in profs)
        n = min(MAX_STATIONS, int(np.ceil(length / STATION_SPACING)) + 1)
        s = np.linspace(0.0, length, n)
        T = np.full((len(profs), n), np.nan)
        M = np.full((len(profs), n), np.nan)
        for k, (_, p) in enumerate(profs):
            ps = np.asarray(p["s"], float)
            inside = (s >= ps[0] - 1e-9) & (s <= ps[-1] + 1e-9)
            T[k, inside] = np.interp(s[inside], ps, np.asarray(p["tension"], float))
            M[k, inside] = np.interp(s[inside], ps, np.asarray(p["moment"], float))
        U = None
        if all(p.get("utilisation") is not None for _, p in profs):
            U = np.full((len(profs), n), np.nan)
            for k, (_, p) in enumerate(profs):
                ps = np.asarray(p["s"], float)
                inside = (s >= ps[0] - 1e-9) & (s <= ps[-1] + 1e-9)
                U[k, inside] = np.interp(s[inside], ps, np.asarray(p["utilisation"], float))
        reached = np.isfinite(T).sum(axis=0)
        ok = reached > 0
        ids = np.array([i for i, _ in profs])
        fill = np.where(np.isfinite(T), T, -np.inf), np.where(np.isfinite(M), M, -np.inf)
        frame = pd.DataFrame({"method": method, "s": s[ok],
                              "tension_min": np.nanmin(T[:, ok], axis=0),
                              "tension_max": np.nanmax(T[:, ok], axis=0),
                              "moment_min": np.nanmin(M[:, ok], axis=0),
                              "moment_max": np.nanmax(M[:, ok], axis=0),
                              "cases": reached[ok],
                              "tension_max_case": ids[np.argmax(fill[0][:, ok], axis=0)],
                              "moment_max_case": ids[np.argmax(fill[1][:, ok], axis=0)]})
        if U is not None:                     # [design]: the code's utilisation against 1
            frame["utilisation_max"] = np.nanmax(U[:, ok], axis=0)
            frame["utilisation_max_case"] = ids[np.argmax(
                np.where(np.isfinite(U), U, -np.inf)[:, ok], axis=0)]
        frames.append(frame)
    return pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(
        columns=["method", "s", "tension_min", "tension_max", "moment_min", "moment_max",
                 "cases", "tension_max_case", "moment_max_case"])


def plots(run: SweepRun, env: pd.DataFrame, out: Path) -> None:
    methods = [m for m in run.sweep.methods if list(_profiles(run, m))]
    if not methods:
        return
    for name, col, unit, scale in (("range_tension.png", "tension", "kN", 1e-3),
                                   ("range_moment.png", "moment", "kN m", 1e-3)):
        fig, axes = new_figure(len(methods), 1, size=(8.0, 2.6 + 2.4 * len(methods)))
        for ax, method in zip(axes[:, 0], methods):
            for _, p in _profiles(run, method):
                ax.plot(p["s"], np.asarray(p[col]) * scale, color="0.7", lw=0.6)
            e = env[env["method"] == method]
            ax.plot(e["s"], e[f"{col}_max"] * scale, color="C3", lw=1.6, label="max")
            ax.plot(e["s"], e[f"{col}_min"] * scale, color="C0", lw=1.6, label="min")
            ax.set_ylabel(f"{col} [{unit}]")
            ax.set_title(f"{run.sweep.name}: {method}, {e['cases'].max()} case(s) (grey), "
                         "envelope", fontsize=9)
            ax.legend(fontsize=8)
            ax.grid(alpha=0.3)
        axes[-1, 0].set_xlabel("arc length s from the bottom end [m]")
        save(fig, out / name)
    if "utilisation_max" in env.columns and env["utilisation_max"].notna().any():
        fig, axes = new_figure(len(methods), 1, size=(8.0, 2.6 + 2.4 * len(methods)))
        for ax, method in zip(axes[:, 0], methods):
            for _, p in _profiles(run, method):
                if p.get("utilisation") is not None:
                    ax.plot(p["s"], p["utilisation"], color="0.7", lw=0.6)
            e = env[env["method"] == method]
            ax.plot(e["s"], e["utilisation_max"], color="C3", lw=1.6, label="max")
            ax.axhline(1.0, color="k", ls="--", lw=1.0, label="1: the code's limit")
            ax.set_ylabel("utilisation [-]")
            ax.set_title(f"{run.sweep.name}: {method}, utilisation of every case (grey), "
                         "envelope", fontsize=9)
            ax.legend(fontsize=8)
            ax.grid(alpha=0.3)
        axes[-1, 0].set_xlabel("arc length s from the bottom end [m]")
        save(fig, out / "range_utilisation.png")
    fig, axes = new_figure(len(methods), 1, size=(8.0, 2.6 + 2.4 * len(methods)))
    for ax, method in zip(axes[:, 0], methods):
        for i, p in _profiles(run, method):
            ax.plot(p["x"], p["y"], lw=0.7)
        ax.set_ylabel("y [m]")
        ax.set_title(f"{run.sweep.name}: {method}, configurations", fontsize=9)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("x [m]")
    save(fig, out / "configurations.png")


def _given(run: SweepRun, index: int) -> str:
    return ", ".join(f"{k} = {value_text(v)}" for k, v in run.sweep.cases[index].values.items())


def report_md(run: SweepRun, cases: pd.DataFrame) -> str:
    sw = run.sweep
    n = len(sw.cases)
    rate = run.cases_per_minute
    lines = [f"# Sweep `{sw.name}`", "", GENERATED_NOTE, "",
             f"- Sweep file: `{sw.source}`" + (f" (built-in: verification/sweeps/builtin/{sw.name}.toml)"
                                               if sw.builtin else "")
             + f"; base scene: `{sw.base}` ({sw.base_scene.title})",
             f"- Methods: {', '.join(sw.methods)}; {n} case(s)",
             (f"- Ran {run.ran} case(s) on {run.engine} in {run.wall_time_s:.1f} s"
              + (f": {rate:.2f} cases per minute" if rate else "")
              + (f"; {run.resumed} finished by an earlier run, skipped" if run.resumed else ""))
             if run.ran else "- Every case was finished by an earlier run (its timings are in "
                             "cases.csv); nothing ran now",
             *(f"- {note}" for note in sw.notes), "", "## Load cases", ""]
    lines.append(md_table(["key", "values", "count", "pairing"],
                          [(f"`{v.key}`", ", ".join(value_text(x) for x in v.values),
                            len(v.values), "zipped with the one above" if v.zip else "")
                           for v in sw.vary]))
    if sw.fixed:
        lines += ["", "Set in every case: " + ", ".join(f"`{k}` = {value_text(v)}"
                                                         for k, v in sw.fixed.items())]
    lines += ["", "## Worst case per quantity", ""]
    rows = []
    for key, how, label, unit in WORST:
        for method in sw.methods:
            sub = cases[(cases["method"] == method) & cases[key].notna()]
            if sub.empty:
                continue
            r = sub.loc[sub[key].idxmax() if how == "max" else sub[key].idxmin()]
            rows.append((label, method, int(r["case"]), f"{r[key] * _SCALE[unit]:.6g} {unit}",
                         _given(run, int(r["case"]))))
    lines.append(md_table(["quantity", "method", "case", "value", "varied values"], rows))
    lines += ["", "## Method agreement (BVP against VFIFE)", ""]
    lines += _agreement_section(run, cases)
    lines += ["", "## Failures", ""]
    fails = run.failures()
    if fails:
        lines.append(md_table(["case", "method", "status", "reason"],
                              [(i, m, s, why.replace("|", "/")) for i, m, s, why in fails]))
    else:
        lines.append("None: every method converged in every case.")
    lines += ["", "## Outside the model's validity", ""]
    warned = run.warned()
    if warned:
        lines.append("Converged, with warnings (the result is doubtful there; "
                     "`riser-verify solve --strict` would exit 1):")
        lines.append("")
        lines.append(md_table(["case", "method", "warnings"],
                              [(i, m, "; ".join(w).replace("|", "/")) for i, m, w in warned]))
    else:
        lines.append("No warning: every converged result is inside its model's validity.")
    if run.design_checked():
        lines += ["", "## Design checks", ""]
        failing = run.design_failures()
        if failing:
            lines.append(f"{len({i for i, _, _ in failing})} case(s) fail a design check "
                         "(`design_fails`; `riser-verify sweep --strict` exits 1):")
            lines.append("")
            lines.append(md_table(["case", "method", "design_fails", "varied values"],
                                  [(i, m, "; ".join(f).replace("|", "/"), _given(run, i))
                                   for i, m, f in failing]))
        else:
            lines.append("Every converged result passes the design checks it makes "
                         "(the code check; a bend limit where a line type has one).")
    lines += ["", "## Files", "",
              "`cases.csv` (one row per case and method), `envelopes.csv` (min and max along s), "
              "`range_tension.png`, `range_moment.png`, `configurations.png`; each case's "
              "folder `cases/NNNN/` holds `scene.toml` (`riser-verify compare "
              "cases/NNNN/scene.toml` reruns it alone), `case.json` and, per method, "
              "`summary.json`, `profile.csv`. A rerun of the same command skips the finished "
              "cases.", ""]
    return "\n".join(lines)


def _agreement_section(run: SweepRun, cases: pd.DataFrame) -> list[str]:
    first = cases.drop_duplicates("case")
    assessed = first[first["agreement"] != ""]
    if assessed.empty:
        return ["Not assessed: it needs both bvp and vfife converged on the same model "
                "in a case."]
    bad = assessed[assessed["agreement"] == "FAIL"]
    out = [f"{len(assessed)} case(s) assessed with the protocol of `riser-verify compare` "
           f"(same rows, tolerances and bases); {len(assessed) - len(bad)} within every "
           f"tolerance, {len(bad)} outside.", "",
           "Largest difference over the cases, per quantity (VFIFE - BVP over the row's "
           "basis):", ""]
    rows = []
    for q in AGREEMENT_KEYS:
        col = assessed[f"{q}_rel_diff"].dropna()
        if col.empty:
            continue
        i = col.abs().idxmax()
        rows.append((q, f"{100 * float(col[i]):+.3g} %", int(assessed.loc[i, "case"]),
                     _given(run, int(assessed.loc[i, "case"]))))
    out.append(md_table(["quantity", "largest rel. difference", "case", "varied values"], rows))
    worst = assessed.sort_values("worst_ratio", ascending=False).head(5)
    out += ["", "The cases nearest their tolerance (|difference| / tolerance of the worst "
            "row; above 1 fails):", ""]
    out.append(md_table(["case", "worst quantity", "ratio", "varied values"],
                        [(int(r["case"]), r["worst_quantity"], fmt(r["worst_ratio"], 3),
                          _given(run, int(r["case"]))) for _, r in worst.iterrows()]))
    out += ["", "### Disagreements", ""]
    if bad.empty:
        out.append("None: the methods agree within the protocol's tolerances in every "
                   "assessed case.")
    else:
        recs = {r["index"]: r for r in run.disagreements()}
        rows = []
        for _, r in bad.iterrows():
            for row in recs[int(r["case"])]["agreement"]["rows"]:
                if row["pass"] is False:
                    rows.append((int(r["case"]), row["quantity"], fmt(row["diff"]),
                                 fmt(row["tolerance"]), row["tol_label"],
                                 _given(run, int(r["case"]))))
        out.append(md_table(["case", "quantity", "difference", "tolerance", "basis",
                             "varied values"], rows))
    not_assessed = first[(first["agreement"] == "") & (first["agreement_note"] != "")]
    if not not_assessed.empty:
        out += ["", "Not assessed: " + "; ".join(
            f"case {int(r['case'])} ({r['agreement_note']})" for _, r in not_assessed.iterrows())]
    return out


def write(run: SweepRun, out: Path) -> list[str]:
    """Write the sweep's files into ``out``; return their names."""
    out = Path(out)
    cases = cases_frame(run)
    cases.to_csv(out / "cases.csv", index=False)
    env = envelopes_frame(run)
    env.to_csv(out / "envelopes.csv", index=False)
    plots(run, env, out)
    (out / "report.md").write_text(report_md(run, cases))
    return [f for f in ("cases.csv", "envelopes.csv", "range_tension.png", "range_moment.png",
                        "range_utilisation.png", "configurations.png", "report.md")
            if (out / f).exists()]

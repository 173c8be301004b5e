"""``reports/README.md``: one line per study, read back from the CSV files of each report."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from .report import GENERATED_NOTE, md_table, pct


def _wang(d: Path):
    df = pd.read_csv(d / "table2.csv")
    fwd = df[(df.variant == "forward") & (df.quantity != "hang_off_height")]
    worst_b = fwd.bvp_rel_err.abs().max()
    cases = f"{df.current.nunique()} currents x {df.variant.nunique()} variants"
    text = f"BVP vs paper (forward) worst {pct(worst_b)}"
    matched = d / "vfife_matched.csv"
    if matched.exists():
        m = pd.read_csv(matched)
        m = m[m.quantity != "hang_off_height"]
        rel = ((m.vfife - m.bvp_matched) / m.bvp_matched.abs()).abs()
        model = ((m.bvp_matched - m.bvp_paper_model) / m.bvp_paper_model.abs()).abs()
        text += (f"; VFIFE vs BVP of the same model worst {pct(rel.max())} "
                 f"({m.loc[rel.idxmax(), 'quantity']}); that model vs the paper's worst "
                 f"{pct(model.max())} ({m.loc[model.idxmax(), 'quantity']})")
    return cases, text, "pass" if worst_b <= 5e-4 else "fail"


def _yu(d: Path):
    df = pd.read_csv(d / "table.csv")
    cmp = df[df.paper.notna()]
    parts = []
    for m in ("bvp", "vfife"):
        col = cmp[f"{m}_rel_err"].abs()
        if col.notna().any():
            parts.append(f"{m.upper()} vs paper median {pct(col.median(), 1)}, worst {pct(col.max(), 1)}")
    both = df[df.bvp.notna() & df.vfife.notna()]
    if len(both):
        rel = ((both.vfife - both.bvp).abs() / both.bvp.abs())
        parts.append(f"VFIFE vs BVP worst {pct(rel.max(), 2)}")
    cases = f"{df[['study', 'case']].drop_duplicates().shape[0]} cases"
    return cases, "; ".join(parts), "reported (paper inputs incomplete)"


def _compare(d: Path):
    df = pd.read_csv(d / "agreement.csv")
    failed = df[~df["pass"].astype(bool)].quantity.tolist()
    rows = df.set_index("quantity")
    bases = {"configuration": "of depth", "tension": "of T_max", "moment": "of M_max"}
    text = ", ".join(f"{q} {pct(rows.loc[q, 'rel_diff'], 2)} {bases[q]}" for q in bases
                     if q in rows.index)
    if "tdp_x" in rows.index:
        tdp = rows.loc["tdp_x"]
        text += f", touchdown {tdp['vfife'] - tdp['bvp']:+.3f} m"
    if failed:
        text += f"; outside tolerance: {', '.join(failed)}"
    return "1 scene", text, "pass" if not failed else "fail"


def write_index(reports: Path = Path("reports")) -> Path:
    rows = []
    for d in sorted(p for p in reports.rglob("*") if p.is_dir()):
        rel = d.relative_to(reports)
        if (d / "table2.csv").exists():
            rows.append((f"[{rel}]({rel}/report.md)", *_wang(d)))
        elif (d / "table.csv").exists():
            rows.append((f"[{rel}]({rel}/report.md)", *_yu(d)))
        elif (d / "agreement.csv").exists():
            rows.append((f"[{rel}]({rel}/report.md)", *_compare(d)))
        elif (d / "summary.csv").exists() and (d / "report.md").exists():
            df = pd.read_csv(d / "summary.csv")
            silent = int((df.outcome == "SILENT FAILURE").sum())
            counts = ", ".join(f"{k} {v}" for k, v in sorted(df.outcome.value_counts().items()))
            rows.append((f"[{rel}]({rel}/report.md)", f"{df.scene.nunique()} scenes x 2 methods",
                         f"{silent} silent failures ({counts})", "pass" if not silent else "fail"))
        elif (d / "runs.csv").exists() and (d / "report.md").exists():
            df = pd.read_csv(d / "runs.csv")
            conv = df["converged"].astype(bool).sum() if "converged" in df else len(df)
            rows.append((f"[{rel}]({rel}/report.md)", f"{len(df)} runs ({conv} converged)",
                         "accuracy vs cost: see the recommendation table", "reported"))
    text = "\n".join([
        "# Verification reports", "", GENERATED_NOTE, "",
        "Regenerate everything with `riser-verify reproduce all`. Each line: the study, its "
        "cases, the worst agreement and the verdict against the stated tolerances.", "",
        md_table(["study", "cases", "worst agreement", "verdict"], rows), "",
    ])
    path = reports / "README.md"
    path.write_text(text)
    return path

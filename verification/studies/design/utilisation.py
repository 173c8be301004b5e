"""Static design checks by both methods (``riser-verify reproduce design``, unit
``utilisation``): the DNV-ST-F201 combined-loading utilisation and the von Mises stress
along a steel catenary riser and a steel lazy wave, each with its contents' design
pressure, from the BVP's and the VFIFE's static profiles (the comparison protocol's
model: the same line, the same seabed), with the protocol's verdict and its
``max_utilisation`` row.

Files in ``reports/design/utilisation/``: ``utilisation.csv`` (scene, method, s [m],
tension [N], moment [N m], wall_tension [N], von_mises [Pa], utilisation [-]),
``cases.csv`` (per scene: code, the largest utilisation by each method and where, their
relative difference and tolerance, the comparison's verdict), ``utilisation.png``,
``report.md``.
"""

from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

from verification.catalog import resolve
from verification.comparison.static.protocol import compare
from verification.report.figures import new_figure, save
from verification.report.markdown import GENERATED_NOTE, md_table, timed

#: scene -> what it is
SCENES = {"scr-steel-design": "steel catenary riser, contents at 20 MPa",
          "wang2014-lazy-wave-design": "steel lazy-wave riser (Wang et al.), gas at 20 MPa"}
COLUMNS = ("tension", "moment", "wall_tension", "von_mises", "utilisation")


def run_unit(out: Path, note: str = "") -> str:
    """Both scenes into ``out``; returns the log line."""
    t0 = time.perf_counter()
    out.mkdir(parents=True, exist_ok=True)
    profiles, cases = [], []
    for name, what in SCENES.items():
        cmp = compare(resolve(name))
        row = next(r for r in cmp.rows if r["quantity"] == "max_utilisation")
        for method, res in (("bvp", cmp.bvp), ("vfife", cmp.vfife)):
            p = res.profile
            frame = pd.DataFrame({"scene": name, "method": method, "s": p.s - cmp.s_shift,
                                  **{c: getattr(p, c) for c in COLUMNS}})
            profiles.append(frame)
        sb, sv = cmp.bvp.summary(), cmp.vfife.summary()
        cases.append({"scene": name, "what": what, "code": sb["design_code"],
                      "bvp_max_utilisation": sb["max_utilisation"],
                      "bvp_at_s": sb["max_utilisation_s"] - cmp.s_shift,
                      "vfife_max_utilisation": sv["max_utilisation"],
                      "vfife_at_s": sv["max_utilisation_s"] - cmp.s_shift,
                      "rel_diff": row["rel_diff"],
                      "tolerance": row["tolerance"] / row["basis"],    # relative, as rel_diff
                      "max_von_mises_MPa": sb["max_von_mises"] / 1e6,
                      "passes_code": bool(sb["design_passes"] and sv["design_passes"]),
                      "verdict": "pass" if cmp.passed else "fail"})
    df = pd.concat(profiles, ignore_index=True)
    df.to_csv(out / "utilisation.csv", index=False, float_format="%.10g")
    cs = pd.DataFrame(cases)
    cs.to_csv(out / "cases.csv", index=False, float_format="%.10g")
    _plot(df, out / "utilisation.png")
    _report(cs, out / "report.md", note, time.perf_counter() - t0)
    worst = cs["rel_diff"].abs().max()
    return (f"design/utilisation: {len(cs)} scenes, max utilisation BVP vs VFIFE within "
            f"{100 * worst:.4f} %, {'pass' if (cs.verdict == 'pass').all() else 'FAIL'}")


def _plot(df: pd.DataFrame, path: Path) -> None:
    fig, axes = new_figure(2, len(SCENES), size=(11.0, 6.5))
    for k, name in enumerate(SCENES):
        for method, style in (("bvp", "-"), ("vfife", "--")):
            d = df[(df.scene == name) & (df.method == method)]
            axes[0, k].plot(d.s, d.utilisation, style, label=method.upper())
            axes[1, k].plot(d.s, d.von_mises / 1e6, style, label=method.upper())
        axes[0, k].set_title(name)
        axes[0, k].set_ylabel("DNV-ST-F201 utilisation [-]")
        axes[1, k].set_ylabel("von Mises stress [MPa]")
        axes[1, k].set_xlabel("s from the bottom end [m] (negative: the line a conversion adds)")
        axes[0, k].legend()
    save(fig, path)


def _report(cs: pd.DataFrame, path: Path, note: str, seconds: float) -> None:
    rows = [(r.scene, r.code, f"{r.bvp_max_utilisation:.5f} at {r.bvp_at_s:.1f} m",
             f"{r.vfife_max_utilisation:.5f} at {r.vfife_at_s:.1f} m",
             f"{100 * r.rel_diff:+.4f} %", f"{100 * r.tolerance:.2g} %",
             f"{r.max_von_mises_MPa:.1f}", "yes" if r.passes_code else "no", r.verdict)
            for r in cs.itertuples()]
    text = [
        "# Design checks, static: utilisation along the line by both methods", "",
        GENERATED_NOTE, "",
        "The DNV-ST-F201 combined-loading utilisation (LRFD, safety class normal, the code's "
        "default factors; riser/design/dnv_f201.py) and the von Mises stress along each line, "
        "from the BVP's and the VFIFE's static profiles of the same model (`riser-verify "
        "compare SCENE`). A static state is all functional load: M_d = 1.1 M, T_ed = 1.1 T_e. "
        "The contents' design pressure acts at the hang-off, with their head below it; the sea "
        "pressure is hydrostatic.", "",
        md_table(["scene", "code", "BVP max utilisation", "VFIFE max utilisation",
                  "difference", "tolerance", "max von Mises [MPa]", "passes the code",
                  "comparison"], rows), "",
        "![utilisation](utilisation.png)", "",
        "Files: `utilisation.csv` (both methods along s), `cases.csv`. Run in "
        f"{timed(seconds, '.1f')}"
        + (f" ({note})" if note else "") + ".", ""]
    path.write_text("\n".join(text))


"""The ANCF as a judged column of a comparison (``riser-verify compare``).

The ANCF (ancf/, Liu et al. 2021's element, Newton statics) solves the same matched scene
as the BVP and the VFIFE, at its own default mesh (``[ancf] element_length``), and its
rows against the BVP are the static protocol's (:func:`.agreement.agreement` with
``names=("bvp", "ancf")``, the same tolerances of :mod:`verification.comparison.tolerances`):
unlike the analytic method's and a peer's columns, they are in the verdict (a comparison
passes when the VFIFE's rows and the ANCF's pass; ``ColumnResult.judged``). A line whose
bending the ANCF's elements cannot resolve has its moment rows shown, not judged, as the
VFIFE's (:func:`.agreement.unresolved_bending` at the ANCF's element length).
"""

from __future__ import annotations

from pathlib import Path

from riser.results.result import Status
from verification.methods import method
from verification.pipeline import shifted
from verification.report.markdown import md_table, timed
from verification.runtime import outdir

from .agreement import agreement, unresolved_bending
from .columns import ColumnResult, verdict_values
from ..formatting import num, signed


class ANCFColumn:
    """The ANCF's column (see the module docstring); a failed ANCF solve fails the
    comparison."""

    name = "ancf"
    label = "ANCF"
    style = {"ls": ":", "lw": 1.4}
    forces = ("tension", "moment", "shear")
    files = tuple(f"ancf/{n}" for n in outdir.SOLVE)
    judged = True

    def solve(self, comp, folder: Path | None = None, progress=None) -> ColumnResult:
        """Solve the comparison's matched scene with the ANCF; its rows against the BVP."""
        if progress is not None:
            progress("ancf: solving the matched model")
        res = method("ancf").solve(comp.matched_scene)
        if res.status is Status.REFUSED:
            reason = res.message.split(": ", 1)[-1]
            return ColumnResult(self, res, note=f"The ANCF does not represent this scene "
                                f"({reason}): its rows are not judged.", judged=True)
        if not res.converged:
            return ColumnResult(self, res, note=f"The ANCF ended in {res.status.value}: "
                                f"{res.message}.", ok=False, judged=True)
        profile = shifted(res.profile, comp.s_shift)
        h = res.info["element_length"]
        bending = unresolved_bending(comp.matched_scene, comp.bvp.profile, h, comp.s_shift)
        matched = comp.matched_scene
        rows = agreement(shifted(comp.bvp.profile, comp.s_shift), profile, comp.depth,
                         moment_reason=bending, ends=matched.ends,
                         points=[a.s - comp.s_shift for a in matched.attachments],
                         scene=matched, names=("bvp", self.name))
        i = res.info
        verdict = "pass" if all(r["pass"] is not False for r in rows) else "FAIL"
        return ColumnResult(
            self, res, profile, verdict_values(comp.rows, rows, self.name), rows,
            note=(f"The ANCF ({i['elements']} cubic elements of {h:.3g} m, "
                  f"{i['newton_iterations']} Newton iterations, "
                  f"{timed(res.wall_time_s, '.2f', ' s')}) solved the same scene: {verdict} "
                  "against the BVP with the protocol's tolerances."),
            judged=True)

    def markdown(self, comp, res: ColumnResult, heading: str = "#") -> list[str]:
        """The report's section: its rows against the BVP with their verdicts, beside the
        VFIFE's differences."""
        lines = ["", f"{heading}# ANCF (third method), in the verdict", "", res.note]
        if res.profile is None:
            return lines
        vf = {r.quantity: r for r in comp.rows}
        table = []
        for a in res.rows:
            v = vf.get(a.quantity)
            rel, label = a.rel_diff, a["basis_label"]
            table.append((f"`{a.quantity}`", a.unit, num(a.value("bvp")),
                          num(a.value(self.name)), signed(a.diff),
                          "" if rel is None else f"{100.0 * rel:+.3g} %"
                          + (f" of {label}" if label else ""),
                          "" if a["tolerance"] is None else f"{a['tolerance']:.3g}",
                          {True: "pass", False: "FAIL", None: "not judged"}[a["pass"]],
                          "" if v is None else signed(v.diff)))
        lines += ["", "Its rows against the BVP, with the protocol's tolerances (its "
                  "differences beside the VFIFE's):", ""]
        lines.append(md_table(["quantity", "unit", "BVP", "ANCF", "ANCF - BVP", "relative",
                               "tolerance", "verdict", "VFIFE - BVP"], table))
        return lines

    def write(self, comp, res: ColumnResult, out: Path) -> None:
        """``ancf/``: its summary.json and profile.csv, and its rows (agreement.csv)."""
        if res.result is None:
            return
        res.result.write(Path(out) / self.name)

    def console(self, res: ColumnResult) -> list[str]:
        return [f"  {res.note}"] if res.note else []

    def files_note(self) -> str:
        return ("`ancf_rel_diff` the ANCF's (judged: the verdict includes its rows, "
                "`ancf/` its solve)")

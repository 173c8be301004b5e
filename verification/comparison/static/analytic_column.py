"""The analytic method as a further column of a comparison (``riser-verify compare``).

Where it applies (one section, no current; analytic/solver.py says what it refuses) the
analytic method solves the same matched scene as the BVP and the VFIFE, and every
agreement row gains ``analytic`` (its value) and ``analytic_rel_diff`` (the signed
(analytic - BVP) / basis, the basis of the row's tolerance). The verdict stays BVP
against VFIFE: the analytic solution is asymptotic, its error a property of the scene
(eps = sqrt(EI / (H L^2)), delta = w lambda / H), not a discretisation that refines away.
Measured on the Kang J-lay case (reports/kang2015/epsilon.csv) the composite's error
against the BVP falls as eps^2 in angle and position and about eps^3 in the peak moment.
"""

from __future__ import annotations

from pathlib import Path

from riser.results.result import Status
from verification.methods import method
from verification.pipeline import shifted
from verification.report.markdown import md_table, timed
from verification.runtime import outdir

from .agreement import agreement
from .columns import ColumnResult, verdict_values
from ..formatting import num, signed


class AnalyticColumn:
    """The analytic method's column (see the module docstring): it always runs and is
    never a failure of the command; where it does not apply, the report says why."""

    name = "analytic"
    label = "analytic"
    style = {"ls": "-.", "lw": 1.0}
    forces = ("tension", "moment", "shear")
    files = tuple(f"analytic/{n}" for n in outdir.SOLVE)

    def solve(self, comp, folder: Path | None = None, progress=None) -> ColumnResult:
        """Solve the comparison's matched scene analytically; its rows against the BVP."""
        res = method("analytic").solve(comp.matched_scene)
        if res.status is Status.REFUSED:
            reason = res.message.split(": ", 1)[-1]
            return ColumnResult(self, note=f"The analytic method does not apply to this "
                                f"scene ({reason}).")
        if not res.converged:
            return ColumnResult(self, res, note=f"The analytic method ended in "
                                f"{res.status.value}: {res.message}.")
        profile = shifted(res.profile, comp.s_shift)
        rows = agreement(shifted(comp.bvp.profile, comp.s_shift), profile, comp.depth,
                         scene=comp.matched_scene, names=("bvp", self.name))
        i = res.info
        return ColumnResult(
            self, res, profile, verdict_values(comp.rows, rows, self.name), rows,
            note=(f"The analytic method ({i['analytic_model']}, "
                  f"{timed(res.wall_time_s, '.2f', ' ms')}) solved the same scene: "
                  f"eps = {i['epsilon']:.3g}, delta = "
                  f"{i['delta']:.3g}, boundary layer {i['boundary_layer_length']:.3g} m."))

    def markdown(self, comp, res: ColumnResult, heading: str = "#") -> list[str]:
        """The report's section: what was solved (or why not), and its differences to the
        BVP beside the VFIFE's."""
        lines = ["", f"{heading}# Analytic method (further column), not part of the verdict", "",
                 res.note]
        if res.profile is None:
            return lines
        lines += ["", "Its error against the BVP is asymptotic: it depends on eps = sqrt(EI / "
                  "(H L^2)) and delta = w lambda / H, not on a mesh. The composite solution "
                  "(catenary with its O(eps^2) bending correction, matched touchdown layer, "
                  "moment-free layer at the hang-off) was measured to converge as eps^2 in "
                  "angle and position and about eps^3 in the peak moment "
                  "(`reports/kang2015/`, epsilon scaling).", ""]
        mine = {r.quantity: r for r in res.rows}
        table = []
        for r in comp.rows:
            a = mine.get(r.quantity)
            if a is None or a.diff is None:
                continue
            rel, label = a.rel_diff, r["basis_label"]
            table.append((f"`{r.quantity}`", r.unit, num(r.value("bvp")),
                          num(a.value(self.name)), signed(a.diff),
                          "" if rel is None else f"{100.0 * rel:+.3g} %"
                          + (f" of {label}" if label else ""), signed(r.diff)))
        lines.append(md_table(["quantity", "unit", "BVP", "analytic", "analytic - BVP",
                               "relative", "VFIFE - BVP"], table))
        return lines

    def write(self, comp, res: ColumnResult, out: Path) -> None:
        """``analytic/``: its summary.json (and profile.csv when it converged)."""
        if res.result is not None:
            res.result.write(Path(out) / self.name)

    def console(self, res: ColumnResult) -> list[str]:
        return [f"  {res.note}"] if res.note else []

    def files_note(self) -> str:
        return "`analytic_rel_diff` the analytic method's, empty where it does not apply"

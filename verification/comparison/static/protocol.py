"""VFIFE vs BVP comparison protocol: both methods on the same model, the verdict rows, the
paper model beside them and the further columns.

Like with like: both methods solve the same scene in the same continuum model, an
extensible line (strain T/EA) on a unilateral frictionless Winkler seabed of the scene's
stiffness. A fixed-ends scene is solved as it is by both. A scene in a Wang form
(touchdown tension; hang-off height and angle; or, J-lay, hang-off height and top
tension) is solved once by the BVP in its paper model (inextensible on a rigid seabed),
converted once to fixed ends (hang-off at that
BVP's top point, anchor on the seabed with extra line ahead of the touchdown,
:func:`verification.pipeline.vfife_equivalent`), and both methods solve the
converted scene. The verdict is that matched comparison alone.

The metric, at the same arc length: :mod:`.agreement`. Further columns beside the
verdict (the analytic method where it applies, a peer asked for): :mod:`.columns`.

A secondary section compares the same VFIFE run with the BVP's paper model (the limit
EA -> inf, k -> inf): for a Wang form the original paper-model BVP result, for a
fixed-ends scene the scene solved by the BVP with ``[model] axial = "inextensible"``,
``seabed = "rigid"``. It shows how far the paper model is from the extensible line on
the soft seabed; it is not part of the verdict.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from riser.errors import SolveFailed
from riser.model.scene import FixedEnds, Scene
from verification.methods import method
from verification.pipeline import shifted, vfife_equivalent
from verification.quantities import reference_depth
from verification.runtime.interrupts import reraise_interrupt

from .agreement import AGREEMENT_COLUMNS, agreement, unresolved_bending
from .analytic_column import AnalyticColumn
from .ancf_column import ANCFColumn
from .columns import Column, ColumnResult

#: the BVP's paper model (Wang et al. 2014): the limit of the matched model
PAPER_MODEL = {"axial": "inextensible", "seabed": "rigid"}

@dataclass
class Comparison:
    """Everything a comparison produced.

    ``matched_scene`` is the scene both methods solved (the scene itself, or its
    fixed-ends conversion for a Wang form); ``vfife_scene`` the one VFIFE solved (the
    matched scene after ``vfife_modifier``). ``s_shift`` [m] is subtracted from both
    methods' arc lengths to report them in the scene's own coordinate (the line added on
    the seabed by the conversion; 0 for a fixed-ends scene). ``rows`` (the verdict) are in
    that coordinate; ``paper_rows`` compare the same VFIFE run with ``paper`` (the BVP's
    paper model, see the module docstring). ``columns``: name -> :class:`ColumnResult`
    of each further column beside the verdict, in the order they ran (:mod:`.columns`)."""

    scene: Scene
    vfife_scene: Scene
    s_shift: float
    depth: float
    bvp: object
    vfife: object
    rows: list[dict]
    matched_scene: Scene | None = None
    paper: object = None
    paper_rows: list[dict] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    columns: dict[str, ColumnResult] = field(default_factory=dict)

    @property
    def passed(self) -> bool:
        """Every judged row within its tolerance, the VFIFE's and those of a judged column
        (the ANCF's; a row shown but not judged, pass None, does not count: its reason is
        in its note), and no judged column failed to solve."""
        return (all(r["pass"] is not False for r in self.rows)
                and all(res.ok and all(r["pass"] is not False for r in res.rows)
                        for res in self.columns.values() if res.judged))

    @property
    def columns_ok(self) -> bool:
        """No further column that was asked for failed (a peer that did not converge)."""
        return all(res.ok for res in self.columns.values())

    def frame(self) -> pd.DataFrame:
        """agreement.csv: the verdict rows (:data:`AGREEMENT_COLUMNS`), then ``NAME`` and
        ``NAME_rel_diff`` of each further column (empty where it gives no value)."""
        df = pd.DataFrame([r.record(AGREEMENT_COLUMNS) for r in self.rows],
                          columns=AGREEMENT_COLUMNS)
        for name, res in self.columns.items():
            values = [res.value(q) for q in df["quantity"]]
            df[name] = [v for v, _ in values]
            df[f"{name}_rel_diff"] = [r for _, r in values]
        return df

    def worst(self) -> dict:
        """quantity -> row of the headline differences (configuration, tension, moment,
        tdp_x) present in the verdict rows."""
        by = {r["quantity"]: r for r in self.rows}
        return {q: by[q] for q in ("configuration", "tension", "moment", "tdp_x") if q in by}


def paper_model_scene(scene: Scene) -> Scene:
    """A fixed-ends ``scene`` in the BVP's paper model: inextensible, and on a rigid seabed
    when it has one."""
    model = dict(PAPER_MODEL) if scene.seabed is not None else {"axial": "inextensible"}
    return scene.replace(model=model)


def model_text(scene: Scene) -> str:
    """One phrase naming the continuum model both methods solve for ``scene``."""
    axial = ("extensible (strain T/EA)" if scene.axial_model == "extensible"
             else "inextensible")
    sm = scene.seabed_model
    if sm == "elastic":
        bed = (f"a unilateral frictionless Winkler seabed of stiffness "
               f"{scene.seabed.stiffness:.3g} N/m2")
    elif sm == "rigid":
        bed = "a rigid seabed"
    else:
        bed = "no seabed"
    return f"{axial} line on {bed}"


def default_columns() -> tuple[Column, ...]:
    """The further columns every comparison has: the analytic method (where it applies) and
    the ANCF (judged); agreement.csv keeps the analytic method's columns where they were
    and adds the ANCF's after them."""
    return (AnalyticColumn(), ANCFColumn())


def compare(scene: Scene, *, element_length: float | None = None, paper_model: bool = True,
            vfife_modifier=None, columns: tuple[Column, ...] | None = None,
            folder: str | Path | None = None, log=None, progress=None) -> Comparison:
    """Solve ``scene`` with both methods in the same model and compute the agreement rows.

    ``element_length`` [m]: VFIFE element length (default the scene's ``[vfife]
    element_length``). ``paper_model``: also solve the BVP's paper model and compare it
    with the same VFIFE run (secondary section, not part of the verdict).
    ``vfife_modifier`` (Scene -> Scene) alters only the VFIFE scene:
    used by the negative controls (e.g. drag halved) to prove that the check can fail.
    A scene with [dynamics] is compared in its static equilibrium. Raises
    :class:`~riser.errors.SolveFailed` when a method does not converge. ``columns``: the
    further columns to run after the two methods (default :func:`default_columns`; a peer's
    column is added by the caller), each writing its files, if any, under ``folder`` (a
    peer's column needs one). ``log``: callable told of each finished solve;
    ``progress``: callable told of what runs now (the VFIFE relaxation included; see
    :mod:`verification.runtime.progress`).
    """
    say = log or (lambda msg: None)
    now = progress or (lambda msg: None)
    notes: list[str] = []
    if scene.dynamics is not None:
        scene = scene.replace(dynamics=None)
        notes.append("The scene's [dynamics] are ignored: the protocol compares the static "
                     "equilibrium.")
    t0 = time.perf_counter()
    if not isinstance(scene.ends, FixedEnds):
        now("bvp: solving the paper model for the conversion to fixed ends")
    eq = vfife_equivalent(scene)
    matched, s_shift, paper = eq.scene, eq.s_shift, eq.paper
    if eq.note:
        say(f"{scene.name}: paper-model BVP {paper.message} ({eq.seconds:.1f} s)")
        notes.append(f"The scene was converted: {eq.note}; both methods solve this "
                     "converted scene.")
    now("bvp: solving the matched model")
    b = method("bvp").solve(matched)
    say(f"{scene.name}: matched BVP {b.message} ({time.perf_counter() - t0:.1f} s)")
    if not b.converged:
        raise SolveFailed("bvp", b.status, f"bvp did not converge on {matched.name}: "
                          f"{b.message}")
    vf_scene = vfife_modifier(matched) if vfife_modifier is not None else matched
    v = method("vfife").solve(vf_scene, element_length=element_length, progress=progress)
    say(f"{scene.name}: VFIFE {v.message} ({time.perf_counter() - t0:.1f} s)")
    if not v.converged:
        raise SolveFailed("vfife", v.status, f"vfife did not converge on {scene.name}: "
                          f"{v.message}")
    depth = reference_depth(scene, b.summary())
    bp, vp = shifted(b.profile, s_shift), shifted(v.profile, s_shift)
    bending = unresolved_bending(matched, b.profile, v.info["element_length"], s_shift)
    rows = agreement(bp, vp, depth, moment_reason=bending, ends=matched.ends,
                     points=[a.s - s_shift for a in matched.attachments],
                     scene=matched)
    comp = Comparison(scene, vf_scene, s_shift, depth, b, v, rows, matched_scene=matched,
                      notes=notes)
    if paper_model:
        if paper is None:
            try:
                now("bvp: solving the paper model (secondary comparison)")
                paper = method("bvp").solve(paper_model_scene(scene))
            except Exception as exc:       # the paper model may not be able to represent it
                reraise_interrupt(exc)     # but a Ctrl-C (in Numba) stops the comparison
                notes.append(f"The paper model could not be set up: {exc}")
                paper = None
            say(f"{scene.name}: paper-model BVP "
                f"{paper.message if paper is not None else 'not set up'}")
        comp.paper = paper
        if paper is not None and paper.converged:
            comp.paper_rows = agreement(paper.profile, vp, depth)
    _run_columns(comp, default_columns() if columns is None else columns, folder, progress)
    return comp


def _run_columns(comp: Comparison, columns, folder, progress) -> None:
    """Run each further column on the finished comparison, its files into ``folder/NAME``
    (None when ``folder`` is)."""
    for col in columns:
        sub = None if folder is None else Path(folder) / col.name
        comp.columns[col.name] = col.solve(comp, sub, progress)

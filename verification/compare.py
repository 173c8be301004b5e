"""VFIFE vs BVP comparison protocol: metrics, the pipeline and its report (with the
analytic method as a third column where it applies, verification/compare_analytic.py).

Like with like: both methods solve the same scene in the same continuum model, an
extensible line (strain T/EA) on a unilateral frictionless Winkler seabed of the scene's
stiffness. A fixed-ends scene is solved as it is by both. A scene in a Wang form
(touchdown tension; hang-off height and angle; or, J-lay, hang-off height and top
tension) is solved once by the BVP in its paper model (inextensible on a rigid seabed),
converted once to fixed ends (hang-off at that
BVP's top point, anchor on the seabed with extra line ahead of the touchdown,
:func:`verification.pipeline.vfife_equivalent`), and both methods solve the
converted scene. The verdict is that matched comparison alone.

The profiles are compared at the same arc length over the range both cover, at the VFIFE
nodes (where VFIFE defines its results), the BVP (stations every sqrt(EI/T)/8, at most
0.5 m) interpolated there; tension is the effective tension and moment the in-plane
bending moment signed with the curvature. Two artefacts of comparing a 1 m VFIFE mesh with
a continuous solution are kept out of the metrics, each measured (issue 11):

- VFIFE values between its nodes are only a linear interpolation: taking them at the BVP
  stations added h^2 |M''| / 8 with M'' ~ w cos(theta) (~65 N m on the Wang pipe; 0.49 %
  of M_max on hard-current-pos2p5, whose M_max is 11 kN m) to the moment metric. At the
  nodes it is 0.24 % there; the choice of interpolant for the BVP (linear, cubic, Akima)
  changes no metric by more than 1e-4 % of M_max.
- A VFIFE element force is constant and belongs to the element midpoint; a node reports
  the mean of its two elements (``vfife.model.Model.nodal_results``). Where the tension
  has a kink (a jump of the submerged weight at a segment joint) that mean is off by
  |dw| h / 4: 0.17-0.20 % of T_max on the Yu risers (1130 N/m of buoyancy) at 1 m,
  halving at 0.5 m. The BVP tension is therefore put through the same operator
  (:func:`verification.quantities.nodal_average`): sampled at the VFIFE element midpoints and averaged to the
  nodes. What remains is the discretisation error (0.02 % on Yu A1, 0.004 % on Wang).

A secondary section compares the same VFIFE run with the BVP's paper model (the limit
EA -> inf, k -> inf): for a Wang form the original paper-model BVP result, for a
fixed-ends scene the scene solved by the BVP with ``[model] axial = "inextensible"``,
``seabed = "rigid"``. It shows how far the paper model is from the extensible line on
the soft seabed; it is not part of the verdict.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

import bvp
import vfife
from riser.errors import SolveFailed
from riser.profile import Profile, summarize
from riser.scene import Scene

from .compare_analytic import third_column
from .pipeline import shifted, vfife_equivalent
from .quantities import (curve_distance, match_feature, nodal_average,
                         peak_location_offset, reference_depth, signed_moment)
from .tolerances import tolerance, tolerance_value, unit

AGREEMENT_COLUMNS = ("quantity", "bvp", "vfife", "abs_diff", "rel_diff", "tolerance", "pass",
                     "analytic", "analytic_rel_diff", "moordyn", "moordyn_rel_diff")

#: differences (and values) below this fraction of their basis are printed as 0: the
#: solvers write their profiles with 10 significant digits, so nothing below ~1e-9 of a
#: quantity's scale is reproducible from the files.
ROUND_OFF = 1.0e-9

#: the BVP's paper model (Wang et al. 2014): the limit of the matched model
PAPER_MODEL = {"axial": "inextensible", "seabed": "rigid"}


def agreement(bvp_prof: Profile, vf_prof: Profile, depth: float,
              s_shift: float = 0.0, nodal: bool = True) -> list[dict]:
    """The protocol's rows for two static profiles.

    Each row has the :data:`AGREEMENT_COLUMNS` (``abs_diff`` = |VFIFE - BVP|, ``rel_diff``
    = the signed (VFIFE - BVP) / basis with the basis of the row's tolerance, see
    :func:`verification.tolerances.tolerance`) and, for the report, ``unit``, ``diff``
    (signed, in the unit), ``basis_label``, ``tol_label`` and ``at_s`` (arc length of the
    largest profile difference, BVP coordinate). ``s_shift`` [m] is subtracted from the
    VFIFE arc lengths. ``nodal``: take the BVP tension through the VFIFE's nodal average
    (module docstring); False compares point values (a second profile that is not a
    VFIFE's, e.g. the analytic method's)."""
    rows: list[dict] = []
    vf = shifted(vf_prof, s_shift)
    sb, sv = summarize(bvp_prof), summarize(vf)
    lo = max(bvp_prof.s[0], vf.s[0])
    hi = min(bvp_prof.s[-1], vf.s[-1])
    Tmax = max(float(np.max(np.abs(bvp_prof.tension))), 1.0)
    Mmax = max(float(np.max(bvp_prof.moment)), 1e-12)
    scales = {"depth": depth, "max_tension": Tmax, "max_moment": Mmax}

    def add(name, b, v, diff=None, at_s=None, note=""):
        """A row; ``diff`` is the signed difference (default v - b)."""
        t = tolerance(name, bvp_value=b, **scales)
        row = {"quantity": name, "bvp": b, "vfife": v, "unit": unit(name), "at_s": at_s,
               "note": note,
               "tol_label": t["label"], "basis_label": t["basis_label"], "basis": t["basis"],
               "tolerance": t["tol"]}
        if diff is None and (v is None or b is None):
            row.update({"abs_diff": None, "rel_diff": None, "diff": None, "pass": False})
        else:
            d = float(v - b) if diff is None else float(diff)
            row.update({"diff": d, "abs_diff": abs(d),
                        "rel_diff": d / t["basis"] if t["basis"] else None,
                        "pass": bool(abs(d) <= t["tol"])})
        rows.append(row)

    dmax, drms, s_at = curve_distance(bvp_prof, vf, (lo, hi))
    add("configuration", None, None, diff=dmax, at_s=s_at)
    add("configuration_rms", None, None, diff=drms)
    # tension and moment at the VFIFE nodes, where VFIFE defines them (see module notes)
    sel = (vf.s >= lo - 1e-9) & (vf.s <= hi + 1e-9)
    grid = vf.s[sel]
    ref = (nodal_average(vf.s, bvp_prof.s, bvp_prof.tension) if nodal
           else np.interp(vf.s, bvp_prof.s, bvp_prof.tension))
    dT = vf.tension[sel] - ref[sel]
    dM = signed_moment(vf)[sel] - np.interp(grid, bvp_prof.s, signed_moment(bvp_prof))
    for name, d in (("tension", dT), ("moment", dM)):
        i = int(np.argmax(np.abs(d)))
        add(name, None, None, diff=float(d[i]), at_s=float(grid[i]))

    add("hang_off_tension", sb["hang_off_tension"], sv["hang_off_tension"])
    if "hang_off_wall_tension" in sb and "hang_off_wall_tension" in sv:
        add("hang_off_wall_tension", sb["hang_off_wall_tension"], sv["hang_off_wall_tension"])
    add("hang_off_angle_deg", sb["hang_off_angle_deg"], sv["hang_off_angle_deg"])
    if sb["tdp_x"] is not None:
        add("tdp_x", sb["tdp_x"], sv["tdp_x"])
        add("tdp_tension", sb["tdp_tension"], sv["tdp_tension"])
    for kind in ("crests", "sags"):
        tag = kind[:-1]
        for i, cb in enumerate(sb[kind]):
            cv = match_feature(cb, sv[kind]) or {"height": None, "s": None}
            add(f"{tag}{i + 1}_height", cb["height"], cv["height"])
            add(f"{tag}{i + 1}_s", cb["s"], cv["s"])
        if len(sv[kind]) != len(sb[kind]):
            n_b, n_v = len(sb[kind]), len(sv[kind])
            rows.append({"quantity": f"{kind}_count", "bvp": n_b, "vfife": n_v, "unit": "-",
                         "diff": n_v - n_b, "abs_diff": abs(n_v - n_b), "rel_diff": None,
                         "tolerance": 0, "tol_label": "equal", "basis_label": "",
                         "basis": None, "at_s": None, "pass": False})
    add("max_moment", sb["max_moment"], sv["max_moment"])
    tol_peak, _ = tolerance_value("max_moment", bvp_value=sb["max_moment"], depth=depth,
                                  max_tension=Tmax, max_moment=Mmax)
    off = peak_location_offset(bvp_prof, vf, tol_peak)
    tie = abs(off - (sv["max_moment_s"] - sb["max_moment_s"])) > 1e-6
    add("max_moment_s", sb["max_moment_s"], sv["max_moment_s"], diff=off,
        note="between the nearest peaks within the max_moment tolerance of the maximum "
             "(a tie)" if tie else "")
    return rows


# ----------------------------------------------------------------------------- pipeline
@dataclass
class Comparison:
    """Everything a comparison produced.

    ``matched_scene`` is the scene both methods solved (the scene itself, or its
    fixed-ends conversion for a Wang form); ``vfife_scene`` the one VFIFE solved (the
    matched scene after ``vfife_modifier``). ``s_shift`` [m] is subtracted from both
    methods' arc lengths to report them in the scene's own coordinate (the line added on
    the seabed by the conversion; 0 for a fixed-ends scene). ``rows`` (the verdict) are in
    that coordinate; ``paper_rows`` compare the same VFIFE run with ``paper`` (the BVP's
    paper model, see the module docstring)."""

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
    analytic: object = None
    analytic_note: str = ""
    moordyn: object = None               # the MoorDyn peer (compare --peer moordyn)
    moordyn_rows: list[dict] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        return all(r["pass"] for r in self.rows)

    def frame(self) -> pd.DataFrame:
        return pd.DataFrame(self.rows, columns=AGREEMENT_COLUMNS)

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


def compare(scene: Scene, *, element_length: float | None = None, paper_model: bool = True,
            vfife_modifier=None, log=None, progress=None) -> Comparison:
    """Solve ``scene`` with both methods in the same model and compute the agreement rows.

    ``element_length`` [m]: VFIFE element length (default the scene's ``[vfife]
    element_length``). ``paper_model``: also solve the BVP's paper model and compare it
    with the same VFIFE run (secondary section, not part of the verdict).
    ``vfife_modifier`` (Scene -> Scene) alters only the VFIFE scene:
    used by the negative controls (e.g. drag halved) to prove that the check can fail.
    A scene with [dynamics] is compared in its static equilibrium. Raises
    :class:`~riser.errors.SolveFailed` when a method does not converge. ``log``: callable
    told of each finished solve; ``progress``: callable told of what runs now (the VFIFE
    relaxation included; see :mod:`verification.progress`).
    """
    say = log or (lambda msg: None)
    now = progress or (lambda msg: None)
    notes: list[str] = []
    if scene.dynamics is not None:
        scene = scene.replace(dynamics=None)
        notes.append("The scene's [dynamics] are ignored: the protocol compares the static "
                     "equilibrium.")
    t0 = time.perf_counter()
    if scene.ends.kind != "fixed":
        now("bvp: solving the paper model for the conversion to fixed ends")
    eq = vfife_equivalent(scene)
    matched, s_shift, paper = eq.scene, eq.s_shift, eq.paper
    if eq.note:
        say(f"{scene.name}: paper-model BVP {paper.message} ({eq.seconds:.1f} s)")
        notes.append(f"The scene was converted: {eq.note}; both methods solve this "
                     "converted scene.")
    now("bvp: solving the matched model")
    b = bvp.solve(matched)
    say(f"{scene.name}: matched BVP {b.message} ({time.perf_counter() - t0:.1f} s)")
    if not b.converged:
        raise SolveFailed("bvp", b.status, f"bvp did not converge on {matched.name}: "
                          f"{b.message}")
    vf_scene = vfife_modifier(matched) if vfife_modifier is not None else matched
    v = vfife.solve(vf_scene, element_length=element_length, progress=progress)
    say(f"{scene.name}: VFIFE {v.message} ({time.perf_counter() - t0:.1f} s)")
    if not v.converged:
        raise SolveFailed("vfife", v.status, f"vfife did not converge on {scene.name}: "
                          f"{v.message}")
    depth = reference_depth(scene, b.summary())
    bp, vp = shifted(b.profile, s_shift), shifted(v.profile, s_shift)
    rows = agreement(bp, vp, depth)
    comp = Comparison(scene, vf_scene, s_shift, depth, b, v, rows, matched_scene=matched,
                      notes=notes)
    # the third column where it applies (verification/compare_analytic.py)
    comp.analytic, comp.analytic_note = third_column(matched, bp, s_shift, depth, rows,
                                                    agreement)
    if paper_model:
        if paper is None:
            try:
                now("bvp: solving the paper model (secondary comparison)")
                paper = bvp.solve(paper_model_scene(scene))
            except Exception as exc:       # the paper model may not be able to represent it
                notes.append(f"The paper model could not be set up: {exc}")
                paper = None
            say(f"{scene.name}: paper-model BVP "
                f"{paper.message if paper is not None else 'not set up'}")
        comp.paper = paper
        if paper is not None and paper.converged:
            comp.paper_rows = agreement(paper.profile, vp, depth)
    return comp
